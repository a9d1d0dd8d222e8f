/* Example 1's observer from C, on the emulated Cortex-M4F (QEMU mps2-an386) or your board: every
 * sample period it reads a measurement, pushes it into the observer `gen` wrote as C
 * (generated/c/vanderpol.h, .c) and prints the estimate over semihosting. The measurements replay a
 * run `mho simulate` recorded (the y column of ../board/data/run.csv); on your board, read your ADC
 * in read_sensor instead. Build and run: README.md. */
#include <stdio.h>
#include "vanderpol.h"

#define SAMPLES 60u

/* The y column of ../board/data/run.csv, as f32. */
static const float RECORDED[SAMPLES] = {
    2.153243f, 2.3621366f, 3.680321f, 3.638622f, 3.7518804f, 3.4455829f, 3.3487124f, 4.458636f,
    3.9554925f, 4.7838607f, 3.3977695f, 3.096212f, 2.1380959f, 0.5310821f, -0.7347244f, -1.6958778f,
    -2.8441973f, -3.4806828f, -3.4741683f, -3.8206472f, -3.6862216f, -3.506493f, -4.213322f, -4.2910333f,
    -4.3540487f, -4.0903254f, -3.5220737f, -3.7922602f, -2.6810462f, 0.16289243f, 1.0392927f, 1.6773835f,
    2.5919456f, 2.7042735f, 3.2723105f, 3.4911485f, 3.239472f, 3.17196f, 3.9336703f, 3.9110596f,
    4.0014944f, 5.029585f, 4.246353f, 3.550176f, 1.633547f, 0.4415519f, -0.8231801f, -2.2369573f,
    -2.4283812f, -2.7219887f, -2.942305f, -4.158789f, -3.8757658f, -3.193966f, -4.0078435f, -3.0462558f,
    -3.8849418f, -3.921392f, -4.011075f, -3.55297f
};

/* This period's measurement of the output y. */
static float read_sensor(unsigned k) {
    return RECORDED[k];
}

int main(void) {
    static vanderpol_observer observer; /* the kind gen chose for Example 1 (VANDERPOL_KIND) */
    unsigned k, i;
    vanderpol_observer_init(&observer);
    for (k = 0u; k < SAMPLES; ++k) {
        const float y[VANDERPOL_OUTPUTS] = {read_sensor(k)};
        float x[VANDERPOL_TARGETS];
        vanderpol_saturation flags[VANDERPOL_TARGETS];
        if (vanderpol_observer_push(&observer, y, NULL) != VANDERPOL_OK) {
            printf("%u refused\n", k);
            continue;
        }
        if (vanderpol_observer_estimate(&observer, x, flags) != VANDERPOL_OK) {
            printf("%u no estimate yet\n", k);
            continue;
        }
        printf("%u", k);
        for (i = 0u; i < VANDERPOL_TARGETS; ++i) {
            /* 9 significant digits: the f32 itself, read back. */
            printf(" %.9g%s", (double)x[i], flags[i] == VANDERPOL_LOW ? " (low)" : flags[i] == VANDERPOL_HIGH ? " (high)" : "");
        }
        printf("\n");
    }
    printf("DONE\n");
    return 0;
}
