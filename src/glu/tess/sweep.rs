//! The tessellator's planar core, in 2D and double precision: given the
//! arrangement of the contours' edges (every crossing and touching split
//! into vertices by [`super::split`]), one sweep computes the winding
//! number of every face, the boundary of the region a winding rule selects
//! and its triangulation (one monotone "reflex chain" per interior region
//! between boundary edges, the textbook monotone-polygon triangulation run
//! on all regions at once; merge vertices are resolved by the next vertex
//! that arrives). Until 2026-11-27 windings and triangles were two sweeps;
//! the one sweep gives the same triangles and boundary edges.
//!
//! Invariants: vertices are visited in lexicographic (x, y) order, every
//! edge runs from its smaller to its larger end in that order, and "above"
//! an edge means to the left of it. Every loop is bounded by the input
//! size; when floating-point inconsistencies (edges that still cross after
//! splitting) break the sweep's assumptions, it degrades (drops a piece)
//! but never loops or indexes out of bounds. All sorts use total orders.

use super::split::Seg;

/// A planar vertex: 2D position (normalised to about [-1, 1]).
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
    /// Pseudo-angle of lo→hi: orders a vertex's outgoing edges.
    key: f64,
}

/// The selected region: its boundary edges directed with the region on
/// their left, and its triangles (counter-clockwise).
#[derive(Default)]
pub struct Region {
    pub boundary: Vec<(usize, usize)>,
    pub triangles: Vec<[usize; 3]>,
}

/// Which triangle edges lie on the region's boundary (for the edge flags):
/// the boundary's edges as sorted (min, max) pairs, found by binary search.
pub struct BoundaryIndex {
    set: Vec<(u32, u32)>,
}

impl BoundaryIndex {
    pub fn new(r: &Region) -> Self {
        let mut set: Vec<(u32, u32)> = r.boundary.iter().map(|&(a, b)| (a.min(b) as u32, a.max(b) as u32)).collect();
        set.sort_unstable();
        BoundaryIndex { set }
    }

    pub fn on_boundary(&self, a: usize, b: usize) -> bool {
        self.set.binary_search(&(a.min(b) as u32, a.max(b) as u32)).is_ok()
    }
}

fn lex_less(p: [f64; 2], q: [f64; 2]) -> bool {
    p[0] < q[0] || (p[0] == q[0] && p[1] < q[1])
}

/// An integer with the order of `f64::total_cmp`.
#[inline]
pub fn ord_key(x: f64) -> u64 {
    let b = x.to_bits();
    if b >> 63 == 1 {
        !b
    } else {
        b | 1 << 63
    }
}

/// Buffers kept from one polygon to the next; `region` leaves its result
/// in `boundary` and `triangles`.
#[derive(Default)]
pub struct Scratch {
    edges: Vec<Edge>,
    order: Vec<u32>,
    keyed: Vec<(u64, u64, u32)>,
    out: Vec<u32>,
    inc: Vec<u32>,
    active: Vec<Active>,
    outs: Vec<Active>,
    pub(super) pool: Pool,
    pub region: Region,
}

impl Scratch {
    /// Room for about `n` of everything, made once when the tessellator
    /// gets its buffers: its first polygons then do not regrow each vector
    /// step by step (a fixed cost that shows on small polygons).
    pub(super) fn reserve(&mut self, n: usize) {
        self.edges.reserve(n);
        self.order.reserve(n);
        self.keyed.reserve(n);
        self.out.reserve(n);
        self.inc.reserve(n);
        self.active.reserve(n);
        self.outs.reserve(n);
        self.region.boundary.reserve(n);
        self.region.triangles.reserve(n);
    }
}

/// Computes windings and the selected region into `sc.region`;
/// triangulates it unless `boundary_only`.
///
/// `sorted`, if given, is every vertex id in sweep order (the fast path's
/// sort merged with the new vertices'); otherwise the vertices are sorted here.
pub fn region(verts: &[Vert], segs: &[Seg], rule: Rule, boundary_only: bool, sorted: Option<&[u32]>, sc: &mut Scratch) {
    let nv = verts.len();
    let Scratch { edges, order, keyed, out, inc, active, outs, pool, region } = sc;
    let Region { boundary, triangles: tris } = region;
    boundary.clear();
    tris.clear();
    // Edges grouped by their left end (a counting sort: no comparisons),
    // each vertex's group ordered counter-clockwise from straight down by a
    // pseudo-angle of the direction (monotone in the angle on the half plane
    // lo→hi spans), then by hi, so that traversals of the same undirected
    // edge are adjacent and add up to its net multiplicity.
    out.clear();
    out.resize(nv + 1, 0);
    for s in segs.iter().filter(|s| s.a != s.b) {
        let lo = if lex_less(verts[s.a].p, verts[s.b].p) { s.a } else { s.b };
        out[lo + 1] += 1;
    }
    for v in 0..nv {
        out[v + 1] += out[v];
    }
    // (Every slot is written below: what the buffer held is left in place
    // rather than cleared first, which cost a memset of it per polygon.)
    let m = out[nv] as usize;
    // (Nor shortened afterwards: the kept edges are a prefix, read as a
    // slice below, so the buffer keeps its high-water length and is
    // filled again only when a polygon needs more.)
    if edges.len() < m {
        edges.resize(m, Edge { lo: 0, hi: 0, w: 0, key: 0.0 });
    }
    {
        let fill = &mut *inc; // reused as the per-vertex fill cursor
        fill.clear();
        fill.extend_from_slice(&out[..nv]);
        for s in segs.iter().filter(|s| s.a != s.b) {
            // (Both ends read once, then ordered: not read again by id.)
            let (pa, pb) = (verts[s.a].p, verts[s.b].p);
            let (lo, hi, w, a, b) = if lex_less(pa, pb) { (s.a, s.b, 1, pa, pb) } else { (s.b, s.a, -1, pb, pa) };
            let (dx, dy) = (b[0] - a[0], b[1] - a[1]);
            let l = dx + dy.abs();
            let key = if l > 0.0 { dy / l } else { 0.0 };
            edges[fill[lo] as usize] = Edge { lo, hi, w, key };
            fill[lo] += 1;
        }
    }
    // Per group: insertion sort (groups are small), then merge runs of the
    // same hi and drop edges whose traversals cancel. The kept edges stay
    // grouped by lo: `out` becomes their offsets as it goes (entry v is
    // rewritten after being read, v + 1 still holds this group's end) and
    // `inc` their count per hi.
    let mut kept = 0;
    inc.clear();
    inc.resize(nv, 0);
    for v in 0..nv {
        let (g0, g1) = (out[v] as usize, out[v + 1] as usize);
        out[v] = kept as u32;
        let g = &mut edges[g0..g1];
        if g.len() > 16 {
            g.sort_unstable_by_key(|e| (ord_key(e.key), e.hi));
        } else {
            for i in 1..g.len() {
                let mut j = i;
                while j > 0 && (ord_key(g[j - 1].key), g[j - 1].hi) > (ord_key(g[j].key), g[j].hi) {
                    g.swap(j - 1, j);
                    j -= 1;
                }
            }
        }
        let mut i = g0;
        while i < g1 {
            let mut e = edges[i];
            i += 1;
            while i < g1 && edges[i].hi == e.hi {
                e.w += edges[i].w;
                i += 1;
            }
            if e.w != 0 {
                inc[e.hi] += 1;
                edges[kept] = e;
                kept += 1;
            }
        }
    }
    out[nv] = kept as u32;
    let edges = &edges[..kept];
    // Sweep order of vertices (integer keys sort faster than float compares).
    let order: &[u32] = match sorted {
        Some(k) => k,
        None => {
            order.clear();
            keyed.clear();
            keyed.extend(verts.iter().enumerate().map(|(i, v)| (ord_key(v.p[0]), ord_key(v.p[1]), i as u32)));
            keyed.sort_unstable();
            order.extend(keyed.iter().map(|k| k.2));
            order
        }
    };
    // One sweep: windings, the boundary and the triangles together. Every
    // edge is in the active list with the winding number above it (known
    // where it starts: from the entry below it), and whether it is on the
    // boundary (its two sides differ). The triangulation sees only the
    // boundary entries, as a sweep over the boundary alone would: a region
    // lies above a boundary entry with the region above it and reaches up
    // to the next boundary entry; vertices without boundary edges are not
    // its business.
    active.clear();
    let mut t = Tri { verts, out: tris, pool };
    let tri = !boundary_only;
    outs.clear();
    for &v in order.iter() {
        let v = v as usize;
        let (o0, o1) = (out[v] as usize, out[v + 1] as usize);
        if inc[v] == 0 && o0 == o1 {
            continue;
        }
        outs.clear();
        outs.extend(edges[o0..o1].iter().enumerate().map(|(k, x)| Active { e: (o0 + k) as u32, hi: x.hi as u32, w: 0, b: false, reg: None }));
        // The entries ending here (normally one contiguous block).
        let first = if inc[v] > 0 { active.iter().position(|x| x.hi as usize == v) } else { None };
        let Some(lo) = first else {
            // A start (or, inconsistent, an end not found: the same).
            let pv = verts[v].p;
            let pos = active.partition_point(|x| {
                let e = edges[x.e as usize];
                orient(verts[e.lo].p, verts[e.hi].p, pv) >= 0.0
            });
            let w0 = if pos > 0 { active[pos - 1].w } else { 0 };
            let top = start_outs(outs, w0, edges, rule, boundary);
            if tri {
                if let Some(k) = top {
                    // v starts a hole in the region around it, or a region.
                    let below = active[..pos].iter().rposition(|x| x.b);
                    let r = below.and_then(|i| active[i].reg.take());
                    start_regions(outs, k, rule, &mut t, v);
                    match r {
                        Some(r) => {
                            let (lower, upper) = t.split(r, v);
                            active[below.unwrap_or(0)].reg = Some(lower);
                            outs[k].reg = Some(upper);
                        }
                        None if rule.inside(outs[k].w) => outs[k].reg = Some(t.start(v)),
                        None => {}
                    }
                }
            }
            insert_all(active, pos, outs);
            continue;
        };
        // (All `inc` of them in one run, normally: no second scan.)
        let run = active[lo..].iter().take_while(|x| x.hi as usize == v).count();
        let hi = if run == inc[v] as usize { lo + run - 1 } else { active.iter().rposition(|x| x.hi as usize == v).unwrap_or(lo) };
        let w0 = if lo > 0 { active[lo - 1].w } else { 0 };
        let top = start_outs(outs, w0, edges, rule, boundary);
        let lo_b = active[lo..=hi].iter().position(|x| x.b).map(|i| lo + i);
        if tri && (lo_b.is_some() || top.is_some()) {
            let below = active[..lo_b.unwrap_or(lo)].iter().rposition(|x| x.b);
            let r_below = below.and_then(|i| active[i].reg.take());
            match lo_b {
                None => {
                    // Only boundary edges leaving: a start, as above.
                    let k = top.unwrap_or(0);
                    start_regions(outs, k, rule, &mut t, v);
                    match r_below {
                        Some(r) => {
                            let (lower, upper) = t.split(r, v);
                            active[below.unwrap_or(0)].reg = Some(lower);
                            outs[k].reg = Some(upper);
                        }
                        None if rule.inside(outs[k].w) => outs[k].reg = Some(t.start(v)),
                        None => {}
                    }
                }
                Some(lo_b) => {
                    let hi_b = active[..=hi].iter().rposition(|x| x.b).unwrap_or(lo_b);
                    let r_above = active[hi_b].reg.take();
                    for x in &mut active[lo_b..=hi_b] {
                        if let Some(r) = x.reg.take() {
                            t.close(r, v);
                        }
                    }
                    let r_below = r_below.map(|r| t.add(r, v, Side::Upper));
                    let r_above = r_above.map(|r| t.add(r, v, Side::Lower));
                    match top {
                        None => match (r_below, r_above) {
                            (Some(b), Some(a)) => active[below.unwrap_or(0)].reg = Some(t.merge(b, a)),
                            (Some(b), None) => active[below.unwrap_or(0)].reg = Some(b),
                            (None, Some(a)) => t.close(a, v),
                            (None, None) => {}
                        },
                        Some(k) => {
                            if let Some(b) = r_below {
                                active[below.unwrap_or(0)].reg = Some(b);
                            }
                            start_regions(outs, k, rule, &mut t, v);
                            outs[k].reg = match r_above {
                                Some(a) => Some(a),
                                None if rule.inside(outs[k].w) => Some(t.start(v)),
                                None => None,
                            };
                        }
                    }
                }
            }
        }
        replace_run(active, lo, hi + 1, outs);
    }
    // Regions left open by floating-point inconsistencies: back to the pool.
    for x in active.drain(..) {
        if let Some(r) = x.reg {
            t.discard(r);
        }
    }
}

/// An active edge: the edge, the winding number above it, whether it is on
/// the boundary, and (if so, and the region is above it) the region
/// between it and the next boundary entry above.
struct Active {
    e: u32,
    /// The edge's right end (`edges[e].hi`), kept here: the scans for the
    /// entries ending at a vertex read only this (no lookup per entry).
    hi: u32,
    w: i64,
    b: bool,
    reg: Option<Reg>,
}

/// Sets the windings of the edges leaving a vertex (`outs`, bottom to top,
/// the face below them winding `w0`) and their boundary flags, and pushes
/// the boundary ones. Returns the top boundary one's index, if any.
#[inline]
fn start_outs(outs: &mut [Active], w0: i64, edges: &[Edge], rule: Rule, boundary: &mut Vec<(usize, usize)>) -> Option<usize> {
    let mut w = w0;
    let mut inside = rule.inside(w);
    let mut top = None;
    for (j, x) in outs.iter_mut().enumerate() {
        let e = edges[x.e as usize];
        w += e.w;
        x.w = w;
        let above = rule.inside(w);
        if above != inside {
            x.b = true;
            top = Some(j);
            boundary.push(if above { (e.lo, e.hi) } else { (e.hi, e.lo) });
        }
        inside = above;
    }
    top
}

/// Starts a region at v above each boundary edge below `outs[k]` (the top
/// boundary one) with the region above it.
#[inline]
fn start_regions(outs: &mut [Active], k: usize, rule: Rule, t: &mut Tri, v: usize) {
    for x in &mut outs[..k] {
        if x.b && rule.inside(x.w) {
            x.reg = Some(t.start(v));
        }
    }
}

/// Puts `outs` in place of `active[lo..hi]`: overwrites what both have,
/// then inserts the rest (usually one or two) or removes the surplus; the
/// same list as a drain and inserts, with less memmove.
fn replace_run<T>(active: &mut Vec<T>, lo: usize, hi: usize, outs: &mut Vec<T>) {
    let mut i = lo;
    for x in outs.drain(..) {
        if i < hi {
            active[i] = x;
        } else {
            active.insert(i, x);
        }
        i += 1;
    }
    if i < hi {
        active.drain(i..hi);
    }
}

/// Moves `outs` into `active` at `pos` (usually one or two: inserts one by
/// one, cheaper than a splice).
fn insert_all<T>(active: &mut Vec<T>, pos: usize, outs: &mut Vec<T>) {
    for (k, x) in outs.drain(..).enumerate() {
        active.insert(pos + k, x);
    }
}

#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(super) enum Side {
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
pub(super) struct Reg {
    subs: Vec<Chain>,
}

/// Spare chain and region vectors, so that regions starting and ending
/// do not allocate (kept across polygons).
#[derive(Default)]
pub(super) struct Pool {
    chains: Vec<Vec<usize>>,
    subs: Vec<Vec<Chain>>,
}

pub(super) struct Tri<'a> {
    pub(super) verts: &'a [Vert],
    pub(super) out: &'a mut Vec<[usize; 3]>,
    pub(super) pool: &'a mut Pool,
}

impl Tri<'_> {
    fn chain(&mut self, vs: &[usize], side: Side) -> Chain {
        // (New vectors start with room for a typical chain: a fresh
        // tessellator's first polygons would otherwise regrow each one.)
        let mut verts = self.pool.chains.pop().unwrap_or_else(|| Vec::with_capacity(16));
        verts.extend_from_slice(vs);
        Chain { verts, side }
    }

    fn reg(&mut self, ch: Chain) -> Reg {
        let mut subs = self.pool.subs.pop().unwrap_or_else(|| Vec::with_capacity(4));
        subs.push(ch);
        Reg { subs }
    }

    /// A region starting at v.
    pub(super) fn start(&mut self, v: usize) -> Reg {
        let ch = self.chain(&[v], Side::Both);
        self.reg(ch)
    }

    fn recycle_chain(&mut self, mut ch: Chain) {
        ch.verts.clear();
        self.pool.chains.push(ch.verts);
    }

    fn recycle_subs(&mut self, mut subs: Vec<Chain>) {
        for ch in subs.drain(..) {
            self.recycle_chain(ch);
        }
        self.pool.subs.push(subs);
    }

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

    /// v arrives on side `s` of the chain: the triangles it closes, and
    /// the chain updated in place (no move of the chain's vector).
    fn step(&mut self, ch: &mut Chain, v: usize, s: Side) {
        if ch.side == Side::Both || ch.verts.len() < 2 {
            ch.verts.push(v);
            ch.side = s;
            return;
        }
        if ch.side != s {
            self.fan(ch, v);
            let last = *ch.verts.last().unwrap();
            ch.verts.clear();
            ch.verts.extend([last, v]);
            ch.side = s;
            return;
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
    }

    /// v arrives on one side of the region.
    pub(super) fn add(&mut self, mut r: Reg, v: usize, s: Side) -> Reg {
        self.add_mut(&mut r, v, s);
        r
    }

    /// [`Tri::add`] on a region left in place.
    #[inline]
    pub(super) fn add_mut(&mut self, r: &mut Reg, v: usize, s: Side) {
        if let [ch] = &mut r.subs[..] {
            self.step(ch, v, s);
            return;
        }
        self.add_merged(r, v, s);
    }

    /// [`Tri::add`] on a region with merge vertices waiting (or none).
    fn add_merged(&mut self, r: &mut Reg, v: usize, s: Side) {
        if r.subs.len() > 1 {
            // Merge vertices waiting in the region: the others end at v.
            let keep = if s == Side::Lower { r.subs.len() - 1 } else { 0 };
            let kept = r.subs.swap_remove(keep);
            for ch in &r.subs {
                self.fan(ch, v);
            }
            for ch in r.subs.drain(..) {
                self.recycle_chain(ch);
            }
            r.subs.push(kept);
        }
        if let Some(ch) = r.subs.last_mut() {
            self.step(ch, v, s);
        }
    }

    /// Two regions become one at a merge vertex (`b` below `a`).
    pub(super) fn merge(&mut self, mut b: Reg, mut a: Reg) -> Reg {
        b.subs.append(&mut a.subs);
        self.recycle_subs(a.subs);
        b
    }

    /// Drops a region without output (its vectors go back to the pool).
    pub(super) fn discard(&mut self, r: Reg) {
        self.recycle_subs(r.subs);
    }

    /// v ends the region.
    pub(super) fn close(&mut self, r: Reg, v: usize) {
        for ch in &r.subs {
            self.fan(ch, v);
        }
        self.recycle_subs(r.subs);
    }

    /// v starts a hole inside the region: returns the parts below and above.
    pub(super) fn split(&mut self, r: Reg, v: usize) -> (Reg, Reg) {
        let mut subs = r.subs;
        if subs.len() > 1 {
            let top = subs.pop().unwrap_or_else(|| Chain { verts: Vec::new(), side: Side::Both });
            let bottom = subs.remove(0);
            for ch in &subs {
                self.fan(ch, v);
            }
            self.recycle_subs(subs);
            let (mut lower, mut upper) = (bottom, top);
            self.step(&mut lower, v, Side::Upper);
            self.step(&mut upper, v, Side::Lower);
            return (self.reg(lower), self.reg(upper));
        }
        let Some(ch) = subs.pop() else { return (self.start(v), self.start(v)) };
        self.recycle_subs(subs);
        let h = ch.verts.last().copied().unwrap_or(v);
        let mut ch = ch;
        if ch.side == Side::Upper {
            self.step(&mut ch, v, Side::Upper);
            let other = self.chain(&[h, v], Side::Lower);
            (self.reg(ch), self.reg(other))
        } else {
            self.step(&mut ch, v, Side::Lower);
            let other = self.chain(&[h, v], Side::Upper);
            (self.reg(other), self.reg(ch))
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// `replace_run` leaves the list a drain of `lo..hi` followed by
    /// inserting `outs` at `lo` would, for every run and replacement length.
    #[test]
    fn replace_run_is_drain_then_insert() {
        for len in 0..7usize {
            for lo in 0..=len {
                for hi in lo..=len {
                    for m in 0..5usize {
                        let base: Vec<u32> = (0..len as u32).collect();
                        let outs: Vec<u32> = (0..m as u32).map(|k| 100 + k).collect();
                        let mut want = base.clone();
                        want.drain(lo..hi);
                        for (k, &x) in outs.iter().enumerate() {
                            want.insert(lo + k, x);
                        }
                        let (mut got, mut o) = (base.clone(), outs.clone());
                        replace_run(&mut got, lo, hi, &mut o);
                        assert_eq!(got, want, "len {len}, {lo}..{hi}, {m} new");
                        assert!(o.is_empty());
                    }
                }
            }
        }
    }
}
