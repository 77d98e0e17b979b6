/* t_watertight: polygon rasterization is point sampling and watertight
 * (GL 1.5 section 3.5.1).
 *
 * - A fragment is produced exactly for the pixels whose centre (x+0.5, y+0.5)
 *   lies inside the triangle; a centre exactly on an edge is decided by an
 *   implementation rule, but "if two polygons lie on either side of a common
 *   edge (with identical endpoints) on which a fragment center lies, then
 *   exactly one of the polygons results in the production of the fragment".
 *
 * Three meshes are drawn one triangle at a time on a cleared buffer and read
 * back; per pixel we count how many triangles covered it:
 *   A: a fan of 37 thin triangles around (31.3125, 32.6875), outer vertices
 *      partly snapped to pixel centres and to integer corners;
 *   B: a fan of 16 triangles around the pixel centre (32.5, 32.5) whose outer
 *      vertices are pixel centres, so its edges (slopes 0, 1/2, 1, 2, inf)
 *      pass through many pixel centres;
 *   C: a perturbed 12x12 grid of quads split into triangles along alternating
 *      diagonals, with some vertices on pixel centres and one row/column of
 *      edges through pixel centres.
 * All vertices are multiples of 1/16 pixel (exactly representable with the
 * minimum 4 subpixel bits GL allows), so the test decides inside/outside
 * with exact integer arithmetic.  Checks:
 *   1. per triangle: centres strictly inside are covered, centres strictly
 *      outside are not;
 *   2. every pixel is covered at most once;
 *   3. every pixel whose centre is inside the union and more than 1/64 pixel
 *      away from its outer boundary is covered exactly once.
 */
#include "harness.h"
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define W 64
#define H 64
#define SUB 16 /* coordinates are in 1/16 pixel units */
#define MAXV 400
#define MAXT 400

typedef long long i64;

static int vx[MAXV], vy[MAXV], nv;
static int tri[MAXT][3], nt;
static int cnt[W * H];
static unsigned char px[W * H * 4];

static int add_v(int x, int y)
{
    vx[nv] = x;
    vy[nv] = y;
    return nv++;
}

static void add_t(int a, int b, int c)
{
    tri[nt][0] = a;
    tri[nt][1] = b;
    tri[nt][2] = c;
    nt++;
}

static int snap(double v, int mode)
{
    /* mode 0: nearest 1/16; 1: nearest pixel centre; 2: nearest integer */
    if (mode == 1)
        return (int)floor(v - 0.5 + 0.5) * SUB + SUB / 2;
    if (mode == 2)
        return (int)floor(v + 0.5) * SUB;
    return (int)floor(v * SUB + 0.5);
}

/* twice the signed area of (a, b, p), in (1/16)^2 units */
static i64 orient(int ax, int ay, int bx, int by, int px_, int py_)
{
    return (i64)(bx - ax) * (py_ - ay) - (i64)(by - ay) * (px_ - ax);
}

/* -1 outside, 0 on the boundary, 1 strictly inside */
static int classify(int t, int cx, int cy)
{
    const int *v = tri[t];
    i64 e0 = orient(vx[v[0]], vy[v[0]], vx[v[1]], vy[v[1]], cx, cy);
    i64 e1 = orient(vx[v[1]], vy[v[1]], vx[v[2]], vy[v[2]], cx, cy);
    i64 e2 = orient(vx[v[2]], vy[v[2]], vx[v[0]], vy[v[0]], cx, cy);
    i64 area = orient(vx[v[0]], vy[v[0]], vx[v[1]], vy[v[1]], vx[v[2]], vy[v[2]]);
    if (area < 0) {
        e0 = -e0;
        e1 = -e1;
        e2 = -e2;
    }
    if (e0 < 0 || e1 < 0 || e2 < 0)
        return -1;
    if (e0 == 0 || e1 == 0 || e2 == 0)
        return 0;
    return 1;
}

/* distance (pixels) from (cx,cy) to the segment a-b, all in 1/16 units */
static double seg_dist(int a, int b, int cx, int cy)
{
    double ax = vx[a], ay = vy[a], bx = vx[b], by = vy[b];
    double dx = bx - ax, dy = by - ay, t;
    t = ((cx - ax) * dx + (cy - ay) * dy) / (dx * dx + dy * dy);
    if (t < 0) t = 0;
    if (t > 1) t = 1;
    dx = ax + t * dx - cx;
    dy = ay + t * dy - cy;
    return sqrt(dx * dx + dy * dy) / SUB;
}

static void check_mesh(const char *name, int want_on_edge)
{
    static int bedge[3 * MAXT][2];
    int nb = 0, t, i, j, x, y;
    int inside_wrong = 0, outside_wrong = 0, multi = 0, holes = 0;
    int interior = 0, on_internal_edge = 0;

    /* sanity: no degenerate triangles, all inside the window */
    for (t = 0; t < nt; t++) {
        const int *v = tri[t];
        i64 area = orient(vx[v[0]], vy[v[0]], vx[v[1]], vy[v[1]], vx[v[2]], vy[v[2]]);
        h_expect(area != 0, "%s: test bug: triangle %d is degenerate", name, t);
    }
    for (i = 0; i < nv; i++)
        h_expect(vx[i] >= 0 && vx[i] <= W * SUB && vy[i] >= 0 && vy[i] <= H * SUB,
                 "%s: test bug: vertex %d outside the window", name, i);

    /* boundary edges: edges used by exactly one triangle */
    for (t = 0; t < nt; t++)
        for (i = 0; i < 3; i++) {
            int a = tri[t][i], b = tri[t][(i + 1) % 3], uses = 0, s, k;
            for (s = 0; s < nt; s++)
                for (k = 0; k < 3; k++) {
                    int c = tri[s][k], d = tri[s][(k + 1) % 3];
                    if ((c == a && d == b) || (c == b && d == a))
                        uses++;
                }
            if (uses == 1) {
                bedge[nb][0] = a;
                bedge[nb][1] = b;
                nb++;
            }
        }

    memset(cnt, 0, sizeof cnt);
    for (t = 0; t < nt; t++) {
        glClear(GL_COLOR_BUFFER_BIT);
        glBegin(GL_TRIANGLES);
        for (i = 0; i < 3; i++)
            glVertex2f((float)vx[tri[t][i]] / SUB, (float)vy[tri[t][i]] / SUB);
        glEnd();
        h_read(px);
        for (y = 0; y < H; y++)
            for (x = 0; x < W; x++) {
                int covered = px[(y * W + x) * 4] > 127;
                int cls = classify(t, x * SUB + SUB / 2, y * SUB + SUB / 2);
                cnt[y * W + x] += covered;
                if (cls == 1 && !covered) {
                    inside_wrong++;
                    h_expect(0, "%s: triangle %d (%g,%g)-(%g,%g)-(%g,%g) misses pixel (%d,%d) whose centre is strictly inside",
                             name, t, vx[tri[t][0]] / 16.0, vy[tri[t][0]] / 16.0, vx[tri[t][1]] / 16.0,
                             vy[tri[t][1]] / 16.0, vx[tri[t][2]] / 16.0, vy[tri[t][2]] / 16.0, x, y);
                } else if (cls == -1 && covered) {
                    outside_wrong++;
                    h_expect(0, "%s: triangle %d (%g,%g)-(%g,%g)-(%g,%g) covers pixel (%d,%d) whose centre is strictly outside",
                             name, t, vx[tri[t][0]] / 16.0, vy[tri[t][0]] / 16.0, vx[tri[t][1]] / 16.0,
                             vy[tri[t][1]] / 16.0, vx[tri[t][2]] / 16.0, vy[tri[t][2]] / 16.0, x, y);
                }
            }
    }

    for (y = 0; y < H; y++)
        for (x = 0; x < W; x++) {
            int cx = x * SUB + SUB / 2, cy = y * SUB + SUB / 2;
            int in_closed = 0, on_edge = 0, near_boundary = 0, c = cnt[y * W + x];
            for (t = 0; t < nt; t++) {
                int cls = classify(t, cx, cy);
                if (cls >= 0)
                    in_closed = 1;
                if (cls == 0)
                    on_edge = 1;
            }
            for (j = 0; j < nb && in_closed; j++)
                if (seg_dist(bedge[j][0], bedge[j][1], cx, cy) < 1.0 / 64)
                    near_boundary = 1;
            if (c > 1) {
                multi++;
                h_expect(0, "%s: pixel (%d,%d) covered %d times", name, x, y, c);
            }
            if (in_closed && !near_boundary) {
                interior++;
                if (on_edge)
                    on_internal_edge++;
                if (c != 1) {
                    holes++;
                    h_expect(0, "%s: pixel (%d,%d) centre inside the mesh%s covered %d times, expected once",
                             name, x, y, on_edge ? " (on a shared edge)" : "", c);
                }
            }
        }
    printf("  %s: %d triangles, %d boundary edges, %d interior centres (%d on shared edges or vertices); "
           "%d inside misses, %d outside hits, %d multiply covered, %d not exactly once\n",
           name, nt, nb, interior, on_internal_edge, inside_wrong, outside_wrong, multi, holes);
    if (want_on_edge)
        h_expect(on_internal_edge >= want_on_edge,
                 "%s: test bug: only %d centres on shared edges, expected at least %d", name,
                 on_internal_edge, want_on_edge);
}

int main(void)
{
    const double PI = 3.14159265358979323846;
    int i, j;

    h_init(W, H);
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    glOrtho(0, W, 0, H, -1, 1);
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
    glClearColor(0, 0, 0, 1);
    glColor3f(1, 1, 1);

    /* A: fan of 37 thin triangles around a non-aligned centre. */
    nv = nt = 0;
    {
        int c = add_v(501, 523), first = -1, prev = -1;
        for (i = 0; i < 37; i++) {
            double a = 2 * PI * (i + 0.3 * sin(i * 1.7)) / 37;
            double r = 27 + 2 * cos(i * 2.3);
            int v = add_v(snap(31.3125 + r * cos(a), i % 4 == 0 ? 1 : i % 4 == 1 ? 2 : 0),
                          snap(32.6875 + r * sin(a), i % 4 == 0 ? 1 : i % 4 == 1 ? 2 : 0));
            if (prev >= 0)
                add_t(c, prev, v);
            else
                first = v;
            prev = v;
        }
        add_t(c, prev, first);
    }
    check_mesh("fan of 37", 0);

    /* B: fan around a pixel centre, outer vertices on pixel centres. */
    nv = nt = 0;
    {
        static const int off[16][2] = {{20, 0},  {20, 10},  {20, 20},  {10, 20},
                                       {0, 20},  {-10, 20}, {-20, 20}, {-20, 10},
                                       {-20, 0}, {-20, -10}, {-20, -20}, {-10, -20},
                                       {0, -20}, {10, -20}, {20, -20}, {20, -10}};
        int c = add_v(520, 520);
        for (i = 0; i < 16; i++)
            add_v(520 + off[i][0] * SUB, 520 + off[i][1] * SUB);
        for (i = 0; i < 16; i++)
            add_t(c, 1 + i, 1 + (i + 1) % 16);
    }
    check_mesh("fan on pixel centres", 100);

    /* C: perturbed 12x12 grid of quads, split into triangles. */
    nv = nt = 0;
    {
        unsigned seed = 12345;
        int idx[13][13];
        for (j = 0; j <= 12; j++)
            for (i = 0; i <= 12; i++) {
                int x = 80 + 72 * i, y = 80 + 72 * j; /* 5 + 4.5 i pixels */
                seed = seed * 1103515245u + 12345u;
                if (i > 0 && i < 12 && j > 0 && j < 12 && (i + j) % 3 != 0) {
                    int dx = (int)((seed >> 8) % 29) - 14;  /* +-14/16 pixel */
                    int dy = (int)((seed >> 18) % 29) - 14;
                    if (i == 7) dx = 0; /* column through x = 36.5 */
                    if (j == 5) dy = 0; /* row through y = 27.5 */
                    x += dx;
                    y += dy;
                }
                idx[j][i] = add_v(x, y);
            }
        for (j = 0; j < 12; j++)
            for (i = 0; i < 12; i++) {
                int a = idx[j][i], b = idx[j][i + 1], c = idx[j + 1][i + 1], d = idx[j + 1][i];
                if ((i + j) % 2 == 0) {
                    add_t(a, b, c);
                    add_t(a, c, d);
                } else {
                    add_t(a, b, d);
                    add_t(b, c, d);
                }
            }
        /* all triangles must keep their (counter-clockwise) orientation */
        for (i = 0; i < nt; i++) {
            const int *v = tri[i];
            h_expect(orient(vx[v[0]], vy[v[0]], vx[v[1]], vy[v[1]], vx[v[2]], vy[v[2]]) > 0,
                     "test bug: grid triangle %d flipped by the perturbation", i);
        }
    }
    check_mesh("perturbed 12x12 grid", 20);

    h_expect_no_error("end");
    return h_finish();
}
