//! Presenting: putting a finished frame (the front colour buffer) into an
//! X drawable. Rows are flipped to X's top-down order and pixels packed in
//! the visual's channel masks, then sent one of two ways:
//!
//! * MIT-SHM (the X server's shared-memory extension, libXext loaded at
//!   run time): the frame is converted straight into a System V segment
//!   the server has attached, and XShmPutImage makes the server copy it;
//!   no pixel crosses the socket. Used when the connection is a local
//!   (AF_UNIX) socket, the server has the extension and XShmAttach
//!   succeeds (its X error, e.g. BadAccess from a server that cannot map
//!   the segment, is trapped; the surface then falls back for good).
//!   After each XShmPutImage a round trip (XSync) makes sure the server has
//!   read the segment before the next frame overwrites it.
//!
//! Either way errors are trapped (xlib::trap_errors: two round trips per
//! frame), so a drawable destroyed under a bound context costs a lost
//! frame, never a BadDrawable in the program's error handler.
//! * XPutImage: the frame goes through the socket in the X protocol.
//!
//! `SOFTGL_NO_SHM=1` forces XPutImage. The segment is made at the first
//! frame, made again when the drawable's size changes, and detached and
//! removed when the surface is dropped (its drawable destroyed or its
//! display closed).

use super::xlib::{self, xext, xlib, Display, XImage, XShmSegmentInfo, Xid};
use crate::framebuffer::Framebuffer;
use std::ffi::{c_char, c_int, c_uint, c_ulong};
use std::ptr::null_mut;

/// A System V shared-memory segment the X server has attached.
struct Segment {
    /// Boxed: XShmPutImage finds it through the XImage's obdata.
    info: Box<XShmSegmentInfo>,
    /// Size in bytes.
    size: usize,
}

/// An X drawable as a place to put finished frames.
pub struct XSurface {
    dpy: *mut Display,
    drawable: Xid,
    gc: xlib::Gc,
    depth: c_int,
    masks: [c_ulong; 3],
    /// The converted frame, for XPutImage.
    pixels: Vec<u32>,
    shm: Option<Segment>,
    /// MIT-SHM may be tried (cleared when it fails once).
    try_shm: bool,
}

// SAFETY: the surface belongs to a drawable that contexts in several
// threads may present to, always under the drawable's mutex; Xlib calls
// from several threads are the program's business (XInitThreads).
unsafe impl Send for XSurface {}

/// Whether `dpy` talks to its server over a local socket, where shared
/// memory is possible.
#[cfg(not(unix))]
unsafe fn is_local(_: &xlib::Xlib, _: *mut Display) -> bool {
    false
}

#[cfg(unix)]
unsafe fn is_local(x: &xlib::Xlib, dpy: *mut Display) -> bool {
    let fd = (x.XConnectionNumber)(dpy);
    let mut addr: libc::sockaddr_storage = std::mem::zeroed();
    let mut len = std::mem::size_of::<libc::sockaddr_storage>() as libc::socklen_t;
    libc::getsockname(fd, &mut addr as *mut _ as *mut libc::sockaddr, &mut len) == 0 && addr.ss_family as c_int == libc::AF_UNIX
}

impl XSurface {
    pub unsafe fn new(dpy: *mut Display, drawable: Xid, depth: c_int, masks: [c_ulong; 3]) -> Option<XSurface> {
        let x = xlib()?;
        let gc = (x.XCreateGC)(dpy, drawable, 0, null_mut());
        if gc.is_null() {
            return None;
        }
        let try_shm = std::env::var_os("SOFTGL_NO_SHM").is_none_or(|v| v.is_empty() || v == "0") && is_local(x, dpy);
        Some(XSurface { dpy, drawable, gc, depth, masks, pixels: Vec::new(), shm: None, try_shm })
    }

    /// Whether the last frame went through MIT-SHM.
    pub fn uses_shm(&self) -> bool {
        self.shm.is_some()
    }

    /// Packs the front buffer into `dst` (w*h words, top row first).
    fn convert(&self, fb: &Framebuffer, dst: &mut [u32]) {
        let (w, h) = (fb.width, fb.height);
        // On a depth-32 visual the bits outside R, G and B hold alpha.
        let rest = !(self.masks[0] | self.masks[1] | self.masks[2]) & 0xffff_ffff;
        let alpha = if self.depth == 32 && super::is_8bit(rest) { Some(rest.trailing_zeros()) } else { None };
        let front = fb.front();
        for (y, out) in (0..h).rev().zip(dst.chunks_exact_mut(w)) {
            pack_row(&front[fb.index(0, y)..fb.index(0, y) + w], out, self.masks, alpha);
        }
    }

    fn image(&self, w: usize, h: usize, data: *mut c_char) -> XImage {
        XImage {
            width: w as c_int,
            height: h as c_int,
            xoffset: 0,
            format: xlib::ZPixmap,
            data,
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
        }
    }

    /// Shows `fb`'s front buffer in the drawable.
    pub fn put(&mut self, fb: &Framebuffer) {
        crate::winsys::dump::frame(fb);
        let (w, h) = (fb.width, fb.height);
        if w == 0 || h == 0 {
            return;
        }
        // SAFETY: the display and drawable were valid when bound; the
        // program keeps them while a context draws to them.
        // Errors are caught: the drawable may be gone (a pixmap freed
        // while a context was still bound to it, presented at release).
        let Some(x) = xlib() else { return };
        unsafe {
            let shm = self.try_shm && self.ensure_segment(w * h * 4);
            let dpy = self.dpy;
            xlib::trap_errors(x, dpy, || {
                if !(shm && self.put_shm(fb)) {
                    self.put_plain(fb);
                }
            });
        }
    }

    unsafe fn put_plain(&mut self, fb: &Framebuffer) {
        let Some(x) = xlib() else { return };
        let (w, h) = (fb.width, fb.height);
        let mut pixels = std::mem::take(&mut self.pixels);
        pixels.clear();
        pixels.resize(w * h, 0);
        self.convert(fb, &mut pixels);
        let mut img = self.image(w, h, pixels.as_mut_ptr() as *mut c_char);
        if (x.XInitImage)(&mut img) != 0 {
            (x.XPutImage)(self.dpy, self.drawable, self.gc, &mut img, 0, 0, 0, 0, w as c_uint, h as c_uint);
        }
        self.pixels = pixels;
    }

    /// Makes sure a segment of `need` bytes is attached (made again when
    /// the size changed); false when MIT-SHM is not possible (then it is
    /// not tried again for this surface).
    unsafe fn ensure_segment(&mut self, need: usize) -> bool {
        if self.shm.as_ref().is_some_and(|s| s.size != need) {
            self.free_shm();
        }
        if self.shm.is_none() {
            match self.attach(need) {
                Some(s) => self.shm = Some(s),
                None => {
                    self.try_shm = false;
                    return false;
                }
            }
        }
        true
    }

    /// MIT-SHM presentation through the attached segment.
    unsafe fn put_shm(&mut self, fb: &Framebuffer) -> bool {
        let (Some(x), Some(e)) = (xlib(), xext()) else { return false };
        let (w, h) = (fb.width, fb.height);
        let Some(seg) = self.shm.as_mut() else { return false };
        if seg.size != w * h * 4 {
            return false;
        }
        let info: *mut XShmSegmentInfo = &mut *seg.info;
        let data = (*info).shmaddr;
        // SAFETY: the segment is `need` bytes, page-aligned.
        let dst = std::slice::from_raw_parts_mut(data as *mut u32, w * h);
        self.convert(fb, dst);
        let mut img = self.image(w, h, data);
        img.obdata = info as *mut c_char;
        if (x.XInitImage)(&mut img) == 0 {
            return false;
        }
        // The server reads the segment asynchronously: the caller's round
        // trip (trap_errors) waits for it before the next frame is written
        // over it.
        (e.XShmPutImage)(self.dpy, self.drawable, self.gc, &mut img, 0, 0, 0, 0, w as c_uint, h as c_uint, 0);
        true
    }

    /// Makes a segment of `size` bytes and has the server attach it.
    #[cfg(not(unix))]
    unsafe fn attach(&self, _: usize) -> Option<Segment> {
        None
    }

    /// Makes a segment of `size` bytes and has the server attach it.
    #[cfg(unix)]
    unsafe fn attach(&self, size: usize) -> Option<Segment> {
        let (x, e) = (xlib()?, xext()?);
        if (e.XShmQueryExtension)(self.dpy) == 0 {
            return None;
        }
        let id = libc::shmget(libc::IPC_PRIVATE, size, libc::IPC_CREAT | 0o600);
        if id < 0 {
            return None;
        }
        let addr = libc::shmat(id, std::ptr::null(), 0);
        if addr as isize == -1 {
            libc::shmctl(id, libc::IPC_RMID, null_mut());
            return None;
        }
        let mut info = Box::new(XShmSegmentInfo { shmseg: 0, shmid: id, shmaddr: addr as *mut c_char, readOnly: 0 });
        // A server on another host, or one not allowed to map the
        // segment, answers with an X error: caught, and XPutImage is used.
        let (ok, failed) = xlib::trap_errors(x, self.dpy, || (e.XShmAttach)(self.dpy, &mut *info));
        // Marked for removal now: it goes when both sides have detached.
        libc::shmctl(id, libc::IPC_RMID, null_mut());
        if ok == 0 || failed {
            libc::shmdt(addr);
            return None;
        }
        Some(Segment { info, size })
    }

    unsafe fn free_shm(&mut self) {
        if let Some(mut s) = self.shm.take() {
            if let Some(e) = xext() {
                (e.XShmDetach)(self.dpy, &mut *s.info);
            }
            if let Some(x) = xlib() {
                // The server detaches before the memory goes.
                (x.XSync)(self.dpy, 0);
            }
            #[cfg(unix)]
            libc::shmdt(s.info.shmaddr as *const libc::c_void);
        }
    }
}

/// Packs RGBA8 pixels into words with the visual's channel masks (and
/// alpha at bit `alpha`, on a depth-32 visual).
fn pack_row(row: &[[u8; 4]], out: &mut [u32], masks: [c_ulong; 3], alpha: Option<u32>) {
    if masks == [0xff_0000, 0xff00, 0xff] && alpha.is_none_or(|s| s == 24) {
        // The usual visual (0x00RRGGBB, or AARRGGBB): red and blue trade
        // places in the little-endian word, a form the compiler turns into
        // a few SIMD instructions per 4 pixels.
        let keep = if alpha.is_some() { 0xff00_ff00 } else { 0x0000_ff00 };
        for (o, c) in out.iter_mut().zip(row) {
            let v = u32::from_le_bytes(*c);
            *o = (v & keep) | ((v & 0xff) << 16) | ((v >> 16) & 0xff);
        }
        return;
    }
    let [rs, gs, bs] = masks.map(|m| m.trailing_zeros());
    match alpha {
        None => {
            for (o, c) in out.iter_mut().zip(row) {
                *o = ((c[0] as u32) << rs) | ((c[1] as u32) << gs) | ((c[2] as u32) << bs);
            }
        }
        Some(s) => {
            for (o, c) in out.iter_mut().zip(row) {
                *o = ((c[0] as u32) << rs) | ((c[1] as u32) << gs) | ((c[2] as u32) << bs) | ((c[3] as u32) << s);
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The general packing, written out per channel.
    fn packed(c: [u8; 4], masks: [c_ulong; 3], alpha: Option<u32>) -> u32 {
        let mut v = 0;
        for (ch, m) in c.iter().zip(masks) {
            v |= (*ch as u32) << m.trailing_zeros();
        }
        v | alpha.map_or(0, |s| (c[3] as u32) << s)
    }

    #[test]
    fn pack_row_matches_the_masks() {
        let mut seed = 0x1234_5678u32;
        let row: Vec<[u8; 4]> = (0..67)
            .map(|_| {
                seed = seed.wrapping_mul(1_664_525).wrapping_add(1_013_904_223);
                seed.to_le_bytes()
            })
            .collect();
        let bgr = [0xff, 0xff00, 0xff_0000];
        let rgb = [0xff_0000, 0xff00, 0xff];
        for (masks, alpha) in [(rgb, None), (rgb, Some(24)), (bgr, None), (bgr, Some(24)), (rgb, Some(0))] {
            let mut out = vec![0u32; row.len()];
            pack_row(&row, &mut out, masks, alpha);
            for (o, c) in out.iter().zip(&row) {
                assert_eq!(*o, packed(*c, masks, alpha), "masks {masks:x?} alpha {alpha:?}");
            }
        }
    }
}

impl Drop for XSurface {
    fn drop(&mut self) {
        // SAFETY: the GC and segment were made on this display, which the
        // program must keep open while its drawables are in use (a closed
        // display drops its surfaces first: see the close hook in mod.rs).
        unsafe {
            self.free_shm();
            if let Some(x) = xlib() {
                (x.XFreeGC)(self.dpy, self.gc);
            }
        }
    }
}
