/* t_book_s3_transforms: the Russian textbook's chapters 10-11, coordinate
 * transformations and projections (seeds-inventory §3.5 F20-F26).
 *
 * BOOK: S3, Russian OpenGL textbook, ch. 10 "Coordinate transformations" (F20 glLoadMatrixf identity, F21 one matrix for scale+translate, F22/F23 rotate-then-translate vs translate-then-rotate, F24 gluLookAt, F25 four CAD views) and ch. 11 "Projections" (F26 reshape with gluPerspective)
 * SHOWS: a red square rotated 45 degrees and centred at (1.41,1.41) (F22) and a green one centred at (2,0) (F23); four viewports with front, top, side and perspective views of one object; the book's reshape with integer width/height (aspect 1 on a 3:2 window, so a sphere comes out 1.5 times wider than high) beside the corrected one
 * FEATURES: glLoadMatrixf (column-major), glLoadIdentity, glRotatef/glTranslatef order, gluLookAt, glGetDoublev(GL_MODELVIEW_MATRIX), glViewport per quadrant, glOrtho, glFrustum via gluPerspective, depth test
 *
 * Book slips (§6): the viewport centre is x + width/2, y + height/2 (not
 * y + height, #12); tan(fovy/2) = top/zNear (#14); F26's width/height on
 * ints is integer division (#15) -- ported as written, and shown.
 */
#include "book.h"

#define W 300
#define H 200

static void matrix_checks(void)
{
    GLfloat mId[4][4] = {{1, 0, 0, 0}, {0, 1, 0, 0}, {0, 0, 1, 0}, {0, 0, 0, 1}};
    GLfloat mST[4][4] = {{1, 0, 0, 0}, {0, 2, 0, 0}, {0, 0, 1, 0}, {3, 0, 4, 1}};
    GLfloat m[16];
    GLdouble mv[16], ex[3], f[3], s[3], u[3], len;
    int i;

    glMatrixMode(GL_MODELVIEW);
    glTranslatef(5, 6, 7);
    glLoadMatrixf(&mId[0][0]); /* F20 */
    glGetFloatv(GL_MODELVIEW_MATRIX, m);
    for (i = 0; i < 16; i++)
        h_expect(m[i] == ((i % 5 == 0) ? 1.0f : 0.0f), "F20: element %d is %g", i, m[i]);
    glLoadMatrixf(&mST[0][0]); /* F21: column-major, so x' = x + 3, y' = 2y, z' = z + 4 */
    glGetFloatv(GL_MODELVIEW_MATRIX, m);
    h_expect(m[5] == 2 && m[12] == 3 && m[13] == 0 && m[14] == 4, "F21: matrix %g %g %g %g", m[5],
             m[12], m[13], m[14]);
    glMultMatrixf(&mId[0][0]);
    glTranslatef(1, 1, 1); /* (1,1,1) in F21's space is (4, 2, 5) */
    glGetFloatv(GL_MODELVIEW_MATRIX, m);
    h_expect(m[12] == 4 && m[13] == 2 && m[14] == 5, "F21: (1,1,1) maps to %g,%g,%g, want 4,2,5",
             m[12], m[13], m[14]);

    /* F24: gluLookAt(2,1,3, 6,0,0, 0,1,0) against the definition (GLU 1.3
     * §4.2): rows s, u, -f, then a translation by -eye. */
    glLoadIdentity();
    gluLookAt(2, 1, 3, 6, 0, 0, 0, 1, 0);
    glGetDoublev(GL_MODELVIEW_MATRIX, mv);
    f[0] = 4; f[1] = -1; f[2] = -3;
    len = sqrt(f[0] * f[0] + f[1] * f[1] + f[2] * f[2]);
    for (i = 0; i < 3; i++) f[i] /= len;
    s[0] = -f[2]; s[1] = 0; s[2] = f[0]; /* f x (0,1,0) */
    len = sqrt(s[0] * s[0] + s[2] * s[2]);
    s[0] /= len; s[2] /= len;
    u[0] = s[1] * f[2] - s[2] * f[1]; u[1] = s[2] * f[0] - s[0] * f[2]; u[2] = s[0] * f[1] - s[1] * f[0];
    ex[0] = 2; ex[1] = 1; ex[2] = 3;
    for (i = 0; i < 3; i++) {
        h_expect(fabs(mv[4 * i + 0] - s[i]) < 1e-6 && fabs(mv[4 * i + 1] - u[i]) < 1e-6 &&
                     fabs(mv[4 * i + 2] + f[i]) < 1e-6,
                 "F24: gluLookAt column %d is %g %g %g", i, mv[4 * i], mv[4 * i + 1], mv[4 * i + 2]);
    }
    h_expect(fabs(mv[12] + (s[0] * ex[0] + s[1] * ex[1] + s[2] * ex[2])) < 1e-6 &&
                 fabs(mv[14] - (f[0] * ex[0] + f[1] * ex[1] + f[2] * ex[2])) < 1e-6,
             "F24: gluLookAt translation %g %g %g", mv[12], mv[13], mv[14]);
    glLoadIdentity();
}

static void quad(void) /* the book's square, listed clockwise */
{
    glBegin(GL_QUADS);
    glVertex2f(-1, 1); glVertex2f(1, 1); glVertex2f(1, -1); glVertex2f(-1, -1);
    glEnd();
}

static void order(void) /* F22, F23 */
{
    double x, y;
    glClear(GL_COLOR_BUFFER_BIT);
    book_ortho_unit(3);
    glTranslatef(-1.5f, -0.8f, 0); /* frame both squares */
    glPushMatrix();
    glRotatef(45, 0, 0, 1);
    glTranslatef(2, 0, 0);
    glColor3f(1, 0, 0);
    quad();
    glPopMatrix();
    glPushMatrix();
    glTranslatef(2, 0, 0);
    glRotatef(45, 0, 0, 1);
    glColor3f(0, 1, 0);
    glBlendFunc(GL_ONE, GL_ONE);
    glEnable(GL_BLEND); /* add, so the overlap shows both */
    quad();
    glDisable(GL_BLEND);
    glPopMatrix();
    book_shot("s3_transforms-order", 0, 0);
    book_project(1.41421356, 1.41421356 + 0.8, 0, &x, &y);
    book_expect_rgb((int)x, (int)y, 255, 0, 0, 0, "F22: centre (1.41,1.41) red only");
    book_project(2.6, -0.6, 0, &x, &y);
    book_expect_rgb((int)x, (int)y, 0, 255, 0, 0, "F23: near (2,0) green only");
    book_project(2, -1.3, 0, &x, &y);
    book_expect_rgb((int)x, (int)y, 0, 255, 0, 0, "F23: the green diamond's lower corner region");
    book_project(1.6, 0.5, 0, &x, &y);
    book_expect_rgb((int)x, (int)y, 255, 255, 0, 0, "F22+F23 overlap");
}

static void object(void)
{
    static const GLfloat c[6][3] = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}, {1, 1, 0}, {0, 1, 1}, {1, 0, 1}};
    /* a unit cube, faces coloured, and a "roof" */
    glBegin(GL_QUADS);
    glColor3fv(c[0]); glVertex3f(-1, -1, 1); glVertex3f(1, -1, 1); glVertex3f(1, 1, 1); glVertex3f(-1, 1, 1);
    glColor3fv(c[1]); glVertex3f(1, -1, -1); glVertex3f(-1, -1, -1); glVertex3f(-1, 1, -1); glVertex3f(1, 1, -1);
    glColor3fv(c[2]); glVertex3f(1, -1, 1); glVertex3f(1, -1, -1); glVertex3f(1, 1, -1); glVertex3f(1, 1, 1);
    glColor3fv(c[3]); glVertex3f(-1, -1, -1); glVertex3f(-1, -1, 1); glVertex3f(-1, 1, 1); glVertex3f(-1, 1, -1);
    glColor3fv(c[4]); glVertex3f(-1, 1, 1); glVertex3f(1, 1, 1); glVertex3f(1, 1, -1); glVertex3f(-1, 1, -1);
    glColor3fv(c[5]); glVertex3f(-1, -1, -1); glVertex3f(1, -1, -1); glVertex3f(1, -1, 1); glVertex3f(-1, -1, 1);
    glEnd();
}

static void four_views(void) /* F25 */
{
    int i;
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    glEnable(GL_DEPTH_TEST);
    for (i = 0; i < 4; i++) {
        glViewport((i % 2) * W / 2, (1 - i / 2) * H / 2, W / 2, H / 2);
        glMatrixMode(GL_PROJECTION);
        glLoadIdentity();
        if (i < 3)
            glOrtho(-2.25, 2.25, -1.5, 1.5, -10, 10);
        else
            gluPerspective(45, 1.5, 1, 20);
        glMatrixMode(GL_MODELVIEW);
        glLoadIdentity();
        if (i == 0) gluLookAt(0, 0, 5, 0, 0, 0, 0, 1, 0);  /* front */
        if (i == 1) gluLookAt(0, 5, 0, 0, 0, 0, 0, 0, -1); /* top */
        if (i == 2) gluLookAt(5, 0, 0, 0, 0, 0, 0, 1, 0);  /* side */
        if (i == 3) gluLookAt(4, 3, 5, 0, 0, 0, 0, 1, 0);  /* perspective */
        object();
    }
    glDisable(GL_DEPTH_TEST);
    book_shot("s3_transforms-four_views", 0, 8);
    book_expect_rgb(W / 4, 3 * H / 4, 255, 0, 0, 0, "F25 front view: the +z face (red)");
    book_expect_rgb(3 * W / 4, 3 * H / 4, 0, 255, 255, 0, "F25 top view: the +y face (cyan)");
    book_expect_rgb(W / 4, H / 4, 0, 0, 255, 0, "F25 side view: the +x face (blue)");
    book_expect_rgb(2, 2, 0, 0, 0, 0, "F25: corners empty");
}

/* Width and height of the lit region of the last book_read. */
static void extent(int *w, int *h)
{
    int x, y, x0 = W, x1 = -1, y0 = H, y1 = -1;
    for (y = 0; y < H; y++)
        for (x = 0; x < W; x++)
            if (book_at(x, y)[0]) {
                if (x < x0) x0 = x;
                if (x > x1) x1 = x;
                if (y < y0) y0 = y;
                if (y > y1) y1 = y;
            }
    *w = x1 - x0 + 1;
    *h = y1 - y0 + 1;
}

static void reshape(int width, int height) /* F26, as printed */
{
    glViewport(0, 0, width, height);
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    gluPerspective(45.0f, width / height, 0.1f, 100.0f);
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
}

static void perspective(void)
{
    GLUquadricObj *q = gluNewQuadric();
    int w1, h1, w2, h2;
    glClear(GL_COLOR_BUFFER_BIT);
    reshape(W, H); /* 300 / 200 = 1 */
    glTranslatef(0, 0, -6);
    glColor3f(1, 0.5f, 0);
    gluSphere(q, 1, 30, 30);
    glFinish();
    book_read();
    extent(&w1, &h1);
    book_shot("s3_transforms-reshape_int_aspect", 0, 0);
    glClear(GL_COLOR_BUFFER_BIT);
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    gluPerspective(45.0f, (double)W / H, 0.1f, 100.0f);
    glMatrixMode(GL_MODELVIEW);
    gluSphere(q, 1, 30, 30);
    book_shot("s3_transforms-reshape_fixed", 0, 0);
    extent(&w2, &h2);
    printf("  sphere: %dx%d with integer aspect, %dx%d with the real one\n", w1, h1, w2, h2);
    h_expect(fabs((double)w1 / h1 - 1.5) < 0.05, "F26: int aspect: sphere %dx%d should be 1.5 times wider", w1, h1);
    h_expect(abs(w2 - h2) <= 1, "fixed aspect: sphere %dx%d should be round", w2, h2);
    gluDeleteQuadric(q);
}

int main(void)
{
    book_open(W, H);
    matrix_checks();
    order();
    four_views();
    perspective();
    h_expect_no_error("end");
    book_close();
    return h_finish();
}
