//! Texture images through the pixel pipeline (GL 1.5 section 3.8.1): the
//! unpack modes, pixel transfer and colour-index maps applied to
//! glTexImage/glTexSubImage, table 3.15/6.1 on the way in and out
//! (glGetTexImage), 8-bit RGBA/BGRA uploads, non-power-of-two sizes,
//! CopyTexImage's internal-format rule, and the texturing of glDrawPixels
//! fragments. Expected values are computed here from the spec's formulas.

use softgl::framebuffer::Config;
use softgl::gl::enums::*;
use softgl::gl::texture::enums as t;
use softgl::gl::texture::CopyTexCmd;
use softgl::gl::{Command, Context};

fn context(w: usize, h: usize) -> Context {
    let mut c = Context::new(Config { alpha_bits: 8, depth_bits: 24, stencil_bits: 8, accum_bits: 0 });
    c.fb.resize(w, h).unwrap();
    c.surface_resized(w as i32, h as i32);
    c
}

fn tex_image(c: &mut Context, ifmt: u32, w: i32, h: i32, format: u32, ty: u32, data: &[u8]) {
    let cmd = unsafe { c.tex_image_command(2, t::GL_TEXTURE_2D, 0, ifmt as i32, [w, h, 1], 0, format, ty, data.as_ptr()) };
    if let Some(cmd) = cmd {
        c.execute(&cmd);
    }
}

/// glGetTexImage of level 0 of the 2D texture as `format`/`ty`, n bytes.
fn get_image(c: &mut Context, format: u32, ty: u32, n: usize) -> Vec<u8> {
    let mut out = vec![0xEEu8; n];
    unsafe { c.get_tex_image(t::GL_TEXTURE_2D, 0, format, ty, out.as_mut_ptr()) };
    out
}

fn unorm8(v: f64) -> u8 {
    (v.clamp(0.0, 1.0) * 255.0).round() as u8
}

fn px(c: &Context, x: usize, y: usize) -> [u8; 4] {
    c.fb.color[c.fb.index(x, y)]
}

fn nearest_replace(c: &mut Context) {
    for (p, v) in [(t::GL_TEXTURE_MIN_FILTER, t::GL_NEAREST), (t::GL_TEXTURE_MAG_FILTER, t::GL_NEAREST)] {
        c.execute(&Command::TexParameter(t::GL_TEXTURE_2D, p, [v as f32, 0.0, 0.0, 0.0]));
    }
    c.execute(&Command::Enable(t::GL_TEXTURE_2D));
    c.execute(&Command::TexEnv(t::GL_TEXTURE_ENV, t::GL_TEXTURE_ENV_MODE, [t::GL_REPLACE as f32, 0.0, 0.0, 0.0]));
}

fn quad(c: &mut Context, s1: f32, t1: f32) {
    c.execute(&Command::Begin(GL_QUADS));
    for (x, y, s, tt) in [(-1.0, -1.0, 0.0, 0.0), (1.0, -1.0, s1, 0.0), (1.0, 1.0, s1, t1), (-1.0, 1.0, 0.0, t1)] {
        c.execute(&Command::TexCoord(t::GL_TEXTURE0, [s, tt, 0.0, 1.0]));
        c.execute(&Command::Vertex([x, y, 0.0, 1.0]));
    }
    c.execute(&Command::End);
}

/// Scale and bias (section 3.6.5) apply to texture images, then the clamp.
#[test]
fn tex_image_scale_and_bias() {
    let mut c = context(4, 4);
    c.pixel_transfer(GL_RED_SCALE, 0.5);
    c.pixel_transfer(GL_GREEN_BIAS, 0.25);
    c.pixel_transfer(GL_BLUE_SCALE, 2.0);
    c.pixel_transfer(GL_ALPHA_BIAS, -0.5);
    let src = [200u8, 100, 200, 255];
    tex_image(&mut c, t::GL_RGBA8, 1, 1, t::GL_RGBA, t::GL_UNSIGNED_BYTE, &src);
    assert_eq!(c.take_error(), GL_NO_ERROR);
    // glGetTexImage applies transfer too: back to identity first.
    c.pixel_transfer(GL_RED_SCALE, 1.0);
    c.pixel_transfer(GL_GREEN_BIAS, 0.0);
    c.pixel_transfer(GL_BLUE_SCALE, 1.0);
    c.pixel_transfer(GL_ALPHA_BIAS, 0.0);
    let f = |b: u8| b as f64 / 255.0;
    let expected = [unorm8(f(200) * 0.5), unorm8(f(100) + 0.25), unorm8(f(200) * 2.0), unorm8(1.0 - 0.5)];
    assert_eq!(expected, [100, 164, 255, 128]);
    assert_eq!(get_image(&mut c, t::GL_RGBA, t::GL_UNSIGNED_BYTE, 4), expected);
    // And glGetTexImage's own transfer: red scaled by 0.5 on the way out.
    c.pixel_transfer(GL_RED_SCALE, 0.5);
    assert_eq!(get_image(&mut c, t::GL_RGBA, t::GL_UNSIGNED_BYTE, 4)[0], unorm8(f(100) * 0.5));
}

/// MAP_COLOR: each component looked up at round(c (size - 1)).
#[test]
fn tex_image_color_maps() {
    let mut c = context(4, 4);
    c.pixel_map(GL_PIXEL_MAP_R_TO_R, &[1.0, 0.0]);
    c.pixel_map(GL_PIXEL_MAP_G_TO_G, &[0.0, 0.5]);
    c.pixel_map(GL_PIXEL_MAP_B_TO_B, &[0.25]);
    c.pixel_map(GL_PIXEL_MAP_A_TO_A, &[1.0]);
    c.pixel_transfer(GL_MAP_COLOR, 1.0);
    tex_image(&mut c, t::GL_RGBA8, 1, 1, t::GL_RGBA, t::GL_UNSIGNED_BYTE, &[200, 200, 50, 0]);
    c.pixel_transfer(GL_MAP_COLOR, 0.0);
    assert_eq!(get_image(&mut c, t::GL_RGBA, t::GL_UNSIGNED_BYTE, 4), [0, unorm8(0.5), unorm8(0.25), 255]);
}

/// Colour-index images go through INDEX_SHIFT/OFFSET and the I_TO_* maps
/// (index ANDed with size - 1).
#[test]
fn tex_image_color_index() {
    let mut c = context(4, 4);
    c.pixel_map(GL_PIXEL_MAP_I_TO_R, &[0.0, 1.0]);
    c.pixel_map(GL_PIXEL_MAP_I_TO_G, &[0.5, 0.25]);
    c.pixel_map(GL_PIXEL_MAP_I_TO_B, &[0.0]);
    c.pixel_map(GL_PIXEL_MAP_I_TO_A, &[1.0]);
    c.pixel_store(GL_UNPACK_ALIGNMENT, 1.0);
    tex_image(&mut c, t::GL_RGBA8, 3, 1, GL_COLOR_INDEX, t::GL_UNSIGNED_BYTE, &[0, 1, 3]);
    assert_eq!(c.take_error(), GL_NO_ERROR);
    let got = get_image(&mut c, t::GL_RGBA, t::GL_UNSIGNED_BYTE, 12);
    assert_eq!(got, [0, 128, 0, 255, 255, 64, 0, 255, 255, 64, 0, 255]);
}

/// Table 3.15 on the way in, table 6.1 on the way out; BGRA bytes.
#[test]
fn base_formats_and_bgra() {
    let mut c = context(4, 4);
    let cases: [(u32, [u8; 4]); 6] = [
        (t::GL_RGBA8, [10, 20, 30, 40]),
        (t::GL_RGB8, [10, 20, 30, 255]),
        (t::GL_ALPHA8, [0, 0, 0, 40]),
        (t::GL_LUMINANCE8, [10, 0, 0, 255]),
        (t::GL_LUMINANCE8_ALPHA8, [10, 0, 0, 40]),
        (t::GL_INTENSITY8, [10, 0, 0, 255]),
    ];
    for (ifmt, expected) in cases {
        tex_image(&mut c, ifmt, 1, 1, t::GL_RGBA, t::GL_UNSIGNED_BYTE, &[10, 20, 30, 40]);
        assert_eq!(get_image(&mut c, t::GL_RGBA, t::GL_UNSIGNED_BYTE, 4), expected, "internal format {ifmt:#x}");
        // BGRA bytes: swizzled into the same texels.
        tex_image(&mut c, ifmt, 1, 1, t::GL_BGRA, t::GL_UNSIGNED_BYTE, &[30, 20, 10, 40]);
        assert_eq!(get_image(&mut c, t::GL_RGBA, t::GL_UNSIGNED_BYTE, 4), expected, "BGRA into {ifmt:#x}");
    }
    // glGetTexImage's LUMINANCE is R, not R + G + B.
    tex_image(&mut c, t::GL_RGBA8, 1, 1, t::GL_RGBA, t::GL_UNSIGNED_BYTE, &[128, 64, 32, 255]);
    assert_eq!(get_image(&mut c, t::GL_LUMINANCE, t::GL_UNSIGNED_BYTE, 1), [128]);
    // Wide formats keep more than 8 bits.
    let v: [f32; 4] = [0.25, 0.5, 0.75, 1.0];
    let bytes: Vec<u8> = v.iter().flat_map(|f| f.to_ne_bytes()).collect();
    tex_image(&mut c, t::GL_RGBA16, 1, 1, t::GL_RGBA, t::GL_FLOAT, &bytes);
    let got = get_image(&mut c, t::GL_RGBA, t::GL_UNSIGNED_SHORT, 8);
    let shorts: Vec<u16> = got.chunks(2).map(|b| u16::from_ne_bytes([b[0], b[1]])).collect();
    assert_eq!(shorts, v.map(|f| (f as f64 * 65535.0).round() as u16));
}

/// RGBA bytes with ROW_LENGTH and SKIP_PIXELS: the row copy honours them.
#[test]
fn byte_upload_honours_unpack_modes() {
    let mut c = context(4, 4);
    // A 3x2 client image; the texture is its right 2x2.
    let img: Vec<u8> = (0..6u8).flat_map(|p| [p * 10, p * 10 + 1, p * 10 + 2, 255]).collect();
    c.pixel_store(GL_UNPACK_ROW_LENGTH, 3.0);
    c.pixel_store(GL_UNPACK_SKIP_PIXELS, 1.0);
    tex_image(&mut c, t::GL_RGBA8, 2, 2, t::GL_RGBA, t::GL_UNSIGNED_BYTE, &img);
    c.pixel_store(GL_UNPACK_ROW_LENGTH, 0.0);
    c.pixel_store(GL_UNPACK_SKIP_PIXELS, 0.0);
    let got = get_image(&mut c, t::GL_RGBA, t::GL_UNSIGNED_BYTE, 16);
    let expected: Vec<u8> = [1u8, 2, 4, 5].iter().flat_map(|&p| [p * 10, p * 10 + 1, p * 10 + 2, 255]).collect();
    assert_eq!(got, expected);
}

/// glTexSubImage goes through the same transfer, into 8-bit storage.
#[test]
fn tex_sub_image_transfer() {
    let mut c = context(4, 4);
    tex_image(&mut c, t::GL_RGBA8, 2, 2, t::GL_RGBA, t::GL_UNSIGNED_BYTE, &[0; 16]);
    c.pixel_transfer(GL_RED_BIAS, 0.5);
    let cmd = unsafe { c.tex_sub_image_command(2, t::GL_TEXTURE_2D, 0, [1, 1, 0], [1, 1, 1], t::GL_RGBA, t::GL_UNSIGNED_BYTE, [0u8, 0, 0, 255].as_ptr()) };
    c.execute(&cmd);
    c.pixel_transfer(GL_RED_BIAS, 0.0);
    assert_eq!(c.take_error(), GL_NO_ERROR);
    let got = get_image(&mut c, t::GL_RGBA, t::GL_UNSIGNED_BYTE, 16);
    assert_eq!(got[..12], [0; 12]);
    assert_eq!(got[12..], [unorm8(0.5), 0, 0, 255]);
}

/// Non-power-of-two textures sample like any other (REPEAT wraps by the
/// size, here 3).
#[test]
fn non_power_of_two_sampling() {
    let mut c = context(6, 4);
    let img: Vec<u8> = (0..2).flat_map(|j| (0..3).flat_map(move |i| [80 * i as u8, 100 * j as u8, 7, 255])).collect();
    tex_image(&mut c, t::GL_RGBA8, 3, 2, t::GL_RGBA, t::GL_UNSIGNED_BYTE, &img);
    assert_eq!(c.take_error(), GL_NO_ERROR);
    nearest_replace(&mut c);
    quad(&mut c, 1.0, 1.0);
    for y in 0..4 {
        for x in 0..6 {
            assert_eq!(px(&c, x, y), [80 * (x / 2) as u8, 100 * (y / 2) as u8, 7, 255], "pixel {x},{y}");
        }
    }
    // s from 0 to 2 over 6 pixels: texel floor((x + 1/2) / 6 * 2 * 3) mod 3.
    quad(&mut c, 2.0, 1.0);
    for x in 0..6 {
        assert_eq!(px(&c, x, 0)[0], 80 * (x % 3) as u8, "repeat at {x}");
    }
}

/// CopyTexImage does not take the internal formats 1 to 4 (GL 1.1):
/// INVALID_ENUM; a copied image goes through pixel transfer.
#[test]
fn copy_tex_image_rules() {
    let mut c = context(4, 4);
    let copy = |c: &mut Context, ifmt: u32| {
        c.execute(&Command::CopyTex(Box::new(CopyTexCmd { dims: 2, sub: false, target: t::GL_TEXTURE_2D, level: 0, internal_format: ifmt, offset: [0; 3], rect: [0, 0, 2, 2], border: 0 })));
        c.take_error()
    };
    for ifmt in 1..=4 {
        assert_eq!(copy(&mut c, ifmt), GL_INVALID_ENUM, "internal format {ifmt}");
    }
    let i = c.fb.index(1, 1);
    c.fb.color[i] = [200, 100, 50, 255];
    c.pixel_transfer(GL_GREEN_SCALE, 0.5);
    assert_eq!(copy(&mut c, t::GL_RGBA8), GL_NO_ERROR);
    c.pixel_transfer(GL_GREEN_SCALE, 1.0);
    let got = get_image(&mut c, t::GL_RGBA, t::GL_UNSIGNED_BYTE, 16);
    assert_eq!(got[12..], [200, unorm8(100.0 / 255.0 * 0.5), 50, 255]);
}

/// glDrawPixels fragments are textured with the raster position's texture
/// coordinates (section 3.6.4): MODULATE multiplies each group's colour.
#[test]
fn draw_pixels_are_textured() {
    let mut c = context(4, 4);
    tex_image(&mut c, t::GL_RGBA8, 1, 1, t::GL_RGBA, t::GL_UNSIGNED_BYTE, &[255, 128, 0, 255]);
    nearest_replace(&mut c);
    c.execute(&Command::TexEnv(t::GL_TEXTURE_ENV, t::GL_TEXTURE_ENV_MODE, [t::GL_MODULATE as f32, 0.0, 0.0, 0.0]));
    c.execute(&Command::TexCoord(t::GL_TEXTURE0, [0.5, 0.5, 0.0, 1.0]));
    c.execute(&Command::RasterPos([-1.0, -1.0, 0.0, 1.0]));
    let groups: [f32; 8] = [0.5, 1.0, 1.0, 1.0, 1.0, 1.0, 1.0, 0.5];
    let draw = |c: &mut Context| {
        let cmd = unsafe { c.build_draw_pixels(2, 1, t::GL_RGBA, t::GL_FLOAT, groups.as_ptr() as *const u8) }.unwrap();
        c.execute(&cmd);
    };
    draw(&mut c);
    assert_eq!(c.take_error(), GL_NO_ERROR);
    let m = |a: f64, b: u8| ((a * (b as f64 / 255.0)) * 255.0 + 0.5) as u8;
    assert_eq!(px(&c, 0, 0), [m(0.5, 255), m(1.0, 128), 0, 255]);
    assert_eq!(px(&c, 1, 0), [255, 128, 0, m(0.5, 255)]);
    // Texturing off: the groups' own colours.
    c.execute(&Command::Disable(t::GL_TEXTURE_2D));
    draw(&mut c);
    assert_eq!(px(&c, 0, 0), [128, 255, 255, 255]);
}

/// EXT_packed_depth_stencil: DEPTH_STENCIL / UNSIGNED_INT_24_8 words
/// (depth << 8 | stencil) through ReadPixels, DrawPixels, CopyPixels and
/// depth textures; its format/type errors.
#[test]
fn packed_depth_stencil() {
    use softgl::gl::pixel_data::{GL_DEPTH_STENCIL, GL_UNSIGNED_INT_24_8};
    let mut c = context(4, 4);
    let i = c.fb.index(1, 2);
    c.fb.depth[i] = 0x123456;
    c.fb.stencil[i] = 0x9A;
    let mut word = [0u32; 1];
    unsafe { c.read_pixels(1, 2, 1, 1, GL_DEPTH_STENCIL, GL_UNSIGNED_INT_24_8, word.as_mut_ptr() as *mut u8) };
    assert_eq!(c.take_error(), GL_NO_ERROR);
    assert_eq!(word[0], 0x123456 << 8 | 0x9A);
    // Errors: the format takes only its type, the type only its format.
    unsafe { c.read_pixels(0, 0, 1, 1, GL_DEPTH_STENCIL, GL_FLOAT, word.as_mut_ptr() as *mut u8) };
    assert_eq!(c.take_error(), GL_INVALID_ENUM);
    unsafe { c.read_pixels(0, 0, 1, 1, GL_DEPTH_COMPONENT, GL_UNSIGNED_INT_24_8, word.as_mut_ptr() as *mut u8) };
    assert_eq!(c.take_error(), GL_INVALID_OPERATION);
    // DrawPixels writes both directly (GL 3.0 section 4.3.1): the depth
    // test is ignored, whether off (as piglit's readdrawpixels draws) or
    // on and failing every fragment; only the depth mask stops the depth.
    c.execute(&Command::RasterPos([-1.0, -1.0, 0.0, 1.0]));
    let words: [u32; 2] = [0x800000 << 8 | 0x11, 0xFFFFFF << 8 | 0x22];
    let cmd = unsafe { c.build_draw_pixels(2, 1, GL_DEPTH_STENCIL, GL_UNSIGNED_INT_24_8, words.as_ptr() as *const u8) }.unwrap();
    let (a, b) = (c.fb.index(0, 0), c.fb.index(1, 0));
    for (test, func) in [(false, GL_LESS), (true, GL_NEVER)] {
        c.fb.depth[a] = 0x10;
        c.fb.depth[b] = 0x10;
        c.fb.stencil[a] = 0;
        c.fb.stencil[b] = 0;
        c.execute(&if test { Command::Enable(GL_DEPTH_TEST) } else { Command::Disable(GL_DEPTH_TEST) });
        c.execute(&Command::DepthFunc(func));
        c.execute(&cmd);
        assert_eq!(c.take_error(), GL_NO_ERROR);
        assert_eq!((c.fb.depth[a], c.fb.stencil[a]), (0x800000, 0x11), "depth test {test}");
        assert_eq!((c.fb.depth[b], c.fb.stencil[b]), (0xFFFFFF, 0x22), "depth test {test}");
    }
    c.execute(&Command::DepthMask(false));
    c.fb.depth[a] = 0x10;
    c.fb.stencil[a] = 0;
    c.execute(&cmd);
    assert_eq!((c.fb.depth[a], c.fb.stencil[a]), (0x10, 0x11));
    c.execute(&Command::DepthMask(true));
    c.execute(&Command::Enable(GL_DEPTH_TEST));
    c.execute(&Command::DepthFunc(GL_ALWAYS));
    c.execute(&cmd);
    // CopyPixels(DEPTH_STENCIL) copies both to the raster position.
    c.execute(&Command::RasterPos([0.0, 0.0, 0.0, 1.0]));
    c.copy_pixels(0, 0, 2, 1, GL_DEPTH_STENCIL);
    assert_eq!(c.take_error(), GL_NO_ERROR);
    let (a2, b2) = (c.fb.index(2, 2), c.fb.index(3, 2));
    assert_eq!((c.fb.depth[a2], c.fb.stencil[a2]), (0x800000, 0x11));
    assert_eq!((c.fb.depth[b2], c.fb.stencil[b2]), (0xFFFFFF, 0x22));
    // A DEPTH24_STENCIL8 texture from DEPTH_STENCIL data keeps the depth
    // and the stencil: glGetTexImage gives the same words back.
    tex_image(&mut c, t::GL_DEPTH24_STENCIL8, 2, 1, GL_DEPTH_STENCIL, GL_UNSIGNED_INT_24_8, &[words[0].to_ne_bytes(), words[1].to_ne_bytes()].concat());
    assert_eq!(c.take_error(), GL_NO_ERROR);
    let q = |c: &mut Context, p: u32| c.get_tex_level_parameter(t::GL_TEXTURE_2D, 0, p).unwrap().as_i32()[0];
    assert_eq!((q(&mut c, t::GL_TEXTURE_DEPTH_SIZE), q(&mut c, t::GL_TEXTURE_STENCIL_SIZE)), (24, 8));
    let words_of = |b: Vec<u8>| -> Vec<u32> { b.chunks(4).map(|b| u32::from_ne_bytes([b[0], b[1], b[2], b[3]])).collect() };
    let got = words_of(get_image(&mut c, GL_DEPTH_STENCIL, GL_UNSIGNED_INT_24_8, 8));
    assert_eq!(got, words);
    // TexSubImage replaces one texel's pair; the other keeps its own.
    let sub = (0x400000u32 << 8 | 0x7F).to_ne_bytes();
    let cmd = unsafe { c.tex_sub_image_command(2, t::GL_TEXTURE_2D, 0, [1, 0, 0], [1, 1, 1], GL_DEPTH_STENCIL, GL_UNSIGNED_INT_24_8, sub.as_ptr()) };
    c.execute(&cmd);
    assert_eq!(c.take_error(), GL_NO_ERROR);
    assert_eq!(words_of(get_image(&mut c, GL_DEPTH_STENCIL, GL_UNSIGNED_INT_24_8, 8)), [words[0], 0x400000 << 8 | 0x7F]);
    // The stencil goes through INDEX_OFFSET on the way out (as for
    // glReadPixels): 0x11 + 3, 0x7F + 3.
    c.execute(&Command::PixelTransfer(GL_INDEX_OFFSET, 3.0));
    assert_eq!(words_of(get_image(&mut c, GL_DEPTH_STENCIL, GL_UNSIGNED_INT_24_8, 8)), [0x800000 << 8 | 0x14, 0x400000 << 8 | 0x82]);
    c.execute(&Command::PixelTransfer(GL_INDEX_OFFSET, 0.0));
    // CopyTexImage into DEPTH24_STENCIL8 copies the stencil buffer too:
    // the pixels at (2, 2), (3, 2) hold the pairs CopyPixels wrote.
    c.execute(&Command::CopyTex(Box::new(CopyTexCmd { dims: 2, sub: false, target: t::GL_TEXTURE_2D, level: 0, internal_format: t::GL_DEPTH24_STENCIL8, offset: [0; 3], rect: [2, 2, 2, 1], border: 0 })));
    assert_eq!(c.take_error(), GL_NO_ERROR);
    assert_eq!(words_of(get_image(&mut c, GL_DEPTH_STENCIL, GL_UNSIGNED_INT_24_8, 8)), words);
    // Colour formats do not take depth/stencil data.
    tex_image(&mut c, t::GL_RGBA8, 1, 1, GL_DEPTH_STENCIL, GL_UNSIGNED_INT_24_8, &[0; 4]);
    assert_eq!(c.take_error(), GL_INVALID_OPERATION);
}

/// ARB_texture_rg: RED and RG internal formats keep R (and G), the other
/// colour components read as 0; GL_RG is a pixel format.
#[test]
fn red_and_rg() {
    let mut c = context(4, 4);
    for (ifmt, expected) in [(t::GL_R8, [10u8, 0, 0, 255]), (t::GL_RG8, [10, 20, 0, 255]), (t::GL_RED, [10, 0, 0, 255]), (t::GL_RG16, [10, 20, 0, 255])] {
        tex_image(&mut c, ifmt, 1, 1, t::GL_RGBA, t::GL_UNSIGNED_BYTE, &[10, 20, 30, 40]);
        assert_eq!(c.take_error(), GL_NO_ERROR);
        assert_eq!(get_image(&mut c, t::GL_RGBA, t::GL_UNSIGNED_BYTE, 4), expected, "{ifmt:#x}");
    }
    let q = |c: &mut Context, p: u32| c.get_tex_level_parameter(t::GL_TEXTURE_2D, 0, p).unwrap().as_i32()[0];
    tex_image(&mut c, t::GL_RG8, 1, 1, t::GL_RGBA, t::GL_UNSIGNED_BYTE, &[10, 20, 30, 40]);
    assert_eq!([q(&mut c, t::GL_TEXTURE_RED_SIZE), q(&mut c, t::GL_TEXTURE_GREEN_SIZE), q(&mut c, t::GL_TEXTURE_BLUE_SIZE)], [8, 8, 0]);
    // GL_RG pixels: R and G, B = 0, A = 1; packed types do not fit it.
    c.execute(&Command::RasterPos([-1.0, -1.0, 0.0, 1.0]));
    let rg: [f32; 2] = [0.5, 0.25];
    let cmd = unsafe { c.build_draw_pixels(1, 1, t::GL_RG, t::GL_FLOAT, rg.as_ptr() as *const u8) }.unwrap();
    c.execute(&cmd);
    assert_eq!(c.take_error(), GL_NO_ERROR);
    assert_eq!(px(&c, 0, 0), [128, 64, 0, 255]);
    let cmd = unsafe { c.build_draw_pixels(1, 1, t::GL_RG, t::GL_UNSIGNED_BYTE_3_3_2, rg.as_ptr() as *const u8) }.unwrap();
    c.execute(&cmd);
    assert_eq!(c.take_error(), GL_INVALID_OPERATION);
}
