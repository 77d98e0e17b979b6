//! GLU NURBS, checked on what they emit (a recording sink, or the
//! GLU_NURBS_TESSELLATOR callbacks through the C entry points): points on a
//! rational circle and a Bezier-equivalent cubic against the Bernstein
//! formula, vertices and normals on a NURBS cylinder patch and sphere,
//! trimmed areas, sampling against the tolerances, callbacks' counts and
//! values, and the errors reported.

use softgl::api::table::*;
use softgl::gl::enums::*;
use softgl::glu::nurbs::*;
use softgl::glu::strings::{GLU_INVALID_ENUM, GLU_INVALID_VALUE};
use std::cell::RefCell;
use std::ffi::c_void;
use std::rc::Rc;

#[derive(Default, Debug)]
struct Rec {
    prims: Vec<(u32, Vec<[f64; 3]>)>,
    normals: Vec<[f64; 3]>,
    colors: Vec<Vec<f64>>,
    texcoords: usize,
    n: Option<[f64; 3]>,
}

struct Shared(Rc<RefCell<Rec>>);

impl NurbsSink for Shared {
    fn begin(&mut self, mode: u32) {
        self.0.borrow_mut().prims.push((mode, vec![]));
    }
    fn end(&mut self) {}
    fn vertex(&mut self, p: [f64; 3]) {
        let mut r = self.0.borrow_mut();
        let n = r.n;
        r.prims.last_mut().unwrap().1.push(p);
        if let Some(n) = n {
            r.normals.push(n);
        }
    }
    fn normal(&mut self, n: [f64; 3]) {
        self.0.borrow_mut().n = Some(n);
    }
    fn color(&mut self, c: &[f64]) {
        self.0.borrow_mut().colors.push(c.to_vec());
    }
    fn tex_coord(&mut self, _t: &[f64]) {
        self.0.borrow_mut().texcoords += 1;
    }
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

fn nurbs() -> (Nurbs, Rc<RefCell<Rec>>) {
    let rec = Rc::new(RefCell::new(Rec::default()));
    let mut n = Nurbs::default();
    n.sink = Some(Box::new(Shared(rec.clone())));
    n.set_callback(GLU_NURBS_ERROR, Some(unsafe { std::mem::transmute::<unsafe extern "system" fn(u32), unsafe extern "system" fn()>(on_error) }));
    n.set_property(GLU_AUTO_LOAD_MATRIX, 0.0);
    (n, rec)
}

fn dist(a: [f64; 3], b: [f64; 3]) -> f64 {
    ((a[0] - b[0]).powi(2) + (a[1] - b[1]).powi(2) + (a[2] - b[2]).powi(2)).sqrt()
}
fn norm(a: [f64; 3]) -> f64 {
    dist(a, [0.0; 3])
}

const H: f32 = std::f32::consts::FRAC_1_SQRT_2;
/// The nine-point quadratic circle of radius r in z = 0, homogeneous.
fn circle(r: f32) -> (Vec<f32>, Vec<f32>) {
    let knots = vec![0.0, 0.0, 0.0, 1.0, 1.0, 2.0, 2.0, 3.0, 3.0, 4.0, 4.0, 4.0];
    let pts = [(1.0, 0.0, 1.0), (1.0, 1.0, H), (0.0, 1.0, 1.0), (-1.0, 1.0, H), (-1.0, 0.0, 1.0), (-1.0, -1.0, H), (0.0, -1.0, 1.0), (1.0, -1.0, H), (1.0, 0.0, 1.0)];
    let ctl = pts.iter().flat_map(|&(x, y, w)| [x * r * w, y * r * w, 0.0, w]).collect();
    (knots, ctl)
}

#[test]
fn rational_circle_lies_on_the_circle_and_meets_the_path_length() {
    let (mut n, rec) = nurbs();
    n.set_property(GLU_SAMPLING_METHOD, GLU_OBJECT_PATH_LENGTH as f32);
    n.set_property(GLU_SAMPLING_TOLERANCE, 0.1);
    let (mut k, mut c) = circle(2.0);
    unsafe {
        n.begin_curve();
        n.nurbs_curve(12, k.as_mut_ptr(), 4, c.as_mut_ptr(), 3, GL_MAP1_VERTEX_4);
        n.end_curve();
    }
    assert!(take_errors().is_empty());
    let r = rec.borrow();
    assert_eq!(r.prims.len(), 1);
    let (mode, v) = &r.prims[0];
    assert_eq!(*mode, GL_LINE_STRIP);
    // The circumference is 4 pi; edges of at most 0.1 need 126 or more.
    assert!(v.len() >= 127, "{} vertices", v.len());
    assert!(dist(v[0], [2.0, 0.0, 0.0]) < 1e-6 && dist(*v.last().unwrap(), [2.0, 0.0, 0.0]) < 1e-6);
    for p in v {
        assert!((norm(*p) - 2.0).abs() < 1e-6, "{p:?} off the circle");
        assert!(p[2] == 0.0);
    }
    for w in v.windows(2) {
        assert!(dist(w[0], w[1]) <= 0.1 + 1e-9, "edge {}", dist(w[0], w[1]));
    }
}

#[test]
fn bezier_cubic_matches_bernstein() {
    let (mut n, rec) = nurbs();
    n.set_property(GLU_SAMPLING_METHOD, GLU_DOMAIN_DISTANCE as f32);
    n.set_property(GLU_U_STEP, 10.0);
    let mut k = [0.0f32, 0.0, 0.0, 0.0, 1.0, 1.0, 1.0, 1.0];
    let mut c = [0.0f32, 0.0, 0.0, 1.0, 2.0, 0.5, 3.0, -2.0, 1.0, 4.0, 1.0, -1.0];
    unsafe {
        n.begin_curve();
        n.nurbs_curve(8, k.as_mut_ptr(), 3, c.as_mut_ptr(), 4, GL_MAP1_VERTEX_3);
        n.end_curve();
    }
    let r = rec.borrow();
    let v = &r.prims[0].1;
    assert_eq!(v.len(), 11);
    for (s, p) in v.iter().enumerate() {
        let t = s as f64 / 10.0;
        let b = [(1.0 - t).powi(3), 3.0 * t * (1.0 - t).powi(2), 3.0 * t * t * (1.0 - t), t.powi(3)];
        let want = [0, 1, 2].map(|k| (0..4).map(|j| b[j] * c[3 * j + k] as f64).sum::<f64>());
        assert!(dist(*p, want) < 1e-12, "t={t}: {p:?} vs {want:?}");
    }
}

#[test]
fn curve_attributes_and_implicit_begin_end() {
    let (mut n, rec) = nurbs();
    n.set_property(GLU_SAMPLING_METHOD, GLU_DOMAIN_DISTANCE as f32);
    n.set_property(GLU_U_STEP, 4.0);
    let mut k = [0.0f32, 0.0, 1.0, 1.0];
    let mut c = [0.0f32, 0.0, 0.0, 4.0, 0.0, 0.0];
    let mut col = [1.0f32, 0.0, 0.0, 1.0, 0.0, 0.0, 1.0, 1.0];
    unsafe {
        n.begin_curve();
        n.nurbs_curve(4, k.as_mut_ptr(), 4, col.as_mut_ptr(), 2, GL_MAP1_COLOR_4);
        n.nurbs_curve(4, k.as_mut_ptr(), 3, c.as_mut_ptr(), 2, GL_MAP1_VERTEX_3);
        n.end_curve();
    }
    {
        let r = rec.borrow();
        assert_eq!(r.prims[0].1.len(), 5);
        assert_eq!(r.colors.len(), 5);
        for (i, col) in r.colors.iter().enumerate() {
            let t = i as f64 / 4.0;
            assert!((col[0] - (1.0 - t)).abs() < 1e-12 && (col[2] - t).abs() < 1e-12);
        }
    }
    // Outside gluBeginCurve: drawn on its own.
    unsafe { n.nurbs_curve(4, k.as_mut_ptr(), 3, c.as_mut_ptr(), 2, GL_MAP1_VERTEX_3) };
    assert_eq!(rec.borrow().prims.len(), 2);
    assert!(take_errors().is_empty());
}

/// A surface through the recorder: (knots u, knots v, control, orders, type).
#[allow(clippy::too_many_arguments)]
fn surface(n: &mut Nurbs, ku: &[f32], kv: &[f32], ctl: &[f32], stride: [i32; 2], order: [i32; 2], t: u32) {
    let (mut ku, mut kv, mut ctl) = (ku.to_vec(), kv.to_vec(), ctl.to_vec());
    unsafe { n.nurbs_surface(ku.len() as i32, ku.as_mut_ptr(), kv.len() as i32, kv.as_mut_ptr(), stride[0], stride[1], ctl.as_mut_ptr(), order[0], order[1], t) };
}

#[test]
fn cylinder_patch_vertices_and_normals() {
    let (mut n, rec) = nurbs();
    n.set_property(GLU_SAMPLING_METHOD, GLU_OBJECT_PARAMETRIC_ERROR as f32);
    n.set_property(GLU_PARAMETRIC_TOLERANCE, 0.001);
    // A quarter cylinder of radius 3, z from 0 to 2: u quadratic rational, v linear.
    let quarter = [(3.0f32, 0.0f32, 1.0f32), (3.0, 3.0, H), (0.0, 3.0, 1.0)];
    let mut ctl = vec![];
    for &(x, y, w) in &quarter {
        for z in [0.0f32, 2.0] {
            ctl.extend([x * w, y * w, z * w, w]);
        }
    }
    n.begin_surface();
    surface(&mut n, &[0.0, 0.0, 0.0, 1.0, 1.0, 1.0], &[0.0, 0.0, 1.0, 1.0], &ctl, [8, 4], [3, 2], GL_MAP2_VERTEX_4);
    n.end_surface();
    assert!(take_errors().is_empty());
    let r = rec.borrow();
    assert!(r.prims.iter().all(|p| p.0 == GL_TRIANGLE_STRIP));
    let verts: Vec<[f64; 3]> = r.prims.iter().flat_map(|p| p.1.clone()).collect();
    assert!(verts.len() >= 20);
    assert_eq!(r.normals.len(), verts.len());
    for (p, nn) in verts.iter().zip(&r.normals) {
        assert!(((p[0] * p[0] + p[1] * p[1]).sqrt() - 3.0).abs() < 1e-6, "{p:?}");
        assert!(p[0] >= -1e-9 && p[1] >= -1e-9 && p[2] >= -1e-9 && p[2] <= 2.0 + 1e-9);
        // dS/du x dS/dv points outwards here.
        let radial = [p[0] / 3.0, p[1] / 3.0, 0.0];
        assert!(dist(*nn, radial) < 1e-6, "normal {nn:?} at {p:?}");
    }
    // The chord error of the sampled arc is within the tolerance: the
    // midpoint of each edge along the arc is at most 0.001 inside.
    for prim in &r.prims {
        for w in prim.1.chunks(2).collect::<Vec<_>>().windows(2) {
            let m = [(w[0][0][0] + w[1][0][0]) / 2.0, (w[0][0][1] + w[1][0][1]) / 2.0, 0.0];
            assert!(3.0 - norm(m) <= 0.001 + 1e-9, "chord error {}", 3.0 - norm(m));
        }
    }
}

#[test]
fn sphere_vertices_and_normals() {
    let (mut n, rec) = nurbs();
    n.set_property(GLU_SAMPLING_METHOD, GLU_DOMAIN_DISTANCE as f32);
    n.set_property(GLU_U_STEP, 4.0);
    n.set_property(GLU_V_STEP, 4.0);
    let (ku, circ) = circle(1.0);
    // Half circle from the south pole to the north in (r, z), homogeneous.
    let prof = [(0.0f32, -1.0f32, 1.0f32), (1.0, -1.0, H), (1.0, 0.0, 1.0), (1.0, 1.0, H), (0.0, 1.0, 1.0)];
    let kv = [0.0f32, 0.0, 0.0, 1.0, 1.0, 2.0, 2.0, 2.0];
    let r = 5.0f32;
    let mut ctl = vec![];
    for i in 0..9 {
        let (cx, cy, cw) = (circ[4 * i] / circ[4 * i + 3], circ[4 * i + 1] / circ[4 * i + 3], circ[4 * i + 3]);
        for &(pr, pz, pw) in &prof {
            let w = cw * pw;
            ctl.extend([cx * pr * r * w, cy * pr * r * w, pz * r * w, w]);
        }
    }
    n.begin_surface();
    surface(&mut n, &ku, &kv, &ctl, [20, 4], [3, 3], GL_MAP2_VERTEX_4);
    n.end_surface();
    assert!(take_errors().is_empty());
    let rr = rec.borrow();
    let verts: Vec<[f64; 3]> = rr.prims.iter().flat_map(|p| p.1.clone()).collect();
    assert!(verts.len() > 100);
    let mut sign = 0.0;
    for (p, nn) in verts.iter().zip(&rr.normals) {
        assert!((norm(*p) - 5.0).abs() < 1e-5, "{p:?} off the sphere");
        assert!((norm(*nn) - 1.0).abs() < 1e-9);
        let d = (nn[0] * p[0] + nn[1] * p[1] + nn[2] * p[2]) / 5.0;
        assert!(d.abs() > 1.0 - 1e-4, "normal {nn:?} at {p:?} not radial ({d})");
        if sign == 0.0 {
            sign = d.signum();
        }
        assert_eq!(d.signum(), sign, "normals flip at {p:?}");
    }
}

/// Sum of the signed (x, y) areas of the triangles.
fn triangles_area(r: &Rec) -> (f64, usize) {
    let mut a = 0.0;
    let mut negative = 0;
    for (mode, v) in &r.prims {
        assert_eq!(*mode, GL_TRIANGLES);
        for t in v.chunks(3) {
            let s = ((t[1][0] - t[0][0]) * (t[2][1] - t[0][1]) - (t[2][0] - t[0][0]) * (t[1][1] - t[0][1])) / 2.0;
            if s < -1e-15 {
                negative += 1;
            }
            a += s;
        }
    }
    (a, negative)
}

fn plane(n: &mut Nurbs) {
    // x = u, y = v over [0, 1]^2.
    surface(n, &[0.0, 0.0, 1.0, 1.0], &[0.0, 0.0, 1.0, 1.0], &[0.0, 0.0, 0.0, 0.0, 1.0, 0.0, 1.0, 0.0, 0.0, 1.0, 1.0, 0.0], [6, 3], [2, 2], GL_MAP2_VERTEX_3);
}

fn pwl(n: &mut Nurbs, pts: &[[f32; 2]]) {
    let mut d: Vec<f32> = pts.iter().flatten().copied().collect();
    unsafe { n.pwl_curve(pts.len() as i32, d.as_mut_ptr(), 2, GLU_MAP1_TRIM_2) };
}

#[test]
fn trimmed_square_with_a_square_hole() {
    for with_outer in [true, false] {
        let (mut n, rec) = nurbs();
        n.set_property(GLU_SAMPLING_METHOD, GLU_DOMAIN_DISTANCE as f32);
        n.set_property(GLU_U_STEP, 10.0);
        n.set_property(GLU_V_STEP, 10.0);
        n.begin_surface();
        plane(&mut n);
        if with_outer {
            n.begin_trim();
            pwl(&mut n, &[[0.0, 0.0], [1.0, 0.0], [1.0, 1.0], [0.0, 1.0], [0.0, 0.0]]);
            n.end_trim();
        }
        n.begin_trim();
        // Clockwise: a hole; in two pieces joined end to end.
        pwl(&mut n, &[[0.25, 0.25], [0.25, 0.75], [0.75, 0.75]]);
        pwl(&mut n, &[[0.75, 0.75], [0.75, 0.25], [0.25, 0.25]]);
        n.end_trim();
        n.end_surface();
        assert!(take_errors().is_empty());
        let (a, neg) = triangles_area(&rec.borrow());
        assert!((a - 0.75).abs() < 1e-9, "area {a} (outer loop {with_outer})");
        assert_eq!(neg, 0);
    }
}

#[test]
fn trimmed_by_a_nurbs_circle() {
    let (mut n, rec) = nurbs();
    n.set_property(GLU_SAMPLING_METHOD, GLU_DOMAIN_DISTANCE as f32);
    n.set_property(GLU_U_STEP, 20.0);
    n.set_property(GLU_V_STEP, 20.0);
    // Keep only the disk of radius 0.3 around (0.5, 0.5): a counter-clockwise
    // rational circle as a GLU_MAP1_TRIM_3 curve.
    let (k, c) = circle(0.3);
    let mut trim: Vec<f32> = c.chunks(4).flat_map(|p| [p[0] + 0.5 * p[3], p[1] + 0.5 * p[3], p[3]]).collect();
    let mut k = k.clone();
    n.begin_surface();
    plane(&mut n);
    n.begin_trim();
    unsafe { n.nurbs_curve(12, k.as_mut_ptr(), 3, trim.as_mut_ptr(), 3, GLU_MAP1_TRIM_3) };
    n.end_trim();
    n.end_surface();
    assert!(take_errors().is_empty());
    let (a, neg) = triangles_area(&rec.borrow());
    let want = std::f64::consts::PI * 0.09;
    assert!((a - want).abs() < 0.002 * want, "area {a}, disk {want}");
    assert_eq!(neg, 0);
    // Every vertex within the disk (up to the polyline's sagitta).
    for p in rec.borrow().prims.iter().flat_map(|p| p.1.clone()) {
        assert!(dist(p, [0.5, 0.5, 0.0]) <= 0.3 + 1e-6);
    }
}

#[test]
fn path_length_in_pixels_through_the_sampling_matrices() {
    let (mut n, rec) = nurbs();
    // Ortho (-10, 10) onto a 200-pixel viewport: 10 pixels per unit.
    let model: [f32; 16] = [1.0, 0.0, 0.0, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0, 0.0, 1.0];
    let mut proj = model;
    proj[0] = 0.1;
    proj[5] = 0.1;
    let view = [0, 0, 200, 200];
    unsafe { n.load_sampling_matrices(model.as_ptr(), proj.as_ptr(), view.as_ptr()) };
    n.set_property(GLU_SAMPLING_TOLERANCE, 5.0);
    let (mut k, mut c) = circle(4.0);
    unsafe { n.nurbs_curve(12, k.as_mut_ptr(), 4, c.as_mut_ptr(), 3, GL_MAP1_VERTEX_4) };
    let r = rec.borrow();
    let v = &r.prims[0].1;
    // 8 pi units = 251 pixels: at least 51 edges of at most 5 pixels.
    assert!(v.len() > 51);
    for w in v.windows(2) {
        assert!(dist(w[0], w[1]) * 10.0 <= 5.0 + 1e-9);
    }
    // Culling: a curve wholly right of the view draws nothing.
    drop(r);
    n.set_property(GLU_CULLING, 1.0);
    let mut c2: Vec<f32> = c.chunks(4).flat_map(|p| [p[0] + 20.0 * p[3], p[1], p[2], p[3]]).collect();
    unsafe { n.nurbs_curve(12, k.as_mut_ptr(), 4, c2.as_mut_ptr(), 3, GL_MAP1_VERTEX_4) };
    assert_eq!(rec.borrow().prims.len(), 1);
}

#[test]
fn display_modes() {
    for (mode, prim) in [(GLU_OUTLINE_POLYGON, GL_LINE_LOOP), (GLU_OUTLINE_PATCH, GL_LINE_STRIP)] {
        let (mut n, rec) = nurbs();
        n.set_property(GLU_SAMPLING_METHOD, GLU_DOMAIN_DISTANCE as f32);
        n.set_property(GLU_U_STEP, 2.0);
        n.set_property(GLU_V_STEP, 2.0);
        n.set_property(GLU_DISPLAY_MODE, mode as f32);
        n.begin_surface();
        plane(&mut n);
        n.end_surface();
        let r = rec.borrow();
        assert!(r.prims.iter().all(|p| p.0 == prim));
        // 2x2 cells: 8 triangles, or the 4 edges of the patch.
        assert_eq!(r.prims.len(), if mode == GLU_OUTLINE_POLYGON { 8 } else { 4 });
    }
}

#[test]
fn properties() {
    let n = Nurbs::default();
    assert_eq!(n.get_property(GLU_SAMPLING_TOLERANCE), Some(50.0));
    assert_eq!(n.get_property(GLU_PARAMETRIC_TOLERANCE), Some(0.5));
    assert_eq!(n.get_property(GLU_U_STEP), Some(100.0));
    assert_eq!(n.get_property(GLU_V_STEP), Some(100.0));
    assert_eq!(n.get_property(GLU_SAMPLING_METHOD), Some(GLU_PATH_LENGTH as f32));
    assert_eq!(n.get_property(GLU_DISPLAY_MODE), Some(GLU_FILL as f32));
    assert_eq!(n.get_property(GLU_CULLING), Some(0.0));
    assert_eq!(n.get_property(GLU_AUTO_LOAD_MATRIX), Some(1.0));
    assert_eq!(n.get_property(GLU_NURBS_MODE), Some(GLU_NURBS_RENDERER as f32));
    let (mut n, _) = nurbs();
    n.set_property(GLU_NURBS_MODE, GLU_NURBS_TESSELLATOR as f32);
    assert_eq!(n.get_property(GLU_NURBS_MODE), Some(GLU_NURBS_TESSELLATOR as f32));
    n.set_property(GLU_SAMPLING_TOLERANCE, -1.0);
    n.set_property(GLU_DISPLAY_MODE, 5.0);
    n.set_property(100110, 1.0);
    assert_eq!(n.get_property(4242), None);
    assert_eq!(take_errors(), vec![GLU_INVALID_VALUE, GLU_INVALID_VALUE, GLU_INVALID_ENUM, GLU_INVALID_ENUM]);
    assert_eq!(n.get_property(GLU_SAMPLING_TOLERANCE), Some(50.0));
}

#[test]
fn errors_through_the_callback() {
    let (mut n, rec) = nurbs();
    let e = |k: u32| GLU_NURBS_ERROR1 + k - 1;
    let mut k = [0.0f32, 0.0, 1.0, 1.0];
    let mut bad = [0.0f32, 1.0, 0.5, 1.0];
    let mut c = [0.0f32; 12];
    n.end_curve();
    n.begin_trim();
    n.end_trim();
    pwl(&mut n, &[[0.0, 0.0]]);
    n.end_surface();
    unsafe {
        n.begin_curve();
        n.begin_curve();
        n.nurbs_curve(4, bad.as_mut_ptr(), 3, c.as_mut_ptr(), 2, GL_MAP1_VERTEX_3);
        n.end_curve();
        n.begin_curve();
        n.nurbs_curve(4, k.as_mut_ptr(), 3, c.as_mut_ptr(), 2, GLU_MAP1_TRIM_2);
        n.nurbs_curve(4, k.as_mut_ptr(), -3, c.as_mut_ptr(), 2, GL_MAP1_VERTEX_3);
        n.end_curve();
        n.begin_curve();
        n.nurbs_curve(4, k.as_mut_ptr(), 3, c.as_mut_ptr(), 2, 0x1234);
        n.end_curve();
        n.begin_curve();
        n.end_curve();
    }
    assert_eq!(take_errors(), vec![e(7), e(15), e(17), e(19), e(13), e(6), e(4), e(22), e(34), e(35), e(8)]);
    // Trims: unconnected pieces, a non-trim curve inside a trim, nesting.
    n.begin_surface();
    plane(&mut n);
    n.begin_trim();
    n.begin_trim();
    pwl(&mut n, &[[0.0, 0.0], [1.0, 0.0]]);
    pwl(&mut n, &[[1.0, 1.0], [0.0, 0.0]]);
    unsafe { n.nurbs_curve(4, k.as_mut_ptr(), 3, c.as_mut_ptr(), 2, GL_MAP1_VERTEX_3) };
    n.end_trim();
    n.end_surface();
    assert_eq!(take_errors(), vec![e(16), e(14)]);
    n.begin_surface();
    plane(&mut n);
    n.begin_trim();
    pwl(&mut n, &[[0.0, 0.0], [1.0, 0.0]]);
    pwl(&mut n, &[[1.0, 1.0], [0.0, 0.0]]);
    n.end_trim();
    n.end_surface();
    assert_eq!(take_errors(), vec![e(31)]);
    assert!(rec.borrow().prims.is_empty());
    // gluEndSurface inside a trim.
    n.begin_surface();
    plane(&mut n);
    n.begin_trim();
    n.end_surface();
    assert_eq!(take_errors(), vec![e(12)]);
}

// ---- GLU_NURBS_TESSELLATOR through the C entry points ----

#[derive(Default)]
struct Calls {
    begins: Vec<u32>,
    ends: usize,
    vertices: Vec<[f32; 3]>,
    normals: Vec<[f32; 3]>,
    colors: Vec<[f32; 4]>,
    data: Vec<usize>,
}
thread_local! {
    static CALLS: RefCell<Calls> = RefCell::new(Calls::default());
}
unsafe extern "system" fn cb_begin(t: u32) {
    CALLS.with(|c| c.borrow_mut().begins.push(t));
}
unsafe extern "system" fn cb_end_data(d: *mut c_void) {
    CALLS.with(|c| {
        let mut c = c.borrow_mut();
        c.ends += 1;
        c.data.push(d as usize);
    });
}
unsafe extern "system" fn cb_vertex(v: *mut f32) {
    CALLS.with(|c| c.borrow_mut().vertices.push([*v, *v.add(1), *v.add(2)]));
}
unsafe extern "system" fn cb_normal_data(v: *mut f32, d: *mut c_void) {
    CALLS.with(|c| {
        let mut c = c.borrow_mut();
        c.normals.push([*v, *v.add(1), *v.add(2)]);
        c.data.push(d as usize);
    });
}
unsafe extern "system" fn cb_color(v: *mut f32) {
    CALLS.with(|c| c.borrow_mut().colors.push([*v, *v.add(1), *v.add(2), *v.add(3)]));
}

fn proc<T>(f: T) -> Option<unsafe extern "system" fn()> {
    Some(unsafe { std::mem::transmute_copy::<T, unsafe extern "system" fn()>(&f) })
}

#[test]
fn tessellator_callbacks() {
    unsafe {
        let n = gluNewNurbsRenderer();
        assert!(!n.is_null());
        gluNurbsProperty(n, GLU_NURBS_MODE, GLU_NURBS_TESSELLATOR as f32);
        gluNurbsProperty(n, GLU_SAMPLING_METHOD, GLU_DOMAIN_DISTANCE as f32);
        gluNurbsProperty(n, GLU_U_STEP, 3.0);
        gluNurbsProperty(n, GLU_V_STEP, 2.0);
        gluNurbsProperty(n, GLU_AUTO_LOAD_MATRIX, 0.0);
        gluNurbsCallback(n, GLU_NURBS_BEGIN, proc(cb_begin as unsafe extern "system" fn(u32)));
        gluNurbsCallback(n, GLU_NURBS_VERTEX, proc(cb_vertex as unsafe extern "system" fn(*mut f32)));
        gluNurbsCallback(n, GLU_NURBS_NORMAL_DATA, proc(cb_normal_data as unsafe extern "system" fn(*mut f32, *mut c_void)));
        gluNurbsCallback(n, GLU_NURBS_COLOR, proc(cb_color as unsafe extern "system" fn(*mut f32)));
        gluNurbsCallback(n, GLU_NURBS_END_DATA, proc(cb_end_data as unsafe extern "system" fn(*mut c_void)));
        gluNurbsCallbackData(n, 0x1234 as *mut c_void);
        let mut k = [0.0f32, 0.0, 1.0, 1.0];
        // A plane z = 1 with x = 2u, y = v, coloured red = u, green = v.
        let mut pos = [0.0f32, 0.0, 1.0, 0.0, 1.0, 1.0, 2.0, 0.0, 1.0, 2.0, 1.0, 1.0];
        let mut col = [0.0f32, 0.0, 0.0, 1.0, 0.0, 1.0, 0.0, 1.0, 1.0, 0.0, 0.0, 1.0, 1.0, 1.0, 0.0, 1.0];
        gluBeginSurface(n);
        gluNurbsSurface(n, 4, k.as_mut_ptr(), 4, k.as_mut_ptr(), 6, 3, pos.as_mut_ptr(), 2, 2, GL_MAP2_VERTEX_3);
        gluNurbsSurface(n, 4, k.as_mut_ptr(), 4, k.as_mut_ptr(), 8, 4, col.as_mut_ptr(), 2, 2, GL_MAP2_COLOR_4);
        gluEndSurface(n);
        let mut data = 0f32;
        gluGetNurbsProperty(n, GLU_U_STEP, &mut data);
        assert_eq!(data, 3.0);
        gluDeleteNurbsRenderer(n);
    }
    CALLS.with(|c| {
        let c = c.borrow();
        // 3 x 2 cells: 2 strips of 4 columns of 2 vertices.
        assert_eq!(c.begins, vec![GL_TRIANGLE_STRIP; 2]);
        assert_eq!(c.ends, 2);
        assert_eq!(c.vertices.len(), 16);
        assert_eq!(c.normals.len(), 16);
        assert_eq!(c.colors.len(), 16);
        assert!(c.data.iter().all(|&d| d == 0x1234));
        for ((v, nn), col) in c.vertices.iter().zip(&c.normals).zip(&c.colors) {
            assert_eq!(v[2], 1.0);
            assert_eq!(*nn, [0.0, 0.0, 1.0]);
            assert!((col[0] - v[0] / 2.0).abs() < 1e-6 && (col[1] - v[1]).abs() < 1e-6, "{col:?} at {v:?}");
        }
        // The first strip starts at (u, v) = (0, 1/2), (0, 0), (1/3, 1/2): counter-clockwise.
        assert_eq!(c.vertices[0], [0.0, 0.5, 1.0]);
        assert_eq!(c.vertices[1], [0.0, 0.0, 1.0]);
    });
}
