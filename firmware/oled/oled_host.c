/* oled_host: oled_show on the host, each frame's RGB rows into a PPM file,
 * OUTDIR/frame-FF.ppm (FF: two digits): the reference the board's frames
 * are compared with after the same dithering (tests/oled.sh).
 *   oled-show-host OUTDIR */
#include <stdio.h>
#include <stdlib.h>

#include "oled_show.h"

static const char *outdir;
static FILE *out;
static char path[4096];
static int32_t row_bytes;

void oled_sink_fail(const char *what, const char *msg)
{
    fprintf(stderr, "oled-show-host: %s: %s\n", what, msg);
    exit(2);
}

void oled_sink_begin(int32_t frame, int32_t width, int32_t height)
{
    snprintf(path, sizeof path, "%s/frame-%02d.ppm", outdir, (int)frame);
    out = fopen(path, "wb");
    if (!out)
        oled_sink_fail(path, "cannot open for writing");
    fprintf(out, "P6\n%d %d\n255\n", (int)width, (int)height);
    row_bytes = 3 * width;
}

void oled_sink_row(int32_t row, const uint8_t *rgb)
{
    (void)row;
    if (fwrite(rgb, 1, (size_t)row_bytes, out) != (size_t)row_bytes)
        oled_sink_fail(path, "write failed");
}

void oled_sink_end(int32_t frame)
{
    if (fclose(out) != 0)
        oled_sink_fail(path, "write failed");
    out = NULL;
    printf("frame=%d method=%s %s\n", (int)frame, oled_dither_name(oled_frame_method(frame)), path);
}

int main(int argc, char **argv)
{
    if (argc != 2) {
        fprintf(stderr, "usage: oled-show-host OUTDIR\n");
        return 2;
    }
    outdir = argv[1];
    return oled_show();
}
