//! The GLXContext handles softgl has given out (GLX 1.4 section 3.3.7). A
//! GLXContext is a pointer to softgl's context; checking a handle here
//! before following it lets a stale or made-up handle get GLXBadContext,
//! as the GLX functions that take contexts say, instead of being
//! dereferenced.

use std::sync::Mutex;

#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum State {
    Live,
    /// glXDestroyContext was called while it was current: the handle is no
    /// longer valid, but the context lives until it is released.
    Destroyed,
}

/// Addresses of the contexts that exist. Programs hold a handful: a scan
/// is cheap.
static CONTEXTS: Mutex<Vec<(usize, State)>> = Mutex::new(Vec::new());

fn contexts() -> std::sync::MutexGuard<'static, Vec<(usize, State)>> {
    CONTEXTS.lock().unwrap_or_else(|e| e.into_inner())
}

/// A context was made.
pub fn add<T>(ctx: *const T) {
    contexts().push((ctx as usize, State::Live));
}

/// glXDestroyContext of a context still current somewhere.
pub fn mark_destroyed<T>(ctx: *const T) {
    for e in contexts().iter_mut().filter(|e| e.0 == ctx as usize) {
        e.1 = State::Destroyed;
    }
}

/// The context is freed.
pub fn remove<T>(ctx: *const T) {
    contexts().retain(|e| e.0 != ctx as usize);
}

/// What `ctx` is: None for a handle softgl never made or has freed.
pub fn state<T>(ctx: *const T) -> Option<State> {
    contexts().iter().find(|e| e.0 == ctx as usize).map(|e| e.1)
}

/// Whether `ctx` is a context that exists and is not destroyed.
pub fn is_live<T>(ctx: *const T) -> bool {
    !ctx.is_null() && state(ctx) == Some(State::Live)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn handles_from_made_to_freed() {
        let a = Box::new(1u32);
        let p: *const u32 = &*a;
        assert!(!is_live(p) && state(p).is_none());
        add(p);
        assert!(is_live(p));
        assert!(!is_live(std::ptr::null::<u32>()));
        assert!(!is_live((p as usize + 4) as *const u32));
        mark_destroyed(p);
        assert!(!is_live(p));
        assert_eq!(state(p), Some(State::Destroyed));
        remove(p);
        assert!(state(p).is_none());
    }
}
