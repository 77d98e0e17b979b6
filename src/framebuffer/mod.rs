//! Framebuffer storage (GL 1.5 chapter 4 intro): the colour buffer (RGBA,
//! 8 bits per channel), the depth buffer (24 bits, kept in the low bits of a
//! u32), the stencil buffer (8 bits) and the accumulation buffer (16 bits
//! signed per channel). Rows are stored bottom-up: row 0 is window y = 0,
//! as in GL's window coordinates, so the pipeline never flips.
//!
//! Colour buffers (section 4.2.1): a single-buffered surface has one, the
//! front (left) buffer. A double-buffered surface keeps two, front and
//! back, and `color` is always the one drawing writes first: the back
//! buffer for GL_BACK and GL_FRONT_AND_BACK, the front buffer for GL_FRONT.
//! Selecting a draw buffer swaps the two vectors (no copy), so the whole
//! pipeline keeps writing `color`; only FRONT_AND_BACK needs the fragment
//! stage's colour write to repeat itself into `other_color` (`draw_both`),
//! blending against that buffer's own contents. Depth, stencil and
//! accumulation are shared by both colour buffers.
//!
//! SwapBuffers copies the back buffer into the front one and leaves the
//! back buffer as it was (GL leaves it undefined; this is what Mesa's xlib
//! driver does, and piglit's swapbuffers-behavior reports it as a copy).
//!
//! Allocation is fallible: a surface too large for memory is reported, never
//! aborts the program.

pub mod clear;
pub mod color;
pub mod plane;
pub mod shared;

pub use color::ColorBuffer;
pub use plane::Plane;

/// Largest surface side; also GL_MAX_VIEWPORT_DIMS. The rasterizer's
/// fixed-point ranges are chosen for it (see `render::setup`).
pub const MAX_SIZE: usize = 16384;

/// Bits of depth stored per pixel.
pub const DEPTH_BITS: u32 = 24;
pub const DEPTH_MAX: u32 = (1 << DEPTH_BITS) - 1;

/// Which ancillary buffers a surface has, as the window system asked.
///
/// `alpha_bits` is 8 or 0. Storage is RGBA8 either way; a surface without
/// alpha (a GLX RGB config) keeps every stored alpha at 255: it starts so,
/// fragments OR 255 into the alpha they store
/// (`render::fragment::FragmentState::alpha_fix`, so the full-mask span
/// kernels still apply), and the other writers (clear, accumulation
/// RETURN, blits) go through [`Config::color_mask`] or store 255. Reads (glReadPixels, GL_DST_ALPHA blending,
/// copies into textures) therefore see 1.0, as GL 1.5 section 4.1.8 and
/// 4.3.2 require of a buffer with no alpha.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Config {
    pub alpha_bits: u8,
    pub depth_bits: u8,
    pub stencil_bits: u8,
    pub accum_bits: u8,
}

impl Config {
    /// The colour write mask as applied to this surface: alpha is never
    /// written when the surface has none.
    pub fn color_mask(&self, mask: [bool; 4]) -> [bool; 4] {
        [mask[0], mask[1], mask[2], mask[3] && self.alpha_bits > 0]
    }

    /// What a colour buffer's pixels start as.
    pub fn initial_color(&self) -> [u8; 4] {
        if self.alpha_bits > 0 { [0; 4] } else { [0, 0, 0, 255] }
    }
}

#[derive(Debug)]
pub struct AllocError;

/// The buffers a context draws into.
pub struct Framebuffer {
    pub width: usize,
    pub height: usize,
    pub config: Config,
    /// The colour buffer drawing writes (see the module comment).
    pub color: ColorBuffer,
    /// Double-buffered surfaces: the other colour buffer; empty otherwise.
    pub other_color: ColorBuffer,
    /// Whether `color` is the back buffer (never, single-buffered).
    pub color_is_back: bool,
    /// GL_FRONT_AND_BACK on a double-buffered surface: every colour write
    /// to `color` is repeated into `other_color`.
    pub draw_both: bool,
    /// Something may have been drawn into the front buffer of a
    /// double-buffered surface since it was last presented: glFlush and
    /// glFinish present it then.
    pub front_dirty: bool,
    double: bool,
    pub depth: Plane<u32>,
    pub stencil: Plane<u8>,
    pub accum: Plane<[i16; 4]>,
    /// A glClear of the accumulation buffer not yet written into `accum`:
    /// the rectangle and the fixed-point value (`gl::accum`; a GL_LOAD
    /// that covers the rectangle makes the fill unnecessary).
    pub accum_clear: Option<(Rect, [i16; 4])>,
    /// Fragments that have passed the depth test (or reached it with the
    /// test off) since the context began: occlusion queries (gl::queries)
    /// take differences of it. Wraps.
    pub samples_passed: u64,
}

impl Framebuffer {
    /// An empty (0x0) framebuffer with the given ancillary buffers.
    pub fn new(config: Config) -> Framebuffer {
        Framebuffer {
            width: 0,
            height: 0,
            config,
            color: ColorBuffer::default(),
            other_color: ColorBuffer::default(),
            color_is_back: false,
            draw_both: false,
            front_dirty: false,
            double: false,
            depth: Plane::default(),
            stencil: Plane::default(),
            accum: Plane::default(),
            accum_clear: None,
            samples_passed: 0,
        }
    }

    /// Gives the surface a back buffer (or takes it away). A new back
    /// buffer starts as a copy of the front one.
    pub fn set_double_buffered(&mut self, double: bool) -> Result<(), AllocError> {
        if double == self.double {
            return Ok(());
        }
        if double {
            let mut back = Vec::new();
            back.try_reserve_exact(self.color.len()).map_err(|_| AllocError)?;
            back.extend_from_slice(&self.color);
            self.other_color = ColorBuffer::owned(Plane::from_vec(back));
            self.color_is_back = false;
        } else {
            if self.color_is_back {
                std::mem::swap(&mut self.color, &mut self.other_color);
            }
            self.other_color = ColorBuffer::default();
            self.color_is_back = false;
            self.draw_both = false;
        }
        self.double = double;
        Ok(())
    }

    pub fn is_double_buffered(&self) -> bool {
        self.double
    }

    /// Whether [`Self::select_draw`] of `target` would swap the colour
    /// buffers.
    pub fn select_swaps(&self, target: DrawTarget) -> bool {
        let want_back = match target {
            DrawTarget::Front => false,
            DrawTarget::Back | DrawTarget::FrontAndBack => true,
            DrawTarget::None => self.color_is_back,
        };
        self.double && want_back != self.color_is_back
    }

    /// Points drawing at the buffers glDrawBuffer names. Cheap when nothing
    /// changes; a no-op on a single-buffered surface, whose one buffer is
    /// every name that exists.
    pub fn select_draw(&mut self, target: DrawTarget) {
        if !self.double {
            return;
        }
        let (want_back, both) = match target {
            DrawTarget::Front => (false, false),
            DrawTarget::Back => (true, false),
            DrawTarget::FrontAndBack => (true, true),
            DrawTarget::None => (self.color_is_back, false),
        };
        if want_back != self.color_is_back {
            std::mem::swap(&mut self.color, &mut self.other_color);
            self.color_is_back = want_back;
        }
        self.draw_both = both;
        if matches!(target, DrawTarget::Front | DrawTarget::FrontAndBack) {
            self.front_dirty = true;
        }
    }

    /// The front colour buffer: what a window shows.
    pub fn front(&self) -> &[[u8; 4]] {
        if self.color_is_back {
            &self.other_color
        } else {
            &self.color
        }
    }

    /// The back colour buffer (the front one on a single-buffered surface).
    pub fn back(&self) -> &[[u8; 4]] {
        if self.double && !self.color_is_back {
            &self.other_color
        } else {
            &self.color
        }
    }

    /// The colour buffer glReadBuffer names: the back one or the front one.
    pub fn read_color(&self, back: bool) -> &[[u8; 4]] {
        if back {
            self.back()
        } else {
            self.front()
        }
    }

    /// The colour buffers drawing writes: `color`, and `other_color` for
    /// FRONT_AND_BACK. For glClear and glAccum's RETURN.
    pub fn draw_colors(&mut self) -> impl Iterator<Item = &mut ColorBuffer> {
        let both = self.draw_both;
        std::iter::once(&mut self.color).chain(both.then_some(&mut self.other_color))
    }

    /// SwapBuffers: the back buffer's contents become the front buffer's;
    /// the back buffer keeps them (see the module comment).
    pub fn swap_buffers(&mut self) {
        if !self.double {
            return;
        }
        if self.color_is_back {
            self.other_color.copy_from_slice(&self.color);
        } else {
            self.color.copy_from_slice(&self.other_color);
        }
        self.front_dirty = false;
    }

    /// Copies the back buffer's rectangle at (x, y) (window coordinates,
    /// origin bottom left), `width` x `height`, clipped to the buffer, into
    /// the front buffer (GLX_MESA_copy_sub_buffer).
    pub fn copy_back_to_front(&mut self, x: isize, y: isize, width: usize, height: usize) {
        if !self.double {
            return;
        }
        let x0 = x.clamp(0, self.width as isize) as usize;
        let y0 = y.clamp(0, self.height as isize) as usize;
        let x1 = x.saturating_add(width as isize).clamp(0, self.width as isize) as usize;
        let y1 = y.saturating_add(height as isize).clamp(0, self.height as isize) as usize;
        if x0 >= x1 {
            return;
        }
        let (back, front) = if self.color_is_back { (&self.color, &mut self.other_color) } else { (&self.other_color, &mut self.color) };
        for row in y0..y1 {
            let i = row * self.width;
            front[i + x0..i + x1].copy_from_slice(&back[i + x0..i + x1]);
        }
    }

    /// Resizes to `width` x `height`. Contents become undefined (zero), as
    /// after a window resize. Fails without changing anything when the size
    /// is out of range or memory runs out.
    pub fn resize(&mut self, width: usize, height: usize) -> Result<(), AllocError> {
        if width > MAX_SIZE || height > MAX_SIZE {
            return Err(AllocError);
        }
        if width == self.width && height == self.height {
            return Ok(());
        }
        let n = width * height;
        let color = ColorBuffer::owned(Plane::new(n, self.config.initial_color())?);
        let other_color = if self.double { ColorBuffer::owned(Plane::new(n, self.config.initial_color())?) } else { ColorBuffer::default() };
        let depth = if self.config.depth_bits > 0 { Plane::new(n, 0u32)? } else { Plane::default() };
        let stencil = if self.config.stencil_bits > 0 { Plane::new(n, 0u8)? } else { Plane::default() };
        let accum = if self.config.accum_bits > 0 { Plane::new(n, [0i16; 4])? } else { Plane::default() };
        *self = Framebuffer {
            width,
            height,
            config: self.config,
            color,
            other_color,
            color_is_back: self.color_is_back,
            draw_both: self.draw_both,
            front_dirty: false,
            double: self.double,
            depth,
            stencil,
            accum,
            accum_clear: None,
            samples_passed: self.samples_passed,
        };
        Ok(())
    }

    /// Draws into the caller's memory from now on (OSMesa, when its buffer
    /// has the colour buffer's own layout; see `color`): the caller's
    /// pixels are the colour buffer's contents. Single-buffered surfaces
    /// only.
    ///
    /// # Safety
    /// `ptr` must hold width x height RGBA8 pixels, rows bottom-up, valid
    /// until the colour buffer is replaced (`own_color`, `resize`) or the
    /// framebuffer dropped.
    pub unsafe fn lend_color(&mut self, ptr: *mut u8) {
        debug_assert!(!self.double);
        // A freshly calloc'ed 1920x1080 buffer would otherwise take ~2,000
        // 4 KiB faults in the first glClear (see `plane`). Advisory: the
        // caller's pixels do not change.
        plane::advise_huge_pages(ptr, self.width * self.height * 4);
        self.color = ColorBuffer::lent(ptr, self.width * self.height);
    }

    /// Gives the colour buffer fresh storage of its own when it was lent
    /// (contents as after a resize; no-op when it has its own already).
    pub fn unlend_color(&mut self) -> Result<(), AllocError> {
        if self.color.is_lent() {
            self.color = ColorBuffer::owned(Plane::new(self.color.len(), self.config.initial_color())?);
        }
        Ok(())
    }

    /// Gives the colour buffer storage of its own again, holding what the
    /// caller's memory holds now (no-op when it has its own already).
    pub fn own_color(&mut self) -> Result<(), AllocError> {
        if self.color.is_lent() {
            let mut v = Vec::new();
            v.try_reserve_exact(self.color.len()).map_err(|_| AllocError)?;
            v.extend_from_slice(&self.color);
            self.color = ColorBuffer::owned(Plane::from_vec(v));
        }
        Ok(())
    }

    #[inline]
    pub fn index(&self, x: usize, y: usize) -> usize {
        y * self.width + x
    }

    pub fn has_depth(&self) -> bool {
        !self.depth.is_empty()
    }

    pub fn has_stencil(&self) -> bool {
        !self.stencil.is_empty()
    }
}

/// Which colour buffers glDrawBuffer's mode names on this surface.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum DrawTarget {
    Front,
    Back,
    FrontAndBack,
    None,
}

/// A pixel rectangle [x0, x1) x [y0, y1) in window coordinates.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Default)]
pub struct Rect {
    pub x0: i32,
    pub y0: i32,
    pub x1: i32,
    pub y1: i32,
}

impl Rect {
    pub fn new(x: i32, y: i32, w: i32, h: i32) -> Rect {
        Rect { x0: x, y0: y, x1: x.saturating_add(w), y1: y.saturating_add(h) }
    }

    pub fn intersect(self, o: Rect) -> Rect {
        Rect { x0: self.x0.max(o.x0), y0: self.y0.max(o.y0), x1: self.x1.min(o.x1), y1: self.y1.min(o.y1) }
    }

    pub fn is_empty(&self) -> bool {
        self.x0 >= self.x1 || self.y0 >= self.y1
    }
}

/// Where a context's finished pixels go: a caller's OSMesa buffer, an X
/// window, a PNG dump. The window system installs one at MakeCurrent; GL
/// calls it at glFlush/glFinish (single-buffered, or a double-buffered
/// surface whose front buffer was drawn) and SwapBuffers. It shows
/// `fb.front()`.
pub trait Present {
    fn present(&mut self, fb: &Framebuffer);
}
