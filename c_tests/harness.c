/* harness.c - see harness.h. */
#define _GNU_SOURCE
#include "harness.h"

#include <errno.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <sys/types.h>

/* Only this many failure messages are printed; the rest are just counted. */
#define H_MAX_PRINTED 40

static int h_nfail;
static const char *h_name;
static OSMesaContext h_ctx;
static unsigned char *h_buf;

static const char *test_name(void)
{
    if (h_name)
        return h_name;
#ifdef __GLIBC__
    return program_invocation_short_name;
#else
    return "test";
#endif
}

void h_set_name(const char *name) { h_name = name; }

static void record_failure(const char *fmt, va_list ap)
{
    h_nfail++;
    if (h_nfail <= H_MAX_PRINTED) {
        printf("  failure: ");
        vprintf(fmt, ap);
        printf("\n");
    } else if (h_nfail == H_MAX_PRINTED + 1) {
        printf("  (further failures not printed)\n");
    }
    fflush(stdout);
}

static void fail(const char *fmt, ...)
{
    va_list ap;
    va_start(ap, fmt);
    record_failure(fmt, ap);
    va_end(ap);
}

void h_expect(int cond, const char *fmt, ...)
{
    va_list ap;
    if (cond)
        return;
    va_start(ap, fmt);
    record_failure(fmt, ap);
    va_end(ap);
}

int h_failures(void) { return h_nfail; }

static void die(const char *msg)
{
    printf("FAIL %s (setup: %s)\n", test_name(), msg);
    fflush(stdout);
    exit(1);
}

void h_init(int w, int h)
{
    if (w <= 0 || h <= 0)
        die("h_init: bad size");
    h_buf = malloc((size_t)w * (size_t)h * 4);
    if (!h_buf)
        die("h_init: out of memory");
    memset(h_buf, 0, (size_t)w * (size_t)h * 4);
    h_ctx = OSMesaCreateContextExt(OSMESA_RGBA, 24, 8, 0, NULL);
    if (!h_ctx)
        die("OSMesaCreateContextExt(OSMESA_RGBA, 24, 8, 0, NULL) failed");
    if (!OSMesaMakeCurrent(h_ctx, h_buf, GL_UNSIGNED_BYTE, w, h))
        die("OSMesaMakeCurrent failed");
}

OSMesaContext h_context(void) { return h_ctx; }
unsigned char *h_buffer(void) { return h_buf; }

int h_width(void)
{
    GLint v = 0;
    OSMesaGetIntegerv(OSMESA_WIDTH, &v);
    return v;
}

int h_height(void)
{
    GLint v = 0;
    OSMesaGetIntegerv(OSMESA_HEIGHT, &v);
    return v;
}

void h_read(unsigned char *rgba)
{
    GLint align = 4;
    glGetIntegerv(GL_PACK_ALIGNMENT, &align); /* leave the test's state alone */
    glPixelStorei(GL_PACK_ALIGNMENT, 4);
    glReadPixels(0, 0, h_width(), h_height(), GL_RGBA, GL_UNSIGNED_BYTE, rgba);
    glPixelStorei(GL_PACK_ALIGNMENT, align);
}

void h_expect_pixel(int x, int y, int r, int g, int b, int a, int tol,
                    const char *what)
{
    unsigned char p[4] = {0, 0, 0, 0};
    const int want[4] = {r, g, b, a};
    int i, bad = 0;
    glReadPixels(x, y, 1, 1, GL_RGBA, GL_UNSIGNED_BYTE, p);
    for (i = 0; i < 4; i++)
        if (want[i] >= 0 && abs((int)p[i] - want[i]) > tol)
            bad = 1;
    if (bad)
        fail("%s: pixel (%d,%d) is %d,%d,%d,%d, expected %d,%d,%d,%d (tol %d, -1 = any)",
             what, x, y, p[0], p[1], p[2], p[3], r, g, b, a, tol);
}

static const char *err_name(GLenum e)
{
    switch (e) {
    case GL_NO_ERROR: return "GL_NO_ERROR";
    case GL_INVALID_ENUM: return "GL_INVALID_ENUM";
    case GL_INVALID_VALUE: return "GL_INVALID_VALUE";
    case GL_INVALID_OPERATION: return "GL_INVALID_OPERATION";
    case GL_STACK_OVERFLOW: return "GL_STACK_OVERFLOW";
    case GL_STACK_UNDERFLOW: return "GL_STACK_UNDERFLOW";
    case GL_OUT_OF_MEMORY: return "GL_OUT_OF_MEMORY";
    default: return "unknown error";
    }
}

void h_expect_no_error(const char *where)
{
    GLenum e = glGetError();
    if (e != GL_NO_ERROR)
        fail("%s: glGetError() = %s (0x%04x), expected GL_NO_ERROR", where,
             err_name(e), e);
}

void h_expect_error(GLenum want, const char *where)
{
    GLenum e = glGetError();
    if (e != want)
        fail("%s: glGetError() = %s (0x%04x), expected %s (0x%04x)", where,
             err_name(e), e, err_name(want), want);
}

static const char *out_dir(void)
{
    const char *d = getenv("SOFTGL_TEST_OUT");
    return (d && *d) ? d : "out/c_tests";
}

/* mkdir -p */
static void make_dirs(const char *path)
{
    char tmp[1024];
    size_t i, n = strlen(path);
    if (n >= sizeof tmp)
        return;
    memcpy(tmp, path, n + 1);
    for (i = 1; i <= n; i++) {
        if (tmp[i] == '/' || tmp[i] == '\0') {
            char c = tmp[i];
            tmp[i] = '\0';
            if (mkdir(tmp, 0777) != 0 && errno != EEXIST)
                return;
            tmp[i] = c;
        }
    }
}

static int pam_path(const char *name, char *buf, size_t n)
{
    return snprintf(buf, n, "%s/%s.pam", out_dir(), name) < (int)n;
}

void h_save(const char *name)
{
    char path[1024];
    int w = h_width(), h = h_height(), y;
    unsigned char *px;
    FILE *f;
    if (w <= 0 || h <= 0) {
        fail("h_save(%s): no current OSMesa buffer", name);
        return;
    }
    if (!pam_path(name, path, sizeof path)) {
        fail("h_save(%s): path too long", name);
        return;
    }
    make_dirs(out_dir());
    px = malloc((size_t)w * h * 4);
    if (!px) {
        fail("h_save(%s): out of memory", name);
        return;
    }
    h_read(px);
    f = fopen(path, "wb");
    if (!f) {
        fail("h_save(%s): cannot write %s: %s", name, path, strerror(errno));
        free(px);
        return;
    }
    fprintf(f, "P7\nWIDTH %d\nHEIGHT %d\nDEPTH 4\nMAXVAL 255\nTUPLTYPE RGB_ALPHA\nENDHDR\n", w, h);
    for (y = h - 1; y >= 0; y--) /* GL rows are bottom-up, PAM top-down */
        fwrite(px + (size_t)y * w * 4, 4, (size_t)w, f);
    if (fclose(f) != 0)
        fail("h_save(%s): error writing %s", name, path);
    free(px);
}

void h_check_golden(const char *name, int tol, int max_bad)
{
    char pam[1024], golden[1024], cmd[4096];
    const char *imgcmp = getenv("SOFTGL_IMGCMP");
    const char *bless = getenv("SOFTGL_BLESS");
    int rc;
    if (!imgcmp || !*imgcmp)
        imgcmp = "target/release/imgcmp";
    h_save(name);
    if (!pam_path(name, pam, sizeof pam))
        return;
    snprintf(golden, sizeof golden, "c_tests/golden/%s.png", name);
    if (bless && strcmp(bless, "1") == 0) {
        make_dirs("c_tests/golden");
        snprintf(cmd, sizeof cmd, "'%s' --to-png '%s' '%s'", imgcmp, pam, golden);
        rc = system(cmd);
        if (rc != 0)
            fail("blessing %s: `%s` failed (status %d)", golden, cmd, rc);
        else
            printf("  blessed %s (look at it before committing)\n", golden);
        return;
    }
    {
        FILE *g = fopen(golden, "rb");
        if (!g) {
            fail("golden %s does not exist: create it with SOFTGL_BLESS=1 c_tests/run.sh %s, "
                 "look at it, and commit it", golden, test_name());
            return;
        }
        fclose(g);
    }
    snprintf(cmd, sizeof cmd, "'%s' '%s' '%s' --tol %d --max-bad %d", imgcmp,
             pam, golden, tol, max_bad);
    fflush(stdout);
    rc = system(cmd);
    if (rc != 0)
        fail("golden %s: image differs from %s (`%s` exit status %d)", name,
             golden, cmd, rc);
}

void h_skip(const char *reason)
{
    printf("SKIP %s\n", reason);
    fflush(stdout);
    exit(H_SKIP_CODE);
}

int h_finish(void)
{
    if (h_nfail == 0)
        printf("PASS %s\n", test_name());
    else
        printf("FAIL %s (%d failure%s)\n", test_name(), h_nfail,
               h_nfail == 1 ? "" : "s");
    fflush(stdout);
    return h_nfail == 0 ? 0 : 1;
}
