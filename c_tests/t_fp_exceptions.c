/* t_fp_exceptions: a program that unmasks floating-point exceptions (as
 * Delphi and Free Pascal programs do by default) still runs through softgl
 * without a SIGFPE, and gets its own floating-point environment back.
 *
 * The scene does what produces NaNs, infinities and divisions by zero
 * inside an implementation: singular matrices (the book's glScalef(1, 0, 1)
 * shadow), lit and normalized zero normals, a projection with w = 0 at a
 * vertex, fog, spot lights, GLU quadrics and a self-intersecting
 * tessellated polygon. It checks that something was drawn, that the
 * program's exception masks are unchanged after each call, and that no
 * exception flag raised inside softgl leaked into the program's status.
 */
#define _GNU_SOURCE
#include "harness.h"
#include <GL/glu.h>
#include <fenv.h>
#include <signal.h>
#include <stdio.h>
#include <stdlib.h>

#define W 64
#define H 64
#define TRAPS (FE_INVALID | FE_DIVBYZERO | FE_OVERFLOW)

static void on_fpe(int sig)
{
    (void)sig;
    printf("FAIL t_fp_exceptions: SIGFPE inside softgl\n");
    fflush(stdout);
    _Exit(1);
}

static void GLAPIENTRY tess_vertex(void *v) { glVertex3dv((const GLdouble *)v); }

static void GLAPIENTRY tess_combine(GLdouble c[3], void *d[4], GLfloat w[4], void **out)
{
    static GLdouble store[64][3];
    static int n;
    (void)d; (void)w;
    GLdouble *p = store[n++ % 64];
    p[0] = c[0]; p[1] = c[1]; p[2] = c[2];
    *out = p;
}

int main(void)
{
    h_init(W, H);
#if !defined(__x86_64__) && !defined(__i386__)
    h_skip("floating-point traps are tested on x86 only");
#endif
    signal(SIGFPE, on_fpe);
    feclearexcept(FE_ALL_EXCEPT);
    if (feenableexcept(TRAPS) == -1)
        h_skip("feenableexcept not available");

    glClearColor(0, 0, 0, 1);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    glEnable(GL_DEPTH_TEST);
    glEnable(GL_LIGHTING);
    glEnable(GL_LIGHT0);
    glEnable(GL_NORMALIZE);
    glEnable(GL_FOG);
    glFogi(GL_FOG_MODE, GL_EXP2);
    glFogf(GL_FOG_DENSITY, 0.1f);
    GLfloat spot[] = {0, 0, -1};
    glLightfv(GL_LIGHT0, GL_SPOT_DIRECTION, spot);
    glLightf(GL_LIGHT0, GL_SPOT_CUTOFF, 30.0f);
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    gluPerspective(60.0, 1.0, 0.5, 10.0);
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
    glTranslatef(0, 0, -3);

    /* A zero normal, normalized and lit. */
    glNormal3f(0, 0, 0);
    glBegin(GL_TRIANGLES);
    glVertex3f(-1, -1, 0); glVertex3f(1, -1, 0); glVertex3f(0, 1, 0);
    glEnd();
    /* The shadow matrix: singular. */
    glPushMatrix();
    glScalef(1, 0, 1);
    GLUquadric *q = gluNewQuadric();
    gluSphere(q, 0.7, 16, 8);
    glPopMatrix();
    gluCylinder(q, 0.3, 0.0, 0.8, 12, 3);
    gluDeleteQuadric(q);
    /* A vertex at w = 0 and one with a huge coordinate. */
    glBegin(GL_TRIANGLES);
    glVertex4f(0, 0, 0, 0); glVertex3f(1e30f, 0, 0); glVertex3f(0, 1, 0);
    glEnd();
    /* A bow tie through the tessellator (COMBINE at the crossing). */
    GLdouble pts[4][3] = {{-1, -1, 0}, {1, 1, 0}, {1, -1, 0}, {-1, 1, 0}};
    GLUtesselator *t = gluNewTess();
    gluTessCallback(t, GLU_TESS_BEGIN, (void (GLAPIENTRY *)(void))glBegin);
    gluTessCallback(t, GLU_TESS_VERTEX, (void (GLAPIENTRY *)(void))tess_vertex);
    gluTessCallback(t, GLU_TESS_END, (void (GLAPIENTRY *)(void))glEnd);
    gluTessCallback(t, GLU_TESS_COMBINE, (void (GLAPIENTRY *)(void))tess_combine);
    gluTessBeginPolygon(t, NULL);
    gluTessBeginContour(t);
    for (int i = 0; i < 4; i++)
        gluTessVertex(t, pts[i], pts[i]);
    gluTessEndContour(t);
    gluTessEndPolygon(t);
    gluDeleteTess(t);
    /* gluUnProject with a singular matrix returns GL_FALSE, no trap. */
    GLdouble zero[16] = {0}, ox, oy, oz;
    GLint vp[4] = {0, 0, W, H};
    h_expect(gluUnProject(1, 1, 0.5, zero, zero, vp, &ox, &oy, &oz) == GL_FALSE, "singular unproject");
    glFinish();

    int traps = fegetexcept();
    int raised = fetestexcept(FE_ALL_EXCEPT);
    fedisableexcept(FE_ALL_EXCEPT);
    h_expect(traps == TRAPS, "the program's traps are back (0x%x, want 0x%x)", traps, TRAPS);
    h_expect((raised & TRAPS) == 0, "no exception flags leaked out of softgl (0x%x)", raised);
    h_expect_no_error("scene");

    unsigned char px[W * H * 4];
    h_read(px);
    int lit = 0;
    for (int i = 0; i < W * H; i++)
        lit += px[4 * i] || px[4 * i + 1] || px[4 * i + 2];
    h_expect(lit > 100, "the scene drew (%d lit pixels)", lit);
    return h_finish();
}
