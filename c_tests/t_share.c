/* t_share: object sharing between contexts (GL 1.5 appendix D.1;
 * OSMesaCreateContextExt's sharelist argument).
 *
 * Part 1, one thread: context B is created sharing A's objects. A display
 * list, a texture object and a buffer object made in A are used by B (B
 * draws with them and its pixels are checked); a list made in B is called
 * by A; deleting a texture in B deletes it for A; a context C made without
 * a share list sees none of them. Bindings stay per context: B's current
 * texture binding is its own. Renderbuffers and sampler objects are
 * shared too (ARB_framebuffer_object, ARB_sampler_objects), framebuffer
 * objects are not: B attaches A's renderbuffer to a framebuffer object of
 * its own and reads what A drew into it. A renderbuffer deleted while
 * attached lives on where it is still attached: A deletes one that B's
 * framebuffer (and A's own unbound one) holds; its name is free (a new
 * renderbuffer may take it), but both framebuffers keep the old image,
 * complete, with A's pixels, until they detach it.
 *
 * Part 2, two threads: A and B current at the same time in two threads.
 * The main thread keeps redefining list L (each definition sets a colour
 * and draws a quad) while the second thread calls L and reads its pixel;
 * every pixel read must be one of the colours a complete definition draws
 * (never a torn or missing list), and nothing may crash. Thread B also
 * makes and deletes textures meanwhile.
 */
#include "harness.h"
#include <pthread.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define S 8

static unsigned char abuf[S * S * 4], bbuf[S * S * 4], cbuf[S * S * 4];
static OSMesaContext A, B, C;
static GLuint L;
static volatile int stop, defined;
static volatile int bad_pixels, calls, calls_defined;

static void quad(void)
{
    glBegin(GL_QUADS);
    glTexCoord2f(0, 0); glVertex2f(-1, -1);
    glTexCoord2f(1, 0); glVertex2f(1, -1);
    glTexCoord2f(1, 1); glVertex2f(1, 1);
    glTexCoord2f(0, 1); glVertex2f(-1, 1);
    glEnd();
}

static void pixel(unsigned char *p)
{
    glReadPixels(S / 2, S / 2, 1, 1, GL_RGBA, GL_UNSIGNED_BYTE, p);
}

static void *caller(void *arg)
{
    unsigned char p[4];
    (void)arg;
    if (!OSMesaMakeCurrent(B, bbuf, GL_UNSIGNED_BYTE, S, S)) {
        bad_pixels = -1000;
        return NULL;
    }
    while (!stop) {
        GLuint t;
        int was_defined = defined;
        glClearColor(0, 0, 0, 0);
        glClear(GL_COLOR_BUFFER_BIT);
        glCallList(L);
        pixel(p);
        /* A definition draws red or blue; calls before A's first
         * definition find the empty list glGenLists made (black). */
        if (!((p[0] == 255 && p[1] == 0 && p[2] == 0) || (p[0] == 0 && p[1] == 0 && p[2] == 255) ||
              (!was_defined && p[0] == 0 && p[1] == 0 && p[2] == 0))) {
            if (bad_pixels < 5)
                printf("  wrong pixel in thread B at call %d: %d,%d,%d\n", calls, p[0], p[1], p[2]);
            bad_pixels++;
        }
        if (was_defined)
            calls_defined++;
        glGenTextures(1, &t);
        glBindTexture(GL_TEXTURE_2D, t);
        glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 1, 1, 0, GL_RGBA, GL_UNSIGNED_BYTE, p);
        glDeleteTextures(1, &t);
        calls++;
    }
    OSMesaMakeCurrent(NULL, NULL, 0, 0, 0);
    return NULL;
}

/* In the current context: a new S x S RGBA8 renderbuffer attached to a new
 * framebuffer object (returned in *fbo) and cleared to (r, g, b); the
 * window's framebuffer is bound again after. */
static GLuint cleared_renderbuffer(GLuint *fbo, float r, float g, float b)
{
    GLuint rb;
    glGenRenderbuffers(1, &rb);
    glBindRenderbuffer(GL_RENDERBUFFER, rb);
    glRenderbufferStorage(GL_RENDERBUFFER, GL_RGBA8, S, S);
    glGenFramebuffers(1, fbo);
    glBindFramebuffer(GL_FRAMEBUFFER, *fbo);
    glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER, rb);
    glClearColor(r, g, b, 1);
    glClear(GL_COLOR_BUFFER_BIT);
    glClearColor(0, 0, 0, 0);
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    return rb;
}

/* A draws red into a renderbuffer through its framebuffer object and makes
 * a sampler; B sees both, but not A's framebuffer object. */
static void share_renderbuffers_and_samplers(void)
{
    GLuint rb, fbo, bfbo, smp;
    GLint v = 0;
    unsigned char p[4] = {0, 0, 0, 0};
    OSMesaMakeCurrent(A, abuf, GL_UNSIGNED_BYTE, S, S);
    rb = cleared_renderbuffer(&fbo, 1, 0, 0);
    glGenSamplers(1, &smp);
    glSamplerParameteri(smp, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    glFinish();
    h_expect_no_error("A makes a renderbuffer and a sampler");

    OSMesaMakeCurrent(B, bbuf, GL_UNSIGNED_BYTE, S, S);
    h_expect(glIsRenderbuffer(rb), "B sees A's renderbuffer");
    h_expect(!glIsFramebuffer(fbo), "B does not see A's framebuffer object");
    h_expect(glIsSampler(smp), "B sees A's sampler");
    glGetSamplerParameteriv(smp, GL_TEXTURE_MAG_FILTER, &v);
    h_expect(v == GL_NEAREST, "B reads the sampler's MAG_FILTER A set: 0x%x", v);
    glGenFramebuffers(1, &bfbo);
    glBindFramebuffer(GL_FRAMEBUFFER, bfbo);
    glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER, rb);
    h_expect(glCheckFramebufferStatus(GL_FRAMEBUFFER) == GL_FRAMEBUFFER_COMPLETE, "B's framebuffer with A's renderbuffer is complete");
    glReadPixels(S / 2, S / 2, 1, 1, GL_RGBA, GL_UNSIGNED_BYTE, p);
    h_expect(p[0] == 255 && p[1] == 0 && p[2] == 0, "B reads what A drew into the renderbuffer: %d,%d,%d", p[0], p[1], p[2]);
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    glDeleteFramebuffers(1, &bfbo);
    h_expect_no_error("B uses A's renderbuffer and sampler");

    OSMesaMakeCurrent(C, cbuf, GL_UNSIGNED_BYTE, S, S);
    h_expect(!glIsRenderbuffer(rb) && !glIsSampler(smp), "C sees neither");
}

/* Reads the bound framebuffer's centre pixel and its status. */
static GLenum read_fbo(unsigned char p[4])
{
    memset(p, 0, 4);
    glReadPixels(S / 2, S / 2, 1, 1, GL_RGBA, GL_UNSIGNED_BYTE, p);
    return glCheckFramebufferStatus(GL_FRAMEBUFFER);
}

/* ARB_framebuffer_object 4.4.2.2: deleting a renderbuffer detaches it from
 * the current context's bound framebuffers only; elsewhere the image stays
 * attached (and alive) though its name is gone. */
static void deleted_renderbuffer_stays_attached(void)
{
    GLuint rb, again, afbo, bfbo, name = 0;
    GLint type = 0;
    unsigned char p[4];
    OSMesaMakeCurrent(A, abuf, GL_UNSIGNED_BYTE, S, S);
    rb = cleared_renderbuffer(&afbo, 0, 0, 1);
    glFinish();

    OSMesaMakeCurrent(B, bbuf, GL_UNSIGNED_BYTE, S, S);
    glGenFramebuffers(1, &bfbo);
    glBindFramebuffer(GL_FRAMEBUFFER, bfbo);
    glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER, rb);
    h_expect(read_fbo(p) == GL_FRAMEBUFFER_COMPLETE && p[2] == 255, "B's framebuffer reads A's blue: %d,%d,%d", p[0], p[1], p[2]);

    /* A deletes it (neither of A's bindings holds it) and reuses the name. */
    OSMesaMakeCurrent(A, abuf, GL_UNSIGNED_BYTE, S, S);
    glDeleteRenderbuffers(1, &rb);
    h_expect(!glIsRenderbuffer(rb), "the deleted renderbuffer's name is free");
    glGenRenderbuffers(1, &again);
    glBindRenderbuffer(GL_RENDERBUFFER, again);
    glRenderbufferStorage(GL_RENDERBUFFER, GL_RGBA8, 2, 2);
    glBindFramebuffer(GL_FRAMEBUFFER, afbo);
    h_expect(read_fbo(p) == GL_FRAMEBUFFER_COMPLETE && p[2] == 255 && p[0] == 0,
             "A's unbound framebuffer kept the deleted image: %d,%d,%d", p[0], p[1], p[2]);
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    h_expect_no_error("A deletes an attached renderbuffer");

    /* B still has the old image, not the new object of the same name... */
    OSMesaMakeCurrent(B, bbuf, GL_UNSIGNED_BYTE, S, S);
    h_expect(read_fbo(p) == GL_FRAMEBUFFER_COMPLETE && p[2] == 255 && p[0] == 0,
             "B's framebuffer kept the deleted image: %d,%d,%d", p[0], p[1], p[2]);
    glGetFramebufferAttachmentParameteriv(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_FRAMEBUFFER_ATTACHMENT_OBJECT_TYPE, &type);
    h_expect(type == GL_RENDERBUFFER, "still a renderbuffer attachment: 0x%x", type);
    /* ... and can draw into it. */
    glClearColor(0, 1, 0, 1);
    glClear(GL_COLOR_BUFFER_BIT);
    glClearColor(0, 0, 0, 0);
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    glBindFramebuffer(GL_FRAMEBUFFER, bfbo);
    h_expect(read_fbo(p) == GL_FRAMEBUFFER_COMPLETE && p[1] == 255 && p[2] == 0, "B draws into the deleted image: %d,%d,%d", p[0], p[1], p[2]);
    /* Detaching lets it go: the framebuffer is then incomplete. */
    glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER, 0);
    glGetFramebufferAttachmentParameteriv(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_FRAMEBUFFER_ATTACHMENT_OBJECT_NAME, (GLint *)&name);
    h_expect(name == 0 && glCheckFramebufferStatus(GL_FRAMEBUFFER) != GL_FRAMEBUFFER_COMPLETE, "detached: name %u", name);
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    glDeleteFramebuffers(1, &bfbo);

    /* Deleted while attached to the current context's bound framebuffer:
     * detached there at once (4.4.2.2). */
    OSMesaMakeCurrent(A, abuf, GL_UNSIGNED_BYTE, S, S);
    glBindFramebuffer(GL_FRAMEBUFFER, afbo);
    glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER, again);
    glDeleteRenderbuffers(1, &again);
    type = -1;
    glGetFramebufferAttachmentParameteriv(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_FRAMEBUFFER_ATTACHMENT_OBJECT_TYPE, &type);
    h_expect(type == GL_NONE, "the bound framebuffer lets the deleted renderbuffer go: 0x%x", type);
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    glDeleteFramebuffers(1, &afbo);
    h_expect_no_error("deleted renderbuffers");
}

int main(void)
{
    static const unsigned char green[4] = {0, 255, 0, 255};
    static const float vbo_data[8] = {-1, -1, 1, -1, 1, 1, -1, 1};
    unsigned char p[4];
    GLuint list, tex, buf, blist;
    GLint bound = -1;
    pthread_t th;
    int i;

    A = OSMesaCreateContextExt(OSMESA_RGBA, 0, 0, 0, NULL);
    B = OSMesaCreateContextExt(OSMESA_RGBA, 0, 0, 0, A);
    C = OSMesaCreateContextExt(OSMESA_RGBA, 0, 0, 0, NULL);
    h_expect(A && B && C, "contexts");

    /* A makes a list, a texture and a buffer object. */
    OSMesaMakeCurrent(A, abuf, GL_UNSIGNED_BYTE, S, S);
    list = glGenLists(1);
    glNewList(list, GL_COMPILE);
    glColor3ub(255, 255, 0);
    quad();
    glEndList();
    glGenTextures(1, &tex);
    glBindTexture(GL_TEXTURE_2D, tex);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 1, 1, 0, GL_RGBA, GL_UNSIGNED_BYTE, green);
    glGenBuffers(1, &buf);
    glBindBuffer(GL_ARRAY_BUFFER, buf);
    glBufferData(GL_ARRAY_BUFFER, sizeof vbo_data, vbo_data, GL_STATIC_DRAW);
    glBindBuffer(GL_ARRAY_BUFFER, 0);
    h_expect_no_error("A makes objects");

    /* B uses them. */
    OSMesaMakeCurrent(B, bbuf, GL_UNSIGNED_BYTE, S, S);
    h_expect(glIsList(list) && glIsTexture(tex) && glIsBuffer(buf), "B sees A's list, texture and buffer");
    glGetIntegerv(GL_TEXTURE_BINDING_2D, &bound);
    h_expect(bound == 0, "B's texture binding is its own: %d", bound);
    glClear(GL_COLOR_BUFFER_BIT);
    glCallList(list);
    pixel(p);
    h_expect(p[0] == 255 && p[1] == 255 && p[2] == 0, "B calls A's list: %d,%d,%d", p[0], p[1], p[2]);
    glBindTexture(GL_TEXTURE_2D, tex);
    glEnable(GL_TEXTURE_2D);
    glColor3ub(255, 255, 255);
    glClear(GL_COLOR_BUFFER_BIT);
    quad();
    pixel(p);
    h_expect(p[0] == 0 && p[1] == 255 && p[2] == 0, "B draws with A's texture: %d,%d,%d", p[0], p[1], p[2]);
    glDisable(GL_TEXTURE_2D);
    glBindBuffer(GL_ARRAY_BUFFER, buf);
    glVertexPointer(2, GL_FLOAT, 0, (void *)0);
    glEnableClientState(GL_VERTEX_ARRAY);
    glColor3ub(0, 255, 255);
    glClear(GL_COLOR_BUFFER_BIT);
    glDrawArrays(GL_QUADS, 0, 4);
    glDisableClientState(GL_VERTEX_ARRAY);
    glBindBuffer(GL_ARRAY_BUFFER, 0);
    pixel(p);
    h_expect(p[0] == 0 && p[1] == 255 && p[2] == 255, "B draws from A's buffer object: %d,%d,%d", p[0], p[1], p[2]);
    blist = glGenLists(1);
    h_expect(blist != list, "B's new list name %u differs from A's %u", blist, list);
    glNewList(blist, GL_COMPILE);
    glColor3ub(255, 0, 255);
    quad();
    glEndList();
    h_expect_no_error("B uses A's objects");

    /* A calls B's list; B's texture re-specification shows in A. */
    OSMesaMakeCurrent(A, abuf, GL_UNSIGNED_BYTE, S, S);
    glClear(GL_COLOR_BUFFER_BIT);
    glCallList(blist);
    pixel(p);
    h_expect(p[0] == 255 && p[1] == 0 && p[2] == 255, "A calls B's list: %d,%d,%d", p[0], p[1], p[2]);

    share_renderbuffers_and_samplers();
    deleted_renderbuffer_stays_attached();

    /* C shares nothing. */
    OSMesaMakeCurrent(C, cbuf, GL_UNSIGNED_BYTE, S, S);
    h_expect(!glIsList(list) && !glIsTexture(tex) && !glIsBuffer(buf), "C sees none of A's objects");

    /* B deletes the texture: gone for A too. */
    OSMesaMakeCurrent(B, bbuf, GL_UNSIGNED_BYTE, S, S);
    glDeleteTextures(1, &tex);
    OSMesaMakeCurrent(A, abuf, GL_UNSIGNED_BYTE, S, S);
    h_expect(!glIsTexture(tex), "a texture B deleted is gone for A");
    h_expect_no_error("A after B's deletion");

    /* Part 2: two threads. A keeps redefining L while B calls it. */
    L = glGenLists(1);
    OSMesaMakeCurrent(NULL, NULL, 0, 0, 0);
    OSMesaMakeCurrent(A, abuf, GL_UNSIGNED_BYTE, S, S);
    if (pthread_create(&th, NULL, caller, NULL) != 0) {
        h_expect(0, "pthread_create");
        return h_finish();
    }
    for (i = 0; i < 3000 || calls_defined < 100; i++) {
        glNewList(L, GL_COMPILE);
        if (i & 1)
            glColor3ub(255, 0, 0);
        else
            glColor3ub(0, 0, 255);
        quad();
        glEndList();
        defined = 1;
        if (i > 200000)
            break;
    }
    stop = 1;
    pthread_join(th, NULL);
    h_expect(bad_pixels == 0, "thread B saw %d wrong pixels in %d calls", bad_pixels, calls);
    h_expect(calls_defined >= 100, "thread B made %d calls after the first definition", calls_defined);
    printf("  %d redefinitions in thread A, %d calls in thread B (%d after the first definition)\n", i, calls, calls_defined);
    h_expect_no_error("A after the threads");

    OSMesaMakeCurrent(NULL, NULL, 0, 0, 0);
    OSMesaDestroyContext(B);
    OSMesaDestroyContext(C);
    /* A outlives B and still has the objects. */
    OSMesaMakeCurrent(A, abuf, GL_UNSIGNED_BYTE, S, S);
    h_expect(glIsList(list) && glIsList(blist), "A keeps the shared lists after B is destroyed");
    OSMesaMakeCurrent(NULL, NULL, 0, 0, 0);
    OSMesaDestroyContext(A);
    return h_finish();
}
