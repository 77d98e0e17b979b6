/* t_fbo: framebuffer objects (EXT/ARB_framebuffer_object, EXT_framebuffer_blit)
 * and float textures (ARB_texture_float).
 *
 * - Completeness (EXT_framebuffer_object 4.4.4): MISSING_ATTACHMENT,
 *   INCOMPLETE_ATTACHMENT (no image; depth format on the colour point),
 *   INCOMPLETE_DIMENSIONS, INCOMPLETE_DRAW_BUFFER / READ_BUFFER, COMPLETE;
 *   the errors of the attach, bind and status calls.
 * - Render to texture: a clear and a depth-tested quad drawn into a texture
 *   (with a depth renderbuffer) are read back from the object, leave the
 *   window untouched, are what glGetTexImage returns, and are what a quad
 *   textured with it shows in the window.
 *   glFinish while the object is bound delivers the window to OSMesa.
 * - glBlitFramebuffer from the object to the window, scaled 2x (NEAREST).
 * - Round trip: colour, depth and stencil patterns drawn (glDrawPixels)
 *   into renderbuffers, and a colour pattern in an attached texture, read
 *   back the same after the object is unbound and bound again (its images
 *   reloaded from the attachments), pixel for pixel.
 * - glGenerateMipmapEXT: the 1x1 level of a 2x2 image is its mean.
 * - RGBA32F: values outside [0,1] and 1/3 come back from glGetTexImage
 *   (GL_FLOAT) bit for bit; TEXTURE_RED_TYPE is FLOAT (UNSIGNED_NORMALIZED
 *   for RGBA8). Drawing into a float texture changes only the drawn texels.
 */
#include "harness.h"
#include <stdio.h>
#include <string.h>

#define W 64
#define H 64
#define TW 32
#define TH 16

static void quad(float x0, float y0, float x1, float y1, float z)
{
    glBegin(GL_QUADS);
    glTexCoord2f(0, 0); glVertex3f(x0, y0, z);
    glTexCoord2f(1, 0); glVertex3f(x1, y0, z);
    glTexCoord2f(1, 1); glVertex3f(x1, y1, z);
    glTexCoord2f(0, 1); glVertex3f(x0, y1, z);
    glEnd();
}

/* Pixels map 1:1 onto window coordinates of the current framebuffer. */
static void pixel_projection(int w, int h)
{
    glViewport(0, 0, w, h);
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    glOrtho(0, w, 0, h, -1, 1);
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
}

static GLuint make_texture(GLenum ifmt, int w, int h, GLenum type, const void *data)
{
    GLuint t;
    glGenTextures(1, &t);
    glBindTexture(GL_TEXTURE_2D, t);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    glTexImage2D(GL_TEXTURE_2D, 0, ifmt, w, h, 0, GL_RGBA, type, data);
    return t;
}

static void completeness(void)
{
    GLuint fb, tex, notex, dtex, rb;
    GLenum s;

    glGenFramebuffersEXT(1, &fb);
    h_expect(!glIsFramebufferEXT(fb), "a generated, unbound name is no framebuffer yet");
    /* No object bound: attaching is INVALID_OPERATION. */
    glFramebufferTexture2DEXT(GL_FRAMEBUFFER_EXT, GL_COLOR_ATTACHMENT0_EXT, GL_TEXTURE_2D, 0, 0);
    h_expect_error(GL_INVALID_OPERATION, "attach with framebuffer 0 bound");
    h_expect(glCheckFramebufferStatusEXT(GL_FRAMEBUFFER_EXT) == GL_FRAMEBUFFER_COMPLETE_EXT,
             "the window framebuffer is complete");
    h_expect(glCheckFramebufferStatusEXT(GL_TEXTURE_2D) == 0, "bad status target returns 0");
    h_expect_error(GL_INVALID_ENUM, "status of a bad target");

    glBindFramebufferEXT(GL_FRAMEBUFFER_EXT, fb);
    h_expect(glIsFramebufferEXT(fb), "bound name is a framebuffer");
    s = glCheckFramebufferStatusEXT(GL_FRAMEBUFFER_EXT);
    h_expect(s == GL_FRAMEBUFFER_INCOMPLETE_MISSING_ATTACHMENT_EXT, "no attachments: 0x%x", s);

    /* A texture object with no image at the level. */
    glGenTextures(1, &notex);
    glBindTexture(GL_TEXTURE_2D, notex);
    glFramebufferTexture2DEXT(GL_FRAMEBUFFER_EXT, GL_COLOR_ATTACHMENT0_EXT, GL_TEXTURE_2D, notex, 0);
    h_expect_no_error("attach an empty texture");
    s = glCheckFramebufferStatusEXT(GL_FRAMEBUFFER_EXT);
    h_expect(s == GL_FRAMEBUFFER_INCOMPLETE_ATTACHMENT_EXT, "image-less attachment: 0x%x", s);

    /* A depth texture is not colour-renderable. */
    glGenTextures(1, &dtex);
    glBindTexture(GL_TEXTURE_2D, dtex);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_DEPTH_COMPONENT, TW, TH, 0, GL_DEPTH_COMPONENT, GL_FLOAT, NULL);
    glFramebufferTexture2DEXT(GL_FRAMEBUFFER_EXT, GL_COLOR_ATTACHMENT0_EXT, GL_TEXTURE_2D, dtex, 0);
    s = glCheckFramebufferStatusEXT(GL_FRAMEBUFFER_EXT);
    h_expect(s == GL_FRAMEBUFFER_INCOMPLETE_ATTACHMENT_EXT, "depth texture as colour: 0x%x", s);

    /* Wrong textarget for the texture's target; a texture that does not exist. */
    glFramebufferTexture2DEXT(GL_FRAMEBUFFER_EXT, GL_COLOR_ATTACHMENT0_EXT, GL_TEXTURE_CUBE_MAP_POSITIVE_X, dtex, 0);
    h_expect_error(GL_INVALID_OPERATION, "2D texture attached as a cube face");
    glFramebufferTexture2DEXT(GL_FRAMEBUFFER_EXT, GL_COLOR_ATTACHMENT0_EXT, GL_TEXTURE_2D, 4242, 0);
    h_expect_error(GL_INVALID_OPERATION, "attach a texture that does not exist");

    /* Colour 32x16 and depth 8x8: dimensions differ. */
    tex = make_texture(GL_RGBA8, TW, TH, GL_UNSIGNED_BYTE, NULL);
    glFramebufferTexture2DEXT(GL_FRAMEBUFFER_EXT, GL_COLOR_ATTACHMENT0_EXT, GL_TEXTURE_2D, tex, 0);
    glGenRenderbuffersEXT(1, &rb);
    glRenderbufferStorageEXT(GL_RENDERBUFFER_EXT, GL_DEPTH_COMPONENT24, 8, 8);
    h_expect_error(GL_INVALID_OPERATION, "storage with renderbuffer 0 bound");
    glBindRenderbufferEXT(GL_RENDERBUFFER_EXT, rb);
    glRenderbufferStorageEXT(GL_RENDERBUFFER_EXT, GL_RGBA, -1, 8);
    h_expect_error(GL_INVALID_VALUE, "negative renderbuffer width");
    glRenderbufferStorageEXT(GL_RENDERBUFFER_EXT, GL_DEPTH_COMPONENT24, 8, 8);
    h_expect_no_error("renderbuffer storage");
    {
        GLint v = 0;
        glGetRenderbufferParameterivEXT(GL_RENDERBUFFER_EXT, GL_RENDERBUFFER_WIDTH_EXT, &v);
        h_expect(v == 8, "renderbuffer width %d", v);
    }
    glFramebufferRenderbufferEXT(GL_FRAMEBUFFER_EXT, GL_DEPTH_ATTACHMENT_EXT, GL_RENDERBUFFER_EXT, rb);
    s = glCheckFramebufferStatusEXT(GL_FRAMEBUFFER_EXT);
    h_expect(s == GL_FRAMEBUFFER_INCOMPLETE_DIMENSIONS_EXT, "mismatched sizes: 0x%x", s);
    {
        GLint v = 0;
        glGetFramebufferAttachmentParameterivEXT(GL_FRAMEBUFFER_EXT, GL_DEPTH_ATTACHMENT_EXT,
                                                 GL_FRAMEBUFFER_ATTACHMENT_OBJECT_TYPE_EXT, &v);
        h_expect(v == GL_RENDERBUFFER_EXT, "depth attachment type 0x%x", v);
        glGetFramebufferAttachmentParameterivEXT(GL_FRAMEBUFFER_EXT, GL_COLOR_ATTACHMENT0_EXT,
                                                 GL_FRAMEBUFFER_ATTACHMENT_OBJECT_NAME_EXT, &v);
        h_expect(v == (GLint)tex, "colour attachment name %d", v);
    }

    /* Depth only: the draw buffer names a missing attachment, then NONE. */
    glFramebufferTexture2DEXT(GL_FRAMEBUFFER_EXT, GL_COLOR_ATTACHMENT0_EXT, GL_TEXTURE_2D, 0, 0);
    s = glCheckFramebufferStatusEXT(GL_FRAMEBUFFER_EXT);
    h_expect(s == GL_FRAMEBUFFER_INCOMPLETE_DRAW_BUFFER_EXT, "no colour, draw buffer ATTACHMENT0: 0x%x", s);
    glDrawBuffer(GL_NONE);
    s = glCheckFramebufferStatusEXT(GL_FRAMEBUFFER_EXT);
    h_expect(s == GL_FRAMEBUFFER_INCOMPLETE_READ_BUFFER_EXT, "no colour, read buffer ATTACHMENT0: 0x%x", s);
    glReadBuffer(GL_NONE);
    s = glCheckFramebufferStatusEXT(GL_FRAMEBUFFER_EXT);
    h_expect(s == GL_FRAMEBUFFER_COMPLETE_EXT, "depth only, draw/read NONE: 0x%x", s);
    glDrawBuffer(GL_BACK);
    h_expect_error(GL_INVALID_OPERATION, "glDrawBuffer(GL_BACK) on a framebuffer object");

    glBindFramebufferEXT(GL_FRAMEBUFFER_EXT, 0);
    {
        GLint v = -1;
        glGetIntegerv(GL_DRAW_BUFFER, &v);
        h_expect(v == GL_FRONT, "window draw buffer restored: 0x%x", v);
    }
    glDeleteFramebuffersEXT(1, &fb);
    h_expect(!glIsFramebufferEXT(fb), "deleted framebuffer");
    glDeleteRenderbuffersEXT(1, &rb);
    h_expect(!glIsRenderbufferEXT(rb), "deleted renderbuffer");
    glDeleteTextures(1, &tex);
    glDeleteTextures(1, &dtex);
    glDeleteTextures(1, &notex);
    h_expect_no_error("completeness");
}

static void render_to_texture(void)
{
    GLuint fb, tex, rb;
    GLint binding = -1;
    static unsigned char texels[TW * TH * 4];
    int x, y, bad = 0;

    /* The window: green. */
    glClearColor(0, 1, 0, 1);
    glClear(GL_COLOR_BUFFER_BIT);

    tex = make_texture(GL_RGBA8, TW, TH, GL_UNSIGNED_BYTE, NULL);
    glBindTexture(GL_TEXTURE_2D, 0);
    glGenFramebuffersEXT(1, &fb);
    glBindFramebufferEXT(GL_FRAMEBUFFER_EXT, fb);
    glGetIntegerv(GL_FRAMEBUFFER_BINDING_EXT, &binding);
    h_expect(binding == (GLint)fb, "framebuffer binding %d", binding);
    glFramebufferTexture2DEXT(GL_FRAMEBUFFER_EXT, GL_COLOR_ATTACHMENT0_EXT, GL_TEXTURE_2D, tex, 0);
    glGenRenderbuffersEXT(1, &rb);
    glBindRenderbufferEXT(GL_RENDERBUFFER_EXT, rb);
    glRenderbufferStorageEXT(GL_RENDERBUFFER_EXT, GL_DEPTH_COMPONENT24, TW, TH);
    glFramebufferRenderbufferEXT(GL_FRAMEBUFFER_EXT, GL_DEPTH_ATTACHMENT_EXT, GL_RENDERBUFFER_EXT, rb);
    h_expect(glCheckFramebufferStatusEXT(GL_FRAMEBUFFER_EXT) == GL_FRAMEBUFFER_COMPLETE_EXT,
             "texture + depth renderbuffer complete");

    /* Blue background at depth 0.5 everywhere (a quad), then a red quad on
     * the left half in front and a yellow one on the right half behind. */
    pixel_projection(TW, TH);
    glClearColor(0, 0, 1, 1);
    glClearDepth(1.0);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_LESS);
    glColor3f(0, 0, 1);
    quad(0, 0, TW, TH, 0.0f);          /* depth 0.5 */
    glColor3f(1, 0, 0);
    quad(0, 0, TW / 2, TH, 0.5f);      /* depth 0.25: passes */
    glColor3f(1, 1, 0);
    quad(TW / 2, 0, TW, TH, -0.5f);    /* depth 0.75: fails */
    glDisable(GL_DEPTH_TEST);

    h_expect_pixel(3, 3, 255, 0, 0, 255, 0, "FBO left half red");
    /* glFinish with the object bound presents the window (all green), not
     * the object, into the OSMesa buffer. */
    glFinish();
    {
        const unsigned char *b = h_buffer() + (3 * W + 3) * 4;
        h_expect(b[0] == 0 && b[1] == 255 && b[2] == 0, "OSMesa buffer after glFinish: %d,%d,%d", b[0], b[1], b[2]);
    }
    h_expect_pixel(TW - 3, TH - 3, 0, 0, 255, 255, 0, "FBO right half blue (yellow failed the depth test)");
    glBindFramebufferEXT(GL_FRAMEBUFFER_EXT, 0);
    pixel_projection(W, H);
    h_expect_pixel(3, 3, 0, 255, 0, 255, 0, "window untouched by FBO drawing");

    /* The texture holds what was drawn. */
    glBindTexture(GL_TEXTURE_2D, tex);
    glGetTexImage(GL_TEXTURE_2D, 0, GL_RGBA, GL_UNSIGNED_BYTE, texels);
    for (y = 0; y < TH; y++)
        for (x = 0; x < TW; x++) {
            const unsigned char *p = &texels[(y * TW + x) * 4];
            int left = x < TW / 2;
            if (p[0] != (left ? 255 : 0) || p[1] != 0 || p[2] != (left ? 0 : 255) || p[3] != 255)
                bad++;
        }
    h_expect(bad == 0, "glGetTexImage of the rendered texture: %d wrong texels", bad);

    /* Sampled: a textured quad 2x the texture's size in the window. */
    glEnable(GL_TEXTURE_2D);
    glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_REPLACE);
    quad(0, 0, 2 * TW, 2 * TH, 0);
    glDisable(GL_TEXTURE_2D);
    h_expect_pixel(5, 5, 255, 0, 0, 255, 0, "textured quad, left");
    h_expect_pixel(2 * TW - 5, 5, 0, 0, 255, 255, 0, "textured quad, right");
    h_expect_pixel(5, 2 * TH + 5, 0, 255, 0, 255, 0, "above the textured quad");

    /* Blit the object (read) to the window (draw), scaled 2x, at y = 40. */
    glClearColor(0, 0, 0, 1);
    glClear(GL_COLOR_BUFFER_BIT);
    glBindFramebufferEXT(GL_READ_FRAMEBUFFER_EXT, fb);
    glBlitFramebufferEXT(0, 0, TW, TH, 0, 32, 2 * TW, 32 + 2 * TH, GL_COLOR_BUFFER_BIT, GL_NEAREST);
    h_expect_no_error("blit");
    glBlitFramebufferEXT(0, 0, TW, TH, 0, 32, 2 * TW, 32 + 2 * TH, GL_DEPTH_BUFFER_BIT, GL_LINEAR);
    h_expect_error(GL_INVALID_OPERATION, "LINEAR depth blit");
    glBindFramebufferEXT(GL_READ_FRAMEBUFFER_EXT, 0);
    h_expect_pixel(TW - 1, 40, 255, 0, 0, 255, 0, "blit: left half red");
    h_expect_pixel(TW, 40, 0, 0, 255, 255, 0, "blit: right half blue");
    h_expect_pixel(10, 10, 0, 0, 0, 255, 0, "blit: outside the destination");

    glDeleteFramebuffersEXT(1, &fb);
    glDeleteRenderbuffersEXT(1, &rb);
    glDeleteTextures(1, &tex);
    h_expect_no_error("render to texture");
}

#define RW 13
#define RH 7

/* Reads colour, depth (as unsigned ints) and stencil of the RW x RH
 * object. */
static void read_all(unsigned char *c, GLuint *d, unsigned char *st)
{
    glPixelStorei(GL_PACK_ALIGNMENT, 1);
    glReadPixels(0, 0, RW, RH, GL_RGBA, GL_UNSIGNED_BYTE, c);
    if (d)
        glReadPixels(0, 0, RW, RH, GL_DEPTH_COMPONENT, GL_UNSIGNED_INT, d);
    if (st)
        glReadPixels(0, 0, RW, RH, GL_STENCIL_INDEX, GL_UNSIGNED_BYTE, st);
    glPixelStorei(GL_PACK_ALIGNMENT, 4);
}

static void round_trip(void)
{
    static unsigned char color[RW * RH * 4], c0[RW * RH * 4], c1[RW * RH * 4];
    static unsigned char sten[RW * RH], s0[RW * RH], s1[RW * RH];
    static float depth[RW * RH];
    static GLuint d0[RW * RH], d1[RW * RH];
    GLuint fb, rb[3], tex;
    int i, bad = 0, depth_levels = 0;

    for (i = 0; i < RW * RH; i++) {
        color[4 * i + 0] = (unsigned char)(i * 7);
        color[4 * i + 1] = (unsigned char)(255 - i);
        color[4 * i + 2] = (unsigned char)(i * i);
        color[4 * i + 3] = (unsigned char)(i * 3 + 1);
        sten[i] = (unsigned char)(i * 5 + 2);
        depth[i] = (float)i / (RW * RH);
    }
    glGenFramebuffersEXT(1, &fb);
    glBindFramebufferEXT(GL_FRAMEBUFFER_EXT, fb);
    glGenRenderbuffersEXT(3, rb);
    glBindRenderbufferEXT(GL_RENDERBUFFER_EXT, rb[0]);
    glRenderbufferStorageEXT(GL_RENDERBUFFER_EXT, GL_RGBA8, RW, RH);
    glBindRenderbufferEXT(GL_RENDERBUFFER_EXT, rb[1]);
    glRenderbufferStorageEXT(GL_RENDERBUFFER_EXT, GL_DEPTH_COMPONENT24, RW, RH);
    glBindRenderbufferEXT(GL_RENDERBUFFER_EXT, rb[2]);
    glRenderbufferStorageEXT(GL_RENDERBUFFER_EXT, GL_STENCIL_INDEX8_EXT, RW, RH);
    glFramebufferRenderbufferEXT(GL_FRAMEBUFFER_EXT, GL_COLOR_ATTACHMENT0_EXT, GL_RENDERBUFFER_EXT, rb[0]);
    glFramebufferRenderbufferEXT(GL_FRAMEBUFFER_EXT, GL_DEPTH_ATTACHMENT_EXT, GL_RENDERBUFFER_EXT, rb[1]);
    glFramebufferRenderbufferEXT(GL_FRAMEBUFFER_EXT, GL_STENCIL_ATTACHMENT_EXT, GL_RENDERBUFFER_EXT, rb[2]);
    h_expect(glCheckFramebufferStatusEXT(GL_FRAMEBUFFER_EXT) == GL_FRAMEBUFFER_COMPLETE_EXT,
             "colour, depth and stencil renderbuffers complete");

    pixel_projection(RW, RH);
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
    glRasterPos2i(0, 0);
    glDrawPixels(RW, RH, GL_RGBA, GL_UNSIGNED_BYTE, color);
    /* Depth pixels carry the raster colour to the colour buffer: masked. */
    glColorMask(GL_FALSE, GL_FALSE, GL_FALSE, GL_FALSE);
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_ALWAYS);
    glDrawPixels(RW, RH, GL_DEPTH_COMPONENT, GL_FLOAT, depth);
    glDisable(GL_DEPTH_TEST);
    glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
    glDrawPixels(RW, RH, GL_STENCIL_INDEX, GL_UNSIGNED_BYTE, sten);
    glDepthFunc(GL_LESS);
    glPixelStorei(GL_UNPACK_ALIGNMENT, 4);
    h_expect_no_error("patterns drawn into renderbuffers");
    read_all(c0, d0, s0);
    for (i = 0; i < RW * RH * 4; i++)
        if (c0[i] != color[i]) {
            h_expect(0, "colour pattern drawn into the renderbuffer: byte %d is %d, drew %d", i, c0[i], color[i]);
            break;
        }
    h_expect(memcmp(s0, sten, sizeof sten) == 0, "stencil pattern drawn into the renderbuffer");
    for (i = 1; i < RW * RH; i++)
        depth_levels += d0[i] > d0[i - 1];
    h_expect(depth_levels == RW * RH - 1, "depth pattern increases: %d steps", depth_levels);

    /* Unbound and bound again: the images come back from the renderbuffers. */
    glBindFramebufferEXT(GL_FRAMEBUFFER_EXT, 0);
    glClearColor(0, 0, 0, 0);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT | GL_STENCIL_BUFFER_BIT);
    glBindFramebufferEXT(GL_FRAMEBUFFER_EXT, fb);
    read_all(c1, d1, s1);
    for (i = 0; i < RW * RH; i++)
        bad += memcmp(&c0[4 * i], &c1[4 * i], 4) != 0 || d0[i] != d1[i] || s0[i] != s1[i];
    h_expect(bad == 0, "renderbuffers after rebinding: %d pixels differ", bad);

    /* The same colour pattern as a texture, attached in place of rb[0]. */
    tex = make_texture(GL_RGBA8, RW, RH, GL_UNSIGNED_BYTE, NULL);
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
    glTexSubImage2D(GL_TEXTURE_2D, 0, 0, 0, RW, RH, GL_RGBA, GL_UNSIGNED_BYTE, color);
    glPixelStorei(GL_UNPACK_ALIGNMENT, 4);
    glFramebufferTexture2DEXT(GL_FRAMEBUFFER_EXT, GL_COLOR_ATTACHMENT0_EXT, GL_TEXTURE_2D, tex, 0);
    read_all(c1, NULL, NULL);
    h_expect(memcmp(c1, color, sizeof color) == 0, "attached texture read back as the framebuffer");

    glBindFramebufferEXT(GL_FRAMEBUFFER_EXT, 0);
    pixel_projection(W, H);
    glDeleteFramebuffersEXT(1, &fb);
    glDeleteRenderbuffersEXT(3, rb);
    glDeleteTextures(1, &tex);
    h_expect_no_error("round trip");
}

static void mipmaps(void)
{
    static const unsigned char img[2 * 2 * 4] = {
        0, 0, 0, 255,   100, 40, 8, 255,
        200, 80, 16, 255,   100, 40, 8, 255,
    };
    unsigned char out[4] = {0};
    GLuint t = make_texture(GL_RGBA8, 2, 2, GL_UNSIGNED_BYTE, img);
    glGenerateMipmapEXT(GL_TEXTURE_2D);
    h_expect_no_error("glGenerateMipmapEXT");
    glGetTexImage(GL_TEXTURE_2D, 1, GL_RGBA, GL_UNSIGNED_BYTE, out);
    h_expect(out[0] == 100 && out[1] == 40 && out[2] == 8 && out[3] == 255,
             "level 1 = mean: %d,%d,%d,%d", out[0], out[1], out[2], out[3]);
    glDeleteTextures(1, &t);
}

static void float_textures(void)
{
    static float in[4 * 4 * 4], out[4 * 4 * 4];
    GLint type = 0;
    GLuint t, t8, fb;
    int i, same = 1;

    for (i = 0; i < 64; i++)
        in[i] = (i % 5 == 0) ? 2.5f : (i % 7 == 0) ? -1.0f : (float)i / 3.0f;
    t = make_texture(GL_RGBA32F_ARB, 4, 4, GL_FLOAT, in);
    h_expect_no_error("RGBA32F upload");
    glGetTexImage(GL_TEXTURE_2D, 0, GL_RGBA, GL_FLOAT, out);
    for (i = 0; i < 64; i++)
        if (memcmp(&in[i], &out[i], sizeof(float)) != 0) {
            h_expect(0, "RGBA32F element %d: put %g, got %g", i, in[i], out[i]);
            same = 0;
            break;
        }
    h_expect(same, "RGBA32F round trip is exact");
    glGetTexLevelParameteriv(GL_TEXTURE_2D, 0, GL_TEXTURE_RED_TYPE_ARB, &type);
    h_expect(type == GL_FLOAT, "RGBA32F red type 0x%x", type);
    t8 = make_texture(GL_RGBA8, 4, 4, GL_UNSIGNED_BYTE, NULL);
    glGetTexLevelParameteriv(GL_TEXTURE_2D, 0, GL_TEXTURE_RED_TYPE_ARB, &type);
    h_expect(type == GL_UNSIGNED_NORMALIZED_ARB, "RGBA8 red type 0x%x", type);

    /* Draw a white texel-sized quad into texel (1, 1) of the float texture:
     * the others keep their values exactly. */
    glBindTexture(GL_TEXTURE_2D, t);
    glGenFramebuffersEXT(1, &fb);
    glBindFramebufferEXT(GL_FRAMEBUFFER_EXT, fb);
    glFramebufferTexture2DEXT(GL_FRAMEBUFFER_EXT, GL_COLOR_ATTACHMENT0_EXT, GL_TEXTURE_2D, t, 0);
    h_expect(glCheckFramebufferStatusEXT(GL_FRAMEBUFFER_EXT) == GL_FRAMEBUFFER_COMPLETE_EXT, "float texture attached");
    pixel_projection(4, 4);
    glColor4f(1, 1, 1, 1);
    quad(1, 1, 2, 2, 0);
    glBindFramebufferEXT(GL_FRAMEBUFFER_EXT, 0);
    pixel_projection(W, H);
    glGetTexImage(GL_TEXTURE_2D, 0, GL_RGBA, GL_FLOAT, out);
    for (i = 0; i < 64; i++) {
        int texel = i / 4;
        float want = texel == 5 ? 1.0f : in[i];
        if (out[i] != want) {
            h_expect(0, "float texture after drawing texel 5: element %d = %g, want %g", i, out[i], want);
            break;
        }
    }
    glDeleteFramebuffersEXT(1, &fb);
    glDeleteTextures(1, &t);
    glDeleteTextures(1, &t8);
    h_expect_no_error("float textures");
}

int main(void)
{
    const char *ext;
    h_init(W, H);
    ext = (const char *)glGetString(GL_EXTENSIONS);
    h_expect(ext && strstr(ext, "GL_EXT_framebuffer_object "), "GL_EXT_framebuffer_object advertised");
    h_expect(ext && strstr(ext, "GL_ARB_texture_float "), "GL_ARB_texture_float advertised");
    completeness();
    render_to_texture();
    round_trip();
    mipmaps();
    float_textures();
    return h_finish();
}
