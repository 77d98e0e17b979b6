/* t_sampler: sampler objects (ARB_sampler_objects) and immutable texture
 * storage (ARB_texture_storage).
 *
 * - glTexStorage2D makes every level (sizes halving), TEXTURE_IMMUTABLE_FORMAT
 *   is true, glTexImage2D on it is INVALID_OPERATION, an unsized format is
 *   INVALID_ENUM and too many levels INVALID_OPERATION.
 * - A 2x2 texture with a red level 0 and a green level 1, its own MIN_FILTER
 *   NEAREST, drawn minified 2x into one pixel: red (level 0 only). With a
 *   sampler whose MIN_FILTER is NEAREST_MIPMAP_NEAREST bound to the unit:
 *   green (level 1). Unbound again: red. Deleting the bound sampler unbinds it.
 * - Errors: a unit beyond the last is INVALID_VALUE, a name glGenSamplers did
 *   not return is INVALID_OPERATION, a bad parameter INVALID_ENUM.
 */
#include "harness.h"
#include <stdio.h>

static void one_pixel_quad(void)
{
    glBegin(GL_QUADS);
    glTexCoord2f(0, 0); glVertex2f(0, 0);
    glTexCoord2f(1, 0); glVertex2f(1, 0);
    glTexCoord2f(1, 1); glVertex2f(1, 1);
    glTexCoord2f(0, 1); glVertex2f(0, 1);
    glEnd();
}

int main(void)
{
    static const unsigned char red[2 * 2 * 4] = {255, 0, 0, 255, 255, 0, 0, 255, 255, 0, 0, 255, 255, 0, 0, 255};
    static const unsigned char green[4] = {0, 255, 0, 255};
    GLuint tex, s, t2;
    GLint v = 0, w = 0;

    h_init(8, 8);
    glViewport(0, 0, 8, 8);
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    glOrtho(0, 8, 0, 8, -1, 1);
    glMatrixMode(GL_MODELVIEW);

    glGenTextures(1, &tex);
    glBindTexture(GL_TEXTURE_2D, tex);
    glTexStorage2D(GL_TEXTURE_2D, 2, GL_RGBA8, 2, 2);
    h_expect_no_error("glTexStorage2D");
    glGetTexLevelParameteriv(GL_TEXTURE_2D, 1, GL_TEXTURE_WIDTH, &w);
    h_expect(w == 1, "level 1 width %d", w);
    glGetTexParameteriv(GL_TEXTURE_2D, GL_TEXTURE_IMMUTABLE_FORMAT, &v);
    h_expect(v == 1, "immutable format %d", v);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, 2, 2, 0, GL_RGBA, GL_UNSIGNED_BYTE, red);
    h_expect_error(GL_INVALID_OPERATION, "glTexImage2D on immutable storage");
    glTexSubImage2D(GL_TEXTURE_2D, 0, 0, 0, 2, 2, GL_RGBA, GL_UNSIGNED_BYTE, red);
    glTexSubImage2D(GL_TEXTURE_2D, 1, 0, 0, 1, 1, GL_RGBA, GL_UNSIGNED_BYTE, green);
    h_expect_no_error("glTexSubImage2D into storage");

    glGenTextures(1, &t2);
    glBindTexture(GL_TEXTURE_2D, t2);
    glTexStorage2D(GL_TEXTURE_2D, 1, GL_RGBA, 2, 2);
    h_expect_error(GL_INVALID_ENUM, "unsized format");
    glTexStorage2D(GL_TEXTURE_2D, 3, GL_RGBA8, 2, 2);
    h_expect_error(GL_INVALID_OPERATION, "3 levels for a 2x2 texture");
    glBindTexture(GL_TEXTURE_2D, tex);

    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_REPLACE);
    glEnable(GL_TEXTURE_2D);

    glClear(GL_COLOR_BUFFER_BIT);
    one_pixel_quad();
    h_expect_pixel(0, 0, 255, 0, 0, 255, 0, "texture's own NEAREST: level 0");

    glGenSamplers(1, &s);
    h_expect(glIsSampler(s), "generated sampler exists");
    glSamplerParameteri(s, GL_TEXTURE_MIN_FILTER, GL_NEAREST_MIPMAP_NEAREST);
    glSamplerParameteri(s, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    glSamplerParameteri(s, GL_TEXTURE_MIN_FILTER, GL_RGBA);
    h_expect_error(GL_INVALID_ENUM, "bad min filter");
    glGetSamplerParameteriv(s, GL_TEXTURE_MIN_FILTER, &v);
    h_expect(v == GL_NEAREST_MIPMAP_NEAREST, "sampler min filter 0x%x", v);
    glBindSampler(0, s);
    h_expect_no_error("glBindSampler");
    glClear(GL_COLOR_BUFFER_BIT);
    one_pixel_quad();
    h_expect_pixel(0, 0, 0, 255, 0, 255, 0, "sampler's NEAREST_MIPMAP_NEAREST: level 1");

    glBindSampler(0, 0);
    glClear(GL_COLOR_BUFFER_BIT);
    one_pixel_quad();
    h_expect_pixel(0, 0, 255, 0, 0, 255, 0, "sampler unbound: level 0 again");

    glBindSampler(64, s);
    h_expect_error(GL_INVALID_VALUE, "unit beyond the last");
    glBindSampler(0, 777);
    h_expect_error(GL_INVALID_OPERATION, "name not from glGenSamplers");

    glBindSampler(0, s);
    glDeleteSamplers(1, &s);
    h_expect(!glIsSampler(s), "deleted sampler");
    glGetIntegerv(GL_SAMPLER_BINDING, &v);
    h_expect(v == 0, "deleting the bound sampler unbinds it (%d)", v);
    glClear(GL_COLOR_BUFFER_BIT);
    one_pixel_quad();
    h_expect_pixel(0, 0, 255, 0, 0, 255, 0, "after deleting the sampler: level 0");
    h_expect_no_error("end");
    return h_finish();
}
