/* lm3s6965: the few LM3S6965 (Stellaris, Cortex-M3) peripherals the OLED
 * firmware uses: the system controller's clock, GPIO ports A, C and D, and
 * the SSI0 serial port (an ARM PL022), at the addresses and with the bits
 * of the LM3S6965 data sheet, which QEMU's lm3s6965evb machine models
 * (hw/arm/stellaris.c, hw/gpio/pl061.c, hw/ssi/pl022.c).
 *
 * The board's OLED (an SSD0323 controller, 128x64 pixels, 16 grey levels)
 * hangs off SSI0: SSI0Clk on PA2, SSI0Fss (the OLED's chip select) on PA3,
 * SSI0Tx on PA5, data/command select on PC7 (high = data), and the SD
 * card's chip select on PD0. QEMU wires it differently in one respect: it
 * takes PD0 as the OLED's chip select, active high (and the SD card's,
 * active low), and raises it at reset; firmware that drives PD0 high
 * selects the OLED in QEMU and leaves the SD card deselected on the real
 * board. */
#ifndef FXRT_LM3S6965_H
#define FXRT_LM3S6965_H

#include <stdbool.h>
#include <stddef.h>
#include <stdint.h>

#define LM3S_REG(addr) (*(volatile uint32_t *)(uintptr_t)(addr))

/* System control (0x400FE000). */
#define SYSCTL_RIS LM3S_REG(0x400FE050u)
#define SYSCTL_MISC LM3S_REG(0x400FE058u) /* write 1 to clear a RIS bit */
#define SYSCTL_RCC LM3S_REG(0x400FE060u)
#define SYSCTL_RCGC1 LM3S_REG(0x400FE104u)
#define SYSCTL_RCGC2 LM3S_REG(0x400FE108u)
#define SYSCTL_RIS_PLLLRIS (1u << 6)  /* the PLL has locked */
#define SYSCTL_RCC_SYSDIV_SHIFT 23u  /* 4 bits: the PLL's 200 MHz (or the source) / (SYSDIV + 1) */
#define SYSCTL_RCC_SYSDIV_MASK (0xFu << SYSCTL_RCC_SYSDIV_SHIFT)
#define SYSCTL_RCC_USESYSDIV (1u << 22)
#define SYSCTL_RCC_PWRDN (1u << 13)   /* PLL powered down */
#define SYSCTL_RCC_BYPASS (1u << 11)  /* system clock from the source, not the PLL */
#define SYSCTL_RCC_XTAL_SHIFT 6u      /* 4 bits: crystal frequency code */
#define SYSCTL_RCC_XTAL_MASK (0xFu << SYSCTL_RCC_XTAL_SHIFT)
#define SYSCTL_RCC_XTAL_8MHZ (0xEu << SYSCTL_RCC_XTAL_SHIFT) /* the evaluation board's crystal */
#define SYSCTL_RCC_OSCSRC_MASK (3u << 4) /* 0: main oscillator */
#define SYSCTL_RCC_MOSCDIS (1u << 0)      /* main oscillator disabled */
#define SYSCTL_RCGC1_SSI0 (1u << 4)
#define SYSCTL_RCGC2_GPIOA (1u << 0)
#define SYSCTL_RCGC2_GPIOC (1u << 2)
#define SYSCTL_RCGC2_GPIOD (1u << 3)

/* GPIO ports: the data register is addressed through a mask, bits 9..2 of
 * the address select the pins a read or write touches. */
#define GPIOA_BASE 0x40004000u
#define GPIOC_BASE 0x40006000u
#define GPIOD_BASE 0x40007000u
#define GPIO_DATA(base, pins) LM3S_REG((base) + ((uint32_t)(pins) << 2))
#define GPIO_DIR(base) LM3S_REG((base) + 0x400u)   /* 1 = output */
#define GPIO_AFSEL(base) LM3S_REG((base) + 0x420u) /* 1 = the pin's peripheral function */
#define GPIO_DEN(base) LM3S_REG((base) + 0x51Cu)   /* 1 = digital pin enabled */
#define PIN(n) (1u << (n))

/* SSI0, a PL022 (0x40008000). Bit rate = system clock / (CPSDVSR * (1 + SCR)). */
#define SSI0_CR0 LM3S_REG(0x40008000u)
#define SSI0_CR1 LM3S_REG(0x40008004u)
#define SSI0_DR LM3S_REG(0x40008008u)
#define SSI0_SR LM3S_REG(0x4000800Cu)
#define SSI0_CPSR LM3S_REG(0x40008010u)
#define SSI_CR0_DSS_8 7u           /* 8-bit frames */
#define SSI_CR0_SCR_SHIFT 8u       /* serial clock rate */
#define SSI_CR1_SSE (1u << 1)      /* port enabled */
#define SSI_SR_TFE (1u << 0)       /* transmit FIFO empty */
#define SSI_SR_TNF (1u << 1)       /* transmit FIFO not full */
#define SSI_SR_RNE (1u << 2)       /* receive FIFO not empty */
#define SSI_SR_BSY (1u << 4)       /* a frame is being sent or the FIFO holds one */

/* The system clock the firmware sets (lm3s6965_clock_50mhz), in Hz and as
 * the SysTick period in ns the host needs to turn ticks into instructions
 * (firmware/counter.c): 50 MHz, 20 ns. */
#define LM3S_SYSCLK_HZ 50000000u
#define LM3S_SYSCLK_NS 20u

/* 50 MHz from the PLL (200 MHz / 4) and the 8 MHz crystal, in the order
 * the data sheet gives (bypass the PLL, configure, wait for lock, switch
 * over). QEMU takes the period from SYSDIV alone: 5 ns * (SYSDIV + 1), so
 * 20 ns, and sets the lock flag when PWRDN goes from 1 to 0. */
void lm3s6965_clock_50mhz(void);

/* SSI0 as SPI master, 8-bit frames, mode 0 (SPO = SPH = 0, clock idle low,
 * data taken on the rising edge, as the SSD0323 reads it), bit rate
 * LM3S_SYSCLK_HZ / (2 * (1 + scr)); its pins PA2, PA3, PA5 handed to it,
 * PC7 (data/command) and PD0 (driven high) made outputs. QEMU does not
 * model the bit rate (a byte goes out as soon as it is written). */
void lm3s6965_ssi0_init(uint32_t scr);

/* Send n bytes on SSI0, emptying the receive FIFO as it goes (the OLED
 * sends nothing back, but the PL022 receives a byte for every byte sent,
 * and QEMU's model stops sending while its receive FIFO is full). */
void lm3s6965_ssi0_send(const uint8_t *buf, size_t n);

/* Wait until every byte written has left the port: before changing the
 * data/command line, which the controller samples with each byte. */
void lm3s6965_ssi0_flush(void);

/* The data/command line (PC7): true = display data, false = commands. */
void lm3s6965_oled_dc(bool data);

#endif
