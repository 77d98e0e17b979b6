//! The hot pipeline (DESIGN.md, "render/"): from transformed vertices to
//! pixels. It reads only the derived state the `gl` layer validated
//! ([`RenderState`]) and writes only the framebuffer.
//!
//! Stages, each its own module: [`clip`] (homogeneous clipping with a guard
//! band), [`setup`] (fixed-point triangle setup and attribute planes),
//! [`raster`] (exact spans with the top-left rule), [`fragment`] (per-fragment
//! operations in the spec's order).

pub mod bin4;
pub mod clip;
pub mod fog;
pub mod fragment;
pub mod light;
pub mod light4;
pub mod line;
pub mod pixels;
pub mod point;
pub mod polygon_mode;
pub mod placement;
pub mod pool;
pub mod raster;
pub mod records;
pub mod runs;
pub mod setup;
pub mod shade_state;
pub mod smooth;
pub mod texture;
pub mod tile;
pub mod trace;
pub mod vertex;
pub mod vertex4;

/// The tests' seeded random numbers (a 64-bit LCG, Knuth's MMIX
/// constants): the same sequence on every run, so a failure repeats.
#[cfg(test)]
pub(crate) mod test_rng {
    /// Draws in `0..m`, from bits `shift..` of each successive state.
    pub fn below(mut seed: u64, shift: u32) -> impl FnMut(i64) -> i64 {
        move |m| {
            seed = seed.wrapping_mul(6364136223846793005).wrapping_add(1442695040888963407);
            ((seed >> shift) as i64).rem_euclid(m)
        }
    }
}

use crate::framebuffer::{Framebuffer, Rect};
use crate::gl::enums::GL_FILL;

pub use fragment::FragmentState;
pub use vertex::ClipVertex;

/// Everything the pipeline needs from GL state, computed once per change.
#[derive(Clone, Debug)]
pub struct RenderState {
    /// Window transform: x_w = ox + px/2 * x_ndc, likewise y; z_w = oz + pz/2 * z_ndc.
    pub viewport_scale: [f64; 3],
    pub viewport_offset: [f64; 3],
    /// Pixels primitives may touch: viewport ∩ scissor ∩ surface.
    pub draw_rect: Rect,
    /// Face culling: None, or cull front-facing (true) / back-facing (false)...
    pub cull: Cull,
    /// glFrontFace(GL_CCW)?
    pub front_ccw: bool,
    pub flat: bool,
    /// Clipping planes in clip coordinates: clip::FIXED_PLANES, then the
    /// enabled user clip planes.
    pub clip_planes: Vec<clip::Plane>,
    /// glPolygonMode for front and back faces (GL_POINT, GL_LINE, GL_FILL).
    pub polygon_mode: [u32; 2],
    /// glPolygonOffset (factor, units) when enabled for filled polygons.
    pub offset_fill: Option<(f32, f32)>,
    /// The same for polygons drawn as lines and as points
    /// (GL_POLYGON_OFFSET_LINE / _POINT).
    pub offset_line: Option<(f32, f32)>,
    pub offset_point: Option<(f32, f32)>,
    /// glPolygonStipple's pattern (bit x of row y) when enabled.
    pub polygon_stipple: Option<Box<[u32; 32]>>,
    /// Line and point state, for polygons drawn as lines or points.
    pub line: line::LineParams,
    pub point_size: f32,
    /// Antialiasing (GL_POINT_SMOOTH, GL_LINE_SMOOTH, GL_POLYGON_SMOOTH)
    /// and its hints, and the point fade threshold.
    pub smooth: smooth::SmoothState,
    /// The colour sum (3.9) is on: GL_COLOR_SUM, or lighting with
    /// GL_SEPARATE_SPECULAR_COLOR.
    pub color_sum: bool,
    /// Fog, when GL_FOG is on.
    pub fog: Option<fog::Fog>,
    /// Two-sided lighting: back-facing polygons take their back colour.
    pub two_side: bool,
    pub fragment: FragmentState,
    /// Texturing: the enabled units with complete textures; None when no
    /// unit textures.
    pub texture: Option<std::sync::Arc<texture::TextureStage>>,
    /// Use the reference path (SOFTGL_REFERENCE=1) instead of the fast
    /// kernels; set at context creation from [`reference_default`].
    pub reference: bool,
    /// Rasterizer threads (SOFTGL_THREADS): above 1, filled triangles are
    /// binned into `batch` and shaded by tiles at the end of the draw call.
    pub threads: usize,
    /// GL_PERSPECTIVE_CORRECTION_HINT is not GL_NICEST: the fast kernels
    /// may approximate colour interpolation (render::fragment::fast).
    pub approximate: bool,
    pub batch: tile::SharedBatch,
    /// Changes whenever validation changes anything here (never reused;
    /// 0 until the first validation): what [`shade_state`] keys on.
    pub stamp: u64,
    /// The last [`shade_state::ShadeState`] captured from this state.
    pub shade: shade_state::ShadeCache,
}

/// SOFTGL_REFERENCE=1 (read once per process): new contexts render through
/// the plain reference path.
pub fn reference_default() -> bool {
    static ON: std::sync::OnceLock<bool> = std::sync::OnceLock::new();
    *ON.get_or_init(|| std::env::var("SOFTGL_REFERENCE").is_ok_and(|v| v == "1"))
}

impl RenderState {
    /// Facing and culling (3.5.1) of a polygon whose window-space
    /// orientation is counter-clockwise or not: Some(front facing), or
    /// None when glCullFace discards it.
    #[inline]
    pub fn facing(&self, ccw: bool) -> Option<bool> {
        let front = ccw == self.front_ccw;
        match self.cull {
            Cull::Front if front => None,
            Cull::Back if !front => None,
            Cull::All => None,
            _ => Some(front),
        }
    }
}

/// Shades the binned triangles (see [`tile`]): called before anything
/// reads or writes the framebuffer.
pub fn flush(rs: &RenderState, fb: &mut Framebuffer) {
    tile::flush(rs, fb)
}

/// Twice the signed window-space area of a polygon (positive
/// counter-clockwise).
pub fn signed_area(win: &[setup::WindowVertex]) -> f64 {
    (0..win.len())
        .map(|i| {
            let (a, b) = (&win[i], &win[(i + 1) % win.len()]);
            a.x * b.y - b.x * a.y
        })
        .sum()
}

#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Cull {
    None,
    Front,
    Back,
    All,
}

/// Draws one triangle given in clip coordinates. `flat_color` is the
/// provoking vertex's [front, back] colour, which a flat-shaded triangle
/// takes; `edges[i]` flags the edge from v[i] to v[i + 1] as a polygon
/// boundary (for polygon modes LINE and POINT).
pub fn draw_triangle(rs: &RenderState, fb: &mut Framebuffer, v: [&ClipVertex; 3], flat_color: [glam::Vec4; 2], edges: [bool; 3]) {
    if rs.draw_rect.is_empty() || rs.cull == Cull::All {
        return;
    }
    if rs.polygon_mode != [GL_FILL; 2] {
        // Shaded immediately (with its lines and points, in order).
        tile::flush(rs, fb);
        return polygon_mode::draw(rs, fb, v, flat_color, edges);
    }
    // No user clip planes and every vertex well inside: no clipping.
    // (Their window positions were computed once per vertex: `place`.)
    if rs.smooth.polygon.is_none() && rs.clip_planes.len() == clip::FIXED_PLANES.len() && v.iter().all(|cv| cv.inside) {
        return setup::triangle_placed(rs, fb, v, flat_color);
    }
    let mut poly = clip::Polygon::new();
    match clip::clip_triangle(&rs.clip_planes, v, &mut poly) {
        clip::Outcome::Rejected => {}
        clip::Outcome::Inside if rs.smooth.polygon.is_none() => {
            // The common case: positions to window space, attributes read
            // in place from the clip vertices.
            let pos = v.map(|cv| setup::window_pos(rs, cv.pos));
            setup::triangle_at(rs, fb, pos, v, flat_color);
        }
        clip::Outcome::Inside => {
            let w = [0, 1, 2].map(|i| setup::to_window(rs, v[i]));
            fill_triangle(rs, fb, &w, flat_color);
        }
        clip::Outcome::Clipped => {
            let w: Vec<_> = poly.verts.iter().map(|cv| setup::to_window(rs, cv)).collect();
            // A clipped convex polygon: a fan; culling uses the original
            // orientation, which every piece shares.
            for i in 1..w.len().saturating_sub(1) {
                fill_triangle(rs, fb, &[w[0], w[i], w[i + 1]], flat_color);
            }
        }
    }
}

/// A filled triangle in window coordinates: by coverage under
/// GL_POLYGON_SMOOTH (`smooth`), else by the exact aliased rules (`setup`).
pub fn fill_triangle(rs: &RenderState, fb: &mut Framebuffer, w: &[setup::WindowVertex; 3], flat_color: [glam::Vec4; 2]) {
    match rs.smooth.polygon {
        Some(q) => {
            tile::sync(rs, fb);
            smooth::triangle(rs, fb, w, flat_color, q)
        }
        None => setup::triangle(rs, fb, w, flat_color),
    }
}
