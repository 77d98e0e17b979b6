//! Vertex arrays, buffer objects and occlusion queries (GL 1.5 sections
//! 2.8, 2.9, 4.1.6) through the exported entry points, on an OSMesa
//! context current in the test's thread: every pointer call with every
//! accepted size and type, tight and padded strides; the 14 interleaved
//! formats against table 2.5's layouts written out here; glDrawElements with
//! each index type; buffer objects as array and index sources at offsets;
//! mapping and its errors; display lists capturing array data at compile
//! time; occlusion query counts on scenes whose pixel counts are known; and
//! the error rules.
#![allow(clippy::missing_safety_doc)]

use softgl::api::table::*;
use softgl::gl::enums::*;
use softgl::winsys::osmesa;
use std::ffi::c_void;
use std::ptr::null;

const GL_TEXTURE0: u32 = 0x84C0;
const GL_CLIENT_ACTIVE_TEXTURE: u32 = 0x84E1;
const GL_ARRAY_BUFFER: u32 = 0x8892;
const GL_ELEMENT_ARRAY_BUFFER: u32 = 0x8893;
const GL_ARRAY_BUFFER_BINDING: u32 = 0x8894;
const GL_ELEMENT_ARRAY_BUFFER_BINDING: u32 = 0x8895;
const GL_VERTEX_ARRAY_BUFFER_BINDING: u32 = 0x8896;
const GL_COLOR_ARRAY_BUFFER_BINDING: u32 = 0x8898;
const GL_STATIC_DRAW: u32 = 0x88E4;
const GL_STREAM_DRAW: u32 = 0x88E0;
const GL_READ_ONLY: u32 = 0x88B8;
const GL_WRITE_ONLY: u32 = 0x88B9;
const GL_READ_WRITE: u32 = 0x88BA;
const GL_BUFFER_SIZE: u32 = 0x8764;
const GL_BUFFER_USAGE: u32 = 0x8765;
const GL_BUFFER_ACCESS: u32 = 0x88BB;
const GL_BUFFER_MAPPED: u32 = 0x88BC;
const GL_BUFFER_MAP_POINTER: u32 = 0x88BD;
const GL_SAMPLES_PASSED: u32 = 0x8914;
const GL_QUERY_COUNTER_BITS: u32 = 0x8864;
const GL_CURRENT_QUERY: u32 = 0x8865;
const GL_QUERY_RESULT: u32 = 0x8866;
const GL_QUERY_RESULT_AVAILABLE: u32 = 0x8867;
const GL_CURRENT_INDEX: u32 = 0x0B01;
const GL_EDGE_FLAG: u32 = 0x0B43;
const GL_CURRENT_FOG_COORD: u32 = 0x8453;
const GL_CURRENT_SECONDARY_COLOR: u32 = 0x8459;
const GL_VERTEX_ARRAY_POINTER: u32 = 0x808E;
const GL_FEEDBACK_BUFFER_POINTER: u32 = 0x0DF0;
const GL_SELECTION_BUFFER_POINTER: u32 = 0x0DF3;
const GL_2D: u32 = 0x0600;
const GL_3D: u32 = 0x0601;
const GL_SELECTION_BUFFER_SIZE: u32 = 0x0DF4;
const GL_FEEDBACK_BUFFER_SIZE: u32 = 0x0DF1;
const GL_FEEDBACK_BUFFER_TYPE: u32 = 0x0DF2;
const GL_INDEX_BITS: u32 = 0x0D51;

const W: i32 = 32;
const H: i32 = 32;

/// An OSMesa context current in this thread, with an ortho projection
/// mapping object coordinates to window pixels, cleared to black.
struct Ctx {
    ctx: *mut osmesa::OsContext,
    _buf: Vec<u8>,
}

impl Drop for Ctx {
    fn drop(&mut self) {
        unsafe { osmesa::destroy_context(self.ctx) };
    }
}

fn setup() -> Ctx {
    let ctx = osmesa::create_context_ext(GL_RGBA, 24, 8, 0, std::ptr::null_mut());
    assert!(!ctx.is_null());
    let mut buf = vec![0u8; (W * H * 4) as usize];
    unsafe {
        assert!(osmesa::make_current(ctx, buf.as_mut_ptr() as *mut c_void, GL_UNSIGNED_BYTE, W, H));
        glMatrixMode(GL_PROJECTION);
        glLoadIdentity();
        glOrtho(0.0, W as f64, 0.0, H as f64, -1.0, 1.0);
        glMatrixMode(GL_MODELVIEW);
        glLoadIdentity();
        glClearColor(0.0, 0.0, 0.0, 0.0);
        glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    }
    Ctx { ctx, _buf: buf }
}

fn error() -> u32 {
    unsafe { glGetError() }
}

fn pixel(x: i32, y: i32) -> [u8; 4] {
    let mut p = [0u8; 4];
    unsafe { glReadPixels(x, y, 1, 1, GL_RGBA, GL_UNSIGNED_BYTE, p.as_mut_ptr() as *mut c_void) };
    p
}

fn clear() {
    unsafe { glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT) };
}

/// Pixels whose red channel is non-zero.
fn lit_pixels() -> usize {
    let mut px = vec![0u8; (W * H * 4) as usize];
    unsafe { glReadPixels(0, 0, W, H, GL_RGBA, GL_UNSIGNED_BYTE, px.as_mut_ptr() as *mut c_void) };
    px.chunks(4).filter(|p| p[0] != 0).count()
}

fn get_i(pname: u32) -> i32 {
    let mut v = [0i32; 4];
    unsafe { glGetIntegerv(pname, v.as_mut_ptr()) };
    v[0]
}

fn get_f<const N: usize>(pname: u32) -> [f32; N] {
    let mut v = [0f32; 16];
    unsafe { glGetFloatv(pname, v.as_mut_ptr()) };
    v[..N].try_into().unwrap()
}

fn current() -> &'static mut softgl::gl::Context {
    unsafe { &mut *softgl::winsys::current::current() }
}

/// Bytes of values of one type, native endian, each value padded to
/// `stride` bytes (0: tight).
fn pack<T: Copy>(rows: &[Vec<T>], stride: usize) -> Vec<u8> {
    let elem = std::mem::size_of::<T>();
    let mut out = Vec::new();
    for r in rows {
        let start = out.len();
        for v in r {
            let b = unsafe { std::slice::from_raw_parts(v as *const T as *const u8, elem) };
            out.extend_from_slice(b);
        }
        if stride > 0 {
            out.resize(start + stride, 0xAB);
        }
    }
    out
}

/// The unit square's corners scaled to [x0, x1) x [y0, y1), as a quad.
fn rect(x0: i32, y0: i32, x1: i32, y1: i32) -> [[i32; 2]; 4] {
    [[x0, y0], [x1, y0], [x1, y1], [x0, y1]]
}

/// Checks that exactly the pixels of [x0,x1) x [y0,y1) have colour `c`
/// and the rest are black.
fn expect_rect(r: [i32; 4], c: [u8; 4], what: &str) {
    let mut px = vec![0u8; (W * H * 4) as usize];
    unsafe { glReadPixels(0, 0, W, H, GL_RGBA, GL_UNSIGNED_BYTE, px.as_mut_ptr() as *mut c_void) };
    for y in 0..H {
        for x in 0..W {
            let p = &px[((y * W + x) * 4) as usize..][..4];
            let inside = x >= r[0] && x < r[2] && y >= r[1] && y < r[3];
            let want = if inside { c } else { [0, 0, 0, 0] };
            assert_eq!(p, want, "{what}: pixel ({x},{y})");
        }
    }
}

#[test]
fn vertex_pointer_every_size_type_and_stride() {
    let _c = setup();
    let r = rect(3, 5, 20, 17);
    for ty in [GL_SHORT, GL_INT, GL_FLOAT, GL_DOUBLE] {
        for size in [2usize, 3, 4] {
            for stride in [0usize, 40] {
                clear();
                let rows: Vec<Vec<f64>> = r
                    .iter()
                    .map(|v| {
                        let mut row = vec![v[0] as f64, v[1] as f64, 0.0, 1.0];
                        if size == 4 {
                            // Homogeneous: w = 2 doubles every coordinate.
                            row = row.iter().map(|c| c * 2.0).collect();
                        }
                        row.truncate(size);
                        row
                    })
                    .collect();
                let bytes = match ty {
                    GL_SHORT => pack(&rows.iter().map(|r| r.iter().map(|&c| c as i16).collect()).collect::<Vec<_>>(), stride),
                    GL_INT => pack(&rows.iter().map(|r| r.iter().map(|&c| c as i32).collect()).collect::<Vec<_>>(), stride),
                    GL_FLOAT => pack(&rows.iter().map(|r| r.iter().map(|&c| c as f32).collect()).collect::<Vec<_>>(), stride),
                    _ => pack(&rows, stride),
                };
                unsafe {
                    glColor4ub(255, 128, 0, 255);
                    glVertexPointer(size as i32, ty, stride as i32, bytes.as_ptr() as *const c_void);
                    glEnableClientState(GL_VERTEX_ARRAY);
                    glDrawArrays(GL_QUADS, 0, 4);
                    glDisableClientState(GL_VERTEX_ARRAY);
                }
                assert_eq!(error(), GL_NO_ERROR);
                expect_rect([3, 5, 20, 17], [255, 128, 0, 255], &format!("vertex type {ty:#x} size {size} stride {stride}"));
            }
        }
    }
}

/// Table 2.9's conversions, written out for the test.
fn norm_i(v: i64, bits: u32, signed: bool) -> f64 {
    let max = ((1u64 << bits) - 1) as f64;
    if signed {
        (2.0 * v as f64 + 1.0) / max
    } else {
        v as f64 / max
    }
}

fn to_u8(f: f64) -> u8 {
    (f.clamp(0.0, 1.0) * 255.0 + 0.5) as u8
}

/// Colour components of every type: raw bytes for `n` components and the
/// value table 2.9 gives them.
fn color_data(ty: u32, comps: &[f64]) -> (Vec<u8>, Vec<f64>) {
    // `comps` are in [0, 1]; pick integers near them.
    let mut bytes = Vec::new();
    let mut want = Vec::new();
    for &c in comps {
        match ty {
            GL_BYTE => {
                let v = (c * 127.0) as i8;
                bytes.extend(v.to_ne_bytes());
                want.push(norm_i(v as i64, 8, true));
            }
            GL_UNSIGNED_BYTE => {
                let v = (c * 255.0) as u8;
                bytes.extend(v.to_ne_bytes());
                want.push(norm_i(v as i64, 8, false));
            }
            GL_SHORT => {
                let v = (c * 32767.0) as i16;
                bytes.extend(v.to_ne_bytes());
                want.push(norm_i(v as i64, 16, true));
            }
            GL_UNSIGNED_SHORT => {
                let v = (c * 65535.0) as u16;
                bytes.extend(v.to_ne_bytes());
                want.push(norm_i(v as i64, 16, false));
            }
            GL_INT => {
                let v = (c * 2147483647.0) as i32;
                bytes.extend(v.to_ne_bytes());
                want.push(norm_i(v as i64, 32, true));
            }
            GL_UNSIGNED_INT => {
                let v = (c * 4294967295.0) as u32;
                bytes.extend(v.to_ne_bytes());
                want.push(norm_i(v as i64, 32, false));
            }
            GL_FLOAT => {
                bytes.extend((c as f32).to_ne_bytes());
                want.push(c as f32 as f64);
            }
            _ => {
                bytes.extend(c.to_ne_bytes());
                want.push(c);
            }
        }
    }
    (bytes, want)
}

const COLOR_TYPES: [u32; 8] = [GL_BYTE, GL_UNSIGNED_BYTE, GL_SHORT, GL_UNSIGNED_SHORT, GL_INT, GL_UNSIGNED_INT, GL_FLOAT, GL_DOUBLE];

#[test]
fn color_pointer_every_size_type_and_stride() {
    let _c = setup();
    let verts: Vec<f32> = rect(2, 2, 30, 30).iter().flat_map(|v| [v[0] as f32, v[1] as f32]).collect();
    for ty in COLOR_TYPES {
        for size in [3usize, 4] {
            for stride in [0usize, 44] {
                clear();
                let comps = [0.8, 0.3, 0.55, 0.7];
                let (one, want) = color_data(ty, &comps[..size]);
                let elem = one.len();
                let mut bytes = Vec::new();
                for _ in 0..4 {
                    let start = bytes.len();
                    bytes.extend_from_slice(&one);
                    if stride > 0 {
                        bytes.resize(start + stride, 0xCD);
                    }
                }
                assert!(stride == 0 || stride >= elem);
                unsafe {
                    glVertexPointer(2, GL_FLOAT, 0, verts.as_ptr() as *const c_void);
                    glColorPointer(size as i32, ty, stride as i32, bytes.as_ptr() as *const c_void);
                    glEnableClientState(GL_VERTEX_ARRAY);
                    glEnableClientState(GL_COLOR_ARRAY);
                    glDrawArrays(GL_TRIANGLE_FAN, 0, 4);
                    glDisableClientState(GL_COLOR_ARRAY);
                }
                assert_eq!(error(), GL_NO_ERROR);
                let a = if size == 4 { to_u8(want[3]) } else { 255 };
                let expect = [to_u8(want[0]), to_u8(want[1]), to_u8(want[2]), a];
                let got = pixel(15, 15);
                for ch in 0..4 {
                    assert!(
                        (got[ch] as i32 - expect[ch] as i32).abs() <= 1,
                        "colour type {ty:#x} size {size} stride {stride}: got {got:?}, want {expect:?}"
                    );
                }
            }
        }
    }
}

/// glArrayElement outside Begin/End sets the current values from every
/// enabled array; the queries read them back.
#[test]
fn attribute_arrays_set_current_values() {
    let _c = setup();
    unsafe {
        // Normals: every type, table 2.9's signed mapping.
        for ty in [GL_BYTE, GL_SHORT, GL_INT, GL_FLOAT, GL_DOUBLE] {
            let (bytes, want) = color_data(ty, &[0.25, 0.0, 0.9]);
            // Padded stride: the element is at index 1.
            let mut data = [0u8; 64];
            data[32..32 + bytes.len()].copy_from_slice(&bytes);
            glNormalPointer(ty, 32, data.as_ptr() as *const c_void);
            glEnableClientState(GL_NORMAL_ARRAY);
            glArrayElement(1);
            glDisableClientState(GL_NORMAL_ARRAY);
            let n = get_f::<3>(GL_CURRENT_NORMAL);
            for i in 0..3 {
                assert!((n[i] as f64 - want[i]).abs() < 1e-6, "normal type {ty:#x}: {n:?} vs {want:?}");
            }
        }
        // Colours through GL_CURRENT_COLOR: size 3 leaves alpha 1.
        for ty in COLOR_TYPES {
            let (bytes, want) = color_data(ty, &[0.5, 0.25, 1.0]);
            glColor4f(0.0, 0.0, 0.0, 0.0);
            glColorPointer(3, ty, 0, bytes.as_ptr() as *const c_void);
            glEnableClientState(GL_COLOR_ARRAY);
            glArrayElement(0);
            glDisableClientState(GL_COLOR_ARRAY);
            let c = get_f::<4>(GL_CURRENT_COLOR);
            for i in 0..3 {
                assert!((c[i] as f64 - want[i]).abs() < 1e-6, "colour type {ty:#x}: {c:?} vs {want:?}");
            }
            assert_eq!(c[3], 1.0);
        }
        // Secondary colours: size 3, every colour type.
        for ty in COLOR_TYPES {
            let (bytes, want) = color_data(ty, &[0.1, 0.6, 0.35]);
            glSecondaryColorPointer(3, ty, 0, bytes.as_ptr() as *const c_void);
            glEnableClientState(GL_SECONDARY_COLOR_ARRAY);
            glArrayElement(0);
            glDisableClientState(GL_SECONDARY_COLOR_ARRAY);
            let c = get_f::<4>(GL_CURRENT_SECONDARY_COLOR);
            for i in 0..3 {
                assert!((c[i] as f64 - want[i]).abs() < 1e-6, "secondary type {ty:#x}: {c:?} vs {want:?}");
            }
        }
        // Fog coordinates: float and double, element 2 of a strided array.
        let fogf = [0f32, 0.0, 0.0, 0.0, 7.5, 0.0];
        glFogCoordPointer(GL_FLOAT, 8, fogf.as_ptr() as *const c_void);
        glEnableClientState(GL_FOG_COORD_ARRAY);
        glArrayElement(2);
        assert_eq!(get_f::<1>(GL_CURRENT_FOG_COORD), [7.5]);
        let fogd = [1.0f64, -3.25];
        glFogCoordPointer(GL_DOUBLE, 0, fogd.as_ptr() as *const c_void);
        glArrayElement(1);
        assert_eq!(get_f::<1>(GL_CURRENT_FOG_COORD), [-3.25]);
        glDisableClientState(GL_FOG_COORD_ARRAY);
        // Colour indices: every type (not normalized).
        let ub = [3u8, 200];
        let sh = [0i16, -7];
        let it = [0i32, 123456];
        let fl = [0f32, 2.5];
        let db = [0f64, 9.0];
        glEnableClientState(GL_INDEX_ARRAY);
        for (ty, p, want) in [
            (GL_UNSIGNED_BYTE, ub.as_ptr() as *const c_void, 200.0),
            (GL_SHORT, sh.as_ptr() as *const c_void, -7.0),
            (GL_INT, it.as_ptr() as *const c_void, 123456.0),
            (GL_FLOAT, fl.as_ptr() as *const c_void, 2.5),
            (GL_DOUBLE, db.as_ptr() as *const c_void, 9.0),
        ] {
            glIndexPointer(ty, 0, p);
            glArrayElement(1);
            assert_eq!(get_f::<1>(GL_CURRENT_INDEX), [want], "index type {ty:#x}");
        }
        glDisableClientState(GL_INDEX_ARRAY);
        // Edge flags.
        let flags = [1u8, 0, 0xFF];
        glEdgeFlagPointer(0, flags.as_ptr() as *const c_void);
        glEnableClientState(GL_EDGE_FLAG_ARRAY);
        glArrayElement(1);
        assert_eq!(get_i(GL_EDGE_FLAG), 0);
        glArrayElement(2);
        assert_eq!(get_i(GL_EDGE_FLAG), 1);
        glDisableClientState(GL_EDGE_FLAG_ARRAY);
        // Texture coordinates per client unit: every size and type.
        for unit in [0u32, 1, 3] {
            glClientActiveTexture(GL_TEXTURE0 + unit);
            for ty in [GL_SHORT, GL_INT, GL_FLOAT, GL_DOUBLE] {
                for size in 1..=4usize {
                    let vals = [3.0, -2.0, 5.0, 4.0];
                    let row: Vec<f64> = vals[..size].to_vec();
                    let bytes = match ty {
                        GL_SHORT => pack(&[row.iter().map(|&c| c as i16).collect::<Vec<_>>()], 0),
                        GL_INT => pack(&[row.iter().map(|&c| c as i32).collect::<Vec<_>>()], 0),
                        GL_FLOAT => pack(&[row.iter().map(|&c| c as f32).collect::<Vec<_>>()], 0),
                        _ => pack(std::slice::from_ref(&row), 0),
                    };
                    glTexCoordPointer(size as i32, ty, 0, bytes.as_ptr() as *const c_void);
                    glEnableClientState(GL_TEXTURE_COORD_ARRAY);
                    glArrayElement(0);
                    glDisableClientState(GL_TEXTURE_COORD_ARRAY);
                    let mut want = [0.0, 0.0, 0.0, 1.0];
                    want[..size].copy_from_slice(&[3.0, -2.0, 5.0, 4.0][..size]);
                    assert_eq!(current().current.tex_coords[unit as usize], want, "unit {unit} type {ty:#x} size {size}");
                }
            }
        }
        glClientActiveTexture(GL_TEXTURE0);
    }
    assert_eq!(error(), GL_NO_ERROR);
}

/// Table 2.5, written out independently: (format, texcoord size, colour
/// (size, is ubyte), normal, vertex size).
type Format = (u32, usize, Option<(usize, bool)>, bool, usize);
const FORMATS: [Format; 14] = [
    (0x2A20, 0, None, false, 2),                  // V2F
    (0x2A21, 0, None, false, 3),                  // V3F
    (0x2A22, 0, Some((4, true)), false, 2),       // C4UB_V2F
    (0x2A23, 0, Some((4, true)), false, 3),       // C4UB_V3F
    (0x2A24, 0, Some((3, false)), false, 3),      // C3F_V3F
    (0x2A25, 0, None, true, 3),                   // N3F_V3F
    (0x2A26, 0, Some((4, false)), true, 3),       // C4F_N3F_V3F
    (0x2A27, 2, None, false, 3),                  // T2F_V3F
    (0x2A28, 4, None, false, 4),                  // T4F_V4F
    (0x2A29, 2, Some((4, true)), false, 3),       // T2F_C4UB_V3F
    (0x2A2A, 2, Some((3, false)), false, 3),      // T2F_C3F_V3F
    (0x2A2B, 2, None, true, 3),                   // T2F_N3F_V3F
    (0x2A2C, 2, Some((4, false)), true, 3),       // T2F_C4F_N3F_V3F
    (0x2A2D, 4, Some((4, false)), true, 4),       // T4F_C4F_N3F_V4F
];

#[test]
fn interleaved_arrays_all_formats() {
    let _c = setup();
    let corners = rect(4, 6, 25, 19);
    for &(format, tsize, color, normal, vsize) in &FORMATS {
        for extra in [0usize, 12] {
            clear();
            // Build each vertex: t, then c, then n, then v (the spec's order).
            let mut data = Vec::new();
            let mut stride = 0;
            for (k, v) in corners.iter().enumerate() {
                let start = data.len();
                let tc = [0.25 * k as f32, 0.5, 0.75, 1.5];
                for t in &tc[..tsize] {
                    data.extend(t.to_ne_bytes());
                }
                match color {
                    Some((_, true)) => data.extend([200u8, 100, 50, 255]),
                    Some((n, false)) => {
                        for c in &[200.0f32 / 255.0, 100.0 / 255.0, 50.0 / 255.0, 1.0][..n] {
                            data.extend(c.to_ne_bytes());
                        }
                    }
                    None => {}
                }
                if normal {
                    for c in [0.0f32, 0.6, 0.8 + k as f32] {
                        data.extend(c.to_ne_bytes());
                    }
                }
                let pos = [v[0] as f32, v[1] as f32, 0.0, 1.0];
                for c in &pos[..vsize] {
                    data.extend(c.to_ne_bytes());
                }
                data.resize(data.len() + extra, 0xEE);
                stride = data.len() - start;
            }
            unsafe {
                glEnableClientState(GL_EDGE_FLAG_ARRAY);
                glEnableClientState(GL_INDEX_ARRAY);
                glColor4ub(10, 20, 30, 255);
                glInterleavedArrays(format, if extra == 0 { 0 } else { stride as i32 }, data.as_ptr() as *const c_void);
                assert_eq!(error(), GL_NO_ERROR, "format {format:#x}");
                assert_eq!(glIsEnabled(GL_VERTEX_ARRAY), 1);
                assert_eq!(glIsEnabled(GL_COLOR_ARRAY), color.is_some() as u8, "format {format:#x}");
                assert_eq!(glIsEnabled(GL_NORMAL_ARRAY), normal as u8);
                assert_eq!(glIsEnabled(GL_TEXTURE_COORD_ARRAY), (tsize > 0) as u8);
                assert_eq!(glIsEnabled(GL_EDGE_FLAG_ARRAY), 0);
                assert_eq!(glIsEnabled(GL_INDEX_ARRAY), 0);
                assert_eq!(get_i(0x807C), stride as i32, "vertex stride of {format:#x}");
                assert_eq!(get_i(0x807A), vsize as i32);
                glDrawArrays(GL_QUADS, 0, 4);
            }
            let c = if color.is_some() { [200, 100, 50, 255] } else { [10, 20, 30, 255] };
            expect_rect([4, 6, 25, 19], c, &format!("interleaved {format:#x} extra {extra}"));
            // A draw leaves the current values alone; glArrayElement sets
            // them from the last element.
            unsafe { glArrayElement(3) };
            if tsize > 0 {
                let mut want = [0.75, 0.5, 0.0, 1.0];
                if tsize == 4 {
                    want = [0.75, 0.5, 0.75, 1.5];
                }
                assert_eq!(current().current.tex_coords[0], want, "texcoord of {format:#x}");
            }
            if normal {
                assert_eq!(get_f::<3>(GL_CURRENT_NORMAL), [0.0, 0.6, 3.8], "normal of {format:#x}");
            }
        }
    }
    unsafe {
        glInterleavedArrays(0x2A2E, 0, null());
        assert_eq!(error(), GL_INVALID_ENUM);
        glInterleavedArrays(0x2A20, -4, null());
        assert_eq!(error(), GL_INVALID_VALUE);
    }
}

/// Four quads' worth of vertices; indices pick the quad at (8..24, 8..24).
fn index_scene() -> Vec<f32> {
    let mut v = vec![0f32; 2 * 12];
    // Decoys at 0..3, 8..11; the quad at 4..7.
    for (i, p) in rect(0, 0, 4, 4).iter().chain(rect(8, 8, 24, 24).iter()).chain(rect(28, 28, 32, 32).iter()).enumerate() {
        v[2 * i] = p[0] as f32;
        v[2 * i + 1] = p[1] as f32;
    }
    v
}

#[test]
fn draw_elements_each_index_type() {
    let _c = setup();
    let verts = index_scene();
    let idx = [4u32, 5, 6, 7];
    unsafe {
        glVertexPointer(2, GL_FLOAT, 0, verts.as_ptr() as *const c_void);
        glEnableClientState(GL_VERTEX_ARRAY);
        glColor4ub(0, 255, 0, 255);
        let ub: Vec<u8> = idx.iter().map(|&i| i as u8).collect();
        let us: Vec<u16> = idx.iter().map(|&i| i as u16).collect();
        for (ty, p) in [
            (GL_UNSIGNED_BYTE, ub.as_ptr() as *const c_void),
            (GL_UNSIGNED_SHORT, us.as_ptr() as *const c_void),
            (GL_UNSIGNED_INT, idx.as_ptr() as *const c_void),
        ] {
            clear();
            glDrawElements(GL_QUADS, 4, ty, p);
            assert_eq!(error(), GL_NO_ERROR);
            expect_rect([8, 8, 24, 24], [0, 255, 0, 255], &format!("DrawElements type {ty:#x}"));
            clear();
            glDrawRangeElements(GL_QUADS, 4, 7, 4, ty, p);
            assert_eq!(error(), GL_NO_ERROR);
            expect_rect([8, 8, 24, 24], [0, 255, 0, 255], &format!("DrawRangeElements type {ty:#x}"));
        }
        // Triangles through shared indices.
        clear();
        let tri = [4u16, 5, 6, 4, 6, 7];
        glDrawElements(GL_TRIANGLES, 6, GL_UNSIGNED_SHORT, tri.as_ptr() as *const c_void);
        expect_rect([8, 8, 24, 24], [0, 255, 0, 255], "indexed triangles");
        // Errors.
        glDrawElements(GL_QUADS, 4, GL_SHORT, tri.as_ptr() as *const c_void);
        assert_eq!(error(), GL_INVALID_ENUM);
        glDrawElements(GL_QUADS, -1, GL_UNSIGNED_SHORT, tri.as_ptr() as *const c_void);
        assert_eq!(error(), GL_INVALID_VALUE);
        glDrawElements(0x000A, 4, GL_UNSIGNED_SHORT, tri.as_ptr() as *const c_void);
        assert_eq!(error(), GL_INVALID_ENUM);
        glDrawRangeElements(GL_QUADS, 7, 4, 4, GL_UNSIGNED_SHORT, tri.as_ptr() as *const c_void);
        assert_eq!(error(), GL_INVALID_VALUE);
        // NULL indices without a buffer: nothing, no crash.
        clear();
        glDrawElements(GL_QUADS, 4, GL_UNSIGNED_SHORT, null());
        assert_eq!(lit_pixels(), 0);
    }
}

#[test]
fn multi_draw() {
    let _c = setup();
    let verts = index_scene();
    unsafe {
        glVertexPointer(2, GL_FLOAT, 0, verts.as_ptr() as *const c_void);
        glEnableClientState(GL_VERTEX_ARRAY);
        glColor4ub(255, 255, 255, 255);
        let first = [0, 8];
        let count = [4, 4];
        glMultiDrawArrays(GL_QUADS, first.as_ptr(), count.as_ptr(), 2);
        assert_eq!(error(), GL_NO_ERROR);
        assert_eq!(lit_pixels(), 16 + 16);
        clear();
        let a = [0u8, 1, 2, 3];
        let b = [4u8, 5, 6, 7];
        let ptrs = [a.as_ptr() as *const c_void, b.as_ptr() as *const c_void];
        glMultiDrawElements(GL_QUADS, count.as_ptr(), GL_UNSIGNED_BYTE, ptrs.as_ptr(), 2);
        assert_eq!(error(), GL_NO_ERROR);
        assert_eq!(lit_pixels(), 16 + 256);
        let bad = [4, -1];
        glMultiDrawArrays(GL_QUADS, first.as_ptr(), bad.as_ptr(), 2);
        assert_eq!(error(), GL_INVALID_VALUE);
        glMultiDrawArrays(GL_QUADS, first.as_ptr(), count.as_ptr(), -1);
        assert_eq!(error(), GL_INVALID_VALUE);
    }
}

#[test]
fn buffer_objects_as_sources_with_offsets() {
    let _c = setup();
    let verts = index_scene();
    unsafe {
        let mut bufs = [0u32; 3];
        glGenBuffers(3, bufs.as_mut_ptr());
        assert!(bufs.iter().all(|&b| b != 0) && bufs[0] != bufs[1] && bufs[1] != bufs[2]);
        assert_eq!(glIsBuffer(bufs[0]), 0, "generated but never bound");
        // Vertices at offset 16 of buffer 0.
        let mut vdata = vec![0u8; 16];
        vdata.extend(pack(std::slice::from_ref(&verts), 0));
        glBindBuffer(GL_ARRAY_BUFFER, bufs[0]);
        assert_eq!(glIsBuffer(bufs[0]), 1);
        glBufferData(GL_ARRAY_BUFFER, vdata.len() as isize, vdata.as_ptr() as *const c_void, GL_STATIC_DRAW);
        glVertexPointer(2, GL_FLOAT, 0, 16 as *const c_void);
        // Colours (ubyte RGBA) at offset 3 of buffer 1, filled by BufferSubData.
        glBindBuffer(GL_ARRAY_BUFFER, bufs[1]);
        glBufferData(GL_ARRAY_BUFFER, 3 + 12 * 4, null(), GL_STREAM_DRAW);
        let colors: Vec<u8> = (0..12).flat_map(|_| [255u8, 0, 255, 255]).collect();
        glBufferSubData(GL_ARRAY_BUFFER, 3, colors.len() as isize, colors.as_ptr() as *const c_void);
        glColorPointer(4, GL_UNSIGNED_BYTE, 0, 3 as *const c_void);
        glBindBuffer(GL_ARRAY_BUFFER, 0);
        assert_eq!(get_i(GL_VERTEX_ARRAY_BUFFER_BINDING), bufs[0] as i32);
        assert_eq!(get_i(GL_COLOR_ARRAY_BUFFER_BINDING), bufs[1] as i32);
        assert_eq!(get_i(GL_ARRAY_BUFFER_BINDING), 0);
        glEnableClientState(GL_VERTEX_ARRAY);
        glEnableClientState(GL_COLOR_ARRAY);
        glDrawArrays(GL_QUADS, 4, 4);
        assert_eq!(error(), GL_NO_ERROR);
        expect_rect([8, 8, 24, 24], [255, 0, 255, 255], "VBO arrays");
        // Indices at offset 2 of an element buffer.
        clear();
        glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, bufs[2]);
        let idx = [0u16, 4, 5, 6, 7];
        glBufferData(GL_ELEMENT_ARRAY_BUFFER, 10, idx.as_ptr() as *const c_void, GL_STATIC_DRAW);
        assert_eq!(get_i(GL_ELEMENT_ARRAY_BUFFER_BINDING), bufs[2] as i32);
        glDrawElements(GL_QUADS, 4, GL_UNSIGNED_SHORT, 2 as *const c_void);
        assert_eq!(error(), GL_NO_ERROR);
        expect_rect([8, 8, 24, 24], [255, 0, 255, 255], "VBO indices");
        // Index reads past the element buffer's end stop the draw, no crash.
        clear();
        glDrawElements(GL_QUADS, 400, GL_UNSIGNED_SHORT, 2 as *const c_void);
        assert_eq!(error(), GL_NO_ERROR);
        // Vertex reads past the vertex buffer's end read (0,0,0,1): no crash.
        glDrawArrays(GL_POINTS, 0, 1000);
        assert_eq!(error(), GL_NO_ERROR);
        // Deleting buffers resets the bindings to them.
        glDeleteBuffers(3, bufs.as_ptr());
        assert_eq!(get_i(GL_ELEMENT_ARRAY_BUFFER_BINDING), 0);
        assert_eq!(get_i(GL_VERTEX_ARRAY_BUFFER_BINDING), 0);
        assert_eq!(get_i(GL_COLOR_ARRAY_BUFFER_BINDING), 0);
        assert_eq!(glIsBuffer(bufs[0]), 0);
        // Drawing with arrays whose buffer was deleted skips them, no crash.
        glDrawArrays(GL_QUADS, 4, 4);
        glDrawElements(GL_QUADS, 4, GL_UNSIGNED_SHORT, 2 as *const c_void);
        assert_eq!(error(), GL_NO_ERROR);
        glDeleteBuffers(-1, bufs.as_ptr());
        assert_eq!(error(), GL_INVALID_VALUE);
    }
}

#[test]
fn map_buffer_access_and_errors() {
    let _c = setup();
    unsafe {
        let mut b = 0u32;
        glGenBuffers(1, &mut b);
        // Nothing bound: INVALID_OPERATION.
        assert!(glMapBuffer(GL_ARRAY_BUFFER, GL_READ_WRITE).is_null());
        assert_eq!(error(), GL_INVALID_OPERATION);
        glBufferData(GL_ARRAY_BUFFER, 4, null(), GL_STATIC_DRAW);
        assert_eq!(error(), GL_INVALID_OPERATION);
        glBindBuffer(GL_ARRAY_BUFFER, b);
        glBindBuffer(0x1234, b);
        assert_eq!(error(), GL_INVALID_ENUM);
        let mut v = [0i32; 1];
        glGetBufferParameteriv(GL_ARRAY_BUFFER, GL_BUFFER_SIZE, v.as_mut_ptr());
        assert_eq!(v[0], 0);
        glGetBufferParameteriv(GL_ARRAY_BUFFER, GL_BUFFER_USAGE, v.as_mut_ptr());
        assert_eq!(v[0] as u32, GL_STATIC_DRAW);
        glGetBufferParameteriv(GL_ARRAY_BUFFER, GL_BUFFER_ACCESS, v.as_mut_ptr());
        assert_eq!(v[0] as u32, GL_READ_WRITE);
        glBufferData(GL_ARRAY_BUFFER, -1, null(), GL_STATIC_DRAW);
        assert_eq!(error(), GL_INVALID_VALUE);
        glBufferData(GL_ARRAY_BUFFER, 16, null(), GL_STATIC_DRAW + 3);
        assert_eq!(error(), GL_INVALID_ENUM);
        let init: Vec<u8> = (0..32).collect();
        glBufferData(GL_ARRAY_BUFFER, 32, init.as_ptr() as *const c_void, 0x88E9);
        glGetBufferParameteriv(GL_ARRAY_BUFFER, GL_BUFFER_SIZE, v.as_mut_ptr());
        assert_eq!(v[0], 32);
        // Read mapping sees the data.
        let p = glMapBuffer(GL_ARRAY_BUFFER, GL_READ_ONLY) as *const u8;
        assert!(!p.is_null());
        assert_eq!(std::slice::from_raw_parts(p, 32), &init[..]);
        glGetBufferParameteriv(GL_ARRAY_BUFFER, GL_BUFFER_MAPPED, v.as_mut_ptr());
        assert_eq!(v[0], 1);
        glGetBufferParameteriv(GL_ARRAY_BUFFER, GL_BUFFER_ACCESS, v.as_mut_ptr());
        assert_eq!(v[0] as u32, GL_READ_ONLY);
        let mut mp: *mut c_void = std::ptr::null_mut();
        glGetBufferPointerv(GL_ARRAY_BUFFER, GL_BUFFER_MAP_POINTER, &mut mp);
        assert_eq!(mp as *const u8, p);
        // Mapping twice, sub-data while mapped, drawing from it: INVALID_OPERATION.
        assert!(glMapBuffer(GL_ARRAY_BUFFER, GL_READ_ONLY).is_null());
        assert_eq!(error(), GL_INVALID_OPERATION);
        glBufferSubData(GL_ARRAY_BUFFER, 0, 4, init.as_ptr() as *const c_void);
        assert_eq!(error(), GL_INVALID_OPERATION);
        let mut out = [0u8; 4];
        glGetBufferSubData(GL_ARRAY_BUFFER, 0, 4, out.as_mut_ptr() as *mut c_void);
        assert_eq!(error(), GL_INVALID_OPERATION);
        glVertexPointer(2, GL_FLOAT, 0, null());
        glEnableClientState(GL_VERTEX_ARRAY);
        glDrawArrays(GL_POINTS, 0, 1);
        assert_eq!(error(), GL_INVALID_OPERATION);
        glArrayElement(0);
        assert_eq!(error(), GL_INVALID_OPERATION);
        assert_eq!(glUnmapBuffer(GL_ARRAY_BUFFER), 1);
        assert_eq!(glUnmapBuffer(GL_ARRAY_BUFFER), 0);
        assert_eq!(error(), GL_INVALID_OPERATION);
        glGetBufferPointerv(GL_ARRAY_BUFFER, GL_BUFFER_MAP_POINTER, &mut mp);
        assert!(mp.is_null());
        // Write mapping changes the store.
        let p = glMapBuffer(GL_ARRAY_BUFFER, GL_WRITE_ONLY) as *mut u8;
        for i in 0..32 {
            *p.add(i) = 100 + i as u8;
        }
        assert_eq!(glUnmapBuffer(GL_ARRAY_BUFFER), 1);
        let mut out = [0u8; 8];
        glGetBufferSubData(GL_ARRAY_BUFFER, 24, 8, out.as_mut_ptr() as *mut c_void);
        assert_eq!(out, [124, 125, 126, 127, 128, 129, 130, 131]);
        // Ranges.
        glGetBufferSubData(GL_ARRAY_BUFFER, 30, 4, out.as_mut_ptr() as *mut c_void);
        assert_eq!(error(), GL_INVALID_VALUE);
        glBufferSubData(GL_ARRAY_BUFFER, -1, 4, out.as_ptr() as *const c_void);
        assert_eq!(error(), GL_INVALID_VALUE);
        glBufferSubData(GL_ARRAY_BUFFER, 28, 4, out.as_ptr() as *const c_void);
        assert_eq!(error(), GL_NO_ERROR);
        // Bad access and bad pname.
        assert!(glMapBuffer(GL_ARRAY_BUFFER, GL_STATIC_DRAW).is_null());
        assert_eq!(error(), GL_INVALID_ENUM);
        glGetBufferParameteriv(GL_ARRAY_BUFFER, GL_BUFFER_MAP_POINTER, v.as_mut_ptr());
        assert_eq!(error(), GL_INVALID_ENUM);
        // BufferData on a mapped buffer unmaps it.
        glMapBuffer(GL_ARRAY_BUFFER, GL_READ_WRITE);
        glBufferData(GL_ARRAY_BUFFER, 8, null(), GL_STATIC_DRAW);
        glGetBufferParameteriv(GL_ARRAY_BUFFER, GL_BUFFER_MAPPED, v.as_mut_ptr());
        assert_eq!(v[0], 0);
        // Buffer commands between Begin and End.
        glBegin(GL_POINTS);
        glBindBuffer(GL_ARRAY_BUFFER, 0);
        glEnd();
        assert_eq!(error(), GL_INVALID_OPERATION);
        assert_eq!(get_i(GL_ARRAY_BUFFER_BINDING), b as i32);
    }
}

#[test]
fn display_lists_capture_array_data() {
    let _c = setup();
    unsafe {
        let mut verts: Vec<f32> = rect(2, 2, 10, 10).iter().flat_map(|v| [v[0] as f32, v[1] as f32]).collect();
        let mut colors: Vec<u8> = (0..4).flat_map(|_| [255u8, 0, 0, 255]).collect();
        glVertexPointer(2, GL_FLOAT, 0, verts.as_ptr() as *const c_void);
        glColorPointer(4, GL_UNSIGNED_BYTE, 0, colors.as_ptr() as *const c_void);
        glEnableClientState(GL_VERTEX_ARRAY);
        glEnableClientState(GL_COLOR_ARRAY);
        let list = glGenLists(3);
        // DrawArrays compiled (GL_COMPILE draws nothing now).
        glNewList(list, GL_COMPILE);
        glDrawArrays(GL_QUADS, 0, 4);
        glEndList();
        assert_eq!(lit_pixels(), 0, "GL_COMPILE must not draw");
        // DrawElements and ArrayElement compiled.
        let idx = [0u8, 1, 2, 3];
        glNewList(list + 1, GL_COMPILE);
        glTranslatef(12.0, 0.0, 0.0);
        glDrawElements(GL_QUADS, 4, GL_UNSIGNED_BYTE, idx.as_ptr() as *const c_void);
        glTranslatef(-12.0, 0.0, 0.0);
        glEndList();
        glNewList(list + 2, GL_COMPILE);
        glTranslatef(0.0, 12.0, 0.0);
        glBegin(GL_QUADS);
        for i in 0..4 {
            glArrayElement(i);
        }
        glEnd();
        glTranslatef(0.0, -12.0, 0.0);
        glEndList();
        assert_eq!(error(), GL_NO_ERROR);
        // Change the arrays' contents and pointers: the lists keep the old data.
        for c in colors.chunks_mut(4) {
            c.copy_from_slice(&[0, 0, 255, 255]);
        }
        for v in verts.iter_mut() {
            *v += 100.0;
        }
        let other = [0f32; 8];
        glVertexPointer(2, GL_FLOAT, 0, other.as_ptr() as *const c_void);
        glDisableClientState(GL_COLOR_ARRAY);
        glCallList(list);
        glCallList(list + 1);
        glCallList(list + 2);
        assert_eq!(error(), GL_NO_ERROR);
        assert_eq!(pixel(5, 5), [255, 0, 0, 255], "DrawArrays list");
        assert_eq!(pixel(17, 5), [255, 0, 0, 255], "DrawElements list");
        assert_eq!(pixel(5, 17), [255, 0, 0, 255], "ArrayElement list");
        assert_eq!(lit_pixels(), 3 * 64);
        // The current colour after replay is the last recorded colour.
        assert_eq!(get_f::<4>(GL_CURRENT_COLOR), [1.0, 0.0, 0.0, 1.0]);
        glDeleteLists(list, 3);

        // GL_COMPILE_AND_EXECUTE draws now and records; buffer data captured too.
        clear();
        let mut b = 0u32;
        glGenBuffers(1, &mut b);
        glBindBuffer(GL_ARRAY_BUFFER, b);
        let vb: Vec<f32> = rect(20, 20, 28, 28).iter().flat_map(|v| [v[0] as f32, v[1] as f32]).collect();
        glBufferData(GL_ARRAY_BUFFER, 32, vb.as_ptr() as *const c_void, GL_STATIC_DRAW);
        glVertexPointer(2, GL_FLOAT, 0, null());
        glColor4ub(0, 255, 0, 255);
        let l2 = glGenLists(1);
        glNewList(l2, GL_COMPILE_AND_EXECUTE);
        glDrawArrays(GL_QUADS, 0, 4);
        glEndList();
        assert_eq!(lit_pixels(), 0, "green only: red channel is 0");
        assert_eq!(pixel(24, 24), [0, 255, 0, 255]);
        let zero = [0u8; 32];
        glBufferSubData(GL_ARRAY_BUFFER, 0, 32, zero.as_ptr() as *const c_void);
        clear();
        glColor4ub(255, 255, 0, 255);
        glCallList(l2);
        assert_eq!(pixel(24, 24), [255, 255, 0, 255], "the list kept the buffer's old vertices");
        assert_eq!(lit_pixels(), 64);

        // Client-state commands inside a list execute immediately, not recorded.
        let l3 = glGenLists(1);
        glNewList(l3, GL_COMPILE);
        glDisableClientState(GL_VERTEX_ARRAY);
        glEndList();
        assert_eq!(glIsEnabled(GL_VERTEX_ARRAY), 0);
        glEnableClientState(GL_VERTEX_ARRAY);
        glCallList(l3);
        assert_eq!(glIsEnabled(GL_VERTEX_ARRAY), 1);
    }
}

#[test]
fn occlusion_queries_count_samples() {
    let _c = setup();
    unsafe {
        let mut q = [0u32; 2];
        glGenQueries(2, q.as_mut_ptr());
        assert_eq!(glIsQuery(q[0]), 0);
        let mut v = [0i32; 1];
        glGetQueryiv(GL_SAMPLES_PASSED, GL_QUERY_COUNTER_BITS, v.as_mut_ptr());
        assert!(v[0] >= 32);
        glEnable(GL_DEPTH_TEST);
        glColor4ub(255, 0, 0, 255);
        // A 10x10 square at z = 0 (window depth 0.5).
        glBeginQuery(GL_SAMPLES_PASSED, q[0]);
        assert_eq!(glIsQuery(q[0]), 1);
        glGetQueryiv(GL_SAMPLES_PASSED, GL_CURRENT_QUERY, v.as_mut_ptr());
        assert_eq!(v[0] as u32, q[0]);
        glRecti(2, 2, 12, 12);
        // Querying the active query is an error.
        glGetQueryObjectiv(q[0], GL_QUERY_RESULT, v.as_mut_ptr());
        assert_eq!(error(), GL_INVALID_OPERATION);
        glBeginQuery(GL_SAMPLES_PASSED, q[1]);
        assert_eq!(error(), GL_INVALID_OPERATION);
        glEndQuery(GL_SAMPLES_PASSED);
        glGetQueryiv(GL_SAMPLES_PASSED, GL_CURRENT_QUERY, v.as_mut_ptr());
        assert_eq!(v[0], 0);
        let mut r = 0u32;
        glGetQueryObjectuiv(q[0], GL_QUERY_RESULT_AVAILABLE, &mut r);
        assert_eq!(r, 1);
        glGetQueryObjectuiv(q[0], GL_QUERY_RESULT, &mut r);
        assert_eq!(r, 100);

        // A square behind it, overlapping 5x10 of it: only 10x10 - 50 pass.
        glBeginQuery(GL_SAMPLES_PASSED, q[1]);
        glPushMatrix();
        glTranslatef(0.0, 0.0, -0.5); // ortho looks down -z: farther
        glRecti(7, 2, 17, 12);
        glPopMatrix();
        glEndQuery(GL_SAMPLES_PASSED);
        glGetQueryObjectuiv(q[1], GL_QUERY_RESULT, &mut r);
        assert_eq!(r, 50);

        // Stencil test failing everything: nothing passes.
        glEnable(GL_STENCIL_TEST);
        glStencilFunc(GL_NEVER, 0, 0xFF);
        glBeginQuery(GL_SAMPLES_PASSED, q[0]);
        glRecti(20, 20, 30, 30);
        glEndQuery(GL_SAMPLES_PASSED);
        glGetQueryObjectuiv(q[0], GL_QUERY_RESULT, &mut r);
        assert_eq!(r, 0);
        glDisable(GL_STENCIL_TEST);

        // Nothing to test or write (colour masked, depth off): still counted.
        glDisable(GL_DEPTH_TEST);
        glColorMask(0, 0, 0, 0);
        glBeginQuery(GL_SAMPLES_PASSED, q[0]);
        glRecti(20, 20, 30, 25);
        glEndQuery(GL_SAMPLES_PASSED);
        glColorMask(1, 1, 1, 1);
        glGetQueryObjectiv(q[0], GL_QUERY_RESULT, v.as_mut_ptr());
        assert_eq!(v[0], 50);

        // Points and lines count too: 3 points.
        glBeginQuery(GL_SAMPLES_PASSED, q[0]);
        glBegin(GL_POINTS);
        glVertex2f(20.5, 5.5);
        glVertex2f(22.5, 5.5);
        glVertex2f(24.5, 5.5);
        glEnd();
        glEndQuery(GL_SAMPLES_PASSED);
        glGetQueryObjectiv(q[0], GL_QUERY_RESULT, v.as_mut_ptr());
        assert_eq!(v[0], 3);

        // Begin/EndQuery compile into lists.
        let l = glGenLists(1);
        glNewList(l, GL_COMPILE);
        glBeginQuery(GL_SAMPLES_PASSED, q[1]);
        glRecti(0, 0, 4, 4);
        glEndQuery(GL_SAMPLES_PASSED);
        glEndList();
        glGetQueryiv(GL_SAMPLES_PASSED, GL_CURRENT_QUERY, v.as_mut_ptr());
        assert_eq!(v[0], 0, "compiled BeginQuery did not run");
        glCallList(l);
        glGetQueryObjectiv(q[1], GL_QUERY_RESULT, v.as_mut_ptr());
        assert_eq!(v[0], 16);

        // Errors.
        assert_eq!(error(), GL_NO_ERROR);
        glEndQuery(GL_SAMPLES_PASSED);
        assert_eq!(error(), GL_INVALID_OPERATION);
        glBeginQuery(GL_SAMPLES_PASSED, 0);
        assert_eq!(error(), GL_INVALID_OPERATION);
        glBeginQuery(0x1234, q[0]);
        assert_eq!(error(), GL_INVALID_ENUM);
        glGetQueryiv(0x1234, GL_CURRENT_QUERY, v.as_mut_ptr());
        assert_eq!(error(), GL_INVALID_ENUM);
        glGetQueryObjectiv(q[0], 0x1234, v.as_mut_ptr());
        assert_eq!(error(), GL_INVALID_ENUM);
        glGetQueryObjectiv(9999, GL_QUERY_RESULT, v.as_mut_ptr());
        assert_eq!(error(), GL_INVALID_OPERATION);
        glGenQueries(-1, q.as_mut_ptr());
        assert_eq!(error(), GL_INVALID_VALUE);
        glBegin(GL_TRIANGLES);
        glBeginQuery(GL_SAMPLES_PASSED, q[0]);
        glEnd();
        assert_eq!(error(), GL_INVALID_OPERATION);
        glDeleteQueries(2, q.as_ptr());
        assert_eq!(glIsQuery(q[0]), 0);
        assert_eq!(error(), GL_NO_ERROR);
    }
}

#[test]
fn draw_errors() {
    let _c = setup();
    unsafe {
        let v = [0f32; 8];
        glVertexPointer(2, GL_FLOAT, 0, v.as_ptr() as *const c_void);
        glEnableClientState(GL_VERTEX_ARRAY);
        glDrawArrays(GL_TRIANGLES, 0, -1);
        assert_eq!(error(), GL_INVALID_VALUE);
        glDrawArrays(GL_POLYGON + 1, 0, 3);
        assert_eq!(error(), GL_INVALID_ENUM);
        glBegin(GL_TRIANGLES);
        glDrawArrays(GL_TRIANGLES, 0, 3);
        glEnd();
        assert_eq!(error(), GL_INVALID_OPERATION);
        glBegin(GL_TRIANGLES);
        let idx = [0u8; 3];
        glDrawElements(GL_TRIANGLES, 3, GL_UNSIGNED_BYTE, idx.as_ptr() as *const c_void);
        glEnd();
        assert_eq!(error(), GL_INVALID_OPERATION);
        // ArrayElement is allowed between Begin and End.
        glBegin(GL_TRIANGLES);
        glArrayElement(0);
        glEnd();
        assert_eq!(error(), GL_NO_ERROR);
        glArrayElement(-1);
        assert_eq!(error(), GL_INVALID_VALUE);
        // Pointer errors change nothing.
        glVertexPointer(1, GL_FLOAT, 0, null());
        assert_eq!(error(), GL_INVALID_VALUE);
        glVertexPointer(2, GL_UNSIGNED_BYTE, 0, null());
        assert_eq!(error(), GL_INVALID_ENUM);
        glVertexPointer(2, GL_FLOAT, -4, null());
        assert_eq!(error(), GL_INVALID_VALUE);
        glColorPointer(2, GL_FLOAT, 0, null());
        assert_eq!(error(), GL_INVALID_VALUE);
        glNormalPointer(GL_UNSIGNED_BYTE, 0, null());
        assert_eq!(error(), GL_INVALID_ENUM);
        glTexCoordPointer(5, GL_FLOAT, 0, null());
        assert_eq!(error(), GL_INVALID_VALUE);
        glTexCoordPointer(2, GL_BYTE, 0, null());
        assert_eq!(error(), GL_INVALID_ENUM);
        glIndexPointer(GL_BYTE, 0, null());
        assert_eq!(error(), GL_INVALID_ENUM);
        glFogCoordPointer(GL_INT, 0, null());
        assert_eq!(error(), GL_INVALID_ENUM);
        glSecondaryColorPointer(4, GL_FLOAT, 0, null());
        assert_eq!(error(), GL_INVALID_VALUE);
        glEdgeFlagPointer(-1, null());
        assert_eq!(error(), GL_INVALID_VALUE);
        let mut p: *mut c_void = std::ptr::null_mut();
        glGetPointerv(0x808E, &mut p);
        assert_eq!(p as *const f32, v.as_ptr());
        assert_eq!(get_i(0x807A), 2);
        assert_eq!(get_i(0x807B) as u32, GL_FLOAT);
        // Client-state enums.
        glEnableClientState(GL_LIGHTING);
        assert_eq!(error(), GL_INVALID_ENUM);
        // glEnable of an array capability is glEnableClientState (EXT_vertex_array's legacy).
        let was = glIsEnabled(GL_VERTEX_ARRAY);
        glEnable(GL_VERTEX_ARRAY);
        assert_eq!((error(), glIsEnabled(GL_VERTEX_ARRAY)), (GL_NO_ERROR, 1));
        if was == 0 {
            glDisable(GL_VERTEX_ARRAY);
        }
        glClientActiveTexture(GL_TEXTURE0 + 32);
        assert_eq!(error(), GL_INVALID_ENUM);
        glGetPointerv(0x1234, &mut p);
        assert_eq!(error(), GL_INVALID_ENUM);
        // A NULL client array is skipped, not read.
        glVertexPointer(2, GL_FLOAT, 0, null());
        glDrawArrays(GL_TRIANGLES, 0, 3);
        assert_eq!(error(), GL_NO_ERROR);
    }
}

#[test]
fn array_state_queries() {
    let _c = setup();
    unsafe {
        // Initial values (tables 6.6 to 6.8).
        for (pname, want) in [
            (0x807A, 4), (0x807B, GL_FLOAT as i32), (0x807C, 0),
            (0x807E, GL_FLOAT as i32), (0x807F, 0),
            (0x8081, 4), (0x8082, GL_FLOAT as i32), (0x8083, 0),
            (0x8085, GL_FLOAT as i32), (0x8086, 0),
            (0x8088, 4), (0x8089, GL_FLOAT as i32), (0x808A, 0),
            (0x808C, 0),
            (0x8454, GL_FLOAT as i32), (0x8455, 0),
            (0x845A, 3), (0x845B, GL_FLOAT as i32), (0x845C, 0),
            (GL_CLIENT_ACTIVE_TEXTURE, GL_TEXTURE0 as i32),
            (GL_ARRAY_BUFFER_BINDING, 0), (GL_ELEMENT_ARRAY_BUFFER_BINDING, 0),
            (GL_EDGE_FLAG, 1), (GL_CURRENT_INDEX, 1),
        ] {
            assert_eq!(get_i(pname), want, "initial value of {pname:#x}");
        }
        for cap in [GL_VERTEX_ARRAY, GL_NORMAL_ARRAY, GL_COLOR_ARRAY, GL_INDEX_ARRAY, GL_TEXTURE_COORD_ARRAY, GL_EDGE_FLAG_ARRAY, GL_FOG_COORD_ARRAY, GL_SECONDARY_COLOR_ARRAY] {
            assert_eq!(glIsEnabled(cap), 0);
            glEnableClientState(cap);
            assert_eq!(glIsEnabled(cap), 1);
            let mut b = 0u8;
            glGetBooleanv(cap, &mut b);
            assert_eq!(b, 1);
        }
        assert_eq!(get_f::<4>(GL_CURRENT_SECONDARY_COLOR), [0.0, 0.0, 0.0, 1.0]);
        assert_eq!(error(), GL_NO_ERROR);
        // Texture coordinate arrays are per client unit.
        let data = [0u8; 4];
        glClientActiveTexture(GL_TEXTURE0 + 2);
        assert_eq!(glIsEnabled(GL_TEXTURE_COORD_ARRAY), 0);
        glTexCoordPointer(3, GL_SHORT, 12, data.as_ptr() as *const c_void);
        assert_eq!(get_i(0x8088), 3);
        assert_eq!(get_i(0x8089) as u32, GL_SHORT);
        assert_eq!(get_i(0x808A), 12);
        assert_eq!(get_i(GL_CLIENT_ACTIVE_TEXTURE) as u32, GL_TEXTURE0 + 2);
        let mut p: *mut c_void = std::ptr::null_mut();
        glGetPointerv(0x8092, &mut p);
        assert_eq!(p as *const u8, data.as_ptr());
        glClientActiveTexture(GL_TEXTURE0);
        assert_eq!(get_i(0x8088), 4);
        glGetPointerv(0x8092, &mut p);
        assert!(p.is_null());
        // Every pointer query.
        for (set, pname) in [
            (0usize, 0x808Eu32), (1, 0x808F), (2, 0x8090), (3, 0x8091), (4, 0x8093), (5, 0x8456), (6, 0x845D),
        ] {
            let ptr = data.as_ptr().wrapping_add(set) as *const c_void;
            match set {
                0 => glVertexPointer(2, GL_FLOAT, 0, ptr),
                1 => glNormalPointer(GL_FLOAT, 0, ptr),
                2 => glColorPointer(4, GL_FLOAT, 0, ptr),
                3 => glIndexPointer(GL_FLOAT, 0, ptr),
                4 => glEdgeFlagPointer(0, ptr),
                5 => glFogCoordPointer(GL_FLOAT, 0, ptr),
                _ => glSecondaryColorPointer(3, GL_FLOAT, 0, ptr),
            }
            glGetPointerv(pname, &mut p);
            assert_eq!(p as *const c_void, ptr, "pointer {pname:#x}");
        }
        assert_eq!(error(), GL_NO_ERROR);
    }
}

#[test]
fn push_pop_client_vertex_array_state() {
    let _c = setup();
    unsafe {
        let a = [0f32; 8];
        let mut b = 0u32;
        glGenBuffers(1, &mut b);
        glVertexPointer(3, GL_SHORT, 8, a.as_ptr() as *const c_void);
        glEnableClientState(GL_VERTEX_ARRAY);
        glClientActiveTexture(GL_TEXTURE0 + 1);
        glPushClientAttrib(0x2);
        glDisableClientState(GL_VERTEX_ARRAY);
        glVertexPointer(2, GL_FLOAT, 0, null());
        glClientActiveTexture(GL_TEXTURE0);
        glBindBuffer(GL_ARRAY_BUFFER, b);
        glPopClientAttrib();
        assert_eq!(error(), GL_NO_ERROR);
        assert_eq!(glIsEnabled(GL_VERTEX_ARRAY), 1);
        assert_eq!(get_i(0x807A), 3);
        assert_eq!(get_i(0x807C), 8);
        let mut p: *mut c_void = std::ptr::null_mut();
        glGetPointerv(0x808E, &mut p);
        assert_eq!(p as *const f32, a.as_ptr());
        assert_eq!(get_i(GL_CLIENT_ACTIVE_TEXTURE) as u32, GL_TEXTURE0 + 1);
        assert_eq!(get_i(GL_ARRAY_BUFFER_BINDING), 0);
        // The pixel-store bit alone leaves arrays alone.
        glPushClientAttrib(0x1);
        glDisableClientState(GL_VERTEX_ARRAY);
        glPopClientAttrib();
        assert_eq!(glIsEnabled(GL_VERTEX_ARRAY), 0);
    }
}

/// The immediate-mode attributes this work stores: current values, and
/// recorded in lists.
#[test]
fn immediate_edge_flag_index_fog_secondary() {
    let _c = setup();
    unsafe {
        glEdgeFlag(0);
        assert_eq!(get_i(GL_EDGE_FLAG), 0);
        let t = 0xFFu8;
        glEdgeFlagv(&t);
        assert_eq!(get_i(GL_EDGE_FLAG), 1);
        glIndexi(7);
        assert_eq!(get_i(GL_CURRENT_INDEX), 7);
        glIndexub(200);
        assert_eq!(get_f::<1>(GL_CURRENT_INDEX), [200.0]);
        let d = 2.5f64;
        glIndexdv(&d);
        assert_eq!(get_f::<1>(GL_CURRENT_INDEX), [2.5]);
        glFogCoordf(3.0);
        assert_eq!(get_f::<1>(GL_CURRENT_FOG_COORD), [3.0]);
        glFogCoordd(-1.0);
        assert_eq!(get_f::<1>(GL_CURRENT_FOG_COORD), [-1.0]);
        glSecondaryColor3ub(255, 0, 51);
        assert_eq!(get_f::<4>(GL_CURRENT_SECONDARY_COLOR), [1.0, 0.0, 0.2, 1.0]);
        glSecondaryColor3f(0.5, 0.25, 0.125);
        assert_eq!(get_f::<4>(GL_CURRENT_SECONDARY_COLOR), [0.5, 0.25, 0.125, 1.0]);
        // Allowed between Begin and End.
        glBegin(GL_POINTS);
        glEdgeFlag(1);
        glIndexf(1.0);
        glFogCoordf(0.0);
        glSecondaryColor3s(0, 0, 0);
        glEnd();
        assert_eq!(error(), GL_NO_ERROR);
        // Compiled into lists.
        let l = glGenLists(1);
        glNewList(l, GL_COMPILE);
        glEdgeFlag(0);
        glIndexs(42);
        glFogCoordf(9.0);
        glSecondaryColor3ub(0, 255, 0);
        glEndList();
        assert_eq!(get_i(GL_EDGE_FLAG), 1);
        glCallList(l);
        assert_eq!(get_i(GL_EDGE_FLAG), 0);
        assert_eq!(get_i(GL_CURRENT_INDEX), 42);
        assert_eq!(get_f::<1>(GL_CURRENT_FOG_COORD), [9.0]);
        assert_eq!(get_f::<4>(GL_CURRENT_SECONDARY_COLOR), [0.0, 1.0, 0.0, 1.0]);
        assert_eq!(error(), GL_NO_ERROR);
    }
}

/// glArrayElement between Begin and End draws what immediate mode draws,
/// with per-vertex colours (smooth shading).
#[test]
fn array_element_matches_immediate_mode() {
    let _c = setup();
    let verts: [f32; 6] = [1.0, 1.0, 31.0, 3.0, 12.0, 30.0];
    let colors: [f32; 9] = [1.0, 0.0, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0, 1.0];
    let mut a = vec![0u8; (W * H * 4) as usize];
    let mut b = a.clone();
    unsafe {
        glBegin(GL_TRIANGLES);
        for i in 0..3 {
            glColor3fv(colors[3 * i..].as_ptr());
            glVertex2fv(verts[2 * i..].as_ptr());
        }
        glEnd();
        glReadPixels(0, 0, W, H, GL_RGBA, GL_UNSIGNED_BYTE, a.as_mut_ptr() as *mut c_void);
        clear();
        glVertexPointer(2, GL_FLOAT, 0, verts.as_ptr() as *const c_void);
        glColorPointer(3, GL_FLOAT, 0, colors.as_ptr() as *const c_void);
        glEnableClientState(GL_VERTEX_ARRAY);
        glEnableClientState(GL_COLOR_ARRAY);
        glBegin(GL_TRIANGLES);
        for i in 0..3 {
            glArrayElement(i);
        }
        glEnd();
        glReadPixels(0, 0, W, H, GL_RGBA, GL_UNSIGNED_BYTE, b.as_mut_ptr() as *mut c_void);
        assert!(a == b, "ArrayElement differs from immediate mode");
        clear();
        glDrawArrays(GL_TRIANGLES, 0, 3);
        glReadPixels(0, 0, W, H, GL_RGBA, GL_UNSIGNED_BYTE, b.as_mut_ptr() as *mut c_void);
        assert!(a == b, "DrawArrays differs from immediate mode");
        assert!(a.chunks(4).filter(|p| p[3] != 0).count() > 300);
    }
}

/// glEnable(GL_VERTEX_ARRAY) and the other array capabilities act as
/// glEnableClientState (EXT_vertex_array's legacy, which programs use);
/// a draw leaves the current values as they were before it.
#[test]
fn enable_of_array_caps_and_draws_keep_current_values() {
    let _c = setup();
    unsafe {
        let v = rect(4, 4, 12, 12);
        let red = [[255u8, 0, 0, 255]; 4];
        glVertexPointer(2, GL_INT, 0, v.as_ptr() as *const c_void);
        glColorPointer(4, GL_UNSIGNED_BYTE, 0, red.as_ptr() as *const c_void);
        glEnable(GL_VERTEX_ARRAY);
        glEnable(GL_COLOR_ARRAY);
        assert_eq!(error(), GL_NO_ERROR);
        assert_eq!(glIsEnabled(GL_VERTEX_ARRAY), 1);
        glColor4f(0.0, 1.0, 0.0, 1.0);
        glDrawArrays(GL_QUADS, 0, 4);
        assert_eq!(pixel(8, 8), [255, 0, 0, 255]);
        assert_eq!(get_f::<4>(GL_CURRENT_COLOR), [0.0, 1.0, 0.0, 1.0]);
        glDisable(GL_COLOR_ARRAY);
        glDisable(GL_VERTEX_ARRAY);
        assert_eq!(glIsEnabled(GL_VERTEX_ARRAY), 0);
        assert_eq!(glIsEnabled(GL_COLOR_ARRAY), 0);
        // glArrayElement does set the current values (it is glColor + glVertex).
        glEnableClientState(GL_COLOR_ARRAY);
        glArrayElement(0);
        assert_eq!(get_f::<4>(GL_CURRENT_COLOR), [1.0, 0.0, 0.0, 1.0]);
        glDisableClientState(GL_COLOR_ARRAY);
    }
    assert_eq!(error(), GL_NO_ERROR);
}

/// A draw compiled into a list is illegal as a whole when the list is
/// called between Begin and End (2.6.3): INVALID_OPERATION and nothing of
/// it drawn, while the list's own vertices still join the open primitive.
#[test]
fn compiled_draw_inside_begin_end_is_skipped() {
    let _c = setup();
    unsafe {
        let v = rect(16, 16, 30, 30);
        glVertexPointer(2, GL_INT, 0, v.as_ptr() as *const c_void);
        glEnableClientState(GL_VERTEX_ARRAY);
        glNewList(5, GL_COMPILE);
        glColor4f(0.0, 1.0, 0.0, 1.0);
        glVertex2f(2.0, 2.0);
        glVertex2f(10.0, 2.0);
        glVertex2f(10.0, 10.0);
        glVertex2f(2.0, 10.0);
        glColor4f(1.0, 0.0, 0.0, 1.0);
        glDrawArrays(GL_QUADS, 0, 4);
        glEndList();
        glDisableClientState(GL_VERTEX_ARRAY);
        assert_eq!(error(), GL_NO_ERROR);
        glBegin(GL_QUADS);
        glCallList(5);
        glEnd();
        assert_eq!(error(), GL_INVALID_OPERATION);
        assert_eq!(pixel(6, 6), [0, 255, 0, 255], "the list's own quad is drawn");
        assert_eq!(pixel(20, 20), [0, 0, 0, 0], "the draw is not");
        assert_eq!(error(), GL_NO_ERROR);
        // Called outside Begin/End the draw happens.
        glCallList(5);
        assert_eq!(pixel(20, 20), [255, 0, 0, 255]);
    }
    assert_eq!(error(), GL_NO_ERROR);
}

/// A list replays every compact command form exactly: the current values
/// after calling it equal those after the same calls made directly.
#[test]
fn compact_list_forms_replay_exactly() {
    let _c = setup();
    let calls = || unsafe {
        glBegin(GL_POINTS);
        glColor4f(0.25, 0.5, 0.75, 0.125);
        glVertex2f(1.5, 2.5);
        glColor3f(0.5, 0.25, 1.0);
        glNormal3f(0.0, -1.0, 0.5);
        glTexCoord4f(1.0, 2.0, 3.0, 4.0);
        glMultiTexCoord4f(GL_TEXTURE0 + 2, 0.5, -0.5, 0.0, 1.0);
        glSecondaryColor3f(0.1, 0.2, 0.3);
        glFogCoordf(3.5);
        glEdgeFlag(0);
        glVertex3f(1.0, 2.0, -0.0);
        glVertex4f(1.0, 2.0, 3.0, 2.0);
        glEnd();
    };
    calls();
    let direct = current().current;
    unsafe {
        glColor4f(1.0, 1.0, 1.0, 1.0);
        glNormal3f(0.0, 0.0, 1.0);
        glTexCoord4f(0.0, 0.0, 0.0, 1.0);
        glMultiTexCoord4f(GL_TEXTURE0 + 2, 0.0, 0.0, 0.0, 1.0);
        glEdgeFlag(1);
        glNewList(6, GL_COMPILE);
    }
    calls();
    unsafe {
        glEndList();
        glCallList(6);
    }
    let replayed = current().current;
    assert_eq!(format!("{direct:?}"), format!("{replayed:?}"));
    assert_eq!(replayed.tex_coords[2], [0.5, -0.5, 0.0, 1.0]);
    assert_eq!(error(), GL_NO_ERROR);
}

/// Compiled vertex commands take a few words each (issue 9): 100,000
/// glColor3f + glVertex3f pairs in well under 40 bytes a pair.
#[test]
fn compiled_vertices_are_compact() {
    let _c = setup();
    unsafe {
        glNewList(7, GL_COMPILE);
        glBegin(GL_TRIANGLES);
        for i in 0..100_000 {
            glColor3f((i % 7) as f32 / 7.0, 0.5, 0.25);
            glVertex3f(i as f32, 1.0, 2.0);
        }
        glEnd();
        glEndList();
    }
    let bytes = current().lists.get(7).unwrap().bytes();
    // Colour: 4 words; vertex: 4 words.
    assert!(bytes <= 100_000 * 32 + 64, "{bytes} bytes");
    assert_eq!(error(), GL_NO_ERROR);
}

/// glMaterial of a property GL_COLOR_MATERIAL tracks is overridden by the
/// current colour at once (piglit dlist-color-material).
#[test]
fn tracked_material_follows_the_current_colour() {
    let _c = setup();
    unsafe {
        glColorMaterial(GL_FRONT_AND_BACK, GL_DIFFUSE);
        glEnable(GL_COLOR_MATERIAL);
        glColor4f(0.0, 1.0, 0.0, 1.0);
        let red = [1.0f32, 0.0, 0.0, 1.0];
        glMaterialfv(GL_FRONT_AND_BACK, GL_DIFFUSE, red.as_ptr());
        glMaterialfv(GL_FRONT_AND_BACK, GL_SPECULAR, red.as_ptr());
        let mut m = [0f32; 4];
        glGetMaterialfv(GL_FRONT, GL_DIFFUSE, m.as_mut_ptr());
        assert_eq!(m, [0.0, 1.0, 0.0, 1.0]);
        glGetMaterialfv(GL_BACK, GL_SPECULAR, m.as_mut_ptr());
        assert_eq!(m, red, "untracked properties take glMaterial");
        glDisable(GL_COLOR_MATERIAL);
    }
    assert_eq!(error(), GL_NO_ERROR);
}

/// GL_EXT_vertex_array: the pointer calls with their element count set the
/// same arrays as the core calls (a negative count is INVALID_VALUE and
/// changes nothing), glDrawArraysEXT draws, glGetPointervEXT reads back.
#[test]
fn ext_vertex_array_entry_points() {
    let _c = setup();
    let verts: [f32; 8] = [4.0, 4.0, 12.0, 4.0, 12.0, 12.0, 4.0, 12.0];
    let colors: [u8; 16] = [0, 255, 0, 255, 0, 255, 0, 255, 0, 255, 0, 255, 0, 255, 0, 255];
    let ext = unsafe { std::str::from_utf8(std::ffi::CStr::from_ptr(glGetString(GL_EXTENSIONS) as *const _).to_bytes()).unwrap().to_owned() };
    assert!(ext.split(' ').any(|e| e == "GL_EXT_vertex_array"));
    unsafe {
        glVertexPointerEXT(2, GL_FLOAT, 0, -1, verts.as_ptr() as *const c_void);
        assert_eq!(error(), GL_INVALID_VALUE);
        let mut p: *mut c_void = std::ptr::null_mut();
        glGetPointervEXT(GL_VERTEX_ARRAY_POINTER, &mut p);
        assert!(p.is_null(), "a negative count changes nothing");
        glVertexPointerEXT(2, GL_FLOAT, 0, 4, verts.as_ptr() as *const c_void);
        glColorPointerEXT(4, GL_UNSIGNED_BYTE, 0, 4, colors.as_ptr() as *const c_void);
        glEnableClientState(GL_VERTEX_ARRAY);
        glEnableClientState(GL_COLOR_ARRAY);
        glGetPointervEXT(GL_VERTEX_ARRAY_POINTER, &mut p);
        assert_eq!(p as *const f32, verts.as_ptr());
        glDrawArraysEXT(GL_QUADS, 0, 4);
        assert_eq!(error(), GL_NO_ERROR);
    }
    assert_eq!(pixel(8, 8), [0, 255, 0, 255]);
    assert_eq!(pixel(2, 2), [0, 0, 0, 0]);
}

/// GL_SELECTION_BUFFER_POINTER and GL_FEEDBACK_BUFFER_POINTER return the
/// buffers given to glSelectBuffer and glFeedbackBuffer; the _SIZE names
/// (and GL_FEEDBACK_BUFFER_TYPE) their sizes and type (GL 1.5 table 6.31).
#[test]
fn selection_and_feedback_buffer_pointers() {
    let _c = setup();
    let mut sel = [0u32; 16];
    let mut fb = [0f32; 16];
    unsafe {
        let mut p: *mut c_void = std::ptr::dangling_mut::<c_void>();
        glGetPointerv(GL_SELECTION_BUFFER_POINTER, &mut p);
        assert!(p.is_null());
        assert_eq!([get_i(GL_SELECTION_BUFFER_SIZE), get_i(GL_FEEDBACK_BUFFER_SIZE), get_i(GL_FEEDBACK_BUFFER_TYPE)], [0, 0, GL_2D as i32]);
        glSelectBuffer(13, sel.as_mut_ptr());
        glFeedbackBuffer(11, GL_3D, fb.as_mut_ptr());
        assert_eq!([get_i(GL_SELECTION_BUFFER_SIZE), get_i(GL_FEEDBACK_BUFFER_SIZE), get_i(GL_FEEDBACK_BUFFER_TYPE)], [13, 11, GL_3D as i32]);
        assert_eq!(get_i(GL_INDEX_BITS), 0, "RGBA visuals have no index bits");
        glGetPointerv(GL_SELECTION_BUFFER_POINTER, &mut p);
        assert_eq!(p as *mut u32, sel.as_mut_ptr());
        glGetPointerv(GL_FEEDBACK_BUFFER_POINTER, &mut p);
        assert_eq!(p as *mut f32, fb.as_mut_ptr());
        assert_eq!(error(), GL_NO_ERROR);
    }
}
