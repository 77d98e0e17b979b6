//! Validation (DESIGN.md, "State, validation, specialization"): setters mark
//! dirty bits; the first draw after a change recomputes the derived state
//! the renderer reads, once.

use super::context::Context;
use super::enums::*;
use crate::framebuffer::Rect;
use crate::render::fragment::{color_to_u8, AlphaTest, Blend, ColorOp, CompareFunc, FragmentState, LogicOp, StencilTest};
use crate::render::light::LightingSetup;
use crate::render::{Cull, RenderState};
use glam::Mat4;

pub const DIRTY_TRANSFORM: u32 = 1 << 0;
pub const DIRTY_VIEWPORT: u32 = 1 << 1;
pub const DIRTY_FRAGMENT: u32 = 1 << 2;
pub const DIRTY_RASTER: u32 = 1 << 3;
pub const DIRTY_LIGHTING: u32 = 1 << 4;
/// Texture objects, images, parameters, environments, enables, texgen.
pub const DIRTY_TEXTURE: u32 = 1 << 12;
pub const DIRTY_FOG: u32 = 1 << 13;
pub const DIRTY_ALL: u32 = !0;

/// State derived from GL state for the renderer.
#[derive(Clone, Debug)]
pub struct Derived {
    /// Projection * modelview, in f32 for the vertex stage.
    pub mvp: Mat4,
    /// The modelview matrix in f32, for eye-space fog distances.
    pub modelview: Mat4,
    /// Lighting prepared for the vertex stage; None when lighting is off.
    pub lighting: Option<LightingSetup>,
    pub render: RenderState,
}

impl Default for Derived {
    fn default() -> Self {
        Derived {
            mvp: Mat4::IDENTITY,
            modelview: Mat4::IDENTITY,
            lighting: None,
            render: RenderState {
                viewport_scale: [0.0; 3],
                viewport_offset: [0.0; 3],
                draw_rect: Rect::default(),
                cull: Cull::None,
                front_ccw: true,
                flat: false,
                two_side: false,
                fog: None,
                color_sum: false,
                polygon_mode: [GL_FILL; 2],
                offset_fill: None,
                offset_line: None,
                offset_point: None,
                polygon_stipple: None,
                line: crate::render::line::LineParams { width: 1.0, stipple: None },
                point_size: 1.0,
                smooth: Default::default(),
                clip_planes: crate::render::clip::FIXED_PLANES.to_vec(),
                fragment: FragmentState::default(),
                texture: None,
                reference: crate::render::reference_default(),
                threads: crate::render::tile::threads_default(),
                approximate: true,
                batch: Default::default(),
                stamp: 0,
                shade: Default::default(),
            },
        }
    }
}

impl Context {
    /// The rectangle glClear and drawing may touch: the surface, cut by the
    /// scissor box when the scissor test is on.
    pub fn scissored_surface(&self) -> Rect {
        let surface = Rect::new(0, 0, self.fb.width as i32, self.fb.height as i32);
        if self.scissor.test {
            let s = &self.scissor;
            surface.intersect(Rect::new(s.x, s.y, s.width, s.height))
        } else {
            surface
        }
    }

    /// Recomputes whatever is dirty.
    pub fn validate(&mut self) {
        // Every draw comes through here: the framebuffer follows the draw
        // buffer (cheap when unchanged; it also notes front-buffer drawing
        // for glFlush).
        self.sync_draw_buffer();
        if self.dirty == 0 {
            return;
        }
        let d = self.dirty;
        self.dirty = 0;
        let surface = self.scissored_surface();
        if d & DIRTY_TRANSFORM != 0 {
            let m = *self.transform.projection.top() * *self.transform.modelview.top();
            self.derived.mvp = m.as_mat4();
            self.derived.modelview = self.transform.modelview.top().as_mat4();
            let mut planes = crate::render::clip::FIXED_PLANES.to_vec();
            planes.extend(self.clip_space_planes(self.transform.projection.top()));
            self.derived.render.clip_planes = planes;
        }
        if d & (DIRTY_LIGHTING | DIRTY_TRANSFORM) != 0 {
            let l = &self.lighting;
            self.derived.lighting = l.enabled.then(|| {
                LightingSetup::new(
                    &l.lights,
                    l.model_ambient,
                    [l.local_viewer, l.two_side, l.separate_specular, l.normalize, l.rescale_normal],
                    self.transform.modelview.top().as_mat4(),
                )
            });
            self.derived.render.two_side = l.enabled && l.two_side;
        }
        if d & (DIRTY_TEXTURE | DIRTY_TRANSFORM | DIRTY_LIGHTING) != 0 {
            self.validate_texture(d & DIRTY_TEXTURE != 0);
        }
        let fragment = (d & DIRTY_FRAGMENT != 0).then(|| self.fragment_state());
        if d & (DIRTY_FOG | DIRTY_LIGHTING) != 0 {
            self.derived.render.color_sum = self.fog.color_sum || (self.lighting.enabled && self.lighting.separate_specular);
        }
        if d & DIRTY_FOG != 0 {
            // glHint marks DIRTY_FOG.
            self.derived.render.approximate = self.hints.perspective_correction != GL_NICEST;
            self.derived.render.fog = self.fog_params();
            // The vertex stage needs eye coordinates for the fog distance.
            self.derived.modelview = self.transform.modelview.top().as_mat4();
        }
        let rs = &mut self.derived.render;
        if d & DIRTY_VIEWPORT != 0 {
            let v = &self.viewport;
            let (w, h) = (v.width as f64, v.height as f64);
            rs.viewport_scale = [w / 2.0, h / 2.0, (v.far - v.near) / 2.0];
            rs.viewport_offset = [v.x as f64 + w / 2.0, v.y as f64 + h / 2.0, (v.far + v.near) / 2.0];
        }
        if d & (DIRTY_VIEWPORT | DIRTY_RASTER) != 0 {
            let v = &self.viewport;
            rs.draw_rect = Rect::new(v.x, v.y, v.width, v.height).intersect(surface);
            rs.cull = if !self.polygon.cull {
                Cull::None
            } else {
                match self.polygon.cull_mode {
                    GL_FRONT => Cull::Front,
                    GL_BACK => Cull::Back,
                    _ => Cull::All,
                }
            };
            rs.front_ccw = self.polygon.front_face == GL_CCW;
            rs.flat = self.shade_model == GL_FLAT;
            let p = &self.polygon;
            rs.polygon_mode = p.mode;
            rs.offset_fill = p.offset_fill.then_some((p.offset_factor, p.offset_units));
            rs.offset_line = p.offset_line.then_some((p.offset_factor, p.offset_units));
            rs.offset_point = p.offset_point.then_some((p.offset_factor, p.offset_units));
            rs.polygon_stipple = p.stipple.then(|| Box::new(p.stipple_pattern));
            let l = &self.line;
            rs.line = crate::render::line::LineParams {
                width: l.width,
                stipple: if l.stipple { Some((l.stipple_repeat as u32, l.stipple_pattern)) } else { None },
            };
            rs.point_size = self.point.size;
            // Antialiasing (3.2): which primitives, at which quality.
            let on = |cap: u32, hint: u32| self.other_caps.0.contains(&cap).then(|| crate::render::smooth::Quality::from_hint(hint));
            rs.smooth = crate::render::smooth::SmoothState {
                point: on(GL_POINT_SMOOTH, self.hints.point_smooth),
                line: on(GL_LINE_SMOOTH, self.hints.line_smooth),
                polygon: on(GL_POLYGON_SMOOTH, self.hints.polygon_smooth),
                fade_threshold: self.point.fade_threshold,
            };
        }
        if let Some(f) = fragment {
            rs.fragment = f;
        }
        // Captures of the old state (render::shade_state) no longer apply.
        rs.stamp = crate::render::shade_state::next_stamp();
    }

    /// Derives the fragment pipeline's configuration (render::fragment):
    /// which stages run, and their parameters in the framebuffer's terms.
    fn fragment_state(&self) -> FragmentState {
        let cb = &self.color_buffer;
        let stencil_bits = self.fb.config.stencil_bits.min(8) as u32;
        let max = ((1u32 << stencil_bits) - 1) as u8;
        let st = &self.stencil;
        let reference = self.stencil_reference() as u8;
        let value_mask = st.value_mask as u8 & max;
        let stencil = StencilTest {
            func: st.func,
            reference,
            masked_ref: reference & value_mask,
            value_mask,
            write_mask: st.write_mask as u8 & max,
            max,
            fail: st.fail,
            zfail: st.zfail,
            zpass: st.zpass,
        };
        // glDrawBuffer(GL_NONE) writes no colour (4.2.1).
        let no_alpha = self.fb.config.alpha_bits == 0;
        let color_mask = if cb.draw_buffer == 0 {
            [false; 4]
        } else if no_alpha {
            // No alpha: every write ORs 255 into alpha (alpha_fix), so
            // alpha may be "written" whenever anything is, which keeps a
            // full mask, and the kernels that need one, for RGB surfaces.
            let m = cb.write_mask;
            [m[0], m[1], m[2], m[0] || m[1] || m[2]]
        } else {
            cb.write_mask
        };
        let color = if color_mask == [false; 4] {
            ColorOp::None
        } else if cb.color_logic_op {
            // Section 4.1.8: with the logic op enabled, blending is bypassed.
            match cb.logic_op {
                LogicOp::Copy => ColorOp::Replace,
                LogicOp::Noop => ColorOp::None,
                op => ColorOp::Logic(op),
            }
        } else if cb.blend {
            let b = Blend {
                equation: cb.blend_equation,
                src_rgb: cb.blend_src_rgb,
                dst_rgb: cb.blend_dst_rgb,
                src_alpha: cb.blend_src_alpha,
                dst_alpha: cb.blend_dst_alpha,
                constant: cb.blend_color,
            };
            if b.is_replace() {
                ColorOp::Replace
            } else {
                ColorOp::Blend(b)
            }
        } else {
            ColorOp::Replace
        };
        FragmentState {
            alpha_test: cb.alpha_test && cb.alpha_func != CompareFunc::Always,
            alpha: AlphaTest { func: cb.alpha_func, reference: color_to_u8(glam::Vec4::splat(cb.alpha_ref))[3] },
            // Without a stencil buffer the test always passes (4.1.5); a
            // test that always passes and never writes is skipped.
            stencil_test: st.test && stencil_bits > 0 && (st.func != CompareFunc::Always || stencil.writes()),
            stencil,
            depth_test: self.depth.test && self.fb.config.depth_bits > 0,
            depth_func: self.depth.func,
            depth_write: self.depth.write_mask,
            color,
            color_mask,
            alpha_fix: if no_alpha { 255 } else { 0 },
        }
    }
}
