/* The `vanderpol_uncertain` observer in C99, emitted by `mho gen`. Do not edit: regenerate. */
#include <stdint.h>
#include <string.h>
#include "vanderpol_uncertain.h"

/* `x1`: gains in regressor order, then the Γ⁻¹ table's segments (a, b). */
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

/* `x2`: gains in regressor order, then the Γ⁻¹ table's segments (a, b). */
static const float GAINS_1[10] = {
    0.06632062f, 0.06250297f, 0.040498633f, 0.01797323f,
    0.00079974055f, -0.007791193f, -0.007125094f, -0.00076618337f,
    0.016579298f, 0.044361085f
};
static const float SEGMENTS_1[2][2] = {
    { -4.7017317f, 4.766553f },
    { -4.701727f, 4.7665486f }
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
                     float *value, vanderpol_uncertain_saturation *saturation) {
    const float inside = segment[0] + segment[1] * (t - start);
    const int low = !(t >= 0.0f);
    const int out = low | (t > t_max);
    const uint32_t flag = select_bits(low, (uint32_t)VANDERPOL_UNCERTAIN_LOW, (uint32_t)VANDERPOL_UNCERTAIN_HIGH);
    *value = select_float(out, select_float(low, r_min, r_max), inside);
    *saturation = (vanderpol_uncertain_saturation)select_bits(out, flag, (uint32_t)VANDERPOL_UNCERTAIN_INSIDE);
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
    observer->filled = observer->filled >= VANDERPOL_UNCERTAIN_HORIZON ? VANDERPOL_UNCERTAIN_HORIZON : observer->filled + 1u;
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
    const uint32_t k_0 = uniform_segment(t_0, 99u);
    evaluate(t_0, SEGMENTS_0[k_0], 0.0f, 99.0f, -2.4087043f, 2.3542836f, &values[0], &saturation[0]);
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
    const uint32_t k_1 = uniform_segment(t_1, 2u);
    evaluate(t_1, SEGMENTS_1[k_1], 0.0f, 2.0f, -4.7017317f, 4.83137f, &values[1], &saturation[1]);
    return VANDERPOL_UNCERTAIN_OK;
}
