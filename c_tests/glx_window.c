/* glx_window: renders into an X window through softgl's GLX and reads the
 * window back with XGetImage.  Built and run by t_glx.sh on its own Xvfb.
 *
 *   glx_window visual     glXChooseVisual + glXCreateContext, double-
 *                         buffered, shown by glXSwapBuffers; then the window
 *                         is resized and the next frame must fill it
 *   glx_window fbconfig   glXChooseFBConfig + glXCreateNewContext +
 *                         glXCreateWindow + glXMakeContextCurrent, single-
 *                         buffered, shown by glFinish; then the same
 *                         context on a GLXPixmap (glXCreatePixmap)
 *   glx_window rootcount  prints the number of non-black pixels on the
 *                         root window (a cheap screenshot check for
 *                         glxgears; start Xvfb with -br)
 *   glx_window screenshot OUT.ppm  writes the root window (the X screen)
 *                         as a binary PPM and prints "window X Y W H", the
 *                         top-most mapped window on it (where a program's
 *                         window is, on a server with no window manager)
 *
 * Scene (GL window coordinates, origin bottom-left): clear to blue, a red
 * triangle (0,0) (W/2,0) (0,H/2).  In X's top-down coordinates the triangle
 * is at the bottom left, so the checks catch a missing row flip.
 * Exit 0 when every check passes; prints "FAIL ..." lines otherwise. */
#include <GL/glx.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static int failures;

#define CHECK(cond, ...)                                 \
    do {                                                 \
        if (!(cond)) {                                   \
            printf("FAIL %s:%d: ", __FILE__, __LINE__);  \
            printf(__VA_ARGS__);                         \
            printf("\n");                                \
            failures++;                                  \
        }                                                \
    } while (0)

static int shift_of(unsigned long m)
{
    int s = 0;
    while (m && !(m & 1)) {
        m >>= 1;
        s++;
    }
    return s;
}

/* The "screenshot" mode: the root window as a PPM, and the top-most
 * viewable child's geometry. */
static int screenshot(Display *dpy, const char *path)
{
    Window root = DefaultRootWindow(dpy), r, parent, *kids = NULL;
    unsigned int n = 0, i;
    XWindowAttributes wa;
    XImage *img;
    FILE *f;
    int x, y;
    XGetWindowAttributes(dpy, root, &wa);
    img = XGetImage(dpy, root, 0, 0, wa.width, wa.height, AllPlanes, ZPixmap);
    if (!img || !(f = fopen(path, "wb"))) {
        printf("FAIL screenshot: XGetImage of the root window or %s\n", path);
        return 1;
    }
    fprintf(f, "P6\n%d %d\n255\n", wa.width, wa.height);
    for (y = 0; y < wa.height; y++)
        for (x = 0; x < wa.width; x++) {
            unsigned long p = XGetPixel(img, x, y);
            unsigned char rgb[3] = {(unsigned char)((p & img->red_mask) >> shift_of(img->red_mask)),
                                    (unsigned char)((p & img->green_mask) >> shift_of(img->green_mask)),
                                    (unsigned char)((p & img->blue_mask) >> shift_of(img->blue_mask))};
            fwrite(rgb, 1, 3, f);
        }
    fclose(f);
    XDestroyImage(img);
    /* Children come bottom to top: the last viewable one is on top. */
    XQueryTree(dpy, root, &r, &parent, &kids, &n);
    for (i = n; i-- > 0;) {
        XWindowAttributes ka;
        if (XGetWindowAttributes(dpy, kids[i], &ka) && ka.map_state == IsViewable) {
            printf("window %d %d %d %d\n", ka.x + ka.border_width, ka.y + ka.border_width, ka.width, ka.height);
            break;
        }
    }
    if (i == (unsigned int)-1)
        printf("window none\n");
    if (kids)
        XFree(kids);
    return 0;
}

/* Reads X pixel (x, y) of the window as 8-bit R, G, B. */
static void read_pixel(Display *dpy, Window win, const XVisualInfo *vi, int x, int y, int rgb[3])
{
    XImage *img = XGetImage(dpy, win, x, y, 1, 1, AllPlanes, ZPixmap);
    unsigned long p;
    if (!img) {
        rgb[0] = rgb[1] = rgb[2] = -1;
        return;
    }
    p = XGetPixel(img, 0, 0);
    rgb[0] = (int)((p & vi->red_mask) >> shift_of(vi->red_mask)) & 0xff;
    rgb[1] = (int)((p & vi->green_mask) >> shift_of(vi->green_mask)) & 0xff;
    rgb[2] = (int)((p & vi->blue_mask) >> shift_of(vi->blue_mask)) & 0xff;
    XDestroyImage(img);
}

static void expect_pixel(Display *dpy, Window win, const XVisualInfo *vi, int x, int y, int r, int g, int b, const char *what)
{
    int c[3];
    read_pixel(dpy, win, vi, x, y, c);
    CHECK(abs(c[0] - r) <= 1 && abs(c[1] - g) <= 1 && abs(c[2] - b) <= 1,
          "%s: X pixel (%d,%d) is %d,%d,%d, expected %d,%d,%d", what, x, y, c[0], c[1], c[2], r, g, b);
}

static Window make_window(Display *dpy, const XVisualInfo *vi, int w, int h)
{
    XSetWindowAttributes swa;
    Window root = RootWindow(dpy, vi->screen), win;
    XEvent ev;
    memset(&swa, 0, sizeof swa);
    swa.colormap = XCreateColormap(dpy, root, vi->visual, AllocNone);
    swa.border_pixel = 0;
    swa.event_mask = StructureNotifyMask | ExposureMask;
    win = XCreateWindow(dpy, root, 0, 0, w, h, 0, vi->depth, InputOutput, vi->visual,
                        CWColormap | CWBorderPixel | CWEventMask, &swa);
    XMapWindow(dpy, win);
    do
        XNextEvent(dpy, &ev);
    while (ev.type != MapNotify || ev.xmap.window != win);
    return win;
}

static void draw_scene(int w, int h)
{
    glViewport(0, 0, w, h);
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    glOrtho(0, w, 0, h, -1, 1);
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
    glClearColor(0, 0, 1, 1);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    glColor3f(1, 0, 0);
    glBegin(GL_TRIANGLES);
    glVertex2i(0, 0);
    glVertex2i(w / 2, 0);
    glVertex2i(0, h / 2);
    glEnd();
}

/* The scene's pixels, in X coordinates of a w x h window. */
static void check_scene(Display *dpy, Window win, const XVisualInfo *vi, int w, int h, const char *what)
{
    expect_pixel(dpy, win, vi, 2, h - 3, 255, 0, 0, what);     /* GL (2,2): triangle */
    expect_pixel(dpy, win, vi, 2, 2, 0, 0, 255, what);         /* GL top left: clear */
    expect_pixel(dpy, win, vi, w - 3, h - 3, 0, 0, 255, what); /* GL bottom right */
    expect_pixel(dpy, win, vi, w - 3, 2, 0, 0, 255, what);     /* GL top right */
}

static int noted_error;
static int note_error(Display *d, XErrorEvent *e)
{
    (void)d;
    noted_error = e->error_code;
    return 0;
}

static void check_common(Display *dpy, GLXContext ctx, Window drawable)
{
    int major = 0, minor = 0, eb, evb;
    const char *ext = glXQueryExtensionsString(dpy, DefaultScreen(dpy));
    const char *r = (const char *)glGetString(GL_RENDERER);
    CHECK(glXQueryExtension(dpy, &eb, &evb), "glXQueryExtension");
    CHECK(glXQueryVersion(dpy, &major, &minor) && major == 1 && minor == 4, "glXQueryVersion %d.%d", major, minor);
    CHECK(ext && strstr(ext, "GLX_ARB_create_context"), "extensions string '%s'", ext ? ext : "(null)");
    CHECK(glXGetClientString(dpy, GLX_VENDOR) != NULL, "glXGetClientString(GLX_VENDOR)");
    CHECK(glXQueryServerString(dpy, DefaultScreen(dpy), GLX_VERSION) != NULL, "glXQueryServerString(GLX_VERSION)");
    CHECK(r && strstr(r, "softgl"), "GL_RENDERER '%s'", r ? r : "(null)");
    CHECK(glXGetCurrentContext() == ctx, "glXGetCurrentContext");
    CHECK(glXGetCurrentDrawable() == drawable, "glXGetCurrentDrawable");
    CHECK(glXGetCurrentReadDrawable() == drawable, "glXGetCurrentReadDrawable");
    CHECK(glXGetCurrentDisplay() == dpy, "glXGetCurrentDisplay");
    CHECK(glXIsDirect(dpy, ctx), "glXIsDirect");
    CHECK(glXGetProcAddressARB((const GLubyte *)"glClear") == (__GLXextFuncPtr)glClear, "glXGetProcAddressARB(glClear)");
    CHECK(glXGetProcAddress((const GLubyte *)"glXSwapBuffers") == (__GLXextFuncPtr)glXSwapBuffers, "glXGetProcAddress(glXSwapBuffers)");
    CHECK(glXGetProcAddress((const GLubyte *)"gluPerspective") != NULL, "glXGetProcAddress(gluPerspective)");
    CHECK(glXGetProcAddress((const GLubyte *)"glXCreateContextAttribsARB") != NULL, "glXCreateContextAttribsARB is offered (glx_drawables.c tests it)");
    CHECK(glGetError() == GL_NO_ERROR, "GL error");
}

static int run_visual(Display *dpy)
{
    int attribs[] = {GLX_RGBA, GLX_RED_SIZE, 8, GLX_GREEN_SIZE, 8, GLX_BLUE_SIZE, 8, GLX_DEPTH_SIZE, 24,
                     GLX_STENCIL_SIZE, 8, GLX_DOUBLEBUFFER, None};
    int single[] = {GLX_RGBA, GLX_DEPTH_SIZE, 16, None};
    int ci[] = {GLX_DEPTH_SIZE, 16, None};
    int v = -1, w = 64, h = 48, bits;
    XVisualInfo *vi;
    GLXContext ctx;
    Window win;

    vi = glXChooseVisual(dpy, DefaultScreen(dpy), ci);
    CHECK(vi == NULL, "a colour-index visual was offered");
    vi = glXChooseVisual(dpy, DefaultScreen(dpy), single);
    CHECK(vi != NULL, "no single-buffered RGBA visual");
    if (vi) {
        CHECK(glXGetConfig(dpy, vi, GLX_DOUBLEBUFFER, &v) == 0 && v == 0, "single-buffered visual: GLX_DOUBLEBUFFER %d", v);
        XFree(vi);
    }
    vi = glXChooseVisual(dpy, DefaultScreen(dpy), attribs);
    if (!vi) {
        printf("FAIL glXChooseVisual found no visual\n");
        return 1;
    }
    CHECK(glXGetConfig(dpy, vi, GLX_USE_GL, &v) == 0 && v == 1, "GLX_USE_GL %d", v);
    CHECK(glXGetConfig(dpy, vi, GLX_RGBA, &v) == 0 && v == 1, "GLX_RGBA %d", v);
    CHECK(glXGetConfig(dpy, vi, GLX_DOUBLEBUFFER, &v) == 0 && v == 1, "GLX_DOUBLEBUFFER %d", v);
    CHECK(glXGetConfig(dpy, vi, GLX_DEPTH_SIZE, &v) == 0 && v >= 24, "GLX_DEPTH_SIZE %d", v);
    CHECK(glXGetConfig(dpy, vi, GLX_STENCIL_SIZE, &v) == 0 && v == 8, "GLX_STENCIL_SIZE %d", v);
    CHECK(glXGetConfig(dpy, vi, GLX_ACCUM_RED_SIZE, &v) == 0 && v == 16, "GLX_ACCUM_RED_SIZE %d", v);
    ctx = glXCreateContext(dpy, vi, NULL, True);
    if (!ctx) {
        printf("FAIL glXCreateContext\n");
        return 1;
    }
    win = make_window(dpy, vi, w, h);
    CHECK(glXMakeCurrent(dpy, win, ctx), "glXMakeCurrent");
    check_common(dpy, ctx, win);
    glGetIntegerv(GL_DEPTH_BITS, &bits);
    CHECK(bits >= 24, "GL_DEPTH_BITS %d", bits);
    glGetIntegerv(GL_STENCIL_BITS, &bits);
    CHECK(bits == 8, "GL_STENCIL_BITS %d", bits);

    draw_scene(w, h);
    glXSwapBuffers(dpy, win);
    XSync(dpy, False);
    check_scene(dpy, win, vi, w, h, "visual, after glXSwapBuffers");

    /* Resize: the framebuffer follows at the next glXSwapBuffers. */
    w = 96;
    h = 72;
    XResizeWindow(dpy, win, w, h);
    XSync(dpy, False);
    glXSwapBuffers(dpy, win);
    draw_scene(w, h);
    glXSwapBuffers(dpy, win);
    XSync(dpy, False);
    check_scene(dpy, win, vi, w, h, "visual, after a resize");

    /* Binding again what is already bound (freeglut does so before every
     * callback) keeps the context working. */
    CHECK(glXMakeCurrent(dpy, win, ctx), "glXMakeCurrent again");
    draw_scene(w, h);
    glXSwapBuffers(dpy, win);
    XSync(dpy, False);
    check_scene(dpy, win, vi, w, h, "visual, after binding again");

    /* Front and back buffers: drawing the front shows at glFlush; the back
     * buffer (still the scene: swaps copy) shows at the next swap. */
    glDrawBuffer(GL_FRONT);
    glClearColor(0, 1, 0, 1);
    glClear(GL_COLOR_BUFFER_BIT);
    glFlush();
    XSync(dpy, False);
    expect_pixel(dpy, win, vi, w - 3, 2, 0, 255, 0, "front buffer drawn, after glFlush");
    glDrawBuffer(GL_BACK);
    glXSwapBuffers(dpy, win);
    XSync(dpy, False);
    check_scene(dpy, win, vi, w, h, "visual, back buffer swapped over the front one");

    /* GLX events: the mask is stored per drawable. */
    {
        unsigned long mask = 1234;
        glXGetSelectedEvent(dpy, win, &mask);
        CHECK(mask == 0, "glXGetSelectedEvent before glXSelectEvent: 0x%lx", mask);
        glXSelectEvent(dpy, win, GLX_PBUFFER_CLOBBER_MASK);
        glXGetSelectedEvent(dpy, win, &mask);
        CHECK(mask == GLX_PBUFFER_CLOBBER_MASK, "glXGetSelectedEvent 0x%lx", mask);
    }

    /* A second context sharing the first one's lists; glXCopyContext
     * copies the colour-buffer group (the clear colour) into it. */
    {
        GLuint list = glGenLists(1);
        GLXContext ctx2 = glXCreateContext(dpy, vi, ctx, True);
        GLfloat cc[4] = {0, 0, 0, 0};
        glNewList(list, GL_COMPILE);
        glColor3f(1, 1, 0);
        glEndList();
        glClearColor(0.5f, 0.25f, 1, 1);
        CHECK(ctx2 != NULL, "glXCreateContext with a share list");
        glXCopyContext(dpy, ctx, ctx2, GL_COLOR_BUFFER_BIT);
        CHECK(glXMakeCurrent(dpy, win, ctx2), "glXMakeCurrent(ctx2)");
        CHECK(glIsList(list), "ctx2 sees ctx's display list %u", list);
        glGetFloatv(GL_COLOR_CLEAR_VALUE, cc);
        CHECK(cc[0] == 0.5f && cc[1] == 0.25f && cc[2] == 1, "glXCopyContext: clear colour %g,%g,%g", cc[0], cc[1], cc[2]);
        CHECK(glXMakeCurrent(dpy, win, ctx), "glXMakeCurrent(ctx) again");
        glXDestroyContext(dpy, ctx2);
        CHECK(glIsList(list), "ctx keeps the list after ctx2 is destroyed");
    }

    /* glXUseXFont with the server's "fixed" font (6x13): a built-in font
     * of cell height 13 draws 'H'; its lit pixels stay within 13 rows and
     * 6 columns of the raster position. A bad font id must not stop the
     * program (the default font is used). */
    {
        Font font = XLoadFont(dpy, "fixed");
        GLuint base = glGenLists(2);
        static unsigned char img[96 * 72 * 4];
        int x, y, lit = 0, x0 = 1000, x1 = -1, y0 = 1000, y1 = -1;
        glXUseXFont(font, 'H', 1, base);
        glXUseXFont((Font)0x1ffffff1, 'H', 1, base + 1);
        CHECK(glIsList(base) && glIsList(base + 1), "glXUseXFont made no lists");
        glClearColor(0, 0, 0, 0);
        glClear(GL_COLOR_BUFFER_BIT);
        glColor3f(1, 1, 1);
        glRasterPos2i(10, 10);
        glCallList(base);
        glReadPixels(0, 0, w, h, GL_RGBA, GL_UNSIGNED_BYTE, img);
        for (y = 0; y < h; y++)
            for (x = 0; x < w; x++)
                if (img[4 * (y * w + x)] == 255) {
                    lit++;
                    if (x < x0) x0 = x;
                    if (x > x1) x1 = x;
                    if (y < y0) y0 = y;
                    if (y > y1) y1 = y;
                }
        CHECK(lit > 10 && x0 >= 10 && x1 < 18 && y0 >= 7 && y1 < 23 && y1 - y0 >= 6,
              "glXUseXFont 'H': %d lit pixels in x %d..%d, y %d..%d", lit, x0, x1, y0, y1);
        printf("glXUseXFont 'H' (fixed): %d lit pixels in x %d..%d, y %d..%d\n", lit, x0, x1, y0, y1);
        {
            /* The default font (16 pixels) from the bad font id: a taller H. */
            int top = -1;
            glClear(GL_COLOR_BUFFER_BIT);
            glRasterPos2i(10, 10);
            glCallList(base + 1);
            glReadPixels(0, 0, w, h, GL_RGBA, GL_UNSIGNED_BYTE, img);
            for (y = 0; y < h; y++)
                for (x = 0; x < w; x++)
                    if (img[4 * (y * w + x)] == 255 && y > top)
                        top = y;
            printf("glXUseXFont 'H' (default font): top row %d\n", top);
            CHECK(top > y1, "the 16-pixel default H (top %d) is not taller than the fixed one (top %d)", top, y1);
        }
        XUnloadFont(dpy, font);
        CHECK(glGetError() == GL_NO_ERROR, "GL error after glXUseXFont");
    }

    /* A window id that does not exist: False with GLXBadDrawable (GLX
     * error 2) for the program's error handler (softgl's own XGetGeometry
     * error is caught), and the context stays usable. */
    {
        int major, ev, er;
        XErrorHandler old = XSetErrorHandler(note_error);
        noted_error = 0;
        CHECK(!glXMakeCurrent(dpy, (Window)0x1ffffff0, ctx), "glXMakeCurrent on a bad window succeeded");
        XSync(dpy, False);
        XSetErrorHandler(old);
        if (XQueryExtension(dpy, "GLX", &major, &ev, &er))
            CHECK(noted_error == er + 2, "bad window: X error %d, expected GLXBadDrawable (%d)", noted_error, er + 2);
    }
    CHECK(glXMakeCurrent(dpy, win, ctx), "glXMakeCurrent after a bad window");

    /* Destroying a current context defers until it is released. */
    glXDestroyContext(dpy, ctx);
    CHECK(glXGetCurrentContext() == ctx, "a destroyed current context stays current until released");
    CHECK(glXMakeCurrent(dpy, None, NULL), "glXMakeCurrent(None, NULL)");
    CHECK(glXGetCurrentContext() == NULL, "still current after release");
    XDestroyWindow(dpy, win);
    XFree(vi);
    return 0;
}

static int run_fbconfig(Display *dpy)
{
    int attribs[] = {GLX_RENDER_TYPE, GLX_RGBA_BIT, GLX_DRAWABLE_TYPE, GLX_WINDOW_BIT, GLX_RED_SIZE, 8,
                     GLX_GREEN_SIZE, 8, GLX_BLUE_SIZE, 8, GLX_ALPHA_SIZE, 8, GLX_DEPTH_SIZE, 24,
                     GLX_STENCIL_SIZE, 8, GLX_DOUBLEBUFFER, False, None};
    int msaa[] = {GLX_SAMPLE_BUFFERS, 1, GLX_SAMPLES, 4, None};
    int n = 0, all = 0, id = 0, v = 0, w = 80, h = 40, i;
    GLXFBConfig *configs, *every, *byid;
    XVisualInfo *vi;
    GLXContext ctx;
    Window win;
    GLXWindow gwin;

    every = glXGetFBConfigs(dpy, DefaultScreen(dpy), &all);
    CHECK(every && all >= 2, "glXGetFBConfigs: %d configs", all);
    for (i = 0; i < all; i++) {
        glXGetFBConfigAttrib(dpy, every[i], GLX_FBCONFIG_ID, &id);
        CHECK(id == i + 1, "config %d has GLX_FBCONFIG_ID %d", i, id);
    }
    if (every)
        XFree(every);
    configs = glXChooseFBConfig(dpy, DefaultScreen(dpy), msaa, &n);
    CHECK(configs == NULL && n == 0, "multisample configs offered: %d", n);
    {
        /* An attribute softgl does not know (GLX_FRAMEBUFFER_SRGB_CAPABLE_ARB)
         * is met when it asks for nothing, unmet when it asks for something. */
        int srgb_off[] = {0x20B2, False, None}, srgb_on[] = {0x20B2, True, None};
        int m = 0;
        GLXFBConfig *c = glXChooseFBConfig(dpy, DefaultScreen(dpy), srgb_off, &m);
        CHECK(c && m > 0, "unknown attribute = False: %d configs", m);
        if (c)
            XFree(c);
        c = glXChooseFBConfig(dpy, DefaultScreen(dpy), srgb_on, &m);
        CHECK(!c && m == 0, "unknown attribute = True: %d configs", m);
    }
    configs = glXChooseFBConfig(dpy, DefaultScreen(dpy), attribs, &n);
    if (!configs || n < 1) {
        printf("FAIL glXChooseFBConfig found no config\n");
        return 1;
    }
    for (i = 0; i < n; i++) {
        glXGetFBConfigAttrib(dpy, configs[i], GLX_DOUBLEBUFFER, &v);
        CHECK(v == 0, "config %d: GLX_DOUBLEBUFFER %d", i, v);
    }
    CHECK(glXGetFBConfigAttrib(dpy, configs[0], GLX_FBCONFIG_ID, &id) == Success && id > 0, "GLX_FBCONFIG_ID %d", id);
    {
        int by_id[] = {GLX_FBCONFIG_ID, id, None};
        int m = 0;
        byid = glXChooseFBConfig(dpy, DefaultScreen(dpy), by_id, &m);
        CHECK(byid && m == 1 && byid[0] == configs[0], "glXChooseFBConfig by GLX_FBCONFIG_ID");
        if (byid)
            XFree(byid);
    }
    glXGetFBConfigAttrib(dpy, configs[0], GLX_DRAWABLE_TYPE, &v);
    CHECK(v & GLX_WINDOW_BIT, "GLX_DRAWABLE_TYPE 0x%x", v);
    glXGetFBConfigAttrib(dpy, configs[0], GLX_X_VISUAL_TYPE, &v);
    CHECK(v == GLX_TRUE_COLOR, "GLX_X_VISUAL_TYPE 0x%x", v);
    vi = glXGetVisualFromFBConfig(dpy, configs[0]);
    if (!vi) {
        printf("FAIL glXGetVisualFromFBConfig\n");
        return 1;
    }
    glXGetFBConfigAttrib(dpy, configs[0], GLX_VISUAL_ID, &v);
    CHECK((VisualID)v == vi->visualid, "GLX_VISUAL_ID 0x%x, visual 0x%lx", v, vi->visualid);
    ctx = glXCreateNewContext(dpy, configs[0], GLX_RGBA_TYPE, NULL, True);
    if (!ctx) {
        printf("FAIL glXCreateNewContext\n");
        return 1;
    }
    CHECK(glXQueryContext(dpy, ctx, GLX_FBCONFIG_ID, &v) == Success && v == id, "glXQueryContext(GLX_FBCONFIG_ID) %d", v);
    win = make_window(dpy, vi, w, h);
    gwin = glXCreateWindow(dpy, configs[0], win, NULL);
    CHECK(gwin != None, "glXCreateWindow");
    CHECK(glXMakeContextCurrent(dpy, gwin, gwin, ctx), "glXMakeContextCurrent");
    check_common(dpy, ctx, gwin);
    {
        unsigned int qw = 0, qh = 0;
        glXQueryDrawable(dpy, gwin, GLX_WIDTH, &qw);
        glXQueryDrawable(dpy, gwin, GLX_HEIGHT, &qh);
        CHECK(qw == (unsigned)w && qh == (unsigned)h, "glXQueryDrawable %ux%u", qw, qh);
    }
    draw_scene(w, h);
    glFinish();
    XSync(dpy, False);
    check_scene(dpy, win, vi, w, h, "fbconfig, single-buffered, after glFinish");

    /* The same context on a GLXPixmap (configs offer GLX_PIXMAP_BIT):
     * single-buffered, shown at glFinish. */
    {
        int pw = 40, ph = 30;
        Pixmap pm = XCreatePixmap(dpy, RootWindow(dpy, vi->screen), pw, ph, vi->depth);
        GLXPixmap gpm;
        glXGetFBConfigAttrib(dpy, configs[0], GLX_DRAWABLE_TYPE, &v);
        CHECK(v & GLX_PIXMAP_BIT, "GLX_DRAWABLE_TYPE 0x%x lacks GLX_PIXMAP_BIT", v);
        gpm = glXCreatePixmap(dpy, configs[0], pm, NULL);
        CHECK(gpm != None, "glXCreatePixmap");
        CHECK(glXMakeContextCurrent(dpy, gpm, gpm, ctx), "glXMakeContextCurrent(pixmap)");
        draw_scene(pw, ph);
        glFinish();
        XSync(dpy, False);
        check_scene(dpy, pm, vi, pw, ph, "fbconfig, GLXPixmap, after glFinish");
        CHECK(glXMakeContextCurrent(dpy, None, None, NULL), "glXMakeContextCurrent(None) after the pixmap");
        glXDestroyPixmap(dpy, gpm);
        XFreePixmap(dpy, pm);
    }

    /* A pbuffer: rendered into and read back with glReadPixels. */
    {
        int pb_attribs[] = {GLX_DRAWABLE_TYPE, GLX_PBUFFER_BIT, GLX_RED_SIZE, 8, None};
        int pbuf_size[] = {GLX_PBUFFER_WIDTH, 20, GLX_PBUFFER_HEIGHT, 10, None};
        int m = 0;
        unsigned int qw = 0, qh = 0, qid = 0;
        unsigned char px[4] = {0, 0, 0, 0}, px2[4] = {0, 0, 0, 0};
        GLXFBConfig *pc = glXChooseFBConfig(dpy, DefaultScreen(dpy), pb_attribs, &m);
        GLXPbuffer pb = None;
        CHECK(pc && m > 0, "no pbuffer config");
        if (pc) {
            glXGetFBConfigAttrib(dpy, pc[0], GLX_MAX_PBUFFER_WIDTH, &v);
            CHECK(v >= 2048, "GLX_MAX_PBUFFER_WIDTH %d", v);
            pb = glXCreatePbuffer(dpy, pc[0], pbuf_size);
        }
        CHECK(pb != None, "glXCreatePbuffer");
        if (pb != None) {
            GLXContext pctx = glXCreateNewContext(dpy, pc[0], GLX_RGBA_TYPE, NULL, True);
            glXQueryDrawable(dpy, pb, GLX_WIDTH, &qw);
            glXQueryDrawable(dpy, pb, GLX_HEIGHT, &qh);
            glXQueryDrawable(dpy, pb, GLX_FBCONFIG_ID, &qid);
            CHECK(qw == 20 && qh == 10, "pbuffer size %ux%u", qw, qh);
            glXGetFBConfigAttrib(dpy, pc[0], GLX_FBCONFIG_ID, &v);
            CHECK(qid == (unsigned)v, "pbuffer GLX_FBCONFIG_ID %u, config %d", qid, v);
            CHECK(pctx && glXMakeContextCurrent(dpy, pb, pb, pctx), "glXMakeContextCurrent(pbuffer)");
            draw_scene(20, 10);
            glReadPixels(2, 2, 1, 1, GL_RGBA, GL_UNSIGNED_BYTE, px);
            glReadPixels(17, 7, 1, 1, GL_RGBA, GL_UNSIGNED_BYTE, px2);
            CHECK(px[0] == 255 && px[2] == 0 && px2[0] == 0 && px2[2] == 255,
                  "pbuffer pixels %d,%d,%d and %d,%d,%d", px[0], px[1], px[2], px2[0], px2[1], px2[2]);
            CHECK(glXMakeContextCurrent(dpy, None, None, NULL), "release the pbuffer");
            glXDestroyContext(dpy, pctx);
            glXDestroyPbuffer(dpy, pb);
            qw = 0;
            {
                /* GLXBadDrawable (GLX error 2) for a destroyed pbuffer. */
                int major, ev, er;
                XErrorHandler old = XSetErrorHandler(note_error);
                noted_error = 0;
                glXQueryDrawable(dpy, pb, GLX_WIDTH, &qw);
                XSync(dpy, False);
                XSetErrorHandler(old);
                if (XQueryExtension(dpy, "GLX", &major, &ev, &er))
                    CHECK(noted_error == er + 2, "destroyed pbuffer: X error %d, expected GLXBadDrawable (%d)", noted_error, er + 2);
            }
            CHECK(qw == 0, "destroyed pbuffer still answers %u", qw);
        }
        if (pc)
            XFree(pc);
    }

    CHECK(glXMakeContextCurrent(dpy, None, None, NULL), "glXMakeContextCurrent(None)");
    glXDestroyContext(dpy, ctx);
    glXDestroyWindow(dpy, gwin);
    XDestroyWindow(dpy, win);
    XFree(vi);
    XFree(configs);
    return 0;
}

int main(int argc, char **argv)
{
    Display *dpy = XOpenDisplay(NULL);
    int rc;
    if (!dpy) {
        printf("FAIL cannot open display '%s'\n", XDisplayName(NULL));
        return 1;
    }
    if (argc > 1 && strcmp(argv[1], "rootcount") == 0) {
        Window root = DefaultRootWindow(dpy);
        XWindowAttributes wa;
        XImage *img;
        long count = 0;
        int x, y;
        XGetWindowAttributes(dpy, root, &wa);
        img = XGetImage(dpy, root, 0, 0, wa.width, wa.height, AllPlanes, ZPixmap);
        if (!img) {
            printf("FAIL XGetImage of the root window\n");
            return 1;
        }
        for (y = 0; y < wa.height; y++)
            for (x = 0; x < wa.width; x++)
                count += XGetPixel(img, x, y) != 0;
        XDestroyImage(img);
        printf("%ld\n", count);
        XCloseDisplay(dpy);
        return 0;
    }
    if (argc > 2 && strcmp(argv[1], "screenshot") == 0) {
        rc = screenshot(dpy, argv[2]);
        XCloseDisplay(dpy);
        return rc;
    }
    if (argc > 1 && strcmp(argv[1], "fbconfig") == 0)
        rc = run_fbconfig(dpy);
    else
        rc = run_visual(dpy);
    XCloseDisplay(dpy);
    if (rc || failures) {
        printf("%d failures\n", failures + rc);
        return 1;
    }
    printf("ok %s\n", argc > 1 ? argv[1] : "visual");
    return 0;
}
