/* t_tex_swizzle: EXT/ARB_texture_swizzle through fixed function.
 *
 * - TEXTURE_SWIZZLE_R/G/B/A take RED, GREEN, BLUE, ALPHA, ZERO, ONE (else
 *   INVALID_ENUM, nothing changes); TEXTURE_SWIZZLE_RGBA sets all four
 *   through the vector forms (glTexParameteri with it is INVALID_ENUM);
 *   queries return what was set; the initial state is the identity.
 * - Texturing with GL_REPLACE gives the swizzled texel: an RGBA texture
 *   under NEAREST, LINEAR and LINEAR_MIPMAP_LINEAR (the filters the
 *   specialized samplers and kernels take unswizzled), a LUMINANCE_ALPHA
 *   texture (swizzle after the base format's expansion), the border
 *   colour under CLAMP_TO_BORDER, and a depth texture's comparison result
 *   (swizzle after DEPTH_TEXTURE_MODE).
 * - glPushAttrib(GL_TEXTURE_BIT) / glPopAttrib restore the swizzle; a bound
 *   sampler object does not replace it.
 */
#include "harness.h"
#include <stdio.h>

#define W 8
#define H 8

#ifndef GL_TEXTURE_SWIZZLE_R
#define GL_TEXTURE_SWIZZLE_R 0x8E42
#define GL_TEXTURE_SWIZZLE_G 0x8E43
#define GL_TEXTURE_SWIZZLE_B 0x8E44
#define GL_TEXTURE_SWIZZLE_A 0x8E45
#define GL_TEXTURE_SWIZZLE_RGBA 0x8E46
#endif

static void quad(float s0, float t0, float s1, float t1)
{
    glBegin(GL_QUADS);
    glTexCoord2f(s0, t0); glVertex2f(-1, -1);
    glTexCoord2f(s1, t0); glVertex2f(1, -1);
    glTexCoord2f(s1, t1); glVertex2f(1, 1);
    glTexCoord2f(s0, t1); glVertex2f(-1, 1);
    glEnd();
}

static void expect_centre(const char *what, int r, int g, int b, int a)
{
    h_expect_pixel(W / 2, H / 2, r, g, b, a, 1, what);
}

static GLint param(GLenum pname)
{
    GLint v = -1;
    glGetTexParameteriv(GL_TEXTURE_2D, pname, &v);
    return v;
}

int main(void)
{
    /* One colour everywhere, so every filter and level gives it exactly. */
    static const unsigned char texel[4] = {200, 100, 50, 150};
    unsigned char img[16 * 16 * 4];
    static const GLint swz[4] = {GL_BLUE, GL_ONE, GL_ALPHA, GL_RED};
    static const GLint bad[4] = {GL_RED, GL_RGBA, GL_RED, GL_RED};
    static const GLenum filters[3] = {GL_NEAREST, GL_LINEAR, GL_LINEAR_MIPMAP_LINEAR};
    GLint got[4] = {0, 0, 0, 0};
    GLuint tex, depth, smp;
    float border[4] = {0.2f, 0.4f, 0.6f, 0.8f};
    float dz[4] = {0.25f, 0.25f, 0.25f, 0.25f};
    unsigned char la[2] = {90, 180};
    int i;

    h_init(W, H);
    for (i = 0; i < 16 * 16; i++) {
        img[i * 4 + 0] = texel[0];
        img[i * 4 + 1] = texel[1];
        img[i * 4 + 2] = texel[2];
        img[i * 4 + 3] = texel[3];
    }
    glGenTextures(1, &tex);
    glBindTexture(GL_TEXTURE_2D, tex);

    /* API. */
    h_expect(param(GL_TEXTURE_SWIZZLE_R) == GL_RED && param(GL_TEXTURE_SWIZZLE_A) == GL_ALPHA, "initial swizzle is the identity");
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_SWIZZLE_G, GL_RGBA);
    h_expect_error(GL_INVALID_ENUM, "TEXTURE_SWIZZLE_G = GL_RGBA");
    h_expect(param(GL_TEXTURE_SWIZZLE_G) == GL_GREEN, "a bad value changes nothing");
    glTexParameteriv(GL_TEXTURE_2D, GL_TEXTURE_SWIZZLE_RGBA, bad);
    h_expect_error(GL_INVALID_ENUM, "TEXTURE_SWIZZLE_RGBA with one bad value");
    h_expect(param(GL_TEXTURE_SWIZZLE_R) == GL_RED, "a bad RGBA vector changes nothing");
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_SWIZZLE_RGBA, GL_RED);
    h_expect_error(GL_INVALID_ENUM, "TEXTURE_SWIZZLE_RGBA through glTexParameteri");
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_SWIZZLE_B, GL_ZERO);
    h_expect(param(GL_TEXTURE_SWIZZLE_B) == GL_ZERO, "TEXTURE_SWIZZLE_B = ZERO reads back");
    glTexParameteriv(GL_TEXTURE_2D, GL_TEXTURE_SWIZZLE_RGBA, swz);
    glGetTexParameteriv(GL_TEXTURE_2D, GL_TEXTURE_SWIZZLE_RGBA, got);
    h_expect(got[0] == GL_BLUE && got[1] == GL_ONE && got[2] == GL_ALPHA && got[3] == GL_RED,
             "TEXTURE_SWIZZLE_RGBA reads back: 0x%x 0x%x 0x%x 0x%x", got[0], got[1], got[2], got[3]);
    h_expect_no_error("swizzle API");

    /* RGBA texture under three filters: (B, 1, A, R) of the texel. */
    glTexParameteri(GL_TEXTURE_2D, GL_GENERATE_MIPMAP, GL_TRUE);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, 16, 16, 0, GL_RGBA, GL_UNSIGNED_BYTE, img);
    glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_REPLACE);
    glEnable(GL_TEXTURE_2D);
    for (i = 0; i < 3; i++) {
        char name[64];
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, (GLint)filters[i]);
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, filters[i] == GL_NEAREST ? GL_NEAREST : GL_LINEAR);
        glClear(GL_COLOR_BUFFER_BIT);
        quad(0, 0, 1, 1);
        snprintf(name, sizeof name, "rgba swizzled, filter 0x%x", filters[i]);
        expect_centre(name, texel[2], 255, texel[3], texel[0]);
    }

    /* Push/pop and a sampler object. */
    glPushAttrib(GL_TEXTURE_BIT);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_SWIZZLE_R, GL_ZERO);
    glPopAttrib();
    h_expect(param(GL_TEXTURE_SWIZZLE_R) == GL_BLUE, "glPopAttrib restores TEXTURE_SWIZZLE_R: 0x%x", param(GL_TEXTURE_SWIZZLE_R));
    glGenSamplers(1, &smp);
    glSamplerParameteri(smp, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    glBindSampler(0, smp);
    glClear(GL_COLOR_BUFFER_BIT);
    quad(0, 0, 1, 1);
    expect_centre("swizzle kept with a sampler object bound", texel[2], 255, texel[3], texel[0]);
    glBindSampler(0, 0);
    glDeleteSamplers(1, &smp);

    /* Border colour: the whole quad samples outside [0, 1]. */
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_BORDER);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_BORDER);
    glTexParameterfv(GL_TEXTURE_2D, GL_TEXTURE_BORDER_COLOR, border);
    glClear(GL_COLOR_BUFFER_BIT);
    quad(2, 2, 3, 3);
    expect_centre("border colour swizzled", 153, 255, 204, 51);

    /* LUMINANCE_ALPHA: expanded to (L, L, L, A), then (B, 1, A, R) = (L, 1, A, L). */
    glTexParameteri(GL_TEXTURE_2D, GL_GENERATE_MIPMAP, GL_FALSE);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_REPEAT);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_REPEAT);
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_LUMINANCE_ALPHA, 1, 1, 0, GL_LUMINANCE_ALPHA, GL_UNSIGNED_BYTE, la);
    glClear(GL_COLOR_BUFFER_BIT);
    quad(0, 0, 1, 1);
    expect_centre("luminance-alpha swizzled", la[0], 255, la[1], la[0]);

    /* Depth texture, compare LEQUAL, INTENSITY mode: r = 0.5 > 0.25 fails:
     * (0, 0, 0, 0), swizzled with (ONE, RED, ZERO, ONE): (1, 0, 0, 1). */
    glGenTextures(1, &depth);
    glBindTexture(GL_TEXTURE_2D, depth);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_DEPTH_COMPONENT, 2, 2, 0, GL_DEPTH_COMPONENT, GL_FLOAT, dz);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_COMPARE_MODE, GL_COMPARE_R_TO_TEXTURE);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_COMPARE_FUNC, GL_LEQUAL);
    glTexParameteri(GL_TEXTURE_2D, GL_DEPTH_TEXTURE_MODE, GL_INTENSITY);
    {
        static const GLint dswz[4] = {GL_ONE, GL_RED, GL_ZERO, GL_ONE};
        glTexParameteriv(GL_TEXTURE_2D, GL_TEXTURE_SWIZZLE_RGBA, dswz);
    }
    glClear(GL_COLOR_BUFFER_BIT);
    glBegin(GL_QUADS);
    glTexCoord3f(0, 0, 0.5f); glVertex2f(-1, -1);
    glTexCoord3f(1, 0, 0.5f); glVertex2f(1, -1);
    glTexCoord3f(1, 1, 0.5f); glVertex2f(1, 1);
    glTexCoord3f(0, 1, 0.5f); glVertex2f(-1, 1);
    glEnd();
    expect_centre("depth comparison swizzled", 255, 0, 0, 255);

    h_expect_no_error("swizzled texturing");
    return h_finish();
}
