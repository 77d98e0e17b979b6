//! The asynchronous flush (render::tile) against every sync point, through
//! the C entry points of an OSMesa context (where the batch stays pending
//! across calls): the same command stream drawn with 1, 2 and 3 rasterizer
//! threads must give the same glReadPixels results at each point, the same
//! occlusion counts and the same final image. The batch limits are set
//! tiny, so that batches are handed to the workers every few triangles and
//! are usually still in flight when the next command arrives.

use softgl::api::table::*;
use softgl::gl::enums::*;
use softgl::winsys::osmesa::OsContext;
use std::ffi::c_void;

const W: i32 = 160;
const H: i32 = 120;
const GL_SAMPLES_PASSED: u32 = 0x8914;
const GL_QUERY_RESULT: u32 = 0x8866;
const GL_TEXTURE_MIN_FILTER: u32 = 0x2801;
const GL_LINEAR: i32 = 0x2601;

struct Rng(u64);

impl Rng {
    fn next(&mut self) -> u32 {
        self.0 = self.0.wrapping_mul(6364136223846793005).wrapping_add(1442695040888963407);
        (self.0 >> 33) as u32
    }
    fn unit(&mut self) -> f32 {
        (self.next() % 10_000) as f32 / 10_000.0
    }
}

/// A context of `threads` rasterizer threads drawing into `buf`.
unsafe fn context(threads: usize, buf: &mut [u8]) -> *mut OsContext {
    context_of(threads, buf, W, H)
}

/// [`context`] of `w` x `h` pixels.
unsafe fn context_of(threads: usize, buf: &mut [u8], w: i32, h: i32) -> *mut OsContext {
    // The pool's workers start with the first current context, as many as
    // the default thread count asks for (one on a 2-core machine); these
    // tests draw with up to 3 threads, so they ask for 3 before any
    // context exists (every test here comes through this function).
    std::env::set_var("SOFTGL_THREADS", "3");
    assert!(softgl::render::tile::threads_default() >= 3, "the pool would have fewer workers than the tests use");
    let ctx = OSMesaCreateContextExt(GL_RGBA, 24, 8, 16, std::ptr::null_mut());
    assert!(!ctx.is_null());
    assert_eq!(OSMesaMakeCurrent(ctx, buf.as_mut_ptr() as *mut c_void, GL_UNSIGNED_BYTE, w, h), 1);
    let rs = &mut (*ctx).gl.derived.render;
    rs.threads = threads;
    softgl::render::tile::set_batch_limits(rs, 7, 0, 0);
    ctx
}

/// `n` random triangles, some textured (texture coordinates always given).
unsafe fn triangles(r: &mut Rng, n: usize) {
    glBegin(GL_TRIANGLES);
    for _ in 0..n {
        let (cx, cy) = (r.unit() * 2.4 - 1.2, r.unit() * 2.4 - 1.2);
        let size = if r.next() % 8 == 0 { 1.5 } else { 0.3 };
        for _ in 0..3 {
            glColor4ub(r.next() as u8, r.next() as u8, r.next() as u8, r.next() as u8);
            glTexCoord2f(r.unit() * 2.0, r.unit() * 2.0);
            glVertex3f(cx + (r.unit() - 0.5) * size, cy + (r.unit() - 0.5) * size, r.unit() * 2.0 - 1.0);
        }
    }
    glEnd();
}

unsafe fn read(out: &mut Vec<Vec<u8>>) {
    read_of(out, W, H);
}

unsafe fn read_of(out: &mut Vec<Vec<u8>>, w: i32, h: i32) {
    let mut px = vec![0u8; (w * h * 4) as usize];
    glReadPixels(0, 0, w, h, GL_RGBA, GL_UNSIGNED_BYTE, px.as_mut_ptr() as *mut c_void);
    out.push(px);
}

/// Reads back the depth (32-bit) and stencil (bytes) of a w x h window.
unsafe fn read_depth_stencil_of(out: &mut Vec<Vec<u8>>, w: i32, h: i32) {
    let mut d = vec![0u8; (w * h * 4) as usize];
    glReadPixels(0, 0, w, h, GL_DEPTH_COMPONENT, GL_UNSIGNED_INT, d.as_mut_ptr() as *mut c_void);
    out.push(d);
    let mut s = vec![0u8; (w * h) as usize];
    glPixelStorei(GL_PACK_ALIGNMENT, 1);
    glReadPixels(0, 0, w, h, GL_STENCIL_INDEX, GL_UNSIGNED_BYTE, s.as_mut_ptr() as *mut c_void);
    glPixelStorei(GL_PACK_ALIGNMENT, 4);
    out.push(s);
}

unsafe fn texture_image(r: &mut Rng, sub: bool) {
    let texels: Vec<u8> = (0..16 * 16 * 4).map(|_| r.next() as u8).collect();
    if sub {
        glTexSubImage2D(GL_TEXTURE_2D, 0, 4, 4, 8, 8, GL_RGBA, GL_UNSIGNED_BYTE, texels.as_ptr() as *const c_void);
    } else {
        glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA as i32, 16, 16, 0, GL_RGBA, GL_UNSIGNED_BYTE, texels.as_ptr() as *const c_void);
    }
}

/// The command stream: draws between every kind of sync point; returns
/// the read-backs, occlusion counts and final image.
unsafe fn scene(threads: usize) -> Vec<Vec<u8>> {
    let mut buf = vec![0u8; (W * H * 4) as usize];
    let mut other = vec![0u8; (W * H * 4) as usize];
    let ctx = context(threads, &mut buf);
    let mut r = Rng(0x5eed);
    let mut out = Vec::new();
    glClearColor(0.1, 0.2, 0.3, 0.4);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    glEnable(GL_DEPTH_TEST);
    // Read-back between draws.
    triangles(&mut r, 60);
    read(&mut out);
    // A texture re-specified, partly replaced and deleted while triangles
    // sampling it may be in flight.
    let mut tex = 0u32;
    glGenTextures(1, &mut tex);
    glBindTexture(GL_TEXTURE_2D, tex);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
    texture_image(&mut r, false);
    glEnable(GL_TEXTURE_2D);
    triangles(&mut r, 40);
    texture_image(&mut r, false);
    triangles(&mut r, 40);
    texture_image(&mut r, true);
    triangles(&mut r, 40);
    glDeleteTextures(1, &tex);
    triangles(&mut r, 40);
    glDisable(GL_TEXTURE_2D);
    // A clear (scissored) between draws, blending.
    glEnable(GL_SCISSOR_TEST);
    glScissor(20, 10, 90, 70);
    glClear(GL_COLOR_BUFFER_BIT);
    glDisable(GL_SCISSOR_TEST);
    glEnable(GL_BLEND);
    glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
    triangles(&mut r, 50);
    read(&mut out);
    // The accumulation buffer between draws.
    glAccum(GL_LOAD, 0.5);
    triangles(&mut r, 50);
    glAccum(GL_ACCUM, 0.5);
    triangles(&mut r, 30);
    glAccum(GL_RETURN, 1.0);
    triangles(&mut r, 30);
    // Pixel rectangles between draws.
    glRasterPos2i(0, 0);
    glCopyPixels(10, 10, 50, 40, GL_COLOR);
    triangles(&mut r, 30);
    let image: Vec<u8> = (0..32 * 32 * 4).map(|_| r.next() as u8).collect();
    glRasterPos2i(0, 0);
    glDrawPixels(32, 32, GL_RGBA, GL_UNSIGNED_BYTE, image.as_ptr() as *const c_void);
    triangles(&mut r, 30);
    let bitmap = [0xA5u8; 32 * 4];
    glBitmap(32, 32, 0.0, 0.0, 0.0, 0.0, bitmap.as_ptr());
    triangles(&mut r, 30);
    glDisable(GL_BLEND);
    read(&mut out);
    // An occlusion query around draws.
    let mut q = 0u32;
    glGenQueries(1, &mut q);
    glBeginQuery(GL_SAMPLES_PASSED, q);
    triangles(&mut r, 80);
    glEndQuery(GL_SAMPLES_PASSED);
    let mut passed = 0u32;
    glGetQueryObjectuiv(q, GL_QUERY_RESULT, &mut passed);
    out.push(passed.to_le_bytes().to_vec());
    // A switch to another context and back, batches pending in both.
    triangles(&mut r, 40);
    let second = context(threads, &mut other);
    glEnable(GL_DEPTH_TEST);
    triangles(&mut r, 40);
    assert_eq!(OSMesaMakeCurrent(ctx, buf.as_mut_ptr() as *mut c_void, GL_UNSIGNED_BYTE, W, H), 1);
    triangles(&mut r, 40);
    // glFinish hands the image over; then the second context's.
    glFinish();
    out.push(buf.clone());
    assert_eq!(OSMesaMakeCurrent(second, other.as_mut_ptr() as *mut c_void, GL_UNSIGNED_BYTE, W, H), 1);
    triangles(&mut r, 40);
    // Destroyed with a batch pending.
    OSMesaDestroyContext(second);
    out.push(other.clone());
    OSMesaDestroyContext(ctx);
    out
}

/// Asserts that two runs of a scene read back the same bytes; `what`
/// names the case (seed, limits, thread counts) in the message.
fn assert_same_read_backs(one: &[Vec<u8>], other: &[Vec<u8>], what: &str) {
    assert_eq!(one.len(), other.len(), "{what}: read-back counts differ");
    for (k, (a, b)) in one.iter().zip(other).enumerate() {
        let diff = a.iter().zip(b).filter(|(x, y)| x != y).count();
        assert_eq!(diff, 0, "{what}: read-back {k} differs in {diff} bytes");
    }
}

#[test]
fn sync_points_do_not_depend_on_thread_count() {
    let before = softgl::render::tile::flights_started();
    let one = unsafe { scene(1) };
    // Not vacuous: the read-backs differ from each other and show drawing.
    for w in one.windows(2) {
        assert_ne!(w[0], w[1]);
    }
    assert!(u32::from_le_bytes(one[3][..4].try_into().unwrap()) > 1000, "the query counts samples");
    for round in 0..4 {
        for threads in [2, 3] {
            let many = unsafe { scene(threads) };
            assert_same_read_backs(&one, &many, &format!("round {round}, 1 thread / {threads} threads"));
        }
    }
    assert!(softgl::render::tile::flights_started() - before > 100, "batches went to the workers");
}

const W2: i32 = 320;
const H2: i32 = 240;

/// Random vertices for lines and points, many crossing the whole window
/// (so across every band), some textured.
unsafe fn line_vertices(r: &mut Rng, mode: u32, n: usize) {
    glBegin(mode);
    for _ in 0..n {
        let reach = if r.next() % 3 == 0 { 2.4 } else { 0.6 };
        glColor4ub(r.next() as u8, r.next() as u8, r.next() as u8, 128 + (r.next() % 128) as u8);
        glTexCoord2f(r.unit() * 2.0, r.unit() * 2.0);
        glVertex3f((r.unit() - 0.5) * reach, (r.unit() - 0.5) * reach, r.unit() * 2.0 - 1.0);
    }
    glEnd();
}

/// Lines (wide, stippled strips and loops whose pattern runs on across
/// bands, smooth, textured, fogged), points (aliased, large, smooth)
/// between triangles, and every glAccum operation on a surface large
/// enough for the accumulation buffer's bands to be shared among threads.
unsafe fn lines_scene(threads: usize) -> Vec<Vec<u8>> {
    let mut buf = vec![0u8; (W2 * H2 * 4) as usize];
    let ctx = context_of(threads, &mut buf, W2, H2);
    let mut r = Rng(0x11e5);
    let mut out = Vec::new();
    glClearColor(0.2, 0.1, 0.3, 1.0);
    glClearAccum(0.1, -0.2, 0.3, 0.0);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT | GL_ACCUM_BUFFER_BIT);
    glEnable(GL_DEPTH_TEST);
    triangles(&mut r, 30);
    for width in [1.0, 3.0, 6.0] {
        glLineWidth(width);
        line_vertices(&mut r, GL_LINES, 40);
    }
    glEnable(GL_LINE_STIPPLE);
    glLineStipple(3, 0x1C47);
    glLineWidth(2.0);
    line_vertices(&mut r, GL_LINE_STRIP, 30);
    glLineStipple(1, 0xF0F3);
    glLineWidth(1.0);
    line_vertices(&mut r, GL_LINE_LOOP, 25);
    line_vertices(&mut r, GL_LINES, 30);
    glDisable(GL_LINE_STIPPLE);
    read_of(&mut out, W2, H2);
    // Smooth lines, blended, then flat-shaded and textured ones.
    glEnable(GL_LINE_SMOOTH);
    glEnable(GL_BLEND);
    glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
    for width in [1.5, 3.0] {
        glLineWidth(width);
        line_vertices(&mut r, GL_LINES, 60);
    }
    glDisable(GL_LINE_SMOOTH);
    glDisable(GL_BLEND);
    glShadeModel(GL_FLAT);
    line_vertices(&mut r, GL_LINE_STRIP, 20);
    glShadeModel(GL_SMOOTH);
    let mut tex = 0u32;
    glGenTextures(1, &mut tex);
    glBindTexture(GL_TEXTURE_2D, tex);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
    texture_image(&mut r, false);
    glEnable(GL_TEXTURE_2D);
    glEnable(GL_FOG);
    glLineWidth(2.0);
    line_vertices(&mut r, GL_LINES, 40);
    glPointSize(4.0);
    line_vertices(&mut r, GL_POINTS, 60);
    glDisable(GL_TEXTURE_2D);
    glDisable(GL_FOG);
    // Points: 1 and 9 pixels, smooth.
    for size in [1.0, 9.0] {
        glPointSize(size);
        line_vertices(&mut r, GL_POINTS, 200);
    }
    glEnable(GL_POINT_SMOOTH);
    glPointSize(5.0);
    line_vertices(&mut r, GL_POINTS, 50);
    glDisable(GL_POINT_SMOOTH);
    glPointSize(1.0);
    glLineWidth(1.0);
    read_of(&mut out, W2, H2);
    // Every accumulation operation, drawing between them.
    glAccum(GL_ACCUM, 0.3);
    triangles(&mut r, 20);
    line_vertices(&mut r, GL_LINES, 20);
    glAccum(GL_LOAD, 0.7);
    glAccum(GL_MULT, 0.9);
    glAccum(GL_ADD, -0.05);
    triangles(&mut r, 20);
    glAccum(GL_ACCUM, -0.4);
    glAccum(GL_RETURN, 1.3);
    read_of(&mut out, W2, H2);
    glEnable(GL_SCISSOR_TEST);
    glScissor(30, 20, 250, 190);
    glColorMask(1, 0, 1, 1);
    glAccum(GL_RETURN, 0.8);
    glColorMask(1, 1, 1, 1);
    glDisable(GL_SCISSOR_TEST);
    line_vertices(&mut r, GL_LINES, 20);
    glFinish();
    out.push(buf.clone());
    OSMesaDestroyContext(ctx);
    out
}

#[test]
fn lines_points_and_accum_do_not_depend_on_thread_count() {
    let before = softgl::render::tile::flights_started();
    let one = unsafe { lines_scene(1) };
    for w in one.windows(2) {
        assert_ne!(w[0], w[1], "each step draws");
    }
    for threads in [2, 3] {
        let many = unsafe { lines_scene(threads) };
        assert_same_read_backs(&one, &many, &format!("1 thread / {threads} threads"));
    }
    assert!(softgl::render::tile::flights_started() - before > 50, "primitives went to the workers");
}

const W3: i32 = 640;
const H3: i32 = 480;

/// Whole-frame operations large enough to be cut into bands of rows for
/// the threads (round 7): clears (whole, masked, scissored), glReadPixels
/// into plain and padded, offset client layouts, and accumulation
/// sequences whose recorded clear is dropped by a covering GL_LOAD, filled
/// before a GL_ACCUM, or filled when a later clear does not cover it; tall
/// stippled strips between them.
unsafe fn frame_ops_scene(threads: usize) -> Vec<Vec<u8>> {
    let mut buf = vec![0u8; (W3 * H3 * 4) as usize];
    let ctx = context_of(threads, &mut buf, W3, H3);
    let mut r = Rng(0xf4a3e);
    let mut out = Vec::new();
    glClearColor(0.3, 0.2, 0.1, 0.5);
    glClearStencil(0x5a);
    glClearAccum(0.25, -0.5, 0.75, 0.1);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT | GL_STENCIL_BUFFER_BIT | GL_ACCUM_BUFFER_BIT);
    glEnable(GL_DEPTH_TEST);
    triangles(&mut r, 40);
    read_of(&mut out, W3, H3);
    // A masked colour clear and a scissored depth and stencil clear.
    glColorMask(1, 0, 1, 0);
    glClearColor(0.9, 0.9, 0.05, 0.9);
    glClear(GL_COLOR_BUFFER_BIT);
    glColorMask(1, 1, 1, 1);
    glEnable(GL_SCISSOR_TEST);
    glScissor(37, 21, 555, 433);
    glClearDepth(0.3);
    glStencilMask(0x0f);
    glClear(GL_DEPTH_BUFFER_BIT | GL_STENCIL_BUFFER_BIT);
    glStencilMask(0xff);
    glDisable(GL_SCISSOR_TEST);
    triangles(&mut r, 40);
    read_of(&mut out, W3, H3);
    // Padded, offset client layout; a sub-rectangle.
    for (row_len, align, skip) in [(W3 + 13, 8, 3), (0, 1, 0)] {
        glPixelStorei(GL_PACK_ROW_LENGTH, row_len);
        glPixelStorei(GL_PACK_ALIGNMENT, align);
        glPixelStorei(GL_PACK_SKIP_ROWS, skip);
        glPixelStorei(GL_PACK_SKIP_PIXELS, skip);
        let stride = ((if row_len > 0 { row_len } else { 600 }) * 4 + align - 1) / align * align;
        let mut px = vec![0xeeu8; (stride * (470 + skip) + 64) as usize];
        glReadPixels(20, 7, 600, 470, GL_RGBA, GL_UNSIGNED_BYTE, px.as_mut_ptr() as *mut c_void);
        out.push(px);
    }
    glPixelStorei(GL_PACK_ROW_LENGTH, 0);
    glPixelStorei(GL_PACK_ALIGNMENT, 4);
    glPixelStorei(GL_PACK_SKIP_ROWS, 0);
    glPixelStorei(GL_PACK_SKIP_PIXELS, 0);
    // Tall stippled strips across many bands.
    glEnable(GL_LINE_STIPPLE);
    glLineStipple(2, 0x33F1);
    glBegin(GL_LINE_STRIP);
    for _ in 0..12 {
        glColor3ub(r.next() as u8, r.next() as u8, r.next() as u8);
        glVertex3f(r.unit() * 1.8 - 0.9, if r.next() % 2 == 0 { -0.99 } else { 0.99 }, 0.0);
    }
    glEnd();
    glDisable(GL_LINE_STIPPLE);
    // LOAD over a full-window recorded clear; ACCUM; a scissored clear
    // (recorded) then ACCUM (fills it first); a full clear then a
    // scissored one (the first filled); MULT, ADD, RETURN.
    glAccum(GL_LOAD, 0.5);
    triangles(&mut r, 30);
    glAccum(GL_ACCUM, 0.25);
    glEnable(GL_SCISSOR_TEST);
    glScissor(100, 50, 300, 300);
    glClear(GL_ACCUM_BUFFER_BIT);
    glDisable(GL_SCISSOR_TEST);
    glAccum(GL_ACCUM, 0.5);
    glAccum(GL_RETURN, 1.0);
    read_of(&mut out, W3, H3);
    glClearAccum(-0.1, 0.2, 0.4, 0.9);
    glClear(GL_ACCUM_BUFFER_BIT);
    glEnable(GL_SCISSOR_TEST);
    glScissor(10, 300, 500, 100);
    glClearAccum(0.6, 0.6, -0.6, 0.2);
    glClear(GL_ACCUM_BUFFER_BIT);
    glDisable(GL_SCISSOR_TEST);
    glAccum(GL_MULT, 0.9);
    glAccum(GL_ADD, 0.05);
    glAccum(GL_RETURN, 1.5);
    read_of(&mut out, W3, H3);
    OSMesaDestroyContext(ctx);
    out
}

#[test]
fn whole_frame_ops_do_not_depend_on_thread_count() {
    let one = unsafe { frame_ops_scene(1) };
    for (k, w) in one.windows(2).enumerate() {
        assert!(w[0] != w[1], "step {} changes something", k + 1);
    }
    for threads in [2, 3] {
        let many = unsafe { frame_ops_scene(threads) };
        assert_same_read_backs(&one, &many, &format!("1 thread / {threads} threads"));
    }
}

/// glDrawPixels and glCopyPixels of colour (the RGBA8 span path, cut into
/// bands of rows for the threads from round 8) with depth and stencil
/// tests, blending, scissoring, rectangles partly outside the window and
/// overlapping copies; read-backs of colour, depth and stencil and the
/// occlusion counts. `reference` draws them on the general path, one
/// fragment at a time.
unsafe fn pixel_rects_scene(threads: usize, reference: bool) -> Vec<Vec<u8>> {
    let mut buf = vec![0u8; (W3 * H3 * 4) as usize];
    let ctx = context_of(threads, &mut buf, W3, H3);
    let mut r = Rng(0xd7a3);
    let mut out = Vec::new();
    let read_all = |out: &mut Vec<Vec<u8>>| {
        read_of(out, W3, H3);
        read_depth_stencil_of(out, W3, H3);
    };
    glClearColor(0.2, 0.1, 0.3, 0.6);
    glClearStencil(3);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT | GL_STENCIL_BUFFER_BIT);
    glEnable(GL_DEPTH_TEST);
    triangles(&mut r, 40);
    // The triangles on the fast path either way (the reference path's
    // triangles may differ within the tolerance of tests/reference_diff.rs).
    glFinish();
    (*ctx).gl.derived.render.reference = reference;
    let mut q = 0u32;
    glGenQueries(1, &mut q);
    let query = |out: &mut Vec<Vec<u8>>| {
        let mut passed = 0u32;
        glEndQuery(GL_SAMPLES_PASSED);
        glGetQueryObjectuiv(q, GL_QUERY_RESULT, &mut passed);
        out.push(passed.to_le_bytes().to_vec());
    };
    let (iw, ih) = (600, 470);
    let img: Vec<u8> = (0..iw * ih * 4).map(|_| r.next() as u8).collect();
    // Depth-tested at the raster position's depth, stencil counted up.
    glEnable(GL_STENCIL_TEST);
    glStencilFunc(GL_ALWAYS, 0, 0xff);
    glStencilOp(GL_KEEP, GL_INCR, GL_INVERT);
    glBeginQuery(GL_SAMPLES_PASSED, q);
    glRasterPos3f(-0.95, -0.97, 0.1);
    glDrawPixels(iw, ih, GL_RGBA, GL_UNSIGNED_BYTE, img.as_ptr() as *const c_void);
    query(&mut out);
    read_all(&mut out);
    // Blended, scissored, partly off the window (left and top).
    glEnable(GL_BLEND);
    glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
    glEnable(GL_SCISSOR_TEST);
    glScissor(13, 9, 611, 455);
    glStencilFunc(GL_LESS, 3, 0xff);
    glBeginQuery(GL_SAMPLES_PASSED, q);
    glWindowPos3f(-41.0, 97.0, 0.4);
    glDrawPixels(iw, ih, GL_RGBA, GL_UNSIGNED_BYTE, img.as_ptr() as *const c_void);
    query(&mut out);
    read_all(&mut out);
    // Overlapping copies: upwards over itself, then a shifted rectangle.
    glDisable(GL_STENCIL_TEST);
    glDisable(GL_BLEND);
    glDisable(GL_SCISSOR_TEST);
    glDepthFunc(GL_ALWAYS);
    glWindowPos3f(0.0, 120.0, 0.7);
    glCopyPixels(0, 0, W3, 240, GL_COLOR);
    glDepthFunc(GL_LESS);
    glBeginQuery(GL_SAMPLES_PASSED, q);
    glWindowPos3f(60.0, 40.0, 0.5);
    glCopyPixels(10, 10, 500, 400, GL_COLOR);
    query(&mut out);
    read_all(&mut out);
    OSMesaDestroyContext(ctx);
    out
}

#[test]
fn pixel_rectangles_do_not_depend_on_thread_count() {
    let one = unsafe { pixel_rects_scene(1, false) };
    for (k, w) in one.chunks(4).collect::<Vec<_>>().windows(2).enumerate() {
        assert!(w[0] != w[1], "step {} changes something", k + 1);
    }
    let reference = unsafe { pixel_rects_scene(1, true) };
    for (name, other) in [("reference", reference), ("2 threads", unsafe { pixel_rects_scene(2, false) }), ("3 threads", unsafe { pixel_rects_scene(3, false) })] {
        assert_same_read_backs(&one, &other, &format!("1 thread / {name}"));
    }
}

/// Frames of many small batches, each frame ending at a sync point
/// (glFinish), allocate their batch vectors once: a context keeps every
/// flight it made (round 10: a sync point dropped one of the two spare
/// flights, and the next frame grew its vectors again from nothing).
#[test]
fn frames_reuse_their_flights() {
    let mut buf = vec![0u8; (W * H * 4) as usize];
    let mut r = Rng(11);
    unsafe {
        let ctx = context(2, &mut buf);
        let mut made = Vec::new();
        for _ in 0..12 {
            triangles(&mut r, 60);
            glFinish();
            made.push(softgl::render::tile::flights_made(&(*ctx).gl.derived.render));
        }
        OSMesaDestroyContext(ctx);
        assert!(made[0] >= 1, "batches went to the workers: {made:?}");
        assert!(made.iter().all(|&m| m <= 2), "at most two flights besides the batch filled: {made:?}");
    }
}

/// Clears large enough to be recorded for the workers (round 11:
/// `tile::defer_clear`, written band by band by the next flight): followed
/// by triangles, by nothing before a read-back, by another recorded clear,
/// by glDrawPixels, glCopyPixels and glAccum; through colour and stencil
/// masks, scissored, depth only; with an occlusion query across one.
/// `limits` = (batch size, submit work, parallel work): tiny batches handed
/// to the workers at once, or batches too small for the workers (then only
/// the clear's flight goes to them).
unsafe fn deferred_clear_scene(threads: usize, limits: (usize, u64, u64)) -> Vec<Vec<u8>> {
    let mut buf = vec![0u8; (W3 * H3 * 4) as usize];
    let ctx = context_of(threads, &mut buf, W3, H3);
    softgl::render::tile::set_batch_limits(&(*ctx).gl.derived.render, limits.0, limits.1, limits.2);
    let mut r = Rng(0xc1ea5);
    let mut out = Vec::new();
    let read_depth_stencil = |out: &mut Vec<Vec<u8>>| read_depth_stencil_of(out, W3, H3);
    // A full clear, then nothing but a read-back.
    glClearColor(0.1, 0.6, 0.3, 0.8);
    glClearDepth(0.75);
    glClearStencil(0x21);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT | GL_STENCIL_BUFFER_BIT);
    read_of(&mut out, W3, H3);
    read_depth_stencil(&mut out);
    // A full clear, triangles (some behind the cleared depth) counted by a query.
    glClearColor(0.5, 0.2, 0.7, 0.4);
    glClearDepth(0.6);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    glEnable(GL_DEPTH_TEST);
    let mut q = 0u32;
    glGenQueries(1, &mut q);
    glBeginQuery(GL_SAMPLES_PASSED, q);
    triangles(&mut r, 50);
    glEndQuery(GL_SAMPLES_PASSED);
    let mut passed = 0u32;
    glGetQueryObjectuiv(q, GL_QUERY_RESULT, &mut passed);
    out.push(passed.to_le_bytes().to_vec());
    read_of(&mut out, W3, H3);
    read_depth_stencil(&mut out);
    // Two recorded clears in a row (colour masked, then depth and stencil
    // through a stencil mask), then triangles.
    glColorMask(0, 1, 1, 0);
    glClearColor(0.95, 0.05, 0.45, 0.15);
    glClear(GL_COLOR_BUFFER_BIT);
    glColorMask(1, 1, 1, 1);
    glStencilMask(0xa5);
    glClearStencil(0xff);
    glClearDepth(0.9);
    glClear(GL_DEPTH_BUFFER_BIT | GL_STENCIL_BUFFER_BIT);
    glStencilMask(0xff);
    triangles(&mut r, 30);
    read_of(&mut out, W3, H3);
    read_depth_stencil(&mut out);
    // Scissored (still large enough to be recorded), then a few triangles.
    glEnable(GL_SCISSOR_TEST);
    glScissor(17, 11, 600, 450);
    glClearColor(0.0, 0.3, 0.9, 1.0);
    glClearDepth(0.2);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    glDisable(GL_SCISSOR_TEST);
    triangles(&mut r, 3);
    read_of(&mut out, W3, H3);
    read_depth_stencil(&mut out);
    // Depth only, then glDrawPixels depth-tested against it.
    glClearDepth(0.45);
    glClear(GL_DEPTH_BUFFER_BIT);
    let img: Vec<u8> = (0..300 * 200 * 4).map(|_| r.next() as u8).collect();
    glWindowPos3f(100.0, 80.0, 0.3);
    glDrawPixels(300, 200, GL_RGBA, GL_UNSIGNED_BYTE, img.as_ptr() as *const c_void);
    read_of(&mut out, W3, H3);
    // Colour clear, then glCopyPixels of part of it over triangles drawn after.
    glClearColor(0.7, 0.7, 0.1, 0.3);
    glClear(GL_COLOR_BUFFER_BIT);
    triangles(&mut r, 20);
    glDepthFunc(GL_ALWAYS);
    glWindowPos3f(200.0, 150.0, 0.5);
    glCopyPixels(0, 0, 300, 250, GL_COLOR);
    glDepthFunc(GL_LESS);
    read_of(&mut out, W3, H3);
    // Colour clear, triangles, accumulated; clear again, RETURN.
    glClearColor(0.2, 0.2, 0.2, 0.2);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    triangles(&mut r, 20);
    glAccum(GL_LOAD, 0.5);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    triangles(&mut r, 20);
    glAccum(GL_ACCUM, 0.5);
    glClear(GL_COLOR_BUFFER_BIT);
    glAccum(GL_RETURN, 1.0);
    read_of(&mut out, W3, H3);
    // A clear left for the context's end.
    glClear(GL_COLOR_BUFFER_BIT);
    OSMesaDestroyContext(ctx);
    out
}

#[test]
fn deferred_clears_do_not_depend_on_thread_count() {
    for limits in [(7, 0, 0), (32 * 1024, 1 << 40, 1 << 40)] {
        let one = unsafe { deferred_clear_scene(1, limits) };
        for (k, w) in one.windows(2).enumerate() {
            assert!(w[0] != w[1], "step {} changes something", k + 1);
        }
        for threads in [2, 3] {
            let many = unsafe { deferred_clear_scene(threads, limits) };
            assert_same_read_backs(&one, &many, &format!("limits {limits:?} 1 thread / {threads} threads"));
        }
    }
}

/// The tests above draw with up to 3 rasterizer threads; the pool must
/// have the 2 workers that takes, or they would test fewer interleavings
/// than they claim (the pool is sized once, at the first current context).
#[cfg(target_os = "linux")]
#[test]
fn the_pool_has_the_workers_these_tests_use() {
    let mut buf = vec![0u8; (W * H * 4) as usize];
    unsafe {
        let ctx = context(3, &mut buf);
        let workers = std::fs::read_dir("/proc/self/task")
            .expect("/proc/self/task")
            .filter_map(|t| std::fs::read_to_string(t.ok()?.path().join("comm")).ok())
            .filter(|name| name.starts_with("softgl-raster"))
            .count();
        assert!(workers >= 2, "{workers} rasterizer workers");
        OSMesaDestroyContext(ctx);
    }
}

/// The state [`state_changes_scene`] and [`far_records_scene`] switch
/// between: a texture, fog's density, a directional light and
/// GL_COLOR_MATERIAL (lighting itself is switched per primitive). Returns
/// the texture.
unsafe fn state_mix_setup(r: &mut Rng) -> u32 {
    let mut tex = 0u32;
    glGenTextures(1, &mut tex);
    glBindTexture(GL_TEXTURE_2D, tex);
    texture_image(r, false);
    glFogf(softgl::gl::fog::GL_FOG_DENSITY, 0.7);
    let light = [0.2f32, 0.4, 1.0, 0.0];
    glLightfv(GL_LIGHT0, GL_POSITION, light.as_ptr());
    glEnable(GL_LIGHT0);
    glEnable(GL_COLOR_MATERIAL);
    tex
}

/// Changes the state between two primitives, by `pick` (0 to 4: shading,
/// texturing, fog, culling, lighting with two-sided or not; anything
/// else: nothing).
unsafe fn change_state(r: &mut Rng, pick: u32) {
    let toggle = |cap: u32, on: bool| if on { glEnable(cap) } else { glDisable(cap) };
    match pick {
        0 => glShadeModel(if r.next() % 2 == 0 { GL_FLAT } else { GL_SMOOTH }),
        1 => toggle(GL_TEXTURE_2D, r.next() % 2 == 0),
        2 => toggle(GL_FOG, r.next() % 2 == 0),
        3 => toggle(GL_CULL_FACE, r.next() % 3 == 0),
        4 => {
            toggle(GL_LIGHTING, r.next() % 3 == 0);
            glLightModeli(GL_LIGHT_MODEL_TWO_SIDE, (r.next() % 2) as i32);
        }
        _ => {}
    }
}

/// A random colour, normal and texture coordinate for the next vertex.
unsafe fn vertex_attributes(r: &mut Rng) {
    glColor4ub(r.next() as u8, r.next() as u8, r.next() as u8, 255);
    glNormal3f(r.unit() - 0.5, r.unit() - 0.5, 1.0);
    glTexCoord2f(r.unit() * 2.0, r.unit() * 2.0);
}

/// Random strips, fans, triangles, quads, quad strips and polygons, some
/// vertices outside the window (clipped) and some triangles culled, with
/// the state changed between primitives (flat and smooth shading,
/// texturing, fog, culling, two-sided lighting), so that one batch holds
/// triangles drawn under many states, one after another and back again
/// (round 12: the binned path keeps the state of the last primitive by
/// its stamp).
unsafe fn state_changes_scene(threads: usize, limits: (usize, u64, u64)) -> Vec<Vec<u8>> {
    let mut buf = vec![0u8; (W2 * H2 * 4) as usize];
    let ctx = context_of(threads, &mut buf, W2, H2);
    softgl::render::tile::set_batch_limits(&(*ctx).gl.derived.render, limits.0, limits.1, limits.2);
    let mut r = Rng(0x57a7e);
    let mut out = Vec::new();
    glClearColor(0.1, 0.1, 0.2, 1.0);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    glEnable(GL_DEPTH_TEST);
    let tex = state_mix_setup(&mut r);
    let modes = [GL_TRIANGLES, GL_TRIANGLE_STRIP, GL_TRIANGLE_FAN, GL_QUADS, GL_QUAD_STRIP, GL_POLYGON];
    for step in 0..400 {
        let pick = r.next() % 6;
        change_state(&mut r, pick);
        let mode = modes[r.next() as usize % modes.len()];
        let n = 3 + r.next() as usize % 14;
        let (cx, cy) = (r.unit() * 2.2 - 1.1, r.unit() * 2.2 - 1.1);
        let size = if r.next() % 10 == 0 { 2.5 } else { 0.35 };
        glBegin(mode);
        for i in 0..n {
            vertex_attributes(&mut r);
            // Strips and fans walk on; the others scatter about the centre.
            let t = i as f32 * 0.7;
            let (x, y) = match mode {
                GL_TRIANGLE_STRIP | GL_QUAD_STRIP => (cx + t * 0.1 * size, cy + if i % 2 == 0 { 0.0 } else { size * 0.4 }),
                GL_TRIANGLE_FAN | GL_POLYGON if i > 0 => (cx + t.cos() * size * 0.5, cy + t.sin() * size * 0.5),
                _ => (cx + (r.unit() - 0.5) * size, cy + (r.unit() - 0.5) * size),
            };
            glVertex3f(x, y, r.unit() * 1.8 - 0.9);
        }
        glEnd();
        if step % 100 == 99 {
            read_of(&mut out, W2, H2);
        }
    }
    glDeleteTextures(1, &tex);
    OSMesaDestroyContext(ctx);
    out
}

/// The binned path (2 and 3 threads) gives the 1-thread path's pixels
/// (which sets each triangle up at once) with states changing between the
/// primitives of one batch: the batch limits let the whole scene between
/// two read-backs be one batch, or cut it every few triangles.
#[test]
fn state_changes_within_a_batch_do_not_depend_on_thread_count() {
    for limits in [(1 << 20, 1 << 40, 0), (5, 0, 0)] {
        let one = unsafe { state_changes_scene(1, limits) };
        for w in one.windows(2) {
            assert_ne!(w[0], w[1], "each part draws");
        }
        for threads in [2, 3] {
            let many = unsafe { state_changes_scene(threads, limits) };
            assert_same_read_backs(&one, &many, &format!("limits {limits:?} 1 thread / {threads} threads"));
        }
    }
}

/// `n` pixel-aligned flat rectangles (drawn the same by the reference
/// path and the fast path), depth-tested at random depths.
unsafe fn flat_rects(r: &mut Rng, n: usize) {
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    glOrtho(0.0, W3 as f64, 0.0, H3 as f64, -1.0, 1.0);
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
    for _ in 0..n {
        glColor4ub(r.next() as u8, r.next() as u8, r.next() as u8, r.next() as u8);
        let (x, y) = ((r.next() % W3 as u32) as i32 - 40, (r.next() % H3 as u32) as i32 - 40);
        let (w, h) = (1 + (r.next() % 400) as i32, 1 + (r.next() % 300) as i32);
        let z = r.unit() * 1.8 - 0.9;
        glBegin(GL_QUADS);
        glVertex3f(x as f32, y as f32, z);
        glVertex3f((x + w) as f32, y as f32, z);
        glVertex3f((x + w) as f32, (y + h) as f32, z);
        glVertex3f(x as f32, (y + h) as f32, z);
        glEnd();
    }
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    glMatrixMode(GL_MODELVIEW);
}

/// A random mix of draws, colour and depth clears, accumulation clears,
/// scissor boxes, colour masks, pixel rectangles and every glAccum
/// operation (round 13: a large glAccum made while binning is recorded
/// in the batch and run band by band after the drawing before it), read
/// back at random sync points and at the end (the accumulation buffer
/// through GL_RETURN). `flat` draws only flat pixel-aligned rectangles
/// (for the comparison with the reference path); `reference` turns the
/// reference path on after the first clear.
unsafe fn accum_mix_scene(threads: usize, limits: (usize, u64, u64), seed: u64, flat: bool, reference: bool) -> Vec<Vec<u8>> {
    let mut buf = vec![0u8; (W3 * H3 * 4) as usize];
    let ctx = context_of(threads, &mut buf, W3, H3);
    softgl::render::tile::set_batch_limits(&(*ctx).gl.derived.render, limits.0, limits.1, limits.2);
    let mut r = Rng(seed);
    let mut out = Vec::new();
    glClearColor(0.3, 0.5, 0.2, 0.9);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT | GL_ACCUM_BUFFER_BIT);
    (*ctx).gl.derived.render.reference = reference;
    glEnable(GL_DEPTH_TEST);
    let ops = [GL_ACCUM, GL_LOAD, GL_RETURN, GL_MULT, GL_ADD];
    for _ in 0..60 {
        match r.next() % 16 {
            0..=4 => {
                let n = r.next() as usize;
                if flat {
                    flat_rects(&mut r, 1 + n % 12);
                } else {
                    triangles(&mut r, 1 + n % 40);
                }
            }
            5..=8 => {
                let op = ops[(r.next() % 5) as usize];
                let value = r.unit() * 3.0 - 1.5;
                glAccum(op, value);
            }
            9 => {
                glClearColor(r.unit(), r.unit(), r.unit(), r.unit());
                let depth = if r.next().is_multiple_of(2) { GL_DEPTH_BUFFER_BIT } else { 0 };
                glClear(GL_COLOR_BUFFER_BIT | depth);
            }
            10 => {
                glClearAccum(r.unit() * 2.0 - 1.0, r.unit() * 2.0 - 1.0, r.unit() * 2.0 - 1.0, r.unit() * 2.0 - 1.0);
                glClear(GL_ACCUM_BUFFER_BIT);
            }
            11 => {
                // A scissor box: off, large (recorded glAccum) or small.
                match r.next() % 3 {
                    0 => glDisable(GL_SCISSOR_TEST),
                    k => {
                        let (x, y) = ((r.next() % 200) as i32 - 20, (r.next() % 150) as i32 - 20);
                        let (w, h) = if k == 1 { (300 + (r.next() % 400) as i32, 200 + (r.next() % 300) as i32) } else { (1 + (r.next() % 100) as i32, 1 + (r.next() % 100) as i32) };
                        glScissor(x, y, w, h);
                        glEnable(GL_SCISSOR_TEST);
                    }
                }
            }
            12 => {
                let m = r.next();
                if m.is_multiple_of(3) {
                    glColorMask((m >> 4) as u8 & 1, (m >> 5) as u8 & 1, (m >> 6) as u8 & 1, (m >> 7) as u8 & 1);
                } else {
                    glColorMask(1, 1, 1, 1);
                }
            }
            13 => {
                glDepthFunc(GL_ALWAYS);
                glWindowPos3f((r.next() % 300) as f32, (r.next() % 200) as f32, 0.5);
                if r.next().is_multiple_of(2) {
                    glCopyPixels((r.next() % 300) as i32, (r.next() % 200) as i32, 200, 150, GL_COLOR);
                } else {
                    let img: Vec<u8> = (0..160 * 90 * 4).map(|_| r.next() as u8).collect();
                    glDrawPixels(160, 90, GL_RGBA, GL_UNSIGNED_BYTE, img.as_ptr() as *const c_void);
                }
                glDepthFunc(GL_LESS);
            }
            _ => read_of(&mut out, W3, H3),
        }
    }
    // The accumulation buffer, whole: returned as is, then shifted by +1
    // and halved (its negative values show).
    glDisable(GL_SCISSOR_TEST);
    glColorMask(1, 1, 1, 1);
    read_of(&mut out, W3, H3);
    glAccum(GL_RETURN, 1.0);
    read_of(&mut out, W3, H3);
    glAccum(GL_ADD, 1.0);
    glAccum(GL_RETURN, 0.5);
    read_of(&mut out, W3, H3);
    OSMesaDestroyContext(ctx);
    out
}

const W4: i32 = 200;
const H4: i32 = 700;

/// Clusters of small triangles (a few bands hold most of the work, so the
/// bands are taken in a different order than top to bottom: round 13's
/// heaviest band first) with some large ones across many bands, after a
/// recorded clear, counted by an occlusion query and read back now and
/// then. With `limits` = (64 triangles, submit work never reached, every
/// batch to the workers), each batch is handed over only when full, and
/// the calling thread, reaching 48 triangles while the flight before is
/// still shaded, takes that flight's untaken bands and goes on binning
/// (round 13: `tile::submit`'s help).
unsafe fn helped_flights_scene(threads: usize, limits: (usize, u64, u64)) -> Vec<Vec<u8>> {
    let mut buf = vec![0u8; (W4 * H4 * 4) as usize];
    let ctx = context_of(threads, &mut buf, W4, H4);
    softgl::render::tile::set_batch_limits(&(*ctx).gl.derived.render, limits.0, limits.1, limits.2);
    let mut r = Rng(0x4e1f);
    let mut out = Vec::new();
    glEnable(GL_DEPTH_TEST);
    for frame in 0..4 {
        glClearColor(0.2 * frame as f32, 0.1, 0.3, 1.0);
        glClearDepth(0.8);
        glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
        let mut q = 0u32;
        glGenQueries(1, &mut q);
        glBeginQuery(GL_SAMPLES_PASSED, q);
        for cluster in 0..30 {
            let (cx, cy) = (r.unit() * 1.6 - 0.8, r.unit() * 1.6 - 0.8);
            glBegin(GL_TRIANGLES);
            for t in 0..(20 + r.next() as usize % 100) {
                let size = if t % 50 == 49 { 1.8 } else { 0.08 };
                let (tx, ty) = (cx + (r.unit() - 0.5) * 0.3, cy + (r.unit() - 0.5) * 0.3);
                for _ in 0..3 {
                    glColor4ub(r.next() as u8, r.next() as u8, r.next() as u8, 255);
                    glVertex3f(tx + (r.unit() - 0.5) * size, ty + (r.unit() - 0.5) * size, r.unit() * 2.0 - 1.0);
                }
            }
            glEnd();
            if cluster % 11 == 10 {
                read_of(&mut out, W4, H4);
            }
        }
        glEndQuery(GL_SAMPLES_PASSED);
        let mut passed = 0u32;
        glGetQueryObjectuiv(q, GL_QUERY_RESULT, &mut passed);
        out.push(passed.to_le_bytes().to_vec());
        glFinish();
        read_of(&mut out, W4, H4);
    }
    OSMesaDestroyContext(ctx);
    out
}

/// Batches that grow past `tile::grow`'s jump to a full batch's room
/// (512 records, round 22) keep every record in order: with every batch
/// held until a read-back (about 800 triangles), 2 and 3 threads give the
/// 1-thread pixels and occlusion counts.
#[test]
fn batches_past_the_growth_jump_do_not_depend_on_thread_count() {
    let limits = (32 * 1024, 1 << 40, 1 << 40);
    let one = unsafe { helped_flights_scene(1, limits) };
    for threads in [2, 3] {
        let many = unsafe { helped_flights_scene(threads, limits) };
        assert_same_read_backs(&one, &many, &format!("limits {limits:?} 1 thread / {threads} threads"));
    }
}

/// Tiny triangles in batches held until full (32K records): each batch
/// passes `tile::grow`'s jump (512 records), its move into a mapping of
/// huge pages (8,192, round 23) and fills it; the batches after take the
/// spare vectors made huge at once (`Batch::reserve_like`). Read back
/// after each batch and in the middle of one.
unsafe fn huge_batches_scene(threads: usize) -> Vec<Vec<u8>> {
    let mut buf = vec![0u8; (W4 * H4 * 4) as usize];
    let ctx = context_of(threads, &mut buf, W4, H4);
    softgl::render::tile::set_batch_limits(&(*ctx).gl.derived.render, 32 * 1024, 1 << 40, 1 << 40);
    let mut r = Rng(0x9a7e);
    let mut out = Vec::new();
    glEnable(GL_DEPTH_TEST);
    glClearColor(0.1, 0.2, 0.3, 1.0);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    read_of(&mut out, W4, H4);
    for n in [20_000usize, 50_000, 9_000] {
        glBegin(GL_TRIANGLES);
        for _ in 0..n {
            let (tx, ty) = (r.unit() * 2.0 - 1.0, r.unit() * 2.0 - 1.0);
            for _ in 0..3 {
                glColor4ub(r.next() as u8, r.next() as u8, r.next() as u8, 255);
                glVertex3f(tx + (r.unit() - 0.5) * 0.05, ty + (r.unit() - 0.5) * 0.02, r.unit() * 2.0 - 1.0);
            }
        }
        glEnd();
        read_of(&mut out, W4, H4);
        assert!(out[out.len() - 1] != out[out.len() - 2], "each batch draws");
    }
    OSMesaDestroyContext(ctx);
    out
}

/// Batches that grow into huge pages (round 23, `render::records`) keep
/// every record in order: 2 and 3 threads give the 1-thread pixels.
#[test]
fn batches_in_huge_pages_do_not_depend_on_thread_count() {
    let one = unsafe { huge_batches_scene(1) };
    for threads in [2, 3] {
        let many = unsafe { huge_batches_scene(threads) };
        assert_same_read_backs(&one, &many, &format!("1 thread / {threads} threads"));
    }
}

/// Round 13's recorded glAccum against the immediate one: the same
/// random command streams with 2 and 3 threads (tiny batches handed to
/// the workers at once, and batches too small for them) as with 1 thread,
/// and, with flat rectangles, as on the reference path.
#[test]
fn recorded_accum_does_not_depend_on_thread_count() {
    for seed in [1u64, 2, 3, 4] {
        let one = unsafe { accum_mix_scene(1, (7, 0, 0), seed, false, false) };
        let n = one.len();
        assert!(n >= 4 && one[n - 3] != one[n - 2] && one[n - 2] != one[n - 1], "seed {seed}: the final GL_RETURNs change nothing");
        for limits in [(7, 0, 0), (32 * 1024, 1 << 40, 1 << 40)] {
            for threads in [2, 3] {
                let many = unsafe { accum_mix_scene(threads, limits, seed, false, false) };
                assert_same_read_backs(&one, &many, &format!("seed {seed} limits {limits:?} 1 thread / {threads} threads"));
            }
        }
        let flat_one = unsafe { accum_mix_scene(1, (7, 0, 0), seed, true, false) };
        for (name, other) in [("reference", unsafe { accum_mix_scene(1, (7, 0, 0), seed, true, true) }), ("2 threads", unsafe { accum_mix_scene(2, (7, 0, 0), seed, true, false) })] {
            assert_same_read_backs(&flat_one, &other, &format!("seed {seed} flat 1 thread / {name}"));
        }
    }
}

/// Flights helped by the calling thread before they are full and bands
/// taken heaviest first give the 1-thread pixels and occlusion counts with
/// 2 and 3 threads; the help happened.
#[test]
fn helped_flights_do_not_depend_on_thread_count() {
    let helps = softgl::render::tile::helps_started();
    for limits in [(64, 1 << 40, 0), (40, 3000, 0), (7, 0, 0)] {
        let one = unsafe { helped_flights_scene(1, limits) };
        for w in one.windows(2) {
            assert_ne!(w[0], w[1], "each part draws");
        }
        for threads in [2, 3] {
            let many = unsafe { helped_flights_scene(threads, limits) };
            assert_same_read_backs(&one, &many, &format!("limits {limits:?} 1 thread / {threads} threads"));
        }
    }
    assert!(softgl::render::tile::helps_started() > helps, "the calling thread helped a flight before its batch was full");
}

const W5: i32 = 16384;
const H5: i32 = 10;

/// Round 14's smaller binned record (x and y in i32, the box in i16, the
/// facing and the extra index packed) at its bounds: a window as wide as
/// the framebuffer allows (boxes up to 16384), viewports moved far to the
/// left and right of it (clipped vertices up to the guard band, hundreds
/// of thousands of pixels out: snapped values of 27 bits), tiny and huge
/// random strips, fans, triangles, quads, quad strips and polygons, both
/// windings, with flat / smooth shading, texturing, fog, culling and
/// two-sided lighting changing between them.
unsafe fn far_records_scene(threads: usize, limits: (usize, u64, u64)) -> Vec<Vec<u8>> {
    let mut buf = vec![0u8; (W5 * H5 * 4) as usize];
    let ctx = context_of(threads, &mut buf, W5, H5);
    softgl::render::tile::set_batch_limits(&(*ctx).gl.derived.render, limits.0, limits.1, limits.2);
    let mut r = Rng(0xfa7);
    let mut out = Vec::new();
    glClearColor(0.1, 0.2, 0.1, 1.0);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    glEnable(GL_DEPTH_TEST);
    let tex = state_mix_setup(&mut r);
    glMatrixMode(GL_PROJECTION);
    glOrtho(0.0, W5 as f64, 0.0, H5 as f64, -1.0, 1.0);
    glMatrixMode(GL_MODELVIEW);
    let modes = [GL_TRIANGLES, GL_TRIANGLE_STRIP, GL_TRIANGLE_FAN, GL_QUADS, GL_QUAD_STRIP, GL_POLYGON];
    let mut off = 0i32;
    for step in 0..300 {
        let pick = r.next() % 7;
        if pick == 5 {
            // The viewport's origin far off the window: the visible part
            // of the guard band is far from the viewport.
            off = [0, -200_000, 150_000, -1000][r.next() as usize % 4];
            glViewport(off, 0, W5, H5);
        } else {
            change_state(&mut r, pick);
        }
        let mode = modes[r.next() as usize % modes.len()];
        let n = 3 + r.next() as usize % 10;
        // Centred on the window (in window x), spread little or far.
        let cx = (r.unit() * 1.2 - 0.1) * W5 as f32 - off as f32;
        let cy = r.unit() * 14.0 - 2.0;
        let size = match r.next() % 4 {
            0 => 800_000.0,
            1 => 20_000.0,
            _ => 60.0,
        };
        glBegin(mode);
        for i in 0..n {
            vertex_attributes(&mut r);
            let t = i as f32 * 0.7;
            let (x, y) = match mode {
                GL_TRIANGLE_STRIP | GL_QUAD_STRIP => (cx + t * 0.1 * size, cy + if i % 2 == 0 { -3.0 } else { 9.0 }),
                GL_TRIANGLE_FAN | GL_POLYGON if i > 0 => (cx + t.cos() * size * 0.5, cy + t.sin() * 8.0),
                _ => (cx + (r.unit() - 0.5) * size, cy + (r.unit() - 0.5) * 16.0),
            };
            glVertex3f(x, y, r.unit() * 1.8 - 0.9);
        }
        glEnd();
        if step % 60 == 59 {
            read_of(&mut out, W5, H5);
        }
    }
    glDeleteTextures(1, &tex);
    OSMesaDestroyContext(ctx);
    out
}

/// The binned path (2 and 3 threads, round 14's record) gives the
/// 1-thread path's pixels at the record's bounds ([`far_records_scene`]).
#[test]
fn far_and_wide_records_do_not_depend_on_thread_count() {
    for limits in [(1 << 20, 1 << 40, 0), (5, 0, 0)] {
        let one = unsafe { far_records_scene(1, limits) };
        for w in one.windows(2) {
            assert_ne!(w[0], w[1], "each part draws");
        }
        for threads in [2, 3] {
            let many = unsafe { far_records_scene(threads, limits) };
            assert_same_read_backs(&one, &many, &format!("limits {limits:?} 1 thread / {threads} threads"));
        }
    }
}
