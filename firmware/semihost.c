/* semihost: ARM semihosting calls (operation numbers from the ARM
 * semihosting specification). */
#include "semihost.h"

enum {
    SYS_OPEN = 0x01,
    SYS_CLOSE = 0x02,
    SYS_WRITE0 = 0x04,
    SYS_WRITE = 0x05,
    SYS_EXIT = 0x18,
    SYS_EXIT_EXTENDED = 0x20,
};
#define ADP_STOPPED_APPLICATION_EXIT 0x20026u
#define OPEN_MODE_WB 5u /* fopen mode index of "wb" */

static int32_t semihost_call(uint32_t op, const void *arg)
{
    register uint32_t r0 __asm__("r0") = op;
    register const void *r1 __asm__("r1") = arg;
    __asm__ volatile("bkpt 0xab" : "+r"(r0) : "r"(r1) : "memory");
    return (int32_t)r0;
}

static size_t semihost_strlen(const char *s)
{
    size_t n = 0;
    while (s[n])
        n++;
    return n;
}

int32_t semihost_open_write(const char *path)
{
    uint32_t args[3] = {(uint32_t)(uintptr_t)path, OPEN_MODE_WB, (uint32_t)semihost_strlen(path)};
    return semihost_call(SYS_OPEN, args);
}

int32_t semihost_write(int32_t handle, const void *buf, size_t len)
{
    uint32_t args[3] = {(uint32_t)handle, (uint32_t)(uintptr_t)buf, (uint32_t)len};
    return semihost_call(SYS_WRITE, args);
}

int32_t semihost_close(int32_t handle)
{
    uint32_t args[1] = {(uint32_t)handle};
    return semihost_call(SYS_CLOSE, args);
}

void semihost_puts(const char *s)
{
    semihost_call(SYS_WRITE0, s);
}

void semihost_exit(int32_t status)
{
    uint32_t args[2] = {ADP_STOPPED_APPLICATION_EXIT, (uint32_t)status};
    semihost_call(SYS_EXIT_EXTENDED, args);
    /* Hosts without the extended call: plain exit (status 0 or 1 only). */
    semihost_call(SYS_EXIT, (const void *)(uintptr_t)(status ? 0x20024u : ADP_STOPPED_APPLICATION_EXIT));
    for (;;)
        ;
}

void semihost_put_u64(uint64_t v)
{
    char buf[24];
    int i = (int)sizeof buf - 1;
    buf[i] = 0;
    do {
        buf[--i] = (char)('0' + (int)(v % 10));
        v /= 10;
    } while (v);
    semihost_puts(&buf[i]);
}

void semihost_put_hex(uint32_t v)
{
    char buf[11] = "0x";
    for (int i = 0; i < 8; i++)
        buf[2 + i] = "0123456789abcdef"[(v >> (28 - 4 * i)) & 15u];
    buf[10] = 0;
    semihost_puts(buf);
}
