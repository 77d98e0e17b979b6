//! Contexts drawing into drawables' shared framebuffers
//! (framebuffer::shared): for the length of each GL call the context's
//! `fb` (and `read_fb`) are exchanged with the drawables' (O(1) swaps,
//! under the drawables' mutexes, taken in address order so that two
//! contexts bound to the same pair the other way round cannot deadlock).
//! Outside calls the framebuffers sit in the drawables, where the window
//! system (SwapBuffers, resizes) and other contexts find them. While a
//! framebuffer object is bound, the window's framebuffer is parked beside
//! `fb` (`Context::window_fb_mut`), and that is what is exchanged.

use crate::framebuffer::shared::SharedFramebuffer;
use crate::gl::{validate::DIRTY_ALL, Context};
use std::cell::Cell;
use std::sync::Arc;

thread_local! {
    /// This thread is inside a call with its framebuffers swapped in (a
    /// nested entry point uses them as they are).
    static ENTERED: Cell<bool> = const { Cell::new(false) };
}

/// Runs `f` on `ctx` with its bound drawables' framebuffers in place.
#[inline]
pub fn with_bound<R>(ctx: &mut Context, f: impl FnOnce(&mut Context) -> R) -> R {
    if ctx.bound.is_none() || ENTERED.with(|e| e.get()) {
        return f(ctx);
    }
    let b: *const crate::framebuffer::shared::Binding = ctx.bound.as_ref().unwrap();
    // SAFETY: the binding changes only at MakeCurrent, never during a call.
    let b = unsafe { &*b };
    let out = swapped(ctx, &b.draw, b.read.as_ref(), f);
    // The call may have presented a frame (glFlush, glFinish of a
    // single-buffered drawable); the drawables' locks are released now.
    crate::winsys::dump::exit_if_due();
    out
}

fn swapped<R>(ctx: &mut Context, draw: &Arc<SharedFramebuffer>, read: Option<&Arc<SharedFramebuffer>>, f: impl FnOnce(&mut Context) -> R) -> R {
    let me = ctx as *const Context as usize;
    // Lock in address order.
    let (mut d, mut r) = match read {
        None => (draw.lock(), None),
        Some(read) if Arc::as_ptr(read) < Arc::as_ptr(draw) => {
            let r = read.lock();
            (draw.lock(), Some(r))
        }
        Some(read) => {
            let d = draw.lock();
            (d, Some(read.lock()))
        }
    };
    if d.last_user != me {
        // Another context (or a resize) changed it: the size and the
        // draw-buffer selection are this context's again.
        d.last_user = me;
        ctx.dirty |= DIRTY_ALL;
        std::mem::swap(ctx.window_fb_mut(), &mut d.fb);
        ctx.sync_draw_buffer();
    } else {
        std::mem::swap(ctx.window_fb_mut(), &mut d.fb);
    }
    if let (Some(r), Some(rf)) = (r.as_mut(), ctx.read_fb.as_mut()) {
        std::mem::swap(rf, &mut r.fb);
    }
    ENTERED.with(|e| e.set(true));
    // `f` catches its own panics (api::dispatch), so this always runs.
    let out = f(ctx);
    // Binned triangles (render::tile) are shaded now, while the drawable's
    // framebuffer is in place: after the call it may be presented, resized
    // or drawn by another context.
    ctx.sync_render();
    ENTERED.with(|e| e.set(false));
    // A framebuffer object's staging buffer stays in `fb` (gl::framebuffer_object):
    // the drawable gets back its own.
    std::mem::swap(ctx.window_fb_mut(), &mut d.fb);
    if let (Some(r), Some(rf)) = (r.as_mut(), ctx.read_fb.as_mut()) {
        std::mem::swap(rf, &mut r.fb);
    }
    out
}
