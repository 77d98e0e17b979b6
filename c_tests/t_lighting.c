/* t_lighting: per-vertex lighting (GL 1.5 section 2.14) on a smooth-shaded
 * sphere built by hand (so the geometry is identical on every GL), with two
 * lights: a white directional light with specular highlights, and a red
 * positional spot light with attenuation; plus two-sided lighting on an
 * open cylinder whose inside shows the back material, and GL_COLOR_MATERIAL
 * on a small quad.
 *
 * Checked against a golden image rendered by Mesa (softpipe: it splits quad
 * strips along the same diagonal as softgl; llvmpipe differs) and reviewed
 * by eye (tolerance 3 per channel; edge pixels may differ), and at a few
 * pixels against the lighting equation computed here.
 */
#include "harness.h"
#include <math.h>
#ifndef M_PI
#define M_PI 3.14159265358979323846
#endif
#include <stdio.h>

#define W 96
#define H 96

static void sphere(double r, int stacks, int slices)
{
    int i, j;
    for (i = 0; i < stacks; i++) {
        double t0 = M_PI * i / stacks, t1 = M_PI * (i + 1) / stacks;
        glBegin(GL_QUAD_STRIP);
        for (j = 0; j <= slices; j++) {
            double p = 2 * M_PI * j / slices;
            double n0[3] = {sin(t0) * cos(p), cos(t0), sin(t0) * sin(p)};
            double n1[3] = {sin(t1) * cos(p), cos(t1), sin(t1) * sin(p)};
            glNormal3dv(n0);
            glVertex3d(r * n0[0], r * n0[1], r * n0[2]);
            glNormal3dv(n1);
            glVertex3d(r * n1[0], r * n1[1], r * n1[2]);
        }
        glEnd();
    }
}

int main(void)
{
    static const GLfloat white[4] = {1, 1, 1, 1}, dir[4] = {-0.5f, 0.6f, 0.8f, 0};
    static const GLfloat red[4] = {1, 0.2f, 0.1f, 1}, spot_pos[4] = {1.5f, -1.0f, 1.0f, 1};
    static const GLfloat spot_dir[3] = {-1.5f, 1.0f, -1.0f};
    static const GLfloat mat_diffuse[4] = {0.3f, 0.5f, 0.9f, 1}, mat_spec[4] = {0.8f, 0.8f, 0.8f, 1};
    static const GLfloat back_diffuse[4] = {0.9f, 0.8f, 0.1f, 1};
    int i;

    h_init(W, H);
    glViewport(0, 0, W, H);
    glClearColor(0, 0, 0, 1);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    glEnable(GL_DEPTH_TEST);
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    glFrustum(-0.6, 0.6, -0.6, 0.6, 2, 10);
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();

    /* Lights are specified with the identity modelview: eye coordinates. */
    glLightfv(GL_LIGHT0, GL_POSITION, dir);
    glLightfv(GL_LIGHT0, GL_SPECULAR, white);
    glLightfv(GL_LIGHT1, GL_POSITION, spot_pos);
    glLightfv(GL_LIGHT1, GL_DIFFUSE, red);
    glLightfv(GL_LIGHT1, GL_SPOT_DIRECTION, spot_dir);
    glLightf(GL_LIGHT1, GL_SPOT_CUTOFF, 30);
    glLightf(GL_LIGHT1, GL_SPOT_EXPONENT, 4);
    glLightf(GL_LIGHT1, GL_LINEAR_ATTENUATION, 0.2f);
    glEnable(GL_LIGHTING);
    glEnable(GL_LIGHT0);
    glEnable(GL_LIGHT1);
    h_expect_no_error("light setup");

    glMaterialfv(GL_FRONT_AND_BACK, GL_DIFFUSE, mat_diffuse);
    glMaterialfv(GL_FRONT_AND_BACK, GL_SPECULAR, mat_spec);
    glMaterialf(GL_FRONT_AND_BACK, GL_SHININESS, 30);

    glTranslatef(-0.35f, 0.3f, -5);
    glShadeModel(GL_SMOOTH);
    sphere(0.9, 24, 48);

    /* Two-sided lighting: an open cylinder tilted towards the viewer, whose
     * inside shows the yellow back material. */
    glLoadIdentity();
    glTranslatef(0.8f, -0.8f, -5);
    glRotatef(60, 1, 0, 0);
    glLightModeli(GL_LIGHT_MODEL_TWO_SIDE, GL_TRUE);
    glMaterialfv(GL_BACK, GL_DIFFUSE, back_diffuse);
    glBegin(GL_QUAD_STRIP);
    for (i = 0; i <= 32; i++) {
        double a = 2 * M_PI * i / 32;
        glNormal3d(cos(a), sin(a), 0);
        glVertex3d(0.45 * cos(a), 0.45 * sin(a), 0.5);
        glVertex3d(0.45 * cos(a), 0.45 * sin(a), -0.5);
    }
    glEnd();
    glLightModeli(GL_LIGHT_MODEL_TWO_SIDE, GL_FALSE);

    /* Colour material: a flat quad facing the viewer, its diffuse colour
     * from glColor; light 0 only. */
    glDisable(GL_LIGHT1);
    glLoadIdentity();
    glColorMaterial(GL_FRONT, GL_AMBIENT_AND_DIFFUSE);
    glEnable(GL_COLOR_MATERIAL);
    glColor3f(0.2f, 0.9f, 0.3f);
    glShadeModel(GL_FLAT);
    glNormal3f(0, 0, 1);
    glBegin(GL_QUADS);
    glVertex3f(-1.1f, -1.1f, -4); glVertex3f(-0.5f, -1.1f, -4);
    glVertex3f(-0.5f, -0.5f, -4); glVertex3f(-1.1f, -0.5f, -4);
    glEnd();
    glDisable(GL_COLOR_MATERIAL);
    h_expect_no_error("drawing");

    /* The quad by the equation: e = 0, ambient = 0.2 * cm (scene) + 0
     * (light 0's ambient), diffuse = (n.l) cm with l = normalize(dir);
     * specular: h = normalize(l + (0,0,1)), (n.h)^30 * 0.8. */
    {
        double l = sqrt(0.25 + 0.36 + 0.64), ndotl = 0.8 / l;
        double hz = 0.8 / l + 1, hl = sqrt(pow(-0.5 / l, 2) + pow(0.6 / l, 2) + hz * hz);
        double spec = 0.8 * pow(hz / hl, 30);
        double cm[3] = {0.2, 0.9, 0.3};
        int e[3];
        for (i = 0; i < 3; i++) {
            double v = 0.2 * cm[i] + ndotl * cm[i] + spec;
            e[i] = (int)((v > 1 ? 1 : v) * 255 + 0.5);
        }
        /* The quad spans window x,y of about 9..23. */
        h_expect_pixel(14, 14, e[0], e[1], e[2], -1, 2, "colour-material quad");
    }
    h_expect_pixel(1, 94, 0, 0, 0, -1, 0, "background");
    h_check_golden("lighting", 2, 10);
    return h_finish();
}
