/* calibrate: a firmware image that runs a loop of exactly 2 * 10^6 + a few
 * instructions and reports the SysTick ticks, so tests/qemu.sh can check the
 * ticks-to-instructions conversion on every board. */
#include "board.h"
#include "semihost.h"
#define CAL_LOOPS 1000000u /* two instructions each: subs, bne */

int main(void);
int main(void)
{
    counter_start();
    uint64_t t0 = counter_ticks();
    register uint32_t n __asm__("r0") = CAL_LOOPS;
    __asm__ volatile(".syntax unified\n1: subs %0, %0, #1\n\tbne 1b" : "+r"(n));
    uint64_t t = counter_ticks() - t0;
    semihost_puts("ticks=");
    semihost_put_u64(t);
    semihost_puts(" expected_instructions=2000000\n");
    return 0;
}
