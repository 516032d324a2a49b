/* oled_board: the LM3S6965 evaluation board's OLED as oled_show's sink, and
 * the firmware's main. Each row is dithered (dither.c) into 64 bytes and
 * streamed into the SSD0323's RAM as soon as it is rendered: besides the
 * program's one RGB row, RAM holds one packed row and the Floyd-Steinberg
 * error row, no frame buffer.
 *
 * After each frame the console gets (semihosting)
 *   oled: frame=F method=NAME frame_tick_count=T display_tick_count=D
 * T: the frame's SysTick ticks (camera and render set-up, every row, the
 * dithering and the SSI writes), D: the part spent dithering and sending.
 * At 50 MHz (LM3S_SYSCLK_NS = 20 ns a tick) under -icount shift=5 a tick
 * is 20/32 of an instruction (firmware/counter.c). Then, with
 * OLED_HANDSHAKE, the firmware waits until the host has created
 * oled-ack-FF (FF: two digits) in QEMU's working directory, so a host
 * script can screendump the display while it holds frame F
 * (firmware/oled/oled-run.sh). The run ends with ticks= (all frames) and
 * the RAM and stack figures, like firmware/main.c. */
#include "board.h"
#include "fxrt.h"
#include "lm3s6965.h"
#include "oled_show.h"
#include "semihost.h"
#include "ssd0323.h"

#if SCENE_WIDTH != SSD0323_WIDTH || SCENE_HEIGHT != SSD0323_HEIGHT
#error "the OLED shows 128x64 frames: compile the scene at that size (fxrt-scenec --size 128x64)"
#endif

/* 1: after each frame, wait for the host's oled-ack-FF (see above); 0: run
 * straight through (instruction counts only). */
#ifndef OLED_HANDSHAKE
#define OLED_HANDSHAKE 1
#endif

/* Spin-loop turns (a few instructions each) between two looks for the
 * host's file: a look is a host call, cheap for the guest, but the host
 * needs milliseconds for a screendump, so there is no point in many. */
#define ACK_POLL_SPIN 20000

#if FXRT_STACK_EXTRA > 0
/* The bounce loop's stack (core/fxrt_config.h), reserved as in
 * firmware/main.c: linker/sections.ld puts it below STACK_SIZE. */
static uint8_t stack_extra[FXRT_STACK_EXTRA] __attribute__((section(".stack_extra"), used, aligned(8)));
#endif

static oled_dither_t dither;
static int32_t fs_err[SSD0323_WIDTH];       /* Floyd-Steinberg: the next row's error, luma units */
static uint8_t packed[SSD0323_ROW_BYTES];   /* one dithered row, as the controller takes it */
static uint64_t frame_t0, display_ticks, total_ticks;

void oled_sink_fail(const char *what, const char *msg)
{
    semihost_puts("oled: ");
    semihost_puts(what);
    semihost_puts(": ");
    semihost_puts(msg);
    semihost_puts("\n");
    semihost_exit(2);
}

void oled_sink_begin(int32_t frame, int32_t width, int32_t height)
{
    (void)width; /* checked at compile time above */
    (void)height;
    frame_t0 = counter_ticks();
    ssd0323_window(0, SSD0323_ROW_BYTES - 1, 0, SSD0323_HEIGHT - 1);
    if (!oled_dither_begin(&dither, oled_frame_method(frame), SSD0323_WIDTH, fs_err))
        oled_sink_fail("dither", "bad method");
    display_ticks = counter_ticks() - frame_t0;
}

void oled_sink_row(int32_t row, const uint8_t *rgb)
{
    uint64_t t = counter_ticks();
    oled_dither_row(&dither, row, rgb, packed);
    ssd0323_data(packed, sizeof packed);
    display_ticks += counter_ticks() - t;
}

/* Semihosting SYS_OPEN in mode "rb" and SYS_CLOSE: does the host file
 * exist? (firmware/semihost.c opens for writing only.) */
static bool host_file_exists(const char *path)
{
    uint32_t n = 0;
    while (path[n])
        n++;
    uint32_t args[3] = {(uint32_t)(uintptr_t)path, 1u /* "rb" */, n};
    register uint32_t r0 __asm__("r0") = 0x01u; /* SYS_OPEN */
    register const void *r1 __asm__("r1") = args;
    __asm__ volatile("bkpt 0xab" : "+r"(r0) : "r"(r1) : "memory");
    if ((int32_t)r0 < 0)
        return false;
    semihost_close((int32_t)r0);
    return true;
}

static void wait_for_host(int32_t frame)
{
    char name[] = "oled-ack-00";
    name[9] = (char)('0' + frame / 10 % 10);
    name[10] = (char)('0' + frame % 10);
    while (!host_file_exists(name))
        for (volatile int32_t spin = 0; spin < ACK_POLL_SPIN; spin++)
            ;
}

void oled_sink_end(int32_t frame)
{
    uint64_t t = counter_ticks();
    lm3s6965_ssi0_flush(); /* the frame's last byte is in the display */
    uint64_t t1 = counter_ticks();
    display_ticks += t1 - t;
    uint64_t ticks = t1 - frame_t0;
    total_ticks += ticks;
    semihost_puts("oled: frame=");
    semihost_put_u64((uint64_t)frame);
    semihost_puts(" method=");
    semihost_puts(oled_dither_name(oled_frame_method(frame)));
    semihost_puts(" frame_tick_count=");
    semihost_put_u64(ticks);
    semihost_puts(" display_tick_count=");
    semihost_put_u64(display_ticks);
    semihost_puts("\n");
    if (OLED_HANDSHAKE)
        wait_for_host(frame);
}

static void report(const char *key, uint64_t v)
{
    semihost_puts(key);
    semihost_put_u64(v);
    semihost_puts(" ");
}

int main(void)
{
    lm3s6965_clock_50mhz();
    counter_start();
    /* The counter at the new clock: a loop of exactly 2 * 10^6
     * instructions (as firmware/calibrate.c), which the host checks
     * against cal_tick_count * LM3S_SYSCLK_NS / 32. */
    uint64_t c0 = counter_ticks();
    register uint32_t n __asm__("r0") = 1000000u;
    __asm__ volatile(".syntax unified\n1: subs %0, %0, #1\n\tbne 1b" : "+r"(n));
    uint64_t cal = counter_ticks() - c0;
    uint64_t i0 = counter_ticks();
    ssd0323_init();
    uint64_t init_ticks = counter_ticks() - i0;
    report("oled: cal_tick_count=", cal);
    report("tick_ns=", LM3S_SYSCLK_NS);
    report("init_tick_count=", init_ticks);
    semihost_puts("\n");
    int rc = oled_show();
    report("ticks=", total_ticks);
    report("frames=", OLED_FRAMES);
    report("ram_static=", board_ram_static());
    report("stack_used=", board_stack_used());
    report("stack_size=", board_stack_size());
    semihost_puts("\n");
    if (board_stack_used() + FXRT_STACK_MARGIN > board_stack_size())
        oled_sink_fail("stack", "the run left less than FXRT_STACK_MARGIN bytes of the reserved stack unused");
    return rc;
}
