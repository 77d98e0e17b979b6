//! Where a rasterizer worker thread runs when it starts and when it is
//! woken (issue 9, round 29: time to first frame, and frames after a
//! pause).
//!
//! Linux may queue a new thread on the core of the thread that created it
//! even when another core is idle; the idle core takes it over only when
//! the busy core's next scheduler tick asks it to balance (up to 4 ms at
//! HZ=250). Measured on the 2-vCPU test host (spheres_s at 1920x1080, 10
//! traced starts): a worker first ran on its creator's core in 5 of 10
//! starts, and then 0.8-4.4 ms late, the calling thread drawing the first
//! frame alone (4.4-4.9 ms against 2.3-3.0 when the worker ran at once).
//!
//! So each worker starts allowed on one core only, not its creator's (the
//! other cores of the process's affinity mask in turn): the kernel moves
//! a queued thread to an allowed core at once. The worker gives itself
//! the creator's whole mask back as soon as it runs, so from then on the
//! scheduler places it freely; a start-up placement, not a pinning.
//!
//! A worker woken from its sleep by a new job was likewise often queued
//! on the waking thread's core (a program pausing 10 ms between frames:
//! 24 of 41 wake-ups in spheres_s, 28 of 41 in book_dino, a median 1.0-1.4
//! ms before the worker ran). So a thread posting a job first takes its
//! own core out of each sleeping worker's mask, and the worker, once it
//! runs, takes the whole mask back.
//!
//! Off Linux, or with one allowed core, nothing is done.

/// The creator's affinity, to hand to each worker it starts.
#[derive(Clone, Copy)]
pub struct Start {
    #[cfg(target_os = "linux")]
    mask: libc::cpu_set_t,
}

#[cfg(target_os = "linux")]
impl Start {
    /// The calling thread's affinity mask, and the cores in it other than
    /// the one it runs on; None when there is no other core.
    pub fn of_caller() -> Option<(Start, Vec<usize>)> {
        // SAFETY: cpu_set_t is plain data (all-zero is the empty set);
        // sched_getaffinity writes at most size_of::<cpu_set_t>() bytes
        // into it; sched_getcpu only reads.
        unsafe {
            let mut mask: libc::cpu_set_t = std::mem::zeroed();
            if libc::sched_getaffinity(0, std::mem::size_of::<libc::cpu_set_t>(), &mut mask) != 0 {
                return None;
            }
            let here = libc::sched_getcpu();
            let others: Vec<usize> = (0..libc::CPU_SETSIZE as usize).filter(|&c| libc::CPU_ISSET(c, &mask) && c as i32 != here).collect();
            if others.is_empty() {
                None
            } else {
                Some((Start { mask }, others))
            }
        }
    }

    /// Lets the thread `t` (just created, maybe not yet run) run only on
    /// `core` until it calls [`Start::release`]. Advisory: a refusal
    /// leaves it where the kernel put it.
    pub fn first_core(t: Handle, core: usize) {
        // SAFETY: `t` is a live thread (the pool's workers never end); the
        // set is plain data passed by pointer with its size.
        unsafe {
            let mut one: libc::cpu_set_t = std::mem::zeroed();
            libc::CPU_SET(core, &mut one);
            libc::pthread_setaffinity_np(t, std::mem::size_of::<libc::cpu_set_t>(), &one);
        }
    }

    /// Lets the thread `t` (asleep) run anywhere in the creator's mask but
    /// on the calling thread's core, until it calls [`Start::release`];
    /// false when that leaves no core (nothing done).
    pub fn away_from_caller(&self, t: Handle) -> bool {
        // SAFETY: as in `first_core`; sched_getcpu only reads.
        unsafe {
            let mut others = self.mask;
            let here = libc::sched_getcpu();
            if here < 0 || !libc::CPU_ISSET(here as usize, &others) {
                return false;
            }
            libc::CPU_CLR(here as usize, &mut others);
            if libc::CPU_COUNT(&others) == 0 {
                return false;
            }
            libc::pthread_setaffinity_np(t, std::mem::size_of::<libc::cpu_set_t>(), &others) == 0
        }
    }

    /// Called on the worker: the creator's whole mask again.
    pub fn release(&self) {
        // SAFETY: pid 0 is the calling thread; the mask is a valid set.
        unsafe {
            libc::sched_setaffinity(0, std::mem::size_of::<libc::cpu_set_t>(), &self.mask);
        }
    }
}

#[cfg(not(target_os = "linux"))]
impl Start {
    pub fn of_caller() -> Option<(Start, Vec<usize>)> {
        None
    }
    pub fn first_core(_t: Handle, _core: usize) {}
    pub fn away_from_caller(&self, _t: Handle) -> bool {
        false
    }
    pub fn release(&self) {}
}

/// A worker thread as [`Start`] names it.
#[cfg(target_os = "linux")]
pub type Handle = libc::pthread_t;
#[cfg(not(target_os = "linux"))]
pub type Handle = ();

/// The thread of `t`.
pub fn handle<T>(t: &std::thread::JoinHandle<T>) -> Handle {
    #[cfg(target_os = "linux")]
    {
        use std::os::unix::thread::JoinHandleExt;
        t.as_pthread_t()
    }
    #[cfg(not(target_os = "linux"))]
    let _ = t;
}

#[cfg(all(test, target_os = "linux"))]
mod tests {
    use super::*;
    use std::sync::atomic::{AtomicBool, Ordering};
    use std::sync::Arc;

    fn affinity() -> Vec<usize> {
        // SAFETY: as in `of_caller`.
        unsafe {
            let mut mask: libc::cpu_set_t = std::mem::zeroed();
            assert_eq!(libc::sched_getaffinity(0, std::mem::size_of::<libc::cpu_set_t>(), &mut mask), 0);
            (0..libc::CPU_SETSIZE as usize).filter(|&c| libc::CPU_ISSET(c, &mask)).collect()
        }
    }

    /// A started thread runs on the core it was given, not its creator's,
    /// until it releases itself; then it has its creator's whole mask.
    #[test]
    fn first_core_then_the_whole_mask() {
        let Some((start, cores)) = Start::of_caller() else {
            eprintln!("one allowed core: nothing to place");
            return;
        };
        let mine = affinity();
        let set = Arc::new(AtomicBool::new(false));
        let seen = set.clone();
        let t = std::thread::spawn(move || {
            while !seen.load(Ordering::Acquire) {
                std::thread::yield_now();
            }
            // SAFETY: sched_getcpu only reads.
            let first = unsafe { libc::sched_getcpu() } as usize;
            let during = affinity();
            start.release();
            (first, during, affinity())
        });
        Start::first_core(handle(&t), cores[0]);
        set.store(true, Ordering::Release);
        let (first, during, after) = t.join().unwrap();
        assert_eq!(during, vec![cores[0]]);
        assert_eq!(first, cores[0]);
        assert_eq!(after, mine);
    }
}
