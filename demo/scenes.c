/* softgl demo scenes: what the current slice of the pipeline draws.
 * Each scene renders offscreen through OSMesa and is written as a PAM file
 * (demo/run.sh converts them to PNG in out/demo/).
 *
 *   scenes OUTDIR
 */
#include <GL/gl.h>
#include <GL/glu.h>
#include <GL/osmesa.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>

#define W 320
#define H 240

static unsigned char buf[W * H * 4];

static void save(const char *dir, const char *name)
{
    char path[512];
    FILE *f;
    int y;
    glFinish();
    snprintf(path, sizeof path, "%s/%s.pam", dir, name);
    f = fopen(path, "wb");
    if (!f) { perror(path); exit(1); }
    fprintf(f, "P7\nWIDTH %d\nHEIGHT %d\nDEPTH 4\nMAXVAL 255\nTUPLTYPE RGB_ALPHA\nENDHDR\n", W, H);
    /* OSMesa's default is Y_UP: row 0 is the bottom; PAM rows go top-down. */
    for (y = H - 1; y >= 0; y--)
        fwrite(buf + (size_t)y * W * 4, 1, W * 4, f);
    fclose(f);
    printf("%s: glGetError 0x%x\n", path, glGetError());
}

static void perspective_view(void)
{
    glViewport(0, 0, W, H);
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    gluPerspective(45.0, (double)W / H, 0.5, 50.0);
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
}

/* A smooth RGB triangle cutting through a flat-shaded quad: depth test,
 * smooth and flat shading, perspective. */
static void intersecting(const char *dir)
{
    glClearColor(0.1f, 0.1f, 0.2f, 1);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    glEnable(GL_DEPTH_TEST);
    perspective_view();
    gluLookAt(0, 0, 4, 0, 0, 0, 0, 1, 0);
    glRotatef(30, 0, 1, 0);
    glShadeModel(GL_SMOOTH);
    glBegin(GL_TRIANGLES);
    glColor3f(1, 0, 0); glVertex3f(-1, -1, 0.5f);
    glColor3f(0, 1, 0); glVertex3f(1, -1, -0.5f);
    glColor3f(0, 0, 1); glVertex3f(0, 1, 0);
    glEnd();
    glShadeModel(GL_FLAT);
    glBegin(GL_QUADS);
    glColor3f(1, 1, 0); glVertex3f(-1.2f, -0.2f, 0); glVertex3f(1.2f, -0.2f, 0);
    glVertex3f(1.2f, 0.2f, 0); glColor3f(1, 0, 1); glVertex3f(-1.2f, 0.2f, 0);
    glEnd();
    save(dir, "intersecting");
}

/* A sphere of triangle strips coloured by its normal (no lighting yet),
 * and a ring of flat-shaded quads around it. */
static void sphere(const char *dir)
{
    int i, j, n = 24, m = 48;
    glClearColor(0, 0, 0, 1);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    glEnable(GL_DEPTH_TEST);
    perspective_view();
    glTranslatef(0, 0, -4);
    glRotatef(20, 1, 0, 0);
    glShadeModel(GL_SMOOTH);
    for (i = 0; i < n; i++) {
        double t0 = M_PI * i / n, t1 = M_PI * (i + 1) / n;
        glBegin(GL_TRIANGLE_STRIP);
        for (j = 0; j <= m; j++) {
            double p = 2 * M_PI * j / m;
            double x0 = sin(t0) * cos(p), y0 = cos(t0), z0 = sin(t0) * sin(p);
            double x1 = sin(t1) * cos(p), y1 = cos(t1), z1 = sin(t1) * sin(p);
            glColor3d(0.5 + 0.5 * x0, 0.5 + 0.5 * y0, 0.5 + 0.5 * z0); glVertex3d(x0, y0, z0);
            glColor3d(0.5 + 0.5 * x1, 0.5 + 0.5 * y1, 0.5 + 0.5 * z1); glVertex3d(x1, y1, z1);
        }
        glEnd();
    }
    glShadeModel(GL_FLAT);
    glBegin(GL_QUAD_STRIP);
    for (j = 0; j <= m; j++) {
        double p = 2 * M_PI * j / m;
        glColor3f(j % 2 ? 1.0f : 0.3f, 0.6f, j % 2 ? 0.2f : 0.9f);
        glVertex3d(1.6 * cos(p), -0.1, 1.6 * sin(p));
        glVertex3d(1.6 * cos(p), 0.1, 1.6 * sin(p));
    }
    glEnd();
    save(dir, "sphere");
}

/* A checkerboard floor running from behind the eye to the horizon: near
 * plane clipping, perspective-correct colour, a display list per row. */
static void floor_scene(const char *dir)
{
    int i, j;
    GLuint rows = glGenLists(1);
    glClearColor(0.5f, 0.7f, 1.0f, 1);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    glEnable(GL_DEPTH_TEST);
    perspective_view();
    gluLookAt(0, 1, 0, 0, 0.6, -5, 0, 1, 0);
    glNewList(rows, GL_COMPILE);
    glShadeModel(GL_FLAT);
    glBegin(GL_QUADS);
    for (j = -40; j < 40; j++)
        for (i = -20; i < 20; i++) {
            if ((i + j) & 1) glColor3f(0.9f, 0.9f, 0.85f); else glColor3f(0.2f, 0.25f, 0.3f);
            glVertex3f((float)i, 0, (float)j); glVertex3f((float)i, 0, (float)j + 1);
            glVertex3f((float)i + 1, 0, (float)j + 1); glVertex3f((float)i + 1, 0, (float)j);
        }
    glEnd();
    glEndList();
    glCallList(rows);
    /* A smooth-shaded pyramid standing on the floor. */
    glShadeModel(GL_SMOOTH);
    glBegin(GL_TRIANGLE_FAN);
    glColor3f(1, 1, 1); glVertex3f(0, 1.2f, -4);
    glColor3f(1, 0, 0); glVertex3f(-0.6f, 0, -3.4f);
    glColor3f(0, 1, 0); glVertex3f(0.6f, 0, -3.4f);
    glColor3f(0, 0, 1); glVertex3f(0.6f, 0, -4.6f);
    glColor3f(1, 1, 0); glVertex3f(-0.6f, 0, -4.6f);
    glColor3f(1, 0, 0); glVertex3f(-0.6f, 0, -3.4f);
    glEnd();
    save(dir, "floor");
}

/* The eight depth functions, one panel each: a far green quad drawn first,
 * then a red quad crossing it in depth, compared with glDepthFunc. */
static void depth_funcs(const char *dir)
{
    static const GLenum funcs[8] = {GL_NEVER, GL_LESS, GL_EQUAL, GL_LEQUAL, GL_GREATER, GL_NOTEQUAL, GL_GEQUAL, GL_ALWAYS};
    int k;
    glClearColor(0.15f, 0.15f, 0.15f, 1);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    glEnable(GL_DEPTH_TEST);
    glShadeModel(GL_FLAT);
    for (k = 0; k < 8; k++) {
        glViewport((k % 4) * (W / 4) + 4, (k < 4 ? H / 2 : 0) + 4, W / 4 - 8, H / 2 - 8);
        glMatrixMode(GL_PROJECTION);
        glLoadIdentity();
        glOrtho(-1, 1, -1, 1, -1, 1);
        glMatrixMode(GL_MODELVIEW);
        glLoadIdentity();
        glDepthFunc(GL_LESS);
        glColor3f(0.1f, 0.7f, 0.2f);
        glRectf(-0.8f, -0.8f, 0.8f, 0.8f); /* z = 0 */
        glDepthFunc(funcs[k]);
        /* Object z -0.9 at the left is far (glOrtho looks down -z), +0.9 at
         * the right is near; the green quad is at depth 0.5. */
        glBegin(GL_QUADS);
        glColor3f(0.9f, 0.2f, 0.1f);
        glVertex3f(-1, -0.4f, -0.9f); glVertex3f(1, -0.4f, 0.9f);
        glVertex3f(1, 0.4f, 0.9f); glVertex3f(-1, 0.4f, -0.9f);
        glEnd();
    }
    glDepthFunc(GL_LESS);
    save(dir, "depth_funcs");
}

/* The Persian book's reflection, in miniature: the floor is written into
 * the stencil buffer with colour writes off, the mirrored lit objects are
 * drawn only where stencil == 1, the floor is blended over them, then the
 * objects are drawn for real. Lighting, stencil, blending, GLU quadrics. */
static void draw_objects(GLUquadric *q)
{
    static const GLfloat blue[4] = {0.2f, 0.4f, 0.9f, 1}, gold[4] = {0.9f, 0.7f, 0.2f, 1}, spec[4] = {1, 1, 1, 1};
    glMaterialfv(GL_FRONT, GL_SPECULAR, spec);
    glMaterialf(GL_FRONT, GL_SHININESS, 40);
    glMaterialfv(GL_FRONT, GL_AMBIENT_AND_DIFFUSE, blue);
    glPushMatrix();
    glTranslatef(-0.7f, 0.6f, 0);
    gluSphere(q, 0.5, 32, 24);
    glPopMatrix();
    glMaterialfv(GL_FRONT, GL_AMBIENT_AND_DIFFUSE, gold);
    glPushMatrix();
    glTranslatef(0.7f, 0.05f, 0);
    glRotatef(-90, 1, 0, 0);
    gluCylinder(q, 0.4, 0.1, 1.1, 32, 8);
    glPopMatrix();
}

static void reflection(const char *dir)
{
    static const GLfloat light_pos[4] = {1.5f, 3, 2, 1};
    GLUquadric *q = gluNewQuadric();
    int i, j;
    glClearColor(0.05f, 0.05f, 0.08f, 1);
    glClearStencil(0);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT | GL_STENCIL_BUFFER_BIT);
    glEnable(GL_DEPTH_TEST);
    glShadeModel(GL_SMOOTH);
    perspective_view();
    gluLookAt(0, 1.6, 4.2, 0, 0.3, 0, 0, 1, 0);
    glEnable(GL_LIGHT0);

    /* 1. The floor into the stencil buffer only. */
    glColorMask(GL_FALSE, GL_FALSE, GL_FALSE, GL_FALSE);
    glDepthMask(GL_FALSE);
    glEnable(GL_STENCIL_TEST);
    glStencilFunc(GL_ALWAYS, 1, 0xff);
    glStencilOp(GL_KEEP, GL_KEEP, GL_REPLACE);
    glBegin(GL_QUADS);
    glVertex3f(-2, 0, -2); glVertex3f(-2, 0, 2); glVertex3f(2, 0, 2); glVertex3f(2, 0, -2);
    glEnd();
    glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
    glDepthMask(GL_TRUE);

    /* 2. The mirrored objects where the floor is (front faces flip). */
    glStencilFunc(GL_EQUAL, 1, 0xff);
    glStencilOp(GL_KEEP, GL_KEEP, GL_KEEP);
    glPushMatrix();
    glScalef(1, -1, 1);
    glLightfv(GL_LIGHT0, GL_POSITION, light_pos);
    glFrontFace(GL_CW);
    glEnable(GL_LIGHTING);
    draw_objects(q);
    glDisable(GL_LIGHTING);
    glFrontFace(GL_CCW);
    glPopMatrix();
    glDisable(GL_STENCIL_TEST);

    /* 3. The floor, a translucent checkerboard blended over the mirror image. */
    glEnable(GL_BLEND);
    glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
    glBegin(GL_QUADS);
    for (i = -4; i < 4; i++)
        for (j = -4; j < 4; j++) {
            float x = i * 0.5f, z = j * 0.5f;
            if ((i + j) & 1) glColor4f(0.8f, 0.8f, 0.85f, 0.7f); else glColor4f(0.3f, 0.3f, 0.4f, 0.7f);
            glVertex3f(x, 0, z); glVertex3f(x, 0, z + 0.5f); glVertex3f(x + 0.5f, 0, z + 0.5f); glVertex3f(x + 0.5f, 0, z);
        }
    glEnd();
    glDisable(GL_BLEND);

    /* 4. The objects themselves. */
    glLightfv(GL_LIGHT0, GL_POSITION, light_pos);
    glEnable(GL_LIGHTING);
    draw_objects(q);
    glDisable(GL_LIGHTING);
    gluDeleteQuadric(q);
    save(dir, "reflection");
}

/* Points, wide and stippled lines, line loops. */
static void lines_points(const char *dir)
{
    int i;
    glClearColor(1, 1, 1, 1);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    glDisable(GL_DEPTH_TEST);
    glViewport(0, 0, W, H);
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    glOrtho(0, W, 0, H, -1, 1);
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
    glShadeModel(GL_SMOOTH);
    for (i = 1; i <= 8; i++) {
        glPointSize((float)i);
        glBegin(GL_POINTS);
        glColor3f(i / 8.0f, 0, 1 - i / 8.0f);
        glVertex2f(20.0f + i * 30, 210);
        glEnd();
    }
    glPointSize(1);
    for (i = 1; i <= 6; i++) {
        glLineWidth((float)i);
        glBegin(GL_LINES);
        glColor3f(1, 0, 0); glVertex2f(20, 180 - i * 14);
        glColor3f(0, 0, 1); glVertex2f(150, 170 - i * 14);
        glEnd();
    }
    glLineWidth(2);
    glEnable(GL_LINE_STIPPLE);
    for (i = 0; i < 4; i++) {
        static const GLushort patterns[4] = {0x00FF, 0x0F0F, 0x5555, 0x1C47};
        glLineStipple(i + 1, patterns[i]);
        glBegin(GL_LINE_STRIP);
        glColor3f(0, 0.5f, 0);
        glVertex2f(180, 180 - i * 20.0f); glVertex2f(240, 190 - i * 20.0f); glVertex2f(300, 175 - i * 20.0f);
        glEnd();
    }
    glDisable(GL_LINE_STIPPLE);
    glLineWidth(1);
    glBegin(GL_LINE_LOOP);
    for (i = 0; i < 7; i++) {
        double a = 2 * M_PI * i / 7;
        glColor3f(0.5f + 0.5f * (float)cos(a), 0.5f, 0.5f + 0.5f * (float)sin(a));
        glVertex2d(240 + 50 * cos(a), 50 + 40 * sin(a));
    }
    glEnd();
    save(dir, "lines_points");
}

int main(int argc, char **argv)
{
    const char *dir = argc > 1 ? argv[1] : ".";
    OSMesaContext ctx = OSMesaCreateContextExt(OSMESA_RGBA, 24, 8, 0, NULL);
    if (!ctx || !OSMesaMakeCurrent(ctx, buf, GL_UNSIGNED_BYTE, W, H)) {
        fprintf(stderr, "no OSMesa context\n");
        return 1;
    }
    printf("GL_RENDERER %s, GL_VERSION %s\n", glGetString(GL_RENDERER), glGetString(GL_VERSION));
    intersecting(dir);
    sphere(dir);
    floor_scene(dir);
    depth_funcs(dir);
    reflection(dir);
    lines_points(dir);
    OSMesaDestroyContext(ctx);
    return 0;
}
