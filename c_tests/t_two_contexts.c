/* t_two_contexts: GL state belongs to a context, and each OSMesa context
 * renders only into its own buffer (GL 1.5 section 2.1: "the GL context";
 * OSMesa: OSMesaMakeCurrent binds a context to a buffer).
 *
 * Context A: OSMESA_RGBA 32x16; context B: OSMESA_BGRA 24x20.  Each is set
 * up once (clear colour, projection, modelview, current colour, shade
 * model), then they are made current alternately for four rounds, each
 * round drawing one more small quad relying only on the state set up
 * earlier; A also clears again in round 2.  Checked: the queried state of
 * each context is its own after every switch, the error flag is per
 * context, and at the end every pixel of both buffers is exactly that
 * context's rendering.
 */
#include "harness.h"
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define AW 32
#define AH 16
#define BW 24
#define BH 20
#define ROUNDS 4

static unsigned char abuf[AW * AH * 4], bbuf[BW * BH * 4];

static void quad(int x0, int y0, int x1, int y1)
{
    glBegin(GL_QUADS);
    glVertex2i(x0, y0);
    glVertex2i(x1, y0);
    glVertex2i(x1, y1);
    glVertex2i(x0, y1);
    glEnd();
}

static void make_current(OSMesaContext c, void *buf, int w, int h, const char *name)
{
    if (!OSMesaMakeCurrent(c, buf, GL_UNSIGNED_BYTE, w, h))
        h_expect(0, "OSMesaMakeCurrent(%s) failed", name);
    h_expect(OSMesaGetCurrentContext() == c, "OSMesaGetCurrentContext is not %s", name);
    h_expect(h_width() == w && h_height() == h, "%s: OSMESA_WIDTH/HEIGHT %dx%d, expected %dx%d", name,
             h_width(), h_height(), w, h);
}

static void expect_state(const char *name, const float clear[4], float proj0, float mv12, const float col[4],
                         int round)
{
    GLfloat v[16];
    GLint shade;
    glGetFloatv(GL_COLOR_CLEAR_VALUE, v);
    h_expect(v[0] == clear[0] && v[1] == clear[1] && v[2] == clear[2] && v[3] == clear[3],
             "round %d: %s clear colour is %g,%g,%g,%g", round, name, v[0], v[1], v[2], v[3]);
    glGetFloatv(GL_PROJECTION_MATRIX, v);
    h_expect(v[0] == proj0, "round %d: %s projection[0] = %g, expected %g", round, name, v[0], proj0);
    glGetFloatv(GL_MODELVIEW_MATRIX, v);
    h_expect(v[12] == mv12, "round %d: %s modelview[12] = %g, expected %g", round, name, v[12], mv12);
    glGetFloatv(GL_CURRENT_COLOR, v);
    h_expect(v[0] == col[0] && v[1] == col[1] && v[2] == col[2],
             "round %d: %s current colour is %g,%g,%g", round, name, v[0], v[1], v[2]);
    glGetIntegerv(GL_SHADE_MODEL, &shade);
    h_expect(shade == (name[0] == 'A' ? GL_FLAT : GL_SMOOTH), "round %d: %s shade model 0x%x", round, name, shade);
}

int main(void)
{
    static const float aclear[4] = {0.2f, 0.0f, 0.0f, 1.0f}, bclear[4] = {0.0f, 0.0f, 0.4f, 1.0f};
    static const float acol[4] = {1, 1, 0, 1}, bcol[4] = {0, 1, 1, 1};
    OSMesaContext a, b;
    int k, x, y, bad;

    memset(abuf, 0x11, sizeof abuf);
    memset(bbuf, 0x22, sizeof bbuf);
    a = OSMesaCreateContextExt(OSMESA_RGBA, 24, 8, 0, NULL);
    b = OSMesaCreateContextExt(OSMESA_BGRA, 16, 0, 0, NULL);
    if (!a || !b) {
        printf("FAIL t_two_contexts (could not create the contexts)\n");
        return 1;
    }

    make_current(a, abuf, AW, AH, "A");
    glClearColor(aclear[0], aclear[1], aclear[2], aclear[3]);
    glMatrixMode(GL_PROJECTION);
    glOrtho(0, AW, 0, AH, -1, 1);
    glMatrixMode(GL_MODELVIEW);
    glColor4fv(acol);
    glShadeModel(GL_FLAT);

    make_current(b, bbuf, BW, BH, "B");
    glClearColor(bclear[0], bclear[1], bclear[2], bclear[3]);
    glMatrixMode(GL_PROJECTION);
    glOrtho(0, BW, 0, BH, -1, 1);
    glMatrixMode(GL_MODELVIEW);
    glTranslatef(2, 3, 0);
    glColor4fv(bcol);
    /* B keeps the default GL_SMOOTH */

    for (k = 0; k < ROUNDS; k++) {
        make_current(a, abuf, AW, AH, "A");
        expect_state("A", aclear, 2.0f / AW, 0.0f, acol, k);
        if (k == 0 || k == 2)
            glClear(GL_COLOR_BUFFER_BIT);
        quad(4 * k + 2, 2, 4 * k + 4, 6);
        if (k == 1) {
            glMatrixMode(0x1234); /* error recorded in A only */
        }

        make_current(b, bbuf, BW, BH, "B");
        expect_state("B", bclear, 2.0f / BW, 2.0f, bcol, k);
        if (k == 0)
            glClear(GL_COLOR_BUFFER_BIT);
        quad(5 * k, 0, 5 * k + 3, 4); /* window [5k+2, 5k+5) x [3, 7) */
        if (k == 1)
            h_expect_no_error("B after an error in A (error flags are per context)");
        if (k == 2) {
            make_current(a, abuf, AW, AH, "A");
            h_expect_error(GL_INVALID_ENUM, "A's error flag after switching back");
            make_current(b, bbuf, BW, BH, "B");
        }
    }

    /* Final contents.  A: background plus the quads of rounds 2 and 3. */
    make_current(a, abuf, AW, AH, "A");
    glFinish();
    bad = 0;
    for (y = 0; y < AH; y++)
        for (x = 0; x < AW; x++) {
            const unsigned char *p = &abuf[(y * AW + x) * 4];
            int q = y >= 2 && y < 6 && ((x >= 10 && x < 12) || (x >= 14 && x < 16));
            unsigned char e[4] = {51, 0, 0, 255};
            if (q) {
                e[0] = 255;
                e[1] = 255;
            }
            if (memcmp(p, e, 4) != 0 && bad++ < 5)
                h_expect(0, "A buffer pixel (%d,%d) = %d,%d,%d,%d, expected %d,%d,%d,%d", x, y, p[0], p[1], p[2], p[3],
                         e[0], e[1], e[2], e[3]);
        }
    h_expect(bad == 0, "A buffer: %d wrong pixels", bad);
    h_expect_no_error("A at the end");

    /* B (BGRA bytes): background plus four quads. */
    make_current(b, bbuf, BW, BH, "B");
    glFinish();
    bad = 0;
    for (y = 0; y < BH; y++)
        for (x = 0; x < BW; x++) {
            const unsigned char *p = &bbuf[(y * BW + x) * 4];
            int q = 0;
            unsigned char e[4] = {102, 0, 0, 255}; /* b, g, r, a */
            for (k = 0; k < ROUNDS; k++)
                if (x >= 5 * k + 2 && x < 5 * k + 5 && y >= 3 && y < 7)
                    q = 1;
            if (q) {
                e[0] = 255;
                e[1] = 255;
            }
            if (memcmp(p, e, 4) != 0 && bad++ < 5)
                h_expect(0, "B buffer pixel (%d,%d) = bytes %d,%d,%d,%d, expected %d,%d,%d,%d", x, y, p[0], p[1], p[2],
                         p[3], e[0], e[1], e[2], e[3]);
        }
    h_expect(bad == 0, "B buffer: %d wrong pixels", bad);
    h_expect_no_error("B at the end");

    OSMesaMakeCurrent(NULL, NULL, 0, 0, 0);
    OSMesaDestroyContext(a);
    OSMesaDestroyContext(b);
    return h_finish();
}
