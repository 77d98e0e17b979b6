//! The rasterizer's persistent worker threads (issue 9): started once per
//! process (each first run on a core other than its creator's, and woken
//! onto a core other than its waker's: `placement`), parked on a
//! condition variable between jobs, so that shading a batch of tiles
//! costs a wake-up, not a thread creation.
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
//!
//! Hand-off cost (round 7): small batches are streamed to the workers while
//! the calling thread goes on with the front end, so a job must not cost a
//! system call when the worker is awake. A worker that ran out of jobs
//! spins (polling the posted generation) for up to [`SPIN`] before it
//! sleeps on the condition variable, and [`start`] and the last worker
//! leaving a job only signal a condition variable when someone sleeps on it
//! (the counts are kept under the state's lock, so no wake-up is lost);
//! [`finish`] likewise spins briefly for the workers still running before
//! it sleeps.

use std::sync::atomic::{AtomicBool, AtomicU64, AtomicUsize, Ordering};
use std::sync::{Condvar, Mutex, MutexGuard, OnceLock};
use std::time::{Duration, Instant};

/// How long an idle worker polls for the next job before it sleeps, and
/// how long [`finish`] polls for running workers: long enough to cover the
/// gap between two streamed batches of a frame (immediate_1m hands the
/// workers about 120 batches a frame, about a millisecond apart), short
/// enough that an idle program does not keep a core busy.
const SPIN: Duration = Duration::from_micros(1000);
const FINISH_SPIN: Duration = Duration::from_micros(50);

/// Polls `done` (with a pause between tries) for at most `limit`; true
/// when it became true.
///
/// Between rounds of polls it yields the core (round 10): a poller that
/// shares its core with the thread it waits for (the scheduler often puts
/// a woken worker on its waker's core until load balancing moves it, and
/// on a loaded machine cores are shared anyway) would otherwise keep that
/// thread off the core for its time slice (immediate_1m at 1920x1080 with
/// both threads pinned to one core: 54-60 ms a frame with round 7's pure
/// spin, 51-53 ms yielding, 39 ms with one thread). With a core to itself
/// the yield returns at once.
fn spin_until(limit: Duration, done: impl Fn() -> bool) -> bool {
    let start = Instant::now();
    loop {
        for _ in 0..64 {
            if done() {
                return true;
            }
            std::hint::spin_loop();
        }
        if start.elapsed() >= limit {
            return done();
        }
        std::thread::yield_now();
    }
}

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
    /// Workers asleep on `wake`.
    sleeping: usize,
    /// Threads asleep on `done` (in `finish`).
    waiting: usize,
    /// Worker i is asleep on `wake` (bit i; workers past 64 are left out).
    asleep: u64,
    /// Worker i was kept off the core of the thread that woke it, and
    /// takes its whole mask back when it runs (`placement`).
    moved: u64,
}

struct Pool {
    state: Mutex<State>,
    wake: Condvar,
    done: Condvar,
    /// A job is posted (from `start` to the end of `finish`). An atomic,
    /// not a lock: the thread finishing a job may not be the one that
    /// started it (a context can move between threads).
    busy: AtomicBool,
    /// `State::generation`, readable without the lock (spinning workers).
    posted: AtomicU64,
    /// `State::running`, readable without the lock (a spinning `finish`).
    running: AtomicUsize,
    /// The creator's affinity and the workers' threads (`placement`), set
    /// once every worker's first core is.
    start: OnceLock<(super::placement::Start, Vec<super::placement::Handle>)>,
}

fn lock(s: &Mutex<State>) -> MutexGuard<'_, State> {
    s.lock().unwrap_or_else(|e| e.into_inner())
}

/// The pool with `workers` threads, started on first use. The count is
/// fixed by the first caller (SOFTGL_THREADS is read once per process).
fn pool(workers: usize) -> &'static Pool {
    static POOL: OnceLock<&'static Pool> = OnceLock::new();
    POOL.get_or_init(|| {
        let p: &'static Pool = Box::leak(Box::new(Pool {
            state: Mutex::new(State::default()),
            wake: Condvar::new(),
            done: Condvar::new(),
            busy: AtomicBool::new(false),
            posted: AtomicU64::new(0),
            running: AtomicUsize::new(0),
            start: OnceLock::new(),
        }));
        // Each worker first runs on a core other than this one (see
        // `placement`), and lets the scheduler place it once it runs.
        let start = super::placement::Start::of_caller();
        let release = start.as_ref().map(|s| s.0);
        let mut handles = Vec::new();
        for i in 0..workers {
            let spawned = std::thread::Builder::new().name(format!("softgl-raster-{i}")).spawn(move || worker(p, i, release));
            let Ok(t) = spawned else {
                // Fewer workers: the caller still does all the work.
                break;
            };
            let h = super::placement::handle(&t);
            handles.push(h);
            if let Some((_, cores)) = &start {
                super::placement::Start::first_core(h, cores[i % cores.len()]);
            }
        }
        if let Some((s, _)) = start {
            let _ = p.start.set((s, handles));
        }
        p
    })
}

fn worker(p: &'static Pool, index: usize, release: Option<super::placement::Start>) {
    let bit = if index < 64 { 1u64 << index } else { 0 };
    super::trace::rec(b's', super::trace::now(), 0);
    if let Some(start) = release {
        // Not before the creator has set the first core, or that would
        // outlast this.
        // (`release` is there exactly when `start` will be set.)
        while p.start.get().is_none() {
            std::thread::yield_now();
        }
        start.release();
    }
    let mut seen = 0u64;
    loop {
        // Poll before sleeping: the next batch of a frame usually comes
        // within microseconds, and then needs no system call either side.
        let t0 = super::trace::now();
        spin_until(SPIN, || p.posted.load(Ordering::Acquire) != seen);
        super::trace::rec(b'p', t0, 0);
        let job = {
            let mut s = lock(&p.state);
            while s.generation == seen {
                s.sleeping += 1;
                s.asleep |= bit;
                let t0 = super::trace::now();
                s = p.wake.wait(s).unwrap_or_else(|e| e.into_inner());
                super::trace::rec(b'z', t0, 0);
                s.sleeping -= 1;
                s.asleep &= !bit;
            }
            if s.moved & bit != 0 {
                // Kept off the waker's core until now (`start`).
                s.moved &= !bit;
                if let Some(start) = release {
                    start.release();
                }
            }
            seen = s.generation;
            match s.job {
                Some(job) => {
                    s.running += 1;
                    p.running.store(s.running, Ordering::Release);
                    job
                }
                None => continue,
            }
        };
        // Safety: `finish` keeps the job alive until `running` is back to 0.
        let t0 = super::trace::now();
        let ok = std::panic::catch_unwind(std::panic::AssertUnwindSafe(|| unsafe { (*job.0).work() })).is_ok();
        super::trace::rec(b'j', t0, 0);
        let mut s = lock(&p.state);
        s.running -= 1;
        p.running.store(s.running, Ordering::Release);
        s.panicked |= !ok;
        if s.running == 0 && s.waiting > 0 {
            p.done.notify_all();
        }
    }
}

/// Starts the pool's `threads - 1` workers now if they are not running
/// yet (round 11: called when a context is first made current, so that
/// the threads exist, and have been placed on a core, before the first
/// frame needs them). Nothing with one thread.
pub fn warm(threads: usize) {
    let t0 = super::trace::now();
    if threads > 1 {
        pool(threads - 1);
        super::trace::rec(b'W', t0, 0);
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
/// # Safety
/// `job` must stay alive, unmoved, until `finish(posted, job)` has
/// returned, and `finish` must be called (not the Posted dropped).
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
    let sleeping = {
        let mut s = lock(&p.state);
        s.job = Some(Job(erased));
        s.generation += 1;
        s.panicked = false;
        p.posted.store(s.generation, Ordering::Release);
        // A sleeping worker would often be woken onto this core
        // (`placement`): its mask leaves this core out until it runs.
        // Under the lock, so that it cannot run (and release) first.
        if let Some((start, handles)) = p.start.get().filter(|_| s.asleep & !s.moved != 0) {
            for (i, &t) in handles.iter().enumerate().take(64) {
                let bit = 1u64 << i;
                if s.asleep & !s.moved & bit != 0 && start.away_from_caller(t) {
                    s.moved |= bit;
                }
            }
        }
        s.sleeping
    };
    // Workers still spinning see `posted`; only sleeping ones need waking
    // (a worker about to sleep checks the generation under the lock first).
    if sleeping > 0 {
        p.wake.notify_all();
    }
    Posted { pool: Some(p) }
}

/// Runs `job` (the one given to [`start`]) on the calling thread with the
/// workers still at it, and returns when every run has finished. A panic
/// in a worker's run is raised again here.
pub fn finish(posted: Posted, job: &(dyn Work + '_)) {
    let t0 = super::trace::now();
    let mine = std::panic::catch_unwind(std::panic::AssertUnwindSafe(|| job.work()));
    super::trace::rec(b'o', t0, 0);
    let t0 = super::trace::now();
    let mut panicked = false;
    if let Some(p) = posted.pool {
        let mut s = lock(&p.state);
        s.job = None;
        if s.running > 0 {
            // Workers still at their last band: poll briefly, then sleep.
            drop(s);
            spin_until(FINISH_SPIN, || p.running.load(Ordering::Acquire) == 0);
            s = lock(&p.state);
        }
        while s.running > 0 {
            s.waiting += 1;
            s = p.done.wait(s).unwrap_or_else(|e| e.into_inner());
            s.waiting -= 1;
        }
        panicked = s.panicked;
        drop(s);
        p.busy.store(false, Ordering::Release);
    }
    super::trace::rec(b'w', t0, 0);
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

/// Cuts `buf` into pieces of `piece` elements (the last may be shorter)
/// and calls `f(k, piece_k)` for each, the pieces shared among `threads`
/// (round 7: whole-frame operations such as glClear and glReadPixels cut
/// into bands of rows). Each piece is handed to exactly one call, so the
/// result does not depend on the thread count.
pub fn for_pieces<T: Send>(threads: usize, buf: &mut [T], piece: usize, f: impl Fn(usize, &mut [T]) + Sync) {
    let piece = piece.max(1);
    if threads <= 1 || buf.len() <= piece {
        for (k, p) in buf.chunks_mut(piece).enumerate() {
            f(k, p);
        }
        return;
    }
    let pieces: Vec<Mutex<Option<&mut [T]>>> = buf.chunks_mut(piece).map(|p| Mutex::new(Some(p))).collect();
    let next = AtomicUsize::new(0);
    run(threads, &|| loop {
        let k = next.fetch_add(1, Ordering::Relaxed);
        let Some(slot) = pieces.get(k) else { break };
        // Uncontended: each slot is taken once.
        if let Some(p) = slot.lock().unwrap_or_else(|e| e.into_inner()).take() {
            f(k, p);
        }
    });
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

    /// The hand-off cost (run by hand: `cargo test --release --lib
    /// handoff_cost -- --ignored --nocapture`): a job of one piece posted
    /// while the calling thread goes on with `gap` of its own work, as a
    /// streamed batch is; prints how often a worker took the piece and
    /// the time `start` and `finish` cost the calling thread.
    #[test]
    #[ignore]
    fn handoff_cost() {
        use std::time::{Duration, Instant};
        for gap_us in [2u64, 10, 50, 500] {
            let gap = Duration::from_micros(gap_us);
            let (n, mut overhead, mut by_worker) = (2000, Duration::ZERO, 0);
            let caller = std::thread::current().id();
            for _ in 0..n {
                let taken = AtomicUsize::new(0);
                let worker = std::sync::atomic::AtomicBool::new(false);
                let job = || {
                    if taken.fetch_add(1, Ordering::Relaxed) == 0 {
                        worker.store(std::thread::current().id() != caller, Ordering::Relaxed);
                    }
                };
                let t0 = Instant::now();
                let posted = unsafe { start(2, &job) };
                let t1 = Instant::now();
                while t1.elapsed() < gap {
                    std::hint::spin_loop();
                }
                let t2 = Instant::now();
                finish(posted, &job);
                overhead += (t1 - t0) + t2.elapsed();
                by_worker += worker.load(Ordering::Relaxed) as usize;
            }
            println!("gap {gap_us} us: start + finish {:.2} us a job, worker took {by_worker} of {n}", overhead.as_secs_f64() * 1e6 / n as f64);
        }
    }

    /// Every element is visited once, in the piece its index says.
    #[test]
    fn pieces_cover_the_buffer_once() {
        for (len, piece) in [(0usize, 4usize), (1, 4), (17, 4), (1000, 16), (1000, 1), (64, 64), (65, 64)] {
            for threads in [1, 2, 3] {
                let mut buf = vec![0usize; len];
                for_pieces(threads, &mut buf, piece, |k, p| {
                    for (i, v) in p.iter_mut().enumerate() {
                        *v += k * piece + i + 1;
                    }
                });
                assert!(buf.iter().enumerate().all(|(i, &v)| v == i + 1), "len {len} piece {piece} threads {threads}");
            }
        }
    }

    /// Round 29: each worker, started allowed on one core only, or woken
    /// from its sleep with the waker's core left out (`placement`), has
    /// its creator's whole affinity mask back once it runs (the test
    /// threads all have the process's mask).
    #[cfg(target_os = "linux")]
    #[test]
    fn workers_end_with_the_creators_mask() {
        fn allowed(status: &str) -> Option<String> {
            status.lines().find_map(|l| l.strip_prefix("Cpus_allowed_list:").map(|v| v.trim().to_string()))
        }
        let mine = allowed(&std::fs::read_to_string("/proc/thread-self/status").unwrap()).unwrap();
        let all_back = |when: &str| {
            let deadline = Instant::now() + Duration::from_secs(5);
            loop {
                let mut masks = Vec::new();
                for task in std::fs::read_dir("/proc/self/task").unwrap().flatten() {
                    let comm = std::fs::read_to_string(task.path().join("comm")).unwrap_or_default();
                    if comm.starts_with("softgl-raster") {
                        masks.push(std::fs::read_to_string(task.path().join("status")).ok().and_then(|s| allowed(&s)).unwrap_or_default());
                    }
                }
                assert!(!masks.is_empty(), "no worker threads");
                if masks.iter().all(|m| *m == mine) {
                    return;
                }
                assert!(Instant::now() < deadline, "{when}: workers' masks {masks:?}, the process's {mine}");
                std::thread::sleep(Duration::from_millis(10));
            }
        };
        warm(3);
        all_back("after the start");
        // Past their polling: the workers sleep, and the next job wakes them.
        std::thread::sleep(SPIN * 20);
        run(3, &|| std::thread::sleep(Duration::from_millis(1)));
        all_back("after a wake-up");
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
