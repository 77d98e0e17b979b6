{ arrays.dpr -- the textbook's §7 vertex arrays (seeds-inventory F13,
  F14): the same pentagon with a colour per vertex, left from two separate
  arrays (glVertexPointer + glColorPointer, stride 0), right from one
  interleaved array (x, y, r, g, b per vertex) with a stride of 5 floats, each drawn
  with glDrawArrays(GL_POLYGON, 0, 5).  The two halves must be identical
  pixel for pixel; a third copy below goes through glArrayElement. }
program arrays;

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
  V: array[0..4, 0..1] of GLfloat = ((0, 2), (2, 1), (1.5, -1), (-1.5, -1), (-2, 1));
  C: array[0..4, 0..2] of GLfloat = ((1, 0, 0), (0, 1, 0), (0, 0, 1), (0, 0.5, 0), (1, 0.5, 1));
  VC: array[0..24] of GLfloat;

constructor TForm1.Create(AOwner: TComponent);
begin
  inherited;
  ClientWidth := 400;
  ClientHeight := 200;
end;

procedure TForm1.Reshape(w, h: Integer);
begin
  glViewport(0, 0, w, h);
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity;
  glOrtho(-5, 5, -2.5, 2.5, -1, 1);   { 40 px per unit }
  glMatrixMode(GL_MODELVIEW);
  glLoadIdentity;
end;

procedure TForm1.Draw;
var i: Integer;
begin
  glClear(GL_COLOR_BUFFER_BIT);
  glPushMatrix;
  glTranslatef(-2.5, 0.25, 0);
  glVertexPointer(2, GL_FLOAT, 0, @V);
  glColorPointer(3, GL_FLOAT, 0, @C);
  glEnableClientState(GL_VERTEX_ARRAY);
  glEnableClientState(GL_COLOR_ARRAY);
  glDrawArrays(GL_POLYGON, 0, 5);
  glDisableClientState(GL_COLOR_ARRAY);
  glDisableClientState(GL_VERTEX_ARRAY);
  glPopMatrix;

  glPushMatrix;
  glTranslatef(2.5, 0.25, 0);
  glVertexPointer(2, GL_FLOAT, 5 * SizeOf(GLfloat), @VC[0]);
  glColorPointer(3, GL_FLOAT, 5 * SizeOf(GLfloat), @VC[2]);
  glEnableClientState(GL_VERTEX_ARRAY);
  glEnableClientState(GL_COLOR_ARRAY);
  glDrawArrays(GL_POLYGON, 0, 5);
  glPopMatrix;

  { a small copy through glArrayElement, the arrays still enabled }
  glPushMatrix;
  glTranslatef(0, -1.6, 0);
  glScalef(0.3, 0.3, 1);
  glBegin(GL_POLYGON);
    for i := 0 to 4 do glArrayElement(i);
  glEnd;
  glPopMatrix;
  glDisableClientState(GL_COLOR_ARRAY);
  glDisableClientState(GL_VERTEX_ARRAY);
end;

var
  i, x, y, r1, g1, b1, r2, g2, b2, diff, filled: Integer;
begin
  for i := 0 to 4 do
  begin
    VC[i * 5] := V[i, 0]; VC[i * 5 + 1] := V[i, 1];
    VC[i * 5 + 2] := C[i, 0]; VC[i * 5 + 3] := C[i, 1]; VC[i * 5 + 4] := C[i, 2];
  end;
  Application.Initialize;
  Application.CreateForm(TForm1, Form1);
  Application.Show;
  Application.Snapshot('arrays');
  diff := 0; filled := 0;
  for y := 70 to 199 do          { above the small copy }
    for x := 0 to 199 do
    begin
      PixelAt(x, y, r1, g1, b1);
      PixelAt(x + 200, y, r2, g2, b2);
      if (r1 <> r2) or (g1 <> g2) or (b1 <> b2) then Inc(diff);
      if (r1 or g1 or b1) <> 0 then Inc(filled);
    end;
  Expect(diff = 0, Format('separate and interleaved arrays differ in %d pixels', [diff]));
  Expect(filled > 8000, Format('%d pixels of pentagon', [filled]));
  { near the top vertex (0,2): red }
  ExpectPixel(100, 100 + 10 + 76, 255, 0, 0, 40, 'left pentagon, top vertex red');
  Expect(CountNonBlack(180, 0, 220, 60) > 100, 'the glArrayElement copy');
  Expect(glGetError = GL_NO_ERROR, 'glGetError');
  Application.Terminate;
  Done('arrays');
end.
