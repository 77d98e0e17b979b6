{ accum.dpr -- the textbook's §14.3 accumulation buffer: "blur,
  anti-aliasing and soft shadows by drawing the scene several times with a
  slightly moved camera".  A white triangle is drawn 8 times, the
  projection jittered by sub-pixel offsets, each frame added with
  glAccum(GL_ACCUM, 1/8) after glAccum(GL_LOAD) of the first, then
  glAccum(GL_RETURN, 1): the interior stays white, the edges get
  in-between greys (anti-aliasing).  On the right a motion blur: a red
  square drawn at 4 positions, each with weight 1/4. }
program accum;

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

const
  { sub-pixel offsets, in pixels }
  Jitter: array[0..7, 0..1] of GLfloat = ((0.5625, 0.4375), (0.0625, 0.9375),
    (0.3125, 0.6875), (0.6875, 0.8125), (0.8125, 0.1875), (0.9375, 0.5625),
    (0.4375, 0.0625), (0.1875, 0.3125));

var
  Form1: TForm1;

constructor TForm1.Create(AOwner: TComponent);
begin
  inherited;
  ClientWidth := 300;
  ClientHeight := 150;
end;

procedure TForm1.InitGL;
begin
  glClearAccum(0, 0, 0, 0);
end;

procedure TForm1.Reshape(w, h: Integer);
begin
  glViewport(0, 0, w, h);
end;

procedure Scene(dx, dy: GLfloat);
begin
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity;
  glTranslatef(dx * 2 / 300, dy * 2 / 150, 0);   { a pixel is 2/w in NDC }
  gluOrtho2D(0, 300, 0, 150);
  glMatrixMode(GL_MODELVIEW);
  glLoadIdentity;
  glClear(GL_COLOR_BUFFER_BIT);
  glColor3f(1, 1, 1);
  glBegin(GL_TRIANGLES);
    glVertex2f(20, 20);
    glVertex2f(130, 40);
    glVertex2f(60, 130);
  glEnd;
end;

procedure Square(x: GLfloat);
begin
  glClear(GL_COLOR_BUFFER_BIT);
  glColor3f(1, 0, 0);
  glRectf(x, 50, x + 40, 100);
end;

procedure TForm1.Draw;
var i: Integer;
begin
  glClear(GL_ACCUM_BUFFER_BIT);
  for i := 0 to 7 do
  begin
    Scene(Jitter[i, 0] - 0.5, Jitter[i, 1] - 0.5);
    if i = 0 then glAccum(GL_LOAD, 1 / 8) else glAccum(GL_ACCUM, 1 / 8);
  end;
  { motion blur of a square: 4 positions 10 px apart }
  for i := 0 to 3 do
  begin
    Square(180 + 10 * i);
    glAccum(GL_ACCUM, 1 / 4);
  end;
  glAccum(GL_RETURN, 1.0);
end;

var
  x, y, r, g, b, grey: Integer;
begin
  Application.Initialize;
  Application.CreateForm(TForm1, Form1);
  Application.Show;
  Application.Snapshot('accum');
  ExpectPixel(60, 60, 255, 255, 255, 1, 'triangle interior: 8 x 1/8 of white');
  ExpectPixel(10, 140, 0, 0, 0, 0, 'outside');
  { edge pixels get partial coverage: count greys strictly between }
  grey := 0;
  for y := 0 to 149 do
    for x := 0 to 149 do
    begin
      PixelAt(x, y, r, g, b);
      if (r > 10) and (r < 245) and (r = g) and (g = b) then Inc(grey);
    end;
  Expect(grey > 150, Format('%d anti-aliased edge pixels (grey)', [grey]));
  { motion blur: 1/4 where one position covers, 4/4 where all four do }
  ExpectPixel(185, 75, 64, 0, 0, 1, 'blur: covered by 1 of 4 positions');
  ExpectPixel(195, 75, 128, 0, 0, 1, 'blur: covered by 2 of 4');
  ExpectPixel(215, 75, 255, 0, 0, 1, 'blur: covered by all 4');
  ExpectPixel(245, 75, 64, 0, 0, 1, 'blur: trailing edge, 1 of 4');
  Expect(glGetError = GL_NO_ERROR, 'glGetError');
  Application.Terminate;
  Done('accum');
end.
