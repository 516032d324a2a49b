/* ssd0323: the Solomon SSD0323 OLED controller of the LM3S6965 evaluation
 * board (128x64 pixels, 16 grey levels) on SSI0, with its data/command
 * line on PC7 (lm3s6965.h).
 *
 * Display RAM: 64 bytes per row, two pixels per byte, the left pixel in
 * the high nibble, a nibble being a grey level 0 (off) .. 15 (brightest).
 * A column address counts bytes (0..63), a row address rows (0..79; rows
 * 0..63 are shown). Data bytes fill the window set by ssd0323_window left
 * to right, then row after row (horizontal address increment), wrapping
 * to the window's start; so a frame streams in as 64 rows of 64 bytes
 * after one window command, and the driver needs no frame buffer.
 *
 * Only commands that QEMU's model (hw/display/ssd0323.c) knows are sent:
 * it stops at an unknown one with an error message and would take that
 * command's parameters for commands. QEMU ignores the panel's analogue
 * settings (contrast, current, clocks, grey-scale table) and draws level n
 * as grey n * 17 / 255; the driver leaves those settings at the
 * controller's reset values, which a real panel may need tuned. */
#ifndef FXRT_SSD0323_H
#define FXRT_SSD0323_H

#include <stddef.h>
#include <stdint.h>

#define SSD0323_WIDTH 128    /* pixels */
#define SSD0323_HEIGHT 64    /* rows shown */
#define SSD0323_ROW_BYTES 64 /* two 4-bit pixels a byte */

/* Re-map and address-increment byte (command 0xA0). Bit 2 chooses the
 * address increment (0: horizontal, which the row streaming needs; QEMU
 * models only this bit). Bits 0, 1, 4, 6 mirror columns, swap nibbles,
 * mirror and split the COM lines: panel wiring, left 0 here, as QEMU
 * draws the RAM unmirrored; a real panel may need others. */
#ifndef SSD0323_REMAP
#define SSD0323_REMAP 0x00
#endif
#if (SSD0323_REMAP) & 0x04
#error "SSD0323_REMAP: bit 2 (vertical address increment) breaks the row streaming"
#endif

/* SSI0 bit rate: 50 MHz / (2 * (1 + SSD0323_SSI_SCR)), 3.57 MHz for 6.
 * A bound on the wire time of a frame: 4,096 bytes * 8 bits / 3.57 MHz =
 * 9.2 ms (QEMU does not model it; docs/OLED.md). */
#ifndef SSD0323_SSI_SCR
#define SSD0323_SSI_SCR 6
#endif

/* Bring SSI0 and the pins up (lm3s6965_ssi0_init), send the controller's
 * set-up and clear the shown rows; leaves the controller in data mode with
 * the window at the whole display. */
void ssd0323_init(void);

/* The window that data fills: byte columns col0..col1 (0..63), rows
 * row0..row1 (0..79); the next data byte goes to (col0, row0). */
void ssd0323_window(uint8_t col0, uint8_t col1, uint8_t row0, uint8_t row1);

/* n bytes of display data into the window. */
void ssd0323_data(const uint8_t *buf, size_t n);

#endif
