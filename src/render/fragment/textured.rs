//! Textured span kernels (GL 1.5 sections 3.8.7 to 3.8.13 and 3.10, then
//! the per-fragment operations of section 4.1) for the common case: one
//! texture unit with a 2D texture whose levels are stored as 8-bit RGBA
//! without border, wrapped by REPEAT or CLAMP_TO_EDGE, any of the six
//! minification filters, the MODULATE, REPLACE or DECAL environment, fog
//! or none, no colour sum, no alpha or stencil test.
//!
//! Exactness: the kernel computes bit for bit what the reference path
//! (`reference::triangle_color`, `TextureStage::shade`,
//! `UnitSampler::sample_general`) computes, in the same operations and
//! the same order: the planes in f64 as `(a0 + dy cy) + dx cx` with the
//! row term hoisted, one division by q per fragment, the derivatives
//! `(S' - s Q') / Q`, ρ from them in f32 with the same sqrt and log2
//! (`texture::lod::log2`), λ,
//! the level choice and the bilinear weights `frac(u - 1/2)`, the texels as
//! `c / 255`, the lerps `a + (b - a) t` (four lanes at once: IEEE
//! single-precision operations lane by lane, no fused multiply-add), the
//! environment and fog as `env.rs` and `fog.rs` write them, and the
//! conversion to 8 bits. What it saves is the general path's overhead, not
//! arithmetic: no per-fragment dispatch over targets, units, formats,
//! wrap modes and environments, no `Coord` arrays, no libm `floorf` (the
//! floor below is exact for every f32), the 1/w of colour and fog shared
//! with the texture's q when their planes are the same (vertex q = 1), and
//! the levels resolved once per span. A fragment whose q is zero or not
//! finite, or whose coordinates are not finite, takes the reference
//! function itself. `tests/reference_diff.rs` compares both paths on
//! random mipmapped textures, filters, wraps, environments, fog and
//! geometry.
//!
//! Depth test first (early rejection), as `fast.rs` does: without the
//! alpha test, a fragment failing the depth test is never textured.
//!
//! On CPUs with AVX2, [`avx2`] runs the same computation 8 pixels at a
//! time for the samplers it takes (see its documentation), and under a
//! perspective hint other than GL_NICEST an approximation of it in 8-bit
//! fixed point (the only inexact textured path); this scalar
//! kernel serves the others, its short spans and irregular groups, and
//! the SSE2 and scalar levels.

use super::reference;
use super::fast::{depth_key, D_ANY, D_LEQUAL, D_LESS, D_OFF};
use super::{depth_to_fixed, write_color, ColorOp, FragmentState, SpanPixels};
use crate::gl::texture::enums::{GL_DECAL, GL_MODULATE, GL_REPLACE};
use crate::render::fog::Fog;
use crate::render::setup::{Plane, TriangleSetup};
use crate::render::texture::{Base, Fast, Filter, Target, Texels, UnitSampler, MAX_LOD_BIAS};
use glam::{Vec3, Vec4};

#[cfg(target_arch = "x86_64")]
mod avx2;

type Kernel = super::fast::Kernel;

/// Most levels a texture can have (a 2^15 base; GL_MAX_TEXTURE_SIZE is
/// smaller).
const MAX_LEVELS: usize = 16;

/// Tests: the 8-wide textured kernel in its AVX2 form on this thread even
/// where the CPU has AVX-512 (`avx2::pick`).
#[cfg(target_arch = "x86_64")]
#[doc(hidden)]
pub fn force_avx2_on_this_thread(on: bool) {
    avx2::force_avx2_on_this_thread(on)
}

/// Tests: the GL_FASTEST kernel on this thread computes λ per group in
/// scalar instead of eight groups ahead (`avx2::lambda_next`), which must
/// give the same bits.
#[cfg(target_arch = "x86_64")]
#[doc(hidden)]
pub fn lambda_ahead_on_this_thread(on: bool) {
    avx2::lambda_ahead_on_this_thread(on)
}

/// The textured kernel for a triangle, if its state is the common case.
/// `approximate`: GL_PERSPECTIVE_CORRECTION_HINT is not GL_NICEST; the
/// 8-wide kernel then filters in 8-bit fixed point (`avx2`'s
/// `fixed_color`); everything else stays exact.
#[cfg_attr(not(target_arch = "x86_64"), allow(unused_variables))] // only the x86-64 kernels read `approximate`
pub fn select(fs: &FragmentState, t: &TriangleSetup, approximate: bool) -> Option<Kernel> {
    let tp = t.tex.as_ref()?;
    if fs.alpha_test || fs.stencil_test || fs.color == ColorOp::None || t.secondary.is_some() || !applies(tp) {
        return None;
    }
    let d = depth_key(fs);
    let store = fs.color == ColorOp::Replace && fs.color_mask == [true; 4];
    #[cfg(target_arch = "x86_64")]
    if super::simd::level_here() == super::simd::Level::Avx2 {
        // Eight pixels at a time where the sampler allows (avx2.rs).
        if unit(tp).is_some_and(|(_, s)| avx2::takes(s)) {
            return Some(avx2::pick(d, store, approximate));
        }
        return Some(match (d, store) {
            (D_LESS, true) => kernel_avx2::<D_LESS, true>,
            (D_LEQUAL, true) => kernel_avx2::<D_LEQUAL, true>,
            (D_OFF, true) => kernel_avx2::<D_OFF, true>,
            (_, true) => kernel_avx2::<D_ANY, true>,
            (D_LESS, false) => kernel_avx2::<D_LESS, false>,
            (D_LEQUAL, false) => kernel_avx2::<D_LEQUAL, false>,
            (D_OFF, false) => kernel_avx2::<D_OFF, false>,
            _ => kernel_avx2::<D_ANY, false>,
        });
    }
    Some(match (d, store) {
        (D_OFF, true) => kernel::<D_OFF, true>,
        (D_LESS, true) => kernel::<D_LESS, true>,
        (D_LEQUAL, true) => kernel::<D_LEQUAL, true>,
        (_, true) => kernel::<D_ANY, true>,
        (D_OFF, false) => kernel::<D_OFF, false>,
        (D_LESS, false) => kernel::<D_LESS, false>,
        (D_LEQUAL, false) => kernel::<D_LEQUAL, false>,
        _ => kernel::<D_ANY, false>,
    })
}

/// The unit and its sampler, when the stage is the common case.
fn unit(tp: &crate::render::setup::TexPlanes) -> Option<(usize, &UnitSampler)> {
    let stage = &tp.stage;
    if stage.active.len() != 1 {
        return None;
    }
    let u = stage.active[0];
    Some((u, stage.units[u].as_ref()?))
}

fn applies(tp: &crate::render::setup::TexPlanes) -> bool {
    let Some((u, s)) = unit(tp) else { return false };
    let levels_ok = s.faces.len() == 1
        && !s.faces[0].is_empty()
        && s.faces[0].len() <= MAX_LEVELS
        && s.faces[0].iter().all(|l| l.border == 0 && l.width > 0 && l.height > 0 && matches!(l.texels, Texels::Rgba8(_)) && l.texels.len() >= (l.width * l.height) as usize);
    s.target == Target::T2D
        && s.base != Base::Depth
        && s.params.swizzle == crate::render::texture::SWIZZLE_IDENTITY
        && s.fast_wrap.is_some()
        && levels_ok
        && s.params.min_lod <= s.params.max_lod
        && matches!(tp.stage.envs[u].mode, GL_MODULATE | GL_REPLACE | GL_DECAL)
}

/// One level's texels and size.
#[derive(Clone, Copy)]
struct Level<'a> {
    tex: &'a [[u8; 4]],
    w: i32,
    h: i32,
    wf: f32,
    hf: f32,
}

/// Below this magnitude an f32 may have a fraction; at and above it every
/// f32 is an integer.
const EXACT: f32 = 8388608.0;

/// floor(x) and floor(x) as i32 for |x| < 2^23 (the caller checks).
#[inline(always)]
fn floor_i(x: f32) -> (f32, i32) {
    // SAFETY: |x| < 2^23, so the truncation fits in an i32.
    let i = unsafe { x.to_int_unchecked::<i32>() };
    let t = i as f32;
    // copysign: floor(-0) is -0.
    if t > x {
        (t - 1.0, i - 1)
    } else {
        (t.copysign(x), i)
    }
}

/// floor(x) for every f32 (values of magnitude 2^23 and more, infinities
/// and NaN stay as they are, as floor leaves them).
#[inline(always)]
fn floor(x: f32) -> f32 {
    if x.abs() < EXACT {
        floor_i(x).0
    } else {
        x
    }
}

/// floor(x) as i32 (saturating, NaN to 0, as `as` does).
#[inline(always)]
fn floor_to_i32(x: f32) -> i32 {
    if x.abs() < EXACT {
        floor_i(x).1
    } else {
        x as i32
    }
}

/// REPEAT or CLAMP_TO_EDGE of an index into [0, n) (`texture::wrap_fast`);
/// `P`: both wrap modes are REPEAT and n is a power of two.
#[inline(always)]
fn wrap<const P: bool>(i: i32, n: i32, repeat: bool) -> i32 {
    if P {
        i & (n - 1)
    } else if !repeat {
        i.clamp(0, n - 1)
    } else if n & (n - 1) == 0 {
        i & (n - 1)
    } else {
        i.rem_euclid(n)
    }
}

/// A texel as c / 255 per component (`texture::UNORM8`): the conversion
/// to f32 is exact and divps rounds the quotient correctly, as the
/// table's scalar division did.
#[cfg(target_arch = "x86_64")]
#[inline(always)]
fn texel(p: [u8; 4]) -> Vec4 {
    use std::arch::x86_64::*;
    // SAFETY: SSE2 is part of x86_64.
    unsafe {
        let z = _mm_setzero_si128();
        let v = _mm_cvtsi32_si128(i32::from_ne_bytes(p));
        let v = _mm_unpacklo_epi16(_mm_unpacklo_epi8(v, z), z);
        Vec4::from(_mm_div_ps(_mm_cvtepi32_ps(v), _mm_set1_ps(255.0)))
    }
}

#[cfg(not(target_arch = "x86_64"))]
#[inline(always)]
fn texel(p: [u8; 4]) -> Vec4 {
    use crate::render::texture::UNORM8;
    Vec4::new(UNORM8[p[0] as usize], UNORM8[p[1] as usize], UNORM8[p[2] as usize], UNORM8[p[3] as usize])
}

/// `fragment::color_to_u8` on four lanes: max(v, 0) gives 0 for NaN as
/// the scalar clamp-then-cast does, and the truncation of a value in
/// [0.5, 255.5] is the cast's.
#[cfg(target_arch = "x86_64")]
#[inline(always)]
fn to_u8(c: Vec4) -> [u8; 4] {
    use std::arch::x86_64::*;
    // SAFETY: SSE2 is part of x86_64.
    unsafe {
        let v = _mm_min_ps(_mm_max_ps(c.into(), _mm_setzero_ps()), _mm_set1_ps(1.0));
        let v = _mm_add_ps(_mm_mul_ps(v, _mm_set1_ps(255.0)), _mm_set1_ps(0.5));
        let i = _mm_cvttps_epi32(v);
        let i = _mm_packs_epi32(i, i);
        (_mm_cvtsi128_si32(_mm_packus_epi16(i, i))).to_ne_bytes()
    }
}

#[cfg(not(target_arch = "x86_64"))]
#[inline(always)]
fn to_u8(c: Vec4) -> [u8; 4] {
    super::color_to_u8(c)
}

#[inline(always)]
fn lerp(a: Vec4, b: Vec4, t: f32) -> Vec4 {
    a + (b - a) * Vec4::splat(t)
}

impl Level<'_> {
    /// Nearest filtering (`UnitSampler::nearest_2d`).
    #[inline(always)]
    fn nearest<const P: bool>(&self, s: f32, t: f32, repeat: [bool; 2]) -> Vec4 {
        let i = wrap::<P>(floor_to_i32(s * self.wf), self.w, repeat[0]);
        let j = wrap::<P>(floor_to_i32(t * self.hf), self.h, repeat[1]);
        texel(self.tex[(j * self.w + i) as usize])
    }

    /// Bilinear filtering (`UnitSampler::linear_2d`).
    #[inline(always)]
    fn linear<const P: bool>(&self, s: f32, t: f32, repeat: [bool; 2]) -> Vec4 {
        let (a, b) = (s * self.wf - 0.5, t * self.hf - 0.5);
        let ((fa, i0), (fb, j0)) = if a.abs() < EXACT && b.abs() < EXACT {
            (floor_i(a), floor_i(b))
        } else {
            ((a.floor(), a.floor() as i32), (b.floor(), b.floor() as i32))
        };
        self.linear_at::<P>((a - fa, b - fb), (i0, j0), repeat)
    }

    /// Bilinear filtering from the floors and weights `linear` computes
    /// (`fa`, `i0` of a = s w - 1/2; `fb`, `j0` of b = t h - 1/2).
    #[inline(always)]
    fn linear_at<const P: bool>(&self, (wa, wb): (f32, f32), ij: (i32, i32), repeat: [bool; 2]) -> Vec4 {
        let [p00, p01, p10, p11] = self.corners::<P>(ij, repeat);
        let top = lerp(texel(p00), texel(p01), wa);
        let bottom = lerp(texel(p10), texel(p11), wa);
        lerp(top, bottom, wb)
    }

    /// The 2x2 texels from (i0, j0), wrapped: top-left, top-right,
    /// bottom-left, bottom-right.
    #[inline(always)]
    fn corners<const P: bool>(&self, (i0, j0): (i32, i32), repeat: [bool; 2]) -> [[u8; 4]; 4] {
        let (i0w, i1w) = (wrap::<P>(i0, self.w, repeat[0]), wrap::<P>(i0.wrapping_add(1), self.w, repeat[0]));
        let (j0w, j1w) = (wrap::<P>(j0, self.h, repeat[1]), wrap::<P>(j0.wrapping_add(1), self.h, repeat[1]));
        let (r0, r1) = ((j0w * self.w) as usize, (j1w * self.w) as usize);
        let (c0, c1) = (i0w as usize, i1w as usize);
        [self.tex[r0 + c0], self.tex[r0 + c1], self.tex[r1 + c0], self.tex[r1 + c1]]
    }

    #[inline(always)]
    fn filter<const P: bool>(&self, s: f32, t: f32, linear: bool, repeat: [bool; 2]) -> Vec4 {
        if linear {
            self.linear::<P>(s, t, repeat)
        } else {
            self.nearest::<P>(s, t, repeat)
        }
    }
}

/// Bilinear filtering of two levels at (s, t) (LINEAR_MIPMAP_LINEAR):
/// `Level::linear` of each, with the four products, the four subtractions
/// of 1/2 and the four floors (`floor_i`, sign of -0 included) done in one
/// SSE2 register: the same IEEE operations lane by lane, so the same
/// values. A lane of magnitude 2^23 or more (or NaN) takes the scalar
/// function.
#[cfg(target_arch = "x86_64")]
#[inline(always)]
fn linear2<const P: bool, const A: bool>(l1: &Level, l2: &Level, s: f32, t: f32, rep: [bool; 2]) -> (Vec4, Vec4) {
    use std::arch::x86_64::*;
    // SAFETY: SSE2 is part of x86_64.
    let (w, i, ok) = unsafe {
        let x = _mm_sub_ps(_mm_mul_ps(_mm_setr_ps(s, t, s, t), _mm_setr_ps(l1.wf, l1.hf, l2.wf, l2.hf)), _mm_set1_ps(0.5));
        let sign = _mm_set1_ps(-0.0);
        let ok = _mm_movemask_ps(_mm_cmplt_ps(_mm_andnot_ps(sign, x), _mm_set1_ps(EXACT))) == 0xf;
        // floor_i: truncate; one less where the truncation is above x;
        // else the truncation with x's sign (only -0 changes).
        let ti = _mm_cvttps_epi32(x);
        let tf = _mm_cvtepi32_ps(ti);
        let gt = _mm_cmpgt_ps(tf, x);
        let fl = _mm_or_ps(_mm_sub_ps(tf, _mm_and_ps(gt, _mm_set1_ps(1.0))), _mm_and_ps(x, sign));
        let i = _mm_add_epi32(ti, _mm_castps_si128(gt));
        let (mut wv, mut iv) = ([0f32; 4], [0i32; 4]);
        _mm_storeu_ps(wv.as_mut_ptr(), _mm_sub_ps(x, fl));
        _mm_storeu_si128(iv.as_mut_ptr() as *mut __m128i, i);
        (wv, iv, ok)
    };
    if !ok {
        return (l1.linear::<P>(s, t, rep), l2.linear::<P>(s, t, rep));
    }
    if A {
        let (a, b) = (l1.corners::<P>((i[0], i[1]), rep), l2.corners::<P>((i[2], i[3]), rep));
        // SAFETY: A is true only in the AVX2 kernel (`kernel_avx2`).
        return unsafe { bilerp2_avx(a, b, w) };
    }
    (l1.linear_at::<P>((w[0], w[1]), (i[0], i[1]), rep), l2.linear_at::<P>((w[2], w[3]), (i[2], i[3]), rep))
}

/// Two levels' bilinear lerps in the two halves of 8-lane registers:
/// `Level::linear_at`'s texel conversions (c / 255, correctly rounded
/// lane by lane) and lerps `a + (b - a) t` (separate multiply and add),
/// with level 1's weights `w[0], w[1]` in the low half and level 2's
/// `w[2], w[3]` in the high half. Corners: top-left, top-right,
/// bottom-left, bottom-right.
#[cfg(target_arch = "x86_64")]
#[inline]
#[target_feature(enable = "avx2")]
unsafe fn bilerp2_avx(a: [[u8; 4]; 4], b: [[u8; 4]; 4], w: [f32; 4]) -> (Vec4, Vec4) {
    use std::arch::x86_64::*;
    // No closures: they would not inherit the function's target feature.
    let k255 = _mm256_set1_ps(255.0);
    let c = [0, 1, 2, 3].map(|k| _mm_set_epi32(0, 0, i32::from_ne_bytes(b[k]), i32::from_ne_bytes(a[k])));
    let c00 = _mm256_div_ps(_mm256_cvtepi32_ps(_mm256_cvtepu8_epi32(c[0])), k255);
    let c01 = _mm256_div_ps(_mm256_cvtepi32_ps(_mm256_cvtepu8_epi32(c[1])), k255);
    let c10 = _mm256_div_ps(_mm256_cvtepi32_ps(_mm256_cvtepu8_epi32(c[2])), k255);
    let c11 = _mm256_div_ps(_mm256_cvtepi32_ps(_mm256_cvtepu8_epi32(c[3])), k255);
    let wa = _mm256_setr_ps(w[0], w[0], w[0], w[0], w[2], w[2], w[2], w[2]);
    let wb = _mm256_setr_ps(w[1], w[1], w[1], w[1], w[3], w[3], w[3], w[3]);
    let top = _mm256_add_ps(c00, _mm256_mul_ps(_mm256_sub_ps(c01, c00), wa));
    let bottom = _mm256_add_ps(c10, _mm256_mul_ps(_mm256_sub_ps(c11, c10), wa));
    let r = _mm256_add_ps(top, _mm256_mul_ps(_mm256_sub_ps(bottom, top), wb));
    (Vec4::from(_mm256_castps256_ps128(r)), Vec4::from(_mm256_extractf128_ps::<1>(r)))
}

#[cfg(not(target_arch = "x86_64"))]
#[inline(always)]
fn linear2<const P: bool, const A: bool>(l1: &Level, l2: &Level, s: f32, t: f32, rep: [bool; 2]) -> (Vec4, Vec4) {
    (l1.linear::<P>(s, t, rep), l2.linear::<P>(s, t, rep))
}

/// A span's view of the sampler: levels resolved, parameters unpacked.
struct Sampler<'a> {
    levels: [Level<'a>; MAX_LEVELS],
    /// q: the last level.
    q: usize,
    repeat: [bool; 2],
    fast: Fast,
    min: Filter,
    mag_linear: bool,
    c_switch: f32,
    bias: f32,
    min_lod: f32,
    max_lod: f32,
}

impl<'a> Sampler<'a> {
    /// All levels have power-of-two sizes and both wrap modes are REPEAT.
    fn pow2_repeat(&self) -> bool {
        self.repeat == [true; 2] && self.levels[..=self.q].iter().all(|l| l.w & (l.w - 1) == 0 && l.h & (l.h - 1) == 0)
    }

    fn new(s: &'a UnitSampler) -> Sampler<'a> {
        let empty = Level { tex: &[], w: 1, h: 1, wf: 1.0, hf: 1.0 };
        let mut levels = [empty; MAX_LEVELS];
        for (l, img) in levels.iter_mut().zip(&s.faces[0]) {
            if let Texels::Rgba8(tex) = &img.texels {
                *l = Level { tex: &tex[..], w: img.width, h: img.height, wf: img.width as f32, hf: img.height as f32 };
            }
        }
        let p = &s.params;
        Sampler {
            levels,
            q: s.faces[0].len() - 1,
            repeat: s.fast_wrap.unwrap_or([true; 2]),
            fast: s.fast,
            min: p.min_filter,
            mag_linear: p.mag_filter == Filter::Linear,
            c_switch: if p.mag_filter == Filter::Linear && matches!(p.min_filter, Filter::NearestMipmapNearest | Filter::LinearMipmapNearest) { 0.5 } else { 0.0 },
            bias: (p.lod_bias + s.unit_bias).clamp(-MAX_LOD_BIAS, MAX_LOD_BIAS),
            min_lod: p.min_lod,
            max_lod: p.max_lod,
        }
    }

    /// `UnitSampler::sample` at (s, t) with derivatives (dsdx, dtdx) and
    /// (dsdy, dtdy).
    #[inline(always)]
    fn sample<const P: bool, const A: bool>(&self, s: f32, t: f32, dx: [f32; 2], dy: [f32; 2]) -> Vec4 {
        let rep = self.repeat;
        match self.fast {
            Fast::Nearest2D { .. } => return self.levels[0].nearest::<P>(s, t, rep),
            Fast::Linear2D { .. } => return self.levels[0].linear::<P>(s, t, rep),
            Fast::General => {}
        }
        let (n0, n1) = (self.levels[0].wf, self.levels[0].hf);
        let lx = ((dx[0] * n0).powi(2) + (dx[1] * n1).powi(2)).sqrt();
        let ly = ((dy[0] * n0).powi(2) + (dy[1] * n1).powi(2)).sqrt();
        let rho = lx.max(ly);
        let lambda = (crate::render::texture::lod::log2(rho) + self.bias).clamp(self.min_lod, self.max_lod);
        if lambda > self.c_switch && !lambda.is_nan() {
            let q = self.q;
            match self.min {
                Filter::Nearest => self.levels[0].nearest::<P>(s, t, rep),
                Filter::Linear => self.levels[0].linear::<P>(s, t, rep),
                f @ (Filter::NearestMipmapNearest | Filter::LinearMipmapNearest) => {
                    let d = if lambda <= 0.5 { 0 } else { (((lambda + 0.5).ceil() - 1.0) as usize).min(q) };
                    self.levels[d].filter::<P>(s, t, f == Filter::LinearMipmapNearest, rep)
                }
                f => {
                    let lin = f == Filter::LinearMipmapLinear;
                    let d1 = floor(lambda);
                    if d1 as usize >= q || d1 >= q as f32 {
                        self.levels[q].filter::<P>(s, t, lin, rep)
                    } else {
                        let d1i = d1.max(0.0) as usize;
                        let (l1, l2) = (&self.levels[d1i], &self.levels[d1i + 1]);
                        let (t1, t2) = if lin {
                            linear2::<P, A>(l1, l2, s, t, rep)
                        } else {
                            (l1.nearest::<P>(s, t, rep), l2.nearest::<P>(s, t, rep))
                        };
                        lerp(t1, t2, lambda - d1)
                    }
                }
            }
        } else {
            self.levels[0].filter::<P>(s, t, self.mag_linear, rep)
        }
    }
}

/// The texture environment of `env.rs` for REPLACE, MODULATE and DECAL,
/// by the texture's base format.
#[derive(Clone, Copy)]
enum EnvFn {
    Replace { color: bool, alpha: bool },
    Modulate { color: bool, alpha: bool },
    DecalRgb,
    DecalRgba,
    /// DECAL of other formats: the primary colour passes (undefined).
    Pass,
}

impl EnvFn {
    fn new(mode: u32, base: Base) -> EnvFn {
        let color = base != Base::Alpha;
        let alpha = matches!(base, Base::Alpha | Base::LuminanceAlpha | Base::Intensity | Base::Rgba);
        match (mode, base) {
            (GL_REPLACE, _) => EnvFn::Replace { color, alpha },
            (GL_MODULATE, _) => EnvFn::Modulate { color, alpha },
            (_, Base::Rgb) => EnvFn::DecalRgb,
            (_, Base::Rgba) => EnvFn::DecalRgba,
            _ => EnvFn::Pass,
        }
    }

    #[inline(always)]
    fn apply(self, prev: Vec4, ct: Vec4) -> Vec4 {
        let (pc, pa) = (prev.truncate(), prev.w);
        let (tc, ta) = (ct.truncate(), ct.w);
        let out: (Vec3, f32) = match self {
            EnvFn::Replace { color, alpha } => (if color { tc } else { pc }, if alpha { ta } else { pa }),
            EnvFn::Modulate { color, alpha } => (if color { pc * tc } else { pc }, if alpha { pa * ta } else { pa }),
            EnvFn::DecalRgb => (tc, pa),
            EnvFn::DecalRgba => (pc * (1.0 - ta) + tc * ta, pa),
            EnvFn::Pass => (pc, pa),
        };
        out.0.extend(out.1).clamp(Vec4::ZERO, Vec4::ONE)
    }
}

/// A plane's row term and x slope.
#[derive(Clone, Copy)]
struct Row {
    r: f64,
    dx: f64,
}

impl Row {
    #[inline(always)]
    fn new(p: &Plane, cy: f64) -> Row {
        Row { r: p.a0 + p.dy * cy, dx: p.dx }
    }
    #[inline(always)]
    fn at(self, cx: f64) -> f64 {
        self.r + self.dx * cx
    }
}

fn same_plane(a: &Plane, b: &Plane) -> bool {
    a.a0.to_bits() == b.a0.to_bits() && a.dx.to_bits() == b.dx.to_bits() && a.dy.to_bits() == b.dy.to_bits()
}

fn kernel<const D: u8, const STORE: bool>(fs: &FragmentState, t: &TriangleSetup, px: &mut SpanPixels, y: usize, x0: usize, x1: usize) {
    kernel_at::<D, STORE, false>(fs, t, px, y, x0, x1)
}

/// The kernel compiled for AVX2: both levels of LINEAR_MIPMAP_LINEAR
/// filtered in one 8-lane register (`bilerp2_avx`). Only selected when
/// the CPU has AVX2 (`simd::level`).
#[cfg(target_arch = "x86_64")]
fn kernel_avx2<const D: u8, const STORE: bool>(fs: &FragmentState, t: &TriangleSetup, px: &mut SpanPixels, y: usize, x0: usize, x1: usize) {
    // SAFETY: `select` hands this out only at simd::Level::Avx2, which is
    // only reported when the CPU has AVX2.
    unsafe { kernel_avx2_at::<D, STORE>(fs, t, px, y, x0, x1) }
}

#[cfg(target_arch = "x86_64")]
#[target_feature(enable = "avx2")]
unsafe fn kernel_avx2_at<const D: u8, const STORE: bool>(fs: &FragmentState, t: &TriangleSetup, px: &mut SpanPixels, y: usize, x0: usize, x1: usize) {
    kernel_at::<D, STORE, true>(fs, t, px, y, x0, x1)
}

#[inline(always)]
fn kernel_at<const D: u8, const STORE: bool, const A: bool>(fs: &FragmentState, t: &TriangleSetup, px: &mut SpanPixels, y: usize, x0: usize, x1: usize) {
    if x0 >= x1 {
        return;
    }
    let Some(tp) = t.tex.as_ref() else { return reference::shade_span(fs, t, px, y, x0, x1) };
    let Some((u, sampler)) = unit(tp) else { return reference::shade_span(fs, t, px, y, x0, x1) };
    let smp = Sampler::new(sampler);
    let env = EnvFn::new(tp.stage.envs[u].mode, sampler.base);
    // MODULATE of a texture with colour and alpha: one four-lane product.
    let modulate = matches!(env, EnvFn::Modulate { color: true, alpha: true });
    match (smp.pow2_repeat(), modulate) {
        (true, true) => span::<D, STORE, true, true, A>(fs, t, px, y, x0, x1, tp, u, env, &smp),
        (true, false) => span::<D, STORE, true, false, A>(fs, t, px, y, x0, x1, tp, u, env, &smp),
        (false, true) => span::<D, STORE, false, true, A>(fs, t, px, y, x0, x1, tp, u, env, &smp),
        (false, false) => span::<D, STORE, false, false, A>(fs, t, px, y, x0, x1, tp, u, env, &smp),
    }
}

#[allow(clippy::too_many_arguments)]
#[inline(always)]
fn span<const D: u8, const STORE: bool, const P: bool, const M: bool, const A: bool>(
    fs: &FragmentState,
    t: &TriangleSetup,
    px: &mut SpanPixels,
    y: usize,
    x0: usize,
    x1: usize,
    tp: &crate::render::setup::TexPlanes,
    u: usize,
    env: EnvFn,
    smp: &Sampler,
) {
    let cy = y as f64 + 0.5 - t.y0;
    let p = &tp.planes[u];
    let (s_row, t_row, q_row) = (Row::new(&p[0], cy), Row::new(&p[1], cy), Row::new(&p[3], cy));
    let (sdx, sdy, tdx, tdy, qdx, qdy) = (p[0].dx, p[0].dy, p[1].dx, p[1].dy, p[3].dx, p[3].dy);
    let z_row = Row::new(&t.z, cy);
    let w_row = Row::new(&t.q, cy);
    // 1/w of colour and fog is the texture's 1/q when the planes agree.
    let shared_w = same_plane(&t.q, &p[3]);
    let color_rows: [Row; 4] = std::array::from_fn(|c| Row::new(&t.color[c], cy));
    let flat = t.flat.map(|c| Vec4::from_array(c.map(|v| v as f32 / 255.0)));
    let fog: Option<(Row, Fog)> = t.fog.as_ref().map(|(plane, f)| (Row::new(plane, cy), *f));
    let n = x1 - x0;
    let SpanPixels { color, depth, passed: total, .. } = px;
    let col = &mut color[..n];
    let dep = &mut depth[..if D != D_OFF { n } else { 0 }];
    let mut passed = 0u64;
    for k in 0..n {
        let cx = (x0 + k) as f64 + 0.5 - t.x0;
        if D != D_OFF {
            let z = depth_to_fixed(z_row.at(cx));
            let stored = dep[k];
            let pass = match D {
                D_LESS => z < stored,
                D_LEQUAL => z <= stored,
                _ => fs.depth_func.test(z, stored),
            };
            if !pass {
                continue;
            }
            if D != D_ANY || fs.depth_write {
                dep[k] = z;
            }
        }
        passed += 1;
        // Texture coordinates (reference::textured_color).
        let q = q_row.at(cx);
        let src = 'shade: {
            if q == 0.0 || !q.is_finite() {
                break 'shade reference::triangle_color(t, cx, cy);
            }
            let iq = 1.0 / q;
            let (s, tt) = (s_row.at(cx) * iq, t_row.at(cx) * iq);
            let (sf, tf) = (s as f32, tt as f32);
            if !(sf.is_finite() && tf.is_finite()) {
                break 'shade reference::triangle_color(t, cx, cy);
            }
            let dx = [((sdx - s * qdx) * iq) as f32, ((tdx - tt * qdx) * iq) as f32];
            let dy = [((sdy - s * qdy) * iq) as f32, ((tdy - tt * qdy) * iq) as f32];
            let w = if !t.perspective {
                1.0
            } else if shared_w {
                iq
            } else {
                1.0 / w_row.at(cx)
            };
            let primary = match flat {
                Some(c) => c,
                None => Vec4::from_array(std::array::from_fn(|c| (color_rows[c].at(cx) * w) as f32)).clamp(Vec4::ZERO, Vec4::ONE),
            };
            let texel = smp.sample::<P, A>(sf, tf, dx, dy);
            // (pc tc, pa ta) lane by lane is env.rs's MODULATE.
            let c = if M { (primary * texel).clamp(Vec4::ZERO, Vec4::ONE) } else { env.apply(primary, texel) };
            match &fog {
                Some((row, f)) => to_u8(f.apply(c, (row.at(cx) * w) as f32)),
                None => to_u8(c),
            }
        };
        if STORE {
            col[k] = super::fast::with_alpha(src, fs.alpha_fix);
        } else {
            write_color(fs, &mut col[k], src);
        }
    }
    *total += passed;
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::render::fragment::color_to_u8;
    use crate::render::texture::UNORM8;

    fn values() -> Vec<f32> {
        let mut v = vec![0.0, -0.0, 0.5, -0.5, 1.0, -1.0, 0.9999999, -0.9999999, 1e-30, -1e-30, 8388607.5, -8388607.5, 8388608.0, -8388608.0, 1e20, -1e20, f32::MAX, f32::MIN, f32::INFINITY, f32::NEG_INFINITY, f32::NAN, 2147483520.0, -2147483648.0, 3e9, -3e9];
        let mut seed = 7u32;
        for _ in 0..200_000 {
            seed = seed.wrapping_mul(1664525).wrapping_add(1013904223);
            v.push(f32::from_bits(seed));
            v.push((seed as i32) as f32 / 65536.0);
            v.push((seed % 4096) as f32 / 64.0 - 32.0);
        }
        v
    }

    /// The floors and the integer conversion agree with std's floor and
    /// `as` on random bit patterns, fractions and the edge values.
    #[test]
    fn floors_match_std() {
        for x in values() {
            assert_eq!(floor(x).to_bits(), x.floor().to_bits(), "floor {x}");
            assert_eq!(floor_to_i32(x), x.floor() as i32, "floor as i32 {x}");
        }
    }

    /// The two-level bilinear filter (floors in SSE2 lanes) agrees bit for
    /// bit with `Level::linear` of each level, at every wrap choice.
    #[test]
    fn linear2_matches_linear() {
        let mut seed = 99u32;
        let mut img = |n: usize| -> Vec<[u8; 4]> {
            (0..n).map(|_| {
                seed = seed.wrapping_mul(1664525).wrapping_add(1013904223);
                seed.to_ne_bytes()
            }).collect()
        };
        let (a, b, c) = (img(64 * 32), img(32 * 16), img(5 * 3));
        fn lv(tex: &[[u8; 4]], w: i32, h: i32) -> Level<'_> {
            Level { tex, w, h, wf: w as f32, hf: h as f32 }
        }
        let (la, lb, lc) = (lv(&a, 64, 32), lv(&b, 32, 16), lv(&c, 5, 3));
        let v = values();
        let bits = |p: (Vec4, Vec4)| (p.0.to_array().map(f32::to_bits), p.1.to_array().map(f32::to_bits));
        for (k, st) in v.chunks_exact(2).enumerate() {
            let (s, t) = (st[0] / 64.0 * (k % 7) as f32, st[1] / 16.0);
            for rep in [[true, true], [false, true], [true, false], [false, false]] {
                let want = (la.linear::<false>(s, t, rep), lb.linear::<false>(s, t, rep));
                assert_eq!(bits(linear2::<false, false>(&la, &lb, s, t, rep)), bits(want), "{s} {t} {rep:?}");
                let want = (lb.linear::<false>(s, t, rep), lc.linear::<false>(s, t, rep));
                assert_eq!(bits(linear2::<false, false>(&lb, &lc, s, t, rep)), bits(want), "{s} {t} {rep:?}");
            }
            let want = (la.linear::<true>(s, t, [true; 2]), lb.linear::<true>(s, t, [true; 2]));
            assert_eq!(bits(linear2::<true, false>(&la, &lb, s, t, [true; 2])), bits(want), "{s} {t}");
            // The AVX2 lerps (the test calls them outside the kernel).
            #[cfg(target_arch = "x86_64")]
            if std::arch::is_x86_feature_detected!("avx2") {
                assert_eq!(bits(linear2::<true, true>(&la, &lb, s, t, [true; 2])), bits(want), "avx2 {s} {t}");
                let want = (lb.linear::<false>(s, t, [false, true]), lc.linear::<false>(s, t, [false, true]));
                assert_eq!(bits(linear2::<false, true>(&lb, &lc, s, t, [false, true])), bits(want), "avx2 {s} {t}");
            }
        }
    }

    /// The four-lane conversions agree with the scalar ones.
    #[test]
    fn lane_conversions_match_scalar() {
        for p in 0..=255u8 {
            let t = texel([p, 255 - p, p / 3, 0]);
            assert_eq!(t.to_array(), [UNORM8[p as usize], UNORM8[255 - p as usize], UNORM8[(p / 3) as usize], 0.0]);
        }
        let v = values();
        for c in v.chunks_exact(4) {
            let c = Vec4::from_slice(c);
            assert_eq!(to_u8(c), color_to_u8(c), "{c:?}");
        }
        for k in 0..=2550 {
            let c = Vec4::splat(k as f32 / 2550.0);
            assert_eq!(to_u8(c), color_to_u8(c), "{c:?}");
        }
    }
}
