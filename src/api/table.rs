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
use crate::gl::eval::read_points;
use crate::gl::fog::fog_param_count;
use crate::gl::polygon::{pack_stipple, unpack_stipple};
use crate::gl::select::NameOp;
use crate::gl::{get, lists::decode_names, Command, Context};
use crate::glu;
use crate::winsys::glx::{self, xlib::{Display, XVisualInfo}, Bool, FbConfig, GlxContext};
use crate::winsys::osmesa::{self, OsContext};
use std::ffi::{c_char, c_int, c_void};
use crate::gl::pixel_transfer::{map_index, map_value_to_uint, map_values_from_uint, MAX_PIXEL_MAP_TABLE};
use crate::gl::texture::enums::{GL_TEXTURE0 as TEX0, GL_TEXTURE_BORDER_COLOR as TBORDER, GL_TEXTURE_SWIZZLE_RGBA as TSWIZZLE_RGBA, GL_TEXTURE_ENV_COLOR as TENV_COLOR, GL_TEXTURE_GEN_MODE as TGEN_MODE};
use crate::gl::texture::CopyTexCmd;
use crate::gl::arrays::Array;
use crate::gl::imaging::ImagingCmd;

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

/// The scalar forms (glLightf, glMaterialf, glLightModelf, glFogf,
/// glPointParameterf) given a vector parameter: the spec lists only the
/// one-value names for them, but every implementation programs meet (Mesa,
/// and piglit's expectations with it) takes the value as the vector's first
/// component and zeros for the rest. softgl does the same; the caller
/// passes [param, 0, 0, 0]. A name that is no parameter at all still raises
/// GL_INVALID_ENUM in the setter, after the Begin/End rule.
fn scalar_param(_c: &mut Context, _count: usize, pname: GLenum) -> Option<GLenum> {
    Some(pname)
}

/// glSamplerParameter's vector forms: four values for the border colour
/// (integers normalized), one otherwise.
unsafe fn sampler_params_f(p: *const GLfloat, pname: GLenum) -> Option<[f32; 4]> {
    if pname == TBORDER { arr::<GLfloat, 4>(p) } else { arr::<GLfloat, 1>(p).map(|v| [v[0], 0.0, 0.0, 0.0]) }
}

unsafe fn sampler_params_i(p: *const GLint, pname: GLenum) -> Option<[f32; 4]> {
    if pname == TBORDER { arr::<GLint, 4>(p).map(|v| v.map(|x| x.normalized())) } else { arr::<GLint, 1>(p).map(|v| [v[0] as f32, 0.0, 0.0, 0.0]) }
}

/// Stores query results (NULL: nothing).
/// A scalar glTexParameter's value. TEXTURE_SWIZZLE_RGBA takes four values
/// and exists only in the vector forms: the missing three are NaN, which no
/// swizzle source matches (INVALID_ENUM).
fn scalar_tex_param(pname: GLenum, v: f32) -> [f32; 4] {
    let rest = if pname == TSWIZZLE_RGBA { f32::NAN } else { 0.0 };
    [v, rest, rest, rest]
}

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

/// glMap's command, or an error command for bad arguments (raised when it
/// executes, after the Begin/End rule).
fn map_command(r: Result<Vec<f32>, GLenum>, build: impl FnOnce(Vec<f32>) -> Command) -> Command {
    match r {
        Ok(points) => build(points),
        Err(e) => Command::Error(e),
    }
}

/// glFog*v's values: the colour maps integers like glColor, the rest
/// convert plainly.
unsafe fn read_fog<T: Component>(p: *const T, pname: GLenum) -> Option<[f32; 4]> {
    if p.is_null() {
        return None;
    }
    let n = fog_param_count(pname);
    let mut v = [0.0f32; 4];
    for (i, out) in v.iter_mut().enumerate().take(n) {
        let x = std::ptr::read_unaligned(p.add(i));
        *out = if pname == crate::gl::fog::GL_FOG_COLOR { x.normalized() } else { x.plain() };
    }
    Some(v)
}

/// glPointParameter*v's values: 3 for the attenuation, else 1.
unsafe fn point_params<T: Component>(p: *const T, pname: GLenum) -> Option<[f32; 3]> {
    if p.is_null() {
        return None;
    }
    let n = if pname == 0x8129 { 3 } else { 1 };
    let mut v = [0.0f32; 3];
    for (i, out) in v.iter_mut().enumerate().take(n) {
        *out = std::ptr::read_unaligned(p.add(i)).plain();
    }
    Some(v)
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

/// glWindowPos's command from 2 or 3 coordinates (z defaults to 0).
fn window_pos<T: Component>(v: &[T]) -> Command {
    let p = position(v);
    Command::WindowPos([p[0], p[1], p[2]])
}

/// glPixelMap's command: the map is checked and the values read (mapsize
/// of them) and converted now; an invalid map or size becomes an error
/// command. NULL values: nothing.
unsafe fn pixel_map<T: Copy>(c: &Context, map: GLenum, mapsize: GLsizei, values: *const T, conv: impl Fn(GLenum, &[T]) -> Vec<f32>) -> Option<Command> {
    if map_index(map).is_none() {
        return Some(Command::Error(GL_INVALID_ENUM));
    }
    if mapsize < 1 || mapsize as usize > MAX_PIXEL_MAP_TABLE {
        return Some(Command::Error(GL_INVALID_VALUE));
    }
    // From a pixel unpack buffer, the values are at offset `values`.
    let bound = c.unpack_buffer_bound();
    let values = match c.unpack_source(values as *const u8, mapsize as usize * std::mem::size_of::<T>()) {
        Ok(p) => p as *const T,
        Err(e) => return Some(Command::Error(e)),
    };
    if values.is_null() && !bound {
        return None;
    }
    let v = slice(values, mapsize as i64);
    Some(Command::PixelMap(map, conv(map, &v)))
}

/// glPolygonStipple's mask: the client pointer, or its place in the pixel
/// unpack buffer (None: out of the buffer's range or mapped).
fn stipple_source(c: &Context, mask: *const GLubyte) -> Option<*const GLubyte> {
    c.unpack_image(&c.pixel_store.unpack, 32, 32, 1, GL_COLOR_INDEX, GL_BITMAP, mask).ok()
}

/// Where glGetPolygonStipple and glGetPixelMap write: the client pointer,
/// or its place in the pixel pack buffer (None: the error is set).
unsafe fn pack_out<T>(c: &mut Context, p: *mut T, count: usize, stipple: bool) -> Option<*mut T> {
    let bound = c.pack_buffer_bound();
    let r = if stipple {
        let modes = c.pixel_store.pack;
        c.pack_image(&modes, 32, 32, 1, GL_COLOR_INDEX, GL_BITMAP, p as *mut u8)
    } else {
        c.pack_dest(p as *mut u8, count * std::mem::size_of::<T>())
    };
    match r {
        Ok(p) if !p.is_null() || bound => Some(p as *mut T),
        Ok(_) => None,
        Err(e) => {
            c.set_error(e);
            None
        }
    }
}

/// An ARB_imaging command.
fn imaging(cmd: ImagingCmd) -> Command {
    Command::Imaging(Box::new(cmd))
}

/// glColorTable's and glHistogram's command; a proxy target runs at once
/// and is never compiled into a display list (section 5.4).
fn imaging_or_proxy(c: &mut Context, cmd: ImagingCmd) -> Option<Command> {
    use crate::gl::imaging::*;
    let proxy = match &cmd {
        ImagingCmd::ColorTable { target, .. } => matches!(*target, GL_PROXY_COLOR_TABLE | GL_PROXY_POST_CONVOLUTION_COLOR_TABLE | GL_PROXY_POST_COLOR_MATRIX_COLOR_TABLE),
        ImagingCmd::Histogram { target, .. } => *target == GL_PROXY_HISTOGRAM,
        _ => false,
    };
    if !proxy {
        return Some(imaging(cmd));
    }
    if c.in_begin_end() {
        c.set_error(GL_INVALID_OPERATION);
    } else {
        c.imaging_command(&cmd);
    }
    None
}

/// glConvolutionParameter*v's values: one for the border mode, else four;
/// the integer form's border colour is normalized as colours are (table
/// 2.9), scale and bias convert plainly.
unsafe fn convolution_params<T: Component>(p: *const T, pname: GLenum) -> Option<[f32; 4]> {
    if p.is_null() {
        return None;
    }
    let n = if pname == crate::gl::imaging::GL_CONVOLUTION_BORDER_MODE { 1 } else { 4 };
    let mut v = [0.0f32; 4];
    for (i, out) in v.iter_mut().enumerate().take(n) {
        let x = std::ptr::read_unaligned(p.add(i));
        *out = if pname == crate::gl::imaging::GL_CONVOLUTION_BORDER_COLOR { x.normalized() } else { x.plain() };
    }
    Some(v)
}

/// Texture coordinates from 1 to 4 components: t and r default to 0, q to 1.
fn texcoord<T: Component>(v: &[T]) -> [f32; 4] {
    [v[0].plain(), v.get(1).map_or(0.0, |c| c.plain()), v.get(2).map_or(0.0, |c| c.plain()), v.get(3).map_or(1.0, |c| c.plain())]
}

super::entry_points! {

    // ---- gl.h ----
    exec glGetError() -> GLenum { |c| c.take_error() }
    list glBegin(mode: GLenum) { |_c| Command::Begin(mode) }
    list glEnd() { |_c| Command::End }
    list glEdgeFlag(flag: GLboolean) { |_c| Command::EdgeFlag(truth(flag)) }
    list glEdgeFlagv(flag: *const GLboolean) { |_c| Command::EdgeFlag(truth(arr::<GLboolean, 1>(flag)?[0])) }
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
    list glTexCoord1d(s: GLdouble) { |_c| Command::TexCoord(TEX0, texcoord(&[s])) }
    list glTexCoord1dv(v: *const GLdouble) { |_c| Command::TexCoord(TEX0, texcoord(&arr::<GLdouble, 1>(v)?)) }
    list glTexCoord1f(s: GLfloat) { |_c| Command::TexCoord(TEX0, texcoord(&[s])) }
    list glTexCoord1fv(v: *const GLfloat) { |_c| Command::TexCoord(TEX0, texcoord(&arr::<GLfloat, 1>(v)?)) }
    list glTexCoord1i(s: GLint) { |_c| Command::TexCoord(TEX0, texcoord(&[s])) }
    list glTexCoord1iv(v: *const GLint) { |_c| Command::TexCoord(TEX0, texcoord(&arr::<GLint, 1>(v)?)) }
    list glTexCoord1s(s: GLshort) { |_c| Command::TexCoord(TEX0, texcoord(&[s])) }
    list glTexCoord1sv(v: *const GLshort) { |_c| Command::TexCoord(TEX0, texcoord(&arr::<GLshort, 1>(v)?)) }
    list glTexCoord2d(s: GLdouble, t: GLdouble) { |_c| Command::TexCoord(TEX0, texcoord(&[s, t])) }
    list glTexCoord2dv(v: *const GLdouble) { |_c| Command::TexCoord(TEX0, texcoord(&arr::<GLdouble, 2>(v)?)) }
    list glTexCoord2f(s: GLfloat, t: GLfloat) { |_c| Command::TexCoord(TEX0, texcoord(&[s, t])) }
    list glTexCoord2fv(v: *const GLfloat) { |_c| Command::TexCoord(TEX0, texcoord(&arr::<GLfloat, 2>(v)?)) }
    list glTexCoord2i(s: GLint, t: GLint) { |_c| Command::TexCoord(TEX0, texcoord(&[s, t])) }
    list glTexCoord2iv(v: *const GLint) { |_c| Command::TexCoord(TEX0, texcoord(&arr::<GLint, 2>(v)?)) }
    list glTexCoord2s(s: GLshort, t: GLshort) { |_c| Command::TexCoord(TEX0, texcoord(&[s, t])) }
    list glTexCoord2sv(v: *const GLshort) { |_c| Command::TexCoord(TEX0, texcoord(&arr::<GLshort, 2>(v)?)) }
    list glTexCoord3d(s: GLdouble, t: GLdouble, r: GLdouble) { |_c| Command::TexCoord(TEX0, texcoord(&[s, t, r])) }
    list glTexCoord3dv(v: *const GLdouble) { |_c| Command::TexCoord(TEX0, texcoord(&arr::<GLdouble, 3>(v)?)) }
    list glTexCoord3f(s: GLfloat, t: GLfloat, r: GLfloat) { |_c| Command::TexCoord(TEX0, texcoord(&[s, t, r])) }
    list glTexCoord3fv(v: *const GLfloat) { |_c| Command::TexCoord(TEX0, texcoord(&arr::<GLfloat, 3>(v)?)) }
    list glTexCoord3i(s: GLint, t: GLint, r: GLint) { |_c| Command::TexCoord(TEX0, texcoord(&[s, t, r])) }
    list glTexCoord3iv(v: *const GLint) { |_c| Command::TexCoord(TEX0, texcoord(&arr::<GLint, 3>(v)?)) }
    list glTexCoord3s(s: GLshort, t: GLshort, r: GLshort) { |_c| Command::TexCoord(TEX0, texcoord(&[s, t, r])) }
    list glTexCoord3sv(v: *const GLshort) { |_c| Command::TexCoord(TEX0, texcoord(&arr::<GLshort, 3>(v)?)) }
    list glTexCoord4d(s: GLdouble, t: GLdouble, r: GLdouble, q: GLdouble) { |_c| Command::TexCoord(TEX0, texcoord(&[s, t, r, q])) }
    list glTexCoord4dv(v: *const GLdouble) { |_c| Command::TexCoord(TEX0, texcoord(&arr::<GLdouble, 4>(v)?)) }
    list glTexCoord4f(s: GLfloat, t: GLfloat, r: GLfloat, q: GLfloat) { |_c| Command::TexCoord(TEX0, texcoord(&[s, t, r, q])) }
    list glTexCoord4fv(v: *const GLfloat) { |_c| Command::TexCoord(TEX0, texcoord(&arr::<GLfloat, 4>(v)?)) }
    list glTexCoord4i(s: GLint, t: GLint, r: GLint, q: GLint) { |_c| Command::TexCoord(TEX0, texcoord(&[s, t, r, q])) }
    list glTexCoord4iv(v: *const GLint) { |_c| Command::TexCoord(TEX0, texcoord(&arr::<GLint, 4>(v)?)) }
    list glTexCoord4s(s: GLshort, t: GLshort, r: GLshort, q: GLshort) { |_c| Command::TexCoord(TEX0, texcoord(&[s, t, r, q])) }
    list glTexCoord4sv(v: *const GLshort) { |_c| Command::TexCoord(TEX0, texcoord(&arr::<GLshort, 4>(v)?)) }
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
    list glIndexd(c: GLdouble) { |_c| Command::Index(c as f32) }
    list glIndexdv(v: *const GLdouble) { |_c| Command::Index(arr::<GLdouble, 1>(v)?[0] as f32) }
    list glIndexf(c: GLfloat) { |_c| Command::Index(c) }
    list glIndexfv(v: *const GLfloat) { |_c| Command::Index(arr::<GLfloat, 1>(v)?[0]) }
    list glIndexi(c: GLint) { |_c| Command::Index(c as f32) }
    list glIndexiv(v: *const GLint) { |_c| Command::Index(arr::<GLint, 1>(v)?[0] as f32) }
    list glIndexs(c: GLshort) { |_c| Command::Index(c as f32) }
    list glIndexsv(v: *const GLshort) { |_c| Command::Index(arr::<GLshort, 1>(v)?[0] as f32) }
    list glIndexub(c: GLubyte) { |_c| Command::Index(c as f32) }
    list glIndexubv(v: *const GLubyte) { |_c| Command::Index(arr::<GLubyte, 1>(v)?[0] as f32) }
    client glVertexPointer(size: GLint, type_: GLenum, stride: GLsizei, ptr: *const c_void) { |c| c.array_pointer(Array::Vertex, size, type_, stride, ptr as usize) }
    client glNormalPointer(type_: GLenum, stride: GLsizei, ptr: *const c_void) { |c| c.array_pointer(Array::Normal, 3, type_, stride, ptr as usize) }
    client glColorPointer(size: GLint, type_: GLenum, stride: GLsizei, ptr: *const c_void) { |c| c.array_pointer(Array::Color, size, type_, stride, ptr as usize) }
    client glIndexPointer(type_: GLenum, stride: GLsizei, ptr: *const c_void) { |c| c.array_pointer(Array::Index, 1, type_, stride, ptr as usize) }
    client glTexCoordPointer(size: GLint, type_: GLenum, stride: GLsizei, ptr: *const c_void) { |c| c.tex_coord_pointer(size, type_, stride, ptr as usize) }
    client glEdgeFlagPointer(stride: GLsizei, ptr: *const c_void) { |c| c.array_pointer(Array::EdgeFlag, 1, GL_UNSIGNED_BYTE, stride, ptr as usize) }
    client glEnableClientState(array: GLenum) { |c| c.client_state(array, true) }
    client glDisableClientState(array: GLenum) { |c| c.client_state(array, false) }
    draw glArrayElement(i: GLint) { |c| c.array_element(i) }
    // GL_EXT_vertex_array, GL 1.1's arrays before promotion: the pointer
    // calls also take the number of elements, which GL 1.1 dropped (a
    // negative count is GL_INVALID_VALUE); the rest are the core calls.
    client glVertexPointerEXT(size: GLint, type_: GLenum, stride: GLsizei, count: GLsizei, ptr: *const c_void) { |c| if c.ext_array_count(count) { c.array_pointer(Array::Vertex, size, type_, stride, ptr as usize) } }
    client glNormalPointerEXT(type_: GLenum, stride: GLsizei, count: GLsizei, ptr: *const c_void) { |c| if c.ext_array_count(count) { c.array_pointer(Array::Normal, 3, type_, stride, ptr as usize) } }
    client glColorPointerEXT(size: GLint, type_: GLenum, stride: GLsizei, count: GLsizei, ptr: *const c_void) { |c| if c.ext_array_count(count) { c.array_pointer(Array::Color, size, type_, stride, ptr as usize) } }
    client glIndexPointerEXT(type_: GLenum, stride: GLsizei, count: GLsizei, ptr: *const c_void) { |c| if c.ext_array_count(count) { c.array_pointer(Array::Index, 1, type_, stride, ptr as usize) } }
    client glTexCoordPointerEXT(size: GLint, type_: GLenum, stride: GLsizei, count: GLsizei, ptr: *const c_void) { |c| if c.ext_array_count(count) { c.tex_coord_pointer(size, type_, stride, ptr as usize) } }
    client glEdgeFlagPointerEXT(stride: GLsizei, count: GLsizei, ptr: *const GLboolean) { |c| if c.ext_array_count(count) { c.array_pointer(Array::EdgeFlag, 1, GL_UNSIGNED_BYTE, stride, ptr as usize) } }
    client glGetPointervEXT(pname: GLenum, params: *mut *mut c_void) { |c| if let Some(p) = c.get_pointer(pname) { write_out(params, &[p as *mut c_void]) } }
    draw glArrayElementEXT(i: GLint) { |c| c.array_element(i) }
    draw glDrawArraysEXT(mode: GLenum, first: GLint, count: GLsizei) { |c| c.draw_arrays(mode, first, count) }
    draw glDrawArrays(mode: GLenum, first: GLint, count: GLsizei) { |c| c.draw_arrays(mode, first, count) }
    draw glDrawElements(mode: GLenum, count: GLsizei, type_: GLenum, indices: *const c_void) { |c| c.draw_elements(mode, count, type_, indices as usize) }
    client glInterleavedArrays(format: GLenum, stride: GLsizei, pointer: *const c_void) { |c| c.interleaved_arrays(format, stride, pointer as usize) }
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
    list glLoadMatrixd(m: *const GLdouble) { |_c| Command::LoadMatrix(Box::new(matrix(arr::<GLdouble, 16>(m)?))) }
    list glLoadMatrixf(m: *const GLfloat) { |_c| Command::LoadMatrix(Box::new(matrix(arr::<GLfloat, 16>(m)?.map(f64::from)))) }
    list glMultMatrixd(m: *const GLdouble) { |_c| Command::MultMatrix(Box::new(matrix(arr::<GLdouble, 16>(m)?))) }
    list glMultMatrixf(m: *const GLfloat) { |_c| Command::MultMatrix(Box::new(matrix(arr::<GLfloat, 16>(m)?.map(f64::from)))) }
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
    list glTexGend(coord: GLenum, pname: GLenum, param: GLdouble) { |_c| { Command::TexGen(coord, pname, [param as f64, 0.0, 0.0, 0.0]) } }
    list glTexGendv(coord: GLenum, pname: GLenum, params: *const GLdouble) { |_c| { let v = slice(params, if pname == TGEN_MODE { 1 } else { 4 }); Command::TexGen(coord, pname, std::array::from_fn(|i| v.get(i).map_or(0.0, |&x| f64::from(x)))) } }
    list glTexGenf(coord: GLenum, pname: GLenum, param: GLfloat) { |_c| { Command::TexGen(coord, pname, [param as f64, 0.0, 0.0, 0.0]) } }
    list glTexGenfv(coord: GLenum, pname: GLenum, params: *const GLfloat) { |_c| { let v = slice(params, if pname == TGEN_MODE { 1 } else { 4 }); Command::TexGen(coord, pname, std::array::from_fn(|i| v.get(i).map_or(0.0, |&x| f64::from(x)))) } }
    list glTexGeni(coord: GLenum, pname: GLenum, param: GLint) { |_c| { Command::TexGen(coord, pname, [param as f64, 0.0, 0.0, 0.0]) } }
    list glTexGeniv(coord: GLenum, pname: GLenum, params: *const GLint) { |_c| { let v = slice(params, if pname == TGEN_MODE { 1 } else { 4 }); Command::TexGen(coord, pname, std::array::from_fn(|i| v.get(i).map_or(0.0, |&x| f64::from(x)))) } }
    list glClipPlane(plane: GLenum, equation: *const GLdouble) { |_c| Command::ClipPlane(plane, arr::<GLdouble, 4>(equation)?) }
    list glRasterPos2d(x: GLdouble, y: GLdouble) { |_c| Command::RasterPos(position(&[x, y])) }
    list glRasterPos2dv(v: *const GLdouble) { |_c| Command::RasterPos(position(&arr::<GLdouble, 2>(v)?)) }
    list glRasterPos2f(x: GLfloat, y: GLfloat) { |_c| Command::RasterPos(position(&[x, y])) }
    list glRasterPos2fv(v: *const GLfloat) { |_c| Command::RasterPos(position(&arr::<GLfloat, 2>(v)?)) }
    list glRasterPos2i(x: GLint, y: GLint) { |_c| Command::RasterPos(position(&[x, y])) }
    list glRasterPos2iv(v: *const GLint) { |_c| Command::RasterPos(position(&arr::<GLint, 2>(v)?)) }
    list glRasterPos2s(x: GLshort, y: GLshort) { |_c| Command::RasterPos(position(&[x, y])) }
    list glRasterPos2sv(v: *const GLshort) { |_c| Command::RasterPos(position(&arr::<GLshort, 2>(v)?)) }
    list glRasterPos3d(x: GLdouble, y: GLdouble, z: GLdouble) { |_c| Command::RasterPos(position(&[x, y, z])) }
    list glRasterPos3dv(v: *const GLdouble) { |_c| Command::RasterPos(position(&arr::<GLdouble, 3>(v)?)) }
    list glRasterPos3f(x: GLfloat, y: GLfloat, z: GLfloat) { |_c| Command::RasterPos(position(&[x, y, z])) }
    list glRasterPos3fv(v: *const GLfloat) { |_c| Command::RasterPos(position(&arr::<GLfloat, 3>(v)?)) }
    list glRasterPos3i(x: GLint, y: GLint, z: GLint) { |_c| Command::RasterPos(position(&[x, y, z])) }
    list glRasterPos3iv(v: *const GLint) { |_c| Command::RasterPos(position(&arr::<GLint, 3>(v)?)) }
    list glRasterPos3s(x: GLshort, y: GLshort, z: GLshort) { |_c| Command::RasterPos(position(&[x, y, z])) }
    list glRasterPos3sv(v: *const GLshort) { |_c| Command::RasterPos(position(&arr::<GLshort, 3>(v)?)) }
    list glRasterPos4d(x: GLdouble, y: GLdouble, z: GLdouble, w: GLdouble) { |_c| Command::RasterPos(position(&[x, y, z, w])) }
    list glRasterPos4dv(v: *const GLdouble) { |_c| Command::RasterPos(position(&arr::<GLdouble, 4>(v)?)) }
    list glRasterPos4f(x: GLfloat, y: GLfloat, z: GLfloat, w: GLfloat) { |_c| Command::RasterPos(position(&[x, y, z, w])) }
    list glRasterPos4fv(v: *const GLfloat) { |_c| Command::RasterPos(position(&arr::<GLfloat, 4>(v)?)) }
    list glRasterPos4i(x: GLint, y: GLint, z: GLint, w: GLint) { |_c| Command::RasterPos(position(&[x, y, z, w])) }
    list glRasterPos4iv(v: *const GLint) { |_c| Command::RasterPos(position(&arr::<GLint, 4>(v)?)) }
    list glRasterPos4s(x: GLshort, y: GLshort, z: GLshort, w: GLshort) { |_c| Command::RasterPos(position(&[x, y, z, w])) }
    list glRasterPos4sv(v: *const GLshort) { |_c| Command::RasterPos(position(&arr::<GLshort, 4>(v)?)) }
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
    list glPointSize(size: GLfloat) { |_c| Command::PointSize(size) }
    list glLineWidth(width: GLfloat) { |_c| Command::LineWidth(width) }
    list glLineStipple(factor: GLint, pattern: GLushort) { |_c| Command::LineStipple(factor, pattern) }
    list glCullFace(mode: GLenum) { |_c| Command::CullFace(mode) }
    list glFrontFace(mode: GLenum) { |_c| Command::FrontFace(mode) }
    list glPolygonStipple(mask: *const GLubyte) { |c| { let Some(mask) = stipple_source(c, mask) else { return Some(Command::Error(GL_INVALID_OPERATION)) }; if mask.is_null() { return None; } Command::PolygonStipple(Box::new(unpack_stipple(&c.pixel_store.unpack, mask))) } }
    list glPolygonMode(face: GLenum, mode: GLenum) { |_c| Command::PolygonMode(face, mode) }
    list glPolygonOffset(factor: GLfloat, units: GLfloat) { |_c| Command::PolygonOffset(factor, units) }
    client glPixelStoref(pname: GLenum, param: GLfloat) { |c| c.pixel_store(pname, param as f64) }
    client glPixelStorei(pname: GLenum, param: GLint) { |c| c.pixel_store(pname, param as f64) }
    list glPixelTransferf(pname: GLenum, param: GLfloat) { |_c| Command::PixelTransfer(pname, param as f64) }
    list glPixelTransferi(pname: GLenum, param: GLint) { |_c| Command::PixelTransfer(pname, param as f64) }
    list glPixelMapfv(map: GLenum, mapsize: GLsizei, values: *const GLfloat) { |c| pixel_map(c, map, mapsize, values, |_, v| v.to_vec())? }
    list glPixelMapuiv(map: GLenum, mapsize: GLsizei, values: *const GLuint) { |c| pixel_map(c, map, mapsize, values, |m, v| map_values_from_uint(m, v, 32))? }
    list glPixelMapusv(map: GLenum, mapsize: GLsizei, values: *const GLushort) { |c| pixel_map(c, map, mapsize, values, |m, v| map_values_from_uint(m, &v.iter().map(|&x| x as u32).collect::<Vec<_>>(), 16))? }
    list glDrawPixels(width: GLsizei, height: GLsizei, format: GLenum, type_: GLenum, pixels: *const c_void) { |c| c.draw_pixels_call(width, height, format, type_, pixels as *const u8)? }
    list glPixelZoom(xfactor: GLfloat, yfactor: GLfloat) { |_c| Command::PixelZoom(xfactor, yfactor) }
    list glBitmap(width: GLsizei, height: GLsizei, xorig: GLfloat, yorig: GLfloat, xmove: GLfloat, ymove: GLfloat, bitmap: *const GLubyte) { |c| c.build_bitmap(width, height, [xorig, yorig], [xmove, ymove], bitmap) }
    list glTexImage1D(target: GLenum, level: GLint, internalFormat: GLint, width: GLsizei, border: GLint, format: GLenum, type_: GLenum, pixels: *const c_void) { |c| c.tex_image_command(1, target, level, internalFormat, [width, 1, 1], border, format, type_, pixels as *const u8)? }
    list glTexImage2D(target: GLenum, level: GLint, internalFormat: GLint, width: GLsizei, height: GLsizei, border: GLint, format: GLenum, type_: GLenum, pixels: *const c_void) { |c| c.tex_image_command(2, target, level, internalFormat, [width, height, 1], border, format, type_, pixels as *const u8)? }
    list glCopyTexImage1D(target: GLenum, level: GLint, internalFormat: GLenum, x: GLint, y: GLint, width: GLsizei, border: GLint) { |_c| Command::CopyTex(Box::new(CopyTexCmd { dims: 1, sub: false, target, level, internal_format: internalFormat, offset: [0; 3], rect: [x, y, width, 1], border })) }
    list glCopyTexImage2D(target: GLenum, level: GLint, internalFormat: GLenum, x: GLint, y: GLint, width: GLsizei, height: GLsizei, border: GLint) { |_c| Command::CopyTex(Box::new(CopyTexCmd { dims: 2, sub: false, target, level, internal_format: internalFormat, offset: [0; 3], rect: [x, y, width, height], border })) }
    list glTexSubImage1D(target: GLenum, level: GLint, xoffset: GLint, width: GLsizei, format: GLenum, type_: GLenum, pixels: *const c_void) { |c| c.tex_sub_image_command(1, target, level, [xoffset, 0, 0], [width, 1, 1], format, type_, pixels as *const u8) }
    list glTexSubImage2D(target: GLenum, level: GLint, xoffset: GLint, yoffset: GLint, width: GLsizei, height: GLsizei, format: GLenum, type_: GLenum, pixels: *const c_void) { |c| c.tex_sub_image_command(2, target, level, [xoffset, yoffset, 0], [width, height, 1], format, type_, pixels as *const u8) }
    list glCopyTexSubImage1D(target: GLenum, level: GLint, xoffset: GLint, x: GLint, y: GLint, width: GLsizei) { |_c| Command::CopyTex(Box::new(CopyTexCmd { dims: 1, sub: true, target, level, internal_format: 0, offset: [xoffset, 0, 0], rect: [x, y, width, 1], border: 0 })) }
    list glCopyTexSubImage2D(target: GLenum, level: GLint, xoffset: GLint, yoffset: GLint, x: GLint, y: GLint, width: GLsizei, height: GLsizei) { |_c| Command::CopyTex(Box::new(CopyTexCmd { dims: 2, sub: true, target, level, internal_format: 0, offset: [xoffset, yoffset, 0], rect: [x, y, width, height], border: 0 })) }
    list glTexParameterf(target: GLenum, pname: GLenum, param: GLfloat) { |_c| { Command::TexParameter(target, pname, scalar_tex_param(pname, param)) } }
    list glTexParameterfv(target: GLenum, pname: GLenum, params: *const GLfloat) { |_c| { let v = slice(params, if pname == TBORDER || pname == TSWIZZLE_RGBA { 4 } else { 1 }); if v.is_empty() { return None; } Command::TexParameter(target, pname, std::array::from_fn(|i| v.get(i).copied().unwrap_or(0.0))) } }
    list glTexParameteri(target: GLenum, pname: GLenum, param: GLint) { |_c| { Command::TexParameter(target, pname, scalar_tex_param(pname, param as f32)) } }
    list glTexParameteriv(target: GLenum, pname: GLenum, params: *const GLint) { |_c| { let border = pname == TBORDER; let v = slice(params, if border || pname == TSWIZZLE_RGBA { 4 } else { 1 }); if v.is_empty() { return None; } Command::TexParameter(target, pname, std::array::from_fn(|i| v.get(i).map_or(0.0, |&x| if border { x.normalized() } else { x as f32 }))) } }
    exec glGenTextures(n: GLsizei, textures: *mut GLuint) { |c| if let Some(v) = c.gen_textures(n) { write_out(textures, &v) } }
    exec glDeleteTextures(n: GLsizei, textures: *const GLuint) { |c| { if n < 0 { return c.set_error(GL_INVALID_VALUE); } let names = slice(textures, n as i64); c.fbo_textures_deleted(&names); c.delete_textures(&names) } }
    list glBindTexture(target: GLenum, texture: GLuint) { |_c| Command::BindTexture(target, texture) }
    list glPrioritizeTextures(n: GLsizei, textures: *const GLuint, priorities: *const GLclampf) { |c| { if n < 0 { c.set_error(GL_INVALID_VALUE); return None; } Command::PrioritizeTextures(slice(textures, n as i64).into_iter().zip(slice(priorities, n as i64)).collect()) } }
    exec glAreTexturesResident(n: GLsizei, textures: *const GLuint, residences: *mut GLboolean) -> GLboolean { |c| { if n < 0 { c.set_error(GL_INVALID_VALUE); return 0; } let _ = residences; match c.are_textures_resident(&slice(textures, n as i64)) { Some(_) => 1, None => 0 } } }
    exec glIsTexture(texture: GLuint) -> GLboolean { |c| gl_bool(c.is_texture(texture)) }
    list glTexEnvf(target: GLenum, pname: GLenum, param: GLfloat) { |c| { if pname == TENV_COLOR { c.set_error(GL_INVALID_ENUM); return None; } Command::TexEnv(target, pname, [param, 0.0, 0.0, 0.0]) } }
    list glTexEnvfv(target: GLenum, pname: GLenum, params: *const GLfloat) { |_c| { let v = slice(params, if pname == TENV_COLOR { 4 } else { 1 }); if v.is_empty() { return None; } Command::TexEnv(target, pname, std::array::from_fn(|i| v.get(i).copied().unwrap_or(0.0))) } }
    list glTexEnvi(target: GLenum, pname: GLenum, param: GLint) { |c| { if pname == TENV_COLOR { c.set_error(GL_INVALID_ENUM); return None; } Command::TexEnv(target, pname, [param as f32, 0.0, 0.0, 0.0]) } }
    list glTexEnviv(target: GLenum, pname: GLenum, params: *const GLint) { |_c| { let color = pname == TENV_COLOR; let v = slice(params, if color { 4 } else { 1 }); if v.is_empty() { return None; } Command::TexEnv(target, pname, std::array::from_fn(|i| v.get(i).map_or(0.0, |&x| if color { x.normalized() } else { x as f32 }))) } }
    list glFogf(pname: GLenum, param: GLfloat) { |c| Command::Fog(scalar_param(c, fog_param_count(pname), pname)?, [param, 0.0, 0.0, 0.0]) }
    list glFogfv(pname: GLenum, params: *const GLfloat) { |_c| Command::Fog(pname, read_fog(params, pname)?) }
    list glFogi(pname: GLenum, param: GLint) { |c| Command::Fog(scalar_param(c, fog_param_count(pname), pname)?, [param as f32, 0.0, 0.0, 0.0]) }
    list glFogiv(pname: GLenum, params: *const GLint) { |_c| Command::Fog(pname, read_fog(params, pname)?) }
    list glScissor(x: GLint, y: GLint, width: GLsizei, height: GLsizei) { |_c| Command::Scissor(x, y, width, height) }
    list glAlphaFunc(func: GLenum, ref_: GLclampf) { |_c| Command::AlphaFunc(func, ref_) }
    list glStencilFunc(func: GLenum, ref_: GLint, mask: GLuint) { |_c| Command::StencilFunc(func, ref_, mask) }
    list glStencilOp(fail: GLenum, zfail: GLenum, zpass: GLenum) { |_c| Command::StencilOp(fail, zfail, zpass) }
    list glDepthFunc(func: GLenum) { |_c| Command::DepthFunc(func) }
    list glBlendFunc(sfactor: GLenum, dfactor: GLenum) { |_c| Command::BlendFunc([sfactor, dfactor, sfactor, dfactor]) }
    list glLogicOp(opcode: GLenum) { |_c| Command::LogicOp(opcode) }
    list glDrawBuffer(mode: GLenum) { |_c| Command::DrawBuffer(mode) }
    list glIndexMask(mask: GLuint) { |_c| Command::IndexMask(mask) }
    list glColorMask(red: GLboolean, green: GLboolean, blue: GLboolean, alpha: GLboolean) { |_c| Command::ColorMask([truth(red), truth(green), truth(blue), truth(alpha)]) }
    list glDepthMask(flag: GLboolean) { |_c| Command::DepthMask(truth(flag)) }
    list glStencilMask(mask: GLuint) { |_c| Command::StencilMask(mask) }
    list glClear(mask: GLbitfield) { |_c| Command::Clear(mask) }
    list glClearColor(red: GLclampf, green: GLclampf, blue: GLclampf, alpha: GLclampf) { |_c| Command::ClearColor([red, green, blue, alpha]) }
    list glClearIndex(c: GLfloat) { |_c| Command::ClearIndex(c) }
    list glClearDepth(depth: GLclampd) { |_c| Command::ClearDepth(depth) }
    list glClearStencil(s: GLint) { |_c| Command::ClearStencil(s) }
    list glClearAccum(red: GLfloat, green: GLfloat, blue: GLfloat, alpha: GLfloat) { |_c| Command::ClearAccum([red, green, blue, alpha]) }
    list glAccum(op: GLenum, value: GLfloat) { |_c| Command::Accum(op, value) }
    list glReadBuffer(mode: GLenum) { |_c| Command::ReadBuffer(mode) }
    exec glReadPixels(x: GLint, y: GLint, width: GLsizei, height: GLsizei, format: GLenum, type_: GLenum, pixels: *mut c_void) { |c| c.read_pixels(x, y, width, height, format, type_, pixels as *mut u8) }
    list glCopyPixels(x: GLint, y: GLint, width: GLsizei, height: GLsizei, type_: GLenum) { |_c| Command::CopyPixels(x, y, width, height, type_) }
    list glMap1d(target: GLenum, u1: GLdouble, u2: GLdouble, stride: GLint, order: GLint, points: *const GLdouble) { |_c| map_command(read_points(target, points, stride, order, 0, 1), |points| Command::Map { target, u: (u1 as f32, u2 as f32), uorder: order, v: None, points }) }
    list glMap1f(target: GLenum, u1: GLfloat, u2: GLfloat, stride: GLint, order: GLint, points: *const GLfloat) { |_c| map_command(read_points(target, points, stride, order, 0, 1), |points| Command::Map { target, u: (u1, u2), uorder: order, v: None, points }) }
    list glMap2d(target: GLenum, u1: GLdouble, u2: GLdouble, ustride: GLint, uorder: GLint, v1: GLdouble, v2: GLdouble, vstride: GLint, vorder: GLint, points: *const GLdouble) { |_c| map_command(read_points(target, points, ustride, uorder, vstride, vorder), |points| Command::Map { target, u: (u1 as f32, u2 as f32), uorder, v: Some(((v1 as f32, v2 as f32), vorder)), points }) }
    list glMap2f(target: GLenum, u1: GLfloat, u2: GLfloat, ustride: GLint, uorder: GLint, v1: GLfloat, v2: GLfloat, vstride: GLint, vorder: GLint, points: *const GLfloat) { |_c| map_command(read_points(target, points, ustride, uorder, vstride, vorder), |points| Command::Map { target, u: (u1, u2), uorder, v: Some(((v1, v2), vorder)), points }) }
    list glEvalCoord1d(u: GLdouble) { |_c| Command::EvalCoord(u as f32, None) }
    list glEvalCoord1dv(u: *const GLdouble) { |_c| Command::EvalCoord(arr::<GLdouble, 1>(u)?[0] as f32, None) }
    list glEvalCoord1f(u: GLfloat) { |_c| Command::EvalCoord(u, None) }
    list glEvalCoord1fv(u: *const GLfloat) { |_c| Command::EvalCoord(arr::<GLfloat, 1>(u)?[0], None) }
    list glEvalCoord2d(u: GLdouble, v: GLdouble) { |_c| Command::EvalCoord(u as f32, Some(v as f32)) }
    list glEvalCoord2dv(u: *const GLdouble) { |_c| { let p = arr::<GLdouble, 2>(u)?; Command::EvalCoord(p[0] as f32, Some(p[1] as f32)) } }
    list glEvalCoord2f(u: GLfloat, v: GLfloat) { |_c| Command::EvalCoord(u, Some(v)) }
    list glEvalCoord2fv(u: *const GLfloat) { |_c| { let p = arr::<GLfloat, 2>(u)?; Command::EvalCoord(p[0], Some(p[1])) } }
    list glMapGrid1d(un: GLint, u1: GLdouble, u2: GLdouble) { |_c| Command::MapGrid(un, (u1 as f32, u2 as f32), None) }
    list glMapGrid1f(un: GLint, u1: GLfloat, u2: GLfloat) { |_c| Command::MapGrid(un, (u1, u2), None) }
    list glMapGrid2d(un: GLint, u1: GLdouble, u2: GLdouble, vn: GLint, v1: GLdouble, v2: GLdouble) { |_c| Command::MapGrid(un, (u1 as f32, u2 as f32), Some((vn, (v1 as f32, v2 as f32)))) }
    list glMapGrid2f(un: GLint, u1: GLfloat, u2: GLfloat, vn: GLint, v1: GLfloat, v2: GLfloat) { |_c| Command::MapGrid(un, (u1, u2), Some((vn, (v1, v2)))) }
    list glEvalMesh1(mode: GLenum, i1: GLint, i2: GLint) { |_c| Command::EvalMesh1(mode, i1, i2) }
    list glEvalMesh2(mode: GLenum, i1: GLint, i2: GLint, j1: GLint, j2: GLint) { |_c| Command::EvalMesh2(mode, i1, i2, j1, j2) }
    list glEvalPoint1(i: GLint) { |_c| Command::EvalPoint(i, None) }
    list glEvalPoint2(i: GLint, j: GLint) { |_c| Command::EvalPoint(i, Some(j)) }
    exec glRenderMode(mode: GLenum) -> GLint { |c| c.render_mode(mode) }
    exec glSelectBuffer(size: GLsizei, buffer: *mut GLuint) { |c| c.select_buffer(size, buffer) }
    list glInitNames() { |_c| Command::NameStack(NameOp::Init) }
    list glLoadName(name: GLuint) { |_c| Command::NameStack(NameOp::Load(name)) }
    list glPushName(name: GLuint) { |_c| Command::NameStack(NameOp::Push(name)) }
    list glPopName() { |_c| Command::NameStack(NameOp::Pop) }
    exec["sphere-map, normal-map and reflection-map texgen are not applied to unit 0's reported coordinates when unit 0 is not texturing"] glFeedbackBuffer(size: GLsizei, type_: GLenum, buffer: *mut GLfloat) { |c| c.feedback_buffer(size, type_, buffer) }
    list glPassThrough(token: GLfloat) { |_c| Command::PassThrough(token) }
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
    list glHint(target: GLenum, mode: GLenum) { |_c| Command::Hint(target, mode) }
    list["GL_MULTISAMPLE, GL_SAMPLE_ALPHA_TO_COVERAGE/ONE are stored and queryable but change nothing: no multisample buffers"] glEnable(cap: GLenum) { |_c| Command::Enable(cap) }
    list["see glEnable"] glDisable(cap: GLenum) { |_c| Command::Disable(cap) }
    exec["as glEnable"] glIsEnabled(cap: GLenum) -> GLboolean { |c| match c.is_enabled(cap) { Some(b) => gl_bool(b), None => { c.set_error(GL_INVALID_ENUM); 0 } } }
    exec glGetBooleanv(pname: GLenum, params: *mut GLboolean) { |c| c.get_into(pname, params, |v| v.as_bool().into_iter().map(gl_bool).collect()) }
    exec glGetIntegerv(pname: GLenum, params: *mut GLint) { |c| c.get_into(pname, params, get::Value::as_i32) }
    exec glGetFloatv(pname: GLenum, params: *mut GLfloat) { |c| c.get_into(pname, params, |v| v.as_f64().into_iter().map(|x| x as f32).collect()) }
    exec glGetDoublev(pname: GLenum, params: *mut GLdouble) { |c| c.get_into(pname, params, get::Value::as_f64) }
    client glGetPointerv(pname: GLenum, params: *mut *mut c_void) { |c| if let Some(p) = c.get_pointer(pname) { write_out(params, &[p as *mut c_void]) } }
    exec glGetClipPlane(plane: GLenum, equation: *mut GLdouble) { |c| match c.get_clip_plane(plane) { Some(p) => write_out(equation, &p), None => c.set_error(GL_INVALID_ENUM) } }
    exec glGetLightfv(light: GLenum, pname: GLenum, params: *mut GLfloat) { |c| match c.get_light(light, pname) { Some(v) => write_out(params, &v), None => c.set_error(GL_INVALID_ENUM) } }
    exec glGetLightiv(light: GLenum, pname: GLenum, params: *mut GLint) { |c| match c.get_light(light, pname) { Some(v) => write_out(params, &ints_out(&v, is_color_param(pname))), None => c.set_error(GL_INVALID_ENUM) } }
    exec glGetMaterialfv(face: GLenum, pname: GLenum, params: *mut GLfloat) { |c| match c.get_material(face, pname) { Some(v) => write_out(params, &v), None => c.set_error(GL_INVALID_ENUM) } }
    exec glGetMaterialiv(face: GLenum, pname: GLenum, params: *mut GLint) { |c| match c.get_material(face, pname) { Some(v) => write_out(params, &ints_out(&v, is_color_param(pname))), None => c.set_error(GL_INVALID_ENUM) } }
    exec glGetTexEnvfv(target: GLenum, pname: GLenum, params: *mut GLfloat) { |c| if let Some(v) = c.get_tex_env(target, pname) { write_out(params, &v.as_f64().iter().map(|&x| x as f32).collect::<Vec<_>>()) } }
    exec glGetTexEnviv(target: GLenum, pname: GLenum, params: *mut GLint) { |c| if let Some(v) = c.get_tex_env(target, pname) { write_out(params, &v.as_i32()) } }
    exec glGetTexGendv(coord: GLenum, pname: GLenum, params: *mut GLdouble) { |c| if let Some(v) = c.get_tex_gen(coord, pname) { write_out(params, &v.as_f64()) } }
    exec glGetTexGenfv(coord: GLenum, pname: GLenum, params: *mut GLfloat) { |c| if let Some(v) = c.get_tex_gen(coord, pname) { write_out(params, &v.as_f64().iter().map(|&x| x as f32).collect::<Vec<_>>()) } }
    exec glGetTexGeniv(coord: GLenum, pname: GLenum, params: *mut GLint) { |c| if let Some(v) = c.get_tex_gen(coord, pname) { write_out(params, &v.as_i32()) } }
    exec glGetTexParameterfv(target: GLenum, pname: GLenum, params: *mut GLfloat) { |c| if let Some(v) = c.get_tex_parameter(target, pname) { write_out(params, &v.as_f64().iter().map(|&x| x as f32).collect::<Vec<_>>()) } }
    exec glGetTexParameteriv(target: GLenum, pname: GLenum, params: *mut GLint) { |c| if let Some(v) = c.get_tex_parameter(target, pname) { write_out(params, &v.as_i32()) } }
    exec glGetTexLevelParameterfv(target: GLenum, level: GLint, pname: GLenum, params: *mut GLfloat) { |c| if let Some(v) = c.get_tex_level_parameter(target, level, pname) { write_out(params, &v.as_f64().iter().map(|&x| x as f32).collect::<Vec<_>>()) } }
    exec glGetTexLevelParameteriv(target: GLenum, level: GLint, pname: GLenum, params: *mut GLint) { |c| if let Some(v) = c.get_tex_level_parameter(target, level, pname) { write_out(params, &v.as_i32()) } }
    exec glGetTexImage(target: GLenum, level: GLint, format: GLenum, type_: GLenum, pixels: *mut c_void) { |c| { c.fbo_store(); c.get_tex_image(target, level, format, type_, pixels as *mut u8) } }
    exec glGetPixelMapfv(map: GLenum, values: *mut GLfloat) { |c| match c.get_pixel_map(map).map(|v| v.to_vec()) { Some(v) => if let Some(p) = pack_out(c, values, v.len(), false) { write_out(p, &v) }, None => c.set_error(GL_INVALID_ENUM) } }
    exec glGetPixelMapuiv(map: GLenum, values: *mut GLuint) { |c| match c.get_pixel_map(map).map(|v| v.iter().map(|&x| map_value_to_uint(map, x, 32)).collect::<Vec<_>>()) { Some(v) => if let Some(p) = pack_out(c, values, v.len(), false) { write_out(p, &v) }, None => c.set_error(GL_INVALID_ENUM) } }
    exec glGetPixelMapusv(map: GLenum, values: *mut GLushort) { |c| match c.get_pixel_map(map).map(|v| v.iter().map(|&x| map_value_to_uint(map, x, 16) as u16).collect::<Vec<_>>()) { Some(v) => if let Some(p) = pack_out(c, values, v.len(), false) { write_out(p, &v) }, None => c.set_error(GL_INVALID_ENUM) } }
    exec glGetMapdv(target: GLenum, query: GLenum, v: *mut GLdouble) { |c| match c.get_map(target, query) { Some(x) => write_out(v, &x), None => c.set_error(GL_INVALID_ENUM) } }
    exec glGetMapfv(target: GLenum, query: GLenum, v: *mut GLfloat) { |c| match c.get_map(target, query) { Some(x) => write_out(v, &x.iter().map(|&f| f as f32).collect::<Vec<_>>()), None => c.set_error(GL_INVALID_ENUM) } }
    exec glGetMapiv(target: GLenum, query: GLenum, v: *mut GLint) { |c| match c.get_map(target, query) { Some(x) => write_out(v, &get::Value::Floats(x).as_i32()), None => c.set_error(GL_INVALID_ENUM) } }
    exec glGetPolygonStipple(mask: *mut GLubyte) { |c| if let Some(p) = pack_out(c, mask, 0, true) { pack_stipple(&c.pixel_store.pack, &c.polygon.stipple_pattern, p) } }
    exec glGetString(name: GLenum) -> *const GLubyte { |c| match get::string(name) { Some(s) => s.as_ptr(), None => { c.set_error(GL_INVALID_ENUM); std::ptr::null() } } }
    list glPushAttrib(mask: GLbitfield) { |_c| Command::PushAttrib(mask) }
    list glPopAttrib() { |_c| Command::PopAttrib }
    client glPushClientAttrib(mask: GLbitfield) { |c| c.push_client_attrib(mask) }
    client glPopClientAttrib() { |c| c.pop_client_attrib() }
    draw glDrawRangeElements(mode: GLenum, start: GLuint, end: GLuint, count: GLsizei, type_: GLenum, indices: *const c_void) { |c| c.draw_range_elements(mode, start, end, count, type_, indices as usize) }
    list glTexImage3D(target: GLenum, level: GLint, internalFormat: GLint, width: GLsizei, height: GLsizei, depth: GLsizei, border: GLint, format: GLenum, type_: GLenum, pixels: *const c_void) { |c| c.tex_image_command(3, target, level, internalFormat, [width, height, depth], border, format, type_, pixels as *const u8)? }
    list glTexSubImage3D(target: GLenum, level: GLint, xoffset: GLint, yoffset: GLint, zoffset: GLint, width: GLsizei, height: GLsizei, depth: GLsizei, format: GLenum, type_: GLenum, pixels: *const c_void) { |c| c.tex_sub_image_command(3, target, level, [xoffset, yoffset, zoffset], [width, height, depth], format, type_, pixels as *const u8) }
    list glCopyTexSubImage3D(target: GLenum, level: GLint, xoffset: GLint, yoffset: GLint, zoffset: GLint, x: GLint, y: GLint, width: GLsizei, height: GLsizei) { |_c| Command::CopyTex(Box::new(CopyTexCmd { dims: 3, sub: true, target, level, internal_format: 0, offset: [xoffset, yoffset, zoffset], rect: [x, y, width, height], border: 0 })) }
    list glBlendColor(red: GLclampf, green: GLclampf, blue: GLclampf, alpha: GLclampf) { |_c| Command::BlendColor([red, green, blue, alpha]) }
    list glBlendEquation(mode: GLenum) { |_c| Command::BlendEquation(mode) }
    list glColorTable(target: GLenum, internalformat: GLenum, width: GLsizei, format: GLenum, type_: GLenum, table: *const c_void) { |c| match c.unpack_imaging(width, 1, format, type_, table as *const u8) { Ok(data) => imaging_or_proxy(c, ImagingCmd::ColorTable { target, internal_format: internalformat, width, data })?, Err(e) => Command::Error(e) } }
    list glColorTableParameterfv(target: GLenum, pname: GLenum, params: *const GLfloat) { |_c| imaging(ImagingCmd::ColorTableParameter { target, pname, v: arr::<GLfloat, 4>(params)? }) }
    list glColorTableParameteriv(target: GLenum, pname: GLenum, params: *const GLint) { |_c| imaging(ImagingCmd::ColorTableParameter { target, pname, v: arr::<GLint, 4>(params)?.map(|x| x as f32) }) }
    list glCopyColorTable(target: GLenum, internalformat: GLenum, x: GLint, y: GLint, width: GLsizei) { |_c| imaging(ImagingCmd::CopyColorTable { target, internal_format: internalformat, x, y, width }) }
    list glColorSubTable(target: GLenum, start: GLsizei, count: GLsizei, format: GLenum, type_: GLenum, data: *const c_void) { |c| match c.unpack_imaging(count, 1, format, type_, data as *const u8) { Ok(data) => imaging(ImagingCmd::ColorSubTable { target, start, count, data }), Err(e) => Command::Error(e) } }
    list glCopyColorSubTable(target: GLenum, start: GLsizei, x: GLint, y: GLint, width: GLsizei) { |_c| imaging(ImagingCmd::CopyColorSubTable { target, start, x, y, width }) }
    exec glGetColorTable(target: GLenum, format: GLenum, type_: GLenum, table: *mut c_void) { |c| c.get_color_table(target, format, type_, table as *mut u8) }
    exec glGetColorTableParameterfv(target: GLenum, pname: GLenum, params: *mut GLfloat) { |c| if let Some(v) = c.get_color_table_parameter(target, pname) { write_out(params, &v.as_f64().iter().map(|&x| x as f32).collect::<Vec<_>>()) } }
    exec glGetColorTableParameteriv(target: GLenum, pname: GLenum, params: *mut GLint) { |c| if let Some(v) = c.get_color_table_parameter(target, pname) { write_out(params, &v.as_i32()) } }
    list glConvolutionFilter1D(target: GLenum, internalformat: GLenum, width: GLsizei, format: GLenum, type_: GLenum, image: *const c_void) { |c| match c.unpack_imaging(width, 1, format, type_, image as *const u8) { Ok(data) if target == GL_CONVOLUTION_1D => imaging(ImagingCmd::ConvolutionFilter { target, internal_format: internalformat, width, height: 1, data }), Ok(_) => Command::Error(GL_INVALID_ENUM), Err(e) => Command::Error(e) } }
    list glConvolutionFilter2D(target: GLenum, internalformat: GLenum, width: GLsizei, height: GLsizei, format: GLenum, type_: GLenum, image: *const c_void) { |c| match c.unpack_imaging(width, height, format, type_, image as *const u8) { Ok(data) if target == GL_CONVOLUTION_2D => imaging(ImagingCmd::ConvolutionFilter { target, internal_format: internalformat, width, height, data }), Ok(_) => Command::Error(GL_INVALID_ENUM), Err(e) => Command::Error(e) } }
    list glSeparableFilter2D(target: GLenum, internalformat: GLenum, width: GLsizei, height: GLsizei, format: GLenum, type_: GLenum, row: *const c_void, column: *const c_void) { |c| match (c.unpack_imaging(width, 1, format, type_, row as *const u8), c.unpack_imaging(height, 1, format, type_, column as *const u8)) { (Ok(row), Ok(column)) => imaging(ImagingCmd::SeparableFilter { target, internal_format: internalformat, width, height, row, column }), (Err(e), _) | (_, Err(e)) => Command::Error(e) } }
    list glCopyConvolutionFilter1D(target: GLenum, internalformat: GLenum, x: GLint, y: GLint, width: GLsizei) { |_c| if target == GL_CONVOLUTION_1D { imaging(ImagingCmd::CopyConvolutionFilter { target, internal_format: internalformat, x, y, width, height: 1 }) } else { Command::Error(GL_INVALID_ENUM) } }
    list glCopyConvolutionFilter2D(target: GLenum, internalformat: GLenum, x: GLint, y: GLint, width: GLsizei, height: GLsizei) { |_c| if target == GL_CONVOLUTION_2D { imaging(ImagingCmd::CopyConvolutionFilter { target, internal_format: internalformat, x, y, width, height }) } else { Command::Error(GL_INVALID_ENUM) } }
    list glConvolutionParameterf(target: GLenum, pname: GLenum, param: GLfloat) { |_c| imaging(ImagingCmd::ConvolutionParameter { target, pname, v: [param, 0.0, 0.0, 0.0] }) }
    list glConvolutionParameterfv(target: GLenum, pname: GLenum, params: *const GLfloat) { |_c| imaging(ImagingCmd::ConvolutionParameter { target, pname, v: convolution_params(params, pname)? }) }
    list glConvolutionParameteri(target: GLenum, pname: GLenum, param: GLint) { |_c| imaging(ImagingCmd::ConvolutionParameter { target, pname, v: [param as f32, 0.0, 0.0, 0.0] }) }
    list glConvolutionParameteriv(target: GLenum, pname: GLenum, params: *const GLint) { |_c| imaging(ImagingCmd::ConvolutionParameter { target, pname, v: convolution_params(params, pname)? }) }
    exec glGetConvolutionFilter(target: GLenum, format: GLenum, type_: GLenum, image: *mut c_void) { |c| if target == GL_SEPARABLE_2D { c.set_error(GL_INVALID_ENUM) } else { c.get_convolution_filter(target, format, type_, image as *mut u8, None) } }
    exec glGetSeparableFilter(target: GLenum, format: GLenum, type_: GLenum, row: *mut c_void, column: *mut c_void, span: *mut c_void) { |c| { let _ = span; if target == GL_SEPARABLE_2D { c.get_convolution_filter(target, format, type_, row as *mut u8, Some(column as *mut u8)) } else { c.set_error(GL_INVALID_ENUM) } } }
    exec glGetConvolutionParameterfv(target: GLenum, pname: GLenum, params: *mut GLfloat) { |c| if let Some(v) = c.get_convolution_parameter(target, pname) { write_out(params, &v.as_f64().iter().map(|&x| x as f32).collect::<Vec<_>>()) } }
    exec glGetConvolutionParameteriv(target: GLenum, pname: GLenum, params: *mut GLint) { |c| if let Some(v) = c.get_convolution_parameter(target, pname) { write_out(params, &v.as_i32()) } }
    list glHistogram(target: GLenum, width: GLsizei, internalformat: GLenum, sink: GLboolean) { |c| imaging_or_proxy(c, ImagingCmd::Histogram { target, width, internal_format: internalformat, sink: truth(sink) })? }
    list glResetHistogram(target: GLenum) { |_c| imaging(ImagingCmd::ResetHistogram(target)) }
    exec glGetHistogram(target: GLenum, reset: GLboolean, format: GLenum, type_: GLenum, values: *mut c_void) { |c| c.get_histogram(target, truth(reset), format, type_, values as *mut u8) }
    exec glGetHistogramParameterfv(target: GLenum, pname: GLenum, params: *mut GLfloat) { |c| if let Some(v) = c.get_histogram_parameter(target, pname) { write_out(params, &v.as_f64().iter().map(|&x| x as f32).collect::<Vec<_>>()) } }
    exec glGetHistogramParameteriv(target: GLenum, pname: GLenum, params: *mut GLint) { |c| if let Some(v) = c.get_histogram_parameter(target, pname) { write_out(params, &v.as_i32()) } }
    list glMinmax(target: GLenum, internalformat: GLenum, sink: GLboolean) { |_c| imaging(ImagingCmd::Minmax { target, internal_format: internalformat, sink: truth(sink) }) }
    list glResetMinmax(target: GLenum) { |_c| imaging(ImagingCmd::ResetMinmax(target)) }
    exec glGetMinmax(target: GLenum, reset: GLboolean, format: GLenum, type_: GLenum, values: *mut c_void) { |c| c.get_minmax(target, truth(reset), format, type_, values as *mut u8) }
    exec glGetMinmaxParameterfv(target: GLenum, pname: GLenum, params: *mut GLfloat) { |c| if let Some(v) = c.get_minmax_parameter(target, pname) { write_out(params, &v.as_f64().iter().map(|&x| x as f32).collect::<Vec<_>>()) } }
    exec glGetMinmaxParameteriv(target: GLenum, pname: GLenum, params: *mut GLint) { |c| if let Some(v) = c.get_minmax_parameter(target, pname) { write_out(params, &v.as_i32()) } }
    list glActiveTexture(texture: GLenum) { |_c| Command::ActiveTexture(texture) }
    client glClientActiveTexture(texture: GLenum) { |c| c.client_active_texture(texture) }
    list glMultiTexCoord1d(target: GLenum, s: GLdouble) { |_c| Command::TexCoord(target, texcoord(&[s])) }
    list glMultiTexCoord1dv(target: GLenum, v: *const GLdouble) { |_c| Command::TexCoord(target, texcoord(&arr::<GLdouble, 1>(v)?)) }
    list glMultiTexCoord1f(target: GLenum, s: GLfloat) { |_c| Command::TexCoord(target, texcoord(&[s])) }
    list glMultiTexCoord1fv(target: GLenum, v: *const GLfloat) { |_c| Command::TexCoord(target, texcoord(&arr::<GLfloat, 1>(v)?)) }
    list glMultiTexCoord1i(target: GLenum, s: GLint) { |_c| Command::TexCoord(target, texcoord(&[s])) }
    list glMultiTexCoord1iv(target: GLenum, v: *const GLint) { |_c| Command::TexCoord(target, texcoord(&arr::<GLint, 1>(v)?)) }
    list glMultiTexCoord1s(target: GLenum, s: GLshort) { |_c| Command::TexCoord(target, texcoord(&[s])) }
    list glMultiTexCoord1sv(target: GLenum, v: *const GLshort) { |_c| Command::TexCoord(target, texcoord(&arr::<GLshort, 1>(v)?)) }
    list glMultiTexCoord2d(target: GLenum, s: GLdouble, t: GLdouble) { |_c| Command::TexCoord(target, texcoord(&[s, t])) }
    list glMultiTexCoord2dv(target: GLenum, v: *const GLdouble) { |_c| Command::TexCoord(target, texcoord(&arr::<GLdouble, 2>(v)?)) }
    list glMultiTexCoord2f(target: GLenum, s: GLfloat, t: GLfloat) { |_c| Command::TexCoord(target, texcoord(&[s, t])) }
    list glMultiTexCoord2fv(target: GLenum, v: *const GLfloat) { |_c| Command::TexCoord(target, texcoord(&arr::<GLfloat, 2>(v)?)) }
    list glMultiTexCoord2i(target: GLenum, s: GLint, t: GLint) { |_c| Command::TexCoord(target, texcoord(&[s, t])) }
    list glMultiTexCoord2iv(target: GLenum, v: *const GLint) { |_c| Command::TexCoord(target, texcoord(&arr::<GLint, 2>(v)?)) }
    list glMultiTexCoord2s(target: GLenum, s: GLshort, t: GLshort) { |_c| Command::TexCoord(target, texcoord(&[s, t])) }
    list glMultiTexCoord2sv(target: GLenum, v: *const GLshort) { |_c| Command::TexCoord(target, texcoord(&arr::<GLshort, 2>(v)?)) }
    list glMultiTexCoord3d(target: GLenum, s: GLdouble, t: GLdouble, r: GLdouble) { |_c| Command::TexCoord(target, texcoord(&[s, t, r])) }
    list glMultiTexCoord3dv(target: GLenum, v: *const GLdouble) { |_c| Command::TexCoord(target, texcoord(&arr::<GLdouble, 3>(v)?)) }
    list glMultiTexCoord3f(target: GLenum, s: GLfloat, t: GLfloat, r: GLfloat) { |_c| Command::TexCoord(target, texcoord(&[s, t, r])) }
    list glMultiTexCoord3fv(target: GLenum, v: *const GLfloat) { |_c| Command::TexCoord(target, texcoord(&arr::<GLfloat, 3>(v)?)) }
    list glMultiTexCoord3i(target: GLenum, s: GLint, t: GLint, r: GLint) { |_c| Command::TexCoord(target, texcoord(&[s, t, r])) }
    list glMultiTexCoord3iv(target: GLenum, v: *const GLint) { |_c| Command::TexCoord(target, texcoord(&arr::<GLint, 3>(v)?)) }
    list glMultiTexCoord3s(target: GLenum, s: GLshort, t: GLshort, r: GLshort) { |_c| Command::TexCoord(target, texcoord(&[s, t, r])) }
    list glMultiTexCoord3sv(target: GLenum, v: *const GLshort) { |_c| Command::TexCoord(target, texcoord(&arr::<GLshort, 3>(v)?)) }
    list glMultiTexCoord4d(target: GLenum, s: GLdouble, t: GLdouble, r: GLdouble, q: GLdouble) { |_c| Command::TexCoord(target, texcoord(&[s, t, r, q])) }
    list glMultiTexCoord4dv(target: GLenum, v: *const GLdouble) { |_c| Command::TexCoord(target, texcoord(&arr::<GLdouble, 4>(v)?)) }
    list glMultiTexCoord4f(target: GLenum, s: GLfloat, t: GLfloat, r: GLfloat, q: GLfloat) { |_c| Command::TexCoord(target, texcoord(&[s, t, r, q])) }
    list glMultiTexCoord4fv(target: GLenum, v: *const GLfloat) { |_c| Command::TexCoord(target, texcoord(&arr::<GLfloat, 4>(v)?)) }
    list glMultiTexCoord4i(target: GLenum, s: GLint, t: GLint, r: GLint, q: GLint) { |_c| Command::TexCoord(target, texcoord(&[s, t, r, q])) }
    list glMultiTexCoord4iv(target: GLenum, v: *const GLint) { |_c| Command::TexCoord(target, texcoord(&arr::<GLint, 4>(v)?)) }
    list glMultiTexCoord4s(target: GLenum, s: GLshort, t: GLshort, r: GLshort, q: GLshort) { |_c| Command::TexCoord(target, texcoord(&[s, t, r, q])) }
    list glMultiTexCoord4sv(target: GLenum, v: *const GLshort) { |_c| Command::TexCoord(target, texcoord(&arr::<GLshort, 4>(v)?)) }
    list glLoadTransposeMatrixf(m: *const GLfloat) { |_c| Command::LoadMatrix(Box::new(matrix(arr::<GLfloat, 16>(m)?.map(f64::from)).transpose())) }
    list glLoadTransposeMatrixd(m: *const GLdouble) { |_c| Command::LoadMatrix(Box::new(matrix(arr::<GLdouble, 16>(m)?).transpose())) }
    list glMultTransposeMatrixf(m: *const GLfloat) { |_c| Command::MultMatrix(Box::new(matrix(arr::<GLfloat, 16>(m)?.map(f64::from)).transpose())) }
    list glMultTransposeMatrixd(m: *const GLdouble) { |_c| Command::MultMatrix(Box::new(matrix(arr::<GLdouble, 16>(m)?).transpose())) }
    list glSampleCoverage(value: GLclampf, invert: GLboolean) { |_c| Command::SampleCoverage(value, truth(invert)) }
    exec["no compressed formats are supported: GL_INVALID_ENUM"] glCompressedTexImage1D(target: GLenum, level: GLint, internalformat: GLenum, width: GLsizei, border: GLint, imageSize: GLsizei, data: *const c_void) { |c| { let _ = (target, level, internalformat, width, border, imageSize, data); c.set_error(GL_INVALID_ENUM) } }
    exec["no compressed formats are supported: GL_INVALID_ENUM"] glCompressedTexImage2D(target: GLenum, level: GLint, internalformat: GLenum, width: GLsizei, height: GLsizei, border: GLint, imageSize: GLsizei, data: *const c_void) { |c| { let _ = (target, level, internalformat, width, height, border, imageSize, data); c.set_error(GL_INVALID_ENUM) } }
    exec["no compressed formats are supported: GL_INVALID_ENUM"] glCompressedTexImage3D(target: GLenum, level: GLint, internalformat: GLenum, width: GLsizei, height: GLsizei, depth: GLsizei, border: GLint, imageSize: GLsizei, data: *const c_void) { |c| { let _ = (target, level, internalformat, width, height, depth, border, imageSize, data); c.set_error(GL_INVALID_ENUM) } }
    exec["no compressed formats are supported: GL_INVALID_ENUM"] glCompressedTexSubImage1D(target: GLenum, level: GLint, xoffset: GLint, width: GLsizei, format: GLenum, imageSize: GLsizei, data: *const c_void) { |c| { let _ = (target, level, xoffset, width, format, imageSize, data); c.set_error(GL_INVALID_ENUM) } }
    exec["no compressed formats are supported: GL_INVALID_ENUM"] glCompressedTexSubImage2D(target: GLenum, level: GLint, xoffset: GLint, yoffset: GLint, width: GLsizei, height: GLsizei, format: GLenum, imageSize: GLsizei, data: *const c_void) { |c| { let _ = (target, level, xoffset, yoffset, width, height, format, imageSize, data); c.set_error(GL_INVALID_ENUM) } }
    exec["no compressed formats are supported: GL_INVALID_ENUM"] glCompressedTexSubImage3D(target: GLenum, level: GLint, xoffset: GLint, yoffset: GLint, zoffset: GLint, width: GLsizei, height: GLsizei, depth: GLsizei, format: GLenum, imageSize: GLsizei, data: *const c_void) { |c| { let _ = (target, level, xoffset, yoffset, zoffset, width, height, depth, format, imageSize, data); c.set_error(GL_INVALID_ENUM) } }
    exec["no image is compressed: GL_INVALID_OPERATION"] glGetCompressedTexImage(target: GLenum, level: GLint, img: *mut c_void) { |c| { let _ = (target, level, img); c.set_error(GL_INVALID_OPERATION) } }
    list glBlendFuncSeparate(sfactorRGB: GLenum, dfactorRGB: GLenum, sfactorAlpha: GLenum, dfactorAlpha: GLenum) { |_c| Command::BlendFunc([sfactorRGB, dfactorRGB, sfactorAlpha, dfactorAlpha]) }
    list glFogCoordf(coord: GLfloat) { |_c| Command::FogCoord(coord) }
    list glFogCoordfv(coord: *const GLfloat) { |_c| Command::FogCoord(arr::<GLfloat, 1>(coord)?[0]) }
    list glFogCoordd(coord: GLdouble) { |_c| Command::FogCoord(coord as f32) }
    list glFogCoorddv(coord: *const GLdouble) { |_c| Command::FogCoord(arr::<GLdouble, 1>(coord)?[0] as f32) }
    client glFogCoordPointer(type_: GLenum, stride: GLsizei, pointer: *const c_void) { |c| c.array_pointer(Array::FogCoord, 1, type_, stride, pointer as usize) }
    draw glMultiDrawArrays(mode: GLenum, first: *const GLint, count: *const GLsizei, drawcount: GLsizei) { |c| if drawcount < 0 { c.set_error(GL_INVALID_VALUE) } else if !first.is_null() && !count.is_null() { c.multi_draw_arrays(mode, &slice(first, drawcount as i64), &slice(count, drawcount as i64)) } }
    draw glMultiDrawElements(mode: GLenum, count: *const GLsizei, type_: GLenum, indices: *const *const c_void, drawcount: GLsizei) { |c| if drawcount < 0 { c.set_error(GL_INVALID_VALUE) } else if !count.is_null() && !indices.is_null() { c.multi_draw_elements(mode, &slice(count, drawcount as i64), type_, &slice(indices, drawcount as i64).into_iter().map(|p| p as usize).collect::<Vec<_>>()) } }
    list glPointParameterf(pname: GLenum, param: GLfloat) { |c| Command::PointParameter(scalar_param(c, (pname != 0x8129) as usize, pname)?, [param, 0.0, 0.0]) }
    list glPointParameterfv(pname: GLenum, params: *const GLfloat) { |_c| Command::PointParameter(pname, point_params(params, pname)?) }
    list glPointParameteri(pname: GLenum, param: GLint) { |c| Command::PointParameter(scalar_param(c, (pname != 0x8129) as usize, pname)?, [param as f32, 0.0, 0.0]) }
    list glPointParameteriv(pname: GLenum, params: *const GLint) { |_c| Command::PointParameter(pname, point_params(params, pname)?) }
    list glSecondaryColor3b(red: GLbyte, green: GLbyte, blue: GLbyte) { |_c| Command::SecondaryColor(color(&[red, green, blue])) }
    list glSecondaryColor3bv(v: *const GLbyte) { |_c| Command::SecondaryColor(color(&arr::<GLbyte, 3>(v)?)) }
    list glSecondaryColor3d(red: GLdouble, green: GLdouble, blue: GLdouble) { |_c| Command::SecondaryColor(color(&[red, green, blue])) }
    list glSecondaryColor3dv(v: *const GLdouble) { |_c| Command::SecondaryColor(color(&arr::<GLdouble, 3>(v)?)) }
    list glSecondaryColor3f(red: GLfloat, green: GLfloat, blue: GLfloat) { |_c| Command::SecondaryColor(color(&[red, green, blue])) }
    list glSecondaryColor3fv(v: *const GLfloat) { |_c| Command::SecondaryColor(color(&arr::<GLfloat, 3>(v)?)) }
    list glSecondaryColor3i(red: GLint, green: GLint, blue: GLint) { |_c| Command::SecondaryColor(color(&[red, green, blue])) }
    list glSecondaryColor3iv(v: *const GLint) { |_c| Command::SecondaryColor(color(&arr::<GLint, 3>(v)?)) }
    list glSecondaryColor3s(red: GLshort, green: GLshort, blue: GLshort) { |_c| Command::SecondaryColor(color(&[red, green, blue])) }
    list glSecondaryColor3sv(v: *const GLshort) { |_c| Command::SecondaryColor(color(&arr::<GLshort, 3>(v)?)) }
    list glSecondaryColor3ub(red: GLubyte, green: GLubyte, blue: GLubyte) { |_c| Command::SecondaryColor(color(&[red, green, blue])) }
    list glSecondaryColor3ubv(v: *const GLubyte) { |_c| Command::SecondaryColor(color(&arr::<GLubyte, 3>(v)?)) }
    list glSecondaryColor3ui(red: GLuint, green: GLuint, blue: GLuint) { |_c| Command::SecondaryColor(color(&[red, green, blue])) }
    list glSecondaryColor3uiv(v: *const GLuint) { |_c| Command::SecondaryColor(color(&arr::<GLuint, 3>(v)?)) }
    list glSecondaryColor3us(red: GLushort, green: GLushort, blue: GLushort) { |_c| Command::SecondaryColor(color(&[red, green, blue])) }
    list glSecondaryColor3usv(v: *const GLushort) { |_c| Command::SecondaryColor(color(&arr::<GLushort, 3>(v)?)) }
    client glSecondaryColorPointer(size: GLint, type_: GLenum, stride: GLsizei, pointer: *const c_void) { |c| c.array_pointer(Array::SecondaryColor, size, type_, stride, pointer as usize) }
    list glWindowPos2d(x: GLdouble, y: GLdouble) { |_c| window_pos(&[x, y]) }
    list glWindowPos2dv(v: *const GLdouble) { |_c| window_pos(&arr::<GLdouble, 2>(v)?) }
    list glWindowPos2f(x: GLfloat, y: GLfloat) { |_c| window_pos(&[x, y]) }
    list glWindowPos2fv(v: *const GLfloat) { |_c| window_pos(&arr::<GLfloat, 2>(v)?) }
    list glWindowPos2i(x: GLint, y: GLint) { |_c| window_pos(&[x, y]) }
    list glWindowPos2iv(v: *const GLint) { |_c| window_pos(&arr::<GLint, 2>(v)?) }
    list glWindowPos2s(x: GLshort, y: GLshort) { |_c| window_pos(&[x, y]) }
    list glWindowPos2sv(v: *const GLshort) { |_c| window_pos(&arr::<GLshort, 2>(v)?) }
    list glWindowPos3d(x: GLdouble, y: GLdouble, z: GLdouble) { |_c| window_pos(&[x, y, z]) }
    list glWindowPos3dv(v: *const GLdouble) { |_c| window_pos(&arr::<GLdouble, 3>(v)?) }
    list glWindowPos3f(x: GLfloat, y: GLfloat, z: GLfloat) { |_c| window_pos(&[x, y, z]) }
    list glWindowPos3fv(v: *const GLfloat) { |_c| window_pos(&arr::<GLfloat, 3>(v)?) }
    list glWindowPos3i(x: GLint, y: GLint, z: GLint) { |_c| window_pos(&[x, y, z]) }
    list glWindowPos3iv(v: *const GLint) { |_c| window_pos(&arr::<GLint, 3>(v)?) }
    list glWindowPos3s(x: GLshort, y: GLshort, z: GLshort) { |_c| window_pos(&[x, y, z]) }
    list glWindowPos3sv(v: *const GLshort) { |_c| window_pos(&arr::<GLshort, 3>(v)?) }
    exec glGenQueries(n: GLsizei, ids: *mut GLuint) { |c| if let Some(v) = c.gen_queries(n) { write_out(ids, &v) } }
    exec glDeleteQueries(n: GLsizei, ids: *const GLuint) { |c| if n < 0 { c.set_error(GL_INVALID_VALUE) } else { c.delete_queries(&slice(ids, n as i64)) } }
    exec glIsQuery(id: GLuint) -> GLboolean { |c| gl_bool(c.is_query(id)) }
    list glBeginQuery(target: GLenum, id: GLuint) { |_c| Command::BeginQuery(target, id) }
    list glEndQuery(target: GLenum) { |_c| Command::EndQuery(target) }
    exec glGetQueryiv(target: GLenum, pname: GLenum, params: *mut GLint) { |c| if let Some(v) = c.get_query(target, pname) { write_out(params, &[v as GLint]) } }
    exec glGetQueryObjectiv(id: GLuint, pname: GLenum, params: *mut GLint) { |c| if let Some(v) = c.get_query_object(id, pname) { write_out(params, &[v.min(i32::MAX as u64) as GLint]) } }
    exec glGetQueryObjectuiv(id: GLuint, pname: GLenum, params: *mut GLuint) { |c| if let Some(v) = c.get_query_object(id, pname) { write_out(params, &[v.min(u32::MAX as u64) as GLuint]) } }
    exec glBindBuffer(target: GLenum, buffer: GLuint) { |c| c.bind_buffer(target, buffer) }
    exec glDeleteBuffers(n: GLsizei, buffers: *const GLuint) { |c| if n < 0 { c.set_error(GL_INVALID_VALUE) } else { c.delete_buffers(&slice(buffers, n as i64)) } }
    exec glGenBuffers(n: GLsizei, buffers: *mut GLuint) { |c| if let Some(v) = c.gen_buffers(n) { write_out(buffers, &v) } }
    exec glIsBuffer(buffer: GLuint) -> GLboolean { |c| gl_bool(c.buffers.is_buffer(buffer)) }
    exec glBufferData(target: GLenum, size: GLsizeiptr, data: *const c_void, usage: GLenum) { |c| c.buffer_data(target, size, data as *const u8, usage) }
    exec glBufferSubData(target: GLenum, offset: GLintptr, size: GLsizeiptr, data: *const c_void) { |c| c.buffer_sub_data(target, offset, size, data as *const u8) }
    exec glGetBufferSubData(target: GLenum, offset: GLintptr, size: GLsizeiptr, data: *mut c_void) { |c| c.get_buffer_sub_data(target, offset, size, data as *mut u8) }
    exec glMapBuffer(target: GLenum, access: GLenum) -> *mut c_void { |c| c.map_buffer(target, access) as *mut c_void }
    exec glUnmapBuffer(target: GLenum) -> GLboolean { |c| gl_bool(c.unmap_buffer(target)) }
    exec glGetBufferParameteriv(target: GLenum, pname: GLenum, params: *mut GLint) { |c| if let Some(v) = c.get_buffer_parameter(target, pname) { write_out(params, &[v as GLint]) } }
    exec glGetBufferPointerv(target: GLenum, pname: GLenum, params: *mut *mut c_void) { |c| if let Some(p) = c.get_buffer_pointer(target, pname) { write_out(params, &[p as *mut c_void]) } }

    // ---- GL_ARB_framebuffer_object (core names) and GL_EXT_framebuffer_object ----
    exec glIsRenderbuffer(renderbuffer: GLuint) -> GLboolean { |c| gl_bool(c.is_renderbuffer(renderbuffer)) }
    exec glBindRenderbuffer(target: GLenum, renderbuffer: GLuint) { |c| c.bind_renderbuffer(target, renderbuffer) }
    exec glDeleteRenderbuffers(n: GLsizei, renderbuffers: *const GLuint) { |c| if n < 0 { c.set_error(GL_INVALID_VALUE) } else { c.delete_renderbuffers(&slice(renderbuffers, n as i64)) } }
    exec glGenRenderbuffers(n: GLsizei, renderbuffers: *mut GLuint) { |c| if let Some(v) = c.gen_renderbuffers(n) { write_out(renderbuffers, &v) } }
    exec glRenderbufferStorage(target: GLenum, internalformat: GLenum, width: GLsizei, height: GLsizei) { |c| c.renderbuffer_storage(target, 0, internalformat, width, height) }
    exec glGetRenderbufferParameteriv(target: GLenum, pname: GLenum, params: *mut GLint) { |c| if let Some(v) = c.get_renderbuffer_parameter(target, pname) { write_out(params, &[v]) } }
    exec glIsFramebuffer(framebuffer: GLuint) -> GLboolean { |c| gl_bool(c.is_framebuffer(framebuffer)) }
    exec glBindFramebuffer(target: GLenum, framebuffer: GLuint) { |c| c.bind_framebuffer(target, framebuffer) }
    exec glDeleteFramebuffers(n: GLsizei, framebuffers: *const GLuint) { |c| if n < 0 { c.set_error(GL_INVALID_VALUE) } else { c.delete_framebuffers(&slice(framebuffers, n as i64)) } }
    exec glGenFramebuffers(n: GLsizei, framebuffers: *mut GLuint) { |c| if let Some(v) = c.gen_framebuffers(n) { write_out(framebuffers, &v) } }
    exec glCheckFramebufferStatus(target: GLenum) -> GLenum { |c| c.check_framebuffer_status(target) }
    exec glFramebufferTexture1D(target: GLenum, attachment: GLenum, textarget: GLenum, texture: GLuint, level: GLint) { |c| c.framebuffer_texture(1, target, attachment, textarget, texture, level, 0) }
    exec glFramebufferTexture2D(target: GLenum, attachment: GLenum, textarget: GLenum, texture: GLuint, level: GLint) { |c| c.framebuffer_texture(2, target, attachment, textarget, texture, level, 0) }
    exec glFramebufferTexture3D(target: GLenum, attachment: GLenum, textarget: GLenum, texture: GLuint, level: GLint, zoffset: GLint) { |c| c.framebuffer_texture(3, target, attachment, textarget, texture, level, zoffset) }
    exec glFramebufferRenderbuffer(target: GLenum, attachment: GLenum, renderbuffertarget: GLenum, renderbuffer: GLuint) { |c| c.framebuffer_renderbuffer(target, attachment, renderbuffertarget, renderbuffer) }
    exec glGetFramebufferAttachmentParameteriv(target: GLenum, attachment: GLenum, pname: GLenum, params: *mut GLint) { |c| if let Some(v) = c.get_framebuffer_attachment_parameter(target, attachment, pname) { write_out(params, &[v]) } }
    exec glGenerateMipmap(target: GLenum) { |c| c.generate_mipmap(target) }
    exec glFramebufferTextureLayer(target: GLenum, attachment: GLenum, texture: GLuint, level: GLint, layer: GLint) { |c| c.framebuffer_texture(0, target, attachment, 0, texture, level, layer) }
    exec glRenderbufferStorageMultisample(target: GLenum, samples: GLsizei, internalformat: GLenum, width: GLsizei, height: GLsizei) { |c| c.renderbuffer_storage(target, samples, internalformat, width, height) }
    exec glBlitFramebuffer(srcX0: GLint, srcY0: GLint, srcX1: GLint, srcY1: GLint, dstX0: GLint, dstY0: GLint, dstX1: GLint, dstY1: GLint, mask: GLbitfield, filter: GLenum) { |c| c.blit_framebuffer([srcX0, srcY0, srcX1, srcY1], [dstX0, dstY0, dstX1, dstY1], mask, filter) }
    exec glIsRenderbufferEXT(renderbuffer: GLuint) -> GLboolean { |c| gl_bool(c.is_renderbuffer(renderbuffer)) }
    exec glBindRenderbufferEXT(target: GLenum, renderbuffer: GLuint) { |c| c.bind_renderbuffer(target, renderbuffer) }
    exec glDeleteRenderbuffersEXT(n: GLsizei, renderbuffers: *const GLuint) { |c| if n < 0 { c.set_error(GL_INVALID_VALUE) } else { c.delete_renderbuffers(&slice(renderbuffers, n as i64)) } }
    exec glGenRenderbuffersEXT(n: GLsizei, renderbuffers: *mut GLuint) { |c| if let Some(v) = c.gen_renderbuffers(n) { write_out(renderbuffers, &v) } }
    exec glRenderbufferStorageEXT(target: GLenum, internalformat: GLenum, width: GLsizei, height: GLsizei) { |c| c.renderbuffer_storage(target, 0, internalformat, width, height) }
    exec glGetRenderbufferParameterivEXT(target: GLenum, pname: GLenum, params: *mut GLint) { |c| if let Some(v) = c.get_renderbuffer_parameter(target, pname) { write_out(params, &[v]) } }
    exec glIsFramebufferEXT(framebuffer: GLuint) -> GLboolean { |c| gl_bool(c.is_framebuffer(framebuffer)) }
    exec glBindFramebufferEXT(target: GLenum, framebuffer: GLuint) { |c| c.bind_framebuffer(target, framebuffer) }
    exec glDeleteFramebuffersEXT(n: GLsizei, framebuffers: *const GLuint) { |c| if n < 0 { c.set_error(GL_INVALID_VALUE) } else { c.delete_framebuffers(&slice(framebuffers, n as i64)) } }
    exec glGenFramebuffersEXT(n: GLsizei, framebuffers: *mut GLuint) { |c| if let Some(v) = c.gen_framebuffers(n) { write_out(framebuffers, &v) } }
    exec glCheckFramebufferStatusEXT(target: GLenum) -> GLenum { |c| c.check_framebuffer_status(target) }
    exec glFramebufferTexture1DEXT(target: GLenum, attachment: GLenum, textarget: GLenum, texture: GLuint, level: GLint) { |c| c.framebuffer_texture(1, target, attachment, textarget, texture, level, 0) }
    exec glFramebufferTexture2DEXT(target: GLenum, attachment: GLenum, textarget: GLenum, texture: GLuint, level: GLint) { |c| c.framebuffer_texture(2, target, attachment, textarget, texture, level, 0) }
    exec glFramebufferTexture3DEXT(target: GLenum, attachment: GLenum, textarget: GLenum, texture: GLuint, level: GLint, zoffset: GLint) { |c| c.framebuffer_texture(3, target, attachment, textarget, texture, level, zoffset) }
    exec glFramebufferRenderbufferEXT(target: GLenum, attachment: GLenum, renderbuffertarget: GLenum, renderbuffer: GLuint) { |c| c.framebuffer_renderbuffer(target, attachment, renderbuffertarget, renderbuffer) }
    exec glGetFramebufferAttachmentParameterivEXT(target: GLenum, attachment: GLenum, pname: GLenum, params: *mut GLint) { |c| if let Some(v) = c.get_framebuffer_attachment_parameter(target, attachment, pname) { write_out(params, &[v]) } }
    exec glGenerateMipmapEXT(target: GLenum) { |c| c.generate_mipmap(target) }
    // ---- GL_ARB_sampler_objects ----
    exec glGenSamplers(count: GLsizei, samplers: *mut GLuint) { |c| if let Some(v) = c.gen_samplers(count) { write_out(samplers, &v) } }
    exec glDeleteSamplers(count: GLsizei, samplers: *const GLuint) { |c| if count < 0 { c.set_error(GL_INVALID_VALUE) } else { c.delete_samplers(&slice(samplers, count as i64)) } }
    exec glIsSampler(sampler: GLuint) -> GLboolean { |c| gl_bool(c.is_sampler(sampler)) }
    exec glBindSampler(unit: GLuint, sampler: GLuint) { |c| c.bind_sampler(unit, sampler) }
    exec glSamplerParameteri(sampler: GLuint, pname: GLenum, param: GLint) { |c| c.sampler_parameter(sampler, pname, [param as f32, 0.0, 0.0, 0.0]) }
    exec glSamplerParameterf(sampler: GLuint, pname: GLenum, param: GLfloat) { |c| c.sampler_parameter(sampler, pname, [param, 0.0, 0.0, 0.0]) }
    exec glSamplerParameteriv(sampler: GLuint, pname: GLenum, param: *const GLint) { |c| if let Some(v) = sampler_params_i(param, pname) { c.sampler_parameter(sampler, pname, v) } }
    exec glSamplerParameterfv(sampler: GLuint, pname: GLenum, param: *const GLfloat) { |c| if let Some(v) = sampler_params_f(param, pname) { c.sampler_parameter(sampler, pname, v) } }
    exec glGetSamplerParameteriv(sampler: GLuint, pname: GLenum, params: *mut GLint) { |c| if let Some(v) = c.get_sampler_parameter(sampler, pname) { write_out(params, &v.as_i32()) } }
    exec glGetSamplerParameterfv(sampler: GLuint, pname: GLenum, params: *mut GLfloat) { |c| if let Some(v) = c.get_sampler_parameter(sampler, pname) { write_out(params, &v.as_f64().iter().map(|&x| x as f32).collect::<Vec<_>>()) } }
    // ---- GL_ARB_texture_storage ----
    exec glTexStorage1D(target: GLenum, levels: GLsizei, internalformat: GLenum, width: GLsizei) { |c| c.tex_storage(1, target, levels, internalformat, [width, 1, 1]) }
    exec glTexStorage2D(target: GLenum, levels: GLsizei, internalformat: GLenum, width: GLsizei, height: GLsizei) { |c| c.tex_storage(2, target, levels, internalformat, [width, height, 1]) }
    exec glTexStorage3D(target: GLenum, levels: GLsizei, internalformat: GLenum, width: GLsizei, height: GLsizei, depth: GLsizei) { |c| c.tex_storage(3, target, levels, internalformat, [width, height, depth]) }
    exec glBlitFramebufferEXT(srcX0: GLint, srcY0: GLint, srcX1: GLint, srcY1: GLint, dstX0: GLint, dstY0: GLint, dstX1: GLint, dstY1: GLint, mask: GLbitfield, filter: GLenum) { |c| c.blit_framebuffer([srcX0, srcY0, srcX1, srcY1], [dstX0, dstY0, dstX1, dstY1], mask, filter) }
    // ---- GL_ARB_map_buffer_range ----
    exec glMapBufferRange(target: GLenum, offset: GLintptr, length: GLsizeiptr, access: GLbitfield) -> *mut c_void { |c| c.map_buffer_range(target, offset, length, access) as *mut c_void }
    exec glFlushMappedBufferRange(target: GLenum, offset: GLintptr, length: GLsizeiptr) { |c| c.flush_mapped_buffer_range(target, offset, length) }

    // ---- glu.h ----
    glu gluErrorString(error: GLenum) -> *const GLubyte { glu::strings::error_string(error) }
    glu gluGetString(name: GLenum) -> *const GLubyte { glu::strings::get_string(name) }
    glu gluCheckExtension(extName: *const GLubyte, extString: *const GLubyte) -> GLboolean { glu::strings::check_extension(extName, extString) }
    glu gluOrtho2D(left: GLdouble, right: GLdouble, bottom: GLdouble, top: GLdouble) { glu::matrix::ortho_2d(left, right, bottom, top) }
    glu gluPerspective(fovy: GLdouble, aspect: GLdouble, zNear: GLdouble, zFar: GLdouble) { glu::matrix::perspective(fovy, aspect, zNear, zFar) }
    glu gluLookAt(eyeX: GLdouble, eyeY: GLdouble, eyeZ: GLdouble, centerX: GLdouble, centerY: GLdouble, centerZ: GLdouble, upX: GLdouble, upY: GLdouble, upZ: GLdouble) { glu::matrix::look_at([eyeX, eyeY, eyeZ], [centerX, centerY, centerZ], [upX, upY, upZ]) }
    glu gluPickMatrix(x: GLdouble, y: GLdouble, delX: GLdouble, delY: GLdouble, viewport: *mut GLint) { glu::matrix::pick_matrix(x, y, delX, delY, viewport) }
    glu gluProject(objX: GLdouble, objY: GLdouble, objZ: GLdouble, model: *const GLdouble, proj: *const GLdouble, view: *const GLint, winX: *mut GLdouble, winY: *mut GLdouble, winZ: *mut GLdouble) -> GLint { glu::matrix::project([objX, objY, objZ], model, proj, view, [winX, winY, winZ]) }
    glu gluUnProject(winX: GLdouble, winY: GLdouble, winZ: GLdouble, model: *const GLdouble, proj: *const GLdouble, view: *const GLint, objX: *mut GLdouble, objY: *mut GLdouble, objZ: *mut GLdouble) -> GLint { glu::matrix::unproject([winX, winY, winZ, 1.0], model, proj, view, 0.0, 1.0, [objX, objY, objZ, std::ptr::null_mut()]) }
    glu gluUnProject4(winX: GLdouble, winY: GLdouble, winZ: GLdouble, clipW: GLdouble, model: *const GLdouble, proj: *const GLdouble, view: *const GLint, nearVal: GLdouble, farVal: GLdouble, objX: *mut GLdouble, objY: *mut GLdouble, objZ: *mut GLdouble, objW: *mut GLdouble) -> GLint { glu::matrix::unproject([winX, winY, winZ, clipW], model, proj, view, nearVal, farVal, [objX, objY, objZ, objW]) }
    glu gluScaleImage(format: GLenum, wIn: GLsizei, hIn: GLsizei, typeIn: GLenum, dataIn: *const c_void, wOut: GLsizei, hOut: GLsizei, typeOut: GLenum, dataOut: *mut c_void) -> GLint { glu::scale::scale_image(&mut glu::scale::GlPixels, format, wIn, hIn, typeIn, dataIn, wOut, hOut, typeOut, dataOut) }
    glu gluBuild1DMipmaps(target: GLenum, internalFormat: GLint, width: GLsizei, format: GLenum, type_: GLenum, data: *const c_void) -> GLint { glu::mipmap::build_mipmaps(&mut glu::mipmap::GlTex, 1, target, internalFormat, [width, 1, 1], format, type_, data) }
    glu gluBuild2DMipmaps(target: GLenum, internalFormat: GLint, width: GLsizei, height: GLsizei, format: GLenum, type_: GLenum, data: *const c_void) -> GLint { glu::mipmap::build_mipmaps(&mut glu::mipmap::GlTex, 2, target, internalFormat, [width, height, 1], format, type_, data) }
    glu gluBuild3DMipmaps(target: GLenum, internalFormat: GLint, width: GLsizei, height: GLsizei, depth: GLsizei, format: GLenum, type_: GLenum, data: *const c_void) -> GLint { glu::mipmap::build_mipmaps(&mut glu::mipmap::GlTex, 3, target, internalFormat, [width, height, depth], format, type_, data) }
    glu gluBuild1DMipmapLevels(target: GLenum, internalFormat: GLint, width: GLsizei, format: GLenum, type_: GLenum, level: GLint, base: GLint, max: GLint, data: *const c_void) -> GLint { glu::mipmap::build_mipmap_levels(&mut glu::mipmap::GlTex, 1, target, internalFormat, [width, 1, 1], format, type_, level, base, max, data) }
    glu gluBuild2DMipmapLevels(target: GLenum, internalFormat: GLint, width: GLsizei, height: GLsizei, format: GLenum, type_: GLenum, level: GLint, base: GLint, max: GLint, data: *const c_void) -> GLint { glu::mipmap::build_mipmap_levels(&mut glu::mipmap::GlTex, 2, target, internalFormat, [width, height, 1], format, type_, level, base, max, data) }
    glu gluBuild3DMipmapLevels(target: GLenum, internalFormat: GLint, width: GLsizei, height: GLsizei, depth: GLsizei, format: GLenum, type_: GLenum, level: GLint, base: GLint, max: GLint, data: *const c_void) -> GLint { glu::mipmap::build_mipmap_levels(&mut glu::mipmap::GlTex, 3, target, internalFormat, [width, height, depth], format, type_, level, base, max, data) }
    glu gluNewQuadric() -> *mut GLUquadric { glu::quadric::new_quadric() }
    glu gluDeleteQuadric(quad: *mut GLUquadric) { glu::quadric::delete_quadric(quad) }
    glu gluQuadricCallback(quad: *mut GLUquadric, which: GLenum, CallBackFunc: GLproc) { glu::quadric::with(quad, |q| q.set_callback(which, CallBackFunc)) }
    glu gluQuadricDrawStyle(quad: *mut GLUquadric, draw: GLenum) { glu::quadric::with(quad, |q| q.set_draw_style(draw)) }
    glu gluQuadricNormals(quad: *mut GLUquadric, normal: GLenum) { glu::quadric::with(quad, |q| q.set_normals(normal)) }
    glu gluQuadricOrientation(quad: *mut GLUquadric, orientation: GLenum) { glu::quadric::with(quad, |q| q.set_orientation(orientation)) }
    glu gluQuadricTexture(quad: *mut GLUquadric, texture: GLboolean) { glu::quadric::with(quad, |q| q.set_texture(truth(texture))) }
    glu gluSphere(quad: *mut GLUquadric, radius: GLdouble, slices: GLint, stacks: GLint) { glu::quadric::with(quad, |q| q.sphere(&mut glu::quadric::GlSink, radius, slices, stacks)) }
    glu gluCylinder(quad: *mut GLUquadric, base: GLdouble, top: GLdouble, height: GLdouble, slices: GLint, stacks: GLint) { glu::quadric::with(quad, |q| q.cylinder(&mut glu::quadric::GlSink, base, top, height, slices, stacks)) }
    glu gluDisk(quad: *mut GLUquadric, inner: GLdouble, outer: GLdouble, slices: GLint, loops: GLint) { glu::quadric::with(quad, |q| q.disk(&mut glu::quadric::GlSink, inner, outer, slices, loops)) }
    glu gluPartialDisk(quad: *mut GLUquadric, inner: GLdouble, outer: GLdouble, slices: GLint, loops: GLint, start: GLdouble, sweep: GLdouble) { glu::quadric::with(quad, |q| q.partial_disk(&mut glu::quadric::GlSink, inner, outer, slices, loops, start, sweep)) }
    glu gluNewTess() -> *mut GLUtesselator { glu::tess::new_tess() }
    glu gluDeleteTess(tess: *mut GLUtesselator) { glu::tess::delete_tess(tess) }
    glu gluTessBeginPolygon(tess: *mut GLUtesselator, data: *mut c_void) { glu::tess::begin_polygon(tess, data) }
    glu gluTessBeginContour(tess: *mut GLUtesselator) { glu::tess::begin_contour(tess) }
    glu gluTessVertex(tess: *mut GLUtesselator, location: *mut GLdouble, data: *mut c_void) { glu::tess::vertex(tess, location, data) }
    glu gluTessEndContour(tess: *mut GLUtesselator) { glu::tess::end_contour(tess) }
    glu gluTessEndPolygon(tess: *mut GLUtesselator) { glu::tess::end_polygon(tess) }
    glu gluTessCallback(tess: *mut GLUtesselator, which: GLenum, CallBackFunc: GLproc) { glu::tess::callback(tess, which, CallBackFunc) }
    glu gluTessProperty(tess: *mut GLUtesselator, which: GLenum, data: GLdouble) { glu::tess::property(tess, which, data) }
    glu gluGetTessProperty(tess: *mut GLUtesselator, which: GLenum, data: *mut GLdouble) { glu::tess::get_property(tess, which, data) }
    glu gluTessNormal(tess: *mut GLUtesselator, valueX: GLdouble, valueY: GLdouble, valueZ: GLdouble) { glu::tess::normal(tess, valueX, valueY, valueZ) }
    glu gluBeginPolygon(tess: *mut GLUtesselator) { glu::tess::begin_polygon_11(tess) }
    glu gluNextContour(tess: *mut GLUtesselator, type_: GLenum) { glu::tess::next_contour(tess, type_) }
    glu gluEndPolygon(tess: *mut GLUtesselator) { glu::tess::end_polygon_11(tess) }
    glu gluNewNurbsRenderer() -> *mut GLUnurbs { glu::nurbs::new_nurbs() }
    glu gluDeleteNurbsRenderer(nurb: *mut GLUnurbs) { glu::nurbs::delete_nurbs(nurb) }
    glu gluNurbsProperty(nurb: *mut GLUnurbs, property: GLenum, value: GLfloat) { glu::nurbs::with(nurb, |n| n.set_property(property, value)) }
    glu gluGetNurbsProperty(nurb: *mut GLUnurbs, property: GLenum, data: *mut GLfloat) { glu::nurbs::get_property(nurb, property, data) }
    glu gluLoadSamplingMatrices(nurb: *mut GLUnurbs, model: *const GLfloat, perspective: *const GLfloat, view: *const GLint) { glu::nurbs::with(nurb, |n| n.load_sampling_matrices(model, perspective, view)) }
    glu gluNurbsCallback(nurb: *mut GLUnurbs, which: GLenum, CallBackFunc: GLproc) { glu::nurbs::with(nurb, |n| n.set_callback(which, CallBackFunc)) }
    glu gluNurbsCallbackData(nurb: *mut GLUnurbs, userData: *mut c_void) { glu::nurbs::with(nurb, |n| n.set_callback_data(userData)) }
    glu gluNurbsCallbackDataEXT(nurb: *mut GLUnurbs, userData: *mut c_void) { glu::nurbs::with(nurb, |n| n.set_callback_data(userData)) }
    glu gluBeginCurve(nurb: *mut GLUnurbs) { glu::nurbs::with(nurb, |n| n.begin_curve()) }
    glu gluNurbsCurve(nurb: *mut GLUnurbs, knotCount: GLint, knots: *mut GLfloat, stride: GLint, control: *mut GLfloat, order: GLint, type_: GLenum) { glu::nurbs::with(nurb, |n| n.nurbs_curve(knotCount, knots, stride, control, order, type_)) }
    glu gluEndCurve(nurb: *mut GLUnurbs) { glu::nurbs::with(nurb, |n| n.end_curve()) }
    glu gluBeginSurface(nurb: *mut GLUnurbs) { glu::nurbs::with(nurb, |n| n.begin_surface()) }
    glu gluNurbsSurface(nurb: *mut GLUnurbs, sKnotCount: GLint, sKnots: *mut GLfloat, tKnotCount: GLint, tKnots: *mut GLfloat, sStride: GLint, tStride: GLint, control: *mut GLfloat, sOrder: GLint, tOrder: GLint, type_: GLenum) { glu::nurbs::with(nurb, |n| n.nurbs_surface(sKnotCount, sKnots, tKnotCount, tKnots, sStride, tStride, control, sOrder, tOrder, type_)) }
    glu gluEndSurface(nurb: *mut GLUnurbs) { glu::nurbs::with(nurb, |n| n.end_surface()) }
    glu gluBeginTrim(nurb: *mut GLUnurbs) { glu::nurbs::with(nurb, |n| n.begin_trim()) }
    glu gluPwlCurve(nurb: *mut GLUnurbs, count: GLint, data: *mut GLfloat, stride: GLint, type_: GLenum) { glu::nurbs::with(nurb, |n| n.pwl_curve(count, data, stride, type_)) }
    glu gluEndTrim(nurb: *mut GLUnurbs) { glu::nurbs::with(nurb, |n| n.end_trim()) }

    // ---- osmesa.h ----
    free OSMesaCreateContext(format: GLenum, sharelist: *mut OsContext) -> *mut OsContext { osmesa::create_context_ext(format, 24, 8, 0, sharelist) }
    free OSMesaCreateContextExt(format: GLenum, depthBits: GLint, stencilBits: GLint, accumBits: GLint, sharelist: *mut OsContext) -> *mut OsContext { osmesa::create_context_ext(format, depthBits, stencilBits, accumBits, sharelist) }
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
    free["single- and double-buffered configs have visuals of their own where the screen has two per depth (else buffering is as glXChooseVisual was last asked for the visual); no colour-index, stereo or multisample visuals"] glXChooseVisual(dpy: *mut Display, screen: c_int, attribList: *mut c_int) -> *mut XVisualInfo { glx::choose_visual(dpy, screen, attribList) }
    free glXGetConfig(dpy: *mut Display, vis: *mut XVisualInfo, attrib: c_int, value: *mut c_int) -> c_int { glx::get_config(dpy, vis, attrib, value) }
    free glXCreateContext(dpy: *mut Display, vis: *mut XVisualInfo, shareList: GLXContext, direct: Bool) -> GLXContext { glx::create_context(dpy, vis, shareList, direct) }
    free glXDestroyContext(dpy: *mut Display, ctx: GLXContext) { glx::destroy_context(dpy, ctx) }
    free glXMakeCurrent(dpy: *mut Display, drawable: GLXDrawable, ctx: GLXContext) -> Bool { glx::make_current(dpy, drawable, ctx) }
    free glXCopyContext(dpy: *mut Display, src: GLXContext, dst: GLXContext, mask: std::ffi::c_ulong) { glx::copy_context(dpy, src, dst, mask) }
    free glXSwapBuffers(dpy: *mut Display, drawable: GLXDrawable) { glx::swap_buffers(dpy, drawable) }
    free glXCreateGLXPixmap(dpy: *mut Display, visual: *mut XVisualInfo, pixmap: XID) -> GLXDrawable { glx::create_glx_pixmap(dpy, visual, pixmap) }
    free glXDestroyGLXPixmap(dpy: *mut Display, pixmap: GLXDrawable) { glx::destroy_pixmap(dpy, pixmap) }
    free glXIsDirect(dpy: *mut Display, ctx: GLXContext) -> Bool { glx::is_direct(dpy, ctx) }
    free glXGetCurrentContext() -> GLXContext { glx::get_current_context() }
    free glXGetCurrentDrawable() -> GLXDrawable { glx::get_current_drawable() }
    free glXWaitGL() { glx::wait_gl() }
    free glXWaitX() { glx::wait_x() }
    free["draws with softgl's built-in bitmap fonts sized like the X font, not the X font's own glyphs"] glXUseXFont(font: XID, first: c_int, count: c_int, list: c_int) { glx::use_x_font(font, first, count, list) }
    free glXGetCurrentDisplay() -> *mut Display { glx::get_current_display() }
    free glXChooseFBConfig(dpy: *mut Display, screen: c_int, attribList: *const c_int, nitems: *mut c_int) -> *mut GLXFBConfig { glx::choose_fb_config(dpy, screen, attribList, nitems) }
    free glXGetFBConfigAttrib(dpy: *mut Display, config: GLXFBConfig, attribute: c_int, value: *mut c_int) -> c_int { glx::get_fb_config_attrib(dpy, config, attribute, value) }
    free glXGetFBConfigs(dpy: *mut Display, screen: c_int, nelements: *mut c_int) -> *mut GLXFBConfig { glx::get_fb_configs(dpy, screen, nelements) }
    free glXGetVisualFromFBConfig(dpy: *mut Display, config: GLXFBConfig) -> *mut XVisualInfo { glx::get_visual_from_fb_config(dpy, config) }
    free glXCreateWindow(dpy: *mut Display, config: GLXFBConfig, win: XID, attribList: *const c_int) -> GLXDrawable { glx::create_window(dpy, config, win, attribList) }
    free glXDestroyWindow(dpy: *mut Display, win: GLXDrawable) { glx::destroy_window(dpy, win) }
    free glXCreatePixmap(dpy: *mut Display, config: GLXFBConfig, pixmap: XID, attribList: *const c_int) -> GLXDrawable { glx::create_fb_pixmap(dpy, config, pixmap, attribList) }
    free glXDestroyPixmap(dpy: *mut Display, pixmap: GLXDrawable) { glx::destroy_pixmap(dpy, pixmap) }
    free glXCreatePbuffer(dpy: *mut Display, config: GLXFBConfig, attribList: *const c_int) -> GLXDrawable { glx::create_pbuffer(dpy, config, attribList) }
    free glXDestroyPbuffer(dpy: *mut Display, pbuf: GLXDrawable) { glx::destroy_pbuffer(dpy, pbuf) }
    free glXQueryDrawable(dpy: *mut Display, draw: GLXDrawable, attribute: c_int, value: *mut std::ffi::c_uint) { glx::query_drawable(dpy, draw, attribute, value) }
    free glXCreateNewContext(dpy: *mut Display, config: GLXFBConfig, renderType: c_int, shareList: GLXContext, direct: Bool) -> GLXContext { glx::create_new_context(dpy, config, renderType, shareList, direct) }
    free glXMakeContextCurrent(dpy: *mut Display, draw: GLXDrawable, read: GLXDrawable, ctx: GLXContext) -> Bool { glx::make_context_current(dpy, draw, read, ctx) }
    free glXGetCurrentReadDrawable() -> GLXDrawable { glx::get_current_read_drawable() }
    free["GLX_FBCONFIG_ID, GLX_RENDER_TYPE and GLX_SCREEN"] glXQueryContext(dpy: *mut Display, ctx: GLXContext, attribute: c_int, value: *mut c_int) -> c_int { glx::query_context(dpy, ctx, attribute, value) }
    free glXSelectEvent(dpy: *mut Display, draw: GLXDrawable, event_mask: std::ffi::c_ulong) { glx::select_event(dpy, draw, event_mask) }
    free glXGetSelectedEvent(dpy: *mut Display, draw: GLXDrawable, event_mask: *mut std::ffi::c_ulong) { glx::get_selected_event(dpy, draw, event_mask) }
    free glXGetProcAddressARB(procName: *const GLubyte) -> GLproc { proc_from_name(procName as *const c_char) }
    free glXGetProcAddress(procName: *const GLubyte) -> GLproc { proc_from_name(procName as *const c_char) }
    free glXCreateContextAttribsARB(dpy: *mut Display, config: GLXFBConfig, shareContext: GLXContext, direct: Bool, attribList: *const c_int) -> GLXContext { glx::create_context_attribs(dpy, config, shareContext, direct, attribList) }
    free glXSwapIntervalEXT(dpy: *mut Display, drawable: GLXDrawable, interval: c_int) { glx::swap::swap_interval_ext(dpy, drawable, interval) }
    free glXSwapIntervalMESA(interval: std::ffi::c_uint) -> c_int { glx::swap::swap_interval_mesa(interval) }
    free glXGetSwapIntervalMESA() -> c_int { glx::swap::get_swap_interval_mesa() }
    free glXSwapIntervalSGI(interval: c_int) -> c_int { glx::swap::swap_interval_sgi(interval) }
    free glXCopySubBufferMESA(dpy: *mut Display, drawable: GLXDrawable, x: c_int, y: c_int, width: c_int, height: c_int) { glx::swap::copy_sub_buffer(dpy, drawable, x, y, width, height) }

    // ---- softgl_wgl.h ----
    free wglCreateContext(hdc: *mut c_void) -> *mut c_void { crate::winsys::wgl::create_context(hdc) }
    free wglDeleteContext(hglrc: *mut c_void) -> c_int { crate::winsys::wgl::delete_context(hglrc) }
    free wglMakeCurrent(hdc: *mut c_void, hglrc: *mut c_void) -> c_int { crate::winsys::wgl::make_current(hdc, hglrc) }
    free wglGetCurrentContext() -> *mut c_void { crate::winsys::wgl::get_current_context() }
    free wglGetCurrentDC() -> *mut c_void { crate::winsys::wgl::get_current_dc() }
    free wglShareLists(hglrc1: *mut c_void, hglrc2: *mut c_void) -> c_int { crate::winsys::wgl::share_lists(hglrc1, hglrc2) }
    free["copies the groups glPushAttrib saves (see glPushAttrib)"] wglCopyContext(hglrcSrc: *mut c_void, hglrcDst: *mut c_void, mask: u32) -> c_int { crate::winsys::wgl::copy_context(hglrcSrc, hglrcDst, mask) }
    free wglGetProcAddress(lpszProc: *const c_char) -> GLproc { proc_from_name(lpszProc) }
    free wglChoosePixelFormat(hdc: *mut c_void, ppfd: *const crate::winsys::wgl::PixelFormatDescriptor) -> c_int { crate::winsys::wgl::choose_pixel_format(hdc, ppfd) }
    free wglDescribePixelFormat(hdc: *mut c_void, iPixelFormat: c_int, nBytes: u32, ppfd: *mut crate::winsys::wgl::PixelFormatDescriptor) -> c_int { crate::winsys::wgl::describe_pixel_format(hdc, iPixelFormat, nBytes, ppfd) }
    free wglSetPixelFormat(hdc: *mut c_void, iPixelFormat: c_int, ppfd: *const crate::winsys::wgl::PixelFormatDescriptor) -> c_int { crate::winsys::wgl::set_pixel_format(hdc, iPixelFormat, ppfd) }
    free wglGetPixelFormat(hdc: *mut c_void) -> c_int { crate::winsys::wgl::get_pixel_format(hdc) }
    free wglSwapBuffers(hdc: *mut c_void) -> c_int { crate::winsys::wgl::swap_buffers(hdc) }
    free["built-in misc-fixed bitmap fonts chosen by height and weight (docs/fonts.md), not the DC's GDI font"] wglUseFontBitmapsA(hdc: *mut c_void, first: u32, count: u32, listBase: u32) -> c_int { crate::winsys::wgl::use_font_bitmaps(hdc, first, count, listBase, false) }
    free["as wglUseFontBitmapsA; code points beyond ASCII, Latin-1, Cyrillic and code pages 1251/1252 draw U+FFFD"] wglUseFontBitmapsW(hdc: *mut c_void, first: u32, count: u32, listBase: u32) -> c_int { crate::winsys::wgl::use_font_bitmaps(hdc, first, count, listBase, true) }
    free["outlines are the exact pixel boundaries of the built-in bitmap fonts (winsys/font_outlines.rs), not TrueType curves; deviation is ignored"] wglUseFontOutlinesA(hdc: *mut c_void, first: u32, count: u32, listBase: u32, deviation: f32, extrusion: f32, format: c_int, lpgmf: *mut c_void) -> c_int { { let _ = deviation; crate::winsys::wgl::use_font_outlines(hdc, first, count, listBase, extrusion, format, lpgmf, false) } }
    free["as wglUseFontOutlinesA"] wglUseFontOutlinesW(hdc: *mut c_void, first: u32, count: u32, listBase: u32, deviation: f32, extrusion: f32, format: c_int, lpgmf: *mut c_void) -> c_int { { let _ = deviation; crate::winsys::wgl::use_font_outlines(hdc, first, count, listBase, extrusion, format, lpgmf, true) } }
    free softglCreateDC(width: c_int, height: c_int) -> *mut c_void { crate::winsys::wgl::create_dc(width, height) }
    free softglDestroyDC(hdc: *mut c_void) -> c_int { crate::winsys::wgl::destroy_dc(hdc) }
    free softglResizeDC(hdc: *mut c_void, width: c_int, height: c_int) -> c_int { crate::winsys::wgl::resize_dc(hdc, width, height) }
    free softglSelectFont(hdc: *mut c_void, height: c_int, weight: c_int, charset: c_int) -> c_int { crate::winsys::wgl::select_font(hdc, height, weight, charset) }
    free softglGetDCImage(hdc: *mut c_void, width: *mut c_int, height: *mut c_int) -> *const GLubyte { crate::winsys::wgl::dc_image(hdc, width, height) }
}
