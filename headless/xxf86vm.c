/* libXxf86vm.so.1 stand-in for softgl's headless Xlib (see x11.c): no
 * XFree86-VidModeExtension. freeglut uses it only for game mode and
 * copes with its absence. Prototypes are written out with opaque pointers
 * (xf86vmode.h is not always installed); every call answers False. */
#include <X11/Xlib.h>

#define EXPORT __attribute__((visibility("default")))

EXPORT Bool XF86VidModeQueryExtension(Display *dpy, int *event, int *error)
{
    (void)dpy;
    *event = *error = 0;
    return False;
}

EXPORT Bool XF86VidModeQueryVersion(Display *dpy, int *major, int *minor)
{
    (void)dpy;
    *major = *minor = 0;
    return False;
}

EXPORT Bool XF86VidModeGetModeLine(Display *dpy, int screen, int *dotclock, void *line)
{
    (void)dpy, (void)screen, (void)line;
    *dotclock = 0;
    return False;
}

EXPORT Bool XF86VidModeGetAllModeLines(Display *dpy, int screen, int *n, void ***modes)
{
    (void)dpy, (void)screen;
    *n = 0;
    *modes = 0;
    return False;
}

EXPORT Bool XF86VidModeSwitchToMode(Display *dpy, int screen, void *mode)
{
    (void)dpy, (void)screen, (void)mode;
    return False;
}

EXPORT Bool XF86VidModeSetViewPort(Display *dpy, int screen, int x, int y)
{
    (void)dpy, (void)screen, (void)x, (void)y;
    return False;
}

EXPORT Bool XF86VidModeGetViewPort(Display *dpy, int screen, int *x, int *y)
{
    (void)dpy, (void)screen;
    *x = *y = 0;
    return False;
}

EXPORT Bool XF86VidModeLockModeSwitch(Display *dpy, int screen, int lock)
{
    (void)dpy, (void)screen, (void)lock;
    return False;
}
