//! GLU quadrics (GLU 1.3 section 6): gluNewQuadric / gluDeleteQuadric, the
//! four shapes (gluSphere, gluCylinder, gluDisk, gluPartialDisk) and the
//! quadric state (normals, texture coordinates, orientation, draw style and
//! the error callback).
//!
//! Every shape is a grid of points `(col, row)`: `col` runs around the z axis
//! (slices), `row` along the shape (stacks, or loops for disks). Angles are
//! measured from +y towards +x, as the man pages specify texture s (0 at +y,
//! 0.25 at +x) and partial-disk angles (0 degrees along +y, 90 along +x).
//!
//! - sphere: row 0 at z = +radius (the +z pole), row `stacks` at -radius;
//!   s = col/slices, t = 1 - row/stacks (0 at z = -radius, 1 at +radius).
//! - cylinder: row 0 at z = 0 (radius `base`), row `stacks` at z = height
//!   (radius `top`); s = col/slices, t = row/stacks.
//! - disks: in the z = 0 plane, row 0 at `inner`, row `loops` at `outer`;
//!   s = 0.5 + x / (2 outer), t = 0.5 + y / (2 outer).
//!
//! Draw styles. GLU_FILL: one GL_QUAD_STRIP per stack (per loop), its faces
//! counter-clockwise seen from the outside for GLU_OUTSIDE (from +z for
//! disks), clockwise for GLU_INSIDE. GLU_LINE: a line loop (line strip for a
//! partial disk) at every row of non-zero radius, and a line strip along every
//! slice. GLU_SILHOUETTE: GLU_LINE without the edges between coplanar faces:
//! the sphere draws as GLU_LINE; the cylinder keeps its end circles and its
//! slice lines; a disk keeps its outer and inner (non-zero) circles, and a
//! partial disk of less than 360 degrees its two straight edges too.
//! GLU_POINT: GL_POINTS, each distinct grid point once.
//!
//! Normals: GLU_SMOOTH gives each vertex the surface normal there; GLU_FLAT
//! gives each face of a filled shape the normal of its plane (set before the
//! vertex pair that completes the face, the vertex GL's flat shading reads),
//! and points and lines their vertex normals; GLU_NONE emits no normals.
//! Normals point away from the centre (sphere), from the z axis (cylinder) or
//! along +z (disks) for GLU_OUTSIDE, the other way for GLU_INSIDE.
//!
//! Emission goes through [`Sink`], whose default [`GlSink`] calls the public
//! GL entry points; tests record it instead.

use crate::api::table as gl;
use crate::api::types::*;
use crate::gl::enums::*;
use crate::glu::strings::{GLU_INVALID_ENUM, GLU_INVALID_VALUE};
use std::ffi::c_void;

pub const GLU_SMOOTH: GLenum = 100000;
pub const GLU_FLAT: GLenum = 100001;
pub const GLU_NONE: GLenum = 100002;
pub const GLU_POINT: GLenum = 100010;
pub const GLU_LINE: GLenum = 100011;
pub const GLU_FILL: GLenum = 100012;
pub const GLU_SILHOUETTE: GLenum = 100013;
pub const GLU_OUTSIDE: GLenum = 100020;
pub const GLU_INSIDE: GLenum = 100021;
pub const GLU_ERROR: GLenum = 100103;

/// The GLU_ERROR callback: `void (GLAPIENTRY *)(GLenum)`.
pub type ErrorCallback = unsafe extern "system" fn(GLenum);

/// Where a quadric's primitives go.
pub trait Sink {
    fn begin(&mut self, mode: GLenum);
    fn end(&mut self);
    fn vertex(&mut self, p: [f64; 3]);
    fn normal(&mut self, n: [f64; 3]);
    fn tex_coord(&mut self, s: f64, t: f64);
}

/// The public GL entry points.
pub struct GlSink;

impl Sink for GlSink {
    fn begin(&mut self, mode: GLenum) {
        unsafe { gl::glBegin(mode) }
    }
    fn end(&mut self) {
        unsafe { gl::glEnd() }
    }
    fn vertex(&mut self, p: [f64; 3]) {
        unsafe { gl::glVertex3d(p[0], p[1], p[2]) }
    }
    fn normal(&mut self, n: [f64; 3]) {
        unsafe { gl::glNormal3d(n[0], n[1], n[2]) }
    }
    fn tex_coord(&mut self, s: f64, t: f64) {
        unsafe { gl::glTexCoord2d(s, t) }
    }
}

/// A quadric object's state.
#[derive(Clone, Copy, Debug)]
pub struct Quadric {
    pub normals: GLenum,
    pub texture: bool,
    pub orientation: GLenum,
    pub draw_style: GLenum,
    pub error: Option<ErrorCallback>,
}

impl Default for Quadric {
    fn default() -> Self {
        Quadric { normals: GLU_SMOOTH, texture: false, orientation: GLU_OUTSIDE, draw_style: GLU_FILL, error: None }
    }
}

/// One grid point: position, unit outward normal, texture coordinates.
#[derive(Clone, Copy)]
struct Pt {
    p: [f64; 3],
    n: [f64; 3],
    t: [f64; 2],
}

use super::vec3::{cross, dot, sub};
fn normalize(a: [f64; 3]) -> Option<[f64; 3]> {
    let l = dot(a, a).sqrt();
    (l > 0.0 && l.is_finite()).then(|| [a[0] / l, a[1] / l, a[2] / l])
}
fn neg(a: [f64; 3]) -> [f64; 3] {
    [-a[0], -a[1], -a[2]]
}

/// sin and cos of the angle of column `i` of `n` around a full circle,
/// exact at the quarter turns and at the seam (column n = column 0).
fn around(i: usize, n: usize) -> (f64, f64) {
    let i = i % n;
    if (4 * i).is_multiple_of(n) {
        return [(0.0, 1.0), (1.0, 0.0), (0.0, -1.0), (-1.0, 0.0)][4 * i / n];
    }
    (std::f64::consts::TAU * i as f64 / n as f64).sin_cos()
}

/// A shape as a grid, with the fill order of its strips.
struct Grid<'a> {
    cols: usize,
    rows: usize,
    /// Column `cols` is column 0 again (a full turn).
    closed: bool,
    at: &'a dyn Fn(usize, usize) -> Pt,
    /// For GLU_OUTSIDE the strips take row j+1 before row j (else j first).
    upper_first: bool,
}

struct Emit<'a> {
    q: &'a Quadric,
    sink: &'a mut dyn Sink,
}

impl Emit<'_> {
    fn inside(&self) -> bool {
        self.q.orientation == GLU_INSIDE
    }
    fn oriented(&self, n: [f64; 3]) -> [f64; 3] {
        if self.inside() { neg(n) } else { n }
    }
    /// A vertex, with its own normal when `normal` (smooth normals, or any
    /// normals for points and lines).
    fn vertex(&mut self, pt: Pt, normal: bool) {
        if normal && self.q.normals != GLU_NONE {
            let n = self.oriented(pt.n);
            self.sink.normal(n);
        }
        if self.q.texture {
            self.sink.tex_coord(pt.t[0], pt.t[1]);
        }
        self.sink.vertex(pt.p);
    }

    /// The plane normal of face (i, j) (corners at columns i, i+1 and rows
    /// j, j+1), oriented like the surface there.
    fn face_normal(&self, g: &Grid, i: usize, j: usize) -> [f64; 3] {
        let (a, b, c, d) = ((g.at)(i, j), (g.at)(i + 1, j), (g.at)(i, j + 1), (g.at)(i + 1, j + 1));
        let mean = [0, 1, 2].map(|k| a.n[k] + b.n[k] + c.n[k] + d.n[k]);
        let mean = normalize(mean).unwrap_or(a.n);
        let n = match normalize(cross(sub(d.p, a.p), sub(c.p, b.p))) {
            Some(n) if dot(n, mean) < 0.0 => neg(n),
            Some(n) => n,
            None => mean,
        };
        self.oriented(n)
    }

    fn fill(&mut self, g: &Grid) {
        let smooth = self.q.normals == GLU_SMOOTH;
        let flat = self.q.normals == GLU_FLAT;
        let upper_first = g.upper_first != self.inside();
        for j in 0..g.rows {
            let (r0, r1) = if upper_first { (j + 1, j) } else { (j, j + 1) };
            self.sink.begin(GL_QUAD_STRIP);
            for i in 0..=g.cols {
                if flat {
                    let n = self.face_normal(g, i.saturating_sub(1), j);
                    self.sink.normal(n);
                }
                self.vertex((g.at)(i, r0), smooth);
                self.vertex((g.at)(i, r1), smooth);
            }
            self.sink.end();
        }
    }

    /// Row j as a line loop (closed grid) or strip.
    fn row_line(&mut self, g: &Grid, j: usize) {
        if g.closed {
            self.sink.begin(GL_LINE_LOOP);
            for i in 0..g.cols {
                self.vertex((g.at)(i, j), true);
            }
        } else {
            self.sink.begin(GL_LINE_STRIP);
            for i in 0..=g.cols {
                self.vertex((g.at)(i, j), true);
            }
        }
        self.sink.end();
    }

    /// Column i as a line strip across all rows.
    fn col_line(&mut self, g: &Grid, i: usize) {
        self.sink.begin(GL_LINE_STRIP);
        for j in 0..=g.rows {
            self.vertex((g.at)(i, j), true);
        }
        self.sink.end();
    }

    /// The columns a line drawing shows: all distinct ones.
    fn distinct_cols(g: &Grid) -> usize {
        if g.closed { g.cols } else { g.cols + 1 }
    }

    /// GL_POINTS: each distinct point once; a row of `degenerate(j)` (all its
    /// points in one place) as a single point.
    fn points(&mut self, g: &Grid, degenerate: &dyn Fn(usize) -> bool) {
        self.sink.begin(GL_POINTS);
        for j in 0..=g.rows {
            if degenerate(j) {
                self.vertex((g.at)(0, j), true);
                continue;
            }
            for i in 0..Self::distinct_cols(g) {
                self.vertex((g.at)(i, j), true);
            }
        }
        self.sink.end();
    }
}

impl Quadric {
    fn report(&self, code: GLenum) {
        if let Some(f) = self.error {
            // SAFETY: the application registered it as a GLU_ERROR callback.
            unsafe { f(code) }
        }
    }

    pub fn set_callback(&mut self, which: GLenum, f: GLproc) {
        match which {
            // SAFETY: GLU_ERROR callbacks take one GLenum (glu.h).
            GLU_ERROR => self.error = f.map(|f| unsafe { std::mem::transmute::<unsafe extern "system" fn(), ErrorCallback>(f) }),
            _ => self.report(GLU_INVALID_ENUM),
        }
    }
    pub fn set_draw_style(&mut self, e: GLenum) {
        match e {
            GLU_FILL | GLU_LINE | GLU_SILHOUETTE | GLU_POINT => self.draw_style = e,
            _ => self.report(GLU_INVALID_ENUM),
        }
    }
    pub fn set_normals(&mut self, e: GLenum) {
        match e {
            GLU_SMOOTH | GLU_FLAT | GLU_NONE => self.normals = e,
            _ => self.report(GLU_INVALID_ENUM),
        }
    }
    pub fn set_orientation(&mut self, e: GLenum) {
        match e {
            GLU_OUTSIDE | GLU_INSIDE => self.orientation = e,
            _ => self.report(GLU_INVALID_ENUM),
        }
    }
    pub fn set_texture(&mut self, on: bool) {
        self.texture = on;
    }

    pub fn sphere(&self, sink: &mut dyn Sink, radius: f64, slices: i32, stacks: i32) {
        if slices < 2 || stacks < 1 || radius < 0.0 || radius.is_nan() {
            return self.report(GLU_INVALID_VALUE);
        }
        let (cols, rows) = (slices as usize, stacks as usize);
        let at = |i: usize, j: usize| {
            // Polar angle from +z: exact at the poles and the equator.
            let (sp, cp) = if j == 0 {
                (0.0, 1.0)
            } else if j == rows {
                (0.0, -1.0)
            } else if 2 * j == rows {
                (1.0, 0.0)
            } else {
                (std::f64::consts::PI * j as f64 / rows as f64).sin_cos()
            };
            let (s, c) = around(i, cols);
            let n = [sp * s, sp * c, cp];
            Pt { p: n.map(|v| v * radius), n, t: [i as f64 / cols as f64, 1.0 - j as f64 / rows as f64] }
        };
        let g = Grid { cols, rows, closed: true, at: &at, upper_first: true };
        let mut e = Emit { q: self, sink };
        match self.draw_style {
            GLU_FILL => e.fill(&g),
            GLU_POINT => e.points(&g, &|j| j == 0 || j == rows),
            _ => {
                // GLU_LINE and GLU_SILHOUETTE: no two faces are coplanar.
                for j in 1..rows {
                    e.row_line(&g, j);
                }
                for i in 0..cols {
                    e.col_line(&g, i);
                }
            }
        }
    }

    pub fn cylinder(&self, sink: &mut dyn Sink, base: f64, top: f64, height: f64, slices: i32, stacks: i32) {
        if slices < 2 || stacks < 1 || !(base >= 0.0 && top >= 0.0 && height >= 0.0) {
            return self.report(GLU_INVALID_VALUE);
        }
        let (cols, rows) = (slices as usize, stacks as usize);
        // The side's normal in the (radial, z) plane: (height, base - top).
        let (nr, nz) = match normalize([height, base - top, 0.0]) {
            Some(v) => (v[0], v[1]),
            None => (1.0, 0.0),
        };
        let at = |i: usize, j: usize| {
            let f = j as f64 / rows as f64;
            let r = if j == rows { top } else { base + (top - base) * f };
            let z = if j == rows { height } else { height * f };
            let (s, c) = around(i, cols);
            Pt { p: [r * s, r * c, z], n: [nr * s, nr * c, nz], t: [i as f64 / cols as f64, f] }
        };
        let g = Grid { cols, rows, closed: true, at: &at, upper_first: false };
        let mut e = Emit { q: self, sink };
        match self.draw_style {
            GLU_FILL => e.fill(&g),
            GLU_POINT => e.points(&g, &|j| (if j == 0 { base } else if j == rows { top } else { base + (top - base) * j as f64 / rows as f64 }) == 0.0),
            style => {
                // GLU_SILHOUETTE: the faces of one slice are coplanar, so only
                // the end circles separate non-coplanar faces.
                for j in 0..=rows {
                    let r = if j == rows { top } else { base + (top - base) * j as f64 / rows as f64 };
                    if r != 0.0 && (style == GLU_LINE || j == 0 || j == rows) {
                        e.row_line(&g, j);
                    }
                }
                for i in 0..cols {
                    e.col_line(&g, i);
                }
            }
        }
    }

    pub fn disk(&self, sink: &mut dyn Sink, inner: f64, outer: f64, slices: i32, loops: i32) {
        self.disk_part(sink, inner, outer, slices, loops, 0.0, 360.0, true)
    }

    #[allow(clippy::too_many_arguments)]
    pub fn partial_disk(&self, sink: &mut dyn Sink, inner: f64, outer: f64, slices: i32, loops: i32, start: f64, sweep: f64) {
        self.disk_part(sink, inner, outer, slices, loops, start, sweep, false)
    }

    #[allow(clippy::too_many_arguments)]
    fn disk_part(&self, sink: &mut dyn Sink, inner: f64, outer: f64, slices: i32, loops: i32, start: f64, sweep: f64, whole: bool) {
        if slices < 2 || loops < 1 || !(inner >= 0.0 && outer >= inner) || !start.is_finite() || sweep.is_nan() {
            return self.report(GLU_INVALID_VALUE);
        }
        // A negative sweep covers the same region as its mirror.
        let (start, sweep) = if sweep < 0.0 { (start + sweep.max(-360.0), -sweep.max(-360.0)) } else { (start, sweep.min(360.0)) };
        let closed = whole || sweep >= 360.0;
        let (cols, rows) = (slices as usize, loops as usize);
        let radius = |j: usize| if j == rows { outer } else { inner + (outer - inner) * j as f64 / rows as f64 };
        let at = |i: usize, j: usize| {
            let (s, c) = if closed {
                around(i, cols)
            } else {
                (start + sweep * i as f64 / cols as f64).to_radians().sin_cos()
            };
            let r = radius(j);
            let (x, y) = (r * s, r * c);
            let t = if outer > 0.0 { [0.5 + x / (2.0 * outer), 0.5 + y / (2.0 * outer)] } else { [0.5, 0.5] };
            Pt { p: [x, y, 0.0], n: [0.0, 0.0, 1.0], t }
        };
        let g = Grid { cols, rows, closed, at: &at, upper_first: true };
        let mut e = Emit { q: self, sink };
        match self.draw_style {
            GLU_FILL => e.fill(&g),
            GLU_POINT => e.points(&g, &|j| radius(j) == 0.0),
            GLU_LINE => {
                for j in 0..=rows {
                    if radius(j) != 0.0 {
                        e.row_line(&g, j);
                    }
                }
                for i in 0..Emit::distinct_cols(&g) {
                    e.col_line(&g, i);
                }
            }
            _ => {
                // GLU_SILHOUETTE: all faces are coplanar; only the boundary.
                for j in [0, rows] {
                    if radius(j) != 0.0 {
                        e.row_line(&g, j);
                    }
                }
                if !closed {
                    e.col_line(&g, 0);
                    e.col_line(&g, cols);
                }
            }
        }
    }
}

// ---- the C entry points ----

pub fn new_quadric() -> *mut c_void {
    Box::into_raw(Box::new(Quadric::default())) as *mut c_void
}

/// # Safety
/// `q` is NULL or a quadric from [`new_quadric`] not yet deleted.
pub unsafe fn delete_quadric(q: *mut c_void) {
    if !q.is_null() {
        drop(Box::from_raw(q as *mut Quadric));
    }
}

/// # Safety
/// As [`delete_quadric`]; a NULL quadric makes every call a no-op.
pub unsafe fn with(q: *mut c_void, f: impl FnOnce(&mut Quadric)) {
    if let Some(q) = (q as *mut Quadric).as_mut() {
        f(q)
    }
}
