//! Client pixel data: unpacking from and packing into client memory by
//! format, type and the pixel storage modes (GL 1.5 sections 3.6.4
//! "Unpacking" and "Conversion to floating-point", 4.3.2 "Final conversion"
//! and "Placement in client memory"). Shared by glDrawPixels, glBitmap,
//! glReadPixels and the texture image commands (glTexImage, glTexSubImage,
//! glGetTexImage).
//!
//! What comes out of unpacking, per pixel, before any pixel transfer:
//! - colour formats: RGBA in f32, components converted by table 2.9
//!   (unsigned c / (2^b - 1), signed (2c + 1) / (2^b - 1), packed fields
//!   c / (2^w - 1), FLOAT as is), luminance copied to R, G and B, missing
//!   R, G, B set to 0 and missing A to 1 ("Final expansion to RGBA");
//! - DEPTH_COMPONENT: one normalized value (f32);
//! - COLOR_INDEX and STENCIL_INDEX: one index (f64), integer types taken
//!   as integers, FLOAT as is, GL_BITMAP one bit per index.
//!
//! Packing is the inverse (table 4.7: unsigned round(c (2^b - 1)), signed
//! round(((2^b - 1) c - 1) / 2)); indices are masked to the type's bits
//! (table 4.6). Pixels the caller marks as not available (outside the
//! window) are left untouched in client memory.
//!
//! EXT_abgr's ABGR_EXT is RGBA with the components in reverse order; like
//! RGB and BGR it takes the non-packed types only (the packed 4-component
//! types name RGBA and BGRA, section 3.6.4).
//!
//! DEPTH_STENCIL with UNSIGNED_INT_24_8 (EXT/NV_packed_depth_stencil): one
//! 32-bit word per group, depth in the upper 24 bits (normalized by
//! 2^24 - 1), the stencil index in the lower 8.
//!
//! Addressing (section 3.6.4, figure 3.8): row length l = ROW_LENGTH or
//! the width; a row holds l groups and is padded to the alignment when the
//! element size is smaller than it; SKIP_ROWS / SKIP_PIXELS / SKIP_IMAGES
//! move the start; SWAP_BYTES reverses each element (each packed value) of
//! more than one byte. GL_BITMAP rows are ceil(l / 8) bytes padded to the
//! alignment; SKIP_PIXELS counts bits; LSB_FIRST picks the bit order.

use super::enums::*;
use super::pixels::PixelModes;

/// EXT_packed_depth_stencil's format and type.
pub const GL_DEPTH_STENCIL: u32 = 0x84F9;
pub const GL_UNSIGNED_INT_24_8: u32 = 0x84FA;
/// ARB_texture_rg's two-component format.
pub const GL_RG: u32 = 0x8227;
/// EXT_abgr's format: RGBA groups in the order A, B, G, R.
pub const GL_ABGR_EXT: u32 = 0x8000;

/// What a format's groups are.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Kind {
    Color,
    Depth,
    Stencil,
    ColorIndex,
    /// DEPTH_STENCIL: (depth, stencil) pairs.
    DepthStencil,
}

/// A format's kind and its components in client order, as indices into
/// [R, G, B, A, L].
pub fn format_info(format: u32) -> Option<(Kind, &'static [usize])> {
    Some(match format {
        GL_COLOR_INDEX => (Kind::ColorIndex, &[0]),
        GL_STENCIL_INDEX => (Kind::Stencil, &[0]),
        GL_DEPTH_COMPONENT => (Kind::Depth, &[0]),
        GL_DEPTH_STENCIL => (Kind::DepthStencil, &[0]),
        GL_RED => (Kind::Color, &[0]),
        GL_GREEN => (Kind::Color, &[1]),
        GL_BLUE => (Kind::Color, &[2]),
        GL_ALPHA => (Kind::Color, &[3]),
        GL_RG => (Kind::Color, &[0, 1]),
        GL_RGB => (Kind::Color, &[0, 1, 2]),
        GL_RGBA => (Kind::Color, &[0, 1, 2, 3]),
        GL_BGR => (Kind::Color, &[2, 1, 0]),
        GL_BGRA => (Kind::Color, &[2, 1, 0, 3]),
        GL_ABGR_EXT => (Kind::Color, &[3, 2, 1, 0]),
        GL_LUMINANCE => (Kind::Color, &[4]),
        GL_LUMINANCE_ALPHA => (Kind::Color, &[4, 3]),
        _ => return None,
    })
}

/// Size in bytes of one element of a non-packed type (not GL_BITMAP).
pub fn elem_size(ty: u32) -> Option<usize> {
    Some(match ty {
        GL_UNSIGNED_BYTE | GL_BYTE => 1,
        GL_UNSIGNED_SHORT | GL_SHORT => 2,
        GL_UNSIGNED_INT | GL_INT | GL_FLOAT => 4,
        _ => return None,
    })
}

/// A packed type (table 3.8): bytes per pixel, and (shift, width) of each
/// component in format order. Non-REV types put the first component in the
/// most significant bits, REV types in the least significant.
pub fn packed_fields(ty: u32) -> Option<(usize, &'static [(u32, u32)])> {
    Some(match ty {
        GL_UNSIGNED_BYTE_3_3_2 => (1, &[(5, 3), (2, 3), (0, 2)]),
        GL_UNSIGNED_BYTE_2_3_3_REV => (1, &[(0, 3), (3, 3), (6, 2)]),
        GL_UNSIGNED_SHORT_5_6_5 => (2, &[(11, 5), (5, 6), (0, 5)]),
        GL_UNSIGNED_SHORT_5_6_5_REV => (2, &[(0, 5), (5, 6), (11, 5)]),
        GL_UNSIGNED_SHORT_4_4_4_4 => (2, &[(12, 4), (8, 4), (4, 4), (0, 4)]),
        GL_UNSIGNED_SHORT_4_4_4_4_REV => (2, &[(0, 4), (4, 4), (8, 4), (12, 4)]),
        GL_UNSIGNED_SHORT_5_5_5_1 => (2, &[(11, 5), (6, 5), (1, 5), (0, 1)]),
        GL_UNSIGNED_SHORT_1_5_5_5_REV => (2, &[(0, 5), (5, 5), (10, 5), (15, 1)]),
        GL_UNSIGNED_INT_8_8_8_8 => (4, &[(24, 8), (16, 8), (8, 8), (0, 8)]),
        GL_UNSIGNED_INT_8_8_8_8_REV => (4, &[(0, 8), (8, 8), (16, 8), (24, 8)]),
        GL_UNSIGNED_INT_10_10_10_2 => (4, &[(22, 10), (12, 10), (2, 10), (0, 2)]),
        GL_UNSIGNED_INT_2_10_10_10_REV => (4, &[(0, 10), (10, 10), (20, 10), (30, 2)]),
        GL_UNSIGNED_INT_24_8 => (4, &[(8, 24), (0, 8)]),
        _ => return None,
    })
}

/// Checks a format/type pair for the pixel commands: an unknown format or
/// type, or GL_BITMAP with a non-index format, is INVALID_ENUM; a packed
/// type whose component count does not match the format (3-component
/// types need RGB, 4-component ones RGBA or BGRA) is INVALID_OPERATION.
pub fn check_format_type(format: u32, ty: u32) -> Result<Kind, u32> {
    let (kind, _) = format_info(format).ok_or(GL_INVALID_ENUM)?;
    // DEPTH_STENCIL takes only its packed type, which no other format takes.
    if kind == Kind::DepthStencil || ty == GL_UNSIGNED_INT_24_8 {
        return match (kind == Kind::DepthStencil, ty == GL_UNSIGNED_INT_24_8) {
            (true, true) => Ok(kind),
            (true, false) => Err(GL_INVALID_ENUM),
            _ => Err(GL_INVALID_OPERATION),
        };
    }
    if ty == GL_BITMAP {
        return if matches!(kind, Kind::ColorIndex | Kind::Stencil) { Ok(kind) } else { Err(GL_INVALID_ENUM) };
    }
    if elem_size(ty).is_some() {
        return Ok(kind);
    }
    let (_, fields) = packed_fields(ty).ok_or(GL_INVALID_ENUM)?;
    let ok = match fields.len() {
        3 => format == GL_RGB,
        _ => matches!(format, GL_RGBA | GL_BGRA),
    };
    if ok {
        Ok(kind)
    } else {
        Err(GL_INVALID_OPERATION)
    }
}

/// Where each group of a width x height (x depth) image lives.
#[derive(Clone, Copy, Debug)]
pub struct Layout {
    /// Byte offset of the first row (skips applied; for GL_BITMAP the
    /// skipped pixels are `bit_skip`).
    pub start: usize,
    pub row_stride: usize,
    pub image_stride: usize,
    /// Bytes per group (0 for GL_BITMAP).
    pub group: usize,
    /// Bytes per element (per packed value for packed types).
    pub elem: usize,
    pub bitmap: bool,
    pub bit_skip: usize,
    pub lsb_first: bool,
    pub swap: bool,
}

impl Layout {
    pub fn new(modes: &PixelModes, width: usize, height: usize, format: u32, ty: u32) -> Layout {
        let l = if modes.row_length > 0 { modes.row_length as usize } else { width };
        let rows = if modes.image_height > 0 { modes.image_height as usize } else { height };
        let a = modes.alignment.max(1) as usize;
        if ty == GL_BITMAP {
            let row_stride = a * l.div_ceil(8).div_ceil(a);
            let image_stride = row_stride * rows;
            return Layout {
                start: modes.skip_rows as usize * row_stride + modes.skip_images as usize * image_stride,
                row_stride,
                image_stride,
                group: 0,
                elem: 1,
                bitmap: true,
                bit_skip: modes.skip_pixels as usize,
                lsb_first: modes.lsb_first,
                swap: false,
            };
        }
        let ncomp = format_info(format).map_or(1, |f| f.1.len());
        let (elem, group) = match packed_fields(ty) {
            Some((size, _)) => (size, size),
            None => {
                let e = elem_size(ty).unwrap_or(1);
                (e, e * ncomp)
            }
        };
        let row_stride = if elem >= a { group * l } else { a * (group * l).div_ceil(a) };
        let image_stride = row_stride * rows;
        Layout {
            start: modes.skip_pixels as usize * group + modes.skip_rows as usize * row_stride + modes.skip_images as usize * image_stride,
            row_stride,
            image_stride,
            group,
            elem,
            bitmap: false,
            bit_skip: 0,
            lsb_first: modes.lsb_first,
            swap: modes.swap_bytes && elem > 1,
        }
    }

    /// Byte offset of group (i, j, k); for GL_BITMAP, of the byte holding
    /// its bit, with the bit's mask.
    #[inline]
    pub fn offset(&self, i: usize, j: usize, k: usize) -> usize {
        self.start + k * self.image_stride + j * self.row_stride + i * self.group
    }

    #[inline]
    pub fn bit(&self, i: usize, j: usize, k: usize) -> (usize, u8) {
        let b = self.bit_skip + i;
        let byte = self.start + k * self.image_stride + j * self.row_stride + b / 8;
        let mask = if self.lsb_first { 1u8 << (b % 8) } else { 0x80u8 >> (b % 8) };
        (byte, mask)
    }

    /// Bytes from the start of client memory to the end of the last group
    /// (the extent a reader touches).
    pub fn extent(&self, width: usize, height: usize, depth: usize) -> usize {
        if width == 0 || height == 0 || depth == 0 {
            return 0;
        }
        if self.bitmap {
            let (last, _) = self.bit(width - 1, height - 1, depth - 1);
            last + 1
        } else {
            self.offset(width - 1, height - 1, depth - 1) + self.group
        }
    }
}

/// Reads one element of a non-packed type at `p`: normalized (colour,
/// depth) or as a plain number (indices).
#[inline]
fn read_elem(p: &[u8], ty: u32, swap: bool, normalized: bool) -> f64 {
    let mut b = [0u8; 4];
    let n = p.len().min(4);
    b[..n].copy_from_slice(&p[..n]);
    if swap {
        b[..n].reverse();
    }
    let (v, bits, signed) = match ty {
        GL_UNSIGNED_BYTE => (b[0] as f64, 8, false),
        GL_BYTE => (b[0] as i8 as f64, 8, true),
        GL_UNSIGNED_SHORT => (u16::from_ne_bytes([b[0], b[1]]) as f64, 16, false),
        GL_SHORT => (i16::from_ne_bytes([b[0], b[1]]) as f64, 16, true),
        GL_UNSIGNED_INT => (u32::from_ne_bytes(b) as f64, 32, false),
        GL_INT => (i32::from_ne_bytes(b) as f64, 32, true),
        _ => return f32::from_ne_bytes(b) as f64,
    };
    if !normalized {
        return v;
    }
    let max = ((1u64 << bits) - 1) as f64;
    if signed {
        (2.0 * v + 1.0) / max
    } else {
        v / max
    }
}

/// Reads a packed value of `size` bytes.
#[inline]
fn read_packed(p: &[u8], size: usize, swap: bool) -> u32 {
    let mut b = [0u8; 4];
    b[..size].copy_from_slice(&p[..size]);
    if swap {
        b[..size].reverse();
    }
    match size {
        1 => b[0] as u32,
        2 => u16::from_ne_bytes([b[0], b[1]]) as u32,
        _ => u32::from_ne_bytes(b),
    }
}

/// The client memory of an image, with its layout.
pub struct Source<'a> {
    pub data: &'a [u8],
    pub layout: Layout,
    pub format: u32,
    pub ty: u32,
}

impl<'a> Source<'a> {
    /// # Safety
    /// `ptr` must point to an image of `width` x `height` x `depth` laid out
    /// by `modes`, `format` and `ty`, as the GL command requires.
    pub unsafe fn new(modes: &PixelModes, width: usize, height: usize, depth: usize, format: u32, ty: u32, ptr: *const u8) -> Source<'a> {
        let layout = Layout::new(modes, width, height, format, ty);
        let len = layout.extent(width, height, depth);
        let data = if len == 0 || ptr.is_null() { &[][..] } else { std::slice::from_raw_parts(ptr, len) };
        Source { data, layout, format, ty }
    }

    /// Unpacks an image of a colour format into RGBA, row by row (rows
    /// bottom-up as given), images one after another.
    pub fn colors(&self, width: usize, height: usize, depth: usize) -> Vec<[f32; 4]> {
        let comps = format_info(self.format).map_or(&[0usize][..], |f| f.1);
        let mut out = Vec::with_capacity(width * height * depth);
        let l = &self.layout;
        let packed = packed_fields(self.ty);
        for k in 0..depth {
            for j in 0..height {
                for i in 0..width {
                    let o = l.offset(i, j, k);
                    let p = &self.data[o..o + l.group];
                    let mut raw = [0f32; 4];
                    match packed {
                        Some((size, fields)) => {
                            let v = read_packed(p, size, l.swap);
                            for (c, &(shift, w)) in fields.iter().enumerate() {
                                let m = (1u32 << w) - 1;
                                raw[c] = ((v >> shift) & m) as f32 / m as f32;
                            }
                        }
                        None if self.ty == GL_UNSIGNED_BYTE => {
                            for c in 0..comps.len() {
                                raw[c] = p[c] as f32 / 255.0;
                            }
                        }
                        None => {
                            for c in 0..comps.len() {
                                raw[c] = read_elem(&p[c * l.elem..(c + 1) * l.elem], self.ty, l.swap, true) as f32;
                            }
                        }
                    }
                    let mut rgba = [0.0, 0.0, 0.0, 1.0];
                    for (c, &dst) in comps.iter().enumerate() {
                        if dst == 4 {
                            rgba[0] = raw[c];
                            rgba[1] = raw[c];
                            rgba[2] = raw[c];
                        } else {
                            rgba[dst] = raw[c];
                        }
                    }
                    out.push(rgba);
                }
            }
        }
        out
    }

    /// Unpacks a DEPTH_STENCIL / UNSIGNED_INT_24_8 image: (depth, stencil)
    /// per group.
    pub fn depth_stencil(&self, width: usize, height: usize, depth: usize) -> Vec<(f64, f64)> {
        let l = &self.layout;
        let mut out = Vec::with_capacity(width * height * depth);
        for k in 0..depth {
            for j in 0..height {
                for i in 0..width {
                    let o = l.offset(i, j, k);
                    let v = read_packed(&self.data[o..o + 4], 4, l.swap);
                    out.push(((v >> 8) as f64 / 16777215.0, (v & 0xFF) as f64));
                }
            }
        }
        out
    }

    /// Unpacks a one-component image: depth values (normalized) or indices
    /// (plain numbers; GL_BITMAP gives 0 or 1).
    pub fn values(&self, width: usize, height: usize, depth: usize, normalized: bool) -> Vec<f64> {
        let mut out = Vec::with_capacity(width * height * depth);
        let l = &self.layout;
        for k in 0..depth {
            for j in 0..height {
                for i in 0..width {
                    if l.bitmap {
                        let (o, m) = l.bit(i, j, k);
                        out.push(if self.data[o] & m != 0 { 1.0 } else { 0.0 });
                    } else {
                        let o = l.offset(i, j, k);
                        out.push(read_elem(&self.data[o..o + l.elem], self.ty, l.swap, normalized));
                    }
                }
            }
        }
        out
    }
}

/// Writes a normalized value as a non-packed type (table 4.7).
#[inline]
fn put_normalized(out: &mut [u8], ty: u32, v: f64) {
    // FLOAT keeps the value: callers have clamped what must be clamped
    // (pixel transfer's final conversion), and float textures read back
    // unclamped (ARB_texture_float).
    if !matches!(ty, GL_UNSIGNED_BYTE | GL_BYTE | GL_UNSIGNED_SHORT | GL_SHORT | GL_UNSIGNED_INT | GL_INT) {
        out[..4].copy_from_slice(&(v as f32).to_ne_bytes());
        return;
    }
    let v = v.clamp(if matches!(ty, GL_BYTE | GL_SHORT | GL_INT) { -1.0 } else { 0.0 }, 1.0);
    match ty {
        GL_UNSIGNED_BYTE => out[0] = (v * 255.0).round() as u8,
        // Signed types: (2^b - 1) c - 1) / 2 (table 2.9 inverted); its ties
        // go to even, so a zero component reads back as 0, not -1.
        GL_BYTE => out[0] = ((v * 255.0 - 1.0) / 2.0).round_ties_even() as i8 as u8,
        GL_UNSIGNED_SHORT => out[..2].copy_from_slice(&((v * 65535.0).round() as u16).to_ne_bytes()),
        GL_SHORT => out[..2].copy_from_slice(&(((v * 65535.0 - 1.0) / 2.0).round_ties_even() as i16).to_ne_bytes()),
        GL_UNSIGNED_INT => out[..4].copy_from_slice(&((v * 4294967295.0).round() as u32).to_ne_bytes()),
        GL_INT => out[..4].copy_from_slice(&(((v * 4294967295.0 - 1.0) / 2.0).round_ties_even() as i32).to_ne_bytes()),
        _ => out[..4].copy_from_slice(&(v as f32).to_ne_bytes()),
    }
}

/// Writes an index as a non-packed type: masked to the type's bits
/// (table 4.6: 2^8 - 1, 2^7 - 1, ...), FLOAT as is.
#[inline]
fn put_index(out: &mut [u8], ty: u32, v: f64) {
    let i = v.floor() as i64;
    match ty {
        GL_UNSIGNED_BYTE => out[0] = (i & 0xFF) as u8,
        GL_BYTE => out[0] = (i & 0x7F) as u8,
        GL_UNSIGNED_SHORT => out[..2].copy_from_slice(&((i & 0xFFFF) as u16).to_ne_bytes()),
        GL_SHORT => out[..2].copy_from_slice(&((i & 0x7FFF) as u16).to_ne_bytes()),
        GL_UNSIGNED_INT => out[..4].copy_from_slice(&((i & 0xFFFF_FFFF) as u32).to_ne_bytes()),
        GL_INT => out[..4].copy_from_slice(&((i & 0x7FFF_FFFF) as u32).to_ne_bytes()),
        _ => out[..4].copy_from_slice(&(v as f32).to_ne_bytes()),
    }
}

/// Client memory to pack an image into.
pub struct Dest<'a> {
    pub data: &'a mut [u8],
    pub layout: Layout,
    pub format: u32,
    pub ty: u32,
}

impl<'a> Dest<'a> {
    /// # Safety
    /// `ptr` must point to writable memory for the image as laid out.
    pub unsafe fn new(modes: &PixelModes, width: usize, height: usize, format: u32, ty: u32, ptr: *mut u8) -> Dest<'a> {
        Self::with_depth(modes, width, height, 1, format, ty, ptr)
    }

    /// A 3D image's memory (glGetTexImage of 3D textures: IMAGE_HEIGHT and
    /// SKIP_IMAGES apply).
    ///
    /// # Safety
    /// As [`Dest::new`], for `depth` images.
    pub unsafe fn with_depth(modes: &PixelModes, width: usize, height: usize, depth: usize, format: u32, ty: u32, ptr: *mut u8) -> Dest<'a> {
        let layout = Layout::new(modes, width, height, format, ty);
        let len = layout.extent(width, height, depth);
        let data = if len == 0 || ptr.is_null() { &mut [][..] } else { std::slice::from_raw_parts_mut(ptr, len) };
        Dest { data, layout, format, ty }
    }

    /// Packs one RGBA pixel (already through final conversion: clamped)
    /// at (i, j): luminance is R + G + B, clamped (section 4.3.2).
    pub fn put_color(&mut self, i: usize, j: usize, c: [f32; 4]) {
        self.put_color_at(i, j, 0, c)
    }

    /// [`Dest::put_color`] in image k of a 3D image.
    pub fn put_color_at(&mut self, i: usize, j: usize, k: usize, c: [f32; 4]) {
        let comps = format_info(self.format).map_or(&[0usize][..], |f| f.1);
        let l = self.layout;
        let o = l.offset(i, j, k);
        let out = &mut self.data[o..o + l.group];
        let comp = |k: usize| -> f64 {
            if k == 4 {
                ((c[0] + c[1] + c[2]) as f64).clamp(0.0, 1.0)
            } else {
                c[k] as f64
            }
        };
        match packed_fields(self.ty) {
            Some((size, fields)) => {
                let mut v = 0u32;
                for (n, &(shift, w)) in fields.iter().enumerate() {
                    let m = (1u32 << w) - 1;
                    let x = (comp(comps[n]).clamp(0.0, 1.0) * m as f64).round() as u32;
                    v |= (x & m) << shift;
                }
                let mut b = [0u8; 4];
                match size {
                    1 => b[0] = v as u8,
                    2 => b[..2].copy_from_slice(&(v as u16).to_ne_bytes()),
                    _ => b = v.to_ne_bytes(),
                }
                if l.swap {
                    b[..size].reverse();
                }
                out.copy_from_slice(&b[..size]);
            }
            None => {
                for (n, &k) in comps.iter().enumerate() {
                    let e = &mut out[n * l.elem..(n + 1) * l.elem];
                    put_normalized(e, self.ty, comp(k));
                    if l.swap {
                        e.reverse();
                    }
                }
            }
        }
    }

    /// Packs a normalized value (depth) at (i, j).
    pub fn put_normalized(&mut self, i: usize, j: usize, v: f64) {
        self.put_normalized_at(i, j, 0, v)
    }

    /// [`Dest::put_normalized`] in image k of a 3D image.
    pub fn put_normalized_at(&mut self, i: usize, j: usize, k: usize, v: f64) {
        let l = self.layout;
        let o = l.offset(i, j, k);
        let e = &mut self.data[o..o + l.elem];
        put_normalized(e, self.ty, v);
        if l.swap {
            e.reverse();
        }
    }

    /// Packs a depth/stencil pair at (i, j) as UNSIGNED_INT_24_8.
    pub fn put_depth_stencil(&mut self, i: usize, j: usize, depth: f64, stencil: i64) {
        let l = self.layout;
        let o = l.offset(i, j, 0);
        let d = (depth.clamp(0.0, 1.0) * 16777215.0).round() as u32;
        let mut b = ((d << 8) | (stencil as u32 & 0xFF)).to_ne_bytes();
        if l.swap {
            b.reverse();
        }
        self.data[o..o + 4].copy_from_slice(&b);
    }

    /// Packs unnormalized values (histogram counts) at (i, j): each
    /// component of the format as an integer of the type (FLOAT as is);
    /// LUMINANCE takes R. Packed types take them as normalized values.
    pub fn put_counts(&mut self, i: usize, j: usize, c: [f64; 4]) {
        if packed_fields(self.ty).is_some() {
            return self.put_color(i, j, c.map(|v| v as f32));
        }
        let comps = format_info(self.format).map_or(&[0usize][..], |f| f.1);
        let l = self.layout;
        let o = l.offset(i, j, 0);
        for (n, &k) in comps.iter().enumerate() {
            let e = &mut self.data[o + n * l.elem..o + (n + 1) * l.elem];
            put_index(e, self.ty, c[if k == 4 { 0 } else { k }]);
            if l.swap {
                e.reverse();
            }
        }
    }

    /// Packs an index (stencil) at (i, j); GL_BITMAP writes its low bit.
    pub fn put_index(&mut self, i: usize, j: usize, v: f64) {
        let l = self.layout;
        if l.bitmap {
            let (o, m) = l.bit(i, j, 0);
            if (v.floor() as i64) & 1 != 0 {
                self.data[o] |= m;
            } else {
                self.data[o] &= !m;
            }
            return;
        }
        let o = l.offset(i, j, 0);
        let e = &mut self.data[o..o + l.elem];
        put_index(e, self.ty, v);
        if l.swap {
            e.reverse();
        }
    }
}
