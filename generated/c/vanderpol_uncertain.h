/* The `vanderpol_uncertain` observers in C99, emitted by `mho gen` from the same tables and programs as the
 * Rust design file. Do not edit: regenerate. Build with -ffp-contract=off (no fused
 * multiply-add) to get the Rust observers' bits. Every observer lives in a struct you allocate
 * (no heap); call its _init first, then _push every sample and _estimate when you need it.
 * Licence: emitted by mho from your spec, this file is yours: you may use, copy, modify and
 * distribute it under any terms, including MIT OR Apache-2.0, with or without this notice. */
#ifndef VANDERPOL_UNCERTAIN_H
#define VANDERPOL_UNCERTAIN_H

#include <stddef.h>
#include <stdint.h>

/* C linkage for a C++ program that includes this header (the observers are compiled as C). */
#ifdef __cplusplus
extern "C" {
#endif

#define VANDERPOL_UNCERTAIN_OUTPUTS 1
#define VANDERPOL_UNCERTAIN_INPUTS 0
#define VANDERPOL_UNCERTAIN_TARGETS 2
/* The map's window, in samples: no map estimate before it is full. */
#define VANDERPOL_UNCERTAIN_HORIZON 10
/* The sample period the design assumes, in its time unit: push one sample every period. */
#define VANDERPOL_UNCERTAIN_SAMPLE_PERIOD 0.1f
#define VANDERPOL_UNCERTAIN_STATES 2
/* Entries of a filter's covariance kept: its upper triangle. */
#define VANDERPOL_UNCERTAIN_COVARIANCE 3

/* What every call returns: the observers' push and estimate, and the storage calls (the same
 * values as the Rust static library's c/include/vanderpol_uncertain.h). */
typedef enum {
    VANDERPOL_UNCERTAIN_OK = 0,
    /* The sample was refused: a NaN or infinite value; the latest estimate is unchanged. */
    VANDERPOL_UNCERTAIN_REFUSED = 1,
    /* No estimate yet (the map: fewer than VANDERPOL_UNCERTAIN_HORIZON accepted samples since init). */
    VANDERPOL_UNCERTAIN_NO_ESTIMATE_YET = 2,
    /* The storage calls only: a null pointer, or storage too small or misaligned; nothing done. */
    VANDERPOL_UNCERTAIN_BAD_ARGUMENT = 3,
    /* The storage calls only: the storage holds no observer of this design. */
    VANDERPOL_UNCERTAIN_NOT_INITIALISED = 4,
    /* The sample's values were finite but the observer's step was not: it restarted (a filter from
     * its start or from the map, the moving-horizon estimate from its start); the latest estimate is
     * unchanged. Counted in the observer's `restarts`. */
    VANDERPOL_UNCERTAIN_RESTARTED = 5
} vanderpol_uncertain_status;

/* Where an estimate lies against its range: inside, or held at its low or high end (the same
 * values from every call that reports it). */
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
 * NULL when there is no input). VANDERPOL_UNCERTAIN_OK, or VANDERPOL_UNCERTAIN_REFUSED for a NaN or infinite value
 * (the observer is unchanged). */
vanderpol_uncertain_status vanderpol_uncertain_map_push(vanderpol_uncertain_map *observer, const float *y, const float *u);

/* The estimate of every target from the last VANDERPOL_UNCERTAIN_HORIZON samples into values[VANDERPOL_UNCERTAIN_TARGETS]
 * and saturation[VANDERPOL_UNCERTAIN_TARGETS]; VANDERPOL_UNCERTAIN_NO_ESTIMATE_YET (nothing written) before the window is full. */
vanderpol_uncertain_status vanderpol_uncertain_map_estimate(const vanderpol_uncertain_map *observer, float *values, vanderpol_uncertain_saturation *saturation);

/* The map in integers, for chips without an FPU: raw converter counts in, each estimate an
 * integer in its target's LSB out, no float operation. Samples (a sample with a value outside
 * its range is refused: the proof that no sum overflows holds there):
 * y[0] (`y`): raw in [-32767, 32767], value = 0.0 + 0.00048828125 * raw
 * Estimates (value = integer * LSB, in the target's unit):
 * estimate 0 (`x1`): LSB 2^-19, proven |fixed - f64 map| <= 2.14e-3
 * estimate 1 (`x2`): LSB 2^-13, proven |fixed - f64 map| <= 2.61e-3
 * Allocate it anywhere (no heap is used) and call vanderpol_uncertain_fixed_init. */
/* Estimate t's scale, in its target's unit: value = integer * 2^VANDERPOL_UNCERTAIN_FIXED_LSB_EXPONENT_t,
 * which is integer * VANDERPOL_UNCERTAIN_FIXED_LSB_t (a float, exact: a power of two). */
#define VANDERPOL_UNCERTAIN_FIXED_LSB_EXPONENT_0 (-19)
#define VANDERPOL_UNCERTAIN_FIXED_LSB_0 1.9073486e-6f
#define VANDERPOL_UNCERTAIN_FIXED_LSB_EXPONENT_1 (-13)
#define VANDERPOL_UNCERTAIN_FIXED_LSB_1 1.2207031e-4f
typedef struct {
    int32_t y[2u * VANDERPOL_UNCERTAIN_HORIZON][VANDERPOL_UNCERTAIN_OUTPUTS];
    unsigned next;
    unsigned filled;
} vanderpol_uncertain_fixed;

/* Empties the window. */
void vanderpol_uncertain_fixed_init(vanderpol_uncertain_fixed *observer);

/* Takes the raw sample of the current instant (u may be NULL when there is no input): VANDERPOL_UNCERTAIN_OK,
 * or VANDERPOL_UNCERTAIN_REFUSED for a value outside its range (the observer is unchanged). */
vanderpol_uncertain_status vanderpol_uncertain_fixed_push(vanderpol_uncertain_fixed *observer, const int32_t *y, const int32_t *u);

/* Every target's estimate (in its LSB) into values[VANDERPOL_UNCERTAIN_TARGETS] and saturation[VANDERPOL_UNCERTAIN_TARGETS];
 * VANDERPOL_UNCERTAIN_NO_ESTIMATE_YET (nothing written) before the window is full. */
vanderpol_uncertain_status vanderpol_uncertain_fixed_estimate(const vanderpol_uncertain_fixed *observer, int32_t *values, vanderpol_uncertain_saturation *saturation);

/* The EKF from the centre of the state box (kind ekf_box, the Rust EkfBoxObserver): an estimate
 * from the first accepted sample; a sample with a non-finite output is refused and only predicted. */
typedef struct {
    float x[VANDERPOL_UNCERTAIN_STATES];
    float p[VANDERPOL_UNCERTAIN_COVARIANCE];
    float chi; /* the watched mean of the normalised innovations squared */
    float values[VANDERPOL_UNCERTAIN_TARGETS];
    vanderpol_uncertain_saturation flags[VANDERPOL_UNCERTAIN_TARGETS];
    int ready;
    /* Samples refused since init for a bad value (a NaN or infinite input or output); saturates. */
    uint32_t refused;
    /* Restarts since init: samples with finite values whose step was not finite; saturates. */
    uint32_t restarts;
} vanderpol_uncertain_ekf_box;

void vanderpol_uncertain_ekf_box_init(vanderpol_uncertain_ekf_box *observer);
vanderpol_uncertain_status vanderpol_uncertain_ekf_box_push(vanderpol_uncertain_ekf_box *observer, const float *y, const float *u);
vanderpol_uncertain_status vanderpol_uncertain_ekf_box_estimate(const vanderpol_uncertain_ekf_box *observer, float *values, vanderpol_uncertain_saturation *saturation);

/* The unscented Kalman filter from the centre of the state box (kind ukf_box, the Rust
 * UkfBoxObserver): an estimate from the first accepted sample; a sample with a non-finite output
 * is refused and only predicted. */
typedef struct {
    float x[VANDERPOL_UNCERTAIN_STATES];
    float p[VANDERPOL_UNCERTAIN_COVARIANCE];
    float chi; /* the watched mean of the normalised innovations squared */
    float values[VANDERPOL_UNCERTAIN_TARGETS];
    vanderpol_uncertain_saturation flags[VANDERPOL_UNCERTAIN_TARGETS];
    int ready;
    /* Samples refused since init for a bad value (a NaN or infinite input or output); saturates. */
    uint32_t refused;
    /* Restarts since init: samples with finite values whose step was not finite; saturates. */
    uint32_t restarts;
} vanderpol_uncertain_ukf_box;

void vanderpol_uncertain_ukf_box_init(vanderpol_uncertain_ukf_box *observer);
vanderpol_uncertain_status vanderpol_uncertain_ukf_box_push(vanderpol_uncertain_ukf_box *observer, const float *y, const float *u);
vanderpol_uncertain_status vanderpol_uncertain_ukf_box_estimate(const vanderpol_uncertain_ukf_box *observer, float *values, vanderpol_uncertain_saturation *saturation);

/* The model-corrected map (kind corrected, the Rust CorrectedObserver): the map's first estimate,
 * then the model's prediction corrected by the output and, during the start-up, blended with the
 * map; each state clamped to its learning range (flagged LOW or HIGH). */
typedef struct {
    vanderpol_uncertain_map window;
    float x[VANDERPOL_UNCERTAIN_STATES];
    unsigned count;
    int started;
    float values[VANDERPOL_UNCERTAIN_TARGETS];
    vanderpol_uncertain_saturation flags[VANDERPOL_UNCERTAIN_TARGETS];
    int ready;
    /* Samples refused since init for a bad value (a NaN or infinite input or output); saturates. */
    uint32_t refused;
    /* Restarts since init: samples with finite values whose step was not finite; saturates. */
    uint32_t restarts;
} vanderpol_uncertain_corrected;

void vanderpol_uncertain_corrected_init(vanderpol_uncertain_corrected *observer);
vanderpol_uncertain_status vanderpol_uncertain_corrected_push(vanderpol_uncertain_corrected *observer, const float *y, const float *u);
vanderpol_uncertain_status vanderpol_uncertain_corrected_estimate(const vanderpol_uncertain_corrected *observer, float *values, vanderpol_uncertain_saturation *saturation);

/* The EKF started at the map's first estimate (kind ekf_map, the Rust EkfMapObserver). */
typedef struct {
    vanderpol_uncertain_map window;
    float x[VANDERPOL_UNCERTAIN_STATES];
    float p[VANDERPOL_UNCERTAIN_COVARIANCE];
    float chi;
    unsigned count;
    int started;
    float values[VANDERPOL_UNCERTAIN_TARGETS];
    vanderpol_uncertain_saturation flags[VANDERPOL_UNCERTAIN_TARGETS];
    int ready;
    /* Samples refused since init for a bad value (a NaN or infinite input or output); saturates. */
    uint32_t refused;
    /* Restarts since init: samples with finite values whose step was not finite; saturates. */
    uint32_t restarts;
} vanderpol_uncertain_ekf_map;

void vanderpol_uncertain_ekf_map_init(vanderpol_uncertain_ekf_map *observer);
vanderpol_uncertain_status vanderpol_uncertain_ekf_map_push(vanderpol_uncertain_ekf_map *observer, const float *y, const float *u);
vanderpol_uncertain_status vanderpol_uncertain_ekf_map_estimate(const vanderpol_uncertain_ekf_map *observer, float *values, vanderpol_uncertain_saturation *saturation);

/* The EKF from the box centre that the map watches at every sample from its first estimate on,
 * restarted from it where the two disagree (kind ekf_restart, the Rust EkfRestartObserver). */
typedef struct {
    vanderpol_uncertain_map window;
    float x[VANDERPOL_UNCERTAIN_STATES];
    float p[VANDERPOL_UNCERTAIN_COVARIANCE];
    float chi;
    float values[VANDERPOL_UNCERTAIN_TARGETS];
    vanderpol_uncertain_saturation flags[VANDERPOL_UNCERTAIN_TARGETS];
    int ready;
    /* Samples refused since init for a bad value (a NaN or infinite input or output); saturates. */
    uint32_t refused;
    /* Restarts since init: samples with finite values whose step was not finite; saturates. */
    uint32_t restarts;
} vanderpol_uncertain_ekf_restart;

void vanderpol_uncertain_ekf_restart_init(vanderpol_uncertain_ekf_restart *observer);
vanderpol_uncertain_status vanderpol_uncertain_ekf_restart_push(vanderpol_uncertain_ekf_restart *observer, const float *y, const float *u);
vanderpol_uncertain_status vanderpol_uncertain_ekf_restart_estimate(const vanderpol_uncertain_ekf_restart *observer, float *values, vanderpol_uncertain_saturation *saturation);

/* The moving-horizon estimate (kind mhe, the Rust MheObserver): at every sample, 2 Gauss-Newton
 * step(s) over the last VANDERPOL_UNCERTAIN_HORIZON samples from the previous solution moved one sample on, each
 * solved by an L D L^T factorisation and projected onto the learning box. Thousands of instructions
 * per sample (docs/chip.md): the on-line estimate the map replaces. */
typedef struct {
    float y[2u * VANDERPOL_UNCERTAIN_HORIZON][VANDERPOL_UNCERTAIN_OUTPUTS];
    unsigned next;
    unsigned filled;
    float solved[VANDERPOL_UNCERTAIN_STATES];
    int has_solved;
    float values[VANDERPOL_UNCERTAIN_TARGETS];
    vanderpol_uncertain_saturation flags[VANDERPOL_UNCERTAIN_TARGETS];
    int ready;
    /* The watched mean of the windows' output costs (firmware::watch), once a window was solved
     * since the last (re)start. */
    float chi;
    int has_chi;
    /* Restarts since init: samples whose solution was not finite, or whose watch found the windows
     * implausible (the next window is then solved from the start); saturates. */
    uint32_t restarts;
} vanderpol_uncertain_mhe;

void vanderpol_uncertain_mhe_init(vanderpol_uncertain_mhe *observer);
vanderpol_uncertain_status vanderpol_uncertain_mhe_push(vanderpol_uncertain_mhe *observer, const float *y, const float *u);
vanderpol_uncertain_status vanderpol_uncertain_mhe_estimate(const vanderpol_uncertain_mhe *observer, float *values, vanderpol_uncertain_saturation *saturation);

/* This design's observer, of the kind `gen` chose or the spec named: ukf_box. */
#define VANDERPOL_UNCERTAIN_KIND "ukf_box"
typedef vanderpol_uncertain_ukf_box vanderpol_uncertain_observer;
#define vanderpol_uncertain_observer_init vanderpol_uncertain_ukf_box_init
#define vanderpol_uncertain_observer_push vanderpol_uncertain_ukf_box_push
#define vanderpol_uncertain_observer_estimate vanderpol_uncertain_ukf_box_estimate

/* The Rust static library's interface (c/include/vanderpol_uncertain.h of a crate `mho gen --spec` writes) over
 * vanderpol_uncertain_observer: the same calls, statuses (vanderpol_uncertain_status) and flags (vanderpol_uncertain_saturation), so
 * that a firmware moves between the two routes without a change. The observer lives in storage you
 * provide, VANDERPOL_UNCERTAIN_STORAGE_SIZE bytes aligned to VANDERPOL_UNCERTAIN_STORAGE_ALIGN: `init` writes a mark of the
 * design and the size before it, and every call checks them first. */
#define VANDERPOL_UNCERTAIN_STORAGE_ALIGN 8
typedef struct {
    uint64_t mark;
    uint64_t size;
    vanderpol_uncertain_observer observer;
} vanderpol_uncertain_stored;
#define VANDERPOL_UNCERTAIN_STORAGE_SIZE 280
/* Does not compile where the observer would not fit in VANDERPOL_UNCERTAIN_STORAGE_SIZE bytes. */
typedef char vanderpol_uncertain_storage_fits[sizeof(vanderpol_uncertain_stored) <= VANDERPOL_UNCERTAIN_STORAGE_SIZE ? 1 : -1];

/* A fresh observer in storage of `size` bytes; call it again to reset. */
vanderpol_uncertain_status vanderpol_uncertain_init(void *storage, size_t size);
/* vanderpol_uncertain_observer_push on the observer in storage. */
vanderpol_uncertain_status vanderpol_uncertain_push(void *storage, const float *y, const float *u);
/* The estimates into estimates[VANDERPOL_UNCERTAIN_TARGETS] and, unless saturation is NULL, whether each was
 * held at an end of its range into saturation[VANDERPOL_UNCERTAIN_TARGETS]. */
vanderpol_uncertain_status vanderpol_uncertain_estimate(void *storage, float *estimates, vanderpol_uncertain_saturation *saturation);
/* Bytes the observer occupies with its mark. */
size_t vanderpol_uncertain_storage_size(void);

#ifdef __cplusplus
}
#endif

#endif
