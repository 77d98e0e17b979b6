//! SOFTGL_DUMP with OSMesa: glFinish presents the frame, which is written
//! as a PNG, top row first.

use softgl::api::table::*;
use softgl::gl::enums::*;
use softgl::winsys::osmesa;

#[test]
fn osmesa_frames_are_dumped() {
    let dir = std::env::temp_dir().join(format!("softgl-dump-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    // This test binary holds only this test, so the variable is set before
    // the dump module first reads it.
    std::env::set_var("SOFTGL_DUMP", &dir);
    let mut buf = vec![0u8; 8 * 4 * 4];
    unsafe {
        let ctx = osmesa::create_context_ext(GL_RGBA, 24, 8, 0, std::ptr::null_mut());
        assert!(osmesa::make_current(ctx, buf.as_mut_ptr() as *mut _, GL_UNSIGNED_BYTE, 8, 4));
        glClearColor(1.0, 0.0, 0.0, 1.0);
        glClear(GL_COLOR_BUFFER_BIT);
        glScissor(0, 0, 8, 1);
        glEnable(GL_SCISSOR_TEST);
        glClearColor(0.0, 0.0, 1.0, 1.0);
        glClear(GL_COLOR_BUFFER_BIT);
        glFinish();
        osmesa::destroy_context(ctx);
    }
    let img = image::open(dir.join("frame-00000.png")).unwrap().to_rgba8();
    assert_eq!(img.dimensions(), (8, 4));
    assert_eq!(img.get_pixel(0, 0).0, [255, 0, 0, 255], "top row: red");
    assert_eq!(img.get_pixel(0, 3).0, [0, 0, 255, 255], "bottom row (window y 0): blue");
    let _ = std::fs::remove_dir_all(&dir);
}
