//! The hot pipeline (DESIGN.md, "render/"): from transformed vertices to
//! pixels. It reads only the derived state the `gl` layer validated
//! ([`RenderState`]) and writes only the framebuffer.
//!
//! Stages, each its own module: [`clip`] (homogeneous clipping with a guard
//! band), [`setup`] (fixed-point triangle setup and attribute planes),
//! [`raster`] (exact spans with the top-left rule), [`fragment`] (per-fragment
//! operations in the spec's order).

pub mod clip;
pub mod fragment;
pub mod light;
pub mod line;
pub mod point;
pub mod raster;
pub mod setup;
pub mod texture;
pub mod vertex;

use crate::framebuffer::{Framebuffer, Rect};

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
    /// Two-sided lighting: back-facing polygons take their back colour.
    pub two_side: bool,
    pub fragment: FragmentState,
    /// Texturing: the enabled units with complete textures; None when no
    /// unit textures.
    pub texture: Option<std::sync::Arc<texture::TextureStage>>,
}

#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Cull {
    None,
    Front,
    Back,
    All,
}

/// Draws one triangle given in clip coordinates. `flat_color` is the
/// provoking vertex's [front, back] colour, which a flat-shaded triangle takes.
pub fn draw_triangle(rs: &RenderState, fb: &mut Framebuffer, v: [&ClipVertex; 3], flat_color: [glam::Vec4; 2]) {
    if rs.draw_rect.is_empty() || rs.cull == Cull::All {
        return;
    }
    let mut poly = clip::Polygon::new();
    match clip::clip_triangle(v, &mut poly) {
        clip::Outcome::Rejected => {}
        clip::Outcome::Inside => {
            let w = [0, 1, 2].map(|i| setup::to_window(rs, v[i]));
            setup::triangle(rs, fb, &w, flat_color);
        }
        clip::Outcome::Clipped => {
            let w: Vec<_> = poly.verts.iter().map(|cv| setup::to_window(rs, cv)).collect();
            // A clipped convex polygon: a fan; culling uses the original
            // orientation, which every piece shares.
            for i in 1..w.len().saturating_sub(1) {
                setup::triangle(rs, fb, &[w[0], w[i], w[i + 1]], flat_color);
            }
        }
    }
}
