{ stencil.dpr -- the textbook's §14.1 stencil example (seeds-inventory F37,
  F38): a square with a colour gradient, a green triangle over it with a
  triangular window cut out by the stencil buffer: clear stencil to 1;
  draw the window with glStencilFunc(GL_NEVER, 2, 0) and
  glStencilOp(GL_REPLACE, ...) (fails always, writes 2, no colour); then
  the green triangle where stencil <> 2.  The gradient shows through the
  window. }
program stencil;

{$mode delphi}

uses
  SysUtils, Windows, Forms, Checks, BookGL, gl, glu;

type
  TForm1 = class(TGLForm)
  protected
    procedure Reshape(w, h: Integer); override;
    procedure Draw; override;
  public
    constructor Create(AOwner: TComponent); override;
  end;

var
  Form1: TForm1;

constructor TForm1.Create(AOwner: TComponent);
begin
  inherited;
  ClientWidth := 240;
  ClientHeight := 240;
end;

procedure TForm1.Reshape(w, h: Integer);
begin
  glViewport(0, 0, w, h);
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity;
  glOrtho(-2.4, 2.4, -2.4, 2.4, -1, 1);   { 50 px per unit }
  glMatrixMode(GL_MODELVIEW);
  glLoadIdentity;
end;

procedure TForm1.Draw;
begin
  glClearStencil(1);
  glStencilMask($FF);
  glClear(GL_COLOR_BUFFER_BIT or GL_STENCIL_BUFFER_BIT);
  glBegin(GL_QUADS);
    glColor3f(1, 0, 0); glVertex3f(2, 2, -0.1);
    glColor3f(0, 1, 0); glVertex3f(-2, 2, -0.1);
    glColor3f(0, 0, 1); glVertex3f(-2, -2, -0.1);
    glColor3f(1, 0, 1); glVertex3f(2, -2, -0.1);
  glEnd;
  glEnable(GL_STENCIL_TEST);
  glStencilFunc(GL_NEVER, 2, 0);
  glStencilOp(GL_REPLACE, GL_KEEP, GL_KEEP);
  glBegin(GL_POLYGON);
    glVertex2f(0, 1);
    glVertex2f(1, -1);
    glVertex2f(-1, -1);
  glEnd;
  glStencilFunc(GL_NOTEQUAL, 2, 255);
  glColor3f(0, 1, 0);
  glBegin(GL_POLYGON);
    glVertex2f(0, 1.6);
    glVertex2f(-1.4, -1.4);
    glVertex2f(1.4, -1.4);
  glEnd;
  glDisable(GL_STENCIL_TEST);
end;

function PX(x: Double): Integer; begin Result := Round((x + 2.4) * 50); end;

var
  r, g, b: Integer;
begin
  Application.Initialize;
  Application.CreateForm(TForm1, Form1);
  Application.Show;
  Application.Snapshot('stencil');
  ExpectPixel(PX(0), PX(1.3), 0, 255, 0, 0, 'green triangle above the window');
  ExpectPixel(PX(-1.1), PX(-1.2), 0, 255, 0, 0, 'green triangle beside the window');
  PixelAt(PX(0), PX(-0.5), r, g, b);
  Expect((r > 20) and (b > 20) and (g < 230), Format('window: the gradient shows (%d,%d,%d)', [r, g, b]));
  PixelAt(PX(1.8), PX(1.8), r, g, b);
  Expect((r > 200) and (g < 60), Format('outside the triangle: the gradient, red corner (%d,%d,%d)', [r, g, b]));
  Expect(glGetError = GL_NO_ERROR, 'glGetError');
  Application.Terminate;
  Done('stencil');
end.
