/* t_stencil_blend: the classic stencil reflection sequence (GL 1.5 sections
 * 4.1.5 stencil test, 4.1.6 depth, 4.1.8 blending, 4.2.2 masks), checked
 * pixel by pixel against values computed here.
 *
 *  1. Floor into the stencil only: colour masked off, depth test off,
 *     glStencilFunc(GL_ALWAYS, 1), glStencilOp(KEEP, KEEP, REPLACE).  The
 *     colour and depth buffers must not change; stencil = 1 on the floor.
 *  2. The reflected object (red, wider than the floor), depth test on,
 *     drawn only where stencil == 1: red appears on the floor only.
 *  3. The translucent floor (204,204,204,77) blended with
 *     glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA), stencil off:
 *     each channel = (s*a + d*(255-a))/255 rounded, within 1 LSB.
 *  4. The real object (green, opaque) above the floor, blending off.
 * Plus the queries and errors of the calls used, stencil reference
 * clamping, GL_INCR_WRAP on 255, and the alpha test discarding fragments
 * before they reach the stencil buffer.
 */
#include "harness.h"
#include <stdio.h>

#define W 32
#define H 32

/* Floor: columns [8,24), rows [0,16).  Reflection: all columns, rows [4,12).
 * Real object: columns [12,20), rows [18,28). */
#define FX0 8
#define FX1 24
#define FY1 16

static unsigned char px[W * H * 4];
static unsigned char st[W * H];

static void rect(int x0, int y0, int x1, int y1, double depth)
{
    /* glOrtho(0,W,0,H,-1,1): window depth = (1 - z) / 2. */
    double z = 1.0 - 2.0 * depth;
    glBegin(GL_QUADS);
    glVertex3d(x0, y0, z);
    glVertex3d(x1, y0, z);
    glVertex3d(x1, y1, z);
    glVertex3d(x0, y1, z);
    glEnd();
}

static int in_floor(int x, int y) { return x >= FX0 && x < FX1 && y < FY1; }

static int blend1(int s, int d, int a)
{
    /* Round half up of the exact value (s*a + d*(255-a)) / 255. */
    return (2 * (s * a + d * (255 - a)) + 255) / 510;
}

static void read_stencil(void)
{
    glPixelStorei(GL_PACK_ALIGNMENT, 1);
    glReadPixels(0, 0, W, H, GL_STENCIL_INDEX, GL_UNSIGNED_BYTE, st);
}

int main(void)
{
    static const int bg[4] = {51, 51, 102, 255};
    int x, y, bad;
    GLint v;
    GLfloat f4[4];

    h_init(W, H);
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    glOrtho(0, W, 0, H, -1, 1);
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();

    /* Initial state and errors. */
    glGetIntegerv(GL_STENCIL_FUNC, &v);
    h_expect(v == GL_ALWAYS, "initial GL_STENCIL_FUNC 0x%x", v);
    glGetIntegerv(GL_STENCIL_PASS_DEPTH_PASS, &v);
    h_expect(v == GL_KEEP, "initial GL_STENCIL_PASS_DEPTH_PASS 0x%x", v);
    glGetIntegerv(GL_BLEND_SRC, &v);
    h_expect(v == GL_ONE, "initial GL_BLEND_SRC 0x%x", v);
    glGetIntegerv(GL_BLEND_DST, &v);
    h_expect(v == GL_ZERO, "initial GL_BLEND_DST 0x%x", v);
    glGetIntegerv(GL_BLEND_EQUATION, &v);
    h_expect(v == GL_FUNC_ADD, "initial GL_BLEND_EQUATION 0x%x", v);
    glGetIntegerv(GL_LOGIC_OP_MODE, &v);
    h_expect(v == GL_COPY, "initial GL_LOGIC_OP_MODE 0x%x", v);
    glGetIntegerv(GL_ALPHA_TEST_FUNC, &v);
    h_expect(v == GL_ALWAYS, "initial GL_ALPHA_TEST_FUNC 0x%x", v);
    h_expect_no_error("initial queries");
    glStencilFunc(GL_KEEP, 0, 0);
    h_expect_error(GL_INVALID_ENUM, "glStencilFunc(GL_KEEP)");
    glStencilOp(GL_KEEP, GL_LESS, GL_KEEP);
    h_expect_error(GL_INVALID_ENUM, "glStencilOp(.., GL_LESS, ..)");
    glBlendFunc(GL_ONE, GL_SRC_ALPHA_SATURATE);
    h_expect_error(GL_INVALID_ENUM, "glBlendFunc(.., GL_SRC_ALPHA_SATURATE)");
    glBlendEquation(GL_ONE);
    h_expect_error(GL_INVALID_ENUM, "glBlendEquation(GL_ONE)");
    glLogicOp(GL_COPY + 0x100);
    h_expect_error(GL_INVALID_ENUM, "glLogicOp(bad)");
    glBegin(GL_TRIANGLES);
    glStencilFunc(GL_EQUAL, 1, 1);
    glEnd();
    h_expect_error(GL_INVALID_OPERATION, "glStencilFunc between glBegin and glEnd");
    glStencilFunc(GL_ALWAYS, 300, 0xFF);
    glGetIntegerv(GL_STENCIL_REF, &v);
    h_expect(v == 255, "GL_STENCIL_REF clamps 300 to 255, got %d", v);
    glBlendColor(0.25f, 1.5f, -1.0f, 0.5f);
    glGetFloatv(GL_BLEND_COLOR, f4);
    h_expect(f4[0] == 0.25f && f4[1] == 1.0f && f4[2] == 0.0f && f4[3] == 0.5f,
             "GL_BLEND_COLOR clamped: %g %g %g %g", f4[0], f4[1], f4[2], f4[3]);
    h_expect_no_error("setters");

    /* GL_INCR_WRAP on 255 gives 0; GL_INCR saturates. Colour masked. */
    glClearStencil(255);
    glClear(GL_STENCIL_BUFFER_BIT);
    glEnable(GL_STENCIL_TEST);
    glColorMask(GL_FALSE, GL_FALSE, GL_FALSE, GL_FALSE);
    glStencilOp(GL_KEEP, GL_KEEP, GL_INCR_WRAP);
    rect(0, 0, W / 2, H, 0.5);
    glStencilOp(GL_KEEP, GL_KEEP, GL_INCR);
    rect(W / 2, 0, W, H, 0.5);
    read_stencil();
    h_expect(st[0] == 0 && st[W - 1] == 255, "INCR_WRAP 255 -> %d (want 0), INCR 255 -> %d (want 255)",
             st[0], st[W - 1]);
    /* The alpha test comes before the stencil test: no stencil change. */
    glEnable(GL_ALPHA_TEST);
    glAlphaFunc(GL_GREATER, 0.5f);
    glColor4f(1, 1, 1, 0.25f);
    glStencilOp(GL_ZERO, GL_ZERO, GL_ZERO);
    rect(0, 0, W, H, 0.5);
    read_stencil();
    h_expect(st[W - 1] == 255, "fragment failing the alpha test changed the stencil to %d", st[W - 1]);
    glDisable(GL_ALPHA_TEST);
    glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
    glDisable(GL_STENCIL_TEST);
    h_expect_no_error("wrap checks");

    /* The reflection. */
    glClearColor(51 / 255.0f, 51 / 255.0f, 102 / 255.0f, 1);
    glClearStencil(0);
    glClearDepth(1.0);
    glStencilMask(0xFF);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT | GL_STENCIL_BUFFER_BIT);

    /* 1. Floor into the stencil buffer only. */
    glColorMask(GL_FALSE, GL_FALSE, GL_FALSE, GL_FALSE);
    glDisable(GL_DEPTH_TEST);
    glEnable(GL_STENCIL_TEST);
    glStencilFunc(GL_ALWAYS, 1, 0xFF);
    glStencilOp(GL_KEEP, GL_KEEP, GL_REPLACE);
    glColor4ub(255, 255, 255, 255);
    rect(FX0, 0, FX1, FY1, 0.5);
    read_stencil();
    h_read(px);
    bad = 0;
    for (y = 0; y < H; y++)
        for (x = 0; x < W; x++) {
            const unsigned char *p = &px[(y * W + x) * 4];
            if (st[y * W + x] != (in_floor(x, y) ? 1 : 0))
                bad++;
            if (p[0] != bg[0] || p[1] != bg[1] || p[2] != bg[2] || p[3] != bg[3])
                bad++;
        }
    h_expect(bad == 0, "stencil-only floor pass: %d wrong stencil or colour values", bad);

    /* 2. The reflected object where stencil == 1. */
    glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_LESS);
    glStencilFunc(GL_EQUAL, 1, 0xFF);
    glStencilOp(GL_KEEP, GL_KEEP, GL_KEEP);
    glColor4ub(255, 0, 0, 255);
    rect(0, 4, W, 12, 0.75);
    glDisable(GL_STENCIL_TEST);

    /* 3. The translucent floor, nearer than the reflection. */
    glEnable(GL_BLEND);
    glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
    glColor4ub(204, 204, 204, 77);
    rect(FX0, 0, FX1, FY1, 0.5);
    glDisable(GL_BLEND);

    /* 4. The real object. */
    glColor4ub(0, 255, 0, 255);
    rect(12, 18, 20, 28, 0.25);
    h_expect_no_error("reflection passes");

    h_read(px);
    bad = 0;
    for (y = 0; y < H; y++)
        for (x = 0; x < W; x++) {
            const unsigned char *p = &px[(y * W + x) * 4];
            int e[4], c;
            if (x >= 12 && x < 20 && y >= 18 && y < 28) {
                e[0] = 0; e[1] = 255; e[2] = 0; e[3] = 255;
            } else if (in_floor(x, y)) {
                int under[4] = {bg[0], bg[1], bg[2], bg[3]};
                if (y >= 4 && y < 12) {
                    under[0] = 255; under[1] = 0; under[2] = 0; under[3] = 255;
                }
                for (c = 0; c < 3; c++)
                    e[c] = blend1(204, under[c], 77);
                e[3] = blend1(77, under[3], 77);
            } else {
                for (c = 0; c < 4; c++)
                    e[c] = bg[c];
            }
            for (c = 0; c < 4; c++)
                if (p[c] - e[c] > 1 || e[c] - p[c] > 1) {
                    if (bad++ < 5)
                        h_expect(0, "pixel (%d,%d) = %d,%d,%d,%d, expected %d,%d,%d,%d", x, y, p[0], p[1],
                                 p[2], p[3], e[0], e[1], e[2], e[3]);
                    break;
                }
        }
    h_expect(bad == 0, "reflection image: %d wrong pixels", bad);
    /* Spot checks with the values worked by hand: red under the floor
     * (255,0,0) -> (240,62,62,201); background -> (97,97,133,201). */
    h_expect_pixel(16, 8, 240, 62, 62, 201, 1, "floor over the reflection");
    h_expect_pixel(16, 14, 97, 97, 133, 201, 1, "floor over the background");
    h_expect_pixel(2, 8, bg[0], bg[1], bg[2], bg[3], 0, "reflection clipped by the stencil");
    h_expect_pixel(16, 20, 0, 255, 0, 255, 0, "real object");
    h_save("stencil_blend");
    return h_finish();
}
