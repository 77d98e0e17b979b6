//! Triangle setup: window coordinates, snapping to fixed point, facing and
//! culling (GL 1.5 section 3.5.1), and the plane equations from which every
//! fragment's depth and colour are interpolated (section 3.5.1, equation 3.9:
//! perspective-correct through 1/w).
//!
//! Precision: vertices snap to 1/256 pixel (SUBPIXEL_BITS = 8). After
//! clipping (`clip`), window coordinates lie within (GUARD + 2) * MAX_SIZE
//! < 2^19 pixels of the origin, so snapped coordinates fit in 27 bits and
//! edge-function products in 55 bits: i64 arithmetic is exact, and the
//! coverage decision is exact for every pixel. Attribute planes are f64.

use super::raster;
use super::vertex::ClipVertex;
use super::shade_state::SetupParams;
use super::RenderState;
use glam::Vec4;

pub const SUBPIXEL_BITS: u32 = 8;
pub const ONE: i64 = 1 << SUBPIXEL_BITS;

/// A vertex after perspective division and the viewport transform.
#[derive(Clone, Copy, Debug)]
pub struct WindowVertex {
    pub x: f64,
    pub y: f64,
    /// Window depth in [0, 1] (before conversion to the depth buffer's bits).
    pub z: f64,
    /// 1 / w_clip.
    pub q: f64,
    pub color: Vec4,
    pub back_color: Vec4,
    pub tex: [Vec4; super::texture::MAX_UNITS],
    pub fog: f32,
    pub secondary: Vec4,
    pub back_secondary: Vec4,
}

/// Window x, y, z and 1/w of a clip-space position (perspective division
/// and the viewport transform, 2.11): the same arithmetic as [`to_window`].
#[inline]
pub fn window_pos(rs: &RenderState, p: glam::Vec4) -> [f64; 4] {
    let q = 1.0 / p.w as f64;
    let [sx, sy, sz] = rs.viewport_scale;
    let [ox, oy, oz] = rs.viewport_offset;
    [ox + sx * (p.x as f64 * q), oy + sy * (p.y as f64 * q), oz + sz * (p.z as f64 * q), q]
}

#[inline]
pub fn to_window(rs: &RenderState, v: &ClipVertex) -> WindowVertex {
    let [x, y, z, q] = window_pos(rs, v.pos);
    WindowVertex {
        x,
        y,
        z,
        q,
        color: v.color,
        back_color: v.back_color,
        tex: v.tex,
        fog: v.fog,
        secondary: v.secondary,
        back_secondary: v.back_secondary,
    }
}

/// The interpolated attributes of a vertex as setup reads them: window
/// vertices, and clip vertices of triangles that need no clipping, read
/// in place (no copy of the whole vertex per triangle).
pub trait Attributes {
    fn color(&self) -> Vec4;
    fn back_color(&self) -> Vec4;
    fn tex(&self, unit: usize) -> Vec4;
    fn fog(&self) -> f32;
    fn secondary(&self) -> Vec4;
    fn back_secondary(&self) -> Vec4;
}

macro_rules! attributes {
    ($t:ty) => {
        impl Attributes for $t {
            #[inline(always)]
            fn color(&self) -> Vec4 {
                self.color
            }
            #[inline(always)]
            fn back_color(&self) -> Vec4 {
                self.back_color
            }
            #[inline(always)]
            fn tex(&self, unit: usize) -> Vec4 {
                self.tex[unit]
            }
            #[inline(always)]
            fn fog(&self) -> f32 {
                self.fog
            }
            #[inline(always)]
            fn secondary(&self) -> Vec4 {
                self.secondary
            }
            #[inline(always)]
            fn back_secondary(&self) -> Vec4 {
                self.back_secondary
            }
        }
    };
}
attributes!(WindowVertex);
attributes!(ClipVertex);

/// round(c * 256) as i64: snapping to the subpixel grid, rounding half
/// away from zero as f64::round does, without its library call.
#[inline(always)]
pub fn snap(c: f64) -> i64 {
    let v = c * ONE as f64;
    // Window coordinates after clipping are far below 2^52; anything else
    // (never reached) takes the library's rounding.
    if !(v.abs() < 4503599627370496.0) {
        return v.round() as i64;
    }
    let t = v as i64; // toward zero, exact for |v| < 2^52
    let frac = v - t as f64; // exact
    if frac >= 0.5 {
        t + 1
    } else if frac <= -0.5 {
        t - 1
    } else {
        t
    }
}

/// a(x, y) = a0 + dx (x - x0) + dy (y - y0), around the setup's origin.
#[derive(Clone, Copy, Debug, Default)]
pub struct Plane {
    pub a0: f64,
    pub dx: f64,
    pub dy: f64,
}

/// What the fragment stage needs to shade a triangle's spans.
#[derive(Clone, Debug)]
pub struct TriangleSetup {
    /// Origin of the planes (vertex 0, snapped).
    pub x0: f64,
    pub y0: f64,
    pub z: Plane,
    /// 1/w plane; unused when `perspective` is false.
    pub q: Plane,
    /// Colour planes: of c/w when perspective, else of c.
    pub color: [Plane; 4],
    pub perspective: bool,
    /// Flat shading: the provoking vertex's colour, already converted.
    pub flat: Option<[u8; 4]>,
    pub front_facing: bool,
    /// Texturing: planes of s/w, t/w, r/w, q/w per unit (section 3.8.7's
    /// perspective-correct coordinates are their ratios to q/w).
    pub tex: Option<Box<TexPlanes>>,
    /// Fog: the plane of the fog value (times 1/w when perspective) and
    /// the fog parameters.
    pub fog: Option<(Plane, super::fog::Fog)>,
    /// The colour sum after texturing: planes of the secondary colour's
    /// RGB (times 1/w when perspective).
    pub secondary: Option<[Plane; 3]>,
}

/// Texture coordinate planes of a triangle and the stage that samples.
#[derive(Clone, Debug)]
pub struct TexPlanes {
    pub stage: std::sync::Arc<super::texture::TextureStage>,
    pub planes: [[Plane; 4]; super::texture::MAX_UNITS],
}

/// Sets up and rasterizes one triangle in window coordinates.
/// `flat_color` is the provoking vertex's [front, back] colour.
pub fn triangle(rs: &RenderState, fb: &mut crate::framebuffer::Framebuffer, w: &[WindowVertex; 3], flat_color: [Vec4; 2]) {
    let pos = w.each_ref().map(|v| [v.x, v.y, v.z, v.q]);
    triangle_at(rs, fb, pos, w.each_ref(), flat_color)
}

/// [`triangle`] for clip vertices whose window positions are already
/// computed (`ClipVertex::place`).
pub fn triangle_placed(rs: &RenderState, fb: &mut crate::framebuffer::Framebuffer, v: [&ClipVertex; 3], flat_color: [Vec4; 2]) {
    let pos = v.map(|cv| cv.win);
    let fx = v.map(|cv| cv.snapped[0]);
    let fy = v.map(|cv| cv.snapped[1]);
    triangle_snapped(rs, fb, pos, fx, fy, v, flat_color)
}

/// [`triangle`] for window positions `pos` (x, y, z, 1/w) whose other
/// attributes are read from `attrs`.
#[inline]
pub fn triangle_at<A: Attributes>(rs: &RenderState, fb: &mut crate::framebuffer::Framebuffer, pos: [[f64; 4]; 3], attrs: [&A; 3], flat_color: [Vec4; 2]) {
    let fx = pos.map(|p| snap(p[0]));
    let fy = pos.map(|p| snap(p[1]));
    triangle_snapped(rs, fb, pos, fx, fy, attrs, flat_color)
}

/// [`triangle_at`] with the vertices already snapped to (fx, fy).
#[inline(always)]
fn triangle_snapped<A: Attributes>(rs: &RenderState, fb: &mut crate::framebuffer::Framebuffer, pos: [[f64; 4]; 3], fx: [i64; 3], fy: [i64; 3], attrs: [&A; 3], flat_color: [Vec4; 2]) {
    let area = (fx[1] - fx[0]) * (fy[2] - fy[0]) - (fx[2] - fx[0]) * (fy[1] - fy[0]);
    if area == 0 {
        return;
    }
    // Window y points up, so counter-clockwise is positive area.
    let ccw = area > 0;
    let Some(front_facing) = rs.facing(ccw) else { return };
    // Rasterize with positive orientation.
    let order = if ccw { [0, 1, 2] } else { [0, 2, 1] };
    let ex = order.map(|i| fx[i]);
    let ey = order.map(|i| fy[i]);
    let zq = order.map(|i| (pos[i][2], pos[i][3]));
    let v = order.map(|i| attrs[i]);
    // Two-sided lighting: a back-facing polygon shows its back colours.
    let back = rs.two_side && !front_facing;
    if super::tile::binning(rs) && !fb.draw_both && rs.polygon_mode == [crate::gl::enums::GL_FILL; 2] {
        // Set up later, in the tile workers.
        if let Some(bbox) = super::tile::bounds(rs, ex, ey) {
            if super::tile::push(rs, ex, ey, bbox, zq, v, flat_color[back as usize], back, front_facing) {
                super::tile::submit(rs, fb);
            }
        }
        return;
    }
    // Drawn now: after what is binned (two colour buffers).
    super::tile::sync(rs, fb);
    // A short triangle's runs are found first: covering no pixel (most
    // often through the stipple or between pixel centres), it needs no
    // planes.
    let mut found = raster::Runs::new();
    let runs = found.find(ex, ey, rs.draw_rect, rs.polygon_stipple.as_deref()).then_some(&found);
    if runs.is_some_and(|r| r.is_empty()) {
        return;
    }
    let setup = planes_of(rs, zq, v, ex, ey, flat_color[back as usize], back, front_facing);
    let k = raster::kernel(rs, fb, &setup);
    match runs {
        Some(r) => r.shade(rs, fb, &setup, k),
        None => raster::triangle(rs, fb, ex, ey, &setup, k),
    }
}

#[allow(clippy::too_many_arguments)]
/// r of polygon offset (3.5.5): the smallest difference in window depth
/// guaranteed to be resolvable. Vertices reach window coordinates through
/// f32 clip coordinates, so near the near plane two depths 1/2^24 apart
/// can round to the same value: r is two steps of the 24-bit depth buffer,
/// as measured by piglit's gl-1.4-polygon-offset (its "ideal MRD" here).
pub const OFFSET_UNIT: f64 = 2.0 / crate::framebuffer::DEPTH_MAX as f64;

pub(crate) fn planes(rs: &RenderState, v: [&WindowVertex; 3], ex: [i64; 3], ey: [i64; 3], flat_color: Vec4, back: bool, front_facing: bool) -> TriangleSetup {
    planes_of(rs, v.map(|w| (w.z, w.q)), v, ex, ey, flat_color, back, front_facing)
}

/// The planes of a positively oriented triangle: window depth and 1/w
/// per vertex in `zq`, the other attributes from `v`.
#[allow(clippy::too_many_arguments)]
#[inline]
pub(crate) fn planes_of<P: SetupParams, A: Attributes>(rs: &P, zq: [(f64, f64); 3], v: [&A; 3], ex: [i64; 3], ey: [i64; 3], flat_color: Vec4, back: bool, front_facing: bool) -> TriangleSetup {
    let inv = 1.0 / ONE as f64;
    let x = ex.map(|c| c as f64 * inv);
    let y = ey.map(|c| c as f64 * inv);
    let (dx1, dy1, dx2, dy2) = (x[1] - x[0], y[1] - y[0], x[2] - x[0], y[2] - y[0]);
    let det = dx1 * dy2 - dx2 * dy1;
    let plane = |a: [f64; 3]| {
        let (da1, da2) = (a[1] - a[0], a[2] - a[0]);
        Plane { a0: a[0], dx: (da1 * dy2 - da2 * dy1) / det, dy: (da2 * dx1 - da1 * dx2) / det }
    };
    let q = zq.map(|p| p.1);
    let perspective = !(q[0] == q[1] && q[1] == q[2]);
    let (flat, color) = if rs.flat() {
        (Some(super::fragment::color_to_u8(flat_color)), [Plane::default(); 4])
    } else {
        let s = if perspective { q } else { [1.0; 3] };
        // Written out: `[0, 1, 2].map` with this closure stayed an
        // out-of-line call copying the colours through memory.
        let c = if back { [v[0].back_color(), v[1].back_color(), v[2].back_color()] } else { [v[0].color(), v[1].color(), v[2].color()] }.map(|c| c.to_array());
        (None, std::array::from_fn(|ch| plane([c[0][ch] as f64 * s[0], c[1][ch] as f64 * s[1], c[2][ch] as f64 * s[2]])))
    };
    let mut z = plane(zq.map(|p| p.0));
    if let Some((factor, units)) = rs.offset_fill() {
        // Polygon offset (3.5.5): m * factor + r * units, with m the
        // largest depth slope and r the depth buffer's resolution.
        let m = z.dx.abs().max(z.dy.abs());
        z.a0 += m * factor as f64 + units as f64 * OFFSET_UNIT;
    }
    let tex = rs.texture().map(|stage| {
        let mut planes = [[Plane::default(); 4]; super::texture::MAX_UNITS];
        for &u in &stage.active {
            for (c, p) in planes[u].iter_mut().enumerate() {
                *p = plane([0, 1, 2].map(|i| v[i].tex(u)[c] as f64 * q[i]));
            }
        }
        Box::new(TexPlanes { stage: stage.clone(), planes })
    });
    let fog = rs.fog().map(|f| (plane([0, 1, 2].map(|i| v[i].fog() as f64 * if perspective { q[i] } else { 1.0 })), f));
    let secondary = (rs.color_sum() && tex.is_some())
        .then(|| [0, 1, 2].map(|ch| plane([0, 1, 2].map(|i| if back { v[i].back_secondary() } else { v[i].secondary() }[ch] as f64 * if perspective { q[i] } else { 1.0 }))));
    TriangleSetup {
        tex,
        fog,
        secondary,
        x0: x[0],
        y0: y[0],
        z,
        q: plane(q),
        color,
        perspective,
        flat,
        front_facing,
    }
}
