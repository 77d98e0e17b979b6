{ blending.dpr -- the textbook's §13.4 transparency (seeds-inventory F35,
  F36): an opaque red triangle at z = 1, a 50% green square at z = 2 and a
  50% blue rectangle at z = 0, blended with glBlendFunc(GL_SRC_ALPHA,
  GL_SRC_ALPHA) as the book has it (for alpha 0.5 the same as "over").
  The book sets no projection; at z = 2 the square would be clipped by the
  default [-1, 1] volume, so the view here is glOrtho(-2.4, 2.4, -2, 2,
  -3, 3).  Every overlap is checked against the blend equation.  On the
  right, F35's alpha test (GL_GREATER 0.4) over quads of alpha 0.3, 0.4,
  0.5: only the last passes. }
program blending;

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
  ClientWidth := 360;
  ClientHeight := 200;
end;

procedure TForm1.Reshape(w, h: Integer);
begin
  glViewport(0, 0, w, h);
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity;
  glOrtho(-2.4, 4.8, -2, 2, -3, 3);   { 50 px per unit }
  glMatrixMode(GL_MODELVIEW);
  glLoadIdentity;
end;

procedure TForm1.Draw;
var i: Integer;
begin
  glClear(GL_COLOR_BUFFER_BIT);
  glColor4f(1, 0, 0, 1);
  glBegin(GL_TRIANGLES);
    glVertex3f(0, 1.8, 1);
    glVertex3f(-1.4, -1.5, 1);
    glVertex3f(1.4, -1.5, 1);
  glEnd;
  glEnable(GL_BLEND);
  glBlendFunc(GL_SRC_ALPHA, GL_SRC_ALPHA);
  glColor4f(0, 1, 0, 0.5);
  glBegin(GL_QUADS);
    glVertex3f(-1, -1, 2); glVertex3f(1, -1, 2);
    glVertex3f(1, 1, 2); glVertex3f(-1, 1, 2);
  glEnd;
  glColor4f(0, 0, 1, 0.5);
  glBegin(GL_QUADS);
    glVertex3f(-2, -0.5, 0); glVertex3f(2, -0.5, 0);
    glVertex3f(2, 0.5, 0); glVertex3f(-2, 0.5, 0);
  glEnd;
  glDisable(GL_BLEND);

  glEnable(GL_ALPHA_TEST);
  glAlphaFunc(GL_GREATER, 0.4);
  for i := 0 to 2 do
  begin
    glColor4f(1, 1, 1, 0.3 + 0.1 * i);
    glRectf(2.6 + 0.7 * i, -1, 3.2 + 0.7 * i, 1);
  end;
  glDisable(GL_ALPHA_TEST);
end;

{ window pixel of world (x, y) }
function PX(x: Double): Integer; begin Result := Round((x + 2.4) * 50); end;
function PY(y: Double): Integer; begin Result := Round((y + 2) * 50); end;

begin
  Application.Initialize;
  Application.CreateForm(TForm1, Form1);
  Application.Show;
  Application.Snapshot('blending');
  { result = src * a + dst * a with a = 0.5 }
  ExpectPixel(PX(0), PY(1.5), 255, 0, 0, 1, 'red triangle alone');
  ExpectPixel(PX(-0.9), PY(0.8), 0, 128, 0, 1, 'square over black: (0, .5, 0)');
  ExpectPixel(PX(0), PY(0.8), 128, 128, 0, 1, 'square over red: (.5, .5, 0)');
  ExpectPixel(PX(-1.8), PY(0), 0, 0, 128, 1, 'rectangle over black: (0, 0, .5)');
  { (no spot has the rectangle over red alone: the square covers the
    triangle's whole width between y = -0.5 and 0.5) }
  ExpectPixel(PX(1.8), PY(0), 0, 0, 128, 1, 'rectangle over black, right');
  ExpectPixel(PX(-0.9), PY(0.3), 0, 64, 128, 1, 'rectangle over square on black: (0, .25, .5)');
  ExpectPixel(PX(0), PY(0), 64, 64, 128, 1, 'rectangle over square on red: (.25, .25, .5)');
  ExpectPixel(PX(2.9), PY(0), 0, 0, 0, 0, 'alpha 0.3 fails GREATER 0.4');
  ExpectPixel(PX(3.6), PY(0), 0, 0, 0, 0, 'alpha 0.4 fails GREATER 0.4');
  ExpectPixel(PX(4.3), PY(0), 255, 255, 255, 0, 'alpha 0.5 passes');
  Expect(glGetError = GL_NO_ERROR, 'glGetError');
  Application.Terminate;
  Done('blending');
end.
