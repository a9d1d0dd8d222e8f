{# The integer map's part of the header: its samples' ranges, its estimates' scales, its struct and
   its functions' prototypes. -#}
/* The map in integers, for chips without an FPU: raw converter counts in, each estimate an
 * integer in its target's LSB out, no float operation. Samples (a sample with a value outside
 * its range is refused: the proof that no sum overflows holds there):
{{ ranges }} * Estimates (value = integer * LSB, in the target's unit):
{{ targets }} * Allocate it anywhere (no heap is used) and call {{ name }}_fixed_init. */
/* Estimate t's scale, in its target's unit: value = integer * 2^{{ upper }}_FIXED_LSB_EXPONENT_t,
 * which is integer * {{ upper }}_FIXED_LSB_t (a float, exact: a power of two). */
{{ scales }}typedef struct {
    int32_t y[2u * {{ upper }}_HORIZON][{{ upper }}_OUTPUTS];
{%- if inputs %}
    int32_t u[2u * {{ upper }}_HORIZON][{{ upper }}_INPUTS];
{%- endif %}
    unsigned next;
    unsigned filled;
} {{ name }}_fixed;

/* Empties the window. */
void {{ name }}_fixed_init({{ name }}_fixed *observer);

/* Takes the raw sample of the current instant (u may be NULL when there is no input): {{ upper }}_OK,
 * or {{ upper }}_REFUSED for a value outside its range (the observer is unchanged). */
{{ name }}_status {{ name }}_fixed_push({{ name }}_fixed *observer, const int32_t *y, const int32_t *u);

/* Every target's estimate (in its LSB) into values[{{ upper }}_TARGETS] and saturation[{{ upper }}_TARGETS];
 * {{ upper }}_NO_ESTIMATE_YET (nothing written) before the window is full. */
{{ name }}_status {{ name }}_fixed_estimate(const {{ name }}_fixed *observer, int32_t *values, {{ name }}_saturation *saturation);


