//! Fog (GL 1.5 section 3.10).

use softgl::framebuffer::Config;
use softgl::gl::enums::*;
use softgl::gl::fog::*;
use softgl::gl::{Command, Context};
use softgl::render::fog::{GL_EXP, GL_EXP2, GL_LINEAR};

fn context() -> Context {
    let mut c = Context::new(Config { alpha_bits: 8, depth_bits: 24, stencil_bits: 8, accum_bits: 0 });
    c.fb.resize(8, 8).unwrap();
    c.surface_resized(8, 8);
    c.execute(&Command::MatrixMode(GL_PROJECTION));
    c.execute(&Command::Ortho([-1.0, 1.0, -1.0, 1.0, 0.0, 100.0]));
    c.execute(&Command::MatrixMode(GL_MODELVIEW));
    c
}

/// A window-filling quad at eye depth -dist; returns the centre pixel.
fn quad_at(c: &mut Context, dist: f32, color: [f32; 4]) -> [u8; 4] {
    c.execute(&Command::Color(color));
    c.execute(&Command::Rect([-1.0, -1.0, 1.0, 1.0]));
    let _ = dist;
    c.fb.color[c.fb.index(4, 4)]
}

fn set(c: &mut Context, pname: u32, v: f32) {
    c.execute(&Command::Fog(pname, [v, 0.0, 0.0, 0.0]));
}

fn want(f: f32, col: [f32; 4], fog: [f32; 4]) -> [u8; 4] {
    let m = |a: f32, b: f32| ((f * a + (1.0 - f) * b).clamp(0.0, 1.0) * 255.0 + 0.5) as u8;
    [m(col[0], fog[0]), m(col[1], fog[1]), m(col[2], fog[2]), (col[3] * 255.0 + 0.5) as u8]
}

#[test]
fn the_three_modes_at_a_known_distance() {
    let fog_color = [0.2, 0.4, 0.6, 0.0];
    let col = [1.0, 0.5, 0.0, 0.75];
    for (mode, f) in [(GL_LINEAR, (10.0f32 - 4.0) / (10.0 - 2.0)), (GL_EXP, (-0.1f32 * 4.0).exp()), (GL_EXP2, (-(0.1f32 * 4.0).powi(2)).exp())] {
        let mut c = context();
        c.execute(&Command::Enable(GL_FOG));
        c.execute(&Command::Fog(GL_FOG_COLOR, fog_color));
        set(&mut c, GL_FOG_MODE, mode as f32);
        set(&mut c, GL_FOG_START, 2.0);
        set(&mut c, GL_FOG_END, 10.0);
        set(&mut c, GL_FOG_DENSITY, 0.1);
        // The quad at eye z = -4.
        c.execute(&Command::Translate([0.0, 0.0, -4.0]));
        let got = quad_at(&mut c, 4.0, col);
        let w = want(f, col, fog_color);
        for i in 0..4 {
            assert!((got[i] as i32 - w[i] as i32).abs() <= 1, "mode {mode:#x}: {got:?} vs {w:?}");
        }
    }
}

#[test]
fn per_vertex_and_per_fragment_agree_for_linear_fog() {
    let draw = |hint: u32| {
        let mut c = context();
        c.execute(&Command::Enable(GL_FOG));
        c.execute(&Command::Hint(GL_FOG_HINT, hint));
        set(&mut c, GL_FOG_MODE, GL_LINEAR as f32);
        set(&mut c, GL_FOG_END, 50.0);
        c.execute(&Command::Fog(GL_FOG_COLOR, [1.0, 1.0, 1.0, 1.0]));
        c.execute(&Command::Color([0.0, 0.0, 0.0, 1.0]));
        c.execute(&Command::Begin(GL_QUADS));
        for v in [[-1.0, -1.0, -2.0], [1.0, -1.0, -40.0], [1.0, 1.0, -40.0], [-1.0, 1.0, -2.0]] {
            c.execute(&Command::Vertex([v[0], v[1], v[2], 1.0]));
        }
        c.execute(&Command::End);
        c.fb.color.to_vec()
    };
    let (a, b) = (draw(GL_NICEST), draw(GL_FASTEST));
    for (p, q) in a.iter().zip(&b) {
        assert!((p[0] as i32 - q[0] as i32).abs() <= 1, "{p:?} {q:?}");
    }
    // Fog grows left to right.
    assert!(a[a.len() - 1][0] > a[a.len() - 8][0] + 100);
}

#[test]
fn lines_and_points_are_fogged() {
    let mut c = context();
    c.execute(&Command::Enable(GL_FOG));
    set(&mut c, GL_FOG_MODE, GL_LINEAR as f32);
    set(&mut c, GL_FOG_END, 8.0);
    c.execute(&Command::Fog(GL_FOG_COLOR, [0.0, 0.0, 1.0, 1.0]));
    c.execute(&Command::Color([1.0, 0.0, 0.0, 1.0]));
    c.execute(&Command::Translate([0.0, 0.0, -4.0]));
    c.execute(&Command::Begin(GL_POINTS));
    c.execute(&Command::Vertex([0.125, 0.125, 0.0, 1.0]));
    c.execute(&Command::End);
    assert_eq!(c.fb.color[c.fb.index(4, 4)], [128, 0, 128, 255]);
    c.execute(&Command::Begin(GL_LINES));
    c.execute(&Command::Vertex([-1.0, -0.875, 0.0, 1.0]));
    c.execute(&Command::Vertex([1.0, -0.875, 0.0, 1.0]));
    c.execute(&Command::End);
    assert_eq!(c.fb.color[c.fb.index(3, 0)], [128, 0, 128, 255]);
}

#[test]
fn fog_errors_and_queries() {
    let mut c = context();
    set(&mut c, GL_FOG_MODE, 0x1234 as f32);
    assert_eq!(c.take_error(), GL_INVALID_ENUM);
    set(&mut c, GL_FOG_DENSITY, -1.0);
    assert_eq!(c.take_error(), GL_INVALID_VALUE);
    c.execute(&Command::Fog(0x1234, [0.0; 4]));
    assert_eq!(c.take_error(), GL_INVALID_ENUM);
    set(&mut c, GL_FOG_START, 3.5);
    let mut v = [0f32; 1];
    unsafe { c.get_into(GL_FOG_START, v.as_mut_ptr(), |x| x.as_f64().into_iter().map(|f| f as f32).collect()) };
    assert_eq!(v[0], 3.5);
    let mut m = [0i32; 1];
    unsafe { c.get_into(GL_FOG_MODE, m.as_mut_ptr(), softgl::gl::get::Value::as_i32) };
    assert_eq!(m[0] as u32, GL_EXP, "the initial mode");
}

/// GL 1.4 point parameters: distance attenuation and the size clamp.
#[test]
fn point_size_attenuation() {
    let count = |c: &Context| c.fb.color.iter().filter(|p| p[0] != 0).count();
    let draw = |att: [f32; 3], min: f32, max: f32| {
        let mut c = Context::new(Config { alpha_bits: 8, depth_bits: 24, stencil_bits: 8, accum_bits: 0 });
        c.fb.resize(32, 32).unwrap();
        c.surface_resized(32, 32);
        c.execute(&Command::MatrixMode(GL_PROJECTION));
        c.execute(&Command::Ortho([-1.0, 1.0, -1.0, 1.0, 0.0, 100.0]));
        c.execute(&Command::MatrixMode(GL_MODELVIEW));
        c.execute(&Command::Translate([0.0, 0.0, -4.0]));
        c.execute(&Command::PointSize(8.0));
        c.execute(&Command::PointParameter(0x8129, att));
        c.execute(&Command::PointParameter(0x8126, [min, 0.0, 0.0]));
        c.execute(&Command::PointParameter(0x8127, [max, 0.0, 0.0]));
        c.execute(&Command::Begin(GL_POINTS));
        c.execute(&Command::Vertex([0.0, 0.0, 0.0, 1.0]));
        c.execute(&Command::End);
        assert_eq!(c.take_error(), GL_NO_ERROR);
        count(&c)
    };
    assert_eq!(draw([1.0, 0.0, 0.0], 0.0, 64.0), 64, "no attenuation: 8x8");
    // d = 4: 1 / (0 + 0 + 1/4 * 16) = 1/4 -> sqrt = 1/2 -> size 4.
    assert_eq!(draw([0.0, 0.0, 0.25], 0.0, 64.0), 16);
    assert_eq!(draw([0.0, 0.0, 0.25], 6.0, 64.0), 36, "clamped up to the minimum");
    assert_eq!(draw([1.0, 0.0, 0.0], 0.0, 3.0), 9, "clamped down to the maximum");
}

/// GL_FOG_COORD_SRC = GL_FOG_COORD takes glFogCoord's value per vertex.
#[test]
fn fog_coordinate_source() {
    let mut c = context();
    c.execute(&Command::Enable(GL_FOG));
    set(&mut c, GL_FOG_MODE, GL_LINEAR as f32);
    set(&mut c, GL_FOG_END, 10.0);
    set(&mut c, GL_FOG_COORD_SRC, GL_FOG_COORD as f32);
    c.execute(&Command::Fog(GL_FOG_COLOR, [0.0, 0.0, 1.0, 1.0]));
    c.current.fog_coord = 7.5; // as glFogCoordf(7.5) leaves it
    // The quad is at eye distance 1; the fog coordinate says 7.5: f = 0.25.
    c.execute(&Command::Translate([0.0, 0.0, -1.0]));
    let got = quad_at(&mut c, 1.0, [1.0, 0.0, 0.0, 1.0]);
    assert_eq!(got, [64, 0, 191, 255]);
}
