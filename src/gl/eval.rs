//! Evaluators (GL 1.5 section 5.1): one- and two-dimensional Bézier maps
//! (glMap1, glMap2), glEvalCoord, glEvalPoint, glMapGrid, glEvalMesh,
//! GL_AUTO_NORMAL, and glGetMap.
//!
//! Maps are evaluated with de Casteljau's algorithm in f64. Evaluated
//! colours and normals feed the generated vertex without changing the
//! current values (5.1). Texture-coordinate maps give the
//! texture coordinates of unit 0 (glTexCoord's unit); with several enabled,
//! the one with the most components wins (5.1).

use super::context::Context;
use super::enums::*;

/// GL_MAX_EVAL_ORDER.
pub const MAX_EVAL_ORDER: i32 = 30;
pub const GL_COEFF: u32 = 0x0A00;
pub const GL_ORDER: u32 = 0x0A01;
pub const GL_DOMAIN: u32 = 0x0A02;

/// Components of each map target, in enum order from GL_MAP1_COLOR_4 /
/// GL_MAP2_COLOR_4: COLOR_4, INDEX, NORMAL, TEXTURE_COORD_1..4, VERTEX_3, VERTEX_4.
const COMPONENTS: [usize; 9] = [4, 1, 3, 1, 2, 3, 4, 3, 4];
const COLOR: usize = 0;
const NORMAL: usize = 2;
const VERTEX_3: usize = 7;
const VERTEX_4: usize = 8;

/// A map: domain, orders (v order 1 for one-dimensional maps), control
/// points packed as [v][u][component]... stored u-major: p(i, j) at
/// (i * vorder + j) * k.
#[derive(Clone, Debug, PartialEq)]
pub struct Map {
    pub u: (f32, f32),
    pub v: (f32, f32),
    pub uorder: usize,
    pub vorder: usize,
    pub points: Vec<f32>,
}

impl Map {
    fn default_for(i: usize) -> Map {
        let points = match i {
            COLOR => vec![1.0, 1.0, 1.0, 1.0],
            1 => vec![1.0],
            NORMAL => vec![0.0, 0.0, 1.0],
            3..=6 => [0.0, 0.0, 0.0, 1.0][..COMPONENTS[i]].to_vec(),
            VERTEX_3 => vec![0.0, 0.0, 0.0],
            _ => vec![0.0, 0.0, 0.0, 1.0],
        };
        Map { u: (0.0, 1.0), v: (0.0, 1.0), uorder: 1, vorder: 1, points }
    }
}

#[derive(Clone, Debug)]
pub struct EvalState {
    pub map1: [Map; 9],
    pub map2: [Map; 9],
    pub enabled1: [bool; 9],
    pub enabled2: [bool; 9],
    pub auto_normal: bool,
    /// glMapGrid1: n, u1, u2.
    pub grid1: (i32, f32, f32),
    /// glMapGrid2: un, u1, u2, vn, v1, v2.
    pub grid2: (i32, f32, f32, i32, f32, f32),
}

impl Default for EvalState {
    fn default() -> Self {
        EvalState {
            map1: std::array::from_fn(Map::default_for),
            map2: std::array::from_fn(Map::default_for),
            enabled1: [false; 9],
            enabled2: [false; 9],
            auto_normal: false,
            grid1: (1, 0.0, 1.0),
            grid2: (1, 0.0, 1.0, 1, 0.0, 1.0),
        }
    }
}

/// (dimension, index) of a map target.
pub fn target(t: u32) -> Option<(u32, usize)> {
    match t {
        GL_MAP1_COLOR_4..=GL_MAP1_VERTEX_4 => Some((1, (t - GL_MAP1_COLOR_4) as usize)),
        GL_MAP2_COLOR_4..=GL_MAP2_VERTEX_4 => Some((2, (t - GL_MAP2_COLOR_4) as usize)),
        _ => None,
    }
}

pub fn components(t: u32) -> usize {
    target(t).map_or(0, |(_, i)| COMPONENTS[i])
}

/// Bernstein evaluation of `n` control values (stride `k`) at t, with the
/// derivative: de Casteljau in f64.
fn casteljau(points: &[f64], t: f64) -> (f64, f64) {
    let n = points.len();
    if n == 1 {
        return (points[0], 0.0);
    }
    let mut b = points.to_vec();
    for r in 1..n {
        if r == n - 1 {
            // The last step: value and derivative from the two remaining.
            let d = (n - 1) as f64 * (b[1] - b[0]);
            return (b[0] + t * (b[1] - b[0]), d);
        }
        for i in 0..n - r {
            b[i] += t * (b[i + 1] - b[i]);
        }
    }
    unreachable!()
}

/// Value, d/du and d/dv of a map at (u, v) already normalized to [0, 1].
fn evaluate(m: &Map, k: usize, u: f64, v: f64) -> (Vec<f64>, Vec<f64>, Vec<f64>) {
    let mut val = vec![0.0; k];
    let mut du = vec![0.0; k];
    let mut dv = vec![0.0; k];
    for c in 0..k {
        // Along v for each u row, then along u.
        let mut rows = Vec::with_capacity(m.uorder);
        let mut rows_dv = Vec::with_capacity(m.uorder);
        for i in 0..m.uorder {
            let col: Vec<f64> = (0..m.vorder).map(|j| m.points[(i * m.vorder + j) * k + c] as f64).collect();
            let (p, d) = casteljau(&col, v);
            rows.push(p);
            rows_dv.push(d);
        }
        let (p, d) = casteljau(&rows, u);
        val[c] = p;
        du[c] = d;
        dv[c] = casteljau(&rows_dv, u).0;
    }
    (val, du, dv)
}

impl Context {
    /// glMap1 / glMap2 with points already read (k components per point,
    /// u-major). `v` is None for glMap1.
    pub fn map(&mut self, t: u32, u: (f32, f32), uorder: i32, v: Option<((f32, f32), i32)>, points: Vec<f32>) {
        let Some((dim, i)) = target(t) else { return self.set_error(GL_INVALID_ENUM) };
        if (dim == 2) != v.is_some() {
            return self.set_error(GL_INVALID_ENUM);
        }
        let (v, vorder) = v.unwrap_or(((0.0, 1.0), 1));
        if u.0 == u.1 || v.0 == v.1 || !(1..=MAX_EVAL_ORDER).contains(&uorder) || !(1..=MAX_EVAL_ORDER).contains(&vorder) {
            return self.set_error(GL_INVALID_VALUE);
        }
        if points.len() != uorder as usize * vorder as usize * COMPONENTS[i] {
            return; // a NULL or short array: nothing to store
        }
        let m = Map { u, v, uorder: uorder as usize, vorder: vorder as usize, points };
        if dim == 1 {
            self.eval.map1[i] = m;
        } else {
            self.eval.map2[i] = m;
        }
    }

    /// glEvalCoord1 (v = None) / glEvalCoord2.
    pub fn eval_coord(&mut self, u: f32, v: Option<f32>) {
        let two = v.is_some();
        let (maps, enabled) = if two { (&self.eval.map2, &self.eval.enabled2) } else { (&self.eval.map1, &self.eval.enabled1) };
        let norm = |m: &Map| {
            let uu = (u as f64 - m.u.0 as f64) / (m.u.1 as f64 - m.u.0 as f64);
            let vv = v.map_or(0.0, |v| (v as f64 - m.v.0 as f64) / (m.v.1 as f64 - m.v.0 as f64));
            (uu, vv)
        };
        let at = |i: usize| {
            let m = &maps[i];
            let (uu, vv) = norm(m);
            evaluate(m, COMPONENTS[i], uu, vv)
        };
        let color = enabled[COLOR].then(|| at(COLOR).0);
        let mut normal = enabled[NORMAL].then(|| at(NORMAL).0);
        // TEXTURE_COORD_4 down to TEXTURE_COORD_1: the first enabled.
        let tex = (3..=6).rev().find(|&i| enabled[i]).map(|i| {
            let t = at(i).0;
            let mut strq = [0.0, 0.0, 0.0, 1.0];
            for (o, v) in strq.iter_mut().zip(&t) {
                *o = *v as f32;
            }
            strq
        });
        let vertex = if enabled[VERTEX_4] {
            let (p, du, dv) = at(VERTEX_4);
            if two && self.eval.auto_normal {
                // Normal of the rational surface: derivatives of (x, y, z) / w.
                let w = p[3];
                let d = |dp: &[f64]| [0, 1, 2].map(|c| (dp[c] * w - p[c] * dp[3]) / (w * w));
                let (a, b) = (d(&du), d(&dv));
                normal = Some(vec![a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]]);
            }
            Some([p[0] as f32, p[1] as f32, p[2] as f32, p[3] as f32])
        } else if enabled[VERTEX_3] {
            let (p, du, dv) = at(VERTEX_3);
            if two && self.eval.auto_normal {
                normal = Some(vec![du[1] * dv[2] - du[2] * dv[1], du[2] * dv[0] - du[0] * dv[2], du[0] * dv[1] - du[1] * dv[0]]);
            }
            Some([p[0] as f32, p[1] as f32, p[2] as f32, 1.0])
        } else {
            None
        };
        let Some(vertex) = vertex else { return };
        // Evaluated values are used for this vertex only (5.1).
        let saved = (self.current.color, self.current.normal, self.current.tex_coords[0]);
        if let Some(t) = tex {
            self.current.tex_coords[0] = t;
        }
        if let Some(c) = color {
            self.current.color = [c[0] as f32, c[1] as f32, c[2] as f32, c[3] as f32];
        }
        if let Some(n) = normal {
            self.current.normal = [n[0] as f32, n[1] as f32, n[2] as f32];
        }
        self.vertex(vertex);
        (self.current.color, self.current.normal, self.current.tex_coords[0]) = saved;
    }

    pub fn map_grid(&mut self, un: i32, u: (f32, f32), v: Option<(i32, (f32, f32))>) {
        if un <= 0 || v.is_some_and(|(vn, _)| vn <= 0) {
            return self.set_error(GL_INVALID_VALUE);
        }
        match v {
            None => self.eval.grid1 = (un, u.0, u.1),
            Some((vn, v)) => self.eval.grid2 = (un, u.0, u.1, vn, v.0, v.1),
        }
    }

    fn grid_u1(&self, i: i32) -> f32 {
        let (n, a, b) = self.eval.grid1;
        if i == n { b } else { a + i as f32 * (b - a) / n as f32 }
    }

    fn grid_uv2(&self, i: i32, j: i32) -> (f32, f32) {
        let (un, u1, u2, vn, v1, v2) = self.eval.grid2;
        let u = if i == un { u2 } else { u1 + i as f32 * (u2 - u1) / un as f32 };
        let v = if j == vn { v2 } else { v1 + j as f32 * (v2 - v1) / vn as f32 };
        (u, v)
    }

    /// glEvalPoint1 / glEvalPoint2.
    pub fn eval_point(&mut self, i: i32, j: Option<i32>) {
        match j {
            None => {
                let u = self.grid_u1(i);
                self.eval_coord(u, None)
            }
            Some(j) => {
                let (u, v) = self.grid_uv2(i, j);
                self.eval_coord(u, Some(v))
            }
        }
    }

    pub fn eval_mesh1(&mut self, mode: u32, i1: i32, i2: i32) {
        let prim = match mode {
            GL_POINT => GL_POINTS,
            GL_LINE => GL_LINE_STRIP,
            _ => return self.set_error(GL_INVALID_ENUM),
        };
        self.begin(prim);
        for i in i1..=i2 {
            self.eval_point(i, None);
        }
        self.end();
    }

    pub fn eval_mesh2(&mut self, mode: u32, i1: i32, i2: i32, j1: i32, j2: i32) {
        match mode {
            GL_FILL => {
                for j in j1..j2 {
                    self.begin(GL_QUAD_STRIP);
                    for i in i1..=i2 {
                        self.eval_point(i, Some(j));
                        self.eval_point(i, Some(j + 1));
                    }
                    self.end();
                }
            }
            GL_LINE => {
                for j in j1..=j2 {
                    self.begin(GL_LINE_STRIP);
                    for i in i1..=i2 {
                        self.eval_point(i, Some(j));
                    }
                    self.end();
                }
                for i in i1..=i2 {
                    self.begin(GL_LINE_STRIP);
                    for j in j1..=j2 {
                        self.eval_point(i, Some(j));
                    }
                    self.end();
                }
            }
            GL_POINT => {
                self.begin(GL_POINTS);
                for j in j1..=j2 {
                    for i in i1..=i2 {
                        self.eval_point(i, Some(j));
                    }
                }
                self.end();
            }
            _ => self.set_error(GL_INVALID_ENUM),
        }
    }

    /// glGetMap*v values.
    pub fn get_map(&self, t: u32, query: u32) -> Option<Vec<f64>> {
        let (dim, i) = target(t)?;
        let m = if dim == 1 { &self.eval.map1[i] } else { &self.eval.map2[i] };
        Some(match (query, dim) {
            (GL_COEFF, _) => m.points.iter().map(|&p| p as f64).collect(),
            (GL_ORDER, 1) => vec![m.uorder as f64],
            (GL_ORDER, _) => vec![m.uorder as f64, m.vorder as f64],
            (GL_DOMAIN, 1) => vec![m.u.0 as f64, m.u.1 as f64],
            (GL_DOMAIN, _) => vec![m.u.0 as f64, m.u.1 as f64, m.v.0 as f64, m.v.1 as f64],
            _ => return None,
        })
    }
}

/// Reads glMap's control points (`stride`s in values) into the packed
/// u-major layout. Empty when the pointer is NULL or a stride is too small
/// (the latter is GL_INVALID_VALUE, returned as Err).
///
/// # Safety
/// `p` must be NULL or hold the points the strides and orders describe.
pub unsafe fn read_points<T: Copy + Into<f64>>(t: u32, p: *const T, ustride: i32, uorder: i32, vstride: i32, vorder: i32) -> Result<Vec<f32>, u32> {
    let k = components(t);
    if k == 0 {
        return Err(GL_INVALID_ENUM);
    }
    if ustride < k as i32 || (vorder > 1 && vstride < k as i32) {
        return Err(GL_INVALID_VALUE);
    }
    if !(1..=MAX_EVAL_ORDER).contains(&uorder) || !(1..=MAX_EVAL_ORDER).contains(&vorder) {
        return Err(GL_INVALID_VALUE);
    }
    if p.is_null() {
        return Ok(Vec::new());
    }
    let mut out = Vec::with_capacity(uorder as usize * vorder as usize * k);
    for i in 0..uorder as usize {
        for j in 0..vorder as usize {
            for c in 0..k {
                let idx = i * ustride as usize + j * vstride.max(0) as usize + c;
                out.push(std::ptr::read_unaligned(p.add(idx)).into() as f32);
            }
        }
    }
    Ok(out)
}
