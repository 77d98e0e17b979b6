{ text.dpr -- the textbook's §9 text output (seeds-inventory F18, F19):
  1. the system font: SelectObject(DC, GetStockObject(SYSTEM_FONT)),
     wglUseFontBitmaps(DC, 1, 255, 1) (list n draws character n), then
     glRasterPos2i(20, 10); glColor3f(1, 1, 0);
     glCallLists(17, GL_UNSIGNED_BYTE, 'Привет OpenGL !!!') in code page
     1251.  The colour is set after the raster position, which latched the
     colour current then: the first frame draws white, the second yellow.
  2. CreateFont('Courier', 36, FW_BOLD, ANSI_CHARSET, ...), lists from
     glGenLists(224) for codes 32..255, glListBase(base - 32) inside
     glPushAttrib(GL_LIST_BIT): bold 36 px text at (20, 60).
  3. the same under gluPerspective: the raster positions are invalid
     (F19 quirk f) and nothing is drawn. }
program text;

{$mode delphi}

uses
  SysUtils, Windows, Forms, Checks, BookGL, gl, glu;

type
  TForm1 = class(TGLForm)
  protected
    procedure InitGL; override;
    procedure Draw; override;
  public
    constructor Create(AOwner: TComponent); override;
  end;

var
  Form1: TForm1;
  base: GLuint;
  Perspective: Boolean = False;
  RasterValid: GLboolean;

const
  { 'Привет OpenGL !!!' in code page 1251 }
  Hello: AnsiString = #$CF#$F0#$E8#$E2#$E5#$F2' OpenGL !!!';

constructor TForm1.Create(AOwner: TComponent);
begin
  inherited;
  ClientWidth := 400;
  ClientHeight := 120;
end;

procedure glPrintText(base: GLuint; s: PAnsiChar);
begin
  if (base = 0) or (s = nil) then Exit;
  glPushAttrib(GL_LIST_BIT);
  glListBase(base - 32);
  glCallLists(StrLen(s), GL_UNSIGNED_BYTE, s);
  glPopAttrib;
end;

procedure CFont(DC: HDC; name: PAnsiChar; size: Integer);
var hFont: Windows.HFONT;
begin
  base := glGenLists(224);
  hFont := CreateFont(size, 0, 0, 0, FW_BOLD, 0, 0, 0, ANSI_CHARSET, OUT_TT_PRECIS,
    CLIP_DEFAULT_PRECIS, ANTIALIASED_QUALITY, FF_DONTCARE or DEFAULT_PITCH, name);
  SelectObject(DC, hFont);
  wglUseFontBitmaps(DC, 32, 224, base);
  DeleteObject(hFont);
end;

procedure TForm1.InitGL;
begin
  SelectObject(DC, GetStockObject(SYSTEM_FONT));
  wglUseFontBitmaps(DC, 1, 255, 1);
  CFont(DC, 'Courier', 36);
end;

procedure TForm1.Draw;
begin
  if Perspective then
  begin
    { (f): a perspective projection and an identity modelview put
      (20, 10, 0) on the eye's plane: w = 0, the raster position is
      invalid and neither glBitmap list draws }
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity;
    gluPerspective(45, ClientWidth / ClientHeight, 0.1, 100);
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity;
  end;
  glClear(GL_COLOR_BUFFER_BIT);
  glRasterPos2i(20, 10);
  glColor3f(1, 1, 0);
  glCallLists(17, GL_UNSIGNED_BYTE, PAnsiChar(Hello));
  glRasterPos2i(20, 60);
  glGetBooleanv(GL_CURRENT_RASTER_POSITION_VALID, @RasterValid);
  glPrintText(base, PAnsiChar(Hello));
end;

var
  white, yellow: Integer;
begin
  Application.Initialize;
  Application.CreateForm(TForm1, Form1);
  Application.Show;
  Application.Snapshot('text_frame1');
  white := CountPixels(255, 255, 255, 0);
  yellow := CountPixels(255, 255, 0, 0);
  WriteLn(Format('frame 1: %d white, %d yellow pixels', [white, yellow]));
  Expect(white > 100, 'frame 1: the system-font line is white (colour latched at glRasterPos)');
  Expect(yellow > 300, 'frame 1: the Courier line is yellow');
  Expect(CountNonBlack(0, 0, 18, 120) = 0, 'both lines start at x = 20');
  Expect(CountNonBlack(0, 4, 400, 30) = white, 'the white line sits on y = 10 (descenders of p and р below)');
  Application.Paint;
  Application.Snapshot('text_frame2');
  Expect(CountPixels(255, 255, 255, 0) = 0, 'frame 2: no white left: both lines yellow');
  Expect(CountPixels(255, 255, 0, 0) = white + yellow, 'frame 2: the same pixels, yellow');
  Perspective := True;
  Application.Paint;
  Application.Snapshot('text_perspective');
  Expect(RasterValid = GL_FALSE, 'raster position on the eye plane is invalid');
  Expect(CountNonBlack(0, 0, 400, 120) = 0, 'an invalid raster position draws no text');
  Expect(glGetError = GL_NO_ERROR, 'glGetError');
  Application.Terminate;
  Done('text');
end.
