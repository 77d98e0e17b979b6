//! glClear (GL 1.5 section 4.2.3): fills the selected buffers with their
//! clear values inside the scissor box (the viewport does not apply),
//! through the colour, depth and stencil write masks. Dithering does not
//! change the 8-bit result.

use super::context::Context;
use super::enums::*;
use crate::framebuffer::Framebuffer;
use crate::render::fragment::{color_to_u8, depth_to_fixed};
use glam::Vec4;

const CLEAR_BITS: u32 = GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT | GL_STENCIL_BUFFER_BIT | GL_ACCUM_BUFFER_BIT;

/// Rectangles of at least this many pixels are cleared in bands of
/// [`BAND_ROWS`] rows shared among the rasterizer's threads (round 7):
/// smaller ones cost less than waking a worker.
const PARALLEL_PIXELS: usize = 1 << 18;
const BAND_ROWS: usize = 32;

/// Applies `f` to each row slice [x0, x1) of the rectangle in a buffer,
/// in bands of rows on `threads` threads when the rectangle is large (each
/// row is written by one call, so the result does not depend on them).
fn rows<T: Send>(threads: usize, buf: &mut [T], width: usize, r: crate::framebuffer::Rect, f: impl Fn(&mut [T]) + Sync) {
    let (x0, x1, y0, y1) = (r.x0 as usize, r.x1 as usize, r.y0 as usize, r.y1 as usize);
    let threads = if (x1 - x0) * (y1 - y0) >= PARALLEL_PIXELS { threads } else { 1 };
    crate::render::pool::for_pieces(threads, &mut buf[y0 * width..y1 * width], BAND_ROWS * width, |_, band| {
        for row in band.chunks_mut(width) {
            f(&mut row[x0..x1]);
        }
    });
}

impl Context {
    pub fn clear(&mut self, mask: u32) {
        if mask & !CLEAR_BITS != 0 {
            return self.set_error(GL_INVALID_VALUE);
        }
        let r = self.scissored_surface();
        if r.is_empty() {
            return;
        }
        // Each draw buffer is cleared (4.2.3): both for FRONT_AND_BACK.
        self.sync_draw_buffer();
        let threads = self.derived.render.threads;
        let fb: &mut Framebuffer = &mut self.fb;
        let w = fb.width;
        if mask & GL_COLOR_BUFFER_BIT != 0 {
            let mut value = color_to_u8(Vec4::from_array(self.color_buffer.clear));
            let mut m = if self.color_buffer.draw_buffer == 0 { [false; 4] } else { self.color_buffer.write_mask };
            if fb.config.alpha_bits == 0 {
                // No alpha: stored alpha stays 255, so writing 255 is the
                // same as not writing it, and keeps the whole-row fill.
                value[3] = 255;
                m[3] = m[0] || m[1] || m[2];
            }
            for color in fb.draw_colors() {
                if m == [true; 4] {
                    rows(threads, &mut color[..], w, r, |row| row.fill(value));
                } else if m != [false; 4] {
                    rows(threads, &mut color[..], w, r, |row| {
                        for px in row {
                            for ch in 0..4 {
                                if m[ch] {
                                    px[ch] = value[ch];
                                }
                            }
                        }
                    });
                }
            }
        }
        if mask & GL_DEPTH_BUFFER_BIT != 0 && fb.has_depth() && self.depth.write_mask {
            let value = depth_to_fixed(self.depth.clear);
            rows(threads, &mut fb.depth, w, r, |row| row.fill(value));
        }
        if mask & GL_STENCIL_BUFFER_BIT != 0 && fb.has_stencil() {
            let bits = fb.config.stencil_bits as u32;
            let full = (1u32 << bits) - 1;
            let value = (self.stencil.clear as u32 & full) as u8;
            let m = (self.stencil.write_mask & full) as u8;
            if m == full as u8 {
                rows(threads, &mut fb.stencil, w, r, |row| row.fill(value));
            } else if m != 0 {
                rows(threads, &mut fb.stencil, w, r, |row| {
                    for s in row {
                        *s = (*s & !m) | (value & m);
                    }
                });
            }
        }
        if mask & GL_ACCUM_BUFFER_BIT != 0 {
            self.clear_accum_buffer(r);
        }
    }
}
