/* t_teximage_formats: texture internal formats keep at least their nominal
 * precision (GL 1.5 section 3.8.1, table 3.16), as piglit's teximage-colors
 * checks them (that test itself needs GLSL, so it skips on GL 1.5).
 *
 * - Exact round trips: a pseudo-random 7x5 image uploaded with the format's
 *   own client format and type (UNPACK_ALIGNMENT 1) comes back byte for
 *   byte from glGetTexImage with the same format and type (the
 *   teximage-colors "Exact upload-download" subtests: R8, RG16, R3_G3_B2
 *   with 3_3_2, RGBA2 and RGBA4 with 4_4_4_4, RGB5_A1, RGB10_A2, RGBA16,
 *   ALPHA16, LUMINANCE16_ALPHA16, RGBA32F...).
 * - Nominal precision of the formats without an exact type (RGB4, RGB5,
 *   RGB10, RGB12, RGBA12, ALPHA4/12, LUMINANCE4/12, the luminance-alpha
 *   ones): every value k / (2^b - 1) of a b-bit component, given as
 *   UNSIGNED_SHORT, reads back (as UNSIGNED_SHORT) within half a step of
 *   b bits.
 * - EXT_abgr: ABGR_EXT bytes unpack and pack in the order A, B, G, R.
 * - Drawn with GL_REPLACE, an RGB10_A2 texture given as UNSIGNED_BYTE comes
 *   out as the bytes given (the teximage-colors draw check, 8-bit window).
 */
#include "harness.h"
#include <stdio.h>
#include <string.h>

#ifndef GL_R8
#define GL_RED_ 0x1903
#define GL_RG 0x8227
#define GL_R8 0x8229
#define GL_R16 0x822A
#define GL_RG8 0x822B
#define GL_RG16 0x822C
#endif
#ifndef GL_ABGR_EXT
#define GL_ABGR_EXT 0x8000
#endif
#ifndef GL_RGBA32F_ARB
#define GL_RGBA32F_ARB 0x8814
#define GL_RGB32F_ARB 0x8815
#endif

#define W 7
#define H 5

static unsigned seed = 12345;
static unsigned char next_byte(void)
{
    seed = seed * 1103515245u + 12345u;
    return (unsigned char)(seed >> 16);
}

struct exact { GLenum ifmt, format, type; int bpp; const char *name; };

static void exact_round_trips(void)
{
    static const struct exact cases[] = {
        {GL_R8, GL_RED, GL_UNSIGNED_BYTE, 1, "R8"},
        {GL_R16, GL_RED, GL_UNSIGNED_SHORT, 2, "R16"},
        {GL_RG8, GL_RG, GL_UNSIGNED_BYTE, 2, "RG8"},
        {GL_RG16, GL_RG, GL_UNSIGNED_SHORT, 4, "RG16"},
        {GL_R3_G3_B2, GL_RGB, GL_UNSIGNED_BYTE_3_3_2, 1, "R3_G3_B2"},
        {GL_RGB8, GL_RGB, GL_UNSIGNED_BYTE, 3, "RGB8"},
        {GL_RGB16, GL_RGB, GL_UNSIGNED_SHORT, 6, "RGB16"},
        {GL_RGBA2, GL_RGBA, GL_UNSIGNED_SHORT_4_4_4_4, 2, "RGBA2"},
        {GL_RGBA4, GL_RGBA, GL_UNSIGNED_SHORT_4_4_4_4, 2, "RGBA4"},
        {GL_RGB5_A1, GL_RGBA, GL_UNSIGNED_SHORT_5_5_5_1, 2, "RGB5_A1"},
        {GL_RGBA8, GL_RGBA, GL_UNSIGNED_BYTE, 4, "RGBA8"},
        {GL_RGB10_A2, GL_RGBA, GL_UNSIGNED_INT_10_10_10_2, 4, "RGB10_A2"},
        {GL_RGBA16, GL_RGBA, GL_UNSIGNED_SHORT, 8, "RGBA16"},
        {GL_ALPHA8, GL_ALPHA, GL_UNSIGNED_BYTE, 1, "ALPHA8"},
        {GL_ALPHA16, GL_ALPHA, GL_UNSIGNED_SHORT, 2, "ALPHA16"},
        {GL_LUMINANCE8, GL_LUMINANCE, GL_UNSIGNED_BYTE, 1, "LUMINANCE8"},
        {GL_LUMINANCE16, GL_LUMINANCE, GL_UNSIGNED_SHORT, 2, "LUMINANCE16"},
        {GL_LUMINANCE8_ALPHA8, GL_LUMINANCE_ALPHA, GL_UNSIGNED_BYTE, 2, "LUMINANCE8_ALPHA8"},
        {GL_LUMINANCE16_ALPHA16, GL_LUMINANCE_ALPHA, GL_UNSIGNED_SHORT, 4, "LUMINANCE16_ALPHA16"},
        {GL_RGB32F_ARB, GL_RGB, GL_FLOAT, 12, "RGB32F"},
        {GL_RGBA32F_ARB, GL_RGBA, GL_FLOAT, 16, "RGBA32F"},
    };
    unsigned char in[W * H * 16], out[W * H * 16];
    size_t c;
    int i;
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
    glPixelStorei(GL_PACK_ALIGNMENT, 1);
    for (c = 0; c < sizeof cases / sizeof cases[0]; c++) {
        const struct exact *e = &cases[c];
        int n = W * H * e->bpp;
        if (e->type == GL_FLOAT) {
            float *f = (float *)in;
            for (i = 0; i < n / 4; i++)
                f[i] = (float)(next_byte() - 128) / 37.0f;
        } else {
            for (i = 0; i < n; i++)
                in[i] = next_byte();
        }
        memset(out, 0xEE, sizeof out);
        glTexImage2D(GL_TEXTURE_2D, 0, e->ifmt, W, H, 0, e->format, e->type, in);
        h_expect_no_error(e->name);
        glGetTexImage(GL_TEXTURE_2D, 0, e->format, e->type, out);
        h_expect_no_error(e->name);
        for (i = 0; i < n && in[i] == out[i]; i++)
            ;
        h_expect(i == n, "%s: exact round trip, first difference at byte %d: %d, got %d", e->name, i, i < n ? in[i] : 0, i < n ? out[i] : 0);
    }
}

struct nominal { GLenum ifmt, format; int comps, bits[2]; const char *name; };

static void nominal_precision(void)
{
    static const struct nominal cases[] = {
        {GL_RGB4, GL_RGB, 3, {4, 4}, "RGB4"},
        {GL_RGB5, GL_RGB, 3, {5, 5}, "RGB5"},
        {GL_RGB10, GL_RGB, 3, {10, 10}, "RGB10"},
        {GL_RGB12, GL_RGB, 3, {12, 12}, "RGB12"},
        {GL_RGBA12, GL_RGBA, 4, {12, 12}, "RGBA12"},
        {GL_ALPHA4, GL_ALPHA, 1, {4, 4}, "ALPHA4"},
        {GL_ALPHA12, GL_ALPHA, 1, {12, 12}, "ALPHA12"},
        {GL_LUMINANCE4, GL_LUMINANCE, 1, {4, 4}, "LUMINANCE4"},
        {GL_LUMINANCE12, GL_LUMINANCE, 1, {12, 12}, "LUMINANCE12"},
        {GL_INTENSITY4, GL_LUMINANCE, 1, {4, 4}, "INTENSITY4"},
        {GL_INTENSITY12, GL_LUMINANCE, 1, {12, 12}, "INTENSITY12"},
        {GL_INTENSITY16, GL_LUMINANCE, 1, {16, 16}, "INTENSITY16"},
        {GL_LUMINANCE4_ALPHA4, GL_LUMINANCE_ALPHA, 2, {4, 4}, "LUMINANCE4_ALPHA4"},
        {GL_LUMINANCE6_ALPHA2, GL_LUMINANCE_ALPHA, 2, {6, 2}, "LUMINANCE6_ALPHA2"},
        {GL_LUMINANCE12_ALPHA4, GL_LUMINANCE_ALPHA, 2, {12, 4}, "LUMINANCE12_ALPHA4"},
        {GL_LUMINANCE12_ALPHA12, GL_LUMINANCE_ALPHA, 2, {12, 12}, "LUMINANCE12_ALPHA12"},
    };
    /* 4096 texels: every 12-bit value once per component (fewer bits: each
     * value repeated). */
    static unsigned short in[4096 * 4], out[4096 * 4];
    size_t c;
    int i, k;
    for (c = 0; c < sizeof cases / sizeof cases[0]; c++) {
        const struct nominal *e = &cases[c];
        int worst = 0, at = -1;
        for (i = 0; i < 4096; i++) {
            for (k = 0; k < e->comps; k++) {
                int b = e->bits[k == e->comps - 1 && e->comps > 1 ? 1 : 0];
                unsigned max = (1u << b) - 1;
                /* value (i + 97 k) mod 2^b of b bits, as 16 bits */
                unsigned v = (unsigned)((i + 97 * k) % (max + 1));
                in[i * e->comps + k] = (unsigned short)((v * 65535u + max / 2) / max);
            }
        }
        glTexImage2D(GL_TEXTURE_2D, 0, e->ifmt, 64, 64, 0, e->format, GL_UNSIGNED_SHORT, in);
        memset(out, 0, sizeof out);
        glGetTexImage(GL_TEXTURE_2D, 0, e->format, GL_UNSIGNED_SHORT, out);
        h_expect_no_error(e->name);
        for (i = 0; i < 4096 * e->comps; i++) {
            int k2 = i % e->comps;
            int b = e->bits[k2 == e->comps - 1 && e->comps > 1 ? 1 : 0];
            /* half a step of b bits, in 16-bit units */
            int tol = (int)(65535.0 / ((1u << b) - 1) / 2.0);
            int d = (int)in[i] - (int)out[i];
            if (d < 0)
                d = -d;
            if (d - tol > worst) {
                worst = d - tol;
                at = i;
            }
        }
        h_expect(worst == 0, "%s: a component is off by more than half a step of its bits at %d (%d, got %d)",
                 e->name, at, at >= 0 ? in[at] : 0, at >= 0 ? out[at] : 0);
    }
}

static void drawn(void)
{
    unsigned char in[8 * 8 * 4];
    int i, x, y;
    for (i = 0; i < 8 * 8 * 4; i++)
        in[i] = next_byte();
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGB10_A2, 8, 8, 0, GL_RGBA, GL_UNSIGNED_BYTE, in);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_REPLACE);
    glEnable(GL_TEXTURE_2D);
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    glOrtho(0, 8, 0, 8, -1, 1);
    glBegin(GL_QUADS);
    glTexCoord2f(0, 0); glVertex2f(0, 0);
    glTexCoord2f(1, 0); glVertex2f(8, 0);
    glTexCoord2f(1, 1); glVertex2f(8, 8);
    glTexCoord2f(0, 1); glVertex2f(0, 8);
    glEnd();
    glDisable(GL_TEXTURE_2D);
    {
        unsigned char px[8 * 8 * 4];
        int bad = 0;
        glReadPixels(0, 0, 8, 8, GL_RGBA, GL_UNSIGNED_BYTE, px);
        for (y = 0; y < 8; y++)
            for (x = 0; x < 8; x++) {
                const unsigned char *p = in + (y * 8 + x) * 4, *q = px + (y * 8 + x) * 4;
                /* Alpha: the byte, or (if stored at the nominal 2 bits) its
                 * nearest of 0, 85, 170, 255. */
                int a2 = (p[3] * 3 + 127) / 255 * 85;
                for (i = 0; i < 3; i++)
                    bad += q[i] != p[i];
                bad += q[3] != p[3] && q[3] != a2;
            }
        h_expect(bad == 0, "RGB10_A2 texels drawn with REPLACE: %d components differ from the bytes given", bad);
    }
}

/* EXT_abgr: ABGR_EXT bytes are A, B, G, R, in and out. */
static void abgr(void)
{
    static const unsigned char in[2 * 4] = {10, 20, 30, 40, 50, 60, 70, 80};
    unsigned char out[2 * 4], back[2 * 4];
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, 2, 1, 0, GL_ABGR_EXT, GL_UNSIGNED_BYTE, in);
    h_expect_no_error("glTexImage2D with ABGR_EXT");
    glGetTexImage(GL_TEXTURE_2D, 0, GL_RGBA, GL_UNSIGNED_BYTE, out);
    h_expect(out[0] == 40 && out[1] == 30 && out[2] == 20 && out[3] == 10 && out[4] == 80, "ABGR_EXT unpacked as R %d G %d B %d A %d", out[0], out[1], out[2], out[3]);
    glGetTexImage(GL_TEXTURE_2D, 0, GL_ABGR_EXT, GL_UNSIGNED_BYTE, back);
    h_expect(memcmp(back, in, sizeof in) == 0, "ABGR_EXT packed back: %d %d %d %d", back[0], back[1], back[2], back[3]);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, 2, 1, 0, GL_ABGR_EXT, GL_UNSIGNED_SHORT_4_4_4_4, in);
    h_expect_error(GL_INVALID_OPERATION, "ABGR_EXT with a packed type");
}

int main(void)
{
    GLuint tex;
    h_init(8, 8);
    glGenTextures(1, &tex);
    glBindTexture(GL_TEXTURE_2D, tex);
    exact_round_trips();
    abgr();
    nominal_precision();
    drawn();
    return h_finish();
}
