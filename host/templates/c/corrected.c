{# The model-corrected map's source: the start-up schedule (no table for no rows: C has no empty
   arrays, every estimate then takes G) and the clamp, its programs (`functions`), and
   `firmware::Started` over the follower `Corrector`. -#}
{% if blends > 0 -%}
/* The start-up schedule, j = 1 … {{ blends }}: the blends g_j per state, then the gains K_j (states x
 * outputs, row by row). */
static const float CORRECTED_BLENDS[{{ blends }}][{{ scheduled }}] = {
{{ rows }}
};
{% endif -%}
static const float CORRECTED_NO_BLEND[{{ scheduled }}] = { 0.0f };
/* The clamp of each state: its map's learning range. */
static const float CORRECTED_LOWER[{{ upper }}_STATES] = {{ lower }};
static const float CORRECTED_UPPER[{{ upper }}_STATES] = {{ upper_bounds }};

{{ functions }}{{ map_states }}{{ targets_of }}/* Corrector::start: the model's period from the map's first estimate (or from the states after
 * a correction), taken into x when finite. */
static int corrected_start(const float *first, const float *u, float *x) {
    float next[{{ upper }}_STATES];
    corrected_predict(first, u, next);
    if (!all_finite(next, {{ upper }}_STATES)) {
        return 0;
    }
    memcpy(x, next, sizeof next);
    return 1;
}

/* Corrector::follow: the correction of the prediction x (the start-up's blend and gain, or
 * G's), clamped to the states' ranges by selects, then the model's period from it. */
static int corrected_follow(float *x, unsigned j, int start_up, const float *f, const float *y, const float *u,
                            float *states, {{ name }}_saturation *flags) {
    float raw[{{ upper }}_STATES];
    unsigned i;
    if (start_up) {
        corrected_start_up(x, y, u, f, {% if blends > 0 %}(j >= 1u && j <= {{ blends }}u) ? CORRECTED_BLENDS[j - 1u] : CORRECTED_NO_BLEND{% else %}CORRECTED_NO_BLEND{% endif %}, raw);
    } else {
        corrected_steady(x, y, u, f, raw);
    }
    for (i = 0u; i < {{ upper }}_STATES; ++i) {
        const int low = !(raw[i] >= CORRECTED_LOWER[i]);
        const int out = low | (raw[i] > CORRECTED_UPPER[i]);
        const float edge = select_float(low, CORRECTED_LOWER[i], CORRECTED_UPPER[i]);
        const uint32_t flag = select_bits(low, (uint32_t){{ upper }}_LOW, (uint32_t){{ upper }}_HIGH);
        states[i] = select_float(out, edge, raw[i]);
        flags[i] = ({{ name }}_saturation)select_bits(out, flag, (uint32_t){{ upper }}_INSIDE);
    }
    return corrected_start(states, u, x);
}

/* Corrector::predict: a lost output, the model's period from x (no correction). */
static void corrected_lost(float *x, const float *u) {
    (void)corrected_start(x, u, x);
}

{{ observer }}
