//! Timeline instrumentation of the threaded rasterizer (round 13): with
//! `SOFTGL_TRACE=FILE` every thread's band work, waits and hand-offs are
//! appended to FILE as text lines `thread kind t0 t1 arg cpu` (nanoseconds;
//! cpu is the core the event ended on, -1 off Linux), each dump after a
//! line `# base UNIX_SECONDS` giving time 0,
//! written at each flush (`tools/trace_frames.py` sums them per thread
//! and frame). Off by default: each event costs a check of a once-set
//! flag.

use std::sync::atomic::{AtomicU32, Ordering};
use std::sync::{Mutex, OnceLock};
use std::time::Instant;

static FILE: OnceLock<Option<String>> = OnceLock::new();
static EVENTS: Mutex<Vec<(u32, u8, u64, u64, u32, i32)>> = Mutex::new(Vec::new());
static NEXT: AtomicU32 = AtomicU32::new(0);

thread_local! {
    static ID: u32 = NEXT.fetch_add(1, Ordering::Relaxed);
}

/// Time 0 of the trace, and the same moment as Unix time in seconds (the
/// `# base` line of each dump), to line a trace up with a program's own
/// clock (round 29: the bench's first-frame times).
fn base() -> Instant {
    static B: OnceLock<Instant> = OnceLock::new();
    *B.get_or_init(|| {
        let unix = std::time::SystemTime::now().duration_since(std::time::UNIX_EPOCH).map(|d| d.as_secs_f64()).unwrap_or(0.0);
        let _ = BASE_UNIX.set(unix);
        Instant::now()
    })
}
static BASE_UNIX: OnceLock<f64> = OnceLock::new();

#[inline]
pub fn on() -> bool {
    FILE.get_or_init(|| std::env::var("SOFTGL_TRACE").ok()).is_some()
}

#[inline]
pub fn now() -> u64 {
    if on() { base().elapsed().as_nanos() as u64 } else { 0 }
}

pub fn rec(kind: u8, t0: u64, arg: u32) {
    if !on() {
        return;
    }
    let t1 = now();
    let id = ID.with(|i| *i);
    // The core the event ended on: shows threads sharing one (round 25).
    #[cfg(target_os = "linux")]
    // SAFETY: sched_getcpu takes no arguments and only reads.
    let cpu = unsafe { libc::sched_getcpu() };
    #[cfg(not(target_os = "linux"))]
    let cpu = -1;
    EVENTS.lock().unwrap_or_else(|e| e.into_inner()).push((id, kind, t0, t1, arg, cpu));
}

pub fn dump() {
    let Some(Some(path)) = FILE.get() else { return };
    let ev = std::mem::take(&mut *EVENTS.lock().unwrap_or_else(|e| e.into_inner()));
    use std::io::Write;
    if let Ok(mut f) = std::fs::OpenOptions::new().create(true).append(true).open(path) {
        let mut s = String::new();
        s.push_str(&format!("# base {:.6}\n", BASE_UNIX.get().copied().unwrap_or(0.0)));
        for (id, k, t0, t1, a, cpu) in ev {
            s.push_str(&format!("{id} {} {t0} {t1} {a} {cpu}\n", k as char));
        }
        let _ = f.write_all(s.as_bytes());
    }
}
