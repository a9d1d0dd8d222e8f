{# A design's C source (`<name>.c`): the checks and helpers its pieces call, then the pieces. -#}
/* The `{{ name }}` observers in C99, emitted by `mho gen`. Do not edit: regenerate.
{{ licence }} */
#include <stdint.h>
#include <string.h>
{% if math %}#include <math.h>
{% endif %}#include <float.h>
#include "{{ name }}.h"

/* The Rust observer's bits need every float operation rounded on its own: no fused multiply-add
 * (gcc: -ffp-contract=off, the default of its ISO modes such as -std=c99; other compilers follow
 * the standard pragma below), no -ffast-math, and float evaluated as float: FLT_EVAL_METHOD 0,
 * or 16 or 32 (ISO/IEC TS 18661-3: types narrower than _Float16, or _Float32, are evaluated in
 * it, so float stays float; gcc says 16 for a Cortex-M55 or with AVX512-FP16 in its GNU modes). */
#if !defined(__GNUC__) || defined(__clang__)
#pragma STDC FP_CONTRACT OFF
#endif
{#- The check that `float` expressions are evaluated in `float`, by FLT_EVAL_METHOD (C99 5.2.4.2.2,
    ISO/IEC TS 18661-3 for 16 and up): accepted are 0 and the TS's 16 and 32, under which every type
    narrower than _Float16 (resp. _Float32) is evaluated in it and float in float (gcc reports 16 for
    -mcpu=cortex-m55 and for x86 with AVX512-FP16 outside its ISO modes); refused, each with its
    reason, are 1 (float evaluated in double), 2 (in long double, e.g. the x87), -1 (indeterminate)
    and every other value (a wider format: 64, 33, …). #}
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

{% if accepts -%}
/* 1 when every output and input of a sample is finite (u is not read without inputs). */
static int accepts(const float *y, const float *u) {
    unsigned i;
    int finite = 1;
    for (i = 0u; i < {{ upper }}_OUTPUTS; ++i) {
        finite &= is_finite(y[i]);
    }
{%- if inputs %}
    for (i = 0u; i < {{ upper }}_INPUTS; ++i) {
        finite &= is_finite(u[i]);
    }
{%- else %}
    (void)u;
{%- endif %}
    return finite;
}

{% endif -%}
{% if choose_float -%}
/* c ? a : b, one select per statement: compilers make it a conditional move (an IT block on
 * Thumb-2), where a chain of them on one condition may become a branch. */
static float choose_float(int c, float a, float b) {
    return c ? a : b;
}

{% endif -%}
{% if select_bits -%}
/* c ? a : b by masks, without a branch (c is 0 or 1): the same instructions whatever c is. */
static uint32_t select_bits(int c, uint32_t a, uint32_t b) {
    const uint32_t mask = 0u - (uint32_t)c;
    return (a & mask) | (b & ~mask);
}

{% endif -%}
{% if select_float -%}
static float select_float(int c, float a, float b) {
    uint32_t x = select_bits(c, bits_of(a), bits_of(b));
    memcpy(&a, &x, sizeof a);
    return a;
}

{% endif -%}
{{ body }}
