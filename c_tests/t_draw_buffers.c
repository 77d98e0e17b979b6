/* t_draw_buffers: front and back colour buffers of a double-buffered
 * surface (GL 1.5 sections 4.2.1, 4.3.2, 4.2.3, 4.2.4; wglSwapBuffers),
 * on a wgl offscreen DC (double-buffered pixel format).
 *
 * Checked, by reading pixels back from the buffer glReadBuffer names and
 * from the DC's shown image (softglGetDCImage, the front buffer):
 * - the initial draw and read buffers are BACK; drawing and clearing the
 *   back buffer leave the front one alone, and glFlush shows nothing new;
 * - glDrawBuffer(GL_FRONT) writes the front buffer only, and glFlush shows
 *   it;
 * - GL_FRONT_AND_BACK (and GL_LEFT, table 4.4) write both, blending against
 *   each buffer's own contents, with the depth test done once per fragment
 *   (a second pass at the same depth with GL_LESS draws nowhere);
 * - glClear clears every draw buffer; GL_NONE draws nothing;
 * - SwapBuffers copies back to front, shows it, and keeps the back buffer;
 * - glReadPixels, glCopyPixels, glCopyTexImage2D and glAccum read the read
 *   buffer; glAccum(GL_RETURN) writes the draw buffers;
 * - errors: READ of FRONT_AND_BACK or NONE is INVALID_ENUM, RIGHT and AUX0
 *   INVALID_OPERATION; on a single-buffered OSMesa context BACK is
 *   INVALID_OPERATION and FRONT works.
 */
#include "harness.h"
#include <GL/softgl_wgl.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define W 32
#define H 16

/* Expects pixel (x, y) of the buffer `buf` (GL_FRONT/GL_BACK) to be rgb. */
static void expect_buf(GLenum buf, int x, int y, int r, int g, int b, const char *what)
{
    unsigned char p[4] = {0, 0, 0, 0};
    glReadBuffer(buf);
    glReadPixels(x, y, 1, 1, GL_RGBA, GL_UNSIGNED_BYTE, p);
    h_expect(abs(p[0] - r) <= 1 && abs(p[1] - g) <= 1 && abs(p[2] - b) <= 1,
             "%s: %s (%d,%d) is %d,%d,%d, expected %d,%d,%d", what, buf == GL_FRONT ? "front" : "back", x, y, p[0],
             p[1], p[2], r, g, b);
}

/* Expects pixel (x, y) of the DC's shown image to be rgb. */
static void expect_shown(HDC dc, int x, int y, int r, int g, int b, const char *what)
{
    int w = 0, h = 0;
    const unsigned char *img = softglGetDCImage(dc, &w, &h);
    const unsigned char *p;
    if (!img || w != W || h != H) {
        h_expect(0, "%s: no shown image", what);
        return;
    }
    p = img + 4 * (y * W + x);
    h_expect(abs(p[0] - r) <= 1 && abs(p[1] - g) <= 1 && abs(p[2] - b) <= 1,
             "%s: shown (%d,%d) is %d,%d,%d, expected %d,%d,%d", what, x, y, p[0], p[1], p[2], r, g, b);
}

static void rect(float x0, float y0, float x1, float y1, float z)
{
    glBegin(GL_QUADS);
    glVertex3f(x0, y0, z);
    glVertex3f(x1, y0, z);
    glVertex3f(x1, y1, z);
    glVertex3f(x0, y1, z);
    glEnd();
}

int main(void)
{
    PIXELFORMATDESCRIPTOR pfd;
    HDC dc;
    HGLRC rc;
    GLint v = 0;
    GLuint tex;
    unsigned char texel[4];
    int fmt;

    dc = softglCreateDC(W, H);
    memset(&pfd, 0, sizeof pfd);
    pfd.nSize = sizeof pfd;
    pfd.dwFlags = PFD_DRAW_TO_WINDOW | PFD_SUPPORT_OPENGL | PFD_DOUBLEBUFFER;
    pfd.cAccumBits = 64;
    fmt = ChoosePixelFormat(dc, &pfd);
    h_expect(fmt > 0 && SetPixelFormat(dc, fmt, &pfd), "double-buffered pixel format");
    rc = wglCreateContext(dc);
    h_expect(rc && wglMakeCurrent(dc, rc), "context");

    glGetIntegerv(GL_DRAW_BUFFER, &v);
    h_expect(v == GL_BACK, "initial draw buffer 0x%x", v);
    glGetIntegerv(GL_READ_BUFFER, &v);
    h_expect(v == GL_BACK, "initial read buffer 0x%x", v);
    glGetIntegerv(GL_DOUBLEBUFFER, &v);
    h_expect(v == 1, "GL_DOUBLEBUFFER %d", v);

    glMatrixMode(GL_PROJECTION);
    glOrtho(0, W, 0, H, -1, 1);
    glMatrixMode(GL_MODELVIEW);

    /* Both buffers black; then the back buffer green. */
    glDrawBuffer(GL_FRONT_AND_BACK);
    glClearColor(0, 0, 0, 0);
    glClear(GL_COLOR_BUFFER_BIT);
    glDrawBuffer(GL_BACK);
    glClearColor(0, 1, 0, 0);
    glClear(GL_COLOR_BUFFER_BIT);
    glFlush();
    expect_buf(GL_BACK, 5, 5, 0, 255, 0, "back cleared green");
    expect_buf(GL_FRONT, 5, 5, 0, 0, 0, "front untouched by a back clear");
    expect_shown(dc, 5, 5, 0, 0, 0, "glFlush of back-buffer drawing shows nothing");

    /* The front buffer: red on the left half (scissored clear) and a grey
     * quad; glFlush shows it. */
    glDrawBuffer(GL_FRONT);
    glEnable(GL_SCISSOR_TEST);
    glScissor(0, 0, W / 2, H);
    glClearColor(1, 0, 0, 0);
    glClear(GL_COLOR_BUFFER_BIT);
    glDisable(GL_SCISSOR_TEST);
    glColor3ub(128, 128, 128);
    rect(28, 12, 32, 16, 0);
    expect_buf(GL_FRONT, 2, 2, 255, 0, 0, "front scissored clear");
    expect_buf(GL_FRONT, 20, 2, 0, 0, 0, "front outside the scissor");
    expect_buf(GL_FRONT, 30, 14, 128, 128, 128, "front quad");
    expect_buf(GL_BACK, 2, 2, 0, 255, 0, "back untouched by front drawing");
    expect_buf(GL_BACK, 30, 14, 0, 255, 0, "back untouched by a front quad");
    glFlush();
    expect_shown(dc, 2, 2, 255, 0, 0, "glFlush shows the front buffer");
    expect_shown(dc, 30, 14, 128, 128, 128, "glFlush shows the front quad");

    /* FRONT_AND_BACK: additive blue over red (front) and green (back), with
     * a depth test that must be done once per fragment. */
    glDrawBuffer(GL_FRONT_AND_BACK);
    glClearDepth(1);
    glClear(GL_DEPTH_BUFFER_BIT);
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_LESS);
    glEnable(GL_BLEND);
    glBlendFunc(GL_ONE, GL_ONE);
    glColor3ub(0, 0, 100);
    rect(0, 0, 8, 8, 0);
    expect_buf(GL_FRONT, 4, 4, 255, 0, 100, "FRONT_AND_BACK blend into front");
    expect_buf(GL_BACK, 4, 4, 0, 255, 100, "FRONT_AND_BACK blend into back");
    /* Same depth again: GL_LESS fails everywhere in both buffers. */
    rect(0, 0, 8, 8, 0);
    expect_buf(GL_FRONT, 4, 4, 255, 0, 100, "second pass fails depth (front)");
    expect_buf(GL_BACK, 4, 4, 0, 255, 100, "second pass fails depth (back)");
    glDisable(GL_DEPTH_TEST);
    glDisable(GL_BLEND);

    /* GL_LEFT is front left and back left (table 4.4). */
    glDrawBuffer(GL_LEFT);
    glColor3ub(10, 20, 30);
    rect(8, 0, 12, 4, 0);
    expect_buf(GL_FRONT, 9, 1, 10, 20, 30, "GL_LEFT draws the front");
    expect_buf(GL_BACK, 9, 1, 10, 20, 30, "GL_LEFT draws the back");

    /* GL_NONE: nothing anywhere. */
    glDrawBuffer(GL_NONE);
    glColor3ub(255, 255, 255);
    rect(0, 0, W, H, 0);
    glClearColor(1, 1, 1, 1);
    glClear(GL_COLOR_BUFFER_BIT);
    expect_buf(GL_FRONT, 20, 2, 0, 0, 0, "GL_NONE leaves the front");
    expect_buf(GL_BACK, 20, 2, 0, 255, 0, "GL_NONE leaves the back");

    /* glClear with FRONT_AND_BACK clears both (inside a scissor box). */
    glDrawBuffer(GL_FRONT_AND_BACK);
    glEnable(GL_SCISSOR_TEST);
    glScissor(16, 8, 4, 4);
    glClearColor(1, 1, 0, 0);
    glClear(GL_COLOR_BUFFER_BIT);
    glDisable(GL_SCISSOR_TEST);
    expect_buf(GL_FRONT, 17, 9, 255, 255, 0, "FRONT_AND_BACK clear, front");
    expect_buf(GL_BACK, 17, 9, 255, 255, 0, "FRONT_AND_BACK clear, back");
    expect_buf(GL_BACK, 21, 9, 0, 255, 0, "FRONT_AND_BACK clear stays in the scissor box");

    /* glCopyPixels reads the read buffer: front (red) into the back. */
    glDrawBuffer(GL_BACK);
    glReadBuffer(GL_FRONT);
    glRasterPos2i(24, 0);
    glCopyPixels(0, 8, 4, 4, GL_COLOR);
    expect_buf(GL_BACK, 25, 1, 255, 0, 0, "glCopyPixels front -> back");
    expect_buf(GL_FRONT, 25, 1, 0, 0, 0, "glCopyPixels leaves the front");

    /* glCopyTexImage2D reads the read buffer. */
    glGenTextures(1, &tex);
    glBindTexture(GL_TEXTURE_2D, tex);
    glReadBuffer(GL_FRONT);
    glCopyTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 2, 2, 1, 1, 0);
    glGetTexImage(GL_TEXTURE_2D, 0, GL_RGBA, GL_UNSIGNED_BYTE, texel);
    h_expect(texel[0] == 255 && texel[1] == 0, "glCopyTexImage2D from the front: %d,%d,%d", texel[0], texel[1], texel[2]);
    glReadBuffer(GL_BACK);
    glCopyTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 20, 2, 1, 1, 0);
    glGetTexImage(GL_TEXTURE_2D, 0, GL_RGBA, GL_UNSIGNED_BYTE, texel);
    h_expect(texel[0] == 0 && texel[1] == 255, "glCopyTexImage2D from the back: %d,%d,%d", texel[0], texel[1], texel[2]);

    /* glAccum reads the read buffer (front, 255,0,100 at (2,2)) and returns into
     * the draw buffer (back), inside the scissor box. */
    glGetIntegerv(GL_ACCUM_RED_BITS, &v);
    if (v > 0) {
        glReadBuffer(GL_FRONT);
        glDrawBuffer(GL_BACK);
        glEnable(GL_SCISSOR_TEST);
        glScissor(0, 0, 4, 4);
        glAccum(GL_LOAD, 0.5f);
        glAccum(GL_RETURN, 1.0f);
        glDisable(GL_SCISSOR_TEST);
        expect_buf(GL_BACK, 2, 2, 128, 0, 50, "glAccum front -> back");
        expect_buf(GL_FRONT, 2, 2, 255, 0, 100, "glAccum RETURN leaves the front");
    } else {
        h_expect(0, "no accumulation buffer");
    }
    h_expect_no_error("drawing");

    /* SwapBuffers: the back buffer is shown and becomes the front; the back
     * buffer keeps its contents (a copy). */
    expect_buf(GL_BACK, 20, 2, 0, 255, 0, "back before swap");
    SwapBuffers(dc);
    expect_shown(dc, 20, 2, 0, 255, 0, "SwapBuffers shows the back buffer");
    expect_shown(dc, 2, 2, 128, 0, 50, "SwapBuffers shows the accumulated pixel");
    expect_buf(GL_FRONT, 20, 2, 0, 255, 0, "front after swap");
    expect_buf(GL_FRONT, 30, 14, 0, 255, 0, "front quad replaced by the swap");
    expect_buf(GL_BACK, 20, 2, 0, 255, 0, "back kept after swap");

    /* Errors. */
    glReadBuffer(GL_FRONT_AND_BACK);
    h_expect_error(GL_INVALID_ENUM, "glReadBuffer(GL_FRONT_AND_BACK)");
    glReadBuffer(GL_NONE);
    h_expect_error(GL_INVALID_ENUM, "glReadBuffer(GL_NONE)");
    glDrawBuffer(GL_RIGHT);
    h_expect_error(GL_INVALID_OPERATION, "glDrawBuffer(GL_RIGHT)");
    glDrawBuffer(GL_AUX0);
    h_expect_error(GL_INVALID_OPERATION, "glDrawBuffer(GL_AUX0)");
    glGetIntegerv(GL_DRAW_BUFFER, &v);
    h_expect(v == GL_BACK, "failed glDrawBuffer changes nothing: 0x%x", v);

    wglMakeCurrent(NULL, NULL);
    wglDeleteContext(rc);
    softglDestroyDC(dc);

    /* Single-buffered OSMesa: BACK does not exist; FRONT is the buffer. */
    h_init(8, 8);
    glGetIntegerv(GL_DRAW_BUFFER, &v);
    h_expect(v == GL_FRONT, "OSMesa draw buffer 0x%x", v);
    glDrawBuffer(GL_BACK);
    h_expect_error(GL_INVALID_OPERATION, "OSMesa glDrawBuffer(GL_BACK)");
    glReadBuffer(GL_BACK);
    h_expect_error(GL_INVALID_OPERATION, "OSMesa glReadBuffer(GL_BACK)");
    glDrawBuffer(GL_FRONT_AND_BACK);
    h_expect_no_error("OSMesa glDrawBuffer(GL_FRONT_AND_BACK)");
    glClearColor(0, 0, 1, 1);
    glClear(GL_COLOR_BUFFER_BIT);
    glFinish();
    h_expect(h_buffer()[2] == 255 && h_buffer()[0] == 0, "OSMesa buffer cleared blue through FRONT_AND_BACK");
    return h_finish();
}
