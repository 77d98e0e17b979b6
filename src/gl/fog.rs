//! Fog state (GL 1.5 section 3.10): glFog and its queries. The blend
//! itself is `render::fog`; each vertex carries its fog coordinate
//! (begin_end.rs).

use super::context::Context;
use super::enums::*;
use super::validate::DIRTY_FOG;
use crate::render::fog::{Fog, GL_EXP, GL_EXP2, GL_LINEAR};
use glam::Vec4;

pub const GL_FOG_INDEX: u32 = 0x0B61;
pub const GL_FOG_DENSITY: u32 = 0x0B62;
pub const GL_FOG_START: u32 = 0x0B63;
pub const GL_FOG_END: u32 = 0x0B64;
pub const GL_FOG_MODE: u32 = 0x0B65;
pub const GL_FOG_COLOR: u32 = 0x0B66;
pub const GL_FOG_COORD_SRC: u32 = 0x8450;
pub const GL_FOG_COORD: u32 = 0x8451;
pub const GL_FRAGMENT_DEPTH: u32 = 0x8452;

/// GL_FOG_BIT state.
#[derive(Clone, Debug)]
pub struct FogState {
    pub enabled: bool,
    pub mode: u32,
    pub density: f32,
    pub start: f32,
    pub end: f32,
    pub color: [f32; 4],
    pub index: f32,
    pub coord_src: u32,
    /// GL_COLOR_SUM (GL 1.4; in the fog attribute group).
    pub color_sum: bool,
}

impl Default for FogState {
    fn default() -> Self {
        FogState { enabled: false, mode: GL_EXP, density: 1.0, start: 0.0, end: 1.0, color: [0.0; 4], index: 0.0, coord_src: GL_FRAGMENT_DEPTH, color_sum: false }
    }
}

/// How many values glFog*v reads for `pname`.
pub fn fog_param_count(pname: u32) -> usize {
    if pname == GL_FOG_COLOR {
        4
    } else {
        1
    }
}

impl Context {
    /// glFog{f,i}[v]; `v` holds 1 or 4 values (colour already mapped).
    pub fn fog(&mut self, pname: u32, v: [f32; 4]) {
        let f = &mut self.fog;
        match pname {
            GL_FOG_MODE => match v[0] as u32 {
                m @ (GL_LINEAR | GL_EXP | GL_EXP2) => f.mode = m,
                _ => return self.set_error(GL_INVALID_ENUM),
            },
            GL_FOG_DENSITY if v[0] < 0.0 => return self.set_error(GL_INVALID_VALUE),
            GL_FOG_DENSITY => f.density = v[0],
            GL_FOG_START => f.start = v[0],
            GL_FOG_END => f.end = v[0],
            GL_FOG_INDEX => f.index = v[0],
            GL_FOG_COLOR => f.color = v.map(|c| c.clamp(0.0, 1.0)),
            GL_FOG_COORD_SRC => match v[0] as u32 {
                s @ (GL_FOG_COORD | GL_FRAGMENT_DEPTH) => f.coord_src = s,
                _ => return self.set_error(GL_INVALID_ENUM),
            },
            _ => return self.set_error(GL_INVALID_ENUM),
        }
        self.dirty |= DIRTY_FOG;
    }

    /// The fog the renderer applies, None when fog is off.
    pub fn fog_params(&self) -> Option<Fog> {
        let f = &self.fog;
        f.enabled.then(|| Fog {
            mode: f.mode,
            density: f.density,
            start: f.start,
            end: f.end,
            color: Vec4::from_array(f.color),
            per_fragment: self.hints.fog != GL_FASTEST,
        })
    }
}
