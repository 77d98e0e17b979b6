//! The rasterizer's persistent worker threads (issue 9): started once per
//! process, parked on a condition variable between jobs, so that shading
//! a batch of tiles costs a wake-up, not a thread creation.
//!
//! A job is a closure every participant runs at once (the calling thread
//! too); it takes its pieces of work from a shared counter, so a worker
//! that wakes late finds little or nothing left. When the caller has
//! finished its own share it withdraws the job: workers that have not
//! picked it up by then never see it, and [`run`] returns as soon as the
//! workers that did pick it up are done. Borrowed data therefore never
//! outlives the call. Two contexts flushing at the same time on different
//! threads do not share the pool: the second runs its job alone.

use std::sync::{Condvar, Mutex, MutexGuard, OnceLock};

/// A job with its lifetime erased; valid while [`run`] is running it.
#[derive(Clone, Copy)]
struct Job(*const (dyn Fn() + Sync));

// The closure is Sync and outlives every use (see `run`).
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
    /// Held by the thread using the pool.
    busy: Mutex<()>,
}

fn lock(s: &Mutex<State>) -> MutexGuard<'_, State> {
    s.lock().unwrap_or_else(|e| e.into_inner())
}

/// The pool with `workers` threads, started on first use. The count is
/// fixed by the first caller (SOFTGL_THREADS is read once per process).
fn pool(workers: usize) -> &'static Pool {
    static POOL: OnceLock<&'static Pool> = OnceLock::new();
    POOL.get_or_init(|| {
        let p: &'static Pool = Box::leak(Box::new(Pool { state: Mutex::new(State::default()), wake: Condvar::new(), done: Condvar::new(), busy: Mutex::new(()) }));
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
        // Safety: `run` keeps the closure alive until `running` is back to 0.
        let ok = std::panic::catch_unwind(std::panic::AssertUnwindSafe(|| unsafe { (*job.0)() })).is_ok();
        let mut s = lock(&p.state);
        s.running -= 1;
        s.panicked |= !ok;
        if s.running == 0 {
            p.done.notify_all();
        }
    }
}

/// Runs `job` on the calling thread and on up to `threads - 1` workers at
/// once; returns when every run that started has finished. A panic in a
/// worker's run is raised again here.
pub fn run(threads: usize, job: &(dyn Fn() + Sync)) {
    if threads <= 1 {
        return job();
    }
    let p = pool(threads - 1);
    let Ok(_busy) = p.busy.try_lock() else {
        return job();
    };
    // Safety of the erased lifetime: the job is withdrawn below, and this
    // function does not return before every worker that took it is done.
    let erased: *const (dyn Fn() + Sync + '_) = job;
    let erased: *const (dyn Fn() + Sync + 'static) = unsafe { std::mem::transmute(erased) };
    {
        let mut s = lock(&p.state);
        s.job = Some(Job(erased));
        s.generation += 1;
        s.panicked = false;
    }
    p.wake.notify_all();
    let mine = std::panic::catch_unwind(std::panic::AssertUnwindSafe(job));
    let panicked = {
        let mut s = lock(&p.state);
        s.job = None;
        while s.running > 0 {
            s = p.done.wait(s).unwrap_or_else(|e| e.into_inner());
        }
        s.panicked
    };
    if let Err(e) = mine {
        std::panic::resume_unwind(e);
    }
    if panicked {
        panic!("a rasterizer worker panicked");
    }
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
