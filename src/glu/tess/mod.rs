//! The GLU 1.3 polygon tessellator (GLU 1.3 specification, chapter 5,
//! "Polygon Tessellation"), written from the specification.
//!
//! gluTessEndPolygon projects the contours onto the plane of the normal
//! (given by gluTessNormal, or Newell's normal of the data, flipped so the
//! polygon's total signed area is positive), normalises the 2D coordinates
//! to about [-1, 1] (exact power-of-two scaling), splits all edges at their
//! crossings (COMBINE for every new vertex) and at vertices lying on them,
//! and hands the arrangement to [`sweep`], which computes windings, selects
//! the region with the winding rule and triangulates it. Output is always
//! GL_TRIANGLES (counter-clockwise about the normal), or GL_LINE_LOOPs with
//! GLU_TESS_BOUNDARY_ONLY (region on the left: exteriors counter-clockwise,
//! holes clockwise). Vertices closer than 2^-42 of the polygon's extent are
//! merged (the first one's data is kept, COMBINE is not called for them).
//! GLU_TESS_TOLERANCE is stored and reported but not honoured: the merge
//! distance is that fixed one whatever the tolerance. The specification
//! makes it a hint (vertices and edges closer than tolerance times the
//! largest coordinate *may* be merged), and merging farther apart moves
//! vertices, so the output would no longer cover exactly the region the
//! rule selects from the input (what the exact-coverage tests check), to
//! gain nothing the fixed distance does not already (coincident and
//! nearly coincident vertices are merged at any tolerance). Zero-area triangles (collinear vertices) are emitted rather
//! than dropped, so the mesh has no T-junctions and edge flags are exact:
//! with an EDGE_FLAG callback, an edge is flagged iff it is an edge of the
//! selected region's boundary.
//!
//! Stages: [`simple`] first, the fast path for input that is already a
//! planar arrangement (no near-coincident vertices, no edges crossing or
//! touching: outlines, glyphs, polygons with holes), which checks that as
//! it sweeps and does windings and triangles in that one sweep; it gives
//! up, having output nothing, on anything else. Then the general path:
//! [`merge`] (near-coincident vertices), [`split`] (the arrangement:
//! crossings and touching), [`sweep`] (windings, the region, triangles).
//! The fast path triangulates faces, so it also takes planar input with
//! edges off the region's boundary (nested same-direction contours under
//! NONZERO, an empty selection); the general path triangulates the region
//! between boundary edges only. A shortcut between them: when the fast
//! path gives up after sorting the input, the general path sorts only the vertices the
//! splitter added and merges them into that order (and, if it got past
//! its near-coincident vertex check, skips the merge lookups: there is
//! nothing to merge). Every buffer they use
//! lives in the tessellator object and is reused by the next polygon.
//!
//! Cost: the fast path is O(n log n) plus O(sqrt n) per vertex for its
//! active list ([`blocks`]). The general path finds edge pairs with a
//! uniform grid of about n cells in which each edge occupies the cells its
//! segment crosses, so typical inputs run in near-linear time; inputs with
//! very many crossings are quadratic, as their output is. Its sweep keeps
//! its active edges in a vector (linear search for the edges ending at a
//! vertex, memmove on insert), so self-intersecting polygons with tens of
//! thousands of edges active at once are still quadratic there.
//!
//! Differences from SGI's libtess worth knowing: COMBINE is called only for
//! real crossings (not for merging coincident vertices); a NaN coordinate is
//! reported as GLU_TESS_COORD_TOO_LARGE and replaced by 0; output is always
//! GL_TRIANGLES (never fans or strips); after NEED_COMBINE_CALLBACK (no
//! COMBINE callback, or one that returns NULL) nothing is output.
//!
//! The tessellator never calls GL. Callbacks may call back into it: while
//! gluTessEndPolygon runs its callbacks, calls on the same object are
//! ignored, and gluDeleteTess is deferred until it returns.
//!
//! Safety of the `unsafe fn`s below: `t` is NULL or a pointer returned by
//! [`new_tess`] and not yet deleted; other pointers are NULL or valid as
//! glu.h describes them; callbacks have the signatures glu.h gives them.
#![allow(clippy::missing_safety_doc)]

pub mod blocks;
pub mod merge;
pub mod simple;
pub mod split;
pub mod sweep;

use crate::api::types::*;
use merge::Grid;
use split::{Combiner, Seg};
use std::ffi::c_void;
use sweep::{Rule, Vert};

pub const GLU_TESS_BEGIN: GLenum = 100100;
pub const GLU_TESS_VERTEX: GLenum = 100101;
pub const GLU_TESS_END: GLenum = 100102;
pub const GLU_TESS_ERROR: GLenum = 100103;
pub const GLU_TESS_EDGE_FLAG: GLenum = 100104;
pub const GLU_TESS_COMBINE: GLenum = 100105;
pub const GLU_TESS_BEGIN_DATA: GLenum = 100106;
pub const GLU_TESS_VERTEX_DATA: GLenum = 100107;
pub const GLU_TESS_END_DATA: GLenum = 100108;
pub const GLU_TESS_ERROR_DATA: GLenum = 100109;
pub const GLU_TESS_EDGE_FLAG_DATA: GLenum = 100110;
pub const GLU_TESS_COMBINE_DATA: GLenum = 100111;
pub const GLU_TESS_WINDING_RULE: GLenum = 100140;
pub const GLU_TESS_BOUNDARY_ONLY: GLenum = 100141;
pub const GLU_TESS_TOLERANCE: GLenum = 100142;
pub const GLU_TESS_WINDING_ODD: GLenum = 100130;
pub const GLU_TESS_WINDING_NONZERO: GLenum = 100131;
pub const GLU_TESS_WINDING_POSITIVE: GLenum = 100132;
pub const GLU_TESS_WINDING_NEGATIVE: GLenum = 100133;
pub const GLU_TESS_WINDING_ABS_GEQ_TWO: GLenum = 100134;
pub const GLU_TESS_MISSING_BEGIN_POLYGON: GLenum = 100151;
pub const GLU_TESS_MISSING_BEGIN_CONTOUR: GLenum = 100152;
pub const GLU_TESS_MISSING_END_POLYGON: GLenum = 100153;
pub const GLU_TESS_MISSING_END_CONTOUR: GLenum = 100154;
pub const GLU_TESS_COORD_TOO_LARGE: GLenum = 100155;
pub const GLU_TESS_NEED_COMBINE_CALLBACK: GLenum = 100156;
pub const GLU_TESS_MAX_COORD: f64 = 1.0e150;
use crate::glu::strings::{GLU_INVALID_ENUM, GLU_INVALID_VALUE};

const GL_LINE_LOOP: GLenum = 0x0002;
const GL_TRIANGLES: GLenum = 0x0004;

type FnEnum = unsafe extern "system" fn(GLenum);
type FnEnumData = unsafe extern "system" fn(GLenum, *mut c_void);
type FnBool = unsafe extern "system" fn(GLboolean);
type FnBoolData = unsafe extern "system" fn(GLboolean, *mut c_void);
type FnPtr = unsafe extern "system" fn(*mut c_void);
type FnPtrData = unsafe extern "system" fn(*mut c_void, *mut c_void);
type FnCombine = unsafe extern "system" fn(*const f64, *const *mut c_void, *const f32, *mut *mut c_void);
type FnCombineData = unsafe extern "system" fn(*const f64, *const *mut c_void, *const f32, *mut *mut c_void, *mut c_void);

/// The twelve callbacks, indexed by `which - GLU_TESS_BEGIN`.
#[derive(Clone, Copy, Default)]
struct Callbacks([GLproc; 12]);

#[derive(Clone, Copy, PartialEq, Eq)]
enum State {
    Dormant,
    InPolygon,
    InContour,
}

struct InVertex {
    p: [f64; 3],
    data: *mut c_void,
}

/// A GLUtesselator.
pub struct Tess {
    cb: Callbacks,
    state: State,
    rule: Rule,
    rule_enum: GLenum,
    boundary_only: bool,
    tolerance: f64,
    normal: [f64; 3],
    polygon_data: *mut c_void,
    /// The polygon's vertices, contour after contour; `starts` holds each
    /// contour's first index.
    input: Vec<InVertex>,
    starts: Vec<usize>,
    /// Boxed: taken out and put back around every polygon, a pointer move.
    scratch: Option<Box<Scratch>>,
    busy: bool,
    delete_pending: bool,
}

pub fn new_tess() -> *mut c_void {
    Box::into_raw(Box::new(Tess {
        cb: Callbacks::default(),
        state: State::Dormant,
        rule: Rule::Odd,
        rule_enum: GLU_TESS_WINDING_ODD,
        boundary_only: false,
        tolerance: 0.0,
        normal: [0.0; 3],
        polygon_data: std::ptr::null_mut(),
        input: Vec::with_capacity(64),
        starts: Vec::with_capacity(8),
        scratch: None,
        busy: false,
        delete_pending: false,
    }))
    .cast()
}

/// The object behind a pointer, unless NULL or busy running callbacks.
unsafe fn get<'a>(t: *mut c_void) -> Option<&'a mut Tess> {
    let t = (t as *mut Tess).as_mut()?;
    (!t.busy).then_some(t)
}

pub unsafe fn delete_tess(t: *mut c_void) {
    let Some(r) = (t as *mut Tess).as_mut() else { return };
    if r.busy {
        r.delete_pending = true;
        return;
    }
    r.require(State::Dormant);
    drop(Box::from_raw(t as *mut Tess));
}

impl Tess {
    fn error(&self, e: GLenum) {
        error_with(&self.cb, self.polygon_data, e);
    }

    /// GLU's state rules: moving to `s` one step at a time, reporting each
    /// missing call and supplying it.
    #[inline]
    fn require(&mut self, s: State) {
        if self.state != s {
            self.require_slow(s);
        }
    }

    #[cold]
    fn require_slow(&mut self, s: State) {
        while self.state != s {
            match (self.state, s) {
                (State::Dormant, _) => {
                    self.error(GLU_TESS_MISSING_BEGIN_POLYGON);
                    self.begin_polygon(std::ptr::null_mut());
                }
                (State::InPolygon, State::InContour) => {
                    self.error(GLU_TESS_MISSING_BEGIN_CONTOUR);
                    self.begin_contour();
                }
                (State::InPolygon, _) => {
                    self.error(GLU_TESS_MISSING_END_POLYGON);
                    self.input.clear();
                    self.starts.clear();
                    self.state = State::Dormant;
                }
                (State::InContour, _) => {
                    self.error(GLU_TESS_MISSING_END_CONTOUR);
                    self.state = State::InPolygon;
                }
            }
        }
    }

    fn begin_polygon(&mut self, data: *mut c_void) {
        self.input.clear();
        self.starts.clear();
        self.state = State::InPolygon;
        self.polygon_data = data;
    }

    fn begin_contour(&mut self) {
        self.starts.push(self.input.len());
        self.state = State::InContour;
    }
}

fn error_with(cb: &Callbacks, pdata: *mut c_void, e: GLenum) {
    unsafe {
        if let Some(f) = cb.0[(GLU_TESS_ERROR_DATA - GLU_TESS_BEGIN) as usize] {
            std::mem::transmute::<unsafe extern "system" fn(), FnEnumData>(f)(e, pdata);
        } else if let Some(f) = cb.0[(GLU_TESS_ERROR - GLU_TESS_BEGIN) as usize] {
            std::mem::transmute::<unsafe extern "system" fn(), FnEnum>(f)(e);
        }
    }
}

pub unsafe fn begin_polygon(t: *mut c_void, data: *mut c_void) {
    let Some(t) = get(t) else { return };
    t.require(State::Dormant);
    t.begin_polygon(data);
}

pub unsafe fn begin_contour(t: *mut c_void) {
    let Some(t) = get(t) else { return };
    t.require(State::InPolygon);
    t.begin_contour();
}

pub unsafe fn end_contour(t: *mut c_void) {
    let Some(t) = get(t) else { return };
    t.require(State::InContour);
    t.state = State::InPolygon;
}

pub unsafe fn vertex(t: *mut c_void, location: *const f64, data: *mut c_void) {
    let Some(t) = get(t) else { return };
    t.require(State::InContour);
    if location.is_null() {
        return;
    }
    let p = [location.read_unaligned(), location.add(1).read_unaligned(), location.add(2).read_unaligned()];
    // The usual case: three finite coordinates within range (NaN fails).
    if p[0].abs() <= GLU_TESS_MAX_COORD && p[1].abs() <= GLU_TESS_MAX_COORD && p[2].abs() <= GLU_TESS_MAX_COORD {
        t.input.push(InVertex { p, data });
        return;
    }
    let mut p = [0.0; 3];
    let mut too_large = false;
    for (i, c) in p.iter_mut().enumerate() {
        let x = location.add(i).read_unaligned();
        *c = if x.is_nan() {
            too_large = true;
            0.0
        } else if x.abs() > GLU_TESS_MAX_COORD {
            too_large = true;
            x.clamp(-GLU_TESS_MAX_COORD, GLU_TESS_MAX_COORD)
        } else {
            x
        };
    }
    if too_large {
        t.error(GLU_TESS_COORD_TOO_LARGE);
    }
    t.input.push(InVertex { p, data });
}

pub unsafe fn normal(t: *mut c_void, x: f64, y: f64, z: f64) {
    let Some(t) = get(t) else { return };
    t.normal = [x, y, z];
}

pub unsafe fn callback(t: *mut c_void, which: GLenum, f: GLproc) {
    let Some(t) = get(t) else { return };
    if (GLU_TESS_BEGIN..=GLU_TESS_COMBINE_DATA).contains(&which) {
        t.cb.0[(which - GLU_TESS_BEGIN) as usize] = f;
    } else {
        t.error(GLU_INVALID_ENUM);
    }
}

pub unsafe fn property(t: *mut c_void, which: GLenum, value: f64) {
    let Some(t) = get(t) else { return };
    match which {
        GLU_TESS_WINDING_RULE => {
            let rule = if value.is_finite() && value == value.trunc() && value >= 0.0 && value <= u32::MAX as f64 {
                match value as u32 {
                    GLU_TESS_WINDING_ODD => Some(Rule::Odd),
                    GLU_TESS_WINDING_NONZERO => Some(Rule::NonZero),
                    GLU_TESS_WINDING_POSITIVE => Some(Rule::Positive),
                    GLU_TESS_WINDING_NEGATIVE => Some(Rule::Negative),
                    GLU_TESS_WINDING_ABS_GEQ_TWO => Some(Rule::AbsGeqTwo),
                    _ => None,
                }
            } else {
                None
            };
            match rule {
                Some(r) => {
                    t.rule = r;
                    t.rule_enum = value as u32;
                }
                None => t.error(GLU_INVALID_VALUE),
            }
        }
        GLU_TESS_BOUNDARY_ONLY => t.boundary_only = value != 0.0,
        GLU_TESS_TOLERANCE => {
            if (0.0..=1.0).contains(&value) {
                t.tolerance = value;
            } else {
                t.error(GLU_INVALID_VALUE);
            }
        }
        _ => t.error(GLU_INVALID_ENUM),
    }
}

pub unsafe fn get_property(t: *mut c_void, which: GLenum, out: *mut f64) {
    let Some(t) = (t as *mut Tess).as_mut() else { return };
    let v = match which {
        GLU_TESS_WINDING_RULE => t.rule_enum as f64,
        GLU_TESS_BOUNDARY_ONLY => t.boundary_only as u8 as f64,
        GLU_TESS_TOLERANCE => t.tolerance,
        _ => {
            if !t.busy {
                t.error(GLU_INVALID_ENUM);
            }
            0.0
        }
    };
    if !out.is_null() {
        out.write_unaligned(v);
    }
}

/// GLU 1.1: gluBeginPolygon.
pub unsafe fn begin_polygon_11(t: *mut c_void) {
    begin_polygon(t, std::ptr::null_mut());
    begin_contour(t);
}

/// GLU 1.1: gluNextContour (the contour type is only a hint; ignored).
pub unsafe fn next_contour(t: *mut c_void, _type: GLenum) {
    end_contour(t);
    begin_contour(t);
}

/// GLU 1.1: gluEndPolygon.
pub unsafe fn end_polygon_11(t: *mut c_void) {
    end_contour(t);
    end_polygon(t);
}

pub unsafe fn end_polygon(tp: *mut c_void) {
    let Some(t) = get(tp) else { return };
    t.require(State::InPolygon);
    t.state = State::Dormant;
    let input = std::mem::take(&mut t.input);
    let starts = std::mem::take(&mut t.starts);
    let mut scratch = t.scratch.take().unwrap_or_else(|| {
        let mut s = Box::<Scratch>::default();
        s.reserve(64);
        s
    });
    let job = Job { cb: t.cb, pdata: t.polygon_data, rule: t.rule, boundary_only: t.boundary_only, normal: t.normal };
    t.busy = true;
    // Callbacks run with `busy` set; a panic in our code is caught by the
    // entry point's guard, so reset the flag whatever happens.
    struct Reset(*mut Tess);
    impl Drop for Reset {
        fn drop(&mut self) {
            unsafe {
                let t = &mut *self.0;
                t.busy = false;
                if t.delete_pending {
                    t.delete_pending = false;
                    delete_tess(self.0.cast());
                }
            }
        }
    }
    let reset = Reset(tp as *mut Tess);
    let contours = Contours { input: &input, starts: &starts };
    job.run(&contours, &mut scratch);
    // Keep the buffers for the next polygon (unless deleted meanwhile).
    let t = &mut *reset.0;
    if !t.delete_pending {
        t.input = input;
        t.starts = starts;
        t.scratch = Some(scratch);
    }
    drop(reset);
}

/// The input as contours: slices of `input` between `starts`.
struct Contours<'a> {
    input: &'a [InVertex],
    starts: &'a [usize],
}

impl<'a> Contours<'a> {
    fn iter(&self) -> impl Iterator<Item = &'a [InVertex]> + '_ {
        (0..self.starts.len()).map(move |k| {
            let end = self.starts.get(k + 1).copied().unwrap_or(self.input.len());
            &self.input[self.starts[k]..end]
        })
    }
}

/// Buffers kept in the tessellator object from one polygon to the next.
#[derive(Default)]
struct Scratch {
    p2: Vec<[f64; 2]>,
    verts: Vec<Vert>,
    p3: Vec<[f64; 3]>,
    data: Vec<*mut c_void>,
    id: Vec<usize>,
    /// Per input vertex: did it become a vertex of its own (not merged)?
    rep: Vec<bool>,
    /// The general path's sweep order, from the fast path's sorted input
    /// and the sorted new (crossing) vertices.
    fresh: Vec<(u64, u64, u32)>,
    sorted: Vec<u32>,
    segs: Vec<Seg>,
    grid: Grid,
    split: split::Scratch,
    sweep: sweep::Scratch,
    simple: simple::Scratch,
}

impl Scratch {
    /// See [`split::Scratch::reserve`].
    fn reserve(&mut self, n: usize) {
        self.fresh.reserve(n);
        self.sorted.reserve(n);
        self.p2.reserve(n);
        self.verts.reserve(n);
        self.p3.reserve(n);
        self.data.reserve(n);
        self.id.reserve(n);
        self.rep.reserve(n);
        self.segs.reserve(n);
        self.split.reserve(n);
        self.sweep.reserve(n);
        self.simple.reserve(n);
    }
}

/// One polygon's tessellation, with a copy of the callbacks it uses.
struct Job {
    cb: Callbacks,
    pdata: *mut c_void,
    rule: Rule,
    boundary_only: bool,
    normal: [f64; 3],
}

use super::vec3::{cross, dot, norm, sub};

/// A power of two near 1/x (x > 0, finite), so scaling by it is exact.
fn pow2_inv(x: f64) -> f64 {
    if !(x > 0.0) || !x.is_finite() {
        return 1.0;
    }
    // From the bits when the answer is clear: a normal x = m·2^e with
    // m > 1 + 2^-40 has ceil(log2 x) = e + 1 (log2 x is then more than a
    // thousand ulps of e above e, so the libm route below agrees). Near a
    // power of two, and for subnormals, that route itself (a libm call
    // and powi: a fixed cost of every polygon).
    let b = x.to_bits();
    let (be, m) = ((b >> 52) as i32, b & ((1u64 << 52) - 1));
    if be > 0 && m >> 12 != 0 {
        let e = (be - 1023 + 1).clamp(-1000, 1000);
        return f64::from_bits(((1023 - e) as u64) << 52);
    }
    let e = x.log2().ceil() as i32;
    2f64.powi(-e.clamp(-1000, 1000))
}

/// Three doubles laid out as a Delphi / Free Pascal dynamic array: the
/// header (reference count, high bound) sits right before the elements.
#[repr(C)]
struct PascalArray3 {
    refcount: isize,
    high: isize,
    coords: [f64; 3],
}

struct Comb<'a> {
    job: &'a Job,
    p3: &'a mut Vec<[f64; 3]>,
    data: &'a mut Vec<*mut c_void>,
    failed: bool,
}

impl Combiner for Comb<'_> {
    fn combine(&mut self, verts: &mut Vec<Vert>, p: [f64; 2], e: [usize; 4], t: f64, s: f64) -> Option<usize> {
        if self.failed {
            return None;
        }
        // (The four vertices read once, into locals: fewer bounds checks
        // than indexing in each expression below.)
        let (v0, v1, v2, v3) = (self.p3[e[0]], self.p3[e[1]], self.p3[e[2]], self.p3[e[3]]);
        let lerp = |a: [f64; 3], b: [f64; 3], t: f64| [a[0] + t * (b[0] - a[0]), a[1] + t * (b[1] - a[1]), a[2] + t * (b[2] - a[2])];
        let q1 = lerp(v0, v1, t);
        let q2 = lerp(v2, v3, s);
        // A convex combination of the four vertices: clamped to their box,
        // since halving subnormals rounds (the fuzz target found z one
        // subnormal ulp above every input z).
        let coords: [f64; 3] = std::array::from_fn(|k| {
            let lo = f64::INFINITY.min(v0[k]).min(v1[k]).min(v2[k]).min(v3[k]);
            let hi = f64::NEG_INFINITY.max(v0[k]).max(v1[k]).max(v2[k]).max(v3[k]);
            (0.5 * q1[k] + 0.5 * q2[k]).max(lo).min(hi)
        });
        // Delphi programs declare `coords` as a dynamic array (the Persian
        // book's tesswind does): the compiled callback then adds and drops
        // a reference in the array header just before the pointer. Give it
        // a header of our own that says "constant array" (reference count
        // -1, high bound 2), so that touches only this struct and never
        // frees anything.
        let pascal = PascalArray3 { refcount: -1, high: 2, coords };
        let vd = [self.data[e[0]], self.data[e[1]], self.data[e[2]], self.data[e[3]]];
        let w = [(0.5 * (1.0 - t)) as f32, (0.5 * t) as f32, (0.5 * (1.0 - s)) as f32, (0.5 * s) as f32];
        let mut out: *mut c_void = std::ptr::null_mut();
        let cb = &self.job.cb.0;
        unsafe {
            if let Some(f) = cb[(GLU_TESS_COMBINE_DATA - GLU_TESS_BEGIN) as usize] {
                std::mem::transmute::<unsafe extern "system" fn(), FnCombineData>(f)(pascal.coords.as_ptr(), vd.as_ptr(), w.as_ptr(), &mut out, self.job.pdata);
            } else if let Some(f) = cb[(GLU_TESS_COMBINE - GLU_TESS_BEGIN) as usize] {
                std::mem::transmute::<unsafe extern "system" fn(), FnCombine>(f)(pascal.coords.as_ptr(), vd.as_ptr(), w.as_ptr(), &mut out);
            }
        }
        if out.is_null() {
            self.failed = true;
            error_with(&self.job.cb, self.job.pdata, GLU_TESS_NEED_COMBINE_CALLBACK);
            return None;
        }
        verts.push(Vert { p });
        self.p3.push(coords);
        self.data.push(out);
        Some(verts.len() - 1)
    }
}

impl Job {
    fn cbf(&self, which: GLenum) -> GLproc {
        self.cb.0[(which - GLU_TESS_BEGIN) as usize]
    }

    fn begin(&self, mode: GLenum) {
        unsafe {
            if let Some(f) = self.cbf(GLU_TESS_BEGIN_DATA) {
                std::mem::transmute::<unsafe extern "system" fn(), FnEnumData>(f)(mode, self.pdata);
            } else if let Some(f) = self.cbf(GLU_TESS_BEGIN) {
                std::mem::transmute::<unsafe extern "system" fn(), FnEnum>(f)(mode);
            }
        }
    }
    fn vertex(&self, d: *mut c_void) {
        unsafe {
            if let Some(f) = self.cbf(GLU_TESS_VERTEX_DATA) {
                std::mem::transmute::<unsafe extern "system" fn(), FnPtrData>(f)(d, self.pdata);
            } else if let Some(f) = self.cbf(GLU_TESS_VERTEX) {
                std::mem::transmute::<unsafe extern "system" fn(), FnPtr>(f)(d);
            }
        }
    }
    fn end(&self) {
        unsafe {
            if let Some(f) = self.cbf(GLU_TESS_END_DATA) {
                std::mem::transmute::<unsafe extern "system" fn(), FnPtr>(f)(self.pdata);
            } else if let Some(f) = self.cbf(GLU_TESS_END) {
                f();
            }
        }
    }
    fn has_edge_flag(&self) -> bool {
        self.cbf(GLU_TESS_EDGE_FLAG_DATA).is_some() || self.cbf(GLU_TESS_EDGE_FLAG).is_some()
    }
    fn edge_flag(&self, b: bool) {
        unsafe {
            if let Some(f) = self.cbf(GLU_TESS_EDGE_FLAG_DATA) {
                std::mem::transmute::<unsafe extern "system" fn(), FnBoolData>(f)(b as GLboolean, self.pdata);
            } else if let Some(f) = self.cbf(GLU_TESS_EDGE_FLAG) {
                std::mem::transmute::<unsafe extern "system" fn(), FnBool>(f)(b as GLboolean);
            }
        }
    }

    fn run(&self, contours: &Contours, sc: &mut Scratch) {
        let all = || contours.input.iter();
        if all().next().is_none() {
            return;
        }
        // Normal: given, or Newell's (on exactly rescaled coordinates, so
        // neither 1e150 nor 1e-150 overflows or underflows).
        // (Coordinates are never NaN here: gluTessVertex replaced them.
        // Plain comparisons then give what f64::max and min would.)
        let larger = |a: f64, b: f64| if b > a { b } else { a };
        let m = all().fold(0.0, |m, v| larger(larger(larger(m, v.p[0].abs()), v.p[1].abs()), v.p[2].abs()));
        let k = pow2_inv(m);
        let mut n = self.normal;
        if !(n.iter().all(|x| x.is_finite()) && norm(n) > 0.0) {
            let mut s = [0.0; 3];
            for c in contours.iter() {
                for i in 0..c.len() {
                    let a = c[i].p.map(|x| x * k);
                    let b = c[(i + 1) % c.len()].p.map(|x| x * k);
                    s[0] += (a[1] - b[1]) * (a[2] + b[2]);
                    s[1] += (a[2] - b[2]) * (a[0] + b[0]);
                    s[2] += (a[0] - b[0]) * (a[1] + b[1]);
                }
            }
            if !(norm(s) > 1e-200) || !s.iter().all(|x| x.is_finite()) {
                // Degenerate (or cancelling) contours: the largest cross
                // product of two spans from the first vertex.
                let v0 = all().next().unwrap().p.map(|x| x * k);
                let far = all().map(|v| v.p.map(|x| x * k)).max_by(|a, b| norm(sub(*a, v0)).total_cmp(&norm(sub(*b, v0)))).unwrap();
                let d1 = sub(far, v0);
                s = all().map(|v| cross(d1, sub(v.p.map(|x| x * k), v0))).max_by(|a, b| norm(*a).total_cmp(&norm(*b))).unwrap();
                if !(norm(s) > 0.0) || !s.iter().all(|x| x.is_finite()) {
                    s = [0.0, 0.0, 1.0];
                }
            }
            n = s;
        }
        let big = n[0].abs().max(n[1].abs()).max(n[2].abs());
        let n = n.map(|x| x / big); // no overflow in the norm of a huge normal
        let ln = norm(n);
        let n = n.map(|x| x / ln);
        // Basis (u, v) with u × v = n.
        let ax = (0..3).min_by(|&i, &j| n[i].abs().total_cmp(&n[j].abs())).unwrap();
        // u is that axis made perpendicular to n (exactly the axis when n
        // is axis-aligned: n = +z gives u = +x, v = +y).
        let mut e = [0.0; 3];
        e[ax] = 1.0;
        let u = sub(e, n.map(|x| x * n[ax]));
        let lu = norm(u);
        let u = u.map(|x| x / lu);
        let v = cross(n, u);
        // Project (scaled), then centre and normalise.
        let p2 = &mut sc.p2;
        p2.clear();
        p2.extend(all().map(|q| {
            let q = q.p.map(|x| x * k);
            [dot(q, u), dot(q, v)]
        }));
        let (mut lo, mut hi) = ([f64::INFINITY; 2], [f64::NEG_INFINITY; 2]);
        for p in p2.iter() {
            for i in 0..2 {
                if p[i] < lo[i] {
                    lo[i] = p[i];
                }
                if p[i] > hi[i] {
                    hi[i] = p[i];
                }
            }
        }
        let c = [0.5 * (lo[0] + hi[0]), 0.5 * (lo[1] + hi[1])];
        let ext = (hi[0] - lo[0]).max(hi[1] - lo[1]);
        let s = pow2_inv(ext);
        // Sweep along the longer side (a quarter turn keeps orientation):
        // a comb is swept along its back, not across its teeth.
        let turn = hi[1] - lo[1] > hi[0] - lo[0];
        for p in p2.iter_mut() {
            let q = [(p[0] - c[0]) * s, (p[1] - c[1]) * s];
            *p = if turn { [q[1], -q[0]] } else { q };
        }
        // Automatic normal: make the total signed area non-negative.
        let auto = !(self.normal.iter().all(|x| x.is_finite()) && norm(self.normal) > 0.0);
        if auto {
            let mut area = 0.0;
            let mut base = 0;
            for cont in contours.iter() {
                for i in 0..cont.len() {
                    let a = p2[base + i];
                    let b = p2[base + (i + 1) % cont.len()];
                    area += a[0] * b[1] - a[1] * b[0];
                }
                base += cont.len();
            }
            if area < 0.0 {
                for p in p2.iter_mut() {
                    p[1] = -p[1];
                }
            }
        }
        let Scratch { p2, verts, p3, data, id, rep, fresh, sorted, segs, grid, split, sweep: sw, simple: si } = sc;
        // Already a planar arrangement (checked as it goes): one sweep.
        verts.clear();
        verts.extend(p2.iter().map(|&p| Vert { p }));
        match simple::tessellate(verts, contours.starts, self.rule, self.boundary_only, self.has_edge_flag(), si, &mut sw.pool, &mut sw.region) {
            simple::Outcome::Done => {
                data.clear();
                data.extend(all().map(|v| v.data));
                self.emit(&sw.region, data);
                return;
            }
            simple::Outcome::No => {}
        }
        // Merge near-coincident vertices.
        verts.clear();
        p3.clear();
        data.clear();
        id.clear();
        rep.clear();
        grid.reset(p2.len());
        if si.distinct {
            // The fast path found no two vertices within EPS (the test a
            // lookup makes): each is its own (`id` and `rep` stay empty:
            // the identity, read below as such); the grid only needs them in.
            verts.extend(p2.iter().map(|&p| Vert { p }));
            p3.extend(all().map(|iv| iv.p));
            data.extend(all().map(|iv| iv.data));
            grid.insert_all(verts);
        } else {
            for (q, iv) in p2.iter().zip(all()) {
                rep.push(false);
                match grid.find(verts, *q) {
                    Some(i) => id.push(i),
                    None => {
                        *rep.last_mut().unwrap() = true;
                        verts.push(Vert { p: *q });
                        p3.push(iv.p);
                        data.push(iv.data);
                        grid.insert(verts, verts.len() - 1);
                        id.push(verts.len() - 1);
                    }
                }
            }
        }
        segs.clear();
        let mut base = 0;
        for cont in contours.iter() {
            let len = cont.len();
            if si.distinct && len >= 3 {
                // (The fast path refuses contours of 1 or 2 vertices first.)
                segs.extend((base..base + len - 1).map(|a| Seg { a, b: a + 1 }));
                segs.push(Seg { a: base + len - 1, b: base });
            } else {
                for i in 0..len {
                    let (a, b) = (id[base + i], id[base + (i + 1) % len]);
                    if a != b {
                        segs.push(Seg { a, b });
                    }
                }
            }
            base += len;
        }
        let merged = verts.len();
        let mut comb = Comb { job: self, p3, data, failed: false };
        if !split::split_all(verts, grid, segs, &mut comb, split) {
            return;
        }
        // The sweep order: the fast path sorted the input already (if it
        // got that far); the merged vertices keep that order (their ids grow
        // with their input index), so only the new vertices need sorting,
        // then one merge of the two runs, the order a full sort would give.
        let order = if si.keyed.len() == p2.len() {
            fresh.clear();
            fresh.extend(verts[merged..].iter().enumerate().map(|(k, v)| (sweep::ord_key(v.p[0]), sweep::ord_key(v.p[1]), (merged + k) as u32)));
            // By (x, y) as one 128-bit key: cheaper comparisons than the
            // tuple's, and the same order (new vertices are pairwise more
            // than EPS apart, so no two share a key and ids never decide).
            fresh.sort_unstable_by_key(|k| (k.0 as u128) << 64 | k.1 as u128);
            sorted.clear();
            if si.distinct {
                // Every input vertex is its own id: merge the two sorted
                // runs directly.
                let (old, new) = (&si.keyed[..], &fresh[..]);
                let (mut i, mut j) = (0, 0);
                while i < old.len() && j < new.len() {
                    if old[i] <= new[j] {
                        sorted.push(old[i].2);
                        i += 1;
                    } else {
                        sorted.push(new[j].2);
                        j += 1;
                    }
                }
                sorted.extend(old[i..].iter().map(|k| k.2));
                sorted.extend(new[j..].iter().map(|k| k.2));
            } else {
                let mut old = si.keyed.iter().filter(|k| rep[k.2 as usize]).map(|k| (k.0, k.1, id[k.2 as usize] as u32)).peekable();
                let mut new = fresh.iter().copied().peekable();
                loop {
                    let next = match (old.peek(), new.peek()) {
                        (Some(a), Some(b)) if a <= b => old.next(),
                        (Some(_), None) => old.next(),
                        (_, Some(_)) => new.next(),
                        (None, None) => break,
                    };
                    sorted.extend(next.map(|k| k.2));
                }
            }
            Some(&sorted[..])
        } else {
            None
        };
        sweep::region(verts, segs, self.rule, self.boundary_only, order, sw);
        self.emit(&sw.region, data);
    }

    fn emit(&self, r: &sweep::Region, data: &[*mut c_void]) {
        if self.boundary_only {
            self.emit_loops(&r.boundary, data);
        } else {
            self.emit_triangles(r, data);
        }
    }

    fn emit_triangles(&self, r: &sweep::Region, data: &[*mut c_void]) {
        if r.triangles.is_empty() {
            return;
        }
        let flags = self.has_edge_flag();
        let bi = if flags { Some(sweep::BoundaryIndex::new(r)) } else { None };
        self.begin(GL_TRIANGLES);
        let mut last: Option<bool> = None;
        for t in &r.triangles {
            for i in 0..3 {
                if flags {
                    let (a, b) = (t[i], t[(i + 1) % 3]);
                    let f = bi.as_ref().is_some_and(|bi| bi.on_boundary(a, b));
                    if last != Some(f) {
                        self.edge_flag(f);
                        last = Some(f);
                    }
                }
                self.vertex(data[t[i]]);
            }
        }
        self.end();
    }

    fn emit_loops(&self, edges: &[(usize, usize)], data: &[*mut c_void]) {
        // Edges leaving each vertex: `by_start` sorted by start vertex (stable,
        // so in boundary order), looked up by binary search.
        let mut by_start: Vec<u32> = (0..edges.len() as u32).collect();
        by_start.sort_by_key(|&i| edges[i as usize].0);
        let mut used = vec![false; edges.len()];
        let mut lp = Vec::new();
        for s in 0..edges.len() {
            if used[s] {
                continue;
            }
            lp.clear();
            let mut e = s;
            loop {
                used[e] = true;
                lp.push(edges[e].0);
                let to = edges[e].1;
                let first = by_start.partition_point(|&i| edges[i as usize].0 < to);
                let next = by_start[first..].iter().take_while(|&&i| edges[i as usize].0 == to).map(|&i| i as usize).find(|&x| !used[x]);
                match next {
                    Some(x) => e = x,
                    None => break,
                }
            }
            if lp.len() >= 2 {
                self.begin(GL_LINE_LOOP);
                for &v in &lp {
                    self.vertex(data[v]);
                }
                self.end();
            }
        }
    }
}

/// The tessellator's unit tests' random numbers: xorshift64 steps, and
/// uniform values in [0, 1) (53 bits) from them.
#[cfg(test)]
pub(super) mod test_rng {
    pub fn xorshift(mut seed: u64) -> impl FnMut() -> u64 {
        move || {
            seed ^= seed << 13;
            seed ^= seed >> 7;
            seed ^= seed << 17;
            seed
        }
    }

    pub fn unit_rng(seed: u64) -> impl FnMut() -> f64 {
        let mut next = xorshift(seed);
        move || (next() >> 11) as f64 / (1u64 << 53) as f64
    }
}

#[cfg(test)]
mod tests {
    use super::pow2_inv;

    /// The bit route of `pow2_inv` gives what the libm route (2^-ceil(log2 x))
    /// gives: random doubles of every exponent, and values next to powers
    /// of two (where the libm route itself decides).
    #[test]
    fn pow2_inv_matches_log2_route() {
        let libm = |x: f64| 2f64.powi(-(x.log2().ceil() as i32).clamp(-1000, 1000));
        let mut s = 0x2545_f491_4f6c_dd1du64;
        let check = |x: f64| {
            if x > 0.0 && x.is_finite() {
                assert_eq!(pow2_inv(x).to_bits(), libm(x).to_bits(), "x = {x:e} ({:#x})", x.to_bits());
            }
        };
        for _ in 0..200_000 {
            s ^= s << 13;
            s ^= s >> 7;
            s ^= s << 17;
            check(f64::from_bits(s >> 1));
        }
        for e in -1074..1024 {
            let p = 2f64.powi(e);
            for k in 0..64u64 {
                check(f64::from_bits(p.to_bits() + k));
                check(f64::from_bits(p.to_bits() + (k << 12)));
                check(f64::from_bits(p.to_bits().wrapping_sub(k)));
            }
        }
    }
}
