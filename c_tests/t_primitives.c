/* t_primitives: the polygon primitive types (GL 1.5 section 2.6.1) cover
 * exactly the expected pixels, and incomplete primitives draw nothing.
 *
 * Every shape here is a union of axis-aligned rectangles with integer
 * corners (window coordinates through an exact ortho projection), so the
 * covered pixel set is known exactly: pixel (x,y) is covered iff its centre
 * (x+0.5, y+0.5) lies inside, i.e. x0 <= x < x1 and y0 <= y < y1.  Every
 * pixel of the buffer is compared, for GL_TRIANGLES, GL_TRIANGLE_STRIP,
 * GL_TRIANGLE_FAN, GL_QUADS, GL_QUAD_STRIP and GL_POLYGON.
 *
 * Incomplete primitives (section 2.6.1): vertices left over that do not
 * complete a triangle/quad are ignored; a primitive with too few vertices
 * draws nothing (2 vertices of GL_TRIANGLES, GL_TRIANGLE_STRIP,
 * GL_TRIANGLE_FAN, GL_POLYGON; 3 of GL_QUADS and GL_QUAD_STRIP).
 */
#include "harness.h"
#include <stdio.h>

#define W 48
#define H 32

struct rect { int x0, y0, x1, y1; };

struct cse {
    const char *name;
    GLenum mode;
    int nverts;
    int v[12][2];
    int nrects;
    struct rect r[2];
};

static const struct cse CASES[] = {
    {"GL_TRIANGLES, two rectangles", GL_TRIANGLES, 12,
     {{2, 3}, {14, 3}, {14, 11}, {2, 3}, {14, 11}, {2, 11},
      {20, 12}, {40, 12}, {20, 30}, {40, 12}, {40, 30}, {20, 30}},
     2, {{2, 3, 14, 11}, {20, 12, 40, 30}}},
    {"GL_TRIANGLE_STRIP, three cells", GL_TRIANGLE_STRIP, 8,
     {{4, 6}, {4, 20}, {12, 6}, {12, 20}, {28, 6}, {28, 20}, {44, 6}, {44, 20}},
     1, {{4, 6, 44, 20}}},
    {"GL_TRIANGLE_FAN around a bottom-edge point", GL_TRIANGLE_FAN, 5,
     {{20, 4}, {40, 4}, {40, 28}, {6, 28}, {6, 4}},
     1, {{6, 4, 40, 28}}},
    {"GL_QUADS, two rectangles", GL_QUADS, 8,
     {{1, 1}, {9, 1}, {9, 31}, {1, 31}, {30, 10}, {47, 10}, {47, 12}, {30, 12}},
     2, {{1, 1, 9, 31}, {30, 10, 47, 12}}},
    {"GL_QUAD_STRIP, two cells", GL_QUAD_STRIP, 6,
     {{3, 5}, {3, 25}, {17, 5}, {17, 25}, {45, 5}, {45, 25}},
     1, {{3, 5, 45, 25}}},
    {"GL_POLYGON rectangle", GL_POLYGON, 4,
     {{10, 2}, {38, 2}, {38, 30}, {10, 30}},
     1, {{10, 2, 38, 30}}},
    {"GL_POLYGON, clockwise, whole window", GL_POLYGON, 4,
     {{0, 0}, {0, 32}, {48, 32}, {48, 0}},
     1, {{0, 0, 48, 32}}},
    /* leftover vertices are ignored */
    {"GL_TRIANGLES with 2 leftover vertices", GL_TRIANGLES, 8,
     {{2, 3}, {14, 3}, {14, 11}, {2, 3}, {14, 11}, {2, 11}, {30, 20}, {40, 20}},
     1, {{2, 3, 14, 11}}},
    {"GL_QUADS with 3 leftover vertices", GL_QUADS, 7,
     {{5, 5}, {15, 5}, {15, 9}, {5, 9}, {20, 20}, {30, 20}, {30, 30}},
     1, {{5, 5, 15, 9}}},
    {"GL_QUAD_STRIP with 1 leftover vertex", GL_QUAD_STRIP, 5,
     {{5, 5}, {5, 9}, {15, 5}, {15, 9}, {30, 30}},
     1, {{5, 5, 15, 9}}},
    /* too few vertices: nothing */
    {"GL_TRIANGLES with 2 vertices", GL_TRIANGLES, 2, {{2, 2}, {40, 2}}, 0, {{0}}},
    {"GL_TRIANGLES with 1 vertex", GL_TRIANGLES, 1, {{2, 2}}, 0, {{0}}},
    {"GL_TRIANGLE_STRIP with 2 vertices", GL_TRIANGLE_STRIP, 2, {{2, 2}, {40, 30}}, 0, {{0}}},
    {"GL_TRIANGLE_FAN with 2 vertices", GL_TRIANGLE_FAN, 2, {{2, 2}, {40, 30}}, 0, {{0}}},
    {"GL_QUADS with 3 vertices", GL_QUADS, 3, {{2, 2}, {40, 2}, {40, 30}}, 0, {{0}}},
    {"GL_QUAD_STRIP with 3 vertices", GL_QUAD_STRIP, 3, {{2, 2}, {2, 30}, {40, 2}}, 0, {{0}}},
    {"GL_POLYGON with 2 vertices", GL_POLYGON, 2, {{2, 2}, {40, 30}}, 0, {{0}}},
    {"GL_TRIANGLES with 0 vertices", GL_TRIANGLES, 0, {{0}}, 0, {{0}}},
};

int main(void)
{
    static unsigned char px[W * H * 4];
    unsigned k;

    h_init(W, H);
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    glOrtho(0, W, 0, H, -1, 1);
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
    glClearColor(0, 0, 0, 1);
    glColor3ub(255, 255, 255);

    for (k = 0; k < sizeof CASES / sizeof CASES[0]; k++) {
        const struct cse *c = &CASES[k];
        int i, x, y, want_n = 0, got_n = 0, missing = 0, extra = 0;
        int fx = -1, fy = -1;
        glClear(GL_COLOR_BUFFER_BIT);
        glBegin(c->mode);
        for (i = 0; i < c->nverts; i++)
            glVertex2i(c->v[i][0], c->v[i][1]);
        glEnd();
        h_expect_no_error(c->name);
        h_read(px);
        for (y = 0; y < H; y++)
            for (x = 0; x < W; x++) {
                const unsigned char *p = &px[(y * W + x) * 4];
                int want = 0, got;
                for (i = 0; i < c->nrects; i++)
                    if (x >= c->r[i].x0 && x < c->r[i].x1 && y >= c->r[i].y0 && y < c->r[i].y1)
                        want = 1;
                got = p[0] == 255 && p[1] == 255 && p[2] == 255 && p[3] == 255;
                if (!got && (p[0] || p[1] || p[2] || p[3] != 255))
                    got = -1; /* neither white nor background */
                want_n += want;
                got_n += got == 1;
                if (got != want) {
                    if (want) missing++; else extra++;
                    if (fx < 0) { fx = x; fy = y; }
                }
            }
        h_expect(missing == 0 && extra == 0,
                 "%s: expected %d covered pixels, got %d (%d missing, %d extra or off-colour; first wrong pixel (%d,%d))",
                 c->name, want_n, got_n, missing, extra, fx, fy);
    }
    return h_finish();
}
