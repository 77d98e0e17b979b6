//! The accumulation buffer (GL 1.5 section 4.2.4): glAccum and glClearAccum.
//!
//! Each channel is a signed 16-bit fixed-point value for [-1, 1]
//! (v * 32767, rounded, clamped), as GL_ACCUM_*_BITS = 16 reports. The
//! operations work on the pixels inside the scissor box when the scissor
//! test is on (as for glClear), read colours from the read buffer
//! (glReadBuffer) as [0, 1] values, and GL_RETURN writes every draw buffer
//! through the colour write mask only: no other fragment operation applies.

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
        let mask = if self.color_buffer.draw_buffer == 0 { [false; 4] } else { self.color_buffer.write_mask };
        self.sync_draw_buffer();
        let read_back = matches!(self.pixel_read_buffer, GL_BACK | 0x0402 /* BACK_LEFT */);
        let fb = &mut self.fb;
        let width = fb.width;
        let rows = r.y0 as usize..r.y1 as usize;
        let cols = r.x0 as usize..r.x1 as usize;
        match op {
            GL_ACCUM | GL_LOAD => {
                // The read buffer and the accumulation buffer are distinct
                // vectors: borrow them apart.
                let src: &[[u8; 4]] = if read_back == fb.color_is_back || !fb.is_double_buffered() { &fb.color } else { &fb.other_color };
                let accum = &mut fb.accum;
                for y in rows {
                    for x in cols.clone() {
                        let i = y * width + x;
                        let c = src[i];
                        let acc = &mut accum[i];
                        for ch in 0..4 {
                            let v = value * (c[ch] as f32 / 255.0);
                            acc[ch] = if op == GL_LOAD { to_fixed(v) } else { to_fixed(from_fixed(acc[ch]) + v) };
                        }
                    }
                }
            }
            GL_MULT | GL_ADD => {
                for y in rows {
                    for a in &mut fb.accum[y * width + cols.start..y * width + cols.end] {
                        for ch in a.iter_mut() {
                            *ch = to_fixed(if op == GL_MULT { from_fixed(*ch) * value } else { from_fixed(*ch) + value });
                        }
                    }
                }
            }
            _ => {
                // GL_RETURN: value * acc, clamped, through the masks, into
                // each draw buffer.
                let both = fb.draw_both;
                for y in rows {
                    for x in cols.clone() {
                        let i = y * width + x;
                        let acc = fb.accum[i];
                        for ch in 0..4 {
                            if mask[ch] {
                                let v = ((value * from_fixed(acc[ch])).clamp(0.0, 1.0) * 255.0 + 0.5) as u8;
                                fb.color[i][ch] = v;
                                if both {
                                    fb.other_color[i][ch] = v;
                                }
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
