//! Selection and feedback (GL 1.5 sections 5.2, 5.3).

use softgl::framebuffer::Config;
use softgl::gl::enums::*;
use softgl::gl::select::*;
use softgl::gl::{Command, Context};

fn context() -> Context {
    let mut c = Context::new(Config { alpha_bits: 8, depth_bits: 24, stencil_bits: 8, accum_bits: 0 });
    c.fb.resize(16, 16).unwrap();
    c.surface_resized(16, 16);
    c.execute(&Command::MatrixMode(GL_PROJECTION));
    c.execute(&Command::Ortho([0.0, 16.0, 0.0, 16.0, -1.0, 1.0]));
    c.execute(&Command::MatrixMode(GL_MODELVIEW));
    c
}

fn tri(c: &mut Context, x: f32, z: [f32; 3]) {
    c.execute(&Command::Begin(GL_TRIANGLES));
    c.execute(&Command::Vertex([x, 1.0, z[0], 1.0]));
    c.execute(&Command::Vertex([x + 4.0, 1.0, z[1], 1.0]));
    c.execute(&Command::Vertex([x, 5.0, z[2], 1.0]));
    c.execute(&Command::End);
}

#[test]
fn selection_hit_records() {
    let mut c = context();
    let mut buf = [0u32; 64];
    c.select_buffer(64, buf.as_mut_ptr());
    assert_eq!(c.render_mode(GL_SELECT), 0);
    c.execute(&Command::NameStack(NameOp::Init));
    c.execute(&Command::NameStack(NameOp::Push(7)));
    // Visible: z from -0.5 to 0.5 in eye space -> window z 0.25 .. 0.75
    // (glOrtho near -1 far 1 flips z: eye z -0.5 is window depth 0.75).
    tri(&mut c, 2.0, [-0.5, 0.5, 0.0]);
    c.execute(&Command::NameStack(NameOp::Load(8)));
    tri(&mut c, 40.0, [0.0, 0.0, 0.0]); // off-screen: no hit
    c.execute(&Command::NameStack(NameOp::Push(9)));
    tri(&mut c, 10.0, [0.0, 0.0, 0.0]);
    let hits = c.render_mode(GL_RENDER);
    assert_eq!(hits, 2);
    let z = |d: f64| (d * 4294967295.0).round() as u32;
    assert_eq!(&buf[..4], &[1, z(0.25), z(0.75), 7]);
    assert_eq!(&buf[4..9], &[2, z(0.5), z(0.5), 8, 9]);
    // Nothing was drawn.
    assert!(c.fb.color.iter().all(|p| *p == [0; 4]));
}

#[test]
fn selection_overflow_and_errors() {
    let mut c = context();
    let mut buf = [0u32; 3];
    c.execute(&Command::NameStack(NameOp::Push(1))); // ignored in render mode
    assert_eq!(c.take_error(), GL_NO_ERROR);
    assert_eq!(c.render_mode(GL_SELECT), 0);
    assert_eq!(c.take_error(), GL_INVALID_OPERATION, "no select buffer");
    c.select_buffer(3, buf.as_mut_ptr());
    c.render_mode(GL_SELECT);
    c.select_buffer(3, buf.as_mut_ptr());
    assert_eq!(c.take_error(), GL_INVALID_OPERATION, "buffer change in select mode");
    c.execute(&Command::NameStack(NameOp::Load(3)));
    assert_eq!(c.take_error(), GL_INVALID_OPERATION, "load on an empty stack");
    c.execute(&Command::NameStack(NameOp::Pop));
    assert_eq!(c.take_error(), GL_STACK_UNDERFLOW);
    c.execute(&Command::NameStack(NameOp::Push(5)));
    tri(&mut c, 2.0, [0.0; 3]);
    assert_eq!(c.render_mode(GL_RENDER), -1, "a 4-value record does not fit in 3");
}

#[test]
fn feedback_tokens_and_values() {
    let mut c = context();
    let mut buf = [0f32; 64];
    c.feedback_buffer(64, GL_3D_COLOR, buf.as_mut_ptr());
    c.render_mode(GL_FEEDBACK);
    c.execute(&Command::Color([1.0, 0.5, 0.25, 1.0]));
    tri(&mut c, 2.0, [0.0; 3]);
    c.execute(&Command::PassThrough(42.0));
    c.execute(&Command::Begin(GL_LINE_STRIP));
    for v in [[1.0, 1.0], [3.0, 1.0], [3.0, 3.0]] {
        c.execute(&Command::Vertex([v[0], v[1], 0.0, 1.0]));
    }
    c.execute(&Command::End);
    let n = c.render_mode(GL_RENDER);
    let poly = 0x0703 as f32;
    let v = |x: f32, y: f32| [x, y, 0.5, 1.0, 0.5, 0.25, 1.0];
    let mut want = vec![poly, 3.0];
    want.extend(v(2.0, 1.0));
    want.extend(v(6.0, 1.0));
    want.extend(v(2.0, 5.0));
    want.extend([0x0700 as f32, 42.0]);
    want.push(0x0707 as f32); // LINE_RESET_TOKEN: first segment of the strip
    want.extend(v(1.0, 1.0));
    want.extend(v(3.0, 1.0));
    want.push(0x0702 as f32);
    want.extend(v(3.0, 1.0));
    want.extend(v(3.0, 3.0));
    assert_eq!(n as usize, want.len());
    for (i, (a, b)) in buf.iter().zip(&want).enumerate() {
        assert!((a - b).abs() < 1e-5, "value {i}: {a} vs {b}");
    }
}

#[test]
fn feedback_overflow_and_culling() {
    let mut c = context();
    let mut buf = [0f32; 4];
    c.feedback_buffer(4, GL_2D, buf.as_mut_ptr());
    c.render_mode(GL_FEEDBACK);
    c.execute(&Command::Enable(GL_CULL_FACE));
    c.execute(&Command::CullFace(GL_FRONT));
    tri(&mut c, 2.0, [0.0; 3]); // counter-clockwise: culled
    assert_eq!(c.render_mode(GL_FEEDBACK), 0);
    c.execute(&Command::Disable(GL_CULL_FACE));
    tri(&mut c, 2.0, [0.0; 3]);
    assert_eq!(c.render_mode(GL_RENDER), -1);
    c.feedback_buffer(4, 0x1234, buf.as_mut_ptr());
    assert_eq!(c.take_error(), GL_INVALID_ENUM);
}

#[test]
fn feedback_reports_texture_coordinates_after_the_texture_matrix() {
    let mut c = context();
    let mut buf = [0f32; 64];
    c.feedback_buffer(64, GL_3D_COLOR_TEXTURE, buf.as_mut_ptr());
    c.render_mode(GL_FEEDBACK);
    c.execute(&Command::MatrixMode(GL_TEXTURE));
    c.execute(&Command::Scale([2.0, 3.0, 1.0]));
    c.execute(&Command::MatrixMode(GL_MODELVIEW));
    c.execute(&Command::TexCoord(0x84C0, [0.25, 0.5, 0.0, 1.0]));
    c.execute(&Command::Begin(GL_POINTS));
    c.execute(&Command::Vertex([3.0, 4.0, 0.0, 1.0]));
    c.execute(&Command::End);
    let n = c.render_mode(GL_RENDER);
    // POINT_TOKEN, x y z, r g b a, s t r q (texture unit 0, scaled).
    let want = [0x0701 as f32, 3.0, 4.0, 0.5, 1.0, 1.0, 1.0, 1.0, 0.5, 1.5, 0.0, 1.0];
    assert_eq!(&buf[..n as usize], &want);
}

#[test]
fn feedback_of_pixel_rectangles_reports_the_raster_position() {
    use softgl::gl::draw_pixels::Bitmap;
    let mut c = context();
    let mut buf = [0f32; 64];
    c.feedback_buffer(64, GL_3D, buf.as_mut_ptr());
    c.render_mode(GL_FEEDBACK);
    c.execute(&Command::RasterPos([2.0, 3.0, 0.0, 1.0]));
    let b = Bitmap { width: 8, height: 1, orig: [0.0, 0.0], step: [5.0, 1.0], bits: vec![0xFF] };
    c.execute(&Command::Bitmap(std::rc::Rc::new(b)));
    c.execute(&Command::CopyPixels(0, 0, 4, 4, GL_COLOR));
    c.execute(&Command::CopyPixels(0, 0, -1, 4, GL_COLOR));
    assert_eq!(c.take_error(), GL_INVALID_VALUE);
    c.execute(&Command::RasterPos([100.0, 3.0, 0.0, 1.0])); // invalid: no record
    c.execute(&Command::CopyPixels(0, 0, 4, 4, GL_COLOR));
    let n = c.render_mode(GL_RENDER);
    let want = [0x0704 as f32, 2.0, 3.0, 0.5, 0x0706 as f32, 7.0, 4.0, 0.5];
    assert_eq!(&buf[..n as usize], &want);
    // Nothing was drawn.
    assert!(c.fb.color.iter().all(|p| *p == [0; 4]));
}

#[test]
fn valid_raster_positions_are_selection_hits() {
    let mut c = context();
    let mut buf = [0u32; 16];
    c.select_buffer(16, buf.as_mut_ptr());
    c.render_mode(GL_SELECT);
    c.execute(&Command::NameStack(NameOp::Init));
    c.execute(&Command::NameStack(NameOp::Push(3)));
    c.execute(&Command::RasterPos([40.0, 2.0, 0.0, 1.0])); // outside: invalid, no hit
    c.execute(&Command::NameStack(NameOp::Load(4)));
    c.execute(&Command::RasterPos([2.0, 2.0, 0.5, 1.0])); // eye z 0.5 -> window depth 0.25
    let hits = c.render_mode(GL_RENDER);
    assert_eq!(hits, 1);
    let z = (0.25f64 * 4294967295.0).round() as u32;
    assert_eq!(&buf[..4], &[1, z, z, 4]);
}
