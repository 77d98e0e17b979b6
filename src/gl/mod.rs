//! The GL state machine (DESIGN.md, "gl/"): state grouped as the spec's
//! attribute groups, the error rules, display lists and queries. Setters
//! only store state and mark dirty bits; [`validate`] derives what the
//! renderer needs at the next draw.

pub mod arrays;
pub mod begin_end;
pub mod buffers;
pub mod clear;
pub mod command;
pub mod context;
pub mod enable;
pub mod enums;
pub mod fragment;
pub mod get;
pub mod lighting;
pub mod lists;
pub mod matrix;
pub mod pixels;
pub mod queries;
pub mod state;
pub mod validate;

pub use command::Command;
pub use context::Context;
