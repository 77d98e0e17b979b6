//! Triangle rasterization (GL 1.5 section 3.5.1) by exact spans.
//!
//! A pixel is covered when its centre (x + 1/2, y + 1/2) is inside all three
//! edges. Edge functions are evaluated in i64 on the fixed-point vertices
//! (see `setup` for the ranges that make this exact). A centre exactly on an
//! edge belongs to the triangle only if the edge is a top or left edge (the
//! top-left rule, with "top" meaning larger window y), so two triangles
//! sharing an edge never both draw a pixel and never both miss it.
//!
//! For each row, each edge bounds x from one side; solving the three
//! inequalities exactly in integers gives the covered span [x_start, x_end)
//! directly, with no per-pixel coverage test.
//!
//! Precision (what is exact, and why):
//! - Coverage is exact for every pixel: vertices snap to 1/256 pixel, and
//!   after clipping with the guard band (`clip`) window coordinates stay
//!   below 2^19 pixels, so snapped values fit in 27 bits, edge functions
//!   in 55 bits of i64 (`setup`), and the span solution is integer floor
//!   division. Tiles (`tile`) only restrict the rectangle spans are cut
//!   to, so binned and immediate rasterization cover the same pixels.
//! - Attributes come from f64 plane equations evaluated at each pixel
//!   centre, `(a0 + dy * cy) + dx * cx`, perspective-corrected by a per-pixel
//!   division by the 1/w plane; depth converts to 24 bits by rounding.
//!   The fast kernels (`fragment::fast`) do the same operations in the same
//!   order as the reference (`fragment::reference`), so their depth,
//!   stencil and colour are bit-identical to it, except that with
//!   GL_PERSPECTIVE_CORRECTION_HINT not GL_NICEST an affine smooth colour
//!   that is stored unblended is stepped in 16.16 fixed point: within
//!   1/255 of the exact value (`tests/reference_diff.rs` checks both).

use super::fragment::{self, fast::Kernel, SpanPixels};
use super::setup::{TriangleSetup, ONE};
use super::RenderState;
use crate::framebuffer::{Framebuffer, Rect};

/// E(px, py) = a * px + b * py + c >= 0 inside, in pixel-centre units.
#[derive(Clone, Copy, Debug)]
struct Edge {
    a: i64,
    b: i64,
    c: i64,
}

impl Edge {
    /// The edge from (xa, ya) to (xb, yb) of a counter-clockwise triangle,
    /// as a function of the integer pixel (px, py): its centre is
    /// (px * ONE + ONE/2, py * ONE + ONE/2) in fixed point.
    fn new(xa: i64, ya: i64, xb: i64, yb: i64) -> Edge {
        let (dx, dy) = (xb - xa, yb - ya);
        // E(P) = dx * (Py - ya) - dy * (Px - xa)
        // Left edges go down (dy < 0); top edges are horizontal going left.
        let top_left = dy < 0 || (dy == 0 && dx < 0);
        let half = ONE / 2;
        let a = -dy * ONE;
        let b = dx * ONE;
        let c = dx * (half - ya) - dy * (half - xa) - if top_left { 0 } else { 1 };
        Edge { a, b, c }
    }
}

/// Floor division for a positive divisor.
#[inline]
fn floor_div(n: i64, d: i64) -> i64 {
    n.div_euclid(d)
}

/// The pixels [lo, hi) of row `py` inside all three edges, within [x0, x1).
#[inline]
fn span(edges: &[Edge; 3], py: i64, x0: i64, x1: i64) -> (i64, i64) {
    let (mut lo, mut hi) = (x0, x1);
    for e in edges {
        // a * px + t >= 0
        let t = e.b * py + e.c;
        if e.a > 0 {
            lo = lo.max(-floor_div(t, e.a));
        } else if e.a < 0 {
            hi = hi.min(floor_div(t, -e.a) + 1);
        } else if t < 0 {
            hi = lo;
        }
    }
    (lo, hi)
}

/// The span solution of [`span`] for consecutive rows without a division
/// per row: each edge's bound floor((b * py + c) / |a|) is kept as a
/// quotient and remainder and stepped by b per row (exact: the same
/// integers `span` computes, for every row).
struct RowStepper {
    /// Per edge: quotient, remainder in [0, |a|), |a|, and b split as
    /// b = bq * |a| + br with br in [0, |a|).
    q: [i64; 3],
    r: [i64; 3],
    d: [i64; 3],
    bq: [i64; 3],
    br: [i64; 3],
    /// Per edge: +1 bounds x from below (a > 0), -1 from above (a < 0),
    /// 0 horizontal (then q holds b * py + c itself).
    side: [i8; 3],
    b: [i64; 3],
}

impl RowStepper {
    /// At row `py`.
    #[inline]
    fn new(edges: &[Edge; 3], py: i64) -> RowStepper {
        let mut st = RowStepper { q: [0; 3], r: [0; 3], d: [1; 3], bq: [0; 3], br: [0; 3], side: [0; 3], b: [0; 3] };
        for (i, e) in edges.iter().enumerate() {
            let t = e.b * py + e.c;
            st.b[i] = e.b;
            if e.a == 0 {
                st.q[i] = t;
                continue;
            }
            let d = e.a.abs();
            st.side[i] = if e.a > 0 { 1 } else { -1 };
            st.d[i] = d;
            st.q[i] = floor_div(t, d);
            st.r[i] = t - st.q[i] * d;
            st.bq[i] = floor_div(e.b, d);
            st.br[i] = e.b - st.bq[i] * d;
        }
        st
    }

    /// The pixels [lo, hi) of the current row inside all three edges,
    /// within [x0, x1) (as [`span`]).
    #[inline(always)]
    fn span(&self, x0: i64, x1: i64) -> (i64, i64) {
        let (mut lo, mut hi) = (x0, x1);
        for i in 0..3 {
            match self.side[i] {
                1 => lo = lo.max(-self.q[i]),
                -1 => hi = hi.min(self.q[i] + 1),
                _ => {
                    if self.q[i] < 0 {
                        hi = lo;
                    }
                }
            }
        }
        (lo, hi)
    }

    /// On to the next row.
    #[inline(always)]
    fn step(&mut self) {
        for i in 0..3 {
            if self.side[i] == 0 {
                self.q[i] += self.b[i];
                continue;
            }
            self.q[i] += self.bq[i];
            self.r[i] += self.br[i];
            if self.r[i] >= self.d[i] {
                self.r[i] -= self.d[i];
                self.q[i] += 1;
            }
        }
    }
}

/// Triangles spanning more rows than this step their span ends from row
/// to row ([`RowStepper`]); shorter ones solve each row.
const STEPPED_ROWS: i64 = 16;

/// Bounding boxes at most this many pixel centres wide are scanned by
/// testing each centre against the edges (a few additions) instead of
/// solving for the span ends (three divisions per row).
const NARROW: i64 = 8;

/// The rows [row0, row1) and columns [col0, col1) of the pixel centres in
/// a triangle's bounding box, cut to a rectangle: taken once and shared
/// by [`Cover::find_in`] and [`Runs::find_in`].
///
/// Round 18: with whether the vertices' extents fit the i32 lanes
/// ([`lanes_fit`]), from the same minima and maxima: `Cover::fill` and
/// `Runs::find_narrow` took them again (on the band side, 8 compares and
/// moves a triangle).
#[derive(Clone, Copy)]
pub struct CentreBox(i64, i64, i64, i64, bool);

impl CentreBox {
    #[inline(always)]
    pub fn of(x: [i64; 3], y: [i64; 3], rect: Rect) -> CentreBox {
        let half = ONE / 2;
        let (ymin, ymax) = (y[0].min(y[1]).min(y[2]), y[0].max(y[1]).max(y[2]));
        let (xmin, xmax) = (x[0].min(x[1]).min(x[2]), x[0].max(x[1]).max(x[2]));
        // Centre p * ONE + half lies in [min, max] for ceil((min - half) / ONE)
        // <= p <= floor((max - half) / ONE).
        let row0 = (-floor_div(half - ymin, ONE)).max(rect.y0 as i64);
        let row1 = (floor_div(ymax - half, ONE) + 1).min(rect.y1 as i64);
        let col0 = (-floor_div(half - xmin, ONE)).max(rect.x0 as i64);
        let col1 = (floor_div(xmax - half, ONE) + 1).min(rect.x1 as i64);
        CentreBox(row0, row1, col0, col1, extents_fit(xmax - xmin, ymax - ymin))
    }

    /// The box of rows [row0, row1) and columns [col0, col1) with `fit`
    /// its [`CentreBox::lanes_fit`], as `bin4` finds them in lanes (the
    /// same arithmetic as [`CentreBox::of`]).
    #[inline(always)]
    pub(crate) fn from_parts(row0: i64, row1: i64, col0: i64, col1: i64, fit: bool) -> CentreBox {
        CentreBox(row0, row1, col0, col1, fit)
    }

    /// The box's centres as a rectangle of pixels (rows y0..y1, columns
    /// x0..x1; empty when it holds none): what `tile` bins a triangle by
    /// (round 23).
    #[inline(always)]
    pub fn rect(&self) -> Rect {
        Rect { x0: self.2 as i32, y0: self.0 as i32, x1: self.3 as i32, y1: self.1 as i32 }
    }

    /// The box of the centres in `r`, a [`CentreBox::rect`] already cut
    /// to a band (round 23: the band side no longer takes the vertices'
    /// minima and maxima again), with `fit` its [`CentreBox::lanes_fit`].
    #[inline(always)]
    pub fn of_rect(r: Rect, fit: bool) -> CentreBox {
        CentreBox(r.y0 as i64, r.y1 as i64, r.x0 as i64, r.x1 as i64, fit)
    }

    /// Do the triangle's extents fit the lanes ([`lanes_fit`] of its
    /// vertices)?
    #[inline(always)]
    pub fn lanes_fit(&self) -> bool {
        self.4
    }

    /// How many pixel centres the box holds (0 when it is empty).
    #[inline(always)]
    pub fn count(&self) -> i64 {
        let (rows, cols) = (self.1 - self.0, self.3 - self.2);
        if rows > 0 && cols > 0 { rows * cols } else { 0 }
    }
}

/// The covered pixels [lo, hi) of row `py` (empty when lo >= hi): by the
/// span solution, or for narrow boxes by testing every centre in
/// [col0, col1) (a centre inside lies in the triangle's bounding box, and
/// the covered centres of a row are contiguous: the triangle is convex).
#[inline(always)]
fn row_span(edges: &[Edge; 3], py: i64, col0: i64, col1: i64) -> (i64, i64) {
    if col1 - col0 > NARROW {
        return span(edges, py, col0, col1);
    }
    let mut e = edges.map(|e| e.a * col0 + e.b * py + e.c);
    let (mut lo, mut hi) = (col1, col0);
    for px in col0..col1 {
        if e[0] >= 0 && e[1] >= 0 && e[2] >= 0 {
            lo = lo.min(px);
            hi = px + 1;
        }
        for i in 0..3 {
            e[i] += edges[i].a;
        }
    }
    (lo, hi)
}

/// Vertex extents (in 1/256 pixel) up to which `Runs::find_narrow`'s
/// edge functions fit in i32 lanes: 64 pixels.
pub(crate) const LANE_EXTENT: i64 = 1 << 14;

/// Do a narrow box's edge functions fit in i32? Every value the lanes
/// hold is E = dx (Py - ya) - dy (Px - xa) - {0, 1} (`Edge::new`, in
/// 1/256 pixel) at a centre P of the box's rows (within the vertices' y
/// extent, or one row past it after the last step) and of columns col0
/// to col0 + 7 (col0's centre within the x extent), so with both
/// extents at most 2^14: |dx|, |dy| <= 2^14, |Py - ya| <= 2^14 + 2^8,
/// |Px - xa| <= 2^14 + 2^11, and |E| < 2^30. The coefficients a = -256 dy
/// (times up to 7 across the lanes) and b = 256 dx are below 2^25. (A
/// narrow box can belong to a large triangle cut by the rectangle: those
/// take the i64 loop.)
/// (Round 18: the renderer takes it from [`CentreBox::lanes_fit`]; this
/// form is the tests'.)
#[inline(always)]
#[cfg_attr(not(test), allow(dead_code))]
fn lanes_fit(x: [i64; 3], y: [i64; 3]) -> bool {
    let extent = |c: [i64; 3]| c[0].max(c[1]).max(c[2]) - c[0].min(c[1]).min(c[2]);
    extents_fit(extent(x), extent(y))
}

/// [`lanes_fit`] of vertices whose x and y extents (max - min) are `w`
/// and `h`.
#[inline(always)]
fn extents_fit(w: i64, h: i64) -> bool {
    w <= LANE_EXTENT && h <= LANE_EXTENT
}

/// The covered runs of a short triangle, found once before setup (which
/// a triangle covering nothing skips) and shaded without a second scan.
pub struct Runs {
    /// The first `len` are written; the rest are never read (no zeroing
    /// of the array per triangle).
    runs: [std::mem::MaybeUninit<(u32, u32, u32)>; Runs::MAX],
    len: usize,
}

impl Runs {
    /// Triangles spanning at most this many rows of pixel centres.
    pub const MAX: usize = 12;

    pub fn new() -> Runs {
        Runs { runs: [std::mem::MaybeUninit::uninit(); Runs::MAX], len: 0 }
    }

    /// Finds the runs of triangle (x, y) in `rect` cut by `stipple`; false
    /// when it may span more rows (or stipple runs) than fit: then take
    /// [`triangle`]. (Filled in place: no copy of the array per triangle.)
    #[inline]
    pub fn find(&mut self, x: [i64; 3], y: [i64; 3], rect: Rect, stipple: Option<&[u32; 32]>) -> bool {
        self.find_in(x, y, CentreBox::of(x, y, rect), rect, stipple)
    }

    /// [`Runs::find`] with the triangle's centre box in `rect` already
    /// taken (`CentreBox::of(x, y, rect)`).
    #[inline]
    pub fn find_in(&mut self, x: [i64; 3], y: [i64; 3], b: CentreBox, rect: Rect, stipple: Option<&[u32; 32]>) -> bool {
        let CentreBox(row0, row1, col0, col1, fit) = b;
        if row1 - row0 > Runs::MAX as i64 {
            return false;
        }
        self.len = 0;
        // No pixel centre in the box (most triangles smaller than a
        // pixel): no run, and no edge set-up.
        if row0 >= row1 || col0 >= col1 {
            return true;
        }
        if stipple.is_none() && col1 - col0 <= NARROW {
            self.find_narrow(x, y, fit, row0, row1, col0, col1);
            return true;
        }
        let r = self;
        let mut overflow = false;
        spans(x, y, rect, stipple, |py, lo, hi| {
            if r.len == Runs::MAX {
                overflow = true;
            } else {
                r.runs[r.len].write((py as u32, lo as u32, hi as u32));
                r.len += 1;
            }
        });
        !overflow
    }

    /// [`Runs::find`] for a box of at most `NARROW` columns and `MAX` rows
    /// with no stipple (most small triangles): `row_span`'s test of every
    /// pixel centre, with the edge functions stepped from the box's corner
    /// by additions (the same integers) and the box computed once. At most
    /// one run per row, so the runs always fit.
    #[inline(always)]
    fn find_narrow(&mut self, x: [i64; 3], y: [i64; 3], fit: bool, row0: i64, row1: i64, col0: i64, col1: i64) {
        if col0 >= col1 {
            return;
        }
        // `fit`: `lanes_fit(x, y)`, from the centre box.
        #[cfg(not(target_arch = "x86_64"))]
        let _ = fit;
        #[cfg(target_arch = "x86_64")]
        if fit && super::fragment::simd::level() != super::fragment::simd::Level::Scalar {
            // SAFETY: SSE2 is part of the x86_64 baseline; the values fit
            // in i32 lanes (`lanes_fit`).
            return unsafe { self.find_narrow_sse2(x, y, row0, row1, col0, col1) };
        }
        let edges = [Edge::new(x[0], y[0], x[1], y[1]), Edge::new(x[1], y[1], x[2], y[2]), Edge::new(x[2], y[2], x[0], y[0])];
        self.find_narrow_scalar(&edges, row0, row1, col0, col1)
    }

    /// `find_narrow`'s test of every pixel centre, in i64.
    #[inline(always)]
    fn find_narrow_scalar(&mut self, edges: &[Edge; 3], row0: i64, row1: i64, col0: i64, col1: i64) {
        let a = edges.map(|e| e.a);
        let mut row = edges.map(|e| e.a * col0 + e.b * row0 + e.c);
        for py in row0..row1 {
            let mut e = row;
            let (mut lo, mut hi) = (col1, col0);
            for px in col0..col1 {
                // Inside all three: no sign bit in their union.
                if (e[0] | e[1] | e[2]) >= 0 {
                    lo = lo.min(px);
                    hi = px + 1;
                }
                e = [e[0] + a[0], e[1] + a[1], e[2] + a[2]];
            }
            if lo < hi {
                self.runs[self.len].write((py as u32, lo as u32, hi as u32));
                self.len += 1;
            }
            row = [row[0] + edges[0].b, row[1] + edges[1].b, row[2] + edges[2].b];
        }
    }

    /// [`Runs::find_narrow_scalar`] a row at a time: the edge functions
    /// of the row's (at most [`NARROW`]) pixel centres in i32 lanes, the
    /// centres outside some edge as the sign bits of the three values'
    /// union, and the run from the first to the last centre inside (the
    /// scalar loop's min and max). The lanes hold the scalar loop's
    /// integers (`lanes_fit`), so the runs are the same.
    #[cfg(target_arch = "x86_64")]
    #[inline(always)]
    unsafe fn find_narrow_sse2(&mut self, x: [i64; 3], y: [i64; 3], row0: i64, row1: i64, col0: i64, col1: i64) {
        if col1 - col0 <= 4 {
            self.narrow_lanes::<false>(x, y, row0, row1, col0, col1)
        } else {
            self.narrow_lanes::<true>(x, y, row0, row1, col0, col1)
        }
    }

    /// The lanes of `find_narrow_sse2`: columns col0 .. col0 + 4, and with
    /// WIDE also col0 + 4 .. col0 + 8.
    #[cfg(target_arch = "x86_64")]
    #[inline(always)]
    unsafe fn narrow_lanes<const WIDE: bool>(&mut self, x: [i64; 3], y: [i64; 3], row0: i64, row1: i64, col0: i64, col1: i64) {
        use std::arch::x86_64::*;
        debug_assert!(col1 > col0 && col1 - col0 <= NARROW);
        let columns = (1u32 << (col1 - col0)) - 1;
        // Per edge: the values at the first row's centres, and the step
        // from row to row (all within i32: `lanes_fit`).
        let (mut lo, mut hi, mut step) = ([_mm_setzero_si128(); 3], [_mm_setzero_si128(); 3], [_mm_setzero_si128(); 3]);
        for i in 0..3 {
            let j = if i == 2 { 0 } else { i + 1 };
            let e = Edge::new(x[i], y[i], x[j], y[j]);
            let (first, a) = ((e.a * col0 + e.b * row0 + e.c) as i32, e.a as i32);
            lo[i] = _mm_add_epi32(_mm_set1_epi32(first), _mm_setr_epi32(0, a, 2 * a, 3 * a));
            hi[i] = _mm_add_epi32(lo[i], _mm_set1_epi32(4 * a));
            step[i] = _mm_set1_epi32(e.b as i32);
        }
        for py in row0..row1 {
            let mut outside = _mm_movemask_ps(_mm_castsi128_ps(_mm_or_si128(_mm_or_si128(lo[0], lo[1]), lo[2]))) as u32;
            if WIDE {
                outside |= (_mm_movemask_ps(_mm_castsi128_ps(_mm_or_si128(_mm_or_si128(hi[0], hi[1]), hi[2]))) as u32) << 4;
            }
            let inside = !outside & columns;
            if inside != 0 {
                let (l, h) = (col0 + inside.trailing_zeros() as i64, col0 + (32 - inside.leading_zeros()) as i64);
                self.runs[self.len].write((py as u32, l as u32, h as u32));
                self.len += 1;
            }
            for i in 0..3 {
                lo[i] = _mm_add_epi32(lo[i], step[i]);
                if WIDE {
                    hi[i] = _mm_add_epi32(hi[i], step[i]);
                }
            }
        }
    }

    pub fn is_empty(&self) -> bool {
        self.len == 0
    }

    /// The runs (y, x0, x1), bottom to top.
    pub fn iter(&self) -> impl Iterator<Item = (usize, usize, usize)> + '_ {
        // SAFETY: the first `len` runs were written by `find`.
        self.runs[..self.len].iter().map(|r| unsafe { r.assume_init() }).map(|(py, lo, hi)| (py as usize, lo as usize, hi as usize))
    }

    /// Shades the runs now, on this thread, with kernel `k`.
    pub fn shade(&self, rs: &RenderState, fb: &mut Framebuffer, setup: &TriangleSetup, k: Kernel) {
        shade_runs(self.iter(), rs, fb, setup, k)
    }
}

/// Shades runs (y, x0, x1) now, on this thread, with span kernel `k`
/// (a [`Runs`], or a [`Cover`]'s rows when its state has no block kernel).
#[inline(always)]
pub fn shade_runs(runs: impl Iterator<Item = (usize, usize, usize)>, rs: &RenderState, fb: &mut Framebuffer, setup: &TriangleSetup, k: Kernel) {
    for (py, lo, hi) in runs {
        let mut px = SpanPixels::of(fb, py, lo, hi);
        k(&rs.fragment, setup, &mut px, py, lo, hi);
        let passed = px.passed;
        fb.samples_passed = fb.samples_passed.wrapping_add(passed);
    }
}

/// The covered pixel centres of a small triangle, found all at once
/// (round 13's 4x8 block, widened in round 14 for the sphere scenes'
/// triangles): a block of up to [`Cover::COLS`] columns and
/// [`Cover::ROWS`] rows from (col0, row0), bit `i` of row `j`
/// ([`Cover::row`]) for pixel (col0 + i, row0 + j). The same exact edge
/// tests as [`Runs::find`] (top-left rule included), so the same pixels;
/// shaded as a block by `fragment::stamp` or, for states it does not
/// cover, row by row ([`Cover::rows`]) by the span kernel.
///
/// Filled in place ([`Cover::find_in`]) and only its first `rows` rows
/// written: it is 200 bytes, and moving or zeroing it per triangle cost
/// spheres_m 9 M instructions of `memcpy` (3 frames).
#[derive(Clone, Copy)]
pub struct Cover {
    pub row0: usize,
    pub col0: usize,
    /// Rows of `mask` written (0: no pixel covered).
    rows: usize,
    /// At most four columns (every row's bits below 16): the block
    /// kernel's one-group-a-row form (round 17).
    narrow: bool,
    mask: [std::mem::MaybeUninit<Row>; Cover::ROWS as usize],
}

/// One row of a [`Cover`]: bit i for column col0 + i.
pub type Row = u32;

impl std::fmt::Debug for Cover {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        let rows: Vec<_> = (0..self.rows).map(|j| format!("{:b}", self.row(j))).collect();
        write!(f, "Cover {{ row0: {}, col0: {}, rows: {rows:?} }}", self.row0, self.col0)
    }
}

impl Cover {
    /// The block's width: a row is up to eight sets of four f64 lanes in
    /// the block kernel, four sets of eight i32 lanes in the cover
    /// (spheres_s's triangles at 1920x1080 are up to about 30 wide).
    pub const COLS: i64 = 32;
    /// The block's height: spheres_s's triangles at 1920x1080 are up to
    /// about 35 rows tall; the rows are stepped in a loop.
    pub const ROWS: i64 = 48;

    /// No pixel.
    pub const EMPTY: Cover = Cover { row0: 0, col0: 0, rows: 0, narrow: true, mask: [std::mem::MaybeUninit::uninit(); Cover::ROWS as usize] };

    /// The cover of triangle (x, y) (positively oriented) within `rect`
    /// when its box of pixel centres there fits the block, the extents
    /// fit the lanes and the CPU has AVX2, for a box of any size up to
    /// the block's (the tests' entry: the renderer asks [`Cover::find_in`],
    /// which leaves the smallest boxes to [`Runs`]); None otherwise. No
    /// stipple: callers with one do not ask.
    pub fn find(x: [i64; 3], y: [i64; 3], rect: Rect) -> Option<Cover> {
        let mut c = Cover::EMPTY;
        c.of_box(&x, &y, CentreBox::of(x, y, rect), 0).then_some(c)
    }

    /// [`Cover::find`] with the centre box already taken, for the
    /// renderer, into `slot`: the cover, or None when it does not fit.
    /// Boxes of at most [`Cover::SMALLEST`] centres are left to
    /// [`Runs::find_in`]. Round 16: into an uninitialized slot, each
    /// field written once (a `Cover::EMPTY` copied in first, its three
    /// counts zero and its rows uninitialized, was stored as 216 bytes of
    /// zeros: 14 instructions a triangle).
    #[inline(always)]
    pub fn find_into<'a>(slot: &'a mut std::mem::MaybeUninit<Cover>, x: &[i64; 3], y: &[i64; 3], b: CentreBox) -> Option<&'a Cover> {
        Cover::find_into_at(slot, x, y, b, blocks_here())
    }

    /// [`Cover::find_into`] with [`blocks_here`]'s answer taken by the
    /// caller (round 18: the band loop asks once a band, not once a
    /// triangle: two loads of globals and four branches).
    #[inline(always)]
    pub fn find_into_at<'a>(slot: &'a mut std::mem::MaybeUninit<Cover>, x: &[i64; 3], y: &[i64; 3], b: CentreBox, blocks: bool) -> Option<&'a Cover> {
        // SAFETY: `fill` writes every field when it returns true.
        unsafe { Cover::fill(slot.as_mut_ptr(), x, y, b, Cover::SMALLEST, blocks).then(|| slot.assume_init_ref()) }
    }

    /// Boxes of at most this many centres are left to [`Runs::find_in`]
    /// (callers test `CentreBox::count` first, so that a box with no
    /// centre skips the cover). Rounds 13 and 14 left boxes of up to 2x2
    /// centres there: by instructions the block was cheaper for them, but
    /// by the clock dearer (immediate_1m, whose triangles all cover one
    /// pixel of a 2x2 box: 39.5 ms a frame against 41.9, 1 thread), for
    /// its masked loads and stores. Round 15: the block kernel stores
    /// plainly inside the rows, and every box with a centre takes the
    /// block (immediate_1m, 1 thread: 1,691 -> 1,544 M instructions for 3
    /// frames, CPU time -8 %).
    pub const SMALLEST: i64 = 0;

    /// The cover of box `b` into `self` when it has more than `smallest`
    /// centres (or none: no rows) and fits the block and the lanes, on a
    /// CPU with AVX2.
    #[inline(always)]
    fn of_box(&mut self, x: &[i64; 3], y: &[i64; 3], b: CentreBox, smallest: i64) -> bool {
        // SAFETY: `self` is a cover, valid to overwrite (nothing to drop).
        unsafe { Cover::fill(self, x, y, b, smallest, blocks_here()) }
    }

    /// [`Cover::of_box`] into `*c`, which may be uninitialized: true when
    /// every field is written (of the rows, the first `rows`). `blocks`:
    /// [`blocks_here`] on this thread.
    ///
    /// Safety: `c` is valid for writes of a `Cover`.
    #[inline(always)]
    unsafe fn fill(c: *mut Cover, x: &[i64; 3], y: &[i64; 3], b: CentreBox, smallest: i64, blocks: bool) -> bool {
        use std::ptr::addr_of_mut;
        let CentreBox(row0, row1, col0, col1, fit) = b;
        let (rows, cols) = (row1 - row0, col1 - col0);
        // No pixel centre in the box (most triangles smaller than a
        // pixel): nothing to test.
        if rows <= 0 || cols <= 0 {
            addr_of_mut!((*c).row0).write(0);
            addr_of_mut!((*c).col0).write(0);
            addr_of_mut!((*c).rows).write(0);
            addr_of_mut!((*c).narrow).write(true);
            return true;
        }
        if rows * cols <= smallest || rows > Cover::ROWS || cols > Cover::COLS || !blocks || !fit {
            return false;
        }
        #[cfg(target_arch = "x86_64")]
        {
            addr_of_mut!((*c).row0).write(row0 as usize);
            addr_of_mut!((*c).col0).write(col0 as usize);
            addr_of_mut!((*c).narrow).write(cols <= 4);
            // SAFETY: `blocks`: `blocks_here` saw AVX2; the values fit in i32
            // (`lanes_fit`, and `cover_avx2`'s bound). It writes the
            // first `rows` rows (`MaybeUninit`s: the reference is to
            // values that need no initialization).
            let any = cover_avx2(x, y, row0, rows, col0, cols, &mut *addr_of_mut!((*c).mask));
            addr_of_mut!((*c).rows).write(if any == 0 { 0 } else { rows as usize });
            true
        }
        #[cfg(not(target_arch = "x86_64"))]
        {
            let _ = (x, y);
            false
        }
    }

    pub fn is_empty(&self) -> bool {
        self.rows == 0
    }

    /// At most four columns wide: each row's bits below 16.
    #[inline(always)]
    pub fn narrow(&self) -> bool {
        self.narrow
    }

    /// Rows of the cover (0 when no pixel is covered).
    #[inline(always)]
    pub fn height(&self) -> usize {
        self.rows
    }

    /// Row `j` (< `height()`) of the cover.
    #[inline(always)]
    pub fn row(&self, j: usize) -> Row {
        // SAFETY: the first `rows` rows were written (`of_box`); the
        // slice's bounds check keeps j there.
        unsafe { self.mask[..self.rows][j].assume_init() }
    }

    /// The rows' bits, bottom to top.
    #[inline(always)]
    pub fn row_bits(&self) -> impl Iterator<Item = Row> + '_ {
        // SAFETY: the first `rows` rows were written (`of_box`).
        self.mask[..self.rows].iter().map(|m| unsafe { m.assume_init() })
    }

    /// The covered runs (y, x0, x1), bottom to top.
    pub fn rows(&self) -> impl Iterator<Item = (usize, usize, usize)> + '_ {
        (0..self.rows).filter_map(move |j| {
            let bits = self.row(j);
            (bits != 0).then(|| (self.row0 + j, self.col0 + bits.trailing_zeros() as usize, self.col0 + (Row::BITS - bits.leading_zeros()) as usize))
        })
    }
}

/// Are small triangles covered and shaded as blocks on this thread
/// (AVX2, not lowered by `SOFTGL_SIMD` or a test)?
#[inline(always)]
pub fn blocks_here() -> bool {
    fragment::simd::level_here() == fragment::simd::Level::Avx2
}

/// The cover of the box [row0, row0 + rows) x [col0, col0 + cols) (at
/// most `Cover::ROWS` by `Cover::COLS`, not empty) into `mask` (one `Row`
/// a row), returning the union of the rows' bits: each edge function at
/// the centres in i32 lanes, a centre outside when the union of its three
/// values has the sign bit. Boxes up to four columns wide take two rows
/// of four centres per eight lanes, stepped two rows at a time; wider ones
/// a row at a time in one, two or four sets of eight lanes
/// (`cover_rows`). The three edges are set up side by side in four lanes.
///
/// Exact: each lane holds `Edge::new`'s E = dx (Py - ya) - dy (Px - xa) -
/// bias at its centre P. With both extents at most 2^14 (`lanes_fit`)
/// and the box's first centre within them, the vertices relative to that
/// centre are within 2^14, the edge vectors within 2^14, every centre of
/// the lanes (up to 31 columns past the first, and the box's rows, which
/// lie within the y extent) within 2^14 + 2^13 of every vertex, so
/// |E| < 2^14 (2^14 + 2^8) + 2^14 (2^14 + 2^13) < 2^29.6 and no lane wraps.
#[cfg(target_arch = "x86_64")]
#[target_feature(enable = "avx2")]
unsafe fn cover_avx2(x: &[i64; 3], y: &[i64; 3], row0: i64, rows: i64, col0: i64, cols: i64, mask: &mut [std::mem::MaybeUninit<Row>; Cover::ROWS as usize]) -> u32 {
    use std::arch::x86_64::*;
    let half = ONE / 2;
    let (px, py) = (col0 * ONE + half, row0 * ONE + half);
    // Lanes 0, 1, 2: edge e from vertex e to vertex e + 1 (mod 3).
    // (Round 17: the coordinates' low halves gathered into lanes, then
    // one subtraction: i32 arithmetic wraps as the truncation of the i64
    // difference does; round 28: one load each, `low_halves`. Lane 3
    // holds vertex 2 again: its edge's vector is zero, and lane 3 is
    // never used.)
    let vx = _mm_sub_epi32(low_halves(x), _mm_set1_epi32(px as i32));
    let vy = _mm_sub_epi32(low_halves(y), _mm_set1_epi32(py as i32));
    let dx = _mm_sub_epi32(_mm_shuffle_epi32::<0b11_00_10_01>(vx), vx);
    let dy = _mm_sub_epi32(_mm_shuffle_epi32::<0b11_00_10_01>(vy), vy);
    // E at the first centre: dx (0 - Y) - dy (0 - X) = dy X - dx Y.
    let zero = _mm_setzero_si128();
    let first = _mm_sub_epi32(_mm_mullo_epi32(dy, vx), _mm_mullo_epi32(dx, vy));
    // `Edge::new`'s top-left rule: a centre on an edge that is neither
    // top nor left (dy < 0, or dy = 0 and dx < 0) is out: minus 1.
    let top_left = _mm_or_si128(_mm_cmpgt_epi32(zero, dy), _mm_and_si128(_mm_cmpeq_epi32(dy, zero), _mm_cmpgt_epi32(zero, dx)));
    let first = _mm_add_epi32(first, _mm_xor_si128(top_left, _mm_set1_epi32(-1)));
    // Steps: a column is -256 dy, a row 256 dx.
    let a = _mm_slli_epi32::<8>(_mm_sub_epi32(zero, dy));
    let b = _mm_slli_epi32::<8>(dx);
    let columns = ((1u64 << cols) - 1) as Row;
    let mut any = 0u32;
    if cols <= 4 {
        // Two rows of four centres in the eight lanes. Round 17: the
        // lanes are built by a transposition, not by broadcasting each
        // edge and multiplying by the lane indices (about 85 of this
        // function's 134 instructions a call on spheres_l): column i of
        // the first row is `first + i a` and of the second that plus b,
        // the three edges side by side (lanes 0-2); the 4x4 transposes
        // within each 128-bit half put each edge's eight values in one
        // register (lane 3, the unused fourth edge, drops out).
        let c1 = _mm_add_epi32(first, a);
        let c2 = _mm_add_epi32(c1, a);
        let c3 = _mm_add_epi32(c2, a);
        let (y0, y1, y2, y3) = (two_rows(first, b), two_rows(c1, b), two_rows(c2, b), two_rows(c3, b));
        // Edges 0, 1 of columns 0, 1 (lo) and edge 2, 3 (hi); then 2, 3.
        let (lo01, hi01) = (_mm256_unpacklo_epi32(y0, y1), _mm256_unpackhi_epi32(y0, y1));
        let (lo23, hi23) = (_mm256_unpacklo_epi32(y2, y3), _mm256_unpackhi_epi32(y2, y3));
        let mut v = [_mm256_unpacklo_epi64(lo01, lo23), _mm256_unpackhi_epi64(lo01, lo23), _mm256_unpacklo_epi64(hi01, hi23)];
        let b2 = _mm_add_epi32(b, b);
        let step = [lane_of(b2, 0), lane_of(b2, 1), lane_of(b2, 2)];
        // Round 18: both rows in one 64-bit store, without a bounds
        // check: j is even and below `rows` <= `Cover::ROWS` (even), so
        // j + 1 < `Cover::ROWS`; a second row past `rows` is written but
        // never read (nor counted in `any`). The rows are stepped only
        // while more follow.
        debug_assert!(rows >= 1 && rows <= Cover::ROWS && Cover::ROWS % 2 == 0);
        let rows = rows as usize;
        let p = mask.as_mut_ptr() as *mut Row;
        let mut j = 0;
        loop {
            let out = _mm256_movemask_ps(_mm256_castsi256_ps(_mm256_or_si256(_mm256_or_si256(v[0], v[1]), v[2]))) as u32;
            let (m0, m1) = (!out as Row & columns, !(out >> 4) as Row & columns);
            (p.add(j) as *mut u64).write_unaligned(m0 as u64 | (m1 as u64) << 32);
            any |= m0 | if j + 1 < rows { m1 } else { 0 };
            j += 2;
            if j >= rows {
                break;
            }
            for e in 0..3 {
                v[e] = _mm256_add_epi32(v[e], step[e]);
            }
        }
    } else if cols <= 8 {
        any = cover_rows::<1>(first, a, b, rows, columns, mask);
    } else if cols <= 16 {
        any = cover_rows::<2>(first, a, b, rows, columns, mask);
    } else {
        any = cover_rows::<4>(first, a, b, rows, columns, mask);
    }
    any
}

/// `cover_avx2`'s rows for boxes of more than four columns: a row's
/// centres in `SETS` sets of eight i32 lanes (columns 8 k .. 8 k + 7 in
/// set k), one row a step. `first`, `a`, `b`: the three edges' values at
/// the box's first centre and their column and row steps, in lanes 0-2.
#[cfg(target_arch = "x86_64")]
#[inline(always)]
unsafe fn cover_rows<const SETS: usize>(first: std::arch::x86_64::__m128i, a: std::arch::x86_64::__m128i, b: std::arch::x86_64::__m128i, rows: i64, columns: Row, mask: &mut [std::mem::MaybeUninit<Row>; Cover::ROWS as usize]) -> u32 {
    use std::arch::x86_64::*;
    let lane_i = _mm256_setr_epi32(0, 1, 2, 3, 4, 5, 6, 7);
    let (mut v, mut step) = ([[_mm256_setzero_si256(); SETS]; 3], [_mm256_setzero_si256(); 3]);
    for e in 0..3 {
        let ae = lane_of(a, e as i32);
        v[e][0] = _mm256_add_epi32(lane_of(first, e as i32), _mm256_mullo_epi32(ae, lane_i));
        for k in 1..SETS {
            v[e][k] = _mm256_add_epi32(v[e][k - 1], _mm256_slli_epi32::<3>(ae));
        }
        step[e] = lane_of(b, e as i32);
    }
    let mut any = 0;
    for m in mask.iter_mut().take(rows as usize) {
        let mut out = 0u32;
        for k in 0..SETS {
            let union = _mm256_or_si256(_mm256_or_si256(v[0][k], v[1][k]), v[2][k]);
            out |= (_mm256_movemask_ps(_mm256_castsi256_ps(union)) as u32) << (8 * k);
        }
        let bits = !out as Row & columns;
        m.write(bits);
        any |= bits;
        for e in 0..3 {
            for k in 0..SETS {
                v[e][k] = _mm256_add_epi32(v[e][k], step[e]);
            }
        }
    }
    any as u32
}

/// The low 32 bits of c[0], c[1], c[2], c[2] (a function, as `lane_of`).
#[cfg(target_arch = "x86_64")]
#[inline(always)]
unsafe fn low_halves(c: &[i64; 3]) -> std::arch::x86_64::__m128i {
    use std::arch::x86_64::*;
    // x86_64 is little-endian: an i64's low half is its first four bytes.
    let p = c.as_ptr().cast::<i32>();
    // Round 28: each coordinate's low half loaded alone (the callers
    // have just stored the three as i64: one 16-byte load across two of
    // those stores could not be forwarded and waited for the stores).
    // (Volatile: LLVM merges plain reads back into one load.)
    let (a, b, c) = (p.read_volatile(), p.add(2).read_volatile(), p.add(4).read_volatile());
    _mm_setr_epi32(a, b, c, c)
}

/// `c` in the low half, `c + b` in the high (a function, as `lane_of`).
#[cfg(target_arch = "x86_64")]
#[inline(always)]
unsafe fn two_rows(c: std::arch::x86_64::__m128i, b: std::arch::x86_64::__m128i) -> std::arch::x86_64::__m256i {
    use std::arch::x86_64::*;
    _mm256_inserti128_si256::<1>(_mm256_castsi128_si256(c), _mm_add_epi32(c, b))
}

/// Lane `e` of `v` in all eight lanes (a function, not a closure: a
/// closure in `cover_avx2` would not have its target features).
#[cfg(target_arch = "x86_64")]
#[inline(always)]
unsafe fn lane_of(v: std::arch::x86_64::__m128i, e: i32) -> std::arch::x86_64::__m256i {
    use std::arch::x86_64::*;
    _mm256_permutevar8x32_epi32(_mm256_castsi128_si256(v), _mm256_set1_epi32(e))
}

/// Calls `emit(py, lo, hi)` for every run of covered pixels [lo, hi) of
/// row py inside `rect`, rows bottom to top, cut by the polygon stipple
/// (3.5.2) when there is one.
#[inline]
pub fn spans(x: [i64; 3], y: [i64; 3], rect: Rect, stipple: Option<&[u32; 32]>, mut emit: impl FnMut(usize, usize, usize)) {
    let edges = [Edge::new(x[0], y[0], x[1], y[1]), Edge::new(x[1], y[1], x[2], y[2]), Edge::new(x[2], y[2], x[0], y[0])];
    // Rows and columns whose centres lie within the bounding box: a
    // superset is enough, spans are exact.
    let CentreBox(row0, row1, col0, col1, _) = CentreBox::of(x, y, rect);
    if col0 >= col1 {
        return;
    }
    // Wide boxes of more than a few rows step the span solution from row
    // to row (setting the stepper up costs six divisions).
    let mut rows = (col1 - col0 > NARROW && row1 - row0 > STEPPED_ROWS).then(|| RowStepper::new(&edges, row0));
    for py in row0..row1 {
        let (lo, hi) = match &mut rows {
            Some(st) => {
                let s = st.span(col0, col1);
                st.step();
                s
            }
            None => row_span(&edges, py, col0, col1),
        };
        if lo >= hi {
            continue;
        }
        match stipple {
            None => emit(py as usize, lo as usize, hi as usize),
            Some(pattern) => {
                // Only pixels whose bit (x mod 32, y mod 32) is set, as runs.
                let row = pattern[py.rem_euclid(32) as usize];
                let mut x = lo;
                while x < hi {
                    if row >> (x.rem_euclid(32)) & 1 == 0 {
                        x += 1;
                        continue;
                    }
                    let start = x;
                    while x < hi && row >> (x.rem_euclid(32)) & 1 == 1 {
                        x += 1;
                    }
                    emit(py as usize, start as usize, x as usize);
                }
            }
        }
    }
}

/// The span kernel for a triangle: the general path's when drawing to two
/// colour buffers (only it writes both), else the reference path's or the
/// fast one specialized for the state and the triangle's attributes (as
/// `fast::select` picks it, once per state: `shade_state`).
#[inline(always)]
pub fn kernel(rs: &RenderState, fb: &Framebuffer, setup: &TriangleSetup) -> Kernel {
    if fb.draw_both || rs.reference {
        fragment::reference::shade_span
    } else {
        rs.shade.kernel(rs, setup)
    }
}

/// Rasterizes and shades a triangle now, on this thread, with kernel `k`.
pub fn triangle(rs: &RenderState, fb: &mut Framebuffer, x: [i64; 3], y: [i64; 3], setup: &TriangleSetup, k: Kernel) {
    spans(x, y, rs.draw_rect, rs.polygon_stipple.as_deref(), |py, lo, hi| {
        let mut px = SpanPixels::of(fb, py, lo, hi);
        k(&rs.fragment, setup, &mut px, py, lo, hi);
        let passed = px.passed;
        fb.samples_passed = fb.samples_passed.wrapping_add(passed);
    });
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A triangle's vertices counter-clockwise and its three edges; None
    /// when it has no area.
    fn ccw_edges(mut x: [i64; 3], mut y: [i64; 3]) -> Option<([i64; 3], [i64; 3], [Edge; 3])> {
        let area = (x[1] - x[0]) as i128 * (y[2] - y[0]) as i128 - (x[2] - x[0]) as i128 * (y[1] - y[0]) as i128;
        if area == 0 {
            return None;
        }
        if area < 0 {
            x.swap(1, 2);
            y.swap(1, 2);
        }
        Some((x, y, [Edge::new(x[0], y[0], x[1], y[1]), Edge::new(x[1], y[1], x[2], y[2]), Edge::new(x[2], y[2], x[0], y[0])]))
    }

    /// Small triangles (the narrow scan): `spans` and `Runs` agree
    /// with testing every pixel centre of a window directly.
    #[test]
    fn narrow_spans_match_per_pixel_edge_tests() {
        let mut rnd = crate::render::test_rng::below(99, 33);
        let rect = Rect { x0: 2, y0: 1, x1: 14, y1: 13 };
        let (mut covered, mut empty) = (0, 0);
        for _ in 0..20000 {
            let (bx, by, size) = (rnd(16 * ONE), rnd(16 * ONE), 1 + rnd(12 * ONE));
            let x = [bx + rnd(size), bx + rnd(size), bx + rnd(size)];
            let y = [by + rnd(size), by + rnd(size), by + rnd(size)];
            let Some((x, y, edges)) = ccw_edges(x, y) else { continue };
            let mut expect = vec![];
            for py in rect.y0 as i64..rect.y1 as i64 {
                for px in rect.x0 as i64..rect.x1 as i64 {
                    if edges.iter().all(|e| e.a * px + e.b * py + e.c >= 0) {
                        expect.push((px, py));
                    }
                }
            }
            let mut got = vec![];
            spans(x, y, rect, None, |py, lo, hi| got.extend((lo..hi).map(|px| (px as i64, py as i64))));
            got.sort_by_key(|&(px, py)| (py, px));
            assert_eq!(got, expect, "{x:?} {y:?}");
            let mut runs = Runs::new();
            assert!(runs.find(x, y, rect, None), "a short triangle");
            let mut got: Vec<_> = runs.iter().flat_map(|(py, lo, hi)| (lo..hi).map(move |px| (px as i64, py as i64))).collect();
            got.sort_by_key(|&(px, py)| (py, px));
            assert_eq!(got, expect, "runs of {x:?} {y:?}");
            if expect.is_empty() { empty += 1 } else { covered += 1 }
        }
        assert!(covered > 1000 && empty > 1000, "{covered} {empty}");
    }

    /// The narrow scan's i32 lanes give the i64 loop's runs, on small
    /// triangles and on triangles up to the lanes' extent cut to a narrow
    /// box by the rectangle (thin slivers, extents of exactly 2^14, boxes
    /// of 1 to 8 columns, both lane widths, negative coordinates).
    #[cfg(target_arch = "x86_64")]
    #[test]
    fn narrow_lanes_match_scalar() {
        let mut rnd = crate::render::test_rng::below(4242, 20);
        let (mut compared, mut at_extent, mut covered, mut ties) = (0, 0, 0, 0);
        for n in 0..400_000 {
            let size = match n % 4 {
                0 => 3 * ONE,
                1 => 10 * ONE,
                2 => LANE_EXTENT + 1,
                _ => 64,
            };
            let (bx, by) = (rnd(64 * ONE) - 32 * ONE, rnd(64 * ONE) - 32 * ONE);
            let mut x = [bx + rnd(size), bx + rnd(size), bx + rnd(size)];
            let mut y = [by + rnd(size), by + rnd(size), by + rnd(size)];
            if n % 5 == 1 {
                // On the half-pixel grid: centres on edges (the top-left
                // rule decides them).
                x = x.map(|c| c & !(ONE / 2 - 1));
                y = y.map(|c| c & !(ONE / 2 - 1));
            }
            if n % 7 == 0 {
                // Extents of exactly the limit.
                x[1] = x[0] + LANE_EXTENT;
                y[2] = y[0] - LANE_EXTENT;
            }
            let Some((x, y, edges)) = ccw_edges(x, y) else { continue };
            if !lanes_fit(x, y) {
                continue;
            }
            // A rectangle cutting the box to at most NARROW columns and
            // MAX rows somewhere over the triangle.
            let (cx, cy) = (x[rnd(3) as usize] / ONE, y[rnd(3) as usize] / ONE);
            let (w, h) = (1 + rnd(NARROW), 1 + rnd(Runs::MAX as i64));
            let rect = Rect { x0: (cx - rnd(w)) as i32, y0: (cy - rnd(h)) as i32, x1: 0, y1: 0 };
            let rect = Rect { x1: rect.x0 + w as i32, y1: rect.y0 + h as i32, ..rect };
            let CentreBox(row0, row1, col0, col1, _) = CentreBox::of(x, y, rect);
            if row0 >= row1 || col0 >= col1 {
                continue;
            }
            let (mut scalar, mut lanes) = (Runs::new(), Runs::new());
            scalar.find_narrow_scalar(&edges, row0, row1, col0, col1);
            // SAFETY: x86_64 has SSE2; the extents fit.
            unsafe { lanes.find_narrow_sse2(x, y, row0, row1, col0, col1) };
            let (s, l): (Vec<_>, Vec<_>) = (scalar.iter().collect(), lanes.iter().collect());
            assert_eq!(l, s, "{x:?} {y:?} {rect:?}");
            compared += 1;
            covered += !s.is_empty() as usize;
            at_extent += (n % 7 == 0) as usize;
            // A centre on an edge: all three edge functions >= 0 there
            // with one of them 0 (or -1 after the rule's bias).
            let on_edge = (row0..row1).any(|py| (col0..col1).any(|px| {
                let e = edges.map(|e| e.a * px + e.b * py + e.c);
                e.iter().all(|&v| v >= -1) && e.iter().any(|&v| v == 0 || v == -1)
            }));
            ties += on_edge as usize;
        }
        assert!(compared > 100_000 && covered > 50_000 && at_extent > 10_000 && ties > 5_000, "{compared} {covered} {at_extent} {ties}");
    }

    /// Round 18: `CentreBox::of`'s `lanes_fit` (from its own minima and
    /// maxima) is `lanes_fit` of the vertices, on extents at, around and
    /// past the limit.
    #[test]
    fn centre_box_fit_matches_lanes_fit() {
        let mut rnd = crate::render::test_rng::below(2026, 18);
        let (mut fit, mut unfit) = (0, 0);
        for n in 0..200_000 {
            // Extents around the limit, exactly at it, one past it.
            let (ex, ey) = match n % 4 {
                0 => (LANE_EXTENT, rnd(LANE_EXTENT + 1)),
                1 => (rnd(LANE_EXTENT + 1), LANE_EXTENT + 1),
                2 => (LANE_EXTENT - 2 + rnd(5), LANE_EXTENT - 2 + rnd(5)),
                _ => (rnd(2 * LANE_EXTENT), rnd(2 * LANE_EXTENT)),
            };
            let (bx, by) = (rnd(1 << 20) - (1 << 19), rnd(1 << 20) - (1 << 19));
            // One vertex at each end of each extent, the third between.
            let mut x = [bx, bx + ex, bx + rnd(ex + 1)];
            let mut y = [by + rnd(ey + 1), by, by + ey];
            let k = rnd(3) as usize;
            x.swap(0, k);
            y.rotate_left(k);
            let rect = Rect { x0: -4096, y0: -4096, x1: 4096, y1: 4096 };
            let b = CentreBox::of(x, y, rect);
            assert_eq!(b.lanes_fit(), lanes_fit(x, y), "{x:?} {y:?}");
            if b.lanes_fit() {
                fit += 1;
            } else {
                unfit += 1;
            }
        }
        assert!(fit > 50_000 && unfit > 50_000, "{fit} {unfit}");
    }

    /// A small triangle's block cover (round 13, widened in round 14) has
    /// exactly `Runs::find`'s runs where it finds them, and `spans`' runs:
    /// random triangles of every orientation whose centre boxes are up to
    /// 35 columns and 36 rows (so some do not fit the block), on
    /// the half-pixel grid in a fifth of them (centres on edges: the
    /// top-left rule decides), horizontal and vertical edges, slivers and
    /// degenerate ones, large ones cut to a small box by a random
    /// rectangle (a band or the scissor), negative coordinates.
    #[cfg(target_arch = "x86_64")]
    #[test]
    fn cover_matches_runs() {
        if !blocks_here() {
            eprintln!("no AVX2: the block cover is not used");
            return;
        }
        let mut rnd = crate::render::test_rng::below(2026, 21);
        let (mut compared, mut covered, mut ties, mut cut, mut flat, mut wide, mut tall_ones) = (0, 0, 0, 0, 0, 0, 0);
        for n in 0..400_000 {
            // Round 14: also boxes up to 35 columns and 36 rows (the
            // sphere strips' narrow triangles), some too large.
            let (size, tall) = match n % 8 {
                0 => (2 * ONE, 2 * ONE),
                1 => (4 * ONE, 4 * ONE),
                2 => (6 * ONE, 6 * ONE),
                3 => (64 * ONE, 64 * ONE),
                4 => (9 * ONE + rnd(26 * ONE), 9 * ONE + rnd(27 * ONE)),
                5 => (4 * ONE + rnd(6 * ONE), 12 * ONE + rnd(24 * ONE)),
                6 => (8 * ONE, 12 * ONE),
                _ => (ONE / 2, ONE / 2),
            };
            let (bx, by) = (rnd(40 * ONE) - 20 * ONE, rnd(40 * ONE) - 20 * ONE);
            let mut x = [bx + rnd(size), bx + rnd(size), bx + rnd(size)];
            let mut y = [by + rnd(tall), by + rnd(tall), by + rnd(tall)];
            if n % 5 == 1 || n % 11 == 0 {
                x = x.map(|c| c & !(ONE / 2 - 1));
                y = y.map(|c| c & !(ONE / 2 - 1));
            }
            match n % 13 {
                0 => y[1] = y[0],
                1 => x[2] = x[0],
                2 => (x[2], y[2]) = (x[0] + (x[1] - x[0]) / 2, y[0] + (y[1] - y[0]) / 2),
                _ => {}
            }
            // Positive orientation, as setup hands triangles on; a
            // degenerate one stays as it is.
            let area = (x[1] - x[0]) * (y[2] - y[0]) - (x[2] - x[0]) * (y[1] - y[0]);
            if area < 0 {
                x.swap(1, 2);
                y.swap(1, 2);
            }
            flat += (area == 0) as usize;
            let rect = if size > 32 * ONE || n % 3 == 0 {
                // A band or a scissor box somewhere over the triangle.
                let (cx, cy) = (x[rnd(3) as usize] / ONE, y[rnd(3) as usize] / ONE);
                let (w, h) = (1 + rnd(6), 1 + rnd(10));
                let x0 = (cx - rnd(w + 1)) as i32;
                let y0 = (cy - rnd(h + 1)) as i32;
                Rect { x0, y0, x1: x0 + w as i32, y1: y0 + h as i32 }
            } else {
                Rect { x0: -64, y0: -64, x1: 64, y1: 64 }
            };
            let Some(cover) = Cover::find(x, y, rect) else { continue };
            // (Runs hold u32: compare negative coordinates as they wrap.)
            let narrow = |(py, lo, hi): (usize, usize, usize)| (py as u32, lo as u32, hi as u32);
            let c: Vec<_> = cover.rows().map(narrow).collect();
            let mut runs = Runs::new();
            if runs.find(x, y, rect, None) {
                let r: Vec<_> = runs.iter().map(narrow).collect();
                assert_eq!(c, r, "{x:?} {y:?} {rect:?} {cover:?}");
            } else {
                tall_ones += 1;
            }
            let mut r = Vec::new();
            spans(x, y, rect, None, |py, lo, hi| r.push(narrow((py, lo, hi))));
            assert_eq!(c, r, "spans: {x:?} {y:?} {rect:?} {cover:?}");
            assert_eq!(cover.is_empty(), c.is_empty());
            let CentreBox(_, _, col0, col1, _) = CentreBox::of(x, y, rect);
            wide += (col1 - col0 > 16) as usize;
            compared += 1;
            covered += !c.is_empty() as usize;
            cut += (rect.x1 - rect.x0 < 8) as usize;
            if area != 0 {
                let (_, _, edges) = ccw_edges(x, y).unwrap();
                let CentreBox(row0, row1, col0, col1, _) = CentreBox::of(x, y, rect);
                ties += (row0..row1).any(|py| (col0..col1).any(|px| edges.iter().any(|e| matches!(e.a * px + e.b * py + e.c, 0 | -1)))) as usize;
            }
        }
        assert!(compared > 200_000 && covered > 80_000 && ties > 20_000 && cut > 30_000 && flat > 10_000 && wide > 3_000 && tall_ones > 20_000, "{compared} {covered} {ties} {cut} {flat} {wide} {tall_ones}");
    }

    /// Stepping the span solution row by row gives `span`'s answer for
    /// every row, on triangles as large as the guard band allows.
    #[test]
    fn stepped_rows_match_span() {
        let mut rnd = crate::render::test_rng::below(777, 20);
        let big = 1i64 << 27;
        let mut rows = 0;
        for n in 0..3000 {
            // Large and small triangles, some with horizontal edges.
            let m = if n % 3 == 0 { 64 * ONE } else { big };
            let x = [rnd(m) - m / 2, rnd(m) - m / 2, rnd(m) - m / 2];
            let mut y = [rnd(m) - m / 2, rnd(m) - m / 2, rnd(m) - m / 2];
            if n % 5 == 0 {
                y[1] = y[0];
            }
            let Some((x, y, edges)) = ccw_edges(x, y) else { continue };
            let row0 = y[0].min(y[1]).min(y[2]) / ONE - 2;
            let (x0, x1) = (x[0].min(x[1]).min(x[2]) / ONE - 2, x[0].max(x[1]).max(x[2]) / ONE + 2);
            let mut st = RowStepper::new(&edges, row0);
            for py in row0..row0 + 200 {
                assert_eq!(st.span(x0, x1), span(&edges, py, x0, x1), "row {py} of {x:?} {y:?}");
                rows += (span(&edges, py, x0, x1).0 < span(&edges, py, x0, x1).1) as usize;
                st.step();
            }
        }
        assert!(rows > 100_000, "{rows} covered rows");
    }

    /// The span solution agrees with testing every pixel centre directly.
    #[test]
    fn spans_match_per_pixel_edge_tests() {
        let mut rnd = crate::render::test_rng::below(12345, 33);
        for _ in 0..500 {
            let x = [rnd(32 * ONE), rnd(32 * ONE), rnd(32 * ONE)];
            let y = [rnd(32 * ONE), rnd(32 * ONE), rnd(32 * ONE)];
            let Some((x, y, edges)) = ccw_edges(x, y) else { continue };
            for py in 0..32i64 {
                for px in 0..32i64 {
                    let inside = edges.iter().all(|e| e.a * px + e.b * py + e.c >= 0);
                    let (lo, hi) = span(&edges, py, 0, 32);
                    assert_eq!(inside, px >= lo && px < hi, "pixel {px},{py} of {x:?} {y:?}");
                    let mut st = RowStepper::new(&edges, py - 5);
                    for _ in 0..5 {
                        st.step();
                    }
                    let (lo, hi) = st.span(0, 32);
                    assert_eq!(inside, px >= lo && px < hi, "stepped rows: pixel {px},{py} of {x:?} {y:?}");
                    let (c0, c1) = (px - 3, px + 4);
                    let (lo, hi) = row_span(&edges, py, c0, c1);
                    assert_eq!(inside, px >= lo && px < hi, "narrow scan: pixel {px},{py} of {x:?} {y:?}");
                }
            }
        }
    }
}
