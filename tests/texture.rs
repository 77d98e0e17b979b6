//! Texturing through the GL state machine: texel fetch, wraps, filters,
//! LOD selection, completeness, errors, environments, texgen.

use softgl::framebuffer::Config;
use softgl::gl::enums::*;
use softgl::gl::texture::enums as t;
use softgl::gl::{Command, Context};

fn context(w: usize, h: usize) -> Context {
    let mut c = Context::new(Config { alpha_bits: 8, depth_bits: 24, stencil_bits: 8, accum_bits: 0 });
    c.fb.resize(w, h).unwrap();
    c.surface_resized(w as i32, h as i32);
    c
}

/// glTexImage2D with RGBA bytes.
fn tex_image_2d(c: &mut Context, level: i32, ifmt: u32, w: i32, h: i32, border: i32, data: &[u8]) {
    c.submit(Command::ActiveTexture(t::GL_TEXTURE0 + active(c)));
    let cmd = unsafe { c.tex_image_command(2, t::GL_TEXTURE_2D, level, ifmt as i32, [w, h, 1], border, t::GL_RGBA, t::GL_UNSIGNED_BYTE, if data.is_empty() { std::ptr::null() } else { data.as_ptr() }) };
    if let Some(cmd) = cmd {
        c.submit(cmd);
    }
}

fn active(c: &Context) -> u32 {
    c.texture.active as u32
}

fn param(c: &mut Context, pname: u32, v: u32) {
    c.execute(&Command::TexParameter(t::GL_TEXTURE_2D, pname, [v as f32, 0.0, 0.0, 0.0]));
}

/// Draws a quad over the whole viewport (identity matrices) with texture
/// coordinates (s0, t0) .. (s1, t1) at its corners.
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

/// A w x h RGBA image whose texel (i, j) is (16 i, 16 j, 200, 255).
fn ramp(w: usize, h: usize) -> Vec<u8> {
    let mut v = Vec::new();
    for j in 0..h {
        for i in 0..w {
            v.extend_from_slice(&[(16 * i) as u8, (16 * j) as u8, 200, 255]);
        }
    }
    v
}

fn setup_2d(c: &mut Context, w: i32, h: i32, filter: u32) {
    tex_image_2d(c, 0, t::GL_RGBA8, w, h, 0, &ramp(w as usize, h as usize));
    param(c, t::GL_TEXTURE_MIN_FILTER, filter);
    param(c, t::GL_TEXTURE_MAG_FILTER, filter);
    c.execute(&Command::Enable(t::GL_TEXTURE_2D));
    c.execute(&Command::TexEnv(t::GL_TEXTURE_ENV, t::GL_TEXTURE_ENV_MODE, [t::GL_REPLACE as f32, 0.0, 0.0, 0.0]));
}

#[test]
fn nearest_fetch_at_texel_centres() {
    let mut c = context(8, 8);
    setup_2d(&mut c, 4, 4, t::GL_NEAREST);
    quad(&mut c, 0.0, 0.0, 1.0, 1.0);
    assert_eq!(c.take_error(), GL_NO_ERROR);
    for y in 0..8 {
        for x in 0..8 {
            assert_eq!(px(&c, x, y), [(16 * (x / 2)) as u8, (16 * (y / 2)) as u8, 200, 255], "pixel {x},{y}");
        }
    }
}

#[test]
fn nearest_one_to_one_and_edges() {
    // 8x8 texture on 8x8 pixels: pixel centres are texel centres.
    let mut c = context(8, 8);
    setup_2d(&mut c, 8, 8, t::GL_NEAREST);
    quad(&mut c, 0.0, 0.0, 1.0, 1.0);
    for y in 0..8 {
        for x in 0..8 {
            assert_eq!(px(&c, x, y)[..2], [(16 * x) as u8, (16 * y) as u8], "pixel {x},{y}");
        }
    }
}

#[test]
fn wrap_modes() {
    // s from -1 to 1 across 8 pixels of a 4-texel-wide texture.
    let cases: [(u32, [u8; 8]); 4] = [
        (t::GL_REPEAT, [0, 1, 2, 3, 0, 1, 2, 3]),
        (t::GL_CLAMP_TO_EDGE, [0, 0, 0, 0, 0, 1, 2, 3]),
        (t::GL_MIRRORED_REPEAT, [3, 2, 1, 0, 0, 1, 2, 3]),
        (t::GL_CLAMP, [0, 0, 0, 0, 0, 1, 2, 3]),
    ];
    for (wrap, expect) in cases {
        let mut c = context(8, 1);
        setup_2d(&mut c, 4, 1, t::GL_NEAREST);
        param(&mut c, t::GL_TEXTURE_WRAP_S, wrap);
        quad(&mut c, -1.0, 0.0, 1.0, 1.0);
        for x in 0..8 {
            assert_eq!(px(&c, x, 0)[0], 16 * expect[x], "wrap {wrap:#x} pixel {x}");
        }
    }
    // CLAMP_TO_BORDER: outside [0, 1] the border colour.
    let mut c = context(8, 1);
    setup_2d(&mut c, 4, 1, t::GL_NEAREST);
    param(&mut c, t::GL_TEXTURE_WRAP_S, t::GL_CLAMP_TO_BORDER);
    c.execute(&Command::TexParameter(t::GL_TEXTURE_2D, t::GL_TEXTURE_BORDER_COLOR, [1.0, 0.0, 1.0, 1.0]));
    quad(&mut c, -1.0, 0.0, 1.0, 1.0);
    for x in 0..4 {
        assert_eq!(px(&c, x, 0), [255, 0, 255, 255], "border pixel {x}");
    }
    assert_eq!(px(&c, 5, 0)[0], 16);
}

#[test]
fn bilinear_weights() {
    // 2x1 texture stretched over 8 pixels, LINEAR, CLAMP_TO_EDGE: pixel x
    // has u = (x + 0.5) / 4, so between the texel centres 0.5 and 1.5 the
    // weight of texel 1 is u - 0.5.
    let mut c = context(8, 1);
    let data = [0u8, 0, 0, 255, 160, 0, 0, 255];
    tex_image_2d(&mut c, 0, t::GL_RGBA8, 2, 1, 0, &data);
    param(&mut c, t::GL_TEXTURE_MIN_FILTER, t::GL_LINEAR);
    param(&mut c, t::GL_TEXTURE_WRAP_S, t::GL_CLAMP_TO_EDGE);
    c.execute(&Command::Enable(t::GL_TEXTURE_2D));
    c.execute(&Command::TexEnv(t::GL_TEXTURE_ENV, t::GL_TEXTURE_ENV_MODE, [t::GL_REPLACE as f32, 0.0, 0.0, 0.0]));
    quad(&mut c, 0.0, 0.0, 1.0, 1.0);
    for x in 0..8 {
        let u = (x as f32 + 0.5) / 4.0;
        let w = (u - 0.5).clamp(0.0, 1.0);
        let e = (160.0 * w).round() as i32;
        assert!((px(&c, x, 0)[0] as i32 - e).abs() <= 1, "pixel {x}: {} vs {e}", px(&c, x, 0)[0]);
    }
}

/// Mipmap levels of distinct colours; level l is (8 - l*... ) grey.
fn mip_chain(c: &mut Context, size: i32) -> Vec<u8> {
    let mut colors = Vec::new();
    let (mut s, mut l) = (size, 0);
    while s >= 1 {
        let v = (40 * l) as u8;
        colors.push(v);
        let data: Vec<u8> = (0..s * s).flat_map(|_| [v, 255 - v, 0, 255]).collect();
        tex_image_2d(c, l, t::GL_RGBA, s, s, 0, &data);
        s /= 2;
        l += 1;
    }
    colors
}

#[test]
fn mipmap_level_selection() {
    // A 64x64 texture on 16x16 pixels: rho = 4, lambda = 2.
    let mut c = context(16, 16);
    let colors = mip_chain(&mut c, 64);
    param(&mut c, t::GL_TEXTURE_MIN_FILTER, t::GL_NEAREST_MIPMAP_NEAREST);
    c.execute(&Command::Enable(t::GL_TEXTURE_2D));
    c.execute(&Command::TexEnv(t::GL_TEXTURE_ENV, t::GL_TEXTURE_ENV_MODE, [t::GL_REPLACE as f32, 0.0, 0.0, 0.0]));
    quad(&mut c, 0.0, 0.0, 1.0, 1.0);
    assert_eq!(px(&c, 5, 7)[0], colors[2]);
    // Over 4 repeats: rho = 16, lambda = 4.
    quad(&mut c, 0.0, 0.0, 4.0, 4.0);
    assert_eq!(px(&c, 5, 7)[0], colors[4]);
    // LINEAR_MIPMAP_LINEAR at rho = 4 * 1.5 = 6 (lambda = log2 6 = 2.585):
    // levels 2 and 3 blended 0.415 / 0.585.
    param(&mut c, t::GL_TEXTURE_MIN_FILTER, t::GL_LINEAR_MIPMAP_LINEAR);
    quad(&mut c, 0.0, 0.0, 1.5, 1.5);
    let f = 6f32.log2().fract();
    let e = colors[2] as f32 * (1.0 - f) + colors[3] as f32 * f;
    assert!((px(&c, 5, 7)[0] as f32 - e).abs() <= 1.0, "{} vs {e}", px(&c, 5, 7)[0]);
    // Base level 1 and LOD bias.
    c.execute(&Command::TexParameter(t::GL_TEXTURE_2D, t::GL_TEXTURE_BASE_LEVEL, [1.0, 0.0, 0.0, 0.0]));
    param(&mut c, t::GL_TEXTURE_MIN_FILTER, t::GL_NEAREST_MIPMAP_NEAREST);
    quad(&mut c, 0.0, 0.0, 1.0, 1.0);
    // Base level 32x32 on 16 pixels: lambda = 1, level 1 + 1 = 2.
    assert_eq!(px(&c, 5, 7)[0], colors[2]);
}

#[test]
fn completeness_disables_the_unit() {
    let mut c = context(4, 4);
    c.execute(&Command::Color([0.0, 1.0, 0.0, 1.0]));
    // Only level 0 with the default NEAREST_MIPMAP_LINEAR filter: incomplete.
    tex_image_2d(&mut c, 0, t::GL_RGBA, 4, 4, 0, &[255u8; 64]);
    c.execute(&Command::Enable(t::GL_TEXTURE_2D));
    c.execute(&Command::TexEnv(t::GL_TEXTURE_ENV, t::GL_TEXTURE_ENV_MODE, [t::GL_REPLACE as f32, 0.0, 0.0, 0.0]));
    quad(&mut c, 0.0, 0.0, 1.0, 1.0);
    assert_eq!(px(&c, 1, 1), [0, 255, 0, 255], "incomplete texture: untextured");
    // With NEAREST it is complete.
    param(&mut c, t::GL_TEXTURE_MIN_FILTER, t::GL_NEAREST);
    quad(&mut c, 0.0, 0.0, 1.0, 1.0);
    assert_eq!(px(&c, 1, 1), [255; 4]);
    // A mipmap chain with a wrongly sized level is incomplete.
    param(&mut c, t::GL_TEXTURE_MIN_FILTER, t::GL_LINEAR_MIPMAP_LINEAR);
    tex_image_2d(&mut c, 1, t::GL_RGBA, 2, 2, 0, &[255u8; 16]);
    tex_image_2d(&mut c, 2, t::GL_RGBA, 2, 2, 0, &[255u8; 16]);
    quad(&mut c, 0.0, 0.0, 1.0, 1.0);
    assert_eq!(px(&c, 1, 1), [0, 255, 0, 255]);
    tex_image_2d(&mut c, 2, t::GL_RGBA, 1, 1, 0, &[255u8; 4]);
    quad(&mut c, 0.0, 0.0, 1.0, 1.0);
    assert_eq!(px(&c, 1, 1), [255; 4]);
    // Different internal formats across levels: incomplete.
    tex_image_2d(&mut c, 1, t::GL_RGB, 2, 2, 0, &[255u8; 16]);
    quad(&mut c, 0.0, 0.0, 1.0, 1.0);
    assert_eq!(px(&c, 1, 1), [0, 255, 0, 255]);
}

#[test]
fn tex_image_errors() {
    let mut c = context(4, 4);
    let e = |c: &mut Context, target: u32, level: i32, ifmt: i32, w: i32, h: i32, border: i32, format: u32, ty: u32| {
        if let Some(cmd) = unsafe { c.tex_image_command(2, target, level, ifmt, [w, h, 1], border, format, ty, std::ptr::null()) } {
            c.execute(&cmd);
        }
        c.take_error()
    };
    assert_eq!(e(&mut c, t::GL_TEXTURE_2D, 0, 4, 4, 4, 0, t::GL_RGBA, t::GL_UNSIGNED_BYTE), GL_NO_ERROR);
    assert_eq!(e(&mut c, t::GL_TEXTURE_1D, 0, 4, 4, 4, 0, t::GL_RGBA, t::GL_UNSIGNED_BYTE), GL_INVALID_ENUM);
    // ARB_texture_non_power_of_two: any size.
    assert_eq!(e(&mut c, t::GL_TEXTURE_2D, 0, 4, 3, 4, 0, t::GL_RGBA, t::GL_UNSIGNED_BYTE), GL_NO_ERROR, "non-power-of-two");
    assert_eq!(e(&mut c, t::GL_TEXTURE_2D, 0, 4, -1, 4, 0, t::GL_RGBA, t::GL_UNSIGNED_BYTE), GL_INVALID_VALUE);
    assert_eq!(e(&mut c, t::GL_TEXTURE_2D, -1, 4, 4, 4, 0, t::GL_RGBA, t::GL_UNSIGNED_BYTE), GL_INVALID_VALUE, "negative level");
    assert_eq!(e(&mut c, t::GL_TEXTURE_2D, 20, 4, 4, 4, 0, t::GL_RGBA, t::GL_UNSIGNED_BYTE), GL_INVALID_VALUE, "level too big");
    assert_eq!(e(&mut c, t::GL_TEXTURE_2D, 0, 4, 4, 4, 2, t::GL_RGBA, t::GL_UNSIGNED_BYTE), GL_INVALID_VALUE, "border 2");
    assert_eq!(e(&mut c, t::GL_TEXTURE_2D, 0, 4, 6, 6, 1, t::GL_RGBA, t::GL_UNSIGNED_BYTE), GL_NO_ERROR, "4 + 2 border");
    assert_eq!(e(&mut c, t::GL_TEXTURE_2D, 0, 4, 5, 5, 1, t::GL_RGBA, t::GL_UNSIGNED_BYTE), GL_NO_ERROR, "5 with border 1");
    assert_eq!(e(&mut c, t::GL_TEXTURE_2D, 0, 4, 1, 1, 1, t::GL_RGBA, t::GL_UNSIGNED_BYTE), GL_INVALID_VALUE, "1 with border 1");
    // Level k holds at most MAX_TEXTURE_SIZE >> k (section 3.8.1).
    assert_eq!(e(&mut c, t::GL_TEXTURE_2D, 0, 4, 4096, 1, 0, t::GL_RGBA, t::GL_UNSIGNED_BYTE), GL_NO_ERROR, "max x 1");
    assert_eq!(e(&mut c, t::GL_TEXTURE_2D, 1, 4, 4096, 1, 0, t::GL_RGBA, t::GL_UNSIGNED_BYTE), GL_INVALID_VALUE, "max at level 1");
    assert_eq!(e(&mut c, t::GL_TEXTURE_2D, 2, 4, 1, 2048, 0, t::GL_RGBA, t::GL_UNSIGNED_BYTE), GL_INVALID_VALUE, "max/2 at level 2");
    assert_eq!(e(&mut c, t::GL_TEXTURE_2D, 0, 4, 8192, 4, 0, t::GL_RGBA, t::GL_UNSIGNED_BYTE), GL_INVALID_VALUE, "too wide");
    assert_eq!(e(&mut c, t::GL_TEXTURE_2D, 0, 5, 4, 4, 0, t::GL_RGBA, t::GL_UNSIGNED_BYTE), GL_INVALID_VALUE, "internal format 5");
    assert_eq!(e(&mut c, t::GL_TEXTURE_2D, 0, 4, 4, 4, 0, 0x1234, t::GL_UNSIGNED_BYTE), GL_INVALID_ENUM, "format");
    assert_eq!(e(&mut c, t::GL_TEXTURE_2D, 0, 4, 4, 4, 0, t::GL_RGBA, 0x1234), GL_INVALID_ENUM, "type");
    assert_eq!(e(&mut c, t::GL_TEXTURE_2D, 0, 4, 4, 4, 0, t::GL_RGBA, t::GL_UNSIGNED_SHORT_5_6_5), GL_INVALID_OPERATION, "packed mismatch");
    assert_eq!(e(&mut c, t::GL_TEXTURE_2D, 0, 4, 4, 4, 0, t::GL_DEPTH_COMPONENT, t::GL_FLOAT), GL_INVALID_OPERATION, "depth format, colour texture");
    assert_eq!(e(&mut c, t::GL_TEXTURE_CUBE_MAP_POSITIVE_X, 0, 4, 4, 2, 0, t::GL_RGBA, t::GL_UNSIGNED_BYTE), GL_INVALID_VALUE, "non-square cube face");
    // Proxies: no error, the proxy's width says whether it fits.
    assert_eq!(e(&mut c, t::GL_PROXY_TEXTURE_2D, 0, 4, 64, 64, 0, t::GL_RGBA, t::GL_UNSIGNED_BYTE), GL_NO_ERROR);
    let w = c.get_tex_level_parameter(t::GL_PROXY_TEXTURE_2D, 0, t::GL_TEXTURE_WIDTH).unwrap().as_i32();
    assert_eq!(w, vec![64]);
    // Errors leave the proxy alone; a size softgl cannot hold zeroes it.
    assert_eq!(e(&mut c, t::GL_PROXY_TEXTURE_2D, 0, 4, 64, 64, 2, t::GL_RGBA, t::GL_UNSIGNED_BYTE), GL_INVALID_VALUE);
    assert_eq!(c.get_tex_level_parameter(t::GL_PROXY_TEXTURE_2D, 0, t::GL_TEXTURE_WIDTH).unwrap().as_i32(), vec![64]);
    assert_eq!(e(&mut c, t::GL_PROXY_TEXTURE_2D, 0, 4, 8192, 8192, 0, t::GL_RGBA, t::GL_UNSIGNED_BYTE), GL_NO_ERROR);
    for pname in [t::GL_TEXTURE_WIDTH, t::GL_TEXTURE_HEIGHT] {
        assert_eq!(c.get_tex_level_parameter(t::GL_PROXY_TEXTURE_2D, 0, pname).unwrap().as_i32(), vec![0]);
    }
    assert_eq!(e(&mut c, t::GL_PROXY_TEXTURE_3D, 0, 4, 512, 512, 512, t::GL_RGBA, t::GL_UNSIGNED_BYTE), GL_INVALID_ENUM, "3D proxy via 2D call");
    // Depth internal format with stencil or colour data: INVALID_OPERATION.
    assert_eq!(e(&mut c, t::GL_TEXTURE_2D, 0, t::GL_DEPTH_COMPONENT16 as i32, 4, 4, 0, t::GL_STENCIL_INDEX, t::GL_INT), GL_INVALID_OPERATION);
    assert_eq!(e(&mut c, t::GL_TEXTURE_2D, 0, 4, 4, 4, 0, t::GL_STENCIL_INDEX, t::GL_INT), GL_INVALID_ENUM);
    // Sub-image outside the image, and of an undefined level.
    let sub = |c: &mut Context, level: i32, x: i32, w: i32| {
        let cmd = unsafe { c.tex_sub_image_command(2, t::GL_TEXTURE_2D, level, [x, 0, 0], [w, 1, 1], t::GL_RGBA, t::GL_UNSIGNED_BYTE, std::ptr::null()) };
        c.execute(&cmd);
        c.take_error()
    };
    e(&mut c, t::GL_TEXTURE_2D, 0, 4, 4, 4, 0, t::GL_RGBA, t::GL_UNSIGNED_BYTE);
    assert_eq!(sub(&mut c, 0, 2, 2), GL_NO_ERROR);
    assert_eq!(sub(&mut c, 0, 3, 2), GL_INVALID_VALUE);
    assert_eq!(sub(&mut c, 3, 0, 1), GL_INVALID_OPERATION);
}

/// Draws one pixel with primary colour `cf`, a 1x1 texture `ct` of the given
/// internal format and the env mode, returns the pixel.
fn env_pixel(ifmt: u32, ct: [u8; 4], cf: [f32; 4], mode: u32, env_color: [f32; 4]) -> [u8; 4] {
    let mut c = context(1, 1);
    tex_image_2d(&mut c, 0, ifmt, 1, 1, 0, &ct);
    param(&mut c, t::GL_TEXTURE_MIN_FILTER, t::GL_NEAREST);
    c.execute(&Command::Enable(t::GL_TEXTURE_2D));
    c.execute(&Command::TexEnv(t::GL_TEXTURE_ENV, t::GL_TEXTURE_ENV_MODE, [mode as f32, 0.0, 0.0, 0.0]));
    c.execute(&Command::TexEnv(t::GL_TEXTURE_ENV, t::GL_TEXTURE_ENV_COLOR, env_color));
    c.execute(&Command::Color(cf));
    quad(&mut c, 0.0, 0.0, 1.0, 1.0);
    px(&c, 0, 0)
}

fn u8c(v: f32) -> i32 {
    (v.clamp(0.0, 1.0) * 255.0).round() as i32
}

#[test]
fn env_modes_against_formulas() {
    let cf = [0.4, 0.6, 0.8, 0.5];
    let ct = [51u8, 102, 204, 153]; // 0.2, 0.4, 0.8, 0.6
    let t_ = [0.2f32, 0.4, 0.8, 0.6];
    let cc = [0.9, 0.1, 0.5, 0.3];
    let close = |got: [u8; 4], want: [f32; 4], what: &str| {
        for k in 0..4 {
            assert!((got[k] as i32 - u8c(want[k])).abs() <= 1, "{what}: channel {k}: {got:?} vs {want:?}");
        }
    };
    close(env_pixel(t::GL_RGBA, ct, cf, t::GL_REPLACE, cc), t_, "RGBA REPLACE");
    close(env_pixel(t::GL_RGBA, ct, cf, t::GL_MODULATE, cc), std::array::from_fn(|k| cf[k] * t_[k]), "RGBA MODULATE");
    close(
        env_pixel(t::GL_RGBA, ct, cf, t::GL_DECAL, cc),
        [0, 1, 2, 3].map(|k| if k < 3 { cf[k] * (1.0 - t_[3]) + t_[k] * t_[3] } else { cf[3] }),
        "RGBA DECAL",
    );
    close(
        env_pixel(t::GL_RGBA, ct, cf, t::GL_BLEND, cc),
        [0, 1, 2, 3].map(|k| if k < 3 { cf[k] * (1.0 - t_[k]) + cc[k] * t_[k] } else { cf[3] * t_[3] }),
        "RGBA BLEND",
    );
    close(env_pixel(t::GL_RGBA, ct, cf, t::GL_ADD, cc), [0, 1, 2, 3].map(|k| if k < 3 { cf[k] + t_[k] } else { cf[3] * t_[3] }), "RGBA ADD");
    close(env_pixel(t::GL_RGB, ct, cf, t::GL_REPLACE, cc), [t_[0], t_[1], t_[2], cf[3]], "RGB REPLACE");
    // LUMINANCE takes R as L; ALPHA takes A; INTENSITY takes R for all.
    close(env_pixel(t::GL_LUMINANCE, ct, cf, t::GL_MODULATE, cc), [cf[0] * 0.2, cf[1] * 0.2, cf[2] * 0.2, cf[3]], "L MODULATE");
    close(env_pixel(t::GL_ALPHA, ct, cf, t::GL_REPLACE, cc), [cf[0], cf[1], cf[2], 0.6], "A REPLACE");
    close(
        env_pixel(t::GL_INTENSITY, ct, cf, t::GL_BLEND, cc),
        [0, 1, 2, 3].map(|k| cf[k] * (1.0 - 0.2) + cc[k] * 0.2),
        "I BLEND",
    );
    close(env_pixel(t::GL_INTENSITY, ct, cf, t::GL_ADD, cc), [0, 1, 2, 3].map(|k| cf[k] + 0.2), "I ADD");
    close(env_pixel(t::GL_LUMINANCE_ALPHA, ct, cf, t::GL_REPLACE, cc), [0.2, 0.2, 0.2, 0.6], "LA REPLACE");
}

#[test]
fn combine_functions() {
    let mut c = context(1, 1);
    tex_image_2d(&mut c, 0, t::GL_RGBA, 1, 1, 0, &[51, 102, 204, 153]);
    param(&mut c, t::GL_TEXTURE_MIN_FILTER, t::GL_NEAREST);
    c.execute(&Command::Enable(t::GL_TEXTURE_2D));
    let env = |c: &mut Context, p: u32, v: u32| c.execute(&Command::TexEnv(t::GL_TEXTURE_ENV, p, [v as f32, 0.0, 0.0, 0.0]));
    env(&mut c, t::GL_TEXTURE_ENV_MODE, t::GL_COMBINE);
    c.execute(&Command::Color([0.4, 0.6, 0.8, 0.5]));
    // SUBTRACT texture - primary, scale 2: (0.2-0.4, 0.4-0.6, 0.8-0.8) * 2 clamped.
    env(&mut c, t::GL_COMBINE_RGB, t::GL_SUBTRACT);
    env(&mut c, t::GL_SOURCE1_RGB, t::GL_PRIMARY_COLOR);
    c.execute(&Command::TexEnv(t::GL_TEXTURE_ENV, t::GL_RGB_SCALE, [2.0, 0.0, 0.0, 0.0]));
    env(&mut c, t::GL_COMBINE_ALPHA, t::GL_ADD);
    env(&mut c, t::GL_SOURCE1_ALPHA, t::GL_PRIMARY_COLOR);
    quad(&mut c, 0.0, 0.0, 1.0, 1.0);
    assert_eq!(c.take_error(), GL_NO_ERROR);
    assert_eq!(px(&c, 0, 0), [0, 0, 0, 255]);
    // DOT3_RGBA of texture and constant (0.5 + 0.25 per channel...).
    c.execute(&Command::TexEnv(t::GL_TEXTURE_ENV, t::GL_RGB_SCALE, [1.0, 0.0, 0.0, 0.0]));
    env(&mut c, t::GL_COMBINE_RGB, t::GL_DOT3_RGBA);
    env(&mut c, t::GL_SOURCE1_RGB, t::GL_CONSTANT);
    c.execute(&Command::TexEnv(t::GL_TEXTURE_ENV, t::GL_TEXTURE_ENV_COLOR, [1.0, 1.0, 1.0, 1.0]));
    quad(&mut c, 0.0, 0.0, 1.0, 1.0);
    let d = 4.0 * ((0.2f32 - 0.5) * 0.5 + (0.4 - 0.5) * 0.5 + (0.8 - 0.5) * 0.5);
    let e = u8c(d) as u8;
    assert!(px(&c, 0, 0).iter().all(|&v| (v as i32 - e as i32).abs() <= 1), "{:?} vs {e}", px(&c, 0, 0));
    // INTERPOLATE texture and primary by the constant's alpha.
    env(&mut c, t::GL_COMBINE_RGB, t::GL_INTERPOLATE);
    env(&mut c, t::GL_SOURCE1_RGB, t::GL_PRIMARY_COLOR);
    env(&mut c, t::GL_SOURCE2_RGB, t::GL_CONSTANT);
    env(&mut c, t::GL_OPERAND2_RGB, t::GL_SRC_ALPHA);
    c.execute(&Command::TexEnv(t::GL_TEXTURE_ENV, t::GL_TEXTURE_ENV_COLOR, [0.0, 0.0, 0.0, 0.25]));
    quad(&mut c, 0.0, 0.0, 1.0, 1.0);
    let want = [0.2 * 0.25 + 0.4 * 0.75, 0.4 * 0.25 + 0.6 * 0.75, 0.8 * 0.25 + 0.8 * 0.75];
    for k in 0..3 {
        assert!((px(&c, 0, 0)[k] as i32 - u8c(want[k])).abs() <= 1);
    }
    // Errors.
    c.execute(&Command::TexEnv(t::GL_TEXTURE_ENV, t::GL_RGB_SCALE, [3.0, 0.0, 0.0, 0.0]));
    assert_eq!(c.take_error(), GL_INVALID_VALUE);
    env(&mut c, t::GL_OPERAND0_ALPHA, t::GL_SRC_COLOR);
    assert_eq!(c.take_error(), GL_INVALID_ENUM);
}

#[test]
fn multitexture_modulates_two_units() {
    let mut c = context(1, 1);
    tex_image_2d(&mut c, 0, t::GL_RGBA, 1, 1, 0, &[255, 128, 0, 255]);
    param(&mut c, t::GL_TEXTURE_MIN_FILTER, t::GL_NEAREST);
    c.execute(&Command::Enable(t::GL_TEXTURE_2D));
    c.execute(&Command::ActiveTexture(t::GL_TEXTURE0 + 1));
    c.execute(&Command::BindTexture(t::GL_TEXTURE_2D, 7));
    tex_image_2d(&mut c, 0, t::GL_RGBA, 1, 1, 0, &[128, 255, 255, 255]);
    param(&mut c, t::GL_TEXTURE_MIN_FILTER, t::GL_NEAREST);
    c.execute(&Command::Enable(t::GL_TEXTURE_2D));
    quad(&mut c, 0.0, 0.0, 1.0, 1.0);
    let p = px(&c, 0, 0);
    assert!((p[0] as i32 - 128).abs() <= 1 && (p[1] as i32 - 128).abs() <= 1 && p[2] == 0, "{p:?}");
    assert!(c.is_texture(7));
    c.execute(&Command::BindTexture(t::GL_TEXTURE_1D, 7));
    assert_eq!(c.take_error(), GL_INVALID_OPERATION, "rebinding to another target");
}

#[test]
fn texgen_object_and_eye_linear() {
    let mut c = context(8, 1);
    setup_2d(&mut c, 4, 1, t::GL_NEAREST);
    // s = (x + 1) / 2 in object coordinates.
    c.execute(&Command::TexGen(t::GL_S, t::GL_TEXTURE_GEN_MODE, [t::GL_OBJECT_LINEAR as f64, 0.0, 0.0, 0.0]));
    c.execute(&Command::TexGen(t::GL_S, t::GL_OBJECT_PLANE, [0.5, 0.0, 0.0, 0.5]));
    c.execute(&Command::Enable(t::GL_TEXTURE_GEN_S));
    quad(&mut c, 9.0, 0.0, 9.0, 1.0);
    for x in 0..8 {
        assert_eq!(px(&c, x, 0)[0], 16 * (x as u8 / 2), "object linear pixel {x}");
    }
    // Eye plane given under a modelview that scales x by 2: the plane is
    // transformed by its inverse, so with the identity modelview at draw
    // time s = 0.25 x + 0.5.
    c.execute(&Command::Scale([2.0, 1.0, 1.0]));
    c.execute(&Command::TexGen(t::GL_S, t::GL_TEXTURE_GEN_MODE, [t::GL_EYE_LINEAR as f64, 0.0, 0.0, 0.0]));
    c.execute(&Command::TexGen(t::GL_S, t::GL_EYE_PLANE, [0.5, 0.0, 0.0, 0.5]));
    c.execute(&Command::LoadIdentity);
    quad(&mut c, 9.0, 0.0, 9.0, 1.0);
    for x in 0..8 {
        let s = 0.25 * ((x as f32 + 0.5) / 4.0 - 1.0) + 0.5;
        assert_eq!(px(&c, x, 0)[0], 16 * (s * 4.0).floor() as u8, "eye linear pixel {x}");
    }
}

#[test]
fn texture_matrix_per_unit() {
    let mut c = context(8, 1);
    setup_2d(&mut c, 4, 1, t::GL_NEAREST);
    c.execute(&Command::MatrixMode(GL_TEXTURE));
    c.execute(&Command::Translate([0.25, 0.0, 0.0]));
    c.execute(&Command::MatrixMode(GL_MODELVIEW));
    quad(&mut c, 0.0, 0.0, 1.0, 1.0);
    for x in 0..8 {
        assert_eq!(px(&c, x, 0)[0], 16 * ((x as u8 / 2 + 1) % 4), "pixel {x}");
    }
    // Unit 1's matrix is separate.
    c.execute(&Command::ActiveTexture(t::GL_TEXTURE0 + 1));
    assert_eq!(c.get(GL_TEXTURE_MATRIX).unwrap().as_f64()[12], 0.0);
    c.execute(&Command::ActiveTexture(t::GL_TEXTURE0));
    assert_eq!(c.get(GL_TEXTURE_MATRIX).unwrap().as_f64()[12], 0.25);
}

#[test]
fn perspective_correct_coordinates() {
    // A quad receding in depth: with w varying, s at the pixel where the
    // projected midpoint lands must be 1/2, not the screen-space midpoint.
    let mut c = context(16, 1);
    setup_2d(&mut c, 16, 1, t::GL_NEAREST);
    c.execute(&Command::Begin(GL_QUADS));
    for (x, y, w, s) in [(-1.0f32, -1.0f32, 1.0f32, 0.0f32), (1.0, -1.0, 3.0, 1.0), (1.0, 1.0, 3.0, 1.0), (-1.0, 1.0, 1.0, 0.0)] {
        c.execute(&Command::TexCoord(t::GL_TEXTURE0, [s, 0.0, 0.0, 1.0]));
        c.execute(&Command::Vertex([x * w, y * w, 0.0, w]));
    }
    c.execute(&Command::End);
    // Along the quad, clip x = -1 + 4t and w = 1 + 2t for s = t, so the
    // pixel at x_ndc has t = (x_ndc + 1) / (4 - 2 x_ndc).
    for x in 0..16 {
        let xn = (x as f64 + 0.5) / 8.0 - 1.0;
        let t = (xn + 1.0) / (4.0 - 2.0 * xn);
        let texel = (t * 16.0).floor() as u8;
        assert_eq!(px(&c, x, 0)[0], 16u8.wrapping_mul(texel), "pixel {x}");
    }
}

/// glTexImage of any dimensionality from RGBA floats.
fn tex_image_f(c: &mut Context, dims: u8, target: u32, ifmt: u32, size: [i32; 3], format: u32, data: &[f32]) {
    let cmd = unsafe { c.tex_image_command(dims, target, 0, ifmt as i32, size, 0, format, t::GL_FLOAT, data.as_ptr() as *const u8) };
    if let Some(cmd) = cmd {
        c.execute(&cmd);
    }
}

fn nearest(c: &mut Context, target: u32) {
    c.execute(&Command::TexParameter(target, t::GL_TEXTURE_MIN_FILTER, [t::GL_NEAREST as f32, 0.0, 0.0, 0.0]));
    c.execute(&Command::TexParameter(target, t::GL_TEXTURE_MAG_FILTER, [t::GL_NEAREST as f32, 0.0, 0.0, 0.0]));
    c.execute(&Command::TexEnv(t::GL_TEXTURE_ENV, t::GL_TEXTURE_ENV_MODE, [t::GL_REPLACE as f32, 0.0, 0.0, 0.0]));
}

/// One pixel drawn with texture coordinates `str`.
fn one_pixel(c: &mut Context, str: [f32; 4]) -> [u8; 4] {
    c.execute(&Command::TexCoord(t::GL_TEXTURE0, str));
    quad_same(c);
    px(c, 0, 0)
}

fn quad_same(c: &mut Context) {
    c.execute(&Command::Begin(GL_QUADS));
    for (x, y) in [(-1.0, -1.0), (1.0, -1.0), (1.0, 1.0), (-1.0, 1.0)] {
        c.execute(&Command::Vertex([x, y, 0.0, 1.0]));
    }
    c.execute(&Command::End);
}

#[test]
fn cube_map_faces() {
    let mut c = context(1, 1);
    for f in 0..6u32 {
        let v = [f as f32 / 8.0, 0.0, 0.0, 1.0];
        let data: Vec<f32> = (0..4).flat_map(|_| v).collect();
        tex_image_f(&mut c, 2, t::GL_TEXTURE_CUBE_MAP_POSITIVE_X + f, t::GL_RGBA, [2, 2, 1], t::GL_RGBA, &data);
    }
    nearest(&mut c, t::GL_TEXTURE_CUBE_MAP);
    c.execute(&Command::Enable(t::GL_TEXTURE_CUBE_MAP));
    assert_eq!(c.take_error(), GL_NO_ERROR);
    let dirs = [[1.0, 0.1, 0.2], [-1.0, 0.1, 0.2], [0.1, 1.0, 0.2], [0.1, -1.0, 0.2], [0.1, 0.2, 1.0], [0.1, 0.2, -1.0]];
    for (f, d) in dirs.iter().enumerate() {
        let p = one_pixel(&mut c, [d[0], d[1], d[2], 1.0]);
        assert_eq!(p[0] as i32, (f as f32 / 8.0 * 255.0).round() as i32, "face {f}");
    }
}

#[test]
fn texture_3d_trilinear() {
    let mut c = context(1, 1);
    // 2x2x2: the red channel is the slice index / 2.
    let data: Vec<f32> = (0..8).flat_map(|i| [if i >= 4 { 0.5 } else { 0.0 }, 0.0, 0.0, 1.0]).collect();
    tex_image_f(&mut c, 3, t::GL_TEXTURE_3D, t::GL_RGBA16, [2, 2, 2], t::GL_RGBA, &data);
    nearest(&mut c, t::GL_TEXTURE_3D);
    c.execute(&Command::TexParameter(t::GL_TEXTURE_3D, t::GL_TEXTURE_MAG_FILTER, [t::GL_LINEAR as f32, 0.0, 0.0, 0.0]));
    c.execute(&Command::TexParameter(t::GL_TEXTURE_3D, t::GL_TEXTURE_WRAP_R, [t::GL_CLAMP_TO_EDGE as f32, 0.0, 0.0, 0.0]));
    c.execute(&Command::Enable(t::GL_TEXTURE_3D));
    assert_eq!(one_pixel(&mut c, [0.5, 0.5, 0.5, 1.0])[0], 64);
    assert_eq!(one_pixel(&mut c, [0.5, 0.5, 0.75, 1.0])[0], 128);
    assert_eq!(one_pixel(&mut c, [0.5, 0.5, 0.0, 1.0])[0], 0);
    // The q coordinate divides r too.
    assert_eq!(one_pixel(&mut c, [1.0, 1.0, 1.5, 2.0])[0], 128);
}

#[test]
fn depth_texture_compare() {
    let mut c = context(1, 1);
    let depth = [0.25f32, 0.75];
    let cmd = unsafe { c.tex_image_command(2, t::GL_TEXTURE_2D, 0, t::GL_DEPTH_COMPONENT24 as i32, [2, 1, 1], 0, t::GL_DEPTH_COMPONENT, t::GL_FLOAT, depth.as_ptr() as *const u8) };
    c.execute(&cmd.unwrap());
    nearest(&mut c, t::GL_TEXTURE_2D);
    c.execute(&Command::Enable(t::GL_TEXTURE_2D));
    assert_eq!(c.take_error(), GL_NO_ERROR);
    // No comparison: luminance = depth.
    assert_eq!(one_pixel(&mut c, [0.25, 0.5, 0.5, 1.0])[..3], [64, 64, 64]);
    c.execute(&Command::TexParameter(t::GL_TEXTURE_2D, t::GL_TEXTURE_COMPARE_MODE, [t::GL_COMPARE_R_TO_TEXTURE as f32, 0.0, 0.0, 0.0]));
    // LEQUAL: r = 0.5 <= 0.25 fails at texel 0, passes at texel 1.
    assert_eq!(one_pixel(&mut c, [0.25, 0.5, 0.5, 1.0])[0], 0);
    assert_eq!(one_pixel(&mut c, [0.75, 0.5, 0.5, 1.0])[0], 255);
    c.execute(&Command::TexParameter(t::GL_TEXTURE_2D, t::GL_TEXTURE_COMPARE_FUNC, [GL_GEQUAL as f32, 0.0, 0.0, 0.0]));
    assert_eq!(one_pixel(&mut c, [0.25, 0.5, 0.5, 1.0])[0], 255);
    // DEPTH_TEXTURE_MODE ALPHA with REPLACE: colour from the fragment.
    c.execute(&Command::TexParameter(t::GL_TEXTURE_2D, t::GL_DEPTH_TEXTURE_MODE, [t::GL_ALPHA as f32, 0.0, 0.0, 0.0]));
    c.execute(&Command::Color([0.0, 1.0, 0.0, 1.0]));
    assert_eq!(one_pixel(&mut c, [0.75, 0.5, 0.5, 1.0]), [0, 255, 0, 0]);
}

#[test]
fn copy_tex_image_and_get_tex_image() {
    let mut c = context(4, 4);
    c.execute(&Command::ClearColor([1.0, 0.5, 0.0, 1.0]));
    c.execute(&Command::Clear(GL_COLOR_BUFFER_BIT));
    c.execute(&Command::CopyTex(Box::new(softgl::gl::texture::CopyTexCmd {
        dims: 2,
        sub: false,
        target: t::GL_TEXTURE_2D,
        level: 0,
        internal_format: t::GL_RGBA8,
        offset: [0; 3],
        rect: [2, 2, 4, 4],
        border: 0,
    })));
    assert_eq!(c.take_error(), GL_NO_ERROR);
    let mut out = [0u8; 4 * 16];
    unsafe { c.get_tex_image(t::GL_TEXTURE_2D, 0, t::GL_RGBA, t::GL_UNSIGNED_BYTE, out.as_mut_ptr()) };
    assert_eq!(out[..4], [255, 128, 0, 255], "inside the window");
    assert_eq!(out[4 * 2..4 * 3], [0, 0, 0, 0], "outside the window reads zero");
    // Packed readback: 5_6_5 of (1, 0.5, 0).
    let mut p = [0u16; 16];
    unsafe { c.get_tex_image(t::GL_TEXTURE_2D, 0, t::GL_RGB, t::GL_UNSIGNED_SHORT_5_6_5, p.as_mut_ptr() as *mut u8) };
    assert_eq!(p[0], (31 << 11) | (32 << 5));
}

#[test]
fn generate_mipmap_and_level_queries() {
    let mut c = context(1, 1);
    c.execute(&Command::TexParameter(t::GL_TEXTURE_2D, t::GL_GENERATE_MIPMAP, [1.0, 0.0, 0.0, 0.0]));
    let data: Vec<u8> = (0..16).flat_map(|i| if i % 2 == 0 { [255, 0, 0, 255] } else { [0, 0, 0, 255] }).collect();
    tex_image_2d(&mut c, 0, t::GL_RGBA, 4, 4, 0, &data);
    let w = |c: &mut Context, l| c.get_tex_level_parameter(t::GL_TEXTURE_2D, l, t::GL_TEXTURE_WIDTH).unwrap().as_i32()[0];
    assert_eq!((w(&mut c, 1), w(&mut c, 2), w(&mut c, 3)), (2, 1, 0));
    let mut out = [0u8; 4];
    unsafe { c.get_tex_image(t::GL_TEXTURE_2D, 2, t::GL_RGBA, t::GL_UNSIGNED_BYTE, out.as_mut_ptr()) };
    assert_eq!(out, [128, 0, 0, 255]);
    // The default min filter now has its mipmaps: complete.
    c.execute(&Command::Enable(t::GL_TEXTURE_2D));
    c.execute(&Command::TexEnv(t::GL_TEXTURE_ENV, t::GL_TEXTURE_ENV_MODE, [t::GL_REPLACE as f32, 0.0, 0.0, 0.0]));
    c.execute(&Command::Color([0.0, 1.0, 0.0, 1.0]));
    quad(&mut c, 0.0, 0.0, 1.0, 1.0);
    assert_eq!(px(&c, 0, 0), [128, 0, 0, 255], "1 pixel for 4 texels: level 2");
    let bits = c.get_tex_level_parameter(t::GL_TEXTURE_2D, 0, t::GL_TEXTURE_RED_SIZE).unwrap().as_i32()[0];
    assert_eq!(bits, 8);
}

#[test]
fn textured_lines_points_and_clipping() {
    let mut c = context(8, 8);
    setup_2d(&mut c, 8, 1, t::GL_NEAREST);
    // A horizontal line along row 3 from s = 0 to 1.
    c.execute(&Command::Begin(GL_LINES));
    c.execute(&Command::TexCoord(t::GL_TEXTURE0, [0.0, 0.0, 0.0, 1.0]));
    c.execute(&Command::Vertex([-1.0, -0.125, 0.0, 1.0]));
    c.execute(&Command::TexCoord(t::GL_TEXTURE0, [1.0, 0.0, 0.0, 1.0]));
    c.execute(&Command::Vertex([1.0, -0.125, 0.0, 1.0]));
    c.execute(&Command::End);
    for x in 0..7 {
        assert_eq!(px(&c, x, 3)[0], 16 * x as u8, "line pixel {x}");
    }
    // A point takes its vertex's coordinates.
    c.execute(&Command::Begin(GL_POINTS));
    c.execute(&Command::TexCoord(t::GL_TEXTURE0, [0.7, 0.0, 0.0, 1.0]));
    c.execute(&Command::Vertex([-0.875, 0.875, 0.0, 1.0]));
    c.execute(&Command::End);
    assert_eq!(px(&c, 0, 7)[0], 16 * 5);
    // A quad crossing the near plane (z from -2 to 0.5 as y goes from -1
    // to 1): clipped at y = -0.2, its coordinates still follow x.
    c.execute(&Command::Begin(GL_QUADS));
    for (x, z, s) in [(-1.0, -2.0, 0.0), (1.0, -2.0, 1.0), (1.0, 0.5, 1.0), (-1.0, 0.5, 0.0)] {
        c.execute(&Command::TexCoord(t::GL_TEXTURE0, [s, 0.0, 0.0, 1.0]));
        c.execute(&Command::Vertex([x, if z < 0.0 { -1.0 } else { 1.0 }, z, 1.0]));
    }
    c.execute(&Command::End);
    for x in 0..8 {
        assert_eq!(px(&c, x, 6)[0], 16 * x as u8, "clipped quad pixel {x}");
        assert_eq!(px(&c, x, 2), [0; 4], "row 2 lies below the near-plane cut at y = -0.2");
    }
}

#[test]
fn tex_image_in_display_list() {
    let mut c = context(8, 8);
    c.execute(&Command::ActiveTexture(t::GL_TEXTURE0));
    // Compile the image; change the client data; replay.
    let mut data = ramp(8, 8);
    c.new_list(1, GL_COMPILE);
    tex_image_2d(&mut c, 0, t::GL_RGBA8, 8, 8, 0, &data);
    c.end_list();
    data.iter_mut().for_each(|b| *b = 0);
    c.execute(&Command::CallList(1));
    param(&mut c, t::GL_TEXTURE_MIN_FILTER, t::GL_NEAREST);
    c.execute(&Command::Enable(t::GL_TEXTURE_2D));
    c.execute(&Command::TexEnv(t::GL_TEXTURE_ENV, t::GL_TEXTURE_ENV_MODE, [t::GL_REPLACE as f32, 0.0, 0.0, 0.0]));
    quad(&mut c, 0.0, 0.0, 1.0, 1.0);
    assert_eq!(px(&c, 3, 5)[..2], [48, 80]);
}
