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
    use super::Fog;
    use std::arch::x86_64::*;

    /// f of four fragments' fog values `v` ([`Fog::fragment_factor`] lane
    /// by lane), computed only for the lanes set in `bits` (the fragments
    /// that are written); the others are 0.
    ///
    /// Safety: SSE2 (x86_64's baseline).
    #[inline(always)]
    pub unsafe fn factors(fog: &Fog, v: __m128, bits: i32) -> __m128 {
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

    /// [`Fog::apply`]'s blend of colour lanes `c` towards fog colour lanes
    /// `fc` by factor lanes `f`: `c * f + fc * (1 - f)`, separate f32
    /// products and sum as glam's Vec3 does them (no FMA).
    #[inline(always)]
    pub unsafe fn mix(c: __m128, f: __m128, fc: __m128) -> __m128 {
        _mm_add_ps(_mm_mul_ps(c, f), _mm_mul_ps(fc, _mm_sub_ps(_mm_set1_ps(1.0), f)))
    }
}
