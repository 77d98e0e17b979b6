//! Lighting (GL 1.5 section 2.14) checked pixel by pixel against the
//! lighting equation written out independently here, on a screen-filling
//! quad whose four vertices share one eye position's worth of geometry
//! (a flat-shaded quad takes its last vertex's lit colour).

use softgl::framebuffer::Config;
use softgl::gl::enums::*;
use softgl::gl::{Command, Context};

fn context() -> Context {
    let mut c = Context::new(Config { alpha_bits: 8, depth_bits: 24, stencil_bits: 8, accum_bits: 0 });
    c.fb.resize(8, 8).unwrap();
    c.surface_resized(8, 8);
    c
}

/// Draws a flat-shaded quad filling the window in the plane z = `z` (eye
/// space, identity modelview, ortho projection) with normal `n`, and
/// returns the centre pixel.
fn lit_quad(c: &mut Context, z: f32, n: [f32; 3]) -> [u8; 4] {
    c.execute(&Command::MatrixMode(GL_PROJECTION));
    c.execute(&Command::LoadIdentity);
    c.execute(&Command::Ortho([-1.0, 1.0, -1.0, 1.0, -100.0, 100.0]));
    c.execute(&Command::MatrixMode(GL_MODELVIEW));
    c.execute(&Command::ShadeModel(GL_FLAT));
    c.execute(&Command::Normal(n));
    c.execute(&Command::Begin(GL_QUADS));
    for v in [[-1.0, -1.0], [1.0, -1.0], [1.0, 1.0], [0.0, 0.0]] {
        // The last (provoking) vertex sits at the origin of the plane.
        c.execute(&Command::Vertex([v[0], v[1], z, 1.0]));
    }
    c.execute(&Command::End);
    // The quad is degenerate-free: (-1,-1), (1,-1), (1,1), (0,0) covers
    // the lower-right half; read a pixel there.
    c.fb.color[c.fb.index(6, 1)]
}

fn to_u8(c: [f32; 3]) -> [u8; 3] {
    c.map(|v| (v.clamp(0.0, 1.0) * 255.0 + 0.5) as u8)
}

fn close(got: [u8; 4], want: [u8; 3], what: &str) {
    for i in 0..3 {
        assert!((got[i] as i32 - want[i] as i32).abs() <= 1, "{what}: got {got:?}, want {want:?}");
    }
}

#[test]
fn directional_diffuse_ambient_and_emission() {
    let mut c = context();
    c.execute(&Command::Enable(GL_LIGHTING));
    c.execute(&Command::Enable(GL_LIGHT0));
    // Light from direction (0, 0.6, 0.8); normal (0, 0, 1): n.l = 0.8.
    c.execute(&Command::Light(GL_LIGHT0, GL_POSITION, [0.0, 0.6, 0.8, 0.0]));
    c.execute(&Command::Light(GL_LIGHT0, GL_AMBIENT, [0.1, 0.2, 0.3, 1.0]));
    c.execute(&Command::Material(GL_FRONT, GL_DIFFUSE, [0.5, 0.25, 1.0, 1.0]));
    c.execute(&Command::Material(GL_FRONT, GL_EMISSION, [0.05, 0.0, 0.0, 1.0]));
    let got = lit_quad(&mut c, 0.0, [0.0, 0.0, 1.0]);
    // e + a_cm * a_scene (0.2) + a_cm * a_light + 0.8 * d_cm * d_light(1)
    let a = 0.2f32;
    let want = [
        0.05 + a * 0.2 + a * 0.1 + 0.8 * 0.5,
        a * 0.2 + a * 0.2 + 0.8 * 0.25,
        a * 0.2 + a * 0.3 + 0.8 * 1.0,
    ];
    close(got, to_u8(want), "directional");
    // Facing away from the light: ambient and emission only.
    let got = lit_quad(&mut c, 0.0, [0.0, -0.6, -0.8]);
    close(got, to_u8([0.05 + a * 0.2 + a * 0.1, a * 0.2 + a * 0.2, a * 0.2 + a * 0.3]), "facing away");
}

#[test]
fn positional_light_with_attenuation_and_specular() {
    let mut c = context();
    c.execute(&Command::Enable(GL_LIGHTING));
    c.execute(&Command::Enable(GL_LIGHT0));
    c.execute(&Command::LightModel(GL_LIGHT_MODEL_AMBIENT, [0.0, 0.0, 0.0, 1.0]));
    // Light 3 units in front of the plane point (0, 0, -5).
    c.execute(&Command::Light(GL_LIGHT0, GL_POSITION, [0.0, 0.0, -2.0, 1.0]));
    c.execute(&Command::Light(GL_LIGHT0, GL_CONSTANT_ATTENUATION, [0.5, 0.0, 0.0, 0.0]));
    c.execute(&Command::Light(GL_LIGHT0, GL_QUADRATIC_ATTENUATION, [0.1, 0.0, 0.0, 0.0]));
    c.execute(&Command::Material(GL_FRONT, GL_DIFFUSE, [0.5, 0.5, 0.5, 1.0]));
    c.execute(&Command::Material(GL_FRONT, GL_AMBIENT, [0.0, 0.0, 0.0, 1.0]));
    c.execute(&Command::Material(GL_FRONT, GL_SPECULAR, [0.3, 0.3, 0.3, 1.0]));
    c.execute(&Command::Material(GL_FRONT, GL_SHININESS, [10.0, 0.0, 0.0, 0.0]));
    let got = lit_quad(&mut c, -5.0, [0.0, 0.0, 1.0]);
    // d = 3: att = 1 / (0.5 + 0.1 * 9) = 1/1.4; n.l = 1; non-local viewer
    // h = normalize((0,0,1) + (0,0,1)) = (0,0,1): n.h = 1.
    let att = 1.0 / 1.4f32;
    let v = att * (0.5 + 0.3);
    close(got, to_u8([v, v, v]), "positional");
    // With a local viewer at the origin the half vector is the same here.
    c.execute(&Command::LightModel(GL_LIGHT_MODEL_LOCAL_VIEWER, [1.0, 0.0, 0.0, 0.0]));
    close(lit_quad(&mut c, -5.0, [0.0, 0.0, 1.0]), to_u8([v, v, v]), "local viewer");
    // Separate specular gives the same sum without texturing.
    c.execute(&Command::LightModel(GL_LIGHT_MODEL_COLOR_CONTROL, [GL_SEPARATE_SPECULAR_COLOR as f32, 0.0, 0.0, 0.0]));
    close(lit_quad(&mut c, -5.0, [0.0, 0.0, 1.0]), to_u8([v, v, v]), "separate specular");
}

#[test]
fn spot_cutoff_and_exponent() {
    let mut c = context();
    c.execute(&Command::Enable(GL_LIGHTING));
    c.execute(&Command::Enable(GL_LIGHT0));
    c.execute(&Command::LightModel(GL_LIGHT_MODEL_AMBIENT, [0.0, 0.0, 0.0, 1.0]));
    c.execute(&Command::Material(GL_FRONT, GL_AMBIENT, [0.0, 0.0, 0.0, 1.0]));
    c.execute(&Command::Material(GL_FRONT, GL_DIFFUSE, [1.0, 1.0, 1.0, 1.0]));
    c.execute(&Command::Light(GL_LIGHT0, GL_POSITION, [0.0, 0.0, 0.0, 1.0]));
    // The vertex at (0,0,-4) is 30 degrees off a spot pointing along
    // (sin 30, 0, -cos 30)... pointing at (tan30*4, 0, -4).
    let a = 30f32.to_radians();
    c.execute(&Command::Light(GL_LIGHT0, GL_SPOT_DIRECTION, [a.sin(), 0.0, -a.cos(), 0.0]));
    c.execute(&Command::Light(GL_LIGHT0, GL_SPOT_CUTOFF, [45.0, 0.0, 0.0, 0.0]));
    c.execute(&Command::Light(GL_LIGHT0, GL_SPOT_EXPONENT, [2.0, 0.0, 0.0, 0.0]));
    let spot = a.cos().powi(2);
    close(lit_quad(&mut c, -4.0, [0.0, 0.0, 1.0]), to_u8([spot; 3]), "inside the cone");
    c.execute(&Command::Light(GL_LIGHT0, GL_SPOT_CUTOFF, [20.0, 0.0, 0.0, 0.0]));
    close(lit_quad(&mut c, -4.0, [0.0, 0.0, 1.0]), [0, 0, 0], "outside the cone");
    // Invalid values change nothing.
    c.execute(&Command::Light(GL_LIGHT0, GL_SPOT_CUTOFF, [100.0, 0.0, 0.0, 0.0]));
    assert_eq!(c.take_error(), GL_INVALID_VALUE);
    assert_eq!(c.get_light(GL_LIGHT0, GL_SPOT_CUTOFF), Some(vec![20.0]));
}

#[test]
fn light_position_uses_the_modelview_at_specification() {
    let mut c = context();
    c.execute(&Command::Rotate(90.0, [1.0, 0.0, 0.0]));
    c.execute(&Command::Light(GL_LIGHT0, GL_POSITION, [0.0, 0.0, 1.0, 0.0]));
    let p = c.get_light(GL_LIGHT0, GL_POSITION).unwrap();
    assert!((p[0]).abs() < 1e-6 && (p[1] + 1.0).abs() < 1e-6 && p[2].abs() < 1e-6, "{p:?}");
}

#[test]
fn color_material_tracks_the_current_colour() {
    let mut c = context();
    c.execute(&Command::Enable(GL_LIGHTING));
    c.execute(&Command::Enable(GL_LIGHT0));
    c.execute(&Command::LightModel(GL_LIGHT_MODEL_AMBIENT, [0.0, 0.0, 0.0, 1.0]));
    c.execute(&Command::ColorMaterial(GL_FRONT, GL_DIFFUSE));
    c.execute(&Command::Enable(GL_COLOR_MATERIAL));
    c.execute(&Command::Color([0.2, 0.4, 0.6, 1.0]));
    // Default light 0: directional along +z, white diffuse.
    close(lit_quad(&mut c, 0.0, [0.0, 0.0, 1.0]), to_u8([0.2 + 0.2 * 0.0, 0.4, 0.6]), "colour material");
    assert_eq!(c.get_material(GL_FRONT, GL_DIFFUSE), Some(vec![0.2, 0.4, 0.6, 1.0]));
    // The back material is untouched.
    assert_eq!(c.get_material(GL_BACK, GL_DIFFUSE), Some(vec![0.8, 0.8, 0.8, 1.0]));
}

#[test]
fn two_sided_lighting_colours_back_faces_with_the_back_material() {
    let mut c = context();
    c.execute(&Command::Enable(GL_LIGHTING));
    c.execute(&Command::Enable(GL_LIGHT0));
    c.execute(&Command::LightModel(GL_LIGHT_MODEL_AMBIENT, [0.0, 0.0, 0.0, 1.0]));
    c.execute(&Command::LightModel(GL_LIGHT_MODEL_TWO_SIDE, [1.0, 0.0, 0.0, 0.0]));
    c.execute(&Command::Material(GL_FRONT, GL_DIFFUSE, [1.0, 0.0, 0.0, 1.0]));
    c.execute(&Command::Material(GL_BACK, GL_DIFFUSE, [0.0, 1.0, 0.0, 1.0]));
    c.execute(&Command::Light(GL_LIGHT0, GL_POSITION, [0.0, 0.0, -1.0, 0.0]));
    // The normal points away from the viewer, towards the light (-z); the
    // quad is counter-clockwise, so front-facing: front material, lit.
    close(lit_quad(&mut c, 0.0, [0.0, 0.0, -1.0]), to_u8([1.0, 0.0, 0.0]), "front face lit from behind");
    // Clockwise winding: back-facing, back material with the negated
    // normal (0, 0, 1), which faces away from the light: black.
    c.execute(&Command::FrontFace(GL_CW));
    close(lit_quad(&mut c, 0.0, [0.0, 0.0, -1.0]), [0, 0, 0], "back face, normal away from light");
    close(lit_quad(&mut c, 0.0, [0.0, 0.0, 1.0]), to_u8([0.0, 1.0, 0.0]), "back face lit");
}

#[test]
fn lighting_errors() {
    let mut c = context();
    c.execute(&Command::Light(GL_LIGHT0 + 8, GL_AMBIENT, [0.0; 4]));
    assert_eq!(c.take_error(), GL_INVALID_ENUM);
    c.execute(&Command::Material(GL_FRONT, GL_SHININESS, [129.0, 0.0, 0.0, 0.0]));
    assert_eq!(c.take_error(), GL_INVALID_VALUE);
    c.execute(&Command::ColorMaterial(GL_FRONT, GL_SHININESS));
    assert_eq!(c.take_error(), GL_INVALID_ENUM);
    c.execute(&Command::LightModel(GL_LIGHT_MODEL_COLOR_CONTROL, [0.0; 4]));
    assert_eq!(c.take_error(), GL_INVALID_ENUM);
    // Material and Normal are legal between Begin and End; Light is not.
    c.execute(&Command::Begin(GL_TRIANGLES));
    c.execute(&Command::Material(GL_FRONT, GL_DIFFUSE, [1.0; 4]));
    c.execute(&Command::Normal([1.0, 0.0, 0.0]));
    assert_eq!(c.take_error(), GL_NO_ERROR);
    c.execute(&Command::Light(GL_LIGHT0, GL_AMBIENT, [0.0; 4]));
    assert_eq!(c.take_error(), GL_INVALID_OPERATION);
    c.execute(&Command::End);
}
