/* The `vanderpol_sparse` observer in C99, emitted by `mho gen` from the same tables as the Rust design file.
 * Do not edit: regenerate. Build with -ffp-contract=off (no fused multiply-add) to get the Rust
 * observer's bits. */
#ifndef VANDERPOL_SPARSE_H
#define VANDERPOL_SPARSE_H

#define VANDERPOL_SPARSE_OUTPUTS 1u
#define VANDERPOL_SPARSE_INPUTS 0u
#define VANDERPOL_SPARSE_TARGETS 2u
/* The map's window, in samples: no estimate before it is full. */
#define VANDERPOL_SPARSE_HORIZON 19u

/* What push and estimate return. */
typedef enum {
    VANDERPOL_SPARSE_OK = 0,
    /* The sample has a NaN or infinite value and was refused; the observer is unchanged. */
    VANDERPOL_SPARSE_REFUSED = 1,
    /* Fewer than VANDERPOL_SPARSE_HORIZON accepted samples since init. */
    VANDERPOL_SPARSE_NO_ESTIMATE_YET = 2
} vanderpol_sparse_status;

/* Where an estimate lies against the map's range: inside, or held at its low or high end. */
typedef enum {
    VANDERPOL_SPARSE_INSIDE = 0,
    VANDERPOL_SPARSE_LOW = 1,
    VANDERPOL_SPARSE_HIGH = 2
} vanderpol_sparse_saturation;

/* The map observer: the last VANDERPOL_SPARSE_HORIZON samples, each stored twice so that the window is
 * always contiguous. Allocate it anywhere (no heap is used) and call vanderpol_sparse_map_init. */
typedef struct {
    float y[2u * VANDERPOL_SPARSE_HORIZON][VANDERPOL_SPARSE_OUTPUTS];
    unsigned next;
    unsigned filled;
} vanderpol_sparse_map;

/* Empties the window (a fresh observer, or a new run). */
void vanderpol_sparse_map_init(vanderpol_sparse_map *observer);

/* Takes the sample of the current instant: y[VANDERPOL_SPARSE_OUTPUTS] and u[VANDERPOL_SPARSE_INPUTS] (u may be
 * NULL when there is no input). VANDERPOL_SPARSE_OK, or VANDERPOL_SPARSE_REFUSED for a NaN or infinite value. */
vanderpol_sparse_status vanderpol_sparse_map_push(vanderpol_sparse_map *observer, const float *y, const float *u);

/* The estimate of every target from the last VANDERPOL_SPARSE_HORIZON samples into values[VANDERPOL_SPARSE_TARGETS]
 * and saturation[VANDERPOL_SPARSE_TARGETS]; VANDERPOL_SPARSE_NO_ESTIMATE_YET (nothing written) before the window is full. */
vanderpol_sparse_status vanderpol_sparse_map_estimate(const vanderpol_sparse_map *observer, float *values, vanderpol_sparse_saturation *saturation);

#endif
