/* t_tess: the GLU tessellator (GLU 1.3 chapter 5) drawing through GL.
 *
 * 1. A pentagram (one self-intersecting contour, radius R about the centre)
 *    with a small square contour at its centre, GLU_TESS_WINDING_ODD:
 *    the five tips have winding 1 (drawn), the inner pentagon winding 2
 *    (not drawn), the square inside it winding 3 (drawn).  The pentagram
 *    crosses itself five times, so COMBINE is called five times.
 *    Covered area = area(10-gon of tips and inner corners) - area(inner
 *    pentagon) + area(square); the inner corners lie at radius
 *    R cos(72 deg) / cos(36 deg).
 * 2. A bow-tie (16,16) (112,112) (112,16) (16,112): one crossing at
 *    (64,64), COMBINE once; its left lobe winds +1, its right lobe -1.
 *    NONZERO draws both lobes (area 2 * 2304), POSITIVE the left only.
 * Pixel counts must match the analytic areas within half the perimeter
 * (pixel centres on the boundary), and probes well inside/outside must be
 * exactly the drawing/background colour.  Only filled output is checked.
 */
#include "harness.h"
#include <GL/glu.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>

#define W 128
#define H 128

#ifndef CALLBACK
#define CALLBACK GLAPIENTRY
#endif

static unsigned char px[W * H * 4];
static int combines, errors;
static double *allocated[64];
static int nallocated;

static void CALLBACK cb_vertex(void *d) { glVertex3dv((const GLdouble *)d); }
static void CALLBACK cb_begin(GLenum m) { glBegin(m); }
static void CALLBACK cb_end(void) { glEnd(); }
static void CALLBACK cb_error(GLenum e)
{
    errors++;
    fprintf(stderr, "tess error %u\n", (unsigned)e);
}
static void CALLBACK cb_combine(GLdouble c[3], void *d[4], GLfloat w[4], void **out)
{
    double *v = malloc(3 * sizeof *v);
    (void)d;
    (void)w;
    h_expect(*out == NULL, "*outData is NULL before COMBINE");
    v[0] = c[0];
    v[1] = c[1];
    v[2] = c[2];
    if (nallocated < 64)
        allocated[nallocated++] = v;
    combines++;
    *out = v;
}

static int count_red(void)
{
    int i, n = 0;
    h_read(px);
    for (i = 0; i < W * H; i++)
        n += px[4 * i] == 255 && px[4 * i + 1] == 0 && px[4 * i + 2] == 0;
    return n;
}

static double shoelace(const double (*p)[3], int n)
{
    double a = 0;
    int i;
    for (i = 0; i < n; i++)
        a += p[i][0] * p[(i + 1) % n][1] - p[(i + 1) % n][0] * p[i][1];
    return 0.5 * fabs(a);
}

static GLUtesselator *new_tess(GLenum rule)
{
    GLUtesselator *t = gluNewTess();
    gluTessCallback(t, GLU_TESS_BEGIN, (_GLUfuncptr)cb_begin);
    gluTessCallback(t, GLU_TESS_VERTEX, (_GLUfuncptr)cb_vertex);
    gluTessCallback(t, GLU_TESS_END, (_GLUfuncptr)cb_end);
    gluTessCallback(t, GLU_TESS_ERROR, (_GLUfuncptr)cb_error);
    gluTessCallback(t, GLU_TESS_COMBINE, (_GLUfuncptr)cb_combine);
    gluTessProperty(t, GLU_TESS_WINDING_RULE, rule);
    return t;
}

static void clear(void)
{
    glClearColor(0, 0, 0, 1);
    glClear(GL_COLOR_BUFFER_BIT);
    glColor3ub(255, 0, 0);
}

int main(void)
{
    const double PI = 3.14159265358979323846, R = 60, C = 64, S = 6;
    double star[5][3], tips[10][3], inner[5][3];
    double sq[4][3] = {{C - S, C - S, 0}, {C + S, C - S, 0}, {C + S, C + S, 0}, {C - S, C + S, 0}};
    double bow[4][3] = {{16, 16, 0}, {112, 112, 0}, {112, 16, 0}, {16, 112, 0}};
    double r_in = R * cos(2 * PI / 5) / cos(PI / 5), area, perim;
    int i, n;
    GLUtesselator *t;

    h_init(W, H);
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    glOrtho(0, W, 0, H, -1, 1);
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();

    /* 1. pentagram + square, ODD */
    for (i = 0; i < 5; i++) {
        double a = PI / 2 + i * 4 * PI / 5; /* every second point of the pentagon */
        double b = PI / 2 + i * 2 * PI / 5, bi = b + PI / 5;
        star[i][0] = C + R * cos(a), star[i][1] = C + R * sin(a), star[i][2] = 0;
        tips[2 * i][0] = C + R * cos(b), tips[2 * i][1] = C + R * sin(b), tips[2 * i][2] = 0;
        tips[2 * i + 1][0] = C + r_in * cos(bi), tips[2 * i + 1][1] = C + r_in * sin(bi), tips[2 * i + 1][2] = 0;
        inner[i][0] = tips[2 * i + 1][0], inner[i][1] = tips[2 * i + 1][1], inner[i][2] = 0;
    }
    clear();
    t = new_tess(GLU_TESS_WINDING_ODD);
    gluTessBeginPolygon(t, NULL);
    gluTessBeginContour(t);
    for (i = 0; i < 5; i++)
        gluTessVertex(t, star[i], star[i]);
    gluTessEndContour(t);
    gluTessBeginContour(t);
    for (i = 0; i < 4; i++)
        gluTessVertex(t, sq[i], sq[i]);
    gluTessEndContour(t);
    gluTessEndPolygon(t);
    h_expect_no_error("star");
    h_expect(combines == 5, "pentagram: %d COMBINE calls, expected 5", combines);
    h_expect(errors == 0, "star: %d tessellator errors", errors);
    area = shoelace(tips, 10) - shoelace(inner, 5) + 4 * S * S;
    perim = 10 * hypot(tips[0][0] - tips[1][0], tips[0][1] - tips[1][1]) + 5 * hypot(inner[0][0] - inner[1][0], inner[0][1] - inner[1][1]) + 8 * S;
    n = count_red();
    h_expect(fabs(n - area) <= perim / 2, "star ODD: %d pixels, expected %.1f +- %.1f", n, area, perim / 2);
    h_expect_pixel((int)C, (int)C, 255, 0, 0, 255, 0, "square at the centre (winding 3)");
    h_expect_pixel((int)C, (int)(C + 12), 0, 0, 0, 255, 0, "inner pentagon (winding 2)");
    h_expect_pixel((int)C, (int)(C + 45), 255, 0, 0, 255, 0, "top tip (winding 1)");
    h_expect_pixel(2, 2, 0, 0, 0, 255, 0, "outside");
    h_save("t_tess_star");
    gluDeleteTess(t);

    /* 2. bow-tie, NONZERO then POSITIVE */
    combines = 0;
    clear();
    t = new_tess(GLU_TESS_WINDING_NONZERO);
    gluTessBeginPolygon(t, NULL);
    gluTessBeginContour(t);
    for (i = 0; i < 4; i++)
        gluTessVertex(t, bow[i], bow[i]);
    gluTessEndContour(t);
    gluTessEndPolygon(t);
    h_expect(combines == 1, "bow-tie: %d COMBINE calls, expected 1", combines);
    n = count_red();
    perim = 2 * (96 + 2 * hypot(48, 48));
    h_expect(fabs(n - 4608) <= perim / 2, "bow-tie NONZERO: %d pixels, expected 4608 +- %.1f", n, perim / 2);
    h_expect_pixel(30, 64, 255, 0, 0, 255, 0, "left lobe");
    h_expect_pixel(98, 64, 255, 0, 0, 255, 0, "right lobe");
    h_expect_pixel(64, 30, 0, 0, 0, 255, 0, "below the crossing");
    h_expect_pixel(64, 98, 0, 0, 0, 255, 0, "above the crossing");
    h_save("t_tess_bowtie");

    clear();
    gluTessProperty(t, GLU_TESS_WINDING_RULE, GLU_TESS_WINDING_POSITIVE);
    gluTessBeginPolygon(t, NULL);
    gluTessBeginContour(t);
    for (i = 0; i < 4; i++)
        gluTessVertex(t, bow[i], bow[i]);
    gluTessEndContour(t);
    gluTessEndPolygon(t);
    n = count_red();
    h_expect(fabs(n - 2304) <= perim / 4, "bow-tie POSITIVE: %d pixels, expected 2304 +- %.1f", n, perim / 4);
    h_expect_pixel(30, 64, 255, 0, 0, 255, 0, "left lobe (winding +1)");
    h_expect_pixel(98, 64, 0, 0, 0, 255, 0, "right lobe (winding -1)");
    h_expect(errors == 0, "bow-tie: %d tessellator errors", errors);
    h_expect_no_error("bow-tie");
    gluDeleteTess(t);

    for (i = 0; i < nallocated; i++)
        free(allocated[i]);
    return h_finish();
}
