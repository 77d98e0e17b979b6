/* t_osmesa_direct: OSMesa draws straight into a caller's GL_RGBA /
 * GL_UNSIGNED_BYTE buffer (src/framebuffer/color.rs); what a program can see
 * of that must be what the copying path gives.
 *
 * - Drawing without a clear keeps what the caller put in the buffer before
 *   OSMesaMakeCurrent, in the direct layout and in a converted one (BGRA).
 * - After OSMesaMakeCurrent with another buffer of the same size, drawing
 *   never reaches the first buffer.
 * - OSMesaPixelStore(OSMESA_Y_UP, 0) then glFinish writes the same image
 *   flipped; back to Y_UP 1, the image is upright again and further drawing
 *   without a clear keeps it.
 * - The same with OSMESA_ROW_LENGTH padding (set right after
 *   OSMesaMakeCurrent): the image lands in padded rows, the padding is left
 *   alone; back to ROW_LENGTH 0 the image moves into packed rows.
 *
 * (Drawn in place, the buffer changes as drawing happens rather than only
 * at glFinish; a program that looks at it after glFinish, as OSMesa's
 * contract says, sees no difference.)
 */
#include "harness.h"
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define W 8
#define H 6

/* A rectangle of colour c over GL pixels [x0, x1) x [y0, y1). */
static void rect(int x0, int y0, int x1, int y1, const unsigned char *c)
{
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    glOrtho(0, W, 0, H, -1, 1);
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
    glColor4ubv(c);
    glRecti(x0, y0, x1, y1);
}

/* Pixel (x, y) of an RGBA buffer whose row r holds GL row r (up) or H-1-r. */
static const unsigned char *px(const unsigned char *buf, int row_pixels, int x, int y, int up)
{
    int r = up ? y : H - 1 - y;
    return buf + ((size_t)r * row_pixels + x) * 4;
}

static int same(const unsigned char *p, const unsigned char *c)
{
    return p[0] == c[0] && p[1] == c[1] && p[2] == c[2] && p[3] == c[3];
}

int main(void)
{
    static const unsigned char red[4] = {255, 0, 0, 255}, blue[4] = {0, 0, 255, 255};
    static const unsigned char grey[4] = {7, 8, 9, 10}, green[4] = {0, 255, 0, 255};
    static unsigned char a[W * H * 4], b[W * H * 4], padded[16 * H * 4];
    unsigned char bgra[W * H * 4];
    static unsigned short shorts[W * H * 4];
    OSMesaContext ctx, cb;
    int x, y, bad;

    ctx = OSMesaCreateContextExt(OSMESA_RGBA, 0, 0, 0, NULL);
    cb = OSMesaCreateContextExt(OSMESA_BGRA, 0, 0, 0, NULL);
    h_expect(ctx && cb, "contexts");

    /* The caller's pixels survive drawing without a clear. */
    for (x = 0; x < W * H; x++)
        memcpy(a + x * 4, grey, 4);
    OSMesaMakeCurrent(ctx, a, GL_UNSIGNED_BYTE, W, H);
    rect(0, 0, 2, 2, red);
    glFinish();
    h_expect(same(px(a, W, 0, 0, 1), red) && same(px(a, W, 5, 4, 1), grey),
             "RGBA: drawn pixel red and untouched pixel kept: %d,%d,%d,%d", px(a, W, 5, 4, 1)[0], px(a, W, 5, 4, 1)[1],
             px(a, W, 5, 4, 1)[2], px(a, W, 5, 4, 1)[3]);
    for (x = 0; x < W * H; x++) {
        bgra[x * 4 + 0] = grey[2];
        bgra[x * 4 + 1] = grey[1];
        bgra[x * 4 + 2] = grey[0];
        bgra[x * 4 + 3] = grey[3];
    }
    OSMesaMakeCurrent(cb, bgra, GL_UNSIGNED_BYTE, W, H);
    rect(0, 0, 2, 2, red);
    glFinish();
    h_expect(bgra[2] == 255 && bgra[0] == 0 && bgra[(5 + 4 * W) * 4 + 0] == grey[2] && bgra[(5 + 4 * W) * 4 + 2] == grey[0],
             "BGRA: drawn pixel red and untouched pixel kept");

    /* Rebinding to another buffer: the first one is left alone. */
    OSMesaMakeCurrent(ctx, a, GL_UNSIGNED_BYTE, W, H);
    memset(b, 0, sizeof b);
    OSMesaMakeCurrent(ctx, b, GL_UNSIGNED_BYTE, W, H);
    glClearColor(0, 1, 0, 1);
    glClear(GL_COLOR_BUFFER_BIT);
    rect(4, 4, 6, 6, blue);
    glFinish();
    h_expect(same(px(b, W, 0, 0, 1), green) && same(px(b, W, 4, 4, 1), blue), "second buffer drawn");
    h_expect(same(px(a, W, 0, 0, 1), red) && same(px(a, W, 4, 4, 1), grey), "first buffer untouched after rebinding");
    /* ... also when the next buffer is one converted into (16-bit). */
    OSMesaMakeCurrent(ctx, a, GL_UNSIGNED_BYTE, W, H);
    OSMesaMakeCurrent(ctx, shorts, GL_UNSIGNED_SHORT, W, H);
    glClear(GL_COLOR_BUFFER_BIT);
    glFinish();
    h_expect(same(px(a, W, 0, 0, 1), red) && same(px(a, W, 4, 4, 1), grey), "first buffer untouched after rebinding to 16-bit");
    h_expect(shorts[0] == 0 && shorts[1] == 65535, "16-bit buffer cleared green: %u %u", shorts[0], shorts[1]);
    OSMesaMakeCurrent(ctx, b, GL_UNSIGNED_BYTE, W, H);

    /* Y_UP 0: the same image, flipped, without drawing. */
    OSMesaPixelStore(OSMESA_Y_UP, 0);
    glFinish();
    bad = 0;
    for (y = 0; y < H; y++)
        for (x = 0; x < W; x++)
            bad += !same(px(b, W, x, y, 0), (x >= 4 && x < 6 && y >= 4) ? blue : green);
    h_expect(bad == 0, "Y_UP 0: %d pixels not the flipped image", bad);
    /* Back to Y_UP 1: upright, and drawing without a clear keeps it. */
    OSMesaPixelStore(OSMESA_Y_UP, 1);
    rect(0, 0, 1, 1, red);
    glFinish();
    bad = 0;
    for (y = 0; y < H; y++)
        for (x = 0; x < W; x++)
            bad += !same(px(b, W, x, y, 1), (x == 0 && y == 0) ? red : (x >= 4 && x < 6 && y >= 4) ? blue : green);
    h_expect(bad == 0, "Y_UP 1 again: %d pixels wrong", bad);

    /* ROW_LENGTH padding: rows 16 pixels apart, then back to W. */
    memset(padded, 0x55, sizeof padded);
    OSMesaMakeCurrent(ctx, padded, GL_UNSIGNED_BYTE, W, H);
    OSMesaPixelStore(OSMESA_ROW_LENGTH, 16);
    glClear(GL_COLOR_BUFFER_BIT);
    rect(4, 4, 6, 6, blue);
    glFinish();
    bad = 0;
    for (y = 0; y < H; y++)
        for (x = 0; x < 16; x++) {
            const unsigned char *p = px(padded, 16, x, y, 1);
            if (x >= W)
                bad += p[0] != 0x55;
            else
                bad += !same(p, (x >= 4 && x < 6 && y >= 4) ? blue : green);
        }
    h_expect(bad == 0, "ROW_LENGTH 16: %d pixels wrong", bad);
    OSMesaPixelStore(OSMESA_ROW_LENGTH, 0);
    rect(0, 0, 1, 1, red);
    glFinish();
    bad = 0;
    for (y = 0; y < H; y++)
        for (x = 0; x < W; x++)
            bad += !same(px(padded, W, x, y, 1), (x == 0 && y == 0) ? red : (x >= 4 && x < 6 && y >= 4) ? blue : green);
    h_expect(bad == 0, "ROW_LENGTH 0 again: %d pixels wrong", bad);
    h_expect_no_error("direct OSMesa buffers");

    OSMesaMakeCurrent(NULL, NULL, 0, 0, 0);
    OSMesaDestroyContext(ctx);
    OSMesaDestroyContext(cb);
    return h_finish();
}
