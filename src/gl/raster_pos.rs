//! The current raster position (GL 1.5 section 2.13): glRasterPos and
//! glWindowPos (GL 1.4).
//!
//! glRasterPos treats its coordinates as a vertex: modelview to eye
//! coordinates, projection to clip coordinates; a position outside the view
//! volume (any of -w <= x, y, z <= w fails, or w <= 0) makes the raster
//! position invalid, and nothing else changes. A valid position is mapped
//! to window coordinates (w keeps the clip w), and latches the colour the
//! vertex would get (the current colour, or the lit front colour with
//! GL_LIGHTING on, through the same `LightingSetup::shade`), the eye
//! distance ||(xe, ye, ze)|| and the texture coordinates.
//!
//! glWindowPos sets the window position directly: z is clamped to [0, 1]
//! and mapped through the depth range, w = 1, the position is always
//! valid, the colour is the current colour (never lit), distance 0.
//!
//! User clip planes invalidate it like the view volume. Not yet: texture
//! coordinates latch through the texture matrices but without
//! texture-coordinate generation; the secondary colour is (0, 0, 0, 1);
//! distance ignores GL_FOG_COORDINATE_SOURCE.

use super::context::Context;
use glam::{DVec4, Vec3, Vec4};

#[derive(Clone, Debug, PartialEq)]
pub struct RasterPos {
    /// Window x, y, z and clip w.
    pub pos: [f32; 4],
    pub valid: bool,
    pub color: [f32; 4],
    pub secondary_color: [f32; 4],
    pub distance: f32,
    /// Texture coordinates per unit, through each unit's texture matrix.
    pub tex: [[f32; 4]; crate::render::texture::MAX_UNITS],
    pub index: f32,
}

impl Default for RasterPos {
    fn default() -> Self {
        RasterPos {
            pos: [0.0, 0.0, 0.0, 1.0],
            valid: true,
            color: [1.0; 4],
            secondary_color: [0.0, 0.0, 0.0, 1.0],
            distance: 0.0,
            tex: [[0.0, 0.0, 0.0, 1.0]; crate::render::texture::MAX_UNITS],
            index: 1.0,
        }
    }
}

impl Context {
    /// glRasterPos with an object-space position.
    pub fn raster_pos(&mut self, p: [f32; 4]) {
        self.validate();
        let obj = DVec4::new(p[0] as f64, p[1] as f64, p[2] as f64, p[3] as f64);
        let eye = *self.transform.modelview.top() * obj;
        let clip = *self.transform.projection.top() * eye;
        let w = clip.w;
        let user_planes_keep = (0..crate::gl::clip_plane::MAX_CLIP_PLANES)
            .filter(|&i| self.user_clip.enabled[i])
            .all(|i| self.user_clip.planes[i].dot(eye) >= 0.0);
        let inside = w > 0.0 && clip.is_finite() && [clip.x, clip.y, clip.z].iter().all(|&c| -w <= c && c <= w) && user_planes_keep;
        if !inside {
            self.raster.valid = false;
            return;
        }
        let rs = &self.derived.render;
        let [sx, sy, sz] = rs.viewport_scale;
        let [ox, oy, oz] = rs.viewport_offset;
        let color = match &self.derived.lighting {
            None => self.current.color,
            Some(ls) => {
                let n = ls.eye_normal(Vec3::from_array(self.current.normal));
                ls.shade(&self.lighting.materials[0], eye.as_vec4(), n).to_array()
            }
        };
        self.raster = RasterPos {
            pos: [(ox + sx * clip.x / w) as f32, (oy + sy * clip.y / w) as f32, (oz + sz * clip.z / w) as f32, w as f32],
            valid: true,
            color: color.map(|c| c.clamp(0.0, 1.0)),
            secondary_color: [0.0, 0.0, 0.0, 1.0],
            distance: eye.truncate().length() as f32,
            tex: self.raster_tex_coords(),
            index: self.raster.index,
        };
    }

    /// glWindowPos: window x, y and a depth in [0, 1].
    pub fn window_pos(&mut self, p: [f32; 3]) {
        let (n, f) = (self.viewport.near, self.viewport.far);
        let z = (p[2] as f64).clamp(0.0, 1.0);
        self.raster = RasterPos {
            pos: [p[0], p[1], (n + z * (f - n)) as f32, 1.0],
            valid: true,
            color: self.current.color.map(|c| c.clamp(0.0, 1.0)),
            secondary_color: [0.0, 0.0, 0.0, 1.0],
            distance: 0.0,
            tex: self.current.tex_coords,
            index: self.raster.index,
        };
    }

    /// The current texture coordinates through each unit's texture matrix
    /// (2.13; texture-coordinate generation is not applied to the raster
    /// position yet).
    fn raster_tex_coords(&self) -> [[f32; 4]; crate::render::texture::MAX_UNITS] {
        std::array::from_fn(|u| match self.transform.textures.get(u) {
            Some(stack) => (stack.top().as_mat4() * glam::Vec4::from_array(self.current.tex_coords[u])).to_array(),
            None => self.current.tex_coords[u],
        })
    }

    /// The latched colour as the fragment stage takes it.
    pub fn raster_color(&self) -> Vec4 {
        Vec4::from_array(self.raster.color)
    }
}
