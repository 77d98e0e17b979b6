//! glPushAttrib / glPopAttrib and the client stack (GL 1.5 section 6.1.14).

use softgl::framebuffer::Config;
use softgl::gl::attrib::*;
use softgl::gl::enums::*;
use softgl::gl::{Command, Context};

fn context() -> Context {
    let mut c = Context::new(Config { alpha_bits: 8, depth_bits: 24, stencil_bits: 8, accum_bits: 16 });
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

fn getf(c: &mut Context, pname: u32) -> Vec<f64> {
    c.get(pname).expect("a known name").as_f64()
}

#[test]
fn fog_group_comes_back_with_its_enable() {
    use softgl::gl::fog::*;
    let mut c = context();
    c.execute(&Command::Fog(GL_FOG_DENSITY, [0.25, 0.0, 0.0, 0.0]));
    c.execute(&Command::PushAttrib(GL_FOG_BIT));
    c.execute(&Command::Enable(GL_FOG));
    c.execute(&Command::Fog(GL_FOG_DENSITY, [0.75, 0.0, 0.0, 0.0]));
    c.execute(&Command::Fog(GL_FOG_MODE, [0x2601 as f32, 0.0, 0.0, 0.0])); // GL_LINEAR
    c.execute(&Command::Fog(GL_FOG_COLOR, [1.0, 0.5, 0.25, 1.0]));
    c.execute(&Command::PopAttrib);
    assert_eq!(c.is_enabled(GL_FOG), Some(false));
    assert_eq!(getf(&mut c, GL_FOG_DENSITY), vec![0.25]);
    assert_eq!(getf(&mut c, GL_FOG_MODE), vec![0x0800 as f64] /* GL_EXP */);
    assert_eq!(getf(&mut c, GL_FOG_COLOR), vec![0.0; 4]);
    assert_eq!(c.take_error(), GL_NO_ERROR);
}

#[test]
fn pixel_mode_group_comes_back() {
    let mut c = context();
    c.execute(&Command::PushAttrib(GL_PIXEL_MODE_BIT));
    c.execute(&Command::PixelTransfer(GL_RED_SCALE, 2.0));
    c.execute(&Command::PixelMap(GL_PIXEL_MAP_I_TO_R, vec![0.0, 0.5, 1.0, 0.25]));
    c.execute(&Command::PixelZoom(2.0, 3.0));
    c.execute(&Command::PopAttrib);
    assert_eq!(getf(&mut c, GL_RED_SCALE), vec![1.0]);
    assert_eq!(c.pixel.zoom, [1.0, 1.0]);
    assert_eq!(c.pixel, softgl::gl::pixel_transfer::PixelTransfer::default());
    assert_eq!(c.take_error(), GL_NO_ERROR);
}

#[test]
fn texture_group_restores_units_bindings_and_bound_parameters() {
    use softgl::gl::texture::enums::*;
    let mut c = context();
    c.execute(&Command::BindTexture(GL_TEXTURE_2D, 7));
    c.execute(&Command::TexParameter(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, [GL_NEAREST as f32, 0.0, 0.0, 0.0]));
    c.execute(&Command::PushAttrib(GL_TEXTURE_BIT));
    // Everything the group holds changes...
    c.execute(&Command::TexParameter(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, [0x2601 as f32, 0.0, 0.0, 0.0])); // GL_LINEAR
    c.execute(&Command::Enable(GL_TEXTURE_2D));
    c.execute(&Command::TexEnv(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, [GL_DECAL as f32, 0.0, 0.0, 0.0]));
    c.execute(&Command::TexGen(GL_S, GL_TEXTURE_GEN_MODE, [GL_OBJECT_LINEAR as f64, 0.0, 0.0, 0.0]));
    c.execute(&Command::Enable(GL_TEXTURE_GEN_S));
    c.execute(&Command::ActiveTexture(GL_TEXTURE0 + 2));
    c.execute(&Command::BindTexture(GL_TEXTURE_2D, 9));
    c.execute(&Command::Enable(GL_TEXTURE_2D));
    c.execute(&Command::PopAttrib);
    // ...and comes back.
    assert_eq!(c.take_error(), GL_NO_ERROR);
    assert_eq!(getf(&mut c, GL_ACTIVE_TEXTURE), vec![GL_TEXTURE0 as f64]);
    assert_eq!(c.is_enabled(GL_TEXTURE_2D), Some(false));
    assert_eq!(c.is_enabled(GL_TEXTURE_GEN_S), Some(false));
    assert_eq!(getf(&mut c, GL_TEXTURE_BINDING_2D), vec![7.0]);
    assert_eq!(c.get_tex_parameter(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER).unwrap().as_f64(), vec![GL_NEAREST as f64]);
    assert_eq!(c.get_tex_env(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE).unwrap().as_f64(), vec![GL_MODULATE as f64]);
    c.execute(&Command::ActiveTexture(GL_TEXTURE0 + 2));
    assert_eq!(getf(&mut c, GL_TEXTURE_BINDING_2D), vec![0.0]);
    assert_eq!(c.is_enabled(GL_TEXTURE_2D), Some(false));
    // Object 9 keeps its own (initial) parameters.
    c.execute(&Command::BindTexture(GL_TEXTURE_2D, 9));
    assert_eq!(c.get_tex_parameter(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER).unwrap().as_f64(), vec![GL_NEAREST_MIPMAP_LINEAR as f64]);
    assert_eq!(c.take_error(), GL_NO_ERROR);
}

#[test]
fn multisample_group_comes_back() {
    let mut c = context();
    c.execute(&Command::Enable(GL_MULTISAMPLE));
    c.execute(&Command::PushAttrib(GL_MULTISAMPLE_BIT));
    c.execute(&Command::Disable(GL_MULTISAMPLE));
    c.execute(&Command::Enable(GL_SAMPLE_COVERAGE));
    c.execute(&Command::SampleCoverage(0.25, true));
    c.execute(&Command::PopAttrib);
    assert_eq!(c.is_enabled(GL_MULTISAMPLE), Some(true));
    assert_eq!(c.is_enabled(GL_SAMPLE_COVERAGE), Some(false));
    assert_eq!(getf(&mut c, 0x80AA), vec![1.0]);
    assert_eq!(c.take_error(), GL_NO_ERROR);
}

/// GL 1.5 table 6.17: GL_MULTISAMPLE is initially enabled (the other three
/// multisample capabilities are not).
#[test]
fn multisample_starts_enabled() {
    let c = context();
    assert_eq!(c.is_enabled(GL_MULTISAMPLE), Some(true));
    assert_eq!(c.is_enabled(GL_SAMPLE_COVERAGE), Some(false));
    assert_eq!(c.is_enabled(GL_SAMPLE_ALPHA_TO_COVERAGE), Some(false));
}
