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

/// f32::round (half away from zero) for |x| <= 32767, inline: the
/// library's `roundf` is a software routine here and was most of
/// glAccum's time. Exact: truncation is exact for |x| < 2^23, and so is
/// the difference x - trunc(x). NaN gives 0, as `round() as i16` does.
#[inline(always)]
fn round_small(x: f32) -> i16 {
    let t = x as i32;
    let frac = x - t as f32;
    (t + (frac >= 0.5) as i32 - (frac <= -0.5) as i32) as i16
}

#[inline(always)]
fn to_fixed(v: f32) -> i16 {
    round_small(v.clamp(-1.0, 1.0) * ONE)
}

#[inline(always)]
fn from_fixed(v: i16) -> f32 {
    v as f32 / ONE
}

/// GL_RETURN's byte for an accumulation value: value * acc, clamped,
/// to 8 bits.
#[inline(always)]
fn returned(value: f32, acc: i16) -> u8 {
    ((value * from_fixed(acc)).clamp(0.0, 1.0) * 255.0 + 0.5) as u8
}

/// Above this many channels a GL_RETURN builds a table of every
/// accumulation value's byte (65536 entries) instead of converting each.
const RETURN_TABLE_MIN: usize = 1 << 17;

impl Context {
    /// glAccum. Whole rows at a time; the colour of a byte c is c / 255
    /// times `value`, the same f32 expression per byte whether computed per
    /// pixel or once into a 256-entry table, so the tables change no
    /// result (tests below compare with the per-pixel arithmetic).
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
        let (x0, x1) = (r.x0 as usize, r.x1 as usize);
        match op {
            GL_ACCUM | GL_LOAD => {
                // The read buffer and the accumulation buffer are distinct
                // vectors: borrow them apart.
                let src: &[[u8; 4]] = if read_back == fb.color_is_back || !fb.is_double_buffered() { &fb.color } else { &fb.other_color };
                let accum = &mut fb.accum;
                let add: [f32; 256] = std::array::from_fn(|c| value * (c as f32 / 255.0));
                let load: [i16; 256] = std::array::from_fn(|c| to_fixed(add[c]));
                for y in rows {
                    let (s, a) = (&src[y * width + x0..y * width + x1], &mut accum[y * width + x0..y * width + x1]);
                    if op == GL_LOAD {
                        for (acc, c) in a.iter_mut().zip(s) {
                            *acc = c.map(|v| load[v as usize]);
                        }
                    } else {
                        for (acc, c) in a.iter_mut().zip(s) {
                            for ch in 0..4 {
                                acc[ch] = to_fixed(from_fixed(acc[ch]) + add[c[ch] as usize]);
                            }
                        }
                    }
                }
            }
            GL_MULT | GL_ADD => {
                for y in rows {
                    for a in &mut fb.accum[y * width + x0..y * width + x1] {
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
                let table: Option<Vec<u8>> = ((x1 - x0) * rows.len() * 4 >= RETURN_TABLE_MIN).then(|| (0..=u16::MAX).map(|a| returned(value, a as i16)).collect());
                let byte = |a: i16| match &table {
                    Some(t) => t[a as u16 as usize],
                    None => returned(value, a),
                };
                for y in rows {
                    let span = y * width + x0..y * width + x1;
                    for (i, acc) in span.clone().zip(&fb.accum[span]) {
                        let mut out = fb.color[i];
                        for ch in 0..4 {
                            if mask[ch] {
                                out[ch] = byte(acc[ch]);
                            }
                        }
                        fb.color[i] = out;
                        if both {
                            let o = &mut fb.other_color[i];
                            for ch in 0..4 {
                                if mask[ch] {
                                    o[ch] = out[ch];
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

#[cfg(test)]
mod tests {
    use super::*;

    /// The inline rounding against the library's on every value a
    /// channel can produce near its rounding points, and a dense grid.
    #[test]
    fn round_small_is_f32_round() {
        let mut xs = Vec::new();
        for i in -32768i32..=32767 {
            for d in [0.0f32, 0.25, 0.5, 0.75] {
                let x = i as f32 + d;
                xs.extend([x, f32::from_bits(x.to_bits().wrapping_add(1)), f32::from_bits(x.to_bits().wrapping_sub(1))]);
            }
        }
        xs.extend([f32::NAN, -0.0, 0.49999997, -0.49999997]);
        for x in xs {
            if x.abs() <= 32767.0 || x.is_nan() {
                assert_eq!(round_small(x), x.round() as i16, "{x}");
            }
        }
        for v in (-1100..=1100).map(|i| i as f32 / 1000.0) {
            assert_eq!(to_fixed(v), (v.clamp(-1.0, 1.0) * ONE).round() as i16, "{v}");
        }
    }

    /// GL_RETURN's table and ACCUM/LOAD's byte tables against the plain
    /// per-pixel arithmetic (the code before the tables), on random
    /// buffers, values and both sides of the table threshold.
    #[test]
    fn row_paths_match_per_pixel_arithmetic() {
        use crate::framebuffer::Config;
        let mut seed = 12345u64;
        let mut next = || {
            seed = seed.wrapping_mul(6364136223846793005).wrapping_add(1442695040888963407);
            (seed >> 33) as u32
        };
        for (w, h) in [(7, 5), (300, 120)] {
            for &value in &[0.25f32, 1.0, -0.7, 2.5, 0.1] {
                let mut c = Context::new(Config { depth_bits: 24, stencil_bits: 8, accum_bits: 16 });
                c.fb.resize(w, h).unwrap();
                c.surface_resized(w as i32, h as i32);
                let color: Vec<[u8; 4]> = (0..w * h).map(|_| next().to_ne_bytes()).collect();
                let acc: Vec<[i16; 4]> = (0..w * h).map(|_| [0; 4].map(|_: i16| next() as i16)).collect();
                for op in [GL_LOAD, GL_ACCUM, GL_RETURN, GL_MULT, GL_ADD] {
                    c.fb.color.copy_from_slice(&color);
                    c.fb.accum.copy_from_slice(&acc);
                    c.accum(op, value);
                    for i in 0..w * h {
                        let (s, a) = (color[i], acc[i]);
                        let want_acc: [i16; 4] = std::array::from_fn(|ch| match op {
                            GL_LOAD => ((value * (s[ch] as f32 / 255.0)).clamp(-1.0, 1.0) * ONE).round() as i16,
                            GL_ACCUM => ((a[ch] as f32 / ONE + value * (s[ch] as f32 / 255.0)).clamp(-1.0, 1.0) * ONE).round() as i16,
                            GL_MULT => ((a[ch] as f32 / ONE * value).clamp(-1.0, 1.0) * ONE).round() as i16,
                            GL_ADD => ((a[ch] as f32 / ONE + value).clamp(-1.0, 1.0) * ONE).round() as i16,
                            _ => a[ch],
                        });
                        assert_eq!(c.fb.accum[i], want_acc, "op {op:#x} value {value} pixel {i}");
                        let want_color: [u8; 4] = if op == GL_RETURN { a.map(|v| ((value * (v as f32 / ONE)).clamp(0.0, 1.0) * 255.0 + 0.5) as u8) } else { s };
                        assert_eq!(c.fb.color[i], want_color, "op {op:#x} value {value} pixel {i}");
                    }
                }
            }
        }
    }
}
