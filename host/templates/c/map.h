{# The map's part of the header: its struct (the window) and its functions' prototypes. -#}
/* The map observer: the last {{ upper }}_HORIZON samples, each stored twice so that the window is
 * always contiguous. Allocate it anywhere (no heap is used) and call {{ name }}_map_init. */
typedef struct {
    float y[2u * {{ upper }}_HORIZON][{{ upper }}_OUTPUTS];
{%- if inputs %}
    float u[2u * {{ upper }}_HORIZON][{{ upper }}_INPUTS];
{%- endif %}
    unsigned next;
    unsigned filled;
} {{ name }}_map;

/* Empties the window (a fresh observer, or a new run). */
void {{ name }}_map_init({{ name }}_map *observer);

/* Takes the sample of the current instant: y[{{ upper }}_OUTPUTS] and u[{{ upper }}_INPUTS] (u may be
 * NULL when there is no input). {{ upper }}_OK, or {{ upper }}_REFUSED for a NaN or infinite value
 * (the observer is unchanged). */
{{ name }}_status {{ name }}_map_push({{ name }}_map *observer, const float *y, const float *u);

/* The estimate of every target from the last {{ upper }}_HORIZON samples into values[{{ upper }}_TARGETS]
 * and saturation[{{ upper }}_TARGETS]; {{ upper }}_NO_ESTIMATE_YET (nothing written) before the window is full. */
{{ name }}_status {{ name }}_map_estimate(const {{ name }}_map *observer, float *values, {{ name }}_saturation *saturation);


