//! The mipmap builders (GLU 1.3 section 3.2): gluBuild1DMipmaps,
//! gluBuild2DMipmaps, gluBuild3DMipmaps and the *MipmapLevels forms.
//!
//! gluBuildNDMipmaps: each dimension that is not a power of two is rescaled
//! to the nearest power of two in GLU's sense (the largest power of two `p`
//! at most `n`, or `2p` when `n >= 1.5 p`: 3 -> 4, 5 -> 4, 6 -> 8), with the
//! box filter of [`crate::glu::scale`]. The size is then checked with a proxy
//! texture (GL_PROXY_TEXTURE_1D/2D/3D/CUBE_MAP at level 0, answered by
//! `glGetTexLevelParameteriv(GL_TEXTURE_WIDTH)`): while the proxy says 0,
//! every dimension above 1 is halved. When GL does not answer the proxy
//! query at all (texturing not implemented), the size is taken as it is.
//! Levels 0 to log2(max dimension) follow, each from the one before it (as
//! stored, in the caller's format and type) by box filtering 2x2 (2x2x2 in
//! 3D; a dimension already 1 stays 1 and is not averaged).
//!
//! gluBuildNDMipmapLevels(..., level, base, max, data): no rescaling; `data`
//! is mipmap level `level`; levels are made down to 1x1 as above and those
//! from `base` to `max` are loaded. An odd dimension halves to floor(n/2)
//! with the area-weighted box filter.
//!
//! Level images go to glTexImage1D/2D/3D in the caller's format and type,
//! tightly packed: the unpack modes are set to alignment 1 and no skips
//! around the calls and restored afterwards, as GLU does. The caller's data
//! is read with the current unpack modes.
//!
//! Errors (returned, as GLU does): GLU_INVALID_ENUM for an unknown target,
//! format or type, GL_STENCIL_INDEX, or GL_BITMAP with a non-index format;
//! GLU_INVALID_OPERATION for a packed type the format does not match;
//! GLU_INVALID_VALUE for a dimension below 1, NULL data, or (levels forms)
//! `level > base`, `base < 0`, `max < base` or `max` beyond the last level.

use crate::api::table as gl;
use crate::api::types::*;
use crate::gl::enums::*;
use crate::glu::scale::{check_format_type, resample, Layout, PixelGl, PixelStore};
use crate::glu::strings::{GLU_INVALID_ENUM, GLU_INVALID_VALUE, GLU_OUT_OF_MEMORY};
use std::ffi::c_void;

pub const GL_PROXY_TEXTURE_1D: GLenum = 0x8063;
pub const GL_PROXY_TEXTURE_2D: GLenum = 0x8064;
pub const GL_PROXY_TEXTURE_3D: GLenum = 0x8070;
pub const GL_TEXTURE_CUBE_MAP_POSITIVE_X: GLenum = 0x8515;
pub const GL_TEXTURE_CUBE_MAP_NEGATIVE_Z: GLenum = 0x851A;
pub const GL_PROXY_TEXTURE_CUBE_MAP: GLenum = 0x851B;
pub const GL_TEXTURE_WIDTH: GLenum = 0x1000;

/// What the mipmap builders need from GL.
pub trait TexGl: PixelGl {
    fn pixel_store(&mut self, pname: GLenum, value: i32);
    /// glTexImage1D/2D/3D (`dims`) of a tightly packed image.
    #[allow(clippy::too_many_arguments)]
    fn tex_image(&mut self, dims: usize, target: GLenum, level: i32, internal: i32, size: [i32; 3], format: GLenum, type_: GLenum, data: &[u8]);
    /// A proxy texture of `size` at level 0: the width GL then reports, or
    /// None when GL does not answer.
    fn proxy_width(&mut self, dims: usize, proxy: GLenum, internal: i32, size: [i32; 3], format: GLenum, type_: GLenum) -> Option<i32>;
}

/// The public GL entry points.
pub struct GlTex;

impl PixelGl for GlTex {
    fn get_integer(&mut self, pname: GLenum) -> Option<i32> {
        crate::glu::scale::get_integer(pname)
    }
}

#[allow(clippy::too_many_arguments)]
unsafe fn tex_image_n(dims: usize, target: GLenum, level: i32, internal: i32, s: [i32; 3], format: GLenum, type_: GLenum, p: *const c_void) {
    match dims {
        1 => gl::glTexImage1D(target, level, internal, s[0], 0, format, type_, p),
        2 => gl::glTexImage2D(target, level, internal, s[0], s[1], 0, format, type_, p),
        _ => gl::glTexImage3D(target, level, internal, s[0], s[1], s[2], 0, format, type_, p),
    }
}

impl TexGl for GlTex {
    fn pixel_store(&mut self, pname: GLenum, value: i32) {
        unsafe { gl::glPixelStorei(pname, value) }
    }
    fn tex_image(&mut self, dims: usize, target: GLenum, level: i32, internal: i32, size: [i32; 3], format: GLenum, type_: GLenum, data: &[u8]) {
        unsafe { tex_image_n(dims, target, level, internal, size, format, type_, data.as_ptr() as *const c_void) }
    }
    fn proxy_width(&mut self, dims: usize, proxy: GLenum, internal: i32, size: [i32; 3], format: GLenum, type_: GLenum) -> Option<i32> {
        let mut w = i32::MIN;
        unsafe {
            tex_image_n(dims, proxy, 0, internal, size, format, type_, std::ptr::null());
            gl::glGetTexLevelParameteriv(proxy, 0, GL_TEXTURE_WIDTH, &mut w);
        }
        (w != i32::MIN).then_some(w)
    }
}

/// GLU's nearest power of two: `p` (the largest power of two <= n), or `2p`
/// when n >= 1.5 p.
pub fn nearest_power(n: usize) -> usize {
    let n = n.max(1);
    let p = 1usize << (usize::BITS - 1 - n.leading_zeros());
    if p > 1 && n - p >= p / 2 { 2 * p } else { p }
}

/// floor(log2(n)) for n >= 1.
fn log2(n: usize) -> i32 {
    (usize::BITS - 1 - n.max(1).leading_zeros()) as i32
}

/// The proxy target of a texture target for `dims`, None if the target is
/// not one of that dimension's.
fn proxy_of(dims: usize, target: GLenum) -> Option<GLenum> {
    match (dims, target) {
        (1, GL_TEXTURE_1D) => Some(GL_PROXY_TEXTURE_1D),
        (2, GL_TEXTURE_2D) => Some(GL_PROXY_TEXTURE_2D),
        (2, GL_TEXTURE_CUBE_MAP_POSITIVE_X..=GL_TEXTURE_CUBE_MAP_NEGATIVE_Z) => Some(GL_PROXY_TEXTURE_CUBE_MAP),
        (3, GL_TEXTURE_3D) => Some(GL_PROXY_TEXTURE_3D),
        _ => None,
    }
}

/// A build request, checked.
struct Build {
    dims: usize,
    target: GLenum,
    proxy: GLenum,
    internal: i32,
    format: GLenum,
    type_: GLenum,
    size: [usize; 3],
}

fn check(dims: usize, target: GLenum, internal: i32, size: [i32; 3], format: GLenum, type_: GLenum, data: *const c_void) -> Result<Build, GLenum> {
    let proxy = proxy_of(dims, target).ok_or(GLU_INVALID_ENUM)?;
    check_format_type(format, type_)?;
    if format == GL_STENCIL_INDEX {
        return Err(GLU_INVALID_ENUM);
    }
    if size[..dims].iter().any(|&s| s < 1) {
        return Err(GLU_INVALID_VALUE);
    }
    if data.is_null() {
        return Err(GLU_INVALID_VALUE);
    }
    let size = size.map(|s| s.max(1) as usize);
    if size[0].checked_mul(size[1]).and_then(|n| n.checked_mul(size[2])).and_then(|n| n.checked_mul(64)).is_none_or(|n| n > isize::MAX as usize) {
        return Err(GLU_OUT_OF_MEMORY);
    }
    Ok(Build { dims, target, proxy, internal, format, type_, size })
}

const UNPACK_NAMES: [GLenum; 8] =
    [GL_UNPACK_SWAP_BYTES, GL_UNPACK_LSB_FIRST, GL_UNPACK_ROW_LENGTH, GL_UNPACK_SKIP_ROWS, GL_UNPACK_SKIP_PIXELS, GL_UNPACK_ALIGNMENT, GL_UNPACK_IMAGE_HEIGHT, GL_UNPACK_SKIP_IMAGES];

fn store_values(s: &PixelStore) -> [i32; 8] {
    [s.swap_bytes as i32, s.lsb_first as i32, s.row_length, s.skip_rows, s.skip_pixels, s.alignment, s.image_height, s.skip_images]
}

impl Build {
    fn kind(&self) -> crate::glu::scale::TypeKind {
        check_format_type(self.format, self.type_).map(|k| k.1).unwrap_or(crate::glu::scale::TypeKind::Bitmap)
    }

    /// The caller's image as f64 components.
    unsafe fn read(&self, gl: &mut dyn TexGl, data: *const c_void) -> Vec<f64> {
        let mut store = PixelStore::query(gl, false);
        if self.dims < 3 {
            store.image_height = 0;
            store.skip_images = 0;
        }
        let l = Layout::new(self.format, self.kind(), store, self.size[0], self.size[1], self.size[2]);
        l.unpack(std::slice::from_raw_parts(data as *const u8, l.extent()))
    }

    /// Loads levels `first..` from `vals` (of `size`) down to 1x1, those in
    /// `base..=max` through glTexImage.
    fn levels(&self, gl: &mut dyn TexGl, mut vals: Vec<f64>, mut size: [usize; 3], first: i32, base: i32, max: i32) {
        let saved = PixelStore::query(gl, false);
        let tight = PixelStore::tight();
        let (old, new) = (store_values(&saved), store_values(&tight));
        for i in 0..8 {
            if old[i] != new[i] {
                gl.pixel_store(UNPACK_NAMES[i], new[i]);
            }
        }
        let kind = self.kind();
        let mut level = first;
        loop {
            let l = Layout::new(self.format, kind, tight, size[0], size[1], size[2]);
            let mut bytes = vec![0u8; l.extent()];
            l.pack(&vals, &mut bytes);
            if level >= base && level <= max {
                let s = size.map(|v| v as i32);
                gl.tex_image(self.dims, self.target, level, self.internal, s, self.format, self.type_, &bytes);
            }
            if size.iter().all(|&v| v == 1) || level >= max {
                break;
            }
            // The next level from this one as stored.
            let stored = l.unpack(&bytes);
            let next = size.map(|v| (v / 2).max(1));
            vals = resample(&stored, size, l.comps, next);
            size = next;
            level += 1;
        }
        for i in 0..8 {
            if old[i] != new[i] {
                gl.pixel_store(UNPACK_NAMES[i], old[i]);
            }
        }
    }
}

/// gluBuild1D/2D/3DMipmaps (`dims`); `size` holds 1 past `dims`.
///
/// # Safety
/// `data` must hold the image the unpack modes describe.
#[allow(clippy::too_many_arguments)]
pub unsafe fn build_mipmaps(gl: &mut dyn TexGl, dims: usize, target: GLenum, internal: i32, size: [i32; 3], format: GLenum, type_: GLenum, data: *const c_void) -> GLint {
    let b = match check(dims, target, internal, size, format, type_, data) {
        Ok(b) => b,
        Err(e) => return e as GLint,
    };
    let mut fit = [0, 1, 2].map(|i| if i < dims { nearest_power(b.size[i]) } else { 1 });
    loop {
        let s = fit.map(|v| v as i32);
        match gl.proxy_width(dims, b.proxy, internal, s, format, type_) {
            Some(0) if fit.iter().any(|&v| v > 1) => fit = fit.map(|v| (v / 2).max(1)),
            _ => break,
        }
    }
    let vals = b.read(gl, data);
    let comps = crate::glu::scale::format_components(format).unwrap_or(1);
    let vals = if fit == b.size { vals } else { resample(&vals, b.size, comps, fit) };
    let max = log2(*fit.iter().max().unwrap_or(&1));
    b.levels(gl, vals, fit, 0, 0, max);
    0
}

/// gluBuild1D/2D/3DMipmapLevels.
///
/// # Safety
/// As [`build_mipmaps`].
#[allow(clippy::too_many_arguments)]
pub unsafe fn build_mipmap_levels(
    gl: &mut dyn TexGl,
    dims: usize,
    target: GLenum,
    internal: i32,
    size: [i32; 3],
    format: GLenum,
    type_: GLenum,
    level: i32,
    base: i32,
    max: i32,
    data: *const c_void,
) -> GLint {
    let b = match check(dims, target, internal, size, format, type_, data) {
        Ok(b) => b,
        Err(e) => return e as GLint,
    };
    let last = level.saturating_add(log2(*b.size.iter().max().unwrap_or(&1)));
    if level > base || base < 0 || max < base || max > last {
        return GLU_INVALID_VALUE as GLint;
    }
    let vals = b.read(gl, data);
    b.levels(gl, vals, b.size, level, base, max);
    0
}
