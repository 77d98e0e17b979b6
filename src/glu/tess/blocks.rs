//! A list with O(sqrt n) insert and remove at any position: runs of at most
//! CAP elements kept in order. The sweeps' active edge lists need
//! positional insert and remove next to a binary-searched position; a flat
//! vector makes that a memmove of the whole list (quadratic when tens of
//! thousands of edges are active at once), and a balanced tree costs
//! pointer chasing that small polygons (one run) would pay for nothing.
//!
//! Invariant: no run is empty; an empty list has no runs. Spare run
//! vectors are kept for reuse, so the list does not allocate in steady
//! state.
//!
//! [`Active`] is the interface the fast path's sweep uses, implemented by
//! [`BlockList`] and by a plain `Vec` (for polygons of at most [`CAP`]
//! vertices, where the block list is a single run anyway: the same
//! positions and the same binary search, without finding the run).

/// The longest run; a list never longer than this is one run.
pub const CAP: usize = 256;

/// A sequence with positional insert and remove and a binary search.
/// (No `is_empty`: the sweep asks only positions against `len`.)
#[allow(clippy::len_without_is_empty)]
pub trait Active<T> {
    fn len(&self) -> usize;
    fn get(&self, i: usize) -> &T;
    fn get_mut(&mut self, i: usize) -> &mut T;
    fn insert(&mut self, i: usize, x: T);
    fn remove(&mut self, i: usize) -> T;
    /// As `slice::partition_point`.
    fn partition_point(&self, pred: impl FnMut(&T) -> bool) -> usize;
    /// Empties the list, handing each element to `f`.
    fn clear_with(&mut self, f: impl FnMut(T));
}

impl<T> Active<T> for Vec<T> {
    #[inline]
    fn len(&self) -> usize {
        Vec::len(self)
    }
    #[inline]
    fn get(&self, i: usize) -> &T {
        &self[i]
    }
    #[inline]
    fn get_mut(&mut self, i: usize) -> &mut T {
        &mut self[i]
    }
    #[inline]
    fn insert(&mut self, i: usize, x: T) {
        Vec::insert(self, i, x)
    }
    #[inline]
    fn remove(&mut self, i: usize) -> T {
        Vec::remove(self, i)
    }
    #[inline]
    fn partition_point(&self, pred: impl FnMut(&T) -> bool) -> usize {
        self[..].partition_point(pred)
    }
    #[inline]
    fn clear_with(&mut self, f: impl FnMut(T)) {
        self.drain(..).for_each(f)
    }
}

impl<T> Active<T> for BlockList<T> {
    #[inline]
    fn len(&self) -> usize {
        BlockList::len(self)
    }
    #[inline]
    fn get(&self, i: usize) -> &T {
        BlockList::get(self, i)
    }
    #[inline]
    fn get_mut(&mut self, i: usize) -> &mut T {
        BlockList::get_mut(self, i)
    }
    #[inline]
    fn insert(&mut self, i: usize, x: T) {
        BlockList::insert(self, i, x)
    }
    #[inline]
    fn remove(&mut self, i: usize) -> T {
        BlockList::remove(self, i)
    }
    #[inline]
    fn partition_point(&self, pred: impl FnMut(&T) -> bool) -> usize {
        BlockList::partition_point(self, pred)
    }
    #[inline]
    fn clear_with(&mut self, f: impl FnMut(T)) {
        BlockList::clear_with(self, f)
    }
}

pub struct BlockList<T> {
    runs: Vec<Vec<T>>,
    spare: Vec<Vec<T>>,
    len: usize,
}

impl<T> Default for BlockList<T> {
    fn default() -> Self {
        BlockList { runs: Vec::new(), spare: Vec::new(), len: 0 }
    }
}

impl<T> BlockList<T> {
    #[inline]
    pub fn len(&self) -> usize {
        self.len
    }

    #[inline]
    pub fn is_empty(&self) -> bool {
        self.len == 0
    }

    /// (run, offset) of index i < len; or of i == len (the end of the last run).
    #[inline]
    fn find(&self, mut i: usize) -> (usize, usize) {
        for (r, run) in self.runs.iter().enumerate() {
            if i < run.len() {
                return (r, i);
            }
            i -= run.len();
        }
        let last = self.runs.len().saturating_sub(1);
        (last, self.runs[..].get(last).map_or(0, |r| r.len()))
    }

    #[inline]
    pub fn get(&self, i: usize) -> &T {
        let (r, k) = self.find(i);
        &self.runs[r][k]
    }

    #[inline]
    pub fn get_mut(&mut self, i: usize) -> &mut T {
        let (r, k) = self.find(i);
        &mut self.runs[r][k]
    }

    pub fn insert(&mut self, i: usize, x: T) {
        if self.runs.is_empty() {
            let mut run = self.spare.pop().unwrap_or_default();
            run.push(x);
            self.runs.push(run);
            self.len = 1;
            return;
        }
        let (r, k) = self.find(i.min(self.len));
        self.runs[r].insert(k, x);
        self.len += 1;
        if self.runs[r].len() > CAP {
            // Split the run in two halves.
            let mut upper = self.spare.pop().unwrap_or_default();
            let half = self.runs[r].len() / 2;
            upper.extend(self.runs[r].drain(half..));
            self.runs.insert(r + 1, upper);
        }
    }

    pub fn remove(&mut self, i: usize) -> T {
        let (r, k) = self.find(i);
        let x = self.runs[r].remove(k);
        self.len -= 1;
        if self.runs[r].is_empty() {
            let run = self.runs.remove(r);
            self.spare.push(run);
        }
        x
    }

    /// The index of the first element for which `pred` is false, `pred`
    /// being true on a prefix of the list (as `slice::partition_point`).
    #[inline]
    pub fn partition_point(&self, mut pred: impl FnMut(&T) -> bool) -> usize {
        // One run (small polygons): the slice's search alone.
        if let [run] = &self.runs[..] {
            return run.partition_point(pred);
        }
        // The first run whose last element fails, by binary search over runs.
        let r = self.runs.partition_point(|run| run.last().is_some_and(&mut pred));
        let before: usize = self.runs[..r].iter().map(|run| run.len()).sum();
        match self.runs[..].get(r) {
            Some(run) => before + run.partition_point(pred),
            None => before,
        }
    }

    /// Visits every element in order.
    pub fn for_each_mut(&mut self, mut f: impl FnMut(&mut T)) {
        for run in &mut self.runs {
            run.iter_mut().for_each(&mut f);
        }
    }

    /// Empties the list, handing each element to `f`.
    pub fn clear_with(&mut self, mut f: impl FnMut(T)) {
        for mut run in self.runs.drain(..) {
            for x in run.drain(..) {
                f(x);
            }
            self.spare.push(run);
        }
        self.len = 0;
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Random inserts, removes and searches against a Vec.
    #[test]
    fn matches_vec() {
        let mut l = BlockList::default();
        let mut v: Vec<u32> = Vec::new();
        let mut s = 0x9e37_79b9_7f4a_7c15u64;
        let mut rnd = |m: usize| {
            s ^= s << 13;
            s ^= s >> 7;
            s ^= s << 17;
            (s % m as u64) as usize
        };
        for step in 0..20000 {
            if v.is_empty() || rnd(3) > 0 || step < 3000 {
                // Sorted inserts, so partition_point has a prefix to find.
                let x = rnd(1 << 20) as u32;
                let i = v.partition_point(|&y| y < x);
                assert_eq!(l.partition_point(|&y: &u32| y < x), i);
                v.insert(i, x);
                l.insert(i, x);
            } else {
                let i = rnd(v.len());
                assert_eq!(l.remove(i), v.remove(i));
            }
            assert_eq!(l.len(), v.len());
            if step % 97 == 0 {
                for (i, x) in v.iter().enumerate() {
                    assert_eq!(l.get(i), x);
                }
            }
        }
        let mut out = Vec::new();
        l.clear_with(|x| out.push(x));
        assert_eq!(out, v);
        assert!(l.is_empty());
    }
}
