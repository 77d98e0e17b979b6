//! Primitive clipping (GL 1.5 section 2.12) in homogeneous clip space.
//!
//! The near and far planes are clipped exactly, as the spec requires. The
//! x and y planes are clipped only against a guard band GUARD times wider
//! than the view volume: the rasterizer restricts pixels to the viewport
//! anyway, which gives the same pixels as clipping to it (viewport edges are
//! integers, pixel centres half-integers), and most triangles that cross a
//! viewport edge then need no new vertices. A last plane w >= W_MIN keeps
//! the perspective division finite. Together they bound window coordinates,
//! which keeps the fixed-point setup exact (see `setup`).
//!
//! New vertices on an edge are always computed from the edge's inside
//! endpoint towards its outside one, so two triangles sharing a clipped edge
//! get bit-identical vertices there: no cracks.

use super::vertex::ClipVertex;

/// Guard band, in multiples of the view volume's half-width.
pub const GUARD: f32 = 16.0;
/// Smallest w kept after clipping.
const W_MIN: f32 = 1e-20;

/// The planes, as functions that are >= 0 inside.
const PLANES: [fn(&glam::Vec4) -> f32; 7] = [
    |p| p.w + p.z,           // near: z >= -w
    |p| p.w - p.z,           // far: z <= w
    |p| p.w - W_MIN,         // w > 0
    |p| GUARD * p.w + p.x,   // guard band left
    |p| GUARD * p.w - p.x,   // guard band right
    |p| GUARD * p.w + p.y,   // guard band bottom
    |p| GUARD * p.w - p.y,   // guard band top
];

/// A clipped polygon: at most 3 + one vertex per plane.
pub struct Polygon {
    pub verts: Vec<ClipVertex>,
    scratch: Vec<ClipVertex>,
}

impl Polygon {
    pub fn new() -> Polygon {
        Polygon { verts: Vec::with_capacity(10), scratch: Vec::with_capacity(10) }
    }
}

impl Default for Polygon {
    fn default() -> Self {
        Self::new()
    }
}

pub enum Outcome {
    /// Entirely outside some plane, or not a finite triangle.
    Rejected,
    /// Needs no clipping: draw the input as it is.
    Inside,
    /// Clipped: draw `Polygon::verts` as a convex fan.
    Clipped,
}

#[inline]
fn outcode(p: &glam::Vec4) -> u32 {
    let mut code = 0;
    for (i, plane) in PLANES.iter().enumerate() {
        // `!(x >= 0)` also catches NaN.
        if !(plane(p) >= 0.0) {
            code |= 1 << i;
        }
    }
    code
}

/// Clips a triangle. Vertices with NaN or infinite coordinates reject it.
pub fn clip_triangle(v: [&ClipVertex; 3], out: &mut Polygon) -> Outcome {
    if !v.iter().all(|cv| cv.pos.is_finite()) {
        return Outcome::Rejected;
    }
    let codes = v.map(|cv| outcode(&cv.pos));
    if codes[0] | codes[1] | codes[2] == 0 {
        return Outcome::Inside;
    }
    if codes[0] & codes[1] & codes[2] != 0 {
        return Outcome::Rejected;
    }
    out.verts.clear();
    out.verts.extend(v.iter().map(|cv| **cv));
    let all = codes[0] | codes[1] | codes[2];
    for (i, plane) in PLANES.iter().enumerate() {
        if all & (1 << i) == 0 {
            continue;
        }
        clip_polygon_to_plane(out, plane);
        if out.verts.len() < 3 {
            return Outcome::Rejected;
        }
    }
    Outcome::Clipped
}

/// Sutherland-Hodgman against one plane.
fn clip_polygon_to_plane(poly: &mut Polygon, plane: &fn(&glam::Vec4) -> f32) {
    let Polygon { verts, scratch } = poly;
    scratch.clear();
    let n = verts.len();
    for i in 0..n {
        let a = &verts[i];
        let b = &verts[(i + 1) % n];
        let da = plane(&a.pos);
        let db = plane(&b.pos);
        let a_in = da >= 0.0;
        let b_in = db >= 0.0;
        if a_in {
            scratch.push(*a);
        }
        if a_in != b_in {
            // Always interpolate from the inside endpoint: canonical, so a
            // shared edge yields the same point from either triangle.
            let (inside, outside, di, dout) = if a_in { (a, b, da, db) } else { (b, a, db, da) };
            let t = di / (di - dout);
            scratch.push(ClipVertex::lerp(inside, outside, t));
        }
    }
    std::mem::swap(verts, scratch);
}
