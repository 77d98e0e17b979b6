//! Texture images (GL 1.5 section 3.8.1, tables 3.15, 3.16 and 3.23;
//! section 6.1.4 for glGetTexImage): internal formats and their base
//! formats, the conversion of client images to stored texels, glGetTexImage's
//! packing, and the box filter of GENERATE_MIPMAP.
//!
//! Client memory is read and written by `pixel_data`, the one per-format,
//! per-type converter (every format of the pixel commands but
//! STENCIL_INDEX, every type); TexImage goes through the same unpacking and
//! pixel transfer as glDrawPixels (`pixel_transfer`), then the final
//! conversion to texture components, as section 3.8.1 says.
//!
//! Storage: texels keep the table 3.23 expansion. Internal formats of at
//! most 8 bits per component are stored as 8-bit RGBA (the values every GL
//! stores for them, at least their nominal precision); wider ones (12, 16
//! bits, depth) keep f32, more than their nominal precision. RGBA or BGRA
//! bytes into an 8-bit format with no pixel transfer are copied without
//! per-pixel conversion (`texels`).

use super::enums::*;
use crate::gl::pixel_data::{self, Dest, Kind, Source};
use crate::gl::pixel_transfer::PixelTransfer;
use crate::gl::pixels::PixelModes;
use crate::render::texture::{to_unorm8, Base, Image, Texels, UNORM8};
use std::sync::Arc;

/// An internal format: base format and bits per component (R, G, B, A,
/// L, I, depth).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct InternalFormat {
    pub base: Base,
    pub bits: [u8; 7],
    /// ARB_texture_float: components are stored as given, unclamped.
    pub float: bool,
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
        // ARB_texture_rg: RGB textures whose missing components are 0.
        GL_RED | GL_R8 | GL_COMPRESSED_RED => (Rgb, [8, 0, 0, 0, 0, 0, 0]),
        GL_R16 => (Rgb, [16, 0, 0, 0, 0, 0, 0]),
        GL_RG | GL_RG8 | GL_COMPRESSED_RG => (Rgb, [8, 8, 0, 0, 0, 0, 0]),
        GL_RG16 => (Rgb, [16, 16, 0, 0, 0, 0, 0]),
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
        // EXT_packed_depth_stencil: sampled as depth; the stencil index is
        // kept in the texel's alpha (see `is_depth_stencil`).
        GL_DEPTH_STENCIL | GL_DEPTH24_STENCIL8 => (Depth, [0, 0, 0, 0, 0, 0, 24]),
        _ => return float_format(f),
    };
    Some(InternalFormat { base, bits, float: false })
}

/// Is `f` a floating-point internal format (ARB_texture_float)?
pub fn is_float_format(f: u32) -> bool {
    float_format(f).is_some()
}

/// ARB_texture_float's internal formats: (base, component bits).
fn float_format(f: u32) -> Option<InternalFormat> {
    use Base::*;
    let (base, b): (Base, u8) = match f {
        0x8814 => (Rgba, 32), // RGBA32F
        0x8815 => (Rgb, 32),  // RGB32F
        0x8816 => (Alpha, 32),
        0x8817 => (Intensity, 32),
        0x8818 => (Luminance, 32),
        0x8819 => (LuminanceAlpha, 32),
        0x881A => (Rgba, 16), // RGBA16F
        0x881B => (Rgb, 16),
        0x881C => (Alpha, 16),
        0x881D => (Intensity, 16),
        0x881E => (Luminance, 16),
        0x881F => (LuminanceAlpha, 16),
        _ => return None,
    };
    let bits = match base {
        Rgba => [b, b, b, b, 0, 0, 0],
        Rgb => [b, b, b, 0, 0, 0, 0],
        Alpha => [0, 0, 0, b, 0, 0, 0],
        Intensity => [0, 0, 0, 0, 0, b, 0],
        Luminance => [0, 0, 0, 0, b, 0, 0],
        LuminanceAlpha => [0, 0, 0, b, b, 0, 0],
        Depth => [0; 7],
    };
    Some(InternalFormat { base, bits, float: true })
}

/// Is `f` a packed depth/stencil internal format? Its texels are stored
/// as (depth, depth, depth, stencil index): depth textures sample only
/// the first component, so the alpha is free to keep the stencil for
/// glGetTexImage's DEPTH_STENCIL.
pub fn is_depth_stencil(f: u32) -> bool {
    matches!(f, GL_DEPTH_STENCIL | GL_DEPTH24_STENCIL8)
}

impl InternalFormat {
    /// The resolution a level query reports for each component: what is
    /// stored (8 bits for formats of at most 8, the nominal width above).
    pub fn stored_bits(&self) -> [u8; 7] {
        let wide = self.bits.iter().any(|&b| b > 8);
        self.bits.map(|b| if b == 0 { 0 } else if wide || self.base == Base::Depth { b.max(8) } else { 8 })
    }

    /// Which of R, G, B an RGB-based format keeps (RED and RG keep fewer:
    /// the others read as 0).
    pub fn rgb_mask(&self) -> [bool; 3] {
        if matches!(self.base, Base::Rgb | Base::Rgba) {
            [self.bits[0] > 0, self.bits[1] > 0, self.bits[2] > 0]
        } else {
            [true; 3]
        }
    }

    /// Stored as 8-bit RGBA ([`Texels::Rgba8`]): every component of at
    /// most 8 bits, and not depth.
    pub fn compact(&self) -> bool {
        self.base != Base::Depth && self.bits.iter().all(|&b| b <= 8)
    }
}

/// Unpacked client pixels of a texture image command, before pixel
/// transfer (display lists keep them in this form, section 5.4).
#[derive(Clone, Debug, PartialEq)]
pub enum Pixels {
    /// RGBA or BGRA UNSIGNED_BYTE groups, as R, G, B, A bytes: uploads of
    /// 8-bit images into 8-bit formats copy them without conversion.
    Rgba8(Arc<Vec<[u8; 4]>>),
    /// Other colour formats, RGBA by table 2.9 and "Final expansion".
    Color(Vec<[f32; 4]>),
    /// COLOR_INDEX groups (converted by the I_TO_* maps).
    Index(Vec<f64>),
    /// DEPTH_COMPONENT groups, normalized.
    Depth(Vec<f64>),
    /// DEPTH_STENCIL groups: (depth, stencil index).
    DepthStencil(Vec<(f64, f64)>),
}

impl Pixels {
    pub fn len(&self) -> usize {
        match self {
            Pixels::Rgba8(v) => v.len(),
            Pixels::Color(v) => v.len(),
            Pixels::Index(v) | Pixels::Depth(v) => v.len(),
            Pixels::DepthStencil(v) => v.len(),
        }
    }

    pub fn is_empty(&self) -> bool {
        self.len() == 0
    }
}

/// Checks a format/type pair for a texture image call (the pixel
/// commands' rules, `pixel_data::check_format_type`); STENCIL_INDEX is
/// not a texture format (INVALID_ENUM; the caller reports the depth
/// mismatch first).
pub fn check_format_type(format: u32, ty: u32) -> Result<Kind, u32> {
    match pixel_data::check_format_type(format, ty)? {
        Kind::Stencil => Err(crate::gl::enums::GL_INVALID_ENUM),
        k => Ok(k),
    }
}

/// Unpacks a w x h x d image of `format`/`ty` from client memory through
/// the unpack modes (section 3.6.4, by `pixel_data`; 3D images use
/// IMAGE_HEIGHT and SKIP_IMAGES, section 3.8.1). RGBA and BGRA bytes are
/// copied a row at a time. The caller has checked format and type.
///
/// # Safety
/// `ptr` must point to the whole image as the modes lay it out.
pub unsafe fn unpack(modes: &PixelModes, w: usize, h: usize, d: usize, format: u32, ty: u32, ptr: *const u8) -> Pixels {
    let src = Source::new(modes, w, h, d, format, ty, ptr);
    // An empty image reads nothing (its layout may still skip past the
    // end of client memory, which `Source` then leaves unmapped).
    if w == 0 || h == 0 || d == 0 {
        return Pixels::Rgba8(Arc::new(Vec::new()));
    }
    if ty == GL_UNSIGNED_BYTE && matches!(format, GL_RGBA | GL_BGRA) {
        let mut out = Vec::with_capacity(w * h * d);
        let bgra = format == GL_BGRA;
        for k in 0..d {
            for j in 0..h {
                let o = src.layout.offset(0, j, k);
                let row = &src.data[o..o + 4 * w];
                if bgra {
                    out.extend(row.chunks_exact(4).map(|p| [p[2], p[1], p[0], p[3]]));
                } else {
                    out.extend(row.chunks_exact(4).map(|p| [p[0], p[1], p[2], p[3]]));
                }
            }
        }
        return Pixels::Rgba8(Arc::new(out));
    }
    match pixel_data::format_info(format).map(|f| f.0) {
        Some(Kind::Depth) => Pixels::Depth(src.values(w, h, d, true)),
        Some(Kind::DepthStencil) => Pixels::DepthStencil(src.depth_stencil(w, h, d)),
        Some(Kind::ColorIndex) => Pixels::Index(src.values(w, h, d, false)),
        _ => Pixels::Color(src.colors(w, h, d)),
    }
}

/// Converts unpacked groups to stored texels of `f` (section 3.8.1): pixel
/// transfer as for glDrawPixels (scale, bias and MAP_COLOR for RGBA, the
/// I_TO_* maps for indices, depth scale and bias), the final clamp, then
/// table 3.15's choice of components and table 3.23's expansion. 8-bit
/// groups into an 8-bit format with no transfer are stored as they are.
pub fn texels(f: &InternalFormat, p: &Pixels, t: &PixelTransfer) -> Texels {
    let compact = f.compact();
    if let (Pixels::Rgba8(v), true, true) = (p, compact, t.color_is_identity()) {
        // Table 3.23 on bytes: no conversion at all for RGBA (the texture
        // shares the command's buffer).
        let out: Vec<[u8; 4]> = match f.base {
            Base::Rgba => return Texels::Rgba8(v.clone()),
            Base::Rgb => {
                let m = f.rgb_mask().map(|keep| if keep { 0xFF } else { 0 });
                v.iter().map(|&[r, g, b, _]| [r & m[0], g & m[1], b & m[2], 255]).collect()
            }
            Base::Alpha => v.iter().map(|&[_, _, _, a]| [0, 0, 0, a]).collect(),
            Base::Luminance => v.iter().map(|&[r, _, _, _]| [r, r, r, 255]).collect(),
            Base::LuminanceAlpha => v.iter().map(|&[r, _, _, a]| [r, r, r, a]).collect(),
            Base::Intensity => v.iter().map(|&[r, _, _, _]| [r, r, r, r]).collect(),
            Base::Depth => vec![[0, 0, 0, 255]; v.len()],
        };
        return Texels::Rgba8(Arc::new(out));
    }
    // Float formats keep values outside [0, 1] (ARB_texture_float): no
    // final clamp.
    let transfer = |c: &mut Vec<[f32; 4]>| if f.float { t.scale_bias_map(c) } else { t.color(c) };
    let rgba: Vec<[f32; 4]> = match p {
        Pixels::Rgba8(v) => {
            let mut c: Vec<[f32; 4]> = v.iter().map(|p| p.map(|x| UNORM8[x as usize])).collect();
            transfer(&mut c);
            c
        }
        Pixels::Color(v) => {
            let mut c = v.clone();
            transfer(&mut c);
            c
        }
        Pixels::Index(v) => v.iter().map(|&i| t.index_to_rgba(i)).collect(),
        Pixels::Depth(v) => v.iter().map(|&z| [t.depth(z) as f32, 0.0, 0.0, 1.0]).collect(),
        Pixels::DepthStencil(v) => {
            // Depth (stored as f32) with the stencil index, shifted, offset
            // and mapped as glDrawPixels does, masked to 8 bits.
            return Texels::Float(
                v.iter()
                    .map(|&(z, i)| {
                        let d = t.depth(z) as f32;
                        [d, d, d, (t.stencil(i) & 0xFF) as f32]
                    })
                    .collect(),
            );
        }
    };
    store(f, rgba)
}

/// Stores RGBA values (depth in R) as texels of `f`: clamped, expanded by
/// the base format, rounded to 8 bits for compact formats.
pub fn store(f: &InternalFormat, rgba: Vec<[f32; 4]>) -> Texels {
    let base = f.base;
    let m = f.rgb_mask();
    let expanded: Vec<[f32; 4]> = rgba
        .into_iter()
        .map(|p| {
            let mut c = if f.float { p } else { p.map(|v| if v.is_nan() { 0.0 } else { v.clamp(0.0, 1.0) }) };
            for k in 0..3 {
                if !m[k] {
                    c[k] = 0.0;
                }
            }
            base.expand(c)
        })
        .collect();
    Texels::from_float(expanded, f.compact())
}

/// The texels of an image of `f` that has no client data: zero.
pub fn zero_texels(f: &InternalFormat, n: usize) -> Texels {
    let t = f.base.expand([0.0; 4]);
    if f.compact() {
        Texels::Rgba8(Arc::new(vec![t.map(to_unorm8); n]))
    } else {
        Texels::Float(vec![t; n])
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

/// glGetTexImage's packing (section 6.1.4): the image's texels as RGBA
/// (table 6.1), through pixel transfer and final conversion as for
/// glReadPixels, packed by `pixel_data`; LUMINANCE packs R.
///
/// # Safety
/// `ptr` must have room for the image as the pack modes lay it out.
#[allow(clippy::too_many_arguments)]
pub unsafe fn pack(modes: &PixelModes, img: &Image, format: u32, ty: u32, t: &PixelTransfer, ptr: *mut u8) {
    let (w, h, d) = (img.width as usize, img.height as usize, img.depth as usize);
    let mut dest = Dest::with_depth(modes, w, h, d, format, ty, ptr);
    // RGBA bytes of an 8-bit RGBA texture with no transfer: a copy per row.
    if let (Texels::Rgba8(tex), Base::Rgba, GL_RGBA, GL_UNSIGNED_BYTE, true) = (&img.texels, img.base, format, ty, t.color_is_identity()) {
        if !dest.data.is_empty() {
            for k in 0..d {
                for j in 0..h {
                    let o = dest.layout.offset(0, j, k);
                    let row = &tex[(k * h + j) * w..][..w];
                    for (out, p) in dest.data[o..o + 4 * w].chunks_exact_mut(4).zip(row) {
                        out.copy_from_slice(p);
                    }
                }
            }
        }
        return;
    }
    let depth = format == GL_DEPTH_COMPONENT;
    let depth_stencil = format == GL_DEPTH_STENCIL;
    let stencil = is_depth_stencil(img.internal_format);
    let lum = matches!(format, GL_LUMINANCE | GL_LUMINANCE_ALPHA);
    let float = is_float_format(img.internal_format);
    for k in 0..d {
        for j in 0..h {
            for i in 0..w {
                let tx = img.texels.get((k * h + j) * w + i);
                if depth_stencil {
                    // Depth textures are 1D, 2D or cube maps: k is 0. The
                    // stencil index goes through shift, offset and
                    // MAP_STENCIL as glReadPixels' does.
                    let s = if stencil { t.stencil(tx[3] as f64) } else { 0 };
                    dest.put_depth_stencil(i, j, t.depth(tx[0] as f64), s);
                } else if depth {
                    dest.put_normalized_at(i, j, k, t.depth(tx[0] as f64));
                } else {
                    let mut c = [texel_to_rgba(img.base, tx)];
                    if float {
                        // Float textures read back unclamped.
                        t.scale_bias_map(&mut c);
                    } else {
                        t.color(&mut c);
                    }
                    if lum {
                        // glGetTexImage's luminance is R (not R + G + B as
                        // for glReadPixels).
                        c[0][1] = 0.0;
                        c[0][2] = 0.0;
                    }
                    dest.put_color_at(i, j, k, c[0]);
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

/// [`downsample`] on 8-bit texels: the exact mean of the covered texels,
/// rounded to nearest (halves up).
pub fn downsample_rgba8(src: &[[u8; 4]], w: usize, h: usize, d: usize) -> (Vec<[u8; 4]>, usize, usize, usize) {
    if d == 1 && w >= 2 && h >= 2 {
        return (box_2x2_rgba8(src, w, h), w / 2, h / 2, 1);
    }
    let (nw, nh, nd) = ((w / 2).max(1), (h / 2).max(1), (d / 2).max(1));
    let (sx, sy, sz) = (if w > 1 { 2 } else { 1 }, if h > 1 { 2 } else { 1 }, if d > 1 { 2 } else { 1 });
    let n = (sx * sy * sz) as u32;
    let mut out = Vec::with_capacity(nw * nh * nd);
    for k in 0..nd {
        for j in 0..nh {
            for i in 0..nw {
                let mut acc = [0u32; 4];
                for dz in 0..sz {
                    for dy in 0..sy {
                        let row = ((k * sz + dz) * h + j * sy + dy) * w + i * sx;
                        for t in &src[row..row + sx] {
                            for c in 0..4 {
                                acc[c] += t[c] as u32;
                            }
                        }
                    }
                }
                out.push(acc.map(|v| ((v + n / 2) / n) as u8));
            }
        }
    }
    (out, nw, nh, nd)
}

/// [`downsample_rgba8`] of a 2D image at least 2x2 (every level but the
/// last few of a mipmapped 2D texture): each texel the rounded mean of a
/// 2x2 block, (sum + 2) / 4, as the general loop computes it, in a loop
/// with the block's shape fixed (round 22: 512x512 with its levels took
/// about 32 instructions a texel made in the general loop, whose block
/// size is a variable; GL_GENERATE_MIPMAP runs in the first frame).
fn box_2x2_rgba8(src: &[[u8; 4]], w: usize, h: usize) -> Vec<[u8; 4]> {
    let (nw, nh) = (w / 2, h / 2);
    let mut out = Vec::with_capacity(nw * nh);
    for j in 0..nh {
        let (r0, r1) = (&src[2 * j * w..][..2 * nw], &src[(2 * j + 1) * w..][..2 * nw]);
        out.extend(r0.chunks_exact(2).zip(r1.chunks_exact(2)).map(|(a, b)| std::array::from_fn(|c| ((a[0][c] as u16 + a[1][c] as u16 + b[0][c] as u16 + b[1][c] as u16 + 2) >> 2) as u8)));
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The byte box filter is the f32 one rounded: compare on every 2x2
    /// block of a pseudo-random image, and on odd and 1-wide sizes.
    #[test]
    fn byte_box_filter_matches_the_mean() {
        let mut seed = 7u32;
        for (w, h, d) in [(8, 8, 1), (5, 3, 1), (1, 6, 1), (4, 4, 4), (7, 1, 1), (64, 33, 1)] {
            let src: Vec<[u8; 4]> = (0..w * h * d)
                .map(|_| {
                    seed = seed.wrapping_mul(1103515245).wrapping_add(12345);
                    (seed >> 3).to_ne_bytes()
                })
                .collect();
            let f: Vec<[f32; 4]> = src.iter().map(|p| p.map(|c| c as f32)).collect();
            let (bytes, bw, bh, bd) = downsample_rgba8(&src, w, h, d);
            let (mean, fw, fh, fd) = downsample(&f, w, h, d);
            assert_eq!((bw, bh, bd), (fw, fh, fd));
            for (b, m) in bytes.iter().zip(&mean) {
                for c in 0..4 {
                    // Halves round up; the f32 mean of integers is exact here.
                    assert_eq!(b[c] as f32, (m[c] + 0.5).floor(), "{w}x{h}x{d}");
                }
            }
        }
    }
}
