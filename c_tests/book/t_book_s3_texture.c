/* t_book_s3_texture: the Russian textbook's textures section (§13.1,
 * seeds-inventory §3.5 F28-F31).
 *
 * BOOK: S3, Russian OpenGL textbook, ch. 13.1 "Textures": loading a BMP with auxDIBImageLoad (F28), gluScaleImage to a power of two, glTexImage2D (F29), gluBuild2DMipmaps, filters and wrap, a textured triangle (F30) and a quad repeating the texture 10 times (F31)
 * SHOWS: with only glTexImage2D (the book's F29, no filter set) the texture is incomplete and the shapes are untextured white; with GL_LINEAR, the upper-left half of the 4-colour texture on the triangle; with mipmaps, the quad showing the texture 10 times across and once up
 * FEATURES: BMP reading (auxDIBImageLoad stand-in), gluScaleImage, glTexImage2D internal format 3, texture completeness and the default GL_NEAREST_MIPMAP_LINEAR, glTexParameteri MIN/MAG filter, GL_REPEAT, gluBuild2DMipmaps, GL_LINEAR_MIPMAP_LINEAR, glTexEnvi(GL_MODULATE/GL_REPLACE), glTexCoord2f
 *
 * The book's Image/t1.bmp is not in the seeds: the test writes its own
 * 100x60 24-bit BMP (four coloured quadrants) into the output directory
 * and loads that.  GLAUX is not available: auxDIBImageLoad is replaced by
 * a small reader returning the same AUX_RGBImageRec.  The book says the
 * default GL_TEXTURE_MIN_FILTER is GL_LINEAR (§6 #17); it is
 * GL_NEAREST_MIPMAP_LINEAR, so F29 alone gives an incomplete texture and
 * no texturing -- shown and checked.
 */
#include "book.h"

#define W 240
#define H 200

typedef struct { GLint sizeX, sizeY; unsigned char *data; } AUX_RGBImageRec;

static void put16(FILE *f, unsigned v) { fputc(v & 255, f); fputc(v >> 8 & 255, f); }
static void put32(FILE *f, unsigned v) { put16(f, v & 0xffff); put16(f, v >> 16); }

/* Quadrant colours: s < 1/2 or >= 1/2, t < 1/2 or >= 1/2. */
static const unsigned char quad_rgb[4][3] = {{255, 0, 0}, {0, 255, 0}, {0, 0, 255}, {255, 255, 0}};

static void write_bmp(const char *path, int w, int h)
{
    int x, y, pad = (4 - (w * 3) % 4) % 4;
    FILE *f = fopen(path, "wb");
    if (!f) return;
    fputc('B', f); fputc('M', f);
    put32(f, 54 + (w * 3 + pad) * h); put32(f, 0); put32(f, 54);
    put32(f, 40); put32(f, w); put32(f, h); put16(f, 1); put16(f, 24);
    put32(f, 0); put32(f, (w * 3 + pad) * h); put32(f, 2835); put32(f, 2835); put32(f, 0); put32(f, 0);
    for (y = 0; y < h; y++) { /* bottom-up, BGR */
        for (x = 0; x < w; x++) {
            const unsigned char *c = quad_rgb[(x >= w / 2) + 2 * (y >= h / 2)];
            fputc(c[2], f); fputc(c[1], f); fputc(c[0], f);
        }
        for (x = 0; x < pad; x++) fputc(0, f);
    }
    fclose(f);
}

static unsigned rd(const unsigned char *p, int n) { unsigned v = 0; while (n--) v = v << 8 | p[n]; return v; }

/* auxDIBImageLoad: a 24-bit BMP as RGB rows, bottom-up, unpadded. */
static AUX_RGBImageRec *auxDIBImageLoad(const char *Filename)
{
    unsigned char hdr[54];
    AUX_RGBImageRec *r;
    int x, y, pad;
    FILE *f = fopen(Filename, "rb");
    if (!f) return NULL;
    if (fread(hdr, 1, 54, f) != 54 || hdr[0] != 'B' || hdr[1] != 'M' || rd(hdr + 28, 2) != 24) {
        fclose(f);
        return NULL;
    }
    r = malloc(sizeof *r);
    r->sizeX = (GLint)rd(hdr + 18, 4);
    r->sizeY = (GLint)rd(hdr + 22, 4);
    r->data = malloc((size_t)r->sizeX * r->sizeY * 3);
    pad = (4 - (r->sizeX * 3) % 4) % 4;
    fseek(f, (long)rd(hdr + 10, 4), SEEK_SET);
    for (y = 0; y < r->sizeY; y++) {
        for (x = 0; x < r->sizeX; x++) {
            unsigned char bgr[3];
            if (fread(bgr, 1, 3, f) != 3) break;
            r->data[3 * (y * r->sizeX + x) + 0] = bgr[2];
            r->data[3 * (y * r->sizeX + x) + 1] = bgr[1];
            r->data[3 * (y * r->sizeX + x) + 2] = bgr[0];
        }
        fseek(f, pad, SEEK_CUR);
    }
    fclose(f);
    return r;
}

static void draw(void)
{
    glClear(GL_COLOR_BUFFER_BIT);
    glColor3f(1, 1, 1);
    glBegin(GL_QUADS); /* F31 (drawn first: the triangle overlaps it) */
    glTexCoord2f(0, 0); glVertex3f(1, 1, 1);
    glTexCoord2f(0, 1); glVertex3f(1, 5, 1);
    glTexCoord2f(10, 1); glVertex3f(11, 5, 1);
    glTexCoord2f(10, 0); glVertex3f(11, 1, 1);
    glEnd();
    glBegin(GL_TRIANGLES); /* F30 */
    glTexCoord2f(0, 1); glVertex3f(2, 8, 0);
    glTexCoord2f(1, 1); glVertex3f(6, 8, 0);
    glTexCoord2f(0, 0); glVertex3f(2, 1, 0);
    glEnd();
}

static void at(double x, double y, int *px, int *py)
{
    double wx, wy;
    book_project(x, y, 0, &wx, &wy);
    *px = (int)wx;
    *py = (int)wy;
}

int main(void)
{
    char path[1024];
    AUX_RGBImageRec *texture, *Texture;
    static unsigned char scaled[64 * 64 * 3];
    int x, y, k, bad;
    GLint v;

    book_open(W, H);
    glViewport(0, 0, W, H);
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    glOrtho(0, 12, 0, 10, -5, 5);
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();

    snprintf(path, sizeof path, "%s/book", book_out_dir());
    book_mkdirs(path);
    snprintf(path, sizeof path, "%s/book/t1.bmp", book_out_dir());
    write_bmp(path, 100, 60);
    texture = auxDIBImageLoad(path); /* F28 */
    h_expect(texture && texture->sizeX == 100 && texture->sizeY == 60, "auxDIBImageLoad stand-in failed");
    if (!texture) return h_finish();
    /* 100x60 is not a power of two: gluScaleImage to 64x64 (§13.1.1). */
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
    glPixelStorei(GL_PACK_ALIGNMENT, 1);
    h_expect(gluScaleImage(GL_RGB, 100, 60, GL_UNSIGNED_BYTE, texture->data, 64, 64, GL_UNSIGNED_BYTE,
                           scaled) == 0, "gluScaleImage");
    texture->sizeX = texture->sizeY = 64;
    memcpy(texture->data, scaled, sizeof scaled);
    Texture = texture;

    glEnable(GL_TEXTURE_2D);
    glTexImage2D(GL_TEXTURE_2D, 0, 3, Texture->sizeX, Texture->sizeY, 0, GL_RGB, GL_UNSIGNED_BYTE,
                 Texture->data); /* F29 */
    glGetTexParameteriv(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, &v);
    h_expect(v == GL_NEAREST_MIPMAP_LINEAR, "default MIN_FILTER 0x%x (the book says GL_LINEAR)", v);
    draw();
    book_shot("s3_texture-incomplete", 0, 0);
    at(3, 6, &x, &y);
    book_expect_rgb(x, y, 255, 255, 255, 0, "F29 alone: incomplete texture, untextured triangle");

    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
    draw();
    book_shot("s3_texture-linear", 2, 20);
    /* F30: the triangle shows the texture's upper-left half. */
    at(2.3, 7.7, &x, &y);
    book_expect_rgb(x, y, 0, 0, 255, 8, "F30 near (0,1): blue quadrant");
    at(5.5, 7.8, &x, &y);
    book_expect_rgb(x, y, 255, 255, 0, 8, "F30 near (1,1): yellow quadrant");
    at(2.2, 1.5, &x, &y);
    book_expect_rgb(x, y, 255, 0, 0, 8, "F30 near (0,0): red quadrant");

    /* Mipmaps for the minified repeats. */
    h_expect(gluBuild2DMipmaps(GL_TEXTURE_2D, 3, 64, 64, GL_RGB, GL_UNSIGNED_BYTE, scaled) == 0,
             "gluBuild2DMipmaps");
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR_MIPMAP_LINEAR);
    glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_REPLACE);
    draw();
    book_shot("s3_texture-mipmap_repeat", 2, 40);
    /* F31: ten copies across (s 0..10 over x 1..11), one up (t over y 1..5);
     * quadrant centres below the triangle (x >= 6.5). */
    bad = 0;
    for (k = 6; k < 10; k++) {
        const double cx[2] = {1 + k + 0.25, 1 + k + 0.75}, cy[2] = {2, 4};
        int i, j;
        for (j = 0; j < 2; j++)
            for (i = 0; i < 2; i++) {
                const unsigned char *c = quad_rgb[i + 2 * j];
                const unsigned char *p;
                at(cx[i], cy[j], &x, &y);
                p = book_at(x, y);
                if (abs(p[0] - c[0]) > 12 || abs(p[1] - c[1]) > 12 || abs(p[2] - c[2]) > 12) {
                    printf("  copy %d quadrant %d: (%d,%d) is %d,%d,%d\n", k, i + 2 * j, x, y, p[0], p[1], p[2]);
                    bad++;
                }
            }
    }
    h_expect(bad == 0, "F31: %d quadrant centres of the repeated texture are wrong", bad);
    glDisable(GL_TEXTURE_2D);
    free(texture->data);
    free(texture);
    h_expect_no_error("end");
    book_close();
    return h_finish();
}
