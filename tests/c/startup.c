/* Cortex-M reset for the emulated board: the vector table, the FPU on, then newlib's semihosting start. */
#include <stdint.h>
extern void _start(void);
extern uint32_t __stack;
void reset(void) {
    *(volatile uint32_t *)0xE000ED88 |= 0xFu << 20; /* CPACR: CP10, CP11 full access */
    __asm volatile("dsb\n isb");
    _start();
    for (;;) {}
}
static void hang(void) { for (;;) {} }
__attribute__((section(".vectors"), used)) static const void *const vectors[16] = {
    &__stack, (void *)reset, (void *)hang, (void *)hang, (void *)hang, (void *)hang, (void *)hang,
};
