//! Antialiasing by coverage (GL 1.5 section 3.2, and the antialiasing
//! parts of 3.3 for points, 3.4.2 for lines, 3.5.3 for polygons): in RGBA
//! mode an antialiased primitive produces a fragment for
//! every pixel square its ideal shape meets, and the fragment's alpha is
//! multiplied by the area of that intersection (its coverage, in [0, 1]).
//!
//! The ideal shapes:
//! - a point: the disc of the smooth point size's diameter centred on the
//!   point's window position;
//! - a line: the rectangle of the line's width centred on the segment, as
//!   long as the segment (no end caps); with stipple, the segment is cut
//!   into 1 x width rectangles counted from the stipple counter, and only
//!   those whose pattern bit is set belong to the shape;
//! - a polygon: the triangle itself (a quad or polygon is drawn as the
//!   triangles primitive assembly makes of it, so their shared diagonals
//!   take two partial fragments, which GL_SRC_ALPHA_SATURATE blending adds
//!   up to full coverage).
//!
//! Coverage quality follows the primitive's smooth hint ([`Quality`]):
//! - GL_NICEST and GL_DONT_CARE: exact. Convex shapes (rectangles,
//!   triangles) are clipped to the pixel square (Sutherland-Hodgman in f64)
//!   and the piece's area taken by the shoelace formula; the disc's area in
//!   a square is the closed form of the integral of its chord length
//!   (`disc_area`). The error is f64 rounding, below 1e-9 per pixel, far
//!   under the 1/510 that would change an 8-bit alpha.
//! - GL_FASTEST: a 4 x 4 grid of samples at ((i + 1/2) / 4, (j + 1/2) / 4)
//!   in each pixel; coverage is the fraction of samples inside. Coverage is
//!   then a multiple of 1/16. For one straight edge across a pixel the
//!   error is about 1/8 at worst (an edge parallel to a row of 4 samples,
//!   halfway between two rows); over 20000 random edges the unit test
//!   measures worst 0.122 and mean 0.026 (alpha off by up to 31 and 7 on
//!   average, in 8 bits). Thin shapes (a corner, a line narrower than a
//!   pixel) can be off more: a shape between samples gets no fragment.
//!
//! The fast path (not `SOFTGL_REFERENCE`) draws unstippled smooth lines
//! with [`LineRect`]'s closed form, the exact area under every hint: at
//! GL_FASTEST it is both cheaper and closer than the 16 samples.
//!
//! Only squares with coverage > 0 produce a fragment: a square that touches
//! the shape along an edge or corner would otherwise write its colour with
//! alpha 0 when blending is off.
//!
//! Sizes: smooth point sizes and line widths are quantized to multiples of
//! [`GRANULARITY`] within [[`MIN_SIZE`], [`MAX_SIZE`]], which is what
//! GL_SMOOTH_POINT_SIZE_RANGE/GRANULARITY and GL_SMOOTH_LINE_WIDTH_RANGE/
//! GRANULARITY report. Geometry is snapped to 1/256 pixel first, like the
//! aliased rasterizers, so a smooth and an aliased primitive start from the
//! same window coordinates.
//!
//! Fragment attributes: points take the vertex's; lines take the value at
//! t of the pixel centre projected on the segment (3.4.2 equation 3.1,
//! clamped to [0, 1]); polygons take their planes evaluated at the pixel
//! centre even when it lies outside (colours clamp, depth clamps to the
//! depth range).

use super::fragment;
use super::setup::{self, WindowVertex, ONE};
use super::RenderState;
use crate::framebuffer::{Framebuffer, Rect};
use glam::Vec4;

/// Granularity of smooth point sizes and line widths.
pub const GRANULARITY: f32 = 1.0 / 16.0;
/// Smallest and largest smooth point size / line width.
pub const MIN_SIZE: f32 = GRANULARITY;
pub const MAX_SIZE: f32 = 64.0;

/// How a primitive's coverage is computed (from its smooth hint).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Quality {
    /// Exact area (GL_NICEST, GL_DONT_CARE).
    Exact,
    /// 16 samples per pixel (GL_FASTEST).
    Sampled,
}

impl Quality {
    pub fn from_hint(hint: u32) -> Quality {
        if hint == crate::gl::enums::GL_FASTEST {
            Quality::Sampled
        } else {
            Quality::Exact
        }
    }
}

/// The antialiasing state the rasterizers read (from validation).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct SmoothState {
    /// GL_POINT_SMOOTH / GL_LINE_SMOOTH / GL_POLYGON_SMOOTH, with the
    /// quality their hints ask for.
    pub point: Option<Quality>,
    pub line: Option<Quality>,
    pub polygon: Option<Quality>,
    /// GL_POINT_FADE_THRESHOLD_SIZE.
    pub fade_threshold: f32,
}

impl Default for SmoothState {
    fn default() -> Self {
        SmoothState { point: None, line: None, polygon: None, fade_threshold: 1.0 }
    }
}

/// A requested smooth size or width as rasterized: clamped to the smooth
/// range and rounded to the granularity.
pub fn smooth_size(s: f32) -> f64 {
    let s = if s.is_nan() { 1.0 } else { s.clamp(MIN_SIZE, MAX_SIZE) };
    ((s / GRANULARITY).round() * GRANULARITY) as f64
}

/// A point's width and alpha factor after the GL 1.4 fade (3.3): a derived
/// size below the fade threshold is drawn at the threshold's size with its
/// alpha scaled by (size / threshold)^2. softgl applies it to smooth
/// points, whose coverage antialiasing plays the part the spec gives
/// multisampling.
pub fn faded_point(size: f32, threshold: f32) -> (f64, f32) {
    if size < threshold {
        let f = size.max(0.0) / threshold;
        (smooth_size(threshold), f * f)
    } else {
        (smooth_size(size), 1.0)
    }
}

pub type P = (f64, f64);

/// A small convex polygon (clipping a triangle or rectangle by four axis
/// planes adds at most four vertices).
#[derive(Clone, Copy)]
struct Poly {
    v: [P; 12],
    n: usize,
}

impl Poly {
    fn from(pts: &[P]) -> Poly {
        let mut p = Poly { v: [(0.0, 0.0); 12], n: pts.len().min(12) };
        p.v[..p.n].copy_from_slice(&pts[..p.n]);
        p
    }

    fn pts(&self) -> &[P] {
        &self.v[..self.n]
    }

    /// The part where coord(axis) >= bound (keep_above) or <= bound.
    /// Axis and side are constants (no per-vertex branching on them), the
    /// next vertex is found without a division; the arithmetic and the
    /// output order are the plain Sutherland-Hodgman step's, so the pieces
    /// and their areas are the same to the bit.
    #[inline(always)]
    fn clip<const AXIS: usize, const ABOVE: bool>(&self, bound: f64) -> Poly {
        let mut out = Poly { v: [(0.0, 0.0); 12], n: 0 };
        let c = |p: P| if AXIS == 0 { p.0 } else { p.1 };
        let d = |p: P| if ABOVE { c(p) - bound } else { bound - c(p) };
        let n = self.n;
        for i in 0..n {
            let a = self.v[i];
            let b = if i + 1 == n { self.v[0] } else { self.v[i + 1] };
            let (da, db) = (d(a), d(b));
            if da >= 0.0 {
                out.push(a);
            }
            if (da >= 0.0) != (db >= 0.0) {
                let t = da / (da - db);
                let mut q = (a.0 + (b.0 - a.0) * t, a.1 + (b.1 - a.1) * t);
                // Exactly on the bound (no drift out of the slab).
                if AXIS == 0 {
                    q.0 = bound
                } else {
                    q.1 = bound
                }
                out.push(q);
            }
        }
        out
    }

    fn push(&mut self, p: P) {
        if self.n < self.v.len() {
            self.v[self.n] = p;
            self.n += 1;
        }
    }

    fn area(&self) -> f64 {
        let mut s = 0.0;
        let n = self.n;
        for i in 0..n {
            let (a, b) = (self.v[i], if i + 1 == n { self.v[0] } else { self.v[i + 1] });
            s += a.0 * b.1 - b.0 * a.1;
        }
        (s * 0.5).abs()
    }
}

/// Is `p` inside the counter-clockwise convex polygon `poly` (edges
/// included)?
#[inline]
pub fn inside_convex(poly: &[P], p: P) -> bool {
    let n = poly.len();
    (0..n).all(|i| {
        let (a, b) = (poly[i], if i + 1 == n { poly[0] } else { poly[i + 1] });
        (b.0 - a.0) * (p.1 - a.1) - (b.1 - a.1) * (p.0 - a.0) >= 0.0
    })
}

/// [`inside_convex`]'s edges with their direction vectors computed once
/// (the same products and sums per test, so the same answers).
struct Edges {
    /// (start, b - a) per edge.
    e: [(P, P); 12],
    n: usize,
}

impl Edges {
    fn of(poly: &[P]) -> Edges {
        let mut e = [((0.0, 0.0), (0.0, 0.0)); 12];
        let n = poly.len().min(12);
        for i in 0..n {
            let (a, b) = (poly[i], if i + 1 == poly.len() { poly[0] } else { poly[i + 1] });
            e[i] = (a, (b.0 - a.0, b.1 - a.1));
        }
        Edges { e, n }
    }

    #[inline(always)]
    fn inside(&self, p: P) -> bool {
        self.e[..self.n].iter().all(|&(a, d)| d.0 * (p.1 - a.1) - d.1 * (p.0 - a.0) >= 0.0)
    }
}

/// The fraction of the 4 x 4 samples of pixel (px, py) inside a shape.
fn sampled(px: i64, py: i64, inside: &impl Fn(f64, f64) -> bool) -> f64 {
    let mut n = 0;
    for j in 0..4 {
        for i in 0..4 {
            if inside(px as f64 + (i as f64 + 0.5) / 4.0, py as f64 + (j as f64 + 0.5) / 4.0) {
                n += 1;
            }
        }
    }
    n as f64 / 16.0
}

/// Visits every pixel of `rect` that the counter-clockwise convex polygon
/// `poly` covers with area > 0 (by `quality`; `inside` is the shape's
/// point test for sampling), row by row, with its coverage.
pub fn convex_pixels(poly: &[P], rect: Rect, quality: Quality, inside: impl Fn(f64, f64) -> bool, mut emit: impl FnMut(i64, i64, f64)) {
    if poly.len() < 3 || rect.is_empty() || poly.iter().any(|p| !p.0.is_finite() || !p.1.is_finite()) {
        return;
    }
    let shape = Poly::from(poly);
    let edges = Edges::of(poly);
    let ymin = poly.iter().map(|p| p.1).fold(f64::INFINITY, f64::min);
    let ymax = poly.iter().map(|p| p.1).fold(f64::NEG_INFINITY, f64::max);
    let row0 = (ymin.floor() as i64).max(rect.y0 as i64);
    let row1 = (ymax.ceil() as i64).min(rect.y1 as i64);
    for py in row0..row1 {
        let slab = shape.clip::<1, true>(py as f64).clip::<1, false>(py as f64 + 1.0);
        if slab.n < 3 {
            continue;
        }
        let xmin = slab.pts().iter().map(|p| p.0).fold(f64::INFINITY, f64::min);
        let xmax = slab.pts().iter().map(|p| p.0).fold(f64::NEG_INFINITY, f64::max);
        let col0 = (xmin.floor() as i64).max(rect.x0 as i64);
        let col1 = (xmax.ceil() as i64).min(rect.x1 as i64);
        for px in col0..col1 {
            let cov = match quality {
                // A square whose corners are all inside a convex shape is
                // covered (by area and by every sample): the interior costs
                // four corner tests, not a clip or 16 samples.
                _ if [(0, 0), (1, 0), (0, 1), (1, 1)].iter().all(|&(i, j)| edges.inside(((px + i) as f64, (py + j) as f64))) => 1.0,
                Quality::Exact => slab.clip::<0, true>(px as f64).clip::<0, false>(px as f64 + 1.0).area().min(1.0),
                Quality::Sampled => sampled(px, py, &inside),
            };
            if cov > 0.0 {
                emit(px, py, cov);
            }
        }
    }
}

/// The rectangle of an unstippled smooth line (3.4.2), with its exact
/// coverage in closed form instead of clipping (the fast path; the
/// reference path runs [`convex_pixels`] on the same corners).
///
/// A pixel square is classified by its centre's coordinates along the
/// segment (`along`, from the start) and across it (`across`): the square
/// projects on either axis of the rectangle to an interval of half length
/// h = (|ux| + |uy|) / 2 around them. Squares wholly beyond a side get no
/// fragment; squares wholly between the two end caps are cut only by the
/// two long sides, so their coverage is C(hw - across) - C(-hw - across),
/// where C(s) is the area of the unit square on the inner side of a line at
/// signed distance s from its centre: the distribution function of the sum
/// of two uniform variables of widths |ux| and |uy| (a quadratic, linear,
/// quadratic piece). The few squares a cap crosses are clipped exactly, in
/// coordinates relative to the square.
///
/// Precision: `along` and `across` are two products and a sum of exact
/// differences (pixel centres and snapped endpoints are multiples of 1/256),
/// so they are within about 2^-52 times the line's length of the real
/// values; C is evaluated near [0, 1]. The coverage is within about 1e-13
/// of the exact area for lines up to a few thousand pixels, closer than
/// [`convex_pixels`], whose shoelace sums products of absolute window
/// coordinates (about 1e-10 there; `tests::line_rect_*` measures both
/// against a double-double evaluation). Coverages below [`COVERAGE_FLOOR`]
/// (squares touching the rectangle, up to rounding) produce no fragment.
pub struct LineRect {
    x: f64,
    y: f64,
    ux: f64,
    uy: f64,
    len: f64,
    hw: f64,
    /// (|ux| + |uy|) / 2 and (max - min) / 2 of |ux|, |uy|.
    h: f64,
    hd: f64,
    /// 1 / max(|ux|, |uy|) and 1 / (2 |ux| |uy|) (0 when the line is
    /// axis-aligned: the quadratic pieces are then empty).
    inv_a: f64,
    inv_2ab: f64,
    corners: [P; 4],
    /// The four sides as `cols` cuts them to a row.
    sides: [Side; 4],
    /// `row_coverage` runs `row_avx2` (the CPU has AVX2).
    #[cfg_attr(not(target_arch = "x86_64"), allow(dead_code))]
    avx2: bool,
}

/// A side of a [`LineRect`] for [`LineRect::cols`]: its y extent, and x
/// as a function of y (`x0 + (y - y0) * slope`), or its x extent when it
/// is (nearly) horizontal.
#[derive(Clone, Copy)]
struct Side {
    ylo: f64,
    yhi: f64,
    x0: f64,
    y0: f64,
    slope: f64,
    flat: bool,
    xlo: f64,
    xhi: f64,
}

impl Side {
    fn new(p: P, q: P) -> Side {
        let dy = q.1 - p.1;
        // Below 2^-20 of y change the whole x extent stands in for the
        // side (a superset, as `cols` allows): no huge or infinite slope.
        let flat = dy.abs() < 1.0 / (1 << 20) as f64;
        Side {
            ylo: p.1.min(q.1),
            yhi: p.1.max(q.1),
            x0: p.0,
            y0: p.1,
            slope: if flat { 0.0 } else { (q.0 - p.0) / dy },
            flat,
            xlo: p.0.min(q.0),
            xhi: p.0.max(q.0),
        }
    }
}

/// Coverage below which a square gets no fragment (fast path).
pub const COVERAGE_FLOOR: f64 = 1e-12;

impl LineRect {
    /// The rectangle of half width `hw` centred on the segment from
    /// (x, y) along (dx, dy); None for an empty or non-finite segment.
    pub fn new(x: f64, y: f64, dx: f64, dy: f64, hw: f64) -> Option<LineRect> {
        let len = (dx * dx + dy * dy).sqrt();
        if !(len > 0.0) || !len.is_finite() || !x.is_finite() || !y.is_finite() {
            return None;
        }
        let (ux, uy) = (dx / len, dy / len);
        // The corners as `line::smooth_line` computes them, so that both
        // paths visit the same rows.
        let (bx, by) = (x + ux * len, y + uy * len);
        let (nx, ny) = (-uy * hw, ux * hw);
        let corners = [(x - nx, y - ny), (bx - nx, by - ny), (bx + nx, by + ny), (x + nx, y + ny)];
        let (a, b) = (ux.abs().max(uy.abs()), ux.abs().min(uy.abs()));
        Some(LineRect {
            x,
            y,
            ux,
            uy,
            len,
            hw,
            h: (a + b) / 2.0,
            hd: (a - b) / 2.0,
            inv_a: 1.0 / a,
            inv_2ab: if b > 0.0 { 1.0 / (2.0 * a * b) } else { 0.0 },
            corners,
            sides: std::array::from_fn(|i| Side::new(corners[i], corners[(i + 1) & 3])),
            avx2: cfg!(target_arch = "x86_64") && super::fragment::simd::level() == super::fragment::simd::Level::Avx2,
        })
    }

    /// Rows of `rect` the rectangle's bounding box meets.
    pub fn rows(&self, rect: Rect) -> std::ops::Range<i64> {
        let ymin = self.corners.iter().map(|p| p.1).fold(f64::INFINITY, f64::min);
        let ymax = self.corners.iter().map(|p| p.1).fold(f64::NEG_INFINITY, f64::max);
        (ymin.floor() as i64).max(rect.y0 as i64)..(ymax.ceil() as i64).min(rect.y1 as i64)
    }

    /// Columns of `rect` that may hold covered squares of row `py`: the
    /// rectangle's x extent within the row (its edges cut to the row), a
    /// little widened against rounding (the squares beyond get coverage 0).
    pub fn cols(&self, py: i64, rect: Rect) -> std::ops::Range<i64> {
        let (y0, y1) = (py as f64, py as f64 + 1.0);
        let (mut xmin, mut xmax) = (f64::INFINITY, f64::NEG_INFINITY);
        // Each side's x where it enters and leaves the row (its y extent
        // cut to the row): slopes from `new`, no division per row. The x
        // values may differ from the exact cut by a few ulps of the
        // coordinates, far inside the margin below.
        for e in &self.sides {
            if e.yhi < y0 || e.ylo > y1 {
                continue;
            }
            let (a, b) = if e.flat {
                (e.xlo, e.xhi)
            } else {
                (e.x0 + (y0.max(e.ylo) - e.y0) * e.slope, e.x0 + (y1.min(e.yhi) - e.y0) * e.slope)
            };
            // Plain compares (f64::min/max add NaN handling; nothing is NaN).
            let (a, b) = if a < b { (a, b) } else { (b, a) };
            xmin = if a < xmin { a } else { xmin };
            xmax = if b > xmax { b } else { xmax };
        }
        if !(xmin <= xmax) {
            return 0..0;
        }
        // Inline floor and ceil (the library calls cost more than the
        // rest of the row set-up); the draw rectangle bounds the result.
        let (lim0, lim1) = (rect.x0 as f64 - 1.0, rect.x1 as f64 + 1.0);
        let fit = |v: f64| if v < lim0 { lim0 } else if v > lim1 { lim1 } else { v };
        let (lo, hi) = (fit(xmin - 1e-7), fit(xmax + 1e-7));
        let (fl, ce) = (lo as i64, hi as i64);
        let fl = fl - ((fl as f64) > lo) as i64;
        let ce = ce + ((ce as f64) < hi) as i64;
        fl.max(rect.x0 as i64)..ce.min(rect.x1 as i64)
    }

    /// The area of the unit square on the inner side of a long side at
    /// signed distance `s` from the square's centre.
    #[inline(always)]
    fn half_plane(&self, s: f64) -> f64 {
        let (m, hd) = (self.h, self.hd);
        if s <= -m {
            0.0
        } else if s >= m {
            1.0
        } else if s < -hd {
            let r = s + m;
            r * r * self.inv_2ab
        } else if s > hd {
            let r = m - s;
            1.0 - r * r * self.inv_2ab
        } else {
            0.5 + s * self.inv_a
        }
    }

    /// The coverage of pixel (px, py): 0 for no fragment.
    #[inline(always)]
    pub fn coverage(&self, px: i64, py: i64) -> f64 {
        let (rx, ry) = (px as f64 + 0.5 - self.x, py as f64 + 0.5 - self.y);
        let along = rx * self.ux + ry * self.uy;
        let across = ry * self.ux - rx * self.uy;
        let h = self.h;
        if across.abs() >= self.hw + h || along <= -h || along >= self.len + h {
            return 0.0;
        }
        let c = if along >= h && along <= self.len - h {
            self.half_plane(self.hw - across) - self.half_plane(-self.hw - across)
        } else {
            self.clipped(px, py)
        };
        if c > COVERAGE_FLOOR {
            c.min(1.0)
        } else {
            0.0
        }
    }

    /// [`coverage`](Self::coverage) of pixels `cols` of row `py`: the
    /// same bits, four pixels at a time where the CPU has AVX2
    /// (`fragment::simd::level`, read once per rectangle). `buf` is
    /// scratch space, grown as needed.
    #[inline]
    pub fn row_coverage<'b>(&self, py: i64, cols: std::ops::Range<i64>, buf: &'b mut Vec<f64>) -> &'b [f64] {
        let n = (cols.end - cols.start).max(0) as usize;
        // Whole groups of four (the lanes past the row are not returned).
        let n4 = (n + 3) & !3;
        if buf.len() < n4 {
            buf.resize(n4, 0.0);
        }
        #[cfg(target_arch = "x86_64")]
        if self.avx2 {
            // SAFETY: AVX2 is present (`new`), `buf` holds whole groups.
            unsafe { row_avx2::coverage(self, py, cols.start, &mut buf[..n4]) };
            return &buf[..n];
        }
        for (c, px) in buf.iter_mut().zip(cols) {
            *c = self.coverage(px, py);
        }
        &buf[..n]
    }

    /// The exact area of the rectangle within square (px, py), clipped in
    /// the square's own coordinates.
    fn clipped(&self, px: i64, py: i64) -> f64 {
        let (ox, oy) = (px as f64, py as f64);
        let rel = self.corners.map(|p| (p.0 - ox, p.1 - oy));
        Poly::from(&rel).clip::<0, true>(0.0).clip::<0, false>(1.0).clip::<1, true>(0.0).clip::<1, false>(1.0).area()
    }
}

/// [`LineRect::coverage`] four pixels at a time: the same operations in
/// the same order on each lane (no fused multiply-add), the branches of
/// `half_plane` as selections made in reverse priority, so every lane
/// holds the scalar bits; squares a cap crosses go to the scalar code.
#[cfg(target_arch = "x86_64")]
mod row_avx2 {
    use super::{LineRect, COVERAGE_FLOOR};
    use std::arch::x86_64::*;

    /// C(s) of `LineRect::half_plane` on four lanes.
    #[inline(always)]
    unsafe fn half_plane(lr: &LineRect, s: __m256d) -> __m256d {
        let (m, hd) = (_mm256_set1_pd(lr.h), _mm256_set1_pd(lr.hd));
        let inv_2ab = _mm256_set1_pd(lr.inv_2ab);
        let lin = _mm256_add_pd(_mm256_set1_pd(0.5), _mm256_mul_pd(s, _mm256_set1_pd(lr.inv_a)));
        let r1 = _mm256_add_pd(s, m);
        let q1 = _mm256_mul_pd(_mm256_mul_pd(r1, r1), inv_2ab);
        let r2 = _mm256_sub_pd(m, s);
        let q2 = _mm256_sub_pd(_mm256_set1_pd(1.0), _mm256_mul_pd(_mm256_mul_pd(r2, r2), inv_2ab));
        let mut c = _mm256_blendv_pd(lin, q2, _mm256_cmp_pd::<_CMP_GT_OQ>(s, hd));
        c = _mm256_blendv_pd(c, q1, _mm256_cmp_pd::<_CMP_LT_OQ>(s, _mm256_set1_pd(-lr.hd)));
        c = _mm256_blendv_pd(c, _mm256_set1_pd(1.0), _mm256_cmp_pd::<_CMP_GE_OQ>(s, m));
        _mm256_andnot_pd(_mm256_cmp_pd::<_CMP_LE_OQ>(s, _mm256_set1_pd(-lr.h)), c)
    }

    /// Coverages of pixels x0, x0 + 1, ... of row `py` into `out`
    /// (`out.len()` a multiple of 4).
    #[target_feature(enable = "avx2")]
    pub(super) unsafe fn coverage(lr: &LineRect, py: i64, x0: i64, out: &mut [f64]) {
        let ry = py as f64 + 0.5 - lr.y;
        let (ry_ux, ry_uy) = (_mm256_set1_pd(ry * lr.ux), _mm256_set1_pd(ry * lr.uy));
        let (ux, uy, x) = (_mm256_set1_pd(lr.ux), _mm256_set1_pd(lr.uy), _mm256_set1_pd(lr.x));
        let h = lr.h;
        let (hwh, neg_h, lenh) = (_mm256_set1_pd(lr.hw + h), _mm256_set1_pd(-h), _mm256_set1_pd(lr.len + h));
        let (vh, len_h) = (_mm256_set1_pd(h), _mm256_set1_pd(lr.len - h));
        let (hw, neg_hw) = (_mm256_set1_pd(lr.hw), _mm256_set1_pd(-lr.hw));
        let abs = _mm256_castsi256_pd(_mm256_set1_epi64x(i64::MAX));
        // Pixel columns as f64 (exact: |px| < 2^53).
        let mut px = _mm256_add_pd(_mm256_set1_pd(x0 as f64), _mm256_set_pd(3.0, 2.0, 1.0, 0.0));
        for (g, chunk) in out.chunks_exact_mut(4).enumerate() {
            let rx = _mm256_sub_pd(_mm256_add_pd(px, _mm256_set1_pd(0.5)), x);
            let along = _mm256_add_pd(_mm256_mul_pd(rx, ux), ry_uy);
            let across = _mm256_sub_pd(ry_ux, _mm256_mul_pd(rx, uy));
            let outside = _mm256_or_pd(
                _mm256_cmp_pd::<_CMP_GE_OQ>(_mm256_and_pd(across, abs), hwh),
                _mm256_or_pd(_mm256_cmp_pd::<_CMP_LE_OQ>(along, neg_h), _mm256_cmp_pd::<_CMP_GE_OQ>(along, lenh)),
            );
            let interior = _mm256_and_pd(_mm256_cmp_pd::<_CMP_GE_OQ>(along, vh), _mm256_cmp_pd::<_CMP_LE_OQ>(along, len_h));
            let c = _mm256_sub_pd(half_plane(lr, _mm256_sub_pd(hw, across)), half_plane(lr, _mm256_sub_pd(neg_hw, across)));
            let c = _mm256_and_pd(_mm256_cmp_pd::<_CMP_GT_OQ>(c, _mm256_set1_pd(COVERAGE_FLOOR)), _mm256_min_pd(c, _mm256_set1_pd(1.0)));
            _mm256_storeu_pd(chunk.as_mut_ptr(), _mm256_andnot_pd(outside, c));
            // Squares a cap crosses: the scalar clip.
            let mut cap = !_mm256_movemask_pd(_mm256_or_pd(outside, interior)) & 0xF;
            while cap != 0 {
                let k = cap.trailing_zeros() as usize;
                chunk[k] = lr.coverage(x0 + (g * 4 + k) as i64, py);
                cap &= cap - 1;
            }
            px = _mm256_add_pd(px, _mm256_set1_pd(4.0));
        }
    }
}

/// ∫₀ˣ sqrt(r² - t²) dt for |x| <= r.
fn chord_integral(x: f64, r: f64) -> f64 {
    0.5 * (x * (r * r - x * x).max(0.0).sqrt() + r * r * (x / r).clamp(-1.0, 1.0).asin())
}

/// Signed area of the disc of radius r at the origin within the rectangle
/// spanned by (0, 0) and (x, y) (negative when one of x, y is).
fn corner_area(x: f64, y: f64, r: f64) -> f64 {
    let sign = if (x < 0.0) != (y < 0.0) { -1.0 } else { 1.0 };
    let (x, y) = (x.abs().min(r), y.abs().min(r));
    let a = if x * x + y * y <= r * r {
        x * y
    } else {
        // Up to xs the rectangle's top edge is inside the disc, beyond it
        // the circle bounds the region.
        let xs = (r * r - y * y).max(0.0).sqrt();
        y * xs + chord_integral(x, r) - chord_integral(xs, r)
    };
    sign * a
}

/// The exact area of the disc centred (cx, cy) of radius r within the
/// pixel square (px, py), by inclusion-exclusion of corner areas.
pub fn disc_area(cx: f64, cy: f64, r: f64, px: i64, py: i64) -> f64 {
    let (x0, y0) = (px as f64 - cx, py as f64 - cy);
    let (x1, y1) = (x0 + 1.0, y0 + 1.0);
    (corner_area(x1, y1, r) - corner_area(x0, y1, r) - corner_area(x1, y0, r) + corner_area(x0, y0, r)).clamp(0.0, 1.0)
}

/// Visits every pixel of `rect` the disc covers with area > 0.
pub fn disc_pixels(cx: f64, cy: f64, r: f64, rect: Rect, quality: Quality, mut emit: impl FnMut(i64, i64, f64)) {
    if !(r > 0.0) || rect.is_empty() || !cx.is_finite() || !cy.is_finite() {
        return;
    }
    let row0 = ((cy - r).floor() as i64).max(rect.y0 as i64);
    let row1 = ((cy + r).ceil() as i64).min(rect.y1 as i64);
    let inside = |x: f64, y: f64| (x - cx) * (x - cx) + (y - cy) * (y - cy) <= r * r;
    for py in row0..row1 {
        // The disc's half-width at the row's y nearest the centre.
        let dy = if cy < py as f64 { py as f64 - cy } else if cy > py as f64 + 1.0 { cy - py as f64 - 1.0 } else { 0.0 };
        if dy >= r {
            continue;
        }
        let h = (r * r - dy * dy).sqrt();
        let col0 = ((cx - h).floor() as i64).max(rect.x0 as i64);
        let col1 = ((cx + h).ceil() as i64).min(rect.x1 as i64);
        for px in col0..col1 {
            // The square's corner farthest from the centre.
            let (fx, fy) = ((px as f64 - cx).abs().max((px as f64 + 1.0 - cx).abs()), (py as f64 - cy).abs().max((py as f64 + 1.0 - cy).abs()));
            let cov = match quality {
                _ if fx * fx + fy * fy <= r * r => 1.0,
                Quality::Exact => disc_area(cx, cy, r, px, py),
                Quality::Sampled => sampled(px, py, &inside),
            };
            if cov > 0.0 {
                emit(px, py, cov);
            }
        }
    }
}

/// An alpha in [0, 1] (already scaled by its coverage) in 8 bits.
#[inline]
pub fn alpha_u8(a: f64) -> u8 {
    (a.clamp(0.0, 1.0) * 255.0 + 0.5) as u8
}

/// An 8-bit alpha scaled by a coverage (rounds twice: within 1 LSB).
#[inline]
pub fn scale_alpha(a: u8, cov: f64) -> u8 {
    (a as f64 * cov.clamp(0.0, 1.0) + 0.5) as u8
}

/// A filled triangle under GL_POLYGON_SMOOTH (3.5.3): facing and culling
/// as for aliased triangles, then a fragment for every pixel the triangle
/// covers, its alpha scaled by the coverage. Polygon stipple still applies
/// (by the pixel's bit).
pub fn triangle(rs: &RenderState, fb: &mut Framebuffer, w: &[WindowVertex; 3], flat_color: [Vec4; 2], quality: Quality) {
    let snap = |c: f64| (c * ONE as f64).round() as i64;
    let fx = [snap(w[0].x), snap(w[1].x), snap(w[2].x)];
    let fy = [snap(w[0].y), snap(w[1].y), snap(w[2].y)];
    let area = (fx[1] - fx[0]) as i128 * (fy[2] - fy[0]) as i128 - (fx[2] - fx[0]) as i128 * (fy[1] - fy[0]) as i128;
    if area == 0 {
        return;
    }
    let ccw = area > 0;
    let Some(front_facing) = rs.facing(ccw) else { return };
    let order = if ccw { [0, 1, 2] } else { [0, 2, 1] };
    let (ex, ey) = (order.map(|i| fx[i]), order.map(|i| fy[i]));
    let v = order.map(|i| &w[i]);
    let back = rs.two_side && !front_facing;
    let t = setup::planes(rs, v, ex, ey, flat_color[back as usize], back, front_facing);
    let inv = 1.0 / ONE as f64;
    let poly: [P; 3] = std::array::from_fn(|i| (ex[i] as f64 * inv, ey[i] as f64 * inv));
    let fs = &rs.fragment;
    convex_pixels(&poly, rs.draw_rect, quality, |x, y| inside_convex(&poly, (x, y)), |px, py, cov| {
        if let Some(pattern) = &rs.polygon_stipple {
            if pattern[py.rem_euclid(32) as usize] >> px.rem_euclid(32) & 1 == 0 {
                return;
            }
        }
        let (cx, cy) = (px as f64 + 0.5 - t.x0, py as f64 + 0.5 - t.y0);
        let mut color = fragment::reference::triangle_color(&t, cx, cy);
        color[3] = scale_alpha(color[3], cov);
        let z = t.z.a0 + t.z.dx * cx + t.z.dy * cy;
        fragment::shade_fragment(fs, fb, px as usize, py as usize, z, color);
    });
}

#[cfg(test)]
mod tests {
    use super::*;

    fn rng(seed: &mut u64) -> f64 {
        *seed = seed.wrapping_mul(6364136223846793005).wrapping_add(1442695040888963407);
        (*seed >> 11) as f64 / (1u64 << 53) as f64
    }

    const BIG: Rect = Rect { x0: -100, y0: -100, x1: 100, y1: 100 };

    /// A disc's coverages add up to its area, and agree with a fine grid.
    #[test]
    fn disc_coverage_sums_to_area() {
        let mut seed = 7;
        for _ in 0..200 {
            let (cx, cy, r) = (rng(&mut seed) * 10.0, rng(&mut seed) * 10.0, 0.05 + rng(&mut seed) * 5.0);
            let mut total = 0.0;
            disc_pixels(cx, cy, r, BIG, Quality::Exact, |px, py, c| {
                total += c;
                if r > 1.0 && (px + py) % 7 == 0 {
                    // 64 x 64 midpoint grid: error below 2 * perimeter-in-pixel / 64.
                    let mut n = 0;
                    for j in 0..64 {
                        for i in 0..64 {
                            let (x, y) = (px as f64 + (i as f64 + 0.5) / 64.0, py as f64 + (j as f64 + 0.5) / 64.0);
                            n += ((x - cx).powi(2) + (y - cy).powi(2) <= r * r) as i32;
                        }
                    }
                    assert!((n as f64 / 4096.0 - c).abs() < 0.05, "disc {cx} {cy} {r} pixel {px} {py}: {c} vs {n}");
                }
            });
            let area = std::f64::consts::PI * r * r;
            assert!((total - area).abs() < 1e-9, "disc {cx} {cy} {r}: {total} vs {area}");
        }
    }

    /// A triangle's coverages add up to its area; interior pixels are 1.
    #[test]
    fn triangle_coverage_sums_to_area() {
        let mut seed = 11;
        for _ in 0..200 {
            let mut t: Vec<P> = (0..3).map(|_| (rng(&mut seed) * 20.0 - 5.0, rng(&mut seed) * 20.0 - 5.0)).collect();
            let a2 = (t[1].0 - t[0].0) * (t[2].1 - t[0].1) - (t[2].0 - t[0].0) * (t[1].1 - t[0].1);
            if a2 < 0.0 {
                t.swap(1, 2);
            }
            let mut total = 0.0;
            convex_pixels(&t, BIG, Quality::Exact, |_, _| true, |px, py, c| {
                total += c;
                let corners = [(0, 0), (1, 0), (0, 1), (1, 1)].map(|(i, j)| ((px + i) as f64, (py + j) as f64));
                if corners.iter().all(|&p| inside_convex(&t, p)) {
                    assert!((c - 1.0).abs() < 1e-12);
                }
            });
            assert!((total - a2.abs() / 2.0).abs() < 1e-9, "{t:?}: {total} vs {}", a2.abs() / 2.0);
        }
    }

    /// GL_FASTEST's 16 samples against the exact area, on random
    /// half-planes cutting one pixel: the error bound the doc states.
    #[test]
    fn sampled_error_is_bounded() {
        let mut seed = 3;
        let (mut worst, mut sum, n) = (0.0f64, 0.0, 20000);
        for _ in 0..n {
            let ang = rng(&mut seed) * std::f64::consts::TAU;
            let (nx, ny) = (ang.cos(), ang.sin());
            let (ox, oy) = (rng(&mut seed), rng(&mut seed));
            // A big square, one side through (ox, oy) with normal (nx, ny).
            let (tx, ty) = (-ny, nx);
            let s = 10.0;
            let q: Vec<P> = vec![
                (ox - tx * s, oy - ty * s),
                (ox - tx * s - nx * s, oy - ty * s - ny * s),
                (ox + tx * s - nx * s, oy + ty * s - ny * s),
                (ox + tx * s, oy + ty * s),
            ];
            let mut q = q;
            let a2 = (q[1].0 - q[0].0) * (q[2].1 - q[0].1) - (q[2].0 - q[0].0) * (q[1].1 - q[0].1);
            if a2 < 0.0 {
                q.reverse();
            }
            let rect = Rect { x0: 0, y0: 0, x1: 1, y1: 1 };
            let (mut e, mut f) = (0.0, 0.0);
            convex_pixels(&q, rect, Quality::Exact, |_, _| true, |_, _, c| e = c);
            convex_pixels(&q, rect, Quality::Sampled, |x, y| inside_convex(&q, (x, y)), |_, _, c| f = c);
            worst = worst.max((e - f).abs());
            sum += (e - f).abs();
        }
        eprintln!("GL_FASTEST coverage error on {n} random edges: worst {worst:.4}, mean {:.4}", sum / n as f64);
        assert!(worst <= 0.13, "worst {worst}");
        assert!(sum / n as f64 <= 0.03, "mean {}", sum / n as f64);
    }

    /// A random unstippled smooth line as `line::smooth_line` sees it:
    /// start and direction on the 1/256 grid, offset by `at`.
    fn random_line(seed: &mut u64, at: f64) -> ([f64; 4], f64) {
        let q = |v: f64| (v * 256.0).round() / 256.0;
        let (x, y) = (q(at + rng(seed) * 20.0), q(at + rng(seed) * 20.0));
        let len = if rng(seed) < 0.2 { rng(seed) * 2.0 } else { rng(seed) * 25.0 };
        let ang = rng(seed) * std::f64::consts::TAU;
        // Sometimes axis-aligned or diagonal.
        let ang = match (rng(seed) * 8.0) as i32 {
            0 => (ang / std::f64::consts::FRAC_PI_4).round() * std::f64::consts::FRAC_PI_4,
            _ => ang,
        };
        let (dx, dy) = (q(len * ang.cos()), q(len * ang.sin()));
        let hw = smooth_size((rng(seed) * 7.0) as f32) / 2.0;
        ([x, y, dx, dy], hw)
    }

    /// The closed-form coverage (fast path) against the clip (reference
    /// path) on the same rectangle: the same pixels, coverages within 1e-9.
    #[test]
    fn line_rect_matches_clipped_coverage() {
        let mut seed = 19;
        let (mut pixels, mut worst) = (0, 0.0f64);
        for _ in 0..3000 {
            let ([x, y, dx, dy], hw) = random_line(&mut seed, 0.0);
            let Some(lr) = LineRect::new(x, y, dx, dy, hw) else { continue };
            let mut reference = std::collections::HashMap::new();
            convex_pixels(&lr.corners, BIG, Quality::Exact, |_, _| true, |px, py, c| {
                reference.insert((px, py), c);
            });
            let mut seen = 0;
            for py in lr.rows(BIG) {
                for px in lr.cols(py, BIG) {
                    let c = lr.coverage(px, py);
                    let r = reference.get(&(px, py)).copied().unwrap_or(0.0);
                    // A square the reference covers by less than the floor may
                    // touch the rectangle only (rounding): either answer.
                    if (c > 0.0) != (r > 0.0) && r.max(c) > 1e-9 {
                        panic!("line {x} {y} {dx} {dy} hw {hw} pixel {px},{py}: fast {c}, reference {r}");
                    }
                    seen += (c > 0.0 && r > 0.0) as usize;
                    worst = worst.max((c - r).abs());
                    assert!((c - r).abs() < 1e-9, "line {x} {y} {dx} {dy} hw {hw} pixel {px},{py}: fast {c}, reference {r}");
                }
            }
            // Every reference pixel was visited (rows and columns wide enough).
            let missed = reference.iter().filter(|(p, &c)| c > 1e-9 && !(lr.rows(BIG).contains(&p.1) && lr.cols(p.1, BIG).contains(&p.0))).count();
            assert_eq!(missed, 0, "line {x} {y} {dx} {dy} hw {hw}: pixels outside rows/cols");
            pixels += seen;
        }
        eprintln!("closed form vs clip: {pixels} pixels, worst difference {worst:e}");
        assert!(pixels > 100_000);
    }

    /// Closer to the exact area than the clip: a line moved by a whole
    /// number of pixels covers the same areas, so coverages near the
    /// origin (small coordinates, little rounding) serve as the exact
    /// values for the same line 1000 pixels away, where the clip's
    /// shoelace sums products of large coordinates.
    #[test]
    fn line_rect_is_closer_to_the_exact_area_than_the_clip() {
        let mut seed = 23;
        let (mut fast_worst, mut clip_worst, mut n) = (0.0f64, 0.0f64, 0);
        for _ in 0..1000 {
            let ([x, y, dx, dy], hw) = random_line(&mut seed, 0.0);
            let Some(near) = LineRect::new(x, y, dx, dy, hw) else { continue };
            let (ox, oy) = (1024.0 + 512.0, 768.0 + 256.0);
            let far = LineRect::new(x + ox, y + oy, dx, dy, hw).unwrap();
            let exact = |px: i64, py: i64| Poly::from(&near.corners.map(|p| (p.0 - px as f64, p.1 - py as f64))).clip::<0, true>(0.0).clip::<0, false>(1.0).clip::<1, true>(0.0).clip::<1, false>(1.0).area().min(1.0);
            let rect = Rect { x0: 0, y0: 0, x1: 4000, y1: 4000 };
            convex_pixels(&far.corners, rect, Quality::Exact, |_, _| true, |px, py, c| {
                let (nx, ny) = (px - ox as i64, py - oy as i64);
                let e = exact(nx, ny);
                clip_worst = clip_worst.max((c - e).abs());
                fast_worst = fast_worst.max((far.coverage(px, py) - e).abs());
                n += 1;
            });
        }
        eprintln!("error against the exact area at 1000 pixels from the origin, {n} pixels: closed form {fast_worst:e}, clip {clip_worst:e}");
        assert!(n > 50_000);
        assert!(fast_worst < 1e-11 && fast_worst <= clip_worst, "closed form {fast_worst:e}, clip {clip_worst:e}");
    }

    /// The four-lane row coverage holds the scalar `coverage` bits on
    /// every pixel of every row (and the lanes past a row's end are not
    /// returned), near the origin and 1000 pixels away.
    #[cfg(target_arch = "x86_64")]
    #[test]
    fn row_coverage_matches_scalar_bits() {
        if !std::arch::is_x86_feature_detected!("avx2") {
            return;
        }
        let mut seed = 31;
        let (mut pixels, mut caps) = (0usize, 0usize);
        let mut buf = vec![0.0; 4];
        const WIDE: Rect = Rect { x0: -100, y0: -100, x1: 1200, y1: 1200 };
        for k in 0..4000 {
            let ([x, y, dx, dy], hw) = random_line(&mut seed, if k % 2 == 0 { 0.0 } else { 1000.0 });
            let Some(lr) = LineRect::new(x, y, dx, dy, hw) else { continue };
            for py in lr.rows(WIDE) {
                let cols = lr.cols(py, WIDE);
                let n = (cols.end - cols.start).max(0) as usize;
                let n4 = (n + 3) & !3;
                buf.clear();
                buf.resize(n4, f64::NAN);
                // SAFETY: AVX2 detected above; whole groups of four.
                unsafe { row_avx2::coverage(&lr, py, cols.start, &mut buf) };
                for (j, px) in cols.enumerate() {
                    let want = lr.coverage(px, py);
                    assert_eq!(buf[j].to_bits(), want.to_bits(), "line {x} {y} {dx} {dy} hw {hw} pixel {px},{py}: lanes {}, scalar {want}", buf[j]);
                    pixels += (want > 0.0) as usize;
                    let along = (px as f64 + 0.5 - lr.x) * lr.ux + (py as f64 + 0.5 - lr.y) * lr.uy;
                    caps += (want > 0.0 && !(along >= lr.h && along <= lr.len - lr.h)) as usize;
                }
                assert_eq!(lr.row_coverage(py, lr.cols(py, WIDE), &mut vec![]), &buf[..n]);
            }
        }
        eprintln!("four-lane coverage: {pixels} covered pixels ({caps} by a cap) bit-identical");
        assert!(pixels > 100_000 && caps > 10_000, "{pixels} {caps}");
    }

    #[test]
    fn fade() {
        assert_eq!(faded_point(4.0, 1.0), (4.0, 1.0));
        assert_eq!(faded_point(0.5, 2.0), (2.0, 0.0625));
        assert_eq!(smooth_size(3.03), 3.0);
        assert_eq!(smooth_size(1000.0), 64.0);
    }
}
