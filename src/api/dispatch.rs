//! How an entry point reaches the GL state machine: find the current
//! context, never let a panic cross the C ABI, and apply the Begin/End rule
//! for commands that are not allowed between glBegin and glEnd. Every
//! entry point also runs with floating-point exceptions masked (`fpenv`).

use super::fpenv::FpGuard;
use super::ret::Zero;
use crate::gl::{enums::GL_INVALID_OPERATION, Context};
use crate::winsys::current::current;
use std::panic::{catch_unwind, AssertUnwindSafe};

/// Runs `f` on the current context. No current context: does nothing and
/// returns zero. A panic is caught, reported as GL_OUT_OF_MEMORY (the only
/// failure the spec lets an implementation report for itself) and the
/// command returns zero.
#[inline(always)]
pub fn with_current<R: Zero>(f: impl FnOnce(&mut Context) -> R) -> R {
    let p = current();
    if p.is_null() {
        return R::zero();
    }
    // SAFETY: the pointer was made current by MakeCurrent and stays valid
    // until it is released; GL contexts are used by one thread at a time.
    let ctx = unsafe { &mut *p };
    // Inside a primitive begun with every exception masked, the caller's
    // environment was read at glBegin (fpenv: reading it waits for the
    // floating-point work in flight).
    let _fp = if ctx.fp_trusted() {
        None
    } else {
        let g = FpGuard::enter();
        ctx.fp_caller_masked = g.caller_masked();
        Some(g)
    };
    // An OSMesa or wgl context with no share group owns its framebuffer
    // and objects: nothing to swap in, so the call goes straight to `f`
    // (immediate mode's hot path; no out-of-line wrappers).
    if ctx.bound.is_none() && ctx.share.is_none() {
        return caught(p, f);
    }
    swapped_in(p, f)
}

/// The `list` entry points' way in: [`with_current`] building the
/// command with `build` and submitting it (`Context::submit_direct`).
/// Round 16: inside a primitive on the batched path's plain case whose
/// caller masked every floating-point exception, while no list is being
/// compiled (`Context::plain_vertex`, one flag set at glBegin), the
/// guard's test, the list's and the batch's are all known: a context
/// with no bound drawable or share group goes straight to
/// `Context::submit_plain` (about 12 instructions a vertex fewer).
/// Round 25: any other primitive begun with every exception masked is
/// inline too, and the rest ([`list_elsewhere`]) out of line.
#[inline(always)]
pub fn with_current_list(build: impl FnOnce(&mut Context) -> Option<crate::gl::Command>) {
    let p = current();
    if p.is_null() {
        return;
    }
    // SAFETY: as in with_current.
    let ctx = unsafe { &mut *p };
    if ctx.plain_vertex && ctx.bound.is_none() && ctx.share.is_none() {
        // The guard would be skipped (`fp_trusted`); the panic guard stays.
        return caught(p, move |ctx| {
            if let Some(cmd) = build(ctx) {
                ctx.submit_plain(cmd);
            }
        });
    }
    // Inside any other primitive begun with every exception masked: as
    // `with_current` would run it, without the guard.
    if ctx.fp_trusted() && ctx.bound.is_none() && ctx.share.is_none() {
        return caught(p, move |ctx| {
            if let Some(cmd) = build(ctx) {
                ctx.submit_direct(cmd);
            }
        });
    }
    list_elsewhere(p, build)
}

/// [`with_current_list`] for the rest: outside a primitive, an untrusted
/// caller's environment, a list being compiled, a bound drawable or a
/// share group. Out of line (round 25), so that the entry points' paths
/// above save and restore only the registers they use: glVertex2f saved
/// five and spilled its arguments for these paths' sake (immediate_1m
/// with 1 thread: 1,375 -> 1,349 M instructions over 3 frames; a list
/// compiled with GL_COMPILE pays about 19 more a command).
#[inline(never)]
fn list_elsewhere(p: *mut Context, build: impl FnOnce(&mut Context) -> Option<crate::gl::Command>) {
    // SAFETY: as in with_current.
    let ctx = unsafe { &mut *p };
    // Round 20: between a recorded glBegin and glEnd of a list compiled
    // with GL_COMPILE, by a caller that masked every exception
    // (`Context::compile_fast`), the command goes straight into the list.
    if ctx.compile_fast && ctx.bound.is_none() && ctx.share.is_none() {
        return caught(p, move |ctx| {
            if let Some(cmd) = build(ctx) {
                ctx.record_compiled(cmd);
            }
        });
    }
    with_current(move |ctx| {
        if let Some(cmd) = build(ctx) {
            ctx.submit_direct(cmd);
        }
    })
}

/// [`with_current`] for contexts with a bound drawable or a share group:
/// objects shared with other contexts, and the bound drawables'
/// framebuffers, are put in place for the call. Out of line: rare.
#[inline(never)]
fn swapped_in<R: Zero>(p: *mut Context, f: impl FnOnce(&mut Context) -> R) -> R {
    // SAFETY: as in with_current.
    let ctx = unsafe { &mut *p };
    crate::winsys::bound::with_bound(ctx, |ctx| crate::gl::share::with_shared(ctx, |ctx| caught(ctx as *mut Context, f)))
}

/// Runs `f` on the context, catching a panic: GL_OUT_OF_MEMORY and zero.
#[inline(always)]
fn caught<R: Zero>(p: *mut Context, f: impl FnOnce(&mut Context) -> R) -> R {
    // SAFETY: as in with_current; `f`'s borrow has ended when the panic
    // handler takes the context again.
    match catch_unwind(AssertUnwindSafe(|| f(unsafe { &mut *p }))) {
        Ok(r) => r,
        Err(_) => {
            let ctx = unsafe { &mut *p };
            ctx.set_error(crate::gl::enums::GL_OUT_OF_MEMORY);
            R::zero()
        }
    }
}

/// For commands that execute immediately and are illegal between Begin and
/// End (GL 1.5 section 2.6.3): INVALID_OPERATION there, and nothing happens.
#[inline]
pub fn outside_begin_end<R: Zero>(f: impl FnOnce(&mut Context) -> R) -> R {
    with_current(|ctx| {
        // Immediate commands may read or write the framebuffer: shade
        // what is binned first (render::tile).
        ctx.sync_render();
        if ctx.in_begin_end() {
            ctx.set_error(GL_INVALID_OPERATION);
            R::zero()
        } else {
            f(ctx)
        }
    })
}

/// GLU's entry points: the floating-point and panic guards only. GLU is
/// a client of GL; the GL calls it makes shade binned triangles when they
/// must.
#[inline]
pub fn guarded_client<R: Zero>(f: impl FnOnce() -> R) -> R {
    let _fp = FpGuard::enter();
    catch_unwind(AssertUnwindSafe(f)).unwrap_or_else(|_| R::zero())
}

/// For window-system entry points, which need no context: the panic
/// guard, after the current context's binned triangles are shaded.
#[inline]
pub fn guarded<R: Zero>(f: impl FnOnce() -> R) -> R {
    guarded_client(|| {
        // Window-system calls present, resize and switch contexts: the
        // current context's binned triangles are shaded first
        // (render::tile).
        let p = current();
        if !p.is_null() {
            // SAFETY: as in with_current. A GLX context's triangles belong
            // to its drawable's framebuffer, swapped in by with_bound.
            unsafe { crate::winsys::bound::with_bound(&mut *p, |c| c.sync_render()) };
        }
        f()
    })
}
