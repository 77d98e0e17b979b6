//! Window-system bindings (DESIGN.md, "winsys/"): how programs get a
//! context and a surface. [`current`] holds the per-thread current context;
//! [`osmesa`] is the OSMesa API over caller-owned buffers; [`glx`] is GLX 1.4
//! over Xlib (loaded at run time).

pub mod bound;
pub mod current;
pub mod dump;
pub mod font_outlines;
#[cfg(windows)]
pub mod gdi;
pub mod glx;
pub mod osmesa;
pub mod wgl;
