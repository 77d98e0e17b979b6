{ unproject.dpr -- the textbook's §10-12: modelview order (F22, F23),
  gluPerspective in a resize handler (F26) and gluUnProject of window
  points (F27).
  Left: glRotatef(45) then glTranslatef(2, 0, 0) puts a square at
  (sqrt 2, sqrt 2) (red); glTranslatef(2, 0, 0) then glRotatef(45) puts it
  at (2, 0) (green).  Right: a perspective view; three "mouse clicks" at
  window points are unprojected with gluUnProject at window z 0 and 1
  (the near and far points of the ray: the book's F27 passes 0 only --
  a window point alone does not fix a depth, S3 §12), and a marker is
  drawn on the ray at z = -5; the marker must land on the clicked pixel.
  The mouse's y runs down the window and GL's up: y is flipped
  (the book's F27 does not). }
program unproject;

{$mode delphi}

uses
  SysUtils, Windows, Forms, Checks, BookGL, gl, glu;

type
  TForm1 = class(TGLForm)
  protected
    procedure Draw; override;
  public
    constructor Create(AOwner: TComponent); override;
  end;

const
  Clicks: array[0..2, 0..1] of Integer = ((230, 40), (300, 100), (370, 170));

var
  Form1: TForm1;
  Hits: array[0..2, 0..2] of GLdouble;

constructor TForm1.Create(AOwner: TComponent);
begin
  inherited;
  ClientWidth := 400;
  ClientHeight := 200;
end;

procedure Square;
begin
  glBegin(GL_QUADS);
    glVertex2f(-1, 1); glVertex2f(1, 1); glVertex2f(1, -1); glVertex2f(-1, -1);
  glEnd;
end;

procedure TForm1.Draw;
var
  viewport: array[0..3] of GLint;
  mvmatrix, projmatrix: array[0..15] of GLdouble;
  i: Integer;
  wx, wy, nx, ny, nz, fx, fy, fz, t: GLdouble;
begin
  glClear(GL_COLOR_BUFFER_BIT or GL_DEPTH_BUFFER_BIT);
  { left half: ortho -4..4 x -4..4, 25 px per unit }
  glViewport(0, 0, 200, 200);
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity;
  glOrtho(-4, 4, -4, 4, -1, 1);
  glMatrixMode(GL_MODELVIEW);
  glLoadIdentity;                      { F22 }
  glRotatef(45, 0, 0, 1);
  glTranslatef(2, 0, 0);
  glColor3f(1, 0, 0);
  Square;
  glLoadIdentity;                      { F23 }
  glTranslatef(2, 0, 0);
  glRotatef(45, 0, 0, 1);
  glColor3f(0, 1, 0);
  Square;

  { right half: F26's reshape, with the aspect ratio in floating point }
  glViewport(200, 0, 200, 200);
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity;
  gluPerspective(45.0, 200 / 200, 0.1, 100.0);
  glMatrixMode(GL_MODELVIEW);
  glLoadIdentity;
  gluLookAt(0, 0, 0, 0, 0, -1, 0, 1, 0);
  { F27 }
  glGetIntegerv(GL_VIEWPORT, @viewport);
  glGetDoublev(GL_MODELVIEW_MATRIX, @mvmatrix);
  glGetDoublev(GL_PROJECTION_MATRIX, @projmatrix);
  glColor3f(1, 1, 0);
  glPointSize(5);
  glBegin(GL_POINTS);
  for i := 0 to 2 do
  begin
    wx := Clicks[i, 0] + 0.5;
    wy := (ClientHeight - 1 - Clicks[i, 1]) + 0.5;    { mouse y is down }
    gluUnProject(wx, wy, 0.0, @mvmatrix, @projmatrix, @viewport, @nx, @ny, @nz);
    gluUnProject(wx, wy, 1.0, @mvmatrix, @projmatrix, @viewport, @fx, @fy, @fz);
    t := (-5 - nz) / (fz - nz);
    Hits[i, 0] := nx + t * (fx - nx);
    Hits[i, 1] := ny + t * (fy - ny);
    Hits[i, 2] := -5;
    glVertex3dv(@Hits[i]);
  end;
  glEnd;
  glPointSize(1);
end;

var
  i: Integer;
  s2: Double;
begin
  Application.Initialize;
  Application.CreateForm(TForm1, Form1);
  Application.Show;
  Application.Snapshot('unproject');
  s2 := Sqrt(2);
  ExpectPixel(100 + Round(25 * s2), 100 + Round(25 * s2), 255, 0, 0, 0, 'F22: rotate then translate: centre (1.41, 1.41)');
  ExpectPixel(100 + 50, 100, 0, 255, 0, 0, 'F23: translate then rotate: centre (2, 0)');
  ExpectPixel(100 + 50, 100 + 33, 0, 255, 0, 0, 'F23: rotated square, top corner at y = 1.41');
  ExpectPixel(100 + 50 + 24, 100 + 24, 0, 0, 0, 0, 'F23: the corner of an unrotated square would be here');
  for i := 0 to 2 do
  begin
    WriteLn(Format('click (%d,%d) -> (%.4f, %.4f, %.4f)', [Clicks[i, 0], Clicks[i, 1], Hits[i, 0], Hits[i, 1], Hits[i, 2]]));
    ExpectPixel(Clicks[i, 0], 199 - Clicks[i, 1], 255, 255, 0, 0, Format('marker %d on the clicked pixel', [i]));
  end;
  { the middle click is the centre of the right viewport: straight ahead }
  Expect((Abs(Hits[1, 0]) < 0.03) and (Abs(Hits[1, 1]) < 0.03), 'centre click unprojects onto the axis');
  Expect(glGetError = GL_NO_ERROR, 'glGetError');
  Application.Terminate;
  Done('unproject');
end.
