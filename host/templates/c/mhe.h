{# The moving-horizon observer's part of the header: its struct and its functions' prototypes. -#}
/* The moving-horizon estimate (kind mhe, the Rust MheObserver): at every sample, {{ iterations }} Gauss-Newton
 * step(s) over the last {{ upper }}_HORIZON samples from the previous solution moved one sample on, each
 * solved by an L D L^T factorisation and projected onto the learning box. Thousands of instructions
 * per sample (docs/chip.md): the on-line estimate the map replaces. */
typedef struct {
    float y[2u * {{ upper }}_HORIZON][{{ upper }}_OUTPUTS];
{%- if inputs %}
    float u[2u * {{ upper }}_HORIZON][{{ upper }}_INPUTS];
{%- endif %}
    unsigned next;
    unsigned filled;
    float solved[{{ upper }}_STATES];
    int has_solved;
    float values[{{ upper }}_TARGETS];
    {{ name }}_saturation flags[{{ upper }}_TARGETS];
    int ready;
} {{ name }}_mhe;

void {{ name }}_mhe_init({{ name }}_mhe *observer);
{{ name }}_status {{ name }}_mhe_push({{ name }}_mhe *observer, const float *y, const float *u);
{{ name }}_status {{ name }}_mhe_estimate(const {{ name }}_mhe *observer, float *values, {{ name }}_saturation *saturation);


