/* The `ecoli_x0_0p5` observer in C99, emitted by `mho gen`. Do not edit: regenerate. */
#include <stdint.h>
#include <string.h>
#include "ecoli_x0_0p5.h"

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
                     float *value, ecoli_x0_0p5_saturation *saturation) {
    const float inside = segment[0] + segment[1] * (t - start);
    const int low = !(t >= 0.0f);
    const int out = low | (t > t_max);
    const uint32_t flag = select_bits(low, (uint32_t)ECOLI_X0_0P5_LOW, (uint32_t)ECOLI_X0_0P5_HIGH);
    *value = select_float(out, select_float(low, r_min, r_max), inside);
    *saturation = (ecoli_x0_0p5_saturation)select_bits(out, flag, (uint32_t)ECOLI_X0_0P5_INSIDE);
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
    observer->filled = observer->filled >= ECOLI_X0_0P5_HORIZON ? ECOLI_X0_0P5_HORIZON : observer->filled + 1u;
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
    const uint32_t k_0 = uniform_segment(t_0, 88u);
    evaluate(t_0, SEGMENTS_0[k_0], 0.0f, 88.0f, 0.0f, 0.4457929f, &values[0], &saturation[0]);
    const float t_1 = 0.022176465f
        + GAINS_1[0] * observer->y[next + 2u][0]
        + GAINS_1[1] * observer->y[next + 2u][1]
        + GAINS_1[2] * observer->y[next + 1u][0]
        + GAINS_1[3] * observer->y[next + 1u][1]
        + GAINS_1[4] * observer->y[next + 0u][0]
        + GAINS_1[5] * observer->y[next + 0u][1];
    const uint32_t k_1 = uniform_segment(t_1, 1u);
    evaluate(t_1, SEGMENTS_1[k_1], 0.0f, 1.0f, 0.0f, 0.43531778f, &values[1], &saturation[1]);
    return ECOLI_X0_0P5_OK;
}
