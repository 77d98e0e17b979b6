//! Windows only: the device contexts of real windows (GetDC, BeginPaint,
//! memory DCs) for the wgl functions of opengl32.dll ([`super::wgl`]).
//!
//! softgl renders into its own framebuffer, as on Linux; a window's DC
//! gets a [`Dc`] record the first time a wgl call names it, sized from the
//! window's client rectangle (or, for a DC without a window, its selected
//! bitmap) at every later call, and each frame shown on it (SwapBuffers,
//! or glFlush when single-buffered) is drawn into the DC with
//! SetDIBitsToDevice: GDI's own copy, so any window the system can paint
//! works without a driver.
//!
//! Pixel formats: on Windows gdi32's ChoosePixelFormat, SetPixelFormat,
//! DescribePixelFormat and SwapBuffers call the same-named wgl exports of
//! the opengl32.dll the process loaded, so softgl's two formats are the
//! ones a program sees. A DC whose format was set by someone else (Wine's
//! gdi32 keeps its own) gets the buffering gdi32 describes for it.

use super::wgl::{Dc, DcState, Hdc, PixelFormatDescriptor, PFD_DOUBLEBUFFER};
use std::collections::HashMap;
use std::ffi::c_int;
use std::sync::{Arc, Mutex};
use windows_sys::Win32::Foundation::RECT;
use windows_sys::Win32::Graphics::Gdi::{
    GetCurrentObject, GetDeviceCaps, GetObjectType, GetObjectW, SetDIBitsToDevice, WindowFromDC, BITMAP, BITMAPINFO,
    BITMAPINFOHEADER, BI_RGB, DIB_RGB_COLORS, HORZRES, OBJ_BITMAP, OBJ_DC, OBJ_MEMDC, VERTRES,
};
use windows_sys::Win32::Graphics::OpenGL::{DescribePixelFormat, GetPixelFormat, PIXELFORMATDESCRIPTOR};
use windows_sys::Win32::UI::WindowsAndMessaging::GetClientRect;

/// The records of the native DCs named so far, by handle. They live as
/// long as the process (a window's DC handle is reused for the window's
/// life; records are small until a frame is shown).
static NATIVE: Mutex<Option<HashMap<usize, &'static Dc>>> = Mutex::new(None);

/// The drawable size of a native DC: its window's client area, or the
/// bitmap selected into a memory DC, or the device's resolution.
unsafe fn size_of(hdc: Hdc) -> (usize, usize) {
    let hwnd = WindowFromDC(hdc);
    if !hwnd.is_null() {
        let mut r = RECT { left: 0, top: 0, right: 0, bottom: 0 };
        if GetClientRect(hwnd, &mut r) != 0 {
            return ((r.right - r.left).max(1) as usize, (r.bottom - r.top).max(1) as usize);
        }
    }
    let bmp = GetCurrentObject(hdc, OBJ_BITMAP as _);
    if !bmp.is_null() {
        let mut b: BITMAP = std::mem::zeroed();
        if GetObjectW(bmp, std::mem::size_of::<BITMAP>() as c_int, &mut b as *mut BITMAP as *mut _) != 0 && b.bmWidth > 0 && b.bmHeight > 0 {
            return (b.bmWidth as usize, b.bmHeight as usize);
        }
    }
    (GetDeviceCaps(hdc, HORZRES as _).max(1) as usize, GetDeviceCaps(hdc, VERTRES as _).max(1) as usize)
}

/// The record of a native DC (None for anything GDI does not call a DC),
/// its size brought up to date.
pub fn native_dc(hdc: Hdc) -> Option<&'static Dc> {
    if hdc.is_null() {
        return None;
    }
    // SAFETY: GetObjectType accepts any value and answers 0 for what is
    // not a GDI object.
    let kind = unsafe { GetObjectType(hdc) };
    if kind != OBJ_DC as u32 && kind != OBJ_MEMDC as u32 {
        return None;
    }
    // SAFETY: hdc is a DC.
    let (w, h) = unsafe { size_of(hdc) };
    let (w, h) = (w.min(crate::framebuffer::MAX_SIZE), h.min(crate::framebuffer::MAX_SIZE));
    let mut map = NATIVE.lock().unwrap_or_else(|e| e.into_inner());
    let d = *map.get_or_insert_with(HashMap::new).entry(hdc as usize).or_insert_with(|| {
        let state = DcState::new(w, h, hdc as usize);
        Box::leak(Box::new(Dc { state: Arc::new(Mutex::new(state)) }))
    });
    let mut s = d.state.lock().unwrap_or_else(|e| e.into_inner());
    s.width = w;
    s.height = h;
    drop(s);
    Some(d)
}

/// softgl's pixel format (1 double-, 2 single-buffered) for a native DC
/// whose format gdi32 set without telling softgl; 0 when it has none.
pub fn format_from_gdi(hdc: Hdc) -> c_int {
    // SAFETY: hdc is a DC (native_dc checked it); the descriptor is ours.
    unsafe {
        let f = GetPixelFormat(hdc);
        if f <= 0 {
            return 0;
        }
        let mut p: PIXELFORMATDESCRIPTOR = std::mem::zeroed();
        if DescribePixelFormat(hdc, f, std::mem::size_of::<PIXELFORMATDESCRIPTOR>() as u32, &mut p) == 0 {
            return 1;
        }
        if p.dwFlags & PFD_DOUBLEBUFFER != 0 {
            1
        } else {
            2
        }
    }
}

/// Draws a shown frame (RGBA8, rows bottom-up) into the DC.
pub fn blit(hdc: usize, rgba: &[[u8; 4]], w: usize, h: usize) {
    if w == 0 || h == 0 || rgba.len() < w * h {
        return;
    }
    // GDI's 32-bit DIBs are BGRX.
    let bgra: Vec<[u8; 4]> = rgba[..w * h].iter().map(|&[r, g, b, a]| [b, g, r, a]).collect();
    // SAFETY: an all-zero BITMAPINFO is valid; the header is filled below.
    let mut bmi: BITMAPINFO = unsafe { std::mem::zeroed() };
    bmi.bmiHeader = BITMAPINFOHEADER {
        biSize: std::mem::size_of::<BITMAPINFOHEADER>() as u32,
        biWidth: w as i32,
        // Positive: bottom-up rows, as GL's.
        biHeight: h as i32,
        biPlanes: 1,
        biBitCount: 32,
        biCompression: BI_RGB,
        ..bmi.bmiHeader
    };
    // SAFETY: bgra holds w * h pixels as the header describes.
    unsafe {
        SetDIBitsToDevice(hdc as Hdc, 0, 0, w as u32, h as u32, 0, 0, 0, h as u32, bgra.as_ptr() as *const _, &bmi, DIB_RGB_COLORS);
    }
}

// The descriptor layouts must agree: gdi32 and programs pass either.
const _: () = assert!(std::mem::size_of::<PixelFormatDescriptor>() == std::mem::size_of::<PIXELFORMATDESCRIPTOR>());
