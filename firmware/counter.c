/* counter: instructions counted with SysTick under QEMU -icount.
 *
 * QEMU does not emulate the DWT cycle counter. With -icount shift=S every
 * instruction advances virtual time by 2^S ns, and SysTick, clocked from
 * the CPU clock, decrements once per clock period. So ticks * period_ns /
 * 2^S is an instruction count (not a cycle count), deterministic from run
 * to run. The 24-bit counter wraps every 2^24 ticks; the interrupt counts
 * the wraps. The host-side script converts ticks to instructions with the
 * board's clock (tests/qemu.sh). */
#include "board.h"

#define SYST_CSR (*(volatile uint32_t *)0xE000E010u)
#define SYST_RVR (*(volatile uint32_t *)0xE000E014u)
#define SYST_CVR (*(volatile uint32_t *)0xE000E018u)
#define SYST_RELOAD 0x00FFFFFFu

static volatile uint32_t counter_wraps;

void SysTick_Handler(void);
void SysTick_Handler(void)
{
    counter_wraps++;
}

void counter_start(void)
{
    SYST_CSR = 0;
    SYST_RVR = SYST_RELOAD;
    SYST_CVR = 0; /* any write clears it; it reloads on the next tick */
    counter_wraps = 0;
    SYST_CSR = 7u; /* enable, interrupt on wrap, CPU clock */
}

uint64_t counter_ticks(void)
{
    uint32_t w, v;
    do { /* re-read if a wrap happened in between */
        w = counter_wraps;
        v = SYST_CVR;
    } while (w != counter_wraps);
    /* Within a period the counter runs RELOAD, ..., 1, 0, and the wrap
     * interrupt comes as it reaches 0: v = 0 is the start of a period.
     * After counter_start it sits at 0 until its first tick. */
    return (uint64_t)w * (SYST_RELOAD + 1u) + ((SYST_RELOAD + 1u - v) & SYST_RELOAD);
}
