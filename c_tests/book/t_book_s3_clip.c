/* t_book_s3_clip: the Russian textbook's scissor, clip-plane and logic-op
 * sections (§5.8-5.10, seeds-inventory §3.5 F10, F11).
 *
 * BOOK: S3, Russian OpenGL textbook, ch. 5.8 "Clipping by a screen region" (F10), 5.9 "Clipping objects by planes" (F11), 5.10 "Logical operations"
 * SHOWS: glScissor(0,0,0,0) blocking all output; a square clipped by the planes {1,0,0,1} and {0,1,0,0}, leaving x >= -1 and y >= 0; overlapping squares combined with GL_XOR
 * FEATURES: glScissor/GL_SCISSOR_TEST, glClipPlane/GL_CLIP_PLANE0..1, glLogicOp/GL_COLOR_LOGIC_OP
 *
 * The book says the plane {1,0,0,1} cuts x < 1; the spec keeps the
 * points where x + 1 >= 0, so it cuts x < -1 (§6 #9): the spec is followed.
 * The logic-op section has no fragment: its picture is this port's own.
 */
#include "book.h"

#define W 240
#define H 240

static void square(GLfloat h)
{
    glBegin(GL_QUADS);
    glVertex2f(-h, -h); glVertex2f(h, -h); glVertex2f(h, h); glVertex2f(-h, h);
    glEnd();
}

int main(void)
{
    static const GLdouble P10[] = {1, 0, 0, 1}, P11[] = {0, 1, 0, 0};
    double x, y;
    int lit;

    book_open(W, H);
    book_ortho_unit(2.5);

    /* F10 */
    glClear(GL_COLOR_BUFFER_BIT);
    glEnable(GL_SCISSOR_TEST);
    glScissor(0, 0, 0, 0);
    glColor3f(1, 1, 1);
    square(2);
    glClearColor(1, 0, 0, 1);
    glClear(GL_COLOR_BUFFER_BIT); /* the clear is scissored too */
    glClearColor(0, 0, 0, 0);
    glDisable(GL_SCISSOR_TEST);
    book_read();
    h_expect(book_count(0, 0, W, H, 0, 0, 0, 0) == W * H, "F10: glScissor(0,0,0,0) let something through");

    /* F11 */
    glClear(GL_COLOR_BUFFER_BIT);
    glClipPlane(GL_CLIP_PLANE0, P10);
    glClipPlane(GL_CLIP_PLANE1, P11);
    glEnable(GL_CLIP_PLANE0);
    glEnable(GL_CLIP_PLANE1);
    glColor3f(0.2f, 0.6f, 1);
    square(2);
    glDisable(GL_CLIP_PLANE0);
    glDisable(GL_CLIP_PLANE1);
    glColor3f(1, 1, 1); /* the unclipped outline */
    glPolygonMode(GL_FRONT_AND_BACK, GL_LINE);
    square(2);
    glPolygonMode(GL_FRONT_AND_BACK, GL_FILL);
    book_shot("s3_clip-planes", 0, 0);
    book_project(-0.5, 1, 0, &x, &y);
    book_expect_rgb((int)x, (int)y, 51, 153, 255, 0, "F11: kept (x >= -1, y >= 0)");
    book_project(-1.5, 1, 0, &x, &y);
    book_expect_rgb((int)x, (int)y, 0, 0, 0, 0, "F11: cut (x < -1; the book says x < 1)");
    book_project(0.5, -1, 0, &x, &y);
    book_expect_rgb((int)x, (int)y, 0, 0, 0, 0, "F11: cut (y < 0)");
    book_project(1.5, 1.5, 0, &x, &y);
    book_expect_rgb((int)x, (int)y, 51, 153, 255, 0, "F11: kept, x = 1.5 > 1");
    lit = book_count(0, 0, W, H, 51, 153, 255, 0);
    /* The kept part is 3 x 2 of the 4 x 4 square: 3/8 of it. */
    book_project(-2, -2, 0, &x, &y);
    {
        double side = W / 2.0 - x;
        double want = 4 * side * side * 3 / 8;
        h_expect(fabs(lit - want) < side * 4, "F11: %d pixels kept, expected about %.0f", lit, want);
    }

    /* Logic op: XOR of a red and a green square, then a white one. */
    glClear(GL_COLOR_BUFFER_BIT);
    glEnable(GL_COLOR_LOGIC_OP);
    glLogicOp(GL_XOR);
    glColor3f(1, 0, 0);
    glPushMatrix(); glTranslatef(-0.6f, 0.4f, 0); square(1.2f); glPopMatrix();
    glColor3f(0, 1, 0);
    glPushMatrix(); glTranslatef(0.6f, 0.4f, 0); square(1.2f); glPopMatrix();
    glColor3f(1, 1, 1);
    glPushMatrix(); glTranslatef(0, -0.6f, 0); square(1.2f); glPopMatrix();
    glDisable(GL_COLOR_LOGIC_OP);
    book_shot("s3_clip-logic_xor", 0, 0);
    book_project(0, 0.2, 0, &x, &y);
    book_expect_rgb((int)x, (int)y, 0, 0, 255, 0, "XOR of red, green and white = blue");
    book_project(0, 1.3, 0, &x, &y);
    book_expect_rgb((int)x, (int)y, 255, 255, 0, 0, "XOR of red and green = yellow");
    book_project(-1.5, 1.3, 0, &x, &y);
    book_expect_rgb((int)x, (int)y, 255, 0, 0, 0, "red alone");
    book_project(0, -1.5, 0, &x, &y);
    book_expect_rgb((int)x, (int)y, 255, 255, 255, 0, "white alone");
    h_expect_no_error("end");
    book_close();
    return h_finish();
}
