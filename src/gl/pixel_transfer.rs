//! Pixel transfer (GL 1.5 section 3.6.3, glPixelTransfer and glPixelMap;
//! section 3.6.5, the operations) and glPixelZoom (section 3.6.4): the
//! GL_PIXEL_MODE_BIT state and the operations glDrawPixels, glReadPixels
//! and glCopyPixels apply, in the spec's order:
//!
//! - RGBA groups: scale and bias per component; then, with GL_MAP_COLOR,
//!   each component clamped to [0, 1] and looked up in its X_TO_X map
//!   (entry round(c (size - 1))); final conversion clamps to [0, 1].
//! - Depth: scale and bias, then clamped to [0, 1].
//! - Colour indices: shifted by INDEX_SHIFT (left if positive) and offset
//!   by INDEX_OFFSET; in RGBA mode, when the groups become fragments, each
//!   index is converted through the I_TO_R/G/B/A maps (the integer part
//!   ANDed with size - 1). RGBA scale, bias and MAP_COLOR do not apply to
//!   these converted groups (they come later in the spec's figure 3.7).
//! - Stencil indices: shift and offset; with GL_MAP_STENCIL, looked up in
//!   S_TO_S. The caller masks the result to the stencil bits.
//!
//! The ARB_imaging stages (colour tables, convolution, colour matrix,
//! histogram, minmax) come after the MAP_COLOR lookup, in `imaging`; their
//! post-convolution and post-colour-matrix scale and bias are set here.

use super::context::Context;
use super::enums::*;

/// GL_MAX_PIXEL_MAP_TABLE.
pub const MAX_PIXEL_MAP_TABLE: usize = 256;

/// The ten maps, in enum order from GL_PIXEL_MAP_I_TO_I.
pub const MAP_COUNT: usize = 10;

#[derive(Clone, Debug, PartialEq)]
pub struct PixelTransfer {
    /// RED/GREEN/BLUE/ALPHA_SCALE and _BIAS.
    pub scale: [f32; 4],
    pub bias: [f32; 4],
    pub depth_scale: f32,
    pub depth_bias: f32,
    pub index_shift: i32,
    pub index_offset: i32,
    pub map_color: bool,
    pub map_stencil: bool,
    /// glPixelZoom.
    pub zoom: [f32; 2],
    /// The maps (each at least one entry; initially one 0).
    pub maps: [Vec<f32>; MAP_COUNT],
    /// ARB_imaging: POST_CONVOLUTION_c_SCALE/_BIAS and
    /// POST_COLOR_MATRIX_c_SCALE/_BIAS.
    pub post_convolution_scale: [f32; 4],
    pub post_convolution_bias: [f32; 4],
    pub post_color_matrix_scale: [f32; 4],
    pub post_color_matrix_bias: [f32; 4],
}

impl Default for PixelTransfer {
    fn default() -> Self {
        PixelTransfer {
            scale: [1.0; 4],
            bias: [0.0; 4],
            depth_scale: 1.0,
            depth_bias: 0.0,
            index_shift: 0,
            index_offset: 0,
            map_color: false,
            map_stencil: false,
            zoom: [1.0, 1.0],
            maps: std::array::from_fn(|_| vec![0.0]),
            post_convolution_scale: [1.0; 4],
            post_convolution_bias: [0.0; 4],
            post_color_matrix_scale: [1.0; 4],
            post_color_matrix_bias: [0.0; 4],
        }
    }
}

/// Index of a map enum in `maps`.
pub fn map_index(map: u32) -> Option<usize> {
    (GL_PIXEL_MAP_I_TO_I..=GL_PIXEL_MAP_A_TO_A).contains(&map).then(|| (map - GL_PIXEL_MAP_I_TO_I) as usize)
}

/// Do a map's entries hold colour components (as opposed to indices)?
pub fn is_color_map(map: u32) -> bool {
    map != GL_PIXEL_MAP_I_TO_I && map != GL_PIXEL_MAP_S_TO_S
}

/// Does a map take an index (its size must then be a power of two)?
fn is_index_input(map: u32) -> bool {
    (GL_PIXEL_MAP_I_TO_I..=GL_PIXEL_MAP_I_TO_A).contains(&map)
}

impl PixelTransfer {
    /// Entry of `map` for index `i` (ANDed with size - 1).
    #[inline]
    fn lookup_index(&self, map: usize, i: f64) -> f32 {
        let m = &self.maps[map];
        if m.is_empty() {
            return 0.0;
        }
        let k = (i.floor() as i64 & (m.len() as i64 - 1)) as usize;
        m[k]
    }

    #[inline]
    fn lookup_color(&self, map: usize, c: f32) -> f32 {
        let m = &self.maps[map];
        if m.is_empty() {
            return 0.0;
        }
        let k = (c.clamp(0.0, 1.0) * (m.len() - 1) as f32).round() as usize;
        m[k.min(m.len() - 1)]
    }

    /// Do the RGBA operations change anything?
    pub fn color_is_identity(&self) -> bool {
        self.scale == [1.0; 4] && self.bias == [0.0; 4] && !self.map_color
    }

    pub fn depth_is_identity(&self) -> bool {
        self.depth_scale == 1.0 && self.depth_bias == 0.0
    }

    /// Scale, bias, MAP_COLOR and final conversion (clamp) of RGBA groups.
    pub fn color(&self, px: &mut [[f32; 4]]) {
        self.scale_bias_map(px);
        for c in px.iter_mut() {
            for v in c.iter_mut() {
                *v = v.clamp(0.0, 1.0);
            }
        }
    }

    /// Scale, bias and MAP_COLOR of RGBA groups, without the final clamp
    /// (the imaging stages come between them).
    pub fn scale_bias_map(&self, px: &mut [[f32; 4]]) {
        let identity_sb = self.scale == [1.0; 4] && self.bias == [0.0; 4];
        for c in px.iter_mut() {
            if !identity_sb {
                for (k, v) in c.iter_mut().enumerate() {
                    *v = *v * self.scale[k] + self.bias[k];
                }
            }
            if self.map_color {
                for (k, v) in c.iter_mut().enumerate() {
                    // R_TO_R .. A_TO_A are maps 6 .. 9.
                    *v = self.lookup_color(6 + k, *v);
                }
            }
        }
    }

    /// Scale, bias and clamp of depth values.
    pub fn depth(&self, d: f64) -> f64 {
        (d * self.depth_scale as f64 + self.depth_bias as f64).clamp(0.0, 1.0)
    }

    /// Index shift and offset (the fixed-point arithmetic of "Arithmetic
    /// on indices", in f64: exact for the integer indices GL deals in).
    #[inline]
    pub fn shift_offset(&self, i: f64) -> f64 {
        i * (2f64).powi(self.index_shift) + self.index_offset as f64
    }

    /// A colour index to RGBA through the I_TO_X maps (after shift/offset).
    pub fn index_to_rgba(&self, i: f64) -> [f32; 4] {
        let i = self.shift_offset(i);
        // I_TO_R .. I_TO_A are maps 2 .. 5.
        [2, 3, 4, 5].map(|m| self.lookup_index(m, i).clamp(0.0, 1.0))
    }

    /// A stencil index through shift, offset and MAP_STENCIL: the integer
    /// result (the caller masks it to the stencil bits).
    pub fn stencil(&self, i: f64) -> i64 {
        let mut i = self.shift_offset(i);
        if self.map_stencil {
            i = self.lookup_index(1, i).round() as f64;
        }
        i.floor() as i64
    }
}

impl Context {
    /// glPixelTransfer{if}.
    pub fn pixel_transfer(&mut self, pname: u32, v: f64) {
        let t = &mut self.pixel;
        let f = v as f32;
        match pname {
            GL_MAP_COLOR => t.map_color = v != 0.0,
            GL_MAP_STENCIL => t.map_stencil = v != 0.0,
            GL_INDEX_SHIFT => t.index_shift = v.round().clamp(-64.0, 64.0) as i32,
            GL_INDEX_OFFSET => t.index_offset = v.round().clamp(i32::MIN as f64, i32::MAX as f64) as i32,
            GL_RED_SCALE => t.scale[0] = f,
            GL_GREEN_SCALE => t.scale[1] = f,
            GL_BLUE_SCALE => t.scale[2] = f,
            GL_ALPHA_SCALE => t.scale[3] = f,
            GL_RED_BIAS => t.bias[0] = f,
            GL_GREEN_BIAS => t.bias[1] = f,
            GL_BLUE_BIAS => t.bias[2] = f,
            GL_ALPHA_BIAS => t.bias[3] = f,
            GL_DEPTH_SCALE => t.depth_scale = f,
            GL_DEPTH_BIAS => t.depth_bias = f,
            0x801C..=0x801F => t.post_convolution_scale[(pname - 0x801C) as usize] = f,
            0x8020..=0x8023 => t.post_convolution_bias[(pname - 0x8020) as usize] = f,
            0x80B4..=0x80B7 => t.post_color_matrix_scale[(pname - 0x80B4) as usize] = f,
            0x80B8..=0x80BB => t.post_color_matrix_bias[(pname - 0x80B8) as usize] = f,
            _ => self.set_error(GL_INVALID_ENUM),
        }
    }

    /// glPixelMap: `values` already converted to floats (colour maps) or
    /// index values (I_TO_I, S_TO_S). Index-input maps need a power-of-two
    /// size.
    pub fn pixel_map(&mut self, map: u32, values: &[f32]) {
        let Some(m) = map_index(map) else { return self.set_error(GL_INVALID_ENUM) };
        let n = values.len();
        if !(1..=MAX_PIXEL_MAP_TABLE).contains(&n) || (is_index_input(map) || map == GL_PIXEL_MAP_S_TO_S) && !n.is_power_of_two() {
            return self.set_error(GL_INVALID_VALUE);
        }
        let values = if is_color_map(map) { values.iter().map(|v| v.clamp(0.0, 1.0)).collect() } else { values.to_vec() };
        self.pixel.maps[m] = values;
    }

    /// glPixelZoom.
    pub fn pixel_zoom(&mut self, x: f32, y: f32) {
        self.pixel.zoom = [x, y];
    }

    /// glGetPixelMap: the map's entries, or None (INVALID_ENUM).
    pub fn get_pixel_map(&self, map: u32) -> Option<&[f32]> {
        map_index(map).map(|m| &self.pixel.maps[m][..])
    }
}

/// The values of a glPixelMapuiv/usv call as floats: colour maps convert
/// as unsigned normalized integers (table 2.9), index maps keep the value.
pub fn map_values_from_uint(map: u32, values: &[u32], bits: u32) -> Vec<f32> {
    let max = ((1u64 << bits) - 1) as f64;
    values.iter().map(|&v| if is_color_map(map) { (v as f64 / max) as f32 } else { v as f32 }).collect()
}

/// glGetPixelMapuiv/usv's conversion: colour entries to unsigned
/// normalized integers, index entries rounded.
pub fn map_value_to_uint(map: u32, v: f32, bits: u32) -> u32 {
    let max = ((1u64 << bits) - 1) as f64;
    if is_color_map(map) {
        (v.clamp(0.0, 1.0) as f64 * max).round() as u32
    } else {
        (v as f64).round().clamp(0.0, max) as u32
    }
}
