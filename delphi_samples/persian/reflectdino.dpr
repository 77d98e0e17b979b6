{ reflectdino.dpr -- drives ch21 (the reflected dinosaur) headless: the
  clock is set so the dinosaur stands at a fixed height, then
    dino_nostencil      the first view, stencil off (the book's default)
    dino_stencil        key '3': the reflection masked to the floor
    dino_below_stencil  dragged to look from under the floor (angle2 -50),
                        stencil on: only the floor's blue underside
    dino_below_nostencil  key '3' again: the "bogus" reflection appears
                        in front of the floor
    dino_wire           key '4' (back above the floor, stencil on): the
                        floor is drawn as lines too, so is its stencil mask
  with pixel checks of what the spec makes of the floor's colours. }
program reflectdino;

{$mode delphi}

uses
  SysUtils, Windows, Forms, Checks, OpenGL, ch21;

var
  floorOnly, below: Integer;
begin
  Application.Initialize;
  SetTickCount(0);
  Application.CreateForm(TForm1, Form1);
  { jump = 6|sin(t/8)| with t the smoothed clock: t = 6 gives 4.09 }
  SetTickCount(12);
  Application.Idle;
  Expect(Abs(jump - 6.0 * Abs(Sin(6 / 8))) < 1e-4, Format('jump %.4f', [jump]));
  Application.Show;
  Application.Snapshot('dino_nostencil');
  { the translucent floor over black: 0.3 * (0.7, 0, 0) = (54, 0, 0) }
  floorOnly := CountPixels(54, 0, 0, 1);
  Expect(floorOnly > 20000, Format('%d pixels of bare floor (54,0,0)', [floorOnly]));
  ExpectPixel(30, 150, 54, 0, 0, 1, 'bare floor, left');
  ExpectPixel(5, 395, 0, 0, 0, 0, 'background, top left');
  { the reflection seen through the floor: darker than the dinosaur, red added }
  ExpectPixel(200, 40, 80, 178, 26, 12, 'reflected body through the floor');

  Application.KeyPress('3');
  Expect(useStencil, 'key 3 turns stencil on');
  Application.Snapshot('dino_stencil');
  ExpectPixel(30, 150, 54, 0, 0, 1, 'bare floor, stencil on');
  { seen from above, the floor covers the whole reflection: same picture }
  Expect(CountPixels(54, 0, 0, 1) = floorOnly, 'stencil on changes nothing seen from above');

  Application.Drag(200, 200, 200, 120);       { angle2 30 -> -50: from below }
  Application.Snapshot('dino_below_stencil');
  { the floor's underside, opaque (0.1, 0.1, 0.7) }
  Expect(CountPixels(26, 26, 179, 1) > 40000, 'the blue underside of the floor');
  { from below, the floor's top face is culled in the stencil pass too:
    no stencil 1 anywhere, no reflection }
  below := CountNonBlack(0, 0, 400, 400) - CountPixels(26, 26, 179, 1);
  Expect(below = 0, Format('stencil on: %d pixels neither floor nor background, expected none', [below]));

  Application.KeyPress('3');
  Application.Snapshot('dino_below_nostencil');
  { without the mask the mirrored dinosaur, below the floor, is in front
    of it seen from there: the "bogus" reflection }
  below := CountNonBlack(0, 0, 400, 400) - CountPixels(26, 26, 179, 1);
  Expect(below > 10000, Format('stencil off: %d pixels of the bogus reflection', [below]));

  Application.KeyPress('3');
  Application.Drag(200, 120, 200, 200);
  Application.KeyPress('4');
  Application.Snapshot('dino_wire');
  { glPolygonMode applies to the floor too: only its outline is drawn, and
    the stencil pass marks only that outline, so no reflection shows }
  floorOnly := CountPixels(54, 0, 0, 1);
  Expect((floorOnly > 100) and (floorOnly < 3000), Format('%d pixels of floor outline', [floorOnly]));
  Expect(CountNonBlack(0, 0, 400, 400) < 20000, 'wireframe: mostly black');
  Expect(glGetError = 0, 'glGetError');
  Application.Terminate;
  Done('reflectdino');
end.
