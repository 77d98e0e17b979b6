//! Framebuffer storage (GL 1.5 chapter 4 intro): the colour buffer (RGBA,
//! 8 bits per channel), the depth buffer (24 bits, kept in the low bits of a
//! u32), the stencil buffer (8 bits) and the accumulation buffer (16 bits
//! signed per channel). Rows are stored bottom-up: row 0 is window y = 0,
//! as in GL's window coordinates, so the pipeline never flips.
//!
//! Allocation is fallible: a surface too large for memory is reported, never
//! aborts the program.

/// Largest surface side; also GL_MAX_VIEWPORT_DIMS. The rasterizer's
/// fixed-point ranges are chosen for it (see `render::setup`).
pub const MAX_SIZE: usize = 16384;

/// Bits of depth stored per pixel.
pub const DEPTH_BITS: u32 = 24;
pub const DEPTH_MAX: u32 = (1 << DEPTH_BITS) - 1;

/// Which ancillary buffers a surface has, as the window system asked.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Config {
    pub depth_bits: u8,
    pub stencil_bits: u8,
    pub accum_bits: u8,
}

#[derive(Debug)]
pub struct AllocError;

/// The buffers a context draws into.
pub struct Framebuffer {
    pub width: usize,
    pub height: usize,
    pub config: Config,
    pub color: Vec<[u8; 4]>,
    pub depth: Vec<u32>,
    pub stencil: Vec<u8>,
    pub accum: Vec<[i16; 4]>,
    /// Fragments that have passed the depth test (or reached it with the
    /// test off) since the context began: occlusion queries (gl::queries)
    /// take differences of it. Wraps.
    pub samples_passed: u64,
}

fn alloc<T: Copy>(n: usize, fill: T) -> Result<Vec<T>, AllocError> {
    let mut v = Vec::new();
    v.try_reserve_exact(n).map_err(|_| AllocError)?;
    v.resize(n, fill);
    Ok(v)
}

impl Framebuffer {
    /// An empty (0x0) framebuffer with the given ancillary buffers.
    pub fn new(config: Config) -> Framebuffer {
        Framebuffer { width: 0, height: 0, config, color: Vec::new(), depth: Vec::new(), stencil: Vec::new(), accum: Vec::new(), samples_passed: 0 }
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
        let color = alloc(n, [0u8; 4])?;
        let depth = if self.config.depth_bits > 0 { alloc(n, 0u32)? } else { Vec::new() };
        let stencil = if self.config.stencil_bits > 0 { alloc(n, 0u8)? } else { Vec::new() };
        let accum = if self.config.accum_bits > 0 { alloc(n, [0i16; 4])? } else { Vec::new() };
        *self = Framebuffer { width, height, config: self.config, color, depth, stencil, accum, samples_passed: self.samples_passed };
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
/// calls it at glFlush/glFinish (single-buffered) or SwapBuffers.
pub trait Present {
    fn present(&mut self, fb: &Framebuffer);
}
