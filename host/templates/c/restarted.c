{# `ekf_restart`: `firmware::Restarted` over `StartedEkf`, with the check `restart_disagrees`
   (`terms`: its sum, one state after another). -#}
/* Whether the filter's prediction x (covariance p) and the map's states f disagree:
 * d = sum_i (x_i - f_i)^2 / (P_ii + e_i^2) > threshold, or d is NaN (restart_disagrees). */
static int restart_disagrees(const float *x, const float *p, const float *f) {
    float d = 0.0f;
    float e;
{{ terms }}    return !(d <= {{ threshold }});
}

/* Restarted::check, at the map's first estimate: 1 when the filter restarted from the map. */
static int restart_check({{ name }}_ekf_restart *o, const float *y, const float *u) {
    float all[{{ upper }}_TARGETS], map[{{ upper }}_STATES];
    {{ name }}_saturation all_flags[{{ upper }}_TARGETS];
    (void){{ name }}_map_push(&o->window, y, u);
    if (o->window.filled < {{ upper }}_HORIZON) {
        return 0;
    }
    o->checked = 1;
    (void){{ name }}_map_estimate(&o->window, all, all_flags);
    started_ekf_map_states(all, map);
    if (!restart_disagrees(o->x, o->p, map) || !started_ekf_start(map, u, o->x, o->p)) {
        return 0;
    }
    memcpy(o->values, all, sizeof all);
    memcpy(o->flags, all_flags, sizeof all_flags);
    o->ready = 1;
    return 1;
}

static void {{ kind }}_fresh({{ name }}_{{ kind }} *o) {
    {{ name }}_map_init(&o->window);
    memcpy(o->x, EKF_X0, sizeof o->x);
    memcpy(o->p, EKF_P0, sizeof o->p);
    o->checked = 0;
    o->ready = 0;
}

static {{ name }}_status {{ kind }}_sample({{ name }}_{{ kind }} *o, const float *y, const float *u) {
    float states[{{ upper }}_STATES];
    {{ name }}_saturation state_flags[{{ upper }}_STATES];
    if (!accepts(y, u)) {
        if (inputs_finite(u)) {
            ekf_predict(o->x, o->p, u);
        }
        return {{ upper }}_REFUSED;
    }
    if (!o->checked && restart_check(o, y, u)) {
        return {{ upper }}_OK;
    }
    if (!started_ekf_follow(o->x, o->p, 1u, 0, NULL, y, u, states, state_flags)) {
        return {{ upper }}_REFUSED;
    }
    started_ekf_targets_of(states, state_flags, u, o->values, o->flags);
    o->ready = 1;
    return {{ upper }}_OK;
}

{% include "c/counted.c" %}
