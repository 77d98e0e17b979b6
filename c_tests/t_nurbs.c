/* t_nurbs: GLU NURBS surfaces drawn filled through an orthographic
 * projection of one unit per pixel, their covered pixels counted and
 * compared with the area of the shape (GLU 1.3 section 7):
 *   - a bicubic patch whose control points lie on a 80x60 grid in z = 0 (a
 *     B-spline reproduces linear functions, so the patch is that rectangle);
 *   - the same patch trimmed by an outer loop (gluPwlCurve) and a clockwise
 *     rational circle of radius 1/4 in (u, v) (a GLU_MAP1_TRIM_3 NURBS
 *     curve): the rectangle less an ellipse of semi-axes 20 and 15;
 *   - a rational biquadratic NURBS sphere of radius 40 seen along z, sampled
 *     with GLU_PATH_LENGTH at 2 pixels: a disk of radius 40;
 *   - errors reach the GLU_NURBS_ERROR callback and draw nothing.
 * Pixel counts may differ from the area by the pixels the boundary crosses.
 */
#include "harness.h"
#include <GL/glu.h>
#include <math.h>
#include <stdio.h>

#ifndef M_PI
#define M_PI 3.14159265358979323846
#endif

#define W 128
#define H 128

static unsigned char px[W * H * 4];
static GLenum errors[16];
static int nerrors;

static void GLAPIENTRY on_error(GLenum e)
{
    if (nerrors < 16)
        errors[nerrors] = e;
    nerrors++;
}

static int count(void)
{
    int i, n = 0;
    h_read(px);
    for (i = 0; i < W * H; i++)
        n += px[i * 4] == 255;
    return n;
}

static int covered(int x, int y)
{
    return px[(y * W + x) * 4] == 255;
}

static void expect_area(const char *what, double area, double perimeter)
{
    int n = count();
    double tol = 0.1 * perimeter + 4;
    h_expect(fabs(n - area) <= tol, "%s: %d pixels, area %.1f (tolerance %.1f)", what, n, area, tol);
}

static GLfloat grid[4][4][3];
static GLfloat bez[8] = {0, 0, 0, 0, 1, 1, 1, 1};

static void patch(GLUnurbs *nb)
{
    gluNurbsSurface(nb, 8, bez, 8, bez, 4 * 3, 3, &grid[0][0][0], 4, 4, GL_MAP2_VERTEX_3);
}

int main(void)
{
    GLUnurbs *nb;
    int i, j, n;
    const GLfloat s = (GLfloat)0.70710678118654752;
    GLfloat outer[5][2] = {{0, 0}, {1, 0}, {1, 1}, {0, 1}, {0, 0}};
    GLfloat cknots[12] = {0, 0, 0, 1, 1, 2, 2, 3, 3, 4, 4, 4};
    /* The unit circle, clockwise, as (x w, y w, w). */
    GLfloat cx[9] = {1, 1, 0, -1, -1, -1, 0, 1, 1}, cy[9] = {0, -1, -1, -1, 0, 1, 1, 1, 0};
    GLfloat cw[9] = {1, 0, 1, 0, 1, 0, 1, 0, 1};
    GLfloat trim[9][3], sphere[9][5][4];
    GLfloat pr[5] = {0, 1, 1, 1, 0}, pz[5] = {-1, -1, 0, 1, 1}, pw[5] = {1, 0, 1, 0, 1};
    GLfloat vknots[8] = {0, 0, 0, 1, 1, 2, 2, 2};
    GLfloat bad[4] = {0, 1, 0.5f, 1}, ctl[6] = {0};

    for (i = 0; i < 9; i++)
        if (cw[i] == 0) cw[i] = s;
    for (i = 0; i < 5; i++)
        if (pw[i] == 0) pw[i] = s;

    h_init(W, H);
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    glOrtho(-W / 2, W / 2, -H / 2, H / 2, -100, 100);
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
    glClearColor(0, 0, 0, 1);
    glColor3ub(255, 255, 255);

    nb = gluNewNurbsRenderer();
    h_expect(nb != NULL, "gluNewNurbsRenderer returned NULL");
    gluNurbsCallback(nb, GLU_NURBS_ERROR, (_GLUfuncptr)on_error);
    gluNurbsProperty(nb, GLU_SAMPLING_TOLERANCE, 2.0f);

    /* A flat bicubic patch over [-40, 40] x [-30, 30]. */
    for (i = 0; i < 4; i++)
        for (j = 0; j < 4; j++) {
            grid[i][j][0] = -40 + 80 * i / 3.0f;
            grid[i][j][1] = -30 + 60 * j / 3.0f;
            grid[i][j][2] = 0;
        }
    glClear(GL_COLOR_BUFFER_BIT);
    gluBeginSurface(nb);
    patch(nb);
    gluEndSurface(nb);
    h_expect_no_error("gluNurbsSurface");
    expect_area("flat patch 80x60", 80 * 60, 280);
    h_expect(covered(64 - 38, 64 - 28) && covered(64 + 38, 64 + 28) && !covered(64 + 42, 64) && !covered(64, 64 + 32),
             "flat patch: corners in, outside out");

    /* Trimmed: an outer loop and a clockwise circle of radius 1/4 at the centre. */
    for (i = 0; i < 9; i++) {
        trim[i][0] = (0.5f + 0.25f * cx[i]) * cw[i];
        trim[i][1] = (0.5f + 0.25f * cy[i]) * cw[i];
        trim[i][2] = cw[i];
    }
    glClear(GL_COLOR_BUFFER_BIT);
    gluBeginSurface(nb);
    patch(nb);
    gluBeginTrim(nb);
    gluPwlCurve(nb, 5, &outer[0][0], 2, GLU_MAP1_TRIM_2);
    gluEndTrim(nb);
    gluBeginTrim(nb);
    gluNurbsCurve(nb, 12, cknots, 3, &trim[0][0], 3, GLU_MAP1_TRIM_3);
    gluEndTrim(nb);
    gluEndSurface(nb);
    h_expect_no_error("trimmed surface");
    expect_area("patch less an ellipse 20x15", 80 * 60 - M_PI * 20 * 15, 280 + 2 * M_PI * 17.5);
    h_expect(!covered(64, 64) && !covered(64 + 18, 64) && covered(64 + 22, 64) && covered(64, 64 + 17),
             "trimmed patch: hole at the centre");

    /* A sphere of radius 40: circle (u) times half circle (v). */
    for (i = 0; i < 9; i++)
        for (j = 0; j < 5; j++) {
            GLfloat w = cw[i] * pw[j];
            sphere[i][j][0] = cx[i] * pr[j] * 40 * w;
            sphere[i][j][1] = cy[i] * pr[j] * 40 * w;
            sphere[i][j][2] = pz[j] * 40 * w;
            sphere[i][j][3] = w;
        }
    glClear(GL_COLOR_BUFFER_BIT);
    gluBeginSurface(nb);
    gluNurbsSurface(nb, 12, cknots, 8, vknots, 5 * 4, 4, &sphere[0][0][0], 3, 3, GL_MAP2_VERTEX_4);
    gluEndSurface(nb);
    h_expect_no_error("sphere");
    expect_area("sphere r=40", M_PI * 40 * 40, 2 * M_PI * 40);
    h_expect(nerrors == 0, "%d NURBS errors (first %u)", nerrors, nerrors ? errors[0] : 0);

    /* Errors: decreasing knots, gluEndCurve without gluBeginCurve. */
    glClear(GL_COLOR_BUFFER_BIT);
    gluBeginCurve(nb);
    gluNurbsCurve(nb, 4, bad, 3, ctl, 2, GL_MAP1_VERTEX_3);
    gluEndCurve(nb);
    gluEndCurve(nb);
    n = count();
    h_expect(nerrors == 2 && errors[0] == GLU_NURBS_ERROR4 && errors[1] == GLU_NURBS_ERROR7,
             "errors: %d reported (%u, %u), want GLU_NURBS_ERROR4, GLU_NURBS_ERROR7", nerrors, errors[0], errors[1]);
    h_expect(n == 0, "a curve with an error drew %d pixels", n);

    gluDeleteNurbsRenderer(nb);
    return h_finish();
}
