//! glPushAttrib / glPopAttrib and the client stack (GL 1.5 section 6.1.14).

use softgl::framebuffer::Config;
use softgl::gl::attrib::*;
use softgl::gl::enums::*;
use softgl::gl::{Command, Context};

fn context() -> Context {
    let mut c = Context::new(Config { depth_bits: 24, stencil_bits: 8, accum_bits: 16 });
    c.fb.resize(4, 4).unwrap();
    c.surface_resized(4, 4);
    c
}

#[test]
fn groups_come_back_and_others_stay() {
    let mut c = context();
    c.execute(&Command::PushAttrib(GL_COLOR_BUFFER_BIT | GL_ENABLE_BIT | GL_LIGHTING_BIT | GL_VIEWPORT_BIT));
    c.execute(&Command::ClearColor([0.5, 0.5, 0.5, 1.0]));
    c.execute(&Command::Enable(GL_DEPTH_TEST));
    c.execute(&Command::Enable(GL_LIGHT0 + 3));
    c.execute(&Command::ShadeModel(GL_FLAT));
    c.execute(&Command::Viewport(1, 1, 2, 2));
    c.execute(&Command::LineWidth(3.0)); // line group: not saved
    c.execute(&Command::PopAttrib);
    assert_eq!(c.color_buffer.clear, [0.0; 4]);
    assert_eq!(c.is_enabled(GL_DEPTH_TEST), Some(false));
    assert_eq!(c.is_enabled(GL_LIGHT0 + 3), Some(false));
    assert_eq!(c.shade_model, GL_SMOOTH);
    assert_eq!((c.viewport.x, c.viewport.width), (0, 4));
    assert_eq!(c.line.width, 3.0);
    assert_eq!(c.take_error(), GL_NO_ERROR);
}

#[test]
fn the_depth_group_carries_its_enable() {
    let mut c = context();
    c.execute(&Command::PushAttrib(GL_DEPTH_BUFFER_BIT));
    c.execute(&Command::Enable(GL_DEPTH_TEST));
    c.execute(&Command::DepthFunc(GL_GREATER));
    c.execute(&Command::PopAttrib);
    assert_eq!(c.is_enabled(GL_DEPTH_TEST), Some(false));
    assert_eq!(c.depth.func.to_gl(), GL_LESS);
}

#[test]
fn stack_limits() {
    let mut c = context();
    c.execute(&Command::PopAttrib);
    assert_eq!(c.take_error(), GL_STACK_UNDERFLOW);
    for _ in 0..MAX_ATTRIB_STACK_DEPTH {
        c.execute(&Command::PushAttrib(!0));
    }
    assert_eq!(c.take_error(), GL_NO_ERROR);
    c.execute(&Command::PushAttrib(!0));
    assert_eq!(c.take_error(), GL_STACK_OVERFLOW);
    c.pop_client_attrib();
    assert_eq!(c.take_error(), GL_STACK_UNDERFLOW);
    c.push_client_attrib(GL_CLIENT_PIXEL_STORE_BIT);
    c.pixel_store(GL_UNPACK_ALIGNMENT, 1.0);
    c.pop_client_attrib();
    assert_eq!(c.pixel_store.unpack.alignment, 4);
}

/// glDrawBuffer / glReadBuffer: names, existence, GL_NONE (4.2.1, 4.3.2).
#[test]
fn draw_and_read_buffers() {
    use softgl::gl::draw_buffer::*;
    let mut c = context();
    c.execute(&Command::DrawBuffer(GL_BACK));
    assert_eq!(c.take_error(), GL_INVALID_OPERATION, "no back buffer on a single-buffered surface");
    c.execute(&Command::DrawBuffer(GL_RIGHT));
    assert_eq!(c.take_error(), GL_INVALID_OPERATION, "no stereo");
    c.execute(&Command::DrawBuffer(0x1234));
    assert_eq!(c.take_error(), GL_INVALID_ENUM);
    c.execute(&Command::ReadBuffer(GL_FRONT_AND_BACK));
    assert_eq!(c.take_error(), GL_INVALID_ENUM);
    // GL_NONE: neither drawing nor clearing writes colour.
    c.execute(&Command::DrawBuffer(GL_NONE));
    c.execute(&Command::ClearColor([1.0; 4]));
    c.execute(&Command::Clear(GL_COLOR_BUFFER_BIT));
    c.execute(&Command::Color([1.0; 4]));
    c.execute(&Command::Rect([-1.0, -1.0, 1.0, 1.0]));
    assert!(c.fb.color.iter().all(|p| *p == [0; 4]));
    c.execute(&Command::DrawBuffer(GL_FRONT_LEFT));
    c.execute(&Command::Clear(GL_COLOR_BUFFER_BIT));
    assert!(c.fb.color.iter().all(|p| *p == [255; 4]));
    assert_eq!(c.take_error(), GL_NO_ERROR);
    c.set_double_buffered(true);
    assert_eq!(c.color_buffer.draw_buffer, GL_BACK);
    c.execute(&Command::ReadBuffer(GL_BACK_LEFT));
    assert_eq!(c.take_error(), GL_NO_ERROR);
}
