{# The integer map's part of the source: its integers, the table's evaluation and its three functions. -#}
{{ tables }}
/* Signed right shifts must be arithmetic (implementation-defined in C99; so on gcc, clang, armcc
 * and IAR): checked at compile time. */
typedef char fixed_shifts_are_arithmetic[((-8) >> 1) == -4 ? 1 : -1];

/* a - b modulo 2^32 (no signed overflow, which C leaves undefined): t_last - t for any t. */
static int32_t wrapping_sub(int32_t a, int32_t b) {
    return (int32_t)((uint32_t)a - (uint32_t)b);
}

/* min <= v <= max, as one unsigned comparison. */
static int in_range(int32_t v, int32_t min, int32_t max) {
    return (uint32_t)v - (uint32_t)min <= (uint32_t)max - (uint32_t)min;
}

/* firmware::fixed::FixedTable::evaluate: t clamped to the table [0, t_last] by sign masks (no
 * branch: the same instructions whatever t is), then the segment and the position in it by shifts. */
static void fixed_evaluate(int32_t t, const int32_t segments[][2], unsigned f, unsigned dropped, unsigned p,
                           int32_t t_last, int32_t *value, {{ name }}_saturation *saturation) {
    const int32_t low = t >> 31;
    const int32_t high = (wrapping_sub(t_last, t) >> 31) & ~low;
    int32_t k;
    int32_t position;
    t &= ~low;
    t ^= (t ^ t_last) & high;
    k = t >> f;
    position = (t - (int32_t)((uint32_t)k << f)) >> dropped;
    *value = segments[k][0] + ((segments[k][1] * position) >> p);
    *saturation = ({{ name }}_saturation)((unsigned)(low & 1) | ((unsigned)high & 2u));
}

void {{ name }}_fixed_init({{ name }}_fixed *observer) {
    observer->next = 0u;
    observer->filled = 0u;
}

{{ name }}_status {{ name }}_fixed_push({{ name }}_fixed *observer, const int32_t *y, const int32_t *u) {
    unsigned i;
    unsigned slot;
    int inside = 1;
{{ checks }}    if (!inside) {
        return {{ upper }}_REFUSED;
    }
{% include "c/window_store.c" %}}

/* The sums are in int32_t: every stored sample is in range, where the proof says they fit. */
{{ name }}_status {{ name }}_fixed_estimate(const {{ name }}_fixed *observer, int32_t *values, {{ name }}_saturation *saturation) {
    const unsigned next = observer->next;
    if (observer->filled < {{ upper }}_HORIZON) {
        return {{ upper }}_NO_ESTIMATE_YET;
    }
{{ projections }}{{ estimates }}    return {{ upper }}_OK;
}


