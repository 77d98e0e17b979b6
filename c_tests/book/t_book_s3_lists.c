/* t_book_s3_lists: the Russian textbook's chapter 8, display lists
 * (seeds-inventory §3.5 F15-F17).
 *
 * BOOK: S3, Russian OpenGL textbook, ch. 8 "Display lists", fragments F15 (a red square in list 2), F16 (nested lists, list 2 redefined), F17 (glDeleteLists)
 * SHOWS: a red square of side 2; then a green triangle (list 1) and a red triangle (the redefined list 2) drawn through list 3, red on top where they overlap
 * FEATURES: glNewList(GL_COMPILE), glEndList, glCallList, nested lists, redefining a list, glCallLists with glListBase, glGenLists, glIsList, glDeleteLists
 *
 * The book writes glCallList(n,type,lists) and glGenList: the spec's
 * glCallLists and glGenLists are meant (§6 #11).
 */
#include "book.h"

#define W 200
#define H 200

int main(void)
{
    static const GLubyte order[3] = {1, 0, 1};
    double x, y;
    GLuint base;

    book_open(W, H);
    book_ortho_unit(2.2);

    /* F15 */
    glClear(GL_COLOR_BUFFER_BIT);
    glNewList(2, GL_COMPILE);
    glColor3f(1, 0, 0);
    glBegin(GL_POLYGON);
    glVertex2f(1, 1); glVertex2f(-1, 1); glVertex2f(-1, -1); glVertex2f(1, -1);
    glEnd();
    glEndList();
    book_read();
    h_expect(book_count(0, 0, W, H, 0, 0, 0, 0) == W * H, "GL_COMPILE drew something");
    glCallList(2);
    book_shot("s3_lists-square", 0, 0);
    book_project(0.9, 0.9, 0, &x, &y);
    book_expect_rgb((int)x, (int)y, 255, 0, 0, 0, "F15: inside the square");
    book_project(1.1, 0.9, 0, &x, &y);
    book_expect_rgb((int)x, (int)y, 0, 0, 0, 0, "F15: outside the square");

    /* F16 */
    glClear(GL_COLOR_BUFFER_BIT);
    glNewList(1, GL_COMPILE);
    glColor3f(0, 1, 0);
    glBegin(GL_TRIANGLES);
    glVertex2f(1, 2); glVertex2f(-1, 2); glVertex2f(-1, -2);
    glEnd();
    glEndList();
    glNewList(2, GL_COMPILE);
    glColor3f(1, 0, 0);
    glBegin(GL_TRIANGLES);
    glVertex2f(1, 1); glVertex2f(-1, -1); glVertex2f(1, -1);
    glEnd();
    glEndList();
    glNewList(3, GL_COMPILE);
    glCallList(1);
    glCallList(2);
    glEndList();
    glCallList(3);
    book_shot("s3_lists-nested", 0, 0);
    book_project(-0.5, 1.5, 0, &x, &y);
    book_expect_rgb((int)x, (int)y, 0, 255, 0, 0, "F16: green triangle");
    book_project(0.5, -0.5, 0, &x, &y);
    book_expect_rgb((int)x, (int)y, 255, 0, 0, 0, "F16: red triangle (list 2 redefined)");
    book_project(0.2, 0.1, 0, &x, &y);
    book_expect_rgb((int)x, (int)y, 255, 0, 0, 0, "F16: overlap, red drawn last");
    book_project(0.9, -1.5, 0, &x, &y);
    book_expect_rgb((int)x, (int)y, 0, 0, 0, 0, "F16: nothing below the red triangle");

    /* glCallLists with glListBase: lists 1, 0+1, 1 -> 2, 1, 2. */
    glListBase(1);
    glClear(GL_COLOR_BUFFER_BIT);
    glCallLists(3, GL_UNSIGNED_BYTE, order);
    glListBase(0);
    book_read();
    book_project(0.5, -0.5, 0, &x, &y);
    book_expect_rgb((int)x, (int)y, 255, 0, 0, 0, "glCallLists: red (list 2) drawn last");

    /* F17 */
    base = glGenLists(6);
    h_expect(base != 0, "glGenLists(6) returned 0");
    for (x = 0; x < 6; x++) {
        glNewList(base + (GLuint)x, GL_COMPILE);
        glEndList();
    }
    glDeleteLists(base + 3, 3);
    h_expect(glIsList(base + 2) && !glIsList(base + 3) && !glIsList(base + 5),
             "glDeleteLists(4,3)-style delete: lists base+3..5 must be gone, base+2 kept");
    h_expect_no_error("end");
    book_close();
    return h_finish();
}
