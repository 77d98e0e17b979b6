{ primitives.dpr -- the textbook's §5.1-5.5 fragments (seeds-inventory
  §3.5 F02-F05) in one window, pixel-aligned ortho 300x200:
  - F02: glBegin(GL_QUADS) with a colour per vertex, the book's fourth
    vertex (1,1,1) as printed (it coincides with the third seen along z,
    so a Gouraud triangle shows), scaled up to 80 px;
  - F03: glEnable(GL_POINTS) (invalid: GL_INVALID_ENUM, no effect), a
    smooth 3 px point at (100,100) -- antialiased points are not in softgl
    yet, so it is a 3x3 square;
  - F04: a yellow line stippled 0xAAAA, factor 1, from (40,120) to
    (240,120), with the book's invalid glEnable/glDisable(GL_LINES);
  - F05: culling on: the counter-clockwise red triangle is drawn, the
    clockwise green quad is culled. }
program primitives;

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

var
  Form1: TForm1;
  Errors: array[0..3] of GLenum;

constructor TForm1.Create(AOwner: TComponent);
begin
  inherited;
  ClientWidth := 300;
  ClientHeight := 200;
end;

procedure TForm1.Draw;
const
  Green: array[0..2] of GLfloat = (0, 1, 0);
begin
  glClearColor(0, 0, 0, 0);
  glClear(GL_COLOR_BUFFER_BIT);

  { F02 }
  glPushMatrix;
  glTranslatef(200, 100, 0);
  glScalef(80, 80, 1);
  glBegin(GL_QUADS);
    glColor3f(1, 0, 0); glVertex3f(0, 0, 0);
    glColor3f(1, 1, 1); glVertex3f(1, 0, 0);
    glColor3fv(@Green); glVertex3f(1, 1, 0);
    glColor3f(0, 0, 1); glVertex3f(1, 1, 1);
  glEnd;
  glPopMatrix;

  { F03 }
  glColor3f(1, 1, 1);
  glEnable(GL_POINTS);
  Errors[0] := glGetError;
  glEnable(GL_POINT_SMOOTH);
  glPointSize(3.0);
  glBegin(GL_POINTS);
    glVertex2i(100, 100);
  glEnd;
  glDisable(GL_POINT_SMOOTH);
  glPointSize(1.0);

  { F04 }
  glLineStipple(1, $AAAA);
  glEnable(GL_LINE_STIPPLE);
  glEnable(GL_LINES);
  Errors[1] := glGetError;
  glBegin(GL_LINES);
    glColor3f(1, 1, 0);
    glVertex2i(40, 120);
    glVertex2i(240, 120);
  glEnd;
  glDisable(GL_LINES);
  Errors[2] := glGetError;
  glDisable(GL_LINE_STIPPLE);

  { F05 }
  glEnable(GL_CULL_FACE);
  glColor3f(1, 0, 0);
  glBegin(GL_TRIANGLES);             { counter-clockwise: front }
    glVertex2i(100, 100 - 40);
    glVertex2i(50, 50 - 40);
    glVertex2i(150, 50 - 40);
  glEnd;
  glColor3f(0, 1, 0);
  glBegin(GL_QUADS);                 { clockwise: back, culled }
    glVertex2i(200, 100 - 40);
    glVertex2i(250, 100 - 40);
    glVertex2i(250, 50 - 40);
    glVertex2i(200, 50 - 40);
  glEnd;
  glDisable(GL_CULL_FACE);
  Errors[3] := glGetError;
end;

var
  x, r, g, b, onCount, adjacent, prevOn: Integer;
begin
  Application.Initialize;
  Application.CreateForm(TForm1, Form1);
  Application.Show;
  Application.Snapshot('primitives');
  Expect(Errors[0] = GL_INVALID_ENUM, 'glEnable(GL_POINTS) is GL_INVALID_ENUM');
  Expect(Errors[1] = GL_INVALID_ENUM, 'glEnable(GL_LINES) is GL_INVALID_ENUM');
  Expect(Errors[2] = GL_INVALID_ENUM, 'glDisable(GL_LINES) is GL_INVALID_ENUM');
  Expect(Errors[3] = GL_NO_ERROR, 'no error after the culling fragment');
  { F02: the red corner and the green corner of the triangle }
  ExpectPixel(202, 101, 255, 0, 0, 12, 'F02 near the red vertex');
  { the third and fourth vertices coincide on screen: which of their
    colours (green, blue) reaches that corner depends on how the quad is
    split into triangles, which GL leaves to the implementation }
  PixelAt(278, 175, r, g, b);
  Expect((r < 20) and ((g > 230) xor (b > 230)), Format('F02 corner (278,175) is (%d,%d,%d): green or blue', [r, g, b]));
  ExpectPixel(210, 170, 0, 0, 0, 0, 'F02 above the diagonal: empty');
  { F03: a 3x3 point centred on (100.5, 100.5) }
  ExpectPixel(100, 100, 255, 255, 255, 0, 'F03 point centre');
  ExpectPixel(99, 99, 255, 255, 255, 0, 'F03 point corner');
  ExpectPixel(102, 100, 0, 0, 0, 0, 'F03 point is 3 px wide');
  { F04: 0xAAAA from the first pixel: off, on, off, on ... }
  onCount := 0; adjacent := 0; prevOn := 0;
  for x := 40 to 239 do
  begin
    PixelAt(x, 119, r, g, b);
    if r = 0 then PixelAt(x, 120, r, g, b);
    if (r = 255) and (g = 255) and (b = 0) then
    begin
      Inc(onCount);
      if prevOn = 1 then Inc(adjacent);
      prevOn := 1;
      Expect(Odd(x - 40), Format('F04: pixel %d of the line is on, the pattern says off', [x - 40]));
    end
    else prevOn := 0;
  end;
  Expect(onCount = 100, Format('F04: %d stipple pixels on, expected 100', [onCount]));
  { F05 }
  ExpectPixel(100, 30, 255, 0, 0, 0, 'F05 red triangle drawn');
  ExpectPixel(225, 35, 0, 0, 0, 0, 'F05 green quad culled');
  Application.Terminate;
  Done('primitives');
end.
