/* t_flat_shading: the provoking vertex under glShadeModel(GL_FLAT)
 * (GL 1.5 section 2.14.7, table 2.9).  A flat-shaded primitive takes the
 * colour of one vertex for all its fragments:
 *   GL_TRIANGLES       triangle i: vertex 3i      (1-based), i.e. its last
 *   GL_TRIANGLE_STRIP  triangle i: vertex i+2     (1-based), its last
 *   GL_TRIANGLE_FAN    triangle i: vertex i+2     (1-based), its last
 *   GL_QUADS           quad i:     vertex 4i      (1-based), its last
 *   GL_QUAD_STRIP      quad i:     vertex 2i+2    (1-based)
 *   GL_POLYGON         vertex 1, the FIRST
 * Every vertex gets a different colour, and a pixel well inside each
 * triangle/quad must have exactly the provoking vertex's colour.
 */
#include "harness.h"
#include <stdio.h>

#define W 64
#define H 64

static const unsigned char COL[10][3] = {
    {255, 0, 0},   {0, 255, 0},   {0, 0, 255},    {255, 255, 0},  {255, 0, 255},
    {0, 255, 255}, {128, 64, 32}, {32, 160, 224}, {200, 200, 200}, {96, 0, 160},
};

struct probe {
    double x, y;  /* a point well inside one sub-primitive (window coords) */
    int provoking; /* 0-based vertex index whose colour it must have */
};

struct prim {
    const char *name;
    GLenum mode;
    int nverts;
    double v[10][2];
    int nprobes;
    struct probe probes[8];
};

static const struct prim PRIMS[] = {
    {"GL_TRIANGLES", GL_TRIANGLES, 6,
     {{4, 4}, {28, 4}, {4, 28}, {60, 60}, {36, 60}, {60, 36}},
     2, {{12, 12, 2}, {52, 52, 5}}},
    /* zig-zag strip; triangle k = (v_k, v_k+1, v_k+2) */
    {"GL_TRIANGLE_STRIP", GL_TRIANGLE_STRIP, 6,
     {{4, 4}, {4, 40}, {20, 4}, {20, 40}, {36, 4}, {36, 40}},
     4, {{28.0 / 3, 48.0 / 3, 2}, {44.0 / 3, 84.0 / 3, 3}, {76.0 / 3, 48.0 / 3, 4}, {92.0 / 3, 84.0 / 3, 5}}},
    /* fan around v0; triangle k = (v0, v_k+1, v_k+2) */
    {"GL_TRIANGLE_FAN", GL_TRIANGLE_FAN, 6,
     {{32, 32}, {60, 20}, {56, 56}, {20, 60}, {6, 30}, {20, 6}},
     4, {{148.0 / 3, 36, 2}, {36, 148.0 / 3, 3}, {58.0 / 3, 122.0 / 3, 4}, {58.0 / 3, 68.0 / 3, 5}}},
    {"GL_QUADS", GL_QUADS, 8,
     {{4, 4}, {28, 4}, {28, 28}, {4, 28}, {36, 36}, {60, 36}, {60, 60}, {36, 60}},
     4, {{16, 16, 3}, {8, 24, 3}, {48, 48, 7}, {56, 40, 7}}},
    /* quad k = (v_2k, v_2k+1, v_2k+3, v_2k+2); provoking v_2k+3 (0-based) */
    {"GL_QUAD_STRIP", GL_QUAD_STRIP, 8,
     {{4, 8}, {4, 56}, {20, 8}, {20, 56}, {40, 8}, {40, 56}, {60, 8}, {60, 56}},
     6, {{12, 16, 3}, {12, 48, 3}, {30, 16, 5}, {30, 48, 5}, {50, 16, 7}, {50, 48, 7}}},
    /* convex hexagon; the whole polygon has v0's colour */
    {"GL_POLYGON", GL_POLYGON, 6,
     {{32, 4}, {56, 18}, {56, 46}, {32, 60}, {8, 46}, {8, 18}},
     7, {{32, 32, 0}, {32, 10, 0}, {50, 20, 0}, {50, 44, 0}, {32, 54, 0}, {14, 44, 0}, {14, 20, 0}}},
};

int main(void)
{
    unsigned p, i;
    GLint model;

    h_init(W, H);
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    glOrtho(0, W, 0, H, -1, 1);
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
    glShadeModel(GL_FLAT);
    glGetIntegerv(GL_SHADE_MODEL, &model);
    h_expect(model == GL_FLAT, "GL_SHADE_MODEL = 0x%x, expected GL_FLAT", model);

    for (p = 0; p < sizeof PRIMS / sizeof PRIMS[0]; p++) {
        const struct prim *pr = &PRIMS[p];
        glClearColor(0, 0, 0, 1);
        glClear(GL_COLOR_BUFFER_BIT);
        glBegin(pr->mode);
        for (i = 0; i < (unsigned)pr->nverts; i++) {
            glColor3ub(COL[i][0], COL[i][1], COL[i][2]);
            glVertex2d(pr->v[i][0], pr->v[i][1]);
        }
        glEnd();
        h_expect_no_error(pr->name);
        for (i = 0; i < (unsigned)pr->nprobes; i++) {
            const struct probe *q = &pr->probes[i];
            const unsigned char *c = COL[q->provoking];
            char what[128];
            snprintf(what, sizeof what, "%s sub-primitive at (%.1f,%.1f): colour of vertex %d (0-based)",
                     pr->name, q->x, q->y, q->provoking);
            h_expect_pixel((int)q->x, (int)q->y, c[0], c[1], c[2], 255, 1, what);
        }
        h_expect_pixel(0, 63, 0, 0, 0, 255, 0, "background stays clear");
    }

    /* GL_SMOOTH again: the fan's first triangle is no longer one colour. */
    glShadeModel(GL_SMOOTH);
    glClear(GL_COLOR_BUFFER_BIT);
    glBegin(GL_TRIANGLES);
    glColor3ub(255, 0, 0);
    glVertex2d(4, 4);
    glColor3ub(0, 255, 0);
    glVertex2d(60, 4);
    glColor3ub(0, 0, 255);
    glVertex2d(4, 60);
    glEnd();
    {
        unsigned char a[4], b[4];
        glReadPixels(6, 6, 1, 1, GL_RGBA, GL_UNSIGNED_BYTE, a);
        glReadPixels(50, 8, 1, 1, GL_RGBA, GL_UNSIGNED_BYTE, b);
        h_expect(a[0] > 200 && b[1] > 150, "GL_SMOOTH after GL_FLAT: (6,6)=%d,%d,%d (6,6) should be red-ish, (50,8)=%d,%d,%d green-ish",
                 a[0], a[1], a[2], b[0], b[1], b[2]);
    }
    return h_finish();
}
