{# A filter's start and one sample (the Rust filter's `push`), shared by the kinds over it. -#}
/* The {{ label }}'s start: the centre of the state box and P(0)'s upper triangle. */
static const float {{ label }}_X0[{{ upper }}_STATES] = {{ x0 }};
static const float {{ label }}_P0[{{ upper }}_COVARIANCE] = {{ p0 }};

/* The {{ label }}'s prediction alone (a lost output), taken when finite. */
static void {{ lower }}_predict(float *x, float *p, const float *u) {
    float out[{{ upper }}_STATES + {{ upper }}_COVARIANCE];
    {{ lower }}_unmeasured(x, p, u, out);
    if (all_finite(out, {{ upper }}_STATES + {{ upper }}_COVARIANCE)) {
        memcpy(x, out, {{ upper }}_STATES * sizeof *x);
        memcpy(p, out + {{ upper }}_STATES, {{ upper }}_COVARIANCE * sizeof *p);
    }
}

/* The {{ label }}'s sample with its measurement, taken when finite (1, the estimate x(k|k) in
 * `estimate`, its normalised innovation squared in `*nis`). */
static int {{ lower }}_measure(float *x, float *p, const float *y, const float *u, float *estimate, float *nis) {
    float out[2u * {{ upper }}_STATES + {{ upper }}_COVARIANCE + 1u];
    {{ lower }}_measured(x, p, y, u, out);
    if (!all_finite(out + {{ upper }}_STATES, {{ upper }}_STATES + {{ upper }}_COVARIANCE)) {
        return 0;
    }
    *nis = out[2u * {{ upper }}_STATES + {{ upper }}_COVARIANCE];
    memcpy(estimate, out, {{ upper }}_STATES * sizeof *x);
    memcpy(x, out + {{ upper }}_STATES, {{ upper }}_STATES * sizeof *x);
    memcpy(p, out + 2u * {{ upper }}_STATES, {{ upper }}_COVARIANCE * sizeof *p);
    return 1;
}


