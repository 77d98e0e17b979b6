//! Vertex arrays (GL 1.5 section 2.8): the array pointers and their
//! client-state enables, glClientActiveTexture, glInterleavedArrays
//! (table 2.5), glArrayElement, glDrawArrays, glDrawElements,
//! glDrawRangeElements, glMultiDrawArrays and glMultiDrawElements, with
//! arrays and indices sourced from client memory or from buffer objects
//! (section 2.9.1: a pointer is then an offset into the buffer bound to
//! ARRAY_BUFFER when the pointer was specified; indices are an offset into
//! the ELEMENT_ARRAY_BUFFER bound at the draw), and the array queries
//! (glGetPointerv, the GL_*_ARRAY_* values of table 6.6 to 6.8).
//!
//! Executing, a draw goes straight to primitive assembly: it reads each
//! enabled array through a [`Source`] chosen once per draw (base address,
//! stride and a reader monomorphized over the component type), sets the
//! current values as glArrayElement would, and calls [`Context::vertex`],
//! with no allocation and no [`Command`] per vertex.
//!
//! Compiling (section 5.4): the array data are read at compile time, and a
//! draw is recorded as the commands it generates, in one draw block
//! (gl::lists' `begin_draw`: Begin(mode), illegal as a whole when the list
//! is called between Begin and End), then for each element its attribute commands (`EdgeFlag`, `MultiTexCoord`,
//! `Color`, `SecondaryColor`, `FogCoord`, `Index`, `Normal`) and `Vertex`,
//! then `End`; glArrayElement records its element alone. Later changes to
//! the arrays or buffers do not change the list. In GL_COMPILE_AND_EXECUTE
//! the draw is also executed. Errors of a draw being compiled (bad mode,
//! negative count, mapped buffer) are reported at compile time and nothing
//! is recorded.
//!
//! Texture coordinates: one array per texture unit; glTexCoordPointer,
//! GL_TEXTURE_COORD_ARRAY and the GL_TEXTURE_COORD_ARRAY_* queries act on
//! the client active unit (`texture.client_active`, gl::texture's
//! glClientActiveTexture). Executed, they set `current.tex_coords`;
//! compiled, they record `Command::TexCoord(GL_TEXTURE0 + unit, strq)`, as
//! glMultiTexCoord does.
//!
//! Safety: client arrays are read through the raw pointers the program
//! gave, as GL requires. A client pointer inside the first page (NULL, or
//! a buffer offset given while no buffer is bound, a common mistake) is
//! never read: its array is treated as disabled, its indices as none.
//! Buffer-object arrays are bounds-checked: an element outside the buffer
//! reads as (0, 0, 0, 1).

use super::command::Command;
use super::context::Context;
use super::enums::*;
use super::get::Value;

/// Texture coordinate sets (and texture coordinate arrays) kept per vertex.
pub use crate::render::texture::MAX_UNITS as MAX_TEXTURE_UNITS;

/// GL_MAX_ELEMENTS_VERTICES and GL_MAX_ELEMENTS_INDICES: a recommendation
/// only; any count draws.
pub const MAX_ELEMENTS: i64 = 65536;

pub const GL_TEXTURE0: u32 = 0x84C0;
pub const GL_CURRENT_INDEX: u32 = 0x0B01;
pub const GL_EDGE_FLAG: u32 = 0x0B43;
pub const GL_CURRENT_FOG_COORD: u32 = 0x8453;
pub const GL_CURRENT_SECONDARY_COLOR: u32 = 0x8459;
const GL_FEEDBACK_BUFFER_POINTER: u32 = 0x0DF0;
const GL_SELECTION_BUFFER_POINTER: u32 = 0x0DF3;

/// glInterleavedArrays formats (table 2.5).
pub const GL_V2F: u32 = 0x2A20;
pub const GL_T4F_C4F_N3F_V4F: u32 = 0x2A2D;

/// One of the arrays of section 2.8.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Array {
    Vertex,
    Normal,
    Color,
    SecondaryColor,
    FogCoord,
    Index,
    EdgeFlag,
    /// The texture coordinate array of a unit.
    TexCoord(usize),
}

/// An array's state (table 6.6 onwards): enable, size, type, stride,
/// pointer and buffer binding.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ArrayPointer {
    pub enabled: bool,
    pub size: i32,
    pub type_: u32,
    /// As specified (0: tightly packed).
    pub stride: i32,
    /// The address given, or an offset into `buffer` when it is not zero.
    pub pointer: usize,
    /// ARRAY_BUFFER_BINDING when the pointer was specified.
    pub buffer: u32,
}

impl ArrayPointer {
    const fn initial(size: i32) -> ArrayPointer {
        ArrayPointer { enabled: false, size, type_: GL_FLOAT, stride: 0, pointer: 0, buffer: 0 }
    }
}

/// GL_CLIENT_VERTEX_ARRAY_BIT state, less the buffer bindings (kept in
/// [`super::buffers::Buffers`]).
#[derive(Clone, Debug, PartialEq)]
pub struct ArrayState {
    pub vertex: ArrayPointer,
    pub normal: ArrayPointer,
    pub color: ArrayPointer,
    pub secondary_color: ArrayPointer,
    pub fog_coord: ArrayPointer,
    pub index: ArrayPointer,
    pub edge_flag: ArrayPointer,
    pub tex_coord: [ArrayPointer; MAX_TEXTURE_UNITS],
}

impl Default for ArrayState {
    fn default() -> Self {
        ArrayState {
            vertex: ArrayPointer::initial(4),
            normal: ArrayPointer::initial(3),
            color: ArrayPointer::initial(4),
            secondary_color: ArrayPointer::initial(3),
            fog_coord: ArrayPointer::initial(1),
            index: ArrayPointer::initial(1),
            edge_flag: ArrayPointer { type_: GL_UNSIGNED_BYTE, ..ArrayPointer::initial(1) },
            tex_coord: [ArrayPointer::initial(4); MAX_TEXTURE_UNITS],
        }
    }
}

impl ArrayState {
    pub fn get(&self, a: Array) -> &ArrayPointer {
        match a {
            Array::Vertex => &self.vertex,
            Array::Normal => &self.normal,
            Array::Color => &self.color,
            Array::SecondaryColor => &self.secondary_color,
            Array::FogCoord => &self.fog_coord,
            Array::Index => &self.index,
            Array::EdgeFlag => &self.edge_flag,
            Array::TexCoord(u) => &self.tex_coord[u],
        }
    }

    pub fn get_mut(&mut self, a: Array) -> &mut ArrayPointer {
        match a {
            Array::Vertex => &mut self.vertex,
            Array::Normal => &mut self.normal,
            Array::Color => &mut self.color,
            Array::SecondaryColor => &mut self.secondary_color,
            Array::FogCoord => &mut self.fog_coord,
            Array::Index => &mut self.index,
            Array::EdgeFlag => &mut self.edge_flag,
            Array::TexCoord(u) => &mut self.tex_coord[u],
        }
    }

    fn all(&self) -> impl Iterator<Item = &ArrayPointer> {
        [&self.vertex, &self.normal, &self.color, &self.secondary_color, &self.fog_coord, &self.index, &self.edge_flag]
            .into_iter()
            .chain(self.tex_coord.iter())
    }

    /// The array a client-state capability names (GL_TEXTURE_COORD_ARRAY:
    /// the client active unit's).
    pub fn from_cap(cap: u32, client_active: usize) -> Option<Array> {
        Some(match cap {
            GL_VERTEX_ARRAY => Array::Vertex,
            GL_NORMAL_ARRAY => Array::Normal,
            GL_COLOR_ARRAY => Array::Color,
            GL_SECONDARY_COLOR_ARRAY => Array::SecondaryColor,
            GL_FOG_COORD_ARRAY => Array::FogCoord,
            GL_INDEX_ARRAY => Array::Index,
            GL_EDGE_FLAG_ARRAY => Array::EdgeFlag,
            GL_TEXTURE_COORD_ARRAY => Array::TexCoord(client_active),
            _ => return None,
        })
    }

    /// A deleted buffer object: arrays bound to it revert to zero (2.9.1).
    /// Their pointers stay (offsets, below FIRST_VALID_ADDRESS when small,
    /// are then skipped by draws); reset them to NULL besides, so that a
    /// large offset is not read as a client address either (glGetPointerv
    /// then returns NULL).
    pub fn unbind_buffer(&mut self, name: u32) {
        for a in [
            &mut self.vertex,
            &mut self.normal,
            &mut self.color,
            &mut self.secondary_color,
            &mut self.fog_coord,
            &mut self.index,
            &mut self.edge_flag,
        ]
        .into_iter()
        .chain(self.tex_coord.iter_mut())
        {
            if a.buffer == name {
                a.buffer = 0;
                a.pointer = 0;
            }
        }
    }
}

/// glPushClientAttrib's GL_CLIENT_VERTEX_ARRAY_BIT.
pub const GL_CLIENT_VERTEX_ARRAY_BIT: u32 = 0x2;

/// The GL_CLIENT_VERTEX_ARRAY_BIT group (table 6.6 to 6.9): the arrays, the
/// client active texture unit and the two buffer bindings.
#[derive(Clone, Debug)]
pub struct ClientArrays {
    arrays: ArrayState,
    client_active: usize,
    array_buffer: u32,
    element_array_buffer: u32,
}

/// Bytes of one component of `ty`, for the types arrays accept.
fn type_size(ty: u32) -> usize {
    match ty {
        GL_BYTE | GL_UNSIGNED_BYTE => 1,
        GL_SHORT | GL_UNSIGNED_SHORT => 2,
        GL_INT | GL_UNSIGNED_INT | GL_FLOAT => 4,
        GL_DOUBLE => 8,
        _ => 0,
    }
}

/// The sizes and types each pointer call accepts (section 2.8, table 2.4).
fn accepts(a: Array, size: i32, ty: u32) -> Result<(), u32> {
    let sizes: &[i32] = match a {
        Array::Vertex => &[2, 3, 4],
        Array::Color => &[3, 4],
        Array::TexCoord(_) => &[1, 2, 3, 4],
        // GL 1.4/1.5 secondary colours have three components.
        Array::SecondaryColor => &[3],
        Array::Normal => &[3],
        Array::FogCoord | Array::Index | Array::EdgeFlag => &[1],
    };
    if !sizes.contains(&size) {
        return Err(GL_INVALID_VALUE);
    }
    let types: &[u32] = match a {
        Array::Vertex | Array::TexCoord(_) => &[GL_SHORT, GL_INT, GL_FLOAT, GL_DOUBLE],
        Array::Normal => &[GL_BYTE, GL_SHORT, GL_INT, GL_FLOAT, GL_DOUBLE],
        Array::Color | Array::SecondaryColor => {
            &[GL_BYTE, GL_UNSIGNED_BYTE, GL_SHORT, GL_UNSIGNED_SHORT, GL_INT, GL_UNSIGNED_INT, GL_FLOAT, GL_DOUBLE]
        }
        Array::Index => &[GL_UNSIGNED_BYTE, GL_SHORT, GL_INT, GL_FLOAT, GL_DOUBLE],
        Array::FogCoord => &[GL_FLOAT, GL_DOUBLE],
        Array::EdgeFlag => &[GL_UNSIGNED_BYTE],
    };
    if !types.contains(&ty) {
        return Err(GL_INVALID_ENUM);
    }
    Ok(())
}

/// A component type of an array, converted to float plainly or with the
/// normalization of table 2.9 (colours, normals).
trait Elem: Copy {
    fn plain(self) -> f32;
    fn normalized(self) -> f32;
}

macro_rules! elem {
    ($t:ty, $norm:expr) => {
        impl Elem for $t {
            #[inline(always)]
            fn plain(self) -> f32 {
                self as f32
            }
            #[inline(always)]
            fn normalized(self) -> f32 {
                let f: fn($t) -> f32 = $norm;
                f(self)
            }
        }
    };
}
elem!(i8, |c| (2.0 * c as f32 + 1.0) / 255.0);
elem!(u8, |c| c as f32 / 255.0);
elem!(i16, |c| (2.0 * c as f32 + 1.0) / 65535.0);
elem!(u16, |c| c as f32 / 65535.0);
elem!(i32, |c| ((2.0 * c as f64 + 1.0) / 4294967295.0) as f32);
elem!(u32, |c| (c as f64 / 4294967295.0) as f32);
elem!(f32, |c| c);
elem!(f64, |c| c as f32);

/// Reads an element's components at `p`, the rest from (0, 0, 0, 1).
type Reader = unsafe fn(*const u8) -> [f32; 4];

/// A reader for `N` components of type `T`, normalized or not: chosen once
/// per draw, so the per-vertex loop has no type, size or normalization
/// branches.
#[inline(always)]
unsafe fn read<T: Elem, const N: usize, const NORM: bool>(p: *const u8) -> [f32; 4] {
    let mut out = [0.0, 0.0, 0.0, 1.0];
    let p = p as *const T;
    for (i, o) in out.iter_mut().enumerate().take(N) {
        let c = std::ptr::read_unaligned(p.add(i));
        *o = if NORM { c.normalized() } else { c.plain() };
    }
    out
}

fn reader(ty: u32, size: usize, normalized: bool) -> Reader {
    macro_rules! by_size {
        ($t:ty, $norm:literal) => {
            match size {
                1 => read::<$t, 1, $norm>,
                2 => read::<$t, 2, $norm>,
                3 => read::<$t, 3, $norm>,
                _ => read::<$t, 4, $norm>,
            }
        };
    }
    macro_rules! pick {
        ($t:ty) => {
            if normalized {
                by_size!($t, true)
            } else {
                by_size!($t, false)
            }
        };
    }
    match ty {
        GL_BYTE => pick!(i8),
        GL_UNSIGNED_BYTE => pick!(u8),
        GL_SHORT => pick!(i16),
        GL_UNSIGNED_SHORT => pick!(u16),
        GL_INT => pick!(i32),
        GL_UNSIGNED_INT => pick!(u32),
        GL_DOUBLE => pick!(f64),
        _ => pick!(f32),
    }
}

/// Where one enabled array's elements are read from during a draw.
#[derive(Clone, Copy)]
struct Source {
    base: *const u8,
    stride: usize,
    /// Bytes of one element.
    elem: usize,
    /// Bytes readable from `base` (a buffer object's store), or None for
    /// client memory.
    limit: Option<usize>,
    read: Reader,
    /// The type and size `read` was chosen for (`draw_specialized`).
    kind: (u32, usize),
}

impl Source {
    #[inline(always)]
    fn fetch(&self, i: usize) -> [f32; 4] {
        self.fetch_with(i, self.read)
    }

    /// `fetch` through a reader known at compile time (inlined, no
    /// indirect call): `draw_specialized`'s loops.
    #[inline(always)]
    fn fetch_as<T: Elem, const N: usize, const NORM: bool>(&self, i: usize) -> [f32; 4] {
        self.fetch_with(i, read::<T, N, NORM>)
    }

    #[inline(always)]
    fn fetch_with(&self, i: usize, read: Reader) -> [f32; 4] {
        let off = i.wrapping_mul(self.stride);
        if let Some(limit) = self.limit {
            let fits = i.checked_mul(self.stride).and_then(|o| o.checked_add(self.elem)).is_some_and(|end| end <= limit);
            if !fits {
                return [0.0, 0.0, 0.0, 1.0];
            }
        }
        // SAFETY: client memory: the program promises the element is there
        // (section 2.8); buffer memory: checked above.
        unsafe { read(self.base.wrapping_add(off)) }
    }
}

/// The enabled arrays of a draw.
struct Fetch {
    vertex: Option<Source>,
    normal: Option<Source>,
    color: Option<Source>,
    secondary_color: Option<Source>,
    fog_coord: Option<Source>,
    index: Option<Source>,
    edge_flag: Option<Source>,
    tex_coord: [Option<Source>; MAX_TEXTURE_UNITS],
    /// Any of edge flag, texture coordinate, secondary colour, fog
    /// coordinate or index arrays enabled (else they are not looked at).
    others: bool,
}

/// The attributes of one array element, as a list records them.
#[derive(Clone, Copy, Default)]
struct Element {
    edge_flag: Option<bool>,
    tex_coord: [Option<[f32; 4]>; MAX_TEXTURE_UNITS],
    color: Option<[f32; 4]>,
    secondary_color: Option<[f32; 4]>,
    fog_coord: Option<f32>,
    index: Option<f32>,
    normal: Option<[f32; 3]>,
    vertex: Option<[f32; 4]>,
}

impl Fetch {
    #[inline(always)]
    fn element(&self, i: usize) -> Element {
        let get = |s: &Option<Source>| s.as_ref().map(|s| s.fetch(i));
        let mut e = Element {
            color: get(&self.color),
            normal: get(&self.normal).map(|n| [n[0], n[1], n[2]]),
            vertex: get(&self.vertex),
            ..Element::default()
        };
        if self.others {
            for (t, s) in e.tex_coord.iter_mut().zip(&self.tex_coord) {
                *t = get(s);
            }
            e.edge_flag = get(&self.edge_flag).map(|e| e[0] != 0.0);
            // Three-component secondary colours keep alpha 1 (current-value rule).
            e.secondary_color = get(&self.secondary_color);
            e.fog_coord = get(&self.fog_coord).map(|f| f[0]);
            e.index = get(&self.index).map(|x| x[0]);
        }
        e
    }
}

/// Where glDrawElements' indices come from.
#[derive(Clone, Copy)]
struct Indices {
    base: *const u8,
    ty: u32,
    /// Indices readable (the count, cut to a buffer object's store).
    count: usize,
}

impl Indices {
    #[inline(always)]
    fn get(&self, k: usize) -> usize {
        // SAFETY: k < count; client memory holds `count` indices (the
        // program's promise), buffer memory was checked when `count` was cut.
        unsafe {
            match self.ty {
                GL_UNSIGNED_BYTE => *self.base.add(k) as usize,
                GL_UNSIGNED_SHORT => std::ptr::read_unaligned((self.base as *const u16).add(k)) as usize,
                _ => std::ptr::read_unaligned((self.base as *const u32).add(k)) as usize,
            }
        }
    }
}

fn index_size(ty: u32) -> Option<usize> {
    match ty {
        GL_UNSIGNED_BYTE => Some(1),
        GL_UNSIGNED_SHORT => Some(2),
        GL_UNSIGNED_INT => Some(4),
        _ => None,
    }
}

/// Lowest client address read: nothing lives in the first page, and
/// smaller "pointers" are NULL or buffer offsets used with no buffer bound.
const FIRST_VALID_ADDRESS: usize = 4096;

/// glInterleavedArrays' table 2.5: which arrays a format enables, their
/// sizes, and offsets in units of f (a float) and c (4 unsigned bytes,
/// rounded to a float: also 4 bytes).
struct Interleaved {
    tex: Option<(i32, usize)>,
    color: Option<(i32, u32, usize)>,
    normal: Option<usize>,
    vertex: (i32, usize),
    stride: usize,
}

fn interleaved(format: u32) -> Option<Interleaved> {
    const F: usize = 4;
    const C: usize = 4;
    let ub = GL_UNSIGNED_BYTE;
    let fl = GL_FLOAT;
    let i = |tex, color, normal, vertex, stride| Interleaved { tex, color, normal, vertex, stride };
    Some(match format {
        0x2A20 => i(None, None, None, (2, 0), 2 * F),                                     // V2F
        0x2A21 => i(None, None, None, (3, 0), 3 * F),                                     // V3F
        0x2A22 => i(None, Some((4, ub, 0)), None, (2, C), C + 2 * F),                      // C4UB_V2F
        0x2A23 => i(None, Some((4, ub, 0)), None, (3, C), C + 3 * F),                      // C4UB_V3F
        0x2A24 => i(None, Some((3, fl, 0)), None, (3, 3 * F), 6 * F),                      // C3F_V3F
        0x2A25 => i(None, None, Some(0), (3, 3 * F), 6 * F),                               // N3F_V3F
        0x2A26 => i(None, Some((4, fl, 0)), Some(4 * F), (3, 7 * F), 10 * F),              // C4F_N3F_V3F
        0x2A27 => i(Some((2, 0)), None, None, (3, 2 * F), 5 * F),                          // T2F_V3F
        0x2A28 => i(Some((4, 0)), None, None, (4, 4 * F), 8 * F),                          // T4F_V4F
        0x2A29 => i(Some((2, 0)), Some((4, ub, 2 * F)), None, (3, C + 2 * F), C + 5 * F), // T2F_C4UB_V3F
        0x2A2A => i(Some((2, 0)), Some((3, fl, 2 * F)), None, (3, 5 * F), 8 * F),          // T2F_C3F_V3F
        0x2A2B => i(Some((2, 0)), None, Some(2 * F), (3, 5 * F), 8 * F),                   // T2F_N3F_V3F
        0x2A2C => i(Some((2, 0)), Some((4, fl, 2 * F)), Some(6 * F), (3, 9 * F), 12 * F),  // T2F_C4F_N3F_V3F
        0x2A2D => i(Some((4, 0)), Some((4, fl, 4 * F)), Some(8 * F), (4, 11 * F), 15 * F), // T4F_C4F_N3F_V4F
        _ => return None,
    })
}

impl Context {
    /// The vertex-array group, for glPushClientAttrib.
    pub fn client_arrays(&self) -> ClientArrays {
        ClientArrays {
            arrays: self.arrays.clone(),
            client_active: self.texture.client_active,
            array_buffer: self.buffers.array,
            element_array_buffer: self.buffers.element_array,
        }
    }

    /// glPopClientAttrib of the vertex-array group. A binding to a buffer
    /// deleted since the push comes back as zero (and its array as NULL),
    /// as deletion would have left it.
    pub fn restore_client_arrays(&mut self, mut saved: ClientArrays) {
        let gone = |b: u32| b != 0 && !self.buffers.is_buffer(b);
        let dead: Vec<u32> = [saved.array_buffer, saved.element_array_buffer]
            .into_iter()
            .chain(saved.arrays.all().map(|p| p.buffer))
            .filter(|&b| gone(b))
            .collect();
        for b in dead {
            saved.arrays.unbind_buffer(b);
            if saved.array_buffer == b {
                saved.array_buffer = 0;
            }
            if saved.element_array_buffer == b {
                saved.element_array_buffer = 0;
            }
        }
        self.arrays = saved.arrays;
        self.texture.client_active = saved.client_active;
        self.buffers.array = saved.array_buffer;
        self.buffers.element_array = saved.element_array_buffer;
    }

    /// GL_EXT_vertex_array's element count, which GL 1.1 dropped: only a
    /// negative one is an error (GL_INVALID_VALUE, and the pointer call does
    /// nothing). Returns whether the call goes on.
    pub fn ext_array_count(&mut self, count: i32) -> bool {
        if count < 0 {
            self.set_error(GL_INVALID_VALUE);
        }
        count >= 0
    }

    /// The gl*Pointer calls. The pointer is an offset when a buffer is
    /// bound to ARRAY_BUFFER.
    pub fn array_pointer(&mut self, a: Array, size: i32, ty: u32, stride: i32, pointer: usize) {
        if let Err(e) = accepts(a, size, ty) {
            return self.set_error(e);
        }
        if stride < 0 {
            return self.set_error(GL_INVALID_VALUE);
        }
        let buffer = self.buffers.array;
        let p = self.arrays.get_mut(a);
        p.size = size;
        p.type_ = ty;
        p.stride = stride;
        p.pointer = pointer;
        p.buffer = buffer;
    }

    /// glTexCoordPointer: the client active unit's array.
    pub fn tex_coord_pointer(&mut self, size: i32, ty: u32, stride: i32, pointer: usize) {
        let u = self.texture.client_active;
        self.array_pointer(Array::TexCoord(u), size, ty, stride, pointer)
    }

    /// glEnableClientState / glDisableClientState.
    pub fn client_state(&mut self, cap: u32, on: bool) {
        match ArrayState::from_cap(cap, self.texture.client_active) {
            Some(a) => self.arrays.get_mut(a).enabled = on,
            None => self.set_error(GL_INVALID_ENUM),
        }
    }

    /// glIsEnabled for the array capabilities.
    pub fn client_state_enabled(&self, cap: u32) -> Option<bool> {
        ArrayState::from_cap(cap, self.texture.client_active).map(|a| self.arrays.get(a).enabled)
    }

    /// glInterleavedArrays (section 2.8, table 2.5).
    pub fn interleaved_arrays(&mut self, format: u32, stride: i32, pointer: usize) {
        let Some(f) = interleaved(format) else { return self.set_error(GL_INVALID_ENUM) };
        if stride < 0 {
            return self.set_error(GL_INVALID_VALUE);
        }
        let s = if stride == 0 { f.stride as i32 } else { stride };
        let unit = self.texture.client_active;
        for a in [Array::EdgeFlag, Array::Index, Array::SecondaryColor, Array::FogCoord] {
            self.arrays.get_mut(a).enabled = false;
        }
        if let Some((size, off)) = f.tex {
            self.array_pointer(Array::TexCoord(unit), size, GL_FLOAT, s, pointer.wrapping_add(off));
        }
        self.arrays.tex_coord[unit].enabled = f.tex.is_some();
        if let Some((size, ty, off)) = f.color {
            self.array_pointer(Array::Color, size, ty, s, pointer.wrapping_add(off));
        }
        self.arrays.color.enabled = f.color.is_some();
        if let Some(off) = f.normal {
            self.array_pointer(Array::Normal, 3, GL_FLOAT, s, pointer.wrapping_add(off));
        }
        self.arrays.normal.enabled = f.normal.is_some();
        let (size, off) = f.vertex;
        self.array_pointer(Array::Vertex, size, GL_FLOAT, s, pointer.wrapping_add(off));
        self.arrays.vertex.enabled = true;
    }

    /// glGetPointerv.
    pub fn get_pointer(&mut self, pname: u32) -> Option<usize> {
        let a = match pname {
            0x808E => Array::Vertex,
            0x808F => Array::Normal,
            0x8090 => Array::Color,
            0x8091 => Array::Index,
            0x8092 => Array::TexCoord(self.texture.client_active),
            0x8093 => Array::EdgeFlag,
            0x8456 => Array::FogCoord,
            0x845D => Array::SecondaryColor,
            GL_SELECTION_BUFFER_POINTER => return Some(self.select.buffer_pointers().0),
            GL_FEEDBACK_BUFFER_POINTER => return Some(self.select.buffer_pointers().1),
            _ => {
                self.set_error(GL_INVALID_ENUM);
                return None;
            }
        };
        Some(self.arrays.get(a).pointer)
    }

    /// The glGet values of vertex arrays, buffer bindings and the current
    /// values this module feeds (edge flag, index, fog coordinate,
    /// secondary colour); None for other names.
    pub fn get_array_value(&self, pname: u32) -> Option<Value> {
        let ar = &self.arrays;
        let tex = &ar.tex_coord[self.texture.client_active];
        let int = |v: i64| Some(Value::Ints(vec![v]));
        match pname {
            0x807A => int(ar.vertex.size as i64),
            0x807B => int(ar.vertex.type_ as i64),
            0x807C => int(ar.vertex.stride as i64),
            0x807E => int(ar.normal.type_ as i64),
            0x807F => int(ar.normal.stride as i64),
            0x8081 => int(ar.color.size as i64),
            0x8082 => int(ar.color.type_ as i64),
            0x8083 => int(ar.color.stride as i64),
            0x8085 => int(ar.index.type_ as i64),
            0x8086 => int(ar.index.stride as i64),
            0x8088 => int(tex.size as i64),
            0x8089 => int(tex.type_ as i64),
            0x808A => int(tex.stride as i64),
            0x808C => int(ar.edge_flag.stride as i64),
            0x8454 => int(ar.fog_coord.type_ as i64),
            0x8455 => int(ar.fog_coord.stride as i64),
            0x845A => int(ar.secondary_color.size as i64),
            0x845B => int(ar.secondary_color.type_ as i64),
            0x845C => int(ar.secondary_color.stride as i64),
            super::buffers::GL_ARRAY_BUFFER_BINDING => int(self.buffers.array as i64),
            super::buffers::GL_ELEMENT_ARRAY_BUFFER_BINDING => int(self.buffers.element_array as i64),
            0x8896 => int(ar.vertex.buffer as i64),
            0x8897 => int(ar.normal.buffer as i64),
            0x8898 => int(ar.color.buffer as i64),
            0x8899 => int(ar.index.buffer as i64),
            0x889A => int(tex.buffer as i64),
            0x889B => int(ar.edge_flag.buffer as i64),
            0x889C => int(ar.secondary_color.buffer as i64),
            0x889D => int(ar.fog_coord.buffer as i64),
            GL_MAX_ELEMENTS_VERTICES | GL_MAX_ELEMENTS_INDICES => int(MAX_ELEMENTS),
            GL_CURRENT_INDEX => Some(Value::Floats(vec![self.current.index as f64])),
            GL_EDGE_FLAG => Some(Value::Bools(vec![self.current.edge_flag])),
            GL_CURRENT_FOG_COORD => Some(Value::Floats(vec![self.current.fog_coord as f64])),
            GL_CURRENT_SECONDARY_COLOR => Some(Value::Normalized(self.current.secondary_color.iter().map(|&c| c as f64).collect())),
            _ => None,
        }
    }

    /// The sources of the enabled arrays, or INVALID_OPERATION when one
    /// is in a mapped buffer (section 2.9.3).
    fn fetch(&mut self) -> Option<Fetch> {
        let ar = &self.arrays;
        if ar.all().any(|p| p.enabled && self.buffers.is_mapped(p.buffer)) {
            self.set_error(GL_INVALID_OPERATION);
            return None;
        }
        let source = |p: &ArrayPointer, normalized: bool| -> Option<Source> {
            if !p.enabled {
                return None;
            }
            let elem = p.size as usize * type_size(p.type_);
            let stride = if p.stride == 0 { elem } else { p.stride as usize };
            let (base, limit) = if p.buffer == 0 {
                if p.pointer < FIRST_VALID_ADDRESS {
                    return None;
                }
                (p.pointer as *const u8, None)
            } else {
                let data = self.buffers.data(p.buffer);
                (data.as_ptr().wrapping_add(p.pointer), Some(data.len().saturating_sub(p.pointer)))
            };
            Some(Source { base, stride, elem, limit, read: reader(p.type_, p.size as usize, normalized), kind: (p.type_, p.size as usize) })
        };
        let mut tex_coord = [None; MAX_TEXTURE_UNITS];
        for (t, p) in tex_coord.iter_mut().zip(&ar.tex_coord) {
            *t = source(p, false);
        }
        let others = ar.edge_flag.enabled
            || ar.secondary_color.enabled
            || ar.fog_coord.enabled
            || ar.index.enabled
            || ar.tex_coord.iter().any(|t| t.enabled);
        Some(Fetch {
            others,
            vertex: source(&ar.vertex, false),
            normal: source(&ar.normal, true),
            color: source(&ar.color, true),
            secondary_color: source(&ar.secondary_color, true),
            fog_coord: source(&ar.fog_coord, false),
            index: source(&ar.index, false),
            edge_flag: source(&ar.edge_flag, false),
            tex_coord,
        })
    }

    /// Sets the current values of array element `i` and sends its vertex
    /// (glArrayElement's effect, executed), reading straight from the
    /// sources into the current values.
    #[inline]
    fn apply_element(&mut self, f: &Fetch, i: usize) {
        if f.others {
            if let Some(s) = &f.edge_flag {
                self.current.edge_flag = s.fetch(i)[0] != 0.0;
            }
            for (u, s) in f.tex_coord.iter().enumerate() {
                if let Some(s) = s {
                    self.current.tex_coords[u] = s.fetch(i);
                }
            }
            if let Some(s) = &f.secondary_color {
                self.current.secondary_color = s.fetch(i);
            }
            if let Some(s) = &f.fog_coord {
                self.current.fog_coord = s.fetch(i)[0];
            }
            if let Some(s) = &f.index {
                self.current.index = s.fetch(i)[0];
            }
        }
        if let Some(s) = &f.color {
            self.current.color = s.fetch(i);
            if self.lighting.color_material {
                self.apply_color_material();
            }
        }
        if let Some(s) = &f.normal {
            let n = s.fetch(i);
            self.current.normal = [n[0], n[1], n[2]];
        }
        if let Some(s) = &f.vertex {
            self.vertex(s.fetch(i));
        }
    }

    /// Records one element as the commands it generates (compiling).
    fn record_element(&mut self, e: &Element) {
        let l = &mut self.lists;
        if let Some(f) = e.edge_flag {
            l.record(Command::EdgeFlag(f));
        }
        for (u, t) in e.tex_coord.iter().enumerate() {
            if let Some(t) = t {
                l.record(Command::TexCoord(GL_TEXTURE0 + u as u32, *t));
            }
        }
        if let Some(c) = e.color {
            l.record(Command::Color(c));
        }
        if let Some(c) = e.secondary_color {
            l.record(Command::SecondaryColor(c));
        }
        if let Some(f) = e.fog_coord {
            l.record(Command::FogCoord(f));
        }
        if let Some(i) = e.index {
            l.record(Command::Index(i));
        }
        if let Some(n) = e.normal {
            l.record(Command::Normal(n));
        }
        if let Some(v) = e.vertex {
            l.record(Command::Vertex(v));
        }
    }

    /// glArrayElement (allowed between Begin and End).
    pub fn array_element(&mut self, i: i32) {
        if i < 0 {
            return self.set_error(GL_INVALID_VALUE);
        }
        let Some(f) = self.fetch() else { return };
        let mode = self.lists.compile_mode();
        if mode.is_some() {
            self.record_element(&f.element(i as usize));
        }
        if mode != Some(GL_COMPILE) {
            self.apply_element(&f, i as usize);
        }
    }

    /// The checks every draw call shares: outside Begin/End (when
    /// executing), a valid mode.
    fn draw_checks(&mut self, mode: u32) -> bool {
        if self.in_begin_end() {
            self.set_error(GL_INVALID_OPERATION);
            // GL_COMPILE_AND_EXECUTE still compiles the draw (5.4); its
            // Begin/End pair makes calling the list raise the same error.
            self.empty_draw(mode);
            return false;
        }
        if mode > GL_POLYGON {
            self.set_error(GL_INVALID_ENUM);
            return false;
        }
        true
    }

    /// A draw with no vertex array enabled is still Begin(mode) ... End()
    /// (2.8): nothing is drawn, but a display list being compiled records
    /// the pair, so calling the list between Begin and End raises
    /// INVALID_OPERATION as the draw would have.
    fn empty_draw(&mut self, mode: u32) {
        if self.lists.compile_mode().is_some() {
            self.lists.begin_draw(mode);
            self.lists.end_draw();
        }
    }

    /// One primitive of `n` elements, element k being array index `index(k)`.
    fn draw(&mut self, mode: u32, f: &Fetch, n: usize, index: impl Fn(usize) -> usize) {
        let list_mode = self.lists.compile_mode();
        if list_mode.is_some() {
            self.lists.begin_draw(mode);
            for k in 0..n {
                let e = f.element(index(k));
                self.record_element(&e);
            }
            self.lists.end_draw();
            if list_mode == Some(GL_COMPILE) {
                return;
            }
        }
        self.begin(mode);
        if !self.in_begin_end() {
            return;
        }
        // The current values a draw's arrays set are indeterminate after
        // it (2.8); softgl leaves them as they were before the draw, as
        // Mesa does and programs (piglit's draw-vertices) expect.
        let saved = self.current;
        if !self.draw_specialized(f, n, &index) {
            for k in 0..n {
                self.apply_element(f, index(k));
            }
        }
        self.end();
        self.current = saved;
        if f.color.is_some() && self.lighting.color_material {
            self.apply_color_material();
        }
    }

    /// The element loop of a draw whose only arrays are float positions
    /// (2 to 4 components) and optionally colours (3 or 4 unsigned bytes
    /// or floats), with both readers chosen at compile time: no indirect
    /// call per attribute, and vertices go straight on to `vertex` (and its
    /// batched path). The same reads, in the same order, as
    /// `apply_element`. False when the draw needs the general loop.
    fn draw_specialized(&mut self, f: &Fetch, n: usize, index: &impl Fn(usize) -> usize) -> bool {
        if !self.vertex_batching || f.others || f.normal.is_some() {
            return false;
        }
        let Some(v) = f.vertex else { return false };
        let color = f.color.map(|s| s.kind);
        macro_rules! with_color {
            ($vn:literal) => {
                match color {
                    // No colour array: the colour type is never used.
                    None => self.draw_elements_as::<$vn, f32, 4>(f, &v, n, index),
                    Some((GL_UNSIGNED_BYTE, 3)) => self.draw_elements_as::<$vn, u8, 3>(f, &v, n, index),
                    Some((GL_UNSIGNED_BYTE, 4)) => self.draw_elements_as::<$vn, u8, 4>(f, &v, n, index),
                    Some((GL_FLOAT, 3)) => self.draw_elements_as::<$vn, f32, 3>(f, &v, n, index),
                    Some((GL_FLOAT, 4)) => self.draw_elements_as::<$vn, f32, 4>(f, &v, n, index),
                    _ => return false,
                }
            };
        }
        match v.kind {
            (GL_FLOAT, 2) => with_color!(2),
            (GL_FLOAT, 3) => with_color!(3),
            (GL_FLOAT, 4) => with_color!(4),
            _ => return false,
        }
        true
    }

    /// `apply_element` for positions of `VN` floats and colours of `CN`
    /// normalized `C`s (see `draw_specialized`).
    fn draw_elements_as<const VN: usize, C: Elem, const CN: usize>(&mut self, f: &Fetch, v: &Source, n: usize, index: &impl Fn(usize) -> usize) {
        // The batched path's plain case is decided once for the draw
        // (nothing in the loop changes the state it depends on): each
        // vertex then enters it directly, as `vertex` would send it.
        let plain = self.plain_batch();
        // The current colour kept in a register as well: the plain case
        // takes it from there (`vertex_fast_colored`).
        let mut color = glam::Vec4::from_array(self.current.color);
        for k in 0..n {
            let i = index(k);
            if let Some(s) = &f.color {
                color = glam::Vec4::from_array(s.fetch_as::<C, CN, true>(i));
                super::begin_end::store4(&mut self.current.color, color);
                if self.lighting.color_material {
                    self.apply_color_material();
                }
            }
            let p = v.fetch_as::<f32, VN, false>(i);
            if plain {
                self.vertex_fast_colored::<true>(p, color);
            } else {
                self.vertex(p);
            }
        }
    }

    pub fn draw_arrays(&mut self, mode: u32, first: i32, count: i32) {
        if !self.draw_checks(mode) {
            return;
        }
        if first < 0 || count < 0 {
            return self.set_error(GL_INVALID_VALUE);
        }
        let Some(f) = self.fetch() else { return self.empty_draw(mode) };
        let first = first as usize;
        self.draw(mode, &f, count as usize, |k| first + k);
    }

    pub fn multi_draw_arrays(&mut self, mode: u32, first: &[i32], count: &[i32]) {
        if !self.draw_checks(mode) {
            return;
        }
        if first.iter().chain(count).any(|&v| v < 0) {
            return self.set_error(GL_INVALID_VALUE);
        }
        let Some(f) = self.fetch() else { return self.empty_draw(mode) };
        for (&first, &count) in first.iter().zip(count) {
            let first = first as usize;
            self.draw(mode, &f, count as usize, |k| first + k);
        }
    }

    /// The indices of a glDrawElements: `indices` is an address, or an
    /// offset into the ELEMENT_ARRAY_BUFFER.
    fn indices(&mut self, count: i32, ty: u32, indices: usize) -> Option<Indices> {
        if count < 0 {
            self.set_error(GL_INVALID_VALUE);
            return None;
        }
        let Some(size) = index_size(ty) else {
            self.set_error(GL_INVALID_ENUM);
            return None;
        };
        let eb = self.buffers.element_array;
        if eb == 0 {
            let count = if indices < FIRST_VALID_ADDRESS { 0 } else { count as usize };
            return Some(Indices { base: indices as *const u8, ty, count });
        }
        if self.buffers.is_mapped(eb) {
            self.set_error(GL_INVALID_OPERATION);
            return None;
        }
        let data = self.buffers.data(eb);
        let available = data.len().saturating_sub(indices) / size;
        Some(Indices { base: data.as_ptr().wrapping_add(indices), ty, count: (count as usize).min(available) })
    }

    pub fn draw_elements(&mut self, mode: u32, count: i32, ty: u32, indices: usize) {
        if !self.draw_checks(mode) {
            return;
        }
        let Some(ix) = self.indices(count, ty, indices) else { return };
        let Some(f) = self.fetch() else { return self.empty_draw(mode) };
        self.draw(mode, &f, ix.count, |k| ix.get(k));
    }

    /// glDrawRangeElements: the range is only a promise about the indices.
    pub fn draw_range_elements(&mut self, mode: u32, start: u32, end: u32, count: i32, ty: u32, indices: usize) {
        if end < start {
            return self.set_error(GL_INVALID_VALUE);
        }
        self.draw_elements(mode, count, ty, indices)
    }

    pub fn multi_draw_elements(&mut self, mode: u32, count: &[i32], ty: u32, indices: &[usize]) {
        if !self.draw_checks(mode) {
            return;
        }
        if count.iter().any(|&c| c < 0) {
            return self.set_error(GL_INVALID_VALUE);
        }
        if index_size(ty).is_none() {
            return self.set_error(GL_INVALID_ENUM);
        }
        for (&c, &p) in count.iter().zip(indices) {
            self.draw_elements(mode, c, ty, p);
        }
    }
}
