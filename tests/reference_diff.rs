//! Differential test of the fast triangle path against the reference path
//! (issue 3 item 6, DESIGN.md "State, validation, specialization"): random
//! triangles (small, large, huge, off-screen, perspective) under random
//! state (shading, depth func and mask, stencil func/ops/masks, alpha test,
//! blending, logic op, colour mask, fog and its hint, texturing, polygon
//! stipple, scissor, culling, depth range, perspective hint) are drawn into
//! identical random framebuffers by two contexts, one forced onto the
//! reference path. Colour, depth, stencil and the occlusion count must be
//! identical: the fast path is exact under every hint (fast.rs says why),
//! so no tolerance is needed.

#![allow(non_snake_case)]
use softgl::framebuffer::Config;
use softgl::gl::enums::*;
use softgl::gl::fog::{GL_FOG_COLOR, GL_FOG_DENSITY, GL_FOG_END, GL_FOG_MODE, GL_FOG_START};
use softgl::gl::texture::enums as t;
use t::{GL_LINEAR, GL_NEAREST};
use softgl::gl::{Command, Context};


struct Rng(u64);

impl Rng {
    fn next(&mut self) -> u64 {
        self.0 = self.0.wrapping_mul(6364136223846793005).wrapping_add(1442695040888963407);
        self.0 >> 33
    }
    fn below(&mut self, n: u64) -> u64 {
        self.next() % n
    }
    fn chance(&mut self, percent: u64) -> bool {
        self.below(100) < percent
    }
    fn unit(&mut self) -> f32 {
        self.next() as f32 / (1u64 << 31) as f32
    }
    fn range(&mut self, lo: f32, hi: f32) -> f32 {
        lo + (hi - lo) * self.unit()
    }
    fn pick<T: Copy>(&mut self, v: &[T]) -> T {
        v[self.below(v.len() as u64) as usize]
    }
}

fn context(reference: bool, (W, H): (usize, usize), threads: usize) -> Context {
    let mut c = Context::new(Config { depth_bits: 24, stencil_bits: 8, accum_bits: 0 });
    c.fb.resize(W, H).unwrap();
    c.surface_resized(W as i32, H as i32);
    c.derived.render.reference = reference;
    c.derived.render.threads = threads;
    // Binned triangles pending across draw calls, as in a window-system
    // context (the comparison shades them first, as a readback does).
    c.defer_render = threads > 1;
    c
}

const FUNCS: [u32; 8] = [GL_NEVER, GL_LESS, GL_EQUAL, GL_LEQUAL, GL_GREATER, GL_NOTEQUAL, GL_GEQUAL, GL_ALWAYS];
const STENCIL_OPS: [u32; 8] = [GL_KEEP, GL_ZERO, GL_REPLACE, GL_INCR, GL_DECR, GL_INVERT, 0x8507, 0x8508];
const FACTORS: [u32; 15] = [
    GL_ZERO,
    GL_ONE,
    GL_SRC_COLOR,
    GL_ONE_MINUS_SRC_COLOR,
    GL_SRC_ALPHA,
    GL_ONE_MINUS_SRC_ALPHA,
    GL_DST_ALPHA,
    GL_ONE_MINUS_DST_ALPHA,
    GL_DST_COLOR,
    GL_ONE_MINUS_DST_COLOR,
    GL_SRC_ALPHA_SATURATE,
    0x8001,
    0x8002,
    0x8003,
    0x8004,
];

/// The commands of one random case: state, then a few triangles.
fn case(r: &mut Rng, tex: u32, (W, H): (usize, usize)) -> Vec<Command> {
    let mut v = Vec::new();
    let en = |v: &mut Vec<Command>, cap: u32, on: bool| v.push(if on { Command::Enable(cap) } else { Command::Disable(cap) });
    v.push(Command::ShadeModel(if r.chance(30) { GL_FLAT } else { GL_SMOOTH }));
    v.push(Command::Hint(GL_PERSPECTIVE_CORRECTION_HINT, r.pick(&[GL_NICEST, GL_FASTEST, GL_DONT_CARE])));
    v.push(Command::Hint(GL_FOG_HINT, r.pick(&[GL_NICEST, GL_FASTEST, GL_DONT_CARE])));
    // Depth.
    en(&mut v, GL_DEPTH_TEST, r.chance(70));
    v.push(Command::DepthFunc(if r.chance(60) { r.pick(&[GL_LESS, GL_LEQUAL]) } else { r.pick(&FUNCS) }));
    v.push(Command::DepthMask(r.chance(80)));
    if r.chance(20) {
        v.push(Command::DepthRange(r.unit() as f64, r.unit() as f64));
    }
    // Stencil.
    en(&mut v, GL_STENCIL_TEST, r.chance(30));
    v.push(Command::StencilFunc(r.pick(&FUNCS), r.below(300) as i32 - 20, if r.chance(50) { 0xFF } else { r.below(256) as u32 }));
    v.push(Command::StencilOp(r.pick(&STENCIL_OPS), r.pick(&STENCIL_OPS), r.pick(&STENCIL_OPS)));
    v.push(Command::StencilMask(if r.chance(60) { 0xFF } else { r.below(256) as u32 }));
    // Alpha test.
    en(&mut v, GL_ALPHA_TEST, r.chance(20));
    v.push(Command::AlphaFunc(r.pick(&FUNCS), r.unit()));
    // Blending: the two common blends often, anything sometimes.
    en(&mut v, GL_BLEND, r.chance(50));
    let f = match r.below(4) {
        0 => [GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA, GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA],
        1 => [GL_SRC_ALPHA, GL_ONE, GL_SRC_ALPHA, GL_ONE],
        _ => {
            let src = r.pick(&FACTORS);
            let dst = r.pick(&FACTORS[..10]);
            if r.chance(50) {
                [src, dst, src, dst]
            } else {
                [src, dst, r.pick(&FACTORS), r.pick(&FACTORS[..10])]
            }
        }
    };
    v.push(Command::BlendFunc(f));
    v.push(Command::BlendEquation(if r.chance(70) { 0x8006 } else { r.pick(&[0x8006, 0x800A, 0x800B, 0x8007, 0x8008]) }));
    v.push(Command::BlendColor([r.unit(), r.unit(), r.unit(), r.unit()]));
    // Logic op.
    en(&mut v, GL_COLOR_LOGIC_OP, r.chance(10));
    v.push(Command::LogicOp(GL_CLEAR + r.below(16) as u32));
    v.push(Command::ColorMask(if r.chance(80) { [true; 4] } else { [r.chance(50), r.chance(50), r.chance(50), r.chance(50)] }));
    // Fog.
    en(&mut v, GL_FOG, r.chance(20));
    v.push(Command::Fog(GL_FOG_MODE, [r.pick(&[0x0800u32, 0x0801, 0x2601]) as f32, 0.0, 0.0, 0.0]));
    v.push(Command::Fog(GL_FOG_DENSITY, [r.range(0.0, 2.0), 0.0, 0.0, 0.0]));
    v.push(Command::Fog(GL_FOG_START, [r.range(-1.0, 1.0), 0.0, 0.0, 0.0]));
    v.push(Command::Fog(GL_FOG_END, [r.range(0.0, 5.0), 0.0, 0.0, 0.0]));
    v.push(Command::Fog(GL_FOG_COLOR, [r.unit(), r.unit(), r.unit(), r.unit()]));
    // Texturing.
    let textured = r.chance(20);
    en(&mut v, t::GL_TEXTURE_2D, textured);
    v.push(Command::BindTexture(t::GL_TEXTURE_2D, tex));
    v.push(Command::TexParameter(t::GL_TEXTURE_2D, t::GL_TEXTURE_MIN_FILTER, [r.pick(&[GL_NEAREST, GL_LINEAR]) as f32, 0.0, 0.0, 0.0]));
    v.push(Command::TexParameter(t::GL_TEXTURE_2D, t::GL_TEXTURE_MAG_FILTER, [r.pick(&[GL_NEAREST, GL_LINEAR]) as f32, 0.0, 0.0, 0.0]));
    // Polygon stipple, scissor, culling.
    en(&mut v, GL_POLYGON_STIPPLE, r.chance(10));
    let mut pattern = Box::new([0u32; 32]);
    for row in pattern.iter_mut() {
        *row = r.next() as u32 ^ (r.next() as u32) << 16;
    }
    v.push(Command::PolygonStipple(pattern));
    en(&mut v, GL_SCISSOR_TEST, r.chance(20));
    v.push(Command::Scissor(r.below(W as u64) as i32 - 5, r.below(H as u64) as i32 - 5, r.below(W as u64) as i32, r.below(H as u64) as i32));
    en(&mut v, GL_CULL_FACE, r.chance(15));
    v.push(Command::CullFace(r.pick(&[GL_FRONT, GL_BACK])));
    // Projection: identity (w = 1, affine) or a frustum (perspective).
    v.push(Command::MatrixMode(GL_PROJECTION));
    v.push(Command::LoadIdentity);
    let perspective = r.chance(50);
    if perspective {
        v.push(Command::Frustum([-1.0, 1.0, -1.0, 1.0, 1.0, 10.0]));
    }
    v.push(Command::MatrixMode(GL_MODELVIEW));
    v.push(Command::LoadIdentity);
    // Triangles.
    let n = 1 + r.below(4);
    let first = v.len();
    v.push(Command::Begin(GL_TRIANGLES));
    for _ in 0..n {
        let scale = match r.below(10) {
            0 => 1000.0, // huge: clipped, guard band
            1 => 3.0,    // mostly off-screen
            2 => 0.05,   // tiny
            _ => 1.2,
        };
        for _ in 0..3 {
            v.push(Command::Color([r.unit(), r.unit(), r.unit(), r.unit()]));
            v.push(Command::TexCoord(t::GL_TEXTURE0, [r.range(-1.0, 2.0), r.range(-1.0, 2.0), 0.0, 1.0]));
            let (x, y) = (r.range(-scale, scale), r.range(-scale, scale));
            if perspective {
                let z = r.range(-9.0, -1.2);
                v.push(Command::Vertex([x * -z, y * -z, z, 1.0]));
            } else {
                v.push(Command::Vertex([x, y, r.range(-1.2, 1.2), 1.0]));
            }
        }
    }
    v.push(Command::End);
    if r.chance(30) {
        // A second pass over the same geometry (equal depths: LEQUAL,
        // EQUAL, LESS decide differently), as multipass algorithms do.
        let again = v[first..].to_vec();
        v.push(Command::DepthFunc(r.pick(&[GL_LEQUAL, GL_EQUAL, GL_LESS, GL_GEQUAL])));
        v.extend(again);
    }
    v
}

/// A small random texture, in both contexts.
fn texture(c: &mut Context, r: &mut Rng) -> u32 {
    let data: Vec<u8> = (0..8 * 8 * 4).map(|_| r.below(256) as u8).collect();
    c.submit(Command::BindTexture(t::GL_TEXTURE_2D, 1));
    let cmd = unsafe { c.tex_image_command(2, t::GL_TEXTURE_2D, 0, t::GL_RGBA as i32, [8, 8, 1], 0, t::GL_RGBA, t::GL_UNSIGNED_BYTE, data.as_ptr()) };
    c.submit(cmd.expect("a valid glTexImage2D"));
    1
}

/// Renders `cases` random cases through both paths and returns the first
/// difference, if any.
fn compare(seed: u64, cases: usize, size: (usize, usize), threads: usize, approximated: &mut usize) -> Result<(), String> {
    let (W, H) = size;
    let mut r = Rng(seed);
    let (mut fast, mut reference) = (context(false, size, threads), context(true, size, 1));
    let mut tr = Rng(seed ^ 0x5eed);
    let tex = texture(&mut fast, &mut tr);
    let mut tr = Rng(seed ^ 0x5eed);
    texture(&mut reference, &mut tr);
    for n in 0..cases {
        // The same random buffers in both.
        let color: Vec<[u8; 4]> = (0..W * H).map(|_| (r.next() as u32).to_ne_bytes()).collect();
        let depth: Vec<u32> = (0..W * H).map(|_| if r.chance(50) { 0xFF_FFFF } else { r.next() as u32 & 0xFF_FFFF }).collect();
        let stencil: Vec<u8> = (0..W * H).map(|_| r.below(4) as u8 * if r.chance(50) { 1 } else { 85 }).collect();
        let cmds = case(&mut r, tex, size);
        for c in [&mut fast, &mut reference] {
            c.fb.color.copy_from_slice(&color);
            c.fb.depth.copy_from_slice(&depth);
            c.fb.stencil.copy_from_slice(&stencil);
            for cmd in &cmds {
                c.execute(cmd);
            }
            // What a readback does first: shade the binned triangles.
            c.sync_render();
        }
        assert!(reference.derived.render.reference && !fast.derived.render.reference);
        // Under GL_NICEST exact; otherwise colour may be 1/255 off (the
        // fixed-point stepped colour of fast.rs).
        let nicest = cmds.contains(&Command::Hint(GL_PERSPECTIVE_CORRECTION_HINT, GL_NICEST));
        let tolerance = if nicest { 0 } else { 1 };
        for i in 0..W * H {
            let (a, b) = (fast.fb.color[i], reference.fb.color[i]);
            let off = (0..4).map(|ch| a[ch].abs_diff(b[ch])).max().unwrap();
            if off > 0 {
                *approximated += 1;
            }
            if off > tolerance || fast.fb.depth[i] != reference.fb.depth[i] || fast.fb.stencil[i] != reference.fb.stencil[i] {
                return Err(format!(
                    "case {n} pixel ({}, {}): fast {a:?} z {:#x} s {} / reference {b:?} z {:#x} s {}\nstate: {:?}\ncommands: {cmds:?}",
                    i % W,
                    i / W,
                    fast.fb.depth[i],
                    fast.fb.stencil[i],
                    reference.fb.depth[i],
                    reference.fb.stencil[i],
                    fast.derived.render.fragment
                ));
            }
        }
        if fast.fb.samples_passed != reference.fb.samples_passed {
            return Err(format!("case {n}: samples passed {} / {}", fast.fb.samples_passed, reference.fb.samples_passed));
        }
    }
    Ok(())
}

#[test]
fn fast_path_matches_reference() {
    let mut approximated = 0;
    for seed in 1..=4 {
        if let Err(e) = compare(seed, 1000, (61, 47), 1, &mut approximated) {
            panic!("{e}");
        }
    }
    eprintln!("pixels 1/255 off under GL_FASTEST/GL_DONT_CARE: {approximated} (of {} compared)", 4000 * 61 * 47);
}

/// The same through the binned, tiled path with 2 and 3 worker threads,
/// on a surface large enough (several tiles, partial edge tiles)
/// that batches go to the workers.
#[test]
fn tiled_threaded_path_matches_reference() {
    for (seed, threads) in [(11, 2), (12, 3)] {
        if let Err(e) = compare(seed, 150, (301, 203), threads, &mut 0) {
            panic!("{e}");
        }
    }
}

/// The cases are not vacuous: they draw pixels, and the states the fast
/// kernels specialize (blends, flat, perspective, depth-only) all occur.
#[test]
fn cases_draw_pixels() {
    let mut r = Rng(7);
    let size = (61, 47);
    let mut c = context(false, size, 1);
    let tex = texture(&mut c, &mut Rng(1));
    let mut changed = 0;
    for _ in 0..200 {
        c.fb.color.fill([1, 2, 3, 4]);
        c.fb.depth.fill(0xFF_FFFF);
        c.fb.stencil.fill(0);
        for cmd in case(&mut r, tex, size) {
            c.execute(&cmd);
        }
        changed += c.fb.color.iter().filter(|&&p| p != [1, 2, 3, 4]).count();
    }
    // 200 cases over 61x47 pixels: most draw something.
    assert!(changed > 200 * 100, "only {changed} pixels changed");
}
