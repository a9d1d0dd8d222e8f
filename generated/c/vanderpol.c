/* The `vanderpol` observer in C99, emitted by `mho gen`. Do not edit: regenerate. */
#include <stdint.h>
#include <string.h>
#include "vanderpol.h"

/* `x1`: gains in regressor order, then the Γ⁻¹ table's segments (a, b). */
static const float GAINS_0[10] = {
    4.0281353f, 0.68335295f, -0.87648195f, -1.1985004f,
    -1.0801039f, -0.37953317f, 0.18793039f, 0.40863973f,
    -0.61078054f, -3.5780258f
};
static const float SEGMENTS_0[92][2] = {
    { -2.411638f, 0.016688406f },
    { -2.4123118f, 0.017362183f },
    { -2.4137836f, 0.018097974f },
    { -2.416198f, 0.01890284f },
    { -2.4197261f, 0.019784853f },
    { -2.4245682f, 0.02075325f },
    { -2.43096f, 0.021818569f },
    { -2.4391797f, 0.022992795f },
    { -2.449553f, 0.024289466f },
    { -2.4624615f, 0.025723737f },
    { -2.4783473f, 0.027312338f },
    { -2.4977186f, 0.029073356f },
    { -2.5211465f, 0.031025676f },
    { -2.5492566f, 0.033187997f },
    { -2.582704f, 0.035577103f },
    { -2.6221254f, 0.038205184f },
    { -2.6680577f, 0.041075956f },
    { -2.7208185f, 0.04417954f },
    { -2.7803438f, 0.047486488f },
    { -2.846002f, 0.050942194f },
    { -2.9164362f, 0.0544639f },
    { -2.989502f, 0.05794323f },
    { -3.062393f, 0.061256446f },
    { -3.1319852f, 0.064282194f },
    { -3.195344f, 0.06692214f },
    { -3.25023f, 0.06911759f },
    { -3.2954264f, 0.07085591f },
    { -3.330788f, 0.07216559f },
    { -3.3570473f, 0.073103435f },
    { -3.3754973f, 0.07373964f },
    { -3.3876696f, 0.074145384f },
    { -3.3950882f, 0.0743847f },
    { -3.3991182f, 0.074510634f },
    { -3.4008937f, 0.074564435f },
    { -3.401302f, 0.074576445f },
    { -3.4009998f, 0.07456781f },
    { -3.4004433f, 0.07455236f },
    { -3.3999245f, 0.07453833f },
    { -3.3996034f, 0.07452988f },
    { -3.3995404f, 0.07452827f },
    { -3.399724f, 0.07453285f },
    { -3.4000928f, 0.074541844f },
    { -3.4005578f, 0.07455292f },
    { -3.40102f, 0.074563675f },
    { -3.4013858f, 0.07457198f },
    { -3.4015796f, 0.07457629f },
    { -3.4015548f, 0.07457575f },
    { -3.4013004f, 0.074570335f },
    { -3.4008453f, 0.07456086f },
    { -3.4002578f, 0.07454886f },
    { -3.3996408f, 0.074536525f },
    { -3.3991213f, 0.07452634f },
    { -3.3988338f, 0.07452081f },
    { -3.3988945f, 0.07452195f },
    { -3.3993657f, 0.07453068f },
    { -3.4002063f, 0.074545965f },
    { -3.4012053f, 0.0745638f },
    { -3.4018912f, 0.07457584f },
    { -3.401417f, 0.07456766f },
    { -3.398413f, 0.07451674f },
    { -3.3908165f, 0.074390136f },
    { -3.3756938f, 0.074142225f },
    { -3.349103f, 0.07371334f },
    { -3.3060749f, 0.07303036f },
    { -3.2408423f, 0.0720111f },
    { -3.1474435f, 0.070574194f },
    { -3.0207608f, 0.06865476f },
    { -2.8578565f, 0.06622335f },
    { -2.6591892f, 0.06330177f },
    { -2.429154f, 0.059967928f },
    { -2.1755621f, 0.056345187f },
    { -1.9081869f, 0.05257934f },
    { -1.6369499f, 0.04881216f },
    { -1.3704251f, 0.045161135f },
    { -1.115029f, 0.041709837f },
    { -0.874887f, 0.038507942f },
    { -0.65214163f, 0.03557708f },
    { -0.44744086f, 0.032918632f },
    { -0.26042584f, 0.030521002f },
    { -0.09013152f, 0.028365377f },
    { 0.06472154f, 0.026429715f },
    { 0.20553209f, 0.024691314f },
    { 0.33369735f, 0.023128321f },
    { 0.45054427f, 0.021720527f },
    { 0.55729496f, 0.020449685f },
    { 0.6550534f, 0.019299587f },
    { 0.7448044f, 0.018255971f },
    { 0.82741964f, 0.01730637f },
    { 0.90366733f, 0.016439918f },
    { 0.97422236f, 0.015647165f },
    { 1.0396773f, 0.014919889f },
    { 1.1005523f, 0.014250932f }
};

/* `x2`: gains in regressor order, then the Γ⁻¹ table's segments (a, b). */
static const float GAINS_1[10] = {
    0.03496939f, 0.032472618f, 0.020010445f, 0.008153512f,
    -0.00033767632f, -0.0037675358f, -0.0035363836f, 0.0008704437f,
    0.009133846f, 0.021195892f
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
                     float *value, vanderpol_saturation *saturation) {
    const float inside = segment[0] + segment[1] * (t - start);
    const int low = !(t >= 0.0f);
    const int out = low | (t > t_max);
    const uint32_t flag = select_bits(low, (uint32_t)VANDERPOL_LOW, (uint32_t)VANDERPOL_HIGH);
    *value = select_float(out, select_float(low, r_min, r_max), inside);
    *saturation = (vanderpol_saturation)select_bits(out, flag, (uint32_t)VANDERPOL_INSIDE);
}

void vanderpol_map_init(vanderpol_map *observer) {
    observer->next = 0u;
    observer->filled = 0u;
}

vanderpol_status vanderpol_map_push(vanderpol_map *observer, const float *y, const float *u) {
    unsigned i;
    unsigned slot;
    int finite = 1;
    for (i = 0u; i < VANDERPOL_OUTPUTS; ++i) {
        finite &= is_finite(y[i]);
    }
    if (!finite) {
        return VANDERPOL_REFUSED;
    }
    slot = observer->next;
    for (i = 0u; i < VANDERPOL_OUTPUTS; ++i) {
        observer->y[slot][i] = y[i];
        observer->y[slot + VANDERPOL_HORIZON][i] = y[i];
    }
    (void)u;
    observer->next = slot + 1u >= VANDERPOL_HORIZON ? 0u : slot + 1u;
    observer->filled = observer->filled >= VANDERPOL_HORIZON ? VANDERPOL_HORIZON : observer->filled + 1u;
    return VANDERPOL_OK;
}

vanderpol_status vanderpol_map_estimate(const vanderpol_map *observer, float *values, vanderpol_saturation *saturation) {
    const unsigned next = observer->next;
    if (observer->filled < VANDERPOL_HORIZON) {
        return VANDERPOL_NO_ESTIMATE_YET;
    }
    const float t_0 = 45.57301f
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
    const uint32_t k_0 = uniform_segment(t_0, 92u);
    evaluate(t_0, SEGMENTS_0[k_0], 0.0f, 92.0f, -2.411638f, 2.411638f, &values[0], &saturation[0]);
    const float t_1 = 0.49988478f
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
    const uint32_t k_1 = uniform_segment(t_1, 1u);
    evaluate(t_1, SEGMENTS_1[k_1], 0.0f, 1.0f, -4.6765766f, 4.6765766f, &values[1], &saturation[1]);
    return VANDERPOL_OK;
}
