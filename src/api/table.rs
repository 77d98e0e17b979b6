//! The one table of entry points (DESIGN.md, "One table of entry points").
//!
//! Each line declares an exported function: its kind (see [`super::Kind`]:
//! `list` builds a display-listable [`Command`]; `exec` runs immediately and
//! is illegal between Begin and End; `client` runs immediately anywhere;
//! `free` needs no context; `todo` is exported but not implemented yet),
//! its C signature in Rust types, and its body. The same list gives
//! GetProcAddress its names and the README its coverage table, and a test
//! checks it against include/GL/*.h name for name.
//!
//! Order follows the headers: gl.h (by GL version and spec section), glu.h,
//! osmesa.h. Parameter names are the headers' own.
#![allow(non_snake_case, clippy::missing_safety_doc)]

use super::args::*;
use super::types::*;
use crate::gl::enums::*;
use crate::gl::lighting::{is_color_param, light_model_param_count, light_param_count, material_param_count, read_params};
use crate::gl::{get, lists::decode_names, Command, Context};
use crate::glu;
use crate::winsys::glx::{self, xlib::{Display, XVisualInfo}, Bool, FbConfig, GlxContext};
use crate::winsys::osmesa::{self, OsContext};
use std::ffi::{c_char, c_int, c_void};

/// GLU's opaque object types, as C sees them.
pub type GLUquadric = c_void;
pub type GLUtesselator = c_void;
pub type GLUnurbs = c_void;

/// GLX's X types, as C sees them (an XID is an unsigned long).
pub type XID = std::ffi::c_ulong;
pub type GLXDrawable = XID;
pub type GLXFBConfig = *const FbConfig;
pub type GLXContext = *mut GlxContext;

/// A column-major GL matrix.
fn matrix(m: [f64; 16]) -> glam::DMat4 {
    glam::DMat4::from_cols_array(&m)
}

/// A normal from integer or double components (table 2.9's signed mapping).
fn normal<T: Component>(n: &[T; 3]) -> [f32; 3] {
    n.map(|c| c.normalized())
}

/// The scalar forms (glLightf, glMaterialf, ...) take only one-value
/// parameters: anything else is GL_INVALID_ENUM.
fn scalar_param(c: &mut Context, count: usize, pname: GLenum) -> Option<GLenum> {
    if count == 1 {
        Some(pname)
    } else {
        c.set_error(GL_INVALID_ENUM);
        None
    }
}

/// Stores query results (NULL: nothing).
unsafe fn write_out<T: Copy>(p: *mut T, v: &[T]) {
    if !p.is_null() {
        for (i, x) in v.iter().enumerate() {
            p.add(i).write_unaligned(*x);
        }
    }
}

/// Integer query results: colours map [-1, 1] onto the integer range,
/// other values round (6.1.2).
fn ints_out(v: &[f32], color: bool) -> Vec<GLint> {
    let values = v.iter().map(|&x| x as f64).collect();
    if color { get::Value::Normalized(values).as_i32() } else { get::Value::Floats(values).as_i32() }
}

/// GetProcAddress by C string.
unsafe fn proc_from_name(name: *const c_char) -> GLproc {
    if name.is_null() {
        return None;
    }
    let addr = super::proc_address(std::ffi::CStr::from_ptr(name).to_bytes());
    if addr.is_null() {
        None
    } else {
        Some(std::mem::transmute::<*const (), unsafe extern "system" fn()>(addr))
    }
}

super::entry_points! {

    // ---- gl.h ----
    exec glGetError() -> GLenum { |c| c.take_error() }
    list["GL_LINE_SMOOTH and GL_POINT_SMOOTH are not antialiased yet (issue 3)"] glBegin(mode: GLenum) { |_c| Command::Begin(mode) }
    list glEnd() { |_c| Command::End }
    todo glEdgeFlag(flag: GLboolean);
    todo glEdgeFlagv(flag: *const GLboolean);
    list glVertex2d(x: GLdouble, y: GLdouble) { |_c| Command::Vertex(position(&[x, y])) }
    list glVertex2dv(v: *const GLdouble) { |_c| Command::Vertex(position(&arr::<GLdouble, 2>(v)?)) }
    list glVertex2f(x: GLfloat, y: GLfloat) { |_c| Command::Vertex(position(&[x, y])) }
    list glVertex2fv(v: *const GLfloat) { |_c| Command::Vertex(position(&arr::<GLfloat, 2>(v)?)) }
    list glVertex2i(x: GLint, y: GLint) { |_c| Command::Vertex(position(&[x, y])) }
    list glVertex2iv(v: *const GLint) { |_c| Command::Vertex(position(&arr::<GLint, 2>(v)?)) }
    list glVertex2s(x: GLshort, y: GLshort) { |_c| Command::Vertex(position(&[x, y])) }
    list glVertex2sv(v: *const GLshort) { |_c| Command::Vertex(position(&arr::<GLshort, 2>(v)?)) }
    list glVertex3d(x: GLdouble, y: GLdouble, z: GLdouble) { |_c| Command::Vertex(position(&[x, y, z])) }
    list glVertex3dv(v: *const GLdouble) { |_c| Command::Vertex(position(&arr::<GLdouble, 3>(v)?)) }
    list glVertex3f(x: GLfloat, y: GLfloat, z: GLfloat) { |_c| Command::Vertex(position(&[x, y, z])) }
    list glVertex3fv(v: *const GLfloat) { |_c| Command::Vertex(position(&arr::<GLfloat, 3>(v)?)) }
    list glVertex3i(x: GLint, y: GLint, z: GLint) { |_c| Command::Vertex(position(&[x, y, z])) }
    list glVertex3iv(v: *const GLint) { |_c| Command::Vertex(position(&arr::<GLint, 3>(v)?)) }
    list glVertex3s(x: GLshort, y: GLshort, z: GLshort) { |_c| Command::Vertex(position(&[x, y, z])) }
    list glVertex3sv(v: *const GLshort) { |_c| Command::Vertex(position(&arr::<GLshort, 3>(v)?)) }
    list glVertex4d(x: GLdouble, y: GLdouble, z: GLdouble, w: GLdouble) { |_c| Command::Vertex(position(&[x, y, z, w])) }
    list glVertex4dv(v: *const GLdouble) { |_c| Command::Vertex(position(&arr::<GLdouble, 4>(v)?)) }
    list glVertex4f(x: GLfloat, y: GLfloat, z: GLfloat, w: GLfloat) { |_c| Command::Vertex(position(&[x, y, z, w])) }
    list glVertex4fv(v: *const GLfloat) { |_c| Command::Vertex(position(&arr::<GLfloat, 4>(v)?)) }
    list glVertex4i(x: GLint, y: GLint, z: GLint, w: GLint) { |_c| Command::Vertex(position(&[x, y, z, w])) }
    list glVertex4iv(v: *const GLint) { |_c| Command::Vertex(position(&arr::<GLint, 4>(v)?)) }
    list glVertex4s(x: GLshort, y: GLshort, z: GLshort, w: GLshort) { |_c| Command::Vertex(position(&[x, y, z, w])) }
    list glVertex4sv(v: *const GLshort) { |_c| Command::Vertex(position(&arr::<GLshort, 4>(v)?)) }
    todo glTexCoord1d(s: GLdouble);
    todo glTexCoord1dv(v: *const GLdouble);
    todo glTexCoord1f(s: GLfloat);
    todo glTexCoord1fv(v: *const GLfloat);
    todo glTexCoord1i(s: GLint);
    todo glTexCoord1iv(v: *const GLint);
    todo glTexCoord1s(s: GLshort);
    todo glTexCoord1sv(v: *const GLshort);
    todo glTexCoord2d(s: GLdouble, t: GLdouble);
    todo glTexCoord2dv(v: *const GLdouble);
    todo glTexCoord2f(s: GLfloat, t: GLfloat);
    todo glTexCoord2fv(v: *const GLfloat);
    todo glTexCoord2i(s: GLint, t: GLint);
    todo glTexCoord2iv(v: *const GLint);
    todo glTexCoord2s(s: GLshort, t: GLshort);
    todo glTexCoord2sv(v: *const GLshort);
    todo glTexCoord3d(s: GLdouble, t: GLdouble, r: GLdouble);
    todo glTexCoord3dv(v: *const GLdouble);
    todo glTexCoord3f(s: GLfloat, t: GLfloat, r: GLfloat);
    todo glTexCoord3fv(v: *const GLfloat);
    todo glTexCoord3i(s: GLint, t: GLint, r: GLint);
    todo glTexCoord3iv(v: *const GLint);
    todo glTexCoord3s(s: GLshort, t: GLshort, r: GLshort);
    todo glTexCoord3sv(v: *const GLshort);
    todo glTexCoord4d(s: GLdouble, t: GLdouble, r: GLdouble, q: GLdouble);
    todo glTexCoord4dv(v: *const GLdouble);
    todo glTexCoord4f(s: GLfloat, t: GLfloat, r: GLfloat, q: GLfloat);
    todo glTexCoord4fv(v: *const GLfloat);
    todo glTexCoord4i(s: GLint, t: GLint, r: GLint, q: GLint);
    todo glTexCoord4iv(v: *const GLint);
    todo glTexCoord4s(s: GLshort, t: GLshort, r: GLshort, q: GLshort);
    todo glTexCoord4sv(v: *const GLshort);
    list glNormal3b(nx: GLbyte, ny: GLbyte, nz: GLbyte) { |_c| Command::Normal(normal(&[nx, ny, nz])) }
    list glNormal3bv(v: *const GLbyte) { |_c| Command::Normal(normal(&arr::<GLbyte, 3>(v)?)) }
    list glNormal3d(nx: GLdouble, ny: GLdouble, nz: GLdouble) { |_c| Command::Normal(normal(&[nx, ny, nz])) }
    list glNormal3dv(v: *const GLdouble) { |_c| Command::Normal(normal(&arr::<GLdouble, 3>(v)?)) }
    list glNormal3f(nx: GLfloat, ny: GLfloat, nz: GLfloat) { |_c| Command::Normal([nx, ny, nz]) }
    list glNormal3fv(v: *const GLfloat) { |_c| Command::Normal(arr::<GLfloat, 3>(v)?) }
    list glNormal3i(nx: GLint, ny: GLint, nz: GLint) { |_c| Command::Normal(normal(&[nx, ny, nz])) }
    list glNormal3iv(v: *const GLint) { |_c| Command::Normal(normal(&arr::<GLint, 3>(v)?)) }
    list glNormal3s(nx: GLshort, ny: GLshort, nz: GLshort) { |_c| Command::Normal(normal(&[nx, ny, nz])) }
    list glNormal3sv(v: *const GLshort) { |_c| Command::Normal(normal(&arr::<GLshort, 3>(v)?)) }
    list glColor3b(red: GLbyte, green: GLbyte, blue: GLbyte) { |_c| Command::Color(color(&[red, green, blue])) }
    list glColor3bv(v: *const GLbyte) { |_c| Command::Color(color(&arr::<GLbyte, 3>(v)?)) }
    list glColor3d(red: GLdouble, green: GLdouble, blue: GLdouble) { |_c| Command::Color(color(&[red, green, blue])) }
    list glColor3dv(v: *const GLdouble) { |_c| Command::Color(color(&arr::<GLdouble, 3>(v)?)) }
    list glColor3f(red: GLfloat, green: GLfloat, blue: GLfloat) { |_c| Command::Color(color(&[red, green, blue])) }
    list glColor3fv(v: *const GLfloat) { |_c| Command::Color(color(&arr::<GLfloat, 3>(v)?)) }
    list glColor3i(red: GLint, green: GLint, blue: GLint) { |_c| Command::Color(color(&[red, green, blue])) }
    list glColor3iv(v: *const GLint) { |_c| Command::Color(color(&arr::<GLint, 3>(v)?)) }
    list glColor3s(red: GLshort, green: GLshort, blue: GLshort) { |_c| Command::Color(color(&[red, green, blue])) }
    list glColor3sv(v: *const GLshort) { |_c| Command::Color(color(&arr::<GLshort, 3>(v)?)) }
    list glColor3ub(red: GLubyte, green: GLubyte, blue: GLubyte) { |_c| Command::Color(color(&[red, green, blue])) }
    list glColor3ubv(v: *const GLubyte) { |_c| Command::Color(color(&arr::<GLubyte, 3>(v)?)) }
    list glColor3ui(red: GLuint, green: GLuint, blue: GLuint) { |_c| Command::Color(color(&[red, green, blue])) }
    list glColor3uiv(v: *const GLuint) { |_c| Command::Color(color(&arr::<GLuint, 3>(v)?)) }
    list glColor3us(red: GLushort, green: GLushort, blue: GLushort) { |_c| Command::Color(color(&[red, green, blue])) }
    list glColor3usv(v: *const GLushort) { |_c| Command::Color(color(&arr::<GLushort, 3>(v)?)) }
    list glColor4b(red: GLbyte, green: GLbyte, blue: GLbyte, alpha: GLbyte) { |_c| Command::Color(color(&[red, green, blue, alpha])) }
    list glColor4bv(v: *const GLbyte) { |_c| Command::Color(color(&arr::<GLbyte, 4>(v)?)) }
    list glColor4d(red: GLdouble, green: GLdouble, blue: GLdouble, alpha: GLdouble) { |_c| Command::Color(color(&[red, green, blue, alpha])) }
    list glColor4dv(v: *const GLdouble) { |_c| Command::Color(color(&arr::<GLdouble, 4>(v)?)) }
    list glColor4f(red: GLfloat, green: GLfloat, blue: GLfloat, alpha: GLfloat) { |_c| Command::Color(color(&[red, green, blue, alpha])) }
    list glColor4fv(v: *const GLfloat) { |_c| Command::Color(color(&arr::<GLfloat, 4>(v)?)) }
    list glColor4i(red: GLint, green: GLint, blue: GLint, alpha: GLint) { |_c| Command::Color(color(&[red, green, blue, alpha])) }
    list glColor4iv(v: *const GLint) { |_c| Command::Color(color(&arr::<GLint, 4>(v)?)) }
    list glColor4s(red: GLshort, green: GLshort, blue: GLshort, alpha: GLshort) { |_c| Command::Color(color(&[red, green, blue, alpha])) }
    list glColor4sv(v: *const GLshort) { |_c| Command::Color(color(&arr::<GLshort, 4>(v)?)) }
    list glColor4ub(red: GLubyte, green: GLubyte, blue: GLubyte, alpha: GLubyte) { |_c| Command::Color(color(&[red, green, blue, alpha])) }
    list glColor4ubv(v: *const GLubyte) { |_c| Command::Color(color(&arr::<GLubyte, 4>(v)?)) }
    list glColor4ui(red: GLuint, green: GLuint, blue: GLuint, alpha: GLuint) { |_c| Command::Color(color(&[red, green, blue, alpha])) }
    list glColor4uiv(v: *const GLuint) { |_c| Command::Color(color(&arr::<GLuint, 4>(v)?)) }
    list glColor4us(red: GLushort, green: GLushort, blue: GLushort, alpha: GLushort) { |_c| Command::Color(color(&[red, green, blue, alpha])) }
    list glColor4usv(v: *const GLushort) { |_c| Command::Color(color(&arr::<GLushort, 4>(v)?)) }
    todo glIndexd(c: GLdouble);
    todo glIndexdv(v: *const GLdouble);
    todo glIndexf(c: GLfloat);
    todo glIndexfv(v: *const GLfloat);
    todo glIndexi(c: GLint);
    todo glIndexiv(v: *const GLint);
    todo glIndexs(c: GLshort);
    todo glIndexsv(v: *const GLshort);
    todo glIndexub(c: GLubyte);
    todo glIndexubv(v: *const GLubyte);
    todo glVertexPointer(size: GLint, type_: GLenum, stride: GLsizei, ptr: *const c_void);
    todo glNormalPointer(type_: GLenum, stride: GLsizei, ptr: *const c_void);
    todo glColorPointer(size: GLint, type_: GLenum, stride: GLsizei, ptr: *const c_void);
    todo glIndexPointer(type_: GLenum, stride: GLsizei, ptr: *const c_void);
    todo glTexCoordPointer(size: GLint, type_: GLenum, stride: GLsizei, ptr: *const c_void);
    todo glEdgeFlagPointer(stride: GLsizei, ptr: *const c_void);
    todo glEnableClientState(array: GLenum);
    todo glDisableClientState(array: GLenum);
    todo glArrayElement(i: GLint);
    todo glDrawArrays(mode: GLenum, first: GLint, count: GLsizei);
    todo glDrawElements(mode: GLenum, count: GLsizei, type_: GLenum, indices: *const c_void);
    todo glInterleavedArrays(format: GLenum, stride: GLsizei, pointer: *const c_void);
    list glRectd(x1: GLdouble, y1: GLdouble, x2: GLdouble, y2: GLdouble) { |_c| Command::Rect([x1 as f32, y1 as f32, x2 as f32, y2 as f32]) }
    list glRectdv(v1: *const GLdouble, v2: *const GLdouble) { |_c| { let (a, b) = (arr::<GLdouble, 2>(v1)?, arr::<GLdouble, 2>(v2)?); Command::Rect([a[0] as f32, a[1] as f32, b[0] as f32, b[1] as f32]) } }
    list glRectf(x1: GLfloat, y1: GLfloat, x2: GLfloat, y2: GLfloat) { |_c| Command::Rect([x1 as f32, y1 as f32, x2 as f32, y2 as f32]) }
    list glRectfv(v1: *const GLfloat, v2: *const GLfloat) { |_c| { let (a, b) = (arr::<GLfloat, 2>(v1)?, arr::<GLfloat, 2>(v2)?); Command::Rect([a[0] as f32, a[1] as f32, b[0] as f32, b[1] as f32]) } }
    list glRecti(x1: GLint, y1: GLint, x2: GLint, y2: GLint) { |_c| Command::Rect([x1 as f32, y1 as f32, x2 as f32, y2 as f32]) }
    list glRectiv(v1: *const GLint, v2: *const GLint) { |_c| { let (a, b) = (arr::<GLint, 2>(v1)?, arr::<GLint, 2>(v2)?); Command::Rect([a[0] as f32, a[1] as f32, b[0] as f32, b[1] as f32]) } }
    list glRects(x1: GLshort, y1: GLshort, x2: GLshort, y2: GLshort) { |_c| Command::Rect([x1 as f32, y1 as f32, x2 as f32, y2 as f32]) }
    list glRectsv(v1: *const GLshort, v2: *const GLshort) { |_c| { let (a, b) = (arr::<GLshort, 2>(v1)?, arr::<GLshort, 2>(v2)?); Command::Rect([a[0] as f32, a[1] as f32, b[0] as f32, b[1] as f32]) } }
    list glDepthRange(zNear: GLclampd, zFar: GLclampd) { |_c| Command::DepthRange(zNear, zFar) }
    list glViewport(x: GLint, y: GLint, width: GLsizei, height: GLsizei) { |_c| Command::Viewport(x, y, width, height) }
    list glMatrixMode(mode: GLenum) { |_c| Command::MatrixMode(mode) }
    list glLoadMatrixd(m: *const GLdouble) { |_c| Command::LoadMatrix(matrix(arr::<GLdouble, 16>(m)?)) }
    list glLoadMatrixf(m: *const GLfloat) { |_c| Command::LoadMatrix(matrix(arr::<GLfloat, 16>(m)?.map(f64::from))) }
    list glMultMatrixd(m: *const GLdouble) { |_c| Command::MultMatrix(matrix(arr::<GLdouble, 16>(m)?)) }
    list glMultMatrixf(m: *const GLfloat) { |_c| Command::MultMatrix(matrix(arr::<GLfloat, 16>(m)?.map(f64::from))) }
    list glLoadIdentity() { |_c| Command::LoadIdentity }
    list glRotated(angle: GLdouble, x: GLdouble, y: GLdouble, z: GLdouble) { |_c| Command::Rotate(angle as f64, [x as f64, y as f64, z as f64]) }
    list glRotatef(angle: GLfloat, x: GLfloat, y: GLfloat, z: GLfloat) { |_c| Command::Rotate(angle as f64, [x as f64, y as f64, z as f64]) }
    list glTranslated(x: GLdouble, y: GLdouble, z: GLdouble) { |_c| Command::Translate([x as f64, y as f64, z as f64]) }
    list glTranslatef(x: GLfloat, y: GLfloat, z: GLfloat) { |_c| Command::Translate([x as f64, y as f64, z as f64]) }
    list glScaled(x: GLdouble, y: GLdouble, z: GLdouble) { |_c| Command::Scale([x as f64, y as f64, z as f64]) }
    list glScalef(x: GLfloat, y: GLfloat, z: GLfloat) { |_c| Command::Scale([x as f64, y as f64, z as f64]) }
    list glFrustum(left: GLdouble, right: GLdouble, bottom: GLdouble, top: GLdouble, zNear: GLdouble, zFar: GLdouble) { |_c| Command::Frustum([left, right, bottom, top, zNear, zFar]) }
    list glOrtho(left: GLdouble, right: GLdouble, bottom: GLdouble, top: GLdouble, zNear: GLdouble, zFar: GLdouble) { |_c| Command::Ortho([left, right, bottom, top, zNear, zFar]) }
    list glPushMatrix() { |_c| Command::PushMatrix }
    list glPopMatrix() { |_c| Command::PopMatrix }
    todo glTexGend(coord: GLenum, pname: GLenum, param: GLdouble);
    todo glTexGendv(coord: GLenum, pname: GLenum, params: *const GLdouble);
    todo glTexGenf(coord: GLenum, pname: GLenum, param: GLfloat);
    todo glTexGenfv(coord: GLenum, pname: GLenum, params: *const GLfloat);
    todo glTexGeni(coord: GLenum, pname: GLenum, param: GLint);
    todo glTexGeniv(coord: GLenum, pname: GLenum, params: *const GLint);
    todo glClipPlane(plane: GLenum, equation: *const GLdouble);
    todo glRasterPos2d(x: GLdouble, y: GLdouble);
    todo glRasterPos2dv(v: *const GLdouble);
    todo glRasterPos2f(x: GLfloat, y: GLfloat);
    todo glRasterPos2fv(v: *const GLfloat);
    todo glRasterPos2i(x: GLint, y: GLint);
    todo glRasterPos2iv(v: *const GLint);
    todo glRasterPos2s(x: GLshort, y: GLshort);
    todo glRasterPos2sv(v: *const GLshort);
    todo glRasterPos3d(x: GLdouble, y: GLdouble, z: GLdouble);
    todo glRasterPos3dv(v: *const GLdouble);
    todo glRasterPos3f(x: GLfloat, y: GLfloat, z: GLfloat);
    todo glRasterPos3fv(v: *const GLfloat);
    todo glRasterPos3i(x: GLint, y: GLint, z: GLint);
    todo glRasterPos3iv(v: *const GLint);
    todo glRasterPos3s(x: GLshort, y: GLshort, z: GLshort);
    todo glRasterPos3sv(v: *const GLshort);
    todo glRasterPos4d(x: GLdouble, y: GLdouble, z: GLdouble, w: GLdouble);
    todo glRasterPos4dv(v: *const GLdouble);
    todo glRasterPos4f(x: GLfloat, y: GLfloat, z: GLfloat, w: GLfloat);
    todo glRasterPos4fv(v: *const GLfloat);
    todo glRasterPos4i(x: GLint, y: GLint, z: GLint, w: GLint);
    todo glRasterPos4iv(v: *const GLint);
    todo glRasterPos4s(x: GLshort, y: GLshort, z: GLshort, w: GLshort);
    todo glRasterPos4sv(v: *const GLshort);
    list glMaterialf(face: GLenum, pname: GLenum, param: GLfloat) { |c| Command::Material(face, scalar_param(c, material_param_count(pname), pname)?, [param, 0.0, 0.0, 0.0]) }
    list glMaterialfv(face: GLenum, pname: GLenum, params: *const GLfloat) { |_c| Command::Material(face, pname, read_params(params, material_param_count(pname), pname)?) }
    list glMateriali(face: GLenum, pname: GLenum, param: GLint) { |c| Command::Material(face, scalar_param(c, material_param_count(pname), pname)?, [param as f32, 0.0, 0.0, 0.0]) }
    list glMaterialiv(face: GLenum, pname: GLenum, params: *const GLint) { |_c| Command::Material(face, pname, read_params(params, material_param_count(pname), pname)?) }
    list glLightf(light: GLenum, pname: GLenum, param: GLfloat) { |c| Command::Light(light, scalar_param(c, light_param_count(pname), pname)?, [param, 0.0, 0.0, 0.0]) }
    list glLightfv(light: GLenum, pname: GLenum, params: *const GLfloat) { |_c| Command::Light(light, pname, read_params(params, light_param_count(pname), pname)?) }
    list glLighti(light: GLenum, pname: GLenum, param: GLint) { |c| Command::Light(light, scalar_param(c, light_param_count(pname), pname)?, [param as f32, 0.0, 0.0, 0.0]) }
    list glLightiv(light: GLenum, pname: GLenum, params: *const GLint) { |_c| Command::Light(light, pname, read_params(params, light_param_count(pname), pname)?) }
    list glLightModelf(pname: GLenum, param: GLfloat) { |c| Command::LightModel(scalar_param(c, light_model_param_count(pname), pname)?, [param, 0.0, 0.0, 0.0]) }
    list glLightModelfv(pname: GLenum, params: *const GLfloat) { |_c| Command::LightModel(pname, read_params(params, light_model_param_count(pname), pname)?) }
    list glLightModeli(pname: GLenum, param: GLint) { |c| Command::LightModel(scalar_param(c, light_model_param_count(pname), pname)?, [param as f32, 0.0, 0.0, 0.0]) }
    list glLightModeliv(pname: GLenum, params: *const GLint) { |_c| Command::LightModel(pname, read_params(params, light_model_param_count(pname), pname)?) }
    list glColorMaterial(face: GLenum, mode: GLenum) { |_c| Command::ColorMaterial(face, mode) }
    list glShadeModel(mode: GLenum) { |_c| Command::ShadeModel(mode) }
    list["GL_POINT_SMOOTH draws square points; no point parameters"] glPointSize(size: GLfloat) { |_c| Command::PointSize(size) }
    list["GL_LINE_SMOOTH draws aliased lines"] glLineWidth(width: GLfloat) { |_c| Command::LineWidth(width) }
    list glLineStipple(factor: GLint, pattern: GLushort) { |_c| Command::LineStipple(factor, pattern) }
    list glCullFace(mode: GLenum) { |_c| Command::CullFace(mode) }
    list glFrontFace(mode: GLenum) { |_c| Command::FrontFace(mode) }
    todo glPolygonStipple(mask: *const GLubyte);
    todo glPolygonMode(face: GLenum, mode: GLenum);
    todo glPolygonOffset(factor: GLfloat, units: GLfloat);
    client["as glPixelStorei"] glPixelStoref(pname: GLenum, param: GLfloat) { |c| c.pixel_store(pname, param as f64) }
    client["pack modes apply to glReadPixels; unpack modes are stored for issue 5"] glPixelStorei(pname: GLenum, param: GLint) { |c| c.pixel_store(pname, param as f64) }
    todo glPixelTransferf(pname: GLenum, param: GLfloat);
    todo glPixelTransferi(pname: GLenum, param: GLint);
    todo glPixelMapfv(map: GLenum, mapsize: GLsizei, values: *const GLfloat);
    todo glPixelMapuiv(map: GLenum, mapsize: GLsizei, values: *const GLuint);
    todo glPixelMapusv(map: GLenum, mapsize: GLsizei, values: *const GLushort);
    todo glDrawPixels(width: GLsizei, height: GLsizei, format: GLenum, type_: GLenum, pixels: *const c_void);
    todo glPixelZoom(xfactor: GLfloat, yfactor: GLfloat);
    todo glBitmap(width: GLsizei, height: GLsizei, xorig: GLfloat, yorig: GLfloat, xmove: GLfloat, ymove: GLfloat, bitmap: *const GLubyte);
    todo glTexImage1D(target: GLenum, level: GLint, internalFormat: GLint, width: GLsizei, border: GLint, format: GLenum, type_: GLenum, pixels: *const c_void);
    todo glTexImage2D(target: GLenum, level: GLint, internalFormat: GLint, width: GLsizei, height: GLsizei, border: GLint, format: GLenum, type_: GLenum, pixels: *const c_void);
    todo glCopyTexImage1D(target: GLenum, level: GLint, internalFormat: GLenum, x: GLint, y: GLint, width: GLsizei, border: GLint);
    todo glCopyTexImage2D(target: GLenum, level: GLint, internalFormat: GLenum, x: GLint, y: GLint, width: GLsizei, height: GLsizei, border: GLint);
    todo glTexSubImage1D(target: GLenum, level: GLint, xoffset: GLint, width: GLsizei, format: GLenum, type_: GLenum, pixels: *const c_void);
    todo glTexSubImage2D(target: GLenum, level: GLint, xoffset: GLint, yoffset: GLint, width: GLsizei, height: GLsizei, format: GLenum, type_: GLenum, pixels: *const c_void);
    todo glCopyTexSubImage1D(target: GLenum, level: GLint, xoffset: GLint, x: GLint, y: GLint, width: GLsizei);
    todo glCopyTexSubImage2D(target: GLenum, level: GLint, xoffset: GLint, yoffset: GLint, x: GLint, y: GLint, width: GLsizei, height: GLsizei);
    todo glTexParameterf(target: GLenum, pname: GLenum, param: GLfloat);
    todo glTexParameterfv(target: GLenum, pname: GLenum, params: *const GLfloat);
    todo glTexParameteri(target: GLenum, pname: GLenum, param: GLint);
    todo glTexParameteriv(target: GLenum, pname: GLenum, params: *const GLint);
    todo glGenTextures(n: GLsizei, textures: *mut GLuint);
    todo glDeleteTextures(n: GLsizei, textures: *const GLuint);
    todo glBindTexture(target: GLenum, texture: GLuint);
    todo glPrioritizeTextures(n: GLsizei, textures: *const GLuint, priorities: *const GLclampf);
    todo glAreTexturesResident(n: GLsizei, textures: *const GLuint, residences: *mut GLboolean) -> GLboolean;
    todo glIsTexture(texture: GLuint) -> GLboolean;
    todo glTexEnvf(target: GLenum, pname: GLenum, param: GLfloat);
    todo glTexEnvfv(target: GLenum, pname: GLenum, params: *const GLfloat);
    todo glTexEnvi(target: GLenum, pname: GLenum, param: GLint);
    todo glTexEnviv(target: GLenum, pname: GLenum, params: *const GLint);
    todo glFogf(pname: GLenum, param: GLfloat);
    todo glFogfv(pname: GLenum, params: *const GLfloat);
    todo glFogi(pname: GLenum, param: GLint);
    todo glFogiv(pname: GLenum, params: *const GLint);
    list glScissor(x: GLint, y: GLint, width: GLsizei, height: GLsizei) { |_c| Command::Scissor(x, y, width, height) }
    list glAlphaFunc(func: GLenum, ref_: GLclampf) { |_c| Command::AlphaFunc(func, ref_) }
    list glStencilFunc(func: GLenum, ref_: GLint, mask: GLuint) { |_c| Command::StencilFunc(func, ref_, mask) }
    list glStencilOp(fail: GLenum, zfail: GLenum, zpass: GLenum) { |_c| Command::StencilOp(fail, zfail, zpass) }
    list glDepthFunc(func: GLenum) { |_c| Command::DepthFunc(func) }
    list glBlendFunc(sfactor: GLenum, dfactor: GLenum) { |_c| Command::BlendFunc([sfactor, dfactor, sfactor, dfactor]) }
    list glLogicOp(opcode: GLenum) { |_c| Command::LogicOp(opcode) }
    todo glDrawBuffer(mode: GLenum);
    todo glIndexMask(mask: GLuint);
    list glColorMask(red: GLboolean, green: GLboolean, blue: GLboolean, alpha: GLboolean) { |_c| Command::ColorMask([truth(red), truth(green), truth(blue), truth(alpha)]) }
    list glDepthMask(flag: GLboolean) { |_c| Command::DepthMask(truth(flag)) }
    list glStencilMask(mask: GLuint) { |_c| Command::StencilMask(mask) }
    list["GL_ACCUM_BUFFER_BIT is accepted but the accumulation buffer is not cleared yet (issue 3)"] glClear(mask: GLbitfield) { |_c| Command::Clear(mask) }
    list glClearColor(red: GLclampf, green: GLclampf, blue: GLclampf, alpha: GLclampf) { |_c| Command::ClearColor([red, green, blue, alpha]) }
    todo glClearIndex(c: GLfloat);
    list glClearDepth(depth: GLclampd) { |_c| Command::ClearDepth(depth) }
    list glClearStencil(s: GLint) { |_c| Command::ClearStencil(s) }
    todo glClearAccum(red: GLfloat, green: GLfloat, blue: GLfloat, alpha: GLfloat);
    todo glAccum(op: GLenum, value: GLfloat);
    todo glReadBuffer(mode: GLenum);
    exec["packed pixel types (3_3_2 .. 2_10_10_10_REV) and GL_BITMAP are not packed yet; pixel transfer is not applied (issue 5)"] glReadPixels(x: GLint, y: GLint, width: GLsizei, height: GLsizei, format: GLenum, type_: GLenum, pixels: *mut c_void) { |c| c.read_pixels(x, y, width, height, format, type_, pixels as *mut u8) }
    todo glCopyPixels(x: GLint, y: GLint, width: GLsizei, height: GLsizei, type_: GLenum);
    todo glMap1d(target: GLenum, u1: GLdouble, u2: GLdouble, stride: GLint, order: GLint, points: *const GLdouble);
    todo glMap1f(target: GLenum, u1: GLfloat, u2: GLfloat, stride: GLint, order: GLint, points: *const GLfloat);
    todo glMap2d(target: GLenum, u1: GLdouble, u2: GLdouble, ustride: GLint, uorder: GLint, v1: GLdouble, v2: GLdouble, vstride: GLint, vorder: GLint, points: *const GLdouble);
    todo glMap2f(target: GLenum, u1: GLfloat, u2: GLfloat, ustride: GLint, uorder: GLint, v1: GLfloat, v2: GLfloat, vstride: GLint, vorder: GLint, points: *const GLfloat);
    todo glEvalCoord1d(u: GLdouble);
    todo glEvalCoord1dv(u: *const GLdouble);
    todo glEvalCoord1f(u: GLfloat);
    todo glEvalCoord1fv(u: *const GLfloat);
    todo glEvalCoord2d(u: GLdouble, v: GLdouble);
    todo glEvalCoord2dv(u: *const GLdouble);
    todo glEvalCoord2f(u: GLfloat, v: GLfloat);
    todo glEvalCoord2fv(u: *const GLfloat);
    todo glMapGrid1d(un: GLint, u1: GLdouble, u2: GLdouble);
    todo glMapGrid1f(un: GLint, u1: GLfloat, u2: GLfloat);
    todo glMapGrid2d(un: GLint, u1: GLdouble, u2: GLdouble, vn: GLint, v1: GLdouble, v2: GLdouble);
    todo glMapGrid2f(un: GLint, u1: GLfloat, u2: GLfloat, vn: GLint, v1: GLfloat, v2: GLfloat);
    todo glEvalMesh1(mode: GLenum, i1: GLint, i2: GLint);
    todo glEvalMesh2(mode: GLenum, i1: GLint, i2: GLint, j1: GLint, j2: GLint);
    todo glEvalPoint1(i: GLint);
    todo glEvalPoint2(i: GLint, j: GLint);
    todo glRenderMode(mode: GLenum) -> GLint;
    todo glSelectBuffer(size: GLsizei, buffer: *mut GLuint);
    todo glInitNames();
    todo glLoadName(name: GLuint);
    todo glPushName(name: GLuint);
    todo glPopName();
    todo glFeedbackBuffer(size: GLsizei, type_: GLenum, buffer: *mut GLfloat);
    todo glPassThrough(token: GLfloat);
    exec glNewList(list: GLuint, mode: GLenum) { |c| c.new_list(list, mode) }
    exec glEndList() { |c| c.end_list() }
    list glCallList(list: GLuint) { |_c| Command::CallList(list) }
    list glCallLists(n: GLsizei, type_: GLenum, lists: *const c_void) { |c| match decode_names(n, type_, lists as *const u8) { Ok(names) => Command::CallLists(names), Err(e) => { c.set_error(e); return None } } }
    list glListBase(base: GLuint) { |_c| Command::ListBase(base) }
    exec glGenLists(range: GLsizei) -> GLuint { |c| c.gen_lists(range) }
    exec glIsList(list: GLuint) -> GLboolean { |c| gl_bool(c.lists.is_list(list)) }
    exec glDeleteLists(list: GLuint, range: GLsizei) { |c| c.delete_lists(list, range) }
    exec glFlush() { |c| c.flush() }
    exec glFinish() { |c| c.flush() }
    list["stored; no hint changes rendering yet"] glHint(target: GLenum, mode: GLenum) { |_c| Command::Hint(target, mode) }
    list["capabilities other than DEPTH_TEST, SCISSOR_TEST, CULL_FACE, DITHER, ALPHA_TEST, STENCIL_TEST, BLEND, COLOR_LOGIC_OP and INDEX_LOGIC_OP are stored and queryable but do not affect rendering yet"] glEnable(cap: GLenum) { |_c| Command::Enable(cap) }
    list["see glEnable"] glDisable(cap: GLenum) { |_c| Command::Disable(cap) }
    exec["as glEnable"] glIsEnabled(cap: GLenum) -> GLboolean { |c| match c.is_enabled(cap) { Some(b) => gl_bool(b), None => { c.set_error(GL_INVALID_ENUM); 0 } } }
    exec["as glGetIntegerv"] glGetBooleanv(pname: GLenum, params: *mut GLboolean) { |c| c.get_into(pname, params, |v| v.as_bool().into_iter().map(gl_bool).collect()) }
    exec["answers the state implemented so far; other names give GL_INVALID_ENUM"] glGetIntegerv(pname: GLenum, params: *mut GLint) { |c| c.get_into(pname, params, get::Value::as_i32) }
    exec["as glGetIntegerv"] glGetFloatv(pname: GLenum, params: *mut GLfloat) { |c| c.get_into(pname, params, |v| v.as_f64().into_iter().map(|x| x as f32).collect()) }
    exec["as glGetIntegerv"] glGetDoublev(pname: GLenum, params: *mut GLdouble) { |c| c.get_into(pname, params, get::Value::as_f64) }
    todo glGetPointerv(pname: GLenum, params: *mut *mut c_void);
    todo glGetClipPlane(plane: GLenum, equation: *mut GLdouble);
    exec glGetLightfv(light: GLenum, pname: GLenum, params: *mut GLfloat) { |c| match c.get_light(light, pname) { Some(v) => write_out(params, &v), None => c.set_error(GL_INVALID_ENUM) } }
    exec glGetLightiv(light: GLenum, pname: GLenum, params: *mut GLint) { |c| match c.get_light(light, pname) { Some(v) => write_out(params, &ints_out(&v, is_color_param(pname))), None => c.set_error(GL_INVALID_ENUM) } }
    exec glGetMaterialfv(face: GLenum, pname: GLenum, params: *mut GLfloat) { |c| match c.get_material(face, pname) { Some(v) => write_out(params, &v), None => c.set_error(GL_INVALID_ENUM) } }
    exec glGetMaterialiv(face: GLenum, pname: GLenum, params: *mut GLint) { |c| match c.get_material(face, pname) { Some(v) => write_out(params, &ints_out(&v, is_color_param(pname))), None => c.set_error(GL_INVALID_ENUM) } }
    todo glGetTexEnvfv(target: GLenum, pname: GLenum, params: *mut GLfloat);
    todo glGetTexEnviv(target: GLenum, pname: GLenum, params: *mut GLint);
    todo glGetTexGendv(coord: GLenum, pname: GLenum, params: *mut GLdouble);
    todo glGetTexGenfv(coord: GLenum, pname: GLenum, params: *mut GLfloat);
    todo glGetTexGeniv(coord: GLenum, pname: GLenum, params: *mut GLint);
    todo glGetTexParameterfv(target: GLenum, pname: GLenum, params: *mut GLfloat);
    todo glGetTexParameteriv(target: GLenum, pname: GLenum, params: *mut GLint);
    todo glGetTexLevelParameterfv(target: GLenum, level: GLint, pname: GLenum, params: *mut GLfloat);
    todo glGetTexLevelParameteriv(target: GLenum, level: GLint, pname: GLenum, params: *mut GLint);
    todo glGetTexImage(target: GLenum, level: GLint, format: GLenum, type_: GLenum, pixels: *mut c_void);
    todo glGetPixelMapfv(map: GLenum, values: *mut GLfloat);
    todo glGetPixelMapuiv(map: GLenum, values: *mut GLuint);
    todo glGetPixelMapusv(map: GLenum, values: *mut GLushort);
    todo glGetMapdv(target: GLenum, query: GLenum, v: *mut GLdouble);
    todo glGetMapfv(target: GLenum, query: GLenum, v: *mut GLfloat);
    todo glGetMapiv(target: GLenum, query: GLenum, v: *mut GLint);
    todo glGetPolygonStipple(mask: *mut GLubyte);
    exec glGetString(name: GLenum) -> *const GLubyte { |c| match get::string(name) { Some(s) => s.as_ptr(), None => { c.set_error(GL_INVALID_ENUM); std::ptr::null() } } }
    todo glPushAttrib(mask: GLbitfield);
    todo glPopAttrib();
    todo glPushClientAttrib(mask: GLbitfield);
    todo glPopClientAttrib();
    todo glDrawRangeElements(mode: GLenum, start: GLuint, end: GLuint, count: GLsizei, type_: GLenum, indices: *const c_void);
    todo glTexImage3D(target: GLenum, level: GLint, internalFormat: GLint, width: GLsizei, height: GLsizei, depth: GLsizei, border: GLint, format: GLenum, type_: GLenum, pixels: *const c_void);
    todo glTexSubImage3D(target: GLenum, level: GLint, xoffset: GLint, yoffset: GLint, zoffset: GLint, width: GLsizei, height: GLsizei, depth: GLsizei, format: GLenum, type_: GLenum, pixels: *const c_void);
    todo glCopyTexSubImage3D(target: GLenum, level: GLint, xoffset: GLint, yoffset: GLint, zoffset: GLint, x: GLint, y: GLint, width: GLsizei, height: GLsizei);
    list glBlendColor(red: GLclampf, green: GLclampf, blue: GLclampf, alpha: GLclampf) { |_c| Command::BlendColor([red, green, blue, alpha]) }
    list glBlendEquation(mode: GLenum) { |_c| Command::BlendEquation(mode) }
    todo glColorTable(target: GLenum, internalformat: GLenum, width: GLsizei, format: GLenum, type_: GLenum, table: *const c_void);
    todo glColorTableParameterfv(target: GLenum, pname: GLenum, params: *const GLfloat);
    todo glColorTableParameteriv(target: GLenum, pname: GLenum, params: *const GLint);
    todo glCopyColorTable(target: GLenum, internalformat: GLenum, x: GLint, y: GLint, width: GLsizei);
    todo glColorSubTable(target: GLenum, start: GLsizei, count: GLsizei, format: GLenum, type_: GLenum, data: *const c_void);
    todo glCopyColorSubTable(target: GLenum, start: GLsizei, x: GLint, y: GLint, width: GLsizei);
    todo glGetColorTable(target: GLenum, format: GLenum, type_: GLenum, table: *mut c_void);
    todo glGetColorTableParameterfv(target: GLenum, pname: GLenum, params: *mut GLfloat);
    todo glGetColorTableParameteriv(target: GLenum, pname: GLenum, params: *mut GLint);
    todo glConvolutionFilter1D(target: GLenum, internalformat: GLenum, width: GLsizei, format: GLenum, type_: GLenum, image: *const c_void);
    todo glConvolutionFilter2D(target: GLenum, internalformat: GLenum, width: GLsizei, height: GLsizei, format: GLenum, type_: GLenum, image: *const c_void);
    todo glSeparableFilter2D(target: GLenum, internalformat: GLenum, width: GLsizei, height: GLsizei, format: GLenum, type_: GLenum, row: *const c_void, column: *const c_void);
    todo glCopyConvolutionFilter1D(target: GLenum, internalformat: GLenum, x: GLint, y: GLint, width: GLsizei);
    todo glCopyConvolutionFilter2D(target: GLenum, internalformat: GLenum, x: GLint, y: GLint, width: GLsizei, height: GLsizei);
    todo glConvolutionParameterf(target: GLenum, pname: GLenum, param: GLfloat);
    todo glConvolutionParameterfv(target: GLenum, pname: GLenum, params: *const GLfloat);
    todo glConvolutionParameteri(target: GLenum, pname: GLenum, param: GLint);
    todo glConvolutionParameteriv(target: GLenum, pname: GLenum, params: *const GLint);
    todo glGetConvolutionFilter(target: GLenum, format: GLenum, type_: GLenum, image: *mut c_void);
    todo glGetSeparableFilter(target: GLenum, format: GLenum, type_: GLenum, row: *mut c_void, column: *mut c_void, span: *mut c_void);
    todo glGetConvolutionParameterfv(target: GLenum, pname: GLenum, params: *mut GLfloat);
    todo glGetConvolutionParameteriv(target: GLenum, pname: GLenum, params: *mut GLint);
    todo glHistogram(target: GLenum, width: GLsizei, internalformat: GLenum, sink: GLboolean);
    todo glResetHistogram(target: GLenum);
    todo glGetHistogram(target: GLenum, reset: GLboolean, format: GLenum, type_: GLenum, values: *mut c_void);
    todo glGetHistogramParameterfv(target: GLenum, pname: GLenum, params: *mut GLfloat);
    todo glGetHistogramParameteriv(target: GLenum, pname: GLenum, params: *mut GLint);
    todo glMinmax(target: GLenum, internalformat: GLenum, sink: GLboolean);
    todo glResetMinmax(target: GLenum);
    todo glGetMinmax(target: GLenum, reset: GLboolean, format: GLenum, type_: GLenum, values: *mut c_void);
    todo glGetMinmaxParameterfv(target: GLenum, pname: GLenum, params: *mut GLfloat);
    todo glGetMinmaxParameteriv(target: GLenum, pname: GLenum, params: *mut GLint);
    todo glActiveTexture(texture: GLenum);
    todo glClientActiveTexture(texture: GLenum);
    todo glMultiTexCoord1d(target: GLenum, s: GLdouble);
    todo glMultiTexCoord1dv(target: GLenum, v: *const GLdouble);
    todo glMultiTexCoord1f(target: GLenum, s: GLfloat);
    todo glMultiTexCoord1fv(target: GLenum, v: *const GLfloat);
    todo glMultiTexCoord1i(target: GLenum, s: GLint);
    todo glMultiTexCoord1iv(target: GLenum, v: *const GLint);
    todo glMultiTexCoord1s(target: GLenum, s: GLshort);
    todo glMultiTexCoord1sv(target: GLenum, v: *const GLshort);
    todo glMultiTexCoord2d(target: GLenum, s: GLdouble, t: GLdouble);
    todo glMultiTexCoord2dv(target: GLenum, v: *const GLdouble);
    todo glMultiTexCoord2f(target: GLenum, s: GLfloat, t: GLfloat);
    todo glMultiTexCoord2fv(target: GLenum, v: *const GLfloat);
    todo glMultiTexCoord2i(target: GLenum, s: GLint, t: GLint);
    todo glMultiTexCoord2iv(target: GLenum, v: *const GLint);
    todo glMultiTexCoord2s(target: GLenum, s: GLshort, t: GLshort);
    todo glMultiTexCoord2sv(target: GLenum, v: *const GLshort);
    todo glMultiTexCoord3d(target: GLenum, s: GLdouble, t: GLdouble, r: GLdouble);
    todo glMultiTexCoord3dv(target: GLenum, v: *const GLdouble);
    todo glMultiTexCoord3f(target: GLenum, s: GLfloat, t: GLfloat, r: GLfloat);
    todo glMultiTexCoord3fv(target: GLenum, v: *const GLfloat);
    todo glMultiTexCoord3i(target: GLenum, s: GLint, t: GLint, r: GLint);
    todo glMultiTexCoord3iv(target: GLenum, v: *const GLint);
    todo glMultiTexCoord3s(target: GLenum, s: GLshort, t: GLshort, r: GLshort);
    todo glMultiTexCoord3sv(target: GLenum, v: *const GLshort);
    todo glMultiTexCoord4d(target: GLenum, s: GLdouble, t: GLdouble, r: GLdouble, q: GLdouble);
    todo glMultiTexCoord4dv(target: GLenum, v: *const GLdouble);
    todo glMultiTexCoord4f(target: GLenum, s: GLfloat, t: GLfloat, r: GLfloat, q: GLfloat);
    todo glMultiTexCoord4fv(target: GLenum, v: *const GLfloat);
    todo glMultiTexCoord4i(target: GLenum, s: GLint, t: GLint, r: GLint, q: GLint);
    todo glMultiTexCoord4iv(target: GLenum, v: *const GLint);
    todo glMultiTexCoord4s(target: GLenum, s: GLshort, t: GLshort, r: GLshort, q: GLshort);
    todo glMultiTexCoord4sv(target: GLenum, v: *const GLshort);
    list glLoadTransposeMatrixf(m: *const GLfloat) { |_c| Command::LoadMatrix(matrix(arr::<GLfloat, 16>(m)?.map(f64::from)).transpose()) }
    list glLoadTransposeMatrixd(m: *const GLdouble) { |_c| Command::LoadMatrix(matrix(arr::<GLdouble, 16>(m)?).transpose()) }
    list glMultTransposeMatrixf(m: *const GLfloat) { |_c| Command::MultMatrix(matrix(arr::<GLfloat, 16>(m)?.map(f64::from)).transpose()) }
    list glMultTransposeMatrixd(m: *const GLdouble) { |_c| Command::MultMatrix(matrix(arr::<GLdouble, 16>(m)?).transpose()) }
    todo glSampleCoverage(value: GLclampf, invert: GLboolean);
    todo glCompressedTexImage1D(target: GLenum, level: GLint, internalformat: GLenum, width: GLsizei, border: GLint, imageSize: GLsizei, data: *const c_void);
    todo glCompressedTexImage2D(target: GLenum, level: GLint, internalformat: GLenum, width: GLsizei, height: GLsizei, border: GLint, imageSize: GLsizei, data: *const c_void);
    todo glCompressedTexImage3D(target: GLenum, level: GLint, internalformat: GLenum, width: GLsizei, height: GLsizei, depth: GLsizei, border: GLint, imageSize: GLsizei, data: *const c_void);
    todo glCompressedTexSubImage1D(target: GLenum, level: GLint, xoffset: GLint, width: GLsizei, format: GLenum, imageSize: GLsizei, data: *const c_void);
    todo glCompressedTexSubImage2D(target: GLenum, level: GLint, xoffset: GLint, yoffset: GLint, width: GLsizei, height: GLsizei, format: GLenum, imageSize: GLsizei, data: *const c_void);
    todo glCompressedTexSubImage3D(target: GLenum, level: GLint, xoffset: GLint, yoffset: GLint, zoffset: GLint, width: GLsizei, height: GLsizei, depth: GLsizei, format: GLenum, imageSize: GLsizei, data: *const c_void);
    todo glGetCompressedTexImage(target: GLenum, level: GLint, img: *mut c_void);
    list glBlendFuncSeparate(sfactorRGB: GLenum, dfactorRGB: GLenum, sfactorAlpha: GLenum, dfactorAlpha: GLenum) { |_c| Command::BlendFunc([sfactorRGB, dfactorRGB, sfactorAlpha, dfactorAlpha]) }
    todo glFogCoordf(coord: GLfloat);
    todo glFogCoordfv(coord: *const GLfloat);
    todo glFogCoordd(coord: GLdouble);
    todo glFogCoorddv(coord: *const GLdouble);
    todo glFogCoordPointer(type_: GLenum, stride: GLsizei, pointer: *const c_void);
    todo glMultiDrawArrays(mode: GLenum, first: *const GLint, count: *const GLsizei, drawcount: GLsizei);
    todo glMultiDrawElements(mode: GLenum, count: *const GLsizei, type_: GLenum, indices: *const *const c_void, drawcount: GLsizei);
    todo glPointParameterf(pname: GLenum, param: GLfloat);
    todo glPointParameterfv(pname: GLenum, params: *const GLfloat);
    todo glPointParameteri(pname: GLenum, param: GLint);
    todo glPointParameteriv(pname: GLenum, params: *const GLint);
    todo glSecondaryColor3b(red: GLbyte, green: GLbyte, blue: GLbyte);
    todo glSecondaryColor3bv(v: *const GLbyte);
    todo glSecondaryColor3d(red: GLdouble, green: GLdouble, blue: GLdouble);
    todo glSecondaryColor3dv(v: *const GLdouble);
    todo glSecondaryColor3f(red: GLfloat, green: GLfloat, blue: GLfloat);
    todo glSecondaryColor3fv(v: *const GLfloat);
    todo glSecondaryColor3i(red: GLint, green: GLint, blue: GLint);
    todo glSecondaryColor3iv(v: *const GLint);
    todo glSecondaryColor3s(red: GLshort, green: GLshort, blue: GLshort);
    todo glSecondaryColor3sv(v: *const GLshort);
    todo glSecondaryColor3ub(red: GLubyte, green: GLubyte, blue: GLubyte);
    todo glSecondaryColor3ubv(v: *const GLubyte);
    todo glSecondaryColor3ui(red: GLuint, green: GLuint, blue: GLuint);
    todo glSecondaryColor3uiv(v: *const GLuint);
    todo glSecondaryColor3us(red: GLushort, green: GLushort, blue: GLushort);
    todo glSecondaryColor3usv(v: *const GLushort);
    todo glSecondaryColorPointer(size: GLint, type_: GLenum, stride: GLsizei, pointer: *const c_void);
    todo glWindowPos2d(x: GLdouble, y: GLdouble);
    todo glWindowPos2dv(v: *const GLdouble);
    todo glWindowPos2f(x: GLfloat, y: GLfloat);
    todo glWindowPos2fv(v: *const GLfloat);
    todo glWindowPos2i(x: GLint, y: GLint);
    todo glWindowPos2iv(v: *const GLint);
    todo glWindowPos2s(x: GLshort, y: GLshort);
    todo glWindowPos2sv(v: *const GLshort);
    todo glWindowPos3d(x: GLdouble, y: GLdouble, z: GLdouble);
    todo glWindowPos3dv(v: *const GLdouble);
    todo glWindowPos3f(x: GLfloat, y: GLfloat, z: GLfloat);
    todo glWindowPos3fv(v: *const GLfloat);
    todo glWindowPos3i(x: GLint, y: GLint, z: GLint);
    todo glWindowPos3iv(v: *const GLint);
    todo glWindowPos3s(x: GLshort, y: GLshort, z: GLshort);
    todo glWindowPos3sv(v: *const GLshort);
    todo glGenQueries(n: GLsizei, ids: *mut GLuint);
    todo glDeleteQueries(n: GLsizei, ids: *const GLuint);
    todo glIsQuery(id: GLuint) -> GLboolean;
    todo glBeginQuery(target: GLenum, id: GLuint);
    todo glEndQuery(target: GLenum);
    todo glGetQueryiv(target: GLenum, pname: GLenum, params: *mut GLint);
    todo glGetQueryObjectiv(id: GLuint, pname: GLenum, params: *mut GLint);
    todo glGetQueryObjectuiv(id: GLuint, pname: GLenum, params: *mut GLuint);
    todo glBindBuffer(target: GLenum, buffer: GLuint);
    todo glDeleteBuffers(n: GLsizei, buffers: *const GLuint);
    todo glGenBuffers(n: GLsizei, buffers: *mut GLuint);
    todo glIsBuffer(buffer: GLuint) -> GLboolean;
    todo glBufferData(target: GLenum, size: GLsizeiptr, data: *const c_void, usage: GLenum);
    todo glBufferSubData(target: GLenum, offset: GLintptr, size: GLsizeiptr, data: *const c_void);
    todo glGetBufferSubData(target: GLenum, offset: GLintptr, size: GLsizeiptr, data: *mut c_void);
    todo glMapBuffer(target: GLenum, access: GLenum) -> *mut c_void;
    todo glUnmapBuffer(target: GLenum) -> GLboolean;
    todo glGetBufferParameteriv(target: GLenum, pname: GLenum, params: *mut GLint);
    todo glGetBufferPointerv(target: GLenum, pname: GLenum, params: *mut *mut c_void);

    // ---- glu.h ----
    free gluErrorString(error: GLenum) -> *const GLubyte { glu::strings::error_string(error) }
    free gluGetString(name: GLenum) -> *const GLubyte { glu::strings::get_string(name) }
    free gluCheckExtension(extName: *const GLubyte, extString: *const GLubyte) -> GLboolean { glu::strings::check_extension(extName, extString) }
    free gluOrtho2D(left: GLdouble, right: GLdouble, bottom: GLdouble, top: GLdouble) { glu::matrix::ortho_2d(left, right, bottom, top) }
    free gluPerspective(fovy: GLdouble, aspect: GLdouble, zNear: GLdouble, zFar: GLdouble) { glu::matrix::perspective(fovy, aspect, zNear, zFar) }
    free gluLookAt(eyeX: GLdouble, eyeY: GLdouble, eyeZ: GLdouble, centerX: GLdouble, centerY: GLdouble, centerZ: GLdouble, upX: GLdouble, upY: GLdouble, upZ: GLdouble) { glu::matrix::look_at([eyeX, eyeY, eyeZ], [centerX, centerY, centerZ], [upX, upY, upZ]) }
    free gluPickMatrix(x: GLdouble, y: GLdouble, delX: GLdouble, delY: GLdouble, viewport: *mut GLint) { glu::matrix::pick_matrix(x, y, delX, delY, viewport) }
    free gluProject(objX: GLdouble, objY: GLdouble, objZ: GLdouble, model: *const GLdouble, proj: *const GLdouble, view: *const GLint, winX: *mut GLdouble, winY: *mut GLdouble, winZ: *mut GLdouble) -> GLint { glu::matrix::project([objX, objY, objZ], model, proj, view, [winX, winY, winZ]) }
    free gluUnProject(winX: GLdouble, winY: GLdouble, winZ: GLdouble, model: *const GLdouble, proj: *const GLdouble, view: *const GLint, objX: *mut GLdouble, objY: *mut GLdouble, objZ: *mut GLdouble) -> GLint { glu::matrix::unproject([winX, winY, winZ, 1.0], model, proj, view, 0.0, 1.0, [objX, objY, objZ, std::ptr::null_mut()]) }
    free gluUnProject4(winX: GLdouble, winY: GLdouble, winZ: GLdouble, clipW: GLdouble, model: *const GLdouble, proj: *const GLdouble, view: *const GLint, nearVal: GLdouble, farVal: GLdouble, objX: *mut GLdouble, objY: *mut GLdouble, objZ: *mut GLdouble, objW: *mut GLdouble) -> GLint { glu::matrix::unproject([winX, winY, winZ, clipW], model, proj, view, nearVal, farVal, [objX, objY, objZ, objW]) }
    free gluScaleImage(format: GLenum, wIn: GLsizei, hIn: GLsizei, typeIn: GLenum, dataIn: *const c_void, wOut: GLsizei, hOut: GLsizei, typeOut: GLenum, dataOut: *mut c_void) -> GLint { glu::scale::scale_image(&mut glu::scale::GlPixels, format, wIn, hIn, typeIn, dataIn, wOut, hOut, typeOut, dataOut) }
    free gluBuild1DMipmaps(target: GLenum, internalFormat: GLint, width: GLsizei, format: GLenum, type_: GLenum, data: *const c_void) -> GLint { glu::mipmap::build_mipmaps(&mut glu::mipmap::GlTex, 1, target, internalFormat, [width, 1, 1], format, type_, data) }
    free gluBuild2DMipmaps(target: GLenum, internalFormat: GLint, width: GLsizei, height: GLsizei, format: GLenum, type_: GLenum, data: *const c_void) -> GLint { glu::mipmap::build_mipmaps(&mut glu::mipmap::GlTex, 2, target, internalFormat, [width, height, 1], format, type_, data) }
    free gluBuild3DMipmaps(target: GLenum, internalFormat: GLint, width: GLsizei, height: GLsizei, depth: GLsizei, format: GLenum, type_: GLenum, data: *const c_void) -> GLint { glu::mipmap::build_mipmaps(&mut glu::mipmap::GlTex, 3, target, internalFormat, [width, height, depth], format, type_, data) }
    free gluBuild1DMipmapLevels(target: GLenum, internalFormat: GLint, width: GLsizei, format: GLenum, type_: GLenum, level: GLint, base: GLint, max: GLint, data: *const c_void) -> GLint { glu::mipmap::build_mipmap_levels(&mut glu::mipmap::GlTex, 1, target, internalFormat, [width, 1, 1], format, type_, level, base, max, data) }
    free gluBuild2DMipmapLevels(target: GLenum, internalFormat: GLint, width: GLsizei, height: GLsizei, format: GLenum, type_: GLenum, level: GLint, base: GLint, max: GLint, data: *const c_void) -> GLint { glu::mipmap::build_mipmap_levels(&mut glu::mipmap::GlTex, 2, target, internalFormat, [width, height, 1], format, type_, level, base, max, data) }
    free gluBuild3DMipmapLevels(target: GLenum, internalFormat: GLint, width: GLsizei, height: GLsizei, depth: GLsizei, format: GLenum, type_: GLenum, level: GLint, base: GLint, max: GLint, data: *const c_void) -> GLint { glu::mipmap::build_mipmap_levels(&mut glu::mipmap::GlTex, 3, target, internalFormat, [width, height, depth], format, type_, level, base, max, data) }
    free gluNewQuadric() -> *mut GLUquadric { glu::quadric::new_quadric() }
    free gluDeleteQuadric(quad: *mut GLUquadric) { glu::quadric::delete_quadric(quad) }
    free gluQuadricCallback(quad: *mut GLUquadric, which: GLenum, CallBackFunc: GLproc) { glu::quadric::with(quad, |q| q.set_callback(which, CallBackFunc)) }
    free gluQuadricDrawStyle(quad: *mut GLUquadric, draw: GLenum) { glu::quadric::with(quad, |q| q.set_draw_style(draw)) }
    free gluQuadricNormals(quad: *mut GLUquadric, normal: GLenum) { glu::quadric::with(quad, |q| q.set_normals(normal)) }
    free gluQuadricOrientation(quad: *mut GLUquadric, orientation: GLenum) { glu::quadric::with(quad, |q| q.set_orientation(orientation)) }
    free gluQuadricTexture(quad: *mut GLUquadric, texture: GLboolean) { glu::quadric::with(quad, |q| q.set_texture(truth(texture))) }
    free gluSphere(quad: *mut GLUquadric, radius: GLdouble, slices: GLint, stacks: GLint) { glu::quadric::with(quad, |q| q.sphere(&mut glu::quadric::GlSink, radius, slices, stacks)) }
    free gluCylinder(quad: *mut GLUquadric, base: GLdouble, top: GLdouble, height: GLdouble, slices: GLint, stacks: GLint) { glu::quadric::with(quad, |q| q.cylinder(&mut glu::quadric::GlSink, base, top, height, slices, stacks)) }
    free gluDisk(quad: *mut GLUquadric, inner: GLdouble, outer: GLdouble, slices: GLint, loops: GLint) { glu::quadric::with(quad, |q| q.disk(&mut glu::quadric::GlSink, inner, outer, slices, loops)) }
    free gluPartialDisk(quad: *mut GLUquadric, inner: GLdouble, outer: GLdouble, slices: GLint, loops: GLint, start: GLdouble, sweep: GLdouble) { glu::quadric::with(quad, |q| q.partial_disk(&mut glu::quadric::GlSink, inner, outer, slices, loops, start, sweep)) }
    todo gluNewTess() -> *mut GLUtesselator;
    todo gluDeleteTess(tess: *mut GLUtesselator);
    todo gluTessBeginPolygon(tess: *mut GLUtesselator, data: *mut c_void);
    todo gluTessBeginContour(tess: *mut GLUtesselator);
    todo gluTessVertex(tess: *mut GLUtesselator, location: *mut GLdouble, data: *mut c_void);
    todo gluTessEndContour(tess: *mut GLUtesselator);
    todo gluTessEndPolygon(tess: *mut GLUtesselator);
    todo gluTessCallback(tess: *mut GLUtesselator, which: GLenum, CallBackFunc: GLproc);
    todo gluTessProperty(tess: *mut GLUtesselator, which: GLenum, data: GLdouble);
    todo gluGetTessProperty(tess: *mut GLUtesselator, which: GLenum, data: *mut GLdouble);
    todo gluTessNormal(tess: *mut GLUtesselator, valueX: GLdouble, valueY: GLdouble, valueZ: GLdouble);
    todo gluBeginPolygon(tess: *mut GLUtesselator);
    todo gluNextContour(tess: *mut GLUtesselator, type_: GLenum);
    todo gluEndPolygon(tess: *mut GLUtesselator);
    free gluNewNurbsRenderer() -> *mut GLUnurbs { glu::nurbs::new_nurbs() }
    free gluDeleteNurbsRenderer(nurb: *mut GLUnurbs) { glu::nurbs::delete_nurbs(nurb) }
    free gluNurbsProperty(nurb: *mut GLUnurbs, property: GLenum, value: GLfloat) { glu::nurbs::with(nurb, |n| n.set_property(property, value)) }
    free gluGetNurbsProperty(nurb: *mut GLUnurbs, property: GLenum, data: *mut GLfloat) { glu::nurbs::get_property(nurb, property, data) }
    free gluLoadSamplingMatrices(nurb: *mut GLUnurbs, model: *const GLfloat, perspective: *const GLfloat, view: *const GLint) { glu::nurbs::with(nurb, |n| n.load_sampling_matrices(model, perspective, view)) }
    free gluNurbsCallback(nurb: *mut GLUnurbs, which: GLenum, CallBackFunc: GLproc) { glu::nurbs::with(nurb, |n| n.set_callback(which, CallBackFunc)) }
    free gluNurbsCallbackData(nurb: *mut GLUnurbs, userData: *mut c_void) { glu::nurbs::with(nurb, |n| n.set_callback_data(userData)) }
    free gluNurbsCallbackDataEXT(nurb: *mut GLUnurbs, userData: *mut c_void) { glu::nurbs::with(nurb, |n| n.set_callback_data(userData)) }
    free gluBeginCurve(nurb: *mut GLUnurbs) { glu::nurbs::with(nurb, |n| n.begin_curve()) }
    free gluNurbsCurve(nurb: *mut GLUnurbs, knotCount: GLint, knots: *mut GLfloat, stride: GLint, control: *mut GLfloat, order: GLint, type_: GLenum) { glu::nurbs::with(nurb, |n| n.nurbs_curve(knotCount, knots, stride, control, order, type_)) }
    free gluEndCurve(nurb: *mut GLUnurbs) { glu::nurbs::with(nurb, |n| n.end_curve()) }
    free gluBeginSurface(nurb: *mut GLUnurbs) { glu::nurbs::with(nurb, |n| n.begin_surface()) }
    free gluNurbsSurface(nurb: *mut GLUnurbs, sKnotCount: GLint, sKnots: *mut GLfloat, tKnotCount: GLint, tKnots: *mut GLfloat, sStride: GLint, tStride: GLint, control: *mut GLfloat, sOrder: GLint, tOrder: GLint, type_: GLenum) { glu::nurbs::with(nurb, |n| n.nurbs_surface(sKnotCount, sKnots, tKnotCount, tKnots, sStride, tStride, control, sOrder, tOrder, type_)) }
    free gluEndSurface(nurb: *mut GLUnurbs) { glu::nurbs::with(nurb, |n| n.end_surface()) }
    free gluBeginTrim(nurb: *mut GLUnurbs) { glu::nurbs::with(nurb, |n| n.begin_trim()) }
    free gluPwlCurve(nurb: *mut GLUnurbs, count: GLint, data: *mut GLfloat, stride: GLint, type_: GLenum) { glu::nurbs::with(nurb, |n| n.pwl_curve(count, data, stride, type_)) }
    free gluEndTrim(nurb: *mut GLUnurbs) { glu::nurbs::with(nurb, |n| n.end_trim()) }

    // ---- osmesa.h ----
    free["the share-list argument is accepted but lists are not shared yet"] OSMesaCreateContext(format: GLenum, sharelist: *mut OsContext) -> *mut OsContext { osmesa::create_context_ext(format, 24, 8, 0, sharelist) }
    free["as OSMesaCreateContext"] OSMesaCreateContextExt(format: GLenum, depthBits: GLint, stencilBits: GLint, accumBits: GLint, sharelist: *mut OsContext) -> *mut OsContext { osmesa::create_context_ext(format, depthBits, stencilBits, accumBits, sharelist) }
    free["as OSMesaCreateContext"] OSMesaCreateContextAttribs(attribList: *const i32, sharelist: *mut OsContext) -> *mut OsContext { osmesa::create_context_attribs(attribList, sharelist) }
    free OSMesaDestroyContext(ctx: *mut OsContext) { osmesa::destroy_context(ctx) }
    free OSMesaMakeCurrent(ctx: *mut OsContext, buffer: *mut c_void, type_: GLenum, width: GLsizei, height: GLsizei) -> GLboolean { gl_bool(osmesa::make_current(ctx, buffer, type_, width, height)) }
    free OSMesaGetCurrentContext() -> *mut OsContext { osmesa::current_context() }
    free OSMesaPixelStore(pname: GLint, value: GLint) { osmesa::pixel_store(pname, value) }
    free OSMesaGetIntegerv(pname: GLint, value: *mut GLint) { if let (Some(v), false) = (osmesa::get_integer(pname), value.is_null()) { *value = v } }
    free OSMesaGetDepthBuffer(c: *mut OsContext, width: *mut GLint, height: *mut GLint, bytesPerValue: *mut GLint, buffer: *mut *mut c_void) -> GLboolean { gl_bool(osmesa::get_depth_buffer(c, width, height, bytesPerValue, buffer)) }
    free OSMesaGetColorBuffer(c: *mut OsContext, width: *mut GLint, height: *mut GLint, format: *mut GLint, buffer: *mut *mut c_void) -> GLboolean { gl_bool(osmesa::get_color_buffer(c, width, height, format, buffer)) }
    free OSMesaGetProcAddress(funcName: *const c_char) -> GLproc { proc_from_name(funcName) }
    todo OSMesaColorClamp(enable: GLboolean);
    todo OSMesaPostprocess(osmesa: *mut OsContext, filter: *const c_char, enable_value: u32);

    // ---- glx.h ----
    free glXQueryExtension(dpy: *mut Display, errorBase: *mut c_int, eventBase: *mut c_int) -> Bool { glx::query_extension(dpy, errorBase, eventBase) }
    free glXQueryVersion(dpy: *mut Display, major: *mut c_int, minor: *mut c_int) -> Bool { glx::query_version(dpy, major, minor) }
    free glXQueryExtensionsString(dpy: *mut Display, screen: c_int) -> *const c_char { glx::query_extensions_string(dpy, screen) }
    free glXQueryServerString(dpy: *mut Display, screen: c_int, name: c_int) -> *const c_char { glx::query_server_string(dpy, screen, name) }
    free glXGetClientString(dpy: *mut Display, name: c_int) -> *const c_char { glx::get_client_string(dpy, name) }
    free["double buffering is per visual as glXChooseVisual was last asked; no colour-index, stereo or multisample visuals"] glXChooseVisual(dpy: *mut Display, screen: c_int, attribList: *mut c_int) -> *mut XVisualInfo { glx::choose_visual(dpy, screen, attribList) }
    free glXGetConfig(dpy: *mut Display, vis: *mut XVisualInfo, attrib: c_int, value: *mut c_int) -> c_int { glx::get_config(dpy, vis, attrib, value) }
    free["the share list is accepted but display lists are not shared yet"] glXCreateContext(dpy: *mut Display, vis: *mut XVisualInfo, shareList: GLXContext, direct: Bool) -> GLXContext { glx::create_context(dpy, vis, shareList, direct) }
    free glXDestroyContext(dpy: *mut Display, ctx: GLXContext) { glx::destroy_context(dpy, ctx) }
    free["GL_FRONT and GL_BACK are one colour buffer"] glXMakeCurrent(dpy: *mut Display, drawable: GLXDrawable, ctx: GLXContext) -> Bool { glx::make_current(dpy, drawable, ctx) }
    todo glXCopyContext(dpy: *mut Display, src: GLXContext, dst: GLXContext, mask: std::ffi::c_ulong);
    free["shows the one colour buffer (no separate front buffer yet); XPutImage, no MIT-SHM"] glXSwapBuffers(dpy: *mut Display, drawable: GLXDrawable) { glx::swap_buffers(dpy, drawable) }
    free glXCreateGLXPixmap(dpy: *mut Display, visual: *mut XVisualInfo, pixmap: XID) -> GLXDrawable { glx::create_pixmap(dpy, if visual.is_null() { 0 } else { pixmap }) }
    free glXDestroyGLXPixmap(dpy: *mut Display, pixmap: GLXDrawable) { glx::destroy_pixmap(dpy, pixmap) }
    free glXIsDirect(dpy: *mut Display, ctx: GLXContext) -> Bool { glx::is_direct(dpy, ctx) }
    free glXGetCurrentContext() -> GLXContext { glx::get_current_context() }
    free glXGetCurrentDrawable() -> GLXDrawable { glx::get_current_drawable() }
    free glXWaitGL() { glx::wait_gl() }
    free glXWaitX() { glx::wait_x() }
    todo glXUseXFont(font: XID, first: c_int, count: c_int, list: c_int);
    free glXGetCurrentDisplay() -> *mut Display { glx::get_current_display() }
    free["no pbuffer configs"] glXChooseFBConfig(dpy: *mut Display, screen: c_int, attribList: *const c_int, nitems: *mut c_int) -> *mut GLXFBConfig { glx::choose_fb_config(dpy, screen, attribList, nitems) }
    free glXGetFBConfigAttrib(dpy: *mut Display, config: GLXFBConfig, attribute: c_int, value: *mut c_int) -> c_int { glx::get_fb_config_attrib(dpy, config, attribute, value) }
    free glXGetFBConfigs(dpy: *mut Display, screen: c_int, nelements: *mut c_int) -> *mut GLXFBConfig { glx::get_fb_configs(dpy, screen, nelements) }
    free glXGetVisualFromFBConfig(dpy: *mut Display, config: GLXFBConfig) -> *mut XVisualInfo { glx::get_visual_from_fb_config(dpy, config) }
    free glXCreateWindow(dpy: *mut Display, config: GLXFBConfig, win: XID, attribList: *const c_int) -> GLXDrawable { glx::create_window(dpy, config, win, attribList) }
    free glXDestroyWindow(dpy: *mut Display, win: GLXDrawable) { glx::destroy_window(dpy, win) }
    free glXCreatePixmap(dpy: *mut Display, config: GLXFBConfig, pixmap: XID, attribList: *const c_int) -> GLXDrawable { glx::create_fb_pixmap(dpy, config, pixmap, attribList) }
    free glXDestroyPixmap(dpy: *mut Display, pixmap: GLXDrawable) { glx::destroy_pixmap(dpy, pixmap) }
    todo glXCreatePbuffer(dpy: *mut Display, config: GLXFBConfig, attribList: *const c_int) -> GLXDrawable;
    todo glXDestroyPbuffer(dpy: *mut Display, pbuf: GLXDrawable);
    free["GLX_WIDTH and GLX_HEIGHT only"] glXQueryDrawable(dpy: *mut Display, draw: GLXDrawable, attribute: c_int, value: *mut std::ffi::c_uint) { glx::query_drawable(dpy, draw, attribute, value) }
    free["the share list is accepted but display lists are not shared yet"] glXCreateNewContext(dpy: *mut Display, config: GLXFBConfig, renderType: c_int, shareList: GLXContext, direct: Bool) -> GLXContext { glx::create_new_context(dpy, config, renderType, shareList, direct) }
    free["the read drawable must be the draw drawable's framebuffer: reads come from the draw drawable"] glXMakeContextCurrent(dpy: *mut Display, draw: GLXDrawable, read: GLXDrawable, ctx: GLXContext) -> Bool { glx::make_context_current(dpy, draw, read, ctx) }
    free glXGetCurrentReadDrawable() -> GLXDrawable { glx::get_current_read_drawable() }
    free["GLX_FBCONFIG_ID, GLX_RENDER_TYPE and GLX_SCREEN"] glXQueryContext(dpy: *mut Display, ctx: GLXContext, attribute: c_int, value: *mut c_int) -> c_int { glx::query_context(dpy, ctx, attribute, value) }
    todo glXSelectEvent(dpy: *mut Display, draw: GLXDrawable, event_mask: std::ffi::c_ulong);
    todo glXGetSelectedEvent(dpy: *mut Display, draw: GLXDrawable, event_mask: *mut std::ffi::c_ulong);
    free glXGetProcAddressARB(procName: *const GLubyte) -> GLproc { proc_from_name(procName as *const c_char) }
    free glXGetProcAddress(procName: *const GLubyte) -> GLproc { proc_from_name(procName as *const c_char) }
}
