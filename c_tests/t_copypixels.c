/* t_copypixels: glCopyPixels (GL 1.5 section 4.3.3).
 *
 * - GL_COLOR copies the source rectangle to the raster position; when
 *   source and destination overlap, the result is as if the whole source
 *   were read before anything is written (checked for shifts in all four
 *   directions against a copy of the original image).
 * - glPixelZoom applies to the copy (zoom 2 doubles each pixel; -1 mirrors).
 * - Pixel transfer applies once (RED_SCALE 0.5).
 * - GL_DEPTH copies depth through the depth test, fragments taking the
 *   raster colour; GL_STENCIL copies stencil through the write mask.
 * - An invalid raster position copies nothing; errors for a bad type and
 *   a negative size.
 */
#define GL_GLEXT_PROTOTYPES 1
#include "harness.h"
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define W 32
#define H 24

static unsigned char orig[W * H * 4], px[W * H * 4];

static void pattern(void)
{
    int x, y;
    for (y = 0; y < H; y++)
        for (x = 0; x < W; x++) {
            unsigned char *p = &orig[(y * W + x) * 4];
            p[0] = (unsigned char)(x * 8);
            p[1] = (unsigned char)(y * 10);
            p[2] = (unsigned char)((x * 7 + y * 13) & 0xFF);
            p[3] = 255;
        }
    glWindowPos2i(0, 0);
    glPixelZoom(1, 1);
    glDrawPixels(W, H, GL_RGBA, GL_UNSIGNED_BYTE, orig);
}

/* Pixel (x, y) must equal orig at (sx, sy) (scaled red if half_red). */
static int same(int x, int y, int sx, int sy, int half_red)
{
    const unsigned char *p = &px[(y * W + x) * 4], *o = &orig[(sy * W + sx) * 4];
    int r = half_red ? (o[0] + 1) / 2 : o[0];
    return abs(p[0] - r) <= (half_red ? 1 : 0) && p[1] == o[1] && p[2] == o[2] && p[3] == o[3];
}

static void copy_case(int sx, int sy, int w, int h, int dx, int dy)
{
    int x, y, bad = 0;
    pattern();
    glWindowPos2i(dx, dy);
    glCopyPixels(sx, sy, w, h, GL_COLOR);
    h_read(px);
    for (y = 0; y < H; y++)
        for (x = 0; x < W; x++) {
            int ix = x - dx + sx, iy = y - dy + sy;
            int in = x >= dx && x < dx + w && y >= dy && y < dy + h;
            if (!(in ? same(x, y, ix, iy, 0) : same(x, y, x, y, 0)) && bad++ < 3)
                h_expect(0, "copy (%d,%d %dx%d) to (%d,%d): pixel (%d,%d) wrong", sx, sy, w, h, dx, dy, x, y);
        }
}

int main(void)
{
    int x, y;
    h_init(W, H);
    glClearColor(0, 0, 0, 0);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT | GL_STENCIL_BUFFER_BIT);

    copy_case(4, 4, 12, 10, 6, 5);  /* up and right, overlapping */
    copy_case(6, 5, 12, 10, 4, 4);  /* down and left, overlapping */
    copy_case(2, 8, 20, 6, 2, 10);  /* straight up */
    copy_case(5, 3, 20, 6, 3, 3);   /* straight left */
    copy_case(0, 0, 8, 8, 20, 12);  /* disjoint */

    /* Zoom 2 and mirrored copies. */
    pattern();
    glWindowPos2i(16, 8);
    glPixelZoom(2, 2);
    glCopyPixels(2, 2, 4, 3, GL_COLOR);
    glPixelZoom(1, 1);
    h_read(px);
    for (y = 8; y < 14; y++)
        for (x = 16; x < 24; x++)
            h_expect(same(x, y, 2 + (x - 16) / 2, 2 + (y - 8) / 2, 0), "zoom 2 copy: pixel (%d,%d)", x, y);
    pattern();
    glWindowPos2i(20, 4);
    glPixelZoom(-1, 1);
    glCopyPixels(0, 0, 5, 3, GL_COLOR);
    glPixelZoom(1, 1);
    h_read(px);
    for (y = 4; y < 7; y++)
        for (x = 15; x < 20; x++)
            h_expect(same(x, y, 19 - x, y - 4, 0), "mirrored copy: pixel (%d,%d)", x, y);

    /* Transfer applies once. */
    pattern();
    glPixelTransferf(GL_RED_SCALE, 0.5f);
    glWindowPos2i(10, 10);
    glCopyPixels(0, 0, 6, 6, GL_COLOR);
    glPixelTransferf(GL_RED_SCALE, 1);
    h_read(px);
    for (y = 10; y < 16; y++)
        for (x = 10; x < 16; x++)
            h_expect(same(x, y, x - 10, y - 10, 1), "RED_SCALE 0.5 copy: pixel (%d,%d)", x, y);

    /* Depth: left half at 0.25, copied over a right half at 0.75 with LESS;
     * the fragments take the raster colour. */
    {
        float d[4 * 4], rd[4];
        int i;
        glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
        glEnable(GL_DEPTH_TEST);
        glDepthFunc(GL_ALWAYS);
        for (i = 0; i < 16; i++)
            d[i] = 0.25f;
        glWindowPos2i(0, 0);
        glDrawPixels(4, 4, GL_DEPTH_COMPONENT, GL_FLOAT, d);
        for (i = 0; i < 16; i++)
            d[i] = 0.75f;
        glWindowPos2i(8, 0);
        glDrawPixels(4, 4, GL_DEPTH_COMPONENT, GL_FLOAT, d);
        glDepthFunc(GL_LESS);
        glColor3f(1, 1, 0);
        glWindowPos2i(8, 0);
        glCopyPixels(0, 0, 4, 4, GL_DEPTH);
        glReadPixels(8, 0, 4, 1, GL_DEPTH_COMPONENT, GL_FLOAT, rd);
        for (i = 0; i < 4; i++)
            h_expect(fabsf(rd[i] - 0.25f) < 1e-6f, "copied depth %g, expected 0.25", rd[i]);
        h_expect_pixel(9, 1, 255, 255, 0, 255, 0, "depth copy fragments take the raster colour");
        /* Copying 0.75 back over 0.25 fails the test. */
        glColor3f(0, 0, 1);
        glWindowPos2i(0, 0);
        glCopyPixels(12, 0, 4, 4, GL_DEPTH); /* 12..15 still hold the clear value 1.0 */
        /* (The depth draw above left the raster colour, white, there.) */
        h_expect_pixel(1, 1, 255, 255, 255, 255, 0, "depth copy of 1.0 over 0.25 fails LESS");
        glDisable(GL_DEPTH_TEST);
    }

    /* Stencil through the write mask. */
    {
        GLubyte s[4] = {0x11, 0x22, 0x33, 0xFF}, rs[4];
        glClear(GL_STENCIL_BUFFER_BIT);
        glWindowPos2i(0, 20);
        glDrawPixels(4, 1, GL_STENCIL_INDEX, GL_UNSIGNED_BYTE, s);
        glStencilMask(0xF0);
        glWindowPos2i(2, 20); /* overlapping */
        glCopyPixels(0, 20, 4, 1, GL_STENCIL);
        glStencilMask(0xFF);
        glReadPixels(0, 20, 6, 1, GL_STENCIL_INDEX, GL_UNSIGNED_BYTE, rs);
        h_expect(rs[0] == 0x11 && rs[1] == 0x22 && rs[2] == 0x13 && rs[3] == 0x2F,
                 "stencil copy through mask 0xf0: %02x %02x %02x %02x", rs[0], rs[1], rs[2], rs[3]);
    }

    /* Invalid raster position: nothing is copied. */
    pattern();
    glMatrixMode(GL_PROJECTION);
    glOrtho(0, W, 0, H, -1, 1);
    glRasterPos2i(-5, -5);
    glCopyPixels(0, 0, 8, 8, GL_COLOR);
    h_read(px);
    h_expect(memcmp(px, orig, sizeof px) == 0, "copy at an invalid raster position changed pixels");

    h_expect_no_error("before errors");
    glCopyPixels(0, 0, 1, 1, GL_RGBA);
    h_expect_error(GL_INVALID_ENUM, "glCopyPixels type GL_RGBA");
    glCopyPixels(0, 0, -1, 1, GL_COLOR);
    h_expect_error(GL_INVALID_VALUE, "negative width");
    return h_finish();
}
