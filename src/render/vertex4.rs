//! The vertex stage's position work four vertices at a time (GL 1.5
//! sections 2.10 and 2.11): object to clip coordinates by the combined
//! modelview-projection matrix, the fixed clip planes' inside test
//! (`clip::inside_fixed`), the perspective division and viewport
//! transformation (`setup::window_pos`) and the fixed-point snap
//! (`vertex::snap`).
//!
//! Invariant: every lane performs the same IEEE operations, in the same
//! order and precision, as the scalar functions named above do for one
//! vertex (glam's `Mat4 * Vec4` is ((c0 x + c1 y) + c2 z) + c3 w per row,
//! in f32; the window position is f64), so a vertex placed here has the
//! bits `ClipVertex::place` gives it. Why lanes: one vertex's work is a
//! chain of dependent latencies (product, division, snap); four
//! independent chains overlap.

use super::vertex::ClipVertex;
use super::RenderState;
use glam::{Mat4, Vec4};

/// Vertices per batch.
pub const LANES: usize = 4;

/// Object coordinates of up to [`LANES`] vertices, one array per
/// coordinate (lane i is the i-th queued vertex).
#[derive(Clone, Copy, Debug)]
pub struct Positions {
    pub x: [f32; LANES],
    pub y: [f32; LANES],
    pub z: [f32; LANES],
    pub w: [f32; LANES],
}

impl Positions {
    /// All lanes (0, 0, 0, 1): finite, so unused lanes raise no
    /// floating-point exceptions of their own.
    pub const ORIGIN: Positions = Positions { x: [0.0; LANES], y: [0.0; LANES], z: [0.0; LANES], w: [1.0; LANES] };

    #[inline(always)]
    pub fn set(&mut self, lane: usize, p: [f32; 4]) {
        self.x[lane] = p[0];
        self.y[lane] = p[1];
        self.z[lane] = p[2];
        self.w[lane] = p[3];
    }

    /// The lanes of a [`Queue`], one array per coordinate (the lit
    /// path's `light4::light_lanes` reads them so).
    #[inline(always)]
    pub fn of(q: &Queue) -> Positions {
        let l = &q.0;
        Positions {
            x: std::array::from_fn(|i| l[i].x),
            y: std::array::from_fn(|i| l[i].y),
            z: std::array::from_fn(|i| l[i].z),
            w: std::array::from_fn(|i| l[i].w),
        }
    }
}

/// Object coordinates of up to [`LANES`] queued vertices, one vector per
/// vertex (round 17): a vertex is queued with one 16-byte store, which
/// the flush's 16-byte load of the lane takes straight from the store
/// buffer. One array per coordinate ([`Positions`]) took four 4-byte
/// stores per vertex, and each 16-byte load of a coordinate's lanes then
/// waited for them to reach the cache (a store-forwarding stall per
/// flush: about a tenth of `flush_vertices`' cycles in immediate_1m).
#[derive(Clone, Copy, Debug)]
pub struct Queue(pub [Vec4; LANES]);

impl Queue {
    /// All lanes (0, 0, 0, 1), as [`Positions::ORIGIN`].
    pub const ORIGIN: Queue = Queue([Vec4::W; LANES]);

    #[inline(always)]
    pub fn set(&mut self, lane: usize, p: Vec4) {
        self.0[lane] = p;
    }
}

/// Transforms the first `k` (1 to [`LANES`]) queued positions by `mvp` and
/// places them: writes `pos`, `inside`, and for inside vertices `win` and
/// `snapped`, of `verts[slots[i]]` for lane i. The same bits as
/// `v.pos = mvp * obj; v.place(rs)` per vertex.
#[inline]
pub fn transform_place(mvp: &Mat4, rs: &RenderState, obj: &Queue, k: usize, verts: &mut [ClipVertex], slots: [usize; LANES]) {
    debug_assert!(k >= 1 && k <= LANES);
    #[cfg(all(any(target_arch = "x86_64", target_arch = "x86"), target_feature = "sse2"))]
    {
        #[cfg(target_arch = "x86_64")]
        if super::fragment::simd::level() == super::fragment::simd::Level::Avx2 {
            // SAFETY: SSE2 is enabled for this target; the CPU has AVX2
            // (`simd::level` detected it).
            return unsafe { avx2::transform_place(mvp, rs, obj, k, verts, slots) };
        }
        // SAFETY: SSE2 is enabled for this target (cfg above).
        unsafe { sse2::transform_place(mvp, rs, obj, k, verts, slots) }
    }
    #[cfg(not(all(any(target_arch = "x86_64", target_arch = "x86"), target_feature = "sse2")))]
    {
        scalar(mvp, rs, obj, k, verts, slots)
    }
}

/// The one-vertex-at-a-time definition the lanes reproduce.
#[inline]
pub fn scalar(mvp: &Mat4, rs: &RenderState, obj: &Queue, k: usize, verts: &mut [ClipVertex], slots: [usize; LANES]) {
    for i in 0..k {
        let v = &mut verts[slots[i]];
        v.pos = *mvp * obj.0[i];
        v.place(rs);
    }
}

#[cfg(all(any(target_arch = "x86_64", target_arch = "x86"), target_feature = "sse2"))]
mod sse2 {
    use super::super::clip::{GUARD, W_MIN};
    use super::super::setup::ONE;
    use super::*;
    #[cfg(target_arch = "x86")]
    use core::arch::x86::*;
    #[cfg(target_arch = "x86_64")]
    use core::arch::x86_64::*;

    /// Snapped values whose magnitude stays below this are converted in
    /// 32-bit lanes (`cvttpd2dq`); the rounding may add one, which must
    /// still fit.
    pub(super) const SNAP_LIMIT: f64 = (1u64 << 30) as f64;

    /// One lane's clip position as glam's `Mat4 * Vec4` computes it (the
    /// scalar stage): x_axis * x + y_axis * y, + z_axis * z, + w_axis * w,
    /// in that order. Round 23: by columns, the lane's coordinates
    /// broadcast, rather than by rows with the matrix's 16 elements
    /// broadcast for every four lanes (32 instructions) and the lanes
    /// transposed first; the same products and sums, so the same bits.
    #[inline(always)]
    unsafe fn column_sum(cols: &[__m128; 4], v: __m128) -> __m128 {
        let a = _mm_mul_ps(cols[0], _mm_shuffle_ps::<0x00>(v, v));
        let a = _mm_add_ps(a, _mm_mul_ps(cols[1], _mm_shuffle_ps::<0x55>(v, v)));
        let a = _mm_add_ps(a, _mm_mul_ps(cols[2], _mm_shuffle_ps::<0xAA>(v, v)));
        _mm_add_ps(a, _mm_mul_ps(cols[3], _mm_shuffle_ps::<0xFF>(v, v)))
    }

    /// `vertex::snap` for two lanes whose |c * ONE| is below SNAP_LIMIT:
    /// truncation (exact), the exact fraction, and the half-away rounding
    /// as -1/0/+1 added in f64 (exact: small integers).
    #[inline(always)]
    unsafe fn snap2(c: __m128d) -> __m128i {
        let v = _mm_mul_pd(c, _mm_set1_pd(ONE as f64));
        let t = _mm_cvttpd_epi32(v);
        let tf = _mm_cvtepi32_pd(t);
        let frac = _mm_sub_pd(v, tf);
        let one = _mm_set1_pd(1.0);
        let up = _mm_and_pd(_mm_cmpge_pd(frac, _mm_set1_pd(0.5)), one);
        let down = _mm_and_pd(_mm_cmple_pd(frac, _mm_set1_pd(-0.5)), one);
        _mm_cvtpd_epi32(_mm_sub_pd(_mm_add_pd(tf, up), down))
    }

    /// Lanes (bits 0 and 1) whose |c * ONE| is below SNAP_LIMIT.
    #[inline(always)]
    unsafe fn snappable(c: __m128d) -> i32 {
        let v = _mm_mul_pd(c, _mm_set1_pd(ONE as f64));
        let abs = _mm_andnot_pd(_mm_set1_pd(-0.0), v);
        _mm_movemask_pd(_mm_cmplt_pd(abs, _mm_set1_pd(SNAP_LIMIT)))
    }

    /// The clip coordinates of the lanes, one vector per coordinate; the
    /// lanes inside the fixed clip planes (bit i for lane i); the clip
    /// positions per lane.
    #[inline(always)]
    pub(super) unsafe fn clip_lanes(mvp: &Mat4, obj: &Queue) -> ([__m128; 4], i32, [__m128; LANES]) {
        let cols = [mvp.x_axis, mvp.y_axis, mvp.z_axis, mvp.w_axis].map(__m128::from);
        // Clip positions per lane, then one vector per coordinate (a 4x4
        // transpose).
        let pos = obj.0.map(|v| column_sum(&cols, __m128::from(v)));
        let t0 = _mm_unpacklo_ps(pos[0], pos[1]); // x0 x1 y0 y1
        let t1 = _mm_unpackhi_ps(pos[0], pos[1]); // z0 z1 w0 w1
        let t2 = _mm_unpacklo_ps(pos[2], pos[3]); // x2 x3 y2 y3
        let t3 = _mm_unpackhi_ps(pos[2], pos[3]); // z2 z3 w2 w3
        let (cx, cy) = (_mm_movelh_ps(t0, t2), _mm_movehl_ps(t2, t0));
        let (cz, cw) = (_mm_movelh_ps(t1, t3), _mm_movehl_ps(t3, t1));

        // `clip::inside_fixed` per lane: z + w, (-z) + w, x + g, (-x) + g,
        // y + g, (-y) + g, w + (-W_MIN), inf + (-w), each >= 0 (false for
        // NaN), g = GUARD * w.
        let sign = _mm_set1_ps(-0.0);
        let zero = _mm_setzero_ps();
        let g = _mm_mul_ps(_mm_set1_ps(GUARD), cw);
        let ge = |a: __m128| _mm_cmpge_ps(a, zero);
        let mut ok = _mm_and_ps(ge(_mm_add_ps(cz, cw)), ge(_mm_add_ps(_mm_xor_ps(cz, sign), cw)));
        ok = _mm_and_ps(ok, _mm_and_ps(ge(_mm_add_ps(cx, g)), ge(_mm_add_ps(_mm_xor_ps(cx, sign), g))));
        ok = _mm_and_ps(ok, _mm_and_ps(ge(_mm_add_ps(cy, g)), ge(_mm_add_ps(_mm_xor_ps(cy, sign), g))));
        ok = _mm_and_ps(ok, ge(_mm_add_ps(cw, _mm_set1_ps(-W_MIN))));
        ok = _mm_and_ps(ok, ge(_mm_add_ps(_mm_set1_ps(f32::INFINITY), _mm_xor_ps(cw, sign))));
        let inside = _mm_movemask_ps(ok);

        ([cx, cy, cz, cw], inside, pos)
    }

    #[inline(always)]
    pub unsafe fn transform_place(mvp: &Mat4, rs: &RenderState, obj: &Queue, k: usize, verts: &mut [ClipVertex], slots: [usize; LANES]) {
        let ([cx, cy, cz, cw], inside, pos) = clip_lanes(mvp, obj);
        // `setup::window_pos` in f64 lanes, two at a time: q = 1 / w,
        // o + s * (c * q).
        let [sx, sy, sz] = rs.viewport_scale;
        let [ox, oy, oz] = rs.viewport_offset;
        let one = _mm_set1_pd(1.0);
        let mut win = [[0.0f64; 4]; LANES];
        let mut snapped = [[0i64; 2]; LANES];
        for h in 0..LANES / 2 {
            let lo = |v: __m128| if h == 0 { _mm_cvtps_pd(v) } else { _mm_cvtps_pd(_mm_movehl_ps(v, v)) };
            let (px, py, pz, pw) = (lo(cx), lo(cy), lo(cz), lo(cw));
            let q = _mm_div_pd(one, pw);
            let wx = _mm_add_pd(_mm_set1_pd(ox), _mm_mul_pd(_mm_set1_pd(sx), _mm_mul_pd(px, q)));
            let wy = _mm_add_pd(_mm_set1_pd(oy), _mm_mul_pd(_mm_set1_pd(sy), _mm_mul_pd(py, q)));
            let wz = _mm_add_pd(_mm_set1_pd(oz), _mm_mul_pd(_mm_set1_pd(sz), _mm_mul_pd(pz, q)));
            let (l0, l1) = (2 * h, 2 * h + 1);
            _mm_storeu_pd(win[l0].as_mut_ptr(), _mm_unpacklo_pd(wx, wy));
            _mm_storeu_pd(win[l0].as_mut_ptr().add(2), _mm_unpacklo_pd(wz, q));
            _mm_storeu_pd(win[l1].as_mut_ptr(), _mm_unpackhi_pd(wx, wy));
            _mm_storeu_pd(win[l1].as_mut_ptr().add(2), _mm_unpackhi_pd(wz, q));
            // Only inside lanes are snapped; one out of the 32-bit range
            // (a huge viewport) takes the scalar snap.
            let need = (inside >> l0) & 3;
            if need & !(snappable(wx) & snappable(wy)) == 0 {
                let (ix, iy) = (snap2(wx), snap2(wy));
                let mut a = [0i32; 4];
                let mut b = [0i32; 4];
                _mm_storeu_si128(a.as_mut_ptr() as *mut __m128i, ix);
                _mm_storeu_si128(b.as_mut_ptr() as *mut __m128i, iy);
                snapped[l0] = [a[0] as i64, b[0] as i64];
                snapped[l1] = [a[1] as i64, b[1] as i64];
            } else {
                for l in [l0, l1] {
                    snapped[l] = [super::super::vertex::snap(win[l][0]), super::super::vertex::snap(win[l][1])];
                }
            }
        }

        for i in 0..k {
            let v = &mut verts[slots[i]];
            _mm_storeu_ps(&mut v.pos as *mut Vec4 as *mut f32, pos[i]);
            v.inside = (inside >> i) & 1 != 0;
            // Stored for outside vertices too: `win` and `snapped` are
            // never read unless `inside`.
            v.win = win[i];
            v.snapped = snapped[i];
        }
    }
}

/// [`transform_place`] with the window position's f64 lanes four wide
/// (round 17): one division, one set of products and sums, one snap for
/// the four vertices, where SSE2 takes two of each. The same operations
/// per lane as `sse2` (and so as the scalar stage).
#[cfg(target_arch = "x86_64")]
mod avx2 {
    use super::super::setup::ONE;
    use super::sse2::{clip_lanes, SNAP_LIMIT};
    use super::*;
    use core::arch::x86_64::*;

    /// `sse2::snap2` for four lanes.
    #[inline(always)]
    unsafe fn snap4(c: __m256d) -> __m128i {
        let v = _mm256_mul_pd(c, _mm256_set1_pd(ONE as f64));
        let t = _mm256_cvttpd_epi32(v);
        let tf = _mm256_cvtepi32_pd(t);
        let frac = _mm256_sub_pd(v, tf);
        let one = _mm256_set1_pd(1.0);
        let up = _mm256_and_pd(_mm256_cmp_pd::<_CMP_GE_OS>(frac, _mm256_set1_pd(0.5)), one);
        let down = _mm256_and_pd(_mm256_cmp_pd::<_CMP_LE_OS>(frac, _mm256_set1_pd(-0.5)), one);
        _mm256_cvtpd_epi32(_mm256_sub_pd(_mm256_add_pd(tf, up), down))
    }

    /// `sse2::snappable` for four lanes (bits 0 to 3).
    #[inline(always)]
    unsafe fn snappable4(c: __m256d) -> i32 {
        let v = _mm256_mul_pd(c, _mm256_set1_pd(ONE as f64));
        let abs = _mm256_andnot_pd(_mm256_set1_pd(-0.0), v);
        _mm256_movemask_pd(_mm256_cmp_pd::<_CMP_LT_OS>(abs, _mm256_set1_pd(SNAP_LIMIT)))
    }

    /// The clip coordinates are made by the SSE2 code (`clip_lanes`):
    /// compiled into an AVX2 function its sums may take their operands
    /// in the other order, and of two NaNs x86 keeps the first, so a
    /// clip position could differ from the scalar stage's in a NaN's sign.
    #[inline(always)]
    pub unsafe fn transform_place(mvp: &Mat4, rs: &RenderState, obj: &Queue, k: usize, verts: &mut [ClipVertex], slots: [usize; LANES]) {
        let (c, inside, pos) = clip_lanes(mvp, obj);
        place(rs, &c, inside, &pos, k, verts, slots)
    }

    #[target_feature(enable = "avx2")]
    unsafe fn place(rs: &RenderState, c: &[__m128; 4], inside: i32, pos: &[__m128; LANES], k: usize, verts: &mut [ClipVertex], slots: [usize; LANES]) {
        let [cx, cy, cz, cw] = *c;
        // `setup::window_pos`: q = 1 / w, o + s * (c * q).
        let [sx, sy, sz] = rs.viewport_scale;
        let [ox, oy, oz] = rs.viewport_offset;
        let (px, py, pz, pw) = (_mm256_cvtps_pd(cx), _mm256_cvtps_pd(cy), _mm256_cvtps_pd(cz), _mm256_cvtps_pd(cw));
        let q = _mm256_div_pd(_mm256_set1_pd(1.0), pw);
        let wx = _mm256_add_pd(_mm256_set1_pd(ox), _mm256_mul_pd(_mm256_set1_pd(sx), _mm256_mul_pd(px, q)));
        let wy = _mm256_add_pd(_mm256_set1_pd(oy), _mm256_mul_pd(_mm256_set1_pd(sy), _mm256_mul_pd(py, q)));
        let wz = _mm256_add_pd(_mm256_set1_pd(oz), _mm256_mul_pd(_mm256_set1_pd(sz), _mm256_mul_pd(pz, q)));
        // Per lane (x, y, z, q): a 4x4 transpose.
        let t0 = _mm256_unpacklo_pd(wx, wy); // x0 y0 x2 y2
        let t1 = _mm256_unpackhi_pd(wx, wy); // x1 y1 x3 y3
        let t2 = _mm256_unpacklo_pd(wz, q); // z0 q0 z2 q2
        let t3 = _mm256_unpackhi_pd(wz, q); // z1 q1 z3 q3
        let win = [
            _mm256_permute2f128_pd::<0x20>(t0, t2),
            _mm256_permute2f128_pd::<0x20>(t1, t3),
            _mm256_permute2f128_pd::<0x31>(t0, t2),
            _mm256_permute2f128_pd::<0x31>(t1, t3),
        ];
        // Only inside lanes are snapped; one out of the 32-bit range (a
        // huge viewport) takes the scalar snap.
        let mut snapped = [_mm_setzero_si128(); LANES];
        if inside & !(snappable4(wx) & snappable4(wy)) == 0 {
            let (ix, iy) = (_mm256_cvtepi32_epi64(snap4(wx)), _mm256_cvtepi32_epi64(snap4(wy)));
            let lo = _mm256_unpacklo_epi64(ix, iy); // x0 y0 x2 y2
            let hi = _mm256_unpackhi_epi64(ix, iy); // x1 y1 x3 y3
            snapped = [_mm256_castsi256_si128(lo), _mm256_castsi256_si128(hi), _mm256_extracti128_si256::<1>(lo), _mm256_extracti128_si256::<1>(hi)];
        } else {
            let mut w = [[0.0f64; 4]; LANES];
            for (l, c) in w.iter_mut().zip(win) {
                _mm256_storeu_pd(l.as_mut_ptr(), c);
            }
            for (s, l) in snapped.iter_mut().zip(w) {
                let xy = [super::super::vertex::snap(l[0]), super::super::vertex::snap(l[1])];
                *s = _mm_loadu_si128(xy.as_ptr() as *const __m128i);
            }
        }
        for i in 0..k {
            let v = &mut verts[slots[i]];
            _mm_storeu_ps(&mut v.pos as *mut Vec4 as *mut f32, pos[i]);
            v.inside = (inside >> i) & 1 != 0;
            // Stored for outside vertices too: `win` and `snapped` are
            // never read unless `inside`.
            _mm256_storeu_pd(v.win.as_mut_ptr(), win[i]);
            _mm_storeu_si128(v.snapped.as_mut_ptr() as *mut __m128i, snapped[i]);
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn rng(seed: u64) -> impl FnMut() -> u64 {
        let mut s = seed;
        move || {
            s = s.wrapping_mul(6364136223846793005).wrapping_add(1442695040888963407);
            s >> 11
        }
    }

    /// The lanes give every vertex the bits the scalar vertex stage gives
    /// it: random matrices and positions (near the view volume, across the
    /// guard band, behind the eye, huge, tiny, zero, infinite, NaN), every
    /// batch length, random viewports (also huge ones, where the snap
    /// leaves the 32-bit lanes).
    #[test]
    fn lanes_match_scalar_vertex_stage() {
        let mut next = rng(11);
        let mut unit = move || (next() as f64 / (1u64 << 53) as f64) as f32;
        let specials = [0.0, -0.0, 1.0, -1.0, f32::INFINITY, f32::NEG_INFINITY, f32::NAN, 1e30, -1e30, 1e-30, 16.0, -16.0, f32::MAX, f32::MIN_POSITIVE];
        let mut rs = crate::gl::validate::Derived::default().render;
        for case in 0..40_000 {
            let mut m = [0.0f32; 16];
            for (i, e) in m.iter_mut().enumerate() {
                *e = if case % 5 == 0 && i % 5 == 0 { 1.0 } else { (unit() - 0.5) * [2.0, 8.0, 0.01, 300.0][case % 4] };
            }
            if case % 7 == 0 {
                // A projection-like last row: w = -z.
                m[3] = 0.0;
                m[7] = 0.0;
                m[11] = -1.0;
                m[15] = 0.0;
            }
            // A quarter of the cases are exact: the identity matrix and a
            // 512-pixel viewport, so clip coordinates are the object ones
            // and window x = 256 + 256 x lands on the snap's rounding ties
            // and on the clip planes' boundaries (|x| = 16 w, w = W_MIN).
            let exact = case % 4 == 3;
            let mvp = if exact { Mat4::IDENTITY } else { Mat4::from_cols_array(&m) };
            let (w, h) = match case % 9 {
                _ if exact => (512.0, 512.0),
                0 => (1e7, 1e7),
                1 => (1.0, 1.0),
                _ => ((unit() * 4000.0).floor() as f64, (unit() * 3000.0).floor() as f64),
            };
            rs.viewport_scale = [w / 2.0, h / 2.0, 0.5 * unit() as f64];
            rs.viewport_offset = [w / 2.0 + if exact { 0.0 } else { (unit() * 100.0) as f64 }, h / 2.0 - if exact { 0.0 } else { (unit() * 100.0) as f64 }, 0.5];
            let mut obj = Queue::ORIGIN;
            for lane in 0..LANES {
                let mut p = [0.0f32; 4];
                for c in p.iter_mut() {
                    *c = match (unit() * 10.0) as u32 {
                        0 => specials[(unit() * specials.len() as f32) as usize % specials.len()],
                        1 | 2 => (unit() - 0.5) * 100.0,
                        // Multiples of 1/131072: window x and y at every
                        // 1/512 pixel (half a subpixel) when exact.
                        3 | 4 if exact => ((unit() - 0.5) * 2.0 * 150_000.0).round() / 131_072.0,
                        _ => (unit() - 0.5) * 2.0,
                    };
                }
                if unit() < 0.7 {
                    p[3] = 1.0;
                }
                if exact && unit() < 0.2 {
                    // On and beside the w >= W_MIN and guard-band planes.
                    p[3] = [1e-20, 1e-21, 2e-20, 1e-20f32.next_up(), 1e-20f32.next_down(), 0.0, -1e-20][(unit() * 7.0) as usize % 7];
                    p[0] = [16.0 * p[3], -16.0 * p[3], (16.0 * p[3]).next_up(), p[0]][(unit() * 4.0) as usize % 4];
                }
                obj.set(lane, Vec4::from_array(p));
            }
            let k = 1 + case % LANES;
            let slots = [3, 0, 5, 1];
            let mut b = vec![ClipVertex::ZERO; 6];
            scalar(&mvp, &rs, &obj, k, &mut b, slots);
            for (variant, place) in variants() {
            let mut a = vec![ClipVertex::ZERO; 6];
            place(&mvp, &rs, &obj, k, &mut a, slots);
            let case = format!("{case} ({variant})");
            for i in 0..k {
                let (va, vb) = (&a[slots[i]], &b[slots[i]]);
                assert_eq!(va.pos.to_array().map(f32::to_bits), vb.pos.to_array().map(f32::to_bits), "case {case} lane {i}");
                assert_eq!(va.inside, vb.inside, "case {case} lane {i} {:?}", vb.pos);
                if vb.inside {
                    assert_eq!(va.win.map(f64::to_bits), vb.win.map(f64::to_bits), "case {case} lane {i}");
                    assert_eq!(va.snapped, vb.snapped, "case {case} lane {i}");
                }
            }
            // Slots of lanes past k are untouched.
            for s in 0..6 {
                if !slots[..k].contains(&s) {
                    assert_eq!(a[s], ClipVertex::ZERO);
                }
            }
            }
        }
    }

    type Place = fn(&Mat4, &RenderState, &Queue, usize, &mut [ClipVertex], [usize; LANES]);

    /// Every lane implementation this CPU runs, besides the dispatching
    /// `transform_place`.
    fn variants() -> Vec<(&'static str, Place)> {
        #[allow(unused_mut)]
        let mut v: Vec<(&'static str, Place)> = vec![("dispatch", transform_place)];
        #[cfg(target_arch = "x86_64")]
        {
            // SAFETY: SSE2 is part of x86-64.
            v.push(("sse2", |m, rs, o, k, vs, s| unsafe { sse2::transform_place(m, rs, o, k, vs, s) }));
            if std::arch::is_x86_feature_detected!("avx2") {
                // SAFETY: AVX2 detected above.
                v.push(("avx2", |m, rs, o, k, vs, s| unsafe { avx2::transform_place(m, rs, o, k, vs, s) }));
            }
        }
        v
    }
}
