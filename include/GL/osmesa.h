/*
 * GL/osmesa.h -- off-screen rendering interface of softgl.
 *
 * Source-compatible with the OSMesa API (interface version 11.2): a context
 * renders into a plain memory buffer supplied by the application, with no
 * window system involved.
 *
 * Typical use:
 *     OSMesaContext ctx = OSMesaCreateContextExt(OSMESA_RGBA, 24, 8, 0, NULL);
 *     OSMesaMakeCurrent(ctx, pixels, GL_UNSIGNED_BYTE, width, height);
 *     ... GL calls ...
 *     glFinish();
 *     OSMesaDestroyContext(ctx);
 */

#ifndef OSMESA_H
#define OSMESA_H

#include <GL/gl.h>

#ifdef __cplusplus
extern "C" {
#endif

/* Interface version */
#define OSMESA_MAJOR_VERSION            11
#define OSMESA_MINOR_VERSION            2
#define OSMESA_PATCH_VERSION            0

/* Color buffer formats (OSMesaCreateContext* format argument) */
#define OSMESA_COLOR_INDEX              GL_COLOR_INDEX
#define OSMESA_RGBA                     GL_RGBA
#define OSMESA_BGRA                     0x1
#define OSMESA_ARGB                     0x2
#define OSMESA_RGB                      GL_RGB
#define OSMESA_BGR                      0x4
#define OSMESA_RGB_565                  0x5

/* OSMesaPixelStore parameters */
#define OSMESA_ROW_LENGTH               0x10
#define OSMESA_Y_UP                     0x11

/* OSMesaGetIntegerv parameters */
#define OSMESA_WIDTH                    0x20
#define OSMESA_HEIGHT                   0x21
#define OSMESA_FORMAT                   0x22
#define OSMESA_TYPE                     0x23
#define OSMESA_MAX_WIDTH                0x24
#define OSMESA_MAX_HEIGHT               0x25

/* OSMesaCreateContextAttribs attribute names and values
 * (the list is pairs of name, value terminated by 0) */
#define OSMESA_DEPTH_BITS               0x30
#define OSMESA_STENCIL_BITS             0x31
#define OSMESA_ACCUM_BITS               0x32
#define OSMESA_PROFILE                  0x33
#define OSMESA_CORE_PROFILE             0x34
#define OSMESA_COMPAT_PROFILE           0x35
#define OSMESA_CONTEXT_MAJOR_VERSION    0x36
#define OSMESA_CONTEXT_MINOR_VERSION    0x37

/* Opaque context handle */
typedef struct osmesa_context *OSMesaContext;

/* Generic function pointer returned by OSMesaGetProcAddress */
typedef void (*OSMESAproc)();

/* ---- Context creation and destruction ---------------------------------- */
GLAPI OSMesaContext GLAPIENTRY OSMesaCreateContext (GLenum format, OSMesaContext sharelist);
GLAPI OSMesaContext GLAPIENTRY OSMesaCreateContextExt (GLenum format, GLint depthBits, GLint stencilBits, GLint accumBits, OSMesaContext sharelist);
GLAPI OSMesaContext GLAPIENTRY OSMesaCreateContextAttribs (const int *attribList, OSMesaContext sharelist);
GLAPI void GLAPIENTRY OSMesaDestroyContext (OSMesaContext ctx);

/* ---- Binding a context to a buffer ------------------------------------- */
GLAPI GLboolean GLAPIENTRY OSMesaMakeCurrent (OSMesaContext ctx, void *buffer, GLenum type, GLsizei width, GLsizei height);
GLAPI OSMesaContext GLAPIENTRY OSMesaGetCurrentContext (void);

/* ---- Buffer layout and queries ----------------------------------------- */
GLAPI void GLAPIENTRY OSMesaPixelStore (GLint pname, GLint value);
GLAPI void GLAPIENTRY OSMesaGetIntegerv (GLint pname, GLint *value);
GLAPI GLboolean GLAPIENTRY OSMesaGetDepthBuffer (OSMesaContext c, GLint *width, GLint *height, GLint *bytesPerValue, void **buffer);
GLAPI GLboolean GLAPIENTRY OSMesaGetColorBuffer (OSMesaContext c, GLint *width, GLint *height, GLint *format, void **buffer);

/* ---- Miscellaneous ----------------------------------------------------- */
GLAPI OSMESAproc GLAPIENTRY OSMesaGetProcAddress (const char *funcName);
GLAPI void GLAPIENTRY OSMesaColorClamp (GLboolean enable);
GLAPI void GLAPIENTRY OSMesaPostprocess (OSMesaContext osmesa, const char *filter, unsigned enable_value);

#ifdef __cplusplus
}
#endif

#endif /* OSMESA_H */
