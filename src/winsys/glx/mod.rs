//! GLX 1.4, client side, over Xlib (GLX 1.4 specification, sections 3.3
//! "Functions and errors"): contexts render in software into their
//! drawables' framebuffers ([`drawable`]) and the image reaches the X
//! drawable through MIT-SHM or XPutImage ([`present`]). libX11 and libXext
//! are loaded at run time ([`xlib`]); the X server needs no GLX extension
//! at all (with one, the errors GLX defines are numbered from its base).
//!
//! What is offered: for each of the depths 24 and 32 that has TrueColor
//! visuals with 8-bit channels, FBConfigs RGBA8 single- and
//! double-buffered with depth 24 and stencil 8; for depth 24 also RGB8
//! (ALPHA_SIZE 0) single- and double-buffered with depth and stencil, and
//! RGB8 double-buffered without depth or stencil; all with accumulation 16 per channel, no multisampling,
//! window, pixmap and pbuffer drawables. Single- and double-buffered
//! configs have their own visuals when the screen has two of that depth;
//! other visuals of the same format are accepted as the configs of their
//! depth. What is advertised is what the drawable's framebuffer gets (an
//! RGB framebuffer reads alpha as 1.0, see framebuffer::Config).
//! glXChooseFBConfig sorts by GLX 1.4 table 3.5, so a program that does
//! not ask for alpha gets an RGB config first. glXChooseVisual picks among
//! the RGBA configs only (see `choose_visual`). Contexts come from
//! glXCreateContext, glXCreateNewContext and glXCreateContextAttribsARB
//! (GLX_ARB_create_context and _profile: GL 1.0 to 1.5).
//!
//! Invariants and limits:
//! * A GLXWindow is the X window id, a GLXPixmap the X pixmap id.
//! * Drawables own their buffers, shared by every context bound to them
//!   (see [`drawable`] and winsys::bound); a read drawable other than the
//!   draw one is what glReadPixels, glCopyPixels and glCopyTexImage read.
//! * Double buffering: a double-buffered drawable keeps a front and a back
//!   buffer (see `framebuffer`); the window shows the front one.
//!   glXSwapBuffers copies back to front and shows it; glFlush, glFinish,
//!   glXWaitGL and releasing the context show the front buffer when it was
//!   drawn into (glDrawBuffer(GL_FRONT) or FRONT_AND_BACK). A
//!   single-buffered context shows its image at each of those.
//! * The framebuffer follows the drawable's size (XGetGeometry) at
//!   MakeCurrent and after each glXSwapBuffers; a resize clears it.
//! * glXDestroyContext of a current context (in any thread) is deferred
//!   until it is released, but its handle is invalid at once; making a
//!   context current that another thread holds fails with BadAccess. X
//!   errors softgl reports to the program's handler: bad context handles
//!   (GLXBadContext, checked against the live ones, [`handles`]), bad
//!   context attributes, configs, visuals and share lists, the errors of
//!   glXMakeCurrent/glXMakeContextCurrent (`bind`), and bad drawables in
//!   glXQueryDrawable, glXDestroyWindow and glXDestroyPbuffer.
//! * The share argument of glXCreateContext/glXCreateNewContext shares
//!   display lists, textures and buffer objects (gl::share), also between
//!   threads. glXCopyContext copies the groups glPushAttrib saves.
//!   glXSelectEvent's mask is stored and returned by glXGetSelectedEvent;
//!   softgl never generates GLX_PBUFFER_CLOBBER events (its drawables are
//!   never clobbered).
//! * glXUseXFont draws with softgl's built-in fonts (src/fonts), not the X
//!   font's glyphs: the one whose cell height is closest to the X font's
//!   ascent + descent (XQueryFont), or the default 16-pixel font when the
//!   font cannot be queried. Characters are taken as Latin-1, the usual X
//!   font encoding.
//! * Pbuffers are offscreen drawables with ids softgl makes (top bits set,
//!   never an X id); like windows, they own their pixels, which every
//!   context bound to them sees.
//! * A visual that two configs share (one visual of its depth on the
//!   screen, or a visual softgl did not hand out): glXChooseVisual
//!   records, per visual, whether the program asked for double buffering,
//!   and glXGetConfig/glXCreateContext answer with that (double-buffered
//!   for a visual never chosen).
//!
//! Safety: the `unsafe fn`s are the bodies of the glX* entry points and
//! take the C caller's pointers as GLX 1.4 defines them (a live Display,
//! NULL or valid XVisualInfo/GLXFBConfig/GLXContext handles, writable
//! output pointers or NULL).
#![allow(clippy::missing_safety_doc)]

pub mod drawable;
pub mod handles;
pub mod present;
pub mod swap;
pub mod xlib;

use crate::api::types::*;
use crate::framebuffer::{Config, Framebuffer, Present, DEPTH_BITS, MAX_SIZE};
use crate::gl::Context;
use crate::framebuffer::shared::Binding;
use crate::winsys::{bound, current};
use drawable::{Drawable, Kind, PBUFFER_ID_BASE};
use std::cell::Cell;
use std::ffi::{c_char, c_int, c_uint, c_ulong, c_void};
use std::ptr::null_mut;
use std::sync::atomic::{AtomicBool, Ordering};
use std::sync::{Arc, Mutex};
use xlib::{xlib, Display, XVisualInfo, Xid};

pub type Bool = c_int;

// GLX tokens (glx.h).
pub const GLX_USE_GL: c_int = 1;
pub const GLX_BUFFER_SIZE: c_int = 2;
pub const GLX_LEVEL: c_int = 3;
pub const GLX_RGBA: c_int = 4;
pub const GLX_DOUBLEBUFFER: c_int = 5;
pub const GLX_STEREO: c_int = 6;
pub const GLX_AUX_BUFFERS: c_int = 7;
pub const GLX_RED_SIZE: c_int = 8;
pub const GLX_GREEN_SIZE: c_int = 9;
pub const GLX_BLUE_SIZE: c_int = 10;
pub const GLX_ALPHA_SIZE: c_int = 11;
pub const GLX_DEPTH_SIZE: c_int = 12;
pub const GLX_STENCIL_SIZE: c_int = 13;
pub const GLX_ACCUM_RED_SIZE: c_int = 14;
pub const GLX_ACCUM_GREEN_SIZE: c_int = 15;
pub const GLX_ACCUM_BLUE_SIZE: c_int = 16;
pub const GLX_ACCUM_ALPHA_SIZE: c_int = 17;
pub const GLX_BAD_SCREEN: c_int = 1;
pub const GLX_BAD_ATTRIBUTE: c_int = 2;
pub const GLX_BAD_VISUAL: c_int = 4;
pub const GLX_BAD_CONTEXT: c_int = 5;
pub const GLX_VENDOR: c_int = 1;
pub const GLX_VERSION: c_int = 2;
pub const GLX_EXTENSIONS: c_int = 3;
pub const GLX_CONFIG_CAVEAT: c_int = 0x20;
pub const GLX_X_VISUAL_TYPE: c_int = 0x22;
pub const GLX_TRANSPARENT_TYPE: c_int = 0x23;
pub const GLX_TRANSPARENT_INDEX_VALUE: c_int = 0x24;
pub const GLX_TRANSPARENT_RED_VALUE: c_int = 0x25;
pub const GLX_TRANSPARENT_GREEN_VALUE: c_int = 0x26;
pub const GLX_TRANSPARENT_BLUE_VALUE: c_int = 0x27;
pub const GLX_TRANSPARENT_ALPHA_VALUE: c_int = 0x28;
pub const GLX_DONT_CARE: c_int = -1;
pub const GLX_NONE: c_int = 0x8000;
pub const GLX_TRUE_COLOR: c_int = 0x8002;
pub const GLX_VISUAL_ID: c_int = 0x800B;
pub const GLX_SCREEN: c_int = 0x800C;
pub const GLX_DRAWABLE_TYPE: c_int = 0x8010;
pub const GLX_RENDER_TYPE: c_int = 0x8011;
pub const GLX_X_RENDERABLE: c_int = 0x8012;
pub const GLX_FBCONFIG_ID: c_int = 0x8013;
pub const GLX_RGBA_TYPE: c_int = 0x8014;
pub const GLX_MAX_PBUFFER_WIDTH: c_int = 0x8016;
pub const GLX_MAX_PBUFFER_HEIGHT: c_int = 0x8017;
pub const GLX_MAX_PBUFFER_PIXELS: c_int = 0x8018;
pub const GLX_WIDTH: c_int = 0x801D;
pub const GLX_HEIGHT: c_int = 0x801E;
pub const GLX_WINDOW_BIT: c_int = 0x1;
pub const GLX_PIXMAP_BIT: c_int = 0x2;
pub const GLX_PBUFFER_BIT: c_int = 0x4;
pub const GLX_RGBA_BIT: c_int = 0x1;
pub const GLX_SAMPLE_BUFFERS: c_int = 100000;
pub const GLX_SAMPLES: c_int = 100001;

/// One FBConfig. Lives for the rest of the process (GLXFBConfig handles
/// are never freed by programs), so its address is a stable handle.
#[derive(Clone, Copy, Debug)]
pub struct FbConfig {
    screen: c_int,
    /// GLX_FBCONFIG_ID: 1-based, per screen.
    id: c_int,
    visualid: c_ulong,
    /// The visual's depth (24 or 32).
    depth: c_int,
    masks: [c_ulong; 3],
    double: bool,
    /// ALPHA_SIZE 8 (else 0: an RGB config, see framebuffer::Config).
    alpha: bool,
    /// DEPTH_SIZE 24 and STENCIL_SIZE 8 (else neither).
    depth_stencil: bool,
}

impl FbConfig {
    fn framebuffer_config(&self) -> Config {
        let zs = self.depth_stencil;
        Config {
            alpha_bits: if self.alpha { 8 } else { 0 },
            depth_bits: if zs { DEPTH_BITS as u8 } else { 0 },
            stencil_bits: if zs { 8 } else { 0 },
            accum_bits: 16,
        }
    }

    /// glXGetFBConfigAttrib / glXGetConfig: None for an unknown attribute.
    fn attrib(&self, a: c_int) -> Option<c_int> {
        Some(match a {
            GLX_USE_GL | GLX_RGBA | GLX_X_RENDERABLE => 1,
            GLX_BUFFER_SIZE => if self.alpha { 32 } else { 24 },
            GLX_LEVEL | GLX_STEREO | GLX_AUX_BUFFERS => 0,
            GLX_DOUBLEBUFFER => self.double as c_int,
            GLX_RED_SIZE | GLX_GREEN_SIZE | GLX_BLUE_SIZE => 8,
            GLX_ALPHA_SIZE => if self.alpha { 8 } else { 0 },
            GLX_DEPTH_SIZE => if self.depth_stencil { DEPTH_BITS as c_int } else { 0 },
            GLX_STENCIL_SIZE => if self.depth_stencil { 8 } else { 0 },
            GLX_ACCUM_RED_SIZE | GLX_ACCUM_GREEN_SIZE | GLX_ACCUM_BLUE_SIZE | GLX_ACCUM_ALPHA_SIZE => 16,
            GLX_CONFIG_CAVEAT | GLX_TRANSPARENT_TYPE => GLX_NONE,
            GLX_TRANSPARENT_INDEX_VALUE..=GLX_TRANSPARENT_ALPHA_VALUE => 0,
            GLX_X_VISUAL_TYPE => GLX_TRUE_COLOR,
            GLX_VISUAL_ID => self.visualid as c_int,
            GLX_SCREEN => self.screen,
            GLX_DRAWABLE_TYPE => GLX_WINDOW_BIT | GLX_PIXMAP_BIT | GLX_PBUFFER_BIT,
            GLX_RENDER_TYPE => GLX_RGBA_BIT,
            GLX_FBCONFIG_ID => self.id,
            GLX_MAX_PBUFFER_WIDTH | GLX_MAX_PBUFFER_HEIGHT => MAX_SIZE as c_int,
            GLX_MAX_PBUFFER_PIXELS => (MAX_SIZE * MAX_SIZE) as c_int,
            GLX_SAMPLE_BUFFERS | GLX_SAMPLES => 0,
            _ => return None,
        })
    }
}

/// The configs of each (display, screen), built on first use.
struct Screens {
    lists: Vec<(usize, c_int, Vec<&'static FbConfig>)>,
    /// Per (display, visual): the config id glXChooseVisual or
    /// glXGetVisualFromFBConfig last handed the visual out for.
    visual_config: Vec<(usize, c_ulong, c_int)>,
    /// glXSelectEvent masks: (display, drawable, mask).
    events: Vec<(usize, Xid, c_ulong)>,
    /// The next pbuffer's id (PBUFFER_ID_BASE + n).
    next_pbuffer: u32,
}


pub const GLX_PRESERVED_CONTENTS: c_int = 0x801B;
pub const GLX_LARGEST_PBUFFER: c_int = 0x801C;
pub const GLX_PBUFFER_HEIGHT: c_int = 0x8040;
pub const GLX_PBUFFER_WIDTH: c_int = 0x8041;

static SCREENS: Mutex<Screens> =
    Mutex::new(Screens { lists: Vec::new(), visual_config: Vec::new(), events: Vec::new(), next_pbuffer: 1 });

fn lock() -> std::sync::MutexGuard<'static, Screens> {
    SCREENS.lock().unwrap_or_else(|e| e.into_inner())
}

/// Whether a mask is 8 contiguous bits.
pub(crate) fn is_8bit(m: c_ulong) -> bool {
    m.count_ones() == 8 && (m >> m.trailing_zeros()) == 0xff
}

/// The configs of `screen`: TrueColor visuals of depth 24 first, then 32;
/// for each, single- then double-buffered (GLX 1.4 section 3.3.3's order).
unsafe fn configs(dpy: *mut Display, screen: c_int) -> Vec<&'static FbConfig> {
    let Some(x) = xlib() else { return Vec::new() };
    if dpy.is_null() || screen < 0 || screen >= (x.XScreenCount)(dpy) {
        return Vec::new();
    }
    let mut s = lock();
    if let Some((_, _, l)) = s.lists.iter().find(|(d, sc, _)| *d == dpy as usize && *sc == screen) {
        return l.clone();
    }
    let mut tmpl: XVisualInfo = std::mem::zeroed();
    tmpl.screen = screen;
    tmpl.class = xlib::TrueColor;
    let mut n = 0;
    let vis = (x.XGetVisualInfo)(dpy, xlib::VisualScreenMask | xlib::VisualClassMask, &mut tmpl, &mut n);
    let mut found: Vec<XVisualInfo> = Vec::new();
    if !vis.is_null() {
        for i in 0..n.max(0) as usize {
            let v = *vis.add(i);
            if (v.depth == 24 || v.depth == 32) && is_8bit(v.red_mask) && is_8bit(v.green_mask) && is_8bit(v.blue_mask) {
                found.push(v);
            }
        }
        (x.XFree)(vis as *mut c_void);
    }
    // The screen's default visual first within its depth (the one windows
    // are most often made with), then the server's order.
    let default_id = (x.XVisualIDFromVisual)((x.XDefaultVisual)(dpy, screen));
    found.sort_by_key(|v| (v.depth, v.visualid != default_id)); // stable
    let mut list = Vec::new();
    // RGBA configs first (ids 1-4 as before RGB configs existed), then RGB
    // ones: with depth and stencil (single, double), and a double-buffered
    // one without. glXChooseFBConfig/glXChooseVisual order them by the GLX
    // sort rules. Kinds are (alpha, depth_stencil, double).
    let groups: [&[(bool, bool, bool)]; 2] = [&[(true, true, false), (true, true, true)], &[(false, true, false), (false, true, true), (false, false, true)]];
    for group in groups {
        for depth in [24, 32] {
            let of_depth: Vec<&XVisualInfo> = found.iter().filter(|v| v.depth == depth).collect();
            let Some(&first) = of_depth.first() else { continue };
            // RGB configs only on depth 24: a config's GLX_BUFFER_SIZE may
            // not be below its visual's depth (piglit glx-fbconfig-sanity).
            if !group[0].0 && depth != 24 {
                continue;
            }
            // One visual per single/double pair when the server has two
            // (a server with GLX has hundreds): a plain X window's visual
            // then names its config, as glXQueryDrawable(GLX_FBCONFIG_ID)
            // and programs matching GLX_VISUAL_ID expect. Double-buffered
            // configs take the first visual. Configs sharing a visual are
            // told apart by `config_of_visual`.
            let single = of_depth.get(1).copied().unwrap_or(first);
            for &(alpha, depth_stencil, double) in group {
                let v = if double { first } else { single };
                let c = FbConfig {
                    screen,
                    id: list.len() as c_int + 1,
                    visualid: v.visualid,
                    depth,
                    masks: [v.red_mask, v.green_mask, v.blue_mask],
                    double,
                    alpha,
                    depth_stencil,
                };
                list.push(&*Box::leak(Box::new(c)));
            }
        }
    }
    s.lists.push((dpy as usize, screen, list.clone()));
    if !s.lists.iter().any(|(d, sc, _)| *d == dpy as usize && *sc != screen) {
        // The display's first use: forget it when it closes.
        drop(s);
        let codes = (x.XAddExtension)(dpy);
        if !codes.is_null() {
            (x.XESetCloseDisplay)(dpy, (*codes).extension, Some(display_closed));
        }
    }
    list
}

/// XCloseDisplay's hook: everything softgl keeps for the display goes
/// (drawables with their framebuffers, shared-memory segments and GCs,
/// configs, chosen visuals), so that a display opened later at the same
/// address starts afresh.
unsafe extern "C" fn display_closed(dpy: *mut Display, _codes: *mut xlib::XExtCodes) -> c_int {
    let _ = std::panic::catch_unwind(|| {
        drawable::remove_display(dpy);
        let mut s = lock();
        s.lists.retain(|(d, _, _)| *d != dpy as usize);
        s.visual_config.retain(|(d, _, _)| *d != dpy as usize);
        s.events.retain(|(d, _, _)| *d != dpy as usize);
    });
    0
}

/// The config a visual stands for (glXChooseVisual's choice of buffering).
unsafe fn config_of_visual(dpy: *mut Display, vis: *const XVisualInfo) -> Option<&'static FbConfig> {
    if vis.is_null() {
        return None;
    }
    let v = &*vis;
    let list = configs(dpy, v.screen);
    let mut of_visual: Vec<&'static FbConfig> = list.iter().copied().filter(|c| c.visualid == v.visualid).collect();
    if let [only] = of_visual[..] {
        return Some(only);
    }
    if of_visual.is_empty() {
        // Another visual of the same format (a program picking one
        // itself): it renders like the configs of its depth.
        let masks = [v.red_mask, v.green_mask, v.blue_mask];
        of_visual = list.into_iter().filter(|c| c.depth == v.depth && c.masks == masks && v.class == xlib::TrueColor).collect();
    }
    // Several configs stand for the visual: the one glXChooseVisual (or
    // glXGetVisualFromFBConfig) last handed it out for, else the
    // double-buffered RGBA one with depth and stencil.
    let chosen = lock().visual_config.iter().find(|(d, id, _)| *d == dpy as usize && *id == v.visualid).map(|e| e.2);
    let pick = of_visual.iter().copied().find(|c| Some(c.id) == chosen);
    pick.or_else(|| of_visual.into_iter().find(|c| c.double && c.alpha && c.depth_stencil))
}

/// A fresh XVisualInfo (the caller XFree's it) for a visual id.
unsafe fn visual_info(dpy: *mut Display, screen: c_int, visualid: c_ulong) -> *mut XVisualInfo {
    let Some(x) = xlib() else { return null_mut() };
    let mut tmpl: XVisualInfo = std::mem::zeroed();
    tmpl.visualid = visualid;
    tmpl.screen = screen;
    let mut n = 0;
    (x.XGetVisualInfo)(dpy, xlib::VisualIDMask | xlib::VisualScreenMask, &mut tmpl, &mut n)
}

// ---- queries ----

pub unsafe fn query_extension(dpy: *mut Display, error_base: *mut c_int, event_base: *mut c_int) -> Bool {
    let Some(x) = xlib() else { return 0 };
    if dpy.is_null() {
        return 0;
    }
    // The server's GLX bases if it has the extension (protocol errors and
    // events would come from there); softgl itself needs none.
    let (mut op, mut ev, mut er) = (0, 0, 0);
    if (x.XQueryExtension)(dpy, c"GLX".as_ptr(), &mut op, &mut ev, &mut er) == 0 {
        ev = 0;
        er = 0;
    }
    if !error_base.is_null() {
        *error_base = er;
    }
    if !event_base.is_null() {
        *event_base = ev;
    }
    1
}

pub unsafe fn query_version(dpy: *mut Display, major: *mut c_int, minor: *mut c_int) -> Bool {
    if dpy.is_null() || xlib().is_none() {
        return 0;
    }
    if !major.is_null() {
        *major = 1;
    }
    if !minor.is_null() {
        *minor = 4;
    }
    1
}

const VENDOR: &[u8] = b"softgl\0";
const VERSION: &[u8] = b"1.4 softgl\0";
/// The GLX extensions softgl implements.
const EXTENSIONS: &[u8] = b"GLX_ARB_create_context GLX_ARB_create_context_profile GLX_ARB_get_proc_address GLX_EXT_swap_control GLX_MESA_copy_sub_buffer GLX_MESA_swap_control GLX_SGI_swap_control\0";

fn string(name: c_int) -> *const c_char {
    match name {
        GLX_VENDOR => VENDOR.as_ptr() as *const c_char,
        GLX_VERSION => VERSION.as_ptr() as *const c_char,
        GLX_EXTENSIONS => EXTENSIONS.as_ptr() as *const c_char,
        _ => std::ptr::null(),
    }
}

pub fn query_extensions_string(_dpy: *mut Display, _screen: c_int) -> *const c_char {
    string(GLX_EXTENSIONS)
}

pub fn query_server_string(_dpy: *mut Display, _screen: c_int, name: c_int) -> *const c_char {
    string(name)
}

pub fn get_client_string(_dpy: *mut Display, name: c_int) -> *const c_char {
    string(name)
}

// ---- visuals and configs ----

/// Reads a None-terminated attribute list into (attribute, value) pairs.
/// With `visual_style` (glXChooseVisual), GLX_USE_GL, GLX_RGBA,
/// GLX_DOUBLEBUFFER and GLX_STEREO take no value and read as 1.
unsafe fn attribs(list: *const c_int, visual_style: bool) -> Option<Vec<(c_int, c_int)>> {
    let mut out = Vec::new();
    if list.is_null() {
        return Some(out);
    }
    let mut p = list;
    loop {
        let a = *p;
        if a == 0 {
            return Some(out);
        }
        if visual_style && matches!(a, GLX_USE_GL | GLX_RGBA | GLX_DOUBLEBUFFER | GLX_STEREO) {
            // GLX 1.4 section 3.3.2: these take no value in glXChooseVisual
            // (GLX_DOUBLEBUFFER and GLX_STEREO may in later practice; Mesa
            // treats them as booleans too).
            out.push((a, 1));
            p = p.add(1);
            continue;
        }
        let v = *p.add(1);
        out.push((a, v));
        p = p.add(2);
        if out.len() > 1000 {
            return None; // an unterminated list
        }
    }
}

/// Whether `c` satisfies one (attribute, value) request. An attribute
/// softgl does not know (an extension's: sRGB, bind-to-texture, ...) is
/// met when it asks for nothing (zero or GLX_DONT_CARE) and unmet
/// otherwise, so programs that list such attributes as False still get a
/// config.
fn matches(c: &FbConfig, a: c_int, v: c_int) -> bool {
    if v == GLX_DONT_CARE && a != GLX_LEVEL {
        return true;
    }
    let Some(have) = c.attrib(a) else { return v == 0 };
    match a {
        // Minimum criteria.
        GLX_BUFFER_SIZE | GLX_AUX_BUFFERS | GLX_RED_SIZE | GLX_GREEN_SIZE | GLX_BLUE_SIZE | GLX_ALPHA_SIZE | GLX_DEPTH_SIZE | GLX_STENCIL_SIZE
        | GLX_ACCUM_RED_SIZE | GLX_ACCUM_GREEN_SIZE | GLX_ACCUM_BLUE_SIZE | GLX_ACCUM_ALPHA_SIZE | GLX_SAMPLE_BUFFERS | GLX_SAMPLES => have >= v,
        // Mask criteria.
        GLX_DRAWABLE_TYPE | GLX_RENDER_TYPE => have & v == v,
        GLX_DOUBLEBUFFER | GLX_STEREO | GLX_X_RENDERABLE | GLX_RGBA | GLX_USE_GL => (have != 0) == (v != 0),
        // Exact.
        _ => have == v,
    }
}

pub unsafe fn choose_visual(dpy: *mut Display, screen: c_int, list: *mut c_int) -> *mut XVisualInfo {
    let Some(req) = attribs(list, true) else { return null_mut() };
    // Colour index is the default (section 3.3.2); softgl has only RGBA.
    if !req.iter().any(|&(a, _)| a == GLX_RGBA) {
        return null_mut();
    }
    let double = req.iter().any(|&(a, v)| a == GLX_DOUBLEBUFFER && v != 0);
    let mut want: Vec<(c_int, c_int)> = req.into_iter().filter(|&(a, _)| a != GLX_RGBA && a != GLX_USE_GL).collect();
    want.retain(|&(a, _)| a != GLX_DOUBLEBUFFER);
    want.push((GLX_DOUBLEBUFFER, double as c_int));
    // Only the RGBA configs with depth and stencil: the others share their
    // visuals, and a visual stands for the first config that has it
    // (piglit and programs look a visual's config up by GLX_VISUAL_ID).
    // Section 3.3.2 would prefer no alpha for GLX_ALPHA_SIZE 0, but the X
    // server has no spare visuals to give RGB configs their own; the RGB
    // configs are reached through glXChooseFBConfig.
    let Some(c) = configs(dpy, screen).into_iter().find(|c| c.alpha && c.depth_stencil && want.iter().all(|&(a, v)| matches(c, a, v))) else {
        return null_mut();
    };
    remember_visual(dpy, c);
    visual_info(dpy, screen, c.visualid)
}

/// Records which config a visual was handed out for (see `config_of_visual`).
fn remember_visual(dpy: *mut Display, c: &FbConfig) {
    let mut s = lock();
    s.visual_config.retain(|(d, id, _)| !(*d == dpy as usize && *id == c.visualid));
    s.visual_config.push((dpy as usize, c.visualid, c.id));
}

pub unsafe fn get_config(dpy: *mut Display, vis: *mut XVisualInfo, attrib: c_int, value: *mut c_int) -> c_int {
    if value.is_null() {
        return GLX_BAD_VALUE;
    }
    match config_of_visual(dpy, vis) {
        Some(c) => match c.attrib(attrib) {
            Some(v) => {
                *value = v;
                0
            }
            None => GLX_BAD_ATTRIBUTE,
        },
        // Section 3.3.1: a visual without GL support answers GLX_USE_GL with
        // False; anything else is GLX_BAD_VISUAL.
        None if attrib == GLX_USE_GL => {
            *value = 0;
            0
        }
        None => GLX_BAD_VISUAL,
    }
}
pub const GLX_BAD_VALUE: c_int = 6;

/// An array of configs the caller frees with XFree (it is malloc'ed).
unsafe fn config_array(list: &[&'static FbConfig], n: *mut c_int) -> *mut *const FbConfig {
    if !n.is_null() {
        *n = list.len() as c_int;
    }
    if list.is_empty() {
        return null_mut();
    }
    let p = libc::malloc(list.len() * std::mem::size_of::<*const FbConfig>()) as *mut *const FbConfig;
    if p.is_null() {
        if !n.is_null() {
            *n = 0;
        }
        return null_mut();
    }
    for (i, c) in list.iter().enumerate() {
        *p.add(i) = *c as *const FbConfig;
    }
    p
}

pub unsafe fn get_fb_configs(dpy: *mut Display, screen: c_int, n: *mut c_int) -> *mut *const FbConfig {
    config_array(&configs(dpy, screen), n)
}

pub unsafe fn choose_fb_config(dpy: *mut Display, screen: c_int, list: *const c_int, n: *mut c_int) -> *mut *const FbConfig {
    if !n.is_null() {
        *n = 0;
    }
    let Some(req) = attribs(list, false) else { return null_mut() };
    // Defaults that are not "don't care" (GLX 1.4 table 3.4).
    let mut want = vec![(GLX_RENDER_TYPE, GLX_RGBA_BIT), (GLX_DRAWABLE_TYPE, GLX_WINDOW_BIT), (GLX_LEVEL, 0)];
    for (a, v) in req {
        want.retain(|&(b, _)| b != a);
        want.push((a, v));
    }
    // GLX_FBCONFIG_ID given: every other attribute is ignored.
    if let Some(&(_, id)) = want.iter().find(|&&(a, v)| a == GLX_FBCONFIG_ID && v != GLX_DONT_CARE) {
        want = vec![(GLX_FBCONFIG_ID, id)];
    }
    let mut out = Vec::new();
    for c in configs(dpy, screen) {
        if want.iter().all(|&(a, v)| matches(c, a, v)) {
            out.push(c);
        }
    }
    // GLX 1.4 table 3.5's sort (caveat, visual type and samples are the
    // same for all of ours): more bits in the colour components asked for
    // (> 0 or GLX_DONT_CARE) first, then smaller GLX_BUFFER_SIZE (so an
    // RGB config comes before an RGBA one when alpha is not asked for),
    // single before double buffered, larger depth, smaller stencil, id.
    let asked = |a: c_int| want.iter().find(|&&(b, _)| b == a).map_or(0, |&(_, v)| v);
    let counted: Vec<c_int> =
        [GLX_RED_SIZE, GLX_GREEN_SIZE, GLX_BLUE_SIZE, GLX_ALPHA_SIZE].into_iter().filter(|&a| asked(a) > 0 || asked(a) == GLX_DONT_CARE).collect();
    let get = |c: &FbConfig, a: c_int| c.attrib(a).unwrap_or(0);
    out.sort_by_key(|c| {
        let color: c_int = counted.iter().map(|&a| get(c, a)).sum();
        (-color, get(c, GLX_BUFFER_SIZE), c.double, -get(c, GLX_DEPTH_SIZE), get(c, GLX_STENCIL_SIZE), c.id)
    });
    config_array(&out, n)
}

pub unsafe fn get_fb_config_attrib(_dpy: *mut Display, config: *const FbConfig, attrib: c_int, value: *mut c_int) -> c_int {
    if config.is_null() || value.is_null() {
        return GLX_BAD_VALUE;
    }
    match (*config).attrib(attrib) {
        Some(v) => {
            *value = v;
            0
        }
        None => GLX_BAD_ATTRIBUTE,
    }
}

pub unsafe fn get_visual_from_fb_config(dpy: *mut Display, config: *const FbConfig) -> *mut XVisualInfo {
    if config.is_null() {
        return null_mut();
    }
    // glXCreateContext with this visual then means this config.
    remember_visual(dpy, &*config);
    visual_info(dpy, (*config).screen, (*config).visualid)
}

// ---- drawables ----

pub unsafe fn create_window(dpy: *mut Display, config: *const FbConfig, win: Xid, _attribs: *const c_int) -> Xid {
    if config.is_null() || dpy.is_null() || win == 0 {
        return 0;
    }
    drawable::create_window(dpy, &*config, win)
}

/// glXDestroyWindow: GLXBadWindow when `win` is not a GLXWindow, or its X
/// window is gone (destroying the X window destroyed the GLXWindow).
pub unsafe fn destroy_window(dpy: *mut Display, win: Xid) {
    let alive = drawable::find(dpy, win).is_some_and(|d| d.kind == Kind::Window) && drawable::x_geometry(dpy, win).is_some();
    drawable::remove(dpy, win, |k| *k == Kind::Window);
    if !alive {
        xlib::report_error(dpy, xlib::GlxError::Glx(GLX_BAD_WINDOW_ERROR), X_GLX_DESTROY_WINDOW);
    }
}

/// GLX error numbers and requests for errors of drawables.
pub(crate) const GLX_BAD_DRAWABLE_ERROR: u8 = 2;
const GLX_BAD_PBUFFER_ERROR: u8 = 10;
const GLX_BAD_WINDOW_ERROR: u8 = 12;
const X_GLX_DESTROY_PBUFFER: u16 = 28;
const X_GLX_GET_DRAWABLE_ATTRIBUTES: u16 = 29;
const X_GLX_DESTROY_WINDOW: u16 = 32;

/// glXCreateGLXPixmap: a pixmap drawable with the visual's config.
pub unsafe fn create_glx_pixmap(dpy: *mut Display, vis: *mut XVisualInfo, pixmap: Xid) -> Xid {
    match config_of_visual(dpy, vis) {
        Some(c) if pixmap != 0 => drawable::create_pixmap(dpy, c, pixmap),
        _ => 0,
    }
}

/// glXCreatePixmap (no attributes are defined for it in GLX 1.4).
pub unsafe fn create_fb_pixmap(dpy: *mut Display, config: *const FbConfig, pixmap: Xid, _attribs: *const c_int) -> Xid {
    if config.is_null() || dpy.is_null() || pixmap == 0 {
        return 0;
    }
    drawable::create_pixmap(dpy, &*config, pixmap)
}

pub fn destroy_pixmap(dpy: *mut Display, pixmap: Xid) {
    drawable::remove(dpy, pixmap, |k| *k == Kind::Pixmap);
}

/// glXCreatePbuffer: GLX_PBUFFER_WIDTH/HEIGHT (default 0, as GLX 1.4
/// table 3.5 says), GLX_PRESERVED_CONTENTS and GLX_LARGEST_PBUFFER (stored
/// and reported; contents are always preserved). The config must offer
/// pbuffers (all do). None on a bad config, attribute or size.
pub unsafe fn create_pbuffer(dpy: *mut Display, config: *const FbConfig, attribs_list: *const c_int) -> Xid {
    if dpy.is_null() || config.is_null() {
        return 0;
    }
    let Some(req) = attribs(attribs_list, false) else { return 0 };
    let (mut w, mut h, mut preserved, mut largest) = (0i64, 0i64, true, false);
    for (a, v) in req {
        match a {
            GLX_PBUFFER_WIDTH => w = v as i64,
            GLX_PBUFFER_HEIGHT => h = v as i64,
            GLX_PRESERVED_CONTENTS => preserved = v != 0,
            GLX_LARGEST_PBUFFER => largest = v != 0,
            _ => return 0, // BadValue
        }
    }
    if w < 0 || h < 0 {
        return 0;
    }
    let max = MAX_SIZE as i64;
    if (w > max || h > max) && !largest {
        return 0; // BadAlloc
    }
    let id = {
        let mut s = lock();
        let id = PBUFFER_ID_BASE | (s.next_pbuffer as Xid & 0x0FFF_FFFF);
        s.next_pbuffer = s.next_pbuffer.wrapping_add(1).max(1);
        id
    };
    let kind = Kind::Pbuffer { width: w.min(max) as usize, height: h.min(max) as usize, preserved, largest };
    drawable::create_pbuffer(dpy, &*config, id, kind)
}

pub unsafe fn destroy_pbuffer(dpy: *mut Display, pbuf: Xid) {
    if !drawable::find(dpy, pbuf).is_some_and(|d| matches!(d.kind, Kind::Pbuffer { .. })) {
        return xlib::report_error(dpy, xlib::GlxError::Glx(GLX_BAD_PBUFFER_ERROR), X_GLX_DESTROY_PBUFFER);
    }
    drawable::remove(dpy, pbuf, |k| matches!(k, Kind::Pbuffer { .. }));
}

/// Presents at glFlush/glFinish (single-buffered drawables, or a drawn
/// front buffer).
struct OnFlush(Arc<Drawable>);

impl Present for OnFlush {
    fn present(&mut self, fb: &Framebuffer) {
        self.0.present(fb);
    }
}

// ---- contexts ----

/// What a GLXContext handle points to.
pub struct GlxContext {
    pub gl: Context,
    config: FbConfig,
    dpy: *mut Display,
    draw: Xid,
    read: Xid,
    /// The bound drawables (kept alive while bound, even if destroyed).
    bound_draw: Option<Arc<Drawable>>,
    bound_read: Option<Arc<Drawable>>,
    /// Current in some thread (GLX 1.4 section 3.3.7: a context is current
    /// in at most one thread).
    bound: AtomicBool,
    /// glXDestroyContext was called while it was current in another
    /// thread: it goes when that thread releases it.
    destroy_pending: AtomicBool,
}

thread_local! {
    static CURRENT_GLX: Cell<*mut GlxContext> = const { Cell::new(null_mut()) };
}

fn current_glx() -> *mut GlxContext {
    CURRENT_GLX.with(|c| c.get())
}

unsafe fn new_context(dpy: *mut Display, config: Option<&'static FbConfig>) -> *mut GlxContext {
    let Some(c) = config else { return null_mut() };
    if dpy.is_null() {
        return null_mut();
    }
    let mut gl = Context::new(c.framebuffer_config());
    gl.set_double_buffered(c.double);
    // Binned triangles stay pending across the primitives of one call (a
    // display list's glBegin/glEnd pairs: glxgears' gears are shaded as
    // one batch), never across calls: a drawable's framebuffer is in the
    // context only for the length of each call, and winsys/bound.rs shades
    // the batch before swapping it back out.
    gl.defer_render = true;
    let ctx = Box::into_raw(Box::new(GlxContext {
        gl,
        config: *c,
        dpy,
        draw: 0,
        read: 0,
        bound_draw: None,
        bound_read: None,
        bound: AtomicBool::new(false),
        destroy_pending: AtomicBool::new(false),
    }));
    handles::add(ctx);
    ctx
}

/// Joins a new context to `share`'s objects (display lists, textures,
/// buffer objects: gl::share) when `share` is not NULL.
unsafe fn with_share(ctx: *mut GlxContext, share: *mut GlxContext) -> *mut GlxContext {
    if !ctx.is_null() && !share.is_null() {
        crate::gl::share::join(&mut (*ctx).gl, &mut (*share).gl);
    }
    ctx
}

/// The share-list errors of context creation (GLX 1.4 section 3.3.7,
/// GLX_ARB_create_context): GLXBadContext for a handle that is neither
/// NULL nor a live context, BadMatch for a context of another screen. All
/// of softgl's contexts are direct and in this process, so no other
/// address-space mismatch exists.
fn check_share(share: *mut GlxContext, screen: c_int) -> Result<(), xlib::GlxError> {
    if share.is_null() {
        return Ok(());
    }
    if !handles::is_live(share) {
        return Err(xlib::GlxError::Glx(GLX_BAD_CONTEXT_ERROR));
    }
    // SAFETY: a live handle points to a context that is not freed.
    if unsafe { (*share).config.screen } != screen {
        return Err(xlib::GlxError::BadMatch);
    }
    Ok(())
}

/// glXCreateContext: BadValue for a visual softgl cannot render to; the
/// share-list errors of `check_share`.
pub unsafe fn create_context(dpy: *mut Display, vis: *mut XVisualInfo, share: *mut GlxContext, _direct: Bool) -> *mut GlxContext {
    const X_GLX_CREATE_CONTEXT: u16 = 3;
    let Some(config) = config_of_visual(dpy, vis) else {
        xlib::report_error(dpy, xlib::GlxError::BadValue, X_GLX_CREATE_CONTEXT);
        return null_mut();
    };
    if let Err(e) = check_share(share, config.screen) {
        xlib::report_error(dpy, e, X_GLX_CREATE_CONTEXT);
        return null_mut();
    }
    with_share(new_context(dpy, Some(config)), share)
}

/// glXCreateNewContext: GLXBadFBConfig for something that is not one of
/// softgl's configs, BadMatch for colour index (no config offers it),
/// BadValue for another render type.
pub unsafe fn create_new_context(dpy: *mut Display, config: *const FbConfig, render_type: c_int, share: *mut GlxContext, _direct: Bool) -> *mut GlxContext {
    const X_GLX_CREATE_NEW_CONTEXT: u16 = 24;
    let err = if config.is_null() || !is_config(config) {
        Some(xlib::GlxError::Glx(GLX_BAD_FBCONFIG_ERROR))
    } else if render_type == GLX_COLOR_INDEX_TYPE {
        Some(xlib::GlxError::BadMatch)
    } else if render_type != GLX_RGBA_TYPE {
        Some(xlib::GlxError::BadValue)
    } else {
        check_share(share, (*config).screen).err()
    };
    if let Some(e) = err {
        xlib::report_error(dpy, e, X_GLX_CREATE_NEW_CONTEXT);
        return null_mut();
    }
    with_share(new_context(dpy, Some(&*config)), share)
}

pub const GLX_CONTEXT_MAJOR_VERSION_ARB: c_int = 0x2091;
pub const GLX_CONTEXT_MINOR_VERSION_ARB: c_int = 0x2092;
pub const GLX_CONTEXT_FLAGS_ARB: c_int = 0x2094;
pub const GLX_CONTEXT_PROFILE_MASK_ARB: c_int = 0x9126;
pub const GLX_CONTEXT_DEBUG_BIT_ARB: c_int = 0x1;
pub const GLX_CONTEXT_FORWARD_COMPATIBLE_BIT_ARB: c_int = 0x2;
pub const GLX_CONTEXT_CORE_PROFILE_BIT_ARB: c_int = 0x1;
pub const GLX_CONTEXT_COMPATIBILITY_PROFILE_BIT_ARB: c_int = 0x2;
pub const GLX_COLOR_INDEX_TYPE: c_int = 0x8015;
/// GLX error numbers (from the extension's first error).
const GLX_BAD_CONTEXT_ERROR: u8 = 0;
const GLX_BAD_FBCONFIG_ERROR: u8 = 9;
const GLX_BAD_PROFILE_ARB_ERROR: u8 = 13;
/// X_GLXCreateContextAttribsARB, the request errors are reported for.
const X_GLX_CREATE_CONTEXT_ATTRIBS_ARB: u16 = 34;

/// Whether `c` is one of the configs softgl handed out.
fn is_config(c: *const FbConfig) -> bool {
    lock().lists.iter().any(|(_, _, l)| l.iter().any(|&k| std::ptr::eq(k, c)))
}

/// What glXCreateContextAttribsARB was asked for, checked.
fn check_context_attribs(req: &[(c_int, c_int)]) -> Result<(), xlib::GlxError> {
    use xlib::GlxError::*;
    let (mut major, mut minor, mut flags, mut profile, mut render) = (1, 0, 0, GLX_CONTEXT_CORE_PROFILE_BIT_ARB, GLX_RGBA_TYPE);
    for &(a, v) in req {
        match a {
            GLX_CONTEXT_MAJOR_VERSION_ARB => major = v,
            GLX_CONTEXT_MINOR_VERSION_ARB => minor = v,
            GLX_CONTEXT_FLAGS_ARB => flags = v,
            GLX_CONTEXT_PROFILE_MASK_ARB => profile = v,
            GLX_RENDER_TYPE => render = v,
            _ => return Err(BadValue), // not an attribute of the extension
        }
    }
    if flags & !(GLX_CONTEXT_DEBUG_BIT_ARB | GLX_CONTEXT_FORWARD_COMPATIBLE_BIT_ARB) != 0 {
        return Err(BadValue);
    }
    // Exactly one of the two profiles (checked whatever the version,
    // though the mask only matters from 3.2 on).
    if profile != GLX_CONTEXT_CORE_PROFILE_BIT_ARB && profile != GLX_CONTEXT_COMPATIBILITY_PROFILE_BIT_ARB {
        return Err(Glx(GLX_BAD_PROFILE_ARB_ERROR));
    }
    if render != GLX_RGBA_TYPE && render != GLX_COLOR_INDEX_TYPE {
        return Err(BadValue);
    }
    // OpenGL versions that exist; forward-compatible contexts exist from
    // 3.0 on (the extension's list of invalid combinations).
    let defined = match major {
        1 => (0..=5).contains(&minor),
        2 => (0..=1).contains(&minor),
        3 => (0..=3).contains(&minor),
        4 => (0..=6).contains(&minor),
        _ => false,
    };
    if !defined || (flags & GLX_CONTEXT_FORWARD_COMPATIBLE_BIT_ARB != 0 && major < 3) || (render == GLX_COLOR_INDEX_TYPE && major >= 3) {
        return Err(BadMatch);
    }
    // A defined version above softgl's 1.5, or colour index: no config
    // supports it.
    if major > 1 || render == GLX_COLOR_INDEX_TYPE {
        return Err(Glx(GLX_BAD_FBCONFIG_ERROR));
    }
    Ok(())
}

/// glXCreateContextAttribsARB (GLX_ARB_create_context and
/// GLX_ARB_create_context_profile): versions 1.0 to 1.5, the debug flag
/// (no effect) and either profile (which only versions from 3.2 on look
/// at). Anything else returns NULL with the error the extension names,
/// reported to the program's X error handler.
pub unsafe fn create_context_attribs(dpy: *mut Display, config: *const FbConfig, share: *mut GlxContext, _direct: Bool, list: *const c_int) -> *mut GlxContext {
    if dpy.is_null() {
        return null_mut();
    }
    let fail = |e| {
        xlib::report_error(dpy, e, X_GLX_CREATE_CONTEXT_ATTRIBS_ARB);
        null_mut()
    };
    if config.is_null() || !is_config(config) {
        return fail(xlib::GlxError::Glx(GLX_BAD_FBCONFIG_ERROR));
    }
    if let Err(e) = check_share(share, (*config).screen) {
        return fail(e);
    }
    let Some(req) = attribs(list, false) else { return fail(xlib::GlxError::BadValue) };
    if let Err(e) = check_context_attribs(&req) {
        return fail(e);
    }
    with_share(new_context(dpy, Some(&*config)), share)
}

/// Unbinds the calling thread's current context from its drawables,
/// delivering a single-buffered image (the implicit glFlush of section
/// 3.3.7), and frees it if its destruction was deferred.
fn release_current() {
    let cur = current_glx();
    CURRENT_GLX.with(|c| c.set(null_mut()));
    current::set_current(null_mut());
    if cur.is_null() {
        return;
    }
    // SAFETY: a current context is live: destroying it is deferred until
    // it is released.
    unsafe {
        let ctx = &mut *cur;
        if ctx.gl.surface.is_some() {
            bound::with_bound(&mut ctx.gl, |gl| gl.flush());
        }
        ctx.gl.surface = None;
        ctx.gl.bound = None;
        ctx.gl.read_fb = None;
        ctx.bound_draw = None;
        ctx.bound_read = None;
        ctx.draw = 0;
        ctx.read = 0;
        ctx.bound.store(false, Ordering::Release);
        if ctx.destroy_pending.load(Ordering::Acquire) {
            handles::remove(cur);
            drop(Box::from_raw(cur));
        }
    }
}

pub unsafe fn make_context_current(dpy: *mut Display, draw: Xid, read: Xid, ctx: *mut GlxContext) -> Bool {
    const X_GLX_MAKE_CONTEXT_CURRENT: u16 = 26;
    bind(dpy, draw, read, ctx, X_GLX_MAKE_CONTEXT_CURRENT)
}

pub unsafe fn make_current(dpy: *mut Display, draw: Xid, ctx: *mut GlxContext) -> Bool {
    const X_GLX_MAKE_CURRENT: u16 = 5;
    bind(dpy, draw, draw, ctx, X_GLX_MAKE_CURRENT)
}

/// glXMakeContextCurrent and glXMakeCurrent (`request` names which, for
/// errors).
///
/// Errors (GLX 1.4 section 3.3.7), reported to the program's X error
/// handler with False returned: BadMatch for a context with a None
/// drawable or NULL with a drawable, GLXBadContext for a bad handle,
/// GLXBadDrawable for a drawable that does not exist (any more),
/// BadAccess for a context current in another thread, BadAlloc when the
/// buffers cannot be had.
unsafe fn bind(dpy: *mut Display, draw: Xid, read: Xid, ctx: *mut GlxContext, request: u16) -> Bool {
    let fail = |e| {
        xlib::report_error(dpy, e, request);
        0
    };
    if ctx.is_null() {
        if draw != 0 || read != 0 {
            return fail(xlib::GlxError::BadMatch);
        }
        release_current();
        return 1;
    }
    if !handles::is_live(ctx) {
        // Destroyed (or never made). The calling thread's own current
        // context, destroyed but kept until released, may be bound again
        // where it already is (a no-op); anything else is GLXBadContext.
        let cur = current_glx();
        if cur == ctx && (*cur).dpy == dpy && (*cur).draw == draw && (*cur).read == read {
            return 1;
        }
        return fail(xlib::GlxError::Glx(GLX_BAD_CONTEXT_ERROR));
    }
    if dpy.is_null() {
        return 0;
    }
    if draw == 0 || read == 0 {
        return fail(xlib::GlxError::BadMatch);
    }
    let c = &mut *ctx;
    let config: &'static FbConfig = match configs(dpy, c.config.screen).into_iter().find(|f| f.id == c.config.id) {
        Some(f) => f,
        None => return 0,
    };
    let bad_drawable = xlib::GlxError::Glx(GLX_BAD_DRAWABLE_ERROR);
    let Some(d) = drawable::for_binding(dpy, draw, config) else { return fail(bad_drawable) };
    let r = if read == draw {
        d.clone()
    } else {
        match drawable::for_binding(dpy, read, config) {
            Some(r) => r,
            None => return fail(bad_drawable),
        }
    };
    let Some(size) = d.size() else { return fail(bad_drawable) };
    let read_size = if read == draw {
        None
    } else {
        match r.size() {
            Some(s) => Some(s),
            None => return fail(bad_drawable),
        }
    };
    let prev = current_glx();
    if prev == ctx && c.dpy == dpy && c.draw == draw && c.read == read {
        // Already bound here (freeglut rebinds before every callback): only
        // follow a resize.
        let ok = d.follow_size(size) && read_size.is_none_or(|s| r.follow_size(s));
        return if ok { 1 } else { fail(xlib::GlxError::BadAlloc) };
    }
    if prev != ctx && c.bound.load(Ordering::Acquire) {
        return fail(xlib::GlxError::BadAccess); // current in another thread
    }
    release_current();
    if !d.follow_size(size) || !read_size.is_none_or(|s| r.follow_size(s)) || (c.config.double && !d.make_double()) {
        return fail(xlib::GlxError::BadAlloc);
    }
    if !d.ensure_surface() {
        return fail(bad_drawable); // gone since it was looked at
    }
    c.gl.surface = if d.kind == Kind::Window || d.kind == Kind::Pixmap { Some(Box::new(OnFlush(d.clone()))) } else { None };
    c.gl.bound = Some(Binding { draw: d.fb.clone(), read: (read != draw).then(|| r.fb.clone()) });
    c.gl.read_fb = (read != draw).then(|| Framebuffer::new(c.config.framebuffer_config()));
    c.bound_draw = Some(d);
    c.bound_read = Some(r);
    c.dpy = dpy;
    c.draw = draw;
    c.read = read;
    c.gl.surface_resized(size.0 as GLint, size.1 as GLint);
    c.bound.store(true, Ordering::Release);
    CURRENT_GLX.with(|cell| cell.set(ctx));
    current::set_current(&mut c.gl);
    1
}


/// glXDestroyContext: GLXBadContext for a handle softgl never made or
/// has freed; destroying again a context that is destroyed but still
/// current does nothing (piglit glx-destroycontext-3), and so does NULL
/// (as in Mesa: cleanup code passes it, and Xlib's default error handler
/// would end the program).
pub unsafe fn destroy_context(dpy: *mut Display, ctx: *mut GlxContext) {
    const X_GLX_DESTROY_CONTEXT: u16 = 4;
    if ctx.is_null() {
        return;
    }
    match handles::state(ctx) {
        Some(handles::State::Live) => {}
        Some(_) => return,
        None => {
            xlib::report_error(dpy, xlib::GlxError::Glx(GLX_BAD_CONTEXT_ERROR), X_GLX_DESTROY_CONTEXT);
            return;
        }
    }
    // Section 3.3.7: a context current to any thread is destroyed when it
    // stops being current (it stays usable until then).
    if current_glx() == ctx || (*ctx).bound.load(Ordering::Acquire) {
        handles::mark_destroyed(ctx);
        (*ctx).destroy_pending.store(true, Ordering::Release);
    } else {
        handles::remove(ctx);
        drop(Box::from_raw(ctx));
    }
}

/// glXSwapBuffers (section 3.3.10): swaps the drawable's buffers, whichever
/// contexts are bound to it; then follows a window's resize for the next
/// frame. A drawable softgl has never bound has nothing to show.
pub unsafe fn swap_buffers(dpy: *mut Display, drawable: Xid) {
    if in_begin_end_on(drawable) {
        return;
    }
    let Some(d) = drawable::find(dpy, drawable) else { return };
    d.swap();
    if d.kind == Kind::Window {
        if let Some(size) = d.size() {
            d.follow_size(size);
        }
    }
    drop(d);
    crate::winsys::dump::exit_if_due();
}


/// Whether the calling thread's context draws to `drawable` and is between
/// glBegin and glEnd (swaps are ignored then).
pub fn in_begin_end_on(drawable: Xid) -> bool {
    let cur = current_glx();
    // SAFETY: the current context is live while it is current.
    !cur.is_null() && unsafe { (*cur).draw == drawable && (*cur).gl.in_begin_end() }
}

/// glXIsDirect: every softgl context is direct; GLXBadContext (and
/// False) for a handle that is not a live context.
// The display pointer is the C caller's, as for every GLX entry point.
#[allow(clippy::not_unsafe_ptr_arg_deref)]
pub fn is_direct(dpy: *mut Display, ctx: *mut GlxContext) -> Bool {
    const X_GLX_IS_DIRECT: u16 = 6;
    if !handles::is_live(ctx) {
        // SAFETY: report_error only reads the display.
        unsafe { xlib::report_error(dpy, xlib::GlxError::Glx(GLX_BAD_CONTEXT_ERROR), X_GLX_IS_DIRECT) };
        return 0;
    }
    1
}

pub fn get_current_context() -> *mut GlxContext {
    current_glx()
}

pub fn get_current_drawable() -> Xid {
    let c = current_glx();
    if c.is_null() {
        0
    } else {
        unsafe { (*c).draw }
    }
}

pub fn get_current_read_drawable() -> Xid {
    let c = current_glx();
    if c.is_null() {
        0
    } else {
        unsafe { (*c).read }
    }
}

pub fn get_current_display() -> *mut Display {
    let c = current_glx();
    if c.is_null() {
        null_mut()
    } else {
        unsafe { (*c).dpy }
    }
}

/// glXWaitGL: GL rendering is synchronous; a single-buffered image is
/// delivered as at glFinish.
pub fn wait_gl() {
    let c = current_glx();
    if !c.is_null() {
        unsafe {
            if (*c).gl.surface.is_some() {
                bound::with_bound(&mut (*c).gl, |gl| gl.flush());
            }
        }
    }
}

/// glXWaitX: X requests made so far reach the server before GL goes on.
pub fn wait_x() {
    let c = current_glx();
    if let (false, Some(x)) = (c.is_null(), xlib()) {
        unsafe { (x.XSync)((*c).dpy, 0) };
    }
}

/// glXQueryContext (GLX 1.4 section 3.3.7).
pub unsafe fn query_context(_dpy: *mut Display, ctx: *mut GlxContext, attrib: c_int, value: *mut c_int) -> c_int {
    if !handles::is_live(ctx) {
        return GLX_BAD_CONTEXT;
    }
    if value.is_null() {
        return GLX_BAD_VALUE;
    }
    let c = &(*ctx).config;
    *value = match attrib {
        GLX_FBCONFIG_ID => c.id,
        GLX_RENDER_TYPE => GLX_RGBA_TYPE,
        GLX_SCREEN => c.screen,
        _ => return GLX_BAD_ATTRIBUTE,
    };
    0
}

/// glXQueryDrawable: GLX_WIDTH and GLX_HEIGHT (of the X drawable, or the
/// pbuffer's as created); for pbuffers also GLX_PRESERVED_CONTENTS and
/// GLX_LARGEST_PBUFFER; GLX_FBCONFIG_ID for drawables softgl knows.
/// GLXBadDrawable for anything else.
pub unsafe fn query_drawable(dpy: *mut Display, d: Xid, attrib: c_int, value: *mut c_uint) {
    if value.is_null() {
        return;
    }
    let rec = drawable::find(dpy, d);
    if let Some(v) = swap::query(rec.as_deref(), attrib) {
        if rec.is_some() || drawable::x_geometry(dpy, d).is_some() {
            *value = v;
            return;
        }
    }
    if let Some(Kind::Pbuffer { width, height, preserved, largest }) = rec.as_ref().map(|r| r.kind) {
        match attrib {
            GLX_WIDTH => *value = width as c_uint,
            GLX_HEIGHT => *value = height as c_uint,
            GLX_PRESERVED_CONTENTS => *value = preserved as c_uint,
            GLX_LARGEST_PBUFFER => *value = largest as c_uint,
            GLX_FBCONFIG_ID => *value = rec.unwrap().config.id as c_uint,
            _ => {}
        }
        return;
    }
    let Some((w, h)) = drawable::x_geometry(dpy, d) else {
        return xlib::report_error(dpy, xlib::GlxError::Glx(GLX_BAD_DRAWABLE_ERROR), X_GLX_GET_DRAWABLE_ATTRIBUTES);
    };
    {
        match attrib {
            GLX_WIDTH => *value = w as c_uint,
            GLX_HEIGHT => *value = h as c_uint,
            GLX_FBCONFIG_ID => {
                if let Some(r) = rec {
                    *value = r.config.id as c_uint;
                }
            }
            _ => {}
        }
    }
}


/// glXCopyContext (GLX 1.4 section 3.3.7): the attribute groups of `mask`
/// (as glPushAttrib saves them, gl::attrib) from `src` to `dst`.
/// GLXBadContext when either is not a live context; nothing happens when
/// they are the same or `dst` is current in some thread (BadAccess, not
/// reported).
pub unsafe fn copy_context(dpy: *mut Display, src: *mut GlxContext, dst: *mut GlxContext, mask: c_ulong) {
    const X_GLX_COPY_CONTEXT: u16 = 10;
    if !handles::is_live(src) || !handles::is_live(dst) {
        xlib::report_error(dpy, xlib::GlxError::Glx(GLX_BAD_CONTEXT_ERROR), X_GLX_COPY_CONTEXT);
        return;
    }
    if src == dst || (*dst).bound.load(Ordering::Acquire) {
        return;
    }
    let saved = (*src).gl.save_attrib(mask as u32);
    (*dst).gl.restore_attrib(saved);
}

/// glXSelectEvent: the mask is kept per drawable (GLX_PBUFFER_CLOBBER_MASK
/// is the only event GLX 1.4 defines, and softgl's drawables are never
/// clobbered, so none is ever sent).
pub fn select_event(dpy: *mut Display, draw: Xid, mask: c_ulong) {
    if draw == 0 {
        return;
    }
    let mut s = lock();
    s.events.retain(|&(d, w, _)| !(d == dpy as usize && w == draw));
    if mask != 0 {
        s.events.push((dpy as usize, draw, mask));
    }
}

/// glXGetSelectedEvent: the mask glXSelectEvent stored (0 if none).
pub unsafe fn get_selected_event(dpy: *mut Display, draw: Xid, mask: *mut c_ulong) {
    if mask.is_null() {
        return;
    }
    *mask = lock().events.iter().find(|&&(d, w, _)| d == dpy as usize && w == draw).map_or(0, |e| e.2);
}

/// glXUseXFont (GLX 1.4 section 3.3.9): display lists list..list+count-1,
/// each a glBitmap of character first+i (see the module comment for the
/// font used). Nothing happens with no current context, inside glBegin/End
/// or while a list is being compiled, or for a negative count.
pub unsafe fn use_x_font(font: Xid, first: c_int, count: c_int, list: c_int) {
    let cur = current_glx();
    if cur.is_null() || first < 0 || count <= 0 || list <= 0 {
        return;
    }
    let dpy = (*cur).dpy;
    let mut height = 0;
    if let (Some(x), false) = (xlib(), dpy.is_null()) {
        let (fs, failed) = xlib::trap_errors(x, dpy, || (x.XQueryFont)(dpy, font));
        if !fs.is_null() {
            if !failed {
                height = ((*fs).ascent + (*fs).descent).clamp(0, 1024);
            }
            (x.XFreeFontInfo)(null_mut(), fs, 1);
        }
    }
    let f = crate::fonts::select(height, 0);
    crate::winsys::wgl::build_font_lists(&f, |c| c, first as u32, count as u32, list as u32);
}
