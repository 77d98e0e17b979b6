//! glClear (GL 1.5 section 4.2.3): fills the selected buffers with their
//! clear values inside the scissor box (the viewport does not apply),
//! through the colour, depth and stencil write masks. Dithering does not
//! change the 8-bit result.
//!
//! Large clears are written in bands of rows by the rasterizer's threads;
//! while they bin triangles, a large clear is instead recorded for the
//! next flight of triangles, whose workers write each band's rows just
//! before they draw into it (round 11: `render::tile::defer_clear`), and
//! since round 13 without waiting for the batches binned before it.

use super::context::Context;
use super::enums::*;
use crate::framebuffer::clear::{self as fill, Clear};
use crate::framebuffer::Framebuffer;
use crate::render::fragment::{color_to_u8, depth_to_fixed};
use glam::Vec4;
use std::sync::atomic::{AtomicUsize, Ordering};
use std::sync::Mutex;

const CLEAR_BITS: u32 = GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT | GL_STENCIL_BUFFER_BIT | GL_ACCUM_BUFFER_BIT;

/// Rectangles of at least this many pixels are cleared in bands of
/// [`BAND_ROWS`] rows shared among the rasterizer's threads (round 7):
/// smaller ones cost less than waking a worker.
const PARALLEL_PIXELS: usize = 1 << 18;
const BAND_ROWS: usize = 32;

/// A band of rows to fill, run by whichever thread takes it.
type Band<'a> = Box<dyn FnOnce() + Send + 'a>;

/// Applies `f` to each row slice [x0, x1) of the rectangle in a buffer:
/// at once when the rectangle is small or there is one thread, else as
/// bands of [`BAND_ROWS`] rows added to `bands`, which [`run_bands`] hands
/// to the threads in one go for every buffer the glClear names (round 9:
/// one hand-off a clear, not one a buffer). Each row is written by one
/// call, so the result does not depend on the thread count.
fn rows<'a, T: Send + 'a>(bands: &mut Vec<Band<'a>>, threads: usize, buf: &'a mut [T], width: usize, r: crate::framebuffer::Rect, f: impl Fn(&mut [T]) + Copy + Send + 'a) {
    let (x0, x1, y0, y1) = (r.x0 as usize, r.x1 as usize, r.y0 as usize, r.y1 as usize);
    // Whole rows: the band is one contiguous run.
    let each = move |band: &mut [T]| fill::each_row(band, width, x0, x1, f);
    let buf = &mut buf[y0 * width..y1 * width];
    if threads <= 1 || (x1 - x0) * (y1 - y0) < PARALLEL_PIXELS {
        return each(buf);
    }
    for band in buf.chunks_mut(BAND_ROWS * width) {
        bands.push(Box::new(move || each(band)));
    }
}

/// Runs the gathered bands on `threads` threads, each band once.
fn run_bands(threads: usize, bands: Vec<Band<'_>>) {
    if bands.is_empty() {
        return;
    }
    let slots: Vec<Mutex<Option<Band>>> = bands.into_iter().map(|b| Mutex::new(Some(b))).collect();
    let next = AtomicUsize::new(0);
    crate::render::pool::run(threads, &|| loop {
        let k = next.fetch_add(1, Ordering::Relaxed);
        let Some(slot) = slots.get(k) else { break };
        // Uncontended: each slot is taken once.
        let band = slot.lock().unwrap_or_else(|e| e.into_inner()).take();
        if let Some(band) = band {
            band();
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
        // `Command::Clear` does not sync first (round 13): a clear
        // recorded for the next flight leaves the batches binned before it
        // to the workers; every other case syncs below.
        self.sync_draw_buffer_keeping_batch();
        let threads = self.derived.render.threads;
        let (has_depth, has_stencil) = (self.fb.has_depth(), self.fb.has_stencil());
        let config = self.fb.config;
        let mut c = Clear { rect: r, color: None, depth: None, stencil: None };
        if mask & GL_COLOR_BUFFER_BIT != 0 {
            let mut value = color_to_u8(Vec4::from_array(self.color_buffer.clear));
            let mut m = if self.color_buffer.draw_buffer == 0 { [false; 4] } else { self.color_buffer.write_mask };
            if config.alpha_bits == 0 {
                // No alpha: stored alpha stays 255, so writing 255 is the
                // same as not writing it, and keeps the whole-row fill.
                value[3] = 255;
                m[3] = m[0] || m[1] || m[2];
            }
            c.color = (m != [false; 4]).then_some((value, m));
        }
        if mask & GL_DEPTH_BUFFER_BIT != 0 && has_depth && self.depth.write_mask {
            c.depth = Some(depth_to_fixed(self.depth.clear));
        }
        if mask & GL_STENCIL_BUFFER_BIT != 0 && has_stencil {
            let bits = config.stencil_bits as u32;
            let full = (1u32 << bits) - 1;
            let value = (self.stencil.clear as u32 & full) as u8;
            let m = (self.stencil.write_mask & full) as u8;
            // Every bit the buffer has: a plain fill.
            c.stencil = (m != 0).then_some((value, if m == full as u8 { u8::MAX } else { m }));
        }
        let pixels = (r.x1 - r.x0) as usize * (r.y1 - r.y0) as usize;
        let writes = c.color.is_some() || c.depth.is_some() || c.stencil.is_some();
        if writes && pixels >= PARALLEL_PIXELS && !self.fb.draw_both && crate::render::tile::binning(&self.derived.render) {
            // Round 11: written by the workers band by band, each band
            // just before they draw into it (see `tile::defer_clear`).
            crate::render::tile::defer_clear(&self.derived.render, &mut self.fb, c);
        } else if writes {
            self.sync_render();
            let Framebuffer { width: w, color, other_color, draw_both, depth, stencil, .. } = &mut self.fb;
            let w = *w;
            let mut bands: Vec<Band> = Vec::new();
            if let Some((value, m)) = c.color {
                // The draw buffers (`Framebuffer::draw_colors`), split borrows.
                for color in std::iter::once(color).chain((*draw_both).then_some(other_color)) {
                    rows(&mut bands, threads, &mut color[..], w, r, move |row| fill::color_row(row, value, m));
                }
            }
            if let Some(value) = c.depth {
                rows(&mut bands, threads, &mut depth[..], w, r, move |row| row.fill(value));
            }
            if let Some((value, m)) = c.stencil {
                rows(&mut bands, threads, &mut stencil[..], w, r, move |row| fill::stencil_row(row, value, m));
            }
            run_bands(threads, bands);
        }
        if mask & GL_ACCUM_BUFFER_BIT != 0 {
            self.clear_accum_buffer(r);
        }
    }
}
