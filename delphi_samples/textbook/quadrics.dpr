{ quadrics.dpr -- the textbook's §6 (GLU quadrics, seeds-inventory F12 and
  §2.18): gluNewQuadric ... gluDeleteQuadric around a sphere, a cylinder
  (a cone: top radius 0), a disk with a hole and a partial disk, in an
  orthographic view, lit, filled; the bottom row repeats them with
  GLU_LINE drawing.  The partial disk runs from 0 degrees (+y) through 90
  (+x), clockwise seen from +z (GLU 1.3 §6.7; the book says
  counter-clockwise, §6 #10): it fills the upper-right quarter. }
program quadrics;

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

constructor TForm1.Create(AOwner: TComponent);
begin
  inherited;
  ClientWidth := 400;
  ClientHeight := 200;
end;

procedure TForm1.InitGL;
const
  pos: array[0..3] of GLfloat = (1, 1, 1, 0);
begin
  glEnable(GL_DEPTH_TEST);
  glEnable(GL_LIGHT0);
  glLightfv(GL_LIGHT0, GL_POSITION, @pos);
  glEnable(GL_COLOR_MATERIAL);
end;

procedure TForm1.Reshape(w, h: Integer);
begin
  glViewport(0, 0, w, h);
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity;
  glOrtho(0, 8, 0, 4, -5, 5);
  glMatrixMode(GL_MODELVIEW);
  glLoadIdentity;
end;

procedure TForm1.Draw;
var
  quadric_obj: PGLUquadric;
  row: Integer;
begin
  glClear(GL_COLOR_BUFFER_BIT or GL_DEPTH_BUFFER_BIT);
  quadric_obj := gluNewQuadric();
  for row := 0 to 1 do
  begin
    if row = 0 then
    begin
      glEnable(GL_LIGHTING);
      gluQuadricDrawStyle(quadric_obj, GLU_FILL);
    end
    else
    begin
      glDisable(GL_LIGHTING);
      gluQuadricDrawStyle(quadric_obj, GLU_LINE);
    end;
    glPushMatrix;
      glTranslatef(1, 3 - 2 * row, 0);
      glColor3f(0.9, 0.9, 0.2);
      gluSphere(quadric_obj, 0.8, 20, 16);
      glTranslatef(2, 0, 0);
      glPushMatrix;
        glRotatef(-90, 1, 0, 0);
        glTranslatef(0, 0, -0.8);
        glColor3f(0.2, 0.9, 0.9);
        gluCylinder(quadric_obj, 0.8, 0.0, 1.6, 20, 4);
      glPopMatrix;
      glTranslatef(2, 0, 0);
      glColor3f(0.9, 0.3, 0.9);
      gluDisk(quadric_obj, 0.3, 0.8, 20, 3);
      glTranslatef(2, 0, 0);
      glColor3f(0.3, 0.9, 0.3);
      gluPartialDisk(quadric_obj, 0.0, 0.8, 20, 3, 0, 90);
    glPopMatrix;
  end;
  gluDeleteQuadric(quadric_obj);
end;

var
  r, g, b: Integer;
begin
  Application.Initialize;
  Application.CreateForm(TForm1, Form1);
  Application.Show;
  Application.Snapshot('quadrics');
  { 50 px per unit; top row centres at y = 150 }
  PixelAt(50, 150, r, g, b);
  Expect((r > 100) and (g > 100) and (b < r), Format('sphere centre lit yellow: (%d,%d,%d)', [r, g, b]));
  ExpectPixel(250, 150, 0, 0, 0, 0, 'disk hole (inner radius 0.3)');
  PixelAt(250 + 27, 150, r, g, b);
  Expect((r > 100) and (g < r) and (b > 100), Format('disk ring magenta: (%d,%d,%d)', [r, g, b]));
  PixelAt(350 + 15, 150 + 15, r, g, b);
  Expect((g > 100) and (r < g), Format('partial disk 0..90: the +x+y quarter is filled: (%d,%d,%d)', [r, g, b]));
  ExpectPixel(350 - 15, 150 + 15, 0, 0, 0, 0, 'partial disk: the -x+y quarter is empty');
  ExpectPixel(350 + 15, 150 - 15, 0, 0, 0, 0, 'partial disk: the +x-y quarter is empty');
  { the wire row: lines, so the sphere's middle has black between them }
  Expect(CountNonBlack(0, 0, 400, 100) < CountNonBlack(0, 100, 400, 200), 'wire row has fewer pixels');
  Expect(glGetError = GL_NO_ERROR, 'glGetError');
  Application.Terminate;
  Done('quadrics');
end.
