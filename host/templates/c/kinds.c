{# What the model-based kinds share: the helpers a program's calls need that <math.h> lacks (`signum`
   and `fract` as firmware::Maths defines them; `expf` as the firmware's libm 0.2.16, from FreeBSD's
   e_expf.c, computes it, operation for operation, so that a model calling `exp` gives the Rust
   observer's bits whatever the C library; its body is shipped unindented, as it always was), then
   the checks of a sample's values; `logf` likewise, from e_logf.c). -#}
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
{% if ln -%}
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


