/* t_book_s0_tessfrag: the Persian book's two C tessellator fragments
 * (seeds-inventory §3.3): a quad with a triangular hole, given once with
 * the GLU 1.2 calls and once with the GLU 1.1 ones.
 *
 * BOOK: S0, Persian "3D programming with OpenGL in Delphi", ch. 21, tessellator reference: gluTessBeginPolygon example (S0:294-307) and gluBeginPolygon/gluNextContour example (S0:396-405)
 * SHOWS: left, the quad minus the triangle from gluTessBeginPolygon + two contours; right, the same from gluBeginPolygon, gluNextContour(GLU_INTERIOR), gluEndPolygon; then both with GLU_TESS_BOUNDARY_ONLY, as line loops
 * FEATURES: gluNewTess, gluTessCallback (BEGIN, VERTEX, END, EDGE_FLAG, ERROR), gluTessBeginPolygon/BeginContour/Vertex/EndContour/EndPolygon, gluBeginPolygon/gluNextContour/gluEndPolygon, GLU_TESS_BOUNDARY_ONLY, glEdgeFlag
 *
 * The fragments leave v1..v7 undefined: here v1..v4 are the quad
 * (40,40)-(160,160) and v5..v7 the triangle (70,60),(130,60),(100,130).
 * The book says the contour type of gluNextContour decides interior and
 * exterior (§6 #39); since GLU 1.2 it is ignored and the winding rule
 * (ODD by default) decides, which gives the same hole here.
 */
#include "book.h"

#define W 400
#define H 400

static GLdouble v[7][3] = {{40, 40, 0}, {160, 40, 0}, {160, 160, 0}, {40, 160, 0},
                           {70, 60, 0}, {130, 60, 0}, {100, 130, 0}};
static int errors, edge_calls;

static void APIENTRY begin_cb(GLenum t) { glBegin(t); }
static void APIENTRY end_cb(void) { glEnd(); }
static void APIENTRY vertex_cb(void *d) { glVertex3dv((const GLdouble *)d); }
static void APIENTRY edge_cb(GLboolean f) { edge_calls++; glEdgeFlag(f); }
static void APIENTRY error_cb(GLenum e) { (void)e; errors++; }

static GLUtesselator *new_tess(void)
{
    GLUtesselator *tobj = gluNewTess();
    gluTessCallback(tobj, GLU_TESS_BEGIN, (void (APIENTRY *)(void))begin_cb);
    gluTessCallback(tobj, GLU_TESS_END, (void (APIENTRY *)(void))end_cb);
    gluTessCallback(tobj, GLU_TESS_VERTEX, (void (APIENTRY *)(void))vertex_cb);
    gluTessCallback(tobj, GLU_TESS_EDGE_FLAG, (void (APIENTRY *)(void))edge_cb);
    gluTessCallback(tobj, GLU_TESS_ERROR, (void (APIENTRY *)(void))error_cb);
    return tobj;
}

static void glu12(GLUtesselator *tobj) /* S0:294-307 */
{
    int i;
    gluTessBeginPolygon(tobj, NULL);
    gluTessBeginContour(tobj);
    for (i = 0; i < 4; i++) gluTessVertex(tobj, v[i], v[i]);
    gluTessEndContour(tobj);
    gluTessBeginContour(tobj);
    for (i = 4; i < 7; i++) gluTessVertex(tobj, v[i], v[i]);
    gluTessEndContour(tobj);
    gluTessEndPolygon(tobj);
}

static void glu11(GLUtesselator *tess) /* S0:396-405 */
{
    int i;
    gluBeginPolygon(tess);
    for (i = 0; i < 4; i++) gluTessVertex(tess, v[i], v[i]);
    gluNextContour(tess, GLU_INTERIOR);
    for (i = 4; i < 7; i++) gluTessVertex(tess, v[i], v[i]);
    gluEndPolygon(tess);
}

/* Inside the triangle v5 v6 v7? */
static int in_tri(double x, double y)
{
    int k, s = 0;
    for (k = 0; k < 3; k++) {
        const GLdouble *a = v[4 + k], *b = v[4 + (k + 1) % 3];
        s += ((b[0] - a[0]) * (y - a[1]) - (b[1] - a[1]) * (x - a[0])) > 0;
    }
    return s == 3;
}

static void check_fill(int ox, int oy, const char *what)
{
    int x, y, bad = 0;
    /* sample a grid of points well away from the edges */
    for (y = 45; y < 160; y += 7)
        for (x = 45; x < 160; x += 7) {
            int near_edge = 0, k;
            for (k = 0; k < 3 && !near_edge; k++) {
                const GLdouble *a = v[4 + k], *b = v[4 + (k + 1) % 3];
                double ex = b[0] - a[0], ey = b[1] - a[1];
                double d = fabs(ex * (y + 0.5 - a[1]) - ey * (x + 0.5 - a[0])) / sqrt(ex * ex + ey * ey);
                near_edge = d < 2;
            }
            if (near_edge)
                continue;
            if ((book_at(ox + x, oy + y)[0] == 255) == in_tri(x + 0.5, y + 0.5))
                bad++;
        }
    h_expect(bad == 0, "%s: %d samples wrong (quad filled, triangle a hole)", what, bad);
}

int main(void)
{
    GLUtesselator *tobj;
    int x, lines;

    book_open(W, H);
    book_ortho_pixels();
    glClear(GL_COLOR_BUFFER_BIT);
    glColor3f(1, 1, 1);
    tobj = new_tess();
    glPushMatrix();
    glTranslatef(0, 200, 0);
    glu12(tobj);
    glTranslatef(200, 0, 0);
    glu11(tobj);
    glPopMatrix();
    h_expect(errors == 0, "%d tessellator errors", errors);
    h_expect(edge_calls > 0, "the EDGE_FLAG callback was never called");

    /* GLU_TESS_BOUNDARY_ONLY: the same, as contours (line loops). */
    glColor3f(1, 1, 0);
    gluTessProperty(tobj, GLU_TESS_BOUNDARY_ONLY, GL_TRUE);
    glu12(tobj);
    glPushMatrix();
    glTranslatef(200, 0, 0);
    glu11(tobj);
    glPopMatrix();
    gluDeleteTess(tobj);
    book_shot("s0_tessfrag-hole", 0, 0);
    check_fill(0, 200, "gluTessBeginPolygon (GLU 1.2)");
    check_fill(200, 200, "gluBeginPolygon/gluNextContour (GLU 1.1)");
    /* boundary only: the outlines are drawn, the inside is not filled */
    book_expect_rgb(100, 100, 0, 0, 0, 0, "boundary only: the quad is not filled");
    lines = 0;
    for (x = 30; x < 170; x++)
        lines += book_at(x, 100)[0] == 255 && book_at(x, 100)[1] == 255;
    h_expect(lines >= 4, "boundary only: the row y=100 crosses %d outline pixels, expected 4", lines);
    h_expect_no_error("end");
    book_close();
    return h_finish();
}
