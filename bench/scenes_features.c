/* Benchmark scenes for the GL features beyond plain shaded triangles
 * (issue 9 item 1): fog, trilinear texturing, pixel rectangles, vertex
 * arrays, the accumulation buffer, stencil shadow volumes and smooth lines.
 * Where a GL hint lets an implementation trade accuracy for time, the scene
 * comes twice: NAME with GL_NICEST and NAME_fast with GL_FASTEST (item 3).
 */
#include <GL/gl.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include "scenes.h"

#ifndef M_PI
#define M_PI 3.14159265358979323846
#endif

/* spheres_m under exponential-squared fog. */
static void fog_spheres(int frame, GLenum hint)
{
    static const GLfloat grey[4] = {0.5f, 0.55f, 0.6f, 1};
    glEnable(GL_FOG);
    glFogi(GL_FOG_MODE, GL_EXP2);
    glFogf(GL_FOG_DENSITY, 0.09f);
    glFogfv(GL_FOG_COLOR, grey);
    glHint(GL_FOG_HINT, hint);
    spheres(frame, 24);
    glDisable(GL_FOG);
}

/* A 512x512 RGBA texture (checks and rings) with its mipmaps made by GL. */
static GLuint tunnel_texture(void)
{
    static GLuint tex;
    int x, y;
    unsigned char *img;
    if (tex)
        return tex;
    img = malloc(512 * 512 * 4);
    for (y = 0; y < 512; y++)
        for (x = 0; x < 512; x++) {
            unsigned char *p = img + 4 * (y * 512 + x);
            int check = ((x >> 5) ^ (y >> 5)) & 1;
            double r = hypot(x - 256, y - 256);
            p[0] = (unsigned char)(check ? 220 : 40);
            p[1] = (unsigned char)(127 + 127 * sin(r * 0.3));
            p[2] = (unsigned char)((x * 255) / 511);
            p[3] = 255;
        }
    glGenTextures(1, &tex);
    glBindTexture(GL_TEXTURE_2D, tex);
    glTexParameteri(GL_TEXTURE_2D, GL_GENERATE_MIPMAP, GL_TRUE);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR_MIPMAP_LINEAR);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 512, 512, 0, GL_RGBA, GL_UNSIGNED_BYTE, img);
    free(img);
    return tex;
}

/* A window-filling textured tunnel seen down its axis: every pixel
 * trilinear-filtered, the LOD running from magnified to the smallest levels. */
static void textured(int frame, GLenum hint)
{
    int side;
    float shift = 0.05f * (frame % 20);
    glClearColor(0, 0, 0, 1);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    glEnable(GL_DEPTH_TEST);
    glHint(GL_PERSPECTIVE_CORRECTION_HINT, hint);
    glBindTexture(GL_TEXTURE_2D, tunnel_texture());
    glEnable(GL_TEXTURE_2D);
    glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_MODULATE);
    perspective();
    glRotatef(frame * 2.0f, 0, 0, 1);
    for (side = 0; side < 4; side++) {
        glPushMatrix();
        glRotatef(90.0f * side, 0, 0, 1);
        glBegin(GL_QUADS);
        glColor3f(1, 1 - 0.15f * side, 1);
        glTexCoord2f(0, shift); glVertex3f(-1, -1, -1);
        glTexCoord2f(1, shift); glVertex3f(1, -1, -1);
        glTexCoord2f(1, shift + 12); glVertex3f(1, -1, -40);
        glTexCoord2f(0, shift + 12); glVertex3f(-1, -1, -40);
        glEnd();
        glPopMatrix();
    }
    glDisable(GL_TEXTURE_2D);
    glHint(GL_PERSPECTIVE_CORRECTION_HINT, GL_DONT_CARE);
}

/* glDrawPixels of a window-sized RGBA image through the fragment pipeline
 * (depth test on, a pixel zoom of 1). */
static void draw_pixels(int frame)
{
    static unsigned char *img;
    int i;
    if (!img) {
        img = malloc((size_t)W * H * 4);
        for (i = 0; i < W * H; i++) {
            img[4 * i] = (unsigned char)(i % W);
            img[4 * i + 1] = (unsigned char)(i / W);
            img[4 * i + 2] = (unsigned char)(i * 7);
            img[4 * i + 3] = 255;
        }
    }
    glClearColor(0, 0, 0, 1);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    glEnable(GL_DEPTH_TEST);
    glWindowPos2i(frame % 8, 0);
    glPixelStorei(GL_UNPACK_ALIGNMENT, 4);
    glDrawPixels(W - 8, H, GL_RGBA, GL_UNSIGNED_BYTE, img);
    glDisable(GL_DEPTH_TEST);
}

/* glCopyPixels: a shaded triangle, then its left half copied over the right
 * half, and the bottom half over the top (overlapping copies included). */
static void copy_pixels(int frame)
{
    clear_2d(0.1f, 0.2f, 0.3f);
    glBegin(GL_TRIANGLES);
    glColor3f(1, 0, 0); glVertex2f(-0.9f, -0.9f);
    glColor3f(0, 1, 0); glVertex2f(0.1f * (frame % 5), -0.7f);
    glColor3f(0, 0, 1); glVertex2f(-0.5f, 0.9f);
    glEnd();
    glWindowPos2i(W / 2, 0);
    glCopyPixels(0, 0, W / 2, H, GL_COLOR);
    glWindowPos2i(0, H / 4);
    glCopyPixels(0, 0, W, H / 2, GL_COLOR);
}

/* The immediate_1m triangles (333,334 tiny triangles, 1,000,002 vertices)
 * from client vertex and colour arrays, one glDrawArrays. */
static void arrays_1m(void)
{
    static GLfloat *v;
    static GLubyte *c;
    enum { N = 333334 };
    int i;
    if (!v) {
        int cols = W / 2;
        float sx = 2.0f / W, sy = 2.0f / H;
        v = malloc(sizeof(GLfloat) * 6 * N);
        c = malloc(3 * 3 * N);
        for (i = 0; i < N; i++) {
            int col = i % cols, row = (i / cols) % (H / 2), k;
            float x = -1 + (2 * col + 0.25f) * sx, y = -1 + (2 * row + 0.25f) * sy;
            GLfloat *p = v + 6 * i;
            p[0] = x; p[1] = y; p[2] = x + 1.5f * sx; p[3] = y; p[4] = x; p[5] = y + 1.5f * sy;
            for (k = 0; k < 3; k++) {
                c[9 * i + 3 * k] = (GLubyte)(i & 255);
                c[9 * i + 3 * k + 1] = (GLubyte)((i >> 8) & 255);
                c[9 * i + 3 * k + 2] = 128;
            }
        }
    }
    clear_2d(0, 0, 0);
    glVertexPointer(2, GL_FLOAT, 0, v);
    glColorPointer(3, GL_UNSIGNED_BYTE, 0, c);
    glEnableClientState(GL_VERTEX_ARRAY);
    glEnableClientState(GL_COLOR_ARRAY);
    glDrawArrays(GL_TRIANGLES, 0, 3 * N);
    glDisableClientState(GL_VERTEX_ARRAY);
    glDisableClientState(GL_COLOR_ARRAY);
}

/* Motion blur with the accumulation buffer: spheres_s four times, each
 * accumulated at 1/4, then returned. */
static void accum_blur(int frame)
{
    int k;
    glClearAccum(0, 0, 0, 0);
    glClear(GL_ACCUM_BUFFER_BIT);
    for (k = 0; k < 4; k++) {
        spheres(frame * 4 + k, 8);
        glAccum(k ? GL_ACCUM : GL_LOAD, 0.25f);
    }
    glAccum(GL_RETURN, 1.0f);
}

/* An axis-aligned box. */
static void box(float x0, float y0, float z0, float x1, float y1, float z1)
{
    glBegin(GL_QUADS);
    glNormal3f(0, 0, 1); glVertex3f(x0, y0, z1); glVertex3f(x1, y0, z1); glVertex3f(x1, y1, z1); glVertex3f(x0, y1, z1);
    glNormal3f(0, 0, -1); glVertex3f(x0, y0, z0); glVertex3f(x0, y1, z0); glVertex3f(x1, y1, z0); glVertex3f(x1, y0, z0);
    glNormal3f(1, 0, 0); glVertex3f(x1, y0, z0); glVertex3f(x1, y1, z0); glVertex3f(x1, y1, z1); glVertex3f(x1, y0, z1);
    glNormal3f(-1, 0, 0); glVertex3f(x0, y0, z0); glVertex3f(x0, y0, z1); glVertex3f(x0, y1, z1); glVertex3f(x0, y1, z0);
    glNormal3f(0, 1, 0); glVertex3f(x0, y1, z0); glVertex3f(x0, y1, z1); glVertex3f(x1, y1, z1); glVertex3f(x1, y1, z0);
    glNormal3f(0, -1, 0); glVertex3f(x0, y0, z0); glVertex3f(x1, y0, z0); glVertex3f(x1, y0, z1); glVertex3f(x0, y0, z1);
    glEnd();
}

/* The shadow volume of a square occluder (corners q, counter-clockwise
 * seen from the light at l): its four sides pushed 30 units away from the
 * light, and both caps, so the volume is closed. */
static void square_volume(const float q[4][3], const float l[3])
{
    float far_[4][3];
    int i, k;
    for (i = 0; i < 4; i++)
        for (k = 0; k < 3; k++)
            far_[i][k] = q[i][k] + 30 * (q[i][k] - l[k]);
    glBegin(GL_QUADS);
    for (i = 0; i < 4; i++) {
        int j = (i + 1) % 4;
        glVertex3fv(q[j]); glVertex3fv(q[i]); glVertex3fv(far_[i]); glVertex3fv(far_[j]);
    }
    glVertex3fv(q[0]); glVertex3fv(q[1]); glVertex3fv(q[2]); glVertex3fv(q[3]);
    glVertex3fv(far_[3]); glVertex3fv(far_[2]); glVertex3fv(far_[1]); glVertex3fv(far_[0]);
    glEnd();
}

/* Stencil shadow volumes (z-pass): a lit room floor with boxes, six
 * floating squares casting shadows from a point light; the volumes counted
 * in the stencil buffer with INCR_WRAP/DECR_WRAP, the shadowed pixels
 * darkened by one blended window-sized quad. */
static void shadow_volume(int frame)
{
    static const GLfloat amb[4] = {0.2f, 0.2f, 0.2f, 1}, white[4] = {1, 1, 1, 1};
    float light[3] = {0, 5, -8};
    GLfloat lpos[4];
    int i;
    glClearColor(0, 0, 0, 1);
    glClearStencil(0);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT | GL_STENCIL_BUFFER_BIT);
    glEnable(GL_DEPTH_TEST);
    perspective();
    glTranslatef(0, -1.5f, -10);
    glRotatef(20, 1, 0, 0);
    lpos[0] = light[0]; lpos[1] = light[1]; lpos[2] = light[2]; lpos[3] = 1;
    glEnable(GL_LIGHTING);
    glEnable(GL_LIGHT0);
    glLightfv(GL_LIGHT0, GL_POSITION, lpos);
    glLightfv(GL_LIGHT0, GL_DIFFUSE, white);
    glLightModelfv(GL_LIGHT_MODEL_AMBIENT, amb);
    glEnable(GL_COLOR_MATERIAL);
    glColor3f(0.8f, 0.8f, 0.7f);
    box(-8, -1, -20, 8, 0, 2); /* the floor */
    for (i = 0; i < 5; i++) {
        glColor3f(0.3f + 0.15f * i, 0.4f, 0.9f - 0.15f * i);
        box(-6 + 3 * i, 0, -10 + (i % 2) * 3, -5 + 3 * i, 1.5f, -9 + (i % 2) * 3);
    }
    glDisable(GL_LIGHTING);
    glDisable(GL_COLOR_MATERIAL);
    /* The occluders, drawn unlit. */
    {
        float squares[6][4][3];
        int s;
        for (s = 0; s < 6; s++) {
            float cx = -5 + 2 * s, cz = -8 + (float)sin(0.1 * frame + s) * 2, y = 3, r = 0.6f;
            float pts[4][3] = {{cx - r, y, cz + r}, {cx + r, y, cz + r}, {cx + r, y, cz - r}, {cx - r, y, cz - r}};
            memcpy(squares[s], pts, sizeof pts);
            glColor3f(0.9f, 0.3f, 0.2f);
            glBegin(GL_QUADS);
            glVertex3fv(pts[3]); glVertex3fv(pts[2]); glVertex3fv(pts[1]); glVertex3fv(pts[0]);
            glEnd();
        }
        /* Volumes into the stencil only: front faces +1, back faces -1. */
        glColorMask(GL_FALSE, GL_FALSE, GL_FALSE, GL_FALSE);
        glDepthMask(GL_FALSE);
        glEnable(GL_STENCIL_TEST);
        glStencilFunc(GL_ALWAYS, 0, ~0u);
        glEnable(GL_CULL_FACE);
        glEnable(GL_POLYGON_OFFSET_FILL);
        glPolygonOffset(0, 1);
        for (s = 0; s < 2; s++) {
            int v;
            glCullFace(s ? GL_FRONT : GL_BACK);
            glStencilOp(GL_KEEP, GL_KEEP, s ? GL_DECR_WRAP : GL_INCR_WRAP);
            for (v = 0; v < 6; v++)
                square_volume((const float (*)[3])squares[v], light);
        }
        glDisable(GL_POLYGON_OFFSET_FILL);
        glDisable(GL_CULL_FACE);
        glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
        glDepthMask(GL_TRUE);
    }
    /* Darken where the count is not zero. */
    glStencilFunc(GL_NOTEQUAL, 0, ~0u);
    glStencilOp(GL_KEEP, GL_KEEP, GL_KEEP);
    glDisable(GL_DEPTH_TEST);
    glEnable(GL_BLEND);
    glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
    glColor4f(0, 0, 0, 0.6f);
    glRectf(-1, -1, 1, 1);
    glDisable(GL_BLEND);
    glDisable(GL_STENCIL_TEST);
}

/* 600 antialiased lines of width 1.5 and 3, blended (GL_LINE_SMOOTH). */
static void smooth_lines(int frame, GLenum hint)
{
    int i, k;
    clear_2d(1, 1, 1);
    glRotatef((float)frame, 0, 0, 1);
    glEnable(GL_LINE_SMOOTH);
    glHint(GL_LINE_SMOOTH_HINT, hint);
    glEnable(GL_BLEND);
    glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
    for (i = 0; i < 2; i++) {
        glLineWidth(1.5f + 1.5f * i);
        glBegin(GL_LINES);
        for (k = 0; k < 300; k++) {
            double a = 2 * M_PI * (k + 0.5 * i) / 300;
            glColor3f((float)k / 300, 0.3f * i, 1 - (float)k / 300);
            glVertex2d(0.1 * cos(a), 0.1 * sin(a));
            glVertex2d((0.6 + 0.3 * i) * cos(a), (0.6 + 0.3 * i) * sin(a));
        }
        glEnd();
    }
    glLineWidth(1);
    glDisable(GL_BLEND);
    glDisable(GL_LINE_SMOOTH);
    glHint(GL_LINE_SMOOTH_HINT, GL_DONT_CARE);
}

int feature_scene(const char *scene, int frame)
{
    if (!strcmp(scene, "fog_spheres")) fog_spheres(frame, GL_NICEST);
    else if (!strcmp(scene, "fog_spheres_fast")) fog_spheres(frame, GL_FASTEST);
    else if (!strcmp(scene, "textured")) textured(frame, GL_NICEST);
    else if (!strcmp(scene, "textured_fast")) textured(frame, GL_FASTEST);
    else if (!strcmp(scene, "drawpixels")) draw_pixels(frame);
    else if (!strcmp(scene, "copypixels")) copy_pixels(frame);
    else if (!strcmp(scene, "arrays_1m")) arrays_1m();
    else if (!strcmp(scene, "accum_blur")) accum_blur(frame);
    else if (!strcmp(scene, "shadow_volume")) shadow_volume(frame);
    else if (!strcmp(scene, "smooth_lines")) smooth_lines(frame, GL_NICEST);
    else if (!strcmp(scene, "smooth_lines_fast")) smooth_lines(frame, GL_FASTEST);
    else return 0;
    return 1;
}
