//! Pixel storage modes (GL 1.5 section 3.6.1, table 3.1) and glReadPixels
//! (section 4.3.2): reading the framebuffer and packing it into client
//! memory by format, type and the pack modes.
//!
//! Implemented: every format except COLOR_INDEX (an RGBA context has no
//! indices: INVALID_OPERATION), with the types UNSIGNED_BYTE, BYTE,
//! UNSIGNED_SHORT, SHORT, UNSIGNED_INT, INT and FLOAT. The GL 1.2 packed
//! types are accepted but not packed yet (issue 5), and pixel transfer
//! (scale, bias, maps) is not applied yet.

use super::context::Context;
use super::enums::*;
use crate::framebuffer::DEPTH_MAX;

/// One direction's storage modes.
#[derive(Clone, Copy, Debug)]
pub struct PixelModes {
    pub swap_bytes: bool,
    pub lsb_first: bool,
    pub row_length: i32,
    pub skip_rows: i32,
    pub skip_pixels: i32,
    pub alignment: i32,
    pub image_height: i32,
    pub skip_images: i32,
}

impl Default for PixelModes {
    fn default() -> Self {
        PixelModes { swap_bytes: false, lsb_first: false, row_length: 0, skip_rows: 0, skip_pixels: 0, alignment: 4, image_height: 0, skip_images: 0 }
    }
}

#[derive(Clone, Copy, Debug, Default)]
pub struct PixelStore {
    pub pack: PixelModes,
    pub unpack: PixelModes,
}

/// Where each pixel of a width x height image lives in client memory
/// (section 3.6.4's addressing, shared by pack and unpack).
#[derive(Clone, Copy, Debug)]
pub struct Layout {
    /// Byte offset of pixel (0, 0).
    pub start: usize,
    /// Bytes between rows.
    pub row_stride: usize,
    /// Bytes per pixel (group).
    pub pixel_size: usize,
    pub elem_size: usize,
}

impl PixelModes {
    pub fn layout(&self, width: usize, components: usize, elem_size: usize) -> Layout {
        let l = if self.row_length > 0 { self.row_length as usize } else { width };
        let a = self.alignment as usize;
        let group = components * elem_size;
        let row_stride = if elem_size >= a { group * l } else { a * (group * l).div_ceil(a) };
        Layout {
            start: self.skip_pixels as usize * group + self.skip_rows as usize * row_stride,
            row_stride,
            pixel_size: group,
            elem_size,
        }
    }
}

/// The framebuffer value a format reads.
#[derive(Clone, Copy, Debug, PartialEq)]
enum Source {
    Color,
    Depth,
    Stencil,
}

/// The components a colour format writes, as indices into
/// [R, G, B, A, L] (L = R + G + B, clamped, section 4.3.2).
fn color_components(format: u32) -> Option<&'static [usize]> {
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
        _ => return None,
    })
}

/// Size in bytes of one element of a non-packed type.
fn elem_size(ty: u32) -> Option<usize> {
    Some(match ty {
        GL_UNSIGNED_BYTE | GL_BYTE => 1,
        GL_UNSIGNED_SHORT | GL_SHORT => 2,
        GL_UNSIGNED_INT | GL_INT | GL_FLOAT => 4,
        _ => return None,
    })
}

/// Types glReadPixels accepts (section 3.6.4 table 3.5).
fn is_pixel_type(ty: u32) -> bool {
    elem_size(ty).is_some() || ty == 0x1A00 /* GL_BITMAP */ || (0x8032..=0x8036).contains(&ty) || (0x8362..=0x8368).contains(&ty)
}

/// Writes a normalized value (colour, depth) as `ty` (table 2.9 inverted).
fn put_normalized(out: &mut [u8], ty: u32, v: f64) {
    let v = v.clamp(if matches!(ty, GL_BYTE | GL_SHORT | GL_INT) { -1.0 } else { 0.0 }, 1.0);
    match ty {
        GL_UNSIGNED_BYTE => out[0] = (v * 255.0).round() as u8,
        GL_BYTE => out[0] = ((v * 255.0 - 1.0) / 2.0).round() as i8 as u8,
        GL_UNSIGNED_SHORT => out.copy_from_slice(&((v * 65535.0).round() as u16).to_ne_bytes()),
        GL_SHORT => out.copy_from_slice(&(((v * 65535.0 - 1.0) / 2.0).round() as i16).to_ne_bytes()),
        GL_UNSIGNED_INT => out.copy_from_slice(&((v * 4294967295.0).round() as u32).to_ne_bytes()),
        GL_INT => out.copy_from_slice(&(((v * 4294967295.0 - 1.0) / 2.0).round() as i32).to_ne_bytes()),
        _ => out.copy_from_slice(&(v as f32).to_ne_bytes()),
    }
}

/// Writes an index (stencil) as `ty`: integer types keep the low bits.
fn put_index(out: &mut [u8], ty: u32, v: u32) {
    match ty {
        GL_UNSIGNED_BYTE | GL_BYTE => out[0] = v as u8,
        GL_UNSIGNED_SHORT | GL_SHORT => out.copy_from_slice(&(v as u16).to_ne_bytes()),
        GL_UNSIGNED_INT | GL_INT => out.copy_from_slice(&v.to_ne_bytes()),
        _ => out.copy_from_slice(&(v as f32).to_ne_bytes()),
    }
}

impl Context {
    /// glPixelStore (either form; floats are rounded for integer modes).
    pub fn pixel_store(&mut self, pname: u32, value: f64) {
        let int = value.round().clamp(i32::MIN as f64, i32::MAX as f64) as i32;
        let (modes, base) = match pname {
            GL_PACK_SWAP_BYTES..=GL_PACK_ALIGNMENT | GL_PACK_SKIP_IMAGES | GL_PACK_IMAGE_HEIGHT => (&mut self.pixel_store.pack, GL_PACK_SWAP_BYTES),
            GL_UNPACK_SWAP_BYTES..=GL_UNPACK_ALIGNMENT | GL_UNPACK_SKIP_IMAGES | GL_UNPACK_IMAGE_HEIGHT => {
                (&mut self.pixel_store.unpack, GL_UNPACK_SWAP_BYTES)
            }
            _ => return self.set_error(GL_INVALID_ENUM),
        };
        let which = match pname {
            GL_PACK_SKIP_IMAGES | GL_UNPACK_SKIP_IMAGES => 6,
            GL_PACK_IMAGE_HEIGHT | GL_UNPACK_IMAGE_HEIGHT => 7,
            _ => pname - base,
        };
        match which {
            0 => modes.swap_bytes = value != 0.0,
            1 => modes.lsb_first = value != 0.0,
            5 if matches!(int, 1 | 2 | 4 | 8) => modes.alignment = int,
            5 => return self.set_error(GL_INVALID_VALUE),
            _ if int < 0 => return self.set_error(GL_INVALID_VALUE),
            2 => modes.row_length = int,
            3 => modes.skip_rows = int,
            4 => modes.skip_pixels = int,
            6 => modes.skip_images = int,
            _ => modes.image_height = int,
        }
    }

    /// glReadPixels into `out` (client memory, already checked non-null).
    ///
    /// # Safety
    /// `out` must be large enough for the image as the pack modes lay it out.
    pub unsafe fn read_pixels(&mut self, x: i32, y: i32, w: i32, h: i32, format: u32, ty: u32, out: *mut u8) {
        if w < 0 || h < 0 {
            return self.set_error(GL_INVALID_VALUE);
        }
        let (source, comps): (Source, &[usize]) = match format {
            GL_DEPTH_COMPONENT => (Source::Depth, &[0]),
            GL_STENCIL_INDEX => (Source::Stencil, &[0]),
            GL_COLOR_INDEX => (Source::Color, &[]),
            f => match color_components(f) {
                Some(c) => (Source::Color, c),
                None => return self.set_error(GL_INVALID_ENUM),
            },
        };
        if !is_pixel_type(ty) {
            return self.set_error(GL_INVALID_ENUM);
        }
        let missing = match source {
            Source::Depth => !self.fb.has_depth(),
            Source::Stencil => !self.fb.has_stencil(),
            Source::Color => format == GL_COLOR_INDEX,
        };
        if missing {
            return self.set_error(GL_INVALID_OPERATION);
        }
        let Some(esize) = elem_size(ty) else {
            // Packed types and GL_BITMAP: not packed yet (issue 5).
            crate::api::unimplemented("glReadPixels with packed pixel types");
            return;
        };
        if out.is_null() || w == 0 || h == 0 {
            return;
        }
        let modes = self.pixel_store.pack;
        let layout = modes.layout(w as usize, comps.len(), esize);
        let fb = &self.fb;
        // Fast path: RGBA bytes inside the window are the stored bytes, a
        // row at a time.
        let inside = x >= 0 && y >= 0 && (x as i64 + w as i64) <= fb.width as i64 && (y as i64 + h as i64) <= fb.height as i64;
        if format == GL_RGBA && ty == GL_UNSIGNED_BYTE && inside {
            for j in 0..h as usize {
                let src = &fb.color[fb.index(x as usize, y as usize + j)..][..w as usize];
                let dst = out.add(layout.start + j * layout.row_stride);
                std::ptr::copy_nonoverlapping(src.as_ptr() as *const u8, dst, w as usize * 4);
            }
            return;
        }
        for j in 0..h {
            let fy = y as i64 + j as i64;
            if fy < 0 || fy >= fb.height as i64 {
                continue; // outside the window: undefined, left untouched
            }
            for i in 0..w {
                let fx = x as i64 + i as i64;
                if fx < 0 || fx >= fb.width as i64 {
                    continue;
                }
                let idx = fb.index(fx as usize, fy as usize);
                let base = layout.start + j as usize * layout.row_stride + i as usize * layout.pixel_size;
                let dst = std::slice::from_raw_parts_mut(out.add(base), layout.pixel_size);
                match source {
                    Source::Color => {
                        let c = fb.color[idx];
                        if ty == GL_UNSIGNED_BYTE {
                            // Exact fast path: the stored bytes.
                            let lum = (c[0] as u32 + c[1] as u32 + c[2] as u32).min(255) as u8;
                            for (k, &comp) in comps.iter().enumerate() {
                                dst[k] = if comp == 4 { lum } else { c[comp] };
                            }
                        } else {
                            let f = c.map(|v| v as f64 / 255.0);
                            for (k, &comp) in comps.iter().enumerate() {
                                let v = if comp == 4 { (f[0] + f[1] + f[2]).min(1.0) } else { f[comp] };
                                put_normalized(&mut dst[k * esize..(k + 1) * esize], ty, v);
                            }
                        }
                    }
                    Source::Depth => put_normalized(dst, ty, fb.depth[idx] as f64 / DEPTH_MAX as f64),
                    Source::Stencil => put_index(dst, ty, fb.stencil[idx] as u32),
                }
                if modes.swap_bytes && esize > 1 {
                    for chunk in dst.chunks_exact_mut(esize) {
                        chunk.reverse();
                    }
                }
            }
        }
    }
}
