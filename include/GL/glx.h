/*
 * GL/glx.h -- GLX 1.4 client interface of softgl.
 *
 * softgl implements GLX itself, over Xlib (loaded at run time): contexts
 * render in software and the image is put into the X drawable with
 * XPutImage. No GLX extension is needed on the X server.
 */

#ifndef GLX_H
#define GLX_H

#include <X11/Xlib.h>
#include <X11/Xutil.h>
#include <stdint.h>
#include <GL/gl.h>

#ifdef __cplusplus
extern "C" {
#endif

#define GLX_VERSION_1_1                 1
#define GLX_VERSION_1_2                 1
#define GLX_VERSION_1_3                 1
#define GLX_VERSION_1_4                 1

#define GLX_EXTENSION_NAME              "GLX"

/* glXGetConfig / glXChooseVisual attributes */
#define GLX_USE_GL                      1
#define GLX_BUFFER_SIZE                 2
#define GLX_LEVEL                       3
#define GLX_RGBA                        4
#define GLX_DOUBLEBUFFER                5
#define GLX_STEREO                      6
#define GLX_AUX_BUFFERS                 7
#define GLX_RED_SIZE                    8
#define GLX_GREEN_SIZE                  9
#define GLX_BLUE_SIZE                   10
#define GLX_ALPHA_SIZE                  11
#define GLX_DEPTH_SIZE                  12
#define GLX_STENCIL_SIZE                13
#define GLX_ACCUM_RED_SIZE              14
#define GLX_ACCUM_GREEN_SIZE            15
#define GLX_ACCUM_BLUE_SIZE             16
#define GLX_ACCUM_ALPHA_SIZE            17

/* Error codes returned by glXGetConfig and friends */
#define GLX_BAD_SCREEN                  1
#define GLX_BAD_ATTRIBUTE               2
#define GLX_NO_EXTENSION                3
#define GLX_BAD_VISUAL                  4
#define GLX_BAD_CONTEXT                 5
#define GLX_BAD_VALUE                   6
#define GLX_BAD_ENUM                    7

/* glXGetClientString / glXQueryServerString names */
#define GLX_VENDOR                      1
#define GLX_VERSION                     2
#define GLX_EXTENSIONS                  3

/* GLX 1.3 */
#define GLX_CONFIG_CAVEAT               0x20
#define GLX_DONT_CARE                   0xFFFFFFFF
#define GLX_X_VISUAL_TYPE               0x22
#define GLX_TRANSPARENT_TYPE            0x23
#define GLX_TRANSPARENT_INDEX_VALUE     0x24
#define GLX_TRANSPARENT_RED_VALUE       0x25
#define GLX_TRANSPARENT_GREEN_VALUE     0x26
#define GLX_TRANSPARENT_BLUE_VALUE      0x27
#define GLX_TRANSPARENT_ALPHA_VALUE     0x28
#define GLX_WINDOW_BIT                  0x00000001
#define GLX_PIXMAP_BIT                  0x00000002
#define GLX_PBUFFER_BIT                 0x00000004
#define GLX_AUX_BUFFERS_BIT             0x00000010
#define GLX_FRONT_LEFT_BUFFER_BIT       0x00000001
#define GLX_FRONT_RIGHT_BUFFER_BIT      0x00000002
#define GLX_BACK_LEFT_BUFFER_BIT        0x00000004
#define GLX_BACK_RIGHT_BUFFER_BIT       0x00000008
#define GLX_DEPTH_BUFFER_BIT            0x00000020
#define GLX_STENCIL_BUFFER_BIT          0x00000040
#define GLX_ACCUM_BUFFER_BIT            0x00000080
#define GLX_NONE                        0x8000
#define GLX_SLOW_CONFIG                 0x8001
#define GLX_TRUE_COLOR                  0x8002
#define GLX_DIRECT_COLOR                0x8003
#define GLX_PSEUDO_COLOR                0x8004
#define GLX_STATIC_COLOR                0x8005
#define GLX_GRAY_SCALE                  0x8006
#define GLX_STATIC_GRAY                 0x8007
#define GLX_TRANSPARENT_RGB             0x8008
#define GLX_TRANSPARENT_INDEX           0x8009
#define GLX_VISUAL_ID                   0x800B
#define GLX_SCREEN                      0x800C
#define GLX_NON_CONFORMANT_CONFIG       0x800D
#define GLX_DRAWABLE_TYPE               0x8010
#define GLX_RENDER_TYPE                 0x8011
#define GLX_X_RENDERABLE                0x8012
#define GLX_FBCONFIG_ID                 0x8013
#define GLX_RGBA_TYPE                   0x8014
#define GLX_COLOR_INDEX_TYPE            0x8015
#define GLX_MAX_PBUFFER_WIDTH           0x8016
#define GLX_MAX_PBUFFER_HEIGHT          0x8017
#define GLX_MAX_PBUFFER_PIXELS          0x8018
#define GLX_PRESERVED_CONTENTS          0x801B
#define GLX_LARGEST_PBUFFER             0x801C
#define GLX_WIDTH                       0x801D
#define GLX_HEIGHT                      0x801E
#define GLX_EVENT_MASK                  0x801F
#define GLX_DAMAGED                     0x8020
#define GLX_SAVED                       0x8021
#define GLX_WINDOW                      0x8022
#define GLX_PBUFFER                     0x8023
#define GLX_PBUFFER_HEIGHT              0x8040
#define GLX_PBUFFER_WIDTH               0x8041
#define GLX_RGBA_BIT                    0x00000001
#define GLX_COLOR_INDEX_BIT             0x00000002
#define GLX_PBUFFER_CLOBBER_MASK        0x08000000

/* GLX 1.4 */
#define GLX_SAMPLE_BUFFERS              100000
#define GLX_SAMPLES                     100001

/* GLX events (glXSelectEvent) */
#define GLX_PbufferClobber              0
#define GLX_BufferSwapComplete          1

typedef struct __GLXcontextRec *GLXContext;
typedef struct __GLXFBConfigRec *GLXFBConfig;
typedef XID GLXPixmap;
typedef XID GLXDrawable;
typedef XID GLXFBConfigID;
typedef XID GLXContextID;
typedef XID GLXWindow;
typedef XID GLXPbuffer;

typedef void (*__GLXextFuncPtr)(void);

typedef struct {
    int event_type;             /* GLX_DAMAGED or GLX_SAVED */
    int draw_type;              /* GLX_WINDOW or GLX_PBUFFER */
    unsigned long serial;
    Bool send_event;
    Display *display;
    GLXDrawable drawable;
    unsigned int buffer_mask;
    unsigned int aux_buffer;
    int x, y;
    int width, height;
    int count;
} GLXPbufferClobberEvent;

typedef struct {
    int type;
    unsigned long serial;
    Bool send_event;
    Display *display;
    int extension;
    int evtype;
    GLXDrawable drawable;
    int64_t ust;
    int64_t msc;
    int64_t sbc;
} GLXBufferSwapComplete;

typedef union __GLXEvent {
    GLXPbufferClobberEvent glxpbufferclobber;
    GLXBufferSwapComplete glxbufferswapcomplete;
    long pad[24];
} GLXEvent;

/* GLX 1.0 - 1.2 */
GLAPI Bool GLAPIENTRY glXQueryExtension (Display *dpy, int *errorBase, int *eventBase);
GLAPI Bool GLAPIENTRY glXQueryVersion (Display *dpy, int *major, int *minor);
GLAPI const char * GLAPIENTRY glXQueryExtensionsString (Display *dpy, int screen);
GLAPI const char * GLAPIENTRY glXQueryServerString (Display *dpy, int screen, int name);
GLAPI const char * GLAPIENTRY glXGetClientString (Display *dpy, int name);
GLAPI XVisualInfo * GLAPIENTRY glXChooseVisual (Display *dpy, int screen, int *attribList);
GLAPI int GLAPIENTRY glXGetConfig (Display *dpy, XVisualInfo *vis, int attrib, int *value);
GLAPI GLXContext GLAPIENTRY glXCreateContext (Display *dpy, XVisualInfo *vis, GLXContext shareList, Bool direct);
GLAPI void GLAPIENTRY glXDestroyContext (Display *dpy, GLXContext ctx);
GLAPI Bool GLAPIENTRY glXMakeCurrent (Display *dpy, GLXDrawable drawable, GLXContext ctx);
GLAPI void GLAPIENTRY glXCopyContext (Display *dpy, GLXContext src, GLXContext dst, unsigned long mask);
GLAPI void GLAPIENTRY glXSwapBuffers (Display *dpy, GLXDrawable drawable);
GLAPI GLXPixmap GLAPIENTRY glXCreateGLXPixmap (Display *dpy, XVisualInfo *visual, Pixmap pixmap);
GLAPI void GLAPIENTRY glXDestroyGLXPixmap (Display *dpy, GLXPixmap pixmap);
GLAPI Bool GLAPIENTRY glXIsDirect (Display *dpy, GLXContext ctx);
GLAPI GLXContext GLAPIENTRY glXGetCurrentContext (void);
GLAPI GLXDrawable GLAPIENTRY glXGetCurrentDrawable (void);
GLAPI void GLAPIENTRY glXWaitGL (void);
GLAPI void GLAPIENTRY glXWaitX (void);
GLAPI void GLAPIENTRY glXUseXFont (Font font, int first, int count, int list);
GLAPI Display * GLAPIENTRY glXGetCurrentDisplay (void);

/* GLX 1.3 */
GLAPI GLXFBConfig * GLAPIENTRY glXChooseFBConfig (Display *dpy, int screen, const int *attribList, int *nitems);
GLAPI int GLAPIENTRY glXGetFBConfigAttrib (Display *dpy, GLXFBConfig config, int attribute, int *value);
GLAPI GLXFBConfig * GLAPIENTRY glXGetFBConfigs (Display *dpy, int screen, int *nelements);
GLAPI XVisualInfo * GLAPIENTRY glXGetVisualFromFBConfig (Display *dpy, GLXFBConfig config);
GLAPI GLXWindow GLAPIENTRY glXCreateWindow (Display *dpy, GLXFBConfig config, Window win, const int *attribList);
GLAPI void GLAPIENTRY glXDestroyWindow (Display *dpy, GLXWindow win);
GLAPI GLXPixmap GLAPIENTRY glXCreatePixmap (Display *dpy, GLXFBConfig config, Pixmap pixmap, const int *attribList);
GLAPI void GLAPIENTRY glXDestroyPixmap (Display *dpy, GLXPixmap pixmap);
GLAPI GLXPbuffer GLAPIENTRY glXCreatePbuffer (Display *dpy, GLXFBConfig config, const int *attribList);
GLAPI void GLAPIENTRY glXDestroyPbuffer (Display *dpy, GLXPbuffer pbuf);
GLAPI void GLAPIENTRY glXQueryDrawable (Display *dpy, GLXDrawable draw, int attribute, unsigned int *value);
GLAPI GLXContext GLAPIENTRY glXCreateNewContext (Display *dpy, GLXFBConfig config, int renderType, GLXContext shareList, Bool direct);
GLAPI Bool GLAPIENTRY glXMakeContextCurrent (Display *dpy, GLXDrawable draw, GLXDrawable read, GLXContext ctx);
GLAPI GLXDrawable GLAPIENTRY glXGetCurrentReadDrawable (void);
GLAPI int GLAPIENTRY glXQueryContext (Display *dpy, GLXContext ctx, int attribute, int *value);
GLAPI void GLAPIENTRY glXSelectEvent (Display *dpy, GLXDrawable draw, unsigned long event_mask);
GLAPI void GLAPIENTRY glXGetSelectedEvent (Display *dpy, GLXDrawable draw, unsigned long *event_mask);

/* GLX 1.4 and GLX_ARB_get_proc_address */
GLAPI __GLXextFuncPtr GLAPIENTRY glXGetProcAddressARB (const GLubyte *procName);
GLAPI __GLXextFuncPtr GLAPIENTRY glXGetProcAddress (const GLubyte *procName);

/* GLX_ARB_create_context, GLX_ARB_create_context_profile */
#define GLX_CONTEXT_DEBUG_BIT_ARB                 0x00000001
#define GLX_CONTEXT_FORWARD_COMPATIBLE_BIT_ARB    0x00000002
#define GLX_CONTEXT_MAJOR_VERSION_ARB             0x2091
#define GLX_CONTEXT_MINOR_VERSION_ARB             0x2092
#define GLX_CONTEXT_FLAGS_ARB                     0x2094
#define GLX_CONTEXT_CORE_PROFILE_BIT_ARB          0x00000001
#define GLX_CONTEXT_COMPATIBILITY_PROFILE_BIT_ARB 0x00000002
#define GLX_CONTEXT_PROFILE_MASK_ARB              0x9126
typedef GLXContext (*PFNGLXCREATECONTEXTATTRIBSARBPROC) (Display *dpy, GLXFBConfig config, GLXContext share_context, Bool direct, const int *attrib_list);
GLAPI GLXContext GLAPIENTRY glXCreateContextAttribsARB (Display *dpy, GLXFBConfig config, GLXContext share_context, Bool direct, const int *attrib_list);

/* GLX_EXT_swap_control, GLX_MESA_swap_control, GLX_SGI_swap_control */
#define GLX_SWAP_INTERVAL_EXT                     0x20F1
#define GLX_MAX_SWAP_INTERVAL_EXT                 0x20F2
GLAPI void GLAPIENTRY glXSwapIntervalEXT (Display *dpy, GLXDrawable drawable, int interval);
GLAPI int GLAPIENTRY glXSwapIntervalMESA (unsigned int interval);
GLAPI int GLAPIENTRY glXGetSwapIntervalMESA (void);
GLAPI int GLAPIENTRY glXSwapIntervalSGI (int interval);

/* GLX_MESA_copy_sub_buffer */
GLAPI void GLAPIENTRY glXCopySubBufferMESA (Display *dpy, GLXDrawable drawable, int x, int y, int width, int height);

#ifdef __cplusplus
}
#endif

#endif /* GLX_H */
