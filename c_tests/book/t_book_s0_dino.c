/* t_book_s0_dino: the reflected dinosaur of the Persian book (seeds-inventory
 * §3.2), Kilgard's "Leapin' Lizards" as the book's Delphi unit ch21 has it.
 *
 * BOOK: S0, Persian "3D programming with OpenGL in Delphi", ch. 21 "Reflection and Tessellation", second program (unit ch21, S0:1105-1610)
 * SHOWS: a green extruded dinosaur hopping over a translucent dark-red floor with its mirror image seen through the floor; from below, the blue floor bottom, and without stencil the "bogus" reflection that the stencil buffer removes; wireframe shows the tessellation; last, the C original (walls with their own normals, both lights)
 * FEATURES: GLU tessellator into display lists (caps wound like the contour), glFrontFace in lists, glScalef(1,-1,1) reflection with lights re-specified, GL_NORMALIZE, glCullFace(GL_FRONT), stencil (ALWAYS/REPLACE then EQUAL), glColorMask, blending SRC_ALPHA/ONE_MINUS_SRC_ALPHA, two lights with attenuation and local viewer, glPolygonMode GL_LINE
 *
 * Ported as the book has it, quirks included (§3.2): the walls have no
 * normals of their own, the walls skip the last outline vertex (i mod
 * count), GL_LIGHT1 is never enabled, and initGL calls redraw before the
 * lists exist (undefined lists are no-ops).  The animation time is frozen:
 * jump = 3.  The last image is Kilgard's C original the port derives from
 * (a unit normal per wall, all outline vertices, GL_LIGHT1 enabled).
 *
 * Checks: with stencil on, the stencil buffer read back is 1 exactly
 * inside the floor's projected outline and 0 outside; stencil on and off
 * differ only where the stencil is 0, and from below the floor they do
 * differ (the artifact exists and is removed); the floor top over the
 * black background is 0.3*(0.7,0,0) = (54,0,0) and its bottom is
 * (26,26,179); the dinosaur is green; wireframe draws fewer pixels.
 */
#include "book.h"

#define W 300
#define H 300

enum { RESERVED, BODY_SIDE, BODY_EDGE, BODY_WHOLE, ARM_SIDE, ARM_EDGE, ARM_WHOLE,
       LEG_SIDE, LEG_EDGE, LEG_WHOLE, EYE_SIDE, EYE_EDGE, EYE_WHOLE };

static GLfloat angle = 20, angle2 = 30;
static int useStencil = 0;
static GLdouble bodyWidth = 3.0;
static GLfloat jump = 3.0f;
/* 0: the Delphi port as printed; 1: Kilgard's C original, which the port
 * derives from: a normal per wall, every outline vertex in the walls, and
 * both lights on. */
static int original = 0;

static GLfloat body[22][3] = {{0, 3, 0}, {1, 1, 0}, {5, 1, 0}, {8, 4, 0}, {10, 4, 0}, {11, 5, 0},
    {11, 11.5, 0}, {13, 12, 0}, {13, 13, 0}, {10, 13.5, 0}, {13, 14, 0}, {13, 15, 0}, {11, 16, 0},
    {8, 16, 0}, {7, 15, 0}, {7, 13, 0}, {8, 12, 0}, {7, 11, 0}, {6, 6, 0}, {4, 3, 0}, {3, 2, 0},
    {1, 2, 0}};
static GLfloat arm[16][3] = {{8, 10, 0}, {9, 9, 0}, {10, 9, 0}, {13, 8, 0}, {14, 9, 0}, {16, 9, 0},
    {15, 9.5, 0}, {16, 10, 0}, {15, 10, 0}, {15.5, 11, 0}, {14.5, 10, 0}, {14, 11, 0}, {14, 10, 0},
    {13, 9, 0}, {11, 11, 0}, {9, 11, 0}};
static GLfloat leg[14][3] = {{8, 6, 0}, {8, 4, 0}, {9, 3, 0}, {9, 2, 0}, {8, 1, 0}, {8, 0.5, 0},
    {9, 0, 0}, {12, 0, 0}, {10, 1, 0}, {10, 2, 0}, {12, 4, 0}, {11, 6, 0}, {10, 7, 0}, {9, 7, 0}};
static GLfloat eye[6][3] = {{8.75f, 15, 0}, {9, 14.7f, 0}, {9.6f, 14.7f, 0}, {10.1f, 15, 0},
    {9.6f, 15.25f, 0}, {9, 15.25f, 0}};

static GLfloat lightZeroPosition[] = {10, 14, 10, 1};
static GLfloat lightZeroColor[] = {0.8f, 1, 0.8f, 1};
static GLfloat lightOnePosition[] = {-1, 1, 1, 0};
static GLfloat lightOneColor[] = {0.6f, 0.3f, 0.2f, 1};
static GLfloat skinColor[] = {0.1f, 1, 0.1f, 1};
static GLfloat eyeColor[] = {1, 0.2f, 0.2f, 1};

static void APIENTRY tessBegin(GLenum type) { glBegin(type); }
static void APIENTRY tessEnd(void) { glEnd(); }
/* The Delphi port passes float vertices as the data (S0: glVertex3fv). */
static void APIENTRY tessVertex(void *data) { glVertex3fv((const GLfloat *)data); }

static void extrudeSolidFromPolygon(GLfloat data[][3], int dataSize, GLdouble thickness,
                                    GLuint side, GLuint edge, GLuint whole)
{
    GLUtesselator *tobj = gluNewTess();
    GLdouble vertex[64][3];
    int i, count = dataSize;
    gluTessCallback(tobj, GLU_TESS_BEGIN, (void (APIENTRY *)(void))tessBegin);
    gluTessCallback(tobj, GLU_TESS_END, (void (APIENTRY *)(void))tessEnd);
    gluTessCallback(tobj, GLU_TESS_VERTEX, (void (APIENTRY *)(void))tessVertex);
    glNewList(side, GL_COMPILE);
    glShadeModel(GL_SMOOTH);
    gluTessBeginPolygon(tobj, NULL);
    gluTessBeginContour(tobj);
    for (i = 0; i <= count; i++) {
        vertex[i][0] = data[i][0];
        vertex[i][1] = data[i][1];
        vertex[i][2] = 0;
        gluTessVertex(tobj, vertex[i], data[i]);
    }
    gluTessEndContour(tobj);
    gluTessEndPolygon(tobj);
    glEndList();
    glNewList(edge, GL_COMPILE);
    glShadeModel(GL_FLAT);
    glBegin(GL_QUAD_STRIP);
    if (!original) {
        for (i = 0; i <= count; i++) { /* the book's i mod count skips data[count] */
            glVertex3f(data[i % count][0], data[i % count][1], 0);
            glVertex3f(data[i % count][0], data[i % count][1], (GLfloat)thickness);
        }
    } else {
        int n = count + 1; /* the original counts every vertex */
        for (i = 0; i <= n; i++) {
            /* flat shading takes a quad's colour from its last vertex pair,
             * so the normal of wall i..i+1 follows vertex i's pair */
            GLfloat dx = data[(i + 1) % n][1] - data[i % n][1];
            GLfloat dy = data[i % n][0] - data[(i + 1) % n][0];
            GLfloat len = (GLfloat)sqrt(dx * dx + dy * dy);
            glVertex3f(data[i % n][0], data[i % n][1], 0);
            glVertex3f(data[i % n][0], data[i % n][1], (GLfloat)thickness);
            if (len > 0)
                glNormal3f(dx / len, dy / len, 0);
        }
    }
    glEnd();
    glEndList();
    glNewList(whole, GL_COMPILE);
    glFrontFace(GL_CW);
    glCallList(edge);
    glNormal3f(0, 0, -1);
    glCallList(side);
    glPushMatrix();
    glTranslatef(0, 0, (GLfloat)thickness);
    glFrontFace(GL_CCW);
    glNormal3f(0, 0, 1);
    glCallList(side);
    glPopMatrix();
    glEndList();
    gluDeleteTess(tobj);
}

static void makeDinosaur(void)
{
    extrudeSolidFromPolygon(body, 21, bodyWidth, BODY_SIDE, BODY_EDGE, BODY_WHOLE);
    extrudeSolidFromPolygon(arm, 15, bodyWidth / 4, ARM_SIDE, ARM_EDGE, ARM_WHOLE);
    extrudeSolidFromPolygon(leg, 13, bodyWidth / 2, LEG_SIDE, LEG_EDGE, LEG_WHOLE);
    extrudeSolidFromPolygon(eye, 5, bodyWidth + 0.2, EYE_SIDE, EYE_EDGE, EYE_WHOLE);
}

static void drawDinosaur(void)
{
    glPushMatrix();
    glTranslatef(0, jump, 0);
    glMaterialfv(GL_FRONT, GL_DIFFUSE, skinColor);
    glCallList(BODY_WHOLE);
    glPushMatrix();
    glTranslatef(0, 0, (GLfloat)bodyWidth);
    glCallList(ARM_WHOLE);
    glCallList(LEG_WHOLE);
    glTranslatef(0, 0, (GLfloat)(-bodyWidth - bodyWidth / 4));
    glCallList(ARM_WHOLE);
    glTranslatef(0, 0, (GLfloat)(-bodyWidth / 4));
    glCallList(LEG_WHOLE);
    glTranslatef(0, 0, (GLfloat)(bodyWidth / 2 - 0.1));
    glMaterialfv(GL_FRONT, GL_DIFFUSE, eyeColor);
    glCallList(EYE_WHOLE);
    glPopMatrix();
    glPopMatrix();
}

static void drawFloor(void)
{
    glDisable(GL_LIGHTING);
    glBegin(GL_QUADS);
    glVertex3f(-18, 0, 27);
    glVertex3f(27, 0, 27);
    glVertex3f(27, 0, -18);
    glVertex3f(-18, 0, -18);
    glEnd();
    glEnable(GL_LIGHTING);
}

static double floor_win[4][2]; /* the floor's corners in window coordinates */

static void redraw(void)
{
    if (useStencil)
        glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT | GL_STENCIL_BUFFER_BIT);
    else
        glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    glPushMatrix();
    glRotatef(angle2, 1, 0, 0);
    glRotatef(angle, 0, 1, 0);
    glTranslatef(-8, -8, (GLfloat)(-bodyWidth / 2));
    glLightfv(GL_LIGHT0, GL_POSITION, lightZeroPosition);
    glLightfv(GL_LIGHT1, GL_POSITION, lightOnePosition);
    book_project(-18, 0, 27, &floor_win[0][0], &floor_win[0][1]);
    book_project(27, 0, 27, &floor_win[1][0], &floor_win[1][1]);
    book_project(27, 0, -18, &floor_win[2][0], &floor_win[2][1]);
    book_project(-18, 0, -18, &floor_win[3][0], &floor_win[3][1]);
    if (useStencil) {
        glDisable(GL_DEPTH_TEST);
        glColorMask(GL_FALSE, GL_FALSE, GL_FALSE, GL_FALSE);
        glEnable(GL_STENCIL_TEST);
        glStencilOp(GL_REPLACE, GL_REPLACE, GL_REPLACE);
        glStencilFunc(GL_ALWAYS, 1, 0xffffffff);
        drawFloor();
        glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
        glEnable(GL_DEPTH_TEST);
        glStencilFunc(GL_EQUAL, 1, 0xffffffff);
        glStencilOp(GL_KEEP, GL_KEEP, GL_KEEP);
    }
    glPushMatrix();
    glScalef(1, -1, 1);
    glLightfv(GL_LIGHT0, GL_POSITION, lightZeroPosition);
    glLightfv(GL_LIGHT1, GL_POSITION, lightOnePosition);
    glEnable(GL_NORMALIZE);
    glCullFace(GL_FRONT);
    drawDinosaur();
    glDisable(GL_NORMALIZE);
    glCullFace(GL_BACK);
    glPopMatrix();
    glLightfv(GL_LIGHT0, GL_POSITION, lightZeroPosition);
    glLightfv(GL_LIGHT1, GL_POSITION, lightOnePosition);
    if (useStencil)
        glDisable(GL_STENCIL_TEST);
    glEnable(GL_BLEND);
    glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
    glColor4f(0.7f, 0, 0, 0.3f);
    drawFloor();
    glDisable(GL_BLEND);
    glFrontFace(GL_CW);
    glColor4f(0.1f, 0.1f, 0.7f, 1);
    drawFloor();
    glFrontFace(GL_CCW);
    drawDinosaur();
    glPopMatrix();
}

static void initGL(void)
{
    redraw(); /* as the book: before the lists and the projection exist */
    makeDinosaur();
    glEnable(GL_CULL_FACE);
    glEnable(GL_DEPTH_TEST);
    glEnable(GL_LIGHTING);
    glMatrixMode(GL_PROJECTION);
    glEnable(GL_NORMALIZE);
    gluPerspective(40, 1, 1, 80);
    glMatrixMode(GL_MODELVIEW);
    gluLookAt(0, 0, 40, 0, 0, 0, 0, 1, 0);
    glLightModeli(GL_LIGHT_MODEL_LOCAL_VIEWER, 1);
    glLightfv(GL_LIGHT0, GL_DIFFUSE, lightZeroColor);
    glLightf(GL_LIGHT0, GL_CONSTANT_ATTENUATION, 0.1f);
    glLightf(GL_LIGHT0, GL_LINEAR_ATTENUATION, 0.05f);
    glLightfv(GL_LIGHT1, GL_DIFFUSE, lightOneColor);
    glEnable(GL_LIGHT0);
    glLightfv(GL_LIGHT0, GL_POSITION, lightZeroPosition);
    glLightfv(GL_LIGHT1, GL_POSITION, lightOnePosition);
    glViewport(0, 0, W, H);
}

/* Is window point (x,y) inside the floor's outline, and how far from it? */
static int in_floor(double x, double y, double *dist)
{
    int k, inside = 1;
    double s0 = 0;
    *dist = 1e9;
    for (k = 0; k < 4; k++) {
        const double *a = floor_win[k], *b = floor_win[(k + 1) % 4];
        double ex = b[0] - a[0], ey = b[1] - a[1], len = sqrt(ex * ex + ey * ey);
        double s = (ex * (y - a[1]) - ey * (x - a[0])) / len;
        if (k == 0) s0 = s;
        if ((s > 0) != (s0 > 0)) inside = 0;
        if (fabs(s) < *dist) *dist = fabs(s);
    }
    return inside;
}

static unsigned char img_off[W * H * 4], img_on[W * H * 4];
static unsigned char stencil[W * H];

/* Render stencil off and on from the current angles; check the stencil
 * values and where the two pictures differ.  Returns the differing count. */
static int off_and_on(const char *off_name, const char *on_name, int floor_visible)
{
    int x, y, diff = 0, bad_stencil = 0, inside = 0, bad_diff = 0;
    useStencil = 0;
    redraw();
    book_shot(off_name, 2, 40);
    memcpy(img_off, book_px, sizeof img_off);
    useStencil = 1;
    redraw();
    glPixelStorei(GL_PACK_ALIGNMENT, 1);
    glReadPixels(0, 0, W, H, GL_STENCIL_INDEX, GL_UNSIGNED_BYTE, stencil);
    book_shot(on_name, 2, 40);
    memcpy(img_on, book_px, sizeof img_on);
    for (y = 0; y < H; y++)
        for (x = 0; x < W; x++) {
            double d;
            int in = in_floor(x + 0.5, y + 0.5, &d) && floor_visible;
            int s = stencil[y * W + x];
            if (memcmp(img_off + 4 * (y * W + x), img_on + 4 * (y * W + x), 3) != 0) {
                diff++;
                if (s != 0)
                    bad_diff++;
            }
            if (d < 1.0)
                continue;
            inside += in;
            if (s != (in ? 1 : 0))
                bad_stencil++;
        }
    h_expect(bad_stencil == 0, "%s: %d pixels have the wrong stencil value", on_name, bad_stencil);
    h_expect(!floor_visible || inside > 1000, "%s: the floor covers only %d pixels", on_name, inside);
    h_expect(bad_diff == 0, "%s: %d pixels inside the floor's stencil differ from stencil off",
             on_name, bad_diff);
    return diff;
}

int main(void)
{
    int x, y, green = 0, lit_fill = 0, lit_wire = 0, diff;

    book_open(W, H);
    initGL();
    h_expect_no_error("initGL");

    /* From above (the book's start angles). */
    diff = off_and_on("s0_dino-stencil_off", "s0_dino-stencil_on", 1);
    printf("  from above: stencil on/off differ in %d pixels\n", diff);
    for (y = 0; y < H; y++)
        for (x = 0; x < W; x++) {
            const unsigned char *p = img_on + 4 * (y * W + x);
            if (p[1] > 60 && p[1] > 2 * p[0] && p[1] > 2 * p[2])
                green++;
            if (p[0] | p[1] | p[2])
                lit_fill++;
        }
    h_expect(green > 2000, "only %d green dinosaur pixels", green);
    /* A floor pixel left of the dinosaur, over the black background:
     * 0.3 * 0.7 * 255 = 53.55 (window (20,100): looked at). */
    book_expect_rgb(20, 100, 54, 0, 0, 1, "floor top over the background");

    /* From below the floor: blue bottom, the bogus reflection without
     * stencil, removed with stencil (floor top culled: stencil stays 0). */
    angle2 = -20;
    diff = off_and_on("s0_dino-below_stencil_off", "s0_dino-below_stencil_on", 0);
    printf("  from below: stencil on/off differ in %d pixels\n", diff);
    h_expect(diff > 200, "from below, stencil on and off differ in only %d pixels", diff);
    book_expect_rgb(250, 150, 26, 26, 179, 1, "floor bottom (0.1,0.1,0.7)");

    /* Key '4': wireframe, from above with stencil. */
    angle2 = 30;
    useStencil = 1;
    glPolygonMode(GL_FRONT_AND_BACK, GL_LINE);
    redraw();
    book_shot("s0_dino-wire", 2, 60);
    for (y = 0; y < H; y++)
        for (x = 0; x < W; x++)
            if (book_at(x, y)[0] | book_at(x, y)[1] | book_at(x, y)[2])
                lit_wire++;
    h_expect(lit_wire > 1000 && lit_wire < lit_fill / 2,
             "wireframe lights %d pixels, filled %d", lit_wire, lit_fill);
    glPolygonMode(GL_FRONT_AND_BACK, GL_FILL);
    h_expect_no_error("after drawing");

    /* The C original: walls with their own normals, both lights. */
    {
        static unsigned char port[W * H * 4];
        int changed = 0;
        useStencil = 1;
        redraw();
        glFinish();
        book_read();
        memcpy(port, book_px, sizeof port);
        original = 1;
        makeDinosaur();
        glEnable(GL_LIGHT1);
        redraw();
        book_shot("s0_dino-c_original", 2, 40);
        for (y = 0; y < H; y++)
            for (x = 0; x < W; x++)
                changed += memcmp(port + 4 * (y * W + x), book_at(x, y), 3) != 0;
        printf("  the C original differs from the Delphi port in %d pixels\n", changed);
        h_expect(changed > 1000, "the original's wall normals and second light change only %d pixels",
                 changed);
        h_expect_no_error("the C original");
    }
    book_close();
    return h_finish();
}
