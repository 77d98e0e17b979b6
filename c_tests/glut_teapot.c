/* glut_teapot: an unmodified freeglut program, built against the system's
 * GL and GLUT (Mesa's headers, -lglut -lGL) and run by t_glx.sh with
 * LD_LIBRARY_PATH=build/lib, so that freeglut and the program both get
 * softgl's libGL.so.1 (issue 7: "a program using glutSolidTeapot and
 * glutBitmapCharacter").
 *
 * It draws a lit red teapot spinning about the vertical axis (a timer
 * turns it 7 degrees and asks for a redisplay every 30 ms) and a yellow
 * line of text; after each glutSwapBuffers it checks its own front buffer
 * with glReadPixels: the teapot's middle is lit red, the corners are the
 * clear colour, the text left yellow pixels (the colour latched at
 * glRasterPos). After 1.5 seconds it prints how many frames it drew and
 * exits 0 (or 1 on a failed check); the script looks at the X screen and
 * the SOFTGL_DUMP frames meanwhile.
 */
#include <GL/freeglut.h>
#include <stdio.h>
#include <stdlib.h>

#define W 240
#define H 240

static int failures, frames;
static float angle;

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
    glMaterialfv(GL_FRONT, GL_AMBIENT_AND_DIFFUSE, red);
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    glOrtho(-1, 1, -1, 1, -5, 5);
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
    /* The light stays put in eye space while the teapot turns. */
    glLightfv(GL_LIGHT0, GL_POSITION, light);
    glPushMatrix();
    glRotatef(20, 1, 0, 0);
    glRotatef(angle, 0, 1, 0);
    glutSolidTeapot(0.5);
    glPopMatrix();
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
        if (frames == 0)
            printf("renderer %s; middle %d %d %d, corner %d %d %d\n", (const char *)glGetString(GL_RENDERER),
                   c[0], c[1], c[2], k[0], k[1], k[2]);
        /* The middle 40x40 block is teapot (body or, seen from the side,
         * the handle), red and shaded by the light: lit red somewhere, and
         * not one flat colour. */
        int x, y, reds = 0, lo = 255, hi = 0;
        for (y = H / 2 - 20; y < H / 2 + 20; y++)
            for (x = W / 2 - 20; x < W / 2 + 20; x++) {
                const unsigned char *p = px + 4 * (y * W + x);
                if (p[0] > 40 && p[0] > 2 * p[1] && p[0] > 2 * p[2]) {
                    reds++;
                    lo = p[0] < lo ? p[0] : lo;
                    hi = p[0] > hi ? p[0] : hi;
                }
            }
        if (reds < 1600 || hi < 150 || hi - lo < 20)
            printf("frame %d (angle %g): %d red pixels in the middle, red %d..%d\n", frames, angle, reds, lo, hi);
        check(reds == 1600 && hi >= 150 && hi - lo >= 20, "the teapot's middle is not lit, shaded red");
        check(k[0] == 26 && k[1] == 26 && k[2] == 77, "the corner is not the clear colour (26, 26, 77)");
    }
    for (i = 0; i < W * 30; i++) {
        const unsigned char *p = px + 4 * i;
        yellow += p[0] > 200 && p[1] > 200 && p[2] < 60;
    }
    if (frames == 0)
        printf("yellow text pixels in the bottom rows: %d\n", yellow);
    check(yellow > 40, "no yellow text (glutBitmapCharacter with the latched raster colour)");
    check(glGetError() == GL_NO_ERROR, "a GL error");
    frames++;
}

static void spin(int value)
{
    (void)value;
    angle += 7;
    glutPostRedisplay();
    glutTimerFunc(30, spin, 0);
}

static void quit(int value)
{
    (void)value;
    printf("frames %d\n", frames);
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
    glutTimerFunc(30, spin, 0);
    glutTimerFunc(1500, quit, 0);
    glutMainLoop();
    return 2;
}
