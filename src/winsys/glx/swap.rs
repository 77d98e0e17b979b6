//! GLX swap extensions: GLX_EXT_swap_control, GLX_MESA_swap_control and
//! GLX_SGI_swap_control (the swap interval), and GLX_MESA_copy_sub_buffer.
//!
//! The swap interval is the least number of display refresh periods
//! between two buffer swaps of a drawable. softgl presents by copying
//! into the X window and sees no retrace, so the period is a clock of its
//! own: SOFTGL_REFRESH_HZ (60 unless set, 1 to 1000). With an interval of
//! N > 0, glXSwapBuffers waits until N periods have passed since the
//! drawable's previous swap; 0 swaps at once.
//!
//! The extensions say a new drawable's interval is 1, a statement about
//! hardware that syncs to the retrace anyway. softgl starts drawables at
//! 0 instead, so a program that never asks is not slowed to 60 frames a
//! second (Mesa's software drivers on an X server without DRI do not pace
//! either), and glXQueryDrawable(GLX_SWAP_INTERVAL_EXT) says 0: what is
//! reported is what happens.

use super::drawable::{self, Drawable, Kind};
use super::xlib::{self, Display, GlxError, Xid};
use std::ffi::{c_int, c_uint};
use std::sync::atomic::{AtomicU32, Ordering};
use std::sync::{Mutex, OnceLock};
use std::time::{Duration, Instant};

pub const GLX_SWAP_INTERVAL_EXT: c_int = 0x20F1;
pub const GLX_MAX_SWAP_INTERVAL_EXT: c_int = 0x20F2;
/// The largest interval accepted (larger ones are clamped to it, as
/// EXT_swap_control allows).
pub const MAX_INTERVAL: u32 = 60;

/// A drawable's swap interval and the time of its last swap.
#[derive(Default)]
pub struct Pacing {
    interval: AtomicU32,
    last: Mutex<Option<Instant>>,
}

impl Pacing {
    pub fn interval(&self) -> u32 {
        self.interval.load(Ordering::Relaxed)
    }

    pub fn set_interval(&self, n: u32) {
        self.interval.store(n.min(MAX_INTERVAL), Ordering::Relaxed);
    }

    /// Called at each swap: sleeps until `interval` periods have passed
    /// since the previous one, then records the swap.
    pub fn wait_for_slot(&self) {
        let n = self.interval();
        let mut last = self.last.lock().unwrap_or_else(|e| e.into_inner());
        if n > 0 {
            if let Some(prev) = *last {
                let due = prev + period() * n;
                let now = Instant::now();
                if due > now {
                    std::thread::sleep(due - now);
                }
            }
        }
        *last = Some(Instant::now());
    }
}

/// One refresh period of softgl's clock.
fn period() -> Duration {
    static HZ: OnceLock<u32> = OnceLock::new();
    let hz = *HZ.get_or_init(|| {
        std::env::var("SOFTGL_REFRESH_HZ").ok().and_then(|v| v.trim().parse().ok()).filter(|h| (1..=1000).contains(h)).unwrap_or(60)
    });
    Duration::from_secs(1) / hz
}

const GLX_BAD_CONTEXT: c_int = 5;
const GLX_BAD_VALUE: c_int = 6;

/// The drawable the calling thread's GLX context draws to, if any.
fn current_drawable() -> Option<std::sync::Arc<Drawable>> {
    let dpy = super::get_current_display();
    let id = super::get_current_drawable();
    if dpy.is_null() || id == 0 {
        return None;
    }
    drawable::find(dpy, id)
}

/// glXSwapIntervalEXT: sets `drawable`'s interval. BadValue for a
/// negative interval, GLXBadDrawable for a drawable softgl does not know.
pub unsafe fn swap_interval_ext(dpy: *mut Display, id: Xid, interval: c_int) {
    const X_GLX_CHANGE_DRAWABLE_ATTRIBUTES: u16 = 30;
    if interval < 0 {
        return xlib::report_error(dpy, GlxError::BadValue, X_GLX_CHANGE_DRAWABLE_ATTRIBUTES);
    }
    match drawable::find(dpy, id) {
        Some(d) => d.pacing.set_interval(interval as u32),
        None => xlib::report_error(dpy, GlxError::Glx(super::GLX_BAD_DRAWABLE_ERROR), X_GLX_CHANGE_DRAWABLE_ATTRIBUTES),
    }
}

/// glXSwapIntervalMESA: sets the current drawable's interval; 0 on
/// success, GLX_BAD_CONTEXT with no current context or drawable.
pub fn swap_interval_mesa(interval: c_uint) -> c_int {
    match current_drawable() {
        Some(d) => {
            d.pacing.set_interval(interval);
            0
        }
        None => GLX_BAD_CONTEXT,
    }
}

/// glXGetSwapIntervalMESA: the current drawable's interval, 0 without one.
pub fn get_swap_interval_mesa() -> c_int {
    current_drawable().map_or(0, |d| d.pacing.interval() as c_int)
}

/// glXSwapIntervalSGI: as MESA's, but 0 is GLX_BAD_VALUE (SGI_swap_control
/// has no way to turn pacing off).
pub fn swap_interval_sgi(interval: c_int) -> c_int {
    if interval <= 0 {
        return GLX_BAD_VALUE;
    }
    swap_interval_mesa(interval as c_uint)
}

/// glXQueryDrawable's answers for the swap attributes, None for others.
pub fn query(d: Option<&Drawable>, attrib: c_int) -> Option<c_uint> {
    match attrib {
        GLX_SWAP_INTERVAL_EXT => Some(d.map_or(0, |d| d.pacing.interval())),
        GLX_MAX_SWAP_INTERVAL_EXT => Some(MAX_INTERVAL),
        _ => None,
    }
}

/// glXCopySubBufferMESA: the back buffer's rectangle (x, y, width, height;
/// window coordinates, origin bottom left) is copied to the front buffer
/// and shown; the back buffer is unchanged. Nothing happens for a
/// single-buffered drawable, a pixmap or pbuffer, or while the current
/// context is between glBegin and glEnd; BadValue for a negative size.
pub unsafe fn copy_sub_buffer(dpy: *mut Display, id: Xid, x: c_int, y: c_int, width: c_int, height: c_int) {
    const X_GLX_VENDOR_PRIVATE: u16 = 16;
    if width < 0 || height < 0 {
        return xlib::report_error(dpy, GlxError::BadValue, X_GLX_VENDOR_PRIVATE);
    }
    if super::in_begin_end_on(id) {
        return;
    }
    let Some(d) = drawable::find(dpy, id) else {
        return xlib::report_error(dpy, GlxError::Glx(super::GLX_BAD_DRAWABLE_ERROR), X_GLX_VENDOR_PRIVATE);
    };
    if d.kind != Kind::Window {
        return;
    }
    let mut slot = d.fb.lock();
    if !slot.fb.is_double_buffered() {
        return;
    }
    slot.fb.copy_back_to_front(x as isize, y as isize, width as usize, height as usize);
    d.present(&slot.fb);
}
