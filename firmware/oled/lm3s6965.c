/* lm3s6965: clock, pins and SSI0 for the OLED (see lm3s6965.h). */
#include "lm3s6965.h"

/* Polls of the PLL lock flag before giving up: the PLL locks within 0.5 ms
 * (25,000 cycles at 50 MHz; a poll takes several). QEMU sets the flag at
 * once, but only when PWRDN goes from 1 to 0, which a warm restart (PWRDN
 * already clear) would not do: the bound keeps that from hanging. */
#define PLL_LOCK_POLLS 100000u

void lm3s6965_clock_50mhz(void)
{
    uint32_t rcc = SYSCTL_RCC;
    /* 1. Run from the oscillator directly while the PLL is configured. */
    rcc = (rcc | SYSCTL_RCC_BYPASS) & ~SYSCTL_RCC_USESYSDIV;
    SYSCTL_RCC = rcc;
    /* 2. The 8 MHz crystal on the main oscillator, PLL powered up (its
     *    lock flag cleared first, so the wait below sees this lock). */
    SYSCTL_MISC = SYSCTL_RIS_PLLLRIS;
    rcc &= ~(SYSCTL_RCC_XTAL_MASK | SYSCTL_RCC_OSCSRC_MASK | SYSCTL_RCC_MOSCDIS | SYSCTL_RCC_PWRDN);
    rcc |= SYSCTL_RCC_XTAL_8MHZ;
    SYSCTL_RCC = rcc;
    /* 3. 200 MHz / 4 = 50 MHz. */
    rcc = (rcc & ~SYSCTL_RCC_SYSDIV_MASK) | (3u << SYSCTL_RCC_SYSDIV_SHIFT) | SYSCTL_RCC_USESYSDIV;
    SYSCTL_RCC = rcc;
    /* 4. Wait for the lock, 5. then switch to the PLL. */
    for (uint32_t i = 0; i < PLL_LOCK_POLLS && !(SYSCTL_RIS & SYSCTL_RIS_PLLLRIS); i++)
        ;
    SYSCTL_RCC = rcc & ~SYSCTL_RCC_BYPASS;
}

void lm3s6965_ssi0_init(uint32_t scr)
{
    SYSCTL_RCGC1 |= SYSCTL_RCGC1_SSI0;
    SYSCTL_RCGC2 |= SYSCTL_RCGC2_GPIOA | SYSCTL_RCGC2_GPIOC | SYSCTL_RCGC2_GPIOD;
    /* A peripheral may be touched 3 cycles after its clock is enabled: the
     * read back takes that long. */
    (void)SYSCTL_RCGC2;

    /* PA2 SSI0Clk, PA3 SSI0Fss (the OLED's chip select), PA5 SSI0Tx. */
    GPIO_AFSEL(GPIOA_BASE) |= PIN(2) | PIN(3) | PIN(5);
    GPIO_DEN(GPIOA_BASE) |= PIN(2) | PIN(3) | PIN(5);
    /* PC7 data/command, low (commands) to start. */
    GPIO_DIR(GPIOC_BASE) |= PIN(7);
    GPIO_DEN(GPIOC_BASE) |= PIN(7);
    GPIO_DATA(GPIOC_BASE, PIN(7)) = 0;
    /* PD0 high: the SD card deselected (and, in QEMU, the OLED selected). */
    GPIO_DIR(GPIOD_BASE) |= PIN(0);
    GPIO_DEN(GPIOD_BASE) |= PIN(0);
    GPIO_DATA(GPIOD_BASE, PIN(0)) = PIN(0);

    SSI0_CR1 = 0; /* disabled, master */
    SSI0_CPSR = 2; /* the smallest prescaler: the bit rate is set by SCR */
    SSI0_CR0 = (scr << SSI_CR0_SCR_SHIFT) | SSI_CR0_DSS_8;
    SSI0_CR1 = SSI_CR1_SSE;
}

static inline void drain_rx(void)
{
    while (SSI0_SR & SSI_SR_RNE)
        (void)SSI0_DR;
}

void lm3s6965_ssi0_send(const uint8_t *buf, size_t n)
{
    for (size_t i = 0; i < n; i++) {
        drain_rx();
        while (!(SSI0_SR & SSI_SR_TNF))
            drain_rx();
        SSI0_DR = buf[i];
    }
}

void lm3s6965_ssi0_flush(void)
{
    while (SSI0_SR & SSI_SR_BSY)
        drain_rx();
    drain_rx();
}

void lm3s6965_oled_dc(bool data)
{
    GPIO_DATA(GPIOC_BASE, PIN(7)) = data ? PIN(7) : 0;
}
