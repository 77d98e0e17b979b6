/* GLX drawables, contexts and presenting beyond the basics of glx_window.c:
 *
 *   shm       frames go through MIT-SHM (a System V segment is mapped in
 *             this process, sized to the window, re-made on resize) and
 *             reach the window correctly; with SOFTGL_NO_SHM=1 none is
 *             mapped and XPutImage shows the same pixels
 *   attribs   glXCreateContextAttribsARB: advertised, found by
 *             glXGetProcAddress, GL 1.0-1.5 contexts work, everything else
 *             is NULL with the error GLX_ARB_create_context names
 *   share     share lists of the three context-creating calls: a live
 *             context shares its display lists; a made-up or destroyed
 *             handle is GLXBadContext, a context of another screen
 *             BadMatch; glXDestroyContext, glXIsDirect, glXMakeCurrent and
 *             glXCopyContext of a bad handle are GLXBadContext
 *   bind      glXMakeCurrent/glXMakeContextCurrent errors: BadMatch (a
 *             context with None, NULL with a drawable), GLXBadDrawable (a
 *             destroyed or made-up window), BadAccess (current in another
 *             thread); the current context stays
 *   configs   a plain X window's visual names its FBConfig: single- and
 *             double-buffered visuals differ, glXGetConfig and
 *             glXQueryDrawable(GLX_FBCONFIG_ID) agree with the config whose
 *             GLX_VISUAL_ID is the window's visual
 *   multi     several contexts on one window, in one thread and in two:
 *             they all draw into the window's one framebuffer
 *   read      glXMakeContextCurrent with a read drawable other than the
 *             draw one: glReadPixels and glCopyPixels read the read one
 *   pbuffer   a pbuffer current in two contexts of a share group
 *   pixmap    a double-buffered GLXPixmap keeps a front buffer (what the X
 *             pixmap shows) beside its back buffer
 *   deferred  with the binned renderer (SOFTGL_THREADS=2), triangles drawn
 *             by the last GL call before a window-system call reach their
 *             window: when the context is then made current on another
 *             drawable, when another context is made current on the
 *             window, at glXSwapBuffers, and for a display list's triangles
 *             (winsys/bound.rs shades them before the drawable's
 *             framebuffer leaves the context at the end of each call)
 *   swap      GLX_EXT/MESA/SGI_swap_control: advertised, found, the
 *             interval starts at 0 and is per drawable; an interval of 3
 *             makes 10 swaps take at least 9 periods of SOFTGL_REFRESH_HZ
 *             (set to 100 here), 0 makes them quick again; errors (a
 *             negative EXT interval is BadValue, SGI's 0 GLX_BAD_VALUE,
 *             MESA's without a context GLX_BAD_CONTEXT);
 *             GLX_MESA_copy_sub_buffer shows just the rectangle of the
 *             back buffer, which stays as drawn
 *   bench W H N   N glXSwapBuffers of a WxH window: ms per present
 *
 * Run by c_tests/t_glx.sh on its Xvfb. Exit status: number of failures. */
#define _GNU_SOURCE
#include <GL/gl.h>
#include <GL/glx.h>
#include <X11/Xlib.h>
#include <X11/Xutil.h>
#include <pthread.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

static int failures;
#define CHECK(cond, ...)                                   \
    do {                                                   \
        if (!(cond)) {                                     \
            printf("  failure (line %d): ", __LINE__);     \
            printf(__VA_ARGS__);                           \
            printf("\n");                                  \
            failures++;                                    \
        }                                                  \
    } while (0)

static Display *dpy;
static XVisualInfo *vi;
static GLXFBConfig cfg;

static int shift_of(unsigned long m)
{
    int s = 0;
    while (m && !(m & 1)) {
        m >>= 1;
        s++;
    }
    return s;
}

/* The pixel at GL coordinates (x, y) of an X drawable of height h. */
static unsigned long x_pixel(Drawable d, int x, int y, int h, int rgb[3])
{
    XImage *img = XGetImage(dpy, d, x, h - 1 - y, 1, 1, AllPlanes, ZPixmap);
    if (!img) {
        rgb[0] = rgb[1] = rgb[2] = -1;
        return 0;
    }
    unsigned long p = XGetPixel(img, 0, 0);
    rgb[0] = (p & vi->red_mask) >> shift_of(vi->red_mask);
    rgb[1] = (p & vi->green_mask) >> shift_of(vi->green_mask);
    rgb[2] = (p & vi->blue_mask) >> shift_of(vi->blue_mask);
    XDestroyImage(img);
    return p;
}

static void expect_x(Drawable d, int x, int y, int h, int r, int g, int b, const char *what)
{
    int c[3];
    x_pixel(d, x, y, h, c);
    CHECK(c[0] == r && c[1] == g && c[2] == b, "%s: X pixel (%d,%d) is %d,%d,%d, expected %d,%d,%d", what, x, y, c[0], c[1], c[2], r, g, b);
}

static void expect_gl(int x, int y, int r, int g, int b, const char *what)
{
    unsigned char p[4] = {0, 0, 0, 0};
    glReadPixels(x, y, 1, 1, GL_RGBA, GL_UNSIGNED_BYTE, p);
    CHECK(p[0] == r && p[1] == g && p[2] == b, "%s: glReadPixels(%d,%d) is %d,%d,%d, expected %d,%d,%d", what, x, y, p[0], p[1], p[2], r, g, b);
}

static Window make_window(int w, int h)
{
    XSetWindowAttributes a;
    a.colormap = XCreateColormap(dpy, RootWindow(dpy, vi->screen), vi->visual, AllocNone);
    a.border_pixel = 0;
    a.background_pixmap = None;
    Window win = XCreateWindow(dpy, RootWindow(dpy, vi->screen), 0, 0, w, h, 0, vi->depth, InputOutput, vi->visual, CWColormap | CWBorderPixel | CWBackPixmap, &a);
    XMapWindow(dpy, win);
    XSync(dpy, False);
    return win;
}

static GLXContext new_context(GLXContext share)
{
    return glXCreateNewContext(dpy, cfg, GLX_RGBA_TYPE, share, True);
}

static void rect(float x0, float y0, float x1, float y1, int w, int h)
{
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    glOrtho(0, w, 0, h, -1, 1);
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
    glRectf(x0, y0, x1, y1);
}

/* Bytes of System V shared memory mapped in this process (/proc/self/maps
 * names such mappings "/SYSV<key>"). */
static long sysv_mapped(void)
{
    FILE *f = fopen("/proc/self/maps", "r");
    char line[512];
    long total = 0;
    if (!f)
        return -1;
    while (fgets(line, sizeof line, f)) {
        unsigned long a, b;
        if (strstr(line, "/SYSV") && sscanf(line, "%lx-%lx", &a, &b) == 2)
            total += (long)(b - a);
    }
    fclose(f);
    return total;
}

static void run_shm(void)
{
    int no_shm = getenv("SOFTGL_NO_SHM") && strcmp(getenv("SOFTGL_NO_SHM"), "0") != 0;
    int w = 160, h = 120;
    Window win = make_window(w, h);
    GLXContext ctx = new_context(NULL);
    CHECK(glXMakeCurrent(dpy, win, ctx), "glXMakeCurrent");
    long before = sysv_mapped();
    glClearColor(0, 0, 1, 1);
    glClear(GL_COLOR_BUFFER_BIT);
    glColor3ub(255, 128, 0);
    rect(10, 20, 50, 60, w, h);
    glXSwapBuffers(dpy, win);
    XSync(dpy, False);
    expect_x(win, 30, 40, h, 255, 128, 0, "shm: rectangle");
    expect_x(win, 100, 100, h, 0, 0, 255, "shm: background");
    expect_x(win, 10, 20, h, 255, 128, 0, "shm: rectangle corner (rows not flipped wrong)");
    long seg = sysv_mapped() - before;
    long need = (long)w * h * 4;
    if (no_shm)
        CHECK(seg == 0, "SOFTGL_NO_SHM=1 but %ld bytes of SysV memory are mapped", seg);
    else
        CHECK(seg >= need && seg < need + 8192, "no MIT-SHM segment of %ld bytes mapped (%ld)", need, seg);
    /* A resize: the segment is made again at the new size. */
    XResizeWindow(dpy, win, 200, 150);
    XSync(dpy, False);
    glXSwapBuffers(dpy, win); /* follows the size for the next frame */
    w = 200, h = 150;
    glViewport(0, 0, w, h);
    glClearColor(0, 1, 0, 1);
    glClear(GL_COLOR_BUFFER_BIT);
    glColor3ub(255, 0, 255);
    rect(150, 100, 190, 140, w, h);
    glXSwapBuffers(dpy, win);
    XSync(dpy, False);
    expect_x(win, 170, 120, h, 255, 0, 255, "shm after resize: rectangle");
    expect_x(win, 5, 5, h, 0, 255, 0, "shm after resize: background");
    seg = sysv_mapped() - before;
    need = (long)w * h * 4;
    if (!no_shm)
        CHECK(seg >= need && seg < need + 8192, "after a resize: no segment of %ld bytes (%ld mapped)", need, seg);
    glXMakeCurrent(dpy, None, NULL);
    glXDestroyContext(dpy, ctx);
    XDestroyWindow(dpy, win);
    XSync(dpy, False);
    printf("  %s: %s\n", no_shm ? "XPutImage" : "MIT-SHM", failures ? "failed" : "ok");
}

/* ---- GLX_ARB_create_context ---- */

static int last_error, last_request, last_minor;
static int glx_error_base;

static int on_error(Display *d, XErrorEvent *e)
{
    (void)d;
    last_error = e->error_code;
    last_request = e->request_code;
    last_minor = e->minor_code;
    return 0;
}

/* Creates a context from `attribs`; expects it to work (err == 0) or to
 * fail with X error `err` (GLX errors: glx_error_base + n). */
static void try_attribs(PFNGLXCREATECONTEXTATTRIBSARBPROC create, const int *attribs, int err, const char *what)
{
    last_error = 0;
    GLXContext c = create(dpy, cfg, NULL, True, attribs);
    XSync(dpy, False);
    if (err == 0) {
        CHECK(c != NULL && last_error == 0, "%s: no context (error %d)", what, last_error);
        if (c) {
            Window win = make_window(8, 8);
            CHECK(glXMakeCurrent(dpy, win, c), "%s: glXMakeCurrent", what);
            const char *v = (const char *)glGetString(GL_VERSION);
            CHECK(v && strncmp(v, "1.5", 3) == 0, "%s: GL_VERSION %s", what, v ? v : "(null)");
            glXMakeCurrent(dpy, None, NULL);
            glXDestroyContext(dpy, c);
            XDestroyWindow(dpy, win);
        }
    } else {
        CHECK(c == NULL, "%s: made a context", what);
        CHECK(last_error == err, "%s: X error %d, expected %d", what, last_error, err);
        int major, ev, er;
        XQueryExtension(dpy, "GLX", &major, &ev, &er);
        CHECK(last_error == 0 || (last_request == major && last_minor == 34), "%s: error for request %d.%d, expected GLX (%d).34", what, last_request, last_minor, major);
    }
}

static void run_attribs(void)
{
    const char *ext = glXQueryExtensionsString(dpy, vi->screen);
    CHECK(ext && strstr(ext, "GLX_ARB_create_context ") && strstr(ext, "GLX_ARB_create_context_profile"), "extensions: %s", ext ? ext : "(null)");
    PFNGLXCREATECONTEXTATTRIBSARBPROC create = (PFNGLXCREATECONTEXTATTRIBSARBPROC)glXGetProcAddress((const GLubyte *)"glXCreateContextAttribsARB");
    CHECK(create != NULL, "glXGetProcAddress(glXCreateContextAttribsARB)");
    if (!create)
        return;
    int major, ev;
    if (!XQueryExtension(dpy, "GLX", &major, &ev, &glx_error_base)) {
        printf("  note: the server has no GLX extension: GLX errors are not checked\n");
        glx_error_base = -1000;
    }
    const int bad_fbconfig = glx_error_base + 9, bad_profile = glx_error_base + 13;
    XErrorHandler old = XSetErrorHandler(on_error);
    try_attribs(create, NULL, 0, "NULL list");
    const int empty[] = {None};
    try_attribs(create, empty, 0, "empty list");
    for (int minor = 0; minor <= 5; minor++) {
        int a[] = {GLX_CONTEXT_MAJOR_VERSION_ARB, 1, GLX_CONTEXT_MINOR_VERSION_ARB, minor, None};
        char what[32];
        snprintf(what, sizeof what, "version 1.%d", minor);
        try_attribs(create, a, 0, what);
    }
    const int debug[] = {GLX_CONTEXT_FLAGS_ARB, GLX_CONTEXT_DEBUG_BIT_ARB, GLX_CONTEXT_PROFILE_MASK_ARB, GLX_CONTEXT_COMPATIBILITY_PROFILE_BIT_ARB, GLX_RENDER_TYPE, GLX_RGBA_TYPE, None};
    try_attribs(create, debug, 0, "debug flag, compatibility profile");
    const int v16[] = {GLX_CONTEXT_MAJOR_VERSION_ARB, 1, GLX_CONTEXT_MINOR_VERSION_ARB, 6, None};
    try_attribs(create, v16, BadMatch, "version 1.6");
    const int v22[] = {GLX_CONTEXT_MAJOR_VERSION_ARB, 2, GLX_CONTEXT_MINOR_VERSION_ARB, 2, None};
    try_attribs(create, v22, BadMatch, "version 2.2");
    const int v0[] = {GLX_CONTEXT_MAJOR_VERSION_ARB, 0, None};
    try_attribs(create, v0, BadMatch, "version 0.0");
    const int fwd[] = {GLX_CONTEXT_MAJOR_VERSION_ARB, 1, GLX_CONTEXT_MINOR_VERSION_ARB, 5, GLX_CONTEXT_FLAGS_ARB, GLX_CONTEXT_FORWARD_COMPATIBLE_BIT_ARB, None};
    try_attribs(create, fwd, BadMatch, "forward-compatible 1.5");
    if (glx_error_base >= 0) {
        const int v20[] = {GLX_CONTEXT_MAJOR_VERSION_ARB, 2, GLX_CONTEXT_MINOR_VERSION_ARB, 0, None};
        try_attribs(create, v20, bad_fbconfig, "version 2.0 (defined, not supported)");
        const int v33[] = {GLX_CONTEXT_MAJOR_VERSION_ARB, 3, GLX_CONTEXT_MINOR_VERSION_ARB, 3, GLX_CONTEXT_PROFILE_MASK_ARB, GLX_CONTEXT_CORE_PROFILE_BIT_ARB, None};
        try_attribs(create, v33, bad_fbconfig, "version 3.3 core");
        const int p0[] = {GLX_CONTEXT_PROFILE_MASK_ARB, 0, None};
        try_attribs(create, p0, bad_profile, "profile mask 0");
        const int p3[] = {GLX_CONTEXT_PROFILE_MASK_ARB, 3, None};
        try_attribs(create, p3, bad_profile, "profile mask core|compatibility");
    }
    const int flag8[] = {GLX_CONTEXT_FLAGS_ARB, 8, None};
    try_attribs(create, flag8, BadValue, "unknown flag");
    const int unknown[] = {0x2093, 0, None};
    try_attribs(create, unknown, BadValue, "unknown attribute");
    XSetErrorHandler(old);
    printf("  attribs: %s\n", failures ? "failed" : "ok");
}

/* ---- share lists ---- */

/* Expects `c` to be NULL with X error `err` for GLX request `minor`. */
static void expect_error(const void *c, int err, int minor, const char *what)
{
    XSync(dpy, False);
    int major, ev, er;
    XQueryExtension(dpy, "GLX", &major, &ev, &er);
    CHECK(c == NULL, "%s: made a context", what);
    CHECK(last_error == err, "%s: X error %d, expected %d", what, last_error, err);
    CHECK(last_request == major && last_minor == minor, "%s: error for request %d.%d, expected GLX (%d).%d", what, last_request, last_minor, major, minor);
    last_error = last_request = last_minor = 0;
}

static void run_share(void)
{
    PFNGLXCREATECONTEXTATTRIBSARBPROC create = (PFNGLXCREATECONTEXTATTRIBSARBPROC)glXGetProcAddress((const GLubyte *)"glXCreateContextAttribsARB");
    int major, ev;
    if (!create || !XQueryExtension(dpy, "GLX", &major, &ev, &glx_error_base)) {
        CHECK(create != NULL, "glXGetProcAddress(glXCreateContextAttribsARB)");
        printf("  note: the server has no GLX extension (GLX errors have no numbers): share lists not checked\n");
        return;
    }
    const int bad_context = glx_error_base + 0;
    XErrorHandler old = XSetErrorHandler(on_error);
    last_error = 0;

    /* A live share context: its display list is seen by all three. */
    Window win = make_window(8, 8);
    GLXContext a = new_context(NULL);
    CHECK(a && glXMakeCurrent(dpy, win, a), "context A");
    GLuint list = glGenLists(1);
    glNewList(list, GL_COMPILE);
    glColor3ub(1, 2, 3);
    glEndList();
    GLXContext made[3] = {
        glXCreateContext(dpy, vi, a, True),
        glXCreateNewContext(dpy, cfg, GLX_RGBA_TYPE, a, True),
        create(dpy, cfg, a, True, NULL),
    };
    XSync(dpy, False);
    CHECK(last_error == 0, "sharing with a live context: X error %d", last_error);
    for (int i = 0; i < 3; i++) {
        CHECK(made[i] && glXMakeCurrent(dpy, win, made[i]), "shared context %d", i);
        CHECK(glIsList(list), "shared context %d does not see A's display list", i);
    }

    /* A made-up handle (never dereferenced by softgl) and a destroyed one. */
    int not_a_context[64] = {0};
    GLXContext bogus = (GLXContext)not_a_context;
    GLXContext dead = new_context(NULL);
    glXDestroyContext(dpy, dead);
    XSync(dpy, False);
    CHECK(last_error == 0, "glXDestroyContext of a live context: X error %d", last_error);
    GLXContext bad[2] = {bogus, dead};
    const char *names[2] = {"made-up share list", "destroyed share list"};
    for (int i = 0; i < 2; i++) {
        char what[80];
        snprintf(what, sizeof what, "glXCreateContext, %s", names[i]);
        expect_error(glXCreateContext(dpy, vi, bad[i], True), bad_context, 3, what);
        snprintf(what, sizeof what, "glXCreateNewContext, %s", names[i]);
        expect_error(glXCreateNewContext(dpy, cfg, GLX_RGBA_TYPE, bad[i], True), bad_context, 24, what);
        snprintf(what, sizeof what, "glXCreateContextAttribsARB, %s", names[i]);
        expect_error(create(dpy, cfg, bad[i], True, NULL), bad_context, 34, what);
    }

    /* Other calls given a bad handle. */
    glXDestroyContext(dpy, bogus);
    expect_error(NULL, bad_context, 4, "glXDestroyContext(made-up)");
    glXDestroyContext(dpy, dead);
    expect_error(NULL, bad_context, 4, "glXDestroyContext twice");
    CHECK(!glXIsDirect(dpy, bogus), "glXIsDirect(made-up) is True");
    expect_error(NULL, bad_context, 6, "glXIsDirect(made-up)");
    CHECK(glXIsDirect(dpy, a), "glXIsDirect(A) is False");
    CHECK(!glXMakeCurrent(dpy, win, dead), "glXMakeCurrent(destroyed) succeeded");
    expect_error(NULL, bad_context, 5, "glXMakeCurrent(destroyed)");
    CHECK(!glXMakeContextCurrent(dpy, win, win, bogus), "glXMakeContextCurrent(made-up) succeeded");
    expect_error(NULL, bad_context, 26, "glXMakeContextCurrent(made-up)");
    CHECK(glXGetCurrentContext() == made[2], "a failed glXMakeCurrent changed the current context");
    glXCopyContext(dpy, bogus, a, GL_ALL_ATTRIB_BITS);
    expect_error(NULL, bad_context, 10, "glXCopyContext(made-up, A)");
    int value = 0;
    CHECK(glXQueryContext(dpy, bogus, GLX_FBCONFIG_ID, &value) == GLX_BAD_CONTEXT, "glXQueryContext(made-up)");

    /* A share list of another screen: BadMatch. */
    if (ScreenCount(dpy) > 1) {
        int s1 = (DefaultScreen(dpy) + 1) % ScreenCount(dpy);
        int fattribs[] = {GLX_RENDER_TYPE, GLX_RGBA_BIT, None};
        int n = 0;
        GLXFBConfig *cs = glXChooseFBConfig(dpy, s1, fattribs, &n);
        CHECK(cs && n > 0, "no FBConfig on screen %d", s1);
        if (cs && n > 0) {
            GLXContext other = glXCreateNewContext(dpy, cs[0], GLX_RGBA_TYPE, NULL, True);
            XSync(dpy, False);
            CHECK(other && last_error == 0, "context on screen %d", s1);
            expect_error(glXCreateContext(dpy, vi, other, True), BadMatch, 3, "glXCreateContext, share list of another screen");
            expect_error(glXCreateNewContext(dpy, cfg, GLX_RGBA_TYPE, other, True), BadMatch, 24, "glXCreateNewContext, share list of another screen");
            expect_error(create(dpy, cfg, other, True, NULL), BadMatch, 34, "glXCreateContextAttribsARB, share list of another screen");
            glXDestroyContext(dpy, other);
            XFree(cs);
        }
    } else {
        printf("  note: one screen: share lists of another screen not checked\n");
    }

    glXMakeCurrent(dpy, None, NULL);
    for (int i = 0; i < 3; i++)
        if (made[i])
            glXDestroyContext(dpy, made[i]);
    glXDestroyContext(dpy, a);
    XSync(dpy, False);
    CHECK(last_error == 0, "destroying the live contexts: X error %d", last_error);
    XDestroyWindow(dpy, win);
    XSetErrorHandler(old);
    printf("  share: %s\n", failures ? "failed" : "ok");
}

/* ---- glXMakeCurrent's errors ---- */

static pthread_barrier_t bind_barrier;
static GLXContext bind_ctx;
static Window bind_win;

static void *thread_holds(void *arg)
{
    (void)arg;
    int ok = glXMakeCurrent(dpy, bind_win, bind_ctx);
    pthread_barrier_wait(&bind_barrier); /* 1: current here */
    pthread_barrier_wait(&bind_barrier); /* 2: the main thread has tried */
    glXMakeCurrent(dpy, None, NULL);
    return (void *)(long)ok;
}

static void run_bind(void)
{
    int major, ev;
    if (!XQueryExtension(dpy, "GLX", &major, &ev, &glx_error_base)) {
        printf("  note: the server has no GLX extension (GLX errors have no numbers): bind not checked\n");
        return;
    }
    const int bad_drawable = glx_error_base + 2;
    XErrorHandler old = XSetErrorHandler(on_error);
    last_error = last_request = last_minor = 0;
    Window win = make_window(16, 16), gone = make_window(16, 16);
    XDestroyWindow(dpy, gone);
    XSync(dpy, False);
    GLXContext c = new_context(NULL), other = new_context(NULL);
    CHECK(c && other && glXMakeCurrent(dpy, win, c), "context C on a window");
    XSync(dpy, False);
    CHECK(last_error == 0, "binding C: X error %d", last_error);

    CHECK(!glXMakeCurrent(dpy, win, NULL), "glXMakeCurrent(window, NULL) succeeded");
    expect_error(NULL, BadMatch, 5, "glXMakeCurrent(window, NULL)");
    CHECK(!glXMakeContextCurrent(dpy, None, None, other), "glXMakeContextCurrent(None, None, a GL 1.5 context) succeeded");
    expect_error(NULL, BadMatch, 26, "glXMakeContextCurrent(None, None, ctx)");
    CHECK(!glXMakeContextCurrent(dpy, win, None, other), "glXMakeContextCurrent(window, None, ctx) succeeded");
    expect_error(NULL, BadMatch, 26, "glXMakeContextCurrent(window, None, ctx)");
    CHECK(!glXMakeCurrent(dpy, gone, other), "glXMakeCurrent(destroyed window) succeeded");
    expect_error(NULL, bad_drawable, 5, "glXMakeCurrent(destroyed window)");
    CHECK(!glXMakeContextCurrent(dpy, win, 0x1fffff0, other), "glXMakeContextCurrent(window, made-up read drawable) succeeded");
    expect_error(NULL, bad_drawable, 26, "glXMakeContextCurrent(window, made-up read drawable)");
    CHECK(glXGetCurrentContext() == c && glXGetCurrentDrawable() == win, "a failed glXMakeCurrent changed the current context");

    /* BadAccess: `other` is current in another thread. */
    bind_ctx = other;
    bind_win = win;
    pthread_barrier_init(&bind_barrier, NULL, 2);
    pthread_t t;
    pthread_create(&t, NULL, thread_holds, NULL);
    pthread_barrier_wait(&bind_barrier);
    CHECK(!glXMakeCurrent(dpy, win, other), "glXMakeCurrent of a context current in another thread succeeded");
    expect_error(NULL, BadAccess, 5, "glXMakeCurrent(context current in another thread)");
    pthread_barrier_wait(&bind_barrier);
    void *held = NULL;
    pthread_join(t, &held);
    pthread_barrier_destroy(&bind_barrier);
    CHECK(held != NULL, "the other thread could not make its context current");
    CHECK(glXMakeCurrent(dpy, win, other), "glXMakeCurrent once the other thread released it");
    XSync(dpy, False);
    CHECK(last_error == 0, "binding released context: X error %d", last_error);

    glXMakeCurrent(dpy, None, NULL);
    glXDestroyContext(dpy, c);
    glXDestroyContext(dpy, other);
    XDestroyWindow(dpy, win);
    XSetErrorHandler(old);
    printf("  bind: %s\n", failures ? "failed" : "ok");
}

/* ---- a window's visual names its FBConfig ---- */

/* The first config (glXGetFBConfigs order) whose GLX_VISUAL_ID is `id`, as
 * piglit and toolkits find a visual's config. */
/* The config a chosen visual stands for: its GLX_VISUAL_ID, and (RGB and
 * RGBA configs share visuals) the alpha, depth and buffering glXGetConfig
 * reports for the visual. */
static GLXFBConfig config_of_visual(XVisualInfo *vis)
{
    static const int same[] = {GLX_ALPHA_SIZE, GLX_DEPTH_SIZE, GLX_DOUBLEBUFFER};
    int n = 0;
    GLXFBConfig *cs = glXGetFBConfigs(dpy, DefaultScreen(dpy), &n), found = NULL;
    for (int i = 0; cs && i < n && !found; i++) {
        int v = 0, ok = glXGetFBConfigAttrib(dpy, cs[i], GLX_VISUAL_ID, &v) == Success && (VisualID)v == vis->visualid;
        for (int k = 0; k < 3 && ok; k++) {
            int want = -1, have = -2;
            glXGetConfig(dpy, vis, same[k], &want);
            glXGetFBConfigAttrib(dpy, cs[i], same[k], &have);
            ok = want == have;
        }
        if (ok)
            found = cs[i];
    }
    if (cs)
        XFree(cs);
    return found;
}

static void run_configs(void)
{
    /* The premise: two TrueColor visuals of the chosen visual's depth (a
     * server with GLX has hundreds; one without may have one). */
    XVisualInfo tmpl = {0};
    tmpl.screen = vi->screen;
    tmpl.depth = vi->depth;
    tmpl.class = TrueColor;
    int nvis = 0;
    XVisualInfo *all = XGetVisualInfo(dpy, VisualScreenMask | VisualDepthMask | VisualClassMask, &tmpl, &nvis);
    if (all)
        XFree(all);
    if (nvis < 2) {
        printf("  note: one TrueColor visual of depth %d: both configs share it; configs not checked\n", vi->depth);
        return;
    }
    int single_attribs[] = {GLX_RGBA, GLX_RED_SIZE, 8, GLX_DEPTH_SIZE, 24, None};
    XVisualInfo *vis[2] = {glXChooseVisual(dpy, DefaultScreen(dpy), single_attribs), vi};
    CHECK(vis[0] && vis[0]->visualid != vi->visualid, "single- and double-buffered visuals are the same (0x%lx)", vi->visualid);
    if (!vis[0])
        return;
    for (int dbl = 0; dbl < 2; dbl++) {
        XVisualInfo *v = vis[dbl];
        int value = -1;
        CHECK(glXGetConfig(dpy, v, GLX_DOUBLEBUFFER, &value) == 0 && value == dbl, "visual 0x%lx: glXGetConfig(GLX_DOUBLEBUFFER) is %d, expected %d", v->visualid, value, dbl);
        GLXFBConfig c = config_of_visual(v);
        CHECK(c != NULL, "visual 0x%lx: no config has it as GLX_VISUAL_ID", v->visualid);
        if (!c)
            continue;
        int want_id = 0, cdbl = -1;
        glXGetFBConfigAttrib(dpy, c, GLX_FBCONFIG_ID, &want_id);
        glXGetFBConfigAttrib(dpy, c, GLX_DOUBLEBUFFER, &cdbl);
        CHECK(cdbl == dbl, "visual 0x%lx: its config %d has GLX_DOUBLEBUFFER %d", v->visualid, want_id, cdbl);
        /* A plain X window of that visual, bound with a glXCreateContext
         * context of the same visual. */
        XVisualInfo *save = vi;
        vi = v;
        Window win = make_window(16, 16);
        vi = save;
        GLXContext ctx = glXCreateContext(dpy, v, NULL, True);
        CHECK(ctx && glXMakeCurrent(dpy, win, ctx), "visual 0x%lx: context", v->visualid);
        unsigned int id = 0;
        glXQueryDrawable(dpy, win, GLX_FBCONFIG_ID, &id);
        CHECK((int)id == want_id, "visual 0x%lx: glXQueryDrawable(window, GLX_FBCONFIG_ID) is %u, expected %d", v->visualid, id, want_id);
        int ctx_id = 0;
        glXQueryContext(dpy, ctx, GLX_FBCONFIG_ID, &ctx_id);
        CHECK(ctx_id == want_id, "visual 0x%lx: glXQueryContext(GLX_FBCONFIG_ID) is %d, expected %d", v->visualid, ctx_id, want_id);
        GLint db = -1;
        glGetIntegerv(GL_DOUBLEBUFFER, &db);
        CHECK(db == dbl, "visual 0x%lx: GL_DOUBLEBUFFER is %d", v->visualid, db);
        glXMakeCurrent(dpy, None, NULL);
        if (ctx)
            glXDestroyContext(dpy, ctx);
        XDestroyWindow(dpy, win);
    }
    XFree(vis[0]);
    printf("  configs: %s\n", failures ? "failed" : "ok");
}

/* ---- RGB configs (ALPHA_SIZE 0) ---- */

/* First config of a glXChooseFBConfig request, with its alpha size. */
static GLXFBConfig first_config(const int *attribs, int *alpha, int *count)
{
    int n = 0;
    GLXFBConfig *cs = glXChooseFBConfig(dpy, DefaultScreen(dpy), attribs, &n), c = NULL;
    *count = n;
    *alpha = -1;
    if (cs && n > 0) {
        c = cs[0];
        glXGetFBConfigAttrib(dpy, c, GLX_ALPHA_SIZE, alpha);
        /* Asked for alpha: every config returned has it. */
        for (int i = 1; i < n && *alpha > 0; i++) {
            int a = -1;
            glXGetFBConfigAttrib(dpy, cs[i], GLX_ALPHA_SIZE, &a);
            CHECK(a > 0, "config %d of a request for alpha has GLX_ALPHA_SIZE %d", i, a);
        }
    }
    if (cs)
        XFree(cs);
    return c;
}

/* Draws a 16x16 window with `c` and checks what alpha reads as: `rgb`
 * says the config has none (so alpha is 1.0 whatever is written). */
static void check_alpha(GLXFBConfig c, int rgb)
{
    XVisualInfo *v = glXGetVisualFromFBConfig(dpy, c), *save = vi;
    CHECK(v != NULL, "no visual for the config");
    if (!v)
        return;
    vi = v;
    Window win = make_window(16, 16);
    vi = save;
    GLXContext ctx = glXCreateNewContext(dpy, c, GLX_RGBA_TYPE, NULL, True);
    CHECK(ctx && glXMakeCurrent(dpy, win, ctx), "rgb=%d: context", rgb);
    GLint bits = -1;
    glGetIntegerv(GL_ALPHA_BITS, &bits);
    CHECK(bits == (rgb ? 0 : 8), "rgb=%d: GL_ALPHA_BITS is %d", rgb, bits);
    glViewport(0, 0, 16, 16);
    glClearColor(0.2f, 0.4f, 0.6f, 0.0f);
    glClear(GL_COLOR_BUFFER_BIT);
    GLubyte px[4] = {0};
    glReadPixels(4, 4, 1, 1, GL_RGBA, GL_UNSIGNED_BYTE, px);
    CHECK(px[3] == (rgb ? 255 : 0), "rgb=%d: alpha after clearing to 0 reads %d", rgb, px[3]);
    GLfloat f[4] = {0};
    glReadPixels(4, 4, 1, 1, GL_RGBA, GL_FLOAT, f);
    CHECK(f[3] == (rgb ? 1.0f : 0.0f), "rgb=%d: float alpha reads %g", rgb, f[3]);
    /* A quad with alpha 0.25, no blending: alpha is written only with
     * an alpha buffer. */
    glColor4f(0.0f, 0.0f, 0.0f, 0.25f);
    glRectf(-1, -1, 1, 1);
    glReadPixels(4, 4, 1, 1, GL_RGBA, GL_UNSIGNED_BYTE, px);
    CHECK(px[3] == (rgb ? 255 : 64), "rgb=%d: alpha after drawing 0.25 reads %d", rgb, px[3]);
    /* Destination alpha: 1.0 without an alpha buffer, 0.25 with. */
    glEnable(GL_BLEND);
    glBlendFunc(GL_DST_ALPHA, GL_ZERO);
    glColor4f(1.0f, 1.0f, 1.0f, 1.0f);
    glRectf(-1, -1, 1, 1);
    glDisable(GL_BLEND);
    glReadPixels(4, 4, 1, 1, GL_RGBA, GL_UNSIGNED_BYTE, px);
    int want = rgb ? 255 : 64;
    CHECK(abs(px[0] - want) <= 1 && abs(px[1] - want) <= 1, "rgb=%d: GL_DST_ALPHA blend gives %d %d %d %d, want red and green %d", rgb, px[0], px[1], px[2], px[3], want);
    glXMakeCurrent(dpy, None, NULL);
    if (ctx)
        glXDestroyContext(dpy, ctx);
    XDestroyWindow(dpy, win);
    XFree(v);
}

static void run_rgb(void)
{
    int alpha = -1, n = 0;
    /* GLX 1.4 table 3.5: alpha not asked for is not counted, and the
     * smaller GLX_BUFFER_SIZE comes first: an RGB config. */
    int no_alpha[] = {GLX_RENDER_TYPE, GLX_RGBA_BIT, GLX_DOUBLEBUFFER, True, GLX_RED_SIZE, 8, GLX_GREEN_SIZE, 8, GLX_BLUE_SIZE, 8, None};
    GLXFBConfig rgb = first_config(no_alpha, &alpha, &n);
    CHECK(rgb && alpha == 0, "first config without alpha asked: GLX_ALPHA_SIZE %d (%d configs)", alpha, n);
    int with_alpha[] = {GLX_RENDER_TYPE, GLX_RGBA_BIT, GLX_DOUBLEBUFFER, True, GLX_ALPHA_SIZE, 1, None};
    GLXFBConfig rgba = first_config(with_alpha, &alpha, &n);
    CHECK(rgba && alpha == 8, "first config with alpha asked: GLX_ALPHA_SIZE %d (%d configs)", alpha, n);
    int buffer = -1;
    if (rgb) {
        glXGetFBConfigAttrib(dpy, rgb, GLX_BUFFER_SIZE, &buffer);
        CHECK(buffer == 24, "RGB config: GLX_BUFFER_SIZE %d", buffer);
    }
    /* glXChooseVisual hands out only RGBA configs (the RGB ones share
     * their visuals; a visual names the first config that has it). */
    int v_no_alpha[] = {GLX_RGBA, GLX_DOUBLEBUFFER, GLX_DEPTH_SIZE, 1, None};
    int v_alpha[] = {GLX_RGBA, GLX_DOUBLEBUFFER, GLX_ALPHA_SIZE, 1, None};
    XVisualInfo *v0 = glXChooseVisual(dpy, DefaultScreen(dpy), v_no_alpha);
    int a0 = -1, d0 = -1;
    if (v0) {
        glXGetConfig(dpy, v0, GLX_ALPHA_SIZE, &a0);
        glXGetConfig(dpy, v0, GLX_DEPTH_SIZE, &d0);
        XFree(v0);
    }
    CHECK(a0 == 8 && d0 == 24, "glXChooseVisual without alpha: GLX_ALPHA_SIZE %d, GLX_DEPTH_SIZE %d", a0, d0);
    XVisualInfo *v1 = glXChooseVisual(dpy, DefaultScreen(dpy), v_alpha);
    int a1 = -1;
    if (v1) {
        glXGetConfig(dpy, v1, GLX_ALPHA_SIZE, &a1);
        XFree(v1);
    }
    CHECK(a1 == 8, "glXChooseVisual with alpha: GLX_ALPHA_SIZE %d", a1);
    if (rgb)
        check_alpha(rgb, 1);
    if (rgba)
        check_alpha(rgba, 0);
    printf("  rgb: %s\n", failures ? "failed" : "ok");
}

/* ---- binned triangles and window-system calls ---- */

/* A quad of colour `rgb` over the middle of a 64x64 drawable, drawn with
 * glBegin/glEnd (the glEnd call is the last GL call) or glCallList. */
static void quad(const unsigned char rgb[3], GLuint list)
{
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    glOrtho(0, 64, 0, 64, -1, 1);
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
    glColor3ubv(rgb);
    if (list) {
        glCallList(list);
        return;
    }
    glBegin(GL_QUADS);
    glVertex2f(16, 16);
    glVertex2f(48, 16);
    glVertex2f(48, 48);
    glVertex2f(16, 48);
    glEnd();
}

static void run_deferred(void)
{
    static const unsigned char green[3] = {0, 255, 0}, blue[3] = {0, 0, 255}, yellow[3] = {255, 255, 0}, white[3] = {255, 255, 255};
    Window b = make_window(64, 64), a = make_window(64, 64);
    /* B would cover A on the screen (both at 0,0). */
    XUnmapWindow(dpy, b);
    GLXContext c = new_context(NULL), d = new_context(c);
    CHECK(c && d, "contexts");

    /* 1. Drawn on A, then made current on B before any flush. */
    CHECK(glXMakeCurrent(dpy, a, c), "C on A");
    glClearColor(1, 0, 0, 1);
    glClear(GL_COLOR_BUFFER_BIT);
    quad(green, 0);
    CHECK(glXMakeCurrent(dpy, b, c), "C on B");
    glClearColor(0, 0, 0, 1);
    glClear(GL_COLOR_BUFFER_BIT);
    expect_gl(32, 32, 0, 0, 0, "B is only cleared (A's quad did not land in B)");
    CHECK(glXMakeCurrent(dpy, a, c), "C on A again");
    expect_gl(32, 32, 0, 255, 0, "A's quad, drawn before C moved to B");
    expect_gl(4, 4, 255, 0, 0, "A's clear");

    /* 2. Drawn on A by C, then D is made current on A. */
    quad(blue, 0);
    CHECK(glXMakeCurrent(dpy, a, d), "D on A");
    expect_gl(32, 32, 0, 0, 255, "D sees C's quad drawn just before the switch");

    /* 3. A display list's triangles (one call, several primitives). */
    GLuint list = glGenLists(1);
    glNewList(list, GL_COMPILE);
    glBegin(GL_TRIANGLES);
    glVertex2f(16, 16);
    glVertex2f(48, 16);
    glVertex2f(48, 48);
    glEnd();
    glBegin(GL_TRIANGLES);
    glVertex2f(16, 16);
    glVertex2f(48, 48);
    glVertex2f(16, 48);
    glEnd();
    glEndList();
    quad(yellow, list);
    CHECK(glXMakeCurrent(dpy, b, d), "D on B");
    CHECK(glXMakeCurrent(dpy, a, c), "C on A (3)");
    expect_gl(32, 32, 255, 255, 0, "the display list's quad, drawn by D before it moved to B");
    expect_gl(20, 40, 255, 255, 0, "the display list's second triangle");

    /* 4. glXSwapBuffers right after the draw: the window shows the quad. */
    quad(white, 0);
    glXSwapBuffers(dpy, a);
    XSync(dpy, False);
    expect_x(a, 32, 32, 64, 255, 255, 255, "window A after glXSwapBuffers right after the draw");
    expect_x(a, 4, 4, 64, 255, 0, 0, "window A's clear");

    glXMakeCurrent(dpy, None, NULL);
    glXDestroyContext(dpy, c);
    glXDestroyContext(dpy, d);
    XDestroyWindow(dpy, a);
    XDestroyWindow(dpy, b);
    printf("  deferred: %s\n", failures ? "failed" : "ok");
}

/* ---- several contexts on one window ---- */

static Window shared_win;
static const int MW = 100, MH = 80;

static void *thread_draw(void *arg)
{
    GLXContext c = new_context(NULL);
    if (!glXMakeCurrent(dpy, shared_win, c)) {
        printf("  failure: thread glXMakeCurrent\n");
        failures++;
        return NULL;
    }
    glColor3ub(0, 0, 255);
    rect(60, 10, 90, 40, MW, MH);
    glFlush();
    glXMakeCurrent(dpy, None, NULL);
    glXDestroyContext(dpy, c);
    (void)arg;
    return NULL;
}

static void run_multi(void)
{
    shared_win = make_window(MW, MH);
    GLXContext a = new_context(NULL), b = new_context(NULL);
    CHECK(glXMakeCurrent(dpy, shared_win, a), "make A current");
    glClearColor(1, 1, 1, 1);
    glClear(GL_COLOR_BUFFER_BIT);
    glColor3ub(255, 0, 0);
    rect(10, 10, 40, 40, MW, MH);
    CHECK(glXMakeCurrent(dpy, shared_win, b), "make B current");
    glColor3ub(0, 255, 0);
    rect(30, 30, 60, 60, MW, MH);
    expect_gl(20, 20, 255, 0, 0, "B sees A's rectangle");
    CHECK(glXMakeCurrent(dpy, shared_win, a), "make A current again");
    expect_gl(50, 50, 0, 255, 0, "A sees B's rectangle");
    expect_gl(5, 70, 255, 255, 255, "A's clear");
    /* Another thread draws with its own context while A stays current here. */
    pthread_t t;
    pthread_create(&t, NULL, thread_draw, NULL);
    pthread_join(t, NULL);
    expect_gl(75, 25, 0, 0, 255, "A sees the other thread's rectangle");
    expect_gl(20, 20, 255, 0, 0, "A's rectangle is still there");
    glXSwapBuffers(dpy, shared_win);
    XSync(dpy, False);
    expect_x(shared_win, 75, 25, MH, 0, 0, 255, "window after swap: the thread's rectangle");
    expect_x(shared_win, 50, 50, MH, 0, 255, 0, "window after swap: B's rectangle");
    glXMakeCurrent(dpy, None, NULL);
    glXDestroyContext(dpy, a);
    glXDestroyContext(dpy, b);
    XDestroyWindow(dpy, shared_win);
    printf("  multi: %s\n", failures ? "failed" : "ok");
}

/* ---- separate read drawable ---- */

static GLXPbuffer pbuffer(int w, int h)
{
    int attribs[] = {GLX_PBUFFER_WIDTH, w, GLX_PBUFFER_HEIGHT, h, None};
    return glXCreatePbuffer(dpy, cfg, attribs);
}

static void run_read(void)
{
    GLXPbuffer pa = pbuffer(64, 64), pb = pbuffer(32, 32);
    GLXContext c = new_context(NULL);
    CHECK(pa && pb && c, "pbuffers and context");
    /* B: blue with a yellow corner. */
    CHECK(glXMakeContextCurrent(dpy, pb, pb, c), "bind B");
    glClearColor(0, 0, 1, 1);
    glClear(GL_COLOR_BUFFER_BIT);
    glColor3ub(255, 255, 0);
    rect(0, 0, 8, 8, 32, 32);
    /* A: grey. */
    CHECK(glXMakeContextCurrent(dpy, pa, pa, c), "bind A");
    glClearColor(0.5f, 0.5f, 0.5f, 1);
    glClear(GL_COLOR_BUFFER_BIT);
    expect_gl(40, 40, 128, 128, 128, "A cleared");
    /* Draw A, read B. */
    CHECK(glXMakeContextCurrent(dpy, pa, pb, c), "draw A read B");
    CHECK(glXGetCurrentDrawable() == pa && glXGetCurrentReadDrawable() == pb, "current draw/read drawables");
    expect_gl(20, 20, 0, 0, 255, "glReadPixels reads B");
    expect_gl(2, 2, 255, 255, 0, "glReadPixels reads B's corner");
    glViewport(0, 0, 64, 64); /* the first binding (B) set it to 32x32 */
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    glOrtho(0, 64, 0, 64, -1, 1);
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
    glRasterPos2i(40, 40);
    glCopyPixels(0, 0, 16, 16, GL_COLOR); /* B's (0..16) to A's (40..56) */
    glColor3ub(255, 0, 0);
    glRectf(0, 0, 4, 4); /* drawn into A */
    /* Back to A alone: the copy and the rectangle are there. */
    CHECK(glXMakeContextCurrent(dpy, pa, pa, c), "bind A again");
    expect_gl(42, 42, 255, 255, 0, "glCopyPixels brought B's yellow corner into A");
    expect_gl(52, 52, 0, 0, 255, "glCopyPixels brought B's blue into A");
    expect_gl(60, 60, 128, 128, 128, "A outside the copy");
    expect_gl(1, 1, 255, 0, 0, "drawing went to A");
    CHECK(glXMakeContextCurrent(dpy, pb, pb, c), "bind B again");
    expect_gl(1, 1, 255, 255, 0, "B unchanged");
    glXMakeContextCurrent(dpy, None, None, NULL);
    glXDestroyContext(dpy, c);
    glXDestroyPbuffer(dpy, pa);
    glXDestroyPbuffer(dpy, pb);
    printf("  read: %s\n", failures ? "failed" : "ok");
}

/* ---- a pbuffer in two contexts of a share group ---- */

static GLXPbuffer shared_pb;
static GLXContext shared_b;
static GLuint shared_tex;

static void *thread_pbuffer(void *arg)
{
    (void)arg;
    if (!glXMakeContextCurrent(dpy, shared_pb, shared_pb, shared_b)) {
        printf("  failure: thread bind of the pbuffer\n");
        failures++;
        return NULL;
    }
    /* The texture A made, drawn into the pbuffer A drew into. */
    glEnable(GL_TEXTURE_2D);
    glBindTexture(GL_TEXTURE_2D, shared_tex);
    glColor3ub(255, 255, 255);
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    glOrtho(0, 32, 0, 32, -1, 1);
    glBegin(GL_QUADS);
    glTexCoord2f(0, 0); glVertex2f(16, 16);
    glTexCoord2f(1, 0); glVertex2f(32, 16);
    glTexCoord2f(1, 1); glVertex2f(32, 32);
    glTexCoord2f(0, 1); glVertex2f(16, 32);
    glEnd();
    glFinish();
    glXMakeContextCurrent(dpy, None, None, NULL);
    return NULL;
}

static void run_pbuffer(void)
{
    shared_pb = pbuffer(32, 32);
    GLXContext a = new_context(NULL);
    shared_b = new_context(a);
    CHECK(glXMakeContextCurrent(dpy, shared_pb, shared_pb, a), "A binds the pbuffer");
    glClearColor(1, 0, 0, 1);
    glClear(GL_COLOR_BUFFER_BIT);
    static const unsigned char green[4] = {0, 255, 0, 255};
    glGenTextures(1, &shared_tex);
    glBindTexture(GL_TEXTURE_2D, shared_tex);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 1, 1, 0, GL_RGBA, GL_UNSIGNED_BYTE, green);
    glFinish();
    /* B in the same thread, while A is released... */
    CHECK(glXMakeContextCurrent(dpy, shared_pb, shared_pb, shared_b), "B binds the pbuffer");
    expect_gl(5, 5, 255, 0, 0, "B sees A's clear");
    glScissor(0, 0, 8, 8);
    glEnable(GL_SCISSOR_TEST);
    glClearColor(0, 0, 1, 1);
    glClear(GL_COLOR_BUFFER_BIT);
    glDisable(GL_SCISSOR_TEST);
    glXMakeContextCurrent(dpy, None, None, NULL);
    /* ... and in another thread while A is current here. */
    CHECK(glXMakeContextCurrent(dpy, shared_pb, shared_pb, a), "A binds the pbuffer again");
    expect_gl(2, 2, 0, 0, 255, "A sees B's clear");
    pthread_t t;
    pthread_create(&t, NULL, thread_pbuffer, NULL);
    pthread_join(t, NULL);
    expect_gl(24, 24, 0, 255, 0, "A sees B's textured quad (shared texture)");
    expect_gl(10, 10, 255, 0, 0, "A's clear elsewhere");
    glXMakeContextCurrent(dpy, None, None, NULL);
    glXDestroyContext(dpy, shared_b);
    glXDestroyContext(dpy, a);
    glXDestroyPbuffer(dpy, shared_pb);
    printf("  pbuffer: %s\n", failures ? "failed" : "ok");
}

/* ---- a double-buffered GLXPixmap ---- */

static void run_pixmap(void)
{
    int w = 40, h = 30;
    Pixmap px = XCreatePixmap(dpy, RootWindow(dpy, vi->screen), w, h, vi->depth);
    GLXPixmap gp = glXCreateGLXPixmap(dpy, vi, px);
    int dbl = 0;
    glXGetConfig(dpy, vi, GLX_DOUBLEBUFFER, &dbl);
    CHECK(dbl, "the visual is double-buffered");
    GLXContext c = glXCreateContext(dpy, vi, NULL, True);
    CHECK(glXMakeCurrent(dpy, gp, c), "bind the GLXPixmap");
    GLint db = 0;
    glGetIntegerv(GL_DRAW_BUFFER, &db);
    CHECK(db == GL_BACK, "draw buffer %#x, expected GL_BACK", db);
    glClearColor(0, 1, 0, 1); /* back: green */
    glClear(GL_COLOR_BUFFER_BIT);
    glDrawBuffer(GL_FRONT);
    glClearColor(0, 0, 1, 1); /* front: blue */
    glClear(GL_COLOR_BUFFER_BIT);
    glXSwapBuffers(dpy, gp); /* no effect on a pixmap (GLX 1.4 section 3.3.10) */
    glFinish();
    XSync(dpy, False);
    expect_x(px, 5, 5, h, 0, 0, 255, "the X pixmap shows the front buffer");
    glReadBuffer(GL_BACK);
    expect_gl(5, 5, 0, 255, 0, "the back buffer is kept");
    glReadBuffer(GL_FRONT);
    expect_gl(5, 5, 0, 0, 255, "the front buffer");
    glXMakeCurrent(dpy, None, NULL);
    glXDestroyContext(dpy, c);
    glXDestroyGLXPixmap(dpy, gp);
    XFreePixmap(dpy, px);
    printf("  pixmap: %s\n", failures ? "failed" : "ok");
}

static double now(void)
{
    struct timespec t;
    clock_gettime(CLOCK_MONOTONIC, &t);
    return t.tv_sec + t.tv_nsec * 1e-9;
}

static void run_bench(int w, int h, int n)
{
    Window win = make_window(w, h);
    GLXContext c = new_context(NULL);
    glXMakeCurrent(dpy, win, c);
    double total = 0, best = 1e9;
    for (int i = 0; i < n; i++) {
        glClearColor((i & 1) ? 1 : 0, 0.5f, 0, 1);
        glClear(GL_COLOR_BUFFER_BIT);
        glFinish();
        double t0 = now();
        glXSwapBuffers(dpy, win);
        XSync(dpy, False);
        double dt = now() - t0;
        if (i > 0) { /* the first one makes the segment */
            total += dt;
            if (dt < best)
                best = dt;
        }
    }
    printf("present %dx%d (%s): mean %.2f ms, best %.2f ms over %d frames\n", w, h, getenv("SOFTGL_NO_SHM") ? "XPutImage" : "MIT-SHM if available", 1000 * total / (n - 1), 1000 * best, n - 1);
    glXMakeCurrent(dpy, None, NULL);
    glXDestroyContext(dpy, c);
}

/* ---- swap control and copy_sub_buffer ---- */

static int x_error_code;
static int catch_error(Display *d, XErrorEvent *e)
{
    (void)d;
    x_error_code = e->error_code;
    return 0;
}

static double now_ms(void)
{
    struct timespec t;
    clock_gettime(CLOCK_MONOTONIC, &t);
    return t.tv_sec * 1e3 + t.tv_nsec / 1e6;
}

static double swaps_ms(Window win, int n)
{
    double t0 = now_ms();
    for (int i = 0; i < n; i++) {
        glClear(GL_COLOR_BUFFER_BIT);
        glXSwapBuffers(dpy, win);
    }
    return now_ms() - t0;
}

static void run_swap(void)
{
    const char *ext = glXQueryExtensionsString(dpy, DefaultScreen(dpy));
    const char *names[] = {"GLX_EXT_swap_control", "GLX_MESA_swap_control", "GLX_SGI_swap_control", "GLX_MESA_copy_sub_buffer"};
    for (int i = 0; i < 4; i++)
        CHECK(ext && strstr(ext, names[i]), "%s not advertised", names[i]);
    typedef void (*SetExt)(Display *, GLXDrawable, int);
    typedef int (*SetMesa)(unsigned);
    typedef int (*GetMesa)(void);
    typedef int (*SetSgi)(int);
    typedef void (*CopySub)(Display *, GLXDrawable, int, int, int, int);
    SetExt set_ext = (SetExt)glXGetProcAddress((const GLubyte *)"glXSwapIntervalEXT");
    SetMesa set_mesa = (SetMesa)glXGetProcAddress((const GLubyte *)"glXSwapIntervalMESA");
    GetMesa get_mesa = (GetMesa)glXGetProcAddress((const GLubyte *)"glXGetSwapIntervalMESA");
    SetSgi set_sgi = (SetSgi)glXGetProcAddress((const GLubyte *)"glXSwapIntervalSGI");
    CopySub copy_sub = (CopySub)glXGetProcAddress((const GLubyte *)"glXCopySubBufferMESA");
    if (!set_ext || !set_mesa || !get_mesa || !set_sgi || !copy_sub) {
        CHECK(0, "a swap-control or copy_sub_buffer entry point is missing");
        return;
    }
    CHECK(set_mesa(1) == GLX_BAD_CONTEXT, "glXSwapIntervalMESA without a context is not GLX_BAD_CONTEXT");
    int w = 64, h = 48;
    Window win = make_window(w, h), other = make_window(w, h);
    GLXContext ctx = new_context(NULL);
    CHECK(glXMakeCurrent(dpy, win, ctx), "glXMakeCurrent");
    glXMakeCurrent(dpy, other, ctx);
    glXMakeCurrent(dpy, win, ctx);
    unsigned v = 99, max = 0;
    glXQueryDrawable(dpy, win, GLX_SWAP_INTERVAL_EXT, &v);
    glXQueryDrawable(dpy, win, GLX_MAX_SWAP_INTERVAL_EXT, &max);
    CHECK(v == 0, "initial GLX_SWAP_INTERVAL_EXT is %u, expected 0", v);
    CHECK(max >= 1, "GLX_MAX_SWAP_INTERVAL_EXT is %u", max);
    CHECK(get_mesa() == 0, "glXGetSwapIntervalMESA is %d, expected 0", get_mesa());
    double quick = swaps_ms(win, 10);
    set_ext(dpy, win, 3);
    glXQueryDrawable(dpy, win, GLX_SWAP_INTERVAL_EXT, &v);
    CHECK(v == 3, "after glXSwapIntervalEXT(3) the interval is %u", v);
    CHECK(get_mesa() == 3, "glXGetSwapIntervalMESA is %d after EXT's 3", get_mesa());
    glXQueryDrawable(dpy, other, GLX_SWAP_INTERVAL_EXT, &v);
    CHECK(v == 0, "another drawable's interval changed to %u", v);
    /* SOFTGL_REFRESH_HZ=100: 3 periods are 30 ms, so 10 swaps (9 gaps) take
     * at least 270 ms. */
    double paced = swaps_ms(win, 10);
    CHECK(paced >= 265, "10 swaps at interval 3 and 100 Hz took %.1f ms (at least 270 expected)", paced);
    CHECK(set_mesa(0) == 0, "glXSwapIntervalMESA(0) failed");
    double again = swaps_ms(win, 10);
    CHECK(again < 200, "10 swaps at interval 0 took %.1f ms", again);
    CHECK(set_sgi(0) == GLX_BAD_VALUE, "glXSwapIntervalSGI(0) is not GLX_BAD_VALUE");
    CHECK(set_sgi(2) == 0 && get_mesa() == 2, "glXSwapIntervalSGI(2) did not set 2");
    XErrorHandler old = XSetErrorHandler(catch_error);
    x_error_code = 0;
    set_ext(dpy, win, -1);
    XSync(dpy, False);
    CHECK(x_error_code == BadValue, "glXSwapIntervalEXT(-1) gave X error %d, expected BadValue", x_error_code);
    XSetErrorHandler(old);
    set_mesa(0);
    XDestroyWindow(dpy, other); /* it covers win, whose pixels are read next */
    XSync(dpy, False);
    printf("  10 swaps: %.1f ms at interval 0, %.1f ms at 3 (100 Hz), %.1f ms at 0 again\n", quick, paced, again);

    /* copy_sub_buffer: blue frame shown; then green back buffer, of which
     * only (10,10)-(30,20) reaches the window. */
    glViewport(0, 0, w, h);
    glClearColor(0, 0, 1, 1);
    glClear(GL_COLOR_BUFFER_BIT);
    glXSwapBuffers(dpy, win);
    glClearColor(0, 1, 0, 1);
    glClear(GL_COLOR_BUFFER_BIT);
    copy_sub(dpy, win, 10, 10, 20, 10);
    XSync(dpy, False);
    expect_x(win, 15, 15, h, 0, 255, 0, "copy_sub_buffer: inside the rectangle");
    expect_x(win, 29, 19, h, 0, 255, 0, "copy_sub_buffer: the rectangle's last pixel");
    expect_x(win, 30, 15, h, 0, 0, 255, "copy_sub_buffer: right of the rectangle");
    expect_x(win, 15, 20, h, 0, 0, 255, "copy_sub_buffer: above the rectangle");
    expect_x(win, 5, 5, h, 0, 0, 255, "copy_sub_buffer: outside");
    glReadBuffer(GL_BACK);
    expect_gl(5, 5, 0, 255, 0, "copy_sub_buffer: back buffer unchanged");
    glReadBuffer(GL_FRONT);
    expect_gl(15, 15, 0, 255, 0, "copy_sub_buffer: front buffer inside");
    expect_gl(40, 40, 0, 0, 255, "copy_sub_buffer: front buffer outside");
    copy_sub(dpy, win, -100, -100, 1000, 1000); /* clipped to the window */
    XSync(dpy, False);
    expect_x(win, 5, 5, h, 0, 255, 0, "copy_sub_buffer: clipped whole window");
    glXMakeCurrent(dpy, None, NULL);
    glXDestroyContext(dpy, ctx);
    XDestroyWindow(dpy, win);
    printf("  swap control, copy_sub_buffer: %s\n", failures ? "failed" : "ok");
}

int main(int argc, char **argv)
{
    const char *mode = argc > 1 ? argv[1] : "shm";
    /* Binning needs two rasterizer threads (with one, triangles are shaded
     * at once); softgl reads this when the first context is made. */
    if (!strcmp(mode, "deferred"))
        setenv("SOFTGL_THREADS", "2", 1);
    if (!strcmp(mode, "swap"))
        setenv("SOFTGL_REFRESH_HZ", "100", 1);
    dpy = XOpenDisplay(NULL);
    if (!dpy) {
        printf("SKIP glx_drawables: cannot open display\n");
        return 77;
    }
    int attribs[] = {GLX_RGBA, GLX_RED_SIZE, 8, GLX_GREEN_SIZE, 8, GLX_BLUE_SIZE, 8, GLX_DOUBLEBUFFER, GLX_DEPTH_SIZE, 24, None};
    vi = glXChooseVisual(dpy, DefaultScreen(dpy), attribs);
    int fattribs[] = {GLX_RENDER_TYPE, GLX_RGBA_BIT, GLX_DRAWABLE_TYPE, GLX_WINDOW_BIT | GLX_PBUFFER_BIT, GLX_DOUBLEBUFFER, True, GLX_RED_SIZE, 8, None};
    int n = 0;
    GLXFBConfig *cs = glXChooseFBConfig(dpy, DefaultScreen(dpy), fattribs, &n);
    if (!vi || !cs || n == 0) {
        printf("FAIL glx_drawables: no visual or FBConfig\n");
        return 1;
    }
    /* The config of the chosen visual, so windows made with vi match. */
    cfg = cs[0];
    for (int i = 0; i < n; i++) {
        int id = 0;
        glXGetFBConfigAttrib(dpy, cs[i], GLX_VISUAL_ID, &id);
        if ((VisualID)id == vi->visualid) {
            cfg = cs[i];
            break;
        }
    }
    if (!strcmp(mode, "shm"))
        run_shm();
    else if (!strcmp(mode, "attribs"))
        run_attribs();
    else if (!strcmp(mode, "share"))
        run_share();
    else if (!strcmp(mode, "configs"))
        run_configs();
    else if (!strcmp(mode, "rgb"))
        run_rgb();
    else if (!strcmp(mode, "bind"))
        run_bind();
    else if (!strcmp(mode, "deferred"))
        run_deferred();
    else if (!strcmp(mode, "multi"))
        run_multi();
    else if (!strcmp(mode, "read"))
        run_read();
    else if (!strcmp(mode, "pbuffer"))
        run_pbuffer();
    else if (!strcmp(mode, "pixmap"))
        run_pixmap();
    else if (!strcmp(mode, "swap"))
        run_swap();
    else if (!strcmp(mode, "bench") && argc > 4)
        run_bench(atoi(argv[2]), atoi(argv[3]), atoi(argv[4]));
    else {
        printf("unknown mode %s\n", mode);
        return 2;
    }
    XCloseDisplay(dpy);
    if (!strcmp(mode, "shm")) {
        /* Closing the display frees what softgl kept for it: the window's
         * segment goes with its drawable. */
        long left = sysv_mapped();
        CHECK(left == 0, "after XCloseDisplay %ld bytes of SysV memory are still mapped", left);
    }
    return failures;
}
