//! Display lists (GL 1.5 section 5.4): names, compilation, execution with
//! the nesting limit, glListBase and glCallLists' name types.

use super::command::Command;
use super::context::Context;
use super::enums::*;
use std::collections::HashMap;
use std::rc::Rc;

/// GL_MAX_LIST_NESTING.
pub const MAX_LIST_NESTING: u32 = 64;

#[derive(Default)]
pub struct Lists {
    /// Defined lists (possibly empty). Rc: a list keeps running even if it
    /// deletes or redefines itself.
    lists: HashMap<u32, Rc<[Command]>>,
    compiling: Option<(u32, u32, Vec<Command>)>,
    pub base: u32,
    depth: u32,
}

impl Lists {
    /// GL_COMPILE or GL_COMPILE_AND_EXECUTE while a list is open.
    #[inline]
    pub fn compile_mode(&self) -> Option<u32> {
        self.compiling.as_ref().map(|c| c.1)
    }

    pub fn record(&mut self, cmd: Command) {
        if let Some((_, _, cmds)) = &mut self.compiling {
            cmds.push(cmd);
        }
    }

    /// GL_LIST_INDEX: the list being compiled, or 0.
    pub fn index(&self) -> u32 {
        self.compiling.as_ref().map_or(0, |c| c.0)
    }

    pub fn is_list(&self, n: u32) -> bool {
        self.lists.contains_key(&n)
    }

    /// Exchanges the table of defined lists with a share group's
    /// (gl::share): the lists are shared, compilation state and the list
    /// base stay per context.
    pub fn swap_table(&mut self, table: &mut HashMap<u32, Rc<[Command]>>) {
        std::mem::swap(&mut self.lists, table);
    }
}

/// Reads glCallLists' `n` names of type `ty` from `p`.
///
/// # Safety
/// `p` must point to `n` names of type `ty` (or be NULL).
pub unsafe fn decode_names(n: i32, ty: u32, p: *const u8) -> Result<Vec<u32>, u32> {
    if n < 0 {
        return Err(GL_INVALID_VALUE);
    }
    let size = match ty {
        GL_BYTE | GL_UNSIGNED_BYTE => 1,
        GL_SHORT | GL_UNSIGNED_SHORT | GL_2_BYTES => 2,
        GL_3_BYTES => 3,
        GL_INT | GL_UNSIGNED_INT | GL_FLOAT | GL_4_BYTES => 4,
        _ => return Err(GL_INVALID_ENUM),
    };
    if p.is_null() {
        return Ok(Vec::new());
    }
    let bytes = std::slice::from_raw_parts(p, n as usize * size);
    Ok(bytes
        .chunks_exact(size)
        .map(|b| match ty {
            GL_BYTE => b[0] as i8 as i32 as u32,
            GL_UNSIGNED_BYTE => b[0] as u32,
            GL_SHORT => i16::from_ne_bytes([b[0], b[1]]) as i32 as u32,
            GL_UNSIGNED_SHORT => u16::from_ne_bytes([b[0], b[1]]) as u32,
            GL_INT => i32::from_ne_bytes([b[0], b[1], b[2], b[3]]) as u32,
            GL_UNSIGNED_INT => u32::from_ne_bytes([b[0], b[1], b[2], b[3]]),
            GL_FLOAT => f32::from_ne_bytes([b[0], b[1], b[2], b[3]]) as i64 as u32,
            // The n-byte types are big-endian byte sequences (table 5.4).
            _ => b.iter().fold(0u32, |acc, &x| (acc << 8) | x as u32),
        })
        .collect())
}

impl Context {
    pub fn gen_lists(&mut self, range: i32) -> u32 {
        if range < 0 {
            self.set_error(GL_INVALID_VALUE);
            return 0;
        }
        if range == 0 {
            return 0;
        }
        let range = range as u32;
        // First run of `range` free names after the highest used one is the
        // simple answer, falling back to a scan when names run out.
        let mut start = 1u32;
        'search: loop {
            let Some(end) = start.checked_add(range - 1) else {
                self.set_error(GL_OUT_OF_MEMORY);
                return 0;
            };
            for n in start..=end {
                if self.lists.lists.contains_key(&n) {
                    start = n + 1;
                    continue 'search;
                }
            }
            for n in start..=end {
                self.lists.lists.insert(n, Rc::from(Vec::new()));
            }
            return start;
        }
    }

    pub fn new_list(&mut self, n: u32, mode: u32) {
        if n == 0 {
            return self.set_error(GL_INVALID_VALUE);
        }
        if mode != GL_COMPILE && mode != GL_COMPILE_AND_EXECUTE {
            return self.set_error(GL_INVALID_ENUM);
        }
        if self.lists.compiling.is_some() {
            return self.set_error(GL_INVALID_OPERATION);
        }
        self.lists.compiling = Some((n, mode, Vec::new()));
    }

    pub fn end_list(&mut self) {
        match self.lists.compiling.take() {
            Some((n, _, cmds)) => {
                self.lists.lists.insert(n, Rc::from(cmds));
            }
            None => self.set_error(GL_INVALID_OPERATION),
        }
    }

    pub fn delete_lists(&mut self, first: u32, range: i32) {
        if range < 0 {
            return self.set_error(GL_INVALID_VALUE);
        }
        for i in 0..range as u32 {
            match first.checked_add(i) {
                Some(n) => {
                    self.lists.lists.remove(&n);
                }
                None => break,
            }
        }
    }

    pub fn call_list(&mut self, n: u32) {
        if self.lists.depth >= MAX_LIST_NESTING {
            return;
        }
        let Some(list) = self.lists.lists.get(&n).cloned() else { return };
        self.lists.depth += 1;
        for cmd in list.iter() {
            self.execute(cmd);
        }
        self.lists.depth -= 1;
    }

    pub fn call_lists(&mut self, names: &[u32]) {
        let base = self.lists.base;
        for &n in names {
            self.call_list(base.wrapping_add(n));
        }
    }
}
