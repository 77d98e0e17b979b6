{ lists.dpr -- the textbook's §8 display lists (seeds-inventory F15-F17):
  list 2 is a red square; list 1 a green triangle; list 2 is then
  redefined as a red triangle (the square is gone); list 3 calls lists 1
  and 2 (nested); glCallList(3) draws green then red, red on top where
  they overlap.  Then glDeleteLists(4, 3) on lists that do not exist (no
  error), glGenLists, glCallLists with glListBase over an array of
  GL_UNSIGNED_BYTE offsets, and a call of an undefined list (nothing). }
program lists;

{$mode delphi}

uses
  SysUtils, Windows, Forms, Checks, BookGL, gl, glu;

type
  TForm1 = class(TGLForm)
  protected
    procedure InitGL; override;
    procedure Reshape(w, h: Integer); override;
    procedure Draw; override;
  public
    constructor Create(AOwner: TComponent); override;
  end;

var
  Form1: TForm1;
  squares: GLuint;
  Err: GLenum;

constructor TForm1.Create(AOwner: TComponent);
begin
  inherited;
  ClientWidth := 300;
  ClientHeight := 200;
end;

procedure TForm1.InitGL;
var i: Integer;
begin
  glNewList(2, GL_COMPILE);            { F15 }
    glColor3f(1.0, 0.0, 0.0);
    glBegin(GL_POLYGON);
      glVertex2f(1.0, 1.0);
      glVertex2f(-1.0, 1.0);
      glVertex2f(-1.0, -1.0);
      glVertex2f(1.0, -1.0);
    glEnd;
  glEndList;
  glNewList(1, GL_COMPILE);            { F16 }
    glColor3f(0.0, 1.0, 0.0);
    glBegin(GL_TRIANGLES);
      glVertex2f(1.0, 2.0);
      glVertex2f(-1.0, 2.0);
      glVertex2f(-1.0, -2.0);
    glEnd;
  glEndList;
  glNewList(2, GL_COMPILE);
    glColor3f(1.0, 0.0, 0.0);
    glBegin(GL_TRIANGLES);
      glVertex2f(1.0, 1.0);
      glVertex2f(-1.0, -1.0);
      glVertex2f(1.0, -1.0);
    glEnd;
  glEndList;
  glNewList(3, GL_COMPILE);
    glCallList(1);
    glCallList(2);
  glEndList;
  glDeleteLists(4, 3);                 { F17: nothing there, no error }
  Err := glGetError;
  { three small squares, called through glListBase + glCallLists }
  squares := glGenLists(3);
  for i := 0 to 2 do
  begin
    glNewList(squares + GLuint(i), GL_COMPILE);
      glColor3f(0, 0, 1);
      glRectf(i * 1.0, -2.0, i * 1.0 + 0.6, -1.4);
    glEndList;
  end;
end;

procedure TForm1.Reshape(w, h: Integer);
begin
  glViewport(0, 0, w, h);
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity;
  glOrtho(-3, 3, -2, 2, -1, 1);    { 50 px per unit }
  glMatrixMode(GL_MODELVIEW);
  glLoadIdentity;
end;

procedure TForm1.Draw;
const
  offsets: array[0..2] of GLubyte = (0, 1, 2);
begin
  glClear(GL_COLOR_BUFFER_BIT);
  glCallList(3);
  glCallList(77);                      { never defined: does nothing }
  glListBase(squares);
  glTranslatef(0.5, 0, 0);
  glCallLists(3, GL_UNSIGNED_BYTE, @offsets);
  glLoadIdentity;
  glListBase(0);
end;

begin
  Application.Initialize;
  Application.CreateForm(TForm1, Form1);
  Application.Show;
  Application.Snapshot('lists');
  Expect(Err = GL_NO_ERROR, 'glDeleteLists of missing lists: no error');
  { window (x,y) = (150 + 50 X, 100 + 50 Y) }
  ExpectPixel(150 - 40, 100 + 80, 0, 255, 0, 0, 'green triangle, upper left');
  ExpectPixel(150 + 40, 100 - 40, 255, 0, 0, 0, 'red triangle, lower right');
  ExpectPixel(150 - 25, 100 - 38, 255, 0, 0, 0, 'overlap: red drawn last');
  ExpectPixel(150 + 30, 100 + 45, 0, 0, 0, 0, 'the first list 2 (a square) was replaced');
  ExpectPixel(150 + 25 + 15, 100 - 85, 0, 0, 255, 0, 'glCallLists square 0');
  ExpectPixel(150 + 25 + 100 + 15, 100 - 85, 0, 0, 255, 0, 'glCallLists square 2');
  Expect(glGetError = GL_NO_ERROR, 'glGetError');
  Application.Terminate;
  Done('lists');
end.
