/* t_bitmap: glBitmap (GL 1.5 section 3.7).
 *
 * - Bit (i, j) of a w x h bitmap drawn at raster position (xr, yr) with
 *   origin (xo, yo) is the fragment at (floor(xr - xo) + i, floor(yr - yo) + j);
 *   fragments take the raster colour; 0 bits leave pixels alone.
 * - The raster position then moves by (xmove, ymove), also for a NULL
 *   bitmap; a string of glyphs lands glyph after glyph.
 * - Unpacking: rows padded to GL_UNPACK_ALIGNMENT, GL_UNPACK_LSB_FIRST,
 *   GL_UNPACK_SKIP_PIXELS / ROW_LENGTH.
 * - Display lists capture the bitmap at compile time (changing the unpack
 *   modes afterwards changes nothing), as wgl/glX font lists need.
 * - Clipping: a bitmap partly outside the window draws its inside part; the
 *   position may move outside the window and stay valid (the "move with a
 *   NULL bitmap" idiom); the scissor test clips.
 * - Fragment operations: the depth test uses the raster z.
 * All checks are exact pixel values computed from the rule above.
 */
#define GL_GLEXT_PROTOTYPES 1
#include "harness.h"
#include <stdio.h>
#include <string.h>

#define W 48
#define H 24

static unsigned char px[W * H * 4];

/* An 8x6 "F" glyph, rows bottom-up, MSB first. */
static const GLubyte glyph[6] = {0x60, 0x60, 0x7C, 0x60, 0x7E, 0x00};

static int bit(const GLubyte *rows, int stride, int i, int j)
{
    return (rows[j * stride + i / 8] >> (7 - i % 8)) & 1;
}

/* Every pixel must be colour c where the glyph (w x h, at lower-left
 * (x0, y0)) has a 1 bit, and the background b elsewhere; pixels not in
 * [cx0, cx1) are ignored. */
static void expect_glyph(const GLubyte *rows, int stride, int w, int h, int x0, int y0,
                         const unsigned char c[3], const unsigned char b[3], const char *what)
{
    int x, y, bad = 0;
    h_read(px);
    for (y = 0; y < H; y++)
        for (x = 0; x < W; x++) {
            int i = x - x0, j = y - y0;
            int on = i >= 0 && j >= 0 && i < w && j < h && bit(rows, stride, i, j);
            const unsigned char *e = on ? c : b;
            const unsigned char *p = &px[(y * W + x) * 4];
            if (p[0] != e[0] || p[1] != e[1] || p[2] != e[2]) {
                if (bad++ < 3)
                    h_expect(0, "%s: pixel (%d,%d) = %d,%d,%d, expected %d,%d,%d", what, x, y, p[0], p[1],
                             p[2], e[0], e[1], e[2]);
            }
        }
    if (bad > 3)
        h_expect(0, "%s: %d wrong pixels in all", what, bad);
}

static void clear(void)
{
    glClearColor(0, 0, 0, 0);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
}

int main(void)
{
    static const unsigned char red[3] = {255, 0, 0}, black[3] = {0, 0, 0}, green[3] = {0, 255, 0};
    GLubyte lsb[6], wide[4 * 6], aligned[4 * 2];
    float pos[4];
    int i, j;
    GLuint list;

    h_init(W, H);
    glMatrixMode(GL_PROJECTION);
    glOrtho(0, W, 0, H, -1, 1);
    glMatrixMode(GL_MODELVIEW);
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);

    /* One glyph with a fractional position and origin. */
    clear();
    glColor3f(1, 0, 0);
    glRasterPos2f(5.75f, 3.5f);
    glBitmap(8, 6, 1.5f, 0.25f, 9.0f, 0.0f, glyph);
    expect_glyph(glyph, 1, 8, 6, 4, 3, red, black, "glyph at (5.75,3.5) origin (1.5,0.25)");
    glGetFloatv(GL_CURRENT_RASTER_POSITION, pos);
    h_expect(pos[0] == 14.75f && pos[1] == 3.5f, "moved to %g,%g, expected 14.75,3.5", pos[0], pos[1]);

    /* A string: three glyphs, 10 pixels apart. */
    clear();
    glRasterPos2i(2, 10);
    for (i = 0; i < 3; i++)
        glBitmap(8, 6, 0, 0, 10, 0, glyph);
    h_read(px);
    for (i = 0; i < 3; i++)
        for (j = 0; j < 6; j++) {
            int k;
            for (k = 0; k < 8; k++) {
                int x = 2 + 10 * i + k, y = 10 + j;
                int on = bit(glyph, 1, k, j);
                h_expect(px[(y * W + x) * 4] == (on ? 255 : 0), "string glyph %d bit (%d,%d)", i, k, j);
            }
        }

    /* Row padding: a 10-wide bitmap, alignment 4 (rows of 4 bytes). */
    memset(aligned, 0, sizeof aligned);
    aligned[0] = 0xC0; aligned[1] = 0x40; /* row 0: 11000000 01 */
    aligned[4] = 0x01; aligned[5] = 0x80; /* row 1: 00000001 10 */
    clear();
    glPixelStorei(GL_UNPACK_ALIGNMENT, 4);
    glRasterPos2i(20, 2);
    glBitmap(10, 2, 0, 0, 0, 0, aligned);
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
    expect_glyph(aligned, 4, 10, 2, 20, 2, red, black, "10x2 bitmap, alignment 4");

    /* LSB first: the glyph with each byte bit-reversed. */
    for (j = 0; j < 6; j++) {
        GLubyte v = glyph[j], r = 0;
        for (i = 0; i < 8; i++)
            if (v & (1 << i))
                r |= 0x80 >> i;
        lsb[j] = r;
    }
    clear();
    glPixelStorei(GL_UNPACK_LSB_FIRST, GL_TRUE);
    glRasterPos2i(6, 6);
    glBitmap(8, 6, 0, 0, 0, 0, lsb);
    glPixelStorei(GL_UNPACK_LSB_FIRST, GL_FALSE);
    expect_glyph(glyph, 1, 8, 6, 6, 6, red, black, "GL_UNPACK_LSB_FIRST");

    /* Skip pixels and row length: the glyph sits at bits 12..19 of 4-byte rows. */
    memset(wide, 0, sizeof wide);
    for (j = 0; j < 6; j++) {
        wide[j * 4 + 1] = glyph[j] >> 4;
        wide[j * 4 + 2] = (GLubyte)(glyph[j] << 4);
    }
    clear();
    glPixelStorei(GL_UNPACK_ROW_LENGTH, 32);
    glPixelStorei(GL_UNPACK_SKIP_PIXELS, 12);
    glRasterPos2i(30, 12);
    glBitmap(8, 6, 0, 0, 0, 0, wide);
    expect_glyph(glyph, 1, 8, 6, 30, 12, red, black, "GL_UNPACK_SKIP_PIXELS 12, ROW_LENGTH 32");

    /* Display list: compiled with these modes, called with others. */
    list = glGenLists(1);
    glNewList(list, GL_COMPILE);
    glBitmap(8, 6, 0, 0, 8, 0, wide);
    glEndList();
    glPixelStorei(GL_UNPACK_ROW_LENGTH, 0);
    glPixelStorei(GL_UNPACK_SKIP_PIXELS, 0);
    clear();
    glColor3f(0, 1, 0);
    glRasterPos2i(1, 1);
    glCallList(list);
    expect_glyph(glyph, 1, 8, 6, 1, 1, green, black, "bitmap in a display list keeps its compile-time unpacking");
    glGetFloatv(GL_CURRENT_RASTER_POSITION, pos);
    h_expect(pos[0] == 9.0f, "list bitmap moved the position to %g, expected 9", pos[0]);

    /* Partly outside the window: the inside part is drawn. */
    clear();
    glColor3f(1, 0, 0);
    glRasterPos2i(44, 20);
    glBitmap(8, 6, 0, 0, 0, 0, glyph);
    expect_glyph(glyph, 1, 8, 6, 44, 20, red, black, "glyph clipped at the top right");
    /* Moving outside the window with a NULL bitmap keeps the position valid. */
    clear();
    glRasterPos2i(2, 2);
    glBitmap(0, 0, 0, 0, -5, -3, NULL);
    {
        GLboolean valid = 0;
        glGetBooleanv(GL_CURRENT_RASTER_POSITION_VALID, &valid);
        h_expect(valid == GL_TRUE, "position moved outside the window stays valid");
    }
    glBitmap(8, 6, 0, 0, 0, 0, glyph);
    expect_glyph(glyph, 1, 8, 6, -3, -1, red, black, "glyph at (-3,-1), clipped at the bottom left");

    /* Scissor. */
    clear();
    glEnable(GL_SCISSOR_TEST);
    glScissor(0, 0, 10, H);
    glRasterPos2i(6, 6);
    glBitmap(8, 6, 0, 0, 0, 0, glyph);
    glDisable(GL_SCISSOR_TEST);
    h_read(px);
    for (j = 0; j < 6; j++)
        for (i = 0; i < 8; i++) {
            int x = 6 + i, y = 6 + j;
            int on = bit(glyph, 1, i, j) && x < 10;
            h_expect(px[(y * W + x) * 4] == (on ? 255 : 0), "scissored glyph pixel (%d,%d)", x, y);
        }

    /* Depth test against the raster z: a quad at depth 0.5 covers the left half. */
    clear();
    glEnable(GL_DEPTH_TEST);
    glColor3f(0, 0, 1);
    glRecti(0, 0, W / 2, H); /* z = 0 -> depth 0.5 */
    glColor3f(1, 0, 0);
    glRasterPos3f(20, 6, 0.5f); /* depth 0.25: passes everywhere */
    glBitmap(8, 6, 0, 0, 0, 0, glyph);
    glRasterPos3f(20, 14, -0.5f); /* depth 0.75: fails over the quad */
    glBitmap(8, 6, 0, 0, 0, 0, glyph);
    glDisable(GL_DEPTH_TEST);
    h_read(px);
    for (j = 0; j < 6; j++)
        for (i = 0; i < 8; i++) {
            int x = 20 + i, on = bit(glyph, 1, i, j);
            int bg = x < W / 2 ? 1 : 0; /* blue background on the left */
            const unsigned char *p1 = &px[((6 + j) * W + x) * 4], *p2 = &px[((14 + j) * W + x) * 4];
            h_expect(p1[0] == (on ? 255 : 0) && p1[2] == (on ? 0 : bg * 255), "depth-passing glyph (%d,%d)", x, 6 + j);
            h_expect(p2[0] == (on && !bg ? 255 : 0), "depth-failing glyph (%d,%d)", x, 14 + j);
        }

    h_expect_no_error("end");
    return h_finish();
}
