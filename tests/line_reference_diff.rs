//! Differential test of the fast line and point paths (render::runs, the
//! fast branches of render::line and render::point) against the reference
//! path: random segments, strips and points (short, long, off-screen,
//! clipped, wide, stippled, smooth, shaded, perspective) under random
//! fragment state (depth, stencil, alpha test, blending, logic op, colour
//! mask, fog, scissor, FRONT_AND_BACK) are drawn into identical random
//! framebuffers by two contexts, one forced onto the reference path.
//!
//! Aliased lines and points must match exactly (colour, depth, stencil,
//! occlusion count). Smooth lines take their coverage in closed form on
//! the fast path (smooth::LineRect) and by clipping on the reference path:
//! both within 1e-9 of the exact area, so a stored value may differ by one
//! where an alpha lands that close to a rounding midpoint; the test allows
//! 1 in colour and bounds how many pixels differ at all. Unstippled
//! GL_FASTEST smooth lines are exact on the fast path: they are compared
//! with the reference path at GL_NICEST.

#![allow(non_snake_case)]
use softgl::framebuffer::Config;
use softgl::gl::enums::*;
use softgl::gl::fog::{GL_FOG_COLOR, GL_FOG_DENSITY, GL_FOG_END, GL_FOG_MODE, GL_FOG_START};
use softgl::gl::{Command, Context};

mod common;
use common::Rng;

fn context(reference: bool, (W, H): (usize, usize)) -> Context {
    let mut c = Context::new(Config { alpha_bits: 8, depth_bits: 24, stencil_bits: 8, accum_bits: 0 });
    c.fb.resize(W, H).unwrap();
    c.surface_resized(W as i32, H as i32);
    c.fb.set_double_buffered(true).unwrap();
    c.execute(&Command::DrawBuffer(GL_BACK));
    c.derived.render.reference = reference;
    c.derived.render.threads = 1;
    c
}

const FUNCS: [u32; 8] = [GL_NEVER, GL_LESS, GL_EQUAL, GL_LEQUAL, GL_GREATER, GL_NOTEQUAL, GL_GEQUAL, GL_ALWAYS];

/// The commands of one case: state, then lines or points. Returns whether
/// smooth lines are drawn.
fn case(r: &mut Rng, (W, H): (usize, usize)) -> (Vec<Command>, bool) {
    let mut v = Vec::new();
    let en = |v: &mut Vec<Command>, cap: u32, on: bool| v.push(if on { Command::Enable(cap) } else { Command::Disable(cap) });
    v.push(Command::ShadeModel(if r.chance(30) { GL_FLAT } else { GL_SMOOTH }));
    en(&mut v, GL_DEPTH_TEST, r.chance(40));
    v.push(Command::DepthFunc(if r.chance(60) { r.pick(&[GL_LESS, GL_LEQUAL]) } else { r.pick(&FUNCS) }));
    v.push(Command::DepthMask(r.chance(80)));
    en(&mut v, GL_STENCIL_TEST, r.chance(15));
    v.push(Command::StencilFunc(r.pick(&FUNCS), r.below(4) as i32, 0xFF));
    v.push(Command::StencilOp(GL_KEEP, GL_INCR, GL_INVERT));
    en(&mut v, GL_ALPHA_TEST, r.chance(15));
    v.push(Command::AlphaFunc(r.pick(&FUNCS), r.unit()));
    en(&mut v, GL_BLEND, r.chance(60));
    v.push(Command::BlendFunc(match r.below(3) {
        0 | 1 => [GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA, GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA],
        _ => [GL_SRC_ALPHA, GL_ONE, GL_SRC_ALPHA, GL_ONE],
    }));
    en(&mut v, GL_COLOR_LOGIC_OP, r.chance(5));
    v.push(Command::LogicOp(GL_CLEAR + r.below(16) as u32));
    v.push(Command::ColorMask(if r.chance(85) { [true; 4] } else { [r.chance(50), r.chance(50), r.chance(50), r.chance(50)] }));
    en(&mut v, GL_FOG, r.chance(15));
    v.push(Command::Fog(GL_FOG_MODE, [r.pick(&[0x0800u32, 0x0801, 0x2601]) as f32, 0.0, 0.0, 0.0]));
    v.push(Command::Fog(GL_FOG_DENSITY, [r.range(0.0, 2.0), 0.0, 0.0, 0.0]));
    v.push(Command::Fog(GL_FOG_START, [r.range(-1.0, 1.0), 0.0, 0.0, 0.0]));
    v.push(Command::Fog(GL_FOG_END, [r.range(0.0, 5.0), 0.0, 0.0, 0.0]));
    v.push(Command::Fog(GL_FOG_COLOR, [r.unit(), r.unit(), r.unit(), r.unit()]));
    en(&mut v, GL_SCISSOR_TEST, r.chance(20));
    v.push(Command::Scissor(r.below(W as u64) as i32 - 5, r.below(H as u64) as i32 - 5, r.below(W as u64) as i32, r.below(H as u64) as i32));
    if r.chance(5) {
        v.push(Command::DrawBuffer(GL_FRONT_AND_BACK));
    }
    let smooth = r.chance(50);
    en(&mut v, GL_LINE_SMOOTH, smooth);
    v.push(Command::Hint(GL_LINE_SMOOTH_HINT, r.pick(&[GL_NICEST, GL_DONT_CARE, GL_FASTEST])));
    en(&mut v, GL_LINE_STIPPLE, r.chance(20));
    v.push(Command::LineStipple(1 + r.below(3) as i32, r.next() as u16));
    v.push(Command::LineWidth(match r.below(4) {
        0 => 1.0,
        1 => r.range(0.1, 2.0),
        _ => r.range(1.0, 8.0),
    }));
    let size = r.range(1.0, 9.0);
    v.push(Command::PointSize(r.pick(&[1.0, 2.0, 3.0, size])));
    v.push(Command::MatrixMode(GL_PROJECTION));
    v.push(Command::LoadIdentity);
    let perspective = r.chance(30);
    if perspective {
        v.push(Command::Frustum([-1.0, 1.0, -1.0, 1.0, 1.0, 10.0]));
    }
    v.push(Command::MatrixMode(GL_MODELVIEW));
    v.push(Command::LoadIdentity);
    let mode = r.pick(&[GL_LINES, GL_LINES, GL_LINE_STRIP, GL_POINTS]);
    v.push(Command::Begin(mode));
    let one_color = r.chance(50);
    let color = [r.unit(), r.unit(), r.unit(), r.unit()];
    let scale = match r.below(8) {
        0 => 30.0, // mostly off-screen, clipped
        1 => 0.05, // short
        _ => 1.1,
    };
    for _ in 0..2 + r.below(8) {
        v.push(Command::Color(if one_color { color } else { [r.unit(), r.unit(), r.unit(), r.unit()] }));
        let (x, y) = (r.range(-scale, scale), r.range(-scale, scale));
        v.push(if perspective {
            let z = r.range(-9.0, -1.2);
            Command::Vertex([x * -z, y * -z, z, 1.0])
        } else {
            Command::Vertex([x, y, r.range(-1.2, 1.2), 1.0])
        });
    }
    v.push(Command::End);
    (v, smooth && mode != GL_POINTS)
}

/// Runs `cases` random cases on both paths; returns the number of pixels
/// that differed (by at most 1, on smooth lines) or the first failure.
fn compare(seed: u64, cases: usize, size: (usize, usize)) -> Result<usize, String> {
    let (W, H) = size;
    let mut r = Rng(seed);
    let (mut fast, mut reference) = (context(false, size), context(true, size));
    let mut differing = 0;
    for n in 0..cases {
        let color: Vec<[u8; 4]> = (0..W * H).map(|_| (r.next() as u32).to_ne_bytes()).collect();
        let depth: Vec<u32> = (0..W * H).map(|_| if r.chance(50) { 0xFF_FFFF } else { r.next() as u32 & 0xFF_FFFF }).collect();
        let stencil: Vec<u8> = (0..W * H).map(|_| r.below(4) as u8).collect();
        let (cmds, smooth) = case(&mut r, size);
        for (c, reference_path) in [(&mut fast, false), (&mut reference, true)] {
            c.fb.color.copy_from_slice(&color);
            c.fb.other_color.copy_from_slice(&color);
            c.fb.depth.copy_from_slice(&depth);
            c.fb.stencil.copy_from_slice(&stencil);
            c.fb.samples_passed = 0;
            let stippled = cmds.contains(&Command::Enable(GL_LINE_STIPPLE));
            for cmd in &cmds {
                // The reference draws unstippled GL_FASTEST smooth lines at
                // GL_NICEST (the fast path's coverage is exact under both;
                // stippled smooth lines take the reference code on both).
                match cmd {
                    Command::Hint(GL_LINE_SMOOTH_HINT, GL_FASTEST) if reference_path && !stippled => c.execute(&Command::Hint(GL_LINE_SMOOTH_HINT, GL_NICEST)),
                    _ => c.execute(cmd),
                }
            }
            c.sync_render();
            c.execute(&Command::DrawBuffer(GL_BACK));
        }
        let tolerance = if smooth { 1 } else { 0 };
        for (buf, (a, b)) in [("colour", (&fast.fb.color, &reference.fb.color)), ("other colour", (&fast.fb.other_color, &reference.fb.other_color))] {
            for i in 0..W * H {
                let off = (0..4).map(|ch| a[i][ch].abs_diff(b[i][ch])).max().unwrap();
                differing += (off > 0) as usize;
                if off > tolerance || fast.fb.depth[i] != reference.fb.depth[i] || fast.fb.stencil[i] != reference.fb.stencil[i] {
                    return Err(format!(
                        "case {n} {buf} pixel ({}, {}): fast {:?} z {:#x} s {} / reference {:?} z {:#x} s {}\ncommands: {cmds:?}",
                        i % W,
                        i / W,
                        a[i],
                        fast.fb.depth[i],
                        fast.fb.stencil[i],
                        b[i],
                        reference.fb.depth[i],
                        reference.fb.stencil[i],
                    ));
                }
            }
        }
        if fast.fb.samples_passed != reference.fb.samples_passed {
            return Err(format!("case {n}: samples passed {} / {}\ncommands: {cmds:?}", fast.fb.samples_passed, reference.fb.samples_passed));
        }
    }
    Ok(differing)
}

#[test]
fn fast_lines_and_points_match_reference() {
    let (size, cases) = ((61, 47), 3000);
    let differing = compare(0x11e5, cases, size).unwrap_or_else(|e| panic!("{e}"));
    eprintln!("{differing} pixels differ by 1 (smooth lines) in {cases} cases of {}x{}", size.0, size.1);
    // Off by one only where an alpha lands within ~1e-9 of a rounding
    // midpoint: a handful in millions of fragments.
    assert!(differing <= 20, "{differing} pixels differ");
}

/// Lines and points binned and drawn band by band in the tile workers
/// (render::tile: 2 and 3 threads, batches of 7 primitives, every batch to
/// the workers) give exactly the 1-thread fast path's colour, depth,
/// stencil and occlusion count: the random cases above (wide, stippled
/// strips across bands, smooth, flat and smooth shaded, fog, scissor) on
/// a surface of several bands.
#[test]
fn threaded_lines_and_points_match_one_thread() {
    let size = (161, 123);
    let (W, H) = size;
    let mut r = Rng(0x7b1e);
    let mut ctx: Vec<Context> = [1, 2, 3]
        .map(|t| {
            let mut c = context(false, size);
            c.derived.render.threads = t;
            softgl::render::tile::set_batch_limits(&c.derived.render, 7, 0, 0);
            c
        })
        .into();
    let before = softgl::render::tile::flights_started();
    let mut drawn = 0;
    for n in 0..600 {
        let color: Vec<[u8; 4]> = (0..W * H).map(|_| (r.next() as u32).to_ne_bytes()).collect();
        let depth: Vec<u32> = (0..W * H).map(|_| if r.chance(50) { 0xFF_FFFF } else { r.next() as u32 & 0xFF_FFFF }).collect();
        let stencil: Vec<u8> = (0..W * H).map(|_| r.below(4) as u8).collect();
        // Two cases in a row, so that state changes between binned
        // primitives of one batch.
        // (Drawing to FRONT_AND_BACK is never binned: the test above
        // covers it.)
        let (mut cmds, _) = case(&mut r, size);
        cmds.extend(case(&mut r, size).0);
        cmds.retain(|c| *c != Command::DrawBuffer(GL_FRONT_AND_BACK));
        for c in ctx.iter_mut() {
            c.fb.color.copy_from_slice(&color);
            c.fb.other_color.copy_from_slice(&color);
            c.fb.depth.copy_from_slice(&depth);
            c.fb.stencil.copy_from_slice(&stencil);
            c.fb.samples_passed = 0;
            for cmd in &cmds {
                c.execute(cmd);
            }
            c.sync_render();
            c.execute(&Command::DrawBuffer(GL_BACK));
        }
        drawn += ctx[0].fb.color.iter().zip(&color).filter(|(a, b)| a != b).count();
        let (one, rest) = ctx.split_first().unwrap();
        for (k, c) in rest.iter().enumerate() {
            for i in 0..W * H {
                let (a, b) = ((one.fb.color[i], one.fb.other_color[i], one.fb.depth[i], one.fb.stencil[i]), (c.fb.color[i], c.fb.other_color[i], c.fb.depth[i], c.fb.stencil[i]));
                assert_eq!(a, b, "case {n} pixel ({}, {}): 1 thread / {} threads\ncommands: {cmds:?}", i % W, i / W, k + 2);
            }
            assert_eq!(one.fb.samples_passed, c.fb.samples_passed, "case {n}: samples passed, 1 / {} threads", k + 2);
        }
    }
    assert!(drawn > 600 * 200, "the cases draw ({drawn} pixels)");
    let flights = softgl::render::tile::flights_started() - before;
    assert!(flights > 300, "primitives went to the workers ({flights} batches)");
}
