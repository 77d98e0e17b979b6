/* t_smooth: antialiasing by coverage (GL 1.5 sections 3.2, 3.3, 3.4.2,
 * 3.5.3): GL_POINT_SMOOTH, GL_LINE_SMOOTH and GL_POLYGON_SMOOTH multiply
 * the fragment's alpha by the area of the pixel square the ideal shape
 * covers.  Blending is off, so the stored alpha is 255 * coverage and the
 * checks compare it with areas this test computes independently (fine
 * midpoint integration), within 1 LSB plus the integration error:
 *  - a smooth point of size 4 centred on a pixel centre: every pixel's
 *    coverage of the disc, the total = pi r^2; point fade and attenuation;
 *  - a smooth horizontal line of width 3 at y = 10.25: row coverages
 *    1/4, 1, 1, 3/4 exactly; a diagonal line's total = length * width;
 *    stipple cutting the line into 1 x width rectangles, its counter
 *    continued across a strip;
 *  - a smooth triangle with an edge of slope 2/3: every pixel's coverage;
 *  - GL_FASTEST: coverages are multiples of 1/16 near the exact ones;
 *  - glBlendFunc(GL_SRC_ALPHA_SATURATE, GL_ONE), front to back: a smooth
 *    quad over a bigger one; the quad's diagonal adds up to full;
 *  - the smooth size ranges and granularities.
 */
#include "harness.h"
#include <math.h>
#include <stdio.h>
#include <stdlib.h>

#ifndef M_PI
#define M_PI 3.14159265358979323846
#endif

#define W 32
#define H 32
#define N 200 /* integration steps per pixel side */

static unsigned char px[W * H * 4];

static int alpha(int x, int y) { return px[(y * W + x) * 4 + 3]; }

typedef int (*inside_fn)(double x, double y);

/* Area of the shape in pixel (x, y) by an N x N midpoint grid. */
static double area(inside_fn in, int x, int y)
{
    int i, j, n = 0;
    for (j = 0; j < N; j++)
        for (i = 0; i < N; i++) n += in(x + (i + 0.5) / N, y + (j + 0.5) / N);
    return (double)n / (N * N);
}

/* Every pixel's alpha against 255 * area within tol; returns the total
 * coverage read back. */
static double check_all(inside_fn in, int tol, const char *what)
{
    int x, y, bad = 0;
    double total = 0;
    h_read(px);
    for (y = 0; y < H; y++)
        for (x = 0; x < W; x++) {
            double a = area(in, x, y);
            int want = (int)floor(255 * a + 0.5);
            total += alpha(x, y) / 255.0;
            if (abs(alpha(x, y) - want) > tol) {
                if (bad++ < 5)
                    h_expect(0, "%s: pixel %d,%d alpha %d, expected %d (area %.4f)", what, x, y, alpha(x, y), want, a);
            }
        }
    h_expect(bad == 0, "%s: %d pixels off", what, bad);
    return total;
}

static double pcx, pcy, pr;
static int in_disc(double x, double y) { return (x - pcx) * (x - pcx) + (y - pcy) * (y - pcy) <= pr * pr; }

static int in_tri(double x, double y) { return y >= 4 && x <= 28 && y <= 4 + (x - 4) * 2.0 / 3.0; }

static int in_diag(double x, double y)
{
    /* (4, 4) -> (24, 19), width 2 */
    double dx = 20, dy = 15, len = 25, ux = dx / len, uy = dy / len;
    double rx = x - 4, ry = y - 4, along = rx * ux + ry * uy, across = -rx * uy + ry * ux;
    return along >= 0 && along <= len && fabs(across) <= 1.0;
}

static void clear(void)
{
    glClearColor(0, 0, 0, 0);
    glClear(GL_COLOR_BUFFER_BIT);
}

static void point(float x, float y)
{
    glBegin(GL_POINTS);
    glVertex2f(x, y);
    glEnd();
}

int main(void)
{
    GLfloat f[2];
    double total;
    int x, y, bad;

    h_init(W, H);
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    glOrtho(0, W, 0, H, -1, 1);
    glMatrixMode(GL_MODELVIEW);
    glColor4f(1, 1, 1, 1);

    /* Limits: smooth sizes are reported and fractional. */
    glGetFloatv(GL_SMOOTH_POINT_SIZE_RANGE, f);
    h_expect(f[0] > 0 && f[0] <= 1 && f[1] >= 4, "GL_SMOOTH_POINT_SIZE_RANGE %g %g", f[0], f[1]);
    glGetFloatv(GL_SMOOTH_POINT_SIZE_GRANULARITY, f);
    h_expect(f[0] > 0 && f[0] < 1, "GL_SMOOTH_POINT_SIZE_GRANULARITY %g", f[0]);
    glGetFloatv(GL_SMOOTH_LINE_WIDTH_RANGE, f);
    h_expect(f[0] > 0 && f[0] <= 1 && f[1] >= 3, "GL_SMOOTH_LINE_WIDTH_RANGE %g %g", f[0], f[1]);
    glGetFloatv(GL_SMOOTH_LINE_WIDTH_GRANULARITY, f);
    h_expect(f[0] > 0 && f[0] < 1, "GL_SMOOTH_LINE_WIDTH_GRANULARITY %g", f[0]);

    /* A smooth point of size 4 at a pixel centre. */
    glEnable(GL_POINT_SMOOTH);
    glHint(GL_POINT_SMOOTH_HINT, GL_NICEST);
    glPointSize(4);
    clear();
    point(10.5f, 10.5f);
    pcx = 10.5, pcy = 10.5, pr = 2;
    total = check_all(in_disc, 1, "point size 4");
    h_expect(alpha(10, 10) == 255 && alpha(9, 9) > 0 && alpha(9, 9) < 255 && alpha(8, 8) == 0,
             "point size 4: centre %d, diagonal neighbour %d, corner %d", alpha(10, 10), alpha(9, 9), alpha(8, 8));
    h_expect(fabs(total - M_PI * 4) < 0.05, "point size 4: total coverage %.4f, pi r^2 = %.4f", total, M_PI * 4);
    h_save("smooth_point");

    /* Off-centre, odd size. */
    glPointSize(3.5f);
    clear();
    point(20.3f, 12.8f);
    pcx = 20.3, pcy = 12.8, pr = 1.75;
    total = check_all(in_disc, 1, "point size 3.5 off-centre");
    h_expect(fabs(total - M_PI * pr * pr) < 0.05, "point size 3.5: total %.4f, pi r^2 = %.4f", total, M_PI * pr * pr);

    /* GL 1.4 attenuation (a = 4 halves the size) and fade: size 8 -> 4. */
    glPointSize(8);
    {
        GLfloat att[3] = {4, 0, 0};
        glPointParameterfv(GL_POINT_DISTANCE_ATTENUATION, att);
    }
    clear();
    point(10.5f, 10.5f);
    pcx = 10.5, pcy = 10.5, pr = 2;
    check_all(in_disc, 1, "attenuated point 8 -> 4");
    /* Derived size 4 below a threshold of 8: drawn at 8, alpha * 1/4. */
    glPointParameterf(GL_POINT_FADE_THRESHOLD_SIZE, 8);
    clear();
    point(10.5f, 10.5f);
    h_read(px);
    h_expect(abs(alpha(10, 10) - 64) <= 1 && abs(alpha(13, 10) - 64) <= 1 && abs(alpha(15, 10) - (int)(64 * area(in_disc, 15, 10) + 0.5)) <= 1,
             "faded point: centre alpha %d, (13,10) %d, expected 64", alpha(10, 10), alpha(13, 10));
    h_expect(alpha(14, 10) > 0 && alpha(6, 10) > 0 && alpha(16, 10) == 0, "faded point drawn at size 8: %d %d %d", alpha(14, 10),
             alpha(6, 10), alpha(16, 10));
    {
        GLfloat att[3] = {1, 0, 0};
        glPointParameterfv(GL_POINT_DISTANCE_ATTENUATION, att);
        glPointParameterf(GL_POINT_FADE_THRESHOLD_SIZE, 1);
    }

    /* GL_FASTEST: multiples of 1/16, near the exact coverage. */
    glHint(GL_POINT_SMOOTH_HINT, GL_FASTEST);
    glPointSize(4);
    clear();
    point(10.5f, 10.5f);
    pcx = 10.5, pcy = 10.5, pr = 2;
    total = check_all(in_disc, 64, "point GL_FASTEST");
    bad = 0;
    for (y = 0; y < H; y++)
        for (x = 0; x < W; x++) {
            int k = (int)floor(alpha(x, y) * 16 / 255.0 + 0.5);
            bad += abs(alpha(x, y) - (int)floor(k * 255 / 16.0 + 0.5)) > 0;
        }
    h_expect(bad == 0, "GL_FASTEST: %d coverages not multiples of 1/16", bad);
    h_expect(fabs(total - M_PI * 4) < 0.5, "GL_FASTEST total %.3f vs %.3f", total, M_PI * 4);
    glDisable(GL_POINT_SMOOTH);

    /* A smooth horizontal line of width 3 at y = 10.25 from x = 4 to 28. */
    glEnable(GL_LINE_SMOOTH);
    glHint(GL_LINE_SMOOTH_HINT, GL_NICEST);
    glLineWidth(3);
    clear();
    glBegin(GL_LINES);
    glVertex2f(4, 10.25f);
    glVertex2f(28, 10.25f);
    glEnd();
    h_read(px);
    bad = 0;
    for (y = 0; y < H; y++)
        for (x = 0; x < W; x++) {
            int want = x < 4 || x >= 28 ? 0 : y == 8 ? 64 : y == 9 || y == 10 ? 255 : y == 11 ? 191 : 0;
            if (alpha(x, y) != want && bad++ < 5)
                h_expect(0, "width-3 line: pixel %d,%d alpha %d, expected %d", x, y, alpha(x, y), want);
        }
    h_expect(bad == 0, "width-3 line at y = 10.25: %d pixels off", bad);

    /* A diagonal of width 2: each pixel, and length * width in total. */
    glLineWidth(2);
    clear();
    glBegin(GL_LINES);
    glVertex2f(4, 4);
    glVertex2f(24, 19);
    glEnd();
    total = check_all(in_diag, 1, "diagonal width 2");
    h_expect(fabs(total - 50) < 0.1, "diagonal: total coverage %.3f, expected 25 * 2", total);
    h_save("smooth_line");

    /* Stipple: 1 x width rectangles from x = 2.5, pattern 0x00FF. */
    glLineWidth(1);
    glEnable(GL_LINE_STIPPLE);
    glLineStipple(1, 0x00FF);
    clear();
    glBegin(GL_LINES);
    glVertex2f(2.5f, 20.5f);
    glVertex2f(30.5f, 20.5f);
    glEnd();
    h_read(px);
    bad = 0;
    for (x = 0; x < W; x++) {
        /* Rectangles k = 0..27 span [2.5 + k, 3.5 + k]; 0-7 and 16-23 drawn. */
        double cov = 0;
        int k, want;
        for (k = 0; k < 28; k++) {
            double lo = 2.5 + k, hi = lo + 1, o = fmin(hi, x + 1.0) - fmax(lo, (double)x);
            if (((0x00FF >> (k % 16)) & 1) && o > 0) cov += o;
        }
        want = (int)floor(255 * cov + 0.5); /* the line covers row 20 exactly */
        if ((alpha(x, 20) != want || alpha(x, 21) != 0 || alpha(x, 19) != 0) && bad++ < 5)
            h_expect(0, "stippled smooth line: column %d alpha %d/%d, expected %d", x, alpha(x, 20), alpha(x, 21), want);
    }
    h_expect(bad == 0, "stippled smooth line: %d columns off", bad);
    /* The counter continues across a strip: two segments of length 4 with
     * pattern 0x00F0 draw only the second (rectangles 4-7). */
    glLineStipple(1, 0x00F0);
    clear();
    glBegin(GL_LINE_STRIP);
    glVertex2f(2.5f, 20.5f);
    glVertex2f(6.5f, 20.5f);
    glVertex2f(10.5f, 20.5f);
    glEnd();
    h_read(px);
    h_expect(alpha(3, 20) == 0 && alpha(5, 20) == 0 && alpha(6, 20) == 128 && alpha(7, 20) == 255 && alpha(9, 20) == 255 &&
                 alpha(10, 20) == 128 && alpha(11, 20) == 0,
             "stippled smooth strip: alpha %d %d %d %d %d %d %d", alpha(3, 20), alpha(5, 20), alpha(6, 20), alpha(7, 20),
             alpha(9, 20), alpha(10, 20), alpha(11, 20));
    glDisable(GL_LINE_STIPPLE);
    glDisable(GL_LINE_SMOOTH);

    /* A smooth triangle with an edge of slope 2/3. */
    glEnable(GL_POLYGON_SMOOTH);
    glHint(GL_POLYGON_SMOOTH_HINT, GL_NICEST);
    clear();
    glBegin(GL_TRIANGLES);
    glVertex2f(4, 4);
    glVertex2f(28, 4);
    glVertex2f(28, 20);
    glEnd();
    total = check_all(in_tri, 1, "smooth triangle");
    h_expect(fabs(total - 24 * 16 / 2.0) < 0.1, "smooth triangle: total %.3f, expected 192", total);
    h_expect(alpha(20, 6) == 255 && alpha(27, 19) > 0 && alpha(27, 19) < 255, "interior %d, edge %d", alpha(20, 6), alpha(27, 19));

    /* GL_SRC_ALPHA_SATURATE, front to back: a white quad, then a bigger
     * red one behind it (drawn after).  Destination alpha accumulates
     * coverage; a pixel already covered takes nothing more. */
    glEnable(GL_BLEND);
    glBlendFunc(GL_SRC_ALPHA_SATURATE, GL_ONE);
    clear();
    glColor4f(1, 1, 1, 1);
    glBegin(GL_QUADS);
    glVertex2f(6.3f, 6.6f);
    glVertex2f(25.7f, 8.2f);
    glVertex2f(24.4f, 25.1f);
    glVertex2f(7.2f, 23.3f);
    glEnd();
    glColor4f(1, 0, 0, 1);
    glRectf(2, 2, 30, 30);
    h_read(px);
    h_save("smooth_saturate");
    bad = 0;
    for (y = 2; y < 30; y++)
        for (x = 2; x < 30; x++) {
            const unsigned char *p = &px[(y * W + x) * 4];
            /* Everywhere inside the red quad: full coverage, red = 255,
             * and green = blue = the white quad's coverage. */
            if ((p[3] < 253 || p[0] < 253 || abs(p[1] - p[2]) > 1) && bad++ < 5)
                h_expect(0, "saturate: pixel %d,%d = %d %d %d %d", x, y, p[0], p[1], p[2], p[3]);
        }
    h_expect(bad == 0, "saturate: %d pixels not fully covered", bad);
    /* The white quad's diagonal (25.7, 8.2)-(7.2, 23.3) (GL_QUADS splits
     * along v1-v3) crosses pixel (16, 15): its two triangles add up to
     * white. */
    h_expect_pixel(16, 15, 255, 255, 255, 255, 2, "quad diagonal");
    h_expect_pixel(16, 7, 255, -1, -1, 255, 2, "bottom edge: red and white");
    h_expect(px[(7 * W + 16) * 4 + 1] > 10 && px[(7 * W + 16) * 4 + 1] < 245, "bottom edge partial: green %d",
             px[(7 * W + 16) * 4 + 1]);
    glDisable(GL_BLEND);
    glDisable(GL_POLYGON_SMOOTH);

    h_expect_no_error("end");
    return h_finish();
}
