{ tesswind.dpr -- drives ch21_01 (the winding-rule demo) headless.

    tesswind odd|nonzero|positive|negative|abs_geq_two
        one rule, set through GLU's real GLU_TESS_WINDING_RULE (100140):
        writes tesswind_<rule>.png
    tesswind book
        the program as the book has it: Borland's property constant 100110
        (GLU must report GLU_INVALID_ENUM and keep ODD) and the book's
        fall-through keyboard, two key presses: tesswind_book.png,
        tesswind_book_key1.png, tesswind_book_key2.png, all the ODD image
    tesswind cycle
        the C original's key cycling (else-if) with the real constant:
        tesswind_cycle_1..4.png = nonzero, positive, negative, abs_geq_two

  Every frame is checked against an exact winding-number computation on a
  grid of sample points (away from edges): white where the rule fills,
  black elsewhere.  The winding numbers are taken relative to the normal
  GLU chooses (see AreaSign). }
program tesswind;

{$mode delphi}

uses
  SysUtils, Windows, Forms, Checks, OpenGL, ch21_01;

type
  TPt = record x, y: Double; end;
  TContour = array of TPt;
  TShape = array of TContour;

var
  Shapes: array[0..3] of TShape;
  Offsets: array[0..3] of TPt = ((x: 0; y: 0), (x: 0; y: 500), (x: 500; y: 0), (x: 500; y: 500));

function C(const pts: array of Double; backwards: Boolean): TContour;
var i, n: Integer;
begin
  Result := nil;
  n := Length(pts) div 2;
  SetLength(Result, n);
  for i := 0 to n - 1 do
    if backwards then
    begin
      Result[i].x := pts[2 * (n - 1 - i)]; Result[i].y := pts[2 * (n - 1 - i) + 1];
    end
    else
    begin
      Result[i].x := pts[2 * i]; Result[i].y := pts[2 * i + 1];
    end;
end;

procedure BuildShapes;
begin
  SetLength(Shapes[0], 3);
  Shapes[0][0] := C([50, 50, 300, 50, 300, 300, 50, 300], False);
  Shapes[0][1] := C([100, 100, 250, 100, 250, 250, 100, 250], False);
  Shapes[0][2] := C([150, 150, 200, 150, 200, 200, 150, 200], False);
  SetLength(Shapes[1], 3);
  Shapes[1][0] := Shapes[0][0];
  Shapes[1][1] := C([100, 100, 250, 100, 250, 250, 100, 250], True);
  Shapes[1][2] := C([150, 150, 200, 150, 200, 200, 150, 200], True);
  SetLength(Shapes[2], 1);
  Shapes[2][0] := C([400, 250, 400, 50, 50, 50, 50, 400, 350, 400, 350, 100, 100, 100,
    100, 350, 300, 350, 300, 150, 150, 150, 150, 300, 250, 300, 250, 200, 200, 200, 200, 250], False);
  SetLength(Shapes[3], 3);
  Shapes[3][0] := C([50, 150, 350, 150, 350, 200, 50, 200], False);
  Shapes[3][1] := C([100, 100, 300, 100, 300, 350, 100, 350], False);
  Shapes[3][2] := C([200, 50, 250, 300, 150, 300], False);
end;

{ winding number of (px,py): signed crossings of the upward ray test }
function Winding(const s: TShape; px, py: Double): Integer;
var ci, i, n: Integer; a, b: TPt; cross: Double;
begin
  Result := 0;
  for ci := 0 to High(s) do
  begin
    n := Length(s[ci]);
    for i := 0 to n - 1 do
    begin
      a := s[ci][i]; b := s[ci][(i + 1) mod n];
      cross := (b.x - a.x) * (py - a.y) - (px - a.x) * (b.y - a.y);
      if (a.y <= py) and (b.y > py) and (cross > 0) then Inc(Result)
      else if (a.y > py) and (b.y <= py) and (cross < 0) then Dec(Result);
    end;
  end;
end;

{ GLU picks the sign of the polygon normal so that the contours' signed
  areas sum to >= 0 (gluTessNormal, GLU 1.3 §5.3.4): a shape whose area sum
  is negative (the clockwise spiral) is seen from the other side, and its
  winding numbers change sign.  seeds-inventory §3.1 leaves this out: by
  the spec the spiral fills under POSITIVE and is empty under NEGATIVE. }
function AreaSign(const s: TShape): Integer;
var ci, i, n: Integer; a, b: TPt; sum: Double;
begin
  sum := 0;
  for ci := 0 to High(s) do
  begin
    n := Length(s[ci]);
    for i := 0 to n - 1 do
    begin
      a := s[ci][i]; b := s[ci][(i + 1) mod n];
      sum := sum + (a.x * b.y - b.x * a.y);
    end;
  end;
  if sum < 0 then Result := -1 else Result := 1;
end;

function NearEdge(const s: TShape; px, py, d: Double): Boolean;
var ci, i, n: Integer; a, b: TPt; t, dx, dy, qx, qy: Double;
begin
  Result := False;
  for ci := 0 to High(s) do
  begin
    n := Length(s[ci]);
    for i := 0 to n - 1 do
    begin
      a := s[ci][i]; b := s[ci][(i + 1) mod n];
      dx := b.x - a.x; dy := b.y - a.y;
      t := ((px - a.x) * dx + (py - a.y) * dy) / (dx * dx + dy * dy);
      if t < 0 then t := 0 else if t > 1 then t := 1;
      qx := a.x + t * dx - px; qy := a.y + t * dy - py;
      if qx * qx + qy * qy < d * d then Exit(True);
    end;
  end;
end;

function Fills(rule: GLenum; w: Integer): Boolean;
begin
  case rule of
    GLU_TESS_WINDING_ODD: Result := Odd(w);
    GLU_TESS_WINDING_NONZERO: Result := w <> 0;
    GLU_TESS_WINDING_POSITIVE: Result := w > 0;
    GLU_TESS_WINDING_NEGATIVE: Result := w < 0;
    GLU_TESS_WINDING_ABS_GEQ_TWO: Result := Abs(w) >= 2;
  else Result := False;
  end;
end;

{ The frame against the rule: the projection is reshape(Width, Height) of a
  500x500 client area, so world (x,y) is window (x*W/1000, y*H/top). }
procedure CheckFrame(rule: GLenum; const what: string);
var
  k, gx, gy, w, white, black, r, g, b: Integer;
  px, py, top, sx, sy: Double;
begin
  top := 1000.0 * Form1.Height / Form1.Width;
  sx := Form1.Width / 1000.0;
  sy := Form1.Height / top;
  white := 0; black := 0;
  for k := 0 to 3 do
    for gy := 0 to 19 do
      for gx := 0 to 19 do
      begin
        px := 12.5 + 25 * gx; py := 12.5 + 25 * gy;
        if NearEdge(Shapes[k], px, py, 6) then Continue;
        w := AreaSign(Shapes[k]) * Winding(Shapes[k], px, py);
        PixelAt(Trunc((px + Offsets[k].x) * sx), Trunc((py + Offsets[k].y) * sy), r, g, b);
        if (r < 0) then Continue;   { cut off by the oversized viewport }
        if Fills(rule, w) then
        begin
          Inc(white);
          Expect((r = 255) and (g = 255) and (b = 255),
            Format('%s: shape %d point (%g,%g) winding %d should be filled, is (%d,%d,%d)', [what, k, px, py, w, r, g, b]));
        end
        else
        begin
          Inc(black);
          Expect((r = 0) and (g = 0) and (b = 0),
            Format('%s: shape %d point (%g,%g) winding %d should be empty, is (%d,%d,%d)', [what, k, px, py, w, r, g, b]));
        end;
      end;
  WriteLn(Format('%s: %d filled and %d empty sample points checked', [what, white, black]));
end;

const
  RuleNames: array[0..4] of string = ('odd', 'nonzero', 'positive', 'negative', 'abs_geq_two');
  Rules: array[0..4] of GLenum = (GLU_TESS_WINDING_ODD, GLU_TESS_WINDING_NONZERO,
    GLU_TESS_WINDING_POSITIVE, GLU_TESS_WINDING_NEGATIVE, GLU_TESS_WINDING_ABS_GEQ_TWO);

var
  mode: string;
  i: Integer;
begin
  BuildShapes;
  mode := LowerCase(ParamStr(1));
  if mode = '' then mode := 'book';
  Application.Initialize;
  if mode = 'book' then
  begin
    Application.CreateForm(TForm1, Form1);
    Application.Show;
    Application.Snapshot('tesswind_book');
    Expect(TessErrors >= 1, 'Borland''s GLU_TESS_WINDING_RULE (100110) reported no error');
    Expect(LastTessError = GLU_INVALID_ENUM, Format('error callback got %d, expected GLU_INVALID_ENUM (100900)', [LastTessError]));
    CheckFrame(GLU_TESS_WINDING_ODD, 'book');
    for i := 1 to 2 do
    begin
      Application.KeyPress('w');
      Application.Snapshot('tesswind_book_key' + IntToStr(i));
      Expect(currentWinding = GLU_TESS_WINDING_ODD, 'the book''s keyboard() should end on ODD');
      Expect(Form1.Caption = 'GLU_TESS_WINDING_ODD', 'caption ' + Form1.Caption);
      CheckFrame(GLU_TESS_WINDING_ODD, 'book key ' + IntToStr(i));
    end;
    Expect(TessErrors = 3, Format('%d tessellator errors, expected one per makeNewLists (3)', [TessErrors]));
  end
  else if mode = 'cycle' then
  begin
    WindingProperty := GLU_TESS_WINDING_RULE_GLU;
    FixedKeyboard := True;
    Application.CreateForm(TForm1, Form1);
    Application.Show;
    CheckFrame(GLU_TESS_WINDING_ODD, 'cycle 0');
    for i := 1 to 4 do
    begin
      Application.KeyPress('w');
      Application.Snapshot('tesswind_cycle_' + IntToStr(i));
      Expect(currentWinding = Rules[i], 'cycle step ' + IntToStr(i));
      CheckFrame(Rules[i], 'cycle ' + IntToStr(i));
    end;
    Expect(TessErrors = 0, Format('%d tessellator errors', [TessErrors]));
  end
  else
  begin
    i := 0;
    while (i <= 4) and (RuleNames[i] <> mode) do Inc(i);
    if i > 4 then
    begin
      WriteLn('usage: tesswind odd|nonzero|positive|negative|abs_geq_two|book|cycle');
      Halt(2);
    end;
    WindingProperty := GLU_TESS_WINDING_RULE_GLU;
    currentWinding := Rules[i];
    Application.CreateForm(TForm1, Form1);
    Application.Show;
    Application.Snapshot('tesswind_' + RuleNames[i]);
    CheckFrame(Rules[i], RuleNames[i]);
    Expect(TessErrors = 0, Format('%d tessellator errors', [TessErrors]));
  end;
  Expect(CombineCount > 0, 'the spiral and the overlapping shapes need COMBINE');
  Expect(CombineHigh = 2, Format('High(coords) in the combine callback is %d: GLU should pass a 3-element array header', [CombineHigh]));
  Expect(glGetError = 0, 'glGetError');
  Application.Terminate;
  Done('tesswind ' + mode);
end.
