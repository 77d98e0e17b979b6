//! glBlitFramebuffer (ARB_framebuffer_object / EXT_framebuffer_blit,
//! section 4.3.3): a rectangle of the read framebuffer's colour, depth or
//! stencil copied to a rectangle of the draw framebuffer, scaled (and
//! mirrored when a rectangle's corners are given reversed) by NEAREST or,
//! for colour, LINEAR filtering. Only the pixel ownership (the
//! framebuffer's bounds) and scissor tests apply. Source samples outside
//! the read framebuffer leave their destination pixels unchanged (the spec
//! leaves them undefined).

use super::context::Context;
use super::enums::*;
use crate::framebuffer::Framebuffer;

const GL_NEAREST: u32 = 0x2600;
const GL_LINEAR: u32 = 0x2601;
const COLOR: u32 = 0x4000;
const DEPTH: u32 = 0x0100;
const STENCIL: u32 = 0x0400;

/// The read side of a blit, copied out first (the two framebuffers may be
/// the same).
struct Source {
    width: usize,
    height: usize,
    color: Vec<[u8; 4]>,
    depth: Vec<u32>,
    stencil: Vec<u8>,
}

impl Context {
    pub fn blit_framebuffer(&mut self, src: [i32; 4], dst: [i32; 4], mask: u32, filter: u32) {
        if mask & !(COLOR | DEPTH | STENCIL) != 0 {
            return self.set_error(GL_INVALID_VALUE);
        }
        if filter != GL_NEAREST && filter != GL_LINEAR {
            return self.set_error(GL_INVALID_ENUM);
        }
        if filter == GL_LINEAR && mask & (DEPTH | STENCIL) != 0 {
            return self.set_error(GL_INVALID_OPERATION);
        }
        if !self.draw_framebuffer_complete() || !self.read_framebuffer_complete() {
            return;
        }
        self.sync_render();
        // The window's draw buffer (FRONT, BACK, FRONT_AND_BACK) is selected
        // lazily: select it now.
        self.sync_draw_buffer();
        let s = {
            let (fb, color): (&Framebuffer, &[[u8; 4]]) = self.read_source();
            // Depth and stencil blits need both framebuffers to have them
            // (INVALID_OPERATION when their formats differ: here, present
            // in one only).
            Source { width: fb.width, height: fb.height, color: color.to_vec(), depth: fb.depth.to_vec(), stencil: fb.stencil.to_vec() }
        };
        if (mask & DEPTH != 0 && s.depth.is_empty() != self.fb.depth.is_empty()) || (mask & STENCIL != 0 && s.stencil.is_empty() != self.fb.stencil.is_empty()) {
            return self.set_error(GL_INVALID_OPERATION);
        }
        let clip = self.scissored_surface();
        let (dx0, dx1) = (dst[0].min(dst[2]), dst[0].max(dst[2]));
        let (dy0, dy1) = (dst[1].min(dst[3]), dst[1].max(dst[3]));
        // An empty source or destination rectangle copies nothing.
        if dx0 == dx1 || dy0 == dy1 || src[0] == src[2] || src[1] == src[3] {
            return;
        }
        // Destination pixel centre -> source coordinate, per axis:
        // s = src0 + (d + 0.5 - dst0) * (src1 - src0) / (dst1 - dst0).
        // (In f64: the corners may be anywhere in the i32 range.)
        let [s0, s1, s2, s3] = src.map(|v| v as f64);
        let [d0, d1, d2, d3] = dst.map(|v| v as f64);
        let sx = |x: i32| s0 + (x as f64 + 0.5 - d0) * (s2 - s0) / (d2 - d0);
        let sy = |y: i32| s1 + (y as f64 + 0.5 - d1) * (s3 - s1) / (d3 - d1);
        // No read colour buffer (an object without one): colour is skipped.
        let color_on = mask & COLOR != 0 && self.color_buffer.draw_buffer != 0 && !s.color.is_empty() && !self.fbo_read_color_missing();
        let fbw = self.fb.width;
        let mut colors: Vec<(usize, [u8; 4])> = Vec::new();
        for y in dy0.max(clip.y0)..dy1.min(clip.y1) {
            let fy = sy(y);
            for x in dx0.max(clip.x0)..dx1.min(clip.x1) {
                let fx = sx(x);
                let d = y as usize * fbw + x as usize;
                let inside = |u: f64, v: f64| u >= 0.0 && v >= 0.0 && u < s.width as f64 && v < s.height as f64;
                if !inside(fx, fy) {
                    continue;
                }
                let k = fy as usize * s.width + fx as usize;
                if color_on {
                    colors.push((d, if filter == GL_LINEAR { bilinear(&s, fx, fy) } else { s.color[k] }));
                }
                if mask & DEPTH != 0 && !s.depth.is_empty() {
                    self.fb.depth[d] = s.depth[k];
                }
                if mask & STENCIL != 0 && !s.stencil.is_empty() {
                    self.fb.stencil[d] = s.stencil[k];
                }
            }
        }
        // Every colour buffer drawing writes (both for FRONT_AND_BACK).
        // Blits ignore the write masks, but a surface without alpha keeps
        // its alpha at 1.0 (see framebuffer::Config).
        let keep_alpha = self.fb.config.alpha_bits == 0;
        for buf in self.fb.draw_colors() {
            for &(d, c) in &colors {
                buf[d] = if keep_alpha { [c[0], c[1], c[2], 255] } else { c };
            }
        }
    }
}

/// The colour at (u, v) filtered from the four nearest texel centres,
/// clamped to the source's edges.
fn bilinear(s: &Source, u: f64, v: f64) -> [u8; 4] {
    let (u, v) = (u - 0.5, v - 0.5);
    let (x0, y0) = (u.floor(), v.floor());
    let (a, b) = (u - x0, v - y0);
    let cx = |x: f64| (x.max(0.0) as usize).min(s.width - 1);
    let cy = |y: f64| (y.max(0.0) as usize).min(s.height - 1);
    let (xa, xb, ya, yb) = (cx(x0), cx(x0 + 1.0), cy(y0), cy(y0 + 1.0));
    let t = |x: usize, y: usize| s.color[y * s.width + x];
    let (p00, p10, p01, p11) = (t(xa, ya), t(xb, ya), t(xa, yb), t(xb, yb));
    let mut out = [0u8; 4];
    for c in 0..4 {
        let top = p00[c] as f64 * (1.0 - a) + p10[c] as f64 * a;
        let bot = p01[c] as f64 * (1.0 - a) + p11[c] as f64 * a;
        out[c] = (top * (1.0 - b) + bot * b).round().clamp(0.0, 255.0) as u8;
    }
    out
}
