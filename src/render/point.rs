//! Points (GL 1.5 section 3.3), non-antialiased: a point is clipped by its
//! centre (section 2.12: kept iff inside the view volume), its size rounds
//! to an integer w (at least 1, at most MAX_SIZE), and it covers the w x w
//! pixels whose centres lie within w/2 of its centre, where the centre is
//! (floor(x) + 1/2, floor(y) + 1/2) for odd w and (floor(x + 1/2),
//! floor(y + 1/2)) for even w. With x snapped to 1/ONE pixel both rules
//! are one formula: the first column is floor(x + 1/2 - w/2). Every
//! fragment takes the vertex's depth and colour.
//!
//! GL_POINT_SMOOTH: the disc of the smooth size centred on the point,
//! by coverage (`smooth`), with the GL 1.4 fade for derived sizes below the
//! fade threshold.

use super::fragment;
use super::runs;
use super::setup::{to_window, ONE};
use super::smooth;
use super::vertex::ClipVertex;
use super::RenderState;
use super::fragment::Buffers;
use crate::framebuffer::{Framebuffer, Rect};

/// Largest aliased point size (GL_ALIASED_POINT_SIZE_RANGE's maximum).
pub const MAX_SIZE: f32 = 64.0;

/// The rasterization size of a requested size: rounded, in [1, MAX_SIZE].
pub fn raster_size(size: f32) -> i64 {
    ((size.clamp(1.0, MAX_SIZE) + 0.5).floor() as i64).clamp(1, MAX_SIZE as i64)
}

/// The first pixel (column or row) of a point of rasterization size `w`
/// at window coordinate `c`.
pub fn first_pixel(c: f64, w: i64) -> i64 {
    let fc = (c * ONE as f64).round() as i64;
    (fc + ONE / 2 - w * ONE / 2).div_euclid(ONE)
}

/// Draws one point given in clip coordinates.
pub fn draw_point(rs: &RenderState, fb: &mut Framebuffer, size: f32, v: &ClipVertex) {
    let r = rs.draw_rect;
    let p = v.pos;
    if r.is_empty() || !p.is_finite() || !(p.w > 0.0) {
        return;
    }
    if p.x < -p.w || p.x > p.w || p.y < -p.w || p.y > p.w || p.z < -p.w || p.z > p.w {
        return;
    }
    // User clip planes (after the fixed ones).
    if rs.clip_planes[super::clip::FIXED_PLANES.len()..].iter().any(|pl| !(pl.dist(&p) >= 0.0)) {
        return;
    }
    let wv = to_window(rs, v);
    let primary = v.color.clamp(glam::Vec4::ZERO, glam::Vec4::ONE);
    let mut c = match &rs.texture {
        // Texturing (3.8): every fragment takes the vertex's coordinates.
        Some(stage) => {
            let c = stage.shade(&super::texture::point_coords(stage, &v.tex), primary);
            // The colour sum (3.9) after texturing.
            (c.truncate() + v.secondary.truncate()).extend(c.w).clamp(glam::Vec4::ZERO, glam::Vec4::ONE)
        }
        None => primary,
    };
    if let Some(f) = &rs.fog {
        c = f.apply(c, v.fog);
    }
    if let Some(quality) = rs.smooth.point {
        // Drawn now: after the binned primitives.
        super::tile::sync(rs, fb);
        let (width, fade) = smooth::faded_point(size, rs.smooth.fade_threshold);
        let alpha = c.w.clamp(0.0, 1.0) as f64 * fade as f64;
        let color = fragment::color_to_u8(c);
        // The centre snaps to 1/ONE pixel like every other vertex.
        let snap = |c: f64| (c * ONE as f64).round() / ONE as f64;
        smooth::disc_pixels(snap(wv.x), snap(wv.y), width / 2.0, r, quality, |x, y, cov| {
            let mut col = color;
            col[3] = smooth::alpha_u8(alpha * cov);
            fragment::shade_fragment(&rs.fragment, fb, x as usize, y as usize, wv.z, col);
        });
        return;
    }
    let w = raster_size(size);
    let (x0, y0) = (first_pixel(wv.x, w), first_pixel(wv.y, w));
    let color = fragment::color_to_u8(c);
    let xs = x0.max(r.x0 as i64)..(x0 + w).min(r.x1 as i64);
    if xs.is_empty() {
        return;
    }
    if !rs.reference {
        // The fast path: one run per row, the depth converted once; binned
        // with the triangles when threaded (`tile`).
        let p = PointRun { x0, y0, w, z: fragment::depth_to_fixed(wv.z), color };
        let bbox = p.rect(r);
        if bbox.is_empty() {
            return;
        }
        if super::tile::binning(rs) && !fb.draw_both {
            if super::tile::push_point(rs, p, bbox) {
                super::tile::submit_binned(rs, fb);
            }
            return;
        }
        super::tile::sync(rs, fb);
        let sink = runs::Sink::new(&rs.fragment, fb);
        let width = fb.width;
        p.draw(&sink, fb, width, bbox);
        return;
    }
    super::tile::sync(rs, fb);
    for y in y0.max(r.y0 as i64)..(y0 + w).min(r.y1 as i64) {
        for x in xs.clone() {
            fragment::shade_fragment(&rs.fragment, fb, x as usize, y as usize, wv.z, color);
        }
    }
}

/// A non-antialiased point as the fast path draws it: its w x w pixels
/// from (x0, y0), one depth and one colour.
#[derive(Clone, Copy, Debug)]
pub struct PointRun {
    pub x0: i64,
    pub y0: i64,
    pub w: i64,
    pub z: u32,
    pub color: [u8; 4],
}

impl PointRun {
    /// Its pixels within `r`.
    pub fn rect(&self, r: Rect) -> Rect {
        let fit = |v: i64, lo: i32, hi: i32| v.max(lo as i64).min(hi as i64) as i32;
        Rect { x0: fit(self.x0, r.x0, r.x1), x1: fit(self.x0 + self.w, r.x0, r.x1), y0: fit(self.y0, r.y0, r.y1), y1: fit(self.y0 + self.w, r.y0, r.y1) }
    }

    /// Its fragments within `r` (inside the framebuffer, `width` wide),
    /// one run per row.
    pub fn draw(&self, sink: &runs::Sink, fb: &mut impl Buffers, width: usize, r: Rect) {
        let r = self.rect(r);
        if r.is_empty() {
            return;
        }
        for y in r.y0 as usize..r.y1 as usize {
            sink.run(fb, y * width + r.x0 as usize, (r.x1 - r.x0) as usize, 1, |_| self.z, |_| self.color);
        }
    }
}
