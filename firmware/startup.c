/* startup: vector table, reset handler and fault handlers for the Cortex-M
 * boards. Written in C (libopencm3 / "zero to main" style): the linker
 * script provides the section symbols. */
#include <stdint.h>

#include "board.h"
#include "semihost.h"

extern uint32_t _sidata, _sdata, _edata, _sbss, _ebss, _sstack, _estack;
int main(void);

/* Paint value for stack-use measurement (board_stack_used). */
#define STACK_PAINT 0xC5C5C5C5u

static void fault_report(const char *what)
{
    semihost_puts("fxrt firmware: FAULT: ");
    semihost_puts(what);
    semihost_puts("\n");
    semihost_exit(3);
}

void Reset_Handler(void);
void Default_Handler(void);
void HardFault_Handler(void);
void MemManage_Handler(void);
void BusFault_Handler(void);
void UsageFault_Handler(void);
void SysTick_Handler(void);

void HardFault_Handler(void) { fault_report("HardFault"); }
void MemManage_Handler(void) { fault_report("MemManage"); }
void BusFault_Handler(void) { fault_report("BusFault"); }
void UsageFault_Handler(void) { fault_report("UsageFault"); }
void Default_Handler(void) { fault_report("unexpected interrupt"); }

void Reset_Handler(void)
{
    /* Paint the unused stack below our own frame so that the high-water
     * mark can be measured at the end. */
    uint32_t *sp;
    __asm__ volatile("mov %0, sp" : "=r"(sp));
    for (uint32_t *p = &_sstack; p < sp - 16; p++)
        *p = STACK_PAINT;
    for (uint32_t *src = &_sidata, *dst = &_sdata; dst < &_edata;)
        *dst++ = *src++;
    for (uint32_t *dst = &_sbss; dst < &_ebss;)
        *dst++ = 0;
#if defined(__ARM_FP)
    /* CPACR: full access to CP10 and CP11 (the FPU) before any float
     * instruction. */
    *(volatile uint32_t *)0xE000ED88u |= 0xFu << 20;
    __asm__ volatile("dsb\n\tisb" ::: "memory");
#endif
    semihost_exit(main());
}

uint32_t board_stack_used(void)
{
    const uint32_t *p = &_sstack;
    while (p < &_estack && *p == STACK_PAINT)
        p++;
    return (uint32_t)((uintptr_t)&_estack - (uintptr_t)p);
}

uint32_t board_stack_size(void)
{
    return (uint32_t)((uintptr_t)&_estack - (uintptr_t)&_sstack);
}

uint32_t board_ram_static(void)
{
    return (uint32_t)((uintptr_t)&_ebss - (uintptr_t)&_sdata);
}

typedef void (*vector_t)(void);

/* Cortex-M core vectors; the boards' peripheral interrupts are unused. */
__attribute__((section(".vectors"), used)) static const vector_t vectors[16] = {
    (vector_t)(uintptr_t)&_estack, /* initial stack pointer */
    Reset_Handler,
    Default_Handler,   /* NMI */
    HardFault_Handler,
    MemManage_Handler, /* reserved on M0 */
    BusFault_Handler,  /* reserved on M0 */
    UsageFault_Handler, /* reserved on M0 */
    0, 0, 0, 0,
    Default_Handler, /* SVCall */
    Default_Handler, /* DebugMon */
    0,
    Default_Handler, /* PendSV */
    SysTick_Handler,
};
