//! gluScaleImage and the mipmap builders, checked against hand-computed box
//! filter results: every type (the packed GL 1.2 types too, and their
//! round trips), the pixel-store modes (queried through a stand-in for
//! glGetIntegerv), mipmap level sizes and contents through a recording
//! [`TexGl`], proxy fitting, and the error codes GLU returns.
#![allow(clippy::type_complexity, clippy::too_many_arguments, clippy::useless_vec)]

use softgl::gl::enums::*;
// Named once: glu::scale keeps its own copies of these GL enums (GLU reaches
// GL only through its public interface), which the two globs would both bring.
use softgl::gl::enums::{
    GL_BITMAP, GL_UNSIGNED_BYTE_2_3_3_REV, GL_UNSIGNED_BYTE_3_3_2, GL_UNSIGNED_INT_10_10_10_2, GL_UNSIGNED_INT_2_10_10_10_REV, GL_UNSIGNED_INT_8_8_8_8, GL_UNSIGNED_INT_8_8_8_8_REV,
    GL_UNSIGNED_SHORT_1_5_5_5_REV, GL_UNSIGNED_SHORT_4_4_4_4, GL_UNSIGNED_SHORT_4_4_4_4_REV, GL_UNSIGNED_SHORT_5_5_5_1, GL_UNSIGNED_SHORT_5_6_5_REV,
};
use softgl::glu::mipmap::*;
use softgl::glu::scale::*;
use softgl::glu::strings::{GLU_INVALID_ENUM, GLU_INVALID_OPERATION, GLU_INVALID_VALUE};
use std::collections::HashMap;
use std::ffi::c_void;

/// Pixel-store answers (defaults when absent), texture images recorded.
#[derive(Default)]
struct Rec {
    ints: HashMap<u32, i32>,
    images: Vec<(usize, u32, i32, i32, [i32; 3], u32, u32, Vec<u8>)>,
    stores: Vec<(u32, i32)>,
    /// The largest size a proxy accepts; None: proxies unanswered.
    proxy_max: Option<i32>,
}

impl PixelGl for Rec {
    fn get_integer(&mut self, pname: u32) -> Option<i32> {
        self.ints.get(&pname).copied()
    }
}

impl TexGl for Rec {
    fn pixel_store(&mut self, pname: u32, value: i32) {
        self.stores.push((pname, value));
        self.ints.insert(pname, value);
    }
    fn tex_image(&mut self, dims: usize, target: u32, level: i32, internal: i32, size: [i32; 3], format: u32, type_: u32, data: &[u8]) {
        self.images.push((dims, target, level, internal, size, format, type_, data.to_vec()));
    }
    fn proxy_width(&mut self, _dims: usize, _proxy: u32, _internal: i32, size: [i32; 3], _format: u32, _type: u32) -> Option<i32> {
        self.proxy_max.map(|m| if size.iter().any(|&s| s > m) { 0 } else { size[0] })
    }
}

fn scale<I: Copy, O: Copy + Default>(gl: &mut Rec, format: u32, win: i32, hin: i32, tin: u32, input: &[I], wout: i32, hout: i32, tout: u32, n_out: usize) -> (i32, Vec<O>) {
    let mut out = vec![O::default(); n_out];
    let r = unsafe { scale_image(gl, format, win, hin, tin, input.as_ptr() as *const c_void, wout, hout, tout, out.as_mut_ptr() as *mut c_void) };
    (r, out)
}

fn tight() -> Rec {
    let mut r = Rec::default();
    r.ints.insert(GL_UNPACK_ALIGNMENT, 1);
    r.ints.insert(GL_PACK_ALIGNMENT, 1);
    r
}

#[test]
fn shrink_rgba_ubyte_by_two_is_the_2x2_average() {
    // 4x4 RGBA: pixel (x, y) = (10x, 20y, x+y, 255).
    let mut img = vec![];
    for y in 0..4u8 {
        for x in 0..4u8 {
            img.extend([10 * x, 20 * y, x + y, 255]);
        }
    }
    let (r, out) = scale::<u8, u8>(&mut Rec::default(), GL_RGBA, 4, 4, GL_UNSIGNED_BYTE, &img, 2, 2, GL_UNSIGNED_BYTE, 16);
    assert_eq!(r, 0);
    // Output (i, j) averages x in {2i, 2i+1}, y in {2j, 2j+1}:
    // R = 10 (2i + 0.5) -> 5, 25; G = 20 (2j + 0.5) -> 10, 50; B = 2i + 2j + 1.
    assert_eq!(out, vec![5, 10, 1, 255, 25, 10, 3, 255, 5, 50, 3, 255, 25, 50, 5, 255]);
}

#[test]
fn magnify_is_linear_interpolation_with_clamped_edges() {
    let (r, out) = scale::<u8, u8>(&mut tight(), GL_LUMINANCE, 2, 1, GL_UNSIGNED_BYTE, &[0, 200], 4, 1, GL_UNSIGNED_BYTE, 4);
    assert_eq!(r, 0);
    // Centres at 0.25, 0.75, 1.25, 1.75 input pixels: 0, 1/4, 3/4, 1.
    assert_eq!(out, vec![0, 50, 150, 200]);
    // 2 -> 3 rows: centres 1/3, 1, 5/3; boxes [-1/6,5/6] [1/2,3/2] [7/6,13/6].
    let (_, out) = scale::<u8, u8>(&mut tight(), GL_LUMINANCE, 1, 2, GL_UNSIGNED_BYTE, &[0, 240], 1, 3, GL_UNSIGNED_BYTE, 3);
    assert_eq!(out, vec![0, 120, 240]);
}

#[test]
fn shrink_by_a_fraction_weights_partial_pixels() {
    // 3 -> 2: [0, 1.5) and [1.5, 3).
    let (_, out) = scale::<u8, u8>(&mut Rec::default(), GL_LUMINANCE, 3, 1, GL_UNSIGNED_BYTE, &[0, 30, 90], 2, 1, GL_UNSIGNED_BYTE, 2);
    assert_eq!(out, vec![10, 70]);
    // 5 -> 2: [0, 2.5) and [2.5, 5).
    let (_, out) = scale::<u8, u8>(&mut Rec::default(), GL_LUMINANCE, 5, 1, GL_UNSIGNED_BYTE, &[10, 20, 30, 40, 50], 2, 1, GL_UNSIGNED_BYTE, 2);
    assert_eq!(out, vec![((10 + 20) as f64 / 2.5 + 30.0 * 0.5 / 2.5).round() as u8, ((30.0 * 0.5 + 40.0 + 50.0) / 2.5_f64).round() as u8]);
}

#[test]
fn every_plain_type_averages_its_values() {
    let mut gl = tight();
    let (r, o) = scale::<i8, i8>(&mut gl, GL_LUMINANCE, 2, 2, GL_BYTE, &[-100, -50, 20, 30], 1, 1, GL_BYTE, 1);
    assert_eq!((r, o), (0, vec![-25]));
    let (_, o) = scale::<u16, u16>(&mut gl, GL_LUMINANCE, 2, 2, GL_UNSIGNED_SHORT, &[1000, 3000, 5000, 7000], 1, 1, GL_UNSIGNED_SHORT, 1);
    assert_eq!(o, vec![4000]);
    let (_, o) = scale::<i16, i16>(&mut gl, GL_LUMINANCE, 2, 2, GL_SHORT, &[-32768, 32767, -1000, -3000], 1, 1, GL_SHORT, 1);
    assert_eq!(o, vec![-1000]);
    let (_, o) = scale::<u32, u32>(&mut gl, GL_LUMINANCE, 2, 2, GL_UNSIGNED_INT, &[4_000_000_000, 2_000_000_000, 0, 2_000_000_000], 1, 1, GL_UNSIGNED_INT, 1);
    assert_eq!(o, vec![2_000_000_000]);
    let (_, o) = scale::<i32, i32>(&mut gl, GL_LUMINANCE, 2, 2, GL_INT, &[-2_000_000_000, 1_000_000_000, 100, -100], 1, 1, GL_INT, 1);
    assert_eq!(o, vec![-250_000_000]);
    // Floats are not clamped.
    let (_, o) = scale::<f32, f32>(&mut gl, GL_LUMINANCE, 2, 2, GL_FLOAT, &[2.0, 4.0, -1.0, 7.0], 1, 1, GL_FLOAT, 1);
    assert_eq!(o, vec![3.0]);
    // Across types: GL's normalized conversions.
    let (_, o) = scale::<u8, u16>(&mut gl, GL_LUMINANCE, 3, 1, GL_UNSIGNED_BYTE, &[255, 0, 128], 3, 1, GL_UNSIGNED_SHORT, 3);
    assert_eq!(o, vec![65535, 0, 32896]);
    let (_, o) = scale::<u8, f32>(&mut gl, GL_LUMINANCE, 2, 1, GL_UNSIGNED_BYTE, &[255, 51], 2, 1, GL_FLOAT, 2);
    assert_eq!(o, vec![1.0, 0.2]);
    let (_, o) = scale::<f32, u8>(&mut gl, GL_LUMINANCE, 3, 1, GL_FLOAT, &[2.0, -1.0, 0.5], 3, 1, GL_UNSIGNED_BYTE, 3);
    assert_eq!(o, vec![255, 0, 128]);
    let (_, o) = scale::<i8, u8>(&mut gl, GL_LUMINANCE, 2, 1, GL_BYTE, &[127, -128], 2, 1, GL_UNSIGNED_BYTE, 2);
    assert_eq!(o, vec![255, 0]);
    // Into signed types 0.0 is the tie -1/2, packed to even as glReadPixels
    // does: 0, not -1.
    let f = [0.0f32, -1.0, 1.0, -2.0, 0.5];
    let (_, o) = scale::<f32, i8>(&mut gl, GL_LUMINANCE, 5, 1, GL_FLOAT, &f, 5, 1, GL_BYTE, 5);
    assert_eq!(o, vec![0, -128, 127, -128, 63]);
    let (_, o) = scale::<f32, i16>(&mut gl, GL_LUMINANCE, 5, 1, GL_FLOAT, &f, 5, 1, GL_SHORT, 5);
    assert_eq!(o, vec![0, -32768, 32767, -32768, 16383]);
    let (_, o) = scale::<f32, i32>(&mut gl, GL_LUMINANCE, 5, 1, GL_FLOAT, &f, 5, 1, GL_INT, 5);
    assert_eq!(o, vec![0, i32::MIN, i32::MAX, i32::MIN, 1_073_741_823]);
}

#[test]
fn packed_types_place_their_fields() {
    let mut gl = Rec::default();
    // One pixel, RGB(A) = first component full, others zero, and the reverse.
    let cases: &[(u32, u32, &[f32], u32)] = &[
        (GL_RGB, GL_UNSIGNED_BYTE_3_3_2, &[1.0, 0.0, 0.0], 0xE0),
        (GL_RGB, GL_UNSIGNED_BYTE_3_3_2, &[0.0, 0.0, 1.0], 0x03),
        (GL_RGB, GL_UNSIGNED_BYTE_2_3_3_REV, &[1.0, 0.0, 0.0], 0x07),
        (GL_RGB, GL_UNSIGNED_BYTE_2_3_3_REV, &[0.0, 0.0, 1.0], 0xC0),
        (GL_RGB, GL_UNSIGNED_SHORT_5_6_5, &[1.0, 0.0, 0.0], 0xF800),
        (GL_RGB, GL_UNSIGNED_SHORT_5_6_5, &[0.0, 1.0, 0.0], 0x07E0),
        (GL_RGB, GL_UNSIGNED_SHORT_5_6_5_REV, &[1.0, 0.0, 0.0], 0x001F),
        (GL_RGBA, GL_UNSIGNED_SHORT_4_4_4_4, &[1.0, 0.0, 0.0, 0.0], 0xF000),
        (GL_RGBA, GL_UNSIGNED_SHORT_4_4_4_4_REV, &[1.0, 0.0, 0.0, 0.0], 0x000F),
        (GL_RGBA, GL_UNSIGNED_SHORT_5_5_5_1, &[0.0, 0.0, 0.0, 1.0], 0x0001),
        (GL_RGBA, GL_UNSIGNED_SHORT_1_5_5_5_REV, &[0.0, 0.0, 0.0, 1.0], 0x8000),
        (GL_BGRA, GL_UNSIGNED_SHORT_1_5_5_5_REV, &[1.0, 0.0, 0.0, 0.0], 0x001F),
        (GL_RGBA, GL_UNSIGNED_INT_8_8_8_8, &[1.0, 0.0, 0.0, 0.0], 0xFF00_0000),
        (GL_RGBA, GL_UNSIGNED_INT_8_8_8_8_REV, &[1.0, 0.0, 0.0, 0.0], 0x0000_00FF),
        (GL_RGBA, GL_UNSIGNED_INT_10_10_10_2, &[0.0, 1.0, 0.0, 0.0], 0x003F_F000),
        (GL_RGBA, GL_UNSIGNED_INT_2_10_10_10_REV, &[0.0, 0.0, 0.0, 1.0], 0xC000_0000),
    ];
    for &(format, type_, px, want) in cases {
        let n = px.len();
        let mut out = [0u8; 4];
        let r = unsafe { scale_image(&mut gl, format, 1, 1, GL_FLOAT, px.as_ptr() as *const c_void, 1, 1, type_, out.as_mut_ptr() as *mut c_void) };
        assert_eq!(r, 0);
        let got = match type_kind(type_) {
            Some(TypeKind::Packed { size: 1, .. }) => out[0] as u32,
            Some(TypeKind::Packed { size: 2, .. }) => u16::from_ne_bytes([out[0], out[1]]) as u32,
            _ => u32::from_ne_bytes(out),
        };
        assert_eq!(got, want, "type {type_:#x} {px:?}");
        // And back.
        let mut back = vec![9.0f32; n];
        unsafe { scale_image(&mut gl, format, 1, 1, type_, out.as_ptr() as *const c_void, 1, 1, GL_FLOAT, back.as_mut_ptr() as *mut c_void) };
        assert_eq!(back, px, "type {type_:#x}");
    }
    // 3_3_2 to bytes: 7/7, 3/7, 1/3.
    let (_, o) = scale::<u8, u8>(&mut gl, GL_RGB, 1, 1, GL_UNSIGNED_BYTE_3_3_2, &[0xE0 | (3 << 2) | 1], 1, 1, GL_UNSIGNED_BYTE, 3);
    assert_eq!(o, vec![255, 109, 85]);
    // Averaging 5_6_5: (31, 63, 0) and (1, 1, 30) -> (16, 32, 15).
    let px = |r: u16, g: u16, b: u16| (r << 11) | (g << 5) | b;
    let (_, o) = scale::<u16, u16>(&mut gl, GL_RGB, 2, 1, GL_UNSIGNED_SHORT_5_6_5, &[px(31, 63, 0), px(1, 1, 30)], 1, 1, GL_UNSIGNED_SHORT_5_6_5, 1);
    assert_eq!(o, vec![px(16, 32, 15)]);
}

#[test]
fn packed_types_round_trip() {
    let mut gl = Rec::default();
    let types = [
        (GL_RGB, GL_UNSIGNED_BYTE_3_3_2, 1),
        (GL_RGB, GL_UNSIGNED_BYTE_2_3_3_REV, 1),
        (GL_RGB, GL_UNSIGNED_SHORT_5_6_5, 2),
        (GL_RGB, GL_UNSIGNED_SHORT_5_6_5_REV, 2),
        (GL_RGBA, GL_UNSIGNED_SHORT_4_4_4_4, 2),
        (GL_BGRA, GL_UNSIGNED_SHORT_4_4_4_4_REV, 2),
        (GL_RGBA, GL_UNSIGNED_SHORT_5_5_5_1, 2),
        (GL_BGRA, GL_UNSIGNED_SHORT_1_5_5_5_REV, 2),
        (GL_RGBA, GL_UNSIGNED_INT_8_8_8_8, 4),
        (GL_BGRA, GL_UNSIGNED_INT_8_8_8_8_REV, 4),
        (GL_RGBA, GL_UNSIGNED_INT_10_10_10_2, 4),
        (GL_RGBA, GL_UNSIGNED_INT_2_10_10_10_REV, 4),
    ];
    let mut seed = 12345u32;
    let mut rnd = || {
        seed = seed.wrapping_mul(1664525).wrapping_add(1013904223);
        (seed >> 8) as u8
    };
    for (format, type_, size) in types {
        let (w, h) = (5usize, 3usize);
        let src: Vec<u8> = (0..w * h * size).map(|_| rnd()).collect();
        // Same size, same type: identity (default alignment 4 on both sides).
        let stride = (w * size).div_ceil(4) * 4;
        let mut padded = vec![0u8; stride * h];
        for y in 0..h {
            padded[y * stride..y * stride + w * size].copy_from_slice(&src[y * w * size..(y + 1) * w * size]);
        }
        let mut out = vec![0u8; stride * h];
        let r = unsafe { scale_image(&mut gl, format, w as i32, h as i32, type_, padded.as_ptr() as *const c_void, w as i32, h as i32, type_, out.as_mut_ptr() as *mut c_void) };
        assert_eq!(r, 0);
        assert_eq!(out, padded, "identity {type_:#x}");
        // Through GL_FLOAT and back.
        let comps = if format == GL_RGB { 3 } else { 4 };
        let mut f = vec![0f32; w * h * comps];
        let mut back = vec![0u8; stride * h];
        unsafe {
            scale_image(&mut gl, format, w as i32, h as i32, type_, padded.as_ptr() as *const c_void, w as i32, h as i32, GL_FLOAT, f.as_mut_ptr() as *mut c_void);
            scale_image(&mut gl, format, w as i32, h as i32, GL_FLOAT, f.as_ptr() as *const c_void, w as i32, h as i32, type_, back.as_mut_ptr() as *mut c_void);
        }
        assert_eq!(back, padded, "float round trip {type_:#x}");
    }
}

#[test]
fn pixel_store_modes_are_honoured() {
    // Unpack: row length 4, skip 1 row and 1 pixel, alignment 8; RGB bytes.
    let mut gl = Rec::default();
    gl.ints.insert(GL_UNPACK_ROW_LENGTH, 4);
    gl.ints.insert(GL_UNPACK_SKIP_ROWS, 1);
    gl.ints.insert(GL_UNPACK_SKIP_PIXELS, 1);
    gl.ints.insert(GL_UNPACK_ALIGNMENT, 8);
    // Row stride: 4 * 3 = 12 bytes -> 16 with alignment 8.
    let mut src = vec![0u8; 16 * 3];
    for (y, row) in [1usize, 2].iter().enumerate() {
        for x in 0..2 {
            let o = row * 16 + (1 + x) * 3;
            src[o..o + 3].copy_from_slice(&[(10 * (x + 1)) as u8, (100 + y) as u8, 7]);
        }
    }
    // Pack: alignment 2, skip 1 pixel, row length 3: stride 9 -> 10.
    gl.ints.insert(GL_PACK_ALIGNMENT, 2);
    gl.ints.insert(GL_PACK_SKIP_PIXELS, 1);
    gl.ints.insert(GL_PACK_ROW_LENGTH, 3);
    let mut out = vec![0xAAu8; 20];
    let r = unsafe { scale_image(&mut gl, GL_RGB, 2, 2, GL_UNSIGNED_BYTE, src.as_ptr() as *const c_void, 2, 2, GL_UNSIGNED_BYTE, out.as_mut_ptr() as *mut c_void) };
    assert_eq!(r, 0);
    let mut want = vec![0xAAu8; 20];
    want[3..9].copy_from_slice(&[10, 100, 7, 20, 100, 7]);
    want[13..19].copy_from_slice(&[10, 101, 7, 20, 101, 7]);
    assert_eq!(out, want);

    // Swap bytes on both sides: shorts read and written big-endian.
    let mut gl = tight();
    gl.ints.insert(GL_UNPACK_SWAP_BYTES, 1);
    let src: Vec<u16> = [1000u16, 3000].iter().map(|v| v.swap_bytes()).collect();
    let (_, o) = scale::<u16, u16>(&mut gl, GL_LUMINANCE, 2, 1, GL_UNSIGNED_SHORT, &src, 1, 1, GL_UNSIGNED_SHORT, 1);
    assert_eq!(o, vec![2000]);
    gl.ints.insert(GL_PACK_SWAP_BYTES, 1);
    let (_, o) = scale::<u16, u16>(&mut gl, GL_LUMINANCE, 2, 1, GL_UNSIGNED_SHORT, &src, 1, 1, GL_UNSIGNED_SHORT, 1);
    assert_eq!(o, vec![2000u16.swap_bytes()]);
}

#[test]
fn bitmaps_and_indices() {
    let mut gl = Rec::default();
    // 16 bits, MSB first: 1110 0000 | 1111 0001 -> groups of four: 3/4, 0, 1, 1/4.
    let (r, o) = scale::<u8, u8>(&mut gl, GL_COLOR_INDEX, 16, 1, GL_BITMAP, &[0b1110_0000, 0b1111_0001], 4, 1, GL_UNSIGNED_BYTE, 4);
    assert_eq!((r, o), (0, vec![1, 0, 1, 0]));
    gl.ints.insert(GL_UNPACK_LSB_FIRST, 1);
    let (_, o) = scale::<u8, u8>(&mut gl, GL_COLOR_INDEX, 16, 1, GL_BITMAP, &[0b0000_0111, 0b1000_1111], 4, 1, GL_UNSIGNED_BYTE, 4);
    assert_eq!(o, vec![1, 0, 1, 0]);
    // Indices to a bitmap (LSB first on the pack side too).
    gl.ints.insert(GL_PACK_LSB_FIRST, 1);
    let (_, o) = scale::<u8, u8>(&mut gl, GL_COLOR_INDEX, 8, 1, GL_UNSIGNED_BYTE, &[1, 0, 1, 1, 0, 0, 0, 1], 8, 1, GL_BITMAP, 1);
    assert_eq!(o, vec![0b1000_1101]);
    // Indices are not normalized: they average and mask.
    let (_, o) = scale::<u16, u8>(&mut gl, GL_COLOR_INDEX, 2, 1, GL_UNSIGNED_SHORT, &[300, 310], 1, 1, GL_UNSIGNED_BYTE, 1);
    assert_eq!(o, vec![(305 & 255) as u8]);
}

#[test]
fn scale_errors() {
    let mut gl = Rec::default();
    let src = [0u8; 64];
    let mut dst = [0u8; 64];
    let mut call = |f, w, t_in, t_out| unsafe { scale_image(&mut gl, f, w, 2, t_in, src.as_ptr() as *const c_void, 2, 2, t_out, dst.as_mut_ptr() as *mut c_void) };
    assert_eq!(call(GL_RGB, -1, GL_UNSIGNED_BYTE, GL_UNSIGNED_BYTE), GLU_INVALID_VALUE as i32);
    assert_eq!(call(0x1234, 2, GL_UNSIGNED_BYTE, GL_UNSIGNED_BYTE), GLU_INVALID_ENUM as i32);
    assert_eq!(call(GL_RGB, 2, 0x1234, GL_UNSIGNED_BYTE), GLU_INVALID_ENUM as i32);
    assert_eq!(call(GL_RGB, 2, GL_UNSIGNED_BYTE, 0x1234), GLU_INVALID_ENUM as i32);
    assert_eq!(call(GL_RGB, 2, GL_BITMAP, GL_UNSIGNED_BYTE), GLU_INVALID_ENUM as i32);
    assert_eq!(call(GL_RGBA, 2, GL_UNSIGNED_SHORT_5_6_5, GL_UNSIGNED_BYTE), GLU_INVALID_OPERATION as i32);
    assert_eq!(call(GL_RGB, 2, GL_UNSIGNED_BYTE, GL_UNSIGNED_SHORT_4_4_4_4), GLU_INVALID_OPERATION as i32);
    assert_eq!(call(GL_LUMINANCE, 2, GL_UNSIGNED_INT_8_8_8_8, GL_UNSIGNED_BYTE), GLU_INVALID_OPERATION as i32);
    assert_eq!(call(GL_RGB, 0, GL_UNSIGNED_BYTE, GL_UNSIGNED_BYTE), 0);
    assert_eq!(dst, [0u8; 64]);
    let r = unsafe { scale_image(&mut gl, GL_RGB, 2, 2, GL_UNSIGNED_BYTE, std::ptr::null(), 2, 2, GL_UNSIGNED_BYTE, dst.as_mut_ptr() as *mut c_void) };
    assert_eq!(r, GLU_INVALID_VALUE as i32);
}

#[test]
fn nearest_power_as_glu_rounds() {
    let got: Vec<usize> = [1, 2, 3, 4, 5, 6, 7, 8, 10, 11, 12, 100, 300].iter().map(|&n| nearest_power(n)).collect();
    assert_eq!(got, vec![1, 2, 4, 4, 4, 8, 8, 8, 8, 8, 16, 128, 256]);
}

fn build2d(gl: &mut Rec, w: i32, h: i32, format: u32, type_: u32, data: &[u8]) -> i32 {
    unsafe { build_mipmaps(gl, 2, GL_TEXTURE_2D, GL_RGBA as i32, [w, h, 1], format, type_, data.as_ptr() as *const c_void) }
}

#[test]
fn mipmap_levels_of_a_power_of_two_image() {
    let mut gl = Rec::default();
    // 4x4 luminance, alignment 4 rows of 4 bytes.
    let img: Vec<u8> = (0..16).map(|i| (i * 16) as u8).collect();
    assert_eq!(build2d(&mut gl, 4, 4, GL_LUMINANCE, GL_UNSIGNED_BYTE, &img), 0);
    let sizes: Vec<(i32, [i32; 3])> = gl.images.iter().map(|i| (i.2, i.4)).collect();
    assert_eq!(sizes, vec![(0, [4, 4, 1]), (1, [2, 2, 1]), (2, [1, 1, 1])]);
    assert_eq!(gl.images[0].7, img);
    // Level 1: 2x2 averages of (16 (x + 4y)).
    let avg = |x: usize, y: usize| -> u8 { ([0, 1].iter().flat_map(|&dy| [0, 1].map(|dx| 16 * (2 * x + dx + 4 * (2 * y + dy)))).sum::<usize>() as f64 / 4.0).round() as u8 };
    assert_eq!(gl.images[1].7, vec![avg(0, 0), avg(1, 0), avg(0, 1), avg(1, 1)]);
    let l1 = &gl.images[1].7;
    let want = ((l1.iter().map(|&v| v as f64).sum::<f64>()) / 4.0).round() as u8;
    assert_eq!(gl.images[2].7, vec![want]);
    for i in &gl.images {
        assert_eq!((i.0, i.1, i.3, i.5, i.6), (2, GL_TEXTURE_2D, GL_RGBA as i32, GL_LUMINANCE, GL_UNSIGNED_BYTE));
    }
    // The unpack modes were made tight around the uploads, then restored.
    assert_eq!(gl.stores, vec![(GL_UNPACK_ALIGNMENT, 1), (GL_UNPACK_ALIGNMENT, 4)]);
}

#[test]
fn non_power_of_two_images_are_rescaled_first() {
    let mut gl = tight();
    // 3x5 RGB -> 4x4 (3 -> 4, 5 -> 4).
    let img: Vec<u8> = (0..3 * 5 * 3).map(|i| (i * 5) as u8).collect();
    assert_eq!(build2d(&mut gl, 3, 5, GL_RGB, GL_UNSIGNED_BYTE, &img), 0);
    let sizes: Vec<[i32; 3]> = gl.images.iter().map(|i| i.4).collect();
    assert_eq!(sizes, vec![[4, 4, 1], [2, 2, 1], [1, 1, 1]]);
    let mut want = vec![0u8; 4 * 4 * 3];
    let r = unsafe { scale_image(&mut tight(), GL_RGB, 3, 5, GL_UNSIGNED_BYTE, img.as_ptr() as *const c_void, 4, 4, GL_UNSIGNED_BYTE, want.as_mut_ptr() as *mut c_void) };
    assert_eq!(r, 0);
    assert_eq!(gl.images[0].7, want);
    // 6x1 -> 8x1, then 4x1, 2x1, 1x1 (height stays 1).
    let mut gl = tight();
    assert_eq!(build2d(&mut gl, 6, 1, GL_LUMINANCE, GL_UNSIGNED_BYTE, &[0, 50, 100, 150, 200, 250]), 0);
    let sizes: Vec<[i32; 3]> = gl.images.iter().map(|i| i.4).collect();
    assert_eq!(sizes, vec![[8, 1, 1], [4, 1, 1], [2, 1, 1], [1, 1, 1]]);
    let l0 = &gl.images[0].7;
    let l1: Vec<u8> = (0..4).map(|i| ((l0[2 * i] as f64 + l0[2 * i + 1] as f64) / 2.0).round() as u8).collect();
    assert_eq!(gl.images[1].7, l1);
}

#[test]
fn proxy_textures_limit_the_size() {
    let mut gl = tight();
    gl.proxy_max = Some(2);
    let img = vec![100u8; 8 * 8];
    assert_eq!(build2d(&mut gl, 8, 8, GL_LUMINANCE, GL_UNSIGNED_BYTE, &img), 0);
    let sizes: Vec<[i32; 3]> = gl.images.iter().map(|i| i.4).collect();
    assert_eq!(sizes, vec![[2, 2, 1], [1, 1, 1]]);
    assert_eq!(gl.images[0].7, vec![100; 4]);
}

#[test]
fn three_d_and_one_d_mipmaps() {
    let mut gl = tight();
    let img: Vec<u8> = (0..8).map(|i| i * 10).collect();
    let r = unsafe { build_mipmaps(&mut gl, 3, GL_TEXTURE_3D, 1, [2, 2, 2], GL_LUMINANCE, GL_UNSIGNED_BYTE, img.as_ptr() as *const c_void) };
    assert_eq!(r, 0);
    assert_eq!(gl.images.len(), 2);
    assert_eq!((gl.images[1].0, gl.images[1].4), (3, [1, 1, 1]));
    assert_eq!(gl.images[1].7, vec![35]);
    let mut gl = tight();
    let img = [10u8, 20, 30, 40, 50, 60, 70, 80];
    let r = unsafe { build_mipmaps(&mut gl, 1, GL_TEXTURE_1D, 1, [8, 1, 1], GL_LUMINANCE, GL_UNSIGNED_BYTE, img.as_ptr() as *const c_void) };
    assert_eq!(r, 0);
    let levels: Vec<Vec<u8>> = gl.images.iter().map(|i| i.7.clone()).collect();
    assert_eq!(levels, vec![img.to_vec(), vec![15, 35, 55, 75], vec![25, 65], vec![45]]);
}

#[test]
fn mipmap_levels_forms() {
    let mut gl = tight();
    let img = vec![7u8; 4 * 4];
    let call = |gl: &mut Rec, level, base, max| unsafe { build_mipmap_levels(gl, 2, GL_TEXTURE_2D, 1, [4, 4, 1], GL_LUMINANCE, GL_UNSIGNED_BYTE, level, base, max, img.as_ptr() as *const c_void) };
    // Data is level 2; levels 2 (4x4), 3 (2x2), 4 (1x1); load 3..=4.
    assert_eq!(call(&mut gl, 2, 3, 4), 0);
    let got: Vec<(i32, [i32; 3])> = gl.images.iter().map(|i| (i.2, i.4)).collect();
    assert_eq!(got, vec![(3, [2, 2, 1]), (4, [1, 1, 1])]);
    assert_eq!(call(&mut gl, 2, 2, 5), GLU_INVALID_VALUE as i32);
    assert_eq!(call(&mut gl, 2, 1, 3), GLU_INVALID_VALUE as i32);
    assert_eq!(call(&mut gl, 0, 2, 1), GLU_INVALID_VALUE as i32);
    // Non-power-of-two: 6x3 halves to 3x1, then 1x1.
    let mut gl = tight();
    let img: Vec<u8> = (0..18).map(|i| i * 10).collect();
    let r = unsafe { build_mipmap_levels(&mut gl, 2, GL_TEXTURE_2D, 1, [6, 3, 1], GL_LUMINANCE, GL_UNSIGNED_BYTE, 0, 0, 2, img.as_ptr() as *const c_void) };
    assert_eq!(r, 0);
    let got: Vec<[i32; 3]> = gl.images.iter().map(|i| i.4).collect();
    assert_eq!(got, vec![[6, 3, 1], [3, 1, 1], [1, 1, 1]]);
    // Level 1 pixel 0: x in [0, 2), y in [0, 3): mean of 0,10,60,70,120,130.
    assert_eq!(gl.images[1].7[0], 65);
}

#[test]
fn mipmap_errors() {
    let mut gl = tight();
    let img = [0u8; 64];
    let p = img.as_ptr() as *const c_void;
    unsafe {
        assert_eq!(build_mipmaps(&mut gl, 2, GL_TEXTURE_2D, 1, [0, 4, 1], GL_RGB, GL_UNSIGNED_BYTE, p), GLU_INVALID_VALUE as i32);
        assert_eq!(build_mipmaps(&mut gl, 2, GL_TEXTURE_1D, 1, [4, 4, 1], GL_RGB, GL_UNSIGNED_BYTE, p), GLU_INVALID_ENUM as i32);
        assert_eq!(build_mipmaps(&mut gl, 2, GL_TEXTURE_2D, 1, [4, 4, 1], GL_STENCIL_INDEX, GL_UNSIGNED_BYTE, p), GLU_INVALID_ENUM as i32);
        assert_eq!(build_mipmaps(&mut gl, 2, GL_TEXTURE_2D, 1, [4, 4, 1], GL_RGB, 0x1234, p), GLU_INVALID_ENUM as i32);
        assert_eq!(build_mipmaps(&mut gl, 2, GL_TEXTURE_2D, 1, [4, 4, 1], GL_RGBA, GL_UNSIGNED_BYTE_3_3_2, p), GLU_INVALID_OPERATION as i32);
        assert_eq!(build_mipmaps(&mut gl, 1, GL_TEXTURE_1D, 1, [4, 1, 1], GL_RGB, GL_UNSIGNED_BYTE, std::ptr::null()), GLU_INVALID_VALUE as i32);
        assert_eq!(build_mipmaps(&mut gl, 3, GL_TEXTURE_3D, 1, [4, 4, -1], GL_RGB, GL_UNSIGNED_BYTE, p), GLU_INVALID_VALUE as i32);
    }
    assert!(gl.images.is_empty());
}
