/* t_vbo: buffer objects (GL 1.5 section 2.9) as vertex array and index
 * sources, mapping, and occlusion queries (section 4.1.6), with exact
 * pixel and sample counts.
 *
 *  - vertices and colours in buffer objects at non-zero offsets (the
 *    pointer is an offset into the buffer bound when it was specified),
 *    indices in an element array buffer at an offset; exact coverage;
 *  - glMapBuffer(GL_WRITE_ONLY) to fill a buffer, then drawing from it;
 *    glBufferSubData updates what is drawn; glGetBufferSubData reads back;
 *  - a display list compiled from buffer-object arrays keeps the data it
 *    read at compile time after the buffer changes;
 *  - errors: mapping twice, unmapping an unmapped buffer, drawing from a
 *    mapped buffer (INVALID_OPERATION); ranges outside the buffer
 *    (INVALID_VALUE); bad targets and access (INVALID_ENUM); the buffer
 *    parameters and bindings;
 *  - occlusion queries: a 10x10 square passes 100 samples; a square half
 *    hidden behind it passes 50; a stencil test that never passes gives 0;
 *    glGetQueryiv(GL_CURRENT_QUERY), result availability, query errors.
 */
#define GL_GLEXT_PROTOTYPES
#include "harness.h"
#include <stdio.h>
#include <string.h>

#define W 48
#define H 32

static unsigned char px[W * H * 4];

static void expect_rect(const int r[4], const unsigned char c[4], const char *what)
{
    int x, y, bad = 0, fx = -1, fy = -1;
    h_read(px);
    for (y = 0; y < H; y++)
        for (x = 0; x < W; x++) {
            const unsigned char *p = &px[(y * W + x) * 4];
            int in = x >= r[0] && x < r[2] && y >= r[1] && y < r[3];
            int k, ok = 1;
            for (k = 0; k < 4; k++)
                if (p[k] != (in ? c[k] : 0))
                    ok = 0;
            if (!ok) {
                if (fx < 0) { fx = x; fy = y; }
                bad++;
            }
        }
    h_expect(bad == 0, "%s: %d wrong pixels, first (%d,%d)", what, bad, fx, fy);
}

static void clear(void)
{
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT | GL_STENCIL_BUFFER_BIT);
}

static const GLfloat SCENE[12][2] = {
    {0, 0}, {4, 0}, {4, 4}, {0, 4},
    {10, 8}, {30, 8}, {30, 24}, {10, 24},
    {40, 28}, {44, 28}, {44, 32}, {40, 32},
};
static const int QUAD[4] = {10, 8, 30, 24};

static void sources(GLuint *b)
{
    static const unsigned char magenta[4] = {255, 0, 255, 255};
    static const unsigned char yellow[4] = {255, 255, 0, 255};
    unsigned char vdata[16 + sizeof SCENE];
    GLubyte cols[12][4];
    GLushort idx[5] = {0, 4, 5, 6, 7};
    GLint v;
    GLubyte *m;
    int i;

    memset(vdata, 0, 16);
    memcpy(vdata + 16, SCENE, sizeof SCENE);
    for (i = 0; i < 12; i++) {
        cols[i][0] = 255; cols[i][1] = 0; cols[i][2] = 255; cols[i][3] = 255;
    }
    glBindBuffer(GL_ARRAY_BUFFER, b[0]);
    glBufferData(GL_ARRAY_BUFFER, sizeof vdata, vdata, GL_STATIC_DRAW);
    glVertexPointer(2, GL_FLOAT, 0, (const GLvoid *)16);
    glBindBuffer(GL_ARRAY_BUFFER, b[1]);
    glBufferData(GL_ARRAY_BUFFER, 4 + sizeof cols, NULL, GL_DYNAMIC_DRAW);
    glBufferSubData(GL_ARRAY_BUFFER, 4, sizeof cols, cols);
    glColorPointer(4, GL_UNSIGNED_BYTE, 0, (const GLvoid *)4);
    glBindBuffer(GL_ARRAY_BUFFER, 0);
    glGetIntegerv(GL_VERTEX_ARRAY_BUFFER_BINDING, &v);
    h_expect(v == (GLint)b[0], "GL_VERTEX_ARRAY_BUFFER_BINDING %d", v);
    glGetIntegerv(GL_COLOR_ARRAY_BUFFER_BINDING, &v);
    h_expect(v == (GLint)b[1], "GL_COLOR_ARRAY_BUFFER_BINDING %d", v);
    glEnableClientState(GL_VERTEX_ARRAY);
    glEnableClientState(GL_COLOR_ARRAY);

    clear();
    glDrawArrays(GL_QUADS, 4, 4);
    h_expect_no_error("glDrawArrays from buffers");
    expect_rect(QUAD, magenta, "glDrawArrays from buffers at offsets");

    glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, b[2]);
    glBufferData(GL_ELEMENT_ARRAY_BUFFER, sizeof idx, idx, GL_STATIC_DRAW);
    clear();
    glDrawElements(GL_QUADS, 4, GL_UNSIGNED_SHORT, (const GLvoid *)2);
    h_expect_no_error("glDrawElements from an element buffer");
    expect_rect(QUAD, magenta, "glDrawElements, indices at offset 2 of a buffer");
    glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, 0);

    /* Fill the colours through a write-only mapping. */
    glBindBuffer(GL_ARRAY_BUFFER, b[1]);
    m = glMapBuffer(GL_ARRAY_BUFFER, GL_WRITE_ONLY);
    h_expect(m != NULL, "glMapBuffer returned NULL");
    if (m) {
        for (i = 0; i < 12; i++) {
            m[4 + 4 * i] = 255; m[5 + 4 * i] = 255; m[6 + 4 * i] = 0; m[7 + 4 * i] = 255;
        }
    }
    glGetBufferParameteriv(GL_ARRAY_BUFFER, GL_BUFFER_MAPPED, &v);
    h_expect(v == GL_TRUE, "GL_BUFFER_MAPPED %d", v);
    glGetBufferParameteriv(GL_ARRAY_BUFFER, GL_BUFFER_ACCESS, &v);
    h_expect(v == GL_WRITE_ONLY, "GL_BUFFER_ACCESS 0x%x", v);
    /* Errors while mapped. */
    h_expect(glMapBuffer(GL_ARRAY_BUFFER, GL_READ_ONLY) == NULL, "second map returned a pointer");
    h_expect_error(GL_INVALID_OPERATION, "glMapBuffer twice");
    /* Sourcing a mapped buffer is INVALID_OPERATION (softgl; tests/arrays.rs
     * checks it); Mesa's OSMesa no longer checks, so either is accepted here. */
    glDrawArrays(GL_QUADS, 4, 4);
    {
        GLenum e = glGetError();
        h_expect(e == GL_INVALID_OPERATION || e == GL_NO_ERROR, "glDrawArrays from a mapped buffer: 0x%x", e);
    }
    glBufferSubData(GL_ARRAY_BUFFER, 0, 4, cols);
    h_expect_error(GL_INVALID_OPERATION, "glBufferSubData on a mapped buffer");
    h_expect(glUnmapBuffer(GL_ARRAY_BUFFER) == GL_TRUE, "glUnmapBuffer");
    h_expect(glUnmapBuffer(GL_ARRAY_BUFFER) == GL_FALSE, "second glUnmapBuffer");
    h_expect_error(GL_INVALID_OPERATION, "glUnmapBuffer of an unmapped buffer");
    clear();
    glDrawArrays(GL_QUADS, 4, 4);
    expect_rect(QUAD, yellow, "drawing after a write mapping");
    {
        GLubyte back[4];
        glGetBufferSubData(GL_ARRAY_BUFFER, 4 + 4 * 5, 4, back);
        h_expect(back[0] == 255 && back[1] == 255 && back[2] == 0 && back[3] == 255,
                 "glGetBufferSubData %d,%d,%d,%d", back[0], back[1], back[2], back[3]);
    }

    /* A list compiled from buffer arrays keeps their data. */
    {
        GLuint l = glGenLists(1);
        glNewList(l, GL_COMPILE);
        glDrawArrays(GL_QUADS, 4, 4);
        glEndList();
        glBufferSubData(GL_ARRAY_BUFFER, 4, sizeof cols, cols); /* back to magenta */
        clear();
        glCallList(l);
        expect_rect(QUAD, yellow, "list compiled from buffer arrays keeps their data");
        clear();
        glDrawArrays(GL_QUADS, 4, 4);
        expect_rect(QUAD, magenta, "glBufferSubData changed what is drawn");
        glDeleteLists(l, 1);
    }

    /* Ranges, enums, parameters. */
    glBufferSubData(GL_ARRAY_BUFFER, 4, sizeof cols + 1, cols);
    h_expect_error(GL_INVALID_VALUE, "glBufferSubData past the end");
    glBufferSubData(GL_ARRAY_BUFFER, -1, 4, cols);
    h_expect_error(GL_INVALID_VALUE, "glBufferSubData negative offset");
    glBufferData(GL_ARRAY_BUFFER, -1, NULL, GL_STATIC_DRAW);
    h_expect_error(GL_INVALID_VALUE, "glBufferData negative size");
    glBufferData(GL_ARRAY_BUFFER, 4, NULL, GL_RGBA);
    h_expect_error(GL_INVALID_ENUM, "glBufferData bad usage");
    h_expect(glMapBuffer(GL_ARRAY_BUFFER, GL_STATIC_DRAW) == NULL, "map with bad access");
    h_expect_error(GL_INVALID_ENUM, "glMapBuffer bad access");
    glBindBuffer(GL_RGBA, b[0]);
    h_expect_error(GL_INVALID_ENUM, "glBindBuffer bad target");
    glGetBufferParameteriv(GL_ARRAY_BUFFER, GL_BUFFER_SIZE, &v);
    h_expect(v == (GLint)(4 + sizeof cols), "GL_BUFFER_SIZE %d", v);
    glGetBufferParameteriv(GL_ARRAY_BUFFER, GL_BUFFER_USAGE, &v);
    h_expect(v == GL_DYNAMIC_DRAW, "GL_BUFFER_USAGE 0x%x", v);
    glBindBuffer(GL_ARRAY_BUFFER, 0);
    h_expect(glMapBuffer(GL_ARRAY_BUFFER, GL_READ_ONLY) == NULL, "map with no buffer bound");
    h_expect_error(GL_INVALID_OPERATION, "glMapBuffer with buffer 0 bound");
    glDisableClientState(GL_VERTEX_ARRAY);
    glDisableClientState(GL_COLOR_ARRAY);
    h_expect_no_error("sources");
}

static GLuint result(GLuint q)
{
    GLuint r = 12345, avail = 0;
    /* Asking for the result waits for it; then it is available (4.1.6). */
    glGetQueryObjectuiv(q, GL_QUERY_RESULT, &r);
    glGetQueryObjectuiv(q, GL_QUERY_RESULT_AVAILABLE, &avail);
    h_expect(avail == GL_TRUE, "query %u not available after its result was read", q);
    return r;
}

static void occlusion(void)
{
    GLuint q[2], r;
    GLint v;
    glGenQueries(2, q);
    glEnable(GL_DEPTH_TEST);
    glColor4ub(255, 0, 0, 255);
    clear();

    glBeginQuery(GL_SAMPLES_PASSED, q[0]);
    glGetQueryiv(GL_SAMPLES_PASSED, GL_CURRENT_QUERY, &v);
    h_expect(v == (GLint)q[0], "GL_CURRENT_QUERY %d", v);
    glRecti(2, 2, 12, 12);
    glEndQuery(GL_SAMPLES_PASSED);
    r = result(q[0]);
    h_expect(r == 100, "a 10x10 square: %u samples passed, want 100", r);
    h_expect(glIsQuery(q[0]) == GL_TRUE, "glIsQuery after use");

    /* A square farther away (eye z = -0.5), half behind the first. */
    glBeginQuery(GL_SAMPLES_PASSED, q[1]);
    glPushMatrix();
    glTranslatef(0, 0, -0.5f);
    glRecti(7, 2, 17, 12);
    glPopMatrix();
    glEndQuery(GL_SAMPLES_PASSED);
    r = result(q[1]);
    h_expect(r == 50, "half-hidden square: %u samples passed, want 50", r);

    /* In front: all 100 pass. */
    glBeginQuery(GL_SAMPLES_PASSED, q[1]);
    glPushMatrix();
    glTranslatef(0, 0, 0.5f);
    glRecti(7, 2, 17, 12);
    glPopMatrix();
    glEndQuery(GL_SAMPLES_PASSED);
    r = result(q[1]);
    h_expect(r == 100, "square in front: %u samples passed, want 100", r);

    glEnable(GL_STENCIL_TEST);
    glStencilFunc(GL_NEVER, 0, 0xFF);
    glBeginQuery(GL_SAMPLES_PASSED, q[0]);
    glRecti(20, 20, 30, 30);
    glEndQuery(GL_SAMPLES_PASSED);
    glDisable(GL_STENCIL_TEST);
    r = result(q[0]);
    h_expect(r == 0, "stencil GL_NEVER: %u samples passed, want 0", r);

    /* Drawn through vertex arrays. */
    glVertexPointer(2, GL_FLOAT, 0, SCENE);
    glEnableClientState(GL_VERTEX_ARRAY);
    clear();
    glBeginQuery(GL_SAMPLES_PASSED, q[0]);
    glDrawArrays(GL_QUADS, 0, 12);
    glEndQuery(GL_SAMPLES_PASSED);
    glDisableClientState(GL_VERTEX_ARRAY);
    r = result(q[0]);
    h_expect(r == 16 + 320 + 16, "three array quads: %u samples passed, want 352", r);
    glDisable(GL_DEPTH_TEST);
    h_expect_no_error("occlusion queries");

    /* Errors. */
    glEndQuery(GL_SAMPLES_PASSED);
    h_expect_error(GL_INVALID_OPERATION, "glEndQuery with no active query");
    glBeginQuery(GL_SAMPLES_PASSED, 0);
    h_expect_error(GL_INVALID_OPERATION, "glBeginQuery(0)");
    glBeginQuery(GL_SAMPLES_PASSED, q[0]);
    glBeginQuery(GL_SAMPLES_PASSED, q[1]);
    h_expect_error(GL_INVALID_OPERATION, "glBeginQuery while one is active");
    glGetQueryObjectuiv(q[0], GL_QUERY_RESULT, &r);
    h_expect_error(GL_INVALID_OPERATION, "result of the active query");
    glEndQuery(GL_SAMPLES_PASSED);
    glGetQueryiv(GL_SAMPLES_PASSED, GL_CURRENT_QUERY, &v);
    h_expect(v == 0, "GL_CURRENT_QUERY after glEndQuery: %d", v);
    glDeleteQueries(2, q);
    h_expect(glIsQuery(q[0]) == GL_FALSE, "glIsQuery after delete");
    h_expect_no_error("query errors");
}

int main(void)
{
    GLuint b[3];
    h_init(W, H);
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    glOrtho(0, W, 0, H, -1, 1);
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
    glClearColor(0, 0, 0, 0);

    glGenBuffers(3, b);
    h_expect(b[0] && b[1] && b[2] && b[0] != b[1] && b[1] != b[2] && b[0] != b[2], "glGenBuffers names");
    h_expect(glIsBuffer(b[0]) == GL_FALSE, "glIsBuffer before first bind");
    sources(b);
    h_expect(glIsBuffer(b[0]) == GL_TRUE, "glIsBuffer after bind");
    glDeleteBuffers(3, b);
    h_expect(glIsBuffer(b[0]) == GL_FALSE, "glIsBuffer after delete");
    occlusion();
    return h_finish();
}
