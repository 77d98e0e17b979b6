//! Setters of the per-fragment operations' state (GL 1.5 sections 4.1.4
//! to 4.1.10): glAlphaFunc, glStencilFunc, glStencilOp, glBlendFunc,
//! glBlendFuncSeparate, glBlendEquation, glLogicOp. Each checks its enums
//! (GL_INVALID_ENUM, changing nothing), stores, and marks the fragment
//! state dirty; validation derives `render::FragmentState`.

use super::context::Context;
use super::enums::*;
use super::validate::DIRTY_FRAGMENT;
use crate::render::fragment::{BlendEquation, BlendFactor, CompareFunc, LogicOp, StencilOp};

impl Context {
    pub fn alpha_func(&mut self, func: u32, reference: f32) {
        let Some(f) = CompareFunc::from_gl(func) else { return self.set_error(GL_INVALID_ENUM) };
        let cb = &mut self.color_buffer;
        cb.alpha_func = f;
        cb.alpha_ref = if reference.is_nan() { 0.0 } else { reference.clamp(0.0, 1.0) };
        self.dirty |= DIRTY_FRAGMENT;
    }

    pub fn stencil_func(&mut self, func: u32, reference: i32, mask: u32) {
        let Some(f) = CompareFunc::from_gl(func) else { return self.set_error(GL_INVALID_ENUM) };
        let s = &mut self.stencil;
        s.func = f;
        s.reference = reference;
        s.value_mask = mask;
        self.dirty |= DIRTY_FRAGMENT;
    }

    pub fn stencil_op(&mut self, fail: u32, zfail: u32, zpass: u32) {
        let (Some(a), Some(b), Some(c)) = (StencilOp::from_gl(fail), StencilOp::from_gl(zfail), StencilOp::from_gl(zpass)) else {
            return self.set_error(GL_INVALID_ENUM);
        };
        let s = &mut self.stencil;
        (s.fail, s.zfail, s.zpass) = (a, b, c);
        self.dirty |= DIRTY_FRAGMENT;
    }

    /// glBlendFuncSeparate(src_rgb, dst_rgb, src_alpha, dst_alpha); glBlendFunc
    /// passes its two factors twice.
    pub fn blend_func(&mut self, f: [u32; 4]) {
        let (Some(sr), Some(dr), Some(sa), Some(da)) = (
            BlendFactor::from_gl(f[0], true),
            BlendFactor::from_gl(f[1], false),
            BlendFactor::from_gl(f[2], true),
            BlendFactor::from_gl(f[3], false),
        ) else {
            return self.set_error(GL_INVALID_ENUM);
        };
        let cb = &mut self.color_buffer;
        (cb.blend_src_rgb, cb.blend_dst_rgb, cb.blend_src_alpha, cb.blend_dst_alpha) = (sr, dr, sa, da);
        self.dirty |= DIRTY_FRAGMENT;
    }

    pub fn blend_equation(&mut self, mode: u32) {
        let Some(m) = BlendEquation::from_gl(mode) else { return self.set_error(GL_INVALID_ENUM) };
        self.color_buffer.blend_equation = m;
        self.dirty |= DIRTY_FRAGMENT;
    }

    pub fn logic_op(&mut self, op: u32) {
        let Some(op) = LogicOp::from_gl(op) else { return self.set_error(GL_INVALID_ENUM) };
        self.color_buffer.logic_op = op;
        self.dirty |= DIRTY_FRAGMENT;
    }

    /// The stencil reference as the test uses it: clamped to [0, 2^bits - 1].
    pub fn stencil_reference(&self) -> i32 {
        let max = (1i32 << self.fb.config.stencil_bits.min(8)) - 1;
        self.stencil.reference.clamp(0, max)
    }
}
