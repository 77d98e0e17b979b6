/* t_smooth_triangle: Gouraud shading (GL 1.5 section 3.5.1, "Polygon
 * rasterization" and 2.13.7 "Flatshading"/smooth): with GL_SMOOTH, the colour
 * of a fragment is the barycentric interpolation of the vertex colours at the
 * pixel centre (x+0.5, y+0.5).  An ortho projection makes w = 1, so the
 * interpolation is linear in window coordinates.
 *
 * Checked two ways: against a reviewed golden image (tol 2, a few edge
 * pixels may differ), and analytically: every pixel whose centre is at least
 * one pixel inside the triangle must be within 2/255 of the barycentric
 * colour, and every pixel whose centre is at least one pixel outside must be
 * the clear colour.
 */
#include "harness.h"
#include <math.h>
#include <stdio.h>
#include <stdlib.h>

#define W 64
#define H 64

/* Window-space vertices (the ortho projection maps object = window). */
static const double V[3][2] = {{6.0, 5.0}, {58.0, 12.0}, {20.0, 59.0}};

/* Signed distance of p from the line a->b (positive on the left). */
static double edge_dist(const double *a, const double *b, double px, double py)
{
    double ex = b[0] - a[0], ey = b[1] - a[1];
    return (ex * (py - a[1]) - ey * (px - a[0])) / sqrt(ex * ex + ey * ey);
}

int main(void)
{
    static unsigned char px[W * H * 4];
    double area;
    int x, y, c, inner = 0, outer = 0, bad_in = 0, bad_out = 0;

    h_init(W, H);
    glViewport(0, 0, W, H);
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    glOrtho(0, W, 0, H, -1, 1);
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
    glClearColor(0, 0, 0, 1);
    glClear(GL_COLOR_BUFFER_BIT);
    glShadeModel(GL_SMOOTH);

    glBegin(GL_TRIANGLES);
    glColor3f(1, 0, 0);
    glVertex2d(V[0][0], V[0][1]);
    glColor3f(0, 1, 0);
    glVertex2d(V[1][0], V[1][1]);
    glColor3f(0, 0, 1);
    glVertex2d(V[2][0], V[2][1]);
    glEnd();
    h_expect_no_error("drawing");

    h_check_golden("smooth_triangle", 2, 6);

    /* Analytic check.  The vertices are counter-clockwise. */
    h_read(px);
    area = (V[1][0] - V[0][0]) * (V[2][1] - V[0][1]) -
           (V[2][0] - V[0][0]) * (V[1][1] - V[0][1]);
    for (y = 0; y < H; y++) {
        for (x = 0; x < W; x++) {
            double cx = x + 0.5, cy = y + 0.5;
            double d0 = edge_dist(V[1], V[2], cx, cy); /* opposite vertex 0 */
            double d1 = edge_dist(V[2], V[0], cx, cy);
            double d2 = edge_dist(V[0], V[1], cx, cy);
            const unsigned char *p = &px[(y * W + x) * 4];
            if (d0 >= 1 && d1 >= 1 && d2 >= 1) {
                /* barycentric weights = sub-triangle areas / area */
                double l0 = ((V[1][0] - cx) * (V[2][1] - cy) - (V[2][0] - cx) * (V[1][1] - cy)) / area;
                double l1 = ((V[2][0] - cx) * (V[0][1] - cy) - (V[0][0] - cx) * (V[2][1] - cy)) / area;
                double l2 = 1.0 - l0 - l1;
                int want[4];
                int bad = 0;
                want[0] = (int)floor(l0 * 255 + 0.5);
                want[1] = (int)floor(l1 * 255 + 0.5);
                want[2] = (int)floor(l2 * 255 + 0.5);
                want[3] = 255;
                inner++;
                for (c = 0; c < 4; c++)
                    if (abs(p[c] - want[c]) > 2)
                        bad = 1;
                if (bad) {
                    bad_in++;
                    h_expect(0, "interior pixel (%d,%d) is %d,%d,%d,%d, barycentric colour %d,%d,%d,%d",
                             x, y, p[0], p[1], p[2], p[3], want[0], want[1], want[2], want[3]);
                }
            } else if (d0 <= -1 || d1 <= -1 || d2 <= -1) {
                outer++;
                if (p[0] || p[1] || p[2] || p[3] != 255) {
                    bad_out++;
                    h_expect(0, "exterior pixel (%d,%d) is %d,%d,%d,%d, expected 0,0,0,255",
                             x, y, p[0], p[1], p[2], p[3]);
                }
            }
        }
    }
    h_expect(inner > 800, "only %d interior pixels checked", inner);
    printf("  checked %d interior pixels (%d bad) and %d exterior pixels (%d bad)\n",
           inner, bad_in, outer, bad_out);

    /* A few hand-picked pixel centres, spelled out. */
    /* centroid (28,25.33): pixel (27,24) centre (27.5,24.5) */
    {
        double cx = 27.5, cy = 24.5;
        double l0 = ((V[1][0] - cx) * (V[2][1] - cy) - (V[2][0] - cx) * (V[1][1] - cy)) / area;
        double l1 = ((V[2][0] - cx) * (V[0][1] - cy) - (V[0][0] - cx) * (V[2][1] - cy)) / area;
        h_expect_pixel(27, 24, (int)floor(l0 * 255 + 0.5), (int)floor(l1 * 255 + 0.5),
                       (int)floor((1 - l0 - l1) * 255 + 0.5), 255, 2, "pixel near the centroid");
    }
    h_expect_pixel(0, 63, 0, 0, 0, 255, 0, "top-left corner is background");
    h_expect_pixel(63, 0, 0, 0, 0, 255, 0, "bottom-right corner is background");
    return h_finish();
}
