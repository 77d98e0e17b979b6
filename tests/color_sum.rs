//! The colour sum (GL 1.4 section 3.9): the secondary colour is added after
//! texturing, when GL_COLOR_SUM is on or lighting uses
//! GL_SEPARATE_SPECULAR_COLOR.

use softgl::framebuffer::Config;
use softgl::gl::enums::*;
use softgl::gl::texture::enums as t;
use softgl::gl::{Command, Context};

fn context() -> Context {
    let mut c = Context::new(Config { alpha_bits: 8, depth_bits: 24, stencil_bits: 8, accum_bits: 0 });
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

#[test]
fn back_faces_take_the_back_specular_under_two_sided_lighting() {
    let mut c = context();
    let texel = [255u8, 255, 255, 255];
    let cmd = unsafe { c.tex_image_command(2, t::GL_TEXTURE_2D, 0, t::GL_RGBA8 as i32, [1, 1, 1], 0, t::GL_RGBA, t::GL_UNSIGNED_BYTE, texel.as_ptr()) };
    c.submit(cmd.unwrap());
    c.execute(&Command::TexParameter(t::GL_TEXTURE_2D, t::GL_TEXTURE_MIN_FILTER, [t::GL_NEAREST as f32, 0.0, 0.0, 0.0]));
    c.execute(&Command::Enable(t::GL_TEXTURE_2D));
    c.execute(&Command::Enable(GL_LIGHTING));
    c.execute(&Command::Enable(GL_LIGHT0));
    c.execute(&Command::LightModel(GL_LIGHT_MODEL_TWO_SIDE, [1.0, 0.0, 0.0, 0.0]));
    c.execute(&Command::LightModel(GL_LIGHT_MODEL_COLOR_CONTROL, [GL_SEPARATE_SPECULAR_COLOR as f32, 0.0, 0.0, 0.0]));
    c.execute(&Command::LightModel(GL_LIGHT_MODEL_AMBIENT, [0.0, 0.0, 0.0, 1.0]));
    let black = [0.0, 0.0, 0.0, 1.0];
    c.execute(&Command::Material(GL_FRONT_AND_BACK, GL_DIFFUSE, black));
    c.execute(&Command::Material(GL_FRONT_AND_BACK, GL_AMBIENT, black));
    c.execute(&Command::Material(GL_FRONT, GL_SPECULAR, [0.0, 0.0, 1.0, 1.0]));
    c.execute(&Command::Material(GL_BACK, GL_SPECULAR, [1.0, 0.0, 0.0, 1.0]));
    // The light (0, 0, 1) shines on the back side of a normal (0, 0, -1),
    // whose back face the lighting sees as (0, 0, 1): full specular.
    c.execute(&Command::Normal([0.0, 0.0, -1.0]));
    c.execute(&Command::FrontFace(GL_CW));
    c.execute(&Command::TexCoord(t::GL_TEXTURE0, [0.5, 0.5, 0.0, 1.0]));
    c.execute(&Command::Rect([-1.0, -1.0, 1.0, 1.0]));
    // Primary 0 times the white texture, plus the back specular: red.
    assert_eq!(c.fb.color[c.fb.index(2, 2)], [255, 0, 0, 255]);
    // The front face (normal towards the light) takes the front specular.
    c.execute(&Command::Normal([0.0, 0.0, 1.0]));
    c.execute(&Command::FrontFace(GL_CCW));
    c.execute(&Command::Rect([-1.0, -1.0, 1.0, 1.0]));
    assert_eq!(c.fb.color[c.fb.index(2, 2)], [0, 0, 255, 255]);
}

/// Flat shading takes the provoking vertex's secondary colour too
/// (section 2.14.7), also when texturing makes the sum per fragment: a
/// triangle (provoking vertex last) and a quad (provoking vertex last)
/// whose other vertices have other secondary colours are uniform.
#[test]
fn flat_shading_takes_the_provoking_secondary_colour() {
    let mut c = context();
    let texel = [255u8, 255, 255, 255];
    let cmd = unsafe { c.tex_image_command(2, t::GL_TEXTURE_2D, 0, t::GL_RGBA8 as i32, [1, 1, 1], 0, t::GL_RGBA, t::GL_UNSIGNED_BYTE, texel.as_ptr()) };
    c.submit(cmd.unwrap());
    c.execute(&Command::TexParameter(t::GL_TEXTURE_2D, t::GL_TEXTURE_MIN_FILTER, [t::GL_NEAREST as f32, 0.0, 0.0, 0.0]));
    c.execute(&Command::Enable(t::GL_TEXTURE_2D));
    c.execute(&Command::Enable(GL_COLOR_SUM));
    c.execute(&Command::ShadeModel(GL_FLAT));
    c.execute(&Command::Color([0.0, 0.0, 0.0, 1.0]));
    for (mode, verts) in [(GL_TRIANGLES, vec![[-3.0, -1.0], [1.0, -1.0], [1.0, 3.0]]), (GL_QUADS, vec![[-1.0, -1.0], [1.0, -1.0], [1.0, 1.0], [-1.0, 1.0]])] {
        c.execute(&Command::Begin(mode));
        let n = verts.len();
        for (i, v) in verts.iter().enumerate() {
            let s = if i + 1 == n { [0.0, 0.0, 1.0, 1.0] } else { [1.0, 0.0, 0.0, 1.0] };
            c.execute(&Command::SecondaryColor(s));
            c.execute(&Command::TexCoord(t::GL_TEXTURE0, [0.5, 0.5, 0.0, 1.0]));
            c.execute(&Command::Vertex([v[0], v[1], 0.0, 1.0]));
        }
        c.execute(&Command::End);
        for (x, y) in [(2, 1), (3, 0), (3, 3), (2, 2)] {
            assert_eq!(c.fb.color[c.fb.index(x, y)], [0, 0, 255, 255], "mode {mode:#x} pixel {x},{y}");
        }
    }
}
