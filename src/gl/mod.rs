//! The GL state machine (DESIGN.md, "gl/"): state grouped as the spec's
//! attribute groups, the error rules, display lists and queries. Setters
//! only store state and mark dirty bits; [`validate`] derives what the
//! renderer needs at the next draw.

pub mod begin_end;
pub mod clear;
pub mod command;
pub mod context;
pub mod draw_pixels;
pub mod enable;
pub mod enums;
pub mod fragment;
pub mod get;
pub mod lighting;
pub mod lists;
pub mod matrix;
pub mod pixel_data;
pub mod pixel_transfer;
pub mod pixels;
pub mod raster_pos;
pub mod state;
pub mod validate;

pub use command::Command;
pub use context::Context;
