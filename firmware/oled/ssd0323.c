/* ssd0323: the OLED controller over SSI0 (see ssd0323.h). */
#include "ssd0323.h"

#include "lm3s6965.h"

/* Command bytes (SSD0323 command table; each is followed by the number of
 * parameter bytes QEMU's model reads for it). */
enum {
    CMD_SET_COLUMN = 0x15,  /* start, end (byte columns) */
    CMD_SET_ROW = 0x75,     /* start, end */
    CMD_REMAP = 0xA0,       /* 1 */
    CMD_START_LINE = 0xA1,  /* 1 */
    CMD_OFFSET = 0xA2,      /* 1 */
    CMD_MODE_NORMAL = 0xA4, /* 0 */
    CMD_MULTIPLEX = 0xA8,   /* 1: rows shown - 1 */
    CMD_DISPLAY_OFF = 0xAE, /* 0 */
    CMD_DISPLAY_ON = 0xAF,  /* 0 */
};

/* Which way the data/command line is set now (it starts low, commands). */
static bool data_mode;

static void set_mode(bool data)
{
    if (data == data_mode)
        return;
    /* The controller samples the line with each byte: the bytes already
     * queued must be out before it changes. */
    lm3s6965_ssi0_flush();
    lm3s6965_oled_dc(data);
    data_mode = data;
}

static void commands(const uint8_t *cmd, size_t n)
{
    set_mode(false);
    lm3s6965_ssi0_send(cmd, n);
}

void ssd0323_window(uint8_t col0, uint8_t col1, uint8_t row0, uint8_t row1)
{
    const uint8_t cmd[6] = {CMD_SET_COLUMN, col0, col1, CMD_SET_ROW, row0, row1};
    commands(cmd, sizeof cmd);
}

void ssd0323_data(const uint8_t *buf, size_t n)
{
    set_mode(true);
    lm3s6965_ssi0_send(buf, n);
}

void ssd0323_init(void)
{
    lm3s6965_ssi0_init(SSD0323_SSI_SCR);
    lm3s6965_oled_dc(false);
    data_mode = false;
    static const uint8_t setup[] = {
        CMD_DISPLAY_OFF,
        CMD_REMAP, SSD0323_REMAP,
        CMD_START_LINE, 0,
        CMD_OFFSET, 0,
        CMD_MULTIPLEX, SSD0323_HEIGHT - 1,
        CMD_MODE_NORMAL,
    };
    commands(setup, sizeof setup);
    /* Clear the shown rows (the RAM powers up undefined), then light the
     * panel: no stale picture shows while the first frame renders. */
    static const uint8_t zeros[SSD0323_ROW_BYTES];
    ssd0323_window(0, SSD0323_ROW_BYTES - 1, 0, SSD0323_HEIGHT - 1);
    for (int32_t row = 0; row < SSD0323_HEIGHT; row++)
        ssd0323_data(zeros, sizeof zeros);
    static const uint8_t on[] = {CMD_DISPLAY_ON};
    commands(on, sizeof on);
    /* Back to the whole display, the next byte at its top left. */
    ssd0323_window(0, SSD0323_ROW_BYTES - 1, 0, SSD0323_HEIGHT - 1);
    set_mode(true);
}
