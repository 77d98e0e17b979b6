/* softgl benchmark scenes, written against the OSMesa API.
 *
 *   bench_scene SCENE WIDTH HEIGHT FRAMES OUT.pam
 *
 * Renders FRAMES timed frames after one untimed warm-up frame, then renders
 * frame IMAGE_FRAME again (the same picture whatever FRAMES is) and writes it
 * as a PAM and prints one JSON line: the renderer, each
 * frame's time in ms, the wall-clock time when the first frame finished
 * (so the runner can compute time to first frame from process start), and
 * peak memory. It is linked against Mesa's libOSMesa.so.8; the runner
 * switches implementations with LD_LIBRARY_PATH (softgl's build/lib holds
 * a libOSMesa.so.8) and GALLIUM_DRIVER / LP_NUM_THREADS for Mesa.
 */
#include <GL/gl.h>
#include <GL/osmesa.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/resource.h>
#include <time.h>
#include <unistd.h>
#include "scenes.h"

static double mono(void)
{
    struct timespec t;
    clock_gettime(CLOCK_MONOTONIC, &t);
    return t.tv_sec + t.tv_nsec * 1e-9;
}

static double wall(void)
{
    struct timespec t;
    clock_gettime(CLOCK_REALTIME, &t);
    return t.tv_sec + t.tv_nsec * 1e-9;
}

#define IMAGE_FRAME 7

int W, H;
static GLuint list_id;

/* Clears the colour buffer to (r, g, b), depth test off, identity
 * matrices: the 2D scenes' start. */
void clear_2d(float r, float g, float b)
{
    glClearColor(r, g, b, 1);
    glClear(GL_COLOR_BUFFER_BIT);
    glDisable(GL_DEPTH_TEST);
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
}

void perspective(void)
{
    double a = (double)W / H;
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    glFrustum(-0.5 * a, 0.5 * a, -0.5, 0.5, 1, 40);
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
}

/* A sphere of smooth-coloured triangle strips.
 *
 * The strips' colours and vertices are computed once per (stacks, slices)
 * and kept: recomputing ~1.2 million sin/cos calls a frame (spheres_l)
 * timed the C library's libm, not the GL under test (about a tenth of
 * spheres_l's 1-thread frame with softgl, 2026-11-28). The values are the
 * same expressions in double as before, so the GL calls and images are
 * unchanged; every frame still makes each glColor3d / glVertex3d call. */
struct sphere_table {
    int stacks, slices;
    double *v; /* per stack, per slice, two (colour, vertex) pairs: 12 doubles */
};

static const double *sphere_values(int stacks, int slices)
{
    static struct sphere_table tables[4];
    int i, j, k;
    double *v;
    for (k = 0; k < 4 && tables[k].v; k++)
        if (tables[k].stacks == stacks && tables[k].slices == slices)
            return tables[k].v;
    v = malloc(sizeof(double) * 12 * stacks * (slices + 1));
    if (!v) {
        fprintf(stderr, "bench: out of memory\n");
        exit(1);
    }
    for (i = 0; i < stacks; i++) {
        double t0 = M_PI * i / stacks, t1 = M_PI * (i + 1) / stacks;
        for (j = 0; j <= slices; j++) {
            double p = 2 * M_PI * j / slices;
            double x0 = sin(t0) * cos(p), y0 = cos(t0), z0 = sin(t0) * sin(p);
            double x1 = sin(t1) * cos(p), y1 = cos(t1), z1 = sin(t1) * sin(p);
            double *e = v + 12 * (i * (slices + 1) + j);
            e[0] = 0.5 + 0.5 * x0; e[1] = 0.5 + 0.5 * y0; e[2] = 0.5 + 0.5 * z0;
            e[3] = x0; e[4] = y0; e[5] = z0;
            e[6] = 0.5 + 0.5 * x1; e[7] = 0.5 + 0.5 * y1; e[8] = 0.5 + 0.5 * z1;
            e[9] = x1; e[10] = y1; e[11] = z1;
        }
    }
    if (k < 4) {
        tables[k].stacks = stacks;
        tables[k].slices = slices;
        tables[k].v = v;
    }
    return v;
}

void sphere(int stacks, int slices)
{
    const double *e = sphere_values(stacks, slices);
    int i, j;
    for (i = 0; i < stacks; i++) {
        glBegin(GL_TRIANGLE_STRIP);
        for (j = 0; j <= slices; j++, e += 12) {
            glColor3d(e[0], e[1], e[2]);
            glVertex3d(e[3], e[4], e[5]);
            glColor3d(e[6], e[7], e[8]);
            glVertex3d(e[9], e[10], e[11]);
        }
        glEnd();
    }
}

/* 5x5 spheres; `detail` sets stacks (slices = 2 stacks): 25 * 4 * detail^2 triangles. */
void spheres(int frame, int detail)
{
    int i, j;
    glClearColor(0.05f, 0.05f, 0.1f, 1);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    glEnable(GL_DEPTH_TEST);
    perspective();
    glTranslatef(0, 0, -9);
    glRotatef(frame * 3.0f, 0, 1, 0);
    for (i = 0; i < 5; i++)
        for (j = 0; j < 5; j++) {
            glPushMatrix();
            glTranslatef((i - 2) * 1.6f, (j - 2) * 1.2f, (float)((i + j) % 3) - 1);
            glScalef(0.6f, 0.6f, 0.6f);
            sphere(detail, 2 * detail);
            glPopMatrix();
        }
}

/* The sphere scene lit: a white directional light and a positional light
 * with attenuation and specular, smooth shading. */
static void lit_spheres(int frame)
{
    static const GLfloat pos1[4] = {2, 3, -4, 1}, col1[4] = {1, 0.6f, 0.3f, 1}, spec[4] = {1, 1, 1, 1};
    static const GLfloat diffuse[4] = {0.3f, 0.6f, 0.9f, 1};
    glEnable(GL_LIGHTING);
    glEnable(GL_LIGHT0);
    glEnable(GL_LIGHT1);
    glLightfv(GL_LIGHT1, GL_POSITION, pos1);
    glLightfv(GL_LIGHT1, GL_DIFFUSE, col1);
    glLightfv(GL_LIGHT1, GL_SPECULAR, spec);
    glLightf(GL_LIGHT1, GL_LINEAR_ATTENUATION, 0.1f);
    glMaterialfv(GL_FRONT, GL_DIFFUSE, diffuse);
    glMaterialfv(GL_FRONT, GL_SPECULAR, spec);
    glMaterialf(GL_FRONT, GL_SHININESS, 20);
    glDisable(GL_COLOR_MATERIAL);
    spheres(frame, 24);
    glDisable(GL_LIGHTING);
}

/* Blended overdraw: 2,000 translucent quads of 1/8 the window (particles). */
static void particles(int frame)
{
    int i;
    unsigned seed = 12345;
    glClearColor(0, 0, 0, 1);
    glClear(GL_COLOR_BUFFER_BIT);
    glDisable(GL_DEPTH_TEST);
    glEnable(GL_BLEND);
    glBlendFunc(GL_SRC_ALPHA, GL_ONE);
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
    glBegin(GL_QUADS);
    for (i = 0; i < 2000; i++) {
        float x, y, s = 0.12f;
        seed = seed * 1103515245u + 12345u; x = (seed >> 8) / 16777216.0f * 2 - 1;
        seed = seed * 1103515245u + 12345u; y = (seed >> 8) / 16777216.0f * 2 - 1;
        x += 0.01f * (frame % 10);
        glColor4f(0.9f, 0.5f + 0.4f * x, 0.2f, 0.08f);
        glVertex2f(x - s, y - s); glVertex2f(x + s, y - s); glVertex2f(x + s, y + s); glVertex2f(x - s, y + s);
    }
    glEnd();
    glDisable(GL_BLEND);
}

/* Wide, stippled and 1-pixel lines and points. */
static void lines(int frame)
{
    int i;
    clear_2d(1, 1, 1);
    glRotatef((float)frame, 0, 0, 1);
    for (i = 0; i < 3; i++) {
        int k;
        glLineWidth(1.0f + 2 * i);
        if (i == 2) { glEnable(GL_LINE_STIPPLE); glLineStipple(2, 0x0F0F); }
        glBegin(GL_LINES);
        for (k = 0; k < 300; k++) {
            double a = 2 * M_PI * k / 300;
            glColor3f((float)k / 300, 0.2f * i, 1 - (float)k / 300);
            glVertex2d(0.1 * cos(a), 0.1 * sin(a));
            glVertex2d((0.5 + 0.2 * i) * cos(a), (0.5 + 0.2 * i) * sin(a));
        }
        glEnd();
        glDisable(GL_LINE_STIPPLE);
    }
    glLineWidth(1);
    glPointSize(3);
    glBegin(GL_POINTS);
    for (i = 0; i < 5000; i++) {
        glColor3f(0, 0.5f, 0);
        glVertex2f((i % 100) / 50.0f - 1, (i / 100) / 25.0f - 1);
    }
    glEnd();
    glPointSize(1);
}

/* Fill rate: 16 window-sized flat quads at decreasing depth (opaque overdraw 16). */
static void overdraw(int frame)
{
    int k;
    glClearColor(0, 0, 0, 1);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_LEQUAL);
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    glOrtho(-1, 1, -1, 1, -1, 1);
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
    glShadeModel(GL_SMOOTH);
    for (k = 0; k < 16; k++) {
        float z = 0.9f - k * 0.1f, s = 0.02f * ((k + frame) % 5);
        glBegin(GL_QUADS);
        glColor3f(k / 16.0f, 0.5f, 1 - k / 16.0f); glVertex3f(-1 + s, -1, -z);
        glColor3f(1, k / 16.0f, 0.2f); glVertex3f(1, -1 + s, -z);
        glColor3f(0.2f, 1, k / 16.0f); glVertex3f(1 - s, 1, -z);
        glColor3f(k / 16.0f, k / 16.0f, k / 16.0f); glVertex3f(-1, 1 - s, -z);
        glEnd();
    }
    glDepthFunc(GL_LESS);
}

/* Immediate-mode call throughput: 1,000,002 glVertex calls per frame, as
 * 333,334 small triangles on a 2-pixel grid (each ~1 pixel in area). */
static void tiny_triangles(void)
{
    int n = 333334, i, cols = W / 2;
    float sx = 2.0f / W, sy = 2.0f / H;
    glBegin(GL_TRIANGLES);
    for (i = 0; i < n; i++) {
        int c = i % cols, r = (i / cols) % (H / 2);
        float x = -1 + (2 * c + 0.25f) * sx, y = -1 + (2 * r + 0.25f) * sy;
        glColor3f((i & 255) / 255.0f, ((i >> 8) & 255) / 255.0f, 0.5f);
        glVertex2f(x, y);
        glVertex2f(x + 1.5f * sx, y);
        glVertex2f(x, y + 1.5f * sy);
    }
    glEnd();
}

static void calls(int use_list)
{
    clear_2d(0, 0, 0);
    if (use_list) {
        if (!list_id) {
            list_id = glGenLists(1);
            glNewList(list_id, GL_COMPILE);
            tiny_triangles();
            glEndList();
        }
        glCallList(list_id);
    } else {
        tiny_triangles();
    }
}

/* glReadPixels throughput: a clear and a triangle, then a full-frame read. */
static unsigned char *readback;
static void read_pixels(int frame)
{
    glClearColor(0.2f, 0.3f, 0.4f, 1);
    glClear(GL_COLOR_BUFFER_BIT);
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
    glBegin(GL_TRIANGLES);
    glColor3f(1, 0.5f, 0); glVertex2f(-0.9f, -0.9f);
    glColor3f(0, 1, 0.5f); glVertex2f(0.9f, -0.8f + 0.01f * (frame % 10));
    glColor3f(0.5f, 0, 1); glVertex2f(0, 0.9f);
    glEnd();
    glReadPixels(0, 0, W, H, GL_RGBA, GL_UNSIGNED_BYTE, readback);
}

/* Clears of colour, depth and stencil. */
static void clears(int frame)
{
    glClearColor((frame % 7) / 7.0f, 0.5f, 0.25f, 1);
    glClearDepth(1.0);
    glClearStencil(frame & 255);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT | GL_STENCIL_BUFFER_BIT);
}

static int render(const char *scene, int frame)
{
    if (!strcmp(scene, "spheres_s")) spheres(frame, 8);
    else if (!strcmp(scene, "spheres_m")) spheres(frame, 24);
    else if (!strcmp(scene, "spheres_l")) spheres(frame, 64);
    else if (!strcmp(scene, "overdraw")) overdraw(frame);
    else if (!strcmp(scene, "lit_spheres")) lit_spheres(frame);
    else if (!strcmp(scene, "particles")) particles(frame);
    else if (!strcmp(scene, "lines")) lines(frame);
    else if (!strcmp(scene, "immediate_1m")) calls(0);
    else if (!strcmp(scene, "display_list_1m")) calls(1);
    else if (!strcmp(scene, "readpixels")) read_pixels(frame);
    else if (!strcmp(scene, "clear")) clears(frame);
    else if (!strcmp(scene, "book_dino")) book_dino(frame);
    else if (!strcmp(scene, "book_decal")) book_decal(frame);
    else if (!strcmp(scene, "book_winding")) book_winding(frame);
    else if (!feature_scene(scene, frame)) return 0;
    glFinish();
    return 1;
}

int main(int argc, char **argv)
{
    const char *scene, *out;
    int frames, f, y;
    unsigned char *buf;
    double *ms, t, first_wall = 0, main_wall = wall(), ctx_wall = 0;
    const char *pause = getenv("BENCH_PAUSE_US");
    int pause_us = pause ? atoi(pause) : 0;
    OSMesaContext ctx;
    struct rusage ru;
    FILE *fp;

    if (argc != 6) {
        fprintf(stderr, "usage: %s SCENE WIDTH HEIGHT FRAMES OUT.pam\n", argv[0]);
        return 2;
    }
    scene = argv[1];
    W = atoi(argv[2]);
    H = atoi(argv[3]);
    frames = atoi(argv[4]);
    out = argv[5];
    buf = calloc((size_t)W * H, 4);
    readback = calloc((size_t)W * H, 4);
    ms = calloc(frames + 1, sizeof *ms);
    /* An accumulation buffer only where a scene uses it: it costs memory. */
    ctx = OSMesaCreateContextExt(OSMESA_RGBA, 24, 8, strcmp(scene, "accum_blur") ? 0 : 16, NULL);
    if (!ctx || !OSMesaMakeCurrent(ctx, buf, GL_UNSIGNED_BYTE, W, H)) {
        fprintf(stderr, "no OSMesa context\n");
        return 1;
    }
    ctx_wall = wall();
    glViewport(0, 0, W, H);
    for (f = 0; f <= frames; f++) {
        t = mono();
        if (!render(scene, f)) {
            fprintf(stderr, "unknown scene %s\n", scene);
            return 2;
        }
        if (f == 0)
            first_wall = wall();
        else
            ms[f - 1] = (mono() - t) * 1000;
        /* For measurements: a pause after each frame, as an interactive
         * program waiting for its next frame makes (round 29). */
        if (pause_us > 0)
            usleep(pause_us);
    }
    render(scene, IMAGE_FRAME);
    fp = fopen(out, "wb");
    if (fp) {
        fprintf(fp, "P7\nWIDTH %d\nHEIGHT %d\nDEPTH 4\nMAXVAL 255\nTUPLTYPE RGB_ALPHA\nENDHDR\n", W, H);
        for (y = H - 1; y >= 0; y--)
            fwrite(buf + (size_t)y * W * 4, 1, (size_t)W * 4, fp);
        fclose(fp);
    }
    getrusage(RUSAGE_SELF, &ru);
    printf("{\"renderer\": \"%s\", \"first_frame_wall\": %.6f, \"main_wall\": %.6f, \"context_wall\": %.6f, \"maxrss_kb\": %ld, \"gl_error\": %u, \"ms\": [",
           (const char *)glGetString(GL_RENDERER), first_wall, main_wall, ctx_wall, ru.ru_maxrss, glGetError());
    for (f = 0; f < frames; f++)
        printf("%s%.4f", f ? ", " : "", ms[f]);
    printf("]}\n");
    OSMesaDestroyContext(ctx);
    return 0;
}
