{# A design's C header (`<name>.h`): sizes, statuses, then each piece's declarations. -#}
/* The `{{ name }}` observers in C99, emitted by `mho gen` from the same tables and programs as the
 * Rust design file. Do not edit: regenerate. Build with -ffp-contract=off (no fused
 * multiply-add) to get the Rust observers' bits. Every observer lives in a struct you allocate
 * (no heap); call its _init first, then _push every sample and _estimate when you need it.
{{ licence }} */
#ifndef {{ upper }}_H
#define {{ upper }}_H

#include <stddef.h>
#include <stdint.h>

/* C linkage for a C++ program that includes this header (the observers are compiled as C). */
#ifdef __cplusplus
extern "C" {
#endif

#define {{ upper }}_OUTPUTS {{ ny }}
#define {{ upper }}_INPUTS {{ nu }}
#define {{ upper }}_TARGETS {{ nt }}
/* The map's window, in samples: no map estimate before it is full. */
#define {{ upper }}_HORIZON {{ n }}
/* The sample period the design assumes, in its time unit: push one sample every period. */
#define {{ upper }}_SAMPLE_PERIOD {{ tau }}
{%- if let Some((states, covariance)) = sizes %}
#define {{ upper }}_STATES {{ states }}
/* Entries of a filter's covariance kept: its upper triangle. */
#define {{ upper }}_COVARIANCE {{ covariance }}
{%- endif %}

/* What every call returns: the observers' push and estimate, and the storage calls (the same
 * values as the Rust static library's c/include/{{ name }}.h). */
typedef enum {
    {{ upper }}_OK = 0,
    /* The sample was refused: a NaN or infinite value; the latest estimate is unchanged. */
    {{ upper }}_REFUSED = 1,
    /* No estimate yet (the map: fewer than {{ upper }}_HORIZON accepted samples since init). */
    {{ upper }}_NO_ESTIMATE_YET = 2,
    /* The storage calls only: a null pointer, or storage too small or misaligned; nothing done. */
    {{ upper }}_BAD_ARGUMENT = 3,
    /* The storage calls only: the storage holds no observer of this design. */
    {{ upper }}_NOT_INITIALISED = 4,
    /* The sample's values were finite but the observer's step was not: it restarted (a filter from
     * its start or from the map, the moving-horizon estimate from its start); the latest estimate is
     * unchanged. Counted in the observer's `restarts`. */
    {{ upper }}_RESTARTED = 5
} {{ name }}_status;

/* Where an estimate lies against its range: inside, or held at its low or high end (the same
 * values from every call that reports it). */
typedef enum {
    {{ upper }}_INSIDE = 0,
    {{ upper }}_LOW = 1,
    {{ upper }}_HIGH = 2
} {{ name }}_saturation;

{{ map_header }}{{ fixed_header }}{{ kinds_header }}{{ alias }}{{ interface_header }}#ifdef __cplusplus
}
#endif

#endif

