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
use crate::framebuffer::{Framebuffer, Rect};
use std::sync::atomic::{AtomicUsize, Ordering};
use std::sync::Mutex;

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

/// GL_ACCUM on one pixel: acc + add per channel, rounded and clamped.
#[inline(always)]
fn accum_pixel(acc: [i16; 4], add: [f32; 4]) -> [i16; 4] {
    std::array::from_fn(|ch| to_fixed(from_fixed(acc[ch]) + add[ch]))
}

/// GL_ACCUM's rows with SSE2: the four channels of a pixel in one vector,
/// each step the IEEE single-precision operation the scalar code does
/// (divide, add, clamp, multiply, round half away from zero), so the
/// results are the same; finite inputs only (a NaN would clamp and
/// convert differently), which the caller's table of finite values and
/// 16-bit accumulation values guarantee.
mod simd {
    #[cfg(target_arch = "x86_64")]
    pub fn accum_row(acc: &mut [[i16; 4]], src: &[[u8; 4]], add: &[f32; 256]) -> bool {
        use std::arch::x86_64::*;
        if !add.iter().all(|v| v.is_finite()) {
            return false;
        }
        // SAFETY: SSE2 is part of x86_64; loads and stores are of 8-byte
        // pixels inside the slices (unaligned forms).
        unsafe {
            let one = _mm_set1_ps(super::ONE);
            let (lo, hi) = (_mm_set1_ps(-1.0), _mm_set1_ps(1.0));
            let (half, neg_half) = (_mm_set1_ps(0.5), _mm_set1_ps(-0.5));
            for (a, c) in acc.iter_mut().zip(src) {
                let p = a.as_mut_ptr() as *mut i64;
                let raw = _mm_cvtsi64_si128(p.read_unaligned());
                let ai = _mm_srai_epi32(_mm_unpacklo_epi16(raw, raw), 16);
                let d = _mm_set_ps(add[c[3] as usize], add[c[2] as usize], add[c[1] as usize], add[c[0] as usize]);
                let sum = _mm_add_ps(_mm_div_ps(_mm_cvtepi32_ps(ai), one), d);
                let v = _mm_mul_ps(_mm_min_ps(hi, _mm_max_ps(lo, sum)), one);
                let t = _mm_cvttps_epi32(v);
                let frac = _mm_sub_ps(v, _mm_cvtepi32_ps(t));
                // Comparison masks are -1 where true: t + 1 above half, t - 1 below.
                let up = _mm_castps_si128(_mm_cmpge_ps(frac, half));
                let down = _mm_castps_si128(_mm_cmple_ps(frac, neg_half));
                let r = _mm_add_epi32(_mm_sub_epi32(t, up), down);
                p.write_unaligned(_mm_cvtsi128_si64(_mm_packs_epi32(r, r)));
            }
        }
        true
    }

    #[cfg(not(target_arch = "x86_64"))]
    pub fn accum_row(_acc: &mut [[i16; 4]], _src: &[[u8; 4]], _add: &[f32; 256]) -> bool {
        false
    }
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

/// Rows of at most this many pixels are done on the calling thread;
/// larger rectangles are cut into bands of rows for the rasterizer's
/// threads (`render::pool`).
const PARALLEL_PIXELS: usize = 1 << 15;

/// Calls `row(y, accum, color, other)` for every row y of `r` with the
/// whole row of the accumulation buffer, the drawn colour buffer and the
/// other one (None when single-buffered), in bands of rows shared among
/// `threads`. Each call gets its own row, so the result does not depend on
/// the thread count.
fn for_bands(threads: usize, fb: &mut Framebuffer, r: Rect, row: impl Fn(usize, &mut [[i16; 4]], &mut [[u8; 4]], Option<&mut [[u8; 4]]>) + Sync) {
    let width = fb.width;
    let (y0, y1) = (r.y0 as usize, r.y1 as usize);
    let Framebuffer { accum, color, other_color, .. } = fb;
    let span = y0 * width..y1 * width;
    let (accum, color) = (&mut accum[span.clone()], &mut color[span.clone()]);
    let mut other = (other_color.len() >= span.end).then(|| other_color[span].chunks_mut(width));
    let rows = accum.chunks_mut(width).zip(color.chunks_mut(width));
    let pixels = (r.x1 - r.x0) as usize * (y1 - y0);
    if threads <= 1 || pixels < PARALLEL_PIXELS {
        for (k, (a, c)) in rows.enumerate() {
            row(y0 + k, a, c, other.as_mut().and_then(|o| o.next()));
        }
        return;
    }
    // Bands of 16 rows, each taken whole by one thread (its lock is never
    // contended: a band is taken once).
    type Rows<'a> = Vec<(usize, &'a mut [[i16; 4]], &'a mut [[u8; 4]], Option<&'a mut [[u8; 4]]>)>;
    let mut bands: Vec<Mutex<Rows>> = Vec::new();
    for (k, (a, c)) in rows.enumerate() {
        if k % 16 == 0 {
            bands.push(Mutex::new(Vec::with_capacity(16)));
        }
        let o = other.as_mut().and_then(|o| o.next());
        bands.last_mut().expect("a band").get_mut().unwrap_or_else(|e| e.into_inner()).push((y0 + k, a, c, o));
    }
    let next = AtomicUsize::new(0);
    crate::render::pool::run(threads, &|| loop {
        let k = next.fetch_add(1, Ordering::Relaxed);
        let Some(band) = bands.get(k) else { break };
        let mut band = band.lock().unwrap_or_else(|e| e.into_inner());
        for (y, a, c, o) in band.drain(..) {
            row(y, a, c, o);
        }
    });
}

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
        let mask = if self.color_buffer.draw_buffer == 0 { [false; 4] } else { self.fb.config.color_mask(self.color_buffer.write_mask) };
        self.sync_draw_buffer();
        let read_back = matches!(self.pixel_read_buffer, GL_BACK | 0x0402 /* BACK_LEFT */);
        let threads = self.derived.render.threads;
        let fb = &mut self.fb;
        // The read buffer of ACCUM and LOAD: the drawn one, or the other.
        let read_other = !(read_back == fb.color_is_back || !fb.is_double_buffered());
        let both = fb.draw_both;
        let (x0, x1) = (r.x0 as usize, r.x1 as usize);
        // Each row is independent of the others: bands of rows in parallel.
        match op {
            GL_ACCUM | GL_LOAD => {
                let add: [f32; 256] = std::array::from_fn(|c| value * (c as f32 / 255.0));
                let load: [i16; 256] = std::array::from_fn(|c| to_fixed(add[c]));
                for_bands(threads, fb, r, |_, a, color, other| {
                    let s: &[[u8; 4]] = if read_other { other.expect("a second colour buffer") } else { color };
                    let (s, a) = (&s[x0..x1], &mut a[x0..x1]);
                    if op == GL_LOAD {
                        for (acc, c) in a.iter_mut().zip(s) {
                            *acc = c.map(|v| load[v as usize]);
                        }
                    } else if !simd::accum_row(a, s, &add) {
                        for (acc, c) in a.iter_mut().zip(s) {
                            *acc = accum_pixel(*acc, c.map(|v| add[v as usize]));
                        }
                    }
                });
            }
            GL_MULT | GL_ADD => {
                for_bands(threads, fb, r, |_, a, _, _| {
                    for a in &mut a[x0..x1] {
                        for ch in a.iter_mut() {
                            *ch = to_fixed(if op == GL_MULT { from_fixed(*ch) * value } else { from_fixed(*ch) + value });
                        }
                    }
                });
            }
            _ => {
                // GL_RETURN: value * acc, clamped, through the masks, into
                // each draw buffer.
                let table: Option<Vec<u8>> = ((x1 - x0) * (r.y1 - r.y0) as usize * 4 >= RETURN_TABLE_MIN).then(|| (0..=u16::MAX).map(|a| returned(value, a as i16)).collect());
                let byte = |a: i16| match &table {
                    Some(t) => t[a as u16 as usize],
                    None => returned(value, a),
                };
                for_bands(threads, fb, r, |_, acc, color, mut other| {
                    let (acc, color) = (&acc[x0..x1], &mut color[x0..x1]);
                    if let (Some(t), [true, true, true, true], false) = (&table, mask, both) {
                        // The common case: a whole row of whole pixels.
                        for (out, acc) in color.iter_mut().zip(acc) {
                            *out = acc.map(|a| t[a as u16 as usize]);
                        }
                        return;
                    }
                    for (i, acc) in acc.iter().enumerate() {
                        let mut out = color[i];
                        for ch in 0..4 {
                            if mask[ch] {
                                out[ch] = byte(acc[ch]);
                            }
                        }
                        color[i] = out;
                        if let (true, Some(other)) = (both, other.as_deref_mut()) {
                            let o = &mut other[x0 + i];
                            for ch in 0..4 {
                                if mask[ch] {
                                    o[ch] = out[ch];
                                }
                            }
                        }
                    }
                });
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

    /// The SSE2 row against the scalar pixel on every accumulation value
    /// near the rounding points and random ones, with large and small
    /// addends (clamping both ways).
    #[test]
    fn simd_accum_row_is_scalar() {
        let mut seed = 99u64;
        let mut next = || {
            seed = seed.wrapping_mul(6364136223846793005).wrapping_add(1442695040888963407);
            (seed >> 33) as u32
        };
        for value in [0.25f32, 1.0, -1.0, 0.5001, 3.0, -0.003, 1e-6] {
            let add: [f32; 256] = std::array::from_fn(|c| value * (c as f32 / 255.0));
            let n = 65536;
            let acc: Vec<[i16; 4]> = (0..n).map(|i| [i as u16 as i16, next() as i16, (i as i16).wrapping_mul(7), next() as i16]).collect();
            let src: Vec<[u8; 4]> = (0..n).map(|_| next().to_ne_bytes()).collect();
            let mut got = acc.clone();
            if !simd::accum_row(&mut got, &src, &add) {
                return;
            }
            for i in 0..n {
                assert_eq!(got[i], accum_pixel(acc[i], src[i].map(|v| add[v as usize])), "value {value} acc {:?} src {:?}", acc[i], src[i]);
            }
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
                let mut c = Context::new(Config { alpha_bits: 8, depth_bits: 24, stencil_bits: 8, accum_bits: 16 });
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
