//! glDrawPixels of RGBA / UNSIGNED_BYTE images (GL 1.5 section 3.6.4), the
//! common case, without the general path's per-group conversions; and
//! glCopyPixels of colour (section 4.3.3) on the same conditions, whose
//! groups are the read buffer's bytes.
//!
//! Unpacking: such an image is kept as its bytes ([`PixelData::Rgba8`],
//! a quarter of the f32 groups' size in display lists). Unpacked to f32 a
//! byte c is c / 255 (table 2.9), and the final conversion to the
//! framebuffer's 8 bits, round(255 * (c / 255)) in f32, gives c back for
//! every byte (tested below): when no pixel transfer operation is on (scale
//! 1, bias 0, no colour maps) and no texturing, colour sum or fog changes
//! the fragments, the bytes are the fragments' colours.
//!
//! Rasterization: at a zoom of (1, 1), group (i, j) covers exactly the
//! pixel (x0 + i, y0 + j) with x0 = ceil(xr - 1/2), y0 = ceil(yr - 1/2)
//! (`render::pixels::covered`), so each row of the image clipped to the
//! window and scissor box is one span of fragments at the raster
//! position's depth, run through the per-fragment operations span by span
//! (`render::fragment::pixel_span`). Every other case, and
//! `SOFTGL_REFERENCE=1`, takes the general path of `draw_pixels`, which
//! produces the same pixels one fragment at a time.
//!
//! Threads (round 8): rectangles of 128K pixels or more are cut into bands
//! of 32 rows that the pool's threads draw ([`RowBand`]); glCopyPixels
//! reads its whole source first (also in bands), so the drawing bands only
//! write.

use super::context::Context;
use super::draw_pixels::PixelData;
use super::pixel_data::Source;
use crate::render::fragment::{depth_to_fixed, pixel_span, SpanPixels};
use crate::render::pixels;
use crate::render::texture::UNORM8;
use std::sync::atomic::{AtomicU64, Ordering};

/// Rectangles of this many pixels or more are drawn in bands of
/// `BAND_ROWS` rows by the pool's threads (as glClear's: smaller ones cost
/// less than waking a worker).
const PARALLEL_PIXELS: usize = 1 << 17;
const BAND_ROWS: usize = 32;

/// Rows [y0, y1) of the framebuffer's planes that one call draws (see
/// `rgba8_spans`): the colour, depth and stencil rows and, under
/// GL_FRONT_AND_BACK, the other colour buffer's.
struct RowBand<'a> {
    y0: usize,
    y1: usize,
    width: usize,
    color: &'a mut [[u8; 4]],
    depth: &'a mut [u32],
    stencil: &'a mut [u8],
    other: Option<&'a mut [[u8; 4]]>,
}

impl<'a> RowBand<'a> {
    /// Rows [y0, y1) cut into bands of `rows` rows, bottom first.
    fn split(fb: &'a mut crate::framebuffer::Framebuffer, y0: usize, y1: usize, rows: usize) -> Vec<RowBand<'a>> {
        let width = fb.width;
        let crate::framebuffer::Framebuffer { color, depth, stencil, other_color, draw_both, .. } = fb;
        let piece = rows * width;
        let (a, b) = (y0 * width, y1 * width);
        let mut color = color[a..b].chunks_mut(piece);
        let mut depth = if depth.is_empty() { None } else { Some(depth[a..b].chunks_mut(piece)) };
        let mut stencil = if stencil.is_empty() { None } else { Some(stencil[a..b].chunks_mut(piece)) };
        let mut other = if *draw_both { Some(other_color[a..b].chunks_mut(piece)) } else { None };
        let mut out = Vec::with_capacity((y1 - y0).div_ceil(rows.max(1)));
        let mut y = y0;
        while y < y1 {
            let top = (y + rows).min(y1);
            out.push(RowBand {
                y0: y,
                y1: top,
                width,
                color: color.next().unwrap_or_default(),
                depth: depth.as_mut().and_then(|d| d.next()).unwrap_or_default(),
                stencil: stencil.as_mut().and_then(|s| s.next()).unwrap_or_default(),
                other: other.as_mut().and_then(|o| o.next()),
            });
            y = top;
        }
        out
    }

    /// Pixels [x0, x1) of row y (in [self.y0, self.y1)), as
    /// `SpanPixels::of` gives them.
    fn span(&mut self, y: usize, x0: usize, x1: usize) -> SpanPixels<'_> {
        let (a, b) = ((y - self.y0) * self.width + x0, (y - self.y0) * self.width + x1);
        SpanPixels {
            color: &mut self.color[a..b],
            other: self.other.as_mut().map(|o| &mut o[a..b]),
            depth: if self.depth.is_empty() { &mut [] } else { &mut self.depth[a..b] },
            stencil: if self.stencil.is_empty() { &mut [] } else { &mut self.stencil[a..b] },
            passed: 0,
        }
    }
}

/// The groups of an RGBA / UNSIGNED_BYTE image as bytes, rows bottom-up;
/// large images in bands of rows on `threads` threads (round 9: the copy
/// was the calling thread's share of a banded glDrawPixels).
pub(super) fn unpack_rgba8(src: &Source, w: usize, h: usize, threads: usize) -> Vec<[u8; 4]> {
    let mut out = Vec::with_capacity(w * h);
    if w == 0 || h == 0 {
        return out;
    }
    let l = &src.layout;
    gather_rows(&mut out, threads, w, h, |j| {
        let o = l.offset(0, j, 0);
        &src.data[o..o + 4 * w]
    });
    out
}

/// Appends `h` rows of `w` groups to `out` (empty, with room for them),
/// row j copied from the 4 w bytes `row(j)` gives; large rectangles in
/// bands of [`BAND_ROWS`] rows on `threads` threads. The memory is not
/// zeroed first (that was one more pass over it): the bands write every
/// element, one memcpy a row, then the length is set.
fn gather_rows<'s>(out: &mut Vec<[u8; 4]>, threads: usize, w: usize, h: usize, row: impl Fn(usize) -> &'s [u8] + Sync) {
    debug_assert!(out.is_empty());
    let threads = if w * h >= PARALLEL_PIXELS { threads } else { 1 };
    crate::render::pool::for_pieces(threads, &mut out.spare_capacity_mut()[..w * h], BAND_ROWS * w, |k, band| {
        for (i, dst) in band.chunks_mut(w).enumerate() {
            let src = &row(k * BAND_ROWS + i)[..4 * dst.len()];
            // SAFETY: `src` holds dst.len() groups of 4 bytes ([u8; 4] has
            // alignment 1), and `dst` as many uninitialised ones.
            unsafe { std::ptr::copy_nonoverlapping(src.as_ptr(), dst.as_mut_ptr() as *mut u8, src.len()) };
        }
    });
    // SAFETY: the pieces cover [0, w * h) once (`for_pieces`), and every
    // element of each piece was written above.
    unsafe { out.set_len(w * h) };
}

/// A colour rectangle's groups as f32 RGBA (c / 255 for bytes), before
/// pixel transfer, as `Source::colors` unpacks them.
pub(super) fn float_colors(d: &PixelData) -> Vec<[f32; 4]> {
    match d {
        PixelData::Color(c) => c.clone(),
        PixelData::Rgba8(b) => b.iter().map(|p| p.map(|v| UNORM8[v as usize])).collect(),
        _ => Vec::new(),
    }
}

impl Context {
    /// Draws an RGBA8 rectangle by spans when nothing but the per-fragment
    /// operations applies (see the module documentation); false when the
    /// general path must draw it. Derived state must be valid, and the
    /// caller has checked that no texturing, colour sum or fog is on.
    pub(super) fn draw_rgba8_fast(&mut self, w: usize, h: usize, data: &[[u8; 4]]) -> bool {
        let Some((xf, yf)) = self.rgba8_span_origin() else { return false };
        if data.len() != w * h {
            return false;
        }
        self.rgba8_spans(xf, yf, w, h, w, data);
        true
    }

    /// glDrawPixels of RGBA / UNSIGNED_BYTE groups from client memory,
    /// outside display-list compilation: drawn by spans straight from
    /// the client's rows when [`Context::draw_rgba8_fast`]'s conditions
    /// hold, as `execute` would run the built command (round 18: the
    /// command's copy of the image was a quarter of a window-sized
    /// draw's time, most of it the fresh copy's page faults). False when
    /// nothing was done: the caller builds the command as before (a list
    /// being compiled, feedback or selection, inside glBegin/glEnd, an
    /// unpack buffer, other formats, zoom, transfer or shading stages).
    ///
    /// # Safety
    /// `ptr` must be NULL or point to the image as the unpack modes lay it
    /// out, as for [`Context::build_draw_pixels`].
    pub(crate) unsafe fn draw_client_rgba8(&mut self, w: i32, h: i32, format: u32, ty: u32, ptr: *const u8) -> bool {
        use super::enums::{GL_RGBA, GL_UNSIGNED_BYTE};
        if format != GL_RGBA
            || ty != GL_UNSIGNED_BYTE
            || w <= 0
            || h <= 0
            || ptr.is_null()
            || self.unpack_buffer_bound()
            || self.lists.compile_mode().is_some()
            || self.select.mode != super::select::GL_RENDER
            || self.in_begin_end()
        {
            return false;
        }
        // What `execute` does before any command that draws.
        self.sync_render();
        if !self.raster.valid {
            return true;
        }
        self.validate();
        if self.imaging_stages(2).is_some() || self.pixel_shading_on() {
            return false;
        }
        let Some((xf, yf)) = self.rgba8_span_origin() else { return false };
        let (w, h) = (w as usize, h as usize);
        let src = Source::new(&self.pixel_store.unpack, w, h, 1, format, ty, ptr);
        let l = &src.layout;
        // Groups are 4 bytes, and both the rows' stride and the skips are
        // whole groups (the alignment rounds a multiple of 4 up to a
        // multiple of at most 8).
        if !l.row_stride.is_multiple_of(4) || !l.start.is_multiple_of(4) {
            return false;
        }
        let (stride, start) = (l.row_stride / 4, l.start / 4);
        let groups = (h - 1) * stride + w;
        // SAFETY: the image covers `start` groups then h rows of `stride`
        // groups (the last one w groups), as `Source::new` measured it;
        // [u8; 4] has alignment 1.
        let data = std::slice::from_raw_parts(ptr.add(4 * start) as *const [u8; 4], groups);
        self.rgba8_spans(xf, yf, w, h, stride, data);
        true
    }

    /// The window pixel of group (0, 0) when a colour rectangle can take
    /// the span path: no reference path, zoom (1, 1), no pixel transfer or
    /// imaging stage, a raster position in range. The caller checks that
    /// no texturing, colour sum or fog is on.
    fn rgba8_span_origin(&self) -> Option<(i64, i64)> {
        let [xr, yr, _, _] = self.raster.pos;
        let ok = !self.derived.render.reference
            && self.pixel.zoom == [1.0, 1.0]
            && self.pixel.color_is_identity()
            && self.imaging_stages(2).is_none()
            && xr.abs() < 1e9
            && yr.abs() < 1e9;
        ok.then(|| (pixels::covered(xr as f64, 1.0, 0).0, pixels::covered(yr as f64, 1.0, 0).0))
    }

    /// Draws a `w` x `h` rectangle of bytes whose group (0, 0) covers the
    /// window pixel (xf, yf), row by row through the per-fragment
    /// operations at the raster position's depth; row j starts at group
    /// `j * stride` of `data`.
    fn rgba8_spans(&mut self, xf: i64, yf: i64, w: usize, h: usize, stride: usize, data: &[[u8; 4]]) {
        let clip = self.scissored_surface();
        if clip.is_empty() || w == 0 || h == 0 {
            return;
        }
        let (x0, x1) = (xf.max(clip.x0 as i64), (xf + w as i64).min(clip.x1 as i64));
        let (y0, y1) = (yf.max(clip.y0 as i64), (yf + h as i64).min(clip.y1 as i64));
        if x0 >= x1 || y0 >= y1 {
            return;
        }
        let z = depth_to_fixed(self.raster.pos[2] as f64);
        let fs = &self.derived.render.fragment;
        let (i0, n) = ((x0 - xf) as usize, (x1 - x0) as usize);
        let (y0, y1) = (y0 as usize, y1 as usize);
        // Rows are independent (each fragment touches only its own pixel),
        // so large rectangles go in bands of rows to the pool's threads;
        // every row is drawn by one call with the same inputs, so the
        // pixels do not depend on the thread count.
        let threads = if n * (y1 - y0) >= PARALLEL_PIXELS { self.derived.render.threads } else { 1 };
        let passed = AtomicU64::new(0);
        let mut bands = RowBand::split(&mut self.fb, y0, y1, BAND_ROWS);
        crate::render::pool::for_pieces(threads, &mut bands, 1, |_, b| {
            let b = &mut b[0];
            let mut sum = 0u64;
            for y in b.y0..b.y1 {
                let row = (y as i64 - yf) as usize * stride + i0;
                let mut px = b.span(y, x0 as usize, x1 as usize);
                pixel_span::color_span(fs, &mut px, z, &data[row..row + n]);
                sum = sum.wrapping_add(px.passed);
            }
            passed.fetch_add(sum, Ordering::Relaxed);
        });
        drop(bands);
        self.fb.samples_passed = self.fb.samples_passed.wrapping_add(passed.into_inner());
    }

    /// glCopyPixels of colour by spans, on the span path's conditions
    /// (and no texturing, colour sum or fog, which the caller checks):
    /// the source rectangle cut to the read framebuffer (outside pixels
    /// make no fragments) is read whole, then drawn like an RGBA8 image
    /// from the group of its first pixel. False: the general path copies.
    pub(super) fn copy_rgba8_fast(&mut self, x: i32, y: i32, w: usize, h: usize) -> bool {
        let Some((xf, yf)) = self.rgba8_span_origin() else { return false };
        let (fb, read) = self.read_source();
        let (fw, fh) = (fb.width as i64, fb.height as i64);
        let (sx0, sx1) = ((x as i64).max(0), (x as i64 + w as i64).min(fw));
        let (sy0, sy1) = ((y as i64).max(0), (y as i64 + h as i64).min(fh));
        if sx0 >= sx1 || sy0 >= sy1 {
            return true;
        }
        let (cw, ch) = ((sx1 - sx0) as usize, (sy1 - sy0) as usize);
        // Read everything first: overlapping copies see the old pixels
        // (large rectangles in bands of rows by the threads too).
        let mut data: Vec<[u8; 4]> = Vec::with_capacity(cw * ch);
        gather_rows(&mut data, self.derived.render.threads, cw, ch, |j| {
            let i = fb.index(sx0 as usize, sy0 as usize + j);
            read[i..i + cw].as_flattened()
        });
        self.rgba8_spans(xf + (sx0 - x as i64), yf + (sy0 - y as i64), cw, ch, cw, &data);
        true
    }
}

#[cfg(test)]
mod tests {
    use crate::render::fragment::color_to_u8;
    use crate::render::texture::UNORM8;

    /// Every byte survives c / 255 and the conversion back to 8 bits: the
    /// identity the fast path relies on.
    #[test]
    fn bytes_round_trip_through_unorm() {
        for c in 0..=255u8 {
            let v = UNORM8[c as usize];
            assert_eq!(color_to_u8(glam::Vec4::splat(v)), [c; 4]);
            assert_eq!(v, c as f32 / 255.0);
        }
    }
}
