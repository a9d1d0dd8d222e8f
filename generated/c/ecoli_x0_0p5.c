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


/* `P`: gains in regressor order, then the Γ⁻¹ table's segments (a, b). */
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

/* `muX`: gains in regressor order, then the Γ⁻¹ table's segments (a, b). */
static const float GAINS_1[6] = {
    0.06840128f, 0.0055591087f, 0.070145f, 0.0003677032f,
    0.053549178f, -0.0047274753f
};
static const float SEGMENTS_1[1][2] = {
    { 0.0f, 0.43531778f }
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
    const float t48 = select_float(!(t43 >= t9), t9, t43);
    const float t49 = select_float(!(t45 >= t9), t9, t45);
    const float t50 = select_float(!(t47 >= t9), t9, t47);
    const float t51 = t41 * t27;
    const float t52 = t1 + t51;
    const float t53 = t41 * t31;
    const float t54 = t2 + t53;
    const float t55 = select_float(!(t0 >= t9), t9, t0);
    const float t56 = select_float(!(t52 >= t9), t9, t52);
    const float t57 = select_float(!(t54 >= t9), t9, t54);
    const float t58 = t41 * t40;
    const float t59 = t2 + t58;
    const float t60 = select_float(!(t1 >= t9), t9, t1);
    const float t61 = select_float(!(t59 >= t9), t9, t59);
    const float t62 = -1.7320508f;
    const float t63 = t62 * t17;
    const float t64 = t0 + t63;
    const float t65 = t62 * t19;
    const float t66 = t1 + t65;
    const float t67 = t62 * t20;
    const float t68 = t2 + t67;
    const float t69 = select_float(!(t64 >= t9), t9, t64);
    const float t70 = select_float(!(t66 >= t9), t9, t66);
    const float t71 = select_float(!(t68 >= t9), t9, t68);
    const float t72 = t62 * t27;
    const float t73 = t1 + t72;
    const float t74 = t62 * t31;
    const float t75 = t2 + t74;
    const float t76 = select_float(!(t73 >= t9), t9, t73);
    const float t77 = select_float(!(t75 >= t9), t9, t75);
    const float t78 = t62 * t40;
    const float t79 = t2 + t78;
    const float t80 = select_float(!(t79 >= t9), t9, t79);
    const float t81 = 0.2f /* mu_m */;
    const float t82 = 0.1f /* k_s */;
    const float t83 = t82 + t49;
    const float t84 = t49 / t83;
    const float t85 = t81 * t84;
    const float t86 = 5000.0f /* y_l */;
    const float t87 = t86 * t85;
    const float t88 = 1.0f /* I */;
    const float t89 = 1.0f /* k_l */;
    const float t90 = t88 + t89;
    const float t91 = t88 / t90;
    const float t92 = t87 * t91;
    const float t93 = t92 * t48;
    const float t94 = t93 * t50;
    const float t95 = t82 + t56;
    const float t96 = t56 / t95;
    const float t97 = t81 * t96;
    const float t98 = t86 * t97;
    const float t99 = t98 * t91;
    const float t100 = t99 * t55;
    const float t101 = t100 * t57;
    const float t102 = t82 + t60;
    const float t103 = t60 / t102;
    const float t104 = t81 * t103;
    const float t105 = t86 * t104;
    const float t106 = t105 * t91;
    const float t107 = t106 * t55;
    const float t108 = t107 * t61;
    const float t109 = t82 + t70;
    const float t110 = t70 / t109;
    const float t111 = t81 * t110;
    const float t112 = t86 * t111;
    const float t113 = t112 * t91;
    const float t114 = t113 * t69;
    const float t115 = t114 * t71;
    const float t116 = t82 + t76;
    const float t117 = t76 / t116;
    const float t118 = t81 * t117;
    const float t119 = t86 * t118;
    const float t120 = t119 * t91;
    const float t121 = t120 * t55;
    const float t122 = t121 * t77;
    const float t123 = t107 * t80;
    const float t124 = 0.16666667f;
    const float t125 = t48 + t55;
    const float t126 = t125 + t55;
    const float t127 = t126 + t69;
    const float t128 = t127 + t55;
    const float t129 = t128 + t55;
    const float t130 = t124 * t129;
    const float t131 = t94 + t101;
    const float t132 = t131 + t108;
    const float t133 = t132 + t115;
    const float t134 = t133 + t122;
    const float t135 = t134 + t123;
    const float t136 = t124 * t135;
    const float t137 = t48 - t130;
    const float t138 = t94 - t136;
    const float t139 = t55 - t130;
    const float t140 = t101 - t136;
    const float t141 = t108 - t136;
    const float t142 = t69 - t130;
    const float t143 = t115 - t136;
    const float t144 = t122 - t136;
    const float t145 = t123 - t136;
    const float t146 = t49 + t56;
    const float t147 = t146 + t60;
    const float t148 = t147 + t70;
    const float t149 = t148 + t76;
    const float t150 = t149 + t60;
    const float t151 = t124 * t150;
    const float t152 = t50 + t57;
    const float t153 = t152 + t61;
    const float t154 = t153 + t71;
    const float t155 = t154 + t77;
    const float t156 = t155 + t80;
    const float t157 = t124 * t156;
    const float t158 = t49 - t151;
    const float t159 = t50 - t157;
    const float t160 = t56 - t151;
    const float t161 = t57 - t157;
    const float t162 = t60 - t151;
    const float t163 = t61 - t157;
    const float t164 = t70 - t151;
    const float t165 = t71 - t157;
    const float t166 = t76 - t151;
    const float t167 = t77 - t157;
    const float t168 = t80 - t157;
    const float t169 = t137 * t137;
    const float t170 = t139 * t139;
    const float t171 = t169 + t170;
    const float t172 = t171 + t170;
    const float t173 = t142 * t142;
    const float t174 = t172 + t173;
    const float t175 = t174 + t170;
    const float t176 = t175 + t170;
    const float t177 = t124 * t176;
    const float t178 = t137 * t158;
    const float t179 = t139 * t160;
    const float t180 = t178 + t179;
    const float t181 = t139 * t162;
    const float t182 = t180 + t181;
    const float t183 = t142 * t164;
    const float t184 = t182 + t183;
    const float t185 = t139 * t166;
    const float t186 = t184 + t185;
    const float t187 = t186 + t181;
    const float t188 = t124 * t187;
    const float t189 = t137 * t159;
    const float t190 = t139 * t161;
    const float t191 = t189 + t190;
    const float t192 = t139 * t163;
    const float t193 = t191 + t192;
    const float t194 = t142 * t165;
    const float t195 = t193 + t194;
    const float t196 = t139 * t167;
    const float t197 = t195 + t196;
    const float t198 = t139 * t168;
    const float t199 = t197 + t198;
    const float t200 = t124 * t199;
    const float t201 = t158 * t158;
    const float t202 = t160 * t160;
    const float t203 = t201 + t202;
    const float t204 = t162 * t162;
    const float t205 = t203 + t204;
    const float t206 = t164 * t164;
    const float t207 = t205 + t206;
    const float t208 = t166 * t166;
    const float t209 = t207 + t208;
    const float t210 = t209 + t204;
    const float t211 = t124 * t210;
    const float t212 = t158 * t159;
    const float t213 = t160 * t161;
    const float t214 = t212 + t213;
    const float t215 = t162 * t163;
    const float t216 = t214 + t215;
    const float t217 = t164 * t165;
    const float t218 = t216 + t217;
    const float t219 = t166 * t167;
    const float t220 = t218 + t219;
    const float t221 = t162 * t168;
    const float t222 = t220 + t221;
    const float t223 = t124 * t222;
    const float t224 = t159 * t159;
    const float t225 = t161 * t161;
    const float t226 = t224 + t225;
    const float t227 = t163 * t163;
    const float t228 = t226 + t227;
    const float t229 = t165 * t165;
    const float t230 = t228 + t229;
    const float t231 = t167 * t167;
    const float t232 = t230 + t231;
    const float t233 = t168 * t168;
    const float t234 = t232 + t233;
    const float t235 = t124 * t234;
    const float t236 = t137 * t138;
    const float t237 = t139 * t140;
    const float t238 = t236 + t237;
    const float t239 = t139 * t141;
    const float t240 = t238 + t239;
    const float t241 = t142 * t143;
    const float t242 = t240 + t241;
    const float t243 = t139 * t144;
    const float t244 = t242 + t243;
    const float t245 = t139 * t145;
    const float t246 = t244 + t245;
    const float t247 = t124 * t246;
    const float t248 = t138 * t138;
    const float t249 = t140 * t140;
    const float t250 = t248 + t249;
    const float t251 = t141 * t141;
    const float t252 = t250 + t251;
    const float t253 = t143 * t143;
    const float t254 = t252 + t253;
    const float t255 = t144 * t144;
    const float t256 = t254 + t255;
    const float t257 = t145 * t145;
    const float t258 = t256 + t257;
    const float t259 = t124 * t258;
    const float t260 = 0.1f;
    const float t261 = t177 + t260;
    const float t262 = 20.0f;
    const float t263 = t259 + t262;
    const float t264 = t158 * t137;
    const float t265 = t160 * t139;
    const float t266 = t264 + t265;
    const float t267 = t162 * t139;
    const float t268 = t266 + t267;
    const float t269 = t164 * t142;
    const float t270 = t268 + t269;
    const float t271 = t166 * t139;
    const float t272 = t270 + t271;
    const float t273 = t272 + t267;
    const float t274 = t124 * t273;
    const float t275 = t158 * t138;
    const float t276 = t160 * t140;
    const float t277 = t275 + t276;
    const float t278 = t162 * t141;
    const float t279 = t277 + t278;
    const float t280 = t164 * t143;
    const float t281 = t279 + t280;
    const float t282 = t166 * t144;
    const float t283 = t281 + t282;
    const float t284 = t162 * t145;
    const float t285 = t283 + t284;
    const float t286 = t124 * t285;
    const float t287 = t159 * t137;
    const float t288 = t161 * t139;
    const float t289 = t287 + t288;
    const float t290 = t163 * t139;
    const float t291 = t289 + t290;
    const float t292 = t165 * t142;
    const float t293 = t291 + t292;
    const float t294 = t167 * t139;
    const float t295 = t293 + t294;
    const float t296 = t168 * t139;
    const float t297 = t295 + t296;
    const float t298 = t124 * t297;
    const float t299 = t159 * t138;
    const float t300 = t161 * t140;
    const float t301 = t299 + t300;
    const float t302 = t163 * t141;
    const float t303 = t301 + t302;
    const float t304 = t165 * t143;
    const float t305 = t303 + t304;
    const float t306 = t167 * t144;
    const float t307 = t305 + t306;
    const float t308 = t168 * t145;
    const float t309 = t307 + t308;
    const float t310 = t124 * t309;
    const float t311 = fabsf(t261);
    const float t312 = t11 * t311;
    const float t313 = t312 + t14;
    const float t314 = select_float(!(t261 >= t313), t313, t261);
    const float t315 = sqrtf(t314);
    const float t316 = t10 / t315;
    const float t317 = t247 * t316;
    const float t318 = t317 * t317;
    const float t319 = t263 - t318;
    const float t320 = fabsf(t263);
    const float t321 = t11 * t320;
    const float t322 = t321 + t14;
    const float t323 = select_float(!(t319 >= t322), t322, t319);
    const float t324 = sqrtf(t323);
    const float t325 = t10 / t324;
    const float t326 = t177 * t316;
    const float t327 = -t247;
    const float t328 = t317 * t326;
    const float t329 = t327 + t328;
    const float t330 = -t329;
    const float t331 = t330 * t325;
    const float t332 = t331 * t325;
    const float t333 = -t326;
    const float t334 = t317 * t332;
    const float t335 = t333 + t334;
    const float t336 = -t335;
    const float t337 = t336 * t316;
    const float t338 = t274 * t316;
    const float t339 = -t286;
    const float t340 = t317 * t338;
    const float t341 = t339 + t340;
    const float t342 = -t341;
    const float t343 = t342 * t325;
    const float t344 = t343 * t325;
    const float t345 = -t338;
    const float t346 = t317 * t344;
    const float t347 = t345 + t346;
    const float t348 = -t347;
    const float t349 = t348 * t316;
    const float t350 = t298 * t316;
    const float t351 = -t310;
    const float t352 = t317 * t350;
    const float t353 = t351 + t352;
    const float t354 = -t353;
    const float t355 = t354 * t325;
    const float t356 = t355 * t325;
    const float t357 = -t350;
    const float t358 = t317 * t356;
    const float t359 = t357 + t358;
    const float t360 = -t359;
    const float t361 = t360 * t316;
    const float t362 = y[0];
    const float t363 = t362 - t130;
    const float t364 = y[1];
    const float t365 = t364 - t136;
    const float t366 = t337 * t363;
    const float t367 = t130 + t366;
    const float t368 = t332 * t365;
    const float t369 = t367 + t368;
    const float t370 = t349 * t363;
    const float t371 = t151 + t370;
    const float t372 = t344 * t365;
    const float t373 = t371 + t372;
    const float t374 = t361 * t363;
    const float t375 = t157 + t374;
    const float t376 = t356 * t365;
    const float t377 = t375 + t376;
    const float t378 = t363 * t316;
    const float t379 = -t365;
    const float t380 = t317 * t378;
    const float t381 = t379 + t380;
    const float t382 = -t381;
    const float t383 = t382 * t325;
    const float t384 = t378 * t378;
    const float t385 = t383 * t383;
    const float t386 = t384 + t385;
    const float t387 = t177 * t337;
    const float t388 = t247 * t332;
    const float t389 = t387 + t388;
    const float t390 = t177 - t389;
    const float t391 = t177 * t349;
    const float t392 = t247 * t344;
    const float t393 = t391 + t392;
    const float t394 = t188 - t393;
    const float t395 = t177 * t361;
    const float t396 = t247 * t356;
    const float t397 = t395 + t396;
    const float t398 = t200 - t397;
    const float t399 = t274 * t349;
    const float t400 = t286 * t344;
    const float t401 = t399 + t400;
    const float t402 = t211 - t401;
    const float t403 = t274 * t361;
    const float t404 = t286 * t356;
    const float t405 = t403 + t404;
    const float t406 = t223 - t405;
    const float t407 = t298 * t361;
    const float t408 = t310 * t356;
    const float t409 = t407 + t408;
    const float t410 = t235 - t409;
    const float t411 = select_float(!(t369 >= t9), t9, t369);
    const float t412 = select_float(!(t373 >= t9), t9, t373);
    const float t413 = select_float(!(t377 >= t9), t9, t377);
    const float t414 = fabsf(t390);
    const float t415 = t11 * t414;
    const float t416 = t415 + t14;
    const float t417 = select_float(!(t390 >= t416), t416, t390);
    const float t418 = sqrtf(t417);
    const float t419 = t10 / t418;
    const float t420 = t394 * t419;
    const float t421 = t398 * t419;
    const float t422 = t420 * t420;
    const float t423 = t402 - t422;
    const float t424 = fabsf(t402);
    const float t425 = t11 * t424;
    const float t426 = t425 + t14;
    const float t427 = select_float(!(t423 >= t426), t426, t423);
    const float t428 = sqrtf(t427);
    const float t429 = t10 / t428;
    const float t430 = t421 * t420;
    const float t431 = t406 - t430;
    const float t432 = t431 * t429;
    const float t433 = t421 * t421;
    const float t434 = t432 * t432;
    const float t435 = t433 + t434;
    const float t436 = t410 - t435;
    const float t437 = fabsf(t410);
    const float t438 = t11 * t437;
    const float t439 = t438 + t14;
    const float t440 = select_float(!(t436 >= t439), t439, t436);
    const float t441 = sqrtf(t440);
    const float t442 = t41 * t418;
    const float t443 = t411 + t442;
    const float t444 = t41 * t420;
    const float t445 = t412 + t444;
    const float t446 = t41 * t421;
    const float t447 = t413 + t446;
    const float t448 = select_float(!(t443 >= t9), t9, t443);
    const float t449 = select_float(!(t445 >= t9), t9, t445);
    const float t450 = select_float(!(t447 >= t9), t9, t447);
    const float t451 = t41 * t428;
    const float t452 = t412 + t451;
    const float t453 = t41 * t432;
    const float t454 = t413 + t453;
    const float t455 = select_float(!(t411 >= t9), t9, t411);
    const float t456 = select_float(!(t452 >= t9), t9, t452);
    const float t457 = select_float(!(t454 >= t9), t9, t454);
    const float t458 = t41 * t441;
    const float t459 = t413 + t458;
    const float t460 = select_float(!(t412 >= t9), t9, t412);
    const float t461 = select_float(!(t459 >= t9), t9, t459);
    const float t462 = t62 * t418;
    const float t463 = t411 + t462;
    const float t464 = t62 * t420;
    const float t465 = t412 + t464;
    const float t466 = t62 * t421;
    const float t467 = t413 + t466;
    const float t468 = select_float(!(t463 >= t9), t9, t463);
    const float t469 = select_float(!(t465 >= t9), t9, t465);
    const float t470 = select_float(!(t467 >= t9), t9, t467);
    const float t471 = t62 * t428;
    const float t472 = t412 + t471;
    const float t473 = t62 * t432;
    const float t474 = t413 + t473;
    const float t475 = select_float(!(t472 >= t9), t9, t472);
    const float t476 = select_float(!(t474 >= t9), t9, t474);
    const float t477 = t62 * t441;
    const float t478 = t413 + t477;
    const float t479 = select_float(!(t478 >= t9), t9, t478);
    const float t480 = 0.2f;
    const float t481 = 2.0f;
    const float t482 = 6.0f;
    const float t483 = t480 / t481;
    const float t484 = t480 / t482;
    const float t485 = t82 + t449;
    const float t486 = t449 / t485;
    const float t487 = t81 * t486;
    const float t488 = 0.1f /* k_d */;
    const float t489 = 0.5f /* k_p */;
    const float t490 = -t489;
    const float t491 = 0.001f;
    const float t492 = fmaxf(t450, t491);
    const float t493 = t490 / t492;
    const float t494 = libm_expf(t493);
    const float t495 = t488 * t494;
    const float t496 = t487 * t448;
    const float t497 = t495 * t448;
    const float t498 = t496 - t497;
    const float t499 = 1.0f /* y_s */;
    const float t500 = t499 * t487;
    const float t501 = t500 * t448;
    const float t502 = -t501;
    const float t503 = 0.05f /* k_m */;
    const float t504 = t503 * t448;
    const float t505 = 0.01f /* ks_m */;
    const float t506 = t449 + t505;
    const float t507 = t449 / t506;
    const float t508 = t504 * t507;
    const float t509 = t502 - t508;
    const float t510 = 0.2f /* y_p */;
    const float t511 = t510 * t487;
    const float t512 = 0.5f /* k_I */;
    const float t513 = t88 + t512;
    const float t514 = t88 / t513;
    const float t515 = t511 * t514;
    const float t516 = t515 * t448;
    const float t517 = t495 * t450;
    const float t518 = t516 - t517;
    const float t519 = t483 * t498;
    const float t520 = t448 + t519;
    const float t521 = t483 * t509;
    const float t522 = t449 + t521;
    const float t523 = t483 * t518;
    const float t524 = t450 + t523;
    const float t525 = t82 + t522;
    const float t526 = t522 / t525;
    const float t527 = t81 * t526;
    const float t528 = fmaxf(t524, t491);
    const float t529 = t490 / t528;
    const float t530 = libm_expf(t529);
    const float t531 = t488 * t530;
    const float t532 = t527 * t520;
    const float t533 = t531 * t520;
    const float t534 = t532 - t533;
    const float t535 = t499 * t527;
    const float t536 = t535 * t520;
    const float t537 = -t536;
    const float t538 = t503 * t520;
    const float t539 = t522 + t505;
    const float t540 = t522 / t539;
    const float t541 = t538 * t540;
    const float t542 = t537 - t541;
    const float t543 = t510 * t527;
    const float t544 = t543 * t514;
    const float t545 = t544 * t520;
    const float t546 = t531 * t524;
    const float t547 = t545 - t546;
    const float t548 = t483 * t534;
    const float t549 = t448 + t548;
    const float t550 = t483 * t542;
    const float t551 = t449 + t550;
    const float t552 = t483 * t547;
    const float t553 = t450 + t552;
    const float t554 = t82 + t551;
    const float t555 = t551 / t554;
    const float t556 = t81 * t555;
    const float t557 = fmaxf(t553, t491);
    const float t558 = t490 / t557;
    const float t559 = libm_expf(t558);
    const float t560 = t488 * t559;
    const float t561 = t556 * t549;
    const float t562 = t560 * t549;
    const float t563 = t561 - t562;
    const float t564 = t499 * t556;
    const float t565 = t564 * t549;
    const float t566 = -t565;
    const float t567 = t503 * t549;
    const float t568 = t551 + t505;
    const float t569 = t551 / t568;
    const float t570 = t567 * t569;
    const float t571 = t566 - t570;
    const float t572 = t510 * t556;
    const float t573 = t572 * t514;
    const float t574 = t573 * t549;
    const float t575 = t560 * t553;
    const float t576 = t574 - t575;
    const float t577 = t480 * t563;
    const float t578 = t448 + t577;
    const float t579 = t480 * t571;
    const float t580 = t449 + t579;
    const float t581 = t480 * t576;
    const float t582 = t450 + t581;
    const float t583 = t82 + t580;
    const float t584 = t580 / t583;
    const float t585 = t81 * t584;
    const float t586 = fmaxf(t582, t491);
    const float t587 = t490 / t586;
    const float t588 = libm_expf(t587);
    const float t589 = t488 * t588;
    const float t590 = t585 * t578;
    const float t591 = t589 * t578;
    const float t592 = t590 - t591;
    const float t593 = t499 * t585;
    const float t594 = t593 * t578;
    const float t595 = -t594;
    const float t596 = t503 * t578;
    const float t597 = t580 + t505;
    const float t598 = t580 / t597;
    const float t599 = t596 * t598;
    const float t600 = t595 - t599;
    const float t601 = t510 * t585;
    const float t602 = t601 * t514;
    const float t603 = t602 * t578;
    const float t604 = t589 * t582;
    const float t605 = t603 - t604;
    const float t606 = t534 + t563;
    const float t607 = t481 * t606;
    const float t608 = t498 + t607;
    const float t609 = t608 + t592;
    const float t610 = t484 * t609;
    const float t611 = t448 + t610;
    const float t612 = t542 + t571;
    const float t613 = t481 * t612;
    const float t614 = t509 + t613;
    const float t615 = t614 + t600;
    const float t616 = t484 * t615;
    const float t617 = t449 + t616;
    const float t618 = t547 + t576;
    const float t619 = t481 * t618;
    const float t620 = t518 + t619;
    const float t621 = t620 + t605;
    const float t622 = t484 * t621;
    const float t623 = t450 + t622;
    const float t624 = t82 + t456;
    const float t625 = t456 / t624;
    const float t626 = t81 * t625;
    const float t627 = fmaxf(t457, t491);
    const float t628 = t490 / t627;
    const float t629 = libm_expf(t628);
    const float t630 = t488 * t629;
    const float t631 = t626 * t455;
    const float t632 = t630 * t455;
    const float t633 = t631 - t632;
    const float t634 = t499 * t626;
    const float t635 = t634 * t455;
    const float t636 = -t635;
    const float t637 = t503 * t455;
    const float t638 = t456 + t505;
    const float t639 = t456 / t638;
    const float t640 = t637 * t639;
    const float t641 = t636 - t640;
    const float t642 = t510 * t626;
    const float t643 = t642 * t514;
    const float t644 = t643 * t455;
    const float t645 = t630 * t457;
    const float t646 = t644 - t645;
    const float t647 = t483 * t633;
    const float t648 = t455 + t647;
    const float t649 = t483 * t641;
    const float t650 = t456 + t649;
    const float t651 = t483 * t646;
    const float t652 = t457 + t651;
    const float t653 = t82 + t650;
    const float t654 = t650 / t653;
    const float t655 = t81 * t654;
    const float t656 = fmaxf(t652, t491);
    const float t657 = t490 / t656;
    const float t658 = libm_expf(t657);
    const float t659 = t488 * t658;
    const float t660 = t655 * t648;
    const float t661 = t659 * t648;
    const float t662 = t660 - t661;
    const float t663 = t499 * t655;
    const float t664 = t663 * t648;
    const float t665 = -t664;
    const float t666 = t503 * t648;
    const float t667 = t650 + t505;
    const float t668 = t650 / t667;
    const float t669 = t666 * t668;
    const float t670 = t665 - t669;
    const float t671 = t510 * t655;
    const float t672 = t671 * t514;
    const float t673 = t672 * t648;
    const float t674 = t659 * t652;
    const float t675 = t673 - t674;
    const float t676 = t483 * t662;
    const float t677 = t455 + t676;
    const float t678 = t483 * t670;
    const float t679 = t456 + t678;
    const float t680 = t483 * t675;
    const float t681 = t457 + t680;
    const float t682 = t82 + t679;
    const float t683 = t679 / t682;
    const float t684 = t81 * t683;
    const float t685 = fmaxf(t681, t491);
    const float t686 = t490 / t685;
    const float t687 = libm_expf(t686);
    const float t688 = t488 * t687;
    const float t689 = t684 * t677;
    const float t690 = t688 * t677;
    const float t691 = t689 - t690;
    const float t692 = t499 * t684;
    const float t693 = t692 * t677;
    const float t694 = -t693;
    const float t695 = t503 * t677;
    const float t696 = t679 + t505;
    const float t697 = t679 / t696;
    const float t698 = t695 * t697;
    const float t699 = t694 - t698;
    const float t700 = t510 * t684;
    const float t701 = t700 * t514;
    const float t702 = t701 * t677;
    const float t703 = t688 * t681;
    const float t704 = t702 - t703;
    const float t705 = t480 * t691;
    const float t706 = t455 + t705;
    const float t707 = t480 * t699;
    const float t708 = t456 + t707;
    const float t709 = t480 * t704;
    const float t710 = t457 + t709;
    const float t711 = t82 + t708;
    const float t712 = t708 / t711;
    const float t713 = t81 * t712;
    const float t714 = fmaxf(t710, t491);
    const float t715 = t490 / t714;
    const float t716 = libm_expf(t715);
    const float t717 = t488 * t716;
    const float t718 = t713 * t706;
    const float t719 = t717 * t706;
    const float t720 = t718 - t719;
    const float t721 = t499 * t713;
    const float t722 = t721 * t706;
    const float t723 = -t722;
    const float t724 = t503 * t706;
    const float t725 = t708 + t505;
    const float t726 = t708 / t725;
    const float t727 = t724 * t726;
    const float t728 = t723 - t727;
    const float t729 = t510 * t713;
    const float t730 = t729 * t514;
    const float t731 = t730 * t706;
    const float t732 = t717 * t710;
    const float t733 = t731 - t732;
    const float t734 = t662 + t691;
    const float t735 = t481 * t734;
    const float t736 = t633 + t735;
    const float t737 = t736 + t720;
    const float t738 = t484 * t737;
    const float t739 = t455 + t738;
    const float t740 = t670 + t699;
    const float t741 = t481 * t740;
    const float t742 = t641 + t741;
    const float t743 = t742 + t728;
    const float t744 = t484 * t743;
    const float t745 = t456 + t744;
    const float t746 = t675 + t704;
    const float t747 = t481 * t746;
    const float t748 = t646 + t747;
    const float t749 = t748 + t733;
    const float t750 = t484 * t749;
    const float t751 = t457 + t750;
    const float t752 = t82 + t460;
    const float t753 = t460 / t752;
    const float t754 = t81 * t753;
    const float t755 = fmaxf(t461, t491);
    const float t756 = t490 / t755;
    const float t757 = libm_expf(t756);
    const float t758 = t488 * t757;
    const float t759 = t754 * t455;
    const float t760 = t758 * t455;
    const float t761 = t759 - t760;
    const float t762 = t499 * t754;
    const float t763 = t762 * t455;
    const float t764 = -t763;
    const float t765 = t460 + t505;
    const float t766 = t460 / t765;
    const float t767 = t637 * t766;
    const float t768 = t764 - t767;
    const float t769 = t510 * t754;
    const float t770 = t769 * t514;
    const float t771 = t770 * t455;
    const float t772 = t758 * t461;
    const float t773 = t771 - t772;
    const float t774 = t483 * t761;
    const float t775 = t455 + t774;
    const float t776 = t483 * t768;
    const float t777 = t460 + t776;
    const float t778 = t483 * t773;
    const float t779 = t461 + t778;
    const float t780 = t82 + t777;
    const float t781 = t777 / t780;
    const float t782 = t81 * t781;
    const float t783 = fmaxf(t779, t491);
    const float t784 = t490 / t783;
    const float t785 = libm_expf(t784);
    const float t786 = t488 * t785;
    const float t787 = t782 * t775;
    const float t788 = t786 * t775;
    const float t789 = t787 - t788;
    const float t790 = t499 * t782;
    const float t791 = t790 * t775;
    const float t792 = -t791;
    const float t793 = t503 * t775;
    const float t794 = t777 + t505;
    const float t795 = t777 / t794;
    const float t796 = t793 * t795;
    const float t797 = t792 - t796;
    const float t798 = t510 * t782;
    const float t799 = t798 * t514;
    const float t800 = t799 * t775;
    const float t801 = t786 * t779;
    const float t802 = t800 - t801;
    const float t803 = t483 * t789;
    const float t804 = t455 + t803;
    const float t805 = t483 * t797;
    const float t806 = t460 + t805;
    const float t807 = t483 * t802;
    const float t808 = t461 + t807;
    const float t809 = t82 + t806;
    const float t810 = t806 / t809;
    const float t811 = t81 * t810;
    const float t812 = fmaxf(t808, t491);
    const float t813 = t490 / t812;
    const float t814 = libm_expf(t813);
    const float t815 = t488 * t814;
    const float t816 = t811 * t804;
    const float t817 = t815 * t804;
    const float t818 = t816 - t817;
    const float t819 = t499 * t811;
    const float t820 = t819 * t804;
    const float t821 = -t820;
    const float t822 = t503 * t804;
    const float t823 = t806 + t505;
    const float t824 = t806 / t823;
    const float t825 = t822 * t824;
    const float t826 = t821 - t825;
    const float t827 = t510 * t811;
    const float t828 = t827 * t514;
    const float t829 = t828 * t804;
    const float t830 = t815 * t808;
    const float t831 = t829 - t830;
    const float t832 = t480 * t818;
    const float t833 = t455 + t832;
    const float t834 = t480 * t826;
    const float t835 = t460 + t834;
    const float t836 = t480 * t831;
    const float t837 = t461 + t836;
    const float t838 = t82 + t835;
    const float t839 = t835 / t838;
    const float t840 = t81 * t839;
    const float t841 = fmaxf(t837, t491);
    const float t842 = t490 / t841;
    const float t843 = libm_expf(t842);
    const float t844 = t488 * t843;
    const float t845 = t840 * t833;
    const float t846 = t844 * t833;
    const float t847 = t845 - t846;
    const float t848 = t499 * t840;
    const float t849 = t848 * t833;
    const float t850 = -t849;
    const float t851 = t503 * t833;
    const float t852 = t835 + t505;
    const float t853 = t835 / t852;
    const float t854 = t851 * t853;
    const float t855 = t850 - t854;
    const float t856 = t510 * t840;
    const float t857 = t856 * t514;
    const float t858 = t857 * t833;
    const float t859 = t844 * t837;
    const float t860 = t858 - t859;
    const float t861 = t789 + t818;
    const float t862 = t481 * t861;
    const float t863 = t761 + t862;
    const float t864 = t863 + t847;
    const float t865 = t484 * t864;
    const float t866 = t455 + t865;
    const float t867 = t797 + t826;
    const float t868 = t481 * t867;
    const float t869 = t768 + t868;
    const float t870 = t869 + t855;
    const float t871 = t484 * t870;
    const float t872 = t460 + t871;
    const float t873 = t802 + t831;
    const float t874 = t481 * t873;
    const float t875 = t773 + t874;
    const float t876 = t875 + t860;
    const float t877 = t484 * t876;
    const float t878 = t461 + t877;
    const float t879 = t82 + t469;
    const float t880 = t469 / t879;
    const float t881 = t81 * t880;
    const float t882 = fmaxf(t470, t491);
    const float t883 = t490 / t882;
    const float t884 = libm_expf(t883);
    const float t885 = t488 * t884;
    const float t886 = t881 * t468;
    const float t887 = t885 * t468;
    const float t888 = t886 - t887;
    const float t889 = t499 * t881;
    const float t890 = t889 * t468;
    const float t891 = -t890;
    const float t892 = t503 * t468;
    const float t893 = t469 + t505;
    const float t894 = t469 / t893;
    const float t895 = t892 * t894;
    const float t896 = t891 - t895;
    const float t897 = t510 * t881;
    const float t898 = t897 * t514;
    const float t899 = t898 * t468;
    const float t900 = t885 * t470;
    const float t901 = t899 - t900;
    const float t902 = t483 * t888;
    const float t903 = t468 + t902;
    const float t904 = t483 * t896;
    const float t905 = t469 + t904;
    const float t906 = t483 * t901;
    const float t907 = t470 + t906;
    const float t908 = t82 + t905;
    const float t909 = t905 / t908;
    const float t910 = t81 * t909;
    const float t911 = fmaxf(t907, t491);
    const float t912 = t490 / t911;
    const float t913 = libm_expf(t912);
    const float t914 = t488 * t913;
    const float t915 = t910 * t903;
    const float t916 = t914 * t903;
    const float t917 = t915 - t916;
    const float t918 = t499 * t910;
    const float t919 = t918 * t903;
    const float t920 = -t919;
    const float t921 = t503 * t903;
    const float t922 = t905 + t505;
    const float t923 = t905 / t922;
    const float t924 = t921 * t923;
    const float t925 = t920 - t924;
    const float t926 = t510 * t910;
    const float t927 = t926 * t514;
    const float t928 = t927 * t903;
    const float t929 = t914 * t907;
    const float t930 = t928 - t929;
    const float t931 = t483 * t917;
    const float t932 = t468 + t931;
    const float t933 = t483 * t925;
    const float t934 = t469 + t933;
    const float t935 = t483 * t930;
    const float t936 = t470 + t935;
    const float t937 = t82 + t934;
    const float t938 = t934 / t937;
    const float t939 = t81 * t938;
    const float t940 = fmaxf(t936, t491);
    const float t941 = t490 / t940;
    const float t942 = libm_expf(t941);
    const float t943 = t488 * t942;
    const float t944 = t939 * t932;
    const float t945 = t943 * t932;
    const float t946 = t944 - t945;
    const float t947 = t499 * t939;
    const float t948 = t947 * t932;
    const float t949 = -t948;
    const float t950 = t503 * t932;
    const float t951 = t934 + t505;
    const float t952 = t934 / t951;
    const float t953 = t950 * t952;
    const float t954 = t949 - t953;
    const float t955 = t510 * t939;
    const float t956 = t955 * t514;
    const float t957 = t956 * t932;
    const float t958 = t943 * t936;
    const float t959 = t957 - t958;
    const float t960 = t480 * t946;
    const float t961 = t468 + t960;
    const float t962 = t480 * t954;
    const float t963 = t469 + t962;
    const float t964 = t480 * t959;
    const float t965 = t470 + t964;
    const float t966 = t82 + t963;
    const float t967 = t963 / t966;
    const float t968 = t81 * t967;
    const float t969 = fmaxf(t965, t491);
    const float t970 = t490 / t969;
    const float t971 = libm_expf(t970);
    const float t972 = t488 * t971;
    const float t973 = t968 * t961;
    const float t974 = t972 * t961;
    const float t975 = t973 - t974;
    const float t976 = t499 * t968;
    const float t977 = t976 * t961;
    const float t978 = -t977;
    const float t979 = t503 * t961;
    const float t980 = t963 + t505;
    const float t981 = t963 / t980;
    const float t982 = t979 * t981;
    const float t983 = t978 - t982;
    const float t984 = t510 * t968;
    const float t985 = t984 * t514;
    const float t986 = t985 * t961;
    const float t987 = t972 * t965;
    const float t988 = t986 - t987;
    const float t989 = t917 + t946;
    const float t990 = t481 * t989;
    const float t991 = t888 + t990;
    const float t992 = t991 + t975;
    const float t993 = t484 * t992;
    const float t994 = t468 + t993;
    const float t995 = t925 + t954;
    const float t996 = t481 * t995;
    const float t997 = t896 + t996;
    const float t998 = t997 + t983;
    const float t999 = t484 * t998;
    const float t1000 = t469 + t999;
    const float t1001 = t930 + t959;
    const float t1002 = t481 * t1001;
    const float t1003 = t901 + t1002;
    const float t1004 = t1003 + t988;
    const float t1005 = t484 * t1004;
    const float t1006 = t470 + t1005;
    const float t1007 = t82 + t475;
    const float t1008 = t475 / t1007;
    const float t1009 = t81 * t1008;
    const float t1010 = fmaxf(t476, t491);
    const float t1011 = t490 / t1010;
    const float t1012 = libm_expf(t1011);
    const float t1013 = t488 * t1012;
    const float t1014 = t1009 * t455;
    const float t1015 = t1013 * t455;
    const float t1016 = t1014 - t1015;
    const float t1017 = t499 * t1009;
    const float t1018 = t1017 * t455;
    const float t1019 = -t1018;
    const float t1020 = t475 + t505;
    const float t1021 = t475 / t1020;
    const float t1022 = t637 * t1021;
    const float t1023 = t1019 - t1022;
    const float t1024 = t510 * t1009;
    const float t1025 = t1024 * t514;
    const float t1026 = t1025 * t455;
    const float t1027 = t1013 * t476;
    const float t1028 = t1026 - t1027;
    const float t1029 = t483 * t1016;
    const float t1030 = t455 + t1029;
    const float t1031 = t483 * t1023;
    const float t1032 = t475 + t1031;
    const float t1033 = t483 * t1028;
    const float t1034 = t476 + t1033;
    const float t1035 = t82 + t1032;
    const float t1036 = t1032 / t1035;
    const float t1037 = t81 * t1036;
    const float t1038 = fmaxf(t1034, t491);
    const float t1039 = t490 / t1038;
    const float t1040 = libm_expf(t1039);
    const float t1041 = t488 * t1040;
    const float t1042 = t1037 * t1030;
    const float t1043 = t1041 * t1030;
    const float t1044 = t1042 - t1043;
    const float t1045 = t499 * t1037;
    const float t1046 = t1045 * t1030;
    const float t1047 = -t1046;
    const float t1048 = t503 * t1030;
    const float t1049 = t1032 + t505;
    const float t1050 = t1032 / t1049;
    const float t1051 = t1048 * t1050;
    const float t1052 = t1047 - t1051;
    const float t1053 = t510 * t1037;
    const float t1054 = t1053 * t514;
    const float t1055 = t1054 * t1030;
    const float t1056 = t1041 * t1034;
    const float t1057 = t1055 - t1056;
    const float t1058 = t483 * t1044;
    const float t1059 = t455 + t1058;
    const float t1060 = t483 * t1052;
    const float t1061 = t475 + t1060;
    const float t1062 = t483 * t1057;
    const float t1063 = t476 + t1062;
    const float t1064 = t82 + t1061;
    const float t1065 = t1061 / t1064;
    const float t1066 = t81 * t1065;
    const float t1067 = fmaxf(t1063, t491);
    const float t1068 = t490 / t1067;
    const float t1069 = libm_expf(t1068);
    const float t1070 = t488 * t1069;
    const float t1071 = t1066 * t1059;
    const float t1072 = t1070 * t1059;
    const float t1073 = t1071 - t1072;
    const float t1074 = t499 * t1066;
    const float t1075 = t1074 * t1059;
    const float t1076 = -t1075;
    const float t1077 = t503 * t1059;
    const float t1078 = t1061 + t505;
    const float t1079 = t1061 / t1078;
    const float t1080 = t1077 * t1079;
    const float t1081 = t1076 - t1080;
    const float t1082 = t510 * t1066;
    const float t1083 = t1082 * t514;
    const float t1084 = t1083 * t1059;
    const float t1085 = t1070 * t1063;
    const float t1086 = t1084 - t1085;
    const float t1087 = t480 * t1073;
    const float t1088 = t455 + t1087;
    const float t1089 = t480 * t1081;
    const float t1090 = t475 + t1089;
    const float t1091 = t480 * t1086;
    const float t1092 = t476 + t1091;
    const float t1093 = t82 + t1090;
    const float t1094 = t1090 / t1093;
    const float t1095 = t81 * t1094;
    const float t1096 = fmaxf(t1092, t491);
    const float t1097 = t490 / t1096;
    const float t1098 = libm_expf(t1097);
    const float t1099 = t488 * t1098;
    const float t1100 = t1095 * t1088;
    const float t1101 = t1099 * t1088;
    const float t1102 = t1100 - t1101;
    const float t1103 = t499 * t1095;
    const float t1104 = t1103 * t1088;
    const float t1105 = -t1104;
    const float t1106 = t503 * t1088;
    const float t1107 = t1090 + t505;
    const float t1108 = t1090 / t1107;
    const float t1109 = t1106 * t1108;
    const float t1110 = t1105 - t1109;
    const float t1111 = t510 * t1095;
    const float t1112 = t1111 * t514;
    const float t1113 = t1112 * t1088;
    const float t1114 = t1099 * t1092;
    const float t1115 = t1113 - t1114;
    const float t1116 = t1044 + t1073;
    const float t1117 = t481 * t1116;
    const float t1118 = t1016 + t1117;
    const float t1119 = t1118 + t1102;
    const float t1120 = t484 * t1119;
    const float t1121 = t455 + t1120;
    const float t1122 = t1052 + t1081;
    const float t1123 = t481 * t1122;
    const float t1124 = t1023 + t1123;
    const float t1125 = t1124 + t1110;
    const float t1126 = t484 * t1125;
    const float t1127 = t475 + t1126;
    const float t1128 = t1057 + t1086;
    const float t1129 = t481 * t1128;
    const float t1130 = t1028 + t1129;
    const float t1131 = t1130 + t1115;
    const float t1132 = t484 * t1131;
    const float t1133 = t476 + t1132;
    const float t1134 = fmaxf(t479, t491);
    const float t1135 = t490 / t1134;
    const float t1136 = libm_expf(t1135);
    const float t1137 = t488 * t1136;
    const float t1138 = t1137 * t455;
    const float t1139 = t759 - t1138;
    const float t1140 = t1137 * t479;
    const float t1141 = t771 - t1140;
    const float t1142 = t483 * t1139;
    const float t1143 = t455 + t1142;
    const float t1144 = t483 * t1141;
    const float t1145 = t479 + t1144;
    const float t1146 = fmaxf(t1145, t491);
    const float t1147 = t490 / t1146;
    const float t1148 = libm_expf(t1147);
    const float t1149 = t488 * t1148;
    const float t1150 = t782 * t1143;
    const float t1151 = t1149 * t1143;
    const float t1152 = t1150 - t1151;
    const float t1153 = t790 * t1143;
    const float t1154 = -t1153;
    const float t1155 = t503 * t1143;
    const float t1156 = t1155 * t795;
    const float t1157 = t1154 - t1156;
    const float t1158 = t799 * t1143;
    const float t1159 = t1149 * t1145;
    const float t1160 = t1158 - t1159;
    const float t1161 = t483 * t1152;
    const float t1162 = t455 + t1161;
    const float t1163 = t483 * t1157;
    const float t1164 = t460 + t1163;
    const float t1165 = t483 * t1160;
    const float t1166 = t479 + t1165;
    const float t1167 = t82 + t1164;
    const float t1168 = t1164 / t1167;
    const float t1169 = t81 * t1168;
    const float t1170 = fmaxf(t1166, t491);
    const float t1171 = t490 / t1170;
    const float t1172 = libm_expf(t1171);
    const float t1173 = t488 * t1172;
    const float t1174 = t1169 * t1162;
    const float t1175 = t1173 * t1162;
    const float t1176 = t1174 - t1175;
    const float t1177 = t499 * t1169;
    const float t1178 = t1177 * t1162;
    const float t1179 = -t1178;
    const float t1180 = t503 * t1162;
    const float t1181 = t1164 + t505;
    const float t1182 = t1164 / t1181;
    const float t1183 = t1180 * t1182;
    const float t1184 = t1179 - t1183;
    const float t1185 = t510 * t1169;
    const float t1186 = t1185 * t514;
    const float t1187 = t1186 * t1162;
    const float t1188 = t1173 * t1166;
    const float t1189 = t1187 - t1188;
    const float t1190 = t480 * t1176;
    const float t1191 = t455 + t1190;
    const float t1192 = t480 * t1184;
    const float t1193 = t460 + t1192;
    const float t1194 = t480 * t1189;
    const float t1195 = t479 + t1194;
    const float t1196 = t82 + t1193;
    const float t1197 = t1193 / t1196;
    const float t1198 = t81 * t1197;
    const float t1199 = fmaxf(t1195, t491);
    const float t1200 = t490 / t1199;
    const float t1201 = libm_expf(t1200);
    const float t1202 = t488 * t1201;
    const float t1203 = t1198 * t1191;
    const float t1204 = t1202 * t1191;
    const float t1205 = t1203 - t1204;
    const float t1206 = t499 * t1198;
    const float t1207 = t1206 * t1191;
    const float t1208 = -t1207;
    const float t1209 = t503 * t1191;
    const float t1210 = t1193 + t505;
    const float t1211 = t1193 / t1210;
    const float t1212 = t1209 * t1211;
    const float t1213 = t1208 - t1212;
    const float t1214 = t510 * t1198;
    const float t1215 = t1214 * t514;
    const float t1216 = t1215 * t1191;
    const float t1217 = t1202 * t1195;
    const float t1218 = t1216 - t1217;
    const float t1219 = t1152 + t1176;
    const float t1220 = t481 * t1219;
    const float t1221 = t1139 + t1220;
    const float t1222 = t1221 + t1205;
    const float t1223 = t484 * t1222;
    const float t1224 = t455 + t1223;
    const float t1225 = t1157 + t1184;
    const float t1226 = t481 * t1225;
    const float t1227 = t768 + t1226;
    const float t1228 = t1227 + t1213;
    const float t1229 = t484 * t1228;
    const float t1230 = t460 + t1229;
    const float t1231 = t1160 + t1189;
    const float t1232 = t481 * t1231;
    const float t1233 = t1141 + t1232;
    const float t1234 = t1233 + t1218;
    const float t1235 = t484 * t1234;
    const float t1236 = t479 + t1235;
    const float t1237 = t611 + t739;
    const float t1238 = t1237 + t866;
    const float t1239 = t1238 + t994;
    const float t1240 = t1239 + t1121;
    const float t1241 = t1240 + t1224;
    const float t1242 = t124 * t1241;
    const float t1243 = t617 + t745;
    const float t1244 = t1243 + t872;
    const float t1245 = t1244 + t1000;
    const float t1246 = t1245 + t1127;
    const float t1247 = t1246 + t1230;
    const float t1248 = t124 * t1247;
    const float t1249 = t623 + t751;
    const float t1250 = t1249 + t878;
    const float t1251 = t1250 + t1006;
    const float t1252 = t1251 + t1133;
    const float t1253 = t1252 + t1236;
    const float t1254 = t124 * t1253;
    const float t1255 = t611 - t1242;
    const float t1256 = t617 - t1248;
    const float t1257 = t623 - t1254;
    const float t1258 = t739 - t1242;
    const float t1259 = t745 - t1248;
    const float t1260 = t751 - t1254;
    const float t1261 = t866 - t1242;
    const float t1262 = t872 - t1248;
    const float t1263 = t878 - t1254;
    const float t1264 = t994 - t1242;
    const float t1265 = t1000 - t1248;
    const float t1266 = t1006 - t1254;
    const float t1267 = t1121 - t1242;
    const float t1268 = t1127 - t1248;
    const float t1269 = t1133 - t1254;
    const float t1270 = t1224 - t1242;
    const float t1271 = t1230 - t1248;
    const float t1272 = t1236 - t1254;
    const float t1273 = t1255 * t1255;
    const float t1274 = t1258 * t1258;
    const float t1275 = t1273 + t1274;
    const float t1276 = t1261 * t1261;
    const float t1277 = t1275 + t1276;
    const float t1278 = t1264 * t1264;
    const float t1279 = t1277 + t1278;
    const float t1280 = t1267 * t1267;
    const float t1281 = t1279 + t1280;
    const float t1282 = t1270 * t1270;
    const float t1283 = t1281 + t1282;
    const float t1284 = t124 * t1283;
    const float t1285 = t1255 * t1256;
    const float t1286 = t1258 * t1259;
    const float t1287 = t1285 + t1286;
    const float t1288 = t1261 * t1262;
    const float t1289 = t1287 + t1288;
    const float t1290 = t1264 * t1265;
    const float t1291 = t1289 + t1290;
    const float t1292 = t1267 * t1268;
    const float t1293 = t1291 + t1292;
    const float t1294 = t1270 * t1271;
    const float t1295 = t1293 + t1294;
    const float t1296 = t124 * t1295;
    const float t1297 = t1255 * t1257;
    const float t1298 = t1258 * t1260;
    const float t1299 = t1297 + t1298;
    const float t1300 = t1261 * t1263;
    const float t1301 = t1299 + t1300;
    const float t1302 = t1264 * t1266;
    const float t1303 = t1301 + t1302;
    const float t1304 = t1267 * t1269;
    const float t1305 = t1303 + t1304;
    const float t1306 = t1270 * t1272;
    const float t1307 = t1305 + t1306;
    const float t1308 = t124 * t1307;
    const float t1309 = t1256 * t1256;
    const float t1310 = t1259 * t1259;
    const float t1311 = t1309 + t1310;
    const float t1312 = t1262 * t1262;
    const float t1313 = t1311 + t1312;
    const float t1314 = t1265 * t1265;
    const float t1315 = t1313 + t1314;
    const float t1316 = t1268 * t1268;
    const float t1317 = t1315 + t1316;
    const float t1318 = t1271 * t1271;
    const float t1319 = t1317 + t1318;
    const float t1320 = t124 * t1319;
    const float t1321 = t1256 * t1257;
    const float t1322 = t1259 * t1260;
    const float t1323 = t1321 + t1322;
    const float t1324 = t1262 * t1263;
    const float t1325 = t1323 + t1324;
    const float t1326 = t1265 * t1266;
    const float t1327 = t1325 + t1326;
    const float t1328 = t1268 * t1269;
    const float t1329 = t1327 + t1328;
    const float t1330 = t1271 * t1272;
    const float t1331 = t1329 + t1330;
    const float t1332 = t124 * t1331;
    const float t1333 = t1257 * t1257;
    const float t1334 = t1260 * t1260;
    const float t1335 = t1333 + t1334;
    const float t1336 = t1263 * t1263;
    const float t1337 = t1335 + t1336;
    const float t1338 = t1266 * t1266;
    const float t1339 = t1337 + t1338;
    const float t1340 = t1269 * t1269;
    const float t1341 = t1339 + t1340;
    const float t1342 = t1272 * t1272;
    const float t1343 = t1341 + t1342;
    const float t1344 = t124 * t1343;
    const float t1345 = 0.0010809527f;
    const float t1346 = t1284 + t1345;
    const float t1347 = 0.0022970699f;
    const float t1348 = t1320 + t1347;
    const float t1349 = 1.6450299e-8f;
    const float t1350 = t1344 + t1349;
    const float t1351 = select_float(!(t1242 >= t9), t9, t1242);
    const float t1352 = select_float(!(t1248 >= t9), t9, t1248);
    const float t1353 = select_float(!(t1254 >= t9), t9, t1254);
    out[0] = t411;
    out[1] = t412;
    out[2] = t413;
    out[3] = t1351;
    out[4] = t1352;
    out[5] = t1353;
    out[6] = t1346;
    out[7] = t1296;
    out[8] = t1308;
    out[9] = t1348;
    out[10] = t1332;
    out[11] = t1350;
    out[12] = t386;
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
    const float t48 = select_float(!(t43 >= t9), t9, t43);
    const float t49 = select_float(!(t45 >= t9), t9, t45);
    const float t50 = select_float(!(t47 >= t9), t9, t47);
    const float t51 = t41 * t27;
    const float t52 = t1 + t51;
    const float t53 = t41 * t31;
    const float t54 = t2 + t53;
    const float t55 = select_float(!(t0 >= t9), t9, t0);
    const float t56 = select_float(!(t52 >= t9), t9, t52);
    const float t57 = select_float(!(t54 >= t9), t9, t54);
    const float t58 = t41 * t40;
    const float t59 = t2 + t58;
    const float t60 = select_float(!(t1 >= t9), t9, t1);
    const float t61 = select_float(!(t59 >= t9), t9, t59);
    const float t62 = -1.7320508f;
    const float t63 = t62 * t17;
    const float t64 = t0 + t63;
    const float t65 = t62 * t19;
    const float t66 = t1 + t65;
    const float t67 = t62 * t20;
    const float t68 = t2 + t67;
    const float t69 = select_float(!(t64 >= t9), t9, t64);
    const float t70 = select_float(!(t66 >= t9), t9, t66);
    const float t71 = select_float(!(t68 >= t9), t9, t68);
    const float t72 = t62 * t27;
    const float t73 = t1 + t72;
    const float t74 = t62 * t31;
    const float t75 = t2 + t74;
    const float t76 = select_float(!(t73 >= t9), t9, t73);
    const float t77 = select_float(!(t75 >= t9), t9, t75);
    const float t78 = t62 * t40;
    const float t79 = t2 + t78;
    const float t80 = select_float(!(t79 >= t9), t9, t79);
    const float t81 = 0.2f;
    const float t82 = 2.0f;
    const float t83 = 6.0f;
    const float t84 = t81 / t82;
    const float t85 = t81 / t83;
    const float t86 = 0.2f /* mu_m */;
    const float t87 = 0.1f /* k_s */;
    const float t88 = t87 + t49;
    const float t89 = t49 / t88;
    const float t90 = t86 * t89;
    const float t91 = 0.1f /* k_d */;
    const float t92 = 0.5f /* k_p */;
    const float t93 = -t92;
    const float t94 = 0.001f;
    const float t95 = fmaxf(t50, t94);
    const float t96 = t93 / t95;
    const float t97 = libm_expf(t96);
    const float t98 = t91 * t97;
    const float t99 = t90 * t48;
    const float t100 = t98 * t48;
    const float t101 = t99 - t100;
    const float t102 = 1.0f /* y_s */;
    const float t103 = t102 * t90;
    const float t104 = t103 * t48;
    const float t105 = -t104;
    const float t106 = 0.05f /* k_m */;
    const float t107 = t106 * t48;
    const float t108 = 0.01f /* ks_m */;
    const float t109 = t49 + t108;
    const float t110 = t49 / t109;
    const float t111 = t107 * t110;
    const float t112 = t105 - t111;
    const float t113 = 0.2f /* y_p */;
    const float t114 = t113 * t90;
    const float t115 = 1.0f /* I */;
    const float t116 = 0.5f /* k_I */;
    const float t117 = t115 + t116;
    const float t118 = t115 / t117;
    const float t119 = t114 * t118;
    const float t120 = t119 * t48;
    const float t121 = t98 * t50;
    const float t122 = t120 - t121;
    const float t123 = t84 * t101;
    const float t124 = t48 + t123;
    const float t125 = t84 * t112;
    const float t126 = t49 + t125;
    const float t127 = t84 * t122;
    const float t128 = t50 + t127;
    const float t129 = t87 + t126;
    const float t130 = t126 / t129;
    const float t131 = t86 * t130;
    const float t132 = fmaxf(t128, t94);
    const float t133 = t93 / t132;
    const float t134 = libm_expf(t133);
    const float t135 = t91 * t134;
    const float t136 = t131 * t124;
    const float t137 = t135 * t124;
    const float t138 = t136 - t137;
    const float t139 = t102 * t131;
    const float t140 = t139 * t124;
    const float t141 = -t140;
    const float t142 = t106 * t124;
    const float t143 = t126 + t108;
    const float t144 = t126 / t143;
    const float t145 = t142 * t144;
    const float t146 = t141 - t145;
    const float t147 = t113 * t131;
    const float t148 = t147 * t118;
    const float t149 = t148 * t124;
    const float t150 = t135 * t128;
    const float t151 = t149 - t150;
    const float t152 = t84 * t138;
    const float t153 = t48 + t152;
    const float t154 = t84 * t146;
    const float t155 = t49 + t154;
    const float t156 = t84 * t151;
    const float t157 = t50 + t156;
    const float t158 = t87 + t155;
    const float t159 = t155 / t158;
    const float t160 = t86 * t159;
    const float t161 = fmaxf(t157, t94);
    const float t162 = t93 / t161;
    const float t163 = libm_expf(t162);
    const float t164 = t91 * t163;
    const float t165 = t160 * t153;
    const float t166 = t164 * t153;
    const float t167 = t165 - t166;
    const float t168 = t102 * t160;
    const float t169 = t168 * t153;
    const float t170 = -t169;
    const float t171 = t106 * t153;
    const float t172 = t155 + t108;
    const float t173 = t155 / t172;
    const float t174 = t171 * t173;
    const float t175 = t170 - t174;
    const float t176 = t113 * t160;
    const float t177 = t176 * t118;
    const float t178 = t177 * t153;
    const float t179 = t164 * t157;
    const float t180 = t178 - t179;
    const float t181 = t81 * t167;
    const float t182 = t48 + t181;
    const float t183 = t81 * t175;
    const float t184 = t49 + t183;
    const float t185 = t81 * t180;
    const float t186 = t50 + t185;
    const float t187 = t87 + t184;
    const float t188 = t184 / t187;
    const float t189 = t86 * t188;
    const float t190 = fmaxf(t186, t94);
    const float t191 = t93 / t190;
    const float t192 = libm_expf(t191);
    const float t193 = t91 * t192;
    const float t194 = t189 * t182;
    const float t195 = t193 * t182;
    const float t196 = t194 - t195;
    const float t197 = t102 * t189;
    const float t198 = t197 * t182;
    const float t199 = -t198;
    const float t200 = t106 * t182;
    const float t201 = t184 + t108;
    const float t202 = t184 / t201;
    const float t203 = t200 * t202;
    const float t204 = t199 - t203;
    const float t205 = t113 * t189;
    const float t206 = t205 * t118;
    const float t207 = t206 * t182;
    const float t208 = t193 * t186;
    const float t209 = t207 - t208;
    const float t210 = t138 + t167;
    const float t211 = t82 * t210;
    const float t212 = t101 + t211;
    const float t213 = t212 + t196;
    const float t214 = t85 * t213;
    const float t215 = t48 + t214;
    const float t216 = t146 + t175;
    const float t217 = t82 * t216;
    const float t218 = t112 + t217;
    const float t219 = t218 + t204;
    const float t220 = t85 * t219;
    const float t221 = t49 + t220;
    const float t222 = t151 + t180;
    const float t223 = t82 * t222;
    const float t224 = t122 + t223;
    const float t225 = t224 + t209;
    const float t226 = t85 * t225;
    const float t227 = t50 + t226;
    const float t228 = t87 + t56;
    const float t229 = t56 / t228;
    const float t230 = t86 * t229;
    const float t231 = fmaxf(t57, t94);
    const float t232 = t93 / t231;
    const float t233 = libm_expf(t232);
    const float t234 = t91 * t233;
    const float t235 = t230 * t55;
    const float t236 = t234 * t55;
    const float t237 = t235 - t236;
    const float t238 = t102 * t230;
    const float t239 = t238 * t55;
    const float t240 = -t239;
    const float t241 = t106 * t55;
    const float t242 = t56 + t108;
    const float t243 = t56 / t242;
    const float t244 = t241 * t243;
    const float t245 = t240 - t244;
    const float t246 = t113 * t230;
    const float t247 = t246 * t118;
    const float t248 = t247 * t55;
    const float t249 = t234 * t57;
    const float t250 = t248 - t249;
    const float t251 = t84 * t237;
    const float t252 = t55 + t251;
    const float t253 = t84 * t245;
    const float t254 = t56 + t253;
    const float t255 = t84 * t250;
    const float t256 = t57 + t255;
    const float t257 = t87 + t254;
    const float t258 = t254 / t257;
    const float t259 = t86 * t258;
    const float t260 = fmaxf(t256, t94);
    const float t261 = t93 / t260;
    const float t262 = libm_expf(t261);
    const float t263 = t91 * t262;
    const float t264 = t259 * t252;
    const float t265 = t263 * t252;
    const float t266 = t264 - t265;
    const float t267 = t102 * t259;
    const float t268 = t267 * t252;
    const float t269 = -t268;
    const float t270 = t106 * t252;
    const float t271 = t254 + t108;
    const float t272 = t254 / t271;
    const float t273 = t270 * t272;
    const float t274 = t269 - t273;
    const float t275 = t113 * t259;
    const float t276 = t275 * t118;
    const float t277 = t276 * t252;
    const float t278 = t263 * t256;
    const float t279 = t277 - t278;
    const float t280 = t84 * t266;
    const float t281 = t55 + t280;
    const float t282 = t84 * t274;
    const float t283 = t56 + t282;
    const float t284 = t84 * t279;
    const float t285 = t57 + t284;
    const float t286 = t87 + t283;
    const float t287 = t283 / t286;
    const float t288 = t86 * t287;
    const float t289 = fmaxf(t285, t94);
    const float t290 = t93 / t289;
    const float t291 = libm_expf(t290);
    const float t292 = t91 * t291;
    const float t293 = t288 * t281;
    const float t294 = t292 * t281;
    const float t295 = t293 - t294;
    const float t296 = t102 * t288;
    const float t297 = t296 * t281;
    const float t298 = -t297;
    const float t299 = t106 * t281;
    const float t300 = t283 + t108;
    const float t301 = t283 / t300;
    const float t302 = t299 * t301;
    const float t303 = t298 - t302;
    const float t304 = t113 * t288;
    const float t305 = t304 * t118;
    const float t306 = t305 * t281;
    const float t307 = t292 * t285;
    const float t308 = t306 - t307;
    const float t309 = t81 * t295;
    const float t310 = t55 + t309;
    const float t311 = t81 * t303;
    const float t312 = t56 + t311;
    const float t313 = t81 * t308;
    const float t314 = t57 + t313;
    const float t315 = t87 + t312;
    const float t316 = t312 / t315;
    const float t317 = t86 * t316;
    const float t318 = fmaxf(t314, t94);
    const float t319 = t93 / t318;
    const float t320 = libm_expf(t319);
    const float t321 = t91 * t320;
    const float t322 = t317 * t310;
    const float t323 = t321 * t310;
    const float t324 = t322 - t323;
    const float t325 = t102 * t317;
    const float t326 = t325 * t310;
    const float t327 = -t326;
    const float t328 = t106 * t310;
    const float t329 = t312 + t108;
    const float t330 = t312 / t329;
    const float t331 = t328 * t330;
    const float t332 = t327 - t331;
    const float t333 = t113 * t317;
    const float t334 = t333 * t118;
    const float t335 = t334 * t310;
    const float t336 = t321 * t314;
    const float t337 = t335 - t336;
    const float t338 = t266 + t295;
    const float t339 = t82 * t338;
    const float t340 = t237 + t339;
    const float t341 = t340 + t324;
    const float t342 = t85 * t341;
    const float t343 = t55 + t342;
    const float t344 = t274 + t303;
    const float t345 = t82 * t344;
    const float t346 = t245 + t345;
    const float t347 = t346 + t332;
    const float t348 = t85 * t347;
    const float t349 = t56 + t348;
    const float t350 = t279 + t308;
    const float t351 = t82 * t350;
    const float t352 = t250 + t351;
    const float t353 = t352 + t337;
    const float t354 = t85 * t353;
    const float t355 = t57 + t354;
    const float t356 = t87 + t60;
    const float t357 = t60 / t356;
    const float t358 = t86 * t357;
    const float t359 = fmaxf(t61, t94);
    const float t360 = t93 / t359;
    const float t361 = libm_expf(t360);
    const float t362 = t91 * t361;
    const float t363 = t358 * t55;
    const float t364 = t362 * t55;
    const float t365 = t363 - t364;
    const float t366 = t102 * t358;
    const float t367 = t366 * t55;
    const float t368 = -t367;
    const float t369 = t60 + t108;
    const float t370 = t60 / t369;
    const float t371 = t241 * t370;
    const float t372 = t368 - t371;
    const float t373 = t113 * t358;
    const float t374 = t373 * t118;
    const float t375 = t374 * t55;
    const float t376 = t362 * t61;
    const float t377 = t375 - t376;
    const float t378 = t84 * t365;
    const float t379 = t55 + t378;
    const float t380 = t84 * t372;
    const float t381 = t60 + t380;
    const float t382 = t84 * t377;
    const float t383 = t61 + t382;
    const float t384 = t87 + t381;
    const float t385 = t381 / t384;
    const float t386 = t86 * t385;
    const float t387 = fmaxf(t383, t94);
    const float t388 = t93 / t387;
    const float t389 = libm_expf(t388);
    const float t390 = t91 * t389;
    const float t391 = t386 * t379;
    const float t392 = t390 * t379;
    const float t393 = t391 - t392;
    const float t394 = t102 * t386;
    const float t395 = t394 * t379;
    const float t396 = -t395;
    const float t397 = t106 * t379;
    const float t398 = t381 + t108;
    const float t399 = t381 / t398;
    const float t400 = t397 * t399;
    const float t401 = t396 - t400;
    const float t402 = t113 * t386;
    const float t403 = t402 * t118;
    const float t404 = t403 * t379;
    const float t405 = t390 * t383;
    const float t406 = t404 - t405;
    const float t407 = t84 * t393;
    const float t408 = t55 + t407;
    const float t409 = t84 * t401;
    const float t410 = t60 + t409;
    const float t411 = t84 * t406;
    const float t412 = t61 + t411;
    const float t413 = t87 + t410;
    const float t414 = t410 / t413;
    const float t415 = t86 * t414;
    const float t416 = fmaxf(t412, t94);
    const float t417 = t93 / t416;
    const float t418 = libm_expf(t417);
    const float t419 = t91 * t418;
    const float t420 = t415 * t408;
    const float t421 = t419 * t408;
    const float t422 = t420 - t421;
    const float t423 = t102 * t415;
    const float t424 = t423 * t408;
    const float t425 = -t424;
    const float t426 = t106 * t408;
    const float t427 = t410 + t108;
    const float t428 = t410 / t427;
    const float t429 = t426 * t428;
    const float t430 = t425 - t429;
    const float t431 = t113 * t415;
    const float t432 = t431 * t118;
    const float t433 = t432 * t408;
    const float t434 = t419 * t412;
    const float t435 = t433 - t434;
    const float t436 = t81 * t422;
    const float t437 = t55 + t436;
    const float t438 = t81 * t430;
    const float t439 = t60 + t438;
    const float t440 = t81 * t435;
    const float t441 = t61 + t440;
    const float t442 = t87 + t439;
    const float t443 = t439 / t442;
    const float t444 = t86 * t443;
    const float t445 = fmaxf(t441, t94);
    const float t446 = t93 / t445;
    const float t447 = libm_expf(t446);
    const float t448 = t91 * t447;
    const float t449 = t444 * t437;
    const float t450 = t448 * t437;
    const float t451 = t449 - t450;
    const float t452 = t102 * t444;
    const float t453 = t452 * t437;
    const float t454 = -t453;
    const float t455 = t106 * t437;
    const float t456 = t439 + t108;
    const float t457 = t439 / t456;
    const float t458 = t455 * t457;
    const float t459 = t454 - t458;
    const float t460 = t113 * t444;
    const float t461 = t460 * t118;
    const float t462 = t461 * t437;
    const float t463 = t448 * t441;
    const float t464 = t462 - t463;
    const float t465 = t393 + t422;
    const float t466 = t82 * t465;
    const float t467 = t365 + t466;
    const float t468 = t467 + t451;
    const float t469 = t85 * t468;
    const float t470 = t55 + t469;
    const float t471 = t401 + t430;
    const float t472 = t82 * t471;
    const float t473 = t372 + t472;
    const float t474 = t473 + t459;
    const float t475 = t85 * t474;
    const float t476 = t60 + t475;
    const float t477 = t406 + t435;
    const float t478 = t82 * t477;
    const float t479 = t377 + t478;
    const float t480 = t479 + t464;
    const float t481 = t85 * t480;
    const float t482 = t61 + t481;
    const float t483 = t87 + t70;
    const float t484 = t70 / t483;
    const float t485 = t86 * t484;
    const float t486 = fmaxf(t71, t94);
    const float t487 = t93 / t486;
    const float t488 = libm_expf(t487);
    const float t489 = t91 * t488;
    const float t490 = t485 * t69;
    const float t491 = t489 * t69;
    const float t492 = t490 - t491;
    const float t493 = t102 * t485;
    const float t494 = t493 * t69;
    const float t495 = -t494;
    const float t496 = t106 * t69;
    const float t497 = t70 + t108;
    const float t498 = t70 / t497;
    const float t499 = t496 * t498;
    const float t500 = t495 - t499;
    const float t501 = t113 * t485;
    const float t502 = t501 * t118;
    const float t503 = t502 * t69;
    const float t504 = t489 * t71;
    const float t505 = t503 - t504;
    const float t506 = t84 * t492;
    const float t507 = t69 + t506;
    const float t508 = t84 * t500;
    const float t509 = t70 + t508;
    const float t510 = t84 * t505;
    const float t511 = t71 + t510;
    const float t512 = t87 + t509;
    const float t513 = t509 / t512;
    const float t514 = t86 * t513;
    const float t515 = fmaxf(t511, t94);
    const float t516 = t93 / t515;
    const float t517 = libm_expf(t516);
    const float t518 = t91 * t517;
    const float t519 = t514 * t507;
    const float t520 = t518 * t507;
    const float t521 = t519 - t520;
    const float t522 = t102 * t514;
    const float t523 = t522 * t507;
    const float t524 = -t523;
    const float t525 = t106 * t507;
    const float t526 = t509 + t108;
    const float t527 = t509 / t526;
    const float t528 = t525 * t527;
    const float t529 = t524 - t528;
    const float t530 = t113 * t514;
    const float t531 = t530 * t118;
    const float t532 = t531 * t507;
    const float t533 = t518 * t511;
    const float t534 = t532 - t533;
    const float t535 = t84 * t521;
    const float t536 = t69 + t535;
    const float t537 = t84 * t529;
    const float t538 = t70 + t537;
    const float t539 = t84 * t534;
    const float t540 = t71 + t539;
    const float t541 = t87 + t538;
    const float t542 = t538 / t541;
    const float t543 = t86 * t542;
    const float t544 = fmaxf(t540, t94);
    const float t545 = t93 / t544;
    const float t546 = libm_expf(t545);
    const float t547 = t91 * t546;
    const float t548 = t543 * t536;
    const float t549 = t547 * t536;
    const float t550 = t548 - t549;
    const float t551 = t102 * t543;
    const float t552 = t551 * t536;
    const float t553 = -t552;
    const float t554 = t106 * t536;
    const float t555 = t538 + t108;
    const float t556 = t538 / t555;
    const float t557 = t554 * t556;
    const float t558 = t553 - t557;
    const float t559 = t113 * t543;
    const float t560 = t559 * t118;
    const float t561 = t560 * t536;
    const float t562 = t547 * t540;
    const float t563 = t561 - t562;
    const float t564 = t81 * t550;
    const float t565 = t69 + t564;
    const float t566 = t81 * t558;
    const float t567 = t70 + t566;
    const float t568 = t81 * t563;
    const float t569 = t71 + t568;
    const float t570 = t87 + t567;
    const float t571 = t567 / t570;
    const float t572 = t86 * t571;
    const float t573 = fmaxf(t569, t94);
    const float t574 = t93 / t573;
    const float t575 = libm_expf(t574);
    const float t576 = t91 * t575;
    const float t577 = t572 * t565;
    const float t578 = t576 * t565;
    const float t579 = t577 - t578;
    const float t580 = t102 * t572;
    const float t581 = t580 * t565;
    const float t582 = -t581;
    const float t583 = t106 * t565;
    const float t584 = t567 + t108;
    const float t585 = t567 / t584;
    const float t586 = t583 * t585;
    const float t587 = t582 - t586;
    const float t588 = t113 * t572;
    const float t589 = t588 * t118;
    const float t590 = t589 * t565;
    const float t591 = t576 * t569;
    const float t592 = t590 - t591;
    const float t593 = t521 + t550;
    const float t594 = t82 * t593;
    const float t595 = t492 + t594;
    const float t596 = t595 + t579;
    const float t597 = t85 * t596;
    const float t598 = t69 + t597;
    const float t599 = t529 + t558;
    const float t600 = t82 * t599;
    const float t601 = t500 + t600;
    const float t602 = t601 + t587;
    const float t603 = t85 * t602;
    const float t604 = t70 + t603;
    const float t605 = t534 + t563;
    const float t606 = t82 * t605;
    const float t607 = t505 + t606;
    const float t608 = t607 + t592;
    const float t609 = t85 * t608;
    const float t610 = t71 + t609;
    const float t611 = t87 + t76;
    const float t612 = t76 / t611;
    const float t613 = t86 * t612;
    const float t614 = fmaxf(t77, t94);
    const float t615 = t93 / t614;
    const float t616 = libm_expf(t615);
    const float t617 = t91 * t616;
    const float t618 = t613 * t55;
    const float t619 = t617 * t55;
    const float t620 = t618 - t619;
    const float t621 = t102 * t613;
    const float t622 = t621 * t55;
    const float t623 = -t622;
    const float t624 = t76 + t108;
    const float t625 = t76 / t624;
    const float t626 = t241 * t625;
    const float t627 = t623 - t626;
    const float t628 = t113 * t613;
    const float t629 = t628 * t118;
    const float t630 = t629 * t55;
    const float t631 = t617 * t77;
    const float t632 = t630 - t631;
    const float t633 = t84 * t620;
    const float t634 = t55 + t633;
    const float t635 = t84 * t627;
    const float t636 = t76 + t635;
    const float t637 = t84 * t632;
    const float t638 = t77 + t637;
    const float t639 = t87 + t636;
    const float t640 = t636 / t639;
    const float t641 = t86 * t640;
    const float t642 = fmaxf(t638, t94);
    const float t643 = t93 / t642;
    const float t644 = libm_expf(t643);
    const float t645 = t91 * t644;
    const float t646 = t641 * t634;
    const float t647 = t645 * t634;
    const float t648 = t646 - t647;
    const float t649 = t102 * t641;
    const float t650 = t649 * t634;
    const float t651 = -t650;
    const float t652 = t106 * t634;
    const float t653 = t636 + t108;
    const float t654 = t636 / t653;
    const float t655 = t652 * t654;
    const float t656 = t651 - t655;
    const float t657 = t113 * t641;
    const float t658 = t657 * t118;
    const float t659 = t658 * t634;
    const float t660 = t645 * t638;
    const float t661 = t659 - t660;
    const float t662 = t84 * t648;
    const float t663 = t55 + t662;
    const float t664 = t84 * t656;
    const float t665 = t76 + t664;
    const float t666 = t84 * t661;
    const float t667 = t77 + t666;
    const float t668 = t87 + t665;
    const float t669 = t665 / t668;
    const float t670 = t86 * t669;
    const float t671 = fmaxf(t667, t94);
    const float t672 = t93 / t671;
    const float t673 = libm_expf(t672);
    const float t674 = t91 * t673;
    const float t675 = t670 * t663;
    const float t676 = t674 * t663;
    const float t677 = t675 - t676;
    const float t678 = t102 * t670;
    const float t679 = t678 * t663;
    const float t680 = -t679;
    const float t681 = t106 * t663;
    const float t682 = t665 + t108;
    const float t683 = t665 / t682;
    const float t684 = t681 * t683;
    const float t685 = t680 - t684;
    const float t686 = t113 * t670;
    const float t687 = t686 * t118;
    const float t688 = t687 * t663;
    const float t689 = t674 * t667;
    const float t690 = t688 - t689;
    const float t691 = t81 * t677;
    const float t692 = t55 + t691;
    const float t693 = t81 * t685;
    const float t694 = t76 + t693;
    const float t695 = t81 * t690;
    const float t696 = t77 + t695;
    const float t697 = t87 + t694;
    const float t698 = t694 / t697;
    const float t699 = t86 * t698;
    const float t700 = fmaxf(t696, t94);
    const float t701 = t93 / t700;
    const float t702 = libm_expf(t701);
    const float t703 = t91 * t702;
    const float t704 = t699 * t692;
    const float t705 = t703 * t692;
    const float t706 = t704 - t705;
    const float t707 = t102 * t699;
    const float t708 = t707 * t692;
    const float t709 = -t708;
    const float t710 = t106 * t692;
    const float t711 = t694 + t108;
    const float t712 = t694 / t711;
    const float t713 = t710 * t712;
    const float t714 = t709 - t713;
    const float t715 = t113 * t699;
    const float t716 = t715 * t118;
    const float t717 = t716 * t692;
    const float t718 = t703 * t696;
    const float t719 = t717 - t718;
    const float t720 = t648 + t677;
    const float t721 = t82 * t720;
    const float t722 = t620 + t721;
    const float t723 = t722 + t706;
    const float t724 = t85 * t723;
    const float t725 = t55 + t724;
    const float t726 = t656 + t685;
    const float t727 = t82 * t726;
    const float t728 = t627 + t727;
    const float t729 = t728 + t714;
    const float t730 = t85 * t729;
    const float t731 = t76 + t730;
    const float t732 = t661 + t690;
    const float t733 = t82 * t732;
    const float t734 = t632 + t733;
    const float t735 = t734 + t719;
    const float t736 = t85 * t735;
    const float t737 = t77 + t736;
    const float t738 = fmaxf(t80, t94);
    const float t739 = t93 / t738;
    const float t740 = libm_expf(t739);
    const float t741 = t91 * t740;
    const float t742 = t741 * t55;
    const float t743 = t363 - t742;
    const float t744 = t741 * t80;
    const float t745 = t375 - t744;
    const float t746 = t84 * t743;
    const float t747 = t55 + t746;
    const float t748 = t84 * t745;
    const float t749 = t80 + t748;
    const float t750 = fmaxf(t749, t94);
    const float t751 = t93 / t750;
    const float t752 = libm_expf(t751);
    const float t753 = t91 * t752;
    const float t754 = t386 * t747;
    const float t755 = t753 * t747;
    const float t756 = t754 - t755;
    const float t757 = t394 * t747;
    const float t758 = -t757;
    const float t759 = t106 * t747;
    const float t760 = t759 * t399;
    const float t761 = t758 - t760;
    const float t762 = t403 * t747;
    const float t763 = t753 * t749;
    const float t764 = t762 - t763;
    const float t765 = t84 * t756;
    const float t766 = t55 + t765;
    const float t767 = t84 * t761;
    const float t768 = t60 + t767;
    const float t769 = t84 * t764;
    const float t770 = t80 + t769;
    const float t771 = t87 + t768;
    const float t772 = t768 / t771;
    const float t773 = t86 * t772;
    const float t774 = fmaxf(t770, t94);
    const float t775 = t93 / t774;
    const float t776 = libm_expf(t775);
    const float t777 = t91 * t776;
    const float t778 = t773 * t766;
    const float t779 = t777 * t766;
    const float t780 = t778 - t779;
    const float t781 = t102 * t773;
    const float t782 = t781 * t766;
    const float t783 = -t782;
    const float t784 = t106 * t766;
    const float t785 = t768 + t108;
    const float t786 = t768 / t785;
    const float t787 = t784 * t786;
    const float t788 = t783 - t787;
    const float t789 = t113 * t773;
    const float t790 = t789 * t118;
    const float t791 = t790 * t766;
    const float t792 = t777 * t770;
    const float t793 = t791 - t792;
    const float t794 = t81 * t780;
    const float t795 = t55 + t794;
    const float t796 = t81 * t788;
    const float t797 = t60 + t796;
    const float t798 = t81 * t793;
    const float t799 = t80 + t798;
    const float t800 = t87 + t797;
    const float t801 = t797 / t800;
    const float t802 = t86 * t801;
    const float t803 = fmaxf(t799, t94);
    const float t804 = t93 / t803;
    const float t805 = libm_expf(t804);
    const float t806 = t91 * t805;
    const float t807 = t802 * t795;
    const float t808 = t806 * t795;
    const float t809 = t807 - t808;
    const float t810 = t102 * t802;
    const float t811 = t810 * t795;
    const float t812 = -t811;
    const float t813 = t106 * t795;
    const float t814 = t797 + t108;
    const float t815 = t797 / t814;
    const float t816 = t813 * t815;
    const float t817 = t812 - t816;
    const float t818 = t113 * t802;
    const float t819 = t818 * t118;
    const float t820 = t819 * t795;
    const float t821 = t806 * t799;
    const float t822 = t820 - t821;
    const float t823 = t756 + t780;
    const float t824 = t82 * t823;
    const float t825 = t743 + t824;
    const float t826 = t825 + t809;
    const float t827 = t85 * t826;
    const float t828 = t55 + t827;
    const float t829 = t761 + t788;
    const float t830 = t82 * t829;
    const float t831 = t372 + t830;
    const float t832 = t831 + t817;
    const float t833 = t85 * t832;
    const float t834 = t60 + t833;
    const float t835 = t764 + t793;
    const float t836 = t82 * t835;
    const float t837 = t745 + t836;
    const float t838 = t837 + t822;
    const float t839 = t85 * t838;
    const float t840 = t80 + t839;
    const float t841 = 0.16666667f;
    const float t842 = t215 + t343;
    const float t843 = t842 + t470;
    const float t844 = t843 + t598;
    const float t845 = t844 + t725;
    const float t846 = t845 + t828;
    const float t847 = t841 * t846;
    const float t848 = t221 + t349;
    const float t849 = t848 + t476;
    const float t850 = t849 + t604;
    const float t851 = t850 + t731;
    const float t852 = t851 + t834;
    const float t853 = t841 * t852;
    const float t854 = t227 + t355;
    const float t855 = t854 + t482;
    const float t856 = t855 + t610;
    const float t857 = t856 + t737;
    const float t858 = t857 + t840;
    const float t859 = t841 * t858;
    const float t860 = t215 - t847;
    const float t861 = t221 - t853;
    const float t862 = t227 - t859;
    const float t863 = t343 - t847;
    const float t864 = t349 - t853;
    const float t865 = t355 - t859;
    const float t866 = t470 - t847;
    const float t867 = t476 - t853;
    const float t868 = t482 - t859;
    const float t869 = t598 - t847;
    const float t870 = t604 - t853;
    const float t871 = t610 - t859;
    const float t872 = t725 - t847;
    const float t873 = t731 - t853;
    const float t874 = t737 - t859;
    const float t875 = t828 - t847;
    const float t876 = t834 - t853;
    const float t877 = t840 - t859;
    const float t878 = t860 * t860;
    const float t879 = t863 * t863;
    const float t880 = t878 + t879;
    const float t881 = t866 * t866;
    const float t882 = t880 + t881;
    const float t883 = t869 * t869;
    const float t884 = t882 + t883;
    const float t885 = t872 * t872;
    const float t886 = t884 + t885;
    const float t887 = t875 * t875;
    const float t888 = t886 + t887;
    const float t889 = t841 * t888;
    const float t890 = t860 * t861;
    const float t891 = t863 * t864;
    const float t892 = t890 + t891;
    const float t893 = t866 * t867;
    const float t894 = t892 + t893;
    const float t895 = t869 * t870;
    const float t896 = t894 + t895;
    const float t897 = t872 * t873;
    const float t898 = t896 + t897;
    const float t899 = t875 * t876;
    const float t900 = t898 + t899;
    const float t901 = t841 * t900;
    const float t902 = t860 * t862;
    const float t903 = t863 * t865;
    const float t904 = t902 + t903;
    const float t905 = t866 * t868;
    const float t906 = t904 + t905;
    const float t907 = t869 * t871;
    const float t908 = t906 + t907;
    const float t909 = t872 * t874;
    const float t910 = t908 + t909;
    const float t911 = t875 * t877;
    const float t912 = t910 + t911;
    const float t913 = t841 * t912;
    const float t914 = t861 * t861;
    const float t915 = t864 * t864;
    const float t916 = t914 + t915;
    const float t917 = t867 * t867;
    const float t918 = t916 + t917;
    const float t919 = t870 * t870;
    const float t920 = t918 + t919;
    const float t921 = t873 * t873;
    const float t922 = t920 + t921;
    const float t923 = t876 * t876;
    const float t924 = t922 + t923;
    const float t925 = t841 * t924;
    const float t926 = t861 * t862;
    const float t927 = t864 * t865;
    const float t928 = t926 + t927;
    const float t929 = t867 * t868;
    const float t930 = t928 + t929;
    const float t931 = t870 * t871;
    const float t932 = t930 + t931;
    const float t933 = t873 * t874;
    const float t934 = t932 + t933;
    const float t935 = t876 * t877;
    const float t936 = t934 + t935;
    const float t937 = t841 * t936;
    const float t938 = t862 * t862;
    const float t939 = t865 * t865;
    const float t940 = t938 + t939;
    const float t941 = t868 * t868;
    const float t942 = t940 + t941;
    const float t943 = t871 * t871;
    const float t944 = t942 + t943;
    const float t945 = t874 * t874;
    const float t946 = t944 + t945;
    const float t947 = t877 * t877;
    const float t948 = t946 + t947;
    const float t949 = t841 * t948;
    const float t950 = 0.0010809527f;
    const float t951 = t889 + t950;
    const float t952 = 0.0022970699f;
    const float t953 = t925 + t952;
    const float t954 = 1.6450299e-8f;
    const float t955 = t949 + t954;
    const float t956 = select_float(!(t847 >= t9), t9, t847);
    const float t957 = select_float(!(t853 >= t9), t9, t853);
    const float t958 = select_float(!(t859 >= t9), t9, t859);
    out[0] = t956;
    out[1] = t957;
    out[2] = t958;
    out[3] = t951;
    out[4] = t901;
    out[5] = t913;
    out[6] = t953;
    out[7] = t937;
    out[8] = t955;
}

/* The UKF's start: the centre of the state box and P(0)'s upper triangle. */
static const float UKF_X0[ECOLI_X0_0P5_STATES] = {
    0.5f, 2.5f, 0.15f
};
static const float UKF_P0[ECOLI_X0_0P5_COVARIANCE] = {
    4.7611105e-5f, 0.0f, 0.0f, 1.174829f,
    0.0f, 0.0013430597f
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
    targets(estimate, u, o->values);
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
static void mhe_normal(const ecoli_x0_0p5_mhe *o, const float *x, float (*matrix)[MHE_NX], float *gradient) {
    float state[MHE_NX];
    float sensitivity[MHE_NX][MHE_NX];
    unsigned k, i, a, b, c, m;
    memcpy(state, x, sizeof state);
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
 * around it when `prior`), each projected; the solution x and the state at the newest sample. */
static void mhe_solve_window(const ecoli_x0_0p5_mhe *o, const float *centre, int prior, float *solution, float *end) {
    float x[MHE_NX], state[MHE_NX];
    unsigned n, i, k;
    memcpy(x, centre, sizeof x);
    for (n = 0u; n < MHE_ITERATIONS; ++n) {
        float matrix[MHE_NX][MHE_NX];
        float gradient[MHE_NX], step[MHE_NX], next[MHE_NX];
        mhe_normal(o, x, matrix, gradient);
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
}

ecoli_x0_0p5_status ecoli_x0_0p5_mhe_push(ecoli_x0_0p5_mhe *o, const float *y, const float *u) {
    float moved[MHE_NX], x[MHE_NX], end[MHE_NX], values[ECOLI_X0_0P5_TARGETS];
    int has_moved = 0;
    unsigned i, slot;
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
    mhe_solve_window(o, has_moved ? moved : MHE_START, has_moved, x, end);
    targets(end, u, values);
    if (!all_finite(x, MHE_NX) || !all_finite(end, MHE_NX) || !all_finite(values, ECOLI_X0_0P5_TARGETS)) {
        /* Restarted: the next window is solved from the start, not from this solution. */
        o->has_solved = 0;
        if (o->restarts != UINT32_MAX) {
            ++o->restarts;
        }
        return ECOLI_X0_0P5_RESTARTED;
    }
    memcpy(o->solved, x, sizeof x);
    o->has_solved = 1;
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
