/* tess_bench: softgl's GLU tessellator against Mesa's libGLU (the SGI
 * tessellator), in one process.
 *
 *   tess_bench [--softgl PATH] [--glu PATH] [--reps N] [--quick] [--only SET;SET] [--lib softgl|libGLU] [--out FILE.md]
 *
 * --only runs the named sets; --lib runs one library alone (for profiling:
 * `valgrind --tool=callgrind --toggle-collect=time_set tess_bench --only
 * 'random simple' --lib softgl --reps 1` counts only the timed pass).
 *
 * Both libraries are loaded with dlopen by path (RTLD_LOCAL, so neither's
 * symbols leak into the other) and driven through the same function
 * pointers. The callbacks only count, so no GL context is needed (the
 * tessellator never calls GL). Every polygon set is first run once
 * untimed to check the output: a polygon fails when the ERROR callback is
 * called or nothing is output; the covered area (sum of |triangle areas|,
 * fans and strips unrolled) is compared between the two. Then each set is
 * timed REPS times, alternating which library goes first; the reported time
 * per polygon is the median over repetitions of (set time / polygons).
 * One tessellator object per library serves a whole set, as programs do.
 */
#define _GNU_SOURCE
#include <dlfcn.h>
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

typedef unsigned int GLenum;
typedef double GLdouble;
typedef float GLfloat;
typedef unsigned char GLboolean;
typedef void (*fnptr)(void);

#define GLU_TESS_BEGIN 100100
#define GLU_TESS_VERTEX 100101
#define GLU_TESS_END 100102
#define GLU_TESS_ERROR 100103
#define GLU_TESS_COMBINE 100105
#define GLU_TESS_WINDING_RULE 100140
#define GLU_TESS_WINDING_ODD 100130
#define GLU_TESS_WINDING_NONZERO 100131
#define GLU_TESS_WINDING_POSITIVE 100132
#define GLU_TESS_WINDING_NEGATIVE 100133
#define GLU_TESS_WINDING_ABS_GEQ_TWO 100134
#define GL_TRIANGLES 4
#define GL_TRIANGLE_STRIP 5
#define GL_TRIANGLE_FAN 6

/* ---- the two libraries ---- */

typedef struct {
    const char *name, *path;
    void *h;
    void *(*NewTess)(void);
    void (*DeleteTess)(void *);
    void (*TessCallback)(void *, GLenum, fnptr);
    void (*TessProperty)(void *, GLenum, GLdouble);
    void (*TessNormal)(void *, GLdouble, GLdouble, GLdouble);
    void (*TessBeginPolygon)(void *, void *);
    void (*TessBeginContour)(void *);
    void (*TessVertex)(void *, GLdouble *, void *);
    void (*TessEndContour)(void *);
    void (*TessEndPolygon)(void *);
} Glu;

static int load(Glu *g)
{
    g->h = dlopen(g->path, RTLD_NOW | RTLD_LOCAL);
    if (!g->h) {
        fprintf(stderr, "tess_bench: %s: %s\n", g->name, dlerror());
        return 0;
    }
#define SYM(f)                                                  \
    if (!(*(void **)&g->f = dlsym(g->h, "glu" #f))) {            \
        fprintf(stderr, "tess_bench: %s lacks glu" #f "\n", g->name); \
        return 0;                                               \
    }
    SYM(NewTess) SYM(DeleteTess) SYM(TessCallback) SYM(TessProperty) SYM(TessNormal)
    SYM(TessBeginPolygon) SYM(TessBeginContour) SYM(TessVertex) SYM(TessEndContour) SYM(TessEndPolygon)
#undef SYM
    return 1;
}

/* ---- callbacks: counting (timed) and checking (untimed) ---- */

static long n_vertices, n_errors, n_combines;
/* Combined vertices: chunks of stable storage, reused from polygon to polygon. */
#define CHUNK 65536
static double (*chunks[4096])[3];
static int chunk_i, chunk_used;

static void reset_pool(void) { chunk_i = 0; chunk_used = 0; }
static double *pool_new(void)
{
    if (chunk_used == CHUNK) {
        chunk_i++;
        chunk_used = 0;
    }
    if (chunk_i >= 4096)
        return NULL;
    if (!chunks[chunk_i] && !(chunks[chunk_i] = malloc(sizeof(double[CHUNK][3]))))
        return NULL;
    return chunks[chunk_i][chunk_used++];
}

static void cb_begin(GLenum m) { (void)m; }
static void cb_vertex(void *d) { (void)d; n_vertices++; }
static void cb_end(void) {}
static void cb_error(GLenum e) { (void)e; n_errors++; }
static void cb_combine(GLdouble c[3], void *d[4], GLfloat w[4], void **out)
{
    double *v = pool_new();
    (void)d; (void)w;
    n_combines++;
    if (v) {
        v[0] = c[0]; v[1] = c[1]; v[2] = c[2];
    }
    *out = v;
}

/* Checking: rebuild triangles from whatever primitive type comes. */
static GLenum chk_mode;
static const double *chk_v[2];
static long chk_k, chk_tris;
static double chk_area;
/* FNV-1a over every checked callback (mode, vertex coordinates): with
 * TESS_BENCH_HASH set, printed per set on stderr, so that a speed change
 * can be shown to leave the output identical. */
static uint64_t chk_hash = 0xcbf29ce484222325ull;
static void hash_bytes(const void *p, size_t n)
{
    const unsigned char *b = p;
    while (n--) chk_hash = (chk_hash ^ *b++) * 0x100000001b3ull;
}
static void chk_begin(GLenum m) { chk_mode = m; chk_k = 0; hash_bytes(&m, sizeof m); }
static void chk_tri(const double *a, const double *b, const double *c)
{
    chk_area += 0.5 * fabs((b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0]));
    chk_tris++;
}
static void chk_vertex(void *d)
{
    const double *p = d;
    n_vertices++;
    hash_bytes(p, 3 * sizeof(double));
    if (chk_mode == GL_TRIANGLES) {
        if (chk_k % 3 == 2) chk_tri(chk_v[0], chk_v[1], p);
        else chk_v[chk_k % 3] = p;
    } else if (chk_mode == GL_TRIANGLE_FAN) {
        if (chk_k >= 2) chk_tri(chk_v[0], chk_v[1], p);
        if (chk_k == 0) chk_v[0] = p; else chk_v[1] = p;
    } else if (chk_mode == GL_TRIANGLE_STRIP) {
        if (chk_k >= 2) chk_tri(chk_v[0], chk_v[1], p);
        chk_v[0] = chk_v[1];
        chk_v[1] = p;
        if (chk_k == 0) chk_v[0] = p;
    }
    chk_k++;
}

/* ---- polygon sets ---- */

typedef struct {
    int ncont, *len; /* contour lengths */
    double (*v)[3];  /* all vertices, contour after contour */
    long nv;
    GLenum rule;
    int simple;  /* simple contours, properly nested, ODD: the shoelace sum is the area */
    double ref;  /* the area the rule selects, computed independently */
} Poly;

typedef struct {
    const char *name, *what;
    Poly *p;
    int n, cap;
} Set;

static Poly *new_poly(Set *s, GLenum rule)
{
    if (s->n == s->cap) {
        s->cap = s->cap ? 2 * s->cap : 16;
        s->p = realloc(s->p, s->cap * sizeof *s->p);
    }
    memset(&s->p[s->n], 0, sizeof(Poly));
    s->p[s->n].rule = rule;
    return &s->p[s->n++];
}
static void add_contour(Poly *p, const double (*v)[3], int n)
{
    p->len = realloc(p->len, (p->ncont + 1) * sizeof *p->len);
    p->len[p->ncont++] = n;
    p->v = realloc(p->v, (p->nv + n) * sizeof *p->v);
    memcpy(p->v + p->nv, v, n * sizeof *v);
    p->nv += n;
}
static void add_contour2(Poly *p, const double (*xy)[2], int n, int step)
{
    double (*v)[3] = malloc(n * sizeof *v);
    int i;
    for (i = 0; i < n; i++) {
        int k = step > 0 ? i : n - 1 - i;
        v[i][0] = xy[k][0]; v[i][1] = xy[k][1]; v[i][2] = 0;
    }
    add_contour(p, (const double (*)[3])v, n);
    free(v);
}

static uint64_t rng = 0x9e3779b97f4a7c15ull;
static double frand(void)
{
    rng ^= rng << 13; rng ^= rng >> 7; rng ^= rng << 17;
    return (rng >> 11) * (1.0 / 9007199254740992.0);
}

static const GLenum RULES[5] = {GLU_TESS_WINDING_ODD, GLU_TESS_WINDING_NONZERO, GLU_TESS_WINDING_POSITIVE,
                                GLU_TESS_WINDING_NEGATIVE, GLU_TESS_WINDING_ABS_GEQ_TWO};

/* The Persian book's shapes (chapter 21, S0): the four winding-rule panels of
 * tesswind (nested rectangles, the spiral, the reversed inner rectangles,
 * two quads and a triangle) under all five rules, the quad with a triangular
 * hole, a pentagram with a square at its centre, and the dinosaur's outlines. */
static void book_set(Set *s)
{
    static const double rects[12][2] = {{50, 50}, {300, 50}, {300, 300}, {50, 300}, {100, 100}, {250, 100},
                                        {250, 250}, {100, 250}, {150, 150}, {200, 150}, {200, 200}, {150, 200}};
    static const double spiral[16][2] = {{400, 250}, {400, 50}, {50, 50}, {50, 400}, {350, 400}, {350, 100},
                                         {100, 100}, {100, 350}, {300, 350}, {300, 150}, {150, 150}, {150, 300},
                                         {250, 300}, {250, 200}, {200, 200}, {200, 250}};
    static const double quad1[4][2] = {{50, 150}, {350, 150}, {350, 200}, {50, 200}};
    static const double quad2[4][2] = {{100, 100}, {300, 100}, {300, 350}, {100, 350}};
    static const double tri[3][2] = {{200, 50}, {250, 300}, {150, 300}};
    static const double frag[7][2] = {{40, 40}, {160, 40}, {160, 160}, {40, 160}, {70, 60}, {130, 60}, {100, 130}};
    static const double body[22][2] = {{0, 3}, {1, 1}, {5, 1}, {8, 4}, {10, 4}, {11, 5}, {11, 11.5}, {13, 12},
                                       {13, 13}, {10, 13.5}, {13, 14}, {13, 15}, {11, 16}, {8, 16}, {7, 15}, {7, 13},
                                       {8, 12}, {7, 11}, {6, 6}, {4, 3}, {3, 2}, {1, 2}};
    static const double arm[16][2] = {{8, 10}, {9, 9}, {10, 9}, {13, 8}, {14, 9}, {16, 9}, {15, 9.5}, {16, 10},
                                      {15, 10}, {15.5, 11}, {14.5, 10}, {14, 11}, {14, 10}, {13, 9}, {11, 11}, {9, 11}};
    static const double leg[14][2] = {{8, 6}, {8, 4}, {9, 3}, {9, 2}, {8, 1}, {8, 0.5}, {9, 0},
                                      {12, 0}, {10, 1}, {10, 2}, {12, 4}, {11, 6}, {10, 7}, {9, 7}};
    static const double eye[6][2] = {{8.75, 15}, {9, 14.7}, {9.6, 14.7}, {10.1, 15}, {9.6, 15.25}, {9, 15.25}};
    double star[5][2], sq[4][2] = {{-8, -8}, {8, -8}, {8, 8}, {-8, 8}};
    int r, i;
    for (i = 0; i < 5; i++) {
        double a = M_PI / 2 + i * 4 * M_PI / 5;
        star[i][0] = 100 * cos(a);
        star[i][1] = 100 * sin(a);
    }
    for (r = 0; r < 5; r++) {
        Poly *p = new_poly(s, RULES[r]);
        add_contour2(p, rects, 4, 1); add_contour2(p, rects + 4, 4, 1); add_contour2(p, rects + 8, 4, 1);
        p = new_poly(s, RULES[r]);
        add_contour2(p, spiral, 16, 1);
        p = new_poly(s, RULES[r]);
        add_contour2(p, rects, 4, 1); add_contour2(p, rects + 4, 4, -1); add_contour2(p, rects + 8, 4, -1);
        p = new_poly(s, RULES[r]);
        add_contour2(p, quad1, 4, 1); add_contour2(p, quad2, 4, 1); add_contour2(p, tri, 3, 1);
        p = new_poly(s, RULES[r]);
        add_contour2(p, star, 5, 1); add_contour2(p, sq, 4, 1);
    }
    {
        Poly *p = new_poly(s, GLU_TESS_WINDING_ODD);
        add_contour2(p, frag, 4, 1); add_contour2(p, frag + 4, 3, 1);
    }
    for (i = 0; i < 4; i++) {
        Poly *p = new_poly(s, GLU_TESS_WINDING_ODD);
        if (i == 0) add_contour2(p, body, 22, 1);
        if (i == 1) add_contour2(p, arm, 16, 1);
        if (i == 2) add_contour2(p, leg, 14, 1);
        if (i == 3) add_contour2(p, eye, 6, 1);
    }
}

/* A random simple polygon: star-shaped about the origin (sorted distinct
 * angles, radii in [0.3, 1]). */
static void star_shaped(Poly *p, int n, double cx, double cy, double scale, int cw)
{
    double (*xy)[2] = malloc(n * sizeof *xy);
    int i;
    double jitter = 0.8 * 2 * M_PI / n;
    for (i = 0; i < n; i++) {
        double a = 2 * M_PI * i / n + jitter * (frand() - 0.5), r = scale * (0.3 + 0.7 * frand());
        xy[i][0] = cx + r * cos(a);
        xy[i][1] = cy + r * sin(a);
    }
    add_contour2(p, (const double (*)[2])xy, n, cw ? -1 : 1);
    free(xy);
}

static void simple_set(Set *s, int n, int count)
{
    int k;
    for (k = 0; k < count; k++) {
        Poly *p = new_poly(s, GLU_TESS_WINDING_ODD);
        p->simple = 1;
        star_shaped(p, n, 0, 0, 1, 0);
    }
}

/* Counter-clockwise, so ODD, NONZERO and POSITIVE all select the inside. */
static void random_simple_set(Set *s, int count)
{
    int k;
    for (k = 0; k < count; k++)
        star_shaped(new_poly(s, RULES[k % 3]), 8 + (int)(frand() * 56), 0, 0, 1, 0);
}

/* Random points in a square joined in random order: many crossings
 * (about n^2/10 for n vertices), rules ODD and NONZERO alternating. */
static void self_intersecting_set(Set *s, int count)
{
    int k, i;
    for (k = 0; k < count; k++) {
        int n = 6 + (int)(frand() * 34);
        double (*xy)[2] = malloc(n * sizeof *xy);
        Poly *p = new_poly(s, k % 2 ? GLU_TESS_WINDING_NONZERO : GLU_TESS_WINDING_ODD);
        for (i = 0; i < n; i++) {
            xy[i][0] = frand();
            xy[i][1] = frand();
        }
        add_contour2(p, (const double (*)[2])xy, n, 1);
        free(xy);
    }
}

/* A rectangle with a grid of holes (16-gons with random radii, clockwise). */
static void holes_set(Set *s, int side, int count)
{
    int k, i, j;
    for (k = 0; k < count; k++) {
        double outer[4][2] = {{0, 0}, {side, 0}, {side, side}, {0, side}};
        Poly *p = new_poly(s, GLU_TESS_WINDING_ODD);
        p->simple = 1;
        add_contour2(p, outer, 4, 1);
        for (i = 0; i < side; i++)
            for (j = 0; j < side; j++)
                star_shaped(p, 16, i + 0.5, j + 0.5, 0.45, 1);
    }
}

static int cmp_d(const void *a, const void *b)
{
    double x = *(const double *)a, y = *(const double *)b;
    return (x > y) - (x < y);
}
static double median(double *x, int n)
{
    qsort(x, n, sizeof *x, cmp_d);
    return n % 2 ? x[n / 2] : 0.5 * (x[n / 2 - 1] + x[n / 2]);
}

/* ---- the reference: the selected area, computed independently ---- */

static int rule_inside(GLenum rule, long w)
{
    switch (rule) {
    case GLU_TESS_WINDING_ODD: return w & 1;
    case GLU_TESS_WINDING_NONZERO: return w != 0;
    case GLU_TESS_WINDING_POSITIVE: return w > 0;
    case GLU_TESS_WINDING_NEGATIVE: return w < 0;
    default: return w >= 2 || w <= -2;
    }
}

typedef struct { double ym, y0, y1; int d; } Span;
static int cmp_span(const void *a, const void *b) { return cmp_d(&((const Span *)a)->ym, &((const Span *)b)->ym); }

/* Vertical slabs between all vertex and crossing abscissae: inside a slab
 * the edges are ordered, the winding number steps by each edge's direction
 * and the area between two edges is a trapezoid. O(edges^2). */
static double slab_area(const Poly *p)
{
    long ne = 0, nx = 0, off = 0, i, j, c, cap = p->nv + 64;
    double (*e)[4] = malloc(p->nv * sizeof *e), *xs = malloc(cap * sizeof *xs), area = 0;
    int *dir = malloc(p->nv * sizeof *dir);
    Span *sp = malloc(p->nv * sizeof *sp);
    for (c = 0; c < p->ncont; c++) {
        for (i = 0; i < p->len[c]; i++) {
            const double *a = p->v[off + i], *b = p->v[off + (i + 1) % p->len[c]];
            xs[nx++] = a[0];
            if (a[0] == b[0]) continue;
            dir[ne] = a[0] < b[0] ? 1 : -1;
            if (a[0] > b[0]) { const double *t = a; a = b; b = t; }
            e[ne][0] = a[0]; e[ne][1] = a[1]; e[ne][2] = b[0]; e[ne][3] = b[1];
            ne++;
        }
        off += p->len[c];
    }
    for (i = 0; i < ne; i++)
        for (j = i + 1; j < ne; j++) {
            double *a = e[i], *b = e[j];
#define O(px, py, qx, qy, rx, ry) (((qx) - (px)) * ((ry) - (py)) - ((qy) - (py)) * ((rx) - (px)))
            double d1 = O(b[0], b[1], b[2], b[3], a[0], a[1]), d2 = O(b[0], b[1], b[2], b[3], a[2], a[3]);
            double d3 = O(a[0], a[1], a[2], a[3], b[0], b[1]), d4 = O(a[0], a[1], a[2], a[3], b[2], b[3]);
#undef O
            if (((d1 > 0 && d2 < 0) || (d1 < 0 && d2 > 0)) && ((d3 > 0 && d4 < 0) || (d3 < 0 && d4 > 0))) {
                if (nx == cap) xs = realloc(xs, (cap *= 2) * sizeof *xs);
                xs[nx++] = a[0] + d1 / (d1 - d2) * (a[2] - a[0]);
            }
        }
    qsort(xs, nx, sizeof *xs, cmp_d);
    for (i = 0; i + 1 < nx; i++) {
        double x0 = xs[i], x1 = xs[i + 1], xm = 0.5 * (x0 + x1);
        long n = 0, w = 0;
        if (!(x1 > x0)) continue;
        for (j = 0; j < ne; j++) {
            double *a = e[j];
            if (a[0] <= x0 && a[2] >= x1) {
#define Y(x) (a[1] + (a[3] - a[1]) * ((x) - a[0]) / (a[2] - a[0]))
                sp[n].ym = Y(xm); sp[n].y0 = Y(x0); sp[n].y1 = Y(x1); sp[n].d = dir[j];
#undef Y
                n++;
            }
        }
        qsort(sp, n, sizeof *sp, cmp_span);
        for (j = 0; j + 1 < n; j++) {
            w += sp[j].d;
            if (rule_inside(p->rule, w))
                area += (x1 - x0) * 0.5 * ((sp[j + 1].y0 + sp[j + 1].y1) - (sp[j].y0 + sp[j].y1));
        }
    }
    free(e); free(xs); free(dir); free(sp);
    return area;
}

static double reference_area(const Poly *p)
{
    long off = 0, i;
    int c;
    double a = 0;
    if (!p->simple) return slab_area(p);
    for (c = 0; c < p->ncont; c++) {
        for (i = 0; i < p->len[c]; i++) {
            const double *u = p->v[off + i], *v = p->v[off + (i + 1) % p->len[c]];
            a += 0.5 * (u[0] * v[1] - u[1] * v[0]);
        }
        off += p->len[c];
    }
    return fabs(a);
}

/* ---- running ---- */

static void *make_tess(Glu *g, int checking)
{
    void *t = g->NewTess();
    g->TessCallback(t, GLU_TESS_BEGIN, checking ? (fnptr)chk_begin : (fnptr)cb_begin);
    g->TessCallback(t, GLU_TESS_VERTEX, checking ? (fnptr)chk_vertex : (fnptr)cb_vertex);
    g->TessCallback(t, GLU_TESS_END, (fnptr)cb_end);
    g->TessCallback(t, GLU_TESS_ERROR, (fnptr)cb_error);
    g->TessCallback(t, GLU_TESS_COMBINE, (fnptr)cb_combine);
    g->TessNormal(t, 0, 0, 1);
    return t;
}

static void run_poly(Glu *g, void *t, Poly *p)
{
    long off = 0;
    int c, i;
    reset_pool();
    g->TessProperty(t, GLU_TESS_WINDING_RULE, p->rule);
    g->TessBeginPolygon(t, NULL);
    for (c = 0; c < p->ncont; c++) {
        g->TessBeginContour(t);
        for (i = 0; i < p->len[c]; i++)
            g->TessVertex(t, p->v[off + i], p->v[off + i]);
        off += p->len[c];
        g->TessEndContour(t);
    }
    g->TessEndPolygon(t);
}

typedef struct {
    int failures; /* polygons with an error or no output where output is due */
    int wrong;     /* polygons whose covered area is off the reference by more than 1e-7 relative */
    long tris;
    double *area;  /* per polygon */
    double *us;    /* per repetition: microseconds per polygon */
} Result;

static void check(Glu *g, Set *s, Result *r)
{
    void *t = make_tess(g, 1);
    int k;
    r->area = calloc(s->n, sizeof(double));
    r->failures = r->wrong = 0;
    for (k = 0; k < s->n; k++) {
        n_errors = 0; n_vertices = 0; chk_area = 0; chk_tris = 0;
        run_poly(g, t, &s->p[k]);
        r->failures += n_errors > 0 || (n_vertices == 0 && s->p[k].ref > 0);
        r->wrong += fabs(chk_area - s->p[k].ref) > 1e-7 * s->p[k].ref;
        r->tris += chk_tris;
        r->area[k] = chk_area;
    }
    g->DeleteTess(t);
    if (getenv("TESS_BENCH_HASH")) fprintf(stderr, "%s %s: output hash %016llx\n", g->name, s->name, (unsigned long long)chk_hash);
    chk_hash = 0xcbf29ce484222325ull;
}

static double now(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return ts.tv_sec + ts.tv_nsec * 1e-9;
}

/* noinline: the symbol callgrind's --toggle-collect=time_set needs */
__attribute__((noinline)) static double time_set(Glu *g, Set *s)
{
    void *t = make_tess(g, 0);
    double t0 = now();
    int k;
    for (k = 0; k < s->n; k++)
        run_poly(g, t, &s->p[k]);
    t0 = now() - t0;
    g->DeleteTess(t);
    return t0 * 1e6 / s->n;
}

/* Is `name` one of the semicolon-separated names in `list`? */
static int listed(const char *list, const char *name)
{
    size_t n = strlen(name);
    const char *p = list;
    while ((p = strstr(p, name))) {
        if ((p == list || p[-1] == ';') && (p[n] == ';' || p[n] == 0)) return 1;
        p++;
    }
    return 0;
}

int main(int argc, char **argv)
{
    Glu glus[2];
    const char *out = NULL, *only = NULL, *lib = NULL;
    int reps = 7, quick = 0, i, k, have[2];
    Set sets[12];
    int nsets = 0;
    FILE *md;
    memset(glus, 0, sizeof glus);
    glus[0].name = "softgl";
    glus[0].path = "build/lib/libGLU.so.1";
    glus[1].name = "libGLU";
    glus[1].path = "/usr/lib/x86_64-linux-gnu/libGLU.so.1";
    for (i = 1; i < argc; i++) {
        if (!strcmp(argv[i], "--softgl") && i + 1 < argc) glus[0].path = argv[++i];
        else if (!strcmp(argv[i], "--glu") && i + 1 < argc) glus[1].path = argv[++i];
        else if (!strcmp(argv[i], "--reps") && i + 1 < argc) reps = atoi(argv[++i]);
        else if (!strcmp(argv[i], "--out") && i + 1 < argc) out = argv[++i];
        else if (!strcmp(argv[i], "--quick")) quick = 1;
        else if (!strcmp(argv[i], "--only") && i + 1 < argc) only = argv[++i];
        else if (!strcmp(argv[i], "--lib") && i + 1 < argc) lib = argv[++i];
        else {
            fprintf(stderr, "usage: %s [--softgl PATH] [--glu PATH] [--reps N] [--quick] [--only SET;SET] [--lib softgl|libGLU] [--out FILE.md]\n", argv[0]);
            return 2;
        }
    }
    if (quick) reps = 3;
    if (reps < 1) reps = 1;
    for (i = 0; i < 2; i++) have[i] = (!lib || !strcmp(lib, glus[i].name)) && load(&glus[i]);
    if (!have[0] && !have[1]) return 1;

    memset(sets, 0, sizeof sets);
#define SET(nm, wh) (sets[nsets].name = nm, sets[nsets].what = wh, &sets[nsets++])
    book_set(SET("book", "the Persian book's shapes: winding-rule panels x 5 rules, star with square, quad with hole, dinosaur outlines"));
    random_simple_set(SET("random simple", "star-shaped, 8-63 vertices"), 400);
    self_intersecting_set(SET("random self-intersecting", "6-39 random points, ODD / NONZERO"), 400);
    holes_set(SET("100 holes", "square with 10x10 holes of 16 vertices"), 10, 20);
    holes_set(SET("1,600 holes", "square with 40x40 holes of 16 vertices"), 40, 2);
    simple_set(SET("n = 10", "random simple, 10 vertices"), 10, 2000);
    simple_set(SET("n = 100", "random simple, 100 vertices"), 100, 200);
    simple_set(SET("n = 1,000", "random simple, 1,000 vertices"), 1000, 20);
    simple_set(SET("n = 10,000", "random simple, 10,000 vertices"), 10000, 3);
    simple_set(SET("n = 100,000", "random simple, 100,000 vertices"), 100000, 1);
#undef SET

    md = out ? fopen(out, "w") : NULL;
    if (out && !md) perror(out);
    {
        const char *head =
            "| set | polygons | vertices / polygon | softgl us / polygon | libGLU us / polygon | libGLU / softgl |"
            " softgl failures / wrong area | libGLU failures / wrong area | softgl / libGLU triangles |\n"
            "| --- | ---: | ---: | ---: | ---: | ---: | ---: | ---: | ---: |\n";
        printf("%s", head);
        if (md) {
            fprintf(md, "# GLU tessellator: softgl against libGLU\n\n");
            fprintf(md, "softgl: `%s`; libGLU: `%s`%s. Median of %d repetitions of each set "
                        "(alternating which library runs first), time per polygon in microseconds; "
                        "a failure is a polygon with an ERROR callback call, or no output where the rule selects a "
                        "non-empty region; a wrong area is a covered area (sum of the output triangles' areas) off "
                        "by more than 1e-7 relative from the area computed independently (vertical slabs; the shoelace "
                        "sum for the simple and nested sets).\n\n",
                    glus[0].path, glus[1].path, have[1] ? "" : " (not found: softgl only)", reps);
            fprintf(md, "%s", head);
        }
    }
    for (k = 0; k < nsets; k++) {
        Set *s = &sets[k];
        Result res[2];
        if (only && !listed(only, s->name)) continue;
        long nv = 0;
        int rep;
        char line[1024], ratio[32] = "-", b_us[32] = "-", b_fail[32] = "-", tris[64];
        memset(res, 0, sizeof res);
        for (i = 0; i < s->n; i++) {
            nv += s->p[i].nv;
            s->p[i].ref = reference_area(&s->p[i]);
        }
        for (i = 0; i < 2; i++) {
            if (!have[i]) continue;
            check(&glus[i], s, &res[i]);
        }
        for (i = 0; i < 2; i++) res[i].us = calloc(reps, sizeof(double)); /* zeros for a library left out */
        for (rep = 0; rep < reps; rep++)
            for (i = 0; i < 2; i++) {
                int j = rep % 2 ? 1 - i : i;
                if (have[j]) res[j].us[rep] = time_set(&glus[j], s);
            }
        if (have[1]) {
            snprintf(b_us, sizeof b_us, "%.2f", median(res[1].us, reps));
            snprintf(b_fail, sizeof b_fail, "%d / %d", res[1].failures, res[1].wrong);
            if (have[0]) snprintf(ratio, sizeof ratio, "%.2fx", median(res[1].us, reps) / median(res[0].us, reps));
            snprintf(tris, sizeof tris, "%ld / %ld", res[0].tris, res[1].tris);
        } else {
            snprintf(tris, sizeof tris, "%ld / -", res[0].tris);
        }
        snprintf(line, sizeof line, "| %s | %d | %.0f | %.2f | %s | %s | %d / %d | %s | %s |\n", s->name, s->n,
                 (double)nv / s->n, median(res[0].us, reps), b_us, ratio, res[0].failures, res[0].wrong, b_fail, tris);
        printf("%s", line);
        fflush(stdout);
        if (md) fprintf(md, "%s", line);
    }
    if (md) {
        fprintf(md, "\nSets:\n\n");
        for (k = 0; k < nsets; k++) fprintf(md, "- %s: %s\n", sets[k].name, sets[k].what);
        fclose(md);
    }
    return 0;
}
