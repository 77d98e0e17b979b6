/* t_points: GL_POINTS with glPointSize (GL 1.5 section 3.3, aliased).
 *
 * For sizes 1..6 at several positions, the lit pixels are exactly those
 * whose centres lie within w/2 of the point's centre in x and y, where the
 * centre is (floor(x) + 1/2, floor(y) + 1/2) for odd w and
 * (floor(x + 1/2), floor(y + 1/2)) for even w.  Non-integer sizes round.
 * Points are clipped by their centre.  glPointSize(<= 0) is
 * GL_INVALID_VALUE; GL_POINT_SIZE and the ranges are reported.
 */
#include "harness.h"
#include <math.h>
#include <stdio.h>

#define W 32
#define H 32

static unsigned char px[W * H * 4];

static int lit(int x, int y) { const unsigned char *p = &px[(y * W + x) * 4]; return p[0] || p[1] || p[2]; }

static int point(float x, float y, float z)
{
    int n = 0, i, j;
    glClear(GL_COLOR_BUFFER_BIT);
    glBegin(GL_POINTS);
    glVertex3f(x, y, z);
    glEnd();
    h_read(px);
    for (j = 0; j < H; j++)
        for (i = 0; i < W; i++) n += lit(i, j);
    return n;
}

int main(void)
{
    static const float pos[][2] = {{10.3f, 10.7f}, {10.5f, 10.5f}, {10.0f, 11.0f}, {4.9f, 20.2f}, {20.75f, 3.25f}};
    unsigned k;
    int size, x, y, bad;
    GLfloat f[2];

    h_init(W, H);
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    glOrtho(0, W, 0, H, -1, 1);
    glMatrixMode(GL_MODELVIEW);
    glClearColor(0, 0, 0, 1);
    glColor3ub(255, 255, 255);

    glGetFloatv(GL_POINT_SIZE, f);
    h_expect(f[0] == 1.0f, "initial GL_POINT_SIZE %g", f[0]);
    for (size = 1; size <= 6; size++) {
        glPointSize((float)size);
        for (k = 0; k < sizeof pos / sizeof pos[0]; k++) {
            double cx, cy, hw = size / 2.0;
            int n = point(pos[k][0], pos[k][1], 0.0f);
            if (size % 2) {
                cx = floor(pos[k][0]) + 0.5;
                cy = floor(pos[k][1]) + 0.5;
            } else {
                cx = floor(pos[k][0] + 0.5);
                cy = floor(pos[k][1] + 0.5);
            }
            bad = 0;
            for (y = 0; y < H; y++)
                for (x = 0; x < W; x++) {
                    int want = fabs(x + 0.5 - cx) < hw && fabs(y + 0.5 - cy) < hw;
                    bad += want != lit(x, y);
                }
            h_expect(bad == 0 && n == size * size, "size %d at (%g, %g): %d pixels, %d wrong", size, pos[k][0], pos[k][1], n, bad);
        }
    }
    glPointSize(2.4f);
    h_expect(point(10.5f, 10.5f, 0) == 4, "size 2.4 rounds to 2");
    glPointSize(2.6f);
    h_expect(point(10.5f, 10.5f, 0) == 9, "size 2.6 rounds to 3");
    glGetFloatv(GL_POINT_SIZE, f);
    h_expect(fabs(f[0] - 2.6f) < 1e-6, "GL_POINT_SIZE %g", f[0]);

    /* Clipped by the centre. */
    glPointSize(6.0f);
    h_expect(point(-0.5f, 10.5f, 0) == 0, "centre left of the window: nothing");
    h_expect(point(10.5f, 10.5f, 1.5f) == 0, "centre beyond the near plane: nothing");
    h_expect(point(0.5f, 10.5f, 0) == 24, "centre inside, square cut by the edge: 4 x 6");

    /* Colour is the vertex's. */
    glPointSize(3.0f);
    glClear(GL_COLOR_BUFFER_BIT);
    glBegin(GL_POINTS);
    glColor3ub(10, 200, 30);
    glVertex2f(16.5f, 16.5f);
    glEnd();
    h_expect_pixel(15, 15, 10, 200, 30, 255, 0, "point colour, corner");
    h_expect_pixel(17, 17, 10, 200, 30, 255, 0, "point colour, corner");
    h_expect_pixel(18, 17, 0, 0, 0, 255, 0, "outside the point");

    h_expect_no_error("points");
    glPointSize(0.0f);
    h_expect_error(GL_INVALID_VALUE, "glPointSize(0)");
    glPointSize(-1.0f);
    h_expect_error(GL_INVALID_VALUE, "glPointSize(-1)");
    glGetFloatv(GL_POINT_SIZE, f);
    h_expect(f[0] == 3.0f, "GL_POINT_SIZE unchanged by errors: %g", f[0]);
    glGetFloatv(GL_ALIASED_POINT_SIZE_RANGE, f);
    h_expect(f[0] == 1.0f && f[1] >= 1.0f, "GL_ALIASED_POINT_SIZE_RANGE %g %g", f[0], f[1]);
    glGetFloatv(GL_POINT_SIZE_RANGE, f);
    h_expect(f[0] <= 1.0f && f[1] >= 1.0f, "GL_POINT_SIZE_RANGE %g %g", f[0], f[1]);
    glGetFloatv(GL_POINT_SIZE_GRANULARITY, f);
    h_expect(f[0] > 0.0f, "GL_POINT_SIZE_GRANULARITY %g", f[0]);
    return h_finish();
}
