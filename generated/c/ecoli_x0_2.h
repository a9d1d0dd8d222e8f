/* The `ecoli_x0_2` observer in C99, emitted by `mho gen` from the same tables as the Rust design file.
 * Do not edit: regenerate. Build with -ffp-contract=off (no fused multiply-add) to get the Rust
 * observer's bits. */
#ifndef ECOLI_X0_2_H
#define ECOLI_X0_2_H

#define ECOLI_X0_2_OUTPUTS 2u
#define ECOLI_X0_2_INPUTS 0u
#define ECOLI_X0_2_TARGETS 2u
/* The map's window, in samples: no estimate before it is full. */
#define ECOLI_X0_2_HORIZON 3u

/* What push and estimate return. */
typedef enum {
    ECOLI_X0_2_OK = 0,
    /* The sample has a NaN or infinite value and was refused; the observer is unchanged. */
    ECOLI_X0_2_REFUSED = 1,
    /* Fewer than ECOLI_X0_2_HORIZON accepted samples since init. */
    ECOLI_X0_2_NO_ESTIMATE_YET = 2
} ecoli_x0_2_status;

/* Where an estimate lies against the map's range: inside, or held at its low or high end. */
typedef enum {
    ECOLI_X0_2_INSIDE = 0,
    ECOLI_X0_2_LOW = 1,
    ECOLI_X0_2_HIGH = 2
} ecoli_x0_2_saturation;

/* The map observer: the last ECOLI_X0_2_HORIZON samples, each stored twice so that the window is
 * always contiguous. Allocate it anywhere (no heap is used) and call ecoli_x0_2_map_init. */
typedef struct {
    float y[2u * ECOLI_X0_2_HORIZON][ECOLI_X0_2_OUTPUTS];
    unsigned next;
    unsigned filled;
} ecoli_x0_2_map;

/* Empties the window (a fresh observer, or a new run). */
void ecoli_x0_2_map_init(ecoli_x0_2_map *observer);

/* Takes the sample of the current instant: y[ECOLI_X0_2_OUTPUTS] and u[ECOLI_X0_2_INPUTS] (u may be
 * NULL when there is no input). ECOLI_X0_2_OK, or ECOLI_X0_2_REFUSED for a NaN or infinite value. */
ecoli_x0_2_status ecoli_x0_2_map_push(ecoli_x0_2_map *observer, const float *y, const float *u);

/* The estimate of every target from the last ECOLI_X0_2_HORIZON samples into values[ECOLI_X0_2_TARGETS]
 * and saturation[ECOLI_X0_2_TARGETS]; ECOLI_X0_2_NO_ESTIMATE_YET (nothing written) before the window is full. */
ecoli_x0_2_status ecoli_x0_2_map_estimate(const ecoli_x0_2_map *observer, float *values, ecoli_x0_2_saturation *saturation);

#endif
