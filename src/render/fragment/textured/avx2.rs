//! The textured span kernel eight pixels at a time (AVX2): what
//! [`super::span`] computes per fragment, in lanes, bit for bit.
//!
//! Per group of 8 pixels: depth (f64 lanes, as `simd.rs`), the
//! perspective divide of s, t and their exact derivatives
//! `(S' - s Q') / Q` (f64 lanes), ρ and λ (f32 lanes, [`lod::log2_8`],
//! the same function the reference sampler uses), the level choice per
//! lane, the 2x2 (or 1) texels of each level by gathers, their conversion
//! c / 255, the lerps `a + (b - a) t`, the environment, fog and the
//! conversion to bytes: every lane runs the scalar kernel's IEEE
//! operations in the same order (no fused multiply-add but those of
//! `lod`'s log2 series, which the scalar form fuses too), so no tolerance
//! is needed.
//!
//! LINEAR filtering reads the bilinear footprint from the sampler's padded
//! copy of the levels (`texture::pairs`): the two texels of a row are
//! adjacent there whatever the wrap, so each row is one 64-bit load per
//! lane. Plain 64-bit loads (`SCALAR_LOADS`) replace `vpgatherdq`: on this
//! AMD machine they took less CPU time (callgrind counts a gather as one
//! instruction, so its counts rise: see docs/perf-notes.md, Round 4).
//!
//! GL_FASTEST / GL_DONT_CARE (`FX`): `fastest` replaces the texturing of
//! a group by an approximation in 8-bit fixed point (its documentation
//! says which); depth stays exact. `tests/reference_diff.rs` bounds its
//! error against the reference path. Its λ at the groups' ends is computed
//! for eight groups at once (`lambda_next`), in the bits of the per-group
//! scalar `lambda_at`.
//!
//! c / 255 (correctly rounded, as the scalar kernel's division) comes from
//! integer bits (`unorm`): for a byte c > 0, n = c 0x010101 < 2^24 is
//! converted exactly, n 2^-24 is an exponent change, and c / 255 =
//! n 2^-24 (1 + 2^-24 + 2^-48 + ...) lies strictly between n 2^-24 plus
//! half an ulp and plus one ulp, so it rounds to n 2^-24 plus one ulp:
//! the float's bits plus 1 - (24 << 23). `vpshufb` builds n from a packed
//! texel (bytes c, c, c, 0). Tested for every byte in every channel.
//! The kernel needs FMA besides AVX2 (`takes` checks; the GL_FASTEST
//! kernel's polynomials may use it).
//!
//! `span_wide` (CPUs with AVX-512 F, VL, BW, DQ) is the same kernel with
//! the f64 lanes in one 512-bit register, the two rows of a bilinear
//! footprint converted and lerped across in 16 lanes at once, and λ's
//! log2 in one register (`Isa`): the same operations lane by lane, so the
//! same bits as `span` (tests run both).
//!
//! Taken: the states `super::select` takes whose per-level filter is the
//! same on both sides of the magnification switch (mag LINEAR with min
//! LINEAR, LINEAR_MIPMAP_NEAREST or LINEAR_MIPMAP_LINEAR; mag NEAREST with
//! min NEAREST, NEAREST_MIPMAP_NEAREST or NEAREST_MIPMAP_LINEAR), each
//! REPEAT axis of power-of-two size at every level (CLAMP_TO_EDGE axes any
//! size). Lanes of a group may use different levels: the group is filtered
//! once per distinct level. A group with a coordinate outside ±2^22 texels,
//! q zero or not finite, or ρ not finite, and spans of fewer than 8
//! pixels and the last pixels of a span (fewer than 8) go through the
//! scalar kernel.

use super::super::fast::{Kernel, D_ANY, D_LEQUAL, D_LESS, D_OFF};
use super::super::{write_color, FragmentState, SpanPixels};
use super::{same_plane, EnvFn, Level, Sampler};
use crate::framebuffer::DEPTH_MAX;
use crate::render::fog::Fog;
use crate::render::setup::TriangleSetup;
use crate::render::texture::pairs::{Padded, PaddedLevel};
use crate::render::texture::{lod, Fast, Filter, UnitSampler};
use std::arch::x86_64::*;

const SCALAR_LOADS: bool = true;

/// Added to the bits of float(c 0x010101) to give c / 255 (`unorm`):
/// 2^-24 (the exponent down by 24) and one ulp up.
const UNORM_BITS: i32 = 1 - (24 << 23);

/// How a span's lanes pick their levels.
#[derive(Clone, Copy, PartialEq)]
enum Lod {
    /// Level 0 only (min and mag filters equal and not mipmapped).
    None,
    /// NEAREST_MIPMAP_NEAREST or LINEAR_MIPMAP_NEAREST; `c`: the
    /// magnification switch-over point.
    Nearest { c: f32 },
    /// NEAREST_MIPMAP_LINEAR or LINEAR_MIPMAP_LINEAR.
    Linear,
}

/// The level choice and per-level filter (LINEAR or NEAREST) of a
/// sampler, if this kernel takes it.
fn plan(smp: &Sampler) -> Option<(Lod, bool)> {
    let (lod, linear) = match smp.fast {
        Fast::Nearest2D { .. } => (Lod::None, false),
        Fast::Linear2D { .. } => (Lod::None, true),
        Fast::General => {
            let linear = smp.mag_linear;
            let lod = match (smp.min, linear) {
                (Filter::LinearMipmapLinear, true) | (Filter::NearestMipmapLinear, false) => Lod::Linear,
                (Filter::LinearMipmapNearest, true) | (Filter::NearestMipmapNearest, false) => Lod::Nearest { c: smp.c_switch },
                _ => return None,
            };
            (lod, linear)
        }
    };
    let levels = &smp.levels[..=smp.q];
    let pow2 = |n: i32| n & (n - 1) == 0;
    if (smp.repeat[0] && !levels.iter().all(|l| pow2(l.w))) || (smp.repeat[1] && !levels.iter().all(|l| pow2(l.h))) {
        return None;
    }
    Some((lod, linear))
}

/// Whether this kernel takes a sampler (`super::select` has checked the
/// rest of the state). POPCNT (on every CPU with AVX2 and FMA, checked all
/// the same) counts a group's passed lanes in one instruction, not the
/// fifteen of the portable bit count.
pub(super) fn takes(s: &UnitSampler) -> bool {
    std::arch::is_x86_feature_detected!("fma") && std::arch::is_x86_feature_detected!("popcnt") && plan(&Sampler::new(s)).is_some()
}

/// The kernel for a depth key, whether colours are stored as they are,
/// and `fx`: GL_PERSPECTIVE_CORRECTION_HINT is not GL_NICEST, so
/// texturing may be approximated (`fastest`). AVX-512 (`span_wide`) when
/// the CPU has it, unless a test asked for AVX2 on this thread.
pub(super) fn pick(d: u8, store: bool, fx: bool) -> Kernel {
    if wide() && !NARROW_HERE.with(|c| c.get()) {
        pick_in::<true>(d, store, fx)
    } else {
        pick_in::<false>(d, store, fx)
    }
}

fn pick_in<const W: bool>(d: u8, store: bool, fx: bool) -> Kernel {
    match (d, store, fx) {
        (D_LESS, true, true) => kernel::<D_LESS, true, true, W>,
        (D_LEQUAL, true, true) => kernel::<D_LEQUAL, true, true, W>,
        (D_OFF, true, true) => kernel::<D_OFF, true, true, W>,
        (_, true, true) => kernel::<D_ANY, true, true, W>,
        (D_LESS, false, true) => kernel::<D_LESS, false, true, W>,
        (D_LEQUAL, false, true) => kernel::<D_LEQUAL, false, true, W>,
        (D_OFF, false, true) => kernel::<D_OFF, false, true, W>,
        (_, false, true) => kernel::<D_ANY, false, true, W>,
        (D_LESS, true, false) => kernel::<D_LESS, true, false, W>,
        (D_LEQUAL, true, false) => kernel::<D_LEQUAL, true, false, W>,
        (D_OFF, true, false) => kernel::<D_OFF, true, false, W>,
        (_, true, false) => kernel::<D_ANY, true, false, W>,
        (D_LESS, false, false) => kernel::<D_LESS, false, false, W>,
        (D_LEQUAL, false, false) => kernel::<D_LEQUAL, false, false, W>,
        (D_OFF, false, false) => kernel::<D_OFF, false, false, W>,
        _ => kernel::<D_ANY, false, false, W>,
    }
}

thread_local! {
    /// Tests: select the AVX2 form on this thread even where AVX-512 is.
    static NARROW_HERE: std::cell::Cell<bool> = const { std::cell::Cell::new(false) };
}

thread_local! {
    /// Tests: no λ ahead (`lambda_next`) on this thread.
    static NO_AHEAD_HERE: std::cell::Cell<bool> = const { std::cell::Cell::new(false) };
}

/// Whether GL_FASTEST spans on the calling thread take λ eight groups
/// ahead (`lambda_next`, the default) or per group: for differential tests.
pub(super) fn lambda_ahead_on_this_thread(on: bool) {
    NO_AHEAD_HERE.with(|c| c.set(!on));
}

/// Makes textured kernel selection on the calling thread take the AVX2
/// form (`span`) even on CPUs with AVX-512: for differential tests.
pub(super) fn force_avx2_on_this_thread(on: bool) {
    NARROW_HERE.with(|c| c.set(on));
}

fn kernel<const D: u8, const STORE: bool, const FX: bool, const W: bool>(fs: &FragmentState, t: &TriangleSetup, px: &mut SpanPixels, y: usize, x0: usize, x1: usize) {
    // SAFETY: `super::select` hands this out only at simd::Level::Avx2,
    // which is only reported when the CPU has AVX2, and when `takes`
    // found FMA and POPCNT; W only when `wide` found AVX-512 F, VL, BW and DQ.
    unsafe {
        if W {
            span_wide::<D, STORE, FX>(fs, t, px, y, x0, x1)
        } else {
            span::<D, STORE, FX>(fs, t, px, y, x0, x1)
        }
    }
}

/// Whether the CPU has AVX-512 (F, VL, BW, DQ) and `SOFTGL_SIMD` does not
/// ask for `avx2`: the kernel then runs as `span_wide` (see `Isa`).
fn wide() -> bool {
    use std::sync::atomic::{AtomicU8, Ordering};
    static WIDE: AtomicU8 = AtomicU8::new(0);
    match WIDE.load(Ordering::Relaxed) {
        1 => return false,
        2 => return true,
        _ => {}
    }
    let has = std::arch::is_x86_feature_detected!("avx512f")
        && std::arch::is_x86_feature_detected!("avx512vl")
        && std::arch::is_x86_feature_detected!("avx512bw")
        && std::arch::is_x86_feature_detected!("avx512dq")
        && std::env::var("SOFTGL_SIMD").as_deref() != Ok("avx2");
    WIDE.store(1 + has as u8, Ordering::Relaxed);
    has
}

/// Pixels [a, b) of the span through the scalar kernel.
fn scalar<const D: u8, const STORE: bool>(fs: &FragmentState, t: &TriangleSetup, px: &mut SpanPixels, y: usize, x0: usize, a: usize, b: usize) {
    let mut sub = SpanPixels {
        color: &mut px.color[a..b],
        depth: if px.depth.is_empty() { &mut [] } else { &mut px.depth[a..b] },
        stencil: if px.stencil.is_empty() { &mut [] } else { &mut px.stencil[a..b] },
        other: px.other.as_deref_mut().map(|o| &mut o[a..b]),
        passed: 0,
    };
    super::kernel_avx2::<D, STORE>(fs, t, &mut sub, y, x0 + a, x0 + b);
    px.passed += sub.passed;
}

/// Two halves of f64 lanes: pixels 0-3 and 4-7.
type D8 = [__m256d; 2];
type Rgba = [__m256; 4];

// The helpers below are `inline(always)` without `target_feature`: they
// are only called from `span` (AVX2), into which they are inlined, and
// the intrinsics with them (a `target_feature` helper may stay a call).

/// The instruction set a span runs with, as its eight f64 lanes (the
/// group's pixels): two AVX2 registers (`D8`, `span`) or one AVX-512
/// register (`span_wide`), with the steps that have a wider form. Both
/// forms run the same IEEE operation on each lane (separate multiplies and
/// adds, as the scalar kernel), so they give the same bits; the wide one
/// in fewer instructions.
trait Isa: Copy {
    /// The AVX-512 form (`span_wide`).
    const WIDE: bool;
    /// `lod::log2_8`.
    unsafe fn log2(x: __m256) -> __m256;
    /// `filter_pairs`; the channels in `skip` (the level's flat ones and
    /// those the environment does not read) may be `p.flat_value`'s.
    unsafe fn filter_pairs(p: &PaddedLevel, l: &Level, s: __m256, t: __m256, rep: [bool; 2], skip: u8) -> Rgba;
    /// `filter_pairs` of two levels (`a` and `b`: level, padded level,
    /// skip), the same bits as two calls; the AVX2 form loads both
    /// levels' texels before it converts either (`filter_pairs2`).
    unsafe fn filter_pairs2(a: (&PaddedLevel, &Level, u8), b: (&PaddedLevel, &Level, u8), s: __m256, t: __m256, rep: [bool; 2]) -> (Rgba, Rgba);
    /// GL_FASTEST: `filter_fixed`.
    unsafe fn filter_fixed(p: &PaddedLevel, l: &Level, s: __m256, t: __m256, linear: bool, rep: [bool; 2]) -> __m256i;
    /// GL_FASTEST: packed RGBA8 lanes a + (b - a) w / 256 rounded (`lerp16`),
    /// w (i32 lanes) in [0, 256].
    unsafe fn lerp_packed(a: __m256i, b: __m256i, w: __m256i) -> __m256i;
    /// GL_FASTEST MODULATE: round(t c / 255) per channel of packed lanes.
    unsafe fn modulate(t: __m256i, c: __m256i) -> __m256i;
    /// The pixel centres x + 0..7 + 1/2 - x0 (`Row::at`'s argument).
    unsafe fn centres(x: f64, x0: f64) -> Self;
    /// (x + 8 j + 1/2 - x0) + 8 for j = 0..7 (`lambda_8`).
    unsafe fn strided(x: f64, x0: f64) -> Self;
    unsafe fn store(&self, out: &mut [f64; 8]);
    unsafe fn splat(v: f64) -> Self;
    /// r + dx c per lane, as `Row::at`.
    unsafe fn at(r: f64, dx: f64, c: &Self) -> Self;
    unsafe fn mul(&self, b: &Self) -> Self;
    /// 1 / v.
    unsafe fn recip(&self) -> Self;
    /// Rounded to f32 (`as f32`).
    unsafe fn to_f32(&self) -> __m256;
    /// ((d - self qd) iq) as f32: a coordinate's derivative.
    unsafe fn deriv(&self, d: f64, qd: f64, iq: &Self) -> __m256;
    /// `depth_to_fixed`: (min(max(v, 0), 1) DEPTH_MAX + 1/2) truncated
    /// (a NaN gives 0).
    unsafe fn depth(&self) -> __m256i;
    /// Every lane non-zero and finite.
    unsafe fn nonzero_finite(&self) -> bool;
}

impl Isa for D8 {
    const WIDE: bool = false;

    #[inline(always)]
    unsafe fn log2(x: __m256) -> __m256 {
        lod::log2_8(x)
    }

    #[inline(always)]
    unsafe fn filter_pairs(p: &PaddedLevel, l: &Level, s: __m256, t: __m256, rep: [bool; 2], skip: u8) -> Rgba {
        filter_pairs(p, l, s, t, rep, skip)
    }

    #[inline(always)]
    unsafe fn filter_pairs2(a: (&PaddedLevel, &Level, u8), b: (&PaddedLevel, &Level, u8), s: __m256, t: __m256, rep: [bool; 2]) -> (Rgba, Rgba) {
        filter_pairs2(a, b, s, t, rep)
    }

    #[inline(always)]
    unsafe fn filter_fixed(p: &PaddedLevel, l: &Level, s: __m256, t: __m256, linear: bool, rep: [bool; 2]) -> __m256i {
        filter_fixed(p, l, s, t, linear, rep)
    }

    #[inline(always)]
    unsafe fn lerp_packed(a: __m256i, b: __m256i, w: __m256i) -> __m256i {
        lerp_packed(a, b, w)
    }

    #[inline(always)]
    unsafe fn modulate(t: __m256i, c: __m256i) -> __m256i {
        modulate(t, c)
    }

    #[inline(always)]
    unsafe fn centres(x: f64, x0: f64) -> Self {
        let (xs, half, x0) = (_mm256_set1_pd(x), _mm256_set1_pd(0.5), _mm256_set1_pd(x0));
        [
            _mm256_sub_pd(_mm256_add_pd(_mm256_add_pd(xs, _mm256_setr_pd(0.0, 1.0, 2.0, 3.0)), half), x0),
            _mm256_sub_pd(_mm256_add_pd(_mm256_add_pd(xs, _mm256_setr_pd(4.0, 5.0, 6.0, 7.0)), half), x0),
        ]
    }

    #[inline(always)]
    unsafe fn strided(x: f64, x0: f64) -> Self {
        let (xs, half, x0, eight) = (_mm256_set1_pd(x), _mm256_set1_pd(0.5), _mm256_set1_pd(x0), _mm256_set1_pd(8.0));
        [
            _mm256_add_pd(_mm256_sub_pd(_mm256_add_pd(_mm256_add_pd(xs, _mm256_setr_pd(0.0, 8.0, 16.0, 24.0)), half), x0), eight),
            _mm256_add_pd(_mm256_sub_pd(_mm256_add_pd(_mm256_add_pd(xs, _mm256_setr_pd(32.0, 40.0, 48.0, 56.0)), half), x0), eight),
        ]
    }

    #[inline(always)]
    unsafe fn store(&self, out: &mut [f64; 8]) {
        _mm256_storeu_pd(out.as_mut_ptr(), self[0]);
        _mm256_storeu_pd(out.as_mut_ptr().add(4), self[1]);
    }

    #[inline(always)]
    unsafe fn splat(v: f64) -> Self {
        [_mm256_set1_pd(v); 2]
    }

    #[inline(always)]
    unsafe fn at(r: f64, dx: f64, c: &Self) -> Self {
        let (r, dx) = (_mm256_set1_pd(r), _mm256_set1_pd(dx));
        [_mm256_add_pd(r, _mm256_mul_pd(dx, c[0])), _mm256_add_pd(r, _mm256_mul_pd(dx, c[1]))]
    }

    #[inline(always)]
    unsafe fn mul(&self, b: &Self) -> Self {
        [_mm256_mul_pd(self[0], b[0]), _mm256_mul_pd(self[1], b[1])]
    }

    #[inline(always)]
    unsafe fn recip(&self) -> Self {
        let one = _mm256_set1_pd(1.0);
        [_mm256_div_pd(one, self[0]), _mm256_div_pd(one, self[1])]
    }

    #[inline(always)]
    unsafe fn to_f32(&self) -> __m256 {
        _mm256_set_m128(_mm256_cvtpd_ps(self[1]), _mm256_cvtpd_ps(self[0]))
    }

    #[inline(always)]
    unsafe fn deriv(&self, d: f64, qd: f64, iq: &Self) -> __m256 {
        let (d, qd) = (_mm256_set1_pd(d), _mm256_set1_pd(qd));
        let lo = _mm256_mul_pd(_mm256_sub_pd(d, _mm256_mul_pd(self[0], qd)), iq[0]);
        let hi = _mm256_mul_pd(_mm256_sub_pd(d, _mm256_mul_pd(self[1], qd)), iq[1]);
        [lo, hi].to_f32()
    }

    #[inline(always)]
    unsafe fn depth(&self) -> __m256i {
        let (zero, one, scale, half) = (_mm256_setzero_pd(), _mm256_set1_pd(1.0), _mm256_set1_pd(DEPTH_MAX as f64), _mm256_set1_pd(0.5));
        // max(v, 0): NaN gives 0, as the scalar clamp-then-cast.
        let lo = _mm256_cvttpd_epi32(_mm256_add_pd(_mm256_mul_pd(_mm256_min_pd(_mm256_max_pd(self[0], zero), one), scale), half));
        let hi = _mm256_cvttpd_epi32(_mm256_add_pd(_mm256_mul_pd(_mm256_min_pd(_mm256_max_pd(self[1], zero), one), scale), half));
        _mm256_set_m128i(hi, lo)
    }

    #[inline(always)]
    unsafe fn nonzero_finite(&self) -> bool {
        let (zero, inf, nz) = (_mm256_setzero_pd(), _mm256_set1_pd(f64::INFINITY), _mm256_set1_pd(-0.0));
        let nonzero = all_pd(_mm256_cmp_pd::<_CMP_NEQ_OQ>(self[0], zero), _mm256_cmp_pd::<_CMP_NEQ_OQ>(self[1], zero));
        let finite = all_pd(_mm256_cmp_pd::<_CMP_LT_OQ>(_mm256_andnot_pd(nz, self[0]), inf), _mm256_cmp_pd::<_CMP_LT_OQ>(_mm256_andnot_pd(nz, self[1]), inf));
        nonzero && finite
    }
}

/// The AVX-512 form: only instantiated by `span_wide` (AVX-512 F and DQ).
impl Isa for __m512d {
    const WIDE: bool = true;

    #[inline(always)]
    unsafe fn log2(x: __m256) -> __m256 {
        lod::log2_8_wide(x)
    }

    #[inline(always)]
    unsafe fn filter_pairs(p: &PaddedLevel, l: &Level, s: __m256, t: __m256, rep: [bool; 2], _skip: u8) -> Rgba {
        // All channels: a flat one filters to its value here too.
        filter_pairs_wide(p, l, s, t, rep)
    }

    #[inline(always)]
    unsafe fn filter_pairs2(a: (&PaddedLevel, &Level, u8), b: (&PaddedLevel, &Level, u8), s: __m256, t: __m256, rep: [bool; 2]) -> (Rgba, Rgba) {
        (filter_pairs_wide(a.0, a.1, s, t, rep), filter_pairs_wide(b.0, b.1, s, t, rep))
    }

    #[inline(always)]
    unsafe fn filter_fixed(p: &PaddedLevel, l: &Level, s: __m256, t: __m256, linear: bool, rep: [bool; 2]) -> __m256i {
        filter_fixed_wide(p, l, s, t, linear, rep)
    }

    #[inline(always)]
    unsafe fn lerp_packed(a: __m256i, b: __m256i, w: __m256i) -> __m256i {
        narrow_z(lerp16z(widen_z(a), widen_z(b), weights_z(w)))
    }

    #[inline(always)]
    unsafe fn modulate(t: __m256i, c: __m256i) -> __m256i {
        let x = _mm512_add_epi16(_mm512_mullo_epi16(widen_z(t), widen_z(c)), _mm512_set1_epi16(128));
        narrow_z(_mm512_srli_epi16::<8>(_mm512_add_epi16(x, _mm512_srli_epi16::<8>(x))))
    }

    #[inline(always)]
    unsafe fn centres(x: f64, x0: f64) -> Self {
        let steps = _mm512_setr_pd(0.0, 1.0, 2.0, 3.0, 4.0, 5.0, 6.0, 7.0);
        _mm512_sub_pd(_mm512_add_pd(_mm512_add_pd(_mm512_set1_pd(x), steps), _mm512_set1_pd(0.5)), _mm512_set1_pd(x0))
    }

    #[inline(always)]
    unsafe fn strided(x: f64, x0: f64) -> Self {
        let steps = _mm512_setr_pd(0.0, 8.0, 16.0, 24.0, 32.0, 40.0, 48.0, 56.0);
        _mm512_add_pd(_mm512_sub_pd(_mm512_add_pd(_mm512_add_pd(_mm512_set1_pd(x), steps), _mm512_set1_pd(0.5)), _mm512_set1_pd(x0)), _mm512_set1_pd(8.0))
    }

    #[inline(always)]
    unsafe fn store(&self, out: &mut [f64; 8]) {
        _mm512_storeu_pd(out.as_mut_ptr(), *self);
    }

    #[inline(always)]
    unsafe fn splat(v: f64) -> Self {
        _mm512_set1_pd(v)
    }

    #[inline(always)]
    unsafe fn at(r: f64, dx: f64, c: &Self) -> Self {
        _mm512_add_pd(_mm512_set1_pd(r), _mm512_mul_pd(_mm512_set1_pd(dx), *c))
    }

    #[inline(always)]
    unsafe fn mul(&self, b: &Self) -> Self {
        _mm512_mul_pd(*self, *b)
    }

    #[inline(always)]
    unsafe fn recip(&self) -> Self {
        _mm512_div_pd(_mm512_set1_pd(1.0), *self)
    }

    #[inline(always)]
    unsafe fn to_f32(&self) -> __m256 {
        _mm512_cvtpd_ps(*self)
    }

    #[inline(always)]
    unsafe fn deriv(&self, d: f64, qd: f64, iq: &Self) -> __m256 {
        _mm512_cvtpd_ps(_mm512_mul_pd(_mm512_sub_pd(_mm512_set1_pd(d), _mm512_mul_pd(*self, _mm512_set1_pd(qd))), *iq))
    }

    #[inline(always)]
    unsafe fn depth(&self) -> __m256i {
        // max(v, 0): NaN gives 0 (vmaxpd returns the second operand).
        let v = _mm512_min_pd(_mm512_max_pd(*self, _mm512_setzero_pd()), _mm512_set1_pd(1.0));
        _mm512_cvttpd_epi32(_mm512_add_pd(_mm512_mul_pd(v, _mm512_set1_pd(DEPTH_MAX as f64)), _mm512_set1_pd(0.5)))
    }

    #[inline(always)]
    unsafe fn nonzero_finite(&self) -> bool {
        let nonzero = _mm512_cmp_pd_mask::<_CMP_NEQ_OQ>(*self, _mm512_setzero_pd());
        let finite = _mm512_cmp_pd_mask::<_CMP_LT_OQ>(_mm512_andnot_pd(_mm512_set1_pd(-0.0), *self), _mm512_set1_pd(f64::INFINITY));
        nonzero & finite == 0xFF
    }
}

/// min(max(v, 0), 1): NaN gives 0 (glam's clamp and `to_u8`).
#[inline(always)]
unsafe fn clamp01(v: __m256) -> __m256 {
    _mm256_min_ps(_mm256_max_ps(v, _mm256_setzero_ps()), _mm256_set1_ps(1.0))
}

#[inline(always)]
unsafe fn lerp(a: __m256, b: __m256, t: __m256) -> __m256 {
    _mm256_add_ps(a, _mm256_mul_ps(_mm256_sub_ps(b, a), t))
}

/// c 0x010101 (i32 lanes, c a byte) to c / 255 (see the module
/// documentation): convert, exponent down by 24 and one ulp up; c = 0
/// gives a negative number there, which the max makes +0.
#[inline(always)]
unsafe fn unorm(n: __m256i) -> __m256 {
    let b = _mm256_add_epi32(_mm256_castps_si256(_mm256_cvtepi32_ps(n)), _mm256_set1_epi32(UNORM_BITS));
    _mm256_castsi256_ps(_mm256_max_epi32(b, _mm256_setzero_si256()))
}

/// The `vpshufb` control taking byte K of each 32-bit lane to bytes 0, 1,
/// 2 and zeroing byte 3: c 0x010101 from channel K.
const fn spread(k: i32) -> [i32; 4] {
    const fn w(d: i32, k: i32) -> i32 {
        ((4 * d + k) * 0x010101) | i32::MIN
    }
    [w(0, k), w(1, k), w(2, k), w(3, k)]
}
const SPREAD: [[i32; 4]; 4] = [spread(0), spread(1), spread(2), spread(3)];

/// Channel `k` of packed RGBA8 lanes as c 0x010101.
#[inline(always)]
unsafe fn spread8(v: __m256i, k: usize) -> __m256i {
    let [a, b, c, d] = SPREAD[k];
    _mm256_shuffle_epi8(v, _mm256_setr_epi32(a, b, c, d, a, b, c, d))
}

/// Eight RGBA8 texels to four channels of c / 255.
#[inline(always)]
unsafe fn channels(v: __m256i) -> Rgba {
    [unorm(spread8(v, 0)), unorm(spread8(v, 1)), unorm(spread8(v, 2)), unorm(spread8(v, 3))]
}

/// `channels` of sixteen texels (AVX-512 BW).
#[inline(always)]
unsafe fn channels16(v: __m512i) -> [__m512; 4] {
    let mut out = [_mm512_setzero_ps(); 4];
    for k in 0..4 {
        let [a, b, c, d] = SPREAD[k];
        let n = _mm512_shuffle_epi8(v, _mm512_setr_epi32(a, b, c, d, a, b, c, d, a, b, c, d, a, b, c, d));
        let bits = _mm512_add_epi32(_mm512_castps_si512(_mm512_cvtepi32_ps(n)), _mm512_set1_epi32(UNORM_BITS));
        out[k] = _mm512_castsi512_ps(_mm512_max_epi32(bits, _mm512_setzero_si512()));
    }
    out
}

/// REPEAT (power-of-two n) or CLAMP_TO_EDGE of indices into [0, n).
#[inline(always)]
unsafe fn wrap(i: __m256i, n: i32, repeat: bool) -> __m256i {
    let last = _mm256_set1_epi32(n - 1);
    if repeat {
        _mm256_and_si256(i, last)
    } else {
        _mm256_max_epi32(_mm256_min_epi32(i, last), _mm256_setzero_si256())
    }
}

#[inline(always)]
unsafe fn fetch(l: &Level, i: __m256i, j: __m256i) -> __m256i {
    let off = _mm256_add_epi32(_mm256_mullo_epi32(j, _mm256_set1_epi32(l.w)), i);
    _mm256_i32gather_epi32::<4>(l.tex.as_ptr().cast(), off)
}

/// floor(x) and floor(x) as i32 lanes (|x| < 2^23: the caller checks).
#[inline(always)]
unsafe fn floor(x: __m256) -> (__m256, __m256i) {
    let f = _mm256_round_ps::<{ _MM_FROUND_TO_NEG_INF | _MM_FROUND_NO_EXC }>(x);
    (f, _mm256_cvttps_epi32(f))
}

/// NEAREST in level `l` at (s, t): the texel as packed RGBA8 lanes.
#[inline(always)]
unsafe fn nearest(l: &Level, s: __m256, t: __m256, rep: [bool; 2]) -> __m256i {
    let (_, i) = floor(_mm256_mul_ps(s, _mm256_set1_ps(l.wf)));
    let (_, j) = floor(_mm256_mul_ps(t, _mm256_set1_ps(l.hf)));
    fetch(l, wrap(i, l.w, rep[0]), wrap(j, l.h, rep[1]))
}

/// LINEAR's footprint in level `l` at (s, t): the top-left texel's
/// indices (unwrapped) and the weights across and down.
#[inline(always)]
unsafe fn footprint(l: &Level, s: __m256, t: __m256) -> (__m256i, __m256i, __m256, __m256) {
    let half = _mm256_set1_ps(0.5);
    let a = _mm256_sub_ps(_mm256_mul_ps(s, _mm256_set1_ps(l.wf)), half);
    let b = _mm256_sub_ps(_mm256_mul_ps(t, _mm256_set1_ps(l.hf)), half);
    let ((fa, i0), (fb, j0)) = (floor(a), floor(b));
    (i0, j0, _mm256_sub_ps(a, fa), _mm256_sub_ps(b, fb))
}

/// The bilinear blend of a footprint's texels (top-left, top-right,
/// bottom-left, bottom-right, packed RGBA8 lanes): rows across by `wa`,
/// then down by `wb`, per channel.
#[inline(always)]
unsafe fn blend(texels: [__m256i; 4], wa: __m256, wb: __m256) -> Rgba {
    // Not `texels.map(..)`: a closure does not inherit `span`'s target
    // feature, so `channels` and its intrinsics would become calls (a
    // sixfold slowdown of the GL_NICEST kernel).
    let [t00, t01, t10, t11] = texels;
    let (c00, c01, c10, c11) = (channels(t00), channels(t01), channels(t10), channels(t11));
    let mut out = [_mm256_setzero_ps(); 4];
    for c in 0..4 {
        let top = lerp(c00[c], c01[c], wa);
        let bottom = lerp(c10[c], c11[c], wa);
        out[c] = lerp(top, bottom, wb);
    }
    out
}

/// Level `l` filtered at (s, t): `Level::nearest` or `Level::linear`.
#[inline(always)]
unsafe fn filter(l: &Level, s: __m256, t: __m256, linear: bool, rep: [bool; 2]) -> Rgba {
    if !linear {
        return channels(nearest(l, s, t, rep));
    }
    let (i0, j0, wa, wb) = footprint(l, s, t);
    let one = _mm256_set1_epi32(1);
    let (i0w, i1w) = (wrap(i0, l.w, rep[0]), wrap(_mm256_add_epi32(i0, one), l.w, rep[0]));
    let (j0w, j1w) = (wrap(j0, l.h, rep[1]), wrap(_mm256_add_epi32(j0, one), l.h, rep[1]));
    blend([fetch(l, i0w, j0w), fetch(l, i1w, j0w), fetch(l, i0w, j1w), fetch(l, i1w, j1w)], wa, wb)
}

/// The bilinear footprint's texels from the padded copy
/// (`texture::pairs`): for each lane the two texels of row j0 and of row
/// j0 + 1, each pair one 64-bit gather element. Returns the texels
/// (top-left, top-right, bottom-left, bottom-right) as packed RGBA8 lanes;
/// the same texels `filter` reads through its four wraps.
#[inline(always)]
unsafe fn pairs(p: &PaddedLevel, l: &Level, i0: __m256i, j0: __m256i, rep: [bool; 2]) -> [__m256i; 4] {
    let (r0, r1) = rows::<true>(p, l, i0, j0, rep);
    let ((c00, c01), (c10, c11)) = (split(r0), split(r1));
    [c00, c01, c10, c11]
}

/// The footprint's rows j0 and j0 + 1 as 64-bit elements (the texel pair
/// of each lane): lanes 0-3 then 4-7, or with `SPLIT` lanes 0, 1, 4, 5
/// then 2, 3, 6, 7 (`split`'s order).
#[inline(always)]
unsafe fn rows<const SPLIT: bool>(p: &PaddedLevel, l: &Level, i0: __m256i, j0: __m256i, rep: [bool; 2]) -> ([__m256i; 2], [__m256i; 2]) {
    let m1 = _mm256_set1_epi32(-1);
    // REPEAT: i0 mod w; CLAMP_TO_EDGE: clamp(i0, -1, w - 1) (the padding
    // holds the edge texel at -1 and w).
    let i = if rep[0] { _mm256_and_si256(i0, _mm256_set1_epi32(l.w - 1)) } else { _mm256_max_epi32(_mm256_min_epi32(i0, _mm256_set1_epi32(l.w - 1)), m1) };
    let j = if rep[1] { _mm256_and_si256(j0, _mm256_set1_epi32(l.h - 1)) } else { _mm256_max_epi32(_mm256_min_epi32(j0, _mm256_set1_epi32(l.h - 1)), m1) };
    let stride = _mm256_set1_epi32(p.stride);
    let off = _mm256_add_epi32(_mm256_mullo_epi32(_mm256_sub_epi32(j, m1), stride), _mm256_sub_epi32(i, m1));
    let off1 = _mm256_add_epi32(off, stride);
    let base = p.texels.as_ptr();
    let (r0, r1) = if SCALAR_LOADS {
        // Eight 64-bit loads per row instead of two gathers: on AMD Zen
        // gathers cost about one micro-op per element and more.
        let mut o = [0i32; 8];
        _mm256_storeu_si256(o.as_mut_ptr().cast(), off);
        // Row j0 + 1 from its own base pointer: each load is then base +
        // 4 * offset, with no address add per lane for the second row.
        let base1 = base.offset(p.stride as isize);
        // With `SPLIT` (`pairs`: the AVX2 filters and GL_FASTEST's) the
        // offsets are read back from memory (volatile: otherwise each
        // becomes an extract from the register and a sign extension, two
        // instructions where one load with sign extension does). Not for
        // `filter_pairs_wide`: its kernel ran about 3 % slower with them.
        let ld = |b: *const u32, k: usize| {
            let o = if SPLIT { std::ptr::read_volatile(&o[k]) } else { o[k] };
            (b.offset(o as isize) as *const i64).read_unaligned()
        };
        let [a, b, c, d, e, f, g, h] = if SPLIT { [0, 1, 4, 5, 2, 3, 6, 7] } else { [0, 1, 2, 3, 4, 5, 6, 7] };
        (
            [_mm256_setr_epi64x(ld(base, a), ld(base, b), ld(base, c), ld(base, d)), _mm256_setr_epi64x(ld(base, e), ld(base, f), ld(base, g), ld(base, h))],
            [_mm256_setr_epi64x(ld(base1, a), ld(base1, b), ld(base1, c), ld(base1, d)), _mm256_setr_epi64x(ld(base1, e), ld(base1, f), ld(base1, g), ld(base1, h))],
        )
    } else {
        let base = base as *const i64;
        let (off, off1) = if SPLIT {
            let order = _mm256_setr_epi32(0, 1, 4, 5, 2, 3, 6, 7);
            (_mm256_permutevar8x32_epi32(off, order), _mm256_permutevar8x32_epi32(off1, order))
        } else {
            (off, off1)
        };
        (
            [_mm256_i32gather_epi64::<4>(base, _mm256_castsi256_si128(off)), _mm256_i32gather_epi64::<4>(base, _mm256_extracti128_si256::<1>(off))],
            [_mm256_i32gather_epi64::<4>(base, _mm256_castsi256_si128(off1)), _mm256_i32gather_epi64::<4>(base, _mm256_extracti128_si256::<1>(off1))],
        )
    };
    (r0, r1)
}

/// [a0 b0 a1 b1 | a4 b4 a5 b5], [a2 b2 a3 b3 | a6 b6 a7 b7] (`rows`
/// with `SPLIT`) -> [a0 .. a7], [b0 .. b7]: one in-lane shuffle each.
#[inline(always)]
unsafe fn split(r: [__m256i; 2]) -> (__m256i, __m256i) {
    let (lo, hi) = (_mm256_castsi256_ps(r[0]), _mm256_castsi256_ps(r[1]));
    let even = _mm256_castps_si256(_mm256_shuffle_ps::<0x88>(lo, hi));
    let odd = _mm256_castps_si256(_mm256_shuffle_ps::<0xDD>(lo, hi));
    (even, odd)
}

/// `filter` for LINEAR with the padded copy: the same weights and lerps
/// (`blend`'s, channel by channel), except for the channels in `skip`,
/// which may be `p.flat_value`'s: a flat channel's value is what the
/// lerps would give (`PaddedLevel::flat`), the others there are not read.
/// Two cases are worth their own code: every channel skipped (a 1x1
/// level; no texel loaded) and alpha skipped (opaque RGBA and RGB
/// textures). The choice is made once per call, so the filter itself has
/// no branches (a branch per channel made the compiler spill around each).
#[inline(always)]
unsafe fn filter_pairs(p: &PaddedLevel, l: &Level, s: __m256, t: __m256, rep: [bool; 2], skip: u8) -> Rgba {
    if skip == 0xF {
        let v = &p.flat_value;
        return [_mm256_set1_ps(v[0]), _mm256_set1_ps(v[1]), _mm256_set1_ps(v[2]), _mm256_set1_ps(v[3])];
    }
    if skip & 0b1000 != 0 {
        filter_channels::<3>(p, l, s, t, rep)
    } else {
        filter_channels::<4>(p, l, s, t, rep)
    }
}

/// `filter_pairs` of channels 0..N; the others `p.flat_value`'s.
#[inline(always)]
unsafe fn filter_channels<const N: usize>(p: &PaddedLevel, l: &Level, s: __m256, t: __m256, rep: [bool; 2]) -> Rgba {
    let (i0, j0, wa, wb) = footprint(l, s, t);
    convert::<N>(p, pairs(p, l, i0, j0, rep), wa, wb)
}

/// `filter_pairs` of two levels with the same `skip` choice as one (the
/// union of what both compute: a flat channel computed anyway gives its
/// flat value, an unread one is not read), each level's footprint and
/// loads before either level's conversions and lerps, so the second
/// level's cache misses overlap the first's arithmetic. A level with
/// every channel skipped (no texel to load) goes through `filter_pairs`.
#[inline(always)]
unsafe fn filter_pairs2(a: (&PaddedLevel, &Level, u8), b: (&PaddedLevel, &Level, u8), s: __m256, t: __m256, rep: [bool; 2]) -> (Rgba, Rgba) {
    if a.2 == 0xF || b.2 == 0xF {
        return (filter_pairs(a.0, a.1, s, t, rep, a.2), filter_pairs(b.0, b.1, s, t, rep, b.2));
    }
    if a.2 & b.2 & 0b1000 != 0 {
        filter_channels2::<3>(a.0, a.1, b.0, b.1, s, t, rep)
    } else {
        filter_channels2::<4>(a.0, a.1, b.0, b.1, s, t, rep)
    }
}

/// `filter_channels` of two levels, both levels' texels loaded first.
#[allow(clippy::too_many_arguments)]
#[inline(always)]
unsafe fn filter_channels2<const N: usize>(pa: &PaddedLevel, la: &Level, pb: &PaddedLevel, lb: &Level, s: __m256, t: __m256, rep: [bool; 2]) -> (Rgba, Rgba) {
    let (ia, ja, wa_a, wb_a) = footprint(la, s, t);
    let (ib, jb, wa_b, wb_b) = footprint(lb, s, t);
    let ta = pairs(pa, la, ia, ja, rep);
    let tb = pairs(pb, lb, ib, jb, rep);
    (convert::<N>(pa, ta, wa_a, wb_a), convert::<N>(pb, tb, wa_b, wb_b))
}

/// A footprint's texels (`pairs`) filtered by its weights: channels 0..N
/// by `blend`'s lerps, the others `p.flat_value`'s.
#[inline(always)]
unsafe fn convert<const N: usize>(p: &PaddedLevel, texels: [__m256i; 4], wa: __m256, wb: __m256) -> Rgba {
    let [t00, t01, t10, t11] = texels;
    let mut out = [_mm256_setzero_ps(); 4];
    for c in 0..4 {
        out[c] = if c < N {
            let top = lerp(unorm(spread8(t00, c)), unorm(spread8(t01, c)), wa);
            let bottom = lerp(unorm(spread8(t10, c)), unorm(spread8(t11, c)), wa);
            lerp(top, bottom, wb)
        } else {
            _mm256_set1_ps(p.flat_value[c])
        };
    }
    out
}

/// `filter_pairs` in 16 lanes (AVX-512 F, BW, DQ): the left texels of both
/// rows [top-left | bottom-left] and the right ones [top-right |
/// bottom-right] in one register each, so their conversion and the lerp
/// across by `wa` run once for both rows; then the lerp down by `wb` in 8
/// lanes. Lane by lane the operations of `blend`.
#[inline(always)]
unsafe fn filter_pairs_wide(p: &PaddedLevel, l: &Level, s: __m256, t: __m256, rep: [bool; 2]) -> Rgba {
    let (i0, j0, wa, wb) = footprint(l, s, t);
    let (r0, r1) = rows::<false>(p, l, i0, j0, rep);
    let (r0, r1) = (_mm512_inserti64x4::<1>(_mm512_castsi256_si512(r0[0]), r0[1]), _mm512_inserti64x4::<1>(_mm512_castsi256_si512(r1[0]), r1[1]));
    // Each 64-bit element is (texel i0, texel i0 + 1): the even 32-bit
    // halves of both rows are the left texels, the odd ones the right.
    let even = _mm512_setr_epi32(0, 2, 4, 6, 8, 10, 12, 14, 16, 18, 20, 22, 24, 26, 28, 30);
    let odd = _mm512_setr_epi32(1, 3, 5, 7, 9, 11, 13, 15, 17, 19, 21, 23, 25, 27, 29, 31);
    let (left, right) = (channels16(_mm512_permutex2var_epi32(r0, even, r1)), channels16(_mm512_permutex2var_epi32(r0, odd, r1)));
    let wa2 = _mm512_insertf32x8::<1>(_mm512_castps256_ps512(wa), wa);
    let mut out = [_mm256_setzero_ps(); 4];
    for c in 0..4 {
        // [top | bottom] = left + (right - left) wa.
        let tb = _mm512_add_ps(left[c], _mm512_mul_ps(_mm512_sub_ps(right[c], left[c]), wa2));
        out[c] = lerp(_mm512_castps512_ps256(tb), _mm512_extractf32x8_ps::<1>(tb), wb);
    }
    out
}

/// 16-bit halves of packed RGBA8 lanes: pixels 0, 1, 4, 5 and 2, 3, 6, 7
/// (the unpack order within 128-bit halves).
type Half16 = [__m256i; 2];

#[inline(always)]
unsafe fn widen(v: __m256i) -> Half16 {
    let z = _mm256_setzero_si256();
    [_mm256_unpacklo_epi8(v, z), _mm256_unpackhi_epi8(v, z)]
}

#[inline(always)]
unsafe fn narrow(v: Half16) -> __m256i {
    _mm256_packus_epi16(v[0], v[1])
}

/// Per-lane weights w in [0, 256] (i32 lanes) spread over the lane's four
/// 16-bit channels, in `widen`'s order.
#[inline(always)]
unsafe fn weights16(w: __m256i) -> Half16 {
    let w2 = _mm256_or_si256(w, _mm256_slli_epi32::<16>(w));
    [_mm256_unpacklo_epi32(w2, w2), _mm256_unpackhi_epi32(w2, w2)]
}

/// (a (256 - w) + b w + 128) / 256 in 16-bit lanes (a, b <= 255,
/// w <= 256: the sum stays below 2^16).
#[inline(always)]
unsafe fn lerp16(a: Half16, b: Half16, w: Half16) -> Half16 {
    [lerp16h(a[0], b[0], w[0]), lerp16h(a[1], b[1], w[1])]
}

#[inline(always)]
unsafe fn lerp16h(a: __m256i, b: __m256i, w: __m256i) -> __m256i {
    let s = _mm256_add_epi16(_mm256_mullo_epi16(a, _mm256_sub_epi16(_mm256_set1_epi16(256), w)), _mm256_mullo_epi16(b, w));
    _mm256_srli_epi16::<8>(_mm256_add_epi16(s, _mm256_set1_epi16(128)))
}

/// `Isa::lerp_packed` in 16-bit halves.
#[inline(always)]
unsafe fn lerp_packed(a: __m256i, b: __m256i, w: __m256i) -> __m256i {
    narrow(lerp16(widen(a), widen(b), weights16(w)))
}

/// `Isa::modulate` in 16-bit halves: round(t c / 255) = (x + x / 256) /
/// 256 with x = t c + 128.
#[inline(always)]
unsafe fn modulate(t: __m256i, c: __m256i) -> __m256i {
    let (t16, c16) = (widen(t), widen(c));
    let k128 = _mm256_set1_epi16(128);
    let x = [_mm256_add_epi16(_mm256_mullo_epi16(t16[0], c16[0]), k128), _mm256_add_epi16(_mm256_mullo_epi16(t16[1], c16[1]), k128)];
    narrow([
        _mm256_srli_epi16::<8>(_mm256_add_epi16(x[0], _mm256_srli_epi16::<8>(x[0]))),
        _mm256_srli_epi16::<8>(_mm256_add_epi16(x[1], _mm256_srli_epi16::<8>(x[1]))),
    ])
}

/// The AVX-512 BW forms of the 16-bit steps: a pixel's four channels as
/// 16-bit lanes of one register (all eight pixels in one), the same
/// integer operations lane by lane as `lerp16h` and `modulate`.
#[inline(always)]
unsafe fn widen_z(v: __m256i) -> __m512i {
    _mm512_cvtepu8_epi16(v)
}

/// Lanes <= 255 back to bytes.
#[inline(always)]
unsafe fn narrow_z(v: __m512i) -> __m256i {
    _mm512_cvtepi16_epi8(v)
}

/// Per-pixel weights (i32 lanes, <= 256) on each of the pixel's four
/// 16-bit lanes.
#[inline(always)]
unsafe fn weights_z(w: __m256i) -> __m512i {
    // 16-bit lane 4p + c takes lane 2p (pixel p's low half).
    const IDX: [i16; 32] = [0, 0, 0, 0, 2, 2, 2, 2, 4, 4, 4, 4, 6, 6, 6, 6, 8, 8, 8, 8, 10, 10, 10, 10, 12, 12, 12, 12, 14, 14, 14, 14];
    _mm512_permutexvar_epi16(_mm512_loadu_si512(IDX.as_ptr().cast()), _mm512_castsi256_si512(w))
}

#[inline(always)]
unsafe fn lerp16z(a: __m512i, b: __m512i, w: __m512i) -> __m512i {
    let s = _mm512_add_epi16(_mm512_mullo_epi16(a, _mm512_sub_epi16(_mm512_set1_epi16(256), w)), _mm512_mullo_epi16(b, w));
    _mm512_srli_epi16::<8>(_mm512_add_epi16(s, _mm512_set1_epi16(128)))
}

/// `filter_fixed` with the lerps in one AVX-512 register.
#[inline(always)]
unsafe fn filter_fixed_wide(p: &PaddedLevel, l: &Level, s: __m256, t: __m256, linear: bool, rep: [bool; 2]) -> __m256i {
    if !linear {
        return nearest(l, s, t, rep);
    }
    let k128 = _mm256_set1_ps(128.0);
    let a = _mm256_cvtps_epi32(_mm256_sub_ps(_mm256_mul_ps(s, _mm256_set1_ps(l.wf * 256.0)), k128));
    let b = _mm256_cvtps_epi32(_mm256_sub_ps(_mm256_mul_ps(t, _mm256_set1_ps(l.hf * 256.0)), k128));
    let ff = _mm256_set1_epi32(0xFF);
    let (wa, wb) = (weights_z(_mm256_and_si256(a, ff)), weights_z(_mm256_and_si256(b, ff)));
    let [c00, c01, c10, c11] = pairs(p, l, _mm256_srai_epi32::<8>(a), _mm256_srai_epi32::<8>(b), rep);
    let top = lerp16z(widen_z(c00), widen_z(c01), wa);
    let bottom = lerp16z(widen_z(c10), widen_z(c11), wa);
    narrow_z(lerp16z(top, bottom, wb))
}

/// GL_FASTEST bilinear filtering (llvmpipe's way): the coordinates in
/// fixed point with 8 fraction bits, the texels lerped in 16-bit integers
/// with 8-bit weights. Packed RGBA8 lanes.
#[inline(always)]
unsafe fn filter_fixed(p: &PaddedLevel, l: &Level, s: __m256, t: __m256, linear: bool, rep: [bool; 2]) -> __m256i {
    if !linear {
        return nearest(l, s, t, rep);
    }
    // u 256 - 128 rounded to an integer: i0 its top bits, the weight its
    // low 8 (|u| < 2^22 texels: the caller checks).
    let k128 = _mm256_set1_ps(128.0);
    let a = _mm256_cvtps_epi32(_mm256_sub_ps(_mm256_mul_ps(s, _mm256_set1_ps(l.wf * 256.0)), k128));
    let b = _mm256_cvtps_epi32(_mm256_sub_ps(_mm256_mul_ps(t, _mm256_set1_ps(l.hf * 256.0)), k128));
    let ff = _mm256_set1_epi32(0xFF);
    let (wa, wb) = (weights16(_mm256_and_si256(a, ff)), weights16(_mm256_and_si256(b, ff)));
    let [c00, c01, c10, c11] = pairs(p, l, _mm256_srai_epi32::<8>(a), _mm256_srai_epi32::<8>(b), rep);
    let top = lerp16(widen(c00), widen(c01), wa);
    let bottom = lerp16(widen(c10), widen(c11), wa);
    narrow(lerp16(top, bottom, wb))
}

/// `EnvFn::apply` on channel lanes.
#[inline(always)]
unsafe fn env_apply(env: EnvFn, p: &Rgba, c: &Rgba) -> Rgba {
    let mut out = *p;
    match env {
        EnvFn::Replace { color, alpha } => {
            if color {
                out[..3].copy_from_slice(&c[..3]);
            }
            if alpha {
                out[3] = c[3];
            }
        }
        EnvFn::Modulate { color, alpha } => {
            if color {
                for k in 0..3 {
                    out[k] = _mm256_mul_ps(p[k], c[k]);
                }
            }
            if alpha {
                out[3] = _mm256_mul_ps(p[3], c[3]);
            }
        }
        EnvFn::DecalRgb => out[..3].copy_from_slice(&c[..3]),
        EnvFn::DecalRgba => {
            let ia = _mm256_sub_ps(_mm256_set1_ps(1.0), c[3]);
            for k in 0..3 {
                out[k] = _mm256_add_ps(_mm256_mul_ps(p[k], ia), _mm256_mul_ps(c[k], c[3]));
            }
        }
        EnvFn::Pass => {}
    }
    for v in out.iter_mut() {
        *v = clamp01(*v);
    }
    out
}

/// `color_to_u8` of a channel, as i32 lanes; with `CLAMP` false, of a
/// channel already through `clamp01` (which gives its own bits again:
/// never NaN, never -0, within [0, 1]), so the clamp is left out.
#[inline(always)]
unsafe fn to_byte<const CLAMP: bool>(v: __m256) -> __m256i {
    let v = if CLAMP { clamp01(v) } else { v };
    _mm256_cvttps_epi32(_mm256_add_ps(_mm256_mul_ps(v, _mm256_set1_ps(255.0)), _mm256_set1_ps(0.5)))
}

/// Level `l` filtered at (s, t) (`filter`), through the padded copy when
/// there is one and the filter is LINEAR.
#[inline(always)]
unsafe fn level_filter<L: Isa>(k: &Ctx, l: usize, s: __m256, t: __m256) -> Rgba {
    match k.pairs {
        Some(p) => {
            let p = &p.levels[l];
            L::filter_pairs(p, &k.smp.levels[l], s, t, k.smp.repeat, (p.flat | !k.reads) & 0xF)
        }
        _ => filter(&k.smp.levels[l], s, t, k.linear, k.smp.repeat),
    }
}

/// Levels `l` and `l + 1` filtered at (s, t): `level_filter` of each,
/// through `Isa::filter_pairs2` when there is a padded copy.
#[inline(always)]
unsafe fn level_filter2<L: Isa>(k: &Ctx, l: usize, s: __m256, t: __m256) -> (Rgba, Rgba) {
    match k.pairs {
        Some(p) => {
            let (pa, pb) = (&p.levels[l], &p.levels[l + 1]);
            let skip = |p: &PaddedLevel| (p.flat | !k.reads) & 0xF;
            L::filter_pairs2((pa, &k.smp.levels[l], skip(pa)), (pb, &k.smp.levels[l + 1], skip(pb)), s, t, k.smp.repeat)
        }
        _ => (level_filter::<L>(k, l, s, t), level_filter::<L>(k, l + 1, s, t)),
    }
}

/// Four channels to packed RGBA8 lanes (`color_to_u8` of each; `CLAMP`
/// as `to_byte`).
#[inline(always)]
unsafe fn pack_bytes<const CLAMP: bool>(col: &Rgba) -> __m256i {
    // Every lane of `to_byte` is within [0, 255], so the saturating packs
    // only narrow: per 128-bit half, bytes r0-r3 g0-g3 b0-b3 a0-a3, which
    // one in-lane shuffle turns into r0 g0 b0 a0 r1 ..; four instructions
    // instead of three shifts and three ors.
    let rg = _mm256_packus_epi32(to_byte::<CLAMP>(col[0]), to_byte::<CLAMP>(col[1]));
    let ba = _mm256_packus_epi32(to_byte::<CLAMP>(col[2]), to_byte::<CLAMP>(col[3]));
    let order = _mm256_setr_epi8(0, 4, 8, 12, 1, 5, 9, 13, 2, 6, 10, 14, 3, 7, 11, 15, 0, 4, 8, 12, 1, 5, 9, 13, 2, 6, 10, 14, 3, 7, 11, 15);
    _mm256_shuffle_epi8(_mm256_packus_epi16(rg, ba), order)
}

/// The rest of a group under GL_FASTEST, after the (exact) depth test:
/// s / q, t / q and the perspective-corrected primary colour per lane in
/// f32 (the planes stepped from pixel 0, one `rcp` and a Newton step for
/// 1 / q); λ computed exactly (the reference's formula) at pixel 0 and at
/// pixel 8 (the next group's pixel 0, kept for it) and linear between
/// (section 3.8.8 allows approximating ρ); texels filtered in 8-bit fixed
/// point (`filter_fixed`), two levels blended with an 8-bit weight,
/// MODULATE as round(t c / 255) in 16-bit lanes, or REPLACE. None
/// (nothing written) sends the group to the exact scalar kernel: q (or w)
/// zero, of different signs, outside [1e-30, 1e30] or not finite at the
/// ends, coordinates beyond ±2^22 texels, ρ or λ not finite.
#[allow(clippy::too_many_arguments)]
#[inline(always)]
unsafe fn fastest<const D: u8, const STORE: bool, L: Isa>(k: &Ctx, x: usize, dp: *mut u32, cp: *mut [u8; 4], m: __m256i, bits: u32, z: __m256i, stored: __m256i) -> Option<Front> {
    let smp = k.smp;
    k.pad?;
    let cx = x as f64 + 0.5 - k.x0;
    let at = |r: (f64, f64), cx: f64| r.0 + r.1 * cx;
    let (qa, qb) = (at(k.q, cx), at(k.q, cx + 8.0));
    if !(qa.is_finite() && qb.is_finite() && qa * qb > 0.0) {
        return None;
    }
    let (ia, ib) = (1.0 / qa, 1.0 / qb);
    let (sa, ta, sb, tb) = (at(k.s, cx) * ia, at(k.t, cx) * ia, at(k.s, cx + 8.0) * ib, at(k.t, cx + 8.0) * ib);
    let (n0, n1) = (smp.levels[0].wf as f64, smp.levels[0].hf as f64);
    let lim = 4194304.0;
    if !(sa.abs() * n0 < lim && sb.abs() * n0 < lim && ta.abs() * n1 < lim && tb.abs() * n1 < lim) {
        return None;
    }
    // s / q and t / q per lane in f32: S, T and Q from their values at
    // lane 0 (f64, rounded once) in steps of their slopes, 1 / Q from
    // `rcp` and one Newton step (about 2^-22 relative: a few 1/256 of a
    // texel at the largest coordinates allowed above).
    if !(qa.abs() > 1e-30 && qa.abs() < 1e30 && qb.abs() > 1e-30 && qb.abs() < 1e30) {
        return None;
    }
    let steps = _mm256_setr_ps(0.0, 1.0, 2.0, 3.0, 4.0, 5.0, 6.0, 7.0);
    let iq = recip(ramp(k.q, cx, steps));
    let (sf, tf) = (_mm256_mul_ps(ramp(k.s, cx, steps), iq), _mm256_mul_ps(ramp(k.t, cx, steps), iq));
    // The primary colour per lane (perspective-corrected as the exact
    // kernel, in f32), before anything is written.
    // Round 22: REPLACE's primary (not read) is `k.flat`'s zero, set per
    // span (`span_body`): with a three-way match per group LLVM stored
    // the zeros and copied the flat colour into the primary's slots for
    // every group before testing which case held.
    let primary: Rgba = match &k.flat {
        Some(f) => *f,
        None => {
            let w = match k.w_mode {
                W_SHARED => iq,
                W_OWN => {
                    let (wa, wb) = (at(k.w, cx), at(k.w, cx + 8.0));
                    if !(wa * wb > 0.0 && wa.abs() > 1e-30 && wa.abs() < 1e30 && wb.abs() > 1e-30 && wb.abs() < 1e30) {
                        return None;
                    }
                    recip(ramp(k.w, cx, steps))
                }
                _ => _mm256_set1_ps(1.0),
            };
            let mut p = [_mm256_setzero_ps(); 4];
            for ch in 0..4 {
                p[ch] = clamp01(_mm256_mul_ps(ramp(k.colors[ch], cx, steps), w));
            }
            p
        }
    };
    // λ exact (the reference's formula) at the group's pixel 0 and at the
    // next group's pixel 0 (kept for that group), linear between.
    let (mut la, mut frac) = (_mm256_setzero_si256(), _mm256_setzero_ps());
    if k.lod_mode != Lod::None {
        let (kept_cx, kept) = k.lambda_kept.get();
        let l0 = if kept_cx == cx { kept } else { lambda_at(k, cx)? };
        let l8 = lambda_next::<L>(k, x)?;
        k.lambda_kept.set((cx + 8.0, l8));
        let lambda = _mm256_add_ps(_mm256_set1_ps(l0), _mm256_mul_ps(_mm256_set1_ps((l8 - l0) * 0.125), steps));
        (la, frac) = levels(k, lambda);
    }
    if D != D_OFF && (D != D_ANY || k.fs.depth_write) {
        _mm256_storeu_si256(dp.cast(), _mm256_blendv_epi8(stored, z, m));
    }
    Some(Front { sf, tf, la, frac, rho: _mm256_setzero_ps(), primary, fog: _mm256_setzero_ps(), m, bits, cp })
}

/// The rest of a GL_FASTEST group after `fastest` (as `back` after
/// `front`): texels, MODULATE or REPLACE, the colours written.
#[inline(always)]
unsafe fn fastest_back<const STORE: bool, L: Isa>(k: &Ctx, g: &Front) {
    let smp = k.smp;
    let Some(pad) = k.pad else { return };
    let Front { sf, tf, la, frac, primary, m, bits, cp, .. } = *g;
    // Texels: once per distinct level among the passing lanes.
    let frac8 = _mm256_cvtps_epi32(_mm256_mul_ps(frac, _mm256_set1_ps(256.0)));
    let mut texel = _mm256_setzero_si256();
    let mut lv = [0i32; 8];
    _mm256_storeu_si256(lv.as_mut_ptr().cast(), la);
    let mut pending = bits;
    let weighted_lanes = _mm256_castps_si256(_mm256_cmp_ps::<_CMP_NEQ_UQ>(frac, _mm256_setzero_ps()));
    // Levels in rising order (`next_level`); the second level of lanes
    // straddling l and l + 1 is carried to the lanes whose first it is.
    let (mut carried, mut carry) = (usize::MAX, _mm256_setzero_si256());
    while pending != 0 {
        let l = next_level(&lv, pending) as usize;
        let same = _mm256_cmpeq_epi32(la, _mm256_set1_epi32(l as i32));
        let lanes = _mm256_movemask_ps(_mm256_castsi256_ps(same)) as u32 & pending;
        pending &= !lanes;
        let mut v = if l == carried { carry } else { L::filter_fixed(&pad.levels[l], &smp.levels[l], sf, tf, k.linear, smp.repeat) };
        let weighted = _mm256_movemask_ps(_mm256_castsi256_ps(_mm256_and_si256(weighted_lanes, same))) as u32 & lanes;
        if k.lod_mode == Lod::Linear && weighted != 0 && l < smp.q {
            let v2 = L::filter_fixed(&pad.levels[l + 1], &smp.levels[l + 1], sf, tf, k.linear, smp.repeat);
            if pending != 0 {
                (carried, carry) = (l + 1, v2);
            }
            v = L::lerp_packed(v, v2, frac8);
        }
        texel = if lanes == bits { v } else { _mm256_blendv_epi8(texel, v, same) };
    }
    let rgba = match k.env {
        EnvFn::Replace { .. } => texel,
        _ => L::modulate(texel, pack_bytes::<true>(&primary)),
    };
    write::<STORE>(k, cp, rgba, m, bits);
}

/// λ at pixel centre `cx` (relative to the triangle's x0) as the
/// reference sampler computes it; None where ρ or λ is not finite.
#[inline(always)]
fn lambda_at(k: &Ctx, cx: f64) -> Option<f32> {
    let smp = k.smp;
    let (n0, n1) = (smp.levels[0].wf, smp.levels[0].hf);
    let q = k.q.0 + k.q.1 * cx;
    let iq = 1.0 / q;
    let (s, t) = ((k.s.0 + k.s.1 * cx) * iq, (k.t.0 + k.t.1 * cx) * iq);
    let dx = [((k.s.1 - s * k.q.1) * iq) as f32 * n0, ((k.t.1 - t * k.q.1) * iq) as f32 * n1];
    let dy = [((k.dy[0] - s * k.dy[2]) * iq) as f32 * n0, ((k.dy[1] - t * k.dy[2]) * iq) as f32 * n1];
    // log2 ρ = log2(ρ²) / 2: no square roots.
    let rho2 = (dx[0] * dx[0] + dx[1] * dx[1]).max(dy[0] * dy[0] + dy[1] * dy[1]);
    if !rho2.is_finite() {
        return None;
    }
    let log2 = if rho2 >= f32::MIN_POSITIVE { log2_approx(rho2) } else { lod::log2(rho2) };
    // `clamp` (min_lod <= max_lod: `super::select` checks) written out:
    // f32::clamp stayed a call here.
    let l = 0.5 * log2 + smp.bias;
    if l.is_nan() {
        None
    } else {
        Some(l.max(smp.min_lod).min(smp.max_lod))
    }
}

/// `lambda_at(k, cx + 8.0)` for the group at window x (cx its pixel 0's
/// centre): looked up in the values `lambda_8` computed for the next eight
/// groups at once, so that λ's long dependent chain (a division, the
/// derivatives, the polynomial) runs once per eight groups on eight lanes
/// instead of once per group in scalar; the same bits.
#[inline(always)]
unsafe fn lambda_next<L: Isa>(k: &Ctx, x: usize) -> Option<f32> {
    if k.no_ahead {
        return lambda_at(k, x as f64 + 0.5 - k.x0 + 8.0);
    }
    let (base, valid, vals) = k.lambda_ahead.get();
    let (valid, vals, j) = if x >= base && (x - base).is_multiple_of(8) && (x - base) / 8 < 8 {
        (valid, vals, (x - base) / 8)
    } else {
        let (valid, vals) = lambda_8::<L>(k, x);
        k.lambda_ahead.set((x, valid, vals));
        (valid, vals, 0)
    };
    if valid & (1 << j) != 0 {
        Some(vals[j])
    } else {
        None
    }
}

/// `lambda_at(k, cx_j + 8.0)` for the groups j = 0..7 at window x + 8 j
/// (cx_j = (x + 8 j) + 1/2 - x0, as `fastest` computes it), the same
/// operations lane by lane; lanes whose ρ² is not a normal finite number
/// (NaN, 0, subnormal, infinite: where the scalar takes another branch)
/// are computed by `lambda_at` itself. Only the groups that start inside
/// the span are computed. Returns the lanes with a value and the values.
#[inline(always)]
unsafe fn lambda_8<L: Isa>(k: &Ctx, x: usize) -> (u32, [f32; 8]) {
    let smp = k.smp;
    let groups = (k.x_end.saturating_sub(x)).div_ceil(8).min(8);
    let cx = L::strided(x as f64, k.x0);
    let q = L::at(k.q.0, k.q.1, &cx);
    let iq = q.recip();
    let s = L::at(k.s.0, k.s.1, &cx).mul(&iq);
    let t = L::at(k.t.0, k.t.1, &cx).mul(&iq);
    let (n0, n1) = (_mm256_set1_ps(smp.levels[0].wf), _mm256_set1_ps(smp.levels[0].hf));
    let dx0 = _mm256_mul_ps(s.deriv(k.s.1, k.q.1, &iq), n0);
    let dx1 = _mm256_mul_ps(t.deriv(k.t.1, k.q.1, &iq), n1);
    let dy0 = _mm256_mul_ps(s.deriv(k.dy[0], k.dy[2], &iq), n0);
    let dy1 = _mm256_mul_ps(t.deriv(k.dy[1], k.dy[2], &iq), n1);
    let x2 = _mm256_add_ps(_mm256_mul_ps(dx0, dx0), _mm256_mul_ps(dx1, dx1));
    let y2 = _mm256_add_ps(_mm256_mul_ps(dy0, dy0), _mm256_mul_ps(dy1, dy1));
    // f32::max where both are numbers; other lanes go to `lambda_at`.
    let rho2 = _mm256_max_ps(x2, y2);
    let normal = _mm256_and_ps(_mm256_cmp_ps::<_CMP_GE_OQ>(rho2, _mm256_set1_ps(f32::MIN_POSITIVE)), _mm256_cmp_ps::<_CMP_LT_OQ>(rho2, _mm256_set1_ps(f32::INFINITY)));
    let numbers = _mm256_cmp_ps::<_CMP_ORD_Q>(x2, y2);
    let regular = _mm256_movemask_ps(_mm256_and_ps(normal, numbers)) as u32;
    let l = _mm256_add_ps(_mm256_mul_ps(_mm256_set1_ps(0.5), log2_approx_8(rho2)), _mm256_set1_ps(smp.bias));
    let l = _mm256_min_ps(_mm256_max_ps(l, _mm256_set1_ps(smp.min_lod)), _mm256_set1_ps(smp.max_lod));
    let mut vals = [0f32; 8];
    _mm256_storeu_ps(vals.as_mut_ptr(), l);
    let want = (1u32 << groups) - 1;
    let mut valid = regular & want;
    let mut odd = !regular & want;
    if odd != 0 {
        let mut c = [0f64; 8];
        L::store(&cx, &mut c);
        while odd != 0 {
            let j = odd.trailing_zeros() as usize;
            odd &= odd - 1;
            if let Some(v) = lambda_at(k, c[j]) {
                vals[j] = v;
                valid |= 1 << j;
            }
        }
    }
    (valid, vals)
}

/// `log2_approx` on eight lanes (positive normal finite values): the same
/// operations, so the same bits.
#[inline(always)]
unsafe fn log2_approx_8(x: __m256) -> __m256 {
    const P: [f32; 5] = LOG2_APPROX;
    let b = _mm256_castps_si256(x);
    let one = _mm256_set1_ps(1.0);
    let t = _mm256_sub_ps(_mm256_castsi256_ps(_mm256_or_si256(_mm256_and_si256(b, _mm256_set1_epi32(0x7F_FFFF)), _mm256_castps_si256(one))), one);
    let p4 = _mm256_mul_ps(t, _mm256_set1_ps(P[4]));
    let p3 = _mm256_mul_ps(t, _mm256_add_ps(_mm256_set1_ps(P[3]), p4));
    let p2 = _mm256_mul_ps(t, _mm256_add_ps(_mm256_set1_ps(P[2]), p3));
    let p1 = _mm256_mul_ps(t, _mm256_add_ps(_mm256_set1_ps(P[1]), p2));
    let p = _mm256_mul_ps(t, _mm256_add_ps(_mm256_set1_ps(P[0]), p1));
    let e = _mm256_cvtepi32_ps(_mm256_sub_epi32(_mm256_srli_epi32::<23>(b), _mm256_set1_epi32(127)));
    _mm256_add_ps(e, p)
}

/// log2 x for positive normal finite x, within 4e-5 (GL_FASTEST's λ,
/// whose fraction becomes an 8-bit weight): the exponent plus a degree-5
/// polynomial in the mantissa's fraction t (least squares for log2(1 + t)
/// on [0, 1]), no division.
#[inline(always)]
fn log2_approx(x: f32) -> f32 {
    const P: [f32; 5] = LOG2_APPROX;
    let b = x.to_bits();
    let t = f32::from_bits((b & 0x7F_FFFF) | 0x3F80_0000) - 1.0;
    let p = t * (P[0] + t * (P[1] + t * (P[2] + t * (P[3] + t * P[4]))));
    ((b >> 23) as i32 - 127) as f32 + p
}

/// `log2_approx`'s coefficients (of t, t², ..., t⁵).
const LOG2_APPROX: [f32; 5] = [1.441_825_8, -0.708_682_1, 0.415_421_95, -0.194_422_67, 0.045_885_527];

/// A plane's values at pixel centres cx + 0..7 in f32 lanes: its value
/// at cx (f64, rounded once) plus its slope times `steps`.
#[inline(always)]
unsafe fn ramp(r: (f64, f64), cx: f64, steps: __m256) -> __m256 {
    _mm256_add_ps(_mm256_set1_ps((r.0 + r.1 * cx) as f32), _mm256_mul_ps(_mm256_set1_ps(r.1 as f32), steps))
}

/// 1 / v from `rcp` and one Newton step (|v| in [1e-30, 1e30]).
#[inline(always)]
unsafe fn recip(v: __m256) -> __m256 {
    let r = _mm256_rcp_ps(v);
    _mm256_mul_ps(r, _mm256_sub_ps(_mm256_set1_ps(2.0), _mm256_mul_ps(v, r)))
}

/// The group's colours to the framebuffer, lanes `m` (`bits`) only.
#[inline(always)]
unsafe fn write<const STORE: bool>(k: &Ctx, cp: *mut [u8; 4], rgba: __m256i, m: __m256i, bits: u32) {
    if STORE {
        let afix = _mm256_set1_epi32(((k.fs.alpha_fix as u32) << 24) as i32);
        let new = _mm256_or_si256(rgba, afix);
        // All eight lanes written: no read of the old colours (a cache
        // miss the group would wait for in large windows).
        let out = if bits == 0xFF { new } else { _mm256_blendv_epi8(_mm256_loadu_si256(cp.cast()), new, m) };
        _mm256_storeu_si256(cp.cast(), out);
    } else {
        let mut src = [[0u8; 4]; 8];
        _mm256_storeu_si256(src.as_mut_ptr().cast(), rgba);
        for l in 0..8 {
            if bits & (1 << l) != 0 {
                write_color(k.fs, &mut *cp.add(l), src[l]);
            }
        }
    }
}

/// Each lane's level (the first of two for MIPMAP_LINEAR) and the weight
/// of the second level from λ lanes (`Sampler::sample`'s choice).
#[inline(always)]
unsafe fn levels(k: &Ctx, lambda: __m256) -> (__m256i, __m256) {
    let qf = k.splat.q;
    let (mut la, mut frac) = (_mm256_setzero_si256(), _mm256_setzero_ps());
    match k.lod_mode {
        Lod::Linear => {
            let minify = _mm256_cmp_ps::<_CMP_GT_OQ>(lambda, _mm256_setzero_ps());
            let d1 = _mm256_round_ps::<{ _MM_FROUND_TO_NEG_INF | _MM_FROUND_NO_EXC }>(lambda);
            let top = _mm256_cmp_ps::<_CMP_GE_OQ>(d1, qf);
            let two = _mm256_andnot_ps(top, minify);
            // Levels d1 and d1 + 1 by λ - d1; the last level alone
            // (d1 >= q); level 0 alone when magnified (weight 0:
            // t1 + (t2 - t1) 0 is t1).
            let lf = _mm256_or_ps(_mm256_and_ps(two, d1), _mm256_and_ps(_mm256_and_ps(top, minify), qf));
            la = _mm256_cvttps_epi32(lf);
            frac = _mm256_and_ps(two, _mm256_sub_ps(lambda, d1));
        }
        Lod::Nearest { c: cs } => {
            let minify = _mm256_cmp_ps::<_CMP_GT_OQ>(lambda, _mm256_set1_ps(cs));
            let above = _mm256_and_ps(minify, _mm256_cmp_ps::<_CMP_GT_OQ>(lambda, _mm256_set1_ps(0.5)));
            let up = _mm256_round_ps::<{ _MM_FROUND_TO_POS_INF | _MM_FROUND_NO_EXC }>(_mm256_add_ps(lambda, _mm256_set1_ps(0.5)));
            let d = _mm256_min_ps(_mm256_sub_ps(up, _mm256_set1_ps(1.0)), qf);
            la = _mm256_cvttps_epi32(_mm256_and_ps(above, d));
        }
        Lod::None => {}
    }
    (la, frac)
}

/// The next level to filter among the lanes `pending` (not empty): the
/// lower of the first and the last pending lane's, so that a group whose
/// levels rise or fall along the span takes them in rising order and
/// level l + 1, filtered as the second level of l's lanes, is carried to
/// the lanes whose first level it is.
#[inline(always)]
fn next_level(levels: &[i32; 8], pending: u32) -> i32 {
    levels[pending.trailing_zeros() as usize].min(levels[31 - pending.leading_zeros() as usize])
}

/// Lanes all true in both halves of an f64 compare.
#[inline(always)]
unsafe fn all_pd(a: __m256d, b: __m256d) -> bool {
    _mm256_movemask_pd(a) & _mm256_movemask_pd(b) == 0xF
}

/// Sampler constants as vectors, made once per span: per group they
/// were converted (q, a usize, to f32 in six instructions) or broadcast
/// from the sampler again; from here they are memory operands.
struct Splats {
    /// The last level, as f32 (`levels`).
    q: __m256,
    bias: __m256,
    min_lod: __m256,
    max_lod: __m256,
    /// Level 0's width and height (`front`).
    n0: __m256,
    n1: __m256,
}

/// A span's constants.
struct Ctx<'a> {
    splat: Splats,
    fs: &'a FragmentState,
    smp: &'a Sampler<'a>,
    /// The padded copy of the levels (`texture::pairs`); always there for
    /// the GL_FASTEST kernel.
    pad: Option<&'a Padded>,
    /// `pad` when the filter is LINEAR (`level_filter`; round 22: one
    /// test per level filtered instead of two).
    pairs: Option<&'a Padded>,
    lod_mode: Lod,
    linear: bool,
    env: EnvFn,
    /// The texture channels `env` reads (bit k: channel k).
    reads: u8,
    x0: f64,
    s: (f64, f64),
    t: (f64, f64),
    q: (f64, f64),
    /// dS/dy, dT/dy, dQ/dy.
    dy: [f64; 3],
    z: (f64, f64),
    w: (f64, f64),
    /// Colour and fog take 1/w from q (same plane) / from their own plane / none.
    w_mode: u8,
    colors: [(f64, f64); 4],
    /// For each colour channel the first channel with the same row (the
    /// same bits of its value and slope), itself if none: white or grey
    /// vertices compute one channel for several (`same_rows`).
    color_src: [u8; 4],
    flat: Option<Rgba>,
    fog: Option<((f64, f64), Fog)>,
    /// GL_FASTEST: λ at a pixel centre (cx, λ), computed for the previous
    /// group's end and reused as the next group's start.
    lambda_kept: std::cell::Cell<(f64, f32)>,
    /// GL_FASTEST: λ at pixel 8 of the groups at x, x + 8, ..., x + 56
    /// (`lambda_next`): (x, lanes that hold `lambda_at`'s value, λ).
    lambda_ahead: std::cell::Cell<(usize, u32, [f32; 8])>,
    /// The span's end (window x, exclusive).
    x_end: usize,
    /// Tests: λ per group, not ahead (`lambda_ahead_on_this_thread`).
    no_ahead: bool,
}

/// `Ctx::color_src` of four rows: the first index whose row has the
/// same bits (equal bits give equal results lane by lane).
fn same_rows(rows: &[(f64, f64); 4]) -> [u8; 4] {
    let bits = rows.map(|(a, d)| (a.to_bits(), d.to_bits()));
    std::array::from_fn(|c| {
        // Stops at c itself at the latest.
        let mut e = 0;
        while bits[e] != bits[c] {
            e += 1;
        }
        e as u8
    })
}

/// `Ctx::reads`: the texture channels an environment reads.
fn reads(env: EnvFn) -> u8 {
    match env {
        EnvFn::Replace { color, alpha } | EnvFn::Modulate { color, alpha } => (if color { 0b0111 } else { 0 }) | (if alpha { 0b1000 } else { 0 }),
        EnvFn::DecalRgb => 0b0111,
        EnvFn::DecalRgba => 0b1111,
        EnvFn::Pass => 0,
    }
}

const W_NONE: u8 = 0;
const W_SHARED: u8 = 1;
const W_OWN: u8 = 2;

/// Eight pixels from x (pixel 0's window x), depth and colour at `dp`
/// and `cp`, lanes `live` only: the number that passed the depth test, or
/// None (nothing written) when a lane needs the scalar kernel.
#[inline(always)]
unsafe fn group<const D: u8, const STORE: bool, const FX: bool, const FOG: bool, L: Isa>(k: &Ctx, x: usize, dp: *mut u32, cp: *mut [u8; 4], live: __m256i) -> Option<u32> {
    match front::<D, STORE, FX, FOG, L>(k, x, x as f64, dp, cp, live) {
        Step::Done(n) => Some(n),
        Step::Scalar => None,
        Step::Texture(mut f) => {
            settle::<FX, L>(k, &mut f);
            back::<STORE, FX, FOG, L>(k, &f);
            Some(f.bits.count_ones())
        }
    }
}

/// A group between `front` and `back`: its texture coordinates, levels
/// and weights, primary colour and fog factor, and which lanes to write.
#[derive(Clone, Copy)]
struct Front {
    sf: __m256,
    tf: __m256,
    la: __m256i,
    frac: __m256,
    /// ρ, from which `settle` computes `la` and `frac` (mipmapped
    /// samplers, not GL_FASTEST).
    rho: __m256,
    primary: Rgba,
    fog: __m256,
    m: __m256i,
    bits: u32,
    cp: *mut [u8; 4],
}

enum Step {
    /// Nothing to write (no lane passed the depth test).
    Done(u32),
    /// Nothing written: the scalar kernel takes the group.
    Scalar,
    /// Depth tested and written; `back` textures and writes the colours
    /// (`fastest_back` under GL_FASTEST).
    Texture(Front),
}

/// A group up to its texturing: the depth test and write, s / q and t / q,
/// ρ, the primary colour and the fog factor (all of `group` that does not
/// read texels but λ and the levels, which `settle` computes from ρ). The
/// span loop runs the next group's `front`, then this group's `back`, then
/// the next group's `settle` (pixels of different groups are disjoint), so
/// that each half of the long dependent chain (q, 1 / q, the derivatives,
/// the square root of ρ; then log2, the levels) has a group's independent
/// work after it in program order instead of filling the reorder buffer
/// behind it (docs/perf-notes.md, round 19).
#[inline(always)]
unsafe fn front<const D: u8, const STORE: bool, const FX: bool, const FOG: bool, L: Isa>(k: &Ctx, x: usize, xf: f64, dp: *mut u32, cp: *mut [u8; 4], live: __m256i) -> Step {
    // `xf` is x as f64 (exact), carried by the span loop: without
    // AVX-512 a usize takes seven instructions to convert.
    let c = L::centres(xf, k.x0);
    // Depth (section 4.1.6): depth_to_fixed lane by lane.
    let mut m = live;
    let (mut z, mut stored) = (_mm256_setzero_si256(), _mm256_setzero_si256());
    if D != D_OFF {
        z = L::at(k.z.0, k.z.1, &c).depth();
        stored = _mm256_loadu_si256(dp.cast());
        let sign = _mm256_set1_epi32(i32::MIN);
        let pass = match D {
            D_LESS => _mm256_cmpgt_epi32(_mm256_xor_si256(stored, sign), _mm256_xor_si256(z, sign)),
            D_LEQUAL => _mm256_xor_si256(_mm256_cmpgt_epi32(_mm256_xor_si256(z, sign), _mm256_xor_si256(stored, sign)), _mm256_set1_epi32(-1)),
            _ => {
                let (mut zs, mut ss) = ([0u32; 8], [0u32; 8]);
                _mm256_storeu_si256(zs.as_mut_ptr().cast(), z);
                _mm256_storeu_si256(ss.as_mut_ptr().cast(), stored);
                let mut r = [0i32; 8];
                for l in 0..8 {
                    r[l] = -(k.fs.depth_func.test(zs[l], ss[l]) as i32);
                }
                _mm256_loadu_si256(r.as_ptr().cast())
            }
        };
        m = _mm256_and_si256(m, pass);
    }
    let bits = _mm256_movemask_ps(_mm256_castsi256_ps(m)) as u32;
    if bits == 0 {
        return Step::Done(0);
    }
    if FX {
        return match fastest::<D, STORE, L>(k, x, dp, cp, m, bits, z, stored) {
            Some(f) => Step::Texture(f),
            None => Step::Scalar,
        };
    }
    // Texture coordinates (reference::textured_color): s / q, t / q.
    let q = L::at(k.q.0, k.q.1, &c);
    if !q.nonzero_finite() {
        return Step::Scalar;
    }
    let iq = q.recip();
    let s = L::at(k.s.0, k.s.1, &c).mul(&iq);
    let tt = L::at(k.t.0, k.t.1, &c).mul(&iq);
    let (sf, tf) = (s.to_f32(), tt.to_f32());
    let (n0, n1) = (k.splat.n0, k.splat.n1);
    // Finite and within ±2^22 texels of level 0 (exact floors and
    // indices at every level).
    let (sign, limit) = (_mm256_set1_ps(-0.0), _mm256_set1_ps(4194304.0));
    let in_range = _mm256_and_ps(
        _mm256_cmp_ps::<_CMP_LT_OQ>(_mm256_mul_ps(_mm256_andnot_ps(sign, sf), n0), limit),
        _mm256_cmp_ps::<_CMP_LT_OQ>(_mm256_mul_ps(_mm256_andnot_ps(sign, tf), n1), limit),
    );
    if _mm256_movemask_ps(in_range) != 0xFF {
        return Step::Scalar;
    }
    // Level of detail (3.8.8): ρ here, λ and each lane's level and
    // weight in `settle`.
    let (la, frac, mut rho_out) = (_mm256_setzero_si256(), _mm256_setzero_ps(), _mm256_setzero_ps());
    if k.lod_mode != Lod::None {
        let dx0 = _mm256_mul_ps(s.deriv(k.s.1, k.q.1, &iq), n0);
        let dx1 = _mm256_mul_ps(tt.deriv(k.t.1, k.q.1, &iq), n1);
        let dy0 = _mm256_mul_ps(s.deriv(k.dy[0], k.dy[2], &iq), n0);
        let dy1 = _mm256_mul_ps(tt.deriv(k.dy[1], k.dy[2], &iq), n1);
        // ρ = max(√x2, √y2) (the reference's) as √max(x2, y2): the
        // square root is monotonic and correctly rounded, so the same
        // bits with one root. NaN: f32::max takes ly for a NaN lx, as
        // maxps takes y2 for a NaN x2; a NaN y2 gives NaN, which fails
        // below (the scalar kernel then runs), as before.
        let x2 = _mm256_add_ps(_mm256_mul_ps(dx0, dx0), _mm256_mul_ps(dx1, dx1));
        let y2 = _mm256_add_ps(_mm256_mul_ps(dy0, dy0), _mm256_mul_ps(dy1, dy1));
        let rho = _mm256_sqrt_ps(_mm256_max_ps(x2, y2));
        let normal = _mm256_and_ps(_mm256_cmp_ps::<_CMP_GE_OQ>(rho, _mm256_set1_ps(f32::MIN_POSITIVE)), _mm256_cmp_ps::<_CMP_LT_OQ>(rho, _mm256_set1_ps(f32::INFINITY)));
        let regular = _mm256_or_ps(normal, _mm256_cmp_ps::<_CMP_EQ_OQ>(rho, _mm256_setzero_ps()));
        if _mm256_movemask_ps(regular) != 0xFF {
            return Step::Scalar;
        }
        // λ and the levels: `settle`, after the previous group's `back`.
        rho_out = rho;
    }
    if D != D_OFF && (D != D_ANY || k.fs.depth_write) {
        _mm256_storeu_si256(dp.cast(), _mm256_blendv_epi8(stored, z, m));
    }
    // The primary colour, perspective-corrected by 1/w.
    let w = match k.w_mode {
        W_SHARED => iq,
        W_OWN => L::at(k.w.0, k.w.1, &c).recip(),
        _ => L::splat(1.0),
    };
    let primary: Rgba = match &k.flat {
        Some(f) => *f,
        None => {
            let mut p = [_mm256_setzero_ps(); 4];
            for ch in 0..4 {
                // A channel whose row is an earlier one's has its bits.
                let from = k.color_src[ch] as usize;
                if from < ch {
                    p[ch] = p[from];
                    continue;
                }
                let v = L::at(k.colors[ch].0, k.colors[ch].1, &c);
                let v = if k.w_mode == W_NONE { v } else { v.mul(&w) };
                p[ch] = clamp01(v.to_f32());
            }
            p
        }
    };
    let fog = match &k.fog {
        Some(((fr, fdx), f)) if FOG => {
            let v = L::at(*fr, *fdx, &c);
            let v = if k.w_mode == W_NONE { v } else { v.mul(&w) }.to_f32();
            let mut vals = [0f32; 8];
            _mm256_storeu_ps(vals.as_mut_ptr(), v);
            for v in vals.iter_mut() {
                *v = if f.per_fragment { f.factor(*v) } else { v.clamp(0.0, 1.0) };
            }
            _mm256_loadu_ps(vals.as_ptr())
        }
        _ => _mm256_setzero_ps(),
    };
    Step::Texture(Front { sf, tf, la, frac, rho: rho_out, primary, fog, m, bits, cp })
}

/// λ (log2 ρ + bias, clamped) and each lane's level and weight of a
/// group from `front` (mipmapped samplers; GL_FASTEST's `fastest` sets
/// them itself). Apart from `front` so that the span loop can run the
/// previous group's `back` between the square root of ρ and log2: the
/// same operations on the same values.
#[inline(always)]
unsafe fn settle<const FX: bool, L: Isa>(k: &Ctx, g: &mut Front) {
    if FX || k.lod_mode == Lod::None {
        return;
    }
    let sp = &k.splat;
    let lambda = _mm256_min_ps(_mm256_max_ps(_mm256_add_ps(L::log2(g.rho), sp.bias), sp.min_lod), sp.max_lod);
    (g.la, g.frac) = levels(k, lambda);
}

/// The rest of a group after `front` and `settle`: its texels, the
/// environment, fog, and the colours written.
#[inline(always)]
unsafe fn back<const STORE: bool, const FX: bool, const FOG: bool, L: Isa>(k: &Ctx, g: &Front) {
    if FX {
        return fastest_back::<STORE, L>(k, g);
    }
    let smp = k.smp;
    let Front { sf, tf, la, frac, primary, fog: fv, m, bits, cp, .. } = *g;
    let rgba = {
        // Texels: once per distinct level among the passing lanes.
        let mut texel = [_mm256_setzero_ps(); 4];
        let mut levels = [0i32; 8];
        _mm256_storeu_si256(levels.as_mut_ptr().cast(), la);
        let mut pending = bits;
        let weighted_lanes = _mm256_castps_si256(_mm256_cmp_ps::<_CMP_NEQ_UQ>(frac, _mm256_setzero_ps()));
        // Levels in rising order (`next_level`); the second level of
        // lanes straddling l and l + 1 is carried to the lanes whose
        // first it is (a filter depends only on the level and (s, t)).
        let (mut carried, mut carry) = (-1, [_mm256_setzero_ps(); 4]);
        while pending != 0 {
            let l = next_level(&levels, pending);
            let same = _mm256_cmpeq_epi32(la, _mm256_set1_epi32(l));
            let lanes = _mm256_movemask_ps(_mm256_castsi256_ps(same)) as u32 & pending;
            pending &= !lanes;
            let weighted = _mm256_movemask_ps(_mm256_castsi256_ps(_mm256_and_si256(weighted_lanes, same))) as u32 & lanes;
            let two = k.lod_mode == Lod::Linear && weighted != 0 && (l as usize) < smp.q;
            // Both levels at once (`level_filter2`) unless the first is
            // carried from the lanes below.
            let (mut v, v2) = if l == carried {
                (carry, if two { level_filter::<L>(k, l as usize + 1, sf, tf) } else { carry })
            } else if two {
                level_filter2::<L>(k, l as usize, sf, tf)
            } else {
                let v = level_filter::<L>(k, l as usize, sf, tf);
                (v, v)
            };
            if two {
                if pending != 0 {
                    (carried, carry) = (l + 1, v2);
                }
                for ch in 0..4 {
                    v[ch] = lerp(v[ch], v2[ch], frac);
                }
            }
            if lanes == bits {
                texel = v;
            } else {
                let sel = _mm256_castsi256_ps(same);
                for ch in 0..4 {
                    texel[ch] = _mm256_blendv_ps(texel[ch], v[ch], sel);
                }
            }
        }
        let mut col = env_apply(k.env, &primary, &texel);
        if let (true, Some((_, f))) = (FOG, &k.fog) {
            let inv = _mm256_sub_ps(_mm256_set1_ps(1.0), fv);
            let fc = f.color.to_array();
            for ch in 0..3 {
                col[ch] = _mm256_add_ps(_mm256_mul_ps(col[ch], fv), _mm256_mul_ps(_mm256_set1_ps(fc[ch]), inv));
            }
        }
        // To bytes (`color_to_u8`), packed RGBA; without fog every channel
        // is as `env_apply` clamped it, and a second clamp changes no bit.
        if FOG {
            pack_bytes::<true>(&col)
        } else {
            pack_bytes::<false>(&col)
        }
    };
    write::<STORE>(k, cp, rgba, m, bits);
}

#[inline]
#[target_feature(enable = "avx2,fma,popcnt")]
unsafe fn span<const D: u8, const STORE: bool, const FX: bool>(fs: &FragmentState, t: &TriangleSetup, px: &mut SpanPixels, y: usize, x0: usize, x1: usize) {
    span_body::<D, STORE, FX, D8>(fs, t, px, y, x0, x1)
}

/// `span` with AVX-512 (see `wide`).
#[inline]
#[target_feature(enable = "avx2,fma,popcnt,avx512f,avx512vl,avx512bw,avx512dq")]
unsafe fn span_wide<const D: u8, const STORE: bool, const FX: bool>(fs: &FragmentState, t: &TriangleSetup, px: &mut SpanPixels, y: usize, x0: usize, x1: usize) {
    span_body::<D, STORE, FX, __m512d>(fs, t, px, y, x0, x1)
}

/// The span loop, inlined into `span` and `span_wide` (`L`: the f64
/// lanes of each).
#[inline(always)]
unsafe fn span_body<const D: u8, const STORE: bool, const FX: bool, L: Isa>(fs: &FragmentState, t: &TriangleSetup, px: &mut SpanPixels, y: usize, x0: usize, x1: usize) {
    if x1 < x0 + 8 {
        return super::kernel_avx2::<D, STORE>(fs, t, px, y, x0, x1);
    }
    let Some(tp) = t.tex.as_ref() else { return super::kernel_avx2::<D, STORE>(fs, t, px, y, x0, x1) };
    let Some((u, sampler)) = super::unit(tp) else { return super::kernel_avx2::<D, STORE>(fs, t, px, y, x0, x1) };
    let smp = Sampler::new(sampler);
    let Some((lod_mode, linear)) = plan(&smp) else { return super::kernel_avx2::<D, STORE>(fs, t, px, y, x0, x1) };
    let cy = y as f64 + 0.5 - t.y0;
    let row = |p: &crate::render::setup::Plane| (p.a0 + p.dy * cy, p.dx);
    let p = &tp.planes[u];
    let pad = if linear || FX { sampler.padded() } else { None };
    let env = EnvFn::new(tp.stage.envs[u].mode, sampler.base);
    let colors = std::array::from_fn(|c| row(&t.color[c]));
    let k = Ctx {
        splat: Splats {
            q: _mm256_set1_ps(smp.q as f32),
            bias: _mm256_set1_ps(smp.bias),
            min_lod: _mm256_set1_ps(smp.min_lod),
            max_lod: _mm256_set1_ps(smp.max_lod),
            n0: _mm256_set1_ps(smp.levels[0].wf),
            n1: _mm256_set1_ps(smp.levels[0].hf),
        },
        fs,
        smp: &smp,
        pad,
        pairs: if linear { pad } else { None },
        lod_mode,
        linear,
        env,
        reads: reads(env),
        x0: t.x0,
        s: row(&p[0]),
        t: row(&p[1]),
        q: row(&p[3]),
        dy: [p[0].dy, p[1].dy, p[3].dy],
        z: row(&t.z),
        w: row(&t.q),
        w_mode: if !t.perspective {
            W_NONE
        } else if same_plane(&t.q, &p[3]) {
            W_SHARED
        } else {
            W_OWN
        },
        color_src: same_rows(&colors),
        colors,
        // GL_FASTEST under REPLACE: zero, a constant primary colour for
        // `fastest` (which REPLACE does not read).
        flat: if FX && matches!(env, EnvFn::Replace { .. }) { Some([_mm256_setzero_ps(); 4]) } else { t.flat.map(|c| c.map(|v| _mm256_set1_ps(v as f32 / 255.0))) },
        fog: t.fog.as_ref().map(|(plane, f)| (row(plane), *f)),
        lambda_kept: std::cell::Cell::new((f64::NAN, 0.0)),
        lambda_ahead: std::cell::Cell::new((usize::MAX, 0, [0.0; 8])),
        x_end: x1,
        no_ahead: FX && NO_AHEAD_HERE.with(|c| c.get()),
    };
    if FX && !(pad.is_some() && k.fog.is_none() && matches!(k.env, EnvFn::Modulate { color: true, .. } | EnvFn::Replace { color: true, alpha: true })) {
        return if L::WIDE { span_wide::<D, STORE, false>(fs, t, px, y, x0, x1) } else { span::<D, STORE, false>(fs, t, px, y, x0, x1) };
    }
    // Round 22: fog as a const (`FOG`), so that a span without fog does no
    // fog work per group: with the flag read per group, LLVM computed the
    // fog blend's (1 - f) c products at the loop head for every group,
    // fog or not (7 instructions and 3 stores). GL_FASTEST (`FX`) never
    // has fog here (above).
    if !FX && k.fog.is_some() {
        run::<D, STORE, FX, true, L>(&k, fs, t, px, y, x0, x1)
    } else {
        run::<D, STORE, FX, false, L>(&k, fs, t, px, y, x0, x1)
    }
}

/// The groups of a span (`span_body`); `FOG`: `k.fog` is there.
#[allow(clippy::too_many_arguments)]
#[inline(always)]
unsafe fn run<const D: u8, const STORE: bool, const FX: bool, const FOG: bool, L: Isa>(k: &Ctx, fs: &FragmentState, t: &TriangleSetup, px: &mut SpanPixels, y: usize, x0: usize, x1: usize) {
    let n = x1 - x0;
    // A group's `back` runs after the next group's `front`, and before
    // that group's `settle` (`front`); the pending group is the one whose
    // `back` is due (settled). It is done before the span's slices are
    // touched any other way (the scalar kernel, the last pixels), and the
    // raw pointers are taken anew after.
    let mut w = Walk { i: 0, xf: x0 as f64, passed: 0, cbase: px.color.as_mut_ptr(), dbase: if D != D_OFF { px.depth.as_mut_ptr() } else { std::ptr::null_mut() } };
    // Round 22: two steps an iteration, the pending group in `waiting`,
    // then in `next`, then in `waiting` again. With one step an iteration
    // the new group and the pending one were both live across the
    // pending one's `back`, so the loop's back edge copied the new
    // group's spilled state into the pending group's slots (eight ymm
    // loads and stores a group); here the group from the second step
    // takes `waiting`'s slot after `waiting` is done with.
    let mut waiting: Option<Front> = None;
    loop {
        let Some(f) = advance::<D, STORE, FX, FOG, L>(k, fs, t, px, y, x0, n, &mut w, &mut waiting) else { break };
        let mut next = Some(f);
        let Some(f) = advance::<D, STORE, FX, FOG, L>(k, fs, t, px, y, x0, n, &mut w, &mut next) else {
            waiting = next;
            break;
        };
        waiting = Some(f);
    }
    if let Some(g) = waiting.take() {
        back::<STORE, FX, FOG, L>(k, &g);
    }
    let i = w.i;
    if i < n {
        // The last pixels: on a stack copy, the missing lanes off.
        let len = n - i;
        let (mut zb, mut cb) = ([0u32; 8], [[0u8; 4]; 8]);
        if D != D_OFF {
            zb[..len].copy_from_slice(&px.depth[i..n]);
        }
        cb[..len].copy_from_slice(&px.color[i..n]);
        let live = _mm256_cmpgt_epi32(_mm256_set1_epi32(len as i32), _mm256_setr_epi32(0, 1, 2, 3, 4, 5, 6, 7));
        match group::<D, STORE, FX, FOG, L>(k, x0 + i, zb.as_mut_ptr(), cb.as_mut_ptr(), live) {
            Some(p) => {
                if D != D_OFF {
                    px.depth[i..n].copy_from_slice(&zb[..len]);
                }
                px.color[i..n].copy_from_slice(&cb[..len]);
                w.passed += p as u64;
            }
            None => scalar::<D, STORE>(fs, t, px, y, x0, i, n),
        }
    }
    px.passed += w.passed;
}

/// The span loop's position: the next group's pixel index `i` and its
/// window x as f64 `xf` (`front`; exact, the sum of integers far below
/// 2^53), the pixels passed so far, and the span's colour and depth
/// pointers.
struct Walk {
    i: usize,
    xf: f64,
    passed: u64,
    cbase: *mut [u8; 4],
    dbase: *mut u32,
}

/// Full groups of eight from `w.i` up to the next one to texture: its
/// `front` done, then `pending`'s `back` (taken), then its `settle`;
/// None when fewer than eight pixels are left (`pending` then as it
/// was, or taken by a group the scalar kernel ran).
#[allow(clippy::too_many_arguments)]
#[inline(always)]
unsafe fn advance<const D: u8, const STORE: bool, const FX: bool, const FOG: bool, L: Isa>(k: &Ctx, fs: &FragmentState, t: &TriangleSetup, px: &mut SpanPixels, y: usize, x0: usize, n: usize, w: &mut Walk, pending: &mut Option<Front>) -> Option<Front> {
    let all = _mm256_set1_epi32(-1);
    while n - w.i >= 8 {
        let i = w.i;
        let dp = if D != D_OFF { w.dbase.add(i) } else { std::ptr::null_mut() };
        // GL_FASTEST converts x itself: the carried xf cost it more
        // than it saved (measured).
        let xg = if FX { (x0 + i) as f64 } else { w.xf };
        let step = front::<D, STORE, FX, FOG, L>(k, x0 + i, xg, dp, w.cbase.add(i), all);
        w.i += 8;
        w.xf += 8.0;
        match step {
            Step::Done(p) => w.passed += p as u64,
            Step::Texture(mut f) => {
                w.passed += f.bits.count_ones() as u64;
                // The previous group's `back` between this group's ρ
                // and its λ (`settle`): both chains then have a
                // group's independent work after them.
                if let Some(g) = pending.take() {
                    back::<STORE, FX, FOG, L>(k, &g);
                }
                settle::<FX, L>(k, &mut f);
                return Some(f);
            }
            Step::Scalar => {
                if let Some(g) = pending.take() {
                    back::<STORE, FX, FOG, L>(k, &g);
                }
                scalar::<D, STORE>(fs, t, px, y, x0, i, i + 8);
                (w.cbase, w.dbase) = (px.color.as_mut_ptr(), if D != D_OFF { px.depth.as_mut_ptr() } else { std::ptr::null_mut() });
            }
        }
    }
    None
}

#[cfg(test)]
mod tests {
    use super::*;

    /// `same_rows` maps a channel to the first with the same value and
    /// slope bits, and only then: a row equal in value but not in slope
    /// (or 0.0 against -0.0) keeps its own.
    #[test]
    fn same_rows_match_bits() {
        let (a, b) = ((0.5, 0.25), (0.5, 0.125));
        assert_eq!(same_rows(&[a, b, a, b]), [0, 1, 0, 1]);
        assert_eq!(same_rows(&[a, a, a, a]), [0, 0, 0, 0]);
        assert_eq!(same_rows(&[a, b, (0.0, 0.25), (-0.0, 0.25)]), [0, 1, 2, 3]);
        assert_eq!(same_rows(&[(0.5, 0.25), (0.75, 0.25), (1.0, 0.5), (1.0, 0.5)]), [0, 1, 2, 2]);
    }

    /// `filter_pairs` (texels from `rows` in `split`'s order, the
    /// channels in `skip` as the level's flat values) gives `filter`'s
    /// bits (four wraps and gathers from the plain level) in every channel
    /// it computes or that is flat, whatever the wrap modes, at levels
    /// with no, some and all channels flat; `PaddedLevel::flat` finds them.
    #[test]
    fn filter_pairs_matches_filter() {
        if !(std::arch::is_x86_feature_detected!("avx2") && std::arch::is_x86_feature_detected!("fma")) {
            return;
        }
        use crate::render::texture::{pairs, Base, Image, Texels};
        use std::sync::Arc;
        let mut seed = 0x9E37_79B9u32;
        let mut rnd = move || {
            seed = seed.wrapping_mul(1_664_525).wrapping_add(1_013_904_223);
            seed >> 8
        };
        for (w, h) in [(8, 8), (16, 4), (4, 1), (1, 1)] {
            for flat in [0u8, 0b1000, 0b0101, 0b1111] {
                let consts = [255u8, 0, 77, 255];
                let tex: Vec<[u8; 4]> = (0..w * h).map(|_| std::array::from_fn(|k| if flat & (1 << k) != 0 { consts[k] } else { rnd() as u8 })).collect();
                let img = Arc::new(Image { width: w, height: h, depth: 1, border: 0, internal_format: 0x8058, base: Base::Rgba, texels: Texels::Rgba8(Arc::new(tex.clone())) });
                let l = Level { tex: &tex, w, h, wf: w as f32, hf: h as f32 };
                for rep in [[true, true], [false, false], [true, false]] {
                    let pad = pairs::build(&[img.clone()], rep).unwrap();
                    let p = &pad.levels[0];
                    assert_eq!(p.flat, if w * h == 1 { 0xF } else { flat }, "{w}x{h} flat");
                    for _ in 0..200 {
                        let coord = |r: u32| (r % 8192) as f32 / 1024.0 - 3.0;
                        let s: [f32; 8] = std::array::from_fn(|_| coord(rnd()));
                        let t: [f32; 8] = std::array::from_fn(|_| coord(rnd()));
                        for skip in [0, p.flat, p.flat | 0b1000, 0b0110] {
                            let (got, want) = unsafe { filter_both(p, &l, &s, &t, rep, skip) };
                            for c in 0..4 {
                                if skip & !p.flat & (1 << c) != 0 {
                                    continue;
                                }
                                for lane in 0..8 {
                                    assert_eq!(got[c][lane].to_bits(), want[c][lane].to_bits(), "{w}x{h} {rep:?} skip {skip:#b} channel {c} at ({}, {})", s[lane], t[lane]);
                                }
                            }
                        }
                    }
                }
            }
        }
    }

    /// `filter_pairs2` (two levels' texels loaded before either is
    /// converted, one channel choice for both) gives, level by level, the
    /// bits of `filter` (plain level, four wraps) in every channel that is
    /// computed or flat, for pairs of levels with different sizes and flat
    /// channels (including a 1x1 level, no texel loaded), both wraps, and
    /// skip masks that differ between the levels.
    #[test]
    fn filter_pairs2_matches_filter() {
        if !(std::arch::is_x86_feature_detected!("avx2") && std::arch::is_x86_feature_detected!("fma")) {
            return;
        }
        use crate::render::texture::{pairs, Base, Image, Texels};
        use std::sync::Arc;
        let mut seed = 0x2545_F491u32;
        let mut rnd = move || {
            seed = seed.wrapping_mul(1_664_525).wrapping_add(1_013_904_223);
            seed >> 8
        };
        let sizes = [((8, 8), (4, 4)), ((16, 4), (8, 2)), ((4, 2), (2, 1)), ((2, 2), (1, 1)), ((32, 16), (16, 8))];
        for ((wa, ha), (wb, hb)) in sizes {
            for (fa, fb) in [(0u8, 0u8), (0b1000, 0), (0, 0b1000), (0b1000, 0b1000), (0b0101, 0b1010)] {
                let consts = [255u8, 0, 77, 255];
                let mut make = |w: i32, h: i32, flat: u8| -> Vec<[u8; 4]> { (0..w * h).map(|_| std::array::from_fn(|k| if flat & (1 << k) != 0 { consts[k] } else { rnd() as u8 })).collect() };
                let (ta, tb) = (make(wa, ha, fa), make(wb, hb, fb));
                let img = |w: i32, h: i32, t: &Vec<[u8; 4]>| Arc::new(Image { width: w, height: h, depth: 1, border: 0, internal_format: 0x8058, base: Base::Rgba, texels: Texels::Rgba8(Arc::new(t.clone())) });
                let (la, lb) = (Level { tex: &ta, w: wa, h: ha, wf: wa as f32, hf: ha as f32 }, Level { tex: &tb, w: wb, h: hb, wf: wb as f32, hf: hb as f32 });
                for rep in [[true, true], [false, false], [false, true]] {
                    let pad = pairs::build(&[img(wa, ha, &ta), img(wb, hb, &tb)], rep).unwrap();
                    let (pa, pb) = (&pad.levels[0], &pad.levels[1]);
                    for _ in 0..100 {
                        let coord = |r: u32| (r % 8192) as f32 / 1024.0 - 3.0;
                        let s: [f32; 8] = std::array::from_fn(|_| coord(rnd()));
                        let t: [f32; 8] = std::array::from_fn(|_| coord(rnd()));
                        for (ka, kb) in [(0, 0), (pa.flat, pb.flat), (pa.flat | 0b1000, pb.flat | 0b1000), (pa.flat | 0b1000, pb.flat), (0b0110, 0b0110 | pb.flat)] {
                            let (got, want) = unsafe { filter2_both((pa, &la, ka), (pb, &lb, kb), &s, &t, rep) };
                            for (lv, (p, skip)) in [(pa, ka), (pb, kb)].into_iter().enumerate() {
                                for c in 0..4 {
                                    if skip & !p.flat & (1 << c) != 0 {
                                        continue;
                                    }
                                    for lane in 0..8 {
                                        assert_eq!(got[lv][c][lane].to_bits(), want[lv][c][lane].to_bits(), "{wa}x{ha} {rep:?} skips {ka:#b} {kb:#b} level {lv} channel {c} at ({}, {})", s[lane], t[lane]);
                                    }
                                }
                            }
                        }
                    }
                }
            }
        }
    }

    #[target_feature(enable = "avx2,fma")]
    unsafe fn filter2_both(a: (&PaddedLevel, &Level, u8), b: (&PaddedLevel, &Level, u8), s: &[f32; 8], t: &[f32; 8], rep: [bool; 2]) -> ([[[f32; 8]; 4]; 2], [[[f32; 8]; 4]; 2]) {
        let (s, t) = (_mm256_loadu_ps(s.as_ptr()), _mm256_loadu_ps(t.as_ptr()));
        let (a1, b1) = filter_pairs2(a, b, s, t, rep);
        let (a2, b2) = (filter(a.1, s, t, true, rep), filter(b.1, s, t, true, rep));
        let mut out = ([[[0f32; 8]; 4]; 2], [[[0f32; 8]; 4]; 2]);
        for c in 0..4 {
            _mm256_storeu_ps(out.0[0][c].as_mut_ptr(), a1[c]);
            _mm256_storeu_ps(out.0[1][c].as_mut_ptr(), b1[c]);
            _mm256_storeu_ps(out.1[0][c].as_mut_ptr(), a2[c]);
            _mm256_storeu_ps(out.1[1][c].as_mut_ptr(), b2[c]);
        }
        out
    }

    #[target_feature(enable = "avx2,fma")]
    unsafe fn filter_both(p: &PaddedLevel, l: &Level, s: &[f32; 8], t: &[f32; 8], rep: [bool; 2], skip: u8) -> ([[f32; 8]; 4], [[f32; 8]; 4]) {
        let (s, t) = (_mm256_loadu_ps(s.as_ptr()), _mm256_loadu_ps(t.as_ptr()));
        let (a, b) = (filter_pairs(p, l, s, t, rep, skip), filter(l, s, t, true, rep));
        let mut out = ([[0f32; 8]; 4], [[0f32; 8]; 4]);
        for c in 0..4 {
            _mm256_storeu_ps(out.0[c].as_mut_ptr(), a[c]);
            _mm256_storeu_ps(out.1[c].as_mut_ptr(), b[c]);
        }
        out
    }

    /// GL_FASTEST's log2 is within 4e-5 of f64's on normal values from
    /// 2^-126 to 2^127 (mantissas sampled densely, every exponent).
    #[test]
    fn log2_approx_is_close() {
        let mut worst = 0f64;
        for e in -126..=127 {
            for k in 0..4096u32 {
                let x = f32::from_bits((((e + 127) as u32) << 23) | (k * 2048 + (k * 7919) % 2048));
                let err = (log2_approx(x) as f64 - (x as f64).log2()).abs();
                worst = worst.max(err);
            }
        }
        assert!(worst < 4e-5, "worst error {worst}");
    }

    /// The 8-lane `log2_approx` (GL_FASTEST's λ ahead) gives the scalar
    /// bits on normal values from 2^-126 to 2^127.
    #[test]
    fn log2_approx_8_matches_scalar() {
        if !(std::arch::is_x86_feature_detected!("avx2") && std::arch::is_x86_feature_detected!("fma")) {
            return;
        }
        for e in -126..=127 {
            for k in (0..4096u32).step_by(8) {
                let x: [f32; 8] = std::array::from_fn(|l| {
                    let k = k + l as u32;
                    f32::from_bits((((e + 127) as u32) << 23) | (k * 2048 + (k * 7919) % 2048))
                });
                let mut out = [0f32; 8];
                unsafe { approx8(&x, &mut out) };
                for l in 0..8 {
                    assert_eq!(out[l].to_bits(), log2_approx(x[l]).to_bits(), "log2_approx_8({:e})", x[l]);
                }
            }
        }
    }

    #[target_feature(enable = "avx2,fma")]
    unsafe fn approx8(x: &[f32; 8], out: &mut [f32; 8]) {
        _mm256_storeu_ps(out.as_mut_ptr(), log2_approx_8(_mm256_loadu_ps(x.as_ptr())));
    }

    /// The bit form of c / 255 (`unorm`, module documentation) is the
    /// division for every byte: in scalar, in `channels` at every channel
    /// position and lane, and in `channels16` when the CPU has AVX-512.
    #[test]
    fn unorm8_by_multiplies() {
        for c in 0..=255u32 {
            let f = (c * 0x010101) as f32;
            let bits = (f.to_bits() as i32).wrapping_add(UNORM_BITS).max(0) as u32;
            assert_eq!(bits, (c as f32 / 255.0).to_bits(), "{c}");
        }
        if !(std::arch::is_x86_feature_detected!("avx2") && std::arch::is_x86_feature_detected!("fma")) {
            return;
        }
        let wide = std::arch::is_x86_feature_detected!("avx512f") && std::arch::is_x86_feature_detected!("avx512bw");
        for c in 0..=255u32 {
            // Lane l holds c in channel l % 4 and other bytes elsewhere.
            let v: [u32; 16] = std::array::from_fn(|l| {
                let other = (c ^ 0xA5).wrapping_add(l as u32 * 37) & 0xFF;
                let k = l % 4;
                (other * 0x01010101) & !(0xFF << (8 * k)) | c << (8 * k)
            });
            let want = c as f32 / 255.0;
            let mut out = [[0f32; 8]; 4];
            unsafe {
                let ch = channels(_mm256_loadu_si256(v.as_ptr().cast()));
                for k in 0..4 {
                    _mm256_storeu_ps(out[k].as_mut_ptr(), ch[k]);
                }
            }
            for l in 0..8 {
                assert_eq!(out[l % 4][l].to_bits(), want.to_bits(), "channels: {c} in lane {l}");
                for k in 0..4 {
                    assert_eq!(out[k][l].to_bits(), (v[l].to_le_bytes()[k] as f32 / 255.0).to_bits(), "channels: lane {l} channel {k}");
                }
            }
            if wide {
                let mut out = [[0f32; 16]; 4];
                unsafe { wide_channels(&v, &mut out) };
                for l in 0..16 {
                    for k in 0..4 {
                        assert_eq!(out[k][l].to_bits(), (v[l].to_le_bytes()[k] as f32 / 255.0).to_bits(), "channels16: lane {l} channel {k}");
                    }
                }
            }
        }
    }

    #[target_feature(enable = "avx2,avx512f,avx512bw")]
    unsafe fn wide_channels(v: &[u32; 16], out: &mut [[f32; 16]; 4]) {
        let ch = channels16(_mm512_loadu_si512(v.as_ptr().cast()));
        for k in 0..4 {
            _mm512_storeu_ps(out[k].as_mut_ptr(), ch[k]);
        }
    }
}
