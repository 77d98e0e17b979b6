//! The accumulation buffer (GL 1.5 section 4.2.4): glAccum and glClearAccum.
//!
//! Each channel is a signed 16-bit fixed-point value for [-1, 1]
//! (v * 32767, rounded, clamped), as GL_ACCUM_*_BITS = 16 reports. The
//! operations work on the pixels inside the scissor box when the scissor
//! test is on (as for glClear), read colours from the read buffer
//! (glReadBuffer) as [0, 1] values, and GL_RETURN writes every draw buffer
//! through the colour write mask only: no other fragment operation applies.
//!
//! Precision: the spec (4.2.4) leaves the accumulation buffer's bits to the
//! implementation and asks only that values in [-1, 1] be kept; 16 bits a
//! channel (15 + sign) is more than the 8-bit colour buffers it is loaded
//! from. Every operation is the single-precision arithmetic written in the
//! scalar functions below; the SIMD rows (SSE2 for ACCUM, AVX2 for every
//! operation, chosen at run time by `fragment::simd::level`) run the same
//! IEEE operations in the same order per channel, so they give the same
//! bits (tests below), and need finite `value`s (else the scalar code runs).
//!
//! glClear of the accumulation buffer is recorded, not done
//! (`Framebuffer::accum_clear`): the next glAccum fills it in first,
//! unless it is a GL_LOAD covering the cleared rectangle, which overwrites
//! every pixel the fill would have written (the usual LOAD-first sequence
//! then writes the 8 bytes a pixel once, not twice). Large rectangles are
//! cut into bands of rows for the rasterizer's threads.

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

    /// Every operation two pixels (eight channels) at a time in 256-bit
    /// lanes, each the scalar code's IEEE steps: `from_fixed` (i16 to f32,
    /// divide by 32767), the byte's value `value * (c / 255)`, the
    /// operation, then `to_fixed` (clamp to [-1, 1], times 32767, round
    /// half away from zero as `round_small`) or RETURN's byte (times
    /// value, clamp to [0, 1], times 255, plus 1/2, truncate). No fused
    /// multiply-add (each product is rounded as in the scalar code). The
    /// caller checks AVX2 and that `value` is finite (no NaN can arise:
    /// the clamps and conversions below differ from the scalar ones on
    /// NaN only). An odd last pixel goes through `tail`.
    #[cfg(target_arch = "x86_64")]
    pub mod avx2 {
        use super::super::ONE;
        use std::arch::x86_64::*;

        #[inline(always)]
        unsafe fn from_fixed(p: *const [i16; 4]) -> __m256 {
            let a = _mm_loadu_si128(p as *const __m128i);
            _mm256_div_ps(_mm256_cvtepi32_ps(_mm256_cvtepi16_epi32(a)), _mm256_set1_ps(ONE))
        }

        #[inline(always)]
        unsafe fn byte_value(p: *const [u8; 4], value: __m256) -> __m256 {
            let c = _mm_loadl_epi64(p as *const __m128i);
            _mm256_mul_ps(value, _mm256_div_ps(_mm256_cvtepi32_ps(_mm256_cvtepu8_epi32(c)), _mm256_set1_ps(255.0)))
        }

        #[inline(always)]
        unsafe fn store_fixed(p: *mut [i16; 4], v: __m256) {
            let v = _mm256_mul_ps(_mm256_min_ps(_mm256_set1_ps(1.0), _mm256_max_ps(_mm256_set1_ps(-1.0), v)), _mm256_set1_ps(ONE));
            let r = round_half_away(v);
            let packed = _mm_packs_epi32(_mm256_castsi256_si128(r), _mm256_extracti128_si256::<1>(r));
            _mm_storeu_si128(p as *mut __m128i, packed);
        }

        /// `round_small` in lanes, for |x| <= 32767 (round 13): the
        /// truncation of x + copysign(pred(1/2), x), 4 instructions
        /// instead of truncate, convert back, subtract, two compares and
        /// two integer steps. Exact: with x = n + f (0 <= f < 1), f >= 1/2
        /// makes the sum at least n + 1 - 2^-25, which rounds to n + 1 or
        /// above (the spacing below n + 1 is at least 2^-24; at x = 1/2
        /// the tie goes to the even 1.0) and stays below n + 3/2; f < 1/2
        /// means f <= 1/2 - ulp(x), so the sum lies more than ulp(x) below
        /// n + 1, farther than half the spacing there (at most 2 ulp(x)):
        /// it rounds below n + 1. Negative x mirrors (truncation is
        /// towards zero). Tested against `round_small` below.
        #[inline(always)]
        pub unsafe fn round_half_away(x: __m256) -> __m256i {
            let half = _mm256_or_ps(_mm256_and_ps(x, _mm256_set1_ps(-0.0)), _mm256_set1_ps(f32::from_bits(0x3eff_ffff)));
            _mm256_cvttps_epi32(_mm256_add_ps(x, half))
        }

        /// GL_ACCUM: acc = to_fixed(from_fixed(acc) + value * c / 255).
        #[target_feature(enable = "avx2")]
        pub unsafe fn accum_row(acc: &mut [[i16; 4]], src: &[[u8; 4]], value: f32, tail: impl Fn(&mut [i16; 4], [u8; 4])) {
            let n = acc.len().min(src.len());
            let v = _mm256_set1_ps(value);
            let (a, c) = (acc.as_mut_ptr(), src.as_ptr());
            let mut i = 0;
            // Two pairs an iteration (round 13: half the loop's counting).
            while i + 4 <= n {
                store_fixed(a.add(i), _mm256_add_ps(from_fixed(a.add(i)), byte_value(c.add(i), v)));
                store_fixed(a.add(i + 2), _mm256_add_ps(from_fixed(a.add(i + 2)), byte_value(c.add(i + 2), v)));
                i += 4;
            }
            while i + 2 <= n {
                store_fixed(a.add(i), _mm256_add_ps(from_fixed(a.add(i)), byte_value(c.add(i), v)));
                i += 2;
            }
            if i < n {
                tail(&mut acc[i], src[i]);
            }
        }

        /// GL_LOAD: acc = to_fixed(value * c / 255).
        #[target_feature(enable = "avx2")]
        pub unsafe fn load_row(acc: &mut [[i16; 4]], src: &[[u8; 4]], value: f32, tail: impl Fn(&mut [i16; 4], [u8; 4])) {
            let n = acc.len().min(src.len());
            let v = _mm256_set1_ps(value);
            let (a, c) = (acc.as_mut_ptr(), src.as_ptr());
            let mut i = 0;
            while i + 2 <= n {
                store_fixed(a.add(i), byte_value(c.add(i), v));
                i += 2;
            }
            if i < n {
                tail(&mut acc[i], src[i]);
            }
        }

        /// GL_MULT (`mult`) or GL_ADD: acc = to_fixed(from_fixed(acc) * or + value).
        #[target_feature(enable = "avx2")]
        pub unsafe fn mult_add_row(acc: &mut [[i16; 4]], mult: bool, value: f32, tail: impl Fn(&mut [i16; 4])) {
            let n = acc.len();
            let v = _mm256_set1_ps(value);
            let a = acc.as_mut_ptr();
            let mut i = 0;
            while i + 2 <= n {
                let f = from_fixed(a.add(i));
                store_fixed(a.add(i), if mult { _mm256_mul_ps(f, v) } else { _mm256_add_ps(f, v) });
                i += 2;
            }
            if i < n {
                tail(&mut acc[i]);
            }
        }

        /// GL_RETURN of whole pixels (all four channels written): the
        /// colour byte of `value * from_fixed(acc)`.
        #[target_feature(enable = "avx2")]
        pub unsafe fn return_row(acc: &[[i16; 4]], dst: &mut [[u8; 4]], value: f32, tail: impl Fn(&mut [u8; 4], [i16; 4])) {
            let n = acc.len().min(dst.len());
            let v = _mm256_set1_ps(value);
            let (a, d) = (acc.as_ptr(), dst.as_mut_ptr());
            let mut i = 0;
            while i + 2 <= n {
                let x = _mm256_mul_ps(v, from_fixed(a.add(i)));
                let x = _mm256_min_ps(_mm256_set1_ps(1.0), _mm256_max_ps(_mm256_setzero_ps(), x));
                let x = _mm256_add_ps(_mm256_mul_ps(x, _mm256_set1_ps(255.0)), _mm256_set1_ps(0.5));
                let t = _mm256_cvttps_epi32(x);
                let w = _mm_packs_epi32(_mm256_castsi256_si128(t), _mm256_extracti128_si256::<1>(t));
                _mm_storel_epi64(d.add(i) as *mut __m128i, _mm_packus_epi16(w, w));
                i += 2;
            }
            if i < n {
                tail(&mut dst[i], acc[i]);
            }
        }
    }
}

/// Whether the AVX2 rows may run for `value` (see `simd::avx2`).
#[inline]
fn avx2_for(value: f32) -> bool {
    cfg!(target_arch = "x86_64") && value.is_finite() && crate::render::fragment::simd::level() == crate::render::fragment::simd::Level::Avx2
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

/// Whether `outer` holds every pixel of `inner`.
fn covers(outer: Rect, inner: Rect) -> bool {
    inner.is_empty() || (outer.x0 <= inner.x0 && outer.y0 <= inner.y0 && outer.x1 >= inner.x1 && outer.y1 >= inner.y1)
}

/// Writes a recorded accumulation clear into the buffer, in bands.
fn fill_pending_clear(threads: usize, fb: &mut Framebuffer) {
    if let Some((r, v)) = fb.accum_clear.take() {
        let (x0, x1) = (r.x0 as usize, r.x1 as usize);
        for_bands(threads, fb, r, |_, a, _, _| a[x0..x1].fill(v));
    }
}

/// One glAccum's work, row by row (section 4.2.4): everything a row
/// needs, computed once per call. The immediate bands ([`for_bands`]) and
/// a band recorded in a flight of the rasterizer (round 13:
/// `render::tile::defer_band_op`) both run [`AccumRows::row`], so the
/// bytes do not depend on the path.
struct AccumRows {
    op: u32,
    value: f32,
    /// The scissored rectangle.
    r: Rect,
    /// ACCUM and LOAD read the colour buffer that is not drawn.
    read_other: bool,
    /// GL_RETURN writes both colour buffers (FRONT_AND_BACK).
    both: bool,
    mask: [bool; 4],
    /// The AVX2 rows may run (`avx2_for`).
    lanes: bool,
    /// A byte's value times `value`, and its LOAD result.
    add: [f32; 256],
    load: [i16; 256],
    /// GL_RETURN's byte per accumulation value, for large rectangles
    /// outside the AVX2 rows.
    table: Option<Vec<u8>>,
    /// A recorded accumulation clear written first (recorded bands only;
    /// the immediate path writes it in its own pass before).
    fill: Option<(Rect, [i16; 4])>,
}

impl AccumRows {
    fn new(op: u32, value: f32, r: Rect, read_other: bool, both: bool, mask: [bool; 4]) -> AccumRows {
        let lanes = avx2_for(value);
        let add: [f32; 256] = std::array::from_fn(|c| value * (c as f32 / 255.0));
        let load: [i16; 256] = std::array::from_fn(|c| to_fixed(add[c]));
        let whole = mask == [true; 4] && !both;
        let big = (r.x1 - r.x0) as usize * (r.y1 - r.y0) as usize * 4 >= RETURN_TABLE_MIN;
        let table = (op == GL_RETURN && !(lanes && whole) && big).then(|| (0..=u16::MAX).map(|a| returned(value, a as i16)).collect());
        AccumRows { op, value, r, read_other, both, mask, lanes, add, load, table, fill: None }
    }

    /// The operation on one row: `a` and `color` are whole rows of the
    /// accumulation buffer and the drawn colour buffer, `other` the row
    /// of the other colour buffer (None when single-buffered).
    fn row(&self, a: &mut [[i16; 4]], color: &mut [[u8; 4]], other: Option<&mut [[u8; 4]]>) {
        let (x0, x1) = (self.r.x0 as usize, self.r.x1 as usize);
        let (op, value, lanes) = (self.op, self.value, self.lanes);
        #[cfg(not(target_arch = "x86_64"))]
        let _ = lanes;
        match op {
            GL_ACCUM | GL_LOAD => {
                let (add, load) = (&self.add, &self.load);
                let s: &[[u8; 4]] = if self.read_other { other.expect("a second colour buffer") } else { color };
                let (s, a) = (&s[x0..x1], &mut a[x0..x1]);
                let load_px = |acc: &mut [i16; 4], c: [u8; 4]| *acc = c.map(|v| load[v as usize]);
                let accum_px = |acc: &mut [i16; 4], c: [u8; 4]| *acc = accum_pixel(*acc, c.map(|v| add[v as usize]));
                #[cfg(target_arch = "x86_64")]
                if lanes {
                    // Safety: AVX2 checked (`avx2_for`).
                    unsafe {
                        if op == GL_LOAD {
                            simd::avx2::load_row(a, s, value, load_px);
                        } else {
                            simd::avx2::accum_row(a, s, value, accum_px);
                        }
                    }
                    return;
                }
                if op == GL_LOAD {
                    for (acc, c) in a.iter_mut().zip(s) {
                        load_px(acc, *c);
                    }
                } else if !simd::accum_row(a, s, add) {
                    for (acc, c) in a.iter_mut().zip(s) {
                        accum_px(acc, *c);
                    }
                }
            }
            GL_MULT | GL_ADD => {
                let px = |a: &mut [i16; 4]| {
                    for ch in a.iter_mut() {
                        *ch = to_fixed(if op == GL_MULT { from_fixed(*ch) * value } else { from_fixed(*ch) + value });
                    }
                };
                #[cfg(target_arch = "x86_64")]
                if lanes {
                    // Safety: AVX2 checked (`avx2_for`).
                    unsafe { simd::avx2::mult_add_row(&mut a[x0..x1], op == GL_MULT, value, px) };
                    return;
                }
                a[x0..x1].iter_mut().for_each(px);
            }
            _ => self.return_row(a, color, other),
        }
    }

    /// GL_RETURN: value * acc, clamped, through the masks, into each draw
    /// buffer.
    fn return_row(&self, acc: &[[i16; 4]], color: &mut [[u8; 4]], mut other: Option<&mut [[u8; 4]]>) {
        let (x0, x1) = (self.r.x0 as usize, self.r.x1 as usize);
        let (value, mask, both) = (self.value, self.mask, self.both);
        let whole = mask == [true; 4] && !both;
        let (acc, color) = (&acc[x0..x1], &mut color[x0..x1]);
        #[cfg(target_arch = "x86_64")]
        if self.lanes && whole {
            // Safety: AVX2 checked (`avx2_for`).
            unsafe { simd::avx2::return_row(acc, color, value, |out, a| *out = a.map(|a| returned(value, a))) };
            return;
        }
        let table = &self.table;
        if let (Some(t), true) = (table, whole) {
            // The common case: a whole row of whole pixels.
            for (out, acc) in color.iter_mut().zip(acc) {
                *out = acc.map(|a| t[a as u16 as usize]);
            }
            return;
        }
        let byte = |a: i16| match table {
            Some(t) => t[a as u16 as usize],
            None => returned(value, a),
        };
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
    }
}

/// A glAccum recorded in a flight (round 13): recorded only when it reads
/// and writes the drawn colour buffer alone (`Context::accum`).
impl crate::render::tile::BandOp for AccumRows {
    fn band(&self, y0: usize, y1: usize, width: usize, color: &mut [[u8; 4]], accum: &mut [[i16; 4]]) {
        if accum.len() < (y1 - y0) * width || color.len() < (y1 - y0) * width {
            return;
        }
        if let Some((c, v)) = self.fill {
            let (x0, x1) = (c.x0 as usize, c.x1 as usize);
            for y in y0.max(c.y0 as usize)..y1.min(c.y1 as usize) {
                accum[(y - y0) * width..][x0..x1].fill(v);
            }
        }
        for y in y0.max(self.r.y0 as usize)..y1.min(self.r.y1 as usize) {
            let at = (y - y0) * width..(y - y0 + 1) * width;
            self.row(&mut accum[at.clone()], &mut color[at], None);
        }
    }
}

impl Context {
    /// glAccum. Whole rows at a time; the colour of a byte c is c / 255
    /// times `value`, the same f32 expression per byte whether computed per
    /// pixel, in lanes or once into a 256-entry table, so the tables and
    /// lanes change no result (tests below compare with the per-pixel
    /// arithmetic).
    ///
    /// Round 13: while the rasterizer's threads bin, a large glAccum that
    /// reads and writes only the drawn colour buffer is not run at once:
    /// it is recorded in the batch after the primitives drawn before it
    /// (`render::tile::defer_band_op`), and each band of the flight runs
    /// it on its rows right after drawing them (`Command::Accum` does not
    /// sync before it; every other case syncs here).
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
        self.sync_draw_buffer_keeping_batch();
        let read_back = matches!(self.pixel_read_buffer, GL_BACK | 0x0402 /* BACK_LEFT */);
        let threads = self.derived.render.threads;
        // The read buffer of ACCUM and LOAD: the drawn one, or the other.
        let read_other = read_back != self.fb.color_is_back && self.fb.is_double_buffered();
        let both = self.fb.draw_both;
        let pixels = (r.x1 - r.x0) as usize * (r.y1 - r.y0) as usize;
        let record = crate::render::tile::binning(&self.derived.render) && pixels >= PARALLEL_PIXELS && !both && (!read_other || matches!(op, GL_MULT | GL_ADD | GL_RETURN)) && self.fb.accum.len() >= self.fb.width * self.fb.height;
        if !record {
            self.sync_render();
        }
        let fb = &mut self.fb;
        // A recorded clear: a LOAD over all of it overwrites it unseen.
        if fb.accum_clear.is_some_and(|(c, _)| op == GL_LOAD && covers(r, c)) {
            fb.accum_clear = None;
        }
        let mut rows = AccumRows::new(op, value, r, read_other, both, mask);
        if record {
            rows.fill = fb.accum_clear.take();
            crate::render::tile::defer_band_op(&self.derived.render, Box::new(rows));
            return;
        }
        fill_pending_clear(threads, fb);
        // Each row is independent of the others: bands of rows in parallel.
        for_bands(threads, fb, r, |_, a, color, other| rows.row(a, color, other));
    }

    /// The accumulation part of glClear: recorded, written by the next
    /// glAccum (see the module comment). A clear covering the one recorded
    /// before replaces it; otherwise that one is written first.
    pub fn clear_accum_buffer(&mut self, r: Rect) {
        if self.fb.accum.is_empty() {
            return;
        }
        let v = self.accum_clear.map(to_fixed);
        let threads = self.derived.render.threads;
        let fb = &mut self.fb;
        if fb.accum_clear.is_some_and(|(c, _)| !covers(r, c)) {
            // Recorded glAccum bands may still be in flight (round 13).
            crate::render::tile::sync(&self.derived.render, fb);
            fill_pending_clear(threads, fb);
        }
        fb.accum_clear = Some((r, v));
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

    /// The AVX2 rounding against `round_small` on every f32 within 8
    /// units in the last place of each integer and each half-integer up
    /// to 32767 (where the result changes), both signs, and a million
    /// random values in range.
    #[test]
    #[cfg(target_arch = "x86_64")]
    fn avx2_rounding_is_round_small() {
        if !is_x86_feature_detected!("avx2") {
            return;
        }
        let mut xs = vec![0.0f32, -0.0, 32767.0, -32767.0];
        for k in 0..=32767i32 {
            for c in [k as f32, k as f32 + 0.5] {
                for d in -8i32..=8 {
                    let x = f32::from_bits((c.to_bits() as i32 + d).max(0) as u32);
                    if x <= 32767.0 {
                        xs.extend([x, -x]);
                    }
                }
            }
        }
        let mut seed = 31u64;
        for _ in 0..1_000_000 {
            seed = seed.wrapping_mul(6364136223846793005).wrapping_add(1442695040888963407);
            xs.push(((seed >> 40) as f32 / (1u64 << 24) as f32) * 65534.0 - 32767.0);
        }
        while xs.len() % 8 != 0 {
            xs.push(0.25);
        }
        for x in xs.chunks(8) {
            let mut got = [0i32; 8];
            // Safety: AVX2 checked above.
            unsafe {
                use std::arch::x86_64::*;
                _mm256_storeu_si256(got.as_mut_ptr() as *mut __m256i, simd::avx2::round_half_away(_mm256_loadu_ps(x.as_ptr())));
            }
            for (g, &x) in got.iter().zip(x) {
                assert_eq!(*g, round_small(x) as i32, "{x} ({:#x})", x.to_bits());
            }
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

    /// The AVX2 rows against the scalar functions on every kind of
    /// accumulation value (random, the extremes, rounding neighbourhoods)
    /// and values that clamp both ways, on odd and even row lengths (the
    /// odd pixel goes through the tail closure, made to mark it here so
    /// that a row that skipped the lanes would be seen).
    #[test]
    #[cfg(target_arch = "x86_64")]
    fn avx2_rows_match_scalar() {
        if !is_x86_feature_detected!("avx2") {
            return;
        }
        let mut seed = 4242u64;
        let mut next = || {
            seed = seed.wrapping_mul(6364136223846793005).wrapping_add(1442695040888963407);
            (seed >> 33) as u32
        };
        let special = [0i16, 1, -1, 16383, 16384, -16384, 32767, -32767, -32768, 100, -100];
        for value in [0.25f32, 1.0, -1.0, 0.5001, 3.0, -0.003, 1e-6, 2.0e38, -3.0e38, 0.0, -0.0, 1.0 / 3.0] {
            for n in [65537usize, 2, 1] {
                let acc: Vec<[i16; 4]> = (0..n).map(|i| if i % 3 == 0 { [0; 4].map(|_: i16| special[next() as usize % special.len()]) } else { [0; 4].map(|_: i16| next() as i16) }).collect();
                let src: Vec<[u8; 4]> = (0..n).map(|_| next().to_ne_bytes()).collect();
                let add: [f32; 256] = std::array::from_fn(|c| value * (c as f32 / 255.0));
                let odd = n % 2 == 1;
                let mark = [i16::MIN + 7; 4];
                // ACCUM
                let mut got = acc.clone();
                unsafe { simd::avx2::accum_row(&mut got, &src, value, |a, _| *a = mark) };
                for i in 0..n {
                    let want = if odd && i == n - 1 { mark } else { accum_pixel(acc[i], src[i].map(|v| add[v as usize])) };
                    assert_eq!(got[i], want, "ACCUM value {value} acc {:?} src {:?}", acc[i], src[i]);
                }
                // LOAD
                let mut got = acc.clone();
                unsafe { simd::avx2::load_row(&mut got, &src, value, |a, _| *a = mark) };
                for i in 0..n {
                    let want = if odd && i == n - 1 { mark } else { src[i].map(|v| to_fixed(value * (v as f32 / 255.0))) };
                    assert_eq!(got[i], want, "LOAD value {value} src {:?}", src[i]);
                }
                // MULT and ADD
                for mult in [true, false] {
                    let mut got = acc.clone();
                    unsafe { simd::avx2::mult_add_row(&mut got, mult, value, |a| *a = mark) };
                    for i in 0..n {
                        let want = if odd && i == n - 1 { mark } else { acc[i].map(|a| to_fixed(if mult { from_fixed(a) * value } else { from_fixed(a) + value })) };
                        assert_eq!(got[i], want, "mult {mult} value {value} acc {:?}", acc[i]);
                    }
                }
                // RETURN
                let mut got = src.clone();
                unsafe { simd::avx2::return_row(&acc, &mut got, value, |o, _| *o = [7; 4]) };
                for i in 0..n {
                    let want = if odd && i == n - 1 { [7; 4] } else { acc[i].map(|a| returned(value, a)) };
                    assert_eq!(got[i], want, "RETURN value {value} acc {:?}", acc[i]);
                }
            }
        }
    }

    /// A recorded clear is written before any operation that reads the
    /// buffer, dropped only by a LOAD that covers it, and replaced by a
    /// clear that covers it: every sequence gives the buffer an immediate
    /// fill would give.
    #[test]
    fn recorded_clear_is_an_immediate_clear() {
        use crate::framebuffer::Config;
        let (w, h) = (37usize, 23usize);
        let mut seed = 777u64;
        let mut next = || {
            seed = seed.wrapping_mul(6364136223846793005).wrapping_add(1442695040888963407);
            (seed >> 33) as u32
        };
        for case in 0..400 {
            let mut c = Context::new(Config { alpha_bits: 8, depth_bits: 0, stencil_bits: 0, accum_bits: 16 });
            c.fb.resize(w, h).unwrap();
            c.surface_resized(w as i32, h as i32);
            for px in c.fb.color.iter_mut() {
                *px = next().to_ne_bytes();
            }
            for a in c.fb.accum.iter_mut() {
                *a = [0; 4].map(|_: i16| next() as i16);
            }
            let mut model = c.fb.accum.clone();
            for _ in 0..4 {
                // A scissor box that is sometimes the whole window.
                let whole = next() % 3 == 0;
                let (x, y) = if whole { (0, 0) } else { ((next() % w as u32) as i32, (next() % h as u32) as i32) };
                let (sw, sh) = if whole { (w as i32, h as i32) } else { ((next() % w as u32) as i32, (next() % h as u32) as i32) };
                c.set_scissor(x, y, sw, sh);
                c.set_enabled(GL_SCISSOR_TEST, !whole);
                let r = c.scissored_surface();
                match next() % 4 {
                    0 => {
                        let v = [0.0f32; 4].map(|_| (next() % 2001) as f32 / 1000.0 - 1.0);
                        c.accum_clear = v;
                        c.clear(GL_ACCUM_BUFFER_BIT);
                        for yy in r.y0..r.y1 {
                            for xx in r.x0..r.x1 {
                                model[yy as usize * w + xx as usize] = v.map(to_fixed);
                            }
                        }
                    }
                    k => {
                        let op = [GL_LOAD, GL_ACCUM, GL_MULT][k as usize - 1];
                        let color = c.fb.color.to_vec();
                        c.accum(op, 0.75);
                        for yy in r.y0..r.y1 {
                            for xx in r.x0..r.x1 {
                                let i = yy as usize * w + xx as usize;
                                let s = color[i];
                                model[i] = std::array::from_fn(|ch| match op {
                                    GL_LOAD => to_fixed(0.75 * (s[ch] as f32 / 255.0)),
                                    GL_ACCUM => to_fixed(from_fixed(model[i][ch]) + 0.75 * (s[ch] as f32 / 255.0)),
                                    _ => to_fixed(from_fixed(model[i][ch]) * 0.75),
                                });
                            }
                        }
                    }
                }
            }
            c.set_enabled(GL_SCISSOR_TEST, false);
            // The last operation reads the whole buffer (writing any
            // recorded clear first).
            c.accum(GL_MULT, 1.0);
            let model: Vec<[i16; 4]> = model.iter().map(|a| a.map(|v| to_fixed(from_fixed(v) * 1.0))).collect();
            let bad = (0..w * h).find(|&i| c.fb.accum[i] != model[i]);
            assert!(bad.is_none(), "case {case}: pixel {bad:?}");
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
                    // A large glAccum may be recorded for the rasterizer's
                    // threads (round 13): whatever reads the buffers syncs.
                    c.sync_render();
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
