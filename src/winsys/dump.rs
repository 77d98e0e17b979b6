//! SOFTGL_DUMP: with SOFTGL_DUMP=DIR in the environment, every presented
//! frame (wglSwapBuffers, and whatever other window systems call
//! [`frame`] at their present) is written as DIR/frame-NNNNN.png, numbered
//! from 00000 in presentation order across the whole process.
//!
//! The PNG is RGB (a window shows no alpha), rows top-down as image
//! viewers expect. The directory is created if missing. A failure to write
//! is reported on stderr once and never reaches the program.
//!
//! SOFTGL_EXIT_AFTER_FRAMES=N: the process exits with status 0 once N
//! frames have been presented (counted here, with or without
//! SOFTGL_DUMP), so that a program that loops forever (glxgears, a GLUT
//! main loop) can be run to capture N frames. The exit happens in
//! [`exit_if_due`], which the window systems call when the presenting
//! call has released its locks (the program's atexit handlers may still
//! call GL or GLX): at the end of glXSwapBuffers, and of the GL call
//! (glFlush, glFinish...) that presented a single-buffered frame.

use crate::framebuffer::Framebuffer;
use std::path::{Path, PathBuf};
use std::sync::atomic::{AtomicBool, AtomicU32, Ordering};
use std::sync::OnceLock;

static NEXT: AtomicU32 = AtomicU32::new(0);
static REPORTED: AtomicBool = AtomicBool::new(false);
/// Frames presented so far (for SOFTGL_EXIT_AFTER_FRAMES).
static PRESENTED: AtomicU32 = AtomicU32::new(0);
/// SOFTGL_EXIT_AFTER_FRAMES was reached: exit at the next `exit_if_due`.
static EXIT_DUE: AtomicBool = AtomicBool::new(false);

/// The dump directory, if SOFTGL_DUMP is set (read once).
pub fn dir() -> Option<&'static Path> {
    static DIR: OnceLock<Option<PathBuf>> = OnceLock::new();
    DIR.get_or_init(|| std::env::var_os("SOFTGL_DUMP").filter(|v| !v.is_empty()).map(PathBuf::from)).as_deref()
}

/// SOFTGL_EXIT_AFTER_FRAMES, if set to a positive number (read once).
pub fn exit_after() -> Option<u32> {
    static N: OnceLock<Option<u32>> = OnceLock::new();
    *N.get_or_init(|| std::env::var("SOFTGL_EXIT_AFTER_FRAMES").ok().and_then(|v| v.trim().parse().ok()).filter(|&n| n > 0))
}

/// Counts a presented frame toward SOFTGL_EXIT_AFTER_FRAMES; true when it
/// is the last one.
fn count_presented(limit: Option<u32>) -> bool {
    let Some(n) = limit else { return false };
    PRESENTED.fetch_add(1, Ordering::Relaxed) + 1 == n
}

/// Exits the process (status 0, atexit handlers and stdio flushed as by
/// exit()) if SOFTGL_EXIT_AFTER_FRAMES frames have been presented. Called
/// by the window systems with no lock held.
pub fn exit_if_due() {
    if EXIT_DUE.load(Ordering::Relaxed) && EXIT_DUE.swap(false, Ordering::SeqCst) {
        // SAFETY: exit() may be called at any time; it does not return.
        unsafe { libc::exit(0) };
    }
}

/// Writes a presented frame if SOFTGL_DUMP is set. Returns the file
/// written. Every call counts as a presented frame for
/// SOFTGL_EXIT_AFTER_FRAMES.
pub fn frame(fb: &Framebuffer) -> Option<PathBuf> {
    if count_presented(exit_after()) {
        EXIT_DUE.store(true, Ordering::SeqCst);
    }
    let dir = dir()?;
    let n = NEXT.fetch_add(1, Ordering::Relaxed);
    let path = dir.join(format!("frame-{n:05}.png"));
    match write_png(&path, fb.width, fb.height, fb.front()) {
        Ok(()) => Some(path),
        Err(e) => {
            if !REPORTED.swap(true, Ordering::Relaxed) {
                eprintln!("softgl: SOFTGL_DUMP: cannot write {}: {e}", path.display());
            }
            None
        }
    }
}

/// Writes RGBA8 pixels given bottom-up (GL's order) as an RGB PNG.
pub fn write_png(path: &Path, width: usize, height: usize, pixels: &[[u8; 4]]) -> Result<(), String> {
    if width == 0 || height == 0 || pixels.len() < width * height {
        return Err("empty image".into());
    }
    if let Some(parent) = path.parent() {
        std::fs::create_dir_all(parent).map_err(|e| e.to_string())?;
    }
    let mut rgb = Vec::with_capacity(width * height * 3);
    for y in (0..height).rev() {
        for p in &pixels[y * width..(y + 1) * width] {
            rgb.extend_from_slice(&p[..3]);
        }
    }
    image::save_buffer(path, &rgb, width as u32, height as u32, image::ColorType::Rgb8).map_err(|e| e.to_string())
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn png_rows_are_top_down() {
        let dir = std::env::temp_dir().join(format!("softgl-dump-test-{}", std::process::id()));
        let path = dir.join("a.png");
        // 2x2: bottom row red, top row green.
        let px = [[255, 0, 0, 255], [255, 0, 0, 255], [0, 255, 0, 0], [0, 255, 0, 0]];
        write_png(&path, 2, 2, &px).unwrap();
        let img = image::open(&path).unwrap().to_rgb8();
        assert_eq!(img.get_pixel(0, 0).0, [0, 255, 0]);
        assert_eq!(img.get_pixel(1, 1).0, [255, 0, 0]);
        let _ = std::fs::remove_dir_all(dir);
    }

    #[test]
    fn exit_counts_to_the_limit_once() {
        // Only the Nth frame is the last one; without a limit none is.
        let before = PRESENTED.load(Ordering::Relaxed);
        let hits: Vec<bool> = (0..5).map(|_| count_presented(Some(before + 3))).collect();
        assert_eq!(hits, [false, false, true, false, false]);
        assert!(!count_presented(None));
    }
}
