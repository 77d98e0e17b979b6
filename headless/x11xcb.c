/* libX11-xcb.so.1 stand-in for softgl's headless Xlib (see x11.c): the
 * headless display has no XCB connection under it, so XGetXCBConnection
 * answers NULL (the real library would read Xlib's private Display fields
 * and hand out a pointer into nothing). Programs that check (waffle:
 * "XGetXCBConnection() failed") stop cleanly. */
#include <X11/Xlib.h>

#define EXPORT __attribute__((visibility("default")))

EXPORT void *XGetXCBConnection(Display *dpy)
{
    (void)dpy;
    return 0;
}

EXPORT void XSetEventQueueOwner(Display *dpy, int owner)
{
    (void)dpy, (void)owner;
}
