//! Evaluators (GL 1.5 section 5.1), observed through feedback mode.

use softgl::framebuffer::Config;
use softgl::gl::enums::*;
use softgl::gl::eval::{GL_COEFF, GL_DOMAIN, GL_ORDER};
use softgl::gl::select::*;
use softgl::gl::{Command, Context};

fn context() -> Context {
    let mut c = Context::new(Config { alpha_bits: 8, depth_bits: 24, stencil_bits: 8, accum_bits: 0 });
    c.fb.resize(100, 100).unwrap();
    c.surface_resized(100, 100);
    c.execute(&Command::MatrixMode(GL_PROJECTION));
    c.execute(&Command::Ortho([0.0, 100.0, 0.0, 100.0, -10.0, 10.0]));
    c.execute(&Command::MatrixMode(GL_MODELVIEW));
    c
}

const MAP1_VERTEX_3: u32 = GL_MAP1_COLOR_4 + 7;
const MAP1_COLOR_4: u32 = GL_MAP1_COLOR_4;
const MAP2_VERTEX_3: u32 = GL_MAP2_COLOR_4 + 7;

fn feedback(c: &mut Context, ty: u32, f: impl FnOnce(&mut Context)) -> Vec<f32> {
    let mut buf = vec![0f32; 4096];
    c.feedback_buffer(4096, ty, buf.as_mut_ptr());
    c.render_mode(GL_FEEDBACK);
    f(c);
    let n = c.render_mode(GL_RENDER);
    assert!(n >= 0);
    buf.truncate(n as usize);
    buf
}

#[test]
fn quadratic_bezier_curve() {
    let mut c = context();
    // Control points (10,10), (50,90), (90,10) over u in [2, 4].
    let pts = vec![10.0, 10.0, 0.0, 50.0, 90.0, 0.0, 90.0, 10.0, 0.0];
    c.map(MAP1_VERTEX_3, (2.0, 4.0), 3, None, pts);
    c.execute(&Command::Enable(MAP1_VERTEX_3));
    let fb = feedback(&mut c, GL_2D, |c| {
        c.execute(&Command::Begin(GL_POINTS));
        for u in [2.0, 2.5, 3.0, 4.0] {
            c.execute(&Command::EvalCoord(u, None));
        }
        c.execute(&Command::End);
    });
    let bez = |t: f32| {
        let (a, b, d) = ((1.0 - t) * (1.0 - t), 2.0 * t * (1.0 - t), t * t);
        [a * 10.0 + b * 50.0 + d * 90.0, a * 10.0 + b * 90.0 + d * 10.0]
    };
    let mut want = Vec::new();
    for t in [0.0, 0.25, 0.5, 1.0] {
        want.push(0x0701 as f32);
        want.extend(bez(t));
    }
    assert_eq!(fb.len(), want.len(), "{fb:?}");
    for (a, b) in fb.iter().zip(&want) {
        assert!((a - b).abs() < 1e-3, "{fb:?} vs {want:?}");
    }
    // Grid and mesh: 4 segments give a strip of 4 lines.
    let fb = feedback(&mut c, GL_2D, |c| {
        c.execute(&Command::MapGrid(4, (2.0, 4.0), None));
        c.execute(&Command::EvalMesh1(GL_LINE, 0, 4));
    });
    assert_eq!(fb.len(), 4 * 5);
    assert!((fb[fb.len() - 2] - 90.0).abs() < 1e-4 && (fb[fb.len() - 1] - 10.0).abs() < 1e-4, "the mesh ends at u2 exactly");
}

#[test]
fn colour_map_does_not_change_the_current_colour() {
    let mut c = context();
    c.map(MAP1_VERTEX_3, (0.0, 1.0), 2, None, vec![10.0, 10.0, 0.0, 90.0, 10.0, 0.0]);
    c.map(MAP1_COLOR_4, (0.0, 1.0), 2, None, vec![1.0, 0.0, 0.0, 1.0, 0.0, 0.0, 1.0, 1.0]);
    c.execute(&Command::Enable(MAP1_VERTEX_3));
    c.execute(&Command::Enable(MAP1_COLOR_4));
    c.execute(&Command::Color([0.0, 1.0, 0.0, 1.0]));
    let fb = feedback(&mut c, GL_3D_COLOR, |c| {
        c.execute(&Command::Begin(GL_POINTS));
        c.execute(&Command::EvalCoord(0.25, None));
        c.execute(&Command::Vertex([5.0, 5.0, 0.0, 1.0]));
        c.execute(&Command::End);
    });
    // token x y z r g b a
    assert_eq!(&fb[4..8], &[0.75, 0.0, 0.25, 1.0]);
    assert_eq!(&fb[12..16], &[0.0, 1.0, 0.0, 1.0]);
}

#[test]
fn auto_normal_faces_the_right_way() {
    let mut c = context();
    // A bilinear patch in z = 0 whose u runs along +x and v along +y: the
    // normal du x dv is +z. Lit by the default light 0 (from +z).
    let pts = vec![10.0, 10.0, 0.0, 10.0, 90.0, 0.0, 90.0, 10.0, 0.0, 90.0, 90.0, 0.0]; // u-major: p(u, v)
    c.map(MAP2_VERTEX_3, (0.0, 1.0), 2, Some(((0.0, 1.0), 2)), pts);
    c.execute(&Command::Enable(MAP2_VERTEX_3));
    c.execute(&Command::Enable(GL_AUTO_NORMAL));
    c.execute(&Command::Enable(GL_LIGHTING));
    c.execute(&Command::Enable(GL_LIGHT0));
    c.execute(&Command::Enable(GL_NORMALIZE));
    let fb = feedback(&mut c, GL_3D_COLOR, |c| {
        c.execute(&Command::Begin(GL_POINTS));
        c.execute(&Command::EvalCoord(0.5, Some(0.5)));
        c.execute(&Command::End);
    });
    assert!((fb[1] - 50.0).abs() < 1e-4 && (fb[2] - 50.0).abs() < 1e-4);
    // 0.2 * 0.2 (scene ambient) + 0.8 (diffuse, n.l = 1) = 0.84
    assert!((fb[4] - 0.84).abs() < 1e-3, "{fb:?}");
    // The mesh covers the patch: FILL draws 2 x 2 quads = 8 triangles.
    c.execute(&Command::Disable(GL_LIGHTING));
    let fb = feedback(&mut c, GL_2D, |c| {
        c.execute(&Command::MapGrid(2, (0.0, 1.0), Some((2, (0.0, 1.0)))));
        c.execute(&Command::EvalMesh2(GL_FILL, 0, 2, 0, 2));
    });
    assert_eq!(fb.len(), 8 * (2 + 3 * 2));
}

#[test]
fn map_errors_and_queries() {
    let mut c = context();
    c.map(0x1234, (0.0, 1.0), 2, None, vec![]);
    assert_eq!(c.take_error(), GL_INVALID_ENUM);
    c.map(MAP1_VERTEX_3, (1.0, 1.0), 2, None, vec![0.0; 6]);
    assert_eq!(c.take_error(), GL_INVALID_VALUE);
    c.map(MAP1_VERTEX_3, (0.0, 1.0), 0, None, vec![]);
    assert_eq!(c.take_error(), GL_INVALID_VALUE);
    let r = unsafe { softgl::gl::eval::read_points(MAP1_VERTEX_3, [0f32; 6].as_ptr(), 2, 2, 0, 1) };
    assert_eq!(r, Err(GL_INVALID_VALUE), "stride below the component count");
    c.execute(&Command::EvalMesh1(GL_FILL, 0, 1));
    assert_eq!(c.take_error(), GL_INVALID_ENUM);
    c.map(MAP1_VERTEX_3, (2.0, 3.0), 2, None, vec![1.0, 2.0, 3.0, 4.0, 5.0, 6.0]);
    assert_eq!(c.get_map(MAP1_VERTEX_3, GL_ORDER), Some(vec![2.0]));
    assert_eq!(c.get_map(MAP1_VERTEX_3, GL_DOMAIN), Some(vec![2.0, 3.0]));
    assert_eq!(c.get_map(MAP1_VERTEX_3, GL_COEFF), Some(vec![1.0, 2.0, 3.0, 4.0, 5.0, 6.0]));
    assert_eq!(c.get_map(MAP2_VERTEX_3, GL_ORDER), Some(vec![1.0, 1.0]));
}

#[test]
fn texture_coordinate_maps_feed_unit_0_and_the_widest_wins() {
    let mut c = context();
    // A line of two control points, with s from 0 to 1 (TEXTURE_COORD_1)
    // and (s, t) from (0, 1) to (1, 0) (TEXTURE_COORD_2).
    c.map(MAP1_VERTEX_3, (0.0, 1.0), 2, None, vec![10.0, 10.0, 0.0, 30.0, 10.0, 0.0]);
    c.map(GL_MAP1_COLOR_4 + 3, (0.0, 1.0), 2, None, vec![0.0, 1.0]);
    c.map(GL_MAP1_COLOR_4 + 4, (0.0, 1.0), 2, None, vec![0.0, 1.0, 1.0, 0.0]);
    c.execute(&Command::Enable(MAP1_VERTEX_3));
    c.execute(&Command::Enable(GL_MAP1_COLOR_4 + 3));
    c.execute(&Command::TexCoord(0x84C0, [0.5, 0.5, 0.5, 0.5]));
    let fb = feedback(&mut c, GL_3D_COLOR_TEXTURE, |c| {
        c.execute(&Command::Begin(GL_POINTS));
        c.execute(&Command::EvalCoord(0.25, None));
        c.execute(&Command::End);
        c.execute(&Command::Enable(GL_MAP1_COLOR_4 + 4));
        c.execute(&Command::Begin(GL_POINTS));
        c.execute(&Command::EvalCoord(0.25, None));
        c.execute(&Command::End);
    });
    // Token, x y z, colour, s t r q.
    assert_eq!(fb.len(), 24);
    assert_eq!(&fb[8..12], &[0.25, 0.0, 0.0, 1.0]);
    assert_eq!(&fb[20..24], &[0.25, 0.75, 0.0, 1.0]);
    assert!((fb[1] - 15.0).abs() < 1e-4);
    // The current texture coordinates did not change.
    assert_eq!(c.current.tex_coords[0], [0.5, 0.5, 0.5, 0.5]);
}
