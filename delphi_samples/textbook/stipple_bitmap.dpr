{ stipple_bitmap.dpr -- the textbook's §5.6-5.7 fragments (seeds-inventory
  F06-F08): a quadrilateral filled through a 32x32 polygon stipple whose
  rows repeat every four (FF FF FF FF / 01.. / 00.. / 01..), and the
  letter T as a 16x12 glBitmap (rows of 2 bytes, so
  GL_UNPACK_ALIGNMENT 1), three times with a 16 px advance.  Expected, by
  the spec: the stipple is anchored at window (0,0), its first byte's most
  significant bit is the leftmost pixel: full rows at y = 0 mod 4, single
  pixels at x = 7 mod 8 on odd rows; each T has a 10x2 bar on top
  (columns 0-9, rows 10-11) and a 2 px stem (columns 4-5, rows 0-9). }
program stipple_bitmap;

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
  StippleMap: array[0..127] of GLubyte;
  TMap: array[0..23] of GLubyte = (
    $0c, $00, $0c, $00, $0c, $00, $0c, $00, $0c, $00,
    $0c, $00, $0c, $00, $0c, $00, $0c, $00, $0c, $00,
    $ff, $c0, $ff, $c0);

constructor TForm1.Create(AOwner: TComponent);
begin
  inherited;
  ClientWidth := 200;
  ClientHeight := 150;
end;

procedure TForm1.Draw;
begin
  glClear(GL_COLOR_BUFFER_BIT);
  { F06 }
  glColor3f(1, 1, 1);
  glEnable(GL_POLYGON_STIPPLE);
  glPolygonStipple(@StippleMap);
  glBegin(GL_POLYGON);
    glVertex2i(10, 10);
    glVertex2i(30, 60);
    glVertex2i(100, 70);
    glVertex2i(80, 20);
  glEnd;
  glDisable(GL_POLYGON_STIPPLE);
  { F07 / F08 }
  glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
  glColor3f(1, 1, 1);
  glRasterPos2i(120, 120);
  glBitmap(16, 12, 0, 0, 16, 0, @TMap);
  glBitmap(16, 12, 0, 0, 16, 0, @TMap);
  glBitmap(16, 12, 0, 0, 16, 0, @TMap);
end;

var
  i, k: Integer;
begin
  for i := 0 to 31 do
    for k := 0 to 3 do
      case i mod 4 of
        0: StippleMap[i * 4 + k] := $FF;
        1, 3: StippleMap[i * 4 + k] := $01;
        2: StippleMap[i * 4 + k] := $00;
      end;
  Application.Initialize;
  Application.CreateForm(TForm1, Form1);
  Application.Show;
  Application.Snapshot('stipple_bitmap');
  ExpectPixel(50, 40, 255, 255, 255, 0, 'stipple: row 40 (0 mod 4) full');
  ExpectPixel(55, 41, 255, 255, 255, 0, 'stipple: x 55 (7 mod 8) on row 41');
  ExpectPixel(54, 41, 0, 0, 0, 0, 'stipple: x 54 on row 41 off');
  ExpectPixel(55, 42, 0, 0, 0, 0, 'stipple: row 42 (2 mod 4) empty');
  ExpectPixel(63, 43, 255, 255, 255, 0, 'stipple: x 63 on row 43');
  ExpectPixel(5, 40, 0, 0, 0, 0, 'stipple: outside the polygon');
  for k := 0 to 2 do
  begin
    ExpectPixel(120 + 16 * k + 4, 120, 255, 255, 255, 0, 'T stem, left column');
    ExpectPixel(120 + 16 * k + 5, 129, 255, 255, 255, 0, 'T stem, right column, top');
    ExpectPixel(120 + 16 * k + 3, 125, 0, 0, 0, 0, 'T: left of the stem');
    ExpectPixel(120 + 16 * k + 0, 131, 255, 255, 255, 0, 'T bar, left end');
    ExpectPixel(120 + 16 * k + 9, 130, 255, 255, 255, 0, 'T bar, right end');
    ExpectPixel(120 + 16 * k + 10, 131, 0, 0, 0, 0, 'T bar is 10 px');
    ExpectPixel(120 + 16 * k + 4, 132, 0, 0, 0, 0, 'T is 12 px high');
  end;
  Application.Terminate;
  Done('stipple_bitmap');
end.
