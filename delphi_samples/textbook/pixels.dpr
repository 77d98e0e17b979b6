{ pixels.dpr -- the textbook's §5.10, §14.5 and §15: logic operations,
  the image buffer (glReadPixels, glDrawPixels, glCopyPixels) and
  attribute groups.
  - a yellow square, then a cyan one drawn over half of it with
    GL_COLOR_LOGIC_OP GL_XOR: the overlap is yellow XOR cyan = magenta;
  - glReadPixels of a 40x40 block, drawn again with glDrawPixels at another
    raster position, and copied with glCopyPixels (GL_COLOR: the book's
    "format" is the copy type);
  - glPushAttrib(GL_COLOR_BUFFER_BIT or GL_CURRENT_BIT) around a change of
    clear colour, logic op and current colour: glPopAttrib restores them. }
program pixels;

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
  block: array[0..40 * 40 * 3 - 1] of GLubyte;
  AfterPop: array[0..3] of GLfloat;
  LogicAfterPop: GLboolean;

constructor TForm1.Create(AOwner: TComponent);
begin
  inherited;
  ClientWidth := 300;
  ClientHeight := 120;
end;

procedure TForm1.Draw;
begin
  glClearColor(0, 0, 0, 0);
  glClear(GL_COLOR_BUFFER_BIT);
  glColor3f(1, 1, 0);
  glRecti(10, 10, 50, 50);
  glEnable(GL_COLOR_LOGIC_OP);
  glLogicOp(GL_XOR);
  glColor3f(0, 1, 1);
  glRecti(30, 30, 70, 70);
  glDisable(GL_COLOR_LOGIC_OP);

  { the image buffer }
  glPixelStorei(GL_PACK_ALIGNMENT, 1);
  glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
  glReadPixels(10, 10, 40, 40, GL_RGB, GL_UNSIGNED_BYTE, @block);
  glRasterPos2i(110, 10);
  glDrawPixels(40, 40, GL_RGB, GL_UNSIGNED_BYTE, @block);
  glRasterPos2i(210, 10);
  glCopyPixels(10, 10, 60, 60, GL_COLOR);

  { attribute groups }
  glColor3f(0.25, 0.5, 0.75);
  glPushAttrib(GL_COLOR_BUFFER_BIT or GL_CURRENT_BIT);
    glClearColor(1, 1, 1, 1);
    glEnable(GL_COLOR_LOGIC_OP);
    glColor3f(1, 0, 0);
  glPopAttrib;
  glGetFloatv(GL_CURRENT_COLOR, @AfterPop);
  LogicAfterPop := glIsEnabled(GL_COLOR_LOGIC_OP);
  glRecti(10, 90, 290, 110);       { in the restored colour }
end;

begin
  Application.Initialize;
  Application.CreateForm(TForm1, Form1);
  Application.Show;
  Application.Snapshot('pixels');
  ExpectPixel(20, 20, 255, 255, 0, 0, 'yellow square');
  ExpectPixel(40, 40, 255, 0, 255, 0, 'yellow XOR cyan = magenta');
  ExpectPixel(60, 60, 0, 255, 255, 0, 'cyan XOR black = cyan');
  ExpectPixel(120, 20, 255, 255, 0, 0, 'glDrawPixels copy: yellow');
  ExpectPixel(140, 40, 255, 0, 255, 0, 'glDrawPixels copy: the overlap');
  ExpectPixel(155, 55, 0, 0, 0, 0, 'glDrawPixels copy is 40x40: the cyan part is outside');
  ExpectPixel(250, 50, 0, 255, 255, 0, 'glCopyPixels copy: cyan');
  ExpectPixel(230, 30, 255, 0, 255, 0, 'glCopyPixels copy: the overlap');
  Expect((Abs(AfterPop[0] - 0.25) < 1e-6) and (Abs(AfterPop[2] - 0.75) < 1e-6), 'glPopAttrib restored the current colour');
  Expect(LogicAfterPop = GL_FALSE, 'glPopAttrib restored GL_COLOR_LOGIC_OP off');
  ExpectPixel(150, 100, 64, 128, 191, 1, 'bar in the restored colour');
  ExpectPixel(150, 80, 0, 0, 0, 0, 'clear colour restored (the next frame would clear black)');
  Expect(glGetError = GL_NO_ERROR, 'glGetError');
  Application.Terminate;
  Done('pixels');
end.
