//! The arrangement of the contours' edges: every crossing becomes a vertex
//! (COMBINE), and every edge is split at the vertices lying on it (within
//! EPS), so that afterwards edges meet only at shared endpoints.
//!
//! Candidate pairs: all pairs for small inputs; otherwise a uniform grid
//! of about n cells in which each edge is entered into the cells its
//! EPS-thickened segment passes through (not its whole bounding box, so
//! long diagonal edges stay cheap), stored flat (counts, then offsets); a
//! per-edge stamp reports each pair once, in a deterministic order.

use super::merge::Grid;
use super::sweep::{orient, Vert, EPS};

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

/// Buffers kept from one polygon to the next.
#[derive(Default)]
pub struct Scratch {
    bb: Vec<[f64; 4]>,
    pairs: Vec<(u32, u32)>,
    /// Split points: (segment, parameter, vertex).
    splits: Vec<(u32, f64, u32)>,
    seg_start: Vec<u32>,
    seg_cells: Vec<u32>,
    cell_start: Vec<u32>,
    cell_segs: Vec<u32>,
    stamp: Vec<u32>,
    out: Vec<Seg>,
    /// Split points grouped by segment: (parameter, vertex).
    by_seg: Vec<(f64, u32)>,
    /// Vertices split at in the last pass, and the pieces meeting there.
    hot: Vec<bool>,
    /// Per vertex: made by COMBINE at a crossing of two edges at a clear
    /// angle, met by no other edge, and with no short piece at it (the
    /// later pass has nothing to find there: see [`CLEAR_SIN`]).
    clean: Vec<bool>,
    /// Run the later pass at every split vertex, clean or not (tests:
    /// the skip must change nothing).
    check_all: bool,
    /// Test every first-pass pair the long way (tests: the shortcut to the
    /// crossing test must change nothing).
    slow_pairs: bool,
    inc: Vec<(u32, u32)>,
    pieces: Vec<Piece>,
    pe: Vec<PairEdge>,
    /// Per vertex: the id of the last long segment (more than
    /// [`SHORT_GROUP`] split points) whose chain went through it.
    seen: Vec<u32>,
    seen_id: u32,
}

impl Scratch {
    /// Room for about `n` of everything, made once when the tessellator
    /// gets its buffers: its first polygons then do not regrow each vector
    /// step by step (a fixed cost that shows on small polygons).
    pub(super) fn reserve(&mut self, n: usize) {
        self.bb.reserve(n);
        self.pairs.reserve(n);
        self.splits.reserve(n);
        self.seg_start.reserve(n);
        self.seg_cells.reserve(n);
        self.cell_start.reserve(n);
        self.cell_segs.reserve(n);
        self.stamp.reserve(n);
        self.out.reserve(n);
        self.by_seg.reserve(n);
        self.hot.reserve(n);
        self.clean.reserve(n);
        self.inc.reserve(n);
        self.pieces.reserve(n);
        self.pe.reserve(n);
    }
}

/// Splits `segs` in place at every crossing and at every vertex lying on
/// another edge. Repeats (a few passes at most) because rounded crossing
/// points can create new near-crossings. Returns false if the combiner aborted.
///
/// Only the first pass tests all candidate pairs. A later one tests the
/// pieces that meet at a vertex where the previous pass split (for an end
/// within EPS of the other piece: they share that vertex, so they cannot
/// cross): pieces lie
/// within rounding of their parent edges, so pieces of edges that neither
/// crossed nor came within EPS cannot meet, and what rounding can do near
/// a new vertex (a piece folding onto another, a sliver between three
/// nearly concurrent edges) shows as a vertex within EPS of a piece that
/// shares another vertex with it.
pub fn split_all(verts: &mut Vec<Vert>, grid: &mut Grid, segs: &mut Vec<Seg>, comb: &mut dyn Combiner, sc: &mut Scratch) -> bool {
    let n = verts.len();
    sc.splits.clear();
    sc.clean.clear();
    sc.clean.resize(n, false);
    let fast = !sc.slow_pairs;
    if segs.len() <= ALL_PAIRS {
        if !all_pairs(verts, grid, segs, comb, sc, fast) {
            return false;
        }
    } else {
        candidate_pairs(verts, segs, sc);
        // Each pair makes at most one new vertex (bounded, in case of very many pairs).
        grid.reserve(verts, n, n + sc.pairs.len().min(8 * n + 1024));
        for k in 0..sc.pairs.len() {
            let (i, j) = sc.pairs[k];
            if !intersect(verts, grid, segs, i as usize, j as usize, comb, &mut sc.splits, &mut sc.clean, fast) {
                return false;
            }
        }
    }
    // (Every new vertex got its flag; padded in case a combiner added more.)
    sc.clean.resize(verts.len(), false);
    for pass in 0..4 {
        if sc.splits.is_empty() {
            return true;
        }
        // Split points per segment in order of their parameter: a counting
        // sort by segment, then insertion sorts (a segment has few).
        let n = segs.len();
        sc.seg_start.clear();
        sc.seg_start.resize(n + 1, 0);
        for x in &sc.splits {
            sc.seg_start[x.0 as usize + 1] += 1;
        }
        for i in 0..n {
            sc.seg_start[i + 1] += sc.seg_start[i];
        }
        sc.by_seg.clear();
        sc.by_seg.resize(sc.splits.len(), (0.0, 0));
        sc.stamp.clear();
        sc.stamp.extend_from_slice(&sc.seg_start[..n]);
        for x in &sc.splits {
            let f = &mut sc.stamp[x.0 as usize];
            sc.by_seg[*f as usize] = (x.1, x.2);
            *f += 1;
        }
        sc.out.clear();
        let clean = &mut sc.clean;
        for (i, s) in segs.iter().enumerate() {
            let g = &mut sc.by_seg[sc.seg_start[i] as usize..sc.seg_start[i + 1] as usize];
            if g.len() > SHORT_GROUP {
                g.sort_unstable_by(|x, y| x.0.total_cmp(&y.0));
            } else {
                // (A plain comparison: the parameters are never NaN or
                // -0.0, the two cases where it differs from `total_cmp`:
                // quotients of positive numbers, or clamped into [0, 1].)
                for k in 1..g.len() {
                    let mut j = k;
                    while j > 0 && g[j - 1].0 > g[j].0 {
                        g.swap(j - 1, j);
                        j -= 1;
                    }
                }
            }
            if g.is_empty() {
                sc.out.push(*s);
                continue;
            }
            // A piece shorter than 2·SHORT (by its parameters: the points
            // lie within rounding of where the parameters put them) leaves
            // its ends to the later pass.
            let (pa, pb) = (verts[s.a].p, verts[s.b].p);
            let (dx, dy) = (pb[0] - pa[0], pb[1] - pa[1]);
            let lim = 4.0 * SHORT * SHORT / (dx * dx + dy * dy);
            let (mut cur, mut tc) = (s.a, 0.0);
            // Each vertex once per chain: two vertices at one parameter
            // (within EPS of the segment, on either side of it) may sort
            // as v, w, v, ...; pieces v-w-v there would be split again by
            // the next pass, and again, growing without bound (fuzz run
            // 15: 52 segments on 5 vertices made 3,647 pieces, then
            // millions). The later occurrences are dropped: the chain
            // still runs from s.a through every vertex on s to s.b
            // (about 2 % of the self-intersecting set's instructions).
            let long = g.len() > SHORT_GROUP;
            if long {
                sc.seen_id = sc.seen_id.wrapping_add(1);
                if sc.seen_id == 0 || sc.seen.len() < verts.len() {
                    sc.seen.clear();
                    sc.seen.resize(verts.len(), 0);
                    sc.seen_id = 1;
                }
            }
            for (k, &(t, v)) in g.iter().enumerate() {
                let v = v as usize;
                // (A repeat needs three points, v, w, v: `cur` catches a
                // consecutive one.)
                let repeated = if long {
                    std::mem::replace(&mut sc.seen[v], sc.seen_id) == sc.seen_id
                } else {
                    k >= 2 && g[..k - 1].iter().any(|&(_, u)| u as usize == v)
                };
                if v != cur && v != s.b && v != s.a && !repeated {
                    sc.out.push(Seg { a: cur, b: v });
                    if !((t - tc) * (t - tc) >= lim) {
                        clean[cur] = false;
                        clean[v] = false;
                    }
                    cur = v;
                    tc = t;
                }
            }
            if cur != s.b {
                sc.out.push(Seg { a: cur, b: s.b });
                if !((1.0 - tc) * (1.0 - tc) >= lim) {
                    clean[cur] = false;
                }
            }
        }
        std::mem::swap(segs, &mut sc.out);
        if pass == 3 {
            break;
        }
        touching_at_split_vertices(verts, segs, sc, pass == 0);
    }
    true
}

/// Crossings whose edges meet at a sine of at least this are clear: where
/// two such edges cross at a new vertex v and no piece at v is shorter
/// than [`SHORT`], the later pass cannot fire at v. Why: every piece's
/// ends lie within 2 EPS of its parent's line (a crossing point at such
/// an angle within rounding of both lines, a merged or touching vertex
/// within 1.5 EPS), so a piece of length >= SHORT (2^-20) points within
/// 4 EPS/SHORT < 10^-6 rad of its parent; pieces of the two edges meet at
/// a sine above 0.99·10^-3, and the far end of one lies at least
/// SHORT·0.99·10^-3 (about 10^-9, 4,000 EPS) from the other's line; the
/// two pieces of one edge point apart (the dot-product tests reject). The
/// pass's own tests would return nothing there, so skipping them changes
/// no output.
const CLEAR_SIN: f64 = 1.0e-3;
/// A segment's split points up to this many are sorted and checked for
/// repeats in place; more, with `sort_unstable` and `Scratch::seen`.
const SHORT_GROUP: usize = 16;
const SHORT: f64 = 1.0 / (1u64 << 20) as f64;

/// A later pass: the pieces meeting at each vertex the last pass split at,
/// tested pairwise (chained lists per vertex: `seg_start` heads, `inc`
/// links) for an endpoint within EPS of the other piece, into `sc.splits`.
/// Such pieces share that vertex, so this is all [`intersect`] would find
/// for them (its crossing test needs four distinct ends); done here without
/// the list of pairs, in the order `intersect` would push.
///
/// After the first pass, vertices still `clean` are left out (their tests
/// would find nothing: [`CLEAR_SIN`]); when that is all of them, the pass
/// ends here, without its per-vertex set-up.
fn touching_at_split_vertices(verts: &[Vert], segs: &[Seg], sc: &mut Scratch, first: bool) {
    const NONE: u32 = u32::MAX;
    let nv = verts.len();
    let first = first && !sc.check_all;
    if first && sc.splits.iter().all(|x| sc.clean[x.2 as usize]) {
        sc.splits.clear();
        return;
    }
    sc.hot.clear();
    sc.hot.resize(nv, false);
    for x in &sc.splits {
        sc.hot[x.2 as usize] = !(first && sc.clean[x.2 as usize]);
    }
    sc.splits.clear();
    // (vertex, segment) incidences at hot vertices, as linked lists.
    sc.seg_start.clear();
    sc.seg_start.resize(nv, NONE);
    sc.inc.clear();
    for (i, s) in segs.iter().enumerate() {
        for v in [s.a, s.b] {
            if sc.hot[v] {
                sc.inc.push((i as u32, sc.seg_start[v]));
                sc.seg_start[v] = sc.inc.len() as u32 - 1;
            }
        }
    }
    let out = &mut sc.splits;
    let pieces = &mut sc.pieces;
    for v in 0..nv {
        // The pieces at v, in list order, with what the tests below need
        // of each (the same expressions as `lies_on`, so the same results).
        pieces.clear();
        let mut a = sc.seg_start[v];
        while a != NONE {
            let (i, link) = sc.inc[a as usize];
            let s = segs[i as usize];
            let (pa, pb) = (verts[s.a].p, verts[s.b].p);
            let (dx, dy) = (pb[0] - pa[0], pb[1] - pa[1]);
            let far = if s.a == v { s.b } else { s.a };
            pieces.push(Piece { seg: i, far: far as u32, pf: verts[far].p, a: pa, d: [dx, dy], l2: dx * dx + dy * dy });
            a = link;
        }
        for (k, x) in pieces.iter().enumerate() {
            for y in &pieces[k + 1..] {
                let (s, r) = if x.seg <= y.seg { (x, y) } else { (y, x) };
                if s.far != r.far {
                    if let Some(t) = lies_on_piece(r.pf, s) {
                        out.push((s.seg, t, r.far));
                    }
                    if let Some(t) = lies_on_piece(s.pf, r) {
                        out.push((r.seg, t, s.far));
                    }
                }
            }
        }
    }
}

/// A piece at a split vertex: its segment, its other end (id and point),
/// its start point, direction and squared length.
#[derive(Clone, Copy)]
struct Piece {
    seg: u32,
    far: u32,
    pf: [f64; 2],
    a: [f64; 2],
    d: [f64; 2],
    l2: f64,
}

/// [`lies_on`] for a piece, with its direction and length precomputed
/// (operation for operation the same arithmetic).
#[inline]
fn lies_on_piece(p: [f64; 2], s: &Piece) -> Option<f64> {
    let (a, [dx, dy], l2) = (s.a, s.d, s.l2);
    if !(l2 > 0.0) {
        return None;
    }
    let dot = (p[0] - a[0]) * dx + (p[1] - a[1]) * dy;
    if !(dot > 0.0 && dot < l2) {
        return None;
    }
    let o = dx * (p[1] - a[1]) - dy * (p[0] - a[0]);
    (o * o <= EPS * EPS * l2).then(|| dot / l2)
}

/// Below this many edges, all pairs are tested (cheaper than a grid).
const ALL_PAIRS: usize = 48;

/// An edge as [`all_pairs`] reads it: its ends (ids and points), its box
/// grown by EPS, its direction and the bound `lies_on` compares an
/// orientation's square with (EPS² times its squared length), each the
/// same expression as there, so the same values.
#[derive(Clone, Copy, Default)]
struct PairEdge {
    bb: [f64; 4],
    a: [f64; 2],
    b: [f64; 2],
    e: [f64; 2],
    tol: f64,
    ia: usize,
    ib: usize,
}

/// The first pass for at most [`ALL_PAIRS`] edges: every pair whose boxes
/// overlap, in order (i, then j > i), tested as it is found. The four
/// orientations come first, from edges read once into `sc.pe` (no vertex
/// lookups per pair): when all four ends are distinct and each lies
/// farther than EPS from the other edge's line, no end can lie on the
/// other edge, and only the crossing test remains (most pairs); otherwise
/// [`intersect`] tests the pair in full. The results are those of
/// [`intersect`] on every pair (`fast` false: that, for tests). The grid is
/// not reserved: with so few edges it is still scanned linearly or small.
fn all_pairs(verts: &mut Vec<Vert>, grid: &mut Grid, segs: &[Seg], comb: &mut dyn Combiner, sc: &mut Scratch, fast: bool) -> bool {
    sc.pe.clear();
    sc.pe.extend(segs.iter().map(|s| {
        let (a, b) = (verts[s.a].p, verts[s.b].p);
        let e = [b[0] - a[0], b[1] - a[1]];
        let bb = [a[0].min(b[0]) - EPS, a[1].min(b[1]) - EPS, a[0].max(b[0]) + EPS, a[1].max(b[1]) + EPS];
        PairEdge { bb, a, b, e, tol: EPS * EPS * (e[0] * e[0] + e[1] * e[1]), ia: s.a, ib: s.b }
    }));
    let (pe, out, clean) = (&sc.pe, &mut sc.splits, &mut sc.clean);
    for (i, x) in pe.iter().enumerate() {
        for (j, y) in pe.iter().enumerate().skip(i + 1) {
            if !(x.bb[0] <= y.bb[2] && y.bb[0] <= x.bb[2] && x.bb[1] <= y.bb[3] && y.bb[1] <= x.bb[3]) {
                continue;
            }
            // orient(c, d, a), orient(c, d, b), orient(a, b, c), orient(a, b, d).
            let d1 = y.e[0] * (x.a[1] - y.a[1]) - y.e[1] * (x.a[0] - y.a[0]);
            let d2 = y.e[0] * (x.b[1] - y.a[1]) - y.e[1] * (x.b[0] - y.a[0]);
            let d3 = x.e[0] * (y.a[1] - x.a[1]) - x.e[1] * (y.a[0] - x.a[0]);
            let d4 = x.e[0] * (y.b[1] - x.a[1]) - x.e[1] * (y.b[0] - x.a[0]);
            let far = !(d3 * d3 <= x.tol) && !(d4 * d4 <= x.tol) && !(d1 * d1 <= y.tol) && !(d2 * d2 <= y.tol);
            let ok = if fast && far && x.ia != y.ia && x.ia != y.ib && x.ib != y.ia && x.ib != y.ib {
                if ((d1 > 0.0 && d2 < 0.0) || (d1 < 0.0 && d2 > 0.0)) && ((d3 > 0.0 && d4 < 0.0) || (d3 < 0.0 && d4 > 0.0)) {
                    cross(verts, grid, i, j, segs[i], segs[j], [x.a, x.b, y.a, y.b], [d1, d2, d3, d4], comb, out, clean)
                } else {
                    true
                }
            } else {
                intersect(verts, grid, segs, i, j, comb, out, clean, false)
            };
            if !ok {
                return false;
            }
        }
    }
    true
}

/// The edges' boxes, grown by EPS, into `sc.bb`.
fn boxes(verts: &[Vert], segs: &[Seg], sc: &mut Scratch) {
    sc.bb.clear();
    sc.bb.extend(segs.iter().map(|s| {
        let (p, q) = (verts[s.a].p, verts[s.b].p);
        [p[0].min(q[0]) - EPS, p[1].min(q[1]) - EPS, p[0].max(q[0]) + EPS, p[1].max(q[1]) + EPS]
    }));
}

/// The pairs of edges whose boxes (grown by EPS) overlap and which may
/// touch, each once, into `sc.pairs` (more than [`ALL_PAIRS`] edges).
fn candidate_pairs(verts: &[Vert], segs: &[Seg], sc: &mut Scratch) {
    let n = segs.len();
    sc.pairs.clear();
    boxes(verts, segs, sc);
    let bb = &sc.bb;
    let overlap = |i: usize, j: usize| {
        let (a, b) = (&bb[i], &bb[j]);
        a[0] <= b[2] && b[0] <= a[2] && a[1] <= b[3] && b[1] <= a[3]
    };
    let (mut lo, mut hi) = ([f64::INFINITY; 2], [f64::NEG_INFINITY; 2]);
    for b in bb {
        lo = [lo[0].min(b[0]), lo[1].min(b[1])];
        hi = [hi[0].max(b[2]), hi[1].max(b[3])];
    }
    // About n square cells (the box's aspect ratio kept).
    let (w, h) = ((hi[0] - lo[0]).max(EPS), (hi[1] - lo[1]).max(EPS));
    let side = (w * h / n as f64).sqrt();
    let cap = (2 * n + 4).min(1 << 22);
    let mut gs = [((w / side) as usize).clamp(1, cap), ((h / side) as usize).clamp(1, cap)];
    while gs[0] * gs[1] > cap {
        let k = if gs[0] > gs[1] { 0 } else { 1 };
        gs[k] = (gs[k] / 2).max(1);
    }
    let size = [(w / gs[0] as f64).max(f64::MIN_POSITIVE), (h / gs[1] as f64).max(f64::MIN_POSITIVE)];
    let cell = |x: f64, k: usize| {
        let c = (x - lo[k]) / size[k];
        if c > 0.0 {
            (c as usize).min(gs[k] - 1)
        } else {
            0
        }
    };
    let g = gs[0];
    // The cells each edge passes through: per column of its box, the rows
    // its EPS-thickened segment covers there.
    sc.seg_start.clear();
    sc.seg_cells.clear();
    for (i, s) in segs.iter().enumerate() {
        sc.seg_start.push(sc.seg_cells.len() as u32);
        let b = bb[i];
        let (x0, x1) = (cell(b[0], 0), cell(b[2], 0));
        let (p, q) = (verts[s.a].p, verts[s.b].p);
        let (y0b, y1b) = (cell(b[1], 1), cell(b[3], 1));
        if x0 == x1 || p[0] == q[0] {
            for x in x0..=x1 {
                for y in y0b..=y1b {
                    sc.seg_cells.push((y * g + x) as u32);
                }
            }
            continue;
        }
        let slope = (q[1] - p[1]) / (q[0] - p[0]);
        let (xmin, xmax) = (p[0].min(q[0]), p[0].max(q[0]));
        for x in x0..=x1 {
            // The column's x range, grown by EPS, within the segment's.
            let cx0 = (lo[0] + x as f64 * size[0] - EPS).max(xmin);
            let cx1 = (lo[0] + (x + 1) as f64 * size[0] + EPS).min(xmax);
            let (ya, yb) = (p[1] + (cx0 - p[0]) * slope, p[1] + (cx1 - p[0]) * slope);
            let (r0, r1) = (cell(ya.min(yb) - EPS, 1).max(y0b), cell(ya.max(yb) + EPS, 1).min(y1b));
            // (Rounding at the box's ends: fall back to the whole box column.)
            let (r0, r1) = if cx0 <= cx1 && r0 <= r1 { (r0, r1) } else { (y0b, y1b) };
            for y in r0..=r1 {
                sc.seg_cells.push((y * g + x) as u32);
            }
        }
    }
    sc.seg_start.push(sc.seg_cells.len() as u32);
    // Cells' lists, flat.
    let nc = gs[0] * gs[1];
    sc.cell_start.clear();
    sc.cell_start.resize(nc + 1, 0);
    for &c in &sc.seg_cells {
        sc.cell_start[c as usize + 1] += 1;
    }
    for c in 0..nc {
        sc.cell_start[c + 1] += sc.cell_start[c];
    }
    sc.cell_segs.clear();
    sc.cell_segs.resize(sc.seg_cells.len(), 0);
    {
        let mut fill: Vec<u32> = sc.cell_start[..nc].to_vec();
        for i in 0..n {
            for k in sc.seg_start[i]..sc.seg_start[i + 1] {
                let c = sc.seg_cells[k as usize] as usize;
                sc.cell_segs[fill[c] as usize] = i as u32;
                fill[c] += 1;
            }
        }
    }
    // Pairs: for each edge, the later edges sharing a cell with it, once.
    sc.stamp.clear();
    sc.stamp.resize(n, u32::MAX);
    for i in 0..n {
        for k in sc.seg_start[i]..sc.seg_start[i + 1] {
            let c = sc.seg_cells[k as usize] as usize;
            for &j in &sc.cell_segs[sc.cell_start[c] as usize..sc.cell_start[c + 1] as usize] {
                if j as usize > i && sc.stamp[j as usize] != i as u32 {
                    sc.stamp[j as usize] = i as u32;
                    if overlap(i, j as usize) {
                        sc.pairs.push((i as u32, j));
                    }
                }
            }
        }
    }
}

/// If p lies within EPS of the open segment a-b, its parameter along it.
/// (Cheap rejections first: no division unless it lies on.)
#[inline]
fn lies_on(p: [f64; 2], a: [f64; 2], b: [f64; 2]) -> Option<f64> {
    let dx = b[0] - a[0];
    let dy = b[1] - a[1];
    let l2 = dx * dx + dy * dy;
    if !(l2 > 0.0) {
        return None;
    }
    let dot = (p[0] - a[0]) * dx + (p[1] - a[1]) * dy;
    if !(dot > 0.0 && dot < l2) {
        return None;
    }
    // Distance to the line at most EPS: orient² <= EPS² · l2.
    let o = orient(a, b, p);
    (o * o <= EPS * EPS * l2).then(|| dot / l2)
}

/// Tests edges i and j; pushes their split points. False if the combiner aborted.
/// `fast`: take the shortcut to the crossing test when no end lies near the
/// other edge's line (off only in tests, which compare both ways).
#[allow(clippy::too_many_arguments)]
fn intersect(verts: &mut Vec<Vert>, grid: &mut Grid, segs: &[Seg], i: usize, j: usize, comb: &mut dyn Combiner, out: &mut Vec<(u32, f64, u32)>, clean: &mut Vec<bool>, fast: bool) -> bool {
    let (s, r) = (segs[i], segs[j]);
    let (a, b, c, d) = (verts[s.a].p, verts[s.b].p, verts[r.a].p, verts[r.b].p);
    // The four orientations first: they are the ones `lies_on` would
    // compute (the same expressions), and when each end lies farther than
    // EPS from the other edge's line, no `lies_on` test can succeed, so
    // the crossing test follows directly (most pairs: the same results as
    // the tests below, without their dot products).
    let d1 = orient(c, d, a);
    let d2 = orient(c, d, b);
    let d3 = orient(a, b, c);
    let d4 = orient(a, b, d);
    let (e, f) = ([b[0] - a[0], b[1] - a[1]], [d[0] - c[0], d[1] - c[1]]);
    let (lab, lcd) = (e[0] * e[0] + e[1] * e[1], f[0] * f[0] + f[1] * f[1]);
    let (tab, tcd) = (EPS * EPS * lab, EPS * EPS * lcd);
    let far = !(d3 * d3 <= tab) && !(d4 * d4 <= tab) && !(d1 * d1 <= tcd) && !(d2 * d2 <= tcd);
    if far && s.a != r.a && s.a != r.b && s.b != r.a && s.b != r.b && fast {
        return cross(verts, grid, i, j, s, r, [a, b, c, d], [d1, d2, d3, d4], comb, out, clean);
    }
    let before = out.len();
    // Endpoints lying on the other edge's interior (touching, collinear overlaps).
    for &(v, p) in &[(r.a, c), (r.b, d)] {
        if v != s.a && v != s.b {
            if let Some(t) = lies_on(p, a, b) {
                out.push((i as u32, t, v as u32));
            }
        }
    }
    for &(v, p) in &[(s.a, a), (s.b, b)] {
        if v != r.a && v != r.b {
            if let Some(t) = lies_on(p, c, d) {
                out.push((j as u32, t, v as u32));
            }
        }
    }
    if out.len() == before && s.a != r.a && s.a != r.b && s.b != r.a && s.b != r.b {
        return cross(verts, grid, i, j, s, r, [a, b, c, d], [d1, d2, d3, d4], comb, out, clean);
    }
    true
}

/// The crossing test of edges i (a→b) and j (c→d), given the four
/// orientations d1 = orient(c, d, a), d2 = orient(c, d, b), d3 =
/// orient(a, b, c), d4 = orient(a, b, d): at a proper crossing, the vertex
/// there (an existing one within EPS, or a new one from the combiner) and
/// the two split points. False if the combiner aborted.
#[inline(always)]
#[allow(clippy::too_many_arguments)]
fn cross(verts: &mut Vec<Vert>, grid: &mut Grid, i: usize, j: usize, s: Seg, r: Seg, [a, b, c, d]: [[f64; 2]; 4], [d1, d2, d3, d4]: [f64; 4], comb: &mut dyn Combiner, out: &mut Vec<(u32, f64, u32)>, clean: &mut Vec<bool>) -> bool {
    if ((d1 > 0.0 && d2 < 0.0) || (d1 < 0.0 && d2 > 0.0)) && ((d3 > 0.0 && d4 < 0.0) || (d3 < 0.0 && d4 > 0.0)) {
        let t = (d1 / (d1 - d2)).clamp(0.0, 1.0);
        let u = (d3 / (d3 - d4)).clamp(0.0, 1.0);
        // Average both parametrisations: symmetric and within both edges' boxes.
        let p1 = [a[0] + t * (b[0] - a[0]), a[1] + t * (b[1] - a[1])];
        let p2 = [c[0] + u * (d[0] - c[0]), c[1] + u * (d[1] - c[1])];
        let p = [0.5 * (p1[0] + p2[0]), 0.5 * (p1[1] + p2[1])];
        let v = match grid.find(verts, p) {
            Some(v) => {
                // Met again: no longer a plain crossing of two edges.
                if let Some(c) = clean.get_mut(v) {
                    *c = false;
                }
                v
            }
            None => match comb.combine(verts, p, [s.a, s.b, r.a, r.b], t, u) {
                Some(v) => {
                    grid.insert(verts, v);
                    // sin² of the angle between the edges: cross² / (|ab|² |cd|²).
                    let (e, f) = ([b[0] - a[0], b[1] - a[1]], [d[0] - c[0], d[1] - c[1]]);
                    let x = e[0] * f[1] - e[1] * f[0];
                    let l = (e[0] * e[0] + e[1] * e[1]) * (f[0] * f[0] + f[1] * f[1]);
                    if clean.len() != v {
                        clean.resize(v, false);
                    }
                    clean.push(x * x >= CLEAR_SIN * CLEAR_SIN * l);
                    v
                }
                None => return false,
            },
        };
        if v != s.a && v != s.b {
            out.push((i as u32, t, v as u32));
        }
        if v != r.a && v != r.b {
            out.push((j as u32, u, v as u32));
        }
    }
    true
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::glu::tess::test_rng::unit_rng;

    struct Plain;
    impl Combiner for Plain {
        fn combine(&mut self, verts: &mut Vec<Vert>, p: [f64; 2], _: [usize; 4], _: f64, _: f64) -> Option<usize> {
            verts.push(Vert { p });
            Some(verts.len() - 1)
        }
    }

    /// The arrangement of one closed polygon, with or without the later
    /// pass's skip at clean crossings.
    fn arrangement(pts: &[[f64; 2]], check_all: bool) -> (Vec<[f64; 2]>, Vec<(usize, usize)>) {
        arrangement_with(pts, Scratch { check_all, ..Scratch::default() })
    }

    fn arrangement_with(pts: &[[f64; 2]], mut sc: Scratch) -> (Vec<[f64; 2]>, Vec<(usize, usize)>) {
        let mut verts: Vec<Vert> = pts.iter().map(|&p| Vert { p }).collect();
        let mut grid = Grid::default();
        grid.reset(verts.len());
        grid.insert_all(&verts);
        let n = pts.len();
        let mut segs: Vec<Seg> = (0..n).map(|i| Seg { a: i, b: (i + 1) % n }).collect();
        assert!(split_all(&mut verts, &mut grid, &mut segs, &mut Plain, &mut sc));
        (verts.iter().map(|v| v.p).collect(), segs.iter().map(|s| (s.a, s.b)).collect())
    }

    /// Skipping the later pass at clean crossings gives the arrangement
    /// running it everywhere gives, on input made to make it fire: chords
    /// through nearly one point (crossings a few EPS apart at clear
    /// angles: short pieces), nearly parallel long edges (pieces at sines
    /// far below CLEAR_SIN), and random polygons.
    #[test]
    fn skipping_clean_crossings_changes_nothing() {
        let mut rnd = unit_rng(0x2545_f491_4f6c_dd1du64);
        let mut fired = 0;
        for k in 0..600 {
            let m = 4 + (rnd() * 20.0) as usize;
            let pts: Vec<[f64; 2]> = match k % 3 {
                // Chords through nearly the origin: alternate ends of
                // lines at random angles, offset by 3 to 50 EPS.
                0 => {
                    let (mut a, mut off) = (0.0f64, 0.0);
                    (0..m)
                        .map(|i| {
                            if i % 2 == 0 {
                                a = rnd() * std::f64::consts::PI;
                                off = (rnd() - 0.5) * [6.0, 30.0, 100.0][k / 3 % 3] * EPS;
                            }
                            let sgn = if i % 2 == 0 { 1.0 } else { -1.0 };
                            [sgn * a.cos() - off * a.sin(), sgn * a.sin() + off * a.cos()]
                        })
                        .collect()
                }
                // Zigzags between two nearly parallel lines (slopes
                // 10^-12 to 10^-6 apart), so their edges cross at tiny angles.
                1 => {
                    let d = 10f64.powf(-6.0 - 6.0 * rnd());
                    (0..m)
                        .map(|i| {
                            let x = 2.0 * rnd() - 1.0;
                            let y = if i % 2 == 0 { 0.3 * x } else { (0.3 + d) * x + (rnd() - 0.5) * 4.0 * EPS };
                            [x, y]
                        })
                        .collect()
                }
                _ => (0..m).map(|_| [2.0 * rnd() - 1.0, 2.0 * rnd() - 1.0]).collect(),
            };
            let skip = arrangement(&pts, false);
            let all = arrangement(&pts, true);
            assert_eq!(skip, all, "polygon {k}: {pts:?}");
            fired += (all.1.len() > pts.len()) as usize;
        }
        assert!(fired > 300, "only {fired} polygons split");
    }

    /// The first pass's shortcut (straight to the crossing test when every
    /// end lies farther than EPS from the other edge's line) gives the
    /// arrangement the full test of every pair gives (`slow_pairs`), on
    /// input made to fall on both sides of it: vertices placed on earlier
    /// edges at -3 to 3 EPS from them (T-junctions found by `lies_on`, and
    /// ends just too far for it), points near a few lines (collinear
    /// overlaps), and random polygons (plain crossings), for the all-pairs
    /// loop and (more than [`ALL_PAIRS`] edges) the grid's pairs.
    #[test]
    fn pair_shortcut_changes_nothing() {
        let mut rnd = unit_rng(0x9e37_79b9_7f4a_7c15u64);
        let (mut touched, mut crossed) = (0, 0);
        for k in 0..900 {
            let m = if k % 10 == 9 { 50 + (rnd() * 30.0) as usize } else { 4 + (rnd() * 24.0) as usize };
            let mut pts: Vec<[f64; 2]> = Vec::with_capacity(m);
            match k % 3 {
                // Each vertex after the third on an earlier edge, offset
                // across it by up to 3 EPS.
                0 => {
                    for i in 0..m {
                        if i < 3 {
                            pts.push([2.0 * rnd() - 1.0, 2.0 * rnd() - 1.0]);
                            continue;
                        }
                        let e = (rnd() * (i - 1) as f64) as usize;
                        let (a, b) = (pts[e], pts[e + 1]);
                        let (t, off) = (0.05 + 0.9 * rnd(), (rnd() - 0.5) * 6.0 * EPS);
                        let (dx, dy) = (b[0] - a[0], b[1] - a[1]);
                        let l = (dx * dx + dy * dy).sqrt();
                        pts.push([a[0] + t * dx - off * dy / l, a[1] + t * dy + off * dx / l]);
                    }
                }
                // Points within 2 EPS of one of three lines.
                1 => {
                    let lines: Vec<(f64, f64)> = (0..3).map(|_| (2.0 * rnd() - 1.0, 0.5 * rnd() - 0.25)).collect();
                    for _ in 0..m {
                        let (s, c) = lines[(rnd() * 3.0) as usize];
                        let x = 2.0 * rnd() - 1.0;
                        pts.push([x, s * x + c + (rnd() - 0.5) * 4.0 * EPS]);
                    }
                }
                _ => pts.extend((0..m).map(|_| [2.0 * rnd() - 1.0, 2.0 * rnd() - 1.0])),
            }
            let fast = arrangement_with(&pts, Scratch::default());
            let slow = arrangement_with(&pts, Scratch { slow_pairs: true, ..Scratch::default() });
            assert_eq!(fast, slow, "polygon {k}: {pts:?}");
            // (Split at input vertices: touching; at new ones: crossings.)
            touched += slow.1.iter().filter(|&&(a, b)| a < m && b < m && (a + 1) % m != b).count().min(1);
            crossed += (slow.0.len() > m) as usize;
        }
        assert!(touched > 200 && crossed > 300, "touched {touched}, crossed {crossed}");
    }
}
