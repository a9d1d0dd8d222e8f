/* The `vanderpol` observer in C99, emitted by `mho gen` from the same tables as the Rust design file.
 * Do not edit: regenerate. Build with -ffp-contract=off (no fused multiply-add) to get the Rust
 * observer's bits. */
#ifndef VANDERPOL_H
#define VANDERPOL_H

#define VANDERPOL_OUTPUTS 1u
#define VANDERPOL_INPUTS 0u
#define VANDERPOL_TARGETS 2u
/* The map's window, in samples: no estimate before it is full. */
#define VANDERPOL_HORIZON 10u

/* What push and estimate return. */
typedef enum {
    VANDERPOL_OK = 0,
    /* The sample has a NaN or infinite value and was refused; the observer is unchanged. */
    VANDERPOL_REFUSED = 1,
    /* Fewer than VANDERPOL_HORIZON accepted samples since init. */
    VANDERPOL_NO_ESTIMATE_YET = 2
} vanderpol_status;

/* Where an estimate lies against the map's range: inside, or held at its low or high end. */
typedef enum {
    VANDERPOL_INSIDE = 0,
    VANDERPOL_LOW = 1,
    VANDERPOL_HIGH = 2
} vanderpol_saturation;

/* The map observer: the last VANDERPOL_HORIZON samples, each stored twice so that the window is
 * always contiguous. Allocate it anywhere (no heap is used) and call vanderpol_map_init. */
typedef struct {
    float y[2u * VANDERPOL_HORIZON][VANDERPOL_OUTPUTS];
    unsigned next;
    unsigned filled;
} vanderpol_map;

/* Empties the window (a fresh observer, or a new run). */
void vanderpol_map_init(vanderpol_map *observer);

/* Takes the sample of the current instant: y[VANDERPOL_OUTPUTS] and u[VANDERPOL_INPUTS] (u may be
 * NULL when there is no input). VANDERPOL_OK, or VANDERPOL_REFUSED for a NaN or infinite value. */
vanderpol_status vanderpol_map_push(vanderpol_map *observer, const float *y, const float *u);

/* The estimate of every target from the last VANDERPOL_HORIZON samples into values[VANDERPOL_TARGETS]
 * and saturation[VANDERPOL_TARGETS]; VANDERPOL_NO_ESTIMATE_YET (nothing written) before the window is full. */
vanderpol_status vanderpol_map_estimate(const vanderpol_map *observer, float *values, vanderpol_saturation *saturation);

#endif
