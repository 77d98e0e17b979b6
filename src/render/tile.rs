//! Binning and tiled, threaded triangle setup and rasterization (DESIGN.md
//! "Tiles and threads"; issue 9 item 4).
//!
//! With more than one thread, filled triangles are not set up at once: the
//! calling thread only orients and culls them and appends a cheap record to
//! the context's [`Batch`] (fixed-point vertices, window depth, 1/w and the
//! attributes setup reads, and an index into the batch's list of captured
//! states, `shade_state::ShadeState`, one per state change). Lines and
//! points of the fast path are binned the same way (round 5): clipped and
//! snapped on the calling thread (`line::LineRun`, `point::PointRun`, a
//! record with the box of the pixels they may touch), drawn by each worker
//! within its band (`runs::Band`). A segment's fragments do not depend on
//! the rectangle drawn, and a stippled segment carries the counter it
//! starts with (the calling thread counts its fragments to move the
//! counter on for the next segment of a strip), so bands see exactly the
//! 1-thread fragments. The batch being filled takes no lock (see
//! [`BatchCell`]).
//!
//! Asynchronous flush (round 4): when a batch is full ([`MAX_BATCH`]), or
//! holds [`SUBMIT_WORK`] while the workers are idle, [`submit`] hands it
//! to the persistent workers of [`super::pool`] as a [`Flight`] and
//! returns: the calling thread goes on with the front end (entry points,
//! vertex stage, clipping, binning) and fills the next batch meanwhile
//! (two batches in rotation, their vectors reused). Only the next
//! submission (batches are shaded in order) and the sync points wait for
//! the flight, and the waiting thread shades the bands left rather than
//! sleep: at a sync point every thread shades. Round 13: a batch three
//! quarters full while the flight before is still shaded makes the
//! calling thread take that flight's untaken bands and bin on rather than
//! wait for the last band ([`submit`]), and a flight's bands are taken
//! heaviest first ([`Flight::bin_once`]). A Flight owns all it reads
//! (triangle records, Arc'ed immutable states whose textures are
//! copy-on-write), and writes the framebuffer's planes through raw
//! pointers, which stay valid because everything that reads, writes,
//! resizes, swaps or frees them calls [`sync`] first (see below;
//! `Context` also waits in its Drop).
//!
//! The screen is cut into full-width bands of up to [`BAND`] rows, each
//! triangle listed in the bands its bounding box touches; workers take
//! bands one at a time. A worker finds a triangle's runs within its band
//! and, when it covers a pixel there, computes its planes and shades them
//! (a triangle crossing bands is set up once per band: the same inputs
//! give the same planes). Within a band the triangles run in submission
//! order, so every pixel sees its fragments in GL's order, and no two
//! threads ever touch the same pixel. Bands rather than square tiles: a
//! row is never cut into pieces that each repeat the span set-up.

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
//! smooth points, stippled smooth lines, antialiased or polygon-mode
//! triangles, anything on the reference path, or to two colour
//! buffers at once. Later state changes cannot reach binned triangles:
//! they carry their own copy of the state (textures are copy-on-write).
//! GLX contexts bound to a drawable still wait at the end of every call
//! (`winsys::bound` swaps the drawable's framebuffer in and out), so they
//! overlap only within a call.
//!
//! `SOFTGL_THREADS=N` (read once per process) sets the thread count; the
//! default is every core, and 1 shades each triangle immediately with no
//! binning and no threads at all. Batches with little work
//! ([`PARALLEL_WORK`]) are shaded on the calling thread.
//! `SOFTGL_SUBMIT_WORK` and `SOFTGL_PARALLEL_WORK` override the two
//! thresholds for measurements (round 7: streaming smaller batches to the
//! workers, so that a small frame's front end overlaps its shading, is not
//! yet shown to pay; the pool's hand-off no longer costs a system call
//! while a worker is awake). Whole-frame operations outside the batch
//! (glAccum, large glClear and glReadPixels) are cut into bands of rows
//! by `pool::for_pieces` and `gl::accum`; a large glClear made while
//! binning is instead recorded for the next flight, which writes each
//! band's rows just before drawing that band ([`defer_clear`], round 11),
//! and a large glAccum is recorded in the batch between the primitives,
//! run by each band after the drawing before it ([`BandOp`], round 13).

use super::fragment::fast::Kernel;
use super::fragment::stamp::{StampKernel, Target as StampTarget};
use super::fragment::{Buffers, SpanPixels};
use super::line::{LineEnv, LineRun};
use super::point::PointRun;
use super::pool;
use super::runs;
use super::raster;
use super::records::Records;
use super::setup::{release, Attributes, TriangleSetup};
use super::shade_state::SetupParams;
use super::shade_state::ShadeState;
use super::texture::MAX_UNITS;
use super::vertex::ClipVertex;
use super::RenderState;
use crate::framebuffer::clear::Clear;
use crate::framebuffer::{Framebuffer, Rect};
use glam::Vec4;
use std::cell::UnsafeCell;
use std::sync::atomic::{AtomicBool, AtomicU64, AtomicU8, AtomicUsize, Ordering};
use std::sync::{Arc, Mutex};

/// Tiles are bands of whole rows, this many high at most (fewer when
/// that leaves less than [`BANDS_PER_THREAD`] bands per thread; at least
/// [`MIN_BAND`]). Square 128x128 tiles cut every row of a large triangle
/// into pieces that each repeat the span kernel's set-up, and set a
/// triangle up in each tile it touches: 2 threads executed 35% (overdraw)
/// to 65% (particles) more instructions than 1 thread at 1920x1080;
/// 64-row bands cost 0-2% more. A band's colour, depth and stencil
/// (about 1 MB at 1920 wide) do not stay in cache as a 128x128 tile's
/// would, but neither do the 1-thread path's, which does not tile at all.
pub const BAND: usize = 64;
const MIN_BAND: usize = 16;
const BANDS_PER_THREAD: usize = 8;

/// The band height for a surface `height` rows high shaded by `threads`.
fn band_rows(height: usize, threads: usize) -> usize {
    let mut rows = BAND;
    while rows > MIN_BAND && height.div_ceil(rows) < BANDS_PER_THREAD * threads {
        rows /= 2;
    }
    rows
}

/// The most triangles a batch holds before it is shaded (its memory,
/// 136 bytes a triangle since round 14, stays bounded).
pub const MAX_BATCH: usize = 32 * 1024;

/// A batch holding this much work is handed to the workers as soon as
/// they are idle, without waiting for it to fill (counted as
/// [`PARALLEL_WORK`]).
const SUBMIT_WORK: u64 = 4 * PARALLEL_WORK;

/// Batches with less work than this are shaded on the calling thread:
/// starting workers would cost more. Work is counted in pixels of the
/// triangles' bounding boxes plus [`SETUP_PIXELS`] per triangle.
const PARALLEL_WORK: u64 = 32 * 1024;

/// A triangle's setup and span scan, counted as this many pixels.
const SETUP_PIXELS: u64 = 32;

/// A batch threshold from the environment (`SOFTGL_SUBMIT_WORK`,
/// `SOFTGL_PARALLEL_WORK`, read per context), for measuring smaller
/// streamed batches (round 7: not yet timed on an idle machine, so the
/// defaults stay).
fn tuned(name: &str, default: u64) -> u64 {
    std::env::var(name).ok().and_then(|v| v.parse().ok()).unwrap_or(default)
}

/// SOFTGL_THREADS, or the number of cores.
pub fn threads_default() -> usize {
    static N: std::sync::OnceLock<usize> = std::sync::OnceLock::new();
    *N.get_or_init(|| match std::env::var("SOFTGL_THREADS").ok().and_then(|v| v.trim().parse::<usize>().ok()) {
        Some(n) if n >= 1 => n.min(64),
        _ => std::thread::available_parallelism().map(|n| n.get()).unwrap_or(1),
    })
}

/// What setup reads of a binned vertex besides its position.
/// Round 14: the colour as an array (alignment 8, not 16), so that the
/// record has no padding; it is loaded unaligned on the band side.
#[derive(Clone, Copy, Debug)]
#[repr(C)]
struct BinVertex {
    z: f64,
    q: f64,
    /// The colour of the side the triangle shows (two-sided lighting),
    /// or the provoking vertex's colour when flat shaded.
    color: [f32; 4],
}

/// Where a record's extra attributes (those only texturing, fog and the
/// colour sum read) sit in its run of [`Batch::extras`], in floats: the
/// three vertices' fog coordinates, then each active unit's texture
/// coordinates (three vertices of four), then the secondary colours
/// (three of four). Round 26: a record keeps only what its state's
/// set-up reads (`setup::planes_of`); every record used to carry all four
/// units' coordinates, the fog coordinates and the secondary colours, 256
/// bytes copied on the calling thread for a fogged triangle that needs 12.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct ExtraLayout {
    /// Floats a record takes (0: none).
    len: u8,
    /// The fog coordinates, at 0.
    fog: bool,
    /// The active units, in order, and their coordinates' offsets.
    units: [u8; MAX_UNITS],
    unit_count: u8,
    tex_at: [u8; MAX_UNITS],
    /// The secondary colours' offset, when read.
    secondary_at: Option<u8>,
}

impl ExtraLayout {
    /// What a state's set-up reads: the coordinates of the texture units
    /// in `active`, the fog coordinate when `fog`, the secondary colour
    /// when `color_sum` and textured (section 3.9).
    pub fn of(active: Option<&[usize]>, fog: bool, color_sum: bool) -> ExtraLayout {
        let mut l = ExtraLayout { fog, len: if fog { 3 } else { 0 }, ..ExtraLayout::default() };
        for &u in active.unwrap_or(&[]).iter().take(MAX_UNITS) {
            l.units[l.unit_count as usize] = u as u8;
            l.unit_count += 1;
            l.tex_at[u.min(MAX_UNITS - 1)] = l.len;
            l.len += 12;
        }
        if color_sum && active.is_some() {
            l.secondary_at = Some(l.len);
            l.len += 12;
        }
        l
    }

    /// Floats a record takes.
    pub fn len(&self) -> usize {
        self.len as usize
    }

    /// Does a record keep nothing besides its colours?
    pub fn is_empty(&self) -> bool {
        self.len == 0
    }

    /// Appends what the layout keeps of the vertices `v` (in record
    /// order; the back secondary colours when `back`) to `to`.
    #[inline(always)]
    fn write<A: Attributes>(&self, to: &mut Vec<f32>, v: [&A; 3], back: bool) {
        if self.fog {
            to.extend_from_slice(&v.map(|v| v.fog()));
        }
        for &u in &self.units[..self.unit_count as usize] {
            for v in v {
                to.extend_from_slice(&v.tex(u as usize).to_array());
            }
        }
        if self.secondary_at.is_some() {
            for v in v {
                to.extend_from_slice(&if back { v.back_secondary() } else { v.secondary() }.to_array());
            }
        }
    }
}

/// A record's extra attributes: the batch's floats and the layout of the
/// record's state.
#[derive(Clone, Copy)]
struct Extra<'a> {
    floats: &'a [f32],
    layout: &'a ExtraLayout,
}

impl<'a> Extra<'a> {
    /// The record's own floats (at `at`, past the end for none).
    #[inline(always)]
    fn at(self, at: usize) -> Extra<'a> {
        let floats = self.floats.get(at..at.saturating_add(self.layout.len())).unwrap_or(&[]);
        Extra { floats, ..self }
    }

    /// Four floats at `at` (zeros past the end, which the layout never
    /// asks for).
    #[inline(always)]
    fn vec4(self, at: usize) -> Vec4 {
        self.floats.get(at..at + 4).map_or(Vec4::ZERO, Vec4::from_slice)
    }
}

/// A triangle waiting to be set up and shaded (in a tile worker): its
/// positively oriented fixed-point vertices, what setup reads of them,
/// and the state it was drawn under.
#[derive(Clone, Copy, Debug)]
///
/// Round 14: 128 bytes and 8 more in [`Batch::boxes`], not 176 (the
/// calling thread writes one per triangle and the band side read it
/// twice, from the other core): snapped x and y in i32 (setup's
/// precision note bounds them by 2^27; `setup::bin_snapped` shades
/// anything else at once), the box apart (read alone by the band
/// listing), the facing and the extra index packed into `prim`, no
/// padding, aligned to cache lines (a record a band picks out touches
/// two lines, not three). Every value the band side reads is the one it
/// read before, so the pixels are too.
#[repr(align(64))]
struct Binned {
    v: [BinVertex; 3],
    x: [i32; 3],
    y: [i32; 3],
    /// Index in [`Batch::states`].
    state: u32,
    /// A line: its index in [`Batch::lines`] (bit 31 clear); a point:
    /// [`POINT`] | its index in [`Batch::points`]; a triangle:
    /// [`TRIANGLE`], [`FRONT`] when it faces the front, [`FIT`] when it
    /// fits the cover's lanes, and the offset of its run in
    /// [`Batch::extras`] in the low 28 bits ([`NO_EXTRA_INDEX`] for
    /// none). A line's or point's other fields except the box and state
    /// are unused.
    prim: u32,
}

// The record's size (round 14): no padding.
const _: () = assert!(std::mem::size_of::<Binned>() == 128);

/// The bits of [`Binned::prim`] marking a triangle.
const TRIANGLE: u32 = 3 << 30;
/// The bit of [`Binned::prim`] marking a point (with bit 30 clear).
const POINT: u32 = 1 << 31;
/// The bit of a triangle's [`Binned::prim`] set when it faces the front.
const FRONT: u32 = 1 << 29;
/// The bit of a triangle's [`Binned::prim`] set when its vertices'
/// extents fit the cover's lanes (`raster::CentreBox::lanes_fit`, round
/// 23: found with its box when it is binned).
const FIT: u32 = 1 << 28;
/// The low bits of a triangle's [`Binned::prim`]: its extras' offset.
const NO_EXTRA_INDEX: u32 = FIT - 1;

impl Binned {
    /// Is the record a triangle (not a line or point)?
    #[inline(always)]
    fn is_triangle(&self) -> bool {
        self.prim >= TRIANGLE
    }

    /// A triangle's facing.
    #[inline(always)]
    fn front_facing(&self) -> bool {
        self.prim & FRONT != 0
    }

    /// Do a triangle's extents fit the cover's lanes ([`FIT`])?
    #[inline(always)]
    fn lanes_fit(&self) -> bool {
        self.prim & FIT != 0
    }

    /// The snapped vertices as setup reads them.
    #[inline(always)]
    fn xy(&self) -> ([i64; 3], [i64; 3]) {
        (self.x.map(i64::from), self.y.map(i64::from))
    }
}

/// A record's box as [`Batch::boxes`] stores it: pixels the primitive
/// may touch, within the draw rectangle (x0, y0, x1, y1: within
/// 0..=`framebuffer::MAX_SIZE`); a triangle's is exactly the pixels
/// whose centres lie in its vertices' bounding box (round 23).
type BinBox = [i16; 4];

/// A box within the draw rectangle as a record stores it.
#[inline(always)]
fn packed_box(r: Rect) -> BinBox {
    [r.x0 as i16, r.y0 as i16, r.x1 as i16, r.y1 as i16]
}

/// A stored box as a [`Rect`].
#[inline(always)]
fn rect_of(b: BinBox) -> Rect {
    let [x0, y0, x1, y1] = b.map(i32::from);
    Rect { x0, y0, x1, y1 }
}

/// One vertex of a binned triangle as setup reads it (round 18: its
/// colour read in place from the record, not copied).
struct BinAttributes<'a> {
    v: &'a BinVertex,
    extra: Extra<'a>,
    i: usize,
}

impl Attributes for BinAttributes<'_> {
    #[inline(always)]
    fn color(&self) -> Vec4 {
        Vec4::from_array(self.v.color)
    }
    #[inline(always)]
    fn back_color(&self) -> Vec4 {
        Vec4::from_array(self.v.color)
    }
    #[inline(always)]
    fn tex(&self, unit: usize) -> Vec4 {
        self.extra.vec4(self.extra.layout.tex_at[unit] as usize + 4 * self.i)
    }
    #[inline(always)]
    fn fog(&self) -> f32 {
        // The fog coordinates come first in a run that has them.
        self.extra.floats.get(self.i).copied().unwrap_or(0.0)
    }
    #[inline(always)]
    fn secondary(&self) -> Vec4 {
        self.extra.layout.secondary_at.map_or(Vec4::ZERO, |at| self.extra.vec4(at as usize + 4 * self.i))
    }
    #[inline(always)]
    fn back_secondary(&self) -> Vec4 {
        self.secondary()
    }
}

/// A vertex of a binned triangle without extra attributes (round 18):
/// the colour read in place, and zeros for the texture coordinates, fog
/// coordinate and secondary colour (its state reads none of them:
/// `state_of` keeps extras for every state that does).
impl Attributes for BinVertex {
    #[inline(always)]
    fn color(&self) -> Vec4 {
        Vec4::from_array(self.color)
    }
    #[inline(always)]
    fn back_color(&self) -> Vec4 {
        Vec4::from_array(self.color)
    }
    #[inline(always)]
    fn tex(&self, _unit: usize) -> Vec4 {
        Vec4::ZERO
    }
    #[inline(always)]
    fn fog(&self) -> f32 {
        0.0
    }
    #[inline(always)]
    fn secondary(&self) -> Vec4 {
        Vec4::ZERO
    }
    #[inline(always)]
    fn back_secondary(&self) -> Vec4 {
        Vec4::ZERO
    }
}

/// The triangles binned since the last flush.
#[derive(Default)]
pub struct Batch {
    /// Every primitive in submission order (lines and points by index).
    tris: Records<Binned>,
    /// Each record's box (round 14: apart from the record, so that the
    /// band listing reads 8 bytes a record, not its cache lines).
    boxes: Vec<BinBox>,
    /// The triangles' extra attributes, each record's run laid out by
    /// its state's [`ExtraLayout`].
    extras: Vec<f32>,
    lines: Vec<LineRun>,
    points: Vec<PointRun>,
    /// The states the triangles were drawn under, in order.
    states: Vec<Arc<ShadeState>>,
    /// Band commands recorded between the primitives (round 13:
    /// glAccum), each with the number of primitives recorded before it:
    /// a band applies it after those and before the rest ([`defer_band_op`]).
    ops: Vec<(usize, Box<dyn BandOp>)>,
    /// Work in pixels: the triangles' bounding boxes, the lines' and
    /// points' fragments, plus [`SETUP_PIXELS`] per primitive.
    work: u64,
    /// The stamp of the render state `states.last()` was captured from
    /// (0: none yet), and what [`state_of`] answers while it is drawn.
    last_stamp: u64,
    last: (u32, bool, bool),
}

impl Batch {
    /// An empty batch (this one, emptied by `Flight::clear`) about to be
    /// filled gets room for as many records as `other`, the batch just
    /// filled, had room for (round 10): the three sets of vectors in
    /// rotation then grow (a copy each time, and a page fault every 4 KiB;
    /// [`grow`]) only in the one batch that first reaches a size, and the
    /// others take that size at once, in fresh memory (an empty vector's
    /// growth would copy its old capacity), the record array in huge
    /// pages when `other`'s is (round 23: it passed [`HUGE_RECORDS`]; one
    /// that never did, as lines' 2,800 records a flight, keeps the 4 KiB
    /// pages it writes).
    fn reserve_like(&mut self, other: &Batch) {
        fn fresh<T>(v: &mut Vec<T>, n: usize) -> bool {
            debug_assert!(v.is_empty());
            let grow = v.capacity() < n;
            if grow {
                *v = Vec::with_capacity(n);
            }
            grow
        }
        let n = other.tris.capacity();
        if self.tris.capacity() < n {
            debug_assert!(self.tris.is_empty());
            self.tris = if other.tris.is_mapped() { Records::with_capacity_huge(n) } else { Records::with_capacity(n) };
        }
        // `room`'s invariant: at least the records' capacity.
        fresh(&mut self.boxes, self.tris.capacity());
        fresh(&mut self.extras, other.extras.capacity());
        fresh(&mut self.lines, other.lines.capacity());
        fresh(&mut self.points, other.points.capacity());
    }
}

impl std::fmt::Debug for Batch {
    fn fmt(&self, f: &mut std::fmt::Formatter) -> std::fmt::Result {
        write!(f, "Batch({} triangles)", self.tris.len())
    }
}

/// A command other than a primitive applied band by band inside a flight
/// (round 13: glAccum, `gl::accum`): each band runs it on its own rows
/// after the primitives recorded before it and before those recorded
/// after it, so it sees exactly the drawing GL's order puts before it.
pub trait BandOp: Send + Sync {
    /// Applies the command to rows [y0, y1) of planes `width` wide, given
    /// as the slices holding exactly those rows (the drawn colour buffer
    /// and the accumulation buffer); rows outside the command's
    /// rectangle are left alone.
    fn band(&self, y0: usize, y1: usize, width: usize, color: &mut [[u8; 4]], accum: &mut [[i16; 4]]);
}

/// A context's batch and whether it holds anything. Beside it, the batch
/// handed to the workers before it ([`Flight`]), if any.
///
/// The batch being filled belongs to the thread using the context: only
/// calls made with the context current (binning, [`submit`], [`flush`],
/// every one of them holding the context's framebuffer mutably) touch it,
/// and a context is current in one thread at a time, so it takes no lock
/// (round 5: a mutex locked and unlocked per triangle was half of
/// display_list_1m's 2-thread samples). It reaches the workers by being
/// moved into a [`Flight`] under the `flights` mutex, once per batch.
pub struct BatchCell {
    pending: AtomicBool,
    batch: UnsafeCell<Batch>,
    /// A glClear recorded for the next flight ([`defer_clear`]); touched
    /// only by the context's thread, as `batch`.
    clear: UnsafeCell<Option<Clear>>,
    flights: Mutex<Flights>,
    /// A batch is in flight (`Flights::current`), read without the lock.
    flying: AtomicBool,
    /// Tiles of the flight not shaded yet (0: none in flight, or done).
    left: Arc<AtomicUsize>,
    /// The calling thread has already helped with the flight's untaken
    /// bands while filling this batch ([`submit`]); touched only by the
    /// context's thread.
    helped: AtomicBool,
    /// [`MAX_BATCH`], [`SUBMIT_WORK`] and [`PARALLEL_WORK`], unless a
    /// test set others.
    max_batch: AtomicUsize,
    submit_work: AtomicU64,
    parallel_work: AtomicU64,
}

// Safety: `batch` is only touched by the thread the context is current in
// (see the type's comment); everything else is atomics and mutexes.
unsafe impl Sync for BatchCell {}

impl std::fmt::Debug for BatchCell {
    fn fmt(&self, f: &mut std::fmt::Formatter) -> std::fmt::Result {
        write!(f, "BatchCell(pending: {})", self.pending.load(Ordering::Relaxed))
    }
}

impl Default for BatchCell {
    fn default() -> BatchCell {
        BatchCell {
            pending: AtomicBool::new(false),
            batch: UnsafeCell::default(),
            clear: UnsafeCell::new(None),
            flights: Mutex::default(),
            flying: AtomicBool::new(false),
            left: Arc::default(),
            helped: AtomicBool::new(false),
            max_batch: AtomicUsize::new((tuned("SOFTGL_MAX_BATCH", MAX_BATCH as u64) as usize).clamp(1, MAX_BATCH)),
            submit_work: AtomicU64::new(tuned("SOFTGL_SUBMIT_WORK", SUBMIT_WORK)),
            parallel_work: AtomicU64::new(tuned("SOFTGL_PARALLEL_WORK", PARALLEL_WORK)),
        }
    }
}

/// The batch in flight and the spare ones.
#[derive(Default)]
struct Flights {
    current: Option<(Box<Flight>, pool::Posted)>,
    /// Finished flights, emptied: their vectors become the next batches'.
    /// All of them are kept (round 10): a context uses at most two flights
    /// at once (one in flight, one taken while it flies) besides the batch
    /// being filled, and a sync point used to drop one of the two spares,
    /// so the next frame grew a third set of batch vectors from nothing
    /// again (immediate_1m: about 7,000 page faults and the copies of
    /// doubling, every frame, at 1920x1080 with 2 threads).
    spare: Vec<Box<Flight>>,
    /// Flights allocated so far ([`flights_made`]).
    made: usize,
}

impl std::fmt::Debug for Flights {
    fn fmt(&self, f: &mut std::fmt::Formatter) -> std::fmt::Result {
        write!(f, "Flights(in flight: {})", self.current.is_some())
    }
}

/// A context's batch, shared by clones of its RenderState.
pub type SharedBatch = Arc<BatchCell>;

/// The batch being filled.
///
/// Safety: called only by the thread the context is current in, and the
/// reference is not held across another call of this function.
#[allow(clippy::mut_from_ref)]
unsafe fn filling(b: &SharedBatch) -> &mut Batch {
    &mut *b.batch.get()
}

fn lock_flights(b: &SharedBatch) -> std::sync::MutexGuard<'_, Flights> {
    b.flights.lock().unwrap_or_else(|e| e.into_inner())
}

/// Sets a context's batch limits (tests: to make small scenes submit
/// many batches to the workers): at most `max_triangles` per batch, a
/// batch is handed to idle workers once it holds `submit_work` of work,
/// and one with less than `parallel_work` is shaded on the calling thread.
/// A batch never holds more than [`MAX_BATCH`] (the extras' offsets in a
/// record's 28 bits rely on it).
pub fn set_batch_limits(rs: &RenderState, max_triangles: usize, submit_work: u64, parallel_work: u64) {
    rs.batch.max_batch.store(max_triangles.clamp(1, MAX_BATCH), Ordering::Relaxed);
    rs.batch.submit_work.store(submit_work, Ordering::Relaxed);
    rs.batch.parallel_work.store(parallel_work, Ordering::Relaxed);
}

/// Batches handed to the workers so far in this process (tests check
/// that they exercised the asynchronous path).
pub fn flights_started() -> u64 {
    FLIGHTS.load(Ordering::Relaxed)
}

static FLIGHTS: AtomicU64 = AtomicU64::new(0);

/// Times the calling thread helped a flight before its next batch was
/// full, in this process ([`submit`]; tests check the path ran).
pub fn helps_started() -> u64 {
    HELPS.load(Ordering::Relaxed)
}

static HELPS: AtomicU64 = AtomicU64::new(0);

/// Flights (batch vectors besides the one being filled) a context has
/// allocated: at most two however many batches it draws (tests).
pub fn flights_made(rs: &RenderState) -> usize {
    lock_flights(&rs.batch).made
}

/// Should this triangle be binned rather than shaded now?
#[inline]
pub fn binning(rs: &RenderState) -> bool {
    rs.threads > 1 && !rs.reference
}

/// What [`bounds`] finds of a triangle.
pub enum Bounds {
    /// The pixel centres of its box: to be binned.
    Box(raster::CentreBox),
    /// No pixel centre of the draw rectangle in its box: nothing to draw.
    Empty,
    /// A vertex too far out for the binned record (never after
    /// clipping): to be shaded at once.
    Far,
}

/// The pixel centres within the draw rectangle of a triangle's bounding
/// box (fixed-point vertices), with whether its extents fit the cover's
/// lanes (`raster::CentreBox`, the box the band side used to find again
/// from the vertices, round 23). A box without centres, a twelfth of
/// spheres_l's triangles at 1920x1080, is [`Bounds::Empty`]: no record.
/// Round 14: the record keeps x and y in i32, which setup's precision
/// note bounds by 2^27 after clipping; anything else is [`Bounds::Far`]
/// (two compares on the min and max).
#[inline]
pub fn bounds(rs: &RenderState, x: [i64; 3], y: [i64; 3]) -> Bounds {
    let (x_lo, x_hi) = (x[0].min(x[1]).min(x[2]), x[0].max(x[1]).max(x[2]));
    let (y_lo, y_hi) = (y[0].min(y[1]).min(y[2]), y[0].max(y[1]).max(y[2]));
    if x_lo.min(y_lo) < i32::MIN as i64 || x_hi.max(y_hi) > i32::MAX as i64 {
        return Bounds::Far;
    }
    let centres = raster::CentreBox::of(x, y, rs.draw_rect);
    if centres.count() == 0 { Bounds::Empty } else { Bounds::Box(centres) }
}

/// Adds a triangle to the batch, to be set up in a worker: fixed-point
/// vertices (x, y), their window positions (`pos`: x, y, depth, 1/w) and
/// attributes in submission order, `ccw` when that order is positively
/// oriented; `flat_color` and `back` as for `setup::planes_of`. The
/// record holds them in positive orientation (vertices 1 and 2 swapped
/// when not `ccw`).
/// True when the batch should be handed to the workers now ([`submit`]):
/// it reached [`MAX_BATCH`], or [`SUBMIT_WORK`] while the workers are
/// idle.
#[allow(clippy::too_many_arguments)]
// Inlined into `setup::bin_snapped` (its one caller on the hot
// path): a call passed its arrays through stack copies, about 25
// instructions a triangle on the calling thread.
#[inline(always)]
pub fn push<A: Attributes>(rs: &RenderState, x: [i64; 3], y: [i64; 3], centres: raster::CentreBox, pos: [[f64; 4]; 3], v: [&A; 3], ccw: bool, flat_color: Vec4, back: bool, front_facing: bool) -> bool {
    let area = centres.count() as u64;
    let bbox = centres.rect();
    // Safety: binning runs on the context's thread (its framebuffer is
    // borrowed mutably by the caller).
    let b = unsafe { filling(&rs.batch) };
    let (state, flat, extra) = state_of(rs, b);
    let extra = if extra {
        let v = if ccw { v } else { [v[0], v[2], v[1]] };
        let at = b.extras.len();
        b.states[state as usize].extras.write(&mut b.extras, v, back);
        // At most `MAX_BATCH` records (`set_batch_limits`) of at most 63
        // floats: below 2^28.
        at as u32
    } else {
        NO_EXTRA_INDEX
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
    // Round 12: each vertex is stored straight into its slot of the
    // record (submitted vertex i in slot `at[i]`) rather than the three
    // arrays being permuted first, in registers and stack copies, and
    // then copied in (about 30 instructions a triangle).
    let at = [0, 2 - ccw as usize, 1 + ccw as usize];
    room(b);
    // Safety: `room` made room for one record and one box past the
    // lengths (equal); every field is written (x, y and v through the
    // three distinct slots of `at`) before the lengths take them in.
    unsafe {
        let t = b.tris.as_mut_ptr().add(b.tris.len());
        let (tx, ty) = (std::ptr::addr_of_mut!((*t).x) as *mut i32, std::ptr::addr_of_mut!((*t).y) as *mut i32);
        let tv = std::ptr::addr_of_mut!((*t).v) as *mut BinVertex;
        for i in 0..3 {
            // `setup::bin_snapped` bins only vertices that fit.
            tx.add(at[i]).write(x[i] as i32);
            ty.add(at[i]).write(y[i] as i32);
            let tv = tv.add(at[i]);
            std::ptr::addr_of_mut!((*tv).z).write(pos[i][2]);
            std::ptr::addr_of_mut!((*tv).q).write(pos[i][3]);
            (std::ptr::addr_of_mut!((*tv).color) as *mut Vec4).write_unaligned(color(i));
        }
        std::ptr::addr_of_mut!((*t).state).write(state);
        std::ptr::addr_of_mut!((*t).prim).write(TRIANGLE | if front_facing { FRONT } else { 0 } | if centres.lanes_fit() { FIT } else { 0 } | extra);
        b.tris.set_len(b.tris.len() + 1);
        let n = b.boxes.len();
        let bb = b.boxes.as_mut_ptr().add(n) as *mut i16;
        // Four 16-bit stores (packing them into one 64-bit word first
        // took about 10 instructions more).
        bb.write(bbox.x0 as i16);
        bb.add(1).write(bbox.y0 as i16);
        bb.add(2).write(bbox.x1 as i16);
        bb.add(3).write(bbox.y1 as i16);
        b.boxes.set_len(n + 1);
    }
    added(&rs.batch, b, area + SETUP_PIXELS)
}

/// [`push`] for the triangles of a `bin4` group that are drawn (the bits
/// of `g.keep`), in order, handing the batch over ([`submit_binned`])
/// whenever [`added`] asks, as `push`'s callers do. Round 27: the state
/// is looked up once (and again after a hand-over) and a record without
/// extras is written straight from the lanes; a state with extras takes
/// [`push`] per triangle.
#[inline(always)]
pub(crate) fn push_group(rs: &RenderState, fb: &mut Framebuffer, g: &super::bin4::Found, tris: &super::bin4::Verts, provoking: &[&ClipVertex; super::bin4::GROUP]) {
    const G: usize = super::bin4::GROUP;
    let mut keep = g.keep;
    while keep != 0 {
        // Safety: as in `push`.
        let b = unsafe { filling(&rs.batch) };
        let (state, flat, extra) = state_of(rs, b);
        if extra {
            return push_each(rs, fb, g, tris, provoking, keep);
        }
        let limits = Limits::of(&rs.batch);
        loop {
            let i = keep.trailing_zeros() as usize & (G - 1);
            keep &= keep - 1;
            let ccw = (g.ccw >> i) & 1 != 0;
            let front_facing = (g.front >> i) & 1 != 0;
            let back = rs.two_side && !front_facing;
            let v = [tris[0][i], tris[1][i], tris[2][i]];
            let (col0, row0, col1, row1) = (g.lo[i], g.lo[G + i], g.hi[i], g.hi[G + i]);
            let fit = (g.fit >> i) & 1 != 0;
            let area = ((col1 - col0) as i64 * (row1 - row0) as i64) as u64;
            // As `push`: vertex j into slot `at[j]`.
            let at = [0, 2 - ccw as usize, 1 + ccw as usize];
            room(b);
            // Safety: as in `push`.
            unsafe {
                let t = b.tris.as_mut_ptr().add(b.tris.len());
                let (tx, ty) = (std::ptr::addr_of_mut!((*t).x) as *mut i32, std::ptr::addr_of_mut!((*t).y) as *mut i32);
                let tv = std::ptr::addr_of_mut!((*t).v) as *mut BinVertex;
                for j in 0..3 {
                    tx.add(at[j]).write(g.v[j][i]);
                    ty.add(at[j]).write(g.v[j][G + i]);
                    let tv = tv.add(at[j]);
                    // z and q together (`BinVertex` is repr(C)).
                    (std::ptr::addr_of_mut!((*tv).z) as *mut [f64; 2]).write_unaligned([v[j].win[2], v[j].win[3]]);
                    let from = if flat { provoking[i] } else { v[j] };
                    let color = if back { &from.back_color } else { &from.color };
                    (std::ptr::addr_of_mut!((*tv).color) as *mut Vec4).write_unaligned(*color);
                }
                std::ptr::addr_of_mut!((*t).state).write(state);
                std::ptr::addr_of_mut!((*t).prim).write(TRIANGLE | if front_facing { FRONT } else { 0 } | if fit { FIT } else { 0 } | NO_EXTRA_INDEX);
                b.tris.set_len(b.tris.len() + 1);
                let n = b.boxes.len();
                b.boxes.as_mut_ptr().add(n).write(g.boxes[i]);
                b.boxes.set_len(n + 1);
            }
            if added_within(&rs.batch, b, area + SETUP_PIXELS, limits) {
                submit_binned(rs, fb);
                break;
            }
            if keep == 0 {
                return;
            }
        }
    }
}

/// [`push_group`] by [`push`], for a state with extras: the triangles
/// of `keep` in order.
#[inline(never)]
fn push_each(rs: &RenderState, fb: &mut Framebuffer, g: &super::bin4::Found, tris: &super::bin4::Verts, provoking: &[&ClipVertex; super::bin4::GROUP], mut keep: u32) {
    const G: usize = super::bin4::GROUP;
    while keep != 0 {
        let i = keep.trailing_zeros() as usize & (G - 1);
        keep &= keep - 1;
        let ccw = (g.ccw >> i) & 1 != 0;
        let front_facing = (g.front >> i) & 1 != 0;
        let back = rs.two_side && !front_facing;
        let x = [0, 1, 2].map(|j| g.v[j][i] as i64);
        let y = [0, 1, 2].map(|j| g.v[j][G + i] as i64);
        let centres = raster::CentreBox::from_parts(g.lo[G + i] as i64, g.hi[G + i] as i64, g.lo[i] as i64, g.hi[i] as i64, (g.fit >> i) & 1 != 0);
        let (v, p) = ([tris[0][i], tris[1][i], tris[2][i]], provoking[i]);
        let flat_color = if back { p.back_color } else { p.color };
        if push(rs, x, y, centres, v.map(|cv| cv.win), v, ccw, flat_color, back, front_facing) {
            submit_binned(rs, fb);
        }
    }
}

/// The records, boxes and work of the batch being filled, the records
/// as bytes (a record has no padding): tests compare two binning paths.
#[cfg(test)]
pub(crate) fn filling_bytes(rs: &RenderState) -> (Vec<[u8; 128]>, Vec<BinBox>, u64) {
    // Safety: the test's thread, the context's; no other reference held.
    let b = unsafe { filling(&rs.batch) };
    // Safety: `Binned` is 128 bytes of plain values, without padding.
    let tris = b.tris.iter().map(|t| unsafe { std::mem::transmute_copy::<Binned, [u8; 128]>(t) }).collect();
    (tris, b.boxes.to_vec(), b.work)
}

/// The batch's index of the state `rs` draws under (added when it
/// changed), whether it is flat shaded and whether it reads texture
/// coordinates or fog. Inlined: called per primitive on the calling
/// thread. Round 12: the answer is kept in the batch with the stamp of
/// the render state it was captured from, so a primitive drawn under the
/// state of the one before (all but the first after a change) costs a
/// stamp compare, not the `ShadeCache` borrow, its stamp check and the
/// `Arc::ptr_eq` against the last state (about 25 instructions). A
/// stamp is never reused and `gl::validate` gives a new one to every
/// change before anything is drawn (`shade_state`), so the same stamp is
/// the same state; a batch starts (and is emptied) with none.
#[inline(always)]
fn state_of(rs: &RenderState, b: &mut Batch) -> (u32, bool, bool) {
    if rs.stamp == b.last_stamp && b.last_stamp != 0 {
        return b.last;
    }
    state_captured(rs, b)
}

/// [`state_of`] for a state not yet seen by this batch (or changed).
#[cold]
#[inline(never)]
fn state_captured(rs: &RenderState, b: &mut Batch) -> (u32, bool, bool) {
    let got = rs.shade.with(rs, |st| {
        if !b.states.last().is_some_and(|l| Arc::ptr_eq(l, st)) {
            b.states.push(st.clone());
        }
        (b.states.len() as u32 - 1, st.flat, !st.extras.is_empty())
    });
    // A reference or never-validated state is captured anew each time.
    b.last_stamp = if rs.reference { 0 } else { rs.stamp };
    b.last = got;
    got
}

/// Counts `work` more in the batch just added to; true when [`submit`]
/// should be called now: the batch is full, or worth handing to workers
/// that have nothing to do, or three quarters full while the flight
/// before it is still being shaded and the calling thread has not helped
/// with it yet ([`help_at`]).
#[inline]
fn added(cell: &SharedBatch, b: &mut Batch, work: u64) -> bool {
    added_within(cell, b, work, Limits::of(cell))
}

/// [`added`] with the batch limits read already (by the calling thread,
/// the only one that sets them: [`push_group`] reads them once a group).
#[inline(always)]
fn added_within(cell: &SharedBatch, b: &mut Batch, work: u64, limits: Limits) -> bool {
    cell.pending.store(true, Ordering::Relaxed);
    b.work += work;
    let len = b.tris.len();
    if len >= limits.max {
        return true;
    }
    if cell.left.load(Ordering::Relaxed) == 0 {
        b.work >= limits.submit_work
    } else {
        len >= limits.help_at && !cell.helped.load(Ordering::Relaxed)
    }
}

/// A batch's limits ([`set_batch_limits`]) as [`added`] reads them.
#[derive(Clone, Copy)]
struct Limits {
    max: usize,
    help_at: usize,
    submit_work: u64,
}

impl Limits {
    #[inline(always)]
    fn of(cell: &SharedBatch) -> Limits {
        let max = cell.max_batch.load(Ordering::Relaxed);
        Limits { max, help_at: help_at(max), submit_work: cell.submit_work.load(Ordering::Relaxed) }
    }
}

/// The batch length at which the calling thread, while the flight before
/// is still being shaded, takes that flight's bands nobody has taken yet
/// and then goes on binning (round 13): the rest of the batch covers the
/// time the other threads need to finish the bands they hold, which the
/// calling thread used to wait out in [`submit`] once the batch was full.
fn help_at(max: usize) -> usize {
    (max - max / 4).max(1)
}

/// Adds the record of a line or point to `b`: its box and state only.
fn push_prim(b: &mut Batch, bbox: Rect, state: u32, prim: u32) {
    let v = BinVertex { z: 0.0, q: 0.0, color: [0.0; 4] };
    room(b);
    b.tris.push(Binned { x: [0; 3], y: [0; 3], v: [v; 3], state, prim });
    b.boxes.push(packed_box(bbox));
}

/// Makes room for one more record and box (round 14: one capacity check
/// for both): `boxes` always has at least the capacity of `tris`, and the
/// same length.
#[inline(always)]
fn room(b: &mut Batch) {
    debug_assert_eq!(b.tris.len(), b.boxes.len());
    if b.tris.len() == b.tris.capacity() {
        grow(b);
    }
    debug_assert!(b.boxes.capacity() > b.boxes.len());
}

/// [`room`]'s growth: the records by doubling while the batch is small,
/// then at once to room for [`HUGE_RECORDS`] (round 22: at once to a full
/// batch), then to room for [`MAX_BATCH`] in a mapping of huge pages
/// (round 23, `render::records`); the boxes to the records' capacity.
/// Doubling to a full batch copied 3.5 MB of records into 7 MB of fresh
/// 4 KiB pages and unmapped the old ones, on the calling thread, in the
/// first frame of every large scene (about a tenth of spheres_m's first
/// frame). Capacity not written is address space only: a scene that
/// never fills a batch touches no more pages than before.
#[cold]
#[inline(never)]
fn grow(b: &mut Batch) {
    let cap = b.tris.capacity();
    if (JUMP_RECORDS..HUGE_RECORDS).contains(&cap) {
        let mut tris = Records::with_capacity(HUGE_RECORDS);
        tris.append(&mut b.tris);
        b.tris = tris;
    } else if (HUGE_RECORDS..MAX_BATCH).contains(&cap) && !b.tris.is_mapped() {
        let mut tris = Records::with_capacity_huge(MAX_BATCH);
        tris.append(&mut b.tris);
        b.tris = tris;
    } else {
        b.tris.reserve(1);
    }
    b.boxes.reserve_exact(b.tris.capacity() - b.boxes.len());
}

/// Past this many records (1 MiB) [`grow`] moves a batch's records
/// into a mapping of huge pages with room for a full batch; a batch that
/// stays below keeps the 4 KiB pages it writes (lines at 300x300: about
/// 2,800 records a flight).
const HUGE_RECORDS: usize = 8192;

/// [`grow`] doubles the records up to this many (64 KiB of records),
/// then makes room for [`HUGE_RECORDS`].
const JUMP_RECORDS: usize = 512;

/// Adds a line segment to the batch, to be drawn band by band in the
/// workers; `bbox` holds every fragment it may produce (within the draw
/// rectangle, not empty). True as for [`push`].
pub fn push_line(rs: &RenderState, line: LineRun, bbox: Rect) -> bool {
    // Safety: as in `push`.
    let b = unsafe { filling(&rs.batch) };
    let (state, _, _) = state_of(rs, b);
    let work = line.work();
    push_prim(b, bbox, state, b.lines.len() as u32);
    b.lines.push(line);
    added(&rs.batch, b, work + SETUP_PIXELS)
}

/// Adds a point to the batch (as [`push_line`]).
pub fn push_point(rs: &RenderState, p: PointRun, bbox: Rect) -> bool {
    // Safety: as in `push`.
    let b = unsafe { filling(&rs.batch) };
    let (state, _, _) = state_of(rs, b);
    let area = (bbox.x1 - bbox.x0) as u64 * (bbox.y1 - bbox.y0) as u64;
    push_prim(b, bbox, state, POINT | b.points.len() as u32);
    b.points.push(p);
    added(&rs.batch, b, area + SETUP_PIXELS)
}

/// Draws a binned line or point's fragments within `r` into `fb`
/// (`width` wide, the whole framebuffer or a band of it).
fn draw_prim(b: &Batch, t: &Binned, st: &ShadeState, fb: &mut impl Buffers, width: usize, r: Rect) {
    // Nothing is binned while drawing to two colour buffers.
    let sink = runs::Sink::with(&st.fragment, false);
    if t.prim & POINT != 0 {
        b.points[(t.prim & !POINT) as usize].draw(&sink, fb, width, r);
    } else {
        let env = LineEnv { fs: &st.fragment, texture: st.texture.as_deref(), fog: st.fog.as_ref() };
        b.lines[t.prim as usize].draw(&env, &sink, fb, width, r);
    }
}

/// How [`shade_binned`] has a triangle's pixels shaded.
enum Shading<'a> {
    /// Pixels [x0, x1) of row y by a span kernel.
    Span(Kernel, &'a TriangleSetup, usize, usize, usize),
    /// A tiny triangle's cover by its block kernel (round 13).
    Stamp(StampKernel, &'a TriangleSetup, &'a raster::Cover),
}

/// Sets up a binned triangle and hands its covered pixels within `rect`
/// (its record's box of centres, cut to the band or the surface) to
/// `shade`: a tiny triangle's cover at once when its state has a block
/// kernel (`fragment::stamp`), else its runs one by one; a triangle
/// covering no pixel centre there is not set up. The setup is the one
/// shading it at once would compute (the same inputs to `planes_of`), so
/// the pixels are the same.
#[inline]
fn shade_binned(t: &Binned, st: &ShadeState, extras: &[f32], rect: Rect, blocks: bool, mut shade: impl FnMut(Shading<'_>)) {
    let stipple = st.polygon_stipple.as_deref();
    let (x, y) = t.xy();
    let centres = raster::CentreBox::of_rect(rect, t.lanes_fit());
    let count = centres.count();
    if count > raster::Cover::SMALLEST && stipple.is_none() && shade_binned_block(t, st, extras, (&x, &y), centres, blocks, &mut shade) {
        return;
    }
    // No pixel centre in the box: no pixel (round 16: before the runs'
    // array is made).
    if count == 0 {
        return;
    }
    let mut runs = raster::Runs::new();
    let found = runs.find_in(x, y, centres, rect, stipple);
    if found && runs.is_empty() {
        return;
    }
    let mut slot = std::mem::MaybeUninit::uninit();
    let setup = solve_binned(&mut slot, st, t, Extra { floats: extras, layout: &st.extras });
    let k = st.kernel(setup);
    if found {
        for (py, lo, hi) in runs.iter() {
            shade(Shading::Span(k, setup, py, lo, hi));
        }
    } else {
        raster::spans(x, y, rect, stipple, |py, lo, hi| shade(Shading::Span(k, setup, py, lo, hi)));
    }
    // SAFETY: solved above.
    unsafe { release(&mut slot) }
}

/// [`shade_binned`] for a triangle whose box has more than
/// `Cover::SMALLEST` centres: its cover and its block kernel, or the
/// cover's runs; false when it does not fit the block.
/// Round 17: the snapped vertices by reference (by value, the band
/// loop kept two more copies of them on its stack).
#[inline(always)]
fn shade_binned_block(t: &Binned, st: &ShadeState, extras: &[f32], (x, y): (&[i64; 3], &[i64; 3]), centres: raster::CentreBox, blocks: bool, shade: &mut impl FnMut(Shading<'_>)) -> bool {
    let mut slot = std::mem::MaybeUninit::uninit();
    let Some(cover) = raster::Cover::find_into_at(&mut slot, x, y, centres, blocks) else {
        return false;
    };
    if cover.is_empty() {
        return true;
    }
    let mut slot = std::mem::MaybeUninit::uninit();
    let setup = solve_binned(&mut slot, st, t, Extra { floats: extras, layout: &st.extras });
    match st.stamp(setup) {
        Some(sk) => shade(Shading::Stamp(sk, setup, cover)),
        None => {
            let k = st.kernel(setup);
            for (py, lo, hi) in cover.rows() {
                shade(Shading::Span(k, setup, py, lo, hi));
            }
        }
    }
    // SAFETY: solved above.
    unsafe { release(&mut slot) };
    true
}

/// A binned triangle's set-up, solved into `slot` (released by the
/// caller, as `setup::solve`'s): the inputs `setup::planes_of` took when the
/// triangle was binned (its vertices' depth, 1/w and colours, the
/// provoking vertex's colour for flat shading, its facing, and `extra`,
/// the batch's extra attributes with the layout of the record's state),
/// so the same planes.
/// Round 18: out of line with the plane solution inlined
/// (`setup::solve_here`), reading the record in place; the shading paths
/// called `planes_into` with the depths, 1/w and colours copied to the
/// stack for it (about 35 instructions a triangle). A record without
/// extras reads its vertices as they are ([`BinVertex`]'s attributes,
/// zeros besides the colour), with no attribute array on the stack.
#[inline(always)]
fn solve_binned<'a, P: SetupParams>(slot: &'a mut std::mem::MaybeUninit<TriangleSetup>, st: &P, t: &Binned, extra: Extra<'_>) -> &'a TriangleSetup {
    if t.prim & NO_EXTRA_INDEX == NO_EXTRA_INDEX {
        solve_plain(slot, st, t)
    } else {
        solve_extra(slot, st, t, extra)
    }
}

/// [`solve_binned`] for a record without extras. Round 28: the snapped
/// vertices read from the record here, not passed by reference: the band
/// loop's i64 copies were read back two at a time, 16-byte loads across
/// two 8-byte stores, which wait for the store buffer (spheres_l).
#[inline(never)]
fn solve_plain<'a, P: SetupParams>(slot: &'a mut std::mem::MaybeUninit<TriangleSetup>, st: &P, t: &Binned) -> &'a TriangleSetup {
    let zq = t.v.map(|v| (v.z, v.q));
    let (x, y) = t.xy();
    super::setup::solve_here(slot, st, zq, [&t.v[0], &t.v[1], &t.v[2]], &x, &y, Vec4::from_array(t.v[0].color), false, t.front_facing())
}

/// [`solve_binned`] for a record with extras (the vertices as
/// [`solve_plain`]'s).
#[inline(never)]
fn solve_extra<'a, P: SetupParams>(slot: &'a mut std::mem::MaybeUninit<TriangleSetup>, st: &P, t: &Binned, extra: Extra<'_>) -> &'a TriangleSetup {
    let extra = extra.at((t.prim & NO_EXTRA_INDEX) as usize);
    let a = [0, 1, 2].map(|i| BinAttributes { v: &t.v[i], extra, i });
    let zq = t.v.map(|v| (v.z, v.q));
    let (x, y) = t.xy();
    super::setup::solve_here(slot, st, zq, a.each_ref(), &x, &y, Vec4::from_array(t.v[0].color), false, t.front_facing())
}

/// Records glClear's writes `c` for the workers instead of writing them
/// now (round 11): the next flight (the batch of triangles drawn after
/// the clear, or an empty one at the next sync point) clears each band's
/// rows just before it draws that band, so the clear's writes are still
/// in cache when the band's fragments read and write the same pixels, the
/// calling thread goes on with the front end meanwhile, and nothing
/// waits for a separate hand-off. Only while binning (more than one
/// thread): the 1-thread path writes clears at once. Anything binned or
/// recorded before is handed to the workers first (round 13: without
/// waiting for it), and flights run in order, so the clear keeps its
/// place in GL's order.
pub fn defer_clear(rs: &RenderState, fb: &mut Framebuffer, c: Clear) {
    let cell = &rs.batch;
    // Round 13: whatever is binned or recorded before the clear is handed
    // to the workers without waiting for it (`gl::clear` no longer syncs
    // first when it records); flights run in order, so the clear's flight
    // comes after it.
    // Safety: the context's thread (as `filling`).
    let b = unsafe { filling(cell) };
    if !b.tris.is_empty() || !b.ops.is_empty() || unsafe { (*cell.clear.get()).is_some() } {
        submit(rs, fb);
    }
    // Safety: as above; no flight holds this slot (flights take it).
    unsafe { *cell.clear.get() = Some(c) };
    cell.pending.store(true, Ordering::Relaxed);
}

/// Records a band command (round 13: glAccum) after everything binned so
/// far: each band of the flight that takes the batch runs it on its rows
/// just after drawing the primitives binned before it, while those rows
/// are in the thread's cache, and the calling thread goes on (no sync, no
/// separate hand-off). Primitives binned after it join the same batch and
/// are drawn after it in each band. Only while binning; the caller has
/// checked that the command reads and writes nothing but the drawn
/// colour buffer and the accumulation buffer, which nothing else touches
/// until the next sync point.
pub fn defer_band_op(rs: &RenderState, op: Box<dyn BandOp>) {
    let cell = &rs.batch;
    // Safety: the context's thread (as `filling`).
    let b = unsafe { filling(cell) };
    b.ops.push((b.tris.len(), op));
    cell.pending.store(true, Ordering::Relaxed);
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
    /// The accumulation buffer (null when there is none).
    accum: *mut [i16; 4],
    depth: *mut u32,
    stencil: *mut u8,
    has_depth: bool,
    has_stencil: bool,
}

// Workers write disjoint tiles (see `Flight`).
unsafe impl Send for RawPixels {}
unsafe impl Sync for RawPixels {}

impl RawPixels {
    fn new(fb: &mut Framebuffer) -> RawPixels {
        RawPixels {
            width: fb.width,
            color: fb.color.as_mut_ptr(),
            accum: if fb.accum.len() >= fb.width * fb.height { fb.accum.as_mut_ptr() } else { std::ptr::null_mut() },
            depth: fb.depth.as_mut_ptr(),
            stencil: fb.stencil.as_mut_ptr(),
            has_depth: fb.has_depth(),
            has_stencil: fb.has_stencil(),
        }
    }

    /// Rows [y0, y1) of the colour and accumulation buffers (the latter
    /// empty when there is none).
    ///
    /// Safety: the rows lie inside the framebuffer, and no other live
    /// slice of them exists.
    #[allow(clippy::mut_from_ref)]
    unsafe fn rows(&self, y0: usize, y1: usize) -> (&mut [[u8; 4]], &mut [[i16; 4]]) {
        let (at, n) = (y0 * self.width, (y1 - y0) * self.width);
        let accum = if self.accum.is_null() { &mut [][..] } else { std::slice::from_raw_parts_mut(self.accum.add(at), n) };
        (std::slice::from_raw_parts_mut(self.color.add(at), n), accum)
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

/// A batch handed to the workers: its triangles listed per tile, shaded
/// tile by tile by whoever takes the next one, while the calling thread
/// bins the next batch. Owns everything the workers read (the states are
/// immutable snapshots, their textures copy-on-write); the framebuffer's
/// planes it writes stay put until [`finish`] returns, because every
/// command that reads, writes, resizes or frees them calls [`sync`] first.
struct Flight {
    batch: Batch,
    /// A glClear made before the batch's triangles: each band's rows are
    /// cleared just before its triangles are drawn ([`defer_clear`]).
    first_clear: Option<Clear>,
    /// Per band, the triangles touching it, in submission order. Filled
    /// by the first thread to run the flight (`bin_once`), not by the
    /// calling thread at [`launch`] (round 8: listing is about 58
    /// instructions a triangle, serial work on the thread that limits
    /// the vertex-bound scenes); resized and cleared only while no
    /// thread runs the flight.
    bins: UnsafeCell<Vec<Vec<u32>>>,
    /// The bands in the order they are taken: most work first (round 13),
    /// so that the last bands taken, which decide when the last thread
    /// is done, are short. Filled with `bins`, under the same rules.
    order: UnsafeCell<Vec<u32>>,
    /// Per band, its estimated work (`bin_once`'s scratch).
    weight: UnsafeCell<Vec<u64>>,
    /// [`UNBINNED`], [`BINNING`] or [`BINNED`].
    binned: AtomicU8,
    /// Rows per band.
    rows: usize,
    surface: Rect,
    raw: RawPixels,
    /// The next tile to take.
    next: AtomicUsize,
    /// Tiles not shaded yet (shared with [`BatchCell::left`]).
    left: Arc<AtomicUsize>,
    /// Fragments that passed the depth test (occlusion queries).
    passed: AtomicU64,
    /// Trace: the flight's number.
    seq: u32,
}

/// [`Flight::binned`]: the band lists are empty, being filled, filled.
const UNBINNED: u8 = 0;
const BINNING: u8 = 1;
const BINNED: u8 = 2;

// Safety: the only field not Sync by itself is `bins`, written by one
// thread at a time (`prepare` and `clear` with no thread in the flight,
// `bin_once` by the one thread that moved `binned` from UNBINNED) and
// read only once `binned` is BINNED.
unsafe impl Sync for Flight {}

impl Flight {
    fn empty(left: Arc<AtomicUsize>) -> Box<Flight> {
        Box::new(Flight {
            batch: Batch::default(),
            first_clear: None,
            bins: UnsafeCell::new(Vec::new()),
            order: UnsafeCell::new(Vec::new()),
            weight: UnsafeCell::new(Vec::new()),
            binned: AtomicU8::new(UNBINNED),
            rows: BAND,
            surface: Rect::new(0, 0, 0, 0),
            raw: RawPixels { width: 0, color: std::ptr::null_mut(), accum: std::ptr::null_mut(), depth: std::ptr::null_mut(), stencil: std::ptr::null_mut(), has_depth: false, has_stencil: false },
            next: AtomicUsize::new(0),
            left,
            passed: AtomicU64::new(0),
            seq: 0,
        })
    }

    /// Cuts `fb` into bands (their lists are filled later, by
    /// [`Flight::bin_once`]) and points at its planes.
    fn prepare(&mut self, fb: &mut Framebuffer, threads: usize) {
        // The framebuffer may have changed size since binning only through
        // commands outside the draw call, which never happens with work
        // pending; still, never write outside it.
        let surface = Rect::new(0, 0, fb.width as i32, fb.height as i32);
        let rows = band_rows(fb.height, threads);
        let bands = fb.height.div_ceil(rows);
        let bins = self.bins.get_mut();
        bins.resize_with(bands, Vec::new);
        bins.truncate(bands);
        *self.binned.get_mut() = UNBINNED;
        self.rows = rows;
        self.surface = surface;
        self.raw = RawPixels::new(fb);
        self.next.store(0, Ordering::Relaxed);
        self.passed.store(0, Ordering::Relaxed);
        self.left.store(bands, Ordering::Release);
    }

    /// The per-band lists, filled by the first thread to get here; the
    /// others wait for it (a few microseconds a batch: a pass over the
    /// records, no shading).
    fn bin_once(&self) -> (&[Vec<u32>], &[u32]) {
        if self.binned.load(Ordering::Acquire) != BINNED {
            if self.binned.compare_exchange(UNBINNED, BINNING, Ordering::Acquire, Ordering::Acquire).is_ok() {
                // Safety: only this thread writes the lists (the state
                // was UNBINNED), and no thread reads them before BINNED.
                let (bins, order, weight) = unsafe { (&mut *self.bins.get(), &mut *self.order.get(), &mut *self.weight.get()) };
                list_bands(&self.batch.boxes, self.surface, self.rows, bins, weight);
                order.clear();
                order.extend(0..bins.len() as u32);
                // Stable: equal bands keep top-to-bottom order.
                order.sort_by_key(|&k| std::cmp::Reverse(weight[k as usize]));
                self.binned.store(BINNED, Ordering::Release);
            } else {
                // Under load the binning thread may be preempted: yield
                // rather than burn the core it needs.
                while self.binned.load(Ordering::Acquire) != BINNED {
                    std::thread::yield_now();
                }
            }
        }
        // Safety: BINNED: nobody writes the lists until `clear`, which
        // runs after every thread has left the flight.
        unsafe { (&*self.bins.get(), &*self.order.get()) }
    }

    /// Back to empty, keeping the vectors' capacity (no regrowth and
    /// copying per batch).
    fn clear(&mut self) {
        let b = &mut self.batch;
        b.tris.clear();
        b.boxes.clear();
        b.extras.clear();
        b.lines.clear();
        b.points.clear();
        b.states.clear();
        b.ops.clear();
        b.work = 0;
        b.last_stamp = 0;
        self.first_clear = None;
        for bin in self.bins.get_mut() {
            bin.clear();
        }
    }
}

/// Lists each record of `tris` in the bands of `rows` rows its box meets
/// within `surface` (`bins`, one list per band, emptied before), in
/// submission order, and estimates each band's work into `weight`: the
/// pixels of the boxes within the band plus [`SETUP_PIXELS`] a record.
fn list_bands(boxes: &[BinBox], surface: Rect, rows: usize, bins: &mut [Vec<u32>], weight: &mut Vec<u64>) {
    weight.clear();
    weight.resize(bins.len(), 0);
    // Round 17: `band_rows` makes `rows` a power of two: a shift, not two
    // divisions a record (spheres_l, 2 threads: about 1.1 M records a
    // frame, listed by one thread while the others wait for it). Any
    // other height (the tests') divides.
    let shift = rows.is_power_of_two().then(|| rows.trailing_zeros());
    let band = |y: usize| match shift {
        Some(s) => y >> s,
        None => y / rows,
    };
    for (i, &t) in boxes.iter().enumerate() {
        let b = rect_of(t).intersect(surface);
        if b.is_empty() {
            continue;
        }
        let (y0, y1, w) = (b.y0 as usize, b.y1 as usize, (b.x1 - b.x0) as u64);
        let (k0, k1) = (band(y0), band(y1 - 1));
        if k0 == k1 {
            // Round 18: a box within one band (most records: spheres_l's
            // tiny triangles at 1920x1080, 2 threads, about 93 %) is
            // within it whole: no cut to the band's rows.
            bins[k0].push(i as u32);
            weight[k0] += w * (y1 - y0) as u64 + SETUP_PIXELS;
            continue;
        }
        for k in k0..=k1 {
            bins[k].push(i as u32);
            let h = y1.min((k + 1) * rows) - y0.max(k * rows);
            weight[k] += w * h as u64 + SETUP_PIXELS;
        }
    }
}

impl pool::Work for Flight {
    fn work(&self) {
        let b = &self.batch;
        let of = |t: &Binned| &*b.states[t.state as usize];
        let raw = &self.raw;
        let stamp_target = StampTarget { color: raw.color, depth: raw.depth, width: raw.width };
        // Asked once for the flight on this thread (round 18), not once a
        // triangle by `Cover::find_into`.
        let blocks = raster::blocks_here();
        let mut local = 0u64;
        let t0 = super::trace::now();
        let (bins, order) = self.bin_once();
        super::trace::rec(b'l', t0, self.seq);
        loop {
            let Some(&k) = order.get(self.next.fetch_add(1, Ordering::Relaxed)) else {
                break;
            };
            let k = k as usize;
            let t0 = super::trace::now();
            let y = k * self.rows;
            let tile = Rect { x0: 0, y0: y as i32, x1: self.surface.x1, y1: (y + self.rows) as i32 }.intersect(self.surface);
            if let Some(c) = &self.first_clear {
                // Safety: the band's rows, which no other thread holds.
                let px = unsafe { raw.span(y, 0, (tile.y1 as usize - y) * raw.width) };
                c.rows(raw.width, y, tile.y1 as usize, px.color, px.depth, px.stencil);
            }
            // Band commands recorded between the primitives: each after
            // the primitives before it (`at`), in order.
            let mut ops = b.ops.iter().peekable();
            let band_op = |op: &dyn BandOp| {
                // Safety: the band's rows, which no other thread holds; no
                // other slice of them is alive during the call.
                let (color, accum) = unsafe { raw.rows(y, tile.y1 as usize) };
                op.band(y, tile.y1 as usize, raw.width, color, accum);
            };
            for &i in &bins[k] {
                while let Some((_, op)) = ops.next_if(|(at, _)| *at <= i as usize) {
                    band_op(&**op);
                }
                let r = rect_of(b.boxes[i as usize]).intersect(tile);
                if r.is_empty() {
                    continue;
                }
                let t = &b.tris[i as usize];
                let st = of(t);
                if !t.is_triangle() {
                    // Safety: the band's rows, which no other thread holds.
                    let px = unsafe { raw.span(y, 0, (tile.y1 as usize - y) * raw.width) };
                    let mut band = runs::Band { px, base: y * raw.width };
                    draw_prim(b, t, st, &mut band, raw.width, r);
                    local += band.px.passed;
                    continue;
                }
                shade_binned(t, st, &b.extras, r, blocks, |how| match how {
                    Shading::Span(kernel, setup, py, lo, hi) => {
                        // Safety: inside the surface and inside this tile,
                        // which no other thread holds.
                        let mut px = unsafe { raw.span(py, lo, hi) };
                        kernel(&st.fragment, setup, &mut px, py, lo, hi);
                        local += px.passed;
                    }
                    Shading::Stamp(sk, setup, cover) => {
                        // Safety: the cover lies within `r`, inside the
                        // surface and this tile, which no other thread
                        // holds; a state testing depth has a depth buffer.
                        local += unsafe { sk(&st.fragment, setup, &stamp_target, cover) };
                    }
                });
            }
            for (_, op) in ops {
                band_op(&**op);
            }
            super::trace::rec(b'b', t0, (self.seq << 8) | k as u32);
            self.left.fetch_sub(1, Ordering::Release);
        }
        self.passed.fetch_add(local, Ordering::Relaxed);
    }
}

/// Waits for the batch in flight, if any, helping the workers with the
/// tiles left; its fragment count goes to `fb` (the framebuffer it drew).
fn finish(cell: &SharedBatch, fl: &mut Flights, fb: &mut Framebuffer) {
    if let Some((mut flight, posted)) = fl.current.take() {
        pool::finish(posted, &*flight);
        debug_assert_eq!(flight.raw.color, fb.color.as_mut_ptr(), "a flight finished on another framebuffer");
        fb.samples_passed = fb.samples_passed.wrapping_add(flight.passed.load(Ordering::Relaxed));
        flight.clear();
        cell.left.store(0, Ordering::Relaxed);
        cell.helped.store(false, Ordering::Relaxed);
        cell.flying.store(false, Ordering::Relaxed);
        fl.spare.push(flight);
    }
}

/// Takes the pending batch, leaving the spare flight's empty vectors in
/// its place; None when nothing is pending.
fn take_batch(cell: &SharedBatch, fl: &mut Flights) -> Option<Box<Flight>> {
    if !cell.pending.load(Ordering::Relaxed) && !cell.flying.load(Ordering::Relaxed) {
        return None;
    }
    // Safety: take_batch runs on the context's thread (`submit`, `flush`).
    let b = unsafe { filling(cell) };
    cell.pending.store(false, Ordering::Relaxed);
    // Safety: as `filling`.
    let clear = unsafe { (*cell.clear.get()).take() };
    if b.tris.is_empty() && clear.is_none() && b.ops.is_empty() {
        return None;
    }
    let mut flight = match fl.spare.pop() {
        Some(f) => f,
        None => {
            fl.made += 1;
            Flight::empty(cell.left.clone())
        }
    };
    flight.batch.reserve_like(b);
    std::mem::swap(&mut flight.batch, b);
    flight.first_clear = clear;
    Some(flight)
}

/// Hands the pending batch to the workers and returns without waiting
/// for it (after waiting for the one before it: batches are shaded in
/// order). A batch with little work is shaded at once on this thread.
/// Always hands the batch over: commands recorded after it (a deferred
/// glClear) rely on that for their place in GL's order.
pub fn submit(rs: &RenderState, fb: &mut Framebuffer) {
    let t0 = super::trace::now();
    hand_over(rs, fb);
    super::trace::rec(b'S', t0, 0);
}

/// [`submit`] for the binning paths, when [`added`] says so: while the
/// batch is not full and the flight before it still has bands being
/// shaded, the calling thread may instead help with that flight once and
/// go back to binning (round 13).
pub fn submit_binned(rs: &RenderState, fb: &mut Framebuffer) {
    let t0 = super::trace::now();
    if !help(&rs.batch) {
        hand_over(rs, fb);
    }
    super::trace::rec(b'S', t0, 0);
}

/// Round 13: when the batch is not full and the flight before it still
/// has bands being shaded, shades the bands nobody has taken and returns
/// true: the caller goes back to binning instead of waiting for the
/// others' last bands (the next primitive submits once the flight is
/// done, or when the batch is full).
fn help(cell: &SharedBatch) -> bool {
    // Safety: the context's thread (as `filling`).
    let len = unsafe { filling(cell) }.tris.len();
    if len >= cell.max_batch.load(Ordering::Relaxed) || cell.left.load(Ordering::Acquire) == 0 || cell.helped.load(Ordering::Relaxed) {
        return false;
    }
    cell.helped.store(true, Ordering::Relaxed);
    let fl = lock_flights(cell);
    if let Some((flight, _)) = &fl.current {
        HELPS.fetch_add(1, Ordering::Relaxed);
        // The flight stays alive: it is only finished by this thread.
        pool::Work::work(&**flight);
    }
    true
}

fn hand_over(rs: &RenderState, fb: &mut Framebuffer) {
    let cell = &rs.batch;
    let mut fl = lock_flights(cell);
    let Some(flight) = take_batch(cell, &mut fl) else {
        return;
    };
    finish(cell, &mut fl, fb);
    launch(rs, &mut fl, flight, fb);
}

/// Starts `flight` on the workers (or shades it now if it is small).
fn launch(rs: &RenderState, fl: &mut Flights, mut flight: Box<Flight>, fb: &mut Framebuffer) {
    let b = &flight.batch;
    // A recorded clear or band command is a whole-frame's work: always
    // on the threads.
    if rs.threads <= 1 || (b.work < rs.batch.parallel_work.load(Ordering::Relaxed) && flight.first_clear.is_none() && b.ops.is_empty()) {
        if let Some(c) = flight.first_clear.take() {
            c.rows(fb.width, 0, fb.height, &mut fb.color[..], &mut fb.depth[..], &mut fb.stencil[..]);
        }
        shade_here(&flight.batch, fb);
        flight.clear();
        fl.spare.push(flight);
        return;
    }
    flight.prepare(fb, rs.threads);
    flight.seq = FLIGHTS.load(Ordering::Relaxed) as u32;
    super::trace::rec(b'L', super::trace::now(), flight.batch.tris.len() as u32);
    // Safety: the flight is boxed (its address stays put) and is only
    // dropped or reused after `finish`, which every path to the
    // framebuffer and the context's end calls first (`sync`).
    let posted = unsafe { pool::start(rs.threads, &*flight) };
    FLIGHTS.fetch_add(1, Ordering::Relaxed);
    fl.current = Some((flight, posted));
    rs.batch.helped.store(false, Ordering::Relaxed);
    rs.batch.flying.store(true, Ordering::Relaxed);
}

/// Shades a batch on the calling thread, triangle by triangle.
fn shade_here(b: &Batch, fb: &mut Framebuffer) {
    let surface = Rect::new(0, 0, fb.width as i32, fb.height as i32);
    let width = fb.width;
    let mut ops = b.ops.iter().peekable();
    let blocks = raster::blocks_here();
    for (i, (t, &bbox)) in b.tris.iter().zip(&b.boxes).enumerate() {
        while let Some((_, op)) = ops.next_if(|(at, _)| *at <= i) {
            op.band(0, fb.height, width, &mut fb.color[..], &mut fb.accum[..]);
        }
        let st = &*b.states[t.state as usize];
        if !t.is_triangle() {
            draw_prim(b, t, st, fb, width, rect_of(bbox).intersect(surface));
            continue;
        }
        shade_binned(t, st, &b.extras, rect_of(bbox).intersect(surface), blocks, |how| {
            let passed = match how {
                Shading::Span(k, setup, py, lo, hi) => {
                    let mut px = SpanPixels::of(fb, py, lo, hi);
                    k(&st.fragment, setup, &mut px, py, lo, hi);
                    px.passed
                }
                // Safety: the cover lies within the surface; nothing is
                // binned while drawing to two colour buffers; this thread
                // holds the framebuffer.
                Shading::Stamp(sk, setup, cover) => unsafe { sk(&st.fragment, setup, &StampTarget::of(fb), cover) },
            };
            fb.samples_passed = fb.samples_passed.wrapping_add(passed);
        });
    }
    for (_, op) in ops {
        op.band(0, fb.height, width, &mut fb.color[..], &mut fb.accum[..]);
    }
}

/// Shades everything binned, in order, the batch in flight first; returns
/// when the framebuffer holds the result.
pub fn flush(rs: &RenderState, fb: &mut Framebuffer) {
    let cell = &rs.batch;
    if !cell.pending.load(Ordering::Relaxed) && !cell.flying.load(Ordering::Relaxed) {
        return;
    }
    let t0 = super::trace::now();
    flush_(rs, fb);
    super::trace::rec(b'F', t0, 0);
    if super::trace::on() {
        super::trace::dump();
    }
}

fn flush_(rs: &RenderState, fb: &mut Framebuffer) {
    let cell = &rs.batch;
    let mut fl = lock_flights(cell);
    finish(cell, &mut fl, fb);
    if let Some(flight) = take_batch(cell, &mut fl) {
        launch(rs, &mut fl, flight, fb);
        finish(cell, &mut fl, fb);
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// An emptied batch gets at least the capacity of the batch just
    /// filled, and one already as large keeps its memory (no new
    /// allocation each batch).
    #[test]
    fn reserved_batches_take_the_filled_size() {
        let mut filled = Batch::default();
        for i in 0..5000 {
            push_prim(&mut filled, Rect::new(0, 0, 1, 1), 0, i);
        }
        filled.extras.extend([0.5; 15]);
        let mut spare = Batch::default();
        spare.reserve_like(&filled);
        assert!(spare.tris.is_empty() && spare.tris.capacity() >= filled.tris.capacity());
        assert!(spare.boxes.is_empty() && spare.boxes.capacity() >= spare.tris.capacity(), "room for a box per record");
        assert!(spare.extras.capacity() >= filled.extras.capacity());
        let at = spare.tris.as_ptr();
        let mut small = Batch::default();
        push_prim(&mut small, Rect::new(0, 0, 1, 1), 0, 0);
        spare.reserve_like(&small);
        assert_eq!(spare.tris.as_ptr(), at, "a large enough batch is not reallocated");
    }

    /// `bin_once` run by several threads at once on the same flight gives
    /// each of them the same lists, and those are, per band, exactly the
    /// records whose box meets the band, in submission order (computed
    /// here by intersecting each box with each band, not by the index
    /// range `bin_once` walks). Boxes empty, outside the surface, one row
    /// high on band edges, and taller than the surface; band heights that
    /// do and do not divide the surface; the same flight binned again
    /// after `clear`.
    #[test]
    fn deferred_band_lists_match_boxes() {
        let mut seed = 7u64;
        let mut next = |n: i32| {
            seed = seed.wrapping_mul(6364136223846793005).wrapping_add(1442695040888963407);
            ((seed >> 33) % n as u64) as i32
        };
        let mut flight = Flight::empty(Arc::default());
        for round in 0..60 {
            let (w, h) = (1 + next(300), 1 + next(300));
            let rows = [16, 32, 64, 7][round % 4];
            let surface = Rect::new(0, 0, w, h);
            let n = next(400) as usize;
            for _ in 0..n {
                let y0 = next(h + 40) - 20;
                let bbox = match next(4) {
                    0 => Rect { x0: 0, y0, x1: w, y1: y0 + 1 },
                    1 => Rect { x0: 0, y0: y0 / rows as i32 * rows as i32, x1: 1, y1: y0 / rows as i32 * rows as i32 + 1 },
                    2 => Rect { x0: next(w + 4) - 2, y0: -5, x1: w + 5, y1: h + next(9) },
                    _ => Rect { x0: next(w), y0, x1: next(w + 1), y1: y0 + next(100) - 10 },
                };
                push_prim(&mut flight.batch, bbox, 0, TRIANGLE | NO_EXTRA_INDEX);
            }
            let bands = (h as usize).div_ceil(rows);
            flight.bins.get_mut().resize_with(bands, Vec::new);
            flight.bins.get_mut().truncate(bands);
            *flight.binned.get_mut() = UNBINNED;
            flight.rows = rows;
            flight.surface = surface;
            let expected: Vec<Vec<u32>> = (0..bands)
                .map(|k| {
                    let band = Rect { x0: 0, y0: (k * rows) as i32, x1: w, y1: ((k + 1) * rows) as i32 }.intersect(surface);
                    (0..n as u32).filter(|&i| !rect_of(flight.batch.boxes[i as usize]).intersect(surface).intersect(band).is_empty()).collect()
                })
                .collect();
            let f = &*flight;
            std::thread::scope(|s| {
                let runs: Vec<_> = (0..4).map(|_| s.spawn(|| f.bin_once().0.to_vec())).collect();
                for r in runs {
                    assert_eq!(r.join().unwrap(), expected, "round {round}");
                }
            });
            // Each band's work: its boxes' pixels within it and the
            // set-up of each; the bands taken heaviest first, each once,
            // equal ones top to bottom.
            let weight: Vec<u64> = (0..bands)
                .map(|k| {
                    let band = Rect { x0: 0, y0: (k * rows) as i32, x1: w, y1: ((k + 1) * rows) as i32 }.intersect(surface);
                    let cost = |i: u32| {
                        let b = rect_of(flight.batch.boxes[i as usize]).intersect(surface).intersect(band);
                        (b.x1 - b.x0) as u64 * (b.y1 - b.y0) as u64 + SETUP_PIXELS
                    };
                    expected[k].iter().map(|&i| cost(i)).sum()
                })
                .collect();
            assert_eq!(flight.weight.get_mut(), &weight, "round {round}");
            let order = flight.order.get_mut().clone();
            let mut sorted = order.clone();
            sorted.sort();
            assert_eq!(sorted, (0..bands as u32).collect::<Vec<_>>(), "round {round}: every band once");
            for p in order.windows(2) {
                let (a, b) = (weight[p[0] as usize], weight[p[1] as usize]);
                assert!(a > b || (a == b && p[0] < p[1]), "round {round}: order {order:?} weights {weight:?}");
            }
            flight.clear();
        }
    }

    /// Setup state for `solve_binned` without texturing.
    struct Params {
        flat: bool,
        offset: Option<(f32, f32)>,
        fog: Option<crate::render::fog::Fog>,
        texture: Option<Arc<crate::render::texture::TextureStage>>,
        color_sum: bool,
    }

    impl SetupParams for Params {
        fn flat(&self) -> bool {
            self.flat
        }
        fn offset_fill(&self) -> Option<(f32, f32)> {
            self.offset
        }
        fn texture(&self) -> Option<&Arc<crate::render::texture::TextureStage>> {
            self.texture.as_ref()
        }
        fn fog(&self) -> Option<crate::render::fog::Fog> {
            self.fog
        }
        fn color_sum(&self) -> bool {
            self.color_sum
        }
    }

    /// A triangle's extra attributes as the calling thread read them.
    #[derive(Default)]
    struct Extras {
        tex: [[Vec4; MAX_UNITS]; 3],
        fog: [f32; 3],
        secondary: [Vec4; 3],
    }

    /// A binned vertex as the band side read it before round 18: its
    /// colour copied out, the rest from the triangle's extras (zeros for
    /// a record without).
    struct Copied<'a> {
        color: Vec4,
        extra: &'a Extras,
        i: usize,
    }

    impl Attributes for Copied<'_> {
        fn color(&self) -> Vec4 {
            self.color
        }
        fn back_color(&self) -> Vec4 {
            self.color
        }
        fn tex(&self, unit: usize) -> Vec4 {
            self.extra.tex[self.i][unit]
        }
        fn fog(&self) -> f32 {
            self.extra.fog[self.i]
        }
        fn secondary(&self) -> Vec4 {
            self.extra.secondary[self.i]
        }
        fn back_secondary(&self) -> Vec4 {
            self.extra.secondary[self.i]
        }
    }

    /// Every field of a set-up as bits.
    fn setup_bits(t: &TriangleSetup) -> Vec<u64> {
        let plane = |p: &crate::render::setup::Plane| [p.a0, p.dx, p.dy].map(f64::to_bits);
        let mut v = vec![t.x0.to_bits(), t.y0.to_bits()];
        v.extend(plane(&t.z));
        v.extend(plane(&t.q));
        t.color.iter().for_each(|p| v.extend(plane(p)));
        v.extend([t.perspective as u64, t.front_facing as u64, t.tex.is_some() as u64]);
        if let Some(tex) = &t.tex {
            for &u in &tex.stage.active {
                v.push(u as u64);
                tex.planes[u].iter().for_each(|p| v.extend(plane(p)));
            }
        }
        v.push(t.flat.map_or(1 << 40, |c| u32::from_le_bytes(c) as u64));
        match &t.fog {
            Some((p, f)) => {
                v.extend(plane(p));
                v.extend([f.mode as u64, f.start.to_bits() as u64]);
            }
            None => v.push(7),
        }
        match &t.secondary {
            Some(s) => s.iter().for_each(|p| v.extend(plane(p))),
            None => v.push(9),
        }
        v
    }

    /// Round 18: `solve_binned` (the record read in place, by
    /// `solve_plain` for a record without extras and `solve_extra` for
    /// one with) gives the bits of `setup::planes_of` on the attributes as
    /// the band side copied them before (`Copied`, zeros for a record
    /// without extras), on random records: perspective or not, equal and
    /// distinct 1/w, flat or smooth, with and without fog and polygon
    /// offset, both facings, the record's vertices in either order.
    /// Round 26: the extras written by their state's `ExtraLayout` (fog,
    /// texture units 0-3 in several sets, the colour sum) into a batch's
    /// floats after other records' and read back from there.
    #[test]
    fn binned_setups_match_planes_of() {
        let mut seed = 11u64;
        let mut next = || {
            seed = seed.wrapping_mul(6364136223846793005).wrapping_add(1442695040888963407);
            seed >> 11
        };
        let fog = crate::render::fog::Fog { mode: crate::render::fog::GL_LINEAR, density: 1.0, start: 0.25, end: 3.0, color: Vec4::ONE, per_fragment: true };
        let unit_sets: [&[usize]; 5] = [&[0], &[1], &[0, 2], &[3], &[0, 1, 2, 3]];
        let stages = unit_sets.map(|active| Arc::new(crate::render::texture::TextureStage { units: Default::default(), envs: [crate::render::texture::env::Env::default(); MAX_UNITS], active: active.to_vec() }));
        let mut floats: Vec<f32> = Vec::new();
        let (mut plain, mut extras, mut textured) = (0, 0, 0);
        for n in 0..40_000 {
            let mut f = |scale: f64| ((next() >> 13) as f64 / (1u64 << 40) as f64 - 0.5) * scale;
            let x: [i64; 3] = std::array::from_fn(|_| (f(2.0) * 4096.0) as i64 + 100_000);
            let y: [i64; 3] = std::array::from_fn(|_| (f(2.0) * 4096.0) as i64 + 50_000);
            let q0 = 0.5 + f(0.5);
            let v: [BinVertex; 3] = std::array::from_fn(|_| BinVertex {
                z: 0.5 + f(1.0),
                q: if n % 3 == 0 { q0 } else { 0.5 + f(0.5) },
                color: std::array::from_fn(|c| if n % 5 == 0 && c == 3 { 1.0 } else { (0.5 + f(1.0)) as f32 }),
            });
            let with_extra = n % 2 == 1;
            let drawn = Extras {
                tex: std::array::from_fn(|_| std::array::from_fn(|_| Vec4::new(f(4.0) as f32, f(4.0) as f32, f(1.0) as f32, 1.0 + f(0.5) as f32))),
                fog: std::array::from_fn(|_| (2.0 * f(2.0)) as f32),
                secondary: std::array::from_fn(|_| Vec4::new(f(1.0) as f32, f(1.0) as f32, f(1.0) as f32, 0.0)),
            };
            let front = n % 4 < 2;
            let params = Params {
                flat: n % 7 == 0,
                offset: (n % 6 == 0).then_some((1.5, 2.0)),
                fog: (with_extra && n % 8 < 5).then_some(fog),
                texture: (with_extra && n % 3 != 0).then(|| stages[(n / 2) % stages.len()].clone()),
                color_sum: n % 10 < 5,
            };
            let layout = ExtraLayout::of(params.texture.as_ref().map(|t| &t.active[..]), params.fog.is_some(), params.color_sum);
            let none = Extras::default();
            let read = if layout.is_empty() { &none } else { &drawn };
            let copied = [0, 1, 2].map(|i| Copied { color: Vec4::from_array(v[i].color), extra: read, i });
            let at = floats.len() as u32;
            layout.write(&mut floats, copied.each_ref(), false);
            let t = Binned {
                v,
                x: x.map(|c| c as i32),
                y: y.map(|c| c as i32),
                state: 0,
                prim: TRIANGLE | if front { FRONT } else { 0 } | if layout.is_empty() { NO_EXTRA_INDEX } else { at },
            };
            let want = crate::render::setup::planes_of(&params, t.v.map(|v| (v.z, v.q)), copied.each_ref(), x, y, Vec4::from_array(t.v[0].color), false, front);
            let (xy, yy) = t.xy();
            assert_eq!((xy, yy), (x, y));
            let mut slot = std::mem::MaybeUninit::uninit();
            let got = solve_binned(&mut slot, &params, &t, Extra { floats: &floats, layout: &layout });
            assert_eq!(setup_bits(got), setup_bits(&want), "record {n}: {x:?} {y:?} {:?} layout {layout:?}", t.v);
            // SAFETY: solved above.
            unsafe { crate::render::setup::release(&mut slot) };
            if !layout.is_empty() {
                extras += 1;
                textured += params.texture.is_some() as u32;
            } else {
                plain += 1;
            }
        }
        assert!(textured > 5_000, "{textured}");
        assert!(plain > 10_000 && extras > 10_000);
    }
}
