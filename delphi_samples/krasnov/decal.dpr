{ decal.dpr -- drives frmMain (Krasnov's stencil decals) headless: keys
  1..6 for each stage in the colour view (decal_stage1..6), the stencil
  view (decal_stencil_stage1..6) and the depth view
  (decal_depth_stage1..6), then the colour view of stage 6 with the
  stencil decals turned off (decal_nostencil).  Pixel checks come from the lighting equation and the
  stencil rules: with the light straight down and GL_NORMALIZE, a colour c
  on a (0,1,0) normal shows as min(1, 0.2 c + c) (global ambient 0.2 +
  diffuse).  The ground's normal comes from glNormal3i(0,1,0), and GL 1.5
  Table 2.9 converts a signed integer c to (2c+1)/(2^32-1): the zeros
  become 1/(2^32-1), so after GL_NORMALIZE the normal is (1,3,1)/sqrt(11)
  and the ground gets 0.2 c + (3/sqrt(11)) c. }
program decal;

{$mode delphi}

uses
  SysUtils, Windows, Forms, Checks, OpenGL, frmMain;

function LitN(c, ndotl: Double): Integer;
begin
  c := (0.2 + ndotl) * c;
  if c > 1 then c := 1;
  Result := Round(c * 255);
end;

function Lit(c: Double): Integer;
begin
  c := 1.2 * c;
  if c > 1 then c := 1;
  Result := Round(c * 255);
end;

const
  GroundNdotL = 3 / Sqrt(11);
  Palette: array[0..6, 0..2] of Integer = ((255, 0, 0), (255, 218, 0), (72, 255, 0),
    (0, 255, 145), (0, 145, 255), (72, 0, 255), (255, 0, 218));
var
  count: array[0..6] of Integer;
  v: Integer;
  i, brown, asphalt, yellow, shadowGround, shadowAsphalt, n: Integer;
begin
  Application.Initialize;
  Application.CreateForm(TfrmGL, frmGL);
  Application.Show;
  for i := 1 to 6 do
  begin
    Application.KeyPress(Chr(Ord('0') + i));
    Application.Snapshot('decal_stage' + IntToStr(i));
    brown := CountPixels(LitN(0.647, GroundNdotL), LitN(0.165, GroundNdotL), LitN(0.165, GroundNdotL), 2);
    asphalt := CountPixels(Lit(0.25), Lit(0.25), Lit(0.25), 2);
    yellow := CountPixels(255, 255, 0, 2);
    shadowGround := CountPixels(LitN(0.647, GroundNdotL) div 2, LitN(0.165, GroundNdotL) div 2, LitN(0.165, GroundNdotL) div 2, 2);
    shadowAsphalt := CountPixels(Lit(0.25) div 2, Lit(0.25) div 2, Lit(0.25) div 2, 2);
    WriteLn(Format('stage %d: ground %d, asphalt %d, yellow %d, shadow on ground %d, on asphalt %d',
      [i, brown, asphalt, yellow, shadowGround, shadowAsphalt]));
    case i of
      1: Expect(CountNonBlack(0, 0, winWidth, winHeight) = 0, 'stage 1 is the clear colour only');
      2: Expect((brown = 0) and (CountNonBlack(0, 0, winWidth, winHeight) > 2000), 'stage 2: the airplane only');
      3: Expect((brown > 50000) and (asphalt < 100), 'stage 3: + ground');
      4: Expect((asphalt > 20000) and (yellow = 0), 'stage 4: + asphalt, no z-fighting with the ground');
      5: Expect((yellow > 4000) and (asphalt > 15000), 'stage 5: + stripes');
      6: Expect(shadowAsphalt > 300, 'stage 6: + a 50% black shadow, blended once');
    end;
  end;

  { the stencil view after each stage.  Palette: 0 red (bare ground),
    1 yellow (asphalt), 2 yellowish green (stripes), 3 bluish cyan
    (shadow), 4 cyanish blue (ground behind the airplane), 5 purplish blue
    (cleared, and the airplane off the ground), 6 never }
  frmGL.miStencilClick(nil);
  for i := 1 to 6 do
  begin
    Application.KeyPress(Chr(Ord('0') + i));
    Application.Snapshot('decal_stencil_stage' + IntToStr(i));
    for v := 0 to 6 do count[v] := CountPixels(Palette[v, 0], Palette[v, 1], Palette[v, 2], 0);
    WriteLn(Format('stencil view, stage %d: values 0..6: %d %d %d %d %d %d %d',
      [i, count[0], count[1], count[2], count[3], count[4], count[5], count[6]]));
    Expect(count[0] + count[1] + count[2] + count[3] + count[4] + count[5] = winWidth * winHeight,
      'every pixel shows a stencil value 0..5');
    Expect(count[6] = 0, 'no stencil value 6');
    { the values a stage can have written: the ground (stage 3) 0 and 4,
      then decal k (stage k + 1) the value k }
    Expect((count[0] > 0) = (i >= 3), Format('stage %d: value 0 (visible ground)', [i]));
    Expect((count[4] > 0) = (i >= 3), Format('stage %d: value 4 (ground behind the airplane)', [i]));
    Expect((count[1] > 0) = (i >= 4), Format('stage %d: value 1 (asphalt)', [i]));
    Expect((count[2] > 0) = (i >= 5), Format('stage %d: value 2 (stripes)', [i]));
    Expect((count[3] > 0) = (i >= 6), Format('stage %d: value 3 (shadow)', [i]));
    ExpectPixel(2, 397, 72, 0, 255, 0, 'top left corner: cleared to 5');
  end;
  Expect(count[1] > 15000, 'stencil 1: asphalt');
  Expect(count[2] > 3000, 'stencil 2: stripes');
  Expect(count[3] > 300, 'stencil 3: shadow');
  Expect(count[4] > 500, 'stencil 4: ground hidden by the airplane');

  { the depth view after each stage: inverted, normalised, background black }
  frmGL.miDepthClick(nil);
  for i := 1 to 6 do
  begin
    Application.KeyPress(Chr(Ord('0') + i));
    Application.Snapshot('decal_depth_stage' + IntToStr(i));
    ExpectPixel(2, 397, 0, 0, 0, 0, 'depth view: the background is black');
    n := CountPixels(255, 255, 255, 0);
    if i = 1 then
      Expect(CountNonBlack(0, 0, winWidth, winHeight) = 0, 'depth view, stage 1: nothing drawn, all black')
    else
      Expect(n >= 1, Format('depth view, stage %d: the nearest point is white', [i]));
  end;

  frmGL.miColorClick(nil);
  frmGL.miStencilDecalsClick(nil);
  Application.KeyPress('6');
  Application.Snapshot('decal_nostencil');
  { the decals are depth-tested against the coplanar ground (GL_LESS): they
    fail where their depth equals the ground's, so most of them vanish }
  asphalt := CountPixels(Lit(0.25), Lit(0.25), Lit(0.25), 2);
  WriteLn(Format('stencil off: asphalt %d pixels', [asphalt]));
  Expect(asphalt < 30000, 'stencil off: the asphalt z-fights with the ground');

  Expect(glGetError = 0, 'glGetError');
  Application.Terminate;
  Done('decal');
end.
