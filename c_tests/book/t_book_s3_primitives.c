/* t_book_s3_primitives: the Russian textbook's chapter 5 fragments on
 * primitives and their rasterization controls (seeds-inventory §3.5 F02-F06).
 *
 * BOOK: S3, Russian OpenGL textbook, ch. 5.1-5.6 (primitives, point size, line width and stipple, faces, polygon stipple), fragments F02-F06
 * SHOWS: a per-vertex coloured "quad" whose 4th vertex makes it a triangle; a 3-pixel round point; dotted yellow lines (0xAAAA factor 1 and 20, 0x00FF); culling keeping only the red triangle (or, with glCullFace(GL_FRONT), only the green square); a quadrilateral filled with the book's 32x32 stipple
 * FEATURES: glBegin modes QUADS/TRIANGLES/POLYGON/LINES/POINTS, smooth shading, glPointSize with GL_POINT_SMOOTH, glLineStipple, GL_CULL_FACE/glCullFace, glPolygonStipple, invalid glEnable(GL_POINTS)/glEnable(GL_LINES)
 *
 * Where the book contradicts the spec the spec wins (§6): glEnable(GL_POINTS)
 * and glEnable/glDisable(GL_LINES) are GL_INVALID_ENUM and do nothing;
 * stipple 0x00FF starts with 8 pixels ON (LSB first), not off; the front
 * face is counter-clockwise.
 */
#include "book.h"

#define W 300
#define H 200

static void quad_fragment(void) /* F02, S3:498-510 */
{
    static const GLfloat Green[3] = {0, 1, 0};
    glClearColor(0, 0, 0, 0);
    glClear(GL_COLOR_BUFFER_BIT);
    book_ortho_unit(1.2);
    glTranslatef(-0.5f, -0.5f, 0);
    glBegin(GL_QUADS);
    glColor3f(1, 0, 0); glVertex3f(0, 0, 0);
    glColor3f(1, 1, 1); glVertex3f(1, 0, 0);
    glColor3fv(Green);  glVertex3f(1, 1, 0);
    glColor3f(0, 0, 1); glVertex3f(1, 1, 1); /* as printed: (0,1,0) was surely meant */
    glEnd();
    h_expect_no_error("F02");
    book_shot("s3_primitives-quad", 2, 40);
    {
        double x, y;
        book_project(0.25, 0.75, 0, &x, &y);
        book_expect_rgb((int)x, (int)y, 0, 0, 0, 0, "F02: above the diagonal nothing is drawn");
        book_project(0.05, 0.02, 0, &x, &y);
        book_expect_rgb((int)x, (int)y, 255, 20, 20, 25, "F02: near vertex 1 the colour is red");
        book_project(0.75, 0.25, 0, &x, &y);
        h_expect(book_at((int)x, (int)y)[0] > 100, "F02: inside the triangle is lit");
    }
}

static void points_and_lines(void) /* F03 S3:569-581, F04 S3:620-643 */
{
    int x, ly, bad = 0;
    glClear(GL_COLOR_BUFFER_BIT);
    book_ortho_pixels();
    glColor3f(1, 1, 1);
    glEnable(GL_POINTS);
    h_expect_error(GL_INVALID_ENUM, "F03: glEnable(GL_POINTS)");
    glEnable(GL_POINT_SMOOTH);
    glPointSize(3.0f);
    glBegin(GL_POINTS);
    glVertex2i(100, 100);
    glEnd();
    glDisable(GL_POINT_SMOOTH);

    glLineStipple(1, 0xAAAA);
    glEnable(GL_LINE_STIPPLE);
    glEnable(GL_LINES);
    h_expect_error(GL_INVALID_ENUM, "F04: glEnable(GL_LINES)");
    glBegin(GL_LINES);
    glColor3f(1, 1, 0);
    glVertex2i(40, 120);
    glVertex2i(240, 120);
    glEnd();
    glDisable(GL_LINES);
    h_expect_error(GL_INVALID_ENUM, "F04: glDisable(GL_LINES)");
    /* The text's other examples: factor 20, and 0x00FF. */
    glLineStipple(20, 0xAAAA);
    glBegin(GL_LINES);
    glVertex2i(40, 150);
    glVertex2i(280, 150);
    glEnd();
    glLineStipple(1, 0x00FF);
    glBegin(GL_LINES);
    glVertex2i(40, 170);
    glVertex2i(104, 170);
    glEnd();
    glDisable(GL_LINE_STIPPLE);
    h_expect(!glIsEnabled(GL_LINE_STIPPLE), "line stipple still enabled");
    book_shot("s3_primitives-point_lines", 0, 12);

    /* A 3-px point centred on the corner (100,100): the four pixels
     * around it are covered whether or not it is smoothed. */
    book_expect_rgb(99, 99, 255, 255, 255, 0, "F03: 3-px point");
    book_expect_rgb(100, 99, 255, 255, 255, 0, "F03: 3-px point");
    book_expect_rgb(99, 100, 255, 255, 255, 0, "F03: 3-px point");
    book_expect_rgb(100, 100, 255, 255, 255, 0, "F03: 3-px point");
    book_expect_rgb(103, 100, 0, 0, 0, 0, "F03: nothing 3 px away");
    /* The lines lie on pixel-row boundaries (integer y under
     * gluOrtho2D(0,w,0,h)): the row below or above may get them. */
    ly = book_count(40, 119, 240, 120, 255, 255, 0, 0) ? 119 : 120;
    h_expect(book_count(40, ly, 240, ly + 1, 255, 255, 0, 0) == 100,
             "F04: the 0xAAAA line has %d pixels, expected 100",
             book_count(40, ly, 240, ly + 1, 255, 255, 0, 0));
    /* 0xAAAA, LSB first: pixel 0 off, pixel 1 on, ... */
    for (x = 40; x < 240; x++) {
        int on = ((x - 40) & 1) == 1;
        const unsigned char *p = book_at(x, ly);
        if ((p[0] == 255 && p[1] == 255 && p[2] == 0) != on) bad++;
    }
    h_expect(bad == 0, "F04: %d pixels of the 0xAAAA line break the pattern", bad);
    bad = 0;
    for (x = 40; x < 280; x++) {
        int on = (((x - 40) / 20) & 1) == 1;
        if ((book_at(x, ly + 30)[1] == 255) != on) bad++;
    }
    h_expect(bad == 0, "F04: %d pixels of the factor-20 line break the pattern", bad);
    bad = 0;
    for (x = 40; x < 104; x++) {
        int on = ((x - 40) % 16) < 8; /* 0x00FF: first 8 ON (the book says off) */
        if ((book_at(x, ly + 50)[1] == 255) != on) bad++;
    }
    h_expect(bad == 0, "0x00FF: %d pixels break the pattern (first 8 pixels on)", bad);
}

static void faces(int cull_front) /* F05, S3:672-694 */
{
    glClear(GL_COLOR_BUFFER_BIT);
    book_ortho_pixels();
    glEnable(GL_CULL_FACE);
    if (cull_front)
        glCullFace(GL_FRONT);
    glColor3f(1, 0, 0);
    glBegin(GL_TRIANGLES); /* counter-clockwise */
    glVertex2i(100, 100); glVertex2i(50, 50); glVertex2i(150, 50);
    glEnd();
    glColor3f(0, 1, 0);
    glBegin(GL_QUADS); /* clockwise */
    glVertex2i(200, 100); glVertex2i(250, 100); glVertex2i(250, 50); glVertex2i(200, 50);
    glEnd();
    glDisable(GL_CULL_FACE);
    glCullFace(GL_BACK);
    book_shot(cull_front ? "s3_primitives-cull_front" : "s3_primitives-cull_back", 0, 0);
    book_expect_rgb(100, 60, cull_front ? 0 : 255, 0, 0, 0, "F05: red triangle");
    book_expect_rgb(225, 75, 0, cull_front ? 255 : 0, 0, 0, "F05: green square");
}

static void stipple(void) /* F06, S3:711-744 */
{
    static GLubyte BitMap[128];
    int i, x, y, bad = 0, lit = 0;
    for (i = 0; i < 32; i++) {
        GLubyte b = (i % 4 == 0) ? 0xff : (i % 4 == 2) ? 0x00 : 0x01;
        BitMap[4 * i] = BitMap[4 * i + 1] = BitMap[4 * i + 2] = BitMap[4 * i + 3] = b;
    }
    glClear(GL_COLOR_BUFFER_BIT);
    book_ortho_pixels();
    glPushMatrix();
    glScalef(2, 2, 1); /* the book's 100x70 polygon, doubled to be seen */
    glColor3f(1, 1, 1);
    glEnable(GL_POLYGON_STIPPLE);
    glPolygonStipple(BitMap);
    glBegin(GL_POLYGON);
    glVertex2i(10, 10); glVertex2i(30, 60); glVertex2i(100, 70); glVertex2i(80, 20);
    glEnd();
    glDisable(GL_POLYGON_STIPPLE);
    glPopMatrix();
    book_shot("s3_primitives-stipple", 0, 0);
    /* Inside the polygon (a box well inside it): the pattern, anchored at
     * window (0,0), MSB first. */
    for (y = 60; y < 110; y++)
        for (x = 90; x < 150; x++) {
            int want = (y % 4 == 0) || ((y % 4 == 1 || y % 4 == 3) && x % 8 == 7);
            int got = book_at(x, y)[0] == 255;
            lit += got;
            if (want != got) bad++;
        }
    h_expect(bad == 0 && lit > 0, "F06: %d pixels break the stipple pattern", bad);
}

int main(void)
{
    book_open(W, H);
    quad_fragment();
    points_and_lines();
    faces(0);
    faces(1);
    stipple();
    h_expect_no_error("end");
    book_close();
    return h_finish();
}
