/* headless_xlib: checks softgl's headless Xlib stand-in (headless/x11.c)
 * the way programs use Xlib. Built against the system's Xlib headers and
 * -lX11 like any X program, and run by t_headless.sh with DISPLAY unset
 * and LD_LIBRARY_PATH=build/headless:build/lib, so that it gets the
 * stand-in and softgl's GLX:
 *   - the Display/Screen/Visual layout: Xlib's macros (which read the
 *     structs directly) agree with the functions and with
 *     SOFTGL_HEADLESS_SCREEN; ConnectionNumber is a descriptor poll()
 *     finds readable exactly while events are queued;
 *   - mapping a window queues MapNotify, ConfigureNotify and Expose to a
 *     window that selected them and nothing to one that did not; resizing
 *     queues ConfigureNotify; XCheckTypedWindowEvent, XPutBackEvent,
 *     XSendEvent, XIfEvent with a predicate;
 *   - atoms (predefined ones keep Xatom.h's numbers), properties written
 *     and read back (XGetWindowProperty, XGetWMName), WM_PROTOCOLS;
 *   - a bad drawable reaches the program's error handler as BadDrawable;
 *   - a second display has its own descriptor; closing it twice is
 *     harmless (waffle does);
 *   - XCreateImage/XPutPixel/XPutImage/XGetImage/XDestroyImage;
 *   - GLX through softgl: a double-buffered window cleared to a colour and
 *     swapped reads back (XGetImage) as that colour, and its size follows
 *     XResizeWindow;
 *   - with arguments "exit single|double": SOFTGL_EXIT_AFTER_FRAMES ends a
 *     program that presents forever, and its atexit handler can still
 *     call GLX (see exit_mode).
 * Prints "ok N checks" and exits 0, or prints each failure and exits 1.
 */
#include <GL/gl.h>
#include <GL/glx.h>
#include <X11/Xatom.h>
#include <X11/Xlib.h>
#include <X11/Xutil.h>
#include <dlfcn.h>
#include <poll.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

static int checks, failures;

static void check(int cond, const char *what)
{
    checks++;
    if (!cond) {
        printf("failure: %s\n", what);
        failures++;
    }
}

static int readable(Display *dpy)
{
    struct pollfd p = {ConnectionNumber(dpy), POLLIN, 0};
    return poll(&p, 1, 0) == 1 && (p.revents & POLLIN);
}

static int last_error, errors;

static int on_error(Display *dpy, XErrorEvent *e)
{
    (void)dpy;
    last_error = e->error_code;
    errors++;
    return 0;
}

static Bool is_client_message(Display *dpy, XEvent *ev, XPointer arg)
{
    (void)dpy;
    return ev->type == ClientMessage && ev->xclient.window == *(Window *)arg;
}

/* "exit single" / "exit double": draws and presents frames (glFlush of a
 * single-buffered window, or glXSwapBuffers) until SOFTGL_EXIT_AFTER_FRAMES
 * ends the process; its atexit handler, which still calls GLX (as
 * programs' cleanup does), prints how many frames were presented. */
static Display *exit_dpy;
static GLXContext exit_ctx;
static int presented;

static void at_exit(void)
{
    glXMakeCurrent(exit_dpy, None, NULL);
    glXDestroyContext(exit_dpy, exit_ctx);
    XCloseDisplay(exit_dpy);
    printf("atexit after %d frames\n", presented);
}

static int exit_mode(int dbl)
{
    int vattr[] = {GLX_RGBA, GLX_RED_SIZE, 8, dbl ? GLX_DOUBLEBUFFER : None, None};
    Display *dpy = exit_dpy = XOpenDisplay(NULL);
    XVisualInfo *vi = dpy ? glXChooseVisual(dpy, DefaultScreen(dpy), vattr) : NULL;
    if (!vi) {
        printf("failure: no visual\n");
        return 1;
    }
    XSetWindowAttributes attr;
    attr.colormap = XCreateColormap(dpy, DefaultRootWindow(dpy), vi->visual, AllocNone);
    Window w = XCreateWindow(dpy, DefaultRootWindow(dpy), 0, 0, 32, 32, 0, vi->depth, InputOutput, vi->visual, CWColormap, &attr);
    exit_ctx = glXCreateContext(dpy, vi, NULL, True);
    XMapWindow(dpy, w);
    if (!glXMakeCurrent(dpy, w, exit_ctx)) {
        printf("failure: glXMakeCurrent\n");
        return 1;
    }
    atexit(at_exit);
    for (presented = 1; presented <= 1000; presented++) {
        glClearColor((float)(presented % 8) / 8, 0.5f, 0, 1);
        glClear(GL_COLOR_BUFFER_BIT);
        if (dbl)
            glXSwapBuffers(dpy, w);
        else
            glFlush();
    }
    printf("failure: still running after 1000 frames (SOFTGL_EXIT_AFTER_FRAMES=%s)\n", getenv("SOFTGL_EXIT_AFTER_FRAMES"));
    fflush(stdout);
    _exit(1); /* not exit(): at_exit would print as if it had worked */
}

int main(int argc, char **argv)
{
    if (argc == 3 && !strcmp(argv[1], "exit"))
        return exit_mode(!strcmp(argv[2], "double"));
    Display *dpy = XOpenDisplay(NULL);
    if (!dpy) {
        printf("failure: XOpenDisplay(NULL) with DISPLAY=%s\n", getenv("DISPLAY") ? getenv("DISPLAY") : "(unset)");
        return 1;
    }
    /* The stand-in, not a real libX11 that found a server. */
    check(dlsym(RTLD_DEFAULT, "softgl_headless_x11") != NULL, "libX11 is softgl's headless stand-in");

    /* Layout: macros read the structs, functions answer from the library. */
    int scr = DefaultScreen(dpy);
    check(scr == 0 && XDefaultScreen(dpy) == 0, "DefaultScreen is 0");
    check(ScreenCount(dpy) == 1 && XScreenCount(dpy) == 1, "one screen");
    check(DisplayWidth(dpy, scr) == 800 && DisplayHeight(dpy, scr) == 600, "screen 800x600 (SOFTGL_HEADLESS_SCREEN)");
    check(XDisplayWidth(dpy, scr) == 800 && XDisplayHeight(dpy, scr) == 600, "XDisplayWidth/Height agree");
    check(DisplayWidthMM(dpy, scr) > 0 && DisplayHeightMM(dpy, scr) > 0, "screen size in mm");
    check(RootWindow(dpy, scr) != None && RootWindow(dpy, scr) == XRootWindow(dpy, scr) &&
              DefaultRootWindow(dpy) == RootWindow(dpy, scr), "RootWindow agrees");
    check(ScreenOfDisplay(dpy, scr) == XScreenOfDisplay(dpy, scr) && XDisplayOfScreen(ScreenOfDisplay(dpy, scr)) == dpy,
          "ScreenOfDisplay agrees and points back");
    check(DefaultDepth(dpy, scr) == 24 && DefaultVisual(dpy, scr) == XDefaultVisual(dpy, scr), "default depth 24, visual");
    check(DefaultVisual(dpy, scr)->class == TrueColor && DefaultVisual(dpy, scr)->red_mask == 0xff0000, "TrueColor visual");
    check(BlackPixel(dpy, scr) == 0 && WhitePixel(dpy, scr) == 0xffffff, "black and white pixels");
    check(ConnectionNumber(dpy) >= 0 && ConnectionNumber(dpy) == XConnectionNumber(dpy), "ConnectionNumber agrees");
    check(QLength(dpy) == 0 && !readable(dpy), "no event queued, descriptor not readable");
    check(ServerVendor(dpy) != NULL && ProtocolVersion(dpy) == 11, "vendor, protocol 11");

    XVisualInfo tmpl, *vi;
    int n = 0;
    tmpl.screen = scr;
    tmpl.class = TrueColor;
    vi = XGetVisualInfo(dpy, VisualScreenMask | VisualClassMask, &tmpl, &n);
    check(vi && n == 3, "three TrueColor visuals");
    XFree(vi);
    tmpl.depth = 32;
    vi = XGetVisualInfo(dpy, VisualDepthMask, &tmpl, &n);
    check(vi && n == 1 && vi[0].depth == 32, "one depth-32 visual");
    XFree(vi);
    XVisualInfo match;
    check(XMatchVisualInfo(dpy, scr, 24, TrueColor, &match) && match.depth == 24, "XMatchVisualInfo depth 24");
    check(!XMatchVisualInfo(dpy, scr, 16, TrueColor, &match), "no depth-16 visual");

    /* Atoms. */
    check(XInternAtom(dpy, "WM_NAME", False) == XA_WM_NAME, "WM_NAME is XA_WM_NAME");
    check(XInternAtom(dpy, "WM_TRANSIENT_FOR", True) == XA_WM_TRANSIENT_FOR, "predefined atoms keep their numbers");
    check(XInternAtom(dpy, "SOFTGL_NOT_YET", True) == None, "only_if_exists: None for a new name");
    Atom a1 = XInternAtom(dpy, "_NET_WM_STATE", False), a2 = XInternAtom(dpy, "_NET_WM_STATE", False);
    check(a1 != None && a1 == a2 && a1 > XA_LAST_PREDEFINED, "a new atom, the same each time");
    char *name = XGetAtomName(dpy, a1);
    check(name && !strcmp(name, "_NET_WM_STATE"), "XGetAtomName");
    XFree(name);

    /* Windows and events. */
    Window root = RootWindow(dpy, scr);
    XSetWindowAttributes attr;
    memset(&attr, 0, sizeof attr);
    attr.event_mask = StructureNotifyMask | ExposureMask;
    Window w = XCreateWindow(dpy, root, 10, 20, 64, 48, 0, CopyFromParent, InputOutput, CopyFromParent, CWEventMask, &attr);
    Window quiet = XCreateSimpleWindow(dpy, root, 0, 0, 32, 32, 0, 0, 0);
    check(w != None && quiet != None && w != quiet, "two windows");
    XMapWindow(dpy, quiet);
    check(XPending(dpy) == 0, "a window that selected nothing gets no events");
    XMapWindow(dpy, w);
    check(readable(dpy), "events queued: the descriptor is readable");
    check(XPending(dpy) == 3 && QLength(dpy) == 3, "map: three events");
    XEvent ev;
    XNextEvent(dpy, &ev);
    check(ev.type == MapNotify && ev.xmap.window == w && ev.xmap.event == w, "MapNotify first");
    XNextEvent(dpy, &ev);
    check(ev.type == ConfigureNotify && ev.xconfigure.width == 64 && ev.xconfigure.height == 48, "ConfigureNotify 64x48");
    XPutBackEvent(dpy, &ev);
    check(XCheckTypedWindowEvent(dpy, w, ConfigureNotify, &ev), "XPutBackEvent puts it back");
    check(XCheckTypedWindowEvent(dpy, w, Expose, &ev) && ev.xexpose.width == 64 && ev.xexpose.count == 0, "Expose, whole window");
    check(XPending(dpy) == 0 && !readable(dpy), "queue empty: the descriptor is not readable");
    XResizeWindow(dpy, w, 100, 80);
    check(XCheckTypedWindowEvent(dpy, w, ConfigureNotify, &ev) && ev.xconfigure.width == 100 && ev.xconfigure.height == 80,
          "resize: ConfigureNotify 100x80");
    check(XCheckTypedWindowEvent(dpy, w, Expose, &ev), "growing: Expose");
    XWindowAttributes wa;
    check(XGetWindowAttributes(dpy, w, &wa) && wa.width == 100 && wa.height == 80 && wa.map_state == IsViewable &&
              wa.depth == 24 && wa.screen == ScreenOfDisplay(dpy, scr), "XGetWindowAttributes");
    Window r;
    int x, y;
    unsigned ww, wh, bw, depth;
    check(XGetGeometry(dpy, w, &r, &x, &y, &ww, &wh, &bw, &depth) && r == root && x == 10 && y == 20 && ww == 100 && wh == 80 &&
              depth == 24, "XGetGeometry");
    Window child;
    check(XTranslateCoordinates(dpy, w, root, 40, 50, &x, &y, &child) && x == 50 && y == 70 && child == w,
          "XTranslateCoordinates to the root: the point is in the window");
    check(XTranslateCoordinates(dpy, w, root, 3, 4, &x, &y, &child) && x == 13 && y == 24 && child == quiet,
          "XTranslateCoordinates: the window made later is on top");
    check(XTranslateCoordinates(dpy, root, w, 0, 0, &x, &y, &child) && x == -10 && y == -20 && child == None,
          "XTranslateCoordinates from the root");
    XEvent msg;
    memset(&msg, 0, sizeof msg);
    msg.xclient.type = ClientMessage;
    msg.xclient.window = w;
    msg.xclient.format = 32;
    msg.xclient.data.l[0] = 42;
    check(XSendEvent(dpy, w, False, 0, &msg), "XSendEvent");
    XIfEvent(dpy, &ev, is_client_message, (XPointer)&w);
    check(ev.type == ClientMessage && ev.xclient.data.l[0] == 42 && ev.xany.send_event, "XIfEvent finds the sent event");

    /* Errors go to the program's handler. */
    XErrorHandler old = XSetErrorHandler(on_error);
    check(old != NULL, "a default error handler");
    check(!XGetGeometry(dpy, 0x7654321, &r, &x, &y, &ww, &wh, &bw, &depth) && errors == 1 && last_error == BadDrawable,
          "XGetGeometry of a bad drawable: BadDrawable");
    XSync(dpy, False);
    XSetErrorHandler(old);

    /* Properties. */
    Atom protocols = XInternAtom(dpy, "WM_PROTOCOLS", False), del = XInternAtom(dpy, "WM_DELETE_WINDOW", False);
    check(XSetWMProtocols(dpy, w, &del, 1), "XSetWMProtocols");
    Atom type;
    int format;
    unsigned long items, after;
    unsigned char *data = NULL;
    check(XGetWindowProperty(dpy, w, protocols, 0, 16, False, XA_ATOM, &type, &format, &items, &after, &data) == Success &&
              type == XA_ATOM && format == 32 && items == 1 && after == 0 && data && ((Atom *)data)[0] == del,
          "WM_PROTOCOLS reads back");
    XFree(data);
    check(XGetWindowProperty(dpy, root, a1, 0, 16, False, XA_ATOM, &type, &format, &items, &after, &data) == Success &&
              type == None && items == 0 && data == NULL, "a missing property: type None, no data");
    XStoreName(dpy, w, "headless");
    XTextProperty tp;
    check(XGetWMName(dpy, w, &tp) && tp.nitems == 8 && !memcmp(tp.value, "headless", 8), "XStoreName, XGetWMName");
    XFree(tp.value);

    /* Images. */
    XImage *im = XCreateImage(dpy, DefaultVisual(dpy, scr), 24, ZPixmap, 0, malloc(4 * 4 * 4), 4, 4, 32, 0);
    check(im && im->bytes_per_line == 16 && im->bits_per_pixel == 32, "XCreateImage 4x4");
    for (int i = 0; i < 16; i++)
        XPutPixel(im, i % 4, i / 4, 0x010203u * (unsigned)i);
    check(XGetPixel(im, 3, 2) == 0x010203u * 11, "XGetPixel reads XPutPixel");
    GC gc = XCreateGC(dpy, w, 0, NULL);
    XPutImage(dpy, w, gc, im, 0, 0, 5, 6, 4, 4);
    XImage *got = XGetImage(dpy, w, 5, 6, 4, 4, AllPlanes, ZPixmap);
    check(got && (XGetPixel(got, 3, 2) & 0xffffff) == 0x010203u * 11 && (XGetPixel(got, 0, 0) & 0xffffff) == 0,
          "XGetImage reads back XPutImage");
    if (got)
        XDestroyImage(got);
    /* Partly outside the window: the part inside lands. */
    XPutImage(dpy, w, gc, im, 0, 0, -2, 70, 4, 4);
    got = XGetImage(dpy, w, 0, 70, 2, 2, AllPlanes, ZPixmap);
    check(got && (XGetPixel(got, 0, 0) & 0xffffff) == 0x010203u * 2 && (XGetPixel(got, 1, 1) & 0xffffff) == 0x010203u * 7,
          "XPutImage clipped at the window's left edge");
    if (got)
        XDestroyImage(got);
    im->byte_order = MSBFirst;
    XPutPixel(im, 1, 1, 0x11223344);
    check(XGetPixel(im, 1, 1) == 0x11223344 && (unsigned char)im->data[4 * 4 + 4] == 0x11, "MSBFirst pixels");
    XDestroyImage(im);
    XFreeGC(dpy, gc);

    /* GLX through softgl into a window of the stand-in. */
    int vattr[] = {GLX_RGBA, GLX_DOUBLEBUFFER, GLX_RED_SIZE, 8, GLX_DEPTH_SIZE, 16, None};
    XVisualInfo *gv = glXChooseVisual(dpy, scr, vattr);
    check(gv != NULL, "glXChooseVisual: RGBA, double-buffered");
    if (gv) {
        attr.colormap = XCreateColormap(dpy, root, gv->visual, AllocNone);
        Window gw = XCreateWindow(dpy, root, 0, 0, 40, 30, 0, gv->depth, InputOutput, gv->visual, CWColormap | CWEventMask, &attr);
        GLXContext ctx = glXCreateContext(dpy, gv, NULL, True);
        XMapWindow(dpy, gw);
        check(ctx && glXMakeCurrent(dpy, gw, ctx), "glXCreateContext, glXMakeCurrent");
        const char *renderer = (const char *)glGetString(GL_RENDERER);
        check(renderer && !strncmp(renderer, "softgl", 6), "GL_RENDERER is softgl");
        glClearColor(0.2f, 0.4f, 0.6f, 1);
        glClear(GL_COLOR_BUFFER_BIT);
        glXSwapBuffers(dpy, gw);
        XImage *shot = XGetImage(dpy, gw, 0, 0, 40, 30, AllPlanes, ZPixmap);
        unsigned long px = shot ? XGetPixel(shot, 20, 15) & 0xffffff : 0;
        check(px == 0x336699, "the swapped frame is in the window (XGetImage)");
        if (shot)
            XDestroyImage(shot);
        XResizeWindow(dpy, gw, 50, 20);
        glXSwapBuffers(dpy, gw); /* follows the size for the next frame */
        glClear(GL_COLOR_BUFFER_BIT);
        glXSwapBuffers(dpy, gw);
        shot = XGetImage(dpy, gw, 0, 0, 50, 20, AllPlanes, ZPixmap);
        check(shot && (XGetPixel(shot, 49, 19) & 0xffffff) == 0x336699, "after XResizeWindow the frame is 50x20");
        if (shot)
            XDestroyImage(shot);
        glXMakeCurrent(dpy, None, NULL);
        glXDestroyContext(dpy, ctx);
        XDestroyWindow(dpy, gw);
        XFree(gv);
    }
    XDestroyWindow(dpy, w);
    check(XCheckTypedWindowEvent(dpy, w, UnmapNotify, &ev) && XCheckTypedWindowEvent(dpy, w, DestroyNotify, &ev),
          "XDestroyWindow: UnmapNotify, DestroyNotify");
    /* A second display is its own; closing it twice is harmless. */
    Display *other = XOpenDisplay(NULL);
    check(other && other != dpy && ConnectionNumber(other) != ConnectionNumber(dpy), "a second display, its own descriptor");
    if (other) {
        XCloseDisplay(other);
        XCloseDisplay(other);
    }
    XCloseDisplay(dpy);

    if (failures) {
        printf("%d of %d checks failed\n", failures, checks);
        return 1;
    }
    printf("ok %d checks\n", checks);
    return 0;
}
