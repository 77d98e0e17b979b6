//! Polygon modes, edge flags, polygon offset and polygon stipple
//! (GL 1.5 sections 2.6.2, 3.5.2–3.5.5).

use softgl::framebuffer::Config;
use softgl::gl::enums::*;
use softgl::gl::{Command, Context};

fn context() -> Context {
    let mut c = Context::new(Config { alpha_bits: 8, depth_bits: 24, stencil_bits: 8, accum_bits: 0 });
    c.fb.resize(16, 16).unwrap();
    c.surface_resized(16, 16);
    c.execute(&Command::MatrixMode(GL_PROJECTION));
    c.execute(&Command::Ortho([0.0, 16.0, 0.0, 16.0, -1.0, 1.0]));
    c.execute(&Command::MatrixMode(GL_MODELVIEW));
    c
}

fn lit(c: &Context) -> Vec<(usize, usize)> {
    let mut v = Vec::new();
    for y in 0..c.fb.height {
        for x in 0..c.fb.width {
            if c.fb.color[c.fb.index(x, y)] != [0; 4] {
                v.push((x, y));
            }
        }
    }
    v
}

/// A quad with corners on pixel centres (4.5, 4.5) .. (11.5, 11.5).
fn quad(c: &mut Context, flags: [bool; 4], ccw: bool) {
    let mut v = [[4.5f32, 4.5], [11.5, 4.5], [11.5, 11.5], [4.5, 11.5]];
    if !ccw {
        v.reverse();
    }
    c.execute(&Command::Color([1.0; 4]));
    c.execute(&Command::Begin(GL_QUADS));
    for (p, f) in v.iter().zip(flags) {
        c.execute(&Command::EdgeFlag(f));
        c.execute(&Command::Vertex([p[0], p[1], 0.0, 1.0]));
    }
    c.execute(&Command::End);
    c.execute(&Command::EdgeFlag(true));
}

#[test]
fn line_mode_draws_the_boundary_not_the_diagonal() {
    let mut c = context();
    c.execute(&Command::PolygonMode(GL_FRONT_AND_BACK, GL_LINE));
    quad(&mut c, [true; 4], true);
    let px = lit(&c);
    // The outline of the 8x8 pixel square from 4 to 11, nothing inside.
    for &(x, y) in &px {
        assert!((4..=11).contains(&x) && (4..=11).contains(&y), "{x},{y}");
        assert!(x == 4 || x == 11 || y == 4 || y == 11, "interior pixel {x},{y} drawn (diagonal?)");
    }
    assert!(px.len() >= 26, "outline has {} pixels", px.len());
    // Without the bottom edge's flag (the edge from vertex 0), row 4 is
    // only touched by the side edges.
    let mut c2 = context();
    c2.execute(&Command::PolygonMode(GL_FRONT_AND_BACK, GL_LINE));
    quad(&mut c2, [false, true, true, true], true);
    let bottom = lit(&c2).iter().filter(|&&(x, y)| y == 4 && (6..=9).contains(&x)).count();
    assert_eq!(bottom, 0);
}

#[test]
fn point_mode_and_per_face_modes() {
    let mut c = context();
    c.execute(&Command::PolygonMode(GL_FRONT, GL_POINT));
    quad(&mut c, [true, true, false, true], true);
    let mut px = lit(&c);
    px.sort();
    assert_eq!(px, vec![(4, 4), (4, 11), (11, 4)], "flagged vertices only");
    // Back faces stay filled.
    let mut c = context();
    c.execute(&Command::PolygonMode(GL_FRONT, GL_POINT));
    quad(&mut c, [true; 4], false);
    assert_eq!(lit(&c).len(), 7 * 7, "a clockwise quad is back-facing: filled");
    // Culling applies in line mode too.
    let mut c = context();
    c.execute(&Command::PolygonMode(GL_FRONT_AND_BACK, GL_LINE));
    c.execute(&Command::Enable(GL_CULL_FACE));
    quad(&mut c, [true; 4], true);
    c.execute(&Command::CullFace(GL_FRONT));
    assert!(!lit(&c).is_empty());
    let mut c = context();
    c.execute(&Command::PolygonMode(GL_FRONT_AND_BACK, GL_LINE));
    c.execute(&Command::Enable(GL_CULL_FACE));
    c.execute(&Command::CullFace(GL_FRONT));
    quad(&mut c, [true; 4], true);
    assert!(lit(&c).is_empty());
}

#[test]
fn polygon_offset_resolves_coplanar_fighting() {
    for slope in [0.0f32, 0.4] {
        let mut c = context();
        c.execute(&Command::Clear(GL_DEPTH_BUFFER_BIT));
        c.execute(&Command::Enable(GL_DEPTH_TEST));
        let draw = |c: &mut Context, color: [f32; 4]| {
            c.execute(&Command::Color(color));
            c.execute(&Command::Begin(GL_QUADS));
            for p in [[0.0f32, 0.0], [16.0, 0.0], [16.0, 16.0], [0.0, 16.0]] {
                c.execute(&Command::Vertex([p[0], p[1], slope * (p[0] / 16.0 - 0.5), 1.0]));
            }
            c.execute(&Command::End);
        };
        draw(&mut c, [1.0, 0.0, 0.0, 1.0]);
        c.execute(&Command::Enable(GL_POLYGON_OFFSET_FILL));
        c.execute(&Command::PolygonOffset(-1.0, -1.0));
        draw(&mut c, [0.0, 1.0, 0.0, 1.0]);
        assert!(c.fb.color.iter().all(|p| *p == [0, 255, 0, 255]), "slope {slope}: the offset quad must win everywhere");
        // Pushed away, it loses everywhere.
        c.execute(&Command::PolygonOffset(1.0, 1.0));
        draw(&mut c, [0.0, 0.0, 1.0, 1.0]);
        assert!(c.fb.color.iter().all(|p| *p == [0, 255, 0, 255]));
    }
}

#[test]
fn stipple_masks_polygon_fragments() {
    let mut c = context();
    // A checkerboard: rows alternate 0x55555555 and 0xAAAAAAAA.
    let mut pattern = [0u32; 32];
    for (y, row) in pattern.iter_mut().enumerate() {
        *row = if y % 2 == 0 { 0x5555_5555 } else { 0xAAAA_AAAA };
    }
    c.execute(&Command::PolygonStipple(Box::new(pattern)));
    c.execute(&Command::Enable(GL_POLYGON_STIPPLE));
    c.execute(&Command::Color([1.0; 4]));
    c.execute(&Command::Rect([0.0, 0.0, 16.0, 16.0]));
    for y in 0..16 {
        for x in 0..16 {
            let on = c.fb.color[c.fb.index(x, y)] != [0; 4];
            assert_eq!(on, (x + y) % 2 == 0, "pixel {x},{y}");
        }
    }
}

#[test]
fn stipple_round_trips_through_the_pixel_store() {
    use softgl::gl::pixels::PixelModes;
    use softgl::gl::polygon::{pack_stipple, unpack_stipple};
    let mut bytes = [0u8; 128];
    for (i, b) in bytes.iter_mut().enumerate() {
        *b = (i * 37 % 251) as u8;
    }
    let modes = PixelModes::default();
    let p = unsafe { unpack_stipple(&modes, bytes.as_ptr()) };
    // The first byte's MSB is pixel (0, 0).
    assert_eq!(p[0] & 1, (bytes[0] >> 7) as u32 & 1);
    let mut back = [0u8; 128];
    unsafe { pack_stipple(&modes, &p, back.as_mut_ptr()) };
    assert_eq!(bytes, back);
    let lsb = PixelModes { lsb_first: true, ..PixelModes::default() };
    let q = unsafe { unpack_stipple(&lsb, bytes.as_ptr()) };
    assert_eq!(q[0] & 1, bytes[0] as u32 & 1);
}

#[test]
fn polygon_errors() {
    let mut c = context();
    c.execute(&Command::PolygonMode(GL_FRONT, 0x1234));
    assert_eq!(c.take_error(), GL_INVALID_ENUM);
    c.execute(&Command::PolygonMode(0x1234, GL_LINE));
    assert_eq!(c.take_error(), GL_INVALID_ENUM);
    c.execute(&Command::Begin(GL_POLYGON));
    c.execute(&Command::EdgeFlag(false));
    assert_eq!(c.take_error(), GL_NO_ERROR, "edge flags are legal inside Begin/End");
    c.execute(&Command::End);
}

#[test]
fn polygon_offset_applies_to_line_mode_when_enabled() {
    let run = |enable_line_offset: bool| {
        let mut c = context();
        c.execute(&Command::Clear(GL_DEPTH_BUFFER_BIT));
        c.execute(&Command::Enable(GL_DEPTH_TEST));
        quad(&mut c, [true; 4], true); // white, filled, depth written
        c.execute(&Command::PolygonMode(GL_FRONT_AND_BACK, GL_LINE));
        if enable_line_offset {
            c.execute(&Command::Enable(GL_POLYGON_OFFSET_LINE));
            c.execute(&Command::PolygonOffset(0.0, -4.0));
        }
        c.execute(&Command::Color([1.0, 0.0, 0.0, 1.0]));
        c.execute(&Command::Begin(GL_QUADS));
        for p in [[4.5f32, 4.5], [11.5, 4.5], [11.5, 11.5], [4.5, 11.5]] {
            c.execute(&Command::Vertex([p[0], p[1], 0.0, 1.0]));
        }
        c.execute(&Command::End);
        c.fb.color.iter().filter(|p| **p == [255, 0, 0, 255]).count()
    };
    // Without the offset, outline pixels inside the filled quad lose the
    // GL_LESS test against its equal depth; only those the fill did not
    // cover (its top and right edges, by the top-left rule) show.
    let (without, with) = (run(false), run(true));
    assert!(without <= 16, "{without}");
    assert!(with >= 26, "offset lines win everywhere: {with}");
}
