/* libXi.so.6 stand-in for softgl's headless Xlib (see x11.c): no X Input
 * extension (XQueryExtension("XInputExtension") is False there), so
 * programs that check first (freeglut) never call these; those that do
 * not get BadRequest, as from a server without it. Prototypes are written
 * out (XInput2.h is not always installed). */
#include <X11/Xlib.h>

#define EXPORT __attribute__((visibility("default")))

EXPORT Status XIQueryVersion(Display *dpy, int *major, int *minor)
{
    (void)dpy, (void)major, (void)minor;
    return BadRequest;
}

EXPORT Status XISelectEvents(Display *dpy, Window w, void *masks, int n)
{
    (void)dpy, (void)w, (void)masks, (void)n;
    return BadRequest;
}

EXPORT void *XIQueryDevice(Display *dpy, int id, int *n)
{
    (void)dpy, (void)id;
    *n = 0;
    return NULL;
}

EXPORT void XIFreeDeviceInfo(void *info) { (void)info; }

EXPORT void *XListInputDevices(Display *dpy, int *n)
{
    (void)dpy;
    *n = 0;
    return NULL;
}

EXPORT void XFreeDeviceList(void *list) { (void)list; }
