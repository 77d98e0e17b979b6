//! Fragment runs of lines and points (GL 1.5 sections 3.3 and 3.4, then
//! the per-fragment operations of section 4.1): the fast path's way of
//! handing a line's or point's fragments to the framebuffer. A run is n
//! fragments at framebuffer indices i0, i0 + stride, ... (a row piece of a
//! point, of a smooth line or of a y-major wide line; a column piece of an
//! x-major wide line), each with its own depth and colour, produced only
//! when a stage needs them.
//!
//! The state is classified once per primitive ([`Sink::new`]): no test and
//! the colour stored unmasked, or blended SRC_ALPHA / ONE_MINUS_SRC_ALPHA
//! (what antialiased lines use), have their own loops; everything else runs
//! [`fragment::fragment`] monomorphized over the stage groups, chosen once
//! per run instead of once per fragment. Every mode computes exactly what
//! `fragment::shade_fragment` does per fragment: the blend is the integer
//! form that fast.rs proves equal to `Blend::apply` (tested here on every
//! operand).

use super::fragment::{self, key, Blend, BlendEquation, BlendFactor, Buffers, ColorOp, FragmentState, SpanPixels};
use crate::framebuffer::Framebuffer;

/// Whole rows of the framebuffer (a tile worker's band) indexed as the
/// framebuffer is, `y * width + x`: where binned lines and points run
/// (`tile`), each worker writing only its band.
pub struct Band<'a> {
    /// Rows [y0, y1) from the band's first pixel.
    pub px: SpanPixels<'a>,
    /// The framebuffer index of the band's first pixel.
    pub base: usize,
}

impl Buffers for Band<'_> {
    #[inline(always)]
    fn stencil(&mut self, i: usize) -> &mut u8 {
        self.px.stencil(i - self.base)
    }
    #[inline(always)]
    fn depth(&mut self, i: usize) -> &mut u32 {
        self.px.depth(i - self.base)
    }
    #[inline(always)]
    fn color(&mut self, i: usize) -> &mut [u8; 4] {
        self.px.color(i - self.base)
    }
    #[inline(always)]
    fn colors(&mut self, i: usize, n: usize) -> &mut [[u8; 4]] {
        self.px.colors(i - self.base, n)
    }
    #[inline(always)]
    fn other_color(&mut self, _: usize) -> Option<&mut [u8; 4]> {
        // Nothing is binned while drawing to GL_FRONT_AND_BACK.
        None
    }
    #[inline(always)]
    fn pass(&mut self) {
        self.px.passed += 1;
    }
}

#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum Mode {
    /// No test, colour stored through a full mask.
    Store,
    /// No test, SRC_ALPHA / ONE_MINUS_SRC_ALPHA through a full mask.
    Over,
    /// Anything: the per-fragment operations of `fragment`.
    General,
}

/// Where a primitive's runs go, for one fragment state.
pub struct Sink<'a> {
    fs: &'a FragmentState,
    mode: Mode,
    key: u8,
    /// `over_covered` runs four pixels at a time (the CPU has AVX2).
    #[cfg_attr(not(target_arch = "x86_64"), allow(dead_code))]
    avx2: bool,
}

fn is_over(b: &Blend) -> bool {
    let (s, d) = (BlendFactor::SrcAlpha, BlendFactor::OneMinusSrcAlpha);
    b.equation == BlendEquation::Add && b.src_rgb == s && b.src_alpha == s && b.dst_rgb == d && b.dst_alpha == d
}

impl<'a> Sink<'a> {
    pub fn new(fs: &'a FragmentState, fb: &Framebuffer) -> Sink<'a> {
        Sink::with(fs, fb.draw_both)
    }

    /// [`Sink::new`] for a target drawing to two colour buffers or not.
    pub fn with(fs: &'a FragmentState, draw_both: bool) -> Sink<'a> {
        let untested = !fs.alpha_test && !fs.stencil_test && !fs.depth_test && fs.color_mask == [true; 4] && !draw_both;
        let mode = match fs.color {
            ColorOp::Replace if untested => Mode::Store,
            ColorOp::Blend(b) if untested && is_over(&b) => Mode::Over,
            _ => Mode::General,
        };
        let avx2 = cfg!(target_arch = "x86_64") && mode == Mode::Over && fragment::simd::level() == fragment::simd::Level::Avx2;
        Sink { fs, mode, key: key(fs), avx2 }
    }

    /// Is the state the untested SRC_ALPHA / ONE_MINUS_SRC_ALPHA blend
    /// ([`Sink::over_covered`] applies)?
    pub fn is_over(&self) -> bool {
        self.mode == Mode::Over
    }

    /// An OVER sink's run of a constant colour `rgb` whose alpha `a` is
    /// scaled by a coverage per pixel: pixels i0, i0 + 1, ... of `fb`,
    /// one per entry of `cov`; a pixel of coverage <= 0 gets no fragment.
    /// The same bits as [`Sink::run`] with colour (rgb, alpha_u8(a * cov))
    /// on each positive-coverage piece (AVX2: four pixels at a time).
    pub fn over_covered(&self, fb: &mut impl Buffers, i0: usize, cov: &[f64], rgb: [u8; 4], a: f64) {
        debug_assert!(self.mode == Mode::Over);
        let fix = self.fs.alpha_fix;
        let px = fb.colors(i0, cov.len());
        #[cfg_attr(not(target_arch = "x86_64"), allow(unused_mut))] // set by the AVX2 lanes only
        let mut done = 0;
        let mut passed = 0u64;
        #[cfg(target_arch = "x86_64")]
        if self.avx2 {
            // SAFETY: AVX2 is present (`with`).
            (done, passed) = unsafe { over_covered_avx2(px, cov, rgb, a, fix) };
        }
        passed += over_covered_scalar(&mut px[done..], &cov[done..], rgb, a, fix);
        fb.pass_n(passed);
    }

    /// Does the state read fragment depths? (Else `depth` is never called.)
    pub fn needs_depth(&self) -> bool {
        self.fs.depth_test
    }

    /// Runs `n` fragments at indices `i0 + k * stride` of `fb` (all inside
    /// the draw rectangle) with depth `depth(k)` (24-bit fixed point) and
    /// colour `color(k)` through the per-fragment operations.
    #[inline]
    pub fn run(&self, fb: &mut impl Buffers, i0: usize, n: usize, stride: usize, depth: impl Fn(usize) -> u32, color: impl Fn(usize) -> [u8; 4]) {
        let fix = self.fs.alpha_fix;
        match self.mode {
            Mode::Store => {
                for k in 0..n {
                    let mut c = color(k);
                    c[3] |= fix;
                    *fb.color(i0 + k * stride) = c;
                }
                fb.pass_n(n as u64);
            }
            Mode::Over => {
                for k in 0..n {
                    let d = fb.color(i0 + k * stride);
                    let mut c = over_pixel(color(k), *d);
                    c[3] |= fix;
                    *d = c;
                }
                fb.pass_n(n as u64);
            }
            Mode::General => {
                let fs = self.fs;
                macro_rules! go {
                    ($a:literal, $s:literal, $d:literal, $c:literal) => {
                        for k in 0..n {
                            fragment::fragment::<$a, $s, $d, $c>(fs, fb, i0 + k * stride, || depth(k), || color(k))
                        }
                    };
                }
                match self.key {
                    0 => go!(false, false, false, false),
                    1 => go!(true, false, false, false),
                    2 => go!(false, true, false, false),
                    3 => go!(true, true, false, false),
                    4 => go!(false, false, true, false),
                    5 => go!(true, false, true, false),
                    6 => go!(false, true, true, false),
                    7 => go!(true, true, true, false),
                    8 => go!(false, false, false, true),
                    9 => go!(true, false, false, true),
                    10 => go!(false, true, false, true),
                    11 => go!(true, true, false, true),
                    12 => go!(false, false, true, true),
                    13 => go!(true, false, true, true),
                    14 => go!(false, true, true, true),
                    _ => go!(true, true, true, true),
                }
            }
        }
    }
}

/// SRC_ALPHA, ONE_MINUS_SRC_ALPHA, ADD on 8-bit values: the real result
/// is x / 255 for an integer x, never within 1/510 of a rounding midpoint,
/// so rounding it is `(x + 127) / 255`, what `Blend::apply`'s f32
/// evaluation rounds to (blend.rs's error bound; tested below).
#[inline(always)]
#[cfg_attr(target_arch = "x86_64", allow(dead_code))]
fn over(s: [u8; 4], d: [u8; 4]) -> [u8; 4] {
    let a = s[3] as u32;
    let ia = 255 - a;
    std::array::from_fn(|ch| ((s[ch] as u32 * a + d[ch] as u32 * ia + 127) / 255) as u8)
}

/// [`over`] on one pixel's four channels at once (SSE2, the x86_64
/// baseline): the same integers, with `(v + 1 + (v >> 8)) >> 8` for
/// `v / 255` (v = x + 127 <= 65152: exact below 65280, simd.rs).
#[cfg(target_arch = "x86_64")]
#[inline(always)]
fn over_pixel(s: [u8; 4], d: [u8; 4]) -> [u8; 4] {
    use std::arch::x86_64::*;
    // SAFETY: SSE2 is part of the x86_64 baseline.
    unsafe {
        let z = _mm_setzero_si128();
        let s16 = _mm_unpacklo_epi8(_mm_cvtsi32_si128(i32::from_ne_bytes(s)), z);
        let d16 = _mm_unpacklo_epi8(_mm_cvtsi32_si128(i32::from_ne_bytes(d)), z);
        // Lane 3 (alpha) in every lane; products and sums stay below 2^16.
        let a = _mm_shufflelo_epi16(s16, 0xFF);
        let ia = _mm_sub_epi16(_mm_set1_epi16(255), a);
        let v = _mm_add_epi16(_mm_add_epi16(_mm_mullo_epi16(s16, a), _mm_mullo_epi16(d16, ia)), _mm_set1_epi16(127));
        let q = _mm_srli_epi16(_mm_add_epi16(_mm_add_epi16(v, _mm_set1_epi16(1)), _mm_srli_epi16(v, 8)), 8);
        _mm_cvtsi128_si32(_mm_packus_epi16(q, q)).to_ne_bytes()
    }
}

/// [`Sink::over_covered`] a pixel at a time, as [`Sink::run`] would
/// blend each positive-coverage pixel; returns the fragments.
#[inline(always)]
fn over_covered_scalar(px: &mut [[u8; 4]], cov: &[f64], rgb: [u8; 4], a: f64, fix: u8) -> u64 {
    let mut passed = 0;
    for (d, &c) in px.iter_mut().zip(cov) {
        if c > 0.0 {
            let mut s = rgb;
            s[3] = super::smooth::alpha_u8(a * c);
            let mut o = over_pixel(s, *d);
            o[3] |= fix;
            *d = o;
            passed += 1;
        }
    }
    passed
}

/// [`Sink::over_covered`]'s whole groups of four pixels: the alpha as
/// `smooth::alpha_u8` computes it (clamp, scale, add 1/2, truncate, in
/// f64), then `over_pixel`'s integers on 16-bit lanes; pixels of coverage
/// <= 0 keep their value. Returns the pixels done and the fragments.
#[cfg(target_arch = "x86_64")]
#[target_feature(enable = "avx2")]
unsafe fn over_covered_avx2(px: &mut [[u8; 4]], cov: &[f64], rgb: [u8; 4], a: f64, fix: u8) -> (usize, u64) {
    use std::arch::x86_64::*;
    let n = px.len().min(cov.len()) & !3;
    let (va, zero, one) = (_mm256_set1_pd(a), _mm256_setzero_pd(), _mm256_set1_pd(1.0));
    let (k255, half) = (_mm256_set1_pd(255.0), _mm256_set1_pd(0.5));
    let color = _mm_set1_epi32(i32::from_le_bytes([rgb[0], rgb[1], rgb[2], 0]));
    let fixv = _mm_set1_epi32((fix as i32) << 24);
    let (c255, c127, c1) = (_mm256_set1_epi16(255), _mm256_set1_epi16(127), _mm256_set1_epi16(1));
    // The low 32 bits of each 64-bit lane (a lane mask to pixel masks).
    let lows = _mm256_setr_epi32(0, 2, 4, 6, 0, 2, 4, 6);
    let mut passed = 0u64;
    let mut k = 0;
    while k < n {
        let c = _mm256_loadu_pd(cov.as_ptr().add(k));
        let pos = _mm256_cmp_pd::<_CMP_GT_OQ>(c, zero);
        passed += (_mm256_movemask_pd(pos) as u32).count_ones() as u64;
        let t = _mm256_min_pd(_mm256_max_pd(_mm256_mul_pd(va, c), zero), one);
        let alpha = _mm256_cvttpd_epi32(_mm256_add_pd(_mm256_mul_pd(t, k255), half));
        let src = _mm_or_si128(color, _mm_slli_epi32::<24>(alpha));
        let p = px.as_mut_ptr().add(k) as *mut __m128i;
        let dst = _mm_loadu_si128(p);
        let (s16, d16) = (_mm256_cvtepu8_epi16(src), _mm256_cvtepu8_epi16(dst));
        let a16 = _mm256_shufflehi_epi16::<0xFF>(_mm256_shufflelo_epi16::<0xFF>(s16));
        let ia = _mm256_sub_epi16(c255, a16);
        let v = _mm256_add_epi16(_mm256_add_epi16(_mm256_mullo_epi16(s16, a16), _mm256_mullo_epi16(d16, ia)), c127);
        let q = _mm256_srli_epi16::<8>(_mm256_add_epi16(_mm256_add_epi16(v, c1), _mm256_srli_epi16::<8>(v)));
        let packed = _mm256_permute4x64_epi64::<0b1000>(_mm256_packus_epi16(q, q));
        let out = _mm_or_si128(_mm256_castsi256_si128(packed), fixv);
        let keep = _mm256_castsi256_si128(_mm256_permutevar8x32_epi32(_mm256_castpd_si256(pos), lows));
        _mm_storeu_si128(p, _mm_blendv_epi8(dst, out, keep));
        k += 4;
    }
    (n, passed)
}

#[cfg(not(target_arch = "x86_64"))]
#[inline(always)]
fn over_pixel(s: [u8; 4], d: [u8; 4]) -> [u8; 4] {
    over(s, d)
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The four-pixel OVER of a covered constant colour stores what the
    /// pixel-at-a-time loop stores (`over`, equal to `Blend::apply`
    /// below) and counts the same fragments: coverages of 0, negative,
    /// tiny, above 1 and in between, alphas including 0 and 1, with and
    /// without the alpha fix.
    #[cfg(target_arch = "x86_64")]
    #[test]
    fn over_covered_avx2_matches_per_pixel() {
        if !std::arch::is_x86_feature_detected!("avx2") {
            return;
        }
        let mut seed = 77u64;
        let mut rnd = || {
            seed = seed.wrapping_mul(6364136223846793005).wrapping_add(1442695040888963407);
            seed >> 11
        };
        let mut blended = 0;
        for case in 0..20000 {
            let n = (rnd() % 23) as usize;
            let cov: Vec<f64> = (0..n)
                .map(|_| match rnd() % 8 {
                    0 => 0.0,
                    1 => -0.25,
                    2 => 1e-13,
                    3 => 1.0,
                    4 => 1.5,
                    _ => (rnd() % 100_001) as f64 / 100_000.0,
                })
                .collect();
            let a = match case % 5 {
                0 => 0.0,
                1 => 1.0,
                _ => (rnd() % 1001) as f64 / 1000.0,
            };
            let rgb = (rnd() as u32).to_le_bytes();
            let fix = if case % 3 == 0 { 255 } else { 0 };
            let dst: Vec<[u8; 4]> = (0..n).map(|_| (rnd() as u32).to_le_bytes()).collect();
            let mut want = dst.clone();
            let mut want_n = 0;
            for (d, &c) in want.iter_mut().zip(&cov) {
                if c > 0.0 {
                    let mut s = rgb;
                    s[3] = crate::render::smooth::alpha_u8(a * c);
                    *d = over(s, *d);
                    d[3] |= fix;
                    want_n += 1;
                }
            }
            let mut got = dst.clone();
            // SAFETY: AVX2 detected above.
            let (done, mut got_n) = unsafe { over_covered_avx2(&mut got, &cov, rgb, a, fix) };
            assert_eq!(done, n & !3);
            got_n += over_covered_scalar(&mut got[done..], &cov[done..], rgb, a, fix);
            assert_eq!((got, got_n), (want, want_n), "case {case}: cov {cov:?} a {a} rgb {rgb:?} fix {fix}");
            blended += want_n;
        }
        assert!(blended > 100_000, "{blended}");
    }

    /// The integer OVER equals `Blend::apply` on every source value,
    /// alpha and destination value.
    #[test]
    fn over_matches_blend_apply() {
        let (s, d) = (BlendFactor::SrcAlpha, BlendFactor::OneMinusSrcAlpha);
        let b = Blend { equation: BlendEquation::Add, src_rgb: s, dst_rgb: d, src_alpha: s, dst_alpha: d, constant: [0.0; 4] };
        for a in 0..=255u8 {
            for sv in 0..=255u8 {
                for dv in 0..=255u8 {
                    let (src, dst) = ([sv, 255 - sv, sv / 2, a], [dv, dv / 3, 255 - dv, dv.wrapping_add(a)]);
                    let want = b.apply(src, dst);
                    assert_eq!(over(src, dst), want, "src {src:?} dst {dst:?}");
                    assert_eq!(over_pixel(src, dst), want, "SSE2: src {src:?} dst {dst:?}");
                }
            }
        }
    }
}
