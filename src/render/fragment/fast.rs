//! The fast span kernels (GL 1.5 section 4.1, the same per-fragment
//! operations as [`super::reference`]), specialized per triangle on a key of
//! the state: stencil on/off, the depth test (off, LESS with write, LEQUAL
//! with write, any other), where the colour comes from (flat, affine
//! smooth, perspective smooth, general: texture/fog) and what the colour
//! write is (none, plain store, the two common blends in integers, general).
//! A triangle picks its kernel once ([`select`]); the loop never re-tests
//! an enable.
//!
//! Exactness: every kernel computes bit-for-bit what the reference does.
//! Planes are evaluated per pixel as `(a0 + dy * cy) + dx * cx` in f64,
//! the reference's own order ([`super::reference::eval`]), with the row
//! term hoisted out of the loop; 1/w is divided per pixel as there. The
//! integer blends are exact: for 8-bit operands and 8-bit factors the real
//! blend result is x / 255 for an integer x, never within 1/510 of a
//! rounding midpoint, while the reference's f32 evaluation is within
//! 2^-20 of it (blend.rs), so both round to the same integer
//! `(x + 127) / 255`.
//!
//! SIMD: where the CPU has SSE2 or AVX2, [`select`] hands out the
//! kernels of [`super::simd`] instead for the common keys (depth off /
//! LESS / LEQUAL / any, stencil, flat / constant / affine / perspective /
//! stepped colour, store / OVER / ADD / none); they compute these kernels'
//! values four pixels at a time, and call them for spans under four pixels.
//!
//! Early rejection: without the alpha test the stencil and depth tests run
//! before any colour work, so a rejected fragment never interpolates or
//! samples. With the alpha test (which needs the colour first) the
//! reference kernel runs. The occlusion count is summed per span.

use super::reference;
use super::{color_to_u8, depth_to_fixed, write_color, Blend, BlendEquation, BlendFactor, ColorOp, CompareFunc, FragmentState, SpanPixels};
use crate::render::setup::TriangleSetup;

/// A span shader: pixels [x0, x1) of row y.
pub type Kernel = fn(&FragmentState, &TriangleSetup, &mut SpanPixels, usize, usize, usize);

/// Depth keys.
pub(super) const D_OFF: u8 = 0;
pub(super) const D_LESS: u8 = 1;
pub(super) const D_LEQUAL: u8 = 2;
pub(super) const D_ANY: u8 = 3;

/// The depth key of a fragment state: off, LESS or LEQUAL with writes (the
/// common cases, specialized), or any other test.
pub(super) fn depth_key(fs: &FragmentState) -> u8 {
    if !fs.depth_test {
        D_OFF
    } else if fs.depth_write && fs.depth_func == CompareFunc::Less {
        D_LESS
    } else if fs.depth_write && fs.depth_func == CompareFunc::Lequal {
        D_LEQUAL
    } else {
        D_ANY
    }
}
/// Colour sources.
pub(super) const CS_FLAT: u8 = 0;
pub(super) const CS_AFFINE: u8 = 1;
pub(super) const CS_PERSPECTIVE: u8 = 2;
pub(super) const CS_GENERAL: u8 = 3;
/// Affine colour whose planes are constant: evaluated once per span.
pub(super) const CS_CONSTANT: u8 = 4;
/// Affine colour stepped in 16.16 fixed point (hint not GL_NICEST).
pub(super) const CS_STEPPED: u8 = 5;
/// Untextured and fogged (3.10): the primary colour (flat, affine or
/// perspective) blended towards the fog colour, as
/// `reference::triangle_color` computes it, without its per-pixel
/// re-evaluation of the row terms and second 1/w division ([`fog_color`]).
pub(super) const CS_FOG: u8 = 6;
/// Colour writes.
pub(super) const CO_NONE: u8 = 0;
pub(super) const CO_STORE: u8 = 1;
pub(super) const CO_OVER: u8 = 2;
pub(super) const CO_ADD: u8 = 3;
pub(super) const CO_GENERAL: u8 = 4;

fn blend_is(b: &Blend, src: BlendFactor, dst: BlendFactor) -> bool {
    b.equation == BlendEquation::Add && b.src_rgb == src && b.src_alpha == src && b.dst_rgb == dst && b.dst_alpha == dst
}

/// How a state writes colour: the `CO_*` key of [`select`] (and of the
/// block kernels, `stamp::select`).
pub(super) fn color_op(fs: &FragmentState) -> u8 {
    let full = fs.color_mask == [true; 4];
    match fs.color {
        ColorOp::None => CO_NONE,
        ColorOp::Replace if full => CO_STORE,
        ColorOp::Blend(b) if full && blend_is(&b, BlendFactor::SrcAlpha, BlendFactor::OneMinusSrcAlpha) => CO_OVER,
        ColorOp::Blend(b) if full && blend_is(&b, BlendFactor::SrcAlpha, BlendFactor::One) => CO_ADD,
        _ => CO_GENERAL,
    }
}

/// Where a triangle's fragment colour comes from: the `CS_*` key of
/// [`select`] (and of the block kernels, `stamp::select`, which take the
/// same key so that they compute what the span kernel would).
pub(super) fn color_source(t: &TriangleSetup, approximate: bool, co: u8) -> u8 {
    if t.tex.is_some() {
        CS_GENERAL
    } else if t.fog.is_some() {
        CS_FOG
    } else if t.flat.is_some() {
        CS_FLAT
    } else if t.perspective {
        CS_PERSPECTIVE
    } else if t.color.iter().all(|p| p.dx == 0.0 && p.dy == 0.0) {
        CS_CONSTANT
    } else if approximate && co == CO_STORE {
        CS_STEPPED
    } else {
        CS_AFFINE
    }
}

/// The kernel for a triangle under a fragment state.
///
/// `approximate`: GL_PERSPECTIVE_CORRECTION_HINT is not GL_NICEST, so
/// colour interpolation may trade exactness for time (section 5.6): an
/// affine smooth colour stored without blending is then stepped in fixed
/// point, within one step (1/255) of the exact value, and the 8-wide
/// textured kernel filters in 8-bit fixed point (`textured::select`).
/// Everything else stays exact.
pub fn select(fs: &FragmentState, t: &TriangleSetup, approximate: bool) -> Kernel {
    if fs.alpha_test {
        return reference::shade_span;
    }
    if let Some(k) = super::textured::select(fs, t, approximate) {
        return k;
    }
    let d = depth_key(fs);
    let co = color_op(fs);
    let cs = color_source(t, approximate, co);
    // The SIMD kernels (simd.rs) where the CPU has them, for the common
    // opaque, blended and stencil cases; they compute what `kernel` does.
    // Under the stencil test colours stay exact (no stepping), as before.
    let simd_cs = match cs {
        _ if co == CO_NONE => CS_FLAT,
        CS_STEPPED if fs.stencil_test => CS_AFFINE,
        _ => cs,
    };
    if let Some(k) = super::simd::pick(fs.stencil_test, d, simd_cs, co) {
        return k;
    }
    if fs.stencil_test {
        // Stencil passes are rarer: general colour, specialized depth.
        return match (d, co) {
            (D_OFF, CO_NONE) => kernel::<true, D_OFF, CS_GENERAL, CO_NONE>,
            (D_LESS, CO_NONE) => kernel::<true, D_LESS, CS_GENERAL, CO_NONE>,
            (D_LEQUAL, CO_NONE) => kernel::<true, D_LEQUAL, CS_GENERAL, CO_NONE>,
            (_, CO_NONE) => kernel::<true, D_ANY, CS_GENERAL, CO_NONE>,
            (D_OFF, _) => kernel::<true, D_OFF, CS_GENERAL, CO_GENERAL>,
            (D_LESS, _) => kernel::<true, D_LESS, CS_GENERAL, CO_GENERAL>,
            (D_LEQUAL, _) => kernel::<true, D_LEQUAL, CS_GENERAL, CO_GENERAL>,
            _ => kernel::<true, D_ANY, CS_GENERAL, CO_GENERAL>,
        };
    }
    match d {
        D_OFF => pick_cs::<D_OFF>(cs, co),
        D_LESS => pick_cs::<D_LESS>(cs, co),
        D_LEQUAL => pick_cs::<D_LEQUAL>(cs, co),
        _ => pick_cs::<D_ANY>(cs, co),
    }
}

fn pick_cs<const D: u8>(cs: u8, co: u8) -> Kernel {
    if co == CO_NONE {
        // Depth-only (or count-only) pass: no colour at all.
        return kernel::<false, D, CS_FLAT, CO_NONE>;
    }
    match cs {
        CS_FLAT => pick_co::<D, CS_FLAT>(co),
        CS_AFFINE => pick_co::<D, CS_AFFINE>(co),
        CS_PERSPECTIVE => pick_co::<D, CS_PERSPECTIVE>(co),
        CS_CONSTANT => pick_co::<D, CS_CONSTANT>(co),
        CS_STEPPED => kernel::<false, D, CS_STEPPED, CO_STORE>,
        CS_FOG => pick_co::<D, CS_FOG>(co),
        _ => pick_co::<D, CS_GENERAL>(co),
    }
}

fn pick_co<const D: u8, const CS: u8>(co: u8) -> Kernel {
    match co {
        CO_STORE => kernel::<false, D, CS, CO_STORE>,
        CO_OVER => kernel::<false, D, CS, CO_OVER>,
        CO_ADD => kernel::<false, D, CS, CO_ADD>,
        _ => kernel::<false, D, CS, CO_GENERAL>,
    }
}

/// round(x / 255) for the integer x of an 8-bit blend (no midpoints).
#[inline(always)]
fn div255(x: u32) -> u32 {
    (x + 127) / 255
}

/// SRC_ALPHA, ONE_MINUS_SRC_ALPHA, ADD.
#[inline(always)]
fn over(s: [u8; 4], d: [u8; 4]) -> [u8; 4] {
    let a = s[3] as u32;
    let ia = 255 - a;
    std::array::from_fn(|ch| div255(s[ch] as u32 * a + d[ch] as u32 * ia) as u8)
}

/// SRC_ALPHA, ONE, ADD (clamped).
#[inline(always)]
fn add(s: [u8; 4], d: [u8; 4]) -> [u8; 4] {
    let a = s[3] as u32;
    std::array::from_fn(|ch| div255(s[ch] as u32 * a + d[ch] as u32 * 255).min(255) as u8)
}

/// The 16.16 fixed-point start `255 * c * 2^16 + 2^15` and step of a
/// stepped colour at the span's first pixel `x0`, whose centre is `cx0`
/// from the planes' origin (shared with the SIMD kernels so that both step
/// from the same integers).
///
/// Pixel x of a row gets `A + dx * x`, with A the value at the row's
/// column 0, whichever span it is shaded in: cutting a span (at tile
/// edges) changes nothing, so images do not depend on the thread count.
/// dx truncates, so pixel x is off by less than x / 65536 of a step
/// (under 1/30 of a step at 1920 pixels) besides A's own rounding. A
/// plane steeper than 1e8 / 65536 steps per pixel (never a visible one:
/// colours in [0, 1] then change by more than 6 per pixel, so a row
/// holds at most one covered pixel) is anchored at the span's start.
#[inline(always)]
pub(super) fn stepped_start(cr: &[f64; 4], cdx: &[f64; 4], cx0: f64, x0: usize) -> ([i64; 4], [i64; 4]) {
    const FX: f64 = 65536.0 * 255.0;
    const STEEP: f64 = 1e8;
    // Column 0's centre (exact: cx0 is a multiple of 1/256 below 2^44).
    let ca = cx0 - x0 as f64;
    let mut fixed: [i64; 4] = [0; 4];
    let mut fixed_dx: [i64; 4] = [0; 4];
    for c in 0..4 {
        let d = cdx[c] * FX;
        if d.abs() < STEEP {
            fixed_dx[c] = d as i64;
            // |value| < 2^53 here (|ca| < 2^20 after clipping): exact
            // enough, and the clamp only guards against the impossible.
            let a = ((cr[c] + cdx[c] * ca) * FX).clamp(-1e15, 1e15);
            fixed[c] = a as i64 + 32768 + fixed_dx[c] * x0 as i64;
        } else {
            // Clamped so that huge off-screen planes cannot overflow.
            fixed_dx[c] = d.clamp(-STEEP, STEEP) as i64;
            fixed[c] = ((cr[c] + cdx[c] * cx0) * FX).clamp(-1e12, 1e12) as i64 + 32768;
        }
    }
    (fixed, fixed_dx)
}

pub(super) fn kernel<const S: bool, const D: u8, const CS: u8, const CO: u8>(fs: &FragmentState, t: &TriangleSetup, px: &mut SpanPixels, y: usize, x0: usize, x1: usize) {
    if x0 >= x1 {
        return;
    }
    let cy = y as f64 + 0.5 - t.y0;
    // Row terms of the planes, hoisted (same rounding as the reference).
    let zr = t.z.a0 + t.z.dy * cy;
    let zdx = t.z.dx;
    let cr: [f64; 4] = std::array::from_fn(|c| t.color[c].a0 + t.color[c].dy * cy);
    let cdx: [f64; 4] = std::array::from_fn(|c| t.color[c].dx);
    let qr = t.q.a0 + t.q.dy * cy;
    let qdx = t.q.dx;
    let fog = if CS == CS_FOG { FogRow::new(t, cy) } else { None };
    let mut flat = t.flat.unwrap_or_default();
    if CS == CS_CONSTANT {
        // a0 + 0 * cy + 0 * cx is a0 exactly: the reference's value.
        flat = color_to_u8(glam::Vec4::from_array(std::array::from_fn(|c| cr[c] as f32)));
    }
    // Fixed-point stepping: 255 * c in 16.16 with the rounding half added.
    let (fixed, fixed_dx) = if CS == CS_STEPPED { stepped_start(&cr, &cdx, x0 as f64 + 0.5 - t.x0, x0) } else { ([0; 4], [0; 4]) };
    let st = &fs.stencil;
    let n = x1 - x0;
    let SpanPixels { color, depth, stencil, passed: total, .. } = px;
    let col = &mut color[..if CO != CO_NONE { n } else { 0 }];
    let dep = &mut depth[..if D != D_OFF { n } else { 0 }];
    let sten = &mut stencil[..if S { n } else { 0 }];
    let mut passed = 0u64;
    // The pixel centre's offset from the planes' origin, stepped by 1:
    // (x + 1/2 - x0) is a multiple of 1/256 far below 2^44, so each sum
    // is exact and equal to the reference's per-pixel value.
    let mut cx = x0 as f64 + 0.5 - t.x0 - 1.0;
    for k in 0..n {
        cx += 1.0;
        if S {
            let s = sten[k];
            if !st.test(s) {
                sten[k] = st.apply(st.fail, s);
                continue;
            }
        }
        if D != D_OFF {
            let z = depth_to_fixed(zr + zdx * cx);
            let stored = dep[k];
            let pass = match D {
                D_LESS => z < stored,
                D_LEQUAL => z <= stored,
                _ => fs.depth_func.test(z, stored),
            };
            if !pass {
                if S {
                    sten[k] = st.apply(st.zfail, sten[k]);
                }
                continue;
            }
            if D != D_ANY || fs.depth_write {
                dep[k] = z;
            }
        }
        passed += 1;
        if S {
            sten[k] = st.apply(st.zpass, sten[k]);
        }
        if CO != CO_NONE {
            let src = match CS {
                CS_FLAT | CS_CONSTANT => flat,
                CS_STEPPED => std::array::from_fn(|c| (fixed[c] + fixed_dx[c] * k as i64).clamp(0, 255 << 16) as u32 >> 16) .map(|v: u32| v as u8),
                CS_AFFINE => color_to_u8(glam::Vec4::from_array(std::array::from_fn(|c| ((cr[c] + cdx[c] * cx) * 1.0) as f32))),
                CS_PERSPECTIVE => {
                    let w = 1.0 / (qr + qdx * cx);
                    color_to_u8(glam::Vec4::from_array(std::array::from_fn(|c| ((cr[c] + cdx[c] * cx) * w) as f32)))
                }
                CS_FOG => match &fog {
                    Some(f) => fog_color(t, f, &cr, &cdx, qr, qdx, cx),
                    None => reference::triangle_color(t, cx, cy),
                },
                _ => reference::triangle_color(t, cx, cy),
            };
            let dst = &mut col[k];
            match CO {
                CO_STORE => *dst = with_alpha(src, fs.alpha_fix),
                CO_OVER => *dst = with_alpha(over(src, *dst), fs.alpha_fix),
                CO_ADD => *dst = with_alpha(add(src, *dst), fs.alpha_fix),
                _ => write_color(fs, dst, src),
            }
        }
    }
    *total += passed;
}

/// A fogged triangle's fog plane with its row term hoisted, and the fog
/// parameters: what [`fog_color`] needs besides the colour planes.
#[derive(Clone, Copy)]
pub(super) struct FogRow {
    /// `a0 + dy * cy` of the fog plane (the reference's order).
    pub r: f64,
    pub dx: f64,
    pub fog: crate::render::fog::Fog,
    /// Flat shading: the provoking colour as the reference reads it
    /// back (bytes / 255), unclamped.
    pub flat: Option<glam::Vec4>,
}

impl FogRow {
    /// Row `cy` of an untextured fogged triangle (None without fog).
    #[inline(always)]
    pub(super) fn new(t: &TriangleSetup, cy: f64) -> Option<FogRow> {
        let (p, fog) = t.fog.as_ref()?;
        let flat = t.flat.map(|c| glam::Vec4::from_array(c.map(|v| v as f32 / 255.0)));
        Some(FogRow { r: p.a0 + p.dy * cy, dx: p.dx, fog: *fog, flat })
    }
}

/// `reference::triangle_color` of an untextured fogged fragment at `cx`
/// (rows hoisted as the kernels do: the same sums and products): one 1/w
/// for colour and fog, then `Fog::apply` on the clamped colour.
#[inline(always)]
pub(super) fn fog_color(t: &TriangleSetup, fog: &FogRow, cr: &[f64; 4], cdx: &[f64; 4], qr: f64, qdx: f64, cx: f64) -> [u8; 4] {
    let w = if t.perspective { 1.0 / (qr + qdx * cx) } else { 1.0 };
    let c = match fog.flat {
        Some(c) => c,
        None => glam::Vec4::from_array(std::array::from_fn(|ch| ((cr[ch] + cdx[ch] * cx) * w) as f32)).clamp(glam::Vec4::ZERO, glam::Vec4::ONE),
    };
    color_to_u8(fog.fog.apply(c, ((fog.r + fog.dx * cx) * w) as f32))
}

/// A stored colour with `fix` (FragmentState::alpha_fix) OR-ed into alpha.
#[inline(always)]
pub(super) fn with_alpha(mut c: [u8; 4], fix: u8) -> [u8; 4] {
    c[3] |= fix;
    c
}
