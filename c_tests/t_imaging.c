/* t_imaging.c - the ARB_imaging subset and ARB_texture_rectangle through
 * the C ABI: a colour table, a 2D convolution, the colour matrix and a
 * histogram applied by glDrawPixels, glGetColorTable/glGetHistogram, and a
 * rectangle texture sampled with texel coordinates. Expected values are
 * computed by hand in the comments. */
#include "harness.h"
#include <string.h>

static int has_extension(const char *name)
{
    const char *s = (const char *)glGetString(GL_EXTENSIONS);
    size_t n = strlen(name);
    while (s && *s) {
        const char *e = strchr(s, ' ');
        size_t len = e ? (size_t)(e - s) : strlen(s);
        if (len == n && strncmp(s, name, n) == 0)
            return 1;
        s = e ? e + 1 : s + len;
    }
    return 0;
}

int main(void)
{
    h_init(8, 8);
    h_expect(has_extension("GL_ARB_imaging"), "GL_ARB_imaging advertised");
    h_expect(has_extension("GL_ARB_texture_rectangle"), "GL_ARB_texture_rectangle advertised");
    glClearColor(0, 0, 0, 1);
    glClear(GL_COLOR_BUFFER_BIT);
    glWindowPos2i(0, 0);

    /* A 2-entry RGB table that inverts: entry 0 = 1, entry 1 = 0. */
    static const GLubyte table[2][3] = {{255, 255, 255}, {0, 0, 0}};
    glColorTable(GL_COLOR_TABLE, GL_RGB, 2, GL_RGB, GL_UNSIGNED_BYTE, table);
    glEnable(GL_COLOR_TABLE);
    static const GLubyte one[4] = {200, 40, 255, 77};
    glDrawPixels(1, 1, GL_RGBA, GL_UNSIGNED_BYTE, one);
    /* (glReadPixels goes through the same stages: off before reading.) */
    glDisable(GL_COLOR_TABLE);
    /* R 200/255 -> index 1 -> 0; G -> 1 -> 255; B -> 0; A unchanged. */
    h_expect_pixel(0, 0, 0, 255, 0, 77, 0, "colour table");
    GLubyte back[2][4];
    glGetColorTable(GL_COLOR_TABLE, GL_RGBA, GL_UNSIGNED_BYTE, back);
    h_expect(back[0][0] == 255 && back[1][0] == 0 && back[0][3] == 255, "glGetColorTable");

    /* A 3x3 box convolution of a 3x3 image with one white pixel in the
     * middle, REDUCE: one pixel, 255 / 9 = 28.3 -> 28. */
    GLfloat box[9];
    for (int i = 0; i < 9; i++)
        box[i] = 1.0f / 9.0f;
    glConvolutionFilter2D(GL_CONVOLUTION_2D, GL_LUMINANCE, 3, 3, GL_LUMINANCE, GL_FLOAT, box);
    glEnable(GL_CONVOLUTION_2D);
    GLubyte img[9] = {0, 0, 0, 0, 255, 0, 0, 0, 0};
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1); /* rows of 3 bytes */
    glWindowPos2i(2, 0);
    glDrawPixels(3, 3, GL_LUMINANCE, GL_UNSIGNED_BYTE, img);
    glDisable(GL_CONVOLUTION_2D);
    h_expect_pixel(2, 0, 28, 28, 28, 255, 1, "convolution");
    h_expect_pixel(3, 0, 0, 0, 0, 255, 0, "REDUCE drew one pixel");
    GLint w = 0;
    glGetConvolutionParameteriv(GL_CONVOLUTION_2D, GL_CONVOLUTION_WIDTH, &w);
    h_expect(w == 3, "CONVOLUTION_WIDTH %d", w);

    /* The colour matrix swaps red and blue. */
    static const GLfloat swap[16] = {0, 0, 1, 0, 0, 1, 0, 0, 1, 0, 0, 0, 0, 0, 0, 1};
    glMatrixMode(GL_COLOR);
    glLoadMatrixf(swap);
    glMatrixMode(GL_MODELVIEW);
    glWindowPos2i(5, 0);
    static const GLubyte red[4] = {255, 0, 0, 255};
    glDrawPixels(1, 1, GL_RGBA, GL_UNSIGNED_BYTE, red);
    glMatrixMode(GL_COLOR);
    glLoadIdentity();
    glMatrixMode(GL_MODELVIEW);
    h_expect_pixel(5, 0, 0, 0, 255, 255, 0, "colour matrix");

    /* A sink histogram of 4 bins counts and draws nothing. */
    glHistogram(GL_HISTOGRAM, 4, GL_LUMINANCE, GL_TRUE);
    glEnable(GL_HISTOGRAM);
    static const GLubyte lum[3] = {0, 128, 255};
    glWindowPos2i(0, 4);
    glDrawPixels(3, 1, GL_LUMINANCE, GL_UNSIGNED_BYTE, lum);
    glDisable(GL_HISTOGRAM);
    h_expect_pixel(1, 4, 0, 0, 0, 255, 0, "sink: nothing drawn");
    GLuint counts[4];
    glGetHistogram(GL_HISTOGRAM, GL_TRUE, GL_LUMINANCE, GL_UNSIGNED_INT, counts);
    /* 0 -> bin 0; 128/255 * 3 = 1.506 -> bin 2; 1 -> bin 3. */
    h_expect(counts[0] == 1 && counts[1] == 0 && counts[2] == 1 && counts[3] == 1,
             "histogram %u %u %u %u", counts[0], counts[1], counts[2], counts[3]);
    /* A proxy table runs at once, even while a list is compiled. */
    GLuint list = glGenLists(1);
    glNewList(list, GL_COMPILE);
    glColorTable(GL_PROXY_COLOR_TABLE, GL_RGBA8, 64, GL_RGBA, GL_UNSIGNED_BYTE, NULL);
    glEndList();
    GLint pw = 0;
    glGetColorTableParameteriv(GL_PROXY_COLOR_TABLE, GL_COLOR_TABLE_WIDTH, &pw);
    h_expect(pw == 64, "proxy table width %d", pw);
    h_expect_no_error("imaging");

    /* A 2x1 rectangle texture, nearest, sampled at s = 1.5: texel 1. */
    static const GLubyte rect[2][4] = {{255, 0, 0, 255}, {0, 255, 0, 255}};
    glBindTexture(GL_TEXTURE_RECTANGLE_ARB, 1);
    glTexImage2D(GL_TEXTURE_RECTANGLE_ARB, 0, GL_RGBA8, 2, 1, 0, GL_RGBA, GL_UNSIGNED_BYTE, rect);
    glTexParameteri(GL_TEXTURE_RECTANGLE_ARB, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    glTexParameteri(GL_TEXTURE_RECTANGLE_ARB, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_REPLACE);
    glEnable(GL_TEXTURE_RECTANGLE_ARB);
    glTexCoord2f(1.5f, 0.5f);
    glBegin(GL_POINTS);
    glVertex2f(0.0f, 0.5f); /* window (4.5, 6.5) of 8x8 */
    glEnd();
    h_expect_pixel(4, 6, 0, 255, 0, 255, 0, "rectangle texel 1");
    glTexParameteri(GL_TEXTURE_RECTANGLE_ARB, GL_TEXTURE_WRAP_S, GL_REPEAT);
    h_expect_error(GL_INVALID_ENUM, "REPEAT on a rectangle");
    GLint max = 0;
    glGetIntegerv(GL_MAX_RECTANGLE_TEXTURE_SIZE_ARB, &max);
    h_expect(max >= 1024, "MAX_RECTANGLE_TEXTURE_SIZE %d", max);
    return h_finish();
}
