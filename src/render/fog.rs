//! Fog (GL 1.5 section 3.10): after texturing, each fragment's colour is
//! blended towards the fog colour by f, where f comes from the fog
//! coordinate c (the eye-space distance |z_eye|, or glFogCoord's value):
//! LINEAR (e - c) / (e - s), EXP exp(-d c), EXP2 exp(-(d c)^2), clamped to
//! [0, 1]. Alpha is unchanged.
//!
//! With GL_FOG_HINT = GL_FASTEST f is computed per vertex and interpolated
//! (the spec allows it); otherwise c is interpolated and f computed for
//! each fragment, which is exact.

use glam::Vec4;

pub const GL_EXP: u32 = 0x0800;
pub const GL_EXP2: u32 = 0x0801;
pub const GL_LINEAR: u32 = 0x2601;

#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Fog {
    pub mode: u32,
    pub density: f32,
    pub start: f32,
    pub end: f32,
    pub color: Vec4,
    /// f per fragment (exact) or per vertex (GL_FASTEST).
    pub per_fragment: bool,
}

impl Fog {
    /// f for fog coordinate c.
    #[inline]
    pub fn factor(&self, c: f32) -> f32 {
        let f = match self.mode {
            GL_LINEAR => {
                if self.end == self.start {
                    1.0
                } else {
                    (self.end - c) / (self.end - self.start)
                }
            }
            GL_EXP2 => {
                let dc = self.density * c;
                (-(dc * dc)).exp()
            }
            _ => (-self.density * c).exp(),
        };
        f.clamp(0.0, 1.0)
    }

    /// The value a vertex carries for interpolation: c, or f per vertex.
    #[inline]
    pub fn vertex_value(&self, c: f32) -> f32 {
        if self.per_fragment {
            c
        } else {
            self.factor(c)
        }
    }

    /// f of a fragment from its interpolated vertex value: computed from
    /// c per fragment, or the interpolated per-vertex f clamped.
    #[inline(always)]
    pub fn fragment_factor(&self, value: f32) -> f32 {
        if self.per_fragment {
            self.factor(value)
        } else {
            value.clamp(0.0, 1.0)
        }
    }

    /// Fogs a colour given the interpolated vertex value. The SIMD kernels
    /// repeat the blend's f32 operations lane by lane ([`lanes::mix`]):
    /// keep the two in step.
    #[inline]
    pub fn apply(&self, color: Vec4, value: f32) -> Vec4 {
        let f = self.fragment_factor(value);
        let rgb = color.truncate() * f + self.color.truncate() * (1.0 - f);
        rgb.extend(color.w)
    }
}

/// Fog in four SIMD lanes, shared by the span kernels (`fragment::simd`,
/// a pixel's channels in the lanes) and the block kernels
/// (`fragment::stamp`, one channel of four pixels in the lanes): the same
/// f32 operations as [`Fog::fragment_factor`] and [`Fog::apply`], so the
/// same bits.
#[cfg(target_arch = "x86_64")]
pub mod lanes {
    use super::{Fog, GL_EXP2, GL_LINEAR};
    use std::arch::x86_64::*;

    /// f of four fragments' fog values `v` ([`Fog::fragment_factor`] lane
    /// by lane, the same f32 operations and `clamp`): for the lanes set in
    /// `bits` (the fragments that are written; the others' f is
    /// unspecified). With `AVX` (callers inside AVX2 code) GL_EXP and
    /// GL_EXP2 take [`exp_avx2`] with libm for its doubtful lanes;
    /// otherwise libm's `expf` lane by lane.
    ///
    /// # Safety
    /// SSE2 (x86_64's baseline); with `AVX`, AVX2.
    #[inline(always)]
    pub unsafe fn factors<const AVX: bool>(fog: &Fog, v: __m128, bits: i32) -> __m128 {
        if !fog.per_fragment {
            return clamp01(v);
        }
        match fog.mode {
            GL_LINEAR if fog.end == fog.start => _mm_set1_ps(1.0),
            GL_LINEAR => clamp01(_mm_div_ps(_mm_sub_ps(_mm_set1_ps(fog.end), v), _mm_set1_ps(fog.end - fog.start))),
            _ if AVX => {
                // The exponent as `Fog::factor` forms it: -(d c)^2, or
                // (-d) c (a sign flip and a product: exact as in scalar).
                let x = if fog.mode == GL_EXP2 {
                    let dc = _mm_mul_ps(_mm_set1_ps(fog.density), v);
                    _mm_xor_ps(_mm_mul_ps(dc, dc), _mm_set1_ps(-0.0))
                } else {
                    _mm_mul_ps(_mm_set1_ps(-fog.density), v)
                };
                let (e, doubtful) = exp_avx2(x);
                let doubtful = doubtful & bits;
                let e = if doubtful == 0 {
                    e
                } else {
                    let (mut x4, mut e4) = ([0.0f32; 4], [0.0f32; 4]);
                    _mm_storeu_ps(x4.as_mut_ptr(), x);
                    _mm_storeu_ps(e4.as_mut_ptr(), e);
                    for k in 0..4 {
                        if doubtful & (1 << k) != 0 {
                            e4[k] = x4[k].exp();
                        }
                    }
                    _mm_loadu_ps(e4.as_ptr())
                };
                clamp01(e)
            }
            _ => {
                let mut v4 = [0.0f32; 4];
                _mm_storeu_ps(v4.as_mut_ptr(), v);
                let mut f = [0.0f32; 4];
                for k in 0..4 {
                    if bits & (1 << k) != 0 {
                        f[k] = fog.fragment_factor(v4[k]);
                    }
                }
                _mm_loadu_ps(f.as_ptr())
            }
        }
    }

    /// `f32::clamp(v, 0, 1)` lane by lane: NaN stays NaN and -0 stays -0
    /// (max / min return their second operand unless the first is larger /
    /// smaller).
    #[inline(always)]
    unsafe fn clamp01(v: __m128) -> __m128 {
        _mm_min_ps(_mm_set1_ps(1.0), _mm_max_ps(_mm_setzero_ps(), v))
    }

    /// Largest |doubt| (in units of 2^-29 of an f32 ulp, the f64 bits
    /// below an f32's mantissa) from a rounding midpoint at which
    /// [`exp_avx2`] hands a lane back to libm: 1/64 of an f32 ulp.
    const DOUBT: i64 = 1 << 23;

    /// e^x of four f32 lanes, rounded to f32: the same f32 as libm's
    /// `expf` (`f32::exp`) for every lane not flagged in the returned
    /// bits, which the caller gives to libm.
    ///
    /// Why it is the same: e^x is computed in f64 to a relative error
    /// under 1e-13 (x - k ln 2 with |k| <= 127 in f64, a degree-10 Taylor
    /// polynomial on |r| <= 0.35, times 2^k exactly), far under 1/128 of
    /// an f32 ulp. A lane whose f64 value lies more than 1/64 of an f32
    /// ulp from a rounding midpoint rounds to the correctly rounded
    /// e^x, as libm's does (glibc's expf errs by at most 0.502 ulp, so it
    /// can only round the other way within 0.002 ulp of a midpoint).
    /// Lanes near a midpoint (about 1 in 32), or with x outside
    /// [-87, 88] (results near f32's subnormals or overflow) or NaN, are
    /// flagged. `exp_matches_libm` checks every f32 in [-88, 89].
    ///
    /// # Safety
    /// The CPU must have AVX2.
    #[inline]
    #[target_feature(enable = "avx2")]
    pub unsafe fn exp_avx2(x: __m128) -> (__m128, i32) {
        let xd = _mm256_cvtps_pd(x);
        let k = _mm256_round_pd::<{ _MM_FROUND_TO_NEAREST_INT | _MM_FROUND_NO_EXC }>(_mm256_mul_pd(xd, _mm256_set1_pd(std::f64::consts::LOG2_E)));
        let r = _mm256_sub_pd(xd, _mm256_mul_pd(k, _mm256_set1_pd(std::f64::consts::LN_2)));
        // 1 + r + r^2/2! + ... + r^10/10!, by Estrin's scheme: pairs
        // c + c' r, then by r^2, r^4, r^8 (Horner's rule is one chain of
        // 20 dependent operations: slower by the clock than libm's four
        // independent calls, for fewer instructions).
        const C: [f64; 11] = [1.0, 1.0, 1.0 / 2.0, 1.0 / 6.0, 1.0 / 24.0, 1.0 / 120.0, 1.0 / 720.0, 1.0 / 5040.0, 1.0 / 40320.0, 1.0 / 362880.0, 1.0 / 3628800.0];
        let c = |i: usize| _mm256_set1_pd(C[i]);
        let pair = |i: usize| _mm256_add_pd(c(i), _mm256_mul_pd(c(i + 1), r));
        let r2 = _mm256_mul_pd(r, r);
        let r4 = _mm256_mul_pd(r2, r2);
        let r8 = _mm256_mul_pd(r4, r4);
        let s0 = _mm256_add_pd(pair(0), _mm256_mul_pd(pair(2), r2));
        let s1 = _mm256_add_pd(pair(4), _mm256_mul_pd(pair(6), r2));
        let s2 = _mm256_add_pd(pair(8), _mm256_mul_pd(c(10), r2));
        let p = _mm256_add_pd(_mm256_add_pd(s0, _mm256_mul_pd(s1, r4)), _mm256_mul_pd(s2, r8));
        // 2^k from its exponent bits (|k| <= 128 for x in range; lanes out
        // of range are flagged, whatever they hold).
        let ki = _mm256_cvtepi32_epi64(_mm256_cvtpd_epi32(k));
        let scale = _mm256_castsi256_pd(_mm256_slli_epi64::<52>(_mm256_add_epi64(ki, _mm256_set1_epi64x(1023))));
        let y = _mm256_mul_pd(p, scale);
        // Near a midpoint: the 29 bits below an f32 mantissa within DOUBT
        // of 2^28, i.e. low + DOUBT - 2^28 in [0, 2 DOUBT).
        let low = _mm256_and_si256(_mm256_castpd_si256(y), _mm256_set1_epi64x((1 << 29) - 1));
        let u = _mm256_add_epi64(low, _mm256_set1_epi64x(DOUBT - (1 << 28)));
        let near = _mm256_cmpeq_epi64(_mm256_srli_epi64::<24>(u), _mm256_setzero_si256());
        const _: () = assert!(2 * DOUBT == 1 << 24);
        let near = _mm256_movemask_pd(_mm256_castsi256_pd(near));
        let inside = _mm_and_ps(_mm_cmpge_ps(x, _mm_set1_ps(-87.0)), _mm_cmple_ps(x, _mm_set1_ps(88.0)));
        let outside = !_mm_movemask_ps(inside) & 15;
        (_mm256_cvtpd_ps(y), near | outside)
    }

    /// [`Fog::apply`]'s blend of colour lanes `c` towards fog colour lanes
    /// `fc` by factor lanes `f`: `c * f + fc * (1 - f)`, separate f32
    /// products and sum as glam's Vec3 does them (no FMA).
    ///
    /// # Safety
    /// SSE2 only (x86_64's baseline): always sound to call there.
    #[inline(always)]
    pub unsafe fn mix(c: __m128, f: __m128, fc: __m128) -> __m128 {
        _mm_add_ps(_mm_mul_ps(c, f), _mm_mul_ps(fc, _mm_sub_ps(_mm_set1_ps(1.0), f)))
    }

    #[cfg(test)]
    mod tests {
        use super::super::{Fog, GL_EXP, GL_EXP2, GL_LINEAR};
        use super::*;

        fn avx2() -> bool {
            is_x86_feature_detected!("avx2")
        }

        /// `exp_avx2`, with libm for its flagged lanes, against libm
        /// (`f32::exp`) on `xs`; returns how many lanes were flagged.
        fn check_exp(xs: impl Iterator<Item = f32>) -> (u64, u64) {
            let (mut n, mut flagged) = (0u64, 0u64);
            let mut buf = [0.0f32; 4];
            let mut fill = 0;
            let mut run = |b: &[f32; 4]| {
                let (e, doubt) = unsafe { exp_avx2(_mm_loadu_ps(b.as_ptr())) };
                let mut got = [0.0f32; 4];
                unsafe { _mm_storeu_ps(got.as_mut_ptr(), e) };
                for k in 0..4 {
                    if doubt & (1 << k) == 0 {
                        assert_eq!(got[k].to_bits(), b[k].exp().to_bits(), "exp({:e}) = {:e}, libm {:e}", b[k], got[k], b[k].exp());
                    } else {
                        flagged += 1;
                    }
                }
            };
            for x in xs {
                buf[fill] = x;
                fill += 1;
                n += 1;
                if fill == 4 {
                    run(&buf);
                    fill = 0;
                }
            }
            if fill > 0 {
                run(&buf);
            }
            (n, flagged)
        }

        /// Every f32 from -88 to 89 (step `stride` in the bit patterns)
        /// and the special values.
        fn sweep(stride: usize) -> (u64, u64) {
            let neg = (0.0f32.to_bits()..=(-88.0f32).to_bits() ^ (1 << 31)).step_by(stride).map(|b| f32::from_bits(b | 1 << 31));
            let pos = (0..=89.0f32.to_bits()).step_by(stride).map(f32::from_bits);
            let special = [f32::NAN, -f32::NAN, f32::INFINITY, f32::NEG_INFINITY, -87.0, 88.0, -87.5, 88.5, -103.9, -104.0, -150.0, f32::MIN_POSITIVE, -f32::MIN_POSITIVE, 1e-40, -1e-40, -0.0, 0.0];
            check_exp(neg.chain(pos).chain(special))
        }

        /// exp_avx2's unflagged lanes equal libm's expf: every 97th f32 of
        /// [-88, 89] (about 22 million) and the special values, and fewer
        /// than 1 in 16 flagged. (`exp_matches_libm_everywhere` takes all.)
        #[test]
        fn exp_matches_libm() {
            if !avx2() {
                return;
            }
            let (n, flagged) = sweep(97);
            assert!(n > 20_000_000 && flagged < n / 16, "{n} {flagged}");
        }

        /// All of [-88, 89]'s f32 (over 2 billion; minutes): run by hand
        /// with `--ignored` when exp_avx2 or the libm changes.
        #[test]
        #[ignore]
        fn exp_matches_libm_everywhere() {
            if !avx2() {
                return;
            }
            let (n, flagged) = sweep(1);
            eprintln!("{n} values, {flagged} flagged");
        }

        /// `factors` (both forms) against `Fog::fragment_factor` for each
        /// mode, per fragment and per vertex, on random fog values in and
        /// out of range (and NaN, infinities, zeros of either sign).
        #[test]
        fn factors_match_fragment_factor() {
            let mut rnd = crate::render::test_rng::below(1515, 3);
            let mut u = |lo: f32, hi: f32| lo + (hi - lo) * (rnd(1 << 24) as f32 / (1 << 24) as f32);
            let special = [f32::NAN, f32::INFINITY, f32::NEG_INFINITY, 0.0, -0.0, 1.0, 1e30, -1e30];
            for n in 0..200_000 {
                let start = u(-2.0, 5.0);
                let fog = Fog {
                    mode: [GL_LINEAR, GL_EXP, GL_EXP2, 0x1234][n % 4],
                    density: if n % 17 == 0 { 0.0 } else { u(-0.2, 3.0) },
                    start,
                    end: if n % 13 == 0 { start } else { u(-2.0, 30.0) },
                    color: glam::Vec4::ONE,
                    per_fragment: n % 5 != 0,
                };
                let scale = [1.0, 10.0, 100.0][n % 3];
                let v: [f32; 4] = std::array::from_fn(|k| if (n + k) % 29 == 0 { special[(n / 29 + k) % special.len()] } else { u(-0.5, 1.5) * scale });
                let bits = (n % 16) as i32 | 1;
                let expect = v.map(|x| fog.fragment_factor(x));
                let mut got = [[0.0f32; 4]; 2];
                unsafe {
                    _mm_storeu_ps(got[0].as_mut_ptr(), factors::<false>(&fog, _mm_loadu_ps(v.as_ptr()), bits));
                    if avx2() {
                        _mm_storeu_ps(got[1].as_mut_ptr(), avx_factors(&fog, _mm_loadu_ps(v.as_ptr()), bits));
                    } else {
                        got[1] = got[0];
                    }
                }
                for g in got {
                    for k in 0..4 {
                        if bits & (1 << k) != 0 {
                            assert_eq!(g[k].to_bits(), expect[k].to_bits(), "{fog:?} f({:e}) = {:e}, not {:e}", v[k], g[k], expect[k]);
                        }
                    }
                }
            }
        }

        #[target_feature(enable = "avx2")]
        unsafe fn avx_factors(fog: &Fog, v: __m128, bits: i32) -> __m128 {
            factors::<true>(fog, v, bits)
        }
    }
}
