/* Colour sweep: every colour 0.0000 .. 1.0000 in steps of 0.0001 gives the
 * same 8-bit value in all three builds, through the real path: scene text
 * -> scene_parse -> each build's world (engine_render) -> rendered pixels,
 * for object colours and the background, with the fast renderer and the
 * per-pixel ray caster.
 *
 * The expected value is computed from the decimal digits alone, in
 * integers: floor(255 d / 10000 + 1/2) = (510 d + 10000) div 20000 for
 * the written value d / 10000 (docs/ACCURACY.md, "Colour": round half up).
 *
 * Each scene is 2 x 1 pixels: an orthographic camera sees a box in the
 * left pixel and the background in the right one. Six channel slots
 * (object r g b, background r g b) take six permutations of the 10001
 * values, so every value passes through every slot; the values are written
 * with exactly four decimals in some slots and with trailing zeros
 * dropped in the others ("0.7000", "0.7", "1"). */
#include <stdio.h>
#include <string.h>

#include "check.h"
#include "engine.h"
#include "scene.h"

#define STEPS 10000 /* values d / STEPS, d = 0..STEPS */

/* The six slots' permutations of 0..STEPS (10001 = 73 * 137; the
 * multipliers are coprime to it). */
static int slot_value(int slot, int i)
{
    static const int mul[6] = {1, 10000, 6007, 3001, 1, 9973};
    static const int add[6] = {0, 0, 0, 17, 5000, 123};
    return (int)(((long)mul[slot] * i + add[slot]) % (STEPS + 1));
}

/* d / 10000 as text: "%d.%04d", trimmed of trailing zeros when trim. */
static void write_value(char *out, size_t n, int d, int trim)
{
    snprintf(out, n, "%d.%04d", d / STEPS, d % STEPS);
    if (trim) {
        size_t len = strlen(out);
        while (out[len - 1] == '0')
            out[--len] = '\0';
        if (out[len - 1] == '.')
            out[--len] = '\0';
    }
}

static int expected8(int d)
{
    return (510 * d + 10000) / 20000;
}

int main(void)
{
    static scene_t sc;
    static const engine_number_t nums[3] = {ENGINE_Q16, ENGINE_FLOAT, ENGINE_DOUBLE};
    static const engine_renderer_t rends[2] = {ENGINE_FAST, ENGINE_RAYCAST};
    long mismatches[3] = {0, 0, 0}, checked[3] = {0, 0, 0}, failed_scenes = 0;
    for (int i = 0; i <= STEPS; i++) {
        int d[6];
        char v[6][16], text[512], err[256];
        for (int k = 0; k < 6; k++) {
            d[k] = slot_value(k, i);
            write_value(v[k], sizeof v[k], d[k], (i + k) & 1);
        }
        snprintf(text, sizeof text,
                 "image 2 1\n"
                 "background %s %s %s\n"
                 "camera orthographic eye 0 0 0 gaze 0 0 -1 up 0 1 0 scale 2\n"
                 "box min -10 -10 -10 max 0 10 -1 color %s %s %s\n",
                 v[3], v[4], v[5], v[0], v[1], v[2]);
        if (scene_parse("sweep", text, strlen(text), &sc, err, sizeof err) != 0) {
            CHECK_SWEEP(0, "value %d: %s", i, err);
            failed_scenes++;
            continue;
        }
        for (int n = 0; n < 3; n++) {
            for (int r = 0; r < 2; r++) {
                uint8_t rgb[6];
                if (engine_render(nums[n], "sweep", &sc, 2, 1, rends[r], rgb, NULL, err, sizeof err) != 0) {
                    CHECK_SWEEP(0, "value %d, %s: %s", i, engine_number_name(nums[n]), err);
                    failed_scenes++;
                    continue;
                }
                for (int k = 0; k < 6; k++) {
                    int want = expected8(d[k]);
                    checked[n]++;
                    if (rgb[k] != want) {
                        mismatches[n]++;
                        CHECK_SWEEP(rgb[k] == want, "%s %s: %s channel %c written %s gives %d, want %d",
                                    engine_number_name(nums[n]), r ? "raycast" : "fast",
                                    k < 3 ? "object" : "background", "rgb"[k % 3], v[k], rgb[k], want);
                    }
                }
            }
        }
    }
    printf("colour sweep: %d values (0.0000..1.0000 step 0.0001) x 6 channel slots x 2 renderers; "
           "mismatches q16=%ld float=%ld double=%ld (of %ld each)\n",
           STEPS + 1, mismatches[0], mismatches[1], mismatches[2], checked[0]);
    for (int n = 0; n < 3; n++)
        CHECK_MSG(mismatches[n] == 0 && checked[n] == (long)(STEPS + 1) * 12, "%s: %ld mismatches in %ld",
                  engine_number_name(nums[n]), mismatches[n], checked[n]);
    CHECK_MSG(failed_scenes == 0, "%ld scenes failed", failed_scenes);

    /* The example and the tie rule, spelled out. */
    {
        const char *t = "image 1 1\nbackground 0.7 0.9 0.3\ncamera perspective eye 0 0 0 gaze 0 0 -1 up 0 1 0 fov 45\n";
        char err[256];
        CHECK(scene_parse("example", t, strlen(t), &sc, err, sizeof err) == 0);
        for (int n = 0; n < 3; n++) {
            uint8_t rgb[3] = {0, 0, 0};
            CHECK(engine_render(nums[n], "example", &sc, 1, 1, ENGINE_FAST, rgb, NULL, err, sizeof err) == 0);
            CHECK_MSG(rgb[0] == 179 && rgb[1] == 230 && rgb[2] == 77, "%s: 0.7 0.9 0.3 -> %d %d %d, want 179 230 77",
                      engine_number_name(nums[n]), rgb[0], rgb[1], rgb[2]);
        }
    }
    return check_report("test_color");
}
