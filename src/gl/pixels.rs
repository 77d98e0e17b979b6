//! Pixel storage modes (GL 1.5 section 3.6.1, table 3.1) and glReadPixels
//! (section 4.3.2): reading the framebuffer and packing it into client
//! memory by format, type and the pack modes.
//!
//! Every format except COLOR_INDEX (an RGBA context has no indices:
//! INVALID_OPERATION) with every type (GL_BITMAP for STENCIL_INDEX;
//! DEPTH_STENCIL as UNSIGNED_INT_24_8), through
//! pixel transfer (scale and bias, MAP_COLOR, index shift and offset,
//! MAP_STENCIL: `pixel_transfer`) and packing (`pixel_data`). Pixels outside
//! the window are undefined: their client memory is left untouched.

use super::context::Context;
use super::enums::*;
use super::pixel_data::{check_format_type, Dest, Kind};
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

/// glReadPixels of at least this many pixels copies bands of rows on the
/// rasterizer's threads (round 7).
const PARALLEL_READ: usize = 1 << 17;

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
            5 => self.set_error(GL_INVALID_VALUE),
            _ if int < 0 => self.set_error(GL_INVALID_VALUE),
            2 => modes.row_length = int,
            3 => modes.skip_rows = int,
            4 => modes.skip_pixels = int,
            6 => modes.skip_images = int,
            _ => modes.image_height = int,
        }
    }

    /// glReadPixels into `out` (client memory).
    ///
    /// # Safety
    /// `out` must be NULL or large enough for the image as the pack modes
    /// lay it out.
    #[allow(clippy::too_many_arguments)]
    pub unsafe fn read_pixels(&mut self, x: i32, y: i32, w: i32, h: i32, format: u32, ty: u32, out: *mut u8) {
        if w < 0 || h < 0 {
            return self.set_error(GL_INVALID_VALUE);
        }
        let kind = match check_format_type(format, ty) {
            Ok(k) => k,
            Err(e) => return self.set_error(e),
        };
        // A framebuffer object must be complete for reading.
        if !self.read_framebuffer_complete() {
            return;
        }
        let (rfb, _) = self.read_source();
        let missing = match kind {
            Kind::Depth => !rfb.has_depth(),
            Kind::Stencil => !rfb.has_stencil(),
            Kind::DepthStencil => !rfb.has_depth() || !rfb.has_stencil(),
            // An RGBA context has no colour indices.
            Kind::ColorIndex => true,
            // A framebuffer object read without a colour attachment or
            // with READ_BUFFER NONE.
            Kind::Color => self.fbo_read_color_missing(),
        };
        if missing {
            return self.set_error(GL_INVALID_OPERATION);
        }
        if (out.is_null() && !self.pack_buffer_bound()) || w == 0 || h == 0 {
            return;
        }
        let modes = self.pixel_store.pack;
        let out = match self.pack_image(&modes, w, h, 1, format, ty, out) {
            Ok(p) => p,
            Err(e) => return self.set_error(e),
        };
        if kind == Kind::Color {
            if let Some(st) = self.imaging_stages(2) {
                // The ARB_imaging stages (section 3.6.5) need the whole
                // rectangle (outside the window as zero); the packed image
                // is what comes out (smaller after a REDUCE convolution,
                // nothing after a sink).
                let mut c = self.framebuffer_colors(x, y, w, h);
                self.pixel.scale_bias_map(&mut c);
                if let Some((c, w2, _)) = self.imaging(st, c, w as usize, h as usize) {
                    let mut dest = Dest::new(&modes, w as usize, h as usize, format, ty, out);
                    for (n, p) in c.iter().enumerate() {
                        dest.put_color(n % w2.max(1), n / w2.max(1), *p);
                    }
                }
                return;
            }
        }
        let (w, h) = (w as usize, h as usize);
        let mut dest = Dest::new(&modes, w, h, format, ty, out);
        // Colours come from the buffer glReadBuffer names.
        let (fb, color) = self.read_source();
        let t = &self.pixel;
        // Fast path: RGBA bytes inside the window with no transfer are the
        // stored bytes, a row at a time.
        let inside = x >= 0 && y >= 0 && (x as i64 + w as i64) <= fb.width as i64 && (y as i64 + h as i64) <= fb.height as i64;
        if format == GL_RGBA && ty == GL_UNSIGNED_BYTE && inside && t.color_is_identity() {
            let layout = dest.layout;
            let (fw, first) = (fb.width, fb.index(x as usize, y as usize));
            let copy_row = |j: usize, out: &mut [u8]| {
                let src = &color[first + j * fw..][..w];
                for (o, px) in out[..4 * w].chunks_exact_mut(4).zip(src) {
                    o.copy_from_slice(px);
                }
            };
            let stride = layout.row_stride;
            if stride >= 4 * w && w * h >= PARALLEL_READ {
                // Large: bands of rows on the rasterizer's threads (each
                // output row lies in one band: rows do not overlap).
                let band = 32;
                let data = &mut dest.data[layout.offset(0, 0, 0)..];
                // A large destination is often fresh memory that this read
                // touches first (round 9: a 1920x1080 read faulted 2,000
                // 4 KiB pages in the first frame): transparent huge pages
                // where the kernel offers them, as for an OSMesa buffer.
                crate::framebuffer::plane::advise_huge_pages(data.as_mut_ptr(), data.len());
                crate::render::pool::for_pieces(self.derived.render.threads, data, band * stride, |k, out| {
                    for (r, row) in out.chunks_mut(stride).enumerate().take(h.saturating_sub(k * band)) {
                        copy_row(k * band + r, row);
                    }
                });
                return;
            }
            for j in 0..h {
                let o = layout.offset(0, j, 0);
                copy_row(j, &mut dest.data[o..]);
            }
            return;
        }
        let max = DEPTH_MAX as f64;
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
                match kind {
                    Kind::Color => {
                        let mut c = [color[idx].map(|v| v as f32 / 255.0)];
                        t.color(&mut c);
                        dest.put_color(i, j, c[0]);
                    }
                    Kind::Depth => dest.put_normalized(i, j, t.depth(fb.depth[idx] as f64 / max)),
                    Kind::DepthStencil => dest.put_depth_stencil(i, j, t.depth(fb.depth[idx] as f64 / max), t.stencil(fb.stencil[idx] as f64)),
                    _ => dest.put_index(i, j, t.stencil(fb.stencil[idx] as f64) as f64),
                }
            }
        }
    }
}
