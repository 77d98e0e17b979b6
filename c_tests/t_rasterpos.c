/* t_rasterpos: the current raster position (GL 1.5 section 2.13) and
 * glWindowPos (GL 1.4).
 *
 * - glRasterPos transforms like a vertex: the window position (x, y, z)
 *   and the clip w are queryable (GL_CURRENT_RASTER_POSITION), all four
 *   forms (2/3/4 coordinates) and types agree, glRasterPos4 divides by w.
 * - A position outside the view volume (x, y or z) is invalid
 *   (GL_CURRENT_RASTER_POSITION_VALID false), and glBitmap/glDrawPixels
 *   then draw nothing; a later valid glRasterPos makes it valid again.
 * - The colour is latched: GL_CURRENT_RASTER_COLOR is the current colour
 *   at glRasterPos, a later glColor does not change it, bitmaps use it.
 *   With lighting, it is the lit colour (emission + ambient here).
 * - GL_CURRENT_RASTER_DISTANCE is the eye distance.
 * - glWindowPos sets window coordinates directly, maps z through the
 *   depth range, is always valid and takes the current (unlit) colour.
 * - glRasterPos between glBegin and glEnd is INVALID_OPERATION.
 */
#define GL_GLEXT_PROTOTYPES 1
#include "harness.h"
#include <math.h>
#include <stdio.h>

#define W 32
#define H 16

static void expect_pos(float x, float y, float z, float w, const char *what)
{
    float p[4];
    glGetFloatv(GL_CURRENT_RASTER_POSITION, p);
    h_expect(fabsf(p[0] - x) < 1e-4f && fabsf(p[1] - y) < 1e-4f && fabsf(p[2] - z) < 1e-4f &&
                 fabsf(p[3] - w) < 1e-4f,
             "%s: raster position %g,%g,%g,%g, expected %g,%g,%g,%g", what, p[0], p[1], p[2], p[3], x, y,
             z, w);
}

static void expect_valid(int v, const char *what)
{
    GLboolean b = 7;
    glGetBooleanv(GL_CURRENT_RASTER_POSITION_VALID, &b);
    h_expect(b == (v ? GL_TRUE : GL_FALSE), "%s: valid = %d, expected %d", what, b, v);
}

static void expect_color(float r, float g, float b, float a, const char *what)
{
    float c[4];
    glGetFloatv(GL_CURRENT_RASTER_COLOR, c);
    h_expect(fabsf(c[0] - r) < 1e-3f && fabsf(c[1] - g) < 1e-3f && fabsf(c[2] - b) < 1e-3f &&
                 fabsf(c[3] - a) < 1e-3f,
             "%s: raster colour %g,%g,%g,%g, expected %g,%g,%g,%g", what, c[0], c[1], c[2], c[3], r, g, b,
             a);
}

static const GLubyte dot[4] = {0x80, 0, 0, 0};

int main(void)
{
    GLint ip[4];
    float d;
    static const GLfloat emission[4] = {0.25f, 0.5f, 0.75f, 1.0f};
    static const GLfloat black[4] = {0, 0, 0, 1};
    static const GLfloat diffuse[4] = {0, 0, 0, 0.5f};
    static const GLubyte white_px[4] = {255, 255, 255, 255};

    h_init(W, H);
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
    glClearColor(0, 0, 0, 0);
    glClear(GL_COLOR_BUFFER_BIT);

    /* Initial state: (0,0,0,1), valid, colour (1,1,1,1). */
    expect_pos(0, 0, 0, 1, "initial");
    expect_valid(1, "initial");
    expect_color(1, 1, 1, 1, "initial");

    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    glOrtho(0, W, 0, H, -1, 1);
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();

    glRasterPos2i(3, 4);
    expect_pos(3, 4, 0.5f, 1, "glRasterPos2i(3,4)");
    expect_valid(1, "glRasterPos2i(3,4)");
    glRasterPos3f(5.5f, 6.25f, 0.5f); /* z_ndc = -0.5 -> window 0.25 */
    expect_pos(5.5f, 6.25f, 0.25f, 1, "glRasterPos3f(5.5,6.25,0.5)");
    glRasterPos4d(12, 8, 0, 2);
    expect_pos(6, 4, 0.5f, 2, "glRasterPos4d(12,8,0,2)");
    {
        GLshort sv[3] = {7, 9, 0};
        glRasterPos3sv(sv);
        expect_pos(7, 9, 0.5f, 1, "glRasterPos3sv(7,9,0)");
    }
    glRasterPos2f(3.4f, 4.6f);
    glGetIntegerv(GL_CURRENT_RASTER_POSITION, ip);
    h_expect(ip[0] == 3 && ip[1] == 5, "integer query rounds: %d,%d, expected 3,5", ip[0], ip[1]);

    /* Outside the view volume: invalid; nothing drawn. */
    glRasterPos2i(-1, 4);
    expect_valid(0, "glRasterPos2i(-1,4), left of the volume");
    glRasterPos2i(3, H + 1);
    expect_valid(0, "glRasterPos2i(3,H+1), above");
    glRasterPos3f(3, 4, 2);
    expect_valid(0, "glRasterPos3f(3,4,2), beyond the far plane");
    glBitmap(1, 1, 0, 0, 0, 0, dot);
    glDrawPixels(1, 1, GL_RGBA, GL_UNSIGNED_BYTE, white_px);
    {
        unsigned char px[W * H * 4];
        int i, drawn = 0;
        h_read(px);
        for (i = 0; i < W * H * 4; i++)
            drawn |= px[i];
        h_expect(!drawn, "bitmap/drawpixels at an invalid raster position drew something");
    }
    glRasterPos2i(3, 4);
    expect_valid(1, "valid again");

    /* Latched colour. */
    glColor3f(1, 0, 0);
    glRasterPos2i(2, 2);
    glColor3f(0, 1, 0);
    expect_color(1, 0, 0, 1, "latched at glRasterPos");
    glBitmap(1, 1, 0, 0, 0, 0, dot);
    h_expect_pixel(2, 2, 255, 0, 0, 255, 0, "bitmap takes the latched colour");

    /* Distance: eye (3, 4, 0) -> 5. */
    glRasterPos2i(3, 4);
    glGetFloatv(GL_CURRENT_RASTER_DISTANCE, &d);
    h_expect(fabsf(d - 5.0f) < 1e-4f, "raster distance %g, expected 5", d);

    /* Lighting: emission + material ambient * scene ambient (0 here). */
    glLightModelfv(GL_LIGHT_MODEL_AMBIENT, black);
    glMaterialfv(GL_FRONT_AND_BACK, GL_EMISSION, emission);
    glMaterialfv(GL_FRONT_AND_BACK, GL_DIFFUSE, diffuse);
    glEnable(GL_LIGHTING);
    glColor3f(1, 1, 1);
    glRasterPos2i(4, 4);
    expect_color(0.25f, 0.5f, 0.75f, 0.5f, "lit raster colour");
    glBitmap(1, 1, 0, 0, 0, 0, dot);
    h_expect_pixel(4, 4, 64, 128, 191, 128, 1, "bitmap takes the lit colour");
    /* glWindowPos is never lit. */
    glWindowPos2i(10, 11);
    expect_color(1, 1, 1, 1, "glWindowPos takes the current colour");
    glDisable(GL_LIGHTING);

    /* glWindowPos: window coordinates, z through the depth range. */
    expect_pos(10, 11, 0, 1, "glWindowPos2i(10,11)");
    expect_valid(1, "glWindowPos2i");
    glDepthRange(0.2, 0.6);
    glWindowPos3f(-3.5f, 40.0f, 0.5f);
    expect_pos(-3.5f, 40.0f, 0.4f, 1, "glWindowPos3f outside the window, depth range 0.2..0.6");
    expect_valid(1, "glWindowPos outside the window");
    glWindowPos3d(1, 2, 7);
    expect_pos(1, 2, 0.6f, 1, "glWindowPos3d z clamped to 1");
    glDepthRange(0, 1);
    glGetFloatv(GL_CURRENT_RASTER_DISTANCE, &d);
    h_expect(d == 0.0f, "glWindowPos distance %g, expected 0", d);

    /* Perspective: behind the eye is invalid. */
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    glFrustum(-1, 1, -1, 1, 1, 10);
    glMatrixMode(GL_MODELVIEW);
    glRasterPos3f(0, 0, 2);
    expect_valid(0, "behind the eye");
    glRasterPos3f(0, 0, -2);
    expect_valid(1, "in front of the eye");
    expect_pos(W / 2.0f, H / 2.0f, (float)((1.0 + (11.0 / 9.0 - 20.0 / 9.0 / 2.0)) / 2.0), 2,
               "glFrustum centre at z = -2");

    h_expect_no_error("before Begin/End");
    glBegin(GL_POINTS);
    glRasterPos2i(1, 1);
    glEnd();
    h_expect_error(GL_INVALID_OPERATION, "glRasterPos between glBegin and glEnd");

    return h_finish();
}
