//! The accumulation buffer (GL 1.5 section 4.2.4): glAccum and glClearAccum.
//!
//! Each channel is a signed 16-bit fixed-point value for [-1, 1]
//! (v * 32767, rounded, clamped), as GL_ACCUM_*_BITS = 16 reports. The
//! operations work on the pixels inside the scissor box when the scissor
//! test is on (as for glClear), read colours from the framebuffer as
//! [0, 1] values, and GL_RETURN writes through the colour write mask only:
//! no other fragment operation applies.

use super::context::Context;
use super::enums::*;
use crate::framebuffer::Rect;

const ONE: f32 = 32767.0;

#[inline]
fn to_fixed(v: f32) -> i16 {
    (v.clamp(-1.0, 1.0) * ONE).round() as i16
}

#[inline]
fn from_fixed(v: i16) -> f32 {
    v as f32 / ONE
}

impl Context {
    pub fn accum(&mut self, op: u32, value: f32) {
        if !matches!(op, GL_ACCUM | GL_LOAD | GL_RETURN | GL_MULT | GL_ADD) {
            return self.set_error(GL_INVALID_ENUM);
        }
        if self.fb.accum.is_empty() {
            return self.set_error(GL_INVALID_OPERATION);
        }
        let r: Rect = self.scissored_surface();
        if r.is_empty() {
            return;
        }
        let mask = self.color_buffer.write_mask;
        let fb = &mut self.fb;
        for y in r.y0 as usize..r.y1 as usize {
            for x in r.x0 as usize..r.x1 as usize {
                let i = fb.index(x, y);
                let acc = &mut fb.accum[i];
                match op {
                    GL_ACCUM | GL_LOAD => {
                        let c = fb.color[i];
                        for ch in 0..4 {
                            let v = value * (c[ch] as f32 / 255.0);
                            acc[ch] = if op == GL_LOAD { to_fixed(v) } else { to_fixed(from_fixed(acc[ch]) + v) };
                        }
                    }
                    GL_MULT => {
                        for a in acc.iter_mut() {
                            *a = to_fixed(from_fixed(*a) * value);
                        }
                    }
                    GL_ADD => {
                        for a in acc.iter_mut() {
                            *a = to_fixed(from_fixed(*a) + value);
                        }
                    }
                    _ => {
                        // GL_RETURN: value * acc, clamped, through the masks.
                        let dst = &mut fb.color[i];
                        for ch in 0..4 {
                            if mask[ch] {
                                let v = (value * from_fixed(acc[ch])).clamp(0.0, 1.0);
                                dst[ch] = (v * 255.0 + 0.5) as u8;
                            }
                        }
                    }
                }
            }
        }
    }

    /// The accumulation part of glClear.
    pub fn clear_accum_buffer(&mut self, r: Rect) {
        if self.fb.accum.is_empty() {
            return;
        }
        let v = self.accum_clear.map(to_fixed);
        let w = self.fb.width;
        for y in r.y0 as usize..r.y1 as usize {
            self.fb.accum[y * w + r.x0 as usize..y * w + r.x1 as usize].fill(v);
        }
    }
}
