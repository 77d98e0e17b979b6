//! gluErrorString, gluGetString, gluCheckExtension (GLU 1.3 sections 2 and 3).

use crate::api::types::*;
use crate::gl::enums::*;

pub const GLU_VERSION: u32 = 100800;
pub const GLU_EXTENSIONS: u32 = 100801;
pub const GLU_INVALID_ENUM: u32 = 100900;
pub const GLU_INVALID_VALUE: u32 = 100901;
pub const GLU_OUT_OF_MEMORY: u32 = 100902;
pub const GLU_INVALID_OPERATION: u32 = 100904;

/// Strings for GL and GLU error codes (NULL for an unknown code).
pub fn error_string(e: GLenum) -> *const GLubyte {
    let s: &'static [u8] = match e {
        GL_NO_ERROR => b"no error\0",
        GL_INVALID_ENUM => b"invalid enumerant\0",
        GL_INVALID_VALUE => b"invalid value\0",
        GL_INVALID_OPERATION => b"invalid operation\0",
        GL_STACK_OVERFLOW => b"stack overflow\0",
        GL_STACK_UNDERFLOW => b"stack underflow\0",
        GL_OUT_OF_MEMORY => b"out of memory\0",
        GLU_INVALID_ENUM => b"invalid enumerant\0",
        GLU_INVALID_VALUE => b"invalid value\0",
        GLU_OUT_OF_MEMORY => b"out of memory\0",
        GLU_INVALID_OPERATION => b"invalid operation\0",
        100101..=100110 => b"tessellation error\0",
        100251..=100287 => b"NURBS error\0",
        _ => return std::ptr::null(),
    };
    s.as_ptr()
}

pub fn get_string(name: GLenum) -> *const GLubyte {
    match name {
        GLU_VERSION => b"1.3 softgl\0".as_ptr(),
        GLU_EXTENSIONS => b"\0".as_ptr(),
        _ => std::ptr::null(),
    }
}

/// Is `name` one of the space-separated words of `list`?
///
/// # Safety
/// Both must be NULL or NUL-terminated strings.
pub unsafe fn check_extension(name: *const GLubyte, list: *const GLubyte) -> GLboolean {
    if name.is_null() || list.is_null() {
        return 0;
    }
    let name = std::ffi::CStr::from_ptr(name as *const _).to_bytes();
    let list = std::ffi::CStr::from_ptr(list as *const _).to_bytes();
    gl_bool(!name.is_empty() && list.split(|&b| b == b' ').any(|w| w == name))
}
