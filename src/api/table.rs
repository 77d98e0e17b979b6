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
use crate::gl::{get, lists::decode_names, Command};
use crate::glu;
use crate::winsys::osmesa::{self, OsContext};
use std::ffi::{c_char, c_void};

/// GLU's opaque object types, as C sees them.
pub type GLUquadric = c_void;
pub type GLUtesselator = c_void;
pub type GLUnurbs = c_void;

/// A column-major GL matrix.
fn matrix(m: [f64; 16]) -> glam::DMat4 {
    glam::DMat4::from_cols_array(&m)
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
    list["GL_POINTS, GL_LINES, GL_LINE_STRIP and GL_LINE_LOOP are accepted but not rasterized yet (issue 3)"] glBegin(mode: GLenum) { |_c| Command::Begin(mode) }
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
    todo glNormal3b(nx: GLbyte, ny: GLbyte, nz: GLbyte);
    todo glNormal3bv(v: *const GLbyte);
    todo glNormal3d(nx: GLdouble, ny: GLdouble, nz: GLdouble);
    todo glNormal3dv(v: *const GLdouble);
    todo glNormal3f(nx: GLfloat, ny: GLfloat, nz: GLfloat);
    todo glNormal3fv(v: *const GLfloat);
    todo glNormal3i(nx: GLint, ny: GLint, nz: GLint);
    todo glNormal3iv(v: *const GLint);
    todo glNormal3s(nx: GLshort, ny: GLshort, nz: GLshort);
    todo glNormal3sv(v: *const GLshort);
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
    todo glMaterialf(face: GLenum, pname: GLenum, param: GLfloat);
    todo glMaterialfv(face: GLenum, pname: GLenum, params: *const GLfloat);
    todo glMateriali(face: GLenum, pname: GLenum, param: GLint);
    todo glMaterialiv(face: GLenum, pname: GLenum, params: *const GLint);
    todo glLightf(light: GLenum, pname: GLenum, param: GLfloat);
    todo glLightfv(light: GLenum, pname: GLenum, params: *const GLfloat);
    todo glLighti(light: GLenum, pname: GLenum, param: GLint);
    todo glLightiv(light: GLenum, pname: GLenum, params: *const GLint);
    todo glLightModelf(pname: GLenum, param: GLfloat);
    todo glLightModelfv(pname: GLenum, params: *const GLfloat);
    todo glLightModeli(pname: GLenum, param: GLint);
    todo glLightModeliv(pname: GLenum, params: *const GLint);
    todo glColorMaterial(face: GLenum, mode: GLenum);
    list glShadeModel(mode: GLenum) { |_c| Command::ShadeModel(mode) }
    todo glPointSize(size: GLfloat);
    todo glLineWidth(width: GLfloat);
    todo glLineStipple(factor: GLint, pattern: GLushort);
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
    todo glAlphaFunc(func: GLenum, ref_: GLclampf);
    todo glStencilFunc(func: GLenum, ref_: GLint, mask: GLuint);
    todo glStencilOp(fail: GLenum, zfail: GLenum, zpass: GLenum);
    list glDepthFunc(func: GLenum) { |_c| Command::DepthFunc(func) }
    todo glBlendFunc(sfactor: GLenum, dfactor: GLenum);
    todo glLogicOp(opcode: GLenum);
    todo glDrawBuffer(mode: GLenum);
    todo glIndexMask(mask: GLuint);
    list glColorMask(red: GLboolean, green: GLboolean, blue: GLboolean, alpha: GLboolean) { |_c| Command::ColorMask([truth(red), truth(green), truth(blue), truth(alpha)]) }
    list glDepthMask(flag: GLboolean) { |_c| Command::DepthMask(truth(flag)) }
    list["applies to glClear; the stencil test arrives with issue 3"] glStencilMask(mask: GLuint) { |_c| Command::StencilMask(mask) }
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
    list["capabilities other than DEPTH_TEST, SCISSOR_TEST, CULL_FACE and DITHER are stored and queryable but do not affect rendering yet"] glEnable(cap: GLenum) { |_c| Command::Enable(cap) }
    list["see glEnable"] glDisable(cap: GLenum) { |_c| Command::Disable(cap) }
    exec["as glEnable"] glIsEnabled(cap: GLenum) -> GLboolean { |c| match c.is_enabled(cap) { Some(b) => gl_bool(b), None => { c.set_error(GL_INVALID_ENUM); 0 } } }
    exec["as glGetIntegerv"] glGetBooleanv(pname: GLenum, params: *mut GLboolean) { |c| c.get_into(pname, params, |v| v.as_bool().into_iter().map(gl_bool).collect()) }
    exec["answers the state implemented so far; other names give GL_INVALID_ENUM"] glGetIntegerv(pname: GLenum, params: *mut GLint) { |c| c.get_into(pname, params, get::Value::as_i32) }
    exec["as glGetIntegerv"] glGetFloatv(pname: GLenum, params: *mut GLfloat) { |c| c.get_into(pname, params, |v| v.as_f64().into_iter().map(|x| x as f32).collect()) }
    exec["as glGetIntegerv"] glGetDoublev(pname: GLenum, params: *mut GLdouble) { |c| c.get_into(pname, params, get::Value::as_f64) }
    todo glGetPointerv(pname: GLenum, params: *mut *mut c_void);
    todo glGetClipPlane(plane: GLenum, equation: *mut GLdouble);
    todo glGetLightfv(light: GLenum, pname: GLenum, params: *mut GLfloat);
    todo glGetLightiv(light: GLenum, pname: GLenum, params: *mut GLint);
    todo glGetMaterialfv(face: GLenum, pname: GLenum, params: *mut GLfloat);
    todo glGetMaterialiv(face: GLenum, pname: GLenum, params: *mut GLint);
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
    todo glBlendColor(red: GLclampf, green: GLclampf, blue: GLclampf, alpha: GLclampf);
    todo glBlendEquation(mode: GLenum);
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
    todo glBlendFuncSeparate(sfactorRGB: GLenum, dfactorRGB: GLenum, sfactorAlpha: GLenum, dfactorAlpha: GLenum);
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
    todo gluScaleImage(format: GLenum, wIn: GLsizei, hIn: GLsizei, typeIn: GLenum, dataIn: *const c_void, wOut: GLsizei, hOut: GLsizei, typeOut: GLenum, dataOut: *mut c_void) -> GLint;
    todo gluBuild1DMipmaps(target: GLenum, internalFormat: GLint, width: GLsizei, format: GLenum, type_: GLenum, data: *const c_void) -> GLint;
    todo gluBuild2DMipmaps(target: GLenum, internalFormat: GLint, width: GLsizei, height: GLsizei, format: GLenum, type_: GLenum, data: *const c_void) -> GLint;
    todo gluBuild3DMipmaps(target: GLenum, internalFormat: GLint, width: GLsizei, height: GLsizei, depth: GLsizei, format: GLenum, type_: GLenum, data: *const c_void) -> GLint;
    todo gluBuild1DMipmapLevels(target: GLenum, internalFormat: GLint, width: GLsizei, format: GLenum, type_: GLenum, level: GLint, base: GLint, max: GLint, data: *const c_void) -> GLint;
    todo gluBuild2DMipmapLevels(target: GLenum, internalFormat: GLint, width: GLsizei, height: GLsizei, format: GLenum, type_: GLenum, level: GLint, base: GLint, max: GLint, data: *const c_void) -> GLint;
    todo gluBuild3DMipmapLevels(target: GLenum, internalFormat: GLint, width: GLsizei, height: GLsizei, depth: GLsizei, format: GLenum, type_: GLenum, level: GLint, base: GLint, max: GLint, data: *const c_void) -> GLint;
    todo gluNewQuadric() -> *mut GLUquadric;
    todo gluDeleteQuadric(quad: *mut GLUquadric);
    todo gluQuadricCallback(quad: *mut GLUquadric, which: GLenum, CallBackFunc: GLproc);
    todo gluQuadricDrawStyle(quad: *mut GLUquadric, draw: GLenum);
    todo gluQuadricNormals(quad: *mut GLUquadric, normal: GLenum);
    todo gluQuadricOrientation(quad: *mut GLUquadric, orientation: GLenum);
    todo gluQuadricTexture(quad: *mut GLUquadric, texture: GLboolean);
    todo gluSphere(quad: *mut GLUquadric, radius: GLdouble, slices: GLint, stacks: GLint);
    todo gluCylinder(quad: *mut GLUquadric, base: GLdouble, top: GLdouble, height: GLdouble, slices: GLint, stacks: GLint);
    todo gluDisk(quad: *mut GLUquadric, inner: GLdouble, outer: GLdouble, slices: GLint, loops: GLint);
    todo gluPartialDisk(quad: *mut GLUquadric, inner: GLdouble, outer: GLdouble, slices: GLint, loops: GLint, start: GLdouble, sweep: GLdouble);
    free gluNewTess() -> *mut GLUtesselator { glu::tess::new_tess() }
    free gluDeleteTess(tess: *mut GLUtesselator) { glu::tess::delete_tess(tess) }
    free gluTessBeginPolygon(tess: *mut GLUtesselator, data: *mut c_void) { glu::tess::begin_polygon(tess, data) }
    free gluTessBeginContour(tess: *mut GLUtesselator) { glu::tess::begin_contour(tess) }
    free gluTessVertex(tess: *mut GLUtesselator, location: *mut GLdouble, data: *mut c_void) { glu::tess::vertex(tess, location, data) }
    free gluTessEndContour(tess: *mut GLUtesselator) { glu::tess::end_contour(tess) }
    free gluTessEndPolygon(tess: *mut GLUtesselator) { glu::tess::end_polygon(tess) }
    free gluTessCallback(tess: *mut GLUtesselator, which: GLenum, CallBackFunc: GLproc) { glu::tess::callback(tess, which, CallBackFunc) }
    free gluTessProperty(tess: *mut GLUtesselator, which: GLenum, data: GLdouble) { glu::tess::property(tess, which, data) }
    free gluGetTessProperty(tess: *mut GLUtesselator, which: GLenum, data: *mut GLdouble) { glu::tess::get_property(tess, which, data) }
    free gluTessNormal(tess: *mut GLUtesselator, valueX: GLdouble, valueY: GLdouble, valueZ: GLdouble) { glu::tess::normal(tess, valueX, valueY, valueZ) }
    free gluBeginPolygon(tess: *mut GLUtesselator) { glu::tess::begin_polygon_11(tess) }
    free gluNextContour(tess: *mut GLUtesselator, type_: GLenum) { glu::tess::next_contour(tess, type_) }
    free gluEndPolygon(tess: *mut GLUtesselator) { glu::tess::end_polygon_11(tess) }
    todo gluNewNurbsRenderer() -> *mut GLUnurbs;
    todo gluDeleteNurbsRenderer(nurb: *mut GLUnurbs);
    todo gluNurbsProperty(nurb: *mut GLUnurbs, property: GLenum, value: GLfloat);
    todo gluGetNurbsProperty(nurb: *mut GLUnurbs, property: GLenum, data: *mut GLfloat);
    todo gluLoadSamplingMatrices(nurb: *mut GLUnurbs, model: *const GLfloat, perspective: *const GLfloat, view: *const GLint);
    todo gluNurbsCallback(nurb: *mut GLUnurbs, which: GLenum, CallBackFunc: GLproc);
    todo gluNurbsCallbackData(nurb: *mut GLUnurbs, userData: *mut c_void);
    todo gluNurbsCallbackDataEXT(nurb: *mut GLUnurbs, userData: *mut c_void);
    todo gluBeginCurve(nurb: *mut GLUnurbs);
    todo gluNurbsCurve(nurb: *mut GLUnurbs, knotCount: GLint, knots: *mut GLfloat, stride: GLint, control: *mut GLfloat, order: GLint, type_: GLenum);
    todo gluEndCurve(nurb: *mut GLUnurbs);
    todo gluBeginSurface(nurb: *mut GLUnurbs);
    todo gluNurbsSurface(nurb: *mut GLUnurbs, sKnotCount: GLint, sKnots: *mut GLfloat, tKnotCount: GLint, tKnots: *mut GLfloat, sStride: GLint, tStride: GLint, control: *mut GLfloat, sOrder: GLint, tOrder: GLint, type_: GLenum);
    todo gluEndSurface(nurb: *mut GLUnurbs);
    todo gluBeginTrim(nurb: *mut GLUnurbs);
    todo gluPwlCurve(nurb: *mut GLUnurbs, count: GLint, data: *mut GLfloat, stride: GLint, type_: GLenum);
    todo gluEndTrim(nurb: *mut GLUnurbs);

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
}
