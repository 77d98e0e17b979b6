//! Per-fragment operations (GL 1.5 section 4.1) for the spans the rasterizer
//! produces, in the spec's order: pixel ownership and scissor (by the
//! rasterizer's draw rectangle), alpha test, stencil test, depth test,
//! blending, dithering (a no-op: fragment colours are already 8-bit, the
//! framebuffer's depth), logical operation, and the colour, depth and
//! stencil write masks.
//!
//! Specialization: validation derives a [`FragmentState`] saying which
//! stages are active; [`shade_span`] picks, once per span, a kernel
//! monomorphized over the four stage groups (alpha, stencil, depth, colour),
//! so an inactive group is not in the loop at all. A colour-masked,
//! depth-disabled stencil pass runs the stencil test and its operations
//! only: no colour is interpolated. The colour stage is one of none /
//! replace / blend / logic op ([`ColorOp`]), chosen at validation.
//!
//! Occlusion queries (section 4.1.6): every fragment that gets past the
//! depth test (or reaches it with the test off) adds one to
//! `Framebuffer::samples_passed`; a key with no active stage still runs
//! the (empty) kernel for that count.
//!
//! Interplay (section 4.1.5): a fragment failing the stencil test takes the
//! `fail` operation; passing it, `zfail` if the depth test fails and `zpass`
//! if it passes or the depth test is disabled. Without a stencil buffer the
//! stencil test always passes and nothing is written. With
//! GL_COLOR_LOGIC_OP enabled, blending is bypassed (section 4.1.8).

pub mod blend;
pub mod logic;
pub mod stencil;

pub use blend::{Blend, BlendEquation, BlendFactor};
pub use logic::LogicOp;
pub use stencil::{StencilOp, StencilTest};

use super::setup::TriangleSetup;
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

/// The alpha test (section 4.1.4): the fragment's 8-bit alpha against the
/// reference converted to 8 bits as an alpha colour component.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct AlphaTest {
    pub func: CompareFunc,
    pub reference: u8,
}

/// What happens to the colour of a fragment that passed every test.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum ColorOp {
    /// Nothing reaches the colour buffer (all channels masked, or GL_NOOP).
    None,
    /// The fragment's colour is stored (through the colour mask).
    Replace,
    Blend(Blend),
    Logic(LogicOp),
}

/// The fragment pipeline's configuration, derived from GL state.
#[derive(Clone, Debug, PartialEq)]
pub struct FragmentState {
    /// Alpha test enabled and not GL_ALWAYS.
    pub alpha_test: bool,
    pub alpha: AlphaTest,
    /// Stencil test enabled and a stencil buffer present.
    pub stencil_test: bool,
    pub stencil: StencilTest,
    /// Depth test enabled and a depth buffer present.
    pub depth_test: bool,
    pub depth_func: CompareFunc,
    pub depth_write: bool,
    pub color: ColorOp,
    /// Bytes of the RGBA pixel that colour writes may change (glColorMask).
    pub color_mask: [bool; 4],
    /// 255 on a surface without alpha (a GLX RGB config), else 0: OR-ed
    /// into the alpha of every colour written, so stored alpha stays 1.0
    /// (framebuffer::Config) while the kernels keep their full-mask paths.
    pub alpha_fix: u8,
}

impl Default for FragmentState {
    fn default() -> Self {
        FragmentState {
            alpha_test: false,
            alpha: AlphaTest { func: CompareFunc::Always, reference: 0 },
            stencil_test: false,
            stencil: StencilTest {
                func: CompareFunc::Always,
                reference: 0,
                masked_ref: 0,
                value_mask: 0xFF,
                write_mask: 0xFF,
                max: 0xFF,
                fail: StencilOp::Keep,
                zfail: StencilOp::Keep,
                zpass: StencilOp::Keep,
            },
            depth_test: false,
            depth_func: CompareFunc::Less,
            depth_write: true,
            color: ColorOp::Replace,
            color_mask: [true; 4],
            alpha_fix: 0,
        }
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

/// The stage-group key of a state: which of [`fragment`]'s const
/// parameters are on.
#[inline]
pub(crate) fn key(fs: &FragmentState) -> u8 {
    (fs.alpha_test as u8) | (fs.stencil_test as u8) << 1 | (fs.depth_test as u8) << 2 | ((fs.color != ColorOp::None) as u8) << 3
}

/// Expands `$call::<A, S, D, C>(..)` for the 16 keys.
macro_rules! dispatch {
    ($k:expr, $f:ident ( $($arg:expr),* )) => {
        match $k {
            // Nothing to test or write: only the occlusion count runs.
            0 => $f::<false, false, false, false>($($arg),*),
            1 => $f::<true, false, false, false>($($arg),*),
            2 => $f::<false, true, false, false>($($arg),*),
            3 => $f::<true, true, false, false>($($arg),*),
            4 => $f::<false, false, true, false>($($arg),*),
            5 => $f::<true, false, true, false>($($arg),*),
            6 => $f::<false, true, true, false>($($arg),*),
            7 => $f::<true, true, true, false>($($arg),*),
            8 => $f::<false, false, false, true>($($arg),*),
            9 => $f::<true, false, false, true>($($arg),*),
            10 => $f::<false, true, false, true>($($arg),*),
            11 => $f::<true, true, false, true>($($arg),*),
            12 => $f::<false, false, true, true>($($arg),*),
            13 => $f::<true, false, true, true>($($arg),*),
            14 => $f::<false, true, true, true>($($arg),*),
            _ => $f::<true, true, true, true>($($arg),*),
        }
    };
}

/// Shades pixels [x0, x1) of row `y` of a triangle through the fast
/// kernels (the rasterizer picks a kernel once per triangle instead, and
/// the reference path when `RenderState::reference` is set).
pub fn shade_span(fs: &FragmentState, t: &TriangleSetup, fb: &mut Framebuffer, y: usize, x0: usize, x1: usize) {
    let mut px = SpanPixels::of(fb, y, x0, x1);
    fast::select(fs, t, false)(fs, t, &mut px, y, x0, x1);
    let passed = px.passed;
    fb.samples_passed = fb.samples_passed.wrapping_add(passed);
}

/// Runs one fragment whose depth (24-bit fixed point) and colour are known
/// through the per-fragment operations, at framebuffer index `i` (for
/// primitives other than triangles: points, lines, pixel rectangles).
pub fn process_fragment(fs: &FragmentState, fb: &mut Framebuffer, i: usize, z: u32, color: [u8; 4]) {
    dispatch!(key(fs), fragment(fs, fb, i, || z, || color))
}

/// Shades one fragment of a point or line at pixel (x, y), already inside
/// the draw rectangle, with its window depth `z` (in [0, 1]) and colour,
/// through the same per-fragment operations as `shade_span`.
pub fn shade_fragment(fs: &FragmentState, fb: &mut Framebuffer, x: usize, y: usize, z: f64, color: [u8; 4]) {
    let i = fb.index(x, y);
    dispatch!(key(fs), fragment(fs, fb, i, || depth_to_fixed(z), || color))
}

/// The pixels a span's fragments go to: the colour, depth and stencil
/// values of pixels [x0, x1) of one row (depth and stencil empty when the
/// buffer is absent), and the span's occlusion count. Spans of different
/// rows or columns are disjoint, so tiles can be shaded in parallel.
pub struct SpanPixels<'a> {
    pub color: &'a mut [[u8; 4]],
    pub depth: &'a mut [u32],
    pub stencil: &'a mut [u8],
    /// The same pixels of the other colour buffer when drawing to
    /// GL_FRONT_AND_BACK (`Framebuffer::draw_both`).
    pub other: Option<&'a mut [[u8; 4]]>,
    /// Fragments that passed the depth test (occlusion queries).
    pub passed: u64,
}

impl<'a> SpanPixels<'a> {
    /// Pixels [x0, x1) of row y of a framebuffer. Inlined: the 1-thread
    /// path calls it per span (a call and four slice checks were about 43
    /// instructions a span).
    #[inline(always)]
    pub fn of(fb: &'a mut Framebuffer, y: usize, x0: usize, x1: usize) -> SpanPixels<'a> {
        let (a, b) = (y * fb.width + x0, y * fb.width + x1);
        let Framebuffer { color, depth, stencil, other_color, draw_both, .. } = fb;
        SpanPixels {
            color: &mut color[a..b],
            other: if *draw_both { Some(&mut other_color[a..b]) } else { None },
            depth: if depth.is_empty() { &mut [] } else { &mut depth[a..b] },
            stencil: if stencil.is_empty() { &mut [] } else { &mut stencil[a..b] },
            passed: 0,
        }
    }
}

/// Where [`fragment`] reads and writes: the whole framebuffer (index
/// `y * width + x`) or one span (index from its start).
pub trait Buffers {
    fn stencil(&mut self, i: usize) -> &mut u8;
    fn depth(&mut self, i: usize) -> &mut u32;
    fn color(&mut self, i: usize) -> &mut [u8; 4];
    /// Colour pixels [i, i + n) (one row piece).
    fn colors(&mut self, i: usize, n: usize) -> &mut [[u8; 4]];
    /// The other colour buffer's pixel under GL_FRONT_AND_BACK.
    fn other_color(&mut self, i: usize) -> Option<&mut [u8; 4]>;
    /// One more fragment passed the depth test.
    fn pass(&mut self);
    /// `n` more fragments passed.
    #[inline(always)]
    fn pass_n(&mut self, n: u64) {
        for _ in 0..n {
            self.pass();
        }
    }
}

impl Buffers for Framebuffer {
    #[inline(always)]
    fn stencil(&mut self, i: usize) -> &mut u8 {
        &mut self.stencil[i]
    }
    #[inline(always)]
    fn depth(&mut self, i: usize) -> &mut u32 {
        &mut self.depth[i]
    }
    #[inline(always)]
    fn color(&mut self, i: usize) -> &mut [u8; 4] {
        &mut self.color[i]
    }
    #[inline(always)]
    fn colors(&mut self, i: usize, n: usize) -> &mut [[u8; 4]] {
        &mut self.color[i..i + n]
    }
    #[inline(always)]
    fn other_color(&mut self, i: usize) -> Option<&mut [u8; 4]> {
        if self.draw_both {
            Some(&mut self.other_color[i])
        } else {
            None
        }
    }
    #[inline(always)]
    fn pass(&mut self) {
        self.samples_passed = self.samples_passed.wrapping_add(1);
    }
    #[inline(always)]
    fn pass_n(&mut self, n: u64) {
        self.samples_passed = self.samples_passed.wrapping_add(n);
    }
}

impl Buffers for SpanPixels<'_> {
    #[inline(always)]
    fn stencil(&mut self, i: usize) -> &mut u8 {
        &mut self.stencil[i]
    }
    #[inline(always)]
    fn depth(&mut self, i: usize) -> &mut u32 {
        &mut self.depth[i]
    }
    #[inline(always)]
    fn color(&mut self, i: usize) -> &mut [u8; 4] {
        &mut self.color[i]
    }
    #[inline(always)]
    fn colors(&mut self, i: usize, n: usize) -> &mut [[u8; 4]] {
        &mut self.color[i..i + n]
    }
    #[inline(always)]
    fn other_color(&mut self, i: usize) -> Option<&mut [u8; 4]> {
        self.other.as_mut().map(|o| &mut o[i])
    }
    #[inline(always)]
    fn pass(&mut self) {
        self.passed += 1;
    }
}

/// The per-fragment operations for one fragment, with the stage groups
/// fixed at compile time: A alpha test, S stencil test, D depth test, C
/// colour write. Depth and colour are computed only when a stage needs them.
#[inline(always)]
pub(crate) fn fragment<const A: bool, const S: bool, const D: bool, const C: bool>(
    fs: &FragmentState,
    fb: &mut impl Buffers,
    i: usize,
    depth: impl Fn() -> u32,
    color: impl Fn() -> [u8; 4],
) {
    let mut src = [0u8; 4];
    // Section 4.1.4: alpha test.
    if A {
        src = color();
        if !fs.alpha.func.test(src[3], fs.alpha.reference) {
            return;
        }
    }
    // Section 4.1.5: stencil test; the fail operation.
    let st = &fs.stencil;
    if S {
        let s = *fb.stencil(i);
        if !st.test(s) {
            *fb.stencil(i) = st.apply(st.fail, s);
            return;
        }
    }
    // Section 4.1.6: depth test; the depth-fail operation.
    if D {
        let z = depth();
        if !fs.depth_func.test(z, *fb.depth(i)) {
            if S {
                let s = fb.stencil(i);
                *s = st.apply(st.zfail, *s);
            }
            return;
        }
        if fs.depth_write {
            *fb.depth(i) = z;
        }
    }
    // Depth passed, or the depth test is off: a sample passed (occlusion
    // queries, gl::queries), and the depth-pass operation.
    fb.pass();
    if S {
        let s = fb.stencil(i);
        *s = st.apply(st.zpass, *s);
    }
    if C {
        if !A {
            src = color();
        }
        write_color(fs, fb.color(i), src);
        // GL_FRONT_AND_BACK (framebuffer module): the same fragment into
        // the other colour buffer, blended against its own contents. Only
        // this general path draws to two buffers: the fast kernels and
        // tile binning are not chosen then (raster::triangle, setup).
        if let Some(other) = fb.other_color(i) {
            write_color(fs, other, src);
        }
    }
}

/// Sections 4.1.8 to 4.1.10 and 4.2.2: blending or the logic op, then the
/// colour write mask.
#[inline(always)]
pub(crate) fn write_color(fs: &FragmentState, dst: &mut [u8; 4], src: [u8; 4]) {
    let new = match fs.color {
        ColorOp::None => return,
        ColorOp::Replace => src,
        ColorOp::Blend(b) => b.apply(src, *dst),
        ColorOp::Logic(op) => op.apply(u32::from_ne_bytes(src), u32::from_ne_bytes(*dst)).to_ne_bytes(),
    };
    let mut new = new;
    new[3] |= fs.alpha_fix;
    let m = fs.color_mask;
    if m == [true; 4] {
        *dst = new;
    } else {
        for ch in 0..4 {
            if m[ch] {
                dst[ch] = new[ch];
            }
        }
    }
}

// After `dispatch!`, which they use (macro scope is textual).
pub mod fast;
pub mod reference;
pub mod pixel_span;
pub mod textured;
pub mod simd;
pub mod stamp;
