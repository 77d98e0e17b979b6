//! Binning and tiled, threaded triangle setup and rasterization (DESIGN.md
//! "Tiles and threads"; issue 9 item 4).
//!
//! With more than one thread, filled triangles are not set up at once: the
//! calling thread only orients and culls them and appends a cheap record to
//! the context's [`Batch`] (fixed-point vertices, window depth, 1/w and the
//! attributes setup reads, and an index into the batch's list of captured
//! states, `shade_state::ShadeState`, one per state change). [`flush`]
//! shades the batch: the screen is cut into TILE x TILE tiles, each
//! triangle is listed in the tiles its bounding box touches, and the
//! persistent workers of [`super::pool`] with the calling thread take
//! tiles one at a time. A worker finds a triangle's runs within its tile
//! and, when it covers a pixel there, computes its planes and shades them
//! (a triangle covering several tiles is set up once per tile: the same
//! inputs give the same planes). Within a tile the triangles run in
//! submission order, so every pixel sees its fragments in GL's order, and
//! no two threads ever touch the same pixel. Setup, span finding and
//! shading thus all run in parallel; the vertex stage, clipping and
//! binning stay on the calling thread.
//!
//! Images do not depend on the thread count: setup is a pure function of
//! the record, and no kernel's result depends on where a span starts (the
//! stepped colour is anchored at column 0 of the row:
//! `fragment::fast::stepped_start`), so cutting spans at tile edges
//! changes nothing.
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
use super::fragment::SpanPixels;
use super::raster;
use super::setup::{planes_of, Attributes, TriangleSetup};
use super::shade_state::ShadeState;
use super::texture::MAX_UNITS;
use super::RenderState;
use crate::framebuffer::{Framebuffer, Rect};
use glam::Vec4;
use std::sync::atomic::{AtomicBool, AtomicU64, AtomicUsize, Ordering};
use std::sync::{Arc, Mutex};

/// Tile side in pixels. 128 rather than llvmpipe's 64: each span piece
/// repeats the span set-up, and at 64 that cost 18% more instructions
/// than shading untiled (particles at 1920x1080; 8% at 128), while 135
/// tiles of a 1080p frame still balance two threads.
pub const TILE: usize = 128;

/// The most triangles a batch holds before it is shaded (its memory,
/// about 180 bytes a triangle, stays bounded).
pub const MAX_BATCH: usize = 32 * 1024;

/// Batches with less work than this are shaded on the calling thread:
/// starting workers would cost more. Work is counted in pixels of the
/// triangles' bounding boxes plus [`SETUP_PIXELS`] per triangle.
const PARALLEL_WORK: u64 = 32 * 1024;

/// A triangle's setup and span scan, counted as this many pixels.
const SETUP_PIXELS: u64 = 32;

/// SOFTGL_THREADS, or the number of cores.
pub fn threads_default() -> usize {
    static N: std::sync::OnceLock<usize> = std::sync::OnceLock::new();
    *N.get_or_init(|| match std::env::var("SOFTGL_THREADS").ok().and_then(|v| v.trim().parse::<usize>().ok()) {
        Some(n) if n >= 1 => n.min(64),
        _ => std::thread::available_parallelism().map(|n| n.get()).unwrap_or(1),
    })
}

/// What setup reads of a binned vertex besides its position.
#[derive(Clone, Copy, Debug)]
struct BinVertex {
    z: f64,
    q: f64,
    /// The colour of the side the triangle shows (two-sided lighting),
    /// or the provoking vertex's colour when flat shaded.
    color: Vec4,
}

/// The attributes only texturing and fog read, per vertex.
#[derive(Clone, Copy, Debug)]
struct BinExtra {
    tex: [[Vec4; MAX_UNITS]; 3],
    fog: [f32; 3],
    /// The secondary colour of the side shown.
    secondary: [Vec4; 3],
}

const NO_EXTRA: BinExtra = BinExtra { tex: [[Vec4::ZERO; MAX_UNITS]; 3], fog: [0.0; 3], secondary: [Vec4::ZERO; 3] };

/// A triangle waiting to be set up and shaded (in a tile worker): its
/// positively oriented fixed-point vertices, what setup reads of them,
/// and the state it was drawn under.
#[derive(Debug)]
struct Binned {
    x: [i64; 3],
    y: [i64; 3],
    v: [BinVertex; 3],
    /// Pixels the triangle may touch: its bounding box within the draw
    /// rectangle.
    bbox: Rect,
    /// Index in [`Batch::states`].
    state: u32,
    /// Index in [`Batch::extras`], or `u32::MAX`.
    extra: u32,
    front_facing: bool,
}

/// One vertex of a binned triangle as setup reads it.
struct BinAttributes<'a> {
    color: Vec4,
    extra: &'a BinExtra,
    i: usize,
}

impl Attributes for BinAttributes<'_> {
    #[inline(always)]
    fn color(&self) -> Vec4 {
        self.color
    }
    #[inline(always)]
    fn back_color(&self) -> Vec4 {
        self.color
    }
    #[inline(always)]
    fn tex(&self, unit: usize) -> Vec4 {
        self.extra.tex[self.i][unit]
    }
    #[inline(always)]
    fn fog(&self) -> f32 {
        self.extra.fog[self.i]
    }
    #[inline(always)]
    fn secondary(&self) -> Vec4 {
        self.extra.secondary[self.i]
    }
    #[inline(always)]
    fn back_secondary(&self) -> Vec4 {
        self.extra.secondary[self.i]
    }
}

/// The triangles binned since the last flush.
#[derive(Default)]
pub struct Batch {
    tris: Vec<Binned>,
    extras: Vec<BinExtra>,
    /// The states the triangles were drawn under, in order.
    states: Vec<Arc<ShadeState>>,
    /// Pixels of the triangles' bounding boxes.
    pixels: u64,
}

impl std::fmt::Debug for Batch {
    fn fmt(&self, f: &mut std::fmt::Formatter) -> std::fmt::Result {
        write!(f, "Batch({} triangles)", self.tris.len())
    }
}

/// A context's batch and whether it holds anything: checked without the
/// lock, so that the commands of a scene that bins nothing cost no
/// locking. Only the thread using the context changes either.
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

/// A triangle's bounding box (positively oriented fixed-point vertices)
/// within the draw rectangle, widened by a pixel each way (a superset is
/// enough: spans are exact); None when empty.
#[inline]
pub fn bounds(rs: &RenderState, x: [i64; 3], y: [i64; 3]) -> Option<Rect> {
    let r = rs.draw_rect;
    // Floor division by ONE; min/max rather than clamp (no assertion).
    let px = |c: i64| c >> super::setup::SUBPIXEL_BITS;
    let fit = |v: i64, lo: i32, hi: i32| v.max(lo as i64).min(hi as i64) as i32;
    let bbox = Rect {
        x0: fit(px(x[0].min(x[1]).min(x[2])) - 1, r.x0, r.x1),
        x1: fit(px(x[0].max(x[1]).max(x[2])) + 2, r.x0, r.x1),
        y0: fit(px(y[0].min(y[1]).min(y[2])) - 1, r.y0, r.y1),
        y1: fit(px(y[0].max(y[1]).max(y[2])) + 2, r.y0, r.y1),
    };
    (!bbox.is_empty()).then_some(bbox)
}

/// Adds a triangle to the batch, to be set up in a worker: positively
/// oriented fixed-point vertices (x, y), their window depth and 1/w, and
/// their attributes; `flat_color` and `back` as for `setup::planes_of`.
/// True when the batch reached [`MAX_BATCH`] and should be flushed.
#[allow(clippy::too_many_arguments)]
#[inline]
pub fn push<A: Attributes>(rs: &RenderState, x: [i64; 3], y: [i64; 3], bbox: Rect, zq: [(f64, f64); 3], v: [&A; 3], flat_color: Vec4, back: bool, front_facing: bool) -> bool {
    let area = (bbox.x1 - bbox.x0) as u64 * (bbox.y1 - bbox.y0) as u64;
    let mut b = lock(&rs.batch);
    rs.batch.pending.store(true, Ordering::Relaxed);
    let b = &mut *b;
    let (state, flat, extra) = rs.shade.with(rs, |st| {
        if !b.states.last().is_some_and(|l| Arc::ptr_eq(l, st)) {
            b.states.push(st.clone());
        }
        (b.states.len() as u32 - 1, st.flat, st.texture.is_some() || st.fog.is_some())
    });
    let extra = if extra {
        b.extras.push(BinExtra {
            tex: std::array::from_fn(|i| std::array::from_fn(|u| v[i].tex(u))),
            fog: std::array::from_fn(|i| v[i].fog()),
            secondary: std::array::from_fn(|i| if back { v[i].back_secondary() } else { v[i].secondary() }),
        });
        b.extras.len() as u32 - 1
    } else {
        u32::MAX
    };
    let color = |i: usize| {
        if flat {
            flat_color
        } else if back {
            v[i].back_color()
        } else {
            v[i].color()
        }
    };
    let v = std::array::from_fn(|i| BinVertex { z: zq[i].0, q: zq[i].1, color: color(i) });
    b.pixels += area;
    b.tris.push(Binned { x, y, v, bbox, state, extra, front_facing });
    b.tris.len() >= MAX_BATCH
}

/// Sets up a binned triangle and hands its covered runs within `rect` to
/// `span(kernel, setup, y, x0, x1)`; a triangle covering no pixel centre
/// there is not set up. The setup is the one shading it at once would
/// compute (the same inputs to `planes_of`), so the pixels are the same.
#[inline]
fn shade_binned(t: &Binned, st: &ShadeState, extra: &BinExtra, rect: Rect, mut span: impl FnMut(Kernel, &TriangleSetup, usize, usize, usize)) {
    let stipple = st.polygon_stipple.as_deref();
    let mut runs = raster::Runs::new();
    let found = runs.find(t.x, t.y, rect, stipple);
    if found && runs.is_empty() {
        return;
    }
    let a = [0, 1, 2].map(|i| BinAttributes { color: t.v[i].color, extra, i });
    let zq = t.v.map(|v| (v.z, v.q));
    let setup = planes_of(st, zq, a.each_ref(), t.x, t.y, t.v[0].color, false, t.front_facing);
    let k = st.kernel(&setup);
    if found {
        for (py, lo, hi) in runs.iter() {
            span(k, &setup, py, lo, hi);
        }
    } else {
        raster::spans(t.x, t.y, rect, stipple, |py, lo, hi| span(k, &setup, py, lo, hi));
    }
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
    let (tris, extras, states, pixels) = {
        let mut b = lock(&rs.batch);
        rs.batch.pending.store(false, Ordering::Relaxed);
        if b.tris.is_empty() {
            return;
        }
        let pixels = std::mem::replace(&mut b.pixels, 0);
        (std::mem::take(&mut b.tris), std::mem::take(&mut b.extras), std::mem::take(&mut b.states), pixels)
    };
    shade_batch(rs, fb, &tris, &extras, &states, pixels);
    // The emptied vectors go back, keeping their capacity (no regrowth
    // and copying per batch).
    let (mut tris, mut extras, mut states) = (tris, extras, states);
    tris.clear();
    extras.clear();
    states.clear();
    let mut b = lock(&rs.batch);
    if b.tris.capacity() == 0 {
        b.tris = tris;
    }
    if b.extras.capacity() == 0 {
        b.extras = extras;
    }
    if b.states.capacity() == 0 {
        b.states = states;
    }
}

/// Shades binned triangles (the body of [`flush`]).
fn shade_batch(rs: &RenderState, fb: &mut Framebuffer, tris: &[Binned], extras: &[BinExtra], states: &[Arc<ShadeState>], pixels: u64) {
    let of = |t: &Binned| (&*states[t.state as usize], extras.get(t.extra as usize).unwrap_or(&NO_EXTRA));
    // The framebuffer may have changed size since binning only through
    // commands outside the draw call, which never happens with work
    // pending; still, never write outside it.
    let surface = Rect::new(0, 0, fb.width as i32, fb.height as i32);
    let threads = rs.threads;
    if threads <= 1 || pixels + SETUP_PIXELS * (tris.len() as u64) < PARALLEL_WORK {
        for t in tris {
            let (st, extra) = of(t);
            shade_binned(t, st, extra, t.bbox.intersect(surface), |k, setup, py, lo, hi| {
                let mut px = SpanPixels::of(fb, py, lo, hi);
                k(&st.fragment, setup, &mut px, py, lo, hi);
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
                let (st, extra) = of(t);
                shade_binned(t, st, extra, r, |kernel, setup, py, lo, hi| {
                    // Safety: inside the surface and inside this tile, which
                    // no other worker holds.
                    let mut px = unsafe { raw.span(py, lo, hi) };
                    kernel(&st.fragment, setup, &mut px, py, lo, hi);
                    local += px.passed;
                });
            }
        }
        passed.fetch_add(local, Ordering::Relaxed);
    };
    super::pool::run(threads, work);
    fb.samples_passed = fb.samples_passed.wrapping_add(passed.into_inner());
}
