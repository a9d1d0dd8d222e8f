/* The `vanderpol_uncertain` observer in C99, emitted by `mho gen` from the same tables as the Rust design file.
 * Do not edit: regenerate. Build with -ffp-contract=off (no fused multiply-add) to get the Rust
 * observer's bits. */
#ifndef VANDERPOL_UNCERTAIN_H
#define VANDERPOL_UNCERTAIN_H

#define VANDERPOL_UNCERTAIN_OUTPUTS 1u
#define VANDERPOL_UNCERTAIN_INPUTS 0u
#define VANDERPOL_UNCERTAIN_TARGETS 2u
/* The map's window, in samples: no estimate before it is full. */
#define VANDERPOL_UNCERTAIN_HORIZON 10u

/* What push and estimate return. */
typedef enum {
    VANDERPOL_UNCERTAIN_OK = 0,
    /* The sample has a NaN or infinite value and was refused; the observer is unchanged. */
    VANDERPOL_UNCERTAIN_REFUSED = 1,
    /* Fewer than VANDERPOL_UNCERTAIN_HORIZON accepted samples since init. */
    VANDERPOL_UNCERTAIN_NO_ESTIMATE_YET = 2
} vanderpol_uncertain_status;

/* Where an estimate lies against the map's range: inside, or held at its low or high end. */
typedef enum {
    VANDERPOL_UNCERTAIN_INSIDE = 0,
    VANDERPOL_UNCERTAIN_LOW = 1,
    VANDERPOL_UNCERTAIN_HIGH = 2
} vanderpol_uncertain_saturation;

/* The map observer: the last VANDERPOL_UNCERTAIN_HORIZON samples, each stored twice so that the window is
 * always contiguous. Allocate it anywhere (no heap is used) and call vanderpol_uncertain_map_init. */
typedef struct {
    float y[2u * VANDERPOL_UNCERTAIN_HORIZON][VANDERPOL_UNCERTAIN_OUTPUTS];
    unsigned next;
    unsigned filled;
} vanderpol_uncertain_map;

/* Empties the window (a fresh observer, or a new run). */
void vanderpol_uncertain_map_init(vanderpol_uncertain_map *observer);

/* Takes the sample of the current instant: y[VANDERPOL_UNCERTAIN_OUTPUTS] and u[VANDERPOL_UNCERTAIN_INPUTS] (u may be
 * NULL when there is no input). VANDERPOL_UNCERTAIN_OK, or VANDERPOL_UNCERTAIN_REFUSED for a NaN or infinite value. */
vanderpol_uncertain_status vanderpol_uncertain_map_push(vanderpol_uncertain_map *observer, const float *y, const float *u);

/* The estimate of every target from the last VANDERPOL_UNCERTAIN_HORIZON samples into values[VANDERPOL_UNCERTAIN_TARGETS]
 * and saturation[VANDERPOL_UNCERTAIN_TARGETS]; VANDERPOL_UNCERTAIN_NO_ESTIMATE_YET (nothing written) before the window is full. */
vanderpol_uncertain_status vanderpol_uncertain_map_estimate(const vanderpol_uncertain_map *observer, float *values, vanderpol_uncertain_saturation *saturation);

#endif
