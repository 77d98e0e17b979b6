/* t_book_s3_text: the Russian textbook's chapter 9, text through
 * wglUseFontBitmaps (seeds-inventory §3.5 F18, F19; §4).
 *
 * BOOK: S3, Russian OpenGL textbook, ch. 9 "Text output", fragments F18 (system font, lists 1..255) and F19 (CreateFont("Courier", 36, FW_BOLD), glPrintText with glListBase(base-32))
 * SHOWS: "Привет OpenGL !!!" in the system font, WHITE on the first frame and yellow on the second (the colour is set after glRasterPos, so the raster colour latched is the previous one); the bold 36-pixel string, yellow only from the second frame on; nothing at all under a perspective projection (the raster position is invalid)
 * FEATURES: wglUseFontBitmaps over softglCreateDC/softglSelectFont (the built-in CP1251 fonts), glCallLists(GL_UNSIGNED_BYTE), glListBase, glPushAttrib(GL_LIST_BIT), glGenLists/glDeleteLists, glRasterPos2i and the latched raster colour, GL_CURRENT_RASTER_POSITION_VALID, SwapBuffers
 *
 * softgl only: the text comes from softgl's wgl shim (include/GL/softgl_wgl.h),
 * which Mesa does not have (the test skips there).  softglSelectFont
 * stands in for CreateFont + SelectObject.  The glyphs are softgl's
 * built-in misc-fixed fonts, not Windows' (docs/fonts.md).  Both programs
 * call glRasterPos2i before glColor3f: a correct GL draws the text in the
 * colour current at glRasterPos (§0 #6), which is what is checked.
 */
#include "book.h"

#define W 360
#define H 80

#ifdef BOOK_HAVE_WGL
static const char hello[] = "\xCF\xF0\xE8\xE2\xE5\xF2 OpenGL !!!"; /* "Привет OpenGL !!!" in CP1251 */
static const char hello2[] = "\xCF\xF0\xE8\xE2\xE5\xF2 OpenGL!!!";
static GLuint base;

/* F18's paint handler. */
static void draw_f18(void)
{
    glClear(GL_COLOR_BUFFER_BIT);
    glRasterPos2i(20, 10);
    glColor3f(1, 1, 0);
    glCallLists(17, GL_UNSIGNED_BYTE, hello);
}

/* F19 */
static void glPrintText(GLuint b, const char *s)
{
    if (b == 0 || s == NULL)
        return;
    glPushAttrib(GL_LIST_BIT);
    glListBase(b - 32);
    glCallLists((GLsizei)strlen(s), GL_UNSIGNED_BYTE, s);
    glPopAttrib();
}

static void CFont(int size)
{
    base = glGenLists(224);
    softglSelectFont(book_dc, size, FW_BOLD, ANSI_CHARSET); /* CreateFont("Courier", size, ...) */
    h_expect(wglUseFontBitmaps(book_dc, 32, 224, base) == TRUE, "wglUseFontBitmaps(32, 224, base)");
}

static void draw_f19(void)
{
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    glLoadIdentity();
    glRasterPos2i(20, 10);
    glColor3f(1, 1, 0);
    glPrintText(base, hello2);
}

/* Text pixels (not black) in the last book_read: count, bounding box and
 * whether all have colour (r,g,b). */
static int text(int r, int g, int b, int box[4], int *all)
{
    int x, y, n = 0;
    box[0] = W; box[1] = H; box[2] = -1; box[3] = -1;
    *all = 1;
    for (y = 0; y < H; y++)
        for (x = 0; x < W; x++) {
            const unsigned char *p = book_at(x, y);
            if (!(p[0] | p[1] | p[2]))
                continue;
            n++;
            if (p[0] != r || p[1] != g || p[2] != b) *all = 0;
            if (x < box[0]) box[0] = x;
            if (y < box[1]) box[1] = y;
            if (x > box[2]) box[2] = x;
            if (y > box[3]) box[3] = y;
        }
    return n;
}
#endif

int main(void)
{
#ifndef BOOK_HAVE_WGL
    h_skip("needs softgl's wgl shim (GL/softgl_wgl.h) for wglUseFontBitmaps");
#else
    int n, n2, box[4], all, i;
    GLint valid = 1;

    book_open(W, H);
    book_ortho_pixels();

    /* F18: SelectObject(hDC, GetStockObject(SYSTEM_FONT)) is the DC's
     * default font; lists 1..255 are the codes 1..255. */
    h_expect(wglUseFontBitmaps(book_dc, 1, 255, 1) == TRUE, "wglUseFontBitmaps(hDC, 1, 255, 1)");
    h_expect_no_error("wglUseFontBitmaps");
    draw_f18();
    book_shot("s3_text-system_frame1", 0, 0);
    n = text(255, 255, 255, box, &all);
    printf("  frame 1: %d text pixels in x %d..%d, y %d..%d\n", n, box[0], box[2], box[1], box[3]);
    h_expect(n > 200 && all, "frame 1: the text must be white (colour latched before glColor3f): %d px, all white %d",
             n, all);
    h_expect(box[0] >= 20 && box[0] <= 24 && box[1] >= 5 && box[1] <= 12,
             "frame 1: text starts at (%d,%d), expected near the raster position (20,10)", box[0], box[1]);
    /* Each of the six Cyrillic letters has ink of its own. */
    for (i = 0; i < 6; i++) {
        GLfloat rp[4];
        int before, after;
        glClear(GL_COLOR_BUFFER_BIT);
        glRasterPos2i(20, 10);
        before = 0;
        glCallLists(1, GL_UNSIGNED_BYTE, hello + i);
        glGetFloatv(GL_CURRENT_RASTER_POSITION, rp);
        glFinish();
        book_read();
        after = text(255, 255, 0, box, &all);
        h_expect(after > before + 10 && rp[0] > 20, "Cyrillic letter %d (0x%02X) drew %d pixels, advanced to %g",
                 i, (unsigned char)hello[i], after, rp[0]);
    }
    draw_f18(); /* second frame: the yellow latched by the first frame's glColor3f */
    book_shot("s3_text-system_frame2", 0, 0);
    n2 = text(255, 255, 0, box, &all);
    h_expect(n2 == n && all, "frame 2: %d pixels, all yellow %d (want %d yellow)", n2, all, n);
    glDeleteLists(1, 255);

    /* F19: InitGL, CFont("Courier", 36), two frames. */
    glShadeModel(GL_SMOOTH);
    glClearColor(0, 0, 0, 0.5f);
    glClearDepth(1.0f);
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_LEQUAL);
    glHint(GL_PERSPECTIVE_CORRECTION_HINT, GL_NICEST);
    glColor3f(1, 1, 1);
    CFont(36);
    draw_f19();
    glFinish();
    book_read();
    n = text(255, 255, 255, box, &all);
    h_expect(n > 500 && all, "F19 frame 1: %d pixels, all white %d", n, all);
    h_expect(box[3] - box[1] >= 20, "F19: a 36-pixel font is only %d pixels high", box[3] - box[1] + 1);
    draw_f19();
    book_shot("s3_text-courier36", 0, 0);
    n2 = text(255, 255, 0, box, &all);
    h_expect(n2 == n && all, "F19 frame 2: %d pixels, all yellow %d", n2, all);

    /* F19 under a perspective projection (its reshape is not shown): with
     * an identity modelview (20,10,0) is on the eye plane, outside the
     * frustum: the raster position is invalid and nothing is drawn. */
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    gluPerspective(45, (double)W / H, 0.1, 100);
    glMatrixMode(GL_MODELVIEW);
    draw_f19();
    glGetIntegerv(GL_CURRENT_RASTER_POSITION_VALID, &valid);
    h_expect(!valid, "F19 under gluPerspective: the raster position should be invalid");
    glFinish();
    book_read();
    h_expect(text(255, 255, 0, box, &all) == 0, "F19 under gluPerspective drew text");
    glDeleteLists(base, 224); /* KillFont */
    h_expect(!glIsList(base), "KillFont: lists still there");
    h_expect_no_error("end");
    book_close();
    return h_finish();
#endif
}
