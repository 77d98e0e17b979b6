/* t_book_s3_unproject: the Russian textbook's chapter 12, from window back
 * to object coordinates (seeds-inventory §3.5 F27).
 *
 * BOOK: S3, Russian OpenGL textbook, ch. 12 "Inverse transformation of window coordinates to object coordinates", fragment F27 (mouse to the near plane with gluUnProject)
 * SHOWS: a tilted grid under a perspective camera with three "clicks": each unprojected at the depth read back under the mouse and marked with a white cross, which lands on the clicked pixel; a yellow cross where the book's unflipped mouse y lands instead
 * FEATURES: gluUnProject, gluUnProject4, gluProject, glGetIntegerv(GL_VIEWPORT), glGetDoublev(GL_MODELVIEW_MATRIX/GL_PROJECTION_MATRIX), glReadPixels(GL_DEPTH_COMPONENT, GL_FLOAT), glDepthRange
 *
 * The book's snippet passes the mouse y (top-down) straight to
 * gluUnProject; window y runs bottom-up, so it must be flipped
 * (y = viewport[3] - 1 - mouse_y).  Both are drawn: the flipped click
 * lands where the mouse is, the unflipped one mirrored about the middle.
 */
#include "book.h"

#define W 240
#define H 240

static void scene(void)
{
    int i;
    glBegin(GL_QUADS);
    glColor3f(0.2f, 0.4f, 0.8f);
    glVertex3f(-2, 0, 2); glVertex3f(2, 0, 2); glVertex3f(2, 0, -2); glVertex3f(-2, 0, -2);
    glEnd();
    glColor3f(0.6f, 0.8f, 1);
    glBegin(GL_LINES);
    for (i = -2; i <= 2; i++) {
        glVertex3f((GLfloat)i, 0.001f, -2); glVertex3f((GLfloat)i, 0.001f, 2);
        glVertex3f(-2, 0.001f, (GLfloat)i); glVertex3f(2, 0.001f, (GLfloat)i);
    }
    glEnd();
}

static void cross(GLdouble x, GLdouble y, GLdouble z)
{
    glBegin(GL_LINES);
    glVertex3d(x - 0.15, y, z); glVertex3d(x + 0.15, y, z);
    glVertex3d(x, y, z - 0.15); glVertex3d(x, y, z + 0.15);
    glEnd();
}

int main(void)
{
    static const int mouse[3][2] = {{120, 150}, {60, 170}, {180, 120}}; /* top-down, like WM_ mouse messages */
    GLint viewport[4];
    GLdouble mv[16], proj[16], ox, oy, oz, ow, wx, wy, wz, nx, ny, nz;
    GLfloat depth;
    int i;

    book_open(W, H);
    glEnable(GL_DEPTH_TEST);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    gluPerspective(50, 1, 1, 20);
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
    gluLookAt(0, 3, 5, 0, 0, 0, 0, 1, 0);
    scene();

    /* F27 */
    glGetIntegerv(GL_VIEWPORT, viewport);
    glGetDoublev(GL_MODELVIEW_MATRIX, mv);
    glGetDoublev(GL_PROJECTION_MATRIX, proj);
    for (i = 0; i < 3; i++) {
        int x = mouse[i][0], y = viewport[3] - 1 - mouse[i][1];
        h_expect(gluUnProject(x + 0.5, y + 0.5, 0.0, mv, proj, viewport, &nx, &ny, &nz) == GL_TRUE,
                 "gluUnProject failed");
        /* winz 0 is the near plane: eye z = -1 */
        gluProject(nx, ny, nz, mv, proj, viewport, &wx, &wy, &wz);
        h_expect(fabs(wz) < 1e-6 && fabs(wx - x - 0.5) < 1e-6, "near-plane point reprojects to %g,%g,%g",
                 wx, wy, wz);
        glReadPixels(x, y, 1, 1, GL_DEPTH_COMPONENT, GL_FLOAT, &depth);
        gluUnProject(x + 0.5, y + 0.5, depth, mv, proj, viewport, &ox, &oy, &oz);
        h_expect(fabs(oy) < 0.02, "click %d: unprojected point (%g,%g,%g) should lie on the floor y = 0", i,
                 ox, oy, oz);
        h_expect(gluUnProject4(x + 0.5, y + 0.5, depth, 1.0, mv, proj, viewport, 0.0, 1.0, &wx, &wy, &wz,
                               &ow) == GL_TRUE &&
                     fabs(wx / ow - ox) < 1e-4 && fabs(wz / ow - oz) < 1e-4,
                 "gluUnProject4 disagrees with gluUnProject");
        glColor3f(1, 1, 1);
        cross(ox, 0.01, oz);
        /* the book's unflipped y */
        glReadPixels(x, mouse[i][1], 1, 1, GL_DEPTH_COMPONENT, GL_FLOAT, &depth);
        if (depth < 1) {
            gluUnProject(x + 0.5, mouse[i][1] + 0.5, depth, mv, proj, viewport, &ox, &oy, &oz);
            glColor3f(1, 1, 0);
            cross(ox, 0.01, oz);
        }
    }
    book_shot("s3_unproject-clicks", 0, 16);
    for (i = 0; i < 3; i++)
        book_expect_rgb(mouse[i][0], H - 1 - mouse[i][1], 255, 255, 255, 0, "the cross is on the clicked pixel");
    h_expect_no_error("end");
    book_close();
    return h_finish();
}
