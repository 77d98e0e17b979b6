//! Binning and tiled, threaded triangle rasterization (DESIGN.md "Tiles and
//! threads"; issue 9 item 4).
//!
//! Filled triangles are not shaded at once: setup captures each one with
//! everything it needs (its planes, fixed-point vertices, the fragment
//! state, draw rectangle, stipple and the span kernel chosen for it) into
//! the context's [`Batch`], across draw calls. [`flush`] shades the batch:
//! the screen is cut into TILE x TILE tiles, each triangle is listed in the
//! tiles its bounding box touches, and the persistent workers of
//! [`super::pool`] with the calling thread take tiles one at a time;
//! within a tile the triangles run in submission order, so every pixel
//! sees its fragments in GL's order, and no two threads ever touch the
//! same pixel.
//!
//! The batch is flushed before anything else reads or writes the
//! framebuffer or changes which buffer is drawn: by the context before
//! every command that is not known to leave the framebuffer alone
//! (`Context::execute`'s list, every immediate (`exec`/`client`) entry
//! point and every window-system call: present, MakeCurrent, resize,
//! queries, pixel commands, clears), and by the renderer before it draws
//! points, lines, antialiased or polygon-mode triangles or to two colour
//! buffers at once. Later state changes cannot reach binned triangles:
//! they carry their own copy of the state (textures are copy-on-write).
//! A batch is also flushed when it holds [`MAX_BATCH`] triangles.
//!
//! `SOFTGL_THREADS=N` (read once per process) sets the thread count; the
//! default is every core, and 1 shades each triangle immediately with no
//! binning. Batches covering few pixels are shaded on the calling thread.

use super::fragment::fast::Kernel;
use super::fragment::{FragmentState, SpanPixels};
use super::raster;
use super::setup::{TriangleSetup, ONE};
use super::RenderState;
use crate::framebuffer::{Framebuffer, Rect};
use std::sync::atomic::{AtomicBool, AtomicU64, AtomicUsize, Ordering};
use std::sync::{Arc, Mutex};

/// Tile side in pixels. 128 rather than llvmpipe's 64: each span piece
/// repeats the span set-up, and at 64 that cost 18% more instructions
/// than shading untiled (particles at 1920x1080; 8% at 128), while 135
/// tiles of a 1080p frame still balance two threads.
pub const TILE: usize = 128;

/// The most triangles a batch holds before it is shaded (its memory,
/// about 400 bytes a triangle, stays bounded).
pub const MAX_BATCH: usize = 32 * 1024;

/// Batches whose triangles' bounding boxes cover fewer pixels than this
/// are shaded on the calling thread: starting workers would cost more.
const PARALLEL_PIXELS: u64 = 32 * 1024;

/// SOFTGL_THREADS, or the number of cores.
pub fn threads_default() -> usize {
    static N: std::sync::OnceLock<usize> = std::sync::OnceLock::new();
    *N.get_or_init(|| match std::env::var("SOFTGL_THREADS").ok().and_then(|v| v.trim().parse::<usize>().ok()) {
        Some(n) if n >= 1 => n.min(64),
        _ => std::thread::available_parallelism().map(|n| n.get()).unwrap_or(1),
    })
}

/// A triangle waiting to be shaded, with the state it was drawn under.
struct Binned {
    setup: TriangleSetup,
    x: [i64; 3],
    y: [i64; 3],
    fs: Arc<FragmentState>,
    stipple: Option<Box<[u32; 32]>>,
    kernel: Kernel,
    /// Pixels the triangle may touch: its bounding box within the draw
    /// rectangle.
    bbox: Rect,
}

/// The triangles of the current draw call.
#[derive(Default)]
pub struct Batch {
    tris: Vec<Binned>,
    pixels: u64,
    /// The fragment state of the last binned triangle, shared by the
    /// following ones while it does not change.
    last_fs: Option<Arc<FragmentState>>,
}

impl std::fmt::Debug for Batch {
    fn fmt(&self, f: &mut std::fmt::Formatter) -> std::fmt::Result {
        write!(f, "Batch({} triangles)", self.tris.len())
    }
}

/// A context's batch and whether it holds anything: checked without the
/// lock, so that the many small triangles and the commands of a scene
/// that bins nothing cost no locking. Only the thread using the context
/// changes either.
#[derive(Default, Debug)]
pub struct BatchCell {
    pending: AtomicBool,
    batch: Mutex<Batch>,
}

/// A context's batch, shared by clones of its RenderState.
pub type SharedBatch = Arc<BatchCell>;

fn lock(b: &SharedBatch) -> std::sync::MutexGuard<'_, Batch> {
    b.batch.lock().unwrap_or_else(|e| e.into_inner())
}

/// Should this triangle be binned rather than shaded now?
#[inline]
pub fn binning(rs: &RenderState) -> bool {
    rs.threads > 1 && !rs.reference
}

/// Triangles whose bounding box covers fewer pixels than this are shaded
/// at once when nothing is binned before them (order is kept): binning
/// costs more than it saves for a sphere's strips.
const SMALL_PIXELS: u64 = 1024;

/// Where a triangle goes: shaded now, or queued in the batch.
pub enum Route {
    /// Small, and nothing pending: shade it now.
    ShadeNow,
    /// Nothing to draw (outside the draw rectangle).
    Nothing,
    /// Bin it with this bounding box ([`push`]).
    Bin(Rect),
}

/// Decides where a triangle (positively oriented fixed-point vertices)
/// goes, before its setup is moved anywhere.
#[inline]
pub fn route(rs: &RenderState, x: [i64; 3], y: [i64; 3]) -> Route {
    let r = rs.draw_rect;
    let px = |c: i64| c.div_euclid(ONE);
    let bbox = Rect {
        x0: (px(x[0].min(x[1]).min(x[2])) - 1).clamp(r.x0 as i64, r.x1 as i64) as i32,
        x1: (px(x[0].max(x[1]).max(x[2])) + 2).clamp(r.x0 as i64, r.x1 as i64) as i32,
        y0: (px(y[0].min(y[1]).min(y[2])) - 1).clamp(r.y0 as i64, r.y1 as i64) as i32,
        y1: (px(y[0].max(y[1]).max(y[2])) + 2).clamp(r.y0 as i64, r.y1 as i64) as i32,
    };
    if bbox.is_empty() {
        return Route::Nothing;
    }
    let area = (bbox.x1 - bbox.x0) as u64 * (bbox.y1 - bbox.y0) as u64;
    if area < SMALL_PIXELS && !rs.batch.pending.load(Ordering::Relaxed) {
        return Route::ShadeNow;
    }
    Route::Bin(bbox)
}

/// Adds a triangle to the batch ([`Route::Bin`]); true when the batch
/// reached [`MAX_BATCH`] and should be flushed.
pub fn push(rs: &RenderState, x: [i64; 3], y: [i64; 3], bbox: Rect, setup: TriangleSetup) -> bool {
    let area = (bbox.x1 - bbox.x0) as u64 * (bbox.y1 - bbox.y0) as u64;
    let mut b = lock(&rs.batch);
    rs.batch.pending.store(true, Ordering::Relaxed);
    let kernel = raster::kernel(rs, &setup);
    let fs = match &b.last_fs {
        Some(f) if **f == rs.fragment => f.clone(),
        _ => {
            let f = Arc::new(rs.fragment.clone());
            b.last_fs = Some(f.clone());
            f
        }
    };
    b.pixels += area;
    b.tris.push(Binned { setup, x, y, fs, stipple: rs.polygon_stipple.clone(), kernel, bbox });
    b.tris.len() >= MAX_BATCH
}

/// Shades whatever is binned before the caller touches the framebuffer
/// itself (nothing to do with one thread: nothing is ever binned then).
#[inline]
pub fn sync(rs: &RenderState, fb: &mut Framebuffer) {
    if binning(rs) {
        flush(rs, fb);
    }
}

/// The framebuffer's planes as raw pointers, for workers that each write
/// only the pixels of the tiles they took.
struct RawPixels {
    width: usize,
    color: *mut [u8; 4],
    depth: *mut u32,
    stencil: *mut u8,
    has_depth: bool,
    has_stencil: bool,
}

// Workers write disjoint tiles (see `flush`).
unsafe impl Send for RawPixels {}
unsafe impl Sync for RawPixels {}

impl RawPixels {
    fn new(fb: &mut Framebuffer) -> RawPixels {
        RawPixels {
            width: fb.width,
            color: fb.color.as_mut_ptr(),
            depth: fb.depth.as_mut_ptr(),
            stencil: fb.stencil.as_mut_ptr(),
            has_depth: fb.has_depth(),
            has_stencil: fb.has_stencil(),
        }
    }

    /// Pixels [x0, x1) of row y.
    ///
    /// Safety: the span lies inside the framebuffer, and no other live
    /// SpanPixels overlaps it.
    unsafe fn span(&self, y: usize, x0: usize, x1: usize) -> SpanPixels<'_> {
        let (at, n) = (y * self.width + x0, x1 - x0);
        SpanPixels {
            color: std::slice::from_raw_parts_mut(self.color.add(at), n),
            depth: if self.has_depth { std::slice::from_raw_parts_mut(self.depth.add(at), n) } else { &mut [] },
            stencil: if self.has_stencil { std::slice::from_raw_parts_mut(self.stencil.add(at), n) } else { &mut [] },
            // Nothing is binned while drawing to GL_FRONT_AND_BACK (setup).
            other: None,
            passed: 0,
        }
    }
}

/// Shades everything binned, in order; returns when the framebuffer holds
/// the result.
pub fn flush(rs: &RenderState, fb: &mut Framebuffer) {
    if !rs.batch.pending.load(Ordering::Relaxed) {
        return;
    }
    let (tris, pixels) = {
        let mut b = lock(&rs.batch);
        rs.batch.pending.store(false, Ordering::Relaxed);
        if b.tris.is_empty() {
            return;
        }
        let pixels = std::mem::replace(&mut b.pixels, 0);
        (std::mem::take(&mut b.tris), pixels)
    };
    // The framebuffer may have changed size since binning only through
    // commands outside the draw call, which never happens with work
    // pending; still, never write outside it.
    let surface = Rect::new(0, 0, fb.width as i32, fb.height as i32);
    let threads = rs.threads;
    if threads <= 1 || pixels < PARALLEL_PIXELS {
        for t in &tris {
            raster::spans(t.x, t.y, t.bbox.intersect(surface), t.stipple.as_deref(), |py, lo, hi| {
                let mut px = SpanPixels::of(fb, py, lo, hi);
                (t.kernel)(&t.fs, &t.setup, &mut px, py, lo, hi);
                let passed = px.passed;
                fb.samples_passed = fb.samples_passed.wrapping_add(passed);
            });
        }
        return;
    }
    let (tw, th) = (fb.width.div_ceil(TILE), fb.height.div_ceil(TILE));
    let mut bins: Vec<Vec<u32>> = vec![Vec::new(); tw * th];
    for (i, t) in tris.iter().enumerate() {
        let b = t.bbox.intersect(surface);
        if b.is_empty() {
            continue;
        }
        let (tx0, tx1) = (b.x0 as usize / TILE, (b.x1 as usize - 1) / TILE);
        let (ty0, ty1) = (b.y0 as usize / TILE, (b.y1 as usize - 1) / TILE);
        for ty in ty0..=ty1 {
            for tx in tx0..=tx1 {
                bins[ty * tw + tx].push(i as u32);
            }
        }
    }
    let raw = RawPixels::new(fb);
    let next = AtomicUsize::new(0);
    let passed = AtomicU64::new(0);
    let work = &|| {
        let mut local = 0u64;
        loop {
            let k = next.fetch_add(1, Ordering::Relaxed);
            if k >= bins.len() {
                break;
            }
            let (tx, ty) = ((k % tw) * TILE, (k / tw) * TILE);
            let tile = Rect { x0: tx as i32, y0: ty as i32, x1: (tx + TILE).min(raw.width) as i32, y1: (ty + TILE) as i32 }.intersect(surface);
            for &i in &bins[k] {
                let t = &tris[i as usize];
                let r = t.bbox.intersect(tile);
                if r.is_empty() {
                    continue;
                }
                raster::spans(t.x, t.y, r, t.stipple.as_deref(), |py, lo, hi| {
                    // Safety: inside the surface and inside this tile, which
                    // no other worker holds.
                    let mut px = unsafe { raw.span(py, lo, hi) };
                    (t.kernel)(&t.fs, &t.setup, &mut px, py, lo, hi);
                    local += px.passed;
                });
            }
        }
        passed.fetch_add(local, Ordering::Relaxed);
    };
    super::pool::run(threads, work);
    fb.samples_passed = fb.samples_passed.wrapping_add(passed.into_inner());
}
