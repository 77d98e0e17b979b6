/* wgl_window: softgl's opengl32.dll and glu32.dll in a real Windows
 * program (run under Wine by windows/run_test.sh).
 *
 * A window's own DC, its pixel format chosen and set through gdi32 as
 * programs do; wglCreateContext / wglMakeCurrent (softgl: GL_RENDERER
 * says so); gluPerspective and gluLookAt through glu32.dll's forwarders
 * (the projection matrix read back against the formula); a cleared,
 * depth-tested frame read back with glReadPixels; wglSwapBuffers draws it
 * into the window, read back with GDI's GetPixel; a second frame after
 * the window is resized fills the new client area.
 */
#include <windows.h>
#include <GL/gl.h>
#include <GL/glu.h>
#include <math.h>
#include <stdio.h>
#include <string.h>

static int failures;

static void expect(int ok, const char *what)
{
    printf("%s %s\n", ok ? "ok  " : "FAIL", what);
    if (!ok)
        failures++;
}

static LRESULT CALLBACK proc(HWND w, UINT m, WPARAM a, LPARAM b)
{
    return DefWindowProcA(w, m, a, b);
}

typedef BOOL(WINAPI *SwapFn)(HDC);

static void frame(int w, int h)
{
    glViewport(0, 0, w, h);
    glClearColor(0, 0, 1, 1);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    glOrtho(0, w, 0, h, -1, 1);
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
    glEnable(GL_DEPTH_TEST);
    glColor3f(1, 0, 0);
    glBegin(GL_QUADS); /* the middle half, in front */
    glVertex3f(w / 4.0f, h / 4.0f, 0.5f);
    glVertex3f(3 * w / 4.0f, h / 4.0f, 0.5f);
    glVertex3f(3 * w / 4.0f, 3 * h / 4.0f, 0.5f);
    glVertex3f(w / 4.0f, 3 * h / 4.0f, 0.5f);
    glEnd();
    glColor3f(0, 1, 0);
    glBegin(GL_QUADS); /* everywhere, behind: only outside the red square */
    glVertex3f(0, 0, -0.5f);
    glVertex3f(w, 0, -0.5f);
    glVertex3f(w, h / 8.0f, -0.5f);
    glVertex3f(0, h / 8.0f, -0.5f);
    glEnd();
    glDisable(GL_DEPTH_TEST);
}

int main(void)
{
    WNDCLASSA wc;
    HWND win;
    HDC dc;
    HGLRC rc;
    PIXELFORMATDESCRIPTOR pfd;
    RECT r = {0, 0, 96, 64};
    int fmt, w, h;
    const char *renderer;
    unsigned char px[4];
    GLdouble p[16];
    SwapFn swap;
    COLORREF c;

    memset(&wc, 0, sizeof wc);
    wc.style = CS_OWNDC;
    wc.lpfnWndProc = proc;
    wc.hInstance = GetModuleHandleA(NULL);
    wc.lpszClassName = "softgl_test";
    RegisterClassA(&wc);
    AdjustWindowRect(&r, WS_OVERLAPPEDWINDOW, FALSE);
    win = CreateWindowA("softgl_test", "softgl", WS_OVERLAPPEDWINDOW, 0, 0, r.right - r.left, r.bottom - r.top, NULL, NULL, wc.hInstance, NULL);
    expect(win != NULL, "CreateWindow");
    ShowWindow(win, SW_SHOW);
    UpdateWindow(win);
    dc = GetDC(win);

    memset(&pfd, 0, sizeof pfd);
    pfd.nSize = sizeof pfd;
    pfd.nVersion = 1;
    pfd.dwFlags = PFD_DRAW_TO_WINDOW | PFD_SUPPORT_OPENGL | PFD_DOUBLEBUFFER;
    pfd.iPixelType = PFD_TYPE_RGBA;
    pfd.cColorBits = 24;
    pfd.cDepthBits = 16;
    fmt = ChoosePixelFormat(dc, &pfd);
    expect(fmt > 0 && SetPixelFormat(dc, fmt, &pfd), "ChoosePixelFormat + SetPixelFormat (gdi32)");

    rc = wglCreateContext(dc);
    expect(rc != NULL, "wglCreateContext on the window's DC");
    expect(wglMakeCurrent(dc, rc), "wglMakeCurrent");
    renderer = (const char *)glGetString(GL_RENDERER);
    printf("GL_RENDERER %s, GL_VERSION %s\n", renderer ? renderer : "(null)", (const char *)glGetString(GL_VERSION));
    expect(renderer && strstr(renderer, "softgl") != NULL, "GL_RENDERER is softgl's");

    /* glu32.dll forwards to softgl: gluPerspective(90, 2, 1, 3). */
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    gluPerspective(90.0, 2.0, 1.0, 3.0);
    glGetDoublev(GL_PROJECTION_MATRIX, p);
    expect(fabs(p[0] - 0.5) < 1e-6 && fabs(p[5] - 1.0) < 1e-6 && fabs(p[10] + 2.0) < 1e-6 && fabs(p[11] + 1.0) < 1e-6 &&
               fabs(p[14] + 3.0) < 1e-6,
           "gluPerspective through glu32.dll");
    expect(strcmp((const char *)gluErrorString(GL_INVALID_ENUM), "invalid enumerant") == 0, "gluErrorString through glu32.dll");

    GetClientRect(win, &r);
    w = r.right;
    h = r.bottom;
    frame(w, h);
    glReadPixels(w / 2, h / 2, 1, 1, GL_RGBA, GL_UNSIGNED_BYTE, px);
    expect(px[0] == 255 && px[1] == 0 && px[2] == 0, "glReadPixels: red in the middle");
    glReadPixels(2, 2, 1, 1, GL_RGBA, GL_UNSIGNED_BYTE, px);
    expect(px[0] == 0 && px[1] == 255 && px[2] == 0, "glReadPixels: green strip at the bottom");
    glReadPixels(2, h - 3, 1, 1, GL_RGBA, GL_UNSIGNED_BYTE, px);
    expect(px[0] == 0 && px[1] == 0 && px[2] == 255, "glReadPixels: blue at the top");
    expect(glGetError() == GL_NO_ERROR, "no GL error");

    swap = (SwapFn)GetProcAddress(GetModuleHandleA("opengl32.dll"), "wglSwapBuffers");
    expect(swap != NULL && swap(dc), "wglSwapBuffers");
    /* GDI's rows are top-down. */
    c = GetPixel(dc, w / 2, h / 2);
    printf("window pixels: middle %06lx, top-left %06lx, bottom-left %06lx\n", (unsigned long)c, (unsigned long)GetPixel(dc, 2, 2),
           (unsigned long)GetPixel(dc, 2, h - 3));
    expect(c == RGB(255, 0, 0), "the window shows red in the middle (GetPixel)");
    expect(GetPixel(dc, 2, 2) == RGB(0, 0, 255), "the window shows blue at the top");
    expect(GetPixel(dc, 2, h - 3) == RGB(0, 255, 0), "the window shows green at the bottom");

    /* Resized: the next frame fills the new client area. */
    SetWindowPos(win, NULL, 0, 0, r.right - r.left + 64, r.bottom - r.top + 32, SWP_NOMOVE | SWP_NOZORDER);
    GetClientRect(win, &r);
    expect(r.right > w && wglMakeCurrent(dc, rc), "resized, made current again");
    w = r.right;
    h = r.bottom;
    frame(w, h);
    swap(dc);
    expect(GetPixel(dc, w / 2, h / 2) == RGB(255, 0, 0) && GetPixel(dc, w - 3, 2) == RGB(0, 0, 255), "the resized window shows the new frame");

    wglMakeCurrent(NULL, NULL);
    expect(wglDeleteContext(rc), "wglDeleteContext");
    ReleaseDC(win, dc);
    DestroyWindow(win);
    printf(failures ? "WGL WINDOW FAILED (%d)\n" : "WGL WINDOW OK\n", failures);
    return failures != 0;
}
