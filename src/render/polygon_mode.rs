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
use super::{line, point, RenderState};
use crate::framebuffer::Framebuffer;
use crate::gl::enums::{GL_FILL, GL_LINE};
use super::vertex::ClipVertex;
use glam::Vec4;

/// m * factor + r * units for a polygon in window coordinates: m is the
/// largest depth slope of its plane (from its first three vertices, as
/// setup does for filled triangles).
fn polygon_offset(win: &[setup::WindowVertex], factor: f32, units: f32) -> f64 {
    let (a, b, c) = (&win[0], &win[1], &win[2]);
    let (dx1, dy1, dz1) = (b.x - a.x, b.y - a.y, b.z - a.z);
    let (dx2, dy2, dz2) = (c.x - a.x, c.y - a.y, c.z - a.z);
    let det = dx1 * dy2 - dx2 * dy1;
    let m = if det != 0.0 {
        let dzdx = (dz1 * dy2 - dz2 * dy1) / det;
        let dzdy = (dz2 * dx1 - dz1 * dx2) / det;
        dzdx.abs().max(dzdy.abs())
    } else {
        0.0
    };
    m * factor as f64 + units as f64 * super::setup::OFFSET_UNIT
}

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
    let area = super::signed_area(&win);
    if area == 0.0 || !area.is_finite() {
        return;
    }
    let Some(front) = rs.facing(area > 0.0) else { return };
    let mode = rs.polygon_mode[if front { 0 } else { 1 }];
    if mode == GL_FILL {
        for i in 1..win.len() - 1 {
            super::fill_triangle(rs, fb, &[win[0], win[i], win[i + 1]], flat_color);
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
            if back {
                c.secondary = cv.back_secondary;
            }
            c
        })
        .collect();
    let n = coloured.len();
    // Polygon offset (3.5.5) for the LINE and POINT modes: the polygon's
    // own depth slope, applied to its vertices' depth.
    let offset = if mode == GL_LINE { rs.offset_line } else { rs.offset_point };
    let mut coloured = coloured;
    if let Some((factor, units)) = offset {
        let o = polygon_offset(&win, factor, units);
        let sz = rs.viewport_scale[2];
        if sz != 0.0 {
            for c in coloured.iter_mut() {
                // Window z = oz + sz * z / w: shift z by o / sz * w.
                c.pos.z += (o / sz) as f32 * c.pos.w;
            }
        }
    }
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
