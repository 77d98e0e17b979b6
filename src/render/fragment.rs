//! Per-fragment operations (GL 1.5 chapter 4.1) for the spans the rasterizer
//! produces, in the spec's order. Implemented so far: the pixel ownership and
//! scissor tests (by the rasterizer's draw rectangle), the depth test with
//! all eight functions and the depth write mask, and the colour write with
//! per-channel masks. Alpha test, stencil, blending, logic op and fog come
//! with issue 3, slotting in between in the same order.

use super::setup::{Plane, TriangleSetup};
use crate::framebuffer::{Framebuffer, DEPTH_MAX};
use glam::Vec4;

/// The comparison of glDepthFunc / glAlphaFunc / glStencilFunc.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum CompareFunc {
    Never,
    Less,
    Equal,
    Lequal,
    Greater,
    Notequal,
    Gequal,
    Always,
}

impl CompareFunc {
    /// From the GL enum (GL_NEVER .. GL_ALWAYS = 0x200 .. 0x207).
    pub fn from_gl(e: u32) -> Option<CompareFunc> {
        use CompareFunc::*;
        Some(match e {
            0x200 => Never,
            0x201 => Less,
            0x202 => Equal,
            0x203 => Lequal,
            0x204 => Greater,
            0x205 => Notequal,
            0x206 => Gequal,
            0x207 => Always,
            _ => return None,
        })
    }

    pub fn to_gl(self) -> u32 {
        0x200 + self as u32
    }

    /// Does `incoming` pass against `stored`?
    #[inline]
    pub fn test<T: PartialOrd>(self, incoming: T, stored: T) -> bool {
        use CompareFunc::*;
        match self {
            Never => false,
            Less => incoming < stored,
            Equal => incoming == stored,
            Lequal => incoming <= stored,
            Greater => incoming > stored,
            Notequal => incoming != stored,
            Gequal => incoming >= stored,
            Always => true,
        }
    }
}

/// The fragment pipeline's configuration, derived from GL state.
#[derive(Clone, Debug, PartialEq)]
pub struct FragmentState {
    /// Depth test enabled and a depth buffer present.
    pub depth_test: bool,
    pub depth_func: CompareFunc,
    pub depth_write: bool,
    /// Bytes of the RGBA pixel that colour writes may change (glColorMask).
    pub color_mask: [bool; 4],
}

impl FragmentState {
    fn writes_color(&self) -> bool {
        self.color_mask.iter().any(|&m| m)
    }
}

/// GL's conversion of a colour to the framebuffer's 8-bit fixed point:
/// clamp to [0, 1], then round c * 255 to the nearest integer (2.14.9).
#[inline]
pub fn color_to_u8(c: Vec4) -> [u8; 4] {
    let conv = |v: f32| (v.clamp(0.0, 1.0) * 255.0 + 0.5) as u8;
    [conv(c.x), conv(c.y), conv(c.z), conv(c.w)]
}

/// Window depth in [0, 1] to the depth buffer's 24-bit fixed point.
#[inline]
pub fn depth_to_fixed(z: f64) -> u32 {
    (z.clamp(0.0, 1.0) * DEPTH_MAX as f64 + 0.5) as u32
}

#[inline]
fn eval(p: &Plane, cx: f64, cy: f64) -> f64 {
    p.a0 + p.dx * cx + p.dy * cy
}

/// Shades pixels [x0, x1) of row `y` of a triangle.
pub fn shade_span(fs: &FragmentState, t: &TriangleSetup, fb: &mut Framebuffer, y: usize, x0: usize, x1: usize) {
    let cy = y as f64 + 0.5 - t.y0;
    let row = fb.index(0, y);
    let write_color = fs.writes_color();
    for x in x0..x1 {
        let cx = x as f64 + 0.5 - t.x0;
        let i = row + x;
        if fs.depth_test {
            let z = depth_to_fixed(eval(&t.z, cx, cy));
            if !fs.depth_func.test(z, fb.depth[i]) {
                continue;
            }
            if fs.depth_write {
                fb.depth[i] = z;
            }
        }
        if !write_color {
            continue;
        }
        let src = match t.flat {
            Some(c) => c,
            None => {
                let mut c = [0.0f32; 4];
                let w = if t.perspective { 1.0 / eval(&t.q, cx, cy) } else { 1.0 };
                for (ch, p) in t.color.iter().enumerate() {
                    c[ch] = (eval(p, cx, cy) * w) as f32;
                }
                color_to_u8(Vec4::from_array(c))
            }
        };
        let dst = &mut fb.color[i];
        for ch in 0..4 {
            if fs.color_mask[ch] {
                dst[ch] = src[ch];
            }
        }
    }
}

/// Shades one fragment of a point or line at pixel (x, y), already inside
/// the draw rectangle, with its window depth `z` (in [0, 1]) and colour,
/// through the same per-fragment operations as `shade_span`.
pub fn shade_fragment(fs: &FragmentState, fb: &mut Framebuffer, x: usize, y: usize, z: f64, color: [u8; 4]) {
    let i = fb.index(x, y);
    if fs.depth_test {
        let z = depth_to_fixed(z);
        if !fs.depth_func.test(z, fb.depth[i]) {
            return;
        }
        if fs.depth_write {
            fb.depth[i] = z;
        }
    }
    let dst = &mut fb.color[i];
    for ch in 0..4 {
        if fs.color_mask[ch] {
            dst[ch] = color[ch];
        }
    }
}
