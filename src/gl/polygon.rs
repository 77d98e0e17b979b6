//! Polygon state (GL 1.5 sections 3.5.2–3.5.5 and 2.6.2): glPolygonMode,
//! glPolygonOffset, glPolygonStipple / glGetPolygonStipple, glEdgeFlag.
//! The rasterizer reads them through `RenderState` (validate.rs).

use super::context::Context;
use super::enums::*;
use super::pixels::PixelModes;
use super::validate::DIRTY_RASTER;

impl Context {
    pub fn polygon_mode(&mut self, face: u32, mode: u32) {
        if !matches!(mode, GL_POINT | GL_LINE | GL_FILL) {
            return self.set_error(GL_INVALID_ENUM);
        }
        let faces: &[usize] = match face {
            GL_FRONT => &[0],
            GL_BACK => &[1],
            GL_FRONT_AND_BACK => &[0, 1],
            _ => return self.set_error(GL_INVALID_ENUM),
        };
        for &f in faces {
            self.polygon.mode[f] = mode;
        }
        self.dirty |= DIRTY_RASTER;
    }

    pub fn polygon_offset(&mut self, factor: f32, units: f32) {
        self.polygon.offset_factor = factor;
        self.polygon.offset_units = units;
        self.dirty |= DIRTY_RASTER;
    }

    pub fn polygon_stipple(&mut self, pattern: [u32; 32]) {
        self.polygon.stipple_pattern = pattern;
        self.dirty |= DIRTY_RASTER;
    }
}

/// Byte offset of bit-row `row` and the bit offset of its first pixel in a
/// GL_BITMAP image of `width` pixels laid out by `modes` (3.6.4: rows of
/// ceil(l / 8) bytes padded to the alignment; skip pixels count bits).
fn bitmap_row(modes: &PixelModes, width: usize, row: usize) -> (usize, usize) {
    let l = if modes.row_length > 0 { modes.row_length as usize } else { width };
    let a = modes.alignment as usize;
    let stride = a * l.div_ceil(8).div_ceil(a);
    ((modes.skip_rows as usize + row) * stride, modes.skip_pixels as usize)
}

/// Reads a 32x32 stipple from a GL_BITMAP image: bit x of row y.
///
/// # Safety
/// `p` must hold the image as the unpack modes lay it out.
pub unsafe fn unpack_stipple(modes: &PixelModes, p: *const u8) -> [u32; 32] {
    let mut out = [0u32; 32];
    for (y, row) in out.iter_mut().enumerate() {
        let (start, skip) = bitmap_row(modes, 32, y);
        for x in 0..32 {
            let bit = skip + x;
            let byte = *p.add(start + bit / 8);
            let shift = if modes.lsb_first { bit % 8 } else { 7 - bit % 8 };
            if byte >> shift & 1 == 1 {
                *row |= 1 << x;
            }
        }
    }
    out
}

/// Writes the stipple as a GL_BITMAP image by the pack modes.
///
/// # Safety
/// `p` must have room for the image as the pack modes lay it out.
pub unsafe fn pack_stipple(modes: &PixelModes, pattern: &[u32; 32], p: *mut u8) {
    for (y, row) in pattern.iter().enumerate() {
        let (start, skip) = bitmap_row(modes, 32, y);
        for x in 0..32 {
            let bit = skip + x;
            let byte = p.add(start + bit / 8);
            let shift = if modes.lsb_first { bit % 8 } else { 7 - bit % 8 };
            if row >> x & 1 == 1 {
                *byte |= 1 << shift;
            } else {
                *byte &= !(1 << shift);
            }
        }
    }
}
