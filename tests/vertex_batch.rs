//! Differential test of the batched vertex path (gl/begin_end.rs,
//! `Assembly::fast`) against the general per-vertex path it stands beside:
//! two contexts on the same (non-reference) rasterizer, one with
//! `vertex_batching` off, draw the same random primitives (every mode,
//! 0 to 13 vertices and sometimes up to 47: every batch length around the
//! four the batched path transforms at once, and primitives split across
//! many batches and wrapping its ring of slots; random interleavings of glColor, glSecondaryColor,
//! glEdgeFlag, glNormal and glTexCoord between the vertices) under random
//! state (shading, culling and front face, polygon modes, scissor,
//! viewport, user clip planes, colour sum, lighting (one or two lights,
//! positional, attenuated, spot, two-sided, local viewer, separate
//! specular, glMaterial between vertices), fog (every mode, per vertex or
//! per fragment, glFogCoord or depth) and texturing), submitted in immediate mode,
//! through display lists (GL_COMPILE then glCallList, or
//! GL_COMPILE_AND_EXECUTE) or from client arrays (glDrawArrays and
//! glDrawElements; positions of 2 to 4 floats, colours of 3 or 4 floats
//! or unsigned bytes, which take the specialized array loops), with the
//! frame shaded and read between glBegin and glEnd (queued vertices must
//! be drawn first), or in feedback or selection mode (never batched: the
//! same buffers). Colour, depth and stencil must be identical: the
//! batched path does the same arithmetic in the same order.

use softgl::framebuffer::Config;
use softgl::gl::arrays::Array;
use softgl::gl::enums::*;
use softgl::gl::select::{NameOp, GL_4D_COLOR_TEXTURE, GL_FEEDBACK, GL_RENDER, GL_SELECT};
use softgl::gl::fog::{GL_FOG_COORD, GL_FOG_COORD_SRC, GL_FOG_END, GL_FOG_MODE, GL_FOG_START, GL_FRAGMENT_DEPTH};
use softgl::gl::texture::enums as t;
use softgl::gl::{Command, Context};

mod common;
use common::Rng;

const W: usize = 40;
const H: usize = 32;

fn context(batching: bool) -> Context {
    let mut c = Context::new(Config { alpha_bits: 8, depth_bits: 24, stencil_bits: 8, accum_bits: 0 });
    c.fb.resize(W, H).unwrap();
    c.surface_resized(W as i32, H as i32);
    c.derived.render.reference = false;
    c.derived.render.threads = 1;
    c.vertex_batching = batching;
    let data: Vec<u8> = (0..4 * 4 * 4).map(|i| (i * 37 % 256) as u8).collect();
    c.submit(Command::BindTexture(t::GL_TEXTURE_2D, 1));
    let cmd = unsafe { c.tex_image_command(2, t::GL_TEXTURE_2D, 0, t::GL_RGBA as i32, [4, 4, 1], 0, t::GL_RGBA, t::GL_UNSIGNED_BYTE, data.as_ptr()) };
    c.submit(cmd.expect("a valid glTexImage2D"));
    // One level: complete only without mipmapping.
    c.submit(Command::TexParameter(t::GL_TEXTURE_2D, t::GL_TEXTURE_MIN_FILTER, [t::GL_LINEAR as f32, 0.0, 0.0, 0.0]));
    c
}

/// The state of one case and whether it takes the batched path.
fn state(r: &mut Rng) -> (Vec<Command>, Batch) {
    let mut v = Vec::new();
    let en = |v: &mut Vec<Command>, cap: u32, on: bool| v.push(if on { Command::Enable(cap) } else { Command::Disable(cap) });
    let flat = r.chance(40);
    v.push(Command::ShadeModel(if flat { GL_FLAT } else { GL_SMOOTH }));
    en(&mut v, GL_DEPTH_TEST, r.chance(60));
    v.push(Command::DepthFunc(r.pick(&[GL_LESS, GL_LEQUAL, GL_ALWAYS])));
    en(&mut v, GL_CULL_FACE, r.chance(25));
    v.push(Command::CullFace(r.pick(&[GL_FRONT, GL_BACK, GL_FRONT_AND_BACK])));
    v.push(Command::FrontFace(r.pick(&[GL_CW, GL_CCW])));
    let modes = [GL_FILL, GL_FILL, GL_FILL, GL_LINE, GL_POINT];
    v.push(Command::PolygonMode(GL_FRONT, r.pick(&modes)));
    v.push(Command::PolygonMode(GL_BACK, r.pick(&modes)));
    en(&mut v, GL_SCISSOR_TEST, r.chance(15));
    // Sometimes empty: nothing may be drawn then.
    v.push(Command::Scissor(r.below(W as u64) as i32 - 4, r.below(H as u64) as i32 - 4, r.below(W as u64) as i32, r.below(H as u64) as i32));
    if r.chance(30) {
        v.push(Command::Viewport(r.below(20) as i32 - 10, r.below(20) as i32 - 10, r.below(60) as i32, r.below(50) as i32));
    } else {
        v.push(Command::Viewport(0, 0, W as i32, H as i32));
    }
    en(&mut v, GL_CLIP_PLANE0, r.chance(10));
    v.push(Command::ClipPlane(GL_CLIP_PLANE0, [r.range(-1.0, 1.0) as f64, r.range(-1.0, 1.0) as f64, 0.0, r.range(-0.5, 0.5) as f64]));
    let sum = r.chance(25);
    en(&mut v, GL_COLOR_SUM, sum);
    let lighting = r.chance(30);
    en(&mut v, GL_LIGHTING, lighting);
    en(&mut v, GL_LIGHT0, r.chance(80));
    en(&mut v, GL_COLOR_MATERIAL, r.chance(50));
    if lighting {
        // The light and model configurations the lit path meets: a second
        // light, positional, attenuated, spot; two-sided; local viewer;
        // separate specular; normalization; shininess.
        en(&mut v, GL_LIGHT0 + 1, r.chance(50));
        let w = if r.chance(50) { 1.0 } else { 0.0 };
        v.push(Command::Light(GL_LIGHT0 + 1, GL_POSITION, [r.range(-3.0, 3.0), r.range(-3.0, 3.0), r.range(-3.0, 3.0), w]));
        v.push(Command::Light(GL_LIGHT0 + 1, GL_DIFFUSE, [r.unit(), r.unit(), r.unit(), 1.0]));
        v.push(Command::Light(GL_LIGHT0 + 1, GL_SPECULAR, [r.unit(), r.unit(), r.unit(), 1.0]));
        v.push(Command::Light(GL_LIGHT0 + 1, GL_LINEAR_ATTENUATION, [r.range(0.0, 0.5), 0.0, 0.0, 0.0]));
        if r.chance(30) {
            v.push(Command::Light(GL_LIGHT0 + 1, GL_SPOT_CUTOFF, [r.range(10.0, 90.0), 0.0, 0.0, 0.0]));
            v.push(Command::Light(GL_LIGHT0 + 1, GL_SPOT_EXPONENT, [r.range(0.0, 8.0), 0.0, 0.0, 0.0]));
        }
        v.push(Command::LightModel(GL_LIGHT_MODEL_TWO_SIDE, [r.chance(40) as u32 as f32, 0.0, 0.0, 0.0]));
        v.push(Command::LightModel(GL_LIGHT_MODEL_LOCAL_VIEWER, [r.chance(40) as u32 as f32, 0.0, 0.0, 0.0]));
        if r.chance(40) {
            v.push(Command::LightModel(GL_LIGHT_MODEL_COLOR_CONTROL, [GL_SEPARATE_SPECULAR_COLOR as f32, 0.0, 0.0, 0.0]));
        }
        en(&mut v, GL_NORMALIZE, r.chance(50));
        let face = r.pick(&[GL_FRONT, GL_BACK, GL_FRONT_AND_BACK]);
        v.push(Command::Material(face, GL_SPECULAR, [r.unit(), r.unit(), r.unit(), 1.0]));
        v.push(Command::Material(face, GL_SHININESS, [r.range(0.0, 60.0), 0.0, 0.0, 0.0]));
        v.push(Command::Material(face, GL_EMISSION, [r.unit() * 0.2, r.unit() * 0.2, 0.0, 1.0]));
    }
    let fog = r.chance(20);
    en(&mut v, GL_FOG, fog);
    v.push(Command::Fog(GL_FOG_MODE, [r.pick(&[t::GL_LINEAR, 0x0800, 0x0801]) as f32, 0.0, 0.0, 0.0])); // LINEAR, EXP, EXP2
    v.push(Command::Fog(GL_FOG_START, [0.0; 4]));
    v.push(Command::Fog(GL_FOG_END, [r.range(1.0, 10.0), 0.0, 0.0, 0.0]));
    v.push(Command::Fog(GL_FOG_COORD_SRC, [r.pick(&[GL_FOG_COORD, GL_FRAGMENT_DEPTH]) as f32, 0.0, 0.0, 0.0]));
    v.push(Command::Hint(GL_FOG_HINT, r.pick(&[GL_FASTEST, GL_NICEST, GL_DONT_CARE])));
    let textured = r.chance(20);
    en(&mut v, t::GL_TEXTURE_2D, textured);
    v.push(Command::MatrixMode(GL_PROJECTION));
    v.push(Command::LoadIdentity);
    if r.chance(50) {
        v.push(Command::Frustum([-1.0, 1.0, -1.0, 1.0, 1.0, 10.0]));
        v.push(Command::MatrixMode(GL_MODELVIEW));
        v.push(Command::LoadIdentity);
        v.push(Command::Translate([0.0, 0.0, -3.0]));
    } else {
        v.push(Command::MatrixMode(GL_MODELVIEW));
        v.push(Command::LoadIdentity);
    }
    if r.chance(50) {
        v.push(Command::Rotate(r.range(-180.0, 180.0) as f64, [r.unit() as f64, r.unit() as f64, 1.0]));
    }
    (v, Batch { fast: !(flat && sum && textured), lit: lighting })
}

/// Whether a case's state takes the batched path (all but flat-shaded
/// textured triangles with the colour sum) and whether it is lit.
#[derive(Clone, Copy)]
struct Batch {
    fast: bool,
    lit: bool,
}

/// One vertex with the attributes set before it.
#[derive(Clone, Copy, Debug)]
struct Vertex {
    pos: [f32; 4],
    color: Option<[f32; 4]>,
    secondary: Option<[f32; 4]>,
    edge: Option<bool>,
    normal: Option<[f32; 3]>,
    tex: Option<[f32; 4]>,
    fog: Option<f32>,
    /// glMaterial(GL_FRONT_AND_BACK, GL_DIFFUSE) between vertices.
    material: Option<[f32; 4]>,
}

fn primitive(r: &mut Rng) -> (u32, Vec<Vertex>) {
    let mode = r.below(10) as u32; // GL_POINTS ..= GL_POLYGON
    // Every length around the batch of four and, a quarter of the time,
    // primitives long enough to wrap the batched path's ring of slots
    // several times (split across many batches).
    let n = if r.chance(25) { r.below(48) } else { r.below(14) } as usize;
    let scale = match r.below(10) {
        0 => 40.0, // far outside: clipped or rejected
        1 => 3.0,  // across the guard band's inside
        2 => 0.1,  // tiny
        _ => 1.2,
    };
    let verts = (0..n)
        .map(|_| Vertex {
            pos: [r.range(-scale, scale), r.range(-scale, scale), r.range(-1.5, 1.5), if r.chance(10) { r.range(0.5, 2.0) } else { 1.0 }],
            color: r.chance(70).then(|| [r.unit(), r.unit(), r.unit(), r.unit()]),
            secondary: r.chance(30).then(|| [r.unit(), r.unit(), r.unit(), 1.0]),
            edge: r.chance(30).then(|| r.chance(50)),
            normal: r.chance(30).then(|| [r.range(-1.0, 1.0), r.range(-1.0, 1.0), r.range(-1.0, 1.0)]),
            tex: r.chance(30).then(|| [r.range(-1.0, 2.0), r.range(-1.0, 2.0), 0.0, 1.0]),
            fog: r.chance(30).then(|| r.range(0.0, 8.0)),
            material: r.chance(10).then(|| [r.unit(), r.unit(), r.unit(), r.unit()]),
        })
        .collect();
    (mode, verts)
}

fn immediate(mode: u32, verts: &[Vertex]) -> Vec<Command> {
    let mut v = vec![Command::Begin(mode)];
    for x in verts {
        if let Some(c) = x.color {
            v.push(Command::Color(c));
        }
        if let Some(c) = x.secondary {
            v.push(Command::SecondaryColor(c));
        }
        if let Some(e) = x.edge {
            v.push(Command::EdgeFlag(e));
        }
        if let Some(n) = x.normal {
            v.push(Command::Normal(n));
        }
        if let Some(tc) = x.tex {
            v.push(Command::TexCoord(t::GL_TEXTURE0, tc));
        }
        if let Some(f) = x.fog {
            v.push(Command::FogCoord(f));
        }
        if let Some(m) = x.material {
            v.push(Command::Material(GL_FRONT_AND_BACK, GL_DIFFUSE, m));
        }
        v.push(Command::Vertex(x.pos));
    }
    v.push(Command::End);
    v
}

/// The primitive from client arrays: positions of 2 to 4 floats, colours
/// (where a vertex has none, the previous one's) as 3 or 4 floats or
/// unsigned bytes or no colour array, and sometimes edge flags; by
/// glDrawArrays or by glDrawElements with random repeated indices.
fn from_arrays(c: &mut Context, r: &mut Rng, mode: u32, verts: &[Vertex]) {
    let vsize = 2 + r.below(3) as usize;
    let pos: Vec<f32> = verts.iter().flat_map(|x| x.pos[..vsize].to_vec()).collect();
    let mut last = [1.0; 4];
    let color: Vec<[f32; 4]> = verts
        .iter()
        .map(|x| {
            if let Some(c) = x.color {
                last = c;
            }
            last
        })
        .collect();
    let csize = 3 + r.below(2) as usize;
    let color_f: Vec<f32> = color.iter().flat_map(|c| c[..csize].to_vec()).collect();
    let color_b: Vec<u8> = color_f.iter().map(|&x| (x * 255.0) as u8).collect();
    let edge: Vec<u8> = verts.iter().map(|x| x.edge.unwrap_or(true) as u8).collect();
    c.array_pointer(Array::Vertex, vsize as i32, GL_FLOAT, 0, pos.as_ptr() as usize);
    if r.chance(50) {
        c.array_pointer(Array::Color, csize as i32, GL_FLOAT, 0, color_f.as_ptr() as usize);
    } else {
        c.array_pointer(Array::Color, csize as i32, GL_UNSIGNED_BYTE, 0, color_b.as_ptr() as usize);
    }
    c.array_pointer(Array::EdgeFlag, 1, GL_UNSIGNED_BYTE, 0, edge.as_ptr() as usize);
    c.client_state(GL_VERTEX_ARRAY, true);
    c.client_state(GL_COLOR_ARRAY, r.chance(85));
    c.client_state(GL_EDGE_FLAG_ARRAY, r.chance(30));
    if r.chance(50) || verts.is_empty() {
        c.draw_arrays(mode, 0, verts.len() as i32);
    } else {
        let n = r.below(16) as usize;
        let idx: Vec<u32> = (0..n).map(|_| r.below(verts.len() as u64) as u32).collect();
        c.draw_elements(mode, n as i32, GL_UNSIGNED_INT, idx.as_ptr() as usize);
    }
    c.client_state(GL_VERTEX_ARRAY, false);
    c.client_state(GL_COLOR_ARRAY, false);
    c.client_state(GL_EDGE_FLAG_ARRAY, false);
}

#[test]
fn batched_vertices_match_the_general_path() {
    let (mut fast, mut general) = (context(true), context(false));
    let mut r = Rng(0x5eed_0001);
    let (mut batchable, mut lit, mut drawn, mut feedback, mut mid_drawn) = (0, 0, 0, 0, 0);
    for case in 0..3000 {
        let (state_cmds, can_batch) = state(&mut r);
        let prims: Vec<(u32, Vec<Vertex>)> = (0..1 + r.below(3)).map(|_| primitive(&mut r)).collect();
        // immediate, list, compile-and-execute, arrays, immediate with the
        // frame shaded and read mid-primitive, feedback, selection
        let route = r.below(7);
        // Where route 4 shades the batch: after this many commands.
        let mid = r.below(40) as usize;
        let seed = r.next();
        let clear = [r.unit(), r.unit(), r.unit(), 1.0];
        let mut seen: [(Vec<_>, Vec<f32>, Vec<u32>, i32); 2] = Default::default();
        for (ci, c) in [&mut fast, &mut general].into_iter().enumerate() {
            c.submit(Command::ClearColor(clear));
            c.submit(Command::Disable(GL_SCISSOR_TEST));
            c.submit(Command::Clear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT | GL_STENCIL_BUFFER_BIT));
            for cmd in &state_cmds {
                c.submit(cmd.clone());
            }
            let mut ar = Rng(seed);
            match route {
                1 | 2 => {
                    c.new_list(1, if route == 1 { GL_COMPILE } else { GL_COMPILE_AND_EXECUTE });
                    for (mode, verts) in &prims {
                        for cmd in immediate(*mode, verts) {
                            c.submit(cmd);
                        }
                    }
                    c.end_list();
                    if route == 1 {
                        c.call_list(1);
                    }
                }
                3 => {
                    for (mode, verts) in &prims {
                        from_arrays(c, &mut ar, *mode, verts);
                    }
                }
                4 => {
                    // A frame shown between glBegin and glEnd (the window
                    // system shades the batch): the triangles the vertices
                    // so far complete are in it, batched or not.
                    let cmds: Vec<Command> = prims.iter().flat_map(|(mode, verts)| immediate(*mode, verts)).collect();
                    for (k, cmd) in cmds.into_iter().enumerate() {
                        c.submit(cmd);
                        if k == mid {
                            c.sync_render();
                            seen[ci].0 = c.fb.color.iter().copied().collect();
                        }
                    }
                }
                5 => {
                    // Feedback: no pixels, the same tokens and vertices.
                    let mut buf = vec![0f32; 4096];
                    c.feedback_buffer(buf.len() as i32, GL_4D_COLOR_TEXTURE, buf.as_mut_ptr());
                    c.render_mode(GL_FEEDBACK);
                    for (mode, verts) in &prims {
                        for cmd in immediate(*mode, verts) {
                            c.submit(cmd);
                        }
                    }
                    seen[ci].3 = c.render_mode(GL_RENDER);
                    seen[ci].1 = buf;
                }
                6 => {
                    // Selection: the same hit records.
                    let mut buf = vec![0u32; 256];
                    c.select_buffer(buf.len() as i32, buf.as_mut_ptr());
                    c.render_mode(GL_SELECT);
                    c.submit(Command::NameStack(NameOp::Init));
                    c.submit(Command::NameStack(NameOp::Push(7)));
                    for (mode, verts) in &prims {
                        for cmd in immediate(*mode, verts) {
                            c.submit(cmd);
                        }
                    }
                    seen[ci].3 = c.render_mode(GL_RENDER);
                    seen[ci].2 = buf;
                }
                _ => {
                    for (mode, verts) in &prims {
                        for cmd in immediate(*mode, verts) {
                            c.submit(cmd);
                        }
                    }
                }
            }
            c.sync_render();
        }
        let filled = prims.iter().any(|(m, v)| *m >= GL_TRIANGLES && *m != GL_POLYGON && v.len() >= 3);
        if can_batch.fast && filled {
            batchable += 1;
            lit += can_batch.lit as u32;
        }
        if fast.fb.color.iter().any(|p| *p != fast.fb.color[0]) {
            drawn += 1;
        }
        let [a, b] = &seen;
        assert!(a.0 == b.0, "case {case}: the frame shaded mid-primitive differs\nstate: {state_cmds:?}\nprimitives: {prims:?}");
        assert!(a.1 == b.1 && a.2 == b.2 && a.3 == b.3, "case {case} (route {route}): feedback or selection differs ({} / {})", a.3, b.3);
        if route >= 5 {
            feedback += (a.3 > 0) as u32;
        }
        if route == 4 && a.0.iter().any(|p| *p != a.0[0]) {
            mid_drawn += 1;
        }
        for i in 0..W * H {
            let (a, b) = (fast.fb.color[i], general.fb.color[i]);
            assert!(
                a == b && fast.fb.depth[i] == general.fb.depth[i] && fast.fb.stencil[i] == general.fb.stencil[i],
                "case {case} (route {route}) pixel ({}, {}): batched {a:?} z {:#x} / general {b:?} z {:#x}\nstate: {state_cmds:?}\nprimitives: {prims:?}",
                i % W,
                i / W,
                fast.fb.depth[i],
                general.fb.depth[i],
            );
        }
    }
    // The comparison meant something: many cases took the batched path
    // and drew pixels.
    assert!(batchable > 1500 && lit > 400 && drawn > 1000, "batchable {batchable}, lit {lit}, drawn {drawn}");
    assert!(feedback > 300 && mid_drawn > 100, "feedback {feedback}, mid-primitive frames drawn {mid_drawn}");
}

/// The batched path's flushes (round 15) test once whether setup bins
/// (`setup::binned_here`) and then send every triangle whose vertices are
/// inside the guard band to `setup::bin_placed` directly, and step the
/// ring slot per vertex: 2D triangles (glVertex2f, as the bench's tiny
/// triangles; sometimes strips and fans, whose slots differ) drawn
/// batched with 2 and 3 threads (batches of 7 triangles, every batch to
/// the workers) give the 1-thread general path's colour (both buffers),
/// depth and stencil, under the states that must leave the binning path:
/// drawing to GL_FRONT_AND_BACK (never binned), polygon modes (not
/// direct), and cases partly outside the guard band (clipped). Strips,
/// fans and quad strips bin four triangles a flush at once
/// (`render::bin4`, round 27), handing batches over inside a group.
#[test]
fn batched_flushes_bin_as_the_general_path() {
    let size = (61, 53);
    let mk = |batching: bool, threads: usize| {
        let mut c = Context::new(Config { alpha_bits: 8, depth_bits: 24, stencil_bits: 8, accum_bits: 0 });
        c.fb.resize(size.0, size.1).unwrap();
        c.surface_resized(size.0 as i32, size.1 as i32);
        c.fb.set_double_buffered(true).unwrap();
        c.execute(&Command::DrawBuffer(GL_BACK));
        c.derived.render.reference = false;
        c.derived.render.threads = threads;
        c.vertex_batching = batching;
        softgl::render::tile::set_batch_limits(&c.derived.render, 7, 0, 0);
        c
    };
    let mut ctx = [mk(false, 1), mk(true, 2), mk(true, 3)];
    let mut r = Rng(0x5eed_0015);
    let before = softgl::render::tile::flights_started();
    let (mut both, mut drawn) = (0, 0);
    for case in 0..400 {
        let mut cmds = vec![Command::ClearColor([r.unit(), r.unit(), r.unit(), 1.0]), Command::Clear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT)];
        let two = r.chance(25);
        both += two as u32;
        cmds.push(Command::DrawBuffer(if two { GL_FRONT_AND_BACK } else { GL_BACK }));
        cmds.push(Command::ShadeModel(if r.chance(30) { GL_FLAT } else { GL_SMOOTH }));
        cmds.push(if r.chance(30) { Command::Enable(GL_CULL_FACE) } else { Command::Disable(GL_CULL_FACE) });
        cmds.push(Command::CullFace(r.pick(&[GL_FRONT, GL_BACK])));
        cmds.push(Command::FrontFace(r.pick(&[GL_CCW, GL_CW])));
        let line = r.chance(15);
        cmds.push(Command::PolygonMode(GL_FRONT_AND_BACK, if line { GL_LINE } else { GL_FILL }));
        cmds.push(if r.chance(50) { Command::Enable(GL_DEPTH_TEST) } else { Command::Disable(GL_DEPTH_TEST) });
        // Mostly 1-3 pixel triangles; sometimes large ones, and ones
        // reaching past the guard band.
        let scale = match r.below(8) {
            0 => 60.0,
            1 => 0.8,
            _ => 0.06,
        };
        for _ in 0..1 + r.below(3) {
            let mode = r.pick(&[GL_TRIANGLES, GL_TRIANGLES, GL_TRIANGLE_STRIP, GL_TRIANGLE_FAN, GL_QUAD_STRIP]);
            cmds.push(Command::Begin(mode));
            for _ in 0..r.below(60) {
                let (x, y) = (r.range(-1.1, 1.1), r.range(-1.1, 1.1));
                cmds.push(Command::Color([r.unit(), r.unit(), r.unit(), 1.0]));
                cmds.push(Command::Vertex([x + r.range(-scale, scale), y + r.range(-scale, scale), 0.0, 1.0]));
            }
            cmds.push(Command::End);
        }
        for c in ctx.iter_mut() {
            for cmd in &cmds {
                c.submit(cmd.clone());
            }
            c.sync_render();
            c.submit(Command::DrawBuffer(GL_BACK));
        }
        let (one, rest) = ctx.split_first().unwrap();
        if one.fb.color.iter().any(|p| *p != one.fb.color[0]) {
            drawn += 1;
        }
        for (k, c) in rest.iter().enumerate() {
            for i in 0..size.0 * size.1 {
                let (a, b) = ((one.fb.color[i], one.fb.other_color[i], one.fb.depth[i]), (c.fb.color[i], c.fb.other_color[i], c.fb.depth[i]));
                assert_eq!(a, b, "case {case} pixel ({}, {}): general 1 thread / batched {} threads\ncommands: {cmds:?}", i % size.0, i / size.0, k + 2);
            }
        }
    }
    assert!(both > 60 && drawn > 350, "cases to both buffers {both}, drawn {drawn}");
    let flights = softgl::render::tile::flights_started() - before;
    assert!(flights > 300, "triangles went to the workers ({flights} batches)");
}

/// MXCSR, for the case of a caller that unmasks exceptions (never
/// trusted: `api::fpenv`).
#[cfg(target_arch = "x86_64")]
fn mxcsr() -> u32 {
    let mut v: u32 = 0;
    // SAFETY: stmxcsr stores 4 bytes to a valid, aligned local.
    unsafe { std::arch::asm!("stmxcsr [{}]", in(reg) &mut v as *mut u32, options(nostack, preserves_flags)) };
    v
}

#[cfg(target_arch = "x86_64")]
fn set_mxcsr(v: u32) {
    // SAFETY: loads 4 bytes from a valid local holding a valid MXCSR.
    unsafe { std::arch::asm!("ldmxcsr [{}]", in(reg) &v as *const u32, options(nostack, preserves_flags)) };
}

/// Two OSMesa contexts (RGBA, depth 24, stencil 8) with a `w` x `h`
/// buffer each, for the entry-point tests: `f` gets them, `current(k)`
/// makes context k current on its buffer; they are released afterwards.
#[cfg(target_arch = "x86_64")]
unsafe fn with_two_contexts(w: usize, h: usize, f: impl FnOnce(&[*mut softgl::winsys::osmesa::OsContext; 2], &mut dyn FnMut(usize), &[Vec<u8>; 2])) {
    use softgl::api::table::*;
    let mut bufs = [vec![0u8; w * h * 4], vec![0u8; w * h * 4]];
    let ctxs = [0, 1].map(|_| OSMesaCreateContextExt(GL_RGBA, 24, 8, 0, std::ptr::null_mut()));
    let ptrs = [bufs[0].as_mut_ptr(), bufs[1].as_mut_ptr()];
    let mut current = |k: usize| assert_eq!(OSMesaMakeCurrent(ctxs[k], ptrs[k] as *mut std::ffi::c_void, GL_UNSIGNED_BYTE, w as i32, h as i32), 1);
    // `f` reads the buffers between draws only (after glFinish).
    f(&ctxs, &mut current, &bufs);
    OSMesaMakeCurrent(std::ptr::null_mut(), std::ptr::null_mut(), 0, 0, 0);
    for c in ctxs {
        OSMesaDestroyContext(c);
    }
}

/// One case through the C entry points: random state, then primitives of
/// every kind by glColor and the float glVertex forms, sometimes compiled
/// (GL_COMPILE then glCallList, or GL_COMPILE_AND_EXECUTE) or begun by a
/// caller that unmasks floating-point exceptions. Pushes, per primitive,
/// whether `plain_vertex` was set inside it, and whether it should have
/// been; asserts it is clear after each glEnd.
#[cfg(target_arch = "x86_64")]
unsafe fn entry_case(r: &mut Rng, gl: *const Context, seen: &mut Vec<(bool, bool)>) {
    use softgl::api::table::*;
    let masked = mxcsr();
    let batching = (*gl).vertex_batching;
    glClearColor(r.unit(), r.unit(), r.unit(), 1.0);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    glShadeModel(if r.chance(30) { GL_FLAT } else { GL_SMOOTH });
    let lit = r.chance(25);
    if lit {
        glEnable(GL_LIGHTING);
        glEnable(GL_LIGHT0);
        let pos = [r.range(-1.0, 1.0), r.range(-1.0, 1.0), 1.0, 0.0];
        glLightfv(GL_LIGHT0, GL_POSITION, pos.as_ptr());
    } else {
        glDisable(GL_LIGHTING);
    }
    let fog = r.chance(15);
    if fog {
        glEnable(GL_FOG);
    } else {
        glDisable(GL_FOG);
    }
    if r.chance(50) {
        glEnable(GL_DEPTH_TEST);
    } else {
        glDisable(GL_DEPTH_TEST);
    }
    for _ in 0..1 + r.below(4) {
        let mode = r.pick(&[GL_TRIANGLES, GL_TRIANGLES, GL_TRIANGLES, GL_TRIANGLE_STRIP, GL_TRIANGLE_FAN, GL_QUADS, GL_QUAD_STRIP, GL_POLYGON, GL_LINES, GL_POINTS]);
        // 0: immediate, 1: GL_COMPILE then glCallList, 2: compile and execute.
        let list = if r.chance(25) { 1 + r.below(2) as u32 } else { 0 };
        let unmasked = r.chance(20);
        if list > 0 {
            glNewList(1, if list == 1 { GL_COMPILE } else { GL_COMPILE_AND_EXECUTE });
        }
        if unmasked {
            // Invalid, divide-by-zero and overflow unmasked (Delphi's).
            set_mxcsr(0x1900);
        }
        glBegin(mode);
        // GL_POLYGON is assembled at glEnd, never batched.
        let filled = !matches!(mode, GL_LINES | GL_POINTS | GL_POLYGON);
        let expect = batching && filled && !lit && !fog && !unmasked && list == 0;
        let mut on = (*gl).plain_vertex;
        let n = if r.chance(20) { r.below(40) } else { r.below(13) };
        for _ in 0..n {
            let (x, y, z) = (r.range(-1.2, 1.2), r.range(-1.2, 1.2), r.range(-0.9, 0.9));
            match r.below(4) {
                0 => glColor3f(r.unit(), r.unit(), r.unit()),
                1 => glColor4f(r.unit(), r.unit(), r.unit(), r.unit()),
                2 => glNormal3f(r.range(-1.0, 1.0), r.range(-1.0, 1.0), 1.0),
                _ => {}
            }
            match r.below(5) {
                0 => glVertex2f(x, y),
                1 => glVertex3f(x, y, z),
                2 => glVertex2fv([x, y].as_ptr()),
                3 => glVertex3fv([x, y, z].as_ptr()),
                _ => glVertex4f(x, y, z, 1.0),
            }
            on |= (*gl).plain_vertex;
        }
        glEnd();
        if unmasked {
            set_mxcsr(masked);
        }
        assert!(!(*gl).plain_vertex, "plain_vertex is cleared at glEnd");
        if list > 0 {
            glEndList();
            if list == 1 {
                glCallList(1);
            }
        }
        seen.push((on, expect));
    }
}

/// Round 16: the `list` entry points' way in while `plain_vertex` holds
/// (`api::dispatch::with_current_list`: one flag set at glBegin instead
/// of the guard's, the list's and the batch's tests per vertex). The same
/// random commands through the C entry points into two contexts, one
/// with the batched path off (the flag never set: the general path), give
/// the same pixels; the flag is set exactly in the filled, unlit,
/// fog-free primitives begun by a masked caller outside list compilation,
/// and clear after glEnd (a list compiled after a plain primitive records
/// its vertices).
#[cfg(target_arch = "x86_64")]
#[test]
fn plain_vertex_entries_match_the_general_path() {
    use softgl::api::table::*;
    let (w, h) = (45, 37);
    unsafe {
        with_two_contexts(w, h, |ctxs, current, bufs| {
            let mut r = Rng(0x5eed_0016);
            let (mut on, mut off) = (0, 0);
            for case in 0..800 {
                let seed = r.next();
                let mut seen = [Vec::new(), Vec::new()];
                for k in 0..2 {
                    current(k);
                    (*ctxs[k]).gl.vertex_batching = k == 0;
                    entry_case(&mut Rng(seed), &(*ctxs[k]).gl, &mut seen[k]);
                    glFinish();
                }
                for (i, &(got, expect)) in seen[0].iter().enumerate() {
                    assert_eq!(got, expect, "case {case} primitive {i}: plain_vertex");
                    on += got as u32;
                    off += (!got) as u32;
                }
                assert!(seen[1].iter().all(|&(got, _)| !got), "case {case}: never set without batching");
                if let Some(i) = (0..w * h * 4).find(|&i| bufs[0][i] != bufs[1][i]) {
                    panic!("case {case}: byte {i} (pixel ({}, {})) differs: entry fast path {} / general {}", i / 4 % w, i / 4 / w, bufs[0][i], bufs[1][i]);
                }
            }
            assert!(on > 400 && off > 400, "primitives on the plain entry path {on}, off it {off}");
        });
    }
}

/// One list compiled through the C entry points (GL_COMPILE): random
/// primitives of per-vertex commands in their many forms, with a few
/// commands that have no compact form (glMaterialf, glCallList, glRectf,
/// glVertex2fv of NULL, which records nothing) between them, some
/// primitives left open by glEndList. Pushes, per primitive, whether
/// `compile_fast` was set inside it; asserts it is clear after each glEnd
/// and glEndList.
#[cfg(target_arch = "x86_64")]
unsafe fn compile_case(r: &mut Rng, gl: *const Context, seen: &mut Vec<bool>) {
    use softgl::api::table::*;
    glNewList(1, GL_COMPILE);
    let prims = 1 + r.below(4);
    for p in 0..prims {
        let mode = r.pick(&[GL_TRIANGLES, GL_TRIANGLE_STRIP, GL_QUADS, GL_POLYGON, GL_LINES, GL_POINTS]);
        if r.chance(30) {
            glColor3ub(r.below(256) as u8, r.below(256) as u8, r.below(256) as u8);
        }
        glBegin(mode);
        let mut on = (*gl).compile_fast;
        for _ in 0..r.below(20) {
            let (x, y, z) = (r.range(-1.2, 1.2), r.range(-1.2, 1.2), r.range(-0.9, 0.9));
            match r.below(12) {
                0 => glColor3f(r.unit(), r.unit(), r.unit()),
                1 => glColor4f(r.unit(), r.unit(), r.unit(), r.unit()),
                2 => glColor3d(r.unit() as f64, r.unit() as f64, r.unit() as f64),
                3 => glColor4ub(r.below(256) as u8, r.below(256) as u8, r.below(256) as u8, r.below(256) as u8),
                4 => glNormal3f(r.range(-1.0, 1.0), r.range(-1.0, 1.0), 1.0),
                5 => glTexCoord2f(r.unit(), r.unit()),
                6 => glMultiTexCoord4f(0x84C0 + r.below(2) as u32, r.unit(), r.unit(), r.unit(), 1.0),
                7 => glEdgeFlag(r.chance(50) as u8),
                8 => glMaterialf(GL_FRONT, GL_SHININESS, r.range(0.0, 100.0)),
                9 => glCallList(2),
                10 => glSecondaryColor3f(r.unit(), r.unit(), r.unit()),
                _ => {}
            }
            match r.below(8) {
                0 => glVertex2f(x, y),
                1 => glVertex3f(x, y, z),
                2 => glVertex2fv([x, y].as_ptr()),
                3 => glVertex3d(x as f64, y as f64, z as f64),
                4 => glVertex2i((x * 3.0) as i32, (y * 3.0) as i32),
                5 => glVertex4f(x, y, z, 1.0 + r.unit()),
                6 => glVertex2fv(std::ptr::null()),
                _ => glRectf(x, y, -x, -y),
            }
            on &= (*gl).compile_fast;
        }
        seen.push(on);
        if p + 1 == prims && r.chance(15) {
            // The list ends inside the primitive.
            break;
        }
        glEnd();
        assert!(!(*gl).compile_fast, "compile_fast is cleared at the recorded glEnd");
    }
    glEndList();
    assert!(!(*gl).compile_fast, "compile_fast is cleared at glEndList");
}

/// Round 20: a list compiled with GL_COMPILE between a recorded glBegin
/// and glEnd by a caller that masks every exception records each command
/// straight from its entry point (`Context::compile_fast`,
/// `api::dispatch::with_current_list`). The same random commands compiled
/// into two contexts, one by a caller that unmasks exceptions (the
/// guarded, general path: the flag is never set there), give the same
/// list, word for word and command for command, and the same pixels
/// when called.
#[cfg(target_arch = "x86_64")]
#[test]
fn compiled_list_entries_match_the_general_path() {
    use softgl::api::table::*;
    let (w, h) = (41, 33);
    unsafe {
        with_two_contexts(w, h, |ctxs, current, bufs| {
            let masked = mxcsr();
            let mut r = Rng(0x5eed_0020);
            let (mut fast, mut words) = (0, 0);
            for case in 0..400 {
                let seed = r.next();
                let mut seen = [Vec::new(), Vec::new()];
                for k in 0..2 {
                    current(k);
                    glNewList(2, GL_COMPILE);
                    glColor3f(0.2, 0.9, 0.4);
                    glEndList();
                    if k == 1 {
                        // Invalid, divide-by-zero and overflow unmasked.
                        set_mxcsr(0x1900);
                    }
                    compile_case(&mut Rng(seed), &(*ctxs[k]).gl, &mut seen[k]);
                    set_mxcsr(masked);
                    glClearColor(0.0, 0.0, 0.0, 1.0);
                    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
                    glCallList(1);
                    // A list that ends inside its primitive leaves it open.
                    glEnd();
                    glGetError();
                    glFinish();
                }
                let lists = ctxs.map(|c| (*c).gl.lists.store.get(1).expect("list 1 defined"));
                assert!(*lists[0] == *lists[1], "case {case}: the lists differ\nfast: {:?}\ngeneral: {:?}", lists[0], lists[1]);
                words += lists[0].bytes();
                assert!(seen[0].iter().all(|&on| on), "case {case}: compile_fast set in every primitive of a masked caller: {:?}", seen[0]);
                assert!(seen[1].iter().all(|&on| !on), "case {case}: never set for a caller that unmasks");
                fast += seen[0].len();
                assert!(bufs[0] == bufs[1], "case {case}: the lists draw differently");
            }
            assert!(fast > 800 && words > 100_000, "primitives compiled on the fast path {fast}, list bytes {words}");
        });
    }
}
