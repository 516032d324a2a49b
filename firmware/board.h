/* board: what the firmware main needs from startup and the counter. */
#ifndef FXRT_BOARD_H
#define FXRT_BOARD_H

#include <stdint.h>

/* Bytes of stack ever used (from the painted stack), the stack's size,
 * and the RAM taken by .data + .bss. */
uint32_t board_stack_used(void);
uint32_t board_stack_size(void);
uint32_t board_ram_static(void);

/* SysTick-based instruction counter (see counter.c for the method). */
void counter_start(void);
uint64_t counter_ticks(void);

/* xorshift32 (Marsaglia 2003): the fixed-seed pseudo-random inputs of the
 * on-board checks and benchmarks (tests/onboard_main.c, benchfx.c). */
static inline uint32_t board_xorshift32(uint32_t *state)
{
    uint32_t x = *state;
    x ^= x << 13;
    x ^= x >> 17;
    x ^= x << 5;
    return *state = x;
}

#endif
