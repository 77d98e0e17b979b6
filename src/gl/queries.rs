//! Occlusion queries (GL 1.5 section 4.1.6, "Occlusion Queries", and the
//! query object queries of section 6.1.12).
//!
//! The count: every fragment that passes the depth test, or reaches it with
//! the depth test disabled, after the stencil test (so also after the alpha
//! test and scissor) is a sample that passed. The fragment stage keeps a
//! running total of such fragments in [`Framebuffer::samples_passed`]
//! (`render::fragment`); glBeginQuery remembers the total and glEndQuery
//! stores the difference. Rendering is synchronous, so a result is always
//! available when it is asked for.
//!
//! Query objects are created by the first glBeginQuery of a name (glIsQuery
//! is false for a name that was only generated). glBeginQuery and
//! glEndQuery are compiled into display lists (they are not in section
//! 5.4's list of commands executed immediately); glGenQueries,
//! glDeleteQueries, glIsQuery and the gets are not.
//!
//! [`Framebuffer::samples_passed`]: crate::framebuffer::Framebuffer::samples_passed

use super::context::Context;
use super::enums::*;
use super::names::Reserved;
use std::collections::HashMap;

pub const GL_QUERY_COUNTER_BITS: u32 = 0x8864;
pub const GL_CURRENT_QUERY: u32 = 0x8865;
pub const GL_QUERY_RESULT: u32 = 0x8866;
pub const GL_QUERY_RESULT_AVAILABLE: u32 = 0x8867;
pub const GL_SAMPLES_PASSED: u32 = 0x8914;

/// GL_QUERY_COUNTER_BITS: results are counted in 64 bits and reported
/// saturated to 32 by the GL 1.5 (32-bit) query functions.
pub const COUNTER_BITS: i64 = 32;

#[derive(Debug, Default)]
pub struct Queries {
    names: Reserved,
    /// Query objects and their last results.
    objects: HashMap<u32, u64>,
    /// The active SAMPLES_PASSED query: its name and the fragment stage's
    /// running total when it began.
    active: Option<(u32, u64)>,
}

impl Context {
    pub fn gen_queries(&mut self, n: i32) -> Option<Vec<u32>> {
        if n < 0 {
            self.set_error(GL_INVALID_VALUE);
            return None;
        }
        Some(self.queries.names.generate(n as usize, |_| false))
    }

    pub fn delete_queries(&mut self, names: &[u32]) {
        for &n in names {
            if n == 0 {
                continue;
            }
            // Deleting the active query ends it; its result is lost.
            if self.queries.active.is_some_and(|(a, _)| a == n) {
                self.queries.active = None;
            }
            self.queries.objects.remove(&n);
            self.queries.names.remove(n);
        }
    }

    pub fn is_query(&self, n: u32) -> bool {
        n != 0 && self.queries.objects.contains_key(&n)
    }

    pub fn begin_query(&mut self, target: u32, id: u32) {
        if target != GL_SAMPLES_PASSED {
            return self.set_error(GL_INVALID_ENUM);
        }
        if id == 0 || self.queries.active.is_some() {
            return self.set_error(GL_INVALID_OPERATION);
        }
        self.queries.names.insert(id);
        self.queries.objects.insert(id, 0);
        self.queries.active = Some((id, self.fb.samples_passed));
    }

    pub fn end_query(&mut self, target: u32) {
        if target != GL_SAMPLES_PASSED {
            return self.set_error(GL_INVALID_ENUM);
        }
        let Some((id, start)) = self.queries.active.take() else {
            return self.set_error(GL_INVALID_OPERATION);
        };
        self.queries.objects.insert(id, self.fb.samples_passed.wrapping_sub(start));
    }

    /// glGetQueryiv.
    pub fn get_query(&mut self, target: u32, pname: u32) -> Option<i64> {
        if target != GL_SAMPLES_PASSED {
            self.set_error(GL_INVALID_ENUM);
            return None;
        }
        match pname {
            GL_CURRENT_QUERY => Some(self.queries.active.map_or(0, |(id, _)| id as i64)),
            GL_QUERY_COUNTER_BITS => Some(COUNTER_BITS),
            _ => {
                self.set_error(GL_INVALID_ENUM);
                None
            }
        }
    }

    /// glGetQueryObject{i,ui}v: the result (unclamped; the entry point
    /// saturates it to its type) or availability.
    pub fn get_query_object(&mut self, id: u32, pname: u32) -> Option<u64> {
        if !matches!(pname, GL_QUERY_RESULT | GL_QUERY_RESULT_AVAILABLE) {
            self.set_error(GL_INVALID_ENUM);
            return None;
        }
        let active = self.queries.active.is_some_and(|(a, _)| a == id);
        let Some(&result) = self.queries.objects.get(&id).filter(|_| !active) else {
            self.set_error(GL_INVALID_OPERATION);
            return None;
        };
        Some(if pname == GL_QUERY_RESULT { result } else { 1 })
    }
}
