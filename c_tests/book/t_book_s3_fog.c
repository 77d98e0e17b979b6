/* t_book_s3_fog: the Russian textbook's fog section (§13.3, seeds-inventory
 * §3.5 F34).
 *
 * BOOK: S3, Russian OpenGL textbook, ch. 13.3 "Modelling fog", fragment F34 (grey linear fog from 2 to 50)
 * SHOWS: five red squares at eye distances 4, 12, 20, 30 and 44 fading into the grey (0.6) fog; beside them the same with GL_EXP and GL_EXP2 (density 0.05)
 * FEATURES: glFogi(GL_FOG_MODE, GL_LINEAR/GL_EXP/GL_EXP2), glFogf(GL_FOG_START/END/DENSITY), glFogfv(GL_FOG_COLOR), perspective projection
 *
 * Checks: the centre of each square is f*red + (1-f)*grey with f from the
 * spec's formula for its mode, at the eye-space depth of that square.
 * The spec's fog distance is the eye distance, which it lets an
 * implementation approximate by |z_e|; softgl (like Mesa) uses |z_e|,
 * which is what the checks assume (a radial distance would be up to 6%
 * larger for the outer squares).
 */
#include "book.h"

#define W 360
#define H 120

static const double dist[5] = {4, 12, 20, 30, 44};

static void squares(int col)
{
    int i;
    for (i = 0; i < 5; i++) {
        /* a square of half-size scaled with distance, centred on a ray so
         * that it appears in slot i of column col */
        double d = dist[i], sx = (-0.32 + 0.16 * i) * d, sy = (0.09 - 0.09 * col) * d, h = 0.04 * d;
        glBegin(GL_QUADS);
        glVertex3d(sx - h, sy - h, -d); glVertex3d(sx + h, sy - h, -d);
        glVertex3d(sx + h, sy + h, -d); glVertex3d(sx - h, sy + h, -d);
        glEnd();
    }
}

static double fog_f(int mode, double d)
{
    double f;
    if (mode == GL_LINEAR) f = (50 - d) / (50 - 2);
    else if (mode == GL_EXP) f = exp(-0.05 * d);
    else f = exp(-(0.05 * d) * (0.05 * d));
    return f < 0 ? 0 : f > 1 ? 1 : f;
}

int main(void)
{
    GLfloat FogColor[4] = {0.6f, 0.6f, 0.6f, 1};
    static const GLenum modes[3] = {GL_LINEAR, GL_EXP, GL_EXP2};
    int m, i;

    book_open(W, H);
    glClearColor(0.6f, 0.6f, 0.6f, 1);
    glClear(GL_COLOR_BUFFER_BIT);
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    glFrustum(-0.15 * W / H, 0.15 * W / H, -0.15, 0.15, 1, 100);
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
    /* F34 */
    glEnable(GL_FOG);
    glFogi(GL_FOG_MODE, GL_LINEAR);
    glFogf(GL_FOG_START, 2);
    glFogf(GL_FOG_END, 50);
    glFogfv(GL_FOG_COLOR, FogColor);
    glFogf(GL_FOG_DENSITY, 0.05f);
    glColor3f(1, 0, 0);
    for (m = 0; m < 3; m++) {
        glFogi(GL_FOG_MODE, (GLint)modes[m]);
        squares(m);
    }
    glDisable(GL_FOG);
    book_shot("s3_fog-linear_exp_exp2", 2, 20);
    for (m = 0; m < 3; m++)
        for (i = 0; i < 5; i++) {
            double d = dist[i], x, y, f = fog_f((int)modes[m], d);
            char what[80];
            book_project((-0.32 + 0.16 * i) * d, (0.09 - 0.09 * m) * d, -d, &x, &y);
            snprintf(what, sizeof what, "fog mode %d at distance %g: f = %.3f", m, d, f);
            book_expect_rgb((int)x, (int)y, (int)(255 * (f + (1 - f) * 0.6) + 0.5),
                            (int)(255 * (1 - f) * 0.6 + 0.5), (int)(255 * (1 - f) * 0.6 + 0.5), 3, what);
        }
    h_expect_no_error("end");
    book_close();
    return h_finish();
}
