{ frmMain.pas -- stencil decals, after Krasnov's "OpenGL. Графика в
  проектах Delphi", project Ex72 (seed S2; seeds-inventory §3.4), itself a
  port of Grantham's decal.c: an airplane over an airfield.  The ground is
  the base polygon (stencil 0 where visible, 4 where the airplane hides
  it), the runway asphalt, its yellow stripes and the airplane's blended
  shadow are decals 1, 2, 3 drawn with the depth test off where
  decal > stencil, so coplanar layers never z-fight and the shadow is
  blended once per pixel.  Keys 1-6 stop the frame after a stage; the
  popup menu (here methods the driver calls) switches the stencil decals
  and shows the colour, stencil (a palette per value) or depth (inverted,
  normalised) buffer.

  Written here in Krasnov's style: a WMPaint message handler with
  BeginPaint/EndPaint and goto doneWithFrame, a zero-filled pixel format
  descriptor that asks for no depth or stencil (softgl gives both anyway),
  glClearStencil(5), glNormal3i(0,1,0) for the ground (a tiny normal that
  GL_NORMALIZE rescues), the depth and stencil read back with
  glReadPixels and drawn again with glDrawPixels into GL_BACK after
  saving GL_DRAW_BUFFER.  The airplane's shape is ours (the seed does not
  print drawAirplane): quadrics as the inventory lists them. }
unit frmMain;

{$mode delphi}

interface

uses
  SysUtils, Windows, Messages, Forms, OpenGL;

const
  winWidth = 400;
  winHeight = 400;

type
  TDataChoice = (DCOLOR, DEPTH, STENCIL);

  TfrmGL = class(TForm)
    procedure FormCreate(Sender: TObject);
    procedure FormDestroy(Sender: TObject);
    procedure FormKeyPress(Sender: TObject; var Key: Char);
  private
    DC: HDC;
    hrc: HGLRC;
    quadric: GLUquadricObj;
    procedure Init;
    procedure SetDCPixelFormat;
    procedure setupLight;
    procedure setupNormalDrawingState;
    procedure setupBasePolygonState(maxDecal: GLint);
    procedure setupDecalState(decalNum: GLint);
    procedure drawAirplane;
    procedure drawGround;
    procedure drawAsphalt;
    procedure drawStripes;
    procedure pushOrthoView(left, right, bottom, top, znear, zfar: GLdouble);
    procedure popView;
    procedure copyDepthToColor(whichColorBuffer: GLenum);
    procedure copyStencilToColor(whichColorBuffer: GLenum);
  protected
    procedure WMPaint(var Msg: TWMPaint); message WM_PAINT;
  public
    stage: Integer;
    dataChoice: TDataChoice;
    useStencil: Boolean;
    constructor Create(AOwner: TComponent); override;
    { the popup menu's items }
    procedure miStencilDecalsClick(Sender: TObject);
    procedure miColorClick(Sender: TObject);
    procedure miStencilClick(Sender: TObject);
    procedure miDepthClick(Sender: TObject);
  end;

var
  frmGL: TfrmGL;

implementation

const
  { a colour per stencil value (mod 7), so that small values can be told apart }
  colors: array[0..6, 0..2] of Byte = (
    (255, 0, 0),     { red }
    (255, 218, 0),   { yellow }
    (72, 255, 0),    { yellowish green }
    (0, 255, 145),   { bluish cyan }
    (0, 145, 255),   { cyanish blue }
    (72, 0, 255),    { purplish blue }
    (255, 0, 218));  { reddish purple }

var
  depthSave: array[0..winWidth * winHeight - 1] of GLfloat;
  stencilSave: array[0..winWidth * winHeight - 1] of GLubyte;
  colorSave: array[0..winWidth * winHeight * 3 - 1] of GLubyte;

constructor TfrmGL.Create(AOwner: TComponent);
begin
  inherited;
  ClientWidth := winWidth;     { BorderStyle = bsSingle: not resizable }
  ClientHeight := winHeight;
  Caption := 'Stencil decals';
  OnCreate := FormCreate;
  OnDestroy := FormDestroy;
  OnKeyPress := FormKeyPress;
  stage := 6;
  dataChoice := DCOLOR;
  useStencil := True;
end;

procedure TfrmGL.SetDCPixelFormat;
var
  pfd: TPixelFormatDescriptor;
  nPixelFormat: Integer;
begin
  FillChar(pfd, SizeOf(pfd), 0);
  pfd.dwFlags := PFD_DRAW_TO_WINDOW or PFD_SUPPORT_OPENGL or PFD_DOUBLEBUFFER;
  nPixelFormat := ChoosePixelFormat(DC, @pfd);
  SetPixelFormat(DC, nPixelFormat, @pfd);
end;

procedure TfrmGL.Init;
begin
  glEnable(GL_DEPTH_TEST);
  glEnable(GL_CULL_FACE);
  glCullFace(GL_BACK);
  quadric := gluNewQuadric;
  glMatrixMode(GL_PROJECTION);
  glFrustum(-0.33, 0.33, -0.33, 0.33, 0.5, 40.0);
  glMatrixMode(GL_MODELVIEW);
  gluLookAt(-4, 10, 6, 0, 0, 0, 0, 1, 0);
  glEnable(GL_LIGHTING);
  glEnable(GL_LIGHT0);
  glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
  glEnable(GL_NORMALIZE);
  glClearStencil(5);
end;

procedure TfrmGL.FormCreate(Sender: TObject);
begin
  DC := GetDC(Handle);
  SetDCPixelFormat;
  hrc := wglCreateContext(DC);
  wglMakeCurrent(DC, hrc);
  Init;
end;

procedure TfrmGL.FormDestroy(Sender: TObject);
begin
  gluDeleteQuadric(quadric);
  wglMakeCurrent(0, 0);
  wglDeleteContext(hrc);
  ReleaseDC(Handle, DC);
  DeleteDC(DC);
end;

procedure TfrmGL.setupLight;
const
  lightpos: array[0..3] of GLfloat = (0, 1, 0, 0);   { straight down }
begin
  glLightfv(GL_LIGHT0, GL_POSITION, @lightpos);
end;

procedure TfrmGL.setupNormalDrawingState;
begin
  glDisable(GL_STENCIL_TEST);
  glEnable(GL_DEPTH_TEST);
  glDepthMask(TRUE);
end;

procedure TfrmGL.setupBasePolygonState(maxDecal: GLint);
begin
  glEnable(GL_DEPTH_TEST);
  if useStencil then
  begin
    glEnable(GL_STENCIL_TEST);
    glStencilFunc(GL_ALWAYS, maxDecal + 1, $ff);   { always drawn }
    glStencilOp(GL_KEEP, GL_REPLACE, GL_ZERO);      { hidden: maxDecal+1, seen: 0 }
  end;
end;

procedure TfrmGL.setupDecalState(decalNum: GLint);
begin
  if useStencil then
  begin
    glDisable(GL_DEPTH_TEST);
    glDepthMask(FALSE);
    glEnable(GL_STENCIL_TEST);
    glStencilFunc(GL_GREATER, decalNum, $ff);       { where decalNum > stencil }
    glStencilOp(GL_KEEP, GL_KEEP, GL_REPLACE);
  end;
end;

procedure material(r, g, b: GLfloat);
var c: array[0..3] of GLfloat;
begin
  c[0] := r; c[1] := g; c[2] := b; c[3] := 1;
  glMaterialfv(GL_FRONT_AND_BACK, GL_AMBIENT_AND_DIFFUSE, @c);
end;

procedure TfrmGL.drawAirplane;
begin
  material(0.75, 0.75, 0.75);
  glDisable(GL_CULL_FACE);
  glPushMatrix;
    glTranslatef(0, 0, -2.5);
    gluCylinder(quadric, 0.5, 0.5, 5, 10, 10);       { fuselage }
    glPushMatrix;
      glTranslatef(0, 0, 5);
      gluCylinder(quadric, 0.5, 0, 1, 10, 10);       { nose cone }
    glPopMatrix;
    glPushMatrix;
      glTranslatef(0, 0, 3);
      glScalef(3, 0.1, 1);
      gluSphere(quadric, 1, 10, 10);                 { wings }
    glPopMatrix;
    glPushMatrix;
      glTranslatef(0, 0, 0.5);
      glScalef(2, 0.1, 0.5);
      gluSphere(quadric, 1, 10, 10);                 { tail plane }
    glPopMatrix;
    glEnable(GL_CULL_FACE);
    glBegin(GL_TRIANGLES);                           { fin, both sides }
      glNormal3f(1, 0, 0);
      glVertex3f(0, 0.5, 0); glVertex3f(0, 1.5, 0); glVertex3f(0, 0.5, 1.5);
      glNormal3f(-1, 0, 0);
      glVertex3f(0, 0.5, 0); glVertex3f(0, 0.5, 1.5); glVertex3f(0, 1.5, 0);
    glEnd;
    glDisable(GL_CULL_FACE);
    glPushMatrix;
      glRotatef(180, 0, 1, 0);
      gluDisk(quadric, 0, 0.5, 10, 10);              { tail end of the fuselage }
    glPopMatrix;
  glPopMatrix;
  glEnable(GL_CULL_FACE);
end;

procedure TfrmGL.drawGround;
begin
  material(0.647, 0.165, 0.165);                     { brown }
  glNormal3i(0, 1, 0);    { 1/(2^31-1) after conversion: GL_NORMALIZE fixes it }
  glBegin(GL_QUADS);
    glVertex3f(-10, 0, 10); glVertex3f(10, 0, 10);
    glVertex3f(10, 0, -10); glVertex3f(-10, 0, -10);
  glEnd;
end;

procedure TfrmGL.drawAsphalt;
begin
  material(0.25, 0.25, 0.25);
  glNormal3f(0, 1, 0);
  glBegin(GL_QUADS);
    glVertex3f(-5, 0, 9.5); glVertex3f(5, 0, 9.5);
    glVertex3f(5, 0, -9.5); glVertex3f(-5, 0, -9.5);
  glEnd;
end;

procedure TfrmGL.drawStripes;
const
  gap = 0.66;
var
  i: Integer;
  len, z: GLfloat;
begin
  material(1, 1, 0);
  glNormal3f(0, 1, 0);
  glBegin(GL_QUADS);
    { the side lines }
    glVertex3f(-4.5, 0, 8.5); glVertex3f(-3.5, 0, 8.5);
    glVertex3f(-3.5, 0, -8.5); glVertex3f(-4.5, 0, -8.5);
    glVertex3f(3.5, 0, 8.5); glVertex3f(4.5, 0, 8.5);
    glVertex3f(4.5, 0, -8.5); glVertex3f(3.5, 0, -8.5);
    { five dashes down the middle }
    len := (16 - gap * 4) / 5;
    for i := 0 to 4 do
    begin
      z := -8 + i * (len + gap);
      glVertex3f(-0.25, 0, z + len); glVertex3f(0.25, 0, z + len);
      glVertex3f(0.25, 0, z); glVertex3f(-0.25, 0, z);
    end;
  glEnd;
end;

procedure TfrmGL.pushOrthoView(left, right, bottom, top, znear, zfar: GLdouble);
begin
  glPushMatrix;
  glLoadIdentity;
  glMatrixMode(GL_PROJECTION);
  glPushMatrix;
  glLoadIdentity;
  glOrtho(left, right, bottom, top, znear, zfar);
end;

procedure TfrmGL.popView;
begin
  glPopMatrix;
  glMatrixMode(GL_MODELVIEW);
  glPopMatrix;
end;

procedure TfrmGL.copyDepthToColor(whichColorBuffer: GLenum);
var
  x, y: GLint;
  max, min: GLfloat;
  previousColorBuffer: GLint;
begin
  glReadPixels(0, 0, winWidth, winHeight, GL_DEPTH_COMPONENT, GL_FLOAT, @depthSave);
  { stretch the objects' depths over 0..1 and invert: near is white,
    the background (1.0) black }
  max := 0;
  min := 1;
  for y := 0 to winHeight - 1 do
    for x := 0 to winWidth - 1 do
    begin
      if depthSave[winWidth * y + x] < min then min := depthSave[winWidth * y + x];
      if (depthSave[winWidth * y + x] > max) and (depthSave[winWidth * y + x] < 0.999) then
        max := depthSave[winWidth * y + x];
    end;
  for y := 0 to winHeight - 1 do
    for x := 0 to winWidth - 1 do
      if depthSave[winWidth * y + x] <= max then
        depthSave[winWidth * y + x] := 1 - (depthSave[winWidth * y + x] - min) / (max - min)
      else
        depthSave[winWidth * y + x] := 0;

  pushOrthoView(0, 1, 0, 1, 0, 1);
  glRasterPos3f(0, 0, -0.5);
  glDisable(GL_DEPTH_TEST);
  glDisable(GL_STENCIL_TEST);
  glColorMask(TRUE, TRUE, TRUE, TRUE);
  glGetIntegerv(GL_DRAW_BUFFER, @previousColorBuffer);
  glDrawBuffer(whichColorBuffer);
  glDrawPixels(winWidth, winHeight, GL_LUMINANCE, GL_FLOAT, @depthSave);
  glDrawBuffer(previousColorBuffer);
  glEnable(GL_DEPTH_TEST);
  popView;
end;

procedure TfrmGL.copyStencilToColor(whichColorBuffer: GLenum);
var
  x, y: GLint;
  previousColorBuffer: GLint;
  stencilValue: GLint;
begin
  glReadPixels(0, 0, winWidth, winHeight, GL_STENCIL_INDEX, GL_UNSIGNED_BYTE, @stencilSave);
  for y := 0 to winHeight - 1 do
    for x := 0 to winWidth - 1 do
    begin
      stencilValue := stencilSave[winWidth * y + x];
      colorSave[(winWidth * y + x) * 3 + 0] := colors[stencilValue mod 7][0];
      colorSave[(winWidth * y + x) * 3 + 1] := colors[stencilValue mod 7][1];
      colorSave[(winWidth * y + x) * 3 + 2] := colors[stencilValue mod 7][2];
    end;
  pushOrthoView(0, 1, 0, 1, 0, 1);
  glRasterPos3f(0, 0, -0.5);
  glDisable(GL_DEPTH_TEST);
  glDisable(GL_STENCIL_TEST);
  glColorMask(TRUE, TRUE, TRUE, TRUE);
  glGetIntegerv(GL_DRAW_BUFFER, @previousColorBuffer);
  glDrawBuffer(whichColorBuffer);
  glDrawPixels(winWidth, winHeight, GL_RGB, GL_UNSIGNED_BYTE, @colorSave);
  glDrawBuffer(previousColorBuffer);
  glEnable(GL_DEPTH_TEST);
  popView;
end;

procedure TfrmGL.WMPaint(var Msg: TWMPaint);
var
  ps: TPaintStruct;
label
  doneWithFrame;
begin
  BeginPaint(Handle, ps);
  glClear(GL_COLOR_BUFFER_BIT or GL_DEPTH_BUFFER_BIT);
  if dataChoice = STENCIL then glClear(GL_STENCIL_BUFFER_BIT);
  glPushMatrix;
  glScalef(0.5, 0.5, 0.5);
  if stage = 1 then goto doneWithFrame;
  setupLight;
  setupNormalDrawingState;
  glPushMatrix;
    glTranslatef(0, 1, 4);
    glRotatef(135, 0, 1, 0);
    drawAirplane;
  glPopMatrix;
  if stage = 2 then goto doneWithFrame;
  setupBasePolygonState(3);        { 3 decals on the ground }
  drawGround;
  if stage = 3 then goto doneWithFrame;
  setupDecalState(1);              { decal 1: the runway's asphalt }
  drawAsphalt;
  if stage = 4 then goto doneWithFrame;
  setupDecalState(2);              { decal 2: the yellow paint }
  drawStripes;
  if stage = 5 then goto doneWithFrame;
  setupDecalState(3);              { decal 3: the airplane's shadow }
  glDisable(GL_LIGHTING);
  glEnable(GL_BLEND);
  glPushMatrix;
    glColor4f(0, 0, 0, 0.5);
    glTranslatef(0, 0, 4);
    glRotatef(135, 0, 1, 0);
    glScalef(1, 0, 1);             { flattened onto the ground: singular }
    drawAirplane;
  glPopMatrix;
  glDisable(GL_BLEND);
  glEnable(GL_LIGHTING);
doneWithFrame:
  setupNormalDrawingState;
  glPopMatrix;
  if dataChoice = STENCIL then copyStencilToColor(GL_BACK);
  if dataChoice = DEPTH then copyDepthToColor(GL_BACK);
  SwapBuffers(DC);
  EndPaint(Handle, ps);
end;

procedure TfrmGL.FormKeyPress(Sender: TObject; var Key: Char);
begin
  if (Key >= '1') and (Key <= '6') then
  begin
    stage := Ord(Key) - Ord('0');
    InvalidateRect(Handle, nil, False);
  end;
end;

procedure TfrmGL.miStencilDecalsClick(Sender: TObject);
begin
  useStencil := not useStencil;
  InvalidateRect(Handle, nil, False);
end;

procedure TfrmGL.miColorClick(Sender: TObject);
begin
  dataChoice := DCOLOR;
  InvalidateRect(Handle, nil, False);
end;

procedure TfrmGL.miStencilClick(Sender: TObject);
begin
  dataChoice := STENCIL;
  InvalidateRect(Handle, nil, False);
end;

procedure TfrmGL.miDepthClick(Sender: TObject);
begin
  dataChoice := DEPTH;
  InvalidateRect(Handle, nil, False);
end;

end.
