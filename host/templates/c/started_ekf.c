{# `ekf_map`: the follower `StartedEkf` (start at the map's states with its `P(N-1)`, then the EKF's
   samples, every state inside) and its observer. -#}
/* P(N-1)'s upper triangle of the EKF the map starts. */
static const float STARTED_P0[{{ upper }}_COVARIANCE] = {{ p0 }};

{{ map_states }}{{ targets_of }}/* StartedEkf::start: one prediction from the map's states with STARTED_P0, taken when finite. */
static int started_ekf_start(const float *first, const float *u, float *x, float *p) {
    float out[{{ upper }}_STATES + {{ upper }}_COVARIANCE];
    ekf_unmeasured(first, STARTED_P0, u, out);
    if (!all_finite(out, {{ upper }}_STATES + {{ upper }}_COVARIANCE)) {
        return 0;
    }
    memcpy(x, out, {{ upper }}_STATES * sizeof *x);
    memcpy(p, out + {{ upper }}_STATES, {{ upper }}_COVARIANCE * sizeof *p);
    return 1;
}

/* StartedEkf::follow: the EKF's sample, every state inside. */
static int started_ekf_follow(float *x, float *p, unsigned j, int start_up, const float *map, const float *y,
                              const float *u, float *states, {{ name }}_saturation *flags) {
    unsigned i;
    (void)j;
    (void)start_up;
    (void)map;
    for (i = 0u; i < {{ upper }}_STATES; ++i) {
        flags[i] = {{ upper }}_INSIDE;
    }
    return ekf_measure(x, p, y, u, states);
}

{{ observer }}
