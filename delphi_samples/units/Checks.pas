{ Checks.pas -- key pixel assertions on the frame a program last showed
  (the DC's front image after SwapBuffers), in GL window coordinates
  (origin bottom-left).  Each failed check prints a FAIL line; Done prints
  PASS or FAIL and exits 1 on failure, so the runner sees it. }
unit Checks;

{$mode delphi}

interface

procedure Expect(Cond: Boolean; const Msg: string);
procedure ExpectPixel(X, Y: Integer; R, G, B, Tol: Integer; const Msg: string);
function PixelAt(X, Y: Integer; out R, G, B: Integer): Boolean;
function CountPixels(R, G, B, Tol: Integer): Integer;
function CountNonBlack(X0, Y0, X1, Y1: Integer): Integer;
procedure Done(const Name: string);

var
  Failures: Integer;

implementation

uses SysUtils, Forms;

procedure Expect(Cond: Boolean; const Msg: string);
begin
  if not Cond then
  begin
    Inc(Failures);
    WriteLn('FAIL ', Msg);
  end;
end;

function PixelAt(X, Y: Integer; out R, G, B: Integer): Boolean;
var p: PByte; w, h: Integer;
begin
  p := Application.FrontImage(w, h);
  R := -1; G := -1; B := -1;
  Result := (p <> nil) and (X >= 0) and (Y >= 0) and (X < w) and (Y < h);
  if not Result then Exit;
  Inc(p, (Y * w + X) * 4);
  R := p[0]; G := p[1]; B := p[2];
end;

procedure ExpectPixel(X, Y: Integer; R, G, B, Tol: Integer; const Msg: string);
var pr, pg, pb: Integer;
begin
  if not PixelAt(X, Y, pr, pg, pb) then
  begin
    Expect(False, Format('%s: pixel (%d,%d) outside the frame', [Msg, X, Y]));
    Exit;
  end;
  Expect((Abs(pr - R) <= Tol) and (Abs(pg - G) <= Tol) and (Abs(pb - B) <= Tol),
    Format('%s: pixel (%d,%d) is (%d,%d,%d), expected (%d,%d,%d) +-%d',
      [Msg, X, Y, pr, pg, pb, R, G, B, Tol]));
end;

function CountPixels(R, G, B, Tol: Integer): Integer;
var p: PByte; w, h, i: Integer;
begin
  Result := 0;
  p := Application.FrontImage(w, h);
  if p = nil then Exit;
  for i := 0 to w * h - 1 do
    if (Abs(p[i*4] - R) <= Tol) and (Abs(p[i*4+1] - G) <= Tol) and (Abs(p[i*4+2] - B) <= Tol) then
      Inc(Result);
end;

{ pixels other than black in the rectangle [X0,X1) x [Y0,Y1) }
function CountNonBlack(X0, Y0, X1, Y1: Integer): Integer;
var p: PByte; w, h, x, y: Integer;
begin
  Result := 0;
  p := Application.FrontImage(w, h);
  if p = nil then Exit;
  for y := Y0 to Y1 - 1 do
    for x := X0 to X1 - 1 do
      if (x >= 0) and (y >= 0) and (x < w) and (y < h) then
        if (p[(y * w + x) * 4] or p[(y * w + x) * 4 + 1] or p[(y * w + x) * 4 + 2]) <> 0 then
          Inc(Result);
end;

procedure Done(const Name: string);
begin
  if Failures = 0 then
  begin
    WriteLn('PASS ', Name);
    Halt(0);
  end;
  WriteLn('FAIL ', Name, ' (', Failures, ' checks failed)');
  Halt(1);
end;

end.
