//! Texture coordinates in the vertex stage (GL 1.5 sections 2.11.4 and
//! 2.10.2): glTexGen (OBJECT_LINEAR, EYE_LINEAR, SPHERE_MAP, NORMAL_MAP,
//! REFLECTION_MAP) and each unit's texture matrix.
//!
//! Eye planes are transformed by the inverse of the modelview current at
//! glTexGen (p_eye = p M^-1) and stored so. Validation prepares, for each
//! unit whose texturing is enabled, which coordinates are generated and
//! the unit's texture matrix (None when it is the identity); units that do
//! not texture carry their current coordinates through unchanged, at no
//! cost beyond a copy.

use super::enums::*;
use super::TexGenCoord;
use crate::gl::context::Context;
use crate::gl::enums::GL_INVALID_ENUM;
use crate::gl::get::Value;
use crate::render::texture::MAX_UNITS;
use glam::{Mat3, Mat4, Vec3, Vec4};

/// One unit's vertex work.
#[derive(Clone, Debug)]
pub struct VertexUnit {
    pub unit: usize,
    pub gen: [Option<TexGenCoord>; 4],
    pub matrix: Option<Mat4>,
}

#[derive(Clone, Debug, Default)]
pub struct VertexTexSetup {
    pub units: Vec<VertexUnit>,
    /// Some generated coordinate needs eye coordinates / the eye normal.
    pub needs_eye: bool,
    pub needs_normal: bool,
    pub modelview: Mat4,
    pub normal_matrix: Mat3,
    pub normalize: bool,
}

impl VertexTexSetup {
    pub fn new(c: &Context) -> VertexTexSetup {
        let mut s = VertexTexSetup::default();
        for u in 0..MAX_UNITS {
            if c.texture.unit_target(u).is_none() {
                continue;
            }
            let unit = &c.texture.units[u];
            let gen = unit.gen.map(|g| g.enabled.then_some(g));
            for g in gen.iter().flatten() {
                match g.mode {
                    GL_OBJECT_LINEAR => {}
                    GL_EYE_LINEAR => s.needs_eye = true,
                    _ => {
                        s.needs_eye = true;
                        s.needs_normal = true;
                    }
                }
            }
            let m = *c.transform.textures[u].top();
            let matrix = (m != glam::DMat4::IDENTITY).then(|| m.as_mat4());
            s.units.push(VertexUnit { unit: u, gen, matrix });
        }
        if s.needs_eye {
            s.modelview = c.transform.modelview.top().as_mat4();
            let m3 = Mat3::from_mat4(s.modelview);
            let inv = m3.inverse();
            s.normal_matrix = if inv.is_finite() { inv.transpose() } else { m3 };
            s.normalize = c.lighting.normalize || c.lighting.rescale_normal;
        }
        s
    }
}

impl Context {
    /// The texture coordinates a vertex at object position `obj` takes.
    pub fn vertex_texcoords(&self, obj: Vec4) -> [Vec4; MAX_UNITS] {
        let cur = &self.current.tex_coords;
        let mut out = [Vec4::ZERO; MAX_UNITS];
        let s = &self.texture.vertex;
        if s.units.is_empty() {
            return out;
        }
        let eye = if s.needs_eye { s.modelview * obj } else { Vec4::ZERO };
        let (n, r, m) = if s.needs_normal {
            let mut n = s.normal_matrix * Vec3::from_array(self.current.normal);
            if s.normalize {
                n = n.normalize_or_zero();
            }
            let u = if eye.w != 0.0 { eye.truncate() / eye.w } else { eye.truncate() }.normalize_or_zero();
            let r = u - 2.0 * n * n.dot(u);
            let m = 2.0 * (r.x * r.x + r.y * r.y + (r.z + 1.0) * (r.z + 1.0)).sqrt();
            (n, r, m)
        } else {
            (Vec3::ZERO, Vec3::ZERO, 1.0)
        };
        for vu in &s.units {
            let mut t = Vec4::from_array(cur[vu.unit]);
            for (k, g) in vu.gen.iter().enumerate() {
                let Some(g) = g else { continue };
                let dot = |p: [f64; 4], v: Vec4| (p[0] * v.x as f64 + p[1] * v.y as f64 + p[2] * v.z as f64 + p[3] * v.w as f64) as f32;
                t[k] = match g.mode {
                    GL_OBJECT_LINEAR => dot(g.object_plane, obj),
                    GL_EYE_LINEAR => dot(g.eye_plane, eye),
                    GL_SPHERE_MAP => {
                        let q = if m != 0.0 { [r.x, r.y][k.min(1)] / m } else { 0.0 };
                        q + 0.5
                    }
                    GL_REFLECTION_MAP => r[k.min(2)],
                    _ => n[k.min(2)],
                };
            }
            if let Some(mat) = vu.matrix {
                t = mat * t;
            }
            out[vu.unit] = t;
        }
        out
    }

    /// glTexGen (section 2.11.4). Planes arrive as four values; the mode
    /// as the first.
    pub fn tex_gen(&mut self, coord: u32, pname: u32, v: [f64; 4]) {
        if !(GL_S..=GL_Q).contains(&coord) {
            return self.set_error(GL_INVALID_ENUM);
        }
        let k = (coord - GL_S) as usize;
        let u = self.texture.active;
        match pname {
            GL_TEXTURE_GEN_MODE => {
                let m = v[0] as u32;
                let ok = match m {
                    GL_OBJECT_LINEAR | GL_EYE_LINEAR => true,
                    GL_SPHERE_MAP => k < 2,
                    GL_NORMAL_MAP | GL_REFLECTION_MAP => k < 3,
                    _ => false,
                };
                if !ok {
                    return self.set_error(GL_INVALID_ENUM);
                }
                self.texture.units[u].gen[k].mode = m;
            }
            GL_OBJECT_PLANE => self.texture.units[u].gen[k].object_plane = v,
            GL_EYE_PLANE => {
                let mv = *self.transform.modelview.top();
                let inv = mv.inverse();
                let p = glam::DVec4::from_array(v);
                // p M^-1: the row vector times the inverse.
                let e = [inv.x_axis.dot(p), inv.y_axis.dot(p), inv.z_axis.dot(p), inv.w_axis.dot(p)];
                let e = if e.iter().all(|x| x.is_finite()) { e } else { v };
                self.texture.units[u].gen[k].eye_plane = e;
            }
            _ => return self.set_error(GL_INVALID_ENUM),
        }
        self.dirty |= super::DIRTY_TEXTURE;
    }

    /// glGetTexGen.
    pub fn get_tex_gen(&mut self, coord: u32, pname: u32) -> Option<Value> {
        if !(GL_S..=GL_Q).contains(&coord) {
            self.set_error(GL_INVALID_ENUM);
            return None;
        }
        let g = &self.texture.units[self.texture.active].gen[(coord - GL_S) as usize];
        match pname {
            GL_TEXTURE_GEN_MODE => Some(Value::Ints(vec![g.mode as i64])),
            GL_OBJECT_PLANE => Some(Value::Floats(g.object_plane.to_vec())),
            GL_EYE_PLANE => Some(Value::Floats(g.eye_plane.to_vec())),
            _ => {
                self.set_error(GL_INVALID_ENUM);
                None
            }
        }
    }
}

