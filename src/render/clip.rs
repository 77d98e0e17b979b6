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
use glam::Vec4;

/// Guard band, in multiples of the view volume's half-width.
pub const GUARD: f32 = 16.0;
/// Smallest w kept after clipping.
pub(crate) const W_MIN: f32 = 1e-20;

/// A clipping plane in clip coordinates: inside where n . p >= d.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Plane {
    pub n: Vec4,
    pub d: f32,
}

impl Plane {
    #[inline]
    pub fn dist(&self, p: &Vec4) -> f32 {
        self.n.dot(*p) - self.d
    }
}

const fn plane(x: f32, y: f32, z: f32, w: f32, d: f32) -> Plane {
    Plane { n: Vec4::new(x, y, z, w), d }
}

/// The planes every primitive is clipped against: near (z >= -w), far
/// (z <= w), w >= W_MIN, and the guard band in x and y. User clip planes
/// (glClipPlane, in clip coordinates) follow them in `RenderState`.
pub const FIXED_PLANES: [Plane; 7] = [
    plane(0.0, 0.0, 1.0, 1.0, 0.0),
    plane(0.0, 0.0, -1.0, 1.0, 0.0),
    plane(0.0, 0.0, 0.0, 1.0, W_MIN),
    plane(1.0, 0.0, 0.0, GUARD, 0.0),
    plane(-1.0, 0.0, 0.0, GUARD, 0.0),
    plane(0.0, 1.0, 0.0, GUARD, 0.0),
    plane(0.0, -1.0, 0.0, GUARD, 0.0),
];

/// A clipped polygon: at most 3 + one vertex per plane.
pub struct Polygon {
    pub verts: Vec<ClipVertex>,
    scratch: Vec<ClipVertex>,
}

impl Polygon {
    /// Empty, with nothing allocated: most triangles are trivially inside
    /// or outside and never use it (no allocation per primitive).
    pub fn new() -> Polygon {
        Polygon { verts: Vec::new(), scratch: Vec::new() }
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
fn outcode(planes: &[Plane], p: &Vec4) -> u32 {
    let mut code = 0;
    for (i, plane) in planes.iter().enumerate() {
        // `!(x >= 0)` also catches NaN.
        if !(plane.dist(p) >= 0.0) {
            code |= 1 << i;
        }
    }
    code
}

/// Is `p` finite and inside every plane of [`FIXED_PLANES`]? The same
/// decision as their outcode (each distance is the same single rounding
/// of the same two terms, the zero terms adding nothing) without the dot
/// products: most vertices pass it, and a triangle of three such vertices
/// needs no clipping when there are no user clip planes.
#[inline(always)]
pub fn inside_fixed(p: Vec4) -> bool {
    let [x, y, z, w] = p.to_array();
    let g = GUARD * w;
    // The eight tests as two 4-wide compares with zero: w - z is
    // (-z) + w, the same single rounding; `w < inf` is inf - w >= 0 (inf
    // for finite w, NaN for +inf and NaN, so false exactly when the
    // comparison is). A NaN anywhere fails its lane.
    let a = Vec4::new(z, -z, x, -x) + Vec4::new(w, w, g, g);
    let b = Vec4::new(y, -y, w, f32::INFINITY) + Vec4::new(g, g, -W_MIN, -w);
    (a.cmpge(Vec4::ZERO) & b.cmpge(Vec4::ZERO)).all()
}

/// Clips a triangle. Vertices with NaN or infinite coordinates reject it.
pub fn clip_triangle(planes: &[Plane], v: [&ClipVertex; 3], out: &mut Polygon) -> Outcome {
    if !v.iter().all(|cv| cv.pos.is_finite()) {
        return Outcome::Rejected;
    }
    let codes = v.map(|cv| outcode(planes, &cv.pos));
    if codes[0] | codes[1] | codes[2] == 0 {
        return Outcome::Inside;
    }
    if codes[0] & codes[1] & codes[2] != 0 {
        return Outcome::Rejected;
    }
    out.verts.clear();
    out.verts.extend(v.iter().map(|cv| **cv));
    let all = codes[0] | codes[1] | codes[2];
    for (i, plane) in planes.iter().enumerate() {
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
fn clip_polygon_to_plane(poly: &mut Polygon, plane: &Plane) {
    let Polygon { verts, scratch } = poly;
    scratch.clear();
    let n = verts.len();
    for i in 0..n {
        let a = &verts[i];
        let b = &verts[(i + 1) % n];
        let da = plane.dist(&a.pos);
        let db = plane.dist(&b.pos);
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
            let mut v = ClipVertex::lerp(inside, outside, t);
            // Leaving the half-space, the new vertex starts an edge along
            // the plane (never a boundary edge); entering, it continues
            // the original edge a->b.
            v.edge = !a_in && a.edge;
            scratch.push(v);
        }
    }
    std::mem::swap(verts, scratch);
}

#[cfg(test)]
mod tests {
    use super::*;

    fn v(p: [f32; 4]) -> ClipVertex {
        ClipVertex { pos: Vec4::from_array(p), color: Vec4::ONE, back_color: Vec4::ONE, edge: true, tex: Default::default(), fog: 0.0, secondary: Vec4::ZERO, back_secondary: Vec4::ZERO, inside: false, win: [0.0; 4], snapped: [0; 2] }
    }

    /// `inside_fixed` agrees with the outcodes of FIXED_PLANES and the
    /// finiteness test on random, extreme and non-finite positions.
    #[test]
    fn inside_fixed_matches_outcodes() {
        let mut seed = 7u64;
        let specials = [0.0, -0.0, 1.0, -1.0, W_MIN, 16.0, -16.0, f32::MAX, f32::MIN, 3e37, f32::INFINITY, f32::NEG_INFINITY, f32::NAN, 1e-30];
        let mut r = |k: u32| {
            seed = seed.wrapping_mul(6364136223846793005).wrapping_add(1442695040888963407);
            let u = (seed >> 40) as usize;
            if k.is_multiple_of(3) { specials[u % specials.len()] } else { ((u as f32 / (1u64 << 24) as f32) - 0.5) * 40.0 }
        };
        let (mut inside, mut outside) = (0, 0);
        for k in 0..200_000u32 {
            let p = Vec4::new(r(k), r(k / 2), r(k / 3), r(k / 5));
            let expect = p.is_finite() && outcode(&FIXED_PLANES, &p) == 0;
            assert_eq!(inside_fixed(p), expect, "{p:?}");
            if expect { inside += 1 } else { outside += 1 }
        }
        assert!(inside > 1000 && outside > 1000, "{inside} {outside}");
    }

    /// Two triangles sharing the edge (a, b), traversed in opposite
    /// directions, get bit-identical new vertices where clipping cuts it.
    #[test]
    fn shared_edges_get_identical_clip_vertices() {
        let mut seed = 1u64;
        let mut r = || {
            seed = seed.wrapping_mul(6364136223846793005).wrapping_add(1442695040888963407);
            ((seed >> 40) as f32 / (1u64 << 24) as f32 - 0.5) * 60.0
        };
        let mut checked = 0;
        for _ in 0..2000 {
            let a = v([r(), r(), r(), r()]);
            let b = v([r(), r(), r(), r()]);
            let c = v([r(), r(), r(), r()]);
            let d = v([r(), r(), r(), r()]);
            let (mut p1, mut p2) = (Polygon::new(), Polygon::new());
            let o1 = clip_triangle(&FIXED_PLANES, [&a, &b, &c], &mut p1);
            let o2 = clip_triangle(&FIXED_PLANES, [&b, &a, &d], &mut p2);
            if !matches!(o1, Outcome::Clipped) || !matches!(o2, Outcome::Clipped) {
                continue;
            }
            // Points of each result that lie on segment ab (not endpoints).
            let on_ab = |p: &Polygon| -> Vec<[u32; 4]> {
                p.verts
                    .iter()
                    .filter(|x| x.pos != a.pos && x.pos != b.pos)
                    .filter(|x| {
                        let (ab, ax) = (b.pos - a.pos, x.pos - a.pos);
                        let t = ax.dot(ab) / ab.dot(ab);
                        (a.pos + ab * t - x.pos).length() < 1e-3 * ab.length()
                    })
                    .map(|x| x.pos.to_array().map(f32::to_bits))
                    .collect()
            };
            let (s1, s2) = (on_ab(&p1), on_ab(&p2));
            for x in &s1 {
                let near_miss = s2.iter().any(|y| {
                    let (fx, fy) = (x.map(f32::from_bits), y.map(f32::from_bits));
                    y != x && (0..4).all(|i| (fx[i] - fy[i]).abs() < 1e-3)
                });
                assert!(!near_miss, "near-identical but different clip vertices {x:?} on a shared edge");
                checked += 1;
            }
        }
        assert!(checked > 50, "too few shared-edge clips exercised: {checked}");
    }
}
