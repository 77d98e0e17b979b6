//! Framebuffers that belong to a drawable rather than a context (GLX 1.4
//! section 2.2: a drawable's buffers are shared by every context bound to
//! it, in any thread). The framebuffer lives behind a mutex; a bound
//! context takes it for the length of each GL call (winsys::bound) and
//! puts it back after, so contexts in different threads drawing to one
//! window serialize on it and all see one image.

use super::Framebuffer;
use std::sync::{Arc, Mutex, MutexGuard};

/// A drawable's framebuffer, while no call is using it.
pub struct Slot {
    pub fb: Framebuffer,
    /// The context whose call last had it (its address; 0: changed by the
    /// window system): any other must revalidate (size, draw buffer).
    pub last_user: usize,
}

pub struct SharedFramebuffer {
    slot: Mutex<Slot>,
}

impl SharedFramebuffer {
    pub fn new(fb: Framebuffer) -> Arc<SharedFramebuffer> {
        Arc::new(SharedFramebuffer { slot: Mutex::new(Slot { fb, last_user: 0 }) })
    }

    pub fn lock(&self) -> MutexGuard<'_, Slot> {
        self.slot.lock().unwrap_or_else(|e| e.into_inner())
    }
}

/// What a context is bound to: the draw drawable's framebuffer and, when
/// it is another drawable, the read one's.
#[derive(Clone)]
pub struct Binding {
    pub draw: Arc<SharedFramebuffer>,
    pub read: Option<Arc<SharedFramebuffer>>,
}
