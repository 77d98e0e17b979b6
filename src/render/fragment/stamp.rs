//! Small triangles shaded as one block (GL 1.5 section 4.1, the per-fragment
//! operations of [`super::fast`]'s kernels; round 13, widened in round 14).
//!
//! A triangle whose pixel centres fit a block of up to 32 columns and 48
//! rows (`raster::Cover`: the sphere scenes' triangles at 1920x1080, and
//! spheres_l's and the million-vertex scenes' tiny ones, round 15)
//! is covered all at once and shaded here, per row each group of four
//! columns holding a covered pixel in one set of lanes, instead of as a
//! run per row through a span kernel (whose fixed cost per span, and
//! `Runs::find`'s row solving, were most of the work on short spans).
//!
//! Covered: no stencil or alpha test; depth off, or LESS / LEQUAL with
//! depth writes; colour flat, constant, affine or perspective, or fogged
//! (untextured: flat or smooth colour, affine or perspective; round 15),
//! not stepped or textured; colour stored unmasked, or not written. Other
//! states shade the cover's runs with their span kernel.
//!
//! Exactness: each lane computes, operation for operation, what the scalar
//! span kernel (`fast::kernel`) computes for its pixel, so the same bits:
//! - centres: `cx = x + 1/2 - x0` and `cy = y + 1/2 - y0` are multiples of
//!   1/256 far below 2^44, exact however formed;
//! - row terms `a0 + dy * cy` (depth, 1/w, each colour channel), then per
//!   pixel `r + dx * cx`, separate IEEE f64 multiplies and adds (no FMA);
//!   perspective colour times `1 / (qr + qdx * cx)`, a correctly rounded
//!   division per pixel;
//! - depth clamped with max / min (NaN to 0, as the scalar clamp and cast),
//!   scaled by `DEPTH_MAX`, plus 1/2, truncated: `depth_to_fixed`;
//!   compared unsigned (sign bits flipped);
//! - colour channels to f32 (round to nearest), then `color_to_u8`'s f32
//!   clamp, x255, +1/2, truncation; a constant colour's row term is
//!   `a0 + (+-0)`, the same for every row, so it is converted once;
//! - fog (`CS_FOG`, `fast::fog_color`'s operations): one 1/w for colour
//!   and fog value, the value `(r + dx * cx) * w` to f32, f by
//!   `fog::lanes::factors` (`Fog::fragment_factor` per lane), a smooth
//!   colour clamped to [0, 1] (max then min, as glam's) or the flat colour
//!   as bytes / 255, then `fog::lanes::mix` per channel, alpha kept.
//!
//! Only covered pixels change. A block whose 32 columns lie inside the
//! rows reads each group's four pixels and writes back, in the lanes it
//! does not shade, the values it read (plain loads, blends and stores:
//! round 15); the rows are the band's, drawn by this thread alone, so no
//! other writer can be overwritten, and pixels outside the scissor
//! rectangle keep their values. A block reaching the buffer's right edge
//! reads and writes the covered pixels only (masked loads and stores),
//! so nothing past the edge (the next row, or the buffer's end) is
//! touched.

use super::fast::{depth_key, CO_NONE, CO_STORE, CS_FLAT, CS_GENERAL, CS_STEPPED, D_ANY, D_LEQUAL, D_LESS, D_OFF};
#[cfg(target_arch = "x86_64")]
use super::fast::{CS_AFFINE, CS_CONSTANT, CS_FOG, CS_PERSPECTIVE};
use super::FragmentState;
use crate::render::raster::Cover;
use crate::render::setup::TriangleSetup;

/// Where a block is shaded: a framebuffer's (or band's) colour and depth
/// planes, `width` pixels a row, pixel (x, y) at `y * width + x`.
#[derive(Clone, Copy)]
pub struct Target {
    pub color: *mut [u8; 4],
    pub depth: *mut u32,
    pub width: usize,
}

impl Target {
    /// The framebuffer's colour buffer and depth (the stamp is never used
    /// while drawing to two colour buffers: callers check `draw_both`).
    pub fn of(fb: &mut crate::framebuffer::Framebuffer) -> Target {
        Target { color: fb.color.as_mut_ptr(), depth: fb.depth.as_mut_ptr(), width: fb.width }
    }
}

/// A block shader: shades `cover`'s pixels of triangle `t` into the
/// target, returning how many passed the depth test.
///
/// Safety: every covered pixel lies inside the target's planes (and its
/// depth plane exists when the state tests depth), and no other thread
/// reads or writes those pixels meanwhile.
pub type StampKernel = unsafe fn(&FragmentState, &TriangleSetup, &Target, &Cover) -> u64;

/// The block shader for a triangle under a fragment state, if this state
/// and triangle have one (the cases of the module comment) and the CPU
/// has AVX2: mirrors [`super::fast::select`]'s choice of colour source, so
/// that the kernel computes what the span kernel would.
pub fn select(fs: &FragmentState, t: &TriangleSetup, approximate: bool) -> Option<StampKernel> {
    if fs.alpha_test || fs.stencil_test || super::simd::level_here() != super::simd::Level::Avx2 {
        return None;
    }
    let d = depth_key(fs);
    if d == D_ANY {
        return None;
    }
    match super::fast::color_op(fs) {
        CO_NONE => pick_d(d, CS_FLAT, CO_NONE),
        CO_STORE => match super::fast::color_source(t, approximate, CO_STORE) {
            // Textures have no block kernel; a stepped colour is the span
            // kernels' 16.16 approximation.
            CS_GENERAL | CS_STEPPED => None,
            cs => pick_d(d, cs, CO_STORE),
        },
        _ => None,
    }
}

fn pick_d(d: u8, cs: u8, co: u8) -> Option<StampKernel> {
    match d {
        D_OFF => pick_cs::<D_OFF>(cs, co),
        D_LESS => pick_cs::<D_LESS>(cs, co),
        _ => pick_cs::<D_LEQUAL>(cs, co),
    }
}

#[cfg(target_arch = "x86_64")]
fn pick_cs<const D: u8>(cs: u8, co: u8) -> Option<StampKernel> {
    use x86::stamp_avx2;
    Some(match (cs, co) {
        (_, CO_NONE) => stamp_avx2::<D, CS_FLAT, CO_NONE>,
        (CS_FLAT, _) => stamp_avx2::<D, CS_FLAT, CO_STORE>,
        (CS_CONSTANT, _) => stamp_avx2::<D, CS_CONSTANT, CO_STORE>,
        (CS_AFFINE, _) => stamp_avx2::<D, CS_AFFINE, CO_STORE>,
        (CS_FOG, _) => stamp_avx2::<D, CS_FOG, CO_STORE>,
        _ => stamp_avx2::<D, CS_PERSPECTIVE, CO_STORE>,
    })
}

#[cfg(not(target_arch = "x86_64"))]
fn pick_cs<const D: u8>(_: u8, _: u8) -> Option<StampKernel> {
    None
}

#[cfg(target_arch = "x86_64")]
mod x86 {
    use super::super::fast::{CO_NONE, CS_AFFINE, CS_CONSTANT, CS_FLAT, CS_FOG, CS_PERSPECTIVE, D_LESS, D_OFF};
    use super::super::{color_to_u8, FragmentState};
    use super::Target;
    use crate::framebuffer::DEPTH_MAX;
    use crate::render::fog::{lanes as fog_lanes, Fog};
    use crate::render::raster::Cover;
    use crate::render::setup::TriangleSetup;
    use std::arch::x86_64::*;

    /// `color_to_u8` of eight f32 lanes (two channels of four pixels), as
    /// i32 lanes in [0, 255]: max first, so NaN gives 0 as the scalar
    /// clamp-then-cast does.
    #[inline(always)]
    unsafe fn to_u8_lanes(c: __m256) -> __m256i {
        let c = _mm256_min_ps(_mm256_max_ps(c, _mm256_setzero_ps()), _mm256_set1_ps(1.0));
        _mm256_cvttps_epi32(_mm256_add_ps(_mm256_mul_ps(c, _mm256_set1_ps(255.0)), _mm256_set1_ps(0.5)))
    }

    /// Four pixels' RGBA bytes from their channels' f32 lanes.
    #[inline(always)]
    unsafe fn pixels(r: __m128, g: __m128, b: __m128, a: __m128) -> __m128i {
        let rg = to_u8_lanes(_mm256_set_m128(g, r));
        let ba = to_u8_lanes(_mm256_set_m128(a, b));
        // i16 lanes: r0..r3 b0..b3 | g0..g3 a0..a3; then bytes
        // r0..r3 b0..b3 g0..g3 a0..a3, gathered pixel by pixel.
        let w = _mm256_packs_epi32(rg, ba);
        let bytes = _mm_packus_epi16(_mm256_castsi256_si128(w), _mm256_extracti128_si256::<1>(w));
        _mm_shuffle_epi8(bytes, _mm_setr_epi8(0, 8, 4, 12, 1, 9, 5, 13, 2, 10, 6, 14, 3, 11, 7, 15))
    }

    /// One channel of four pixels: `(r + dx * cx) * w` (w only under
    /// perspective), to f32; `d` is the channel's `dx * cx` ([`Steps`]).
    #[inline(always)]
    unsafe fn channel<const CS: u8>(r: __m256d, d: __m256d, w: __m256d) -> __m128 {
        let v = _mm256_add_pd(r, d);
        _mm256_cvtpd_ps(if CS == CS_PERSPECTIVE { _mm256_mul_pd(v, w) } else { v })
    }

    /// `dx * cx`: a plane's slope times the lanes' centre offsets.
    #[inline(always)]
    unsafe fn step(dx: f64, cx: __m256d) -> __m256d {
        _mm256_mul_pd(_mm256_set1_pd(dx), cx)
    }

    /// The per-pixel terms `dx * cx` of a group of four columns (centre
    /// offsets `cx`): depth, 1/w, the four colour channels, the fog value
    /// (fogged only). Round 17: computed once a block for the groups at
    /// the block's first column (every group of a narrow block), and per
    /// group for the others.
    struct Steps {
        z: __m256d,
        q: __m256d,
        c: [__m256d; 4],
        f: __m256d,
    }

    impl Steps {
        #[inline(always)]
        unsafe fn at<const CS: u8>(t: &TriangleSetup, fogged: Option<&Fogged>, cx: __m256d) -> Steps {
            let z = step(t.z.dx, cx);
            let (mut q, mut c, mut f) = (z, [z; 4], z);
            if CS == CS_AFFINE || CS == CS_PERSPECTIVE || CS == CS_FOG {
                q = step(t.q.dx, cx);
                c = [step(t.color[0].dx, cx), step(t.color[1].dx, cx), step(t.color[2].dx, cx), step(t.color[3].dx, cx)];
            }
            if let Some(fg) = fogged {
                f = step(fg.dx, cx);
            }
            Steps { z, q, c, f }
        }
    }

    /// A fogged triangle's fog for the block: its fog value plane, the
    /// fog parameters, and the colours in lanes (each channel in all four).
    struct Fogged {
        fog: Fog,
        a0: f64,
        dy: f64,
        dx: f64,
        /// The fog colour's r, g, b.
        color: [__m128; 3],
        /// Flat shading: the provoking colour as bytes / 255 (as
        /// `fast::FogRow`), unclamped.
        flat: Option<[__m128; 4]>,
        perspective: bool,
    }

    impl Fogged {
        #[inline(always)]
        unsafe fn of(t: &TriangleSetup) -> Option<Fogged> {
            let (p, fog) = t.fog.as_ref()?;
            // (Written out, not `map`: round 17's `Block::of`, inlined in
            // two kernels, left `map` an out-of-line call.)
            let byte = |v: u8| _mm_set1_ps(v as f32 / 255.0);
            let flat = t.flat.map(|c| [byte(c[0]), byte(c[1]), byte(c[2]), byte(c[3])]);
            let color = [_mm_set1_ps(fog.color[0]), _mm_set1_ps(fog.color[1]), _mm_set1_ps(fog.color[2])];
            Some(Fogged { fog: *fog, a0: p.a0, dy: p.dy, dx: p.dx, color, flat, perspective: t.perspective })
        }
    }

    /// Four fogged pixels' colour bytes, `fast::fog_color` lane by lane:
    /// `w` their 1/w (1 when affine), `cr` the colour row terms, `bits`
    /// the lanes written (the others' f is not computed).
    #[inline(always)]
    unsafe fn fog_pixels(fg: &Fogged, cy: f64, s: &Steps, w: __m256d, cr: __m256d, bits: i32) -> __m128i {
        let v = channel::<CS_PERSPECTIVE>(_mm256_set1_pd(fg.a0 + fg.dy * cy), s.f, w);
        let f = fog_lanes::factors::<true>(&fg.fog, v, bits);
        let [r, g, b, a] = match fg.flat {
            Some(c) => c,
            None => {
                let clamp = |c: __m128| _mm_min_ps(_mm_max_ps(c, _mm_setzero_ps()), _mm_set1_ps(1.0));
                [
                    clamp(channel::<CS_PERSPECTIVE>(_mm256_permute4x64_pd::<0x00>(cr), s.c[0], w)),
                    clamp(channel::<CS_PERSPECTIVE>(_mm256_permute4x64_pd::<0x55>(cr), s.c[1], w)),
                    clamp(channel::<CS_PERSPECTIVE>(_mm256_permute4x64_pd::<0xAA>(cr), s.c[2], w)),
                    clamp(channel::<CS_PERSPECTIVE>(_mm256_permute4x64_pd::<0xFF>(cr), s.c[3], w)),
                ]
            }
        };
        pixels(fog_lanes::mix(r, f, fg.color[0]), fog_lanes::mix(g, f, fg.color[1]), fog_lanes::mix(b, f, fg.color[2]), a)
    }

    /// What every group of a block shares: the colour planes' row-term
    /// inputs (channels side by side), the block's colour (flat or
    /// constant) with the fixed alpha, the fixed alpha alone, the fog.
    struct Block {
        ca0: __m256d,
        cdy: __m256d,
        src: __m128i,
        afix: __m128i,
        fogged: Option<Fogged>,
    }

    impl Block {
        #[inline(always)]
        unsafe fn of<const CS: u8>(fs: &FragmentState, t: &TriangleSetup, c: &Cover) -> Block {
            let afix = _mm_set1_epi32(((fs.alpha_fix as u32) << 24) as i32);
            let ca0 = _mm256_setr_pd(t.color[0].a0, t.color[1].a0, t.color[2].a0, t.color[3].a0);
            let cdy = _mm256_setr_pd(t.color[0].dy, t.color[1].dy, t.color[2].dy, t.color[3].dy);
            let fogged = if CS == CS_FOG { Fogged::of(t) } else { None };
            let mut src = _mm_setzero_si128();
            if CS == CS_FLAT {
                src = _mm_set1_epi32(u32::from_ne_bytes(t.flat.unwrap_or_default()) as i32);
            } else if CS == CS_CONSTANT {
                // a0 + (+-0) * cy: the same value in every row (module comment).
                let cy = c.row0 as i64 as f64 + 0.5 - t.y0;
                // (Written out, not `map`: see `Fogged::of`; 41 instructions
                // a call on immediate_1m.)
                let row = |ch: usize| (t.color[ch].a0 + t.color[ch].dy * cy) as f32;
                let cr = [row(0), row(1), row(2), row(3)];
                src = _mm_set1_epi32(u32::from_ne_bytes(color_to_u8(glam::Vec4::from_array(cr))) as i32);
            }
            Block { ca0, cdy, src: _mm_or_si128(src, afix), afix, fogged }
        }
    }

    /// The centre offsets `x + 1/2 - x0` of the block's first four columns.
    #[inline(always)]
    unsafe fn first_columns(t: &TriangleSetup, c: &Cover) -> __m256d {
        // (Through i64: one conversion instruction, not usize's several.)
        let cx0 = c.col0 as i64 as f64 + 0.5 - t.x0;
        _mm256_add_pd(_mm256_set1_pd(cx0), _mm256_setr_pd(0.0, 1.0, 2.0, 3.0))
    }

    /// Four pixels of row `cy`, columns `at .. at + 4` of the target, the
    /// covered ones (`nibble`) only (FULL: all four read, the others
    /// written back as read; else masked loads and stores): depth (row
    /// term `zr`, per pixel `zr + dx * cx`), then colour (the planes' row
    /// terms and per pixel values, perspective divided, fogged), or the
    /// block's `src`. Returns the passing lanes (all ones).
    #[inline(always)]
    #[allow(clippy::too_many_arguments)]
    unsafe fn group<const D: u8, const CS: u8, const CO: u8, const FULL: bool>(px: &Target, t: &TriangleSetup, at: usize, nibble: u32, cy: f64, zr: __m256d, s: &Steps, b: &Block) -> __m128i {
        let bit = _mm_setr_epi32(1, 2, 4, 8);
        let one = _mm256_set1_pd(1.0);
        let mut lanes = _mm_cmpeq_epi32(_mm_and_si128(_mm_set1_epi32(nibble as i32), bit), bit);
        if D != D_OFF {
            let z = _mm256_add_pd(zr, s.z);
            let z = _mm256_min_pd(_mm256_max_pd(z, _mm256_setzero_pd()), one);
            let z = _mm256_cvttpd_epi32(_mm256_add_pd(_mm256_mul_pd(z, _mm256_set1_pd(DEPTH_MAX as f64)), _mm256_set1_pd(0.5)));
            let dp = px.depth.add(at).cast::<i32>();
            let stored = if FULL { _mm_loadu_si128(dp.cast()) } else { _mm_maskload_epi32(dp, lanes) };
            let sign = _mm_set1_epi32(i32::MIN);
            let (zs, ss) = (_mm_xor_si128(z, sign), _mm_xor_si128(stored, sign));
            let pass = if D == D_LESS { _mm_cmplt_epi32(zs, ss) } else { _mm_xor_si128(_mm_cmpgt_epi32(zs, ss), _mm_set1_epi32(-1)) };
            lanes = _mm_and_si128(lanes, pass);
            if !FULL {
                _mm_maskstore_epi32(dp, lanes, z);
            } else if _mm_testz_si128(lanes, lanes) == 0 {
                // The failing and uncovered lanes store what they read.
                _mm_storeu_si128(dp.cast(), _mm_blendv_epi8(stored, z, lanes));
            }
        }
        let m = _mm_movemask_ps(_mm_castsi128_ps(lanes));
        if CO != CO_NONE && m != 0 {
            let mut src = b.src;
            if CS == CS_AFFINE || CS == CS_PERSPECTIVE {
                // The colour row terms (`a0 + dy * cy`, the channels side
                // by side), only for groups that store: the same values
                // in each group of a row.
                let cr = _mm256_add_pd(b.ca0, _mm256_mul_pd(b.cdy, _mm256_set1_pd(cy)));
                let w = if CS == CS_PERSPECTIVE {
                    let qr = _mm256_set1_pd(t.q.a0 + t.q.dy * cy);
                    _mm256_div_pd(one, _mm256_add_pd(qr, s.q))
                } else {
                    one
                };
                let r = channel::<CS>(_mm256_permute4x64_pd::<0x00>(cr), s.c[0], w);
                let g = channel::<CS>(_mm256_permute4x64_pd::<0x55>(cr), s.c[1], w);
                let bl = channel::<CS>(_mm256_permute4x64_pd::<0xAA>(cr), s.c[2], w);
                let a = channel::<CS>(_mm256_permute4x64_pd::<0xFF>(cr), s.c[3], w);
                src = _mm_or_si128(pixels(r, g, bl, a), b.afix);
            } else if let (CS_FOG, Some(fg)) = (CS, b.fogged.as_ref()) {
                // As CS_PERSPECTIVE's, but the colour row terms only for
                // smooth colour and 1/w only under perspective
                // (`fast::fog_color`'s w is 1 otherwise).
                let cr = if fg.flat.is_none() { _mm256_add_pd(b.ca0, _mm256_mul_pd(b.cdy, _mm256_set1_pd(cy))) } else { b.ca0 };
                let w = if fg.perspective {
                    let qr = _mm256_set1_pd(t.q.a0 + t.q.dy * cy);
                    _mm256_div_pd(one, _mm256_add_pd(qr, s.q))
                } else {
                    one
                };
                src = _mm_or_si128(fog_pixels(fg, cy, s, w, cr, m), b.afix);
            }
            let cp = px.color.add(at).cast::<i32>();
            if FULL {
                _mm_storeu_si128(cp.cast(), _mm_blendv_epi8(_mm_loadu_si128(cp.cast()), src, lanes));
            } else {
                _mm_maskstore_epi32(cp, lanes, src);
            }
        }
        lanes
    }

    /// The block kernel: the cover's rows bottom to top, each row's groups
    /// of four columns that hold a covered pixel in the lanes, only the
    /// covered pixels changed (module comment). Round 17: a narrow cover
    /// (at most four columns: spheres_l's tiny triangles, 2.9 rows and 1.5
    /// storing groups a call) is shaded here, one group a row, its
    /// per-pixel terms computed once and few values live across the rows;
    /// wider ones by [`wide`], out of line, so that its set-up (the
    /// slopes in lanes for groups further right, hoisted and spilled: a
    /// 512-byte frame, about 85 instructions a call) is not paid here.
    #[target_feature(enable = "avx2")]
    pub(super) unsafe fn stamp_avx2<const D: u8, const CS: u8, const CO: u8>(fs: &FragmentState, t: &TriangleSetup, px: &Target, c: &Cover) -> u64 {
        if !c.narrow() {
            return wide::<D, CS, CO>(fs, t, px, c);
        }
        let b = Block::of::<CS>(fs, t, c);
        let s = Steps::at::<CS>(t, b.fogged.as_ref(), first_columns(t, c));
        // The group's four pixels lie within the row (the rows are the
        // band's): plain loads and stores (as `wide`'s FULL), else masked.
        if c.col0 + 4 <= px.width {
            narrow::<D, CS, CO, true>(px, t, c, &s, &b)
        } else {
            narrow::<D, CS, CO, false>(px, t, c, &s, &b)
        }
    }

    /// [`stamp_avx2`]'s rows for a narrow cover: one group a row, the
    /// passing lanes counted in lanes; `cy` stepped by one a row (exact:
    /// multiples of 1/256 far below 2^44, module comment).
    #[inline(always)]
    unsafe fn narrow<const D: u8, const CS: u8, const CO: u8, const FULL: bool>(px: &Target, t: &TriangleSetup, c: &Cover, s: &Steps, b: &Block) -> u64 {
        let mut count = _mm_setzero_si128();
        let mut cy = c.row0 as i64 as f64 + 0.5 - t.y0;
        let mut at = c.row0 * px.width + c.col0;
        for bits in c.row_bits() {
            if bits != 0 {
                // The depth row term, as the span kernel computes it once
                // a row (`a0 + dy * cy`).
                let zr = _mm256_set1_pd(t.z.a0 + t.z.dy * cy);
                // Passing lanes are -1: subtracting counts them.
                count = _mm_sub_epi32(count, group::<D, CS, CO, FULL>(px, t, at, bits, cy, zr, s, b));
            }
            cy += 1.0;
            at += px.width;
        }
        let count = _mm_add_epi32(count, _mm_shuffle_epi32::<0b01_00_11_10>(count));
        let count = _mm_add_epi32(count, _mm_shuffle_epi32::<0b10_11_00_01>(count));
        _mm_cvtsi128_si32(count) as u32 as u64
    }

    /// [`stamp_avx2`] for covers wider than four columns.
    #[target_feature(enable = "avx2")]
    #[inline(never)]
    unsafe fn wide<const D: u8, const CS: u8, const CO: u8>(fs: &FragmentState, t: &TriangleSetup, px: &Target, c: &Cover) -> u64 {
        let b = Block::of::<CS>(fs, t, c);
        let cx = first_columns(t, c);
        let s0 = Steps::at::<CS>(t, b.fogged.as_ref(), cx);
        // Round 15: masked loads and stores (`vpmaskmovd`) are slow on
        // some CPUs (AMD Zen 3 here: about 9.5 ns a group of four against
        // 3 ns with plain loads, blends and stores), so a cover whose
        // block lies inside the rows (every group's four pixels within
        // the row: the rows are the band's, drawn by this thread alone)
        // reads all four lanes and stores back what it read in the lanes
        // it does not write; only a block reaching the buffer's right edge
        // keeps the masked forms (past the edge lie the next row, or the
        // end of the buffer).
        let full = c.col0 + Cover::COLS as usize <= px.width;
        let mut passed = 0u64;
        let mut at = c.row0 * px.width + c.col0;
        let mut row = c.row0;
        for bits in c.row_bits() {
            if bits != 0 {
                let cy = row as i64 as f64 + 0.5 - t.y0;
                // The depth row term, as the span kernel computes it once
                // a row (`a0 + dy * cy`).
                let zr = _mm256_set1_pd(t.z.a0 + t.z.dy * cy);
                if bits < 16 {
                    // One group.
                    let lanes = if full { group::<D, CS, CO, true>(px, t, at, bits, cy, zr, &s0, &b) } else { group::<D, CS, CO, false>(px, t, at, bits, cy, zr, &s0, &b) };
                    passed += _mm_movemask_ps(_mm_castsi128_ps(lanes)).count_ones() as u64;
                } else {
                    // The groups of four columns with a covered pixel
                    // (the centres `cx + 4 g` are exact: multiples of 1/256).
                    let mut bits = bits;
                    while bits != 0 {
                        let g = bits.trailing_zeros() & !3;
                        let nibble = (bits >> g) & 15;
                        bits &= !(15 << g);
                        let s = Steps::at::<CS>(t, b.fogged.as_ref(), _mm256_add_pd(cx, _mm256_set1_pd(g as f64)));
                        let at = at + g as usize;
                        let lanes = if full { group::<D, CS, CO, true>(px, t, at, nibble, cy, zr, &s, &b) } else { group::<D, CS, CO, false>(px, t, at, nibble, cy, zr, &s, &b) };
                        passed += _mm_movemask_ps(_mm_castsi128_ps(lanes)).count_ones() as u64;
                    }
                }
            }
            row += 1;
            at += px.width;
        }
        passed
    }
}

#[cfg(all(test, target_arch = "x86_64"))]
mod tests {
    use super::super::{fast, reference, ColorOp, CompareFunc, SpanPixels};
    use super::*;
    use crate::framebuffer::{Rect, DEPTH_MAX};
    use crate::render::fog::{Fog, GL_EXP, GL_EXP2, GL_LINEAR};
    use crate::render::raster::Cover;
    use crate::render::setup::{Plane, ONE};

    /// A random plane whose values over the block lie in about
    /// [lo, hi], at times constant (zero slopes of either sign).
    fn plane(rnd: &mut impl FnMut(i64) -> i64, lo: f64, hi: f64, constant: bool) -> Plane {
        let u = |rnd: &mut dyn FnMut(i64) -> i64| rnd(1 << 20) as f64 / (1 << 20) as f64;
        let a0 = lo + (hi - lo) * u(rnd);
        if constant {
            let z = if rnd(2) == 0 { 0.0 } else { -0.0 };
            return Plane { a0, dx: z, dy: z };
        }
        let slope = (hi - lo) / 3.0;
        Plane { a0, dx: slope * (2.0 * u(rnd) - 1.0), dy: slope * (2.0 * u(rnd) - 1.0) }
    }

    /// The block kernels give what the span kernels give on the cover's
    /// runs (and what the reference gives): colour, depth, the passed
    /// count, stencil untouched, pixels outside the cover untouched. Random
    /// tiny triangles (as `raster::tests::cover_matches_runs` makes them,
    /// clipped by random rectangles) with random planes: depth partly
    /// outside [0, 1], stored depths equal to, just above and just below
    /// the fragment's (ties), perspective and affine, flat and constant
    /// colours (zero slopes of either sign), colours outside [0, 1];
    /// depth off / LESS / LEQUAL, colour stored or not, alpha_fix on and off.
    /// Round 15: a third of the triangles fogged (LINEAR, with start = end
    /// at times, EXP, EXP2; f per fragment or interpolated and clamped;
    /// flat and smooth, perspective and affine), fog values also outside
    /// the fog's range.
    #[test]
    fn stamp_matches_span_kernels() {
        if super::super::simd::level_here() != super::super::simd::Level::Avx2 {
            eprintln!("no AVX2: no block kernels");
            return;
        }
        const W: usize = 48;
        const H: usize = 44;
        let mut rnd = crate::render::test_rng::below(1313, 19);
        let (mut shaded, mut written, mut ties, mut kinds, mut wide, mut tall_covers) = (0usize, 0u64, 0usize, [0usize; 4], 0usize, 0usize);
        let (mut inside, mut narrow) = ([0usize; 2], [0usize; 2]);
        // Fogged covers shaded: by mode (LINEAR, EXP, EXP2, per vertex),
        // and by flat * 2 + perspective.
        let (mut fog_modes, mut fog_kinds) = ([0usize; 4], [0usize; 4]);
        for n in 0..120_000 {
            // Round 14: also boxes up to 32 columns and 32 rows.
            let (size, tall) = [(ONE, ONE), (2 * ONE, 2 * ONE), (4 * ONE, 4 * ONE), (7 * ONE, 7 * ONE), (8 * ONE, 14 * ONE), (15 * ONE, 30 * ONE), (31 * ONE, 31 * ONE)][n % 7];
            let (mut bx, by) = (rnd(12 * ONE) + 2 * ONE, rnd(10 * ONE) + 2 * ONE);
            if n % 5 == 2 {
                // Round 17: narrow covers at the buffer's right edge
                // (masked loads and stores), the others further left.
                bx = if n % 10 == 2 { (W as i64 - 4) * ONE + rnd(3 * ONE) } else { rnd(40 * ONE) };
            }
            let mut x = [bx + rnd(size), bx + rnd(size), bx + rnd(size)];
            let mut y = [by + rnd(tall), by + rnd(tall), by + rnd(tall)];
            if n % 4 == 1 {
                x = x.map(|c| c & !(ONE / 2 - 1));
                y = y.map(|c| c & !(ONE / 2 - 1));
            }
            let area = (x[1] - x[0]) * (y[2] - y[0]) - (x[2] - x[0]) * (y[1] - y[0]);
            if area == 0 {
                continue;
            }
            if area < 0 {
                x.swap(1, 2);
                y.swap(1, 2);
            }
            let rect = if n % 3 == 0 {
                let (x0, y0) = ((x[0] / ONE) as i32 - rnd(3) as i32, (y[0] / ONE) as i32 - rnd(4) as i32);
                Rect { x0, y0, x1: x0 + 1 + rnd(4) as i32, y1: y0 + 1 + rnd(6) as i32 }.intersect(Rect { x0: 0, y0: 0, x1: W as i32, y1: H as i32 })
            } else {
                Rect { x0: 0, y0: 0, x1: W as i32, y1: H as i32 }
            };
            let Some(cover) = Cover::find(x, y, rect) else { continue };
            if cover.is_empty() {
                continue;
            }
            // The triangle's planes.
            let perspective = rnd(3) != 0;
            let constant = rnd(4) == 0;
            let flat = rnd(6) == 0;
            let z_constant = rnd(20) == 0;
            let mut t = TriangleSetup {
                x0: x[0] as f64 / ONE as f64,
                y0: y[0] as f64 / ONE as f64,
                z: plane(&mut rnd, -0.2, 1.2, z_constant),
                q: if perspective { plane(&mut rnd, 0.3, 3.0, false) } else { Plane { a0: 1.0, dx: 0.0, dy: 0.0 } },
                color: [0; 4].map(|_| plane(&mut rnd, -0.3, 1.3, constant)),
                perspective,
                flat: None,
                front_facing: true,
                tex: None,
                fog: None,
                secondary: None,
            };
            if flat {
                t.flat = Some([0; 4].map(|_| rnd(256) as u8));
                t.color = [Plane::default(); 4];
            }
            let mode = rnd(12);
            if mode < 4 {
                let u = |rnd: &mut dyn FnMut(i64) -> i64| rnd(1 << 20) as f32 / (1 << 20) as f32;
                let per_fragment = mode != 3;
                let (start, end) = (u(&mut rnd) * 4.0 - 1.0, u(&mut rnd) * 12.0);
                let fog = Fog {
                    mode: [GL_LINEAR, GL_EXP, GL_EXP2, [GL_LINEAR, GL_EXP, GL_EXP2][rnd(3) as usize]][mode as usize],
                    density: u(&mut rnd) * 0.5 - 0.05,
                    start,
                    end: if rnd(8) == 0 { start } else { end },
                    color: glam::Vec4::from_array([0; 4].map(|_| u(&mut rnd) * 1.2 - 0.1)),
                    per_fragment,
                };
                // Fog coordinates (eye distances) or per-vertex factors,
                // a little outside their range.
                let (lo, hi) = if per_fragment { (-1.0, 14.0) } else { (-0.2, 1.2) };
                let constant = rnd(10) == 0;
                t.fog = Some((plane(&mut rnd, lo, hi, constant), fog));
                fog_modes[if per_fragment { mode as usize } else { 3 }] += 1;
                fog_kinds[flat as usize * 2 + perspective as usize] += 1;
            }
            let mut fs = FragmentState::default();
            match rnd(3) {
                0 => fs.depth_test = false,
                1 => (fs.depth_test, fs.depth_func) = (true, CompareFunc::Less),
                _ => (fs.depth_test, fs.depth_func) = (true, CompareFunc::Lequal),
            }
            if rnd(5) == 0 {
                fs.color = ColorOp::None;
            }
            fs.alpha_fix = if rnd(4) == 0 { 255 } else { 0 };
            let Some(sk) = select(&fs, &t, false) else { panic!("a block kernel for {fs:?}") };
            kinds[t.flat.is_some() as usize * 2 + perspective as usize] += 1;
            // Buffers: random colours and stencil; depths near the
            // fragments' own, some exactly equal.
            let color: Vec<[u8; 4]> = (0..W * H).map(|_| [0; 4].map(|_| rnd(256) as u8)).collect();
            let mut depth: Vec<u32> = (0..W * H).map(|_| rnd(DEPTH_MAX as i64 + 1) as u32).collect();
            let stencil: Vec<u8> = (0..W * H).map(|_| rnd(256) as u8).collect();
            for (py, lo, hi) in cover.rows() {
                for px in lo..hi {
                    let cx = px as f64 + 0.5 - t.x0;
                    let cy = py as f64 + 0.5 - t.y0;
                    let z = super::super::depth_to_fixed((t.z.a0 + t.z.dy * cy) + t.z.dx * cx);
                    let i = py * W + px;
                    match rnd(4) {
                        0 => depth[i] = z,
                        1 => depth[i] = z.saturating_add(1).min(DEPTH_MAX),
                        2 => depth[i] = z.saturating_sub(1),
                        _ => {}
                    }
                    ties += (depth[i] == z) as usize;
                }
            }
            let (mut c1, mut d1, s1) = (color.clone(), depth.clone(), stencil.clone());
            let target = Target { color: c1.as_mut_ptr(), depth: d1.as_mut_ptr(), width: W };
            // SAFETY: the cover lies within the W x H buffers.
            let passed = unsafe { sk(&fs, &t, &target, &cover) };
            // The span kernels (SIMD where they have them) and the
            // reference on the cover's runs.
            for k in [fast::select(&fs, &t, false), reference::shade_span as fast::Kernel] {
                let (mut c2, mut d2, mut s2) = (color.clone(), depth.clone(), stencil.clone());
                let mut expect = 0;
                for (py, lo, hi) in cover.rows() {
                    let (a, b) = (py * W + lo, py * W + hi);
                    let mut px = SpanPixels { color: &mut c2[a..b], depth: &mut d2[a..b], stencil: &mut s2[a..b], other: None, passed: 0 };
                    k(&fs, &t, &mut px, py, lo, hi);
                    expect += px.passed;
                }
                assert_eq!(passed, expect, "passed: {x:?} {y:?} {rect:?} {cover:?} {fs:?} {t:?}");
                assert!(d1 == d2, "depth: {x:?} {y:?} {rect:?} {cover:?} {fs:?} {t:?}");
                assert!(c1 == c2, "colour: {x:?} {y:?} {rect:?} {cover:?} {fs:?} {t:?}");
                assert!(s1 == s2 && s2 == stencil, "stencil");
            }
            shaded += 1;
            written += passed;
            wide += ((0..cover.height()).any(|j| cover.row(j) >= 1 << 16)) as usize;
            tall_covers += (cover.height() > 8) as usize;
            // Round 15: blocks inside the rows (plain loads and stores,
            // the other lanes written back) and at the right edge (masked).
            inside[(cover.col0 + Cover::COLS as usize <= W) as usize] += 1;
            // Round 17: narrow covers (one group a row), plain and masked.
            if cover.narrow() {
                assert!((0..cover.height()).all(|j| cover.row(j) < 16), "narrow: {cover:?}");
                narrow[(cover.col0 + 4 <= W) as usize] += 1;
            }
        }
        assert!(shaded > 30_000 && written > 40_000 && ties > 20_000 && wide > 3_000 && tall_covers > 10_000 && kinds.iter().all(|&k| k > 1000), "{shaded} {written} {ties} {kinds:?} {wide} {tall_covers}");
        assert!(inside.iter().all(|&k| k > 5_000), "edge / inside: {inside:?}");
        eprintln!("narrow covers at the edge / inside: {narrow:?}");
        assert!(narrow[0] > 1_000 && narrow[1] > 10_000, "narrow covers at the edge / inside: {narrow:?}");
        assert!(fog_modes.iter().all(|&k| k > 1500) && fog_kinds.iter().all(|&k| k > 400), "{fog_modes:?} {fog_kinds:?}");
    }
}
