/* The `vanderpol_uncertain` observers in C99, emitted by `mho gen`. Do not edit: regenerate.
 * Licence: emitted by mho from your spec, this file is yours: you may use, copy, modify and
 * distribute it under any terms, including MIT OR Apache-2.0, with or without this notice. */
#include <stdint.h>
#include <string.h>
#include <math.h>
#include <float.h>
#include "vanderpol_uncertain.h"

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
    for (i = 0u; i < VANDERPOL_UNCERTAIN_OUTPUTS; ++i) {
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


/* target `x1`: gains in regressor order, then the Γ⁻¹ table's segments (a, b). */
static const float GAINS_0[10] = {
    4.543185f, 0.7786889f, -1.0524274f, -1.3822162f,
    -1.2224729f, -0.1508291f, 0.2517326f, 0.33626536f,
    -0.7091271f, -3.988934f
};
static const float SEGMENTS_0[99][2] = {
    { -2.4087043f, 0.0090096975f },
    { -2.4091089f, 0.009414231f },
    { -2.4099846f, 0.009852051f },
    { -2.4114096f, 0.010327091f },
    { -2.4134767f, 0.010843886f },
    { -2.4162958f, 0.011407666f },
    { -2.4199967f, 0.012024485f },
    { -2.4247348f, 0.012701372f },
    { -2.4306958f, 0.013446496f },
    { -2.4381018f, 0.014269379f },
    { -2.4472191f, 0.015181112f },
    { -2.4583678f, 0.016194621f },
    { -2.4719315f, 0.01732493f },
    { -2.4883697f, 0.018589415f },
    { -2.50823f, 0.020008f },
    { -2.5321581f, 0.021603208f },
    { -2.5609052f, 0.02339991f },
    { -2.5953238f, 0.025424534f },
    { -2.636343f, 0.027703373f },
    { -2.684909f, 0.03025949f },
    { -2.7418728f, 0.033107676f },
    { -2.807799f, 0.036247015f },
    { -2.8826954f, 0.0396514f },
    { -2.9656875f, 0.043259744f },
    { -3.0547304f, 0.046969865f },
    { -3.1465287f, 0.050641805f },
    { -3.2368298f, 0.054114915f },
    { -3.3211308f, 0.057237174f },
    { -3.395597f, 0.05989668f },
    { -3.4578073f, 0.06204187f },
    { -3.5070267f, 0.06368252f },
    { -3.5439765f, 0.06487445f },
    { -3.5703192f, 0.06569765f },
    { -3.588116f, 0.06623694f },
    { -3.5994215f, 0.06656947f },
    { -3.606051f, 0.06675888f },
    { -3.609486f, 0.0668543f },
    { -3.6108708f, 0.06689172f },
    { -3.6110482f, 0.06689639f },
    { -3.610613f, 0.06688524f },
    { -3.6099658f, 0.06686905f },
    { -3.6093569f, 0.0668542f },
    { -3.6089263f, 0.06684395f },
    { -3.6087344f, 0.06683949f },
    { -3.6087847f, 0.06684063f },
    { -3.6090434f, 0.06684638f },
    { -3.609454f, 0.066855304f },
    { -3.6099484f, 0.066865824f },
    { -3.6104567f, 0.06687641f },
    { -3.610913f, 0.066885725f },
    { -3.6112626f, 0.06689271f },
    { -3.611465f, 0.066896684f },
    { -3.6114972f, 0.0668973f },
    { -3.611355f, 0.06689462f },
    { -3.6110542f, 0.066889055f },
    { -3.6106286f, 0.066881314f },
    { -3.6101296f, 0.0668724f },
    { -3.6096213f, 0.066863485f },
    { -3.6091764f, 0.06685582f },
    { -3.6088703f, 0.066850625f },
    { -3.6087706f, 0.06684896f },
    { -3.6089275f, 0.066851534f },
    { -3.6093583f, 0.066858485f },
    { -3.61003f, 0.06686915f },
    { -3.6108341f, 0.066881716f },
    { -3.6115596f, 0.06689287f },
    { -3.6118531f, 0.06689732f },
    { -3.6111765f, 0.06688722f },
    { -3.608751f, 0.06685156f },
    { -3.6034975f, 0.06677541f },
    { -3.5939705f, 0.06663931f },
    { -3.5783007f, 0.06641862f },
    { -3.5541553f, 0.06608326f },
    { -3.518744f, 0.065598175f },
    { -3.4689f, 0.064924605f },
    { -3.4012704f, 0.06402288f },
    { -3.3126397f, 0.06285668f },
    { -3.2003727f, 0.06139867f },
    { -3.0629241f, 0.05963651f },
    { -2.9002934f, 0.057577893f },
    { -2.7142787f, 0.05525271f },
    { -2.5084224f, 0.052711274f },
    { -2.2876225f, 0.05001859f },
    { -2.0575078f, 0.047246125f },
    { -1.8237516f, 0.044463314f },
    { -1.5914872f, 0.04173079f },
    { -1.3649315f, 0.039096422f },
    { -1.1472329f, 0.03659414f },
    { -0.9404996f, 0.0342449f },
    { -0.7459388f, 0.03205882f },
    { -0.56404334f, 0.030037763f },
    { -0.3947811f, 0.028177736f },
    { -0.23776026f, 0.026470989f },
    { -0.09236246f, 0.024907572f },
    { 0.042157184f, 0.023476511f },
    { 0.1665992f, 0.022166595f },
    { 0.2817716f, 0.020966884f },
    { 0.38845912f, 0.019867012f },
    { 0.48740476f, 0.018857362f }
};

/* target `x2`: gains in regressor order, then the Γ⁻¹ table's segments (a, b). */
static const float GAINS_1[10] = {
    0.06632062f, 0.06250297f, 0.040498633f, 0.01797323f,
    0.00079974055f, -0.007791193f, -0.007125094f, -0.00076618337f,
    0.016579298f, 0.044361085f
};
static const float SEGMENTS_1[2][2] = {
    { -4.7017317f, 4.766553f },
    { -4.701727f, 4.7665486f }
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
                     float *value, vanderpol_uncertain_saturation *saturation) {
    const int low = !(t >= 0.0f);
    const int high = t > t_max;
    float r = segment[0] + segment[1] * (t - start);
    r = choose_float(high, r_max, r);
    r = choose_float(low, r_min, r);
    *value = r;
    *saturation = (vanderpol_uncertain_saturation)((unsigned)low | (unsigned)high << 1);
}

void vanderpol_uncertain_map_init(vanderpol_uncertain_map *observer) {
    observer->next = 0u;
    observer->filled = 0u;
}

vanderpol_uncertain_status vanderpol_uncertain_map_push(vanderpol_uncertain_map *observer, const float *y, const float *u) {
    unsigned i;
    unsigned slot;
    int finite = 1;
    for (i = 0u; i < VANDERPOL_UNCERTAIN_OUTPUTS; ++i) {
        finite &= is_finite(y[i]);
    }
    if (!finite) {
        return VANDERPOL_UNCERTAIN_REFUSED;
    }
    slot = observer->next;
    for (i = 0u; i < VANDERPOL_UNCERTAIN_OUTPUTS; ++i) {
        observer->y[slot][i] = y[i];
        observer->y[slot + VANDERPOL_UNCERTAIN_HORIZON][i] = y[i];
    }
    (void)u;
    observer->next = slot + 1u >= VANDERPOL_UNCERTAIN_HORIZON ? 0u : slot + 1u;
    observer->filled += (unsigned)(observer->filled < VANDERPOL_UNCERTAIN_HORIZON);
    return VANDERPOL_UNCERTAIN_OK;
}

vanderpol_uncertain_status vanderpol_uncertain_map_estimate(const vanderpol_uncertain_map *observer, float *values, vanderpol_uncertain_saturation *saturation) {
    const unsigned next = observer->next;
    if (observer->filled < VANDERPOL_UNCERTAIN_HORIZON) {
        return VANDERPOL_UNCERTAIN_NO_ESTIMATE_YET;
    }
    const float t_0 = 54.02016f
        + GAINS_0[0] * observer->y[next + 9u][0]
        + GAINS_0[1] * observer->y[next + 8u][0]
        + GAINS_0[2] * observer->y[next + 7u][0]
        + GAINS_0[3] * observer->y[next + 6u][0]
        + GAINS_0[4] * observer->y[next + 5u][0]
        + GAINS_0[5] * observer->y[next + 4u][0]
        + GAINS_0[6] * observer->y[next + 3u][0]
        + GAINS_0[7] * observer->y[next + 2u][0]
        + GAINS_0[8] * observer->y[next + 1u][0]
        + GAINS_0[9] * observer->y[next + 0u][0];
    const float t_1 = 0.9872462f
        + GAINS_1[0] * observer->y[next + 9u][0]
        + GAINS_1[1] * observer->y[next + 8u][0]
        + GAINS_1[2] * observer->y[next + 7u][0]
        + GAINS_1[3] * observer->y[next + 6u][0]
        + GAINS_1[4] * observer->y[next + 5u][0]
        + GAINS_1[5] * observer->y[next + 4u][0]
        + GAINS_1[6] * observer->y[next + 3u][0]
        + GAINS_1[7] * observer->y[next + 2u][0]
        + GAINS_1[8] * observer->y[next + 1u][0]
        + GAINS_1[9] * observer->y[next + 0u][0];
    const uint32_t k_0 = uniform_segment(t_0, 99u);
    evaluate(t_0, SEGMENTS_0[k_0], 0.0f, 99.0f, -2.4087043f, 2.3542836f, &values[0], &saturation[0]);
    const uint32_t k_1 = uniform_segment(t_1, 2u);
    evaluate(t_1, SEGMENTS_1[k_1], 0.0f, 2.0f, -4.7017317f, 4.83137f, &values[1], &saturation[1]);
    return VANDERPOL_UNCERTAIN_OK;
}


#define VANDERPOL_UNCERTAIN_MAP_ROWS VANDERPOL_UNCERTAIN_TARGETS
#define start_map_estimate vanderpol_uncertain_map_estimate

/* `x1` in integers: gains in regressor order (2^-22 per count), then (A_k, B_k) in its LSB. */
static const int32_t FIXED_GAINS_0[10] = { 9304, 1595, -2155, -2831, -2504, -309, 516, 689, -1452, -8169 };
static const int32_t FIXED_SEGMENTS_0[99][2] = {
    { -1262855, 4724 },
    { -1258131, 4936 },
    { -1253195, 5165 },
    { -1248030, 5414 },
    { -1242616, 5685 },
    { -1236930, 5981 },
    { -1230949, 6304 },
    { -1224645, 6659 },
    { -1217986, 7050 },
    { -1210936, 7481 },
    { -1203455, 7959 },
    { -1195496, 8491 },
    { -1187005, 9083 },
    { -1177922, 9746 },
    { -1168175, 10490 },
    { -1157686, 11326 },
    { -1146359, 12268 },
    { -1134091, 13330 },
    { -1120761, 14525 },
    { -1106237, 15865 },
    { -1090372, 17358 },
    { -1073014, 19004 },
    { -1054010, 20789 },
    { -1033221, 22681 },
    { -1010541, 24626 },
    { -985915, 26551 },
    { -959364, 28372 },
    { -930992, 30009 },
    { -900984, 31403 },
    { -869580, 32528 },
    { -837053, 33388 },
    { -803665, 34013 },
    { -769652, 34444 },
    { -735207, 34727 },
    { -700480, 34902 },
    { -665578, 35001 },
    { -630578, 35051 },
    { -595527, 35071 },
    { -560456, 35073 },
    { -525383, 35067 },
    { -490316, 35059 },
    { -455257, 35051 },
    { -420207, 35045 },
    { -385161, 35043 },
    { -350118, 35044 },
    { -315074, 35047 },
    { -280027, 35051 },
    { -244976, 35057 },
    { -209919, 35062 },
    { -174857, 35067 },
    { -139789, 35071 },
    { -104718, 35073 },
    { -69645, 35073 },
    { -34572, 35072 },
    { 500, 35069 },
    { 35570, 35065 },
    { 70635, 35060 },
    { 105695, 35056 },
    { 140751, 35052 },
    { 175802, 35049 },
    { 210851, 35048 },
    { 245900, 35049 },
    { 280949, 35053 },
    { 316002, 35059 },
    { 351061, 35065 },
    { 386126, 35071 },
    { 421197, 35073 },
    { 456271, 35068 },
    { 491339, 35049 },
    { 526388, 35010 },
    { 561398, 34938 },
    { 596336, 34822 },
    { 631159, 34647 },
    { 665805, 34392 },
    { 700198, 34039 },
    { 734237, 33566 },
    { 767803, 32955 },
    { 800758, 32191 },
    { 832949, 31267 },
    { 864215, 30187 },
    { 894403, 28968 },
    { 923371, 27636 },
    { 951007, 26224 },
    { 977231, 24771 },
    { 1002002, 23312 },
    { 1025313, 21879 },
    { 1047192, 20498 },
    { 1067690, 19186 },
    { 1086876, 17954 },
    { 1104830, 16808 },
    { 1121638, 15748 },
    { 1137387, 14773 },
    { 1152160, 13878 },
    { 1166038, 13059 },
    { 1179097, 12308 },
    { 1191406, 11622 },
    { 1203027, 10993 },
    { 1214020, 10416 },
    { 1224436, 9887 }
};

/* `x2` in integers: gains in regressor order (2^-28 per count), then (A_k, B_k) in its LSB. */
static const int32_t FIXED_GAINS_1[10] = { 8693, 8192, 5308, 2356, 105, -1021, -934, -100, 2173, 5814 };
static const int32_t FIXED_SEGMENTS_1[2][2] = {
    { -38517, 39048 },
    { 531, 39048 }
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
                           int32_t t_last, int32_t *value, vanderpol_uncertain_saturation *saturation) {
    const int32_t low = t >> 31;
    const int32_t high = (wrapping_sub(t_last, t) >> 31) & ~low;
    int32_t k;
    int32_t position;
    t &= ~low;
    t ^= (t ^ t_last) & high;
    k = t >> f;
    position = (t - (int32_t)((uint32_t)k << f)) >> dropped;
    *value = segments[k][0] + ((segments[k][1] * position) >> p);
    *saturation = (vanderpol_uncertain_saturation)((unsigned)(low & 1) | ((unsigned)high & 2u));
}

void vanderpol_uncertain_fixed_init(vanderpol_uncertain_fixed *observer) {
    observer->next = 0u;
    observer->filled = 0u;
}

vanderpol_uncertain_status vanderpol_uncertain_fixed_push(vanderpol_uncertain_fixed *observer, const int32_t *y, const int32_t *u) {
    unsigned i;
    unsigned slot;
    int inside = 1;
    inside &= in_range(y[0], -32767, 32767);
    if (!inside) {
        return VANDERPOL_UNCERTAIN_REFUSED;
    }
    slot = observer->next;
    for (i = 0u; i < VANDERPOL_UNCERTAIN_OUTPUTS; ++i) {
        observer->y[slot][i] = y[i];
        observer->y[slot + VANDERPOL_UNCERTAIN_HORIZON][i] = y[i];
    }
    (void)u;
    observer->next = slot + 1u >= VANDERPOL_UNCERTAIN_HORIZON ? 0u : slot + 1u;
    observer->filled += (unsigned)(observer->filled < VANDERPOL_UNCERTAIN_HORIZON);
    return VANDERPOL_UNCERTAIN_OK;
}

/* The sums are in int32_t: every stored sample is in range, where the proof says they fit. */
vanderpol_uncertain_status vanderpol_uncertain_fixed_estimate(const vanderpol_uncertain_fixed *observer, int32_t *values, vanderpol_uncertain_saturation *saturation) {
    const unsigned next = observer->next;
    if (observer->filled < VANDERPOL_UNCERTAIN_HORIZON) {
        return VANDERPOL_UNCERTAIN_NO_ESTIMATE_YET;
    }
    int32_t t_0 = 226576983;
    int32_t t_1 = 265011886;
    {
        const int32_t z = observer->y[next + 9u][0];
        t_0 += FIXED_GAINS_0[0] * z;
        t_1 += FIXED_GAINS_1[0] * z;
    }
    {
        const int32_t z = observer->y[next + 8u][0];
        t_0 += FIXED_GAINS_0[1] * z;
        t_1 += FIXED_GAINS_1[1] * z;
    }
    {
        const int32_t z = observer->y[next + 7u][0];
        t_0 += FIXED_GAINS_0[2] * z;
        t_1 += FIXED_GAINS_1[2] * z;
    }
    {
        const int32_t z = observer->y[next + 6u][0];
        t_0 += FIXED_GAINS_0[3] * z;
        t_1 += FIXED_GAINS_1[3] * z;
    }
    {
        const int32_t z = observer->y[next + 5u][0];
        t_0 += FIXED_GAINS_0[4] * z;
        t_1 += FIXED_GAINS_1[4] * z;
    }
    {
        const int32_t z = observer->y[next + 4u][0];
        t_0 += FIXED_GAINS_0[5] * z;
        t_1 += FIXED_GAINS_1[5] * z;
    }
    {
        const int32_t z = observer->y[next + 3u][0];
        t_0 += FIXED_GAINS_0[6] * z;
        t_1 += FIXED_GAINS_1[6] * z;
    }
    {
        const int32_t z = observer->y[next + 2u][0];
        t_0 += FIXED_GAINS_0[7] * z;
        t_1 += FIXED_GAINS_1[7] * z;
    }
    {
        const int32_t z = observer->y[next + 1u][0];
        t_0 += FIXED_GAINS_0[8] * z;
        t_1 += FIXED_GAINS_1[8] * z;
    }
    {
        const int32_t z = observer->y[next + 0u][0];
        t_0 += FIXED_GAINS_0[9] * z;
        t_1 += FIXED_GAINS_1[9] * z;
    }
    fixed_evaluate(t_0, FIXED_SEGMENTS_0, 22u, 7u, 15u, 415236095, &values[0], &saturation[0]);
    fixed_evaluate(t_1, FIXED_SEGMENTS_1, 28u, 13u, 15u, 536870911, &values[1], &saturation[1]);
    return VANDERPOL_UNCERTAIN_OK;
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
    const float t0 = x[0];
    const float t1 = x[1];
    out[0] = t0;
    out[1] = t1;
}

/* One EKF sample with its measurement: out = (x(k|k), x+, P+, nis) from (x, P), nis the normalised innovation squared, as the Rust file's ekf_measured. */
static void ekf_measured(const float *x, const float *p, const float *y, const float *u, float *out) {
    (void)u;
    const float t0 = x[0];
    const float t1 = x[1];
    const float t2 = p[0];
    const float t3 = p[1];
    const float t4 = p[2];
    const float t5 = t0 + t1;
    const float t6 = 1.0f;
    const float t7 = t2 + t3;
    const float t8 = t3 + t4;
    const float t9 = 0.2f;
    const float t10 = t9 + t7;
    const float t11 = t10 + t8;
    const float t12 = t6 / t11;
    const float t13 = t7 * t12;
    const float t14 = t8 * t12;
    const float t15 = y[0];
    const float t16 = t15 - t5;
    const float t17 = t13 * t16;
    const float t18 = t0 + t17;
    const float t19 = t14 * t16;
    const float t20 = t1 + t19;
    const float t21 = t16 * t16;
    const float t22 = t21 * t12;
    const float t23 = t6 - t13;
    const float t24 = -t13;
    const float t25 = -t14;
    const float t26 = t6 - t14;
    const float t27 = t23 * t2;
    const float t28 = t24 * t3;
    const float t29 = t27 + t28;
    const float t30 = t23 * t3;
    const float t31 = t24 * t4;
    const float t32 = t30 + t31;
    const float t33 = t25 * t2;
    const float t34 = t26 * t3;
    const float t35 = t33 + t34;
    const float t36 = t25 * t3;
    const float t37 = t26 * t4;
    const float t38 = t36 + t37;
    const float t39 = t29 * t23;
    const float t40 = t32 * t24;
    const float t41 = t39 + t40;
    const float t42 = t29 * t25;
    const float t43 = t32 * t26;
    const float t44 = t42 + t43;
    const float t45 = t35 * t25;
    const float t46 = t38 * t26;
    const float t47 = t45 + t46;
    const float t48 = t13 * t9;
    const float t49 = t48 * t13;
    const float t50 = t41 + t49;
    const float t51 = t48 * t14;
    const float t52 = t44 + t51;
    const float t53 = t14 * t9;
    const float t54 = t53 * t14;
    const float t55 = t47 + t54;
    const float t56 = 0.1f;
    const float t57 = 2.0f;
    const float t58 = 6.0f;
    const float t59 = t56 / t57;
    const float t60 = t56 / t58;
    const float t61 = -t20;
    const float t62 = -1.0f;
    const float t63 = 4.0f /* a */;
    const float t64 = t63 * t18;
    const float t65 = 1.0f /* b */;
    const float t66 = t18 * t18;
    const float t67 = t65 - t66;
    const float t68 = t67 * t20;
    const float t69 = t64 + t68;
    const float t70 = t57 * t18;
    const float t71 = -t70;
    const float t72 = t71 * t20;
    const float t73 = t63 + t72;
    const float t74 = t59 * t61;
    const float t75 = t18 + t74;
    const float t76 = t59 * t69;
    const float t77 = t20 + t76;
    const float t78 = -t59;
    const float t79 = t59 * t73;
    const float t80 = t59 * t67;
    const float t81 = t6 + t80;
    const float t82 = -t77;
    const float t83 = t63 * t75;
    const float t84 = t75 * t75;
    const float t85 = t65 - t84;
    const float t86 = t85 * t77;
    const float t87 = t83 + t86;
    const float t88 = t57 * t75;
    const float t89 = -t88;
    const float t90 = t89 * t77;
    const float t91 = t63 + t90;
    const float t92 = -t79;
    const float t93 = -t81;
    const float t94 = t85 * t79;
    const float t95 = t91 + t94;
    const float t96 = t91 * t78;
    const float t97 = t85 * t81;
    const float t98 = t96 + t97;
    const float t99 = t59 * t82;
    const float t100 = t18 + t99;
    const float t101 = t59 * t87;
    const float t102 = t20 + t101;
    const float t103 = t59 * t92;
    const float t104 = t6 + t103;
    const float t105 = t59 * t93;
    const float t106 = t59 * t95;
    const float t107 = t59 * t98;
    const float t108 = t6 + t107;
    const float t109 = -t102;
    const float t110 = t63 * t100;
    const float t111 = t100 * t100;
    const float t112 = t65 - t111;
    const float t113 = t112 * t102;
    const float t114 = t110 + t113;
    const float t115 = t57 * t100;
    const float t116 = -t115;
    const float t117 = t116 * t102;
    const float t118 = t63 + t117;
    const float t119 = -t106;
    const float t120 = -t108;
    const float t121 = t118 * t104;
    const float t122 = t112 * t106;
    const float t123 = t121 + t122;
    const float t124 = t118 * t105;
    const float t125 = t112 * t108;
    const float t126 = t124 + t125;
    const float t127 = t56 * t109;
    const float t128 = t18 + t127;
    const float t129 = t56 * t114;
    const float t130 = t20 + t129;
    const float t131 = t56 * t119;
    const float t132 = t6 + t131;
    const float t133 = t56 * t120;
    const float t134 = t56 * t123;
    const float t135 = t56 * t126;
    const float t136 = t6 + t135;
    const float t137 = -t130;
    const float t138 = t63 * t128;
    const float t139 = t128 * t128;
    const float t140 = t65 - t139;
    const float t141 = t140 * t130;
    const float t142 = t138 + t141;
    const float t143 = t57 * t128;
    const float t144 = -t143;
    const float t145 = t144 * t130;
    const float t146 = t63 + t145;
    const float t147 = -t134;
    const float t148 = -t136;
    const float t149 = t146 * t132;
    const float t150 = t140 * t134;
    const float t151 = t149 + t150;
    const float t152 = t146 * t133;
    const float t153 = t140 * t136;
    const float t154 = t152 + t153;
    const float t155 = t82 + t109;
    const float t156 = t57 * t155;
    const float t157 = t61 + t156;
    const float t158 = t157 + t137;
    const float t159 = t60 * t158;
    const float t160 = t18 + t159;
    const float t161 = t87 + t114;
    const float t162 = t57 * t161;
    const float t163 = t69 + t162;
    const float t164 = t163 + t142;
    const float t165 = t60 * t164;
    const float t166 = t20 + t165;
    const float t167 = t92 + t119;
    const float t168 = t57 * t167;
    const float t169 = t168 + t147;
    const float t170 = t60 * t169;
    const float t171 = t6 + t170;
    const float t172 = t93 + t120;
    const float t173 = t57 * t172;
    const float t174 = t62 + t173;
    const float t175 = t174 + t148;
    const float t176 = t60 * t175;
    const float t177 = t95 + t123;
    const float t178 = t57 * t177;
    const float t179 = t73 + t178;
    const float t180 = t179 + t151;
    const float t181 = t60 * t180;
    const float t182 = t98 + t126;
    const float t183 = t57 * t182;
    const float t184 = t67 + t183;
    const float t185 = t184 + t154;
    const float t186 = t60 * t185;
    const float t187 = t6 + t186;
    const float t188 = t171 * t50;
    const float t189 = t176 * t52;
    const float t190 = t188 + t189;
    const float t191 = t171 * t52;
    const float t192 = t176 * t55;
    const float t193 = t191 + t192;
    const float t194 = t181 * t50;
    const float t195 = t187 * t52;
    const float t196 = t194 + t195;
    const float t197 = t181 * t52;
    const float t198 = t187 * t55;
    const float t199 = t197 + t198;
    const float t200 = t190 * t171;
    const float t201 = t193 * t176;
    const float t202 = t200 + t201;
    const float t203 = t190 * t181;
    const float t204 = t193 * t187;
    const float t205 = t203 + t204;
    const float t206 = t196 * t181;
    const float t207 = t199 * t187;
    const float t208 = t206 + t207;
    const float t209 = 0.0028291305f;
    const float t210 = t202 + t209;
    const float t211 = 0.033209372f;
    const float t212 = t208 + t211;
    out[0] = t18;
    out[1] = t20;
    out[2] = t160;
    out[3] = t166;
    out[4] = t210;
    out[5] = t205;
    out[6] = t212;
    out[7] = t22;
}

/* One EKF sample without its measurement: out = (x+, P+) from (x, P), as the Rust file's ekf_unmeasured. */
static void ekf_unmeasured(const float *x, const float *p, const float *u, float *out) {
    (void)u;
    const float t0 = x[0];
    const float t1 = x[1];
    const float t2 = p[0];
    const float t3 = p[1];
    const float t4 = p[2];
    const float t5 = 0.1f;
    const float t6 = 2.0f;
    const float t7 = 6.0f;
    const float t8 = t5 / t6;
    const float t9 = t5 / t7;
    const float t10 = -t1;
    const float t11 = -1.0f;
    const float t12 = 4.0f /* a */;
    const float t13 = t12 * t0;
    const float t14 = 1.0f /* b */;
    const float t15 = t0 * t0;
    const float t16 = t14 - t15;
    const float t17 = t16 * t1;
    const float t18 = t13 + t17;
    const float t19 = t6 * t0;
    const float t20 = -t19;
    const float t21 = t20 * t1;
    const float t22 = t12 + t21;
    const float t23 = t8 * t10;
    const float t24 = t0 + t23;
    const float t25 = t8 * t18;
    const float t26 = t1 + t25;
    const float t27 = 1.0f;
    const float t28 = -t8;
    const float t29 = t8 * t22;
    const float t30 = t8 * t16;
    const float t31 = t27 + t30;
    const float t32 = -t26;
    const float t33 = t12 * t24;
    const float t34 = t24 * t24;
    const float t35 = t14 - t34;
    const float t36 = t35 * t26;
    const float t37 = t33 + t36;
    const float t38 = t6 * t24;
    const float t39 = -t38;
    const float t40 = t39 * t26;
    const float t41 = t12 + t40;
    const float t42 = -t29;
    const float t43 = -t31;
    const float t44 = t35 * t29;
    const float t45 = t41 + t44;
    const float t46 = t41 * t28;
    const float t47 = t35 * t31;
    const float t48 = t46 + t47;
    const float t49 = t8 * t32;
    const float t50 = t0 + t49;
    const float t51 = t8 * t37;
    const float t52 = t1 + t51;
    const float t53 = t8 * t42;
    const float t54 = t27 + t53;
    const float t55 = t8 * t43;
    const float t56 = t8 * t45;
    const float t57 = t8 * t48;
    const float t58 = t27 + t57;
    const float t59 = -t52;
    const float t60 = t12 * t50;
    const float t61 = t50 * t50;
    const float t62 = t14 - t61;
    const float t63 = t62 * t52;
    const float t64 = t60 + t63;
    const float t65 = t6 * t50;
    const float t66 = -t65;
    const float t67 = t66 * t52;
    const float t68 = t12 + t67;
    const float t69 = -t56;
    const float t70 = -t58;
    const float t71 = t68 * t54;
    const float t72 = t62 * t56;
    const float t73 = t71 + t72;
    const float t74 = t68 * t55;
    const float t75 = t62 * t58;
    const float t76 = t74 + t75;
    const float t77 = t5 * t59;
    const float t78 = t0 + t77;
    const float t79 = t5 * t64;
    const float t80 = t1 + t79;
    const float t81 = t5 * t69;
    const float t82 = t27 + t81;
    const float t83 = t5 * t70;
    const float t84 = t5 * t73;
    const float t85 = t5 * t76;
    const float t86 = t27 + t85;
    const float t87 = -t80;
    const float t88 = t12 * t78;
    const float t89 = t78 * t78;
    const float t90 = t14 - t89;
    const float t91 = t90 * t80;
    const float t92 = t88 + t91;
    const float t93 = t6 * t78;
    const float t94 = -t93;
    const float t95 = t94 * t80;
    const float t96 = t12 + t95;
    const float t97 = -t84;
    const float t98 = -t86;
    const float t99 = t96 * t82;
    const float t100 = t90 * t84;
    const float t101 = t99 + t100;
    const float t102 = t96 * t83;
    const float t103 = t90 * t86;
    const float t104 = t102 + t103;
    const float t105 = t32 + t59;
    const float t106 = t6 * t105;
    const float t107 = t10 + t106;
    const float t108 = t107 + t87;
    const float t109 = t9 * t108;
    const float t110 = t0 + t109;
    const float t111 = t37 + t64;
    const float t112 = t6 * t111;
    const float t113 = t18 + t112;
    const float t114 = t113 + t92;
    const float t115 = t9 * t114;
    const float t116 = t1 + t115;
    const float t117 = t42 + t69;
    const float t118 = t6 * t117;
    const float t119 = t118 + t97;
    const float t120 = t9 * t119;
    const float t121 = t27 + t120;
    const float t122 = t43 + t70;
    const float t123 = t6 * t122;
    const float t124 = t11 + t123;
    const float t125 = t124 + t98;
    const float t126 = t9 * t125;
    const float t127 = t45 + t73;
    const float t128 = t6 * t127;
    const float t129 = t22 + t128;
    const float t130 = t129 + t101;
    const float t131 = t9 * t130;
    const float t132 = t48 + t76;
    const float t133 = t6 * t132;
    const float t134 = t16 + t133;
    const float t135 = t134 + t104;
    const float t136 = t9 * t135;
    const float t137 = t27 + t136;
    const float t138 = t121 * t2;
    const float t139 = t126 * t3;
    const float t140 = t138 + t139;
    const float t141 = t121 * t3;
    const float t142 = t126 * t4;
    const float t143 = t141 + t142;
    const float t144 = t131 * t2;
    const float t145 = t137 * t3;
    const float t146 = t144 + t145;
    const float t147 = t131 * t3;
    const float t148 = t137 * t4;
    const float t149 = t147 + t148;
    const float t150 = t140 * t121;
    const float t151 = t143 * t126;
    const float t152 = t150 + t151;
    const float t153 = t140 * t131;
    const float t154 = t143 * t137;
    const float t155 = t153 + t154;
    const float t156 = t146 * t131;
    const float t157 = t149 * t137;
    const float t158 = t156 + t157;
    const float t159 = 0.0028291305f;
    const float t160 = t152 + t159;
    const float t161 = 0.033209372f;
    const float t162 = t158 + t161;
    out[0] = t110;
    out[1] = t116;
    out[2] = t160;
    out[3] = t155;
    out[4] = t162;
}

/* The EKF's start: the centre of the state box and P(0)'s upper triangle. */
static const float EKF_X0[VANDERPOL_UNCERTAIN_STATES] = {
    0.0f, 0.0f
};
static const float EKF_P0[VANDERPOL_UNCERTAIN_COVARIANCE] = {
    1.5927348f, 0.0f, 19.371712f
};

/* The EKF's prediction alone (a lost output), taken when finite. */
static void ekf_predict(float *x, float *p, const float *u) {
    float out[VANDERPOL_UNCERTAIN_STATES + VANDERPOL_UNCERTAIN_COVARIANCE];
    ekf_unmeasured(x, p, u, out);
    if (all_finite(out, VANDERPOL_UNCERTAIN_STATES + VANDERPOL_UNCERTAIN_COVARIANCE)) {
        memcpy(x, out, VANDERPOL_UNCERTAIN_STATES * sizeof *x);
        memcpy(p, out + VANDERPOL_UNCERTAIN_STATES, VANDERPOL_UNCERTAIN_COVARIANCE * sizeof *p);
    }
}

/* The EKF's sample with its measurement, taken when finite (1, the estimate x(k|k) in
 * `estimate`, its normalised innovation squared in `*nis`). */
static int ekf_measure(float *x, float *p, const float *y, const float *u, float *estimate, float *nis) {
    float out[2u * VANDERPOL_UNCERTAIN_STATES + VANDERPOL_UNCERTAIN_COVARIANCE + 1u];
    ekf_measured(x, p, y, u, out);
    if (!all_finite(out + VANDERPOL_UNCERTAIN_STATES, VANDERPOL_UNCERTAIN_STATES + VANDERPOL_UNCERTAIN_COVARIANCE)) {
        return 0;
    }
    *nis = out[2u * VANDERPOL_UNCERTAIN_STATES + VANDERPOL_UNCERTAIN_COVARIANCE];
    memcpy(estimate, out, VANDERPOL_UNCERTAIN_STATES * sizeof *x);
    memcpy(x, out + VANDERPOL_UNCERTAIN_STATES, VANDERPOL_UNCERTAIN_STATES * sizeof *x);
    memcpy(p, out + 2u * VANDERPOL_UNCERTAIN_STATES, VANDERPOL_UNCERTAIN_COVARIANCE * sizeof *p);
    return 1;
}


static void ekf_box_fresh(vanderpol_uncertain_ekf_box *o) {
    memcpy(o->x, EKF_X0, sizeof o->x);
    memcpy(o->p, EKF_P0, sizeof o->p);
    o->chi = 1.0f;
}

static vanderpol_uncertain_status ekf_box_sample(vanderpol_uncertain_ekf_box *o, const float *y, const float *u) {
    float estimate[VANDERPOL_UNCERTAIN_STATES];
    float nis;
    unsigned i;
    if (!inputs_finite(u)) {
        return VANDERPOL_UNCERTAIN_REFUSED;
    }
    if (!accepts(y, u)) {
        ekf_predict(o->x, o->p, u);
        return VANDERPOL_UNCERTAIN_REFUSED;
    }
    if (!ekf_measure(o->x, o->p, y, u, estimate, &nis)) {
        ekf_box_fresh(o);
        return VANDERPOL_UNCERTAIN_RESTARTED;
    }
    /* The chi-squared watch (firmware::watch): the mean of the normalised innovations squared. */
    o->chi = o->chi + 0.1f * (nis - o->chi);
    if (!(o->chi <= 1024.0f)) {
        ekf_box_fresh(o);
        return VANDERPOL_UNCERTAIN_RESTARTED;
    }
    targets(estimate, u, o->values);
    for (i = 0u; i < VANDERPOL_UNCERTAIN_TARGETS; ++i) {
        o->flags[i] = VANDERPOL_UNCERTAIN_INSIDE;
    }
    o->ready = 1;
    return VANDERPOL_UNCERTAIN_OK;
}

void vanderpol_uncertain_ekf_box_init(vanderpol_uncertain_ekf_box *o) {
    ekf_box_fresh(o);
    o->ready = 0;
    o->refused = 0u;
    o->restarts = 0u;
}

vanderpol_uncertain_status vanderpol_uncertain_ekf_box_push(vanderpol_uncertain_ekf_box *o, const float *y, const float *u) {
    const vanderpol_uncertain_status status = ekf_box_sample(o, y, u);
    if (status == VANDERPOL_UNCERTAIN_REFUSED && o->refused != UINT32_MAX) {
        ++o->refused;
    } else if (status == VANDERPOL_UNCERTAIN_RESTARTED && o->restarts != UINT32_MAX) {
        ++o->restarts;
    }
    return status;
}

vanderpol_uncertain_status vanderpol_uncertain_ekf_box_estimate(const vanderpol_uncertain_ekf_box *o, float *values, vanderpol_uncertain_saturation *saturation) {
    if (!o->ready) {
        return VANDERPOL_UNCERTAIN_NO_ESTIMATE_YET;
    }
    memcpy(values, o->values, sizeof o->values);
    memcpy(saturation, o->flags, sizeof o->flags);
    return VANDERPOL_UNCERTAIN_OK;
}

/* One UKF sample with its measurement: out = (x(k|k), x+, P+, nis) from (x, P), nis the normalised innovation squared, as the Rust file's ukf_measured. */
static void ukf_measured(const float *x, const float *p, const float *y, const float *u, float *out) {
    (void)u;
    const float t0 = x[0];
    const float t1 = x[1];
    const float t2 = p[0];
    const float t3 = p[1];
    const float t4 = p[2];
    const float t5 = 1.0f;
    const float t6 = 1.1920929e-7f;
    const float t7 = fabsf(t2);
    const float t8 = t6 * t7;
    const float t9 = 1.1754944e-38f;
    const float t10 = t8 + t9;
    const float t11 = select_float(!(t2 >= t10), t10, t2);
    const float t12 = sqrtf(t11);
    const float t13 = t5 / t12;
    const float t14 = t3 * t13;
    const float t15 = t14 * t14;
    const float t16 = t4 - t15;
    const float t17 = fabsf(t4);
    const float t18 = t6 * t17;
    const float t19 = t18 + t9;
    const float t20 = select_float(!(t16 >= t19), t19, t16);
    const float t21 = sqrtf(t20);
    const float t22 = 1.4142135f;
    const float t23 = t22 * t12;
    const float t24 = t0 + t23;
    const float t25 = t22 * t14;
    const float t26 = t1 + t25;
    const float t27 = t22 * t21;
    const float t28 = t1 + t27;
    const float t29 = -1.4142135f;
    const float t30 = t29 * t12;
    const float t31 = t0 + t30;
    const float t32 = t29 * t14;
    const float t33 = t1 + t32;
    const float t34 = t29 * t21;
    const float t35 = t1 + t34;
    const float t36 = t24 + t26;
    const float t37 = t0 + t28;
    const float t38 = t31 + t33;
    const float t39 = t0 + t35;
    const float t40 = 0.25f;
    const float t41 = t36 + t37;
    const float t42 = t41 + t38;
    const float t43 = t42 + t39;
    const float t44 = t40 * t43;
    const float t45 = t36 - t44;
    const float t46 = t37 - t44;
    const float t47 = t38 - t44;
    const float t48 = t39 - t44;
    const float t49 = t24 - t0;
    const float t50 = t26 - t1;
    const float t51 = t28 - t1;
    const float t52 = t31 - t0;
    const float t53 = t33 - t1;
    const float t54 = t35 - t1;
    const float t55 = t45 * t45;
    const float t56 = t46 * t46;
    const float t57 = t55 + t56;
    const float t58 = t47 * t47;
    const float t59 = t57 + t58;
    const float t60 = t48 * t48;
    const float t61 = t59 + t60;
    const float t62 = t40 * t61;
    const float t63 = 0.2f;
    const float t64 = t62 + t63;
    const float t65 = t49 * t45;
    const float t66 = t52 * t47;
    const float t67 = t65 + t66;
    const float t68 = t40 * t67;
    const float t69 = t50 * t45;
    const float t70 = t51 * t46;
    const float t71 = t69 + t70;
    const float t72 = t53 * t47;
    const float t73 = t71 + t72;
    const float t74 = t54 * t48;
    const float t75 = t73 + t74;
    const float t76 = t40 * t75;
    const float t77 = fabsf(t64);
    const float t78 = t6 * t77;
    const float t79 = t78 + t9;
    const float t80 = select_float(!(t64 >= t79), t79, t64);
    const float t81 = sqrtf(t80);
    const float t82 = t5 / t81;
    const float t83 = t68 * t82;
    const float t84 = t83 * t82;
    const float t85 = t76 * t82;
    const float t86 = t85 * t82;
    const float t87 = y[0];
    const float t88 = t87 - t44;
    const float t89 = t84 * t88;
    const float t90 = t0 + t89;
    const float t91 = t86 * t88;
    const float t92 = t1 + t91;
    const float t93 = t88 * t82;
    const float t94 = t93 * t93;
    const float t95 = t68 * t84;
    const float t96 = t2 - t95;
    const float t97 = t68 * t86;
    const float t98 = t3 - t97;
    const float t99 = t76 * t86;
    const float t100 = t4 - t99;
    const float t101 = fabsf(t96);
    const float t102 = t6 * t101;
    const float t103 = t102 + t9;
    const float t104 = select_float(!(t96 >= t103), t103, t96);
    const float t105 = sqrtf(t104);
    const float t106 = t5 / t105;
    const float t107 = t98 * t106;
    const float t108 = t107 * t107;
    const float t109 = t100 - t108;
    const float t110 = fabsf(t100);
    const float t111 = t6 * t110;
    const float t112 = t111 + t9;
    const float t113 = select_float(!(t109 >= t112), t112, t109);
    const float t114 = sqrtf(t113);
    const float t115 = t22 * t105;
    const float t116 = t90 + t115;
    const float t117 = t22 * t107;
    const float t118 = t92 + t117;
    const float t119 = t22 * t114;
    const float t120 = t92 + t119;
    const float t121 = t29 * t105;
    const float t122 = t90 + t121;
    const float t123 = t29 * t107;
    const float t124 = t92 + t123;
    const float t125 = t29 * t114;
    const float t126 = t92 + t125;
    const float t127 = 0.1f;
    const float t128 = 2.0f;
    const float t129 = 6.0f;
    const float t130 = t127 / t128;
    const float t131 = t127 / t129;
    const float t132 = -t118;
    const float t133 = 4.0f /* a */;
    const float t134 = t133 * t116;
    const float t135 = 1.0f /* b */;
    const float t136 = t116 * t116;
    const float t137 = t135 - t136;
    const float t138 = t137 * t118;
    const float t139 = t134 + t138;
    const float t140 = t130 * t132;
    const float t141 = t116 + t140;
    const float t142 = t130 * t139;
    const float t143 = t118 + t142;
    const float t144 = -t143;
    const float t145 = t133 * t141;
    const float t146 = t141 * t141;
    const float t147 = t135 - t146;
    const float t148 = t147 * t143;
    const float t149 = t145 + t148;
    const float t150 = t130 * t144;
    const float t151 = t116 + t150;
    const float t152 = t130 * t149;
    const float t153 = t118 + t152;
    const float t154 = -t153;
    const float t155 = t133 * t151;
    const float t156 = t151 * t151;
    const float t157 = t135 - t156;
    const float t158 = t157 * t153;
    const float t159 = t155 + t158;
    const float t160 = t127 * t154;
    const float t161 = t116 + t160;
    const float t162 = t127 * t159;
    const float t163 = t118 + t162;
    const float t164 = -t163;
    const float t165 = t133 * t161;
    const float t166 = t161 * t161;
    const float t167 = t135 - t166;
    const float t168 = t167 * t163;
    const float t169 = t165 + t168;
    const float t170 = t144 + t154;
    const float t171 = t128 * t170;
    const float t172 = t132 + t171;
    const float t173 = t172 + t164;
    const float t174 = t131 * t173;
    const float t175 = t116 + t174;
    const float t176 = t149 + t159;
    const float t177 = t128 * t176;
    const float t178 = t139 + t177;
    const float t179 = t178 + t169;
    const float t180 = t131 * t179;
    const float t181 = t118 + t180;
    const float t182 = -t120;
    const float t183 = t133 * t90;
    const float t184 = t90 * t90;
    const float t185 = t135 - t184;
    const float t186 = t185 * t120;
    const float t187 = t183 + t186;
    const float t188 = t130 * t182;
    const float t189 = t90 + t188;
    const float t190 = t130 * t187;
    const float t191 = t120 + t190;
    const float t192 = -t191;
    const float t193 = t133 * t189;
    const float t194 = t189 * t189;
    const float t195 = t135 - t194;
    const float t196 = t195 * t191;
    const float t197 = t193 + t196;
    const float t198 = t130 * t192;
    const float t199 = t90 + t198;
    const float t200 = t130 * t197;
    const float t201 = t120 + t200;
    const float t202 = -t201;
    const float t203 = t133 * t199;
    const float t204 = t199 * t199;
    const float t205 = t135 - t204;
    const float t206 = t205 * t201;
    const float t207 = t203 + t206;
    const float t208 = t127 * t202;
    const float t209 = t90 + t208;
    const float t210 = t127 * t207;
    const float t211 = t120 + t210;
    const float t212 = -t211;
    const float t213 = t133 * t209;
    const float t214 = t209 * t209;
    const float t215 = t135 - t214;
    const float t216 = t215 * t211;
    const float t217 = t213 + t216;
    const float t218 = t192 + t202;
    const float t219 = t128 * t218;
    const float t220 = t182 + t219;
    const float t221 = t220 + t212;
    const float t222 = t131 * t221;
    const float t223 = t90 + t222;
    const float t224 = t197 + t207;
    const float t225 = t128 * t224;
    const float t226 = t187 + t225;
    const float t227 = t226 + t217;
    const float t228 = t131 * t227;
    const float t229 = t120 + t228;
    const float t230 = -t124;
    const float t231 = t133 * t122;
    const float t232 = t122 * t122;
    const float t233 = t135 - t232;
    const float t234 = t233 * t124;
    const float t235 = t231 + t234;
    const float t236 = t130 * t230;
    const float t237 = t122 + t236;
    const float t238 = t130 * t235;
    const float t239 = t124 + t238;
    const float t240 = -t239;
    const float t241 = t133 * t237;
    const float t242 = t237 * t237;
    const float t243 = t135 - t242;
    const float t244 = t243 * t239;
    const float t245 = t241 + t244;
    const float t246 = t130 * t240;
    const float t247 = t122 + t246;
    const float t248 = t130 * t245;
    const float t249 = t124 + t248;
    const float t250 = -t249;
    const float t251 = t133 * t247;
    const float t252 = t247 * t247;
    const float t253 = t135 - t252;
    const float t254 = t253 * t249;
    const float t255 = t251 + t254;
    const float t256 = t127 * t250;
    const float t257 = t122 + t256;
    const float t258 = t127 * t255;
    const float t259 = t124 + t258;
    const float t260 = -t259;
    const float t261 = t133 * t257;
    const float t262 = t257 * t257;
    const float t263 = t135 - t262;
    const float t264 = t263 * t259;
    const float t265 = t261 + t264;
    const float t266 = t240 + t250;
    const float t267 = t128 * t266;
    const float t268 = t230 + t267;
    const float t269 = t268 + t260;
    const float t270 = t131 * t269;
    const float t271 = t122 + t270;
    const float t272 = t245 + t255;
    const float t273 = t128 * t272;
    const float t274 = t235 + t273;
    const float t275 = t274 + t265;
    const float t276 = t131 * t275;
    const float t277 = t124 + t276;
    const float t278 = -t126;
    const float t279 = t185 * t126;
    const float t280 = t183 + t279;
    const float t281 = t130 * t278;
    const float t282 = t90 + t281;
    const float t283 = t130 * t280;
    const float t284 = t126 + t283;
    const float t285 = -t284;
    const float t286 = t133 * t282;
    const float t287 = t282 * t282;
    const float t288 = t135 - t287;
    const float t289 = t288 * t284;
    const float t290 = t286 + t289;
    const float t291 = t130 * t285;
    const float t292 = t90 + t291;
    const float t293 = t130 * t290;
    const float t294 = t126 + t293;
    const float t295 = -t294;
    const float t296 = t133 * t292;
    const float t297 = t292 * t292;
    const float t298 = t135 - t297;
    const float t299 = t298 * t294;
    const float t300 = t296 + t299;
    const float t301 = t127 * t295;
    const float t302 = t90 + t301;
    const float t303 = t127 * t300;
    const float t304 = t126 + t303;
    const float t305 = -t304;
    const float t306 = t133 * t302;
    const float t307 = t302 * t302;
    const float t308 = t135 - t307;
    const float t309 = t308 * t304;
    const float t310 = t306 + t309;
    const float t311 = t285 + t295;
    const float t312 = t128 * t311;
    const float t313 = t278 + t312;
    const float t314 = t313 + t305;
    const float t315 = t131 * t314;
    const float t316 = t90 + t315;
    const float t317 = t290 + t300;
    const float t318 = t128 * t317;
    const float t319 = t280 + t318;
    const float t320 = t319 + t310;
    const float t321 = t131 * t320;
    const float t322 = t126 + t321;
    const float t323 = t175 + t223;
    const float t324 = t323 + t271;
    const float t325 = t324 + t316;
    const float t326 = t40 * t325;
    const float t327 = t181 + t229;
    const float t328 = t327 + t277;
    const float t329 = t328 + t322;
    const float t330 = t40 * t329;
    const float t331 = t175 - t326;
    const float t332 = t181 - t330;
    const float t333 = t223 - t326;
    const float t334 = t229 - t330;
    const float t335 = t271 - t326;
    const float t336 = t277 - t330;
    const float t337 = t316 - t326;
    const float t338 = t322 - t330;
    const float t339 = t331 * t331;
    const float t340 = t333 * t333;
    const float t341 = t339 + t340;
    const float t342 = t335 * t335;
    const float t343 = t341 + t342;
    const float t344 = t337 * t337;
    const float t345 = t343 + t344;
    const float t346 = t40 * t345;
    const float t347 = t331 * t332;
    const float t348 = t333 * t334;
    const float t349 = t347 + t348;
    const float t350 = t335 * t336;
    const float t351 = t349 + t350;
    const float t352 = t337 * t338;
    const float t353 = t351 + t352;
    const float t354 = t40 * t353;
    const float t355 = t332 * t332;
    const float t356 = t334 * t334;
    const float t357 = t355 + t356;
    const float t358 = t336 * t336;
    const float t359 = t357 + t358;
    const float t360 = t338 * t338;
    const float t361 = t359 + t360;
    const float t362 = t40 * t361;
    const float t363 = 0.00011795237f;
    const float t364 = t346 + t363;
    const float t365 = 0.03254314f;
    const float t366 = t362 + t365;
    out[0] = t90;
    out[1] = t92;
    out[2] = t326;
    out[3] = t330;
    out[4] = t364;
    out[5] = t354;
    out[6] = t366;
    out[7] = t94;
}

/* One UKF sample without its measurement: out = (x+, P+) from (x, P), as the Rust file's ukf_unmeasured. */
static void ukf_unmeasured(const float *x, const float *p, const float *u, float *out) {
    (void)u;
    const float t0 = x[0];
    const float t1 = x[1];
    const float t2 = p[0];
    const float t3 = p[1];
    const float t4 = p[2];
    const float t5 = 1.0f;
    const float t6 = 1.1920929e-7f;
    const float t7 = fabsf(t2);
    const float t8 = t6 * t7;
    const float t9 = 1.1754944e-38f;
    const float t10 = t8 + t9;
    const float t11 = select_float(!(t2 >= t10), t10, t2);
    const float t12 = sqrtf(t11);
    const float t13 = t5 / t12;
    const float t14 = t3 * t13;
    const float t15 = t14 * t14;
    const float t16 = t4 - t15;
    const float t17 = fabsf(t4);
    const float t18 = t6 * t17;
    const float t19 = t18 + t9;
    const float t20 = select_float(!(t16 >= t19), t19, t16);
    const float t21 = sqrtf(t20);
    const float t22 = 1.4142135f;
    const float t23 = t22 * t12;
    const float t24 = t0 + t23;
    const float t25 = t22 * t14;
    const float t26 = t1 + t25;
    const float t27 = t22 * t21;
    const float t28 = t1 + t27;
    const float t29 = -1.4142135f;
    const float t30 = t29 * t12;
    const float t31 = t0 + t30;
    const float t32 = t29 * t14;
    const float t33 = t1 + t32;
    const float t34 = t29 * t21;
    const float t35 = t1 + t34;
    const float t36 = 0.1f;
    const float t37 = 2.0f;
    const float t38 = 6.0f;
    const float t39 = t36 / t37;
    const float t40 = t36 / t38;
    const float t41 = -t26;
    const float t42 = 4.0f /* a */;
    const float t43 = t42 * t24;
    const float t44 = 1.0f /* b */;
    const float t45 = t24 * t24;
    const float t46 = t44 - t45;
    const float t47 = t46 * t26;
    const float t48 = t43 + t47;
    const float t49 = t39 * t41;
    const float t50 = t24 + t49;
    const float t51 = t39 * t48;
    const float t52 = t26 + t51;
    const float t53 = -t52;
    const float t54 = t42 * t50;
    const float t55 = t50 * t50;
    const float t56 = t44 - t55;
    const float t57 = t56 * t52;
    const float t58 = t54 + t57;
    const float t59 = t39 * t53;
    const float t60 = t24 + t59;
    const float t61 = t39 * t58;
    const float t62 = t26 + t61;
    const float t63 = -t62;
    const float t64 = t42 * t60;
    const float t65 = t60 * t60;
    const float t66 = t44 - t65;
    const float t67 = t66 * t62;
    const float t68 = t64 + t67;
    const float t69 = t36 * t63;
    const float t70 = t24 + t69;
    const float t71 = t36 * t68;
    const float t72 = t26 + t71;
    const float t73 = -t72;
    const float t74 = t42 * t70;
    const float t75 = t70 * t70;
    const float t76 = t44 - t75;
    const float t77 = t76 * t72;
    const float t78 = t74 + t77;
    const float t79 = t53 + t63;
    const float t80 = t37 * t79;
    const float t81 = t41 + t80;
    const float t82 = t81 + t73;
    const float t83 = t40 * t82;
    const float t84 = t24 + t83;
    const float t85 = t58 + t68;
    const float t86 = t37 * t85;
    const float t87 = t48 + t86;
    const float t88 = t87 + t78;
    const float t89 = t40 * t88;
    const float t90 = t26 + t89;
    const float t91 = -t28;
    const float t92 = t42 * t0;
    const float t93 = t0 * t0;
    const float t94 = t44 - t93;
    const float t95 = t94 * t28;
    const float t96 = t92 + t95;
    const float t97 = t39 * t91;
    const float t98 = t0 + t97;
    const float t99 = t39 * t96;
    const float t100 = t28 + t99;
    const float t101 = -t100;
    const float t102 = t42 * t98;
    const float t103 = t98 * t98;
    const float t104 = t44 - t103;
    const float t105 = t104 * t100;
    const float t106 = t102 + t105;
    const float t107 = t39 * t101;
    const float t108 = t0 + t107;
    const float t109 = t39 * t106;
    const float t110 = t28 + t109;
    const float t111 = -t110;
    const float t112 = t42 * t108;
    const float t113 = t108 * t108;
    const float t114 = t44 - t113;
    const float t115 = t114 * t110;
    const float t116 = t112 + t115;
    const float t117 = t36 * t111;
    const float t118 = t0 + t117;
    const float t119 = t36 * t116;
    const float t120 = t28 + t119;
    const float t121 = -t120;
    const float t122 = t42 * t118;
    const float t123 = t118 * t118;
    const float t124 = t44 - t123;
    const float t125 = t124 * t120;
    const float t126 = t122 + t125;
    const float t127 = t101 + t111;
    const float t128 = t37 * t127;
    const float t129 = t91 + t128;
    const float t130 = t129 + t121;
    const float t131 = t40 * t130;
    const float t132 = t0 + t131;
    const float t133 = t106 + t116;
    const float t134 = t37 * t133;
    const float t135 = t96 + t134;
    const float t136 = t135 + t126;
    const float t137 = t40 * t136;
    const float t138 = t28 + t137;
    const float t139 = -t33;
    const float t140 = t42 * t31;
    const float t141 = t31 * t31;
    const float t142 = t44 - t141;
    const float t143 = t142 * t33;
    const float t144 = t140 + t143;
    const float t145 = t39 * t139;
    const float t146 = t31 + t145;
    const float t147 = t39 * t144;
    const float t148 = t33 + t147;
    const float t149 = -t148;
    const float t150 = t42 * t146;
    const float t151 = t146 * t146;
    const float t152 = t44 - t151;
    const float t153 = t152 * t148;
    const float t154 = t150 + t153;
    const float t155 = t39 * t149;
    const float t156 = t31 + t155;
    const float t157 = t39 * t154;
    const float t158 = t33 + t157;
    const float t159 = -t158;
    const float t160 = t42 * t156;
    const float t161 = t156 * t156;
    const float t162 = t44 - t161;
    const float t163 = t162 * t158;
    const float t164 = t160 + t163;
    const float t165 = t36 * t159;
    const float t166 = t31 + t165;
    const float t167 = t36 * t164;
    const float t168 = t33 + t167;
    const float t169 = -t168;
    const float t170 = t42 * t166;
    const float t171 = t166 * t166;
    const float t172 = t44 - t171;
    const float t173 = t172 * t168;
    const float t174 = t170 + t173;
    const float t175 = t149 + t159;
    const float t176 = t37 * t175;
    const float t177 = t139 + t176;
    const float t178 = t177 + t169;
    const float t179 = t40 * t178;
    const float t180 = t31 + t179;
    const float t181 = t154 + t164;
    const float t182 = t37 * t181;
    const float t183 = t144 + t182;
    const float t184 = t183 + t174;
    const float t185 = t40 * t184;
    const float t186 = t33 + t185;
    const float t187 = -t35;
    const float t188 = t94 * t35;
    const float t189 = t92 + t188;
    const float t190 = t39 * t187;
    const float t191 = t0 + t190;
    const float t192 = t39 * t189;
    const float t193 = t35 + t192;
    const float t194 = -t193;
    const float t195 = t42 * t191;
    const float t196 = t191 * t191;
    const float t197 = t44 - t196;
    const float t198 = t197 * t193;
    const float t199 = t195 + t198;
    const float t200 = t39 * t194;
    const float t201 = t0 + t200;
    const float t202 = t39 * t199;
    const float t203 = t35 + t202;
    const float t204 = -t203;
    const float t205 = t42 * t201;
    const float t206 = t201 * t201;
    const float t207 = t44 - t206;
    const float t208 = t207 * t203;
    const float t209 = t205 + t208;
    const float t210 = t36 * t204;
    const float t211 = t0 + t210;
    const float t212 = t36 * t209;
    const float t213 = t35 + t212;
    const float t214 = -t213;
    const float t215 = t42 * t211;
    const float t216 = t211 * t211;
    const float t217 = t44 - t216;
    const float t218 = t217 * t213;
    const float t219 = t215 + t218;
    const float t220 = t194 + t204;
    const float t221 = t37 * t220;
    const float t222 = t187 + t221;
    const float t223 = t222 + t214;
    const float t224 = t40 * t223;
    const float t225 = t0 + t224;
    const float t226 = t199 + t209;
    const float t227 = t37 * t226;
    const float t228 = t189 + t227;
    const float t229 = t228 + t219;
    const float t230 = t40 * t229;
    const float t231 = t35 + t230;
    const float t232 = 0.25f;
    const float t233 = t84 + t132;
    const float t234 = t233 + t180;
    const float t235 = t234 + t225;
    const float t236 = t232 * t235;
    const float t237 = t90 + t138;
    const float t238 = t237 + t186;
    const float t239 = t238 + t231;
    const float t240 = t232 * t239;
    const float t241 = t84 - t236;
    const float t242 = t90 - t240;
    const float t243 = t132 - t236;
    const float t244 = t138 - t240;
    const float t245 = t180 - t236;
    const float t246 = t186 - t240;
    const float t247 = t225 - t236;
    const float t248 = t231 - t240;
    const float t249 = t241 * t241;
    const float t250 = t243 * t243;
    const float t251 = t249 + t250;
    const float t252 = t245 * t245;
    const float t253 = t251 + t252;
    const float t254 = t247 * t247;
    const float t255 = t253 + t254;
    const float t256 = t232 * t255;
    const float t257 = t241 * t242;
    const float t258 = t243 * t244;
    const float t259 = t257 + t258;
    const float t260 = t245 * t246;
    const float t261 = t259 + t260;
    const float t262 = t247 * t248;
    const float t263 = t261 + t262;
    const float t264 = t232 * t263;
    const float t265 = t242 * t242;
    const float t266 = t244 * t244;
    const float t267 = t265 + t266;
    const float t268 = t246 * t246;
    const float t269 = t267 + t268;
    const float t270 = t248 * t248;
    const float t271 = t269 + t270;
    const float t272 = t232 * t271;
    const float t273 = 0.00011795237f;
    const float t274 = t256 + t273;
    const float t275 = 0.03254314f;
    const float t276 = t272 + t275;
    out[0] = t236;
    out[1] = t240;
    out[2] = t274;
    out[3] = t264;
    out[4] = t276;
}

/* The UKF's start: the centre of the state box and P(0)'s upper triangle. */
static const float UKF_X0[VANDERPOL_UNCERTAIN_STATES] = {
    0.0f, 0.0f
};
static const float UKF_P0[VANDERPOL_UNCERTAIN_COVARIANCE] = {
    1.8518863f, 0.0f, 22.292301f
};

/* The UKF's prediction alone (a lost output), taken when finite. */
static void ukf_predict(float *x, float *p, const float *u) {
    float out[VANDERPOL_UNCERTAIN_STATES + VANDERPOL_UNCERTAIN_COVARIANCE];
    ukf_unmeasured(x, p, u, out);
    if (all_finite(out, VANDERPOL_UNCERTAIN_STATES + VANDERPOL_UNCERTAIN_COVARIANCE)) {
        memcpy(x, out, VANDERPOL_UNCERTAIN_STATES * sizeof *x);
        memcpy(p, out + VANDERPOL_UNCERTAIN_STATES, VANDERPOL_UNCERTAIN_COVARIANCE * sizeof *p);
    }
}

/* The UKF's sample with its measurement, taken when finite (1, the estimate x(k|k) in
 * `estimate`, its normalised innovation squared in `*nis`). */
static int ukf_measure(float *x, float *p, const float *y, const float *u, float *estimate, float *nis) {
    float out[2u * VANDERPOL_UNCERTAIN_STATES + VANDERPOL_UNCERTAIN_COVARIANCE + 1u];
    ukf_measured(x, p, y, u, out);
    if (!all_finite(out + VANDERPOL_UNCERTAIN_STATES, VANDERPOL_UNCERTAIN_STATES + VANDERPOL_UNCERTAIN_COVARIANCE)) {
        return 0;
    }
    *nis = out[2u * VANDERPOL_UNCERTAIN_STATES + VANDERPOL_UNCERTAIN_COVARIANCE];
    memcpy(estimate, out, VANDERPOL_UNCERTAIN_STATES * sizeof *x);
    memcpy(x, out + VANDERPOL_UNCERTAIN_STATES, VANDERPOL_UNCERTAIN_STATES * sizeof *x);
    memcpy(p, out + 2u * VANDERPOL_UNCERTAIN_STATES, VANDERPOL_UNCERTAIN_COVARIANCE * sizeof *p);
    return 1;
}


static void ukf_box_fresh(vanderpol_uncertain_ukf_box *o) {
    memcpy(o->x, UKF_X0, sizeof o->x);
    memcpy(o->p, UKF_P0, sizeof o->p);
    o->chi = 1.0f;
}

static vanderpol_uncertain_status ukf_box_sample(vanderpol_uncertain_ukf_box *o, const float *y, const float *u) {
    float estimate[VANDERPOL_UNCERTAIN_STATES];
    float nis;
    unsigned i;
    if (!inputs_finite(u)) {
        return VANDERPOL_UNCERTAIN_REFUSED;
    }
    if (!accepts(y, u)) {
        ukf_predict(o->x, o->p, u);
        return VANDERPOL_UNCERTAIN_REFUSED;
    }
    if (!ukf_measure(o->x, o->p, y, u, estimate, &nis)) {
        ukf_box_fresh(o);
        return VANDERPOL_UNCERTAIN_RESTARTED;
    }
    /* The chi-squared watch (firmware::watch): the mean of the normalised innovations squared. */
    o->chi = o->chi + 0.1f * (nis - o->chi);
    if (!(o->chi <= 1024.0f)) {
        ukf_box_fresh(o);
        return VANDERPOL_UNCERTAIN_RESTARTED;
    }
    targets(estimate, u, o->values);
    for (i = 0u; i < VANDERPOL_UNCERTAIN_TARGETS; ++i) {
        o->flags[i] = VANDERPOL_UNCERTAIN_INSIDE;
    }
    o->ready = 1;
    return VANDERPOL_UNCERTAIN_OK;
}

void vanderpol_uncertain_ukf_box_init(vanderpol_uncertain_ukf_box *o) {
    ukf_box_fresh(o);
    o->ready = 0;
    o->refused = 0u;
    o->restarts = 0u;
}

vanderpol_uncertain_status vanderpol_uncertain_ukf_box_push(vanderpol_uncertain_ukf_box *o, const float *y, const float *u) {
    const vanderpol_uncertain_status status = ukf_box_sample(o, y, u);
    if (status == VANDERPOL_UNCERTAIN_REFUSED && o->refused != UINT32_MAX) {
        ++o->refused;
    } else if (status == VANDERPOL_UNCERTAIN_RESTARTED && o->restarts != UINT32_MAX) {
        ++o->restarts;
    }
    return status;
}

vanderpol_uncertain_status vanderpol_uncertain_ukf_box_estimate(const vanderpol_uncertain_ukf_box *o, float *values, vanderpol_uncertain_saturation *saturation) {
    if (!o->ready) {
        return VANDERPOL_UNCERTAIN_NO_ESTIMATE_YET;
    }
    memcpy(values, o->values, sizeof o->values);
    memcpy(saturation, o->flags, sizeof o->flags);
    return VANDERPOL_UNCERTAIN_OK;
}

/* The start-up schedule, j = 1 … 30: the blends g_j per state, then the gains K_j (states x
 * outputs, row by row). */
static const float CORRECTED_BLENDS[30][4] = {
{
    0.21296108f, 0.21296108f, 0.1761969f, 0.13654825f
},
{
    0.11916981f, 0.11916981f, 0.12621607f, 0.24141166f
},
{
    0.08273296f, 0.08273296f, 0.10679908f, 0.2821499f
},
{
    0.063360214f, 0.063360214f, 0.09647545f, 0.3038096f
},
{
    0.05133874f, 0.05133874f, 0.09006928f, 0.31725022f
},
{
    0.043151505f, 0.043151505f, 0.085706346f, 0.32640398f
},
{
    0.037216425f, 0.037216425f, 0.08254358f, 0.3330397f
},
{
    0.032716572f, 0.032716572f, 0.080145635f, 0.33807075f
},
{
    0.029187499f, 0.029187499f, 0.07826501f, 0.34201646f
},
{
    0.026345646f, 0.026345646f, 0.0767506f, 0.34519377f
},
{
    0.024008088f, 0.024008088f, 0.07550493f, 0.3478073f
},
{
    0.022051532f, 0.022051532f, 0.074462295f, 0.3499948f
},
{
    0.020389847f, 0.020389847f, 0.07357679f, 0.35185266f
},
{
    0.018961044f, 0.018961044f, 0.07281539f, 0.35345015f
},
{
    0.017719373f, 0.017719373f, 0.07215371f, 0.3548384f
},
{
    0.01663033f, 0.01663033f, 0.07157337f, 0.356056f
},
{
    0.015667401f, 0.015667401f, 0.071060225f, 0.3571326f
},
{
    0.014809881f, 0.014809881f, 0.07060326f, 0.35809135f
},
{
    0.014041359f, 0.014041359f, 0.070193715f, 0.3589506f
},
{
    0.013348662f, 0.013348662f, 0.069824584f, 0.35972506f
},
{
    0.012721098f, 0.012721098f, 0.06949016f, 0.36042672f
},
{
    0.012149892f, 0.012149892f, 0.06918576f, 0.36106536f
},
{
    0.011627778f, 0.011627778f, 0.06890754f, 0.3616491f
},
{
    0.011148688f, 0.011148688f, 0.06865223f, 0.36218476f
},
{
    0.010707516f, 0.010707516f, 0.06841713f, 0.362678f
},
{
    0.01029993f, 0.01029993f, 0.06819993f, 0.3631337f
},
{
    0.009922236f, 0.009922236f, 0.06799866f, 0.363556f
},
{
    0.009571263f, 0.009571263f, 0.06781163f, 0.3639484f
},
{
    0.009244271f, 0.009244271f, 0.06763738f, 0.364314f
},
{
    0.0089388825f, 0.0089388825f, 0.06747463f, 0.36465544f
}
};
static const float CORRECTED_NO_BLEND[4] = { 0.0f };
/* The clamp of each state: its map's learning range. */
static const float CORRECTED_LOWER[VANDERPOL_UNCERTAIN_STATES] = {
    -2.4087043f, -4.7017317f
};
static const float CORRECTED_UPPER[VANDERPOL_UNCERTAIN_STATES] = {
    2.3542836f, 4.83137f
};

/* One sampling period of the model from x, the value alone: out = x+ (corrected_predict). */
static void corrected_predict(const float *x, const float *u, float *out) {
    (void)u;
    const float t0 = x[0];
    const float t1 = x[1];
    const float t2 = 0.1f;
    const float t3 = 2.0f;
    const float t4 = 6.0f;
    const float t5 = t2 / t3;
    const float t6 = t2 / t4;
    const float t7 = -t1;
    const float t8 = 4.0f /* a */;
    const float t9 = t8 * t0;
    const float t10 = 1.0f /* b */;
    const float t11 = t0 * t0;
    const float t12 = t10 - t11;
    const float t13 = t12 * t1;
    const float t14 = t9 + t13;
    const float t15 = t5 * t7;
    const float t16 = t0 + t15;
    const float t17 = t5 * t14;
    const float t18 = t1 + t17;
    const float t19 = -t18;
    const float t20 = t8 * t16;
    const float t21 = t16 * t16;
    const float t22 = t10 - t21;
    const float t23 = t22 * t18;
    const float t24 = t20 + t23;
    const float t25 = t5 * t19;
    const float t26 = t0 + t25;
    const float t27 = t5 * t24;
    const float t28 = t1 + t27;
    const float t29 = -t28;
    const float t30 = t8 * t26;
    const float t31 = t26 * t26;
    const float t32 = t10 - t31;
    const float t33 = t32 * t28;
    const float t34 = t30 + t33;
    const float t35 = t2 * t29;
    const float t36 = t0 + t35;
    const float t37 = t2 * t34;
    const float t38 = t1 + t37;
    const float t39 = -t38;
    const float t40 = t8 * t36;
    const float t41 = t36 * t36;
    const float t42 = t10 - t41;
    const float t43 = t42 * t38;
    const float t44 = t40 + t43;
    const float t45 = t19 + t29;
    const float t46 = t3 * t45;
    const float t47 = t7 + t46;
    const float t48 = t47 + t39;
    const float t49 = t6 * t48;
    const float t50 = t0 + t49;
    const float t51 = t24 + t34;
    const float t52 = t3 * t51;
    const float t53 = t14 + t52;
    const float t54 = t53 + t44;
    const float t55 = t6 * t54;
    const float t56 = t1 + t55;
    out[0] = t50;
    out[1] = t56;
}

/* The correction during the start-up, g = (blends g_j, gains K_j): x before its clamp. */
static void corrected_start_up(const float *x, const float *y, const float *u, const float *f, const float *g, float *out) {
    (void)u;
    const float t0 = x[0];
    const float t1 = x[1];
    const float t2 = t0 + t1;
    const float t3 = y[0];
    const float t4 = t3 - t2;
    const float t5 = g[0];
    const float t6 = f[0];
    const float t7 = t6 - t0;
    const float t8 = t5 * t7;
    const float t9 = t0 + t8;
    const float t10 = g[2];
    const float t11 = t10 * t4;
    const float t12 = t9 + t11;
    const float t13 = g[1];
    const float t14 = f[1];
    const float t15 = t14 - t1;
    const float t16 = t13 * t15;
    const float t17 = t1 + t16;
    const float t18 = g[3];
    const float t19 = t18 * t4;
    const float t20 = t17 + t19;
    out[0] = t12;
    out[1] = t20;
}

/* The correction after the start-up: x before its clamp. */
static void corrected_steady(const float *x, const float *y, const float *u, const float *f, float *out) {
    (void)u;
    (void)f;
    const float t0 = x[0];
    const float t1 = x[1];
    const float t2 = t0 + t1;
    const float t3 = y[0];
    const float t4 = t3 - t2;
    const float t5 = 0.06271116f;
    const float t6 = t5 * t4;
    const float t7 = t0 + t6;
    const float t8 = 0.37464955f;
    const float t9 = t8 * t4;
    const float t10 = t1 + t9;
    out[0] = t7;
    out[1] = t10;
}

/* Each state's map estimate, from the map's rows (a target's or a helper map's). */
static void corrected_map_states(const float *all, float *map) {
    map[0] = all[0];
    map[1] = all[1];
}

/* The targets of a follower's states, flagged with their states' saturation. */
static void corrected_targets_of(const float *states, const vanderpol_uncertain_saturation *state_flags, const float *u,
                                float *values, vanderpol_uncertain_saturation *flags) {
    targets(states, u, values);
    flags[0] = VANDERPOL_UNCERTAIN_INSIDE;
    flags[1] = VANDERPOL_UNCERTAIN_INSIDE;
    flags[0] = state_flags[0];
    flags[1] = state_flags[1];
}

/* Corrector::start: the model's period from the map's first estimate (or from the states after
 * a correction), taken into x when finite. */
static int corrected_start(const float *first, const float *u, float *x) {
    float next[VANDERPOL_UNCERTAIN_STATES];
    corrected_predict(first, u, next);
    if (!all_finite(next, VANDERPOL_UNCERTAIN_STATES)) {
        return 0;
    }
    memcpy(x, next, sizeof next);
    return 1;
}

/* Corrector::follow: the correction of the prediction x (the start-up's blend and gain, or
 * G's), clamped to the states' ranges by selects, then the model's period from it. */
static int corrected_follow(float *x, unsigned j, int start_up, const float *f, const float *y, const float *u,
                            float *states, vanderpol_uncertain_saturation *flags) {
    float raw[VANDERPOL_UNCERTAIN_STATES];
    unsigned i;
    if (start_up) {
        corrected_start_up(x, y, u, f, (j >= 1u && j <= 30u) ? CORRECTED_BLENDS[j - 1u] : CORRECTED_NO_BLEND, raw);
    } else {
        corrected_steady(x, y, u, f, raw);
    }
    for (i = 0u; i < VANDERPOL_UNCERTAIN_STATES; ++i) {
        const int low = !(raw[i] >= CORRECTED_LOWER[i]);
        const int out = low | (raw[i] > CORRECTED_UPPER[i]);
        const float edge = select_float(low, CORRECTED_LOWER[i], CORRECTED_UPPER[i]);
        const uint32_t flag = select_bits(low, (uint32_t)VANDERPOL_UNCERTAIN_LOW, (uint32_t)VANDERPOL_UNCERTAIN_HIGH);
        states[i] = select_float(out, edge, raw[i]);
        flags[i] = (vanderpol_uncertain_saturation)select_bits(out, flag, (uint32_t)VANDERPOL_UNCERTAIN_INSIDE);
    }
    return corrected_start(states, u, x);
}

/* Corrector::predict: a lost output, the model's period from x (no correction). */
static void corrected_lost(float *x, const float *u) {
    (void)corrected_start(x, u, x);
}


static void corrected_fresh(vanderpol_uncertain_corrected *o) {
    vanderpol_uncertain_map_init(&o->window);
    memset(o->x, 0, sizeof o->x);
    o->count = 0u;
    o->started = 0;
}

static vanderpol_uncertain_status corrected_sample(vanderpol_uncertain_corrected *o, const float *y, const float *u) {
    const int start_up = o->count <= 30u;
    float all[VANDERPOL_UNCERTAIN_MAP_ROWS], map[VANDERPOL_UNCERTAIN_STATES], states[VANDERPOL_UNCERTAIN_STATES];
    vanderpol_uncertain_saturation all_flags[VANDERPOL_UNCERTAIN_MAP_ROWS], state_flags[VANDERPOL_UNCERTAIN_STATES];
    int estimated = 0;
    if (!accepts(y, u)) {
        if (o->started && inputs_finite(u)) {
            corrected_lost(o->x, u);
        }
        return VANDERPOL_UNCERTAIN_REFUSED;
    }
    memset(map, 0, sizeof map);
    if (start_up) {
        (void)vanderpol_uncertain_map_push(&o->window, y, u);
        if (o->window.filled < VANDERPOL_UNCERTAIN_HORIZON) {
            return VANDERPOL_UNCERTAIN_OK;
        }
        (void)start_map_estimate(&o->window, all, all_flags);
        corrected_map_states(all, map);
        estimated = 1;
    }
    if (!o->started && estimated) {
        if (!corrected_start(map, u, o->x)) {
            corrected_fresh(o);
            return VANDERPOL_UNCERTAIN_RESTARTED;
        }
        o->started = 1;
        memcpy(o->values, all, sizeof o->values);
        memcpy(o->flags, all_flags, sizeof o->flags);
    } else if (o->started) {
        if (!corrected_follow(o->x, o->count, start_up, map, y, u, states, state_flags)) {
            corrected_fresh(o);
            return VANDERPOL_UNCERTAIN_RESTARTED;
        }
        corrected_targets_of(states, state_flags, u, o->values, o->flags);
    } else {
        return VANDERPOL_UNCERTAIN_OK;
    }
    o->ready = 1;
    o->count = start_up ? o->count + 1u : o->count;
    return VANDERPOL_UNCERTAIN_OK;
}

void vanderpol_uncertain_corrected_init(vanderpol_uncertain_corrected *o) {
    corrected_fresh(o);
    o->ready = 0;
    o->refused = 0u;
    o->restarts = 0u;
}

vanderpol_uncertain_status vanderpol_uncertain_corrected_push(vanderpol_uncertain_corrected *o, const float *y, const float *u) {
    const vanderpol_uncertain_status status = corrected_sample(o, y, u);
    if (status == VANDERPOL_UNCERTAIN_REFUSED && o->refused != UINT32_MAX) {
        ++o->refused;
    } else if (status == VANDERPOL_UNCERTAIN_RESTARTED && o->restarts != UINT32_MAX) {
        ++o->restarts;
    }
    return status;
}

vanderpol_uncertain_status vanderpol_uncertain_corrected_estimate(const vanderpol_uncertain_corrected *o, float *values, vanderpol_uncertain_saturation *saturation) {
    if (!o->ready) {
        return VANDERPOL_UNCERTAIN_NO_ESTIMATE_YET;
    }
    memcpy(values, o->values, sizeof o->values);
    memcpy(saturation, o->flags, sizeof o->flags);
    return VANDERPOL_UNCERTAIN_OK;
}

/* P(N-1)'s upper triangle of the EKF the map starts. */
static const float STARTED_P0[VANDERPOL_UNCERTAIN_COVARIANCE] = {
    0.0066589005f, 0.0f, 0.008897506f
};

/* Each state's map estimate, from the map's rows (a target's or a helper map's). */
static void started_ekf_map_states(const float *all, float *map) {
    map[0] = all[0];
    map[1] = all[1];
}

/* The targets of a follower's states, flagged with their states' saturation. */
static void started_ekf_targets_of(const float *states, const vanderpol_uncertain_saturation *state_flags, const float *u,
                                float *values, vanderpol_uncertain_saturation *flags) {
    targets(states, u, values);
    flags[0] = VANDERPOL_UNCERTAIN_INSIDE;
    flags[1] = VANDERPOL_UNCERTAIN_INSIDE;
    flags[0] = state_flags[0];
    flags[1] = state_flags[1];
}

/* StartedEkf::start: one prediction from the map's states with STARTED_P0, taken when finite;
 * the watched mean at its start. */
static int started_ekf_start(const float *first, const float *u, float *x, float *p, float *chi) {
    float out[VANDERPOL_UNCERTAIN_STATES + VANDERPOL_UNCERTAIN_COVARIANCE];
    ekf_unmeasured(first, STARTED_P0, u, out);
    if (!all_finite(out, VANDERPOL_UNCERTAIN_STATES + VANDERPOL_UNCERTAIN_COVARIANCE)) {
        return 0;
    }
    memcpy(x, out, VANDERPOL_UNCERTAIN_STATES * sizeof *x);
    memcpy(p, out + VANDERPOL_UNCERTAIN_STATES, VANDERPOL_UNCERTAIN_COVARIANCE * sizeof *p);
    *chi = 1.0f;
    return 1;
}

/* StartedEkf::follow: the EKF's sample, every state inside; not taken when the
 * chi-squared watch (firmware::watch) finds the innovations implausible. */
static int started_ekf_follow(float *x, float *p, float *chi, unsigned j, int start_up, const float *map,
                              const float *y, const float *u, float *states, vanderpol_uncertain_saturation *flags) {
    unsigned i;
    float nis;
    (void)j;
    (void)start_up;
    (void)map;
    for (i = 0u; i < VANDERPOL_UNCERTAIN_STATES; ++i) {
        flags[i] = VANDERPOL_UNCERTAIN_INSIDE;
    }
    if (!ekf_measure(x, p, y, u, states, &nis)) {
        return 0;
    }
    *chi = *chi + 0.1f * (nis - *chi);
    return *chi <= 1024.0f;
}


static void ekf_map_fresh(vanderpol_uncertain_ekf_map *o) {
    vanderpol_uncertain_map_init(&o->window);
    memcpy(o->x, EKF_X0, sizeof o->x);
    memcpy(o->p, EKF_P0, sizeof o->p);
    o->count = 0u;
    o->started = 0;
}

static vanderpol_uncertain_status ekf_map_sample(vanderpol_uncertain_ekf_map *o, const float *y, const float *u) {
    const int start_up = o->count <= 0u;
    float all[VANDERPOL_UNCERTAIN_MAP_ROWS], map[VANDERPOL_UNCERTAIN_STATES], states[VANDERPOL_UNCERTAIN_STATES];
    vanderpol_uncertain_saturation all_flags[VANDERPOL_UNCERTAIN_MAP_ROWS], state_flags[VANDERPOL_UNCERTAIN_STATES];
    int estimated = 0;
    if (!accepts(y, u)) {
        if (o->started && inputs_finite(u)) {
            ekf_predict(o->x, o->p, u);
        }
        return VANDERPOL_UNCERTAIN_REFUSED;
    }
    memset(map, 0, sizeof map);
    if (start_up) {
        (void)vanderpol_uncertain_map_push(&o->window, y, u);
        if (o->window.filled < VANDERPOL_UNCERTAIN_HORIZON) {
            return VANDERPOL_UNCERTAIN_OK;
        }
        (void)start_map_estimate(&o->window, all, all_flags);
        started_ekf_map_states(all, map);
        estimated = 1;
    }
    if (!o->started && estimated) {
        if (!started_ekf_start(map, u, o->x, o->p, &o->chi)) {
            ekf_map_fresh(o);
            return VANDERPOL_UNCERTAIN_RESTARTED;
        }
        o->started = 1;
        memcpy(o->values, all, sizeof o->values);
        memcpy(o->flags, all_flags, sizeof o->flags);
    } else if (o->started) {
        if (!started_ekf_follow(o->x, o->p, &o->chi, o->count, start_up, map, y, u, states, state_flags)) {
            ekf_map_fresh(o);
            return VANDERPOL_UNCERTAIN_RESTARTED;
        }
        started_ekf_targets_of(states, state_flags, u, o->values, o->flags);
    } else {
        return VANDERPOL_UNCERTAIN_OK;
    }
    o->ready = 1;
    o->count = start_up ? o->count + 1u : o->count;
    return VANDERPOL_UNCERTAIN_OK;
}

void vanderpol_uncertain_ekf_map_init(vanderpol_uncertain_ekf_map *o) {
    ekf_map_fresh(o);
    o->ready = 0;
    o->refused = 0u;
    o->restarts = 0u;
}

vanderpol_uncertain_status vanderpol_uncertain_ekf_map_push(vanderpol_uncertain_ekf_map *o, const float *y, const float *u) {
    const vanderpol_uncertain_status status = ekf_map_sample(o, y, u);
    if (status == VANDERPOL_UNCERTAIN_REFUSED && o->refused != UINT32_MAX) {
        ++o->refused;
    } else if (status == VANDERPOL_UNCERTAIN_RESTARTED && o->restarts != UINT32_MAX) {
        ++o->restarts;
    }
    return status;
}

vanderpol_uncertain_status vanderpol_uncertain_ekf_map_estimate(const vanderpol_uncertain_ekf_map *o, float *values, vanderpol_uncertain_saturation *saturation) {
    if (!o->ready) {
        return VANDERPOL_UNCERTAIN_NO_ESTIMATE_YET;
    }
    memcpy(values, o->values, sizeof o->values);
    memcpy(saturation, o->flags, sizeof o->flags);
    return VANDERPOL_UNCERTAIN_OK;
}

/* Whether the filter's prediction x (covariance p) and the map's states f disagree:
 * d = sum_i (x_i - f_i)^2 / (P_ii + e_i^2) > threshold, or d is NaN (restart_disagrees). */
static int restart_disagrees(const float *x, const float *p, const float *f) {
    float d = 0.0f;
    float e;
    e = x[0] - f[0];
    d += e * e / (p[0] + 0.066589005f);
    e = x[1] - f[1];
    d += e * e / (p[2] + 0.08897506f);
    return !(d <= 16.0f);
}

static void ekf_restart_fresh(vanderpol_uncertain_ekf_restart *o) {
    vanderpol_uncertain_map_init(&o->window);
    memcpy(o->x, EKF_X0, sizeof o->x);
    memcpy(o->p, EKF_P0, sizeof o->p);
    o->chi = 1.0f;
}

/* firmware::Restarted: the sample to the map's window; from its first estimate on, the map's states
 * against the filter's prediction at every sample, restarted from the map when they disagree;
 * else the filter's sample, restarted (from the map where it has an estimate, else from the start)
 * when its step is not finite or its chi-squared watch finds the innovations implausible. */
static vanderpol_uncertain_status ekf_restart_sample(vanderpol_uncertain_ekf_restart *o, const float *y, const float *u) {
    float all[VANDERPOL_UNCERTAIN_MAP_ROWS], map[VANDERPOL_UNCERTAIN_STATES], states[VANDERPOL_UNCERTAIN_STATES];
    vanderpol_uncertain_saturation all_flags[VANDERPOL_UNCERTAIN_MAP_ROWS], state_flags[VANDERPOL_UNCERTAIN_STATES];
    int mapped = 0;
    if (!accepts(y, u)) {
        if (inputs_finite(u)) {
            ekf_predict(o->x, o->p, u);
        }
        return VANDERPOL_UNCERTAIN_REFUSED;
    }
    (void)vanderpol_uncertain_map_push(&o->window, y, u);
    if (o->window.filled >= VANDERPOL_UNCERTAIN_HORIZON) {
        (void)start_map_estimate(&o->window, all, all_flags);
        started_ekf_map_states(all, map);
        mapped = 1;
        if (restart_disagrees(o->x, o->p, map) && started_ekf_start(map, u, o->x, o->p, &o->chi)) {
            memcpy(o->values, all, sizeof o->values);
            memcpy(o->flags, all_flags, sizeof o->flags);
            o->ready = 1;
            return VANDERPOL_UNCERTAIN_OK;
        }
    }
    if (!started_ekf_follow(o->x, o->p, &o->chi, 1u, 0, NULL, y, u, states, state_flags)) {
        if (!(mapped && started_ekf_start(map, u, o->x, o->p, &o->chi))) {
            memcpy(o->x, EKF_X0, sizeof o->x);
            memcpy(o->p, EKF_P0, sizeof o->p);
            o->chi = 1.0f;
        }
        return VANDERPOL_UNCERTAIN_RESTARTED;
    }
    started_ekf_targets_of(states, state_flags, u, o->values, o->flags);
    o->ready = 1;
    return VANDERPOL_UNCERTAIN_OK;
}

void vanderpol_uncertain_ekf_restart_init(vanderpol_uncertain_ekf_restart *o) {
    ekf_restart_fresh(o);
    o->ready = 0;
    o->refused = 0u;
    o->restarts = 0u;
}

vanderpol_uncertain_status vanderpol_uncertain_ekf_restart_push(vanderpol_uncertain_ekf_restart *o, const float *y, const float *u) {
    const vanderpol_uncertain_status status = ekf_restart_sample(o, y, u);
    if (status == VANDERPOL_UNCERTAIN_REFUSED && o->refused != UINT32_MAX) {
        ++o->refused;
    } else if (status == VANDERPOL_UNCERTAIN_RESTARTED && o->restarts != UINT32_MAX) {
        ++o->restarts;
    }
    return status;
}

vanderpol_uncertain_status vanderpol_uncertain_ekf_restart_estimate(const vanderpol_uncertain_ekf_restart *o, float *values, vanderpol_uncertain_saturation *saturation) {
    if (!o->ready) {
        return VANDERPOL_UNCERTAIN_NO_ESTIMATE_YET;
    }
    memcpy(values, o->values, sizeof o->values);
    memcpy(saturation, o->flags, sizeof o->flags);
    return VANDERPOL_UNCERTAIN_OK;
}

/* The model's derivative f(x, u), then its Jacobian row by row (the Rust file's Plant::derivative). */
static void model_derivative(const float *x, const float *u, float *out) {
    (void)u;
    const float t0 = x[1];
    const float t1 = -t0;
    const float t2 = -0.0f;
    const float t3 = -1.0f;
    const float t4 = 4.0f /* a */;
    const float t5 = x[0];
    const float t6 = t4 * t5;
    const float t7 = 1.0f /* b */;
    const float t8 = t5 * t5;
    const float t9 = t7 - t8;
    const float t10 = t9 * t0;
    const float t11 = t6 + t10;
    const float t12 = 2.0f;
    const float t13 = t12 * t5;
    const float t14 = -t13;
    const float t15 = t14 * t0;
    const float t16 = t4 + t15;
    out[0] = t1;
    out[1] = t11;
    out[2] = t2;
    out[3] = t3;
    out[4] = t16;
    out[5] = t9;
}

/* The model's outputs h(x, u), then their Jacobian row by row (the Rust file's Plant::output). */
static void model_output(const float *x, const float *u, float *out) {
    (void)u;
    const float t0 = x[0];
    const float t1 = x[1];
    const float t2 = t0 + t1;
    const float t3 = 1.0f;
    out[0] = t2;
    out[1] = t3;
    out[2] = t3;
}

/* The moving-horizon estimate's constants: the outputs' weights 1 / sigma^2, the prior's weight per
 * state, the learning box, the first window's start, Levenberg's damping, the RK4 substep. */
static const float MHE_WEIGHTS[VANDERPOL_UNCERTAIN_OUTPUTS] = {
    5.0f
};
static const float MHE_PRIOR[VANDERPOL_UNCERTAIN_STATES] = {
    378.56992f, 64.13714f
};
static const float MHE_LOWER[VANDERPOL_UNCERTAIN_STATES] = {
    -2.5734026f, -6.151861f
};
static const float MHE_UPPER[VANDERPOL_UNCERTAIN_STATES] = {
    2.5661693f, 6.334768f
};
static const float MHE_START[VANDERPOL_UNCERTAIN_STATES] = {
    0.0f, 0.0f
};
static const float MHE_DAMPING = 1e-6f;
static const float MHE_H = 0.1f;
/* The chi-square watch over the windows' output costs (firmware::watch): the mean's start N m, its
 * gain 1 / W and its limit tau N m. */
static const float MHE_WATCH_START = 10.0f;
static const float MHE_WATCH_GAIN = 0.1f;
static const float MHE_WATCH_LIMIT = 10240.0f;
#define MHE_ITERATIONS 2u
#define MHE_SUBSTEPS 1u
#define MHE_NX VANDERPOL_UNCERTAIN_STATES
#define MHE_NY VANDERPOL_UNCERTAIN_OUTPUTS
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
static void mhe_normal(const vanderpol_uncertain_mhe *o, const float *x, float (*matrix)[MHE_NX], float *gradient, float *cost) {
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
    for (k = 0u; k < VANDERPOL_UNCERTAIN_HORIZON; ++k) {
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
static void mhe_solve_window(const vanderpol_uncertain_mhe *o, const float *centre, int prior, float *solution, float *end, float *cost) {
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
    for (k = 1u; k < VANDERPOL_UNCERTAIN_HORIZON; ++k) {
        float next[MHE_NX];
        float f[MHE_NX][MHE_NX];
        mhe_step(state, MHE_U(o, k - 1u), next, f);
        memcpy(state, next, sizeof state);
    }
    mhe_project(state, end);
}

void vanderpol_uncertain_mhe_init(vanderpol_uncertain_mhe *o) {
    o->next = 0u;
    o->filled = 0u;
    o->has_solved = 0;
    o->ready = 0;
    o->restarts = 0u;
    o->chi = 0.0f;
    o->has_chi = 0;
}

vanderpol_uncertain_status vanderpol_uncertain_mhe_push(vanderpol_uncertain_mhe *o, const float *y, const float *u) {
    float moved[MHE_NX], x[MHE_NX], end[MHE_NX], values[VANDERPOL_UNCERTAIN_TARGETS], cost;
    int has_moved = 0;
    unsigned i, slot;
    float chi;
    if (!all_finite(y, VANDERPOL_UNCERTAIN_OUTPUTS) || !inputs_finite(u)) {
        return VANDERPOL_UNCERTAIN_REFUSED;
    }
    /* The previous solution moved one sample on: the prior's centre and the first iterate. */
    if (o->has_solved && o->filled >= VANDERPOL_UNCERTAIN_HORIZON) {
        float next[MHE_NX];
        float f[MHE_NX][MHE_NX];
        mhe_step(o->solved, MHE_U(o, 0u), next, f);
        mhe_project(next, moved);
        has_moved = 1;
    }
    /* Every value of the sample is finite: stored. */
    slot = o->next;
    for (i = 0u; i < VANDERPOL_UNCERTAIN_OUTPUTS; ++i) {
        o->y[slot][i] = y[i];
        o->y[slot + VANDERPOL_UNCERTAIN_HORIZON][i] = y[i];
    }
    o->next = slot + 1u >= VANDERPOL_UNCERTAIN_HORIZON ? 0u : slot + 1u;
    o->filled += (unsigned)(o->filled < VANDERPOL_UNCERTAIN_HORIZON);
    if (o->filled < VANDERPOL_UNCERTAIN_HORIZON) {
        return VANDERPOL_UNCERTAIN_OK;
    }
    mhe_solve_window(o, has_moved ? moved : MHE_START, has_moved, x, end, &cost);
    targets(end, u, values);
    /* firmware::watch: the windows' costs' mean, from its start after a (re)start. */
    chi = o->has_chi ? o->chi : MHE_WATCH_START;
    chi = chi + MHE_WATCH_GAIN * (cost - chi);
    if (!all_finite(x, MHE_NX) || !all_finite(end, MHE_NX) || !all_finite(values, VANDERPOL_UNCERTAIN_TARGETS)
        || !(chi <= MHE_WATCH_LIMIT)) {
        /* Restarted: the next window is solved from the start, not from this solution. */
        o->has_chi = 0;
        o->has_solved = 0;
        if (o->restarts != UINT32_MAX) {
            ++o->restarts;
        }
        return VANDERPOL_UNCERTAIN_RESTARTED;
    }
    memcpy(o->solved, x, sizeof x);
    o->has_solved = 1;
    o->chi = chi;
    o->has_chi = 1;
    memcpy(o->values, values, sizeof values);
    for (i = 0u; i < VANDERPOL_UNCERTAIN_TARGETS; ++i) {
        o->flags[i] = VANDERPOL_UNCERTAIN_INSIDE;
    }
    o->ready = 1;
    return VANDERPOL_UNCERTAIN_OK;
}

#undef MHE_ITERATIONS
#undef MHE_SUBSTEPS
#undef MHE_NX
#undef MHE_NY
#undef MHE_U

vanderpol_uncertain_status vanderpol_uncertain_mhe_estimate(const vanderpol_uncertain_mhe *o, float *values, vanderpol_uncertain_saturation *saturation) {
    if (!o->ready) {
        return VANDERPOL_UNCERTAIN_NO_ESTIMATE_YET;
    }
    memcpy(values, o->values, sizeof o->values);
    memcpy(saturation, o->flags, sizeof o->flags);
    return VANDERPOL_UNCERTAIN_OK;
}

/* The mark of this design's observer in storage (never 0: zeroed storage holds none). */
#define STORAGE_MARK 0x30357733908387b1ull

/* The observer in storage: VANDERPOL_UNCERTAIN_BAD_ARGUMENT for a null or misaligned pointer,
 * VANDERPOL_UNCERTAIN_NOT_INITIALISED where vanderpol_uncertain_init did not make one (it reads the first 16 bytes only). */
static vanderpol_uncertain_status stored_observer(void *storage, vanderpol_uncertain_observer **observer) {
    vanderpol_uncertain_stored *stored = (vanderpol_uncertain_stored *)storage;
    if (storage == NULL || (uintptr_t)storage % VANDERPOL_UNCERTAIN_STORAGE_ALIGN != 0u) {
        return VANDERPOL_UNCERTAIN_BAD_ARGUMENT;
    }
    if (stored->mark != STORAGE_MARK || stored->size < (uint64_t)sizeof(vanderpol_uncertain_stored)) {
        return VANDERPOL_UNCERTAIN_NOT_INITIALISED;
    }
    *observer = &stored->observer;
    return VANDERPOL_UNCERTAIN_OK;
}

vanderpol_uncertain_status vanderpol_uncertain_init(void *storage, size_t size) {
    vanderpol_uncertain_stored *stored = (vanderpol_uncertain_stored *)storage;
    if (storage == NULL || size < sizeof(vanderpol_uncertain_stored) || (uintptr_t)storage % VANDERPOL_UNCERTAIN_STORAGE_ALIGN != 0u) {
        return VANDERPOL_UNCERTAIN_BAD_ARGUMENT;
    }
    stored->mark = STORAGE_MARK;
    stored->size = (uint64_t)size;
    vanderpol_uncertain_observer_init(&stored->observer);
    return VANDERPOL_UNCERTAIN_OK;
}

vanderpol_uncertain_status vanderpol_uncertain_push(void *storage, const float *y, const float *u) {
    vanderpol_uncertain_observer *observer = NULL;
    const vanderpol_uncertain_status found = stored_observer(storage, &observer);
    if (found != VANDERPOL_UNCERTAIN_OK) {
        return found;
    }
    if (y == NULL) {
        return VANDERPOL_UNCERTAIN_BAD_ARGUMENT;
    }
    return vanderpol_uncertain_observer_push(observer, y, u);
}

vanderpol_uncertain_status vanderpol_uncertain_estimate(void *storage, float *estimates, vanderpol_uncertain_saturation *saturation) {
    vanderpol_uncertain_observer *observer = NULL;
    vanderpol_uncertain_saturation flags[VANDERPOL_UNCERTAIN_TARGETS];
    const vanderpol_uncertain_status found = stored_observer(storage, &observer);
    if (found != VANDERPOL_UNCERTAIN_OK) {
        return found;
    }
    if (estimates == NULL) {
        return VANDERPOL_UNCERTAIN_BAD_ARGUMENT;
    }
    return vanderpol_uncertain_observer_estimate(observer, estimates, saturation != NULL ? saturation : flags);
}

size_t vanderpol_uncertain_storage_size(void) {
    return sizeof(vanderpol_uncertain_stored);
}

#undef STORAGE_MARK
