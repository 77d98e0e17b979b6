/* t_book_s3_buffers: the Russian textbook's chapters 14.2-16: colour
 * buffers, the depth buffer, the image buffer (read, draw, copy pixels),
 * attribute groups and hints (seeds-inventory §2, §3.5, §6 #28-#32).
 *
 * BOOK: S3, Russian OpenGL textbook, ch. 14.2 (colour buffers, glDrawBuffer/glReadBuffer), 14.4 "The depth buffer" (glDepthFunc), 14.5 "The image buffer" (glReadPixels, glDrawPixels, glCopyPixels), 15 "Attribute groups" (glPushAttrib/glPopAttrib), 16 "Controlling rasterization efficiency" (glHint)
 * SHOWS: two overlapping squares with GL_LESS (the near red one in front) and GL_GREATER (the far blue one in front); a smooth-shaded triangle, its copy through glReadPixels + glDrawPixels and its copy through glCopyPixels(GL_COLOR); a square drawn before glPushAttrib and again after glPopAttrib, identical
 * FEATURES: glDepthFunc(GL_LESS/GL_GREATER), glClearDepth, glDrawBuffer, glReadBuffer, glReadPixels(GL_RGBA), glDrawPixels, glCopyPixels(GL_COLOR), glRasterPos2i, glPushAttrib with ORed bits, glPopAttrib, glHint/glGetIntegerv, invalid hint targets
 *
 * Book slips followed by the spec (§6): the section headed "accumulation
 * buffers" is about colour buffers (#28); glReadBuffer/glDrawBuffer, not
 * glReadBuffers/glDrawBuffers (#29); glCopyPixels' last parameter is a
 * type, GL_COLOR/GL_DEPTH/GL_STENCIL (#30); attribute bits may be ORed
 * into one push (#31); GL_NICEST (#32).
 */
#include "book.h"

#define W 320
#define H 160

static void sq(GLfloat x, GLfloat y, GLfloat z, GLfloat h)
{
    glBegin(GL_QUADS);
    glVertex3f(x - h, y - h, z); glVertex3f(x + h, y - h, z); glVertex3f(x + h, y + h, z); glVertex3f(x - h, y + h, z);
    glEnd();
}

int main(void)
{
    static unsigned char region[60 * 60 * 4];
    GLint v, db = 0;
    GLfloat c[4];
    int i, bad = 0, x, y;

    book_open(W, H);
    glGetIntegerv(GL_DRAW_BUFFER, &db);
    glDrawBuffer((GLenum)db);
    glReadBuffer((GLenum)db);
    h_expect_no_error("glDrawBuffer/glReadBuffer of the current buffer");
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    glOrtho(0, W, 0, H, -10, 10); /* z = -depth */
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
    glClearDepth(1.0);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    glEnable(GL_DEPTH_TEST);
    glGetIntegerv(GL_DEPTH_FUNC, &v);
    h_expect(v == GL_LESS, "default depth func 0x%x", v);
    /* 14.4: GL_LESS, near (z=5) red drawn first, far blue second */
    glColor3f(1, 0, 0); sq(30, 110, 5, 25);
    glColor3f(0, 0, 1); sq(50, 90, -5, 25);
    /* GL_GREATER with depth cleared to 0 in that area */
    glEnable(GL_SCISSOR_TEST);
    glScissor(80, 40, 80, 120);
    glClearDepth(0.0);
    glClear(GL_DEPTH_BUFFER_BIT);
    glDisable(GL_SCISSOR_TEST);
    glDepthFunc(GL_GREATER);
    glColor3f(1, 0, 0); sq(110, 110, 5, 25);
    glColor3f(0, 0, 1); sq(130, 90, -5, 25);
    glDepthFunc(GL_LESS);
    glDisable(GL_DEPTH_TEST);

    /* 14.5: a smooth triangle at (170..230, 90..150) */
    glBegin(GL_TRIANGLES);
    glColor3f(1, 0, 0); glVertex2i(172, 92);
    glColor3f(0, 1, 0); glVertex2i(228, 100);
    glColor3f(0, 0, 1); glVertex2i(190, 148);
    glEnd();
    glPixelStorei(GL_PACK_ALIGNMENT, 1);
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
    glReadPixels(170, 90, 60, 60, GL_RGBA, GL_UNSIGNED_BYTE, region);
    glRasterPos2i(250, 90);
    glDrawPixels(60, 60, GL_RGBA, GL_UNSIGNED_BYTE, region);
    glRasterPos2i(170, 20);
    glCopyPixels(170, 90, 60, 60, GL_COLOR);
    h_expect_no_error("pixels");

    /* 15: push several groups at once, change, pop. */
    glColor3f(0.2f, 0.8f, 0.4f);
    sq(30, 30, 0, 15);
    glPushAttrib(GL_CURRENT_BIT | GL_ENABLE_BIT | GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT | GL_HINT_BIT);
    glColor3f(1, 1, 1);
    glEnable(GL_BLEND);
    glEnable(GL_DEPTH_TEST);
    glClearColor(1, 0, 0, 1);
    glDepthFunc(GL_ALWAYS);
    glHint(GL_FOG_HINT, GL_NICEST);
    glGetIntegerv(GL_FOG_HINT, &v);
    h_expect(v == GL_NICEST, "glHint(GL_FOG_HINT, GL_NICEST) reads back 0x%x", v);
    glPopAttrib();
    glGetFloatv(GL_CURRENT_COLOR, c);
    h_expect(fabs(c[0] - 0.2f) < 1e-6 && fabs(c[1] - 0.8f) < 1e-6, "glPopAttrib: current colour %g %g", c[0], c[1]);
    h_expect(!glIsEnabled(GL_BLEND) && !glIsEnabled(GL_DEPTH_TEST), "glPopAttrib: enables not restored");
    glGetIntegerv(GL_DEPTH_FUNC, &v);
    h_expect(v == GL_LESS, "glPopAttrib: depth func 0x%x", v);
    glGetIntegerv(GL_FOG_HINT, &v);
    h_expect(v == GL_DONT_CARE, "glPopAttrib: fog hint 0x%x", v);
    glGetFloatv(GL_COLOR_CLEAR_VALUE, c);
    h_expect(c[0] == 0 && c[3] == 0, "glPopAttrib: clear colour %g %g %g %g", c[0], c[1], c[2], c[3]);
    sq(70, 30, 0, 15); /* the same colour as before the push */
    /* 16: hints */
    glHint(GL_PERSPECTIVE_CORRECTION_HINT, GL_FASTEST);
    glGetIntegerv(GL_PERSPECTIVE_CORRECTION_HINT, &v);
    h_expect(v == GL_FASTEST, "perspective hint 0x%x", v);
    glHint(GL_FOG, GL_NICEST);
    h_expect_error(GL_INVALID_ENUM, "glHint(GL_FOG, ...)");
    glHint(GL_FOG_HINT, GL_FOG);
    h_expect_error(GL_INVALID_ENUM, "glHint(GL_FOG_HINT, GL_FOG)");

    /* Smooth shading under the default GL_PERSPECTIVE_CORRECTION_HINT may
     * be stepped approximately, within 1/255 (README, SOFTGL_REFERENCE). */
    book_shot("s3_buffers-depth_pixels_attrib", 1, 0);
    book_expect_rgb(40, 100, 255, 0, 0, 0, "GL_LESS: the near red square in front");
    book_expect_rgb(120, 100, 0, 0, 255, 0, "GL_GREATER: the far blue square in front");
    for (y = 0; y < 60; y++)
        for (x = 0; x < 60; x++) {
            const unsigned char *s = book_at(170 + x, 90 + y), *d = book_at(250 + x, 90 + y),
                                *cp = book_at(170 + x, 20 + y);
            if (memcmp(s, d, 3) != 0 || memcmp(s, cp, 3) != 0)
                bad++;
        }
    h_expect(bad == 0, "glDrawPixels / glCopyPixels copies differ from the source in %d pixels", bad);
    book_expect_rgb(70, 30, 51, 204, 102, 0, "square after glPopAttrib has the pushed colour");
    for (i = 0; i < 4; i++)
        h_expect(book_at(30, 30)[i % 3] == book_at(70, 30)[i % 3], "squares before/after differ");
    h_expect_no_error("end");
    book_close();
    return h_finish();
}
