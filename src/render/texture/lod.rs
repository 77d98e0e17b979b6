//! log2 for the level-of-detail computation (GL 1.5 section 3.8.8,
//! λ = log2 ρ + bias): one definition shared by the general sampler
//! (`UnitSampler::sample_general`, the reference path) and the textured
//! span kernels, in a scalar form and an 8-lane AVX2 form that give the
//! same bits for every input.
//!
//! Why not libm's `log2f`: its result cannot be reproduced lane by lane in
//! SIMD, and the kernels must agree bit for bit with the reference (λ's
//! fraction is the weight between two mipmap levels). The spec does not
//! say how exact log2 is; this one is within one ulp of log2 (nearly
//! always correctly rounded: the f32 result is rounded once from an f64
//! value good to about 2^-40 relative), tested against f64's log2.
//!
//! Method: x = 2^e m with m in [√½, √2); log2 m = 2/ln 2 · atanh r with
//! r = (m - 1) / (m + 1), |r| < 0.172, as an odd series in r to r^13
//! (truncation below 2^-41), all in f64 in one fixed order of IEEE
//! operations, so the SIMD lanes repeat the scalar ones exactly. The
//! series in r² is evaluated in Estrin's order with fused multiply-adds
//! (`f64::mul_add`, a single rounding wherever it runs, so still
//! reproducible lane by lane): the chain after the division is four
//! dependent steps (r², r⁴, r⁸, then two fused multiply-adds) instead of
//! Horner's twelve, which is what the textured kernels wait for per
//! group (docs/perf-notes.md, round 7).
//!
//! The f64 series: C0 + C1 r² + ... + C6 r¹² as
//! (C0 + C1 r²) + (C2 + C3 r²) r⁴ + ((C4 + C5 r²) + C6 r⁴) r⁸.

/// 2 / (k ln 2) for k = 1, 3, ..., 13: the series of log2 m in r.
const C: [f64; 7] = {
    let ln2 = std::f64::consts::LN_2;
    [2.0 / ln2, 2.0 / (3.0 * ln2), 2.0 / (5.0 * ln2), 2.0 / (7.0 * ln2), 2.0 / (9.0 * ln2), 2.0 / (11.0 * ln2), 2.0 / (13.0 * ln2)]
};

/// Mantissa bits above √2's (1.41421354 = 0x3FB504F3): such an m is
/// halved and e raised by one.
const SQRT2_MANTISSA: u32 = 0x3504F3;

/// log2 of a positive normal f32 given its bits, plus `extra` to the
/// exponent (for subnormals scaled into the normal range).
#[inline(always)]
fn normal(bits: u32, extra: i32) -> f32 {
    let mant = bits & 0x7F_FFFF;
    let big = mant > SQRT2_MANTISSA;
    let e = (bits >> 23) as i32 - 127 + big as i32 + extra;
    let m = f32::from_bits(mant | if big { 0x3F00_0000 } else { 0x3F80_0000 }) as f64;
    let r = (m - 1.0) / (m + 1.0);
    (r.mul_add(series(r * r), e as f64)) as f32
}

/// The series in r² in Estrin's order (module documentation): the
/// operations every form repeats.
#[inline(always)]
fn series(r2: f64) -> f64 {
    let r4 = r2 * r2;
    let r8 = r4 * r4;
    let a = C[1].mul_add(r2, C[0]);
    let b = C[3].mul_add(r2, C[2]);
    let c = C[5].mul_add(r2, C[4]);
    let hi = C[6].mul_add(r4, c);
    hi.mul_add(r8, b.mul_add(r4, a))
}

/// log2 x: -inf at ±0, NaN below 0 and for NaN, +inf at +inf.
#[inline]
pub fn log2(x: f32) -> f32 {
    if x >= f32::MIN_POSITIVE && x < f32::INFINITY {
        normal(x.to_bits(), 0)
    } else if x == 0.0 {
        f32::NEG_INFINITY
    } else if x > 0.0 && x < f32::MIN_POSITIVE {
        // A subnormal: 2^23 x is normal (and exact).
        normal((x * 8388608.0).to_bits(), -23)
    } else if x == f32::INFINITY {
        x
    } else {
        f32::NAN
    }
}

/// `log2` of 8 lanes whose values are positive normal finite f32 or zero
/// (zero lanes give -inf); other lanes give unspecified values, the
/// caller checks.
///
/// # Safety
/// The CPU must have AVX2 and FMA.
#[cfg(target_arch = "x86_64")]
#[inline]
#[target_feature(enable = "avx2,fma")]
pub unsafe fn log2_8(x: std::arch::x86_64::__m256) -> std::arch::x86_64::__m256 {
    use std::arch::x86_64::*;
    let bits = _mm256_castps_si256(x);
    let mant = _mm256_and_si256(bits, _mm256_set1_epi32(0x7F_FFFF));
    // -1 where the mantissa is above √2's.
    let big = _mm256_cmpgt_epi32(mant, _mm256_set1_epi32(SQRT2_MANTISSA as i32));
    let e = _mm256_sub_epi32(_mm256_sub_epi32(_mm256_srli_epi32::<23>(bits), _mm256_set1_epi32(127)), big);
    let expo = _mm256_blendv_epi8(_mm256_set1_epi32(0x3F80_0000), _mm256_set1_epi32(0x3F00_0000), big);
    let m = _mm256_castsi256_ps(_mm256_or_si256(mant, expo));
    let lo = half(_mm256_castps256_ps128(m), _mm256_castsi256_si128(e));
    let hi = half(_mm256_extractf128_ps::<1>(m), _mm256_extracti128_si256::<1>(e));
    let v = _mm256_set_m128(hi, lo);
    let zero = _mm256_cmp_ps::<_CMP_EQ_OQ>(x, _mm256_setzero_ps());
    _mm256_blendv_ps(v, _mm256_set1_ps(f32::NEG_INFINITY), zero)
}

/// `log2_8` with the eight f64 lanes in one AVX-512 register: the same
/// operations per lane, so the same bits, in half the instructions.
///
/// # Safety
/// The CPU must have AVX2, FMA and AVX-512 F.
#[cfg(target_arch = "x86_64")]
#[inline]
#[target_feature(enable = "avx2,fma,avx512f")]
pub unsafe fn log2_8_wide(x: std::arch::x86_64::__m256) -> std::arch::x86_64::__m256 {
    use std::arch::x86_64::*;
    let bits = _mm256_castps_si256(x);
    let mant = _mm256_and_si256(bits, _mm256_set1_epi32(0x7F_FFFF));
    let big = _mm256_cmpgt_epi32(mant, _mm256_set1_epi32(SQRT2_MANTISSA as i32));
    let e = _mm256_sub_epi32(_mm256_sub_epi32(_mm256_srli_epi32::<23>(bits), _mm256_set1_epi32(127)), big);
    let expo = _mm256_blendv_epi8(_mm256_set1_epi32(0x3F80_0000), _mm256_set1_epi32(0x3F00_0000), big);
    let m = _mm512_cvtps_pd(_mm256_castsi256_ps(_mm256_or_si256(mant, expo)));
    let one = _mm512_set1_pd(1.0);
    let r = _mm512_div_pd(_mm512_sub_pd(m, one), _mm512_add_pd(m, one));
    let r2 = _mm512_mul_pd(r, r);
    // `series`.
    // (No closure for the constants: it would not inherit the target
    // features, and its intrinsics would become calls.)
    let c: [_; 7] = [_mm512_set1_pd(C[0]), _mm512_set1_pd(C[1]), _mm512_set1_pd(C[2]), _mm512_set1_pd(C[3]), _mm512_set1_pd(C[4]), _mm512_set1_pd(C[5]), _mm512_set1_pd(C[6])];
    let r4 = _mm512_mul_pd(r2, r2);
    let r8 = _mm512_mul_pd(r4, r4);
    let a = _mm512_fmadd_pd(c[1], r2, c[0]);
    let b = _mm512_fmadd_pd(c[3], r2, c[2]);
    let hi = _mm512_fmadd_pd(c[6], r4, _mm512_fmadd_pd(c[5], r2, c[4]));
    let p = _mm512_fmadd_pd(hi, r8, _mm512_fmadd_pd(b, r4, a));
    let v = _mm512_cvtpd_ps(_mm512_fmadd_pd(r, p, _mm512_cvtepi32_pd(e)));
    let zero = _mm256_cmp_ps::<_CMP_EQ_OQ>(x, _mm256_setzero_ps());
    _mm256_blendv_ps(v, _mm256_set1_ps(f32::NEG_INFINITY), zero)
}

/// Four lanes of `normal`'s f64 part: m (already in [√½, √2)) and e.
#[cfg(target_arch = "x86_64")]
#[inline]
#[target_feature(enable = "avx2,fma")]
unsafe fn half(m: std::arch::x86_64::__m128, e: std::arch::x86_64::__m128i) -> std::arch::x86_64::__m128 {
    use std::arch::x86_64::*;
    let m = _mm256_cvtps_pd(m);
    let one = _mm256_set1_pd(1.0);
    let r = _mm256_div_pd(_mm256_sub_pd(m, one), _mm256_add_pd(m, one));
    let r2 = _mm256_mul_pd(r, r);
    // `series`.
    // (No closure for the constants: it would not inherit the target
    // features, and its intrinsics would become calls.)
    let c: [_; 7] = [_mm256_set1_pd(C[0]), _mm256_set1_pd(C[1]), _mm256_set1_pd(C[2]), _mm256_set1_pd(C[3]), _mm256_set1_pd(C[4]), _mm256_set1_pd(C[5]), _mm256_set1_pd(C[6])];
    let r4 = _mm256_mul_pd(r2, r2);
    let r8 = _mm256_mul_pd(r4, r4);
    let a = _mm256_fmadd_pd(c[1], r2, c[0]);
    let b = _mm256_fmadd_pd(c[3], r2, c[2]);
    let hi = _mm256_fmadd_pd(c[6], r4, _mm256_fmadd_pd(c[5], r2, c[4]));
    let p = _mm256_fmadd_pd(hi, r8, _mm256_fmadd_pd(b, r4, a));
    _mm256_cvtpd_ps(_mm256_fmadd_pd(r, p, _mm256_cvtepi32_pd(e)))
}

#[cfg(test)]
mod tests {
    use super::*;

    fn values() -> Vec<f32> {
        let mut v = vec![0.0, -0.0, 1.0, 2.0, 0.5, 1.4142135, 1.4142136, 0.70710677, 0.7071068, f32::MIN_POSITIVE, f32::MAX, 1e-45, 3e-40, f32::INFINITY, f32::NEG_INFINITY, f32::NAN, -1.0];
        let mut seed = 11u32;
        for _ in 0..300_000 {
            seed = seed.wrapping_mul(1664525).wrapping_add(1013904223);
            v.push(f32::from_bits(seed >> 1));
            v.push((seed >> 8) as f32 / 65536.0);
        }
        // Every mantissa near 1 and near √2, in a few binades.
        for m in 0..200_000u32 {
            v.push(f32::from_bits(0x3F80_0000 + m));
            v.push(f32::from_bits(0x3F7F_FFFF - m));
            v.push(f32::from_bits(0x4135_04F3 - 100_000 + m));
        }
        v
    }

    /// Within one ulp of f64's log2 rounded to f32, and the specials.
    #[test]
    fn log2_is_within_one_ulp() {
        let mut inexact = 0;
        for x in values() {
            let got = log2(x);
            let want = (x as f64).log2() as f32;
            if want.is_nan() {
                assert!(got.is_nan(), "{x}");
                continue;
            }
            if got != want {
                inexact += 1;
                let d = (got.to_bits() as i64 - want.to_bits() as i64).abs();
                assert!(d <= 1 && got.signum() == want.signum(), "log2({x:e}) = {got:e}, want {want:e}");
            }
        }
        // Nearly always correctly rounded.
        assert!(inexact < 50, "{inexact} results not correctly rounded");
    }

    /// The 8-lane form gives the scalar bits on every normal value and zero.
    #[cfg(target_arch = "x86_64")]
    #[test]
    fn log2_8_matches_scalar() {
        use std::arch::x86_64::*;
        if !(std::arch::is_x86_feature_detected!("avx2") && std::arch::is_x86_feature_detected!("fma")) {
            return;
        }
        let v: Vec<f32> = values().into_iter().filter(|&x| x == 0.0 || (x >= f32::MIN_POSITIVE && x < f32::INFINITY)).collect();
        for c in v.chunks_exact(8) {
            let mut out = [0f32; 8];
            unsafe { _mm256_storeu_ps(out.as_mut_ptr(), log2_8(_mm256_loadu_ps(c.as_ptr()))) };
            for k in 0..8 {
                assert_eq!(out[k].to_bits(), log2(c[k]).to_bits(), "log2_8({:e})", c[k]);
            }
        }
    }

    /// The AVX-512 form too (when the CPU has it).
    #[cfg(target_arch = "x86_64")]
    #[test]
    fn log2_8_wide_matches_scalar() {
        use std::arch::x86_64::*;
        if !(std::arch::is_x86_feature_detected!("avx2") && std::arch::is_x86_feature_detected!("fma") && std::arch::is_x86_feature_detected!("avx512f")) {
            eprintln!("no AVX-512: log2_8_wide not tested");
            return;
        }
        let v: Vec<f32> = values().into_iter().filter(|&x| x == 0.0 || (x >= f32::MIN_POSITIVE && x < f32::INFINITY)).collect();
        for c in v.chunks_exact(8) {
            let mut out = [0f32; 8];
            unsafe { _mm256_storeu_ps(out.as_mut_ptr(), log2_8_wide(_mm256_loadu_ps(c.as_ptr()))) };
            for k in 0..8 {
                assert_eq!(out[k].to_bits(), log2(c[k]).to_bits(), "log2_8_wide({:e})", c[k]);
            }
        }
    }
}
