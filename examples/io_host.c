/* io_host: the examples' frames as binary PPM files on the host:
 *   build/examples/host/NAME OUTDIR  ->  OUTDIR/NAME-00.ppm, NAME-01.ppm ...
 * Each file is written under a temporary name and renamed when complete. */
#include <stdio.h>
#include <stdlib.h>

#include "example_io.h"

static const char *outdir = ".";
static FILE *frame;
static char path[1024], tmp[1100];

void example_fail(const char *what, const char *msg)
{
    fprintf(stderr, "%s: %s: %s\n", example_name, what, msg);
    if (frame) {
        fclose(frame);
        remove(tmp);
    }
    exit(2);
}

void example_frame_begin(int32_t n, int32_t width, int32_t height)
{
    snprintf(path, sizeof path, "%s/%s-%02d.ppm", outdir, example_name, (int)n);
    snprintf(tmp, sizeof tmp, "%s.part", path);
    frame = fopen(tmp, "wb");
    if (!frame)
        example_fail(tmp, "cannot write");
    fprintf(frame, "P6\n%d %d\n255\n", (int)width, (int)height);
}

void example_row(const uint8_t *row, size_t len)
{
    if (fwrite(row, 1, len, frame) != len)
        example_fail(tmp, "write failed");
}

void example_frame_end(int32_t n)
{
    (void)n;
    FILE *f = frame;
    frame = NULL;
    if (fclose(f) != 0 || rename(tmp, path) != 0) {
        remove(tmp);
        example_fail(path, "cannot write");
    }
}

int main(int argc, char **argv)
{
    if (argc != 2) {
        fprintf(stderr, "usage: %s OUTDIR\n", argv[0]);
        return 2;
    }
    outdir = argv[1];
    return example_main();
}
