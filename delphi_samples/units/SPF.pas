{ SPF.pas -- the helper unit the Persian book's chapter 21 programs use
  (`uses ..., OpenGL, SPF`) and do not print: SetDCPixelFormat, the global
  rendering context hrc, and CleanUp.  Written here from what the programs
  ask of it (seeds-inventory §4): a double-buffered RGBA format with the
  requested colour and depth bits, a context made current on the DC.
  softgl gives every format depth 24 and stencil 8 whatever the request, so
  the reflected dinosaur gets the stencil buffer it needs. }
unit SPF;

{$mode delphi}

interface

uses Windows;

var
  hrc: HGLRC;

procedure SetDCPixelFormat(dc: HDC; colorBits, depthBits: Byte);
procedure CleanUp(dc: HDC);

implementation

procedure SetDCPixelFormat(dc: HDC; colorBits, depthBits: Byte);
var
  pfd: TPixelFormatDescriptor;
  nPixelFormat: Integer;
begin
  FillChar(pfd, SizeOf(pfd), 0);
  pfd.nSize := SizeOf(pfd);
  pfd.nVersion := 1;
  pfd.dwFlags := PFD_DRAW_TO_WINDOW or PFD_SUPPORT_OPENGL or PFD_DOUBLEBUFFER;
  pfd.iPixelType := PFD_TYPE_RGBA;
  pfd.cColorBits := colorBits;
  pfd.cDepthBits := depthBits;
  pfd.iLayerType := PFD_MAIN_PLANE;
  nPixelFormat := ChoosePixelFormat(dc, @pfd);
  SetPixelFormat(dc, nPixelFormat, @pfd);
  hrc := wglCreateContext(dc);
  wglMakeCurrent(dc, hrc);
end;

procedure CleanUp(dc: HDC);
begin
  wglMakeCurrent(0, 0);
  wglDeleteContext(hrc);
  hrc := 0;
  ReleaseDC(0, dc);
end;

end.
