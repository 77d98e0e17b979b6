//! GLX drawables (GLX 1.4 sections 3.3.4–3.3.6): windows, pixmaps and
//! pbuffers, each owning its framebuffer (framebuffer::shared), so that
//! every context bound to a drawable, in any thread, draws into the same
//! buffers: several contexts on one window, a pbuffer current in two
//! contexts of a share group, a read drawable other than the draw one.
//!
//! A drawable's record is made by glXCreateWindow, glXCreatePixmap,
//! glXCreateGLXPixmap and glXCreatePbuffer, or, for a plain X window
//! given to glXMakeCurrent, at its first binding (with the binding
//! context's config). It goes at the matching glXDestroy* (when no context
//! is bound to it any more); records of plain X windows that no longer
//! exist are collected when a new window is first bound.
//!
//! Buffers: a config's double buffering gives the framebuffer a back
//! buffer (a GLXPixmap too: it keeps its front buffer, which is what the
//! X pixmap shows, and glXSwapBuffers on it does nothing, section 3.3.10);
//! a context with a double-buffered config bound to a single-buffered
//! drawable gives it a back buffer. Windows and pixmaps follow the X
//! drawable's size at each binding and after each glXSwapBuffers (a
//! resize clears them); pbuffers keep the size they were made with.

use super::present::XSurface;
use super::xlib::{self, xlib, Display, Xid};
use super::FbConfig;
use crate::framebuffer::shared::SharedFramebuffer;
use crate::framebuffer::{Framebuffer, MAX_SIZE};
use std::ffi::{c_int, c_uint};
use std::sync::{Arc, Mutex};

#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Kind {
    Window,
    Pixmap,
    Pbuffer { width: usize, height: usize, preserved: bool, largest: bool },
}

pub struct Drawable {
    pub dpy: usize,
    pub id: Xid,
    pub kind: Kind,
    pub config: &'static FbConfig,
    pub fb: Arc<SharedFramebuffer>,
    /// Where frames go (windows and pixmaps), made at the first binding.
    pub surface: Mutex<Option<XSurface>>,
    /// The swap interval (GLX_EXT_swap_control) and last swap time.
    pub pacing: super::swap::Pacing,
}

// SAFETY: the raw pointers inside (display, GC, segment) are used under
// the surface's mutex only.
unsafe impl Sync for Drawable {}
unsafe impl Send for Drawable {}

static DRAWABLES: Mutex<Vec<Arc<Drawable>>> = Mutex::new(Vec::new());

fn list() -> std::sync::MutexGuard<'static, Vec<Arc<Drawable>>> {
    DRAWABLES.lock().unwrap_or_else(|e| e.into_inner())
}

/// Pbuffer ids have the top bits set, which X resource ids (29 bits) never
/// have: they cannot collide with windows or pixmaps.
pub const PBUFFER_ID_BASE: Xid = 0xE000_0000;

impl Drawable {
    fn new(dpy: *mut Display, id: Xid, kind: Kind, config: &'static FbConfig) -> Option<Arc<Drawable>> {
        let mut fb = Framebuffer::new(config.framebuffer_config());
        fb.set_double_buffered(config.double).ok()?;
        if let Kind::Pbuffer { width, height, .. } = kind {
            // A 0x0 pbuffer is legal; the framebuffer gets at least a pixel.
            fb.resize(width.max(1), height.max(1)).ok()?;
        }
        Some(Arc::new(Drawable { dpy: dpy as usize, id, kind, config, fb: SharedFramebuffer::new(fb), surface: Mutex::new(None), pacing: Default::default() }))
    }

    /// The drawable's size now: the X drawable's (None if it is gone), or
    /// the pbuffer's.
    pub unsafe fn size(&self) -> Option<(usize, usize)> {
        match self.kind {
            Kind::Pbuffer { width, height, .. } => Some((width.max(1), height.max(1))),
            _ => x_geometry(self.dpy as *mut Display, self.id),
        }
    }

    /// Resizes the framebuffer to `size` if it differs (contents are lost).
    pub fn follow_size(&self, (w, h): (usize, usize)) -> bool {
        let mut slot = self.fb.lock();
        if (slot.fb.width, slot.fb.height) == (w, h) {
            return true;
        }
        slot.last_user = 0;
        slot.fb.resize(w, h).is_ok()
    }

    /// Gives the framebuffer a back buffer (a double-buffered context).
    pub fn make_double(&self) -> bool {
        let mut slot = self.fb.lock();
        if slot.fb.is_double_buffered() {
            return true;
        }
        slot.last_user = 0;
        slot.fb.set_double_buffered(true).is_ok()
    }

    /// Makes the X surface frames are put into (windows and pixmaps).
    pub unsafe fn ensure_surface(&self) -> bool {
        if matches!(self.kind, Kind::Pbuffer { .. }) {
            return true;
        }
        let mut s = self.surface.lock().unwrap_or_else(|e| e.into_inner());
        if s.is_none() {
            // Images must have the drawable's own depth (a pixmap made with
            // another depth than the visual's would make XPutImage fail with
            // BadMatch): 24 and 32 share the 32-bit pixel layout; other
            // depths get no image (frames still reach SOFTGL_DUMP).
            let dpy = self.dpy as *mut Display;
            match x_geometry_depth(dpy, self.id) {
                Some((_, _, depth @ (24 | 32))) => *s = XSurface::new(dpy, self.id, depth, self.config.masks),
                Some(_) => return true,
                None => return false,
            }
        }
        s.is_some()
    }

    /// Shows `fb`'s front buffer in the X drawable.
    pub fn present(&self, fb: &Framebuffer) {
        if let Some(s) = self.surface.lock().unwrap_or_else(|e| e.into_inner()).as_mut() {
            s.put(fb);
        } else {
            crate::winsys::dump::frame(fb);
        }
    }

    /// glXSwapBuffers (section 3.3.10): the back buffer becomes the front
    /// one and is shown. Nothing happens on a single-buffered drawable or a
    /// pixmap.
    pub fn swap(&self) {
        if self.kind == Kind::Pixmap {
            return;
        }
        // Paced before the lock: contexts sharing the drawable go on.
        self.pacing.wait_for_slot();
        let mut slot = self.fb.lock();
        if !slot.fb.is_double_buffered() {
            return;
        }
        slot.fb.swap_buffers();
        if self.kind == Kind::Window {
            self.present(&slot.fb);
        }
    }
}

/// The size of an X drawable (XGetGeometry), or None (no such drawable,
/// no X).
pub unsafe fn x_geometry(dpy: *mut Display, d: Xid) -> Option<(usize, usize)> {
    x_geometry_depth(dpy, d).map(|(w, h, _)| (w, h))
}

/// The size and depth of an X drawable.
pub unsafe fn x_geometry_depth(dpy: *mut Display, d: Xid) -> Option<(usize, usize, c_int)> {
    if d & PBUFFER_ID_BASE == PBUFFER_ID_BASE || dpy.is_null() {
        return None; // a destroyed pbuffer: not an X id
    }
    let x = xlib()?;
    let (mut root, mut px, mut py, mut w, mut h, mut bw, mut depth): (Xid, c_int, c_int, c_uint, c_uint, c_uint, c_uint) = (0, 0, 0, 0, 0, 0, 0);
    // A bad drawable is BadDrawable: caught, so that the program's handler
    // (Xlib's default one exits) never sees an error softgl caused.
    let (ok, failed) = xlib::trap_errors(x, dpy, || (x.XGetGeometry)(dpy, d, &mut root, &mut px, &mut py, &mut w, &mut h, &mut bw, &mut depth));
    if ok == 0 || failed {
        return None;
    }
    Some(((w as usize).clamp(1, MAX_SIZE), (h as usize).clamp(1, MAX_SIZE), depth as c_int))
}

/// The record of drawable `id` on `dpy`.
pub fn find(dpy: *mut Display, id: Xid) -> Option<Arc<Drawable>> {
    list().iter().find(|d| d.dpy == dpy as usize && d.id == id).cloned()
}

/// The record of `id` for binding a context with `config`: the one made by
/// glXCreate*, or a new one for a plain X window that exists.
pub unsafe fn for_binding(dpy: *mut Display, id: Xid, config: &'static FbConfig) -> Option<Arc<Drawable>> {
    if let Some(d) = find(dpy, id) {
        return Some(d);
    }
    x_geometry(dpy, id)?;
    collect_destroyed(dpy);
    let d = Drawable::new(dpy, id, Kind::Window, config)?;
    list().push(d.clone());
    Some(d)
}

/// Forgets plain X windows that are gone and that no context is bound to.
unsafe fn collect_destroyed(dpy: *mut Display) {
    let candidates: Vec<Arc<Drawable>> = list().iter().filter(|d| d.dpy == dpy as usize && d.kind == Kind::Window && Arc::strong_count(d) == 1).cloned().collect();
    for d in candidates {
        if x_geometry(dpy, d.id).is_none() {
            list().retain(|e| !Arc::ptr_eq(e, &d));
        }
    }
}

/// Registers a drawable made by glXCreate*; replaces an older record of
/// the same id.
fn add(d: Arc<Drawable>) {
    let mut l = list();
    l.retain(|e| !(e.dpy == d.dpy && e.id == d.id));
    l.push(d);
}

/// glXDestroyWindow, glXDestroyPixmap, glXDestroyGLXPixmap,
/// glXDestroyPbuffer: the record goes (its buffers stay with contexts still
/// bound to it until they are released).
pub fn remove(dpy: *mut Display, id: Xid, kind_is: impl Fn(&Kind) -> bool) {
    list().retain(|d| !(d.dpy == dpy as usize && d.id == id && kind_is(&d.kind)));
}

/// Forgets every drawable of a display (it is being closed).
pub fn remove_display(dpy: *mut Display) {
    let gone: Vec<Arc<Drawable>> = {
        let mut l = list();
        let (gone, keep) = l.drain(..).partition(|d| d.dpy == dpy as usize);
        *l = keep;
        gone
    };
    drop(gone); // outside the list's lock: dropping surfaces talks to X
}

pub fn create_window(dpy: *mut Display, config: &'static FbConfig, win: Xid) -> Xid {
    match Drawable::new(dpy, win, Kind::Window, config) {
        Some(d) => {
            add(d);
            win
        }
        None => 0,
    }
}

pub fn create_pixmap(dpy: *mut Display, config: &'static FbConfig, pixmap: Xid) -> Xid {
    match Drawable::new(dpy, pixmap, Kind::Pixmap, config) {
        Some(d) => {
            add(d);
            pixmap
        }
        None => 0,
    }
}

pub fn create_pbuffer(dpy: *mut Display, config: &'static FbConfig, id: Xid, kind: Kind) -> Xid {
    match Drawable::new(dpy, id, kind, config) {
        Some(d) => {
            add(d);
            id
        }
        None => 0, // BadAlloc
    }
}
