//! Texture environments and functions (GL 1.5 section 3.8.13, tables
//! 3.22 to 3.25): REPLACE, MODULATE, DECAL, BLEND, ADD by the texture's
//! base format, and COMBINE with its RGB and alpha functions (REPLACE,
//! MODULATE, ADD, ADD_SIGNED, INTERPOLATE, SUBTRACT, DOT3_RGB, DOT3_RGBA),
//! three sources each (TEXTURE, TEXTUREn of the GL 1.4 crossbar, CONSTANT,
//! PRIMARY_COLOR, PREVIOUS) with their operands, and the RGB and alpha
//! scales. Every result is clamped to [0, 1].
//!
//! Crossbar rule (GL 1.4): a unit whose combiner names the texture of a
//! unit that is disabled or has no complete texture acts as if its own
//! texturing were disabled: it passes the previous colour on.
//!
//! The environment keeps the GL enums as given (queries return them);
//! `gl::texture` has checked them.

use super::{Base, UnitSampler, MAX_UNITS};
use crate::gl::texture::enums::*;
use glam::{Vec3, Vec4};

#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Env {
    pub mode: u32,
    pub color: [f32; 4],
    pub combine_rgb: u32,
    pub combine_alpha: u32,
    pub src_rgb: [u32; 3],
    pub src_alpha: [u32; 3],
    pub op_rgb: [u32; 3],
    pub op_alpha: [u32; 3],
    pub scale_rgb: f32,
    pub scale_alpha: f32,
}

impl Default for Env {
    fn default() -> Self {
        Env {
            mode: GL_MODULATE,
            color: [0.0; 4],
            combine_rgb: GL_MODULATE,
            combine_alpha: GL_MODULATE,
            src_rgb: [GL_TEXTURE, GL_PREVIOUS, GL_CONSTANT],
            src_alpha: [GL_TEXTURE, GL_PREVIOUS, GL_CONSTANT],
            op_rgb: [GL_SRC_COLOR, GL_SRC_COLOR, GL_SRC_ALPHA],
            op_alpha: [GL_SRC_ALPHA, GL_SRC_ALPHA, GL_SRC_ALPHA],
            scale_rgb: 1.0,
            scale_alpha: 1.0,
        }
    }
}

#[inline]
fn clamp01(v: Vec4) -> Vec4 {
    v.clamp(Vec4::ZERO, Vec4::ONE)
}

impl Env {
    /// One unit's environment: `prev` is Cp/Ap (the previous unit's result,
    /// or the primary colour for the first), `cf` the primary colour,
    /// `ct` this unit's texel, `all` every unit's texel (for TEXTUREn).
    pub fn apply(&self, base: Base, prev: Vec4, cf: Vec4, ct: Vec4, all: &[Vec4; MAX_UNITS], units: &[Option<UnitSampler>; MAX_UNITS]) -> Vec4 {
        let has_color = base != Base::Alpha;
        let has_alpha = matches!(base, Base::Alpha | Base::LuminanceAlpha | Base::Intensity | Base::Rgba);
        let (pc, pa) = (prev.truncate(), prev.w);
        let (tc, ta) = (ct.truncate(), ct.w);
        let cc = Vec3::new(self.color[0], self.color[1], self.color[2]);
        let ac = self.color[3];
        let out = match self.mode {
            GL_REPLACE => (if has_color { tc } else { pc }, if has_alpha { ta } else { pa }),
            GL_MODULATE => (if has_color { pc * tc } else { pc }, if has_alpha { pa * ta } else { pa }),
            GL_DECAL => match base {
                Base::Rgb => (tc, pa),
                Base::Rgba => (pc * (1.0 - ta) + tc * ta, pa),
                _ => (pc, pa), // undefined by the spec
            },
            GL_BLEND => (
                if has_color { pc * (Vec3::ONE - tc) + cc * tc } else { pc },
                if base == Base::Intensity {
                    pa * (1.0 - ta) + ac * ta
                } else if has_alpha {
                    pa * ta
                } else {
                    pa
                },
            ),
            GL_ADD => (
                if has_color { pc + tc } else { pc },
                if base == Base::Intensity {
                    pa + ta
                } else if has_alpha {
                    pa * ta
                } else {
                    pa
                },
            ),
            GL_COMBINE => return self.combine(prev, cf, ct, all, units),
            _ => (pc, pa),
        };
        clamp01(out.0.extend(out.1))
    }

    fn combine(&self, prev: Vec4, cf: Vec4, ct: Vec4, all: &[Vec4; MAX_UNITS], units: &[Option<UnitSampler>; MAX_UNITS]) -> Vec4 {
        // The crossbar: a source naming a unit without a texture disables
        // this unit's texturing.
        let uses_dot3_rgba = self.combine_rgb == GL_DOT3_RGBA;
        let n_rgb = args(self.combine_rgb);
        let n_alpha = if uses_dot3_rgba { 0 } else { args(self.combine_alpha) };
        for &s in self.src_rgb[..n_rgb].iter().chain(&self.src_alpha[..n_alpha]) {
            if (GL_TEXTURE0..GL_TEXTURE0 + MAX_UNITS as u32).contains(&s) && units[(s - GL_TEXTURE0) as usize].is_none() {
                return prev;
            }
            if s >= GL_TEXTURE0 + MAX_UNITS as u32 && s <= GL_TEXTURE0 + 31 {
                return prev;
            }
        }
        let source = |s: u32| -> Vec4 {
            match s {
                GL_TEXTURE => ct,
                GL_CONSTANT => Vec4::from_array(self.color),
                GL_PRIMARY_COLOR => cf,
                GL_PREVIOUS => prev,
                _ => all[(s - GL_TEXTURE0) as usize],
            }
        };
        let rgb_arg = |i: usize| -> Vec3 {
            let v = source(self.src_rgb[i]);
            match self.op_rgb[i] {
                GL_SRC_COLOR => v.truncate(),
                GL_ONE_MINUS_SRC_COLOR => Vec3::ONE - v.truncate(),
                GL_SRC_ALPHA => Vec3::splat(v.w),
                _ => Vec3::splat(1.0 - v.w),
            }
        };
        let alpha_arg = |i: usize| -> f32 {
            let v = source(self.src_alpha[i]).w;
            if self.op_alpha[i] == GL_SRC_ALPHA {
                v
            } else {
                1.0 - v
            }
        };
        let a: [Vec3; 3] = [0, 1, 2].map(|i| if i < n_rgb { rgb_arg(i) } else { Vec3::ZERO });
        let (rgb, dot) = match self.combine_rgb {
            GL_REPLACE => (a[0], None),
            GL_MODULATE => (a[0] * a[1], None),
            GL_ADD => (a[0] + a[1], None),
            GL_ADD_SIGNED => (a[0] + a[1] - Vec3::splat(0.5), None),
            GL_INTERPOLATE => (a[0] * a[2] + a[1] * (Vec3::ONE - a[2]), None),
            GL_SUBTRACT => (a[0] - a[1], None),
            _ => {
                let d = 4.0 * (a[0] - Vec3::splat(0.5)).dot(a[1] - Vec3::splat(0.5));
                (Vec3::splat(d), Some(d))
            }
        };
        let rgb = (rgb * self.scale_rgb).clamp(Vec3::ZERO, Vec3::ONE);
        let alpha = if uses_dot3_rgba {
            // DOT3_RGBA writes the dot product to alpha too; the alpha
            // combiner is ignored.
            (dot.unwrap_or(0.0) * self.scale_rgb).clamp(0.0, 1.0)
        } else {
            let b: [f32; 3] = [0, 1, 2].map(|i| if i < n_alpha { alpha_arg(i) } else { 0.0 });
            let v = match self.combine_alpha {
                GL_REPLACE => b[0],
                GL_MODULATE => b[0] * b[1],
                GL_ADD => b[0] + b[1],
                GL_ADD_SIGNED => b[0] + b[1] - 0.5,
                GL_INTERPOLATE => b[0] * b[2] + b[1] * (1.0 - b[2]),
                _ => b[0] - b[1],
            };
            (v * self.scale_alpha).clamp(0.0, 1.0)
        };
        rgb.extend(alpha)
    }
}

/// How many arguments a combiner function reads.
fn args(f: u32) -> usize {
    match f {
        GL_REPLACE => 1,
        GL_INTERPOLATE => 3,
        _ => 2,
    }
}
