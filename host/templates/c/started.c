{# `<name>_<kind>_init`, `_push` and `_estimate` of a follower of the map as `firmware::Started` runs
   it; `init_carried` resets the carried state. -#}
{# `_fresh`: the follower waiting for the map's first estimate (at init, and where a start or
   follow-up was not finite: a restart). #}
static void {{ kind }}_fresh({{ name }}_{{ kind }} *o) {
    {{ name }}_map_init(&o->window);
{{ init_carried }}    o->count = 0u;
    o->started = 0;
}

static {{ name }}_status {{ kind }}_sample({{ name }}_{{ kind }} *o, const float *y, const float *u) {
    const int start_up = o->count <= {{ start_up }}u;
    float all[{{ upper }}_MAP_ROWS], map[{{ upper }}_STATES], states[{{ upper }}_STATES];
    {{ name }}_saturation all_flags[{{ upper }}_MAP_ROWS], state_flags[{{ upper }}_STATES];
    int estimated = 0;
    if (!accepts(y, u)) {
        if (o->started && inputs_finite(u)) {
            {{ predict }}({{ predicted }}, u);
        }
        return {{ upper }}_REFUSED;
    }
    memset(map, 0, sizeof map);
    if ({% if steady_reads_map %}start_up || 1{% else %}start_up{% endif %}) {
        (void){{ name }}_map_push(&o->window, y, u);
        if (o->window.filled < {{ upper }}_HORIZON) {
            return {{ upper }}_OK;
        }
        (void)start_map_estimate(&o->window, all, all_flags);
        {{ prefix }}_map_states(all, map);
        estimated = 1;
    }
    if (!o->started && estimated) {
        if (!{{ prefix }}_start(map, u, {{ carried }})) {
            {{ kind }}_fresh(o);
            return {{ upper }}_RESTARTED;
        }
        o->started = 1;
        memcpy(o->values, all, sizeof o->values);
        memcpy(o->flags, all_flags, sizeof o->flags);
    } else if (o->started) {
        if (!{{ prefix }}_follow({{ carried }}, o->count, start_up, map, y, u, states, state_flags)) {
            {{ kind }}_fresh(o);
            return {{ upper }}_RESTARTED;
        }
        {{ prefix }}_targets_of(states, state_flags, u, o->values, o->flags);
    } else {
        return {{ upper }}_OK;
    }
    o->ready = 1;
    o->count = start_up ? o->count + 1u : o->count;
    return {{ upper }}_OK;
}

{% include "c/counted.c" %}
