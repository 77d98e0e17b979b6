{ clipplanes.dpr -- the textbook's §5.8-5.9 (seeds-inventory F10, F11):
  two user clip planes, P10 = (1, 0, 0, 1) and P11 = (0, 1, 0, 0), keep
  x >= -1 and y >= 0 of a sphere of radius 1.6 drawn in wireframe and of a
  filled square behind it (the book says the first plane cuts x < 1; by
  the spec a plane keeps the points where p . (x, y, z, w) >= 0, so it
  cuts x < -1).  On the right, glScissor(0, 0, 0, 0) with the scissor test
  on: nothing is drawn. }
program clipplanes;

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
  P10: array[0..3] of GLdouble = (1, 0, 0, 1);
  P11: array[0..3] of GLdouble = (0, 1, 0, 0);

constructor TForm1.Create(AOwner: TComponent);
begin
  inherited;
  ClientWidth := 200;
  ClientHeight := 200;
end;

procedure TForm1.Reshape(w, h: Integer);
begin
  glViewport(0, 0, w, h);
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity;
  glOrtho(-2, 2, -2, 2, -2, 2);    { 50 px per unit }
  glMatrixMode(GL_MODELVIEW);
  glLoadIdentity;
end;

procedure TForm1.Draw;
var q: PGLUquadric;
begin
  glClear(GL_COLOR_BUFFER_BIT);
  glClipPlane(GL_CLIP_PLANE0, @P10);
  glClipPlane(GL_CLIP_PLANE1, @P11);
  glEnable(GL_CLIP_PLANE0);
  glEnable(GL_CLIP_PLANE1);
  glColor3f(0.2, 0.2, 0.6);
  glRectf(-1.8, -1.8, 1.8, 1.8);
  glColor3f(1, 1, 0);
  q := gluNewQuadric;
  gluQuadricDrawStyle(q, GLU_LINE);
  glPushMatrix;
  glTranslatef(0, 0, 0.1);
  glRotatef(90, 1, 0, 0);
  gluSphere(q, 1.6, 16, 12);
  glPopMatrix;
  gluDeleteQuadric(q);
  glDisable(GL_CLIP_PLANE0);
  glDisable(GL_CLIP_PLANE1);
  { F10 }
  glEnable(GL_SCISSOR_TEST);
  glScissor(0, 0, 0, 0);
  glColor3f(1, 1, 1);
  glRectf(-2, -2, 2, 2);
  glDisable(GL_SCISSOR_TEST);
end;

begin
  Application.Initialize;
  Application.CreateForm(TForm1, Form1);
  Application.Show;
  Application.Snapshot('clipplanes');
  { window x = 100 + 50 X, y = 100 + 50 Y }
  Expect(CountNonBlack(0, 0, 200, 99) = 0, 'y < 0 clipped away');
  Expect(CountNonBlack(0, 0, 49, 200) = 0, 'x < -1 clipped away');
  ExpectPixel(60, 160, 51, 51, 153, 0, 'x = -0.8, y = 1.2: kept');
  ExpectPixel(180, 101, 51, 51, 153, 0, 'x = 1.6, y = 0.02: kept');
  Expect(CountPixels(255, 255, 0, 0) > 200, 'the wire sphere in the kept quarter');
  Expect(CountPixels(255, 255, 255, 0) = 0, 'glScissor(0,0,0,0): nothing drawn');
  Expect(glGetError = GL_NO_ERROR, 'glGetError');
  Application.Terminate;
  Done('clipplanes');
end.
