//! Window-system bindings (DESIGN.md, "winsys/"): how programs get a
//! context and a surface. [`current`] holds the per-thread current context;
//! [`osmesa`] is the OSMesa API over caller-owned buffers.

pub mod current;
pub mod osmesa;
