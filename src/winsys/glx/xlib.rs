//! The few Xlib functions GLX needs, found at run time with
//! `dlopen("libX11.so.6")` so that softgl has no link-time X dependency
//! (a program that never calls glX* never loads X). The C structures
//! below are Xlib's public ABI (Xlib.h, Xutil.h) on LP64 and ILP32 alike:
//! `long`/`unsigned long` are `c_long`/`c_ulong`.

#![allow(non_snake_case, non_upper_case_globals)]

use std::ffi::{c_char, c_int, c_long, c_uint, c_ulong, c_void};
use std::sync::OnceLock;

pub type Display = c_void;
pub type Visual = c_void;
pub type Xid = c_ulong;
pub type Gc = *mut c_void;

/// XVisualInfo (Xutil.h).
#[repr(C)]
#[derive(Clone, Copy)]
pub struct XVisualInfo {
    pub visual: *mut Visual,
    pub visualid: c_ulong,
    pub screen: c_int,
    pub depth: c_int,
    pub class: c_int,
    pub red_mask: c_ulong,
    pub green_mask: c_ulong,
    pub blue_mask: c_ulong,
    pub colormap_size: c_int,
    pub bits_per_rgb: c_int,
}

/// XImage (Xlib.h). softgl fills one itself and lets XInitImage supply the
/// function table, so no Xlib allocation has to be freed.
#[repr(C)]
pub struct XImage {
    pub width: c_int,
    pub height: c_int,
    pub xoffset: c_int,
    pub format: c_int,
    pub data: *mut c_char,
    pub byte_order: c_int,
    pub bitmap_unit: c_int,
    pub bitmap_bit_order: c_int,
    pub bitmap_pad: c_int,
    pub depth: c_int,
    pub bytes_per_line: c_int,
    pub bits_per_pixel: c_int,
    pub red_mask: c_ulong,
    pub green_mask: c_ulong,
    pub blue_mask: c_ulong,
    pub obdata: *mut c_char,
    pub funcs: [*mut c_void; 6],
}

pub const VisualIDMask: c_long = 0x1;
pub const VisualScreenMask: c_long = 0x2;
pub const VisualClassMask: c_long = 0x8;
pub const TrueColor: c_int = 4;
pub const ZPixmap: c_int = 2;
pub const LSBFirst: c_int = 0;
pub const MSBFirst: c_int = 1;

/// XCharStruct (Xlib.h).
#[repr(C)]
#[derive(Clone, Copy)]
pub struct XCharStruct {
    pub lbearing: i16,
    pub rbearing: i16,
    pub width: i16,
    pub ascent: i16,
    pub descent: i16,
    pub attributes: u16,
}

/// XFontStruct (Xlib.h): only ascent and descent are read.
#[repr(C)]
pub struct XFontStruct {
    pub ext_data: *mut c_void,
    pub fid: Xid,
    pub direction: c_uint,
    pub min_char_or_byte2: c_uint,
    pub max_char_or_byte2: c_uint,
    pub min_byte1: c_uint,
    pub max_byte1: c_uint,
    pub all_chars_exist: c_int,
    pub default_char: c_uint,
    pub n_properties: c_int,
    pub properties: *mut c_void,
    pub min_bounds: XCharStruct,
    pub max_bounds: XCharStruct,
    pub per_char: *mut XCharStruct,
    pub ascent: c_int,
    pub descent: c_int,
}

/// An Xlib error handler (XErrorHandler).
pub type ErrorHandler = unsafe extern "C" fn(*mut Display, *mut c_void) -> c_int;

/// The Xlib entry points softgl calls.
pub struct Xlib {
    pub XSetErrorHandler: unsafe extern "C" fn(Option<ErrorHandler>) -> Option<ErrorHandler>,
    pub XQueryFont: unsafe extern "C" fn(*mut Display, Xid) -> *mut XFontStruct,
    pub XFreeFontInfo: unsafe extern "C" fn(*mut *mut c_char, *mut XFontStruct, c_int) -> c_int,
    pub XGetVisualInfo: unsafe extern "C" fn(*mut Display, c_long, *mut XVisualInfo, *mut c_int) -> *mut XVisualInfo,
    pub XFree: unsafe extern "C" fn(*mut c_void) -> c_int,
    pub XGetGeometry: unsafe extern "C" fn(*mut Display, Xid, *mut Xid, *mut c_int, *mut c_int, *mut c_uint, *mut c_uint, *mut c_uint, *mut c_uint) -> c_int,
    pub XCreateGC: unsafe extern "C" fn(*mut Display, Xid, c_ulong, *mut c_void) -> Gc,
    pub XFreeGC: unsafe extern "C" fn(*mut Display, Gc) -> c_int,
    pub XInitImage: unsafe extern "C" fn(*mut XImage) -> c_int,
    pub XPutImage: unsafe extern "C" fn(*mut Display, Xid, Gc, *mut XImage, c_int, c_int, c_int, c_int, c_uint, c_uint) -> c_int,
    pub XFlush: unsafe extern "C" fn(*mut Display) -> c_int,
    pub XSync: unsafe extern "C" fn(*mut Display, c_int) -> c_int,
    pub XQueryExtension: unsafe extern "C" fn(*mut Display, *const c_char, *mut c_int, *mut c_int, *mut c_int) -> c_int,
    pub XScreenCount: unsafe extern "C" fn(*mut Display) -> c_int,
    pub XDefaultVisual: unsafe extern "C" fn(*mut Display, c_int) -> *mut Visual,
    pub XVisualIDFromVisual: unsafe extern "C" fn(*mut Visual) -> c_ulong,
    pub XConnectionNumber: unsafe extern "C" fn(*mut Display) -> c_int,
    pub XNextRequest: unsafe extern "C" fn(*mut Display) -> c_ulong,
    pub XAddExtension: unsafe extern "C" fn(*mut Display) -> *mut XExtCodes,
    pub XESetCloseDisplay: unsafe extern "C" fn(*mut Display, c_int, Option<CloseDisplay>) -> Option<CloseDisplay>,
}

/// XExtCodes (Xlib.h).
#[repr(C)]
pub struct XExtCodes {
    pub extension: c_int,
    pub major_opcode: c_int,
    pub first_event: c_int,
    pub first_error: c_int,
}

/// A close-display hook (XESetCloseDisplay).
pub type CloseDisplay = unsafe extern "C" fn(*mut Display, *mut XExtCodes) -> c_int;

/// XErrorEvent (Xlib.h).
#[repr(C)]
pub struct XErrorEvent {
    pub kind: c_int,
    pub display: *mut Display,
    pub resourceid: Xid,
    pub serial: c_ulong,
    pub error_code: u8,
    pub request_code: u8,
    pub minor_code: u8,
}

/// The shared library `name`, loaded (null when it cannot be: always on
/// Windows, which has no Xlib).
unsafe fn open_library(name: &std::ffi::CStr) -> *mut c_void {
    #[cfg(unix)]
    return libc::dlopen(name.as_ptr(), libc::RTLD_LAZY | libc::RTLD_LOCAL);
    #[cfg(not(unix))]
    {
        let _ = name;
        std::ptr::null_mut()
    }
}

unsafe fn sym<T: Copy>(lib: *mut c_void, name: &[u8]) -> Option<T> {
    #[cfg(unix)]
    let p = libc::dlsym(lib, name.as_ptr() as *const c_char);
    #[cfg(not(unix))]
    let p: *mut c_void = {
        let _ = (lib, name);
        std::ptr::null_mut()
    };
    if p.is_null() {
        None
    } else {
        // SAFETY: T is a function pointer type of the symbol's C signature.
        Some(std::mem::transmute_copy::<*mut c_void, T>(&p))
    }
}

unsafe fn load() -> Option<Xlib> {
    let lib = open_library(c"libX11.so.6");
    if lib.is_null() {
        return None;
    }
    // Runs before the libraries' destructors (registered after _dl_fini's).
    libc::atexit(mark_exiting);
    Some(Xlib {
        XSetErrorHandler: sym(lib, b"XSetErrorHandler\0")?,
        XQueryFont: sym(lib, b"XQueryFont\0")?,
        XFreeFontInfo: sym(lib, b"XFreeFontInfo\0")?,
        XGetVisualInfo: sym(lib, b"XGetVisualInfo\0")?,
        XFree: sym(lib, b"XFree\0")?,
        XGetGeometry: sym(lib, b"XGetGeometry\0")?,
        XCreateGC: sym(lib, b"XCreateGC\0")?,
        XFreeGC: sym(lib, b"XFreeGC\0")?,
        XInitImage: sym(lib, b"XInitImage\0")?,
        XPutImage: sym(lib, b"XPutImage\0")?,
        XFlush: sym(lib, b"XFlush\0")?,
        XSync: sym(lib, b"XSync\0")?,
        XQueryExtension: sym(lib, b"XQueryExtension\0")?,
        XScreenCount: sym(lib, b"XScreenCount\0")?,
        XDefaultVisual: sym(lib, b"XDefaultVisual\0")?,
        XVisualIDFromVisual: sym(lib, b"XVisualIDFromVisual\0")?,
        XConnectionNumber: sym(lib, b"XConnectionNumber\0")?,
        XNextRequest: sym(lib, b"XNextRequest\0")?,
        XAddExtension: sym(lib, b"XAddExtension\0")?,
        XESetCloseDisplay: sym(lib, b"XESetCloseDisplay\0")?,
    })
}

/// libX11, loaded on first use; None when it cannot be loaded (then every
/// GLX call fails cleanly).
pub fn xlib() -> Option<&'static Xlib> {
    static X: OnceLock<Option<Xlib>> = OnceLock::new();
    X.get_or_init(|| unsafe { load() }).as_ref()
}

/// XShmSegmentInfo (XShm.h).
#[repr(C)]
pub struct XShmSegmentInfo {
    pub shmseg: Xid,
    pub shmid: c_int,
    pub shmaddr: *mut c_char,
    pub readOnly: c_int,
}

/// The MIT-SHM entry points of libXext (XShm.h), for presenting through
/// shared memory.
pub struct Xext {
    pub XShmQueryExtension: unsafe extern "C" fn(*mut Display) -> c_int,
    pub XShmAttach: unsafe extern "C" fn(*mut Display, *mut XShmSegmentInfo) -> c_int,
    pub XShmDetach: unsafe extern "C" fn(*mut Display, *mut XShmSegmentInfo) -> c_int,
    pub XShmPutImage: unsafe extern "C" fn(*mut Display, Xid, Gc, *mut XImage, c_int, c_int, c_int, c_int, c_uint, c_uint, c_int) -> c_int,
}

unsafe fn load_xext() -> Option<Xext> {
    let lib = open_library(c"libXext.so.6");
    if lib.is_null() {
        return None;
    }
    Some(Xext {
        XShmQueryExtension: sym(lib, b"XShmQueryExtension\0")?,
        XShmAttach: sym(lib, b"XShmAttach\0")?,
        XShmDetach: sym(lib, b"XShmDetach\0")?,
        XShmPutImage: sym(lib, b"XShmPutImage\0")?,
    })
}

/// libXext, loaded the first time a surface may use MIT-SHM; None when it
/// is not installed (then presenting uses XPutImage).
pub fn xext() -> Option<&'static Xext> {
    static X: OnceLock<Option<Xext>> = OnceLock::new();
    X.get_or_init(|| unsafe { load_xext() }).as_ref()
}

/// The thread that called exit(), once it has (0 before). libX11 tears
/// down its global lock in its destructor; a program thread still calling
/// GLX then (piglit's glx-multithread-* tests exit from one thread while
/// others make contexts current) would crash inside Xlib. Such threads
/// wait instead for the process to end; the exiting thread itself (its
/// later atexit handlers may still destroy contexts) goes on.
static EXITING: std::sync::atomic::AtomicUsize = std::sync::atomic::AtomicUsize::new(0);

/// The calling thread's identity (never 0).
fn this_thread() -> usize {
    // SAFETY: pthread_self has no preconditions.
    #[cfg(unix)]
    return unsafe { libc::pthread_self() } as usize;
    #[cfg(not(unix))]
    {
        thread_local!(static ID: u8 = const { 0 });
        ID.with(|t| t as *const u8 as usize)
    }
}

extern "C" fn mark_exiting() {
    EXITING.store(this_thread(), std::sync::atomic::Ordering::SeqCst);
}

fn park_if_exiting() {
    let e = EXITING.load(std::sync::atomic::Ordering::SeqCst);
    if e != 0 && e != this_thread() {
        loop {
            std::thread::park();
        }
    }
}

static TRAPPED: std::sync::atomic::AtomicBool = std::sync::atomic::AtomicBool::new(false);
static TRAP: std::sync::Mutex<()> = std::sync::Mutex::new(());

unsafe extern "C" fn note_error(_dpy: *mut Display, _event: *mut c_void) -> c_int {
    TRAPPED.store(true, std::sync::atomic::Ordering::Relaxed);
    0
}

/// Runs `f` (requests on `dpy`) with X errors caught instead of reaching
/// the program's handler (Xlib's default one exits): returns f's result and
/// whether an error came. Requests made before are synced first, so their
/// errors still go to the program. Costs two round trips.
pub unsafe fn trap_errors<R>(x: &Xlib, dpy: *mut Display, f: impl FnOnce() -> R) -> (R, bool) {
    // Checked before each Xlib call: exit() may begin on another thread
    // while this one waits for the lock or for the server. (A thread
    // parked holding the lock would block the exiting thread's own later
    // GLX calls, a far rarer case than this race.)
    park_if_exiting();
    // The handler is process-wide: one trap at a time.
    let _g = TRAP.lock().unwrap_or_else(|e| e.into_inner());
    park_if_exiting();
    (x.XSync)(dpy, 0);
    park_if_exiting();
    let old = (x.XSetErrorHandler)(Some(note_error));
    TRAPPED.store(false, std::sync::atomic::Ordering::Relaxed);
    let r = f();
    park_if_exiting();
    (x.XSync)(dpy, 0);
    park_if_exiting();
    (x.XSetErrorHandler)(old);
    (r, TRAPPED.swap(false, std::sync::atomic::Ordering::Relaxed))
}

/// The errors GLX functions generate (GLX 1.4 section 3.3; the X errors
/// of the core protocol, or GLX's own, numbered from the GLX extension's
/// first error).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum GlxError {
    BadValue,
    BadMatch,
    BadAccess,
    BadAlloc,
    /// GLXBadContext, GLXBadFBConfig (9), GLXBadProfileARB (13), ...
    Glx(u8),
}

/// Reports `err` for GLX request `minor` to the program's X error handler,
/// as a direct-rendering GLX library does for errors it finds itself.
/// (Not through Xlib's internal _XError, which needs the display's
/// internal lock held, something only Xlib's macros can take.)
/// GLX's own errors need the server's GLX extension (for their numbers);
/// without it they are not reported.
pub unsafe fn report_error(dpy: *mut Display, err: GlxError, minor: u16) {
    let Some(x) = xlib() else { return };
    if dpy.is_null() {
        return;
    }
    let (mut major, mut first_event, mut first_error) = (0, 0, 0);
    let has_glx = (x.XQueryExtension)(dpy, c"GLX".as_ptr(), &mut major, &mut first_event, &mut first_error) != 0;
    let code = match err {
        GlxError::BadValue => 2,
        GlxError::BadMatch => 8,
        GlxError::BadAccess => 10,
        GlxError::BadAlloc => 11,
        GlxError::Glx(n) if has_glx => (first_error + n as c_int) as u8,
        GlxError::Glx(_) => return,
    };
    let mut e = XErrorEvent {
        kind: 0,
        display: dpy,
        resourceid: 0,
        // The last request sent: the error belongs to the GLX call made now.
        serial: (x.XNextRequest)(dpy).wrapping_sub(1),
        error_code: code,
        request_code: major as u8,
        minor_code: minor as u8,
    };
    // The program's handler, called as Xlib would (without the display
    // lock held); Xlib's default one prints the error and exits, as for
    // any X error.
    let handler = {
        let _g = TRAP.lock().unwrap_or_else(|e| e.into_inner());
        let h = (x.XSetErrorHandler)(None);
        (x.XSetErrorHandler)(h);
        h
    };
    if let Some(h) = handler {
        h(dpy, &mut e as *mut XErrorEvent as *mut c_void);
    }
}
