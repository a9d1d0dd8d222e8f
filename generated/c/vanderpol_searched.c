/* The `vanderpol_searched` observer in C99, emitted by `mho gen`. Do not edit: regenerate. */
#include <stdint.h>
#include <string.h>
#include "vanderpol_searched.h"

/* `x1`: gains in regressor order, then the Γ⁻¹ table's segments (a, b). */
static const float GAINS_0[16] = {
    0.017425023f, 0.0037131133f, -0.004852354f, -0.0077679497f,
    -0.00902742f, -0.00846091f, -0.0072684176f, -0.0074997274f,
    -0.0071325297f, -0.009853884f, -0.01242134f, -0.013911357f,
    -0.013883764f, -0.01496041f, -0.011572627f, -0.007700188f
};
static const float SEGMENTS_0[1][2] = {
    { -2.0616221f, 4.1232443f }
};

/* `x2`: gains in regressor order, then the Γ⁻¹ table's segments (a, b). */
static const float GAINS_1[16] = {
    0.032474767f, 0.027363943f, 0.016799463f, 0.007769529f,
    0.0012106312f, -0.00082871964f, -0.00085571123f, 0.002111885f,
    0.00464232f, 0.00694893f, 0.0074764704f, 0.0076656174f,
    0.006606008f, 0.0017127888f, -0.005782365f, -0.012064387f
};
static const float SEGMENTS_1[1][2] = {
    { -4.6765766f, 9.353153f }
};

/* 1 when v is finite: NaN - NaN and inf - inf are NaN, which equals nothing. */
static int is_finite(float v) {
    return (v - v) == 0.0f;
}

/* c ? a : b by masks, without a branch (c is 0 or 1): the same instructions whatever c is. */
static uint32_t select_bits(int c, uint32_t a, uint32_t b) {
    const uint32_t mask = 0u - (uint32_t)c;
    return (a & mask) | (b & ~mask);
}

static float select_float(int c, float a, float b) {
    uint32_t x, y;
    memcpy(&x, &a, sizeof x);
    memcpy(&y, &b, sizeof y);
    x = select_bits(c, x, y);
    memcpy(&a, &x, sizeof a);
    return a;
}

/* floor(t) for t >= 0 (0 for NaN and negatives), at most count - 1: a uniform table's segment. */
static uint32_t uniform_segment(float t, uint32_t count) {
    const float last = (float)(count - 1u);
    const float below = select_float(t < last, t, last);
    return (uint32_t)select_float(t >= 0.0f, below, 0.0f);
}

/* r(t) on one segment (a, b) starting at `start`, held at r_min below 0 (or NaN) and r_max above
 * t_max; by selects, as firmware::InverseTable (the same instructions whatever t is). */
static void evaluate(float t, const float *segment, float start, float t_max, float r_min, float r_max,
                     float *value, vanderpol_searched_saturation *saturation) {
    const float inside = segment[0] + segment[1] * (t - start);
    const int low = !(t >= 0.0f);
    const int out = low | (t > t_max);
    const uint32_t flag = select_bits(low, (uint32_t)VANDERPOL_SEARCHED_LOW, (uint32_t)VANDERPOL_SEARCHED_HIGH);
    *value = select_float(out, select_float(low, r_min, r_max), inside);
    *saturation = (vanderpol_searched_saturation)select_bits(out, flag, (uint32_t)VANDERPOL_SEARCHED_INSIDE);
}

void vanderpol_searched_map_init(vanderpol_searched_map *observer) {
    observer->next = 0u;
    observer->filled = 0u;
}

vanderpol_searched_status vanderpol_searched_map_push(vanderpol_searched_map *observer, const float *y, const float *u) {
    unsigned i;
    unsigned slot;
    int finite = 1;
    for (i = 0u; i < VANDERPOL_SEARCHED_OUTPUTS; ++i) {
        finite &= is_finite(y[i]);
    }
    if (!finite) {
        return VANDERPOL_SEARCHED_REFUSED;
    }
    slot = observer->next;
    for (i = 0u; i < VANDERPOL_SEARCHED_OUTPUTS; ++i) {
        observer->y[slot][i] = y[i];
        observer->y[slot + VANDERPOL_SEARCHED_HORIZON][i] = y[i];
    }
    (void)u;
    observer->next = slot + 1u >= VANDERPOL_SEARCHED_HORIZON ? 0u : slot + 1u;
    observer->filled = observer->filled >= VANDERPOL_SEARCHED_HORIZON ? VANDERPOL_SEARCHED_HORIZON : observer->filled + 1u;
    return VANDERPOL_SEARCHED_OK;
}

vanderpol_searched_status vanderpol_searched_map_estimate(const vanderpol_searched_map *observer, float *values, vanderpol_searched_saturation *saturation) {
    const unsigned next = observer->next;
    if (observer->filled < VANDERPOL_SEARCHED_HORIZON) {
        return VANDERPOL_SEARCHED_NO_ESTIMATE_YET;
    }
    const float t_0 = 0.5003434f
        + GAINS_0[0] * observer->y[next + 15u][0]
        + GAINS_0[1] * observer->y[next + 14u][0]
        + GAINS_0[2] * observer->y[next + 13u][0]
        + GAINS_0[3] * observer->y[next + 12u][0]
        + GAINS_0[4] * observer->y[next + 11u][0]
        + GAINS_0[5] * observer->y[next + 10u][0]
        + GAINS_0[6] * observer->y[next + 9u][0]
        + GAINS_0[7] * observer->y[next + 8u][0]
        + GAINS_0[8] * observer->y[next + 7u][0]
        + GAINS_0[9] * observer->y[next + 6u][0]
        + GAINS_0[10] * observer->y[next + 5u][0]
        + GAINS_0[11] * observer->y[next + 4u][0]
        + GAINS_0[12] * observer->y[next + 3u][0]
        + GAINS_0[13] * observer->y[next + 2u][0]
        + GAINS_0[14] * observer->y[next + 1u][0]
        + GAINS_0[15] * observer->y[next + 0u][0];
    const uint32_t k_0 = uniform_segment(t_0, 1u);
    evaluate(t_0, SEGMENTS_0[k_0], 0.0f, 1.0f, -2.0616221f, 2.0616221f, &values[0], &saturation[0]);
    const float t_1 = 0.5002161f
        + GAINS_1[0] * observer->y[next + 15u][0]
        + GAINS_1[1] * observer->y[next + 14u][0]
        + GAINS_1[2] * observer->y[next + 13u][0]
        + GAINS_1[3] * observer->y[next + 12u][0]
        + GAINS_1[4] * observer->y[next + 11u][0]
        + GAINS_1[5] * observer->y[next + 10u][0]
        + GAINS_1[6] * observer->y[next + 9u][0]
        + GAINS_1[7] * observer->y[next + 8u][0]
        + GAINS_1[8] * observer->y[next + 7u][0]
        + GAINS_1[9] * observer->y[next + 6u][0]
        + GAINS_1[10] * observer->y[next + 5u][0]
        + GAINS_1[11] * observer->y[next + 4u][0]
        + GAINS_1[12] * observer->y[next + 3u][0]
        + GAINS_1[13] * observer->y[next + 2u][0]
        + GAINS_1[14] * observer->y[next + 1u][0]
        + GAINS_1[15] * observer->y[next + 0u][0];
    const uint32_t k_1 = uniform_segment(t_1, 1u);
    evaluate(t_1, SEGMENTS_1[k_1], 0.0f, 1.0f, -4.6765766f, 4.6765766f, &values[1], &saturation[1]);
    return VANDERPOL_SEARCHED_OK;
}
