/* libX11.so.6 stand-in: an Xlib with no X server behind it, so that
 * unmodified X11 OpenGL programs (glxgears, freeglut programs) run on
 * softgl with no display at all (issue 7, "Headless"). Installed as
 * build/headless/libX11.so.6 and found through LD_LIBRARY_PATH; softgl's
 * GLX (src/winsys/glx), which dlopens "libX11.so.6", then gets this one
 * too and presents into it; SOFTGL_DUMP captures the frames.
 *
 * What it models, in-process:
 * - Displays: XOpenDisplay returns a struct with Xlib's public layout
 *   (_XPrivDisplay, Screen, Depth, Visual from <X11/Xlib.h>, so that the
 *   macros DefaultScreen, RootWindow, DisplayWidth, ConnectionNumber...
 *   read the right fields). One screen (SOFTGL_HEADLESS_SCREEN=WxH, default
 *   1280x1024) with two depth-24 TrueColor visuals and one depth-32 one
 *   (softgl's GLX gives single- and double-buffered configs their own
 *   visuals when a depth has two). ConnectionNumber is an eventfd that is
 *   readable exactly while the event queue is not empty (programs sleep in
 *   select/poll on it).
 * - Windows and pixmaps with their geometry, parent, event mask and map
 *   state; mapping queues MapNotify, ConfigureNotify, VisibilityNotify and
 *   Expose to the windows that selected them (as a server with a window
 *   manager would), resizing ConfigureNotify and Expose, unmapping and
 *   destroying UnmapNotify and DestroyNotify. XPutImage keeps the image of
 *   32-bit drawables so that XGetImage reads it back.
 * - The event queue (XNextEvent, XPending, XCheck*Event, XIfEvent,
 *   XPeekEvent, XSendEvent, XPutBackEvent...). A wait on an empty queue
 *   blocks as in Xlib (only XSendEvent from another thread can end it) and
 *   says so once on stderr.
 * - Atoms (Xatom.h's predefined ones, then new ones in order) and window
 *   properties (stored, read back by XGetWindowProperty, XGetWMName).
 * - Errors: a bad drawable in XGetGeometry, XPutImage, XGetImage... goes
 *   to the program's error handler (XSetErrorHandler) as a BadDrawable,
 *   BadWindow or BadPixmap; Xlib's default handler prints it and exits.
 * - Everything else a program may ask (extensions, keyboard, pointer,
 *   grabs, cursors, fonts, colours) answers as a server without those
 *   things would: no extensions, no key symbols, grabs that succeed.
 *
 * Every function defined here is declared by Xlib.h or Xutil.h, so the
 * compiler checks the signatures against Xlib's own.
 */
#define _GNU_SOURCE
#include <X11/Xlib.h>
#include <X11/Xutil.h>
#include <X11/Xatom.h>
#include <X11/Xproto.h>
#include <X11/XKBlib.h>
#include <errno.h>
#include <pthread.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/eventfd.h>
#include <unistd.h>

#define EXPORT __attribute__((visibility("default")))

/* Marks this library as softgl's stand-in (dlsym finds it only here). */
EXPORT const int softgl_headless_x11 = 1;

/* ---- state ---- */

typedef __typeof__(*((_XPrivDisplay)0)) PubDisplay;

enum { KIND_WINDOW, KIND_PIXMAP };

typedef struct Drawable_ {
    XID id;
    int kind;
    Window parent; /* windows: the root for top-level ones */
    int x, y;
    unsigned w, h, border, depth;
    Visual *visual;
    Colormap cmap;
    long event_mask;
    int mapped, input_only, override_redirect;
    /* The last XPutImage'd pixels of a 24/32-bit drawable (w*h words,
     * top row first), or NULL. */
    uint32_t *pixels;
    struct Drawable_ *next;
} HDrawable;

typedef struct Prop_ {
    Window w;
    Atom name, type;
    int format;
    unsigned long nitems;
    unsigned char *data; /* client format: format 32 items are longs */
    struct Prop_ *next;
} Prop;

typedef struct Ext_ {
    XExtCodes codes;
    int (*close)(Display *, XExtCodes *);
    struct Ext_ *next;
} Ext;

#define NVISUALS 3

typedef struct {
    PubDisplay pub; /* first: Display* points here */
    /* Zeros after the public part: code peeking at Xlib's private fields
     * (lock_fns, flags...) reads "nothing set" instead of past the end. */
    char private_zeros[2048];
    Screen screen;
    Depth depths[3];
    Visual visuals[NVISUALS];
    XGCValues gcv;
    int efd;
    XEvent *queue; /* ring */
    int qhead, qcap;
    HDrawable *drawables;
    Prop *props;
    Ext *exts;
    char *name;
    char vendor[32];
} HDisplay;

static pthread_mutex_t lock = PTHREAD_MUTEX_INITIALIZER;
/* Open displays, so that closing one twice (waffle does, on its error
 * path) is a no-op instead of a double free. */
static HDisplay **open_displays;
static size_t n_open, cap_open;
static pthread_cond_t queued = PTHREAD_COND_INITIALIZER;
static XID next_id = 0x200000;
static int next_ext = 128;

#define ROOT_ID 0x100
#define H(dpy) ((HDisplay *)(dpy))
#define P(dpy) (&H(dpy)->pub)

static XID new_id(void)
{
    return next_id++;
}

static void bump(Display *dpy)
{
    P(dpy)->request++;
    P(dpy)->last_request_read = P(dpy)->request;
}

/* ---- errors ---- */

static int default_error_handler(Display *dpy, XErrorEvent *e);
static XErrorHandler error_handler = default_error_handler;
static XIOErrorHandler io_error_handler;

static const char *const error_names[] = {
    "Success", "BadRequest", "BadValue", "BadWindow", "BadPixmap", "BadAtom", "BadCursor", "BadFont", "BadMatch",
    "BadDrawable", "BadAccess", "BadAlloc", "BadColor", "BadGC", "BadIDChoice", "BadName", "BadLength",
    "BadImplementation",
};

EXPORT int XGetErrorText(Display *dpy, int code, char *buf, int len)
{
    (void)dpy;
    if (!buf || len <= 0)
        return 0;
    if (code >= 0 && code < (int)(sizeof error_names / sizeof *error_names))
        snprintf(buf, (size_t)len, "%s", error_names[code]);
    else
        snprintf(buf, (size_t)len, "%d", code);
    return 0;
}

EXPORT int XGetErrorDatabaseText(Display *dpy, const char *name, const char *message, const char *def, char *buf, int len)
{
    (void)dpy, (void)name, (void)message;
    if (buf && len > 0)
        snprintf(buf, (size_t)len, "%s", def ? def : "");
    return 0;
}

static int default_error_handler(Display *dpy, XErrorEvent *e)
{
    char text[64];
    XGetErrorText(dpy, e->error_code, text, sizeof text);
    fprintf(stderr, "X Error of failed request:  %s\n  Major opcode of failed request:  %d\n"
                    "  Resource id in failed request:  0x%lx\n  (softgl headless Xlib: no X server)\n",
            text, e->request_code, e->resourceid);
    exit(1);
}

EXPORT XErrorHandler XSetErrorHandler(XErrorHandler h)
{
    pthread_mutex_lock(&lock);
    XErrorHandler old = error_handler;
    error_handler = h ? h : default_error_handler;
    pthread_mutex_unlock(&lock);
    return old;
}

EXPORT XIOErrorHandler XSetIOErrorHandler(XIOErrorHandler h)
{
    pthread_mutex_lock(&lock);
    XIOErrorHandler old = io_error_handler;
    io_error_handler = h;
    pthread_mutex_unlock(&lock);
    return old;
}

/* Reports an X error to the program's handler. Called without the lock
 * held (the handler may call Xlib). */
static void x_error(Display *dpy, int code, int request, XID resource)
{
    XErrorEvent e;
    memset(&e, 0, sizeof e);
    e.type = 0;
    e.display = dpy;
    e.resourceid = resource;
    e.serial = P(dpy)->request;
    e.error_code = (unsigned char)code;
    e.request_code = (unsigned char)request;
    pthread_mutex_lock(&lock);
    XErrorHandler h = error_handler;
    pthread_mutex_unlock(&lock);
    h(dpy, &e);
}

/* ---- drawables (the lock held) ---- */

static HDrawable *find(Display *dpy, XID id)
{
    for (HDrawable *d = H(dpy)->drawables; d; d = d->next)
        if (d->id == id)
            return d;
    return NULL;
}

static HDrawable *find_window(Display *dpy, Window w)
{
    HDrawable *d = find(dpy, w);
    return d && d->kind == KIND_WINDOW ? d : NULL;
}

static int is_root(Display *dpy, XID id)
{
    (void)dpy;
    return id == ROOT_ID;
}

/* Viewable: mapped, and so are all its ancestors. */
static int viewable(Display *dpy, HDrawable *w)
{
    while (w) {
        if (!w->mapped)
            return 0;
        if (is_root(dpy, w->parent))
            return 1;
        w = find_window(dpy, w->parent);
    }
    return 0;
}

/* ---- the event queue (the lock held) ---- */

static int qlen(Display *dpy)
{
    return P(dpy)->qlen;
}

static void set_fd(Display *dpy)
{
    uint64_t v = 1;
    if (qlen(dpy) > 0) {
        /* Readable while events wait: one write makes it so. */
        if (write(H(dpy)->efd, &v, sizeof v) < 0) {
            /* the counter is full (never with one write per event): still readable */
        }
    } else {
        while (read(H(dpy)->efd, &v, sizeof v) > 0) {
        }
    }
}

static void push(Display *dpy, const XEvent *ev, int front)
{
    HDisplay *h = H(dpy);
    int n = qlen(dpy);
    if (n == h->qcap) {
        int cap = h->qcap ? 2 * h->qcap : 64;
        XEvent *q = malloc((size_t)cap * sizeof *q);
        if (!q)
            return; /* out of memory: the event is lost */
        for (int i = 0; i < n; i++)
            q[i] = h->queue[(h->qhead + i) % h->qcap];
        free(h->queue);
        h->queue = q;
        h->qhead = 0;
        h->qcap = cap;
    }
    if (front) {
        h->qhead = (h->qhead + h->qcap - 1) % h->qcap;
        h->queue[h->qhead] = *ev;
    } else {
        h->queue[(h->qhead + n) % h->qcap] = *ev;
    }
    P(dpy)->qlen = n + 1;
    if (n == 0)
        set_fd(dpy);
    pthread_cond_broadcast(&queued);
}

static XEvent *at(Display *dpy, int i)
{
    return &H(dpy)->queue[(H(dpy)->qhead + i) % H(dpy)->qcap];
}

/* Removes the i-th queued event into *out. */
static void take(Display *dpy, int i, XEvent *out)
{
    HDisplay *h = H(dpy);
    int n = qlen(dpy);
    *out = *at(dpy, i);
    for (int k = i; k > 0; k--)
        *at(dpy, k) = *at(dpy, k - 1);
    h->qhead = (h->qhead + 1) % h->qcap;
    P(dpy)->qlen = n - 1;
    if (n == 1)
        set_fd(dpy);
}

/* Queues an event of `type` about window `w` for the window `to` if it
 * selected `mask`. */
static void deliver(Display *dpy, HDrawable *to, long mask, XEvent *ev)
{
    if (!to || !(to->event_mask & mask))
        return;
    ev->xany.serial = P(dpy)->request;
    ev->xany.send_event = False;
    ev->xany.display = dpy;
    push(dpy, ev, 0);
}

/* StructureNotify on the window itself, SubstructureNotify on its parent
 * (the `event` field names the window the event is reported to). */
static void notify_structure(Display *dpy, HDrawable *w, XEvent *ev, Window *event_field)
{
    *event_field = w->id;
    deliver(dpy, w, StructureNotifyMask, ev);
    HDrawable *parent = find_window(dpy, w->parent);
    if (parent) {
        *event_field = parent->id;
        deliver(dpy, parent, SubstructureNotifyMask, ev);
    }
}

static void send_configure(Display *dpy, HDrawable *w)
{
    XEvent ev;
    memset(&ev, 0, sizeof ev);
    ev.xconfigure.type = ConfigureNotify;
    ev.xconfigure.window = w->id;
    ev.xconfigure.x = w->x;
    ev.xconfigure.y = w->y;
    ev.xconfigure.width = (int)w->w;
    ev.xconfigure.height = (int)w->h;
    ev.xconfigure.border_width = (int)w->border;
    ev.xconfigure.override_redirect = w->override_redirect;
    notify_structure(dpy, w, &ev, &ev.xconfigure.event);
}

/* Expose for a viewable window and its mapped children. */
static void expose_tree(Display *dpy, HDrawable *w)
{
    if (!w->mapped)
        return;
    if (!w->input_only) {
        XEvent ev;
        memset(&ev, 0, sizeof ev);
        ev.xvisibility.type = VisibilityNotify;
        ev.xvisibility.window = w->id;
        ev.xvisibility.state = VisibilityUnobscured;
        deliver(dpy, w, VisibilityChangeMask, &ev);
        memset(&ev, 0, sizeof ev);
        ev.xexpose.type = Expose;
        ev.xexpose.window = w->id;
        ev.xexpose.width = (int)w->w;
        ev.xexpose.height = (int)w->h;
        ev.xexpose.count = 0;
        deliver(dpy, w, ExposureMask, &ev);
    }
    for (HDrawable *c = H(dpy)->drawables; c; c = c->next)
        if (c->kind == KIND_WINDOW && c->parent == w->id)
            expose_tree(dpy, c);
}

static void map_window(Display *dpy, HDrawable *w)
{
    if (w->mapped)
        return;
    w->mapped = 1;
    XEvent ev;
    memset(&ev, 0, sizeof ev);
    ev.xmap.type = MapNotify;
    ev.xmap.window = w->id;
    ev.xmap.override_redirect = w->override_redirect;
    notify_structure(dpy, w, &ev, &ev.xmap.event);
    /* What a window manager sends a top-level window it has placed. */
    if (is_root(dpy, w->parent))
        send_configure(dpy, w);
    if (viewable(dpy, w))
        expose_tree(dpy, w);
}

static void unmap_window(Display *dpy, HDrawable *w)
{
    if (!w->mapped)
        return;
    w->mapped = 0;
    XEvent ev;
    memset(&ev, 0, sizeof ev);
    ev.xunmap.type = UnmapNotify;
    ev.xunmap.window = w->id;
    notify_structure(dpy, w, &ev, &ev.xunmap.event);
}

static void drop_props(Display *dpy, Window w)
{
    Prop **pp = &H(dpy)->props;
    while (*pp) {
        if ((*pp)->w == w) {
            Prop *p = *pp;
            *pp = p->next;
            free(p->data);
            free(p);
        } else {
            pp = &(*pp)->next;
        }
    }
}

static void unlink_drawable(Display *dpy, HDrawable *d)
{
    for (HDrawable **pp = &H(dpy)->drawables; *pp; pp = &(*pp)->next)
        if (*pp == d) {
            *pp = d->next;
            break;
        }
    free(d->pixels);
    free(d);
}

static void destroy_window(Display *dpy, HDrawable *w)
{
    /* Children first (DestroyNotify goes bottom-up). */
    for (;;) {
        HDrawable *c = H(dpy)->drawables;
        while (c && !(c->kind == KIND_WINDOW && c->parent == w->id))
            c = c->next;
        if (!c)
            break;
        destroy_window(dpy, c);
    }
    unmap_window(dpy, w);
    XEvent ev;
    memset(&ev, 0, sizeof ev);
    ev.xdestroywindow.type = DestroyNotify;
    ev.xdestroywindow.window = w->id;
    notify_structure(dpy, w, &ev, &ev.xdestroywindow.event);
    drop_props(dpy, w->id);
    unlink_drawable(dpy, w);
}

/* ---- displays ---- */

static const struct {
    int depth;
    unsigned long r, g, b;
} visual_formats[NVISUALS] = {
    {24, 0xff0000, 0xff00, 0xff},
    {24, 0xff0000, 0xff00, 0xff},
    {32, 0xff0000, 0xff00, 0xff},
};

static void screen_size(int *w, int *h)
{
    const char *s = getenv("SOFTGL_HEADLESS_SCREEN");
    int a, b;
    *w = 1280;
    *h = 1024;
    if (s && sscanf(s, "%dx%d", &a, &b) == 2 && a > 0 && b > 0 && a <= 16384 && b <= 16384) {
        *w = a;
        *h = b;
    }
}

EXPORT char *XDisplayName(const char *name)
{
    static char empty[] = "";
    if (name && *name)
        return (char *)name;
    name = getenv("DISPLAY");
    return name ? (char *)name : empty;
}

EXPORT Display *XOpenDisplay(const char *name)
{
    HDisplay *h = calloc(1, sizeof *h);
    if (!h)
        return NULL;
    h->efd = eventfd(0, EFD_NONBLOCK | EFD_CLOEXEC);
    if (h->efd < 0) {
        free(h);
        return NULL;
    }
    Display *dpy = (Display *)h;
    PubDisplay *p = &h->pub;
    h->name = strdup(XDisplayName(name));
    snprintf(h->vendor, sizeof h->vendor, "softgl headless");
    p->fd = h->efd;
    p->proto_major_version = 11;
    p->proto_minor_version = 0;
    p->vendor = h->vendor;
    p->byte_order = LSBFirst;
    p->bitmap_unit = 32;
    p->bitmap_pad = 32;
    p->bitmap_bit_order = LSBFirst;
    p->release = 12101000;
    p->max_request_size = 65535;
    p->display_name = h->name;
    p->default_screen = 0;
    p->nscreens = 1;
    p->screens = &h->screen;
    p->min_keycode = 8;
    p->max_keycode = 255;

    for (int i = 0; i < NVISUALS; i++) {
        Visual *v = &h->visuals[i];
        v->visualid = 0x21 + (VisualID)i;
#if defined(__cplusplus) || defined(c_plusplus)
        v->c_class = TrueColor;
#else
        v->class = TrueColor;
#endif
        v->red_mask = visual_formats[i].r;
        v->green_mask = visual_formats[i].g;
        v->blue_mask = visual_formats[i].b;
        v->bits_per_rgb = 8;
        v->map_entries = 256;
    }
    h->depths[0].depth = 24;
    h->depths[0].nvisuals = 2;
    h->depths[0].visuals = &h->visuals[0];
    h->depths[1].depth = 32;
    h->depths[1].nvisuals = 1;
    h->depths[1].visuals = &h->visuals[2];
    h->depths[2].depth = 1;

    Screen *s = &h->screen;
    int w, hh;
    screen_size(&w, &hh);
    s->display = (struct _XDisplay *)dpy;
    s->root = ROOT_ID;
    s->width = w;
    s->height = hh;
    /* 96 dots per inch. */
    s->mwidth = w * 254 / 960;
    s->mheight = hh * 254 / 960;
    s->ndepths = 3;
    s->depths = h->depths;
    s->root_depth = 24;
    s->root_visual = &h->visuals[0];
    s->default_gc = calloc(1, 256);
    s->cmap = 0x20;
    s->white_pixel = 0xffffff;
    s->black_pixel = 0;
    s->max_maps = 1;
    s->min_maps = 1;
    s->backing_store = NotUseful;
    s->save_unders = False;
    pthread_mutex_lock(&lock);
    if (n_open == cap_open) {
        size_t cap = cap_open ? 2 * cap_open : 8;
        HDisplay **l = realloc(open_displays, cap * sizeof *l);
        if (l) {
            open_displays = l;
            cap_open = cap;
        }
    }
    int ok = n_open < cap_open;
    if (ok)
        open_displays[n_open++] = h;
    pthread_mutex_unlock(&lock);
    if (!ok) {
        close(h->efd);
        free(h->screen.default_gc);
        free(h->name);
        free(h);
        return NULL;
    }
    return dpy;
}

/* Forgets an open display; false if it was not open (the lock held). */
static int forget_display(HDisplay *h)
{
    for (size_t i = 0; i < n_open; i++)
        if (open_displays[i] == h) {
            open_displays[i] = open_displays[--n_open];
            return 1;
        }
    return 0;
}

EXPORT int XCloseDisplay(Display *dpy)
{
    if (!dpy)
        return 0;
    HDisplay *h = H(dpy);
    pthread_mutex_lock(&lock);
    int known = forget_display(h);
    pthread_mutex_unlock(&lock);
    if (!known)
        return 0; /* closed already */
    /* Extensions' close hooks first (softgl's GLX drops its drawables). */
    for (Ext *e = h->exts; e; e = e->next)
        if (e->close)
            e->close(dpy, &e->codes);
    pthread_mutex_lock(&lock);
    while (h->exts) {
        Ext *e = h->exts;
        h->exts = e->next;
        free(e);
    }
    while (h->drawables) {
        HDrawable *d = h->drawables;
        h->drawables = d->next;
        free(d->pixels);
        free(d);
    }
    while (h->props) {
        Prop *p = h->props;
        h->props = p->next;
        free(p->data);
        free(p);
    }
    pthread_mutex_unlock(&lock);
    close(h->efd);
    free(h->queue);
    free(h->screen.default_gc);
    free(h->name);
    free(h);
    return 0;
}

EXPORT XExtCodes *XAddExtension(Display *dpy)
{
    Ext *e = calloc(1, sizeof *e);
    if (!e)
        return NULL;
    pthread_mutex_lock(&lock);
    e->codes.extension = next_ext++;
    e->next = H(dpy)->exts;
    H(dpy)->exts = e;
    pthread_mutex_unlock(&lock);
    return &e->codes;
}

typedef int (*CloseDisplayProc)(Display *, XExtCodes *);

EXPORT CloseDisplayProc XESetCloseDisplay(Display *dpy, int extension, CloseDisplayProc proc)
{
    CloseDisplayProc old = NULL;
    pthread_mutex_lock(&lock);
    for (Ext *e = H(dpy)->exts; e; e = e->next)
        if (e->codes.extension == extension) {
            old = e->close;
            e->close = proc;
        }
    pthread_mutex_unlock(&lock);
    return old;
}

EXPORT Bool XQueryExtension(Display *dpy, const char *name, int *major, int *event, int *error)
{
    /* No server, no extensions: freeglut, glxgears and softgl's GLX all
     * cope (GLX is softgl's own, MIT-SHM falls back to XPutImage). */
    (void)dpy, (void)name;
    if (major)
        *major = 0;
    if (event)
        *event = 0;
    if (error)
        *error = 0;
    return False;
}

EXPORT char **XListExtensions(Display *dpy, int *n)
{
    (void)dpy;
    if (n)
        *n = 0;
    return NULL;
}

EXPORT int XFreeExtensionList(char **list)
{
    (void)list;
    return 1;
}

EXPORT Status XInitThreads(void)
{
    return 1;
}

EXPORT void XLockDisplay(Display *dpy)
{
    (void)dpy;
}

EXPORT void XUnlockDisplay(Display *dpy)
{
    (void)dpy;
}

EXPORT int XFree(void *p)
{
    free(p);
    return 1;
}

EXPORT int XFlush(Display *dpy)
{
    (void)dpy;
    return 1;
}

EXPORT int XSync(Display *dpy, Bool discard)
{
    if (!dpy)
        return 0;
    pthread_mutex_lock(&lock);
    bump(dpy);
    if (discard)
        while (qlen(dpy) > 0) {
            XEvent ev;
            take(dpy, 0, &ev);
        }
    pthread_mutex_unlock(&lock);
    return 1;
}

EXPORT int XNoOp(Display *dpy)
{
    (void)dpy;
    return 1;
}

typedef int (*AfterFunction)(Display *);

EXPORT AfterFunction XSynchronize(Display *dpy, Bool on)
{
    (void)dpy, (void)on;
    return NULL;
}

EXPORT AfterFunction XSetAfterFunction(Display *dpy, AfterFunction f)
{
    (void)dpy, (void)f;
    return NULL;
}

EXPORT int XSetCloseDownMode(Display *dpy, int mode)
{
    (void)dpy, (void)mode;
    return 1;
}

EXPORT int XBell(Display *dpy, int percent)
{
    (void)dpy, (void)percent;
    return 1;
}

/* The macro equivalents. */
EXPORT int XConnectionNumber(Display *dpy) { return P(dpy)->fd; }
EXPORT int XDefaultScreen(Display *dpy) { return P(dpy)->default_screen; }
EXPORT int XScreenCount(Display *dpy) { return P(dpy)->nscreens; }
EXPORT Screen *XScreenOfDisplay(Display *dpy, int s) { return &P(dpy)->screens[s]; }
EXPORT Screen *XDefaultScreenOfDisplay(Display *dpy) { return &H(dpy)->screen; }
EXPORT Window XRootWindow(Display *dpy, int s) { return P(dpy)->screens[s].root; }
EXPORT Window XDefaultRootWindow(Display *dpy) { return H(dpy)->screen.root; }
EXPORT Window XRootWindowOfScreen(Screen *s) { return s->root; }
EXPORT Visual *XDefaultVisual(Display *dpy, int s) { return P(dpy)->screens[s].root_visual; }
EXPORT Visual *XDefaultVisualOfScreen(Screen *s) { return s->root_visual; }
EXPORT int XDefaultDepth(Display *dpy, int s) { return P(dpy)->screens[s].root_depth; }
EXPORT int XDefaultDepthOfScreen(Screen *s) { return s->root_depth; }
EXPORT int XDisplayPlanes(Display *dpy, int s) { return P(dpy)->screens[s].root_depth; }
EXPORT int XDisplayCells(Display *dpy, int s) { return P(dpy)->screens[s].root_visual->map_entries; }
EXPORT Colormap XDefaultColormap(Display *dpy, int s) { return P(dpy)->screens[s].cmap; }
EXPORT Colormap XDefaultColormapOfScreen(Screen *s) { return s->cmap; }
EXPORT GC XDefaultGC(Display *dpy, int s) { return P(dpy)->screens[s].default_gc; }
EXPORT GC XDefaultGCOfScreen(Screen *s) { return s->default_gc; }
EXPORT unsigned long XBlackPixel(Display *dpy, int s) { return P(dpy)->screens[s].black_pixel; }
EXPORT unsigned long XWhitePixel(Display *dpy, int s) { return P(dpy)->screens[s].white_pixel; }
EXPORT unsigned long XBlackPixelOfScreen(Screen *s) { return s->black_pixel; }
EXPORT unsigned long XWhitePixelOfScreen(Screen *s) { return s->white_pixel; }
EXPORT int XDisplayWidth(Display *dpy, int s) { return P(dpy)->screens[s].width; }
EXPORT int XDisplayHeight(Display *dpy, int s) { return P(dpy)->screens[s].height; }
EXPORT int XDisplayWidthMM(Display *dpy, int s) { return P(dpy)->screens[s].mwidth; }
EXPORT int XDisplayHeightMM(Display *dpy, int s) { return P(dpy)->screens[s].mheight; }
EXPORT int XWidthOfScreen(Screen *s) { return s->width; }
EXPORT int XHeightOfScreen(Screen *s) { return s->height; }
EXPORT int XWidthMMOfScreen(Screen *s) { return s->mwidth; }
EXPORT int XHeightMMOfScreen(Screen *s) { return s->mheight; }
EXPORT int XPlanesOfScreen(Screen *s) { return s->root_depth; }
EXPORT Display *XDisplayOfScreen(Screen *s) { return (Display *)s->display; }
EXPORT int XScreenNumberOfScreen(Screen *s) { return (int)(s - ((PubDisplay *)s->display)->screens); }
EXPORT char *XDisplayString(Display *dpy) { return P(dpy)->display_name; }
EXPORT char *XServerVendor(Display *dpy) { return P(dpy)->vendor; }
EXPORT int XVendorRelease(Display *dpy) { return P(dpy)->release; }
EXPORT int XProtocolVersion(Display *dpy) { return P(dpy)->proto_major_version; }
EXPORT int XProtocolRevision(Display *dpy) { return P(dpy)->proto_minor_version; }
EXPORT int XQLength(Display *dpy) { return P(dpy)->qlen; }
EXPORT unsigned long XNextRequest(Display *dpy) { return P(dpy)->request + 1; }
EXPORT unsigned long XLastKnownRequestProcessed(Display *dpy) { return P(dpy)->last_request_read; }
EXPORT int XBitmapUnit(Display *dpy) { return P(dpy)->bitmap_unit; }
EXPORT int XBitmapPad(Display *dpy) { return P(dpy)->bitmap_pad; }
EXPORT int XBitmapBitOrder(Display *dpy) { return P(dpy)->bitmap_bit_order; }
EXPORT int XImageByteOrder(Display *dpy) { return P(dpy)->byte_order; }
EXPORT long XMaxRequestSize(Display *dpy) { return (long)P(dpy)->max_request_size; }
EXPORT long XExtendedMaxRequestSize(Display *dpy) { (void)dpy; return 0; }
EXPORT int XDoesBackingStore(Screen *s) { return s->backing_store; }
EXPORT Bool XDoesSaveUnders(Screen *s) { return s->save_unders; }
EXPORT long XEventMaskOfScreen(Screen *s) { return s->root_input_mask; }
EXPORT VisualID XVisualIDFromVisual(Visual *v) { return v ? v->visualid : 0; }

EXPORT int *XListDepths(Display *dpy, int s, int *n)
{
    Screen *sc = &P(dpy)->screens[s];
    int *d = malloc((size_t)sc->ndepths * sizeof *d);
    if (!d) {
        *n = 0;
        return NULL;
    }
    for (int i = 0; i < sc->ndepths; i++)
        d[i] = sc->depths[i].depth;
    *n = sc->ndepths;
    return d;
}

/* ---- visuals ---- */

static int screen_of_visual(Display *dpy, Visual *v, int *depth)
{
    for (int i = 0; i < NVISUALS; i++)
        if (&H(dpy)->visuals[i] == v) {
            *depth = visual_formats[i].depth;
            return 0;
        }
    return -1;
}

static void fill_visual_info(Display *dpy, int i, XVisualInfo *vi)
{
    Visual *v = &H(dpy)->visuals[i];
    vi->visual = v;
    vi->visualid = v->visualid;
    vi->screen = 0;
    vi->depth = visual_formats[i].depth;
#if defined(__cplusplus) || defined(c_plusplus)
    vi->c_class = TrueColor;
#else
    vi->class = TrueColor;
#endif
    vi->red_mask = v->red_mask;
    vi->green_mask = v->green_mask;
    vi->blue_mask = v->blue_mask;
    vi->colormap_size = v->map_entries;
    vi->bits_per_rgb = v->bits_per_rgb;
}

EXPORT XVisualInfo *XGetVisualInfo(Display *dpy, long mask, XVisualInfo *t, int *n)
{
    XVisualInfo all[NVISUALS];
    int count = 0;
    for (int i = 0; i < NVISUALS; i++) {
        XVisualInfo vi;
        fill_visual_info(dpy, i, &vi);
        if (t && (((mask & VisualIDMask) && vi.visualid != t->visualid) || ((mask & VisualScreenMask) && vi.screen != t->screen) ||
                  ((mask & VisualDepthMask) && vi.depth != t->depth) ||
#if defined(__cplusplus) || defined(c_plusplus)
                  ((mask & VisualClassMask) && vi.c_class != t->c_class) ||
#else
                  ((mask & VisualClassMask) && vi.class != t->class) ||
#endif
                  ((mask & VisualRedMaskMask) && vi.red_mask != t->red_mask) ||
                  ((mask & VisualGreenMaskMask) && vi.green_mask != t->green_mask) ||
                  ((mask & VisualBlueMaskMask) && vi.blue_mask != t->blue_mask) ||
                  ((mask & VisualColormapSizeMask) && vi.colormap_size != t->colormap_size) ||
                  ((mask & VisualBitsPerRGBMask) && vi.bits_per_rgb != t->bits_per_rgb)))
            continue;
        all[count++] = vi;
    }
    if (n)
        *n = count;
    if (count == 0)
        return NULL;
    XVisualInfo *r = malloc((size_t)count * sizeof *r);
    if (!r) {
        if (n)
            *n = 0;
        return NULL;
    }
    memcpy(r, all, (size_t)count * sizeof *r);
    return r;
}

EXPORT Status XMatchVisualInfo(Display *dpy, int screen, int depth, int klass, XVisualInfo *out)
{
    for (int i = 0; i < NVISUALS; i++)
        if (screen == 0 && visual_formats[i].depth == depth && klass == TrueColor) {
            fill_visual_info(dpy, i, out);
            return 1;
        }
    return 0;
}

EXPORT XPixmapFormatValues *XListPixmapFormats(Display *dpy, int *n)
{
    (void)dpy;
    static const int depths[] = {1, 24, 32};
    XPixmapFormatValues *f = malloc(3 * sizeof *f);
    if (!f) {
        *n = 0;
        return NULL;
    }
    for (int i = 0; i < 3; i++) {
        f[i].depth = depths[i];
        f[i].bits_per_pixel = depths[i] == 1 ? 1 : 32;
        f[i].scanline_pad = 32;
    }
    *n = 3;
    return f;
}

/* ---- windows ---- */

EXPORT Window XCreateWindow(Display *dpy, Window parent, int x, int y, unsigned w, unsigned h, unsigned border, int depth,
                            unsigned klass, Visual *visual, unsigned long mask, XSetWindowAttributes *attrs)
{
    pthread_mutex_lock(&lock);
    bump(dpy);
    HDrawable *p = is_root(dpy, parent) ? NULL : find_window(dpy, parent);
    if (!is_root(dpy, parent) && !p) {
        pthread_mutex_unlock(&lock);
        x_error(dpy, BadWindow, X_CreateWindow, parent);
        return None;
    }
    HDrawable *d = w && h ? calloc(1, sizeof *d) : NULL;
    if (!d) {
        pthread_mutex_unlock(&lock);
        x_error(dpy, w && h ? BadAlloc : BadValue, X_CreateWindow, 0);
        return None;
    }
    d->id = new_id();
    d->kind = KIND_WINDOW;
    d->parent = parent;
    d->x = x;
    d->y = y;
    d->w = w;
    d->h = h;
    d->border = border;
    d->input_only = klass == InputOnly;
    /* CopyFromParent: the parent's depth and visual (the root's here). */
    int vdepth = 24;
    if (visual == CopyFromParent || !visual || screen_of_visual(dpy, visual, &vdepth) < 0)
        visual = p ? p->visual : H(dpy)->screen.root_visual, vdepth = p ? (int)p->depth : 24;
    d->visual = visual;
    d->depth = depth == CopyFromParent ? (unsigned)vdepth : (unsigned)depth;
    if (d->input_only)
        d->depth = 0;
    d->cmap = H(dpy)->screen.cmap;
    if (attrs) {
        if (mask & CWEventMask)
            d->event_mask = attrs->event_mask;
        if (mask & CWColormap)
            d->cmap = attrs->colormap;
        if (mask & CWOverrideRedirect)
            d->override_redirect = attrs->override_redirect;
    }
    d->next = H(dpy)->drawables;
    H(dpy)->drawables = d;
    XID id = d->id;
    pthread_mutex_unlock(&lock);
    return id;
}

EXPORT Window XCreateSimpleWindow(Display *dpy, Window parent, int x, int y, unsigned w, unsigned h, unsigned border,
                                  unsigned long border_pixel, unsigned long background)
{
    (void)border_pixel, (void)background;
    return XCreateWindow(dpy, parent, x, y, w, h, border, CopyFromParent, InputOutput, CopyFromParent, 0, NULL);
}

/* Runs `f` on window `w`, or reports BadWindow for `request`. */
#define WITH_WINDOW(dpy, win, request, body)                                                                           \
    do {                                                                                                               \
        pthread_mutex_lock(&lock);                                                                                     \
        bump(dpy);                                                                                                     \
        HDrawable *w_ = find_window(dpy, win);                                                                         \
        if (!w_) {                                                                                                     \
            pthread_mutex_unlock(&lock);                                                                               \
            if (!is_root(dpy, win))                                                                                    \
                x_error(dpy, BadWindow, request, win);                                                                 \
            return is_root(dpy, win);                                                                                  \
        }                                                                                                              \
        body;                                                                                                          \
        pthread_mutex_unlock(&lock);                                                                                   \
        return 1;                                                                                                      \
    } while (0)

EXPORT int XDestroyWindow(Display *dpy, Window win) { WITH_WINDOW(dpy, win, X_DestroyWindow, destroy_window(dpy, w_)); }

EXPORT int XDestroySubwindows(Display *dpy, Window win)
{
    WITH_WINDOW(dpy, win, X_DestroySubwindows, {
        for (;;) {
            HDrawable *c = H(dpy)->drawables;
            while (c && !(c->kind == KIND_WINDOW && c->parent == w_->id))
                c = c->next;
            if (!c)
                break;
            destroy_window(dpy, c);
        }
    });
}

EXPORT int XMapWindow(Display *dpy, Window win) { WITH_WINDOW(dpy, win, X_MapWindow, map_window(dpy, w_)); }
EXPORT int XMapRaised(Display *dpy, Window win) { WITH_WINDOW(dpy, win, X_MapWindow, map_window(dpy, w_)); }
EXPORT int XUnmapWindow(Display *dpy, Window win) { WITH_WINDOW(dpy, win, X_UnmapWindow, unmap_window(dpy, w_)); }

EXPORT int XMapSubwindows(Display *dpy, Window win)
{
    WITH_WINDOW(dpy, win, X_MapSubwindows, {
        for (HDrawable *c = H(dpy)->drawables; c; c = c->next)
            if (c->kind == KIND_WINDOW && c->parent == w_->id)
                map_window(dpy, c);
    });
}

EXPORT int XUnmapSubwindows(Display *dpy, Window win)
{
    WITH_WINDOW(dpy, win, X_UnmapSubwindows, {
        for (HDrawable *c = H(dpy)->drawables; c; c = c->next)
            if (c->kind == KIND_WINDOW && c->parent == w_->id)
                unmap_window(dpy, c);
    });
}

EXPORT Status XWithdrawWindow(Display *dpy, Window win, int screen)
{
    (void)screen;
    WITH_WINDOW(dpy, win, X_UnmapWindow, unmap_window(dpy, w_));
}

EXPORT Status XIconifyWindow(Display *dpy, Window win, int screen)
{
    (void)screen;
    WITH_WINDOW(dpy, win, X_UnmapWindow, unmap_window(dpy, w_));
}

static void configure(Display *dpy, HDrawable *w, unsigned mask, int x, int y, unsigned width, unsigned height, unsigned border)
{
    unsigned ow = w->w, oh = w->h;
    if (mask & CWX)
        w->x = x;
    if (mask & CWY)
        w->y = y;
    if ((mask & CWWidth) && width > 0)
        w->w = width;
    if ((mask & CWHeight) && height > 0)
        w->h = height;
    if (mask & CWBorderWidth)
        w->border = border;
    if (w->w != ow || w->h != oh) {
        free(w->pixels);
        w->pixels = NULL;
    }
    send_configure(dpy, w);
    if ((w->w > ow || w->h > oh) && viewable(dpy, w))
        expose_tree(dpy, w);
}

EXPORT int XConfigureWindow(Display *dpy, Window win, unsigned mask, XWindowChanges *c)
{
    WITH_WINDOW(dpy, win, X_ConfigureWindow, configure(dpy, w_, mask, c->x, c->y, (unsigned)c->width, (unsigned)c->height, (unsigned)c->border_width));
}

EXPORT int XMoveWindow(Display *dpy, Window win, int x, int y)
{
    WITH_WINDOW(dpy, win, X_ConfigureWindow, configure(dpy, w_, CWX | CWY, x, y, 0, 0, 0));
}

EXPORT int XResizeWindow(Display *dpy, Window win, unsigned width, unsigned height)
{
    WITH_WINDOW(dpy, win, X_ConfigureWindow, configure(dpy, w_, CWWidth | CWHeight, 0, 0, width, height, 0));
}

EXPORT int XMoveResizeWindow(Display *dpy, Window win, int x, int y, unsigned width, unsigned height)
{
    WITH_WINDOW(dpy, win, X_ConfigureWindow, configure(dpy, w_, CWX | CWY | CWWidth | CWHeight, x, y, width, height, 0));
}

EXPORT int XSetWindowBorderWidth(Display *dpy, Window win, unsigned width)
{
    WITH_WINDOW(dpy, win, X_ConfigureWindow, configure(dpy, w_, CWBorderWidth, 0, 0, 0, 0, width));
}

EXPORT int XRaiseWindow(Display *dpy, Window win) { WITH_WINDOW(dpy, win, X_ConfigureWindow, (void)w_); }
EXPORT int XLowerWindow(Display *dpy, Window win) { WITH_WINDOW(dpy, win, X_ConfigureWindow, (void)w_); }

EXPORT int XSelectInput(Display *dpy, Window win, long mask) { WITH_WINDOW(dpy, win, X_ChangeWindowAttributes, w_->event_mask = mask); }

EXPORT int XChangeWindowAttributes(Display *dpy, Window win, unsigned long mask, XSetWindowAttributes *a)
{
    WITH_WINDOW(dpy, win, X_ChangeWindowAttributes, {
        if (mask & CWEventMask)
            w_->event_mask = a->event_mask;
        if (mask & CWColormap)
            w_->cmap = a->colormap;
        if (mask & CWOverrideRedirect)
            w_->override_redirect = a->override_redirect;
    });
}

EXPORT int XSetWindowBackground(Display *dpy, Window win, unsigned long pixel) { (void)pixel; WITH_WINDOW(dpy, win, X_ChangeWindowAttributes, (void)w_); }
EXPORT int XSetWindowBackgroundPixmap(Display *dpy, Window win, Pixmap pm) { (void)pm; WITH_WINDOW(dpy, win, X_ChangeWindowAttributes, (void)w_); }
EXPORT int XSetWindowBorder(Display *dpy, Window win, unsigned long pixel) { (void)pixel; WITH_WINDOW(dpy, win, X_ChangeWindowAttributes, (void)w_); }
EXPORT int XSetWindowColormap(Display *dpy, Window win, Colormap c) { WITH_WINDOW(dpy, win, X_ChangeWindowAttributes, w_->cmap = c); }
EXPORT int XDefineCursor(Display *dpy, Window win, Cursor c) { (void)c; WITH_WINDOW(dpy, win, X_ChangeWindowAttributes, (void)w_); }
EXPORT int XUndefineCursor(Display *dpy, Window win) { WITH_WINDOW(dpy, win, X_ChangeWindowAttributes, (void)w_); }

EXPORT int XClearWindow(Display *dpy, Window win) { WITH_WINDOW(dpy, win, X_ClearArea, (void)w_); }

EXPORT int XClearArea(Display *dpy, Window win, int x, int y, unsigned w, unsigned h, Bool exposures)
{
    (void)x, (void)y, (void)w, (void)h, (void)exposures;
    WITH_WINDOW(dpy, win, X_ClearArea, (void)w_);
}

EXPORT Status XGetWindowAttributes(Display *dpy, Window win, XWindowAttributes *a)
{
    pthread_mutex_lock(&lock);
    bump(dpy);
    memset(a, 0, sizeof *a);
    Screen *s = &H(dpy)->screen;
    a->root = s->root;
    a->screen = s;
    a->bit_gravity = ForgetGravity;
    a->win_gravity = NorthWestGravity;
    a->backing_store = NotUseful;
    a->backing_planes = AllPlanes;
    a->map_installed = True;
    if (is_root(dpy, win)) {
        a->width = s->width;
        a->height = s->height;
        a->depth = s->root_depth;
        a->visual = s->root_visual;
        a->class = InputOutput;
        a->colormap = s->cmap;
        a->map_state = IsViewable;
        a->your_event_mask = a->all_event_masks = s->root_input_mask;
        pthread_mutex_unlock(&lock);
        return 1;
    }
    HDrawable *w = find_window(dpy, win);
    if (!w) {
        pthread_mutex_unlock(&lock);
        x_error(dpy, BadWindow, X_GetWindowAttributes, win);
        return 0;
    }
    a->x = w->x;
    a->y = w->y;
    a->width = (int)w->w;
    a->height = (int)w->h;
    a->border_width = (int)w->border;
    a->depth = (int)w->depth;
    a->visual = w->visual;
    a->class = w->input_only ? InputOnly : InputOutput;
    a->colormap = w->cmap;
    a->map_state = !w->mapped ? IsUnmapped : viewable(dpy, w) ? IsViewable : IsUnviewable;
    a->your_event_mask = a->all_event_masks = w->event_mask;
    a->override_redirect = w->override_redirect;
    pthread_mutex_unlock(&lock);
    return 1;
}

EXPORT Status XGetGeometry(Display *dpy, Drawable d, Window *root, int *x, int *y, unsigned *w, unsigned *h, unsigned *border,
                           unsigned *depth)
{
    pthread_mutex_lock(&lock);
    bump(dpy);
    Screen *s = &H(dpy)->screen;
    HDrawable *dr = find(dpy, d);
    if (!dr && !is_root(dpy, d)) {
        pthread_mutex_unlock(&lock);
        x_error(dpy, BadDrawable, X_GetGeometry, d);
        return 0;
    }
    *root = s->root;
    *x = dr ? dr->x : 0;
    *y = dr ? dr->y : 0;
    *w = dr ? dr->w : (unsigned)s->width;
    *h = dr ? dr->h : (unsigned)s->height;
    *border = dr ? dr->border : 0;
    *depth = dr ? dr->depth : (unsigned)s->root_depth;
    pthread_mutex_unlock(&lock);
    return 1;
}

EXPORT Status XQueryTree(Display *dpy, Window win, Window *root, Window *parent, Window **children, unsigned *n)
{
    pthread_mutex_lock(&lock);
    bump(dpy);
    HDrawable *w = find_window(dpy, win);
    if (!w && !is_root(dpy, win)) {
        pthread_mutex_unlock(&lock);
        x_error(dpy, BadWindow, X_QueryTree, win);
        return 0;
    }
    *root = ROOT_ID;
    *parent = w ? w->parent : None;
    unsigned count = 0;
    for (HDrawable *c = H(dpy)->drawables; c; c = c->next)
        count += c->kind == KIND_WINDOW && c->parent == win;
    Window *list = count ? malloc(count * sizeof *list) : NULL;
    unsigned i = 0;
    if (list)
        for (HDrawable *c = H(dpy)->drawables; c; c = c->next)
            if (c->kind == KIND_WINDOW && c->parent == win)
                list[count - 1 - i++] = c->id; /* bottom to top: creation order */
    *children = list;
    *n = list ? count : 0;
    pthread_mutex_unlock(&lock);
    return 1;
}

/* The position of a window's origin on the root window. */
static void root_position(Display *dpy, Window win, int *x, int *y)
{
    *x = *y = 0;
    HDrawable *w;
    while ((w = find_window(dpy, win))) {
        *x += w->x + (int)w->border;
        *y += w->y + (int)w->border;
        win = w->parent;
    }
}

EXPORT Bool XTranslateCoordinates(Display *dpy, Window src, Window dst, int sx, int sy, int *dx, int *dy, Window *child)
{
    int ax, ay, bx, by;
    pthread_mutex_lock(&lock);
    bump(dpy);
    int ok = (is_root(dpy, src) || find_window(dpy, src)) && (is_root(dpy, dst) || find_window(dpy, dst));
    if (ok) {
        root_position(dpy, src, &ax, &ay);
        root_position(dpy, dst, &bx, &by);
        *dx = sx + ax - bx;
        *dy = sy + ay - by;
        /* The mapped child of dst holding the point, topmost first (the
         * list is newest first, and windows stack in creation order). */
        *child = None;
        for (HDrawable *c = H(dpy)->drawables; c && *child == None; c = c->next)
            if (c->kind == KIND_WINDOW && c->parent == dst && c->mapped && *dx >= c->x && *dy >= c->y &&
                *dx < c->x + (int)(c->w + 2 * c->border) && *dy < c->y + (int)(c->h + 2 * c->border))
                *child = c->id;
    }
    pthread_mutex_unlock(&lock);
    if (!ok)
        x_error(dpy, BadWindow, X_TranslateCoords, src);
    return ok;
}

EXPORT int XReparentWindow(Display *dpy, Window win, Window parent, int x, int y)
{
    WITH_WINDOW(dpy, win, X_ReparentWindow, {
        w_->parent = parent;
        w_->x = x;
        w_->y = y;
    });
}

/* ---- pixmaps, GCs, cursors, colormaps ---- */

EXPORT Pixmap XCreatePixmap(Display *dpy, Drawable d, unsigned w, unsigned h, unsigned depth)
{
    (void)d;
    pthread_mutex_lock(&lock);
    bump(dpy);
    HDrawable *p = w && h ? calloc(1, sizeof *p) : NULL;
    if (!p) {
        pthread_mutex_unlock(&lock);
        x_error(dpy, w && h ? BadAlloc : BadValue, X_CreatePixmap, 0);
        return None;
    }
    p->id = new_id();
    p->kind = KIND_PIXMAP;
    p->parent = ROOT_ID;
    p->w = w;
    p->h = h;
    p->depth = depth;
    p->next = H(dpy)->drawables;
    H(dpy)->drawables = p;
    XID id = p->id;
    pthread_mutex_unlock(&lock);
    return id;
}

EXPORT int XFreePixmap(Display *dpy, Pixmap pm)
{
    pthread_mutex_lock(&lock);
    bump(dpy);
    HDrawable *p = find(dpy, pm);
    if (p && p->kind == KIND_PIXMAP)
        unlink_drawable(dpy, p);
    pthread_mutex_unlock(&lock);
    if (!p || p->kind != KIND_PIXMAP)
        x_error(dpy, BadPixmap, X_FreePixmap, pm);
    return 1;
}

EXPORT Pixmap XCreateBitmapFromData(Display *dpy, Drawable d, const char *data, unsigned w, unsigned h)
{
    (void)data;
    return XCreatePixmap(dpy, d, w, h, 1);
}

EXPORT Pixmap XCreatePixmapFromBitmapData(Display *dpy, Drawable d, char *data, unsigned w, unsigned h, unsigned long fg,
                                          unsigned long bg, unsigned depth)
{
    (void)data, (void)fg, (void)bg;
    return XCreatePixmap(dpy, d, w, h, depth);
}

EXPORT GC XCreateGC(Display *dpy, Drawable d, unsigned long mask, XGCValues *v)
{
    (void)mask, (void)v;
    pthread_mutex_lock(&lock);
    bump(dpy);
    int ok = is_root(dpy, d) || find(dpy, d);
    pthread_mutex_unlock(&lock);
    if (!ok) {
        x_error(dpy, BadDrawable, X_CreateGC, d);
        return NULL;
    }
    /* An opaque block (struct _XGC is private; its first words are
     * ext_data and the GContext, which XGContextFromGC reads). */
    XID *gc = calloc(1, 256);
    if (gc)
        gc[1] = new_id();
    return (GC)gc;
}

EXPORT int XFreeGC(Display *dpy, GC gc)
{
    (void)dpy;
    free(gc);
    return 1;
}

EXPORT GContext XGContextFromGC(GC gc) { return gc ? ((XID *)gc)[1] : 0; }
EXPORT int XSetForeground(Display *dpy, GC gc, unsigned long p) { (void)dpy, (void)gc, (void)p; return 1; }
EXPORT int XSetBackground(Display *dpy, GC gc, unsigned long p) { (void)dpy, (void)gc, (void)p; return 1; }
EXPORT int XSetFunction(Display *dpy, GC gc, int f) { (void)dpy, (void)gc, (void)f; return 1; }
EXPORT int XSetFont(Display *dpy, GC gc, Font f) { (void)dpy, (void)gc, (void)f; return 1; }
EXPORT int XSetLineAttributes(Display *dpy, GC gc, unsigned w, int s, int c, int j) { (void)dpy, (void)gc, (void)w, (void)s, (void)c, (void)j; return 1; }
EXPORT int XChangeGC(Display *dpy, GC gc, unsigned long m, XGCValues *v) { (void)dpy, (void)gc, (void)m, (void)v; return 1; }
EXPORT int XSetGraphicsExposures(Display *dpy, GC gc, Bool b) { (void)dpy, (void)gc, (void)b; return 1; }

/* Drawing requests: no server draws them (windows show what XPutImage put). */
EXPORT int XDrawLine(Display *dpy, Drawable d, GC gc, int a, int b, int c, int e) { (void)dpy, (void)d, (void)gc, (void)a, (void)b, (void)c, (void)e; return 1; }
EXPORT int XDrawRectangle(Display *dpy, Drawable d, GC gc, int x, int y, unsigned w, unsigned h) { (void)dpy, (void)d, (void)gc, (void)x, (void)y, (void)w, (void)h; return 1; }
EXPORT int XFillRectangle(Display *dpy, Drawable d, GC gc, int x, int y, unsigned w, unsigned h) { (void)dpy, (void)d, (void)gc, (void)x, (void)y, (void)w, (void)h; return 1; }
EXPORT int XDrawString(Display *dpy, Drawable d, GC gc, int x, int y, const char *s, int n) { (void)dpy, (void)d, (void)gc, (void)x, (void)y, (void)s, (void)n; return 1; }
EXPORT int XCopyArea(Display *dpy, Drawable s, Drawable d, GC gc, int sx, int sy, unsigned w, unsigned h, int dx, int dy)
{
    (void)dpy, (void)s, (void)d, (void)gc, (void)sx, (void)sy, (void)w, (void)h, (void)dx, (void)dy;
    return 1;
}

EXPORT Cursor XCreateFontCursor(Display *dpy, unsigned shape)
{
    (void)shape;
    pthread_mutex_lock(&lock);
    bump(dpy);
    Cursor c = new_id();
    pthread_mutex_unlock(&lock);
    return c;
}

EXPORT Cursor XCreatePixmapCursor(Display *dpy, Pixmap s, Pixmap m, XColor *fg, XColor *bg, unsigned x, unsigned y)
{
    (void)s, (void)m, (void)fg, (void)bg, (void)x, (void)y;
    return XCreateFontCursor(dpy, 0);
}

EXPORT int XFreeCursor(Display *dpy, Cursor c) { (void)dpy, (void)c; return 1; }

EXPORT Colormap XCreateColormap(Display *dpy, Window w, Visual *v, int alloc)
{
    (void)w, (void)v, (void)alloc;
    return XCreateFontCursor(dpy, 0); /* a fresh id */
}

EXPORT int XFreeColormap(Display *dpy, Colormap c) { (void)dpy, (void)c; return 1; }
EXPORT int XInstallColormap(Display *dpy, Colormap c) { (void)dpy, (void)c; return 1; }
EXPORT int XStoreColor(Display *dpy, Colormap c, XColor *col) { (void)dpy, (void)c, (void)col; return 1; }
EXPORT int XStoreColors(Display *dpy, Colormap c, XColor *col, int n) { (void)dpy, (void)c, (void)col, (void)n; return 1; }

/* TrueColor 8-8-8: pixel <-> 16-bit channels. */
EXPORT Status XAllocColor(Display *dpy, Colormap c, XColor *col)
{
    (void)dpy, (void)c;
    col->pixel = ((unsigned long)(col->red >> 8) << 16) | ((unsigned long)(col->green >> 8) << 8) | (col->blue >> 8);
    col->red = (unsigned short)((col->red >> 8) * 257);
    col->green = (unsigned short)((col->green >> 8) * 257);
    col->blue = (unsigned short)((col->blue >> 8) * 257);
    return 1;
}

EXPORT int XQueryColor(Display *dpy, Colormap c, XColor *col)
{
    (void)dpy, (void)c;
    col->red = (unsigned short)(((col->pixel >> 16) & 0xff) * 257);
    col->green = (unsigned short)(((col->pixel >> 8) & 0xff) * 257);
    col->blue = (unsigned short)((col->pixel & 0xff) * 257);
    col->flags = DoRed | DoGreen | DoBlue;
    return 1;
}

EXPORT int XQueryColors(Display *dpy, Colormap c, XColor *cols, int n)
{
    for (int i = 0; i < n; i++)
        XQueryColor(dpy, c, &cols[i]);
    return 1;
}

/* ---- fonts: metrics of a 9x15 cell (softgl's glXUseXFont picks its
 * built-in font by ascent + descent) ---- */

EXPORT Font XLoadFont(Display *dpy, const char *name)
{
    (void)name;
    return XCreateFontCursor(dpy, 0);
}

EXPORT XFontStruct *XQueryFont(Display *dpy, XID font)
{
    (void)dpy;
    XFontStruct *f = calloc(1, sizeof *f);
    if (!f)
        return NULL;
    f->fid = font;
    f->min_char_or_byte2 = 32;
    f->max_char_or_byte2 = 255;
    f->default_char = 32;
    f->all_chars_exist = True;
    XCharStruct cs = {0, 9, 9, 12, 3, 0};
    f->min_bounds = f->max_bounds = cs;
    f->ascent = 12;
    f->descent = 3;
    return f;
}

EXPORT XFontStruct *XLoadQueryFont(Display *dpy, const char *name)
{
    return XQueryFont(dpy, XLoadFont(dpy, name));
}

EXPORT int XFreeFontInfo(char **names, XFontStruct *info, int n)
{
    (void)names, (void)n;
    free(info);
    return 1;
}

EXPORT int XFreeFont(Display *dpy, XFontStruct *f)
{
    (void)dpy;
    free(f);
    return 1;
}

EXPORT int XUnloadFont(Display *dpy, Font f) { (void)dpy, (void)f; return 1; }

EXPORT int XTextWidth(XFontStruct *f, const char *s, int n)
{
    (void)s;
    return f ? n * f->max_bounds.width : 0;
}

/* ---- images ---- */

#undef XDestroyImage
#undef XGetPixel
#undef XPutPixel
#undef XSubImage
#undef XAddPixel

static unsigned char *pixel_at(XImage *im, int x, int y)
{
    return (unsigned char *)im->data + (long)y * im->bytes_per_line + (long)x * (im->bits_per_pixel / 8);
}

static unsigned long get_pixel(XImage *im, int x, int y)
{
    if (!im->data || x < 0 || y < 0 || x >= im->width || y >= im->height)
        return 0;
    if (im->bits_per_pixel == 1) {
        unsigned char b = ((unsigned char *)im->data)[(long)y * im->bytes_per_line + x / 8];
        return (b >> (im->bitmap_bit_order == LSBFirst ? x % 8 : 7 - x % 8)) & 1;
    }
    unsigned char *p = pixel_at(im, x, y);
    int n = im->bits_per_pixel / 8;
    unsigned long v = 0;
    for (int i = 0; i < n && i < 4; i++)
        v |= (unsigned long)p[im->byte_order == LSBFirst ? i : n - 1 - i] << (8 * i);
    return v;
}

static int put_pixel(XImage *im, int x, int y, unsigned long v)
{
    if (!im->data || x < 0 || y < 0 || x >= im->width || y >= im->height)
        return 0;
    if (im->bits_per_pixel == 1) {
        unsigned char *b = (unsigned char *)im->data + (long)y * im->bytes_per_line + x / 8;
        int bit = im->bitmap_bit_order == LSBFirst ? x % 8 : 7 - x % 8;
        *b = (unsigned char)((*b & ~(1 << bit)) | ((v & 1) << bit));
        return 1;
    }
    unsigned char *p = pixel_at(im, x, y);
    int n = im->bits_per_pixel / 8;
    for (int i = 0; i < n && i < 4; i++)
        p[im->byte_order == LSBFirst ? i : n - 1 - i] = (unsigned char)(v >> (8 * i));
    return 1;
}

static int destroy_image(XImage *im)
{
    if (im) {
        free(im->data);
        free(im->obdata);
        free(im);
    }
    return 1;
}

static XImage *create_image(Display *, Visual *, unsigned, int, int, char *, unsigned, unsigned, int, int);

static XImage *sub_image(XImage *im, int x, int y, unsigned w, unsigned h)
{
    XImage *r = create_image(NULL, NULL, (unsigned)im->depth, im->format, 0, NULL, w, h, im->bitmap_pad, 0);
    if (!r)
        return NULL;
    r->data = calloc((size_t)r->bytes_per_line * h, 1);
    if (!r->data) {
        free(r);
        return NULL;
    }
    for (unsigned j = 0; j < h; j++)
        for (unsigned i = 0; i < w; i++)
            put_pixel(r, (int)i, (int)j, get_pixel(im, x + (int)i, y + (int)j));
    return r;
}

static int add_pixel(XImage *im, long v)
{
    for (int y = 0; y < im->height; y++)
        for (int x = 0; x < im->width; x++)
            put_pixel(im, x, y, get_pixel(im, x, y) + (unsigned long)v);
    return 1;
}

EXPORT Status XInitImage(XImage *im)
{
    if (!im || im->width < 0 || im->height < 0 || im->depth <= 0 || im->bits_per_pixel <= 0)
        return 0;
    if (im->bytes_per_line == 0)
        im->bytes_per_line = ((im->width * im->bits_per_pixel + im->bitmap_pad - 1) / im->bitmap_pad) * (im->bitmap_pad / 8);
    im->f.create_image = create_image;
    im->f.destroy_image = destroy_image;
    im->f.get_pixel = get_pixel;
    im->f.put_pixel = put_pixel;
    im->f.sub_image = sub_image;
    im->f.add_pixel = add_pixel;
    return 1;
}

static XImage *create_image(Display *dpy, Visual *v, unsigned depth, int format, int offset, char *data, unsigned w, unsigned h,
                            int pad, int bpl)
{
    (void)dpy;
    if (pad != 8 && pad != 16 && pad != 32)
        return NULL;
    XImage *im = calloc(1, sizeof *im);
    if (!im)
        return NULL;
    im->width = (int)w;
    im->height = (int)h;
    im->xoffset = offset;
    im->format = format;
    im->data = data;
    im->byte_order = LSBFirst;
    im->bitmap_unit = 32;
    im->bitmap_bit_order = LSBFirst;
    im->bitmap_pad = pad;
    im->depth = (int)depth;
    im->bits_per_pixel = format == ZPixmap ? (depth == 1 ? 1 : depth <= 8 ? 8 : depth <= 16 ? 16 : 32) : 1;
    im->bytes_per_line = bpl;
    if (v) {
        im->red_mask = v->red_mask;
        im->green_mask = v->green_mask;
        im->blue_mask = v->blue_mask;
    }
    if (!XInitImage(im)) {
        free(im);
        return NULL;
    }
    return im;
}

EXPORT XImage *XCreateImage(Display *dpy, Visual *v, unsigned depth, int format, int offset, char *data, unsigned w, unsigned h,
                            int pad, int bpl)
{
    return create_image(dpy, v, depth, format, offset, data, w, h, pad, bpl);
}

EXPORT int XDestroyImage(XImage *im) { return im ? im->f.destroy_image(im) : 0; }
EXPORT unsigned long XGetPixel(XImage *im, int x, int y) { return im->f.get_pixel(im, x, y); }
EXPORT int XPutPixel(XImage *im, int x, int y, unsigned long v) { return im->f.put_pixel(im, x, y, v); }
EXPORT XImage *XSubImage(XImage *im, int x, int y, unsigned w, unsigned h) { return im->f.sub_image(im, x, y, w, h); }
EXPORT int XAddPixel(XImage *im, long v) { return im->f.add_pixel(im, v); }

/* Keeps the pixels of 24/32-bit images put into 24/32-bit drawables (what
 * XGetImage reads back); others are accepted and dropped. */
EXPORT int XPutImage(Display *dpy, Drawable d, GC gc, XImage *im, int sx, int sy, int dx, int dy, unsigned w, unsigned h)
{
    (void)gc;
    pthread_mutex_lock(&lock);
    bump(dpy);
    HDrawable *dr = find(dpy, d);
    if (!dr) {
        pthread_mutex_unlock(&lock);
        x_error(dpy, is_root(dpy, d) ? BadMatch : BadDrawable, X_PutImage, d);
        return 0;
    }
    if (im && im->data && im->format == ZPixmap && im->bits_per_pixel == 32 && (dr->depth == 24 || dr->depth == 32)) {
        if (!dr->pixels)
            dr->pixels = calloc((size_t)dr->w * dr->h, sizeof *dr->pixels);
        /* The part of the w x h rectangle inside both the image and the
         * drawable: rows are copied whole (little-endian 32-bit pixels are
         * the stored words). */
        int x0 = dx > 0 ? 0 : -dx, x1 = (int)w;
        if (sx + x0 < 0)
            x0 = -sx;
        if (x1 > im->width - sx)
            x1 = im->width - sx;
        if (x1 > (int)dr->w - dx)
            x1 = (int)dr->w - dx;
        if (dr->pixels && x0 < x1)
            for (unsigned j = 0; j < h; j++) {
                int y = dy + (int)j, iy = sy + (int)j;
                if (y < 0 || y >= (int)dr->h || iy < 0 || iy >= im->height)
                    continue;
                uint32_t *dst = dr->pixels + (size_t)y * dr->w + (size_t)(dx + x0);
                if (im->byte_order == LSBFirst) {
                    memcpy(dst, pixel_at(im, sx + x0, iy), (size_t)(x1 - x0) * 4);
                } else {
                    for (int i = x0; i < x1; i++)
                        *dst++ = (uint32_t)get_pixel(im, sx + i, iy);
                }
            }
    }
    pthread_mutex_unlock(&lock);
    return 1;
}

EXPORT XImage *XGetImage(Display *dpy, Drawable d, int x, int y, unsigned w, unsigned h, unsigned long planes, int format)
{
    (void)planes;
    pthread_mutex_lock(&lock);
    bump(dpy);
    HDrawable *dr = find(dpy, d);
    if (!dr || x < 0 || y < 0 || w == 0 || h == 0 || x + (long)w > (long)dr->w || y + (long)h > (long)dr->h || format != ZPixmap ||
        (dr->depth != 24 && dr->depth != 32)) {
        pthread_mutex_unlock(&lock);
        x_error(dpy, dr ? BadMatch : BadDrawable, X_GetImage, d);
        return NULL;
    }
    XImage *im = create_image(dpy, dr->visual ? dr->visual : H(dpy)->screen.root_visual, dr->depth, ZPixmap, 0, NULL, w, h, 32, 0);
    if (im)
        im->data = calloc((size_t)w * h, 4);
    if (im && im->data && dr->pixels)
        for (unsigned j = 0; j < h; j++)
            memcpy(im->data + (size_t)j * im->bytes_per_line, dr->pixels + (size_t)(y + (int)j) * dr->w + x, (size_t)w * 4);
    pthread_mutex_unlock(&lock);
    if (im && !im->data) {
        free(im);
        im = NULL;
    }
    return im;
}

/* ---- events ---- */

static int warned_wait;

/* Blocks until predicate(i) holds for a queued event; returns its index.
 * The lock is held. */
static int wait_for(Display *dpy, int (*pred)(Display *, XEvent *, void *), void *arg, const char *who)
{
    for (;;) {
        for (int i = 0; i < qlen(dpy); i++)
            if (pred(dpy, at(dpy, i), arg))
                return i;
        if (!warned_wait) {
            warned_wait = 1;
            fprintf(stderr, "softgl headless Xlib: %s waits for an event no server will send "
                            "(only XSendEvent from another thread can end the wait)\n", who);
        }
        pthread_cond_wait(&queued, &lock);
    }
}

static int any_event(Display *dpy, XEvent *ev, void *arg)
{
    (void)dpy, (void)ev, (void)arg;
    return 1;
}

EXPORT int XPending(Display *dpy)
{
    pthread_mutex_lock(&lock);
    int n = qlen(dpy);
    pthread_mutex_unlock(&lock);
    return n;
}

EXPORT int XEventsQueued(Display *dpy, int mode)
{
    (void)mode;
    return XPending(dpy);
}

EXPORT int XNextEvent(Display *dpy, XEvent *ev)
{
    pthread_mutex_lock(&lock);
    take(dpy, wait_for(dpy, any_event, NULL, "XNextEvent"), ev);
    pthread_mutex_unlock(&lock);
    return 0;
}

EXPORT int XPeekEvent(Display *dpy, XEvent *ev)
{
    pthread_mutex_lock(&lock);
    *ev = *at(dpy, wait_for(dpy, any_event, NULL, "XPeekEvent"));
    pthread_mutex_unlock(&lock);
    return 1;
}

/* The program's predicates run without the lock (they may call Xlib):
 * the queue is copied, then the match taken out if still there. */
typedef Bool (*Predicate)(Display *, XEvent *, XPointer);

static int find_if(Display *dpy, Predicate pred, XPointer arg, XEvent *out, int remove, int block, const char *who)
{
    unsigned long seen = 0; /* events already tested, by position */
    pthread_mutex_lock(&lock);
    for (;;) {
        int n = qlen(dpy);
        for (int i = (int)seen; i < n; i++) {
            XEvent copy = *at(dpy, i);
            pthread_mutex_unlock(&lock);
            Bool match = pred(dpy, &copy, arg);
            pthread_mutex_lock(&lock);
            if (match) {
                /* Find it again (the queue may have moved meanwhile). */
                for (int k = 0; k < qlen(dpy); k++)
                    if (!memcmp(at(dpy, k), &copy, sizeof copy)) {
                        if (remove)
                            take(dpy, k, out);
                        else
                            *out = copy;
                        pthread_mutex_unlock(&lock);
                        return 1;
                    }
            }
        }
        seen = (unsigned long)qlen(dpy);
        if (!block) {
            pthread_mutex_unlock(&lock);
            return 0;
        }
        if (!warned_wait) {
            warned_wait = 1;
            fprintf(stderr, "softgl headless Xlib: %s waits for an event no server will send "
                            "(only XSendEvent from another thread can end the wait)\n", who);
        }
        int before = qlen(dpy);
        while (qlen(dpy) == before)
            pthread_cond_wait(&queued, &lock);
        if (qlen(dpy) < before)
            seen = 0;
    }
}

EXPORT int XIfEvent(Display *dpy, XEvent *ev, Predicate pred, XPointer arg) { return find_if(dpy, pred, arg, ev, 1, 1, "XIfEvent"); }
EXPORT Bool XCheckIfEvent(Display *dpy, XEvent *ev, Predicate pred, XPointer arg) { return find_if(dpy, pred, arg, ev, 1, 0, ""); }
EXPORT int XPeekIfEvent(Display *dpy, XEvent *ev, Predicate pred, XPointer arg) { return find_if(dpy, pred, arg, ev, 0, 1, "XPeekIfEvent"); }

/* The event-mask bits that select an event type (for XMaskEvent and
 * XWindowEvent, as in Xlib's table). */
static long mask_of(int type)
{
    switch (type) {
    case KeyPress: return KeyPressMask;
    case KeyRelease: return KeyReleaseMask;
    case ButtonPress: return ButtonPressMask;
    case ButtonRelease: return ButtonReleaseMask;
    case MotionNotify: return PointerMotionMask | ButtonMotionMask | Button1MotionMask | Button2MotionMask | Button3MotionMask |
                              Button4MotionMask | Button5MotionMask | PointerMotionHintMask;
    case EnterNotify: return EnterWindowMask;
    case LeaveNotify: return LeaveWindowMask;
    case FocusIn:
    case FocusOut: return FocusChangeMask;
    case KeymapNotify: return KeymapStateMask;
    case Expose:
    case GraphicsExpose:
    case NoExpose: return ExposureMask;
    case VisibilityNotify: return VisibilityChangeMask;
    case CreateNotify: return SubstructureNotifyMask;
    case DestroyNotify:
    case UnmapNotify:
    case MapNotify:
    case ReparentNotify:
    case ConfigureNotify:
    case GravityNotify:
    case CirculateNotify: return StructureNotifyMask | SubstructureNotifyMask;
    case MapRequest:
    case ConfigureRequest:
    case CirculateRequest: return SubstructureRedirectMask;
    case ResizeRequest: return ResizeRedirectMask;
    case PropertyNotify: return PropertyChangeMask;
    case ColormapNotify: return ColormapChangeMask;
    }
    return 0; /* ClientMessage, Selection*, MappingNotify: no mask */
}

typedef struct {
    Window w;
    long mask;
    int type;
} Match;

static int match_window_mask(Display *dpy, XEvent *ev, void *arg)
{
    (void)dpy;
    Match *m = arg;
    return ev->xany.window == m->w && (mask_of(ev->type) & m->mask);
}

static int match_mask(Display *dpy, XEvent *ev, void *arg)
{
    (void)dpy;
    return (mask_of(ev->type) & ((Match *)arg)->mask) != 0;
}

static int match_type(Display *dpy, XEvent *ev, void *arg)
{
    (void)dpy;
    return ev->type == ((Match *)arg)->type;
}

static int match_window_type(Display *dpy, XEvent *ev, void *arg)
{
    (void)dpy;
    Match *m = arg;
    return ev->type == m->type && ev->xany.window == m->w;
}

static Bool check(Display *dpy, XEvent *ev, int (*pred)(Display *, XEvent *, void *), Match *m, int block, const char *who)
{
    pthread_mutex_lock(&lock);
    int i = -1;
    if (block) {
        i = wait_for(dpy, pred, m, who);
    } else {
        for (int k = 0; k < qlen(dpy) && i < 0; k++)
            if (pred(dpy, at(dpy, k), m))
                i = k;
    }
    if (i >= 0)
        take(dpy, i, ev);
    pthread_mutex_unlock(&lock);
    return i >= 0;
}

EXPORT int XWindowEvent(Display *dpy, Window w, long mask, XEvent *ev)
{
    Match m = {w, mask, 0};
    return check(dpy, ev, match_window_mask, &m, 1, "XWindowEvent");
}

EXPORT Bool XCheckWindowEvent(Display *dpy, Window w, long mask, XEvent *ev)
{
    Match m = {w, mask, 0};
    return check(dpy, ev, match_window_mask, &m, 0, "");
}

EXPORT int XMaskEvent(Display *dpy, long mask, XEvent *ev)
{
    Match m = {0, mask, 0};
    return check(dpy, ev, match_mask, &m, 1, "XMaskEvent");
}

EXPORT Bool XCheckMaskEvent(Display *dpy, long mask, XEvent *ev)
{
    Match m = {0, mask, 0};
    return check(dpy, ev, match_mask, &m, 0, "");
}

EXPORT Bool XCheckTypedEvent(Display *dpy, int type, XEvent *ev)
{
    Match m = {0, 0, type};
    return check(dpy, ev, match_type, &m, 0, "");
}

EXPORT Bool XCheckTypedWindowEvent(Display *dpy, Window w, int type, XEvent *ev)
{
    Match m = {w, 0, type};
    return check(dpy, ev, match_window_type, &m, 0, "");
}

EXPORT int XPutBackEvent(Display *dpy, XEvent *ev)
{
    pthread_mutex_lock(&lock);
    push(dpy, ev, 1);
    pthread_mutex_unlock(&lock);
    return 0;
}

/* Delivered to the window's own queue when it selected any of `mask` (or
 * for mask 0, as the server does for the window's creator). */
EXPORT Status XSendEvent(Display *dpy, Window win, Bool propagate, long mask, XEvent *ev)
{
    (void)propagate;
    pthread_mutex_lock(&lock);
    bump(dpy);
    HDrawable *w = find_window(dpy, win);
    if (!w && !is_root(dpy, win) && win != PointerWindow && win != InputFocus) {
        pthread_mutex_unlock(&lock);
        x_error(dpy, BadWindow, X_SendEvent, win);
        return 0;
    }
    if (w && (mask == 0 || (w->event_mask & mask))) {
        XEvent copy = *ev;
        copy.xany.send_event = True;
        copy.xany.display = dpy;
        copy.xany.serial = P(dpy)->request;
        push(dpy, &copy, 0);
    }
    pthread_mutex_unlock(&lock);
    return 1;
}

EXPORT Bool XGetEventData(Display *dpy, XGenericEventCookie *cookie)
{
    (void)dpy, (void)cookie;
    return False;
}

EXPORT void XFreeEventData(Display *dpy, XGenericEventCookie *cookie)
{
    (void)dpy, (void)cookie;
}

EXPORT Bool XFilterEvent(XEvent *ev, Window w)
{
    (void)ev, (void)w;
    return False;
}

/* ---- atoms and properties ---- */

static const char *const predefined_atoms[] = {
    "PRIMARY", "SECONDARY", "ARC", "ATOM", "BITMAP", "CARDINAL", "COLORMAP", "CURSOR", "CUT_BUFFER0", "CUT_BUFFER1",
    "CUT_BUFFER2", "CUT_BUFFER3", "CUT_BUFFER4", "CUT_BUFFER5", "CUT_BUFFER6", "CUT_BUFFER7", "DRAWABLE", "FONT", "INTEGER",
    "PIXMAP", "POINT", "RECTANGLE", "RESOURCE_MANAGER", "RGB_COLOR_MAP", "RGB_BEST_MAP", "RGB_BLUE_MAP", "RGB_DEFAULT_MAP",
    "RGB_GRAY_MAP", "RGB_GREEN_MAP", "RGB_RED_MAP", "STRING", "VISUALID", "WINDOW", "WM_COMMAND", "WM_HINTS",
    "WM_CLIENT_MACHINE", "WM_ICON_NAME", "WM_ICON_SIZE", "WM_NAME", "WM_NORMAL_HINTS", "WM_SIZE_HINTS", "WM_ZOOM_HINTS",
    "MIN_SPACE", "NORM_SPACE", "MAX_SPACE", "END_SPACE", "SUPERSCRIPT_X", "SUPERSCRIPT_Y", "SUBSCRIPT_X", "SUBSCRIPT_Y",
    "UNDERLINE_POSITION", "UNDERLINE_THICKNESS", "STRIKEOUT_ASCENT", "STRIKEOUT_DESCENT", "ITALIC_ANGLE", "X_HEIGHT",
    "QUAD_WIDTH", "WEIGHT", "POINT_SIZE", "RESOLUTION", "COPYRIGHT", "NOTICE", "FONT_NAME", "FAMILY_NAME", "FULL_NAME",
    "CAP_HEIGHT", "WM_CLASS", "WM_TRANSIENT_FOR",
};
_Static_assert(sizeof predefined_atoms / sizeof *predefined_atoms == XA_LAST_PREDEFINED, "Xatom.h's predefined atoms");

/* Atoms are the server's: shared by all displays. Index i is atom i + 1. */
static char **atom_names;
static size_t atom_count, atom_cap;

/* The lock held. */
static Atom intern(const char *name, int only_if_exists)
{
    if (!atom_names) {
        atom_cap = 256;
        atom_names = calloc(atom_cap, sizeof *atom_names);
        if (!atom_names)
            return None;
        for (size_t i = 0; i < XA_LAST_PREDEFINED; i++)
            atom_names[i] = strdup(predefined_atoms[i]);
        atom_count = XA_LAST_PREDEFINED;
    }
    for (size_t i = 0; i < atom_count; i++)
        if (atom_names[i] && !strcmp(atom_names[i], name))
            return (Atom)(i + 1);
    if (only_if_exists)
        return None;
    if (atom_count == atom_cap) {
        char **n = realloc(atom_names, 2 * atom_cap * sizeof *n);
        if (!n)
            return None;
        atom_names = n;
        atom_cap *= 2;
    }
    atom_names[atom_count] = strdup(name);
    return (Atom)++atom_count;
}

EXPORT Atom XInternAtom(Display *dpy, const char *name, Bool only_if_exists)
{
    if (!name)
        return None;
    pthread_mutex_lock(&lock);
    bump(dpy);
    Atom a = intern(name, only_if_exists);
    pthread_mutex_unlock(&lock);
    return a;
}

EXPORT Status XInternAtoms(Display *dpy, char **names, int n, Bool only_if_exists, Atom *out)
{
    Status ok = 1;
    for (int i = 0; i < n; i++) {
        out[i] = XInternAtom(dpy, names[i], only_if_exists);
        ok &= out[i] != None;
    }
    return ok;
}

EXPORT char *XGetAtomName(Display *dpy, Atom a)
{
    pthread_mutex_lock(&lock);
    bump(dpy);
    intern("PRIMARY", 1); /* makes the table */
    char *name = a >= 1 && a <= atom_count && atom_names[a - 1] ? strdup(atom_names[a - 1]) : NULL;
    pthread_mutex_unlock(&lock);
    if (!name)
        x_error(dpy, BadAtom, X_GetAtomName, a);
    return name;
}

static size_t item_size(int format)
{
    return format == 8 ? 1 : format == 16 ? sizeof(short) : sizeof(long);
}

EXPORT int XChangeProperty(Display *dpy, Window win, Atom name, Atom type, int format, int mode, const unsigned char *data, int n)
{
    if (format != 8 && format != 16 && format != 32) {
        x_error(dpy, BadValue, X_ChangeProperty, (XID)format);
        return 0;
    }
    pthread_mutex_lock(&lock);
    bump(dpy);
    if (!find_window(dpy, win) && !is_root(dpy, win)) {
        pthread_mutex_unlock(&lock);
        x_error(dpy, BadWindow, X_ChangeProperty, win);
        return 0;
    }
    Prop *p = H(dpy)->props;
    while (p && !(p->w == win && p->name == name))
        p = p->next;
    if (p && mode != PropModeReplace && (p->format != format || p->type != type)) {
        pthread_mutex_unlock(&lock);
        x_error(dpy, BadMatch, X_ChangeProperty, win);
        return 0;
    }
    if (!p) {
        p = calloc(1, sizeof *p);
        if (!p) {
            pthread_mutex_unlock(&lock);
            return 0;
        }
        p->w = win;
        p->name = name;
        p->next = H(dpy)->props;
        H(dpy)->props = p;
    }
    size_t sz = item_size(format), count = n > 0 ? (size_t)n : 0;
    size_t keep = mode == PropModeReplace ? 0 : p->nitems;
    unsigned char *d = malloc((keep + count) * sz + 1);
    if (d) {
        if (mode == PropModePrepend) {
            memcpy(d, data, count * sz);
            if (keep)
                memcpy(d + count * sz, p->data, keep * sz);
        } else {
            if (keep)
                memcpy(d, p->data, keep * sz);
            memcpy(d + keep * sz, data, count * sz);
        }
        free(p->data);
        p->data = d;
        p->nitems = keep + count;
        p->type = type;
        p->format = format;
    }
    pthread_mutex_unlock(&lock);
    return 1;
}

EXPORT int XDeleteProperty(Display *dpy, Window win, Atom name)
{
    pthread_mutex_lock(&lock);
    bump(dpy);
    for (Prop **pp = &H(dpy)->props; *pp; pp = &(*pp)->next)
        if ((*pp)->w == win && (*pp)->name == name) {
            Prop *p = *pp;
            *pp = p->next;
            free(p->data);
            free(p);
            break;
        }
    pthread_mutex_unlock(&lock);
    return 1;
}

/* Offsets and lengths in 32-bit units of the protocol's data, as the
 * request has them. */
EXPORT int XGetWindowProperty(Display *dpy, Window win, Atom name, long offset, long length, Bool del, Atom req_type,
                              Atom *type, int *format, unsigned long *nitems, unsigned long *after, unsigned char **prop)
{
    *type = None;
    *format = 0;
    *nitems = 0;
    *after = 0;
    *prop = NULL;
    pthread_mutex_lock(&lock);
    bump(dpy);
    if (!find_window(dpy, win) && !is_root(dpy, win)) {
        pthread_mutex_unlock(&lock);
        x_error(dpy, BadWindow, X_GetProperty, win);
        return BadWindow;
    }
    Prop **pp = &H(dpy)->props;
    while (*pp && !((*pp)->w == win && (*pp)->name == name))
        pp = &(*pp)->next;
    Prop *p = *pp;
    if (!p) {
        pthread_mutex_unlock(&lock);
        return Success;
    }
    *type = p->type;
    *format = p->format;
    if (req_type != AnyPropertyType && req_type != p->type) {
        /* The type does not match: only its size is told. */
        *after = p->nitems * (size_t)(p->format / 8);
        pthread_mutex_unlock(&lock);
        return Success;
    }
    size_t wire = (size_t)(p->format / 8), total = p->nitems * wire;
    size_t start = offset > 0 ? (size_t)offset * 4 : 0;
    if (start > total) {
        pthread_mutex_unlock(&lock);
        x_error(dpy, BadValue, X_GetProperty, (XID)offset);
        return BadValue;
    }
    size_t want = length > 0 ? (size_t)length * 4 : 0;
    size_t bytes = total - start < want ? total - start : want;
    size_t first = start / wire, count = bytes / wire, sz = item_size(p->format);
    unsigned char *out = malloc(count * sz + 1);
    if (out) {
        memcpy(out, p->data + first * sz, count * sz);
        out[count * sz] = 0; /* Xlib's extra NUL */
        *prop = out;
        *nitems = count;
        *after = total - start - count * wire;
    }
    if (del && *after == 0) {
        *pp = p->next;
        free(p->data);
        free(p);
    }
    pthread_mutex_unlock(&lock);
    return Success;
}

EXPORT Atom *XListProperties(Display *dpy, Window win, int *n)
{
    pthread_mutex_lock(&lock);
    int count = 0;
    for (Prop *p = H(dpy)->props; p; p = p->next)
        count += p->w == win;
    Atom *list = count ? malloc((size_t)count * sizeof *list) : NULL;
    int i = 0;
    if (list)
        for (Prop *p = H(dpy)->props; p; p = p->next)
            if (p->w == win)
                list[i++] = p->name;
    *n = i;
    pthread_mutex_unlock(&lock);
    return list;
}

EXPORT Status XStringListToTextProperty(char **list, int n, XTextProperty *tp)
{
    size_t len = 0;
    for (int i = 0; i < n; i++)
        len += (list[i] ? strlen(list[i]) : 0) + 1;
    char *buf = malloc(len ? len : 1);
    if (!buf)
        return 0;
    char *q = buf;
    for (int i = 0; i < n; i++) {
        size_t l = list[i] ? strlen(list[i]) : 0;
        memcpy(q, list[i] ? list[i] : "", l);
        q[l] = 0;
        q += l + 1;
    }
    if (!len)
        buf[0] = 0;
    tp->value = (unsigned char *)buf;
    tp->encoding = XA_STRING;
    tp->format = 8;
    tp->nitems = len ? len - 1 : 0;
    return 1;
}

EXPORT Status XTextPropertyToStringList(XTextProperty *tp, char ***list, int *n)
{
    int count = 0;
    for (unsigned long i = 0; i <= tp->nitems; i++)
        count += i == tp->nitems || tp->value[i] == 0;
    char **l = malloc((size_t)count * sizeof *l + tp->nitems + 1);
    if (!l)
        return 0;
    char *s = (char *)(l + count);
    memcpy(s, tp->value, tp->nitems);
    s[tp->nitems] = 0;
    for (int k = 0; k < count; k++) {
        l[k] = s;
        s += strlen(s) + 1;
    }
    *list = l;
    *n = count;
    return 1;
}

EXPORT void XFreeStringList(char **list)
{
    free(list);
}

static void set_text(Display *dpy, Window w, XTextProperty *tp, Atom name)
{
    if (tp)
        XChangeProperty(dpy, w, name, tp->encoding, tp->format, PropModeReplace, tp->value, (int)tp->nitems);
}

static void set_string(Display *dpy, Window w, const char *s, Atom name)
{
    if (s)
        XChangeProperty(dpy, w, name, XA_STRING, 8, PropModeReplace, (const unsigned char *)s, (int)strlen(s));
}

static Status get_text(Display *dpy, Window w, XTextProperty *tp, Atom name)
{
    Atom type;
    int format;
    unsigned long n, after;
    unsigned char *data;
    memset(tp, 0, sizeof *tp);
    if (XGetWindowProperty(dpy, w, name, 0, 0x7fffffff, False, AnyPropertyType, &type, &format, &n, &after, &data) != Success ||
        type == None) {
        return 0;
    }
    tp->value = data;
    tp->encoding = type;
    tp->format = format;
    tp->nitems = n;
    return 1;
}

EXPORT void XSetWMName(Display *dpy, Window w, XTextProperty *tp) { set_text(dpy, w, tp, XA_WM_NAME); }
EXPORT void XSetWMIconName(Display *dpy, Window w, XTextProperty *tp) { set_text(dpy, w, tp, XA_WM_ICON_NAME); }
EXPORT Status XGetWMName(Display *dpy, Window w, XTextProperty *tp) { return get_text(dpy, w, tp, XA_WM_NAME); }
EXPORT Status XGetWMIconName(Display *dpy, Window w, XTextProperty *tp) { return get_text(dpy, w, tp, XA_WM_ICON_NAME); }
EXPORT int XStoreName(Display *dpy, Window w, const char *s) { set_string(dpy, w, s, XA_WM_NAME); return 1; }
EXPORT int XSetIconName(Display *dpy, Window w, const char *s) { set_string(dpy, w, s, XA_WM_ICON_NAME); return 1; }

EXPORT Status XFetchName(Display *dpy, Window w, char **name)
{
    XTextProperty tp;
    *name = NULL;
    if (!get_text(dpy, w, &tp, XA_WM_NAME))
        return 0;
    *name = (char *)tp.value;
    return 1;
}

EXPORT int XSetStandardProperties(Display *dpy, Window w, const char *name, const char *icon, Pixmap pm, char **argv, int argc,
                                  XSizeHints *hints)
{
    (void)pm, (void)argv, (void)argc, (void)hints;
    set_string(dpy, w, name, XA_WM_NAME);
    set_string(dpy, w, icon, XA_WM_ICON_NAME);
    return 1;
}

EXPORT void XSetWMProperties(Display *dpy, Window w, XTextProperty *name, XTextProperty *icon, char **argv, int argc,
                             XSizeHints *normal, XWMHints *wm, XClassHint *cls)
{
    (void)argv, (void)argc, (void)normal, (void)wm, (void)cls;
    set_text(dpy, w, name, XA_WM_NAME);
    set_text(dpy, w, icon, XA_WM_ICON_NAME);
}

EXPORT Status XSetWMProtocols(Display *dpy, Window w, Atom *protocols, int n)
{
    Atom wm_protocols = XInternAtom(dpy, "WM_PROTOCOLS", False);
    return XChangeProperty(dpy, w, wm_protocols, XA_ATOM, 32, PropModeReplace, (const unsigned char *)protocols, n);
}

/* Hints only a window manager would read. */
EXPORT int XSetNormalHints(Display *dpy, Window w, XSizeHints *h) { (void)dpy, (void)w, (void)h; return 1; }
EXPORT void XSetWMNormalHints(Display *dpy, Window w, XSizeHints *h) { (void)dpy, (void)w, (void)h; }
EXPORT void XSetWMSizeHints(Display *dpy, Window w, XSizeHints *h, Atom a) { (void)dpy, (void)w, (void)h, (void)a; }
EXPORT int XSetWMHints(Display *dpy, Window w, XWMHints *h) { (void)dpy, (void)w, (void)h; return 1; }
EXPORT int XSetClassHint(Display *dpy, Window w, XClassHint *h) { (void)dpy, (void)w, (void)h; return 1; }
EXPORT int XSetTransientForHint(Display *dpy, Window w, Window f) { (void)dpy, (void)w, (void)f; return 1; }
EXPORT int XSetCommand(Display *dpy, Window w, char **argv, int argc) { (void)dpy, (void)w, (void)argv, (void)argc; return 1; }

EXPORT Status XGetWMNormalHints(Display *dpy, Window w, XSizeHints *h, long *supplied)
{
    (void)dpy, (void)w;
    memset(h, 0, sizeof *h);
    *supplied = 0;
    return 0;
}

EXPORT XSizeHints *XAllocSizeHints(void) { return calloc(1, sizeof(XSizeHints)); }
EXPORT XWMHints *XAllocWMHints(void) { return calloc(1, sizeof(XWMHints)); }
EXPORT XClassHint *XAllocClassHint(void) { return calloc(1, sizeof(XClassHint)); }

EXPORT int XParseGeometry(const char *s, int *x, int *y, unsigned *w, unsigned *h)
{
    int mask = NoValue;
    char *end;
    if (!s || !*s)
        return mask;
    if (*s == '=')
        s++;
    if (*s != '+' && *s != '-' && *s != 'x' && *s != 'X') {
        unsigned long v = strtoul(s, &end, 10);
        if (end == s)
            return 0;
        *w = (unsigned)v;
        mask |= WidthValue;
        s = end;
    }
    if (*s == 'x' || *s == 'X') {
        s++;
        unsigned long v = strtoul(s, &end, 10);
        if (end == s)
            return 0;
        *h = (unsigned)v;
        mask |= HeightValue;
        s = end;
    }
    if (*s == '+' || *s == '-') {
        int neg = *s == '-';
        long v = strtol(s + 1, &end, 10);
        if (end == s + 1)
            return 0;
        *x = neg ? -(int)v : (int)v;
        mask |= XValue | (neg ? XNegative : 0);
        s = end;
        if (*s != '+' && *s != '-')
            return 0;
        neg = *s == '-';
        v = strtol(s + 1, &end, 10);
        if (end == s + 1)
            return 0;
        *y = neg ? -(int)v : (int)v;
        mask |= YValue | (neg ? YNegative : 0);
        s = end;
    }
    return *s ? 0 : mask;
}

/* ---- keyboard and pointer: no devices ---- */

EXPORT int XLookupString(XKeyEvent *ev, char *buf, int len, KeySym *sym, XComposeStatus *st)
{
    (void)ev, (void)st;
    if (buf && len > 0)
        buf[0] = 0;
    if (sym)
        *sym = NoSymbol;
    return 0;
}

EXPORT KeySym XLookupKeysym(XKeyEvent *ev, int index) { (void)ev, (void)index; return NoSymbol; }
EXPORT KeySym XKeycodeToKeysym(Display *dpy, KeyCode k, int index) { (void)dpy, (void)k, (void)index; return NoSymbol; }
EXPORT KeySym XkbKeycodeToKeysym(Display *dpy, KeyCode k, int group, int level) { (void)dpy, (void)k, (void)group, (void)level; return NoSymbol; }
EXPORT KeyCode XKeysymToKeycode(Display *dpy, KeySym s) { (void)dpy, (void)s; return 0; }
EXPORT char *XKeysymToString(KeySym s) { (void)s; return NULL; }
EXPORT KeySym XStringToKeysym(const char *s) { (void)s; return NoSymbol; }
EXPORT int XRefreshKeyboardMapping(XMappingEvent *ev) { (void)ev; return 1; }
EXPORT Bool XkbSetDetectableAutoRepeat(Display *dpy, Bool on, Bool *supported) { (void)dpy, (void)on; if (supported) *supported = False; return False; }

EXPORT int XQueryKeymap(Display *dpy, char keys[32])
{
    (void)dpy;
    memset(keys, 0, 32);
    return 1;
}

EXPORT KeySym *XGetKeyboardMapping(Display *dpy, KeyCode first, int count, int *per)
{
    (void)dpy, (void)first, (void)count;
    *per = 0;
    return NULL;
}

EXPORT int XAutoRepeatOn(Display *dpy) { (void)dpy; return 1; }
EXPORT int XAutoRepeatOff(Display *dpy) { (void)dpy; return 1; }

EXPORT int XGetPointerMapping(Display *dpy, unsigned char *map, int n)
{
    (void)dpy;
    for (int i = 0; i < n && i < 3; i++)
        map[i] = (unsigned char)(i + 1);
    return 3;
}

EXPORT Bool XQueryPointer(Display *dpy, Window w, Window *root, Window *child, int *rx, int *ry, int *wx, int *wy, unsigned *mask)
{
    (void)w;
    *root = XDefaultRootWindow(dpy);
    *child = None;
    *rx = *ry = *wx = *wy = 0;
    *mask = 0;
    return True;
}

EXPORT int XWarpPointer(Display *dpy, Window s, Window d, int sx, int sy, unsigned sw, unsigned sh, int dx, int dy)
{
    (void)dpy, (void)s, (void)d, (void)sx, (void)sy, (void)sw, (void)sh, (void)dx, (void)dy;
    return 1;
}

EXPORT int XGrabPointer(Display *dpy, Window w, Bool owner, unsigned mask, int pm, int km, Window confine, Cursor c, Time t)
{
    (void)dpy, (void)w, (void)owner, (void)mask, (void)pm, (void)km, (void)confine, (void)c, (void)t;
    return GrabSuccess;
}

EXPORT int XGrabKeyboard(Display *dpy, Window w, Bool owner, int pm, int km, Time t)
{
    (void)dpy, (void)w, (void)owner, (void)pm, (void)km, (void)t;
    return GrabSuccess;
}

EXPORT int XUngrabPointer(Display *dpy, Time t) { (void)dpy, (void)t; return 1; }
EXPORT int XUngrabKeyboard(Display *dpy, Time t) { (void)dpy, (void)t; return 1; }
EXPORT int XSetInputFocus(Display *dpy, Window w, int revert, Time t) { (void)dpy, (void)w, (void)revert, (void)t; return 1; }

EXPORT int XGetInputFocus(Display *dpy, Window *w, int *revert)
{
    (void)dpy;
    *w = PointerRoot;
    *revert = RevertToPointerRoot;
    return 1;
}

/* ---- locale and resources ---- */

EXPORT Bool XSupportsLocale(void) { return True; }
EXPORT char *XSetLocaleModifiers(const char *m) { (void)m; return (char *)""; }
EXPORT char *XResourceManagerString(Display *dpy) { (void)dpy; return NULL; }
EXPORT char *XGetDefault(Display *dpy, const char *prog, const char *opt) { (void)dpy, (void)prog, (void)opt; return NULL; }
