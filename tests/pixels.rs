//! Pixel rectangles through the GL state machine: pack/unpack round trips
//! for every format and type under the storage modes, pixel transfer and
//! maps, zoom coverage against the spec's rule, glCopyPixels overlap, the
//! raster position (validity, latched colour, distance, glWindowPos) and
//! glBitmap (pixels, movement, clipping, display lists, LSB first).

use softgl::framebuffer::Config;
use softgl::gl::enums::*;
use softgl::gl::pixel_data::Layout;
use softgl::gl::{Command, Context};

const W: usize = 32;
const H: usize = 16;

fn context() -> Context {
    let mut c = Context::new(Config { alpha_bits: 8, depth_bits: 24, stencil_bits: 8, accum_bits: 0 });
    c.fb.resize(W, H).unwrap();
    c.surface_resized(W as i32, H as i32);
    c
}

mod common;
use common::Rng;

fn draw(c: &mut Context, w: i32, h: i32, format: u32, ty: u32, data: &[u8]) {
    let cmd = unsafe { c.build_draw_pixels(w, h, format, ty, data.as_ptr()) }.expect("a command");
    c.execute(&cmd);
}

/// glReadPixels into a buffer sized by the pack layout (plus slack),
/// pre-filled with `fill`.
fn read(c: &mut Context, x: i32, y: i32, w: i32, h: i32, format: u32, ty: u32, fill: u8) -> Vec<u8> {
    let l = Layout::new(&c.pixel_store.pack, w as usize, h as usize, format, ty);
    let mut buf = vec![fill; l.extent(w as usize, h as usize, 1) + 16];
    unsafe { c.read_pixels(x, y, w, h, format, ty, buf.as_mut_ptr()) };
    buf
}

fn window_pos(c: &mut Context, x: f32, y: f32) {
    c.execute(&Command::WindowPos([x, y, 0.0]));
}

fn set_modes(c: &mut Context, pack: bool, modes: &[(u32, f64)]) {
    for &(pname, v) in modes {
        // The unpack enums are the pack ones minus 0x10.
        c.pixel_store(if pack { pname } else { pname - 0x10 }, v);
    }
}

const COLOR_FORMATS: [u32; 10] = [GL_RED, GL_GREEN, GL_BLUE, GL_ALPHA, GL_RGB, GL_RGBA, GL_BGR, GL_BGRA, GL_LUMINANCE, GL_LUMINANCE_ALPHA];
const PLAIN_TYPES: [u32; 7] = [GL_UNSIGNED_BYTE, GL_BYTE, GL_UNSIGNED_SHORT, GL_SHORT, GL_UNSIGNED_INT, GL_INT, GL_FLOAT];
const PACKED3: [u32; 4] = [GL_UNSIGNED_BYTE_3_3_2, GL_UNSIGNED_BYTE_2_3_3_REV, GL_UNSIGNED_SHORT_5_6_5, GL_UNSIGNED_SHORT_5_6_5_REV];
const PACKED4: [u32; 8] = [
    GL_UNSIGNED_SHORT_4_4_4_4,
    GL_UNSIGNED_SHORT_4_4_4_4_REV,
    GL_UNSIGNED_SHORT_5_5_5_1,
    GL_UNSIGNED_SHORT_1_5_5_5_REV,
    GL_UNSIGNED_INT_8_8_8_8,
    GL_UNSIGNED_INT_8_8_8_8_REV,
    GL_UNSIGNED_INT_10_10_10_2,
    GL_UNSIGNED_INT_2_10_10_10_REV,
];

/// Pack (= unpack) storage modes the round trips run under.
fn mode_sets() -> Vec<Vec<(u32, f64)>> {
    vec![
        vec![],
        vec![(GL_PACK_ALIGNMENT, 1.0)],
        vec![(GL_PACK_ALIGNMENT, 8.0), (GL_PACK_ROW_LENGTH, 7.0), (GL_PACK_SKIP_PIXELS, 2.0), (GL_PACK_SKIP_ROWS, 1.0)],
        vec![(GL_PACK_SWAP_BYTES, 1.0), (GL_PACK_ALIGNMENT, 2.0)],
        vec![(GL_PACK_SWAP_BYTES, 1.0), (GL_PACK_LSB_FIRST, 1.0), (GL_PACK_ROW_LENGTH, 9.0), (GL_PACK_SKIP_PIXELS, 3.0)],
    ]
}

fn reset_modes(c: &mut Context) {
    for pack in [true, false] {
        set_modes(c, pack, &[(GL_PACK_SWAP_BYTES, 0.0), (GL_PACK_LSB_FIRST, 0.0), (GL_PACK_ROW_LENGTH, 0.0), (GL_PACK_SKIP_PIXELS, 0.0), (GL_PACK_SKIP_ROWS, 0.0), (GL_PACK_ALIGNMENT, 4.0)]);
    }
}

/// An 8-bit value through a b-bit unsigned normalized field and back.
fn quant(v: u8, bits: u32) -> u8 {
    let m = ((1u64 << bits) - 1) as f64;
    ((v as f64 / 255.0 * m).round() / m * 255.0).round() as u8
}

/// Bits each component of a type keeps, by position in the format.
fn type_bits(ty: u32, n: usize) -> u32 {
    let fields: &[u32] = match ty {
        GL_UNSIGNED_BYTE_3_3_2 => &[3, 3, 2],
        GL_UNSIGNED_BYTE_2_3_3_REV => &[3, 3, 2],
        GL_UNSIGNED_SHORT_5_6_5 | GL_UNSIGNED_SHORT_5_6_5_REV => &[5, 6, 5],
        GL_UNSIGNED_SHORT_4_4_4_4 | GL_UNSIGNED_SHORT_4_4_4_4_REV => &[4, 4, 4, 4],
        GL_UNSIGNED_SHORT_5_5_5_1 | GL_UNSIGNED_SHORT_1_5_5_5_REV => &[5, 5, 5, 1],
        GL_UNSIGNED_INT_10_10_10_2 | GL_UNSIGNED_INT_2_10_10_10_REV => &[10, 10, 10, 2],
        _ => &[8, 8, 8, 8],
    };
    fields[n]
}

#[test]
fn color_round_trips_every_format_type_and_mode() {
    let mut c = context();
    let mut rng = Rng(7);
    let (w, h) = (5usize, 3usize);
    let (sx, sy) = (1usize, 2usize);
    let (dx, dy) = (10usize, 4usize);
    let mut src = vec![[0u8; 4]; w * h];
    for p in src.iter_mut() {
        *p = [0, 0, 0, 0].map(|_| (rng.next() % 256) as u8);
        // Keep luminance sums varied but sometimes saturating.
    }
    let mut failures = Vec::new();
    for modes in mode_sets() {
        for &format in &COLOR_FORMATS {
            let comps: Vec<usize> = match format {
                GL_RED => vec![0],
                GL_GREEN => vec![1],
                GL_BLUE => vec![2],
                GL_ALPHA => vec![3],
                GL_RGB => vec![0, 1, 2],
                GL_RGBA => vec![0, 1, 2, 3],
                GL_BGR => vec![2, 1, 0],
                GL_BGRA => vec![2, 1, 0, 3],
                GL_LUMINANCE => vec![4],
                _ => vec![4, 3],
            };
            let mut types: Vec<u32> = PLAIN_TYPES.to_vec();
            if format == GL_RGB {
                types.extend(PACKED3);
            }
            if format == GL_RGBA || format == GL_BGRA {
                types.extend(PACKED4);
            }
            for ty in types {
                reset_modes(&mut c);
                set_modes(&mut c, true, &modes);
                set_modes(&mut c, false, &modes);
                for j in 0..h {
                    for i in 0..w {
                        let k = c.fb.index(sx + i, sy + j);
                        c.fb.color[k] = src[j * w + i];
                    }
                }
                let buf = read(&mut c, sx as i32, sy as i32, w as i32, h as i32, format, ty, 0xAA);
                assert_eq!(c.take_error(), GL_NO_ERROR, "read {format:#x} {ty:#x}");
                c.fb.color.fill([9, 9, 9, 9]);
                window_pos(&mut c, dx as f32, dy as f32);
                draw(&mut c, w as i32, h as i32, format, ty, &buf);
                assert_eq!(c.take_error(), GL_NO_ERROR, "draw {format:#x} {ty:#x}");
                for j in 0..h {
                    for i in 0..w {
                        let s = src[j * w + i];
                        let mut exp = [0u8, 0, 0, 255];
                        for (n, &k) in comps.iter().enumerate() {
                            let bits = type_bits(ty, n);
                            if k == 4 {
                                let l = (s[0] as u32 + s[1] as u32 + s[2] as u32).min(255) as u8;
                                exp[0] = quant(l, bits);
                                exp[1] = exp[0];
                                exp[2] = exp[0];
                            } else {
                                exp[k] = quant(s[k], bits);
                            }
                        }
                        let got = c.fb.color[c.fb.index(dx + i, dy + j)];
                        // Signed types keep one bit less (table 2.9/4.7).
                        let tol = if matches!(ty, GL_BYTE) { 1 } else { 0 };
                        if (0..4).any(|k| (got[k] as i32 - exp[k] as i32).abs() > tol) {
                            failures.push(format!("modes {modes:?} format {format:#x} type {ty:#x} pixel ({i},{j}): got {got:?} expected {exp:?}"));
                        }
                    }
                }
            }
        }
    }
    assert!(failures.is_empty(), "{} failures, first: {:#?}", failures.len(), &failures[..failures.len().min(5)]);
}

#[test]
fn depth_and_stencil_round_trips() {
    let mut c = context();
    let mut rng = Rng(3);
    let (w, h) = (6usize, 4usize);
    let depth: Vec<u32> = (0..w * h).map(|_| (rng.next() & 0xFF_FFFF) as u32).collect();
    let stencil: Vec<u8> = (0..w * h).map(|_| rng.next() as u8).collect();
    c.execute(&Command::Enable(GL_DEPTH_TEST));
    c.execute(&Command::DepthFunc(GL_ALWAYS));
    for modes in mode_sets() {
        for ty in PLAIN_TYPES {
            reset_modes(&mut c);
            set_modes(&mut c, true, &modes);
            set_modes(&mut c, false, &modes);
            for j in 0..h {
                for i in 0..w {
                    let k = c.fb.index(i, j);
                    c.fb.depth[k] = depth[j * w + i];
                    c.fb.stencil[k] = stencil[j * w + i];
                }
            }
            let d = read(&mut c, 0, 0, w as i32, h as i32, GL_DEPTH_COMPONENT, ty, 0);
            let s = read(&mut c, 0, 0, w as i32, h as i32, GL_STENCIL_INDEX, ty, 0);
            assert_eq!(c.take_error(), GL_NO_ERROR);
            c.fb.depth.fill(0);
            c.fb.stencil.fill(0);
            window_pos(&mut c, 20.0, 3.0);
            draw(&mut c, w as i32, h as i32, GL_DEPTH_COMPONENT, ty, &d);
            draw(&mut c, w as i32, h as i32, GL_STENCIL_INDEX, ty, &s);
            assert_eq!(c.take_error(), GL_NO_ERROR);
            let bits = match ty {
                GL_UNSIGNED_BYTE | GL_BYTE => 7,
                GL_UNSIGNED_SHORT | GL_SHORT => 15,
                _ => 24,
            };
            let tol = (1u32 << (24 - bits.min(24))) + 1;
            for j in 0..h {
                for i in 0..w {
                    let k = c.fb.index(20 + i, 3 + j);
                    let (gd, ed) = (c.fb.depth[k], depth[j * w + i]);
                    assert!(gd.abs_diff(ed) <= tol, "depth type {ty:#x} modes {modes:?}: {gd} vs {ed}");
                    // Indices are masked to the type's bits (table 4.6).
                    let es = if ty == GL_BYTE { stencil[j * w + i] & 0x7F } else { stencil[j * w + i] };
                    assert_eq!(c.fb.stencil[k], es, "stencil type {ty:#x} modes {modes:?}");
                }
            }
        }
        // GL_BITMAP: one bit per index.
        reset_modes(&mut c);
        set_modes(&mut c, true, &modes);
        set_modes(&mut c, false, &modes);
        for j in 0..h {
            for i in 0..w {
                let k = c.fb.index(i, j);
                c.fb.stencil[k] = stencil[j * w + i];
            }
        }
        let s = read(&mut c, 0, 0, w as i32, h as i32, GL_STENCIL_INDEX, GL_BITMAP, 0);
        c.fb.stencil.fill(0xF0);
        draw(&mut c, w as i32, h as i32, GL_STENCIL_INDEX, GL_BITMAP, &s);
        for j in 0..h {
            for i in 0..w {
                assert_eq!(c.fb.stencil[c.fb.index(20 + i, 3 + j)], stencil[j * w + i] & 1, "bitmap modes {modes:?}");
            }
        }
    }
}

#[test]
fn pack_layout_bytes() {
    let mut c = context();
    for (i, p) in c.fb.color.iter_mut().enumerate() {
        *p = [i as u8, (i * 3) as u8, (i * 7) as u8, 200];
    }
    let px = |c: &Context, x: usize, y: usize| c.fb.color[c.fb.index(x, y)];
    // RGB bytes, 3 wide: rows of 9 bytes padded to 12; padding untouched.
    let b = read(&mut c, 2, 1, 3, 2, GL_RGB, GL_UNSIGNED_BYTE, 0xEE);
    assert_eq!(&b[0..3], &px(&c, 2, 1)[..3]);
    assert_eq!(&b[9..12], &[0xEE; 3]);
    assert_eq!(&b[12..15], &px(&c, 2, 2)[..3]);
    // 5_6_5: R in the top 5 bits.
    let k = c.fb.index(0, 0);
    c.fb.color[k] = [255, 0, 255, 255];
    let b = read(&mut c, 0, 0, 1, 1, GL_RGB, GL_UNSIGNED_SHORT_5_6_5, 0);
    assert_eq!(u16::from_ne_bytes([b[0], b[1]]), 0xF81F);
    c.fb.color[k] = [255, 0, 0, 0];
    let b = read(&mut c, 0, 0, 1, 1, GL_RGB, GL_UNSIGNED_SHORT_5_6_5_REV, 0);
    assert_eq!(u16::from_ne_bytes([b[0], b[1]]), 0x001F);
    let b = read(&mut c, 0, 0, 1, 1, GL_BGRA, GL_UNSIGNED_INT_8_8_8_8_REV, 0);
    // BGRA with 8_8_8_8_REV: B lowest ... A highest: red is bits 16..23.
    assert_eq!(u32::from_ne_bytes([b[0], b[1], b[2], b[3]]), 0x00FF_0000);
    let b = read(&mut c, 0, 0, 1, 1, GL_RGBA, GL_UNSIGNED_INT_8_8_8_8, 0);
    assert_eq!(u32::from_ne_bytes([b[0], b[1], b[2], b[3]]), 0xFF00_0000);
    // Swap bytes on shorts.
    c.fb.color[k] = [255, 0, 0, 0];
    c.pixel_store(GL_PACK_SWAP_BYTES, 1.0);
    let b = read(&mut c, 0, 0, 1, 1, GL_RGB, GL_UNSIGNED_SHORT_5_6_5, 0);
    assert_eq!(u16::from_ne_bytes([b[1], b[0]]), 0xF800);
    c.pixel_store(GL_PACK_SWAP_BYTES, 0.0);
    // Stencil as a bitmap, MSB first and LSB first, with skipped bits.
    for (i, s) in [1u8, 0, 1, 1, 0, 0, 0, 1, 1].iter().enumerate() {
        let k = c.fb.index(i, 0);
        c.fb.stencil[k] = *s;
    }
    let b = read(&mut c, 0, 0, 9, 1, GL_STENCIL_INDEX, GL_BITMAP, 0);
    assert_eq!(&b[..2], &[0b1011_0001, 0b1000_0000]);
    c.pixel_store(GL_PACK_LSB_FIRST, 1.0);
    c.pixel_store(GL_PACK_SKIP_PIXELS, 2.0);
    let b = read(&mut c, 0, 0, 9, 1, GL_STENCIL_INDEX, GL_BITMAP, 0);
    // Bits 2.. hold the pixels, least significant first.
    assert_eq!(&b[..2], &[0b0011_0100, 0b0000_0110]);
    // Errors: BITMAP with a colour format, packed type with the wrong format.
    let _ = read(&mut c, 0, 0, 1, 1, GL_RGBA, GL_BITMAP, 0);
    assert_eq!(c.take_error(), GL_INVALID_ENUM);
    let _ = read(&mut c, 0, 0, 1, 1, GL_RGBA, GL_UNSIGNED_SHORT_5_6_5, 0);
    assert_eq!(c.take_error(), GL_INVALID_OPERATION);
    let _ = read(&mut c, 0, 0, 1, 1, GL_COLOR_INDEX, GL_UNSIGNED_BYTE, 0);
    assert_eq!(c.take_error(), GL_INVALID_OPERATION);
    // Reading outside the window leaves client memory alone.
    let b = read(&mut c, -2, -2, 3, 3, GL_RGBA, GL_UNSIGNED_BYTE, 0x55);
    assert_eq!(&b[..4], &[0x55; 4]);
    assert_eq!(c.take_error(), GL_NO_ERROR);
}

#[test]
fn unpack_skips_pick_the_subimage() {
    let mut c = context();
    // An 8x4 image of luminance bytes i + 16 j; draw its 3x2 part at (2, 1).
    let img: Vec<u8> = (0..4).flat_map(|j| (0..8).map(move |i| (i + 16 * j) as u8)).collect();
    c.pixel_store(GL_UNPACK_ROW_LENGTH, 8.0);
    c.pixel_store(GL_UNPACK_SKIP_PIXELS, 2.0);
    c.pixel_store(GL_UNPACK_SKIP_ROWS, 1.0);
    c.pixel_store(GL_UNPACK_ALIGNMENT, 1.0);
    window_pos(&mut c, 0.0, 0.0);
    draw(&mut c, 3, 2, GL_LUMINANCE, GL_UNSIGNED_BYTE, &img);
    for j in 0..2 {
        for i in 0..3 {
            let v = (2 + i + 16 * (1 + j)) as u8;
            assert_eq!(c.fb.color[c.fb.index(i, j)], [v, v, v, 255]);
        }
    }
}

#[test]
fn transfer_scale_bias_and_maps() {
    let mut c = context();
    window_pos(&mut c, 0.0, 0.0);
    c.execute(&Command::PixelTransfer(GL_RED_SCALE, 0.5));
    c.execute(&Command::PixelTransfer(GL_GREEN_BIAS, 0.25));
    c.execute(&Command::PixelTransfer(GL_ALPHA_SCALE, 0.0));
    c.execute(&Command::PixelTransfer(GL_ALPHA_BIAS, 2.0));
    draw(&mut c, 1, 1, GL_RGBA, GL_UNSIGNED_BYTE, &[200, 100, 50, 10]);
    assert_eq!(c.fb.color[0], [100, 164, 50, 255]);
    // MAP_COLOR: R_TO_R inverts through a 256-entry map; others identity by a 2-entry map.
    let inv: Vec<f32> = (0..256).map(|i| 1.0 - i as f32 / 255.0).collect();
    for s in [GL_RED_SCALE, GL_GREEN_BIAS, GL_ALPHA_SCALE, GL_ALPHA_BIAS] {
        c.execute(&Command::PixelTransfer(s, if s == GL_RED_SCALE || s == GL_ALPHA_SCALE { 1.0 } else { 0.0 }));
    }
    c.execute(&Command::PixelMap(GL_PIXEL_MAP_R_TO_R, inv));
    for m in [GL_PIXEL_MAP_G_TO_G, GL_PIXEL_MAP_B_TO_B, GL_PIXEL_MAP_A_TO_A] {
        c.execute(&Command::PixelMap(m, vec![0.0, 1.0]));
    }
    c.execute(&Command::PixelTransfer(GL_MAP_COLOR, 1.0));
    draw(&mut c, 1, 1, GL_RGBA, GL_UNSIGNED_BYTE, &[200, 100, 50, 10]);
    // G: round(100/255) = 0 -> 0; B: 0; A: 0.
    assert_eq!(c.fb.color[0], [55, 0, 0, 0]);
    // The same maps apply to glReadPixels.
    let k = c.fb.index(3, 3);
    c.fb.color[k] = [10, 200, 255, 128];
    let b = read(&mut c, 3, 3, 1, 1, GL_RGBA, GL_UNSIGNED_BYTE, 0);
    assert_eq!(&b[..4], &[245, 255, 255, 255]);
    c.execute(&Command::PixelTransfer(GL_MAP_COLOR, 0.0));

    // Colour indices: shift/offset, then I_TO_R/G/B/A (index & (size - 1)).
    c.execute(&Command::PixelMap(GL_PIXEL_MAP_I_TO_R, vec![0.0, 1.0, 0.0, 0.5]));
    c.execute(&Command::PixelMap(GL_PIXEL_MAP_I_TO_G, vec![0.0, 0.0, 1.0, 1.0]));
    c.execute(&Command::PixelMap(GL_PIXEL_MAP_I_TO_B, vec![1.0]));
    c.execute(&Command::PixelMap(GL_PIXEL_MAP_I_TO_A, vec![1.0, 1.0]));
    c.execute(&Command::PixelTransfer(GL_INDEX_SHIFT, 1.0));
    c.execute(&Command::PixelTransfer(GL_INDEX_OFFSET, 1.0));
    // Index i -> 2i + 1: 0 -> 1, 1 -> 3, 2 -> 5 & 3 = 1.
    draw(&mut c, 3, 1, GL_COLOR_INDEX, GL_UNSIGNED_BYTE, &[0, 1, 2, 0]);
    assert_eq!(c.fb.color[0], [255, 0, 255, 255]);
    assert_eq!(c.fb.color[1], [128, 255, 255, 255]);
    assert_eq!(c.fb.color[2], [255, 0, 255, 255]);
    // COLOR_INDEX as GL_BITMAP: bits 1 0 1 -> indices 3, 1, 3.
    draw(&mut c, 3, 1, GL_COLOR_INDEX, GL_BITMAP, &[0b1010_0000, 0, 0, 0]);
    assert_eq!(c.fb.color[0], [128, 255, 255, 255]);
    assert_eq!(c.fb.color[1], [255, 0, 255, 255]);

    // Stencil: shift/offset, MAP_STENCIL, then the write mask.
    c.execute(&Command::PixelMap(GL_PIXEL_MAP_S_TO_S, (0..16).map(|i| (15 - i) as f32).collect()));
    c.execute(&Command::PixelTransfer(GL_MAP_STENCIL, 1.0));
    c.execute(&Command::StencilMask(0x0F));
    c.fb.stencil.fill(0xA0);
    // 2 -> 5 -> 10; 7 -> 15 -> 0.
    draw(&mut c, 2, 1, GL_STENCIL_INDEX, GL_UNSIGNED_BYTE, &[2, 7, 0, 0]);
    assert_eq!(&c.fb.stencil[..2], &[0xAA, 0xA0]);
    c.execute(&Command::StencilMask(0xFF));
    c.execute(&Command::PixelTransfer(GL_MAP_STENCIL, 0.0));
    c.execute(&Command::PixelTransfer(GL_INDEX_SHIFT, 0.0));
    c.execute(&Command::PixelTransfer(GL_INDEX_OFFSET, 0.0));

    // Depth scale and bias on read.
    c.execute(&Command::PixelTransfer(GL_DEPTH_SCALE, 0.5));
    c.execute(&Command::PixelTransfer(GL_DEPTH_BIAS, 0.25));
    c.fb.depth[0] = softgl::framebuffer::DEPTH_MAX;
    let b = read(&mut c, 0, 0, 1, 1, GL_DEPTH_COMPONENT, GL_FLOAT, 0);
    assert_eq!(f32::from_ne_bytes([b[0], b[1], b[2], b[3]]), 0.75);
    assert_eq!(c.take_error(), GL_NO_ERROR);
}

#[test]
fn pixel_map_errors_and_queries() {
    let mut c = context();
    c.execute(&Command::PixelMap(GL_PIXEL_MAP_I_TO_R, vec![0.0; 3]));
    assert_eq!(c.take_error(), GL_INVALID_VALUE);
    c.execute(&Command::PixelMap(GL_PIXEL_MAP_S_TO_S, vec![0.0; 6]));
    assert_eq!(c.take_error(), GL_INVALID_VALUE);
    // R_TO_R takes any size.
    c.execute(&Command::PixelMap(GL_PIXEL_MAP_R_TO_R, vec![0.0, 0.5, 2.0]));
    assert_eq!(c.take_error(), GL_NO_ERROR);
    assert_eq!(c.get_pixel_map(GL_PIXEL_MAP_R_TO_R).unwrap(), &[0.0, 0.5, 1.0]);
    c.execute(&Command::PixelMap(0x0C7A, vec![0.0]));
    assert_eq!(c.take_error(), GL_INVALID_ENUM);
    c.execute(&Command::PixelTransfer(0x0D20, 1.0));
    assert_eq!(c.take_error(), GL_INVALID_ENUM);
    // Initial maps: one entry, 0.
    assert_eq!(c.get(GL_PIXEL_MAP_I_TO_I_SIZE).unwrap().as_i32(), vec![1]);
    assert_eq!(c.get(GL_PIXEL_MAP_I_TO_I_SIZE + 6).unwrap().as_i32(), vec![3]);
    c.execute(&Command::PixelTransfer(GL_INDEX_SHIFT, -3.0));
    assert_eq!(c.get(GL_INDEX_SHIFT).unwrap().as_i32(), vec![-3]);
    c.execute(&Command::PixelZoom(2.0, -1.5));
    assert_eq!(c.get(GL_ZOOM_Y).unwrap().as_f64(), vec![-1.5]);
    assert_eq!(softgl::gl::pixel_transfer::map_value_to_uint(GL_PIXEL_MAP_R_TO_R, 0.5, 16), 32768);
    assert_eq!(softgl::gl::pixel_transfer::map_values_from_uint(GL_PIXEL_MAP_I_TO_I, &[7], 32), vec![7.0]);
}

/// Every window pixel whose centre lies in group (i, j)'s rectangle gets
/// that group's colour; others keep the clear colour.
#[test]
fn zoom_coverage_follows_the_spec_rule() {
    let (w, h) = (4usize, 3usize);
    let img: Vec<u8> = (0..w * h).flat_map(|g| [g as u8 + 1, 0, 0, 255]).collect();
    for &(xr, yr) in &[(3.0f32, 2.0f32), (3.3, 2.7), (20.5, 12.25)] {
        for &(zx, zy) in &[(1.0f32, 1.0f32), (2.0, 3.0), (1.5, 0.5), (-1.0, 1.0), (-2.5, -1.25), (0.3, 2.0)] {
            let mut c = context();
            window_pos(&mut c, xr, yr);
            c.execute(&Command::PixelZoom(zx, zy));
            draw(&mut c, w as i32, h as i32, GL_RGBA, GL_UNSIGNED_BYTE, &img);
            for y in 0..H {
                for x in 0..W {
                    let (cx, cy) = (x as f64 + 0.5, y as f64 + 0.5);
                    let inside = |o: f64, z: f64, k: usize, c: f64| {
                        let (a, b) = (o + z * k as f64, o + z * (k + 1) as f64);
                        a.min(b) <= c && c < a.max(b)
                    };
                    let gi = (0..w).find(|&i| inside(xr as f64, zx as f64, i, cx));
                    let gj = (0..h).find(|&j| inside(yr as f64, zy as f64, j, cy));
                    let exp = match (gi, gj) {
                        (Some(i), Some(j)) => (j * w + i) as u8 + 1,
                        _ => 0,
                    };
                    assert_eq!(c.fb.color[c.fb.index(x, y)][0], exp, "pos ({xr},{yr}) zoom ({zx},{zy}) pixel ({x},{y})");
                }
            }
        }
    }
}

#[test]
fn draw_pixels_fragment_operations() {
    let mut c = context();
    // Colour draws take the raster z: depth test LESS against 0.5.
    c.execute(&Command::Enable(GL_DEPTH_TEST));
    c.execute(&Command::ClearDepth(0.5));
    c.execute(&Command::Clear(GL_DEPTH_BUFFER_BIT | GL_COLOR_BUFFER_BIT));
    c.execute(&Command::WindowPos([0.0, 0.0, 0.25]));
    draw(&mut c, 1, 1, GL_RGBA, GL_UNSIGNED_BYTE, &[255, 0, 0, 255]);
    c.execute(&Command::WindowPos([1.0, 0.0, 0.75]));
    draw(&mut c, 1, 1, GL_RGBA, GL_UNSIGNED_BYTE, &[255, 0, 0, 255]);
    assert_eq!(c.fb.color[0], [255, 0, 0, 255]);
    assert_eq!(c.fb.color[1], [0, 0, 0, 0]);
    // Depth draws take the raster colour and their own depth.
    c.execute(&Command::Color([0.0, 1.0, 0.0, 1.0]));
    c.execute(&Command::WindowPos([4.0, 0.0, 0.0]));
    let d: Vec<u8> = [0.25f32, 0.75].iter().flat_map(|v| v.to_ne_bytes()).collect();
    draw(&mut c, 2, 1, GL_DEPTH_COMPONENT, GL_FLOAT, &d);
    assert_eq!(c.fb.color[4], [0, 255, 0, 255]);
    assert_eq!(c.fb.color[5], [0, 0, 0, 0]);
    assert_eq!(c.fb.depth[4], softgl::render::fragment::depth_to_fixed(0.25));
    c.execute(&Command::Disable(GL_DEPTH_TEST));
    // Blending and the colour mask apply.
    c.execute(&Command::Enable(GL_BLEND));
    c.execute(&Command::BlendFunc([GL_ONE, GL_ONE, GL_ONE, GL_ONE]));
    c.execute(&Command::ColorMask([true, true, false, true]));
    window_pos(&mut c, 0.0, 0.0);
    draw(&mut c, 1, 1, GL_RGBA, GL_UNSIGNED_BYTE, &[0, 10, 20, 0]);
    assert_eq!(c.fb.color[0], [255, 10, 0, 255]);
    c.execute(&Command::Disable(GL_BLEND));
    c.execute(&Command::ColorMask([true; 4]));
    // The scissor box clips; the viewport does not.
    c.execute(&Command::Viewport(0, 0, 2, 2));
    c.execute(&Command::Scissor(10, 0, 2, 16));
    c.execute(&Command::Enable(GL_SCISSOR_TEST));
    window_pos(&mut c, 8.0, 0.0);
    draw(&mut c, 6, 1, GL_LUMINANCE, GL_UNSIGNED_BYTE, &[200; 8]);
    let row: Vec<u8> = (8..14).map(|x| c.fb.color[x][0]).collect();
    assert_eq!(row, vec![0, 0, 200, 200, 0, 0]);
    // No depth/stencil buffer: INVALID_OPERATION; bad arguments.
    let mut n = Context::new(Config { alpha_bits: 8, depth_bits: 0, stencil_bits: 0, accum_bits: 0 });
    n.fb.resize(4, 4).unwrap();
    n.surface_resized(4, 4);
    draw(&mut n, 1, 1, GL_DEPTH_COMPONENT, GL_FLOAT, &[0; 4]);
    assert_eq!(n.take_error(), GL_INVALID_OPERATION);
    n.execute(&Command::CopyPixels(0, 0, 1, 1, GL_STENCIL));
    assert_eq!(n.take_error(), GL_INVALID_OPERATION);
    draw(&mut n, -1, 1, GL_RGBA, GL_UNSIGNED_BYTE, &[0; 4]);
    assert_eq!(n.take_error(), GL_INVALID_VALUE);
    draw(&mut n, 1, 1, GL_RGBA, GL_BITMAP, &[0; 4]);
    assert_eq!(n.take_error(), GL_INVALID_ENUM);
    draw(&mut n, 1, 1, GL_BGR, GL_UNSIGNED_BYTE_3_3_2, &[0; 4]);
    assert_eq!(n.take_error(), GL_INVALID_OPERATION);
    n.execute(&Command::CopyPixels(0, 0, 1, 1, GL_RGBA));
    assert_eq!(n.take_error(), GL_INVALID_ENUM);
}

#[test]
fn copy_pixels_overlap() {
    for &(dx, dy) in &[(2i32, 1i32), (-2, -1), (3, 0), (0, -3), (-1, 2)] {
        let mut c = context();
        let mut rng = Rng(dx as u64 * 31 + dy as u64);
        for i in 0..W * H {
            c.fb.color[i] = [rng.next() as u8, rng.next() as u8, rng.next() as u8, 255];
            c.fb.depth[i] = (rng.next() & 0xFF_FFFF) as u32;
            c.fb.stencil[i] = rng.next() as u8;
        }
        let old = (c.fb.color.to_vec(), c.fb.depth.clone(), c.fb.stencil.clone());
        let (sx, sy, w, h) = (8, 5, 10, 6);
        window_pos(&mut c, (sx + dx) as f32, (sy + dy) as f32);
        c.execute(&Command::CopyPixels(sx, sy, w, h, GL_COLOR));
        let copied = c.fb.color.to_vec();
        // Depth copies write the raster colour too: mask it.
        c.execute(&Command::ColorMask([false; 4]));
        c.execute(&Command::Enable(GL_DEPTH_TEST));
        c.execute(&Command::DepthFunc(GL_ALWAYS));
        c.execute(&Command::CopyPixels(sx, sy, w, h, GL_DEPTH));
        c.execute(&Command::CopyPixels(sx, sy, w, h, GL_STENCIL));
        assert_eq!(c.take_error(), GL_NO_ERROR);
        for y in 0..H as i32 {
            for x in 0..W as i32 {
                let k = c.fb.index(x as usize, y as usize);
                let (ix, iy) = (x - dx, y - dy);
                let from = (ix >= sx && ix < sx + w && iy >= sy && iy < sy + h).then(|| c.fb.index(ix as usize, iy as usize));
                match from {
                    Some(s) => {
                        assert_eq!(copied[k], old.0[s], "colour ({x},{y}) shift ({dx},{dy})");
                        assert_eq!(c.fb.depth[k], old.1[s], "depth ({x},{y})");
                        assert_eq!(c.fb.stencil[k], old.2[s], "stencil ({x},{y})");
                    }
                    None => {
                        assert_eq!(copied[k], old.0[k]);
                        assert_eq!(c.fb.depth[k], old.1[k]);
                        assert_eq!(c.fb.stencil[k], old.2[k]);
                    }
                }
            }
        }
    }
}

#[test]
fn raster_position_validity_colour_and_distance() {
    let mut c = context();
    c.execute(&Command::MatrixMode(GL_PROJECTION));
    c.execute(&Command::Ortho([0.0, W as f64, 0.0, H as f64, -10.0, 10.0]));
    c.execute(&Command::MatrixMode(GL_MODELVIEW));
    c.execute(&Command::Color([1.0, 0.0, 0.0, 1.0]));
    c.execute(&Command::RasterPos([3.0, 4.0, 0.0, 1.0]));
    assert_eq!(c.get(GL_CURRENT_RASTER_POSITION).unwrap().as_f64(), vec![3.0, 4.0, 0.5, 1.0]);
    assert_eq!(c.get(GL_CURRENT_RASTER_POSITION_VALID).unwrap().as_bool(), vec![true]);
    assert_eq!(c.get(GL_CURRENT_RASTER_DISTANCE).unwrap().as_f64(), vec![5.0]);
    // The colour is latched: a later glColor does not change bitmap fragments.
    c.execute(&Command::Color([0.0, 1.0, 0.0, 1.0]));
    assert_eq!(c.get(GL_CURRENT_RASTER_COLOR).unwrap().as_f64(), vec![1.0, 0.0, 0.0, 1.0]);
    let bm = unsafe { c.build_bitmap(1, 1, [0.0, 0.0], [1.0, 0.0], [0x80u8].as_ptr()) };
    c.execute(&bm);
    assert_eq!(c.fb.color[c.fb.index(3, 4)], [255, 0, 0, 255]);
    assert_eq!(c.get(GL_CURRENT_RASTER_POSITION).unwrap().as_f64()[0], 4.0);
    // Outside the view volume: invalid; bitmaps then draw nothing and do not move it.
    c.execute(&Command::RasterPos([-1.0, 4.0, 0.0, 1.0]));
    assert_eq!(c.get(GL_CURRENT_RASTER_POSITION_VALID).unwrap().as_bool(), vec![false]);
    c.execute(&Command::RasterPos([3.0, 4.0, 11.0, 1.0]));
    assert_eq!(c.get(GL_CURRENT_RASTER_POSITION_VALID).unwrap().as_bool(), vec![false]);
    c.fb.color.fill([0; 4]);
    c.execute(&bm);
    assert!(c.fb.color.iter().all(|p| *p == [0; 4]));
    draw(&mut c, 1, 1, GL_RGBA, GL_UNSIGNED_BYTE, &[255; 4]);
    assert!(c.fb.color.iter().all(|p| *p == [0; 4]));
    // glWindowPos is always valid, z through the depth range, colour unlit.
    c.execute(&Command::DepthRange(0.2, 0.6));
    c.execute(&Command::WindowPos([-5.0, 2.5, 0.5]));
    let p = c.get(GL_CURRENT_RASTER_POSITION).unwrap().as_f64();
    assert_eq!(p[..2], [-5.0, 2.5]);
    assert!((p[2] - 0.4).abs() < 1e-6 && p[3] == 1.0);
    assert_eq!(c.get(GL_CURRENT_RASTER_POSITION_VALID).unwrap().as_bool(), vec![true]);
    assert_eq!(c.get(GL_CURRENT_RASTER_COLOR).unwrap().as_f64(), vec![0.0, 1.0, 0.0, 1.0]);
    assert_eq!(c.get(GL_CURRENT_RASTER_DISTANCE).unwrap().as_f64(), vec![0.0]);
    // Between Begin and End: INVALID_OPERATION.
    c.execute(&Command::Begin(GL_POINTS));
    c.execute(&Command::RasterPos([1.0, 1.0, 0.0, 1.0]));
    assert_eq!(c.take_error(), GL_INVALID_OPERATION);
    c.execute(&Command::End);
}

#[test]
fn raster_colour_is_lit_with_lighting() {
    let mut c = context();
    c.execute(&Command::LightModel(GL_LIGHT_MODEL_AMBIENT, [0.0, 0.0, 0.0, 1.0]));
    c.execute(&Command::Material(GL_FRONT_AND_BACK, GL_EMISSION, [0.2, 0.4, 0.6, 1.0]));
    c.execute(&Command::Material(GL_FRONT_AND_BACK, GL_DIFFUSE, [0.0, 0.0, 0.0, 0.5]));
    c.execute(&Command::Enable(GL_LIGHTING));
    c.execute(&Command::Color([1.0, 1.0, 1.0, 1.0]));
    c.execute(&Command::RasterPos([0.0, 0.0, 0.0, 1.0]));
    let col = c.get(GL_CURRENT_RASTER_COLOR).unwrap().as_f64();
    let exp = [0.2, 0.4, 0.6, 0.5];
    for k in 0..4 {
        assert!((col[k] - exp[k]).abs() < 1e-6, "{col:?}");
    }
    // glWindowPos is not lit.
    c.execute(&Command::WindowPos([0.0, 0.0, 0.0]));
    assert_eq!(c.get(GL_CURRENT_RASTER_COLOR).unwrap().as_f64(), vec![1.0; 4]);
}

#[test]
fn bitmap_pixels_movement_clipping_and_lists() {
    let mut c = context();
    // A 10x2 bitmap (rows of 2 bytes, alignment 1): row 0 = 1100000001, row 1 = 0010000010.
    let bits = [0b1100_0000u8, 0b0100_0000, 0b0010_0000, 0b1000_0000];
    c.pixel_store(GL_UNPACK_ALIGNMENT, 1.0);
    c.execute(&Command::Color([0.0, 0.0, 1.0, 1.0]));
    c.execute(&Command::WindowPos([5.7, 3.2, 0.0]));
    let bm = unsafe { c.build_bitmap(10, 2, [1.5, 0.0], [12.0, -1.0], bits.as_ptr()) };
    c.execute(&bm);
    // Lower left: (floor(5.7 - 1.5), floor(3.2)) = (4, 3).
    let set: Vec<(usize, usize)> = (0..H).flat_map(|y| (0..W).map(move |x| (x, y))).filter(|&(x, y)| c.fb.color[c.fb.index(x, y)][2] == 255).collect();
    assert_eq!(set, vec![(4, 3), (5, 3), (13, 3), (6, 4), (12, 4)]);
    let p = c.get(GL_CURRENT_RASTER_POSITION).unwrap().as_f64();
    assert!((p[0] - 17.7).abs() < 1e-5 && (p[1] - 2.2).abs() < 1e-5);
    // Partly outside the window: clipped, no panic; the position may leave the window and stays valid.
    c.execute(&Command::WindowPos([30.0, 15.0, 0.0]));
    c.execute(&bm);
    c.execute(&bm);
    assert_eq!(c.get(GL_CURRENT_RASTER_POSITION_VALID).unwrap().as_bool(), vec![true]);
    assert_eq!(c.fb.color[c.fb.index(29, 15)][2], 255);
    // LSB first and skip pixels: the same picture from a differently packed bitmap.
    let mut d = context();
    d.pixel_store(GL_UNPACK_ALIGNMENT, 1.0);
    d.pixel_store(GL_UNPACK_LSB_FIRST, 1.0);
    d.pixel_store(GL_UNPACK_SKIP_PIXELS, 3.0);
    // Bits 3..12 of each row, least significant first.
    let rev = |row: u16| -> [u8; 2] {
        let v = (row as u32) << 3; // pixel i at bit 3 + i
        [(v & 0xFF) as u8, (v >> 8) as u8]
    };
    let r0 = rev(0b10_0000_0011);
    let r1 = rev(0b01_0000_0100);
    let lsb = [r0[0], r0[1], r1[0], r1[1]];
    d.execute(&Command::Color([0.0, 0.0, 1.0, 1.0]));
    d.execute(&Command::WindowPos([5.7, 3.2, 0.0]));
    // Compile into a list, then change the unpack modes: the list keeps its bitmap.
    d.new_list(1, GL_COMPILE);
    let cmd = unsafe { d.build_bitmap(10, 2, [1.5, 0.0], [12.0, -1.0], lsb.as_ptr()) };
    d.submit(cmd);
    d.end_list();
    assert!(d.fb.color.iter().all(|p| *p == [0; 4]), "GL_COMPILE draws nothing");
    d.pixel_store(GL_UNPACK_LSB_FIRST, 0.0);
    d.pixel_store(GL_UNPACK_SKIP_PIXELS, 0.0);
    d.execute(&Command::CallList(1));
    let set2: Vec<(usize, usize)> = (0..H).flat_map(|y| (0..W).map(move |x| (x, y))).filter(|&(x, y)| d.fb.color[d.fb.index(x, y)][2] == 255).collect();
    assert_eq!(set2, vec![(4, 3), (5, 3), (13, 3), (6, 4), (12, 4)]);
    // A NULL bitmap only moves the position.
    let mv = unsafe { d.build_bitmap(0, 0, [0.0, 0.0], [-2.0, 3.0], std::ptr::null()) };
    d.execute(&mv);
    let p = d.get(GL_CURRENT_RASTER_POSITION).unwrap().as_f64();
    assert!((p[0] - 15.7).abs() < 1e-5 && (p[1] - 5.2).abs() < 1e-5);
}
