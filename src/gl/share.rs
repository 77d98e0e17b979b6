//! Object sharing between contexts (GL 1.5 appendix D.1; GLX 1.4 section
//! 3.3.7's share_list, wglShareLists, OSMesaCreateContextExt's sharelist):
//! contexts of one share group see the same display lists, texture objects
//! (not the default, name-0 ones), buffer objects, renderbuffers
//! (ARB_framebuffer_object: framebuffer objects themselves are not shared)
//! and sampler objects (ARB_sampler_objects). Everything else, bindings
//! included, stays per context.
//!
//! A renderbuffer another context draws into through its framebuffer
//! object shows that drawing once that context has written its staging
//! copy back (it does on unbinding, and before anything of its own reads
//! the image; see `framebuffer_object`), which meets the spec's rule that
//! another context sees the results after the drawing context's
//! glFinish/glFlush and a rebind.
//!
//! How: the shared tables live in a [`ShareGroup`] behind a mutex. A
//! context of a group holds empty tables of its own; for the length of each
//! GL call ([`with_shared`], from the API's dispatch) it locks the group and
//! swaps the group's tables in (three O(1) swaps), then swaps them back. So
//! contexts current in different threads never touch the tables at the
//! same time: their calls are serialized on the group's mutex (the price of
//! sharing; contexts outside a group pay one branch per call). A context
//! that was not the group's last user revalidates its texture state, since
//! another context may have changed the objects it has bound.
//!
//! Display lists hold `Rc`s, which are not thread-safe. They are only ever
//! touched by the thread holding the group's lock, and no clone outlives a
//! GL call (a running glCallList holds one only during the call), which is
//! what makes sending them between threads sound (the `Send` impl below).

use super::buffers::Buffers;
use super::lists::ListStore;
use super::context::Context;
use super::texture::TexObject;
use super::validate::DIRTY_TEXTURE;
use std::cell::Cell;
use std::collections::HashMap;
use std::sync::{Arc, Mutex};

/// The objects a share group has in common.
#[derive(Default)]
pub struct Tables {
    lists: ListStore,
    textures: HashMap<u32, TexObject>,
    texture_names: super::names::Reserved,
    buffers: Buffers,
    fbo: super::framebuffer_object::SharedRenderbuffers,
    samplers: super::texture::sampler::SharedSamplers,
}

struct Inner {
    tables: Tables,
    /// The context whose call last had the tables (its address).
    last_user: usize,
}

// SAFETY: see the module comment: the Rc's inside are used only by the
// thread that holds the mutex, and none escapes a call.
unsafe impl Send for Inner {}

/// A set of contexts sharing objects.
pub struct ShareGroup {
    inner: Mutex<Inner>,
}

thread_local! {
    /// This thread is inside a call with its group's tables swapped in:
    /// a nested entry point (none should nest, but a window-system helper
    /// calling GL from inside a call must not deadlock) uses them as they
    /// are.
    static ENTERED: Cell<bool> = const { Cell::new(false) };
}

impl Context {
    /// Exchanges the shared objects with `t`.
    fn swap_shared(&mut self, t: &mut Tables) {
        self.lists.swap_table(&mut t.lists);
        std::mem::swap(&mut self.texture.objects, &mut t.textures);
        std::mem::swap(&mut self.texture.reserved, &mut t.texture_names);
        self.buffers.swap_objects(&mut t.buffers);
        self.fbo.swap_renderbuffers(&mut t.fbo);
        self.samplers.swap_objects(&mut t.samplers);
    }
}

/// Runs `f` on `ctx` with its share group's objects in place.
#[inline]
pub fn with_shared<R>(ctx: &mut Context, f: impl FnOnce(&mut Context) -> R) -> R {
    let Some(group) = ctx.share.clone() else { return f(ctx) };
    if ENTERED.with(|e| e.get()) {
        return f(ctx);
    }
    let mut g = group.inner.lock().unwrap_or_else(|e| e.into_inner());
    let id = ctx as *const Context as usize;
    if g.last_user != id {
        g.last_user = id;
        ctx.dirty |= DIRTY_TEXTURE;
    }
    ctx.swap_shared(&mut g.tables);
    ENTERED.with(|e| e.set(true));
    // `f` catches its own panics (api::dispatch), so this always runs.
    let r = f(ctx);
    ENTERED.with(|e| e.set(false));
    ctx.swap_shared(&mut g.tables);
    r
}

/// Makes `ctx` (a new context, with no objects yet) share `other`'s
/// objects. A group is made from `other`'s objects the first time. `other`
/// must not be inside a GL call in another thread meanwhile (the window
/// systems call this while creating `ctx`).
pub fn join(ctx: &mut Context, other: &mut Context) {
    if std::ptr::eq(ctx, other) {
        return;
    }
    let group = match &other.share {
        Some(g) => g.clone(),
        None => {
            let mut tables = Tables::default();
            other.swap_shared(&mut tables);
            let g = Arc::new(ShareGroup { inner: Mutex::new(Inner { tables, last_user: 0 }) });
            other.share = Some(g.clone());
            g
        }
    };
    // Objects `ctx` made before joining (none, for a new context) are
    // dropped: it sees the group's.
    ctx.swap_shared(&mut Tables::default());
    ctx.share = Some(group);
    ctx.dirty |= DIRTY_TEXTURE;
}
