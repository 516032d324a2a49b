/* engine_select: choose a number build at run time. */
#include <string.h>

#include "engine.h"

int engine_number_parse(const char *s, engine_number_t *out)
{
    static const char *const names[] = {"q16", "float", "double"};
    for (int i = 0; i < 3; i++) {
        if (strcmp(s, names[i]) == 0) {
            *out = (engine_number_t)i;
            return 0;
        }
    }
    return -1;
}

int engine_renderer_parse(const char *s, engine_renderer_t *out)
{
    static const char *const names[] = {"fast", "reference", "raycast"};
    for (int i = 0; i < 3; i++) {
        if (strcmp(s, names[i]) == 0) {
            *out = (engine_renderer_t)i;
            return 0;
        }
    }
    return -1;
}

const char *engine_number_name(engine_number_t n)
{
    return n == ENGINE_Q16 ? "q16" : n == ENGINE_FLOAT ? "float" : "double";
}

int engine_render(engine_number_t n, const char *path, const scene_t *sc, int width, int height, engine_renderer_t renderer,
                  uint8_t *rgb, uint32_t *keys, char *err, size_t errlen)
{
    switch (n) {
    case ENGINE_Q16: return engine_render_q16(path, sc, width, height, renderer, rgb, keys, err, errlen);
    case ENGINE_FLOAT: return engine_render_float(path, sc, width, height, renderer, rgb, keys, err, errlen);
    case ENGINE_DOUBLE: return engine_render_double(path, sc, width, height, renderer, rgb, keys, err, errlen);
    }
    return -1;
}
