//! The accumulation buffer (GL 1.5 section 4.2.4): LOAD, ACCUM, MULT, ADD,
//! RETURN with clamping, glClearAccum, the scissor box and the errors.

use softgl::framebuffer::Config;
use softgl::gl::enums::*;
use softgl::gl::{Command, Context};

fn context(accum: bool) -> Context {
    let mut c = Context::new(Config { alpha_bits: 8, depth_bits: 24, stencil_bits: 8, accum_bits: if accum { 16 } else { 0 } });
    c.fb.resize(4, 4).unwrap();
    c.surface_resized(4, 4);
    c
}

fn clear_to(c: &mut Context, rgba: [f32; 4]) {
    c.execute(&Command::ClearColor(rgba));
    c.execute(&Command::Clear(GL_COLOR_BUFFER_BIT));
}

fn px(c: &Context) -> [u8; 4] {
    c.fb.color[c.fb.index(1, 1)]
}

fn near(got: [u8; 4], want: [f32; 4]) {
    for i in 0..4 {
        let w = (want[i].clamp(0.0, 1.0) * 255.0).round() as i32;
        assert!((got[i] as i32 - w).abs() <= 1, "got {got:?}, want {want:?}");
    }
}

#[test]
fn averaging_frames_and_return() {
    let mut c = context(true);
    clear_to(&mut c, [1.0, 0.0, 0.2, 1.0]);
    c.execute(&Command::Accum(GL_LOAD, 0.5));
    clear_to(&mut c, [0.0, 1.0, 0.6, 1.0]);
    c.execute(&Command::Accum(GL_ACCUM, 0.5));
    clear_to(&mut c, [0.0; 4]);
    c.execute(&Command::Accum(GL_RETURN, 1.0));
    near(px(&c), [0.5, 0.5, 0.4, 1.0]);
    // RETURN scales and clamps.
    c.execute(&Command::Accum(GL_RETURN, 3.0));
    near(px(&c), [1.0, 1.0, 1.0, 1.0]);
    // MULT and ADD act on the accumulation values.
    c.execute(&Command::Accum(GL_MULT, 0.5));
    c.execute(&Command::Accum(GL_ADD, 0.1));
    c.execute(&Command::Accum(GL_RETURN, 1.0));
    near(px(&c), [0.35, 0.35, 0.3, 0.6]);
    // Accumulation values saturate at [-1, 1].
    c.execute(&Command::Accum(GL_ADD, 5.0));
    c.execute(&Command::Accum(GL_ADD, -1.5));
    c.execute(&Command::Accum(GL_RETURN, 1.0));
    near(px(&c), [0.0, 0.0, 0.0, 0.0]);
    assert_eq!(c.take_error(), GL_NO_ERROR);
}

#[test]
fn return_honours_the_colour_mask_and_clear_accum() {
    let mut c = context(true);
    c.execute(&Command::ClearAccum([0.25, -0.5, 2.0, 0.5]));
    c.execute(&Command::Clear(GL_ACCUM_BUFFER_BIT));
    clear_to(&mut c, [0.9, 0.9, 0.9, 0.9]);
    c.execute(&Command::ColorMask([true, true, false, true]));
    c.execute(&Command::Accum(GL_RETURN, 1.0));
    // Blue is masked; clear values clamp to [-1, 1] and return clamps at 0.
    near(px(&c), [0.25, 0.0, 0.9, 0.5]);
    let mut v = [0f32; 4];
    unsafe { c.get_into(GL_ACCUM_CLEAR_VALUE, v.as_mut_ptr(), |x| x.as_f64().into_iter().map(|f| f as f32).collect()) };
    assert_eq!(v, [0.25, -0.5, 1.0, 0.5]);
}

#[test]
fn scissor_limits_accumulation() {
    let mut c = context(true);
    clear_to(&mut c, [1.0; 4]);
    c.execute(&Command::Accum(GL_LOAD, 1.0));
    clear_to(&mut c, [0.0; 4]);
    c.execute(&Command::Scissor(0, 0, 2, 2));
    c.execute(&Command::Enable(GL_SCISSOR_TEST));
    c.execute(&Command::Accum(GL_RETURN, 1.0));
    assert_eq!(c.fb.color[c.fb.index(1, 1)], [255; 4]);
    assert_eq!(c.fb.color[c.fb.index(2, 2)], [0; 4]);
}

#[test]
fn accum_errors() {
    let mut c = context(false);
    c.execute(&Command::Accum(GL_LOAD, 1.0));
    assert_eq!(c.take_error(), GL_INVALID_OPERATION);
    let mut c = context(true);
    c.execute(&Command::Accum(0x1234, 1.0));
    assert_eq!(c.take_error(), GL_INVALID_ENUM);
    c.execute(&Command::Begin(GL_TRIANGLES));
    c.execute(&Command::Accum(GL_LOAD, 1.0));
    assert_eq!(c.take_error(), GL_INVALID_OPERATION);
}

/// A surface without alpha (a GLX RGB config) keeps alpha at 1.0 through
/// clears, colour masks and RETURN (framebuffer::Config::color_mask).
#[test]
fn no_alpha_surface_keeps_alpha_one() {
    let mut c = Context::new(Config { alpha_bits: 0, depth_bits: 24, stencil_bits: 8, accum_bits: 16 });
    c.fb.resize(4, 4).unwrap();
    c.surface_resized(4, 4);
    assert_eq!(px(&c)[3], 255, "a new RGB buffer starts with alpha 1.0");
    clear_to(&mut c, [0.2, 0.4, 0.6, 0.0]);
    near(px(&c), [0.2, 0.4, 0.6, 1.0]);
    // Only alpha enabled for writing: the clear changes nothing.
    c.execute(&Command::ColorMask([false, false, false, true]));
    clear_to(&mut c, [0.0; 4]);
    near(px(&c), [0.2, 0.4, 0.6, 1.0]);
    c.execute(&Command::ColorMask([true; 4]));
    c.execute(&Command::ClearAccum([0.5, 0.5, 0.5, 0.0]));
    c.execute(&Command::Clear(GL_ACCUM_BUFFER_BIT));
    c.execute(&Command::Accum(GL_RETURN, 1.0));
    near(px(&c), [0.5, 0.5, 0.5, 1.0]);
    assert_eq!(c.take_error(), GL_NO_ERROR);
}
