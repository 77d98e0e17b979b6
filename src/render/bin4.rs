//! Binning up to four triangles at once (round 27): the batched vertex
//! path's flush (`gl::begin_end`, four vertices) completes up to four
//! triangles, and this finds their orientation (GL 1.5 section 3.5.1's
//! area sign), their culling and the box of pixel centres each covers
//! (`raster::CentreBox`) in SIMD lanes, then writes their records one
//! by one, in order (`tile::push_group`).
//!
//! The same decisions, in the same order of records, as
//! [`setup::bin_placed`] for each triangle: the area is exact (32-bit
//! differences, 64-bit products), the box is the same integer arithmetic
//! in 32 bits. A group with a coordinate beyond [`LIMIT`] (never after
//! the guard band at ordinary viewport sizes) takes `bin_placed` per
//! triangle. Why: per triangle, `bin_placed` was about 240 instructions
//! of the calling thread's 490 (spheres_l, 2 threads), more than half of
//! them the scalar minima, maxima, box and area, and the call's spills.

use super::setup;
use super::vertex::ClipVertex;
use super::RenderState;
use crate::framebuffer::Framebuffer;

/// Triangles a group holds: as many as one flush of the batched path can
/// complete (four vertices; a quad strip's two quads).
pub const GROUP: usize = 4;

/// Snapped coordinates within +-LIMIT take the lanes: their differences
/// fit in i32 and `tile::bounds` would never find them far.
#[cfg(target_arch = "x86_64")]
const LIMIT: i32 = 1 << 29;

/// The vertices of a group's triangles: vertex j of triangle i at
/// `[j][i]` (round 27: as three stores of a pointer each; a triangle's
/// three pointers written as an array and copied in were read back as
/// one 16-byte load from two 8-byte stores, a store-forwarding stall a
/// triangle).
pub type Verts<'a> = [[&'a ClipVertex; GROUP]; 3];

/// Up to [`GROUP`] triangles whose vertices are all inside the guard band,
/// each with the vertex whose colours flat shading takes.
pub struct Group<'a> {
    tris: Verts<'a>,
    provoking: [&'a ClipVertex; GROUP],
    len: usize,
}

impl<'a> Group<'a> {
    #[inline(always)]
    pub fn new(first: &'a ClipVertex) -> Group<'a> {
        Group { tris: [[first; GROUP]; 3], provoking: [first; GROUP], len: 0 }
    }

    /// Adds a triangle, binning the group first when it is full.
    #[inline(always)]
    pub fn push(&mut self, rs: &RenderState, fb: &mut Framebuffer, v: [&'a ClipVertex; 3], provoking: &'a ClipVertex) {
        if self.len == GROUP {
            self.bin(rs, fb);
        }
        let i = self.len;
        self.tris[0][i] = v[0];
        self.tris[1][i] = v[1];
        self.tris[2][i] = v[2];
        self.provoking[i] = provoking;
        self.len += 1;
    }

    /// Bins the triangles held, in order, and empties the group.
    #[inline(always)]
    pub fn bin(&mut self, rs: &RenderState, fb: &mut Framebuffer) {
        if self.len > 0 {
            bin_group(rs, fb, &self.tris, &self.provoking, self.len);
            self.len = 0;
        }
    }
}

/// Can this CPU bin in lanes (AVX2)? Asked once per flush by the caller.
#[inline(always)]
pub fn available() -> bool {
    #[cfg(target_arch = "x86_64")]
    {
        super::fragment::simd::level() == super::fragment::simd::Level::Avx2
    }
    #[cfg(not(target_arch = "x86_64"))]
    {
        false
    }
}

/// Bins the first `n` triangles of `tris` as [`setup::bin_placed`] would,
/// one after the other. Only called when [`available`].
#[inline(never)]
fn bin_group(rs: &RenderState, fb: &mut Framebuffer, tris: &Verts, provoking: &[&ClipVertex; GROUP], n: usize) {
    #[cfg(target_arch = "x86_64")]
    // SAFETY: `available` saw AVX2 before the group was filled.
    unsafe {
        avx2::bin_group(rs, fb, tris, provoking, n)
    }
    #[cfg(not(target_arch = "x86_64"))]
    per_triangle(rs, fb, tris, provoking, n)
}

/// [`bin_group`] by [`setup::bin_placed`], one triangle at a time.
#[cold]
#[inline(never)]
fn per_triangle(rs: &RenderState, fb: &mut Framebuffer, tris: &Verts, provoking: &[&ClipVertex; GROUP], n: usize) {
    for (i, p) in provoking.iter().enumerate().take(n) {
        setup::bin_placed(rs, fb, [tris[0][i], tris[1][i], tris[2][i]], [p.color, p.back_color]);
    }
}

/// What the lanes find of a group: lane i of the x halves (and
/// `GROUP + i` of the y halves) is triangle i's; bit i of the masks.
pub struct Found {
    /// The vertices' snapped x (lanes 0-3) and y (lanes 4-7).
    pub v: [[i32; 2 * GROUP]; 3],
    /// First column and row of the pixel centres in the box, cut to the
    /// draw rectangle (`raster::CentreBox`).
    pub lo: [i32; 2 * GROUP],
    /// One past the last column and row.
    pub hi: [i32; 2 * GROUP],
    /// The boxes as records store them: first column, first row, end
    /// column, end row in i16 (`tile::BinBox`).
    pub boxes: [[i16; 4]; GROUP],
    /// Counter-clockwise (positive area).
    pub ccw: u32,
    /// Front-facing.
    pub front: u32,
    /// The extents fit the cover's lanes (`raster::CentreBox::lanes_fit`).
    pub fit: u32,
    /// To be binned: some area, pixel centres in the box, not culled.
    pub keep: u32,
}

#[cfg(target_arch = "x86_64")]
mod avx2 {
    use super::*;
    use crate::framebuffer::Rect;
    use core::arch::x86_64::*;

    /// [`super::bin_group`] in AVX2: the lanes, then the records.
    #[target_feature(enable = "avx2")]
    pub(super) unsafe fn bin_group(rs: &RenderState, fb: &mut Framebuffer, tris: &Verts, provoking: &[&ClipVertex; GROUP], n: usize) {
        let mut found = std::mem::MaybeUninit::uninit();
        if !lanes(&mut found, tris, n, rs.draw_rect) {
            return per_triangle(rs, fb, tris, provoking, n);
        }
        let found = found.assume_init_mut();
        // `RenderState::facing` for the four at once: front when the
        // orientation is the front face's; culled faces are dropped.
        let all = (1 << GROUP) - 1;
        found.front = if rs.front_ccw { found.ccw } else { !found.ccw & all };
        let shown = match rs.cull {
            super::super::Cull::None => all,
            super::super::Cull::Front => !found.front & all,
            super::super::Cull::Back => found.front,
            super::super::Cull::All => 0,
        };
        found.keep &= shown & ((1 << n) - 1);
        super::super::tile::push_group(rs, fb, found, tris, provoking);
    }

    /// The lanes of all four slots of `tris` into `out`, of which the
    /// first `n` are the group's (the others hold earlier vertices: their
    /// lanes are computed and never read); false, with `out` not written,
    /// when a coordinate of the first `n` lies beyond [`LIMIT`]. `front`
    /// is left for the caller (0).
    #[target_feature(enable = "avx2")]
    #[inline]
    unsafe fn lanes(out: &mut std::mem::MaybeUninit<Found>, tris: &Verts, n: usize, rect: Rect) -> bool {
        // Vertex j of the four triangles: x in lanes 0-3, y in 4-7.
        let gather = |j: usize| {
            let p = |i: usize| tris[j][i].snapped.as_ptr() as *const __m128i;
            // Two triangles' (x, y) in i64 per 256 bits.
            let a = _mm256_loadu2_m128i(p(1), p(0)); // x0 y0 | x1 y1
            let b = _mm256_loadu2_m128i(p(3), p(2)); // x2 y2 | x3 y3
            // The low halves: x0 y0 x2 y2 | x1 y1 x3 y3; the high halves
            // the same places.
            let lo = _mm256_castps_si256(_mm256_shuffle_ps::<0b10_00_10_00>(_mm256_castsi256_ps(a), _mm256_castsi256_ps(b)));
            let hi = _mm256_castps_si256(_mm256_shuffle_ps::<0b11_01_11_01>(_mm256_castsi256_ps(a), _mm256_castsi256_ps(b)));
            // Within LIMIT: the high half is the low half's sign, and the
            // low half's magnitude is at most LIMIT.
            let sign = _mm256_cmpeq_epi32(hi, _mm256_srai_epi32::<31>(lo));
            let small = _mm256_and_si256(_mm256_cmpgt_epi32(_mm256_set1_epi32(LIMIT + 1), lo), _mm256_cmpgt_epi32(lo, _mm256_set1_epi32(-LIMIT - 1)));
            let order = _mm256_setr_epi32(0, 4, 2, 6, 1, 5, 3, 7);
            (_mm256_permutevar8x32_epi32(lo, order), _mm256_and_si256(sign, small))
        };
        let (p0, ok0) = gather(0);
        let (p1, ok1) = gather(1);
        let (p2, ok2) = gather(2);
        // Lanes x0 y0 x2 y2 | x1 y1 x3 y3 in `ok` (triangle 0: bits 0-1,
        // 1: 4-5, 2: 2-3, 3: 6-7); lanes past `n` may hold stale
        // coordinates (vertices never placed inside) and are not checked.
        let ok = _mm256_movemask_ps(_mm256_castsi256_ps(_mm256_and_si256(_mm256_and_si256(ok0, ok1), ok2)));
        const NEED: [i32; GROUP + 1] = [0, 0b11, 0b11_0011, 0b11_1111, 0b1111_1111];
        let need = NEED[n.min(GROUP)];
        if ok & need != need {
            return false;
        }
        // The box of the vertices, and its centres (`CentreBox::of`):
        // ceil((min - half) / ONE) to floor((max - half) / ONE), a shift
        // for the floor of a division by ONE.
        let min = _mm256_min_epi32(_mm256_min_epi32(p0, p1), p2);
        let max = _mm256_max_epi32(_mm256_max_epi32(p0, p1), p2);
        let half = _mm256_set1_epi32((setup::ONE / 2) as i32);
        let bits = _mm_cvtsi32_si128(setup::SUBPIXEL_BITS as i32);
        let first = _mm256_sub_epi32(_mm256_setzero_si256(), _mm256_sra_epi32(_mm256_sub_epi32(half, min), bits));
        let last = _mm256_add_epi32(_mm256_sra_epi32(_mm256_sub_epi32(max, half), bits), _mm256_set1_epi32(1));
        let r0 = _mm256_setr_epi32(rect.x0, rect.x0, rect.x0, rect.x0, rect.y0, rect.y0, rect.y0, rect.y0);
        let r1 = _mm256_setr_epi32(rect.x1, rect.x1, rect.x1, rect.x1, rect.y1, rect.y1, rect.y1, rect.y1);
        let lo = _mm256_max_epi32(first, r0);
        let hi = _mm256_min_epi32(last, r1);
        // Extents within the cover's lanes, x and y alike.
        let within = _mm256_cmpgt_epi32(_mm256_set1_epi32(super::super::raster::LANE_EXTENT as i32 + 1), _mm256_sub_epi32(max, min));
        let within = _mm256_movemask_ps(_mm256_castsi256_ps(within));
        // Twice the area, (x1 - x0)(y2 - y0) - (x2 - x0)(y1 - y0), in i64.
        let d1 = _mm256_sub_epi32(p1, p0); // dx1 | dy1
        let d2 = _mm256_permute2x128_si256::<0x01>(_mm256_sub_epi32(p2, p0), _mm256_setzero_si256()); // dy2 | dx2
        let wide = |v: __m256i, half: bool| _mm256_cvtepi32_epi64(if half { _mm256_extracti128_si256::<1>(v) } else { _mm256_castsi256_si128(v) });
        let a = _mm256_mul_epi32(wide(d1, false), wide(d2, false)); // dx1 dy2
        let b = _mm256_mul_epi32(wide(d1, true), wide(d2, true)); // dy1 dx2
        let area = _mm256_sub_epi64(a, b);
        let zero = _mm256_movemask_pd(_mm256_castsi256_pd(_mm256_cmpeq_epi64(area, _mm256_setzero_si256())));
        let ccw = _mm256_movemask_pd(_mm256_castsi256_pd(_mm256_cmpgt_epi64(area, _mm256_setzero_si256())));
        // Centres in the box: columns and rows both.
        let some = _mm256_movemask_ps(_mm256_castsi256_ps(_mm256_cmpgt_epi32(hi, lo)));
        let keep = (some & (some >> GROUP) & !zero) as u32 & ((1 << GROUP) - 1);
        let fit = (within & (within >> GROUP)) as u32 & ((1 << GROUP) - 1);
        // The boxes in i16 (values within the draw rectangle, saturated
        // where not kept): cols | rows, then per triangle (col0, row0,
        // col1, row1).
        let packed = _mm256_packs_epi32(lo, hi); // c0 x4, c1 x4 | r0 x4, r1 x4
        let (cols, rows) = (_mm256_castsi256_si128(packed), _mm256_extracti128_si256::<1>(packed));
        let (firsts, ends) = (_mm_unpacklo_epi16(cols, rows), _mm_unpackhi_epi16(cols, rows));
        let o = out.as_mut_ptr();
        let boxes = std::ptr::addr_of_mut!((*o).boxes) as *mut __m128i;
        _mm_storeu_si128(boxes, _mm_unpacklo_epi32(firsts, ends));
        _mm_storeu_si128(boxes.add(1), _mm_unpackhi_epi32(firsts, ends));
        let v = std::ptr::addr_of_mut!((*o).v) as *mut [i32; 2 * GROUP];
        for (j, p) in [p0, p1, p2].into_iter().enumerate() {
            _mm256_storeu_si256(v.add(j) as *mut __m256i, p);
        }
        _mm256_storeu_si256(std::ptr::addr_of_mut!((*o).lo) as *mut __m256i, lo);
        _mm256_storeu_si256(std::ptr::addr_of_mut!((*o).hi) as *mut __m256i, hi);
        std::ptr::addr_of_mut!((*o).ccw).write(ccw as u32);
        std::ptr::addr_of_mut!((*o).front).write(0);
        std::ptr::addr_of_mut!((*o).fit).write(fit);
        std::ptr::addr_of_mut!((*o).keep).write(keep);
        true
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::framebuffer::Config;
    use crate::gl::enums::*;
    use crate::gl::{Command, Context};
    use glam::Vec4;

    const W: usize = 300;
    const H: usize = 200;

    /// A context that bins (two threads) under the state of case `n`
    /// (shading, culling, front face, two-sided lighting, scissor, fog)
    /// and never hands its batch over.
    fn context(n: u32) -> Context {
        let mut c = Context::new(Config { alpha_bits: 8, depth_bits: 24, stencil_bits: 8, accum_bits: 0 });
        c.fb.resize(W, H).unwrap();
        c.surface_resized(W as i32, H as i32);
        c.derived.render.reference = false;
        c.derived.render.threads = 2;
        crate::render::tile::set_batch_limits(&c.derived.render, crate::render::tile::MAX_BATCH, u64::MAX, u64::MAX);
        let mut cmds = vec![Command::ShadeModel(if n.is_multiple_of(3) { GL_FLAT } else { GL_SMOOTH })];
        match n % 5 {
            1 => cmds.extend([Command::Enable(GL_CULL_FACE), Command::CullFace(GL_BACK)]),
            2 => cmds.extend([Command::Enable(GL_CULL_FACE), Command::CullFace(GL_FRONT)]),
            3 if n % 4 == 3 => cmds.extend([Command::Enable(GL_CULL_FACE), Command::CullFace(GL_FRONT_AND_BACK)]),
            _ => {}
        }
        cmds.push(Command::FrontFace(if n % 2 == 1 { GL_CW } else { GL_CCW }));
        if n % 4 == 1 {
            cmds.extend([Command::Enable(GL_LIGHTING), Command::LightModel(GL_LIGHT_MODEL_TWO_SIDE, [1.0, 0.0, 0.0, 0.0])]);
        }
        if n.is_multiple_of(6) {
            cmds.extend([Command::Enable(GL_SCISSOR_TEST), Command::Scissor(20 + (n % 13) as i32, 10, 200, 150)]);
        }
        if n % 7 == 3 {
            cmds.push(Command::Enable(GL_FOG));
        }
        for cmd in &cmds {
            c.execute(cmd);
        }
        c.validate();
        c
    }

    /// A placed vertex near (cx, cy) pixels, `spread` subpixels around.
    fn vertex(r: &mut impl FnMut(i64) -> i64, cx: i64, cy: i64, spread: i64) -> ClipVertex {
        let x = cx * setup::ONE + r(2 * spread + 1) - spread;
        let y = cy * setup::ONE + r(2 * spread + 1) - spread;
        let u = |r: &mut dyn FnMut(i64) -> i64| r(1 << 20) as f32 / (1 << 20) as f32;
        let mut v = ClipVertex::ZERO;
        v.inside = true;
        v.snapped = [x, y];
        v.win = [x as f64 / setup::ONE as f64, y as f64 / setup::ONE as f64, u(r) as f64, 0.5 + u(r) as f64];
        v.color = Vec4::new(u(r), u(r), u(r), 1.0);
        v.back_color = Vec4::new(u(r), u(r), u(r), u(r));
        v.fog = u(r);
        v
    }

    /// Groups of one to four triangles binned by `bin_group` leave the
    /// same records, boxes and work, bit for bit, as `setup::bin_placed`
    /// called per triangle: tiny, small and large triangles, ones without
    /// area, without pixel centres, partly or wholly outside the draw
    /// rectangle, with coordinates past the lanes' limit (the group falls
    /// back) and extents past the cover's lanes, under every culling,
    /// facing, flat and two-sided state, with and without extras (fog).
    #[test]
    fn groups_bin_as_bin_placed() {
        if !available() {
            return;
        }
        let mut r = crate::render::test_rng::below(0x27, 20);
        let (mut records, mut fallbacks, mut dropped) = (0, 0, 0);
        for n in 0..1500u32 {
            let (mut grouped, mut single) = (context(n), context(n));
            let mut verts = Vec::new();
            let groups = 1 + r(3) as usize;
            let sizes: Vec<usize> = (0..groups).map(|_| 1 + r(4) as usize).collect();
            for _ in 0..sizes.iter().sum::<usize>() * 3 {
                let (cx, cy) = (r(W as i64 + 40) - 20, r(H as i64 + 40) - 20);
                let spread = match r(10) {
                    0 => 0,
                    1 => 80 * setup::ONE,
                    2 => 1 << 15,
                    _ => 3 * setup::ONE,
                };
                let mut v = vertex(&mut r, cx, cy, spread);
                if r(40) == 0 {
                    // Past the lanes' limit, within i32: binned all the same.
                    v.snapped[r(2) as usize] = (1 << 29) + r(1 << 30);
                }
                if r(30) == 0 {
                    // A repeated vertex: no area.
                    v.snapped = verts.last().map_or(v.snapped, |p: &ClipVertex| p.snapped);
                }
                verts.push(v);
            }
            let mut at = 0;
            for &len in &sizes {
                let tri = |i: usize| [&verts[at + 3 * i], &verts[at + 3 * i + 1], &verts[at + 3 * i + 2]];
                let mut group = Group::new(&verts[0]);
                for i in 0..len {
                    group.push(&grouped.derived.render, &mut grouped.fb, tri(i), tri(i)[(i + n as usize) % 3]);
                    setup::bin_placed(&single.derived.render, &mut single.fb, tri(i), {
                        let p = tri(i)[(i + n as usize) % 3];
                        [p.color, p.back_color]
                    });
                }
                let far = (0..3 * len).any(|k| verts[at + k].snapped.iter().any(|c| c.abs() > LIMIT as i64));
                fallbacks += far as u32;
                group.bin(&grouped.derived.render, &mut grouped.fb);
                at += 3 * len;
            }
            let (a, b) = (crate::render::tile::filling_bytes(&grouped.derived.render), crate::render::tile::filling_bytes(&single.derived.render));
            assert_eq!(a.0.len(), b.0.len(), "case {n}: record count");
            for (k, (x, y)) in a.0.iter().zip(&b.0).enumerate() {
                assert_eq!(x, y, "case {n}: record {k}");
            }
            assert_eq!(a.1, b.1, "case {n}: boxes");
            assert_eq!(a.2, b.2, "case {n}: work");
            records += a.0.len();
            dropped += sizes.iter().sum::<usize>() - a.0.len();
        }
        assert!(records > 3000 && dropped > 1000 && fallbacks > 20, "records {records}, dropped {dropped}, fallbacks {fallbacks}");
    }
}
