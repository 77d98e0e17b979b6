{ decal.dpr -- drives frmMain (Krasnov's stencil decals) headless: keys
  1..6 for each stage in the colour view (decal_stage1..6), then at
  stage 6 the stencil view (decal_stencil), the depth view (decal_depth)
  and the colour view with the stencil decals turned off
  (decal_nostencil).  Pixel checks come from the lighting equation and the
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
var
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

  frmGL.miStencilClick(nil);
  Application.Paint;
  Application.Snapshot('decal_stencil');
  { palette: 0 red (bare ground), 1 yellow (asphalt), 2 yellowish green
    (stripes), 3 bluish cyan (shadow), 4 cyanish blue (ground behind the
    airplane), 5 purplish blue (cleared, and the airplane off the ground) }
  Expect(CountPixels(255, 0, 0, 0) > 20000, 'stencil 0: visible ground');
  Expect(CountPixels(255, 218, 0, 0) > 15000, 'stencil 1: asphalt');
  Expect(CountPixels(72, 255, 0, 0) > 3000, 'stencil 2: stripes');
  Expect(CountPixels(0, 255, 145, 0) > 300, 'stencil 3: shadow');
  Expect(CountPixels(0, 145, 255, 0) > 500, 'stencil 4: ground hidden by the airplane');
  Expect(CountPixels(72, 0, 255, 0) > 5000, 'stencil 5: background');
  n := CountPixels(255, 0, 218, 0);
  Expect(n = 0, Format('%d pixels of stencil 6: no such value', [n]));
  ExpectPixel(2, 397, 72, 0, 255, 0, 'top left corner: cleared to 5');

  frmGL.miDepthClick(nil);
  Application.Paint;
  Application.Snapshot('decal_depth');
  ExpectPixel(2, 397, 0, 0, 0, 0, 'depth view: the background is black');
  n := CountPixels(255, 255, 255, 0);
  Expect(n >= 1, 'depth view: the nearest point is white');

  frmGL.miColorClick(nil);
  frmGL.miStencilDecalsClick(nil);
  Application.Paint;
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
