/* book.h - shared helpers for the C ports of the three textbooks' programs
 * (c_tests/book/t_book_*.c; seeds-inventory §3 lists them).
 *
 * The books open their GL window with wgl (GetDC, ChoosePixelFormat on a
 * PIXELFORMATDESCRIPTOR, wglCreateContext, wglMakeCurrent, SwapBuffers), so
 * a port does the same through softgl's wgl shim (include/GL/softgl_wgl.h),
 * with softglCreateDC standing in for GetDC.  Built against Mesa (no
 * softgl_wgl.h on the include path) the same port falls back to an OSMesa
 * context with the depth, stencil and accumulation buffers a Windows
 * pixel format gives, so its images can be cross-checked against Mesa.
 *
 * Each port's header comment carries three lines the gallery generator
 * (demo/gallery.py) reads:  "BOOK:" (book and section), "SHOWS:" (what the
 * picture must show) and "FEATURES:" (GL features exercised).  Images are
 * named "<program>-<view>" after the file name without "t_book_".
 *
 * Header-only (static functions) so c_tests/run.sh builds a port like any
 * other test: the port plus c_tests/harness.c.
 */
#ifndef SOFTGL_BOOK_H
#define SOFTGL_BOOK_H

#include "harness.h"
#include <GL/gl.h>
#include <GL/glu.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <errno.h>
#include <sys/stat.h>

#if defined(__has_include)
#if __has_include(<GL/softgl_wgl.h>)
#include <GL/softgl_wgl.h>
#define BOOK_HAVE_WGL 1
#endif
#endif

#if defined(__GNUC__)
#define BOOK_FN static __attribute__((unused))
#else
#define BOOK_FN static
#endif

#ifndef M_PI
#define M_PI 3.14159265358979323846
#endif

static int book_w, book_h;
static unsigned char *book_px;
#ifdef BOOK_HAVE_WGL
static HDC book_dc;
static HGLRC book_rc;
#else
static OSMesaContext book_osmesa;
static unsigned char *book_osmesa_buf;
#endif

/* Open a w x h "window" the way the books do (SetDCPixelFormat of their SPF
 * unit / Krasnov's FormCreate: a zero-filled PIXELFORMATDESCRIPTOR with only
 * the flags set, which must still get depth, stencil and accumulation). */
BOOK_FN void book_open(int w, int h)
{
    book_w = w;
    book_h = h;
    book_px = malloc((size_t)w * h * 4);
    if (!book_px) {
        printf("FAIL (out of memory)\n");
        exit(1);
    }
#ifdef BOOK_HAVE_WGL
    {
        PIXELFORMATDESCRIPTOR pfd;
        int fmt;
        memset(&pfd, 0, sizeof pfd);
        pfd.dwFlags = PFD_DRAW_TO_WINDOW | PFD_SUPPORT_OPENGL | PFD_DOUBLEBUFFER;
        book_dc = softglCreateDC(w, h);
        fmt = ChoosePixelFormat(book_dc, &pfd);
        if (!book_dc || fmt <= 0 || !SetPixelFormat(book_dc, fmt, &pfd)) {
            printf("FAIL (no device context / pixel format)\n");
            exit(1);
        }
        book_rc = wglCreateContext(book_dc);
        if (!book_rc || !wglMakeCurrent(book_dc, book_rc)) {
            printf("FAIL (wglCreateContext/wglMakeCurrent)\n");
            exit(1);
        }
    }
#else
    book_osmesa_buf = calloc((size_t)w * h, 4);
    book_osmesa = OSMesaCreateContextExt(OSMESA_RGBA, 24, 8, 16, NULL);
    if (!book_osmesa || !OSMesaMakeCurrent(book_osmesa, book_osmesa_buf, GL_UNSIGNED_BYTE, w, h)) {
        printf("FAIL (OSMesa context)\n");
        exit(1);
    }
#endif
    glViewport(0, 0, w, h);
}

BOOK_FN void book_close(void)
{
#ifdef BOOK_HAVE_WGL
    wglMakeCurrent(NULL, NULL);
    wglDeleteContext(book_rc);
    softglDestroyDC(book_dc);
#else
    OSMesaDestroyContext(book_osmesa);
    free(book_osmesa_buf);
#endif
    free(book_px);
}

/* The books' SwapBuffers(DC). */
BOOK_FN void book_swap(void)
{
#ifdef BOOK_HAVE_WGL
    SwapBuffers(book_dc);
#else
    glFinish();
#endif
}

static const char *book_out_dir(void)
{
    const char *d = getenv("SOFTGL_TEST_OUT");
    return (d && *d) ? d : "out/c_tests";
}

/* Read the whole colour buffer (rows bottom-up) into book_px. */
BOOK_FN void book_read(void)
{
    glPixelStorei(GL_PACK_ALIGNMENT, 4);
    glReadPixels(0, 0, book_w, book_h, GL_RGBA, GL_UNSIGNED_BYTE, book_px);
}

/* Pixel (x, y) of the last book_read. */
static const unsigned char *book_at(int x, int y)
{
    return book_px + 4 * ((size_t)y * book_w + x);
}

/* Record a failure unless pixel (x,y) is (r,g,b) within tol (reads GL). */
BOOK_FN void book_expect_rgb(int x, int y, int r, int g, int b, int tol, const char *what)
{
    h_expect_pixel(x, y, r, g, b, -1, tol, what);
}

/* Number of pixels in [x0,x1)x[y0,y1) of the last book_read equal to
 * (r,g,b) within tol. */
BOOK_FN int book_count(int x0, int y0, int x1, int y1, int r, int g, int b, int tol)
{
    int x, y, n = 0;
    for (y = y0; y < y1; y++)
        for (x = x0; x < x1; x++) {
            const unsigned char *p = book_at(x, y);
            if (abs(p[0] - r) <= tol && abs(p[1] - g) <= tol && abs(p[2] - b) <= tol)
                n++;
        }
    return n;
}

/* Compare with goldens?  Not with BOOK_NO_GOLDEN set (make demo), nor when
 * built against another GL (Mesa): the goldens are softgl's renders and GL
 * leaves edge ties to the implementation, so there only the pixel checks
 * apply (c_tests/book/crosscheck.sh reports the RMSE). */
BOOK_FN int book_compare_goldens(void)
{
#ifdef BOOK_HAVE_WGL
    return getenv("BOOK_NO_GOLDEN") == NULL;
#else
    return 0;
#endif
}

/* mkdir -p */
BOOK_FN void book_mkdirs(const char *path)
{
    char tmp[1024];
    size_t i, n = strlen(path);
    if (n >= sizeof tmp)
        return;
    memcpy(tmp, path, n + 1);
    for (i = 1; i <= n; i++)
        if (tmp[i] == '/' || tmp[i] == '\0') {
            char c = tmp[i];
            tmp[i] = '\0';
            mkdir(tmp, 0777);
            tmp[i] = c;
        }
}

/* Write the current image as $SOFTGL_TEST_OUT/book/NAME.pam and compare it
 * with c_tests/golden/book/NAME.png (SOFTGL_BLESS=1 writes the golden;
 * look at it before committing; skipped when built without softgl's wgl
 * header, i.e. against Mesa).  Then SwapBuffers, as the book does at
 * the end of its paint handler; with wgl the presented frame must be the
 * image just read. */
BOOK_FN void book_shot(const char *name, int tol, int max_bad)
{
    char dir[1024], pam[1200], golden[1200], cmd[3000];
    const char *imgcmp = getenv("SOFTGL_IMGCMP");
    const char *bless = getenv("SOFTGL_BLESS");
    FILE *f;
    int y, rc;
    if (!imgcmp || !*imgcmp)
        imgcmp = "target/release/imgcmp";
    glFinish();
    book_read();
    snprintf(dir, sizeof dir, "%s/book", book_out_dir());
    book_mkdirs(dir);
    snprintf(pam, sizeof pam, "%s/%s.pam", dir, name);
    f = fopen(pam, "wb");
    if (!f) {
        h_expect(0, "cannot write %s: %s", pam, strerror(errno));
        return;
    }
    fprintf(f, "P7\nWIDTH %d\nHEIGHT %d\nDEPTH 4\nMAXVAL 255\nTUPLTYPE RGB_ALPHA\nENDHDR\n",
            book_w, book_h);
    for (y = book_h - 1; y >= 0; y--)
        fwrite(book_at(0, y), 4, (size_t)book_w, f);
    fclose(f);
    snprintf(golden, sizeof golden, "c_tests/golden/book/%s.png", name);
    if (bless && strcmp(bless, "1") == 0) {
#ifndef BOOK_HAVE_WGL
        return; /* the book goldens are softgl's (book_compare_goldens) */
#endif
        mkdir("c_tests/golden/book", 0777);
        snprintf(cmd, sizeof cmd, "'%s' --to-png '%s' '%s'", imgcmp, pam, golden);
        rc = system(cmd);
        h_expect(rc == 0, "blessing %s failed", golden);
        if (rc == 0)
            printf("  blessed %s (look at it before committing)\n", golden);
    } else if (book_compare_goldens()) {
        snprintf(cmd, sizeof cmd, "'%s' '%s' '%s' --tol %d --max-bad %d", imgcmp, pam,
                 golden, tol, max_bad);
        fflush(stdout);
        rc = system(cmd);
        h_expect(rc == 0, "golden %s: image differs from %s", name, golden);
    }
    book_swap();
#ifdef BOOK_HAVE_WGL
    {
        int fw = 0, fh = 0;
        const unsigned char *front = softglGetDCImage(book_dc, &fw, &fh);
        h_expect(front && fw == book_w && fh == book_h &&
                     memcmp(front, book_px, (size_t)fw * fh * 4) == 0,
                 "%s: the frame SwapBuffers showed is not the image read back", name);
    }
#endif
}

/* A pixel-aligned 2-D projection (what the 2-D fragments of the Russian
 * textbook assume: gluOrtho2D(0, w, 0, h)). */
BOOK_FN void book_ortho_pixels(void)
{
    glViewport(0, 0, book_w, book_h);
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    gluOrtho2D(0, book_w, 0, book_h);
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
}

/* A camera framing about -2.5..2.5 around the origin (the 3-D fragments of
 * the textbook never show theirs): orthographic, z in [-5, 5]. */
BOOK_FN void book_ortho_unit(double half)
{
    double a = (double)book_w / book_h;
    glViewport(0, 0, book_w, book_h);
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    glOrtho(-half * a, half * a, -half, half, -5, 5);
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
}

/* Window coordinates of object point (x,y,z) under the current matrices. */
BOOK_FN void book_project(double x, double y, double z, double *wx, double *wy)
{
    GLdouble mv[16], pr[16], wz;
    GLint vp[4];
    glGetDoublev(GL_MODELVIEW_MATRIX, mv);
    glGetDoublev(GL_PROJECTION_MATRIX, pr);
    glGetIntegerv(GL_VIEWPORT, vp);
    gluProject(x, y, z, mv, pr, vp, wx, wy, &wz);
}

#endif
