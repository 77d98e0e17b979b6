/* t_book_s3_blend: the Russian textbook's transparency section (§13.4,
 * seeds-inventory §3.5 F35, F36).
 *
 * BOOK: S3, Russian OpenGL textbook, ch. 13.4 "Transparency": the alpha test (F35, GL_GREATER 0.4) and the blending demo (F36: an opaque red triangle seen through a 50% green square and a 50% blue rectangle)
 * SHOWS: left, F36: the red triangle visible through the green square and the blue rectangle; right, F35: of three white bars with alpha 0.3, 0.4 and 0.5 only the last passes GL_GREATER 0.4
 * FEATURES: glEnable(GL_BLEND), glBlendFunc(GL_SRC_ALPHA, GL_SRC_ALPHA) (the book's unusual pair), glColor4f, GL_ALPHA_TEST, glAlphaFunc
 *
 * F36 puts the square at z = 2, outside the unit cube: under an identity
 * projection it would be clipped away, so a camera with z in [-5, 5] is
 * used (the book's figure shows the square).  With alpha 0.5,
 * (SRC_ALPHA, SRC_ALPHA) is 0.5*src + 0.5*dst, checked for each overlap.
 */
#include "book.h"

#define W 360
#define H 180

int main(void)
{
    double x, y;
    book_open(W, H);
    glClear(GL_COLOR_BUFFER_BIT);
    glViewport(0, 0, H, H);
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    glOrtho(-2.2, 2.2, -2.2, 2.2, -5, 5);
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();

    /* F36 */
    glColor4f(1, 0, 0, 1);
    glBegin(GL_TRIANGLES);
    glVertex3f(0, 1.8f, 1); glVertex3f(-1.4f, -1.5f, 1); glVertex3f(1.4f, -1.5f, 1);
    glEnd();
    glEnable(GL_BLEND);
    glBlendFunc(GL_SRC_ALPHA, GL_SRC_ALPHA);
    glColor4f(0, 1, 0, 0.5f);
    glBegin(GL_QUADS);
    glVertex3f(-1, -1, 2); glVertex3f(1, -1, 2); glVertex3f(1, 1, 2); glVertex3f(-1, 1, 2);
    glEnd();
    glColor4f(0, 0, 1, 0.5f);
    glBegin(GL_QUADS);
    glVertex3f(-2, -0.5f, 0); glVertex3f(2, -0.5f, 0); glVertex3f(2, 0.5f, 0); glVertex3f(-2, 0.5f, 0);
    glEnd();
    glDisable(GL_BLEND);

    /* F35, right half: bars of alpha 0.3, 0.4, 0.5 */
    glViewport(H, 0, W - H, H);
    glLoadIdentity();
    glEnable(GL_ALPHA_TEST);
    glAlphaFunc(GL_GREATER, 0.4f);
    for (x = 0; x < 3; x++) {
        glColor4f(1, 1, 1, (GLfloat)(0.3 + 0.1 * x));
        glRectf((GLfloat)(-1.8 + 1.2 * x), -1.5f, (GLfloat)(-1.0 + 1.2 * x), 1.5f);
    }
    glDisable(GL_ALPHA_TEST);
    book_shot("s3_blend-transparency", 1, 10);

    glViewport(0, 0, H, H);
    book_project(0, 1.4, 0, &x, &y);
    book_expect_rgb((int)x, (int)y, 255, 0, 0, 0, "F36: red triangle alone");
    book_project(-0.9, 0.8, 0, &x, &y);
    book_expect_rgb((int)x, (int)y, 0, 128, 0, 1, "F36: square over black");
    book_project(0, 0.8, 0, &x, &y);
    book_expect_rgb((int)x, (int)y, 128, 128, 0, 1, "F36: square over red");
    book_project(-1.7, 0, 0, &x, &y);
    book_expect_rgb((int)x, (int)y, 0, 0, 128, 1, "F36: rectangle over black");
    /* (seeds-inventory also lists "rectangle over red only": with these
     * coordinates the triangle never leaves the square inside the band.) */
    book_project(-0.95, 0, 0, &x, &y);
    book_expect_rgb((int)x, (int)y, 0, 64, 128, 1, "F36: rectangle over square-on-black");
    book_project(0, 0, 0, &x, &y);
    book_expect_rgb((int)x, (int)y, 64, 64, 128, 1, "F36: rectangle over square-on-red");
    glViewport(H, 0, W - H, H);
    book_project(-1.4, 0, 0, &x, &y);
    book_expect_rgb((int)x, (int)y, 0, 0, 0, 0, "F35: alpha 0.3 fails GREATER 0.4");
    book_project(-0.2, 0, 0, &x, &y);
    book_expect_rgb((int)x, (int)y, 0, 0, 0, 0, "F35: alpha 0.4 fails GREATER 0.4");
    book_project(1.0, 0, 0, &x, &y);
    book_expect_rgb((int)x, (int)y, 255, 255, 255, 0, "F35: alpha 0.5 passes");
    h_expect_no_error("end");
    book_close();
    return h_finish();
}
