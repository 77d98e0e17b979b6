/* t_book_s2_decal: Krasnov's stencil-decal airplane (project Ex72, after
 * Grantham's decal.c), seeds-inventory §3.4.
 *
 * BOOK: S2, Russian "OpenGL in Delphi" (M. V. Krasnov, "OpenGL. Grafika v proektakh Delphi"), stencil patterns on a plane, Ex72 (S2:19-178)
 * SHOWS: stages 1-6 (clear, airplane, ground, runway asphalt, yellow stripes, a 50% black shadow) drawn coplanar without z-fighting, each in the colour, stencil and depth views; the stencil view (palette: 0 red, 1 yellow, 2 yellow-green, 3 blue-cyan, 4 cyan-blue, 5 purple-blue background); the inverted normalised depth view; the decals without stencil
 * FEATURES: stencil decals (ALWAYS/KEEP,REPLACE,ZERO then GREATER/KEEP,KEEP,REPLACE), glDepthMask, glReadPixels of GL_STENCIL_INDEX and GL_DEPTH_COMPONENT/GL_FLOAT, glDrawPixels GL_RGB and GL_LUMINANCE/GL_FLOAT, glGetIntegerv(GL_DRAW_BUFFER), glDrawBuffer(GL_BACK), GLU quadrics under non-uniform scale, GL_NORMALIZE rescuing glNormal3i, projected shadow with glScalef(1,0,1), blending
 *
 * The window code is Krasnov's: a zero-filled PIXELFORMATDESCRIPTOR with
 * only the flags (it must still get a stencil buffer), 400x400, not
 * resizable.  drawAirplane's parts are as the inventory lists them
 * (cylinder fuselage, cone nose, flattened spheres for wings and tail, a
 * two-triangle fin, a disk closing the back); their placement is not in
 * the seed, so it is reconstructed here.
 *
 * Checks: the stencil values read back at stage 6 (0 bare ground, 1
 * asphalt, 2 stripes, 3 shadow, 4 ground hidden by the airplane, 5
 * background and airplane off the ground) at points whose expected value
 * is known, and every value in 0..5; the colours of lit ground, asphalt,
 * stripes and shadow-on-asphalt; stage by stage only the new layer
 * changes; the depth view is black on the background and white at the
 * nearest pixel.
 */
#include "book.h"

#define W 400
#define H 400

static GLUquadricObj *quadric;
static int useStencil = 1;
static int stage = 6;
enum { DCOLOR, DEPTH, STENCIL } dataChoice = DCOLOR;

static const GLubyte colors[7][3] = {
    {255, 0, 0}, {255, 218, 0}, {72, 255, 0}, {0, 255, 145},
    {0, 145, 255}, {72, 0, 255}, {255, 0, 218}};

static GLfloat depthSave[W * H];
static GLubyte stencilSave[W * H];
static GLubyte colorSave[W * H * 3];

static void pushOrthoView(double l, double r, double b, double t, double n, double f)
{
    glMatrixMode(GL_PROJECTION);
    glPushMatrix();
    glLoadIdentity();
    glOrtho(l, r, b, t, n, f);
    glMatrixMode(GL_MODELVIEW);
    glPushMatrix();
    glLoadIdentity();
}

static void popView(void)
{
    glMatrixMode(GL_PROJECTION);
    glPopMatrix();
    glMatrixMode(GL_MODELVIEW);
    glPopMatrix();
}

static void copyDepthToColor(GLenum whichColorBuffer)
{
    int i;
    GLint previousColorBuffer;
    GLfloat mn = 1, mx = 0;
    glReadPixels(0, 0, W, H, GL_DEPTH_COMPONENT, GL_FLOAT, depthSave);
    for (i = 0; i < W * H; i++) {
        if (depthSave[i] < mn) mn = depthSave[i];
        if (depthSave[i] > mx && depthSave[i] < 0.999f) mx = depthSave[i];
    }
    for (i = 0; i < W * H; i++)
        depthSave[i] = depthSave[i] <= mx ? 1 - (depthSave[i] - mn) / (mx - mn) : 0;
    pushOrthoView(0, 1, 0, 1, 0, 1);
    glRasterPos3f(0, 0, -0.5f);
    glDisable(GL_DEPTH_TEST);
    glDisable(GL_STENCIL_TEST);
    glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
    glGetIntegerv(GL_DRAW_BUFFER, &previousColorBuffer);
    glDrawBuffer(whichColorBuffer);
    glDrawPixels(W, H, GL_LUMINANCE, GL_FLOAT, depthSave);
    glDrawBuffer((GLenum)previousColorBuffer); /* lost in the seed's OCR (S2:54) */
    glEnable(GL_DEPTH_TEST);
    popView();
}

static void copyStencilToColor(GLenum whichColorBuffer)
{
    int i;
    GLint previousColorBuffer;
    glReadPixels(0, 0, W, H, GL_STENCIL_INDEX, GL_UNSIGNED_BYTE, stencilSave);
    for (i = 0; i < W * H; i++) {
        colorSave[3 * i + 0] = colors[stencilSave[i] % 7][0];
        colorSave[3 * i + 1] = colors[stencilSave[i] % 7][1];
        colorSave[3 * i + 2] = colors[stencilSave[i] % 7][2];
    }
    pushOrthoView(0, 1, 0, 1, 0, 1);
    glRasterPos3f(0, 0, -0.5f);
    glDisable(GL_DEPTH_TEST);
    glDisable(GL_STENCIL_TEST);
    glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
    glGetIntegerv(GL_DRAW_BUFFER, &previousColorBuffer);
    glDrawBuffer(whichColorBuffer);
    glDrawPixels(W, H, GL_RGB, GL_UNSIGNED_BYTE, colorSave);
    glDrawBuffer((GLenum)previousColorBuffer);
    glEnable(GL_DEPTH_TEST);
    popView();
}

static void setupBasePolygonState(GLint maxDecal)
{
    glEnable(GL_DEPTH_TEST);
    if (useStencil) {
        glEnable(GL_STENCIL_TEST);
        glStencilFunc(GL_ALWAYS, maxDecal + 1, 0xff);
        glStencilOp(GL_KEEP, GL_REPLACE, GL_ZERO);
    }
}

static void setupDecalState(GLint decalNum)
{
    if (useStencil) {
        glDisable(GL_DEPTH_TEST);
        glDepthMask(GL_FALSE);
        glEnable(GL_STENCIL_TEST);
        glStencilFunc(GL_GREATER, decalNum, 0xff);
        glStencilOp(GL_KEEP, GL_KEEP, GL_REPLACE);
    }
}

static void setupNormalDrawingState(void)
{
    glDisable(GL_STENCIL_TEST);
    glEnable(GL_DEPTH_TEST);
    glDepthMask(GL_TRUE);
}

static void setupLight(void)
{
    static const GLfloat pos[] = {0, 1, 0, 0};
    glLightfv(GL_LIGHT0, GL_POSITION, pos);
}

static void material(GLfloat r, GLfloat g, GLfloat b)
{
    GLfloat c[4];
    c[0] = r; c[1] = g; c[2] = b; c[3] = 1;
    glMaterialfv(GL_FRONT_AND_BACK, GL_AMBIENT_AND_DIFFUSE, c);
}

static void drawAirplane(void)
{
    material(0.75f, 0.75f, 0.75f);
    glDisable(GL_CULL_FACE);
    glPushMatrix(); /* fuselage and nose cone, along +z */
    glTranslatef(0, 0, -2.5f);
    gluCylinder(quadric, .5, .5, 5, 10, 10);
    glTranslatef(0, 0, 5);
    gluCylinder(quadric, .5, 0, 1, 10, 10);
    glPopMatrix();
    glPushMatrix(); /* the disk closing the back */
    glTranslatef(0, 0, -2.5f);
    glRotatef(180, 0, 1, 0);
    gluDisk(quadric, 0, .5, 10, 10);
    glPopMatrix();
    glPushMatrix(); /* wings */
    glScalef(3, .1f, 1);
    gluSphere(quadric, 1, 10, 10);
    glPopMatrix();
    glPushMatrix(); /* tail plane */
    glTranslatef(0, 0, -2);
    glScalef(2, .1f, .5f);
    gluSphere(quadric, 1, 10, 10);
    glPopMatrix();
    glEnable(GL_CULL_FACE);
    glBegin(GL_TRIANGLES); /* fin */
    glNormal3f(1, 0, 0);
    glVertex3f(0, 0, -2.5f); glVertex3f(0, 1.5f, -2.5f); glVertex3f(0, 0, -1.2f);
    glNormal3f(-1, 0, 0);
    glVertex3f(0, 0, -2.5f); glVertex3f(0, 0, -1.2f); glVertex3f(0, 1.5f, -2.5f);
    glEnd();
}

/* A quad in the y = 0 plane, counter-clockwise seen from above. */
static void flat_quad(GLfloat x0, GLfloat x1, GLfloat z0, GLfloat z1)
{
    glVertex3f(x0, 0, z1); glVertex3f(x1, 0, z1); glVertex3f(x1, 0, z0); glVertex3f(x0, 0, z0);
}

static void drawGround(void)
{
    material(0.647f, 0.165f, 0.165f);
    glBegin(GL_QUADS);
    glNormal3i(0, 1, 0); /* a tiny normal: only GL_NORMALIZE rescues it */
    flat_quad(-10, 10, -10, 10);
    glEnd();
}

static void drawAsphalt(void)
{
    material(0.25f, 0.25f, 0.25f);
    glBegin(GL_QUADS);
    glNormal3f(0, 1, 0);
    flat_quad(-5, 5, -9.5f, 9.5f);
    glEnd();
}

static void drawStripes(void)
{
    int i;
    const GLfloat gap = 0.66f, len = (16 - gap * 4) / 5;
    material(1, 1, 0);
    glBegin(GL_QUADS);
    glNormal3f(0, 1, 0);
    flat_quad(-4.5f, -3.5f, -8.5f, 8.5f);
    flat_quad(3.5f, 4.5f, -8.5f, 8.5f);
    for (i = 0; i < 5; i++) {
        GLfloat z0 = -8 + i * (len + gap);
        flat_quad(-.25f, .25f, z0, z0 + len);
    }
    glEnd();
}

static void init(void)
{
    glEnable(GL_DEPTH_TEST);
    glEnable(GL_CULL_FACE);
    glCullFace(GL_BACK);
    quadric = gluNewQuadric();
    glMatrixMode(GL_PROJECTION);
    glFrustum(-.33, .33, -.33, .33, .5, 40);
    glMatrixMode(GL_MODELVIEW);
    gluLookAt(-4, 10, 6, 0, 0, 0, 0, 1, 0);
    glEnable(GL_LIGHTING);
    glEnable(GL_LIGHT0);
    glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
    glEnable(GL_NORMALIZE);
    glClearStencil(5);
}

static void WMPaint(void)
{
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    if (dataChoice == STENCIL)
        glClear(GL_STENCIL_BUFFER_BIT);
    glPushMatrix();
    glScalef(.5f, .5f, .5f);
    if (stage == 1) goto doneWithFrame;
    setupLight();
    setupNormalDrawingState();
    glPushMatrix();
    glTranslatef(0, 1, 4);
    glRotatef(135, 0, 1, 0);
    drawAirplane();
    glPopMatrix();
    if (stage == 2) goto doneWithFrame;
    setupBasePolygonState(3);
    drawGround();
    if (stage == 3) goto doneWithFrame;
    setupDecalState(1);
    drawAsphalt();
    if (stage == 4) goto doneWithFrame;
    setupDecalState(2);
    drawStripes();
    if (stage == 5) goto doneWithFrame;
    setupDecalState(3);
    glDisable(GL_LIGHTING);
    glEnable(GL_BLEND);
    glPushMatrix();
    glColor4f(0, 0, 0, .5f);
    glTranslatef(0, 0, 4);
    glRotatef(135, 0, 1, 0);
    glScalef(1, 0, 1);
    drawAirplane();
    glPopMatrix();
    glDisable(GL_BLEND);
    glEnable(GL_LIGHTING);
doneWithFrame:
    setupNormalDrawingState();
    glPopMatrix();
    if (dataChoice == STENCIL) copyStencilToColor(GL_BACK);
    if (dataChoice == DEPTH) copyDepthToColor(GL_BACK);
}

/* Window position of ground point (x, 0, z) (before the 0.5 scale). */
static void ground_win(double x, double z, int *wx, int *wy)
{
    double fx, fy;
    glPushMatrix();
    glScalef(.5f, .5f, .5f);
    book_project(x, 0, z, &fx, &fy);
    glPopMatrix();
    *wx = (int)fx;
    *wy = (int)fy;
}

static int stencil_at(int x, int y)
{
    return stencilSave[y * W + x];
}

int main(void)
{
    static unsigned char prev[W * H * 4];
    static const struct { double x, z; int want; const char *what; } probes[] = {
        {8, 8, 0, "bare ground"},        {2, -7, 1, "asphalt"},
        {4, -7, 2, "left stripe"},       {-4, -7, 2, "right stripe"},
        {0, -7.2, 2, "centre dash"},     {-8, -8, 0, "bare ground far"}};
    char name[64];
    int i, x, y, n[8] = {0}, bad = 0, changed_outside = 0;
    GLint db = 0, sbits = 0;

    book_open(W, H);
    init();
    glGetIntegerv(GL_STENCIL_BITS, &sbits);
    h_expect(sbits >= 3, "a zero-filled PFD got %d stencil bits", sbits);
    glGetIntegerv(GL_DRAW_BUFFER, &db);
#ifdef BOOK_HAVE_WGL /* (OSMesa under Mesa is single-buffered: GL_FRONT) */
    h_expect(db == GL_BACK, "GL_DRAW_BUFFER is 0x%x, expected GL_BACK", db);
#endif

    /* Colour view, stages 1..6: each stage only adds its layer. */
    for (stage = 1; stage <= 6; stage++) {
        WMPaint();
        snprintf(name, sizeof name, "s2_decal-stage%d", stage);
        book_shot(name, 2, 60);
        if (stage >= 4) {
            /* Decals change nothing outside the ground (stencil 5 there). */
            changed_outside = 0;
            for (y = 0; y < H; y++)
                for (x = 0; x < W; x++)
                    if (memcmp(prev + 4 * (y * W + x), book_at(x, y), 3) != 0 &&
                        book_at(x, y)[0] == 0 && book_at(x, y)[1] == 0 && book_at(x, y)[2] == 0 &&
                        stage != 6)
                        changed_outside++;
            h_expect(changed_outside == 0, "stage %d made %d pixels black", stage, changed_outside);
        }
        memcpy(prev, book_px, sizeof prev);
        if (stage == 1)
            h_expect(book_count(0, 0, W, H, 0, 0, 0, 0) == W * H, "stage 1 is not all black");
    }
    /* Stage 6 colours (lit: 0.2 global ambient + diffuse * N.L = 1.2 * colour
     * for N = L = +y).  The ground's glNormal3i(0,1,0) is not (0,1,0): GL
     * 1.x converts a signed int c to (2c+1)/(2^32-1) (GL 1.5 table 2.9), so
     * it is (1,3,1)/(2^32-1), which GL_NORMALIZE makes (1,3,1)/sqrt(11):
     * N.L = 0.905 and the ground is 0.647*(0.2+0.905)*255 = 182. */
    {
        int gx, gy;
        ground_win(8, 8, &gx, &gy);
        book_expect_rgb(gx, gy, 182, 46, 46, 2, "bare ground 0.647*(0.2+0.905)");
        ground_win(2, -7, &gx, &gy);
        book_expect_rgb(gx, gy, 77, 77, 77, 2, "asphalt 1.2*0.25");
        ground_win(4, -7, &gx, &gy);
        book_expect_rgb(gx, gy, 255, 255, 0, 2, "yellow stripe");
    }
    h_expect_no_error("colour view");

    /* Stencil view (clears the stencil to 5 first). */
    dataChoice = STENCIL;
    WMPaint();
    /* stencilSave holds the raw values copyStencilToColor read. */
    for (i = 0; i < W * H; i++) {
        if (stencilSave[i] > 5) bad++;
        n[stencilSave[i] > 7 ? 7 : stencilSave[i]]++;
    }
    printf("  stencil histogram: 0:%d 1:%d 2:%d 3:%d 4:%d 5:%d other:%d\n", n[0], n[1], n[2], n[3],
           n[4], n[5], n[6] + n[7]);
    h_expect(bad == 0, "%d stencil values outside 0..5", bad);
    for (i = 0; i < 6; i++)
        h_expect(n[i] > 300, "only %d pixels have stencil %d", n[i], i);
    for (i = 0; i < (int)(sizeof probes / sizeof probes[0]); i++) {
        int gx, gy;
        ground_win(probes[i].x, probes[i].z, &gx, &gy);
        h_expect(stencil_at(gx, gy) == probes[i].want, "stencil at %s (%d,%d) is %d, expected %d",
                 probes[i].what, gx, gy, stencil_at(gx, gy), probes[i].want);
    }
    h_expect(stencil_at(W - 1, H - 1) == 5, "stencil of the background (top right) is %d, expected 5",
             stencil_at(W - 1, H - 1));
    book_shot("s2_decal-stencil_view", 0, 0);
    for (i = 0; i < 6; i++) {
        int k = book_count(0, 0, W, H, colors[i][0], colors[i][1], colors[i][2], 0);
        h_expect(k == n[i], "stencil view: %d pixels of colour %d, %d stencil values %d", k, i, n[i], i);
    }

    /* Stencil and depth views of every stage: the stencil holds only the
     * values of the layers drawn so far (5 = cleared; the airplane is
     * drawn with the stencil test off and writes nothing). */
    for (stage = 1; stage <= 6; stage++) {
        static const int allowed[7] = {0, 1 << 5, 1 << 5, 0x31, 0x33, 0x37, 0x3f};
        int seen = 0;
        dataChoice = STENCIL;
        WMPaint();
        for (i = 0; i < W * H; i++)
            seen |= 1 << (stencilSave[i] & 31);
        h_expect(seen == allowed[stage], "stage %d: stencil values seen 0x%x, expected 0x%x", stage, seen,
                 allowed[stage]);
        snprintf(name, sizeof name, "s2_decal-stage%d_stencil", stage);
        book_shot(name, 0, 0);
        dataChoice = DEPTH;
        WMPaint();
        snprintf(name, sizeof name, "s2_decal-stage%d_depth", stage);
        book_shot(name, 2, 60);
        if (stage == 1)
            h_expect(book_count(0, 0, W, H, 0, 0, 0, 0) == W * H, "stage 1 depth view is not black");
    }
    stage = 6;

    /* Depth view. */
    dataChoice = DEPTH;
    WMPaint();
    book_shot("s2_decal-depth_view", 2, 60);
    book_expect_rgb(W - 1, H - 1, 0, 0, 0, 0, "depth view: background black");
    h_expect(book_count(0, 0, W, H, 255, 255, 255, 1) >= 1, "depth view: no white nearest pixel");
    h_expect_no_error("depth view");

    /* The menu's "stencil decals" off: the decals are depth-tested against
     * the coplanar ground (GL_LESS): equal depths fail, so most of them
     * vanish (only a loose golden: which pixels survive is not fixed). */
    dataChoice = DCOLOR;
    useStencil = 0;
    WMPaint();
    book_shot("s2_decal-no_stencil", 255, W * H);
    {
        int asphalt = book_count(0, 0, W, H, 77, 77, 77, 2);
        int stripes = book_count(0, 0, W, H, 255, 255, 0, 2);
        printf("  without stencil: %d asphalt and %d stripe pixels survive (with: %d, %d)\n",
               asphalt, stripes, n[1], n[2]);
        h_expect(asphalt < n[1] && stripes < n[2],
                 "without stencil the decals should lose pixels to z-fighting");
    }
    book_close();
    return h_finish();
}
