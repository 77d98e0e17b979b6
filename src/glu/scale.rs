//! gluScaleImage (GLU 1.3 section 3.1) and the pixel machinery the mipmap
//! builders share with it: the formats and types of GL 1.2 pixel
//! rectangles (the packed types too), the pack/unpack pixel-store modes as
//! GL 1.5 section 3.6.4 (unpack) and 4.3.2 (pack) lay images out in memory,
//! and a box filter.
//!
//! Conversions. Images are unpacked to f64 components:
//! - colour and depth formats are normalized as GL converts integers
//!   (GL 1.5 table 2.9): unsigned `c / (2^b - 1)`, signed
//!   `(2c + 1) / (2^b - 1)`, packed fields `c / (2^b - 1)`, floats as is;
//!   packing inverts the same formula and rounds to nearest (a signed tie
//!   to even, so 0.0 packs as 0, as glReadPixels does), after clamping
//!   to [0, 1] (unsigned) or [-1, 1] (signed); floats are stored unclamped.
//!   So a same-type scale averages the raw integers and rounds.
//! - GL_COLOR_INDEX and GL_STENCIL_INDEX keep the raw integer values;
//!   packing rounds and masks to the destination's bits (GL 1.5 section
//!   4.3.2); GL_BITMAP holds indices 0 and 1.
//!
//! The filter (the gluScaleImage man page): each output pixel is the
//! area-weighted average of the input pixels under its footprint. Along an
//! axis shrinking from n to m, output pixel o covers `[o n/m, (o+1) n/m)` of
//! the input (a box filter); along an axis magnifying (m > n) it covers the
//! unit box around its centre mapped to the input, `(o + 1/2) n/m -+ 1/2`,
//! which is linear interpolation between the two nearest input pixels. A
//! footprint is clipped to the image (clamp to edge), so the first and last
//! output pixels of a magnification repeat the edge pixels. The filter is
//! separable and applied axis by axis on f64 values, rounding once at the
//! end.
//!
//! Pixel-store modes are queried through [`PixelGl`] (`glGetIntegerv`, as
//! GLU does; the defaults when no context answers).

use crate::api::table as gl;
use crate::api::types::*;
use crate::gl::enums::*;
use crate::glu::strings::{GLU_INVALID_ENUM, GLU_INVALID_OPERATION, GLU_INVALID_VALUE, GLU_OUT_OF_MEMORY};
use std::ffi::c_void;

pub const GL_BITMAP: GLenum = 0x1A00;
pub const GL_UNSIGNED_BYTE_3_3_2: GLenum = 0x8032;
pub const GL_UNSIGNED_SHORT_4_4_4_4: GLenum = 0x8033;
pub const GL_UNSIGNED_SHORT_5_5_5_1: GLenum = 0x8034;
pub const GL_UNSIGNED_INT_8_8_8_8: GLenum = 0x8035;
pub const GL_UNSIGNED_INT_10_10_10_2: GLenum = 0x8036;
pub const GL_UNSIGNED_BYTE_2_3_3_REV: GLenum = 0x8362;
pub const GL_UNSIGNED_SHORT_5_6_5_REV: GLenum = 0x8364;
pub const GL_UNSIGNED_SHORT_4_4_4_4_REV: GLenum = 0x8365;
pub const GL_UNSIGNED_SHORT_1_5_5_5_REV: GLenum = 0x8366;
pub const GL_UNSIGNED_INT_8_8_8_8_REV: GLenum = 0x8367;
pub const GL_UNSIGNED_INT_2_10_10_10_REV: GLenum = 0x8368;

/// What GLU needs from GL for images: pixel-store queries (and, for the
/// mipmap builders, see [`crate::glu::mipmap::TexGl`]).
pub trait PixelGl {
    /// `glGetIntegerv(pname)`; None when GL does not answer.
    fn get_integer(&mut self, pname: GLenum) -> Option<i32>;
}

/// The public GL entry points.
pub struct GlPixels;

impl PixelGl for GlPixels {
    fn get_integer(&mut self, pname: GLenum) -> Option<i32> {
        get_integer(pname)
    }
}

/// `glGetIntegerv` through the public entry point; None when nothing was
/// written (no current context, or a name GL does not answer).
pub fn get_integer(pname: GLenum) -> Option<i32> {
    let mut v = [i32::MIN; 16];
    unsafe { gl::glGetIntegerv(pname, v.as_mut_ptr()) };
    (v[0] != i32::MIN).then_some(v[0])
}

/// One direction's pixel-store modes (GL 1.5 table 3.1 / 4.5).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct PixelStore {
    pub swap_bytes: bool,
    pub lsb_first: bool,
    pub row_length: i32,
    pub skip_rows: i32,
    pub skip_pixels: i32,
    pub alignment: i32,
    pub image_height: i32,
    pub skip_images: i32,
}

impl Default for PixelStore {
    fn default() -> Self {
        PixelStore { swap_bytes: false, lsb_first: false, row_length: 0, skip_rows: 0, skip_pixels: 0, alignment: 4, image_height: 0, skip_images: 0 }
    }
}

impl PixelStore {
    /// Tightly packed: alignment 1, nothing skipped.
    pub fn tight() -> Self {
        PixelStore { alignment: 1, ..Default::default() }
    }

    /// The unpack (`pack == false`) or pack modes, as GL reports them.
    pub fn query(gl: &mut dyn PixelGl, pack: bool) -> Self {
        let d = PixelStore::default();
        let names = if pack {
            [GL_PACK_SWAP_BYTES, GL_PACK_LSB_FIRST, GL_PACK_ROW_LENGTH, GL_PACK_SKIP_ROWS, GL_PACK_SKIP_PIXELS, GL_PACK_ALIGNMENT, GL_PACK_IMAGE_HEIGHT, GL_PACK_SKIP_IMAGES]
        } else {
            [GL_UNPACK_SWAP_BYTES, GL_UNPACK_LSB_FIRST, GL_UNPACK_ROW_LENGTH, GL_UNPACK_SKIP_ROWS, GL_UNPACK_SKIP_PIXELS, GL_UNPACK_ALIGNMENT, GL_UNPACK_IMAGE_HEIGHT, GL_UNPACK_SKIP_IMAGES]
        };
        let mut q = |i: usize, dflt: i32| gl.get_integer(names[i]).unwrap_or(dflt);
        let s = PixelStore {
            swap_bytes: q(0, 0) != 0,
            lsb_first: q(1, 0) != 0,
            row_length: q(2, 0).max(0),
            skip_rows: q(3, 0).max(0),
            skip_pixels: q(4, 0).max(0),
            alignment: q(5, d.alignment),
            image_height: q(6, 0).max(0),
            skip_images: q(7, 0).max(0),
        };
        let alignment = if matches!(s.alignment, 1 | 2 | 4 | 8) { s.alignment } else { d.alignment };
        PixelStore { alignment, ..s }
    }
}

/// How a type stores a pixel's components.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum TypeKind {
    /// One bit per index (GL_BITMAP).
    Bitmap,
    /// One element of `size` bytes per component.
    Plain { size: usize, signed: bool, float: bool },
    /// One element of `size` bytes per pixel, fields of `bits` in component
    /// order, the first component in the most significant bits, or in the
    /// least significant for the _REV types.
    Packed { size: usize, bits: [u32; 4], n: usize, rev: bool },
}

pub fn type_kind(t: GLenum) -> Option<TypeKind> {
    use TypeKind::*;
    let packed = |size, name: &[u32], rev: bool| {
        let n = name.len();
        let mut bits = [0; 4];
        for k in 0..n {
            bits[k] = if rev { name[n - 1 - k] } else { name[k] };
        }
        Packed { size, bits, n, rev }
    };
    Some(match t {
        GL_BITMAP => Bitmap,
        GL_UNSIGNED_BYTE => Plain { size: 1, signed: false, float: false },
        GL_BYTE => Plain { size: 1, signed: true, float: false },
        GL_UNSIGNED_SHORT => Plain { size: 2, signed: false, float: false },
        GL_SHORT => Plain { size: 2, signed: true, float: false },
        GL_UNSIGNED_INT => Plain { size: 4, signed: false, float: false },
        GL_INT => Plain { size: 4, signed: true, float: false },
        GL_FLOAT => Plain { size: 4, signed: true, float: true },
        GL_UNSIGNED_BYTE_3_3_2 => packed(1, &[3, 3, 2], false),
        GL_UNSIGNED_BYTE_2_3_3_REV => packed(1, &[2, 3, 3], true),
        GL_UNSIGNED_SHORT_5_6_5 => packed(2, &[5, 6, 5], false),
        GL_UNSIGNED_SHORT_5_6_5_REV => packed(2, &[5, 6, 5], true),
        GL_UNSIGNED_SHORT_4_4_4_4 => packed(2, &[4, 4, 4, 4], false),
        GL_UNSIGNED_SHORT_4_4_4_4_REV => packed(2, &[4, 4, 4, 4], true),
        GL_UNSIGNED_SHORT_5_5_5_1 => packed(2, &[5, 5, 5, 1], false),
        GL_UNSIGNED_SHORT_1_5_5_5_REV => packed(2, &[1, 5, 5, 5], true),
        GL_UNSIGNED_INT_8_8_8_8 => packed(4, &[8, 8, 8, 8], false),
        GL_UNSIGNED_INT_8_8_8_8_REV => packed(4, &[8, 8, 8, 8], true),
        GL_UNSIGNED_INT_10_10_10_2 => packed(4, &[10, 10, 10, 2], false),
        GL_UNSIGNED_INT_2_10_10_10_REV => packed(4, &[2, 10, 10, 10], true),
        _ => return None,
    })
}

/// Components per pixel of a format (GL 1.5 table 3.6), None if unknown.
pub fn format_components(f: GLenum) -> Option<usize> {
    Some(match f {
        GL_COLOR_INDEX | GL_STENCIL_INDEX | GL_DEPTH_COMPONENT | GL_RED | GL_GREEN | GL_BLUE | GL_ALPHA | GL_LUMINANCE => 1,
        GL_LUMINANCE_ALPHA => 2,
        GL_RGB | GL_BGR => 3,
        GL_RGBA | GL_BGRA => 4,
        _ => return None,
    })
}

fn is_index(f: GLenum) -> bool {
    matches!(f, GL_COLOR_INDEX | GL_STENCIL_INDEX)
}

/// GLU's argument check for a format and type: GLU_INVALID_ENUM for an
/// unknown one or GL_BITMAP with a non-index format, GLU_INVALID_OPERATION
/// for a packed type whose component count the format does not have
/// (3_3_2 and 5_6_5 need GL_RGB; the four-field types GL_RGBA or GL_BGRA).
pub fn check_format_type(format: GLenum, type_: GLenum) -> Result<(usize, TypeKind), GLenum> {
    let (Some(n), Some(k)) = (format_components(format), type_kind(type_)) else {
        return Err(GLU_INVALID_ENUM);
    };
    match k {
        TypeKind::Bitmap if !is_index(format) => Err(GLU_INVALID_ENUM),
        TypeKind::Packed { n: 3, .. } if format != GL_RGB => Err(GLU_INVALID_OPERATION),
        TypeKind::Packed { n: 4, .. } if format != GL_RGBA && format != GL_BGRA => Err(GLU_INVALID_OPERATION),
        _ => Ok((n, k)),
    }
}

/// Where each pixel of a `w x h x d` image lives in memory.
#[derive(Clone, Copy, Debug)]
pub struct Layout {
    pub comps: usize,
    pub kind: TypeKind,
    pub index: bool,
    pub store: PixelStore,
    pub w: usize,
    pub h: usize,
    pub d: usize,
    /// Bytes from one row / image to the next.
    pub row_stride: usize,
    pub image_stride: usize,
}

impl Layout {
    pub fn new(format: GLenum, kind: TypeKind, store: PixelStore, w: usize, h: usize, d: usize) -> Self {
        let comps = format_components(format).unwrap_or(1);
        let a = store.alignment.max(1) as usize;
        let l = if store.row_length > 0 { store.row_length as usize } else { w };
        let row_stride = match kind {
            TypeKind::Bitmap => a * l.div_ceil(8 * a),
            _ => {
                let (s, n) = Self::elem(kind, comps);
                let bytes = s * n * l;
                if s >= a { bytes } else { a * bytes.div_ceil(a) }
            }
        };
        let rows = if store.image_height > 0 { store.image_height as usize } else { h };
        Layout { comps, kind, index: is_index(format), store, w, h, d, row_stride, image_stride: row_stride * rows }
    }

    /// Element size in bytes and elements per pixel.
    fn elem(kind: TypeKind, comps: usize) -> (usize, usize) {
        match kind {
            TypeKind::Bitmap => (1, 1),
            TypeKind::Plain { size, .. } => (size, comps),
            TypeKind::Packed { size, .. } => (size, 1),
        }
    }

    /// Byte offset of pixel (x, y, z) (for GL_BITMAP: of its byte, with the
    /// bit index).
    fn offset(&self, x: usize, y: usize, z: usize) -> (usize, u32) {
        let s = &self.store;
        let base = (z + s.skip_images as usize) * self.image_stride + (y + s.skip_rows as usize) * self.row_stride;
        match self.kind {
            TypeKind::Bitmap => {
                let bit = s.skip_pixels as usize + x;
                let b = (bit % 8) as u32;
                (base + bit / 8, if s.lsb_first { b } else { 7 - b })
            }
            k => {
                let (sz, n) = Self::elem(k, self.comps);
                (base + (x + s.skip_pixels as usize) * sz * n, 0)
            }
        }
    }

    /// Bytes the image spans from its start pointer (the last pixel's end).
    pub fn extent(&self) -> usize {
        if self.w == 0 || self.h == 0 || self.d == 0 {
            return 0;
        }
        let (off, _) = self.offset(self.w - 1, self.h - 1, self.d - 1);
        match self.kind {
            TypeKind::Bitmap => off + 1,
            k => {
                let (sz, n) = Self::elem(k, self.comps);
                off + sz * n
            }
        }
    }

    fn read_elem(&self, bytes: &[u8], off: usize, size: usize) -> [u8; 4] {
        let mut e = [0u8; 4];
        e[..size].copy_from_slice(&bytes[off..off + size]);
        if self.store.swap_bytes {
            e[..size].reverse();
        }
        e
    }

    fn write_elem(&self, bytes: &mut [u8], off: usize, size: usize, mut e: [u8; 4]) {
        if self.store.swap_bytes {
            e[..size].reverse();
        }
        bytes[off..off + size].copy_from_slice(&e[..size]);
    }

    /// The image as f64 components, `((z h + y) w + x) comps + c`.
    pub fn unpack(&self, bytes: &[u8]) -> Vec<f64> {
        let mut out = Vec::with_capacity(self.w * self.h * self.d * self.comps);
        for z in 0..self.d {
            for y in 0..self.h {
                for x in 0..self.w {
                    let (off, bit) = self.offset(x, y, z);
                    match self.kind {
                        TypeKind::Bitmap => out.push(((bytes[off] >> bit) & 1) as f64),
                        TypeKind::Plain { size, signed, float } => {
                            for c in 0..self.comps {
                                let e = self.read_elem(bytes, off + c * size, size);
                                out.push(decode_plain(e, size, signed, float, self.index));
                            }
                        }
                        TypeKind::Packed { size, bits, n, rev } => {
                            let e = self.read_elem(bytes, off, size);
                            let v = packed_value(e, size);
                            for c in 0..n {
                                let (shift, b) = field(bits, rev, size, c);
                                let f = (v >> shift) & mask_bits(b);
                                out.push(if self.index { f as f64 } else { f as f64 / mask_bits(b) as f64 });
                            }
                        }
                    }
                }
            }
        }
        out
    }

    /// Stores f64 components (as [`Layout::unpack`] returns them) into `bytes`,
    /// leaving bytes between pixels alone.
    pub fn pack(&self, vals: &[f64], bytes: &mut [u8]) {
        let mut i = 0;
        for z in 0..self.d {
            for y in 0..self.h {
                for x in 0..self.w {
                    let (off, bit) = self.offset(x, y, z);
                    match self.kind {
                        TypeKind::Bitmap => {
                            let on = (vals[i].round() as i64) & 1 != 0;
                            i += 1;
                            if on {
                                bytes[off] |= 1 << bit;
                            } else {
                                bytes[off] &= !(1 << bit);
                            }
                        }
                        TypeKind::Plain { size, signed, float } => {
                            for c in 0..self.comps {
                                let e = encode_plain(vals[i], size, signed, float, self.index);
                                i += 1;
                                self.write_elem(bytes, off + c * size, size, e);
                            }
                        }
                        TypeKind::Packed { size, bits, n, rev } => {
                            let mut v: u64 = 0;
                            for c in 0..n {
                                let (shift, b) = field(bits, rev, size, c);
                                let m = mask_bits(b);
                                let f = if self.index {
                                    (vals[i].round() as i64 as u64) & m
                                } else {
                                    (vals[i].clamp(0.0, 1.0) * m as f64).round() as u64
                                };
                                i += 1;
                                v |= f << shift;
                            }
                            let e = match size {
                                1 => [v as u8, 0, 0, 0],
                                2 => {
                                    let b = (v as u16).to_ne_bytes();
                                    [b[0], b[1], 0, 0]
                                }
                                _ => (v as u32).to_ne_bytes(),
                            };
                            self.write_elem(bytes, off, size, e);
                        }
                    }
                }
            }
        }
    }
}

fn mask_bits(b: u32) -> u64 {
    (1u64 << b) - 1
}

/// Shift and width of packed component `c`.
fn field(bits: [u32; 4], rev: bool, size: usize, c: usize) -> (u32, u32) {
    let before: u32 = bits[..c].iter().sum();
    if rev {
        (before, bits[c])
    } else {
        (8 * size as u32 - before - bits[c], bits[c])
    }
}

/// A packed element's value.
fn packed_value(e: [u8; 4], size: usize) -> u64 {
    match size {
        1 => e[0] as u64,
        2 => u16::from_ne_bytes([e[0], e[1]]) as u64,
        _ => u32::from_ne_bytes(e) as u64,
    }
}

fn decode_plain(e: [u8; 4], size: usize, signed: bool, float: bool, index: bool) -> f64 {
    if float {
        return f32::from_ne_bytes(e) as f64;
    }
    let (c, bits): (f64, u32) = match (size, signed) {
        (1, false) => (e[0] as f64, 8),
        (1, true) => (e[0] as i8 as f64, 8),
        (2, false) => (u16::from_ne_bytes([e[0], e[1]]) as f64, 16),
        (2, true) => (i16::from_ne_bytes([e[0], e[1]]) as f64, 16),
        (_, false) => (u32::from_ne_bytes(e) as f64, 32),
        (_, true) => (i32::from_ne_bytes(e) as f64, 32),
    };
    if index {
        return c;
    }
    let m = mask_bits(bits) as f64;
    if signed { (2.0 * c + 1.0) / m } else { c / m }
}

fn encode_plain(v: f64, size: usize, signed: bool, float: bool, index: bool) -> [u8; 4] {
    if float {
        return (v as f32).to_ne_bytes();
    }
    let bits = 8 * size as u32;
    let m = mask_bits(bits) as f64;
    let raw: i64 = if index {
        // Indices are masked to the destination's bits.
        let r = if v.is_finite() { v.round() as i64 } else { 0 };
        r & mask_bits(bits) as i64
    } else if signed {
        let v = if v.is_nan() { 0.0 } else { v.clamp(-1.0, 1.0) };
        // Ties to even, as glReadPixels packs (gl/pixel_data.rs): 0.0's
        // exact value is -1/2, which must give 0, not -1.
        ((m * v - 1.0) / 2.0).round_ties_even().clamp(-(m + 1.0) / 2.0, (m - 1.0) / 2.0) as i64
    } else {
        let v = if v.is_nan() { 0.0 } else { v.clamp(0.0, 1.0) };
        (v * m).round() as i64
    };
    match size {
        1 => [raw as u8, 0, 0, 0],
        2 => {
            let b = (raw as u16).to_ne_bytes();
            [b[0], b[1], 0, 0]
        }
        _ => (raw as u32).to_ne_bytes(),
    }
}

/// The box filter's weights along one axis: for each output pixel, the
/// input pixels under its footprint and their normalized weights.
pub fn axis_weights(n: usize, m: usize) -> Vec<Vec<(usize, f64)>> {
    let conv = n as f64 / m as f64;
    (0..m)
        .map(|o| {
            let (lo, hi) = if m < n {
                (o as f64 * conv, (o + 1) as f64 * conv)
            } else {
                let c = (o as f64 + 0.5) * conv;
                (c - 0.5, c + 0.5)
            };
            let (lo, hi) = (lo.max(0.0), hi.min(n as f64));
            let first = lo.floor() as usize;
            let last = (hi.ceil() as usize).min(n).max(first + 1);
            let mut ws: Vec<(usize, f64)> = (first..last)
                .map(|i| (i, (hi.min(i as f64 + 1.0) - lo.max(i as f64)).max(0.0)))
                .filter(|&(_, w)| w > 0.0)
                .collect();
            let total: f64 = ws.iter().map(|w| w.1).sum();
            if total > 0.0 {
                ws.iter_mut().for_each(|w| w.1 /= total);
            } else {
                ws = vec![(first.min(n - 1), 1.0)];
            }
            ws
        })
        .collect()
}

/// Box-filters an image of `dims` (w, h, d) with `comps` components to
/// `to`, axis by axis.
pub fn resample(src: &[f64], dims: [usize; 3], comps: usize, to: [usize; 3]) -> Vec<f64> {
    let mut cur = src.to_vec();
    let mut d = dims;
    for axis in 0..3 {
        if d[axis] == to[axis] {
            continue;
        }
        let ws = axis_weights(d[axis], to[axis]);
        let mut nd = d;
        nd[axis] = to[axis];
        let mut out = vec![0.0; nd[0] * nd[1] * nd[2] * comps];
        for z in 0..nd[2] {
            for y in 0..nd[1] {
                for x in 0..nd[0] {
                    let o = ((z * nd[1] + y) * nd[0] + x) * comps;
                    let p = [x, y, z];
                    for &(i, w) in &ws[p[axis]] {
                        let mut q = p;
                        q[axis] = i;
                        let s = ((q[2] * d[1] + q[1]) * d[0] + q[0]) * comps;
                        for c in 0..comps {
                            out[o + c] += w * cur[s + c];
                        }
                    }
                }
            }
        }
        cur = out;
        d = nd;
    }
    cur
}

/// gluScaleImage: returns 0 or a GLU error code.
///
/// # Safety
/// `data_in` / `data_out` must hold the images the pixel-store modes
/// describe (NULL gives GLU_INVALID_VALUE).
#[allow(clippy::too_many_arguments)]
pub unsafe fn scale_image(
    gl: &mut dyn PixelGl,
    format: GLenum,
    w_in: GLsizei,
    h_in: GLsizei,
    type_in: GLenum,
    data_in: *const c_void,
    w_out: GLsizei,
    h_out: GLsizei,
    type_out: GLenum,
    data_out: *mut c_void,
) -> GLint {
    if w_in < 0 || h_in < 0 || w_out < 0 || h_out < 0 {
        return GLU_INVALID_VALUE as GLint;
    }
    let kin = match check_format_type(format, type_in) {
        Ok((_, k)) => k,
        Err(e) => return e as GLint,
    };
    let kout = match check_format_type(format, type_out) {
        Ok((_, k)) => k,
        Err(e) => return e as GLint,
    };
    if w_in == 0 || h_in == 0 || w_out == 0 || h_out == 0 {
        return 0;
    }
    if data_in.is_null() || data_out.is_null() {
        return GLU_INVALID_VALUE as GLint;
    }
    let (wi, hi, wo, ho) = (w_in as usize, h_in as usize, w_out as usize, h_out as usize);
    if wi.checked_mul(hi).and_then(|n| n.checked_mul(32)).is_none() || wo.checked_mul(ho).and_then(|n| n.checked_mul(32)).is_none() {
        return GLU_OUT_OF_MEMORY as GLint;
    }
    let unpack = PixelStore::query(gl, false);
    let pack = PixelStore::query(gl, true);
    let lin = Layout::new(format, kin, PixelStore { image_height: 0, skip_images: 0, ..unpack }, wi, hi, 1);
    let lout = Layout::new(format, kout, PixelStore { image_height: 0, skip_images: 0, ..pack }, wo, ho, 1);
    let src = std::slice::from_raw_parts(data_in as *const u8, lin.extent());
    let vals = lin.unpack(src);
    let scaled = resample(&vals, [wi, hi, 1], lin.comps, [wo, ho, 1]);
    let dst = std::slice::from_raw_parts_mut(data_out as *mut u8, lout.extent());
    lout.pack(&scaled, dst);
    0
}
