/* t_osmesa_formats: the OSMesa buffer contract (Mesa's osmesa.h).
 *
 * - OSMesaMakeCurrent(ctx, buf, type, w, h) renders into the caller's buffer
 *   (visible after glFinish) with the pixel layout of the context format:
 *   OSMESA_RGBA r,g,b,a; OSMESA_BGRA b,g,r,a; OSMESA_ARGB a,r,g,b;
 *   OSMESA_RGB r,g,b; OSMESA_RGB_565 one native-endian 16-bit word
 *   r<<11 | g<<5 | b (type GL_UNSIGNED_SHORT_5_6_5; Mesa rejects RGB_565
 *   with GL_UNSIGNED_BYTE, and so does this test, to match Mesa).
 * - Rows are bottom-up by default (OSMESA_Y_UP = 1: buffer row 0 is GL row
 *   0); after OSMesaPixelStore(OSMESA_Y_UP, 0), newly rendered images have
 *   buffer row 0 = the top row.  glReadPixels keeps GL coordinates.
 * - OSMesaPixelStore(OSMESA_ROW_LENGTH, n): rows are n pixels apart; the
 *   padding after each row is not written.
 * - OSMesaGetIntegerv(OSMESA_WIDTH/HEIGHT/FORMAT/TYPE/Y_UP/ROW_LENGTH),
 *   OSMesaGetColorBuffer, OSMesaGetDepthBuffer (Mesa reports
 *   bytesPerValue 4 for a 24-bit depth buffer, 2 for 16-bit),
 *   OSMesaGetCurrentContext, OSMesaGetProcAddress("glClear"),
 *   OSMesaMakeCurrent(NULL, NULL, 0, 0, 0) releasing the context.
 * - Re-binding a context to a bigger buffer: GL initialises the viewport to
 *   the window size only the first time a context is made current, so the
 *   viewport keeps its old size (Mesa agrees); glClear fills the whole new
 *   buffer.
 *
 * Mesa deviation: Mesa 22.3's llvmpipe renders wrong pixels into
 * OSMESA_RGB (24-bit) buffers (a scissored clear or a quad over a cleared
 * buffer leaves garbled bytes; the same program is right with
 * GALLIUM_DRIVER=softpipe).  When GL_RENDERER contains "llvmpipe", the
 * OSMESA_RGB pixel checks are reported as notes and not counted; they stay
 * strict for every other renderer.
 *
 * The pattern: clear to A, scissored clear of the bottom-left [0,5)x[0,3) to
 * B, and a flat quad C over the top-right [7,10)x[4,6), in a 10x6 buffer.
 */
#include "harness.h"
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define W 10
#define H 6
#define PAD_ROW 16 /* OSMESA_ROW_LENGTH used in the row-length check */
#define SENTINEL 0xEE

static const unsigned char A[4] = {51, 102, 153, 204};
static const unsigned char B[4] = {255, 0, 128, 255};
static const unsigned char C[4] = {0, 255, 64, 255};

struct fmt {
    GLenum format, type;
    const char *name;
    int bpp;
};

static const struct fmt FMTS[] = {
    {OSMESA_RGBA, GL_UNSIGNED_BYTE, "OSMESA_RGBA", 4},
    {OSMESA_BGRA, GL_UNSIGNED_BYTE, "OSMESA_BGRA", 4},
    {OSMESA_ARGB, GL_UNSIGNED_BYTE, "OSMESA_ARGB", 4},
    {OSMESA_RGB, GL_UNSIGNED_BYTE, "OSMESA_RGB", 3},
    {OSMESA_RGB_565, GL_UNSIGNED_SHORT_5_6_5, "OSMESA_RGB_565", 2},
};

/* Colour expected at GL pixel (x, y) of the pattern. */
static const unsigned char *expected(int x, int y)
{
    if (x < 5 && y < 3)
        return B;
    if (x >= 7 && y >= 4)
        return C;
    return A;
}

static void draw_pattern(int w, int h)
{
    glViewport(0, 0, w, h);
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    glOrtho(0, w, 0, h, -1, 1);
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
    glDisable(GL_SCISSOR_TEST);
    glClearColor(A[0] / 255.0f, A[1] / 255.0f, A[2] / 255.0f, A[3] / 255.0f);
    glClear(GL_COLOR_BUFFER_BIT);
    glEnable(GL_SCISSOR_TEST);
    glScissor(0, 0, 5, 3);
    glClearColor(B[0] / 255.0f, B[1] / 255.0f, B[2] / 255.0f, B[3] / 255.0f);
    glClear(GL_COLOR_BUFFER_BIT);
    glDisable(GL_SCISSOR_TEST);
    glColor4ub(C[0], C[1], C[2], C[3]);
    glBegin(GL_QUADS);
    glVertex2i(7, 4);
    glVertex2i(10, 4);
    glVertex2i(10, 6);
    glVertex2i(7, 6);
    glEnd();
    glFinish();
}

/* Does the pixel at p hold colour c in format f? */
static int pixel_ok(const struct fmt *f, const unsigned char *p, const unsigned char *c, char *got, size_t n)
{
    switch (f->format) {
    case OSMESA_RGBA:
        snprintf(got, n, "bytes %d,%d,%d,%d", p[0], p[1], p[2], p[3]);
        return p[0] == c[0] && p[1] == c[1] && p[2] == c[2] && p[3] == c[3];
    case OSMESA_BGRA:
        snprintf(got, n, "bytes %d,%d,%d,%d", p[0], p[1], p[2], p[3]);
        return p[0] == c[2] && p[1] == c[1] && p[2] == c[0] && p[3] == c[3];
    case OSMESA_ARGB:
        snprintf(got, n, "bytes %d,%d,%d,%d", p[0], p[1], p[2], p[3]);
        return p[0] == c[3] && p[1] == c[0] && p[2] == c[1] && p[3] == c[2];
    case OSMESA_RGB:
        snprintf(got, n, "bytes %d,%d,%d", p[0], p[1], p[2]);
        return p[0] == c[0] && p[1] == c[1] && p[2] == c[2];
    case OSMESA_RGB_565: {
        uint16_t v;
        int r, g, b, er = (c[0] * 31 + 127) / 255, eg = (c[1] * 63 + 127) / 255,
                     eb = (c[2] * 31 + 127) / 255;
        memcpy(&v, p, 2);
        r = v >> 11;
        g = (v >> 5) & 63;
        b = v & 31;
        snprintf(got, n, "word 0x%04x (r5 %d g6 %d b5 %d; expected about %d %d %d)", v, r, g, b, er, eg, eb);
        return abs(r - er) <= 1 && abs(g - eg) <= 1 && abs(b - eb) <= 1;
    }
    }
    return 0;
}

/* Set for OSMESA_RGB on Mesa's llvmpipe (see the comment at the top). */
static int lenient;

/* Check the caller's buffer: rows row_len pixels apart, y_up orientation. */
static void check_buffer(const struct fmt *f, const unsigned char *buf, int row_len, int y_up,
                         const char *what)
{
    int row, x, bad = 0, pad_bad = 0;
    size_t stride = (size_t)row_len * f->bpp, i;
    for (row = 0; row < H; row++) {
        int gl_y = y_up ? row : H - 1 - row;
        for (x = 0; x < W; x++) {
            char got[128];
            const unsigned char *c = expected(x, gl_y);
            if (!pixel_ok(f, buf + row * stride + (size_t)x * f->bpp, c, got, sizeof got)) {
                if (bad++ < 3 && !lenient)
                    h_expect(0, "%s %s: buffer row %d pixel %d (GL pixel %d,%d): %s, expected colour %d,%d,%d,%d",
                             f->name, what, row, x, x, gl_y, got, c[0], c[1], c[2], c[3]);
            }
        }
        for (i = (size_t)W * f->bpp; i < stride; i++)
            if (buf[row * stride + i] != SENTINEL)
                pad_bad++;
    }
    if (lenient && bad) {
        printf("  note: %s %s: %d wrong pixels; known Mesa llvmpipe bug with 24-bit RGB, not counted\n",
               f->name, what, bad);
        bad = 0;
    }
    h_expect(bad == 0, "%s %s: %d wrong pixels", f->name, what, bad);
    h_expect(pad_bad == 0, "%s %s: %d padding bytes beyond the row width were written", f->name, what, pad_bad);
}

static GLint get_int(GLint pname)
{
    GLint v = -12345;
    OSMesaGetIntegerv(pname, &v);
    return v;
}

static void test_format(const struct fmt *f)
{
    size_t size = (size_t)W * H * f->bpp, psize = (size_t)PAD_ROW * H * f->bpp;
    unsigned char *buf = malloc(size), *pbuf = malloc(psize);
    OSMesaContext ctx;
    GLint w, h, v, bpv;
    void *p;

    memset(buf, SENTINEL, size);
    memset(pbuf, SENTINEL, psize);
    ctx = OSMesaCreateContextExt(f->format, 24, 8, 0, NULL);
    h_expect(ctx != NULL, "%s: OSMesaCreateContextExt failed", f->name);
    if (!ctx)
        return;
    if (!OSMesaMakeCurrent(ctx, buf, f->type, W, H)) {
        h_expect(0, "%s: OSMesaMakeCurrent failed", f->name);
        OSMesaDestroyContext(ctx);
        return;
    }
    h_expect(OSMesaGetCurrentContext() == ctx, "%s: OSMesaGetCurrentContext is not the context", f->name);
    h_expect(get_int(OSMESA_WIDTH) == W, "%s: OSMESA_WIDTH = %d", f->name, get_int(OSMESA_WIDTH));
    h_expect(get_int(OSMESA_HEIGHT) == H, "%s: OSMESA_HEIGHT = %d", f->name, get_int(OSMESA_HEIGHT));
    h_expect(get_int(OSMESA_FORMAT) == (GLint)f->format, "%s: OSMESA_FORMAT = 0x%x", f->name, get_int(OSMESA_FORMAT));
    h_expect(get_int(OSMESA_TYPE) == (GLint)f->type, "%s: OSMESA_TYPE = 0x%x", f->name, get_int(OSMESA_TYPE));
    h_expect(get_int(OSMESA_Y_UP) == 1, "%s: initial OSMESA_Y_UP = %d, expected 1", f->name, get_int(OSMESA_Y_UP));
    v = get_int(OSMESA_ROW_LENGTH);
    /* Mesa reports 0 ("same as the width"); the width itself would do too. */
    h_expect(v == 0 || v == W, "%s: initial OSMESA_ROW_LENGTH = %d, expected 0 or %d", f->name, v, W);

    h_expect(OSMesaGetColorBuffer(ctx, &w, &h, &v, &p) == GL_TRUE, "%s: OSMesaGetColorBuffer failed", f->name);
    h_expect(w == W && h == H && v == (GLint)f->format && p == buf,
             "%s: OSMesaGetColorBuffer gave %dx%d format 0x%x buffer %p, expected %dx%d 0x%x %p", f->name,
             w, h, v, p, W, H, f->format, (void *)buf);
    p = NULL;
    h_expect(OSMesaGetDepthBuffer(ctx, &w, &h, &bpv, &p) == GL_TRUE, "%s: OSMesaGetDepthBuffer failed", f->name);
    h_expect(w == W && h == H && p != NULL && (bpv == 2 || bpv == 4),
             "%s: OSMesaGetDepthBuffer gave %dx%d, %d bytes per value, buffer %p", f->name, w, h, bpv, p);
    {
        const char *r = (const char *)glGetString(GL_RENDERER);
        lenient = f->format == OSMESA_RGB && r && strstr(r, "llvmpipe");
    }
    if (f->format == OSMESA_RGBA)
        printf("  OSMesaGetDepthBuffer (24-bit depth, 8-bit stencil): %d bytes per value\n", bpv);

    /* Default orientation: row 0 is the bottom. */
    draw_pattern(W, H);
    h_expect_no_error(f->name);
    check_buffer(f, buf, W, 1, "Y_UP=1");
    if (!lenient) {
        /* 5/6-bit channels read back as the nearest representable value */
        int tol = f->format == OSMESA_RGB_565 ? 8 : 1;
        h_expect_pixel(0, 0, B[0], B[1], B[2], -1, tol, "glReadPixels(0,0) (bottom-left)");
        h_expect_pixel(9, 5, C[0], C[1], C[2], -1, tol, "glReadPixels(9,5) (top-right)");
    }

    /* Y_UP = 0: newly rendered images have row 0 at the top. */
    OSMesaPixelStore(OSMESA_Y_UP, 0);
    h_expect(get_int(OSMESA_Y_UP) == 0, "%s: OSMESA_Y_UP after setting 0 = %d", f->name, get_int(OSMESA_Y_UP));
    memset(buf, SENTINEL, size);
    draw_pattern(W, H);
    check_buffer(f, buf, W, 0, "Y_UP=0");
    if (!lenient)
        h_expect_pixel(0, 0, B[0], B[1], B[2], -1, f->format == OSMESA_RGB_565 ? 8 : 1,
                       "glReadPixels(0,0) with Y_UP=0 is still bottom-left");

    /* Row length larger than the width, both orientations. */
    if (!OSMesaMakeCurrent(ctx, pbuf, f->type, W, H)) {
        h_expect(0, "%s: OSMesaMakeCurrent (row length buffer) failed", f->name);
    } else {
        OSMesaPixelStore(OSMESA_ROW_LENGTH, PAD_ROW);
        h_expect(get_int(OSMESA_ROW_LENGTH) == PAD_ROW, "%s: OSMESA_ROW_LENGTH = %d, expected %d", f->name,
                 get_int(OSMESA_ROW_LENGTH), PAD_ROW);
        OSMesaPixelStore(OSMESA_Y_UP, 1);
        draw_pattern(W, H);
        check_buffer(f, pbuf, PAD_ROW, 1, "ROW_LENGTH=16, Y_UP=1");
        OSMesaPixelStore(OSMESA_Y_UP, 0);
        memset(pbuf, SENTINEL, psize);
        draw_pattern(W, H);
        check_buffer(f, pbuf, PAD_ROW, 0, "ROW_LENGTH=16, Y_UP=0");
    }
    h_expect_no_error(f->name);

    OSMesaMakeCurrent(NULL, NULL, 0, 0, 0);
    OSMesaDestroyContext(ctx);
    free(buf);
    free(pbuf);
}

typedef void (*clear_fn)(GLbitfield);

int main(void)
{
    unsigned i;

    for (i = 0; i < sizeof FMTS / sizeof FMTS[0]; i++)
        test_format(&FMTS[i]);

    /* RGB_565 with GL_UNSIGNED_BYTE: Mesa refuses the combination. */
    {
        static unsigned char buf[W * H * 4];
        OSMesaContext ctx = OSMesaCreateContextExt(OSMESA_RGB_565, 0, 0, 0, NULL);
        h_expect(ctx != NULL, "OSMESA_RGB_565 context");
        if (ctx) {
            h_expect(OSMesaMakeCurrent(ctx, buf, GL_UNSIGNED_BYTE, W, H) == GL_FALSE,
                     "OSMesaMakeCurrent(OSMESA_RGB_565 context, GL_UNSIGNED_BYTE) should fail as in Mesa");
            OSMesaMakeCurrent(NULL, NULL, 0, 0, 0);
            OSMesaDestroyContext(ctx);
        }
    }

    /* Current context, proc address, release, re-bind with a bigger buffer. */
    {
        static unsigned char small[W * H * 4], big[2 * W * 2 * H * 4];
        OSMesaContext ctx = OSMesaCreateContextExt(OSMESA_RGBA, 24, 8, 0, NULL);
        OSMESAproc proc;
        GLint vp[4];
        int x, y, bad;

        if (!ctx || !OSMesaMakeCurrent(ctx, small, GL_UNSIGNED_BYTE, W, H)) {
            h_expect(0, "RGBA context for the remaining checks");
            return h_finish();
        }
        h_expect(OSMesaGetCurrentContext() == ctx, "OSMesaGetCurrentContext after make-current");

        proc = OSMesaGetProcAddress("glClear");
        h_expect(proc != NULL, "OSMesaGetProcAddress(\"glClear\") is NULL");
        if (proc) {
            glClearColor(0, 0, 1, 1);
            ((clear_fn)proc)(GL_COLOR_BUFFER_BIT);
            glFinish();
            h_expect(small[0] == 0 && small[1] == 0 && small[2] == 255 && small[3] == 255,
                     "glClear through OSMesaGetProcAddress: first pixel %d,%d,%d,%d, expected 0,0,255,255",
                     small[0], small[1], small[2], small[3]);
        }

        glGetIntegerv(GL_VIEWPORT, vp);
        h_expect(vp[2] == W && vp[3] == H, "viewport after first make-current %dx%d, expected %dx%d", vp[2], vp[3], W, H);

        /* Bigger buffer: the viewport must NOT follow (set on first make-current only). */
        h_expect(OSMesaMakeCurrent(ctx, big, GL_UNSIGNED_BYTE, 2 * W, 2 * H) == GL_TRUE, "re-bind to %dx%d", 2 * W, 2 * H);
        h_expect(get_int(OSMESA_WIDTH) == 2 * W && get_int(OSMESA_HEIGHT) == 2 * H,
                 "OSMESA_WIDTH/HEIGHT after re-bind: %dx%d", get_int(OSMESA_WIDTH), get_int(OSMESA_HEIGHT));
        glGetIntegerv(GL_VIEWPORT, vp);
        h_expect(vp[0] == 0 && vp[1] == 0 && vp[2] == W && vp[3] == H,
                 "viewport after re-binding to a bigger buffer is %d,%d,%d,%d, expected unchanged 0,0,%d,%d",
                 vp[0], vp[1], vp[2], vp[3], W, H);
        glMatrixMode(GL_PROJECTION);
        glLoadIdentity();
        glMatrixMode(GL_MODELVIEW);
        glLoadIdentity();
        glClearColor(1, 0, 0, 1);
        glClear(GL_COLOR_BUFFER_BIT); /* whole new buffer */
        glColor3ub(0, 255, 0);
        glRecti(-1, -1, 1, 1);        /* fills the (old-size) viewport */
        glFinish();
        bad = 0;
        for (y = 0; y < 2 * H; y++)
            for (x = 0; x < 2 * W; x++) {
                const unsigned char *p = &big[(y * 2 * W + x) * 4];
                int in_vp = x < W && y < H;
                if (p[0] != (in_vp ? 0 : 255) || p[1] != (in_vp ? 255 : 0) || p[2] != 0 || p[3] != 255)
                    bad++;
            }
        h_expect(bad == 0, "bigger buffer: %d pixels wrong (expected red clear everywhere, green quad only in the %dx%d viewport)",
                 bad, W, H);
        glViewport(0, 0, 2 * W, 2 * H);
        glRecti(-1, -1, 1, 1);
        glFinish();
        h_expect(big[(2 * H * 2 * W - 1) * 4 + 1] == 255, "after glViewport(0,0,%d,%d) the quad reaches the top-right corner", 2 * W, 2 * H);

        /* Release. */
        h_expect(OSMesaMakeCurrent(NULL, NULL, 0, 0, 0) == GL_TRUE, "OSMesaMakeCurrent(NULL, NULL, 0, 0, 0) returns GL_TRUE");
        h_expect(OSMesaGetCurrentContext() == NULL, "OSMesaGetCurrentContext() after release is not NULL");
        h_expect(OSMesaMakeCurrent(ctx, small, GL_UNSIGNED_BYTE, W, H) == GL_TRUE, "make-current again after release");
        h_expect(OSMesaGetCurrentContext() == ctx, "OSMesaGetCurrentContext after re-binding");
        h_expect_no_error("end");
        OSMesaMakeCurrent(NULL, NULL, 0, 0, 0);
        OSMesaDestroyContext(ctx);
    }
    return h_finish();
}
