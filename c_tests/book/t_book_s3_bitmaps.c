/* t_book_s3_bitmaps: the Russian textbook's bitmap fragments (§5.7,
 * seeds-inventory §3.5 F07-F09).
 *
 * BOOK: S3, Russian OpenGL textbook, ch. 5.7 "Drawing bitmaps", fragments F07 (the letter T), F08 (three T's), F09 (A, B, C)
 * SHOWS: one T at (120,120); three T's in a row 16 pixels apart; the letters A, B, C; in the raster colour latched at glRasterPos
 * FEATURES: glBitmap with and without raster-position advance, glRasterPos2i, glPixelStorei(GL_UNPACK_ALIGNMENT, 1), the raster colour latched at glRasterPos, GL_CURRENT_RASTER_POSITION
 *
 * The book says bitmaps are stored "bottom-up and right-to-left"; the
 * spec (and this port) has rows bottom-up and the most significant bit
 * leftmost (§6 #7).  It says the T is at (100,50) but the code uses
 * (120,120) (§6 #8): the code is followed.  F09's A, B and C arrays are
 * not printed in the book; the ones here are this port's own.
 */
#include "book.h"

#define W 240
#define H 160

static GLubyte BitMap[24] = {
    0x0c, 0x00, 0x0c, 0x00, 0x0c, 0x00, 0x0c, 0x00, 0x0c, 0x00, 0x0c, 0x00,
    0x0c, 0x00, 0x0c, 0x00, 0x0c, 0x00, 0x0c, 0x00, 0xff, 0xc0, 0xff, 0xc0};

/* 16x12 letters, bottom row first, MSB leftmost (this port's own). */
static GLubyte BitMap_A[24] = {
    0xc0, 0xc0, 0xc0, 0xc0, 0xc0, 0xc0, 0xff, 0xc0, 0xff, 0xc0, 0xc0, 0xc0,
    0xc0, 0xc0, 0x61, 0x80, 0x61, 0x80, 0x33, 0x00, 0x1e, 0x00, 0x0c, 0x00};
static GLubyte BitMap_B[24] = {
    0xff, 0x00, 0xff, 0x80, 0xc1, 0xc0, 0xc0, 0xc0, 0xc1, 0xc0, 0xff, 0x80,
    0xff, 0x80, 0xc1, 0xc0, 0xc0, 0xc0, 0xc1, 0xc0, 0xff, 0x80, 0xff, 0x00};
static GLubyte BitMap_C[24] = {
    0x1f, 0x80, 0x7f, 0xc0, 0xe0, 0x40, 0xc0, 0x00, 0xc0, 0x00, 0xc0, 0x00,
    0xc0, 0x00, 0xc0, 0x00, 0xc0, 0x00, 0xe0, 0x40, 0x7f, 0xc0, 0x1f, 0x80};

/* Does bitmap bm (16 wide, 12 rows) have pixel (x,y) set? */
static int bit(const GLubyte *bm, int x, int y)
{
    return (bm[2 * y + x / 8] >> (7 - x % 8)) & 1;
}

/* Every pixel of the 16x12 cell at (x0,y0) is colour c where bm is set
 * and black elsewhere. */
static void expect_glyph(const GLubyte *bm, int x0, int y0, const int c[3], const char *what)
{
    int x, y, bad = 0;
    for (y = 0; y < 12; y++)
        for (x = 0; x < 16; x++) {
            const unsigned char *p = book_at(x0 + x, y0 + y);
            int on = bit(bm, x, y);
            if (on ? (p[0] != c[0] || p[1] != c[1] || p[2] != c[2]) : (p[0] | p[1] | p[2]))
                bad++;
        }
    h_expect(bad == 0, "%s at (%d,%d): %d pixels wrong", what, x0, y0, bad);
}

int main(void)
{
    static const int white[3] = {255, 255, 255}, yellow[3] = {255, 255, 0};
    GLfloat rp[4];

    book_open(W, H);
    book_ortho_pixels();
    glClear(GL_COLOR_BUFFER_BIT);

    /* F07: one T.  The raster colour is the current colour at glRasterPos:
     * set white first (the book's fragment does not set one; white is the
     * default). */
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
    glRasterPos2i(120, 120);
    glBitmap(16, 12, 0, 0, 0, 0, BitMap);
    glGetFloatv(GL_CURRENT_RASTER_POSITION, rp);
    h_expect(rp[0] == 120 && rp[1] == 120, "F07: glBitmap(…, 0, 0, …) moved the raster position to %g,%g",
             rp[0], rp[1]);
    book_shot("s3_bitmaps-T", 0, 0);
    expect_glyph(BitMap, 120, 120, white, "F07 T");

    /* F08: three T's, each advancing 16 pixels. */
    glClear(GL_COLOR_BUFFER_BIT);
    glColor3f(1, 1, 1);
    glRasterPos2i(120, 120);
    glBitmap(16, 12, 0, 0, 16, 0, BitMap);
    glBitmap(16, 12, 0, 0, 16, 0, BitMap);
    glBitmap(16, 12, 0, 0, 16, 0, BitMap);
    glGetFloatv(GL_CURRENT_RASTER_POSITION, rp);
    h_expect(rp[0] == 168 && rp[1] == 120, "F08: raster position after three T's is %g,%g",
             rp[0], rp[1]);
    /* F09: A, B, C below, yellow: glColor before glRasterPos latches it. */
    glColor3f(1, 1, 0);
    glRasterPos2i(120, 60);
    glBitmap(16, 12, 0, 0, 16, 0, BitMap_A);
    glBitmap(16, 12, 0, 0, 16, 0, BitMap_B);
    glBitmap(16, 12, 0, 0, 16, 0, BitMap_C);
    /* And a colour change after glRasterPos does not apply (§0 #6). */
    glRasterPos2i(20, 20);
    glColor3f(1, 0, 0);
    glBitmap(16, 12, 0, 0, 16, 0, BitMap_A);
    book_shot("s3_bitmaps-TTT_ABC", 0, 0);
    expect_glyph(BitMap, 120, 120, white, "F08 first T");
    expect_glyph(BitMap, 136, 120, white, "F08 second T");
    expect_glyph(BitMap, 152, 120, white, "F08 third T");
    expect_glyph(BitMap_A, 120, 60, yellow, "F09 A");
    expect_glyph(BitMap_B, 136, 60, yellow, "F09 B");
    expect_glyph(BitMap_C, 152, 60, yellow, "F09 C");
    expect_glyph(BitMap_A, 20, 20, yellow, "A drawn in the colour latched before glColor3f(1,0,0)");
    h_expect_no_error("end");
    book_close();
    return h_finish();
}
