{ ch21.pas -- the reflected dinosaur of the Persian book's chapter 21,
  second program (S0:1105-1610; seeds-inventory §3.2), a port of Kilgard's
  "Leapin' Lizards": a dinosaur extruded from tessellated outlines hops
  over a translucent red floor; its mirror image (glScalef(1,-1,1), lights
  mirrored too) shows through the floor, confined to the floor by the
  stencil buffer when stencil is on (key '3'); '4' toggles wireframe, '1'
  and '2' the lights; dragging the mouse turns the view.

  Written here in the book's style (FormCreate / FormResize / FormPaint /
  FormKeyPress, stdcall tessellator callbacks, display lists named by an
  enumeration without glGenLists, Borland's one-argument
  gluTessBeginPolygon).  Kept from the book, as softgl must draw them as
  they are: the side walls get no normals of their own (they are lit with
  the last normal, (0,0,1)); the wall strip skips the last outline vertex
  (`i mod count` with count = High(data)); GL_LIGHT1 starts disabled while
  its switch says on; redraw runs once in initGL before any list exists;
  the viewport is the outer Width/Height.  Changed: time comes from the
  driver (GetTickCount is the driver's clock), and the caption is not
  rewritten inside the tessellation loop. }
unit ch21;

{$mode delphi}

interface

uses
  SysUtils, Windows, Forms, OpenGL, SPF;   { Windows after SysUtils: its GetTickCount }

type
  TForm1 = class(TForm)
    procedure FormCreate(Sender: TObject);
    procedure FormMouseDown(Sender: TObject; Button: TMouseButton;
      Shift: TShiftState; X, Y: Integer);
    procedure FormMouseUp(Sender: TObject; Button: TMouseButton;
      Shift: TShiftState; X, Y: Integer);
    procedure FormMouseMove(Sender: TObject; Shift: TShiftState; X, Y: Integer);
    procedure FormResize(Sender: TObject);
    procedure FormDestroy(Sender: TObject);
    procedure FormPaint(Sender: TObject);
    procedure FormKeyPress(Sender: TObject; var Key: Char);
  private
    procedure Idle(Sender: TObject; var Done: Boolean);
  public
    constructor Create(AOwner: TComponent); override;
  end;

var
  Form1: TForm1;
  useStencil: GLboolean = GL_FALSE;   { initially, allow the artifacts }
  jump: Single = 0.0;

implementation

type
  displayLists = (RESERVED, BODY_SIDE, BODY_EDGE, BODY_WHOLE, ARM_SIDE,
    ARM_EDGE, ARM_WHOLE, LEG_SIDE, LEG_EDGE, LEG_WHOLE,
    EYE_SIDE, EYE_EDGE, EYE_WHOLE);
  T3dArray = array[0..2] of GLfloat;
  TVertexf = T3dArray;

var
  angle: GLfloat = 20;     { degrees }
  angle2: GLfloat = 30;
  startx, starty: LongInt;
  moving: GLboolean = GL_FALSE;
  bodyWidth: GLdouble = 3.0;
  body, arm, leg, eye: array of TVertexf;
  lightZeroPosition: array[0..3] of GLfloat = (10.0, 14.0, 10.0, 1.0);
  lightZeroColor: array[0..3] of GLfloat = (0.8, 1.0, 0.8, 1.0);
  lightOnePosition: array[0..3] of GLfloat = (-1.0, 1.0, 1.0, 0.0);
  lightOneColor: array[0..3] of GLfloat = (0.6, 0.3, 0.2, 1.0);
  skinColor: array[0..3] of GLfloat = (0.1, 1.0, 0.1, 1.0);
  eyeColor: array[0..3] of GLfloat = (1.0, 0.2, 0.2, 1.0);
  lightZeroSwitch: GLboolean = GL_TRUE;
  lightOneSwitch: GLboolean = GL_TRUE;
  ElapsedTime, DemoStart, LastTime: DWORD;
  wire: Boolean = False;
  f_Hdc: LongInt;

constructor TForm1.Create(AOwner: TComponent);
begin
  inherited;
  ClientWidth := 400;
  ClientHeight := 400;
  Caption := 'OpenGL Reflected Dinosaur!';
  OnCreate := FormCreate;
  OnResize := FormResize;
  OnPaint := FormPaint;
  OnKeyPress := FormKeyPress;
  OnDestroy := FormDestroy;
  OnMouseDown := FormMouseDown;
  OnMouseUp := FormMouseUp;
  OnMouseMove := FormMouseMove;
end;

function Vertexf(x, y, z: Single): TVertexf;
begin
  Result[0] := x;
  Result[1] := y;
  Result[2] := z;
end;

procedure tessBegin(atype: GLenum); stdcall;
begin
  glBegin(atype);   { GL_TRIANGLES, _FAN or _STRIP, as GLU chooses }
end;

procedure tessEnd; stdcall;
begin
  glEnd;
end;

procedure tessVertex(data: Pointer); stdcall;
begin
  glVertex3fv(data);  { data: the TVertexf (singles) given to gluTessVertex }
end;

procedure InitVariables;
const
  B: array[0..21, 0..1] of Single = ((0, 3), (1, 1), (5, 1), (8, 4), (10, 4), (11, 5),
    (11, 11.5), (13, 12), (13, 13), (10, 13.5), (13, 14), (13, 15), (11, 16), (8, 16),
    (7, 15), (7, 13), (8, 12), (7, 11), (6, 6), (4, 3), (3, 2), (1, 2));
  A: array[0..15, 0..1] of Single = ((8, 10), (9, 9), (10, 9), (13, 8), (14, 9), (16, 9),
    (15, 9.5), (16, 10), (15, 10), (15.5, 11), (14.5, 10), (14, 11), (14, 10), (13, 9),
    (11, 11), (9, 11));
  L: array[0..13, 0..1] of Single = ((8, 6), (8, 4), (9, 3), (9, 2), (8, 1), (8, 0.5),
    (9, 0), (12, 0), (10, 1), (10, 2), (12, 4), (11, 6), (10, 7), (9, 7));
  E: array[0..5, 0..1] of Single = ((8.75, 15), (9, 14.7), (9.6, 14.7), (10.1, 15),
    (9.6, 15.25), (9, 15.25));
var i: Integer;
begin
  SetLength(body, 22);
  for i := 0 to 21 do body[i] := Vertexf(B[i, 0], B[i, 1], 0);
  SetLength(arm, 16);
  for i := 0 to 15 do arm[i] := Vertexf(A[i, 0], A[i, 1], 0);
  SetLength(leg, 14);
  for i := 0 to 13 do leg[i] := Vertexf(L[i, 0], L[i, 1], 0);
  SetLength(eye, 6);
  for i := 0 to 5 do eye[i] := Vertexf(E[i, 0], E[i, 1], 0);
end;

procedure extrudeSolidFromPolygon(data: array of TVertexf; dataSize: GLuint;
  thickness: GLdouble; side, edge, whole: GLuint);
var
  tobj: GLUtesselator;
  vertex: array[0..2] of GLdouble;
  i, count: LongInt;
begin
  count := dataSize;
  tobj := gluNewTess();
  gluTessCallback(tobj, GLU_TESS_BEGIN, @tessBegin);
  gluTessCallback(tobj, GLU_TESS_END, @tessEnd);
  gluTessCallback(tobj, GLU_TESS_VERTEX, @tessVertex);

  glNewList(side, GL_COMPILE);
    glShadeModel(GL_SMOOTH);
    gluTessBeginPolygon(tobj);
      gluTessBeginContour(tobj);
      for i := 0 to count do
      begin
        { one coordinate array reused for every vertex: GLU must copy it }
        vertex[0] := data[i, 0];
        vertex[1] := data[i, 1];
        vertex[2] := 0;
        gluTessVertex(tobj, @vertex, @data[i]);
      end;
      gluTessEndContour(tobj);
    gluTessEndPolygon(tobj);
  glEndList;

  glNewList(edge, GL_COMPILE);
    glShadeModel(GL_FLAT);
    glBegin(GL_QUAD_STRIP);
    for i := 0 to count do
    begin
      glVertex3f(data[i mod count, 0], data[i mod count, 1], 0.0);
      glVertex3f(data[i mod count, 0], data[i mod count, 1], thickness);
    end;
    glEnd;
  glEndList;

  glNewList(whole, GL_COMPILE);
    glFrontFace(GL_CW);
    glCallList(edge);
    glNormal3f(0.0, 0.0, -1.0);
    glCallList(side);
    glPushMatrix;
      glTranslatef(0.0, 0.0, thickness);
      glFrontFace(GL_CCW);
      glNormal3f(0.0, 0.0, 1.0);
      glCallList(side);
    glPopMatrix;
  glEndList;
end;

procedure makeDinosaur;
begin
  extrudeSolidFromPolygon(body, High(body), bodyWidth,
    Ord(BODY_SIDE), Ord(BODY_EDGE), Ord(BODY_WHOLE));
  extrudeSolidFromPolygon(arm, High(arm), bodyWidth / 4,
    Ord(ARM_SIDE), Ord(ARM_EDGE), Ord(ARM_WHOLE));
  extrudeSolidFromPolygon(leg, High(leg), bodyWidth / 2,
    Ord(LEG_SIDE), Ord(LEG_EDGE), Ord(LEG_WHOLE));
  extrudeSolidFromPolygon(eye, High(eye), bodyWidth + 0.2,
    Ord(EYE_SIDE), Ord(EYE_EDGE), Ord(EYE_WHOLE));
end;

procedure drawDinosaur;
begin
  glPushMatrix;
    glTranslatef(0.0, jump, 0.0);
    glMaterialfv(GL_FRONT, GL_DIFFUSE, @skinColor);
    glCallList(Ord(BODY_WHOLE));
    glPushMatrix;
      glTranslatef(0.0, 0.0, bodyWidth);
      glCallList(Ord(ARM_WHOLE));
      glCallList(Ord(LEG_WHOLE));
      glTranslatef(0.0, 0.0, -bodyWidth - bodyWidth / 4);
      glCallList(Ord(ARM_WHOLE));
      glTranslatef(0.0, 0.0, -bodyWidth / 4);
      glCallList(Ord(LEG_WHOLE));
      glTranslatef(0.0, 0.0, bodyWidth / 2 - 0.1);
      glMaterialfv(GL_FRONT, GL_DIFFUSE, @eyeColor);
      glCallList(Ord(EYE_WHOLE));
    glPopMatrix;
  glPopMatrix;
end;

procedure drawFloor;
begin
  glDisable(GL_LIGHTING);
  glBegin(GL_QUADS);
    glVertex3f(-18.0, 0.0, 27.0);
    glVertex3f(27.0, 0.0, 27.0);
    glVertex3f(27.0, 0.0, -18.0);
    glVertex3f(-18.0, 0.0, -18.0);
  glEnd;
  glEnable(GL_LIGHTING);
end;

procedure redraw;
begin
  if useStencil then
    glClear(GL_COLOR_BUFFER_BIT or GL_DEPTH_BUFFER_BIT or GL_STENCIL_BUFFER_BIT)
  else
    glClear(GL_COLOR_BUFFER_BIT or GL_DEPTH_BUFFER_BIT);

  glPushMatrix;
    glRotatef(angle2, 1.0, 0.0, 0.0);
    glRotatef(angle, 0.0, 1.0, 0.0);
    glTranslatef(-8, -8, -bodyWidth / 2);   { centre the dinosaur }
    glLightfv(GL_LIGHT0, GL_POSITION, @lightZeroPosition);
    glLightfv(GL_LIGHT1, GL_POSITION, @lightOnePosition);

    if useStencil then
    begin
      { the floor into the stencil buffer only: 1 where it covers }
      glDisable(GL_DEPTH_TEST);
      glColorMask(GL_FALSE, GL_FALSE, GL_FALSE, GL_FALSE);
      glEnable(GL_STENCIL_TEST);
      glStencilOp(GL_REPLACE, GL_REPLACE, GL_REPLACE);
      glStencilFunc(GL_ALWAYS, 1, $ffffffff);
      drawFloor;
      glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
      glEnable(GL_DEPTH_TEST);
      { the reflection only where the floor is }
      glStencilFunc(GL_EQUAL, 1, $ffffffff);
      glStencilOp(GL_KEEP, GL_KEEP, GL_KEEP);
    end;

    glPushMatrix;
      { the mirror image: the scale turns faces inside out, so cull the
        front, and renormalize the scaled normals }
      glScalef(1.0, -1.0, 1.0);
      glLightfv(GL_LIGHT0, GL_POSITION, @lightZeroPosition);
      glLightfv(GL_LIGHT1, GL_POSITION, @lightOnePosition);
      glEnable(GL_NORMALIZE);
      glCullFace(GL_FRONT);
      drawDinosaur;
      glDisable(GL_NORMALIZE);
      glCullFace(GL_BACK);
    glPopMatrix;

    glLightfv(GL_LIGHT0, GL_POSITION, @lightZeroPosition);
    glLightfv(GL_LIGHT1, GL_POSITION, @lightOnePosition);
    if useStencil then glDisable(GL_STENCIL_TEST);

    { the floor's top, translucent red over the reflection }
    glEnable(GL_BLEND);
    glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
    glColor4f(0.7, 0.0, 0.0, 0.3);
    drawFloor;
    glDisable(GL_BLEND);

    { the floor's bottom, opaque blue, seen from below }
    glFrontFace(GL_CW);
    glColor4f(0.1, 0.1, 0.7, 1.0);
    drawFloor;
    glFrontFace(GL_CCW);

    drawDinosaur;
  glPopMatrix;
  SwapBuffers(f_Hdc);
end;

procedure controlLights(value: LongInt);
begin
  if value = 1 then
  begin
    lightZeroSwitch := not lightZeroSwitch;
    if lightZeroSwitch then glEnable(GL_LIGHT0) else glDisable(GL_LIGHT0);
  end;
  if value = 2 then
  begin
    lightOneSwitch := not lightOneSwitch;
    if lightOneSwitch then glEnable(GL_LIGHT1) else glDisable(GL_LIGHT1);
  end;
  if value = 3 then
    useStencil := not useStencil;
end;

procedure initGL;
begin
  InitVariables;
  redraw;            { before the lists and the projection exist, as the book }
  makeDinosaur;
  glEnable(GL_CULL_FACE);
  glEnable(GL_DEPTH_TEST);
  glEnable(GL_LIGHTING);
  glMatrixMode(GL_PROJECTION);
  glEnable(GL_NORMALIZE);
  gluPerspective(40.0, 1.0, 1.0, 80.0);
  glMatrixMode(GL_MODELVIEW);
  gluLookAt(0.0, 0.0, 40.0, 0.0, 0.0, 0.0, 0.0, 1.0, 0.0);
  glLightModeli(GL_LIGHT_MODEL_LOCAL_VIEWER, 1);
  glLightfv(GL_LIGHT0, GL_DIFFUSE, @lightZeroColor);
  glLightf(GL_LIGHT0, GL_CONSTANT_ATTENUATION, 0.1);
  glLightf(GL_LIGHT0, GL_LINEAR_ATTENUATION, 0.05);
  glLightfv(GL_LIGHT1, GL_DIFFUSE, @lightOneColor);
  glEnable(GL_LIGHT0);
  glLightfv(GL_LIGHT0, GL_POSITION, @lightZeroPosition);
  glLightfv(GL_LIGHT1, GL_POSITION, @lightOnePosition);
  glViewport(0, 0, Form1.Width, Form1.Height);
end;

procedure TForm1.FormCreate(Sender: TObject);
begin
  f_Hdc := GetDC(Handle);
  SetDCPixelFormat(f_Hdc, 16, 16);
  initGL;
  DemoStart := GetTickCount;
  Application.OnIdle := Idle;
end;

procedure TForm1.Idle(Sender: TObject; var Done: Boolean);
begin
  if not moving then
  begin
    ElapsedTime := GetTickCount - DemoStart;
    ElapsedTime := (ElapsedTime + LastTime) div 2;   { smooth the steps }
    LastTime := ElapsedTime;
    jump := 6.0 * Abs(Sin(ElapsedTime / 8));
    InvalidateRect(Handle, nil, False);
  end;
  Done := False;
end;

procedure TForm1.FormMouseDown(Sender: TObject; Button: TMouseButton;
  Shift: TShiftState; X, Y: Integer);
begin
  if Button = mbLeft then
  begin
    moving := GL_TRUE;
    startx := X;
    starty := Y;
  end;
end;

procedure TForm1.FormMouseUp(Sender: TObject; Button: TMouseButton;
  Shift: TShiftState; X, Y: Integer);
begin
  if Button = mbLeft then moving := GL_FALSE;
end;

procedure TForm1.FormMouseMove(Sender: TObject; Shift: TShiftState; X, Y: Integer);
begin
  if moving then
  begin
    angle := angle + (X - startx);
    angle2 := angle2 + (Y - starty);
    startx := X;
    starty := Y;
    InvalidateRect(Handle, nil, False);
  end;
end;

procedure TForm1.FormResize(Sender: TObject);
begin
  wglMakeCurrent(f_Hdc, hrc);
  glViewport(0, 0, Width, Height);
  InvalidateRect(Handle, nil, False);
end;

procedure TForm1.FormPaint(Sender: TObject);
begin
  wglMakeCurrent(f_Hdc, hrc);
  redraw;
end;

procedure TForm1.FormKeyPress(Sender: TObject; var Key: Char);
begin
  if Key = '4' then
  begin
    wire := not wire;
    if wire then glPolygonMode(GL_FRONT_AND_BACK, GL_LINE)
    else glPolygonMode(GL_FRONT_AND_BACK, GL_FILL);
  end;
  controlLights(StrToInt(Key));
  InvalidateRect(Handle, nil, False);
end;

procedure TForm1.FormDestroy(Sender: TObject);
begin
  CleanUp(f_Hdc);
end;

end.
