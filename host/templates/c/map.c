{# The map's part of the source: its tables, the table's evaluation (a uniform table's segment where one
   is used) and its three functions. The check of a sample is written out rather than a call of
   `accepts`, which the compiler keeps out of line where the followers call it too (about 10
   instructions more per sample). -#}
{{ tables }}
{% if uniform -%}
/* floor(t) for 0 <= t, at most count - 1: a uniform table's segment. Any other t (negative, NaN,
 * infinite) gives some segment, whose value evaluate replaces by r_min or r_max. The clamp is an
 * unsigned minimum of the bits of |t|, which are ordered as the values: the conversion is always
 * defined, and the same instructions run whatever t is. */
static uint32_t uniform_segment(float t, uint32_t count) {
    const uint32_t magnitude = bits_of(t) & 0x7fffffffu;
    const uint32_t last = bits_of((float)(count - 1u));
    const uint32_t least = magnitude < last ? magnitude : last;
    float clamped;
    memcpy(&clamped, &least, sizeof clamped);
    return (uint32_t)clamped;
}

{% endif -%}
/* r(t) on one segment (a, b) starting at `start`, held at r_min below 0 (or NaN) and r_max above
 * t_max (t_max >= 0: never both); as firmware::InverseTable, by one select per statement, which
 * compilers make a conditional move (an IT block on Thumb-2): the same instructions whatever t is. */
static void evaluate(float t, const float *segment, float start, float t_max, float r_min, float r_max,
                     float *value, {{ name }}_saturation *saturation) {
    const int low = !(t >= 0.0f);
    const int high = t > t_max;
    float r = segment[0] + segment[1] * (t - start);
    r = choose_float(high, r_max, r);
    r = choose_float(low, r_min, r);
    *value = r;
    *saturation = ({{ name }}_saturation)((unsigned)low | (unsigned)high << 1);
}

void {{ name }}_map_init({{ name }}_map *observer) {
    observer->next = 0u;
    observer->filled = 0u;
}

{{ name }}_status {{ name }}_map_push({{ name }}_map *observer, const float *y, const float *u) {
    unsigned i;
    unsigned slot;
    int finite = 1;
    for (i = 0u; i < {{ upper }}_OUTPUTS; ++i) {
        finite &= is_finite(y[i]);
    }
{%- if inputs %}
    for (i = 0u; i < {{ upper }}_INPUTS; ++i) {
        finite &= is_finite(u[i]);
    }
{%- endif %}
    if (!finite) {
        return {{ upper }}_REFUSED;
    }
{% include "c/window_store.c" %}}

{{ name }}_status {{ name }}_map_estimate(const {{ name }}_map *observer, float *values, {{ name }}_saturation *saturation) {
    const unsigned next = observer->next;
    if (observer->filled < {{ upper }}_HORIZON) {
        return {{ upper }}_NO_ESTIMATE_YET;
    }
{{ projections }}{{ estimates }}    return {{ upper }}_OK;
}


