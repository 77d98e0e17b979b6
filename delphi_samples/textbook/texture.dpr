{ texture.dpr -- the textbook's §13.1 textures (seeds-inventory F28-F31):
  the image comes from a BMP through auxDIBImageLoad ('Image/t1.bmp', 64x48
  -- not a power of two, so gluScaleImage makes it 64x64, §13.1.1), then
  gluBuild2DMipmaps and GL_LINEAR_MIPMAP_LINEAR / GL_LINEAR filters.
  F30: a triangle mapped with the upper-left half of the texture; F31: a
  quad repeating it 10 times across (GL_REPEAT, minified through the
  mipmaps).  Third, what the book's F29 does when followed literally: one
  level through glTexImage2D into another texture and no filter set.  The
  book claims GL_TEXTURE_MIN_FILTER defaults to GL_LINEAR (§6 #17); it is
  GL_NEAREST_MIPMAP_LINEAR, so that texture is incomplete and the quad is
  drawn as if texturing were off: the current colour, white. }
program texture;

{$mode delphi}

uses
  SysUtils, Windows, Forms, Checks, BookGL, GLAux, gl, glu;

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
  Tex: array[0..1] of GLuint;
  texImage: PAUX_RGBImageRec;
  scaled: array[0..64 * 64 * 3 - 1] of GLubyte;
  ScaleErr, MipErr: GLint;

constructor TForm1.Create(AOwner: TComponent);
begin
  inherited;
  ClientWidth := 480;
  ClientHeight := 180;
end;

procedure TForm1.InitGL;
begin
  glGenTextures(2, @Tex);
  glBindTexture(GL_TEXTURE_2D, Tex[0]);
  glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
  glPixelStorei(GL_PACK_ALIGNMENT, 1);
  ScaleErr := gluScaleImage(GL_RGB, texImage^.sizeX, texImage^.sizeY, GL_UNSIGNED_BYTE,
    texImage^.data, 64, 64, GL_UNSIGNED_BYTE, @scaled);
  MipErr := gluBuild2DMipmaps(GL_TEXTURE_2D, 3, 64, 64, GL_RGB, GL_UNSIGNED_BYTE, @scaled);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR_MIPMAP_LINEAR);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);

  glBindTexture(GL_TEXTURE_2D, Tex[1]);        { F29 as printed: no filters }
  glTexImage2D(GL_TEXTURE_2D, 0, 3, 64, 64, 0, GL_RGB, GL_UNSIGNED_BYTE, @scaled);
  glEnable(GL_TEXTURE_2D);
end;

procedure TForm1.Reshape(w, h: Integer);
begin
  glViewport(0, 0, w, h);
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity;
  glOrtho(0, 24, 0, 9, -2, 2);    { 20 px per unit }
  glMatrixMode(GL_MODELVIEW);
  glLoadIdentity;
end;

procedure TForm1.Draw;
begin
  glClear(GL_COLOR_BUFFER_BIT);
  glColor3f(1, 1, 1);
  glBindTexture(GL_TEXTURE_2D, Tex[0]);
  glBegin(GL_TRIANGLES);                        { F30 }
    glTexCoord2f(0, 1); glVertex3f(2, 8, 0);
    glTexCoord2f(1, 1); glVertex3f(6, 8, 0);
    glTexCoord2f(0, 0); glVertex3f(2, 1, 0);
  glEnd;
  glPushMatrix;
  glTranslatef(12, 0, 0);
  glBegin(GL_QUADS);                            { F31 }
    glTexCoord2f(0, 0); glVertex3f(1, 1, 1);
    glTexCoord2f(0, 1); glVertex3f(1, 5, 1);
    glTexCoord2f(10, 1); glVertex3f(11, 5, 1);
    glTexCoord2f(10, 0); glVertex3f(11, 1, 1);
  glEnd;
  glBindTexture(GL_TEXTURE_2D, Tex[1]);
  glBegin(GL_QUADS);                            { F29's texture: incomplete }
    glTexCoord2f(0, 0); glVertex3f(1, 6, 0);
    glTexCoord2f(1, 0); glVertex3f(11, 6, 0);
    glTexCoord2f(1, 1); glVertex3f(11, 8, 0);
    glTexCoord2f(0, 1); glVertex3f(1, 8, 0);
  glEnd;
  glPopMatrix;
end;

var
  x, y, r, g, b, n: Integer;
  sr, sg, sb, mr, mg, mb: Double;
  i: Integer;
begin
  texImage := auxDIBImageLoad('Image/t1.bmp');
  if texImage = nil then
  begin
    WriteLn('FAIL cannot load Image/t1.bmp (run from delphi_samples/textbook)');
    Halt(1);
  end;
  Expect((texImage^.sizeX = 64) and (texImage^.sizeY = 48), 'BMP is 64x48');
  Application.Initialize;
  Application.CreateForm(TForm1, Form1);
  Application.Show;
  Application.Snapshot('texture');
  Expect((ScaleErr = 0) and (MipErr = 0), Format('gluScaleImage %d, gluBuild2DMipmaps %d', [ScaleErr, MipErr]));
  { F30: texture (s,t) = (0,1) at (2,8), (1,1) at (6,8), (0,0) at (2,1):
    the triangle's upper-left part shows the red quadrant, its lower-left
    the blue one (flat areas, so the filter gives their exact colour) }
  ExpectPixel(2 * 20 + 12, 8 * 20 - 12, 220, 40, 40, 3, 'F30: red quadrant near (0,1)');
  ExpectPixel(2 * 20 + 8, 1 * 20 + 30, 40, 60, 220, 3, 'F30: blue quadrant near (0,0)');
  ExpectPixel(7 * 20, 4 * 20, 0, 0, 0, 0, 'F30: right of the triangle is empty');
  { F31: ten copies, minified across: the mean colour over the quad is the
    texture's mean }
  sr := 0; sg := 0; sb := 0;
  for i := 0 to 64 * 64 - 1 do
  begin
    sr := sr + scaled[i * 3]; sg := sg + scaled[i * 3 + 1]; sb := sb + scaled[i * 3 + 2];
  end;
  sr := sr / 4096; sg := sg / 4096; sb := sb / 4096;
  mr := 0; mg := 0; mb := 0; n := 0;
  for y := 21 to 99 do
    for x := 261 to 459 do
    begin
      PixelAt(x, y, r, g, b);
      mr := mr + r; mg := mg + g; mb := mb + b; Inc(n);
    end;
  mr := mr / n; mg := mg / n; mb := mb / n;
  WriteLn(Format('F31 mean (%.1f, %.1f, %.1f), texture mean (%.1f, %.1f, %.1f)', [mr, mg, mb, sr, sg, sb]));
  Expect((Abs(mr - sr) < 10) and (Abs(mg - sg) < 10) and (Abs(mb - sb) < 10), 'F31: the repeated texture averages to the image');
  { F29 followed literally: incomplete texture, plain white }
  ExpectPixel(12 * 20 + 100, 7 * 20, 255, 255, 255, 0, 'F29: incomplete texture: untextured white');
  Expect(glGetError = GL_NO_ERROR, 'glGetError');
  Application.Terminate;
  Done('texture');
end.
