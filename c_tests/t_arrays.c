/* t_arrays: vertex arrays (GL 1.5 section 2.8) drawn with exact pixel checks.
 *
 * Every shape is a union of axis-aligned rectangles with integer corners
 * under an exact ortho projection, so the covered pixels are known: (x,y)
 * is covered iff x0 <= x < x1 and y0 <= y < y1 (see t_primitives).
 *
 *  - glDrawArrays with vertex arrays of every type (short, int, float,
 *    double) and size (2, 3, 4 with w = 2), tight and padded strides;
 *  - colour arrays of every type, flat-shaded quads taking their last
 *    vertex's colour, exact 8-bit values;
 *  - glInterleavedArrays in all 14 formats laid out by hand from table 2.5:
 *    coverage checks the vertex offsets, the colour its offset and type,
 *    and for the N3F formats a directional light shows N.L (normal offset);
 *  - glDrawElements / glDrawRangeElements with each index type,
 *    glMultiDrawArrays / glMultiDrawElements;
 *  - glArrayElement between Begin and End;
 *  - display lists: the array data are captured when the list is compiled,
 *    later changes to the arrays do not reach the list;
 *  - errors: negative count, bad mode, bad index type, draws between Begin
 *    and End, bad sizes, types and strides.
 */
#define GL_GLEXT_PROTOTYPES
#include "harness.h"
#include <stdio.h>
#include <string.h>

#define W 48
#define H 32

static unsigned char px[W * H * 4];

/* Count pixels inside/outside rectangle r (x0,y0,x1,y1) that are not the
 * expected colour (inside) / not black (outside). */
static void expect_rect(const int r[4], const unsigned char c[4], int tol, const char *what)
{
    int x, y, bad = 0, fx = -1, fy = -1;
    h_read(px);
    for (y = 0; y < H; y++)
        for (x = 0; x < W; x++) {
            const unsigned char *p = &px[(y * W + x) * 4];
            int in = x >= r[0] && x < r[2] && y >= r[1] && y < r[3];
            int k, ok = 1;
            for (k = 0; k < 4; k++) {
                int want = in ? c[k] : 0;
                int d = p[k] - want;
                if (d < -tol || d > tol)
                    ok = 0;
            }
            if (!ok) {
                if (fx < 0) { fx = x; fy = y; }
                bad++;
            }
        }
    h_expect(bad == 0, "%s: %d wrong pixels, first (%d,%d) = %d,%d,%d,%d", what, bad, fx, fy,
             fx < 0 ? 0 : px[(fy * W + fx) * 4], fx < 0 ? 0 : px[(fy * W + fx) * 4 + 1],
             fx < 0 ? 0 : px[(fy * W + fx) * 4 + 2], fx < 0 ? 0 : px[(fy * W + fx) * 4 + 3]);
}

static void clear(void)
{
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
}

static const int RECT[4] = {3, 5, 29, 27};

/* The four corners of RECT as a quad, counter-clockwise. */
static void corners(double out[4][4], double w)
{
    double c[4][2] = {{RECT[0], RECT[1]}, {RECT[2], RECT[1]}, {RECT[2], RECT[3]}, {RECT[0], RECT[3]}};
    int i;
    for (i = 0; i < 4; i++) {
        out[i][0] = c[i][0] * w;
        out[i][1] = c[i][1] * w;
        out[i][2] = 0;
        out[i][3] = w;
    }
}

static void vertex_types(void)
{
    static const GLenum types[4] = {GL_SHORT, GL_INT, GL_FLOAT, GL_DOUBLE};
    static const unsigned char white[4] = {255, 255, 255, 255};
    unsigned char buf[4 * 64];
    int t, size, s;
    glColor4ub(255, 255, 255, 255);
    for (t = 0; t < 4; t++)
        for (size = 2; size <= 4; size++)
            for (s = 0; s < 2; s++) {
                double c[4][4];
                int stride = s ? 48 : 0, i, k, esize;
                char what[96];
                esize = types[t] == GL_SHORT ? 2 : types[t] == GL_DOUBLE ? 8 : 4;
                corners(c, size == 4 ? 2.0 : 1.0);
                memset(buf, 0x5A, sizeof buf);
                for (i = 0; i < 4; i++)
                    for (k = 0; k < size; k++) {
                        unsigned char *p = buf + i * (stride ? stride : size * esize) + k * esize;
                        double v = c[i][k];
                        switch (types[t]) {
                        case GL_SHORT: { GLshort x = (GLshort)v; memcpy(p, &x, 2); break; }
                        case GL_INT: { GLint x = (GLint)v; memcpy(p, &x, 4); break; }
                        case GL_FLOAT: { GLfloat x = (GLfloat)v; memcpy(p, &x, 4); break; }
                        default: memcpy(p, &v, 8);
                        }
                    }
                clear();
                glVertexPointer(size, types[t], stride, buf);
                glEnableClientState(GL_VERTEX_ARRAY);
                glDrawArrays(GL_TRIANGLE_FAN, 0, 4);
                glDisableClientState(GL_VERTEX_ARRAY);
                snprintf(what, sizeof what, "vertex array type 0x%x size %d stride %d", types[t], size, stride);
                h_expect_no_error(what);
                expect_rect(RECT, white, 0, what);
            }
}

/* Two flat-shaded quads side by side; each takes its 4th vertex's colour. */
static void color_types(void)
{
    static const GLenum types[8] = {GL_BYTE, GL_UNSIGNED_BYTE, GL_SHORT, GL_UNSIGNED_SHORT,
                                    GL_INT, GL_UNSIGNED_INT, GL_FLOAT, GL_DOUBLE};
    static const GLfloat v[8][2] = {{2, 2}, {20, 2}, {20, 30}, {2, 30},
                                    {20, 2}, {46, 2}, {46, 30}, {20, 30}};
    /* Colours whose conversion is exact enough to land on known bytes:
     * full-scale and zero components only (table 2.9 maps them to 1, 0 for
     * unsigned types; signed types map 0 to 1/(2^b-1), which rounds to 0). */
    static const int cols[8][4] = {{0, 0, 0, 0}, {0, 0, 0, 0}, {0, 0, 0, 0}, {1, 0, 1, 1},
                                   {0, 0, 0, 0}, {0, 0, 0, 0}, {0, 0, 0, 0}, {0, 1, 1, 1}};
    unsigned char buf[8 * 64];
    int t, size, i, k;
    glShadeModel(GL_FLAT);
    glVertexPointer(2, GL_FLOAT, 0, v);
    glEnableClientState(GL_VERTEX_ARRAY);
    for (t = 0; t < 8; t++)
        for (size = 3; size <= 4; size++) {
            int esize = types[t] == GL_BYTE || types[t] == GL_UNSIGNED_BYTE ? 1
                      : types[t] == GL_SHORT || types[t] == GL_UNSIGNED_SHORT ? 2
                      : types[t] == GL_DOUBLE ? 8 : 4;
            int stride = size * esize + 3;
            char what[96];
            memset(buf, 0, sizeof buf);
            for (i = 0; i < 8; i++)
                for (k = 0; k < size; k++) {
                    unsigned char *p = buf + i * stride + k * esize;
                    int one = cols[i][k];
                    switch (types[t]) {
                    case GL_BYTE: { GLbyte x = one ? 127 : 0; memcpy(p, &x, 1); break; }
                    case GL_UNSIGNED_BYTE: { GLubyte x = one ? 255 : 0; memcpy(p, &x, 1); break; }
                    case GL_SHORT: { GLshort x = one ? 32767 : 0; memcpy(p, &x, 2); break; }
                    case GL_UNSIGNED_SHORT: { GLushort x = one ? 65535 : 0; memcpy(p, &x, 2); break; }
                    case GL_INT: { GLint x = one ? 2147483647 : 0; memcpy(p, &x, 4); break; }
                    case GL_UNSIGNED_INT: { GLuint x = one ? 4294967295u : 0; memcpy(p, &x, 4); break; }
                    case GL_FLOAT: { GLfloat x = (GLfloat)one; memcpy(p, &x, 4); break; }
                    default: { GLdouble x = one; memcpy(p, &x, 8); }
                    }
                }
            clear();
            glColorPointer(size, types[t], stride, buf);
            glEnableClientState(GL_COLOR_ARRAY);
            glDrawArrays(GL_QUADS, 0, 8);
            glDisableClientState(GL_COLOR_ARRAY);
            snprintf(what, sizeof what, "colour array type 0x%x size %d", types[t], size);
            h_expect_no_error(what);
            h_expect_pixel(10, 15, 255, 0, 255, 255, 1, what);
            h_expect_pixel(30, 15, 0, 255, 255, 255, 1, what);
            h_expect_pixel(47, 31, 0, 0, 0, 0, 0, what);
        }
    glDisableClientState(GL_VERTEX_ARRAY);
    glShadeModel(GL_SMOOTH);
}

/* Table 2.5, written out for the test: texcoord size, colour size (0 none),
 * colour is ubyte, normal, vertex size. */
struct fmt { GLenum f; const char *name; int t, c, ub, n, v; };
static const struct fmt FORMATS[14] = {
    {GL_V2F, "V2F", 0, 0, 0, 0, 2},
    {GL_V3F, "V3F", 0, 0, 0, 0, 3},
    {GL_C4UB_V2F, "C4UB_V2F", 0, 4, 1, 0, 2},
    {GL_C4UB_V3F, "C4UB_V3F", 0, 4, 1, 0, 3},
    {GL_C3F_V3F, "C3F_V3F", 0, 3, 0, 0, 3},
    {GL_N3F_V3F, "N3F_V3F", 0, 0, 0, 1, 3},
    {GL_C4F_N3F_V3F, "C4F_N3F_V3F", 0, 4, 0, 1, 3},
    {GL_T2F_V3F, "T2F_V3F", 2, 0, 0, 0, 3},
    {GL_T4F_V4F, "T4F_V4F", 4, 0, 0, 0, 4},
    {GL_T2F_C4UB_V3F, "T2F_C4UB_V3F", 2, 4, 1, 0, 3},
    {GL_T2F_C3F_V3F, "T2F_C3F_V3F", 2, 3, 0, 0, 3},
    {GL_T2F_N3F_V3F, "T2F_N3F_V3F", 2, 0, 0, 1, 3},
    {GL_T2F_C4F_N3F_V3F, "T2F_C4F_N3F_V3F", 2, 4, 0, 1, 3},
    {GL_T4F_C4F_N3F_V4F, "T4F_C4F_N3F_V4F", 4, 4, 0, 1, 4},
};

static void put_f(unsigned char **p, float f)
{
    memcpy(*p, &f, 4);
    *p += 4;
}

static void interleaved(void)
{
    static const GLfloat light_pos[4] = {0, 0, 1, 0};
    static const GLfloat white[4] = {1, 1, 1, 1};
    static const GLfloat black[4] = {0, 0, 0, 1};
    unsigned char buf[4 * 128];
    int k, pad;
    glLightfv(GL_LIGHT0, GL_POSITION, light_pos);
    glLightfv(GL_LIGHT0, GL_DIFFUSE, white);
    glLightModelfv(GL_LIGHT_MODEL_AMBIENT, black);
    glMaterialfv(GL_FRONT_AND_BACK, GL_AMBIENT, black);
    glMaterialfv(GL_FRONT_AND_BACK, GL_DIFFUSE, white);
    glEnable(GL_LIGHT0);
    for (k = 0; k < 14; k++)
        for (pad = 0; pad <= 8; pad += 8) {
            const struct fmt *f = &FORMATS[k];
            double c[4][4];
            unsigned char *p = buf;
            unsigned char want[4];
            int i, j, stride = 0;
            char what[96];
            corners(c, f->v == 4 ? 2.0 : 1.0);
            memset(buf, 0x77, sizeof buf);
            for (i = 0; i < 4; i++) {
                unsigned char *start = p;
                for (j = 0; j < f->t; j++)
                    put_f(&p, 0.5f + j);
                if (f->c && f->ub) {
                    p[0] = 51; p[1] = 102; p[2] = 204; p[3] = 255;
                    p += 4;
                } else if (f->c) {
                    put_f(&p, 0.2f); put_f(&p, 0.4f); put_f(&p, 0.8f);
                    if (f->c == 4)
                        put_f(&p, 1.0f);
                }
                if (f->n) {
                    put_f(&p, 0.0f); put_f(&p, 0.6f); put_f(&p, 0.8f);
                }
                for (j = 0; j < f->v; j++)
                    put_f(&p, (float)c[i][j]);
                p += pad;
                stride = (int)(p - start);
            }
            if (f->n) {
                /* Lit: white diffuse times N.L = 0.8; a colour array does not
                 * feed the material (no COLOR_MATERIAL). */
                glEnable(GL_LIGHTING);
                want[0] = want[1] = want[2] = 204;
            } else if (f->c) {
                want[0] = 51; want[1] = 102; want[2] = 204;
            } else {
                want[0] = 255; want[1] = 255; want[2] = 0;
            }
            want[3] = 255;
            clear();
            glColor4ub(255, 255, 0, 255);
            glInterleavedArrays(f->f, pad ? stride : 0, buf);
            glDrawArrays(GL_QUADS, 0, 4);
            glDisable(GL_LIGHTING);
            glDisableClientState(GL_VERTEX_ARRAY);
            glDisableClientState(GL_COLOR_ARRAY);
            glDisableClientState(GL_NORMAL_ARRAY);
            glDisableClientState(GL_TEXTURE_COORD_ARRAY);
            snprintf(what, sizeof what, "glInterleavedArrays(GL_%s) stride %d", f->name, pad ? stride : 0);
            h_expect_no_error(what);
            expect_rect(RECT, want, 1, what);
        }
    glDisable(GL_LIGHT0);
}

static const GLfloat SCENE[12][2] = {
    {0, 0}, {4, 0}, {4, 4}, {0, 4},         /* decoy 0..3 */
    {10, 8}, {30, 8}, {30, 24}, {10, 24},   /* the quad 4..7 */
    {40, 28}, {44, 28}, {44, 32}, {40, 32}, /* decoy 8..11 */
};

static void elements(void)
{
    static const int quad[4] = {10, 8, 30, 24};
    static const unsigned char green[4] = {0, 255, 0, 255};
    static const GLubyte ub[4] = {4, 5, 6, 7};
    static const GLushort us[6] = {4, 5, 6, 4, 6, 7};
    static const GLuint ui[4] = {4, 5, 6, 7};
    static const GLint first[2] = {0, 8};
    static const GLsizei count[2] = {4, 4};
    static const GLubyte a[4] = {0, 1, 2, 3}, b[4] = {4, 5, 6, 7};
    const GLvoid *ptrs[2];
    int i, n = 0;
    glColor4ub(0, 255, 0, 255);
    glVertexPointer(2, GL_FLOAT, 0, SCENE);
    glEnableClientState(GL_VERTEX_ARRAY);
    clear();
    glDrawElements(GL_QUADS, 4, GL_UNSIGNED_BYTE, ub);
    expect_rect(quad, green, 0, "glDrawElements GL_UNSIGNED_BYTE");
    clear();
    glDrawElements(GL_TRIANGLES, 6, GL_UNSIGNED_SHORT, us);
    expect_rect(quad, green, 0, "glDrawElements GL_UNSIGNED_SHORT triangles");
    clear();
    glDrawElements(GL_QUADS, 4, GL_UNSIGNED_INT, ui);
    expect_rect(quad, green, 0, "glDrawElements GL_UNSIGNED_INT");
    clear();
    glDrawRangeElements(GL_QUADS, 4, 7, 4, GL_UNSIGNED_INT, ui);
    expect_rect(quad, green, 0, "glDrawRangeElements");
    h_expect_no_error("draw elements");

    clear();
    glMultiDrawArrays(GL_QUADS, first, count, 2);
    h_read(px);
    for (i = 0; i < W * H; i++)
        n += px[i * 4 + 1] == 255;
    h_expect(n == 32, "glMultiDrawArrays: %d pixels drawn, want 32", n);
    clear();
    ptrs[0] = a;
    ptrs[1] = b;
    glMultiDrawElements(GL_QUADS, count, GL_UNSIGNED_BYTE, ptrs, 2);
    h_read(px);
    for (n = 0, i = 0; i < W * H; i++)
        n += px[i * 4 + 1] == 255;
    h_expect(n == 16 + 320, "glMultiDrawElements: %d pixels drawn, want 336", n);
    h_expect_no_error("multi draw");

    /* glArrayElement between Begin and End, with a colour array. */
    {
        static const GLubyte cols[12][4] = {{0}, {0}, {0}, {0},
            {255, 0, 0, 255}, {255, 0, 0, 255}, {255, 0, 0, 255}, {255, 0, 0, 255}};
        static const unsigned char red[4] = {255, 0, 0, 255};
        glColorPointer(4, GL_UNSIGNED_BYTE, 0, cols);
        glEnableClientState(GL_COLOR_ARRAY);
        clear();
        glBegin(GL_QUADS);
        for (i = 4; i < 8; i++)
            glArrayElement(i);
        glEnd();
        glDisableClientState(GL_COLOR_ARRAY);
        h_expect_no_error("glArrayElement");
        expect_rect(quad, red, 0, "glArrayElement in Begin/End");
    }
    glDisableClientState(GL_VERTEX_ARRAY);
}

static void lists(void)
{
    static const int quad[4] = {10, 8, 30, 24};
    static const unsigned char blue[4] = {0, 0, 255, 255};
    GLfloat v[12][2];
    GLubyte cols[12][4];
    GLubyte idx[4] = {4, 5, 6, 7};
    GLuint l = glGenLists(3);
    int i;
    memcpy(v, SCENE, sizeof v);
    for (i = 0; i < 12; i++) {
        cols[i][0] = 0; cols[i][1] = 0; cols[i][2] = 255; cols[i][3] = 255;
    }
    glVertexPointer(2, GL_FLOAT, 0, v);
    glColorPointer(4, GL_UNSIGNED_BYTE, 0, cols);
    glEnableClientState(GL_VERTEX_ARRAY);
    glEnableClientState(GL_COLOR_ARRAY);
    clear();
    glNewList(l, GL_COMPILE);
    glDrawArrays(GL_QUADS, 4, 4);
    glEndList();
    glNewList(l + 1, GL_COMPILE);
    glDrawElements(GL_QUADS, 4, GL_UNSIGNED_BYTE, idx);
    glEndList();
    glNewList(l + 2, GL_COMPILE);
    glBegin(GL_QUADS);
    for (i = 4; i < 8; i++)
        glArrayElement(i);
    glEnd();
    glEndList();
    h_expect_no_error("compiling array draws");
    h_read(px);
    for (i = 0; i < W * H * 4; i++)
        if (px[i] && (i % 4) != 3)
            break;
    h_expect(i == W * H * 4, "GL_COMPILE drew something");
    /* Change everything the lists read. */
    for (i = 0; i < 12; i++) {
        v[i][0] += 100;
        cols[i][0] = 255; cols[i][2] = 0;
    }
    idx[0] = idx[1] = idx[2] = idx[3] = 0;
    for (i = 0; i < 3; i++) {
        clear();
        glCallList(l + i);
        expect_rect(quad, blue, 0, i == 0 ? "list of glDrawArrays keeps the old data"
                                  : i == 1 ? "list of glDrawElements keeps the old data"
                                           : "list of glArrayElement keeps the old data");
    }
    glDisableClientState(GL_VERTEX_ARRAY);
    glDisableClientState(GL_COLOR_ARRAY);
    glDeleteLists(l, 3);
}

static void errors(void)
{
    static const GLfloat v[6] = {0, 0, 1, 0, 0, 1};
    static const GLubyte idx[3] = {0, 1, 2};
    glVertexPointer(2, GL_FLOAT, 0, v);
    glEnableClientState(GL_VERTEX_ARRAY);
    glDrawArrays(GL_TRIANGLES, 0, -1);
    h_expect_error(GL_INVALID_VALUE, "glDrawArrays count -1");
    glDrawArrays(0x1234, 0, 3);
    h_expect_error(GL_INVALID_ENUM, "glDrawArrays bad mode");
    glDrawElements(GL_TRIANGLES, -1, GL_UNSIGNED_BYTE, idx);
    h_expect_error(GL_INVALID_VALUE, "glDrawElements count -1");
    glDrawElements(GL_TRIANGLES, 3, GL_BYTE, idx);
    h_expect_error(GL_INVALID_ENUM, "glDrawElements GL_BYTE");
    glDrawRangeElements(GL_TRIANGLES, 2, 1, 3, GL_UNSIGNED_BYTE, idx);
    h_expect_error(GL_INVALID_VALUE, "glDrawRangeElements end < start");
    glBegin(GL_TRIANGLES);
    glDrawArrays(GL_TRIANGLES, 0, 3);
    glEnd();
    h_expect_error(GL_INVALID_OPERATION, "glDrawArrays between Begin and End");
    glVertexPointer(1, GL_FLOAT, 0, v);
    h_expect_error(GL_INVALID_VALUE, "glVertexPointer size 1");
    glVertexPointer(2, GL_BYTE, 0, v);
    h_expect_error(GL_INVALID_ENUM, "glVertexPointer GL_BYTE");
    glVertexPointer(2, GL_FLOAT, -1, v);
    h_expect_error(GL_INVALID_VALUE, "glVertexPointer stride -1");
    glColorPointer(2, GL_FLOAT, 0, v);
    h_expect_error(GL_INVALID_VALUE, "glColorPointer size 2");
    glNormalPointer(GL_UNSIGNED_BYTE, 0, v);
    h_expect_error(GL_INVALID_ENUM, "glNormalPointer GL_UNSIGNED_BYTE");
    glEnableClientState(GL_LIGHTING);
    h_expect_error(GL_INVALID_ENUM, "glEnableClientState(GL_LIGHTING)");
    glInterleavedArrays(GL_RGBA, 0, v);
    h_expect_error(GL_INVALID_ENUM, "glInterleavedArrays bad format");
    {
        GLint i;
        GLvoid *p = NULL;
        glGetIntegerv(GL_VERTEX_ARRAY_SIZE, &i);
        h_expect(i == 2, "GL_VERTEX_ARRAY_SIZE unchanged by errors: %d", i);
        glGetPointerv(GL_VERTEX_ARRAY_POINTER, &p);
        h_expect(p == (GLvoid *)v, "GL_VERTEX_ARRAY_POINTER");
    }
    glDisableClientState(GL_VERTEX_ARRAY);
    h_expect_no_error("errors");
}

int main(void)
{
    h_init(W, H);
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    glOrtho(0, W, 0, H, -1, 1);
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
    glClearColor(0, 0, 0, 0);

    vertex_types();
    color_types();
    interleaved();
    elements();
    lists();
    errors();
    return h_finish();
}
