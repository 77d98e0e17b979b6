//! SIMD span kernels (GL 1.5 section 4.1): the common cases of
//! [`super::fast`]'s kernel four pixels at a time, chosen at run time by
//! CPU features (SSE2, the x86_64 baseline, or AVX2); other targets, and
//! `SOFTGL_SIMD=0`, keep the scalar kernels.
//!
//! Covered: no stencil or alpha test; depth off, or LESS / LEQUAL with
//! depth writes; colour flat, constant, affine, perspective or stepped
//! (16.16 fixed point, hint not NICEST), or any of those but stepped
//! under fog without texturing; colour stored unmasked, blended
//! SRC_ALPHA / ONE_MINUS_SRC_ALPHA or SRC_ALPHA / ONE, or not written
//! (depth-only passes).
//!
//! Exactness: the lanes run the scalar kernel's arithmetic operation for
//! operation, so every pixel gets the scalar kernel's bits:
//! - pixel centres `cx` are `x + 1/2 - x0`, exact in f64 (multiples of
//!   1/256 far below 2^44), whether stepped by 1 or by 4;
//! - depth `zr + zdx * cx` is a separate IEEE f64 multiply and add (no FMA),
//!   clamped with max/min (whose NaN rule sends NaN to 0, as the scalar
//!   clamp-then-cast does), scaled, and truncated;
//! - colours are f64 plane values converted to f32 with the current (round
//!   to nearest) mode, then the f32 clamp / ×255 / +½ / truncate of
//!   `color_to_u8`;
//! - fog (`CS_FOG`): the fog value `(r + dx * cx) * w` per lane in f64 and
//!   to f32, f from it by `fog::lanes::factors` (`Fog::fragment_factor`'s
//!   f32 operations in lanes; under AVX2 its exponential gives libm's
//!   `expf` bits, handing libm the lanes it cannot vouch for), then
//!   `Fog::apply`'s f32 products and sum in lanes (`fog::lanes::mix`),
//!   alpha kept;
//! - stepped colours use 32-bit lanes when the span's values stay in i32
//!   (the scalar kernel's i64 values are then the same integers); the clamp
//!   to [0, 255 << 16] followed by >> 16 equals >> 16 followed by the
//!   saturating packs to i16 and u8. Otherwise the scalar kernel runs;
//! - the blends are the integer forms of fast.rs: `(x + 127) / 255` as
//!   `(v + 1 + (v >> 8)) >> 8` with v = x + 127 <= 65152 (exact below
//!   65280, tested on every such v), and SRC_ALPHA / ONE as a saturating
//!   byte add of `d + div255(s a)` (`d * 255` is a multiple of 255).
//!
//! Depth compares are unsigned (sign bit flipped). The last partial group
//! of a span goes through a 4-pixel stack copy, so no lane reads or writes
//! outside the span. `tests/reference_diff.rs` compares these kernels with
//! the reference and, bit for bit, with the scalar kernels.

use super::fast::Kernel;
#[allow(unused_imports)]
use super::fast::{CO_ADD, CO_NONE, CO_OVER, CO_STORE, CS_AFFINE, CS_CONSTANT, CS_FLAT, CS_FOG, CS_PERSPECTIVE, CS_STEPPED, D_ANY, D_LEQUAL, D_LESS, D_OFF};
use std::cell::Cell;
use std::sync::atomic::{AtomicBool, AtomicU8, Ordering};

/// Instruction sets the kernels use.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Level {
    Scalar = 1,
    Sse2 = 2,
    Avx2 = 3,
}

static LEVEL: AtomicU8 = AtomicU8::new(0);
/// Set once any thread has called `force_level_on_this_thread`: until
/// then `pick` skips the thread-local (a `__tls_get_addr` call in the
/// shared library, about 60 instructions per triangle).
static LEVEL_FORCED: AtomicBool = AtomicBool::new(false);

thread_local! {
    /// Tests: the level for triangles selected on this thread (0: `level()`).
    static LEVEL_HERE: Cell<u8> = const { Cell::new(0) };
}

/// The best level this CPU has, unless `SOFTGL_SIMD` lowers it
/// (`0` scalar, `sse2`), decided once. Inlined (a load and a compare:
/// `raster::Runs::find` asks once per small triangle); the first call
/// decides out of line.
#[inline]
pub fn level() -> Level {
    match LEVEL.load(Ordering::Relaxed) {
        1 => Level::Scalar,
        2 => Level::Sse2,
        3 => Level::Avx2,
        _ => decide_level(),
    }
}

#[cold]
#[inline(never)]
fn decide_level() -> Level {
    let detected = detect();
    let l = match std::env::var("SOFTGL_SIMD").as_deref() {
        Ok("0") | Ok("scalar") => Level::Scalar,
        Ok("sse2") if detected != Level::Scalar => Level::Sse2,
        _ => detected,
    };
    LEVEL.store(l as u8, Ordering::Relaxed);
    l
}

#[cfg(target_arch = "x86_64")]
fn detect() -> Level {
    if is_x86_feature_detected!("avx2") {
        Level::Avx2
    } else {
        Level::Sse2
    }
}

#[cfg(not(target_arch = "x86_64"))]
fn detect() -> Level {
    Level::Scalar
}

/// Makes kernel selection on the calling thread use `level` (at most the
/// detected one), or `level()` again with `None`: for differential tests.
#[doc(hidden)]
pub fn force_level_on_this_thread(level: Option<Level>) {
    LEVEL_FORCED.store(true, Ordering::Relaxed);
    LEVEL_HERE.with(|c| c.set(level.map_or(0, |l| l as u8)));
}

/// The level for triangles selected on this thread (`level()` unless a
/// test forced a lower one), as `pick` decides it.
/// Inlined (round 16: `raster::Cover` asks once per small triangle; the
/// call cost about 20 instructions a triangle), the forced level apart.
#[cfg_attr(not(target_arch = "x86_64"), allow(dead_code))] // its callers pick x86-64 kernels
#[inline(always)]
pub(crate) fn level_here() -> Level {
    if LEVEL_FORCED.load(Ordering::Relaxed) {
        level_forced()
    } else {
        level()
    }
}

/// [`level_here`] once a test has forced a level on some thread.
#[cold]
#[inline(never)]
fn level_forced() -> Level {
    let l = level();
    match LEVEL_HERE.with(|c| c.get()) {
        1 => Level::Scalar,
        2 if l != Level::Scalar => Level::Sse2,
        _ => l,
    }
}

/// The SIMD kernel for the stencil test `s` (on / off), depth key `d`,
/// colour source `cs` and colour write `co` (fast.rs's keys; no alpha
/// test), if there is one.
pub(super) fn pick(s: bool, d: u8, cs: u8, co: u8) -> Option<Kernel> {
    let mut l = level();
    match if LEVEL_FORCED.load(Ordering::Relaxed) { LEVEL_HERE.with(|c| c.get()) } else { 0 } {
        1 => l = Level::Scalar,
        2 if l != Level::Scalar => l = Level::Sse2,
        _ => {}
    }
    if l == Level::Scalar {
        return None;
    }
    if s {
        pick_at::<true>(l, d, cs, co)
    } else {
        pick_at::<false>(l, d, cs, co)
    }
}

#[cfg(not(target_arch = "x86_64"))]
fn pick_at<const S: bool>(_: Level, _: u8, _: u8, _: u8) -> Option<Kernel> {
    None
}

#[cfg(target_arch = "x86_64")]
fn pick_at<const S: bool>(l: Level, d: u8, cs: u8, co: u8) -> Option<Kernel> {
    use x86::{avx2, sse2};
    macro_rules! by_level {
        ($d:ident, $cs:ident, $co:ident) => {
            Some(if l == Level::Avx2 { avx2::<S, $d, $cs, $co> } else { sse2::<S, $d, $cs, $co> })
        };
    }
    macro_rules! by_co {
        ($d:ident, $cs:ident) => {
            match co {
                CO_STORE => by_level!($d, $cs, CO_STORE),
                CO_OVER => by_level!($d, $cs, CO_OVER),
                CO_ADD => by_level!($d, $cs, CO_ADD),
                _ => None,
            }
        };
    }
    macro_rules! by_cs {
        ($d:ident) => {
            match (cs, co) {
                (_, CO_NONE) if $d != D_OFF || S => by_level!($d, CS_FLAT, CO_NONE),
                (CS_STEPPED, CO_STORE) => by_level!($d, CS_STEPPED, CO_STORE),
                (CS_FLAT, _) => by_co!($d, CS_FLAT),
                (CS_CONSTANT, _) => by_co!($d, CS_CONSTANT),
                (CS_AFFINE, _) => by_co!($d, CS_AFFINE),
                (CS_PERSPECTIVE, _) => by_co!($d, CS_PERSPECTIVE),
                (CS_FOG, _) => by_co!($d, CS_FOG),
                _ => None,
            }
        };
    }
    match d {
        D_OFF => by_cs!(D_OFF),
        D_LESS => by_cs!(D_LESS),
        D_LEQUAL => by_cs!(D_LEQUAL),
        _ => by_cs!(D_ANY),
    }
}

#[cfg(target_arch = "x86_64")]
mod x86 {
    use super::super::fast::{self, FogRow, CO_ADD, CO_NONE, CO_OVER, CS_AFFINE, CS_CONSTANT, CS_FOG, CS_PERSPECTIVE, CS_STEPPED, D_ANY, D_LEQUAL, D_LESS, D_OFF};
    use super::super::{color_to_u8, CompareFunc, FragmentState, SpanPixels, StencilOp, StencilTest};
    use crate::framebuffer::DEPTH_MAX;
    use crate::render::fog::lanes as fog_lanes;
    use crate::render::setup::TriangleSetup;
    use std::arch::x86_64::*;

    /// The SSE2 kernel (x86_64's baseline: no detection needed).
    pub(super) fn sse2<const S: bool, const D: u8, const CS: u8, const CO: u8>(fs: &FragmentState, t: &TriangleSetup, px: &mut SpanPixels, y: usize, x0: usize, x1: usize) {
        // SAFETY: SSE2 is part of x86_64.
        unsafe { span::<false, S, D, CS, CO>(fs, t, px, y, x0, x1) }
    }

    /// The AVX2 kernel: depth and colour planes evaluated four f64 lanes
    /// at a time. Only selected when the CPU has AVX2 (`super::detect`).
    pub(super) fn avx2<const S: bool, const D: u8, const CS: u8, const CO: u8>(fs: &FragmentState, t: &TriangleSetup, px: &mut SpanPixels, y: usize, x0: usize, x1: usize) {
        // SAFETY: `pick_at` hands this out only at Level::Avx2, which
        // `detect` returns only when the CPU reports AVX2.
        unsafe { span_avx2::<S, D, CS, CO>(fs, t, px, y, x0, x1) }
    }

    #[target_feature(enable = "avx2")]
    unsafe fn span_avx2<const S: bool, const D: u8, const CS: u8, const CO: u8>(fs: &FragmentState, t: &TriangleSetup, px: &mut SpanPixels, y: usize, x0: usize, x1: usize) {
        span::<true, S, D, CS, CO>(fs, t, px, y, x0, x1)
    }

    /// `func(a, b)` of four i32 lanes (callers flip the sign bit of u32s).
    #[inline(always)]
    unsafe fn compare(func: CompareFunc, a: __m128i, b: __m128i) -> __m128i {
        let ones = _mm_set1_epi32(-1);
        match func {
            CompareFunc::Never => _mm_setzero_si128(),
            CompareFunc::Less => _mm_cmplt_epi32(a, b),
            CompareFunc::Equal => _mm_cmpeq_epi32(a, b),
            CompareFunc::Lequal => _mm_xor_si128(_mm_cmpgt_epi32(a, b), ones),
            CompareFunc::Greater => _mm_cmpgt_epi32(a, b),
            CompareFunc::Notequal => _mm_xor_si128(_mm_cmpeq_epi32(a, b), ones),
            CompareFunc::Gequal => _mm_xor_si128(_mm_cmplt_epi32(a, b), ones),
            CompareFunc::Always => ones,
        }
    }

    /// `StencilTest::apply(op, s)` on four i32 lanes holding stencil bytes.
    #[inline(always)]
    unsafe fn stencil_op(st: &StencilTest, op: StencilOp, s: __m128i) -> __m128i {
        let max = _mm_set1_epi32(st.max as i32);
        let one = _mm_set1_epi32(1);
        let v = match op {
            StencilOp::Keep => return s,
            StencilOp::Zero => _mm_setzero_si128(),
            StencilOp::Replace => _mm_set1_epi32(st.reference as i32),
            // s >= max ? max : s + 1 (s <= 255: no wrap in i32).
            StencilOp::Incr => {
                let up = _mm_add_epi32(s, one);
                select(_mm_cmplt_epi32(s, max), up, max)
            }
            // saturating_sub(1): s > 0 ? s - 1 : 0.
            StencilOp::Decr => {
                let down = _mm_sub_epi32(s, one);
                _mm_and_si128(_mm_cmpgt_epi32(s, _mm_setzero_si128()), down)
            }
            StencilOp::Invert => _mm_andnot_si128(s, max),
            StencilOp::IncrWrap => _mm_and_si128(_mm_add_epi32(s, one), max),
            StencilOp::DecrWrap => _mm_and_si128(_mm_sub_epi32(s, one), max),
        };
        let wm = _mm_set1_epi32(st.write_mask as i32);
        _mm_or_si128(_mm_andnot_si128(wm, s), _mm_and_si128(v, wm))
    }

    /// Depth of four pixels at cx, cx + 1, cx + 2, cx + 3 in 24-bit fixed
    /// point: `depth_to_fixed(zr + zdx * cx)` lane by lane.
    #[inline(always)]
    unsafe fn depth4<const AVX: bool>(zr: f64, zdx: f64, cx: f64) -> __m128i {
        if AVX {
            depth4_avx(zr, zdx, cx)
        } else {
            let (zr, zdx) = (_mm_set1_pd(zr), _mm_set1_pd(zdx));
            let (zero, one) = (_mm_setzero_pd(), _mm_set1_pd(1.0));
            let (scale, half) = (_mm_set1_pd(DEPTH_MAX as f64), _mm_set1_pd(0.5));
            let lo = _mm_set_pd(cx + 1.0, cx);
            let hi = _mm_set_pd(cx + 3.0, cx + 2.0);
            let conv = |c: __m128d| {
                let z = _mm_add_pd(zr, _mm_mul_pd(zdx, c));
                // max(z, 0): NaN z gives the second operand, 0.
                let z = _mm_min_pd(_mm_max_pd(z, zero), one);
                _mm_cvttpd_epi32(_mm_add_pd(_mm_mul_pd(z, scale), half))
            };
            _mm_unpacklo_epi64(conv(lo), conv(hi))
        }
    }

    #[inline]
    #[target_feature(enable = "avx2")]
    unsafe fn depth4_avx(zr: f64, zdx: f64, cx: f64) -> __m128i {
        let c = _mm256_add_pd(_mm256_set1_pd(cx), _mm256_setr_pd(0.0, 1.0, 2.0, 3.0));
        let z = _mm256_add_pd(_mm256_set1_pd(zr), _mm256_mul_pd(_mm256_set1_pd(zdx), c));
        let z = _mm256_min_pd(_mm256_max_pd(z, _mm256_setzero_pd()), _mm256_set1_pd(1.0));
        _mm256_cvttpd_epi32(_mm256_add_pd(_mm256_mul_pd(z, _mm256_set1_pd(DEPTH_MAX as f64)), _mm256_set1_pd(0.5)))
    }

    /// `1 / (qr + qdx * c)` for c = cx .. cx + 3: four correctly rounded
    /// divisions, as the scalar kernel's per pixel.
    #[inline(always)]
    unsafe fn recip4<const AVX: bool>(qr: f64, qdx: f64, cx: f64) -> [f64; 4] {
        let mut w = [0.0f64; 4];
        if AVX {
            recip4_avx(qr, qdx, cx, &mut w);
        } else {
            let (qr, qdx, one) = (_mm_set1_pd(qr), _mm_set1_pd(qdx), _mm_set1_pd(1.0));
            let lo = _mm_div_pd(one, _mm_add_pd(qr, _mm_mul_pd(qdx, _mm_set_pd(cx + 1.0, cx))));
            let hi = _mm_div_pd(one, _mm_add_pd(qr, _mm_mul_pd(qdx, _mm_set_pd(cx + 3.0, cx + 2.0))));
            _mm_storeu_pd(w.as_mut_ptr(), lo);
            _mm_storeu_pd(w.as_mut_ptr().add(2), hi);
        }
        w
    }

    #[inline]
    #[target_feature(enable = "avx2")]
    unsafe fn recip4_avx(qr: f64, qdx: f64, cx: f64, w: &mut [f64; 4]) {
        let c = _mm256_add_pd(_mm256_set1_pd(cx), _mm256_setr_pd(0.0, 1.0, 2.0, 3.0));
        let q = _mm256_add_pd(_mm256_set1_pd(qr), _mm256_mul_pd(_mm256_set1_pd(qdx), c));
        _mm256_storeu_pd(w.as_mut_ptr(), _mm256_div_pd(_mm256_set1_pd(1.0), q));
    }

    /// `color_to_u8` of four f32 channels, as i32 lanes in [0, 255].
    #[inline(always)]
    unsafe fn to_u8_lanes(c: __m128) -> __m128i {
        // max(c, 0): NaN gives 0, as the scalar clamp-then-cast does.
        let c = _mm_min_ps(_mm_max_ps(c, _mm_setzero_ps()), _mm_set1_ps(1.0));
        _mm_cvttps_epi32(_mm_add_ps(_mm_mul_ps(c, _mm_set1_ps(255.0)), _mm_set1_ps(0.5)))
    }

    /// One pixel's colour from the planes: `(cr + cdx * cx) * w` per channel
    /// in f64 (w = 1 and no multiply when affine), then to f32 and bytes.
    #[inline(always)]
    unsafe fn plane_color<const AVX: bool, const PERSP: bool>(cr: &[f64; 4], cdx: &[f64; 4], cx: f64, w: f64) -> __m128i {
        to_u8_lanes(plane_color_f32::<AVX, PERSP>(cr, cdx, cx, w))
    }

    /// [`plane_color`] before the conversion to bytes: the f32 channels.
    #[inline(always)]
    unsafe fn plane_color_f32<const AVX: bool, const PERSP: bool>(cr: &[f64; 4], cdx: &[f64; 4], cx: f64, w: f64) -> __m128 {
        if AVX {
            plane_color_avx::<PERSP>(cr, cdx, cx, w)
        } else {
            let c = _mm_set1_pd(cx);
            let mut rg = _mm_add_pd(_mm_loadu_pd(cr.as_ptr()), _mm_mul_pd(_mm_loadu_pd(cdx.as_ptr()), c));
            let mut ba = _mm_add_pd(_mm_loadu_pd(cr.as_ptr().add(2)), _mm_mul_pd(_mm_loadu_pd(cdx.as_ptr().add(2)), c));
            if PERSP {
                rg = _mm_mul_pd(rg, _mm_set1_pd(w));
                ba = _mm_mul_pd(ba, _mm_set1_pd(w));
            }
            _mm_movelh_ps(_mm_cvtpd_ps(rg), _mm_cvtpd_ps(ba))
        }
    }

    /// The fog values of pixels cx .. cx + 3, `((r + dx * c) * w) as f32`
    /// lane by lane (w = 1 when not perspective, as in the reference).
    #[inline(always)]
    unsafe fn fog_values<const AVX: bool>(r: f64, dx: f64, cx: f64, w: &[f64; 4]) -> [f32; 4] {
        let mut v = [0.0f32; 4];
        if AVX {
            fog_values_avx(r, dx, cx, w, &mut v);
        } else {
            let (r, dx) = (_mm_set1_pd(r), _mm_set1_pd(dx));
            let lo = _mm_mul_pd(_mm_add_pd(r, _mm_mul_pd(dx, _mm_set_pd(cx + 1.0, cx))), _mm_loadu_pd(w.as_ptr()));
            let hi = _mm_mul_pd(_mm_add_pd(r, _mm_mul_pd(dx, _mm_set_pd(cx + 3.0, cx + 2.0))), _mm_loadu_pd(w.as_ptr().add(2)));
            _mm_storeu_ps(v.as_mut_ptr(), _mm_movelh_ps(_mm_cvtpd_ps(lo), _mm_cvtpd_ps(hi)));
        }
        v
    }

    #[inline]
    #[target_feature(enable = "avx2")]
    unsafe fn fog_values_avx(r: f64, dx: f64, cx: f64, w: &[f64; 4], v: &mut [f32; 4]) {
        let c = _mm256_add_pd(_mm256_set1_pd(cx), _mm256_setr_pd(0.0, 1.0, 2.0, 3.0));
        let f = _mm256_mul_pd(_mm256_add_pd(_mm256_set1_pd(r), _mm256_mul_pd(_mm256_set1_pd(dx), c)), _mm256_loadu_pd(w.as_ptr()));
        _mm_storeu_ps(v.as_mut_ptr(), _mm256_cvtpd_ps(f));
    }

    /// `Fog::apply(color, ..)` for fog factor f and fog colour `fc`:
    /// `fog::lanes::mix` of the channels, alpha from `color`.
    #[inline(always)]
    unsafe fn fog_blend(color: __m128, f: f32, fc: __m128) -> __m128 {
        let rgb = fog_lanes::mix(color, _mm_set1_ps(f), fc);
        let alpha = _mm_castsi128_ps(_mm_setr_epi32(0, 0, 0, -1));
        _mm_or_ps(_mm_and_ps(alpha, color), _mm_andnot_ps(alpha, rgb))
    }

    #[inline]
    #[target_feature(enable = "avx2")]
    unsafe fn plane_color_avx<const PERSP: bool>(cr: &[f64; 4], cdx: &[f64; 4], cx: f64, w: f64) -> __m128 {
        let mut v = _mm256_add_pd(_mm256_loadu_pd(cr.as_ptr()), _mm256_mul_pd(_mm256_loadu_pd(cdx.as_ptr()), _mm256_set1_pd(cx)));
        if PERSP {
            v = _mm256_mul_pd(v, _mm256_set1_pd(w));
        }
        _mm256_cvtpd_ps(v)
    }

    /// Four pixels' i32 channel lanes (each in [0, 255] or to be saturated)
    /// packed to 16 bytes, pixel 0 first.
    #[inline(always)]
    unsafe fn pack4(p0: __m128i, p1: __m128i, p2: __m128i, p3: __m128i) -> __m128i {
        _mm_packus_epi16(_mm_packs_epi32(p0, p1), _mm_packs_epi32(p2, p3))
    }

    /// round(x / 255) of u16 lanes holding v = x + 127 <= 65152 (exact
    /// for v < 65280, where v + 1 + (v >> 8) does not wrap).
    #[inline(always)]
    unsafe fn div255(v: __m128i) -> __m128i {
        _mm_srli_epi16::<8>(_mm_add_epi16(_mm_add_epi16(v, _mm_set1_epi16(1)), _mm_srli_epi16::<8>(v)))
    }

    /// Each pixel's alpha in all four of its u16 lanes.
    #[inline(always)]
    unsafe fn alpha16(s: __m128i) -> __m128i {
        _mm_shufflehi_epi16::<0xFF>(_mm_shufflelo_epi16::<0xFF>(s))
    }

    /// SRC_ALPHA, ONE_MINUS_SRC_ALPHA of four pixels.
    #[inline(always)]
    unsafe fn over(s: __m128i, d: __m128i) -> __m128i {
        let z = _mm_setzero_si128();
        let half = |s: __m128i, d: __m128i| {
            let a = alpha16(s);
            let ia = _mm_sub_epi16(_mm_set1_epi16(255), a);
            let x = _mm_add_epi16(_mm_add_epi16(_mm_mullo_epi16(s, a), _mm_mullo_epi16(d, ia)), _mm_set1_epi16(127));
            div255(x)
        };
        let lo = half(_mm_unpacklo_epi8(s, z), _mm_unpacklo_epi8(d, z));
        let hi = half(_mm_unpackhi_epi8(s, z), _mm_unpackhi_epi8(d, z));
        _mm_packus_epi16(lo, hi)
    }

    /// SRC_ALPHA, ONE of four pixels: d + round(s a / 255), saturated.
    #[inline(always)]
    unsafe fn add(s: __m128i, d: __m128i) -> __m128i {
        let z = _mm_setzero_si128();
        let half = |s: __m128i| div255(_mm_add_epi16(_mm_mullo_epi16(s, alpha16(s)), _mm_set1_epi16(127)));
        let sa = _mm_packus_epi16(half(_mm_unpacklo_epi8(s, z)), half(_mm_unpackhi_epi8(s, z)));
        _mm_adds_epu8(d, sa)
    }

    /// (m & a) | (!m & b).
    #[inline(always)]
    unsafe fn select(m: __m128i, a: __m128i, b: __m128i) -> __m128i {
        _mm_or_si128(_mm_and_si128(m, a), _mm_andnot_si128(m, b))
    }

    /// `select` for AVX2 kernels, as one `blendv` (m's lanes all ones or
    /// all zeros).
    #[inline]
    #[target_feature(enable = "avx2")]
    unsafe fn blend_avx(m: __m128i, a: __m128i, b: __m128i) -> __m128i {
        _mm_blendv_epi8(b, a, m)
    }

    /// A span's constants, for [`group`].
    struct Ctx<'a> {
        fs: &'a FragmentState,
        st: &'a StencilTest,
        zr: f64,
        zdx: f64,
        cr: [f64; 4],
        cdx: [f64; 4],
        qr: f64,
        qdx: f64,
        flat: __m128i,
        /// CS_FOG: the fog row, the fog colour, and whether 1/w is divided.
        fog: Option<FogRow>,
        fog_color: __m128,
        perspective: bool,
        /// FragmentState::alpha_fix in every lane's alpha byte.
        afix: __m128i,
        sref: __m128i,
        svmask: __m128i,
        sign: __m128i,
    }

    /// Four pixels at cx .. cx + 3 whose depth, colour and stencil are at
    /// zp, cp, sp, the lanes in `m` only; returns how many passed.
    #[inline(always)]
    unsafe fn group<const AVX: bool, const S: bool, const D: u8, const CS: u8, const CO: u8>(
        c: &Ctx,
        zp: *mut u32,
        cp: *mut u8,
        sp: *mut u8,
        mut m: __m128i,
        cx: f64,
        step: &[__m128i; 4],
    ) -> u32 {
        // Stencil (section 4.1.5): the four bytes as i32 lanes.
        let (mut s_in, mut s_new) = (_mm_setzero_si128(), _mm_setzero_si128());
        if S {
            let z = _mm_setzero_si128();
            s_in = _mm_unpacklo_epi16(_mm_unpacklo_epi8(_mm_cvtsi32_si128(sp.cast::<i32>().read_unaligned()), z), z);
            let pass = _mm_and_si128(compare(c.st.func, c.sref, _mm_and_si128(s_in, c.svmask)), m);
            let fail = _mm_andnot_si128(pass, m);
            s_new = select(fail, stencil_op(c.st, c.st.fail, s_in), s_in);
            m = pass;
        }
        if D != D_OFF {
            let z = depth4::<AVX>(c.zr, c.zdx, cx);
            let stored = _mm_loadu_si128(zp.cast());
            let (zs, ss) = (_mm_xor_si128(z, c.sign), _mm_xor_si128(stored, c.sign));
            let pass = match D {
                D_LESS => _mm_cmplt_epi32(zs, ss),
                D_LEQUAL => _mm_xor_si128(_mm_cmpgt_epi32(zs, ss), _mm_set1_epi32(-1)),
                _ => compare(c.fs.depth_func, zs, ss),
            };
            if S {
                let zfail = _mm_andnot_si128(pass, m);
                s_new = select(zfail, stencil_op(c.st, c.st.zfail, s_in), s_new);
            }
            m = _mm_and_si128(m, pass);
            if D != D_ANY || c.fs.depth_write {
                _mm_storeu_si128(zp.cast(), select(m, z, stored));
            }
        }
        if S {
            s_new = select(m, stencil_op(c.st, c.st.zpass, s_in), s_new);
            let bytes = _mm_packus_epi16(_mm_packs_epi32(s_new, s_new), s_new);
            sp.cast::<i32>().write_unaligned(_mm_cvtsi128_si32(bytes));
        }
        let bits = _mm_movemask_ps(_mm_castsi128_ps(m));
        let count = bits.count_ones();
        if CO != CO_NONE && bits != 0 {
            let src = match CS {
                CS_STEPPED => pack4(_mm_srai_epi32::<16>(step[0]), _mm_srai_epi32::<16>(step[1]), _mm_srai_epi32::<16>(step[2]), _mm_srai_epi32::<16>(step[3])),
                CS_AFFINE => pack4(
                    plane_color::<AVX, false>(&c.cr, &c.cdx, cx, 1.0),
                    plane_color::<AVX, false>(&c.cr, &c.cdx, cx + 1.0, 1.0),
                    plane_color::<AVX, false>(&c.cr, &c.cdx, cx + 2.0, 1.0),
                    plane_color::<AVX, false>(&c.cr, &c.cdx, cx + 3.0, 1.0),
                ),
                CS_PERSPECTIVE => {
                    let w = recip4::<AVX>(c.qr, c.qdx, cx);
                    let p = |k: usize| plane_color::<AVX, true>(&c.cr, &c.cdx, cx + k as f64, w[k]);
                    pack4(p(0), p(1), p(2), p(3))
                }
                CS_FOG => match &c.fog {
                    Some(fog) => {
                        // `fast::fog_color` in lanes: one 1/w for colour and
                        // fog, the clamped colour (glam's max-then-min), f
                        // per lane, the blend.
                        let w = if c.perspective { recip4::<AVX>(c.qr, c.qdx, cx) } else { [1.0; 4] };
                        let v = fog_values::<AVX>(fog.r, fog.dx, cx, &w);
                        // f for the written lanes (the others' colours
                        // are dropped).
                        let mut f = [0.0f32; 4];
                        _mm_storeu_ps(f.as_mut_ptr(), fog_lanes::factors::<AVX>(&fog.fog, _mm_loadu_ps(v.as_ptr()), bits));
                        let flat = fog.flat.map(|c| _mm_loadu_ps(c.as_ref().as_ptr()));
                        let p = |k: usize| {
                            let col = match flat {
                                Some(col) => col,
                                None => _mm_min_ps(_mm_max_ps(plane_color_f32::<AVX, true>(&c.cr, &c.cdx, cx + k as f64, w[k]), _mm_setzero_ps()), _mm_set1_ps(1.0)),
                            };
                            to_u8_lanes(fog_blend(col, f[k], c.fog_color))
                        };
                        pack4(p(0), p(1), p(2), p(3))
                    }
                    None => c.flat,
                },
                _ => c.flat,
            };
            let dst = _mm_loadu_si128(cp.cast());
            let new = match CO {
                CO_OVER => over(src, dst),
                CO_ADD => add(src, dst),
                _ => src,
            };
            let out = _mm_or_si128(new, c.afix);
            // LLVM turns a store of `select(m, out, dst)` back to `dst`'s
            // address into a masked store (`vpmaskmovd` under AVX2), which
            // costs about three plain stores on AMD Zen 3 (stamp.rs, round
            // 15). The group's four pixels are all the span's, so it may
            // store all four: plainly when every lane is written (whole
            // groups of window-filling spans), else through `blendv`,
            // which LLVM leaves a blend.
            if bits == 15 {
                _mm_storeu_si128(cp.cast(), out);
            } else if AVX {
                _mm_storeu_si128(cp.cast(), blend_avx(m, out, dst));
            } else {
                _mm_storeu_si128(cp.cast(), select(m, out, dst));
            }
        }
        count
    }

    /// Pixels [x0, x1) of row y, four at a time; the scalar kernel when a
    /// stepped colour leaves i32.
    #[inline(always)]
    unsafe fn span<const AVX: bool, const S: bool, const D: u8, const CS: u8, const CO: u8>(fs: &FragmentState, t: &TriangleSetup, px: &mut SpanPixels, y: usize, x0: usize, x1: usize) {
        if x1 < x0 + 4 && CS != CS_FOG {
            // Fewer than four pixels: the set-up and the stack copy of a
            // partial group cost more than the scalar loop (small
            // triangles), except for fogged colour, whose scalar form costs
            // more per pixel than the group's set-up.
            return fast::kernel::<S, D, CS, CO>(fs, t, px, y, x0, x1);
        }
        if x0 >= x1 {
            return;
        }
        let n = x1 - x0;
        let cy = y as f64 + 0.5 - t.y0;
        // Row terms, as the scalar kernel hoists them.
        let zr = t.z.a0 + t.z.dy * cy;
        let zdx = t.z.dx;
        let cr: [f64; 4] = std::array::from_fn(|c| t.color[c].a0 + t.color[c].dy * cy);
        let cdx: [f64; 4] = std::array::from_fn(|c| t.color[c].dx);
        let qr = t.q.a0 + t.q.dy * cy;
        let qdx = t.q.dx;
        let cx0 = x0 as f64 + 0.5 - t.x0;
        let mut flat = _mm_setzero_si128();
        if CS == CS_CONSTANT {
            flat = _mm_set1_epi32(u32::from_ne_bytes(color_to_u8(glam::Vec4::from_array(std::array::from_fn(|c| cr[c] as f32)))) as i32);
        } else if CS != CS_AFFINE && CS != CS_PERSPECTIVE && CS != CS_STEPPED {
            flat = _mm_set1_epi32(u32::from_ne_bytes(t.flat.unwrap_or_default()) as i32);
        }
        // Stepped colour: pixel k's channels are fixed + k * dx (i64 in the
        // scalar kernel); in i32 lanes when every pixel's value fits.
        let mut step = [_mm_setzero_si128(); 4];
        let mut step4 = _mm_setzero_si128();
        if CS == CS_STEPPED {
            let (fixed, dx) = fast::stepped_start(&cr, &cdx, cx0, x0);
            let last = (n - 1) as i64;
            let fits = |v: i64| v >= i32::MIN as i64 && v <= i32::MAX as i64;
            if !(0..4).all(|c| fits(fixed[c]) && fits(fixed[c] + dx[c] * last)) {
                return fast::kernel::<S, D, CS, CO>(fs, t, px, y, x0, x1);
            }
            // Wrapping: lanes past the end may leave i32; they are unused.
            let lane = |k: i64| _mm_setr_epi32((fixed[0] + dx[0] * k) as i32, (fixed[1] + dx[1] * k) as i32, (fixed[2] + dx[2] * k) as i32, (fixed[3] + dx[3] * k) as i32);
            step = [lane(0), lane(1), lane(2), lane(3)];
            step4 = _mm_setr_epi32((dx[0] * 4) as i32, (dx[1] * 4) as i32, (dx[2] * 4) as i32, (dx[3] * 4) as i32);
        }
        let SpanPixels { color, depth, stencil, passed: total, .. } = px;
        let col: *mut u8 = if CO != CO_NONE { color[..n].as_mut_ptr().cast() } else { std::ptr::null_mut() };
        let dep: *mut u32 = if D != D_OFF { depth[..n].as_mut_ptr() } else { std::ptr::null_mut() };
        let sten: *mut u8 = if S { stencil[..n].as_mut_ptr() } else { std::ptr::null_mut() };
        let st = &fs.stencil;
        let (sref, svmask) = (_mm_set1_epi32(st.masked_ref as i32), _mm_set1_epi32(st.value_mask as i32));
        let sign = _mm_set1_epi32(i32::MIN);
        let lanes = _mm_setr_epi32(0, 1, 2, 3);
        let mut passed = 0u64;
        let mut cx = cx0;
        let fog = if CS == CS_FOG { FogRow::new(t, cy) } else { None };
        let fog_color = match &fog {
            Some(f) => _mm_loadu_ps(f.fog.color.as_ref().as_ptr()),
            None => _mm_setzero_ps(),
        };
        let ctx = Ctx { fs, st, zr, zdx, cr, cdx, qr, qdx, flat, fog, fog_color, perspective: t.perspective, afix: _mm_set1_epi32(((fs.alpha_fix as u32) << 24) as i32), sref, svmask, sign };
        // Pointers for the buffers a kernel does not touch (never read).
        let (mut zbuf, mut cbuf, mut sbuf) = ([0u32; 4], [0u32; 4], [0u8; 4]);
        let pick = |i: usize, zb: *mut u32, cb: *mut u8, sb: *mut u8| -> (*mut u32, *mut u8, *mut u8) {
            (if D != D_OFF { dep.add(i) } else { zb }, if CO != CO_NONE { col.add(4 * i) } else { cb }, if S { sten.add(i) } else { sb })
        };
        let full = n & !3;
        let mut i = 0;
        while i < full {
            let (zp, cp, sp) = pick(i, zbuf.as_mut_ptr(), cbuf.as_mut_ptr().cast(), sbuf.as_mut_ptr());
            passed += group::<AVX, S, D, CS, CO>(&ctx, zp, cp, sp, _mm_set1_epi32(-1), cx, &step) as u64;
            if CS == CS_STEPPED {
                for s in step.iter_mut() {
                    *s = _mm_add_epi32(*s, step4);
                }
            }
            cx += 4.0;
            i += 4;
        }
        let left = n - i;
        if left > 0 {
            // The last partial group works on a stack copy of its pixels.
            for k in 0..left {
                if S {
                    sbuf[k] = *sten.add(i + k);
                }
                if D != D_OFF {
                    zbuf[k] = *dep.add(i + k);
                }
                if CO != CO_NONE {
                    cbuf[k] = u32::from_ne_bytes(*col.add(4 * (i + k)).cast::<[u8; 4]>());
                }
            }
            let m = _mm_cmpgt_epi32(_mm_set1_epi32(left as i32), lanes);
            passed += group::<AVX, S, D, CS, CO>(&ctx, zbuf.as_mut_ptr(), cbuf.as_mut_ptr().cast(), sbuf.as_mut_ptr(), m, cx, &step) as u64;
            for k in 0..left {
                if S {
                    *sten.add(i + k) = sbuf[k];
                }
                if D != D_OFF {
                    *dep.add(i + k) = zbuf[k];
                }
                if CO != CO_NONE {
                    *col.add(4 * (i + k)).cast::<[u8; 4]>() = cbuf[k].to_ne_bytes();
                }
            }
        }
        *total += passed;
    }

    #[cfg(test)]
    mod tests {
        use super::*;

        /// The u16 division identity the blends use, on every lane value
        /// below 65280 (the blends' largest is 255 * 255 + 127 = 65152;
        /// from 65280 on, v + 1 + (v >> 8) wraps).
        #[test]
        fn div255_identity() {
            for v in 0..65280u32 {
                let got = unsafe { _mm_extract_epi16::<0>(div255(_mm_set1_epi16(v as u16 as i16))) } as u32;
                assert_eq!(got, v / 255, "v = {v}");
            }
        }

        /// The 4-pixel blends against fast.rs's scalar formulas.
        #[test]
        fn blends_match_scalar() {
            let mut seed = 7u64;
            for _ in 0..200_000 {
                seed = seed.wrapping_mul(6364136223846793005).wrapping_add(1442695040888963407);
                let (s, d) = ((seed >> 1) as u32, (seed >> 33) as u32 ^ (seed as u32));
                let (sv, dv) = (unsafe { _mm_set1_epi32(s as i32) }, unsafe { _mm_set1_epi32(d as i32) });
                let (sb, db) = (s.to_ne_bytes(), d.to_ne_bytes());
                let o = unsafe { _mm_cvtsi128_si32(over(sv, dv)) } as u32;
                let a = unsafe { _mm_cvtsi128_si32(add(sv, dv)) } as u32;
                let (ea, ia) = (sb[3] as u32, 255 - sb[3] as u32);
                let eo: [u8; 4] = std::array::from_fn(|c| ((sb[c] as u32 * ea + db[c] as u32 * ia + 127) / 255) as u8);
                let eadd: [u8; 4] = std::array::from_fn(|c| ((sb[c] as u32 * ea + db[c] as u32 * 255 + 127) / 255).min(255) as u8);
                assert_eq!(o.to_ne_bytes(), eo, "over {sb:?} {db:?}");
                assert_eq!(a.to_ne_bytes(), eadd, "add {sb:?} {db:?}");
            }
        }
    }
}
