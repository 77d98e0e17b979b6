/* t_quadric: GLU quadrics drawn filled through an orthographic projection of
 * one unit per pixel, their covered pixels counted and compared with the area
 * of the polygonal shape GLU builds (GLU 1.3 section 6, the gluSphere,
 * gluCylinder, gluDisk and gluPartialDisk man pages), plus inside/outside
 * pixels:
 *   - a sphere seen along z covers the regular polygon of its equator;
 *   - a disk with a hole, an annulus; a partial disk, the sector from its
 *     start angle (0 along +y, 90 along +x) through start + sweep;
 *   - a cylinder seen from the side (z turned to window y), a rectangle;
 *     a cone from the side, a triangle; a cone along z, a polygon;
 *   - a disk is front-facing from +z for GLU_OUTSIDE and back-facing for
 *     GLU_INSIDE (checked with face culling);
 *   - bad values and enums reach the GLU_ERROR callback and draw nothing.
 * Pixel counts may differ from the area by the pixels the boundary crosses;
 * the tolerance is a fraction of the perimeter.
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
#define CX 64
#define CY 64

static unsigned char px[W * H * 4];
static GLenum errors[16];
static int nerrors;

static void GLAPIENTRY on_error(GLenum e)
{
    if (nerrors < 16)
        errors[nerrors] = e;
    nerrors++;
}

static int covered(int x, int y)
{
    const unsigned char *p = &px[(y * W + x) * 4];
    return p[0] == 255 && p[1] == 255 && p[2] == 255;
}

static int count(void)
{
    int i, n = 0;
    h_read(px);
    for (i = 0; i < W * H; i++)
        n += px[i * 4] == 255;
    return n;
}

static void start(void)
{
    glClear(GL_COLOR_BUFFER_BIT);
    glLoadIdentity();
}

static void expect_area(const char *what, double area, double perimeter)
{
    int n = count();
    double tol = 0.05 * perimeter + 4;
    h_expect(fabs(n - area) <= tol, "%s: %d pixels, polygon area %.1f (tolerance %.1f)", what, n, area, tol);
}

/* (dx, dy) from the centre covered or not. */
static void expect_at(const char *what, int dx, int dy, int want)
{
    h_expect(covered(CX + dx, CY + dy) == want, "%s: pixel (%+d,%+d) from the centre should be %s",
             what, dx, dy, want ? "covered" : "empty");
}

static double polygon_area(int n, double r)
{
    return n / 2.0 * r * r * sin(2 * M_PI / n);
}

int main(void)
{
    GLUquadric *q;
    int n;

    h_init(W, H);
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    glOrtho(-W / 2, W / 2, -H / 2, H / 2, -100, 100);
    glMatrixMode(GL_MODELVIEW);
    glClearColor(0, 0, 0, 1);
    glColor3ub(255, 255, 255);

    q = gluNewQuadric();
    h_expect(q != NULL, "gluNewQuadric returned NULL");
    gluQuadricCallback(q, GLU_ERROR, (_GLUfuncptr)on_error);

    /* Sphere along z: the equator's 64-gon (32 stacks: the equator is a row). */
    start();
    gluSphere(q, 40, 64, 32);
    h_expect_no_error("gluSphere");
    expect_area("sphere r=40 64x32", polygon_area(64, 40), 2 * M_PI * 40);
    expect_at("sphere", 0, 0, 1);
    expect_at("sphere", 38, 0, 1);
    expect_at("sphere", 0, -38, 1);
    expect_at("sphere", 42, 0, 0);
    expect_at("sphere", 29, 29, 0);

    /* Sphere turned on its side (z to window y): still a disk. */
    start();
    glRotatef(-90, 1, 0, 0);
    gluQuadricNormals(q, GLU_FLAT);
    gluQuadricTexture(q, GL_TRUE);
    gluSphere(q, 30, 48, 24);
    h_expect_no_error("gluSphere on its side");
    n = count();
    h_expect(n > polygon_area(24, 30) * 0.97 && n < M_PI * 30 * 30 + 20, "sphere r=30 on its side: %d pixels", n);
    gluQuadricNormals(q, GLU_SMOOTH);
    gluQuadricTexture(q, GL_FALSE);

    /* Disk with a hole. */
    start();
    gluDisk(q, 15, 40, 64, 3);
    h_expect_no_error("gluDisk");
    expect_area("disk 15..40", polygon_area(64, 40) - polygon_area(64, 15), 2 * M_PI * 55);
    expect_at("disk", 0, 0, 0);
    expect_at("disk", 10, 0, 0);
    expect_at("disk", 27, 0, 1);
    expect_at("disk", -19, -19, 1);
    expect_at("disk", 0, 43, 0);

    /* Partial disk: 0..90 degrees is the quadrant from +y to +x. */
    start();
    gluPartialDisk(q, 10, 40, 32, 2, 0, 90);
    h_expect_no_error("gluPartialDisk");
    expect_area("partial disk 10..40, 0+90", 16.0 * (1600 - 100) * sin(M_PI / 2 / 32), M_PI / 2 * 50 + 60);
    expect_at("partial disk 0+90", 20, 20, 1);
    expect_at("partial disk 0+90", -20, 20, 0);
    expect_at("partial disk 0+90", 20, -20, 0);
    expect_at("partial disk 0+90", -20, -20, 0);
    expect_at("partial disk 0+90", 3, 3, 0);

    /* 180+90: from -y to -x, the third quadrant; a negative sweep alike. */
    start();
    gluPartialDisk(q, 0, 40, 32, 2, 180, 90);
    n = count();
    expect_at("partial disk 180+90", -20, -20, 1);
    expect_at("partial disk 180+90", 20, 20, 0);
    expect_at("partial disk 180+90", -20, 20, 0);
    start();
    gluPartialDisk(q, 0, 40, 32, 2, 270, -90);
    h_expect(count() == n, "gluPartialDisk 270-90 covers what 180+90 does (%d pixels)", n);
    expect_at("partial disk 270-90", -20, -20, 1);

    /* 90+180: from +x through -y to -x, the lower half. */
    start();
    gluPartialDisk(q, 0, 40, 64, 1, 90, 180);
    expect_area("partial disk 90+180", 32 * 1600 * sin(M_PI / 64), M_PI * 40 + 80);
    expect_at("partial disk 90+180", 0, -20, 1);
    expect_at("partial disk 90+180", 0, 20, 0);

    /* Cylinder from the side: z (0..60) to window y, a 60x60 rectangle. */
    start();
    glTranslatef(0, -30, 0);
    glRotatef(-90, 1, 0, 0);
    gluCylinder(q, 30, 30, 60, 64, 4);
    h_expect_no_error("gluCylinder");
    expect_area("cylinder r=30 h=60 from the side", 60 * 60, 240);
    expect_at("cylinder", 0, 0, 1);
    expect_at("cylinder", 28, 28, 1);
    expect_at("cylinder", -28, -28, 1);
    expect_at("cylinder", 32, 0, 0);
    expect_at("cylinder", 0, 32, 0);

    /* Cone from the side: a triangle, apex at the top. */
    start();
    glTranslatef(0, -30, 0);
    glRotatef(-90, 1, 0, 0);
    gluCylinder(q, 30, 0, 60, 64, 3);
    expect_area("cone from the side", 30 * 60, 60 + 2 * sqrt(30 * 30 + 60 * 60));
    expect_at("cone", 0, 25, 1);
    expect_at("cone", 20, 20, 0);
    expect_at("cone", -25, -25, 1);

    /* Cone along z: the base's 64-gon. */
    start();
    gluCylinder(q, 30, 0, 60, 64, 3);
    expect_area("cone along z", polygon_area(64, 30), 2 * M_PI * 30);

    /* Orientation: a disk faces +z for GLU_OUTSIDE, -z for GLU_INSIDE. */
    glEnable(GL_CULL_FACE);
    start();
    gluDisk(q, 0, 40, 32, 2);
    h_expect(count() > 4000, "GLU_OUTSIDE disk is front-facing from +z");
    start();
    gluQuadricOrientation(q, GLU_INSIDE);
    gluDisk(q, 0, 40, 32, 2);
    h_expect(count() == 0, "GLU_INSIDE disk is back-facing from +z");
    start();
    gluSphere(q, 40, 32, 16); /* inside: the far hemisphere's inner side */
    expect_area("GLU_INSIDE sphere, culled", polygon_area(32, 40), 2 * M_PI * 40);
    gluQuadricOrientation(q, GLU_OUTSIDE);
    glDisable(GL_CULL_FACE);

    /* The line and point styles go through GL without errors (GL does not
     * rasterize lines and points yet, so their pixels are not checked). */
    {
        static const GLenum styles[] = {GLU_LINE, GLU_SILHOUETTE, GLU_POINT};
        unsigned k;
        for (k = 0; k < 3; k++) {
            gluQuadricDrawStyle(q, styles[k]);
            gluSphere(q, 20, 12, 6);
            gluCylinder(q, 20, 5, 30, 12, 3);
            gluDisk(q, 5, 20, 12, 2);
            gluPartialDisk(q, 0, 20, 12, 2, 45, 200);
            h_expect_no_error("line and point styles");
        }
        gluQuadricDrawStyle(q, GLU_FILL);
    }

    /* Errors reach the callback and draw nothing. */
    start();
    nerrors = 0;
    gluSphere(q, -1, 16, 16);
    gluSphere(q, 10, 1, 16);
    gluCylinder(q, 10, 10, 10, 16, 0);
    gluDisk(q, 20, 10, 16, 1);
    gluPartialDisk(q, -1, 10, 16, 1, 0, 90);
    h_expect(nerrors == 5, "%d errors reported, expected 5", nerrors);
    for (n = 0; n < 5 && n < nerrors; n++)
        h_expect(errors[n] == GLU_INVALID_VALUE, "error %d is %u, not GLU_INVALID_VALUE", n, errors[n]);
    h_expect(count() == 0, "nothing drawn on error");
    nerrors = 0;
    gluQuadricDrawStyle(q, GL_TRIANGLES);
    gluQuadricNormals(q, GLU_FILL);
    gluQuadricOrientation(q, GLU_SMOOTH);
    h_expect(nerrors == 3 && errors[0] == GLU_INVALID_ENUM && errors[2] == GLU_INVALID_ENUM,
             "bad enums: %d errors, first %u", nerrors, errors[0]);
    gluSphere(q, 20, 16, 8);
    h_expect(count() > 1000, "the draw style stays GLU_FILL after a bad enum");
    h_expect_no_error("errors");

    gluDeleteQuadric(q);
    return h_finish();
}
