//! SOFTGL_DUMP: with SOFTGL_DUMP=DIR in the environment, every presented
//! frame (wglSwapBuffers, and whatever other window systems call
//! [`frame`] at their present) is written as DIR/frame-NNNNN.png, numbered
//! from 00000 in presentation order across the whole process.
//!
//! The PNG is RGB (a window shows no alpha), rows top-down as image
//! viewers expect. The directory is created if missing. A failure to write
//! is reported on stderr once and never reaches the program.

use crate::framebuffer::Framebuffer;
use std::path::{Path, PathBuf};
use std::sync::atomic::{AtomicBool, AtomicU32, Ordering};
use std::sync::OnceLock;

static NEXT: AtomicU32 = AtomicU32::new(0);
static REPORTED: AtomicBool = AtomicBool::new(false);

/// The dump directory, if SOFTGL_DUMP is set (read once).
pub fn dir() -> Option<&'static Path> {
    static DIR: OnceLock<Option<PathBuf>> = OnceLock::new();
    DIR.get_or_init(|| std::env::var_os("SOFTGL_DUMP").filter(|v| !v.is_empty()).map(PathBuf::from)).as_deref()
}

/// Writes a presented frame if SOFTGL_DUMP is set. Returns the file
/// written.
pub fn frame(fb: &Framebuffer) -> Option<PathBuf> {
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
}
