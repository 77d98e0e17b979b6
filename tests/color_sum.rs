//! The colour sum (GL 1.4 section 3.9): the secondary colour is added after
//! texturing, when GL_COLOR_SUM is on or lighting uses
//! GL_SEPARATE_SPECULAR_COLOR.

use softgl::framebuffer::Config;
use softgl::gl::enums::*;
use softgl::gl::texture::enums as t;
use softgl::gl::{Command, Context};

fn context() -> Context {
    let mut c = Context::new(Config { depth_bits: 24, stencil_bits: 8, accum_bits: 0 });
    c.fb.resize(4, 4).unwrap();
    c.surface_resized(4, 4);
    c
}

fn quad(c: &mut Context) -> [u8; 4] {
    c.execute(&Command::Color([0.25, 0.0, 0.0, 1.0]));
    c.execute(&Command::SecondaryColor([0.5, 0.25, 0.0, 1.0]));
    c.execute(&Command::TexCoord(t::GL_TEXTURE0, [0.5, 0.5, 0.0, 1.0]));
    c.execute(&Command::Rect([-1.0, -1.0, 1.0, 1.0]));
    c.fb.color[c.fb.index(2, 2)]
}

#[test]
fn secondary_colour_is_added_when_enabled() {
    let mut c = context();
    assert_eq!(quad(&mut c), [64, 0, 0, 255], "off: the primary colour only");
    c.execute(&Command::Enable(GL_COLOR_SUM));
    assert_eq!(quad(&mut c), [191, 64, 0, 255]);
}

#[test]
fn the_sum_comes_after_texturing() {
    let mut c = context();
    // A 1x1 texture of grey 0.5, GL_MODULATE: (primary * 0.5) + secondary.
    let texel = [128u8, 128, 128, 255];
    let cmd = unsafe { c.tex_image_command(2, t::GL_TEXTURE_2D, 0, t::GL_RGBA8 as i32, [1, 1, 1], 0, t::GL_RGBA, t::GL_UNSIGNED_BYTE, texel.as_ptr()) };
    c.submit(cmd.unwrap());
    c.execute(&Command::TexParameter(t::GL_TEXTURE_2D, t::GL_TEXTURE_MIN_FILTER, [t::GL_NEAREST as f32, 0.0, 0.0, 0.0]));
    c.execute(&Command::Enable(t::GL_TEXTURE_2D));
    c.execute(&Command::Enable(GL_COLOR_SUM));
    let got = quad(&mut c);
    // 0.25 * 128/255 + 0.5 = 0.6255 -> 160; 0.25; 0.
    assert_eq!(got, [160, 64, 0, 255]);
    c.execute(&Command::Disable(GL_COLOR_SUM));
    assert_eq!(quad(&mut c), [32, 0, 0, 255], "modulated primary only");
}
