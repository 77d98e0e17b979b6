//! The tessellator's planar core, in 2D and double precision: the
//! arrangement of the contours' edges (every crossing and touching split
//! into vertices), the winding number of every face (one sweep), the
//! boundary of the region a winding rule selects, and its triangulation
//! (a second sweep that keeps one monotone "reflex chain" per interior
//! region, the textbook monotone-polygon triangulation run on all regions
//! at once; merge vertices are resolved by the next vertex that arrives).
//!
//! Invariants: vertices are visited in lexicographic (x, y) order, every
//! edge runs from its smaller to its larger end in that order, and "above"
//! an edge means to the left of it. Every loop is bounded by the input
//! size; when floating-point inconsistencies (edges that still cross after
//! splitting) break the sweep's assumptions, it degrades (drops a piece)
//! but never loops or indexes out of bounds. All sorts use total orders.

use std::collections::HashMap;

/// A planar vertex: 2D position (normalised to about [-1, 1]) and where it came from.
#[derive(Clone, Copy, Debug)]
pub struct Vert {
    pub p: [f64; 2],
}

#[inline]
pub fn orient(a: [f64; 2], b: [f64; 2], c: [f64; 2]) -> f64 {
    (b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0])
}

/// Merge distance, in normalised units.
pub const EPS: f64 = 1.0 / (1u64 << 42) as f64;

/// A spatial hash that finds an existing vertex within EPS of a point.
pub struct Grid {
    cells: HashMap<(i64, i64), Vec<usize>>,
}

impl Default for Grid {
    fn default() -> Self {
        Self::new()
    }
}

impl Grid {
    pub fn new() -> Self {
        Grid { cells: HashMap::new() }
    }
    fn key(p: [f64; 2]) -> (i64, i64) {
        let c = 4.0 * EPS;
        ((p[0] / c).floor() as i64, (p[1] / c).floor() as i64)
    }
    pub fn find(&self, verts: &[Vert], p: [f64; 2]) -> Option<usize> {
        let (kx, ky) = Self::key(p);
        let mut best: Option<(f64, usize)> = None;
        for dx in -1..=1 {
            for dy in -1..=1 {
                if let Some(list) = self.cells.get(&(kx + dx, ky + dy)) {
                    for &i in list {
                        let q = verts[i].p;
                        let d = (q[0] - p[0]).abs().max((q[1] - p[1]).abs());
                        if d <= EPS && best.is_none_or(|(bd, _)| d < bd) {
                            best = Some((d, i));
                        }
                    }
                }
            }
        }
        best.map(|b| b.1)
    }
    pub fn insert(&mut self, verts: &[Vert], i: usize) {
        self.cells.entry(Self::key(verts[i].p)).or_default().push(i);
    }
}

/// A directed input edge between vertex ids.
#[derive(Clone, Copy, Debug)]
pub struct Seg {
    pub a: usize,
    pub b: usize,
}

/// What the splitter asks of its caller when two edges cross at a new point:
/// create a vertex there (returns its id, or None to abort).
pub trait Combiner {
    /// `ends` are the crossing edges' endpoints (a, b, c, d), `t`/`s` the
    /// parameters of the point along a→b and c→d.
    fn combine(&mut self, verts: &mut Vec<Vert>, p: [f64; 2], ends: [usize; 4], t: f64, s: f64) -> Option<usize>;
}

/// Splits the edges at every crossing and at every vertex lying on another
/// edge. Repeats (a few passes at most) because rounded crossing points can
/// create new near-crossings. Returns None if the combiner aborted.
pub fn split_all(verts: &mut Vec<Vert>, grid: &mut Grid, segs: Vec<Seg>, comb: &mut dyn Combiner) -> Option<Vec<Seg>> {
    let mut segs = segs;
    for _pass in 0..4 {
        let n = segs.len();
        // splits[i] = (param, vertex) points to insert into segment i.
        let mut splits: Vec<Vec<(f64, usize)>> = vec![Vec::new(); n];
        let mut any = false;
        for (i, j) in candidate_pairs(verts, &segs) {
            let (si, sj) = (segs[i], segs[j]);
            if let Some(found) = intersect(verts, grid, si, sj, comb) {
                let (pi, pj) = found?;
                for (t, v) in pi {
                    splits[i].push((t, v));
                    any = true;
                }
                for (t, v) in pj {
                    splits[j].push((t, v));
                    any = true;
                }
            }
        }
        if !any {
            return Some(segs);
        }
        let mut out = Vec::with_capacity(n * 2);
        for (i, s) in segs.iter().enumerate() {
            let sp = &mut splits[i];
            if sp.is_empty() {
                out.push(*s);
                continue;
            }
            sp.sort_by(|x, y| x.0.total_cmp(&y.0));
            let mut cur = s.a;
            for &(_, v) in sp.iter() {
                if v != cur && v != s.b {
                    out.push(Seg { a: cur, b: v });
                    cur = v;
                }
            }
            if cur != s.b {
                out.push(Seg { a: cur, b: s.b });
            }
        }
        segs = out;
    }
    Some(segs)
}

/// The pairs of edges whose boxes (grown by EPS) overlap, each once, in a
/// deterministic order: a uniform grid of about n square cells;
/// a pair is reported by the cell holding the low corner of the two boxes'
/// overlap. Edges spanning more than 64 cells are checked against all edges.
fn candidate_pairs(verts: &[Vert], segs: &[Seg]) -> Vec<(usize, usize)> {
    let n = segs.len();
    let bb: Vec<[f64; 4]> = segs
        .iter()
        .map(|s| {
            let (p, q) = (verts[s.a].p, verts[s.b].p);
            [p[0].min(q[0]) - EPS, p[1].min(q[1]) - EPS, p[0].max(q[0]) + EPS, p[1].max(q[1]) + EPS]
        })
        .collect();
    let overlap = |i: usize, j: usize| {
        let (a, b) = (&bb[i], &bb[j]);
        a[0] <= b[2] && b[0] <= a[2] && a[1] <= b[3] && b[1] <= a[3]
    };
    let mut pairs = Vec::new();
    if n < 2 {
        return pairs;
    }
    let (mut lo, mut hi) = ([f64::INFINITY; 2], [f64::NEG_INFINITY; 2]);
    for b in &bb {
        lo = [lo[0].min(b[0]), lo[1].min(b[1])];
        hi = [hi[0].max(b[2]), hi[1].max(b[3])];
    }
    // About n square cells (the box's aspect ratio kept), at most 2^20.
    let (w, h) = ((hi[0] - lo[0]).max(EPS), (hi[1] - lo[1]).max(EPS));
    let cells_wanted = (n as f64).min((1u64 << 20) as f64);
    let side = (w * h / cells_wanted).sqrt();
    let cap = (2 * n + 4).min(1 << 21);
    let mut gs = [((w / side) as usize).clamp(1, cap), ((h / side) as usize).clamp(1, cap)];
    while gs[0] * gs[1] > cap {
        let k = if gs[0] > gs[1] { 0 } else { 1 };
        gs[k] = (gs[k] / 2).max(1);
    }
    let size = [(w / gs[0] as f64).max(f64::MIN_POSITIVE), (h / gs[1] as f64).max(f64::MIN_POSITIVE)];
    let cell = |x: f64, k: usize| (((x - lo[k]) / size[k]) as usize).min(gs[k] - 1);
    let g = gs[0];
    let mut cells: Vec<Vec<u32>> = vec![Vec::new(); gs[0] * gs[1]];
    let mut long = Vec::new();
    for (i, b) in bb.iter().enumerate() {
        let (x0, y0, x1, y1) = (cell(b[0], 0), cell(b[1], 1), cell(b[2], 0), cell(b[3], 1));
        if (x1 - x0 + 1) * (y1 - y0 + 1) > 64 {
            long.push(i);
            continue;
        }
        for y in y0..=y1 {
            for x in x0..=x1 {
                cells[y * g + x].push(i as u32);
            }
        }
    }
    let mut is_long = vec![false; n];
    for &i in &long {
        is_long[i] = true;
    }
    for (c, list) in cells.iter().enumerate() {
        let (cx, cy) = (c % g, c / g);
        for (k, &i) in list.iter().enumerate() {
            for &j in &list[k + 1..] {
                let (i, j) = (i as usize, j as usize);
                if !overlap(i, j) {
                    continue;
                }
                let (a, b) = (&bb[i], &bb[j]);
                if cell(a[0].max(b[0]), 0) == cx && cell(a[1].max(b[1]), 1) == cy {
                    pairs.push((i, j));
                }
            }
        }
    }
    for &i in &long {
        for j in 0..n {
            if j != i && (!is_long[j] || j > i) && overlap(i, j) {
                pairs.push((i, j));
            }
        }
    }
    pairs
}

type Splits = (Vec<(f64, usize)>, Vec<(f64, usize)>);

/// Tests two edges. Returns None when nothing is to be split,
/// Some(None) when the combiner aborted.
fn intersect(verts: &mut Vec<Vert>, grid: &mut Grid, s: Seg, r: Seg, comb: &mut dyn Combiner) -> Option<Option<Splits>> {
    let (a, b, c, d) = (verts[s.a].p, verts[s.b].p, verts[r.a].p, verts[r.b].p);
    let mut on_s = Vec::new();
    let mut on_r = Vec::new();
    // Endpoints lying on the other edge's interior (touching, collinear overlaps).
    let lies_on = |p: [f64; 2], a: [f64; 2], b: [f64; 2]| -> Option<f64> {
        let dx = b[0] - a[0];
        let dy = b[1] - a[1];
        let l2 = dx * dx + dy * dy;
        if !(l2 > 0.0) {
            return None;
        }
        let t = ((p[0] - a[0]) * dx + (p[1] - a[1]) * dy) / l2;
        if !(t > 0.0 && t < 1.0) {
            return None;
        }
        let dist = orient(a, b, p).abs() / l2.sqrt();
        (dist <= EPS).then_some(t)
    };
    for &(v, p) in &[(r.a, c), (r.b, d)] {
        if v != s.a && v != s.b {
            if let Some(t) = lies_on(p, a, b) {
                on_s.push((t, v));
            }
        }
    }
    for &(v, p) in &[(s.a, a), (s.b, b)] {
        if v != r.a && v != r.b {
            if let Some(t) = lies_on(p, c, d) {
                on_r.push((t, v));
            }
        }
    }
    if on_s.is_empty() && on_r.is_empty() && s.a != r.a && s.a != r.b && s.b != r.a && s.b != r.b {
        let d1 = orient(c, d, a);
        let d2 = orient(c, d, b);
        let d3 = orient(a, b, c);
        let d4 = orient(a, b, d);
        if ((d1 > 0.0 && d2 < 0.0) || (d1 < 0.0 && d2 > 0.0)) && ((d3 > 0.0 && d4 < 0.0) || (d3 < 0.0 && d4 > 0.0)) {
            let t = (d1 / (d1 - d2)).clamp(0.0, 1.0);
            let u = (d3 / (d3 - d4)).clamp(0.0, 1.0);
            // Average both parametrisations: symmetric and within both edges' boxes.
            let p1 = [a[0] + t * (b[0] - a[0]), a[1] + t * (b[1] - a[1])];
            let p2 = [c[0] + u * (d[0] - c[0]), c[1] + u * (d[1] - c[1])];
            let p = [0.5 * (p1[0] + p2[0]), 0.5 * (p1[1] + p2[1])];
            let v = match grid.find(verts, p) {
                Some(v) => v,
                None => match comb.combine(verts, p, [s.a, s.b, r.a, r.b], t, u) {
                    Some(v) => {
                        grid.insert(verts, v);
                        v
                    }
                    None => return Some(None),
                },
            };
            if v != s.a && v != s.b {
                on_s.push((t, v));
            }
            if v != r.a && v != r.b {
                on_r.push((u, v));
            }
        }
    }
    if on_s.is_empty() && on_r.is_empty() {
        None
    } else {
        Some(Some((on_s, on_r)))
    }
}

/// The winding rules (GLU_TESS_WINDING_*).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Rule {
    Odd,
    NonZero,
    Positive,
    Negative,
    AbsGeqTwo,
}

impl Rule {
    pub fn inside(self, w: i64) -> bool {
        match self {
            Rule::Odd => w & 1 != 0,
            Rule::NonZero => w != 0,
            Rule::Positive => w > 0,
            Rule::Negative => w < 0,
            Rule::AbsGeqTwo => w.abs() >= 2,
        }
    }
}

/// An undirected edge of the arrangement, lo before hi in sweep order,
/// with its net multiplicity (input traversals lo→hi minus hi→lo).
#[derive(Clone, Copy, Debug)]
struct Edge {
    lo: usize,
    hi: usize,
    w: i64,
}

/// The selected region: its boundary edges directed with the region on
/// their left, and its triangles (counter-clockwise).
pub struct Region {
    pub boundary: Vec<(usize, usize)>,
    pub triangles: Vec<[usize; 3]>,
}

/// Which triangle edges lie on the region's boundary (for the edge flags).
pub struct BoundaryIndex {
    set: std::collections::HashSet<(usize, usize)>,
}

impl BoundaryIndex {
    pub fn new(r: &Region) -> Self {
        BoundaryIndex { set: r.boundary.iter().map(|&(a, b)| (a.min(b), a.max(b))).collect() }
    }

    pub fn on_boundary(&self, a: usize, b: usize) -> bool {
        self.set.contains(&(a.min(b), a.max(b)))
    }
}

fn lex_less(p: [f64; 2], q: [f64; 2]) -> bool {
    p[0] < q[0] || (p[0] == q[0] && p[1] < q[1])
}

/// Computes windings and the selected region; triangulates it unless `boundary_only`.
pub fn region(verts: &[Vert], segs: &[Seg], rule: Rule, boundary_only: bool) -> Region {
    let nv = verts.len();
    // Net multiplicity per undirected edge.
    let mut map: HashMap<(usize, usize), i64> = HashMap::new();
    for s in segs {
        if s.a == s.b {
            continue;
        }
        let (lo, hi, w) = if lex_less(verts[s.a].p, verts[s.b].p) { (s.a, s.b, 1) } else { (s.b, s.a, -1) };
        *map.entry((lo, hi)).or_insert(0) += w;
    }
    let mut edges: Vec<Edge> = map.into_iter().filter(|&(_, w)| w != 0).map(|((lo, hi), w)| Edge { lo, hi, w }).collect();
    edges.sort_by_key(|e| (e.lo, e.hi));
    // Sweep order of vertices.
    let mut order: Vec<usize> = (0..nv).collect();
    order.sort_by(|&i, &j| {
        let (p, q) = (verts[i].p, verts[j].p);
        p[0].total_cmp(&q[0]).then(p[1].total_cmp(&q[1]))
    });
    let angle = |e: &Edge| {
        let (a, b) = (verts[e.lo].p, verts[e.hi].p);
        (b[1] - a[1]).atan2(b[0] - a[0])
    };
    let build_out = |es: &[Edge]| {
        let mut out: Vec<Vec<usize>> = vec![Vec::new(); nv];
        let mut inc = vec![0u32; nv];
        for (i, e) in es.iter().enumerate() {
            out[e.lo].push(i);
            inc[e.hi] += 1;
        }
        for o in out.iter_mut() {
            o.sort_by(|&i, &j| angle(&es[i]).total_cmp(&angle(&es[j])));
        }
        (out, inc)
    };

    // Sweep 1: the winding number below every edge.
    let (out, inc) = build_out(&edges);
    let mut below = vec![0i64; edges.len()];
    {
        let mut active: Vec<(usize, i64)> = Vec::new();
        for &v in &order {
            let pos = locate(&mut active, v, inc[v], verts, |x| edges[x.0].hi, |x| (edges[x.0].lo, edges[x.0].hi));
            let mut w = if pos > 0 { active[pos - 1].1 } else { 0 };
            let mut ins = Vec::with_capacity(out[v].len());
            for &e in &out[v] {
                below[e] = w;
                w += edges[e].w;
                ins.push((e, w));
            }
            active.splice(pos..pos, ins);
        }
    }
    // The boundary: edges whose two sides differ; "inside above" per edge.
    let mut bedges = Vec::new();
    let mut inside_above = Vec::new();
    let mut boundary = Vec::new();
    for (i, e) in edges.iter().enumerate() {
        let (b, a) = (rule.inside(below[i]), rule.inside(below[i] + e.w));
        if a != b {
            bedges.push(Edge { lo: e.lo, hi: e.hi, w: e.w });
            inside_above.push(a);
            boundary.push(if a { (e.lo, e.hi) } else { (e.hi, e.lo) });
        }
    }
    if boundary_only {
        return Region { boundary, triangles: Vec::new() };
    }

    // Sweep 2: triangulate.
    let (out, inc) = build_out(&bedges);
    let mut tris: Vec<[usize; 3]> = Vec::new();
    let mut active: Vec<(usize, Option<Reg>)> = Vec::new();
    let p = |i: usize| verts[i].p;
    let mut t = Tri { verts, out: &mut tris };
    for &v in &order {
        if inc[v] == 0 && out[v].is_empty() {
            continue;
        }
        let outs: Vec<(usize, Option<Reg>)> = out[v].iter().map(|&e| (e, None)).collect();
        if inc[v] > 0 {
            // The entries ending here (normally one contiguous block).
            let idx: Vec<usize> = (0..active.len()).filter(|&i| bedges[active[i].0].hi == v).collect();
            if idx.is_empty() {
                // Inconsistent: treat as a start below.
                insert_start(&mut active, v, outs, &bedges, &inside_above, verts, &mut t);
                continue;
            }
            let lo = idx[0];
            let hi = *idx.last().unwrap();
            let r_below = if lo > 0 { active[lo - 1].1.take() } else { None };
            let mut removed: Vec<(usize, Option<Reg>)> = active.drain(lo..=hi).collect();
            let r_above = removed.last_mut().and_then(|x| x.1.take());
            for (_, r) in removed.into_iter() {
                if let Some(r) = r {
                    t.close(r, v);
                }
            }
            let r_below = r_below.map(|r| t.add(r, v, Side::Upper));
            let r_above = r_above.map(|r| t.add(r, v, Side::Lower));
            if outs.is_empty() {
                match (r_below, r_above) {
                    (Some(b), Some(a)) => {
                        let mut subs = b.subs;
                        subs.extend(a.subs);
                        active[lo - 1].1 = Some(Reg { subs });
                    }
                    (Some(b), None) => active[lo - 1].1 = Some(b),
                    (None, Some(a)) => t.close(a, v),
                    (None, None) => {}
                }
            } else {
                if let Some(b) = r_below {
                    if lo > 0 {
                        active[lo - 1].1 = Some(b);
                    } else {
                        t.close(b, v);
                    }
                }
                let mut outs = outs;
                let k = outs.len();
                for j in 0..k - 1 {
                    if inside_above[outs[j].0] {
                        outs[j].1 = Some(Reg::start(v));
                    }
                }
                outs[k - 1].1 = match r_above {
                    Some(a) => Some(a),
                    None if inside_above[outs[k - 1].0] => Some(Reg::start(v)),
                    None => None,
                };
                active.splice(lo..lo, outs);
            }
        } else {
            insert_start(&mut active, v, outs, &bedges, &inside_above, verts, &mut t);
        }
    }
    let _ = p;
    Region { boundary, triangles: tris }
}

/// Finds where vertex v goes in the active list: removes the entries ending
/// at v (if `inc` > 0) and returns the position of the first, or binary
/// searches by orientation.
fn locate<T>(active: &mut Vec<T>, v: usize, inc: u32, verts: &[Vert], hi_of: impl Fn(&T) -> usize, ends: impl Fn(&T) -> (usize, usize)) -> usize {
    if inc > 0 {
        let first = active.iter().position(|x| hi_of(x) == v);
        if let Some(first) = first {
            active.retain(|x| hi_of(x) != v);
            return first.min(active.len());
        }
    }
    let pv = verts[v].p;
    active.partition_point(|x| {
        let (a, b) = ends(x);
        orient(verts[a].p, verts[b].p, pv) >= 0.0
    })
}

fn insert_start(active: &mut Vec<(usize, Option<Reg>)>, v: usize, mut outs: Vec<(usize, Option<Reg>)>, bedges: &[Edge], inside_above: &[bool], verts: &[Vert], t: &mut Tri) {
    if outs.is_empty() {
        return;
    }
    let pv = verts[v].p;
    let pos = active.partition_point(|x| {
        let e = bedges[x.0];
        orient(verts[e.lo].p, verts[e.hi].p, pv) >= 0.0
    });
    let r = if pos > 0 { active[pos - 1].1.take() } else { None };
    let k = outs.len();
    for j in 0..k - 1 {
        if inside_above[outs[j].0] {
            outs[j].1 = Some(Reg::start(v));
        }
    }
    match r {
        Some(r) => {
            let (lower, upper) = t.split(r, v);
            active[pos - 1].1 = Some(lower);
            outs[k - 1].1 = Some(upper);
        }
        None => {
            if inside_above[outs[k - 1].0] {
                outs[k - 1].1 = Some(Reg::start(v));
            }
        }
    }
    active.splice(pos..pos, outs);
}

#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum Side {
    Lower,
    Upper,
    Both,
}

/// An untriangulated reflex chain: verts[1..] lie on `side`, verts[0] on
/// the other side (or it is the region's start vertex).
#[derive(Debug)]
struct Chain {
    verts: Vec<usize>,
    side: Side,
}

/// An interior region between two active edges: its chains from bottom to
/// top; more than one while merge vertices wait for the next vertex.
#[derive(Debug)]
struct Reg {
    subs: Vec<Chain>,
}

impl Reg {
    fn start(v: usize) -> Reg {
        Reg { subs: vec![Chain { verts: vec![v], side: Side::Both }] }
    }
}

struct Tri<'a> {
    verts: &'a [Vert],
    out: &'a mut Vec<[usize; 3]>,
}

impl Tri<'_> {
    fn tri(&mut self, a: usize, b: usize, c: usize) {
        let o = orient(self.verts[a].p, self.verts[b].p, self.verts[c].p);
        // Zero-area triangles (collinear vertices) are kept: they keep the
        // mesh free of T-junctions, so edge flags stay exact.
        if o >= 0.0 {
            self.out.push([a, b, c]);
        } else {
            self.out.push([a, c, b]);
        }
    }

    fn fan(&mut self, ch: &Chain, v: usize) {
        for w in ch.verts.windows(2) {
            self.tri(v, w[0], w[1]);
        }
    }

    fn step(&mut self, mut ch: Chain, v: usize, s: Side) -> Chain {
        if ch.side == Side::Both || ch.verts.len() < 2 {
            ch.verts.push(v);
            ch.side = s;
            return ch;
        }
        if ch.side != s {
            self.fan(&ch, v);
            let last = *ch.verts.last().unwrap();
            return Chain { verts: vec![last, v], side: s };
        }
        while ch.verts.len() >= 2 {
            let n = ch.verts.len();
            let (a, b) = (ch.verts[n - 2], ch.verts[n - 1]);
            let o = orient(self.verts[a].p, self.verts[b].p, self.verts[v].p);
            let convex = if s == Side::Lower { o > 0.0 } else { o < 0.0 };
            if !convex {
                break;
            }
            self.tri(a, b, v);
            ch.verts.pop();
        }
        ch.verts.push(v);
        ch
    }

    /// v arrives on one side of the region.
    fn add(&mut self, r: Reg, v: usize, s: Side) -> Reg {
        let mut subs = r.subs;
        let keep = if s == Side::Lower { subs.len() - 1 } else { 0 };
        let mut kept = None;
        for (i, ch) in subs.drain(..).enumerate() {
            if i == keep {
                kept = Some(ch);
            } else {
                self.fan(&ch, v);
            }
        }
        let ch = self.step(kept.unwrap(), v, s);
        Reg { subs: vec![ch] }
    }

    /// v ends the region.
    fn close(&mut self, r: Reg, v: usize) {
        for ch in &r.subs {
            self.fan(ch, v);
        }
    }

    /// v starts a hole inside the region: returns the parts below and above.
    fn split(&mut self, r: Reg, v: usize) -> (Reg, Reg) {
        let mut subs = r.subs;
        if subs.len() > 1 {
            let top = subs.pop().unwrap();
            let mut it = subs.into_iter();
            let bottom = it.next().unwrap();
            for ch in it {
                self.fan(&ch, v);
            }
            let lower = self.step(bottom, v, Side::Upper);
            let upper = self.step(top, v, Side::Lower);
            return (Reg { subs: vec![lower] }, Reg { subs: vec![upper] });
        }
        let ch = subs.pop().unwrap();
        let h = *ch.verts.last().unwrap();
        if ch.side == Side::Upper {
            let lower = self.step(ch, v, Side::Upper);
            (Reg { subs: vec![lower] }, Reg { subs: vec![Chain { verts: vec![h, v], side: Side::Lower }] })
        } else {
            let upper = self.step(ch, v, Side::Lower);
            (Reg { subs: vec![Chain { verts: vec![h, v], side: Side::Upper }] }, Reg { subs: vec![upper] })
        }
    }
}
