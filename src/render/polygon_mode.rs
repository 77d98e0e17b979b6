//! Polygons drawn as lines or points (GL 1.5 section 3.5.4, glPolygonMode).
//!
//! The triangle is clipped first; the clipped polygon's facing (from its
//! window-space area) picks the front or back mode and is culled like a
//! filled one. LINE draws the flagged edges with the line rasterizer (its
//! width and stipple apply; the stipple restarts for each polygon), POINT
//! draws the flagged vertices with the point rasterizer. Edges that
//! clipping created are never flagged (see `clip`). Flat shading and
//! two-sided colours follow the polygon.

use super::clip;
use super::setup;
use super::{line, point, Cull, RenderState};
use crate::framebuffer::Framebuffer;
use crate::gl::enums::{GL_FILL, GL_LINE};
use super::vertex::ClipVertex;
use glam::Vec4;

pub fn draw(rs: &RenderState, fb: &mut Framebuffer, v: [&ClipVertex; 3], flat_color: [Vec4; 2], edges: [bool; 3]) {
    let mut tri = [*v[0], *v[1], *v[2]];
    for (t, e) in tri.iter_mut().zip(edges) {
        t.edge = e;
    }
    let mut poly = clip::Polygon::new();
    let verts: Vec<ClipVertex> = match clip::clip_triangle(&rs.clip_planes, [&tri[0], &tri[1], &tri[2]], &mut poly) {
        clip::Outcome::Rejected => return,
        clip::Outcome::Inside => tri.to_vec(),
        clip::Outcome::Clipped => poly.verts.clone(),
    };
    let win: Vec<_> = verts.iter().map(|cv| setup::to_window(rs, cv)).collect();
    let mut area = 0.0;
    for i in 0..win.len() {
        let (a, b) = (&win[i], &win[(i + 1) % win.len()]);
        area += a.x * b.y - b.x * a.y;
    }
    if area == 0.0 || !area.is_finite() {
        return;
    }
    let front = (area > 0.0) == rs.front_ccw;
    match rs.cull {
        Cull::Front if front => return,
        Cull::Back if !front => return,
        Cull::All => return,
        _ => {}
    }
    let mode = rs.polygon_mode[if front { 0 } else { 1 }];
    if mode == GL_FILL {
        for i in 1..win.len() - 1 {
            setup::triangle(rs, fb, &[win[0], win[i], win[i + 1]], flat_color);
        }
        return;
    }
    // The polygon's colours for this face, flat or smooth.
    let back = rs.two_side && !front;
    let flat = flat_color[back as usize];
    let coloured: Vec<ClipVertex> = verts
        .iter()
        .map(|cv| {
            let mut c = *cv;
            c.color = if rs.flat { flat } else if back { cv.back_color } else { cv.color };
            c
        })
        .collect();
    let n = coloured.len();
    if mode == GL_LINE {
        let mut stipple = 0;
        for i in 0..n {
            if coloured[i].edge {
                line::draw_line(rs, fb, &rs.line, &coloured[i], &coloured[(i + 1) % n], flat, &mut stipple);
            }
        }
    } else {
        for c in coloured.iter().filter(|c| c.edge) {
            point::draw_point(rs, fb, rs.point_size, c);
        }
    }
}
