//! The per-thread current context (GL 1.5 spec, section 2.1: commands act on
//! the context current in the calling thread).

use crate::gl::Context;
use std::cell::Cell;
use std::ptr::null_mut;

thread_local! {
    static CURRENT: Cell<*mut Context> = const { Cell::new(null_mut()) };
}

/// The calling thread's current context, or null.
#[inline]
pub fn current() -> *mut Context {
    CURRENT.with(|c| c.get())
}

pub fn set_current(ctx: *mut Context) {
    CURRENT.with(|c| c.set(ctx));
}
