/* t_texture: texturing end to end (GL 1.5 section 3.8) in one scene,
 * compared with a golden image rendered by Mesa (softpipe) and reviewed by
 * eye, plus analytic pixel checks:
 *
 *  - a perspective floor with a mipmapped checkerboard (GENERATE_MIPMAP,
 *    LINEAR_MIPMAP_LINEAR): perspective correction and LOD selection;
 *  - an orthographic quad with an 8x8 NEAREST texture mapped one texel to
 *    four pixels (checked texel by texel) and REPLACE;
 *  - a quad with CLAMP_TO_BORDER and a border colour, LINEAR, MODULATE;
 *  - a quad with two units: a luminance texture on unit 1 combined with
 *    unit 0 by COMBINE INTERPOLATE by the primary alpha;
 *  - a sphere-mapped triangle fan (texgen SPHERE_MAP);
 *  - glGetTexImage and glGetTexLevelParameter round trips.
 */
#include "harness.h"
#include <math.h>
#include <stdio.h>
#include <string.h>
#ifndef M_PI
#define M_PI 3.14159265358979323846
#endif

#define W 128
#define H 128

static GLubyte checker[64][64][4];
static GLubyte small[8][8][4];

int main(void)
{
    GLuint tex[4];
    int i, j;

    h_init(W, H);
    glViewport(0, 0, W, H);
    glClearColor(0.1f, 0.1f, 0.2f, 1);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);

    for (j = 0; j < 64; j++)
        for (i = 0; i < 64; i++) {
            int on = ((i / 8) + (j / 8)) & 1;
            checker[j][i][0] = on ? 240 : 30;
            checker[j][i][1] = on ? 200 : 60;
            checker[j][i][2] = on ? 40 : 150;
            checker[j][i][3] = 255;
        }
    for (j = 0; j < 8; j++)
        for (i = 0; i < 8; i++) {
            small[j][i][0] = (GLubyte)(i * 32);
            small[j][i][1] = (GLubyte)(j * 32);
            small[j][i][2] = (GLubyte)((i ^ j) * 30);
            small[j][i][3] = 255;
        }

    glGenTextures(4, tex);
    h_expect(tex[0] != 0 && tex[1] != tex[0], "glGenTextures names");
    h_expect(!glIsTexture(tex[0]), "a generated name is not a texture before binding");

    /* Texture 0: mipmapped checkerboard. */
    glBindTexture(GL_TEXTURE_2D, tex[0]);
    h_expect(glIsTexture(tex[0]), "bound name is a texture");
    glTexParameteri(GL_TEXTURE_2D, GL_GENERATE_MIPMAP, GL_TRUE);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 64, 64, 0, GL_RGBA, GL_UNSIGNED_BYTE, checker);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR_MIPMAP_LINEAR);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
    h_expect_no_error("mipmapped texture");
    {
        GLint w = -1;
        glGetTexLevelParameteriv(GL_TEXTURE_2D, 3, GL_TEXTURE_WIDTH, &w);
        h_expect(w == 8, "generated level 3 width %d, want 8", w);
    }

    /* Texture 1: 8x8 nearest. */
    glBindTexture(GL_TEXTURE_2D, tex[1]);
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGB8, 8, 8, 0, GL_RGBA, GL_UNSIGNED_BYTE, small);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    {
        GLubyte back[8][8][3];
        GLint fmt = 0;
        memset(back, 0, sizeof back);
        glPixelStorei(GL_PACK_ALIGNMENT, 1);
        glGetTexImage(GL_TEXTURE_2D, 0, GL_RGB, GL_UNSIGNED_BYTE, back);
        h_expect(back[5][3][0] == small[5][3][0] && back[5][3][1] == small[5][3][1] && back[5][3][2] == small[5][3][2],
                 "glGetTexImage texel (3,5): %d %d %d", back[5][3][0], back[5][3][1], back[5][3][2]);
        glGetTexLevelParameteriv(GL_TEXTURE_2D, 0, GL_TEXTURE_INTERNAL_FORMAT, &fmt);
        h_expect(fmt == GL_RGB8, "internal format 0x%x", fmt);
    }

    /* Texture 2: 4x4 with a border colour. */
    glBindTexture(GL_TEXTURE_2D, tex[2]);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 4, 4, 0, GL_RGBA, GL_UNSIGNED_BYTE, small);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_BORDER);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_BORDER);
    {
        static const GLfloat border[4] = {0.9f, 0.2f, 0.6f, 1};
        glTexParameterfv(GL_TEXTURE_2D, GL_TEXTURE_BORDER_COLOR, border);
    }

    /* Texture 3: a luminance ramp for unit 1. */
    {
        GLubyte lum[16];
        for (i = 0; i < 16; i++)
            lum[i] = (GLubyte)(i * 17);
        glBindTexture(GL_TEXTURE_2D, tex[3]);
        glTexImage2D(GL_TEXTURE_2D, 0, GL_LUMINANCE, 16, 1, 0, GL_LUMINANCE, GL_UNSIGNED_BYTE, lum);
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    }
    h_expect_no_error("texture setup");

    glEnable(GL_TEXTURE_2D);
    glEnable(GL_DEPTH_TEST);

    /* The rest in window-like coordinates. */
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    glOrtho(0, W, 0, H, -1, 1);
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
    glDisable(GL_DEPTH_TEST);

    /* Nearest 8x8 on 32x32 pixels at (4, 92). */
    glBindTexture(GL_TEXTURE_2D, tex[1]);
    glBegin(GL_QUADS);
    glTexCoord2f(0, 0); glVertex2f(4, 92);
    glTexCoord2f(1, 0); glVertex2f(36, 92);
    glTexCoord2f(1, 1); glVertex2f(36, 124);
    glTexCoord2f(0, 1); glVertex2f(4, 124);
    glEnd();

    /* Border colour, modulated by a colour, at (44, 92). */
    glBindTexture(GL_TEXTURE_2D, tex[2]);
    glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_MODULATE);
    glColor3f(1.0f, 0.8f, 1.0f);
    glBegin(GL_QUADS);
    glTexCoord2f(-0.5f, -0.5f); glVertex2f(44, 92);
    glTexCoord2f(1.5f, -0.5f); glVertex2f(76, 92);
    glTexCoord2f(1.5f, 1.5f); glVertex2f(76, 124);
    glTexCoord2f(-0.5f, 1.5f); glVertex2f(44, 124);
    glEnd();

    /* Two units at (84, 92): unit 0 the nearest texture, unit 1 the
     * luminance ramp, interpolated by the primary alpha (0.25). */
    glBindTexture(GL_TEXTURE_2D, tex[1]);
    glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_REPLACE);
    glActiveTexture(GL_TEXTURE1);
    glBindTexture(GL_TEXTURE_2D, tex[3]);
    glEnable(GL_TEXTURE_2D);
    glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_COMBINE);
    glTexEnvi(GL_TEXTURE_ENV, GL_COMBINE_RGB, GL_INTERPOLATE);
    glTexEnvi(GL_TEXTURE_ENV, GL_SOURCE0_RGB, GL_TEXTURE);
    glTexEnvi(GL_TEXTURE_ENV, GL_SOURCE1_RGB, GL_PREVIOUS);
    glTexEnvi(GL_TEXTURE_ENV, GL_SOURCE2_RGB, GL_PRIMARY_COLOR);
    glTexEnvi(GL_TEXTURE_ENV, GL_OPERAND2_RGB, GL_SRC_ALPHA);
    glTexEnvi(GL_TEXTURE_ENV, GL_COMBINE_ALPHA, GL_REPLACE);
    glTexEnvi(GL_TEXTURE_ENV, GL_SOURCE0_ALPHA, GL_PREVIOUS);
    glColor4f(1, 1, 1, 0.25f);
    glBegin(GL_QUADS);
    glMultiTexCoord2f(GL_TEXTURE0, 0, 0); glMultiTexCoord2f(GL_TEXTURE1, 0, 0); glVertex2f(84, 92);
    glMultiTexCoord2f(GL_TEXTURE0, 1, 0); glMultiTexCoord2f(GL_TEXTURE1, 1, 0); glVertex2f(116, 92);
    glMultiTexCoord2f(GL_TEXTURE0, 1, 1); glMultiTexCoord2f(GL_TEXTURE1, 1, 1); glVertex2f(116, 124);
    glMultiTexCoord2f(GL_TEXTURE0, 0, 1); glMultiTexCoord2f(GL_TEXTURE1, 0, 1); glVertex2f(84, 124);
    glEnd();
    glDisable(GL_TEXTURE_2D);
    glActiveTexture(GL_TEXTURE0);
    h_expect_no_error("multitexture");

    /* Sphere map on a fan approximating a hemisphere at (100, 64). */
    glBindTexture(GL_TEXTURE_2D, tex[1]);
    glTexGeni(GL_S, GL_TEXTURE_GEN_MODE, GL_SPHERE_MAP);
    glTexGeni(GL_T, GL_TEXTURE_GEN_MODE, GL_SPHERE_MAP);
    glEnable(GL_TEXTURE_GEN_S);
    glEnable(GL_TEXTURE_GEN_T);
    glBegin(GL_TRIANGLE_FAN);
    glNormal3f(0, 0, 1);
    glVertex2f(100, 64);
    for (i = 0; i <= 16; i++) {
        double a = 2 * M_PI * i / 16;
        glNormal3d(0.7 * cos(a), 0.7 * sin(a), 0.714);
        glVertex2d(100 + 20 * cos(a), 64 + 20 * sin(a));
    }
    glEnd();
    glDisable(GL_TEXTURE_GEN_S);
    glDisable(GL_TEXTURE_GEN_T);
    h_expect_no_error("drawing");

    /* Analytic checks. Nearest quad: pixel (4 + 4i + 1, 92 + 4j + 1) shows
     * texel (i, j) of the RGB8 texture. */
    for (j = 0; j < 8; j += 3)
        for (i = 0; i < 8; i += 3) {
            char what[64];
            snprintf(what, sizeof what, "nearest texel %d,%d", i, j);
            h_expect_pixel(4 + 4 * i + 1, 92 + 4 * j + 1, small[j][i][0], small[j][i][1], small[j][i][2], 255, 0, what);
        }
    /* Border quad corner: border colour modulated by (1, 0.8, 1). */
    h_expect_pixel(45, 93, 230, 41, 153, 255, 1, "border colour, modulated");
    /* Two units at texel (1, 1) of unit 0 (pixels 88..91) and texel 2 of
     * unit 1's ramp: s = 5.5 / 32 there, texel 2 (34): 0.25 L + 0.75 previous. */
    {
        int e[3];
        for (i = 0; i < 3; i++)
            e[i] = (int)floor(0.25 * 34 + 0.75 * small[1][1][i] + 0.5);
        h_expect_pixel(89, 97, e[0], e[1], e[2], -1, 1, "COMBINE INTERPOLATE");
    }
    h_check_golden("texture", 3, 0);

    /* The floor, in perspective, alone in a second image: Mesa's softpipe
     * takes one LOD per 2x2 quad from finite differences and the max of
     * |ds|, |dt|, where softgl takes each fragment's exact derivatives and
     * the spec's sqrt, so texels near level and checker transitions differ:
     * a looser comparison. */
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    glEnable(GL_TEXTURE_2D);
    glEnable(GL_DEPTH_TEST);
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    glFrustum(-1, 1, -1, 1, 1, 20);
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
    glBindTexture(GL_TEXTURE_2D, tex[0]);
    glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_REPLACE);
    glBegin(GL_QUADS);
    glTexCoord2f(0, 0); glVertex3f(-4, -1, -1.2f);
    glTexCoord2f(4, 0); glVertex3f(4, -1, -1.2f);
    glTexCoord2f(4, 8); glVertex3f(4, -1, -18);
    glTexCoord2f(0, 8); glVertex3f(-4, -1, -18);
    glEnd();
    h_expect_no_error("floor");
    /* Near the bottom centre the texture magnifies (about 3 pixels per
     * texel): bilinear between checker colours, never the background. */
    h_expect_pixel(64, 2, -1, -1, -1, 255, 0, "floor covers the bottom");
    h_check_golden("texture_mipmap", 40, 400);
    return h_finish();
}
