{# What the model-based kinds share: the helpers a program's calls need that <math.h> lacks (`signum`
   and `fract` as firmware::Maths defines them; `expf` as the firmware's libm 0.2.16, from FreeBSD's
   e_expf.c, computes it, operation for operation, so that a model calling `exp` gives the Rust
   observer's bits whatever the C library; its body is shipped unindented, as it always was), then
   the checks of a sample's values. -#}
{% if signum -%}
/* 1 with the sign of v (NaN stays NaN), as firmware::Maths::signum; NaN told by its bits. */
static float signum(float v) {
    return select_float((bits_of(v) & 0x7fffffffu) > 0x7f800000u, v, copysignf(1.0f, v));
}

{% endif -%}
{% if exp -%}
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

{% endif -%}
{% if fract -%}
/* v - trunc(v), as firmware::Maths::fract. */
static float fract(float v) {
    return v - truncf(v);
}

{% endif %}
/* 1 when every input is finite. */
static int inputs_finite(const float *u) {
{%- if inputs %}
    unsigned i;
    int finite = 1;
    for (i = 0u; i < {{ upper }}_INPUTS; ++i) {
        finite &= is_finite(u[i]);
    }
    return finite;
{%- else %}
    (void)u;
    return 1;
{%- endif %}
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


