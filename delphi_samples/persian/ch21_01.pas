{ ch21_01.pas -- the winding-rule tessellation demo of the Persian book's
  chapter 21, first program (S0:715-1104; seeds-inventory §3.1), itself a
  port of the Red Book's tesswind: four shapes tessellated into display
  lists, one per quadrant, filled white on black with the current winding
  rule.  Written here in the book's Delphi style: a form unit with
  FormCreate / FormResize / FormPaint / FormKeyPress, stdcall tessellator
  callbacks, the Borland-style OpenGL unit and the helper unit SPF.

  Kept from the book, because softgl must cope with them:
  - gluTessBeginPolygon(tobj) with one argument (Borland's declaration);
  - gluTessProperty(tobj, GLU_TESS_WINDING_RULE, ...) with Borland's wrong
    constant 100110: GLU answers GLU_INVALID_ENUM and keeps ODD;
  - keyboard() as five plain `if`s: each key press runs through every rule
    and ends on ODD again (the C original uses `else if`);
  - the viewport from the outer Width/Height of the form.
  - the combine callback's dynamic-array parameters (`coords: my_arr`,
    `var dataOut: my_arr`), which make the compiled code count references
    in a header before GLU's coordinates.
  Changed: the error callback is registered (the book comments it out) so
  the INVALID_ENUM is seen; the combine callback allocates three doubles
  (the book's SetLength(vertex, 2) writes past the end).

  For the other rules the driver can switch to GLU's real property value
  (WindingProperty) and to the C original's `else if` keyboard
  (FixedKeyboard). }
unit ch21_01;

{$mode delphi}

interface

uses
  Windows, SysUtils, Forms, OpenGL, SPF;

type
  TForm1 = class(TForm)
    procedure FormCreate(Sender: TObject);
    procedure FormResize(Sender: TObject);
    procedure FormPaint(Sender: TObject);
    procedure FormKeyPress(Sender: TObject; var Key: Char);
    procedure FormClose(Sender: TObject; var Action: TCloseAction);
    procedure FormDestroy(Sender: TObject);
  public
    constructor Create(AOwner: TComponent); override;
  end;

procedure gluNextContour(tess: GLUtesselator; atype: GLenum); stdcall; external glu32;

const
  GLU_CW = 100120;          { missing from Borland's unit: obsolete GLU 1.1 }
  GLU_CCW = 100121;
  GLU_INTERIOR = 100122;
  GLU_EXTERIOR = 100123;
  GLU_UNKNOWN = 100124;

var
  Form1: TForm1;
  currentWinding: GLdouble = GLU_TESS_WINDING_ODD;
  { driver switches (not in the book) }
  WindingProperty: GLenum = GLU_TESS_WINDING_RULE;   { Borland's 100110 }
  FixedKeyboard: Boolean = False;
  TessErrors: Integer = 0;
  LastTessError: GLenum = 0;
  CombineCount: Integer = 0;
  CombineHigh: Integer = -99;

implementation

var
  tobj: GLUtesselator;
  list: GLuint;
  f_Hdc: LongInt;

  rects: array[0..11] of array[0..2] of GLdouble = (
    (50, 50, 0), (300, 50, 0), (300, 300, 0), (50, 300, 0),
    (100, 100, 0), (250, 100, 0), (250, 250, 0), (100, 250, 0),
    (150, 150, 0), (200, 150, 0), (200, 200, 0), (150, 200, 0));
  spiral: array[0..15] of array[0..2] of GLdouble = (
    (400, 250, 0), (400, 50, 0), (50, 50, 0), (50, 400, 0),
    (350, 400, 0), (350, 100, 0), (100, 100, 0), (100, 350, 0),
    (300, 350, 0), (300, 150, 0), (150, 150, 0), (150, 300, 0),
    (250, 300, 0), (250, 200, 0), (200, 200, 0), (200, 250, 0));
  quad1: array[0..3] of array[0..2] of GLdouble = (
    (50, 150, 0), (350, 150, 0), (350, 200, 0), (50, 200, 0));
  quad2: array[0..3] of array[0..2] of GLdouble = (
    (100, 100, 0), (300, 100, 0), (300, 350, 0), (100, 350, 0));
  tri: array[0..2] of array[0..2] of GLdouble = (
    (200, 50, 0), (250, 300, 0), (150, 300, 0));

type
  my_arr = array of GLdouble;

constructor TForm1.Create(AOwner: TComponent);
begin
  inherited;
  { what Unit1.dfm would hold }
  ClientWidth := 500;
  ClientHeight := 500;
  Caption := 'Winding rules';
  OnCreate := FormCreate;
  OnResize := FormResize;
  OnPaint := FormPaint;
  OnKeyPress := FormKeyPress;
  OnClose := FormClose;
  OnDestroy := FormDestroy;
end;

procedure errorCallback(errorCode: GLenum); stdcall;
begin
  Inc(TessErrors);
  LastTessError := errorCode;
  case errorCode of
    GLU_TESS_MISSING_BEGIN_POLYGON: MessageBox(0, 'GLU_TESS_MISSING_BEGIN_POLYGON', 'error..', MB_OK);
    GLU_TESS_MISSING_END_POLYGON: MessageBox(0, 'GLU_TESS_MISSING_END_POLYGON', 'error..', MB_OK);
    GLU_TESS_MISSING_BEGIN_CONTOUR: MessageBox(0, 'GLU_TESS_MISSING_BEGIN_CONTOUR', 'error..', MB_OK);
    GLU_TESS_MISSING_END_CONTOUR: MessageBox(0, 'GLU_TESS_MISSING_END_CONTOUR', 'error..', MB_OK);
    GLU_TESS_COORD_TOO_LARGE: MessageBox(0, 'GLU_TESS_COORD_TOO_LARGE', 'error..', MB_OK);
    GLU_TESS_NEED_COMBINE_CALLBACK: MessageBox(0, 'GLU_TESS_NEED_COMBINE_CALLBACK', 'error..', MB_OK);
  end;
  MessageBox(0, gluErrorString(errorCode), 'error..', MB_OK);
end;

procedure beginCallback(which: GLenum); stdcall;
begin
  glBegin(which);
end;

procedure endCallback; stdcall;
begin
  glEnd;
end;

procedure tessVertex(data: Pointer); stdcall;
begin
  glVertex3dv(data);
end;

{ A new vertex where edges cross.  As in the book, coords and dataOut are
  Pascal dynamic arrays: the compiled callback adds a reference to coords'
  header and assigning dataOut drops one from the old value, so GLU must
  hand over coords behind a valid-looking header and dataOut as nil.  The
  vertices are never freed, as in the book. }
procedure combineCallback(coords: my_arr; var vdata: Pointer;
  weight: Pointer; var dataOut: my_arr); stdcall;
var
  vertex: my_arr;
begin
  Inc(CombineCount);
  CombineHigh := High(coords);
  SetLength(vertex, 3);      { the book allocates 2 and writes 3 }
  vertex[0] := coords[0];
  vertex[1] := coords[1];
  vertex[2] := coords[2];
  dataOut := vertex;
end;

procedure makeNewLists;
var
  i: Integer;
begin
  gluTessProperty(tobj, WindingProperty, currentWinding);

  glNewList(list, GL_COMPILE);        { three nested squares, all CCW }
    gluTessBeginPolygon(tobj);
      gluTessBeginContour(tobj);
      for i := 0 to 3 do gluTessVertex(tobj, @rects[i], @rects[i]);
      gluTessEndContour(tobj);
      gluTessBeginContour(tobj);
      for i := 4 to 7 do gluTessVertex(tobj, @rects[i], @rects[i]);
      gluTessEndContour(tobj);
      gluTessBeginContour(tobj);
      for i := 8 to 11 do gluTessVertex(tobj, @rects[i], @rects[i]);
      gluTessEndContour(tobj);
    gluTessEndPolygon(tobj);
  glEndList;

  glNewList(list + 1, GL_COMPILE);    { the same, inner two reversed }
    gluTessBeginPolygon(tobj);
      gluTessBeginContour(tobj);
      for i := 0 to 3 do gluTessVertex(tobj, @rects[i], @rects[i]);
      gluTessEndContour(tobj);
      gluTessBeginContour(tobj);
      for i := 7 downto 4 do gluTessVertex(tobj, @rects[i], @rects[i]);
      gluTessEndContour(tobj);
      gluTessBeginContour(tobj);
      for i := 11 downto 8 do gluTessVertex(tobj, @rects[i], @rects[i]);
      gluTessEndContour(tobj);
    gluTessEndPolygon(tobj);
  glEndList;

  glNewList(list + 2, GL_COMPILE);    { a clockwise spiral, one contour }
    gluTessBeginPolygon(tobj);
      gluTessBeginContour(tobj);
      for i := 0 to 15 do gluTessVertex(tobj, @spiral[i], @spiral[i]);
      gluTessEndContour(tobj);
    gluTessEndPolygon(tobj);
  glEndList;

  glNewList(list + 3, GL_COMPILE);    { two quads and a triangle overlapping }
    gluTessBeginPolygon(tobj);
      gluTessBeginContour(tobj);
      for i := 0 to 3 do gluTessVertex(tobj, @quad1[i], @quad1[i]);
      gluTessEndContour(tobj);
      gluTessBeginContour(tobj);
      for i := 0 to 3 do gluTessVertex(tobj, @quad2[i], @quad2[i]);
      gluTessEndContour(tobj);
      gluTessBeginContour(tobj);
      for i := 0 to 2 do gluTessVertex(tobj, @tri[i], @tri[i]);
      gluTessEndContour(tobj);
    gluTessEndPolygon(tobj);
  glEndList;
end;

procedure display;
begin
  glClear(GL_COLOR_BUFFER_BIT);
  glColor3f(1.0, 1.0, 1.0);
  glPushMatrix;
    glCallList(list);
    glTranslatef(0.0, 500.0, 0.0);
    glCallList(list + 1);
    glTranslatef(500.0, -500.0, 0.0);
    glCallList(list + 2);
    glTranslatef(0.0, 500.0, 0.0);
    glCallList(list + 3);
  glPopMatrix;
  SwapBuffers(f_Hdc);
end;

procedure initGL;
begin
  glClearColor(0.0, 0.0, 0.0, 0.0);
  glShadeModel(GL_FLAT);
  tobj := gluNewTess();
  gluTessCallback(tobj, GLU_TESS_BEGIN, @beginCallback);
  gluTessCallback(tobj, GLU_TESS_END, @endCallback);
  gluTessCallback(tobj, GLU_TESS_VERTEX, @tessVertex);
  gluTessCallback(tobj, GLU_TESS_COMBINE, @combineCallback);
  gluTessCallback(tobj, GLU_TESS_ERROR, @errorCallback);
  list := glGenLists(4);
  makeNewLists;
end;

procedure reshape(w, h: Integer);
begin
  glViewport(0, 0, w, h);
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity;
  if w <= h then
    gluOrtho2D(0.0, 1000.0, 0.0, 1000.0 * h / w)
  else
    gluOrtho2D(0.0, 1000.0 * w / h, 0.0, 1000.0);
  glMatrixMode(GL_MODELVIEW);
  glLoadIdentity;
end;

procedure keyboard(key: Char);
begin
  if FixedKeyboard then
  begin
    { the C original: one step per key }
    if currentWinding = GLU_TESS_WINDING_ODD then currentWinding := GLU_TESS_WINDING_NONZERO
    else if currentWinding = GLU_TESS_WINDING_NONZERO then currentWinding := GLU_TESS_WINDING_POSITIVE
    else if currentWinding = GLU_TESS_WINDING_POSITIVE then currentWinding := GLU_TESS_WINDING_NEGATIVE
    else if currentWinding = GLU_TESS_WINDING_NEGATIVE then currentWinding := GLU_TESS_WINDING_ABS_GEQ_TWO
    else if currentWinding = GLU_TESS_WINDING_ABS_GEQ_TWO then currentWinding := GLU_TESS_WINDING_ODD;
  end
  else
  begin
    { the book: no `else`, so the chain runs through to ODD every time }
    if currentWinding = GLU_TESS_WINDING_ODD then
    begin
      currentWinding := GLU_TESS_WINDING_NONZERO;
      Form1.Caption := 'GLU_TESS_WINDING_NONZERO';
    end;
    if currentWinding = GLU_TESS_WINDING_NONZERO then
    begin
      currentWinding := GLU_TESS_WINDING_POSITIVE;
      Form1.Caption := 'GLU_TESS_WINDING_POSITIVE';
    end;
    if currentWinding = GLU_TESS_WINDING_POSITIVE then
    begin
      currentWinding := GLU_TESS_WINDING_NEGATIVE;
      Form1.Caption := 'GLU_TESS_WINDING_NEGATIVE';
    end;
    if currentWinding = GLU_TESS_WINDING_NEGATIVE then
    begin
      currentWinding := GLU_TESS_WINDING_ABS_GEQ_TWO;
      Form1.Caption := 'GLU_TESS_WINDING_ABS_GEQ_TWO';
    end;
    if currentWinding = GLU_TESS_WINDING_ABS_GEQ_TWO then
    begin
      currentWinding := GLU_TESS_WINDING_ODD;
      Form1.Caption := 'GLU_TESS_WINDING_ODD';
    end;
  end;
  makeNewLists;
end;

procedure TForm1.FormCreate(Sender: TObject);
begin
  f_Hdc := GetDC(Handle);
  SetDCPixelFormat(f_Hdc, 16, 16);
  initGL;
end;

procedure TForm1.FormResize(Sender: TObject);
begin
  wglMakeCurrent(f_Hdc, hrc);
  reshape(Width, Height);
  InvalidateRect(Handle, nil, False);
end;

procedure TForm1.FormPaint(Sender: TObject);
begin
  wglMakeCurrent(f_Hdc, hrc);
  display;
end;

procedure TForm1.FormKeyPress(Sender: TObject; var Key: Char);
begin
  keyboard(Key);
  InvalidateRect(Handle, nil, False);
end;

procedure TForm1.FormClose(Sender: TObject; var Action: TCloseAction);
begin
  gluDeleteTess(tobj);
end;

procedure TForm1.FormDestroy(Sender: TObject);
begin
  CleanUp(f_Hdc);
end;

end.
