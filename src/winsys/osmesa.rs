//! The OSMesa API (Mesa's off-screen interface, as of Mesa 22): contexts
//! that render into a buffer the caller owns.
//!
//! When the caller's buffer has the colour buffer's own layout (GL_RGBA,
//! GL_UNSIGNED_BYTE, Y_UP, no ROW_LENGTH padding: the usual case), drawing
//! goes straight into it (`framebuffer::color`), as Mesa's classic OSMesa
//! did. Otherwise rendering goes to the context's own colour buffer and
//! the image is converted into the caller's buffer (format, Y_UP,
//! ROW_LENGTH) at glFlush, glFinish and when the context stops being
//! current, as Mesa's gallium OSMesa does; at MakeCurrent the buffer's
//! contents are loaded. Either way drawing without a clear keeps what the
//! caller put there.

use crate::api::types::*;
use crate::framebuffer::{Config, Framebuffer, Present, MAX_SIZE};
use crate::gl::enums::*;
use crate::gl::Context;
use crate::winsys::current;
use std::cell::Cell;
use std::ffi::c_void;
use std::ptr::null_mut;

// OSMesa enums (osmesa.h).
pub const OSMESA_BGRA: u32 = 0x1;
pub const OSMESA_ARGB: u32 = 0x2;
pub const OSMESA_BGR: u32 = 0x4;
pub const OSMESA_RGB_565: u32 = 0x5;
pub const OSMESA_ROW_LENGTH: i32 = 0x10;
pub const OSMESA_Y_UP: i32 = 0x11;
pub const OSMESA_WIDTH: i32 = 0x20;
pub const OSMESA_HEIGHT: i32 = 0x21;
pub const OSMESA_FORMAT: i32 = 0x22;
pub const OSMESA_TYPE: i32 = 0x23;
pub const OSMESA_MAX_WIDTH: i32 = 0x24;
pub const OSMESA_MAX_HEIGHT: i32 = 0x25;
pub const OSMESA_DEPTH_BITS: i32 = 0x30;
pub const OSMESA_STENCIL_BITS: i32 = 0x31;
pub const OSMESA_ACCUM_BITS: i32 = 0x32;
pub const OSMESA_PROFILE: i32 = 0x33;
pub const OSMESA_CORE_PROFILE: i32 = 0x34;
pub const OSMESA_COMPAT_PROFILE: i32 = 0x35;
pub const OSMESA_CONTEXT_MAJOR_VERSION: i32 = 0x36;
pub const OSMESA_CONTEXT_MINOR_VERSION: i32 = 0x37;

/// What an OSMesaContext handle points to.
pub struct OsContext {
    pub gl: Context,
    format: u32,
    /// The caller's buffer, as last bound.
    buffer: Option<UserBuffer>,
    row_length: i32,
    y_up: bool,
}

/// A caller-owned colour buffer and how its pixels are laid out.
#[derive(Clone, Copy, Debug)]
pub struct UserBuffer {
    ptr: *mut u8,
    format: u32,
    ty: u32,
    width: usize,
    height: usize,
    /// Pixels per row in the caller's buffer (>= width).
    row_pixels: usize,
    y_up: bool,
}

thread_local! {
    static CURRENT_OS: Cell<*mut OsContext> = const { Cell::new(null_mut()) };
}

fn is_format(f: u32) -> bool {
    matches!(f, GL_RGBA | GL_RGB | OSMESA_BGRA | OSMESA_ARGB | OSMESA_BGR | OSMESA_RGB_565)
}

impl UserBuffer {
    /// Is the buffer laid out as the colour buffer is, so that drawing can
    /// go straight into it?
    fn is_direct(&self) -> bool {
        self.format == GL_RGBA && self.ty == GL_UNSIGNED_BYTE && self.y_up && self.row_pixels == self.width
    }

    /// Can `fb`'s colour buffer be this buffer's memory?
    fn can_lend(&self, fb: &Framebuffer) -> bool {
        self.is_direct() && fb.width == self.width && fb.height == self.height && !fb.is_double_buffered()
    }

    /// OSMesaMakeCurrent's binding: points `fb`'s colour buffer at this
    /// buffer when its layout allows, else gives `fb` storage of its own
    /// loaded from it (false: out of memory).
    ///
    /// # Safety
    /// The buffer must be valid as OSMesaMakeCurrent's contract says.
    unsafe fn attach(&self, fb: &mut Framebuffer) -> bool {
        if self.can_lend(fb) {
            fb.lend_color(self.ptr);
            return true;
        }
        // Never write through to memory lent before.
        if fb.unlend_color().is_err() {
            return false;
        }
        self.load_into(fb);
        true
    }

    /// OSMesaPixelStore's change of layout: the colour buffer's contents
    /// stay what they are; drawing goes into the buffer if the new layout
    /// allows (it is written in that layout first), else into storage of
    /// the colour buffer's own (false: out of memory).
    ///
    /// # Safety
    /// As for `attach`.
    unsafe fn relayout(&mut self, fb: &mut Framebuffer) -> bool {
        let lent_here = fb.color.is_lent() && std::ptr::eq(fb.color.as_ptr() as *const u8, self.ptr);
        if self.can_lend(fb) {
            if !lent_here {
                self.present(fb);
                fb.lend_color(self.ptr);
            }
            return true;
        }
        fb.own_color().is_ok()
    }

    fn channels(&self) -> usize {
        match self.format {
            GL_RGB | OSMESA_BGR => 3,
            OSMESA_RGB_565 => 1,
            _ => 4,
        }
    }

    fn bytes_per_channel(&self) -> usize {
        match self.ty {
            GL_UNSIGNED_SHORT | GL_UNSIGNED_SHORT_5_6_5 => 2,
            GL_FLOAT => 4,
            _ => 1,
        }
    }

    fn pixel_bytes(&self) -> usize {
        if self.format == OSMESA_RGB_565 {
            2
        } else {
            self.channels() * self.bytes_per_channel()
        }
    }

    /// Byte offset of GL row `y` (bottom-up) in the caller's buffer.
    fn row_offset(&self, y: usize) -> usize {
        let row = if self.y_up { y } else { self.height - 1 - y };
        row * self.row_pixels * self.pixel_bytes()
    }

    /// Order of R, G, B, A within a pixel: position of each channel.
    fn order(&self) -> [usize; 4] {
        match self.format {
            OSMESA_BGRA => [2, 1, 0, 3],
            OSMESA_ARGB => [1, 2, 3, 0],
            OSMESA_BGR => [2, 1, 0, 4],
            GL_RGB => [0, 1, 2, 4],
            _ => [0, 1, 2, 3],
        }
    }

    /// Stores one RGBA8 pixel at `p`.
    unsafe fn store(&self, p: *mut u8, c: [u8; 4]) {
        if self.format == OSMESA_RGB_565 {
            let q = |v: u8, bits: u32| ((v as u32 * ((1 << bits) - 1) + 127) / 255) as u16;
            let v = (q(c[0], 5) << 11) | (q(c[1], 6) << 5) | q(c[2], 5);
            (p as *mut u16).write_unaligned(v);
            return;
        }
        for (ch, &pos) in self.order().iter().enumerate() {
            if pos == 4 {
                continue;
            }
            match self.ty {
                GL_UNSIGNED_SHORT => (p as *mut u16).add(pos).write_unaligned(c[ch] as u16 * 257),
                GL_FLOAT => (p as *mut f32).add(pos).write_unaligned(c[ch] as f32 / 255.0),
                _ => *p.add(pos) = c[ch],
            }
        }
    }

    /// Loads one pixel at `p` as RGBA8.
    unsafe fn load(&self, p: *const u8) -> [u8; 4] {
        if self.format == OSMESA_RGB_565 {
            let v = (p as *const u16).read_unaligned() as u32;
            let e = |x: u32, bits: u32| ((x * 255 + ((1 << bits) - 1) / 2) / ((1 << bits) - 1)) as u8;
            return [e(v >> 11, 5), e((v >> 5) & 63, 6), e(v & 31, 5), 255];
        }
        let mut c = [255u8; 4];
        for (ch, &pos) in self.order().iter().enumerate() {
            if pos == 4 {
                continue;
            }
            c[ch] = match self.ty {
                GL_UNSIGNED_SHORT => ((p as *const u16).add(pos).read_unaligned() / 257) as u8,
                GL_FLOAT => ((p as *const f32).add(pos).read_unaligned().clamp(0.0, 1.0) * 255.0 + 0.5) as u8,
                _ => *p.add(pos),
            };
        }
        c
    }

    unsafe fn load_into(&self, fb: &mut Framebuffer) {
        let pb = self.pixel_bytes();
        let w = self.width.min(fb.width);
        for y in 0..self.height.min(fb.height) {
            let row = self.ptr.add(self.row_offset(y));
            if self.format == GL_RGBA && self.ty == GL_UNSIGNED_BYTE {
                // The colour buffer's own layout: a row copy (this runs at
                // every OSMesaMakeCurrent, which many programs call per frame).
                let i = fb.index(0, y);
                std::ptr::copy_nonoverlapping(row, fb.color[i..i + w].as_mut_ptr() as *mut u8, w * 4);
                continue;
            }
            for x in 0..w {
                let i = fb.index(x, y);
                fb.color[i] = self.load(row.add(x * pb));
            }
        }
    }
}

impl Present for UserBuffer {
    fn present(&mut self, fb: &Framebuffer) {
        crate::winsys::dump::frame(fb);
        if std::ptr::eq(fb.front().as_ptr() as *const u8, self.ptr) {
            // Drawn in place (see `attach`).
            return;
        }
        let pb = self.pixel_bytes();
        // SAFETY: the caller promised a buffer of at least row_pixels x height
        // pixels of this format when it called OSMesaMakeCurrent.
        unsafe {
            for y in 0..self.height.min(fb.height) {
                let row = self.ptr.add(self.row_offset(y));
                let src = &fb.front()[fb.index(0, y)..fb.index(0, y) + self.width.min(fb.width)];
                if self.format == GL_RGBA && self.ty == GL_UNSIGNED_BYTE {
                    std::ptr::copy_nonoverlapping(src.as_ptr() as *const u8, row, src.len() * 4);
                } else {
                    for (x, &c) in src.iter().enumerate() {
                        self.store(row.add(x * pb), c);
                    }
                }
            }
        }
    }
}

fn config(depth: i32, stencil: i32, accum: i32) -> Config {
    Config {
        alpha_bits: 8,
        depth_bits: if depth > 0 { crate::framebuffer::DEPTH_BITS as u8 } else { 0 },
        stencil_bits: if stencil > 0 { 8 } else { 0 },
        accum_bits: if accum > 0 { 16 } else { 0 },
    }
}

/// OSMesaCreateContextExt. A non-NULL `share` must be a live context: the
/// new one shares its display lists, textures and buffer objects
/// (gl::share).
// `share` is the C caller's, under OSMesa's contract above.
#[allow(clippy::not_unsafe_ptr_arg_deref)]
pub fn create_context_ext(format: u32, depth: i32, stencil: i32, accum: i32, share: *mut OsContext) -> *mut OsContext {
    if !is_format(format) {
        return null_mut();
    }
    let mut ctx = Box::new(OsContext { gl: Context::new(config(depth, stencil, accum)), format, buffer: None, row_length: 0, y_up: true });
    ctx.gl.defer_render = true;
    if !share.is_null() {
        // SAFETY: OSMesa's contract: sharelist is NULL or a live context.
        crate::gl::share::join(&mut ctx.gl, unsafe { &mut (*share).gl });
    }
    Box::into_raw(ctx)
}

/// OSMesaCreateContextAttribs: a zero-terminated list of (name, value).
///
/// # Safety
/// `attribs` must be NULL or a zero-terminated attribute list.
pub unsafe fn create_context_attribs(attribs: *const i32, share: *mut OsContext) -> *mut OsContext {
    let (mut format, mut depth, mut stencil, mut accum) = (GL_RGBA, 24, 8, 0);
    let (mut major, mut minor) = (1, 0);
    if !attribs.is_null() {
        let mut p = attribs;
        loop {
            let name = *p;
            if name == 0 {
                break;
            }
            let value = *p.add(1);
            match name {
                OSMESA_FORMAT => format = value as u32,
                OSMESA_DEPTH_BITS => depth = value,
                OSMESA_STENCIL_BITS => stencil = value,
                OSMESA_ACCUM_BITS => accum = value,
                OSMESA_PROFILE if value == OSMESA_COMPAT_PROFILE => {}
                OSMESA_PROFILE => return null_mut(), // GL 1.x has no core profile
                OSMESA_CONTEXT_MAJOR_VERSION => major = value,
                OSMESA_CONTEXT_MINOR_VERSION => minor = value,
                _ => return null_mut(),
            }
            p = p.add(2);
        }
    }
    // Only versions softgl provides.
    if major > 1 || (major == 1 && minor > 5) {
        return null_mut();
    }
    create_context_ext(format, depth, stencil, accum, share)
}

/// Delivers the current context's image and releases it.
fn release_current() {
    let cur = CURRENT_OS.with(|c| c.get());
    if !cur.is_null() {
        // SAFETY: a current context is live until destroyed, and destroying
        // it releases it first.
        unsafe { (*cur).gl.flush() };
    }
    CURRENT_OS.with(|c| c.set(null_mut()));
    current::set_current(null_mut());
}

/// OSMesaMakeCurrent.
///
/// # Safety
/// `ctx` must be NULL or a live context; `buffer` must hold width x height
/// pixels (or ROW_LENGTH x height) of the context's format and `ty`.
pub unsafe fn make_current(ctx: *mut OsContext, buffer: *mut c_void, ty: u32, width: i32, height: i32) -> bool {
    if ctx.is_null() {
        release_current();
        return true;
    }
    let os = &mut *ctx;
    if buffer.is_null() || width < 1 || height < 1 || width as usize > MAX_SIZE || height as usize > MAX_SIZE {
        return false;
    }
    let type_ok = match os.format {
        // As in Mesa: 5-6-5 pixels come only as GL_UNSIGNED_SHORT_5_6_5.
        OSMESA_RGB_565 => ty == GL_UNSIGNED_SHORT_5_6_5,
        _ => matches!(ty, GL_UNSIGNED_BYTE | GL_UNSIGNED_SHORT | GL_FLOAT),
    };
    if !type_ok {
        return false;
    }
    // The previous binding (maybe this context with another buffer) gets
    // its image first.
    let prev = CURRENT_OS.with(|c| c.get());
    if !prev.is_null() {
        (*prev).gl.flush();
    }
    // The window's framebuffer, also while a framebuffer object is bound.
    if os.gl.window_fb_mut().resize(width as usize, height as usize).is_err() {
        return false;
    }
    let (w, h) = (width as usize, height as usize);
    let row_pixels = if os.row_length > 0 { (os.row_length as usize).max(w) } else { w };
    let ub = UserBuffer { ptr: buffer as *mut u8, format: os.format, ty, width: w, height: h, row_pixels, y_up: os.y_up };
    if !ub.attach(os.gl.window_fb_mut()) {
        return false;
    }
    os.buffer = Some(ub);
    os.gl.surface = Some(Box::new(ub));
    os.gl.surface_resized(width, height);
    CURRENT_OS.with(|c| c.set(ctx));
    current::set_current(&mut os.gl);
    true
}

pub fn current_context() -> *mut OsContext {
    CURRENT_OS.with(|c| c.get())
}

/// # Safety
/// `ctx` must be NULL or a context from create_context_*, not used after.
pub unsafe fn destroy_context(ctx: *mut OsContext) {
    if ctx.is_null() {
        return;
    }
    if CURRENT_OS.with(|c| c.get()) == ctx {
        CURRENT_OS.with(|c| c.set(null_mut()));
        current::set_current(null_mut());
    }
    drop(Box::from_raw(ctx));
}

/// OSMesaPixelStore: applies to the current context's buffer layout.
pub fn pixel_store(pname: i32, value: i32) {
    let cur = current_context();
    if cur.is_null() {
        return;
    }
    // SAFETY: current contexts are live.
    let os = unsafe { &mut *cur };
    match pname {
        OSMESA_ROW_LENGTH if value >= 0 => os.row_length = value,
        OSMESA_Y_UP => os.y_up = value != 0,
        _ => {
            os.gl.set_error(GL_INVALID_ENUM);
            return;
        }
    }
    if let Some(mut ub) = os.buffer {
        ub.row_pixels = if os.row_length > 0 { (os.row_length as usize).max(ub.width) } else { ub.width };
        ub.y_up = os.y_up;
        // Pending drawing lands first; then the colour buffer follows the
        // new layout (into the buffer, or out of it into storage of its own).
        os.gl.flush();
        // SAFETY: the buffer is the one bound by OSMesaMakeCurrent, still
        // valid by its contract.
        if !unsafe { ub.relayout(os.gl.window_fb_mut()) } {
            os.gl.set_error(GL_OUT_OF_MEMORY);
            return;
        }
        os.buffer = Some(ub);
        os.gl.surface = Some(Box::new(ub));
    }
}

/// OSMesaGetIntegerv; None for an unknown name.
pub fn get_integer(pname: i32) -> Option<i32> {
    if pname == OSMESA_MAX_WIDTH || pname == OSMESA_MAX_HEIGHT {
        return Some(MAX_SIZE as i32);
    }
    let cur = current_context();
    if cur.is_null() {
        return None;
    }
    // SAFETY: current contexts are live.
    let os = unsafe { &*cur };
    let ub = os.buffer.as_ref();
    Some(match pname {
        OSMESA_WIDTH => ub.map_or(0, |b| b.width as i32),
        OSMESA_HEIGHT => ub.map_or(0, |b| b.height as i32),
        OSMESA_FORMAT => os.format as i32,
        OSMESA_TYPE => ub.map_or(0, |b| b.ty as i32),
        OSMESA_ROW_LENGTH => os.row_length,
        OSMESA_Y_UP => os.y_up as i32,
        _ => return None,
    })
}

/// OSMesaGetDepthBuffer: the 24-bit depth values, one u32 per pixel, rows
/// bottom-up.
///
/// # Safety
/// Output pointers must be NULL or writable.
pub unsafe fn get_depth_buffer(ctx: *mut OsContext, w: *mut GLint, h: *mut GLint, bpv: *mut GLint, buf: *mut *mut c_void) -> bool {
    let put = |p: *mut GLint, v: GLint| {
        if !p.is_null() {
            *p = v
        }
    };
    let ok = !ctx.is_null() && (*ctx).gl.window_fb().has_depth() && (*ctx).buffer.is_some();
    if !ok {
        put(w, 0);
        put(h, 0);
        put(bpv, 0);
        if !buf.is_null() {
            *buf = null_mut();
        }
        return false;
    }
    let fb = (*ctx).gl.window_fb_mut();
    put(w, fb.width as GLint);
    put(h, fb.height as GLint);
    put(bpv, 4);
    if !buf.is_null() {
        *buf = fb.depth.as_mut_ptr() as *mut c_void;
    }
    true
}

/// OSMesaGetColorBuffer: the caller's buffer as last bound.
///
/// # Safety
/// Output pointers must be NULL or writable.
pub unsafe fn get_color_buffer(ctx: *mut OsContext, w: *mut GLint, h: *mut GLint, format: *mut GLint, buf: *mut *mut c_void) -> bool {
    let put = |p: *mut GLint, v: GLint| {
        if !p.is_null() {
            *p = v
        }
    };
    let b = if ctx.is_null() { None } else { (*ctx).buffer };
    put(w, b.map_or(0, |b| b.width as GLint));
    put(h, b.map_or(0, |b| b.height as GLint));
    put(format, b.map_or(0, |b| b.format as GLint));
    if !buf.is_null() {
        *buf = b.map_or(null_mut(), |b| b.ptr as *mut c_void);
    }
    b.is_some()
}
