//! Fuzz target for the GLU tessellator, driven through the C entry points
//! (gluNewTess ... gluTessEndPolygon) exactly as a C program would.
//!
//! The input bytes decode into options (winding rule, boundary-only, edge
//! flag / combine callbacks on or off, the _DATA callback forms, a normal,
//! a COMBINE that fails, sloppy begin/end calls) and one to three polygons
//! tessellated by the same object. Vertices come from a small integer grid
//! (duplicates, collinear runs, touching edges), raw bit patterns (NaN,
//! infinities, subnormals), a table of extreme values (±1e150, 1e-150,
//! 1e300 ...), scaled grid points and near-duplicates of the last vertex.
//!
//! Checked on every run: no panic (libfuzzer-sys aborts on one, before the
//! entry point's guard could catch it), termination (libFuzzer's -timeout),
//! every VERTEX pointer is one given to gluTessVertex or returned by
//! COMBINE, COMBINE gets known pointers, finite weights summing to 1,
//! finite coordinates inside the input's bounding box and *dataOut NULL,
//! BEGIN/END nest and carry the right primitive type, triangles come in
//! threes, EDGE_FLAG only when set and never for line loops, and only the
//! errors the input can cause are reported.
#![no_main]

use libfuzzer_sys::fuzz_target;
use softgl::api::table::*;
use softgl::glu::tess::*;
use std::cell::RefCell;
use std::collections::HashSet;
use std::ffi::c_void;

const RULES: [u32; 5] = [GLU_TESS_WINDING_ODD, GLU_TESS_WINDING_NONZERO, GLU_TESS_WINDING_POSITIVE, GLU_TESS_WINDING_NEGATIVE, GLU_TESS_WINDING_ABS_GEQ_TWO];
const GL_LINE_LOOP: u32 = 2;
const GL_TRIANGLES: u32 = 4;
const SPECIAL: [f64; 16] = [
    0.0, 1.0, -1.0, f64::NAN, f64::INFINITY, f64::NEG_INFINITY, 1e150, -1e150, 1e-150, -1e-150, 1e300, f64::MIN_POSITIVE, 5e-324, 1.0 + f64::EPSILON, 1e151, 0.5,
];
const SCALES: [f64; 8] = [1.0, 1e150, 1e-150, 1e-300, 1e300, 1e-5, 1e10, 3.0];
const MAX_VERTS: usize = 4000;

/// What the callbacks check against, and what they saw.
#[derive(Default)]
struct Check {
    known: HashSet<usize>,
    boundary: bool,
    flags_cb: bool,
    combine_fail_at: Option<usize>,
    combines: usize,
    combine_failed: bool,
    in_prim: Option<u32>,
    prim_verts: usize,
    begins: usize,
    errors: Vec<u32>,
    /// Bounding box of the (clamped) input coordinates, for COMBINE's output.
    lo: [f64; 3],
    hi: [f64; 3],
    arena: Vec<Box<[f64; 3]>>,
    /// The output's vertices in order (for the coverage check), and the
    /// edge flag in force at each.
    out: Vec<[f64; 3]>,
    out_flags: Vec<bool>,
    flag: bool,
}

thread_local! {
    static CHECK: RefCell<Check> = RefCell::new(Check::default());
}

fn with<R>(f: impl FnOnce(&mut Check) -> R) -> R {
    CHECK.with(|c| f(&mut c.borrow_mut()))
}

extern "system" fn cb_begin(mode: u32) {
    with(|c| {
        assert!(c.in_prim.is_none(), "BEGIN inside BEGIN/END");
        let want = if c.boundary { GL_LINE_LOOP } else { GL_TRIANGLES };
        assert_eq!(mode, want, "primitive type");
        assert!(!c.combine_failed, "output after NEED_COMBINE_CALLBACK");
        c.in_prim = Some(mode);
        c.prim_verts = 0;
        c.begins += 1;
    });
}
extern "system" fn cb_begin_data(mode: u32, d: *mut c_void) {
    assert_eq!(d as usize, 0x5eed, "polygon data");
    cb_begin(mode);
}
extern "system" fn cb_vertex(d: *mut c_void) {
    with(|c| {
        assert!(c.in_prim.is_some(), "VERTEX outside BEGIN/END");
        assert!(c.known.contains(&(d as usize)), "VERTEX with a pointer never given: {d:p}");
        c.prim_verts += 1;
        // Every known pointer points at an [f64; 3] (input or COMBINE's).
        c.out.push(unsafe { *(d as *const [f64; 3]) });
        let f = c.flag;
        c.out_flags.push(f);
    });
}
extern "system" fn cb_vertex_data(d: *mut c_void, pd: *mut c_void) {
    assert_eq!(pd as usize, 0x5eed, "polygon data");
    cb_vertex(d);
}
extern "system" fn cb_end() {
    with(|c| {
        let mode = c.in_prim.take().expect("END without BEGIN");
        if mode == GL_TRIANGLES {
            assert!(c.prim_verts > 0 && c.prim_verts % 3 == 0, "GL_TRIANGLES with {} vertices", c.prim_verts);
        } else {
            assert!(c.prim_verts >= 2, "GL_LINE_LOOP with {} vertices", c.prim_verts);
        }
    });
}
extern "system" fn cb_end_data(pd: *mut c_void) {
    assert_eq!(pd as usize, 0x5eed, "polygon data");
    cb_end();
}
extern "system" fn cb_flag(f: u8) {
    with(|c| {
        c.flag = f != 0;
        assert!(c.flags_cb, "EDGE_FLAG without a callback set");
        assert!(!c.boundary, "EDGE_FLAG in boundary-only mode");
    });
}
extern "system" fn cb_flag_data(f: u8, pd: *mut c_void) {
    assert_eq!(pd as usize, 0x5eed, "polygon data");
    cb_flag(f);
}
extern "system" fn cb_error(e: u32) {
    with(|c| {
        c.errors.push(e);
        c.combine_failed |= e == GLU_TESS_NEED_COMBINE_CALLBACK;
    });
}
extern "system" fn cb_error_data(e: u32, pd: *mut c_void) {
    assert_eq!(pd as usize, 0x5eed, "polygon data");
    cb_error(e);
}
extern "system" fn cb_combine(co: *const f64, d: *const *mut c_void, w: *const f32, out: *mut *mut c_void) {
    unsafe {
        assert!((*out).is_null(), "*dataOut not NULL before COMBINE");
        let p = [*co, *co.add(1), *co.add(2)];
        with(|c| {
            c.combines += 1;
            let mut sum = 0.0f64;
            for i in 0..4 {
                let wi = *w.add(i);
                let di = *d.add(i);
                assert!(wi.is_finite() && (0.0..=1.0).contains(&wi), "weight {wi}");
                sum += wi as f64;
                assert!(di.is_null() && wi == 0.0 || c.known.contains(&(di as usize)), "COMBINE given an unknown vertex {di:p}");
            }
            assert!((sum - 1.0).abs() < 1e-5, "weights sum to {sum}");
            for k in 0..3 {
                let slack = 1e-9 * (c.hi[k] - c.lo[k]).abs().max(c.lo[k].abs()).max(c.hi[k].abs());
                assert!(p[k].is_finite() && p[k] >= c.lo[k] - slack && p[k] <= c.hi[k] + slack, "combined coordinate {k} = {} outside [{}, {}]", p[k], c.lo[k], c.hi[k]);
            }
            if c.combine_fail_at == Some(c.combines) {
                return; // leaves *out NULL: the tessellator must report NEED_COMBINE_CALLBACK
            }
            let b = Box::new(p);
            let ptr = &*b as *const [f64; 3] as *mut c_void;
            c.arena.push(b);
            c.known.insert(ptr as usize);
            *out = ptr;
        });
    }
}
extern "system" fn cb_combine_data(co: *const f64, d: *const *mut c_void, w: *const f32, out: *mut *mut c_void, pd: *mut c_void) {
    assert_eq!(pd as usize, 0x5eed, "polygon data");
    cb_combine(co, d, w, out);
}

fn proc_of<T>(f: T) -> Option<unsafe extern "system" fn()> {
    assert_eq!(std::mem::size_of::<T>(), std::mem::size_of::<usize>());
    Some(unsafe { std::mem::transmute_copy::<T, unsafe extern "system" fn()>(&f) })
}

/// A byte reader that yields zeros once the input runs out.
struct Bytes<'a>(&'a [u8]);
impl Bytes<'_> {
    fn u8(&mut self) -> u8 {
        match self.0.split_first() {
            Some((&b, rest)) => {
                self.0 = rest;
                b
            }
            None => 0,
        }
    }
    fn f64(&mut self) -> f64 {
        let mut b = [0u8; 8];
        for x in b.iter_mut() {
            *x = self.u8();
        }
        f64::from_le_bytes(b)
    }
    fn done(&self) -> bool {
        self.0.is_empty()
    }
}

/// One polygon: contours of points.
type Polygon = Vec<Vec<[f64; 3]>>;

/// Decodes contours until the input ends or a polygon break. The flag
/// says whether every vertex is a grid point in the plane z = 0 (then the
/// output's coverage is checked exactly).
fn decode_polygon(b: &mut Bytes, budget: &mut usize) -> (Polygon, bool) {
    let mut poly: Polygon = vec![Vec::new()];
    let mut planar_grid = true;
    let mut last = [0.0f64; 3];
    while !b.done() && *budget > 0 {
        let op = b.u8();
        let p = match op & 7 {
            0 => {
                if op & 0x80 != 0 {
                    break; // next polygon
                }
                poly.push(Vec::new());
                continue;
            }
            1..=3 => {
                let g = b.u8();
                planar_grid &= op & 0x80 == 0;
                [(g & 15) as f64, (g >> 4) as f64, if op & 0x80 != 0 { (op >> 3 & 3) as f64 } else { 0.0 }]
            }
            4 => {
                planar_grid = false;
                [b.f64(), b.f64(), if op & 0x80 != 0 { b.f64() } else { 0.0 }]
            }
            5 => {
                planar_grid = false;
                let (i, j) = (b.u8(), b.u8());
                [SPECIAL[(i & 15) as usize], SPECIAL[(j & 15) as usize], if op & 0x80 != 0 { SPECIAL[(i >> 4) as usize] } else { 0.0 }]
            }
            6 => {
                planar_grid = false;
                let g = b.u8();
                let s = SCALES[(op >> 3 & 7) as usize];
                [(g & 15) as f64 * s, (g >> 4) as f64 * s, 0.0]
            }
            _ => {
                // Near-duplicate of the last vertex: a few ulps or 2^-k away.
                planar_grid = false;
                let k = b.u8();
                let d = |x: f64, s: u8| if s & 1 == 0 { x + x.abs().max(1.0) * (2f64).powi(-(s as i32 >> 1) - 10) } else { f64::from_bits(x.to_bits().wrapping_add((s >> 1) as u64)) };
                [d(last[0], k & 0x3f), d(last[1], op >> 3), last[2]]
            }
        };
        last = p;
        poly.last_mut().unwrap().push(p);
        *budget -= 1;
    }
    (poly, planar_grid)
}

fn inside(rule: u32, w: i64) -> bool {
    match rule {
        GLU_TESS_WINDING_ODD => w % 2 != 0,
        GLU_TESS_WINDING_NONZERO => w != 0,
        GLU_TESS_WINDING_POSITIVE => w > 0,
        GLU_TESS_WINDING_NEGATIVE => w < 0,
        _ => w.abs() >= 2,
    }
}

/// The area `rule` selects (windings times `sign`), by vertical slabs
/// between all vertex and crossing abscissae (as tests/tess.rs).
fn rule_area(contours: &Polygon, rule: u32, sign: i64) -> f64 {
    let mut edges = Vec::new();
    for c in contours {
        for i in 0..c.len() {
            let (a, b) = (c[i], c[(i + 1) % c.len()]);
            if a[0] != b[0] {
                edges.push(if a[0] < b[0] { (a, b, sign) } else { (b, a, -sign) });
            }
        }
    }
    let mut xs: Vec<f64> = contours.iter().flatten().map(|v| v[0]).collect();
    let o = |p: [f64; 3], q: [f64; 3], r: [f64; 3]| (q[0] - p[0]) * (r[1] - p[1]) - (q[1] - p[1]) * (r[0] - p[0]);
    for i in 0..edges.len() {
        for j in i + 1..edges.len() {
            let ((a, b, _), (c, d, _)) = (edges[i], edges[j]);
            let (d1, d2, d3, d4) = (o(c, d, a), o(c, d, b), o(a, b, c), o(a, b, d));
            if (d1 > 0.0 && d2 < 0.0 || d1 < 0.0 && d2 > 0.0) && (d3 > 0.0 && d4 < 0.0 || d3 < 0.0 && d4 > 0.0) {
                xs.push(a[0] + d1 / (d1 - d2) * (b[0] - a[0]));
            }
        }
    }
    xs.sort_by(f64::total_cmp);
    xs.dedup();
    let mut area = 0.0;
    for s in xs.windows(2) {
        let (x0, x1) = (s[0], s[1]);
        let xm = 0.5 * (x0 + x1);
        let mut span: Vec<(f64, f64, f64, i64)> = Vec::new();
        for &(a, b, d) in &edges {
            if a[0] <= x0 && b[0] >= x1 {
                let y = |x: f64| a[1] + (b[1] - a[1]) * (x - a[0]) / (b[0] - a[0]);
                span.push((y(xm), y(x0), y(x1), d));
            }
        }
        span.sort_by(|p, q| p.0.total_cmp(&q.0));
        let mut w = 0;
        for k in 0..span.len() {
            w += span[k].3;
            if k + 1 < span.len() && inside(rule, w) {
                area += (x1 - x0) * ((span[k + 1].1 + span[k + 1].2) - (span[k].1 + span[k].2)) * 0.5;
            }
        }
    }
    area
}

/// The output triangles (`out`, in threes) cover the area the rule selects
/// and all turn one way: counter-clockwise about +z, or with the automatic
/// normal, the way that makes the polygon's signed area positive.
fn check_coverage(poly: &Polygon, rule: u32, auto_normal: bool, out: &[[f64; 3]]) {
    let signed: f64 = poly.iter().map(|c| (0..c.len()).map(|i| o2(c[i], c[(i + 1) % c.len()])).sum::<f64>()).sum();
    if auto_normal && signed == 0.0 {
        return; // the orientation is the fallback normal's: not checked
    }
    let sign = if auto_normal && signed < 0.0 { -1.0 } else { 1.0 };
    let mut area = 0.0;
    for t in out.chunks(3) {
        let a = 0.5 * sign * ((t[1][0] - t[0][0]) * (t[2][1] - t[0][1]) - (t[1][1] - t[0][1]) * (t[2][0] - t[0][0]));
        assert!(a >= -1e-9, "triangle {t:?} turns the wrong way (area {a})");
        area += a;
    }
    let want = rule_area(poly, rule, sign as i64);
    assert!((area - want).abs() <= 1e-9 * want.max(1.0), "covered area {area}, the rule selects {want} (rule {rule}, polygon {poly:?})");
}

/// The output triangles form a conforming mesh: an edge off the region's
/// boundary (flag off) is shared with exactly one other triangle, the other
/// way round; a boundary edge (flag on) with none, and no output vertex
/// lies within 2^-46 of the extent of its interior (T-junctions at the
/// merge distance's scale, which the coverage check cannot see).
fn check_conforming(out: &[[f64; 3]], flags: &[bool]) {
    let key = |p: [f64; 3]| (p[0].to_bits(), p[1].to_bits());
    let mut count: std::collections::HashMap<((u64, u64), (u64, u64)), usize> = Default::default();
    for t in out.chunks(3) {
        for i in 0..3 {
            *count.entry((key(t[i]), key(t[(i + 1) % 3]))).or_default() += 1;
        }
    }
    let ext = out.iter().map(|v| v[0].abs().max(v[1].abs())).fold(1.0, f64::max);
    let tol = ext / (1u64 << 46) as f64;
    let mut pts: Vec<[f64; 3]> = out.to_vec();
    pts.sort_by(|a, b| a[0].total_cmp(&b[0]).then(a[1].total_cmp(&b[1])));
    pts.dedup_by(|a, b| key(*a) == key(*b));
    for (k, t) in out.chunks(3).enumerate() {
        for i in 0..3 {
            let (a, b, flag) = (t[i], t[(i + 1) % 3], flags[3 * k + i]);
            assert_ne!(key(a), key(b), "triangle with a repeated vertex {t:?}");
            let fwd = count[&(key(a), key(b))];
            let rev = count.get(&(key(b), key(a))).copied().unwrap_or(0);
            if flag {
                assert_eq!((fwd, rev), (1, 0), "boundary edge {a:?}-{b:?} used {fwd} times, reversed {rev} times");
                let (dx, dy) = (b[0] - a[0], b[1] - a[1]);
                let l2 = dx * dx + dy * dy;
                for &p in &pts {
                    if key(p) == key(a) || key(p) == key(b) {
                        continue;
                    }
                    let s = (((p[0] - a[0]) * dx + (p[1] - a[1]) * dy) / l2).clamp(0.0, 1.0);
                    let d = (a[0] + s * dx - p[0]).hypot(a[1] + s * dy - p[1]);
                    assert!(d > tol, "vertex {p:?} at {d:e} from boundary edge {a:?}-{b:?} (T-junction)");
                }
            } else {
                assert_eq!((fwd, rev), (1, 1), "interior edge {a:?}-{b:?} used {fwd} times, reversed {rev} times (T-junction)");
            }
        }
    }
}

/// Twice the signed area contribution of edge a→b (shoelace).
fn o2(a: [f64; 3], b: [f64; 3]) -> f64 {
    a[0] * b[1] - a[1] * b[0]
}

fn clamp_coord(x: f64) -> f64 {
    if x.is_nan() {
        0.0
    } else {
        x.clamp(-GLU_TESS_MAX_COORD, GLU_TESS_MAX_COORD)
    }
}

fuzz_target!(|data: &[u8]| {
    let mut b = Bytes(data);
    let (f0, f1) = (b.u8(), b.u8());
    let data_forms = f0 & 0x40 != 0;
    let flags_cb = f0 & 0x10 != 0;
    let combine_cb = f0 & 0x20 != 0;
    let sloppy = f1 & 2 != 0;
    let normal = if f0 & 0x80 != 0 { Some([SPECIAL[(f1 >> 4) as usize], b.f64(), SPECIAL[(f1 >> 2 & 3) as usize]]) } else { None };
    let mut budget = MAX_VERTS;
    let mut polys = Vec::new();
    while polys.len() < 3 && (polys.is_empty() || !b.done()) {
        polys.push(decode_polygon(&mut b, &mut budget));
    }
    let pd = 0x5eed as *mut c_void;
    unsafe {
        let t = gluNewTess();
        if data_forms {
            gluTessCallback(t, GLU_TESS_BEGIN_DATA, proc_of(cb_begin_data as extern "system" fn(u32, *mut c_void)));
            gluTessCallback(t, GLU_TESS_VERTEX_DATA, proc_of(cb_vertex_data as extern "system" fn(*mut c_void, *mut c_void)));
            gluTessCallback(t, GLU_TESS_END_DATA, proc_of(cb_end_data as extern "system" fn(*mut c_void)));
            gluTessCallback(t, GLU_TESS_ERROR_DATA, proc_of(cb_error_data as extern "system" fn(u32, *mut c_void)));
            if flags_cb {
                gluTessCallback(t, GLU_TESS_EDGE_FLAG_DATA, proc_of(cb_flag_data as extern "system" fn(u8, *mut c_void)));
            }
            if combine_cb {
                gluTessCallback(t, GLU_TESS_COMBINE_DATA, proc_of(cb_combine_data as extern "system" fn(*const f64, *const *mut c_void, *const f32, *mut *mut c_void, *mut c_void)));
            }
        } else {
            gluTessCallback(t, GLU_TESS_BEGIN, proc_of(cb_begin as extern "system" fn(u32)));
            gluTessCallback(t, GLU_TESS_VERTEX, proc_of(cb_vertex as extern "system" fn(*mut c_void)));
            gluTessCallback(t, GLU_TESS_END, proc_of(cb_end as extern "system" fn()));
            gluTessCallback(t, GLU_TESS_ERROR, proc_of(cb_error as extern "system" fn(u32)));
            if flags_cb {
                gluTessCallback(t, GLU_TESS_EDGE_FLAG, proc_of(cb_flag as extern "system" fn(u8)));
            }
            if combine_cb {
                gluTessCallback(t, GLU_TESS_COMBINE, proc_of(cb_combine as extern "system" fn(*const f64, *const *mut c_void, *const f32, *mut *mut c_void)));
            }
        }
        if let Some(n) = normal {
            gluTessNormal(t, n[0], n[1], n[2]);
        }
        for (k, (poly, planar_grid)) in polys.iter().enumerate() {
            // Each polygon may change the rule and boundary mode of the same object.
            let opt = if k == 0 { f0 } else { f0.rotate_left(k as u32 * 3) ^ f1 };
            let boundary = opt & 8 != 0;
            let rule = RULES[(opt & 7) as usize % 5];
            gluTessProperty(t, GLU_TESS_WINDING_RULE, RULES[(opt & 7) as usize % 5] as f64);
            gluTessProperty(t, GLU_TESS_BOUNDARY_ONLY, boundary as u8 as f64);
            let mut store: Polygon = poly.clone();
            let mut too_large = false;
            let (mut lo, mut hi) = ([f64::INFINITY; 3], [f64::NEG_INFINITY; 3]);
            let mut known = HashSet::new();
            for v in store.iter_mut().flatten() {
                for i in 0..3 {
                    too_large |= v[i].is_nan() || v[i].abs() > GLU_TESS_MAX_COORD;
                    let x = clamp_coord(v[i]);
                    lo[i] = lo[i].min(x);
                    hi[i] = hi[i].max(x);
                }
                known.insert(v as *mut [f64; 3] as usize);
            }
            let fail_at = if f1 & 1 != 0 { Some(1 + (f1 >> 5) as usize) } else { None };
            with(|c| *c = Check { known, boundary, flags_cb, combine_fail_at: fail_at, lo, hi, ..Default::default() });
            gluTessBeginPolygon(t, pd);
            for (ci, c) in store.iter_mut().enumerate() {
                if !(sloppy && ci % 2 == 1) {
                    gluTessBeginContour(t);
                }
                for v in c.iter_mut() {
                    gluTessVertex(t, v.as_mut_ptr(), v as *mut [f64; 3] as *mut c_void);
                }
                if !(sloppy && ci % 3 == 2) {
                    gluTessEndContour(t);
                }
            }
            gluTessEndPolygon(t);
            // Exact coverage on grid polygons in the plane z = 0 (small
            // enough for the quadratic reference): the output's area and
            // orientation against an independent winding computation.
            let nv: usize = store.iter().map(|c| c.len()).sum();
            let z_normal = normal.map_or(true, |n| n[0] == 0.0 && n[1] == 0.0 && n[2] > 0.0 && n[2].is_finite());
            // (TESS_FUZZ_NO_COVERAGE=1 turns it off: docs/glu-fuzz.md, planted bugs.)
            let coverage = std::env::var_os("TESS_FUZZ_NO_COVERAGE").is_none();
            if coverage && *planar_grid && !boundary && !sloppy && combine_cb && fail_at.is_none() && z_normal && nv <= 64 {
                with(|c| check_coverage(&store, rule, normal.is_none(), &c.out));
                if flags_cb {
                    with(|c| check_conforming(&c.out, &c.out_flags));
                }
            }
            with(|c| {
                assert!(c.in_prim.is_none(), "BEGIN without END");
                if c.combine_failed || c.errors.contains(&GLU_TESS_NEED_COMBINE_CALLBACK) {
                    assert!(!combine_cb || fail_at.is_some_and(|n| n <= c.combines), "NEED_COMBINE_CALLBACK with a working COMBINE");
                }
                for &e in &c.errors {
                    match e {
                        GLU_TESS_COORD_TOO_LARGE => assert!(too_large, "COORD_TOO_LARGE for in-range input"),
                        GLU_TESS_NEED_COMBINE_CALLBACK => {}
                        GLU_TESS_MISSING_BEGIN_CONTOUR | GLU_TESS_MISSING_END_CONTOUR => assert!(sloppy, "missing-call error {e} for well-formed calls"),
                        _ => panic!("unexpected error {e}"),
                    }
                }
            });
        }
        gluDeleteTess(t);
    }
    with(|c| *c = Check::default());
});
