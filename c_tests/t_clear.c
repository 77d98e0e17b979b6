/* t_clear: glClear semantics (GL 1.5 section 4.2.3, 4.2.2).
 *
 * - glClear writes the clear colour to every pixel; it ignores the viewport
 *   but honours the scissor box and the colour/depth/stencil write masks.
 * - Depth clears are read back with glReadPixels(GL_DEPTH_COMPONENT, GL_FLOAT)
 *   within 2^-16; glDepthMask(GL_FALSE) leaves depth unchanged.
 * - Stencil clears honour glStencilMask bit by bit.
 * - glClearDepth clamps its argument to [0,1].
 * - glClear with a bit other than COLOR/DEPTH/STENCIL/ACCUM gives
 *   GL_INVALID_VALUE and does nothing; glClear between glBegin/glEnd gives
 *   GL_INVALID_OPERATION and does nothing.
 */
#include "harness.h"
#include <math.h>
#include <stdio.h>
#include <stdlib.h>

#define W 32
#define H 24

static unsigned char px[W * H * 4];

/* Every pixel inside [x0,x1)x[y0,y1) must be `in`, every other pixel `out`. */
static void expect_box(int x0, int y0, int x1, int y1, const unsigned char in[4],
                       const unsigned char out[4], const char *what)
{
    int x, y, c, bad = 0, fx = -1, fy = -1;
    h_read(px);
    for (y = 0; y < H; y++)
        for (x = 0; x < W; x++) {
            int inside = x >= x0 && x < x1 && y >= y0 && y < y1;
            const unsigned char *e = inside ? in : out;
            for (c = 0; c < 4; c++)
                if (abs(px[(y * W + x) * 4 + c] - e[c]) > 1) {
                    if (!bad) { fx = x; fy = y; }
                    bad++;
                    break;
                }
        }
    if (bad) {
        const unsigned char *p = &px[(fy * W + fx) * 4];
        h_expect(0, "%s: %d wrong pixels; first (%d,%d) = %d,%d,%d,%d", what, bad,
                 fx, fy, p[0], p[1], p[2], p[3]);
    }
}

static void expect_all(const unsigned char c[4], const char *what)
{
    expect_box(0, 0, W, H, c, c, what);
}

static float depth[W * H];

static void expect_depth_all(float want, const char *what)
{
    int i, bad = 0;
    glReadPixels(0, 0, W, H, GL_DEPTH_COMPONENT, GL_FLOAT, depth);
    for (i = 0; i < W * H; i++)
        if (fabsf(depth[i] - want) > 1.0f / 65536.0f)
            bad++;
    h_expect(bad == 0, "%s: %d depth values differ from %g (first: %g)", what, bad,
             want, depth[0]);
}

static unsigned char stencil[W * H];

static void expect_stencil_all(int want, const char *what)
{
    int i, bad = 0;
    glPixelStorei(GL_PACK_ALIGNMENT, 1);
    glReadPixels(0, 0, W, H, GL_STENCIL_INDEX, GL_UNSIGNED_BYTE, stencil);
    for (i = 0; i < W * H; i++)
        if (stencil[i] != want)
            bad++;
    h_expect(bad == 0, "%s: %d stencil values differ from 0x%02x (first: 0x%02x)",
             what, bad, want, stencil[0]);
}

int main(void)
{
    static const unsigned char grey[4] = {51, 102, 153, 204};
    static const unsigned char masked[4] = {255, 102, 255, 204};
    static const unsigned char yellow[4] = {255, 255, 0, 255};
    GLfloat f;

    h_init(W, H);
    h_expect_no_error("after init");

    /* Plain colour clear; a small viewport must not limit it. */
    glViewport(2, 2, 4, 4);
    glClearColor(51 / 255.0f, 102 / 255.0f, 153 / 255.0f, 204 / 255.0f);
    glClear(GL_COLOR_BUFFER_BIT);
    expect_all(grey, "colour clear (viewport 4x4 ignored)");
    glViewport(0, 0, W, H);

    /* Colour mask: only red and blue change. */
    glColorMask(GL_TRUE, GL_FALSE, GL_TRUE, GL_FALSE);
    glClearColor(1, 1, 1, 1);
    glClear(GL_COLOR_BUFFER_BIT);
    expect_all(masked, "glColorMask(T,F,T,F) clear to white");
    glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);

    /* Scissored clear: exactly the box [5,15)x[7,13) changes. */
    glClearColor(51 / 255.0f, 102 / 255.0f, 153 / 255.0f, 204 / 255.0f);
    glClear(GL_COLOR_BUFFER_BIT);
    glEnable(GL_SCISSOR_TEST);
    glScissor(5, 7, 10, 6);
    glClearColor(1, 1, 0, 1);
    glClear(GL_COLOR_BUFFER_BIT);
    expect_box(5, 7, 15, 13, yellow, grey, "scissored clear of [5,15)x[7,13)");
    h_expect_pixel(5, 7, 255, 255, 0, 255, 1, "scissor box bottom-left pixel");
    h_expect_pixel(14, 12, 255, 255, 0, 255, 1, "scissor box top-right pixel");
    h_expect_pixel(4, 7, 51, 102, 153, 204, 1, "left of scissor box");
    h_expect_pixel(15, 12, 51, 102, 153, 204, 1, "right of scissor box");
    h_expect_pixel(5, 6, 51, 102, 153, 204, 1, "below scissor box");
    h_expect_pixel(14, 13, 51, 102, 153, 204, 1, "above scissor box");
    /* Scissor box partly outside the window. */
    glScissor(-4, 20, 10, 10);
    glClearColor(0, 0, 1, 1);
    glClear(GL_COLOR_BUFFER_BIT);
    h_expect_pixel(0, 23, 0, 0, 255, 255, 1, "scissor box clipped at top-left corner");
    h_expect_pixel(5, 20, 0, 0, 255, 255, 1, "scissor box clipped, its last column");
    h_expect_pixel(6, 20, 51, 102, 153, 204, 1, "right of clipped scissor box");
    h_expect_pixel(0, 19, 51, 102, 153, 204, 1, "below clipped scissor box");
    glDisable(GL_SCISSOR_TEST);
    h_expect_no_error("colour clears");

    /* Depth clears. */
    glClearDepth(0.0);
    glClear(GL_DEPTH_BUFFER_BIT);
    expect_depth_all(0.0f, "depth clear 0");
    glClearDepth(0.25);
    glClear(GL_DEPTH_BUFFER_BIT);
    expect_depth_all(0.25f, "depth clear 0.25");
    glClearDepth(0.7);
    glClear(GL_DEPTH_BUFFER_BIT);
    expect_depth_all(0.7f, "depth clear 0.7");
    glClearDepth(1.0);
    glClear(GL_DEPTH_BUFFER_BIT);
    expect_depth_all(1.0f, "depth clear 1");
    glDepthMask(GL_FALSE);
    glClearDepth(0.5);
    glClear(GL_DEPTH_BUFFER_BIT);
    expect_depth_all(1.0f, "depth clear 0.5 with glDepthMask(GL_FALSE)");
    glDepthMask(GL_TRUE);
    glClear(GL_DEPTH_BUFFER_BIT);
    expect_depth_all(0.5f, "depth clear 0.5 after glDepthMask(GL_TRUE)");
    /* Scissor applies to depth clears too. */
    glEnable(GL_SCISSOR_TEST);
    glScissor(0, 0, 1, 1);
    glClearDepth(0.125);
    glClear(GL_DEPTH_BUFFER_BIT);
    glDisable(GL_SCISSOR_TEST);
    glReadPixels(0, 0, W, H, GL_DEPTH_COMPONENT, GL_FLOAT, depth);
    h_expect(fabsf(depth[0] - 0.125f) <= 1.0f / 65536, "scissored depth clear: (0,0) = %g, expected 0.125", depth[0]);
    h_expect(fabsf(depth[1] - 0.5f) <= 1.0f / 65536, "scissored depth clear: (1,0) = %g, expected 0.5", depth[1]);
    h_expect(fabsf(depth[W] - 0.5f) <= 1.0f / 65536, "scissored depth clear: (0,1) = %g, expected 0.5", depth[W]);

    /* glClearDepth clamps to [0,1]. */
    glClearDepth(2.0);
    glGetFloatv(GL_DEPTH_CLEAR_VALUE, &f);
    h_expect(f == 1.0f, "glClearDepth(2.0): GL_DEPTH_CLEAR_VALUE = %g, expected 1", f);
    glClear(GL_DEPTH_BUFFER_BIT);
    expect_depth_all(1.0f, "depth clear after glClearDepth(2.0)");
    glClearDepth(-3.0);
    glGetFloatv(GL_DEPTH_CLEAR_VALUE, &f);
    h_expect(f == 0.0f, "glClearDepth(-3.0): GL_DEPTH_CLEAR_VALUE = %g, expected 0", f);
    glClear(GL_DEPTH_BUFFER_BIT);
    expect_depth_all(0.0f, "depth clear after glClearDepth(-3.0)");
    h_expect_no_error("depth clears");

    /* Stencil clears and the stencil write mask. */
    glClearStencil(0xff);
    glClear(GL_STENCIL_BUFFER_BIT);
    expect_stencil_all(0xff, "stencil clear 0xff");
    glStencilMask(0x0f);
    glClearStencil(0x35);
    glClear(GL_STENCIL_BUFFER_BIT);
    expect_stencil_all(0xf5, "stencil clear 0x35 with mask 0x0f over 0xff");
    glStencilMask(0xa0);
    glClearStencil(0x00);
    glClear(GL_STENCIL_BUFFER_BIT);
    expect_stencil_all(0x55, "stencil clear 0x00 with mask 0xa0 over 0xf5");
    glStencilMask(0xff);
    glClearStencil(0x12);
    glClear(GL_STENCIL_BUFFER_BIT);
    expect_stencil_all(0x12, "stencil clear 0x12 with mask 0xff");
    h_expect_no_error("stencil clears");

    /* Clearing all three at once. */
    glClearColor(0, 1, 0, 1);
    glClearDepth(0.75);
    glClearStencil(0x3c);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT | GL_STENCIL_BUFFER_BIT);
    {
        static const unsigned char green[4] = {0, 255, 0, 255};
        expect_all(green, "combined clear: colour");
    }
    expect_depth_all(0.75f, "combined clear: depth");
    expect_stencil_all(0x3c, "combined clear: stencil");

    /* An invalid bit: GL_INVALID_VALUE and nothing is cleared. */
    glClearColor(1, 0, 0, 1);
    glClearDepth(0.0);
    glClearStencil(0);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT | GL_STENCIL_BUFFER_BIT | 0x00010000);
    h_expect_error(GL_INVALID_VALUE, "glClear with bit 0x00010000");
    {
        static const unsigned char green[4] = {0, 255, 0, 255};
        expect_all(green, "colour after invalid glClear");
    }
    expect_depth_all(0.75f, "depth after invalid glClear");
    expect_stencil_all(0x3c, "stencil after invalid glClear");

    /* glClear inside glBegin/glEnd: GL_INVALID_OPERATION, nothing cleared. */
    glBegin(GL_TRIANGLES);
    glClear(GL_COLOR_BUFFER_BIT);
    glEnd();
    h_expect_error(GL_INVALID_OPERATION, "glClear between glBegin/glEnd");
    h_expect_no_error("error flag cleared after reading it");
    {
        static const unsigned char green[4] = {0, 255, 0, 255};
        expect_all(green, "colour after glClear inside glBegin/glEnd");
    }

    return h_finish();
}
