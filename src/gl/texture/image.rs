//! Texture image formats and pixel conversion (GL 1.5 sections 3.6.4 and
//! 3.8.1, table 3.15; section 6.1.4 for glGetTexImage): internal formats and
//! their base formats, unpacking client memory through the unpack modes
//! into RGBA (or depth) floats, conversion to stored texels, packing texels
//! back for glGetTexImage, and the box filter of GENERATE_MIPMAP.
//!
//! Formats: RED, GREEN, BLUE, ALPHA, RGB, RGBA, BGR, BGRA, LUMINANCE,
//! LUMINANCE_ALPHA, DEPTH_COMPONENT. Types: UNSIGNED_BYTE, BYTE,
//! UNSIGNED_SHORT, SHORT, UNSIGNED_INT, INT, FLOAT and the twelve GL 1.2
//! packed types. Signed integers convert by (2c + 1) / (2^b - 1) (table
//! 2.9), unsigned by c / (2^b - 1). Pixel transfer (scale, bias, maps) is
//! not applied yet. COLOR_INDEX and BITMAP are not accepted.
//!
//! Storage: texels keep the table 3.23 expansion as f32. Internal formats
//! of at most 8 bits per component are rounded to 8 bits (the RGBA8 values
//! every GL stores for them, at least their nominal precision); wider ones
//! (12, 16 bits, depth) keep f32, more than their nominal precision.

use super::enums::*;
use crate::gl::pixels::PixelModes;
use crate::render::texture::Base;

/// An internal format: base format and bits per component (R, G, B, A,
/// L, I, depth).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct InternalFormat {
    pub base: Base,
    pub bits: [u8; 7],
}

/// Table 3.16's sized formats and the unsized ones (1-4, base names,
/// generic compressed names stored uncompressed). None: not a texture
/// internal format (INVALID_VALUE).
pub fn internal_format(f: u32) -> Option<InternalFormat> {
    use Base::*;
    let (base, bits): (Base, [u8; 7]) = match f {
        1 | GL_LUMINANCE | GL_LUMINANCE8 | GL_COMPRESSED_LUMINANCE => (Luminance, [0, 0, 0, 0, 8, 0, 0]),
        GL_LUMINANCE4 => (Luminance, [0, 0, 0, 0, 4, 0, 0]),
        GL_LUMINANCE12 => (Luminance, [0, 0, 0, 0, 12, 0, 0]),
        GL_LUMINANCE16 => (Luminance, [0, 0, 0, 0, 16, 0, 0]),
        2 | GL_LUMINANCE_ALPHA | GL_LUMINANCE8_ALPHA8 | GL_COMPRESSED_LUMINANCE_ALPHA => (LuminanceAlpha, [0, 0, 0, 8, 8, 0, 0]),
        GL_LUMINANCE4_ALPHA4 => (LuminanceAlpha, [0, 0, 0, 4, 4, 0, 0]),
        GL_LUMINANCE6_ALPHA2 => (LuminanceAlpha, [0, 0, 0, 2, 6, 0, 0]),
        GL_LUMINANCE12_ALPHA4 => (LuminanceAlpha, [0, 0, 0, 4, 12, 0, 0]),
        GL_LUMINANCE12_ALPHA12 => (LuminanceAlpha, [0, 0, 0, 12, 12, 0, 0]),
        GL_LUMINANCE16_ALPHA16 => (LuminanceAlpha, [0, 0, 0, 16, 16, 0, 0]),
        GL_ALPHA | GL_ALPHA8 | GL_COMPRESSED_ALPHA => (Alpha, [0, 0, 0, 8, 0, 0, 0]),
        GL_ALPHA4 => (Alpha, [0, 0, 0, 4, 0, 0, 0]),
        GL_ALPHA12 => (Alpha, [0, 0, 0, 12, 0, 0, 0]),
        GL_ALPHA16 => (Alpha, [0, 0, 0, 16, 0, 0, 0]),
        GL_INTENSITY | GL_INTENSITY8 | GL_COMPRESSED_INTENSITY => (Intensity, [0, 0, 0, 0, 0, 8, 0]),
        GL_INTENSITY4 => (Intensity, [0, 0, 0, 0, 0, 4, 0]),
        GL_INTENSITY12 => (Intensity, [0, 0, 0, 0, 0, 12, 0]),
        GL_INTENSITY16 => (Intensity, [0, 0, 0, 0, 0, 16, 0]),
        3 | GL_RGB | GL_RGB8 | GL_COMPRESSED_RGB => (Rgb, [8, 8, 8, 0, 0, 0, 0]),
        GL_R3_G3_B2 => (Rgb, [3, 3, 2, 0, 0, 0, 0]),
        GL_RGB4 => (Rgb, [4, 4, 4, 0, 0, 0, 0]),
        GL_RGB5 => (Rgb, [5, 5, 5, 0, 0, 0, 0]),
        GL_RGB10 => (Rgb, [10, 10, 10, 0, 0, 0, 0]),
        GL_RGB12 => (Rgb, [12, 12, 12, 0, 0, 0, 0]),
        GL_RGB16 => (Rgb, [16, 16, 16, 0, 0, 0, 0]),
        4 | GL_RGBA | GL_RGBA8 | GL_COMPRESSED_RGBA => (Rgba, [8, 8, 8, 8, 0, 0, 0]),
        GL_RGBA2 => (Rgba, [2, 2, 2, 2, 0, 0, 0]),
        GL_RGBA4 => (Rgba, [4, 4, 4, 4, 0, 0, 0]),
        GL_RGB5_A1 => (Rgba, [5, 5, 5, 1, 0, 0, 0]),
        GL_RGB10_A2 => (Rgba, [10, 10, 10, 2, 0, 0, 0]),
        GL_RGBA12 => (Rgba, [12, 12, 12, 12, 0, 0, 0]),
        GL_RGBA16 => (Rgba, [16, 16, 16, 16, 0, 0, 0]),
        GL_DEPTH_COMPONENT | GL_DEPTH_COMPONENT24 => (Depth, [0, 0, 0, 0, 0, 0, 24]),
        GL_DEPTH_COMPONENT16 => (Depth, [0, 0, 0, 0, 0, 0, 16]),
        GL_DEPTH_COMPONENT32 => (Depth, [0, 0, 0, 0, 0, 0, 32]),
        _ => return None,
    };
    Some(InternalFormat { base, bits })
}

impl InternalFormat {
    /// The resolution a level query reports for each component: what is
    /// stored (8 bits for formats of at most 8, the nominal width above).
    pub fn stored_bits(&self) -> [u8; 7] {
        let wide = self.bits.iter().any(|&b| b > 8);
        self.bits.map(|b| if b == 0 { 0 } else if wide || self.base == Base::Depth { b.max(8) } else { 8 })
    }

    fn quantize_8(&self) -> bool {
        self.base != Base::Depth && self.bits.iter().all(|&b| b <= 8)
    }
}

/// Components of a client pixel format, as indices into RGBA (4 = L:
/// copied into R, G and B; 5 = depth).
pub fn format_components(format: u32) -> Option<&'static [usize]> {
    Some(match format {
        GL_RED => &[0],
        GL_GREEN => &[1],
        GL_BLUE => &[2],
        GL_ALPHA => &[3],
        GL_RGB => &[0, 1, 2],
        GL_RGBA => &[0, 1, 2, 3],
        GL_BGR => &[2, 1, 0],
        GL_BGRA => &[2, 1, 0, 3],
        GL_LUMINANCE => &[4],
        GL_LUMINANCE_ALPHA => &[4, 3],
        GL_DEPTH_COMPONENT => &[5],
        _ => return None,
    })
}

/// A packed type: bytes per pixel, bit widths from the most significant
/// field down (non-REV) or from the least significant up (REV), and the
/// component count it requires.
fn packed(ty: u32) -> Option<(usize, &'static [u32], bool, usize)> {
    Some(match ty {
        GL_UNSIGNED_BYTE_3_3_2 => (1, &[3, 3, 2], false, 3),
        GL_UNSIGNED_BYTE_2_3_3_REV => (1, &[3, 3, 2], true, 3),
        GL_UNSIGNED_SHORT_5_6_5 => (2, &[5, 6, 5], false, 3),
        GL_UNSIGNED_SHORT_5_6_5_REV => (2, &[5, 6, 5], true, 3),
        GL_UNSIGNED_SHORT_4_4_4_4 => (2, &[4, 4, 4, 4], false, 4),
        GL_UNSIGNED_SHORT_4_4_4_4_REV => (2, &[4, 4, 4, 4], true, 4),
        GL_UNSIGNED_SHORT_5_5_5_1 => (2, &[5, 5, 5, 1], false, 4),
        GL_UNSIGNED_SHORT_1_5_5_5_REV => (2, &[5, 5, 5, 1], true, 4),
        GL_UNSIGNED_INT_8_8_8_8 => (4, &[8, 8, 8, 8], false, 4),
        GL_UNSIGNED_INT_8_8_8_8_REV => (4, &[8, 8, 8, 8], true, 4),
        GL_UNSIGNED_INT_10_10_10_2 => (4, &[10, 10, 10, 2], false, 4),
        GL_UNSIGNED_INT_2_10_10_10_REV => (4, &[10, 10, 10, 2], true, 4),
        _ => return None,
    })
}

fn elem_size(ty: u32) -> Option<usize> {
    Some(match ty {
        GL_UNSIGNED_BYTE | GL_BYTE => 1,
        GL_UNSIGNED_SHORT | GL_SHORT => 2,
        GL_UNSIGNED_INT | GL_INT | GL_FLOAT => 4,
        _ => return None,
    })
}

/// Checks a format/type pair for an image call: INVALID_ENUM for unknown
/// enums, INVALID_OPERATION for a packed type the format does not fit.
pub fn check_format_type(format: u32, ty: u32) -> Result<(), u32> {
    let Some(comps) = format_components(format) else { return Err(crate::gl::enums::GL_INVALID_ENUM) };
    if elem_size(ty).is_some() {
        return Ok(());
    }
    match packed(ty) {
        None => Err(crate::gl::enums::GL_INVALID_ENUM),
        Some((_, _, _, n)) if n == comps.len() && matches!(format, GL_RGB | GL_BGR | GL_RGBA | GL_BGRA) => Ok(()),
        Some(_) => Err(crate::gl::enums::GL_INVALID_OPERATION),
    }
}

/// Unpacked client pixels: RGBA floats per pixel (depth in [0]).
pub type Pixels = Vec<[f32; 4]>;

#[inline]
fn read_elem(p: &[u8], ty: u32, swap: bool) -> f32 {
    let mut b = [0u8; 4];
    let n = elem_size(ty).unwrap_or(1);
    b[..n].copy_from_slice(&p[..n]);
    if swap {
        b[..n].reverse();
    }
    match ty {
        GL_UNSIGNED_BYTE => b[0] as f32 / 255.0,
        GL_BYTE => ((2.0 * (b[0] as i8) as f64 + 1.0) / 255.0) as f32,
        GL_UNSIGNED_SHORT => u16::from_ne_bytes([b[0], b[1]]) as f32 / 65535.0,
        GL_SHORT => ((2.0 * i16::from_ne_bytes([b[0], b[1]]) as f64 + 1.0) / 65535.0) as f32,
        GL_UNSIGNED_INT => (u32::from_ne_bytes(b) as f64 / 4294967295.0) as f32,
        GL_INT => ((2.0 * i32::from_ne_bytes(b) as f64 + 1.0) / 4294967295.0) as f32,
        _ => f32::from_ne_bytes(b),
    }
}

/// Unpacks a w x h x d image of `format`/`ty` from client memory at `ptr`
/// through the unpack modes (section 3.6.4; 3D images use IMAGE_HEIGHT and
/// SKIP_IMAGES, section 3.8.1). The caller has checked format and type.
///
/// # Safety
/// `ptr` must point to the whole image as the modes lay it out.
pub unsafe fn unpack(modes: &PixelModes, w: usize, h: usize, d: usize, format: u32, ty: u32, ptr: *const u8) -> Pixels {
    let comps = format_components(format).unwrap_or(&[0]);
    let (n_elems, esize, pk) = match packed(ty) {
        Some(p) => (1, p.0, Some(p)),
        None => (comps.len(), elem_size(ty).unwrap_or(1), None),
    };
    // Addressing by the shared pixel-store layout (3.6.4).
    let layout = crate::gl::pixel_data::Layout::new(modes, w, h, format, ty);
    let (start, image_stride) = (layout.start, layout.image_stride);
    debug_assert_eq!(layout.group, n_elems * esize);
    let mut out = Vec::with_capacity(w * h * d);
    for k in 0..d {
        for j in 0..h {
            let row = ptr.add(start + k * image_stride + j * layout.row_stride);
            let bytes = std::slice::from_raw_parts(row, w * layout.group);
            for i in 0..w {
                let px = &bytes[i * layout.group..(i + 1) * layout.group];
                let mut v = [0.0f32; 6];
                if let Some((size, widths, rev, _)) = pk {
                    let mut b = [0u8; 4];
                    b[..size].copy_from_slice(px);
                    if modes.swap_bytes {
                        b[..size].reverse();
                    }
                    let word = match size {
                        1 => b[0] as u32,
                        2 => u16::from_ne_bytes([b[0], b[1]]) as u32,
                        _ => u32::from_ne_bytes(b),
                    };
                    let total: u32 = widths.iter().sum();
                    let mut shift = if rev { 0 } else { total };
                    for (c, &bits) in widths.iter().enumerate() {
                        let sh = if rev {
                            let s = shift;
                            shift += bits;
                            s
                        } else {
                            shift -= bits;
                            shift
                        };
                        let field = (word >> sh) & ((1 << bits) - 1);
                        v[comps[c]] = field as f32 / ((1u32 << bits) - 1) as f32;
                    }
                } else {
                    for (c, &slot) in comps.iter().enumerate() {
                        v[slot] = read_elem(&px[c * esize..], ty, modes.swap_bytes && esize > 1);
                    }
                }
                let mut rgba = [v[0], v[1], v[2], 1.0];
                if comps.contains(&3) {
                    rgba[3] = v[3];
                }
                if comps.contains(&4) {
                    rgba[0] = v[4];
                    rgba[1] = v[4];
                    rgba[2] = v[4];
                }
                if comps.contains(&5) {
                    rgba = [v[5], 0.0, 0.0, 1.0];
                }
                out.push(rgba);
            }
        }
    }
    out
}

/// Converts unpacked RGBA to stored texels of `ifmt` (table 3.15 picks
/// the components; table 3.23 expands them; colours clamp to [0, 1]).
pub fn to_texel(ifmt: &InternalFormat, p: [f32; 4]) -> [f32; 4] {
    let c = p.map(|v| if v.is_nan() { 0.0 } else { v.clamp(0.0, 1.0) });
    let q = |v: f32| if ifmt.quantize_8() { (v * 255.0).round() / 255.0 } else { v };
    let [r, g, b, a] = c.map(q);
    match ifmt.base {
        Base::Alpha => [0.0, 0.0, 0.0, a],
        Base::Luminance => [r, r, r, 1.0],
        Base::LuminanceAlpha => [r, r, r, a],
        Base::Intensity => [r, r, r, r],
        Base::Rgb => [r, g, b, 1.0],
        Base::Rgba => [r, g, b, a],
        Base::Depth => [c[0], c[0], c[0], 1.0],
    }
}

/// A stored texel as glGetTexImage sees it (table 6.1): R, G, B, A with
/// luminance and intensity in R.
pub fn texel_to_rgba(base: Base, t: [f32; 4]) -> [f32; 4] {
    match base {
        Base::Alpha => [0.0, 0.0, 0.0, t[3]],
        Base::Luminance | Base::Intensity => [t[0], 0.0, 0.0, 1.0],
        Base::LuminanceAlpha => [t[0], 0.0, 0.0, t[3]],
        Base::Rgb => [t[0], t[1], t[2], 1.0],
        Base::Rgba => t,
        Base::Depth => [t[0], 0.0, 0.0, 1.0],
    }
}

fn put_elem(out: &mut [u8], ty: u32, v: f32, swap: bool) {
    let v = v as f64;
    let signed = matches!(ty, GL_BYTE | GL_SHORT | GL_INT);
    let c = if ty == GL_FLOAT { v } else { v.clamp(if signed { -1.0 } else { 0.0 }, 1.0) };
    let n = elem_size(ty).unwrap_or(1);
    let b: [u8; 4] = match ty {
        GL_UNSIGNED_BYTE => [(c * 255.0).round() as u8, 0, 0, 0],
        GL_BYTE => [((c * 255.0 - 1.0) / 2.0).round() as i8 as u8, 0, 0, 0],
        GL_UNSIGNED_SHORT => {
            let x = ((c * 65535.0).round() as u16).to_ne_bytes();
            [x[0], x[1], 0, 0]
        }
        GL_SHORT => {
            let x = (((c * 65535.0 - 1.0) / 2.0).round() as i16).to_ne_bytes();
            [x[0], x[1], 0, 0]
        }
        GL_UNSIGNED_INT => ((c * 4294967295.0).round() as u32).to_ne_bytes(),
        GL_INT => (((c * 4294967295.0 - 1.0) / 2.0).round() as i32).to_ne_bytes(),
        _ => (c as f32).to_ne_bytes(),
    };
    out[..n].copy_from_slice(&b[..n]);
    if swap {
        out[..n].reverse();
    }
}

/// Packs RGBA pixels (depth in [0] for DEPTH_COMPONENT) into client memory
/// as `format`/`ty` through the pack modes. LUMINANCE packs R.
///
/// # Safety
/// `ptr` must have room for the image as the modes lay it out.
#[allow(clippy::too_many_arguments)]
pub unsafe fn pack(modes: &PixelModes, w: usize, h: usize, d: usize, format: u32, ty: u32, pixels: &[[f32; 4]], ptr: *mut u8) {
    let comps = format_components(format).unwrap_or(&[0]);
    let (n_elems, esize, pk) = match packed(ty) {
        Some(p) => (1, p.0, Some(p)),
        None => (comps.len(), elem_size(ty).unwrap_or(1), None),
    };
    // Addressing by the shared pixel-store layout (3.6.4).
    let layout = crate::gl::pixel_data::Layout::new(modes, w, h, format, ty);
    let (start, image_stride) = (layout.start, layout.image_stride);
    debug_assert_eq!(layout.group, n_elems * esize);
    for k in 0..d {
        for j in 0..h {
            let row = ptr.add(start + k * image_stride + j * layout.row_stride);
            let bytes = std::slice::from_raw_parts_mut(row, w * layout.group);
            for i in 0..w {
                let p = pixels[(k * h + j) * w + i];
                let px = &mut bytes[i * layout.group..(i + 1) * layout.group];
                let value = |slot: usize| match slot {
                    4 | 5 => p[0],
                    s => p[s],
                };
                if let Some((size, widths, rev, _)) = pk {
                    let total: u32 = widths.iter().sum();
                    let mut word = 0u32;
                    let mut shift = if rev { 0 } else { total };
                    for (c, &bits) in widths.iter().enumerate() {
                        let sh = if rev {
                            let s = shift;
                            shift += bits;
                            s
                        } else {
                            shift -= bits;
                            shift
                        };
                        let max = ((1u32 << bits) - 1) as f32;
                        word |= ((value(comps[c]).clamp(0.0, 1.0) * max).round() as u32) << sh;
                    }
                    let mut b = word.to_ne_bytes();
                    if size == 2 {
                        let s = (word as u16).to_ne_bytes();
                        b = [s[0], s[1], 0, 0];
                    } else if size == 1 {
                        b = [word as u8, 0, 0, 0];
                    }
                    if modes.swap_bytes {
                        b[..size].reverse();
                    }
                    px.copy_from_slice(&b[..size]);
                } else {
                    for (c, &slot) in comps.iter().enumerate() {
                        put_elem(&mut px[c * esize..], ty, value(slot), modes.swap_bytes && esize > 1);
                    }
                }
            }
        }
    }
}

/// The next mipmap level of a w x h x d image (no border): each texel the
/// mean of the 2x2x2 (or fewer, along sides of size 1) texels it covers.
pub fn downsample(src: &[[f32; 4]], w: usize, h: usize, d: usize) -> (Vec<[f32; 4]>, usize, usize, usize) {
    let (nw, nh, nd) = ((w / 2).max(1), (h / 2).max(1), (d / 2).max(1));
    let (sx, sy, sz) = (if w > 1 { 2 } else { 1 }, if h > 1 { 2 } else { 1 }, if d > 1 { 2 } else { 1 });
    let mut out = Vec::with_capacity(nw * nh * nd);
    for k in 0..nd {
        for j in 0..nh {
            for i in 0..nw {
                let mut acc = [0.0f32; 4];
                for dz in 0..sz {
                    for dy in 0..sy {
                        for dx in 0..sx {
                            let t = src[((k * sz + dz) * h + j * sy + dy) * w + i * sx + dx];
                            for c in 0..4 {
                                acc[c] += t[c];
                            }
                        }
                    }
                }
                let n = (sx * sy * sz) as f32;
                out.push(acc.map(|v| v / n));
            }
        }
    }
    (out, nw, nh, nd)
}
