/* t_book_s3_select: picking with GL selection, to go with the Russian
 * textbook's chapter 12 (mouse picking by unprojection).  The textbook
 * itself has no selection code: this program is written in its style for
 * the same task, so the gallery shows both ways of picking.
 *
 * BOOK: S3, Russian OpenGL textbook, ch. 12 (picking what is under the mouse) -- not a book fragment: the GL selection counterpart of F27
 * SHOWS: three squares at different depths, two overlapping; each "click" is resolved with GL_SELECT and gluPickMatrix, and the nearest square hit is redrawn brighter with a white frame
 * FEATURES: glSelectBuffer, glRenderMode(GL_SELECT/GL_RENDER), glInitNames, glPushName/glLoadName, gluPickMatrix, hit records (name count, min and max depth), depth test
 *
 * Checks: the hit records (how many, which names, the nearest by the
 * minimum depth) for clicks on one square, on two overlapping ones and on
 * the background; the picked square is the one redrawn.
 */
#include "book.h"

#define W 240
#define H 180

static const GLfloat sq[3][4] = {/* x, y, z, colour index */
    {-1.0f, 0.3f, -1, 0}, {0.2f, 0.0f, 0, 1}, {-0.3f, -0.6f, 1, 2}};
static const GLfloat colour[3][3] = {{0.6f, 0, 0}, {0, 0.6f, 0}, {0, 0, 0.6f}};

static void projection(int pick, int x, int y)
{
    GLint vp[4];
    glGetIntegerv(GL_VIEWPORT, vp);
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    if (pick)
        gluPickMatrix(x + 0.5, y + 0.5, 3, 3, vp);
    glOrtho(-2, 2, -1.5, 1.5, -5, 5);
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
}

static void square(int i, GLfloat grow)
{
    GLfloat x = sq[i][0], y = sq[i][1], z = sq[i][2]; /* larger z: nearer the viewer */
    glBegin(GL_QUADS);
    glVertex3f(x - grow, y - grow, z); glVertex3f(x + 1 + grow, y - grow, z);
    glVertex3f(x + 1 + grow, y + 1 + grow, z); glVertex3f(x - grow, y + 1 + grow, z);
    glEnd();
}

static void scene(int select)
{
    int i;
    for (i = 0; i < 3; i++) {
        if (select)
            glLoadName((GLuint)i + 1);
        glColor3fv(colour[i]);
        square(i, 0);
    }
}

/* Pick at window (x, y): number of hits, and the name of the nearest. */
static int pick(int x, int y, GLuint *nearest, GLuint *names_mask)
{
    GLuint buf[64], *p = buf, best = 0, zmin = 0xffffffffu;
    GLint hits, i;
    glSelectBuffer(64, buf);
    glRenderMode(GL_SELECT);
    glInitNames();
    glPushName(0);
    projection(1, x, y);
    scene(1);
    hits = glRenderMode(GL_RENDER);
    *names_mask = 0;
    for (i = 0; i < hits; i++) {
        GLuint n = p[0], z1 = p[1], k;
        for (k = 0; k < n; k++)
            *names_mask |= 1u << p[3 + k];
        if (n > 0 && z1 <= zmin) {
            zmin = z1;
            best = p[3 + n - 1];
        }
        p += 3 + n;
    }
    *nearest = best;
    return hits;
}

int main(void)
{
    static const struct { int x, y, hits; GLuint nearest, mask; } clicks[3] = {
        {80, 140, 1, 1, 1u << 1},                /* the red square alone */
        {147, 102, 2, 3, (1u << 2) | (1u << 3)}, /* green and blue overlap: blue is nearer */
        {225, 10, 0, 0, 0}};                     /* background */
    GLuint nearest, mask;
    int i, hits;

    book_open(W, H);
    glEnable(GL_DEPTH_TEST);
    for (i = 0; i < 3; i++) {
        hits = pick(clicks[i].x, clicks[i].y, &nearest, &mask);
        h_expect(hits == clicks[i].hits && nearest == clicks[i].nearest && mask == clicks[i].mask,
                 "click %d at (%d,%d): %d hits, nearest %u, names 0x%x; expected %d, %u, 0x%x", i,
                 clicks[i].x, clicks[i].y, hits, nearest, mask, clicks[i].hits, clicks[i].nearest,
                 clicks[i].mask);
    }
    /* Draw the scene and highlight what the overlap click picked. */
    pick(clicks[1].x, clicks[1].y, &nearest, &mask);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    projection(0, 0, 0);
    scene(0);
    if (nearest >= 1 && nearest <= 3) {
        const GLfloat *c = colour[nearest - 1];
        glDepthFunc(GL_LEQUAL);
        glColor3f(c[0] / 0.6f, c[1] / 0.6f, c[2] / 0.6f);
        square((int)nearest - 1, 0);
        glColor3f(1, 1, 1);
        glPolygonMode(GL_FRONT_AND_BACK, GL_LINE);
        glDisable(GL_DEPTH_TEST);
        square((int)nearest - 1, 0.03f);
        glEnable(GL_DEPTH_TEST);
        glPolygonMode(GL_FRONT_AND_BACK, GL_FILL);
        glDepthFunc(GL_LESS);
    }
    book_shot("s3_select-pick", 0, 8);
    book_expect_rgb(clicks[1].x, clicks[1].y, 0, 0, 255, 0, "the picked (nearest, blue) square is highlighted");
    book_expect_rgb(clicks[0].x, clicks[0].y, 153, 0, 0, 1, "the red square is not");
    h_expect_no_error("end");
    book_close();
    return h_finish();
}
