/* The `ecoli_x0_0p5` observers in C99, emitted by `mho gen` from the same tables and programs as the
 * Rust design file. Do not edit: regenerate. Build with -ffp-contract=off (no fused
 * multiply-add) to get the Rust observers' bits. Every observer lives in a struct you allocate
 * (no heap); call its _init first, then _push every sample and _estimate when you need it.
 * Licence: emitted by mho from your spec, this file is yours: you may use, copy, modify and
 * distribute it under any terms, including MIT OR Apache-2.0, with or without this notice. */
#ifndef ECOLI_X0_0P5_H
#define ECOLI_X0_0P5_H

#include <stddef.h>
#include <stdint.h>

/* C linkage for a C++ program that includes this header (the observers are compiled as C). */
#ifdef __cplusplus
extern "C" {
#endif

#define ECOLI_X0_0P5_OUTPUTS 2
#define ECOLI_X0_0P5_INPUTS 0
#define ECOLI_X0_0P5_TARGETS 2
/* The map's window, in samples: no map estimate before it is full. */
#define ECOLI_X0_0P5_HORIZON 3
/* The sample period the design assumes, in its time unit: push one sample every period. */
#define ECOLI_X0_0P5_SAMPLE_PERIOD 0.2f
#define ECOLI_X0_0P5_STATES 3
/* Entries of a filter's covariance kept: its upper triangle. */
#define ECOLI_X0_0P5_COVARIANCE 6

/* What every call returns: the observers' push and estimate, and the storage calls (the same
 * values as the Rust static library's c/include/ecoli_x0_0p5.h). */
typedef enum {
    ECOLI_X0_0P5_OK = 0,
    /* The sample was refused: a NaN or infinite value; the latest estimate is unchanged. */
    ECOLI_X0_0P5_REFUSED = 1,
    /* No estimate yet (the map: fewer than ECOLI_X0_0P5_HORIZON accepted samples since init). */
    ECOLI_X0_0P5_NO_ESTIMATE_YET = 2,
    /* The storage calls only: a null pointer, or storage too small or misaligned; nothing done. */
    ECOLI_X0_0P5_BAD_ARGUMENT = 3,
    /* The storage calls only: the storage holds no observer of this design. */
    ECOLI_X0_0P5_NOT_INITIALISED = 4,
    /* The sample's values were finite but the observer's step was not: it restarted (a filter from
     * its start or from the map, the moving-horizon estimate from its start); the latest estimate is
     * unchanged. Counted in the observer's `restarts`. */
    ECOLI_X0_0P5_RESTARTED = 5
} ecoli_x0_0p5_status;

/* Where an estimate lies against its range: inside, or held at its low or high end (the same
 * values from every call that reports it). */
typedef enum {
    ECOLI_X0_0P5_INSIDE = 0,
    ECOLI_X0_0P5_LOW = 1,
    ECOLI_X0_0P5_HIGH = 2
} ecoli_x0_0p5_saturation;

/* The map observer: the last ECOLI_X0_0P5_HORIZON samples, each stored twice so that the window is
 * always contiguous. Allocate it anywhere (no heap is used) and call ecoli_x0_0p5_map_init. */
typedef struct {
    float y[2u * ECOLI_X0_0P5_HORIZON][ECOLI_X0_0P5_OUTPUTS];
    unsigned next;
    unsigned filled;
} ecoli_x0_0p5_map;

/* Empties the window (a fresh observer, or a new run). */
void ecoli_x0_0p5_map_init(ecoli_x0_0p5_map *observer);

/* Takes the sample of the current instant: y[ECOLI_X0_0P5_OUTPUTS] and u[ECOLI_X0_0P5_INPUTS] (u may be
 * NULL when there is no input). ECOLI_X0_0P5_OK, or ECOLI_X0_0P5_REFUSED for a NaN or infinite value
 * (the observer is unchanged). */
ecoli_x0_0p5_status ecoli_x0_0p5_map_push(ecoli_x0_0p5_map *observer, const float *y, const float *u);

/* The estimate of every target from the last ECOLI_X0_0P5_HORIZON samples into values[ECOLI_X0_0P5_TARGETS]
 * and saturation[ECOLI_X0_0P5_TARGETS]; ECOLI_X0_0P5_NO_ESTIMATE_YET (nothing written) before the window is full. */
ecoli_x0_0p5_status ecoli_x0_0p5_map_estimate(const ecoli_x0_0p5_map *observer, float *values, ecoli_x0_0p5_saturation *saturation);

/* The map in integers, for chips without an FPU: raw converter counts in, each estimate an
 * integer in its target's LSB out, no float operation. Samples (a sample with a value outside
 * its range is refused: the proof that no sum overflows holds there):
 * y[0] (`X_meas`): raw in [-32767, 32767], value = 0.0 + 0.000244140625 * raw
 * y[1] (`L`): raw in [-32767, 32767], value = 0.0 + 0.03125 * raw
 * Estimates (value = integer * LSB, in the target's unit):
 * estimate 0 (`P`): LSB 2^-23, proven |fixed - f64 map| <= 3.07e-4
 * estimate 1 (`muX`): LSB 2^-17, proven |fixed - f64 map| <= 2.85e-4
 * Allocate it anywhere (no heap is used) and call ecoli_x0_0p5_fixed_init. */
/* Estimate t's scale, in its target's unit: value = integer * 2^ECOLI_X0_0P5_FIXED_LSB_EXPONENT_t,
 * which is integer * ECOLI_X0_0P5_FIXED_LSB_t (a float, exact: a power of two). */
#define ECOLI_X0_0P5_FIXED_LSB_EXPONENT_0 (-23)
#define ECOLI_X0_0P5_FIXED_LSB_0 1.1920929e-7f
#define ECOLI_X0_0P5_FIXED_LSB_EXPONENT_1 (-17)
#define ECOLI_X0_0P5_FIXED_LSB_1 7.6293945e-6f
typedef struct {
    int32_t y[2u * ECOLI_X0_0P5_HORIZON][ECOLI_X0_0P5_OUTPUTS];
    unsigned next;
    unsigned filled;
} ecoli_x0_0p5_fixed;

/* Empties the window. */
void ecoli_x0_0p5_fixed_init(ecoli_x0_0p5_fixed *observer);

/* Takes the raw sample of the current instant (u may be NULL when there is no input): ECOLI_X0_0P5_OK,
 * or ECOLI_X0_0P5_REFUSED for a value outside its range (the observer is unchanged). */
ecoli_x0_0p5_status ecoli_x0_0p5_fixed_push(ecoli_x0_0p5_fixed *observer, const int32_t *y, const int32_t *u);

/* Every target's estimate (in its LSB) into values[ECOLI_X0_0P5_TARGETS] and saturation[ECOLI_X0_0P5_TARGETS];
 * ECOLI_X0_0P5_NO_ESTIMATE_YET (nothing written) before the window is full. */
ecoli_x0_0p5_status ecoli_x0_0p5_fixed_estimate(const ecoli_x0_0p5_fixed *observer, int32_t *values, ecoli_x0_0p5_saturation *saturation);

/* The EKF from the centre of the state box (kind ekf_box, the Rust EkfBoxObserver): an estimate
 * from the first accepted sample; a sample with a non-finite output is refused and only predicted. */
typedef struct {
    float x[ECOLI_X0_0P5_STATES];
    float p[ECOLI_X0_0P5_COVARIANCE];
    float chi; /* the watched mean of the normalised innovations squared */
    float values[ECOLI_X0_0P5_TARGETS];
    ecoli_x0_0p5_saturation flags[ECOLI_X0_0P5_TARGETS];
    int ready;
    /* Samples refused since init for a bad value (a NaN or infinite input or output); saturates. */
    uint32_t refused;
    /* Restarts since init: samples with finite values whose step was not finite; saturates. */
    uint32_t restarts;
} ecoli_x0_0p5_ekf_box;

void ecoli_x0_0p5_ekf_box_init(ecoli_x0_0p5_ekf_box *observer);
ecoli_x0_0p5_status ecoli_x0_0p5_ekf_box_push(ecoli_x0_0p5_ekf_box *observer, const float *y, const float *u);
ecoli_x0_0p5_status ecoli_x0_0p5_ekf_box_estimate(const ecoli_x0_0p5_ekf_box *observer, float *values, ecoli_x0_0p5_saturation *saturation);

/* The unscented Kalman filter from the centre of the state box (kind ukf_box, the Rust
 * UkfBoxObserver): an estimate from the first accepted sample; a sample with a non-finite output
 * is refused and only predicted. */
typedef struct {
    float x[ECOLI_X0_0P5_STATES];
    float p[ECOLI_X0_0P5_COVARIANCE];
    float chi; /* the watched mean of the normalised innovations squared */
    float values[ECOLI_X0_0P5_TARGETS];
    ecoli_x0_0p5_saturation flags[ECOLI_X0_0P5_TARGETS];
    int ready;
    /* Samples refused since init for a bad value (a NaN or infinite input or output); saturates. */
    uint32_t refused;
    /* Restarts since init: samples with finite values whose step was not finite; saturates. */
    uint32_t restarts;
} ecoli_x0_0p5_ukf_box;

void ecoli_x0_0p5_ukf_box_init(ecoli_x0_0p5_ukf_box *observer);
ecoli_x0_0p5_status ecoli_x0_0p5_ukf_box_push(ecoli_x0_0p5_ukf_box *observer, const float *y, const float *u);
ecoli_x0_0p5_status ecoli_x0_0p5_ukf_box_estimate(const ecoli_x0_0p5_ukf_box *observer, float *values, ecoli_x0_0p5_saturation *saturation);

/* The model-corrected map (kind corrected, the Rust CorrectedObserver): the map's first estimate,
 * then the model's prediction corrected by the output and, during the start-up, blended with the
 * map; each state clamped to its learning range (flagged LOW or HIGH). */
typedef struct {
    ecoli_x0_0p5_map window;
    float x[ECOLI_X0_0P5_STATES];
    unsigned count;
    int started;
    float values[ECOLI_X0_0P5_TARGETS];
    ecoli_x0_0p5_saturation flags[ECOLI_X0_0P5_TARGETS];
    int ready;
    /* Samples refused since init for a bad value (a NaN or infinite input or output); saturates. */
    uint32_t refused;
    /* Restarts since init: samples with finite values whose step was not finite; saturates. */
    uint32_t restarts;
} ecoli_x0_0p5_corrected;

void ecoli_x0_0p5_corrected_init(ecoli_x0_0p5_corrected *observer);
ecoli_x0_0p5_status ecoli_x0_0p5_corrected_push(ecoli_x0_0p5_corrected *observer, const float *y, const float *u);
ecoli_x0_0p5_status ecoli_x0_0p5_corrected_estimate(const ecoli_x0_0p5_corrected *observer, float *values, ecoli_x0_0p5_saturation *saturation);

/* The EKF started at the map's first estimate (kind ekf_map, the Rust EkfMapObserver). */
typedef struct {
    ecoli_x0_0p5_map window;
    float x[ECOLI_X0_0P5_STATES];
    float p[ECOLI_X0_0P5_COVARIANCE];
    float chi;
    unsigned count;
    int started;
    float values[ECOLI_X0_0P5_TARGETS];
    ecoli_x0_0p5_saturation flags[ECOLI_X0_0P5_TARGETS];
    int ready;
    /* Samples refused since init for a bad value (a NaN or infinite input or output); saturates. */
    uint32_t refused;
    /* Restarts since init: samples with finite values whose step was not finite; saturates. */
    uint32_t restarts;
} ecoli_x0_0p5_ekf_map;

void ecoli_x0_0p5_ekf_map_init(ecoli_x0_0p5_ekf_map *observer);
ecoli_x0_0p5_status ecoli_x0_0p5_ekf_map_push(ecoli_x0_0p5_ekf_map *observer, const float *y, const float *u);
ecoli_x0_0p5_status ecoli_x0_0p5_ekf_map_estimate(const ecoli_x0_0p5_ekf_map *observer, float *values, ecoli_x0_0p5_saturation *saturation);

/* The EKF from the box centre that the map watches at every sample from its first estimate on,
 * restarted from it where the two disagree (kind ekf_restart, the Rust EkfRestartObserver). */
typedef struct {
    ecoli_x0_0p5_map window;
    float x[ECOLI_X0_0P5_STATES];
    float p[ECOLI_X0_0P5_COVARIANCE];
    float chi;
    float values[ECOLI_X0_0P5_TARGETS];
    ecoli_x0_0p5_saturation flags[ECOLI_X0_0P5_TARGETS];
    int ready;
    /* Samples refused since init for a bad value (a NaN or infinite input or output); saturates. */
    uint32_t refused;
    /* Restarts since init: samples with finite values whose step was not finite; saturates. */
    uint32_t restarts;
} ecoli_x0_0p5_ekf_restart;

void ecoli_x0_0p5_ekf_restart_init(ecoli_x0_0p5_ekf_restart *observer);
ecoli_x0_0p5_status ecoli_x0_0p5_ekf_restart_push(ecoli_x0_0p5_ekf_restart *observer, const float *y, const float *u);
ecoli_x0_0p5_status ecoli_x0_0p5_ekf_restart_estimate(const ecoli_x0_0p5_ekf_restart *observer, float *values, ecoli_x0_0p5_saturation *saturation);

/* The moving-horizon estimate (kind mhe, the Rust MheObserver): at every sample, 6 Gauss-Newton
 * step(s) over the last ECOLI_X0_0P5_HORIZON samples from the previous solution moved one sample on, each
 * solved by an L D L^T factorisation and projected onto the learning box. Thousands of instructions
 * per sample (docs/chip.md): the on-line estimate the map replaces. */
typedef struct {
    float y[2u * ECOLI_X0_0P5_HORIZON][ECOLI_X0_0P5_OUTPUTS];
    unsigned next;
    unsigned filled;
    float solved[ECOLI_X0_0P5_STATES];
    int has_solved;
    float values[ECOLI_X0_0P5_TARGETS];
    ecoli_x0_0p5_saturation flags[ECOLI_X0_0P5_TARGETS];
    int ready;
    /* The watched mean of the windows' output costs (firmware::watch), once a window was solved
     * since the last (re)start. */
    float chi;
    int has_chi;
    /* Restarts since init: samples whose solution was not finite, or whose watch found the windows
     * implausible (the next window is then solved from the start); saturates. */
    uint32_t restarts;
} ecoli_x0_0p5_mhe;

void ecoli_x0_0p5_mhe_init(ecoli_x0_0p5_mhe *observer);
ecoli_x0_0p5_status ecoli_x0_0p5_mhe_push(ecoli_x0_0p5_mhe *observer, const float *y, const float *u);
ecoli_x0_0p5_status ecoli_x0_0p5_mhe_estimate(const ecoli_x0_0p5_mhe *observer, float *values, ecoli_x0_0p5_saturation *saturation);

/* This design's observer, of the kind `gen` chose or the spec named: ukf_box. */
#define ECOLI_X0_0P5_KIND "ukf_box"
typedef ecoli_x0_0p5_ukf_box ecoli_x0_0p5_observer;
#define ecoli_x0_0p5_observer_init ecoli_x0_0p5_ukf_box_init
#define ecoli_x0_0p5_observer_push ecoli_x0_0p5_ukf_box_push
#define ecoli_x0_0p5_observer_estimate ecoli_x0_0p5_ukf_box_estimate

/* The Rust static library's interface (c/include/ecoli_x0_0p5.h of a crate `mho gen --spec` writes) over
 * ecoli_x0_0p5_observer: the same calls, statuses (ecoli_x0_0p5_status) and flags (ecoli_x0_0p5_saturation), so
 * that a firmware moves between the two routes without a change. The observer lives in storage you
 * provide, ECOLI_X0_0P5_STORAGE_SIZE bytes aligned to ECOLI_X0_0P5_STORAGE_ALIGN: `init` writes a mark of the
 * design and the size before it, and every call checks them first. */
#define ECOLI_X0_0P5_STORAGE_ALIGN 8
typedef struct {
    uint64_t mark;
    uint64_t size;
    ecoli_x0_0p5_observer observer;
} ecoli_x0_0p5_stored;
#define ECOLI_X0_0P5_STORAGE_SIZE 296
/* Does not compile where the observer would not fit in ECOLI_X0_0P5_STORAGE_SIZE bytes. */
typedef char ecoli_x0_0p5_storage_fits[sizeof(ecoli_x0_0p5_stored) <= ECOLI_X0_0P5_STORAGE_SIZE ? 1 : -1];

/* A fresh observer in storage of `size` bytes; call it again to reset. */
ecoli_x0_0p5_status ecoli_x0_0p5_init(void *storage, size_t size);
/* ecoli_x0_0p5_observer_push on the observer in storage. */
ecoli_x0_0p5_status ecoli_x0_0p5_push(void *storage, const float *y, const float *u);
/* The estimates into estimates[ECOLI_X0_0P5_TARGETS] and, unless saturation is NULL, whether each was
 * held at an end of its range into saturation[ECOLI_X0_0P5_TARGETS]. */
ecoli_x0_0p5_status ecoli_x0_0p5_estimate(void *storage, float *estimates, ecoli_x0_0p5_saturation *saturation);
/* Bytes the observer occupies with its mark. */
size_t ecoli_x0_0p5_storage_size(void);

#ifdef __cplusplus
}
#endif

#endif
