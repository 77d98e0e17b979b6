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

use super::context::Context;
use super::draw_pixels::PixelData;
use super::pixel_data::Source;
use crate::render::fragment::{depth_to_fixed, pixel_span, SpanPixels};
use crate::render::pixels;
use crate::render::texture::UNORM8;

/// The groups of an RGBA / UNSIGNED_BYTE image as bytes, rows bottom-up.
pub(super) fn unpack_rgba8(src: &Source, w: usize, h: usize) -> Vec<[u8; 4]> {
    let mut out = Vec::with_capacity(w * h);
    if w == 0 || h == 0 {
        return out;
    }
    let l = &src.layout;
    for j in 0..h {
        let o = l.offset(0, j, 0);
        let row = &src.data[o..o + 4 * w];
        out.extend(row.chunks_exact(4).map(|p| [p[0], p[1], p[2], p[3]]));
    }
    out
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
        self.rgba8_spans(xf, yf, w, h, data);
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
    /// operations at the raster position's depth.
    fn rgba8_spans(&mut self, xf: i64, yf: i64, w: usize, h: usize, data: &[[u8; 4]]) {
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
        let fb = &mut self.fb;
        let (i0, n) = ((x0 - xf) as usize, (x1 - x0) as usize);
        let mut passed = 0u64;
        for y in y0..y1 {
            let row = (y - yf) as usize * w + i0;
            let mut px = SpanPixels::of(fb, y as usize, x0 as usize, x1 as usize);
            pixel_span::color_span(fs, &mut px, z, &data[row..row + n]);
            passed += px.passed;
        }
        fb.samples_passed = fb.samples_passed.wrapping_add(passed);
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
        // Read everything first: overlapping copies see the old pixels.
        let mut data = Vec::with_capacity(cw * ch);
        for sy in sy0..sy1 {
            let i = fb.index(sx0 as usize, sy as usize);
            data.extend_from_slice(&read[i..i + cw]);
        }
        self.rgba8_spans(xf + (sx0 - x as i64), yf + (sy0 - y as i64), cw, ch, &data);
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
