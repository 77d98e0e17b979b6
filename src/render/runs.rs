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
        Sink { fs, mode, key: key(fs) }
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

#[cfg(not(target_arch = "x86_64"))]
#[inline(always)]
fn over_pixel(s: [u8; 4], d: [u8; 4]) -> [u8; 4] {
    over(s, d)
}

#[cfg(test)]
mod tests {
    use super::*;

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
