/* io_board: the examples' frames streamed to the host over semihosting,
 * one file per frame (NAME-NN.ppm.part in QEMU's working directory;
 * tests/examples.sh renames them after a clean exit), and the instructions
 * each frame takes: camera set-up, render set-up and every row, counted
 * with the SysTick counter (firmware/counter.c) between opening and
 * closing the frame's file. The console gets one line per frame and a
 * last line with the totals, RAM and stack (firmware/qemu-run.sh reads
 * its ticks=). */
#include "board.h"
#include "example_io.h"
#include "semihost.h"

static int32_t fd = -1;
static uint64_t t0, total;

void example_fail(const char *what, const char *msg)
{
    semihost_puts(example_name);
    semihost_puts(": ");
    semihost_puts(what);
    semihost_puts(": ");
    semihost_puts(msg);
    semihost_puts("\n");
    semihost_exit(2);
}

/* Decimal digits of v into s (no printf on the board). */
static char *put_dec(char *s, uint32_t v, int min_digits)
{
    char d[10];
    int n = 0;
    do {
        d[n++] = (char)('0' + v % 10);
        v /= 10;
    } while (v || n < min_digits);
    while (n)
        *s++ = d[--n];
    return s;
}

static void send(const void *buf, size_t len)
{
    if (semihost_write(fd, buf, len) != 0)
        example_fail("semihosting", "write failed");
}

void example_frame_begin(int32_t n, int32_t width, int32_t height)
{
    char name[48], *p = name;
    for (const char *q = example_name; *q && p < name + 24; q++)
        *p++ = *q;
    *p++ = '-';
    p = put_dec(p, (uint32_t)n, 2);
    const char *ext = ".ppm.part";
    while (*ext)
        *p++ = *ext++;
    *p = 0;
    fd = semihost_open_write(name);
    if (fd < 0)
        example_fail(name, "cannot open on the host");
    char hdr[32] = "P6\n";
    p = put_dec(hdr + 3, (uint32_t)width, 1);
    *p++ = ' ';
    p = put_dec(p, (uint32_t)height, 1);
    const char *tail = "\n255\n";
    while (*tail)
        *p++ = *tail++;
    send(hdr, (size_t)(p - hdr));
    t0 = counter_ticks();
}

void example_row(const uint8_t *row, size_t len)
{
    send(row, len);
}

void example_frame_end(int32_t n)
{
    uint64_t t = counter_ticks() - t0;
    total += t;
    if (semihost_close(fd) != 0)
        example_fail("semihosting", "close failed");
    fd = -1;
    /* Not "ticks=": qemu-run.sh takes the last ticks= as the run's total. */
    semihost_puts("frame=");
    semihost_put_u64((uint64_t)n);
    semihost_puts(" frame_tick_count=");
    semihost_put_u64(t);
    semihost_puts("\n");
}

int main(void)
{
    counter_start();
    int rc = example_main();
    semihost_puts("ticks=");
    semihost_put_u64(total);
    semihost_puts(" ram_static=");
    semihost_put_u64(board_ram_static());
    semihost_puts(" stack_used=");
    semihost_put_u64(board_stack_used());
    semihost_puts(" stack_size=");
    semihost_put_u64(board_stack_size());
    semihost_puts("\n");
    return rc;
}
