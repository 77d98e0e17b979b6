/* t_book_s3_lighting: the Russian textbook's lighting section (§13.2,
 * seeds-inventory §3.5 F32, F33).
 *
 * BOOK: S3, Russian OpenGL textbook, ch. 13.2 "Working with light": glMaterial (F32, a purple material), glLight and the lit sphere (F33), glLightModel
 * SHOWS: left, the lit sphere of F33 (default grey material, white specular highlight of exponent 40, light at (1,1,1)); right, the same sphere with F32's purple material (shininess 90) and a local viewer; unlit parts keep the ambient term
 * FEATURES: glMaterialfv AMBIENT/DIFFUSE/SPECULAR/SHININESS, glLightfv POSITION/AMBIENT/DIFFUSE/SPECULAR, positional light, GL_LIGHT_MODEL_LOCAL_VIEWER (default FALSE), gluSphere normals, depth test
 *
 * F32's arrays have 3 elements where glMaterialfv reads 4 (the 4th comes
 * from whatever follows in memory): the port gives them alpha 1.  The book
 * says LOCAL_VIEWER defaults to TRUE (§6 #25); the spec's FALSE is checked.
 * F33's Resize is not shown: an orthographic camera frames the sphere.
 */
#include "book.h"

#define W 320
#define H 160

int main(void)
{
    GLfloat m_specular[] = {1, 1, 1, 1}, m_shininess[] = {40};
    GLfloat Ambient[] = {0.5f, 0.5f, 0.5f, 1}, Diffuse[] = {1, 1, 1, 1}, Specular[] = {1, 1, 1, 1};
    GLfloat Position[] = {1, 1, 1, 1};
    float amb[] = {0.4f, 0.3f, 0.4f, 1}, dif[] = {0.7f, 0.4f, 0.7f, 1}, spec[] = {0.5f, 0.5f, 0.2f, 1};
    GLUquadricObj *quadratic;
    GLint lv = -1;
    double x, y;
    int i, maxv = 0;

    book_open(W, H);
    glGetIntegerv(GL_LIGHT_MODEL_LOCAL_VIEWER, &lv);
    h_expect(lv == GL_FALSE, "GL_LIGHT_MODEL_LOCAL_VIEWER defaults to %d (the book says TRUE)", lv);

    /* F33 Initial(w, h) */
    glClearColor(0, 0, 0, 0);
    glMaterialfv(GL_FRONT, GL_SPECULAR, m_specular);
    glMaterialfv(GL_FRONT, GL_SHININESS, m_shininess);
    glLightfv(GL_LIGHT0, GL_POSITION, Position);
    glLightfv(GL_LIGHT0, GL_AMBIENT, Ambient);
    glLightfv(GL_LIGHT0, GL_DIFFUSE, Diffuse);
    glLightfv(GL_LIGHT0, GL_SPECULAR, Specular);
    glEnable(GL_LIGHTING);
    glEnable(GL_LIGHT0);
    glEnable(GL_DEPTH_TEST);

    /* F33 DrawPrim, in the left half */
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    glViewport(0, 0, W / 2, H);
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    glOrtho(-1.25, 1.25, -1.25, 1.25, -5, 5);
    glMatrixMode(GL_MODELVIEW);
    quadratic = gluNewQuadric();
    gluSphere(quadratic, 1, 40, 40);
    /* checks on the left sphere: dark side = ambient only:
     * 0.2 (material) * (0.2 global + 0.5 light) = 0.14 -> 36 */
    book_project(-0.6, -0.6, 0.53, &x, &y);
    book_expect_rgb((int)x, (int)y, 36, 36, 36, 2, "F33 unlit side: ambient 0.14");

    /* F32's material, right half, local viewer */
    glMaterialfv(GL_FRONT, GL_AMBIENT, amb);
    glMaterialfv(GL_FRONT, GL_DIFFUSE, dif);
    glMaterialfv(GL_FRONT, GL_SPECULAR, spec);
    glMaterialf(GL_FRONT, GL_SHININESS, 90);
    glLightModeli(GL_LIGHT_MODEL_LOCAL_VIEWER, GL_TRUE);
    glViewport(W / 2, 0, W / 2, H);
    gluSphere(quadratic, 1, 40, 40);
    gluDeleteQuadric(quadratic);
    book_shot("s3_lighting-spheres", 2, 30);

    /* F32's dark side: 0.4,0.3,0.4 * (0.2 + 0.5) = 0.28,0.21,0.28 */
    book_project(-0.6, -0.6, 0.53, &x, &y);
    book_expect_rgb((int)x, (int)y, 71, 54, 71, 2, "F32 unlit side: ambient (0.28,0.21,0.28)");
    /* F33 highlight: some pixel of the left sphere reaches white */
    for (i = 0; i < W / 2 * H; i++) {
        const unsigned char *p = book_px + 4 * ((i / (W / 2)) * W + i % (W / 2));
        if (p[2] > maxv) maxv = p[2];
    }
    h_expect(maxv >= 250, "F33: no white specular highlight (max blue %d)", maxv);
    h_expect_no_error("end");
    book_close();
    return h_finish();
}
