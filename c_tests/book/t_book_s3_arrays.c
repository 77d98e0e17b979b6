/* t_book_s3_arrays: the Russian textbook's chapter 7, vertex arrays
 * (seeds-inventory §3.5 F13, F14).
 *
 * BOOK: S3, Russian OpenGL textbook, ch. 7 "Vertex arrays and their attributes", fragments F13 (separate arrays) and F14 (interleaved with a stride)
 * SHOWS: the same smooth-shaded pentagon twice (red, green, blue, dark green, pink corners): from separate vertex and colour arrays, and from one interleaved array with a stride of 5 floats
 * FEATURES: glVertexPointer, glColorPointer, strides, glEnableClientState/glDisableClientState, glDrawArrays(GL_POLYGON), glArrayElement
 *
 * The pentagon's vertices run clockwise, so it is back-facing (drawn:
 * culling is off).  Checks: the two pictures are identical, each corner
 * pixel has its vertex colour, the centre is the mean, and glArrayElement
 * inside glBegin/glEnd draws the same pentagon.
 */
#include "book.h"

#define W 200
#define H 200

static GLfloat V[5][2] = {{0, 2}, {2, 1}, {1.5f, -1}, {-1.5f, -1}, {-2, 1}};
static GLfloat C[5][3] = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}, {0, 0.5f, 0}, {1, 0.5f, 1}};
static GLfloat VC[25] = {
    0, 2, 1, 0, 0,   2, 1, 0, 1, 0,   1.5f, -1, 0, 0, 1,
    -1.5f, -1, 0, 0.5f, 0,   -2, 1, 1, 0.5f, 1};

static void check_corners(const char *what)
{
    int i;
    for (i = 0; i < 5; i++) {
        /* a point 4% of the way from the vertex to the centroid (0, 0.4) */
        double x, y, px = V[i][0] * 0.96, py = V[i][1] * 0.96 + 0.4 * 0.04;
        book_project(px, py, 0, &x, &y);
        book_expect_rgb((int)x, (int)y, (int)(C[i][0] * 255), (int)(C[i][1] * 255),
                        (int)(C[i][2] * 255), 32, what);
    }
}

int main(void)
{
    static unsigned char first[W * H * 4];
    int i;

    book_open(W, H);
    book_ortho_unit(2.2);

    /* F13 */
    glClear(GL_COLOR_BUFFER_BIT);
    glVertexPointer(2, GL_FLOAT, 0, V);
    glColorPointer(3, GL_FLOAT, 0, C);
    glEnableClientState(GL_VERTEX_ARRAY);
    glEnableClientState(GL_COLOR_ARRAY);
    glDrawArrays(GL_POLYGON, 0, 5);
    glDisableClientState(GL_VERTEX_ARRAY);
    glDisableClientState(GL_COLOR_ARRAY);
    book_shot("s3_arrays-pentagon", 2, 20);
    memcpy(first, book_px, sizeof first);
    check_corners("F13 corner colour");

    /* F14 */
    glClear(GL_COLOR_BUFFER_BIT);
    glEnableClientState(GL_VERTEX_ARRAY);
    glEnableClientState(GL_COLOR_ARRAY);
    glVertexPointer(2, GL_FLOAT, 5 * sizeof(GLfloat), &VC[0]);
    glColorPointer(3, GL_FLOAT, 5 * sizeof(GLfloat), &VC[2]);
    glDrawArrays(GL_POLYGON, 0, 5);
    glFinish();
    book_read();
    h_expect(memcmp(first, book_px, sizeof first) == 0, "F14 (interleaved) differs from F13");

    /* glArrayElement, also named in the chapter. */
    glClear(GL_COLOR_BUFFER_BIT);
    glBegin(GL_POLYGON);
    for (i = 0; i < 5; i++)
        glArrayElement(i);
    glEnd();
    glDisableClientState(GL_VERTEX_ARRAY);
    glDisableClientState(GL_COLOR_ARRAY);
    glFinish();
    book_read();
    h_expect(memcmp(first, book_px, sizeof first) == 0, "glArrayElement differs from glDrawArrays");
    h_expect_no_error("end");
    book_close();
    return h_finish();
}
