//! The lighting equation (GL 1.5 section 2.14.1), evaluated per vertex in
//! eye coordinates, in f32 like the rest of the vertex stage.
//!
//! c = e_cm + a_cm a_cs + sum over enabled lights of
//!     att_i spot_i (a_cm a_cli + (n . VP_i) d_cm d_cli + f_i (n . h_i)^s_rm s_cm s_cli)
//! with dot products clamped at 0, f_i = 1 only where n . VP_i > 0 (no
//! highlight on the far side), and alpha = d_cm's alpha. With
//! GL_SEPARATE_SPECULAR_COLOR the specular sum is a secondary colour; with
//! no texturing the colour sum adds the two clamped colours back together.

use crate::gl::lighting::{Light, Material};
use glam::{Mat3, Mat4, Vec3, Vec4};

/// A light prepared for the vertex loop.
#[derive(Clone, Debug)]
pub struct LightSetup {
    pub light: Light,
    pub positional: bool,
    /// Eye-space position (positional lights) or unit direction to the light.
    pub pos: Vec3,
    pub spot: Option<(Vec3, f32)>, // unit direction, cos(cutoff)
}

/// Derived lighting state (validate.rs builds it when lighting is on).
#[derive(Clone, Debug)]
pub struct LightingSetup {
    pub lights: Vec<LightSetup>,
    pub model_ambient: Vec4,
    pub local_viewer: bool,
    pub two_side: bool,
    pub separate_specular: bool,
    pub modelview: Mat4,
    /// Inverse transpose of the modelview's upper 3x3.
    pub normal_matrix: Mat3,
    pub normalize: bool,
    /// GL_RESCALE_NORMAL's factor (1 when off or when normalizing).
    pub rescale: f32,
}

impl LightingSetup {
    pub fn new(lights: &[Light], model_ambient: Vec4, flags: [bool; 5], modelview: Mat4) -> LightingSetup {
        let [local_viewer, two_side, separate_specular, normalize, rescale_normal] = flags;
        let m3 = Mat3::from_mat4(modelview);
        let inv = m3.inverse();
        // A singular modelview (the book's flattening glScalef(1, 0, 1))
        // has no inverse: keep normals finite and let normalization sort
        // out their length.
        let normal_matrix = if inv.is_finite() { inv.transpose() } else { m3 };
        let rescale = if rescale_normal && !normalize {
            let row = Vec3::new(inv.x_axis.z, inv.y_axis.z, inv.z_axis.z);
            let l = row.length();
            if l > 0.0 && l.is_finite() { 1.0 / l } else { 1.0 }
        } else {
            1.0
        };
        let lights = lights
            .iter()
            .filter(|l| l.enabled)
            .map(|l| {
                let positional = l.position.w != 0.0;
                let pos = if positional { l.position.truncate() / l.position.w } else { l.position.truncate().normalize_or_zero() };
                let spot = (l.spot_cutoff != 180.0).then(|| (l.spot_direction.normalize_or_zero(), l.spot_cutoff.to_radians().cos()));
                LightSetup { light: l.clone(), positional, pos, spot }
            })
            .collect();
        LightingSetup {
            lights,
            model_ambient,
            local_viewer,
            two_side,
            separate_specular,
            modelview,
            normal_matrix,
            normalize: normalize || (!normal_matrix.is_finite()),
            rescale,
        }
    }

    /// The eye-space normal for an object-space one.
    #[inline]
    pub fn eye_normal(&self, n: Vec3) -> Vec3 {
        let e = self.normal_matrix * n;
        if self.normalize {
            e.normalize_or_zero()
        } else {
            e * self.rescale
        }
    }

    /// The lit colour of a vertex at eye position `eye` with eye normal `n`
    /// (already negated for back faces), for material `m`.
    pub fn shade(&self, m: &Material, eye: Vec4, n: Vec3) -> Vec4 {
        let (p, s) = self.shade_split(m, eye, n);
        (p + s).clamp(Vec4::ZERO, Vec4::ONE)
    }

    /// The lit primary and secondary colours (2.14.1): with
    /// GL_SEPARATE_SPECULAR_COLOR the specular sum is the secondary colour
    /// (alpha 0), otherwise it is in the primary and the secondary is 0.
    /// Both are clamped; the colour sum (3.9) adds them later.
    pub fn shade_split(&self, m: &Material, eye: Vec4, n: Vec3) -> (Vec4, Vec4) {
        // x / 1 is x exactly: the usual w = 1 skips three divisions.
        let v = if eye.w != 0.0 && eye.w != 1.0 { eye.truncate() / eye.w } else { eye.truncate() };
        let mut primary = m.emission + m.ambient * self.model_ambient;
        let mut specular = Vec4::ZERO;
        for ls in &self.lights {
            let l = &ls.light;
            let (vp, att) = if ls.positional {
                let d = ls.pos - v;
                let dist = d.length();
                let [k0, k1, k2] = l.attenuation;
                let denom = k0 + k1 * dist + k2 * dist * dist;
                (if dist > 0.0 { d / dist } else { Vec3::ZERO }, if denom > 0.0 { 1.0 / denom } else { 1.0 })
            } else {
                (ls.pos, 1.0)
            };
            let spot = match ls.spot {
                None => 1.0,
                Some((dir, cos_cutoff)) => {
                    let c = (-vp).dot(dir);
                    if c >= cos_cutoff {
                        if l.spot_exponent == 0.0 { 1.0 } else { c.max(0.0).powf(l.spot_exponent) }
                    } else {
                        0.0
                    }
                }
            };
            let k = att * spot;
            if k == 0.0 {
                continue;
            }
            let ndotl = n.dot(vp);
            let mut c = m.ambient * l.ambient;
            if ndotl > 0.0 {
                c += m.diffuse * l.diffuse * ndotl;
                let eye_dir = if self.local_viewer { (-v).normalize_or_zero() } else { Vec3::Z };
                let h = (vp + eye_dir).normalize_or_zero();
                let ndoth = n.dot(h).max(0.0);
                let p = if m.shininess == 0.0 { 1.0 } else { ndoth.powf(m.shininess) };
                specular += m.specular * l.specular * (p * k);
            }
            primary += c * k;
        }
        let clamp = |c: Vec4| c.clamp(Vec4::ZERO, Vec4::ONE);
        let alpha = m.diffuse.w.clamp(0.0, 1.0);
        if self.separate_specular {
            (clamp(primary).truncate().extend(alpha), clamp(specular).truncate().extend(0.0))
        } else {
            (clamp(primary + specular).truncate().extend(alpha), Vec4::ZERO)
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The w = 1 shortcut of `shade_split` gives the division's bits: an
    /// eye position with w = 1 lights exactly as the same point scaled by
    /// 2 with w = 2 (x * 2 / 2 is x exactly), which divides. Random lights
    /// (directional, positional, attenuated, spot), materials, normals,
    /// local viewer and separate specular.
    #[test]
    fn w_one_matches_division() {
        let mut seed = 11u64;
        let mut unit = || {
            seed = seed.wrapping_mul(6364136223846793005).wrapping_add(1442695040888963407);
            (seed >> 40) as f32 / (1u64 << 24) as f32
        };
        let mut lit = 0;
        for case in 0..20_000 {
            let mut r = |lo: f32, hi: f32| lo + (hi - lo) * unit();
            let v4 = |r: &mut dyn FnMut(f32, f32) -> f32, lo: f32, hi: f32| Vec4::new(r(lo, hi), r(lo, hi), r(lo, hi), r(lo, hi));
            let lights: Vec<Light> = (0..2)
                .map(|_| Light {
                    enabled: true,
                    ambient: v4(&mut r, 0.0, 0.3),
                    diffuse: v4(&mut r, 0.0, 1.0),
                    specular: v4(&mut r, 0.0, 1.0),
                    position: Vec4::new(r(-5.0, 5.0), r(-5.0, 5.0), r(-5.0, 5.0), if r(0.0, 1.0) < 0.5 { 0.0 } else { 1.0 }),
                    spot_direction: Vec3::new(r(-1.0, 1.0), r(-1.0, 1.0), r(-1.0, 1.0)),
                    spot_exponent: if r(0.0, 1.0) < 0.5 { 0.0 } else { r(0.0, 64.0) },
                    spot_cutoff: if r(0.0, 1.0) < 0.5 { 180.0 } else { r(5.0, 90.0) },
                    attenuation: [r(0.5, 1.5), r(0.0, 0.5), r(0.0, 0.2)],
                })
                .collect();
            let m = Material { ambient: v4(&mut r, 0.0, 1.0), diffuse: v4(&mut r, 0.0, 1.0), specular: v4(&mut r, 0.0, 1.0), emission: v4(&mut r, 0.0, 0.3), shininess: r(0.0, 128.0) };
            let flags = [case % 2 == 0, false, case % 3 == 0, false, false];
            let ls = LightingSetup::new(&lights, Vec4::new(0.2, 0.2, 0.2, 1.0), flags, Mat4::IDENTITY);
            let eye = Vec3::new(r(-4.0, 4.0), r(-4.0, 4.0), r(-9.0, 1.0));
            let n = Vec3::new(r(-1.0, 1.0), r(-1.0, 1.0), r(-1.0, 1.0)).normalize_or_zero();
            let one = ls.shade_split(&m, eye.extend(1.0), n);
            let two = ls.shade_split(&m, (eye * 2.0).extend(2.0), n);
            assert_eq!([one.0.to_array(), one.1.to_array()].map(|a| a.map(f32::to_bits)), [two.0.to_array(), two.1.to_array()].map(|a| a.map(f32::to_bits)), "case {case}");
            lit += (one.0 != m.emission + m.ambient * ls.model_ambient) as usize;
        }
        assert!(lit > 10_000, "only {lit} cases lit");
    }
}
