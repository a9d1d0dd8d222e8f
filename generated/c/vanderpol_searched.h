/* The `vanderpol_searched` observer in C99, emitted by `mho gen` from the same tables as the Rust design file.
 * Do not edit: regenerate. Build with -ffp-contract=off (no fused multiply-add) to get the Rust
 * observer's bits. */
#ifndef VANDERPOL_SEARCHED_H
#define VANDERPOL_SEARCHED_H

#define VANDERPOL_SEARCHED_OUTPUTS 1u
#define VANDERPOL_SEARCHED_INPUTS 0u
#define VANDERPOL_SEARCHED_TARGETS 2u
/* The map's window, in samples: no estimate before it is full. */
#define VANDERPOL_SEARCHED_HORIZON 16u

/* What push and estimate return. */
typedef enum {
    VANDERPOL_SEARCHED_OK = 0,
    /* The sample has a NaN or infinite value and was refused; the observer is unchanged. */
    VANDERPOL_SEARCHED_REFUSED = 1,
    /* Fewer than VANDERPOL_SEARCHED_HORIZON accepted samples since init. */
    VANDERPOL_SEARCHED_NO_ESTIMATE_YET = 2
} vanderpol_searched_status;

/* Where an estimate lies against the map's range: inside, or held at its low or high end. */
typedef enum {
    VANDERPOL_SEARCHED_INSIDE = 0,
    VANDERPOL_SEARCHED_LOW = 1,
    VANDERPOL_SEARCHED_HIGH = 2
} vanderpol_searched_saturation;

/* The map observer: the last VANDERPOL_SEARCHED_HORIZON samples, each stored twice so that the window is
 * always contiguous. Allocate it anywhere (no heap is used) and call vanderpol_searched_map_init. */
typedef struct {
    float y[2u * VANDERPOL_SEARCHED_HORIZON][VANDERPOL_SEARCHED_OUTPUTS];
    unsigned next;
    unsigned filled;
} vanderpol_searched_map;

/* Empties the window (a fresh observer, or a new run). */
void vanderpol_searched_map_init(vanderpol_searched_map *observer);

/* Takes the sample of the current instant: y[VANDERPOL_SEARCHED_OUTPUTS] and u[VANDERPOL_SEARCHED_INPUTS] (u may be
 * NULL when there is no input). VANDERPOL_SEARCHED_OK, or VANDERPOL_SEARCHED_REFUSED for a NaN or infinite value. */
vanderpol_searched_status vanderpol_searched_map_push(vanderpol_searched_map *observer, const float *y, const float *u);

/* The estimate of every target from the last VANDERPOL_SEARCHED_HORIZON samples into values[VANDERPOL_SEARCHED_TARGETS]
 * and saturation[VANDERPOL_SEARCHED_TARGETS]; VANDERPOL_SEARCHED_NO_ESTIMATE_YET (nothing written) before the window is full. */
vanderpol_searched_status vanderpol_searched_map_estimate(const vanderpol_searched_map *observer, float *values, vanderpol_searched_saturation *saturation);

#endif
