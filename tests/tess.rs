//! The GLU tessellator through its C entry points: exact coverage against an
//! independent winding computation (slab areas and point samples) for all
//! five winding rules on thousands of random polygons, orientation, edge
//! flags, boundary loops, the error reports, and a stress test over
//! degenerate and hostile input.

use softgl::api::table::*;
use softgl::glu::tess::*;
use std::cell::RefCell;
use std::ffi::c_void;

const RULES: [u32; 5] = [GLU_TESS_WINDING_ODD, GLU_TESS_WINDING_NONZERO, GLU_TESS_WINDING_POSITIVE, GLU_TESS_WINDING_NEGATIVE, GLU_TESS_WINDING_ABS_GEQ_TWO];

fn inside(rule: u32, w: i64) -> bool {
    match rule {
        GLU_TESS_WINDING_ODD => w % 2 != 0,
        GLU_TESS_WINDING_NONZERO => w != 0,
        GLU_TESS_WINDING_POSITIVE => w > 0,
        GLU_TESS_WINDING_NEGATIVE => w < 0,
        _ => w.abs() >= 2,
    }
}

/// What the callbacks saw.
#[derive(Default)]
struct Out {
    begins: Vec<u32>,
    ends: usize,
    /// Vertices per primitive: (x, y, z, edge flag in force).
    prims: Vec<Vec<([f64; 3], bool)>>,
    errors: Vec<u32>,
    combines: usize,
    combine_out_was_null: bool,
    flag: bool,
    /// Storage for combined vertices (stable addresses).
    arena: Vec<Box<[f64; 3]>>,
}

thread_local! {
    static OUT: RefCell<Out> = RefCell::new(Out::default());
}

extern "system" fn cb_begin(mode: u32) {
    OUT.with(|o| {
        let mut o = o.borrow_mut();
        o.begins.push(mode);
        o.prims.push(Vec::new());
    });
}
extern "system" fn cb_vertex(d: *mut c_void) {
    let p = unsafe { *(d as *const [f64; 3]) };
    OUT.with(|o| {
        let mut o = o.borrow_mut();
        let f = o.flag;
        if let Some(l) = o.prims.last_mut() {
            l.push((p, f));
        }
    });
}
extern "system" fn cb_end() {
    OUT.with(|o| o.borrow_mut().ends += 1);
}
extern "system" fn cb_error(e: u32) {
    OUT.with(|o| o.borrow_mut().errors.push(e));
}
extern "system" fn cb_flag(f: u8) {
    OUT.with(|o| o.borrow_mut().flag = f != 0);
}
extern "system" fn cb_combine(c: *const f64, _d: *const *mut c_void, _w: *const f32, out: *mut *mut c_void) {
    unsafe {
        let p = Box::new([*c, *c.add(1), *c.add(2)]);
        OUT.with(|o| {
            let mut o = o.borrow_mut();
            o.combines += 1;
            if !(*out).is_null() {
                o.combine_out_was_null = false;
            }
            let ptr = &*p as *const [f64; 3] as *mut c_void;
            o.arena.push(p);
            *out = ptr;
        });
    }
}

fn proc_of<T>(f: T) -> Option<unsafe extern "system" fn()> {
    assert_eq!(std::mem::size_of::<T>(), std::mem::size_of::<usize>());
    Some(unsafe { std::mem::transmute_copy::<T, unsafe extern "system" fn()>(&f) })
}

struct Opts {
    rule: u32,
    flags: bool,
    combine: bool,
    boundary: bool,
    normal: Option<[f64; 3]>,
}

/// Tessellates `contours` and returns what the callbacks saw.
fn tess(contours: &[Vec<[f64; 3]>], o: &Opts) -> Out {
    tess_calls(contours, o, |_| true, |_| true)
}

/// [`tess`], calling gluTessBeginContour / gluTessEndContour only for the
/// contours `begin` / `end` pick (the fuzz target's "sloppy" calls).
fn tess_calls(contours: &[Vec<[f64; 3]>], o: &Opts, begin: impl Fn(usize) -> bool, end: impl Fn(usize) -> bool) -> Out {
    OUT.with(|x| *x.borrow_mut() = Out { combine_out_was_null: true, ..Default::default() });
    unsafe {
        let t = gluNewTess();
        gluTessCallback(t, GLU_TESS_BEGIN, proc_of(cb_begin as extern "system" fn(u32)));
        gluTessCallback(t, GLU_TESS_VERTEX, proc_of(cb_vertex as extern "system" fn(*mut c_void)));
        gluTessCallback(t, GLU_TESS_END, proc_of(cb_end as extern "system" fn()));
        gluTessCallback(t, GLU_TESS_ERROR, proc_of(cb_error as extern "system" fn(u32)));
        if o.flags {
            gluTessCallback(t, GLU_TESS_EDGE_FLAG, proc_of(cb_flag as extern "system" fn(u8)));
        }
        if o.combine {
            gluTessCallback(t, GLU_TESS_COMBINE, proc_of(cb_combine as extern "system" fn(*const f64, *const *mut c_void, *const f32, *mut *mut c_void)));
        }
        gluTessProperty(t, GLU_TESS_WINDING_RULE, o.rule as f64);
        gluTessProperty(t, GLU_TESS_BOUNDARY_ONLY, o.boundary as u8 as f64);
        if let Some(n) = o.normal {
            gluTessNormal(t, n[0], n[1], n[2]);
        }
        let mut store: Vec<Vec<[f64; 3]>> = contours.to_vec();
        gluTessBeginPolygon(t, std::ptr::null_mut());
        for (ci, c) in store.iter_mut().enumerate() {
            if begin(ci) {
                gluTessBeginContour(t);
            }
            for v in c.iter_mut() {
                gluTessVertex(t, v.as_mut_ptr(), v as *mut [f64; 3] as *mut c_void);
            }
            if end(ci) {
                gluTessEndContour(t);
            }
        }
        gluTessEndPolygon(t);
        gluDeleteTess(t);
    }
    OUT.with(|x| std::mem::take(&mut *x.borrow_mut()))
}

/// Winding number of p (2D) with respect to the contours: signed crossings
/// of the downward ray (edges going +x count +1).
fn winding(contours: &[Vec<[f64; 3]>], p: [f64; 2]) -> i64 {
    let mut w = 0;
    for c in contours {
        for i in 0..c.len() {
            let a = c[i];
            let b = c[(i + 1) % c.len()];
            let (l, r, s) = if a[0] < b[0] { (a, b, 1) } else { (b, a, -1) };
            if l[0] <= p[0] && p[0] < r[0] {
                let y = l[1] + (r[1] - l[1]) * (p[0] - l[0]) / (r[0] - l[0]);
                if y < p[1] {
                    w += s;
                }
            }
        }
    }
    w
}

/// Exact-ish area of the region selected by `rule`, by vertical slabs
/// between all vertex and crossing abscissae.
fn rule_area(contours: &[Vec<[f64; 3]>], rule: u32) -> f64 {
    let mut edges = Vec::new();
    for c in contours {
        for i in 0..c.len() {
            let a = c[i];
            let b = c[(i + 1) % c.len()];
            if a[0] != b[0] {
                edges.push(if a[0] < b[0] { (a, b, 1i64) } else { (b, a, -1) });
            }
        }
    }
    let mut xs: Vec<f64> = contours.iter().flatten().map(|v| v[0]).collect();
    for i in 0..edges.len() {
        for j in i + 1..edges.len() {
            let (a, b, _) = edges[i];
            let (c, d, _) = edges[j];
            let o = |p: [f64; 3], q: [f64; 3], r: [f64; 3]| (q[0] - p[0]) * (r[1] - p[1]) - (q[1] - p[1]) * (r[0] - p[0]);
            let (d1, d2) = (o(c, d, a), o(c, d, b));
            let (d3, d4) = (o(a, b, c), o(a, b, d));
            if (d1 > 0.0 && d2 < 0.0 || d1 < 0.0 && d2 > 0.0) && (d3 > 0.0 && d4 < 0.0 || d3 < 0.0 && d4 > 0.0) {
                let t = d1 / (d1 - d2);
                xs.push(a[0] + t * (b[0] - a[0]));
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

fn tri_area(t: &[([f64; 3], bool)]) -> f64 {
    let (a, b, c) = (t[0].0, t[1].0, t[2].0);
    0.5 * ((b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0]))
}

/// Distance from p to segment ab.
fn seg_dist(p: [f64; 2], a: [f64; 3], b: [f64; 3]) -> f64 {
    let (dx, dy) = (b[0] - a[0], b[1] - a[1]);
    let l2 = dx * dx + dy * dy;
    let t = if l2 > 0.0 { (((p[0] - a[0]) * dx + (p[1] - a[1]) * dy) / l2).clamp(0.0, 1.0) } else { 0.0 };
    ((a[0] + t * dx - p[0]).powi(2) + (a[1] + t * dy - p[1]).powi(2)).sqrt()
}

struct Rng(u64);
impl Rng {
    fn next(&mut self) -> u64 {
        self.0 ^= self.0 << 13;
        self.0 ^= self.0 >> 7;
        self.0 ^= self.0 << 17;
        self.0
    }
    fn below(&mut self, n: u64) -> u64 {
        self.next() % n
    }
    fn f(&mut self) -> f64 {
        (self.next() >> 11) as f64 / (1u64 << 53) as f64
    }
}

/// A random polygon family member.
fn random_polygon(r: &mut Rng, family: u64) -> Vec<Vec<[f64; 3]>> {
    let mut cs = Vec::new();
    match family {
        // Self-intersecting, on a small integer grid: duplicates, collinear runs, touching.
        0 => {
            for _ in 0..1 + r.below(3) {
                let n = 3 + r.below(9);
                cs.push((0..n).map(|_| [r.below(8) as f64, r.below(8) as f64, 0.0]).collect());
            }
        }
        // Random real coordinates.
        1 => {
            for _ in 0..1 + r.below(2) {
                let n = 3 + r.below(12);
                cs.push((0..n).map(|_| [r.f() * 10.0, r.f() * 10.0, 0.0]).collect());
            }
        }
        // Simple star-shaped polygons with star-shaped holes (either orientation).
        2 => {
            let star = |r: &mut Rng, cx: f64, cy: f64, rad: f64, rev: bool| {
                let n = 3 + r.below(12) as usize;
                let mut v: Vec<[f64; 3]> = (0..n)
                    .map(|i| {
                        let a = i as f64 / n as f64 * std::f64::consts::TAU;
                        let rr = rad * (0.5 + 0.5 * r.f());
                        [cx + rr * a.cos(), cy + rr * a.sin(), 0.0]
                    })
                    .collect();
                if rev {
                    v.reverse();
                }
                v
            };
            cs.push(star(r, 0.0, 0.0, 10.0, false));
            for _ in 0..r.below(3) {
                let rev = r.below(2) == 0;
                let (cx, cy) = (r.f() * 6.0 - 3.0, r.f() * 6.0 - 3.0);
                cs.push(star(r, cx, cy, 3.0, rev));
            }
        }
        // Many crossings: 20 to 60 random vertices.
        4 => {
            let n = 20 + r.below(41);
            cs.push((0..n).map(|_| [r.f() * 10.0, r.f() * 10.0, 0.0]).collect());
        }
        // Near-degenerate: grid points nudged by up to 1e-9, nearly parallel edges.
        5 => {
            for _ in 0..1 + r.below(3) {
                let n = 3 + r.below(8);
                cs.push((0..n).map(|_| [r.below(5) as f64 + (r.f() - 0.5) * 1e-9, r.below(5) as f64 + (r.f() - 0.5) * 1e-9, 0.0]).collect());
            }
        }
        // Axis-aligned rectangles on a grid: coincident and overlapping edges.
        _ => {
            for _ in 0..1 + r.below(4) {
                let (x0, y0) = (r.below(6) as f64, r.below(6) as f64);
                let (x1, y1) = (x0 + 1.0 + r.below(4) as f64, y0 + 1.0 + r.below(4) as f64);
                let mut v = vec![[x0, y0, 0.0], [x1, y0, 0.0], [x1, y1, 0.0], [x0, y1, 0.0]];
                if r.below(2) == 0 {
                    v.reverse();
                }
                cs.push(v);
            }
        }
    }
    cs
}

fn check_coverage(cs: &[Vec<[f64; 3]>], rule: u32, r: &mut Rng, flags: bool, what: &str) {
    let out = tess(cs, &Opts { rule, flags, combine: true, boundary: false, normal: Some([0.0, 0.0, 1.0]) });
    assert!(out.errors.is_empty(), "{what}: errors {:?}", out.errors);
    assert_eq!(out.begins.len(), out.ends, "{what}");
    let mut tris = Vec::new();
    for (m, p) in out.begins.iter().zip(&out.prims) {
        assert_eq!(*m, 0x0004, "{what}: GL_TRIANGLES only");
        assert_eq!(p.len() % 3, 0, "{what}");
        tris.extend(p.chunks(3).map(|c| c.to_vec()));
    }
    // Orientation: counter-clockwise about the given normal.
    let scale = cs.iter().flatten().map(|v| v[0].abs().max(v[1].abs())).fold(1.0, f64::max).powi(2);
    let mut area = 0.0;
    for t in &tris {
        let a = tri_area(t);
        assert!(a >= -1e-12 * scale, "{what}: clockwise triangle {t:?}");
        area += a;
    }
    let want = rule_area(cs, rule);
    assert!((area - want).abs() <= 1e-9 * scale, "{what}: area {area} want {want} (contours {cs:?})");
    // Point samples: covered exactly once inside, never outside.
    let (mut lo, mut hi) = ([f64::MAX; 2], [f64::MIN; 2]);
    for v in cs.iter().flatten() {
        for i in 0..2 {
            lo[i] = lo[i].min(v[i]);
            hi[i] = hi[i].max(v[i]);
        }
    }
    for _ in 0..40 {
        let p = [lo[0] + (hi[0] - lo[0]) * r.f(), lo[1] + (hi[1] - lo[1]) * r.f()];
        let near_input = cs.iter().any(|c| (0..c.len()).any(|i| seg_dist(p, c[i], c[(i + 1) % c.len()]) < 1e-7));
        let near_tri = tris.iter().any(|t| (0..3).any(|i| seg_dist(p, t[i].0, t[(i + 1) % 3].0) < 1e-7));
        if near_input || near_tri {
            continue;
        }
        let cover = tris
            .iter()
            .filter(|t| {
                let (a, b, c) = (t[0].0, t[1].0, t[2].0);
                let o = |p1: [f64; 3], p2: [f64; 3]| (p2[0] - p1[0]) * (p[1] - p1[1]) - (p2[1] - p1[1]) * (p[0] - p1[0]);
                o(a, b) > 0.0 && o(b, c) > 0.0 && o(c, a) > 0.0
            })
            .count();
        let ins = inside(rule, winding(cs, p));
        assert_eq!(cover, ins as usize, "{what}: point {p:?} covered {cover} times, inside={ins} (contours {cs:?})");
    }
    // Edge flags: flagged edges separate inside from outside, others don't.
    if flags {
        for t in &tris {
            if tri_area(t) < 1e-6 {
                continue;
            }
            for i in 0..3 {
                let (a, b, f) = (t[i].0, t[(i + 1) % 3].0, t[i].1);
                let (dx, dy) = (b[0] - a[0], b[1] - a[1]);
                let l = (dx * dx + dy * dy).sqrt();
                let m = [0.5 * (a[0] + b[0]), 0.5 * (a[1] + b[1])];
                // Probe at half the clearance to the nearest other input edge.
                let clear = cs
                    .iter()
                    .flat_map(|c| (0..c.len()).map(move |i| (c[i], c[(i + 1) % c.len()])))
                    .map(|(p, q)| seg_dist(m, p, q))
                    .filter(|&d| d > 1e-11)
                    .fold(f64::INFINITY, f64::min);
                // Skip edges crossed at their midpoint by another input edge
                // (cancelling overlaps leave such edges inside the region).
                let crossed = cs.iter().flat_map(|c| (0..c.len()).map(move |i| (c[i], c[(i + 1) % c.len()]))).any(|(p, q)| {
                    let par = ((q[0] - p[0]) * dy - (q[1] - p[1]) * dx).abs() <= 1e-12 * l * ((q[0] - p[0]).hypot(q[1] - p[1]));
                    !par && seg_dist(m, p, q) < 1e-9
                });
                if clear < 1e-9 || crossed {
                    continue;
                }
                let h = (0.5 * clear).min(1e-4);
                let right = [m[0] + dy / l * h, m[1] - dx / l * h];
                let left = [m[0] - dy / l * h, m[1] + dx / l * h];
                let near = cs.iter().flatten().any(|v| ((v[0] - m[0]).powi(2) + (v[1] - m[1]).powi(2)).sqrt() < 1e-5);
                if near {
                    continue;
                }
                let (li, ri) = (inside(rule, winding(cs, left)), inside(rule, winding(cs, right)));
                if li == ri && li {
                    assert!(!f, "{what}: interior edge {a:?}-{b:?} flagged");
                } else if li && !ri {
                    // Unless a zero-area triangle (collinear vertices) shares the edge.
                    let key = |p: [f64; 3]| (p[0].to_bits(), p[1].to_bits());
                    let shared = tris.iter().any(|u| {
                        tri_area(u).abs() < 1e-9 && (0..3).any(|j| key(u[j].0) == key(b) && key(u[(j + 1) % 3].0) == key(a))
                    });
                    if !(f || shared) {
                        let touching: Vec<_> = tris.iter().filter(|u| u.iter().any(|v| key(v.0) == key(a) || key(v.0) == key(b))).collect();
                        panic!("{what}: boundary edge {a:?}-{b:?} not flagged; left {:?} right {:?}; triangles at its ends {touching:?} CONTOURS {cs:?}", winding(cs, left), winding(cs, right));
                    }
                }
            }
        }
    }
}

#[test]
fn exact_coverage_random_polygons() {
    // TESS_SEED / TESS_POLYGONS run a longer search (e.g. 200000 polygons).
    let env = |k: &str, d: u64| std::env::var(k).ok().and_then(|v| v.parse().ok()).unwrap_or(d);
    let mut r = Rng(env("TESS_SEED", 0x9e3779b97f4a7c15) | 1);
    let mut n = 0;
    for i in 0..env("TESS_POLYGONS", 2400) {
        let family = i % 6;
        let cs = random_polygon(&mut r, family);
        for &rule in &RULES {
            check_coverage(&cs, rule, &mut r, i % 2 == 0, &format!("polygon {i} family {family} rule {rule}"));
            n += 1;
        }
    }
    assert!(n >= 10000);
}

#[test]
fn book_shapes() {
    // Star with a square hole (ODD): star area minus hole.
    let star: Vec<[f64; 3]> = (0..5).map(|i| {
        let a = std::f64::consts::FRAC_PI_2 + i as f64 * 4.0 * std::f64::consts::PI / 5.0;
        [10.0 * a.cos(), 10.0 * a.sin(), 0.0]
    }).collect();
    let hole = vec![[-1.0, -1.0, 0.0], [1.0, -1.0, 0.0], [1.0, 1.0, 0.0], [-1.0, 1.0, 0.0]];
    let mut r = Rng(1);
    for &rule in &RULES {
        check_coverage(&[star.clone(), hole.clone()], rule, &mut r, true, "star+hole");
    }
    // Bow-tie: one crossing, COMBINE called once.
    let bow = vec![vec![[0.0, 0.0, 0.0], [4.0, 4.0, 0.0], [4.0, 0.0, 0.0], [0.0, 4.0, 0.0]]];
    let out = tess(&bow, &Opts { rule: GLU_TESS_WINDING_NONZERO, flags: false, combine: true, boundary: false, normal: None });
    assert_eq!(out.combines, 1);
    assert!(out.combine_out_was_null, "*outData must be NULL before COMBINE");
    let area: f64 = out.prims.iter().flat_map(|p| p.chunks(3)).map(|t| tri_area(t).abs()).sum();
    assert!((area - 8.0).abs() < 1e-12, "{area}");
    // Without COMBINE: NEED_COMBINE_CALLBACK, no output.
    let out = tess(&bow, &Opts { rule: GLU_TESS_WINDING_NONZERO, flags: false, combine: false, boundary: false, normal: None });
    assert_eq!(out.errors, vec![GLU_TESS_NEED_COMBINE_CALLBACK]);
}

#[test]
fn orientation_follows_normal() {
    let sq = vec![vec![[0.0, 0.0, 0.0], [1.0, 0.0, 0.0], [1.0, 1.0, 0.0], [0.0, 1.0, 0.0]]];
    let cw: Vec<Vec<[f64; 3]>> = vec![sq[0].iter().rev().copied().collect()];
    for (cs, n, sign) in [(&sq, None, 1.0), (&cw, None, -1.0), (&sq, Some([0.0, 0.0, -1.0]), -1.0), (&cw, Some([0.0, 0.0, 1.0]), 1.0)] {
        // CW input with the normal +z: winding -1, selected by NONZERO.
        let out = tess(cs, &Opts { rule: GLU_TESS_WINDING_NONZERO, flags: false, combine: true, boundary: false, normal: n });
        let tris: Vec<_> = out.prims.iter().flat_map(|p| p.chunks(3)).collect();
        assert_eq!(tris.len(), 2);
        for t in tris {
            assert!(tri_area(t) * sign > 0.0, "{n:?} {t:?}");
        }
    }
    // A huge or tiny user normal works like a unit one.
    for n in [[0.0, 0.0, 1e300], [1e-300, 0.0, 1e-300]] {
        let out = tess(&sq, &Opts { rule: GLU_TESS_WINDING_NONZERO, flags: false, combine: true, boundary: false, normal: Some(n) });
        assert_eq!(out.prims.iter().map(|p| p.len()).sum::<usize>(), 6, "{n:?}");
    }
    // A tilted plane: vertices come back untouched.
    let tilted = vec![vec![[0.0, 0.0, 0.0], [1.0, 0.0, 1.0], [1.0, 1.0, 1.0], [0.0, 1.0, 0.0]]];
    let out = tess(&tilted, &Opts { rule: GLU_TESS_WINDING_ODD, flags: false, combine: true, boundary: false, normal: None });
    assert_eq!(out.prims.iter().map(|p| p.len()).sum::<usize>(), 6);
}

#[test]
fn boundary_only_loops() {
    // Square with a hole, ODD: two loops, outer CCW, inner CW.
    let cs = vec![
        vec![[0.0, 0.0, 0.0], [4.0, 0.0, 0.0], [4.0, 4.0, 0.0], [0.0, 4.0, 0.0]],
        vec![[1.0, 1.0, 0.0], [3.0, 1.0, 0.0], [3.0, 3.0, 0.0], [1.0, 3.0, 0.0]],
    ];
    let out = tess(&cs, &Opts { rule: GLU_TESS_WINDING_ODD, flags: false, combine: true, boundary: true, normal: Some([0.0, 0.0, 1.0]) });
    assert_eq!(out.begins, vec![2, 2]);
    let mut areas: Vec<f64> = out
        .prims
        .iter()
        .map(|l| (0..l.len()).map(|i| { let (a, b) = (l[i].0, l[(i + 1) % l.len()].0); 0.5 * (a[0] * b[1] - a[1] * b[0]) }).sum())
        .collect();
    areas.sort_by(f64::total_cmp);
    assert_eq!(areas, vec![-4.0, 16.0]);
}

#[test]
fn properties_callbacks_and_errors() {
    unsafe {
        let t = gluNewTess();
        OUT.with(|x| *x.borrow_mut() = Out::default());
        gluTessCallback(t, GLU_TESS_ERROR, proc_of(cb_error as extern "system" fn(u32)));
        let mut v = 0.0;
        gluGetTessProperty(t, GLU_TESS_WINDING_RULE, &mut v);
        assert_eq!(v, GLU_TESS_WINDING_ODD as f64);
        gluTessProperty(t, GLU_TESS_WINDING_RULE, GLU_TESS_WINDING_POSITIVE as f64);
        // Borland units pass 100110 (GLU_TESS_EDGE_FLAG_DATA) as the property.
        gluTessProperty(t, 100110, GLU_TESS_WINDING_NONZERO as f64);
        gluTessProperty(t, GLU_TESS_WINDING_RULE, 12345.0);
        gluTessProperty(t, GLU_TESS_TOLERANCE, 2.0);
        gluGetTessProperty(t, GLU_TESS_WINDING_RULE, &mut v);
        assert_eq!(v, GLU_TESS_WINDING_POSITIVE as f64);
        gluTessCallback(t, 7, None);
        gluGetTessProperty(t, 1, &mut v);
        let errs = OUT.with(|x| std::mem::take(&mut x.borrow_mut().errors));
        assert_eq!(errs, vec![100900, 100901, 100901, 100900, 100900]);
        // Missing calls.
        gluTessBeginContour(t); // missing begin polygon
        gluTessBeginPolygon(t, std::ptr::null_mut()); // missing end contour, missing end polygon
        let mut p = [0.0f64; 3];
        gluTessVertex(t, p.as_mut_ptr(), std::ptr::null_mut()); // missing begin contour
        gluTessEndPolygon(t); // missing end contour
        gluTessEndContour(t); // missing begin polygon, begin contour
        gluTessEndPolygon(t);
        let errs = OUT.with(|x| std::mem::take(&mut x.borrow_mut().errors));
        assert_eq!(errs, vec![100151, 100154, 100153, 100152, 100154, 100151, 100152]);
        // Coordinates: NaN, inf, huge.
        gluTessBeginPolygon(t, std::ptr::null_mut());
        gluTessBeginContour(t);
        for q in [[f64::NAN, 0.0, 0.0], [f64::INFINITY, 0.0, 0.0], [1e200, 1.0, 0.0], [0.0, 1.0, 0.0]] {
            let mut q = q;
            gluTessVertex(t, q.as_mut_ptr(), std::ptr::null_mut());
        }
        gluTessEndContour(t);
        // A NULL callback unsets: no more reports.
        gluTessCallback(t, GLU_TESS_ERROR, None);
        gluTessEndPolygon(t);
        gluTessEndPolygon(t);
        let errs = OUT.with(|x| std::mem::take(&mut x.borrow_mut().errors));
        assert_eq!(errs, vec![100155, 100155, 100155]);
        gluDeleteTess(t);
        // GLU 1.1 interface.
        let t = gluNewTess();
        OUT.with(|x| *x.borrow_mut() = Out::default());
        gluTessCallback(t, GLU_TESS_BEGIN, proc_of(cb_begin as extern "system" fn(u32)));
        gluTessCallback(t, GLU_TESS_VERTEX, proc_of(cb_vertex as extern "system" fn(*mut c_void)));
        let mut pts = [[0.0, 0.0, 0.0], [4.0, 0.0, 0.0], [4.0, 4.0, 0.0], [0.0, 4.0, 0.0], [1.0, 1.0, 0.0], [3.0, 1.0, 0.0], [3.0, 3.0, 0.0], [1.0, 3.0, 0.0]];
        gluBeginPolygon(t);
        for (i, q) in pts.iter_mut().enumerate() {
            if i == 4 {
                gluNextContour(t, 100122);
            }
            gluTessVertex(t, q.as_mut_ptr(), q as *mut [f64; 3] as *mut c_void);
        }
        gluEndPolygon(t);
        gluDeleteTess(t);
        let out = OUT.with(|x| std::mem::take(&mut *x.borrow_mut()));
        let area: f64 = out.prims.iter().flat_map(|p| p.chunks(3)).map(tri_area).sum();
        assert_eq!(area, 12.0);
        // NULL tessellator pointers are ignored.
        gluTessBeginPolygon(std::ptr::null_mut(), std::ptr::null_mut());
        gluDeleteTess(std::ptr::null_mut());
    }
}

/// Re-entrancy: a callback that calls back into the same tessellator.
extern "system" fn cb_reenter(_mode: u32, data: *mut c_void) {
    unsafe {
        gluTessBeginPolygon(data, std::ptr::null_mut());
        gluTessEndPolygon(data);
        gluDeleteTess(data);
    }
}

#[test]
fn reentrant_callbacks() {
    unsafe {
        let t = gluNewTess();
        gluTessCallback(t, GLU_TESS_BEGIN_DATA, proc_of(cb_reenter as extern "system" fn(u32, *mut c_void)));
        let mut pts = [[0.0, 0.0, 0.0], [1.0, 0.0, 0.0], [0.0, 1.0, 0.0]];
        gluTessBeginPolygon(t, t);
        gluTessBeginContour(t);
        for q in pts.iter_mut() {
            gluTessVertex(t, q.as_mut_ptr(), std::ptr::null_mut());
        }
        gluTessEndContour(t);
        gluTessEndPolygon(t); // the callback's gluDeleteTess frees it afterwards
    }
}

#[test]
fn stress_degenerate_input() {
    let all = |cs: &[Vec<[f64; 3]>], combine: bool| {
        for &rule in &RULES {
            for boundary in [false, true] {
                tess(cs, &Opts { rule, flags: rule == GLU_TESS_WINDING_ODD, combine, boundary, normal: None });
            }
        }
    };
    let mut r = Rng(77);
    // Empty polygon, empty contours, single points, zero-area contours.
    all(&[], true);
    all(&[vec![], vec![]], true);
    all(&[vec![[1.0, 2.0, 3.0]]], true);
    all(&[vec![[0.0; 3], [0.0; 3], [0.0; 3]]], true);
    all(&[vec![[0.0, 0.0, 0.0], [1.0, 1.0, 0.0], [2.0, 2.0, 0.0], [1.0, 1.0, 0.0]]], true);
    // Non-finite and huge coordinates: reported, clamped, terminate.
    let out = tess(&[vec![[f64::NAN, 0.0, 0.0], [1.0, f64::INFINITY, 0.0], [-1e300, 5.0, 0.0], [1.0, 1.0, f64::NEG_INFINITY]]], &Opts { rule: GLU_TESS_WINDING_ODD, flags: false, combine: true, boundary: false, normal: None });
    assert!(out.errors.iter().all(|&e| e == GLU_TESS_COORD_TOO_LARGE) && out.errors.len() == 4, "{:?}", out.errors);
    // Scales 1e150 and 1e-150: same triangles as at scale 1.
    for scale in [1e149, 1e-150, 1e-300] {
        let cs: Vec<Vec<[f64; 3]>> = random_polygon(&mut Rng(5), 1).into_iter().map(|c| c.into_iter().map(|v| [v[0] * scale, v[1] * scale, 0.0]).collect()).collect();
        let out = tess(&cs, &Opts { rule: GLU_TESS_WINDING_ODD, flags: false, combine: true, boundary: false, normal: Some([0.0, 0.0, 1.0]) });
        let area: f64 = out.prims.iter().flat_map(|p| p.chunks(3)).map(tri_area).sum();
        if scale >= 1e-150 {
            let want = rule_area(&cs, GLU_TESS_WINDING_ODD);
            assert!(((area - want) / want).abs() < 1e-9, "scale {scale}: {area} vs {want}");
        }
    }
    // Near-coincident vertices and near-collinear runs.
    for _ in 0..200 {
        let n = 3 + r.below(20);
        let c: Vec<[f64; 3]> = (0..n).map(|_| [(r.below(3) as f64) + r.f() * 1e-13, (r.below(3) as f64) + r.f() * 1e-13, r.f() * 1e-14]).collect();
        all(&[c], true);
    }
    // Thousands of self-intersections.
    let c: Vec<[f64; 3]> = (0..300).map(|_| [r.f(), r.f(), 0.0]).collect();
    let out = tess(&[c.clone()], &Opts { rule: GLU_TESS_WINDING_NONZERO, flags: false, combine: true, boundary: false, normal: None });
    assert!(out.combines > 2000, "{}", out.combines);
    let want = rule_area(&[c.clone()], GLU_TESS_WINDING_NONZERO);
    let area: f64 = out.prims.iter().flat_map(|p| p.chunks(3)).map(|t| tri_area(t).abs()).sum();
    assert!((area - want).abs() < 1e-9, "{area} vs {want}");
    all(&[c], false);
    // Random garbage including non-finite values.
    let vals = [0.0, 1.0, -1.0, f64::NAN, f64::INFINITY, f64::NEG_INFINITY, 1e150, -1e150, 1e-150, f64::MIN_POSITIVE, 0.5];
    for _ in 0..300 {
        let cs: Vec<Vec<[f64; 3]>> = (0..r.below(3)).map(|_| (0..r.below(8)).map(|_| [vals[r.below(11) as usize], vals[r.below(11) as usize], vals[r.below(11) as usize]]).collect()).collect();
        all(&cs, r.below(2) == 0);
    }
}

#[test]
fn big_polygons_are_not_quadratic() {
    // A 100k-vertex flower, and a square with 1000 circular holes of 100 vertices.
    // (Each must take well under the 5 s allowed; they take ~0.1-0.3 s.)
    let n = 100_000;
    let flower: Vec<[f64; 3]> = (0..n)
        .map(|i| {
            let a = i as f64 / n as f64 * std::f64::consts::TAU;
            let rr = 1.0 + 0.3 * (50.0 * a).sin();
            [rr * a.cos(), rr * a.sin(), 0.0]
        })
        .collect();
    let mut holes = vec![vec![[0.0, 0.0, 0.0], [40.0, 0.0, 0.0], [40.0, 25.0, 0.0], [0.0, 25.0, 0.0]]];
    for k in 0..1000 {
        let (cx, cy) = (0.5 + (k % 40) as f64, 0.5 + (k / 40) as f64);
        holes.push((0..100).map(|i| {
            let a = -(i as f64) / 100.0 * std::f64::consts::TAU;
            [cx + 0.4 * a.cos(), cy + 0.4 * a.sin(), 0.0]
        }).collect());
    }
    // A comb of 20000 teeth, and the same turned a quarter.
    let mut comb = vec![[0.0, 0.0, 0.0], [20000.0, 0.0, 0.0]];
    for k in (0..20000).rev() {
        let x = k as f64;
        comb.extend([[x + 0.9, 10.0, 0.0], [x + 0.5, 1.0, 0.0], [x + 0.1, 10.0, 0.0]]);
    }
    let turned: Vec<[f64; 3]> = comb.iter().map(|p| [-p[1], p[0], 0.0]).collect();
    let m = comb.len();
    for (cs, want_tris) in [(vec![flower], n - 2), (holes, 4 + 100 * 1000 + 2 * 1000 - 2), (vec![comb], m - 2), (vec![turned], m - 2)] {
        let t0 = std::time::Instant::now();
        let out = tess(&cs, &Opts { rule: GLU_TESS_WINDING_ODD, flags: false, combine: true, boundary: false, normal: None });
        let ntri: usize = out.prims.iter().map(|p| p.len() / 3).sum();
        assert_eq!(ntri, want_tris);
        let area: f64 = out.prims.iter().flat_map(|p| p.chunks(3)).map(tri_area).sum();
        let want = rule_area_shoelace(&cs);
        assert!((area - want).abs() < 1e-9 * want.abs(), "{area} vs {want}");
        assert!(t0.elapsed().as_secs_f64() < 5.0, "{:?}", t0.elapsed());
    }
}

/// Signed area by the shoelace formula (for simple, properly nested input).
fn rule_area_shoelace(cs: &[Vec<[f64; 3]>]) -> f64 {
    cs.iter().map(|c| (0..c.len()).map(|i| { let (a, b) = (c[i], c[(i + 1) % c.len()]); 0.5 * (a[0] * b[1] - a[1] * b[0]) }).sum::<f64>()).sum()
}

/// GLU 1.3: "If the callback function is NULL, the callback is removed" —
/// for every kind, not only ERROR (Delphi programs reset callbacks with nil).
#[test]
fn null_callback_unsets_vertex_begin_and_combine() {
    let bow = [[0.0, 0.0, 0.0], [4.0, 4.0, 0.0], [4.0, 0.0, 0.0], [0.0, 4.0, 0.0]];
    OUT.with(|x| *x.borrow_mut() = Out::default());
    unsafe {
        let t = gluNewTess();
        gluTessCallback(t, GLU_TESS_BEGIN, proc_of(cb_begin as extern "system" fn(u32)));
        gluTessCallback(t, GLU_TESS_VERTEX, proc_of(cb_vertex as extern "system" fn(*mut c_void)));
        gluTessCallback(t, GLU_TESS_ERROR, proc_of(cb_error as extern "system" fn(u32)));
        gluTessCallback(t, GLU_TESS_COMBINE, proc_of(cb_combine as extern "system" fn(*const f64, *const *mut c_void, *const f32, *mut *mut c_void)));
        let run = |t: *mut c_void| {
            let mut pts = bow;
            gluTessBeginPolygon(t, std::ptr::null_mut());
            gluTessBeginContour(t);
            for q in pts.iter_mut() {
                gluTessVertex(t, q.as_mut_ptr(), q as *mut [f64; 3] as *mut c_void);
            }
            gluTessEndContour(t);
            gluTessEndPolygon(t);
            OUT.with(|x| std::mem::take(&mut *x.borrow_mut()))
        };
        // All set: two triangles through BEGIN and VERTEX, one COMBINE.
        let o = run(t);
        assert_eq!((o.begins.len(), o.prims.iter().map(|p| p.len()).sum::<usize>(), o.combines), (1, 6, 1));
        assert!(o.errors.is_empty());
        // VERTEX unset: BEGIN still comes, no vertices.
        gluTessCallback(t, GLU_TESS_VERTEX, None);
        let o = run(t);
        assert_eq!((o.begins.len(), o.prims.iter().map(|p| p.len()).sum::<usize>()), (1, 0));
        // BEGIN unset too: nothing at all.
        gluTessCallback(t, GLU_TESS_BEGIN, None);
        assert!(run(t).begins.is_empty());
        // COMBINE unset: the crossing needs one.
        gluTessCallback(t, GLU_TESS_COMBINE, None);
        let o = run(t);
        assert_eq!((o.combines, o.errors.clone()), (0, vec![GLU_TESS_NEED_COMBINE_CALLBACK]));
        gluDeleteTess(t);
    }
}

/// Polygons with more than 48 edges take the grid path of the pair search
/// (each edge entered into the cells its segment crosses): the same exact
/// checks on integer-grid polygons (collinear overlaps, vertices on edges,
/// duplicates), long thin spikes, and random real coordinates.
#[test]
fn exact_coverage_grid_path() {
    let mut r = Rng(0x5eed_1234_5678_9abd);
    for i in 0..36 {
        let n = 50 + r.below(70) as usize;
        let cs: Vec<Vec<[f64; 3]>> = match i % 3 {
            0 => vec![(0..n).map(|_| [r.below(12) as f64, r.below(12) as f64, 0.0]).collect()],
            1 => {
                // A star with spikes from radius 0.3 to 1: long nearly radial edges.
                vec![(0..n)
                    .map(|k| {
                        let a = k as f64 / n as f64 * std::f64::consts::TAU;
                        let rr = 0.3 + 0.7 * r.f();
                        [rr * a.cos(), rr * a.sin(), 0.0]
                    })
                    .collect()]
            }
            _ => vec![(0..n).map(|_| [r.f() * 10.0, r.f() * 10.0, 0.0]).collect()],
        };
        assert!(cs[0].len() > 48);
        for &rule in &RULES {
            check_coverage(&cs, rule, &mut r, rule == GLU_TESS_WINDING_ODD, &format!("grid-path polygon {i} rule {rule}"));
        }
    }
}

/// The bench's worst case: a random 100,000-vertex star (radii in [0.3, 1]),
/// where a vertical line crosses tens of thousands of edges, so a flat
/// active list makes the sweep quadratic (4-4.6 s before the blocked list;
/// 0.15-0.6 s after, on the shared 2-core build machine).
#[test]
fn random_star_with_many_active_edges_is_not_quadratic() {
    let mut r = Rng(0x2545_f491_4f6c_dd1d);
    let n = 100_000;
    let star: Vec<[f64; 3]> = (0..n)
        .map(|i| {
            let a = (i as f64 + 0.8 * (r.f() - 0.5)) / n as f64 * std::f64::consts::TAU;
            let rr = 0.3 + 0.7 * r.f();
            [rr * a.cos(), rr * a.sin(), 0.0]
        })
        .collect();
    let cs = vec![star];
    let t0 = std::time::Instant::now();
    let out = tess(&cs, &Opts { rule: GLU_TESS_WINDING_ODD, flags: false, combine: true, boundary: false, normal: None });
    let dt = t0.elapsed().as_secs_f64();
    let ntri: usize = out.prims.iter().map(|p| p.len() / 3).sum();
    assert_eq!(ntri, n - 2);
    let area: f64 = out.prims.iter().flat_map(|p| p.chunks(3)).map(tri_area).sum();
    let want = rule_area_shoelace(&cs);
    assert!((area - want).abs() < 1e-9 * want.abs(), "{area} vs {want}");
    assert!(dt < 3.0, "{dt} s");
}

/// Simple polygons with a vertex close to another edge, at distances
/// either side of the merge distance (2^-42 of the extent): the one-sweep
/// fast path takes the far ones and leaves the near ones to the general
/// path; both must cover exactly, under every rule, with edge flags.
#[test]
fn near_touching_vertices_either_side_of_the_merge_distance() {
    let mut r = Rng(0x5851_f42d_4c95_7f2d);
    for &d in &[1e-3, 1e-8, 1e-11, 1e-12, 3e-13, 2e-13, 1e-13, 1e-15, 0.0, -1e-15, -1e-12] {
        // A notch whose tip reaches down to y = d above the bottom edge.
        let notch = vec![[0.0, 0.0, 0.0], [4.0, 0.0, 0.0], [4.0, 3.0, 0.0], [2.5, 3.0, 0.0], [2.0, d, 0.0], [1.5, 3.0, 0.0], [0.0, 3.0, 0.0]];
        // The same with a hole next to the tip, and reversed.
        let hole = vec![[2.6, 0.5, 0.0], [2.6, 1.0, 0.0], [3.5, 1.0, 0.0], [3.5, 0.5, 0.0]];
        let mut rev = notch.clone();
        rev.reverse();
        for cs in [vec![notch.clone()], vec![notch.clone(), hole.clone()], vec![rev.clone(), hole.clone()]] {
            for &rule in &RULES {
                check_coverage(&cs, rule, &mut r, true, &format!("d = {d} rule {rule}"));
            }
        }
    }
}

/// COMBINE's coordinates stay inside the box of the four vertices it
/// combines, even where halving rounds: a fuzz finding had z one subnormal
/// ulp above every input z (all z = 3 ulps: 0.5 * 3 ulps rounds to 2).
#[test]
fn combined_coordinates_stay_in_the_box_with_subnormal_z() {
    let z = f64::from_bits(3);
    for k in 0..8 {
        let s = 1.0 + k as f64 * 0.37;
        let bow = vec![[0.0, 0.0, z], [4.0 * s, 4.0, z], [4.0 * s, 0.0, z], [0.0, 4.0, z]];
        let out = tess(&[bow], &Opts { rule: GLU_TESS_WINDING_ODD, flags: false, combine: true, boundary: false, normal: None });
        assert!(out.combines > 0);
        for p in out.prims.iter().flatten() {
            assert_eq!(p.0[2].to_bits(), z.to_bits(), "z {:e} from inputs all at {:e}", p.0[2], z);
        }
    }
}

/// The output is a conforming mesh: every edge that is not on the selected
/// region's boundary (edge flag off) is shared with exactly one other
/// triangle, traversed the other way, and no output vertex lies within
/// `tol` of the open segment of a boundary edge (flag on) without being one
/// of its ends. A T-junction (an edge left unsplit at a vertex within the
/// merge distance of it) breaks one or the other, however small it is; the
/// area and point probes of `check_coverage` skip anything that close to
/// an edge, so they cannot see it.
fn check_conforming(cs: &[Vec<[f64; 3]>], rule: u32, tol: f64, what: &str) {
    let out = tess(cs, &Opts { rule, flags: true, combine: true, boundary: false, normal: Some([0.0, 0.0, 1.0]) });
    assert!(out.errors.is_empty(), "{what}: errors {:?}", out.errors);
    let key = |p: [f64; 3]| (p[0].to_bits(), p[1].to_bits());
    let tris: Vec<&[([f64; 3], bool)]> = out.prims.iter().flat_map(|p| p.chunks(3)).collect();
    let mut count: std::collections::HashMap<((u64, u64), (u64, u64)), usize> = Default::default();
    for t in &tris {
        for i in 0..3 {
            *count.entry((key(t[i].0), key(t[(i + 1) % 3].0))).or_default() += 1;
        }
    }
    let mut pts: Vec<[f64; 3]> = tris.iter().flat_map(|t| t.iter().map(|v| v.0)).collect();
    pts.sort_by(|a, b| a[0].total_cmp(&b[0]).then(a[1].total_cmp(&b[1])));
    pts.dedup_by(|a, b| key(*a) == key(*b));
    for t in &tris {
        for i in 0..3 {
            let (a, b, flag) = (t[i].0, t[(i + 1) % 3].0, t[i].1);
            assert_ne!(key(a), key(b), "{what}: triangle with a repeated vertex {t:?}");
            let fwd = count[&(key(a), key(b))];
            let rev = count.get(&(key(b), key(a))).copied().unwrap_or(0);
            if flag {
                assert_eq!((fwd, rev), (1, 0), "{what}: boundary edge {a:?}-{b:?} used {fwd} times, reversed {rev} times (contours {cs:?})");
                for &p in &pts {
                    if key(p) != key(a) && key(p) != key(b) {
                        let d = seg_dist([p[0], p[1]], a, b);
                        assert!(d > tol, "{what}: vertex {p:?} at {d:e} from boundary edge {a:?}-{b:?} (T-junction; contours {cs:?})");
                    }
                }
            } else {
                assert_eq!((fwd, rev), (1, 1), "{what}: interior edge {a:?}-{b:?} used {fwd} times, reversed {rev} times (T-junction; contours {cs:?})");
            }
        }
    }
}

/// Splits at the merge distance's scale. Long chords through nearly one
/// point (offsets of 0.1 to 4 times the merge distance, 2^-42 of the
/// extent): their crossings are rounded to points a few merge distances
/// apart, each near the other chords, and only the splitter's later passes
/// (`touching_at_split_vertices`) split a chord at a crossing point that
/// lies within the merge distance of it. Also a vertex of one contour
/// within 1/8 of the merge distance of another contour's edge. Checked
/// with `check_conforming` (the exact-coverage checks pass either way).
#[test]
fn merge_distance_splits_leave_no_t_junctions() {
    let eps = 1.0 / (1u64 << 42) as f64; // the merge distance at extent 1..2
    let tol = eps / 4.0;
    let mut r = Rng(0x0dd_ba11_cafe_f00d);
    for i in 0..400 {
        let c = [r.f() * 0.4 - 0.2, r.f() * 0.4 - 0.2];
        let spread = [0.1, 0.5, 1.0, 2.0, 4.0][r.below(5) as usize] * eps;
        let k = 3 + r.below(4) as usize;
        let chords: Vec<([f64; 3], [f64; 3])> = (0..k)
            .map(|_| {
                let a = r.f() * std::f64::consts::PI;
                let (o, oa) = (spread * r.f(), r.f() * std::f64::consts::TAU);
                let m = [c[0] + o * oa.cos(), c[1] + o * oa.sin()];
                let (dx, dy) = (0.8 * a.cos(), 0.8 * a.sin());
                ([m[0] + dx, m[1] + dy, 0.0], [m[0] - dx, m[1] - dy, 0.0])
            })
            .collect();
        let cs: Vec<Vec<[f64; 3]>> = if i % 2 == 0 {
            // One self-intersecting contour through every chord.
            vec![chords.iter().flat_map(|&(p, q)| [p, q]).collect()]
        } else {
            // A thin triangle on each chord (either orientation).
            chords
                .iter()
                .map(|&(p, q)| {
                    let w = [0.5 * (p[0] + q[0]) + 0.3 * (q[1] - p[1]), 0.5 * (p[1] + q[1]) - 0.3 * (q[0] - p[0]), 0.0];
                    if r.below(2) == 0 { vec![p, q, w] } else { vec![q, p, w] }
                })
                .collect()
        };
        let rule = RULES[i % 5];
        check_conforming(&cs, rule, tol, &format!("chords {i} spread {spread:e} rule {rule}"));
    }
    // A vertex of one contour within eps/8 of another's edge (either side),
    // the edge at random slopes.
    for i in 0..200 {
        let a = r.f() * std::f64::consts::TAU;
        let (dx, dy) = (a.cos(), a.sin());
        let t = 0.2 + 0.6 * r.f();
        let d = (r.f() - 0.5) * eps / 4.0;
        let p = [-dx + 2.0 * t * dx - dy * d, -dy + 2.0 * t * dy + dx * d, 0.0];
        let big = vec![[-dx, -dy, 0.0], [dx, dy, 0.0], [-dy * 0.9, dx * 0.9, 0.0]];
        let side = if r.below(2) == 0 { 1.0 } else { -1.0 };
        let notch = vec![p, [p[0] + side * (0.3 * dx - 0.5 * dy), p[1] + side * (0.3 * dy + 0.5 * dx), 0.0], [p[0] + side * (-0.3 * dx - 0.5 * dy), p[1] + side * (-0.3 * dy + 0.5 * dx), 0.0]];
        let rule = RULES[i % 5];
        check_conforming(&[big, notch], rule, tol, &format!("vertex near edge {i} d {d:e} rule {rule}"));
    }
}

/// The conforming-mesh check on the random families of
/// `exact_coverage_random_polygons` (grid polygons with duplicates,
/// collinear runs, touching and overlapping edges; nudged grid points;
/// rectangles; random real coordinates).
#[test]
fn random_polygons_give_conforming_meshes() {
    let mut r = Rng(0x2545_f491_4f6c_dd1d);
    for i in 0..1200 {
        let family = i % 6;
        let cs = random_polygon(&mut r, family);
        let ext = cs.iter().flatten().map(|v| v[0].abs().max(v[1].abs())).fold(1.0, f64::max);
        check_conforming(&cs, RULES[(i / 6) as usize % 5], ext / (1u64 << 46) as f64, &format!("polygon {i} family {family}"));
    }
}

/// Planar input with edges off the region's boundary (nested contours the
/// same way round under NONZERO, POSITIVE..., nothing selected under
/// NEGATIVE), small and large: the fast path triangulates every selected
/// face, so an edge with the region on both sides is a triangle edge but
/// not a boundary edge (unflagged). Exact coverage, edge flags and a
/// conforming mesh, every rule.
#[test]
fn planar_hand_off_covers_exactly() {
    let mut r = Rng(0x0dd_ba11_5eed_0001);
    let star = |r: &mut Rng, c: [f64; 2], lo: f64, hi: f64, n: usize, rev: bool| {
        let mut v: Vec<[f64; 3]> = (0..n)
            .map(|i| {
                let a = i as f64 / n as f64 * std::f64::consts::TAU;
                let rr = lo + (hi - lo) * r.f();
                [c[0] + rr * a.cos(), c[1] + rr * a.sin(), 0.0]
            })
            .collect();
        if rev {
            v.reverse();
        }
        v
    };
    for i in 0..40 {
        // Outer radius 9-10; holes at distance 4.95 of radius 1-2, each
        // perhaps with an island of radius at most 0.8: nothing crosses.
        // (An outline of 6 vertices or more keeps the holes inside.)
        let n = if i % 2 == 0 { 64 + r.below(40) } else { 6 + r.below(40) } as usize;
        let mut cs = vec![star(&mut r, [0.0, 0.0], 9.0, 10.0, n, i % 5 == 4)];
        for k in 0..1 + r.below(4) {
            let c = [if k % 2 == 0 { 3.5 } else { -3.5 }, if k / 2 == 0 { 3.5 } else { -3.5 }];
            let (n, rev) = (8 + r.below(16) as usize, r.below(2) == 0);
            cs.push(star(&mut r, c, 1.0, 2.0, n, rev));
            if r.below(2) == 0 {
                let (n, rev) = (3 + r.below(6) as usize, r.below(2) == 0);
                cs.push(star(&mut r, c, 0.4, 0.8, n, rev));
            }
        }
        for &rule in &RULES {
            let what = format!("planar polygon {i} rule {rule}");
            check_coverage(&cs, rule, &mut r, true, &what);
            check_conforming(&cs, rule, 10.0 / (1u64 << 46) as f64, &what);
        }
    }
}

/// Fuzz run 15's finding (2026-11-27): under huge coordinates (2.2e13
/// beside a 0..15 grid) this input merges into 5 vertices carrying 52
/// segments, and two vertices on one segment at the same parameter sorted
/// as v, w, v, ...: the pieces between them were split again by each later
/// pass, 52 -> 199 -> 3,647 -> millions of pieces (8 GiB). Replayed with
/// the fuzz target's call sequence ("sloppy": odd contours without
/// gluTessBeginContour, every third without gluTessEndContour). It must
/// finish with a bounded output in triangles.
#[test]
fn fuzz_run_15_repeated_split_vertices_stay_bounded() {
    let contours: Vec<Vec<[f64; 3]>> = vec![
        vec![[0.0, 0.0, 0.0], [10.0, 10.0, 1.0], [10.0, 0.0, 0.0], [3.0, 12.0, 0.0], [0.0, 0.0, 1.0], [0.0, 0.0, 0.0]],
        vec![],
        vec![[14.0, 15.0, 0.0], [1.0, 5.0, 0.0], [2e-05, 0.0, 0.0], [3.0, 6.0, 0.0]],
        vec![[3.00018310546875, 6.0000000000000036, 0.0], [15.0, 15.0, 0.0], [14.0, 0.0, 0.0], [0.0, 0.0, 0.0]],
        vec![[7.0, 11.0, 0.0], [7.0, 2.0, 0.0], [8.0, 11.0, 0.0], [14.0, 2.0, 0.0], [3e-150, 1.2e-149, 0.0], [0.0, 0.0, 0.0], [1.0, 3.0, 0.0], [1.0000000000000038, 3.000732421875, 0.0], [1.0, 9.0, 2.0], [1.0, 9.0, 2.0], [1.0, 9.0, 2.0], [0.0, 3.0, 0.0], [6.103515625e-05, 3.0000000000000018, 0.0], [15.0, 15.0, 0.0], [14.0, 0.0, 0.0], [6.0, 8.0, 0.0], [9.0, 15.0, 0.0], [5.0, 3.0, 0.0], [15.0, 1.0, 0.0], [7.0, 2.0, 0.0], [14.0, 15.0, 0.0], [15.0, 15.0, 1.0], [3.0000000000000004e-05, 6.000000000000001e-05, 0.0], [3.000000000000007e-05, 6.00596046447754e-05, 0.0], [8.0, 2.0, 0.0], [15.0, 15.0, 0.0], [3.0, 3.0, 0.0], [9.0, 12.0, 0.0], [3.0, 12.0, 0.0], [1.0, 0.0, 0.0], [3.0, 2.0, 0.0], [0.0, 3.0, 0.0], [6.103515625e-05, 3.0000000000000018, 0.0], [15.0, 15.0, 0.0], [14.0, 0.0, 0.0], [6.0, 8.0, 0.0], [9.0, 15.0, 0.0], [5.0, 3.0, 0.0], [15.0, 1.0, 0.0]],
        vec![],
        vec![[14.0, 11.0, 0.0], [7.0, 2.0, 0.0], [14.0, 15.0, 0.0], [15.0, 15.0, 1.0], [3.0000000000000004e-05, 6.000000000000001e-05, 0.0], [2.0, 4.0, 0.0], [2.0, 4.0, 0.0], [2.0, 4.0, 0.0], [2.0, 4.0, 0.0], [2.0, 4.0, 0.0], [2.0, 4.0, 0.0], [2.0, 4.0, 0.0], [2.0009765625, 4.000000000000006, 0.0], [2.0, 4.0, 0.0], [2.0, 4.0, 0.0], [2.0, 4.0, 0.0], [2.0, 4.0, 0.0], [2.0, 4.0, 0.0], [2.0, 4.0, 0.0], [1.0, 0.0, 0.0], [7.0, 8.0, 0.0], [22274812035650.258, 156842099844.51764, 0.0], [2.0, 4.0, 0.0], [2.0, 4.0, 0.0], [2.0000000000000124, 4.000000238418579, 0.0], [2.0, 4.0, 0.0], [10.0, 0.0, 0.0], [1.0, 0.0, 0.0], [1.0000000000000064, 3.814697265625e-06, 0.0], [3.0, 3.0, 0.0], [3.000091552734375, 3.0003662109375, 0.0]],
        vec![[8.0, 3.0, 0.0], [7.0, 8.0, 0.0], [0.0, 0.0, 0.0], [9.0, 3.0, 0.0]],
        vec![],
        vec![],
        vec![[8.0, 3.0, 0.0], [14.0, 0.0, 0.0], [14.00042724609375, 0.000244140625, 0.0], [8.0, 2.0, 0.0], [1.0, 5.0, 0.0], [1.0000000000004547, 5.000000000000013, 0.0], [3.0, 12.0, 0.0], [3.0, 0.0, 1.0], [3.0, 12.0, 0.0], [6.0, 12.0, 0.0], [1.0, 0.0, 0.0], [1.0009765625, 1.5e-323, 0.0]],
    ];
    let opts = Opts { rule: GLU_TESS_WINDING_ODD, flags: true, combine: true, boundary: false, normal: None };
    let o = tess_calls(&contours, &opts, |ci| ci % 2 == 0, |ci| ci % 3 != 2);
    let tris: usize = o.prims.iter().map(|p| p.len()).sum();
    assert_eq!(tris % 3, 0);
    assert!(o.begins.iter().all(|&m| m == 0x0004), "{:?}", o.begins);
    assert!(tris / 3 < 1_000 && o.combines < 1_000, "{} triangles, {} COMBINE calls", tris / 3, o.combines);
}
