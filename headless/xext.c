/* libXext.so.6 stand-in for softgl's headless Xlib (see x11.c): the
 * extensions libXext wraps are absent, as on a server without them.
 * softgl's GLX asks for MIT-SHM (src/winsys/glx/present.rs) and falls back
 * to XPutImage; programs asking for the others get "not present". */
#include <X11/Xlib.h>
#include <X11/extensions/XShm.h>
#include <X11/extensions/shape.h>

#define EXPORT __attribute__((visibility("default")))

EXPORT Bool XShmQueryExtension(Display *dpy) { (void)dpy; return False; }
EXPORT int XShmGetEventBase(Display *dpy) { (void)dpy; return 0; }

EXPORT Bool XShmQueryVersion(Display *dpy, int *major, int *minor, Bool *pixmaps)
{
    (void)dpy;
    *major = *minor = 0;
    *pixmaps = False;
    return False;
}

EXPORT int XShmPixmapFormat(Display *dpy) { (void)dpy; return 0; }
EXPORT Bool XShmAttach(Display *dpy, XShmSegmentInfo *info) { (void)dpy, (void)info; return False; }
EXPORT Bool XShmDetach(Display *dpy, XShmSegmentInfo *info) { (void)dpy, (void)info; return False; }

EXPORT Bool XShmPutImage(Display *dpy, Drawable d, GC gc, XImage *im, int sx, int sy, int dx, int dy, unsigned w, unsigned h, Bool ev)
{
    (void)dpy, (void)d, (void)gc, (void)im, (void)sx, (void)sy, (void)dx, (void)dy, (void)w, (void)h, (void)ev;
    return False;
}

EXPORT Bool XShmGetImage(Display *dpy, Drawable d, XImage *im, int x, int y, unsigned long planes)
{
    (void)dpy, (void)d, (void)im, (void)x, (void)y, (void)planes;
    return False;
}

EXPORT XImage *XShmCreateImage(Display *dpy, Visual *v, unsigned depth, int format, char *data, XShmSegmentInfo *info, unsigned w, unsigned h)
{
    (void)dpy, (void)v, (void)depth, (void)format, (void)data, (void)info, (void)w, (void)h;
    return NULL;
}

EXPORT Pixmap XShmCreatePixmap(Display *dpy, Drawable d, char *data, XShmSegmentInfo *info, unsigned w, unsigned h, unsigned depth)
{
    (void)dpy, (void)d, (void)data, (void)info, (void)w, (void)h, (void)depth;
    return None;
}

EXPORT Bool XShapeQueryExtension(Display *dpy, int *event, int *error)
{
    (void)dpy;
    *event = *error = 0;
    return False;
}

EXPORT Status XShapeQueryVersion(Display *dpy, int *major, int *minor)
{
    (void)dpy;
    *major = *minor = 0;
    return 0;
}
