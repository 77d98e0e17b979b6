/* t_lines: GL_LINES, GL_LINE_STRIP, GL_LINE_LOOP (GL 1.5 section 3.4).
 *
 * Exact pixel sets, through an exact ortho projection (window = object
 * coordinates):
 *  - 1-pixel lines by the diamond-exit rule: endpoints at pixel centres
 *    (the last pixel is not drawn), on pixel edges (the spec's perturbation
 *    by (-e, -e^2) puts the line in the row below / the column to the left),
 *    diagonals through diamond corners;
 *  - strips and loops: no pixel drawn twice at a joint (each pixel is
 *    checked against the union of the segments drawn one by one, and the
 *    segments' pixel counts add up);
 *  - wide lines (glLineWidth 3 and 2: columns of w fragments);
 *  - stipple: pattern bit (s / factor) % 16, s reset at glBegin and for
 *    each GL_LINES segment, continued across a strip;
 *  - flat shading takes a segment's second vertex;
 *  - clipping at the near plane and at the window edges;
 *  - glLineWidth(<= 0) is GL_INVALID_VALUE; GL_LINE_WIDTH, the ranges and
 *    granularity, GL_LINE_STIPPLE_PATTERN/REPEAT and the enable are
 *    reported; a display list replays lines identically.
 */
#include "harness.h"
#include <stdio.h>
#include <string.h>

#define W 32
#define H 32

static unsigned char px[W * H * 4];

static int lit(int x, int y) { const unsigned char *p = &px[(y * W + x) * 4]; return p[0] || p[1] || p[2]; }

static int count(void)
{
    int n = 0, x, y;
    for (y = 0; y < H; y++)
        for (x = 0; x < W; x++)
            n += lit(x, y);
    return n;
}

/* Every lit pixel is in row y with x0 <= x < x1, and all of those are lit
 * (when step > 0 only x with ((x - x0) / step) % 2 == 0: stipple). */
static void expect_row(const char *what, int y, int x0, int x1, int want_n)
{
    int n = count();
    int ok = 1, x;
    for (x = x0; x < x1; x++)
        if (!lit(x, y)) ok = 0;
    h_expect(ok && n == want_n, "%s: want row %d x %d..%d (%d pixels), got %d pixels%s", what, y, x0, x1 - 1,
             want_n, n, ok ? "" : " and some missing");
}

static void seg(float x0, float y0, float x1, float y1)
{
    glClear(GL_COLOR_BUFFER_BIT);
    glBegin(GL_LINES);
    glVertex2f(x0, y0);
    glVertex2f(x1, y1);
    glEnd();
    h_read(px);
}

int main(void)
{
    static unsigned char a[W * H * 4];
    int x, y, i, n, over;
    GLfloat f[2];
    GLint iv[2];

    h_init(W, H);
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    glOrtho(0, W, 0, H, -1, 1);
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
    glClearColor(0, 0, 0, 1);
    glColor3ub(255, 255, 255);

    /* Diamond-exit rule. */
    seg(2.5f, 5.5f, 10.5f, 5.5f);
    expect_row("horizontal, centres", 5, 2, 10, 8);
    seg(10.5f, 5.5f, 2.5f, 5.5f);
    expect_row("horizontal, centres, reversed", 5, 3, 11, 8);
    seg(2.0f, 5.0f, 10.0f, 5.0f);
    expect_row("horizontal on a pixel edge: row below", 4, 2, 10, 8);
    seg(5.0f, 2.0f, 5.0f, 10.0f);
    for (y = 2, n = 0; y < 10; y++) n += lit(4, y);
    h_expect(n == 8 && count() == 8, "vertical on a pixel edge: column 4 rows 2..9 (got %d of %d)", n, count());
    seg(2.0f, 2.0f, 10.0f, 10.0f);
    for (i = 2, n = 0; i < 10; i++) n += lit(i, i);
    h_expect(n == 8 && count() == 8, "diagonal through diamond corners: (2,2)..(9,9) (got %d of %d)", n, count());
    seg(4.5f, 4.5f, 4.5f, 4.5f);
    h_expect(count() == 0, "zero-length line draws nothing (%d)", count());
    h_expect_no_error("1-pixel lines");

    /* Strip and loop: joints drawn once. */
    {
        static const float v[5][2] = {{1.25f, 10.0f}, {7.5f, 14.75f}, {15.0f, 12.0f}, {22.25f, 20.5f}, {30.0f, 18.0f}};
        static int cnt[W * H];
        int total = 0, bad = 0;
        memset(cnt, 0, sizeof cnt);
        for (i = 0; i < 4; i++) {
            seg(v[i][0], v[i][1], v[i + 1][0], v[i + 1][1]);
            for (y = 0; y < H; y++)
                for (x = 0; x < W; x++)
                    if (lit(x, y)) { cnt[y * W + x]++; total++; }
        }
        glClear(GL_COLOR_BUFFER_BIT);
        glBegin(GL_LINE_STRIP);
        for (i = 0; i < 5; i++) glVertex2f(v[i][0], v[i][1]);
        glEnd();
        h_read(px);
        over = 0;
        for (y = 0; y < H; y++)
            for (x = 0; x < W; x++) {
                if (cnt[y * W + x] > 1) over++;
                if (lit(x, y) != (cnt[y * W + x] > 0)) bad++;
            }
        h_expect(over == 0 && bad == 0 && count() == total,
                 "strip = union of its segments, none shared (%d shared, %d differing, %d vs %d)", over, bad, count(), total);
        /* The loop: the strip plus the closing segment (which crosses the
         * strip, so compare sets, not counts). */
        seg(v[4][0], v[4][1], v[0][0], v[0][1]);
        for (y = 0; y < H; y++)
            for (x = 0; x < W; x++)
                if (lit(x, y)) cnt[y * W + x]++;
        glClear(GL_COLOR_BUFFER_BIT);
        glBegin(GL_LINE_LOOP);
        for (i = 0; i < 5; i++) glVertex2f(v[i][0], v[i][1]);
        glEnd();
        h_read(px);
        bad = 0;
        for (y = 0; y < H; y++)
            for (x = 0; x < W; x++)
                if (lit(x, y) != (cnt[y * W + x] > 0)) bad++;
        h_expect(bad == 0, "loop = strip + closing segment (%d differing pixels)", bad);
    }

    /* Wide lines. */
    glLineWidth(3.0f);
    seg(2.5f, 10.5f, 12.5f, 10.5f);
    for (y = 9, n = 0; y < 12; y++)
        for (x = 2; x < 12; x++) n += lit(x, y);
    h_expect(n == 30 && count() == 30, "width 3: rows 9..11, x 2..11 (%d of %d)", n, count());
    glLineWidth(2.0f);
    seg(2.5f, 10.5f, 12.5f, 10.5f);
    for (y = 9, n = 0; y < 11; y++)
        for (x = 2; x < 12; x++) n += lit(x, y);
    h_expect(n == 20 && count() == 20, "width 2: rows 9..10 (%d of %d)", n, count());
    glGetFloatv(GL_LINE_WIDTH, f);
    h_expect(f[0] == 2.0f, "GL_LINE_WIDTH %g", f[0]);
    glLineWidth(0.0f);
    h_expect_error(GL_INVALID_VALUE, "glLineWidth(0)");
    glLineWidth(-2.0f);
    h_expect_error(GL_INVALID_VALUE, "glLineWidth(-2)");
    glGetFloatv(GL_LINE_WIDTH, f);
    h_expect(f[0] == 2.0f, "GL_LINE_WIDTH unchanged by errors: %g", f[0]);
    glLineWidth(1.0f);
    glGetFloatv(GL_ALIASED_LINE_WIDTH_RANGE, f);
    h_expect(f[0] == 1.0f && f[1] >= 1.0f, "GL_ALIASED_LINE_WIDTH_RANGE %g %g", f[0], f[1]);
    glGetFloatv(GL_LINE_WIDTH_RANGE, f);
    h_expect(f[0] <= 1.0f && f[1] >= 1.0f, "GL_LINE_WIDTH_RANGE %g %g", f[0], f[1]);
    glGetFloatv(GL_LINE_WIDTH_GRANULARITY, f);
    h_expect(f[0] > 0.0f, "GL_LINE_WIDTH_GRANULARITY %g", f[0]);

    /* Stipple. */
    glGetIntegerv(GL_LINE_STIPPLE_PATTERN, iv);
    glGetIntegerv(GL_LINE_STIPPLE_REPEAT, iv + 1);
    h_expect(iv[0] == 0xFFFF && iv[1] == 1, "initial stipple 0x%x x%d", iv[0], iv[1]);
    h_expect(!glIsEnabled(GL_LINE_STIPPLE), "GL_LINE_STIPPLE initially off");
    glEnable(GL_LINE_STIPPLE);
    glLineStipple(2, 0x0F0F);
    glGetIntegerv(GL_LINE_STIPPLE_PATTERN, iv);
    glGetIntegerv(GL_LINE_STIPPLE_REPEAT, iv + 1);
    h_expect(iv[0] == 0x0F0F && iv[1] == 2 && glIsEnabled(GL_LINE_STIPPLE), "stipple state 0x%x x%d", iv[0], iv[1]);
    /* A strip along row 4: fragment s is at x = s. */
    glClear(GL_COLOR_BUFFER_BIT);
    glBegin(GL_LINE_STRIP);
    glVertex2f(0.5f, 4.5f);
    glVertex2f(11.5f, 4.5f);
    glVertex2f(28.5f, 4.5f);
    glEnd();
    h_read(px);
    for (x = 0, n = 0; x < W; x++) {
        int want = x < 28 && ((0x0F0F >> ((x / 2) % 16)) & 1);
        if (lit(x, 4) != want) n++;
    }
    h_expect(n == 0, "stipple continues across a strip (%d wrong pixels)", n);
    /* GL_LINES: reset per segment. */
    glClear(GL_COLOR_BUFFER_BIT);
    glBegin(GL_LINES);
    glVertex2f(0.5f, 4.5f);
    glVertex2f(11.5f, 4.5f);
    glVertex2f(11.5f, 4.5f);
    glVertex2f(28.5f, 4.5f);
    glEnd();
    h_read(px);
    for (x = 0, n = 0; x < W; x++) {
        int s = x < 11 ? x : x - 11;
        int want = x < 28 && ((0x0F0F >> ((s / 2) % 16)) & 1);
        if (lit(x, 4) != want) n++;
    }
    h_expect(n == 0, "stipple restarts for each GL_LINES segment (%d wrong pixels)", n);
    /* And at each glBegin. */
    glClear(GL_COLOR_BUFFER_BIT);
    for (i = 0; i < 2; i++) {
        glBegin(GL_LINE_STRIP);
        glVertex2f(0.5f, 6.5f + i);
        glVertex2f(20.5f, 6.5f + i);
        glEnd();
    }
    h_read(px);
    for (x = 0, n = 0; x < 20; x++) n += lit(x, 6) != lit(x, 7);
    h_expect(n == 0, "stipple restarts at glBegin (%d differences)", n);
    glDisable(GL_LINE_STIPPLE);

    /* Flat shading: the second vertex of each segment. */
    glShadeModel(GL_FLAT);
    glClear(GL_COLOR_BUFFER_BIT);
    glBegin(GL_LINE_STRIP);
    glColor3ub(255, 0, 0); glVertex2f(0.5f, 3.5f);
    glColor3ub(0, 255, 0); glVertex2f(10.5f, 3.5f);
    glColor3ub(0, 0, 255); glVertex2f(20.5f, 3.5f);
    glEnd();
    h_expect_pixel(0, 3, 0, 255, 0, 255, 0, "flat, segment 1 takes vertex 2");
    h_expect_pixel(9, 3, 0, 255, 0, 255, 0, "flat, segment 1 end");
    h_expect_pixel(10, 3, 0, 0, 255, 255, 0, "flat, segment 2 takes vertex 3");
    glShadeModel(GL_SMOOTH);
    glClear(GL_COLOR_BUFFER_BIT);
    glBegin(GL_LINES);
    glColor3ub(255, 0, 0); glVertex2f(0.5f, 3.5f);
    glColor3ub(0, 0, 255); glVertex2f(30.5f, 3.5f);
    glEnd();
    h_expect_pixel(0, 3, 255, 0, 0, 255, 0, "smooth, first fragment");
    h_expect_pixel(15, 3, 128, 0, 128, 255, 1, "smooth, middle");
    h_expect_pixel(29, 3, 9, 0, 247, 255, 1, "smooth, last fragment");
    glColor3ub(255, 255, 255);

    /* Clipping: near plane at z = 1 here (z_ndc = -z); crossing at x = 16.5. */
    glClear(GL_COLOR_BUFFER_BIT);
    glBegin(GL_LINES);
    glVertex3f(2.5f, 5.5f, 0.0f);
    glVertex3f(30.5f, 5.5f, 2.0f);
    glEnd();
    h_read(px);
    expect_row("clipped at the near plane", 5, 2, 16, 14);
    seg(-10.5f, 7.5f, 40.5f, 7.5f);
    expect_row("across both window edges", 7, 0, 32, 32);

    /* A display list gives the same pixels. */
    glLineWidth(2.0f);
    glNewList(1, GL_COMPILE);
    glLineWidth(3.0f);
    glBegin(GL_LINES);
    glVertex2f(3.25f, 2.0f);
    glVertex2f(27.5f, 29.75f);
    glEnd();
    glEndList();
    h_expect_no_error("compile");
    glGetFloatv(GL_LINE_WIDTH, f);
    h_expect(f[0] == 2.0f, "GL_COMPILE does not execute glLineWidth (%g)", f[0]);
    glClear(GL_COLOR_BUFFER_BIT);
    glCallList(1);
    h_read(a);
    seg(3.25f, 2.0f, 27.5f, 29.75f);
    h_expect(memcmp(a, px, sizeof a) == 0 && count() > 3 * 24, "display list replays the wide line (%d pixels)", count());
    h_expect_no_error("end");
    return h_finish();
}
