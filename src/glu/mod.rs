//! GLU 1.3 (DESIGN.md, "glu/"), written as a client of GL: it calls the
//! public GL entry points as any program would, never context internals.
//!
//! Implemented so far: the matrix utilities ([`matrix`]) and the strings
//! ([`strings`]) and the polygon tessellator ([`tess`]). Quadrics, mipmaps and NURBS are issue 6.

pub mod matrix;
pub mod mipmap;
pub mod nurbs;
pub mod quadric;
pub mod scale;
pub mod strings;
pub mod tess;
pub mod vec3;
