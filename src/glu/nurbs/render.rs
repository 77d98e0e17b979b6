//! Sampling, trimming and emission of NURBS curves and surfaces.
//!
//! Sampling. The parameter range is cut at every distinct knot; each span
//! gets N uniform segments, N from the span's control points (those that
//! influence it) and the sampling method:
//! - GLU_PATH_LENGTH / GLU_OBJECT_PATH_LENGTH: the control polygon's length
//!   in window (pixels, through the sampling matrices) or object units,
//!   divided by GLU_SAMPLING_TOLERANCE (the polygon bounds the curve's
//!   length, so no edge is longer than the tolerance);
//! - GLU_PARAMETRIC_ERROR / GLU_OBJECT_PARAMETRIC_ERROR: the chord-error
//!   bound of a degree-p polynomial sampled at N points,
//!   p (p - 1) max|second difference| / (8 N^2) <= GLU_PARAMETRIC_TOLERANCE;
//! - GLU_DOMAIN_DISTANCE: GLU_U_STEP (GLU_V_STEP) segments per parameter unit.
//!
//! For a surface, the u segments of a span are the most any row of control
//! points asks for, and likewise in v. N is at least 1 and at most 1024
//! per span; a control point behind the eye gives 64.
//!
//! Trimming (GLU 1.3 section 7.2): the loops, in (u, v), keep the region of
//! winding number >= 1 (the left of each curve: counter-clockwise outer
//! loops, clockwise holes); when all loops together are clockwise, the
//! domain's boundary is added as an outer loop. A first, simple approach:
//! the sampling grid's cells that no trim edge crosses are kept whole or
//! dropped by their centre; a crossed cell is split 4x4 and each piece not
//! crossed again goes by its centre, while the crossed pieces are cut
//! along the trim edges (marching triangles: each triangle edge whose ends
//! differ is cut where it meets the trim polyline). Corners of trim loops
//! inside a smallest piece are cut off; the area error is within a
//! fraction of a sixteenth of a cell per crossed cell.

use super::bspline::{self, de_boor, dehomogenize};
use super::*;

type P3 = [f64; 3];

use super::super::vec3::{cross, norm, sub};

const MAX_SEGMENTS: usize = 1024;

pub struct Renderer {
    pub method: GLenum,
    pub tolerance: f64,
    pub step: [f64; 2],
    pub display: GLenum,
    pub culling: bool,
    pub m: Matrices,
}

fn mat_vec(m: &[f64; 16], v: [f64; 4]) -> [f64; 4] {
    [0, 1, 2, 3].map(|r| (0..4).map(|c| m[c * 4 + r] * v[c]).sum())
}

impl Renderer {
    /// A control point in the space the sampling method measures, None if
    /// it cannot be placed there (behind the eye, w <= 0).
    fn measure_point(&self, p: [f64; 4]) -> Option<P3> {
        match self.method {
            GLU_PATH_LENGTH | GLU_PARAMETRIC_ERROR => {
                let c = mat_vec(&self.m.proj, mat_vec(&self.m.model, p));
                if c[3] <= 0.0 {
                    return None;
                }
                let v = &self.m.viewport;
                Some([v[0] + (c[0] / c[3] + 1.0) * v[2] / 2.0, v[1] + (c[1] / c[3] + 1.0) * v[3] / 2.0, 0.0])
            }
            _ => (p[3] > 0.0).then(|| [p[0] / p[3], p[1] / p[3], p[2] / p[3]]),
        }
    }

    /// Segments for one span whose control points are `pts`, of `degree`,
    /// over a parameter length `dl`, in direction `dir` (0 = u, 1 = v).
    fn segments(&self, pts: &[[f64; 4]], degree: usize, dl: f64, dir: usize) -> usize {
        let n = if self.method == GLU_DOMAIN_DISTANCE {
            (self.step[dir] * dl).ceil()
        } else {
            let q: Option<Vec<P3>> = pts.iter().map(|&p| self.measure_point(p)).collect();
            let Some(q) = q else { return 64 };
            match self.method {
                GLU_PATH_LENGTH | GLU_OBJECT_PATH_LENGTH => {
                    let l: f64 = q.windows(2).map(|w| norm(sub(w[1], w[0]))).sum();
                    (l / self.tolerance).ceil()
                }
                _ => {
                    if degree < 2 {
                        1.0
                    } else {
                        let d = q.windows(3).map(|w| norm([0, 1, 2].map(|k| w[2][k] - 2.0 * w[1][k] + w[0][k]))).fold(0.0, f64::max);
                        (degree as f64 * (degree - 1) as f64 * d / (8.0 * self.tolerance)).sqrt().ceil()
                    }
                }
            }
        };
        if n.is_nan() { 1 } else { (n as usize).clamp(1, MAX_SEGMENTS) }
    }

    /// Sample parameters along one direction: every breakpoint, and the
    /// segments of each span (`count(span index i, lo, hi)`).
    fn params(knots: &[f64], order: usize, count: &dyn Fn(usize, f64, f64) -> usize) -> Vec<f64> {
        let bp = bspline::breakpoints(knots, order);
        let mut out = vec![bp[0]];
        for w in bp.windows(2) {
            let i = bspline::span(knots, order, (w[0] + w[1]) / 2.0);
            let n = count(i, w[0], w[1]);
            for s in 1..n {
                out.push(w[0] + (w[1] - w[0]) * s as f64 / n as f64);
            }
            out.push(w[1]);
        }
        out
    }

    /// True when every control point is outside one clip plane.
    fn culled(&self, pts: &[[f64; 4]]) -> bool {
        if !self.culling || pts.is_empty() {
            return false;
        }
        let c: Vec<[f64; 4]> = pts.iter().map(|&p| mat_vec(&self.m.proj, mat_vec(&self.m.model, p))).collect();
        (0..3).any(|k| c.iter().all(|v| v[k] > v[3]) || c.iter().all(|v| v[k] < -v[3]))
    }

    // ---- curves ----

    pub fn curve(&self, curves: &[Curve], sink: &mut dyn NurbsSink) {
        let Some(pos) = curves.iter().find(|c| c.role == Role::Position) else { return };
        if self.culled(&pos.pts) {
            return;
        }
        let p = pos.order - 1;
        let us = Self::params(&pos.knots, pos.order, &|i, lo, hi| self.segments(&pos.pts[i - p..=i], p, hi - lo, 0));
        let (a, b) = bspline::domain(&pos.knots, pos.order);
        sink.begin(GL_LINE_STRIP);
        for &u in &us {
            for c in curves.iter().filter(|c| c.role != Role::Position) {
                let (ca, cb) = bspline::domain(&c.knots, c.order);
                let cu = ca + (u - a) / (b - a) * (cb - ca);
                let (v, _) = de_boor(&c.knots, c.order, &|j| c.pts[j], cu);
                attribute(sink, c.role, &v[..c.dim]);
            }
            let (v, d) = de_boor(&pos.knots, pos.order, &|j| pos.pts[j], u);
            sink.vertex(dehomogenize(v, d).0);
        }
        sink.end();
    }

    // ---- surfaces ----

    pub fn surface(&self, surfaces: &[Surface], loops: &[Vec<TrimPiece>], sink: &mut dyn NurbsSink) {
        let Some(pos) = surfaces.iter().find(|s| s.role == Role::Position) else { return };
        if self.culled(&pos.pts) {
            return;
        }
        let [pu, pv] = pos.order.map(|o| o - 1);
        let us = Self::params(&pos.knots[0], pos.order[0], &|i, lo, hi| {
            (0..pos.nv).map(|j| self.segments(&(i - pu..=i).map(|r| pos.pts[r * pos.nv + j]).collect::<Vec<_>>(), pu, hi - lo, 0)).max().unwrap_or(1)
        });
        let vs = Self::params(&pos.knots[1], pos.order[1], &|i, lo, hi| {
            (0..pos.nu).map(|r| self.segments(&pos.pts[r * pos.nv + i - pv..=r * pos.nv + i], pv, hi - lo, 1)).max().unwrap_or(1)
        });
        let ev = Eval { surfaces, pos };
        if loops.is_empty() {
            self.untrimmed(&ev, &us, &vs, sink);
        } else {
            let (u0, u1) = bspline::domain(&pos.knots[0], pos.order[0]);
            let (v0, v1) = bspline::domain(&pos.knots[1], pos.order[1]);
            let cell = (us.windows(2).map(|w| w[1] - w[0]).fold(f64::INFINITY, f64::min)).min(vs.windows(2).map(|w| w[1] - w[0]).fold(f64::INFINITY, f64::min));
            let mut polys: Vec<Vec<[f64; 2]>> = loops.iter().map(|l| loop_polyline(l, cell)).collect();
            let area: f64 = polys.iter().map(|p| signed_area(p)).sum();
            if area < 0.0 {
                polys.push(vec![[u0, v0], [u1, v0], [u1, v1], [u0, v1]]);
            }
            let region = Region::new(polys);
            if self.display == GLU_OUTLINE_PATCH {
                for l in &region.loops {
                    sink.begin(GL_LINE_LOOP);
                    for &[u, v] in l {
                        ev.emit(sink, u, v);
                    }
                    sink.end();
                }
                return;
            }
            let mut tris = vec![];
            for j in 0..vs.len() - 1 {
                for i in 0..us.len() - 1 {
                    region.clip([us[i], vs[j], us[i + 1], vs[j + 1]], 2, &mut tris);
                }
            }
            if self.display == GLU_OUTLINE_POLYGON {
                for t in &tris {
                    sink.begin(GL_LINE_LOOP);
                    for &[u, v] in t {
                        ev.emit(sink, u, v);
                    }
                    sink.end();
                }
            } else if !tris.is_empty() {
                sink.begin(GL_TRIANGLES);
                for t in &tris {
                    for &[u, v] in t {
                        ev.emit(sink, u, v);
                    }
                }
                sink.end();
            }
        }
    }

    fn untrimmed(&self, ev: &Eval, us: &[f64], vs: &[f64], sink: &mut dyn NurbsSink) {
        match self.display {
            GLU_OUTLINE_PATCH => {
                let (nu, nv) = (us.len() - 1, vs.len() - 1);
                let edges: [Vec<[f64; 2]>; 4] = [
                    us.iter().map(|&u| [u, vs[0]]).collect(),
                    vs.iter().map(|&v| [us[nu], v]).collect(),
                    us.iter().rev().map(|&u| [u, vs[nv]]).collect(),
                    vs.iter().rev().map(|&v| [us[0], v]).collect(),
                ];
                for e in &edges {
                    sink.begin(GL_LINE_STRIP);
                    for &[u, v] in e {
                        ev.emit(sink, u, v);
                    }
                    sink.end();
                }
            }
            GLU_OUTLINE_POLYGON => {
                for j in 0..vs.len() - 1 {
                    for i in 0..us.len() - 1 {
                        for t in [[[us[i], vs[j]], [us[i + 1], vs[j]], [us[i + 1], vs[j + 1]]], [[us[i], vs[j]], [us[i + 1], vs[j + 1]], [us[i], vs[j + 1]]]] {
                            sink.begin(GL_LINE_LOOP);
                            for [u, v] in t {
                                ev.emit(sink, u, v);
                            }
                            sink.end();
                        }
                    }
                }
            }
            _ => {
                // Row j: a strip from (u0, v_j+1), (u0, v_j), (u1, v_j+1), ...:
                // counter-clockwise in (u, v).
                let grid: Vec<Vec<Vertex>> = vs.iter().map(|&v| us.iter().map(|&u| ev.vertex(u, v)).collect()).collect();
                for j in 0..vs.len() - 1 {
                    sink.begin(GL_TRIANGLE_STRIP);
                    for (upper, lower) in grid[j + 1].iter().zip(&grid[j]) {
                        upper.emit(sink);
                        lower.emit(sink);
                    }
                    sink.end();
                }
            }
        }
    }
}

fn attribute(sink: &mut dyn NurbsSink, role: Role, v: &[f64]) {
    match role {
        Role::Normal => sink.normal([v[0], v[1], v[2]]),
        Role::Color | Role::Index => sink.color(v),
        Role::TexCoord => sink.tex_coord(v),
        _ => {}
    }
}

/// An evaluated surface vertex.
struct Vertex {
    p: P3,
    n: P3,
    attrs: Vec<(Role, Vec<f64>)>,
}

impl Vertex {
    fn emit(&self, sink: &mut dyn NurbsSink) {
        sink.normal(self.n);
        for (r, a) in &self.attrs {
            attribute(sink, *r, a);
        }
        sink.vertex(self.p);
    }
}

struct Eval<'a> {
    surfaces: &'a [Surface],
    pos: &'a Surface,
}

/// S, dS/du, dS/dv (homogeneous) of a surface map at (u, v).
pub fn eval_surface(s: &Surface, u: f64, v: f64) -> ([f64; 4], [f64; 4], [f64; 4]) {
    let pu = s.order[0] - 1;
    let i = bspline::span(&s.knots[0], s.order[0], u);
    let mut q = vec![[0.0; 4]; s.nu];
    let mut dq = vec![[0.0; 4]; s.nu];
    for r in i - pu..=i {
        let row = &s.pts[r * s.nv..(r + 1) * s.nv];
        let (a, d) = de_boor(&s.knots[1], s.order[1], &|j| row[j], v);
        q[r] = a;
        dq[r] = d;
    }
    let (p, du) = de_boor(&s.knots[0], s.order[0], &|r| q[r], u);
    let (dv, _) = de_boor(&s.knots[0], s.order[0], &|r| dq[r], u);
    (p, du, dv)
}

/// The Cartesian point and unit normal dS/du x dS/dv at (u, v); where that
/// vanishes (a pole), the normal a little way towards the domain's centre.
pub fn point_normal(s: &Surface, u: f64, v: f64) -> (P3, P3) {
    let (ua, ub) = bspline::domain(&s.knots[0], s.order[0]);
    let (va, vb) = bspline::domain(&s.knots[1], s.order[1]);
    let (p, du, dv) = eval_surface(s, u, v);
    let (pt, su) = dehomogenize(p, du);
    let (_, sv) = dehomogenize(p, dv);
    let mut n = cross(su, sv);
    let mut scale = norm(su).max(norm(sv)).powi(2);
    let mut k = 1e-6;
    // (Written so that a NaN length also counts as degenerate.)
    #[allow(clippy::neg_cmp_op_on_partial_ord)]
    while !(norm(n) > 1e-5 * scale) && k < 0.2 {
        let (cu, cv) = ((ua + ub) / 2.0, (va + vb) / 2.0);
        let (uu, vv) = (u + (cu - u) * k, v + (cv - v) * k);
        let (p2, du2, dv2) = eval_surface(s, uu, vv);
        let (_, su2) = dehomogenize(p2, du2);
        let (_, sv2) = dehomogenize(p2, dv2);
        n = cross(su2, sv2);
        scale = norm(su2).max(norm(sv2)).powi(2);
        k *= 10.0;
    }
    let l = norm(n);
    let n = if l > 0.0 && l.is_finite() { n.map(|c| c / l) } else { [0.0, 0.0, 1.0] };
    (pt, n)
}

impl Eval<'_> {
    fn vertex(&self, u: f64, v: f64) -> Vertex {
        let pos = self.pos;
        let (p, mut n) = point_normal(pos, u, v);
        let (ua, ub) = bspline::domain(&pos.knots[0], pos.order[0]);
        let (va, vb) = bspline::domain(&pos.knots[1], pos.order[1]);
        let mut attrs = vec![];
        for s in self.surfaces.iter().filter(|s| s.role != Role::Position) {
            let (sa, sb) = bspline::domain(&s.knots[0], s.order[0]);
            let (ta, tb) = bspline::domain(&s.knots[1], s.order[1]);
            let su = sa + (u - ua) / (ub - ua) * (sb - sa);
            let sv = ta + (v - va) / (vb - va) * (tb - ta);
            let (a, _, _) = eval_surface(s, su, sv);
            if s.role == Role::Normal {
                n = [a[0], a[1], a[2]];
            } else {
                attrs.push((s.role, a[..s.dim].to_vec()));
            }
        }
        Vertex { p, n, attrs }
    }

    fn emit(&self, sink: &mut dyn NurbsSink, u: f64, v: f64) {
        self.vertex(u, v).emit(sink)
    }
}

// ---- trimming ----

fn piece_ends(p: &TrimPiece) -> Option<([f64; 2], [f64; 2])> {
    match p {
        TrimPiece::Pwl(v) => Some((*v.first()?, *v.last()?)),
        TrimPiece::Nurbs(c) => {
            let (a, b) = bspline::domain(&c.knots, c.order);
            let e = |u| {
                let (v, _) = de_boor(&c.knots, c.order, &|j| c.pts[j], u);
                [v[0] / v[3], v[1] / v[3]]
            };
            Some((e(a), e(b)))
        }
    }
}

/// Whether a loop's pieces join end to start, the last back to the first.
pub fn connected(l: &[TrimPiece]) -> bool {
    let ends: Option<Vec<_>> = l.iter().map(piece_ends).collect();
    let Some(ends) = ends else { return false };
    let near = |a: [f64; 2], b: [f64; 2]| {
        let s = 1.0 + a[0].abs().max(a[1].abs());
        (a[0] - b[0]).abs() <= 1e-5 * s && (a[1] - b[1]).abs() <= 1e-5 * s
    };
    !ends.is_empty() && (0..ends.len()).all(|k| near(ends[k].1, ends[(k + 1) % ends.len()].0))
}

/// A loop as a closed polyline (last point not repeated); NURBS pieces
/// sampled so that no segment is longer than a quarter of `cell` (at most
/// 1024 per span).
fn loop_polyline(l: &[TrimPiece], cell: f64) -> Vec<[f64; 2]> {
    let mut out: Vec<[f64; 2]> = vec![];
    for piece in l {
        let pts: Vec<[f64; 2]> = match piece {
            TrimPiece::Pwl(v) => v.clone(),
            TrimPiece::Nurbs(c) => {
                let p = c.order - 1;
                let us = Renderer::params(&c.knots, c.order, &|i, _, _| {
                    let q: Vec<[f64; 2]> = c.pts[i - p..=i].iter().map(|v| [v[0] / v[3], v[1] / v[3]]).collect();
                    let l: f64 = q.windows(2).map(|w| ((w[1][0] - w[0][0]).powi(2) + (w[1][1] - w[0][1]).powi(2)).sqrt()).sum();
                    let n = if cell > 0.0 { (4.0 * l / cell).ceil() } else { 1.0 };
                    (n as usize).clamp(p.max(1) * 4, MAX_SEGMENTS)
                });
                us.iter()
                    .map(|&u| {
                        let (v, _) = de_boor(&c.knots, c.order, &|j| c.pts[j], u);
                        [v[0] / v[3], v[1] / v[3]]
                    })
                    .collect()
            }
        };
        for q in pts {
            if out.last() != Some(&q) {
                out.push(q);
            }
        }
    }
    if out.len() > 1 && out.first() == out.last() {
        out.pop();
    }
    out
}

fn signed_area(p: &[[f64; 2]]) -> f64 {
    (0..p.len()).map(|i| {
        let (a, b) = (p[i], p[(i + 1) % p.len()]);
        a[0] * b[1] - b[0] * a[1]
    }).sum::<f64>() / 2.0
}

/// The trimmed region: closed loops, inside where the winding number >= 1.
struct Region {
    loops: Vec<Vec<[f64; 2]>>,
    segs: Vec<([f64; 2], [f64; 2])>,
}

type Rect = [f64; 4];

impl Region {
    fn new(loops: Vec<Vec<[f64; 2]>>) -> Self {
        let segs = loops.iter().flat_map(|l| (0..l.len()).map(move |i| (l[i], l[(i + 1) % l.len()]))).filter(|(a, b)| a != b).collect();
        Region { loops, segs }
    }

    fn inside(&self, p: [f64; 2]) -> bool {
        let mut w = 0i32;
        for &(a, b) in &self.segs {
            if (a[1] <= p[1]) != (b[1] <= p[1]) {
                let side = (b[0] - a[0]) * (p[1] - a[1]) - (p[0] - a[0]) * (b[1] - a[1]);
                if b[1] > a[1] && side > 0.0 {
                    w += 1;
                } else if b[1] <= a[1] && side < 0.0 {
                    w -= 1;
                }
            }
        }
        w >= 1
    }

    /// Whether segment (a, b) meets the open rectangle.
    fn crosses(r: &Rect, a: [f64; 2], b: [f64; 2]) -> bool {
        let (mut t0, mut t1) = (0.0f64, 1.0f64);
        let d = [b[0] - a[0], b[1] - a[1]];
        for k in 0..2 {
            let (lo, hi) = (r[k], r[k + 2]);
            if d[k] == 0.0 {
                if a[k] <= lo || a[k] >= hi {
                    return false;
                }
            } else {
                let (mut ta, mut tb) = ((lo - a[k]) / d[k], (hi - a[k]) / d[k]);
                if ta > tb {
                    std::mem::swap(&mut ta, &mut tb);
                }
                t0 = t0.max(ta);
                t1 = t1.min(tb);
            }
        }
        t0 < t1
    }

    /// The inside part of the cell `r` as triangles (counter-clockwise).
    fn clip(&self, r: Rect, depth: u32, out: &mut Vec<[[f64; 2]; 3]>) {
        let crossing: Vec<usize> = (0..self.segs.len()).filter(|&s| Self::crosses(&r, self.segs[s].0, self.segs[s].1)).collect();
        let corners = [[r[0], r[1]], [r[2], r[1]], [r[2], r[3]], [r[0], r[3]]];
        if crossing.is_empty() {
            if self.inside([(r[0] + r[2]) / 2.0, (r[1] + r[3]) / 2.0]) {
                out.push([corners[0], corners[1], corners[2]]);
                out.push([corners[0], corners[2], corners[3]]);
            }
            return;
        }
        if depth > 0 {
            let (mu, mv) = ((r[0] + r[2]) / 2.0, (r[1] + r[3]) / 2.0);
            for q in [[r[0], r[1], mu, mv], [mu, r[1], r[2], mv], [r[0], mv, mu, r[3]], [mu, mv, r[2], r[3]]] {
                self.clip(q, depth - 1, out);
            }
            return;
        }
        for tri in [[corners[0], corners[1], corners[2]], [corners[0], corners[2], corners[3]]] {
            let ins = tri.map(|p| self.inside(p));
            let mut poly: Vec<[f64; 2]> = vec![];
            for k in 0..3 {
                let (a, b) = (tri[k], tri[(k + 1) % 3]);
                if ins[k] {
                    poly.push(a);
                }
                if ins[k] != ins[(k + 1) % 3] {
                    poly.push(self.crossing_point(&crossing, a, b, ins[k]));
                }
            }
            for k in 1..poly.len().saturating_sub(1) {
                out.push([poly[0], poly[k], poly[k + 1]]);
            }
        }
    }

    /// Where edge a -> b leaves (or enters) the region: its intersection
    /// with a trim segment nearest the inside end.
    fn crossing_point(&self, cand: &[usize], a: [f64; 2], b: [f64; 2], a_inside: bool) -> [f64; 2] {
        let d = [b[0] - a[0], b[1] - a[1]];
        let mut best: Option<f64> = None;
        for &s in cand {
            let (p, q) = self.segs[s];
            let e = [q[0] - p[0], q[1] - p[1]];
            let den = d[0] * e[1] - d[1] * e[0];
            if den == 0.0 {
                continue;
            }
            let t = ((p[0] - a[0]) * e[1] - (p[1] - a[1]) * e[0]) / den;
            let s2 = ((p[0] - a[0]) * d[1] - (p[1] - a[1]) * d[0]) / den;
            if (-1e-12..=1.0 + 1e-12).contains(&t) && (-1e-12..=1.0 + 1e-12).contains(&s2) {
                let key = if a_inside { t } else { 1.0 - t };
                if best.is_none_or(|b| key < if a_inside { b } else { 1.0 - b }) {
                    best = Some(t);
                }
            }
        }
        let t = best.unwrap_or(0.5).clamp(0.0, 1.0);
        [a[0] + d[0] * t, a[1] + d[1] * t]
    }
}
