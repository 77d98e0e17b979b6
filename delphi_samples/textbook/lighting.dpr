{ lighting.dpr -- the textbook's §13.2 lighting (seeds-inventory F32, F33):
  left, the lit sphere of F33: default material with a white specular
  (shininess 40), light 0 at (1,1,1,1) with ambient 0.5, diffuse and
  specular 1, set while the modelview is the identity (so in eye space);
  right, the same sphere with F32's purple material (ambient 0.4,0.3,0.4,
  diffuse 0.7,0.4,0.7, specular 0.5,0.5,0.2, shininess 90) -- given here
  as four-element arrays: the book's three-element ones make glMaterialfv
  read past their end.  Checked against the lighting equation (GL 1.5
  §2.14.1): where no light reaches, colour = global ambient 0.2 x material
  ambient + light ambient x material ambient; F33: 0.2*0.2 + 0.5*0.2 =
  0.14. }
program lighting;

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
  m_specular: array[0..3] of GLfloat = (1, 1, 1, 1);
  m_shininess: array[0..0] of GLfloat = (40);
  l_ambient: array[0..3] of GLfloat = (0.5, 0.5, 0.5, 1);
  l_diffuse: array[0..3] of GLfloat = (1, 1, 1, 1);
  l_specular: array[0..3] of GLfloat = (1, 1, 1, 1);
  l_position: array[0..3] of GLfloat = (1, 1, 1, 1);
  amb: array[0..3] of GLfloat = (0.4, 0.3, 0.4, 1);
  dif: array[0..3] of GLfloat = (0.7, 0.4, 0.7, 1);
  spec: array[0..3] of GLfloat = (0.5, 0.5, 0.2, 1);

constructor TForm1.Create(AOwner: TComponent);
begin
  inherited;
  ClientWidth := 400;
  ClientHeight := 200;
end;

procedure TForm1.InitGL;
begin
  glClearColor(0, 0, 0, 0);
  glLightfv(GL_LIGHT0, GL_POSITION, @l_position);   { eye space: modelview is I }
  glLightfv(GL_LIGHT0, GL_AMBIENT, @l_ambient);
  glLightfv(GL_LIGHT0, GL_DIFFUSE, @l_diffuse);
  glLightfv(GL_LIGHT0, GL_SPECULAR, @l_specular);
  glEnable(GL_LIGHTING);
  glEnable(GL_LIGHT0);
  glEnable(GL_DEPTH_TEST);
end;

procedure TForm1.Reshape(w, h: Integer);
begin
  glViewport(0, 0, w, h);
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity;
  glOrtho(-2.4, 2.4, -1.2, 1.2, -5, 5);
  glMatrixMode(GL_MODELVIEW);
  glLoadIdentity;
end;

procedure TForm1.Draw;
var quadratic: PGLUquadric;
begin
  glClear(GL_COLOR_BUFFER_BIT or GL_DEPTH_BUFFER_BIT);
  quadratic := gluNewQuadric();
  glPushMatrix;
    glTranslatef(-1.2, 0, 0);
    glMaterialfv(GL_FRONT, GL_SPECULAR, @m_specular);
    glMaterialfv(GL_FRONT, GL_SHININESS, @m_shininess);
    gluSphere(quadratic, 1, 40, 40);
  glPopMatrix;
  glPushMatrix;
    glTranslatef(1.2, 0, 0);
    glMaterialfv(GL_FRONT, GL_AMBIENT, @amb);
    glMaterialfv(GL_FRONT, GL_DIFFUSE, @dif);
    glMaterialfv(GL_FRONT, GL_SPECULAR, @spec);
    glMaterialf(GL_FRONT, GL_SHININESS, 90);
    gluSphere(quadratic, 1, 40, 40);
  glPopMatrix;
  gluDeleteQuadric(quadratic);
end;

var
  r, g, b, bright: Integer;
begin
  Application.Initialize;
  Application.CreateForm(TForm1, Form1);
  Application.Show;
  Application.Snapshot('lighting');
  { lower-left rim of the left sphere faces away from (1,1,1): ambient only }
  { 83 1/3 px per unit: centres (100,100) and (300,100), radius 83 px }
  ExpectPixel(100 - 70, 100 - 70, 0, 0, 0, 0, 'outside the sphere');
  ExpectPixel(100 - 45, 100 - 45, 36, 36, 36, 1, 'F33 unlit side: 0.14 grey');
  { F32 unlit side: 0.2*0.4 + 0.5*0.4 = 0.28 (71), 0.2*0.3+0.5*0.3 = 0.21 (54) }
  ExpectPixel(300 - 45, 100 - 45, 71, 54, 71, 1, 'F32 unlit side: purple ambient');
  { the highlight of the left sphere: white, towards the light }
  bright := CountPixels(255, 255, 255, 3);
  Expect(bright > 10, Format('%d white highlight pixels', [bright]));
  PixelAt(100 + 30, 100 + 30, r, g, b);
  Expect((r > 120) and (r = g) and (g = b), Format('F33 lit side grey (%d,%d,%d)', [r, g, b]));
  Expect(glGetError = GL_NO_ERROR, 'glGetError');
  Application.Terminate;
  Done('lighting');
end.
