/* t_depth_funcs: the depth buffer test (GL 1.5 section 4.1.6) and the depth
 * range mapping (section 2.11.1).
 *
 * - For each of the eight glDepthFunc values, a fragment passes iff
 *   "incoming <func> stored"; passing fragments write colour and (with
 *   glDepthMask(GL_TRUE)) depth, failing ones write nothing.  Two quads
 *   overlap: A (red, depth 0.5) drawn first with GL_ALWAYS, then B (green)
 *   at depth 0.25, 0.5 and 0.75 with the function under test.  The overlap
 *   and the part of B over the cleared depth (1.0) are checked exactly, and
 *   the depth buffer is read back (tolerance 2^-16).
 * - glDepthRange(n, f) maps NDC z in [-1,1] to window z = n + (f-n)(z+1)/2,
 *   including reversed ranges; arguments are clamped to [0,1].
 * - glDepthMask(GL_FALSE) keeps the stored depth while colour is written.
 * - With GL_DEPTH_TEST disabled, the depth buffer is not updated.
 */
#include "harness.h"
#include <math.h>
#include <stdio.h>
#include <stdlib.h>

#define W 32
#define H 16
#define DEPTH_TOL (1.0f / 65536.0f)

static unsigned char px[W * H * 4];
static float dbuf[W * H];

/* glOrtho(0,W,0,H,-1,1) gives NDC z = -z_obj, so window depth (with the
 * default range) = (1 - z_obj) / 2. */
static void quad(int x0, int x1, double depth, unsigned char r, unsigned char g,
                 unsigned char b)
{
    double z = 1.0 - 2.0 * depth;
    glColor3ub(r, g, b);
    glBegin(GL_QUADS);
    glVertex3d(x0, 0, z);
    glVertex3d(x1, 0, z);
    glVertex3d(x1, H, z);
    glVertex3d(x0, H, z);
    glEnd();
}

/* Quad given directly by its NDC z (for the glDepthRange checks). */
static void quad_ndc(int x0, int x1, double zndc)
{
    glColor3ub(255, 255, 255);
    glBegin(GL_QUADS);
    glVertex3d(x0, 0, -zndc);
    glVertex3d(x1, 0, -zndc);
    glVertex3d(x1, H, -zndc);
    glVertex3d(x0, H, -zndc);
    glEnd();
}

static int passes(GLenum func, double incoming, double stored)
{
    switch (func) {
    case GL_NEVER: return 0;
    case GL_LESS: return incoming < stored;
    case GL_EQUAL: return incoming == stored;
    case GL_LEQUAL: return incoming <= stored;
    case GL_GREATER: return incoming > stored;
    case GL_NOTEQUAL: return incoming != stored;
    case GL_GEQUAL: return incoming >= stored;
    case GL_ALWAYS: return 1;
    }
    return -1;
}

/* Columns [x0,x1) must all have colour c and depth d. */
static void expect_cols(int x0, int x1, const unsigned char c[3], double d, const char *what)
{
    int x, y, bad = 0, badd = 0;
    h_read(px);
    glReadPixels(0, 0, W, H, GL_DEPTH_COMPONENT, GL_FLOAT, dbuf);
    for (y = 0; y < H; y++)
        for (x = x0; x < x1; x++) {
            const unsigned char *p = &px[(y * W + x) * 4];
            if (p[0] != c[0] || p[1] != c[1] || p[2] != c[2])
                bad++;
            if (d >= 0 && fabs(dbuf[y * W + x] - d) > DEPTH_TOL)
                badd++;
        }
    if (bad) {
        const unsigned char *p = &px[((H / 2) * W + x0) * 4];
        h_expect(0, "%s: %d pixels in columns [%d,%d) are not %d,%d,%d (e.g. (%d,%d) = %d,%d,%d)",
                 what, bad, x0, x1, c[0], c[1], c[2], x0, H / 2, p[0], p[1], p[2]);
    }
    if (badd)
        h_expect(0, "%s: %d depth values in columns [%d,%d) are not %g (e.g. %g)",
                 what, badd, x0, x1, d, dbuf[(H / 2) * W + x0]);
}

static void setup(double clear_depth)
{
    glDepthMask(GL_TRUE);
    glClearColor(0, 0, 0, 1);
    glClearDepth(clear_depth);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
}

int main(void)
{
    static const GLenum funcs[8] = {GL_NEVER, GL_LESS, GL_EQUAL, GL_LEQUAL,
                                    GL_GREATER, GL_NOTEQUAL, GL_GEQUAL, GL_ALWAYS};
    static const char *names[8] = {"GL_NEVER", "GL_LESS", "GL_EQUAL", "GL_LEQUAL",
                                   "GL_GREATER", "GL_NOTEQUAL", "GL_GEQUAL", "GL_ALWAYS"};
    static const unsigned char red[3] = {255, 0, 0}, green[3] = {0, 255, 0},
                               blue[3] = {0, 0, 255}, black[3] = {0, 0, 0},
                               white[3] = {255, 255, 255};
    static const double dBs[3] = {0.25, 0.5, 0.75};
    const double dA = 0.5;
    int f, k;
    GLint v;
    GLfloat range[2];

    h_init(W, H);
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    glOrtho(0, W, 0, H, -1, 1);
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();

    glGetIntegerv(GL_DEPTH_FUNC, &v);
    h_expect(v == GL_LESS, "initial GL_DEPTH_FUNC = 0x%x, expected GL_LESS", v);
    h_expect(!glIsEnabled(GL_DEPTH_TEST), "GL_DEPTH_TEST is initially disabled");
    glEnable(GL_DEPTH_TEST);

    for (k = 0; k < 3; k++) {
        for (f = 0; f < 8; f++) {
            double dB = dBs[k];
            int pov = passes(funcs[f], dB, dA), pright = passes(funcs[f], dB, 1.0);
            char what[96];
            setup(1.0);
            glDepthFunc(GL_ALWAYS);
            quad(0, 20, dA, 255, 0, 0);      /* A: columns [0,20) */
            glDepthFunc(funcs[f]);
            quad(12, 32, dB, 0, 255, 0);     /* B: columns [12,32) */
            glGetIntegerv(GL_DEPTH_FUNC, &v);
            h_expect(v == (GLint)funcs[f], "GL_DEPTH_FUNC = 0x%x, expected %s", v, names[f]);
            h_expect_no_error(names[f]);
            snprintf(what, sizeof what, "%s, B at %.2f over A at 0.5: A only", names[f], dB);
            expect_cols(0, 12, red, dA, what);
            snprintf(what, sizeof what, "%s, B at %.2f over A at 0.5: overlap", names[f], dB);
            expect_cols(12, 20, pov ? green : red, pov ? dB : dA, what);
            snprintf(what, sizeof what, "%s, B at %.2f over cleared 1.0", names[f], dB);
            expect_cols(20, 32, pright ? green : black, pright ? dB : 1.0, what);
        }
    }

    /* glDepthRange. */
    setup(1.0);
    glDepthFunc(GL_ALWAYS);
    glDepthRange(0.25, 0.75);
    quad_ndc(0, 8, -1.0);
    quad_ndc(8, 16, 0.0);
    quad_ndc(16, 24, 1.0);
    quad_ndc(24, 32, 0.5);
    expect_cols(0, 8, white, 0.25, "glDepthRange(0.25,0.75), NDC z -1");
    expect_cols(8, 16, white, 0.5, "glDepthRange(0.25,0.75), NDC z 0");
    expect_cols(16, 24, white, 0.75, "glDepthRange(0.25,0.75), NDC z 1");
    expect_cols(24, 32, white, 0.625, "glDepthRange(0.25,0.75), NDC z 0.5");
    glGetFloatv(GL_DEPTH_RANGE, range);
    h_expect(range[0] == 0.25f && range[1] == 0.75f, "GL_DEPTH_RANGE = %g,%g, expected 0.25,0.75",
             range[0], range[1]);

    setup(1.0);
    glDepthRange(1.0, 0.0); /* reversed */
    quad_ndc(0, 16, -1.0);
    quad_ndc(16, 32, 0.5);
    expect_cols(0, 16, white, 1.0, "glDepthRange(1,0), NDC z -1");
    expect_cols(16, 32, white, 0.25, "glDepthRange(1,0), NDC z 0.5");

    glDepthRange(-1.0, 2.0); /* clamped to [0,1] */
    glGetFloatv(GL_DEPTH_RANGE, range);
    h_expect(range[0] == 0.0f && range[1] == 1.0f,
             "glDepthRange(-1,2): GL_DEPTH_RANGE = %g,%g, expected clamped 0,1", range[0], range[1]);
    setup(1.0);
    quad_ndc(0, 32, -1.0);
    expect_cols(0, 32, white, 0.0, "glDepthRange(-1,2) clamped, NDC z -1");
    glDepthRange(0.0, 1.0);

    /* The depth range also moves what the depth test sees. */
    setup(1.0);
    glDepthFunc(GL_LESS);
    glDepthRange(0.5, 1.0);
    quad(0, 32, 0.0, 255, 0, 0);  /* NDC z -1 -> window depth 0.5 */
    glDepthRange(0.0, 1.0);
    quad(0, 16, 0.4, 0, 255, 0);  /* 0.4 < 0.5: passes */
    quad(16, 32, 0.6, 0, 0, 255); /* 0.6 > 0.5: fails */
    expect_cols(0, 16, green, 0.4, "depth 0.4 drawn over depth 0.5 set through glDepthRange(0.5,1)");
    expect_cols(16, 32, red, 0.5, "depth 0.6 rejected by depth 0.5 set through glDepthRange(0.5,1)");

    /* glDepthMask(GL_FALSE): colour written, depth kept. */
    setup(1.0);
    glDepthFunc(GL_LESS);
    quad(0, 32, 0.5, 255, 0, 0);
    glDepthMask(GL_FALSE);
    quad(0, 16, 0.25, 0, 255, 0);
    expect_cols(0, 16, green, 0.5, "glDepthMask(GL_FALSE): colour drawn, depth stays 0.5");
    glDepthMask(GL_TRUE);
    quad(0, 32, 0.375, 0, 0, 255); /* passes everywhere iff depth stayed 0.5 */
    expect_cols(0, 32, blue, 0.375, "depth 0.375 after the masked draw passes everywhere");

    /* Depth test disabled: fragments always drawn, depth buffer untouched. */
    setup(1.0);
    glDepthFunc(GL_LESS);
    glDisable(GL_DEPTH_TEST);
    quad(0, 32, 0.25, 255, 0, 0);
    expect_cols(0, 32, red, 1.0, "GL_DEPTH_TEST disabled: drawn, depth not written");
    glEnable(GL_DEPTH_TEST);
    quad(0, 32, 0.75, 0, 255, 0); /* 0.75 < 1.0 passes */
    expect_cols(0, 32, green, 0.75, "after re-enabling the depth test");

    h_expect_no_error("end");
    return h_finish();
}
