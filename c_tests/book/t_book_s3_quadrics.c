/* t_book_s3_quadrics: the Russian textbook's chapter 6, ready-made 3-D
 * objects from GLU (seeds-inventory §2.18, §3.5 F12).
 *
 * BOOK: S3, Russian OpenGL textbook, ch. 6 "Drawing ready-made 3D objects" (gluNewQuadric, gluSphere, gluCylinder, gluDisk, gluPartialDisk), fragment F12
 * SHOWS: six panels: a lit sphere (40x40), the "interesting effect" of a 4x3 sphere, a tube, a cone (one radius 0), a disk with a hole, a partial disk from 0 (+y) sweeping 90 degrees to +x
 * FEATURES: gluNewQuadric/gluDeleteQuadric, gluSphere, gluCylinder, gluDisk, gluPartialDisk, gluQuadricDrawStyle, lighting, several viewports in one frame
 *
 * The book says gluPartialDisk's angles run counter-clockwise from +y;
 * GLU measures them clockwise seen from +z (0 = +y, 90 = +x, §6 #10):
 * GLU is followed, and checked.
 */
#include "book.h"

#define W 360
#define H 240
#define P 120 /* panel size */

static void panel(int i)
{
    glViewport((i % 3) * P, (1 - i / 3) * P, P, P);
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    glOrtho(-1.5, 1.5, -1.5, 1.5, -5, 5);
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
}

int main(void)
{
    static const GLfloat pos[] = {1, 1, 1, 0};
    GLUquadricObj *quadric_obj;
    double x, y;

    book_open(W, H);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    glEnable(GL_DEPTH_TEST);
    glEnable(GL_LIGHTING);
    glEnable(GL_LIGHT0);
    glLightfv(GL_LIGHT0, GL_POSITION, pos);

    quadric_obj = gluNewQuadric(); /* F12 */

    panel(0);
    gluSphere(quadric_obj, 1, 40, 40);
    panel(1);
    gluSphere(quadric_obj, 1, 4, 3);
    panel(2);
    glRotatef(-60, 1, 0, 0);
    glTranslatef(0, 0, -1);
    gluCylinder(quadric_obj, 0.7, 0.7, 2, 20, 4);
    panel(3);
    glRotatef(-60, 1, 0, 0);
    glTranslatef(0, 0, -1);
    gluCylinder(quadric_obj, 1, 0, 2, 20, 4);
    panel(4);
    gluDisk(quadric_obj, 0.4, 1.2, 20, 3);
    panel(5);
    glDisable(GL_LIGHTING);
    glColor3f(1, 0.8f, 0.2f);
    gluPartialDisk(quadric_obj, 0.3, 1.2, 20, 3, 0, 90);
    glEnable(GL_LIGHTING);
    gluDeleteQuadric(quadric_obj);
    book_shot("s3_quadrics-objects", 2, 30);

    /* The partial disk lies in the +x,+y quadrant of panel 5. */
    panel(5);
    book_project(0.5, 0.5, 0, &x, &y);
    book_expect_rgb((int)x, (int)y, 255, 204, 51, 1, "gluPartialDisk(0, 90) covers +x,+y");
    book_project(-0.5, 0.5, 0, &x, &y);
    book_expect_rgb((int)x, (int)y, 0, 0, 0, 0, "gluPartialDisk(0, 90) leaves -x,+y empty");
    book_project(0.5, -0.5, 0, &x, &y);
    book_expect_rgb((int)x, (int)y, 0, 0, 0, 0, "gluPartialDisk(0, 90) leaves +x,-y empty");
    /* The disk's hole, and its ring. */
    panel(4);
    book_project(0, 0, 0, &x, &y);
    book_expect_rgb((int)x, (int)y, 0, 0, 0, 0, "gluDisk inner radius 0.4: hole at the centre");
    book_project(0.8, 0, 0, &x, &y);
    h_expect(book_at((int)x, (int)y)[0] > 100, "gluDisk: ring lit (faces +z)");
    /* The sphere: brightest towards the light (1,1,1), dark at the far side. */
    panel(0);
    book_project(0.55, 0.55, 0.6, &x, &y);
    h_expect(book_at((int)x, (int)y)[0] > 200, "sphere lit towards the light: %d", book_at((int)x, (int)y)[0]);
    book_project(-0.7, -0.7, 0.1, &x, &y);
    h_expect(book_at((int)x, (int)y)[0] < 60, "sphere dark away from the light: %d", book_at((int)x, (int)y)[0]);
    h_expect_no_error("end");
    book_close();
    return h_finish();
}
