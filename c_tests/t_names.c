/* t_names: object names from every glGen* call (GL 1.5 sections 2.9,
 * 3.8.12, 4.1.6, 5.4; ARB_framebuffer_object, ARB_sampler_objects).
 *
 * - A generated name is nonzero, unused and not handed out twice while it is
 *   reserved or in use: names bound or defined without glGen (texture 3,
 *   list 7, buffer 2, ...) are skipped, and so are names generated earlier
 *   and not bound yet.
 * - 20,000 textures generated one at a time, each bound before the next call
 *   (as a program loading many images does), get 20,000 distinct names; a
 *   deleted name may come back, but never while its texture lives.
 * - glGenLists(n) returns the first of n consecutive names that were not
 *   lists, each now an (empty) list; 0 for n = 0; INVALID_VALUE for n < 0.
 */
#define GL_GLEXT_PROTOTYPES
#include "harness.h"
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define MANY 20000

/* True when v[0..n) holds distinct nonzero names, none in taken[0..t). */
static int fresh(const GLuint *v, int n, const GLuint *taken, int t)
{
    int i, j;
    for (i = 0; i < n; i++) {
        if (v[i] == 0)
            return 0;
        for (j = 0; j < i; j++)
            if (v[j] == v[i])
                return 0;
        for (j = 0; j < t; j++)
            if (taken[j] == v[i])
                return 0;
    }
    return 1;
}

/* glGen* twice, 8 names each, after `preset` was bound without glGen (0:
 * none): 16 distinct fresh names, none of them `preset` (reserved names
 * are not handed out again). */
static void sixteen(const char *what, void (APIENTRY *gen)(GLsizei, GLuint *), GLuint preset)
{
    GLuint v[8], w[8];
    gen(8, v);
    gen(8, w);
    h_expect(fresh(v, 8, &preset, preset != 0) && fresh(w, 8, v, 8) && fresh(w, 8, &preset, preset != 0),
             "%s: 16 distinct fresh names besides %u", what, preset);
}

int main(void)
{
    GLuint v[1];
    GLuint *many;
    unsigned char *seen;
    int i, ok;
    h_init(16, 16);

    /* Textures: 3 bound without glGen. */
    glBindTexture(GL_TEXTURE_2D, 3);
    sixteen("glGenTextures", glGenTextures, 3);
    glBindTexture(GL_TEXTURE_2D, 0);
    h_expect_no_error("textures");

    /* Many textures, one name a call, each bound before the next call. */
    many = malloc(MANY * sizeof *many);
    seen = calloc(4 * MANY + 64, 1);
    ok = many && seen;
    for (i = 0; ok && i < MANY; i++) {
        glGenTextures(1, &many[i]);
        glBindTexture(GL_TEXTURE_2D, many[i]);
        /* The 17 names above are below 64; more than 4 MANY names would
         * mean names were skipped for no reason. */
        if (many[i] == 0 || many[i] >= 4 * MANY + 64 || seen[many[i]] || many[i] == 3)
            ok = 0;
        else
            seen[many[i]] = 1;
    }
    h_expect(ok, "20000 textures one at a time: distinct fresh names (failed at %d)", i);
    /* Deleting one and generating again: never a living texture's name. */
    glDeleteTextures(1, &many[100]);
    seen[many[100]] = 0;
    glGenTextures(1, v);
    h_expect(v[0] != 0 && v[0] != 3 && (v[0] >= 4 * MANY + 64 || !seen[v[0]]), "name after a deletion: %u", v[0]);
    glDeleteTextures(MANY, many);
    free(many);
    free(seen);
    glBindTexture(GL_TEXTURE_2D, 0);
    h_expect_no_error("many textures");

    /* Display lists: 7 defined directly; runs of consecutive free names. */
    glNewList(7, GL_COMPILE);
    glEndList();
    {
        GLuint a = glGenLists(5), b = glGenLists(3), c;
        h_expect(a != 0 && b != 0, "glGenLists gave %u and %u", a, b);
        for (i = 0; i < 5; i++)
            h_expect(glIsList(a + i) && a + i != 7, "list %u of the first run", a + i);
        for (i = 0; i < 3; i++)
            h_expect(glIsList(b + i) && b + i != 7 && (b + i < a || b + i >= a + 5), "list %u of the second run", b + i);
        h_expect(glGenLists(0) == 0, "glGenLists(0) is 0");
        h_expect_no_error("glGenLists");
        c = glGenLists(-1);
        h_expect(c == 0, "glGenLists(-1) is 0");
        h_expect_error(GL_INVALID_VALUE, "glGenLists(-1)");
    }

    /* Buffers, queries, framebuffers, renderbuffers: names bound without
     * glGen are skipped. */
    glBindBuffer(GL_ARRAY_BUFFER, 2);
    sixteen("glGenBuffers", glGenBuffers, 2);
    glBindBuffer(GL_ARRAY_BUFFER, 0);
    sixteen("glGenQueries", glGenQueries, 0);
    glBindFramebuffer(GL_FRAMEBUFFER, 4);
    sixteen("glGenFramebuffers", glGenFramebuffers, 4);
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    glBindRenderbuffer(GL_RENDERBUFFER, 5);
    sixteen("glGenRenderbuffers", glGenRenderbuffers, 5);
    glBindRenderbuffer(GL_RENDERBUFFER, 0);
    h_expect_no_error("buffers, queries and framebuffer objects");

    /* Samplers exist from glGenSamplers on. */
    sixteen("glGenSamplers", glGenSamplers, 0);
    glGenSamplers(1, v);
    h_expect(glIsSampler(v[0]), "a generated sampler exists");
    h_expect_no_error("samplers");

    return h_finish();
}
