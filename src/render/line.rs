//! Line segments (GL 1.5 section 3.4): clipping (section 2.12), the
//! diamond-exit rule for width 1, wide lines, line stipple, and the
//! interpolation of depth and colour along the segment (equations 3.6-3.8).
//!
//! The diamond-exit rule (3.4.1) is decided exactly. Endpoints snap to
//! 1/256 pixel (`setup::ONE`) like triangle vertices. A fragment at pixel
//! (px, py) is produced when the segment from pa' to pb' meets the open
//! diamond |x - cx| + |y - cy| < 1/2 around the pixel centre, unless pb'
//! lies inside it; pa' and pb' are the endpoints moved by (-ε, -ε²). The
//! perturbation is carried symbolically: every quantity that depends on it
//! is a polynomial a + bε + cε² with integer coefficients, compared
//! lexicographically, so endpoints on diamond corners or edges and lines
//! through corners get exactly the spec's answer, never a rounding's.
//! The segment meets the diamond iff some t in [0, 1] satisfies the four
//! half-plane inequalities, a one-dimensional feasibility problem whose
//! bounds are compared by cross-multiplication (i128, exact: snapped
//! coordinates are bounded by the clip guard band, see `setup`).
//!
//! Candidate pixels: for an x-major segment (|Δx| >= |Δy|) the line meets
//! at most one diamond per pixel column, within one pixel of its height at
//! the column centre, so three rows per column are tested; columns are
//! visited from pa towards pb, which is the order the stipple counter
//! needs. y-major segments swap the roles of x and y.
//!
//! Wide lines (3.4.2, non-antialiased): the width rounds to an integer w
//! (at least 1, at most MAX_WIDTH); the segment moved by -(w-1)/2 along
//! its minor axis is rasterized with width 1, and each fragment becomes a
//! column (x-major) or row (y-major) of w fragments starting there.
//!
//! Stipple (3.4.3): the counter s counts width-1 fragments; a fragment is
//! drawn iff bit (s / repeat) mod 16 of the pattern is set. The caller owns
//! s (reset at glBegin and per GL_LINES segment; kept across a strip).
//! A tile band that draws part of a stippled segment starts s in closed
//! form at its first column (`fragments_before`: one fragment per column
//! the segment crosses, the few columns at its ends walked), so stippled
//! segments are binned like the others.
//!
//! GL_LINE_SMOOTH (3.4.2, "Antialiasing"): the rectangle of the smooth
//! width centred on the segment, by coverage (`smooth_line`, `smooth`);
//! stipple counts 1 x width rectangles instead of fragments.
//!
//! Two paths: the reference (`SOFTGL_REFERENCE=1`) shades each fragment
//! through `fragment::shade_fragment`; the fast path hands the same
//! fragments to `runs::Sink` (a width-w column or row, a smooth line's row
//! piece), computes the colour once when it cannot vary along the segment,
//! depth only when it is tested, steps the column's line height instead
//! of dividing (`fragments_stepped`) and takes unstippled smooth lines'
//! coverage in closed form (`smooth::LineRect`, a row four pixels at a
//! time with AVX2; a constant colour under the untested OVER blend goes
//! to the framebuffer a whole row at once, `runs::Sink::over_covered`,
//! the same bits as cutting it into runs). Aliased results are
//! identical (tests/line_reference_diff.rs); smooth coverages agree within
//! 1e-9 (see `smooth::LineRect`).

use super::clip::Plane;
use super::fragment;
use super::runs;
use super::fog::Fog;
use super::fragment::{Buffers, FragmentState};
use super::setup::{to_window, WindowVertex, ONE};
use super::smooth;
use super::texture::TextureStage;
use super::vertex::ClipVertex;
use super::RenderState;
use crate::framebuffer::{Framebuffer, Rect};
use glam::Vec4;

/// Largest aliased line width (GL_ALIASED_LINE_WIDTH_RANGE's maximum).
pub const MAX_WIDTH: f32 = 64.0;
/// Line state the rasterizer needs.
#[derive(Clone, Copy, Debug)]
pub struct LineParams {
    pub width: f32,
    /// (repeat factor, pattern) when GL_LINE_STIPPLE is enabled.
    pub stipple: Option<(u32, u16)>,
}

/// The rasterization width of a requested width: rounded, in [1, MAX_WIDTH].
pub fn raster_width(width: f32) -> i64 {
    let w = (width.clamp(1.0, MAX_WIDTH) + 0.5).floor() as i64;
    w.clamp(1, MAX_WIDTH as i64)
}

/// Clips a segment in clip coordinates against `planes` (exactly at near,
/// far and user planes, at the guard band in x and y). None when nothing
/// is left.
pub fn clip_segment(planes: &[Plane], a: &ClipVertex, b: &ClipVertex) -> Option<(ClipVertex, ClipVertex)> {
    if !a.pos.is_finite() || !b.pos.is_finite() {
        return None;
    }
    let (mut t0, mut t1) = (0.0f32, 1.0f32);
    for plane in planes {
        let (da, db) = (plane.dist(&a.pos), plane.dist(&b.pos));
        let (a_in, b_in) = (da >= 0.0, db >= 0.0);
        match (a_in, b_in) {
            (true, true) => {}
            (false, false) => return None,
            (false, true) => t0 = t0.max(da / (da - db)),
            (true, false) => t1 = t1.min(da / (da - db)),
        }
    }
    if !(t0 <= t1) {
        return None;
    }
    let na = if t0 > 0.0 { ClipVertex::lerp(a, b, t0) } else { *a };
    let nb = if t1 < 1.0 { ClipVertex::lerp(a, b, t1) } else { *b };
    Some((na, nb))
}

/// a + bε + cε².
type Eps = [i128; 3];

#[inline]
fn eps_lt(a: Eps, b: Eps) -> bool {
    a < b // lexicographic on arrays
}

#[inline]
fn eps_scale(a: Eps, k: i128) -> Eps {
    [a[0] * k, a[1] * k, a[2] * k]
}

const HALF: i128 = (ONE / 2) as i128;
const SIGNS: [(i128, i128); 4] = [(1, 1), (1, -1), (-1, 1), (-1, -1)];

/// The diamond-exit rule for the pixel whose centre is (cx, cy), for the
/// segment (xa, ya) -> (xb, yb); all in 1/ONE pixel units.
pub fn diamond_exit(xa: i64, ya: i64, xb: i64, yb: i64, cx: i64, cy: i64) -> bool {
    let (xa, ya, xb, yb, cx, cy) = (xa as i128, ya as i128, xb as i128, yb as i128, cx as i128, cy as i128);
    // pb' inside the open diamond: excluded.
    let b_inside = SIGNS.iter().all(|&(sx, sy)| eps_lt([sx * (xb - cx) + sy * (yb - cy), -sx, -sy], [HALF, 0, 0]));
    if b_inside {
        return false;
    }
    let (dx, dy) = (xb - xa, yb - ya);
    // Bounds on t: value num/den with den > 0.
    let mut lower: [(Eps, i128); 4] = [([0; 3], 1); 4];
    let mut upper: [(Eps, i128); 4] = [([0; 3], 1); 4];
    let (mut nl, mut nu) = (0, 0);
    for &(sx, sy) in &SIGNS {
        let alpha: Eps = [sx * (xa - cx) + sy * (ya - cy), -sx, -sy];
        let beta = sx * dx + sy * dy;
        // alpha + beta t < HALF
        if beta > 0 {
            upper[nu] = ([HALF - alpha[0], -alpha[1], -alpha[2]], beta);
            nu += 1;
        } else if beta < 0 {
            lower[nl] = ([alpha[0] - HALF, alpha[1], alpha[2]], -beta);
            nl += 1;
        } else if !eps_lt(alpha, [HALF, 0, 0]) {
            return false;
        }
    }
    // t in [0, 1] with t > every lower bound and t < every upper bound.
    for &(n, d) in &lower[..nl] {
        if !eps_lt(n, [d, 0, 0]) {
            return false;
        }
    }
    for &(n, _) in &upper[..nu] {
        if !eps_lt([0; 3], n) {
            return false;
        }
    }
    for &(ln, ld) in &lower[..nl] {
        for &(un, ud) in &upper[..nu] {
            if !eps_lt(eps_scale(ln, ud), eps_scale(un, ld)) {
                return false;
            }
        }
    }
    true
}

#[inline]
fn floor_div(n: i64, d: i64) -> i64 {
    n.div_euclid(d)
}

/// The diamond-exit rule where the segment spans the diamond of the pixel
/// centred at (cm, cn) along its major axis (major, minor coordinates,
/// segment from (ma, na) with direction (dm, dn), |dn| <= |dm|): neither
/// endpoint is near the diamond, so the segment meets it iff its line
/// does, and a line of slope at most 1 meets the open diamond iff at the
/// centre's major coordinate it passes less than 1/2 from the centre
/// (moving d along the major axis, the line moves at most |d| while the
/// diamond narrows by exactly |d|). The endpoints' perturbation by
/// epsilon only matters at exactly 1/2: None then, for [`diamond_exit`].
#[inline]
fn interior_hit(ma: i64, na: i64, dm: i64, dn: i64, cm: i64, cn: i64) -> Option<bool> {
    // (line's minor coordinate at cm - cn) * dm, exactly (|values| < 2^57).
    let num = (na - cn) * dm + dn * (cm - ma);
    let lim = (ONE / 2) * dm.abs();
    (num.abs() != lim).then_some(num.abs() < lim)
}

/// The width-1 fragments of the segment (xa, ya) -> (xb, yb) (1/ONE pixel
/// units), in order from a to b, limited to major-axis pixels in
/// [lo, hi). `emit(px, py)` receives each.
pub fn fragments(xa: i64, ya: i64, xb: i64, yb: i64, lo: i64, hi: i64, mut emit: impl FnMut(i64, i64)) {
    let (dx, dy) = (xb - xa, yb - ya);
    if dx == 0 && dy == 0 {
        return;
    }
    let x_major = dx.abs() >= dy.abs();
    // Work in (major, minor) coordinates.
    let (ma, na, mb, nb) = if x_major { (xa, ya, xb, yb) } else { (ya, xa, yb, xb) };
    let (dm, dn) = (mb - ma, nb - na);
    let first = (floor_div(ma.min(mb), ONE) - 1).max(lo);
    let last = (floor_div(ma.max(mb), ONE) + 1).min(hi - 1);
    if first > last {
        return;
    }
    let step = if dm > 0 { 1 } else { -1 };
    let (mut p, end) = if dm > 0 { (first, last) } else { (last, first) };
    let seg = Segment { xa, ya, xb, yb, x_major, ma, na, dm, dn, lo_m: ma.min(mb), hi_m: ma.max(mb) };
    loop {
        let cm = p * ONE + ONE / 2;
        // Minor coordinate of the line at the column centre (floored).
        // (|dn * (cm - ma)| < 2^57: exact in i64, one hardware division.)
        let n_at = na + (dn * (cm - ma)).div_euclid(dm);
        column_hits(&seg, p, n_at, &mut emit);
        if p == end {
            break;
        }
        p += step;
    }
}

/// A segment in window fixed point (`ONE` per pixel) as the column walks of
/// [`fragments`] and [`fragments_stepped`] see it: its ends, its major
/// axis, and its major/minor start, deltas and major extent.
struct Segment {
    xa: i64,
    ya: i64,
    xb: i64,
    yb: i64,
    x_major: bool,
    ma: i64,
    na: i64,
    dm: i64,
    dn: i64,
    lo_m: i64,
    hi_m: i64,
}

/// The diamond-exit test for the three candidate pixels of major column
/// `p`, where the line's minor coordinate at the column centre is `n_at`
/// (floored); emits the hits as (x, y) in minor order.
#[inline(always)]
fn column_hits(s: &Segment, p: i64, n_at: i64, emit: &mut impl FnMut(i64, i64)) {
    let cm = p * ONE + ONE / 2;
    let r0 = n_at.div_euclid(ONE);
    // The segment spans this column's diamonds from side to side (both
    // endpoints at least one unit beyond them): see `interior_hit`.
    let interior = s.lo_m <= cm - ONE / 2 - 1 && s.hi_m >= cm + ONE / 2 + 1;
    for q in r0 - 1..=r0 + 1 {
        let cn = q * ONE + ONE / 2;
        let hit = match interior.then(|| interior_hit(s.ma, s.na, s.dm, s.dn, cm, cn)).flatten() {
            Some(h) => h,
            None if s.x_major => diamond_exit(s.xa, s.ya, s.xb, s.yb, cm, cn),
            None => diamond_exit(s.xa, s.ya, s.xb, s.yb, cn, cm),
        };
        if hit {
            if s.x_major {
                emit(p, q)
            } else {
                emit(q, p)
            }
        }
    }
}

/// [`fragments`] for the fast path: the same fragments in the same order,
/// with the column's line height stepped exactly instead of divided: the
/// quotient and remainder of `dn * (cm - ma)` by `dm` advance by those of
/// `dn * ONE` per column (one compare carries the remainder), so no
/// hardware division runs per column.
pub fn fragments_stepped(xa: i64, ya: i64, xb: i64, yb: i64, lo: i64, hi: i64, mut emit: impl FnMut(i64, i64)) {
    let (dx, dy) = (xb - xa, yb - ya);
    if dx == 0 && dy == 0 {
        return;
    }
    let x_major = dx.abs() >= dy.abs();
    let (ma, na, mb, nb) = if x_major { (xa, ya, xb, yb) } else { (ya, xa, yb, xb) };
    let (dm, dn) = (mb - ma, nb - na);
    let first = (floor_div(ma.min(mb), ONE) - 1).max(lo);
    let last = (floor_div(ma.max(mb), ONE) + 1).min(hi - 1);
    if first > last {
        return;
    }
    let step = if dm > 0 { 1 } else { -1 };
    let (mut p, end) = if dm > 0 { (first, last) } else { (last, first) };
    let seg = Segment { xa, ya, xb, yb, x_major, ma, na, dm, dn, lo_m: ma.min(mb), hi_m: ma.max(mb) };
    // a = dn * (cm - ma) = quot * dm + rem, 0 <= rem < |dm| (div_euclid).
    let cm0 = p * ONE + ONE / 2;
    let a = dn * (cm0 - ma);
    let (mut quot, mut rem) = (a.div_euclid(dm), a.rem_euclid(dm));
    let da = dn * ONE * step;
    let (dq, dr) = (da.div_euclid(dm), da.rem_euclid(dm));
    let (adm, sdm) = (dm.abs(), dm.signum());
    loop {
        column_hits(&seg, p, na + quot, &mut emit);
        if p == end {
            break;
        }
        p += step;
        quot += dq;
        rem += dr;
        if rem >= adm {
            rem -= adm;
            quot += sdm;
        }
    }
}

/// How many width-1 fragments the segment (xa, ya) -> (xb, yb) has in
/// the major-axis pixels that [`fragments`] visits before pixel `p` (in
/// its order, from a towards b): the stipple counter's advance at `p`,
/// without walking the segment. A column the segment spans from side to
/// side with a unit to spare (`column_hits`' interior columns) holds
/// exactly one fragment: at most one because a line of slope at most 1
/// meets at most one diamond per column (`interior_hit`), at least one
/// because at the column's centre the line lies strictly inside one
/// diamond (on a boundary only where the exact rule's epsilon moves it off
/// to one side). So only the few columns near the ends are walked.
pub fn fragments_before(xa: i64, ya: i64, xb: i64, yb: i64, p: i64) -> u64 {
    let (dx, dy) = (xb - xa, yb - ya);
    if dx == 0 && dy == 0 {
        return 0;
    }
    let (ma, mb) = if dx.abs() >= dy.abs() { (xa, xb) } else { (ya, yb) };
    let (lo_m, hi_m) = (ma.min(mb), ma.max(mb));
    let (first, last) = (floor_div(lo_m, ONE) - 1, floor_div(hi_m, ONE) + 1);
    // The columns before p in the walk's order, as the range [u, v).
    let (u, v) = if mb > ma { (first, p.min(last + 1)) } else { ((p + 1).max(first), last + 1) };
    if u >= v {
        return 0;
    }
    let walked = |a: i64, b: i64| {
        let mut n = 0u64;
        if a < b {
            fragments_stepped(xa, ya, xb, yb, a, b, |_, _| n += 1);
        }
        n
    };
    // Interior columns: lo_m <= p * ONE - 1 and hi_m >= p * ONE + ONE + 1.
    let (ilo, ihi) = (floor_div(lo_m + ONE, ONE), floor_div(hi_m - ONE - 1, ONE));
    if ilo > ihi {
        return walked(u, v);
    }
    let inner = (v.min(ihi + 1) - u.max(ilo)).max(0) as u64;
    walked(u, v.min(ilo)) + inner + walked(u.max(ihi + 1), v)
}

/// Draws one segment given in clip coordinates. `flat_color` is the
/// provoking vertex's colour; `s` is the stipple counter.
pub fn draw_line(rs: &RenderState, fb: &mut Framebuffer, lp: &LineParams, a: &ClipVertex, b: &ClipVertex, flat_color: Vec4, s: &mut u32) {
    let r = rs.draw_rect;
    if r.is_empty() {
        return;
    }
    let Some((a, b)) = clip_segment(&rs.clip_planes, a, b) else { return };
    let (wa, wb) = (to_window(rs, &a), to_window(rs, &b));
    let snap = |c: f64| (c * ONE as f64).round() as i64;
    let (xa, ya, xb, yb) = (snap(wa.x), snap(wa.y), snap(wb.x), snap(wb.y));
    if xa == xb && ya == yb {
        return;
    }
    let flat = if rs.flat { Some(fragment::color_to_u8(flat_color)) } else { None };
    let line = LineRun::new(wa, wb, [xa, ya, xb, yb], flat, lp, rs.smooth.line.is_some(), *s);
    let env = LineEnv { fs: &rs.fragment, texture: rs.texture.as_deref(), fog: rs.fog.as_ref() };
    if !rs.reference && !(line.smooth && line.stipple.is_some()) {
        // The fast path (stippled smooth lines keep the reference code).
        let bbox = line.bounds(r);
        // A stippled segment's band starts its counter in closed form
        // (`fragments_before`), so segments of any height are binned.
        if super::tile::binning(rs) && !fb.draw_both {
            // Shaded later, band by band, in the tile workers; the
            // counter moves on as drawing would move it.
            *s = line.stipple_end();
            if !bbox.is_empty() && super::tile::push_line(rs, line, bbox) {
                super::tile::submit_binned(rs, fb);
            }
            return;
        }
        // Drawn now: after the binned primitives.
        super::tile::sync(rs, fb);
        let sink = runs::Sink::new(&rs.fragment, fb);
        let width = fb.width;
        line.draw(&env, &sink, fb, width, r);
        *s = line.stipple_end();
        return;
    }
    super::tile::sync(rs, fb);
    let fs = &rs.fragment;
    let (t_at, color_at) = (|px, py| line.t_at(px, py), |t| line.color_at(&env, t));
    let (wa, wb) = (&line.wa, &line.wb);
    if let Some(quality) = rs.smooth.line {
        let f = line.unit();
        return smooth_line(rs, fb, lp, f, s, quality, |fb, px, py, cov| {
            let t = t_at(px, py);
            let c = color_at(t);
            let mut color = fragment::color_to_u8(c);
            color[3] = smooth::alpha_u8(c.w as f64 * cov);
            fragment::shade_fragment(fs, fb, px as usize, py as usize, wa.z + t * (wb.z - wa.z), color);
        });
    }
    let shade = |fb: &mut Framebuffer, px: i64, py: i64| {
        if px < r.x0 as i64 || px >= r.x1 as i64 || py < r.y0 as i64 || py >= r.y1 as i64 {
            return;
        }
        let t = t_at(px, py);
        let z = wa.z + t * (wb.z - wa.z);
        fragment::shade_fragment(fs, fb, px as usize, py as usize, z, fragment::color_to_u8(color_at(t)));
    };
    let ([sxa, sya, sxb, syb], x_major, (lo, hi)) = (line.shifted(), line.x_major(), line.major_range(r));
    let w = line.w;
    // With stipple, fragments outside the draw rectangle still advance the
    // counter, so the whole (guard-band-clipped) segment is walked.
    let (lo, hi) = if lp.stipple.is_some() { (i64::MIN / 4, i64::MAX / 4) } else { (lo, hi) };
    fragments(sxa, sya, sxb, syb, lo, hi, |px, py| {
        if let Some((repeat, pattern)) = lp.stipple {
            let bit = (*s / repeat) % 16;
            *s = s.wrapping_add(1);
            if pattern & (1 << bit) == 0 {
                return;
            }
        }
        for k in 0..w {
            if x_major {
                shade(fb, px, py + k)
            } else {
                shade(fb, px + k, py)
            }
        }
    });
}

/// What a segment's fragments read of the state besides its own record.
pub struct LineEnv<'a> {
    pub fs: &'a FragmentState,
    pub texture: Option<&'a TextureStage>,
    pub fog: Option<&'a Fog>,
}

/// A segment after clipping and snapping, as the fast path draws it (at
/// once, or later in the tile workers band by band: everything a fragment
/// depends on is here or in [`LineEnv`], nothing on the rectangle drawn).
#[derive(Clone, Copy, Debug)]
pub struct LineRun {
    wa: WindowVertex,
    wb: WindowVertex,
    /// The snapped endpoints (1/ONE pixel).
    xa: i64,
    ya: i64,
    xb: i64,
    yb: i64,
    /// The flat colour, when flat shaded.
    flat: Option<[u8; 4]>,
    /// Aliased width, and half the smooth width.
    w: i64,
    hw: f64,
    smooth: bool,
    stipple: Option<(u32, u16)>,
    /// The stipple counter at the segment's start.
    s0: u32,
    /// `unit()` and its squared length, computed once.
    f: [f64; 4],
    len2: f64,
}

impl LineRun {
    fn new(wa: WindowVertex, wb: WindowVertex, [xa, ya, xb, yb]: [i64; 4], flat: Option<[u8; 4]>, lp: &LineParams, smooth: bool, s0: u32) -> LineRun {
        let inv = 1.0 / ONE as f64;
        let f = [xa as f64 * inv, ya as f64 * inv, (xb - xa) as f64 * inv, (yb - ya) as f64 * inv];
        let len2 = f[2] * f[2] + f[3] * f[3];
        LineRun { wa, wb, xa, ya, xb, yb, flat, w: raster_width(lp.width), hw: smooth::smooth_size(lp.width) / 2.0, smooth, stipple: lp.stipple, s0, f, len2 }
    }

    fn x_major(&self) -> bool {
        (self.xb - self.xa).abs() >= (self.yb - self.ya).abs()
    }

    /// The width-1 segment whose fragments start the wide line's columns
    /// (x-major) or rows: moved by -(w - 1) / 2 along the minor axis.
    fn shifted(&self) -> [i64; 4] {
        let shift = (self.w - 1) * ONE / 2;
        let (xa, ya, xb, yb) = (self.xa, self.ya, self.xb, self.yb);
        if self.x_major() {
            [xa, ya - shift, xb, yb - shift]
        } else {
            [xa - shift, ya, xb - shift, yb]
        }
    }

    /// The major-axis pixels of `r`.
    fn major_range(&self, r: Rect) -> (i64, i64) {
        if self.x_major() {
            (r.x0 as i64, r.x1 as i64)
        } else {
            (r.y0 as i64, r.y1 as i64)
        }
    }

    /// [x, y, dx, dy] of the snapped segment in pixels.
    #[inline]
    fn unit(&self) -> [f64; 4] {
        self.f
    }

    /// t of the pixel centre projected on the segment (3.4.1 equation 3.6).
    #[inline]
    fn t_at(&self, px: i64, py: i64) -> f64 {
        let [fxa, fya, fdx, fdy] = self.f;
        (((px as f64 + 0.5 - fxa) * fdx + (py as f64 + 0.5 - fya) * fdy) / self.len2).clamp(0.0, 1.0)
    }

    /// The fragment colour at parameter t (3.4.1 equation 3.7): texturing,
    /// the colour sum and fog when on, perspective-correct through 1/w.
    fn color_at(&self, env: &LineEnv, t: f64) -> Vec4 {
        let (wa, wb) = (&self.wa, &self.wb);
        let [_, _, fdx, fdy] = self.unit();
        // The parameter change of one pixel along the major axis (texture LOD).
        let step = 1.0 / fdx.abs().max(fdy.abs());
        let (ka, kb) = ((1.0 - t) * wa.q, t * wb.q);
        let primary = match self.flat {
            Some(c) => Vec4::from_array(c.map(|v| v as f32 / 255.0)),
            None => ((wa.color.as_dvec4() * ka + wb.color.as_dvec4() * kb) / (ka + kb)).as_vec4().clamp(Vec4::ZERO, Vec4::ONE),
        };
        let mut c = match env.texture {
            Some(stage) => {
                let c = stage.shade(&super::texture::line_coords(stage, &wa.tex, wa.q, &wb.tex, wb.q, t, step), primary);
                // The colour sum (3.9) after texturing.
                let sec = ((wa.secondary.as_dvec4() * ka + wb.secondary.as_dvec4() * kb) / (ka + kb)).as_vec4();
                (c.truncate() + sec.truncate()).extend(c.w).clamp(Vec4::ZERO, Vec4::ONE)
            }
            None => primary,
        };
        if let Some(f) = env.fog {
            c = f.apply(c, ((wa.fog as f64 * ka + wb.fog as f64 * kb) / (ka + kb)) as f32);
        }
        c
    }

    /// A rectangle of `r` holding every fragment the segment may produce
    /// there (a superset: the endpoints widened by the width and two pixels).
    pub fn bounds(&self, r: Rect) -> Rect {
        let m = if self.smooth { self.hw.ceil() as i64 + 2 } else { self.w + 2 };
        let px = |c: i64| c.div_euclid(ONE);
        let fit = |v: i64, lo: i32, hi: i32| v.max(lo as i64).min(hi as i64) as i32;
        Rect {
            x0: fit(px(self.xa.min(self.xb)) - m, r.x0, r.x1),
            x1: fit(px(self.xa.max(self.xb)) + m + 1, r.x0, r.x1),
            y0: fit(px(self.ya.min(self.yb)) - m, r.y0, r.y1),
            y1: fit(px(self.ya.max(self.yb)) + m + 1, r.y0, r.y1),
        }
    }

    /// About how many fragments the segment has (work, for `tile`).
    pub fn work(&self) -> u64 {
        let len = ((self.xb - self.xa).abs().max((self.yb - self.ya).abs()) / ONE) as u64 + 1;
        let across = if self.smooth { 2 * self.hw.ceil() as u64 + 2 } else { self.w as u64 };
        len.saturating_mul(across)
    }

    /// The stipple counter after the segment: drawing counts every
    /// width-1 fragment of the whole segment (aliased lines; the fast path
    /// draws no stippled smooth line).
    pub fn stipple_end(&self) -> u32 {
        if self.stipple.is_none() || self.smooth {
            return self.s0;
        }
        self.stipple_at(if self.forward() { i64::MAX / 4 } else { i64::MIN / 4 })
    }

    /// Whether the walk from a to b goes up its major axis.
    fn forward(&self) -> bool {
        if self.x_major() {
            self.xb > self.xa
        } else {
            self.yb > self.ya
        }
    }

    /// The stipple counter at major-axis pixel `p`: after the fragments
    /// of the pixels before `p` in the walk's order (`fragments_before`).
    fn stipple_at(&self, p: i64) -> u32 {
        let [sxa, sya, sxb, syb] = self.shifted();
        self.s0.wrapping_add(fragments_before(sxa, sya, sxb, syb, p) as u32)
    }

    /// The fast path: the segment's fragments within `r` (inside the
    /// draw rectangle and the framebuffer, `width` wide) in runs through
    /// `sink`, depth only when tested, the colour once per segment when it
    /// cannot vary along it (no texture or fog, flat shading or equal
    /// colours at both ends: the interpolation of equal f32 values rounds
    /// back to them). Returns the stipple counter after the pixels walked
    /// (those that may reach `r`): the segment's end counter is
    /// `stipple_end`, which a band's draw does not need.
    pub fn draw(&self, env: &LineEnv, sink: &runs::Sink, fb: &mut impl Buffers, width: usize, r: Rect) -> u32 {
        let (wa, wb) = (&self.wa, &self.wb);
        let depth = |px: i64, py: i64| fragment::depth_to_fixed(wa.z + self.t_at(px, py) * (wb.z - wa.z));
        let constant = (env.texture.is_none() && env.fog.is_none() && (self.flat.is_some() || wa.color == wb.color)).then(|| self.color_at(env, 0.0));
        let mut s = self.s0;
        match (self.smooth, constant) {
            (true, Some(c)) => {
                let (cu, cw) = (fragment::color_to_u8(c), c.w as f64);
                smooth_line_fast(r, fb, width, sink, self.unit(), self.hw, Some((cu, cw)), depth, |_, _| (cu, cw));
            }
            (true, None) => {
                smooth_line_fast(r, fb, width, sink, self.unit(), self.hw, None, depth, |px, py| {
                    let c = self.color_at(env, self.t_at(px, py));
                    (fragment::color_to_u8(c), c.w as f64)
                });
            }
            (false, Some(c)) => {
                let cu = fragment::color_to_u8(c);
                self.aliased_fast(r, fb, width, sink, &mut s, depth, |_, _| cu);
            }
            (false, None) => {
                self.aliased_fast(r, fb, width, sink, &mut s, depth, |px, py| fragment::color_to_u8(self.color_at(env, self.t_at(px, py))));
            }
        }
        s
    }

    /// The major-axis pixels whose fragments may fall in rows [y0, y1) of
    /// an x-major segment (a superset: the line's height at a
    /// column is within a pixel of its fragment, whose run is `w` high);
    /// all of `lo..hi` otherwise. A tile worker's band walks only these.
    fn band_columns(&self, (lo, hi): (i64, i64), r: Rect) -> (i64, i64) {
        let [sxa, sya, sxb, syb] = self.shifted();
        let (dx, dy) = (sxb - sxa, syb - sya);
        if !self.x_major() || dy == 0 {
            return (lo, hi);
        }
        // Columns where the line's height is within [y0 - w - 2, y1 + 2].
        let inv = 1.0 / ONE as f64;
        let at = |y: i64| sxa as f64 * inv + ((y as f64) - sya as f64 * inv) * (dx as f64 / dy as f64);
        let (ya, yb) = (r.y0 as i64 - self.w - 2, r.y1 as i64 + 2);
        let (p, q) = (at(ya), at(yb));
        let (first, last) = (p.min(q).floor() - 2.0, p.max(q).ceil() + 2.0);
        if !(first.is_finite() && last.is_finite()) {
            return (lo, hi);
        }
        (lo.max(first as i64), hi.min(last as i64 + 1))
    }

    /// The fast path's aliased segment: `fragments` and the stipple as in
    /// `draw_line`'s reference code, each width-1 fragment's column
    /// (x-major) or row (y-major) of `w` cut to `r` and run through `sink`.
    #[allow(clippy::too_many_arguments)]
    fn aliased_fast(&self, r: Rect, fb: &mut impl Buffers, width: usize, sink: &runs::Sink, s: &mut u32, depth: impl Fn(i64, i64) -> u32, color: impl Fn(i64, i64) -> [u8; 4]) {
        let (rx0, ry0, rx1, ry1) = (r.x0 as i64, r.y0 as i64, r.x1 as i64, r.y1 as i64);
        let ([sxa, sya, sxb, syb], x_major, w, stipple) = (self.shifted(), self.x_major(), self.w, self.stipple);
        // Only the columns that may reach `r` are walked; with stipple the
        // counter starts at the first of them in the walk's order, as if
        // the fragments before (outside `r` too) had been counted.
        let (lo, hi) = self.band_columns(self.major_range(r), r);
        if stipple.is_some() {
            *s = self.stipple_at(if self.forward() { lo } else { hi - 1 });
        }
        fragments_stepped(sxa, sya, sxb, syb, lo, hi, |px, py| {
            if let Some((repeat, pattern)) = stipple {
                let bit = (*s / repeat) % 16;
                *s = s.wrapping_add(1);
                if pattern & (1 << bit) == 0 {
                    return;
                }
            }
            if x_major {
                let (y0, y1) = (py.max(ry0), (py + w).min(ry1));
                if px < rx0 || px >= rx1 || y0 >= y1 {
                    return;
                }
                let i0 = y0 as usize * width + px as usize;
                sink.run(fb, i0, (y1 - y0) as usize, width, |k| depth(px, y0 + k as i64), |k| color(px, y0 + k as i64));
            } else {
                let (x0, x1) = (px.max(rx0), (px + w).min(rx1));
                if py < ry0 || py >= ry1 || x0 >= x1 {
                    return;
                }
                let i0 = py as usize * width + x0 as usize;
                sink.run(fb, i0, (x1 - x0) as usize, 1, |k| depth(x0 + k as i64, py), |k| color(x0 + k as i64, py));
            }
        });
    }
}

/// The fast path's unstippled smooth segment [x, y, dx, dy] of half width
/// `hw`: row by row, the pixels of positive coverage (`smooth::LineRect`)
/// in runs through `sink`; `color` gives a pixel's colour and its alpha
/// before coverage, which scales it as in `draw_line`'s reference code.
/// `constant` is that colour when it is the same for every pixel: under
/// the untested OVER blend a row then goes to the sink whole
/// (`Sink::over_covered`: the same fragments, without cutting the row
/// into runs).
#[allow(clippy::too_many_arguments)]
fn smooth_line_fast(
    r: Rect,
    fb: &mut impl Buffers,
    width: usize,
    sink: &runs::Sink,
    [x, y, dx, dy]: [f64; 4],
    hw: f64,
    constant: Option<([u8; 4], f64)>,
    depth: impl Fn(i64, i64) -> u32,
    color: impl Fn(i64, i64) -> ([u8; 4], f64),
) {
    let Some(lr) = smooth::LineRect::new(x, y, dx, dy, hw) else { return };
    let mut buf: Vec<f64> = Vec::with_capacity(64);
    let over = constant.filter(|_| sink.is_over());
    for py in lr.rows(r) {
        let cols = lr.cols(py, r);
        let cov = lr.row_coverage(py, cols.clone(), &mut buf);
        if let Some((rgb, a)) = over {
            if !cov.is_empty() {
                sink.over_covered(fb, py as usize * width + cols.start as usize, cov, rgb, a);
            }
            continue;
        }
        let mut k = 0;
        while k < cov.len() {
            if cov[k] <= 0.0 {
                k += 1;
                continue;
            }
            let start = k;
            while k < cov.len() && cov[k] > 0.0 {
                k += 1;
            }
            let x0 = cols.start + start as i64;
            let covs = &cov[start..k];
            sink.run(fb, py as usize * width + x0 as usize, k - start, 1, |j| depth(x0 + j as i64, py), |j| {
                let (mut c, a) = color(x0 + j as i64, py);
                c[3] = smooth::alpha_u8(a * covs[j]);
                c
            });
        }
    }
}

/// GL_LINE_SMOOTH (3.4.2, "Antialiasing"): the rectangle of the smooth
/// width centred on the segment [x, y, dx, dy] (window coordinates, from
/// the snapped endpoints), by coverage. With stipple, the segment is a
/// sequence of 1 x width rectangles counted on from `*s`; runs of those
/// whose pattern bit is set are each a rectangle, and a pixel two runs
/// share gets one fragment with the sum of their coverages. `*s` advances
/// by the number of rectangles, ceil(length).
#[allow(clippy::too_many_arguments)]
fn smooth_line(
    rs: &RenderState,
    fb: &mut Framebuffer,
    lp: &LineParams,
    [x, y, dx, dy]: [f64; 4],
    s: &mut u32,
    quality: smooth::Quality,
    mut shade: impl FnMut(&mut Framebuffer, i64, i64, f64),
) {
    let len = (dx * dx + dy * dy).sqrt();
    if !(len > 0.0) || !len.is_finite() {
        return;
    }
    let hw = smooth::smooth_size(lp.width) / 2.0;
    let (ux, uy) = (dx / len, dy / len);
    // The rectangle between lengths l0 and l1 along the segment,
    // counter-clockwise.
    let rect = |l0: f64, l1: f64| -> [smooth::P; 4] {
        let (ax, ay, bx, by) = (x + ux * l0, y + uy * l0, x + ux * l1, y + uy * l1);
        let (nx, ny) = (-uy * hw, ux * hw);
        [(ax - nx, ay - ny), (bx - nx, by - ny), (bx + nx, by + ny), (ax + nx, ay + ny)]
    };
    // The point test for GL_FASTEST's samples: inside the run [l0, l1).
    let inside = |l0: f64, l1: f64| {
        move |px: f64, py: f64| {
            let (rx, ry) = (px - x, py - y);
            let along = rx * ux + ry * uy;
            let across = -rx * uy + ry * ux;
            along >= l0 && along < l1 && across.abs() <= hw
        }
    };
    let Some((repeat, pattern)) = lp.stipple else {
        let q = rect(0.0, len);
        smooth::convex_pixels(&q, rs.draw_rect, quality, inside(0.0, len), |px, py, cov| shade(fb, px, py, cov));
        return;
    };
    let n = len.ceil().min(u32::MAX as f64) as u32;
    let on = |k: u32| pattern & (1 << ((s.wrapping_add(k) / repeat) % 16)) != 0;
    let mut acc: std::collections::HashMap<(i64, i64), f64> = std::collections::HashMap::new();
    let mut order = Vec::new();
    let mut k = 0;
    while k < n {
        if !on(k) {
            k += 1;
            continue;
        }
        let start = k;
        while k < n && on(k) {
            k += 1;
        }
        let (l0, l1) = (start as f64, (k as f64).min(len));
        let q = rect(l0, l1);
        smooth::convex_pixels(&q, rs.draw_rect, quality, inside(l0, l1), |px, py, cov| {
            let e = acc.entry((px, py)).or_insert_with(|| {
                order.push((px, py));
                0.0
            });
            *e += cov;
        });
    }
    *s = s.wrapping_add(n);
    for p in order {
        shade(fb, p.0, p.1, acc[&p].min(1.0));
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The stepped enumeration gives the reference enumeration's
    /// fragments in the same order, on segments of every slope and
    /// direction, clipped to a column range or not.
    #[test]
    fn stepped_fragments_match() {
        let mut rnd = crate::render::test_rng::below(9, 33);
        let mut total = 0;
        for k in 0..20000 {
            let unit = if k % 3 == 0 { ONE / 4 } else { 1 };
            let span = if k % 5 == 0 { 400 } else { 40 };
            let mut c = || rnd(span * ONE / unit) * unit - span / 2 * ONE;
            let (xa, ya, xb, yb) = (c(), c(), c(), c());
            let (lo, hi) = if k % 4 == 0 { (rnd(20) - 10, rnd(20) + 5) } else { (i64::MIN / 4, i64::MAX / 4) };
            let (mut a, mut b) = (Vec::new(), Vec::new());
            fragments(xa, ya, xb, yb, lo, hi, |x, y| a.push((x, y)));
            fragments_stepped(xa, ya, xb, yb, lo, hi, |x, y| b.push((x, y)));
            assert_eq!(a, b, "segment ({xa},{ya})-({xb},{yb}) columns {lo}..{hi}");
            total += a.len();
        }
        assert!(total > 100_000, "{total}");
    }

    /// The closed-form stipple count (`fragments_before`) is the number
    /// of fragments a walk from a meets before each pixel of the major
    /// axis, both directions, on segments often through pixel centres and
    /// diamond corners (quarter pixels), of slope 0 and 1, short and long.
    #[test]
    fn fragments_before_counts_the_walk() {
        let mut rnd = crate::render::test_rng::below(11, 33);
        let mut checked = 0;
        for k in 0..6000 {
            let unit = if k % 2 == 0 { ONE / 4 } else { 1 };
            let span = if k % 7 == 0 { 4 } else { 60 };
            let mut c = || rnd(span * ONE / unit) * unit - span / 2 * ONE;
            let (xa, ya) = (c(), c());
            let (mut xb, mut yb) = (c(), c());
            match k % 5 {
                0 => yb = ya,                             // horizontal
                1 => yb = ya + (xb - xa) * if k % 2 == 0 { 1 } else { -1 }, // slope 1
                2 => xb = xa,                             // vertical
                _ => {}
            }
            let (dx, dy) = (xb - xa, yb - ya);
            let x_major = dx.abs() >= dy.abs();
            let forward = if x_major { dx > 0 } else { dy > 0 };
            let mut walk = Vec::new();
            fragments(xa, ya, xb, yb, i64::MIN / 4, i64::MAX / 4, |x, y| walk.push(if x_major { x } else { y }));
            for p in -span..span {
                let before = walk.iter().filter(|&&m| if forward { m < p } else { m > p }).count() as u64;
                assert_eq!(fragments_before(xa, ya, xb, yb, p), before, "segment ({xa},{ya})-({xb},{yb}) pixel {p}");
                checked += 1;
            }
            let end = if forward { i64::MAX / 4 } else { i64::MIN / 4 };
            assert_eq!(fragments_before(xa, ya, xb, yb, end), walk.len() as u64, "segment ({xa},{ya})-({xb},{yb}) whole");
        }
        assert!(checked > 200_000, "{checked}");
    }

    /// The interior shortcut agrees with the exact rule wherever it
    /// answers, on segments whose coordinates often lie on pixel centres,
    /// diamond corners and edges (multiples of 1/4 pixel), slopes 1 included.
    #[test]
    fn interior_hits_agree_with_diamond_exit() {
        let mut rnd = crate::render::test_rng::below(5, 33);
        let (mut decided, mut ties) = (0, 0);
        for k in 0..20000 {
            let unit = if k % 2 == 0 { ONE / 4 } else { 1 };
            let mut c = || rnd(40 * ONE / unit) * unit - 20 * ONE;
            let (xa, ya, xb, yb) = (c(), c(), c(), c());
            let (dx, dy) = (xb - xa, yb - ya);
            if dx == 0 && dy == 0 {
                continue;
            }
            let x_major = dx.abs() >= dy.abs();
            let (ma, na, mb, nb) = if x_major { (xa, ya, xb, yb) } else { (ya, xa, yb, xb) };
            let (dm, dn) = (mb - ma, nb - na);
            for p in -21..21 {
                let cm = p * ONE + ONE / 2;
                if !(ma.min(mb) <= cm - ONE / 2 - 1 && ma.max(mb) >= cm + ONE / 2 + 1) {
                    continue;
                }
                for q in -22..22 {
                    let cn = q * ONE + ONE / 2;
                    let exact = if x_major { diamond_exit(xa, ya, xb, yb, cm, cn) } else { diamond_exit(xa, ya, xb, yb, cn, cm) };
                    match interior_hit(ma, na, dm, dn, cm, cn) {
                        Some(h) => {
                            assert_eq!(h, exact, "segment ({xa},{ya})-({xb},{yb}) pixel centre {cm},{cn}");
                            decided += 1;
                        }
                        None => ties += 1,
                    }
                }
            }
        }
        assert!(decided > 100_000 && ties > 100, "{decided} {ties}");
    }
}
