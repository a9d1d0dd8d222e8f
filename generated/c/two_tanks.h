/* The `two_tanks` observer in C99, emitted by `mho gen` from the same tables as the Rust design file.
 * Do not edit: regenerate. Build with -ffp-contract=off (no fused multiply-add) to get the Rust
 * observer's bits. */
#ifndef TWO_TANKS_H
#define TWO_TANKS_H

#define TWO_TANKS_OUTPUTS 1u
#define TWO_TANKS_INPUTS 1u
#define TWO_TANKS_TARGETS 2u
/* The map's window, in samples: no estimate before it is full. */
#define TWO_TANKS_HORIZON 10u

/* What push and estimate return. */
typedef enum {
    TWO_TANKS_OK = 0,
    /* The sample has a NaN or infinite value and was refused; the observer is unchanged. */
    TWO_TANKS_REFUSED = 1,
    /* Fewer than TWO_TANKS_HORIZON accepted samples since init. */
    TWO_TANKS_NO_ESTIMATE_YET = 2
} two_tanks_status;

/* Where an estimate lies against the map's range: inside, or held at its low or high end. */
typedef enum {
    TWO_TANKS_INSIDE = 0,
    TWO_TANKS_LOW = 1,
    TWO_TANKS_HIGH = 2
} two_tanks_saturation;

/* The map observer: the last TWO_TANKS_HORIZON samples, each stored twice so that the window is
 * always contiguous. Allocate it anywhere (no heap is used) and call two_tanks_map_init. */
typedef struct {
    float y[2u * TWO_TANKS_HORIZON][TWO_TANKS_OUTPUTS];
    float u[2u * TWO_TANKS_HORIZON][TWO_TANKS_INPUTS];
    unsigned next;
    unsigned filled;
} two_tanks_map;

/* Empties the window (a fresh observer, or a new run). */
void two_tanks_map_init(two_tanks_map *observer);

/* Takes the sample of the current instant: y[TWO_TANKS_OUTPUTS] and u[TWO_TANKS_INPUTS] (u may be
 * NULL when there is no input). TWO_TANKS_OK, or TWO_TANKS_REFUSED for a NaN or infinite value. */
two_tanks_status two_tanks_map_push(two_tanks_map *observer, const float *y, const float *u);

/* The estimate of every target from the last TWO_TANKS_HORIZON samples into values[TWO_TANKS_TARGETS]
 * and saturation[TWO_TANKS_TARGETS]; TWO_TANKS_NO_ESTIMATE_YET (nothing written) before the window is full. */
two_tanks_status two_tanks_map_estimate(const two_tanks_map *observer, float *values, two_tanks_saturation *saturation);

#endif
