//! The WGL functions of Windows' opengl32.dll and the pixel-format
//! functions gdi32 forwards to it: on Windows over the program's window
//! DCs ([`super::gdi`]), and for programs written against wgl that run on
//! Linux, headless, over offscreen DCs.
//!
//! Device contexts: on Linux there is no GDI, so an HDC is an offscreen
//! surface of a given size that softgl makes: `softglCreateDC(w, h)`
//! (declared in include/GL/softgl_wgl.h, with `softglResizeDC`,
//! `softglDestroyDC`, `softglSelectFont` standing in for
//! CreateFont+SelectObject, and `softglGetDCImage` to read the last
//! presented frame). Handles are checked against the live ones, so a
//! stale or foreign HDC/HGLRC fails cleanly instead of being dereferenced.
//!
//! Pixel formats: two, both RGBA 8888 with depth 24, stencil 8 and
//! accumulation 16 per channel: 1 is double-buffered (PFD_SWAP_COPY), 2 is
//! single-buffered (also PFD_DRAW_TO_BITMAP | PFD_SUPPORT_GDI).
//! wglChoosePixelFormat picks by PFD_DOUBLEBUFFER alone: a request for
//! fewer (or no) depth, stencil or accumulation bits still gets them, as
//! the textbook programs need (seeds-inventory §4). SetPixelFormat fixes a
//! DC's format once; a second call with the same format succeeds, with
//! another fails.
//!
//! Contexts wrap [`crate::gl::Context`]; a context made current on a DC
//! renders into its own framebuffer of the DC's size (followed on resize
//! at MakeCurrent and after SwapBuffers; viewport and scissor are set from
//! it at the first MakeCurrent only). A double-buffered DC shows a frame
//! at wglSwapBuffers (the image stays in the back buffer: PFD_SWAP_COPY);
//! a single-buffered one at glFlush/glFinish, at SwapBuffers and when the
//! context stops being current. Showing a frame copies it into the DC's
//! front image and, with SOFTGL_DUMP=DIR, writes it as a PNG
//! ([`super::dump`]).
//!
//! Threads: a context is current in at most one thread; MakeCurrent of a
//! context current elsewhere fails, as does deleting it. Any failing
//! MakeCurrent leaves the thread with no current context (as Windows does).
//!
//! wglShareLists shares display lists, textures and buffer objects
//! (gl::share). wglCopyContext copies the attribute groups softgl keeps
//! (see [`copy_context`]); wglUseFontOutlines is not implemented.
#![allow(clippy::missing_safety_doc)]

use crate::api::types::*;
use crate::fonts::{self, CodePage, Font};
use crate::framebuffer::{Config, Framebuffer, Present, DEPTH_BITS, MAX_SIZE};
use crate::gl::Context;
use crate::winsys::{current, dump};
use std::cell::Cell;
use std::collections::HashSet;
use std::ffi::{c_int, c_void};
use std::ptr::null_mut;
use std::sync::atomic::{AtomicBool, Ordering};
use std::sync::{Arc, Mutex, MutexGuard};

pub type Bool = c_int;
pub type Hdc = *mut c_void;
pub type Hglrc = *mut c_void;

// PIXELFORMATDESCRIPTOR flags and types (wingdi.h).
pub const PFD_DOUBLEBUFFER: u32 = 0x1;
pub const PFD_STEREO: u32 = 0x2;
pub const PFD_DRAW_TO_WINDOW: u32 = 0x4;
pub const PFD_DRAW_TO_BITMAP: u32 = 0x8;
pub const PFD_SUPPORT_GDI: u32 = 0x10;
pub const PFD_SUPPORT_OPENGL: u32 = 0x20;
pub const PFD_SWAP_COPY: u32 = 0x400;
pub const PFD_DOUBLEBUFFER_DONTCARE: u32 = 0x4000_0000;
pub const PFD_TYPE_RGBA: u8 = 0;
pub const PFD_MAIN_PLANE: u8 = 0;

// CreateFont charsets (wingdi.h).
pub const ANSI_CHARSET: c_int = 0;
pub const DEFAULT_CHARSET: c_int = 1;
pub const RUSSIAN_CHARSET: c_int = 204;
/// FW_BOLD: the weight of Windows' System font, the default font of a DC.
pub const FW_BOLD: c_int = 700;

/// wingdi.h's PIXELFORMATDESCRIPTOR (40 bytes; DWORD is 32 bits).
#[repr(C)]
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct PixelFormatDescriptor {
    pub n_size: u16,
    pub n_version: u16,
    pub dw_flags: u32,
    pub i_pixel_type: u8,
    pub c_color_bits: u8,
    pub c_red_bits: u8,
    pub c_red_shift: u8,
    pub c_green_bits: u8,
    pub c_green_shift: u8,
    pub c_blue_bits: u8,
    pub c_blue_shift: u8,
    pub c_alpha_bits: u8,
    pub c_alpha_shift: u8,
    pub c_accum_bits: u8,
    pub c_accum_red_bits: u8,
    pub c_accum_green_bits: u8,
    pub c_accum_blue_bits: u8,
    pub c_accum_alpha_bits: u8,
    pub c_depth_bits: u8,
    pub c_stencil_bits: u8,
    pub c_aux_buffers: u8,
    pub i_layer_type: u8,
    pub b_reserved: u8,
    pub dw_layer_mask: u32,
    pub dw_visible_mask: u32,
    pub dw_damage_mask: u32,
}

/// Number of pixel formats.
pub const FORMATS: c_int = 2;

/// The descriptor of pixel format `i` (1-based).
pub fn describe(i: c_int) -> Option<PixelFormatDescriptor> {
    let flags = match i {
        1 => PFD_DRAW_TO_WINDOW | PFD_SUPPORT_OPENGL | PFD_DOUBLEBUFFER | PFD_SWAP_COPY,
        2 => PFD_DRAW_TO_WINDOW | PFD_DRAW_TO_BITMAP | PFD_SUPPORT_GDI | PFD_SUPPORT_OPENGL,
        _ => return None,
    };
    Some(PixelFormatDescriptor {
        n_size: std::mem::size_of::<PixelFormatDescriptor>() as u16,
        n_version: 1,
        dw_flags: flags,
        i_pixel_type: PFD_TYPE_RGBA,
        c_color_bits: 32,
        c_red_bits: 8,
        c_red_shift: 0,
        c_green_bits: 8,
        c_green_shift: 8,
        c_blue_bits: 8,
        c_blue_shift: 16,
        c_alpha_bits: 8,
        c_alpha_shift: 24,
        c_accum_bits: 64,
        c_accum_red_bits: 16,
        c_accum_green_bits: 16,
        c_accum_blue_bits: 16,
        c_accum_alpha_bits: 16,
        c_depth_bits: DEPTH_BITS as u8,
        c_stencil_bits: 8,
        c_aux_buffers: 0,
        i_layer_type: PFD_MAIN_PLANE,
        ..Default::default()
    })
}

fn is_double(format: c_int) -> bool {
    format == 1
}

/// wglChoosePixelFormat: the format closest to the request. Only
/// PFD_DOUBLEBUFFER decides (single-buffered when asked for without
/// PFD_DOUBLEBUFFER_DONTCARE); every bit count is met or exceeded except
/// requests beyond what softgl has (more than 8 bits per colour channel,
/// 24 depth, 8 stencil, 16 per accumulation channel), which get the most
/// it has. nSize and nVersion are not checked (programs zero them).
pub unsafe fn choose_pixel_format(_hdc: Hdc, pfd: *const PixelFormatDescriptor) -> c_int {
    if pfd.is_null() {
        return 0;
    }
    let p = pfd.read_unaligned();
    if p.dw_flags & PFD_DOUBLEBUFFER != 0 || p.dw_flags & PFD_DOUBLEBUFFER_DONTCARE != 0 {
        1
    } else {
        2
    }
}

/// wglDescribePixelFormat: the number of formats; fills up to `bytes`
/// bytes of `pfd` when it is not NULL. 0 for a format that does not exist.
pub unsafe fn describe_pixel_format(_hdc: Hdc, format: c_int, bytes: u32, pfd: *mut PixelFormatDescriptor) -> c_int {
    if pfd.is_null() {
        return FORMATS;
    }
    let Some(d) = describe(format) else { return 0 };
    let n = (bytes as usize).min(std::mem::size_of::<PixelFormatDescriptor>());
    std::ptr::copy_nonoverlapping(&d as *const _ as *const u8, pfd as *mut u8, n);
    FORMATS
}

// ---- device contexts ----

/// What a DC holds: its size, pixel format, selected font and the last
/// frame shown on it.
pub struct DcState {
    pub width: usize,
    pub height: usize,
    /// 0 until SetPixelFormat.
    pub pixel_format: c_int,
    /// CreateFont-style (height, weight, charset) of the selected font.
    pub font: (c_int, c_int, c_int),
    /// The shown image, RGBA8, rows bottom-up, front_size pixels.
    pub front: Vec<[u8; 4]>,
    pub front_size: (usize, usize),
    /// Frames shown so far.
    pub frames: u64,
    /// Windows: the real DC frames are also drawn into (0: softgl's own
    /// offscreen DC).
    pub native: usize,
}

impl DcState {
    /// A black DC of w x h pixels with no pixel format and the System font
    /// (16 pixels, bold) selected.
    pub fn new(w: usize, h: usize, native: usize) -> DcState {
        DcState { width: w, height: h, pixel_format: 0, font: (16, FW_BOLD, DEFAULT_CHARSET), front: vec![[0, 0, 0, 255]; w * h], front_size: (w, h), frames: 0, native }
    }

    fn show(&mut self, fb: &Framebuffer) {
        let n = fb.width * fb.height;
        self.front.clear();
        self.front.extend_from_slice(&fb.front()[..n]);
        // The frame's size: the DC may have been resized since the context
        // last followed it.
        self.front_size = (fb.width, fb.height);
        self.frames += 1;
        #[cfg(windows)]
        if self.native != 0 {
            super::gdi::blit(self.native, &self.front, fb.width, fb.height);
        }
        dump::frame(fb);
    }
}

pub struct Dc {
    pub state: Arc<Mutex<DcState>>,
}

fn lock_dc(s: &Mutex<DcState>) -> MutexGuard<'_, DcState> {
    s.lock().unwrap_or_else(|e| e.into_inner())
}

/// Live handles (addresses of boxed Dc / WglContext).
static DCS: Mutex<Option<HashSet<usize>>> = Mutex::new(None);
static CONTEXTS: Mutex<Option<HashSet<usize>>> = Mutex::new(None);

fn live(set: &Mutex<Option<HashSet<usize>>>, h: usize) -> bool {
    h != 0 && set.lock().unwrap_or_else(|e| e.into_inner()).as_ref().is_some_and(|s| s.contains(&h))
}

fn register(set: &Mutex<Option<HashSet<usize>>>, h: usize, add: bool) -> bool {
    let mut g = set.lock().unwrap_or_else(|e| e.into_inner());
    let s = g.get_or_insert_with(HashSet::new);
    if add {
        s.insert(h)
    } else {
        s.remove(&h)
    }
}

/// The DC a handle names, if it is live: one of softglCreateDC's, or on
/// Windows a real DC ([`super::gdi`]).
fn dc(hdc: Hdc) -> Option<&'static Dc> {
    if live(&DCS, hdc as usize) {
        // SAFETY: live handles are boxed Dcs that stay allocated until
        // softglDestroyDC removes them from the set (under the same check).
        return Some(unsafe { &*(hdc as *const Dc) });
    }
    #[cfg(windows)]
    return super::gdi::native_dc(hdc);
    #[cfg(not(windows))]
    None
}

/// softglCreateDC: an offscreen device context of width x height pixels
/// (each clamped to 1..=16384), black, with no pixel format yet and the
/// System font (16 pixels, bold) selected.
pub fn create_dc(width: c_int, height: c_int) -> Hdc {
    if width < 1 || height < 1 || width as usize > MAX_SIZE || height as usize > MAX_SIZE {
        return null_mut();
    }
    let state = DcState::new(width as usize, height as usize, 0);
    let p = Box::into_raw(Box::new(Dc { state: Arc::new(Mutex::new(state)) }));
    register(&DCS, p as usize, true);
    p as Hdc
}

/// softglDestroyDC. Contexts bound to the DC keep drawing into their own
/// framebuffers; their frames go nowhere (but SOFTGL_DUMP) from now on.
pub unsafe fn destroy_dc(hdc: Hdc) -> Bool {
    if !register(&DCS, hdc as usize, false) {
        return 0;
    }
    drop(Box::from_raw(hdc as *mut Dc));
    1
}

/// softglResizeDC: the window was resized. Contexts follow at their next
/// MakeCurrent or SwapBuffers.
pub fn resize_dc(hdc: Hdc, width: c_int, height: c_int) -> Bool {
    let Some(d) = dc(hdc) else { return 0 };
    if width < 1 || height < 1 || width as usize > MAX_SIZE || height as usize > MAX_SIZE {
        return 0;
    }
    let mut s = lock_dc(&d.state);
    s.width = width as usize;
    s.height = height as usize;
    1
}

/// softglSelectFont: what CreateFont + SelectObject would select, for
/// wglUseFontBitmaps. height: as CreateFont's nHeight (0: 16); weight:
/// 0..1000 (FW_BOLD = 700); charset: RUSSIAN_CHARSET (204) reads bytes as
/// code page 1251, ANSI_CHARSET (0) and DEFAULT_CHARSET (1) as the
/// process's ANSI code page (see [`ansi_code_page`]), anything else as 1252.
pub fn select_font(hdc: Hdc, height: c_int, weight: c_int, charset: c_int) -> Bool {
    let Some(d) = dc(hdc) else { return 0 };
    lock_dc(&d.state).font = (height, weight, charset);
    1
}

/// softglGetDCImage: the last frame shown on the DC (RGBA8, rows bottom-up,
/// width x height), valid until the next frame is shown on it or it is
/// resized or destroyed.
pub unsafe fn dc_image(hdc: Hdc, width: *mut c_int, height: *mut c_int) -> *const u8 {
    let Some(d) = dc(hdc) else { return std::ptr::null() };
    let s = lock_dc(&d.state);
    let (w, h) = s.front_size;
    if !width.is_null() {
        *width = w as c_int;
    }
    if !height.is_null() {
        *height = h as c_int;
    }
    s.front.as_ptr() as *const u8
}

/// The ANSI code page: 1251 (Russian Windows, where the textbook's
/// programs come from) unless SOFTGL_CODEPAGE=1252.
pub fn ansi_code_page() -> CodePage {
    match std::env::var("SOFTGL_CODEPAGE").as_deref() {
        Ok("1252") => CodePage::Cp1252,
        _ => CodePage::Cp1251,
    }
}

fn code_page(charset: c_int) -> CodePage {
    match charset {
        RUSSIAN_CHARSET => CodePage::Cp1251,
        ANSI_CHARSET | DEFAULT_CHARSET => ansi_code_page(),
        _ => CodePage::Cp1252,
    }
}

pub fn set_pixel_format(hdc: Hdc, format: c_int, _pfd: *const PixelFormatDescriptor) -> Bool {
    let Some(d) = dc(hdc) else { return 0 };
    if describe(format).is_none() {
        return 0;
    }
    let mut s = lock_dc(&d.state);
    if s.pixel_format != 0 && s.pixel_format != format {
        return 0;
    }
    s.pixel_format = format;
    1
}

pub fn get_pixel_format(hdc: Hdc) -> c_int {
    dc(hdc).map_or(0, |d| lock_dc(&d.state).pixel_format)
}

// ---- contexts ----

/// What an HGLRC points to.
pub struct WglContext {
    pub gl: Context,
    pixel_format: c_int,
    /// The DC it is current on (handle and state).
    dc: Option<(Hdc, Arc<Mutex<DcState>>)>,
    /// Current in some thread.
    bound: AtomicBool,
}

/// Shows frames at glFlush/glFinish (single-buffered formats).
struct OnFlush(Arc<Mutex<DcState>>);

impl Present for OnFlush {
    fn present(&mut self, fb: &Framebuffer) {
        lock_dc(&self.0).show(fb);
    }
}

thread_local! {
    static CURRENT_WGL: Cell<*mut WglContext> = const { Cell::new(null_mut()) };
}

fn current_wgl() -> *mut WglContext {
    CURRENT_WGL.with(|c| c.get())
}

fn context(h: Hglrc) -> Option<*mut WglContext> {
    live(&CONTEXTS, h as usize).then_some(h as *mut WglContext)
}

pub fn create_context(hdc: Hdc) -> Hglrc {
    let Some(d) = dc(hdc) else { return null_mut() };
    let format = lock_dc(&d.state).pixel_format;
    // A window's DC whose format gdi32 set without softgl (Wine).
    #[cfg(windows)]
    let format = if format == 0 && lock_dc(&d.state).native != 0 { super::gdi::format_from_gdi(hdc) } else { format };
    if format == 0 {
        return null_mut(); // Windows: ERROR_INVALID_PIXEL_FORMAT
    }
    let config = Config { alpha_bits: 8, depth_bits: DEPTH_BITS as u8, stencil_bits: 8, accum_bits: 16 };
    let mut gl = Context::new(config);
    gl.set_double_buffered(is_double(format));
    gl.defer_render = true;
    let p = Box::into_raw(Box::new(WglContext { gl, pixel_format: format, dc: None, bound: AtomicBool::new(false) }));
    register(&CONTEXTS, p as usize, true);
    p as Hglrc
}

/// Releases the calling thread's current context, showing a
/// single-buffered image first (the implicit flush).
fn release_current() {
    let cur = current_wgl();
    CURRENT_WGL.with(|c| c.set(null_mut()));
    current::set_current(null_mut());
    if cur.is_null() {
        return;
    }
    // SAFETY: a current context is live: deleting it releases it first.
    let c = unsafe { &mut *cur };
    // Single-buffered, or a double-buffered front buffer drawn into.
    c.gl.flush();
    c.gl.surface = None;
    c.dc = None;
    c.bound.store(false, Ordering::Release);
}

/// Resizes the context's framebuffer to the DC's size if it differs.
fn follow_size(c: &mut WglContext, w: usize, h: usize) -> bool {
    let fb = c.gl.window_fb_mut();
    if (w, h) != (fb.width, fb.height) {
        if fb.resize(w, h).is_err() {
            return false;
        }
        c.gl.surface_resized(w as GLint, h as GLint);
    }
    true
}

pub fn make_current(hdc: Hdc, hglrc: Hglrc) -> Bool {
    if hglrc.is_null() {
        // The DC is ignored (also NULL, and before any context exists).
        release_current();
        return 1;
    }
    let (Some(ctx), Some(d)) = (context(hglrc), dc(hdc)) else {
        release_current();
        return 0;
    };
    // SAFETY: live handle.
    let c = unsafe { &mut *ctx };
    let (w, h, format) = {
        let s = lock_dc(&d.state);
        (s.width, s.height, s.pixel_format)
    };
    if format != c.pixel_format {
        release_current();
        return 0;
    }
    if current_wgl() == ctx && c.dc.as_ref().is_some_and(|(h, _)| *h == hdc) {
        // Rebinding what is bound (the textbook programs do it every paint).
        return follow_size(c, w, h) as Bool;
    }
    if current_wgl() != ctx && c.bound.load(Ordering::Acquire) {
        release_current();
        return 0; // ERROR_BUSY: current in another thread
    }
    release_current();
    if c.gl.window_fb_mut().resize(w, h).is_err() {
        return 0;
    }
    // glFlush shows the front buffer (single-buffered, or drawn with
    // glDrawBuffer(GL_FRONT)); SwapBuffers the back one.
    c.gl.surface = Some(Box::new(OnFlush(d.state.clone())));
    c.dc = Some((hdc, d.state.clone()));
    c.gl.surface_resized(w as GLint, h as GLint);
    c.bound.store(true, Ordering::Release);
    CURRENT_WGL.with(|cell| cell.set(ctx));
    current::set_current(&mut c.gl);
    1
}

pub unsafe fn delete_context(hglrc: Hglrc) -> Bool {
    let Some(ctx) = context(hglrc) else { return 0 };
    if current_wgl() == ctx {
        release_current();
    } else if (*ctx).bound.load(Ordering::Acquire) {
        return 0; // current in another thread
    }
    if !register(&CONTEXTS, ctx as usize, false) {
        return 0;
    }
    drop(Box::from_raw(ctx));
    1
}

pub fn get_current_context() -> Hglrc {
    current_wgl() as Hglrc
}

pub fn get_current_dc() -> Hdc {
    let c = current_wgl();
    if c.is_null() {
        return null_mut();
    }
    // SAFETY: current contexts are live.
    unsafe { (*c).dc.as_ref().map_or(null_mut(), |(h, _)| *h) }
}

/// wglSwapBuffers: shows the frame of the calling thread's current
/// context if it is current on `hdc`, then follows a DC resize. A valid DC
/// with no context current on it here: TRUE, nothing shown.
pub fn swap_buffers(hdc: Hdc) -> Bool {
    let Some(d) = dc(hdc) else { return 0 };
    let cur = current_wgl();
    if cur.is_null() {
        return 1;
    }
    // SAFETY: current contexts are live.
    let c = unsafe { &mut *cur };
    if c.dc.as_ref().is_none_or(|(h, _)| *h != hdc) {
        return 1;
    }
    if c.gl.in_begin_end() {
        return 0;
    }
    c.gl.swap_buffers();
    let (w, h) = {
        let s = lock_dc(&d.state);
        (s.width, s.height)
    };
    let ok = follow_size(c, w, h) as Bool;
    dump::exit_if_due();
    ok
}

/// wglShareLists: `b` shares `a`'s display lists, textures and buffer
/// objects from now on (gl::share); what `b` had is dropped (Windows
/// requires it to have none). Both contexts must exist and `b` must not
/// be current in another thread.
pub fn share_lists(a: Hglrc, b: Hglrc) -> Bool {
    let (Some(a), Some(b)) = (context(a), context(b)) else { return 0 };
    // SAFETY: registered contexts are live.
    unsafe {
        if a != b && (*b).bound.load(Ordering::Acquire) && current_wgl() != b {
            return 0;
        }
        crate::gl::share::join(&mut (*b).gl, &mut (*a).gl);
    }
    1
}

/// wglCopyContext: copies the attribute groups of `mask`, as glPushAttrib
/// saves them (gl::attrib). The destination must not be current in any
/// thread.
pub unsafe fn copy_context(src: Hglrc, dst: Hglrc, mask: u32) -> Bool {
    let (Some(s), Some(d)) = (context(src), context(dst)) else { return 0 };
    if s == d {
        return 1;
    }
    if (*d).bound.load(Ordering::Acquire) {
        return 0;
    }
    // The same groups glPushAttrib saves.
    let saved = (*s).gl.save_attrib(mask);
    (*d).gl.restore_attrib(saved);
    1
}

// ---- fonts ----

/// wglUseFontBitmapsA/W: display lists base..base+count, list i drawing
/// character first+i of the DC's selected font with one glBitmap (as
/// Windows does: glBitmap(w, h, xorig, yorig, advance, 0, bits)). `wide`:
/// characters are Unicode code points (W); otherwise bytes in the font's
/// code page (A). Needs a current context, outside glBegin/glEnd and
/// outside list compilation. The lists are built through the public
/// entry points with the unpack modes at their defaults (alignment 1) and
/// the program's unpack modes restored afterwards.
pub fn use_font_bitmaps(hdc: Hdc, first: u32, count: u32, base: u32, wide: bool) -> Bool {
    let Some(d) = dc(hdc) else { return 0 };
    let (height, weight, charset) = lock_dc(&d.state).font;
    let font = fonts::select(height, weight);
    let page = code_page(charset);
    let decode = move |code: u32| -> u32 {
        if wide {
            code
        } else if code <= 0xff {
            page.decode(code as u8).unwrap_or(0xFFFD)
        } else {
            0xFFFD
        }
    };
    build_font_lists(&font, decode, first, count, base) as Bool
}

/// wglUseFontOutlinesA/W: outlines of the DC's (built-in) font, see
/// `winsys::font_outlines`.
///
/// # Safety
/// `gmf` is NULL or points to `count` writable GLYPHMETRICSFLOATs.
pub unsafe fn use_font_outlines(hdc: Hdc, first: u32, count: u32, base: u32, extrusion: f32, format: i32, gmf: *mut std::ffi::c_void, wide: bool) -> Bool {
    let Some(d) = dc(hdc) else { return 0 };
    let (height, weight, charset) = lock_dc(&d.state).font;
    let font = fonts::select(height, weight);
    let page = code_page(charset);
    let decode = move |code: u32| -> u32 {
        if wide {
            code
        } else if code <= 0xff {
            page.decode(code as u8).unwrap_or(0xFFFD)
        } else {
            0xFFFD
        }
    };
    super::font_outlines::build_outline_lists(&font, decode, first, count, base, extrusion, format, gmf as *mut super::font_outlines::GlyphMetricsFloat) as Bool
}

/// Builds glyph display lists through the public GL entry points (shared
/// with glXUseXFont's built-in fallback). False without a usable current
/// context.
pub fn build_font_lists(font: &Font, decode: impl Fn(u32) -> u32, first: u32, count: u32, base: u32) -> bool {
    use crate::api::table::{glBitmap, glEndList, glNewList};
    use crate::gl::enums::GL_COMPILE;
    let ctx = current::current();
    if ctx.is_null() || base == 0 || base.checked_add(count).is_none() || first.checked_add(count).is_none() {
        return false;
    }
    // SAFETY: the current context is live for this thread.
    let saved = unsafe {
        let c = &mut *ctx;
        if c.in_begin_end() || c.lists.compile_mode().is_some() {
            return false;
        }
        let saved = c.pixel_store.unpack;
        let u = &mut c.pixel_store.unpack;
        u.swap_bytes = false;
        u.lsb_first = false;
        u.row_length = 0;
        u.skip_rows = 0;
        u.skip_pixels = 0;
        u.alignment = 1;
        saved
    };
    for i in 0..count {
        let b = font.bitmap(decode(first + i));
        // SAFETY: the bits are width x height at alignment 1.
        unsafe {
            glNewList(base + i, GL_COMPILE);
            glBitmap(b.width, b.height, b.xorig, b.yorig, b.xmove, b.ymove, if b.bits.is_empty() { std::ptr::null() } else { b.bits.as_ptr() });
            glEndList();
        }
    }
    // SAFETY: as above; glNewList/glEndList do not change the current context.
    unsafe { (*ctx).pixel_store.unpack = saved };
    true
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::api::table::*;
    use crate::gl::enums::*;

    fn pfd(flags: u32, depth: u8, stencil: u8) -> PixelFormatDescriptor {
        PixelFormatDescriptor { dw_flags: flags, c_color_bits: 16, c_depth_bits: depth, c_stencil_bits: stencil, ..Default::default() }
    }

    #[test]
    fn pixel_formats_always_have_depth_and_stencil() {
        unsafe {
            let hdc = create_dc(64, 32);
            // Krasnov's zero-filled request, and SPF's (16 colour, 16 depth).
            for (p, want) in [(pfd(PFD_DRAW_TO_WINDOW | PFD_SUPPORT_OPENGL | PFD_DOUBLEBUFFER, 0, 0), 1), (pfd(PFD_SUPPORT_OPENGL, 16, 0), 2)] {
                let f = choose_pixel_format(hdc, &p);
                assert_eq!(f, want);
                let mut out = PixelFormatDescriptor::default();
                assert_eq!(describe_pixel_format(hdc, f, 40, &mut out), FORMATS);
                assert_eq!((out.c_depth_bits, out.c_stencil_bits, out.c_accum_bits, out.n_size), (24, 8, 64, 40));
                assert_eq!(out.dw_flags & PFD_DOUBLEBUFFER != 0, f == 1);
            }
            assert_eq!(describe_pixel_format(hdc, 3, 40, &mut PixelFormatDescriptor::default()), 0);
            assert_eq!(describe_pixel_format(hdc, 1, 0, null_mut()), FORMATS);
            assert_eq!(get_pixel_format(hdc), 0);
            assert_eq!(create_context(hdc), null_mut(), "no pixel format yet");
            assert_eq!(set_pixel_format(hdc, 1, null_mut()), 1);
            assert_eq!(set_pixel_format(hdc, 1, null_mut()), 1);
            assert_eq!(set_pixel_format(hdc, 2, null_mut()), 0);
            assert_eq!(get_pixel_format(hdc), 1);
            assert_eq!(destroy_dc(hdc), 1);
            assert_eq!(destroy_dc(hdc), 0);
            assert_eq!(get_pixel_format(hdc), 0);
        }
    }

    #[test]
    fn contexts_make_current_swap_and_delete() {
        unsafe {
            // Before any context: releasing is fine, GL calls are no-ops.
            assert_eq!(make_current(null_mut(), null_mut()), 1);
            glClear(GL_COLOR_BUFFER_BIT);
            let hdc = create_dc(40, 30);
            assert_eq!(set_pixel_format(hdc, 1, null_mut()), 1);
            let rc = create_context(hdc);
            assert!(!rc.is_null());
            assert_eq!(make_current(hdc, rc), 1);
            assert_eq!((get_current_context(), get_current_dc()), (rc, hdc));
            let mut vp = [0; 4];
            glGetIntegerv(GL_VIEWPORT, vp.as_mut_ptr());
            assert_eq!(vp, [0, 0, 40, 30]);
            glClearColor(0.0, 1.0, 0.0, 1.0);
            glClear(GL_COLOR_BUFFER_BIT);
            glFlush();
            // Double-buffered: nothing shown before SwapBuffers.
            let (mut w, mut h) = (0, 0);
            let img = dc_image(hdc, &mut w, &mut h);
            assert_eq!((w, h, *img.add(1)), (40, 30, 0));
            assert_eq!(swap_buffers(hdc), 1);
            let img = dc_image(hdc, &mut w, &mut h);
            assert_eq!(std::slice::from_raw_parts(img, 4), [0, 255, 0, 255]);
            // Resize: followed after the swap; the viewport stays.
            assert_eq!(resize_dc(hdc, 50, 20), 1);
            assert_eq!(swap_buffers(hdc), 1);
            assert_eq!(((*(rc as *mut WglContext)).gl.fb.width, (*(rc as *mut WglContext)).gl.fb.height), (50, 20));
            // Another thread cannot take it or delete it while it is current here.
            let (hdc_u, rc_u) = (hdc as usize, rc as usize);
            std::thread::spawn(move || {
                assert_eq!(make_current(hdc_u as Hdc, rc_u as Hglrc), 0);
                assert_eq!(delete_context(rc_u as Hglrc), 0);
            })
            .join()
            .unwrap();
            assert_eq!(get_current_context(), rc);
            // A wrong handle fails and leaves nothing current.
            assert_eq!(make_current(hdc, 0x1234 as Hglrc), 0);
            assert_eq!(get_current_context(), null_mut());
            assert_eq!(make_current(hdc, rc), 1);
            // Deleting the current context releases it.
            assert_eq!(delete_context(rc), 1);
            assert_eq!((get_current_context(), current::current()), (null_mut(), null_mut()));
            assert_eq!(delete_context(rc), 0);
            destroy_dc(hdc);
        }
    }

    #[test]
    fn single_buffered_shows_at_flush() {
        unsafe {
            let hdc = create_dc(8, 8);
            set_pixel_format(hdc, 2, null_mut());
            let rc = create_context(hdc);
            assert_eq!(make_current(hdc, rc), 1);
            glClearColor(1.0, 0.0, 0.0, 1.0);
            glClear(GL_COLOR_BUFFER_BIT);
            let (mut w, mut h) = (0, 0);
            assert_eq!(*dc_image(hdc, &mut w, &mut h), 0);
            glFlush();
            assert_eq!(*dc_image(hdc, &mut w, &mut h), 255);
            // A context of another format does not go on this DC.
            let hdc2 = create_dc(8, 8);
            set_pixel_format(hdc2, 1, null_mut());
            assert_eq!(make_current(hdc2, rc), 0);
            assert_eq!(delete_context(rc), 1);
            destroy_dc(hdc);
            destroy_dc(hdc2);
        }
    }

    #[test]
    fn font_lists_are_made_for_every_character() {
        unsafe {
            let hdc = create_dc(16, 16);
            set_pixel_format(hdc, 1, null_mut());
            let rc = create_context(hdc);
            // No current context: fails.
            assert_eq!(use_font_bitmaps(hdc, 32, 224, 1000, false), 0);
            assert_eq!(make_current(hdc, rc), 1);
            glPixelStorei(GL_UNPACK_ALIGNMENT, 8);
            let base = glGenLists(224);
            assert_eq!(use_font_bitmaps(hdc, 32, 224, base, false), 1);
            for i in 0..224 {
                assert_eq!(glIsList(base + i), 1, "list {}", base + i);
            }
            assert_eq!(glIsList(base + 224), 0);
            let mut a = 0;
            glGetIntegerv(GL_UNPACK_ALIGNMENT, &mut a);
            assert_eq!(a, 8, "the program's unpack alignment is restored");
            assert_eq!(glGetError(), GL_NO_ERROR);
            // Bad arguments and list compilation in progress.
            assert_eq!(use_font_bitmaps(hdc, 0, 10, 0, false), 0);
            glNewList(5000, GL_COMPILE);
            assert_eq!(use_font_bitmaps(hdc, 0, 10, 6000, true), 0);
            glEndList();
            assert_eq!(select_font(hdc, 36, 700, RUSSIAN_CHARSET), 1);
            assert_eq!(use_font_bitmaps(hdc, 1, 255, 1, false), 1);
            assert_eq!(glIsList(255), 1);
            delete_context(rc);
            destroy_dc(hdc);
        }
    }

    /// What the lists draw: the glyphs of the selected font in the code
    /// page of the selected charset ("Привет" in CP1251).
    #[test]
    fn font_selection_reaches_the_glyphs() {
        let hdc = create_dc(4, 4);
        select_font(hdc, 36, 700, RUSSIAN_CHARSET);
        let (h, w, cs) = dc(hdc).map(|d| lock_dc(&d.state).font).unwrap();
        let font = fonts::select(h, w);
        assert_eq!(font.cell_height(), 36);
        let pe = font.bitmap(code_page(cs).decode(0xCF).unwrap());
        assert_eq!(pe, font.bitmap(0x041F));
        assert_eq!(code_page(ANSI_CHARSET), ansi_code_page());
        unsafe { destroy_dc(hdc) };
    }

    /// wglUseFontOutlines: the filled outline of each glyph, drawn with one
    /// em mapped to the font's cell height in pixels, covers exactly the
    /// pixels its bitmap does; the back face of an extruded glyph (seen
    /// with front faces culled) covers them too, the side walls being edge
    /// on; the metrics are the bitmap's in em units; each list advances by
    /// the cell increment.
    #[test]
    fn font_outlines_cover_the_bitmap_glyphs() {
        use crate::winsys::font_outlines::{GlyphMetricsFloat, WGL_FONT_LINES, WGL_FONT_POLYGONS};
        unsafe {
            let (w, h) = (96, 48);
            let hdc = create_dc(w, h);
            set_pixel_format(hdc, 1, null_mut());
            let rc = create_context(hdc);
            let mut gmf = [GlyphMetricsFloat::default(); 3];
            assert_eq!(use_font_outlines(hdc, 65, 3, 100, 0.5, WGL_FONT_POLYGONS, gmf.as_mut_ptr() as *mut _, false), 0, "no context");
            assert_eq!(make_current(hdc, rc), 1);
            select_font(hdc, 24, 400, ANSI_CHARSET);
            let font = fonts::select(24, 400);
            let em = font.cell_height() as f32;
            assert_eq!(use_font_outlines(hdc, 65, 3, 100, 0.5, WGL_FONT_POLYGONS, gmf.as_mut_ptr() as *mut _, false), 1);
            assert_eq!(use_font_outlines(hdc, 65, 3, 200, 0.0, WGL_FONT_LINES, null_mut(), false), 1);
            assert_eq!(use_font_outlines(hdc, 65, 3, 300, 0.0, 7, null_mut(), false), 0, "unknown format");
            assert_eq!(use_font_bitmaps(hdc, 65, 3, 400, false), 1);
            let b = font.bitmap(66);
            assert_eq!(gmf[1].black_box_x, b.width as f32 / em);
            assert_eq!(gmf[1].cell_inc_x, b.xmove / em);
            assert_eq!(gmf[1].origin_y, (b.height as f32 - b.yorig) / em);
            glMatrixMode(GL_PROJECTION);
            glOrtho(0.0, w as f64 / em as f64, 0.0, h as f64 / em as f64, -1.0, 1.0);
            glMatrixMode(GL_MODELVIEW);
            let read = || {
                let mut px = vec![0u8; (w * h * 4) as usize];
                glReadPixels(0, 0, w, h, GL_RGBA, GL_UNSIGNED_BYTE, px.as_mut_ptr() as *mut _);
                px
            };
            // "ABC" from the origin (10, 12) pixels, as bitmaps, then as
            // outlines (front faces), then as back faces only.
            let origin = (10.0 / em, 12.0 / em);
            glClear(GL_COLOR_BUFFER_BIT);
            glRasterPos2f(origin.0, origin.1);
            let names: [u8; 3] = [0, 1, 2];
            glListBase(400);
            glCallLists(3, GL_UNSIGNED_BYTE, names.as_ptr() as *const _);
            let bitmaps = read();
            assert!(bitmaps.chunks(4).filter(|p| p[0] != 0).count() > 40, "the bitmaps drew");
            for (base, cull) in [(100, GL_BACK), (100, GL_FRONT)] {
                glClear(GL_COLOR_BUFFER_BIT);
                glEnable(GL_CULL_FACE);
                glCullFace(cull);
                glLoadIdentity();
                glTranslatef(origin.0, origin.1, 0.0);
                glListBase(base);
                glCallLists(3, GL_UNSIGNED_BYTE, names.as_ptr() as *const _);
                glDisable(GL_CULL_FACE);
                assert!(read() == bitmaps, "outlines (culling {cull:#x}) cover the bitmap pixels");
            }
            // The lines format draws the boundary: only pixels on or next
            // to glyph pixels.
            glClear(GL_COLOR_BUFFER_BIT);
            glLoadIdentity();
            glTranslatef(origin.0, origin.1, 0.0);
            glListBase(200);
            glCallLists(3, GL_UNSIGNED_BYTE, names.as_ptr() as *const _);
            let lines = read();
            let lit = |img: &[u8], x: i32, y: i32| x >= 0 && y >= 0 && x < w && y < h && img[((y * w + x) * 4) as usize] != 0;
            let mut n = 0;
            for y in 0..h {
                for x in 0..w {
                    if lit(&lines, x, y) {
                        n += 1;
                        assert!((-1..=1).any(|dy| (-1..=1).any(|dx| lit(&bitmaps, x + dx, y + dy))), "line pixel {x},{y} away from the glyphs");
                    }
                }
            }
            assert!(n > 40, "the outlines drew ({n} pixels)");
            assert_eq!(glGetError(), GL_NO_ERROR);
            delete_context(rc);
            destroy_dc(hdc);
        }
    }
}
