{# A kind's part of the header: its struct (the map's window when the map starts it, the carried
   `fields`, the latest estimate) and its three functions, documented by `what`. -#}
/* {{ what }} */
typedef struct {
{%- if window %}
    {{ name }}_map window;
{%- endif %}
{{ fields }}    float values[{{ upper }}_TARGETS];
    {{ name }}_saturation flags[{{ upper }}_TARGETS];
    int ready;
    /* Samples refused since init for a bad value (a NaN or infinite input or output); saturates. */
    uint32_t refused;
    /* Restarts since init: samples with finite values whose step was not finite; saturates. */
    uint32_t restarts;
} {{ name }}_{{ kind }};

void {{ name }}_{{ kind }}_init({{ name }}_{{ kind }} *observer);
{{ name }}_status {{ name }}_{{ kind }}_push({{ name }}_{{ kind }} *observer, const float *y, const float *u);
{{ name }}_status {{ name }}_{{ kind }}_estimate(const {{ name }}_{{ kind }} *observer, float *values, {{ name }}_saturation *saturation);


