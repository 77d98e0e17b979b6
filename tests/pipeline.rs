//! Rasterization properties checked through the GL state machine directly:
//! watertight meshes (also across clipping at the near plane and the guard
//! band), robustness against degenerate and non-finite input, and the
//! display-list path giving the same pixels as immediate mode.

use softgl::framebuffer::Config;
use softgl::gl::enums::*;
use softgl::gl::{Command, Context};

fn context(w: usize, h: usize) -> Context {
    let mut c = Context::new(Config { alpha_bits: 8, depth_bits: 24, stencil_bits: 8, accum_bits: 0 });
    c.fb.resize(w, h).unwrap();
    c.surface_resized(w as i32, h as i32);
    c
}

mod common;
use common::Rng;

type Tri = [[f32; 4]; 3];

/// Draws each triangle alone on a cleared buffer and counts, per pixel, how
/// many triangles covered it.
fn coverage_counts(c: &mut Context, tris: &[Tri]) -> Vec<u32> {
    let n = c.fb.width * c.fb.height;
    let mut counts = vec![0u32; n];
    for t in tris {
        c.execute(&Command::ClearColor([0.0; 4]));
        c.execute(&Command::Clear(GL_COLOR_BUFFER_BIT));
        c.execute(&Command::Color([1.0; 4]));
        c.execute(&Command::Begin(GL_TRIANGLES));
        for v in t {
            c.execute(&Command::Vertex(*v));
        }
        c.execute(&Command::End);
        for (i, px) in c.fb.color.iter().enumerate() {
            if px[0] != 0 {
                counts[i] += 1;
            }
        }
    }
    counts
}

/// A perturbed grid of quads split into triangles, covering `rect` exactly.
fn grid(rng: &mut Rng, n: usize, rect: [f32; 4], z: impl Fn(f32, f32) -> f32) -> Vec<Tri> {
    let [x0, y0, x1, y1] = rect;
    let mut p = vec![[0f32; 2]; (n + 1) * (n + 1)];
    for j in 0..=n {
        for i in 0..=n {
            let mut x = x0 + (x1 - x0) * i as f32 / n as f32;
            let mut y = y0 + (y1 - y0) * j as f32 / n as f32;
            if i > 0 && i < n {
                x += (rng.f24() - 0.5) * (x1 - x0) / n as f32 * 0.6;
            }
            if j > 0 && j < n {
                y += (rng.f24() - 0.5) * (y1 - y0) / n as f32 * 0.6;
            }
            p[j * (n + 1) + i] = [x, y];
        }
    }
    let v = |i: usize, j: usize| {
        let [x, y] = p[j * (n + 1) + i];
        [x, y, z(x, y), 1.0]
    };
    let mut tris = Vec::new();
    for j in 0..n {
        for i in 0..n {
            tris.push([v(i, j), v(i + 1, j), v(i + 1, j + 1)]);
            tris.push([v(i, j), v(i + 1, j + 1), v(i, j + 1)]);
        }
    }
    tris
}

#[test]
fn perturbed_grid_is_watertight_in_ortho() {
    let mut c = context(64, 64);
    c.execute(&Command::MatrixMode(GL_PROJECTION));
    c.execute(&Command::Ortho([0.0, 64.0, 0.0, 64.0, -1.0, 1.0]));
    let mut rng = Rng(7);
    for round in 0..4 {
        let tris = grid(&mut rng, 9, [3.3, 2.7, 60.1 + round as f32 * 0.25, 61.9], |_, _| 0.0);
        let counts = coverage_counts(&mut c, &tris);
        assert!(counts.iter().all(|&n| n <= 1), "a pixel was drawn twice");
        // Every pixel whose centre is well inside the grid's outer edges is drawn.
        for y in 4..61 {
            for x in 4..59 {
                assert_eq!(counts[y * 64 + x], 1, "pixel {x},{y} missed");
            }
        }
    }
}

#[test]
fn fan_with_pixel_centre_vertices_is_watertight() {
    let mut c = context(48, 48);
    c.execute(&Command::MatrixMode(GL_PROJECTION));
    c.execute(&Command::Ortho([0.0, 48.0, 0.0, 48.0, -1.0, 1.0]));
    // Centre exactly on a pixel centre; rim vertices on pixel centres and
    // edges, so many edges pass exactly through sample points.
    let centre = [24.5f32, 24.5, 0.0, 1.0];
    let rim: Vec<[f32; 4]> = (0..32)
        .map(|i| {
            let a = i as f32 / 32.0 * std::f32::consts::TAU;
            [(24.5 + 20.0 * a.cos()).round() + 0.5, (24.5 + 20.0 * a.sin()).round(), 0.0, 1.0]
        })
        .collect();
    let tris: Vec<Tri> = (0..rim.len()).map(|i| [centre, rim[i], rim[(i + 1) % rim.len()]]).collect();
    let counts = coverage_counts(&mut c, &tris);
    assert!(counts.iter().all(|&n| n <= 1), "a pixel was drawn twice");
    let inner = counts.iter().enumerate().filter(|(i, _)| {
        let (x, y) = ((i % 48) as f32 + 0.5, (i / 48) as f32 + 0.5);
        (x - 24.5).hypot(y - 24.5) < 17.0
    });
    for (i, &n) in inner {
        assert_eq!(n, 1, "pixel {},{} missed", i % 48, i / 48);
    }
}

#[test]
fn clipped_perspective_mesh_is_watertight() {
    // A grid that crosses the near plane and extends past the guard band:
    // new vertices from clipping must coincide on shared edges.
    let mut c = context(64, 64);
    c.execute(&Command::MatrixMode(GL_PROJECTION));
    c.execute(&Command::Frustum([-1.0, 1.0, -1.0, 1.0, 1.0, 100.0]));
    c.execute(&Command::MatrixMode(GL_MODELVIEW));
    c.execute(&Command::Rotate(70.0, [1.0, 0.0, 0.0]));
    c.execute(&Command::Translate([0.0, 2.0, -3.0]));
    let mut rng = Rng(99);
    let tris = grid(&mut rng, 12, [-300.0, -300.0, 300.0, 300.0], |_, _| 0.0);
    let counts = coverage_counts(&mut c, &tris);
    assert!(counts.iter().all(|&n| n <= 1), "a pixel was drawn twice");
    let drawn = counts.iter().filter(|&&n| n == 1).count();
    assert!(drawn > 64 * 20, "the plane should cover a good part of the view, got {drawn}");
    // Holes: a covered pixel's 4 neighbours inside the covered region's rows
    // must not be empty when both of their horizontal neighbours are covered.
    for y in 0..64 {
        for x in 1..63 {
            let i = y * 64 + x;
            if counts[i - 1] == 1 && counts[i + 1] == 1 {
                assert_eq!(counts[i], 1, "crack at {x},{y}");
            }
        }
    }
}

#[test]
fn non_finite_and_huge_vertices_do_not_panic() {
    let mut c = context(32, 32);
    let bad = [f32::NAN, f32::INFINITY, f32::NEG_INFINITY, 1e30, -1e30, 1e-30, 0.0];
    for &a in &bad {
        for &b in &bad {
            for mode in [GL_TRIANGLES, GL_TRIANGLE_STRIP, GL_TRIANGLE_FAN, GL_QUADS, GL_QUAD_STRIP, GL_POLYGON] {
                c.execute(&Command::Begin(mode));
                for v in [[a, b, 0.0, 1.0], [0.5, b, a, 1.0], [b, 0.5, 0.0, a], [a, a, b, b], [0.0, 0.0, 0.0, 0.0]] {
                    c.execute(&Command::Vertex(v));
                }
                c.execute(&Command::End);
            }
        }
    }
    assert_eq!(c.take_error(), GL_NO_ERROR);
}

#[test]
fn singular_matrix_draws_nothing_and_stays_finite() {
    // The book's planar shadow: glScalef(1, 0, 1) flattens geometry.
    let mut c = context(16, 16);
    c.execute(&Command::Scale([1.0, 0.0, 1.0]));
    c.execute(&Command::Begin(GL_TRIANGLES));
    for v in [[-1.0, -1.0, 0.0, 1.0], [1.0, -1.0, 0.0, 1.0], [0.0, 1.0, 0.0, 1.0]] {
        c.execute(&Command::Vertex(v));
    }
    c.execute(&Command::End);
    assert!(c.fb.color.iter().all(|p| *p == [0, 0, 0, 0]));
}

#[test]
fn display_list_replays_like_immediate_mode() {
    let draw = |c: &mut Context, compile: bool| {
        let cmds = [
            Command::Clear(GL_COLOR_BUFFER_BIT),
            Command::Begin(GL_TRIANGLE_FAN),
            Command::Color([1.0, 0.0, 0.0, 1.0]),
            Command::Vertex([0.0, 0.0, 0.0, 1.0]),
            Command::Color([0.0, 1.0, 0.0, 1.0]),
            Command::Vertex([0.9, 0.1, 0.0, 1.0]),
            Command::Vertex([0.5, 0.8, 0.0, 1.0]),
            Command::Color([0.0, 0.0, 1.0, 1.0]),
            Command::Vertex([-0.7, 0.6, 0.0, 1.0]),
            Command::End,
        ];
        if compile {
            let n = c.gen_lists(1);
            c.new_list(n, GL_COMPILE);
            for cmd in cmds {
                c.submit(cmd);
            }
            c.end_list();
            assert!(c.fb.color.iter().all(|p| *p == [0, 0, 0, 0]), "GL_COMPILE must not draw");
            c.submit(Command::CallList(n));
        } else {
            for cmd in cmds {
                c.submit(cmd);
            }
        }
        c.fb.color.to_vec()
    };
    let a = draw(&mut context(24, 24), false);
    let b = draw(&mut context(24, 24), true);
    assert!(a.iter().any(|p| p[0] > 0));
    assert_eq!(a, b);
}

#[test]
fn errors_follow_the_spec() {
    let mut c = context(8, 8);
    c.execute(&Command::Begin(0x7777));
    assert_eq!(c.take_error(), GL_INVALID_ENUM);
    c.execute(&Command::End);
    assert_eq!(c.take_error(), GL_INVALID_OPERATION);
    c.execute(&Command::Begin(GL_TRIANGLES));
    c.execute(&Command::Clear(GL_COLOR_BUFFER_BIT));
    c.execute(&Command::Viewport(0, 0, 1, 1));
    // The first error is kept.
    assert_eq!(c.take_error(), GL_INVALID_OPERATION);
    assert_eq!(c.take_error(), GL_NO_ERROR);
    c.execute(&Command::End);
    c.execute(&Command::PopMatrix);
    assert_eq!(c.take_error(), GL_STACK_UNDERFLOW);
    for _ in 0..40 {
        c.execute(&Command::PushMatrix);
    }
    assert_eq!(c.take_error(), GL_STACK_OVERFLOW);
    c.execute(&Command::Clear(0x8000_0000));
    assert_eq!(c.take_error(), GL_INVALID_VALUE);
}

#[test]
fn extension_names_resolve_to_core_functions() {
    use softgl::api::proc_address;
    assert_eq!(proc_address(b"glActiveTextureARB"), proc_address(b"glActiveTexture"));
    assert!(!proc_address(b"glActiveTexture").is_null());
    assert_eq!(proc_address(b"glBlendEquationEXT"), proc_address(b"glBlendEquation"));
    // EXT_vertex_array's pointer calls take a count: their own functions,
    // not aliases of the core ones.
    assert!(!proc_address(b"glVertexPointerEXT").is_null());
    assert_ne!(proc_address(b"glVertexPointerEXT"), proc_address(b"glVertexPointer"));
    assert!(proc_address(b"glNoSuchFunction").is_null());
    // Every advertised extension name is well formed.
    let ext = softgl::gl::get::string(GL_EXTENSIONS).unwrap();
    let ext = std::str::from_utf8(&ext[..ext.len() - 1]).unwrap();
    assert!(ext.ends_with(' '), "a separator after the last name, as Mesa's string has");
    assert!(ext.split_whitespace().all(|e| e.starts_with("GL_")));
    assert!(ext.contains("GL_EXT_bgra") && ext.contains("GL_ARB_multitexture"));
}
