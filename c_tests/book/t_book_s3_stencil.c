/* t_book_s3_stencil: the Russian textbook's stencil buffer section (§14.1,
 * seeds-inventory §3.5 F37, F38).
 *
 * BOOK: S3, Russian OpenGL textbook, ch. 14.1 "The stencil buffer", fragment F37 (a green triangle with a triangular window onto a gradient square) and its algorithm F38
 * SHOWS: a red/green/blue/magenta gradient square, covered by a green triangle with a smaller triangular hole through which the gradient shows
 * FEATURES: glClearStencil, glStencilMask, glClear(GL_STENCIL_BUFFER_BIT), GL_STENCIL_TEST, glStencilFunc(GL_NEVER, 2, 0) with glStencilOp(GL_REPLACE, ...), glStencilFunc(GL_NOTEQUAL, 2, 255), glReadPixels(GL_STENCIL_INDEX)
 *
 * The book says REPLACE writes the reference "set by glStencilOp" (§6 #27):
 * it is glStencilFunc's.  Checks: the stencil read back is 2 inside the
 * window and 1 elsewhere; inside the window the gradient shows; in the
 * triangle outside the window it is green.
 */
#include "book.h"

#define W 200
#define H 200

int main(void)
{
    static unsigned char st[W * H];
    double x, y;
    int i, inside = 0, ones = 0, other = 0;

    book_open(W, H);
    book_ortho_unit(2.2);
    glClearStencil(1);
    glStencilMask(0xFF);
    glClear(GL_COLOR_BUFFER_BIT | GL_STENCIL_BUFFER_BIT);
    glBegin(GL_QUADS);
    glColor3f(1, 0, 0); glVertex3f(2, 2, -0.1f);
    glColor3f(0, 1, 0); glVertex3f(-2, 2, -0.1f);
    glColor3f(0, 0, 1); glVertex3f(-2, -2, -0.1f);
    glColor3f(1, 0, 1); glVertex3f(2, -2, -0.1f);
    glEnd();
    glEnable(GL_STENCIL_TEST);
    glStencilFunc(GL_NEVER, 2, 0);
    glStencilOp(GL_REPLACE, GL_KEEP, GL_KEEP);
    glBegin(GL_POLYGON); /* the window: writes 2, draws nothing */
    glVertex2f(0, 1); glVertex2f(1, -1); glVertex2f(-1, -1);
    glEnd();
    glStencilFunc(GL_NOTEQUAL, 2, 255);
    glColor3f(0, 1, 0);
    glBegin(GL_POLYGON);
    glVertex2f(0, 1.6f); glVertex2f(-1.4f, -1.4f); glVertex2f(1.4f, -1.4f);
    glEnd();
    book_shot("s3_stencil-window", 1, 20);

    glPixelStorei(GL_PACK_ALIGNMENT, 1);
    glReadPixels(0, 0, W, H, GL_STENCIL_INDEX, GL_UNSIGNED_BYTE, st);
    for (i = 0; i < W * H; i++) {
        inside += st[i] == 2;
        ones += st[i] == 1;
        other += st[i] != 1 && st[i] != 2;
    }
    /* the window is a triangle of area 2 on a 4.4 x 4.4 view of 200 px */
    h_expect(other == 0 && fabs(inside - 2 * (200 / 4.4) * (200 / 4.4)) < 300,
             "stencil: %d pixels of 2 (window), %d of 1, %d other", inside, ones, other);
    book_project(0, -0.5, 0, &x, &y);
    h_expect(st[(int)y * W + (int)x] == 2, "stencil inside the window");
    h_expect(book_at((int)x, (int)y)[1] != 255 || book_at((int)x, (int)y)[0] != 0,
             "the window shows the gradient, not green");
    book_project(0, 1.3, 0, &x, &y);
    book_expect_rgb((int)x, (int)y, 0, 255, 0, 0, "green triangle above the window");
    book_project(-1.2, -1.2, 0, &x, &y);
    book_expect_rgb((int)x, (int)y, 0, 255, 0, 0, "green triangle left of the window");
    book_project(1.8, 1.8, 0, &x, &y);
    h_expect(book_at((int)x, (int)y)[0] > 200 && book_at((int)x, (int)y)[1] < 60,
             "gradient near its red corner outside the triangle");
    glDisable(GL_STENCIL_TEST);
    h_expect_no_error("end");
    book_close();
    return h_finish();
}
