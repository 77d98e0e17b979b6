//! GLU quadrics, checked on what they emit: a recording [`Sink`] stands in for
//! GL, and every vertex, normal and texture coordinate is compared with the
//! analytic surface (GLU 1.3 and the gluSphere / gluCylinder / gluDisk /
//! gluPartialDisk / gluQuadricTexture man pages); primitive counts, winding
//! against the orientation, flat normals against the faces' planes, and the
//! errors reported through the GLU_ERROR callback.

use softgl::gl::enums::*;
use softgl::glu::quadric::*;
use softgl::glu::strings::{GLU_INVALID_ENUM, GLU_INVALID_VALUE};
use std::cell::RefCell;
use std::f64::consts::{PI, TAU};

#[derive(Clone, Copy, Debug)]
struct V {
    p: [f64; 3],
    /// The current normal / texture coordinates when the vertex was sent.
    n: Option<[f64; 3]>,
    t: Option<[f64; 2]>,
}

#[derive(Debug)]
struct Prim {
    mode: u32,
    v: Vec<V>,
}

#[derive(Default)]
struct Rec {
    prims: Vec<Prim>,
    open: bool,
    n: Option<[f64; 3]>,
    t: Option<[f64; 2]>,
    normals: usize,
    texcoords: usize,
}

impl Sink for Rec {
    fn begin(&mut self, mode: u32) {
        assert!(!self.open, "nested begin");
        self.open = true;
        self.prims.push(Prim { mode, v: vec![] });
    }
    fn end(&mut self) {
        assert!(self.open, "end without begin");
        self.open = false;
    }
    fn vertex(&mut self, p: [f64; 3]) {
        assert!(self.open, "vertex outside begin/end");
        let v = V { p, n: self.n, t: self.t };
        self.prims.last_mut().unwrap().v.push(v);
    }
    fn normal(&mut self, n: [f64; 3]) {
        self.normals += 1;
        self.n = Some(n);
    }
    fn tex_coord(&mut self, s: f64, t: f64) {
        self.texcoords += 1;
        self.t = Some([s, t]);
    }
}

fn quadric(normals: u32, texture: bool, orientation: u32, style: u32) -> Quadric {
    let mut q = Quadric::default();
    q.set_normals(normals);
    q.set_texture(texture);
    q.set_orientation(orientation);
    q.set_draw_style(style);
    q
}

fn sub(a: [f64; 3], b: [f64; 3]) -> [f64; 3] {
    [a[0] - b[0], a[1] - b[1], a[2] - b[2]]
}
fn cross(a: [f64; 3], b: [f64; 3]) -> [f64; 3] {
    [a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]]
}
fn dot(a: [f64; 3], b: [f64; 3]) -> f64 {
    a[0] * b[0] + a[1] * b[1] + a[2] * b[2]
}
fn len(a: [f64; 3]) -> f64 {
    dot(a, a).sqrt()
}
fn close3(a: [f64; 3], b: [f64; 3], eps: f64) -> bool {
    len(sub(a, b)) <= eps
}

/// Triangles of a GL_QUAD_STRIP, per quad: (v2k, v2k+1, v2k+3), (v2k, v2k+3,
/// v2k+2), and the quad's last vertex (the one flat shading reads).
fn quad_strip_tris(p: &Prim) -> Vec<([V; 3], V)> {
    assert_eq!(p.mode, GL_QUAD_STRIP);
    let v = &p.v;
    let mut out = vec![];
    for k in 0..(v.len() / 2).saturating_sub(1) {
        let (a, b, c, d) = (v[2 * k], v[2 * k + 1], v[2 * k + 2], v[2 * k + 3]);
        out.push(([a, b, d], d));
        out.push(([a, d, c], d));
    }
    out
}

/// Angle of (x, y) from +y towards +x, in turns, in [0, 1).
fn turns(p: [f64; 3]) -> f64 {
    let a = p[0].atan2(p[1]) / TAU;
    if a < 0.0 { a + 1.0 } else { a }
}

/// s agrees with the angle (mod 1: the seam may carry s = 1).
fn check_s(s: f64, p: [f64; 3]) {
    let d = (s - turns(p)).rem_euclid(1.0);
    assert!(!(1e-9..=1.0 - 1e-9).contains(&d), "s {s} at {p:?} (angle {} turns)", turns(p));
    assert!((-1e-12..=1.0 + 1e-12).contains(&s));
}

/// Checks winding and flat normals of a filled shape: each non-degenerate
/// triangle faces `outward(centroid)` (or away for inside), and with flat
/// normals the normal at the quad's last vertex is the plane's.
fn check_fill(rec: &Rec, inside: bool, flat: bool, outward: &dyn Fn([f64; 3]) -> [f64; 3]) -> usize {
    let mut tris = 0;
    for p in &rec.prims {
        for (t, last) in quad_strip_tris(p) {
            let n = cross(sub(t[1].p, t[0].p), sub(t[2].p, t[0].p));
            if len(n) < 1e-12 {
                continue; // the degenerate half of a pole / centre quad
            }
            tris += 1;
            let c = [0, 1, 2].map(|k| (t[0].p[k] + t[1].p[k] + t[2].p[k]) / 3.0);
            let facing = dot(n, outward(c));
            assert!(if inside { facing < 0.0 } else { facing > 0.0 }, "winding of {t:?}, inside {inside}");
            if flat {
                let fnorm = last.n.expect("flat normal");
                assert!((len(fnorm) - 1.0).abs() < 1e-9);
                // The front face's normal: outward for GLU_OUTSIDE, inward
                // for GLU_INSIDE, as the winding already is.
                let want = n.map(|x| x / len(n));
                assert!(close3(fnorm, want, 1e-6), "flat normal {fnorm:?}, plane {want:?}");
            }
        }
    }
    tris
}

const STYLES: [u32; 4] = [GLU_FILL, GLU_LINE, GLU_SILHOUETTE, GLU_POINT];
const NORMALS: [u32; 3] = [GLU_SMOOTH, GLU_FLAT, GLU_NONE];
const ORIENT: [u32; 2] = [GLU_OUTSIDE, GLU_INSIDE];

#[test]
fn sphere_geometry_normals_texcoords() {
    for &(r, slices, stacks) in &[(1.0, 16, 8), (2.5, 7, 5), (0.5, 2, 1), (3.0, 32, 17)] {
        for style in STYLES {
            for normals in NORMALS {
                for orient in ORIENT {
                    let q = quadric(normals, true, orient, style);
                    let mut rec = Rec::default();
                    q.sphere(&mut rec, r, slices, stacks);
                    assert!(!rec.open);
                    let inside = orient == GLU_INSIDE;
                    for v in rec.prims.iter().flat_map(|p| &p.v) {
                        assert!((len(v.p) - r).abs() < 1e-6 * r.max(1.0), "off the sphere: {:?}", v.p);
                        let t = v.t.unwrap();
                        let want_t = 1.0 - (v.p[2] / r).clamp(-1.0, 1.0).acos() / PI;
                        assert!((t[1] - want_t).abs() < 1e-9, "t {} at {:?}", t[1], v.p);
                        if v.p[0].hypot(v.p[1]) > 1e-9 {
                            check_s(t[0], v.p);
                        }
                        if normals == GLU_SMOOTH || (normals == GLU_FLAT && style != GLU_FILL) {
                            let n = v.n.unwrap();
                            let radial = v.p.map(|x| x / r);
                            let want = if inside { radial.map(|x| -x) } else { radial };
                            assert!(close3(n, want, 1e-9), "normal {n:?} at {:?}", v.p);
                        }
                    }
                    if normals == GLU_NONE {
                        assert_eq!(rec.normals, 0);
                    }
                    let (s, k) = (slices as usize, stacks as usize);
                    let counts: Vec<(u32, usize)> = rec.prims.iter().map(|p| (p.mode, p.v.len())).collect();
                    match style {
                        GLU_FILL => {
                            assert_eq!(counts, vec![(GL_QUAD_STRIP, 2 * (s + 1)); k]);
                            let tris = check_fill(&rec, inside, normals == GLU_FLAT, &|c| c);
                            // two triangles per face, one at each pole face
                            assert_eq!(tris, 2 * s * k - 2 * s);
                        }
                        GLU_POINT => assert_eq!(counts, vec![(GL_POINTS, 2 + (k - 1) * s)]),
                        _ => {
                            let mut want = vec![(GL_LINE_LOOP, s); k - 1];
                            want.extend(vec![(GL_LINE_STRIP, k + 1); s]);
                            assert_eq!(counts, want);
                        }
                    }
                }
            }
        }
    }
}

#[test]
fn sphere_silhouette_from_z_is_the_equator_polygon() {
    // Projected on z = 0, a sphere with an even number of stacks covers the
    // regular polygon of its equator: its triangles' projected areas, each
    // side of z = 0, add up to n/2 r^2 sin(2 pi/n).
    let q = quadric(GLU_SMOOTH, false, GLU_OUTSIDE, GLU_FILL);
    let mut rec = Rec::default();
    let (r, n) = (2.0, 24);
    q.sphere(&mut rec, r, n, 10);
    let (mut up, mut down) = (0.0, 0.0);
    for p in &rec.prims {
        for (t, _) in quad_strip_tris(p) {
            let a = cross(sub(t[1].p, t[0].p), sub(t[2].p, t[0].p))[2] / 2.0;
            if a > 0.0 { up += a } else { down -= a }
        }
    }
    let want = n as f64 / 2.0 * r * r * (TAU / n as f64).sin();
    assert!((up - want).abs() < 1e-9 && (down - want).abs() < 1e-9, "{up} {down} {want}");
}

#[test]
fn cylinder_geometry_normals_texcoords() {
    for &(base, top, h, slices, stacks) in &[(1.0, 1.0, 2.0, 12, 3), (2.0, 0.0, 3.0, 9, 4), (0.5, 1.5, 1.0, 3, 1), (1.0, 0.25, 0.0, 8, 2)] {
        for style in STYLES {
            for normals in NORMALS {
                for orient in ORIENT {
                    let q = quadric(normals, true, orient, style);
                    let mut rec = Rec::default();
                    q.cylinder(&mut rec, base, top, h, slices, stacks);
                    let inside = orient == GLU_INSIDE;
                    let l = h.hypot(base - top);
                    let outward = |p: [f64; 3]| {
                        let rr = p[0].hypot(p[1]);
                        if rr == 0.0 { [0.0, 0.0, 0.0] } else { [h * p[0] / rr / l, h * p[1] / rr / l, (base - top) / l] }
                    };
                    for v in rec.prims.iter().flat_map(|p| &p.v) {
                        let t = v.t.unwrap();
                        assert!((0.0..=h).contains(&v.p[2]));
                        // t runs 0..1 from base to top; the radius follows it.
                        let want_r = base + (top - base) * t[1];
                        assert!((v.p[0].hypot(v.p[1]) - want_r).abs() < 1e-9, "radius at {:?}", v.p);
                        assert!((v.p[2] - h * t[1]).abs() < 1e-9);
                        if want_r > 1e-9 {
                            check_s(t[0], v.p);
                        }
                        if normals == GLU_SMOOTH && want_r > 1e-9 {
                            let n = v.n.unwrap();
                            assert!((len(n) - 1.0).abs() < 1e-9);
                            let o = outward(v.p);
                            let want = if inside { o.map(|x| -x) } else { o };
                            assert!(close3(n, want, 1e-9), "normal {n:?} want {want:?}");
                        }
                    }
                    let (s, k) = (slices as usize, stacks as usize);
                    let counts: Vec<(u32, usize)> = rec.prims.iter().map(|p| (p.mode, p.v.len())).collect();
                    match style {
                        GLU_FILL => {
                            assert_eq!(counts, vec![(GL_QUAD_STRIP, 2 * (s + 1)); k]);
                            if h > 0.0 {
                                let tris = check_fill(&rec, inside, normals == GLU_FLAT, &|c| outward(c));
                                assert!(tris >= 2 * s * k - s);
                            }
                        }
                        GLU_POINT => assert_eq!(counts.len(), 1),
                        GLU_LINE => {
                            let loops = (0..=k).filter(|&j| base + (top - base) * j as f64 / k as f64 > 0.0).count();
                            let mut want = vec![(GL_LINE_LOOP, s); loops];
                            want.extend(vec![(GL_LINE_STRIP, k + 1); s]);
                            assert_eq!(counts, want);
                        }
                        _ => {
                            let loops = [base, top].iter().filter(|&&x| x > 0.0).count();
                            let mut want = vec![(GL_LINE_LOOP, s); loops];
                            want.extend(vec![(GL_LINE_STRIP, k + 1); s]);
                            assert_eq!(counts, want);
                        }
                    }
                }
            }
        }
    }
}

/// Sum of the z components of the triangles' areas (signed, +z positive).
fn signed_area_z(rec: &Rec) -> f64 {
    let mut a = 0.0;
    for p in &rec.prims {
        for (t, _) in quad_strip_tris(p) {
            a += cross(sub(t[1].p, t[0].p), sub(t[2].p, t[0].p))[2] / 2.0;
        }
    }
    a
}

#[test]
fn disks() {
    // (inner, outer, slices, loops, start, sweep); sweep None = gluDisk
    type Case = (f64, f64, i32, i32, f64, Option<f64>);
    let cases: &[Case] = &[
        (0.0, 2.0, 16, 3, 0.0, None),
        (0.5, 1.5, 7, 2, 0.0, None),
        (1.0, 1.0, 4, 1, 0.0, None),
        (0.0, 2.0, 10, 2, 30.0, Some(90.0)),
        (0.5, 3.0, 5, 4, 200.0, Some(250.0)),
        (0.5, 3.0, 5, 4, 100.0, Some(-60.0)),
        (0.0, 1.0, 12, 1, 45.0, Some(360.0)),
        (0.25, 1.0, 3, 1, -90.0, Some(500.0)),
    ];
    for &(inner, outer, slices, loops, start, sweep) in cases {
        for style in STYLES {
            for normals in NORMALS {
                for orient in ORIENT {
                    let q = quadric(normals, true, orient, style);
                    let mut rec = Rec::default();
                    match sweep {
                        None => q.disk(&mut rec, inner, outer, slices, loops),
                        Some(sw) => q.partial_disk(&mut rec, inner, outer, slices, loops, start, sw),
                    }
                    let inside = orient == GLU_INSIDE;
                    let (a0, sw) = match sweep {
                        None => (0.0, 360.0),
                        Some(sw) if sw < 0.0 => (start + sw, -sw),
                        Some(sw) => (start, sw.min(360.0)),
                    };
                    let full = sw >= 360.0;
                    for v in rec.prims.iter().flat_map(|p| &p.v) {
                        assert_eq!(v.p[2], 0.0);
                        let r = v.p[0].hypot(v.p[1]);
                        assert!(r >= inner - 1e-9 && r <= outer + 1e-9, "radius {r}");
                        if !full && r > 1e-9 {
                            let rel = (turns(v.p) * 360.0 - a0).rem_euclid(360.0);
                            assert!(rel <= sw + 1e-6 || rel >= 360.0 - 1e-6, "angle {rel} outside sweep {sw}");
                        }
                        let t = v.t.unwrap();
                        assert!((t[0] - (0.5 + v.p[0] / (2.0 * outer))).abs() < 1e-12);
                        assert!((t[1] - (0.5 + v.p[1] / (2.0 * outer))).abs() < 1e-12);
                        if normals != GLU_NONE {
                            let want = if inside { [0.0, 0.0, -1.0] } else { [0.0, 0.0, 1.0] };
                            assert_eq!(v.n.unwrap(), want);
                        }
                    }
                    let (s, k) = (slices as usize, loops as usize);
                    let counts: Vec<(u32, usize)> = rec.prims.iter().map(|p| (p.mode, p.v.len())).collect();
                    let rings = (0..=k).filter(|&j| inner + (outer - inner) * j as f64 / k as f64 > 0.0).count();
                    let arc = if full { (GL_LINE_LOOP, s) } else { (GL_LINE_STRIP, s + 1) };
                    match style {
                        GLU_FILL => {
                            assert_eq!(counts, vec![(GL_QUAD_STRIP, 2 * (s + 1)); k]);
                            check_fill(&rec, inside, normals == GLU_FLAT, &|_| [0.0, 0.0, 1.0]);
                            let n = s as f64;
                            let step = sw.to_radians() / n;
                            let want = n / 2.0 * (outer * outer - inner * inner) * step.sin();
                            let got = signed_area_z(&rec);
                            let want = if inside { -want } else { want };
                            assert!((got - want).abs() < 1e-9, "area {got}, want {want}");
                        }
                        GLU_POINT => {
                            let centre = if inner == 0.0 { 1 } else { 0 };
                            let per_ring = if full { s } else { s + 1 };
                            assert_eq!(counts, vec![(GL_POINTS, centre + rings * per_ring)]);
                        }
                        GLU_LINE => {
                            let mut want = vec![arc; rings];
                            want.extend(vec![(GL_LINE_STRIP, k + 1); if full { s } else { s + 1 }]);
                            assert_eq!(counts, want);
                        }
                        _ => {
                            let ends = [inner, outer].iter().filter(|&&x| x > 0.0).count();
                            let mut want = vec![arc; ends];
                            if !full {
                                want.extend(vec![(GL_LINE_STRIP, k + 1); 2]);
                            }
                            assert_eq!(counts, want);
                        }
                    }
                }
            }
        }
    }
}

#[test]
fn no_normals_no_texcoords_unless_asked() {
    let q = quadric(GLU_NONE, false, GLU_OUTSIDE, GLU_FILL);
    let mut rec = Rec::default();
    q.sphere(&mut rec, 1.0, 8, 4);
    q.cylinder(&mut rec, 1.0, 0.5, 1.0, 8, 4);
    q.disk(&mut rec, 0.0, 1.0, 8, 2);
    q.partial_disk(&mut rec, 0.0, 1.0, 8, 2, 0.0, 90.0);
    assert!(!rec.prims.is_empty());
    assert_eq!((rec.normals, rec.texcoords), (0, 0));
}

#[test]
fn defaults_are_smooth_outside_fill_untextured() {
    let q = Quadric::default();
    assert_eq!((q.normals, q.texture, q.orientation, q.draw_style), (GLU_SMOOTH, false, GLU_OUTSIDE, GLU_FILL));
}

thread_local! {
    static ERRORS: RefCell<Vec<u32>> = const { RefCell::new(Vec::new()) };
}

unsafe extern "system" fn on_error(e: u32) {
    ERRORS.with(|v| v.borrow_mut().push(e));
}

fn take_errors() -> Vec<u32> {
    ERRORS.with(|v| std::mem::take(&mut *v.borrow_mut()))
}

fn error_proc() -> Option<unsafe extern "system" fn()> {
    Some(unsafe { std::mem::transmute::<unsafe extern "system" fn(u32), unsafe extern "system" fn()>(on_error) })
}

#[test]
fn errors_through_the_callback() {
    let mut q = Quadric::default();
    q.set_callback(GLU_ERROR, error_proc());
    let mut rec = Rec::default();
    q.sphere(&mut rec, -1.0, 8, 4);
    q.sphere(&mut rec, 1.0, 1, 4);
    q.sphere(&mut rec, 1.0, 8, 0);
    q.cylinder(&mut rec, -1.0, 1.0, 1.0, 8, 1);
    q.cylinder(&mut rec, 1.0, -1.0, 1.0, 8, 1);
    q.cylinder(&mut rec, 1.0, 1.0, -1.0, 8, 1);
    q.cylinder(&mut rec, 1.0, 1.0, 1.0, 1, 1);
    q.cylinder(&mut rec, 1.0, 1.0, 1.0, 8, 0);
    q.disk(&mut rec, -0.5, 1.0, 8, 1);
    q.disk(&mut rec, 2.0, 1.0, 8, 1);
    q.disk(&mut rec, 0.0, 1.0, 1, 1);
    q.disk(&mut rec, 0.0, 1.0, 8, 0);
    q.partial_disk(&mut rec, 0.0, -1.0, 8, 1, 0.0, 90.0);
    q.partial_disk(&mut rec, 0.0, 1.0, 0, 1, 0.0, 90.0);
    q.sphere(&mut rec, f64::NAN, 8, 4);
    assert_eq!(take_errors(), vec![GLU_INVALID_VALUE; 15]);
    assert!(rec.prims.is_empty(), "nothing drawn on error");

    q.set_draw_style(GL_TRIANGLES);
    q.set_normals(12345);
    q.set_orientation(GLU_FILL);
    q.set_callback(GLU_FILL, None);
    assert_eq!(take_errors(), vec![GLU_INVALID_ENUM; 4]);
    assert_eq!((q.normals, q.orientation, q.draw_style), (GLU_SMOOTH, GLU_OUTSIDE, GLU_FILL));
    assert!(q.error.is_some(), "a bad enum leaves the callback alone");

    // Zero sizes are not errors.
    q.sphere(&mut rec, 0.0, 8, 4);
    q.cylinder(&mut rec, 0.0, 0.0, 0.0, 8, 1);
    q.disk(&mut rec, 0.0, 0.0, 8, 1);
    assert!(take_errors().is_empty());

    // A NULL callback unsets it.
    q.set_callback(GLU_ERROR, None);
    q.sphere(&mut rec, -1.0, 8, 4);
    assert!(take_errors().is_empty());
}

#[test]
fn c_entry_points() {
    use softgl::api::table::*;
    unsafe {
        let q = gluNewQuadric();
        assert!(!q.is_null());
        gluQuadricCallback(q, GLU_ERROR, error_proc());
        // Without a context: errors come before any GL call.
        gluSphere(q, -1.0, 8, 8);
        gluCylinder(q, 1.0, 1.0, 1.0, 1, 1);
        gluDisk(q, 0.0, 1.0, 8, 0);
        gluPartialDisk(q, 1.0, 0.5, 8, 1, 0.0, 90.0);
        gluQuadricDrawStyle(q, 7);
        gluQuadricNormals(q, 7);
        gluQuadricOrientation(q, 7);
        gluQuadricTexture(q, 0xFF);
        assert_eq!(take_errors(), [vec![GLU_INVALID_VALUE; 4], vec![GLU_INVALID_ENUM; 3]].concat());
        gluDeleteQuadric(q);
        // NULL quadrics are ignored.
        gluSphere(std::ptr::null_mut(), 1.0, 8, 8);
        gluQuadricNormals(std::ptr::null_mut(), GLU_FLAT);
        gluDeleteQuadric(std::ptr::null_mut());
    }
}
