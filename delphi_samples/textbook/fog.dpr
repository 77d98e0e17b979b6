{ fog.dpr -- the textbook's §13.3 fog (seeds-inventory F34): grey linear
  fog from eye distance 2 to 50 over a row of red quads receding from 3 to
  47 units, seen in perspective.  By GL 1.5 §3.10 the fog factor is
  f = (end - z) / (end - start) with z the eye distance, and the colour
  f * red + (1 - f) * grey; each quad is checked at its centre. }
program fog;

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
  Depths: array[0..4] of GLfloat = (3, 10, 20, 35, 47);

var
  Form1: TForm1;
  FogColor: array[0..3] of GLfloat = (0.6, 0.6, 0.6, 1);

constructor TForm1.Create(AOwner: TComponent);
begin
  inherited;
  ClientWidth := 400;
  ClientHeight := 200;
end;

procedure TForm1.InitGL;
begin
  glClearColor(0.6, 0.6, 0.6, 1);   { the sky is the fog }
  glEnable(GL_FOG);
  glFogi(GL_FOG_MODE, GL_LINEAR);
  glFogf(GL_FOG_START, 2.0);
  glFogf(GL_FOG_END, 50.0);
  glFogfv(GL_FOG_COLOR, @FogColor);
  glHint(GL_FOG_HINT, GL_NICEST);
end;

procedure TForm1.Reshape(w, h: Integer);
begin
  glViewport(0, 0, w, h);
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity;
  glFrustum(-1, 1, -0.5, 0.5, 1, 60);
  glMatrixMode(GL_MODELVIEW);
  glLoadIdentity;
end;

{ quad i: at eye depth Depths[i], spread along x so each is seen apart,
  and sized so it covers the same window area }
procedure TForm1.Draw;
var
  i: Integer;
  z, cx, s: GLfloat;
begin
  glClear(GL_COLOR_BUFFER_BIT);
  glColor3f(1, 0, 0);
  for i := 0 to 4 do
  begin
    z := Depths[i];
    cx := (-0.8 + 0.4 * i) * z;   { window x = 200 + 200 * (-0.8 + 0.4 i) }
    s := 0.1 * z;
    glBegin(GL_QUADS);
      glVertex3f(cx - s, -s, -z);
      glVertex3f(cx + s, -s, -z);
      glVertex3f(cx + s, s, -z);
      glVertex3f(cx - s, s, -z);
    glEnd;
  end;
end;

var
  i: Integer;
  f: Double;
begin
  Application.Initialize;
  Application.CreateForm(TForm1, Form1);
  Application.Show;
  Application.Snapshot('fog');
  for i := 0 to 4 do
  begin
    f := (50 - Depths[i]) / (50 - 2);
    ExpectPixel(Round(200 + 200 * (-0.8 + 0.4 * i)), 100,
      Round(255 * (f * 1 + (1 - f) * 0.6)), Round(255 * (1 - f) * 0.6), Round(255 * (1 - f) * 0.6), 2,
      Format('quad at depth %g, fog factor %.3f', [Depths[i], f]));
  end;
  ExpectPixel(200, 180, 153, 153, 153, 1, 'background: the fog colour');
  Expect(glGetError = GL_NO_ERROR, 'glGetError');
  Application.Terminate;
  Done('fog');
end.
