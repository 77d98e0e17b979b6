//! softgl: a software OpenGL 1.x — GL 1.0–1.5 fixed function and GLU 1.3
//! behind a C ABI, over its own CPU rasterizer — that programs load in place
//! of `libGL.so.1`, `libGLU.so.1` or `libOSMesa.so.8`.
//!
//! Layers (DESIGN.md): [`api`] (the C ABI and its one table of entry points)
//! → [`gl`] (the state machine) → [`render`] (the pipeline) →
//! [`framebuffer`] (storage); [`glu`] and [`winsys`] sit beside them.

// `!(a < b)` on floats is how this crate says "not less, or NaN": a
// NaN input must take the rejecting branch (clipping, GLU's checks, the
// rasterizer's guards), which `a >= b` would not.
#![allow(clippy::neg_cmp_op_on_partial_ord)]

pub mod api;
pub mod fonts;
pub mod framebuffer;
pub mod gl;
pub mod glu;
pub mod render;
pub mod winsys;
