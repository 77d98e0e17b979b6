//! glEnable/glDisable/glIsEnabled (GL 1.5 section 2.10 and table 6.x of
//! enables), and the small state setters of sections 3.5, 4.1 and 5.6
//! (cull face, front face, shade model, depth function, scissor, hints).

use super::context::Context;
use super::enums::*;
use super::lighting::MAX_LIGHTS;
use super::clip_plane::MAX_CLIP_PLANES;
use super::validate::{DIRTY_FOG, DIRTY_FRAGMENT, DIRTY_LIGHTING, DIRTY_RASTER, DIRTY_TRANSFORM};
use crate::render::fragment::CompareFunc;
use std::collections::BTreeSet;

/// Capabilities that glEnable accepts and remembers, but whose rendering is
/// not implemented yet (lighting, fog, textures, ...). glIsEnabled
/// reports them faithfully.
#[derive(Clone, Debug, Default)]
pub struct OtherCaps(pub BTreeSet<u32>);

/// Every capability of GL 1.5 kept in OtherCaps: the GL_*_SMOOTH ones
/// (validation reads them from here), and those softgl does not act on yet.
fn is_stored_cap(cap: u32) -> bool {
    matches!(
        cap,
        GL_POINT_SMOOTH
            | GL_LINE_SMOOTH
            | GL_POLYGON_SMOOTH
            | GL_TEXTURE_GEN_S
            | GL_TEXTURE_GEN_T
            | GL_TEXTURE_GEN_R
            | GL_TEXTURE_GEN_Q
            | GL_TEXTURE_1D
            | GL_TEXTURE_2D
            | GL_TEXTURE_3D
            | GL_TEXTURE_CUBE_MAP
            | GL_MULTISAMPLE
            | GL_SAMPLE_ALPHA_TO_COVERAGE
            | GL_SAMPLE_ALPHA_TO_ONE
            | GL_SAMPLE_COVERAGE
            | GL_COLOR_TABLE
            | GL_POST_CONVOLUTION_COLOR_TABLE
            | GL_POST_COLOR_MATRIX_COLOR_TABLE
            | GL_CONVOLUTION_1D
            | GL_CONVOLUTION_2D
            | GL_SEPARABLE_2D
            | GL_HISTOGRAM
            | GL_MINMAX
    )
}

impl Context {
    pub fn set_enabled(&mut self, cap: u32, on: bool) {
        if self.set_texture_enabled(cap, on) {
            return;
        }
        // glEnable(GL_VERTEX_ARRAY) and the other array capabilities: not in
        // the GL 1.5 tables, but EXT_vertex_array allowed them and programs
        // (and piglit) still use them; they act as glEnableClientState.
        if super::arrays::ArrayState::from_cap(cap, self.texture.client_active).is_some() {
            return self.client_state(cap, on);
        }
        match cap {
            GL_DEPTH_TEST => {
                self.depth.test = on;
                self.dirty |= DIRTY_FRAGMENT;
            }
            GL_SCISSOR_TEST => {
                self.scissor.test = on;
                self.dirty |= DIRTY_RASTER;
            }
            GL_CULL_FACE => {
                self.polygon.cull = on;
                self.dirty |= DIRTY_RASTER;
            }
            GL_DITHER => self.color_buffer.dither = on,
            GL_AUTO_NORMAL => self.eval.auto_normal = on,
            GL_FOG => {
                self.fog.enabled = on;
                self.dirty |= DIRTY_FOG;
            }
            GL_COLOR_SUM => {
                self.fog.color_sum = on;
                self.dirty |= DIRTY_FOG;
            }
            _ if (GL_CLIP_PLANE0..GL_CLIP_PLANE0 + MAX_CLIP_PLANES as u32).contains(&cap) => {
                self.user_clip.enabled[(cap - GL_CLIP_PLANE0) as usize] = on;
                self.dirty |= DIRTY_TRANSFORM;
            }
            GL_MAP1_COLOR_4..=GL_MAP1_VERTEX_4 => self.eval.enabled1[(cap - GL_MAP1_COLOR_4) as usize] = on,
            GL_MAP2_COLOR_4..=GL_MAP2_VERTEX_4 => self.eval.enabled2[(cap - GL_MAP2_COLOR_4) as usize] = on,
            GL_LIGHTING => {
                self.lighting.enabled = on;
                self.dirty |= DIRTY_LIGHTING;
            }
            _ if (GL_LIGHT0..GL_LIGHT0 + MAX_LIGHTS as u32).contains(&cap) => {
                self.lighting.lights[(cap - GL_LIGHT0) as usize].enabled = on;
                self.dirty |= DIRTY_LIGHTING;
            }
            GL_COLOR_MATERIAL => {
                self.lighting.color_material = on;
                // Enabling it applies the current colour at once (2.14.3).
                self.apply_color_material();
            }
            GL_NORMALIZE => {
                self.lighting.normalize = on;
                self.dirty |= DIRTY_LIGHTING;
            }
            GL_RESCALE_NORMAL => {
                self.lighting.rescale_normal = on;
                self.dirty |= DIRTY_LIGHTING;
            }
            GL_ALPHA_TEST | GL_STENCIL_TEST | GL_BLEND | GL_COLOR_LOGIC_OP | GL_INDEX_LOGIC_OP => {
                let cb = &mut self.color_buffer;
                *match cap {
                    GL_ALPHA_TEST => &mut cb.alpha_test,
                    GL_STENCIL_TEST => &mut self.stencil.test,
                    GL_BLEND => &mut cb.blend,
                    GL_COLOR_LOGIC_OP => &mut cb.color_logic_op,
                    _ => &mut cb.index_logic_op,
                } = on;
                self.dirty |= DIRTY_FRAGMENT;
            }
            GL_LINE_STIPPLE => {
                self.line.stipple = on;
                self.dirty |= DIRTY_RASTER;
            }
            GL_POLYGON_STIPPLE => {
                self.polygon.stipple = on;
                self.dirty |= DIRTY_RASTER;
            }
            GL_POLYGON_OFFSET_FILL => {
                self.polygon.offset_fill = on;
                self.dirty |= DIRTY_RASTER;
            }
            GL_POLYGON_OFFSET_LINE => {
                self.polygon.offset_line = on;
                self.dirty |= DIRTY_RASTER;
            }
            GL_POLYGON_OFFSET_POINT => {
                self.polygon.offset_point = on;
                self.dirty |= DIRTY_RASTER;
            }
            _ if is_stored_cap(cap) => {
                if on {
                    self.other_caps.0.insert(cap);
                } else {
                    self.other_caps.0.remove(&cap);
                }
                // GL_*_SMOOTH: validation derives the antialiasing state.
                self.dirty |= DIRTY_RASTER;
            }
            _ => self.set_error(GL_INVALID_ENUM),
        }
    }

    /// glIsEnabled; None for an invalid capability.
    pub fn is_enabled(&self, cap: u32) -> Option<bool> {
        if let Some(on) = self.texture_is_enabled(cap) {
            return Some(on);
        }
        if let Some(on) = self.client_state_enabled(cap) {
            return Some(on);
        }
        Some(match cap {
            GL_DEPTH_TEST => self.depth.test,
            GL_SCISSOR_TEST => self.scissor.test,
            GL_CULL_FACE => self.polygon.cull,
            GL_DITHER => self.color_buffer.dither,
            GL_ALPHA_TEST => self.color_buffer.alpha_test,
            GL_STENCIL_TEST => self.stencil.test,
            GL_BLEND => self.color_buffer.blend,
            GL_COLOR_LOGIC_OP => self.color_buffer.color_logic_op,
            GL_INDEX_LOGIC_OP => self.color_buffer.index_logic_op,
            GL_LINE_STIPPLE => self.line.stipple,
            GL_POLYGON_STIPPLE => self.polygon.stipple,
            GL_POLYGON_OFFSET_FILL => self.polygon.offset_fill,
            GL_POLYGON_OFFSET_LINE => self.polygon.offset_line,
            GL_POLYGON_OFFSET_POINT => self.polygon.offset_point,
            GL_LIGHTING => self.lighting.enabled,
            GL_AUTO_NORMAL => self.eval.auto_normal,
            GL_FOG => self.fog.enabled,
            GL_COLOR_SUM => self.fog.color_sum,
            _ if (GL_CLIP_PLANE0..GL_CLIP_PLANE0 + MAX_CLIP_PLANES as u32).contains(&cap) => {
                self.user_clip.enabled[(cap - GL_CLIP_PLANE0) as usize]
            }
            GL_MAP1_COLOR_4..=GL_MAP1_VERTEX_4 => self.eval.enabled1[(cap - GL_MAP1_COLOR_4) as usize],
            GL_MAP2_COLOR_4..=GL_MAP2_VERTEX_4 => self.eval.enabled2[(cap - GL_MAP2_COLOR_4) as usize],
            _ if (GL_LIGHT0..GL_LIGHT0 + MAX_LIGHTS as u32).contains(&cap) => self.lighting.lights[(cap - GL_LIGHT0) as usize].enabled,
            GL_COLOR_MATERIAL => self.lighting.color_material,
            GL_NORMALIZE => self.lighting.normalize,
            GL_RESCALE_NORMAL => self.lighting.rescale_normal,
            _ if is_stored_cap(cap) => self.other_caps.0.contains(&cap),
            _ => return None,
        })
    }

    pub fn cull_face(&mut self, mode: u32) {
        match mode {
            GL_FRONT | GL_BACK | GL_FRONT_AND_BACK => {
                self.polygon.cull_mode = mode;
                self.dirty |= DIRTY_RASTER;
            }
            _ => self.set_error(GL_INVALID_ENUM),
        }
    }

    pub fn front_face(&mut self, mode: u32) {
        match mode {
            GL_CW | GL_CCW => {
                self.polygon.front_face = mode;
                self.dirty |= DIRTY_RASTER;
            }
            _ => self.set_error(GL_INVALID_ENUM),
        }
    }

    pub fn set_shade_model(&mut self, mode: u32) {
        match mode {
            GL_FLAT | GL_SMOOTH => {
                self.shade_model = mode;
                self.dirty |= DIRTY_RASTER;
            }
            _ => self.set_error(GL_INVALID_ENUM),
        }
    }

    pub fn depth_func(&mut self, func: u32) {
        match CompareFunc::from_gl(func) {
            Some(f) => {
                self.depth.func = f;
                self.dirty |= DIRTY_FRAGMENT;
            }
            None => self.set_error(GL_INVALID_ENUM),
        }
    }

    pub fn set_scissor(&mut self, x: i32, y: i32, w: i32, h: i32) {
        if w < 0 || h < 0 {
            return self.set_error(GL_INVALID_VALUE);
        }
        self.scissor.x = x;
        self.scissor.y = y;
        self.scissor.width = w;
        self.scissor.height = h;
        self.dirty |= DIRTY_RASTER;
    }

    /// glPointParameter (GL 1.4, section 3.3).
    pub fn point_parameter(&mut self, pname: u32, v: [f32; 3]) {
        let p = &mut self.point;
        match pname {
            0x8126 | 0x8127 | 0x8128 if v[0] < 0.0 => return self.set_error(GL_INVALID_VALUE),
            0x8126 /* GL_POINT_SIZE_MIN */ => p.size_min = v[0],
            0x8127 /* GL_POINT_SIZE_MAX */ => p.size_max = v[0],
            0x8128 /* GL_POINT_FADE_THRESHOLD_SIZE */ => p.fade_threshold = v[0],
            0x8129 /* GL_POINT_DISTANCE_ATTENUATION */ => p.attenuation = v,
            _ => return self.set_error(GL_INVALID_ENUM),
        }
        self.dirty |= DIRTY_RASTER; // the fade threshold (smooth points)
    }

    /// glHint (section 5.6).
    pub fn hint(&mut self, target: u32, mode: u32) {
        if !matches!(mode, GL_FASTEST | GL_NICEST | GL_DONT_CARE) {
            return self.set_error(GL_INVALID_ENUM);
        }
        let h = &mut self.hints;
        let slot = match target {
            GL_PERSPECTIVE_CORRECTION_HINT => &mut h.perspective_correction,
            GL_POINT_SMOOTH_HINT => &mut h.point_smooth,
            GL_LINE_SMOOTH_HINT => &mut h.line_smooth,
            GL_POLYGON_SMOOTH_HINT => &mut h.polygon_smooth,
            GL_FOG_HINT => &mut h.fog,
            GL_GENERATE_MIPMAP_HINT => &mut h.generate_mipmap,
            GL_TEXTURE_COMPRESSION_HINT => &mut h.texture_compression,
            _ => return self.set_error(GL_INVALID_ENUM),
        };
        *slot = mode;
        // GL_FOG_HINT picks per-vertex or per-fragment fog; the smooth hints
        // pick the coverage quality.
        self.dirty |= DIRTY_FOG | DIRTY_RASTER;
    }
}
