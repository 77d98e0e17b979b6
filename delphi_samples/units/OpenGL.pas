{ OpenGL.pas -- a small Borland-style OpenGL unit: the declarations the
  Delphi 7 programs of the Persian book (chapter 21) and Krasnov's Ex72
  compile against, in the shape of Borland's OpenGL.pas: `stdcall;
  external opengl32` procedures, GLboolean = ByteBool, GLUtesselator a
  pointer.  Only what those programs call is declared.

  Borland's unit has two known defects, kept here on purpose so the
  programs behave as they did on Windows (seeds-inventory §2.17, §3.6):
  - gluTessBeginPolygon takes one argument (the real function takes two:
    the polygon_data pointer is then whatever is in the register);
  - GLU_TESS_WINDING_RULE / BOUNDARY_ONLY / TOLERANCE are 100110..100112,
    not GLU's 100140..100142: gluTessProperty with them is an invalid
    property, which GLU must report as GLU_INVALID_ENUM through the error
    callback, leaving the winding rule at ODD.
  The correct values are declared as GLU_TESS_WINDING_RULE_GLU etc. for
  the programs that need to set a rule for real.

  Its initialization masks floating-point exceptions, as Borland's does.

  On Linux opengl32 and glu32 are softgl (libGL.so, libGLU.so under
  build/lib); stdcall is the platform's C convention on x86-64. }
unit OpenGL;

{$mode delphi}

interface

const
  opengl32 = 'GL';
  glu32 = 'GLU';

type
  GLenum = Cardinal;
  GLboolean = ByteBool;
  GLbitfield = Cardinal;
  GLbyte = ShortInt;
  GLshort = SmallInt;
  GLint = Integer;
  GLsizei = Integer;
  GLubyte = Byte;
  GLushort = Word;
  GLuint = Cardinal;
  GLfloat = Single;
  GLclampf = Single;
  GLdouble = Double;
  GLclampd = Double;
  PGLfloat = ^GLfloat;
  PGLdouble = ^GLdouble;
  PGLint = ^GLint;
  PGLubyte = ^GLubyte;
  _GLUtesselator = record end;
  GLUtesselator = ^_GLUtesselator;
  _GLUquadricObj = record end;
  GLUquadricObj = ^_GLUquadricObj;

const
  GL_FALSE = False;
  GL_TRUE = True;

  GL_POINTS = $0000; GL_LINES = $0001; GL_LINE_LOOP = $0002; GL_LINE_STRIP = $0003;
  GL_TRIANGLES = $0004; GL_TRIANGLE_STRIP = $0005; GL_TRIANGLE_FAN = $0006;
  GL_QUADS = $0007; GL_QUAD_STRIP = $0008; GL_POLYGON = $0009;

  GL_DEPTH_BUFFER_BIT = $00000100; GL_STENCIL_BUFFER_BIT = $00000400;
  GL_COLOR_BUFFER_BIT = $00004000;

  GL_NEVER = $0200; GL_LESS = $0201; GL_EQUAL = $0202; GL_LEQUAL = $0203;
  GL_GREATER = $0204; GL_NOTEQUAL = $0205; GL_GEQUAL = $0206; GL_ALWAYS = $0207;

  GL_SRC_ALPHA = $0302; GL_ONE_MINUS_SRC_ALPHA = $0303;
  GL_FRONT = $0404; GL_BACK = $0405; GL_FRONT_AND_BACK = $0408;
  GL_CW = $0900; GL_CCW = $0901;

  GL_CULL_FACE = $0B44; GL_LIGHTING = $0B50; GL_DEPTH_TEST = $0B71;
  GL_STENCIL_TEST = $0B90; GL_NORMALIZE = $0BA1; GL_BLEND = $0BE2;
  GL_DRAW_BUFFER = $0C01; GL_VIEWPORT = $0BA2;
  GL_LIGHT_MODEL_LOCAL_VIEWER = $0B51;

  GL_AMBIENT = $1200; GL_DIFFUSE = $1201; GL_SPECULAR = $1202; GL_POSITION = $1203;
  GL_CONSTANT_ATTENUATION = $1207; GL_LINEAR_ATTENUATION = $1208;
  GL_AMBIENT_AND_DIFFUSE = $1602;
  GL_COMPILE = $1300; GL_COMPILE_AND_EXECUTE = $1301;
  GL_UNSIGNED_BYTE = $1401; GL_FLOAT = $1406;
  GL_STENCIL_INDEX = $1901; GL_DEPTH_COMPONENT = $1902;
  GL_RGB = $1907; GL_RGBA = $1908; GL_LUMINANCE = $1909;
  GL_LINE = $1B01; GL_FILL = $1B02;
  GL_FLAT = $1D00; GL_SMOOTH = $1D01;
  GL_KEEP = $1E00; GL_REPLACE = $1E01; GL_INCR = $1E02;
  GL_ZERO = 0;
  GL_MODELVIEW = $1700; GL_PROJECTION = $1701;
  GL_LIGHT0 = $4000; GL_LIGHT1 = $4001;

  { GLU }
  GLU_INVALID_ENUM = 100900; GLU_INVALID_VALUE = 100901; GLU_OUT_OF_MEMORY = 100902;
  GLU_TESS_BEGIN = 100100; GLU_TESS_VERTEX = 100101; GLU_TESS_END = 100102;
  GLU_TESS_ERROR = 100103; GLU_TESS_EDGE_FLAG = 100104; GLU_TESS_COMBINE = 100105;
  { Borland's values (wrong, see the header comment) }
  GLU_TESS_WINDING_RULE = 100110;
  GLU_TESS_BOUNDARY_ONLY = 100111;
  GLU_TESS_TOLERANCE = 100112;
  { GLU's values }
  GLU_TESS_WINDING_RULE_GLU = 100140;
  GLU_TESS_BOUNDARY_ONLY_GLU = 100141;
  GLU_TESS_TOLERANCE_GLU = 100142;
  GLU_TESS_WINDING_ODD = 100130; GLU_TESS_WINDING_NONZERO = 100131;
  GLU_TESS_WINDING_POSITIVE = 100132; GLU_TESS_WINDING_NEGATIVE = 100133;
  GLU_TESS_WINDING_ABS_GEQ_TWO = 100134;
  GLU_TESS_MISSING_BEGIN_POLYGON = 100151; GLU_TESS_MISSING_BEGIN_CONTOUR = 100152;
  GLU_TESS_MISSING_END_POLYGON = 100153; GLU_TESS_MISSING_END_CONTOUR = 100154;
  GLU_TESS_COORD_TOO_LARGE = 100155; GLU_TESS_NEED_COMBINE_CALLBACK = 100156;

procedure glBegin(mode: GLenum); stdcall; external opengl32;
procedure glEnd; stdcall; external opengl32;
procedure glVertex3f(x, y, z: GLfloat); stdcall; external opengl32;
procedure glVertex3fv(v: PGLfloat); stdcall; external opengl32;
procedure glVertex3dv(v: PGLdouble); stdcall; external opengl32;
procedure glNormal3f(nx, ny, nz: GLfloat); stdcall; external opengl32;
procedure glNormal3i(nx, ny, nz: GLint); stdcall; external opengl32;
procedure glColor3f(r, g, b: GLfloat); stdcall; external opengl32;
procedure glColor3ub(r, g, b: GLubyte); stdcall; external opengl32;
procedure glColor4f(r, g, b, a: GLfloat); stdcall; external opengl32;
procedure glClear(mask: GLbitfield); stdcall; external opengl32;
procedure glClearColor(r, g, b, a: GLclampf); stdcall; external opengl32;
procedure glClearStencil(s: GLint); stdcall; external opengl32;
procedure glShadeModel(mode: GLenum); stdcall; external opengl32;
procedure glEnable(cap: GLenum); stdcall; external opengl32;
procedure glDisable(cap: GLenum); stdcall; external opengl32;
procedure glMatrixMode(mode: GLenum); stdcall; external opengl32;
procedure glLoadIdentity; stdcall; external opengl32;
procedure glPushMatrix; stdcall; external opengl32;
procedure glPopMatrix; stdcall; external opengl32;
procedure glTranslatef(x, y, z: GLfloat); stdcall; external opengl32;
procedure glRotatef(angle, x, y, z: GLfloat); stdcall; external opengl32;
procedure glScalef(x, y, z: GLfloat); stdcall; external opengl32;
procedure glFrustum(l, r, b, t, n, f: GLdouble); stdcall; external opengl32;
procedure glOrtho(l, r, b, t, n, f: GLdouble); stdcall; external opengl32;
procedure glViewport(x, y: GLint; width, height: GLsizei); stdcall; external opengl32;
function glGenLists(range: GLsizei): GLuint; stdcall; external opengl32;
procedure glNewList(list: GLuint; mode: GLenum); stdcall; external opengl32;
procedure glEndList; stdcall; external opengl32;
procedure glCallList(list: GLuint); stdcall; external opengl32;
procedure glFrontFace(mode: GLenum); stdcall; external opengl32;
procedure glCullFace(mode: GLenum); stdcall; external opengl32;
procedure glPolygonMode(face, mode: GLenum); stdcall; external opengl32;
procedure glColorMask(r, g, b, a: GLboolean); stdcall; external opengl32;
procedure glDepthMask(flag: GLboolean); stdcall; external opengl32;
procedure glStencilFunc(func: GLenum; ref: GLint; mask: GLuint); stdcall; external opengl32;
procedure glStencilOp(fail, zfail, zpass: GLenum); stdcall; external opengl32;
procedure glBlendFunc(sfactor, dfactor: GLenum); stdcall; external opengl32;
procedure glMaterialfv(face, pname: GLenum; params: PGLfloat); stdcall; external opengl32;
procedure glLightfv(light, pname: GLenum; params: PGLfloat); stdcall; external opengl32;
procedure glLightf(light, pname: GLenum; param: GLfloat); stdcall; external opengl32;
procedure glLightModeli(pname: GLenum; param: GLint); stdcall; external opengl32;
procedure glReadPixels(x, y: GLint; width, height: GLsizei; format, atype: GLenum; pixels: Pointer); stdcall; external opengl32;
procedure glDrawPixels(width, height: GLsizei; format, atype: GLenum; pixels: Pointer); stdcall; external opengl32;
procedure glRasterPos3f(x, y, z: GLfloat); stdcall; external opengl32;
procedure glGetIntegerv(pname: GLenum; params: PGLint); stdcall; external opengl32;
procedure glDrawBuffer(mode: GLenum); stdcall; external opengl32;
procedure glFinish; stdcall; external opengl32;
function glGetError: GLenum; stdcall; external opengl32;

function gluNewTess: GLUtesselator; stdcall; external glu32;
procedure gluDeleteTess(tess: GLUtesselator); stdcall; external glu32;
procedure gluTessCallback(tess: GLUtesselator; which: GLenum; fn: Pointer); stdcall; external glu32;
procedure gluTessProperty(tess: GLUtesselator; which: GLenum; value: GLdouble); stdcall; external glu32;
procedure gluTessBeginPolygon(tess: GLUtesselator); stdcall; external glu32;  { sic: one argument }
procedure gluTessBeginContour(tess: GLUtesselator); stdcall; external glu32;
procedure gluTessVertex(tess: GLUtesselator; coords: PGLdouble; data: Pointer); stdcall; external glu32;
procedure gluTessEndContour(tess: GLUtesselator); stdcall; external glu32;
procedure gluTessEndPolygon(tess: GLUtesselator); stdcall; external glu32;
function gluErrorString(errCode: GLenum): PAnsiChar; stdcall; external glu32;
procedure gluOrtho2D(left, right, bottom, top: GLdouble); stdcall; external glu32;
procedure gluPerspective(fovy, aspect, zNear, zFar: GLdouble); stdcall; external glu32;
procedure gluLookAt(eyex, eyey, eyez, centerx, centery, centerz, upx, upy, upz: GLdouble); stdcall; external glu32;
function gluNewQuadric: GLUquadricObj; stdcall; external glu32;
procedure gluDeleteQuadric(state: GLUquadricObj); stdcall; external glu32;
procedure gluCylinder(qobj: GLUquadricObj; baseRadius, topRadius, height: GLdouble; slices, stacks: GLint); stdcall; external glu32;
procedure gluSphere(qobj: GLUquadricObj; radius: GLdouble; slices, stacks: GLint); stdcall; external glu32;
procedure gluDisk(qobj: GLUquadricObj; innerRadius, outerRadius: GLdouble; slices, loops: GLint); stdcall; external glu32;

implementation

uses Math;

initialization
  { Borland's unit does the same (Set8087CW($133F)): GL implementations
    compute with infinities and NaNs (w = 0 vertices, degenerate normals),
    which must not trap in the program. }
  SetExceptionMask([exInvalidOp, exDenormalized, exZeroDivide, exOverflow,
    exUnderflow, exPrecision]);
end.
