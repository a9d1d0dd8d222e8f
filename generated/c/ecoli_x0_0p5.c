/* The `ecoli_x0_0p5` observers in C99, emitted by `mho gen`. Do not edit: regenerate.
 * Licence: emitted by mho from your spec, this file is yours: you may use, copy, modify and
 * distribute it under any terms, including MIT OR Apache-2.0, with or without this notice. */
#include <stdint.h>
#include <string.h>
#include <math.h>
#include <float.h>
#include "ecoli_x0_0p5.h"

/* The Rust observer's bits need every float operation rounded on its own: no fused multiply-add
 * (gcc: -ffp-contract=off, the default of its ISO modes such as -std=c99; other compilers follow
 * the standard pragma below), no -ffast-math, and float evaluated as float: FLT_EVAL_METHOD 0,
 * or 16 or 32 (ISO/IEC TS 18661-3: types narrower than _Float16, or _Float32, are evaluated in
 * it, so float stays float; gcc says 16 for a Cortex-M55 or with AVX512-FP16 in its GNU modes). */
#if !defined(__GNUC__) || defined(__clang__)
#pragma STDC FP_CONTRACT OFF
#endif
#if defined(FLT_EVAL_METHOD)
#if FLT_EVAL_METHOD == 1
#error "float expressions are evaluated in double here (FLT_EVAL_METHOD 1): the observers need them evaluated in float"
#elif FLT_EVAL_METHOD == 2
#error "float expressions are evaluated in long double here (FLT_EVAL_METHOD 2, e.g. the x87): use SSE (gcc: -mfpmath=sse)"
#elif FLT_EVAL_METHOD == -1
#error "the format float expressions are evaluated in is indeterminate here (FLT_EVAL_METHOD -1): the observers need float"
#elif FLT_EVAL_METHOD != 0 && FLT_EVAL_METHOD != 16 && FLT_EVAL_METHOD != 32
#error "float expressions are evaluated in a format wider than float here (FLT_EVAL_METHOD not 0, 16 or 32)"
#endif
#endif


/* The bits of v (memcpy: no aliasing, no conversion). */
static uint32_t bits_of(float v) {
    uint32_t x;
    memcpy(&x, &v, sizeof x);
    return x;
}

/* 1 when v is finite: its exponent is not all ones (an integer test, as Rust's is_finite). */
static int is_finite(float v) {
    return (bits_of(v) & 0x7fffffffu) < 0x7f800000u;
}

/* 1 when every output and input of a sample is finite (u is not read without inputs). */
static int accepts(const float *y, const float *u) {
    unsigned i;
    int finite = 1;
    for (i = 0u; i < ECOLI_X0_0P5_OUTPUTS; ++i) {
        finite &= is_finite(y[i]);
    }
    (void)u;
    return finite;
}

/* c ? a : b, one select per statement: compilers make it a conditional move (an IT block on
 * Thumb-2), where a chain of them on one condition may become a branch. */
static float choose_float(int c, float a, float b) {
    return c ? a : b;
}

/* c ? a : b by masks, without a branch (c is 0 or 1): the same instructions whatever c is. */
static uint32_t select_bits(int c, uint32_t a, uint32_t b) {
    const uint32_t mask = 0u - (uint32_t)c;
    return (a & mask) | (b & ~mask);
}

static float select_float(int c, float a, float b) {
    uint32_t x = select_bits(c, bits_of(a), bits_of(b));
    memcpy(&a, &x, sizeof a);
    return a;
}


/* target `P`: gains in regressor order, then the Γ⁻¹ table's segments (a, b). */
static const float GAINS_0[6] = {
    -4.039889f, -0.34156004f, -4.308531f, 0.077934295f,
    -3.0881793f, 0.50124514f
};
static const float SEGMENTS_0[88][2] = {
    { 0.0f, 0.006248085f },
    { -2.2744691e-6f, 0.006250359f },
    { -8.913187e-6f, 0.006253679f },
    { -1.2436404e-5f, 0.006254853f },
    { -1.2694873e-5f, 0.0062549175f },
    { -1.10100245e-5f, 0.006254581f },
    { -8.62894e-6f, 0.006254184f },
    { -6.419705e-6f, 0.0062538683f },
    { -4.890204e-6f, 0.006253677f },
    { -4.273855e-6f, 0.0062536085f },
    { -4.613077e-6f, 0.0062536425f },
    { -5.825301e-6f, 0.006253753f },
    { -7.751546e-6f, 0.006253913f },
    { -1.019106e-5f, 0.0062541007f },
    { -1.2925674e-5f, 0.0062542963f },
    { -1.5736801e-5f, 0.0062544835f },
    { -1.8417295e-5f, 0.006254651f },
    { -2.0779711e-5f, 0.0062547904f },
    { -2.266211e-5f, 0.0062548947f },
    { -2.3932156e-5f, 0.0062549617f },
    { -2.4490024e-5f, 0.0062549897f },
    { -2.4270526e-5f, 0.006254979f },
    { -2.3244625e-5f, 0.0062549324f },
    { -2.1420527e-5f, 0.006254853f },
    { -1.8844366e-5f, 0.0062547456f },
    { -1.5600515e-5f, 0.006254616f },
    { -1.1811434e-5f, 0.0062544704f },
    { -7.636928e-6f, 0.006254316f },
    { -3.272621e-6f, 0.00625416f },
    { 1.0526552e-6f, 0.006254011f },
    { 5.0809344e-6f, 0.0062538763f },
    { 8.531201e-6f, 0.006253765f },
    { 1.1108181e-5f, 0.0062536844f },
    { 1.2514787e-5f, 0.006253642f },
    { 1.2469467e-5f, 0.0062536434f },
    { 1.0730102e-5f, 0.006253693f },
    { 7.12666e-6f, 0.006253793f },
    { 1.605526e-6f, 0.0062539424f },
    { -5.7106054e-6f, 0.0062541347f },
    { -1.4442076e-5f, 0.0062543587f },
    { -2.3843897e-5f, 0.006254594f },
    { -3.266038e-5f, 0.0062548085f },
    { -3.8930237e-5f, 0.006254958f },
    { -3.9725383e-5f, 0.0062549766f },
    { -3.0800864e-5f, 0.0062547736f },
    { -6.1255687e-6f, 0.0062542255f },
    { 4.2746982e-5f, 0.006253163f },
    { 0.00012752203f, 0.0062513594f },
    { 0.0002642931f, 0.00624851f },
    { 0.00047505187f, 0.0062442087f },
    { 0.0007896987f, 0.0062379157f },
    { 0.0012487032f, 0.0062289154f },
    { 0.0019065897f, 0.006216264f },
    { 0.0028364283f, 0.0061987196f },
    { 0.004135479f, 0.006174663f },
    { 0.0059319967f, 0.0061419993f },
    { 0.008392889f, 0.006098055f },
    { 0.011731282f, 0.0060394863f },
    { 0.016211927f, 0.005962234f },
    { 0.022150729f, 0.005861576f },
    { 0.029902654f, 0.0057323775f },
    { 0.03983098f, 0.005569618f },
    { 0.052252375f, 0.005369273f },
    { 0.06735947f, 0.005129478f },
    { 0.08513654f, 0.004851711f },
    { 0.10529912f, 0.0045415177f },
    { 0.1272922f, 0.004208289f },
    { 0.15036273f, 0.0038639528f },
    { 0.173687f, 0.003520949f },
    { 0.19650573f, 0.0031902427f },
    { 0.21822134f, 0.0028800196f },
    { 0.23843737f, 0.002595287f },
    { 0.2569477f, 0.0023381992f },
    { 0.2736975f, 0.00210875f },
    { 0.28873637f, 0.0019055217f },
    { 0.30217662f, 0.0017263184f },
    { 0.3141616f, 0.0015686213f },
    { 0.3248444f, 0.0014298838f },
    { 0.33437476f, 0.0013076994f },
    { 0.34289217f, 0.0011998842f },
    { 0.35052243f, 0.001104506f },
    { 0.35737696f, 0.001019882f },
    { 0.36355323f, 0.0009445618f },
    { 0.36913577f, 0.00087730214f },
    { 0.37419772f, 0.000817041f },
    { 0.3788021f, 0.00076287193f },
    { 0.3830032f, 0.00071402156f },
    { 0.38684797f, 0.00066982885f }
};

/* target `muX`: gains in regressor order, then the Γ⁻¹ table's segments (a, b). */
static const float GAINS_1[6] = {
    0.06840128f, 0.0055591087f, 0.070145f, 0.0003677032f,
    0.053549178f, -0.0047274753f
};
static const float SEGMENTS_1[1][2] = {
    { 0.0f, 0.43531778f }
};

/* helper map `X`: gains in regressor order, then the Γ⁻¹ table's segments (a, b). */
static const float GAINS_2[6] = {
    0.38688287f, 0.00011909063f, 0.42060104f, 2.1403303e-5f,
    0.37400255f, 0.0022436865f
};
static const float SEGMENTS_2[3][2] = {
    { 0.4385543f, 0.6056552f },
    { 0.4385536f, 0.6056559f },
    { 0.4385614f, 0.605652f }
};

/* helper map `S`: gains in regressor order, then the Γ⁻¹ table's segments (a, b). */
static const float GAINS_3[6] = {
    -0.046064626f, 0.008455554f, -0.055173066f, -0.0006070147f,
    -0.06394423f, -0.0069448985f
};
static const float SEGMENTS_3[1][2] = {
    { 0.0f, 4.949024f }
};

/* floor(t) for 0 <= t, at most count - 1: a uniform table's segment. Any other t (negative, NaN,
 * infinite) gives some segment, whose value evaluate replaces by r_min or r_max. The clamp is an
 * unsigned minimum of the bits of |t|, which are ordered as the values: the conversion is always
 * defined, and the same instructions run whatever t is. */
static uint32_t uniform_segment(float t, uint32_t count) {
    const uint32_t magnitude = bits_of(t) & 0x7fffffffu;
    const uint32_t last = bits_of((float)(count - 1u));
    const uint32_t least = magnitude < last ? magnitude : last;
    float clamped;
    memcpy(&clamped, &least, sizeof clamped);
    return (uint32_t)clamped;
}

/* r(t) on one segment (a, b) starting at `start`, held at r_min below 0 (or NaN) and r_max above
 * t_max (t_max >= 0: never both); as firmware::InverseTable, by one select per statement, which
 * compilers make a conditional move (an IT block on Thumb-2): the same instructions whatever t is. */
static void evaluate(float t, const float *segment, float start, float t_max, float r_min, float r_max,
                     float *value, ecoli_x0_0p5_saturation *saturation) {
    const int low = !(t >= 0.0f);
    const int high = t > t_max;
    float r = segment[0] + segment[1] * (t - start);
    r = choose_float(high, r_max, r);
    r = choose_float(low, r_min, r);
    *value = r;
    *saturation = (ecoli_x0_0p5_saturation)((unsigned)low | (unsigned)high << 1);
}

void ecoli_x0_0p5_map_init(ecoli_x0_0p5_map *observer) {
    observer->next = 0u;
    observer->filled = 0u;
}

ecoli_x0_0p5_status ecoli_x0_0p5_map_push(ecoli_x0_0p5_map *observer, const float *y, const float *u) {
    unsigned i;
    unsigned slot;
    int finite = 1;
    for (i = 0u; i < ECOLI_X0_0P5_OUTPUTS; ++i) {
        finite &= is_finite(y[i]);
    }
    if (!finite) {
        return ECOLI_X0_0P5_REFUSED;
    }
    slot = observer->next;
    for (i = 0u; i < ECOLI_X0_0P5_OUTPUTS; ++i) {
        observer->y[slot][i] = y[i];
        observer->y[slot + ECOLI_X0_0P5_HORIZON][i] = y[i];
    }
    (void)u;
    observer->next = slot + 1u >= ECOLI_X0_0P5_HORIZON ? 0u : slot + 1u;
    observer->filled += (unsigned)(observer->filled < ECOLI_X0_0P5_HORIZON);
    return ECOLI_X0_0P5_OK;
}

ecoli_x0_0p5_status ecoli_x0_0p5_map_estimate(const ecoli_x0_0p5_map *observer, float *values, ecoli_x0_0p5_saturation *saturation) {
    const unsigned next = observer->next;
    if (observer->filled < ECOLI_X0_0P5_HORIZON) {
        return ECOLI_X0_0P5_NO_ESTIMATE_YET;
    }
    const float t_0 = 26.752401f
        + GAINS_0[0] * observer->y[next + 2u][0]
        + GAINS_0[1] * observer->y[next + 2u][1]
        + GAINS_0[2] * observer->y[next + 1u][0]
        + GAINS_0[3] * observer->y[next + 1u][1]
        + GAINS_0[4] * observer->y[next + 0u][0]
        + GAINS_0[5] * observer->y[next + 0u][1];
    const float t_1 = 0.022176465f
        + GAINS_1[0] * observer->y[next + 2u][0]
        + GAINS_1[1] * observer->y[next + 2u][1]
        + GAINS_1[2] * observer->y[next + 1u][0]
        + GAINS_1[3] * observer->y[next + 1u][1]
        + GAINS_1[4] * observer->y[next + 0u][0]
        + GAINS_1[5] * observer->y[next + 0u][1];
    const uint32_t k_0 = uniform_segment(t_0, 88u);
    evaluate(t_0, SEGMENTS_0[k_0], 0.0f, 88.0f, 0.0f, 0.4457929f, &values[0], &saturation[0]);
    evaluate(t_1, SEGMENTS_1[0], 0.0f, 1.0f, 0.0f, 0.43531778f, &values[1], &saturation[1]);
    return ECOLI_X0_0P5_OK;
}


/* The map the map-started kinds read: the targets' rows, then a helper map per state that no
 * target is. */
#define ECOLI_X0_0P5_MAP_ROWS 4u
static inline ecoli_x0_0p5_status start_map_estimate(const ecoli_x0_0p5_map *observer, float *values, ecoli_x0_0p5_saturation *saturation) {
    const unsigned next = observer->next;
    if (observer->filled < ECOLI_X0_0P5_HORIZON) {
        return ECOLI_X0_0P5_NO_ESTIMATE_YET;
    }
    const float t_0 = 26.752401f
        + GAINS_0[0] * observer->y[next + 2u][0]
        + GAINS_0[1] * observer->y[next + 2u][1]
        + GAINS_0[2] * observer->y[next + 1u][0]
        + GAINS_0[3] * observer->y[next + 1u][1]
        + GAINS_0[4] * observer->y[next + 0u][0]
        + GAINS_0[5] * observer->y[next + 0u][1];
    const float t_1 = 0.022176465f
        + GAINS_1[0] * observer->y[next + 2u][0]
        + GAINS_1[1] * observer->y[next + 2u][1]
        + GAINS_1[2] * observer->y[next + 1u][0]
        + GAINS_1[3] * observer->y[next + 1u][1]
        + GAINS_1[4] * observer->y[next + 0u][0]
        + GAINS_1[5] * observer->y[next + 0u][1];
    const float t_2 = -0.43697193f
        + GAINS_2[0] * observer->y[next + 2u][0]
        + GAINS_2[1] * observer->y[next + 2u][1]
        + GAINS_2[2] * observer->y[next + 1u][0]
        + GAINS_2[3] * observer->y[next + 1u][1]
        + GAINS_2[4] * observer->y[next + 0u][0]
        + GAINS_2[5] * observer->y[next + 0u][1];
    const float t_3 = 0.38749164f
        + GAINS_3[0] * observer->y[next + 2u][0]
        + GAINS_3[1] * observer->y[next + 2u][1]
        + GAINS_3[2] * observer->y[next + 1u][0]
        + GAINS_3[3] * observer->y[next + 1u][1]
        + GAINS_3[4] * observer->y[next + 0u][0]
        + GAINS_3[5] * observer->y[next + 0u][1];
    const uint32_t k_0 = uniform_segment(t_0, 88u);
    evaluate(t_0, SEGMENTS_0[k_0], 0.0f, 88.0f, 0.0f, 0.4457929f, &values[0], &saturation[0]);
    evaluate(t_1, SEGMENTS_1[0], 0.0f, 1.0f, 0.0f, 0.43531778f, &values[1], &saturation[1]);
    const uint32_t k_2 = uniform_segment(t_2, 3u);
    evaluate(t_2, SEGMENTS_2[k_2], 0.0f, 3.0f, 0.4385543f, 2.2555175f, &values[2], &saturation[2]);
    evaluate(t_3, SEGMENTS_3[0], 0.0f, 1.0f, 0.0f, 4.949024f, &values[3], &saturation[3]);
    return ECOLI_X0_0P5_OK;
}

/* `P` in integers: gains in regressor order (2^-20 per count), then (A_k, B_k) in its LSB. */
static const int32_t FIXED_GAINS_0[6] = { -1034, -11192, -1103, 2554, -791, 16425 };
static const int32_t FIXED_SEGMENTS_0[88][2] = {
    { 0, 52413 },
    { 52413, 52432 },
    { 104845, 52460 },
    { 157304, 52470 },
    { 209774, 52470 },
    { 262244, 52467 },
    { 314711, 52464 },
    { 367175, 52461 },
    { 419636, 52460 },
    { 472096, 52459 },
    { 524555, 52459 },
    { 577014, 52460 },
    { 629474, 52462 },
    { 681936, 52463 },
    { 734399, 52465 },
    { 786864, 52466 },
    { 839331, 52468 },
    { 891798, 52469 },
    { 944267, 52470 },
    { 996737, 52470 },
    { 1049208, 52471 },
    { 1101678, 52471 },
    { 1154149, 52470 },
    { 1206619, 52470 },
    { 1259089, 52469 },
    { 1311557, 52468 },
    { 1364025, 52466 },
    { 1416491, 52465 },
    { 1468956, 52464 },
    { 1521420, 52462 },
    { 1573882, 52461 },
    { 1626343, 52460 },
    { 1678804, 52460 },
    { 1731264, 52459 },
    { 1783723, 52459 },
    { 1836182, 52460 },
    { 1888642, 52461 },
    { 1941103, 52462 },
    { 1993565, 52463 },
    { 2046028, 52465 },
    { 2098493, 52467 },
    { 2150961, 52469 },
    { 2203430, 52470 },
    { 2255900, 52471 },
    { 2308371, 52469 },
    { 2360840, 52464 },
    { 2413304, 52455 },
    { 2465759, 52440 },
    { 2518199, 52416 },
    { 2570616, 52380 },
    { 2622996, 52327 },
    { 2675323, 52252 },
    { 2727575, 52146 },
    { 2779721, 51999 },
    { 2831720, 51797 },
    { 2883517, 51523 },
    { 2935039, 51154 },
    { 2986194, 50663 },
    { 3036856, 50015 },
    { 3086871, 49170 },
    { 3136042, 48087 },
    { 3184128, 46721 },
    { 3230850, 45041 },
    { 3275890, 43029 },
    { 3318920, 40699 },
    { 3359619, 38097 },
    { 3397716, 35302 },
    { 3433017, 32413 },
    { 3465431, 29536 },
    { 3494967, 26762 },
    { 3521728, 24159 },
    { 3545888, 21771 },
    { 3567658, 19614 },
    { 3587273, 17689 },
    { 3604962, 15985 },
    { 3620947, 14481 },
    { 3635428, 13159 },
    { 3648587, 11995 },
    { 3660581, 10970 },
    { 3671551, 10065 },
    { 3681617, 9265 },
    { 3690882, 8555 },
    { 3699437, 7924 },
    { 3707361, 7359 },
    { 3714720, 6854 },
    { 3721574, 6399 },
    { 3727973, 5990 },
    { 3733963, 5619 }
};

/* `muX` in integers: gains in regressor order (2^-27 per count), then (A_k, B_k) in its LSB. */
static const int32_t FIXED_GAINS_1[6] = { 2241, 23317, 2299, 1542, 1755, -19828 };
static const int32_t FIXED_SEGMENTS_1[1][2] = {
    { 0, 57058 }
};

/* Signed right shifts must be arithmetic (implementation-defined in C99; so on gcc, clang, armcc
 * and IAR): checked at compile time. */
typedef char fixed_shifts_are_arithmetic[((-8) >> 1) == -4 ? 1 : -1];

/* a - b modulo 2^32 (no signed overflow, which C leaves undefined): t_last - t for any t. */
static int32_t wrapping_sub(int32_t a, int32_t b) {
    return (int32_t)((uint32_t)a - (uint32_t)b);
}

/* min <= v <= max, as one unsigned comparison. */
static int in_range(int32_t v, int32_t min, int32_t max) {
    return (uint32_t)v - (uint32_t)min <= (uint32_t)max - (uint32_t)min;
}

/* firmware::fixed::FixedTable::evaluate: t clamped to the table [0, t_last] by sign masks (no
 * branch: the same instructions whatever t is), then the segment and the position in it by shifts. */
static void fixed_evaluate(int32_t t, const int32_t segments[][2], unsigned f, unsigned dropped, unsigned p,
                           int32_t t_last, int32_t *value, ecoli_x0_0p5_saturation *saturation) {
    const int32_t low = t >> 31;
    const int32_t high = (wrapping_sub(t_last, t) >> 31) & ~low;
    int32_t k;
    int32_t position;
    t &= ~low;
    t ^= (t ^ t_last) & high;
    k = t >> f;
    position = (t - (int32_t)((uint32_t)k << f)) >> dropped;
    *value = segments[k][0] + ((segments[k][1] * position) >> p);
    *saturation = (ecoli_x0_0p5_saturation)((unsigned)(low & 1) | ((unsigned)high & 2u));
}

void ecoli_x0_0p5_fixed_init(ecoli_x0_0p5_fixed *observer) {
    observer->next = 0u;
    observer->filled = 0u;
}

ecoli_x0_0p5_status ecoli_x0_0p5_fixed_push(ecoli_x0_0p5_fixed *observer, const int32_t *y, const int32_t *u) {
    unsigned i;
    unsigned slot;
    int inside = 1;
    inside &= in_range(y[0], -32767, 32767);
    inside &= in_range(y[1], -32767, 32767);
    if (!inside) {
        return ECOLI_X0_0P5_REFUSED;
    }
    slot = observer->next;
    for (i = 0u; i < ECOLI_X0_0P5_OUTPUTS; ++i) {
        observer->y[slot][i] = y[i];
        observer->y[slot + ECOLI_X0_0P5_HORIZON][i] = y[i];
    }
    (void)u;
    observer->next = slot + 1u >= ECOLI_X0_0P5_HORIZON ? 0u : slot + 1u;
    observer->filled += (unsigned)(observer->filled < ECOLI_X0_0P5_HORIZON);
    return ECOLI_X0_0P5_OK;
}

/* The sums are in int32_t: every stored sample is in range, where the proof says they fit. */
ecoli_x0_0p5_status ecoli_x0_0p5_fixed_estimate(const ecoli_x0_0p5_fixed *observer, int32_t *values, ecoli_x0_0p5_saturation *saturation) {
    const unsigned next = observer->next;
    if (observer->filled < ECOLI_X0_0P5_HORIZON) {
        return ECOLI_X0_0P5_NO_ESTIMATE_YET;
    }
    int32_t t_0 = 28051925;
    int32_t t_1 = 2976475;
    {
        const int32_t z = observer->y[next + 2u][0];
        t_0 += FIXED_GAINS_0[0] * z;
        t_1 += FIXED_GAINS_1[0] * z;
    }
    {
        const int32_t z = observer->y[next + 2u][1];
        t_0 += FIXED_GAINS_0[1] * z;
        t_1 += FIXED_GAINS_1[1] * z;
    }
    {
        const int32_t z = observer->y[next + 1u][0];
        t_0 += FIXED_GAINS_0[2] * z;
        t_1 += FIXED_GAINS_1[2] * z;
    }
    {
        const int32_t z = observer->y[next + 1u][1];
        t_0 += FIXED_GAINS_0[3] * z;
        t_1 += FIXED_GAINS_1[3] * z;
    }
    {
        const int32_t z = observer->y[next + 0u][0];
        t_0 += FIXED_GAINS_0[4] * z;
        t_1 += FIXED_GAINS_1[4] * z;
    }
    {
        const int32_t z = observer->y[next + 0u][1];
        t_0 += FIXED_GAINS_0[5] * z;
        t_1 += FIXED_GAINS_1[5] * z;
    }
    fixed_evaluate(t_0, FIXED_SEGMENTS_0, 20u, 5u, 15u, 92274687, &values[0], &saturation[0]);
    fixed_evaluate(t_1, FIXED_SEGMENTS_1, 27u, 12u, 15u, 134217727, &values[1], &saturation[1]);
    return ECOLI_X0_0P5_OK;
}

/* 1 with the sign of v (NaN stays NaN), as firmware::Maths::signum; NaN told by its bits. */
static float signum(float v) {
    return select_float((bits_of(v) & 0x7fffffffu) > 0x7f800000u, v, copysignf(1.0f, v));
}

/* e^x in float as Rust's libm computes it (FreeBSD e_expf.c, Sun Microsystems 1993: "Permission
* to use, copy, modify, and distribute this software is freely granted, provided that this notice is
* preserved"), operation for operation: C libraries' expf differ from it in the last bit. */
static float libm_expf(float x) {
static const float HALF[2] = {0.5f, -0.5f};
const float ln2_hi = 6.9314575195e-01f, ln2_lo = 1.4286067653e-06f, inv_ln2 = 1.4426950216e+00f;
const float p1 = 1.6666625440e-1f, p2 = -2.7667332906e-3f;
const uint32_t sign = bits_of(x) >> 31;
const uint32_t hx = bits_of(x) & 0x7fffffffu;
float hi, lo, xx, c, y, x1p127;
int32_t k;
const uint32_t x1p127_bits = 0x7f000000u;
memcpy(&x1p127, &x1p127_bits, sizeof x1p127);
if (hx >= 0x42aeac50u) { /* |x| >= 87.33655 or NaN */
if (hx > 0x7f800000u) {
return x;
}
if (hx >= 0x42b17218u && sign == 0u) { /* overflow */
return x * x1p127;
}
if (sign != 0u && hx >= 0x42cff1b5u) { /* underflow */
return 0.0f;
}
}
if (hx > 0x3eb17218u) { /* |x| > ln2 / 2: argument reduction */
if (hx > 0x3f851592u) {
k = (int32_t)(inv_ln2 * x + HALF[sign]);
} else {
k = 1 - (int32_t)sign - (int32_t)sign;
}
hi = x - (float)k * ln2_hi;
lo = (float)k * ln2_lo;
x = hi - lo;
} else if (hx > 0x39000000u) { /* |x| > 2^-14 */
k = 0;
hi = x;
lo = 0.0f;
} else {
return 1.0f + x;
}
xx = x * x;
c = x - xx * (p1 + xx * p2);
y = 1.0f + (x * c / (2.0f - c) - lo + hi);
return k == 0 ? y : scalbnf(y, (int)k);
}

/* ln x in float as Rust's libm computes it (FreeBSD e_logf.c, Sun Microsystems 1993: "Permission to
 * use, copy, modify, and distribute this software is freely granted, provided that this notice is
 * preserved"), operation for operation: C libraries' logf may differ from it in the last bit. */
static float libm_logf(float x) {
    const float ln2_hi = 6.9313812256e-01f, ln2_lo = 9.0580006145e-06f;
    const float lg1 = 0.66666662693f, lg2 = 0.40000972152f, lg3 = 0.28498786688f, lg4 = 0.24279078841f;
    const uint32_t x1p25_bits = 0x4c000000u;
    float x1p25, f, s, z, w, t1, t2, r, hfsq, dk;
    uint32_t ix = bits_of(x);
    int32_t k = 0;
    memcpy(&x1p25, &x1p25_bits, sizeof x1p25);
    if (ix < 0x00800000u || (ix >> 31) != 0u) { /* x < 2^-126 or negative */
        if ((uint32_t)(ix << 1) == 0u) {
            return -1.0f / (x * x); /* ln(±0) = -inf */
        }
        if ((ix >> 31) != 0u) {
            return (x - x) / 0.0f; /* ln(negative) = NaN */
        }
        k -= 25; /* subnormal: scale up */
        x *= x1p25;
        ix = bits_of(x);
    } else if (ix >= 0x7f800000u) {
        return x;
    } else if (ix == 0x3f800000u) {
        return 0.0f;
    }
    /* x reduced into [sqrt(2)/2, sqrt(2)] */
    ix += 0x3f800000u - 0x3f3504f3u;
    k += (int32_t)(ix >> 23) - 0x7f;
    ix = (ix & 0x007fffffu) + 0x3f3504f3u;
    memcpy(&x, &ix, sizeof x);
    f = x - 1.0f;
    s = f / (2.0f + f);
    z = s * s;
    w = z * z;
    t1 = w * (lg2 + w * lg4);
    t2 = z * (lg1 + w * lg3);
    r = t2 + t1;
    hfsq = 0.5f * f * f;
    dk = (float)k;
    return s * (hfsq + r) + dk * ln2_lo - hfsq + f + dk * ln2_hi;
}


/* 1 when every input is finite. */
static int inputs_finite(const float *u) {
    (void)u;
    return 1;
}

/* 1 when the n values from v are finite. */
static int all_finite(const float *v, unsigned n) {
    unsigned i;
    int finite = 1;
    for (i = 0u; i < n; ++i) {
        finite &= is_finite(v[i]);
    }
    return finite;
}

/* The targets at state x and input u. */
static void targets(const float *x, const float *u, float *out) {
    (void)u;
    const float t0 = 0.2f /* mu_m */;
    const float t1 = x[1];
    const float t2 = 0.1f /* k_s */;
    const float t3 = t2 + t1;
    const float t4 = t1 / t3;
    const float t5 = t0 * t4;
    const float t6 = x[2];
    const float t7 = x[0];
    const float t8 = t5 * t7;
    out[0] = t6;
    out[1] = t8;
}

/* One EKF sample with its measurement: out = (x(k|k), x+, P+, nis) from (x, P), nis the normalised innovation squared, as the Rust file's ekf_measured. */
static void ekf_measured(const float *x, const float *p, const float *y, const float *u, float *out) {
    (void)u;
    const float t0 = x[0];
    const float t1 = x[1];
    const float t2 = x[2];
    const float t3 = p[0];
    const float t4 = p[1];
    const float t5 = p[2];
    const float t6 = p[3];
    const float t7 = p[4];
    const float t8 = p[5];
    const float t9 = 0.0f;
    const float t10 = 0.2f /* mu_m */;
    const float t11 = 0.1f /* k_s */;
    const float t12 = 1.0f;
    const float t13 = 5000.0f /* y_l */;
    const float t14 = 1.0f /* I */;
    const float t15 = 1.0f /* k_l */;
    const float t16 = t14 + t15;
    const float t17 = t14 / t16;
    const float t18 = t13 * t17;
    const float t19 = 0.1f;
    const float t20 = t19 + t3;
    const float t21 = t12 / t20;
    const float t22 = t3 * t21;
    const float t23 = t4 * t21;
    const float t24 = t5 * t21;
    const float t25 = y[0];
    const float t26 = t25 - t0;
    const float t27 = t22 * t26;
    const float t28 = t0 + t27;
    const float t29 = t23 * t26;
    const float t30 = t1 + t29;
    const float t31 = t24 * t26;
    const float t32 = t2 + t31;
    const float t33 = t26 * t26;
    const float t34 = t33 * t21;
    const float t35 = t12 - t22;
    const float t36 = -t23;
    const float t37 = -t24;
    const float t38 = t35 * t3;
    const float t39 = t35 * t4;
    const float t40 = t35 * t5;
    const float t41 = t36 * t3;
    const float t42 = t41 + t4;
    const float t43 = t36 * t4;
    const float t44 = t43 + t6;
    const float t45 = t36 * t5;
    const float t46 = t45 + t7;
    const float t47 = t37 * t3;
    const float t48 = t47 + t5;
    const float t49 = t37 * t5;
    const float t50 = t49 + t8;
    const float t51 = t38 * t35;
    const float t52 = t38 * t36;
    const float t53 = t52 + t39;
    const float t54 = t38 * t37;
    const float t55 = t54 + t40;
    const float t56 = t42 * t36;
    const float t57 = t56 + t44;
    const float t58 = t42 * t37;
    const float t59 = t58 + t46;
    const float t60 = t48 * t37;
    const float t61 = t60 + t50;
    const float t62 = t22 * t19;
    const float t63 = t62 * t22;
    const float t64 = t51 + t63;
    const float t65 = t62 * t23;
    const float t66 = t53 + t65;
    const float t67 = t62 * t24;
    const float t68 = t55 + t67;
    const float t69 = t23 * t19;
    const float t70 = t69 * t23;
    const float t71 = t57 + t70;
    const float t72 = t69 * t24;
    const float t73 = t59 + t72;
    const float t74 = t24 * t19;
    const float t75 = t74 * t24;
    const float t76 = t61 + t75;
    const float t77 = t11 + t30;
    const float t78 = t30 / t77;
    const float t79 = t10 * t78;
    const float t80 = t12 / t77;
    const float t81 = t77 * t77;
    const float t82 = t30 / t81;
    const float t83 = t80 - t82;
    const float t84 = t10 * t83;
    const float t85 = t13 * t79;
    const float t86 = t85 * t17;
    const float t87 = t86 * t28;
    const float t88 = t87 * t32;
    const float t89 = t86 * t32;
    const float t90 = t18 * t28;
    const float t91 = t90 * t32;
    const float t92 = t91 * t84;
    const float t93 = t64 * t89;
    const float t94 = t66 * t92;
    const float t95 = t93 + t94;
    const float t96 = t68 * t87;
    const float t97 = t95 + t96;
    const float t98 = t66 * t89;
    const float t99 = t71 * t92;
    const float t100 = t98 + t99;
    const float t101 = t73 * t87;
    const float t102 = t100 + t101;
    const float t103 = t68 * t89;
    const float t104 = t73 * t92;
    const float t105 = t103 + t104;
    const float t106 = t76 * t87;
    const float t107 = t105 + t106;
    const float t108 = 20.0f;
    const float t109 = t89 * t97;
    const float t110 = t108 + t109;
    const float t111 = t92 * t102;
    const float t112 = t110 + t111;
    const float t113 = t87 * t107;
    const float t114 = t112 + t113;
    const float t115 = t12 / t114;
    const float t116 = t97 * t115;
    const float t117 = t102 * t115;
    const float t118 = t107 * t115;
    const float t119 = y[1];
    const float t120 = t119 - t88;
    const float t121 = t116 * t120;
    const float t122 = t28 + t121;
    const float t123 = t117 * t120;
    const float t124 = t30 + t123;
    const float t125 = t118 * t120;
    const float t126 = t32 + t125;
    const float t127 = t120 * t120;
    const float t128 = t127 * t115;
    const float t129 = t116 * t89;
    const float t130 = t12 - t129;
    const float t131 = t116 * t92;
    const float t132 = -t131;
    const float t133 = t116 * t87;
    const float t134 = -t133;
    const float t135 = t117 * t89;
    const float t136 = -t135;
    const float t137 = t117 * t92;
    const float t138 = t12 - t137;
    const float t139 = t117 * t87;
    const float t140 = -t139;
    const float t141 = t118 * t89;
    const float t142 = -t141;
    const float t143 = t118 * t92;
    const float t144 = -t143;
    const float t145 = t118 * t87;
    const float t146 = t12 - t145;
    const float t147 = t130 * t64;
    const float t148 = t132 * t66;
    const float t149 = t147 + t148;
    const float t150 = t134 * t68;
    const float t151 = t149 + t150;
    const float t152 = t130 * t66;
    const float t153 = t132 * t71;
    const float t154 = t152 + t153;
    const float t155 = t134 * t73;
    const float t156 = t154 + t155;
    const float t157 = t130 * t68;
    const float t158 = t132 * t73;
    const float t159 = t157 + t158;
    const float t160 = t134 * t76;
    const float t161 = t159 + t160;
    const float t162 = t136 * t64;
    const float t163 = t138 * t66;
    const float t164 = t162 + t163;
    const float t165 = t140 * t68;
    const float t166 = t164 + t165;
    const float t167 = t136 * t66;
    const float t168 = t138 * t71;
    const float t169 = t167 + t168;
    const float t170 = t140 * t73;
    const float t171 = t169 + t170;
    const float t172 = t136 * t68;
    const float t173 = t138 * t73;
    const float t174 = t172 + t173;
    const float t175 = t140 * t76;
    const float t176 = t174 + t175;
    const float t177 = t142 * t64;
    const float t178 = t144 * t66;
    const float t179 = t177 + t178;
    const float t180 = t146 * t68;
    const float t181 = t179 + t180;
    const float t182 = t142 * t66;
    const float t183 = t144 * t71;
    const float t184 = t182 + t183;
    const float t185 = t146 * t73;
    const float t186 = t184 + t185;
    const float t187 = t142 * t68;
    const float t188 = t144 * t73;
    const float t189 = t187 + t188;
    const float t190 = t146 * t76;
    const float t191 = t189 + t190;
    const float t192 = t151 * t130;
    const float t193 = t156 * t132;
    const float t194 = t192 + t193;
    const float t195 = t161 * t134;
    const float t196 = t194 + t195;
    const float t197 = t151 * t136;
    const float t198 = t156 * t138;
    const float t199 = t197 + t198;
    const float t200 = t161 * t140;
    const float t201 = t199 + t200;
    const float t202 = t151 * t142;
    const float t203 = t156 * t144;
    const float t204 = t202 + t203;
    const float t205 = t161 * t146;
    const float t206 = t204 + t205;
    const float t207 = t166 * t136;
    const float t208 = t171 * t138;
    const float t209 = t207 + t208;
    const float t210 = t176 * t140;
    const float t211 = t209 + t210;
    const float t212 = t166 * t142;
    const float t213 = t171 * t144;
    const float t214 = t212 + t213;
    const float t215 = t176 * t146;
    const float t216 = t214 + t215;
    const float t217 = t181 * t142;
    const float t218 = t186 * t144;
    const float t219 = t217 + t218;
    const float t220 = t191 * t146;
    const float t221 = t219 + t220;
    const float t222 = t116 * t108;
    const float t223 = t222 * t116;
    const float t224 = t196 + t223;
    const float t225 = t222 * t117;
    const float t226 = t201 + t225;
    const float t227 = t222 * t118;
    const float t228 = t206 + t227;
    const float t229 = t117 * t108;
    const float t230 = t229 * t117;
    const float t231 = t211 + t230;
    const float t232 = t229 * t118;
    const float t233 = t216 + t232;
    const float t234 = t118 * t108;
    const float t235 = t234 * t118;
    const float t236 = t221 + t235;
    const float t237 = t34 + t128;
    const float t238 = select_float(!(t122 >= t9), t9, t122);
    const float t239 = select_float(!(t124 >= t9), t9, t124);
    const float t240 = select_float(!(t126 >= t9), t9, t126);
    const float t241 = 0.2f;
    const float t242 = 2.0f;
    const float t243 = 6.0f;
    const float t244 = t241 / t242;
    const float t245 = t241 / t243;
    const float t246 = t11 + t239;
    const float t247 = t239 / t246;
    const float t248 = t10 * t247;
    const float t249 = t12 / t246;
    const float t250 = t246 * t246;
    const float t251 = t239 / t250;
    const float t252 = t249 - t251;
    const float t253 = t10 * t252;
    const float t254 = 0.1f /* k_d */;
    const float t255 = 0.5f /* k_p */;
    const float t256 = -t255;
    const float t257 = 0.001f;
    const float t258 = fmaxf(t240, t257);
    const float t259 = t256 / t258;
    const float t260 = libm_expf(t259);
    const float t261 = t254 * t260;
    const float t262 = 0.5f;
    const float t263 = -0.5f;
    const float t264 = t257 - t240;
    const float t265 = signum(t264);
    const float t266 = t263 * t265;
    const float t267 = t262 + t266;
    const float t268 = t256 * t267;
    const float t269 = t258 * t258;
    const float t270 = t268 / t269;
    const float t271 = -t270;
    const float t272 = t260 * t271;
    const float t273 = t254 * t272;
    const float t274 = t248 * t238;
    const float t275 = t261 * t238;
    const float t276 = t274 - t275;
    const float t277 = t248 - t261;
    const float t278 = -t238;
    const float t279 = t238 * t253;
    const float t280 = t278 * t273;
    const float t281 = 1.0f /* y_s */;
    const float t282 = t281 * t248;
    const float t283 = t282 * t238;
    const float t284 = -t283;
    const float t285 = 0.05f /* k_m */;
    const float t286 = t285 * t238;
    const float t287 = 0.01f /* ks_m */;
    const float t288 = t239 + t287;
    const float t289 = t239 / t288;
    const float t290 = t286 * t289;
    const float t291 = t284 - t290;
    const float t292 = -t282;
    const float t293 = t285 * t289;
    const float t294 = t292 - t293;
    const float t295 = t281 * t238;
    const float t296 = -t295;
    const float t297 = t12 / t288;
    const float t298 = t288 * t288;
    const float t299 = t239 / t298;
    const float t300 = t297 - t299;
    const float t301 = t286 * t300;
    const float t302 = -t301;
    const float t303 = t296 * t253;
    const float t304 = t302 + t303;
    const float t305 = 0.2f /* y_p */;
    const float t306 = t305 * t248;
    const float t307 = 0.5f /* k_I */;
    const float t308 = t14 + t307;
    const float t309 = t14 / t308;
    const float t310 = t306 * t309;
    const float t311 = t310 * t238;
    const float t312 = t261 * t240;
    const float t313 = t311 - t312;
    const float t314 = t305 * t309;
    const float t315 = t314 * t238;
    const float t316 = -t240;
    const float t317 = t315 * t253;
    const float t318 = -t261;
    const float t319 = t316 * t273;
    const float t320 = t318 + t319;
    const float t321 = t244 * t276;
    const float t322 = t238 + t321;
    const float t323 = t244 * t291;
    const float t324 = t239 + t323;
    const float t325 = t244 * t313;
    const float t326 = t240 + t325;
    const float t327 = t244 * t277;
    const float t328 = t12 + t327;
    const float t329 = t244 * t279;
    const float t330 = t244 * t280;
    const float t331 = t244 * t294;
    const float t332 = t244 * t304;
    const float t333 = t12 + t332;
    const float t334 = t244 * t310;
    const float t335 = t244 * t317;
    const float t336 = t244 * t320;
    const float t337 = t12 + t336;
    const float t338 = t11 + t324;
    const float t339 = t324 / t338;
    const float t340 = t10 * t339;
    const float t341 = t12 / t338;
    const float t342 = t338 * t338;
    const float t343 = t324 / t342;
    const float t344 = t341 - t343;
    const float t345 = t10 * t344;
    const float t346 = fmaxf(t326, t257);
    const float t347 = t256 / t346;
    const float t348 = libm_expf(t347);
    const float t349 = t254 * t348;
    const float t350 = t257 - t326;
    const float t351 = signum(t350);
    const float t352 = t263 * t351;
    const float t353 = t262 + t352;
    const float t354 = t256 * t353;
    const float t355 = t346 * t346;
    const float t356 = t354 / t355;
    const float t357 = -t356;
    const float t358 = t348 * t357;
    const float t359 = t254 * t358;
    const float t360 = t340 * t322;
    const float t361 = t349 * t322;
    const float t362 = t360 - t361;
    const float t363 = t340 - t349;
    const float t364 = -t322;
    const float t365 = t322 * t345;
    const float t366 = t364 * t359;
    const float t367 = t281 * t340;
    const float t368 = t367 * t322;
    const float t369 = -t368;
    const float t370 = t285 * t322;
    const float t371 = t324 + t287;
    const float t372 = t324 / t371;
    const float t373 = t370 * t372;
    const float t374 = t369 - t373;
    const float t375 = -t367;
    const float t376 = t285 * t372;
    const float t377 = t375 - t376;
    const float t378 = t281 * t322;
    const float t379 = -t378;
    const float t380 = t12 / t371;
    const float t381 = t371 * t371;
    const float t382 = t324 / t381;
    const float t383 = t380 - t382;
    const float t384 = t370 * t383;
    const float t385 = -t384;
    const float t386 = t379 * t345;
    const float t387 = t385 + t386;
    const float t388 = t305 * t340;
    const float t389 = t388 * t309;
    const float t390 = t389 * t322;
    const float t391 = t349 * t326;
    const float t392 = t390 - t391;
    const float t393 = t314 * t322;
    const float t394 = -t326;
    const float t395 = t393 * t345;
    const float t396 = -t349;
    const float t397 = t394 * t359;
    const float t398 = t396 + t397;
    const float t399 = t363 * t328;
    const float t400 = t365 * t331;
    const float t401 = t399 + t400;
    const float t402 = t366 * t334;
    const float t403 = t401 + t402;
    const float t404 = t363 * t329;
    const float t405 = t365 * t333;
    const float t406 = t404 + t405;
    const float t407 = t366 * t335;
    const float t408 = t406 + t407;
    const float t409 = t363 * t330;
    const float t410 = t366 * t337;
    const float t411 = t409 + t410;
    const float t412 = t377 * t328;
    const float t413 = t387 * t331;
    const float t414 = t412 + t413;
    const float t415 = t377 * t329;
    const float t416 = t387 * t333;
    const float t417 = t415 + t416;
    const float t418 = t377 * t330;
    const float t419 = t389 * t328;
    const float t420 = t395 * t331;
    const float t421 = t419 + t420;
    const float t422 = t398 * t334;
    const float t423 = t421 + t422;
    const float t424 = t389 * t329;
    const float t425 = t395 * t333;
    const float t426 = t424 + t425;
    const float t427 = t398 * t335;
    const float t428 = t426 + t427;
    const float t429 = t389 * t330;
    const float t430 = t398 * t337;
    const float t431 = t429 + t430;
    const float t432 = t244 * t362;
    const float t433 = t238 + t432;
    const float t434 = t244 * t374;
    const float t435 = t239 + t434;
    const float t436 = t244 * t392;
    const float t437 = t240 + t436;
    const float t438 = t244 * t403;
    const float t439 = t12 + t438;
    const float t440 = t244 * t408;
    const float t441 = t244 * t411;
    const float t442 = t244 * t414;
    const float t443 = t244 * t417;
    const float t444 = t12 + t443;
    const float t445 = t244 * t418;
    const float t446 = t244 * t423;
    const float t447 = t244 * t428;
    const float t448 = t244 * t431;
    const float t449 = t12 + t448;
    const float t450 = t11 + t435;
    const float t451 = t435 / t450;
    const float t452 = t10 * t451;
    const float t453 = t12 / t450;
    const float t454 = t450 * t450;
    const float t455 = t435 / t454;
    const float t456 = t453 - t455;
    const float t457 = t10 * t456;
    const float t458 = fmaxf(t437, t257);
    const float t459 = t256 / t458;
    const float t460 = libm_expf(t459);
    const float t461 = t254 * t460;
    const float t462 = t257 - t437;
    const float t463 = signum(t462);
    const float t464 = t263 * t463;
    const float t465 = t262 + t464;
    const float t466 = t256 * t465;
    const float t467 = t458 * t458;
    const float t468 = t466 / t467;
    const float t469 = -t468;
    const float t470 = t460 * t469;
    const float t471 = t254 * t470;
    const float t472 = t452 * t433;
    const float t473 = t461 * t433;
    const float t474 = t472 - t473;
    const float t475 = t452 - t461;
    const float t476 = -t433;
    const float t477 = t433 * t457;
    const float t478 = t476 * t471;
    const float t479 = t281 * t452;
    const float t480 = t479 * t433;
    const float t481 = -t480;
    const float t482 = t285 * t433;
    const float t483 = t435 + t287;
    const float t484 = t435 / t483;
    const float t485 = t482 * t484;
    const float t486 = t481 - t485;
    const float t487 = -t479;
    const float t488 = t285 * t484;
    const float t489 = t487 - t488;
    const float t490 = t281 * t433;
    const float t491 = -t490;
    const float t492 = t12 / t483;
    const float t493 = t483 * t483;
    const float t494 = t435 / t493;
    const float t495 = t492 - t494;
    const float t496 = t482 * t495;
    const float t497 = -t496;
    const float t498 = t491 * t457;
    const float t499 = t497 + t498;
    const float t500 = t305 * t452;
    const float t501 = t500 * t309;
    const float t502 = t501 * t433;
    const float t503 = t461 * t437;
    const float t504 = t502 - t503;
    const float t505 = t314 * t433;
    const float t506 = -t437;
    const float t507 = t505 * t457;
    const float t508 = -t461;
    const float t509 = t506 * t471;
    const float t510 = t508 + t509;
    const float t511 = t475 * t439;
    const float t512 = t477 * t442;
    const float t513 = t511 + t512;
    const float t514 = t478 * t446;
    const float t515 = t513 + t514;
    const float t516 = t475 * t440;
    const float t517 = t477 * t444;
    const float t518 = t516 + t517;
    const float t519 = t478 * t447;
    const float t520 = t518 + t519;
    const float t521 = t475 * t441;
    const float t522 = t477 * t445;
    const float t523 = t521 + t522;
    const float t524 = t478 * t449;
    const float t525 = t523 + t524;
    const float t526 = t489 * t439;
    const float t527 = t499 * t442;
    const float t528 = t526 + t527;
    const float t529 = t489 * t440;
    const float t530 = t499 * t444;
    const float t531 = t529 + t530;
    const float t532 = t489 * t441;
    const float t533 = t499 * t445;
    const float t534 = t532 + t533;
    const float t535 = t501 * t439;
    const float t536 = t507 * t442;
    const float t537 = t535 + t536;
    const float t538 = t510 * t446;
    const float t539 = t537 + t538;
    const float t540 = t501 * t440;
    const float t541 = t507 * t444;
    const float t542 = t540 + t541;
    const float t543 = t510 * t447;
    const float t544 = t542 + t543;
    const float t545 = t501 * t441;
    const float t546 = t507 * t445;
    const float t547 = t545 + t546;
    const float t548 = t510 * t449;
    const float t549 = t547 + t548;
    const float t550 = t241 * t474;
    const float t551 = t238 + t550;
    const float t552 = t241 * t486;
    const float t553 = t239 + t552;
    const float t554 = t241 * t504;
    const float t555 = t240 + t554;
    const float t556 = t241 * t515;
    const float t557 = t12 + t556;
    const float t558 = t241 * t520;
    const float t559 = t241 * t525;
    const float t560 = t241 * t528;
    const float t561 = t241 * t531;
    const float t562 = t12 + t561;
    const float t563 = t241 * t534;
    const float t564 = t241 * t539;
    const float t565 = t241 * t544;
    const float t566 = t241 * t549;
    const float t567 = t12 + t566;
    const float t568 = t11 + t553;
    const float t569 = t553 / t568;
    const float t570 = t10 * t569;
    const float t571 = t12 / t568;
    const float t572 = t568 * t568;
    const float t573 = t553 / t572;
    const float t574 = t571 - t573;
    const float t575 = t10 * t574;
    const float t576 = fmaxf(t555, t257);
    const float t577 = t256 / t576;
    const float t578 = libm_expf(t577);
    const float t579 = t254 * t578;
    const float t580 = t257 - t555;
    const float t581 = signum(t580);
    const float t582 = t263 * t581;
    const float t583 = t262 + t582;
    const float t584 = t256 * t583;
    const float t585 = t576 * t576;
    const float t586 = t584 / t585;
    const float t587 = -t586;
    const float t588 = t578 * t587;
    const float t589 = t254 * t588;
    const float t590 = t570 * t551;
    const float t591 = t579 * t551;
    const float t592 = t590 - t591;
    const float t593 = t570 - t579;
    const float t594 = -t551;
    const float t595 = t551 * t575;
    const float t596 = t594 * t589;
    const float t597 = t281 * t570;
    const float t598 = t597 * t551;
    const float t599 = -t598;
    const float t600 = t285 * t551;
    const float t601 = t553 + t287;
    const float t602 = t553 / t601;
    const float t603 = t600 * t602;
    const float t604 = t599 - t603;
    const float t605 = -t597;
    const float t606 = t285 * t602;
    const float t607 = t605 - t606;
    const float t608 = t281 * t551;
    const float t609 = -t608;
    const float t610 = t12 / t601;
    const float t611 = t601 * t601;
    const float t612 = t553 / t611;
    const float t613 = t610 - t612;
    const float t614 = t600 * t613;
    const float t615 = -t614;
    const float t616 = t609 * t575;
    const float t617 = t615 + t616;
    const float t618 = t305 * t570;
    const float t619 = t618 * t309;
    const float t620 = t619 * t551;
    const float t621 = t579 * t555;
    const float t622 = t620 - t621;
    const float t623 = t314 * t551;
    const float t624 = -t555;
    const float t625 = t623 * t575;
    const float t626 = -t579;
    const float t627 = t624 * t589;
    const float t628 = t626 + t627;
    const float t629 = t593 * t557;
    const float t630 = t595 * t560;
    const float t631 = t629 + t630;
    const float t632 = t596 * t564;
    const float t633 = t631 + t632;
    const float t634 = t593 * t558;
    const float t635 = t595 * t562;
    const float t636 = t634 + t635;
    const float t637 = t596 * t565;
    const float t638 = t636 + t637;
    const float t639 = t593 * t559;
    const float t640 = t595 * t563;
    const float t641 = t639 + t640;
    const float t642 = t596 * t567;
    const float t643 = t641 + t642;
    const float t644 = t607 * t557;
    const float t645 = t617 * t560;
    const float t646 = t644 + t645;
    const float t647 = t607 * t558;
    const float t648 = t617 * t562;
    const float t649 = t647 + t648;
    const float t650 = t607 * t559;
    const float t651 = t617 * t563;
    const float t652 = t650 + t651;
    const float t653 = t619 * t557;
    const float t654 = t625 * t560;
    const float t655 = t653 + t654;
    const float t656 = t628 * t564;
    const float t657 = t655 + t656;
    const float t658 = t619 * t558;
    const float t659 = t625 * t562;
    const float t660 = t658 + t659;
    const float t661 = t628 * t565;
    const float t662 = t660 + t661;
    const float t663 = t619 * t559;
    const float t664 = t625 * t563;
    const float t665 = t663 + t664;
    const float t666 = t628 * t567;
    const float t667 = t665 + t666;
    const float t668 = t362 + t474;
    const float t669 = t242 * t668;
    const float t670 = t276 + t669;
    const float t671 = t670 + t592;
    const float t672 = t245 * t671;
    const float t673 = t238 + t672;
    const float t674 = t374 + t486;
    const float t675 = t242 * t674;
    const float t676 = t291 + t675;
    const float t677 = t676 + t604;
    const float t678 = t245 * t677;
    const float t679 = t239 + t678;
    const float t680 = t392 + t504;
    const float t681 = t242 * t680;
    const float t682 = t313 + t681;
    const float t683 = t682 + t622;
    const float t684 = t245 * t683;
    const float t685 = t240 + t684;
    const float t686 = t403 + t515;
    const float t687 = t242 * t686;
    const float t688 = t277 + t687;
    const float t689 = t688 + t633;
    const float t690 = t245 * t689;
    const float t691 = t12 + t690;
    const float t692 = t408 + t520;
    const float t693 = t242 * t692;
    const float t694 = t279 + t693;
    const float t695 = t694 + t638;
    const float t696 = t245 * t695;
    const float t697 = t411 + t525;
    const float t698 = t242 * t697;
    const float t699 = t280 + t698;
    const float t700 = t699 + t643;
    const float t701 = t245 * t700;
    const float t702 = t414 + t528;
    const float t703 = t242 * t702;
    const float t704 = t294 + t703;
    const float t705 = t704 + t646;
    const float t706 = t245 * t705;
    const float t707 = t417 + t531;
    const float t708 = t242 * t707;
    const float t709 = t304 + t708;
    const float t710 = t709 + t649;
    const float t711 = t245 * t710;
    const float t712 = t12 + t711;
    const float t713 = t418 + t534;
    const float t714 = t242 * t713;
    const float t715 = t714 + t652;
    const float t716 = t245 * t715;
    const float t717 = t423 + t539;
    const float t718 = t242 * t717;
    const float t719 = t310 + t718;
    const float t720 = t719 + t657;
    const float t721 = t245 * t720;
    const float t722 = t428 + t544;
    const float t723 = t242 * t722;
    const float t724 = t317 + t723;
    const float t725 = t724 + t662;
    const float t726 = t245 * t725;
    const float t727 = t431 + t549;
    const float t728 = t242 * t727;
    const float t729 = t320 + t728;
    const float t730 = t729 + t667;
    const float t731 = t245 * t730;
    const float t732 = t12 + t731;
    const float t733 = t691 * t224;
    const float t734 = t696 * t226;
    const float t735 = t733 + t734;
    const float t736 = t701 * t228;
    const float t737 = t735 + t736;
    const float t738 = t691 * t226;
    const float t739 = t696 * t231;
    const float t740 = t738 + t739;
    const float t741 = t701 * t233;
    const float t742 = t740 + t741;
    const float t743 = t691 * t228;
    const float t744 = t696 * t233;
    const float t745 = t743 + t744;
    const float t746 = t701 * t236;
    const float t747 = t745 + t746;
    const float t748 = t706 * t224;
    const float t749 = t712 * t226;
    const float t750 = t748 + t749;
    const float t751 = t716 * t228;
    const float t752 = t750 + t751;
    const float t753 = t706 * t226;
    const float t754 = t712 * t231;
    const float t755 = t753 + t754;
    const float t756 = t716 * t233;
    const float t757 = t755 + t756;
    const float t758 = t706 * t228;
    const float t759 = t712 * t233;
    const float t760 = t758 + t759;
    const float t761 = t716 * t236;
    const float t762 = t760 + t761;
    const float t763 = t721 * t224;
    const float t764 = t726 * t226;
    const float t765 = t763 + t764;
    const float t766 = t732 * t228;
    const float t767 = t765 + t766;
    const float t768 = t721 * t226;
    const float t769 = t726 * t231;
    const float t770 = t768 + t769;
    const float t771 = t732 * t233;
    const float t772 = t770 + t771;
    const float t773 = t721 * t228;
    const float t774 = t726 * t233;
    const float t775 = t773 + t774;
    const float t776 = t732 * t236;
    const float t777 = t775 + t776;
    const float t778 = t737 * t691;
    const float t779 = t742 * t696;
    const float t780 = t778 + t779;
    const float t781 = t747 * t701;
    const float t782 = t780 + t781;
    const float t783 = t737 * t706;
    const float t784 = t742 * t712;
    const float t785 = t783 + t784;
    const float t786 = t747 * t716;
    const float t787 = t785 + t786;
    const float t788 = t737 * t721;
    const float t789 = t742 * t726;
    const float t790 = t788 + t789;
    const float t791 = t747 * t732;
    const float t792 = t790 + t791;
    const float t793 = t752 * t706;
    const float t794 = t757 * t712;
    const float t795 = t793 + t794;
    const float t796 = t762 * t716;
    const float t797 = t795 + t796;
    const float t798 = t752 * t721;
    const float t799 = t757 * t726;
    const float t800 = t798 + t799;
    const float t801 = t762 * t732;
    const float t802 = t800 + t801;
    const float t803 = t767 * t721;
    const float t804 = t772 * t726;
    const float t805 = t803 + t804;
    const float t806 = t777 * t732;
    const float t807 = t805 + t806;
    const float t808 = 0.00053441565f;
    const float t809 = t782 + t808;
    const float t810 = 0.00022407259f;
    const float t811 = t797 + t810;
    const float t812 = 6.2443684e-7f;
    const float t813 = t807 + t812;
    const float t814 = select_float(!(t673 >= t9), t9, t673);
    const float t815 = select_float(!(t679 >= t9), t9, t679);
    const float t816 = select_float(!(t685 >= t9), t9, t685);
    out[0] = t238;
    out[1] = t239;
    out[2] = t240;
    out[3] = t814;
    out[4] = t815;
    out[5] = t816;
    out[6] = t809;
    out[7] = t787;
    out[8] = t792;
    out[9] = t811;
    out[10] = t802;
    out[11] = t813;
    out[12] = t237;
}

/* One EKF sample without its measurement: out = (x+, P+) from (x, P), as the Rust file's ekf_unmeasured. */
static void ekf_unmeasured(const float *x, const float *p, const float *u, float *out) {
    (void)u;
    const float t0 = x[0];
    const float t1 = x[1];
    const float t2 = x[2];
    const float t3 = p[0];
    const float t4 = p[1];
    const float t5 = p[2];
    const float t6 = p[3];
    const float t7 = p[4];
    const float t8 = p[5];
    const float t9 = 0.2f;
    const float t10 = 2.0f;
    const float t11 = 6.0f;
    const float t12 = t9 / t10;
    const float t13 = t9 / t11;
    const float t14 = 0.2f /* mu_m */;
    const float t15 = 0.1f /* k_s */;
    const float t16 = t15 + t1;
    const float t17 = t1 / t16;
    const float t18 = t14 * t17;
    const float t19 = 0.0f;
    const float t20 = 1.0f;
    const float t21 = t20 / t16;
    const float t22 = t16 * t16;
    const float t23 = t1 / t22;
    const float t24 = t21 - t23;
    const float t25 = t14 * t24;
    const float t26 = 0.1f /* k_d */;
    const float t27 = 0.5f /* k_p */;
    const float t28 = -t27;
    const float t29 = 0.001f;
    const float t30 = fmaxf(t2, t29);
    const float t31 = t28 / t30;
    const float t32 = libm_expf(t31);
    const float t33 = t26 * t32;
    const float t34 = 0.5f;
    const float t35 = -0.5f;
    const float t36 = t29 - t2;
    const float t37 = signum(t36);
    const float t38 = t35 * t37;
    const float t39 = t34 + t38;
    const float t40 = t28 * t39;
    const float t41 = t30 * t30;
    const float t42 = t40 / t41;
    const float t43 = -t42;
    const float t44 = t32 * t43;
    const float t45 = t26 * t44;
    const float t46 = t18 * t0;
    const float t47 = t33 * t0;
    const float t48 = t46 - t47;
    const float t49 = t18 - t33;
    const float t50 = -t0;
    const float t51 = t0 * t25;
    const float t52 = t50 * t45;
    const float t53 = 1.0f /* y_s */;
    const float t54 = t53 * t18;
    const float t55 = t54 * t0;
    const float t56 = -t55;
    const float t57 = 0.05f /* k_m */;
    const float t58 = t57 * t0;
    const float t59 = 0.01f /* ks_m */;
    const float t60 = t1 + t59;
    const float t61 = t1 / t60;
    const float t62 = t58 * t61;
    const float t63 = t56 - t62;
    const float t64 = -t54;
    const float t65 = t57 * t61;
    const float t66 = t64 - t65;
    const float t67 = t53 * t0;
    const float t68 = -t67;
    const float t69 = t20 / t60;
    const float t70 = t60 * t60;
    const float t71 = t1 / t70;
    const float t72 = t69 - t71;
    const float t73 = t58 * t72;
    const float t74 = -t73;
    const float t75 = t68 * t25;
    const float t76 = t74 + t75;
    const float t77 = 0.2f /* y_p */;
    const float t78 = t77 * t18;
    const float t79 = 1.0f /* I */;
    const float t80 = 0.5f /* k_I */;
    const float t81 = t79 + t80;
    const float t82 = t79 / t81;
    const float t83 = t78 * t82;
    const float t84 = t83 * t0;
    const float t85 = t33 * t2;
    const float t86 = t84 - t85;
    const float t87 = t77 * t82;
    const float t88 = t87 * t0;
    const float t89 = -t2;
    const float t90 = t88 * t25;
    const float t91 = -t33;
    const float t92 = t89 * t45;
    const float t93 = t91 + t92;
    const float t94 = t12 * t48;
    const float t95 = t0 + t94;
    const float t96 = t12 * t63;
    const float t97 = t1 + t96;
    const float t98 = t12 * t86;
    const float t99 = t2 + t98;
    const float t100 = t12 * t49;
    const float t101 = t20 + t100;
    const float t102 = t12 * t51;
    const float t103 = t12 * t52;
    const float t104 = t12 * t66;
    const float t105 = t12 * t76;
    const float t106 = t20 + t105;
    const float t107 = t12 * t83;
    const float t108 = t12 * t90;
    const float t109 = t12 * t93;
    const float t110 = t20 + t109;
    const float t111 = t15 + t97;
    const float t112 = t97 / t111;
    const float t113 = t14 * t112;
    const float t114 = t20 / t111;
    const float t115 = t111 * t111;
    const float t116 = t97 / t115;
    const float t117 = t114 - t116;
    const float t118 = t14 * t117;
    const float t119 = fmaxf(t99, t29);
    const float t120 = t28 / t119;
    const float t121 = libm_expf(t120);
    const float t122 = t26 * t121;
    const float t123 = t29 - t99;
    const float t124 = signum(t123);
    const float t125 = t35 * t124;
    const float t126 = t34 + t125;
    const float t127 = t28 * t126;
    const float t128 = t119 * t119;
    const float t129 = t127 / t128;
    const float t130 = -t129;
    const float t131 = t121 * t130;
    const float t132 = t26 * t131;
    const float t133 = t113 * t95;
    const float t134 = t122 * t95;
    const float t135 = t133 - t134;
    const float t136 = t113 - t122;
    const float t137 = -t95;
    const float t138 = t95 * t118;
    const float t139 = t137 * t132;
    const float t140 = t53 * t113;
    const float t141 = t140 * t95;
    const float t142 = -t141;
    const float t143 = t57 * t95;
    const float t144 = t97 + t59;
    const float t145 = t97 / t144;
    const float t146 = t143 * t145;
    const float t147 = t142 - t146;
    const float t148 = -t140;
    const float t149 = t57 * t145;
    const float t150 = t148 - t149;
    const float t151 = t53 * t95;
    const float t152 = -t151;
    const float t153 = t20 / t144;
    const float t154 = t144 * t144;
    const float t155 = t97 / t154;
    const float t156 = t153 - t155;
    const float t157 = t143 * t156;
    const float t158 = -t157;
    const float t159 = t152 * t118;
    const float t160 = t158 + t159;
    const float t161 = t77 * t113;
    const float t162 = t161 * t82;
    const float t163 = t162 * t95;
    const float t164 = t122 * t99;
    const float t165 = t163 - t164;
    const float t166 = t87 * t95;
    const float t167 = -t99;
    const float t168 = t166 * t118;
    const float t169 = -t122;
    const float t170 = t167 * t132;
    const float t171 = t169 + t170;
    const float t172 = t136 * t101;
    const float t173 = t138 * t104;
    const float t174 = t172 + t173;
    const float t175 = t139 * t107;
    const float t176 = t174 + t175;
    const float t177 = t136 * t102;
    const float t178 = t138 * t106;
    const float t179 = t177 + t178;
    const float t180 = t139 * t108;
    const float t181 = t179 + t180;
    const float t182 = t136 * t103;
    const float t183 = t139 * t110;
    const float t184 = t182 + t183;
    const float t185 = t150 * t101;
    const float t186 = t160 * t104;
    const float t187 = t185 + t186;
    const float t188 = t150 * t102;
    const float t189 = t160 * t106;
    const float t190 = t188 + t189;
    const float t191 = t150 * t103;
    const float t192 = t162 * t101;
    const float t193 = t168 * t104;
    const float t194 = t192 + t193;
    const float t195 = t171 * t107;
    const float t196 = t194 + t195;
    const float t197 = t162 * t102;
    const float t198 = t168 * t106;
    const float t199 = t197 + t198;
    const float t200 = t171 * t108;
    const float t201 = t199 + t200;
    const float t202 = t162 * t103;
    const float t203 = t171 * t110;
    const float t204 = t202 + t203;
    const float t205 = t12 * t135;
    const float t206 = t0 + t205;
    const float t207 = t12 * t147;
    const float t208 = t1 + t207;
    const float t209 = t12 * t165;
    const float t210 = t2 + t209;
    const float t211 = t12 * t176;
    const float t212 = t20 + t211;
    const float t213 = t12 * t181;
    const float t214 = t12 * t184;
    const float t215 = t12 * t187;
    const float t216 = t12 * t190;
    const float t217 = t20 + t216;
    const float t218 = t12 * t191;
    const float t219 = t12 * t196;
    const float t220 = t12 * t201;
    const float t221 = t12 * t204;
    const float t222 = t20 + t221;
    const float t223 = t15 + t208;
    const float t224 = t208 / t223;
    const float t225 = t14 * t224;
    const float t226 = t20 / t223;
    const float t227 = t223 * t223;
    const float t228 = t208 / t227;
    const float t229 = t226 - t228;
    const float t230 = t14 * t229;
    const float t231 = fmaxf(t210, t29);
    const float t232 = t28 / t231;
    const float t233 = libm_expf(t232);
    const float t234 = t26 * t233;
    const float t235 = t29 - t210;
    const float t236 = signum(t235);
    const float t237 = t35 * t236;
    const float t238 = t34 + t237;
    const float t239 = t28 * t238;
    const float t240 = t231 * t231;
    const float t241 = t239 / t240;
    const float t242 = -t241;
    const float t243 = t233 * t242;
    const float t244 = t26 * t243;
    const float t245 = t225 * t206;
    const float t246 = t234 * t206;
    const float t247 = t245 - t246;
    const float t248 = t225 - t234;
    const float t249 = -t206;
    const float t250 = t206 * t230;
    const float t251 = t249 * t244;
    const float t252 = t53 * t225;
    const float t253 = t252 * t206;
    const float t254 = -t253;
    const float t255 = t57 * t206;
    const float t256 = t208 + t59;
    const float t257 = t208 / t256;
    const float t258 = t255 * t257;
    const float t259 = t254 - t258;
    const float t260 = -t252;
    const float t261 = t57 * t257;
    const float t262 = t260 - t261;
    const float t263 = t53 * t206;
    const float t264 = -t263;
    const float t265 = t20 / t256;
    const float t266 = t256 * t256;
    const float t267 = t208 / t266;
    const float t268 = t265 - t267;
    const float t269 = t255 * t268;
    const float t270 = -t269;
    const float t271 = t264 * t230;
    const float t272 = t270 + t271;
    const float t273 = t77 * t225;
    const float t274 = t273 * t82;
    const float t275 = t274 * t206;
    const float t276 = t234 * t210;
    const float t277 = t275 - t276;
    const float t278 = t87 * t206;
    const float t279 = -t210;
    const float t280 = t278 * t230;
    const float t281 = -t234;
    const float t282 = t279 * t244;
    const float t283 = t281 + t282;
    const float t284 = t248 * t212;
    const float t285 = t250 * t215;
    const float t286 = t284 + t285;
    const float t287 = t251 * t219;
    const float t288 = t286 + t287;
    const float t289 = t248 * t213;
    const float t290 = t250 * t217;
    const float t291 = t289 + t290;
    const float t292 = t251 * t220;
    const float t293 = t291 + t292;
    const float t294 = t248 * t214;
    const float t295 = t250 * t218;
    const float t296 = t294 + t295;
    const float t297 = t251 * t222;
    const float t298 = t296 + t297;
    const float t299 = t262 * t212;
    const float t300 = t272 * t215;
    const float t301 = t299 + t300;
    const float t302 = t262 * t213;
    const float t303 = t272 * t217;
    const float t304 = t302 + t303;
    const float t305 = t262 * t214;
    const float t306 = t272 * t218;
    const float t307 = t305 + t306;
    const float t308 = t274 * t212;
    const float t309 = t280 * t215;
    const float t310 = t308 + t309;
    const float t311 = t283 * t219;
    const float t312 = t310 + t311;
    const float t313 = t274 * t213;
    const float t314 = t280 * t217;
    const float t315 = t313 + t314;
    const float t316 = t283 * t220;
    const float t317 = t315 + t316;
    const float t318 = t274 * t214;
    const float t319 = t280 * t218;
    const float t320 = t318 + t319;
    const float t321 = t283 * t222;
    const float t322 = t320 + t321;
    const float t323 = t9 * t247;
    const float t324 = t0 + t323;
    const float t325 = t9 * t259;
    const float t326 = t1 + t325;
    const float t327 = t9 * t277;
    const float t328 = t2 + t327;
    const float t329 = t9 * t288;
    const float t330 = t20 + t329;
    const float t331 = t9 * t293;
    const float t332 = t9 * t298;
    const float t333 = t9 * t301;
    const float t334 = t9 * t304;
    const float t335 = t20 + t334;
    const float t336 = t9 * t307;
    const float t337 = t9 * t312;
    const float t338 = t9 * t317;
    const float t339 = t9 * t322;
    const float t340 = t20 + t339;
    const float t341 = t15 + t326;
    const float t342 = t326 / t341;
    const float t343 = t14 * t342;
    const float t344 = t20 / t341;
    const float t345 = t341 * t341;
    const float t346 = t326 / t345;
    const float t347 = t344 - t346;
    const float t348 = t14 * t347;
    const float t349 = fmaxf(t328, t29);
    const float t350 = t28 / t349;
    const float t351 = libm_expf(t350);
    const float t352 = t26 * t351;
    const float t353 = t29 - t328;
    const float t354 = signum(t353);
    const float t355 = t35 * t354;
    const float t356 = t34 + t355;
    const float t357 = t28 * t356;
    const float t358 = t349 * t349;
    const float t359 = t357 / t358;
    const float t360 = -t359;
    const float t361 = t351 * t360;
    const float t362 = t26 * t361;
    const float t363 = t343 * t324;
    const float t364 = t352 * t324;
    const float t365 = t363 - t364;
    const float t366 = t343 - t352;
    const float t367 = -t324;
    const float t368 = t324 * t348;
    const float t369 = t367 * t362;
    const float t370 = t53 * t343;
    const float t371 = t370 * t324;
    const float t372 = -t371;
    const float t373 = t57 * t324;
    const float t374 = t326 + t59;
    const float t375 = t326 / t374;
    const float t376 = t373 * t375;
    const float t377 = t372 - t376;
    const float t378 = -t370;
    const float t379 = t57 * t375;
    const float t380 = t378 - t379;
    const float t381 = t53 * t324;
    const float t382 = -t381;
    const float t383 = t20 / t374;
    const float t384 = t374 * t374;
    const float t385 = t326 / t384;
    const float t386 = t383 - t385;
    const float t387 = t373 * t386;
    const float t388 = -t387;
    const float t389 = t382 * t348;
    const float t390 = t388 + t389;
    const float t391 = t77 * t343;
    const float t392 = t391 * t82;
    const float t393 = t392 * t324;
    const float t394 = t352 * t328;
    const float t395 = t393 - t394;
    const float t396 = t87 * t324;
    const float t397 = -t328;
    const float t398 = t396 * t348;
    const float t399 = -t352;
    const float t400 = t397 * t362;
    const float t401 = t399 + t400;
    const float t402 = t366 * t330;
    const float t403 = t368 * t333;
    const float t404 = t402 + t403;
    const float t405 = t369 * t337;
    const float t406 = t404 + t405;
    const float t407 = t366 * t331;
    const float t408 = t368 * t335;
    const float t409 = t407 + t408;
    const float t410 = t369 * t338;
    const float t411 = t409 + t410;
    const float t412 = t366 * t332;
    const float t413 = t368 * t336;
    const float t414 = t412 + t413;
    const float t415 = t369 * t340;
    const float t416 = t414 + t415;
    const float t417 = t380 * t330;
    const float t418 = t390 * t333;
    const float t419 = t417 + t418;
    const float t420 = t380 * t331;
    const float t421 = t390 * t335;
    const float t422 = t420 + t421;
    const float t423 = t380 * t332;
    const float t424 = t390 * t336;
    const float t425 = t423 + t424;
    const float t426 = t392 * t330;
    const float t427 = t398 * t333;
    const float t428 = t426 + t427;
    const float t429 = t401 * t337;
    const float t430 = t428 + t429;
    const float t431 = t392 * t331;
    const float t432 = t398 * t335;
    const float t433 = t431 + t432;
    const float t434 = t401 * t338;
    const float t435 = t433 + t434;
    const float t436 = t392 * t332;
    const float t437 = t398 * t336;
    const float t438 = t436 + t437;
    const float t439 = t401 * t340;
    const float t440 = t438 + t439;
    const float t441 = t135 + t247;
    const float t442 = t10 * t441;
    const float t443 = t48 + t442;
    const float t444 = t443 + t365;
    const float t445 = t13 * t444;
    const float t446 = t0 + t445;
    const float t447 = t147 + t259;
    const float t448 = t10 * t447;
    const float t449 = t63 + t448;
    const float t450 = t449 + t377;
    const float t451 = t13 * t450;
    const float t452 = t1 + t451;
    const float t453 = t165 + t277;
    const float t454 = t10 * t453;
    const float t455 = t86 + t454;
    const float t456 = t455 + t395;
    const float t457 = t13 * t456;
    const float t458 = t2 + t457;
    const float t459 = t176 + t288;
    const float t460 = t10 * t459;
    const float t461 = t49 + t460;
    const float t462 = t461 + t406;
    const float t463 = t13 * t462;
    const float t464 = t20 + t463;
    const float t465 = t181 + t293;
    const float t466 = t10 * t465;
    const float t467 = t51 + t466;
    const float t468 = t467 + t411;
    const float t469 = t13 * t468;
    const float t470 = t184 + t298;
    const float t471 = t10 * t470;
    const float t472 = t52 + t471;
    const float t473 = t472 + t416;
    const float t474 = t13 * t473;
    const float t475 = t187 + t301;
    const float t476 = t10 * t475;
    const float t477 = t66 + t476;
    const float t478 = t477 + t419;
    const float t479 = t13 * t478;
    const float t480 = t190 + t304;
    const float t481 = t10 * t480;
    const float t482 = t76 + t481;
    const float t483 = t482 + t422;
    const float t484 = t13 * t483;
    const float t485 = t20 + t484;
    const float t486 = t191 + t307;
    const float t487 = t10 * t486;
    const float t488 = t487 + t425;
    const float t489 = t13 * t488;
    const float t490 = t196 + t312;
    const float t491 = t10 * t490;
    const float t492 = t83 + t491;
    const float t493 = t492 + t430;
    const float t494 = t13 * t493;
    const float t495 = t201 + t317;
    const float t496 = t10 * t495;
    const float t497 = t90 + t496;
    const float t498 = t497 + t435;
    const float t499 = t13 * t498;
    const float t500 = t204 + t322;
    const float t501 = t10 * t500;
    const float t502 = t93 + t501;
    const float t503 = t502 + t440;
    const float t504 = t13 * t503;
    const float t505 = t20 + t504;
    const float t506 = t464 * t3;
    const float t507 = t469 * t4;
    const float t508 = t506 + t507;
    const float t509 = t474 * t5;
    const float t510 = t508 + t509;
    const float t511 = t464 * t4;
    const float t512 = t469 * t6;
    const float t513 = t511 + t512;
    const float t514 = t474 * t7;
    const float t515 = t513 + t514;
    const float t516 = t464 * t5;
    const float t517 = t469 * t7;
    const float t518 = t516 + t517;
    const float t519 = t474 * t8;
    const float t520 = t518 + t519;
    const float t521 = t479 * t3;
    const float t522 = t485 * t4;
    const float t523 = t521 + t522;
    const float t524 = t489 * t5;
    const float t525 = t523 + t524;
    const float t526 = t479 * t4;
    const float t527 = t485 * t6;
    const float t528 = t526 + t527;
    const float t529 = t489 * t7;
    const float t530 = t528 + t529;
    const float t531 = t479 * t5;
    const float t532 = t485 * t7;
    const float t533 = t531 + t532;
    const float t534 = t489 * t8;
    const float t535 = t533 + t534;
    const float t536 = t494 * t3;
    const float t537 = t499 * t4;
    const float t538 = t536 + t537;
    const float t539 = t505 * t5;
    const float t540 = t538 + t539;
    const float t541 = t494 * t4;
    const float t542 = t499 * t6;
    const float t543 = t541 + t542;
    const float t544 = t505 * t7;
    const float t545 = t543 + t544;
    const float t546 = t494 * t5;
    const float t547 = t499 * t7;
    const float t548 = t546 + t547;
    const float t549 = t505 * t8;
    const float t550 = t548 + t549;
    const float t551 = t510 * t464;
    const float t552 = t515 * t469;
    const float t553 = t551 + t552;
    const float t554 = t520 * t474;
    const float t555 = t553 + t554;
    const float t556 = t510 * t479;
    const float t557 = t515 * t485;
    const float t558 = t556 + t557;
    const float t559 = t520 * t489;
    const float t560 = t558 + t559;
    const float t561 = t510 * t494;
    const float t562 = t515 * t499;
    const float t563 = t561 + t562;
    const float t564 = t520 * t505;
    const float t565 = t563 + t564;
    const float t566 = t525 * t479;
    const float t567 = t530 * t485;
    const float t568 = t566 + t567;
    const float t569 = t535 * t489;
    const float t570 = t568 + t569;
    const float t571 = t525 * t494;
    const float t572 = t530 * t499;
    const float t573 = t571 + t572;
    const float t574 = t535 * t505;
    const float t575 = t573 + t574;
    const float t576 = t540 * t494;
    const float t577 = t545 * t499;
    const float t578 = t576 + t577;
    const float t579 = t550 * t505;
    const float t580 = t578 + t579;
    const float t581 = 0.00053441565f;
    const float t582 = t555 + t581;
    const float t583 = 0.00022407259f;
    const float t584 = t570 + t583;
    const float t585 = 6.2443684e-7f;
    const float t586 = t580 + t585;
    const float t587 = select_float(!(t446 >= t19), t19, t446);
    const float t588 = select_float(!(t452 >= t19), t19, t452);
    const float t589 = select_float(!(t458 >= t19), t19, t458);
    out[0] = t587;
    out[1] = t588;
    out[2] = t589;
    out[3] = t582;
    out[4] = t560;
    out[5] = t565;
    out[6] = t584;
    out[7] = t575;
    out[8] = t586;
}

/* The EKF's start: the centre of the state box and P(0)'s upper triangle. */
static const float EKF_X0[ECOLI_X0_0P5_STATES] = {
    0.5f, 2.5f, 0.15f
};
static const float EKF_P0[ECOLI_X0_0P5_COVARIANCE] = {
    0.005098792f, 0.0f, 0.0f, 0.4831565f,
    0.0f, 0.0051940335f
};

/* The EKF's prediction alone (a lost output), taken when finite. */
static void ekf_predict(float *x, float *p, const float *u) {
    float out[ECOLI_X0_0P5_STATES + ECOLI_X0_0P5_COVARIANCE];
    ekf_unmeasured(x, p, u, out);
    if (all_finite(out, ECOLI_X0_0P5_STATES + ECOLI_X0_0P5_COVARIANCE)) {
        memcpy(x, out, ECOLI_X0_0P5_STATES * sizeof *x);
        memcpy(p, out + ECOLI_X0_0P5_STATES, ECOLI_X0_0P5_COVARIANCE * sizeof *p);
    }
}

/* The EKF's sample with its measurement, taken when finite (1, the estimate x(k|k) in
 * `estimate`, its normalised innovation squared in `*nis`). */
static int ekf_measure(float *x, float *p, const float *y, const float *u, float *estimate, float *nis) {
    float out[2u * ECOLI_X0_0P5_STATES + ECOLI_X0_0P5_COVARIANCE + 1u];
    ekf_measured(x, p, y, u, out);
    if (!all_finite(out + ECOLI_X0_0P5_STATES, ECOLI_X0_0P5_STATES + ECOLI_X0_0P5_COVARIANCE)) {
        return 0;
    }
    *nis = out[2u * ECOLI_X0_0P5_STATES + ECOLI_X0_0P5_COVARIANCE];
    memcpy(estimate, out, ECOLI_X0_0P5_STATES * sizeof *x);
    memcpy(x, out + ECOLI_X0_0P5_STATES, ECOLI_X0_0P5_STATES * sizeof *x);
    memcpy(p, out + 2u * ECOLI_X0_0P5_STATES, ECOLI_X0_0P5_COVARIANCE * sizeof *p);
    return 1;
}


static void ekf_box_fresh(ecoli_x0_0p5_ekf_box *o) {
    memcpy(o->x, EKF_X0, sizeof o->x);
    memcpy(o->p, EKF_P0, sizeof o->p);
    o->chi = 2.0f;
}

static ecoli_x0_0p5_status ekf_box_sample(ecoli_x0_0p5_ekf_box *o, const float *y, const float *u) {
    float estimate[ECOLI_X0_0P5_STATES];
    float nis;
    unsigned i;
    if (!inputs_finite(u)) {
        return ECOLI_X0_0P5_REFUSED;
    }
    if (!accepts(y, u)) {
        ekf_predict(o->x, o->p, u);
        return ECOLI_X0_0P5_REFUSED;
    }
    if (!ekf_measure(o->x, o->p, y, u, estimate, &nis)) {
        ekf_box_fresh(o);
        return ECOLI_X0_0P5_RESTARTED;
    }
    /* The chi-squared watch (firmware::watch): the mean of the normalised innovations squared. */
    o->chi = o->chi + 0.33333334f * (nis - o->chi);
    if (!(o->chi <= 2048.0f)) {
        ekf_box_fresh(o);
        return ECOLI_X0_0P5_RESTARTED;
    }
    targets(estimate, u, o->values);
    for (i = 0u; i < ECOLI_X0_0P5_TARGETS; ++i) {
        o->flags[i] = ECOLI_X0_0P5_INSIDE;
    }
    o->ready = 1;
    return ECOLI_X0_0P5_OK;
}

void ecoli_x0_0p5_ekf_box_init(ecoli_x0_0p5_ekf_box *o) {
    ekf_box_fresh(o);
    o->ready = 0;
    o->refused = 0u;
    o->restarts = 0u;
}

ecoli_x0_0p5_status ecoli_x0_0p5_ekf_box_push(ecoli_x0_0p5_ekf_box *o, const float *y, const float *u) {
    const ecoli_x0_0p5_status status = ekf_box_sample(o, y, u);
    if (status == ECOLI_X0_0P5_REFUSED && o->refused != UINT32_MAX) {
        ++o->refused;
    } else if (status == ECOLI_X0_0P5_RESTARTED && o->restarts != UINT32_MAX) {
        ++o->restarts;
    }
    return status;
}

ecoli_x0_0p5_status ecoli_x0_0p5_ekf_box_estimate(const ecoli_x0_0p5_ekf_box *o, float *values, ecoli_x0_0p5_saturation *saturation) {
    if (!o->ready) {
        return ECOLI_X0_0P5_NO_ESTIMATE_YET;
    }
    memcpy(values, o->values, sizeof o->values);
    memcpy(saturation, o->flags, sizeof o->flags);
    return ECOLI_X0_0P5_OK;
}

/* One UKF sample with its measurement: out = (x(k|k), x+, P+, nis) from (x, P), nis the normalised innovation squared, as the Rust file's ukf_measured. */
static void ukf_measured(const float *x, const float *p, const float *y, const float *u, float *out) {
    (void)u;
    const float t0 = x[0];
    const float t1 = x[1];
    const float t2 = x[2];
    const float t3 = p[0];
    const float t4 = p[1];
    const float t5 = p[2];
    const float t6 = p[3];
    const float t7 = p[4];
    const float t8 = p[5];
    const float t9 = 0.0f;
    const float t10 = 1.0f;
    const float t11 = 1.1920929e-7f;
    const float t12 = fabsf(t3);
    const float t13 = t11 * t12;
    const float t14 = 1.1754944e-38f;
    const float t15 = t13 + t14;
    const float t16 = select_float(!(t3 >= t15), t15, t3);
    const float t17 = sqrtf(t16);
    const float t18 = t10 / t17;
    const float t19 = t4 * t18;
    const float t20 = t5 * t18;
    const float t21 = t19 * t19;
    const float t22 = t6 - t21;
    const float t23 = fabsf(t6);
    const float t24 = t11 * t23;
    const float t25 = t24 + t14;
    const float t26 = select_float(!(t22 >= t25), t25, t22);
    const float t27 = sqrtf(t26);
    const float t28 = t10 / t27;
    const float t29 = t20 * t19;
    const float t30 = t7 - t29;
    const float t31 = t30 * t28;
    const float t32 = t20 * t20;
    const float t33 = t31 * t31;
    const float t34 = t32 + t33;
    const float t35 = t8 - t34;
    const float t36 = fabsf(t8);
    const float t37 = t11 * t36;
    const float t38 = t37 + t14;
    const float t39 = select_float(!(t35 >= t38), t38, t35);
    const float t40 = sqrtf(t39);
    const float t41 = 1.7320508f;
    const float t42 = t41 * t17;
    const float t43 = t0 + t42;
    const float t44 = t41 * t19;
    const float t45 = t1 + t44;
    const float t46 = t41 * t20;
    const float t47 = t2 + t46;
    const float t48 = -5.2983174f;
    const float t49 = select_float(!(t43 >= t48), t48, t43);
    const float t50 = -3.6888795f;
    const float t51 = select_float(!(t45 >= t50), t50, t45);
    const float t52 = -6.5022902f;
    const float t53 = select_float(!(t47 >= t52), t52, t47);
    const float t54 = t41 * t27;
    const float t55 = t1 + t54;
    const float t56 = t41 * t31;
    const float t57 = t2 + t56;
    const float t58 = select_float(!(t0 >= t48), t48, t0);
    const float t59 = select_float(!(t55 >= t50), t50, t55);
    const float t60 = select_float(!(t57 >= t52), t52, t57);
    const float t61 = t41 * t40;
    const float t62 = t2 + t61;
    const float t63 = select_float(!(t1 >= t50), t50, t1);
    const float t64 = select_float(!(t62 >= t52), t52, t62);
    const float t65 = -1.7320508f;
    const float t66 = t65 * t17;
    const float t67 = t0 + t66;
    const float t68 = t65 * t19;
    const float t69 = t1 + t68;
    const float t70 = t65 * t20;
    const float t71 = t2 + t70;
    const float t72 = select_float(!(t67 >= t48), t48, t67);
    const float t73 = select_float(!(t69 >= t50), t50, t69);
    const float t74 = select_float(!(t71 >= t52), t52, t71);
    const float t75 = t65 * t27;
    const float t76 = t1 + t75;
    const float t77 = t65 * t31;
    const float t78 = t2 + t77;
    const float t79 = select_float(!(t76 >= t50), t50, t76);
    const float t80 = select_float(!(t78 >= t52), t52, t78);
    const float t81 = t65 * t40;
    const float t82 = t2 + t81;
    const float t83 = select_float(!(t82 >= t52), t52, t82);
    const float t84 = libm_expf(t49);
    const float t85 = libm_expf(t51);
    const float t86 = libm_expf(t53);
    const float t87 = -0.005f;
    const float t88 = t84 + t87;
    const float t89 = select_float(!(t88 >= t9), t9, t88);
    const float t90 = -0.025f;
    const float t91 = t85 + t90;
    const float t92 = select_float(!(t91 >= t9), t9, t91);
    const float t93 = -0.0015f;
    const float t94 = t86 + t93;
    const float t95 = select_float(!(t94 >= t9), t9, t94);
    const float t96 = 0.2f /* mu_m */;
    const float t97 = 0.1f /* k_s */;
    const float t98 = t97 + t92;
    const float t99 = t92 / t98;
    const float t100 = t96 * t99;
    const float t101 = 5000.0f /* y_l */;
    const float t102 = t101 * t100;
    const float t103 = 1.0f /* I */;
    const float t104 = 1.0f /* k_l */;
    const float t105 = t103 + t104;
    const float t106 = t103 / t105;
    const float t107 = t102 * t106;
    const float t108 = t107 * t89;
    const float t109 = t108 * t95;
    const float t110 = libm_expf(t58);
    const float t111 = libm_expf(t59);
    const float t112 = libm_expf(t60);
    const float t113 = t110 + t87;
    const float t114 = select_float(!(t113 >= t9), t9, t113);
    const float t115 = t111 + t90;
    const float t116 = select_float(!(t115 >= t9), t9, t115);
    const float t117 = t112 + t93;
    const float t118 = select_float(!(t117 >= t9), t9, t117);
    const float t119 = t97 + t116;
    const float t120 = t116 / t119;
    const float t121 = t96 * t120;
    const float t122 = t101 * t121;
    const float t123 = t122 * t106;
    const float t124 = t123 * t114;
    const float t125 = t124 * t118;
    const float t126 = libm_expf(t63);
    const float t127 = libm_expf(t64);
    const float t128 = t126 + t90;
    const float t129 = select_float(!(t128 >= t9), t9, t128);
    const float t130 = t127 + t93;
    const float t131 = select_float(!(t130 >= t9), t9, t130);
    const float t132 = t97 + t129;
    const float t133 = t129 / t132;
    const float t134 = t96 * t133;
    const float t135 = t101 * t134;
    const float t136 = t135 * t106;
    const float t137 = t136 * t114;
    const float t138 = t137 * t131;
    const float t139 = libm_expf(t72);
    const float t140 = libm_expf(t73);
    const float t141 = libm_expf(t74);
    const float t142 = t139 + t87;
    const float t143 = select_float(!(t142 >= t9), t9, t142);
    const float t144 = t140 + t90;
    const float t145 = select_float(!(t144 >= t9), t9, t144);
    const float t146 = t141 + t93;
    const float t147 = select_float(!(t146 >= t9), t9, t146);
    const float t148 = t97 + t145;
    const float t149 = t145 / t148;
    const float t150 = t96 * t149;
    const float t151 = t101 * t150;
    const float t152 = t151 * t106;
    const float t153 = t152 * t143;
    const float t154 = t153 * t147;
    const float t155 = libm_expf(t79);
    const float t156 = libm_expf(t80);
    const float t157 = t155 + t90;
    const float t158 = select_float(!(t157 >= t9), t9, t157);
    const float t159 = t156 + t93;
    const float t160 = select_float(!(t159 >= t9), t9, t159);
    const float t161 = t97 + t158;
    const float t162 = t158 / t161;
    const float t163 = t96 * t162;
    const float t164 = t101 * t163;
    const float t165 = t164 * t106;
    const float t166 = t165 * t114;
    const float t167 = t166 * t160;
    const float t168 = libm_expf(t83);
    const float t169 = t168 + t93;
    const float t170 = select_float(!(t169 >= t9), t9, t169);
    const float t171 = t137 * t170;
    const float t172 = 0.16666667f;
    const float t173 = t89 + t114;
    const float t174 = t173 + t114;
    const float t175 = t174 + t143;
    const float t176 = t175 + t114;
    const float t177 = t176 + t114;
    const float t178 = t172 * t177;
    const float t179 = t109 + t125;
    const float t180 = t179 + t138;
    const float t181 = t180 + t154;
    const float t182 = t181 + t167;
    const float t183 = t182 + t171;
    const float t184 = t172 * t183;
    const float t185 = t89 - t178;
    const float t186 = t109 - t184;
    const float t187 = t114 - t178;
    const float t188 = t125 - t184;
    const float t189 = t138 - t184;
    const float t190 = t143 - t178;
    const float t191 = t154 - t184;
    const float t192 = t167 - t184;
    const float t193 = t171 - t184;
    const float t194 = t49 + t58;
    const float t195 = t194 + t58;
    const float t196 = t195 + t72;
    const float t197 = t196 + t58;
    const float t198 = t197 + t58;
    const float t199 = t172 * t198;
    const float t200 = t51 + t59;
    const float t201 = t200 + t63;
    const float t202 = t201 + t73;
    const float t203 = t202 + t79;
    const float t204 = t203 + t63;
    const float t205 = t172 * t204;
    const float t206 = t53 + t60;
    const float t207 = t206 + t64;
    const float t208 = t207 + t74;
    const float t209 = t208 + t80;
    const float t210 = t209 + t83;
    const float t211 = t172 * t210;
    const float t212 = t49 - t199;
    const float t213 = t51 - t205;
    const float t214 = t53 - t211;
    const float t215 = t58 - t199;
    const float t216 = t59 - t205;
    const float t217 = t60 - t211;
    const float t218 = t63 - t205;
    const float t219 = t64 - t211;
    const float t220 = t72 - t199;
    const float t221 = t73 - t205;
    const float t222 = t74 - t211;
    const float t223 = t79 - t205;
    const float t224 = t80 - t211;
    const float t225 = t83 - t211;
    const float t226 = t212 * t212;
    const float t227 = t215 * t215;
    const float t228 = t226 + t227;
    const float t229 = t228 + t227;
    const float t230 = t220 * t220;
    const float t231 = t229 + t230;
    const float t232 = t231 + t227;
    const float t233 = t232 + t227;
    const float t234 = t172 * t233;
    const float t235 = t212 * t213;
    const float t236 = t215 * t216;
    const float t237 = t235 + t236;
    const float t238 = t215 * t218;
    const float t239 = t237 + t238;
    const float t240 = t220 * t221;
    const float t241 = t239 + t240;
    const float t242 = t215 * t223;
    const float t243 = t241 + t242;
    const float t244 = t243 + t238;
    const float t245 = t172 * t244;
    const float t246 = t212 * t214;
    const float t247 = t215 * t217;
    const float t248 = t246 + t247;
    const float t249 = t215 * t219;
    const float t250 = t248 + t249;
    const float t251 = t220 * t222;
    const float t252 = t250 + t251;
    const float t253 = t215 * t224;
    const float t254 = t252 + t253;
    const float t255 = t215 * t225;
    const float t256 = t254 + t255;
    const float t257 = t172 * t256;
    const float t258 = t213 * t213;
    const float t259 = t216 * t216;
    const float t260 = t258 + t259;
    const float t261 = t218 * t218;
    const float t262 = t260 + t261;
    const float t263 = t221 * t221;
    const float t264 = t262 + t263;
    const float t265 = t223 * t223;
    const float t266 = t264 + t265;
    const float t267 = t266 + t261;
    const float t268 = t172 * t267;
    const float t269 = t213 * t214;
    const float t270 = t216 * t217;
    const float t271 = t269 + t270;
    const float t272 = t218 * t219;
    const float t273 = t271 + t272;
    const float t274 = t221 * t222;
    const float t275 = t273 + t274;
    const float t276 = t223 * t224;
    const float t277 = t275 + t276;
    const float t278 = t218 * t225;
    const float t279 = t277 + t278;
    const float t280 = t172 * t279;
    const float t281 = t214 * t214;
    const float t282 = t217 * t217;
    const float t283 = t281 + t282;
    const float t284 = t219 * t219;
    const float t285 = t283 + t284;
    const float t286 = t222 * t222;
    const float t287 = t285 + t286;
    const float t288 = t224 * t224;
    const float t289 = t287 + t288;
    const float t290 = t225 * t225;
    const float t291 = t289 + t290;
    const float t292 = t172 * t291;
    const float t293 = t185 * t185;
    const float t294 = t187 * t187;
    const float t295 = t293 + t294;
    const float t296 = t295 + t294;
    const float t297 = t190 * t190;
    const float t298 = t296 + t297;
    const float t299 = t298 + t294;
    const float t300 = t299 + t294;
    const float t301 = t172 * t300;
    const float t302 = t185 * t186;
    const float t303 = t187 * t188;
    const float t304 = t302 + t303;
    const float t305 = t187 * t189;
    const float t306 = t304 + t305;
    const float t307 = t190 * t191;
    const float t308 = t306 + t307;
    const float t309 = t187 * t192;
    const float t310 = t308 + t309;
    const float t311 = t187 * t193;
    const float t312 = t310 + t311;
    const float t313 = t172 * t312;
    const float t314 = t186 * t186;
    const float t315 = t188 * t188;
    const float t316 = t314 + t315;
    const float t317 = t189 * t189;
    const float t318 = t316 + t317;
    const float t319 = t191 * t191;
    const float t320 = t318 + t319;
    const float t321 = t192 * t192;
    const float t322 = t320 + t321;
    const float t323 = t193 * t193;
    const float t324 = t322 + t323;
    const float t325 = t172 * t324;
    const float t326 = 0.1f;
    const float t327 = t301 + t326;
    const float t328 = 20.0f;
    const float t329 = t325 + t328;
    const float t330 = t212 * t185;
    const float t331 = t215 * t187;
    const float t332 = t330 + t331;
    const float t333 = t332 + t331;
    const float t334 = t220 * t190;
    const float t335 = t333 + t334;
    const float t336 = t335 + t331;
    const float t337 = t336 + t331;
    const float t338 = t172 * t337;
    const float t339 = t212 * t186;
    const float t340 = t215 * t188;
    const float t341 = t339 + t340;
    const float t342 = t215 * t189;
    const float t343 = t341 + t342;
    const float t344 = t220 * t191;
    const float t345 = t343 + t344;
    const float t346 = t215 * t192;
    const float t347 = t345 + t346;
    const float t348 = t215 * t193;
    const float t349 = t347 + t348;
    const float t350 = t172 * t349;
    const float t351 = t213 * t185;
    const float t352 = t216 * t187;
    const float t353 = t351 + t352;
    const float t354 = t218 * t187;
    const float t355 = t353 + t354;
    const float t356 = t221 * t190;
    const float t357 = t355 + t356;
    const float t358 = t223 * t187;
    const float t359 = t357 + t358;
    const float t360 = t359 + t354;
    const float t361 = t172 * t360;
    const float t362 = t213 * t186;
    const float t363 = t216 * t188;
    const float t364 = t362 + t363;
    const float t365 = t218 * t189;
    const float t366 = t364 + t365;
    const float t367 = t221 * t191;
    const float t368 = t366 + t367;
    const float t369 = t223 * t192;
    const float t370 = t368 + t369;
    const float t371 = t218 * t193;
    const float t372 = t370 + t371;
    const float t373 = t172 * t372;
    const float t374 = t214 * t185;
    const float t375 = t217 * t187;
    const float t376 = t374 + t375;
    const float t377 = t219 * t187;
    const float t378 = t376 + t377;
    const float t379 = t222 * t190;
    const float t380 = t378 + t379;
    const float t381 = t224 * t187;
    const float t382 = t380 + t381;
    const float t383 = t225 * t187;
    const float t384 = t382 + t383;
    const float t385 = t172 * t384;
    const float t386 = t214 * t186;
    const float t387 = t217 * t188;
    const float t388 = t386 + t387;
    const float t389 = t219 * t189;
    const float t390 = t388 + t389;
    const float t391 = t222 * t191;
    const float t392 = t390 + t391;
    const float t393 = t224 * t192;
    const float t394 = t392 + t393;
    const float t395 = t225 * t193;
    const float t396 = t394 + t395;
    const float t397 = t172 * t396;
    const float t398 = fabsf(t327);
    const float t399 = t11 * t398;
    const float t400 = t399 + t14;
    const float t401 = select_float(!(t327 >= t400), t400, t327);
    const float t402 = sqrtf(t401);
    const float t403 = t10 / t402;
    const float t404 = t313 * t403;
    const float t405 = t404 * t404;
    const float t406 = t329 - t405;
    const float t407 = fabsf(t329);
    const float t408 = t11 * t407;
    const float t409 = t408 + t14;
    const float t410 = select_float(!(t406 >= t409), t409, t406);
    const float t411 = sqrtf(t410);
    const float t412 = t10 / t411;
    const float t413 = t338 * t403;
    const float t414 = -t350;
    const float t415 = t404 * t413;
    const float t416 = t414 + t415;
    const float t417 = -t416;
    const float t418 = t417 * t412;
    const float t419 = t418 * t412;
    const float t420 = -t413;
    const float t421 = t404 * t419;
    const float t422 = t420 + t421;
    const float t423 = -t422;
    const float t424 = t423 * t403;
    const float t425 = t361 * t403;
    const float t426 = -t373;
    const float t427 = t404 * t425;
    const float t428 = t426 + t427;
    const float t429 = -t428;
    const float t430 = t429 * t412;
    const float t431 = t430 * t412;
    const float t432 = -t425;
    const float t433 = t404 * t431;
    const float t434 = t432 + t433;
    const float t435 = -t434;
    const float t436 = t435 * t403;
    const float t437 = t385 * t403;
    const float t438 = -t397;
    const float t439 = t404 * t437;
    const float t440 = t438 + t439;
    const float t441 = -t440;
    const float t442 = t441 * t412;
    const float t443 = t442 * t412;
    const float t444 = -t437;
    const float t445 = t404 * t443;
    const float t446 = t444 + t445;
    const float t447 = -t446;
    const float t448 = t447 * t403;
    const float t449 = y[0];
    const float t450 = t449 - t178;
    const float t451 = y[1];
    const float t452 = t451 - t184;
    const float t453 = t424 * t450;
    const float t454 = t199 + t453;
    const float t455 = t419 * t452;
    const float t456 = t454 + t455;
    const float t457 = t436 * t450;
    const float t458 = t205 + t457;
    const float t459 = t431 * t452;
    const float t460 = t458 + t459;
    const float t461 = t448 * t450;
    const float t462 = t211 + t461;
    const float t463 = t443 * t452;
    const float t464 = t462 + t463;
    const float t465 = t450 * t403;
    const float t466 = -t452;
    const float t467 = t404 * t465;
    const float t468 = t466 + t467;
    const float t469 = -t468;
    const float t470 = t469 * t412;
    const float t471 = t465 * t465;
    const float t472 = t470 * t470;
    const float t473 = t471 + t472;
    const float t474 = t338 * t424;
    const float t475 = t350 * t419;
    const float t476 = t474 + t475;
    const float t477 = t234 - t476;
    const float t478 = t338 * t436;
    const float t479 = t350 * t431;
    const float t480 = t478 + t479;
    const float t481 = t245 - t480;
    const float t482 = t338 * t448;
    const float t483 = t350 * t443;
    const float t484 = t482 + t483;
    const float t485 = t257 - t484;
    const float t486 = t361 * t436;
    const float t487 = t373 * t431;
    const float t488 = t486 + t487;
    const float t489 = t268 - t488;
    const float t490 = t361 * t448;
    const float t491 = t373 * t443;
    const float t492 = t490 + t491;
    const float t493 = t280 - t492;
    const float t494 = t385 * t448;
    const float t495 = t397 * t443;
    const float t496 = t494 + t495;
    const float t497 = t292 - t496;
    const float t498 = select_float(!(t456 >= t48), t48, t456);
    const float t499 = select_float(!(t460 >= t50), t50, t460);
    const float t500 = select_float(!(t464 >= t52), t52, t464);
    const float t501 = fabsf(t477);
    const float t502 = t11 * t501;
    const float t503 = t502 + t14;
    const float t504 = select_float(!(t477 >= t503), t503, t477);
    const float t505 = sqrtf(t504);
    const float t506 = t10 / t505;
    const float t507 = t481 * t506;
    const float t508 = t485 * t506;
    const float t509 = t507 * t507;
    const float t510 = t489 - t509;
    const float t511 = fabsf(t489);
    const float t512 = t11 * t511;
    const float t513 = t512 + t14;
    const float t514 = select_float(!(t510 >= t513), t513, t510);
    const float t515 = sqrtf(t514);
    const float t516 = t10 / t515;
    const float t517 = t508 * t507;
    const float t518 = t493 - t517;
    const float t519 = t518 * t516;
    const float t520 = t508 * t508;
    const float t521 = t519 * t519;
    const float t522 = t520 + t521;
    const float t523 = t497 - t522;
    const float t524 = fabsf(t497);
    const float t525 = t11 * t524;
    const float t526 = t525 + t14;
    const float t527 = select_float(!(t523 >= t526), t526, t523);
    const float t528 = sqrtf(t527);
    const float t529 = t41 * t505;
    const float t530 = t498 + t529;
    const float t531 = t41 * t507;
    const float t532 = t499 + t531;
    const float t533 = t41 * t508;
    const float t534 = t500 + t533;
    const float t535 = select_float(!(t530 >= t48), t48, t530);
    const float t536 = select_float(!(t532 >= t50), t50, t532);
    const float t537 = select_float(!(t534 >= t52), t52, t534);
    const float t538 = t41 * t515;
    const float t539 = t499 + t538;
    const float t540 = t41 * t519;
    const float t541 = t500 + t540;
    const float t542 = select_float(!(t498 >= t48), t48, t498);
    const float t543 = select_float(!(t539 >= t50), t50, t539);
    const float t544 = select_float(!(t541 >= t52), t52, t541);
    const float t545 = t41 * t528;
    const float t546 = t500 + t545;
    const float t547 = select_float(!(t499 >= t50), t50, t499);
    const float t548 = select_float(!(t546 >= t52), t52, t546);
    const float t549 = t65 * t505;
    const float t550 = t498 + t549;
    const float t551 = t65 * t507;
    const float t552 = t499 + t551;
    const float t553 = t65 * t508;
    const float t554 = t500 + t553;
    const float t555 = select_float(!(t550 >= t48), t48, t550);
    const float t556 = select_float(!(t552 >= t50), t50, t552);
    const float t557 = select_float(!(t554 >= t52), t52, t554);
    const float t558 = t65 * t515;
    const float t559 = t499 + t558;
    const float t560 = t65 * t519;
    const float t561 = t500 + t560;
    const float t562 = select_float(!(t559 >= t50), t50, t559);
    const float t563 = select_float(!(t561 >= t52), t52, t561);
    const float t564 = t65 * t528;
    const float t565 = t500 + t564;
    const float t566 = select_float(!(t565 >= t52), t52, t565);
    const float t567 = libm_expf(t535);
    const float t568 = t567 + t87;
    const float t569 = select_float(!(t568 >= t9), t9, t568);
    const float t570 = libm_expf(t536);
    const float t571 = t570 + t90;
    const float t572 = select_float(!(t571 >= t9), t9, t571);
    const float t573 = libm_expf(t537);
    const float t574 = t573 + t93;
    const float t575 = select_float(!(t574 >= t9), t9, t574);
    const float t576 = 0.2f;
    const float t577 = 2.0f;
    const float t578 = 6.0f;
    const float t579 = t576 / t577;
    const float t580 = t576 / t578;
    const float t581 = t97 + t572;
    const float t582 = t572 / t581;
    const float t583 = t96 * t582;
    const float t584 = 0.1f /* k_d */;
    const float t585 = 0.5f /* k_p */;
    const float t586 = -t585;
    const float t587 = 0.001f;
    const float t588 = fmaxf(t575, t587);
    const float t589 = t586 / t588;
    const float t590 = libm_expf(t589);
    const float t591 = t584 * t590;
    const float t592 = t583 * t569;
    const float t593 = t591 * t569;
    const float t594 = t592 - t593;
    const float t595 = 1.0f /* y_s */;
    const float t596 = t595 * t583;
    const float t597 = t596 * t569;
    const float t598 = -t597;
    const float t599 = 0.05f /* k_m */;
    const float t600 = t599 * t569;
    const float t601 = 0.01f /* ks_m */;
    const float t602 = t572 + t601;
    const float t603 = t572 / t602;
    const float t604 = t600 * t603;
    const float t605 = t598 - t604;
    const float t606 = 0.2f /* y_p */;
    const float t607 = t606 * t583;
    const float t608 = 0.5f /* k_I */;
    const float t609 = t103 + t608;
    const float t610 = t103 / t609;
    const float t611 = t607 * t610;
    const float t612 = t611 * t569;
    const float t613 = t591 * t575;
    const float t614 = t612 - t613;
    const float t615 = t579 * t594;
    const float t616 = t569 + t615;
    const float t617 = t579 * t605;
    const float t618 = t572 + t617;
    const float t619 = t579 * t614;
    const float t620 = t575 + t619;
    const float t621 = t97 + t618;
    const float t622 = t618 / t621;
    const float t623 = t96 * t622;
    const float t624 = fmaxf(t620, t587);
    const float t625 = t586 / t624;
    const float t626 = libm_expf(t625);
    const float t627 = t584 * t626;
    const float t628 = t623 * t616;
    const float t629 = t627 * t616;
    const float t630 = t628 - t629;
    const float t631 = t595 * t623;
    const float t632 = t631 * t616;
    const float t633 = -t632;
    const float t634 = t599 * t616;
    const float t635 = t618 + t601;
    const float t636 = t618 / t635;
    const float t637 = t634 * t636;
    const float t638 = t633 - t637;
    const float t639 = t606 * t623;
    const float t640 = t639 * t610;
    const float t641 = t640 * t616;
    const float t642 = t627 * t620;
    const float t643 = t641 - t642;
    const float t644 = t579 * t630;
    const float t645 = t569 + t644;
    const float t646 = t579 * t638;
    const float t647 = t572 + t646;
    const float t648 = t579 * t643;
    const float t649 = t575 + t648;
    const float t650 = t97 + t647;
    const float t651 = t647 / t650;
    const float t652 = t96 * t651;
    const float t653 = fmaxf(t649, t587);
    const float t654 = t586 / t653;
    const float t655 = libm_expf(t654);
    const float t656 = t584 * t655;
    const float t657 = t652 * t645;
    const float t658 = t656 * t645;
    const float t659 = t657 - t658;
    const float t660 = t595 * t652;
    const float t661 = t660 * t645;
    const float t662 = -t661;
    const float t663 = t599 * t645;
    const float t664 = t647 + t601;
    const float t665 = t647 / t664;
    const float t666 = t663 * t665;
    const float t667 = t662 - t666;
    const float t668 = t606 * t652;
    const float t669 = t668 * t610;
    const float t670 = t669 * t645;
    const float t671 = t656 * t649;
    const float t672 = t670 - t671;
    const float t673 = t576 * t659;
    const float t674 = t569 + t673;
    const float t675 = t576 * t667;
    const float t676 = t572 + t675;
    const float t677 = t576 * t672;
    const float t678 = t575 + t677;
    const float t679 = t97 + t676;
    const float t680 = t676 / t679;
    const float t681 = t96 * t680;
    const float t682 = fmaxf(t678, t587);
    const float t683 = t586 / t682;
    const float t684 = libm_expf(t683);
    const float t685 = t584 * t684;
    const float t686 = t681 * t674;
    const float t687 = t685 * t674;
    const float t688 = t686 - t687;
    const float t689 = t595 * t681;
    const float t690 = t689 * t674;
    const float t691 = -t690;
    const float t692 = t599 * t674;
    const float t693 = t676 + t601;
    const float t694 = t676 / t693;
    const float t695 = t692 * t694;
    const float t696 = t691 - t695;
    const float t697 = t606 * t681;
    const float t698 = t697 * t610;
    const float t699 = t698 * t674;
    const float t700 = t685 * t678;
    const float t701 = t699 - t700;
    const float t702 = t630 + t659;
    const float t703 = t577 * t702;
    const float t704 = t594 + t703;
    const float t705 = t704 + t688;
    const float t706 = t580 * t705;
    const float t707 = t569 + t706;
    const float t708 = t638 + t667;
    const float t709 = t577 * t708;
    const float t710 = t605 + t709;
    const float t711 = t710 + t696;
    const float t712 = t580 * t711;
    const float t713 = t572 + t712;
    const float t714 = t643 + t672;
    const float t715 = t577 * t714;
    const float t716 = t614 + t715;
    const float t717 = t716 + t701;
    const float t718 = t580 * t717;
    const float t719 = t575 + t718;
    const float t720 = 0.005f;
    const float t721 = t707 - t87;
    const float t722 = select_float(!(t721 >= t720), t720, t721);
    const float t723 = libm_logf(t722);
    const float t724 = 0.025f;
    const float t725 = t713 - t90;
    const float t726 = select_float(!(t725 >= t724), t724, t725);
    const float t727 = libm_logf(t726);
    const float t728 = 0.0015f;
    const float t729 = t719 - t93;
    const float t730 = select_float(!(t729 >= t728), t728, t729);
    const float t731 = libm_logf(t730);
    const float t732 = libm_expf(t542);
    const float t733 = t732 + t87;
    const float t734 = select_float(!(t733 >= t9), t9, t733);
    const float t735 = libm_expf(t543);
    const float t736 = t735 + t90;
    const float t737 = select_float(!(t736 >= t9), t9, t736);
    const float t738 = libm_expf(t544);
    const float t739 = t738 + t93;
    const float t740 = select_float(!(t739 >= t9), t9, t739);
    const float t741 = t97 + t737;
    const float t742 = t737 / t741;
    const float t743 = t96 * t742;
    const float t744 = fmaxf(t740, t587);
    const float t745 = t586 / t744;
    const float t746 = libm_expf(t745);
    const float t747 = t584 * t746;
    const float t748 = t743 * t734;
    const float t749 = t747 * t734;
    const float t750 = t748 - t749;
    const float t751 = t595 * t743;
    const float t752 = t751 * t734;
    const float t753 = -t752;
    const float t754 = t599 * t734;
    const float t755 = t737 + t601;
    const float t756 = t737 / t755;
    const float t757 = t754 * t756;
    const float t758 = t753 - t757;
    const float t759 = t606 * t743;
    const float t760 = t759 * t610;
    const float t761 = t760 * t734;
    const float t762 = t747 * t740;
    const float t763 = t761 - t762;
    const float t764 = t579 * t750;
    const float t765 = t734 + t764;
    const float t766 = t579 * t758;
    const float t767 = t737 + t766;
    const float t768 = t579 * t763;
    const float t769 = t740 + t768;
    const float t770 = t97 + t767;
    const float t771 = t767 / t770;
    const float t772 = t96 * t771;
    const float t773 = fmaxf(t769, t587);
    const float t774 = t586 / t773;
    const float t775 = libm_expf(t774);
    const float t776 = t584 * t775;
    const float t777 = t772 * t765;
    const float t778 = t776 * t765;
    const float t779 = t777 - t778;
    const float t780 = t595 * t772;
    const float t781 = t780 * t765;
    const float t782 = -t781;
    const float t783 = t599 * t765;
    const float t784 = t767 + t601;
    const float t785 = t767 / t784;
    const float t786 = t783 * t785;
    const float t787 = t782 - t786;
    const float t788 = t606 * t772;
    const float t789 = t788 * t610;
    const float t790 = t789 * t765;
    const float t791 = t776 * t769;
    const float t792 = t790 - t791;
    const float t793 = t579 * t779;
    const float t794 = t734 + t793;
    const float t795 = t579 * t787;
    const float t796 = t737 + t795;
    const float t797 = t579 * t792;
    const float t798 = t740 + t797;
    const float t799 = t97 + t796;
    const float t800 = t796 / t799;
    const float t801 = t96 * t800;
    const float t802 = fmaxf(t798, t587);
    const float t803 = t586 / t802;
    const float t804 = libm_expf(t803);
    const float t805 = t584 * t804;
    const float t806 = t801 * t794;
    const float t807 = t805 * t794;
    const float t808 = t806 - t807;
    const float t809 = t595 * t801;
    const float t810 = t809 * t794;
    const float t811 = -t810;
    const float t812 = t599 * t794;
    const float t813 = t796 + t601;
    const float t814 = t796 / t813;
    const float t815 = t812 * t814;
    const float t816 = t811 - t815;
    const float t817 = t606 * t801;
    const float t818 = t817 * t610;
    const float t819 = t818 * t794;
    const float t820 = t805 * t798;
    const float t821 = t819 - t820;
    const float t822 = t576 * t808;
    const float t823 = t734 + t822;
    const float t824 = t576 * t816;
    const float t825 = t737 + t824;
    const float t826 = t576 * t821;
    const float t827 = t740 + t826;
    const float t828 = t97 + t825;
    const float t829 = t825 / t828;
    const float t830 = t96 * t829;
    const float t831 = fmaxf(t827, t587);
    const float t832 = t586 / t831;
    const float t833 = libm_expf(t832);
    const float t834 = t584 * t833;
    const float t835 = t830 * t823;
    const float t836 = t834 * t823;
    const float t837 = t835 - t836;
    const float t838 = t595 * t830;
    const float t839 = t838 * t823;
    const float t840 = -t839;
    const float t841 = t599 * t823;
    const float t842 = t825 + t601;
    const float t843 = t825 / t842;
    const float t844 = t841 * t843;
    const float t845 = t840 - t844;
    const float t846 = t606 * t830;
    const float t847 = t846 * t610;
    const float t848 = t847 * t823;
    const float t849 = t834 * t827;
    const float t850 = t848 - t849;
    const float t851 = t779 + t808;
    const float t852 = t577 * t851;
    const float t853 = t750 + t852;
    const float t854 = t853 + t837;
    const float t855 = t580 * t854;
    const float t856 = t734 + t855;
    const float t857 = t787 + t816;
    const float t858 = t577 * t857;
    const float t859 = t758 + t858;
    const float t860 = t859 + t845;
    const float t861 = t580 * t860;
    const float t862 = t737 + t861;
    const float t863 = t792 + t821;
    const float t864 = t577 * t863;
    const float t865 = t763 + t864;
    const float t866 = t865 + t850;
    const float t867 = t580 * t866;
    const float t868 = t740 + t867;
    const float t869 = t856 - t87;
    const float t870 = select_float(!(t869 >= t720), t720, t869);
    const float t871 = libm_logf(t870);
    const float t872 = t862 - t90;
    const float t873 = select_float(!(t872 >= t724), t724, t872);
    const float t874 = libm_logf(t873);
    const float t875 = t868 - t93;
    const float t876 = select_float(!(t875 >= t728), t728, t875);
    const float t877 = libm_logf(t876);
    const float t878 = libm_expf(t547);
    const float t879 = t878 + t90;
    const float t880 = select_float(!(t879 >= t9), t9, t879);
    const float t881 = libm_expf(t548);
    const float t882 = t881 + t93;
    const float t883 = select_float(!(t882 >= t9), t9, t882);
    const float t884 = t97 + t880;
    const float t885 = t880 / t884;
    const float t886 = t96 * t885;
    const float t887 = fmaxf(t883, t587);
    const float t888 = t586 / t887;
    const float t889 = libm_expf(t888);
    const float t890 = t584 * t889;
    const float t891 = t886 * t734;
    const float t892 = t890 * t734;
    const float t893 = t891 - t892;
    const float t894 = t595 * t886;
    const float t895 = t894 * t734;
    const float t896 = -t895;
    const float t897 = t880 + t601;
    const float t898 = t880 / t897;
    const float t899 = t754 * t898;
    const float t900 = t896 - t899;
    const float t901 = t606 * t886;
    const float t902 = t901 * t610;
    const float t903 = t902 * t734;
    const float t904 = t890 * t883;
    const float t905 = t903 - t904;
    const float t906 = t579 * t893;
    const float t907 = t734 + t906;
    const float t908 = t579 * t900;
    const float t909 = t880 + t908;
    const float t910 = t579 * t905;
    const float t911 = t883 + t910;
    const float t912 = t97 + t909;
    const float t913 = t909 / t912;
    const float t914 = t96 * t913;
    const float t915 = fmaxf(t911, t587);
    const float t916 = t586 / t915;
    const float t917 = libm_expf(t916);
    const float t918 = t584 * t917;
    const float t919 = t914 * t907;
    const float t920 = t918 * t907;
    const float t921 = t919 - t920;
    const float t922 = t595 * t914;
    const float t923 = t922 * t907;
    const float t924 = -t923;
    const float t925 = t599 * t907;
    const float t926 = t909 + t601;
    const float t927 = t909 / t926;
    const float t928 = t925 * t927;
    const float t929 = t924 - t928;
    const float t930 = t606 * t914;
    const float t931 = t930 * t610;
    const float t932 = t931 * t907;
    const float t933 = t918 * t911;
    const float t934 = t932 - t933;
    const float t935 = t579 * t921;
    const float t936 = t734 + t935;
    const float t937 = t579 * t929;
    const float t938 = t880 + t937;
    const float t939 = t579 * t934;
    const float t940 = t883 + t939;
    const float t941 = t97 + t938;
    const float t942 = t938 / t941;
    const float t943 = t96 * t942;
    const float t944 = fmaxf(t940, t587);
    const float t945 = t586 / t944;
    const float t946 = libm_expf(t945);
    const float t947 = t584 * t946;
    const float t948 = t943 * t936;
    const float t949 = t947 * t936;
    const float t950 = t948 - t949;
    const float t951 = t595 * t943;
    const float t952 = t951 * t936;
    const float t953 = -t952;
    const float t954 = t599 * t936;
    const float t955 = t938 + t601;
    const float t956 = t938 / t955;
    const float t957 = t954 * t956;
    const float t958 = t953 - t957;
    const float t959 = t606 * t943;
    const float t960 = t959 * t610;
    const float t961 = t960 * t936;
    const float t962 = t947 * t940;
    const float t963 = t961 - t962;
    const float t964 = t576 * t950;
    const float t965 = t734 + t964;
    const float t966 = t576 * t958;
    const float t967 = t880 + t966;
    const float t968 = t576 * t963;
    const float t969 = t883 + t968;
    const float t970 = t97 + t967;
    const float t971 = t967 / t970;
    const float t972 = t96 * t971;
    const float t973 = fmaxf(t969, t587);
    const float t974 = t586 / t973;
    const float t975 = libm_expf(t974);
    const float t976 = t584 * t975;
    const float t977 = t972 * t965;
    const float t978 = t976 * t965;
    const float t979 = t977 - t978;
    const float t980 = t595 * t972;
    const float t981 = t980 * t965;
    const float t982 = -t981;
    const float t983 = t599 * t965;
    const float t984 = t967 + t601;
    const float t985 = t967 / t984;
    const float t986 = t983 * t985;
    const float t987 = t982 - t986;
    const float t988 = t606 * t972;
    const float t989 = t988 * t610;
    const float t990 = t989 * t965;
    const float t991 = t976 * t969;
    const float t992 = t990 - t991;
    const float t993 = t921 + t950;
    const float t994 = t577 * t993;
    const float t995 = t893 + t994;
    const float t996 = t995 + t979;
    const float t997 = t580 * t996;
    const float t998 = t734 + t997;
    const float t999 = t929 + t958;
    const float t1000 = t577 * t999;
    const float t1001 = t900 + t1000;
    const float t1002 = t1001 + t987;
    const float t1003 = t580 * t1002;
    const float t1004 = t880 + t1003;
    const float t1005 = t934 + t963;
    const float t1006 = t577 * t1005;
    const float t1007 = t905 + t1006;
    const float t1008 = t1007 + t992;
    const float t1009 = t580 * t1008;
    const float t1010 = t883 + t1009;
    const float t1011 = t998 - t87;
    const float t1012 = select_float(!(t1011 >= t720), t720, t1011);
    const float t1013 = libm_logf(t1012);
    const float t1014 = t1004 - t90;
    const float t1015 = select_float(!(t1014 >= t724), t724, t1014);
    const float t1016 = libm_logf(t1015);
    const float t1017 = t1010 - t93;
    const float t1018 = select_float(!(t1017 >= t728), t728, t1017);
    const float t1019 = libm_logf(t1018);
    const float t1020 = libm_expf(t555);
    const float t1021 = t1020 + t87;
    const float t1022 = select_float(!(t1021 >= t9), t9, t1021);
    const float t1023 = libm_expf(t556);
    const float t1024 = t1023 + t90;
    const float t1025 = select_float(!(t1024 >= t9), t9, t1024);
    const float t1026 = libm_expf(t557);
    const float t1027 = t1026 + t93;
    const float t1028 = select_float(!(t1027 >= t9), t9, t1027);
    const float t1029 = t97 + t1025;
    const float t1030 = t1025 / t1029;
    const float t1031 = t96 * t1030;
    const float t1032 = fmaxf(t1028, t587);
    const float t1033 = t586 / t1032;
    const float t1034 = libm_expf(t1033);
    const float t1035 = t584 * t1034;
    const float t1036 = t1031 * t1022;
    const float t1037 = t1035 * t1022;
    const float t1038 = t1036 - t1037;
    const float t1039 = t595 * t1031;
    const float t1040 = t1039 * t1022;
    const float t1041 = -t1040;
    const float t1042 = t599 * t1022;
    const float t1043 = t1025 + t601;
    const float t1044 = t1025 / t1043;
    const float t1045 = t1042 * t1044;
    const float t1046 = t1041 - t1045;
    const float t1047 = t606 * t1031;
    const float t1048 = t1047 * t610;
    const float t1049 = t1048 * t1022;
    const float t1050 = t1035 * t1028;
    const float t1051 = t1049 - t1050;
    const float t1052 = t579 * t1038;
    const float t1053 = t1022 + t1052;
    const float t1054 = t579 * t1046;
    const float t1055 = t1025 + t1054;
    const float t1056 = t579 * t1051;
    const float t1057 = t1028 + t1056;
    const float t1058 = t97 + t1055;
    const float t1059 = t1055 / t1058;
    const float t1060 = t96 * t1059;
    const float t1061 = fmaxf(t1057, t587);
    const float t1062 = t586 / t1061;
    const float t1063 = libm_expf(t1062);
    const float t1064 = t584 * t1063;
    const float t1065 = t1060 * t1053;
    const float t1066 = t1064 * t1053;
    const float t1067 = t1065 - t1066;
    const float t1068 = t595 * t1060;
    const float t1069 = t1068 * t1053;
    const float t1070 = -t1069;
    const float t1071 = t599 * t1053;
    const float t1072 = t1055 + t601;
    const float t1073 = t1055 / t1072;
    const float t1074 = t1071 * t1073;
    const float t1075 = t1070 - t1074;
    const float t1076 = t606 * t1060;
    const float t1077 = t1076 * t610;
    const float t1078 = t1077 * t1053;
    const float t1079 = t1064 * t1057;
    const float t1080 = t1078 - t1079;
    const float t1081 = t579 * t1067;
    const float t1082 = t1022 + t1081;
    const float t1083 = t579 * t1075;
    const float t1084 = t1025 + t1083;
    const float t1085 = t579 * t1080;
    const float t1086 = t1028 + t1085;
    const float t1087 = t97 + t1084;
    const float t1088 = t1084 / t1087;
    const float t1089 = t96 * t1088;
    const float t1090 = fmaxf(t1086, t587);
    const float t1091 = t586 / t1090;
    const float t1092 = libm_expf(t1091);
    const float t1093 = t584 * t1092;
    const float t1094 = t1089 * t1082;
    const float t1095 = t1093 * t1082;
    const float t1096 = t1094 - t1095;
    const float t1097 = t595 * t1089;
    const float t1098 = t1097 * t1082;
    const float t1099 = -t1098;
    const float t1100 = t599 * t1082;
    const float t1101 = t1084 + t601;
    const float t1102 = t1084 / t1101;
    const float t1103 = t1100 * t1102;
    const float t1104 = t1099 - t1103;
    const float t1105 = t606 * t1089;
    const float t1106 = t1105 * t610;
    const float t1107 = t1106 * t1082;
    const float t1108 = t1093 * t1086;
    const float t1109 = t1107 - t1108;
    const float t1110 = t576 * t1096;
    const float t1111 = t1022 + t1110;
    const float t1112 = t576 * t1104;
    const float t1113 = t1025 + t1112;
    const float t1114 = t576 * t1109;
    const float t1115 = t1028 + t1114;
    const float t1116 = t97 + t1113;
    const float t1117 = t1113 / t1116;
    const float t1118 = t96 * t1117;
    const float t1119 = fmaxf(t1115, t587);
    const float t1120 = t586 / t1119;
    const float t1121 = libm_expf(t1120);
    const float t1122 = t584 * t1121;
    const float t1123 = t1118 * t1111;
    const float t1124 = t1122 * t1111;
    const float t1125 = t1123 - t1124;
    const float t1126 = t595 * t1118;
    const float t1127 = t1126 * t1111;
    const float t1128 = -t1127;
    const float t1129 = t599 * t1111;
    const float t1130 = t1113 + t601;
    const float t1131 = t1113 / t1130;
    const float t1132 = t1129 * t1131;
    const float t1133 = t1128 - t1132;
    const float t1134 = t606 * t1118;
    const float t1135 = t1134 * t610;
    const float t1136 = t1135 * t1111;
    const float t1137 = t1122 * t1115;
    const float t1138 = t1136 - t1137;
    const float t1139 = t1067 + t1096;
    const float t1140 = t577 * t1139;
    const float t1141 = t1038 + t1140;
    const float t1142 = t1141 + t1125;
    const float t1143 = t580 * t1142;
    const float t1144 = t1022 + t1143;
    const float t1145 = t1075 + t1104;
    const float t1146 = t577 * t1145;
    const float t1147 = t1046 + t1146;
    const float t1148 = t1147 + t1133;
    const float t1149 = t580 * t1148;
    const float t1150 = t1025 + t1149;
    const float t1151 = t1080 + t1109;
    const float t1152 = t577 * t1151;
    const float t1153 = t1051 + t1152;
    const float t1154 = t1153 + t1138;
    const float t1155 = t580 * t1154;
    const float t1156 = t1028 + t1155;
    const float t1157 = t1144 - t87;
    const float t1158 = select_float(!(t1157 >= t720), t720, t1157);
    const float t1159 = libm_logf(t1158);
    const float t1160 = t1150 - t90;
    const float t1161 = select_float(!(t1160 >= t724), t724, t1160);
    const float t1162 = libm_logf(t1161);
    const float t1163 = t1156 - t93;
    const float t1164 = select_float(!(t1163 >= t728), t728, t1163);
    const float t1165 = libm_logf(t1164);
    const float t1166 = libm_expf(t562);
    const float t1167 = t1166 + t90;
    const float t1168 = select_float(!(t1167 >= t9), t9, t1167);
    const float t1169 = libm_expf(t563);
    const float t1170 = t1169 + t93;
    const float t1171 = select_float(!(t1170 >= t9), t9, t1170);
    const float t1172 = t97 + t1168;
    const float t1173 = t1168 / t1172;
    const float t1174 = t96 * t1173;
    const float t1175 = fmaxf(t1171, t587);
    const float t1176 = t586 / t1175;
    const float t1177 = libm_expf(t1176);
    const float t1178 = t584 * t1177;
    const float t1179 = t1174 * t734;
    const float t1180 = t1178 * t734;
    const float t1181 = t1179 - t1180;
    const float t1182 = t595 * t1174;
    const float t1183 = t1182 * t734;
    const float t1184 = -t1183;
    const float t1185 = t1168 + t601;
    const float t1186 = t1168 / t1185;
    const float t1187 = t754 * t1186;
    const float t1188 = t1184 - t1187;
    const float t1189 = t606 * t1174;
    const float t1190 = t1189 * t610;
    const float t1191 = t1190 * t734;
    const float t1192 = t1178 * t1171;
    const float t1193 = t1191 - t1192;
    const float t1194 = t579 * t1181;
    const float t1195 = t734 + t1194;
    const float t1196 = t579 * t1188;
    const float t1197 = t1168 + t1196;
    const float t1198 = t579 * t1193;
    const float t1199 = t1171 + t1198;
    const float t1200 = t97 + t1197;
    const float t1201 = t1197 / t1200;
    const float t1202 = t96 * t1201;
    const float t1203 = fmaxf(t1199, t587);
    const float t1204 = t586 / t1203;
    const float t1205 = libm_expf(t1204);
    const float t1206 = t584 * t1205;
    const float t1207 = t1202 * t1195;
    const float t1208 = t1206 * t1195;
    const float t1209 = t1207 - t1208;
    const float t1210 = t595 * t1202;
    const float t1211 = t1210 * t1195;
    const float t1212 = -t1211;
    const float t1213 = t599 * t1195;
    const float t1214 = t1197 + t601;
    const float t1215 = t1197 / t1214;
    const float t1216 = t1213 * t1215;
    const float t1217 = t1212 - t1216;
    const float t1218 = t606 * t1202;
    const float t1219 = t1218 * t610;
    const float t1220 = t1219 * t1195;
    const float t1221 = t1206 * t1199;
    const float t1222 = t1220 - t1221;
    const float t1223 = t579 * t1209;
    const float t1224 = t734 + t1223;
    const float t1225 = t579 * t1217;
    const float t1226 = t1168 + t1225;
    const float t1227 = t579 * t1222;
    const float t1228 = t1171 + t1227;
    const float t1229 = t97 + t1226;
    const float t1230 = t1226 / t1229;
    const float t1231 = t96 * t1230;
    const float t1232 = fmaxf(t1228, t587);
    const float t1233 = t586 / t1232;
    const float t1234 = libm_expf(t1233);
    const float t1235 = t584 * t1234;
    const float t1236 = t1231 * t1224;
    const float t1237 = t1235 * t1224;
    const float t1238 = t1236 - t1237;
    const float t1239 = t595 * t1231;
    const float t1240 = t1239 * t1224;
    const float t1241 = -t1240;
    const float t1242 = t599 * t1224;
    const float t1243 = t1226 + t601;
    const float t1244 = t1226 / t1243;
    const float t1245 = t1242 * t1244;
    const float t1246 = t1241 - t1245;
    const float t1247 = t606 * t1231;
    const float t1248 = t1247 * t610;
    const float t1249 = t1248 * t1224;
    const float t1250 = t1235 * t1228;
    const float t1251 = t1249 - t1250;
    const float t1252 = t576 * t1238;
    const float t1253 = t734 + t1252;
    const float t1254 = t576 * t1246;
    const float t1255 = t1168 + t1254;
    const float t1256 = t576 * t1251;
    const float t1257 = t1171 + t1256;
    const float t1258 = t97 + t1255;
    const float t1259 = t1255 / t1258;
    const float t1260 = t96 * t1259;
    const float t1261 = fmaxf(t1257, t587);
    const float t1262 = t586 / t1261;
    const float t1263 = libm_expf(t1262);
    const float t1264 = t584 * t1263;
    const float t1265 = t1260 * t1253;
    const float t1266 = t1264 * t1253;
    const float t1267 = t1265 - t1266;
    const float t1268 = t595 * t1260;
    const float t1269 = t1268 * t1253;
    const float t1270 = -t1269;
    const float t1271 = t599 * t1253;
    const float t1272 = t1255 + t601;
    const float t1273 = t1255 / t1272;
    const float t1274 = t1271 * t1273;
    const float t1275 = t1270 - t1274;
    const float t1276 = t606 * t1260;
    const float t1277 = t1276 * t610;
    const float t1278 = t1277 * t1253;
    const float t1279 = t1264 * t1257;
    const float t1280 = t1278 - t1279;
    const float t1281 = t1209 + t1238;
    const float t1282 = t577 * t1281;
    const float t1283 = t1181 + t1282;
    const float t1284 = t1283 + t1267;
    const float t1285 = t580 * t1284;
    const float t1286 = t734 + t1285;
    const float t1287 = t1217 + t1246;
    const float t1288 = t577 * t1287;
    const float t1289 = t1188 + t1288;
    const float t1290 = t1289 + t1275;
    const float t1291 = t580 * t1290;
    const float t1292 = t1168 + t1291;
    const float t1293 = t1222 + t1251;
    const float t1294 = t577 * t1293;
    const float t1295 = t1193 + t1294;
    const float t1296 = t1295 + t1280;
    const float t1297 = t580 * t1296;
    const float t1298 = t1171 + t1297;
    const float t1299 = t1286 - t87;
    const float t1300 = select_float(!(t1299 >= t720), t720, t1299);
    const float t1301 = libm_logf(t1300);
    const float t1302 = t1292 - t90;
    const float t1303 = select_float(!(t1302 >= t724), t724, t1302);
    const float t1304 = libm_logf(t1303);
    const float t1305 = t1298 - t93;
    const float t1306 = select_float(!(t1305 >= t728), t728, t1305);
    const float t1307 = libm_logf(t1306);
    const float t1308 = libm_expf(t566);
    const float t1309 = t1308 + t93;
    const float t1310 = select_float(!(t1309 >= t9), t9, t1309);
    const float t1311 = fmaxf(t1310, t587);
    const float t1312 = t586 / t1311;
    const float t1313 = libm_expf(t1312);
    const float t1314 = t584 * t1313;
    const float t1315 = t1314 * t734;
    const float t1316 = t891 - t1315;
    const float t1317 = t1314 * t1310;
    const float t1318 = t903 - t1317;
    const float t1319 = t579 * t1316;
    const float t1320 = t734 + t1319;
    const float t1321 = t579 * t1318;
    const float t1322 = t1310 + t1321;
    const float t1323 = fmaxf(t1322, t587);
    const float t1324 = t586 / t1323;
    const float t1325 = libm_expf(t1324);
    const float t1326 = t584 * t1325;
    const float t1327 = t914 * t1320;
    const float t1328 = t1326 * t1320;
    const float t1329 = t1327 - t1328;
    const float t1330 = t922 * t1320;
    const float t1331 = -t1330;
    const float t1332 = t599 * t1320;
    const float t1333 = t1332 * t927;
    const float t1334 = t1331 - t1333;
    const float t1335 = t931 * t1320;
    const float t1336 = t1326 * t1322;
    const float t1337 = t1335 - t1336;
    const float t1338 = t579 * t1329;
    const float t1339 = t734 + t1338;
    const float t1340 = t579 * t1334;
    const float t1341 = t880 + t1340;
    const float t1342 = t579 * t1337;
    const float t1343 = t1310 + t1342;
    const float t1344 = t97 + t1341;
    const float t1345 = t1341 / t1344;
    const float t1346 = t96 * t1345;
    const float t1347 = fmaxf(t1343, t587);
    const float t1348 = t586 / t1347;
    const float t1349 = libm_expf(t1348);
    const float t1350 = t584 * t1349;
    const float t1351 = t1346 * t1339;
    const float t1352 = t1350 * t1339;
    const float t1353 = t1351 - t1352;
    const float t1354 = t595 * t1346;
    const float t1355 = t1354 * t1339;
    const float t1356 = -t1355;
    const float t1357 = t599 * t1339;
    const float t1358 = t1341 + t601;
    const float t1359 = t1341 / t1358;
    const float t1360 = t1357 * t1359;
    const float t1361 = t1356 - t1360;
    const float t1362 = t606 * t1346;
    const float t1363 = t1362 * t610;
    const float t1364 = t1363 * t1339;
    const float t1365 = t1350 * t1343;
    const float t1366 = t1364 - t1365;
    const float t1367 = t576 * t1353;
    const float t1368 = t734 + t1367;
    const float t1369 = t576 * t1361;
    const float t1370 = t880 + t1369;
    const float t1371 = t576 * t1366;
    const float t1372 = t1310 + t1371;
    const float t1373 = t97 + t1370;
    const float t1374 = t1370 / t1373;
    const float t1375 = t96 * t1374;
    const float t1376 = fmaxf(t1372, t587);
    const float t1377 = t586 / t1376;
    const float t1378 = libm_expf(t1377);
    const float t1379 = t584 * t1378;
    const float t1380 = t1375 * t1368;
    const float t1381 = t1379 * t1368;
    const float t1382 = t1380 - t1381;
    const float t1383 = t595 * t1375;
    const float t1384 = t1383 * t1368;
    const float t1385 = -t1384;
    const float t1386 = t599 * t1368;
    const float t1387 = t1370 + t601;
    const float t1388 = t1370 / t1387;
    const float t1389 = t1386 * t1388;
    const float t1390 = t1385 - t1389;
    const float t1391 = t606 * t1375;
    const float t1392 = t1391 * t610;
    const float t1393 = t1392 * t1368;
    const float t1394 = t1379 * t1372;
    const float t1395 = t1393 - t1394;
    const float t1396 = t1329 + t1353;
    const float t1397 = t577 * t1396;
    const float t1398 = t1316 + t1397;
    const float t1399 = t1398 + t1382;
    const float t1400 = t580 * t1399;
    const float t1401 = t734 + t1400;
    const float t1402 = t1334 + t1361;
    const float t1403 = t577 * t1402;
    const float t1404 = t900 + t1403;
    const float t1405 = t1404 + t1390;
    const float t1406 = t580 * t1405;
    const float t1407 = t880 + t1406;
    const float t1408 = t1337 + t1366;
    const float t1409 = t577 * t1408;
    const float t1410 = t1318 + t1409;
    const float t1411 = t1410 + t1395;
    const float t1412 = t580 * t1411;
    const float t1413 = t1310 + t1412;
    const float t1414 = t1401 - t87;
    const float t1415 = select_float(!(t1414 >= t720), t720, t1414);
    const float t1416 = libm_logf(t1415);
    const float t1417 = t1407 - t90;
    const float t1418 = select_float(!(t1417 >= t724), t724, t1417);
    const float t1419 = libm_logf(t1418);
    const float t1420 = t1413 - t93;
    const float t1421 = select_float(!(t1420 >= t728), t728, t1420);
    const float t1422 = libm_logf(t1421);
    const float t1423 = t723 + t871;
    const float t1424 = t1423 + t1013;
    const float t1425 = t1424 + t1159;
    const float t1426 = t1425 + t1301;
    const float t1427 = t1426 + t1416;
    const float t1428 = t172 * t1427;
    const float t1429 = t727 + t874;
    const float t1430 = t1429 + t1016;
    const float t1431 = t1430 + t1162;
    const float t1432 = t1431 + t1304;
    const float t1433 = t1432 + t1419;
    const float t1434 = t172 * t1433;
    const float t1435 = t731 + t877;
    const float t1436 = t1435 + t1019;
    const float t1437 = t1436 + t1165;
    const float t1438 = t1437 + t1307;
    const float t1439 = t1438 + t1422;
    const float t1440 = t172 * t1439;
    const float t1441 = t723 - t1428;
    const float t1442 = t727 - t1434;
    const float t1443 = t731 - t1440;
    const float t1444 = t871 - t1428;
    const float t1445 = t874 - t1434;
    const float t1446 = t877 - t1440;
    const float t1447 = t1013 - t1428;
    const float t1448 = t1016 - t1434;
    const float t1449 = t1019 - t1440;
    const float t1450 = t1159 - t1428;
    const float t1451 = t1162 - t1434;
    const float t1452 = t1165 - t1440;
    const float t1453 = t1301 - t1428;
    const float t1454 = t1304 - t1434;
    const float t1455 = t1307 - t1440;
    const float t1456 = t1416 - t1428;
    const float t1457 = t1419 - t1434;
    const float t1458 = t1422 - t1440;
    const float t1459 = t1441 * t1441;
    const float t1460 = t1444 * t1444;
    const float t1461 = t1459 + t1460;
    const float t1462 = t1447 * t1447;
    const float t1463 = t1461 + t1462;
    const float t1464 = t1450 * t1450;
    const float t1465 = t1463 + t1464;
    const float t1466 = t1453 * t1453;
    const float t1467 = t1465 + t1466;
    const float t1468 = t1456 * t1456;
    const float t1469 = t1467 + t1468;
    const float t1470 = t172 * t1469;
    const float t1471 = t1441 * t1442;
    const float t1472 = t1444 * t1445;
    const float t1473 = t1471 + t1472;
    const float t1474 = t1447 * t1448;
    const float t1475 = t1473 + t1474;
    const float t1476 = t1450 * t1451;
    const float t1477 = t1475 + t1476;
    const float t1478 = t1453 * t1454;
    const float t1479 = t1477 + t1478;
    const float t1480 = t1456 * t1457;
    const float t1481 = t1479 + t1480;
    const float t1482 = t172 * t1481;
    const float t1483 = t1441 * t1443;
    const float t1484 = t1444 * t1446;
    const float t1485 = t1483 + t1484;
    const float t1486 = t1447 * t1449;
    const float t1487 = t1485 + t1486;
    const float t1488 = t1450 * t1452;
    const float t1489 = t1487 + t1488;
    const float t1490 = t1453 * t1455;
    const float t1491 = t1489 + t1490;
    const float t1492 = t1456 * t1458;
    const float t1493 = t1491 + t1492;
    const float t1494 = t172 * t1493;
    const float t1495 = t1442 * t1442;
    const float t1496 = t1445 * t1445;
    const float t1497 = t1495 + t1496;
    const float t1498 = t1448 * t1448;
    const float t1499 = t1497 + t1498;
    const float t1500 = t1451 * t1451;
    const float t1501 = t1499 + t1500;
    const float t1502 = t1454 * t1454;
    const float t1503 = t1501 + t1502;
    const float t1504 = t1457 * t1457;
    const float t1505 = t1503 + t1504;
    const float t1506 = t172 * t1505;
    const float t1507 = t1442 * t1443;
    const float t1508 = t1445 * t1446;
    const float t1509 = t1507 + t1508;
    const float t1510 = t1448 * t1449;
    const float t1511 = t1509 + t1510;
    const float t1512 = t1451 * t1452;
    const float t1513 = t1511 + t1512;
    const float t1514 = t1454 * t1455;
    const float t1515 = t1513 + t1514;
    const float t1516 = t1457 * t1458;
    const float t1517 = t1515 + t1516;
    const float t1518 = t172 * t1517;
    const float t1519 = t1443 * t1443;
    const float t1520 = t1446 * t1446;
    const float t1521 = t1519 + t1520;
    const float t1522 = t1449 * t1449;
    const float t1523 = t1521 + t1522;
    const float t1524 = t1452 * t1452;
    const float t1525 = t1523 + t1524;
    const float t1526 = t1455 * t1455;
    const float t1527 = t1525 + t1526;
    const float t1528 = t1458 * t1458;
    const float t1529 = t1527 + t1528;
    const float t1530 = t172 * t1529;
    const float t1531 = 6.4324554e-6f;
    const float t1532 = t1470 + t1531;
    const float t1533 = 4.555184e-6f;
    const float t1534 = t1506 + t1533;
    const float t1535 = 7.5633906e-8f;
    const float t1536 = t1530 + t1535;
    const float t1537 = select_float(!(t1428 >= t48), t48, t1428);
    const float t1538 = select_float(!(t1434 >= t50), t50, t1434);
    const float t1539 = select_float(!(t1440 >= t52), t52, t1440);
    out[0] = t498;
    out[1] = t499;
    out[2] = t500;
    out[3] = t1537;
    out[4] = t1538;
    out[5] = t1539;
    out[6] = t1532;
    out[7] = t1482;
    out[8] = t1494;
    out[9] = t1534;
    out[10] = t1518;
    out[11] = t1536;
    out[12] = t473;
}

/* One UKF sample without its measurement: out = (x+, P+) from (x, P), as the Rust file's ukf_unmeasured. */
static void ukf_unmeasured(const float *x, const float *p, const float *u, float *out) {
    (void)u;
    const float t0 = x[0];
    const float t1 = x[1];
    const float t2 = x[2];
    const float t3 = p[0];
    const float t4 = p[1];
    const float t5 = p[2];
    const float t6 = p[3];
    const float t7 = p[4];
    const float t8 = p[5];
    const float t9 = 0.0f;
    const float t10 = 1.0f;
    const float t11 = 1.1920929e-7f;
    const float t12 = fabsf(t3);
    const float t13 = t11 * t12;
    const float t14 = 1.1754944e-38f;
    const float t15 = t13 + t14;
    const float t16 = select_float(!(t3 >= t15), t15, t3);
    const float t17 = sqrtf(t16);
    const float t18 = t10 / t17;
    const float t19 = t4 * t18;
    const float t20 = t5 * t18;
    const float t21 = t19 * t19;
    const float t22 = t6 - t21;
    const float t23 = fabsf(t6);
    const float t24 = t11 * t23;
    const float t25 = t24 + t14;
    const float t26 = select_float(!(t22 >= t25), t25, t22);
    const float t27 = sqrtf(t26);
    const float t28 = t10 / t27;
    const float t29 = t20 * t19;
    const float t30 = t7 - t29;
    const float t31 = t30 * t28;
    const float t32 = t20 * t20;
    const float t33 = t31 * t31;
    const float t34 = t32 + t33;
    const float t35 = t8 - t34;
    const float t36 = fabsf(t8);
    const float t37 = t11 * t36;
    const float t38 = t37 + t14;
    const float t39 = select_float(!(t35 >= t38), t38, t35);
    const float t40 = sqrtf(t39);
    const float t41 = 1.7320508f;
    const float t42 = t41 * t17;
    const float t43 = t0 + t42;
    const float t44 = t41 * t19;
    const float t45 = t1 + t44;
    const float t46 = t41 * t20;
    const float t47 = t2 + t46;
    const float t48 = -5.2983174f;
    const float t49 = select_float(!(t43 >= t48), t48, t43);
    const float t50 = -3.6888795f;
    const float t51 = select_float(!(t45 >= t50), t50, t45);
    const float t52 = -6.5022902f;
    const float t53 = select_float(!(t47 >= t52), t52, t47);
    const float t54 = t41 * t27;
    const float t55 = t1 + t54;
    const float t56 = t41 * t31;
    const float t57 = t2 + t56;
    const float t58 = select_float(!(t0 >= t48), t48, t0);
    const float t59 = select_float(!(t55 >= t50), t50, t55);
    const float t60 = select_float(!(t57 >= t52), t52, t57);
    const float t61 = t41 * t40;
    const float t62 = t2 + t61;
    const float t63 = select_float(!(t1 >= t50), t50, t1);
    const float t64 = select_float(!(t62 >= t52), t52, t62);
    const float t65 = -1.7320508f;
    const float t66 = t65 * t17;
    const float t67 = t0 + t66;
    const float t68 = t65 * t19;
    const float t69 = t1 + t68;
    const float t70 = t65 * t20;
    const float t71 = t2 + t70;
    const float t72 = select_float(!(t67 >= t48), t48, t67);
    const float t73 = select_float(!(t69 >= t50), t50, t69);
    const float t74 = select_float(!(t71 >= t52), t52, t71);
    const float t75 = t65 * t27;
    const float t76 = t1 + t75;
    const float t77 = t65 * t31;
    const float t78 = t2 + t77;
    const float t79 = select_float(!(t76 >= t50), t50, t76);
    const float t80 = select_float(!(t78 >= t52), t52, t78);
    const float t81 = t65 * t40;
    const float t82 = t2 + t81;
    const float t83 = select_float(!(t82 >= t52), t52, t82);
    const float t84 = libm_expf(t49);
    const float t85 = -0.005f;
    const float t86 = t84 + t85;
    const float t87 = select_float(!(t86 >= t9), t9, t86);
    const float t88 = libm_expf(t51);
    const float t89 = -0.025f;
    const float t90 = t88 + t89;
    const float t91 = select_float(!(t90 >= t9), t9, t90);
    const float t92 = libm_expf(t53);
    const float t93 = -0.0015f;
    const float t94 = t92 + t93;
    const float t95 = select_float(!(t94 >= t9), t9, t94);
    const float t96 = 0.2f;
    const float t97 = 2.0f;
    const float t98 = 6.0f;
    const float t99 = t96 / t97;
    const float t100 = t96 / t98;
    const float t101 = 0.2f /* mu_m */;
    const float t102 = 0.1f /* k_s */;
    const float t103 = t102 + t91;
    const float t104 = t91 / t103;
    const float t105 = t101 * t104;
    const float t106 = 0.1f /* k_d */;
    const float t107 = 0.5f /* k_p */;
    const float t108 = -t107;
    const float t109 = 0.001f;
    const float t110 = fmaxf(t95, t109);
    const float t111 = t108 / t110;
    const float t112 = libm_expf(t111);
    const float t113 = t106 * t112;
    const float t114 = t105 * t87;
    const float t115 = t113 * t87;
    const float t116 = t114 - t115;
    const float t117 = 1.0f /* y_s */;
    const float t118 = t117 * t105;
    const float t119 = t118 * t87;
    const float t120 = -t119;
    const float t121 = 0.05f /* k_m */;
    const float t122 = t121 * t87;
    const float t123 = 0.01f /* ks_m */;
    const float t124 = t91 + t123;
    const float t125 = t91 / t124;
    const float t126 = t122 * t125;
    const float t127 = t120 - t126;
    const float t128 = 0.2f /* y_p */;
    const float t129 = t128 * t105;
    const float t130 = 1.0f /* I */;
    const float t131 = 0.5f /* k_I */;
    const float t132 = t130 + t131;
    const float t133 = t130 / t132;
    const float t134 = t129 * t133;
    const float t135 = t134 * t87;
    const float t136 = t113 * t95;
    const float t137 = t135 - t136;
    const float t138 = t99 * t116;
    const float t139 = t87 + t138;
    const float t140 = t99 * t127;
    const float t141 = t91 + t140;
    const float t142 = t99 * t137;
    const float t143 = t95 + t142;
    const float t144 = t102 + t141;
    const float t145 = t141 / t144;
    const float t146 = t101 * t145;
    const float t147 = fmaxf(t143, t109);
    const float t148 = t108 / t147;
    const float t149 = libm_expf(t148);
    const float t150 = t106 * t149;
    const float t151 = t146 * t139;
    const float t152 = t150 * t139;
    const float t153 = t151 - t152;
    const float t154 = t117 * t146;
    const float t155 = t154 * t139;
    const float t156 = -t155;
    const float t157 = t121 * t139;
    const float t158 = t141 + t123;
    const float t159 = t141 / t158;
    const float t160 = t157 * t159;
    const float t161 = t156 - t160;
    const float t162 = t128 * t146;
    const float t163 = t162 * t133;
    const float t164 = t163 * t139;
    const float t165 = t150 * t143;
    const float t166 = t164 - t165;
    const float t167 = t99 * t153;
    const float t168 = t87 + t167;
    const float t169 = t99 * t161;
    const float t170 = t91 + t169;
    const float t171 = t99 * t166;
    const float t172 = t95 + t171;
    const float t173 = t102 + t170;
    const float t174 = t170 / t173;
    const float t175 = t101 * t174;
    const float t176 = fmaxf(t172, t109);
    const float t177 = t108 / t176;
    const float t178 = libm_expf(t177);
    const float t179 = t106 * t178;
    const float t180 = t175 * t168;
    const float t181 = t179 * t168;
    const float t182 = t180 - t181;
    const float t183 = t117 * t175;
    const float t184 = t183 * t168;
    const float t185 = -t184;
    const float t186 = t121 * t168;
    const float t187 = t170 + t123;
    const float t188 = t170 / t187;
    const float t189 = t186 * t188;
    const float t190 = t185 - t189;
    const float t191 = t128 * t175;
    const float t192 = t191 * t133;
    const float t193 = t192 * t168;
    const float t194 = t179 * t172;
    const float t195 = t193 - t194;
    const float t196 = t96 * t182;
    const float t197 = t87 + t196;
    const float t198 = t96 * t190;
    const float t199 = t91 + t198;
    const float t200 = t96 * t195;
    const float t201 = t95 + t200;
    const float t202 = t102 + t199;
    const float t203 = t199 / t202;
    const float t204 = t101 * t203;
    const float t205 = fmaxf(t201, t109);
    const float t206 = t108 / t205;
    const float t207 = libm_expf(t206);
    const float t208 = t106 * t207;
    const float t209 = t204 * t197;
    const float t210 = t208 * t197;
    const float t211 = t209 - t210;
    const float t212 = t117 * t204;
    const float t213 = t212 * t197;
    const float t214 = -t213;
    const float t215 = t121 * t197;
    const float t216 = t199 + t123;
    const float t217 = t199 / t216;
    const float t218 = t215 * t217;
    const float t219 = t214 - t218;
    const float t220 = t128 * t204;
    const float t221 = t220 * t133;
    const float t222 = t221 * t197;
    const float t223 = t208 * t201;
    const float t224 = t222 - t223;
    const float t225 = t153 + t182;
    const float t226 = t97 * t225;
    const float t227 = t116 + t226;
    const float t228 = t227 + t211;
    const float t229 = t100 * t228;
    const float t230 = t87 + t229;
    const float t231 = t161 + t190;
    const float t232 = t97 * t231;
    const float t233 = t127 + t232;
    const float t234 = t233 + t219;
    const float t235 = t100 * t234;
    const float t236 = t91 + t235;
    const float t237 = t166 + t195;
    const float t238 = t97 * t237;
    const float t239 = t137 + t238;
    const float t240 = t239 + t224;
    const float t241 = t100 * t240;
    const float t242 = t95 + t241;
    const float t243 = 0.005f;
    const float t244 = t230 - t85;
    const float t245 = select_float(!(t244 >= t243), t243, t244);
    const float t246 = libm_logf(t245);
    const float t247 = 0.025f;
    const float t248 = t236 - t89;
    const float t249 = select_float(!(t248 >= t247), t247, t248);
    const float t250 = libm_logf(t249);
    const float t251 = 0.0015f;
    const float t252 = t242 - t93;
    const float t253 = select_float(!(t252 >= t251), t251, t252);
    const float t254 = libm_logf(t253);
    const float t255 = libm_expf(t58);
    const float t256 = t255 + t85;
    const float t257 = select_float(!(t256 >= t9), t9, t256);
    const float t258 = libm_expf(t59);
    const float t259 = t258 + t89;
    const float t260 = select_float(!(t259 >= t9), t9, t259);
    const float t261 = libm_expf(t60);
    const float t262 = t261 + t93;
    const float t263 = select_float(!(t262 >= t9), t9, t262);
    const float t264 = t102 + t260;
    const float t265 = t260 / t264;
    const float t266 = t101 * t265;
    const float t267 = fmaxf(t263, t109);
    const float t268 = t108 / t267;
    const float t269 = libm_expf(t268);
    const float t270 = t106 * t269;
    const float t271 = t266 * t257;
    const float t272 = t270 * t257;
    const float t273 = t271 - t272;
    const float t274 = t117 * t266;
    const float t275 = t274 * t257;
    const float t276 = -t275;
    const float t277 = t121 * t257;
    const float t278 = t260 + t123;
    const float t279 = t260 / t278;
    const float t280 = t277 * t279;
    const float t281 = t276 - t280;
    const float t282 = t128 * t266;
    const float t283 = t282 * t133;
    const float t284 = t283 * t257;
    const float t285 = t270 * t263;
    const float t286 = t284 - t285;
    const float t287 = t99 * t273;
    const float t288 = t257 + t287;
    const float t289 = t99 * t281;
    const float t290 = t260 + t289;
    const float t291 = t99 * t286;
    const float t292 = t263 + t291;
    const float t293 = t102 + t290;
    const float t294 = t290 / t293;
    const float t295 = t101 * t294;
    const float t296 = fmaxf(t292, t109);
    const float t297 = t108 / t296;
    const float t298 = libm_expf(t297);
    const float t299 = t106 * t298;
    const float t300 = t295 * t288;
    const float t301 = t299 * t288;
    const float t302 = t300 - t301;
    const float t303 = t117 * t295;
    const float t304 = t303 * t288;
    const float t305 = -t304;
    const float t306 = t121 * t288;
    const float t307 = t290 + t123;
    const float t308 = t290 / t307;
    const float t309 = t306 * t308;
    const float t310 = t305 - t309;
    const float t311 = t128 * t295;
    const float t312 = t311 * t133;
    const float t313 = t312 * t288;
    const float t314 = t299 * t292;
    const float t315 = t313 - t314;
    const float t316 = t99 * t302;
    const float t317 = t257 + t316;
    const float t318 = t99 * t310;
    const float t319 = t260 + t318;
    const float t320 = t99 * t315;
    const float t321 = t263 + t320;
    const float t322 = t102 + t319;
    const float t323 = t319 / t322;
    const float t324 = t101 * t323;
    const float t325 = fmaxf(t321, t109);
    const float t326 = t108 / t325;
    const float t327 = libm_expf(t326);
    const float t328 = t106 * t327;
    const float t329 = t324 * t317;
    const float t330 = t328 * t317;
    const float t331 = t329 - t330;
    const float t332 = t117 * t324;
    const float t333 = t332 * t317;
    const float t334 = -t333;
    const float t335 = t121 * t317;
    const float t336 = t319 + t123;
    const float t337 = t319 / t336;
    const float t338 = t335 * t337;
    const float t339 = t334 - t338;
    const float t340 = t128 * t324;
    const float t341 = t340 * t133;
    const float t342 = t341 * t317;
    const float t343 = t328 * t321;
    const float t344 = t342 - t343;
    const float t345 = t96 * t331;
    const float t346 = t257 + t345;
    const float t347 = t96 * t339;
    const float t348 = t260 + t347;
    const float t349 = t96 * t344;
    const float t350 = t263 + t349;
    const float t351 = t102 + t348;
    const float t352 = t348 / t351;
    const float t353 = t101 * t352;
    const float t354 = fmaxf(t350, t109);
    const float t355 = t108 / t354;
    const float t356 = libm_expf(t355);
    const float t357 = t106 * t356;
    const float t358 = t353 * t346;
    const float t359 = t357 * t346;
    const float t360 = t358 - t359;
    const float t361 = t117 * t353;
    const float t362 = t361 * t346;
    const float t363 = -t362;
    const float t364 = t121 * t346;
    const float t365 = t348 + t123;
    const float t366 = t348 / t365;
    const float t367 = t364 * t366;
    const float t368 = t363 - t367;
    const float t369 = t128 * t353;
    const float t370 = t369 * t133;
    const float t371 = t370 * t346;
    const float t372 = t357 * t350;
    const float t373 = t371 - t372;
    const float t374 = t302 + t331;
    const float t375 = t97 * t374;
    const float t376 = t273 + t375;
    const float t377 = t376 + t360;
    const float t378 = t100 * t377;
    const float t379 = t257 + t378;
    const float t380 = t310 + t339;
    const float t381 = t97 * t380;
    const float t382 = t281 + t381;
    const float t383 = t382 + t368;
    const float t384 = t100 * t383;
    const float t385 = t260 + t384;
    const float t386 = t315 + t344;
    const float t387 = t97 * t386;
    const float t388 = t286 + t387;
    const float t389 = t388 + t373;
    const float t390 = t100 * t389;
    const float t391 = t263 + t390;
    const float t392 = t379 - t85;
    const float t393 = select_float(!(t392 >= t243), t243, t392);
    const float t394 = libm_logf(t393);
    const float t395 = t385 - t89;
    const float t396 = select_float(!(t395 >= t247), t247, t395);
    const float t397 = libm_logf(t396);
    const float t398 = t391 - t93;
    const float t399 = select_float(!(t398 >= t251), t251, t398);
    const float t400 = libm_logf(t399);
    const float t401 = libm_expf(t63);
    const float t402 = t401 + t89;
    const float t403 = select_float(!(t402 >= t9), t9, t402);
    const float t404 = libm_expf(t64);
    const float t405 = t404 + t93;
    const float t406 = select_float(!(t405 >= t9), t9, t405);
    const float t407 = t102 + t403;
    const float t408 = t403 / t407;
    const float t409 = t101 * t408;
    const float t410 = fmaxf(t406, t109);
    const float t411 = t108 / t410;
    const float t412 = libm_expf(t411);
    const float t413 = t106 * t412;
    const float t414 = t409 * t257;
    const float t415 = t413 * t257;
    const float t416 = t414 - t415;
    const float t417 = t117 * t409;
    const float t418 = t417 * t257;
    const float t419 = -t418;
    const float t420 = t403 + t123;
    const float t421 = t403 / t420;
    const float t422 = t277 * t421;
    const float t423 = t419 - t422;
    const float t424 = t128 * t409;
    const float t425 = t424 * t133;
    const float t426 = t425 * t257;
    const float t427 = t413 * t406;
    const float t428 = t426 - t427;
    const float t429 = t99 * t416;
    const float t430 = t257 + t429;
    const float t431 = t99 * t423;
    const float t432 = t403 + t431;
    const float t433 = t99 * t428;
    const float t434 = t406 + t433;
    const float t435 = t102 + t432;
    const float t436 = t432 / t435;
    const float t437 = t101 * t436;
    const float t438 = fmaxf(t434, t109);
    const float t439 = t108 / t438;
    const float t440 = libm_expf(t439);
    const float t441 = t106 * t440;
    const float t442 = t437 * t430;
    const float t443 = t441 * t430;
    const float t444 = t442 - t443;
    const float t445 = t117 * t437;
    const float t446 = t445 * t430;
    const float t447 = -t446;
    const float t448 = t121 * t430;
    const float t449 = t432 + t123;
    const float t450 = t432 / t449;
    const float t451 = t448 * t450;
    const float t452 = t447 - t451;
    const float t453 = t128 * t437;
    const float t454 = t453 * t133;
    const float t455 = t454 * t430;
    const float t456 = t441 * t434;
    const float t457 = t455 - t456;
    const float t458 = t99 * t444;
    const float t459 = t257 + t458;
    const float t460 = t99 * t452;
    const float t461 = t403 + t460;
    const float t462 = t99 * t457;
    const float t463 = t406 + t462;
    const float t464 = t102 + t461;
    const float t465 = t461 / t464;
    const float t466 = t101 * t465;
    const float t467 = fmaxf(t463, t109);
    const float t468 = t108 / t467;
    const float t469 = libm_expf(t468);
    const float t470 = t106 * t469;
    const float t471 = t466 * t459;
    const float t472 = t470 * t459;
    const float t473 = t471 - t472;
    const float t474 = t117 * t466;
    const float t475 = t474 * t459;
    const float t476 = -t475;
    const float t477 = t121 * t459;
    const float t478 = t461 + t123;
    const float t479 = t461 / t478;
    const float t480 = t477 * t479;
    const float t481 = t476 - t480;
    const float t482 = t128 * t466;
    const float t483 = t482 * t133;
    const float t484 = t483 * t459;
    const float t485 = t470 * t463;
    const float t486 = t484 - t485;
    const float t487 = t96 * t473;
    const float t488 = t257 + t487;
    const float t489 = t96 * t481;
    const float t490 = t403 + t489;
    const float t491 = t96 * t486;
    const float t492 = t406 + t491;
    const float t493 = t102 + t490;
    const float t494 = t490 / t493;
    const float t495 = t101 * t494;
    const float t496 = fmaxf(t492, t109);
    const float t497 = t108 / t496;
    const float t498 = libm_expf(t497);
    const float t499 = t106 * t498;
    const float t500 = t495 * t488;
    const float t501 = t499 * t488;
    const float t502 = t500 - t501;
    const float t503 = t117 * t495;
    const float t504 = t503 * t488;
    const float t505 = -t504;
    const float t506 = t121 * t488;
    const float t507 = t490 + t123;
    const float t508 = t490 / t507;
    const float t509 = t506 * t508;
    const float t510 = t505 - t509;
    const float t511 = t128 * t495;
    const float t512 = t511 * t133;
    const float t513 = t512 * t488;
    const float t514 = t499 * t492;
    const float t515 = t513 - t514;
    const float t516 = t444 + t473;
    const float t517 = t97 * t516;
    const float t518 = t416 + t517;
    const float t519 = t518 + t502;
    const float t520 = t100 * t519;
    const float t521 = t257 + t520;
    const float t522 = t452 + t481;
    const float t523 = t97 * t522;
    const float t524 = t423 + t523;
    const float t525 = t524 + t510;
    const float t526 = t100 * t525;
    const float t527 = t403 + t526;
    const float t528 = t457 + t486;
    const float t529 = t97 * t528;
    const float t530 = t428 + t529;
    const float t531 = t530 + t515;
    const float t532 = t100 * t531;
    const float t533 = t406 + t532;
    const float t534 = t521 - t85;
    const float t535 = select_float(!(t534 >= t243), t243, t534);
    const float t536 = libm_logf(t535);
    const float t537 = t527 - t89;
    const float t538 = select_float(!(t537 >= t247), t247, t537);
    const float t539 = libm_logf(t538);
    const float t540 = t533 - t93;
    const float t541 = select_float(!(t540 >= t251), t251, t540);
    const float t542 = libm_logf(t541);
    const float t543 = libm_expf(t72);
    const float t544 = t543 + t85;
    const float t545 = select_float(!(t544 >= t9), t9, t544);
    const float t546 = libm_expf(t73);
    const float t547 = t546 + t89;
    const float t548 = select_float(!(t547 >= t9), t9, t547);
    const float t549 = libm_expf(t74);
    const float t550 = t549 + t93;
    const float t551 = select_float(!(t550 >= t9), t9, t550);
    const float t552 = t102 + t548;
    const float t553 = t548 / t552;
    const float t554 = t101 * t553;
    const float t555 = fmaxf(t551, t109);
    const float t556 = t108 / t555;
    const float t557 = libm_expf(t556);
    const float t558 = t106 * t557;
    const float t559 = t554 * t545;
    const float t560 = t558 * t545;
    const float t561 = t559 - t560;
    const float t562 = t117 * t554;
    const float t563 = t562 * t545;
    const float t564 = -t563;
    const float t565 = t121 * t545;
    const float t566 = t548 + t123;
    const float t567 = t548 / t566;
    const float t568 = t565 * t567;
    const float t569 = t564 - t568;
    const float t570 = t128 * t554;
    const float t571 = t570 * t133;
    const float t572 = t571 * t545;
    const float t573 = t558 * t551;
    const float t574 = t572 - t573;
    const float t575 = t99 * t561;
    const float t576 = t545 + t575;
    const float t577 = t99 * t569;
    const float t578 = t548 + t577;
    const float t579 = t99 * t574;
    const float t580 = t551 + t579;
    const float t581 = t102 + t578;
    const float t582 = t578 / t581;
    const float t583 = t101 * t582;
    const float t584 = fmaxf(t580, t109);
    const float t585 = t108 / t584;
    const float t586 = libm_expf(t585);
    const float t587 = t106 * t586;
    const float t588 = t583 * t576;
    const float t589 = t587 * t576;
    const float t590 = t588 - t589;
    const float t591 = t117 * t583;
    const float t592 = t591 * t576;
    const float t593 = -t592;
    const float t594 = t121 * t576;
    const float t595 = t578 + t123;
    const float t596 = t578 / t595;
    const float t597 = t594 * t596;
    const float t598 = t593 - t597;
    const float t599 = t128 * t583;
    const float t600 = t599 * t133;
    const float t601 = t600 * t576;
    const float t602 = t587 * t580;
    const float t603 = t601 - t602;
    const float t604 = t99 * t590;
    const float t605 = t545 + t604;
    const float t606 = t99 * t598;
    const float t607 = t548 + t606;
    const float t608 = t99 * t603;
    const float t609 = t551 + t608;
    const float t610 = t102 + t607;
    const float t611 = t607 / t610;
    const float t612 = t101 * t611;
    const float t613 = fmaxf(t609, t109);
    const float t614 = t108 / t613;
    const float t615 = libm_expf(t614);
    const float t616 = t106 * t615;
    const float t617 = t612 * t605;
    const float t618 = t616 * t605;
    const float t619 = t617 - t618;
    const float t620 = t117 * t612;
    const float t621 = t620 * t605;
    const float t622 = -t621;
    const float t623 = t121 * t605;
    const float t624 = t607 + t123;
    const float t625 = t607 / t624;
    const float t626 = t623 * t625;
    const float t627 = t622 - t626;
    const float t628 = t128 * t612;
    const float t629 = t628 * t133;
    const float t630 = t629 * t605;
    const float t631 = t616 * t609;
    const float t632 = t630 - t631;
    const float t633 = t96 * t619;
    const float t634 = t545 + t633;
    const float t635 = t96 * t627;
    const float t636 = t548 + t635;
    const float t637 = t96 * t632;
    const float t638 = t551 + t637;
    const float t639 = t102 + t636;
    const float t640 = t636 / t639;
    const float t641 = t101 * t640;
    const float t642 = fmaxf(t638, t109);
    const float t643 = t108 / t642;
    const float t644 = libm_expf(t643);
    const float t645 = t106 * t644;
    const float t646 = t641 * t634;
    const float t647 = t645 * t634;
    const float t648 = t646 - t647;
    const float t649 = t117 * t641;
    const float t650 = t649 * t634;
    const float t651 = -t650;
    const float t652 = t121 * t634;
    const float t653 = t636 + t123;
    const float t654 = t636 / t653;
    const float t655 = t652 * t654;
    const float t656 = t651 - t655;
    const float t657 = t128 * t641;
    const float t658 = t657 * t133;
    const float t659 = t658 * t634;
    const float t660 = t645 * t638;
    const float t661 = t659 - t660;
    const float t662 = t590 + t619;
    const float t663 = t97 * t662;
    const float t664 = t561 + t663;
    const float t665 = t664 + t648;
    const float t666 = t100 * t665;
    const float t667 = t545 + t666;
    const float t668 = t598 + t627;
    const float t669 = t97 * t668;
    const float t670 = t569 + t669;
    const float t671 = t670 + t656;
    const float t672 = t100 * t671;
    const float t673 = t548 + t672;
    const float t674 = t603 + t632;
    const float t675 = t97 * t674;
    const float t676 = t574 + t675;
    const float t677 = t676 + t661;
    const float t678 = t100 * t677;
    const float t679 = t551 + t678;
    const float t680 = t667 - t85;
    const float t681 = select_float(!(t680 >= t243), t243, t680);
    const float t682 = libm_logf(t681);
    const float t683 = t673 - t89;
    const float t684 = select_float(!(t683 >= t247), t247, t683);
    const float t685 = libm_logf(t684);
    const float t686 = t679 - t93;
    const float t687 = select_float(!(t686 >= t251), t251, t686);
    const float t688 = libm_logf(t687);
    const float t689 = libm_expf(t79);
    const float t690 = t689 + t89;
    const float t691 = select_float(!(t690 >= t9), t9, t690);
    const float t692 = libm_expf(t80);
    const float t693 = t692 + t93;
    const float t694 = select_float(!(t693 >= t9), t9, t693);
    const float t695 = t102 + t691;
    const float t696 = t691 / t695;
    const float t697 = t101 * t696;
    const float t698 = fmaxf(t694, t109);
    const float t699 = t108 / t698;
    const float t700 = libm_expf(t699);
    const float t701 = t106 * t700;
    const float t702 = t697 * t257;
    const float t703 = t701 * t257;
    const float t704 = t702 - t703;
    const float t705 = t117 * t697;
    const float t706 = t705 * t257;
    const float t707 = -t706;
    const float t708 = t691 + t123;
    const float t709 = t691 / t708;
    const float t710 = t277 * t709;
    const float t711 = t707 - t710;
    const float t712 = t128 * t697;
    const float t713 = t712 * t133;
    const float t714 = t713 * t257;
    const float t715 = t701 * t694;
    const float t716 = t714 - t715;
    const float t717 = t99 * t704;
    const float t718 = t257 + t717;
    const float t719 = t99 * t711;
    const float t720 = t691 + t719;
    const float t721 = t99 * t716;
    const float t722 = t694 + t721;
    const float t723 = t102 + t720;
    const float t724 = t720 / t723;
    const float t725 = t101 * t724;
    const float t726 = fmaxf(t722, t109);
    const float t727 = t108 / t726;
    const float t728 = libm_expf(t727);
    const float t729 = t106 * t728;
    const float t730 = t725 * t718;
    const float t731 = t729 * t718;
    const float t732 = t730 - t731;
    const float t733 = t117 * t725;
    const float t734 = t733 * t718;
    const float t735 = -t734;
    const float t736 = t121 * t718;
    const float t737 = t720 + t123;
    const float t738 = t720 / t737;
    const float t739 = t736 * t738;
    const float t740 = t735 - t739;
    const float t741 = t128 * t725;
    const float t742 = t741 * t133;
    const float t743 = t742 * t718;
    const float t744 = t729 * t722;
    const float t745 = t743 - t744;
    const float t746 = t99 * t732;
    const float t747 = t257 + t746;
    const float t748 = t99 * t740;
    const float t749 = t691 + t748;
    const float t750 = t99 * t745;
    const float t751 = t694 + t750;
    const float t752 = t102 + t749;
    const float t753 = t749 / t752;
    const float t754 = t101 * t753;
    const float t755 = fmaxf(t751, t109);
    const float t756 = t108 / t755;
    const float t757 = libm_expf(t756);
    const float t758 = t106 * t757;
    const float t759 = t754 * t747;
    const float t760 = t758 * t747;
    const float t761 = t759 - t760;
    const float t762 = t117 * t754;
    const float t763 = t762 * t747;
    const float t764 = -t763;
    const float t765 = t121 * t747;
    const float t766 = t749 + t123;
    const float t767 = t749 / t766;
    const float t768 = t765 * t767;
    const float t769 = t764 - t768;
    const float t770 = t128 * t754;
    const float t771 = t770 * t133;
    const float t772 = t771 * t747;
    const float t773 = t758 * t751;
    const float t774 = t772 - t773;
    const float t775 = t96 * t761;
    const float t776 = t257 + t775;
    const float t777 = t96 * t769;
    const float t778 = t691 + t777;
    const float t779 = t96 * t774;
    const float t780 = t694 + t779;
    const float t781 = t102 + t778;
    const float t782 = t778 / t781;
    const float t783 = t101 * t782;
    const float t784 = fmaxf(t780, t109);
    const float t785 = t108 / t784;
    const float t786 = libm_expf(t785);
    const float t787 = t106 * t786;
    const float t788 = t783 * t776;
    const float t789 = t787 * t776;
    const float t790 = t788 - t789;
    const float t791 = t117 * t783;
    const float t792 = t791 * t776;
    const float t793 = -t792;
    const float t794 = t121 * t776;
    const float t795 = t778 + t123;
    const float t796 = t778 / t795;
    const float t797 = t794 * t796;
    const float t798 = t793 - t797;
    const float t799 = t128 * t783;
    const float t800 = t799 * t133;
    const float t801 = t800 * t776;
    const float t802 = t787 * t780;
    const float t803 = t801 - t802;
    const float t804 = t732 + t761;
    const float t805 = t97 * t804;
    const float t806 = t704 + t805;
    const float t807 = t806 + t790;
    const float t808 = t100 * t807;
    const float t809 = t257 + t808;
    const float t810 = t740 + t769;
    const float t811 = t97 * t810;
    const float t812 = t711 + t811;
    const float t813 = t812 + t798;
    const float t814 = t100 * t813;
    const float t815 = t691 + t814;
    const float t816 = t745 + t774;
    const float t817 = t97 * t816;
    const float t818 = t716 + t817;
    const float t819 = t818 + t803;
    const float t820 = t100 * t819;
    const float t821 = t694 + t820;
    const float t822 = t809 - t85;
    const float t823 = select_float(!(t822 >= t243), t243, t822);
    const float t824 = libm_logf(t823);
    const float t825 = t815 - t89;
    const float t826 = select_float(!(t825 >= t247), t247, t825);
    const float t827 = libm_logf(t826);
    const float t828 = t821 - t93;
    const float t829 = select_float(!(t828 >= t251), t251, t828);
    const float t830 = libm_logf(t829);
    const float t831 = libm_expf(t83);
    const float t832 = t831 + t93;
    const float t833 = select_float(!(t832 >= t9), t9, t832);
    const float t834 = fmaxf(t833, t109);
    const float t835 = t108 / t834;
    const float t836 = libm_expf(t835);
    const float t837 = t106 * t836;
    const float t838 = t837 * t257;
    const float t839 = t414 - t838;
    const float t840 = t837 * t833;
    const float t841 = t426 - t840;
    const float t842 = t99 * t839;
    const float t843 = t257 + t842;
    const float t844 = t99 * t841;
    const float t845 = t833 + t844;
    const float t846 = fmaxf(t845, t109);
    const float t847 = t108 / t846;
    const float t848 = libm_expf(t847);
    const float t849 = t106 * t848;
    const float t850 = t437 * t843;
    const float t851 = t849 * t843;
    const float t852 = t850 - t851;
    const float t853 = t445 * t843;
    const float t854 = -t853;
    const float t855 = t121 * t843;
    const float t856 = t855 * t450;
    const float t857 = t854 - t856;
    const float t858 = t454 * t843;
    const float t859 = t849 * t845;
    const float t860 = t858 - t859;
    const float t861 = t99 * t852;
    const float t862 = t257 + t861;
    const float t863 = t99 * t857;
    const float t864 = t403 + t863;
    const float t865 = t99 * t860;
    const float t866 = t833 + t865;
    const float t867 = t102 + t864;
    const float t868 = t864 / t867;
    const float t869 = t101 * t868;
    const float t870 = fmaxf(t866, t109);
    const float t871 = t108 / t870;
    const float t872 = libm_expf(t871);
    const float t873 = t106 * t872;
    const float t874 = t869 * t862;
    const float t875 = t873 * t862;
    const float t876 = t874 - t875;
    const float t877 = t117 * t869;
    const float t878 = t877 * t862;
    const float t879 = -t878;
    const float t880 = t121 * t862;
    const float t881 = t864 + t123;
    const float t882 = t864 / t881;
    const float t883 = t880 * t882;
    const float t884 = t879 - t883;
    const float t885 = t128 * t869;
    const float t886 = t885 * t133;
    const float t887 = t886 * t862;
    const float t888 = t873 * t866;
    const float t889 = t887 - t888;
    const float t890 = t96 * t876;
    const float t891 = t257 + t890;
    const float t892 = t96 * t884;
    const float t893 = t403 + t892;
    const float t894 = t96 * t889;
    const float t895 = t833 + t894;
    const float t896 = t102 + t893;
    const float t897 = t893 / t896;
    const float t898 = t101 * t897;
    const float t899 = fmaxf(t895, t109);
    const float t900 = t108 / t899;
    const float t901 = libm_expf(t900);
    const float t902 = t106 * t901;
    const float t903 = t898 * t891;
    const float t904 = t902 * t891;
    const float t905 = t903 - t904;
    const float t906 = t117 * t898;
    const float t907 = t906 * t891;
    const float t908 = -t907;
    const float t909 = t121 * t891;
    const float t910 = t893 + t123;
    const float t911 = t893 / t910;
    const float t912 = t909 * t911;
    const float t913 = t908 - t912;
    const float t914 = t128 * t898;
    const float t915 = t914 * t133;
    const float t916 = t915 * t891;
    const float t917 = t902 * t895;
    const float t918 = t916 - t917;
    const float t919 = t852 + t876;
    const float t920 = t97 * t919;
    const float t921 = t839 + t920;
    const float t922 = t921 + t905;
    const float t923 = t100 * t922;
    const float t924 = t257 + t923;
    const float t925 = t857 + t884;
    const float t926 = t97 * t925;
    const float t927 = t423 + t926;
    const float t928 = t927 + t913;
    const float t929 = t100 * t928;
    const float t930 = t403 + t929;
    const float t931 = t860 + t889;
    const float t932 = t97 * t931;
    const float t933 = t841 + t932;
    const float t934 = t933 + t918;
    const float t935 = t100 * t934;
    const float t936 = t833 + t935;
    const float t937 = t924 - t85;
    const float t938 = select_float(!(t937 >= t243), t243, t937);
    const float t939 = libm_logf(t938);
    const float t940 = t930 - t89;
    const float t941 = select_float(!(t940 >= t247), t247, t940);
    const float t942 = libm_logf(t941);
    const float t943 = t936 - t93;
    const float t944 = select_float(!(t943 >= t251), t251, t943);
    const float t945 = libm_logf(t944);
    const float t946 = 0.16666667f;
    const float t947 = t246 + t394;
    const float t948 = t947 + t536;
    const float t949 = t948 + t682;
    const float t950 = t949 + t824;
    const float t951 = t950 + t939;
    const float t952 = t946 * t951;
    const float t953 = t250 + t397;
    const float t954 = t953 + t539;
    const float t955 = t954 + t685;
    const float t956 = t955 + t827;
    const float t957 = t956 + t942;
    const float t958 = t946 * t957;
    const float t959 = t254 + t400;
    const float t960 = t959 + t542;
    const float t961 = t960 + t688;
    const float t962 = t961 + t830;
    const float t963 = t962 + t945;
    const float t964 = t946 * t963;
    const float t965 = t246 - t952;
    const float t966 = t250 - t958;
    const float t967 = t254 - t964;
    const float t968 = t394 - t952;
    const float t969 = t397 - t958;
    const float t970 = t400 - t964;
    const float t971 = t536 - t952;
    const float t972 = t539 - t958;
    const float t973 = t542 - t964;
    const float t974 = t682 - t952;
    const float t975 = t685 - t958;
    const float t976 = t688 - t964;
    const float t977 = t824 - t952;
    const float t978 = t827 - t958;
    const float t979 = t830 - t964;
    const float t980 = t939 - t952;
    const float t981 = t942 - t958;
    const float t982 = t945 - t964;
    const float t983 = t965 * t965;
    const float t984 = t968 * t968;
    const float t985 = t983 + t984;
    const float t986 = t971 * t971;
    const float t987 = t985 + t986;
    const float t988 = t974 * t974;
    const float t989 = t987 + t988;
    const float t990 = t977 * t977;
    const float t991 = t989 + t990;
    const float t992 = t980 * t980;
    const float t993 = t991 + t992;
    const float t994 = t946 * t993;
    const float t995 = t965 * t966;
    const float t996 = t968 * t969;
    const float t997 = t995 + t996;
    const float t998 = t971 * t972;
    const float t999 = t997 + t998;
    const float t1000 = t974 * t975;
    const float t1001 = t999 + t1000;
    const float t1002 = t977 * t978;
    const float t1003 = t1001 + t1002;
    const float t1004 = t980 * t981;
    const float t1005 = t1003 + t1004;
    const float t1006 = t946 * t1005;
    const float t1007 = t965 * t967;
    const float t1008 = t968 * t970;
    const float t1009 = t1007 + t1008;
    const float t1010 = t971 * t973;
    const float t1011 = t1009 + t1010;
    const float t1012 = t974 * t976;
    const float t1013 = t1011 + t1012;
    const float t1014 = t977 * t979;
    const float t1015 = t1013 + t1014;
    const float t1016 = t980 * t982;
    const float t1017 = t1015 + t1016;
    const float t1018 = t946 * t1017;
    const float t1019 = t966 * t966;
    const float t1020 = t969 * t969;
    const float t1021 = t1019 + t1020;
    const float t1022 = t972 * t972;
    const float t1023 = t1021 + t1022;
    const float t1024 = t975 * t975;
    const float t1025 = t1023 + t1024;
    const float t1026 = t978 * t978;
    const float t1027 = t1025 + t1026;
    const float t1028 = t981 * t981;
    const float t1029 = t1027 + t1028;
    const float t1030 = t946 * t1029;
    const float t1031 = t966 * t967;
    const float t1032 = t969 * t970;
    const float t1033 = t1031 + t1032;
    const float t1034 = t972 * t973;
    const float t1035 = t1033 + t1034;
    const float t1036 = t975 * t976;
    const float t1037 = t1035 + t1036;
    const float t1038 = t978 * t979;
    const float t1039 = t1037 + t1038;
    const float t1040 = t981 * t982;
    const float t1041 = t1039 + t1040;
    const float t1042 = t946 * t1041;
    const float t1043 = t967 * t967;
    const float t1044 = t970 * t970;
    const float t1045 = t1043 + t1044;
    const float t1046 = t973 * t973;
    const float t1047 = t1045 + t1046;
    const float t1048 = t976 * t976;
    const float t1049 = t1047 + t1048;
    const float t1050 = t979 * t979;
    const float t1051 = t1049 + t1050;
    const float t1052 = t982 * t982;
    const float t1053 = t1051 + t1052;
    const float t1054 = t946 * t1053;
    const float t1055 = 6.4324554e-6f;
    const float t1056 = t994 + t1055;
    const float t1057 = 4.555184e-6f;
    const float t1058 = t1030 + t1057;
    const float t1059 = 7.5633906e-8f;
    const float t1060 = t1054 + t1059;
    const float t1061 = select_float(!(t952 >= t48), t48, t952);
    const float t1062 = select_float(!(t958 >= t50), t50, t958);
    const float t1063 = select_float(!(t964 >= t52), t52, t964);
    out[0] = t1061;
    out[1] = t1062;
    out[2] = t1063;
    out[3] = t1056;
    out[4] = t1006;
    out[5] = t1018;
    out[6] = t1058;
    out[7] = t1042;
    out[8] = t1060;
}

/* The targets at the UKF state x (in its log coordinates) and input u. */
static void ukf_targets(const float *x, const float *u, float *out) {
    (void)u;
    const float t0 = x[0];
    const float t1 = x[1];
    const float t2 = x[2];
    const float t3 = libm_expf(t0);
    const float t4 = libm_expf(t1);
    const float t5 = libm_expf(t2);
    const float t6 = -0.005f;
    const float t7 = 0.0f;
    const float t8 = t3 + t6;
    const float t9 = select_float(!(t8 >= t7), t7, t8);
    const float t10 = -0.025f;
    const float t11 = t4 + t10;
    const float t12 = select_float(!(t11 >= t7), t7, t11);
    const float t13 = -0.0015f;
    const float t14 = t5 + t13;
    const float t15 = select_float(!(t14 >= t7), t7, t14);
    const float t16 = 0.2f /* mu_m */;
    const float t17 = 0.1f /* k_s */;
    const float t18 = t17 + t12;
    const float t19 = t12 / t18;
    const float t20 = t16 * t19;
    const float t21 = t20 * t9;
    out[0] = t15;
    out[1] = t21;
}

/* The UKF's start: the centre of the state box and P(0)'s upper triangle. */
static const float UKF_X0[ECOLI_X0_0P5_STATES] = {
    -0.68319684f, 0.92624104f, -1.8871696f
};
static const float UKF_P0[ECOLI_X0_0P5_COVARIANCE] = {
    0.013220721f, 0.0f, 0.0f, 0.9173836f,
    0.0f, 1.1573175f
};

/* The UKF's prediction alone (a lost output), taken when finite. */
static void ukf_predict(float *x, float *p, const float *u) {
    float out[ECOLI_X0_0P5_STATES + ECOLI_X0_0P5_COVARIANCE];
    ukf_unmeasured(x, p, u, out);
    if (all_finite(out, ECOLI_X0_0P5_STATES + ECOLI_X0_0P5_COVARIANCE)) {
        memcpy(x, out, ECOLI_X0_0P5_STATES * sizeof *x);
        memcpy(p, out + ECOLI_X0_0P5_STATES, ECOLI_X0_0P5_COVARIANCE * sizeof *p);
    }
}

/* The UKF's sample with its measurement, taken when finite (1, the estimate x(k|k) in
 * `estimate`, its normalised innovation squared in `*nis`). */
static int ukf_measure(float *x, float *p, const float *y, const float *u, float *estimate, float *nis) {
    float out[2u * ECOLI_X0_0P5_STATES + ECOLI_X0_0P5_COVARIANCE + 1u];
    ukf_measured(x, p, y, u, out);
    if (!all_finite(out + ECOLI_X0_0P5_STATES, ECOLI_X0_0P5_STATES + ECOLI_X0_0P5_COVARIANCE)) {
        return 0;
    }
    *nis = out[2u * ECOLI_X0_0P5_STATES + ECOLI_X0_0P5_COVARIANCE];
    memcpy(estimate, out, ECOLI_X0_0P5_STATES * sizeof *x);
    memcpy(x, out + ECOLI_X0_0P5_STATES, ECOLI_X0_0P5_STATES * sizeof *x);
    memcpy(p, out + 2u * ECOLI_X0_0P5_STATES, ECOLI_X0_0P5_COVARIANCE * sizeof *p);
    return 1;
}


static void ukf_box_fresh(ecoli_x0_0p5_ukf_box *o) {
    memcpy(o->x, UKF_X0, sizeof o->x);
    memcpy(o->p, UKF_P0, sizeof o->p);
    o->chi = 2.0f;
}

static ecoli_x0_0p5_status ukf_box_sample(ecoli_x0_0p5_ukf_box *o, const float *y, const float *u) {
    float estimate[ECOLI_X0_0P5_STATES];
    float nis;
    unsigned i;
    if (!inputs_finite(u)) {
        return ECOLI_X0_0P5_REFUSED;
    }
    if (!accepts(y, u)) {
        ukf_predict(o->x, o->p, u);
        return ECOLI_X0_0P5_REFUSED;
    }
    if (!ukf_measure(o->x, o->p, y, u, estimate, &nis)) {
        ukf_box_fresh(o);
        return ECOLI_X0_0P5_RESTARTED;
    }
    /* The chi-squared watch (firmware::watch): the mean of the normalised innovations squared. */
    o->chi = o->chi + 0.33333334f * (nis - o->chi);
    if (!(o->chi <= 2048.0f)) {
        ukf_box_fresh(o);
        return ECOLI_X0_0P5_RESTARTED;
    }
    ukf_targets(estimate, u, o->values);
    for (i = 0u; i < ECOLI_X0_0P5_TARGETS; ++i) {
        o->flags[i] = ECOLI_X0_0P5_INSIDE;
    }
    o->ready = 1;
    return ECOLI_X0_0P5_OK;
}

void ecoli_x0_0p5_ukf_box_init(ecoli_x0_0p5_ukf_box *o) {
    ukf_box_fresh(o);
    o->ready = 0;
    o->refused = 0u;
    o->restarts = 0u;
}

ecoli_x0_0p5_status ecoli_x0_0p5_ukf_box_push(ecoli_x0_0p5_ukf_box *o, const float *y, const float *u) {
    const ecoli_x0_0p5_status status = ukf_box_sample(o, y, u);
    if (status == ECOLI_X0_0P5_REFUSED && o->refused != UINT32_MAX) {
        ++o->refused;
    } else if (status == ECOLI_X0_0P5_RESTARTED && o->restarts != UINT32_MAX) {
        ++o->restarts;
    }
    return status;
}

ecoli_x0_0p5_status ecoli_x0_0p5_ukf_box_estimate(const ecoli_x0_0p5_ukf_box *o, float *values, ecoli_x0_0p5_saturation *saturation) {
    if (!o->ready) {
        return ECOLI_X0_0P5_NO_ESTIMATE_YET;
    }
    memcpy(values, o->values, sizeof o->values);
    memcpy(saturation, o->flags, sizeof o->flags);
    return ECOLI_X0_0P5_OK;
}

/* The start-up schedule, j = 1 … 9: the blends g_j per state, then the gains K_j (states x
 * outputs, row by row). */
static const float CORRECTED_BLENDS[9][9] = {
{
    0.91009295f, 0.91009295f, 0.91009295f, 0.01579626f,
    0.007345757f, 0.02186814f, -0.004741332f, 0.0047839326f,
    0.00063607196f
},
{
    0.8350189f, 0.8350189f, 0.8350189f, 0.016995262f,
    0.0068494407f, 0.02044855f, -0.004209568f, 0.003932146f,
    0.0005854047f
},
{
    0.77138674f, 0.77138674f, 0.77138674f, 0.018011527f,
    0.006428767f, 0.019245319f, -0.0037588486f, 0.0032101793f,
    0.00054245954f
},
{
    0.716766f, 0.716766f, 0.716766f, 0.018883869f,
    0.0060676686f, 0.018212488f, -0.0033719593f, 0.0025904553f,
    0.00050559617f
},
{
    0.669369f, 0.669369f, 0.669369f, 0.019640842f,
    0.0057543255f, 0.01731625f, -0.003036237f, 0.0020526915f,
    0.0004736081f
},
{
    0.62785155f, 0.62785155f, 0.62785155f, 0.020303914f,
    0.005479853f, 0.01653119f, -0.0027421608f, 0.0015816368f,
    0.00044558808f
},
{
    0.59118354f, 0.59118354f, 0.59118354f, 0.020889536f,
    0.00523744f, 0.015837828f, -0.0024824343f, 0.0011656036f,
    0.00042084095f
},
{
    0.5585622f, 0.5585622f, 0.5585622f, 0.021410529f,
    0.00502178f, 0.015220986f, -0.0022513708f, 0.00079548365f,
    0.0003988249f
},
{
    0.52935266f, 0.52935266f, 0.52935266f, 0.021877032f,
    0.0048286747f, 0.014668657f, -0.002044474f, 0.00046407388f,
    0.00037911147f
}
};
static const float CORRECTED_NO_BLEND[9] = { 0.0f };
/* The clamp of each state: its map's learning range. */
static const float CORRECTED_LOWER[ECOLI_X0_0P5_STATES] = {
    0.4385543f, 0.0f, 0.0f
};
static const float CORRECTED_UPPER[ECOLI_X0_0P5_STATES] = {
    2.2555175f, 4.949024f, 0.4457929f
};

/* One sampling period of the model from x, the value alone: out = x+ (corrected_predict). */
static void corrected_predict(const float *x, const float *u, float *out) {
    (void)u;
    const float t0 = x[0];
    const float t1 = x[1];
    const float t2 = x[2];
    const float t3 = 0.2f;
    const float t4 = 2.0f;
    const float t5 = 6.0f;
    const float t6 = t3 / t4;
    const float t7 = t3 / t5;
    const float t8 = 0.2f /* mu_m */;
    const float t9 = 0.1f /* k_s */;
    const float t10 = t9 + t1;
    const float t11 = t1 / t10;
    const float t12 = t8 * t11;
    const float t13 = 0.1f /* k_d */;
    const float t14 = 0.5f /* k_p */;
    const float t15 = -t14;
    const float t16 = 0.001f;
    const float t17 = fmaxf(t2, t16);
    const float t18 = t15 / t17;
    const float t19 = libm_expf(t18);
    const float t20 = t13 * t19;
    const float t21 = t12 * t0;
    const float t22 = t20 * t0;
    const float t23 = t21 - t22;
    const float t24 = 1.0f /* y_s */;
    const float t25 = t24 * t12;
    const float t26 = t25 * t0;
    const float t27 = -t26;
    const float t28 = 0.05f /* k_m */;
    const float t29 = t28 * t0;
    const float t30 = 0.01f /* ks_m */;
    const float t31 = t1 + t30;
    const float t32 = t1 / t31;
    const float t33 = t29 * t32;
    const float t34 = t27 - t33;
    const float t35 = 0.2f /* y_p */;
    const float t36 = t35 * t12;
    const float t37 = 1.0f /* I */;
    const float t38 = 0.5f /* k_I */;
    const float t39 = t37 + t38;
    const float t40 = t37 / t39;
    const float t41 = t36 * t40;
    const float t42 = t41 * t0;
    const float t43 = t20 * t2;
    const float t44 = t42 - t43;
    const float t45 = t6 * t23;
    const float t46 = t0 + t45;
    const float t47 = t6 * t34;
    const float t48 = t1 + t47;
    const float t49 = t6 * t44;
    const float t50 = t2 + t49;
    const float t51 = t9 + t48;
    const float t52 = t48 / t51;
    const float t53 = t8 * t52;
    const float t54 = fmaxf(t50, t16);
    const float t55 = t15 / t54;
    const float t56 = libm_expf(t55);
    const float t57 = t13 * t56;
    const float t58 = t53 * t46;
    const float t59 = t57 * t46;
    const float t60 = t58 - t59;
    const float t61 = t24 * t53;
    const float t62 = t61 * t46;
    const float t63 = -t62;
    const float t64 = t28 * t46;
    const float t65 = t48 + t30;
    const float t66 = t48 / t65;
    const float t67 = t64 * t66;
    const float t68 = t63 - t67;
    const float t69 = t35 * t53;
    const float t70 = t69 * t40;
    const float t71 = t70 * t46;
    const float t72 = t57 * t50;
    const float t73 = t71 - t72;
    const float t74 = t6 * t60;
    const float t75 = t0 + t74;
    const float t76 = t6 * t68;
    const float t77 = t1 + t76;
    const float t78 = t6 * t73;
    const float t79 = t2 + t78;
    const float t80 = t9 + t77;
    const float t81 = t77 / t80;
    const float t82 = t8 * t81;
    const float t83 = fmaxf(t79, t16);
    const float t84 = t15 / t83;
    const float t85 = libm_expf(t84);
    const float t86 = t13 * t85;
    const float t87 = t82 * t75;
    const float t88 = t86 * t75;
    const float t89 = t87 - t88;
    const float t90 = t24 * t82;
    const float t91 = t90 * t75;
    const float t92 = -t91;
    const float t93 = t28 * t75;
    const float t94 = t77 + t30;
    const float t95 = t77 / t94;
    const float t96 = t93 * t95;
    const float t97 = t92 - t96;
    const float t98 = t35 * t82;
    const float t99 = t98 * t40;
    const float t100 = t99 * t75;
    const float t101 = t86 * t79;
    const float t102 = t100 - t101;
    const float t103 = t3 * t89;
    const float t104 = t0 + t103;
    const float t105 = t3 * t97;
    const float t106 = t1 + t105;
    const float t107 = t3 * t102;
    const float t108 = t2 + t107;
    const float t109 = t9 + t106;
    const float t110 = t106 / t109;
    const float t111 = t8 * t110;
    const float t112 = fmaxf(t108, t16);
    const float t113 = t15 / t112;
    const float t114 = libm_expf(t113);
    const float t115 = t13 * t114;
    const float t116 = t111 * t104;
    const float t117 = t115 * t104;
    const float t118 = t116 - t117;
    const float t119 = t24 * t111;
    const float t120 = t119 * t104;
    const float t121 = -t120;
    const float t122 = t28 * t104;
    const float t123 = t106 + t30;
    const float t124 = t106 / t123;
    const float t125 = t122 * t124;
    const float t126 = t121 - t125;
    const float t127 = t35 * t111;
    const float t128 = t127 * t40;
    const float t129 = t128 * t104;
    const float t130 = t115 * t108;
    const float t131 = t129 - t130;
    const float t132 = t60 + t89;
    const float t133 = t4 * t132;
    const float t134 = t23 + t133;
    const float t135 = t134 + t118;
    const float t136 = t7 * t135;
    const float t137 = t0 + t136;
    const float t138 = t68 + t97;
    const float t139 = t4 * t138;
    const float t140 = t34 + t139;
    const float t141 = t140 + t126;
    const float t142 = t7 * t141;
    const float t143 = t1 + t142;
    const float t144 = t73 + t102;
    const float t145 = t4 * t144;
    const float t146 = t44 + t145;
    const float t147 = t146 + t131;
    const float t148 = t7 * t147;
    const float t149 = t2 + t148;
    out[0] = t137;
    out[1] = t143;
    out[2] = t149;
}

/* The correction during the start-up, g = (blends g_j, gains K_j): x before its clamp. */
static void corrected_start_up(const float *x, const float *y, const float *u, const float *f, const float *g, float *out) {
    (void)u;
    const float t0 = x[0];
    const float t1 = x[1];
    const float t2 = x[2];
    const float t3 = 0.2f /* mu_m */;
    const float t4 = 0.1f /* k_s */;
    const float t5 = t4 + t1;
    const float t6 = t1 / t5;
    const float t7 = t3 * t6;
    const float t8 = 5000.0f /* y_l */;
    const float t9 = t8 * t7;
    const float t10 = 1.0f /* I */;
    const float t11 = 1.0f /* k_l */;
    const float t12 = t10 + t11;
    const float t13 = t10 / t12;
    const float t14 = t9 * t13;
    const float t15 = t14 * t0;
    const float t16 = t15 * t2;
    const float t17 = y[0];
    const float t18 = t17 - t0;
    const float t19 = y[1];
    const float t20 = t19 - t16;
    const float t21 = g[0];
    const float t22 = f[0];
    const float t23 = t22 - t0;
    const float t24 = t21 * t23;
    const float t25 = t0 + t24;
    const float t26 = g[3];
    const float t27 = g[4];
    const float t28 = t26 * t18;
    const float t29 = t25 + t28;
    const float t30 = t27 * t20;
    const float t31 = t29 + t30;
    const float t32 = g[1];
    const float t33 = f[1];
    const float t34 = t33 - t1;
    const float t35 = t32 * t34;
    const float t36 = t1 + t35;
    const float t37 = g[5];
    const float t38 = g[6];
    const float t39 = t37 * t18;
    const float t40 = t36 + t39;
    const float t41 = t38 * t20;
    const float t42 = t40 + t41;
    const float t43 = g[2];
    const float t44 = f[2];
    const float t45 = t44 - t2;
    const float t46 = t43 * t45;
    const float t47 = t2 + t46;
    const float t48 = g[7];
    const float t49 = g[8];
    const float t50 = t48 * t18;
    const float t51 = t47 + t50;
    const float t52 = t49 * t20;
    const float t53 = t51 + t52;
    out[0] = t31;
    out[1] = t42;
    out[2] = t53;
}

/* The correction after the start-up: x before its clamp. */
static void corrected_steady(const float *x, const float *y, const float *u, const float *f, float *out) {
    (void)u;
    (void)f;
    const float t0 = x[0];
    const float t1 = x[1];
    const float t2 = x[2];
    const float t3 = 0.2f /* mu_m */;
    const float t4 = 0.1f /* k_s */;
    const float t5 = t4 + t1;
    const float t6 = t1 / t5;
    const float t7 = t3 * t6;
    const float t8 = 5000.0f /* y_l */;
    const float t9 = t8 * t7;
    const float t10 = 1.0f /* I */;
    const float t11 = 1.0f /* k_l */;
    const float t12 = t10 + t11;
    const float t13 = t10 / t12;
    const float t14 = t9 * t13;
    const float t15 = t14 * t0;
    const float t16 = t15 * t2;
    const float t17 = y[0];
    const float t18 = t17 - t0;
    const float t19 = y[1];
    const float t20 = t19 - t16;
    const float t21 = 0.030331278f;
    const float t22 = 0.0013291131f;
    const float t23 = t21 * t18;
    const float t24 = t0 + t23;
    const float t25 = t22 * t20;
    const float t26 = t24 + t25;
    const float t27 = 0.0046590413f;
    const float t28 = 0.0017050348f;
    const float t29 = t27 * t18;
    const float t30 = t1 + t29;
    const float t31 = t28 * t20;
    const float t32 = t30 + t31;
    const float t33 = -0.0055419323f;
    const float t34 = 2.185293e-5f;
    const float t35 = t33 * t18;
    const float t36 = t2 + t35;
    const float t37 = t34 * t20;
    const float t38 = t36 + t37;
    out[0] = t26;
    out[1] = t32;
    out[2] = t38;
}

/* Each state's map estimate, from the map's rows (a target's or a helper map's). */
static void corrected_map_states(const float *all, float *map) {
    map[0] = all[2];
    map[1] = all[3];
    map[2] = all[0];
}

/* The targets of a follower's states, flagged with their states' saturation. */
static void corrected_targets_of(const float *states, const ecoli_x0_0p5_saturation *state_flags, const float *u,
                                float *values, ecoli_x0_0p5_saturation *flags) {
    targets(states, u, values);
    flags[0] = ECOLI_X0_0P5_INSIDE;
    flags[1] = ECOLI_X0_0P5_INSIDE;
    flags[0] = state_flags[2];
}

/* Corrector::start: the model's period from the map's first estimate (or from the states after
 * a correction), taken into x when finite. */
static int corrected_start(const float *first, const float *u, float *x) {
    float next[ECOLI_X0_0P5_STATES];
    corrected_predict(first, u, next);
    if (!all_finite(next, ECOLI_X0_0P5_STATES)) {
        return 0;
    }
    memcpy(x, next, sizeof next);
    return 1;
}

/* Corrector::follow: the correction of the prediction x (the start-up's blend and gain, or
 * G's), clamped to the states' ranges by selects, then the model's period from it. */
static int corrected_follow(float *x, unsigned j, int start_up, const float *f, const float *y, const float *u,
                            float *states, ecoli_x0_0p5_saturation *flags) {
    float raw[ECOLI_X0_0P5_STATES];
    unsigned i;
    if (start_up) {
        corrected_start_up(x, y, u, f, (j >= 1u && j <= 9u) ? CORRECTED_BLENDS[j - 1u] : CORRECTED_NO_BLEND, raw);
    } else {
        corrected_steady(x, y, u, f, raw);
    }
    for (i = 0u; i < ECOLI_X0_0P5_STATES; ++i) {
        const int low = !(raw[i] >= CORRECTED_LOWER[i]);
        const int out = low | (raw[i] > CORRECTED_UPPER[i]);
        const float edge = select_float(low, CORRECTED_LOWER[i], CORRECTED_UPPER[i]);
        const uint32_t flag = select_bits(low, (uint32_t)ECOLI_X0_0P5_LOW, (uint32_t)ECOLI_X0_0P5_HIGH);
        states[i] = select_float(out, edge, raw[i]);
        flags[i] = (ecoli_x0_0p5_saturation)select_bits(out, flag, (uint32_t)ECOLI_X0_0P5_INSIDE);
    }
    return corrected_start(states, u, x);
}

/* Corrector::predict: a lost output, the model's period from x (no correction). */
static void corrected_lost(float *x, const float *u) {
    (void)corrected_start(x, u, x);
}


static void corrected_fresh(ecoli_x0_0p5_corrected *o) {
    ecoli_x0_0p5_map_init(&o->window);
    memset(o->x, 0, sizeof o->x);
    o->count = 0u;
    o->started = 0;
}

static ecoli_x0_0p5_status corrected_sample(ecoli_x0_0p5_corrected *o, const float *y, const float *u) {
    const int start_up = o->count <= 9u;
    float all[ECOLI_X0_0P5_MAP_ROWS], map[ECOLI_X0_0P5_STATES], states[ECOLI_X0_0P5_STATES];
    ecoli_x0_0p5_saturation all_flags[ECOLI_X0_0P5_MAP_ROWS], state_flags[ECOLI_X0_0P5_STATES];
    int estimated = 0;
    if (!accepts(y, u)) {
        if (o->started && inputs_finite(u)) {
            corrected_lost(o->x, u);
        }
        return ECOLI_X0_0P5_REFUSED;
    }
    memset(map, 0, sizeof map);
    if (start_up) {
        (void)ecoli_x0_0p5_map_push(&o->window, y, u);
        if (o->window.filled < ECOLI_X0_0P5_HORIZON) {
            return ECOLI_X0_0P5_OK;
        }
        (void)start_map_estimate(&o->window, all, all_flags);
        corrected_map_states(all, map);
        estimated = 1;
    }
    if (!o->started && estimated) {
        if (!corrected_start(map, u, o->x)) {
            corrected_fresh(o);
            return ECOLI_X0_0P5_RESTARTED;
        }
        o->started = 1;
        memcpy(o->values, all, sizeof o->values);
        memcpy(o->flags, all_flags, sizeof o->flags);
    } else if (o->started) {
        if (!corrected_follow(o->x, o->count, start_up, map, y, u, states, state_flags)) {
            corrected_fresh(o);
            return ECOLI_X0_0P5_RESTARTED;
        }
        corrected_targets_of(states, state_flags, u, o->values, o->flags);
    } else {
        return ECOLI_X0_0P5_OK;
    }
    o->ready = 1;
    o->count = start_up ? o->count + 1u : o->count;
    return ECOLI_X0_0P5_OK;
}

void ecoli_x0_0p5_corrected_init(ecoli_x0_0p5_corrected *o) {
    corrected_fresh(o);
    o->ready = 0;
    o->refused = 0u;
    o->restarts = 0u;
}

ecoli_x0_0p5_status ecoli_x0_0p5_corrected_push(ecoli_x0_0p5_corrected *o, const float *y, const float *u) {
    const ecoli_x0_0p5_status status = corrected_sample(o, y, u);
    if (status == ECOLI_X0_0P5_REFUSED && o->refused != UINT32_MAX) {
        ++o->refused;
    } else if (status == ECOLI_X0_0P5_RESTARTED && o->restarts != UINT32_MAX) {
        ++o->restarts;
    }
    return status;
}

ecoli_x0_0p5_status ecoli_x0_0p5_corrected_estimate(const ecoli_x0_0p5_corrected *o, float *values, ecoli_x0_0p5_saturation *saturation) {
    if (!o->ready) {
        return ECOLI_X0_0P5_NO_ESTIMATE_YET;
    }
    memcpy(values, o->values, sizeof o->values);
    memcpy(saturation, o->flags, sizeof o->flags);
    return ECOLI_X0_0P5_OK;
}

/* P(N-1)'s upper triangle of the EKF the map starts. */
static const float STARTED_P0[ECOLI_X0_0P5_COVARIANCE] = {
    0.00022294049f, 0.0f, 0.0f, 0.015391284f,
    0.0f, 3.2587675e-5f
};

/* Each state's map estimate, from the map's rows (a target's or a helper map's). */
static void started_ekf_map_states(const float *all, float *map) {
    map[0] = all[2];
    map[1] = all[3];
    map[2] = all[0];
}

/* The targets of a follower's states, flagged with their states' saturation. */
static void started_ekf_targets_of(const float *states, const ecoli_x0_0p5_saturation *state_flags, const float *u,
                                float *values, ecoli_x0_0p5_saturation *flags) {
    targets(states, u, values);
    flags[0] = ECOLI_X0_0P5_INSIDE;
    flags[1] = ECOLI_X0_0P5_INSIDE;
    flags[0] = state_flags[2];
}

/* StartedEkf::start: one prediction from the map's states with STARTED_P0, taken when finite;
 * the watched mean at its start. */
static int started_ekf_start(const float *first, const float *u, float *x, float *p, float *chi) {
    float out[ECOLI_X0_0P5_STATES + ECOLI_X0_0P5_COVARIANCE];
    ekf_unmeasured(first, STARTED_P0, u, out);
    if (!all_finite(out, ECOLI_X0_0P5_STATES + ECOLI_X0_0P5_COVARIANCE)) {
        return 0;
    }
    memcpy(x, out, ECOLI_X0_0P5_STATES * sizeof *x);
    memcpy(p, out + ECOLI_X0_0P5_STATES, ECOLI_X0_0P5_COVARIANCE * sizeof *p);
    *chi = 2.0f;
    return 1;
}

/* StartedEkf::follow: the EKF's sample, every state inside; not taken when the
 * chi-squared watch (firmware::watch) finds the innovations implausible. */
static int started_ekf_follow(float *x, float *p, float *chi, unsigned j, int start_up, const float *map,
                              const float *y, const float *u, float *states, ecoli_x0_0p5_saturation *flags) {
    unsigned i;
    float nis;
    (void)j;
    (void)start_up;
    (void)map;
    for (i = 0u; i < ECOLI_X0_0P5_STATES; ++i) {
        flags[i] = ECOLI_X0_0P5_INSIDE;
    }
    if (!ekf_measure(x, p, y, u, states, &nis)) {
        return 0;
    }
    *chi = *chi + 0.33333334f * (nis - *chi);
    return *chi <= 2048.0f;
}


static void ekf_map_fresh(ecoli_x0_0p5_ekf_map *o) {
    ecoli_x0_0p5_map_init(&o->window);
    memcpy(o->x, EKF_X0, sizeof o->x);
    memcpy(o->p, EKF_P0, sizeof o->p);
    o->count = 0u;
    o->started = 0;
}

static ecoli_x0_0p5_status ekf_map_sample(ecoli_x0_0p5_ekf_map *o, const float *y, const float *u) {
    const int start_up = o->count <= 0u;
    float all[ECOLI_X0_0P5_MAP_ROWS], map[ECOLI_X0_0P5_STATES], states[ECOLI_X0_0P5_STATES];
    ecoli_x0_0p5_saturation all_flags[ECOLI_X0_0P5_MAP_ROWS], state_flags[ECOLI_X0_0P5_STATES];
    int estimated = 0;
    if (!accepts(y, u)) {
        if (o->started && inputs_finite(u)) {
            ekf_predict(o->x, o->p, u);
        }
        return ECOLI_X0_0P5_REFUSED;
    }
    memset(map, 0, sizeof map);
    if (start_up) {
        (void)ecoli_x0_0p5_map_push(&o->window, y, u);
        if (o->window.filled < ECOLI_X0_0P5_HORIZON) {
            return ECOLI_X0_0P5_OK;
        }
        (void)start_map_estimate(&o->window, all, all_flags);
        started_ekf_map_states(all, map);
        estimated = 1;
    }
    if (!o->started && estimated) {
        if (!started_ekf_start(map, u, o->x, o->p, &o->chi)) {
            ekf_map_fresh(o);
            return ECOLI_X0_0P5_RESTARTED;
        }
        o->started = 1;
        memcpy(o->values, all, sizeof o->values);
        memcpy(o->flags, all_flags, sizeof o->flags);
    } else if (o->started) {
        if (!started_ekf_follow(o->x, o->p, &o->chi, o->count, start_up, map, y, u, states, state_flags)) {
            ekf_map_fresh(o);
            return ECOLI_X0_0P5_RESTARTED;
        }
        started_ekf_targets_of(states, state_flags, u, o->values, o->flags);
    } else {
        return ECOLI_X0_0P5_OK;
    }
    o->ready = 1;
    o->count = start_up ? o->count + 1u : o->count;
    return ECOLI_X0_0P5_OK;
}

void ecoli_x0_0p5_ekf_map_init(ecoli_x0_0p5_ekf_map *o) {
    ekf_map_fresh(o);
    o->ready = 0;
    o->refused = 0u;
    o->restarts = 0u;
}

ecoli_x0_0p5_status ecoli_x0_0p5_ekf_map_push(ecoli_x0_0p5_ekf_map *o, const float *y, const float *u) {
    const ecoli_x0_0p5_status status = ekf_map_sample(o, y, u);
    if (status == ECOLI_X0_0P5_REFUSED && o->refused != UINT32_MAX) {
        ++o->refused;
    } else if (status == ECOLI_X0_0P5_RESTARTED && o->restarts != UINT32_MAX) {
        ++o->restarts;
    }
    return status;
}

ecoli_x0_0p5_status ecoli_x0_0p5_ekf_map_estimate(const ecoli_x0_0p5_ekf_map *o, float *values, ecoli_x0_0p5_saturation *saturation) {
    if (!o->ready) {
        return ECOLI_X0_0P5_NO_ESTIMATE_YET;
    }
    memcpy(values, o->values, sizeof o->values);
    memcpy(saturation, o->flags, sizeof o->flags);
    return ECOLI_X0_0P5_OK;
}

/* Whether the filter's prediction x (covariance p) and the map's states f disagree:
 * d = sum_i (x_i - f_i)^2 / (P_ii + e_i^2) > threshold, or d is NaN (restart_disagrees). */
static int restart_disagrees(const float *x, const float *p, const float *f) {
    float d = 0.0f;
    float e;
    e = x[0] - f[0];
    d += e * e / (p[0] + 0.022294048f);
    e = x[1] - f[1];
    d += e * e / (p[3] + 1.5391283f);
    e = x[2] - f[2];
    d += e * e / (p[5] + 0.0032587678f);
    return !(d <= 64.0f);
}

static void ekf_restart_fresh(ecoli_x0_0p5_ekf_restart *o) {
    ecoli_x0_0p5_map_init(&o->window);
    memcpy(o->x, EKF_X0, sizeof o->x);
    memcpy(o->p, EKF_P0, sizeof o->p);
    o->chi = 2.0f;
}

/* firmware::Restarted: the sample to the map's window; from its first estimate on, the map's states
 * against the filter's prediction at every sample, restarted from the map when they disagree;
 * else the filter's sample, restarted (from the map where it has an estimate, else from the start)
 * when its step is not finite or its chi-squared watch finds the innovations implausible. */
static ecoli_x0_0p5_status ekf_restart_sample(ecoli_x0_0p5_ekf_restart *o, const float *y, const float *u) {
    float all[ECOLI_X0_0P5_MAP_ROWS], map[ECOLI_X0_0P5_STATES], states[ECOLI_X0_0P5_STATES];
    ecoli_x0_0p5_saturation all_flags[ECOLI_X0_0P5_MAP_ROWS], state_flags[ECOLI_X0_0P5_STATES];
    int mapped = 0;
    if (!accepts(y, u)) {
        if (inputs_finite(u)) {
            ekf_predict(o->x, o->p, u);
        }
        return ECOLI_X0_0P5_REFUSED;
    }
    (void)ecoli_x0_0p5_map_push(&o->window, y, u);
    if (o->window.filled >= ECOLI_X0_0P5_HORIZON) {
        (void)start_map_estimate(&o->window, all, all_flags);
        started_ekf_map_states(all, map);
        mapped = 1;
        if (restart_disagrees(o->x, o->p, map) && started_ekf_start(map, u, o->x, o->p, &o->chi)) {
            memcpy(o->values, all, sizeof o->values);
            memcpy(o->flags, all_flags, sizeof o->flags);
            o->ready = 1;
            return ECOLI_X0_0P5_OK;
        }
    }
    if (!started_ekf_follow(o->x, o->p, &o->chi, 1u, 0, NULL, y, u, states, state_flags)) {
        if (!(mapped && started_ekf_start(map, u, o->x, o->p, &o->chi))) {
            memcpy(o->x, EKF_X0, sizeof o->x);
            memcpy(o->p, EKF_P0, sizeof o->p);
            o->chi = 2.0f;
        }
        return ECOLI_X0_0P5_RESTARTED;
    }
    started_ekf_targets_of(states, state_flags, u, o->values, o->flags);
    o->ready = 1;
    return ECOLI_X0_0P5_OK;
}

void ecoli_x0_0p5_ekf_restart_init(ecoli_x0_0p5_ekf_restart *o) {
    ekf_restart_fresh(o);
    o->ready = 0;
    o->refused = 0u;
    o->restarts = 0u;
}

ecoli_x0_0p5_status ecoli_x0_0p5_ekf_restart_push(ecoli_x0_0p5_ekf_restart *o, const float *y, const float *u) {
    const ecoli_x0_0p5_status status = ekf_restart_sample(o, y, u);
    if (status == ECOLI_X0_0P5_REFUSED && o->refused != UINT32_MAX) {
        ++o->refused;
    } else if (status == ECOLI_X0_0P5_RESTARTED && o->restarts != UINT32_MAX) {
        ++o->restarts;
    }
    return status;
}

ecoli_x0_0p5_status ecoli_x0_0p5_ekf_restart_estimate(const ecoli_x0_0p5_ekf_restart *o, float *values, ecoli_x0_0p5_saturation *saturation) {
    if (!o->ready) {
        return ECOLI_X0_0P5_NO_ESTIMATE_YET;
    }
    memcpy(values, o->values, sizeof o->values);
    memcpy(saturation, o->flags, sizeof o->flags);
    return ECOLI_X0_0P5_OK;
}

/* The model's derivative f(x, u), then its Jacobian row by row (the Rust file's Plant::derivative). */
static void model_derivative(const float *x, const float *u, float *out) {
    (void)u;
    const float t0 = 0.2f /* mu_m */;
    const float t1 = x[1];
    const float t2 = 0.1f /* k_s */;
    const float t3 = t2 + t1;
    const float t4 = t1 / t3;
    const float t5 = t0 * t4;
    const float t6 = 0.0f;
    const float t7 = 1.0f;
    const float t8 = t7 / t3;
    const float t9 = t3 * t3;
    const float t10 = t1 / t9;
    const float t11 = t8 - t10;
    const float t12 = t0 * t11;
    const float t13 = 0.1f /* k_d */;
    const float t14 = 0.5f /* k_p */;
    const float t15 = -t14;
    const float t16 = x[2];
    const float t17 = 0.001f;
    const float t18 = fmaxf(t16, t17);
    const float t19 = t15 / t18;
    const float t20 = libm_expf(t19);
    const float t21 = t13 * t20;
    const float t22 = 0.5f;
    const float t23 = -0.5f;
    const float t24 = t17 - t16;
    const float t25 = signum(t24);
    const float t26 = t23 * t25;
    const float t27 = t22 + t26;
    const float t28 = t15 * t27;
    const float t29 = t18 * t18;
    const float t30 = t28 / t29;
    const float t31 = -t30;
    const float t32 = t20 * t31;
    const float t33 = t13 * t32;
    const float t34 = x[0];
    const float t35 = t5 * t34;
    const float t36 = t21 * t34;
    const float t37 = t35 - t36;
    const float t38 = t5 - t21;
    const float t39 = t34 * t6;
    const float t40 = t38 + t39;
    const float t41 = -t34;
    const float t42 = t41 * t6;
    const float t43 = t40 + t42;
    const float t44 = t34 * t12;
    const float t45 = t44 + t42;
    const float t46 = t41 * t33;
    const float t47 = t39 + t46;
    const float t48 = 1.0f /* y_s */;
    const float t49 = t48 * t5;
    const float t50 = t49 * t34;
    const float t51 = t6 - t50;
    const float t52 = 0.05f /* k_m */;
    const float t53 = t52 * t34;
    const float t54 = 0.01f /* ks_m */;
    const float t55 = t1 + t54;
    const float t56 = t1 / t55;
    const float t57 = t53 * t56;
    const float t58 = t51 - t57;
    const float t59 = -t49;
    const float t60 = t52 * t56;
    const float t61 = t59 - t60;
    const float t62 = t48 * t34;
    const float t63 = -t62;
    const float t64 = t63 * t6;
    const float t65 = t61 + t64;
    const float t66 = t7 / t55;
    const float t67 = t55 * t55;
    const float t68 = t1 / t67;
    const float t69 = t66 - t68;
    const float t70 = t53 * t69;
    const float t71 = -t70;
    const float t72 = t63 * t12;
    const float t73 = t71 + t72;
    const float t74 = 0.2f /* y_p */;
    const float t75 = t74 * t5;
    const float t76 = 1.0f /* I */;
    const float t77 = 0.5f /* k_I */;
    const float t78 = t76 + t77;
    const float t79 = t76 / t78;
    const float t80 = t75 * t79;
    const float t81 = t80 * t34;
    const float t82 = t21 * t16;
    const float t83 = t81 - t82;
    const float t84 = t74 * t79;
    const float t85 = t84 * t34;
    const float t86 = t85 * t6;
    const float t87 = t80 + t86;
    const float t88 = -t16;
    const float t89 = t88 * t6;
    const float t90 = t87 + t89;
    const float t91 = t85 * t12;
    const float t92 = t91 + t89;
    const float t93 = -t21;
    const float t94 = t93 + t86;
    const float t95 = t88 * t33;
    const float t96 = t94 + t95;
    out[0] = t37;
    out[1] = t58;
    out[2] = t83;
    out[3] = t43;
    out[4] = t45;
    out[5] = t47;
    out[6] = t65;
    out[7] = t73;
    out[8] = t64;
    out[9] = t90;
    out[10] = t92;
    out[11] = t96;
}

/* The model's outputs h(x, u), then their Jacobian row by row (the Rust file's Plant::output). */
static void model_output(const float *x, const float *u, float *out) {
    (void)u;
    const float t0 = 0.2f /* mu_m */;
    const float t1 = x[1];
    const float t2 = 0.1f /* k_s */;
    const float t3 = t2 + t1;
    const float t4 = t1 / t3;
    const float t5 = t0 * t4;
    const float t6 = 0.0f;
    const float t7 = 1.0f;
    const float t8 = t7 / t3;
    const float t9 = t3 * t3;
    const float t10 = t1 / t9;
    const float t11 = t8 - t10;
    const float t12 = t0 * t11;
    const float t13 = x[2];
    const float t14 = x[0];
    const float t15 = 5000.0f /* y_l */;
    const float t16 = t15 * t5;
    const float t17 = 1.0f /* I */;
    const float t18 = 1.0f /* k_l */;
    const float t19 = t17 + t18;
    const float t20 = t17 / t19;
    const float t21 = t16 * t20;
    const float t22 = t21 * t14;
    const float t23 = t22 * t13;
    const float t24 = t21 * t13;
    const float t25 = t15 * t20;
    const float t26 = t25 * t14;
    const float t27 = t26 * t13;
    const float t28 = t27 * t6;
    const float t29 = t24 + t28;
    const float t30 = t27 * t12;
    const float t31 = t22 + t28;
    out[0] = t14;
    out[1] = t23;
    out[2] = t7;
    out[3] = t6;
    out[4] = t6;
    out[5] = t29;
    out[6] = t30;
    out[7] = t31;
}

/* The moving-horizon estimate's constants: the outputs' weights 1 / sigma^2, the prior's weight per
 * state, the learning box, the first window's start, Levenberg's damping, the RK4 substep. */
static const float MHE_WEIGHTS[ECOLI_X0_0P5_OUTPUTS] = {
    10.0f, 0.05f
};
static const float MHE_PRIOR[ECOLI_X0_0P5_STATES] = {
    30.290594f, 4.0f, 503.19193f
};
static const float MHE_LOWER[ECOLI_X0_0P5_STATES] = {
    0.4385543f, 0.0f, 0.0f
};
static const float MHE_UPPER[ECOLI_X0_0P5_STATES] = {
    2.2555175f, 5.0f, 0.4457929f
};
static const float MHE_START[ECOLI_X0_0P5_STATES] = {
    0.5f, 2.5f, 0.15f
};
static const float MHE_DAMPING = 1e-6f;
static const float MHE_H = 0.2f;
/* The chi-square watch over the windows' output costs (firmware::watch): the mean's start N m, its
 * gain 1 / W and its limit tau N m. */
static const float MHE_WATCH_START = 6.0f;
static const float MHE_WATCH_GAIN = 0.33333334f;
static const float MHE_WATCH_LIMIT = 6144.0f;
#define MHE_ITERATIONS 6u
#define MHE_SUBSTEPS 1u
#define MHE_NX ECOLI_X0_0P5_STATES
#define MHE_NY ECOLI_X0_0P5_OUTPUTS
/* The inputs of the window's sample k (oldest first) of the observer o. */
#define MHE_U(o, k) NULL

/* firmware::matrix::product: out = a b, each entry summed from 0 in k's order. */
static void mhe_product(float (*a)[MHE_NX], float (*b)[MHE_NX], float (*out)[MHE_NX]) {
    unsigned r, c, k;
    for (r = 0u; r < MHE_NX; ++r) {
        for (c = 0u; c < MHE_NX; ++c) {
            float entry = 0.0f;
            for (k = 0u; k < MHE_NX; ++k) {
                entry += a[r][k] * b[k][c];
            }
            out[r][c] = entry;
        }
    }
}

/* The derivative k and its Jacobian d at x. */
static void mhe_derivative(const float *x, const float *u, float *k, float (*d)[MHE_NX]) {
    float out[MHE_NX + MHE_NX * MHE_NX];
    unsigned i, j;
    model_derivative(x, u, out);
    for (i = 0u; i < MHE_NX; ++i) {
        k[i] = out[i];
        for (j = 0u; j < MHE_NX; ++j) {
            d[i][j] = out[MHE_NX + i * MHE_NX + j];
        }
    }
}

/* Rk4::stage: the derivative at x + w k, and its Jacobian times (I + w d). */
static void mhe_stage(const float *x, const float *k, float (*d)[MHE_NX], float w, const float *u, float *value,
                      float (*jacobian)[MHE_NX]) {
    float point[MHE_NX];
    float moved[MHE_NX][MHE_NX], a[MHE_NX][MHE_NX];
    unsigned i, j;
    for (i = 0u; i < MHE_NX; ++i) {
        point[i] = x[i] + w * k[i];
        for (j = 0u; j < MHE_NX; ++j) {
            moved[i][j] = (i == j ? 1.0f : 0.0f) + w * d[i][j];
        }
    }
    mhe_derivative(point, u, value, a);
    mhe_product(a, moved, jacobian);
}

/* Rk4::substep: one classical RK4 step of MHE_H from x, with its Jacobian. */
static void mhe_substep(const float *x, const float *u, float *next, float (*jacobian)[MHE_NX]) {
    const float two = 1.0f + 1.0f;
    const float half = MHE_H / two;
    const float sixth = MHE_H / (two + two + two);
    float k1[MHE_NX], k2[MHE_NX], k3[MHE_NX], k4[MHE_NX];
    float d1[MHE_NX][MHE_NX], d2[MHE_NX][MHE_NX], d3[MHE_NX][MHE_NX], d4[MHE_NX][MHE_NX];
    unsigned i, j;
    mhe_derivative(x, u, k1, d1);
    mhe_stage(x, k1, d1, half, u, k2, d2);
    mhe_stage(x, k2, d2, half, u, k3, d3);
    mhe_stage(x, k3, d3, MHE_H, u, k4, d4);
    for (i = 0u; i < MHE_NX; ++i) {
        next[i] = x[i] + sixth * (k1[i] + two * (k2[i] + k3[i]) + k4[i]);
        for (j = 0u; j < MHE_NX; ++j) {
            jacobian[i][j] = (i == j ? 1.0f : 0.0f) + sixth * (d1[i][j] + two * (d2[i][j] + d3[i][j]) + d4[i][j]);
        }
    }
}

/* Rk4::step: one sampling period (MHE_SUBSTEPS substeps, their Jacobians composed). */
static void mhe_step(const float *x, const float *u, float *next, float (*jacobian)[MHE_NX]) {
    unsigned s;
    mhe_substep(x, u, next, jacobian);
    for (s = 1u; s < MHE_SUBSTEPS; ++s) {
        float from[MHE_NX];
        float d[MHE_NX][MHE_NX], composed[MHE_NX][MHE_NX];
        memcpy(from, next, sizeof from);
        mhe_substep(from, u, next, d);
        mhe_product(d, jacobian, composed);
        memcpy(jacobian, composed, sizeof composed);
    }
}

/* firmware::bounds::project onto the learning box: at_least, then at_most, by selects. */
static void mhe_project(const float *x, float *out) {
    unsigned i;
    for (i = 0u; i < MHE_NX; ++i) {
        const float above = select_float(!(x[i] >= MHE_LOWER[i]), MHE_LOWER[i], x[i]);
        out[i] = select_float(above > MHE_UPPER[i], MHE_UPPER[i], above);
    }
}

/* firmware::mhe::normal_equations over the window of o from x: J^T W J and J^T W r (a non-finite
 * residual weighs nothing). */
static void mhe_normal(const ecoli_x0_0p5_mhe *o, const float *x, float (*matrix)[MHE_NX], float *gradient, float *cost) {
    float state[MHE_NX];
    float sensitivity[MHE_NX][MHE_NX];
    unsigned k, i, a, b, c, m;
    memcpy(state, x, sizeof state);
    *cost = 0.0f;
    for (a = 0u; a < MHE_NX; ++a) {
        gradient[a] = 0.0f;
        for (b = 0u; b < MHE_NX; ++b) {
            matrix[a][b] = 0.0f;
            sensitivity[a][b] = a == b ? 1.0f : 0.0f;
        }
    }
    for (k = 0u; k < ECOLI_X0_0P5_HORIZON; ++k) {
        const float *y = o->y[o->next + k];
        float out[MHE_NY + MHE_NY * MHE_NX];
        if (k > 0u) {
            float next[MHE_NX];
            float f[MHE_NX][MHE_NX], composed[MHE_NX][MHE_NX];
            mhe_step(state, MHE_U(o, k - 1u), next, f);
            memcpy(state, next, sizeof state);
            mhe_product(f, sensitivity, composed);
            memcpy(sensitivity, composed, sizeof composed);
        }
        model_output(state, MHE_U(o, k), out);
        for (i = 0u; i < MHE_NY; ++i) {
            const float raw = y[i] - out[i];
            const int finite = is_finite(raw);
            const float residual = select_float(finite, raw, 0.0f);
            const float w = select_float(finite, MHE_WEIGHTS[i], 0.0f);
            float row[MHE_NX];
            *cost += w * residual * residual;
            for (c = 0u; c < MHE_NX; ++c) {
                row[c] = 0.0f;
                for (m = 0u; m < MHE_NX; ++m) {
                    row[c] += out[MHE_NY + i * MHE_NX + m] * sensitivity[m][c];
                }
            }
            for (a = 0u; a < MHE_NX; ++a) {
                const float weighted = w * row[a];
                gradient[a] += weighted * residual;
                for (b = 0u; b < MHE_NX; ++b) {
                    matrix[a][b] += weighted * row[b];
                }
            }
        }
    }
}

/* firmware::mhe::solve_cholesky: a x = b by a = L D L^T (no square root); 0 where a pivot is not
 * positive and finite. */
static int mhe_cholesky(float (*a)[MHE_NX], const float *b, float *x) {
    float l[MHE_NX][MHE_NX], d[MHE_NX], inverse_d[MHE_NX], z[MHE_NX];
    unsigned i, j, k, r;
    memset(l, 0, sizeof l);
    for (j = 0u; j < MHE_NX; ++j) {
        float pivot = a[j][j];
        for (k = 0u; k < j; ++k) {
            pivot -= l[j][k] * l[j][k] * d[k];
        }
        if (!(pivot > 0.0f) || !is_finite(pivot)) {
            return 0;
        }
        d[j] = pivot;
        inverse_d[j] = 1.0f / pivot;
        for (i = j + 1u; i < MHE_NX; ++i) {
            float sum = a[i][j];
            /* k < MHE_NX always holds: said for gcc -O1, which otherwise warns of an access beyond l. */
            for (k = 0u; k < j && k < MHE_NX; ++k) {
                sum -= l[i][k] * l[j][k] * d[k];
            }
            l[i][j] = sum * inverse_d[j];
        }
    }
    for (r = 0u; r < MHE_NX; ++r) {
        float sum = b[r];
        for (k = 0u; k < r; ++k) {
            sum -= l[r][k] * z[k];
        }
        z[r] = sum;
    }
    for (r = MHE_NX; r-- > 0u;) {
        float sum = z[r] * inverse_d[r];
        for (k = r + 1u; k < MHE_NX; ++k) {
            sum -= l[k][r] * x[k];
        }
        x[r] = sum;
    }
    return 1;
}

/* firmware::mhe::solve_window: MHE_ITERATIONS damped Gauss-Newton steps from centre (with the prior
 * around it when `prior`), each projected; the solution x, the state at the newest sample and the
 * window's output cost at the last step's start. */
static void mhe_solve_window(const ecoli_x0_0p5_mhe *o, const float *centre, int prior, float *solution, float *end, float *cost) {
    float x[MHE_NX], state[MHE_NX];
    unsigned n, i, k;
    memcpy(x, centre, sizeof x);
    *cost = 0.0f;
    for (n = 0u; n < MHE_ITERATIONS; ++n) {
        float matrix[MHE_NX][MHE_NX];
        float gradient[MHE_NX], step[MHE_NX], next[MHE_NX];
        mhe_normal(o, x, matrix, gradient, cost);
        for (i = 0u; i < MHE_NX; ++i) {
            if (prior) {
                matrix[i][i] += MHE_PRIOR[i];
                gradient[i] -= MHE_PRIOR[i] * (x[i] - centre[i]);
            }
            matrix[i][i] += MHE_DAMPING * matrix[i][i];
        }
        if (!mhe_cholesky(matrix, gradient, step)) {
            break;
        }
        for (i = 0u; i < MHE_NX; ++i) {
            next[i] = x[i] + step[i];
        }
        mhe_project(next, x);
    }
    memcpy(solution, x, sizeof x);
    memcpy(state, x, sizeof state);
    for (k = 1u; k < ECOLI_X0_0P5_HORIZON; ++k) {
        float next[MHE_NX];
        float f[MHE_NX][MHE_NX];
        mhe_step(state, MHE_U(o, k - 1u), next, f);
        memcpy(state, next, sizeof state);
    }
    mhe_project(state, end);
}

void ecoli_x0_0p5_mhe_init(ecoli_x0_0p5_mhe *o) {
    o->next = 0u;
    o->filled = 0u;
    o->has_solved = 0;
    o->ready = 0;
    o->restarts = 0u;
    o->chi = 0.0f;
    o->has_chi = 0;
}

ecoli_x0_0p5_status ecoli_x0_0p5_mhe_push(ecoli_x0_0p5_mhe *o, const float *y, const float *u) {
    float moved[MHE_NX], x[MHE_NX], end[MHE_NX], values[ECOLI_X0_0P5_TARGETS], cost;
    int has_moved = 0;
    unsigned i, slot;
    float chi;
    if (!all_finite(y, ECOLI_X0_0P5_OUTPUTS) || !inputs_finite(u)) {
        return ECOLI_X0_0P5_REFUSED;
    }
    /* The previous solution moved one sample on: the prior's centre and the first iterate. */
    if (o->has_solved && o->filled >= ECOLI_X0_0P5_HORIZON) {
        float next[MHE_NX];
        float f[MHE_NX][MHE_NX];
        mhe_step(o->solved, MHE_U(o, 0u), next, f);
        mhe_project(next, moved);
        has_moved = 1;
    }
    /* Every value of the sample is finite: stored. */
    slot = o->next;
    for (i = 0u; i < ECOLI_X0_0P5_OUTPUTS; ++i) {
        o->y[slot][i] = y[i];
        o->y[slot + ECOLI_X0_0P5_HORIZON][i] = y[i];
    }
    o->next = slot + 1u >= ECOLI_X0_0P5_HORIZON ? 0u : slot + 1u;
    o->filled += (unsigned)(o->filled < ECOLI_X0_0P5_HORIZON);
    if (o->filled < ECOLI_X0_0P5_HORIZON) {
        return ECOLI_X0_0P5_OK;
    }
    mhe_solve_window(o, has_moved ? moved : MHE_START, has_moved, x, end, &cost);
    targets(end, u, values);
    /* firmware::watch: the windows' costs' mean, from its start after a (re)start. */
    chi = o->has_chi ? o->chi : MHE_WATCH_START;
    chi = chi + MHE_WATCH_GAIN * (cost - chi);
    if (!all_finite(x, MHE_NX) || !all_finite(end, MHE_NX) || !all_finite(values, ECOLI_X0_0P5_TARGETS)
        || !(chi <= MHE_WATCH_LIMIT)) {
        /* Restarted: the next window is solved from the start, not from this solution. */
        o->has_chi = 0;
        o->has_solved = 0;
        if (o->restarts != UINT32_MAX) {
            ++o->restarts;
        }
        return ECOLI_X0_0P5_RESTARTED;
    }
    memcpy(o->solved, x, sizeof x);
    o->has_solved = 1;
    o->chi = chi;
    o->has_chi = 1;
    memcpy(o->values, values, sizeof values);
    for (i = 0u; i < ECOLI_X0_0P5_TARGETS; ++i) {
        o->flags[i] = ECOLI_X0_0P5_INSIDE;
    }
    o->ready = 1;
    return ECOLI_X0_0P5_OK;
}

#undef MHE_ITERATIONS
#undef MHE_SUBSTEPS
#undef MHE_NX
#undef MHE_NY
#undef MHE_U

ecoli_x0_0p5_status ecoli_x0_0p5_mhe_estimate(const ecoli_x0_0p5_mhe *o, float *values, ecoli_x0_0p5_saturation *saturation) {
    if (!o->ready) {
        return ECOLI_X0_0P5_NO_ESTIMATE_YET;
    }
    memcpy(values, o->values, sizeof o->values);
    memcpy(saturation, o->flags, sizeof o->flags);
    return ECOLI_X0_0P5_OK;
}

/* The mark of this design's observer in storage (never 0: zeroed storage holds none). */
#define STORAGE_MARK 0x3175f7f9ff31ad97ull

/* The observer in storage: ECOLI_X0_0P5_BAD_ARGUMENT for a null or misaligned pointer,
 * ECOLI_X0_0P5_NOT_INITIALISED where ecoli_x0_0p5_init did not make one (it reads the first 16 bytes only). */
static ecoli_x0_0p5_status stored_observer(void *storage, ecoli_x0_0p5_observer **observer) {
    ecoli_x0_0p5_stored *stored = (ecoli_x0_0p5_stored *)storage;
    if (storage == NULL || (uintptr_t)storage % ECOLI_X0_0P5_STORAGE_ALIGN != 0u) {
        return ECOLI_X0_0P5_BAD_ARGUMENT;
    }
    if (stored->mark != STORAGE_MARK || stored->size < (uint64_t)sizeof(ecoli_x0_0p5_stored)) {
        return ECOLI_X0_0P5_NOT_INITIALISED;
    }
    *observer = &stored->observer;
    return ECOLI_X0_0P5_OK;
}

ecoli_x0_0p5_status ecoli_x0_0p5_init(void *storage, size_t size) {
    ecoli_x0_0p5_stored *stored = (ecoli_x0_0p5_stored *)storage;
    if (storage == NULL || size < sizeof(ecoli_x0_0p5_stored) || (uintptr_t)storage % ECOLI_X0_0P5_STORAGE_ALIGN != 0u) {
        return ECOLI_X0_0P5_BAD_ARGUMENT;
    }
    stored->mark = STORAGE_MARK;
    stored->size = (uint64_t)size;
    ecoli_x0_0p5_observer_init(&stored->observer);
    return ECOLI_X0_0P5_OK;
}

ecoli_x0_0p5_status ecoli_x0_0p5_push(void *storage, const float *y, const float *u) {
    ecoli_x0_0p5_observer *observer = NULL;
    const ecoli_x0_0p5_status found = stored_observer(storage, &observer);
    if (found != ECOLI_X0_0P5_OK) {
        return found;
    }
    if (y == NULL) {
        return ECOLI_X0_0P5_BAD_ARGUMENT;
    }
    return ecoli_x0_0p5_observer_push(observer, y, u);
}

ecoli_x0_0p5_status ecoli_x0_0p5_estimate(void *storage, float *estimates, ecoli_x0_0p5_saturation *saturation) {
    ecoli_x0_0p5_observer *observer = NULL;
    ecoli_x0_0p5_saturation flags[ECOLI_X0_0P5_TARGETS];
    const ecoli_x0_0p5_status found = stored_observer(storage, &observer);
    if (found != ECOLI_X0_0P5_OK) {
        return found;
    }
    if (estimates == NULL) {
        return ECOLI_X0_0P5_BAD_ARGUMENT;
    }
    return ecoli_x0_0p5_observer_estimate(observer, estimates, saturation != NULL ? saturation : flags);
}

size_t ecoli_x0_0p5_storage_size(void) {
    return sizeof(ecoli_x0_0p5_stored);
}

#undef STORAGE_MARK
