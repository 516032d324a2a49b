/* libFuzzer harness for the intersection kernels and the camera: each
 * input becomes one case inside the documented domain, run through the
 * Q16.16 and double builds (tests/diffk.c), and checked against exactly
 * the bounds of tests/test_diff.c (included below); a violation prints the
 * case (replayable %a values) and aborts.
 *
 * Input: byte 0 picks the kind (plane, sphere, triangle, box, camera, and
 * the lighting kinds normal, shade, pow, spot, shadow: geom_*_surface,
 * shade_point, numw_pow_int, the spot cone, world_occluded; their checks
 * include the invariants unit-length normal and colour in range);
 * byte 1 bit 0 picks the decoding:
 *   0: the test_diff generators, drawing their random numbers from the
 *      remaining bytes (then from a counter), so mutations move through
 *      the generators' modes, log scales and offsets;
 *   1: raw Q16.16 bit patterns for every value (coordinates folded into
 *      +-8192, sizes into (0, 4096]), the ray either given directly or
 *      aimed at the object's reference point plus a raw offset, so the
 *      fuzzer reaches exact ties and single-LSB geometry.
 *
 * Build and run: make fuzz-kernels (tests/diff.mk). */
#define DIFF_NO_MAIN
#include "test_diff.c"

typedef struct {
    const uint8_t *p;
    size_t n;
} fz_src_t;

static uint32_t fz_u32(fz_src_t *s)
{
    uint32_t v = 0;
    for (int i = 0; i < 4; i++) {
        v <<= 8;
        if (s->n) {
            v |= *s->p++;
            s->n--;
        }
    }
    return v;
}

/* A Q16.16 value in [-limit, limit] (limit in LSB) from raw bits. */
static double fz_signed(fz_src_t *s, int64_t limit)
{
    int64_t v = (int32_t)fz_u32(s);
    v %= limit + 1;
    return (double)v / 65536.0;
}

static double fz_coord(fz_src_t *s)
{
    return fz_signed(s, (int64_t)8192 << 16);
}

static void fz_point(fz_src_t *s, double p[3])
{
    for (int i = 0; i < 3; i++)
        p[i] = fz_coord(s);
}

/* (0, limit] in LSB. */
static double fz_positive(fz_src_t *s, int64_t limit)
{
    return (double)(1 + (int64_t)(fz_u32(s) % (uint64_t)limit)) / 65536.0;
}

/* A unit direction from three raw values (rounded like the renderer's). */
static void fz_dir(fz_src_t *s, double d[3])
{
    for (int i = 0; i < 3; i++)
        d[i] = (double)(int32_t)fz_u32(s);
    if (!normalize3(d))
        set3(d, 0, 0, -1);
    ray_dir_round(d);
}

/* The ray: origin raw; direction raw, or towards ref + a small raw offset
 * (+-2^-8 .. +-8 scene units, chosen by one byte). */
static void fz_ray(fz_src_t *s, const double ref[3], diffk_ray_t *ray)
{
    fz_point(s, ray->o);
    uint32_t how = fz_u32(s);
    if (how & 1) {
        fz_dir(s, ray->d);
        return;
    }
    int64_t lim = (int64_t)1 << (8 + (how >> 1) % 12);
    double t[3];
    for (int i = 0; i < 3; i++)
        t[i] = ref[i] + fz_signed(s, lim);
    sub3(t, ray->o, ray->d);
    if (!normalize3(ray->d))
        set3(ray->d, 0, 0, -1);
    ray_dir_round(ray->d);
}

static void fz_raw(int kind, fz_src_t *s, dcase_t *c)
{
    memset(c, 0, sizeof *c);
    c->kind = kind;
    c->mode = -1;
    switch (kind) {
    case K_PLANE:
        fz_point(s, c->p[0]);
        fz_point(s, c->p[1]);
        if (c->p[1][0] == 0 && c->p[1][1] == 0 && c->p[1][2] == 0)
            c->p[1][2] = 1;
        fz_ray(s, c->p[0], &c->ray);
        break;
    case K_SPHERE:
        fz_point(s, c->p[0]);
        c->radius = fz_positive(s, (int64_t)4096 << 16);
        fz_ray(s, c->p[0], &c->ray);
        break;
    case K_TRIANGLE: {
        double ctr[3];
        for (int k = 0; k < 3; k++)
            fz_point(s, c->p[k]);
        for (int i = 0; i < 3; i++)
            ctr[i] = (c->p[0][i] + c->p[1][i] + c->p[2][i]) / 3;
        fz_ray(s, ctr, &c->ray);
        break;
    }
    case K_BOX: {
        double ctr[3];
        fz_point(s, c->p[0]);
        fz_point(s, c->p[1]);
        for (int i = 0; i < 3; i++) {
            double lo = fmin(c->p[0][i], c->p[1][i]), hi = fmax(c->p[0][i], c->p[1][i]);
            c->p[0][i] = lo;
            c->p[1][i] = hi;
            ctr[i] = (lo + hi) / 2;
        }
        fz_ray(s, ctr, &c->ray);
        break;
    }
    default: {
        diffk_cam_t *m = &c->cam;
        uint32_t v = fz_u32(s);
        m->kind = (v & 1) ? DIFFK_ORTHOGRAPHIC : DIFFK_PERSPECTIVE;
        m->width = 1 + (int)((v >> 1) % 4096);
        m->height = 1 + (int)((v >> 13) % 4096);
        fz_point(s, m->eye);
        fz_point(s, m->gaze);
        fz_point(s, m->up);
        m->fov_deg = fz_positive(s, (int64_t)180 * 65536 - 1);
        m->scale = fz_positive(s, (int64_t)4096 << 16);
        for (int i = 0; i < CAM_PIXELS; i++) {
            uint32_t p = fz_u32(s);
            c->px[i] = (int)((p & 0xffff) % (uint32_t)m->width);
            c->py[i] = (int)((p >> 16) % (uint32_t)m->height);
        }
        break;
    }
    }
}

/* A fraction 0..1 (Q16.16) from raw bits. */
static double fz_frac(fz_src_t *s)
{
    return (double)(fz_u32(s) % 65537u) / 65536.0;
}

/* The lighting kinds from raw bits: objects as fz_raw makes them; shading
 * inputs with every value raw (a light may sit exactly on p, a spot's
 * half-angle is any Q16.16 value in (0, 90], colours any fraction). */
static void fz_raw_light(int kind, fz_src_t *s, dcase_t *c)
{
    dcase_t tmp;
    memset(c, 0, sizeof *c);
    c->kind = kind;
    c->mode = -1;
    switch (kind) {
    case K_NORMAL:
        c->sub = (int)(fz_u32(s) % 4);
        fz_raw(c->sub, s, &tmp);
        memcpy(c->p, tmp.p, sizeof c->p);
        c->radius = tmp.radius;
        c->ray = tmp.ray;
        break;
    case K_SHADOW:
        c->sub = 1 + (int)(fz_u32(s) % SHADOW_OBJS);
        for (int j = 0; j < c->sub; j++) {
            fz_raw((int)(fz_u32(s) % 4), s, &tmp);
            obj_from_case(&tmp, &c->obj[j]);
            if (j == 0)
                c->ray = tmp.ray;
        }
        c->tmax = (fz_u32(s) & 1) ? -1.0 : fz_positive(s, 0x7fffffff);
        break;
    case K_POW:
        c->xq = (long long)((uint64_t)fz_u32(s) << 32 | fz_u32(s));
        c->k = 1 + fz_u32(s) % 1024;
        break;
    default: { /* shade, spot */
        diffk_shade_t *sh = &c->sh;
        uint32_t v = fz_u32(s);
        sh->material = (v & 1) ? DIFFK_PHONG : DIFFK_LAMBERT;
        sh->exponent = 1 + (int)((v >> 1) % 1024);
        sh->n_lights = kind == K_SPOT ? 1 : 1 + (int)((v >> 11) % DIFFK_MAX_LIGHTS);
        for (int i = 0; i < 3; i++) {
            sh->color[i] = fz_frac(s) * 255.0;
            sh->color[i] = rq(sh->color[i]);
            sh->specular[i] = fz_frac(s);
            sh->ambient[i] = fz_frac(s);
        }
        fz_point(s, c->sp);
        fz_dir(s, c->sn);
        fz_dir(s, c->sdir);
        for (int j = 0; j < sh->n_lights; j++) {
            diffk_light_t *L = &sh->lights[j];
            uint32_t w = fz_u32(s);
            L->kind = kind == K_SPOT ? DIFFK_LIGHT_SPOT : (int)(w % 3);
            /* the position raw, or p plus a raw offset of +-2^-16 .. +-2^-4 */
            if (w & 4) {
                fz_point(s, L->pos);
            } else {
                for (int i = 0; i < 3; i++)
                    L->pos[i] = clampd(c->sp[i] + fz_signed(s, (int64_t)1 << (w >> 3) % 13), -COORD, COORD);
            }
            do
                fz_point(s, L->dir);
            while (L->dir[0] == 0 && L->dir[1] == 0 && L->dir[2] == 0 && s->n > 0);
            if (L->dir[0] == 0 && L->dir[1] == 0 && L->dir[2] == 0)
                L->dir[2] = 1;
            L->angle = fz_positive(s, (int64_t)90 << 16);
            for (int i = 0; i < 3; i++)
                L->color[i] = fz_frac(s);
        }
        break;
    }
    }
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    if (size < 2)
        return 0;
    int kind = data[0] % K_COUNT;
    dcase_t c;
    if (data[1] & 1) {
        fz_src_t s = {data + 2, size - 2};
        if (kind >= K_NORMAL)
            fz_raw_light(kind, &s, &c);
        else
            fz_raw(kind, &s, &c);
    } else {
        rng_t r = {0x5EED0F0F1u, data + 2, size - 2};
        gen_case_rng(kind, &r, &c);
    }
    dres_t res;
    diff_eval(&c, &res);
    if (res.fail) {
        fprintf(stderr, "fuzz_kernels: %s: %s\n", kind_name[kind], res.fail);
        case_print(stderr, &c, "  ");
        fflush(stderr);
        diff_verbose = true; /* the evaluators' details, on stdout */
        diff_eval(&c, &res);
        fflush(stdout);
        result_print(stderr, &c, &res);
        fflush(stderr);
        abort();
    }
    return 0;
}
