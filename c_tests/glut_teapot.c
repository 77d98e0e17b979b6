/* glut_teapot: an unmodified freeglut program, built against the system's
 * GL and GLUT (Mesa's headers, -lglut -lGL) and run by t_glx.sh with
 * LD_LIBRARY_PATH=build/lib, so that freeglut and the program both get
 * softgl's libGL.so.1 (issue 7: "a program using glutSolidTeapot and
 * glutBitmapCharacter").
 *
 * It draws a lit red teapot and a yellow line of text, swaps, then checks
 * its own front buffer with glReadPixels: the teapot's middle is lit red,
 * the corners are the clear colour, the text left yellow pixels (the
 * colour latched at glRasterPos). It stays on the screen for a moment so
 * the script can look at the X screen, then exits 0 (or 1 on a failed check).
 */
#include <GL/freeglut.h>
#include <stdio.h>
#include <stdlib.h>

#define W 240
#define H 240

static int failures;

static void check(int cond, const char *what)
{
    if (!cond) {
        printf("failure: %s\n", what);
        failures++;
    }
}

static void display(void)
{
    static const GLfloat light[4] = {1, 1, 1, 0}, red[4] = {0.9f, 0.15f, 0.1f, 1};
    static unsigned char px[W * H * 4];
    const char *s = "softgl teapot";
    int i, yellow = 0;

    glClearColor(0.1f, 0.1f, 0.3f, 1);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    glEnable(GL_DEPTH_TEST);
    glEnable(GL_LIGHTING);
    glEnable(GL_LIGHT0);
    glLightfv(GL_LIGHT0, GL_POSITION, light);
    glMaterialfv(GL_FRONT, GL_AMBIENT_AND_DIFFUSE, red);
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    glOrtho(-1, 1, -1, 1, -5, 5);
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
    glRotatef(20, 1, 0, 0);
    glutSolidTeapot(0.5);
    glDisable(GL_LIGHTING);
    glDisable(GL_DEPTH_TEST);
    glColor3f(1, 1, 0);
    glRasterPos2f(-0.9f, -0.9f);
    glColor3f(0, 1, 1); /* too late: the raster colour is latched */
    for (i = 0; s[i]; i++)
        glutBitmapCharacter(GLUT_BITMAP_9_BY_15, s[i]);
    glutSwapBuffers();

    glReadBuffer(GL_FRONT);
    glReadPixels(0, 0, W, H, GL_RGBA, GL_UNSIGNED_BYTE, px);
    {
        const unsigned char *c = px + 4 * ((H / 2) * W + W / 2), *k = px;
        printf("renderer %s; middle %d %d %d, corner %d %d %d\n", (const char *)glGetString(GL_RENDERER),
               c[0], c[1], c[2], k[0], k[1], k[2]);
        check(c[0] > 80 && c[0] > c[1] + 40 && c[0] > c[2] + 40, "the teapot's middle is not lit red");
        check(k[0] == 26 && k[1] == 26 && k[2] == 77, "the corner is not the clear colour (26, 26, 77)");
    }
    for (i = 0; i < W * 30; i++) {
        const unsigned char *p = px + 4 * i;
        yellow += p[0] > 200 && p[1] > 200 && p[2] < 60;
    }
    printf("yellow text pixels in the bottom rows: %d\n", yellow);
    check(yellow > 40, "no yellow text (glutBitmapCharacter with the latched raster colour)");
    check(glGetError() == GL_NO_ERROR, "a GL error");
}

static void quit(int value)
{
    (void)value;
    exit(failures ? 1 : 0);
}

int main(int argc, char **argv)
{
    glutInit(&argc, argv);
    glutInitDisplayMode(GLUT_RGB | GLUT_DOUBLE | GLUT_DEPTH);
    glutInitWindowSize(W, H);
    glutInitWindowPosition(0, 0);
    glutCreateWindow("glut_teapot");
    glutDisplayFunc(display);
    glutTimerFunc(1500, quit, 0);
    glutMainLoop();
    return 2;
}
