/* The `vanderpol_sparse` observers in C99, emitted by `mho gen`. Do not edit: regenerate.
 * Licence: emitted by mho from your spec, this file is yours: you may use, copy, modify and
 * distribute it under any terms, including MIT OR Apache-2.0, with or without this notice. */
#include <stdint.h>
#include <string.h>
#include <math.h>
#include <float.h>
#include "vanderpol_sparse.h"

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
    for (i = 0u; i < VANDERPOL_SPARSE_OUTPUTS; ++i) {
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
static const float GAINS_0[19] = {
    0.0f, 0.0f, 0.0f, 0.0f,
    0.0f, -0.024965525f, 0.0f, 0.0f,
    -0.023485338f, 0.0f, -0.017927244f, 0.0f,
    -0.019214869f, -0.022770798f, -0.025959969f, 0.0f,
    0.0f, 0.0f, 0.0f
};
static const float SEGMENTS_0[1][2] = {
    { -2.0616221f, 4.1232443f }
};

/* target `x2`: gains in regressor order, then the Γ⁻¹ table's segments (a, b). */
static const float GAINS_1[19] = {
    0.03106531f, 0.027483545f, 0.022598177f, 0.0f,
    0.0f, 0.0f, 0.0f, 0.0f,
    0.0f, 0.020445434f, 0.0f, 0.010715283f,
    0.0f, 0.0f, 0.0f, 0.0f,
    -0.015461479f, 0.0f, 0.0f
};
static const float SEGMENTS_1[1][2] = {
    { -4.6765766f, 9.353153f }
};

/* r(t) on one segment (a, b) starting at `start`, held at r_min below 0 (or NaN) and r_max above
 * t_max (t_max >= 0: never both); as firmware::InverseTable, by one select per statement, which
 * compilers make a conditional move (an IT block on Thumb-2): the same instructions whatever t is. */
static void evaluate(float t, const float *segment, float start, float t_max, float r_min, float r_max,
                     float *value, vanderpol_sparse_saturation *saturation) {
    const int low = !(t >= 0.0f);
    const int high = t > t_max;
    float r = segment[0] + segment[1] * (t - start);
    r = choose_float(high, r_max, r);
    r = choose_float(low, r_min, r);
    *value = r;
    *saturation = (vanderpol_sparse_saturation)((unsigned)low | (unsigned)high << 1);
}

void vanderpol_sparse_map_init(vanderpol_sparse_map *observer) {
    observer->next = 0u;
    observer->filled = 0u;
}

vanderpol_sparse_status vanderpol_sparse_map_push(vanderpol_sparse_map *observer, const float *y, const float *u) {
    unsigned i;
    unsigned slot;
    int finite = 1;
    for (i = 0u; i < VANDERPOL_SPARSE_OUTPUTS; ++i) {
        finite &= is_finite(y[i]);
    }
    if (!finite) {
        return VANDERPOL_SPARSE_REFUSED;
    }
    slot = observer->next;
    for (i = 0u; i < VANDERPOL_SPARSE_OUTPUTS; ++i) {
        observer->y[slot][i] = y[i];
        observer->y[slot + VANDERPOL_SPARSE_HORIZON][i] = y[i];
    }
    (void)u;
    observer->next = slot + 1u >= VANDERPOL_SPARSE_HORIZON ? 0u : slot + 1u;
    observer->filled += (unsigned)(observer->filled < VANDERPOL_SPARSE_HORIZON);
    return VANDERPOL_SPARSE_OK;
}

vanderpol_sparse_status vanderpol_sparse_map_estimate(const vanderpol_sparse_map *observer, float *values, vanderpol_sparse_saturation *saturation) {
    const unsigned next = observer->next;
    if (observer->filled < VANDERPOL_SPARSE_HORIZON) {
        return VANDERPOL_SPARSE_NO_ESTIMATE_YET;
    }
    const float t_0 = 0.50028557f
        + GAINS_0[5] * observer->y[next + 13u][0]
        + GAINS_0[8] * observer->y[next + 10u][0]
        + GAINS_0[10] * observer->y[next + 8u][0]
        + GAINS_0[12] * observer->y[next + 6u][0]
        + GAINS_0[13] * observer->y[next + 5u][0]
        + GAINS_0[14] * observer->y[next + 4u][0];
    const float t_1 = 0.5003894f
        + GAINS_1[0] * observer->y[next + 18u][0]
        + GAINS_1[1] * observer->y[next + 17u][0]
        + GAINS_1[2] * observer->y[next + 16u][0]
        + GAINS_1[9] * observer->y[next + 9u][0]
        + GAINS_1[11] * observer->y[next + 7u][0]
        + GAINS_1[16] * observer->y[next + 2u][0];
    evaluate(t_0, SEGMENTS_0[0], 0.0f, 1.0f, -2.0616221f, 2.0616221f, &values[0], &saturation[0]);
    evaluate(t_1, SEGMENTS_1[0], 0.0f, 1.0f, -4.6765766f, 4.6765766f, &values[1], &saturation[1]);
    return VANDERPOL_SPARSE_OK;
}


#define VANDERPOL_SPARSE_MAP_ROWS VANDERPOL_SPARSE_TARGETS
#define start_map_estimate vanderpol_sparse_map_estimate

/* `x1` in integers: gains in regressor order (2^-29 per count), then (A_k, B_k) in its LSB. */
static const int32_t FIXED_GAINS_0[19] = { 0, 0, 0, 0, 0, -6545, 0, 0, -6157, 0, -4700, 0, -5037, -5969, -6805, 0, 0, 0, 0 };
static const int32_t FIXED_SEGMENTS_0[1][2] = {
    { -16889, 33778 }
};

/* `x2` in integers: gains in regressor order (2^-29 per count), then (A_k, B_k) in its LSB. */
static const int32_t FIXED_GAINS_1[19] = { 8144, 7205, 5924, 0, 0, 0, 0, 0, 0, 5360, 0, 2809, 0, 0, 0, 0, -4053, 0, 0 };
static const int32_t FIXED_SEGMENTS_1[1][2] = {
    { -19155, 38311 }
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
                           int32_t t_last, int32_t *value, vanderpol_sparse_saturation *saturation) {
    const int32_t low = t >> 31;
    const int32_t high = (wrapping_sub(t_last, t) >> 31) & ~low;
    int32_t k;
    int32_t position;
    t &= ~low;
    t ^= (t ^ t_last) & high;
    k = t >> f;
    position = (t - (int32_t)((uint32_t)k << f)) >> dropped;
    *value = segments[k][0] + ((segments[k][1] * position) >> p);
    *saturation = (vanderpol_sparse_saturation)((unsigned)(low & 1) | ((unsigned)high & 2u));
}

void vanderpol_sparse_fixed_init(vanderpol_sparse_fixed *observer) {
    observer->next = 0u;
    observer->filled = 0u;
}

vanderpol_sparse_status vanderpol_sparse_fixed_push(vanderpol_sparse_fixed *observer, const int32_t *y, const int32_t *u) {
    unsigned i;
    unsigned slot;
    int inside = 1;
    inside &= in_range(y[0], -32767, 32767);
    if (!inside) {
        return VANDERPOL_SPARSE_REFUSED;
    }
    slot = observer->next;
    for (i = 0u; i < VANDERPOL_SPARSE_OUTPUTS; ++i) {
        observer->y[slot][i] = y[i];
        observer->y[slot + VANDERPOL_SPARSE_HORIZON][i] = y[i];
    }
    (void)u;
    observer->next = slot + 1u >= VANDERPOL_SPARSE_HORIZON ? 0u : slot + 1u;
    observer->filled += (unsigned)(observer->filled < VANDERPOL_SPARSE_HORIZON);
    return VANDERPOL_SPARSE_OK;
}

/* The sums are in int32_t: every stored sample is in range, where the proof says they fit. */
vanderpol_sparse_status vanderpol_sparse_fixed_estimate(const vanderpol_sparse_fixed *observer, int32_t *values, vanderpol_sparse_saturation *saturation) {
    const unsigned next = observer->next;
    if (observer->filled < VANDERPOL_SPARSE_HORIZON) {
        return VANDERPOL_SPARSE_NO_ESTIMATE_YET;
    }
    int32_t t_0 = 268588758;
    int32_t t_1 = 268644515;
    {
        const int32_t z = observer->y[next + 18u][0];
        t_1 += FIXED_GAINS_1[0] * z;
    }
    {
        const int32_t z = observer->y[next + 17u][0];
        t_1 += FIXED_GAINS_1[1] * z;
    }
    {
        const int32_t z = observer->y[next + 16u][0];
        t_1 += FIXED_GAINS_1[2] * z;
    }
    {
        const int32_t z = observer->y[next + 13u][0];
        t_0 += FIXED_GAINS_0[5] * z;
    }
    {
        const int32_t z = observer->y[next + 10u][0];
        t_0 += FIXED_GAINS_0[8] * z;
    }
    {
        const int32_t z = observer->y[next + 9u][0];
        t_1 += FIXED_GAINS_1[9] * z;
    }
    {
        const int32_t z = observer->y[next + 8u][0];
        t_0 += FIXED_GAINS_0[10] * z;
    }
    {
        const int32_t z = observer->y[next + 7u][0];
        t_1 += FIXED_GAINS_1[11] * z;
    }
    {
        const int32_t z = observer->y[next + 6u][0];
        t_0 += FIXED_GAINS_0[12] * z;
    }
    {
        const int32_t z = observer->y[next + 5u][0];
        t_0 += FIXED_GAINS_0[13] * z;
    }
    {
        const int32_t z = observer->y[next + 4u][0];
        t_0 += FIXED_GAINS_0[14] * z;
    }
    {
        const int32_t z = observer->y[next + 2u][0];
        t_1 += FIXED_GAINS_1[16] * z;
    }
    fixed_evaluate(t_0, FIXED_SEGMENTS_0, 29u, 14u, 15u, 536870911, &values[0], &saturation[0]);
    fixed_evaluate(t_1, FIXED_SEGMENTS_1, 29u, 14u, 15u, 536870911, &values[1], &saturation[1]);
    return VANDERPOL_SPARSE_OK;
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
    const float t63 = 4.0f;
    const float t64 = t63 * t18;
    const float t65 = t18 * t18;
    const float t66 = t6 - t65;
    const float t67 = t66 * t20;
    const float t68 = t64 + t67;
    const float t69 = t57 * t18;
    const float t70 = -t69;
    const float t71 = t70 * t20;
    const float t72 = t63 + t71;
    const float t73 = t59 * t61;
    const float t74 = t18 + t73;
    const float t75 = t59 * t68;
    const float t76 = t20 + t75;
    const float t77 = -t59;
    const float t78 = t59 * t72;
    const float t79 = t59 * t66;
    const float t80 = t6 + t79;
    const float t81 = -t76;
    const float t82 = t63 * t74;
    const float t83 = t74 * t74;
    const float t84 = t6 - t83;
    const float t85 = t84 * t76;
    const float t86 = t82 + t85;
    const float t87 = t57 * t74;
    const float t88 = -t87;
    const float t89 = t88 * t76;
    const float t90 = t63 + t89;
    const float t91 = -t78;
    const float t92 = -t80;
    const float t93 = t84 * t78;
    const float t94 = t90 + t93;
    const float t95 = t90 * t77;
    const float t96 = t84 * t80;
    const float t97 = t95 + t96;
    const float t98 = t59 * t81;
    const float t99 = t18 + t98;
    const float t100 = t59 * t86;
    const float t101 = t20 + t100;
    const float t102 = t59 * t91;
    const float t103 = t6 + t102;
    const float t104 = t59 * t92;
    const float t105 = t59 * t94;
    const float t106 = t59 * t97;
    const float t107 = t6 + t106;
    const float t108 = -t101;
    const float t109 = t63 * t99;
    const float t110 = t99 * t99;
    const float t111 = t6 - t110;
    const float t112 = t111 * t101;
    const float t113 = t109 + t112;
    const float t114 = t57 * t99;
    const float t115 = -t114;
    const float t116 = t115 * t101;
    const float t117 = t63 + t116;
    const float t118 = -t105;
    const float t119 = -t107;
    const float t120 = t117 * t103;
    const float t121 = t111 * t105;
    const float t122 = t120 + t121;
    const float t123 = t117 * t104;
    const float t124 = t111 * t107;
    const float t125 = t123 + t124;
    const float t126 = t56 * t108;
    const float t127 = t18 + t126;
    const float t128 = t56 * t113;
    const float t129 = t20 + t128;
    const float t130 = t56 * t118;
    const float t131 = t6 + t130;
    const float t132 = t56 * t119;
    const float t133 = t56 * t122;
    const float t134 = t56 * t125;
    const float t135 = t6 + t134;
    const float t136 = -t129;
    const float t137 = t63 * t127;
    const float t138 = t127 * t127;
    const float t139 = t6 - t138;
    const float t140 = t139 * t129;
    const float t141 = t137 + t140;
    const float t142 = t57 * t127;
    const float t143 = -t142;
    const float t144 = t143 * t129;
    const float t145 = t63 + t144;
    const float t146 = -t133;
    const float t147 = -t135;
    const float t148 = t145 * t131;
    const float t149 = t139 * t133;
    const float t150 = t148 + t149;
    const float t151 = t145 * t132;
    const float t152 = t139 * t135;
    const float t153 = t151 + t152;
    const float t154 = t81 + t108;
    const float t155 = t57 * t154;
    const float t156 = t61 + t155;
    const float t157 = t156 + t136;
    const float t158 = t60 * t157;
    const float t159 = t18 + t158;
    const float t160 = t86 + t113;
    const float t161 = t57 * t160;
    const float t162 = t68 + t161;
    const float t163 = t162 + t141;
    const float t164 = t60 * t163;
    const float t165 = t20 + t164;
    const float t166 = t91 + t118;
    const float t167 = t57 * t166;
    const float t168 = t167 + t146;
    const float t169 = t60 * t168;
    const float t170 = t6 + t169;
    const float t171 = t92 + t119;
    const float t172 = t57 * t171;
    const float t173 = t62 + t172;
    const float t174 = t173 + t147;
    const float t175 = t60 * t174;
    const float t176 = t94 + t122;
    const float t177 = t57 * t176;
    const float t178 = t72 + t177;
    const float t179 = t178 + t150;
    const float t180 = t60 * t179;
    const float t181 = t97 + t125;
    const float t182 = t57 * t181;
    const float t183 = t66 + t182;
    const float t184 = t183 + t153;
    const float t185 = t60 * t184;
    const float t186 = t6 + t185;
    const float t187 = t170 * t50;
    const float t188 = t175 * t52;
    const float t189 = t187 + t188;
    const float t190 = t170 * t52;
    const float t191 = t175 * t55;
    const float t192 = t190 + t191;
    const float t193 = t180 * t50;
    const float t194 = t186 * t52;
    const float t195 = t193 + t194;
    const float t196 = t180 * t52;
    const float t197 = t186 * t55;
    const float t198 = t196 + t197;
    const float t199 = t189 * t170;
    const float t200 = t192 * t175;
    const float t201 = t199 + t200;
    const float t202 = t189 * t180;
    const float t203 = t192 * t186;
    const float t204 = t202 + t203;
    const float t205 = t195 * t180;
    const float t206 = t198 * t186;
    const float t207 = t205 + t206;
    const float t208 = 7.734046e-6f;
    const float t209 = t201 + t208;
    const float t210 = 0.0010240098f;
    const float t211 = t207 + t210;
    out[0] = t18;
    out[1] = t20;
    out[2] = t159;
    out[3] = t165;
    out[4] = t209;
    out[5] = t204;
    out[6] = t211;
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
    const float t12 = 4.0f;
    const float t13 = t12 * t0;
    const float t14 = 1.0f;
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
    const float t27 = -t8;
    const float t28 = t8 * t22;
    const float t29 = t8 * t16;
    const float t30 = t14 + t29;
    const float t31 = -t26;
    const float t32 = t12 * t24;
    const float t33 = t24 * t24;
    const float t34 = t14 - t33;
    const float t35 = t34 * t26;
    const float t36 = t32 + t35;
    const float t37 = t6 * t24;
    const float t38 = -t37;
    const float t39 = t38 * t26;
    const float t40 = t12 + t39;
    const float t41 = -t28;
    const float t42 = -t30;
    const float t43 = t34 * t28;
    const float t44 = t40 + t43;
    const float t45 = t40 * t27;
    const float t46 = t34 * t30;
    const float t47 = t45 + t46;
    const float t48 = t8 * t31;
    const float t49 = t0 + t48;
    const float t50 = t8 * t36;
    const float t51 = t1 + t50;
    const float t52 = t8 * t41;
    const float t53 = t14 + t52;
    const float t54 = t8 * t42;
    const float t55 = t8 * t44;
    const float t56 = t8 * t47;
    const float t57 = t14 + t56;
    const float t58 = -t51;
    const float t59 = t12 * t49;
    const float t60 = t49 * t49;
    const float t61 = t14 - t60;
    const float t62 = t61 * t51;
    const float t63 = t59 + t62;
    const float t64 = t6 * t49;
    const float t65 = -t64;
    const float t66 = t65 * t51;
    const float t67 = t12 + t66;
    const float t68 = -t55;
    const float t69 = -t57;
    const float t70 = t67 * t53;
    const float t71 = t61 * t55;
    const float t72 = t70 + t71;
    const float t73 = t67 * t54;
    const float t74 = t61 * t57;
    const float t75 = t73 + t74;
    const float t76 = t5 * t58;
    const float t77 = t0 + t76;
    const float t78 = t5 * t63;
    const float t79 = t1 + t78;
    const float t80 = t5 * t68;
    const float t81 = t14 + t80;
    const float t82 = t5 * t69;
    const float t83 = t5 * t72;
    const float t84 = t5 * t75;
    const float t85 = t14 + t84;
    const float t86 = -t79;
    const float t87 = t12 * t77;
    const float t88 = t77 * t77;
    const float t89 = t14 - t88;
    const float t90 = t89 * t79;
    const float t91 = t87 + t90;
    const float t92 = t6 * t77;
    const float t93 = -t92;
    const float t94 = t93 * t79;
    const float t95 = t12 + t94;
    const float t96 = -t83;
    const float t97 = -t85;
    const float t98 = t95 * t81;
    const float t99 = t89 * t83;
    const float t100 = t98 + t99;
    const float t101 = t95 * t82;
    const float t102 = t89 * t85;
    const float t103 = t101 + t102;
    const float t104 = t31 + t58;
    const float t105 = t6 * t104;
    const float t106 = t10 + t105;
    const float t107 = t106 + t86;
    const float t108 = t9 * t107;
    const float t109 = t0 + t108;
    const float t110 = t36 + t63;
    const float t111 = t6 * t110;
    const float t112 = t18 + t111;
    const float t113 = t112 + t91;
    const float t114 = t9 * t113;
    const float t115 = t1 + t114;
    const float t116 = t41 + t68;
    const float t117 = t6 * t116;
    const float t118 = t117 + t96;
    const float t119 = t9 * t118;
    const float t120 = t14 + t119;
    const float t121 = t42 + t69;
    const float t122 = t6 * t121;
    const float t123 = t11 + t122;
    const float t124 = t123 + t97;
    const float t125 = t9 * t124;
    const float t126 = t44 + t72;
    const float t127 = t6 * t126;
    const float t128 = t22 + t127;
    const float t129 = t128 + t100;
    const float t130 = t9 * t129;
    const float t131 = t47 + t75;
    const float t132 = t6 * t131;
    const float t133 = t16 + t132;
    const float t134 = t133 + t103;
    const float t135 = t9 * t134;
    const float t136 = t14 + t135;
    const float t137 = t120 * t2;
    const float t138 = t125 * t3;
    const float t139 = t137 + t138;
    const float t140 = t120 * t3;
    const float t141 = t125 * t4;
    const float t142 = t140 + t141;
    const float t143 = t130 * t2;
    const float t144 = t136 * t3;
    const float t145 = t143 + t144;
    const float t146 = t130 * t3;
    const float t147 = t136 * t4;
    const float t148 = t146 + t147;
    const float t149 = t139 * t120;
    const float t150 = t142 * t125;
    const float t151 = t149 + t150;
    const float t152 = t139 * t130;
    const float t153 = t142 * t136;
    const float t154 = t152 + t153;
    const float t155 = t145 * t130;
    const float t156 = t148 * t136;
    const float t157 = t155 + t156;
    const float t158 = 7.734046e-6f;
    const float t159 = t151 + t158;
    const float t160 = 0.0010240098f;
    const float t161 = t157 + t160;
    out[0] = t109;
    out[1] = t115;
    out[2] = t159;
    out[3] = t154;
    out[4] = t161;
}

/* The EKF's start: the centre of the state box and P(0)'s upper triangle. */
static const float EKF_X0[VANDERPOL_SPARSE_STATES] = {
    0.0f, 0.0f
};
static const float EKF_P0[VANDERPOL_SPARSE_COVARIANCE] = {
    0.1428417f, 0.0f, 0.38269034f
};

/* The EKF's prediction alone (a lost output), taken when finite. */
static void ekf_predict(float *x, float *p, const float *u) {
    float out[VANDERPOL_SPARSE_STATES + VANDERPOL_SPARSE_COVARIANCE];
    ekf_unmeasured(x, p, u, out);
    if (all_finite(out, VANDERPOL_SPARSE_STATES + VANDERPOL_SPARSE_COVARIANCE)) {
        memcpy(x, out, VANDERPOL_SPARSE_STATES * sizeof *x);
        memcpy(p, out + VANDERPOL_SPARSE_STATES, VANDERPOL_SPARSE_COVARIANCE * sizeof *p);
    }
}

/* The EKF's sample with its measurement, taken when finite (1, the estimate x(k|k) in
 * `estimate`, its normalised innovation squared in `*nis`). */
static int ekf_measure(float *x, float *p, const float *y, const float *u, float *estimate, float *nis) {
    float out[2u * VANDERPOL_SPARSE_STATES + VANDERPOL_SPARSE_COVARIANCE + 1u];
    ekf_measured(x, p, y, u, out);
    if (!all_finite(out + VANDERPOL_SPARSE_STATES, VANDERPOL_SPARSE_STATES + VANDERPOL_SPARSE_COVARIANCE)) {
        return 0;
    }
    *nis = out[2u * VANDERPOL_SPARSE_STATES + VANDERPOL_SPARSE_COVARIANCE];
    memcpy(estimate, out, VANDERPOL_SPARSE_STATES * sizeof *x);
    memcpy(x, out + VANDERPOL_SPARSE_STATES, VANDERPOL_SPARSE_STATES * sizeof *x);
    memcpy(p, out + 2u * VANDERPOL_SPARSE_STATES, VANDERPOL_SPARSE_COVARIANCE * sizeof *p);
    return 1;
}


static void ekf_box_fresh(vanderpol_sparse_ekf_box *o) {
    memcpy(o->x, EKF_X0, sizeof o->x);
    memcpy(o->p, EKF_P0, sizeof o->p);
    o->chi = 1.0f;
}

static vanderpol_sparse_status ekf_box_sample(vanderpol_sparse_ekf_box *o, const float *y, const float *u) {
    float estimate[VANDERPOL_SPARSE_STATES];
    float nis;
    unsigned i;
    if (!inputs_finite(u)) {
        return VANDERPOL_SPARSE_REFUSED;
    }
    if (!accepts(y, u)) {
        ekf_predict(o->x, o->p, u);
        return VANDERPOL_SPARSE_REFUSED;
    }
    if (!ekf_measure(o->x, o->p, y, u, estimate, &nis)) {
        ekf_box_fresh(o);
        return VANDERPOL_SPARSE_RESTARTED;
    }
    /* The chi-squared watch (firmware::watch): the mean of the normalised innovations squared. */
    o->chi = o->chi + 0.05263158f * (nis - o->chi);
    if (!(o->chi <= 1024.0f)) {
        ekf_box_fresh(o);
        return VANDERPOL_SPARSE_RESTARTED;
    }
    targets(estimate, u, o->values);
    for (i = 0u; i < VANDERPOL_SPARSE_TARGETS; ++i) {
        o->flags[i] = VANDERPOL_SPARSE_INSIDE;
    }
    o->ready = 1;
    return VANDERPOL_SPARSE_OK;
}

void vanderpol_sparse_ekf_box_init(vanderpol_sparse_ekf_box *o) {
    ekf_box_fresh(o);
    o->ready = 0;
    o->refused = 0u;
    o->restarts = 0u;
}

vanderpol_sparse_status vanderpol_sparse_ekf_box_push(vanderpol_sparse_ekf_box *o, const float *y, const float *u) {
    const vanderpol_sparse_status status = ekf_box_sample(o, y, u);
    if (status == VANDERPOL_SPARSE_REFUSED && o->refused != UINT32_MAX) {
        ++o->refused;
    } else if (status == VANDERPOL_SPARSE_RESTARTED && o->restarts != UINT32_MAX) {
        ++o->restarts;
    }
    return status;
}

vanderpol_sparse_status vanderpol_sparse_ekf_box_estimate(const vanderpol_sparse_ekf_box *o, float *values, vanderpol_sparse_saturation *saturation) {
    if (!o->ready) {
        return VANDERPOL_SPARSE_NO_ESTIMATE_YET;
    }
    memcpy(values, o->values, sizeof o->values);
    memcpy(saturation, o->flags, sizeof o->flags);
    return VANDERPOL_SPARSE_OK;
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
    const float t133 = 4.0f;
    const float t134 = t133 * t116;
    const float t135 = t116 * t116;
    const float t136 = t5 - t135;
    const float t137 = t136 * t118;
    const float t138 = t134 + t137;
    const float t139 = t130 * t132;
    const float t140 = t116 + t139;
    const float t141 = t130 * t138;
    const float t142 = t118 + t141;
    const float t143 = -t142;
    const float t144 = t133 * t140;
    const float t145 = t140 * t140;
    const float t146 = t5 - t145;
    const float t147 = t146 * t142;
    const float t148 = t144 + t147;
    const float t149 = t130 * t143;
    const float t150 = t116 + t149;
    const float t151 = t130 * t148;
    const float t152 = t118 + t151;
    const float t153 = -t152;
    const float t154 = t133 * t150;
    const float t155 = t150 * t150;
    const float t156 = t5 - t155;
    const float t157 = t156 * t152;
    const float t158 = t154 + t157;
    const float t159 = t127 * t153;
    const float t160 = t116 + t159;
    const float t161 = t127 * t158;
    const float t162 = t118 + t161;
    const float t163 = -t162;
    const float t164 = t133 * t160;
    const float t165 = t160 * t160;
    const float t166 = t5 - t165;
    const float t167 = t166 * t162;
    const float t168 = t164 + t167;
    const float t169 = t143 + t153;
    const float t170 = t128 * t169;
    const float t171 = t132 + t170;
    const float t172 = t171 + t163;
    const float t173 = t131 * t172;
    const float t174 = t116 + t173;
    const float t175 = t148 + t158;
    const float t176 = t128 * t175;
    const float t177 = t138 + t176;
    const float t178 = t177 + t168;
    const float t179 = t131 * t178;
    const float t180 = t118 + t179;
    const float t181 = -t120;
    const float t182 = t133 * t90;
    const float t183 = t90 * t90;
    const float t184 = t5 - t183;
    const float t185 = t184 * t120;
    const float t186 = t182 + t185;
    const float t187 = t130 * t181;
    const float t188 = t90 + t187;
    const float t189 = t130 * t186;
    const float t190 = t120 + t189;
    const float t191 = -t190;
    const float t192 = t133 * t188;
    const float t193 = t188 * t188;
    const float t194 = t5 - t193;
    const float t195 = t194 * t190;
    const float t196 = t192 + t195;
    const float t197 = t130 * t191;
    const float t198 = t90 + t197;
    const float t199 = t130 * t196;
    const float t200 = t120 + t199;
    const float t201 = -t200;
    const float t202 = t133 * t198;
    const float t203 = t198 * t198;
    const float t204 = t5 - t203;
    const float t205 = t204 * t200;
    const float t206 = t202 + t205;
    const float t207 = t127 * t201;
    const float t208 = t90 + t207;
    const float t209 = t127 * t206;
    const float t210 = t120 + t209;
    const float t211 = -t210;
    const float t212 = t133 * t208;
    const float t213 = t208 * t208;
    const float t214 = t5 - t213;
    const float t215 = t214 * t210;
    const float t216 = t212 + t215;
    const float t217 = t191 + t201;
    const float t218 = t128 * t217;
    const float t219 = t181 + t218;
    const float t220 = t219 + t211;
    const float t221 = t131 * t220;
    const float t222 = t90 + t221;
    const float t223 = t196 + t206;
    const float t224 = t128 * t223;
    const float t225 = t186 + t224;
    const float t226 = t225 + t216;
    const float t227 = t131 * t226;
    const float t228 = t120 + t227;
    const float t229 = -t124;
    const float t230 = t133 * t122;
    const float t231 = t122 * t122;
    const float t232 = t5 - t231;
    const float t233 = t232 * t124;
    const float t234 = t230 + t233;
    const float t235 = t130 * t229;
    const float t236 = t122 + t235;
    const float t237 = t130 * t234;
    const float t238 = t124 + t237;
    const float t239 = -t238;
    const float t240 = t133 * t236;
    const float t241 = t236 * t236;
    const float t242 = t5 - t241;
    const float t243 = t242 * t238;
    const float t244 = t240 + t243;
    const float t245 = t130 * t239;
    const float t246 = t122 + t245;
    const float t247 = t130 * t244;
    const float t248 = t124 + t247;
    const float t249 = -t248;
    const float t250 = t133 * t246;
    const float t251 = t246 * t246;
    const float t252 = t5 - t251;
    const float t253 = t252 * t248;
    const float t254 = t250 + t253;
    const float t255 = t127 * t249;
    const float t256 = t122 + t255;
    const float t257 = t127 * t254;
    const float t258 = t124 + t257;
    const float t259 = -t258;
    const float t260 = t133 * t256;
    const float t261 = t256 * t256;
    const float t262 = t5 - t261;
    const float t263 = t262 * t258;
    const float t264 = t260 + t263;
    const float t265 = t239 + t249;
    const float t266 = t128 * t265;
    const float t267 = t229 + t266;
    const float t268 = t267 + t259;
    const float t269 = t131 * t268;
    const float t270 = t122 + t269;
    const float t271 = t244 + t254;
    const float t272 = t128 * t271;
    const float t273 = t234 + t272;
    const float t274 = t273 + t264;
    const float t275 = t131 * t274;
    const float t276 = t124 + t275;
    const float t277 = -t126;
    const float t278 = t184 * t126;
    const float t279 = t182 + t278;
    const float t280 = t130 * t277;
    const float t281 = t90 + t280;
    const float t282 = t130 * t279;
    const float t283 = t126 + t282;
    const float t284 = -t283;
    const float t285 = t133 * t281;
    const float t286 = t281 * t281;
    const float t287 = t5 - t286;
    const float t288 = t287 * t283;
    const float t289 = t285 + t288;
    const float t290 = t130 * t284;
    const float t291 = t90 + t290;
    const float t292 = t130 * t289;
    const float t293 = t126 + t292;
    const float t294 = -t293;
    const float t295 = t133 * t291;
    const float t296 = t291 * t291;
    const float t297 = t5 - t296;
    const float t298 = t297 * t293;
    const float t299 = t295 + t298;
    const float t300 = t127 * t294;
    const float t301 = t90 + t300;
    const float t302 = t127 * t299;
    const float t303 = t126 + t302;
    const float t304 = -t303;
    const float t305 = t133 * t301;
    const float t306 = t301 * t301;
    const float t307 = t5 - t306;
    const float t308 = t307 * t303;
    const float t309 = t305 + t308;
    const float t310 = t284 + t294;
    const float t311 = t128 * t310;
    const float t312 = t277 + t311;
    const float t313 = t312 + t304;
    const float t314 = t131 * t313;
    const float t315 = t90 + t314;
    const float t316 = t289 + t299;
    const float t317 = t128 * t316;
    const float t318 = t279 + t317;
    const float t319 = t318 + t309;
    const float t320 = t131 * t319;
    const float t321 = t126 + t320;
    const float t322 = t174 + t222;
    const float t323 = t322 + t270;
    const float t324 = t323 + t315;
    const float t325 = t40 * t324;
    const float t326 = t180 + t228;
    const float t327 = t326 + t276;
    const float t328 = t327 + t321;
    const float t329 = t40 * t328;
    const float t330 = t174 - t325;
    const float t331 = t180 - t329;
    const float t332 = t222 - t325;
    const float t333 = t228 - t329;
    const float t334 = t270 - t325;
    const float t335 = t276 - t329;
    const float t336 = t315 - t325;
    const float t337 = t321 - t329;
    const float t338 = t330 * t330;
    const float t339 = t332 * t332;
    const float t340 = t338 + t339;
    const float t341 = t334 * t334;
    const float t342 = t340 + t341;
    const float t343 = t336 * t336;
    const float t344 = t342 + t343;
    const float t345 = t40 * t344;
    const float t346 = t330 * t331;
    const float t347 = t332 * t333;
    const float t348 = t346 + t347;
    const float t349 = t334 * t335;
    const float t350 = t348 + t349;
    const float t351 = t336 * t337;
    const float t352 = t350 + t351;
    const float t353 = t40 * t352;
    const float t354 = t331 * t331;
    const float t355 = t333 * t333;
    const float t356 = t354 + t355;
    const float t357 = t335 * t335;
    const float t358 = t356 + t357;
    const float t359 = t337 * t337;
    const float t360 = t358 + t359;
    const float t361 = t40 * t360;
    const float t362 = 2.4706553e-6f;
    const float t363 = t345 + t362;
    const float t364 = 0.0002079303f;
    const float t365 = t361 + t364;
    out[0] = t90;
    out[1] = t92;
    out[2] = t325;
    out[3] = t329;
    out[4] = t363;
    out[5] = t353;
    out[6] = t365;
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
    const float t42 = 4.0f;
    const float t43 = t42 * t24;
    const float t44 = t24 * t24;
    const float t45 = t5 - t44;
    const float t46 = t45 * t26;
    const float t47 = t43 + t46;
    const float t48 = t39 * t41;
    const float t49 = t24 + t48;
    const float t50 = t39 * t47;
    const float t51 = t26 + t50;
    const float t52 = -t51;
    const float t53 = t42 * t49;
    const float t54 = t49 * t49;
    const float t55 = t5 - t54;
    const float t56 = t55 * t51;
    const float t57 = t53 + t56;
    const float t58 = t39 * t52;
    const float t59 = t24 + t58;
    const float t60 = t39 * t57;
    const float t61 = t26 + t60;
    const float t62 = -t61;
    const float t63 = t42 * t59;
    const float t64 = t59 * t59;
    const float t65 = t5 - t64;
    const float t66 = t65 * t61;
    const float t67 = t63 + t66;
    const float t68 = t36 * t62;
    const float t69 = t24 + t68;
    const float t70 = t36 * t67;
    const float t71 = t26 + t70;
    const float t72 = -t71;
    const float t73 = t42 * t69;
    const float t74 = t69 * t69;
    const float t75 = t5 - t74;
    const float t76 = t75 * t71;
    const float t77 = t73 + t76;
    const float t78 = t52 + t62;
    const float t79 = t37 * t78;
    const float t80 = t41 + t79;
    const float t81 = t80 + t72;
    const float t82 = t40 * t81;
    const float t83 = t24 + t82;
    const float t84 = t57 + t67;
    const float t85 = t37 * t84;
    const float t86 = t47 + t85;
    const float t87 = t86 + t77;
    const float t88 = t40 * t87;
    const float t89 = t26 + t88;
    const float t90 = -t28;
    const float t91 = t42 * t0;
    const float t92 = t0 * t0;
    const float t93 = t5 - t92;
    const float t94 = t93 * t28;
    const float t95 = t91 + t94;
    const float t96 = t39 * t90;
    const float t97 = t0 + t96;
    const float t98 = t39 * t95;
    const float t99 = t28 + t98;
    const float t100 = -t99;
    const float t101 = t42 * t97;
    const float t102 = t97 * t97;
    const float t103 = t5 - t102;
    const float t104 = t103 * t99;
    const float t105 = t101 + t104;
    const float t106 = t39 * t100;
    const float t107 = t0 + t106;
    const float t108 = t39 * t105;
    const float t109 = t28 + t108;
    const float t110 = -t109;
    const float t111 = t42 * t107;
    const float t112 = t107 * t107;
    const float t113 = t5 - t112;
    const float t114 = t113 * t109;
    const float t115 = t111 + t114;
    const float t116 = t36 * t110;
    const float t117 = t0 + t116;
    const float t118 = t36 * t115;
    const float t119 = t28 + t118;
    const float t120 = -t119;
    const float t121 = t42 * t117;
    const float t122 = t117 * t117;
    const float t123 = t5 - t122;
    const float t124 = t123 * t119;
    const float t125 = t121 + t124;
    const float t126 = t100 + t110;
    const float t127 = t37 * t126;
    const float t128 = t90 + t127;
    const float t129 = t128 + t120;
    const float t130 = t40 * t129;
    const float t131 = t0 + t130;
    const float t132 = t105 + t115;
    const float t133 = t37 * t132;
    const float t134 = t95 + t133;
    const float t135 = t134 + t125;
    const float t136 = t40 * t135;
    const float t137 = t28 + t136;
    const float t138 = -t33;
    const float t139 = t42 * t31;
    const float t140 = t31 * t31;
    const float t141 = t5 - t140;
    const float t142 = t141 * t33;
    const float t143 = t139 + t142;
    const float t144 = t39 * t138;
    const float t145 = t31 + t144;
    const float t146 = t39 * t143;
    const float t147 = t33 + t146;
    const float t148 = -t147;
    const float t149 = t42 * t145;
    const float t150 = t145 * t145;
    const float t151 = t5 - t150;
    const float t152 = t151 * t147;
    const float t153 = t149 + t152;
    const float t154 = t39 * t148;
    const float t155 = t31 + t154;
    const float t156 = t39 * t153;
    const float t157 = t33 + t156;
    const float t158 = -t157;
    const float t159 = t42 * t155;
    const float t160 = t155 * t155;
    const float t161 = t5 - t160;
    const float t162 = t161 * t157;
    const float t163 = t159 + t162;
    const float t164 = t36 * t158;
    const float t165 = t31 + t164;
    const float t166 = t36 * t163;
    const float t167 = t33 + t166;
    const float t168 = -t167;
    const float t169 = t42 * t165;
    const float t170 = t165 * t165;
    const float t171 = t5 - t170;
    const float t172 = t171 * t167;
    const float t173 = t169 + t172;
    const float t174 = t148 + t158;
    const float t175 = t37 * t174;
    const float t176 = t138 + t175;
    const float t177 = t176 + t168;
    const float t178 = t40 * t177;
    const float t179 = t31 + t178;
    const float t180 = t153 + t163;
    const float t181 = t37 * t180;
    const float t182 = t143 + t181;
    const float t183 = t182 + t173;
    const float t184 = t40 * t183;
    const float t185 = t33 + t184;
    const float t186 = -t35;
    const float t187 = t93 * t35;
    const float t188 = t91 + t187;
    const float t189 = t39 * t186;
    const float t190 = t0 + t189;
    const float t191 = t39 * t188;
    const float t192 = t35 + t191;
    const float t193 = -t192;
    const float t194 = t42 * t190;
    const float t195 = t190 * t190;
    const float t196 = t5 - t195;
    const float t197 = t196 * t192;
    const float t198 = t194 + t197;
    const float t199 = t39 * t193;
    const float t200 = t0 + t199;
    const float t201 = t39 * t198;
    const float t202 = t35 + t201;
    const float t203 = -t202;
    const float t204 = t42 * t200;
    const float t205 = t200 * t200;
    const float t206 = t5 - t205;
    const float t207 = t206 * t202;
    const float t208 = t204 + t207;
    const float t209 = t36 * t203;
    const float t210 = t0 + t209;
    const float t211 = t36 * t208;
    const float t212 = t35 + t211;
    const float t213 = -t212;
    const float t214 = t42 * t210;
    const float t215 = t210 * t210;
    const float t216 = t5 - t215;
    const float t217 = t216 * t212;
    const float t218 = t214 + t217;
    const float t219 = t193 + t203;
    const float t220 = t37 * t219;
    const float t221 = t186 + t220;
    const float t222 = t221 + t213;
    const float t223 = t40 * t222;
    const float t224 = t0 + t223;
    const float t225 = t198 + t208;
    const float t226 = t37 * t225;
    const float t227 = t188 + t226;
    const float t228 = t227 + t218;
    const float t229 = t40 * t228;
    const float t230 = t35 + t229;
    const float t231 = 0.25f;
    const float t232 = t83 + t131;
    const float t233 = t232 + t179;
    const float t234 = t233 + t224;
    const float t235 = t231 * t234;
    const float t236 = t89 + t137;
    const float t237 = t236 + t185;
    const float t238 = t237 + t230;
    const float t239 = t231 * t238;
    const float t240 = t83 - t235;
    const float t241 = t89 - t239;
    const float t242 = t131 - t235;
    const float t243 = t137 - t239;
    const float t244 = t179 - t235;
    const float t245 = t185 - t239;
    const float t246 = t224 - t235;
    const float t247 = t230 - t239;
    const float t248 = t240 * t240;
    const float t249 = t242 * t242;
    const float t250 = t248 + t249;
    const float t251 = t244 * t244;
    const float t252 = t250 + t251;
    const float t253 = t246 * t246;
    const float t254 = t252 + t253;
    const float t255 = t231 * t254;
    const float t256 = t240 * t241;
    const float t257 = t242 * t243;
    const float t258 = t256 + t257;
    const float t259 = t244 * t245;
    const float t260 = t258 + t259;
    const float t261 = t246 * t247;
    const float t262 = t260 + t261;
    const float t263 = t231 * t262;
    const float t264 = t241 * t241;
    const float t265 = t243 * t243;
    const float t266 = t264 + t265;
    const float t267 = t245 * t245;
    const float t268 = t266 + t267;
    const float t269 = t247 * t247;
    const float t270 = t268 + t269;
    const float t271 = t231 * t270;
    const float t272 = 2.4706553e-6f;
    const float t273 = t255 + t272;
    const float t274 = 0.0002079303f;
    const float t275 = t271 + t274;
    out[0] = t235;
    out[1] = t239;
    out[2] = t273;
    out[3] = t263;
    out[4] = t275;
}

/* The UKF's start: the centre of the state box and P(0)'s upper triangle. */
static const float UKF_X0[VANDERPOL_SPARSE_STATES] = {
    0.0f, 0.0f
};
static const float UKF_P0[VANDERPOL_SPARSE_COVARIANCE] = {
    2.2759757f, 0.0f, 908.95575f
};

/* The UKF's prediction alone (a lost output), taken when finite. */
static void ukf_predict(float *x, float *p, const float *u) {
    float out[VANDERPOL_SPARSE_STATES + VANDERPOL_SPARSE_COVARIANCE];
    ukf_unmeasured(x, p, u, out);
    if (all_finite(out, VANDERPOL_SPARSE_STATES + VANDERPOL_SPARSE_COVARIANCE)) {
        memcpy(x, out, VANDERPOL_SPARSE_STATES * sizeof *x);
        memcpy(p, out + VANDERPOL_SPARSE_STATES, VANDERPOL_SPARSE_COVARIANCE * sizeof *p);
    }
}

/* The UKF's sample with its measurement, taken when finite (1, the estimate x(k|k) in
 * `estimate`, its normalised innovation squared in `*nis`). */
static int ukf_measure(float *x, float *p, const float *y, const float *u, float *estimate, float *nis) {
    float out[2u * VANDERPOL_SPARSE_STATES + VANDERPOL_SPARSE_COVARIANCE + 1u];
    ukf_measured(x, p, y, u, out);
    if (!all_finite(out + VANDERPOL_SPARSE_STATES, VANDERPOL_SPARSE_STATES + VANDERPOL_SPARSE_COVARIANCE)) {
        return 0;
    }
    *nis = out[2u * VANDERPOL_SPARSE_STATES + VANDERPOL_SPARSE_COVARIANCE];
    memcpy(estimate, out, VANDERPOL_SPARSE_STATES * sizeof *x);
    memcpy(x, out + VANDERPOL_SPARSE_STATES, VANDERPOL_SPARSE_STATES * sizeof *x);
    memcpy(p, out + 2u * VANDERPOL_SPARSE_STATES, VANDERPOL_SPARSE_COVARIANCE * sizeof *p);
    return 1;
}


static void ukf_box_fresh(vanderpol_sparse_ukf_box *o) {
    memcpy(o->x, UKF_X0, sizeof o->x);
    memcpy(o->p, UKF_P0, sizeof o->p);
    o->chi = 1.0f;
}

static vanderpol_sparse_status ukf_box_sample(vanderpol_sparse_ukf_box *o, const float *y, const float *u) {
    float estimate[VANDERPOL_SPARSE_STATES];
    float nis;
    unsigned i;
    if (!inputs_finite(u)) {
        return VANDERPOL_SPARSE_REFUSED;
    }
    if (!accepts(y, u)) {
        ukf_predict(o->x, o->p, u);
        return VANDERPOL_SPARSE_REFUSED;
    }
    if (!ukf_measure(o->x, o->p, y, u, estimate, &nis)) {
        ukf_box_fresh(o);
        return VANDERPOL_SPARSE_RESTARTED;
    }
    /* The chi-squared watch (firmware::watch): the mean of the normalised innovations squared. */
    o->chi = o->chi + 0.05263158f * (nis - o->chi);
    if (!(o->chi <= 1024.0f)) {
        ukf_box_fresh(o);
        return VANDERPOL_SPARSE_RESTARTED;
    }
    targets(estimate, u, o->values);
    for (i = 0u; i < VANDERPOL_SPARSE_TARGETS; ++i) {
        o->flags[i] = VANDERPOL_SPARSE_INSIDE;
    }
    o->ready = 1;
    return VANDERPOL_SPARSE_OK;
}

void vanderpol_sparse_ukf_box_init(vanderpol_sparse_ukf_box *o) {
    ukf_box_fresh(o);
    o->ready = 0;
    o->refused = 0u;
    o->restarts = 0u;
}

vanderpol_sparse_status vanderpol_sparse_ukf_box_push(vanderpol_sparse_ukf_box *o, const float *y, const float *u) {
    const vanderpol_sparse_status status = ukf_box_sample(o, y, u);
    if (status == VANDERPOL_SPARSE_REFUSED && o->refused != UINT32_MAX) {
        ++o->refused;
    } else if (status == VANDERPOL_SPARSE_RESTARTED && o->restarts != UINT32_MAX) {
        ++o->restarts;
    }
    return status;
}

vanderpol_sparse_status vanderpol_sparse_ukf_box_estimate(const vanderpol_sparse_ukf_box *o, float *values, vanderpol_sparse_saturation *saturation) {
    if (!o->ready) {
        return VANDERPOL_SPARSE_NO_ESTIMATE_YET;
    }
    memcpy(values, o->values, sizeof o->values);
    memcpy(saturation, o->flags, sizeof o->flags);
    return VANDERPOL_SPARSE_OK;
}

/* The start-up schedule, j = 1 … 57: the blends g_j per state, then the gains K_j (states x
 * outputs, row by row). */
static const float CORRECTED_BLENDS[57][4] = {
{
    0.26723105f, 0.26723105f, 0.34510237f, 0.50800985f
},
{
    0.15422198f, 0.15422198f, 0.20147789f, 0.310414f
},
{
    0.10838651f, 0.10838651f, 0.14322509f, 0.23027089f
},
{
    0.08355391f, 0.08355391f, 0.11166506f, 0.1868512f
},
{
    0.06797911f, 0.06797911f, 0.09187088f, 0.15961875f
},
{
    0.057298444f, 0.057298444f, 0.0782967f, 0.14094365f
},
{
    0.049518283f, 0.049518283f, 0.06840881f, 0.12734006f
},
{
    0.043598365f, 0.043598365f, 0.060885113f, 0.11698911f
},
{
    0.03894275f, 0.03894275f, 0.05496824f, 0.108848795f
},
{
    0.035185497f, 0.035185497f, 0.05019311f, 0.10227925f
},
{
    0.03208946f, 0.03208946f, 0.04625832f, 0.09686585f
},
{
    0.02949421f, 0.02949421f, 0.042959988f, 0.092328064f
},
{
    0.027287332f, 0.027287332f, 0.040155243f, 0.08846935f
},
{
    0.025387721f, 0.025387721f, 0.037741005f, 0.08514789f
},
{
    0.023735378f, 0.023735378f, 0.035641026f, 0.082258776f
},
{
    0.022284975f, 0.022284975f, 0.033797693f, 0.079722755f
},
{
    0.021001626f, 0.021001626f, 0.03216667f, 0.07747882f
},
{
    0.019858038f, 0.019858038f, 0.030713271f, 0.07547926f
},
{
    0.01883256f, 0.01883256f, 0.029409982f, 0.07368622f
},
{
    0.017907796f, 0.017907796f, 0.028234687f, 0.07206927f
},
{
    0.0170696f, 0.0170696f, 0.027169416f, 0.07060369f
},
{
    0.016306361f, 0.016306361f, 0.026199406f, 0.06926917f
},
{
    0.015608454f, 0.015608454f, 0.02531243f, 0.06804889f
},
{
    0.014967836f, 0.014967836f, 0.024498262f, 0.06692877f
},
{
    0.014377731f, 0.014377731f, 0.02374829f, 0.06589697f
},
{
    0.013832391f, 0.013832391f, 0.02305521f, 0.06494345f
},
{
    0.0133269075f, 0.0133269075f, 0.022412786f, 0.064059615f
},
{
    0.0128570665f, 0.0128570665f, 0.02181566f, 0.0632381f
},
{
    0.012419225f, 0.012419225f, 0.021259202f, 0.062472533f
},
{
    0.012010222f, 0.012010222f, 0.020739397f, 0.061757397f
},
{
    0.011627301f, 0.011627301f, 0.020252738f, 0.061087858f
},
{
    0.011268042f, 0.011268042f, 0.019796152f, 0.060459696f
},
{
    0.010930318f, 0.010930318f, 0.019366935f, 0.05986919f
},
{
    0.01061225f, 0.01061225f, 0.018962698f, 0.059313048f
},
{
    0.01031217f, 0.01031217f, 0.018581323f, 0.05878836f
},
{
    0.010028593f, 0.010028593f, 0.018220922f, 0.058292527f
},
{
    0.009760195f, 0.009760195f, 0.017879812f, 0.057823233f
},
{
    0.00950579f, 0.00950579f, 0.017556485f, 0.057378408f
},
{
    0.00926431f, 0.00926431f, 0.017249586f, 0.05695618f
},
{
    0.009034795f, 0.009034795f, 0.016957892f, 0.056554873f
},
{
    0.008816376f, 0.008816376f, 0.016680302f, 0.05617297f
},
{
    0.0086082695f, 0.0086082695f, 0.016415818f, 0.055809096f
},
{
    0.008409761f, 0.008409761f, 0.01616353f, 0.055462003f
},
{
    0.008220201f, 0.008220201f, 0.015922617f, 0.05513056f
},
{
    0.008038999f, 0.008038999f, 0.015692323f, 0.054813728f
},
{
    0.007865612f, 0.007865612f, 0.015471966f, 0.054510564f
},
{
    0.0076995473f, 0.0076995473f, 0.015260912f, 0.0542202f
},
{
    0.00754035f, 0.00754035f, 0.015058585f, 0.053941842f
},
{
    0.007387602f, 0.007387602f, 0.014864457f, 0.053674765f
},
{
    0.00724092f, 0.00724092f, 0.014678037f, 0.05341829f
},
{
    0.007099949f, 0.007099949f, 0.0144988755f, 0.053171806f
},
{
    0.006964362f, 0.006964362f, 0.0143265575f, 0.052934732f
},
{
    0.0068338574f, 0.0068338574f, 0.014160696f, 0.052706543f
},
{
    0.006708153f, 0.006708153f, 0.014000938f, 0.05248675f
},
{
    0.0065869903f, 0.0065869903f, 0.013846951f, 0.052274898f
},
{
    0.0064701266f, 0.0064701266f, 0.013698427f, 0.05207056f
},
{
    0.006357337f, 0.006357337f, 0.0135550825f, 0.051873352f
}
};
static const float CORRECTED_NO_BLEND[4] = { 0.0f };
/* The clamp of each state: its map's learning range. */
static const float CORRECTED_LOWER[VANDERPOL_SPARSE_STATES] = {
    -2.0616221f, -4.6765766f
};
static const float CORRECTED_UPPER[VANDERPOL_SPARSE_STATES] = {
    2.0616221f, 4.6765766f
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
    const float t8 = 4.0f;
    const float t9 = t8 * t0;
    const float t10 = 1.0f;
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
    const float t5 = 0.005475472f;
    const float t6 = t5 * t4;
    const float t7 = t0 + t6;
    const float t8 = 0.040757578f;
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
static void corrected_targets_of(const float *states, const vanderpol_sparse_saturation *state_flags, const float *u,
                                float *values, vanderpol_sparse_saturation *flags) {
    targets(states, u, values);
    flags[0] = VANDERPOL_SPARSE_INSIDE;
    flags[1] = VANDERPOL_SPARSE_INSIDE;
    flags[0] = state_flags[0];
    flags[1] = state_flags[1];
}

/* Corrector::start: the model's period from the map's first estimate (or from the states after
 * a correction), taken into x when finite. */
static int corrected_start(const float *first, const float *u, float *x) {
    float next[VANDERPOL_SPARSE_STATES];
    corrected_predict(first, u, next);
    if (!all_finite(next, VANDERPOL_SPARSE_STATES)) {
        return 0;
    }
    memcpy(x, next, sizeof next);
    return 1;
}

/* Corrector::follow: the correction of the prediction x (the start-up's blend and gain, or
 * G's), clamped to the states' ranges by selects, then the model's period from it. */
static int corrected_follow(float *x, unsigned j, int start_up, const float *f, const float *y, const float *u,
                            float *states, vanderpol_sparse_saturation *flags) {
    float raw[VANDERPOL_SPARSE_STATES];
    unsigned i;
    if (start_up) {
        corrected_start_up(x, y, u, f, (j >= 1u && j <= 57u) ? CORRECTED_BLENDS[j - 1u] : CORRECTED_NO_BLEND, raw);
    } else {
        corrected_steady(x, y, u, f, raw);
    }
    for (i = 0u; i < VANDERPOL_SPARSE_STATES; ++i) {
        const int low = !(raw[i] >= CORRECTED_LOWER[i]);
        const int out = low | (raw[i] > CORRECTED_UPPER[i]);
        const float edge = select_float(low, CORRECTED_LOWER[i], CORRECTED_UPPER[i]);
        const uint32_t flag = select_bits(low, (uint32_t)VANDERPOL_SPARSE_LOW, (uint32_t)VANDERPOL_SPARSE_HIGH);
        states[i] = select_float(out, edge, raw[i]);
        flags[i] = (vanderpol_sparse_saturation)select_bits(out, flag, (uint32_t)VANDERPOL_SPARSE_INSIDE);
    }
    return corrected_start(states, u, x);
}

/* Corrector::predict: a lost output, the model's period from x (no correction). */
static void corrected_lost(float *x, const float *u) {
    (void)corrected_start(x, u, x);
}


static void corrected_fresh(vanderpol_sparse_corrected *o) {
    vanderpol_sparse_map_init(&o->window);
    memset(o->x, 0, sizeof o->x);
    o->count = 0u;
    o->started = 0;
}

static vanderpol_sparse_status corrected_sample(vanderpol_sparse_corrected *o, const float *y, const float *u) {
    const int start_up = o->count <= 57u;
    float all[VANDERPOL_SPARSE_MAP_ROWS], map[VANDERPOL_SPARSE_STATES], states[VANDERPOL_SPARSE_STATES];
    vanderpol_sparse_saturation all_flags[VANDERPOL_SPARSE_MAP_ROWS], state_flags[VANDERPOL_SPARSE_STATES];
    int estimated = 0;
    if (!accepts(y, u)) {
        if (o->started && inputs_finite(u)) {
            corrected_lost(o->x, u);
        }
        return VANDERPOL_SPARSE_REFUSED;
    }
    memset(map, 0, sizeof map);
    if (start_up) {
        (void)vanderpol_sparse_map_push(&o->window, y, u);
        if (o->window.filled < VANDERPOL_SPARSE_HORIZON) {
            return VANDERPOL_SPARSE_OK;
        }
        (void)start_map_estimate(&o->window, all, all_flags);
        corrected_map_states(all, map);
        estimated = 1;
    }
    if (!o->started && estimated) {
        if (!corrected_start(map, u, o->x)) {
            corrected_fresh(o);
            return VANDERPOL_SPARSE_RESTARTED;
        }
        o->started = 1;
        memcpy(o->values, all, sizeof o->values);
        memcpy(o->flags, all_flags, sizeof o->flags);
    } else if (o->started) {
        if (!corrected_follow(o->x, o->count, start_up, map, y, u, states, state_flags)) {
            corrected_fresh(o);
            return VANDERPOL_SPARSE_RESTARTED;
        }
        corrected_targets_of(states, state_flags, u, o->values, o->flags);
    } else {
        return VANDERPOL_SPARSE_OK;
    }
    o->ready = 1;
    o->count = start_up ? o->count + 1u : o->count;
    return VANDERPOL_SPARSE_OK;
}

void vanderpol_sparse_corrected_init(vanderpol_sparse_corrected *o) {
    corrected_fresh(o);
    o->ready = 0;
    o->refused = 0u;
    o->restarts = 0u;
}

vanderpol_sparse_status vanderpol_sparse_corrected_push(vanderpol_sparse_corrected *o, const float *y, const float *u) {
    const vanderpol_sparse_status status = corrected_sample(o, y, u);
    if (status == VANDERPOL_SPARSE_REFUSED && o->refused != UINT32_MAX) {
        ++o->refused;
    } else if (status == VANDERPOL_SPARSE_RESTARTED && o->restarts != UINT32_MAX) {
        ++o->restarts;
    }
    return status;
}

vanderpol_sparse_status vanderpol_sparse_corrected_estimate(const vanderpol_sparse_corrected *o, float *values, vanderpol_sparse_saturation *saturation) {
    if (!o->ready) {
        return VANDERPOL_SPARSE_NO_ESTIMATE_YET;
    }
    memcpy(values, o->values, sizeof o->values);
    memcpy(saturation, o->flags, sizeof o->flags);
    return VANDERPOL_SPARSE_OK;
}

/* P(N-1)'s upper triangle of the EKF the map starts. */
static const float STARTED_P0[VANDERPOL_SPARSE_COVARIANCE] = {
    0.055246208f, 0.0f, 0.20179923f
};

/* Each state's map estimate, from the map's rows (a target's or a helper map's). */
static void started_ekf_map_states(const float *all, float *map) {
    map[0] = all[0];
    map[1] = all[1];
}

/* The targets of a follower's states, flagged with their states' saturation. */
static void started_ekf_targets_of(const float *states, const vanderpol_sparse_saturation *state_flags, const float *u,
                                float *values, vanderpol_sparse_saturation *flags) {
    targets(states, u, values);
    flags[0] = VANDERPOL_SPARSE_INSIDE;
    flags[1] = VANDERPOL_SPARSE_INSIDE;
    flags[0] = state_flags[0];
    flags[1] = state_flags[1];
}

/* StartedEkf::start: one prediction from the map's states with STARTED_P0, taken when finite;
 * the watched mean at its start. */
static int started_ekf_start(const float *first, const float *u, float *x, float *p, float *chi) {
    float out[VANDERPOL_SPARSE_STATES + VANDERPOL_SPARSE_COVARIANCE];
    ekf_unmeasured(first, STARTED_P0, u, out);
    if (!all_finite(out, VANDERPOL_SPARSE_STATES + VANDERPOL_SPARSE_COVARIANCE)) {
        return 0;
    }
    memcpy(x, out, VANDERPOL_SPARSE_STATES * sizeof *x);
    memcpy(p, out + VANDERPOL_SPARSE_STATES, VANDERPOL_SPARSE_COVARIANCE * sizeof *p);
    *chi = 1.0f;
    return 1;
}

/* StartedEkf::follow: the EKF's sample, every state inside; not taken when the
 * chi-squared watch (firmware::watch) finds the innovations implausible. */
static int started_ekf_follow(float *x, float *p, float *chi, unsigned j, int start_up, const float *map,
                              const float *y, const float *u, float *states, vanderpol_sparse_saturation *flags) {
    unsigned i;
    float nis;
    (void)j;
    (void)start_up;
    (void)map;
    for (i = 0u; i < VANDERPOL_SPARSE_STATES; ++i) {
        flags[i] = VANDERPOL_SPARSE_INSIDE;
    }
    if (!ekf_measure(x, p, y, u, states, &nis)) {
        return 0;
    }
    *chi = *chi + 0.05263158f * (nis - *chi);
    return *chi <= 1024.0f;
}


static void ekf_map_fresh(vanderpol_sparse_ekf_map *o) {
    vanderpol_sparse_map_init(&o->window);
    memcpy(o->x, EKF_X0, sizeof o->x);
    memcpy(o->p, EKF_P0, sizeof o->p);
    o->count = 0u;
    o->started = 0;
}

static vanderpol_sparse_status ekf_map_sample(vanderpol_sparse_ekf_map *o, const float *y, const float *u) {
    const int start_up = o->count <= 0u;
    float all[VANDERPOL_SPARSE_MAP_ROWS], map[VANDERPOL_SPARSE_STATES], states[VANDERPOL_SPARSE_STATES];
    vanderpol_sparse_saturation all_flags[VANDERPOL_SPARSE_MAP_ROWS], state_flags[VANDERPOL_SPARSE_STATES];
    int estimated = 0;
    if (!accepts(y, u)) {
        if (o->started && inputs_finite(u)) {
            ekf_predict(o->x, o->p, u);
        }
        return VANDERPOL_SPARSE_REFUSED;
    }
    memset(map, 0, sizeof map);
    if (start_up) {
        (void)vanderpol_sparse_map_push(&o->window, y, u);
        if (o->window.filled < VANDERPOL_SPARSE_HORIZON) {
            return VANDERPOL_SPARSE_OK;
        }
        (void)start_map_estimate(&o->window, all, all_flags);
        started_ekf_map_states(all, map);
        estimated = 1;
    }
    if (!o->started && estimated) {
        if (!started_ekf_start(map, u, o->x, o->p, &o->chi)) {
            ekf_map_fresh(o);
            return VANDERPOL_SPARSE_RESTARTED;
        }
        o->started = 1;
        memcpy(o->values, all, sizeof o->values);
        memcpy(o->flags, all_flags, sizeof o->flags);
    } else if (o->started) {
        if (!started_ekf_follow(o->x, o->p, &o->chi, o->count, start_up, map, y, u, states, state_flags)) {
            ekf_map_fresh(o);
            return VANDERPOL_SPARSE_RESTARTED;
        }
        started_ekf_targets_of(states, state_flags, u, o->values, o->flags);
    } else {
        return VANDERPOL_SPARSE_OK;
    }
    o->ready = 1;
    o->count = start_up ? o->count + 1u : o->count;
    return VANDERPOL_SPARSE_OK;
}

void vanderpol_sparse_ekf_map_init(vanderpol_sparse_ekf_map *o) {
    ekf_map_fresh(o);
    o->ready = 0;
    o->refused = 0u;
    o->restarts = 0u;
}

vanderpol_sparse_status vanderpol_sparse_ekf_map_push(vanderpol_sparse_ekf_map *o, const float *y, const float *u) {
    const vanderpol_sparse_status status = ekf_map_sample(o, y, u);
    if (status == VANDERPOL_SPARSE_REFUSED && o->refused != UINT32_MAX) {
        ++o->refused;
    } else if (status == VANDERPOL_SPARSE_RESTARTED && o->restarts != UINT32_MAX) {
        ++o->restarts;
    }
    return status;
}

vanderpol_sparse_status vanderpol_sparse_ekf_map_estimate(const vanderpol_sparse_ekf_map *o, float *values, vanderpol_sparse_saturation *saturation) {
    if (!o->ready) {
        return VANDERPOL_SPARSE_NO_ESTIMATE_YET;
    }
    memcpy(values, o->values, sizeof o->values);
    memcpy(saturation, o->flags, sizeof o->flags);
    return VANDERPOL_SPARSE_OK;
}

/* Whether the filter's prediction x (covariance p) and the map's states f disagree:
 * d = sum_i (x_i - f_i)^2 / (P_ii + e_i^2) > threshold, or d is NaN (restart_disagrees). */
static int restart_disagrees(const float *x, const float *p, const float *f) {
    float d = 0.0f;
    float e;
    e = x[0] - f[0];
    d += e * e / (p[0] + 0.017470384f);
    e = x[1] - f[1];
    d += e * e / (p[2] + 0.06381451f);
    return !(d <= 32.0f);
}

static void ekf_restart_fresh(vanderpol_sparse_ekf_restart *o) {
    vanderpol_sparse_map_init(&o->window);
    memcpy(o->x, EKF_X0, sizeof o->x);
    memcpy(o->p, EKF_P0, sizeof o->p);
    o->chi = 1.0f;
}

/* firmware::Restarted: the sample to the map's window; from its first estimate on, the map's states
 * against the filter's prediction at every sample, restarted from the map when they disagree;
 * else the filter's sample, restarted (from the map where it has an estimate, else from the start)
 * when its step is not finite or its chi-squared watch finds the innovations implausible. */
static vanderpol_sparse_status ekf_restart_sample(vanderpol_sparse_ekf_restart *o, const float *y, const float *u) {
    float all[VANDERPOL_SPARSE_MAP_ROWS], map[VANDERPOL_SPARSE_STATES], states[VANDERPOL_SPARSE_STATES];
    vanderpol_sparse_saturation all_flags[VANDERPOL_SPARSE_MAP_ROWS], state_flags[VANDERPOL_SPARSE_STATES];
    int mapped = 0;
    if (!accepts(y, u)) {
        if (inputs_finite(u)) {
            ekf_predict(o->x, o->p, u);
        }
        return VANDERPOL_SPARSE_REFUSED;
    }
    (void)vanderpol_sparse_map_push(&o->window, y, u);
    if (o->window.filled >= VANDERPOL_SPARSE_HORIZON) {
        (void)start_map_estimate(&o->window, all, all_flags);
        started_ekf_map_states(all, map);
        mapped = 1;
        if (restart_disagrees(o->x, o->p, map) && started_ekf_start(map, u, o->x, o->p, &o->chi)) {
            memcpy(o->values, all, sizeof o->values);
            memcpy(o->flags, all_flags, sizeof o->flags);
            o->ready = 1;
            return VANDERPOL_SPARSE_OK;
        }
    }
    if (!started_ekf_follow(o->x, o->p, &o->chi, 1u, 0, NULL, y, u, states, state_flags)) {
        if (!(mapped && started_ekf_start(map, u, o->x, o->p, &o->chi))) {
            memcpy(o->x, EKF_X0, sizeof o->x);
            memcpy(o->p, EKF_P0, sizeof o->p);
            o->chi = 1.0f;
        }
        return VANDERPOL_SPARSE_RESTARTED;
    }
    started_ekf_targets_of(states, state_flags, u, o->values, o->flags);
    o->ready = 1;
    return VANDERPOL_SPARSE_OK;
}

void vanderpol_sparse_ekf_restart_init(vanderpol_sparse_ekf_restart *o) {
    ekf_restart_fresh(o);
    o->ready = 0;
    o->refused = 0u;
    o->restarts = 0u;
}

vanderpol_sparse_status vanderpol_sparse_ekf_restart_push(vanderpol_sparse_ekf_restart *o, const float *y, const float *u) {
    const vanderpol_sparse_status status = ekf_restart_sample(o, y, u);
    if (status == VANDERPOL_SPARSE_REFUSED && o->refused != UINT32_MAX) {
        ++o->refused;
    } else if (status == VANDERPOL_SPARSE_RESTARTED && o->restarts != UINT32_MAX) {
        ++o->restarts;
    }
    return status;
}

vanderpol_sparse_status vanderpol_sparse_ekf_restart_estimate(const vanderpol_sparse_ekf_restart *o, float *values, vanderpol_sparse_saturation *saturation) {
    if (!o->ready) {
        return VANDERPOL_SPARSE_NO_ESTIMATE_YET;
    }
    memcpy(values, o->values, sizeof o->values);
    memcpy(saturation, o->flags, sizeof o->flags);
    return VANDERPOL_SPARSE_OK;
}

/* The model's derivative f(x, u), then its Jacobian row by row (the Rust file's Plant::derivative). */
static void model_derivative(const float *x, const float *u, float *out) {
    (void)u;
    const float t0 = x[1];
    const float t1 = -t0;
    const float t2 = -0.0f;
    const float t3 = -1.0f;
    const float t4 = 4.0f;
    const float t5 = x[0];
    const float t6 = t4 * t5;
    const float t7 = 1.0f;
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
static const float MHE_WEIGHTS[VANDERPOL_SPARSE_OUTPUTS] = {
    5.0f
};
static const float MHE_PRIOR[VANDERPOL_SPARSE_STATES] = {
    3787.7322f, 611.06323f
};
static const float MHE_LOWER[VANDERPOL_SPARSE_STATES] = {
    -2.5690963f, -6.396272f
};
static const float MHE_UPPER[VANDERPOL_SPARSE_STATES] = {
    2.5690963f, 6.396272f
};
static const float MHE_START[VANDERPOL_SPARSE_STATES] = {
    0.0f, 0.0f
};
static const float MHE_DAMPING = 1e-6f;
static const float MHE_H = 0.1f;
/* The chi-square watch over the windows' output costs (firmware::watch): the mean's start N m, its
 * gain 1 / W and its limit tau N m. */
static const float MHE_WATCH_START = 19.0f;
static const float MHE_WATCH_GAIN = 0.05263158f;
static const float MHE_WATCH_LIMIT = 19456.0f;
#define MHE_ITERATIONS 3u
#define MHE_SUBSTEPS 1u
#define MHE_NX VANDERPOL_SPARSE_STATES
#define MHE_NY VANDERPOL_SPARSE_OUTPUTS
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
static void mhe_normal(const vanderpol_sparse_mhe *o, const float *x, float (*matrix)[MHE_NX], float *gradient, float *cost) {
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
    for (k = 0u; k < VANDERPOL_SPARSE_HORIZON; ++k) {
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
static void mhe_solve_window(const vanderpol_sparse_mhe *o, const float *centre, int prior, float *solution, float *end, float *cost) {
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
    for (k = 1u; k < VANDERPOL_SPARSE_HORIZON; ++k) {
        float next[MHE_NX];
        float f[MHE_NX][MHE_NX];
        mhe_step(state, MHE_U(o, k - 1u), next, f);
        memcpy(state, next, sizeof state);
    }
    mhe_project(state, end);
}

void vanderpol_sparse_mhe_init(vanderpol_sparse_mhe *o) {
    o->next = 0u;
    o->filled = 0u;
    o->has_solved = 0;
    o->ready = 0;
    o->restarts = 0u;
    o->chi = 0.0f;
    o->has_chi = 0;
}

vanderpol_sparse_status vanderpol_sparse_mhe_push(vanderpol_sparse_mhe *o, const float *y, const float *u) {
    float moved[MHE_NX], x[MHE_NX], end[MHE_NX], values[VANDERPOL_SPARSE_TARGETS], cost;
    int has_moved = 0;
    unsigned i, slot;
    float chi;
    if (!all_finite(y, VANDERPOL_SPARSE_OUTPUTS) || !inputs_finite(u)) {
        return VANDERPOL_SPARSE_REFUSED;
    }
    /* The previous solution moved one sample on: the prior's centre and the first iterate. */
    if (o->has_solved && o->filled >= VANDERPOL_SPARSE_HORIZON) {
        float next[MHE_NX];
        float f[MHE_NX][MHE_NX];
        mhe_step(o->solved, MHE_U(o, 0u), next, f);
        mhe_project(next, moved);
        has_moved = 1;
    }
    /* Every value of the sample is finite: stored. */
    slot = o->next;
    for (i = 0u; i < VANDERPOL_SPARSE_OUTPUTS; ++i) {
        o->y[slot][i] = y[i];
        o->y[slot + VANDERPOL_SPARSE_HORIZON][i] = y[i];
    }
    o->next = slot + 1u >= VANDERPOL_SPARSE_HORIZON ? 0u : slot + 1u;
    o->filled += (unsigned)(o->filled < VANDERPOL_SPARSE_HORIZON);
    if (o->filled < VANDERPOL_SPARSE_HORIZON) {
        return VANDERPOL_SPARSE_OK;
    }
    mhe_solve_window(o, has_moved ? moved : MHE_START, has_moved, x, end, &cost);
    targets(end, u, values);
    /* firmware::watch: the windows' costs' mean, from its start after a (re)start. */
    chi = o->has_chi ? o->chi : MHE_WATCH_START;
    chi = chi + MHE_WATCH_GAIN * (cost - chi);
    if (!all_finite(x, MHE_NX) || !all_finite(end, MHE_NX) || !all_finite(values, VANDERPOL_SPARSE_TARGETS)
        || !(chi <= MHE_WATCH_LIMIT)) {
        /* Restarted: the next window is solved from the start, not from this solution. */
        o->has_chi = 0;
        o->has_solved = 0;
        if (o->restarts != UINT32_MAX) {
            ++o->restarts;
        }
        return VANDERPOL_SPARSE_RESTARTED;
    }
    memcpy(o->solved, x, sizeof x);
    o->has_solved = 1;
    o->chi = chi;
    o->has_chi = 1;
    memcpy(o->values, values, sizeof values);
    for (i = 0u; i < VANDERPOL_SPARSE_TARGETS; ++i) {
        o->flags[i] = VANDERPOL_SPARSE_INSIDE;
    }
    o->ready = 1;
    return VANDERPOL_SPARSE_OK;
}

#undef MHE_ITERATIONS
#undef MHE_SUBSTEPS
#undef MHE_NX
#undef MHE_NY
#undef MHE_U

vanderpol_sparse_status vanderpol_sparse_mhe_estimate(const vanderpol_sparse_mhe *o, float *values, vanderpol_sparse_saturation *saturation) {
    if (!o->ready) {
        return VANDERPOL_SPARSE_NO_ESTIMATE_YET;
    }
    memcpy(values, o->values, sizeof o->values);
    memcpy(saturation, o->flags, sizeof o->flags);
    return VANDERPOL_SPARSE_OK;
}

/* The mark of this design's observer in storage (never 0: zeroed storage holds none). */
#define STORAGE_MARK 0x19a78b3901da6189ull

/* The observer in storage: VANDERPOL_SPARSE_BAD_ARGUMENT for a null or misaligned pointer,
 * VANDERPOL_SPARSE_NOT_INITIALISED where vanderpol_sparse_init did not make one (it reads the first 16 bytes only). */
static vanderpol_sparse_status stored_observer(void *storage, vanderpol_sparse_observer **observer) {
    vanderpol_sparse_stored *stored = (vanderpol_sparse_stored *)storage;
    if (storage == NULL || (uintptr_t)storage % VANDERPOL_SPARSE_STORAGE_ALIGN != 0u) {
        return VANDERPOL_SPARSE_BAD_ARGUMENT;
    }
    if (stored->mark != STORAGE_MARK || stored->size < (uint64_t)sizeof(vanderpol_sparse_stored)) {
        return VANDERPOL_SPARSE_NOT_INITIALISED;
    }
    *observer = &stored->observer;
    return VANDERPOL_SPARSE_OK;
}

vanderpol_sparse_status vanderpol_sparse_init(void *storage, size_t size) {
    vanderpol_sparse_stored *stored = (vanderpol_sparse_stored *)storage;
    if (storage == NULL || size < sizeof(vanderpol_sparse_stored) || (uintptr_t)storage % VANDERPOL_SPARSE_STORAGE_ALIGN != 0u) {
        return VANDERPOL_SPARSE_BAD_ARGUMENT;
    }
    stored->mark = STORAGE_MARK;
    stored->size = (uint64_t)size;
    vanderpol_sparse_observer_init(&stored->observer);
    return VANDERPOL_SPARSE_OK;
}

vanderpol_sparse_status vanderpol_sparse_push(void *storage, const float *y, const float *u) {
    vanderpol_sparse_observer *observer = NULL;
    const vanderpol_sparse_status found = stored_observer(storage, &observer);
    if (found != VANDERPOL_SPARSE_OK) {
        return found;
    }
    if (y == NULL) {
        return VANDERPOL_SPARSE_BAD_ARGUMENT;
    }
    return vanderpol_sparse_observer_push(observer, y, u);
}

vanderpol_sparse_status vanderpol_sparse_estimate(void *storage, float *estimates, vanderpol_sparse_saturation *saturation) {
    vanderpol_sparse_observer *observer = NULL;
    vanderpol_sparse_saturation flags[VANDERPOL_SPARSE_TARGETS];
    const vanderpol_sparse_status found = stored_observer(storage, &observer);
    if (found != VANDERPOL_SPARSE_OK) {
        return found;
    }
    if (estimates == NULL) {
        return VANDERPOL_SPARSE_BAD_ARGUMENT;
    }
    return vanderpol_sparse_observer_estimate(observer, estimates, saturation != NULL ? saturation : flags);
}

size_t vanderpol_sparse_storage_size(void) {
    return sizeof(vanderpol_sparse_stored);
}

#undef STORAGE_MARK
