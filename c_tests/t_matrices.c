/* t_matrices: the vertex transformation (GL 1.5 sections 2.10, 2.11).
 *
 * - window = viewport(project(P * M * v)): glOrtho, glFrustum, glViewport;
 * - glTranslate/glRotate/glScale/glMultMatrix multiply the current matrix on
 *   the RIGHT (M := M * T), so the last call applies to vertices first;
 *   glRotate normalises its axis and rotates counter-clockwise;
 * - glLoadMatrix/glMultMatrix/glGet(GL_MODELVIEW_MATRIX) are column-major
 *   (translation in elements 12, 13, 14);
 * - glPushMatrix/glPopMatrix per matrix mode; popping a depth-1 stack gives
 *   GL_STACK_UNDERFLOW, pushing a full one GL_STACK_OVERFLOW, and neither
 *   changes the matrix; glMatrixMode(bad) gives GL_INVALID_ENUM;
 *   glOrtho with l == r and glFrustum with near <= 0 give GL_INVALID_VALUE.
 * Checked by where small quads land: the exact set of covered pixels (all
 * quad edges land on integer window coordinates, which pixel centres are
 * 0.5 away from, so rounding in the transform cannot change the set).
 */
#include "harness.h"
#include <math.h>
#include <stdio.h>
#include <string.h>

#define W 64
#define H 64

struct rect { int x0, y0, x1, y1; };

static unsigned char px[W * H * 4];

static void quad(double x0, double y0, double x1, double y1, double z)
{
    glBegin(GL_QUADS);
    glVertex3d(x0, y0, z);
    glVertex3d(x1, y0, z);
    glVertex3d(x1, y1, z);
    glVertex3d(x0, y1, z);
    glEnd();
}

/* Exactly the pixels of the n rectangles must be white. */
static void expect_rects(int n, const struct rect *r, const char *what)
{
    int x, y, i, wrong = 0, fx = -1, fy = -1, want_n = 0, got_n = 0;
    h_read(px);
    for (y = 0; y < H; y++)
        for (x = 0; x < W; x++) {
            int want = 0, got = px[(y * W + x) * 4 + 1] > 127;
            for (i = 0; i < n; i++)
                if (x >= r[i].x0 && x < r[i].x1 && y >= r[i].y0 && y < r[i].y1)
                    want = 1;
            want_n += want;
            got_n += got;
            if (want != got && wrong++ == 0) {
                fx = x;
                fy = y;
            }
        }
    h_expect(wrong == 0, "%s: %d pixels wrong (expected %d covered, got %d; first wrong pixel (%d,%d))",
             what, wrong, want_n, got_n, fx, fy);
}

static void expect_rect(int x0, int y0, int x1, int y1, const char *what)
{
    struct rect r;
    r.x0 = x0; r.y0 = y0; r.x1 = x1; r.y1 = y1;
    expect_rects(1, &r, what);
}

static void reset(void)
{
    glViewport(0, 0, W, H);
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    glOrtho(0, W, 0, H, -1, 1);
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
    glClear(GL_COLOR_BUFFER_BIT);
}

static void get_mv(GLfloat m[16]) { glGetFloatv(GL_MODELVIEW_MATRIX, m); }

int main(void)
{
    GLint depth, mode, maxdepth, vp[4];
    GLfloat m[16], m2[16];
    int i;

    h_init(W, H);
    glClearColor(0, 0, 0, 1);
    glColor3ub(255, 255, 255);

    /* Initial state: viewport = window, identity matrices, depth-1 stacks. */
    glGetIntegerv(GL_VIEWPORT, vp);
    h_expect(vp[0] == 0 && vp[1] == 0 && vp[2] == W && vp[3] == H,
             "initial viewport %d,%d,%d,%d, expected 0,0,%d,%d", vp[0], vp[1], vp[2], vp[3], W, H);
    glGetIntegerv(GL_MATRIX_MODE, &mode);
    h_expect(mode == GL_MODELVIEW, "initial GL_MATRIX_MODE 0x%x, expected GL_MODELVIEW", mode);
    get_mv(m);
    for (i = 0; i < 16; i++)
        h_expect(m[i] == (i % 5 == 0 ? 1.0f : 0.0f), "initial modelview[%d] = %g", i, m[i]);

    /* Identity everything: the quad [-0.5,0.5]^2 in NDC is the centre half. */
    glClear(GL_COLOR_BUFFER_BIT);
    quad(-0.5, -0.5, 0.5, 0.5, 0);
    expect_rect(16, 16, 48, 48, "identity matrices, NDC quad [-0.5,0.5]");

    reset();
    quad(10, 20, 14, 24, 0);
    expect_rect(10, 20, 14, 24, "glOrtho(0,64,0,64): quad [10,14)x[20,24)");

    reset();
    glTranslatef(32, 32, 0);
    glScalef(8, 4, 1);
    quad(-1, -1, 1, 1, 0);
    expect_rect(24, 28, 40, 36, "glTranslate(32,32) glScale(8,4): unit quad");

    reset();
    glTranslatef(32, 32, 0);
    glRotatef(90, 0, 0, 5); /* axis is normalised */
    quad(4, -2, 12, 2, 0);
    expect_rect(30, 36, 34, 44, "glRotate(90, 0,0,5) is counter-clockwise");

    reset();
    glTranslatef(32, 32, 0);
    glRotatef(180, 1, 0, 0);
    quad(0, 2, 8, 10, 0);
    expect_rect(32, 22, 40, 30, "glRotate(180, 1,0,0) flips y");

    reset();
    glTranslatef(32, 32, 0);
    glRotatef(90, 0, 0, 1);
    glTranslatef(10, 0, 0); /* applied first: moves along the rotated x axis, i.e. up */
    quad(-2, -2, 2, 2, 0);
    expect_rect(30, 40, 34, 44, "translate, rotate 90, translate(10,0): order of composition");

    /* Push/pop. */
    reset();
    glTranslatef(10, 10, 0);
    glPushMatrix();
    glGetIntegerv(GL_MODELVIEW_STACK_DEPTH, &depth);
    h_expect(depth == 2, "GL_MODELVIEW_STACK_DEPTH after push = %d, expected 2", depth);
    glTranslatef(20, 0, 0);
    quad(0, 0, 4, 4, 0);
    glPopMatrix();
    glGetIntegerv(GL_MODELVIEW_STACK_DEPTH, &depth);
    h_expect(depth == 1, "GL_MODELVIEW_STACK_DEPTH after pop = %d, expected 1", depth);
    quad(0, 0, 4, 4, 0);
    {
        struct rect r[2] = {{30, 10, 34, 14}, {10, 10, 14, 14}};
        expect_rects(2, r, "glPushMatrix/glTranslate/glPopMatrix");
    }

    /* Column-major glLoadMatrix. */
    reset();
    memset(m, 0, sizeof m);
    m[0] = m[5] = m[10] = m[15] = 1;
    m[12] = 20;
    m[13] = 30;
    glLoadMatrixf(m);
    quad(0, 0, 4, 4, 0);
    expect_rect(20, 30, 24, 34, "glLoadMatrixf with translation in m[12], m[13]");
    get_mv(m2);
    h_expect(memcmp(m, m2, sizeof m) == 0, "glGetFloatv(GL_MODELVIEW_MATRIX) differs from the loaded matrix");

    /* glMultMatrix multiplies on the right: T(8,8) * S(2) maps p to 8 + 2p. */
    reset();
    glTranslatef(8, 8, 0);
    memset(m, 0, sizeof m);
    m[0] = m[5] = 2;
    m[10] = m[15] = 1;
    glMultMatrixf(m);
    quad(0, 0, 4, 4, 0);
    expect_rect(8, 8, 16, 16, "glTranslate(8,8) then glMultMatrix(scale 2)");

    /* A shear x' = x + 0.5 y: column 1, row 0 is element 4. */
    reset();
    glTranslatef(8, 8, 0);
    memset(m, 0, sizeof m);
    m[0] = m[5] = m[10] = m[15] = 1;
    m[4] = 0.5f;
    glMultMatrixf(m);
    quad(0, 0, 8, 16, 0);
    /* row y=8 (object y 0.5): x in [8.25, 16.25] -> pixels 8..15 */
    h_expect_pixel(8, 8, 255, 255, 255, 255, 0, "shear, row 8, first pixel");
    h_expect_pixel(15, 8, 255, 255, 255, 255, 0, "shear, row 8, last pixel");
    h_expect_pixel(16, 8, 0, 0, 0, 255, 0, "shear, row 8, right of the quad");
    /* row y=15 (object y 7.5): x in [11.75, 19.75] -> pixels 12..19 */
    h_expect_pixel(11, 15, 0, 0, 0, 255, 0, "shear, row 15, left of the quad");
    h_expect_pixel(12, 15, 255, 255, 255, 255, 0, "shear, row 15, first pixel");
    h_expect_pixel(19, 15, 255, 255, 255, 255, 0, "shear, row 15, last pixel");
    h_expect_pixel(20, 15, 0, 0, 0, 255, 0, "shear, row 15, right of the quad");

    /* glFrustum: x_ndc = x_eye * n / -z_eye for a symmetric unit frustum. */
    reset();
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    glFrustum(-1, 1, -1, 1, 1, 10);
    glMatrixMode(GL_MODELVIEW);
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_ALWAYS);
    glClear(GL_DEPTH_BUFFER_BIT);
    quad(-1, -1, 1, 1, -2);  /* NDC [-0.5,0.5] */
    expect_rect(16, 16, 48, 48, "glFrustum(-1,1,-1,1,1,10): quad at z=-2");
    {
        /* z_ndc = (f+n)/(f-n) + 2fn/((f-n) z_eye) = 11/9 - 10/9 = 1/9 -> depth 5/9 */
        float d;
        glReadPixels(32, 32, 1, 1, GL_DEPTH_COMPONENT, GL_FLOAT, &d);
        h_expect(fabs(d - 5.0 / 9.0) <= 1.0 / 65536, "glFrustum depth at z_eye=-2 is %g, expected 5/9", d);
    }
    glClear(GL_COLOR_BUFFER_BIT);
    quad(-2, 0, 0, 2, -4);   /* NDC x [-0.5,0], y [0,0.5] */
    expect_rect(16, 32, 32, 48, "glFrustum: quad at z=-4");
    glDisable(GL_DEPTH_TEST);

    /* glViewport maps NDC [-1,1] onto the viewport rectangle. */
    reset();
    glViewport(16, 8, 32, 16);
    glGetIntegerv(GL_VIEWPORT, vp);
    h_expect(vp[0] == 16 && vp[1] == 8 && vp[2] == 32 && vp[3] == 16,
             "GL_VIEWPORT = %d,%d,%d,%d, expected 16,8,32,16", vp[0], vp[1], vp[2], vp[3]);
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    glOrtho(0, 1, 0, 1, -1, 1);
    glMatrixMode(GL_MODELVIEW);
    quad(0, 0, 1, 1, 0);
    expect_rect(16, 8, 48, 24, "glViewport(16,8,32,16): full quad");
    glClear(GL_COLOR_BUFFER_BIT);
    quad(0.5, 0.5, 1, 1, 0);
    expect_rect(32, 16, 48, 24, "glViewport(16,8,32,16): upper-right quarter");
    /* Geometry outside the viewport but inside the window is clipped. */
    glClear(GL_COLOR_BUFFER_BIT);
    quad(-1, 0, 2, 1, 0);
    expect_rect(16, 8, 48, 24, "glViewport: a quad wider than the view volume is clipped to the viewport");

    /* Projection stack is separate from the modelview stack. */
    reset();
    glMatrixMode(GL_PROJECTION);
    glPushMatrix();
    glGetIntegerv(GL_PROJECTION_STACK_DEPTH, &depth);
    h_expect(depth == 2, "GL_PROJECTION_STACK_DEPTH after push = %d, expected 2", depth);
    glGetIntegerv(GL_MODELVIEW_STACK_DEPTH, &depth);
    h_expect(depth == 1, "GL_MODELVIEW_STACK_DEPTH after projection push = %d, expected 1", depth);
    glLoadIdentity();
    glPopMatrix();
    glMatrixMode(GL_MODELVIEW);
    quad(10, 20, 14, 24, 0);
    expect_rect(10, 20, 14, 24, "projection restored by glPopMatrix");
    h_expect_no_error("transforms");

    /* Errors. */
    reset();
    glTranslatef(3, 4, 0);
    get_mv(m);
    glPopMatrix();
    h_expect_error(GL_STACK_UNDERFLOW, "glPopMatrix on a depth-1 modelview stack");
    get_mv(m2);
    h_expect(memcmp(m, m2, sizeof m) == 0, "failed glPopMatrix changed the modelview matrix");
    glMatrixMode(GL_PROJECTION);
    glPopMatrix();
    h_expect_error(GL_STACK_UNDERFLOW, "glPopMatrix on a depth-1 projection stack");
    glMatrixMode(GL_MODELVIEW);

    glGetIntegerv(GL_MAX_MODELVIEW_STACK_DEPTH, &maxdepth);
    h_expect(maxdepth >= 32, "GL_MAX_MODELVIEW_STACK_DEPTH = %d, at least 32 required", maxdepth);
    for (i = 1; i < maxdepth; i++)
        glPushMatrix();
    h_expect_no_error("pushing to the maximum depth");
    glPushMatrix();
    h_expect_error(GL_STACK_OVERFLOW, "glPushMatrix on a full modelview stack");
    glGetIntegerv(GL_MODELVIEW_STACK_DEPTH, &depth);
    h_expect(depth == maxdepth, "stack depth after overflow = %d, expected %d", depth, maxdepth);
    for (i = 1; i < maxdepth; i++)
        glPopMatrix();
    h_expect_no_error("popping back to depth 1");

    glMatrixMode(GL_PROJECTION);
    glMatrixMode(0x1234);
    h_expect_error(GL_INVALID_ENUM, "glMatrixMode(0x1234)");
    glGetIntegerv(GL_MATRIX_MODE, &mode);
    h_expect(mode == GL_PROJECTION, "GL_MATRIX_MODE after a bad glMatrixMode = 0x%x, expected GL_PROJECTION", mode);
    glMatrixMode(GL_MODELVIEW);

    glLoadIdentity();
    glOrtho(1, 1, 0, 1, -1, 1);
    h_expect_error(GL_INVALID_VALUE, "glOrtho with left == right");
    glFrustum(-1, 1, -1, 1, 0, 10);
    h_expect_error(GL_INVALID_VALUE, "glFrustum with near = 0");
    get_mv(m);
    for (i = 0; i < 16; i++)
        h_expect(m[i] == (i % 5 == 0 ? 1.0f : 0.0f), "modelview[%d] = %g after rejected glOrtho/glFrustum", i, m[i]);

    return h_finish();
}
