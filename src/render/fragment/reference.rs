//! The reference path (DESIGN.md, "State, validation, specialization";
//! issue 3 item 6): the plain, general, per-pixel evaluation of a
//! triangle's spans. Every plane is evaluated in f64 at each pixel centre
//! from its equation, 1/w is divided per pixel, and every fragment goes
//! through the general per-fragment operations of [`super`]. It is what
//! `SOFTGL_REFERENCE=1` selects and what `tests/reference_diff.rs` checks
//! the fast kernels ([`super::fast`]) against.

use super::{color_to_u8, depth_to_fixed, fragment, key, FragmentState, SpanPixels};
use crate::render::setup::{Plane, TriangleSetup};
use glam::Vec4;

/// A plane at (cx, cy) relative to its origin. The order (row term
/// first) is part of the contract with [`super::fast`], which hoists
/// `a0 + dy * cy` out of the row loop and must round identically.
#[inline]
pub fn eval(p: &Plane, cx: f64, cy: f64) -> f64 {
    p.a0 + p.dy * cy + p.dx * cx
}

/// The colour of a triangle's fragment at (cx, cy) relative to its origin.
#[inline(always)]
pub fn triangle_color(t: &TriangleSetup, cx: f64, cy: f64) -> [u8; 4] {
    if let Some((plane, fog)) = &t.fog {
        // Fog (3.10) after texturing, on the unconverted colour.
        let c = match &t.tex {
            Some(tp) => textured_color(t, tp, cx, cy),
            None => primary_color(t, cx, cy),
        };
        let w = if t.perspective { 1.0 / eval(&t.q, cx, cy) } else { 1.0 };
        return color_to_u8(fog.apply(c, (eval(plane, cx, cy) * w) as f32));
    }
    if let Some(tp) = &t.tex {
        return color_to_u8(textured_color(t, tp, cx, cy));
    }
    match t.flat {
        Some(c) => c,
        None => {
            let mut c = [0.0f32; 4];
            let w = if t.perspective { 1.0 / eval(&t.q, cx, cy) } else { 1.0 };
            for (ch, p) in t.color.iter().enumerate() {
                c[ch] = (eval(p, cx, cy) * w) as f32;
            }
            color_to_u8(Vec4::from_array(c))
        }
    }
}

/// The interpolated (or flat) primary colour, clamped, as floats.
#[inline]
pub fn primary_color(t: &TriangleSetup, cx: f64, cy: f64) -> Vec4 {
    match t.flat {
        Some(c) => Vec4::from_array(c.map(|v| v as f32 / 255.0)),
        None => {
            let w = if t.perspective { 1.0 / eval(&t.q, cx, cy) } else { 1.0 };
            let c: [f32; 4] = std::array::from_fn(|ch| (eval(&t.color[ch], cx, cy) * w) as f32);
            Vec4::from_array(c).clamp(Vec4::ZERO, Vec4::ONE)
        }
    }
}

/// Texturing (section 3.8) of a triangle's fragment at (cx, cy): the
/// primary colour, then each unit's sample and environment. Coordinates
/// are the perspective-correct ratios S/Q of the planes, and their screen
/// derivatives the exact ones of those ratios, (S' - s Q') / Q.
pub fn textured_color(t: &TriangleSetup, tp: &crate::render::setup::TexPlanes, cx: f64, cy: f64) -> Vec4 {
    let primary = primary_color(t, cx, cy);
    let mut coords = [crate::render::texture::Coord::default(); crate::render::texture::MAX_UNITS];
    for &u in &tp.stage.active {
        let p = &tp.planes[u];
        let q = eval(&p[3], cx, cy);
        if q == 0.0 || !q.is_finite() {
            continue;
        }
        let iq = 1.0 / q;
        let c = &mut coords[u];
        for k in 0..3 {
            let s = eval(&p[k], cx, cy) * iq;
            c.str[k] = s as f32;
            c.dx[k] = ((p[k].dx - s * p[3].dx) * iq) as f32;
            c.dy[k] = ((p[k].dy - s * p[3].dy) * iq) as f32;
        }
    }
    let c = tp.stage.shade(&coords, primary);
    match &t.secondary {
        // The colour sum (3.9): the secondary colour after texturing.
        Some(s) => {
            let w = if t.perspective { 1.0 / eval(&t.q, cx, cy) } else { 1.0 };
            let sec = glam::Vec3::from_array(std::array::from_fn(|ch| (eval(&s[ch], cx, cy) * w) as f32));
            (c.truncate() + sec).extend(c.w).clamp(Vec4::ZERO, Vec4::ONE)
        }
        None => c,
    }
}


/// Shades pixels [x0, x1) of row `y` of a triangle.
pub fn shade_span(fs: &FragmentState, t: &TriangleSetup, px: &mut SpanPixels, y: usize, x0: usize, x1: usize) {
    dispatch!(key(fs), span(fs, t, px, y, x0, x1))
}

fn span<const A: bool, const S: bool, const D: bool, const C: bool>(fs: &FragmentState, t: &TriangleSetup, px: &mut SpanPixels, y: usize, x0: usize, x1: usize) {
    let cy = y as f64 + 0.5 - t.y0;
    for x in x0..x1 {
        let cx = x as f64 + 0.5 - t.x0;
        fragment::<A, S, D, C>(fs, px, x - x0, || depth_to_fixed(eval(&t.z, cx, cy)), || triangle_color(t, cx, cy));
    }
}
