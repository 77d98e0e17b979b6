/* t_book_s3_accum: the Russian textbook's accumulation buffer section
 * (§14.3, seeds-inventory §2 glAccum, §5 #16).
 *
 * BOOK: S3, Russian OpenGL textbook, ch. 14.3 "The accumulation buffer" (glAccum GL_LOAD/GL_ACCUM/GL_MULT/GL_ADD/GL_RETURN, glClearAccum; blur, anti-aliasing and soft shadows by rendering the scene several times)
 * SHOWS: a white square rendered at four positions and averaged (motion blur: steps of 1/4 intensity), and a sphere averaged over 8 jittered camera positions (anti-aliased edges)
 * FEATURES: glClearAccum, glClear(GL_ACCUM_BUFFER_BIT), glAccum(GL_LOAD, GL_ACCUM, GL_MULT, GL_ADD, GL_RETURN), accumulation precision above 8 bits
 *
 * The section has no code of its own: the scenes are the uses it names.
 * Checks: pixels covered by k of the 4 squares are k/4 white; GL_MULT and
 * GL_ADD act as the spec says; 8 passes of value 1/8*100/255 each return
 * 100/255 (more precision than 8 bits per pass would keep).
 */
#include "book.h"

#define W 320
#define H 160

int main(void)
{
    static const double jit[8][2] = {{-.375, .125}, {.125, .375}, {.375, -.125}, {-.125, -.375},
                                     {-.25, -.25}, {.25, .25}, {-.5, .5}, {.5, -.5}};
    GLUquadricObj *q = gluNewQuadric();
    GLint abits = 0;
    int i, k;

    book_open(W, H);
    glGetIntegerv(GL_ACCUM_RED_BITS, &abits);
    h_expect(abits >= 16, "a zero-filled PFD got %d accumulation red bits", abits);

    /* Motion blur: left half. */
    glViewport(0, 0, W / 2, H);
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    gluOrtho2D(0, W / 2, 0, H);
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
    glClearAccum(0, 0, 0, 0);
    glClear(GL_ACCUM_BUFFER_BIT);
    for (i = 0; i < 4; i++) {
        glClear(GL_COLOR_BUFFER_BIT);
        glColor3f(1, 1, 1);
        glRecti(20 + 20 * i, 40, 80 + 20 * i, 120);
        glAccum(GL_ACCUM, 0.25f);
    }
    glAccum(GL_RETURN, 1);

    /* Anti-aliasing by jittering the projection: right half. */
    glViewport(W / 2, 0, W / 2, H);
    glClear(GL_ACCUM_BUFFER_BIT);
    glEnable(GL_DEPTH_TEST);
    glEnable(GL_SCISSOR_TEST); /* keep the left half while clearing */
    glScissor(W / 2, 0, W / 2, H);
    for (i = 0; i < 8; i++) {
        glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
        glMatrixMode(GL_PROJECTION);
        glLoadIdentity();
        /* shift by a subpixel: 2.4 units span W/2 pixels */
        glOrtho(-1.2 - jit[i][0] * 2.4 / (W / 2), 1.2 - jit[i][0] * 2.4 / (W / 2),
                -1.2 - jit[i][1] * 2.4 / H, 1.2 - jit[i][1] * 2.4 / H, -5, 5);
        glMatrixMode(GL_MODELVIEW);
        glColor3f(1, 0.6f, 0.2f);
        gluSphere(q, 1, 24, 24);
        glAccum(i == 0 ? GL_LOAD : GL_ACCUM, i == 0 ? 0.125f : 0.125f);
    }
    glAccum(GL_RETURN, 1);
    glDisable(GL_SCISSOR_TEST);
    glDisable(GL_DEPTH_TEST);
    glViewport(0, 0, W, H);
    book_shot("s3_accum-blur_antialias", 2, 40);

    /* Square i covers x in [20+20i, 80+20i): a pixel is covered by k. */
    for (k = 0; k < 7; k++) {
        int x = 30 + 15 * k, cover = 0, want;
        for (i = 0; i < 4; i++)
            cover += x >= 20 + 20 * i && x < 80 + 20 * i;
        want = (int)(cover * 0.25 * 255 + 0.5);
        book_expect_rgb(x, 80, want, want, want, 1, "motion blur: k/4 white");
    }
    /* anti-aliased edge: some pixels on the sphere's rim are in between */
    {
        int x, mid = 0;
        for (x = W / 2; x < W; x++) {
            int r = book_at(x, H / 2)[0];
            if (r > 20 && r < 235) mid++;
        }
        h_expect(mid >= 2, "the jittered sphere has no intermediate edge pixels (%d)", mid);
    }

    /* GL_MULT, GL_ADD, and precision over 8 passes. */
    glViewport(0, 0, W, H);
    glClearColor(0.5f, 0.5f, 0.5f, 1);
    glClear(GL_COLOR_BUFFER_BIT);
    glAccum(GL_LOAD, 1);     /* 0.5 */
    glAccum(GL_MULT, 0.5f);  /* 0.25 */
    glAccum(GL_ADD, 0.25f);  /* 0.5 */
    glAccum(GL_RETURN, 1.5f);/* 0.75 */
    book_expect_rgb(5, 5, 191, 191, 191, 1, "GL_LOAD 1, MULT 0.5, ADD 0.25, RETURN 1.5 = 0.75");
    glClearColor(100 / 255.0f, 100 / 255.0f, 100 / 255.0f, 1);
    glClear(GL_COLOR_BUFFER_BIT | GL_ACCUM_BUFFER_BIT);
    for (i = 0; i < 8; i++)
        glAccum(GL_ACCUM, 0.125f);
    glClearColor(0, 0, 0, 0);
    glClear(GL_COLOR_BUFFER_BIT);
    glAccum(GL_RETURN, 1);
    book_expect_rgb(5, 5, 100, 100, 100, 1, "8 x ACCUM 1/8 of 100 returns 100");
    gluDeleteQuadric(q);
    h_expect_no_error("end");
    book_close();
    return h_finish();
}
