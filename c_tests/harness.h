/* harness.h - tiny helpers for softgl's C tests.
 *
 * A test is a C program c_tests/t_NAME.c that calls h_init() (or makes its
 * own OSMesa context current), draws, checks with the h_expect* helpers and
 * ends with `return h_finish();`.  Checks never exit: every failure is
 * recorded and printed, and h_finish() reports PASS/FAIL and the exit code.
 * Tests run with the repo root as the current directory.
 */
#ifndef SOFTGL_C_TESTS_HARNESS_H
#define SOFTGL_C_TESTS_HARNESS_H

#include <GL/gl.h>
#include <GL/osmesa.h>

/* Exit code a test uses to say "skipped" (see h_skip). */
#define H_SKIP_CODE 77

/* Create an OSMESA_RGBA context (24 depth bits, 8 stencil bits, no accum)
 * over a malloc'd w*h GL_UNSIGNED_BYTE buffer and make it current.
 * Exits with a message if anything fails. */
void h_init(int w, int h);

/* The context / colour buffer created by h_init (NULL before). */
OSMesaContext h_context(void);
unsigned char *h_buffer(void);

/* Width and height of the current OSMesa drawing buffer. */
int h_width(void);
int h_height(void);

/* Override the test name printed by h_finish (default: program name). */
void h_set_name(const char *name);

/* glReadPixels(0, 0, w, h, GL_RGBA, GL_UNSIGNED_BYTE) of the whole current
 * buffer into rgba (w*h*4 bytes, rows bottom-up as GL returns them). */
void h_read(unsigned char *rgba);

/* Read pixel (x, y) (GL window coordinates, y up) and record a failure if any
 * channel differs from r,g,b,a by more than tol.  A negative expected value
 * means "don't care" for that channel. */
void h_expect_pixel(int x, int y, int r, int g, int b, int a, int tol,
                    const char *what);

/* Record a failure with a printf-style message if cond is false. */
void h_expect(int cond, const char *fmt, ...)
#if defined(__GNUC__)
    __attribute__((format(printf, 2, 3)))
#endif
    ;

/* glGetError() must be GL_NO_ERROR / must be e. */
void h_expect_no_error(const char *where);
void h_expect_error(GLenum e, const char *where);

/* Write the current buffer as $SOFTGL_TEST_OUT/<name>.pam (RGBA, rows
 * top-down; default directory out/c_tests). */
void h_save(const char *name);

/* h_save, then compare against c_tests/golden/<name>.png with
 * $SOFTGL_IMGCMP (default target/release/imgcmp).  With SOFTGL_BLESS=1 the
 * golden is (re)written instead; a person must then look at it. */
void h_check_golden(const char *name, int tol, int max_bad);

/* Print "SKIP reason" and exit with H_SKIP_CODE. */
void h_skip(const char *reason);

/* Number of failures recorded so far. */
int h_failures(void);

/* Print "PASS name" or "FAIL name (n failures)"; return the exit code. */
int h_finish(void);

#endif
