//! The GL state machine (DESIGN.md, "gl/"): state grouped as the spec's
//! attribute groups, the error rules, display lists and queries. Setters
//! only store state and mark dirty bits; [`validate`] derives what the
//! renderer needs at the next draw.

pub mod arrays;
pub mod accum;
pub mod attrib;
pub mod begin_end;
pub mod blit;
pub mod buffers;
pub mod clear;
pub mod clip_plane;
pub mod command;
pub mod context;
pub mod draw_buffer;
pub mod draw_pixels;
pub mod draw_pixels_fast;
pub mod enable;
pub mod enums;
pub mod eval;
pub mod fog;
pub mod fragment;
pub mod framebuffer_object;
pub mod get;
pub mod imaging;
pub mod lighting;
pub mod lists;
pub mod matrix;
pub mod names;
pub mod pixel_buffer;
pub mod pixel_data;
pub mod pixel_transfer;
pub mod pixels;
pub mod queries;
pub mod polygon;
pub mod select;
pub mod share;
pub mod raster_pos;
pub mod state;
pub mod texture;
pub mod validate;

pub use command::Command;
pub use context::Context;
