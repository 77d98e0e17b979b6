//! Merging near-coincident vertices: a hash grid of cells 4·EPS wide that
//! finds an existing vertex within EPS (max norm) of a point.
//!
//! Chained buckets over vertex ids (`head` per bucket, `next` per vertex)
//! with a multiplicative hash of the cell; no per-cell allocation, and the
//! arrays are kept from one polygon to the next. A point within EPS of
//! another lies in at most 2×2 cells, so a lookup probes one to four buckets.

use super::sweep::{Vert, EPS};

const CELL: f64 = 4.0 * EPS;
const NONE: u32 = u32::MAX;

#[derive(Default)]
pub struct Grid {
    head: Vec<u32>,
    next: Vec<u32>,
    shift: u32,
    /// Vertices inserted while the grid is small enough to scan them all
    /// (then no buckets are kept).
    linear: usize,
    hashed: bool,
}

/// Up to this many vertices, lookups scan them all (cheaper than hashing).
const LINEAR: usize = 24;

/// The cell of coordinate x: x / CELL rounded to the nearest integer (any
/// monotone quantization into cells at least 2 EPS wide serves: a point
/// within EPS of p then lies in one of the at most two cells of p ± EPS).
/// By the 1.5·2^52 trick: adding it rounds to an integer, which the low
/// bits then hold, with no float-to-integer conversion (cheaper than a
/// floor). Clamped to ±2^50 first, where the trick holds (coordinates are
/// normalised to within ±1; huge values and NaN share an end cell, harmless).
#[inline]
#[allow(clippy::manual_clamp)] // (`clamp` would keep NaN.)
fn cell(x: f64) -> i64 {
    const LIM: f64 = (1u64 << 50) as f64;
    const ROUND: f64 = 1.5 * (1u64 << 52) as f64;
    let c = (x * (1.0 / CELL)).max(-LIM).min(LIM);
    (c + ROUND).to_bits() as i64
}

impl Grid {
    /// Empties the grid, sized for about `n` vertices.
    pub fn reset(&mut self, n: usize) {
        self.linear = 0;
        self.hashed = false;
        if n <= LINEAR {
            return;
        }
        self.hashed = true;
        let size = (2 * n).max(16).next_power_of_two();
        self.head.clear();
        self.head.resize(size, NONE);
        // (`next` keeps its length and old entries: an entry is written
        // when its vertex goes in, before any chain reaches it.)
        self.shift = 64 - size.trailing_zeros();
    }

    #[inline]
    fn bucket(&self, kx: i64, ky: i64) -> usize {
        let h = (kx as u64).wrapping_mul(0x9e37_79b9_7f4a_7c15) ^ (ky as u64).wrapping_mul(0xc2b2_ae3d_27d4_eb4f);
        (h.wrapping_mul(0x94d0_49bb_1331_11eb) >> self.shift) as usize
    }

    /// The closest vertex within EPS of `p` (the lowest id among equals).
    #[inline]
    pub fn find(&self, verts: &[Vert], p: [f64; 2]) -> Option<usize> {
        if !self.hashed {
            let mut best: Option<(f64, usize)> = None;
            for (i, q) in verts[..self.linear.min(verts.len())].iter().enumerate() {
                // (Plain comparisons first: coordinates are finite here,
                // and most vertices are far in x or y.)
                let (dx, dy) = ((q.p[0] - p[0]).abs(), (q.p[1] - p[1]).abs());
                if dx <= EPS && dy <= EPS {
                    let d = if dx < dy { dy } else { dx };
                    if best.is_none_or(|(bd, _)| d < bd) {
                        best = Some((d, i));
                    }
                }
            }
            return best.map(|b| b.1);
        }
        let (x0, x1) = (cell(p[0] - EPS), cell(p[0] + EPS));
        let (y0, y1) = (cell(p[1] - EPS), cell(p[1] + EPS));
        // (Half-open ranges of one or two cells: cheaper loops than `..=`.)
        let (x1, y1) = (x0 + 1 + (x1 > x0) as i64, y0 + 1 + (y1 > y0) as i64);
        let mut best: Option<(f64, usize)> = None;
        for kx in x0..x1 {
            for ky in y0..y1 {
                let mut i = self.head[self.bucket(kx, ky)];
                while i != NONE {
                    let q = verts[i as usize].p;
                    let (dx, dy) = ((q[0] - p[0]).abs(), (q[1] - p[1]).abs());
                    // The same vertex can be met twice (two probed cells in one bucket): harmless.
                    if dx <= EPS && dy <= EPS {
                        let d = if dx < dy { dy } else { dx };
                        if best.is_none_or(|(bd, bi)| d < bd || (d == bd && (i as usize) < bi)) {
                            best = Some((d, i as usize));
                        }
                    }
                    i = self.next[i as usize];
                }
            }
        }
        best.map(|b| b.1)
    }

    /// Makes room for about `total` vertices in all (the `n` first of
    /// `verts` already in), so that the inserts that follow do not rehash
    /// as the table grows. Lookups give the same answers either way. A grid
    /// still scanned linearly stays so (small polygons: cheaper).
    pub fn reserve(&mut self, verts: &[Vert], n: usize, total: usize) {
        if !self.hashed || 2 * total <= self.head.len() {
            return;
        }
        self.hashed = true;
        let size = (2 * total).next_power_of_two();
        self.head.clear();
        self.head.resize(size, NONE);
        self.shift = 64 - size.trailing_zeros();
        if self.next.len() < n {
            self.next.resize(n, NONE);
        }
        for j in 0..n {
            self.link(verts, j);
        }
    }

    /// Adds every vertex of `verts`, in order, to a grid just [`reset`](Self::reset)
    /// for that many: what inserting them one by one does, without the calls
    /// while the grid is still scanned linearly.
    pub fn insert_all(&mut self, verts: &[Vert]) {
        let n = verts.len();
        if !self.hashed && self.linear == 0 && n <= LINEAR {
            self.linear = n;
            return;
        }
        for i in 0..n {
            self.insert(verts, i);
        }
    }

    /// Adds vertex `i`; every vertex below `i` must be in the grid already
    /// (the tessellator inserts each vertex it creates, in order).
    #[inline]
    pub fn insert(&mut self, verts: &[Vert], i: usize) {
        if !self.hashed {
            if i < LINEAR {
                self.linear = i + 1;
                return;
            }
            // Outgrown: switch to buckets (rehashing below).
            self.hashed = true;
            self.head.clear();
        }
        if self.next.len() <= i {
            // (Doubled, not one at a time: each insert adds one. Entries of
            // vertices not yet in are never read.)
            let len = (i + 1).max(2 * self.next.len());
            self.next.resize(len, NONE);
        }
        if 2 * (i + 1) > self.head.len() {
            // Grow and rehash.
            let size = (4 * (i + 1)).next_power_of_two();
            self.head.clear();
            self.head.resize(size, NONE);
            self.shift = 64 - size.trailing_zeros();
            for j in 0..i {
                self.link(verts, j);
            }
        }
        self.link(verts, i);
    }

    fn link(&mut self, verts: &[Vert], i: usize) {
        let p = verts[i].p;
        let b = self.bucket(cell(p[0]), cell(p[1]));
        self.next[i] = self.head[b];
        self.head[b] = i as u32;
    }
}
