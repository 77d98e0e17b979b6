//! User clip planes (GL 1.5 section 2.12).

use softgl::framebuffer::Config;
use softgl::gl::enums::*;
use softgl::gl::{Command, Context};

fn context() -> Context {
    let mut c = Context::new(Config { alpha_bits: 8, depth_bits: 24, stencil_bits: 8, accum_bits: 0 });
    c.fb.resize(32, 32).unwrap();
    c.surface_resized(32, 32);
    c.execute(&Command::MatrixMode(GL_PROJECTION));
    c.execute(&Command::Ortho([0.0, 32.0, 0.0, 32.0, -1.0, 1.0]));
    c.execute(&Command::MatrixMode(GL_MODELVIEW));
    c
}

fn covered(c: &Context) -> Vec<(usize, usize)> {
    let mut v = Vec::new();
    for y in 0..c.fb.height {
        for x in 0..c.fb.width {
            if c.fb.color[c.fb.index(x, y)][0] != 0 {
                v.push((x, y));
            }
        }
    }
    v
}

fn full_quad(c: &mut Context) {
    c.execute(&Command::Color([1.0; 4]));
    c.execute(&Command::Rect([0.0, 0.0, 32.0, 32.0]));
}

#[test]
fn a_plane_cuts_a_quad_exactly() {
    let mut c = context();
    // Keep x <= 10.25: -x + 10.25 >= 0.
    c.execute(&Command::ClipPlane(GL_CLIP_PLANE0 + 2, [-1.0, 0.0, 0.0, 10.25]));
    c.execute(&Command::Enable(GL_CLIP_PLANE0 + 2));
    full_quad(&mut c);
    let px = covered(&c);
    assert_eq!(px.len(), 10 * 32, "columns 0..9 have centres at most 9.5 <= 10.25");
    assert!(px.iter().all(|&(x, _)| x < 10));
    assert!(c.is_enabled(GL_CLIP_PLANE0 + 2).unwrap());
}

#[test]
fn planes_are_stored_in_eye_space_at_specification() {
    let mut c = context();
    // Under a translation by (8, 0): the plane x >= 0 in object space is
    // x_eye >= 8.
    c.execute(&Command::Translate([8.0, 0.0, 0.0]));
    c.execute(&Command::ClipPlane(GL_CLIP_PLANE0, [1.0, 0.0, 0.0, 0.0]));
    assert_eq!(c.get_clip_plane(GL_CLIP_PLANE0), Some([1.0, 0.0, 0.0, -8.0]));
    c.execute(&Command::LoadIdentity);
    // A later projection change does not move the plane in eye space.
    c.execute(&Command::MatrixMode(GL_PROJECTION));
    c.execute(&Command::LoadIdentity);
    c.execute(&Command::Ortho([0.0, 64.0, 0.0, 32.0, -1.0, 1.0]));
    c.execute(&Command::MatrixMode(GL_MODELVIEW));
    c.execute(&Command::Enable(GL_CLIP_PLANE0));
    full_quad(&mut c);
    // Window x = eye x / 2: eye x >= 8 is window x >= 4; the quad ends at
    // window 16.
    let px = covered(&c);
    assert!(px.iter().all(|&(x, _)| (4..16).contains(&x)));
    assert_eq!(px.len(), 12 * 32);
}

#[test]
fn two_triangles_sharing_a_clipped_edge_stay_watertight() {
    let mut c = context();
    c.execute(&Command::ClipPlane(GL_CLIP_PLANE0, [0.3, 1.0, 0.0, -9.7]));
    c.execute(&Command::Enable(GL_CLIP_PLANE0));
    let tris = [[[1.3f32, 2.1], [30.2, 27.9], [2.7, 30.6]], [[1.3, 2.1], [29.1, 1.4], [30.2, 27.9]]];
    let mut counts = vec![0u32; 32 * 32];
    for t in tris {
        c.execute(&Command::ClearColor([0.0; 4]));
        c.execute(&Command::Clear(GL_COLOR_BUFFER_BIT));
        c.execute(&Command::Color([1.0; 4]));
        c.execute(&Command::Begin(GL_TRIANGLES));
        for v in t {
            c.execute(&Command::Vertex([v[0], v[1], 0.0, 1.0]));
        }
        c.execute(&Command::End);
        for (x, y) in covered(&c) {
            counts[y * 32 + x] += 1;
        }
    }
    assert!(counts.iter().all(|&n| n <= 1));
    // Pixels well inside both the union and the kept half-space are drawn.
    for y in 14..26 {
        for x in 8..24 {
            let kept = 0.3 * (x as f32 + 0.5) + (y as f32 + 0.5) - 9.7 > 0.5;
            if kept {
                assert_eq!(counts[y * 32 + x], 1, "pixel {x},{y}");
            }
        }
    }
}

#[test]
fn lines_and_points_are_clipped_too() {
    let mut c = context();
    c.execute(&Command::ClipPlane(GL_CLIP_PLANE0 + 5, [0.0, -1.0, 0.0, 16.0]));
    c.execute(&Command::Enable(GL_CLIP_PLANE0 + 5));
    c.execute(&Command::Color([1.0; 4]));
    c.execute(&Command::Begin(GL_LINES));
    c.execute(&Command::Vertex([5.5, 0.0, 0.0, 1.0]));
    c.execute(&Command::Vertex([5.5, 32.0, 0.0, 1.0]));
    c.execute(&Command::End);
    c.execute(&Command::Begin(GL_POINTS));
    c.execute(&Command::Vertex([20.5, 10.5, 0.0, 1.0]));
    c.execute(&Command::Vertex([20.5, 20.5, 0.0, 1.0]));
    c.execute(&Command::End);
    let px = covered(&c);
    assert!(px.iter().all(|&(_, y)| y < 16), "{px:?}");
    assert!(px.contains(&(20, 10)) && !px.contains(&(20, 20)));
    assert_eq!(px.iter().filter(|&&(x, _)| x == 5).count(), 16);
}

#[test]
fn clip_plane_errors() {
    let mut c = context();
    c.execute(&Command::ClipPlane(GL_CLIP_PLANE0 + 6, [0.0; 4]));
    assert_eq!(c.take_error(), GL_INVALID_ENUM);
    c.execute(&Command::Enable(GL_CLIP_PLANE0 + 6));
    assert_eq!(c.take_error(), GL_INVALID_ENUM);
}

#[test]
fn raster_position_respects_clip_planes_and_latches_texcoords() {
    let mut c = context();
    c.current.tex_coords[1] = [0.25, 0.5, 0.0, 1.0];
    c.execute(&Command::RasterPos([4.0, 4.0, 0.0, 1.0]));
    assert!(c.raster.valid);
    assert_eq!(c.raster.tex[1], [0.25, 0.5, 0.0, 1.0]);
    // Keep x <= 2: the raster position at x = 4 is clipped away.
    c.execute(&Command::ClipPlane(GL_CLIP_PLANE0, [-1.0, 0.0, 0.0, 2.0]));
    c.execute(&Command::Enable(GL_CLIP_PLANE0));
    c.execute(&Command::RasterPos([4.0, 4.0, 0.0, 1.0]));
    assert!(!c.raster.valid);
    c.execute(&Command::RasterPos([1.0, 4.0, 0.0, 1.0]));
    assert!(c.raster.valid);
}
