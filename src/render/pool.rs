//! The rasterizer's persistent worker threads (issue 9): started once per
//! process, parked on a condition variable between jobs, so that shading
//! a batch of tiles costs a wake-up, not a thread creation.
//!
//! A job is a [`Work`] every participant runs at once; it takes its pieces
//! of work from a shared counter, so a worker that wakes late finds little
//! or nothing left. [`start`] posts a job and returns at once (the calling
//! thread goes on with other work: `tile` builds the next batch meanwhile);
//! [`finish`] runs the job on the calling thread too (it helps with what
//! is left rather than sleep), withdraws it, so that workers that have not
//! picked it up never see it, and returns when the workers that did pick
//! it up are done. [`run`] is both at once. A job's data therefore only has
//! to live from `start` to the end of `finish`. The pool runs one job at a
//! time: a second context posting while another's job is posted gets no
//! workers, and its job runs on its own thread in `finish`.

use std::sync::atomic::{AtomicBool, Ordering};
use std::sync::{Condvar, Mutex, MutexGuard, OnceLock};

/// A job: takes pieces of work until none is left. Every participant
/// calls `work` once, at the same time as the others.
pub trait Work: Sync {
    fn work(&self);
}

impl<F: Fn() + Sync> Work for F {
    fn work(&self) {
        self()
    }
}

/// A job with its lifetime erased; valid from [`start`] to the end of
/// [`finish`].
#[derive(Clone, Copy)]
struct Job(*const (dyn Work + 'static));

// The job is Sync and outlives every use (see `start`).
unsafe impl Send for Job {}

#[derive(Default)]
struct State {
    job: Option<Job>,
    /// Incremented per job, so that a worker runs each job at most once.
    generation: u64,
    /// Workers running the current job.
    running: usize,
    /// A worker's run of a job panicked.
    panicked: bool,
}

struct Pool {
    state: Mutex<State>,
    wake: Condvar,
    done: Condvar,
    /// A job is posted (from `start` to the end of `finish`). An atomic,
    /// not a lock: the thread finishing a job may not be the one that
    /// started it (a context can move between threads).
    busy: AtomicBool,
}

fn lock(s: &Mutex<State>) -> MutexGuard<'_, State> {
    s.lock().unwrap_or_else(|e| e.into_inner())
}

/// The pool with `workers` threads, started on first use. The count is
/// fixed by the first caller (SOFTGL_THREADS is read once per process).
fn pool(workers: usize) -> &'static Pool {
    static POOL: OnceLock<&'static Pool> = OnceLock::new();
    POOL.get_or_init(|| {
        let p: &'static Pool = Box::leak(Box::new(Pool { state: Mutex::new(State::default()), wake: Condvar::new(), done: Condvar::new(), busy: AtomicBool::new(false) }));
        for i in 0..workers {
            let spawned = std::thread::Builder::new().name(format!("softgl-raster-{i}")).spawn(move || worker(p));
            if spawned.is_err() {
                // Fewer workers: the caller still does all the work.
                break;
            }
        }
        p
    })
}

fn worker(p: &'static Pool) {
    let mut seen = 0u64;
    loop {
        let job = {
            let mut s = lock(&p.state);
            while s.generation == seen {
                s = p.wake.wait(s).unwrap_or_else(|e| e.into_inner());
            }
            seen = s.generation;
            match s.job {
                Some(job) => {
                    s.running += 1;
                    job
                }
                None => continue,
            }
        };
        // Safety: `finish` keeps the job alive until `running` is back to 0.
        let ok = std::panic::catch_unwind(std::panic::AssertUnwindSafe(|| unsafe { (*job.0).work() })).is_ok();
        let mut s = lock(&p.state);
        s.running -= 1;
        s.panicked |= !ok;
        if s.running == 0 {
            p.done.notify_all();
        }
    }
}

/// A job [`start`] posted (or kept for the calling thread alone), to be
/// handed to [`finish`].
#[must_use]
pub struct Posted {
    pool: Option<&'static Pool>,
}

/// Posts `job` to up to `threads - 1` workers and returns at once. With
/// one thread, or while another job is posted, nothing runs until
/// [`finish`], which then does all the work on its thread.
///
/// Safety: `job` must stay alive, unmoved, until `finish(posted, job)`
/// has returned, and `finish` must be called (not the Posted dropped).
pub unsafe fn start(threads: usize, job: &(dyn Work + '_)) -> Posted {
    if threads <= 1 {
        return Posted { pool: None };
    }
    let p = pool(threads - 1);
    if p.busy.compare_exchange(false, true, Ordering::Acquire, Ordering::Relaxed).is_err() {
        return Posted { pool: None };
    }
    let erased: *const (dyn Work + '_) = job;
    // Safety of the erased lifetime: the caller's contract above.
    let erased: *const (dyn Work + 'static) = std::mem::transmute(erased);
    {
        let mut s = lock(&p.state);
        s.job = Some(Job(erased));
        s.generation += 1;
        s.panicked = false;
    }
    p.wake.notify_all();
    Posted { pool: Some(p) }
}

/// Runs `job` (the one given to [`start`]) on the calling thread with the
/// workers still at it, and returns when every run has finished. A panic
/// in a worker's run is raised again here.
pub fn finish(posted: Posted, job: &(dyn Work + '_)) {
    let mine = std::panic::catch_unwind(std::panic::AssertUnwindSafe(|| job.work()));
    let mut panicked = false;
    if let Some(p) = posted.pool {
        let mut s = lock(&p.state);
        s.job = None;
        while s.running > 0 {
            s = p.done.wait(s).unwrap_or_else(|e| e.into_inner());
        }
        panicked = s.panicked;
        drop(s);
        p.busy.store(false, Ordering::Release);
    }
    if let Err(e) = mine {
        std::panic::resume_unwind(e);
    }
    if panicked {
        panic!("a rasterizer worker panicked");
    }
}

/// Runs `job` on the calling thread and on up to `threads - 1` workers at
/// once; returns when every run that started has finished.
pub fn run(threads: usize, job: &(dyn Work + Sync)) {
    // Safety: finished before `job`'s borrow ends.
    let posted = unsafe { start(threads, job) };
    finish(posted, job);
}

#[cfg(test)]
mod tests {
    use super::*;
    use std::sync::atomic::{AtomicUsize, Ordering};

    /// Every piece of every job is done exactly once, whoever does it, and
    /// borrowed data is only used while `run` runs.
    #[test]
    fn jobs_run_every_piece_once() {
        for round in 0..200 {
            let pieces: Vec<AtomicUsize> = (0..64 + round % 7).map(|_| AtomicUsize::new(0)).collect();
            let next = AtomicUsize::new(0);
            run(3, &|| loop {
                let k = next.fetch_add(1, Ordering::Relaxed);
                if k >= pieces.len() {
                    break;
                }
                pieces[k].fetch_add(1, Ordering::Relaxed);
            });
            assert!(pieces.iter().all(|p| p.load(Ordering::Relaxed) == 1), "round {round}");
        }
    }

    /// A panic in a job reaches the caller, and the pool still works.
    #[test]
    fn a_panicking_job_is_reported() {
        let r = std::panic::catch_unwind(|| run(2, &|| panic!("boom")));
        assert!(r.is_err());
        let n = AtomicUsize::new(0);
        run(2, &|| {
            n.fetch_add(1, Ordering::Relaxed);
        });
        assert!(n.load(Ordering::Relaxed) >= 1);
    }
}
