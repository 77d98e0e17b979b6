//! Display lists (GL 1.5 section 5.4): names, compilation, execution with
//! the nesting limit, glListBase and glCallLists' name types.
//!
//! Storage: a list is a packed stream of 32-bit words, not a vector of
//! [`Command`] values. The commands programs put in lists by the million
//! (glVertex, glColor, glNormal, glTexCoord, ...) take a header word and
//! their floats (a 2D or 3D vertex: 3 or 4 words, 12 or 16 bytes, where a
//! `Command` value is 64); everything else is kept as a `Command` in a side
//! table and the stream holds its index. A vertex-array draw compiled into
//! a list is one block (`OP_DRAW`), so that calling the list between Begin
//! and End raises INVALID_OPERATION for the draw and skips it as a whole,
//! as executing the draw there would (section 2.6.3), while the list's
//! other vertex commands still go to the open primitive.
//!
//! Header word: bits 0-7 the opcode, bits 8-31 an argument (a primitive
//! mode, a texture unit, an edge flag).
//!
//! The store is reached through [`Lists`]' methods only (define, get,
//! delete, name allocation), so that it can later be shared between
//! contexts without touching the rest of `gl`.

use super::command::Command;
use super::context::Context;
use super::enums::*;
use std::collections::HashMap;
use std::rc::Rc;

/// GL_MAX_LIST_NESTING.
pub const MAX_LIST_NESTING: u32 = 64;

// Opcodes of the word stream. The floats follow the header as f32 bits.
const OP_CMD: u32 = 0; // [index into List::cmds]
const OP_VERTEX2: u32 = 1; // [x y] (z 0, w 1)
const OP_VERTEX3: u32 = 2; // [x y z] (w 1)
const OP_VERTEX4: u32 = 3; // [x y z w]
const OP_COLOR3: u32 = 4; // [r g b] (alpha 1)
const OP_COLOR4: u32 = 5; // [r g b a]
const OP_NORMAL: u32 = 6; // [x y z]
const OP_TEXCOORD2: u32 = 7; // arg: unit; [s t] (r 0, q 1)
const OP_TEXCOORD4: u32 = 8; // arg: unit; [s t r q]
const OP_SECONDARY: u32 = 9; // [r g b a]
const OP_FOGCOORD: u32 = 10; // [f]
const OP_INDEX: u32 = 11; // [i]
const OP_EDGEFLAG: u32 = 12; // arg: flag
const OP_BEGIN: u32 = 13; // arg: mode
const OP_END: u32 = 14;
const OP_DRAW: u32 = 15; // arg: mode; [n], then n words: the elements and OP_END

/// One compiled list.
#[derive(Default, Debug, PartialEq)]
pub struct List {
    words: Vec<u32>,
    /// The commands with no compact form, referenced by OP_CMD.
    cmds: Vec<Command>,
}

impl List {
    /// Appends a header and its N floats: one capacity check, then plain
    /// stores (round 20: pushing the header and extending from an
    /// iterator checked the capacity per word).
    #[inline(always)]
    fn op<const N: usize>(&mut self, op: u32, arg: u32, data: [f32; N]) {
        self.words.reserve(N + 1);
        let at = self.words.len();
        // SAFETY: `reserve` made room for N + 1 more words past `at`; all
        // of them are written before the length takes them in.
        unsafe {
            let w = self.words.as_mut_ptr().add(at);
            w.write(op | (arg << 8));
            for (i, f) in data.iter().enumerate() {
                w.add(1 + i).write(f.to_bits());
            }
            self.words.set_len(at + N + 1);
        }
    }

    /// Appends one command: in its compact form when it has one, else to
    /// the side table.
    #[inline(always)]
    fn push(&mut self, cmd: Command) {
        // The compact variants own nothing: held in ManuallyDrop, they
        // skip the drop of a generic Command.
        let cmd = std::mem::ManuallyDrop::new(cmd);
        if !self.push_compact(&cmd) {
            self.push_cmd(std::mem::ManuallyDrop::into_inner(cmd));
        }
    }

    /// Appends `cmd` in its compact form and returns true, or returns
    /// false when it has none. Inlined: a `list` entry point compiling
    /// its command (`Context::record_compiled`) builds the command right
    /// before, so the match folds to its one arm and the words are
    /// stored from registers (round 20: matching a copy of the 64-byte
    /// command read it back from memory, a store-forwarding stall a
    /// call, and did not fold).
    #[inline(always)]
    fn push_compact(&mut self, cmd: &Command) -> bool {
        let is = |x: f32, v: f32| x.to_bits() == v.to_bits();
        match *cmd {
            Command::Vertex([x, y, z, w]) if is(w, 1.0) && is(z, 0.0) => self.op(OP_VERTEX2, 0, [x, y]),
            Command::Vertex([x, y, z, w]) if is(w, 1.0) => self.op(OP_VERTEX3, 0, [x, y, z]),
            Command::Vertex(v) => self.op(OP_VERTEX4, 0, v),
            Command::Color([r, g, b, a]) if is(a, 1.0) => self.op(OP_COLOR3, 0, [r, g, b]),
            Command::Color(c) => self.op(OP_COLOR4, 0, c),
            Command::Normal(n) => self.op(OP_NORMAL, 0, n),
            // Units beyond the header's range are kept as commands (they
            // raise INVALID_ENUM when run).
            Command::TexCoord(unit, [s, t, r, q]) if unit.wrapping_sub(super::arrays::GL_TEXTURE0) < 256 => {
                let u = unit - super::arrays::GL_TEXTURE0;
                if is(r, 0.0) && is(q, 1.0) {
                    self.op(OP_TEXCOORD2, u, [s, t])
                } else {
                    self.op(OP_TEXCOORD4, u, [s, t, r, q])
                }
            }
            Command::SecondaryColor(c) => self.op(OP_SECONDARY, 0, c),
            Command::FogCoord(f) => self.op(OP_FOGCOORD, 0, [f]),
            Command::Index(i) => self.op(OP_INDEX, 0, [i]),
            Command::EdgeFlag(f) => self.op(OP_EDGEFLAG, f as u32, []),
            Command::Begin(mode) if mode <= 0xFF_FFFF => self.op(OP_BEGIN, mode, []),
            Command::End => self.op(OP_END, 0, []),
            _ => return false,
        }
        true
    }

    /// A command with no compact form: kept in the side table, referenced
    /// by OP_CMD. Out of line (rare; keeps `push` small where inlined).
    #[inline(never)]
    fn push_cmd(&mut self, cmd: Command) {
        let i = self.cmds.len() as u32;
        self.cmds.push(cmd);
        self.words.push(OP_CMD);
        self.words.push(i);
    }

    /// Bytes the list holds (for tests and measurements).
    pub fn bytes(&self) -> usize {
        self.words.capacity() * 4 + self.cmds.capacity() * std::mem::size_of::<Command>()
    }
}

/// The list names in use and their contents: the part of display-list
/// state that contexts sharing lists (glXCreateContext's share_list,
/// wglShareLists) share (gl::share swaps it in for each call). Everything
/// else reaches it through these four methods.
#[derive(Default)]
pub struct ListStore {
    /// Defined lists (possibly empty). Rc: a list keeps running even if it
    /// deletes or redefines itself.
    lists: HashMap<u32, Rc<List>>,
    /// Where glGenLists' search starts (`names`).
    cursor: u32,
}

impl ListStore {
    pub fn contains(&self, n: u32) -> bool {
        self.lists.contains_key(&n)
    }

    pub fn get(&self, n: u32) -> Option<Rc<List>> {
        self.lists.get(&n).cloned()
    }

    /// Defines (or redefines) list `n`.
    pub fn define(&mut self, n: u32, list: List) {
        self.lists.insert(n, Rc::new(list));
    }

    pub fn remove(&mut self, n: u32) {
        self.lists.remove(&n);
    }

    /// glGenLists: the first of `range` (> 0) consecutive unused names,
    /// each defined as an empty list.
    pub fn generate(&mut self, range: u32) -> Option<u32> {
        let lists = &self.lists;
        let start = super::names::free_run(&mut self.cursor, range, |n| !lists.contains_key(&n))?;
        for n in start..=start + (range - 1) {
            self.define(n, List::default());
        }
        Some(start)
    }
}

#[derive(Default)]
pub struct Lists {
    pub store: ListStore,
    compiling: Option<Compiling>,
    pub base: u32,
    depth: u32,
}

struct Compiling {
    name: u32,
    mode: u32,
    list: List,
    /// Where the open OP_DRAW block's length word is.
    draw: Option<usize>,
}

impl Lists {
    /// GL_COMPILE or GL_COMPILE_AND_EXECUTE while a list is open.
    #[inline]
    pub fn compile_mode(&self) -> Option<u32> {
        self.compiling.as_ref().map(|c| c.mode)
    }

    #[inline(always)]
    pub fn record(&mut self, cmd: Command) {
        if let Some(c) = &mut self.compiling {
            c.list.push(cmd);
        }
    }

    /// Records `cmd` when it has a compact form (true); false leaves it
    /// to [`Lists::record`]. See `List::push_compact`.
    #[inline(always)]
    pub fn record_compact(&mut self, cmd: &Command) -> bool {
        match &mut self.compiling {
            Some(c) => c.list.push_compact(cmd),
            None => false,
        }
    }

    /// Opens the block of a vertex-array draw being compiled: Begin(mode),
    /// the elements recorded next, and the End of [`Lists::end_draw`].
    pub fn begin_draw(&mut self, mode: u32) {
        if let Some(c) = &mut self.compiling {
            c.list.words.push(OP_DRAW | (mode << 8));
            c.draw = Some(c.list.words.len());
            c.list.words.push(0);
        }
    }

    pub fn end_draw(&mut self) {
        if let Some(c) = &mut self.compiling {
            c.list.words.push(OP_END);
            if let Some(at) = c.draw.take() {
                c.list.words[at] = (c.list.words.len() - at - 1) as u32;
            }
        }
    }

    /// GL_LIST_INDEX: the list being compiled, or 0.
    pub fn index(&self) -> u32 {
        self.compiling.as_ref().map_or(0, |c| c.name)
    }

    pub fn is_list(&self, n: u32) -> bool {
        self.store.contains(n)
    }

    /// The list named `n`, for measurements and tests.
    pub fn get(&self, n: u32) -> Option<Rc<List>> {
        self.store.get(n)
    }

    /// Exchanges the table of defined lists with a share group's
    /// (gl::share): the lists are shared, compilation state and the list
    /// base stay per context.
    pub fn swap_table(&mut self, table: &mut ListStore) {
        std::mem::swap(&mut self.store, table);
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
        match self.lists.store.generate(range as u32) {
            Some(start) => start,
            None => {
                self.set_error(GL_OUT_OF_MEMORY);
                0
            }
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
        self.lists.compiling = Some(Compiling { name: n, mode, list: List::default(), draw: None });
    }

    pub fn end_list(&mut self) {
        match self.lists.compiling.take() {
            Some(Compiling { name, mut list, .. }) => {
                self.compile_fast = false;
                list.words.shrink_to_fit();
                list.cmds.shrink_to_fit();
                self.lists.store.define(name, list);
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
                    self.lists.store.remove(n);
                }
                None => break,
            }
        }
    }

    pub fn call_list(&mut self, n: u32) {
        if self.lists.depth >= MAX_LIST_NESTING {
            return;
        }
        let Some(list) = self.lists.store.get(n) else { return };
        self.lists.depth += 1;
        self.replay(&list);
        self.lists.depth -= 1;
    }

    pub fn call_lists(&mut self, names: &[u32]) {
        let base = self.lists.base;
        for &n in names {
            self.call_list(base.wrapping_add(n));
        }
    }

    /// Executes a list's word stream.
    fn replay(&mut self, list: &List) {
        let w = &list.words[..];
        let f = |i: usize| f32::from_bits(w[i]);
        let mut i = 0;
        // Whether the open primitive is on the batched path's plain case
        // (`Context::plain_batch`): only Begin, End, a draw or a general
        // command (a nested list) can change it, and it is read again
        // after each; vertices then enter the batched path directly.
        let mut plain = self.plain_batch();
        while i < w.len() {
            let (op, arg) = (w[i] & 0xFF, w[i] >> 8);
            i += 1;
            match op {
                OP_VERTEX2 => {
                    let p = [f(i), f(i + 1), 0.0, 1.0];
                    if plain { self.vertex_fast::<true>(p) } else { self.vertex(p) }
                    i += 2;
                }
                OP_VERTEX3 => {
                    let p = [f(i), f(i + 1), f(i + 2), 1.0];
                    if plain { self.vertex_fast::<true>(p) } else { self.vertex(p) }
                    i += 3;
                }
                OP_VERTEX4 => {
                    self.vertex([f(i), f(i + 1), f(i + 2), f(i + 3)]);
                    i += 4;
                }
                OP_COLOR3 => {
                    self.set_color([f(i), f(i + 1), f(i + 2), 1.0]);
                    i += 3;
                }
                OP_COLOR4 => {
                    self.set_color([f(i), f(i + 1), f(i + 2), f(i + 3)]);
                    i += 4;
                }
                OP_NORMAL => {
                    self.current.normal = [f(i), f(i + 1), f(i + 2)];
                    i += 3;
                }
                OP_TEXCOORD2 => {
                    self.tex_coord(super::arrays::GL_TEXTURE0 + arg, [f(i), f(i + 1), 0.0, 1.0]);
                    i += 2;
                }
                OP_TEXCOORD4 => {
                    self.tex_coord(super::arrays::GL_TEXTURE0 + arg, [f(i), f(i + 1), f(i + 2), f(i + 3)]);
                    i += 4;
                }
                OP_SECONDARY => {
                    self.current.secondary_color = [f(i), f(i + 1), f(i + 2), f(i + 3)];
                    i += 4;
                }
                OP_FOGCOORD => {
                    self.current.fog_coord = f(i);
                    i += 1;
                }
                OP_INDEX => {
                    self.current.index = f(i);
                    i += 1;
                }
                OP_EDGEFLAG => self.current.edge_flag = arg != 0,
                OP_BEGIN => {
                    self.execute(&Command::Begin(arg));
                    plain = self.plain_batch();
                }
                OP_END => {
                    self.execute(&Command::End);
                    plain = self.plain_batch();
                }
                OP_DRAW => {
                    let n = w[i] as usize;
                    i += 1;
                    if self.in_begin_end() {
                        // The draw as a whole is illegal here; skip it.
                        self.set_error(GL_INVALID_OPERATION);
                        i += n;
                    } else {
                        self.begin(arg);
                        plain = self.plain_batch();
                    }
                }
                _ => {
                    let cmd = &list.cmds[w[i] as usize];
                    i += 1;
                    self.execute(cmd);
                    plain = self.plain_batch();
                }
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn replayed(cmds: Vec<Command>) -> (Vec<u32>, Vec<Command>) {
        let mut l = List::default();
        for c in cmds {
            l.push(c);
        }
        (l.words, l.cmds)
    }

    #[test]
    fn vertex_commands_are_compact() {
        let (w, cmds) = replayed(vec![
            Command::Vertex([1.0, 2.0, 0.0, 1.0]),
            Command::Vertex([1.0, 2.0, 3.0, 1.0]),
            Command::Vertex([1.0, 2.0, -0.0, 1.0]),
            Command::Color([0.5, 0.25, 0.0, 1.0]),
            Command::Normal([0.0, 0.0, 1.0]),
            Command::TexCoord(0x84C1, [0.5, 0.5, 0.0, 1.0]),
            Command::ShadeModel(GL_FLAT),
        ]);
        // 3 + 4 + 4 (-0.0 is kept, so a 3D vertex) + 4 + 4 + 3 + 2 words.
        assert_eq!(w.len(), 24);
        assert_eq!(w[0], OP_VERTEX2);
        assert_eq!(w[3], OP_VERTEX3);
        assert_eq!(w[7], OP_VERTEX3);
        assert_eq!(f32::from_bits(w[10]).to_bits(), (-0.0f32).to_bits());
        assert_eq!(w[11], OP_COLOR3);
        assert_eq!(w[19], OP_TEXCOORD2 | (1 << 8));
        assert_eq!(cmds, vec![Command::ShadeModel(GL_FLAT)]);
    }
}
