//! Pixel-rectangle spans (GL 1.5 section 3.6.4, "Conversion to fragments",
//! then the per-fragment operations of section 4.1): a row of fragments
//! that share one window depth (the raster position's) and carry their own
//! 8-bit colours, as glDrawPixels produces at a zoom of 1.
//!
//! The same per-fragment operations as every other primitive
//! ([`super::fragment`], monomorphized per stage group by `dispatch!`),
//! run once per span instead of once per fragment through the
//! framebuffer's index; the common state (no alpha or stencil test, a
//! depth test that writes, colour stored unmasked) has its own loop. Both
//! compute exactly what [`super::process_fragment`] computes per pixel.

use super::{fragment, key, ColorOp, CompareFunc, FragmentState, SpanPixels};

/// Runs the fragments `colors[k]` (pixels x0 + k of the span `px`), all
/// at depth `z` (24-bit fixed point), through the per-fragment operations.
pub fn color_span(fs: &FragmentState, px: &mut SpanPixels, z: u32, colors: &[[u8; 4]]) {
    let n = colors.len().min(px.color.len());
    let plain = !fs.alpha_test && !fs.stencil_test && fs.color == ColorOp::Replace && fs.color_mask == [true; 4] && fs.alpha_fix == 0 && px.other.is_none();
    if plain && !fs.depth_test {
        px.color[..n].copy_from_slice(&colors[..n]);
        px.passed += n as u64;
        return;
    }
    if plain && fs.depth_write && px.depth.len() >= n {
        match fs.depth_func {
            CompareFunc::Less => return depth_store(px, z, &colors[..n], |z, d| z < d),
            CompareFunc::Lequal => return depth_store(px, z, &colors[..n], |z, d| z <= d),
            _ => {}
        }
    }
    dispatch!(key(fs), span(fs, px, z, &colors[..n]))
}

/// Depth test `pass`, depth write, plain colour store.
#[inline(always)]
fn depth_store(px: &mut SpanPixels, z: u32, colors: &[[u8; 4]], pass: impl Fn(u32, u32) -> bool) {
    let n = colors.len();
    let (depth, color) = (&mut px.depth[..n], &mut px.color[..n]);
    let mut passed = 0u64;
    for k in 0..n {
        if pass(z, depth[k]) {
            depth[k] = z;
            color[k] = colors[k];
            passed += 1;
        }
    }
    px.passed += passed;
}

fn span<const A: bool, const S: bool, const D: bool, const C: bool>(fs: &FragmentState, px: &mut SpanPixels, z: u32, colors: &[[u8; 4]]) {
    for (k, &c) in colors.iter().enumerate() {
        fragment::<A, S, D, C>(fs, px, k, || z, || c);
    }
}
