/* semihost: the minimal ARM semihosting layer (one `bkpt 0xab`), enough to
 * write files and the console on the host and to exit with a status. It
 * allocates nothing, unlike newlib's rdimon. */
#ifndef FXRT_SEMIHOST_H
#define FXRT_SEMIHOST_H

#include <stddef.h>
#include <stdint.h>

/* Open a host file for binary writing ("wb"); returns a handle >= 0 or -1. */
int32_t semihost_open_write(const char *path);
/* Write len bytes; returns 0 on success, else the number NOT written. */
int32_t semihost_write(int32_t handle, const void *buf, size_t len);
int32_t semihost_close(int32_t handle);
/* Write a NUL-terminated string to the host console (QEMU's stdout). */
void semihost_puts(const char *s);
/* End the program; QEMU exits with this status. */
void semihost_exit(int32_t status) __attribute__((noreturn));

/* Console helpers for reports: decimal and hex numbers, no printf. */
void semihost_put_u64(uint64_t v);
void semihost_put_hex(uint32_t v);

#endif
