//! The C types of the GL, GLU and OSMesa APIs, as Rust aliases (gl.h's typedefs).
#![allow(non_camel_case_types)]

use std::ffi::c_void;

pub type GLenum = u32;
pub type GLboolean = u8;
pub type GLbitfield = u32;
pub type GLvoid = c_void;
pub type GLbyte = i8;
pub type GLshort = i16;
pub type GLint = i32;
pub type GLubyte = u8;
pub type GLushort = u16;
pub type GLuint = u32;
pub type GLsizei = i32;
pub type GLfloat = f32;
pub type GLclampf = f32;
pub type GLdouble = f64;
pub type GLclampd = f64;
pub type GLchar = std::ffi::c_char;
pub type GLintptr = isize;
pub type GLsizeiptr = isize;

/// An untyped function pointer as GetProcAddress returns it.
pub type GLproc = Option<unsafe extern "system" fn()>;

/// `GLboolean` in: any non-zero value is true (Delphi passes 0xFF).
#[inline]
pub fn truth(b: GLboolean) -> bool {
    b != 0
}

/// `GLboolean` out.
#[inline]
pub fn gl_bool(b: bool) -> GLboolean {
    b as GLboolean
}
