//! ARB_texture_rectangle through the GL state machine: unnormalized
//! coordinates, filters and wraps, enable priority, the extension's errors
//! and initial state, proxies and queries.

use softgl::framebuffer::Config;
use softgl::gl::enums::*;
use softgl::gl::texture::enums as t;
use softgl::gl::{Command, Context};

const RECT: u32 = t::GL_TEXTURE_RECTANGLE;

fn context(w: usize, h: usize) -> Context {
    let mut c = Context::new(Config { alpha_bits: 8, depth_bits: 24, stencil_bits: 8, accum_bits: 0 });
    c.fb.resize(w, h).unwrap();
    c.surface_resized(w as i32, h as i32);
    c
}

fn tex_image(c: &mut Context, target: u32, level: i32, w: i32, h: i32, border: i32, data: &[u8]) {
    let ptr = if data.is_empty() { std::ptr::null() } else { data.as_ptr() };
    if let Some(cmd) = unsafe { c.tex_image_command(2, target, level, t::GL_RGBA8 as i32, [w, h, 1], border, t::GL_RGBA, t::GL_UNSIGNED_BYTE, ptr) } {
        c.submit(cmd);
    }
}

fn param(c: &mut Context, target: u32, pname: u32, v: u32) {
    c.execute(&Command::TexParameter(target, pname, [v as f32, 0.0, 0.0, 0.0]));
}

fn replace_env(c: &mut Context) {
    c.execute(&Command::TexEnv(t::GL_TEXTURE_ENV, t::GL_TEXTURE_ENV_MODE, [t::GL_REPLACE as f32, 0.0, 0.0, 0.0]));
}

/// A quad over the whole viewport with (s0, t0) .. (s1, t1) at its corners.
fn quad(c: &mut Context, s0: f32, t0: f32, s1: f32, t1: f32) {
    c.execute(&Command::Begin(GL_QUADS));
    for (x, y, s, tt) in [(-1.0, -1.0, s0, t0), (1.0, -1.0, s1, t0), (1.0, 1.0, s1, t1), (-1.0, 1.0, s0, t1)] {
        c.execute(&Command::TexCoord(t::GL_TEXTURE0, [s, tt, 0.0, 1.0]));
        c.execute(&Command::Vertex([x, y, 0.0, 1.0]));
    }
    c.execute(&Command::End);
}

fn px(c: &Context, x: usize, y: usize) -> [u8; 4] {
    c.fb.color[c.fb.index(x, y)]
}

fn int(c: &mut Context, pname: u32) -> i64 {
    c.get(pname).unwrap().as_f64()[0] as i64
}

/// Texel (i, j) of the test images: (40 i, 60 j, 7, 255).
fn image(w: usize, h: usize) -> Vec<u8> {
    (0..h).flat_map(|j| (0..w).flat_map(move |i| [(40 * i) as u8, (60 * j) as u8, 7, 255])).collect()
}

#[test]
fn nearest_uses_texel_coordinates() {
    // A 4x3 rectangle over an 8x6 window, s from 0 to 4 and t from 0 to 3:
    // pixel (x, y) has its centre at s = (x + 1/2) / 2, so texel x / 2.
    let mut c = context(8, 6);
    tex_image(&mut c, RECT, 0, 4, 3, 0, &image(4, 3));
    param(&mut c, RECT, t::GL_TEXTURE_MIN_FILTER, t::GL_NEAREST);
    param(&mut c, RECT, t::GL_TEXTURE_MAG_FILTER, t::GL_NEAREST);
    c.execute(&Command::Enable(RECT));
    replace_env(&mut c);
    quad(&mut c, 0.0, 0.0, 4.0, 3.0);
    assert_eq!(c.take_error(), GL_NO_ERROR);
    for y in 0..6 {
        for x in 0..8 {
            assert_eq!(px(&c, x, y), [(40 * (x / 2)) as u8, (60 * (y / 2)) as u8, 7, 255], "pixel {x},{y}");
        }
    }
}

#[test]
fn linear_weights_in_texels() {
    // A 2x1 rectangle (red 0 and 200) over 4x1 pixels, s from 0 to 2:
    // centres at s = 0.25, 0.75, 1.25, 1.75; u - 1/2 = -0.25 (clamped to
    // texel 0), 0.25, 0.75, 1.25 (clamped to texel 1).
    let mut c = context(4, 1);
    tex_image(&mut c, RECT, 0, 2, 1, 0, &[0, 0, 0, 255, 200, 0, 0, 255]);
    c.execute(&Command::Enable(RECT));
    replace_env(&mut c);
    // The initial filters are LINEAR (the rectangle's minification default).
    quad(&mut c, 0.0, 0.0, 2.0, 1.0);
    let red: Vec<u8> = (0..4).map(|x| px(&c, x, 0)[0]).collect();
    assert_eq!(red, [0, 50, 150, 200]);
}

#[test]
fn clamp_to_border_and_clamp() {
    // s from -2 to 6 over 8 pixels on a 4x1 nearest rectangle: centres at
    // -1.5 .. 5.5. CLAMP_TO_BORDER reads the border colour outside [0, 4];
    // CLAMP_TO_EDGE repeats the edge texels.
    let mut c = context(8, 1);
    tex_image(&mut c, RECT, 0, 4, 1, 0, &image(4, 1));
    param(&mut c, RECT, t::GL_TEXTURE_MIN_FILTER, t::GL_NEAREST);
    param(&mut c, RECT, t::GL_TEXTURE_MAG_FILTER, t::GL_NEAREST);
    param(&mut c, RECT, t::GL_TEXTURE_WRAP_S, t::GL_CLAMP_TO_BORDER);
    c.execute(&Command::TexParameter(RECT, t::GL_TEXTURE_BORDER_COLOR, [0.0, 0.0, 1.0, 1.0]));
    c.execute(&Command::Enable(RECT));
    replace_env(&mut c);
    quad(&mut c, -2.0, 0.0, 6.0, 1.0);
    assert_eq!(c.take_error(), GL_NO_ERROR);
    let blue = [0, 0, 255, 255];
    let row: Vec<[u8; 4]> = (0..8).map(|x| px(&c, x, 0)).collect();
    assert_eq!(row, [blue, blue, [0, 0, 7, 255], [40, 0, 7, 255], [80, 0, 7, 255], [120, 0, 7, 255], blue, blue]);
    param(&mut c, RECT, t::GL_TEXTURE_WRAP_S, t::GL_CLAMP_TO_EDGE);
    quad(&mut c, -2.0, 0.0, 6.0, 1.0);
    let red: Vec<u8> = (0..8).map(|x| px(&c, x, 0)[0]).collect();
    assert_eq!(red, [0, 0, 0, 40, 80, 120, 120, 120]);
}

#[test]
fn enable_priority_cube_3d_rect_2d() {
    let mut c = context(2, 2);
    replace_env(&mut c);
    // 2D: one green texel; rectangle: one red texel.
    tex_image(&mut c, t::GL_TEXTURE_2D, 0, 1, 1, 0, &[0, 255, 0, 255]);
    param(&mut c, t::GL_TEXTURE_2D, t::GL_TEXTURE_MIN_FILTER, t::GL_NEAREST);
    tex_image(&mut c, RECT, 0, 1, 1, 0, &[255, 0, 0, 255]);
    c.execute(&Command::Enable(t::GL_TEXTURE_2D));
    quad(&mut c, 0.0, 0.0, 1.0, 1.0);
    assert_eq!(px(&c, 0, 0), [0, 255, 0, 255]);
    c.execute(&Command::Enable(RECT));
    assert!(c.is_enabled(RECT).unwrap());
    quad(&mut c, 0.0, 0.0, 1.0, 1.0);
    assert_eq!(px(&c, 0, 0), [255, 0, 0, 255], "rectangle over 2D");
    // 3D wins over the rectangle: one blue texel.
    let blue = [0u8, 0, 255, 255];
    if let Some(cmd) = unsafe { c.tex_image_command(3, t::GL_TEXTURE_3D, 0, t::GL_RGBA8 as i32, [1, 1, 1], 0, t::GL_RGBA, t::GL_UNSIGNED_BYTE, blue.as_ptr()) } {
        c.submit(cmd);
    }
    param(&mut c, t::GL_TEXTURE_3D, t::GL_TEXTURE_MIN_FILTER, t::GL_NEAREST);
    c.execute(&Command::Enable(t::GL_TEXTURE_3D));
    quad(&mut c, 0.0, 0.0, 1.0, 1.0);
    assert_eq!(px(&c, 0, 0), blue, "3D over rectangle");
    c.execute(&Command::Disable(t::GL_TEXTURE_3D));
    c.execute(&Command::Disable(RECT));
    quad(&mut c, 0.0, 0.0, 1.0, 1.0);
    assert_eq!(px(&c, 0, 0), [0, 255, 0, 255]);
}

#[test]
fn initial_state_errors_and_queries() {
    let mut c = context(4, 4);
    assert_eq!(int(&mut c, t::GL_MAX_RECTANGLE_TEXTURE_SIZE), 4096);
    assert_eq!(int(&mut c, t::GL_TEXTURE_BINDING_RECTANGLE), 0);
    c.execute(&Command::BindTexture(RECT, 7));
    assert_eq!(int(&mut c, t::GL_TEXTURE_BINDING_RECTANGLE), 7);
    // An object first bound as a rectangle cannot be bound as 2D.
    c.execute(&Command::BindTexture(t::GL_TEXTURE_2D, 7));
    assert_eq!(c.take_error(), GL_INVALID_OPERATION);
    let get = |c: &mut Context, pname: u32| c.get_tex_parameter(RECT, pname).unwrap().as_f64()[0] as u32;
    assert_eq!(get(&mut c, t::GL_TEXTURE_WRAP_S), t::GL_CLAMP_TO_EDGE);
    assert_eq!(get(&mut c, t::GL_TEXTURE_WRAP_T), t::GL_CLAMP_TO_EDGE);
    assert_eq!(get(&mut c, t::GL_TEXTURE_MIN_FILTER), t::GL_LINEAR);
    for (pname, v, err) in [
        (t::GL_TEXTURE_WRAP_S, t::GL_REPEAT, GL_INVALID_ENUM),
        (t::GL_TEXTURE_WRAP_T, t::GL_MIRRORED_REPEAT, GL_INVALID_ENUM),
        (t::GL_TEXTURE_MIN_FILTER, t::GL_LINEAR_MIPMAP_LINEAR, GL_INVALID_ENUM),
        (t::GL_TEXTURE_MIN_FILTER, t::GL_NEAREST_MIPMAP_NEAREST, GL_INVALID_ENUM),
        (t::GL_TEXTURE_BASE_LEVEL, 1, GL_INVALID_OPERATION),
    ] {
        param(&mut c, RECT, pname, v);
        assert_eq!(c.take_error(), err, "{pname:#x} {v:#x}");
    }
    assert_eq!(get(&mut c, t::GL_TEXTURE_WRAP_S), t::GL_CLAMP_TO_EDGE, "a rejected value changes nothing");
    for (pname, v) in [(t::GL_TEXTURE_WRAP_S, t::GL_CLAMP), (t::GL_TEXTURE_WRAP_T, t::GL_CLAMP_TO_BORDER), (t::GL_TEXTURE_MIN_FILTER, t::GL_NEAREST), (t::GL_TEXTURE_BASE_LEVEL, 0)] {
        param(&mut c, RECT, pname, v);
        assert_eq!(c.take_error(), GL_NO_ERROR);
    }
    // One level, no border.
    tex_image(&mut c, RECT, 1, 4, 4, 0, &[]);
    assert_eq!(c.take_error(), GL_INVALID_VALUE);
    tex_image(&mut c, RECT, 0, 6, 6, 1, &[]);
    assert_eq!(c.take_error(), GL_INVALID_VALUE);
    tex_image(&mut c, RECT, 0, 5, 3, 0, &[]);
    assert_eq!(c.take_error(), GL_NO_ERROR);
    let level = |c: &mut Context, target: u32, pname: u32| c.get_tex_level_parameter(target, 0, pname).unwrap().as_f64()[0] as i64;
    assert_eq!((level(&mut c, RECT, t::GL_TEXTURE_WIDTH), level(&mut c, RECT, t::GL_TEXTURE_HEIGHT)), (5, 3));
    assert!(c.get_tex_level_parameter(RECT, 1, t::GL_TEXTURE_WIDTH).is_none());
    assert_eq!(c.take_error(), GL_INVALID_VALUE);
    // 1D and 3D image calls do not take the rectangle target.
    let cmd = unsafe { c.tex_image_command(1, RECT, 0, t::GL_RGBA8 as i32, [4, 1, 1], 0, t::GL_RGBA, t::GL_UNSIGNED_BYTE, std::ptr::null()) };
    c.submit(cmd.unwrap());
    assert_eq!(c.take_error(), GL_INVALID_ENUM);
    // Proxies: the largest size fits, twice it gives width 0 and no error.
    tex_image(&mut c, t::GL_PROXY_TEXTURE_RECTANGLE, 0, 4096, 4096, 0, &[]);
    assert_eq!(level(&mut c, t::GL_PROXY_TEXTURE_RECTANGLE, t::GL_TEXTURE_WIDTH), 4096);
    tex_image(&mut c, t::GL_PROXY_TEXTURE_RECTANGLE, 0, 8192, 8192, 0, &[]);
    assert_eq!(level(&mut c, t::GL_PROXY_TEXTURE_RECTANGLE, t::GL_TEXTURE_WIDTH), 0);
    tex_image(&mut c, t::GL_PROXY_TEXTURE_RECTANGLE, 0, 4097, 16, 0, &[]);
    assert_eq!(level(&mut c, t::GL_PROXY_TEXTURE_RECTANGLE, t::GL_TEXTURE_WIDTH), 0);
    assert_eq!(c.take_error(), GL_NO_ERROR);
}

#[test]
fn copy_and_get_image() {
    let mut c = context(4, 4);
    c.execute(&Command::ClearColor([1.0, 0.0, 1.0, 1.0]));
    c.execute(&Command::Clear(GL_COLOR_BUFFER_BIT));
    c.execute(&Command::CopyTex(Box::new(softgl::gl::texture::CopyTexCmd { dims: 2, sub: false, target: RECT, level: 0, internal_format: t::GL_RGBA8, offset: [0; 3], rect: [0, 0, 3, 2], border: 0 })));
    assert_eq!(c.take_error(), GL_NO_ERROR);
    let mut out = vec![0u8; 3 * 2 * 4];
    unsafe { c.get_tex_image(RECT, 0, t::GL_RGBA, t::GL_UNSIGNED_BYTE, out.as_mut_ptr()) };
    assert_eq!(c.take_error(), GL_NO_ERROR);
    assert!(out.chunks(4).all(|p| p == [255, 0, 255, 255]), "{out:?}");
}

#[test]
fn advertised() {
    let s = softgl::gl::get::string(GL_EXTENSIONS).unwrap();
    let s = std::str::from_utf8(&s[..s.len() - 1]).unwrap();
    for name in ["GL_ARB_texture_rectangle", "GL_EXT_texture_rectangle", "GL_NV_texture_rectangle"] {
        assert!(s.split(' ').any(|n| n == name), "{name}");
    }
    assert!(s.ends_with(' '));
}
