//! GLX 1.4, client side, over Xlib (GLX 1.4 specification, sections 3.3
//! "Functions and errors"): contexts render in software into their own
//! [`Framebuffer`] and the image reaches the X drawable with XPutImage.
//! libX11 is loaded at run time ([`xlib`]); the X server needs no GLX
//! extension at all.
//!
//! What is offered: every TrueColor visual of depth 24 or 32 on the screen
//! whose channels are 8 bits wide, as two FBConfigs (single- and
//! double-buffered), each RGBA8 with depth 24, stencil 8, accumulation 16
//! per channel, no multisampling, window and pixmap drawables. What is
//! advertised is what the context's framebuffer gets.
//!
//! Invariants and limits of this first slice:
//! * A GLXWindow is the X window id, a GLXPixmap the X pixmap id.
//! * Double buffering: a double-buffered context renders into its one
//!   colour buffer and shows it at glXSwapBuffers only; glFlush/glFinish
//!   show nothing. GL_FRONT and GL_BACK are the same buffer (distinct
//!   front/back buffers are a later step). A single-buffered context (or
//!   any context drawing into a GLXPixmap) shows its image at glFlush,
//!   glFinish, glXWaitGL and when it stops being current.
//! * The framebuffer follows the drawable's size (XGetGeometry) at
//!   MakeCurrent and after each glXSwapBuffers; a resize clears it.
//! * Share lists are accepted and ignored; pbuffers, glXCopyContext,
//!   glXUseXFont and GLX events are not implemented (`todo` in the table).
//! * X visuals have no per-visual buffering in softgl: glXChooseVisual
//!   records, per visual, whether the program asked for double buffering,
//!   and glXGetConfig/glXCreateContext answer with that (double-buffered
//!   for a visual never chosen).
//!
//! Safety: the `unsafe fn`s are the bodies of the glX* entry points and
//! take the C caller's pointers as GLX 1.4 defines them (a live Display,
//! NULL or valid XVisualInfo/GLXFBConfig/GLXContext handles, writable
//! output pointers or NULL).
#![allow(clippy::missing_safety_doc)]

pub mod xlib;

use crate::api::types::*;
use crate::framebuffer::{Config, Framebuffer, Present, DEPTH_BITS, MAX_SIZE};
use crate::gl::Context;
use crate::winsys::current;
use std::cell::{Cell, RefCell};
use std::ffi::{c_char, c_int, c_uint, c_ulong, c_void};
use std::ptr::null_mut;
use std::rc::Rc;
use std::sync::Mutex;
use xlib::{xlib, Display, XImage, XVisualInfo, Xid};

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
    depth: c_int,
    masks: [c_ulong; 3],
    double: bool,
}

impl FbConfig {
    fn framebuffer_config(&self) -> Config {
        Config { depth_bits: DEPTH_BITS as u8, stencil_bits: 8, accum_bits: 16 }
    }

    /// glXGetFBConfigAttrib / glXGetConfig: None for an unknown attribute.
    fn attrib(&self, a: c_int) -> Option<c_int> {
        Some(match a {
            GLX_USE_GL | GLX_RGBA | GLX_X_RENDERABLE => 1,
            GLX_BUFFER_SIZE => 32,
            GLX_LEVEL | GLX_STEREO | GLX_AUX_BUFFERS => 0,
            GLX_DOUBLEBUFFER => self.double as c_int,
            GLX_RED_SIZE | GLX_GREEN_SIZE | GLX_BLUE_SIZE | GLX_ALPHA_SIZE => 8,
            GLX_DEPTH_SIZE => DEPTH_BITS as c_int,
            GLX_STENCIL_SIZE => 8,
            GLX_ACCUM_RED_SIZE | GLX_ACCUM_GREEN_SIZE | GLX_ACCUM_BLUE_SIZE | GLX_ACCUM_ALPHA_SIZE => 16,
            GLX_CONFIG_CAVEAT | GLX_TRANSPARENT_TYPE => GLX_NONE,
            GLX_TRANSPARENT_INDEX_VALUE..=GLX_TRANSPARENT_ALPHA_VALUE => 0,
            GLX_X_VISUAL_TYPE => GLX_TRUE_COLOR,
            GLX_VISUAL_ID => self.visualid as c_int,
            GLX_SCREEN => self.screen,
            GLX_DRAWABLE_TYPE => GLX_WINDOW_BIT | GLX_PIXMAP_BIT,
            GLX_RENDER_TYPE => GLX_RGBA_BIT,
            GLX_FBCONFIG_ID => self.id,
            GLX_MAX_PBUFFER_WIDTH | GLX_MAX_PBUFFER_HEIGHT | GLX_MAX_PBUFFER_PIXELS => 0,
            GLX_SAMPLE_BUFFERS | GLX_SAMPLES => 0,
            _ => return None,
        })
    }
}

/// The configs of each (display, screen), built on first use.
struct Screens {
    lists: Vec<(usize, c_int, Vec<&'static FbConfig>)>,
    /// Per (display, visual): double-buffered as glXChooseVisual was asked.
    visual_double: Vec<(usize, c_ulong, bool)>,
    /// GLXPixmaps (single-buffered drawables): (display, pixmap).
    pixmaps: Vec<(usize, Xid)>,
}

static SCREENS: Mutex<Screens> = Mutex::new(Screens { lists: Vec::new(), visual_double: Vec::new(), pixmaps: Vec::new() });

fn lock() -> std::sync::MutexGuard<'static, Screens> {
    SCREENS.lock().unwrap_or_else(|e| e.into_inner())
}

/// Whether a mask is 8 contiguous bits.
fn is_8bit(m: c_ulong) -> bool {
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
    found.sort_by_key(|v| v.depth); // stable: the server's order within a depth
    let mut list = Vec::new();
    for v in &found {
        for double in [false, true] {
            let c = FbConfig {
                screen,
                id: list.len() as c_int + 1,
                visualid: v.visualid,
                depth: v.depth,
                masks: [v.red_mask, v.green_mask, v.blue_mask],
                double,
            };
            list.push(&*Box::leak(Box::new(c)));
        }
    }
    s.lists.push((dpy as usize, screen, list.clone()));
    list
}

/// The config a visual stands for (glXChooseVisual's choice of buffering).
unsafe fn config_of_visual(dpy: *mut Display, vis: *const XVisualInfo) -> Option<&'static FbConfig> {
    if vis.is_null() {
        return None;
    }
    let v = &*vis;
    let list = configs(dpy, v.screen);
    let double = lock().visual_double.iter().find(|(d, id, _)| *d == dpy as usize && *id == v.visualid).is_none_or(|e| e.2);
    list.into_iter().find(|c| c.visualid == v.visualid && c.double == double)
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
/// No GLX extensions yet (in particular not GLX_ARB_create_context).
const EXTENSIONS: &[u8] = b"\0";

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

/// Reads an attribute list. `boolean` lists glXChooseVisual's attributes
/// that take no value.
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
    for c in configs(dpy, screen) {
        if want.iter().all(|&(a, v)| matches(c, a, v)) {
            let mut s = lock();
            s.visual_double.retain(|(d, id, _)| !(*d == dpy as usize && *id == c.visualid));
            s.visual_double.push((dpy as usize, c.visualid, double));
            drop(s);
            return visual_info(dpy, screen, c.visualid);
        }
    }
    null_mut()
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
    visual_info(dpy, (*config).screen, (*config).visualid)
}

// ---- drawables ----

pub fn create_window(_dpy: *mut Display, config: *const FbConfig, win: Xid, _attribs: *const c_int) -> Xid {
    if config.is_null() {
        return 0;
    }
    win
}

pub fn destroy_window(_dpy: *mut Display, _win: Xid) {}

pub fn create_pixmap(dpy: *mut Display, pixmap: Xid) -> Xid {
    if pixmap != 0 {
        let mut s = lock();
        if !s.pixmaps.contains(&(dpy as usize, pixmap)) {
            s.pixmaps.push((dpy as usize, pixmap));
        }
    }
    pixmap
}

/// glXCreatePixmap (no attributes are defined for it in GLX 1.4).
pub fn create_fb_pixmap(dpy: *mut Display, config: *const FbConfig, pixmap: Xid, _attribs: *const c_int) -> Xid {
    if config.is_null() {
        return 0;
    }
    create_pixmap(dpy, pixmap)
}

pub fn destroy_pixmap(dpy: *mut Display, pixmap: Xid) {
    lock().pixmaps.retain(|&p| p != (dpy as usize, pixmap));
}

fn is_pixmap(dpy: *mut Display, d: Xid) -> bool {
    lock().pixmaps.contains(&(dpy as usize, d))
}

/// The size of a drawable, or None (no such drawable, no X).
unsafe fn geometry(dpy: *mut Display, d: Xid) -> Option<(usize, usize)> {
    let x = xlib()?;
    let (mut root, mut px, mut py, mut w, mut h, mut bw, mut depth): (Xid, c_int, c_int, c_uint, c_uint, c_uint, c_uint) = (0, 0, 0, 0, 0, 0, 0);
    if (x.XGetGeometry)(dpy, d, &mut root, &mut px, &mut py, &mut w, &mut h, &mut bw, &mut depth) == 0 {
        return None;
    }
    Some(((w as usize).clamp(1, MAX_SIZE), (h as usize).clamp(1, MAX_SIZE)))
}

/// An X drawable as a place to put finished frames: XPutImage of the
/// framebuffer, rows flipped to X's top-down order, pixels in the visual's
/// channel masks.
pub struct XSurface {
    dpy: *mut Display,
    drawable: Xid,
    gc: xlib::Gc,
    depth: c_int,
    masks: [c_ulong; 3],
    pixels: Vec<u32>,
}

impl XSurface {
    unsafe fn new(dpy: *mut Display, drawable: Xid, config: &FbConfig) -> Option<XSurface> {
        let x = xlib()?;
        let gc = (x.XCreateGC)(dpy, drawable, 0, null_mut());
        if gc.is_null() {
            return None;
        }
        Some(XSurface { dpy, drawable, gc, depth: config.depth, masks: config.masks, pixels: Vec::new() })
    }

    fn put(&mut self, fb: &Framebuffer) {
        let Some(x) = xlib() else { return };
        let (w, h) = (fb.width, fb.height);
        if w == 0 || h == 0 {
            return;
        }
        let shift = |m: c_ulong| m.trailing_zeros();
        let [rs, gs, bs] = self.masks.map(shift);
        // On a depth-32 visual the bits outside R, G and B hold alpha.
        let rest = !(self.masks[0] | self.masks[1] | self.masks[2]) & 0xffff_ffff;
        let alpha = if self.depth == 32 && is_8bit(rest) { Some(shift(rest)) } else { None };
        self.pixels.clear();
        self.pixels.reserve(w * h);
        for y in (0..h).rev() {
            let row = &fb.color[fb.index(0, y)..fb.index(0, y) + w];
            for c in row {
                let mut p = ((c[0] as u32) << rs) | ((c[1] as u32) << gs) | ((c[2] as u32) << bs);
                if let Some(s) = alpha {
                    p |= (c[3] as u32) << s;
                }
                self.pixels.push(p);
            }
        }
        let mut img = XImage {
            width: w as c_int,
            height: h as c_int,
            xoffset: 0,
            format: xlib::ZPixmap,
            data: self.pixels.as_mut_ptr() as *mut c_char,
            byte_order: if cfg!(target_endian = "little") { xlib::LSBFirst } else { xlib::MSBFirst },
            bitmap_unit: 32,
            bitmap_bit_order: xlib::LSBFirst,
            bitmap_pad: 32,
            depth: self.depth,
            bytes_per_line: (w * 4) as c_int,
            bits_per_pixel: 32,
            red_mask: self.masks[0],
            green_mask: self.masks[1],
            blue_mask: self.masks[2],
            obdata: null_mut(),
            funcs: [null_mut(); 6],
        };
        // SAFETY: img describes self.pixels, which outlives the call; the
        // display and drawable were valid at MakeCurrent.
        unsafe {
            if (x.XInitImage)(&mut img) == 0 {
                return;
            }
            (x.XPutImage)(self.dpy, self.drawable, self.gc, &mut img, 0, 0, 0, 0, w as c_uint, h as c_uint);
            (x.XFlush)(self.dpy);
        }
    }
}

impl Drop for XSurface {
    fn drop(&mut self) {
        if let Some(x) = xlib() {
            // SAFETY: the GC was made on this display, which the program
            // must keep open while a context is bound to its drawables.
            unsafe { (x.XFreeGC)(self.dpy, self.gc) };
        }
    }
}

/// Presents at glFlush/glFinish (single-buffered drawables).
struct OnFlush(Rc<RefCell<XSurface>>);

impl Present for OnFlush {
    fn present(&mut self, fb: &Framebuffer) {
        self.0.borrow_mut().put(fb);
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
    /// The bound drawable, and whether it shows frames at SwapBuffers
    /// (double-buffered window) rather than at glFlush.
    surface: Option<(Rc<RefCell<XSurface>>, bool)>,
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
    Box::into_raw(Box::new(GlxContext { gl: Context::new(c.framebuffer_config()), config: *c, dpy, draw: 0, read: 0, surface: None }))
}

pub unsafe fn create_context(dpy: *mut Display, vis: *mut XVisualInfo, _share: *mut GlxContext, _direct: Bool) -> *mut GlxContext {
    new_context(dpy, config_of_visual(dpy, vis))
}

pub unsafe fn create_new_context(dpy: *mut Display, config: *const FbConfig, render_type: c_int, _share: *mut GlxContext, _direct: Bool) -> *mut GlxContext {
    if config.is_null() || render_type != GLX_RGBA_TYPE {
        return null_mut();
    }
    new_context(dpy, Some(&*config))
}

/// Unbinds `ctx` from its drawable, delivering a single-buffered image.
unsafe fn unbind(ctx: &mut GlxContext) {
    if let Some((_, false)) = &ctx.surface {
        ctx.gl.flush();
    }
    ctx.gl.surface = None;
    ctx.surface = None;
    ctx.draw = 0;
    ctx.read = 0;
}

fn release_current() {
    let cur = current_glx();
    if !cur.is_null() {
        // SAFETY: a current context is live: destroying it releases it first.
        unsafe { unbind(&mut *cur) };
    }
    CURRENT_GLX.with(|c| c.set(null_mut()));
    current::set_current(null_mut());
}

pub unsafe fn make_context_current(dpy: *mut Display, draw: Xid, read: Xid, ctx: *mut GlxContext) -> Bool {
    if ctx.is_null() {
        if draw != 0 || read != 0 {
            return 0; // BadMatch
        }
        release_current();
        return 1;
    }
    if draw == 0 || read == 0 || dpy.is_null() {
        return 0;
    }
    let c = &mut *ctx;
    let Some((w, h)) = geometry(dpy, draw) else { return 0 };
    // Reading from another drawable than the one drawn to is not supported
    // yet: both are the context's one framebuffer.
    let prev = current_glx();
    if !prev.is_null() {
        unbind(&mut *prev);
    }
    CURRENT_GLX.with(|cell| cell.set(null_mut()));
    current::set_current(null_mut());
    if c.gl.fb.resize(w, h).is_err() {
        return 0;
    }
    let Some(surface) = XSurface::new(dpy, draw, &c.config) else { return 0 };
    let surface = Rc::new(RefCell::new(surface));
    let double = c.config.double && !is_pixmap(dpy, draw);
    c.gl.surface = if double { None } else { Some(Box::new(OnFlush(surface.clone()))) };
    c.surface = Some((surface, double));
    c.dpy = dpy;
    c.draw = draw;
    c.read = read;
    c.gl.surface_resized(w as GLint, h as GLint);
    CURRENT_GLX.with(|cell| cell.set(ctx));
    current::set_current(&mut c.gl);
    1
}

pub unsafe fn make_current(dpy: *mut Display, draw: Xid, ctx: *mut GlxContext) -> Bool {
    make_context_current(dpy, draw, draw, ctx)
}

pub unsafe fn destroy_context(_dpy: *mut Display, ctx: *mut GlxContext) {
    if ctx.is_null() {
        return;
    }
    if current_glx() == ctx {
        release_current();
    }
    drop(Box::from_raw(ctx));
}

pub unsafe fn swap_buffers(dpy: *mut Display, drawable: Xid) {
    let cur = current_glx();
    if cur.is_null() {
        return;
    }
    let c = &mut *cur;
    if c.draw != drawable || c.dpy != dpy || c.gl.in_begin_end() {
        return;
    }
    let Some((surface, double)) = c.surface.clone() else { return };
    if !double {
        return; // no effect on a single-buffered drawable (section 3.3.10)
    }
    surface.borrow_mut().put(&c.gl.fb);
    // Follow a resize for the next frame.
    if let Some((w, h)) = geometry(dpy, drawable) {
        if (w, h) != (c.gl.fb.width, c.gl.fb.height) && c.gl.fb.resize(w, h).is_ok() {
            c.gl.surface_resized(w as GLint, h as GLint);
        }
    }
}

pub fn is_direct(_dpy: *mut Display, ctx: *mut GlxContext) -> Bool {
    (!ctx.is_null()) as Bool
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
            if let Some((_, false)) = &(*c).surface {
                (*c).gl.flush();
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
    if ctx.is_null() {
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

/// glXQueryDrawable: GLX_WIDTH and GLX_HEIGHT from the X drawable.
pub unsafe fn query_drawable(dpy: *mut Display, d: Xid, attrib: c_int, value: *mut c_uint) {
    if value.is_null() {
        return;
    }
    if let Some((w, h)) = geometry(dpy, d) {
        match attrib {
            GLX_WIDTH => *value = w as c_uint,
            GLX_HEIGHT => *value = h as c_uint,
            _ => {}
        }
    }
}
