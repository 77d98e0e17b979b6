//! wglUseFontOutlines: one display list of 3D geometry per character.
//!
//! On Windows the outlines come from the DC's TrueType font. softgl has
//! only its built-in bitmap fonts (`crate::fonts`, docs/fonts.md), so a
//! glyph's outline here is the exact boundary of its pixels: the shape is
//! the union of the set pixels' unit squares, scaled so that the font's
//! cell height is 1.0 (Windows' unit is the em square). `deviation` (the
//! allowed chordal error of curve flattening) has nothing to flatten and is
//! ignored; the outlines are exact.
//!
//! What each list holds (through the public GL entry points, as a program
//! would compile it):
//! - WGL_FONT_POLYGONS: the front face at z = 0 as GL_QUADS, one per
//!   horizontal run of set pixels, normal (0, 0, 1), counter-clockwise seen
//!   from +z. With a non-zero `extrusion`, the back face at z = -extrusion
//!   (normal (0, 0, -1), clockwise seen from +z) and the side walls along
//!   every boundary edge, each with its outward normal and wound
//!   counter-clockwise seen from outside.
//! - WGL_FONT_LINES: the boundary edges at z = 0 as GL_LINES (collinear
//!   unit edges merged into one segment).
//! - then glTranslatef(cell increment x, y, 0), so that glCallLists writes
//!   a string, as on Windows.
//!
//! `lpgmf`, when not NULL, receives one GLYPHMETRICSFLOAT per character in
//! the same unit: black box size, the black box's upper-left corner
//! relative to the origin, and the cell increment.

use crate::api::table::{glBegin, glEnd, glEndList, glNewList, glNormal3f, glTranslatef, glVertex3f};
use crate::fonts::{Bitmap, Font};
use crate::gl::enums::{GL_COMPILE, GL_LINES, GL_QUADS};
use crate::winsys::current;

pub const WGL_FONT_LINES: i32 = 0;
pub const WGL_FONT_POLYGONS: i32 = 1;

/// GLYPHMETRICSFLOAT (wingdi.h): six FLOATs.
#[repr(C)]
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct GlyphMetricsFloat {
    pub black_box_x: f32,
    pub black_box_y: f32,
    pub origin_x: f32,
    pub origin_y: f32,
    pub cell_inc_x: f32,
    pub cell_inc_y: f32,
}

/// A boundary edge of a glyph's pixel region, in pixel units: from `a` to
/// `b` along an axis, with the region on its left (so the outward normal
/// is the direction turned clockwise).
#[derive(Clone, Copy, Debug, PartialEq)]
struct Edge {
    a: (i32, i32),
    b: (i32, i32),
}

impl Edge {
    /// The outward normal: the edge direction turned clockwise.
    fn normal(&self) -> (f32, f32) {
        let (dx, dy) = ((self.b.0 - self.a.0).signum(), (self.b.1 - self.a.1).signum());
        (dy as f32, -dx as f32)
    }
}

/// The boundary of the set pixels of `b`, as maximal straight edges
/// oriented with the region on their left (counter-clockwise around
/// filled areas, clockwise around holes).
fn boundary(b: &Bitmap) -> Vec<Edge> {
    let (w, h) = (b.width, b.height);
    let on = |x: i32, y: i32| x >= 0 && y >= 0 && x < w && y < h && b.pixel(x as usize, y as usize);
    let mut edges = Vec::new();
    // Horizontal edges on the line y: filled above → edge goes +x (the
    // region is on its left); filled below → it goes -x.
    for y in 0..=h {
        let mut run: Option<(i32, bool)> = None;
        for x in 0..=w {
            let kind = match (on(x, y), on(x, y - 1)) {
                (true, false) => Some(true),
                (false, true) => Some(false),
                _ => None,
            };
            if run.map(|r| r.1) != kind || x == w {
                if let Some((x0, above)) = run.take() {
                    let (a, bb) = ((x0, y), (x, y));
                    edges.push(if above { Edge { a, b: bb } } else { Edge { a: bb, b: a } });
                }
                run = kind.map(|k| (x, k));
            }
        }
    }
    // Vertical edges on the line x: filled to the right → edge goes -y;
    // filled to the left → +y.
    for x in 0..=w {
        let mut run: Option<(i32, bool)> = None;
        for y in 0..=h {
            let kind = match (on(x, y), on(x - 1, y)) {
                (true, false) => Some(true),
                (false, true) => Some(false),
                _ => None,
            };
            if run.map(|r| r.1) != kind || y == h {
                if let Some((y0, right)) = run.take() {
                    let (a, bb) = ((x, y0), (x, y));
                    edges.push(if right { Edge { a: bb, b: a } } else { Edge { a, b: bb } });
                }
                run = kind.map(|k| (y, k));
            }
        }
    }
    edges
}

/// Horizontal runs [x0, x1) of set pixels in each row: (x0, x1, y).
fn runs(b: &Bitmap) -> Vec<(i32, i32, i32)> {
    let mut out = Vec::new();
    for y in 0..b.height {
        let mut x = 0;
        while x < b.width {
            if !b.pixel(x as usize, y as usize) {
                x += 1;
                continue;
            }
            let x0 = x;
            while x < b.width && b.pixel(x as usize, y as usize) {
                x += 1;
            }
            out.push((x0, x, y));
        }
    }
    out
}

/// The metrics of a glyph bitmap in em units (`em` pixels = 1.0).
fn metrics(b: &Bitmap, em: f32) -> GlyphMetricsFloat {
    GlyphMetricsFloat {
        black_box_x: b.width as f32 / em,
        black_box_y: b.height as f32 / em,
        origin_x: -b.xorig / em,
        origin_y: (b.height as f32 - b.yorig) / em,
        cell_inc_x: b.xmove / em,
        cell_inc_y: b.ymove / em,
    }
}

/// Emits one glyph's geometry (between glNewList and glEndList).
///
/// # Safety
/// A context must be current on this thread.
unsafe fn emit_glyph(b: &Bitmap, em: f32, extrusion: f32, format: i32) {
    // Pixel (px, py) of the bitmap covers [px - xorig, px + 1 - xorig] x
    // [py - yorig, py + 1 - yorig] around the origin, in pixels.
    let pos = |x: i32, y: i32| ((x as f32 - b.xorig) / em, (y as f32 - b.yorig) / em);
    if format == WGL_FONT_LINES {
        glBegin(GL_LINES);
        for e in boundary(b) {
            let (p, q) = (pos(e.a.0, e.a.1), pos(e.b.0, e.b.1));
            glVertex3f(p.0, p.1, 0.0);
            glVertex3f(q.0, q.1, 0.0);
        }
        glEnd();
        return;
    }
    let runs = runs(b);
    glBegin(GL_QUADS);
    glNormal3f(0.0, 0.0, 1.0);
    for &(x0, x1, y) in &runs {
        for (x, yy) in [(x0, y), (x1, y), (x1, y + 1), (x0, y + 1)] {
            let p = pos(x, yy);
            glVertex3f(p.0, p.1, 0.0);
        }
    }
    if extrusion != 0.0 {
        let z = -extrusion;
        glNormal3f(0.0, 0.0, -1.0);
        for &(x0, x1, y) in &runs {
            for (x, yy) in [(x0, y), (x0, y + 1), (x1, y + 1), (x1, y)] {
                let p = pos(x, yy);
                glVertex3f(p.0, p.1, z);
            }
        }
        // Side walls: walking an edge from a to b with the region on the
        // left, the quad a0, a-z, b-z, b0 is counter-clockwise seen from
        // outside (from the edge's outward normal).
        for e in boundary(b) {
            let n = e.normal();
            glNormal3f(n.0, n.1, 0.0);
            let (p, q) = (pos(e.a.0, e.a.1), pos(e.b.0, e.b.1));
            glVertex3f(p.0, p.1, 0.0);
            glVertex3f(p.0, p.1, z);
            glVertex3f(q.0, q.1, z);
            glVertex3f(q.0, q.1, 0.0);
        }
    }
    glEnd();
}

/// Builds the outline lists `base .. base + count` for characters
/// `first ..` of `font` (code points through `decode`). False, and
/// nothing built, without a usable current context, with an unknown
/// format or when the ranges overflow.
///
/// # Safety
/// `gmf` is NULL or points to `count` writable GLYPHMETRICSFLOATs.
pub unsafe fn build_outline_lists(
    font: &Font,
    decode: impl Fn(u32) -> u32,
    first: u32,
    count: u32,
    base: u32,
    extrusion: f32,
    format: i32,
    gmf: *mut GlyphMetricsFloat,
) -> bool {
    let ctx = current::current();
    if ctx.is_null() || base == 0 || base.checked_add(count).is_none() || first.checked_add(count).is_none() {
        return false;
    }
    if format != WGL_FONT_LINES && format != WGL_FONT_POLYGONS || !extrusion.is_finite() || extrusion < 0.0 {
        return false;
    }
    let c = &mut *ctx;
    if c.in_begin_end() || c.lists.compile_mode().is_some() {
        return false;
    }
    let em = font.cell_height().max(1) as f32;
    for i in 0..count {
        let b = font.bitmap(decode(first + i));
        let m = metrics(&b, em);
        if !gmf.is_null() {
            gmf.add(i as usize).write_unaligned(m);
        }
        glNewList(base + i, GL_COMPILE);
        emit_glyph(&b, em, extrusion, format);
        glTranslatef(m.cell_inc_x, m.cell_inc_y, 0.0);
        glEndList();
    }
    true
}

#[cfg(test)]
mod tests {
    use super::*;

    fn bitmap(rows_top_down: &[&str]) -> Bitmap {
        let height = rows_top_down.len() as i32;
        let width = rows_top_down[0].len() as i32;
        let stride = (width as usize).div_ceil(8);
        let mut bits = vec![0u8; stride * height as usize];
        for (r, row) in rows_top_down.iter().enumerate() {
            let y = height as usize - 1 - r;
            for (x, ch) in row.chars().enumerate() {
                if ch == '#' {
                    bits[y * stride + x / 8] |= 0x80 >> (x % 8);
                }
            }
        }
        Bitmap { width, height, xorig: 1.0, yorig: 2.0, xmove: 6.0, ymove: 0.0, bits }
    }

    /// The boundary is closed and oriented: every vertex has as many edges
    /// leaving as arriving, and the signed area it encloses (shoelace over
    /// the edges) equals the number of set pixels, a hole counting
    /// negatively through its clockwise edges.
    #[test]
    fn boundary_is_closed_and_encloses_the_pixels() {
        let b = bitmap(&["####.", "#..#.", "####.", "...##"]);
        let edges = boundary(&b);
        let mut degree = std::collections::HashMap::new();
        let mut area2 = 0i64;
        for e in &edges {
            *degree.entry(e.a).or_insert(0i32) += 1;
            *degree.entry(e.b).or_insert(0i32) -= 1;
            area2 += e.a.0 as i64 * e.b.1 as i64 - e.b.0 as i64 * e.a.1 as i64;
        }
        assert!(degree.values().all(|&d| d == 0), "closed: {degree:?}");
        let set = runs(&b).iter().map(|r| (r.1 - r.0) as i64).sum::<i64>();
        assert_eq!(set, 12);
        assert_eq!(area2, 2 * set);
        // Outward normals point away from the set pixels.
        for e in &edges {
            let (nx, ny) = e.normal();
            let mid = ((e.a.0 + e.b.0) as f32 / 2.0, (e.a.1 + e.b.1) as f32 / 2.0);
            let probe = |s: f32| {
                let (x, y) = ((mid.0 + nx * s + if nx == 0.0 { 0.25 } else { 0.0 }).floor() as i32, (mid.1 + ny * s + if ny == 0.0 { 0.25 } else { 0.0 }).floor() as i32);
                x >= 0 && y >= 0 && x < b.width && y < b.height && b.pixel(x as usize, y as usize)
            };
            assert!(!probe(0.5) && probe(-0.5), "edge {e:?}");
        }
    }

    #[test]
    fn metrics_are_in_em_units() {
        let b = bitmap(&["##", "##", "##", "##"]);
        let m = metrics(&b, 8.0);
        assert_eq!(m, GlyphMetricsFloat { black_box_x: 0.25, black_box_y: 0.5, origin_x: -0.125, origin_y: 0.25, cell_inc_x: 0.75, cell_inc_y: 0.0 });
    }
}
