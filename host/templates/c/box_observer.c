{# A filter from the box centre: `push` of the filter, then the targets of
   its estimate, each inside. -#}
{# `_fresh`: the filter at its start (at init, and where a step was not finite: a restart). #}
static void {{ kind }}_fresh({{ name }}_{{ kind }} *o) {
    memcpy(o->x, {{ label }}_X0, sizeof o->x);
    memcpy(o->p, {{ label }}_P0, sizeof o->p);
{%- if let Some(w) = watch %}
    o->chi = {{ w.start }};
{%- endif %}
}

static {{ name }}_status {{ kind }}_sample({{ name }}_{{ kind }} *o, const float *y, const float *u) {
    float estimate[{{ upper }}_STATES];
    float nis;
    unsigned i;
    if (!inputs_finite(u)) {
        return {{ upper }}_REFUSED;
    }
    if (!accepts(y, u)) {
        {{ lower }}_predict(o->x, o->p, u);
        return {{ upper }}_REFUSED;
    }
    if (!{{ lower }}_measure(o->x, o->p, y, u, estimate, &nis)) {
        {{ kind }}_fresh(o);
        return {{ upper }}_RESTARTED;
    }
{%- if let Some(w) = watch %}
    /* The chi-squared watch (firmware::watch): the mean of the normalised innovations squared. */
    o->chi = o->chi + {{ w.gain }} * (nis - o->chi);
    if (!(o->chi <= {{ w.limit }})) {
        {{ kind }}_fresh(o);
        return {{ upper }}_RESTARTED;
    }
{%- else %}
    (void)nis;
{%- endif %}
    {{ targets }}(estimate, u, o->values);
    for (i = 0u; i < {{ upper }}_TARGETS; ++i) {
        o->flags[i] = {{ upper }}_INSIDE;
    }
    o->ready = 1;
    return {{ upper }}_OK;
}

{% include "c/counted.c" %}
