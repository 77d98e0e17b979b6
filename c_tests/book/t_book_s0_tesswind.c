/* t_book_s0_tesswind: the winding-rule tessellation demo of the Persian
 * book (seeds-inventory §3.1), in C, as the Red Book program it ports.
 *
 * BOOK: S0, Persian "3D programming with OpenGL in Delphi", ch. 21 "Reflection and Tessellation", first program (unit ch21_01, S0:715-1104)
 * SHOWS: four tessellated shapes (nested squares, the same with two contours reversed, a self-crossing spiral, two quads and a triangle), one image per winding rule; the Delphi program's own output, which is always the ODD image, and that image with the Delphi viewport sized from the form's outer size (scaled up, cut at the top and right)
 * FEATURES: GLU tessellator (gluTessBeginPolygon/Contour/Vertex, BEGIN/VERTEX/END/COMBINE/ERROR callbacks, all five GLU_TESS_WINDING_* rules, an invalid property), display lists compiled while the tessellator calls back, gluOrtho2D, flat shading
 *
 * Checks: every pixel whose centre lies more than a pixel away from an edge
 * is white exactly when the winding rule accepts the winding number there,
 * which the test computes itself from the contours (with the sign GLU
 * gives it when no normal is set: the clockwise spiral counts positive, so
 * POSITIVE fills it and NEGATIVE shows nothing; seeds-inventory's table
 * assumed the +z normal and has those two spiral cells the other way); no tessellator errors;
 * and the Delphi program's two bugs (keyboard() is a chain of plain ifs
 * that always ends on ODD, and Borland's OpenGL.pas passes 100110 for
 * GLU_TESS_WINDING_RULE) must leave the ODD picture, with GLU reporting
 * GLU_INVALID_ENUM through the error callback and keeping the rule.
 */
#include "book.h"

#define W 400
#define H 400
static double sx = 0.4, sy = 0.4; /* pixels per unit: gluOrtho2D(0,1000,...) on 400 pixels */

static GLdouble rects[12][3] = {
    {50, 50, 0}, {300, 50, 0}, {300, 300, 0}, {50, 300, 0},
    {100, 100, 0}, {250, 100, 0}, {250, 250, 0}, {100, 250, 0},
    {150, 150, 0}, {200, 150, 0}, {200, 200, 0}, {150, 200, 0}};
static GLdouble spiral[16][3] = {
    {400, 250, 0}, {400, 50, 0}, {50, 50, 0}, {50, 400, 0},
    {350, 400, 0}, {350, 100, 0}, {100, 100, 0}, {100, 350, 0},
    {300, 350, 0}, {300, 150, 0}, {150, 150, 0}, {150, 300, 0},
    {250, 300, 0}, {250, 200, 0}, {200, 200, 0}, {200, 250, 0}};
static GLdouble quad1[4][3] = {{50, 150, 0}, {350, 150, 0}, {350, 200, 0}, {50, 200, 0}};
static GLdouble quad2[4][3] = {{100, 100, 0}, {300, 100, 0}, {300, 350, 0}, {100, 350, 0}};
static GLdouble tri[3][3] = {{200, 50, 0}, {250, 300, 0}, {150, 300, 0}};

static GLUtesselator *tobj;
static GLuint list;
static int tess_errors, last_error;

/* Combined vertices live until the end of the program (the Red Book
 * leaks them; the Delphi port allocates 2 doubles for 3, S0:882). */
static GLdouble combined[4096][3];
static int ncombined;

static void APIENTRY begin_cb(GLenum which) { glBegin(which); }
static void APIENTRY end_cb(void) { glEnd(); }
static void APIENTRY vertex_cb(void *data) { glVertex3dv((const GLdouble *)data); }
static void APIENTRY error_cb(GLenum code)
{
    tess_errors++;
    last_error = (int)code;
}
static void APIENTRY combine_cb(GLdouble coords[3], void *vdata[4], GLfloat weight[4], void **out)
{
    GLdouble *v;
    (void)vdata;
    (void)weight;
    if (ncombined >= 4096) {
        *out = NULL;
        return;
    }
    v = combined[ncombined++];
    v[0] = coords[0];
    v[1] = coords[1];
    v[2] = coords[2];
    *out = v;
}

static void contour(GLdouble (*v)[3], int from, int to, int step)
{
    int i;
    gluTessBeginContour(tobj);
    for (i = from; i != to + step; i += step)
        gluTessVertex(tobj, v[i], v[i]);
    gluTessEndContour(tobj);
}

/* makeNewLists of the book; `which` is the property name the program
 * passes (GLU_TESS_WINDING_RULE, or Borland's 100110). */
static void make_new_lists(GLenum which, GLdouble winding)
{
    gluTessProperty(tobj, which, winding);
    glNewList(list, GL_COMPILE);
    gluTessBeginPolygon(tobj, NULL);
    contour(rects, 0, 3, 1);
    contour(rects, 4, 7, 1);
    contour(rects, 8, 11, 1);
    gluTessEndPolygon(tobj);
    glEndList();

    glNewList(list + 1, GL_COMPILE);
    gluTessBeginPolygon(tobj, NULL);
    contour(rects, 0, 3, 1);
    contour(rects, 7, 4, -1);
    contour(rects, 11, 8, -1);
    gluTessEndPolygon(tobj);
    glEndList();

    glNewList(list + 2, GL_COMPILE);
    gluTessBeginPolygon(tobj, NULL);
    contour(spiral, 0, 15, 1);
    gluTessEndPolygon(tobj);
    glEndList();

    glNewList(list + 3, GL_COMPILE);
    gluTessBeginPolygon(tobj, NULL);
    contour(quad1, 0, 3, 1);
    contour(quad2, 0, 3, 1);
    contour(tri, 0, 2, 1);
    gluTessEndPolygon(tobj);
    glEndList();
}

/* initGL of the book: the tessellator, its callbacks and the lists. */
static void init_gl(void)
{
    glClearColor(0, 0, 0, 0);
    glShadeModel(GL_FLAT);
    tobj = gluNewTess();
    gluTessCallback(tobj, GLU_TESS_VERTEX, (void (APIENTRY *)(void))vertex_cb);
    gluTessCallback(tobj, GLU_TESS_BEGIN, (void (APIENTRY *)(void))begin_cb);
    gluTessCallback(tobj, GLU_TESS_END, (void (APIENTRY *)(void))end_cb);
    gluTessCallback(tobj, GLU_TESS_ERROR, (void (APIENTRY *)(void))error_cb);
    gluTessCallback(tobj, GLU_TESS_COMBINE, (void (APIENTRY *)(void))combine_cb);
    list = glGenLists(4);
}

static void display(void)
{
    glClear(GL_COLOR_BUFFER_BIT);
    glColor3f(1, 1, 1);
    glPushMatrix();
    glCallList(list);
    glTranslatef(0, 500, 0);
    glCallList(list + 1);
    glTranslatef(500, -500, 0);
    glCallList(list + 2);
    glTranslatef(0, 500, 0);
    glCallList(list + 3);
    glPopMatrix();
}

static void reshape(int w, int h)
{
    glViewport(0, 0, w, h);
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    if (w <= h)
        gluOrtho2D(0, 1000, 0, 1000.0 * h / w);
    else
        gluOrtho2D(0, 1000.0 * w / h, 0, 1000);
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
}

/* ---- the expected picture, computed independently ---- */

struct contour_ref { GLdouble (*v)[3]; int from, to, step; };

/* Twice the signed area of a contour (CCW positive). */
static double contour_area(const struct contour_ref *c)
{
    int n = (c->to - c->from) / c->step + 1, k;
    double a2 = 0;
    for (k = 0; k < n; k++) {
        const GLdouble *a = c->v[c->from + k * c->step];
        const GLdouble *b = c->v[c->from + ((k + 1) % n) * c->step];
        a2 += a[0] * b[1] - b[0] * a[1];
    }
    return a2;
}

static void add_edges(const struct contour_ref *c, double p[2], int *wind, double *dmin)
{
    int n = (c->to - c->from) / c->step + 1, k;
    for (k = 0; k < n; k++) {
        const GLdouble *a = c->v[c->from + k * c->step];
        const GLdouble *b = c->v[c->from + ((k + 1) % n) * c->step];
        double ex = b[0] - a[0], ey = b[1] - a[1], len2 = ex * ex + ey * ey;
        double t = ((p[0] - a[0]) * ex + (p[1] - a[1]) * ey) / len2, dx, dy, d;
        if (t < 0) t = 0;
        if (t > 1) t = 1;
        dx = a[0] + t * ex - p[0];
        dy = a[1] + t * ey - p[1];
        d = sqrt(dx * dx + dy * dy);
        if (d < *dmin) *dmin = d;
        /* crossing number with direction: edges crossing the ray to +x */
        if ((a[1] <= p[1]) != (b[1] <= p[1])) {
            double x = a[0] + (p[1] - a[1]) * ex / ey;
            if (x > p[0])
                *wind += (b[1] > a[1]) ? 1 : -1;
        }
    }
}

static int rule_accepts(GLdouble rule, int w)
{
    if (rule == GLU_TESS_WINDING_ODD) return (w & 1) != 0;
    if (rule == GLU_TESS_WINDING_NONZERO) return w != 0;
    if (rule == GLU_TESS_WINDING_POSITIVE) return w > 0;
    if (rule == GLU_TESS_WINDING_NEGATIVE) return w < 0;
    return abs(w) >= 2; /* ABS_GEQ_TWO */
}

/* Compare the last book_read with the expected picture; returns the
 * number of wrong pixels and counts white pixels per panel. */
static int check_picture(GLdouble rule, const char *name)
{
    static const struct contour_ref panels[4][3] = {
        {{rects, 0, 3, 1}, {rects, 4, 7, 1}, {rects, 8, 11, 1}},
        {{spiral, 0, 15, 1}, {0, 0, 0, 0}, {0, 0, 0, 0}},
        {{rects, 0, 3, 1}, {rects, 7, 4, -1}, {rects, 11, 8, -1}},
        {{quad1, 0, 3, 1}, {quad2, 0, 3, 1}, {tri, 0, 2, 1}}};
    int x, y, bad = 0, checked = 0;
    for (y = 0; y < H; y++)
        for (x = 0; x < W; x++) {
            double p[2] = {(x + 0.5) / sx, (y + 0.5) / sy}, dmin = 1e9;
            int col = p[0] >= 500, row = p[1] >= 500, wind = 0, k, want;
            const unsigned char *px = book_at(x, y);
            double area = 0;
            const struct contour_ref *panel = panels[col + 2 * row];
            p[0] -= 500 * col;
            p[1] -= 500 * row;
            for (k = 0; k < 3; k++)
                if (panel[k].v) {
                    add_edges(&panel[k], p, &wind, &dmin);
                    area += contour_area(&panel[k]);
                }
            /* No gluTessNormal: GLU picks the normal's sign so that the
             * contours' total signed area is positive (GLU 1.3 §5.3), so
             * the lone clockwise spiral has windings +1..+4, not -1..-4. */
            if (area < 0)
                wind = -wind;
            if (dmin < 1.0 / (sx < sy ? sx : sy))
                continue; /* within a pixel of an edge: left to the rasterizer */
            checked++;
            want = rule_accepts(rule, wind) ? 255 : 0;
            if (px[0] != want || px[1] != want || px[2] != want) {
                if (bad < 5)
                    printf("  %s: pixel (%d,%d) winding %d is %d,%d,%d, expected %d\n", name,
                           x, y, wind, px[0], px[1], px[2], want);
                bad++;
            }
        }
    h_expect(bad == 0, "%s: %d of %d pixels disagree with the winding rule", name, bad, checked);
    return bad;
}

/* The Delphi program's keyboard(): five plain ifs, no else (S0:1031-1066). */
static GLdouble book_keyboard(GLdouble current)
{
    if (current == GLU_TESS_WINDING_ODD) current = GLU_TESS_WINDING_NONZERO;
    if (current == GLU_TESS_WINDING_NONZERO) current = GLU_TESS_WINDING_POSITIVE;
    if (current == GLU_TESS_WINDING_POSITIVE) current = GLU_TESS_WINDING_NEGATIVE;
    if (current == GLU_TESS_WINDING_NEGATIVE) current = GLU_TESS_WINDING_ABS_GEQ_TWO;
    if (current == GLU_TESS_WINDING_ABS_GEQ_TWO) current = GLU_TESS_WINDING_ODD;
    return current;
}

int main(void)
{
    static const struct { GLdouble rule; const char *name; } rules[5] = {
        {GLU_TESS_WINDING_ODD, "s0_tesswind-odd"},
        {GLU_TESS_WINDING_NONZERO, "s0_tesswind-nonzero"},
        {GLU_TESS_WINDING_POSITIVE, "s0_tesswind-positive"},
        {GLU_TESS_WINDING_NEGATIVE, "s0_tesswind-negative"},
        {GLU_TESS_WINDING_ABS_GEQ_TWO, "s0_tesswind-abs_geq_two"}};
    static unsigned char odd[W * H * 4];
    GLdouble current, got = 0;
    int i;

#ifdef BOOK_HAVE_WGL
    /* VCL may call FormResize before FormCreate: wglMakeCurrent(0, 0) and
     * GL calls with no context at all must do nothing, harmlessly. */
    h_expect(wglMakeCurrent(NULL, NULL) == TRUE, "wglMakeCurrent(0, 0) before any context");
    reshape(W, H);
    h_expect(glGetError() == GL_NO_ERROR, "glGetError with no context");
#endif
    book_open(W, H);
    init_gl();
    reshape(W, H);

    /* The C original: a key press selects the next rule (else-if chain). */
    for (i = 0; i < 5; i++) {
        tess_errors = 0;
        make_new_lists(GLU_TESS_WINDING_RULE, rules[i].rule);
        display();
        h_expect(tess_errors == 0, "%s: %d tessellator errors (last %d)", rules[i].name,
                 tess_errors, last_error);
        h_expect_no_error(rules[i].name);
        book_shot(rules[i].name, 0, 0);
        check_picture(rules[i].rule, rules[i].name);
        if (i == 0)
            memcpy(odd, book_px, sizeof odd);
    }

    /* The Delphi program: start on ODD, press a key, compile with Borland's
     * constant.  Both bugs leave ODD; GLU must say GLU_INVALID_ENUM. */
    current = book_keyboard(GLU_TESS_WINDING_ODD);
    h_expect(current == GLU_TESS_WINDING_ODD, "the book's keyboard() cascade ends on %g", current);
    current = book_keyboard(GLU_TESS_WINDING_NEGATIVE);
    h_expect(current == GLU_TESS_WINDING_ODD, "the book's keyboard() cascade ends on %g", current);
    gluTessProperty(tobj, GLU_TESS_WINDING_RULE, GLU_TESS_WINDING_ODD);
    tess_errors = 0;
    last_error = 0;
    make_new_lists(100110 /* Borland's GLU_TESS_WINDING_RULE */, GLU_TESS_WINDING_POSITIVE);
    h_expect(tess_errors >= 1 && last_error == GLU_INVALID_ENUM,
             "gluTessProperty(100110): error callback got %d errors, last %d (want GLU_INVALID_ENUM %d)",
             tess_errors, last_error, GLU_INVALID_ENUM);
    gluGetTessProperty(tobj, GLU_TESS_WINDING_RULE, &got);
    h_expect(got == GLU_TESS_WINDING_ODD, "winding rule after the invalid property: %g", got);
    display();
    glFinish();
    book_read();
    h_expect(memcmp(book_px, odd, sizeof odd) == 0,
             "the Delphi program's picture (Borland constant) differs from the ODD picture");
    check_picture(GLU_TESS_WINDING_ODD, "s0_tesswind-delphi");

    /* The Delphi program sizes the viewport from the form's outer Width and
     * Height (416 x 439 for a 400 x 400 client area), not the client area:
     * the viewport is larger than the drawable, the picture is scaled up
     * and its top and right are cut off (§3.1 quirk 5) -- cleanly. */
    reshape(416, 439);
    display();
    book_shot("s0_tesswind-delphi_outer_size", 0, 0);
    sx = 416 / 1000.0;
    sy = 439 / (1000.0 * 439 / 416);
    check_picture(GLU_TESS_WINDING_ODD, "s0_tesswind-delphi_outer_size");
    reshape(W, H);

    gluDeleteTess(tobj);
    book_close();
    return h_finish();
}
