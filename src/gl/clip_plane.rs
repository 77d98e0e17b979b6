//! User clip planes (GL 1.5 section 2.12): glClipPlane and
//! glGetClipPlane. A plane is given in object coordinates and stored in eye
//! coordinates (transformed by the inverse of the modelview current at the
//! call); validation turns the enabled ones into clip coordinates with the
//! inverse projection, so the clipper tests every plane the same way:
//! p_eye . v_eye = (P^-T p_eye) . v_clip.

use super::context::Context;
use super::enums::*;
use super::validate::DIRTY_TRANSFORM;
use glam::{DMat4, DVec4};

/// GL_MAX_CLIP_PLANES.
pub const MAX_CLIP_PLANES: usize = 6;

#[derive(Clone, Debug, Default)]
pub struct UserClipState {
    pub planes: [DVec4; MAX_CLIP_PLANES],
    pub enabled: [bool; MAX_CLIP_PLANES],
}

impl Context {
    pub fn clip_plane(&mut self, plane: u32, eq: [f64; 4]) {
        let i = plane.wrapping_sub(GL_CLIP_PLANE0) as usize;
        if i >= MAX_CLIP_PLANES {
            return self.set_error(GL_INVALID_ENUM);
        }
        let inv = self.transform.modelview.top().inverse();
        // A singular modelview has no eye-space plane: keep the equation.
        let p = DVec4::from_array(eq);
        let e = inv.transpose() * p;
        self.user_clip.planes[i] = if e.is_finite() { e } else { p };
        self.dirty |= DIRTY_TRANSFORM;
    }

    pub fn get_clip_plane(&self, plane: u32) -> Option<[f64; 4]> {
        let i = plane.wrapping_sub(GL_CLIP_PLANE0) as usize;
        (i < MAX_CLIP_PLANES).then(|| self.user_clip.planes[i].to_array())
    }

    /// The enabled planes in clip coordinates for the projection `p`.
    pub fn clip_space_planes(&self, p: &DMat4) -> Vec<crate::render::clip::Plane> {
        let inv_t = p.inverse().transpose();
        (0..MAX_CLIP_PLANES)
            .filter(|&i| self.user_clip.enabled[i])
            .map(|i| {
                let c = inv_t * self.user_clip.planes[i];
                let n = if c.is_finite() { c } else { self.user_clip.planes[i] };
                crate::render::clip::Plane { n: n.as_vec4(), d: 0.0 }
            })
            .collect()
    }
}
