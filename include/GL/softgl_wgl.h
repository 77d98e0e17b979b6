/*
 * GL/softgl_wgl.h -- softgl's wgl shim: the WGL functions of Windows'
 * opengl32.dll (and the pixel-format calls gdi32 forwards to it), for
 * programs written against wgl that run on Linux without a window system.
 *
 * On Linux a device context (HDC) is an offscreen surface softgl makes:
 *
 *     HDC dc = softglCreateDC(width, height);    -- instead of GetDC(hwnd)
 *     PIXELFORMATDESCRIPTOR pfd = {0};  pfd.dwFlags = PFD_DRAW_TO_WINDOW |
 *         PFD_SUPPORT_OPENGL | PFD_DOUBLEBUFFER;
 *     SetPixelFormat(dc, ChoosePixelFormat(dc, &pfd), &pfd);
 *     HGLRC rc = wglCreateContext(dc);
 *     wglMakeCurrent(dc, rc);
 *     ... draw ...;  SwapBuffers(dc);             -- shows the frame
 *     wglMakeCurrent(NULL, NULL);  wglDeleteContext(rc);
 *     softglDestroyDC(dc);                        -- instead of ReleaseDC
 *
 * Every pixel format has RGBA 8888, depth 24, stencil 8 and accumulation
 * 16 per channel, whatever the request asks (format 1 double-buffered,
 * format 2 single-buffered). A frame is shown at SwapBuffers (single-
 * buffered: also at glFlush/glFinish); softglGetDCImage returns it, and
 * with SOFTGL_DUMP=DIR in the environment each shown frame is written as
 * DIR/frame-NNNNN.png. softglSelectFont stands in for CreateFont +
 * SelectObject before wglUseFontBitmaps; the fonts are built in (see
 * docs/fonts.md).
 *
 * On Windows (_WIN32) the wgl declarations come from <windows.h>; this
 * header then declares only the softgl* functions.
 */

#ifndef SOFTGL_WGL_H
#define SOFTGL_WGL_H

#include <GL/gl.h>

#if defined(_WIN32)
#include <windows.h>
#else
#include <stdint.h>
#endif

#ifdef __cplusplus
extern "C" {
#endif

#if !defined(_WIN32)

/* ---- Windows types, as wingdi.h has them (DWORD is 32 bits) ---- */
typedef int BOOL;
typedef unsigned char BYTE;
typedef uint16_t WORD;
typedef uint32_t DWORD;
typedef unsigned int UINT;
typedef float FLOAT;
typedef struct softgl_HDC__ *HDC;
typedef struct softgl_HGLRC__ *HGLRC;
typedef void (*PROC)(void);
typedef const char *LPCSTR;

#ifndef TRUE
#define TRUE 1
#endif
#ifndef FALSE
#define FALSE 0
#endif

typedef struct tagPIXELFORMATDESCRIPTOR {
    WORD  nSize;
    WORD  nVersion;
    DWORD dwFlags;
    BYTE  iPixelType;
    BYTE  cColorBits;
    BYTE  cRedBits;
    BYTE  cRedShift;
    BYTE  cGreenBits;
    BYTE  cGreenShift;
    BYTE  cBlueBits;
    BYTE  cBlueShift;
    BYTE  cAlphaBits;
    BYTE  cAlphaShift;
    BYTE  cAccumBits;
    BYTE  cAccumRedBits;
    BYTE  cAccumGreenBits;
    BYTE  cAccumBlueBits;
    BYTE  cAccumAlphaBits;
    BYTE  cDepthBits;
    BYTE  cStencilBits;
    BYTE  cAuxBuffers;
    BYTE  iLayerType;
    BYTE  bReserved;
    DWORD dwLayerMask;
    DWORD dwVisibleMask;
    DWORD dwDamageMask;
} PIXELFORMATDESCRIPTOR, *PPIXELFORMATDESCRIPTOR, *LPPIXELFORMATDESCRIPTOR;

typedef struct _POINTFLOAT {
    FLOAT x;
    FLOAT y;
} POINTFLOAT;

typedef struct _GLYPHMETRICSFLOAT {
    FLOAT      gmfBlackBoxX;
    FLOAT      gmfBlackBoxY;
    POINTFLOAT gmfptGlyphOrigin;
    FLOAT      gmfCellIncX;
    FLOAT      gmfCellIncY;
} GLYPHMETRICSFLOAT, *LPGLYPHMETRICSFLOAT;

/* PIXELFORMATDESCRIPTOR dwFlags */
#define PFD_DOUBLEBUFFER            0x00000001
#define PFD_STEREO                  0x00000002
#define PFD_DRAW_TO_WINDOW          0x00000004
#define PFD_DRAW_TO_BITMAP          0x00000008
#define PFD_SUPPORT_GDI             0x00000010
#define PFD_SUPPORT_OPENGL          0x00000020
#define PFD_GENERIC_FORMAT          0x00000040
#define PFD_NEED_PALETTE            0x00000080
#define PFD_NEED_SYSTEM_PALETTE     0x00000100
#define PFD_SWAP_EXCHANGE           0x00000200
#define PFD_SWAP_COPY               0x00000400
#define PFD_SWAP_LAYER_BUFFERS      0x00000800
#define PFD_GENERIC_ACCELERATED     0x00001000
#define PFD_SUPPORT_DIRECTDRAW      0x00002000
#define PFD_DEPTH_DONTCARE          0x20000000
#define PFD_DOUBLEBUFFER_DONTCARE   0x40000000
#define PFD_STEREO_DONTCARE         0x80000000

/* iPixelType, iLayerType */
#define PFD_TYPE_RGBA               0
#define PFD_TYPE_COLORINDEX         1
#define PFD_MAIN_PLANE              0
#define PFD_OVERLAY_PLANE           1
#define PFD_UNDERLAY_PLANE          (-1)

/* wglUseFontOutlines formats */
#define WGL_FONT_LINES              0
#define WGL_FONT_POLYGONS           1

/* CreateFont weights and charsets, for softglSelectFont */
#define FW_DONTCARE                 0
#define FW_THIN                     100
#define FW_LIGHT                    300
#define FW_NORMAL                   400
#define FW_MEDIUM                   500
#define FW_SEMIBOLD                 600
#define FW_BOLD                     700
#define FW_HEAVY                    900
#define FW_BLACK                    900
#define ANSI_CHARSET                0
#define DEFAULT_CHARSET             1
#define RUSSIAN_CHARSET             204

/* ---- WGL ---- */
GLAPI HGLRC APIENTRY wglCreateContext(HDC hdc);
GLAPI BOOL APIENTRY wglDeleteContext(HGLRC hglrc);
GLAPI BOOL APIENTRY wglMakeCurrent(HDC hdc, HGLRC hglrc);
GLAPI HGLRC APIENTRY wglGetCurrentContext(void);
GLAPI HDC APIENTRY wglGetCurrentDC(void);
GLAPI BOOL APIENTRY wglShareLists(HGLRC hglrc1, HGLRC hglrc2);
GLAPI BOOL APIENTRY wglCopyContext(HGLRC hglrcSrc, HGLRC hglrcDst, UINT mask);
GLAPI PROC APIENTRY wglGetProcAddress(LPCSTR lpszProc);
GLAPI int APIENTRY wglChoosePixelFormat(HDC hdc, const PIXELFORMATDESCRIPTOR *ppfd);
GLAPI int APIENTRY wglDescribePixelFormat(HDC hdc, int iPixelFormat, UINT nBytes, LPPIXELFORMATDESCRIPTOR ppfd);
GLAPI BOOL APIENTRY wglSetPixelFormat(HDC hdc, int iPixelFormat, const PIXELFORMATDESCRIPTOR *ppfd);
GLAPI int APIENTRY wglGetPixelFormat(HDC hdc);
GLAPI BOOL APIENTRY wglSwapBuffers(HDC hdc);
GLAPI BOOL APIENTRY wglUseFontBitmapsA(HDC hdc, DWORD first, DWORD count, DWORD listBase);
GLAPI BOOL APIENTRY wglUseFontBitmapsW(HDC hdc, DWORD first, DWORD count, DWORD listBase);
GLAPI BOOL APIENTRY wglUseFontOutlinesA(HDC hdc, DWORD first, DWORD count, DWORD listBase, FLOAT deviation, FLOAT extrusion, int format, LPGLYPHMETRICSFLOAT lpgmf);
GLAPI BOOL APIENTRY wglUseFontOutlinesW(HDC hdc, DWORD first, DWORD count, DWORD listBase, FLOAT deviation, FLOAT extrusion, int format, LPGLYPHMETRICSFLOAT lpgmf);

#ifdef UNICODE
#define wglUseFontBitmaps wglUseFontBitmapsW
#define wglUseFontOutlines wglUseFontOutlinesW
#else
#define wglUseFontBitmaps wglUseFontBitmapsA
#define wglUseFontOutlines wglUseFontOutlinesA
#endif

/* gdi32's names for the pixel-format and swap calls (which gdi32 forwards
 * to opengl32's wgl* functions).  Define SOFTGL_NO_GDI_NAMES to do
 * without them. */
#ifndef SOFTGL_NO_GDI_NAMES
#define ChoosePixelFormat   wglChoosePixelFormat
#define DescribePixelFormat wglDescribePixelFormat
#define SetPixelFormat      wglSetPixelFormat
#define GetPixelFormat      wglGetPixelFormat
#define SwapBuffers         wglSwapBuffers
#endif

#endif /* !_WIN32 */

/* ---- softgl's device contexts (Linux: what GetDC/ReleaseDC give) ---- */

/* An offscreen device context of width x height pixels (1..16384 each):
 * black, no pixel format set yet, the System font (16 px, FW_BOLD,
 * DEFAULT_CHARSET) selected.  NULL for a bad size. */
GLAPI HDC APIENTRY softglCreateDC(int width, int height);

/* Frees the DC.  Contexts current on it keep rendering into their own
 * buffers, but their frames are shown nowhere (SOFTGL_DUMP still gets
 * them).  FALSE for a handle that is not a live DC. */
GLAPI BOOL APIENTRY softglDestroyDC(HDC hdc);

/* The window was resized: contexts follow at their next wglMakeCurrent or
 * SwapBuffers (the viewport is not changed: the program's resize handler
 * does that, as on Windows). */
GLAPI BOOL APIENTRY softglResizeDC(HDC hdc, int width, int height);

/* Selects a font into the DC, as CreateFont(height, 0, 0, 0, weight, ...,
 * charset, ...) + SelectObject would, for wglUseFontBitmaps.  height as
 * CreateFont's nHeight (0: default, 16); weight 0..1000 (bold from 600);
 * charset RUSSIAN_CHARSET reads bytes as code page 1251, ANSI_CHARSET and
 * DEFAULT_CHARSET as the ANSI code page (1251 unless SOFTGL_CODEPAGE=1252),
 * others as 1252.  See docs/fonts.md. */
GLAPI BOOL APIENTRY softglSelectFont(HDC hdc, int height, int weight, int charset);

/* The last frame shown on the DC: width x height RGBA8 pixels, rows
 * bottom-up (as glReadPixels returns them).  Valid until the next frame is
 * shown or the DC is destroyed.  NULL for a bad handle. */
GLAPI const unsigned char * APIENTRY softglGetDCImage(HDC hdc, int *width, int *height);

#ifdef __cplusplus
}
#endif

#endif /* SOFTGL_WGL_H */
