/* t_errors: GL error semantics (GL 1.5 section 2.5) and glGetString (6.1.11).
 *
 * - glGetError returns the recorded error and resets it; until read, an
 *   error flag stays set (later valid commands do not clear it, and while
 *   it is set further errors of the same kind are not queued).
 * - A command that generates an error is ignored (state unchanged).
 * - Bad enums to glBegin, glDepthFunc, glShadeModel, glMatrixMode, glGetString
 *   give GL_INVALID_ENUM; glViewport with a negative width/height gives
 *   GL_INVALID_VALUE.
 * - glEnd without glBegin, glBegin inside glBegin/glEnd, and commands not
 *   allowed between glBegin/glEnd (glClear, glViewport, glMatrixMode,
 *   glGetError itself, which then returns 0) give GL_INVALID_OPERATION; the
 *   primitive still ends normally at glEnd.
 * - glGetString(GL_VENDOR/RENDERER/VERSION/EXTENSIONS) are non-NULL; on
 *   softgl GL_VERSION starts with "1." (not checked on other renderers:
 *   Mesa reports 4.x).
 */
#include "harness.h"
#include <stdio.h>
#include <string.h>

#define W 8
#define H 8

/* Read every pending error (an implementation may keep several flags). */
static int drain_has(GLenum want)
{
    int i, seen = 0;
    for (i = 0; i < 16; i++) {
        GLenum e = glGetError();
        if (e == GL_NO_ERROR)
            return seen;
        if (e == want)
            seen = 1;
    }
    h_expect(0, "glGetError never returned GL_NO_ERROR in 16 calls");
    return seen;
}

int main(void)
{
    GLint v, vp[4];
    const char *s;
    unsigned char px[4];

    h_init(W, H);
    h_expect_no_error("initial state");

    /* Sticky until read, then reset. */
    glDepthFunc(0x9999);
    glClearColor(0, 0, 0, 1); /* valid commands do not clear the flag */
    glClear(GL_COLOR_BUFFER_BIT);
    glDepthFunc(0x9998);      /* same kind again */
    h_expect_error(GL_INVALID_ENUM, "glDepthFunc(0x9999) read after valid commands");
    h_expect_no_error("second glGetError after reading the error");
    h_expect_no_error("third glGetError");

    /* Two different errors: the first one is kept (and GetError must
     * eventually return GL_NO_ERROR). */
    glShadeModel(0x1234);
    glViewport(0, 0, -1, 4);
    h_expect(drain_has(GL_INVALID_ENUM), "GL_INVALID_ENUM from glShadeModel lost after a later GL_INVALID_VALUE");

    /* GL_INVALID_ENUM, and the command is ignored. */
    glDepthFunc(GL_GEQUAL);
    glDepthFunc(GL_LINE_LOOP);
    h_expect_error(GL_INVALID_ENUM, "glDepthFunc(GL_LINE_LOOP)");
    glGetIntegerv(GL_DEPTH_FUNC, &v);
    h_expect(v == GL_GEQUAL, "GL_DEPTH_FUNC after a bad glDepthFunc = 0x%x, expected GL_GEQUAL", v);

    glShadeModel(GL_FLAT);
    glShadeModel(GL_LESS);
    h_expect_error(GL_INVALID_ENUM, "glShadeModel(GL_LESS)");
    glGetIntegerv(GL_SHADE_MODEL, &v);
    h_expect(v == GL_FLAT, "GL_SHADE_MODEL after a bad glShadeModel = 0x%x, expected GL_FLAT", v);
    glShadeModel(GL_SMOOTH);

    glMatrixMode(GL_PROJECTION);
    glMatrixMode(GL_SMOOTH);
    h_expect_error(GL_INVALID_ENUM, "glMatrixMode(GL_SMOOTH)");
    glGetIntegerv(GL_MATRIX_MODE, &v);
    h_expect(v == GL_PROJECTION, "GL_MATRIX_MODE after a bad glMatrixMode = 0x%x", v);
    glMatrixMode(GL_MODELVIEW);

    /* glBegin(bad): GL_INVALID_ENUM and we are NOT inside glBegin/glEnd. */
    glBegin(0x0dad);
    h_expect_error(GL_INVALID_ENUM, "glBegin(0x0dad)");
    glClear(GL_COLOR_BUFFER_BIT);
    h_expect_no_error("glClear after a rejected glBegin (not inside begin/end)");
    glEnd();
    h_expect_error(GL_INVALID_OPERATION, "glEnd after a rejected glBegin");

    /* glEnd without glBegin. */
    glEnd();
    h_expect_error(GL_INVALID_OPERATION, "glEnd without glBegin");

    /* glBegin twice: the second is ignored, glEnd ends the first. */
    glBegin(GL_TRIANGLES);
    glBegin(GL_QUADS);
    glEnd();
    h_expect_error(GL_INVALID_OPERATION, "glBegin inside glBegin/glEnd");
    glEnd();
    h_expect_error(GL_INVALID_OPERATION, "second glEnd (the first one ended the primitive)");

    /* Commands not allowed between glBegin/glEnd. */
    glBegin(GL_TRIANGLES);
    glClear(GL_COLOR_BUFFER_BIT);
    glEnd();
    h_expect_error(GL_INVALID_OPERATION, "glClear inside glBegin/glEnd");

    glViewport(1, 2, 3, 4);
    glGetIntegerv(GL_VIEWPORT, vp);
    glBegin(GL_TRIANGLES);
    glViewport(0, 0, 5, 5);
    glEnd();
    h_expect_error(GL_INVALID_OPERATION, "glViewport inside glBegin/glEnd");
    glGetIntegerv(GL_VIEWPORT, vp);
    h_expect(vp[0] == 1 && vp[1] == 2 && vp[2] == 3 && vp[3] == 4,
             "viewport changed by glViewport inside glBegin/glEnd: %d,%d,%d,%d", vp[0], vp[1], vp[2], vp[3]);
    glViewport(0, 0, W, H);

    glBegin(GL_TRIANGLES);
    glMatrixMode(GL_PROJECTION);
    glEnd();
    h_expect_error(GL_INVALID_OPERATION, "glMatrixMode inside glBegin/glEnd");
    glGetIntegerv(GL_MATRIX_MODE, &v);
    h_expect(v == GL_MODELVIEW, "glMatrixMode inside glBegin/glEnd changed the mode to 0x%x", v);

    glBegin(GL_TRIANGLES);
    {
        GLenum inside = glGetError();
        glEnd();
        h_expect(inside == GL_NO_ERROR, "glGetError inside glBegin/glEnd returned 0x%x, expected 0", inside);
    }
    h_expect_error(GL_INVALID_OPERATION, "glGetError inside glBegin/glEnd");

    /* A primitive with an error inside still draws (only the bad command is
     * ignored). */
    glClearColor(0, 0, 0, 1);
    glClear(GL_COLOR_BUFFER_BIT);
    glColor3ub(255, 255, 255);
    glBegin(GL_QUADS);
    glVertex2f(-1, -1);
    glVertex2f(1, -1);
    glClear(GL_COLOR_BUFFER_BIT);
    glVertex2f(1, 1);
    glVertex2f(-1, 1);
    glEnd();
    h_expect_error(GL_INVALID_OPERATION, "glClear inside a quad");
    glReadPixels(4, 4, 1, 1, GL_RGBA, GL_UNSIGNED_BYTE, px);
    h_expect(px[0] == 255 && px[1] == 255 && px[2] == 255,
             "quad with an ignored glClear inside was not drawn: (4,4) = %d,%d,%d", px[0], px[1], px[2]);

    /* glViewport with negative sizes. */
    glViewport(0, 0, -1, 5);
    h_expect_error(GL_INVALID_VALUE, "glViewport(0,0,-1,5)");
    glViewport(0, 0, 5, -1);
    h_expect_error(GL_INVALID_VALUE, "glViewport(0,0,5,-1)");
    glGetIntegerv(GL_VIEWPORT, vp);
    h_expect(vp[2] == W && vp[3] == H, "viewport after rejected glViewport: %dx%d", vp[2], vp[3]);

    /* glGetString. */
    {
        const char *vendor = (const char *)glGetString(GL_VENDOR);
        const char *renderer = (const char *)glGetString(GL_RENDERER);
        const char *version = (const char *)glGetString(GL_VERSION);
        const char *ext = (const char *)glGetString(GL_EXTENSIONS);
        h_expect(vendor != NULL, "glGetString(GL_VENDOR) is NULL");
        h_expect(renderer != NULL, "glGetString(GL_RENDERER) is NULL");
        h_expect(version != NULL, "glGetString(GL_VERSION) is NULL");
        h_expect(ext != NULL, "glGetString(GL_EXTENSIONS) is NULL");
        h_expect_no_error("glGetString");
        printf("  GL_VENDOR %s\n  GL_RENDERER %s\n  GL_VERSION %s\n", vendor ? vendor : "(null)",
               renderer ? renderer : "(null)", version ? version : "(null)");
        if (renderer && version && strstr(renderer, "softgl"))
            h_expect(strncmp(version, "1.", 2) == 0, "softgl GL_VERSION \"%s\" does not start with \"1.\"", version);
        else
            printf("  (GL_VERSION \"1.x\" check skipped: renderer is not softgl)\n");
    }
    s = (const char *)glGetString(0x4321);
    h_expect(s == NULL, "glGetString(0x4321) is not NULL");
    h_expect_error(GL_INVALID_ENUM, "glGetString(0x4321)");
    h_expect_no_error("end");
    return h_finish();
}
