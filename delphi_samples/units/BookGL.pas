{ BookGL.pas -- the Russian textbook's program skeleton (S3 §2, "the
  structure of an OpenGL program for Windows", eight steps) as a Delphi
  form: FormCreate gets the window's DC, fills a PIXELFORMATDESCRIPTOR,
  ChoosePixelFormat + SetPixelFormat, wglCreateContext + wglMakeCurrent,
  then InitGL; FormResize sets the viewport and projection (Reshape);
  FormPaint clears, draws (Draw) and SwapBuffers; FormDestroy releases the
  context and the DC.  Each textbook program derives a form from TGLForm
  and fills in InitGL / Reshape / Draw with its chapter's fragment.  Uses
  Free Pascal's own gl and glu units. }
unit BookGL;

{$mode delphi}

interface

uses
  Windows, Forms, gl, glu;

type
  TGLForm = class(TForm)
    procedure FormCreate(Sender: TObject);
    procedure FormResize(Sender: TObject);
    procedure FormPaint(Sender: TObject);
    procedure FormDestroy(Sender: TObject);
  protected
    DC: HDC;
    hrc: HGLRC;
    procedure InitGL; virtual;
    procedure Reshape(w, h: Integer); virtual;
    procedure Draw; virtual; abstract;
  public
    constructor Create(AOwner: TComponent); override;
  end;

implementation

constructor TGLForm.Create(AOwner: TComponent);
begin
  inherited;
  ClientWidth := 300;
  ClientHeight := 300;
  OnCreate := FormCreate;
  OnResize := FormResize;
  OnPaint := FormPaint;
  OnDestroy := FormDestroy;
end;

procedure TGLForm.FormCreate(Sender: TObject);
var
  pfd: TPixelFormatDescriptor;
  nPixelFormat: Integer;
begin
  DC := GetDC(Handle);                                  { step 3 }
  FillChar(pfd, SizeOf(pfd), 0);                        { step 4 }
  pfd.nSize := SizeOf(pfd);
  pfd.nVersion := 1;
  pfd.dwFlags := PFD_DRAW_TO_WINDOW or PFD_SUPPORT_OPENGL or PFD_DOUBLEBUFFER;
  pfd.iPixelType := PFD_TYPE_RGBA;
  pfd.cColorBits := 24;
  pfd.cDepthBits := 32;
  pfd.iLayerType := PFD_MAIN_PLANE;
  nPixelFormat := ChoosePixelFormat(DC, @pfd);
  SetPixelFormat(DC, nPixelFormat, @pfd);               { step 5 }
  hrc := wglCreateContext(DC);                          { step 6 }
  wglMakeCurrent(DC, hrc);
  InitGL;
end;

procedure TGLForm.InitGL;
begin
end;

{ the default: a pixel-aligned orthographic view of the client area }
procedure TGLForm.Reshape(w, h: Integer);
begin
  glViewport(0, 0, w, h);
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity;
  gluOrtho2D(0, w, 0, h);
  glMatrixMode(GL_MODELVIEW);
  glLoadIdentity;
end;

procedure TGLForm.FormResize(Sender: TObject);
begin
  wglMakeCurrent(DC, hrc);
  Reshape(ClientWidth, ClientHeight);
  InvalidateRect(Handle, nil, False);
end;

procedure TGLForm.FormPaint(Sender: TObject);
begin
  wglMakeCurrent(DC, hrc);                              { step 7 }
  Draw;
  SwapBuffers(DC);
end;

procedure TGLForm.FormDestroy(Sender: TObject);
begin
  wglMakeCurrent(0, 0);                                 { step 8 }
  wglDeleteContext(hrc);
  ReleaseDC(Handle, DC);
end;

end.
