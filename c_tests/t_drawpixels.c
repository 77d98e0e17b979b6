/* t_drawpixels: glDrawPixels and glReadPixels (GL 1.5 sections 3.6, 4.3).
 *
 * - Formats and types: an RGBA image given as RGBA, BGRA, RGB, BGR,
 *   LUMINANCE(_ALPHA), RED, ALPHA in UNSIGNED_BYTE, UNSIGNED_SHORT, FLOAT and
 *   the packed types draws the colours the conversion rules give; the missing
 *   components become 0 (R, G, B) and 1 (A).
 * - glReadPixels packs the packed types and swaps bytes as asked.
 * - glPixelZoom: group (i, j) covers the pixels whose centres lie in
 *   [xr + zx i, xr + zx (i + 1)) x [yr + zy j, ...), also for negative zoom.
 * - Pixel transfer: scale and bias; MAP_COLOR; COLOR_INDEX through the
 *   I_TO_R/G/B/A maps (with GL_BITMAP); glGetPixelMap.
 * - DEPTH_COMPONENT writes depth through the depth test with the raster
 *   colour; STENCIL_INDEX writes stencil through the write mask; colour
 *   rectangles are depth tested at the raster z.
 * All expectations are computed from the spec's rules.
 *
 * Against Mesa 25 OSMesa (llvmpipe and softpipe) the rest passes, but Mesa
 * deviates from GL 1.5 here, and the spec wins:
 * - it rounds a fractional raster position before zooming (the (6.25, 3.75)
 *   zoom case lands a row/column off);
 * - with MAP_COLOR, blue and alpha come out of the wrong maps (B_TO_B and
 *   A_TO_A are not what it applies);
 * - glDrawPixels ignores INDEX_SHIFT / INDEX_OFFSET for COLOR_INDEX and
 *   MAP_STENCIL for STENCIL_INDEX.
 */
#define GL_GLEXT_PROTOTYPES 1
#include "harness.h"
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define W 40
#define H 24

static unsigned char px[W * H * 4];

/* A 4x3 RGBA test image with distinct, 5-6-5-friendly values. */
static const GLubyte img[3][4][4] = {
    {{255, 0, 0, 255}, {0, 255, 0, 128}, {0, 0, 255, 0}, {255, 255, 255, 255}},
    {{132, 68, 16, 64}, {0, 0, 0, 255}, {66, 130, 198, 32}, {255, 255, 0, 200}},
    {{8, 4, 8, 16}, {16, 36, 24, 96}, {255, 0, 255, 128}, {0, 255, 255, 4}},
};

static void clear(void)
{
    glClearColor(0, 0, 0, 0);
    glClearDepth(1);
    glClearStencil(0);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT | GL_STENCIL_BUFFER_BIT);
}

/* Pixel (x, y) must be (r, g, b, a) within tol. */
static void expect_px(int x, int y, const int e[4], int tol, const char *what)
{
    const unsigned char *p = &px[(y * W + x) * 4];
    int k;
    for (k = 0; k < 4; k++)
        if (abs(p[k] - e[k]) > tol) {
            h_expect(0, "%s: pixel (%d,%d) = %d,%d,%d,%d, expected %d,%d,%d,%d", what, x, y, p[0], p[1], p[2],
                     p[3], e[0], e[1], e[2], e[3]);
            return;
        }
}

static int q(int v, int bits)
{
    int m = (1 << bits) - 1;
    return (int)floor(floor(v * m / 255.0 + 0.5) * 255.0 / m + 0.5);
}

/* Draw img converted to `format`/`type` by the test itself, then check. */
static void format_case(GLenum format, GLenum type, const char *name)
{
    unsigned char buf[4 * 3 * 16];
    int i, j, k, n = 0, tol = 0;
    memset(buf, 0, sizeof buf);
    for (j = 0; j < 3; j++)
        for (i = 0; i < 4; i++) {
            const GLubyte *c = img[j][i];
            int l = c[0]; /* luminance draws use R as L */
            switch (format) {
            case GL_RGBA:
            case GL_BGRA:
            case GL_RGB:
            case GL_BGR: {
                int comps = (format == GL_RGB || format == GL_BGR) ? 3 : 4;
                int order[4];
                if (format == GL_BGRA || format == GL_BGR) {
                    order[0] = 2; order[1] = 1; order[2] = 0; order[3] = 3;
                } else {
                    order[0] = 0; order[1] = 1; order[2] = 2; order[3] = 3;
                }
                if (type == GL_UNSIGNED_BYTE) {
                    for (k = 0; k < comps; k++)
                        buf[n++] = c[order[k]];
                } else if (type == GL_UNSIGNED_SHORT) {
                    for (k = 0; k < comps; k++) {
                        GLushort v = (GLushort)(c[order[k]] * 257);
                        memcpy(buf + n, &v, 2);
                        n += 2;
                    }
                } else if (type == GL_FLOAT) {
                    for (k = 0; k < comps; k++) {
                        float v = c[order[k]] / 255.0f;
                        memcpy(buf + n, &v, 4);
                        n += 4;
                    }
                } else if (type == GL_UNSIGNED_SHORT_5_6_5) {
                    GLushort v = (GLushort)(((c[0] * 31 + 127) / 255) << 11 | ((c[1] * 63 + 127) / 255) << 5 |
                                            ((c[2] * 31 + 127) / 255));
                    memcpy(buf + n, &v, 2);
                    n += 2;
                } else if (type == GL_UNSIGNED_SHORT_4_4_4_4_REV) {
                    GLushort v = 0;
                    for (k = 0; k < 4; k++)
                        v |= (GLushort)(((c[order[k]] * 15 + 127) / 255) << (4 * k));
                    memcpy(buf + n, &v, 2);
                    n += 2;
                } else if (type == GL_UNSIGNED_INT_8_8_8_8) {
                    GLuint v = 0;
                    for (k = 0; k < 4; k++)
                        v |= (GLuint)c[order[k]] << (24 - 8 * k);
                    memcpy(buf + n, &v, 4);
                    n += 4;
                }
                break;
            }
            case GL_LUMINANCE: buf[n++] = (GLubyte)l; break;
            case GL_LUMINANCE_ALPHA: buf[n++] = (GLubyte)l; buf[n++] = c[3]; break;
            case GL_RED: buf[n++] = c[0]; break;
            case GL_ALPHA: buf[n++] = c[3]; break;
            }
        }
    clear();
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
    glWindowPos2i(3, 2);
    glDrawPixels(4, 3, format, type, buf);
    glPixelStorei(GL_UNPACK_ALIGNMENT, 4);
    h_expect_no_error(name);
    h_read(px);
    for (j = 0; j < 3; j++)
        for (i = 0; i < 4; i++) {
            const GLubyte *c = img[j][i];
            int e[4];
            switch (format) {
            case GL_LUMINANCE: e[0] = e[1] = e[2] = c[0]; e[3] = 255; break;
            case GL_LUMINANCE_ALPHA: e[0] = e[1] = e[2] = c[0]; e[3] = c[3]; break;
            case GL_RED: e[0] = c[0]; e[1] = e[2] = 0; e[3] = 255; break;
            case GL_ALPHA: e[0] = e[1] = e[2] = 0; e[3] = c[3]; break;
            default:
                for (k = 0; k < 4; k++)
                    e[k] = c[k];
                if (format == GL_RGB || format == GL_BGR)
                    e[3] = 255;
            }
            if (type == GL_UNSIGNED_SHORT_5_6_5) {
                e[0] = q(c[0], 5); e[1] = q(c[1], 6); e[2] = q(c[2], 5); e[3] = 255;
                tol = 1;
            }
            if (type == GL_UNSIGNED_SHORT_4_4_4_4_REV) {
                for (k = 0; k < 4; k++)
                    e[k] = q(c[k], 4);
                tol = 1;
            }
            expect_px(3 + i, 2 + j, e, tol, name);
        }
    /* Nothing outside the rectangle. */
    {
        static const int zero[4] = {0, 0, 0, 0};
        expect_px(2, 2, zero, 0, name);
        expect_px(7, 4, zero, 0, name);
        expect_px(3, 5, zero, 0, name);
    }
}

static void zoom_case(float xr, float yr, float zx, float zy)
{
    int x, y, i, j;
    char what[96];
    clear();
    glWindowPos2f(xr, yr);
    glPixelZoom(zx, zy);
    glDrawPixels(4, 3, GL_RGBA, GL_UNSIGNED_BYTE, img);
    glPixelZoom(1, 1);
    snprintf(what, sizeof what, "zoom (%g,%g) at (%g,%g)", zx, zy, xr, yr);
    h_read(px);
    for (y = 0; y < H; y++)
        for (x = 0; x < W; x++) {
            double cx = x + 0.5, cy = y + 0.5;
            int gi = -1, gj = -1, e[4] = {0, 0, 0, 0};
            for (i = 0; i < 4; i++) {
                double a = xr + zx * i, b = xr + zx * (i + 1);
                if (cx >= fmin(a, b) && cx < fmax(a, b))
                    gi = i;
            }
            for (j = 0; j < 3; j++) {
                double a = yr + zy * j, b = yr + zy * (j + 1);
                if (cy >= fmin(a, b) && cy < fmax(a, b))
                    gj = j;
            }
            if (gi >= 0 && gj >= 0) {
                const GLubyte *c = img[gj][gi];
                e[0] = c[0]; e[1] = c[1]; e[2] = c[2]; e[3] = c[3];
            }
            expect_px(x, y, e, 0, what);
        }
}

int main(void)
{
    int i;
    h_init(W, H);

    format_case(GL_RGBA, GL_UNSIGNED_BYTE, "RGBA/UNSIGNED_BYTE");
    format_case(GL_BGRA, GL_UNSIGNED_BYTE, "BGRA/UNSIGNED_BYTE");
    format_case(GL_RGB, GL_UNSIGNED_BYTE, "RGB/UNSIGNED_BYTE");
    format_case(GL_BGR, GL_UNSIGNED_BYTE, "BGR/UNSIGNED_BYTE");
    format_case(GL_RGBA, GL_UNSIGNED_SHORT, "RGBA/UNSIGNED_SHORT");
    format_case(GL_RGBA, GL_FLOAT, "RGBA/FLOAT");
    format_case(GL_BGR, GL_FLOAT, "BGR/FLOAT");
    format_case(GL_LUMINANCE, GL_UNSIGNED_BYTE, "LUMINANCE/UNSIGNED_BYTE");
    format_case(GL_LUMINANCE_ALPHA, GL_UNSIGNED_BYTE, "LUMINANCE_ALPHA/UNSIGNED_BYTE");
    format_case(GL_RED, GL_UNSIGNED_BYTE, "RED/UNSIGNED_BYTE");
    format_case(GL_ALPHA, GL_UNSIGNED_BYTE, "ALPHA/UNSIGNED_BYTE");
    format_case(GL_RGB, GL_UNSIGNED_SHORT_5_6_5, "RGB/UNSIGNED_SHORT_5_6_5");
    format_case(GL_BGRA, GL_UNSIGNED_SHORT_4_4_4_4_REV, "BGRA/UNSIGNED_SHORT_4_4_4_4_REV");
    format_case(GL_RGBA, GL_UNSIGNED_INT_8_8_8_8, "RGBA/UNSIGNED_INT_8_8_8_8");

    /* glReadPixels of packed types and swapped shorts. */
    clear();
    glWindowPos2i(0, 0);
    glDrawPixels(4, 3, GL_RGBA, GL_UNSIGNED_BYTE, img);
    {
        GLushort s[4];
        GLuint u[4];
        GLubyte b[8];
        glReadPixels(0, 0, 1, 1, GL_RGB, GL_UNSIGNED_SHORT_5_6_5, s);
        h_expect(s[0] == 0xF800, "red as 5_6_5: %#x, expected 0xf800", s[0]);
        glReadPixels(1, 0, 1, 1, GL_BGRA, GL_UNSIGNED_INT_8_8_8_8_REV, u);
        h_expect(u[0] == 0x8000FF00u, "(0,255,0,128) as BGRA 8_8_8_8_REV: %#x, expected 0x8000ff00", u[0]);
        glReadPixels(2, 0, 1, 1, GL_RGBA, GL_UNSIGNED_INT_8_8_8_8, u);
        h_expect(u[0] == 0x0000FF00u, "(0,0,255,0) as RGBA 8_8_8_8: %#x, expected 0x0000ff00", u[0]);
        glReadPixels(3, 0, 1, 1, GL_RGBA, GL_UNSIGNED_SHORT_5_5_5_1, s);
        h_expect(s[0] == 0xFFFF, "white as 5_5_5_1: %#x", s[0]);
        glPixelStorei(GL_PACK_SWAP_BYTES, GL_TRUE);
        glReadPixels(0, 1, 1, 1, GL_RED, GL_UNSIGNED_SHORT, b);
        glPixelStorei(GL_PACK_SWAP_BYTES, GL_FALSE);
        h_expect(b[0] == 0x84 && b[1] == 0x84, "swapped short 132*257: %02x %02x", b[0], b[1]);
        glReadPixels(0, 0, 1, 1, GL_RGB, GL_UNSIGNED_BYTE_3_3_2, b);
        h_expect(b[0] == 0xE0, "red as 3_3_2: %#x, expected 0xe0", b[0]);
    }

    /* Zoom. */
    zoom_case(5, 4, 1, 1);
    zoom_case(5, 4, 3, 2);
    zoom_case(6, 3, 2.2f, 1.3f);
    zoom_case(30, 20, -2, -3);
    zoom_case(20, 4, -1, 4);
    zoom_case(2, 2, 0.4f, 0.6f);
    zoom_case(25, 20, -1.3f, -0.6f);
    /* Fractional raster position (Mesa rounds it first). */
    zoom_case(6.25f, 3.75f, 2.5f, 1.5f);

    /* Scale and bias. */
    clear();
    glPixelTransferf(GL_RED_SCALE, 0.5f);
    glPixelTransferf(GL_BLUE_BIAS, 0.25f);
    glWindowPos2i(0, 0);
    glDrawPixels(4, 3, GL_RGBA, GL_UNSIGNED_BYTE, img);
    glPixelTransferf(GL_RED_SCALE, 1);
    glPixelTransferf(GL_BLUE_BIAS, 0);
    h_read(px);
    {
        static const int e0[4] = {128, 0, 64, 255}, e1[4] = {66, 68, 80, 64};
        expect_px(0, 0, e0, 1, "RED_SCALE 0.5, BLUE_BIAS 0.25, red");
        expect_px(0, 1, e1, 1, "RED_SCALE 0.5, BLUE_BIAS 0.25, (132,68,16)");
    }

    /* MAP_COLOR: R_TO_R inverts (size 256); other maps: identity of size 2. */
    {
        GLfloat inv[256], id[2] = {0, 1}, got[256];
        GLushort us[2];
        for (i = 0; i < 256; i++)
            inv[i] = 1.0f - i / 255.0f;
        glPixelMapfv(GL_PIXEL_MAP_R_TO_R, 256, inv);
        glPixelMapfv(GL_PIXEL_MAP_G_TO_G, 2, id);
        glPixelMapfv(GL_PIXEL_MAP_B_TO_B, 2, id);
        glPixelMapfv(GL_PIXEL_MAP_A_TO_A, 2, id);
        glPixelTransferi(GL_MAP_COLOR, GL_TRUE);
        clear();
        glWindowPos2i(0, 0);
        glDrawPixels(4, 3, GL_RGBA, GL_UNSIGNED_BYTE, img);
        glPixelTransferi(GL_MAP_COLOR, GL_FALSE);
        h_read(px);
        {
            static const int e0[4] = {0, 0, 0, 255}, e1[4] = {123, 0, 0, 0};
            expect_px(0, 0, e0, 0, "MAP_COLOR red");
            expect_px(0, 1, e1, 0, "MAP_COLOR (132,68,16,64)");
        }
        glGetPixelMapfv(GL_PIXEL_MAP_R_TO_R, got);
        h_expect(got[0] == 1.0f && got[255] == 0.0f, "glGetPixelMapfv R_TO_R %g..%g", got[0], got[255]);
        glGetPixelMapusv(GL_PIXEL_MAP_G_TO_G, us);
        h_expect(us[0] == 0 && us[1] == 65535, "glGetPixelMapusv G_TO_G %u %u", us[0], us[1]);
        glGetIntegerv(GL_PIXEL_MAP_R_TO_R_SIZE, &i);
        h_expect(i == 256, "GL_PIXEL_MAP_R_TO_R_SIZE %d", i);
        glPixelMapfv(GL_PIXEL_MAP_I_TO_R, 3, inv);
        h_expect_error(GL_INVALID_VALUE, "I_TO_R of size 3");
    }

    /* COLOR_INDEX through I_TO_R/G/B/A, with shift and offset and as GL_BITMAP. */
    {
        GLuint r[4] = {0, 0xFFFFFFFFu, 0, 0x80000000u}, g[4] = {0, 0, 0xFFFFFFFFu, 0xFFFFFFFFu};
        GLushort b[1] = {65535}, a[2] = {65535, 65535};
        GLubyte idx[3] = {0, 1, 2}, bits[1] = {0xA0};
        glPixelMapuiv(GL_PIXEL_MAP_I_TO_R, 4, r);
        glPixelMapuiv(GL_PIXEL_MAP_I_TO_G, 4, g);
        glPixelMapusv(GL_PIXEL_MAP_I_TO_B, 1, b);
        glPixelMapusv(GL_PIXEL_MAP_I_TO_A, 2, a);
        clear();
        glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
        glWindowPos2i(0, 2);
        glDrawPixels(3, 1, GL_COLOR_INDEX, GL_UNSIGNED_BYTE, idx); /* no shift: 0, 1, 2 */
        h_read(px);
        {
            static const int i0[4] = {0, 0, 255, 255}, i1[4] = {255, 0, 255, 255}, i2[4] = {0, 255, 255, 255};
            expect_px(0, 2, i0, 1, "index 0");
            expect_px(1, 2, i1, 1, "index 1");
            expect_px(2, 2, i2, 1, "index 2");
        }
        glPixelTransferi(GL_INDEX_SHIFT, 1);
        glPixelTransferi(GL_INDEX_OFFSET, 1);
        glWindowPos2i(0, 0);
        glDrawPixels(3, 1, GL_COLOR_INDEX, GL_UNSIGNED_BYTE, idx); /* -> 1, 3, 5 & 3 = 1 */
        glWindowPos2i(0, 1);
        glDrawPixels(3, 1, GL_COLOR_INDEX, GL_BITMAP, bits); /* 1 0 1 -> 3, 1, 3 */
        glPixelTransferi(GL_INDEX_SHIFT, 0);
        glPixelTransferi(GL_INDEX_OFFSET, 0);
        h_read(px);
        {
            static const int i1[4] = {255, 0, 255, 255}, i3[4] = {128, 255, 255, 255};
            expect_px(0, 0, i1, 1, "index 0 -> 1");
            expect_px(1, 0, i3, 1, "index 1 -> 3");
            expect_px(2, 0, i1, 1, "index 2 -> 5 & 3");
            expect_px(0, 1, i3, 1, "bitmap index 1 -> 3");
            expect_px(1, 1, i1, 1, "bitmap index 0 -> 1");
        }
        glPixelStorei(GL_UNPACK_ALIGNMENT, 4);
    }

    /* Depth: DEPTH_COMPONENT fragments take the raster colour. */
    {
        float dv[4] = {0.25f, 0.75f, 0.5f, 0.0f}, rd[4];
        clear();
        glEnable(GL_DEPTH_TEST);
        glDepthFunc(GL_LESS);
        glColor3f(0, 1, 0);
        glWindowPos2i(0, 0);
        glDrawPixels(4, 1, GL_DEPTH_COMPONENT, GL_FLOAT, dv);
        glReadPixels(0, 0, 4, 1, GL_DEPTH_COMPONENT, GL_FLOAT, rd);
        for (i = 0; i < 4; i++)
            h_expect(fabsf(rd[i] - dv[i]) < 1e-6f, "depth %d: %g, expected %g", i, rd[i], dv[i]);
        h_expect_pixel(1, 0, 0, 255, 0, 255, 0, "depth fragment takes the raster colour");
        /* A colour rectangle at raster z 0.5 passes where depth > 0.5 only. */
        glWindowPos3f(0, 0, 0.5f);
        glDrawPixels(4, 1, GL_RGBA, GL_UNSIGNED_BYTE, img);
        h_expect_pixel(0, 0, 0, 255, 0, 255, 0, "0.5 < 0.25 fails");
        h_expect_pixel(1, 0, 0, 255, 0, 128, 0, "0.5 < 0.75 passes");
        h_expect_pixel(2, 0, 0, 255, 0, 255, 0, "0.5 < 0.5 fails");
        glDisable(GL_DEPTH_TEST);
    }

    /* Stencil: written through the write mask; MAP_STENCIL. */
    {
        GLubyte sv[4] = {1, 2, 0x7F, 0xFF}, rs[4];
        GLuint smap[2] = {5, 9};
        clear();
        glStencilMask(0x0F);
        glWindowPos2i(0, 0);
        glDrawPixels(4, 1, GL_STENCIL_INDEX, GL_UNSIGNED_BYTE, sv);
        glStencilMask(0xFF);
        glReadPixels(0, 0, 4, 1, GL_STENCIL_INDEX, GL_UNSIGNED_BYTE, rs);
        h_expect(rs[0] == 1 && rs[1] == 2 && rs[2] == 0x0F && rs[3] == 0x0F, "stencil through mask 0x0f: %d %d %d %d",
                 rs[0], rs[1], rs[2], rs[3]);
        glPixelMapuiv(GL_PIXEL_MAP_S_TO_S, 2, smap);
        glPixelTransferi(GL_MAP_STENCIL, GL_TRUE);
        glDrawPixels(4, 1, GL_STENCIL_INDEX, GL_UNSIGNED_BYTE, sv);
        glPixelTransferi(GL_MAP_STENCIL, GL_FALSE);
        glReadPixels(0, 0, 4, 1, GL_STENCIL_INDEX, GL_UNSIGNED_BYTE, rs);
        h_expect(rs[0] == 9 && rs[1] == 5 && rs[2] == 9 && rs[3] == 9, "MAP_STENCIL: %d %d %d %d", rs[0], rs[1], rs[2],
                 rs[3]);
    }

    /* RGBA / UNSIGNED_BYTE through the entry point in every mode (softgl
     * draws such images from the client's memory outside list compilation):
     * a list keeps the image as it was at glNewList time; GL_COMPILE draws
     * nothing; GL_COMPILE_AND_EXECUTE draws at once; feedback records a
     * DRAW_PIXEL_TOKEN and draws nothing; inside glBegin it is an error. */
    {
        GLubyte copy[3][4][4];
        GLfloat fb[8];
        GLuint lists = glGenLists(2);
        static const int red[4] = {255, 0, 0, 255}, none[4] = {0, 0, 0, 0}, grey[4] = {7, 7, 7, 7};
        memcpy(copy, img, sizeof copy);
        clear();
        glWindowPos2i(0, 0);
        glNewList(lists, GL_COMPILE);
        glDrawPixels(4, 3, GL_RGBA, GL_UNSIGNED_BYTE, copy);
        glEndList();
        h_read(px);
        expect_px(0, 0, none, 0, "glDrawPixels compiled (GL_COMPILE) draws nothing");
        glWindowPos2i(10, 0);
        glNewList(lists + 1, GL_COMPILE_AND_EXECUTE);
        glDrawPixels(4, 3, GL_RGBA, GL_UNSIGNED_BYTE, copy);
        glEndList();
        h_read(px);
        expect_px(10, 0, red, 0, "glDrawPixels under GL_COMPILE_AND_EXECUTE draws at once");
        memset(copy, 7, sizeof copy);
        clear();
        glWindowPos2i(0, 0);
        glCallList(lists);
        glWindowPos2i(10, 0);
        glCallList(lists + 1);
        h_read(px);
        expect_px(0, 0, red, 0, "a list's glDrawPixels keeps the image of its compilation");
        expect_px(10, 0, red, 0, "a list's glDrawPixels (COMPILE_AND_EXECUTE) keeps its image");
        glWindowPos2i(20, 0);
        glDrawPixels(4, 3, GL_RGBA, GL_UNSIGNED_BYTE, copy);
        h_read(px);
        expect_px(20, 0, grey, 0, "glDrawPixels draws the client's current image");
        glDeleteLists(lists, 2);

        clear();
        glFeedbackBuffer(8, GL_2D, fb);
        glRenderMode(GL_FEEDBACK);
        glWindowPos2i(3, 2);
        glDrawPixels(4, 3, GL_RGBA, GL_UNSIGNED_BYTE, img);
        i = glRenderMode(GL_RENDER);
        h_expect(i == 3 && fb[0] == GL_DRAW_PIXEL_TOKEN && fb[1] == 3 && fb[2] == 2, "feedback of glDrawPixels: %d values, %g %g %g",
                 i, fb[0], fb[1], fb[2]);
        h_read(px);
        expect_px(3, 2, none, 0, "glDrawPixels in feedback mode draws nothing");

        glBegin(GL_POINTS);
        glDrawPixels(4, 3, GL_RGBA, GL_UNSIGNED_BYTE, img);
        glEnd();
        h_expect_error(GL_INVALID_OPERATION, "glDrawPixels between glBegin and glEnd");
        h_read(px);
        expect_px(3, 2, none, 0, "glDrawPixels between glBegin and glEnd draws nothing");
    }

    /* Errors. */
    glDrawPixels(1, 1, GL_RGBA, GL_BITMAP, img);
    h_expect_error(GL_INVALID_ENUM, "RGBA with GL_BITMAP");
    glDrawPixels(1, 1, GL_BGR, GL_UNSIGNED_SHORT_5_6_5, img);
    h_expect_error(GL_INVALID_OPERATION, "BGR with 5_6_5");
    glDrawPixels(-1, 1, GL_RGBA, GL_UNSIGNED_BYTE, img);
    h_expect_error(GL_INVALID_VALUE, "negative width");

    h_expect_no_error("end");
    return h_finish();
}
