//! Coordinate transformations (GL 1.5 section 2.11): matrix modes and
//! stacks, the matrix commands, the viewport and the depth range.
//!
//! Matrices are kept in f64: composing many transformations (deep scene
//! graphs, large translations) loses less that way, and it costs nothing on
//! the hot path, which uses the f32 combined matrix `validate` derives.

use super::context::Context;
use super::enums::*;
use super::validate::{DIRTY_TRANSFORM, DIRTY_VIEWPORT};
use crate::framebuffer::MAX_SIZE;
use glam::{DMat4, DVec3};

pub const MAX_MODELVIEW_DEPTH: usize = 32;
pub const MAX_PROJECTION_DEPTH: usize = 32;
pub const MAX_TEXTURE_DEPTH: usize = 10;
/// GL_MAX_COLOR_MATRIX_STACK_DEPTH (ARB_imaging; the spec's minimum is 2).
pub const MAX_COLOR_DEPTH: usize = 10;

/// A matrix stack; the last element is the current matrix.
#[derive(Clone, Debug)]
pub struct Stack {
    pub mats: Vec<DMat4>,
    pub max: usize,
}

impl Stack {
    fn new(max: usize) -> Stack {
        Stack { mats: vec![DMat4::IDENTITY], max }
    }

    pub fn top(&self) -> &DMat4 {
        self.mats.last().expect("a matrix stack is never empty")
    }

    fn top_mut(&mut self) -> &mut DMat4 {
        self.mats.last_mut().expect("a matrix stack is never empty")
    }

    pub fn depth(&self) -> usize {
        self.mats.len()
    }
}

#[derive(Clone, Debug)]
pub struct Transform {
    pub mode: u32,
    pub modelview: Stack,
    pub projection: Stack,
    /// One texture matrix stack per texture unit.
    pub textures: Vec<Stack>,
    /// ACTIVE_TEXTURE's unit: the stack GL_TEXTURE mode works on.
    pub active_texture: usize,
    /// The colour matrix stack (GL_COLOR mode, ARB_imaging): pixel
    /// transfer's colour matrix (`imaging`).
    pub color: Stack,
}

impl Transform {
    pub fn new() -> Transform {
        Transform {
            mode: GL_MODELVIEW,
            modelview: Stack::new(MAX_MODELVIEW_DEPTH),
            projection: Stack::new(MAX_PROJECTION_DEPTH),
            textures: vec![Stack::new(MAX_TEXTURE_DEPTH); crate::render::texture::MAX_UNITS],
            active_texture: 0,
            color: Stack::new(MAX_COLOR_DEPTH),
        }
    }

    /// The active texture unit's stack.
    pub fn texture(&self) -> &Stack {
        &self.textures[self.active_texture]
    }

    pub fn current_stack(&mut self) -> &mut Stack {
        match self.mode {
            GL_PROJECTION => &mut self.projection,
            GL_TEXTURE => &mut self.textures[self.active_texture],
            GL_COLOR => &mut self.color,
            _ => &mut self.modelview,
        }
    }
}

impl Default for Transform {
    fn default() -> Self {
        Self::new()
    }
}

impl Context {
    pub fn matrix_mode(&mut self, mode: u32) {
        match mode {
            GL_MODELVIEW | GL_PROJECTION | GL_TEXTURE | GL_COLOR => self.transform.mode = mode,
            _ => self.set_error(GL_INVALID_ENUM),
        }
    }

    pub fn load_matrix(&mut self, m: DMat4) {
        *self.transform.current_stack().top_mut() = m;
        self.dirty |= DIRTY_TRANSFORM;
    }

    /// C = C * M (section 2.11.2).
    pub fn mult_matrix(&mut self, m: DMat4) {
        let top = self.transform.current_stack().top_mut();
        *top *= m;
        self.dirty |= DIRTY_TRANSFORM;
    }

    pub fn rotate(&mut self, angle_degrees: f64, axis: [f64; 3]) {
        let axis = DVec3::from(axis);
        let len = axis.length();
        // A zero axis has no direction: the rotation is the identity.
        if len == 0.0 || !len.is_finite() {
            return;
        }
        self.mult_matrix(DMat4::from_axis_angle(axis / len, angle_degrees.to_radians()));
    }

    pub fn ortho(&mut self, [l, r, b, t, n, f]: [f64; 6]) {
        if l == r || b == t || n == f {
            return self.set_error(GL_INVALID_VALUE);
        }
        let m = DMat4::from_cols_array(&[
            2.0 / (r - l), 0.0, 0.0, 0.0,
            0.0, 2.0 / (t - b), 0.0, 0.0,
            0.0, 0.0, -2.0 / (f - n), 0.0,
            -(r + l) / (r - l), -(t + b) / (t - b), -(f + n) / (f - n), 1.0,
        ]);
        self.mult_matrix(m);
    }

    pub fn frustum(&mut self, [l, r, b, t, n, f]: [f64; 6]) {
        if n <= 0.0 || f <= 0.0 || l == r || b == t || n == f {
            return self.set_error(GL_INVALID_VALUE);
        }
        let m = DMat4::from_cols_array(&[
            2.0 * n / (r - l), 0.0, 0.0, 0.0,
            0.0, 2.0 * n / (t - b), 0.0, 0.0,
            (r + l) / (r - l), (t + b) / (t - b), -(f + n) / (f - n), -1.0,
            0.0, 0.0, -2.0 * f * n / (f - n), 0.0,
        ]);
        self.mult_matrix(m);
    }

    pub fn push_matrix(&mut self) {
        let stack = self.transform.current_stack();
        if stack.depth() >= stack.max {
            return self.set_error(GL_STACK_OVERFLOW);
        }
        let top = *stack.top();
        stack.mats.push(top);
    }

    pub fn pop_matrix(&mut self) {
        let stack = self.transform.current_stack();
        if stack.depth() <= 1 {
            return self.set_error(GL_STACK_UNDERFLOW);
        }
        stack.mats.pop();
        self.dirty |= DIRTY_TRANSFORM;
    }

    /// Section 2.11.1: sizes are clamped to GL_MAX_VIEWPORT_DIMS.
    pub fn set_viewport(&mut self, x: i32, y: i32, w: i32, h: i32) {
        if w < 0 || h < 0 {
            return self.set_error(GL_INVALID_VALUE);
        }
        let v = &mut self.viewport;
        v.x = x;
        v.y = y;
        v.width = w.min(MAX_SIZE as i32);
        v.height = h.min(MAX_SIZE as i32);
        self.dirty |= DIRTY_VIEWPORT;
    }

    pub fn depth_range(&mut self, n: f64, f: f64) {
        self.viewport.near = n.clamp(0.0, 1.0);
        self.viewport.far = f.clamp(0.0, 1.0);
        self.dirty |= DIRTY_VIEWPORT;
    }
}
