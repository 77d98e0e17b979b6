//! Object names: the search for unused names behind glGenTextures (GL 1.5
//! section 3.8.12), glGenLists (5.4), glGenBuffers (2.9), glGenQueries
//! (4.1.6), glGenSamplers (ARB_sampler_objects) and glGenFramebuffers /
//! glGenRenderbuffers (ARB_framebuffer_object), and the set of names
//! generated but not yet bound.
//!
//! Each kind of object keeps a cursor, and a search starts there, wrapping
//! past the largest name to 1 (0 is never a name), instead of at 1: a
//! program generating names one at a time pays O(1) a name, not a scan of
//! every name in use (100,000 textures generated one by one would take 5
//! billion lookups). Names deleted below the cursor come back once the
//! search wraps; the spec only asks that a generated name be unused.

use std::collections::HashSet;

/// The first name from `*cursor` on (wrapping past u32::MAX to 1) for which
/// `free` holds; the cursor moves past it. None when no name is free.
pub fn next_free(cursor: &mut u32, mut free: impl FnMut(u32) -> bool) -> Option<u32> {
    let mut k = (*cursor).max(1);
    // Every nonzero name once at most.
    for _ in 0..u32::MAX {
        if free(k) {
            *cursor = k.wrapping_add(1).max(1);
            return Some(k);
        }
        k = k.wrapping_add(1).max(1);
    }
    None
}

/// The first of `range` (> 0) consecutive names, all free, from `*cursor`
/// on (runs do not wrap: the last name of a run is at most u32::MAX; the
/// search does, to 1); the cursor moves past the run. None when there is
/// no such run.
pub fn free_run(cursor: &mut u32, range: u32, free: impl Fn(u32) -> bool) -> Option<u32> {
    let first = (*cursor).max(1);
    let (mut start, mut wrapped) = (first, false);
    'search: loop {
        if wrapped && start >= first {
            return None;
        }
        let Some(end) = start.checked_add(range - 1) else {
            if wrapped || first == 1 {
                return None;
            }
            (start, wrapped) = (1, true);
            continue;
        };
        // A used name ends the candidate run: the next starts after it.
        for k in start..=end {
            if !free(k) {
                match k.checked_add(1) {
                    Some(next) => start = next,
                    None if wrapped || first == 1 => return None,
                    None => (start, wrapped) = (1, true),
                }
                continue 'search;
            }
        }
        *cursor = end.wrapping_add(1).max(1);
        return Some(start);
    }
}

/// Names generated and not yet used by an object (or, for buffers and
/// queries, every name in use), with the cursor their search starts at.
#[derive(Clone, Debug, Default)]
pub struct Reserved {
    set: HashSet<u32>,
    cursor: u32,
}

impl Reserved {
    /// `n` names neither `used` nor reserved, reserved now, in the order
    /// found.
    pub fn generate(&mut self, n: usize, mut used: impl FnMut(u32) -> bool) -> Vec<u32> {
        // The capacity is a guess: a caller's `n` is not trusted with an
        // allocation of its own size.
        let mut out = Vec::with_capacity(n.min(1 << 12));
        while out.len() < n {
            let set = &self.set;
            let Some(k) = next_free(&mut self.cursor, |k| !used(k) && !set.contains(&k)) else { break };
            self.set.insert(k);
            out.push(k);
        }
        out
    }

    pub fn insert(&mut self, name: u32) {
        self.set.insert(name);
    }

    pub fn remove(&mut self, name: u32) {
        self.set.remove(&name);
    }

    pub fn contains(&self, name: u32) -> bool {
        self.set.contains(&name)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Generating one name after 1..=N are in use looks at one candidate,
    /// not N (the search starts at the cursor, not at 1).
    #[test]
    fn generating_one_at_a_time_is_constant_work() {
        let mut r = Reserved::default();
        let mut looked = 0u64;
        // As a program would: each name becomes an object (leaves the
        // reserved set for the objects' table) before the next glGen call.
        let mut objects = HashSet::new();
        for i in 0..20_000u32 {
            let got = r.generate(1, |k| {
                looked += 1;
                objects.contains(&k)
            });
            assert_eq!(got, vec![i + 1]);
            r.remove(got[0]);
            objects.insert(got[0]);
        }
        assert_eq!(looked, 20_000, "one candidate a name");
    }

    #[test]
    fn names_skip_used_and_reserved_and_wrap_past_the_largest() {
        let mut r = Reserved::default();
        let used = |k: u32| k == 2 || k == 5;
        assert_eq!(r.generate(4, used), vec![1, 3, 4, 6]);
        // Reserved names are not handed out again.
        assert_eq!(r.generate(1, used), vec![7]);
        // A name freed below the cursor comes back after the wrap.
        r.remove(3);
        r.cursor = u32::MAX - 1;
        assert_eq!(r.generate(4, used), vec![u32::MAX - 1, u32::MAX, 3, 8]);
        assert!(r.contains(u32::MAX) && !r.contains(0));
        // The search wraps past u32::MAX to 1, never to 0.
        let mut c = u32::MAX - 1;
        assert_eq!(next_free(&mut c, |k| k == 2), Some(2));
        assert_eq!(c, 3);
    }

    #[test]
    fn runs_are_consecutive_free_names() {
        let used = |k: u32| k == 3 || k == 9;
        let mut c = 0;
        assert_eq!(free_run(&mut c, 2, |k| !used(k)), Some(1));
        assert_eq!(free_run(&mut c, 2, |k| !used(k)), Some(4));
        assert_eq!(free_run(&mut c, 4, |k| !used(k)), Some(10));
        assert_eq!(c, 14);
        // A run does not cross u32::MAX: the search wraps to 1 instead.
        let mut c = u32::MAX - 2;
        assert_eq!(free_run(&mut c, 5, |k| !used(k) && k > 3), Some(4));
        let mut c = u32::MAX - 2;
        assert_eq!(free_run(&mut c, 2, |k| !used(k)), Some(u32::MAX - 2));
        assert_eq!(c, u32::MAX);
        assert_eq!(free_run(&mut c, 1, |k| !used(k)), Some(u32::MAX));
        assert_eq!(c, 1);
        // No run: None, once the search is round (not forever), and the
        // cursor stays.
        let mut c = 50;
        assert_eq!(free_run(&mut c, u32::MAX - 10, |k| k < 20), None);
        assert_eq!(c, 50);
        let mut c = 1;
        assert_eq!(free_run(&mut c, u32::MAX, |k| k != 7), None);
        assert_eq!(c, 1);
    }
}
