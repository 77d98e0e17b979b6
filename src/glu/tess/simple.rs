//! The fast path for polygons whose contours are already a planar
//! arrangement: no two vertices within EPS, no edge crossing or touching
//! another, every contour at least a triangle. That is most real input
//! (outlines, glyphs, polygons with holes), and for it the general path's
//! merging, splitting and winding sweep find nothing to do.
//!
//! One sweep does everything: it checks the preconditions as it goes
//! (Shamos and Hoey: if two edges cross, two crossing edges are adjacent in
//! the active list at some event before the leftmost crossing, so testing
//! every pair that becomes adjacent finds one; the test is conservative,
//! "within EPS" counts as touching), computes each edge's winding from the
//! edge below it, and triangulates with [`sweep`]'s monotone chains. It
//! gives up ([`Outcome::No`], having output nothing) at the first sign of
//! anything the general path handles: near-coincident vertices, edges
//! that cross, touch or overlap, or a vertex where the active list is not
//! as a planar arrangement would have it (floating-point doubt).
//!
//! The triangulation works on faces, not on the selected region: every
//! face between two active edges whose winding the rule selects is a
//! region of its own, so an edge with the selected region on both sides
//! (same-direction nested contours under NONZERO) separates two regions
//! and becomes a triangle edge (unflagged: it is not on the boundary), and
//! an edge with the region on neither side (an empty selection) only takes
//! part in the planarity check. Only edges whose two sides differ go into
//! the boundary.
//!
//! Edge e is the contour edge from vertex e to its successor; vertex ids
//! are input indices (nothing is merged). The active list is a
//! [`BlockList`], so polygons with tens of thousands of edges active at
//! once stay O(n sqrt n) in the worst case; polygons of at most
//! [`blocks::CAP`] vertices use a plain vector instead (the block list
//! would be one run: the same positions and binary searches, so the same
//! output, without the run bookkeeping that small polygons pay per step).

use super::blocks::{self, Active, BlockList};
use super::sweep::{orient, Pool, Reg, Region, Rule, Side, Tri, Vert, EPS};

/// What the fast path did with a polygon.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(super) enum Outcome {
    /// Tessellated: `region` holds the result.
    Done,
    /// Anything else: the general path's business.
    No,
}

/// An active edge: its ends in sweep order, the winding number above it,
/// and the region above it (if that region is selected).
struct Entry {
    lo: u32,
    hi: u32,
    w: i32,
    reg: Option<Reg>,
}


/// Buffers kept from one polygon to the next.
#[derive(Default)]
pub struct Scratch {
    /// The vertices in sweep order: (x key, y key, index); empty if the
    /// polygon was refused before they were sorted.
    pub(super) keyed: Vec<(u64, u64, u32)>,
    /// No two vertices within EPS (max norm) of each other: the check
    /// below passed, so the general path has nothing to merge.
    pub(super) distinct: bool,
    rank: Vec<u32>,
    next: Vec<u32>,
    prev: Vec<u32>,
    active: BlockList<Entry>,
    small: Vec<Entry>,
}

impl Scratch {
    /// Room for about `n` of everything, made once when the tessellator
    /// gets its buffers: its first polygons then do not regrow each vector
    /// step by step (a fixed cost that shows on small polygons).
    pub(super) fn reserve(&mut self, n: usize) {
        self.keyed.reserve(n);
        self.rank.reserve(n);
        self.next.reserve(n);
        self.prev.reserve(n);
    }
}

use super::sweep::ord_key;

/// Does p lie within EPS of the open segment a-b? (As the splitter tests.)
#[inline]
fn lies_on(p: [f64; 2], a: [f64; 2], b: [f64; 2]) -> bool {
    let (dx, dy) = (b[0] - a[0], b[1] - a[1]);
    let l2 = dx * dx + dy * dy;
    let dot = (p[0] - a[0]) * dx + (p[1] - a[1]) * dy;
    if !(dot > 0.0 && dot < l2) {
        return false;
    }
    let o = orient(a, b, p);
    o * o <= EPS * EPS * l2
}

/// Do edges (a, b) and (c, d) (vertex ids) cross, touch or come within
/// EPS, other than at a shared endpoint?
/// (Inlined: the boxes' test is the common answer; coordinates are finite
/// here, so plain comparisons give what `f64::max`/`min` would.)
#[inline(always)]
fn interact(v: &[Vert], a: u32, b: u32, c: u32, d: u32) -> bool {
    let (pa, pb, pc, pd) = (v[a as usize].p, v[b as usize].p, v[c as usize].p, v[d as usize].p);
    let span = |x: f64, y: f64| if x < y { (x, y) } else { (y, x) };
    let ((ax0, ax1), (ay0, ay1)) = (span(pa[0], pb[0]), span(pa[1], pb[1]));
    let ((cx0, cx1), (cy0, cy1)) = (span(pc[0], pd[0]), span(pc[1], pd[1]));
    // Boxes apart by more than EPS: nothing to test (the common case).
    if ax1 + EPS < cx0 || cx1 + EPS < ax0 || ay1 + EPS < cy0 || cy1 + EPS < ay0 {
        return false;
    }
    interact_near(pa, pb, pc, pd, a, b, c, d)
}

/// [`interact`] for edges whose boxes come within EPS.
#[inline(never)]
#[allow(clippy::too_many_arguments)]
fn interact_near(pa: [f64; 2], pb: [f64; 2], pc: [f64; 2], pd: [f64; 2], a: u32, b: u32, c: u32, d: u32) -> bool {
    if (c != a && c != b && lies_on(pc, pa, pb))
        || (d != a && d != b && lies_on(pd, pa, pb))
        || (a != c && a != d && lies_on(pa, pc, pd))
        || (b != c && b != d && lies_on(pb, pc, pd))
    {
        return true;
    }
    if a == c || a == d || b == c || b == d {
        return false;
    }
    let (d1, d2, d3, d4) = (orient(pc, pd, pa), orient(pc, pd, pb), orient(pa, pb, pc), orient(pa, pb, pd));
    // Touching with a zero orientation is within EPS, found above; only
    // strict sign changes are left.
    ((d1 > 0.0 && d2 < 0.0) || (d1 < 0.0 && d2 > 0.0)) && ((d3 > 0.0 && d4 < 0.0) || (d3 < 0.0 && d4 > 0.0))
}

/// Up to this many vertices, [`sort_small`] orders them.
const SMALL_SORT: usize = 32;

/// Sorts keys made in index order as `sort_unstable` would: an insertion
/// sort on (x, y) as one 128-bit key (cheaper comparisons than the
/// tuple's), stable, so equal positions stay in index order, the tuple's
/// tie-break.
fn sort_small(k: &mut [(u64, u64, u32)]) {
    let key = |e: &(u64, u64, u32)| (e.0 as u128) << 64 | e.1 as u128;
    for i in 1..k.len() {
        let e = k[i];
        let ke = key(&e);
        let mut j = i;
        while j > 0 && key(&k[j - 1]) > ke {
            k[j] = k[j - 1];
            j -= 1;
        }
        k[j] = e;
    }
}

/// Tessellates contours `starts` (first indices; the last runs to the end)
/// of `verts` into `region` (the boundary if `edges` or `boundary_only`,
/// triangles unless `boundary_only`); see [`Outcome`]. (Triangles without
/// edge flags need no boundary: not collecting it saves a push per edge.)
#[allow(clippy::too_many_arguments)]
pub(super) fn tessellate(verts: &[Vert], starts: &[usize], rule: Rule, boundary_only: bool, edges: bool, sc: &mut Scratch, pool: &mut Pool, region: &mut Region) -> Outcome {
    tessellate_with(verts, starts, rule, boundary_only, edges || boundary_only, sc, pool, region, verts.len() <= blocks::CAP)
}

/// [`tessellate`] with the active list chosen: `small` a vector (for at
/// most [`blocks::CAP`] vertices, or the output may differ), else the
/// block list. (Tests compare the two.)
#[allow(clippy::too_many_arguments)]
fn tessellate_with(verts: &[Vert], starts: &[usize], rule: Rule, boundary_only: bool, edges: bool, sc: &mut Scratch, pool: &mut Pool, region: &mut Region, small: bool) -> Outcome {
    let n = verts.len();
    region.boundary.clear();
    region.triangles.clear();
    sc.keyed.clear();
    sc.distinct = false;
    if n < 3 || n >= u32::MAX as usize / 2 {
        return Outcome::No;
    }
    // Successors and predecessors along the contours.
    sc.next.clear();
    sc.prev.clear();
    sc.next.resize(n, 0);
    sc.prev.resize(n, 0);
    for (k, &s) in starts.iter().enumerate() {
        let e = starts.get(k + 1).copied().unwrap_or(n);
        if e == s {
            continue; // empty contours add nothing
        }
        if e < s + 3 {
            return Outcome::No;
        }
        for i in s..e {
            let j = if i + 1 < e { i + 1 } else { s };
            sc.next[i] = j as u32;
            sc.prev[j] = i as u32;
        }
    }
    // Sweep order; near-coincident vertices are adjacent in it up to the
    // few within EPS in x, which the window below visits.
    sc.keyed.clear();
    sc.keyed.extend(verts.iter().enumerate().map(|(i, v)| (ord_key(v.p[0]), ord_key(v.p[1]), i as u32)));
    if n <= SMALL_SORT {
        sort_small(&mut sc.keyed);
    } else {
        sc.keyed.sort_unstable();
    }
    sc.rank.clear();
    sc.rank.resize(n, 0);
    for (r, k) in sc.keyed.iter().enumerate() {
        sc.rank[k.2 as usize] = r as u32;
    }
    for (r, k) in sc.keyed.iter().enumerate() {
        let p = verts[k.2 as usize].p;
        for q in &sc.keyed[r + 1..] {
            let q = verts[q.2 as usize].p;
            // (Past EPS in x, or NaN: the window ends.)
            if !matches!((q[0] - p[0]).partial_cmp(&EPS), Some(std::cmp::Ordering::Less | std::cmp::Ordering::Equal)) {
                break;
            }
            if (q[1] - p[1]).abs() <= EPS {
                return Outcome::No;
            }
        }
    }
    sc.distinct = true;
    let Scratch { keyed, rank, next, prev, active, small: vec, .. } = sc;
    let mut t = Tri { verts, out: &mut region.triangles, pool };
    let boundary = edges.then_some(&mut region.boundary);
    let input = Input { verts, keyed, rank, next, prev, rule, boundary_only };
    if small {
        run(&input, vec, &mut t, boundary)
    } else {
        run(&input, active, &mut t, boundary)
    }
}

/// What the sweep reads and never changes: the vertices, their sweep order
/// (`keyed`) and rank in it, the contours' successors and predecessors,
/// the winding rule and whether only the boundary is wanted.
#[derive(Clone, Copy)]
struct Input<'a> {
    verts: &'a [Vert],
    keyed: &'a [(u64, u64, u32)],
    rank: &'a [u32],
    next: &'a [u32],
    prev: &'a [u32],
    rule: Rule,
    boundary_only: bool,
}

/// The sweep on an emptied active list, emptied again afterwards.
#[inline(always)]
fn run(input: &Input, active: &mut impl Active<Entry>, t: &mut Tri, mut boundary: Option<&mut Vec<(usize, usize)>>) -> Outcome {
    active.clear_with(drop);
    let out = sweep(input, active, t, &mut boundary);
    // Regions left behind after giving up: back to the pool.
    active.clear_with(|e| {
        if let Some(r) = e.reg {
            t.discard(r);
        }
    });
    out
}

/// The sweep proper: the vertices in order, the active list's edges and
/// regions, triangles and the boundary out; see [`Outcome`].
fn sweep(input: &Input, active: &mut impl Active<Entry>, t: &mut Tri, boundary: &mut Option<&mut Vec<(usize, usize)>>) -> Outcome {
    let Input { verts, keyed, rank, next, prev, rule, boundary_only } = *input;
    let at = |i: u32| verts[i as usize].p;
    // v is above (left of) the entry's edge.
    let above = |e: &Entry, pv: [f64; 2]| orient(at(e.lo), at(e.hi), pv);
    for k in keyed {
        let v = k.2;
        let pv = at(v);
        let (p, q) = (prev[v as usize], next[v as usize]);
        // Edge p→v and edge v→q; "out" when v is its left end.
        let a_out = rank[p as usize] > rank[v as usize];
        let b_out = rank[q as usize] > rank[v as usize];
        match (a_out, b_out) {
            (true, true) => {
                // Both edges start here: lower and upper by direction.
                let pos = active.partition_point(|e| above(e, pv) >= 0.0);
                let o = orient(pv, at(p), at(q));
                if o == 0.0 {
                    return Outcome::No;
                }
                // o > 0: q is left of v→p, so v→p is the lower edge.
                let (l, u) = if o > 0.0 { (p, q) } else { (q, p) };
                // Windings: +1 for an edge traversed from its left end.
                let dir = |far: u32| if far == q { 1 } else { -1 };
                let w0 = if pos > 0 { active.get(pos - 1).w } else { 0 };
                let (w1, w2) = (w0 + dir(l), w0 + dir(l) + dir(u));
                let (i0, i1, i2) = (rule.inside(w0 as i64), rule.inside(w1 as i64), rule.inside(w2 as i64));
                // The two new edges are adjacent too (nearly overlapping?).
                if interact(verts, v, l, v, u) {
                    return Outcome::No;
                }
                if pos > 0 {
                    let b = active.get(pos - 1);
                    if interact(verts, b.lo, b.hi, v, l) {
                        return Outcome::No;
                    }
                }
                if pos < active.len() {
                    let a = active.get(pos);
                    if interact(verts, a.lo, a.hi, v, u) {
                        return Outcome::No;
                    }
                }
                let (mut rl, mut ru) = (None, None);
                // (An edge with the same side both ways is no boundary.)
                if i0 != i1 {
                    push_boundary(boundary, v, l, i1);
                }
                if i1 != i2 {
                    push_boundary(boundary, v, u, i2);
                }
                if !boundary_only {
                    let r = if pos > 0 { active.get_mut(pos - 1).reg.take() } else { None };
                    if i1 {
                        rl = Some(t.start(v as usize));
                    }
                    match r {
                        Some(r) => {
                            let (lower, upper) = t.split(r, v as usize);
                            active.get_mut(pos - 1).reg = Some(lower);
                            ru = Some(upper);
                        }
                        None if i2 => ru = Some(t.start(v as usize)),
                        None => {}
                    }
                }
                active.insert(pos, Entry { lo: v, hi: u, w: w2, reg: ru });
                active.insert(pos, Entry { lo: v, hi: l, w: w1, reg: rl });
            }
            (false, false) => {
                // Both edges end here: they must be adjacent entries.
                let pos = active.partition_point(|e| above(e, pv) > 0.0);
                if pos + 1 >= active.len() || active.get(pos).hi != v || active.get(pos + 1).hi != v {
                    return Outcome::No;
                }
                let r_below = if pos > 0 { active.get_mut(pos - 1).reg.take() } else { None };
                let r_above = active.get_mut(pos + 1).reg.take();
                let inner = active.remove(pos).reg;
                active.remove(pos);
                if let Some(r) = inner {
                    t.close(r, v as usize);
                }
                let r_below = r_below.map(|r| t.add(r, v as usize, Side::Upper));
                let r_above = r_above.map(|r| t.add(r, v as usize, Side::Lower));
                match (r_below, r_above) {
                    (Some(b), Some(a)) => active.get_mut(pos - 1).reg = Some(t.merge(b, a)),
                    (Some(b), None) => active.get_mut(pos - 1).reg = Some(b),
                    (None, Some(a)) => t.close(a, v as usize),
                    (None, None) => {}
                }
                if pos > 0 && pos < active.len() {
                    let (b, a) = (active.get(pos - 1), active.get(pos));
                    if interact(verts, b.lo, b.hi, a.lo, a.hi) {
                        return Outcome::No;
                    }
                }
            }
            _ => {
                // One edge ends, the other continues to the right.
                let far = if a_out { p } else { q };
                let pos = active.partition_point(|e| above(e, pv) > 0.0);
                if pos >= active.len() || active.get(pos).hi != v || (pos + 1 < active.len() && active.get(pos + 1).hi == v) {
                    return Outcome::No;
                }
                let w0 = if pos > 0 { active.get(pos - 1).w } else { 0 };
                let w1 = w0 + if far == q { 1 } else { -1 };
                let i1 = rule.inside(w1 as i64);
                if pos > 0 {
                    let b = active.get(pos - 1);
                    if interact(verts, b.lo, b.hi, v, far) {
                        return Outcome::No;
                    }
                }
                if pos + 1 < active.len() {
                    let a = active.get(pos + 1);
                    if interact(verts, a.lo, a.hi, v, far) {
                        return Outcome::No;
                    }
                }
                if rule.inside(w0 as i64) != i1 {
                    push_boundary(boundary, v, far, i1);
                }
                if !boundary_only {
                    // (The regions stepped where they lie in the list.)
                    if pos > 0 {
                        if let Some(r) = &mut active.get_mut(pos - 1).reg {
                            t.add_mut(r, v as usize, Side::Upper);
                        }
                    }
                    let e = active.get_mut(pos);
                    match &mut e.reg {
                        Some(a) => t.add_mut(a, v as usize, Side::Lower),
                        None if i1 => e.reg = Some(t.start(v as usize)),
                        None => {}
                    }
                }
                // The entry becomes edge v→far, its region (if any) kept in
                // place (field writes: no drop of the old region to check).
                let e = active.get_mut(pos);
                (e.lo, e.hi, e.w) = (v, far, w1);
            }
        }
    }
    Outcome::Done
}

/// The boundary edge lo→hi (lo left of hi), directed with the region on its left.
#[inline]
fn push_boundary(boundary: &mut Option<&mut Vec<(usize, usize)>>, lo: u32, hi: u32, inside_above: bool) {
    if let Some(b) = boundary {
        b.push(if inside_above { (lo as usize, hi as usize) } else { (hi as usize, lo as usize) });
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn outcome(contours: &[&[[f64; 2]]], rule: Rule) -> (Outcome, Region) {
        let verts: Vec<Vert> = contours.iter().flat_map(|c| c.iter().map(|&p| Vert { p })).collect();
        let mut starts = Vec::new();
        let mut n = 0;
        for c in contours {
            starts.push(n);
            n += c.len();
        }
        let (mut sc, mut pool, mut region) = (Scratch::default(), Pool::default(), Region::default());
        (tessellate(&verts, &starts, rule, false, true, &mut sc, &mut pool, &mut region), region)
    }

    fn run(contours: &[&[[f64; 2]]], rule: Rule) -> Option<Region> {
        let (o, r) = outcome(contours, rule);
        (o == Outcome::Done).then_some(r)
    }

    fn area(r: &Region, v: &[[f64; 2]]) -> f64 {
        r.triangles.iter().map(|t| 0.5 * orient(v[t[0]], v[t[1]], v[t[2]])).sum()
    }

    #[test]
    fn takes_planar_input() {
        let sq = [[0.0, 0.0], [1.0, 0.0], [1.0, 1.0], [0.0, 1.0]];
        let hole = [[0.25, 0.25], [0.25, 0.75], [0.75, 0.75], [0.75, 0.25]];
        let r = run(&[&sq], Rule::Odd).expect("a square");
        assert_eq!(r.triangles.len(), 2);
        assert!((area(&r, &sq) - 1.0).abs() < 1e-15);
        let all: Vec<[f64; 2]> = sq.iter().chain(hole.iter()).copied().collect();
        for rule in [Rule::Odd, Rule::NonZero, Rule::Positive] {
            let r = run(&[&sq, &hole], rule).expect("a square with a hole");
            assert!((area(&r, &all) - 0.75).abs() < 1e-15);
            assert_eq!(r.boundary.len(), 8);
        }
        // Nested the same way round: NONZERO has an edge with the region
        // on both sides (a triangle edge, not a boundary edge).
        let inner: Vec<[f64; 2]> = hole.iter().rev().copied().collect();
        let both: Vec<[f64; 2]> = sq.iter().chain(inner.iter()).copied().collect();
        let r = run(&[&sq, &inner], Rule::NonZero).expect("nested squares");
        assert!((area(&r, &both) - 1.0).abs() < 1e-15);
        assert_eq!(r.boundary.len(), 4);
        let r = run(&[&sq, &inner], Rule::AbsGeqTwo).expect("nested squares");
        assert!((area(&r, &both) - 0.25).abs() < 1e-15);
        assert_eq!(r.boundary.len(), 4);
        let r = run(&[&sq, &inner], Rule::Odd).expect("nested squares");
        assert!((area(&r, &both) - 0.75).abs() < 1e-15);
        assert_eq!(r.boundary.len(), 8);
        // Nothing selected: nothing output, but done.
        let r = run(&[&sq, &inner], Rule::Negative).expect("nested squares");
        assert!(r.triangles.is_empty() && r.boundary.is_empty());
        // An edge off the boundary first, a crossing later: not planar.
        let far = [[3.0, 0.0], [4.0, 1.0], [4.0, 0.0], [3.0, 1.0]];
        assert_eq!(outcome(&[&sq, &inner, &far], Rule::NonZero).0, Outcome::No);
    }

    #[test]
    fn leaves_the_rest_to_the_general_path() {
        let cases: [&[[f64; 2]]; 6] = [
            // A bow tie (crossing edges).
            &[[0.0, 0.0], [1.0, 1.0], [1.0, 0.0], [0.0, 1.0]],
            // A vertex on another edge (pinch).
            &[[0.0, 0.0], [2.0, 0.0], [2.0, 2.0], [1.0, 0.0], [0.0, 2.0]],
            // A vertex within EPS of another edge.
            &[[0.0, 0.0], [2.0, 0.0], [2.0, 2.0], [1.0, 1e-14], [0.0, 2.0]],
            // Near-coincident vertices.
            &[[0.0, 0.0], [1.0, 0.0], [1.0, 1e-14], [1.0, 1.0], [0.0, 1.0]],
            // A spike folding back on its own edge.
            &[[0.0, 0.0], [2.0, 0.0], [1.0, 0.0], [1.0, 1.0]],
            // Two edges leaving a vertex nearly overlapping: the upper one
            // ends (both its vertex's edges come from the left) within EPS
            // of the lower one.
            &[[0.0, 0.0], [2.0, 0.0], [2.0, 1.0], [0.5, 1.0], [1.0, 1e-14]],
        ];
        for (i, c) in cases.iter().enumerate() {
            for rule in [Rule::Odd, Rule::Negative] {
                assert_eq!(outcome(&[c], rule).0, Outcome::No, "case {i}, {rule:?}");
            }
        }
        // Two triangles crossing each other (each simple).
        let a = [[0.0, 0.0], [2.0, 0.0], [1.0, 2.0]];
        let b = [[0.0, 1.0], [2.0, 1.0], [1.0, -1.0]];
        assert_eq!(outcome(&[&a, &b], Rule::Odd).0, Outcome::No);
        assert_eq!(outcome(&[&a, &b], Rule::AbsGeqTwo).0, Outcome::No);
    }

    /// The vector active list (polygons of at most `blocks::CAP` vertices)
    /// gives what the block list gives: outcome, triangles and boundary, on
    /// thousands of random polygons: star-shaped ones (done), with holes,
    /// random point lists (mostly crossing: given up), and some with
    /// duplicated or near-coincident vertices (given up before the sweep).
    #[test]
    fn vector_list_matches_block_list() {
        let mut rnd = crate::glu::tess::test_rng::unit_rng(0x853c_49e6_748f_ea9b);
        let (mut sc, mut pool) = (Scratch::default(), Pool::default());
        let (mut done, mut no) = (0, 0);
        for case in 0..6000 {
            let n = 3 + (rnd() * if case % 50 == 0 { 250.0 } else { 30.0 }) as usize;
            let mut contours: Vec<Vec<[f64; 2]>> = Vec::new();
            let kind = case % 4;
            let star = |rnd: &mut dyn FnMut() -> f64, n: usize, c: [f64; 2], r: f64, ccw: bool| {
                let mut a: Vec<f64> = (0..n).map(|_| rnd() * std::f64::consts::TAU).collect();
                a.sort_by(f64::total_cmp);
                if !ccw {
                    a.reverse();
                }
                a.iter().map(|&t| {
                    let rr = r * (0.3 + 0.7 * rnd());
                    [c[0] + rr * t.cos(), c[1] + rr * t.sin()]
                }).collect::<Vec<_>>()
            };
            match kind {
                0 => contours.push(star(&mut rnd, n, [0.0, 0.0], 1.0, true)),
                1 => {
                    let ccw = rnd() < 0.5;
                    contours.push(star(&mut rnd, n, [0.0, 0.0], 1.0, ccw));
                    for _ in 0..1 + (rnd() * 3.0) as usize {
                        let (c, m, ccw) = ([rnd() * 0.4 - 0.2, rnd() * 0.4 - 0.2], 3 + (rnd() * 6.0) as usize, rnd() < 0.5);
                        contours.push(star(&mut rnd, m, c, 0.1, ccw));
                    }
                }
                2 => contours.push((0..n).map(|_| [rnd() * 2.0 - 1.0, rnd() * 2.0 - 1.0]).collect()),
                _ => {
                    // On a coarse grid: shared coordinates, collinear and
                    // repeated vertices.
                    let mut c = star(&mut rnd, n, [0.0, 0.0], 1.0, true);
                    for p in &mut c {
                        *p = p.map(|x| (x * 4.0).round() / 4.0);
                    }
                    if rnd() < 0.3 {
                        let k = (rnd() * n as f64) as usize % n;
                        c[k][1] += 1e-14;
                    }
                    contours.push(c);
                }
            }
            let verts: Vec<Vert> = contours.iter().flat_map(|c| c.iter().map(|&p| Vert { p })).collect();
            if verts.len() > blocks::CAP {
                continue;
            }
            let mut starts = Vec::new();
            let mut m = 0;
            for c in &contours {
                starts.push(m);
                m += c.len();
            }
            let rule = [Rule::Odd, Rule::NonZero, Rule::Positive, Rule::Negative, Rule::AbsGeqTwo][case % 5];
            let bo = case % 7 == 0;
            let (mut ra, mut rb) = (Region::default(), Region::default());
            let a = tessellate_with(&verts, &starts, rule, bo, true, &mut sc, &mut pool, &mut ra, true);
            let b = tessellate_with(&verts, &starts, rule, bo, true, &mut sc, &mut pool, &mut rb, false);
            assert_eq!(a, b, "case {case}");
            assert_eq!(ra.triangles, rb.triangles, "case {case}");
            assert_eq!(ra.boundary, rb.boundary, "case {case}");
            if a == Outcome::Done {
                done += 1;
            } else {
                no += 1;
            }
        }
        // Both outcomes are exercised, often.
        assert!(done > 2000 && no > 1000, "done {done}, given up {no}");
    }

    /// `sort_small` gives `sort_unstable`'s order, ties in x and in (x, y)
    /// included (keys made in index order, as `tessellate` makes them).
    #[test]
    fn small_sort_matches_sort_unstable() {
        let mut next = crate::glu::tess::test_rng::xorshift(0x2545_f491_4f6c_dd1d);
        let mut rnd = move |m: u64| next() % m;
        for case in 0..20000 {
            let n = rnd(SMALL_SORT as u64 + 1) as usize;
            // Few distinct values: many ties.
            let m = if case % 2 == 0 { 4 } else { 1 << 40 };
            let mut k: Vec<(u64, u64, u32)> = (0..n as u32).map(|i| (rnd(m) << 20, rnd(m), i)).collect();
            let mut want = k.clone();
            want.sort_unstable();
            sort_small(&mut k);
            assert_eq!(k, want, "case {case}");
        }
    }
}
