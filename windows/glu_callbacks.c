/* glu_callbacks: GLU's callbacks into a Windows program, through
 * glu32.dll's forwarders (run under Wine by windows/run_test.sh).
 *
 * On 32-bit Windows GLU calls its callbacks with the CALLBACK (__stdcall)
 * convention: the callee pops its arguments, so a callback called with
 * the wrong convention, or with the wrong number of arguments, leaves the
 * stack off by that many bytes and the program crashes or reads garbage.
 * The callbacks here take 0, 1, 2, 4 and 5 arguments, and each result is
 * checked: the tessellator's triangles (the data forms and the GLU 1.1
 * forms), COMBINE with its four vertices and weights, the tessellator's,
 * quadric's and NURBS object's error callbacks, and the NURBS curve's
 * vertices in GLU_NURBS_TESSELLATOR mode. No GL context is needed: with
 * every callback set, GLU calls no GL entry point.
 */
#include <windows.h>
#include <GL/gl.h>
#include <GL/glu.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static int failures;

static void expect(int ok, const char *what)
{
    printf("%s %s\n", ok ? "ok  " : "FAIL", what);
    if (!ok)
        failures++;
}

/* What the tessellator's callbacks saw. */
struct tess_log {
    int magic;
    int begins, ends, vertices, combines, edge_flags, errors;
    GLenum prim, last_error;
    double tri[3][2];
    double area;
};

static struct tess_log *current; /* for the GLU 1.1 forms, which have no data pointer */

static void add_vertex(struct tess_log *l, const double *v)
{
    l->tri[l->vertices % 3][0] = v[0];
    l->tri[l->vertices % 3][1] = v[1];
    l->vertices++;
    if (l->vertices % 3 == 0)
        l->area += fabs((l->tri[1][0] - l->tri[0][0]) * (l->tri[2][1] - l->tri[0][1]) -
                        (l->tri[2][0] - l->tri[0][0]) * (l->tri[1][1] - l->tri[0][1])) / 2;
}

static void CALLBACK begin_data(GLenum prim, void *data)
{
    struct tess_log *l = data;
    l->begins++;
    l->prim = prim;
}

static void CALLBACK vertex_data(void *v, void *data)
{
    add_vertex(data, v);
}

static void CALLBACK end_data(void *data)
{
    ((struct tess_log *)data)->ends++;
}

static void CALLBACK edge_flag_data(GLboolean flag, void *data)
{
    (void)flag;
    ((struct tess_log *)data)->edge_flags++;
}

static int null_data_errors;
static GLenum null_data_last;

static void CALLBACK error_data(GLenum err, void *data)
{
    struct tess_log *l = data;
    if (!l) { /* the polygon GLU supplied for a missing gluTessBeginPolygon */
        null_data_errors++;
        null_data_last = err;
        return;
    }
    l->errors++;
    l->last_error = err;
}

static double combined[16][3];

static void CALLBACK combine_data(GLdouble coords[3], void *in[4], GLfloat w[4], void **out, void *data)
{
    struct tess_log *l = data;
    double *v = combined[l->combines % 16];
    int i;
    float sum = 0;
    for (i = 0; i < 3; i++)
        v[i] = coords[i];
    for (i = 0; i < 4; i++)
        sum += w[i];
    /* Two edges crossing: the weights of their four ends sum to 1, and
     * every in[i] with a weight is one of the program's vertices. */
    if (fabsf(sum - 1) > 1e-6f || !in[0] || !in[1])
        l->magic = 0;
    l->combines++;
    *out = v;
}

/* The GLU 1.1 forms: one argument fewer each. */
static void CALLBACK begin_plain(GLenum prim)
{
    current->begins++;
    current->prim = prim;
}

static void CALLBACK vertex_plain(void *v)
{
    add_vertex(current, v);
}

static void CALLBACK end_plain(void)
{
    current->ends++;
}

static void CALLBACK error_plain(GLenum err)
{
    current->errors++;
    current->last_error = err;
}

static void tessellate(GLUtesselator *t, struct tess_log *l, double (*pts)[3], int n, GLenum rule)
{
    int i;
    gluTessProperty(t, GLU_TESS_WINDING_RULE, rule);
    gluTessBeginPolygon(t, l);
    gluTessBeginContour(t);
    for (i = 0; i < n; i++)
        gluTessVertex(t, pts[i], pts[i]);
    gluTessEndContour(t);
    gluTessEndPolygon(t);
}

static void test_tessellator(void)
{
    /* A bow-tie: its two edges cross at (1, 1); each lobe has area 1. */
    static double bowtie[4][3] = {{0, 0, 0}, {2, 2, 0}, {2, 0, 0}, {0, 2, 0}};
    /* A 4x4 square, counter-clockwise. */
    static double square[4][3] = {{0, 0, 0}, {4, 0, 0}, {4, 4, 0}, {0, 4, 0}};
    struct tess_log l;
    GLUtesselator *t = gluNewTess();
    char what[256];

    expect(t != NULL, "gluNewTess");
    if (!t)
        return;
    gluTessCallback(t, GLU_TESS_BEGIN_DATA, (_GLUfuncptr)begin_data);
    gluTessCallback(t, GLU_TESS_VERTEX_DATA, (_GLUfuncptr)vertex_data);
    gluTessCallback(t, GLU_TESS_END_DATA, (_GLUfuncptr)end_data);
    gluTessCallback(t, GLU_TESS_EDGE_FLAG_DATA, (_GLUfuncptr)edge_flag_data);
    gluTessCallback(t, GLU_TESS_COMBINE_DATA, (_GLUfuncptr)combine_data);
    gluTessCallback(t, GLU_TESS_ERROR_DATA, (_GLUfuncptr)error_data);
    gluTessNormal(t, 0, 0, 1);

    memset(&l, 0, sizeof l);
    l.magic = 1;
    tessellate(t, &l, bowtie, 4, GLU_TESS_WINDING_NONZERO);
    snprintf(what, sizeof what, "bow-tie (NONZERO): %d begin / %d end, GL_TRIANGLES (0x%x), %d vertices, area %.6f (2), %d COMBINE, weights sum to 1",
            l.begins, l.ends, l.prim, l.vertices, l.area, l.combines);
    expect(l.begins == 1 && l.ends == 1 && l.prim == GL_TRIANGLES && l.vertices == 6 &&
           fabs(l.area - 2) < 1e-9 && l.combines == 1 && l.magic == 1 && l.edge_flags > 0 && l.errors == 0, what);
    snprintf(what, sizeof what, "COMBINE at (%.3f, %.3f) (the crossing (1, 1))", combined[0][0], combined[0][1]);
    expect(fabs(combined[0][0] - 1) < 1e-12 && fabs(combined[0][1] - 1) < 1e-12, what);

    memset(&l, 0, sizeof l);
    tessellate(t, &l, square, 4, GLU_TESS_WINDING_POSITIVE);
    snprintf(what, sizeof what, "square (POSITIVE): area %.6f (16), %d vertices", l.area, l.vertices);
    expect(fabs(l.area - 16) < 1e-9 && l.vertices == 6 && l.ends == 1, what);

    memset(&l, 0, sizeof l);
    gluTessVertex(t, square[0], square[0]); /* outside gluTessBeginPolygon */
    /* GLU reports the missing gluTessBeginPolygon with the last polygon's
     * data (&l), then supplies gluTessBeginPolygon(tess, NULL) and reports
     * the missing gluTessBeginContour with that NULL. */
    snprintf(what, sizeof what, "ERROR_DATA: GLU_TESS_MISSING_BEGIN_POLYGON (%u) with the last data, got %u from %d calls; "
            "then GLU_TESS_MISSING_BEGIN_CONTOUR (%u) with NULL, got %u from %d calls",
            GLU_TESS_MISSING_BEGIN_POLYGON, l.last_error, l.errors,
            GLU_TESS_MISSING_BEGIN_CONTOUR, null_data_last, null_data_errors);
    expect(l.errors == 1 && l.last_error == GLU_TESS_MISSING_BEGIN_POLYGON &&
           null_data_errors == 1 && null_data_last == GLU_TESS_MISSING_BEGIN_CONTOUR, what);
    gluTessEndContour(t);
    gluTessEndPolygon(t); /* one vertex: no output */

    /* The GLU 1.1 forms (no data pointer), with ERROR_DATA unset by NULL. */
    gluTessCallback(t, GLU_TESS_BEGIN_DATA, NULL);
    gluTessCallback(t, GLU_TESS_VERTEX_DATA, NULL);
    gluTessCallback(t, GLU_TESS_END_DATA, NULL);
    gluTessCallback(t, GLU_TESS_EDGE_FLAG_DATA, NULL);
    gluTessCallback(t, GLU_TESS_ERROR_DATA, NULL);
    gluTessCallback(t, GLU_TESS_BEGIN, (_GLUfuncptr)begin_plain);
    gluTessCallback(t, GLU_TESS_VERTEX, (_GLUfuncptr)vertex_plain);
    gluTessCallback(t, GLU_TESS_END, (_GLUfuncptr)end_plain);
    gluTessCallback(t, GLU_TESS_ERROR, (_GLUfuncptr)error_plain);
    memset(&l, 0, sizeof l);
    l.magic = 1;
    current = &l;
    tessellate(t, &l, bowtie, 4, GLU_TESS_WINDING_ODD);
    snprintf(what, sizeof what, "GLU 1.1 callbacks, bow-tie (ODD): %d begin / %d end, %d vertices, area %.6f (2)",
            l.begins, l.ends, l.vertices, l.area);
    /* Without an edge-flag callback the triangles may come as fans or
     * strips; the area is summed only for GL_TRIANGLES, so check the
     * vertex count's lower bound and the ends instead when it is not. */
    expect(l.begins >= 1 && l.begins == l.ends && l.vertices >= 6 && l.errors == 0 &&
           (l.prim != GL_TRIANGLES || fabs(l.area - 2) < 1e-9), what);
    gluTessEndPolygon(t); /* with no polygon begun */
    snprintf(what, sizeof what, "GLU_TESS_ERROR (one argument): GLU_TESS_MISSING_BEGIN_POLYGON (%u), got %u",
            GLU_TESS_MISSING_BEGIN_POLYGON, l.last_error);
    expect(l.errors == 1 && l.last_error == GLU_TESS_MISSING_BEGIN_POLYGON, what);
    gluTessProperty(t, 100110, GLU_TESS_WINDING_ODD); /* a Borland unit's wrong enum */
    snprintf(what, sizeof what, "gluTessProperty(100110): GLU_INVALID_ENUM (%u), got %u", GLU_INVALID_ENUM, l.last_error);
    expect(l.errors == 2 && l.last_error == GLU_INVALID_ENUM, what);
    gluDeleteTess(t);
}

static GLenum quadric_error;

static void CALLBACK quadric_error_cb(GLenum err)
{
    quadric_error = err;
}

static void test_quadric(void)
{
    GLUquadric *q = gluNewQuadric();
    char what[256];
    expect(q != NULL, "gluNewQuadric");
    if (!q)
        return;
    gluQuadricCallback(q, GLU_ERROR, (_GLUfuncptr)quadric_error_cb);
    gluQuadricDrawStyle(q, 12345);
    snprintf(what, sizeof what, "quadric GLU_ERROR callback: GLU_INVALID_ENUM (%u), got %u", GLU_INVALID_ENUM, quadric_error);
    expect(quadric_error == GLU_INVALID_ENUM, what);
    gluDeleteQuadric(q);
}

struct nurbs_log {
    int begins, ends, vertices, errors;
    GLenum prim, last_error;
    double max_off_line, min_x, max_x;
};

static void CALLBACK nurbs_begin(GLenum prim, void *data)
{
    struct nurbs_log *l = data;
    l->begins++;
    l->prim = prim;
}

static void CALLBACK nurbs_vertex(GLfloat *v, void *data)
{
    struct nurbs_log *l = data;
    /* The curve's control points lie on the line y = 2x, z = 1. */
    double off = fabs(v[1] - 2 * v[0]) + fabs(v[2] - 1);
    if (off > l->max_off_line)
        l->max_off_line = off;
    if (v[0] < l->min_x)
        l->min_x = v[0];
    if (v[0] > l->max_x)
        l->max_x = v[0];
    l->vertices++;
}

static void CALLBACK nurbs_end(void *data)
{
    ((struct nurbs_log *)data)->ends++;
}

static struct nurbs_log *nurbs_current;

static void CALLBACK nurbs_error(GLenum err)
{
    nurbs_current->errors++;
    nurbs_current->last_error = err;
}

static void test_nurbs(void)
{
    /* A cubic Bezier (as a NURBS) with its control points on a line. */
    static GLfloat knots[8] = {0, 0, 0, 0, 1, 1, 1, 1};
    static GLfloat ctl[4][3] = {{0, 0, 1}, {1, 2, 1}, {2, 4, 1}, {3, 6, 1}};
    struct nurbs_log l;
    GLUnurbs *n = gluNewNurbsRenderer();
    char what[256];

    expect(n != NULL, "gluNewNurbsRenderer");
    if (!n)
        return;
    memset(&l, 0, sizeof l);
    l.min_x = 1e9;
    l.max_x = -1e9;
    nurbs_current = &l;
    gluNurbsProperty(n, GLU_NURBS_MODE, GLU_NURBS_TESSELLATOR);
    gluNurbsProperty(n, GLU_AUTO_LOAD_MATRIX, GL_FALSE);
    gluNurbsProperty(n, GLU_SAMPLING_METHOD, GLU_DOMAIN_DISTANCE);
    gluNurbsProperty(n, GLU_U_STEP, 10);
    /* GLU 1.3's gluNurbsCallbackData is not in Microsoft's GLU 1.2 import
     * library (nor mingw-w64's): found at run time, as programs do. */
    {
        typedef void(APIENTRY * CallbackDataFn)(GLUnurbs *, void *);
        CallbackDataFn set_data = (CallbackDataFn)(void (*)(void))GetProcAddress(GetModuleHandleA("glu32.dll"), "gluNurbsCallbackData");
        expect(set_data != NULL, "glu32.dll: GetProcAddress(gluNurbsCallbackData)");
        if (!set_data)
            return;
        set_data(n, &l);
    }
    gluNurbsCallback(n, GLU_NURBS_BEGIN_DATA, (_GLUfuncptr)nurbs_begin);
    gluNurbsCallback(n, GLU_NURBS_VERTEX_DATA, (_GLUfuncptr)nurbs_vertex);
    gluNurbsCallback(n, GLU_NURBS_END_DATA, (_GLUfuncptr)nurbs_end);
    gluNurbsCallback(n, GLU_NURBS_ERROR, (_GLUfuncptr)nurbs_error);
    gluBeginCurve(n);
    gluNurbsCurve(n, 8, knots, 3, &ctl[0][0], 4, GL_MAP1_VERTEX_3);
    gluEndCurve(n);
    snprintf(what, sizeof what, "NURBS in GLU_NURBS_TESSELLATOR mode: %d begin / %d end (prim 0x%x), %d vertices from x %.3f to %.3f, %.2g off the line",
            l.begins, l.ends, l.prim, l.vertices, l.min_x, l.max_x, l.max_off_line);
    expect(l.begins >= 1 && l.begins == l.ends && l.prim == GL_LINE_STRIP && l.vertices >= 10 &&
           fabs(l.min_x) < 1e-5 && fabs(l.max_x - 3) < 1e-5 && l.max_off_line < 1e-4 && l.errors == 0, what);
    gluNurbsProperty(n, 12345, 1);
    snprintf(what, sizeof what, "NURBS error callback: GLU_INVALID_ENUM (%u), got %u from %d calls",
            GLU_INVALID_ENUM, l.last_error, l.errors);
    expect(l.errors == 1 && l.last_error == GLU_INVALID_ENUM, what);
    gluDeleteNurbsRenderer(n);
}

int main(void)
{
    printf("glu_callbacks: %d-bit, GLU %s\n", (int)(8 * sizeof(void *)), (const char *)gluGetString(GLU_VERSION));
    test_tessellator();
    test_quadric();
    test_nurbs();
    if (failures) {
        printf("GLU CALLBACKS FAILED (%d)\n", failures);
        return 1;
    }
    printf("GLU CALLBACKS OK\n");
    return 0;
}
