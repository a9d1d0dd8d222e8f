/* The `two_tanks` observers in C99, emitted by `mho gen` from the same tables and programs as the
 * Rust design file. Do not edit: regenerate. Build with -ffp-contract=off (no fused
 * multiply-add) to get the Rust observers' bits. Every observer lives in a struct you allocate
 * (no heap); call its _init first, then _push every sample and _estimate when you need it.
 * Licence: emitted by mho from your spec, this file is yours: you may use, copy, modify and
 * distribute it under any terms, including MIT OR Apache-2.0, with or without this notice. */
#ifndef TWO_TANKS_H
#define TWO_TANKS_H

#include <stddef.h>
#include <stdint.h>

/* C linkage for a C++ program that includes this header (the observers are compiled as C). */
#ifdef __cplusplus
extern "C" {
#endif

#define TWO_TANKS_OUTPUTS 1
#define TWO_TANKS_INPUTS 1
#define TWO_TANKS_TARGETS 2
/* The map's window, in samples: no map estimate before it is full. */
#define TWO_TANKS_HORIZON 10
/* The sample period the design assumes, in its time unit: push one sample every period. */
#define TWO_TANKS_SAMPLE_PERIOD 1.0f
#define TWO_TANKS_STATES 2
/* Entries of a filter's covariance kept: its upper triangle. */
#define TWO_TANKS_COVARIANCE 3

/* What every call returns: the observers' push and estimate, and the storage calls (the same
 * values as the Rust static library's c/include/two_tanks.h). */
typedef enum {
    TWO_TANKS_OK = 0,
    /* The sample was refused: a NaN or infinite value; the latest estimate is unchanged. */
    TWO_TANKS_REFUSED = 1,
    /* No estimate yet (the map: fewer than TWO_TANKS_HORIZON accepted samples since init). */
    TWO_TANKS_NO_ESTIMATE_YET = 2,
    /* The storage calls only: a null pointer, or storage too small or misaligned; nothing done. */
    TWO_TANKS_BAD_ARGUMENT = 3,
    /* The storage calls only: the storage holds no observer of this design. */
    TWO_TANKS_NOT_INITIALISED = 4,
    /* The sample's values were finite but the observer's step was not: it restarted (a filter from
     * its start or from the map, the moving-horizon estimate from its start); the latest estimate is
     * unchanged. Counted in the observer's `restarts`. */
    TWO_TANKS_RESTARTED = 5
} two_tanks_status;

/* Where an estimate lies against its range: inside, or held at its low or high end (the same
 * values from every call that reports it). */
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
 * NULL when there is no input). TWO_TANKS_OK, or TWO_TANKS_REFUSED for a NaN or infinite value
 * (the observer is unchanged). */
two_tanks_status two_tanks_map_push(two_tanks_map *observer, const float *y, const float *u);

/* The estimate of every target from the last TWO_TANKS_HORIZON samples into values[TWO_TANKS_TARGETS]
 * and saturation[TWO_TANKS_TARGETS]; TWO_TANKS_NO_ESTIMATE_YET (nothing written) before the window is full. */
two_tanks_status two_tanks_map_estimate(const two_tanks_map *observer, float *values, two_tanks_saturation *saturation);

/* The map in integers, for chips without an FPU: raw converter counts in, each estimate an
 * integer in its target's LSB out, no float operation. Samples (a sample with a value outside
 * its range is refused: the proof that no sum overflows holds there):
 * y[0] (`y`): raw in [-32767, 32767], value = 0.0 + 0.001953125 * raw
 * u[0] (`u`): raw in [-32767, 32767], value = 0.0 + 0.0009765625 * raw
 * Estimates (value = integer * LSB, in the target's unit):
 * estimate 0 (`h1`): LSB 2^-19, proven |fixed - f64 map| <= 4.16e-2
 * estimate 1 (`h2`): LSB 2^-19, proven |fixed - f64 map| <= 2.06e-2
 * Allocate it anywhere (no heap is used) and call two_tanks_fixed_init. */
/* Estimate t's scale, in its target's unit: value = integer * 2^TWO_TANKS_FIXED_LSB_EXPONENT_t,
 * which is integer * TWO_TANKS_FIXED_LSB_t (a float, exact: a power of two). */
#define TWO_TANKS_FIXED_LSB_EXPONENT_0 (-19)
#define TWO_TANKS_FIXED_LSB_0 1.9073486e-6f
#define TWO_TANKS_FIXED_LSB_EXPONENT_1 (-19)
#define TWO_TANKS_FIXED_LSB_1 1.9073486e-6f
typedef struct {
    int32_t y[2u * TWO_TANKS_HORIZON][TWO_TANKS_OUTPUTS];
    int32_t u[2u * TWO_TANKS_HORIZON][TWO_TANKS_INPUTS];
    unsigned next;
    unsigned filled;
} two_tanks_fixed;

/* Empties the window. */
void two_tanks_fixed_init(two_tanks_fixed *observer);

/* Takes the raw sample of the current instant (u may be NULL when there is no input): TWO_TANKS_OK,
 * or TWO_TANKS_REFUSED for a value outside its range (the observer is unchanged). */
two_tanks_status two_tanks_fixed_push(two_tanks_fixed *observer, const int32_t *y, const int32_t *u);

/* Every target's estimate (in its LSB) into values[TWO_TANKS_TARGETS] and saturation[TWO_TANKS_TARGETS];
 * TWO_TANKS_NO_ESTIMATE_YET (nothing written) before the window is full. */
two_tanks_status two_tanks_fixed_estimate(const two_tanks_fixed *observer, int32_t *values, two_tanks_saturation *saturation);

/* The EKF from the centre of the state box (kind ekf_box, the Rust EkfBoxObserver): an estimate
 * from the first accepted sample; a sample with a non-finite output is refused and only predicted. */
typedef struct {
    float x[TWO_TANKS_STATES];
    float p[TWO_TANKS_COVARIANCE];
    float chi; /* the watched mean of the normalised innovations squared */
    float values[TWO_TANKS_TARGETS];
    two_tanks_saturation flags[TWO_TANKS_TARGETS];
    int ready;
    /* Samples refused since init for a bad value (a NaN or infinite input or output); saturates. */
    uint32_t refused;
    /* Restarts since init: samples with finite values whose step was not finite; saturates. */
    uint32_t restarts;
} two_tanks_ekf_box;

void two_tanks_ekf_box_init(two_tanks_ekf_box *observer);
two_tanks_status two_tanks_ekf_box_push(two_tanks_ekf_box *observer, const float *y, const float *u);
two_tanks_status two_tanks_ekf_box_estimate(const two_tanks_ekf_box *observer, float *values, two_tanks_saturation *saturation);

/* The unscented Kalman filter from the centre of the state box (kind ukf_box, the Rust
 * UkfBoxObserver): an estimate from the first accepted sample; a sample with a non-finite output
 * is refused and only predicted. */
typedef struct {
    float x[TWO_TANKS_STATES];
    float p[TWO_TANKS_COVARIANCE];
    float chi; /* the watched mean of the normalised innovations squared */
    float values[TWO_TANKS_TARGETS];
    two_tanks_saturation flags[TWO_TANKS_TARGETS];
    int ready;
    /* Samples refused since init for a bad value (a NaN or infinite input or output); saturates. */
    uint32_t refused;
    /* Restarts since init: samples with finite values whose step was not finite; saturates. */
    uint32_t restarts;
} two_tanks_ukf_box;

void two_tanks_ukf_box_init(two_tanks_ukf_box *observer);
two_tanks_status two_tanks_ukf_box_push(two_tanks_ukf_box *observer, const float *y, const float *u);
two_tanks_status two_tanks_ukf_box_estimate(const two_tanks_ukf_box *observer, float *values, two_tanks_saturation *saturation);

/* The model-corrected map (kind corrected, the Rust CorrectedObserver): the map's first estimate,
 * then the model's prediction corrected by the output and, during the start-up, blended with the
 * map; each state clamped to its learning range (flagged LOW or HIGH). */
typedef struct {
    two_tanks_map window;
    float x[TWO_TANKS_STATES];
    unsigned count;
    int started;
    float values[TWO_TANKS_TARGETS];
    two_tanks_saturation flags[TWO_TANKS_TARGETS];
    int ready;
    /* Samples refused since init for a bad value (a NaN or infinite input or output); saturates. */
    uint32_t refused;
    /* Restarts since init: samples with finite values whose step was not finite; saturates. */
    uint32_t restarts;
} two_tanks_corrected;

void two_tanks_corrected_init(two_tanks_corrected *observer);
two_tanks_status two_tanks_corrected_push(two_tanks_corrected *observer, const float *y, const float *u);
two_tanks_status two_tanks_corrected_estimate(const two_tanks_corrected *observer, float *values, two_tanks_saturation *saturation);

/* The EKF started at the map's first estimate (kind ekf_map, the Rust EkfMapObserver). */
typedef struct {
    two_tanks_map window;
    float x[TWO_TANKS_STATES];
    float p[TWO_TANKS_COVARIANCE];
    float chi;
    unsigned count;
    int started;
    float values[TWO_TANKS_TARGETS];
    two_tanks_saturation flags[TWO_TANKS_TARGETS];
    int ready;
    /* Samples refused since init for a bad value (a NaN or infinite input or output); saturates. */
    uint32_t refused;
    /* Restarts since init: samples with finite values whose step was not finite; saturates. */
    uint32_t restarts;
} two_tanks_ekf_map;

void two_tanks_ekf_map_init(two_tanks_ekf_map *observer);
two_tanks_status two_tanks_ekf_map_push(two_tanks_ekf_map *observer, const float *y, const float *u);
two_tanks_status two_tanks_ekf_map_estimate(const two_tanks_ekf_map *observer, float *values, two_tanks_saturation *saturation);

/* The EKF from the box centre that the map watches at every sample from its first estimate on,
 * restarted from it where the two disagree (kind ekf_restart, the Rust EkfRestartObserver). */
typedef struct {
    two_tanks_map window;
    float x[TWO_TANKS_STATES];
    float p[TWO_TANKS_COVARIANCE];
    float chi;
    float values[TWO_TANKS_TARGETS];
    two_tanks_saturation flags[TWO_TANKS_TARGETS];
    int ready;
    /* Samples refused since init for a bad value (a NaN or infinite input or output); saturates. */
    uint32_t refused;
    /* Restarts since init: samples with finite values whose step was not finite; saturates. */
    uint32_t restarts;
} two_tanks_ekf_restart;

void two_tanks_ekf_restart_init(two_tanks_ekf_restart *observer);
two_tanks_status two_tanks_ekf_restart_push(two_tanks_ekf_restart *observer, const float *y, const float *u);
two_tanks_status two_tanks_ekf_restart_estimate(const two_tanks_ekf_restart *observer, float *values, two_tanks_saturation *saturation);

/* The moving-horizon estimate (kind mhe, the Rust MheObserver): at every sample, 2 Gauss-Newton
 * step(s) over the last TWO_TANKS_HORIZON samples from the previous solution moved one sample on, each
 * solved by an L D L^T factorisation and projected onto the learning box. Thousands of instructions
 * per sample (docs/chip.md): the on-line estimate the map replaces. */
typedef struct {
    float y[2u * TWO_TANKS_HORIZON][TWO_TANKS_OUTPUTS];
    float u[2u * TWO_TANKS_HORIZON][TWO_TANKS_INPUTS];
    unsigned next;
    unsigned filled;
    float solved[TWO_TANKS_STATES];
    int has_solved;
    float values[TWO_TANKS_TARGETS];
    two_tanks_saturation flags[TWO_TANKS_TARGETS];
    int ready;
    /* The watched mean of the windows' output costs (firmware::watch), once a window was solved
     * since the last (re)start. */
    float chi;
    int has_chi;
    /* Restarts since init: samples whose solution was not finite, or whose watch found the windows
     * implausible (the next window is then solved from the start); saturates. */
    uint32_t restarts;
} two_tanks_mhe;

void two_tanks_mhe_init(two_tanks_mhe *observer);
two_tanks_status two_tanks_mhe_push(two_tanks_mhe *observer, const float *y, const float *u);
two_tanks_status two_tanks_mhe_estimate(const two_tanks_mhe *observer, float *values, two_tanks_saturation *saturation);

/* This design's observer, of the kind `gen` chose or the spec named: corrected. */
#define TWO_TANKS_KIND "corrected"
typedef two_tanks_corrected two_tanks_observer;
#define two_tanks_observer_init two_tanks_corrected_init
#define two_tanks_observer_push two_tanks_corrected_push
#define two_tanks_observer_estimate two_tanks_corrected_estimate

/* The Rust static library's interface (c/include/two_tanks.h of a crate `mho gen --spec` writes) over
 * two_tanks_observer: the same calls, statuses (two_tanks_status) and flags (two_tanks_saturation), so
 * that a firmware moves between the two routes without a change. The observer lives in storage you
 * provide, TWO_TANKS_STORAGE_SIZE bytes aligned to TWO_TANKS_STORAGE_ALIGN: `init` writes a mark of the
 * design and the size before it, and every call checks them first. */
#define TWO_TANKS_STORAGE_ALIGN 8
typedef struct {
    uint64_t mark;
    uint64_t size;
    two_tanks_observer observer;
} two_tanks_stored;
#define TWO_TANKS_STORAGE_SIZE 360
/* Does not compile where the observer would not fit in TWO_TANKS_STORAGE_SIZE bytes. */
typedef char two_tanks_storage_fits[sizeof(two_tanks_stored) <= TWO_TANKS_STORAGE_SIZE ? 1 : -1];

/* A fresh observer in storage of `size` bytes; call it again to reset. */
two_tanks_status two_tanks_init(void *storage, size_t size);
/* two_tanks_observer_push on the observer in storage. */
two_tanks_status two_tanks_push(void *storage, const float *y, const float *u);
/* The estimates into estimates[TWO_TANKS_TARGETS] and, unless saturation is NULL, whether each was
 * held at an end of its range into saturation[TWO_TANKS_TARGETS]. */
two_tanks_status two_tanks_estimate(void *storage, float *estimates, two_tanks_saturation *saturation);
/* Bytes the observer occupies with its mark. */
size_t two_tanks_storage_size(void);

#ifdef __cplusplus
}
#endif

#endif
