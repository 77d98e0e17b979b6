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
use std::mem::MaybeUninit;
use std::ptr::addr_of_mut;

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
    // Round 12: the binning path in a function of its own (a jump from
    // here), so that neither path's code is compiled around the other's
    // (both inlined here cost the shading path about 12 instructions a
    // triangle).
    if binned_here(rs, fb) {
        return bin_placed(rs, fb, v, flat_color);
    }
    let pos = v.map(|cv| cv.win);
    let fx = v.map(|cv| cv.snapped[0]);
    let fy = v.map(|cv| cv.snapped[1]);
    let Some(o) = oriented(rs, fx, fy) else { return };
    shade_snapped(rs, fb, pos, fx, fy, v, flat_color, o)
}

/// [`triangle_placed`] while binning ([`binned_here`]; the batched
/// vertex path calls it directly, having tested that once per flush).
#[inline(never)]
pub(crate) fn bin_placed(rs: &RenderState, fb: &mut crate::framebuffer::Framebuffer, v: [&ClipVertex; 3], flat_color: [Vec4; 2]) {
    let pos = v.map(|cv| cv.win);
    let fx = v.map(|cv| cv.snapped[0]);
    let fy = v.map(|cv| cv.snapped[1]);
    let Some(o) = oriented(rs, fx, fy) else { return };
    if !bin_snapped(rs, fb, pos, fx, fy, v, flat_color, o) {
        shade_placed(rs, fb, v, flat_color)
    }
}

/// [`triangle_placed`]'s shading path for a triangle [`bin_snapped`]
/// cannot bin (round 14: never reached after clipping); out of line, so
/// that the binning path keeps its arrays in registers.
#[cold]
#[inline(never)]
fn shade_placed(rs: &RenderState, fb: &mut crate::framebuffer::Framebuffer, v: [&ClipVertex; 3], flat_color: [Vec4; 2]) {
    let pos = v.map(|cv| cv.win);
    let fx = v.map(|cv| cv.snapped[0]);
    let fy = v.map(|cv| cv.snapped[1]);
    let Some(o) = oriented(rs, fx, fy) else { return };
    shade_snapped(rs, fb, pos, fx, fy, v, flat_color, o)
}

/// [`triangle_at`] for window positions `pos` (x, y, z, 1/w) whose other
/// attributes are read from `attrs`.
#[inline]
pub fn triangle_at<A: Attributes>(rs: &RenderState, fb: &mut crate::framebuffer::Framebuffer, pos: [[f64; 4]; 3], attrs: [&A; 3], flat_color: [Vec4; 2]) {
    let fx = pos.map(|p| snap(p[0]));
    let fy = pos.map(|p| snap(p[1]));
    let Some(o) = oriented(rs, fx, fy) else { return };
    if !(binned_here(rs, fb) && bin_snapped(rs, fb, pos, fx, fy, attrs, flat_color, o)) {
        shade_snapped(rs, fb, pos, fx, fy, attrs, flat_color, o)
    }
}

/// Is a filled triangle binned (set up later, in the tile workers)
/// rather than shaded now?
#[inline(always)]
pub(crate) fn binned_here(rs: &RenderState, fb: &crate::framebuffer::Framebuffer) -> bool {
    super::tile::binning(rs) && !fb.draw_both && rs.polygon_mode == [crate::gl::enums::GL_FILL; 2]
}

/// A snapped triangle's orientation: whether its vertices are counter-
/// clockwise, whether it faces the front and whether it shows its back
/// colours; None when it has no area or is culled.
#[derive(Clone, Copy)]
struct Oriented {
    ccw: bool,
    front_facing: bool,
    back: bool,
}

#[inline(always)]
fn oriented(rs: &RenderState, fx: [i64; 3], fy: [i64; 3]) -> Option<Oriented> {
    let area = (fx[1] - fx[0]) * (fy[2] - fy[0]) - (fx[2] - fx[0]) * (fy[1] - fy[0]);
    if area == 0 {
        return None;
    }
    // Window y points up, so counter-clockwise is positive area.
    let ccw = area > 0;
    let front_facing = rs.facing(ccw)?;
    // Two-sided lighting: a back-facing polygon shows its back colours.
    Some(Oriented { ccw, front_facing, back: rs.two_side && !front_facing })
}

/// Bins a snapped triangle, to be set up later in the tile workers; the
/// record takes the vertices in positive orientation (the box does not
/// depend on their order). False when it cannot be binned (a vertex too
/// far out, [`super::tile::Bounds::Far`]): the caller shades it now.
#[allow(clippy::too_many_arguments)]
#[inline(always)]
fn bin_snapped<A: Attributes>(rs: &RenderState, fb: &mut crate::framebuffer::Framebuffer, pos: [[f64; 4]; 3], fx: [i64; 3], fy: [i64; 3], attrs: [&A; 3], flat_color: [Vec4; 2], o: Oriented) -> bool {
    match super::tile::bounds(rs, fx, fy) {
        super::tile::Bounds::Box(centres) => {
            if super::tile::push(rs, fx, fy, centres, pos, attrs, o.ccw, flat_color[o.back as usize], o.back, o.front_facing) {
                super::tile::submit_binned(rs, fb);
            }
            true
        }
        super::tile::Bounds::Empty => true,
        super::tile::Bounds::Far => false,
    }
}

/// Sets up and shades a snapped triangle now.
#[allow(clippy::too_many_arguments)]
#[inline(always)]
fn shade_snapped<A: Attributes>(rs: &RenderState, fb: &mut crate::framebuffer::Framebuffer, pos: [[f64; 4]; 3], fx: [i64; 3], fy: [i64; 3], attrs: [&A; 3], flat_color: [Vec4; 2], o: Oriented) {
    let Oriented { ccw, front_facing, back } = o;
    // Rasterize with positive orientation.
    let order = if ccw { [0, 1, 2] } else { [0, 2, 1] };
    let ex = order.map(|i| fx[i]);
    let ey = order.map(|i| fy[i]);
    let zq = order.map(|i| (pos[i][2], pos[i][3]));
    let v = order.map(|i| attrs[i]);
    // Drawn now: after what is binned (two colour buffers).
    super::tile::sync(rs, fb);
    // A tiny triangle (round 13) is covered as one block and, under the
    // common states, shaded as one (`fragment::stamp`).
    let centres = raster::CentreBox::of(ex, ey, rs.draw_rect);
    let count = centres.count();
    if count > raster::Cover::SMALLEST && rs.polygon_stipple.is_none() && !rs.reference && !fb.draw_both {
        let mut slot = MaybeUninit::uninit();
        if let Some(cover) = raster::Cover::find_into(&mut slot, &ex, &ey, centres) {
            if !cover.is_empty() {
                shade_cover(rs, fb, zq, v, ex, ey, flat_color[back as usize], back, front_facing, cover);
            }
            return;
        }
    }
    // No pixel centre in the box (most often a triangle smaller than a
    // pixel): no pixel (round 16: before the runs' array is made).
    if count == 0 {
        return;
    }
    // A short triangle's runs are found first: covering no pixel (most
    // often through the stipple or between pixel centres), it needs no
    // planes.
    let mut found = raster::Runs::new();
    let runs = found.find_in(ex, ey, centres, rs.draw_rect, rs.polygon_stipple.as_deref()).then_some(&found);
    if runs.is_some_and(|r| r.is_empty()) {
        return;
    }
    let mut slot = MaybeUninit::uninit();
    let setup = solve(&mut slot, rs, zq, v, &ex, &ey, flat_color[back as usize], back, front_facing);
    let k = raster::kernel(rs, fb, setup);
    match runs {
        Some(r) => r.shade(rs, fb, setup, k),
        None => raster::triangle(rs, fb, ex, ey, setup, k),
    }
    // SAFETY: solved above.
    unsafe { release(&mut slot) }
}

/// Sets up and shades a small triangle's cover now: by its block kernel,
/// or its runs by its span kernel when the state has no block kernel.
#[allow(clippy::too_many_arguments)]
#[inline(always)]
fn shade_cover<A: Attributes>(rs: &RenderState, fb: &mut crate::framebuffer::Framebuffer, zq: [(f64, f64); 3], v: [&A; 3], ex: [i64; 3], ey: [i64; 3], flat_color: Vec4, back: bool, front_facing: bool, cover: &raster::Cover) {
    let mut slot = MaybeUninit::uninit();
    let setup = solve(&mut slot, rs, zq, v, &ex, &ey, flat_color, back, front_facing);
    match rs.shade.stamp(rs, setup) {
        Some(sk) => {
            // SAFETY: the cover lies within the draw rectangle, inside the
            // framebuffer; the state tests depth only with a depth buffer;
            // nothing else runs on the framebuffer (1 thread, or synced).
            let passed = unsafe { sk(&rs.fragment, setup, &super::fragment::stamp::Target::of(fb), cover) };
            fb.samples_passed = fb.samples_passed.wrapping_add(passed);
        }
        None => {
            let k = raster::kernel(rs, fb, setup);
            raster::shade_runs(cover.rows(), rs, fb, setup, k)
        }
    }
    // SAFETY: solved above.
    unsafe { release(&mut slot) }
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

/// The edge vectors and determinant a triangle's planes are solved with.
#[derive(Clone, Copy)]
struct PlaneDivisor {
    dx1: f64,
    dy1: f64,
    dx2: f64,
    dy2: f64,
    det: f64,
    det_sign: u64,
    /// det is finite and not zero (it can round to zero, or be NaN, only
    /// for degenerate input).
    zero_quotients: bool,
    /// The lanes' operands, each value in both lanes.
    #[cfg(target_arch = "x86_64")]
    splat: Splat,
}

/// [`PlaneDivisor`]'s values for the planes in lanes, each in both lanes
/// of a register, made once from the values in registers (round 24).
/// Broadcast where a plane is solved, LLVM kept the divisor on the stack
/// as its scalar fields and rebuilt them with 16-byte loads across two
/// of those 8-byte stores, which the store buffer cannot forward: two
/// waits for the stores to reach the cache per triangle, about a third
/// of the band side's set-up samples on spheres_l with 2 threads.
#[cfg(target_arch = "x86_64")]
#[derive(Clone, Copy)]
struct Splat {
    dx1: std::arch::x86_64::__m128d,
    dy1: std::arch::x86_64::__m128d,
    dx2: std::arch::x86_64::__m128d,
    dy2: std::arch::x86_64::__m128d,
    det: std::arch::x86_64::__m128d,
    /// det is neither zero nor NaN: a zero numerator's quotient is the
    /// zero whose sign is the exclusive or of theirs (IEEE 754; for an
    /// infinite det too), so its division may be skipped.
    signed_zeros: bool,
}

#[cfg(target_arch = "x86_64")]
impl Splat {
    #[inline(always)]
    fn new(dx1: f64, dy1: f64, dx2: f64, dy2: f64, det: f64) -> Splat {
        use std::arch::x86_64::*;
        // SAFETY: SSE2 is part of the x86_64 baseline.
        unsafe {
            Splat {
                dx1: _mm_set1_pd(dx1),
                dy1: _mm_set1_pd(dy1),
                dx2: _mm_set1_pd(dx2),
                dy2: _mm_set1_pd(dy2),
                det: _mm_set1_pd(det),
                signed_zeros: det != 0.0 && !det.is_nan(),
            }
        }
    }
}

/// Two attributes' values at vertex 0 and their planes' numerators, lane
/// by lane ([`PlaneDivisor::numerators_sse2`]).
#[cfg(target_arch = "x86_64")]
#[derive(Clone, Copy)]
struct Numerators {
    a0: std::arch::x86_64::__m128d,
    nx: std::arch::x86_64::__m128d,
    ny: std::arch::x86_64::__m128d,
}

/// The colours c s (s is 1/w with perspective, else 1) as two pairs of
/// attributes in lanes: red and green, then blue and alpha, per vertex.
#[cfg(target_arch = "x86_64")]
#[inline(always)]
fn colour_lanes(c: [Vec4; 3], s: [f64; 3], perspective: bool) -> [[std::arch::x86_64::__m128d; 3]; 2] {
    use std::arch::x86_64::*;
    // SAFETY: SSE2 is part of the x86_64 baseline.
    unsafe {
        let wide = |i: usize| {
            let v = _mm_loadu_ps(c[i].as_ref().as_ptr());
            let (lo, hi) = (_mm_cvtps_pd(v), _mm_cvtps_pd(_mm_movehl_ps(v, v)));
            // Times 1 is the identity: skipped without perspective.
            if perspective {
                let si = _mm_set1_pd(s[i]);
                (_mm_mul_pd(lo, si), _mm_mul_pd(hi, si))
            } else {
                (lo, hi)
            }
        };
        let (w0, w1, w2) = (wide(0), wide(1), wide(2));
        [[w0.0, w1.0, w2.0], [w0.1, w1.1, w2.1]]
    }
}

impl PlaneDivisor {
    #[inline(always)]
    fn new(dx1: f64, dy1: f64, dx2: f64, dy2: f64, det: f64) -> PlaneDivisor {
        PlaneDivisor {
            dx1,
            dy1,
            dx2,
            dy2,
            det,
            det_sign: det.to_bits() & SIGN,
            zero_quotients: det != 0.0 && det.is_finite(),
            #[cfg(target_arch = "x86_64")]
            splat: Splat::new(dx1, dy1, dx2, dy2, det),
        }
    }

    /// [`PlaneDivisor::new`] for the planes in lanes (LANES, on x86_64)
    /// or by the scalar form: the lanes always divide, so they need
    /// neither det's sign nor the zero test (left false and 0; about 15
    /// instructions a triangle).
    #[inline(always)]
    fn new_for<const LANES: bool>(dx1: f64, dy1: f64, dx2: f64, dy2: f64, det: f64) -> PlaneDivisor {
        #[cfg(target_arch = "x86_64")]
        if LANES {
            return PlaneDivisor { dx1, dy1, dx2, dy2, det, det_sign: 0, zero_quotients: false, splat: Splat::new(dx1, dy1, dx2, dy2, det) };
        }
        PlaneDivisor::new(dx1, dy1, dx2, dy2, det)
    }

    /// The plane of the values `a` at the three vertices:
    /// dx = (da1 dy2 - da2 dy1) / det, dy = (da2 dx1 - da1 dx2) / det.
    /// An attribute equal at the three vertices (flat-coloured triangles,
    /// 1/w without perspective, the depth of a face parallel to the
    /// screen) has zero numerators; a zero divided by a finite non-zero
    /// det is exactly the zero whose sign is the exclusive or of theirs
    /// (IEEE 754), so its two divisions are skipped with the same bits.
    #[inline(always)]
    fn plane(&self, a: [f64; 3]) -> Plane {
        let (da1, da2) = (a[1] - a[0], a[2] - a[0]);
        let (nx, ny) = (da1 * self.dy2 - da2 * self.dy1, da2 * self.dx1 - da1 * self.dx2);
        if nx == 0.0 && ny == 0.0 && self.zero_quotients {
            Plane { a0: a[0], dx: signed_zero(nx, self.det_sign), dy: signed_zero(ny, self.det_sign) }
        } else {
            Plane { a0: a[0], dx: nx / self.det, dy: ny / self.det }
        }
    }

    /// [`PlaneDivisor::plane`] with the two numerators side by side in
    /// one SSE2 register (lane 0 the x slope, lane 1 the y slope): the
    /// same IEEE operations on the same operands, lane by lane, so the
    /// same bits. Both quotients always come from one `divpd`; the
    /// scalar form's skipped divisions give exactly the bits dividing
    /// gives (`constant_planes_match_division`), so dividing always is
    /// the same answer with no branch on the numerators. The divisor's
    /// values come broadcast ([`Splat`], round 24: 8 instructions a
    /// triangle more than broadcasting them here, but no stall).
    #[cfg(target_arch = "x86_64")]
    #[inline(always)]
    fn plane_sse2(&self, a: [f64; 3]) -> Plane {
        use std::arch::x86_64::*;
        // SAFETY: SSE2 is part of the x86_64 baseline.
        unsafe {
            // [da1, da2] and [da2, da1].
            let da = _mm_sub_pd(_mm_set_pd(a[2], a[1]), _mm_set1_pd(a[0]));
            let swapped = _mm_shuffle_pd::<1>(da, da);
            // nx = da1 dy2 - da2 dy1; ny = da2 dx1 - da1 dx2.
            let v = &self.splat;
            let n = _mm_sub_pd(_mm_mul_pd(da, _mm_unpacklo_pd(v.dy2, v.dx1)), _mm_mul_pd(swapped, _mm_unpacklo_pd(v.dy1, v.dx2)));
            let q = _mm_div_pd(n, v.det);
            Plane { a0: a[0], dx: _mm_cvtsd_f64(q), dy: _mm_cvtsd_f64(_mm_unpackhi_pd(q, q)) }
        }
    }

    /// The plane in lanes (LANES, on x86_64) or by the scalar form.
    #[inline(always)]
    fn plane_by<const LANES: bool>(&self, a: [f64; 3]) -> Plane {
        #[cfg(target_arch = "x86_64")]
        if LANES {
            return self.plane_sse2(a);
        }
        self.plane(a)
    }

    /// The planes of two attributes at once, lane 0 and lane 1 of `a[i]`
    /// their values at vertex i, in two halves: here the values at vertex
    /// 0 and [`PlaneDivisor::plane`]'s numerators lane by lane (da1 dy2 -
    /// da2 dy1 and da2 dx1 - da1 dx2), then their quotients by det
    /// ([`PlaneDivisor::quotients_sse2`]); so each plane has the bits
    /// `plane_sse2` gives it, with half its instructions (no swap, no
    /// per-plane broadcasts).
    #[cfg(target_arch = "x86_64")]
    #[inline(always)]
    fn numerators_sse2(&self, a: [std::arch::x86_64::__m128d; 3]) -> Numerators {
        use std::arch::x86_64::*;
        // SAFETY: SSE2 is part of the x86_64 baseline.
        unsafe {
            let da1 = _mm_sub_pd(a[1], a[0]);
            let da2 = _mm_sub_pd(a[2], a[0]);
            let v = &self.splat;
            let nx = _mm_sub_pd(_mm_mul_pd(da1, v.dy2), _mm_mul_pd(da2, v.dy1));
            let ny = _mm_sub_pd(_mm_mul_pd(da2, v.dx1), _mm_mul_pd(da1, v.dx2));
            Numerators { a0: a[0], nx, ny }
        }
    }

    /// [`PlaneDivisor::numerators_sse2`]'s second half: the numerators divided
    /// by det, or when `zeros` (the caller found every numerator ±0, and
    /// det is neither zero nor NaN: `Splat::signed_zeros`) the zeros
    /// dividing gives, whose sign is the exclusive or of theirs (IEEE
    /// 754), with no division.
    #[cfg(target_arch = "x86_64")]
    #[inline(always)]
    fn quotients_sse2(&self, n: Numerators, zeros: bool) -> [Plane; 2] {
        use std::arch::x86_64::*;
        // SAFETY: SSE2 is part of the x86_64 baseline.
        unsafe {
            let det = self.splat.det;
            let (dx, dy) = if zeros {
                let sign = _mm_set1_pd(-0.0);
                (_mm_and_pd(_mm_xor_pd(n.nx, det), sign), _mm_and_pd(_mm_xor_pd(n.ny, det), sign))
            } else {
                (_mm_div_pd(n.nx, det), _mm_div_pd(n.ny, det))
            };
            let hi = |v: __m128d| _mm_cvtsd_f64(_mm_unpackhi_pd(v, v));
            [
                Plane { a0: _mm_cvtsd_f64(n.a0), dx: _mm_cvtsd_f64(dx), dy: _mm_cvtsd_f64(dy) },
                Plane { a0: hi(n.a0), dx: hi(dx), dy: hi(dy) },
            ]
        }
    }

    /// The depth and 1/w planes and, unless flat shaded (`c` None), the
    /// four colour planes of smooth shading, of c s per vertex (s is 1/w
    /// with perspective, else 1): in lanes (LANES, on x86_64), depth and
    /// 1/w side by side, then red and green, then blue and alpha; or one at
    /// a time by the scalar form ([`PlaneDivisor::depth_q`],
    /// [`PlaneDivisor::colours`]); the same bits. In lanes (round 24): when every
    /// numerator of the three pairs is zero (a face parallel to the screen
    /// without perspective, coloured alike at its vertices: every
    /// immediate_1m and arrays_1m triangle) no division is made, the same
    /// bits; one test a triangle, so that a triangle with anything varying
    /// pays only that test (three tests, one a pair, cost spheres_l 3 %).
    #[inline(always)]
    fn depth_colours_by<const LANES: bool>(&self, zq: [(f64, f64); 3], c: Option<[Vec4; 3]>, s: [f64; 3], perspective: bool) -> ([Plane; 2], Option<[Plane; 4]>) {
        #[cfg(target_arch = "x86_64")]
        if LANES {
            use std::arch::x86_64::*;
            // SAFETY: SSE2 is part of the x86_64 baseline.
            unsafe {
                let dq = self.numerators_sse2(zq.map(|(z, q)| _mm_set_pd(q, z)));
                let cn = c.map(|c| colour_lanes(c, s, perspective).map(|a| self.numerators_sse2(a)));
                let mut any = _mm_or_pd(dq.nx, dq.ny);
                if let Some([rg, ba]) = &cn {
                    any = _mm_or_pd(any, _mm_or_pd(_mm_or_pd(rg.nx, rg.ny), _mm_or_pd(ba.nx, ba.ny)));
                }
                // Every numerator ±0: the bits' union is ±0 in both lanes.
                let zeros = self.splat.signed_zeros && _mm_movemask_pd(_mm_cmpeq_pd(any, _mm_setzero_pd())) == 3;
                let dq = self.quotients_sse2(dq, zeros);
                let color = cn.map(|[rg, ba]| {
                    let (rg, ba) = (self.quotients_sse2(rg, zeros), self.quotients_sse2(ba, zeros));
                    [rg[0], rg[1], ba[0], ba[1]]
                });
                return (dq, color);
            }
        }
        let dq = self.depth_q(zq);
        (dq, c.map(|c| self.colours(c, s, perspective, dq[1])))
    }

    /// The scalar form's depth and 1/w planes.
    #[inline(always)]
    fn depth_q(&self, zq: [(f64, f64); 3]) -> [Plane; 2] {
        [self.plane(zq.map(|p| p.0)), self.plane(zq.map(|p| p.1))]
    }

    /// The scalar form's colour planes. It shares `q_plane` for a channel
    /// of exactly 1 at every vertex under perspective (1 q is q: the same
    /// values, so the same plane); the lanes solve it again, to the same
    /// bits.
    #[inline(always)]
    fn colours(&self, c: [Vec4; 3], s: [f64; 3], perspective: bool, q_plane: Plane) -> [Plane; 4] {
        let c = c.map(|c| c.to_array());
        let channel = |ch: usize| {
            if perspective && c[0][ch] == 1.0 && c[1][ch] == 1.0 && c[2][ch] == 1.0 {
                // 1 * q is q: the plane of q's very values (most often
                // opaque alpha), already solved.
                q_plane
            } else {
                self.plane([c[0][ch] as f64 * s[0], c[1][ch] as f64 * s[1], c[2][ch] as f64 * s[2]])
            }
        };
        // Written out: `array::from_fn` with this closure stayed an
        // out-of-line loop.
        [channel(0), channel(1), channel(2), channel(3)]
    }
}

/// Solve a triangle's planes in SSE2 lanes ([`PlaneDivisor::plane_sse2`])?
/// Unless `SOFTGL_SIMD=0` asks for the scalar forms (x86_64 only).
#[inline(always)]
fn planes_lanes() -> bool {
    cfg!(target_arch = "x86_64") && super::fragment::simd::level() != super::fragment::simd::Level::Scalar
}

const SIGN: u64 = 1 << 63;

/// zero / d for a zero `zero` and a finite non-zero d of sign bit
/// `d_sign`: a zero with the sign bits' exclusive or.
#[inline(always)]
fn signed_zero(zero: f64, d_sign: u64) -> f64 {
    f64::from_bits((zero.to_bits() ^ d_sign) & SIGN)
}

/// The planes of a positively oriented triangle: window depth and 1/w
/// per vertex in `zq`, the other attributes from `v`.
#[allow(clippy::too_many_arguments)]
#[inline]
pub(crate) fn planes_of<P: SetupParams, A: Attributes>(rs: &P, zq: [(f64, f64); 3], v: [&A; 3], ex: [i64; 3], ey: [i64; 3], flat_color: Vec4, back: bool, front_facing: bool) -> TriangleSetup {
    let mut t = MaybeUninit::uninit();
    planes_into(&mut t, rs, zq, v, &ex, &ey, flat_color, back, front_facing);
    // SAFETY: `planes_into` writes every field.
    unsafe { t.assume_init() }
}

/// [`planes_of`]'s set-up for the shading paths, solved in place into
/// `slot` (the caller's frame) and lent out; the caller passes the slot to
/// [`release`] when done. Round 16: returned by value, the 336-byte
/// set-up was built on `planes_of`'s stack and copied to the caller's
/// (about 47 instructions a triangle), and dropped by an out-of-line call
/// (9 more); here each field is stored once, and only a set-up holding
/// texture planes has anything to drop. (A slot type with `Drop` was
/// zeroed with `memset` at each construction: 35 instructions.)
/// Round 17: the snapped vertices by reference: by value, each
/// out-of-line callee (this and the cover) took its own copy of the two
/// arrays (about 22 stack moves a triangle in the band loop).
#[allow(clippy::too_many_arguments)]
#[inline(always)]
pub(crate) fn solve<'a, P: SetupParams, A: Attributes>(slot: &'a mut MaybeUninit<TriangleSetup>, rs: &P, zq: [(f64, f64); 3], v: [&A; 3], ex: &[i64; 3], ey: &[i64; 3], flat_color: Vec4, back: bool, front_facing: bool) -> &'a TriangleSetup {
    planes_into(slot, rs, zq, v, ex, ey, flat_color, back, front_facing);
    // SAFETY: `planes_into` writes every field.
    unsafe { slot.assume_init_ref() }
}

/// Drops a set-up [`solve`] wrote into `slot` (only texture planes own
/// anything, as `only_texture_planes_need_dropping` checks; a slot never
/// released leaks them, nothing worse).
///
/// Safety: `slot` was written by [`solve`] and not released since.
#[inline(always)]
pub(crate) unsafe fn release(slot: &mut MaybeUninit<TriangleSetup>) {
    if slot.assume_init_ref().tex.is_some() {
        slot.assume_init_drop()
    }
}

/// Writes the planes of [`planes_of`] into `out`, every field.
#[allow(clippy::too_many_arguments)]
#[inline]
fn planes_into<P: SetupParams, A: Attributes>(out: &mut MaybeUninit<TriangleSetup>, rs: &P, zq: [(f64, f64); 3], v: [&A; 3], ex: &[i64; 3], ey: &[i64; 3], flat_color: Vec4, back: bool, front_facing: bool) {
    planes_here(out, rs, zq, v, ex, ey, flat_color, back, front_facing)
}

/// [`solve`] with the planes solved in the caller's code ([`planes_into`]
/// inlined): for a caller that is itself out of line and reads the
/// vertices in place (round 18: the band side's `tile::solve_binned`,
/// whose call to `planes_into` passed the depths, 1/w and colours
/// through stack copies, about 35 instructions a triangle). The same
/// code, so the same bits.
#[allow(clippy::too_many_arguments)]
#[inline(always)]
pub(crate) fn solve_here<'a, P: SetupParams, A: Attributes>(slot: &'a mut MaybeUninit<TriangleSetup>, rs: &P, zq: [(f64, f64); 3], v: [&A; 3], ex: &[i64; 3], ey: &[i64; 3], flat_color: Vec4, back: bool, front_facing: bool) -> &'a TriangleSetup {
    planes_here(slot, rs, zq, v, ex, ey, flat_color, back, front_facing);
    // SAFETY: `planes_here` writes every field.
    unsafe { slot.assume_init_ref() }
}

/// [`planes_into`]'s body.
#[allow(clippy::too_many_arguments)]
#[inline(always)]
fn planes_here<P: SetupParams, A: Attributes>(out: &mut MaybeUninit<TriangleSetup>, rs: &P, zq: [(f64, f64); 3], v: [&A; 3], ex: &[i64; 3], ey: &[i64; 3], flat_color: Vec4, back: bool, front_facing: bool) {
    // Decided once per triangle, not per plane.
    if planes_lanes() {
        planes_by::<P, A, true>(out, rs, zq, v, ex, ey, flat_color, back, front_facing)
    } else {
        planes_by::<P, A, false>(out, rs, zq, v, ex, ey, flat_color, back, front_facing)
    }
}

/// [`planes_into`] with every plane solved in lanes (LANES) or by the
/// scalar form: the same bits either way.
#[allow(clippy::too_many_arguments)]
#[inline(always)]
fn planes_by<P: SetupParams, A: Attributes, const LANES: bool>(out: &mut MaybeUninit<TriangleSetup>, rs: &P, zq: [(f64, f64); 3], v: [&A; 3], ex: &[i64; 3], ey: &[i64; 3], flat_color: Vec4, back: bool, front_facing: bool) {
    let inv = 1.0 / ONE as f64;
    let x = ex.map(|c| c as f64 * inv);
    let y = ey.map(|c| c as f64 * inv);
    let (dx1, dy1, dx2, dy2) = (x[1] - x[0], y[1] - y[0], x[2] - x[0], y[2] - y[0]);
    let det = dx1 * dy2 - dx2 * dy1;
    let d = PlaneDivisor::new_for::<LANES>(dx1, dy1, dx2, dy2, det);
    let plane = |a: [f64; 3]| d.plane_by::<LANES>(a);
    let q = zq.map(|p| p.1);
    let perspective = !(q[0] == q[1] && q[1] == q[2]);
    let s = if perspective { q } else { [1.0; 3] };
    // Written out: `[0, 1, 2].map` with this closure stayed an
    // out-of-line call copying the colours through memory.
    let c = (!rs.flat()).then(|| if back { [v[0].back_color(), v[1].back_color(), v[2].back_color()] } else { [v[0].color(), v[1].color(), v[2].color()] });
    let ([mut z, q_plane], color) = d.depth_colours_by::<LANES>(zq, c, s, perspective);
    let (flat, color) = match color {
        None => (Some(super::fragment::color_to_u8(flat_color)), [Plane::default(); 4]),
        Some(color) => (None, color),
    };
    if let Some((factor, units)) = rs.offset_fill() {
        // Polygon offset (3.5.5): m * factor + r * units, with m the
        // largest depth slope and r the depth buffer's resolution.
        let m = z.dx.abs().max(z.dy.abs());
        z.a0 += m * factor as f64 + units as f64 * OFFSET_UNIT;
    }
    let t = out.as_mut_ptr();
    // SAFETY: `t` points to `out`'s (uninitialized) set-up; each field is
    // written once through a raw pointer (no reference to an unwritten
    // field, nothing read or dropped). The optional planes are written in
    // their own branches, so an absent one stores its tag only (moved in
    // as a whole `Option`, its payload was copied from the stack even when
    // absent).
    unsafe {
        addr_of_mut!((*t).x0).write(x[0]);
        addr_of_mut!((*t).y0).write(y[0]);
        addr_of_mut!((*t).z).write(z);
        addr_of_mut!((*t).q).write(q_plane);
        addr_of_mut!((*t).color).write(color);
        addr_of_mut!((*t).perspective).write(perspective);
        addr_of_mut!((*t).flat).write(flat);
        addr_of_mut!((*t).front_facing).write(front_facing);
        let textured = match rs.texture() {
            Some(stage) => {
                let mut planes = [[Plane::default(); 4]; super::texture::MAX_UNITS];
                for &u in &stage.active {
                    for (c, p) in planes[u].iter_mut().enumerate() {
                        *p = plane([0, 1, 2].map(|i| v[i].tex(u)[c] as f64 * q[i]));
                    }
                }
                addr_of_mut!((*t).tex).write(Some(Box::new(TexPlanes { stage: stage.clone(), planes })));
                true
            }
            None => {
                addr_of_mut!((*t).tex).write(None);
                false
            }
        };
        match rs.fog() {
            Some(f) => addr_of_mut!((*t).fog).write(Some((plane([0, 1, 2].map(|i| v[i].fog() as f64 * if perspective { q[i] } else { 1.0 })), f))),
            None => addr_of_mut!((*t).fog).write(None),
        }
        if rs.color_sum() && textured {
            addr_of_mut!((*t).secondary).write(Some([0, 1, 2].map(|ch| plane([0, 1, 2].map(|i| if back { v[i].back_secondary() } else { v[i].secondary() }[ch] as f64 * if perspective { q[i] } else { 1.0 })))));
        } else {
            addr_of_mut!((*t).secondary).write(None);
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// `PlaneDivisor::plane` gives the bits of dividing both numerators by
    /// det, on random triangles whose attributes are constant (the skipped
    /// divisions) or not, with zeros of both signs, det of both signs,
    /// tiny, huge, zero, infinite and NaN, and non-finite attributes.
    #[test]
    fn constant_planes_match_division() {
        let mut seed = 5u64;
        let mut next = || {
            seed = seed.wrapping_mul(6364136223846793005).wrapping_add(1442695040888963407);
            seed >> 11
        };
        let specials = [0.0, -0.0, 1.0, -1.0, 0.5, 1e-300, -1e-300, 5e-324, 1e300, -1e300, f64::INFINITY, f64::NEG_INFINITY, f64::NAN];
        let (mut skipped, mut divided) = (0, 0);
        for n in 0..300_000 {
            let pick = |next: &mut dyn FnMut() -> u64| {
                let r = next();
                if r.is_multiple_of(8) {
                    specials[(r >> 3) as usize % specials.len()]
                } else {
                    ((r >> 3) as f64 / (1u64 << 50) as f64 - 0.5) * [1.0, 1e-3, 1e3, 1e-200, 1e200][(r >> 60) as usize % 5]
                }
            };
            let (dx1, dy1, dx2, dy2) = (pick(&mut next), pick(&mut next), pick(&mut next), pick(&mut next));
            // Mostly the triangle's own det, sometimes an unrelated one.
            let det = if n % 5 == 0 { pick(&mut next) } else { dx1 * dy2 - dx2 * dy1 };
            let a0 = pick(&mut next);
            let a = match n % 4 {
                0 => [a0, a0, a0],
                1 => [a0, -a0, a0],
                2 => [a0, pick(&mut next), a0],
                _ => [a0, pick(&mut next), pick(&mut next)],
            };
            let d = PlaneDivisor::new(dx1, dy1, dx2, dy2, det);
            let got = d.plane(a);
            let (da1, da2) = (a[1] - a[0], a[2] - a[0]);
            let (nx, ny) = (da1 * dy2 - da2 * dy1, da2 * dx1 - da1 * dx2);
            let want = Plane { a0: a[0], dx: nx / det, dy: ny / det };
            assert_eq!(
                [got.a0, got.dx, got.dy].map(f64::to_bits),
                [want.a0, want.dx, want.dy].map(f64::to_bits),
                "{a:?} {dx1} {dy1} {dx2} {dy2} {det}"
            );
            // The lanes' form: the scalar form's bits, or NaN where it is
            // NaN (a NaN's sign and payload are not specified by Rust's
            // arithmetic, and LLVM may swap a product's operands, so the
            // scalar form's NaN itself can change with the compiler; no
            // conversion to a colour or depth reads them).
            #[cfg(target_arch = "x86_64")]
            {
                let lanes = d.plane_sse2(a);
                let same = |x: f64, y: f64| x.to_bits() == y.to_bits() || (x.is_nan() && y.is_nan());
                assert!(
                    same(lanes.a0, got.a0) && same(lanes.dx, got.dx) && same(lanes.dy, got.dy),
                    "lanes: {lanes:?} scalar: {got:?} of {a:?} {dx1} {dy1} {dx2} {dy2} {det}"
                );
            }
            if nx == 0.0 && ny == 0.0 && det != 0.0 && det.is_finite() {
                skipped += 1;
            } else {
                divided += 1;
            }
        }
        assert!(skipped > 50_000 && divided > 50_000, "{skipped} {divided}");
    }

    /// Planes in lanes, two at a time (`depth_colours_by`: depth and 1/w,
    /// colours, their divisions skipped when every numerator is zero) have
    /// the bits of the scalar form's one at a time, on
    /// random values with zeros of both signs, ones, tiny, huge, infinite
    /// and NaN values, det of both signs, zero and NaN, with and without
    /// perspective (NaN compared as NaN, as in
    /// `constant_planes_match_division`).
    #[cfg(target_arch = "x86_64")]
    #[test]
    fn pairs_match_single_planes() {
        let mut seed = 23u64;
        let mut next = || {
            seed = seed.wrapping_mul(6364136223846793005).wrapping_add(1442695040888963407);
            seed >> 11
        };
        let specials = [0.0, -0.0, 1.0, -1.0, 0.5, 1e-300, -1e-300, 1e300, f64::INFINITY, f64::NEG_INFINITY, f64::NAN];
        let pick = move |next: &mut dyn FnMut() -> u64| {
            let r = next();
            if r.is_multiple_of(8) {
                specials[(r >> 3) as usize % specials.len()]
            } else if r % 8 == 1 {
                1.0
            } else {
                ((r >> 3) as f64 / (1u64 << 50) as f64 - 0.5) * [1.0, 1e-3, 1e3, 1e-30, 1e30][(r >> 60) as usize % 5]
            }
        };
        let same = |x: &Plane, y: &Plane| [(x.a0, y.a0), (x.dx, y.dx), (x.dy, y.dy)].iter().all(|&(a, b)| a.to_bits() == b.to_bits() || (a.is_nan() && b.is_nan()));
        let mut skipped = 0;
        for n in 0..200_000 {
            let (dx1, dy1, dx2, dy2) = (pick(&mut next), pick(&mut next), pick(&mut next), pick(&mut next));
            let det = if n % 9 == 0 { pick(&mut next) } else { dx1 * dy2 - dx2 * dy1 };
            let d = PlaneDivisor::new(dx1, dy1, dx2, dy2, det);
            // A quarter of the triangles with every attribute constant
            // (round 24: all numerators zero, whose divisions
            // `depth_colours_by` skips in lanes).
            let constant = n % 4 == 1;
            let mut zq: [(f64, f64); 3] = std::array::from_fn(|_| (pick(&mut next), pick(&mut next)));
            if constant {
                zq = [zq[0]; 3];
            }
            let mut c: [Vec4; 3] = std::array::from_fn(|_| Vec4::new(pick(&mut next) as f32, pick(&mut next) as f32, pick(&mut next) as f32, pick(&mut next) as f32));
            if constant {
                c = [c[0]; 3];
            }
            let perspective = n % 3 != 0;
            let s = if perspective { zq.map(|p| p.1) } else { [1.0; 3] };
            // Depth, 1/w and colours at once (flat shaded: no colours),
            // with the divisions skipped when every numerator is zero.
            let colours = (n % 5 != 0).then_some(c);
            let (lanes, lanes_c) = d.depth_colours_by::<true>(zq, colours, s, perspective);
            let (scalar, scalar_c) = d.depth_colours_by::<false>(zq, colours, s, perspective);
            assert!(same(&lanes[0], &scalar[0]) && same(&lanes[1], &scalar[1]), "{zq:?} {lanes:?} {scalar:?}");
            assert_eq!(lanes_c.is_some(), scalar_c.is_some());
            if let (Some(l), Some(sc)) = (lanes_c, scalar_c) {
                assert!((0..4).all(|ch| same(&l[ch], &sc[ch])), "{c:?} {s:?}: {l:?} {sc:?}");
            }
            let finite = zq[0].0.is_finite() && zq[0].1.is_finite() && c[0].is_finite() && [dx1, dy1, dx2, dy2].iter().all(|v| v.is_finite());
            skipped += (constant && finite && det != 0.0 && !det.is_nan()) as usize;
        }
        // Constant triangles with finite values and a det the zeros may
        // be signed by: the skipped divisions were compared.
        assert!(skipped > 10_000, "{skipped}");
    }

    /// Setup state for `planes_of` without textures.
    struct Params {
        flat: bool,
        offset: Option<(f32, f32)>,
        fog: Option<crate::render::fog::Fog>,
    }

    impl SetupParams for Params {
        fn flat(&self) -> bool {
            self.flat
        }
        fn offset_fill(&self) -> Option<(f32, f32)> {
            self.offset
        }
        fn texture(&self) -> Option<&std::sync::Arc<crate::render::texture::TextureStage>> {
            None
        }
        fn fog(&self) -> Option<crate::render::fog::Fog> {
            self.fog
        }
        fn color_sum(&self) -> bool {
            false
        }
    }

    /// Every plane divided out as written in the spec's terms, with no
    /// shortcut: what `planes_of` must equal bit for bit.
    fn plane_by_division(ex: [i64; 3], ey: [i64; 3], a: [f64; 3]) -> Plane {
        let x = ex.map(|c| c as f64 / ONE as f64);
        let y = ey.map(|c| c as f64 / ONE as f64);
        let (dx1, dy1, dx2, dy2) = (x[1] - x[0], y[1] - y[0], x[2] - x[0], y[2] - y[0]);
        let det = dx1 * dy2 - dx2 * dy1;
        let (da1, da2) = (a[1] - a[0], a[2] - a[0]);
        Plane { a0: a[0], dx: (da1 * dy2 - da2 * dy1) / det, dy: (da2 * dx1 - da1 * dx2) / det }
    }

    fn bits(p: &Plane) -> [u64; 3] {
        [p.a0, p.dx, p.dy].map(f64::to_bits)
    }

    /// `planes_of` (constant planes without division, an all-one colour
    /// channel sharing the 1/w plane) equals dividing every plane, on
    /// random small and large triangles with and without perspective,
    /// constant and varying colours, channels of exactly 1 and 0, depth
    /// constant or not, fog, polygon offset and both facings' colours.
    /// [`release`] drops a solved set-up only when it holds texture
    /// planes: `tex` must stay the only field that owns anything. The
    /// pattern names every field, so a new one does not compile until it
    /// is listed here and checked.
    #[test]
    fn only_texture_planes_need_dropping() {
        fn owns<T>(_: &T) -> bool {
            std::mem::needs_drop::<T>()
        }
        let t = TriangleSetup {
            x0: 0.0,
            y0: 0.0,
            z: Plane::default(),
            q: Plane::default(),
            color: [Plane::default(); 4],
            perspective: false,
            flat: None,
            front_facing: true,
            tex: None,
            fog: None,
            secondary: None,
        };
        let TriangleSetup { x0, y0, z, q, color, perspective, flat, front_facing, tex, fog, secondary } = &t;
        assert!(owns(tex));
        let others = [owns(x0), owns(y0), owns(z), owns(q), owns(color), owns(perspective), owns(flat), owns(front_facing), owns(fog), owns(secondary)];
        assert_eq!(others, [false; 10], "a field besides tex owns memory: release() would leak it");
    }

    #[test]
    fn planes_match_dividing_every_plane() {
        let mut seed = 17u64;
        let mut next = move || {
            seed = seed.wrapping_mul(6364136223846793005).wrapping_add(1442695040888963407);
            seed >> 11
        };
        let fog = crate::render::fog::Fog { mode: crate::render::fog::GL_LINEAR, density: 1.0, start: 0.0, end: 1.0, color: Vec4::ONE, per_fragment: true };
        let (mut shared, mut constant, mut perspective_n) = (0, 0, 0);
        for n in 0..100_000 {
            let size = [3 * ONE, 40 * ONE, 3000 * ONE][n % 3];
            let mut coord = || (next() % size as u64) as i64 - size / 2;
            let (ex, ey) = ([coord(), coord(), coord()], [coord(), coord(), coord()]);
            let area = (ex[1] - ex[0]) * (ey[2] - ey[0]) - (ex[2] - ex[0]) * (ey[1] - ey[0]);
            if area <= 0 {
                continue;
            }
            let mut unit = || (next() % 1_000_001) as f32 / 1_000_000.0;
            let q: [f64; 3] = if n % 4 == 0 { [0.25; 3] } else { [0.1 + unit() as f64, 0.1 + unit() as f64, 0.1 + unit() as f64] };
            let z: [f64; 3] = if n % 5 == 0 { [0.5; 3] } else { [unit() as f64, unit() as f64, unit() as f64] };
            let mut colour = |k: usize| -> [Vec4; 3] {
                let c = Vec4::new(unit(), unit(), unit(), 1.0);
                match (n / 2 + k) % 4 {
                    // Flat colour per triangle, opaque.
                    0 => [c; 3],
                    // Smooth, opaque, a channel 0 and one 1.
                    1 => [0, 1, 2].map(|_| Vec4::new(unit(), 0.0, 1.0, 1.0)),
                    // Smooth, channels 1 at two vertices of three.
                    2 => [Vec4::new(unit(), 1.0, unit(), 1.0), Vec4::new(unit(), 1.0, 1.0, 1.0), Vec4::new(1.0, unit(), 1.0, unit())],
                    _ => [0, 1, 2].map(|_| Vec4::new(unit(), unit(), unit(), 1.0)),
                }
            };
            let (front, backc) = (colour(0), colour(1));
            let fogv = [unit(), unit(), unit()];
            let w: [WindowVertex; 3] = std::array::from_fn(|i| WindowVertex {
                x: ex[i] as f64 / ONE as f64,
                y: ey[i] as f64 / ONE as f64,
                z: z[i],
                q: q[i],
                color: front[i],
                back_color: backc[i],
                tex: [Vec4::ZERO; crate::render::texture::MAX_UNITS],
                fog: fogv[i],
                secondary: Vec4::ZERO,
                back_secondary: Vec4::ZERO,
            });
            let back = n % 7 == 3;
            let params = Params { flat: n % 11 == 5, offset: (n % 13 == 1).then_some((1.5, 2.0)), fog: (n % 3 == 0).then_some(fog) };
            let zq = [0, 1, 2].map(|i| (z[i], q[i]));
            let t = planes_of(&params, zq, w.each_ref(), ex, ey, front[2], back, !back);
            // Round 16: every field written in place, through `solve`
            // (the shading paths' form) as through `planes_of`.
            let mut slot = MaybeUninit::uninit();
            let solved = solve(&mut slot, &params, zq, w.each_ref(), &ex, &ey, front[2], back, !back);
            let fields = |t: &TriangleSetup| {
                let planes = [t.z, t.q, t.color[0], t.color[1], t.color[2], t.color[3], t.fog.map_or(Plane::default(), |f| f.0)].map(|p| bits(&p));
                (planes, [t.x0, t.y0].map(f64::to_bits), t.perspective, t.flat, t.front_facing, t.tex.is_some(), t.fog.map(|f| f.1.mode), t.secondary.is_some())
            };
            assert_eq!(fields(solved), fields(&t), "{ex:?} {ey:?}");
            // SAFETY: solved above.
            unsafe { release(&mut slot) };
            assert_eq!([t.x0, t.y0], [ex[0] as f64 / ONE as f64, ey[0] as f64 / ONE as f64]);
            assert_eq!(t.front_facing, !back);
            assert!(t.tex.is_none() && t.secondary.is_none());
            assert_eq!(t.fog.map(|f| f.1.mode), params.fog.map(|f| f.mode));
            // The lanes' and the scalar form's planes, bit for bit.
            let by = |lanes: bool| {
                let mut t = MaybeUninit::uninit();
                if lanes {
                    planes_by::<_, _, true>(&mut t, &params, zq, w.each_ref(), &ex, &ey, front[2], back, !back);
                } else {
                    planes_by::<_, _, false>(&mut t, &params, zq, w.each_ref(), &ex, &ey, front[2], back, !back);
                }
                // SAFETY: `planes_by` writes every field.
                unsafe { t.assume_init() }
            };
            let (scalar, lanes) = (by(false), by(true));
            for u in [&scalar, &lanes] {
                let all = |t: &TriangleSetup| [t.z, t.q, t.color[0], t.color[1], t.color[2], t.color[3], t.fog.map_or(Plane::default(), |f| f.0)].map(|p| bits(&p));
                assert_eq!(all(u), all(&t), "{ex:?} {ey:?}");
            }
            let perspective = !(q[0] == q[1] && q[1] == q[2]);
            assert_eq!(t.perspective, perspective);
            perspective_n += perspective as usize;
            let s = if perspective { q } else { [1.0; 3] };
            assert_eq!(bits(&t.q), bits(&plane_by_division(ex, ey, q)), "q of {ex:?} {ey:?}");
            let mut zp = plane_by_division(ex, ey, z);
            if let Some((factor, units)) = params.offset {
                zp.a0 += zp.dx.abs().max(zp.dy.abs()) * factor as f64 + units as f64 * OFFSET_UNIT;
            }
            assert_eq!(bits(&t.z), bits(&zp), "z of {ex:?} {ey:?}");
            if params.flat {
                assert_eq!(t.flat, Some(crate::render::fragment::color_to_u8(front[2])));
            } else {
                assert!(t.flat.is_none());
                let c = if back { backc } else { front };
                for ch in 0..4 {
                    let want = plane_by_division(ex, ey, [0, 1, 2].map(|i| c[i][ch] as f64 * s[i]));
                    assert_eq!(bits(&t.color[ch]), bits(&want), "channel {ch} of {c:?} {ex:?} {ey:?} {q:?}");
                    shared += (perspective && c.iter().all(|v| v[ch] == 1.0)) as usize;
                    constant += (c[0][ch] == c[1][ch] && c[1][ch] == c[2][ch] && !perspective) as usize;
                }
            }
            if let Some((p, _)) = &t.fog {
                let want = plane_by_division(ex, ey, [0, 1, 2].map(|i| fogv[i] as f64 * s[i]));
                assert_eq!(bits(p), bits(&want));
            }
        }
        assert!(shared > 10_000 && constant > 10_000 && perspective_n > 10_000, "{shared} {constant} {perspective_n}");
    }
}
