//! Buffer objects (GL 1.5 section 2.9): names, the ARRAY_BUFFER,
//! ELEMENT_ARRAY_BUFFER and (ARB_pixel_buffer_object) PIXEL_PACK_BUFFER /
//! PIXEL_UNPACK_BUFFER bindings, data store creation and update, mapping
//! (glMapBuffer, and ARB_map_buffer_range's glMapBufferRange and
//! glFlushMappedBufferRange), and the buffer queries (section 6.1.13).
//! How pixel commands read and write the pixel buffers is `pixel_buffer`.
//!
//! A buffer's data store is a `Vec<u8>` owned by the context. While a
//! buffer is mapped its Vec is never reallocated (BufferData and deletion
//! unmap first), so the pointer glMapBuffer returned stays valid until
//! glUnmapBuffer. Vertex arrays and glDrawElements read buffers through
//! [`Buffers::data`]; reads are bounds-checked against the store, so a bad
//! offset draws defaults instead of reading outside it.
//!
//! Names: glGenBuffers reserves names; the object itself is created by the
//! first glBindBuffer of a name (so glIsBuffer is false for a name that
//! was generated but never bound), and any unused name may be bound.
//! Deleting a bound buffer resets the bindings to it to zero, including
//! the vertex arrays' (section 2.9.1); [`Context::delete_buffers`] does that.

use super::context::Context;
use super::enums::*;
use super::names::Reserved;
use std::collections::HashMap;

pub const GL_BUFFER_SIZE: u32 = 0x8764;
pub const GL_BUFFER_USAGE: u32 = 0x8765;
pub const GL_ARRAY_BUFFER: u32 = 0x8892;
pub const GL_ELEMENT_ARRAY_BUFFER: u32 = 0x8893;
pub const GL_ARRAY_BUFFER_BINDING: u32 = 0x8894;
pub const GL_ELEMENT_ARRAY_BUFFER_BINDING: u32 = 0x8895;
pub const GL_READ_ONLY: u32 = 0x88B8;
pub const GL_WRITE_ONLY: u32 = 0x88B9;
pub const GL_READ_WRITE: u32 = 0x88BA;
pub const GL_BUFFER_ACCESS: u32 = 0x88BB;
pub const GL_BUFFER_MAPPED: u32 = 0x88BC;
pub const GL_BUFFER_MAP_POINTER: u32 = 0x88BD;
pub const GL_STREAM_DRAW: u32 = 0x88E0;
pub const GL_PIXEL_PACK_BUFFER: u32 = 0x88EB;
pub const GL_PIXEL_UNPACK_BUFFER: u32 = 0x88EC;
pub const GL_PIXEL_PACK_BUFFER_BINDING: u32 = 0x88ED;
pub const GL_PIXEL_UNPACK_BUFFER_BINDING: u32 = 0x88EF;
// ARB_map_buffer_range's access bits and (GL 3.0) map queries.
pub const GL_MAP_READ_BIT: u32 = 0x1;
pub const GL_MAP_WRITE_BIT: u32 = 0x2;
pub const GL_MAP_INVALIDATE_RANGE_BIT: u32 = 0x4;
pub const GL_MAP_INVALIDATE_BUFFER_BIT: u32 = 0x8;
pub const GL_MAP_FLUSH_EXPLICIT_BIT: u32 = 0x10;
pub const GL_MAP_UNSYNCHRONIZED_BIT: u32 = 0x20;
pub const GL_BUFFER_ACCESS_FLAGS: u32 = 0x911F;
pub const GL_BUFFER_MAP_LENGTH: u32 = 0x9120;
pub const GL_BUFFER_MAP_OFFSET: u32 = 0x9121;
pub const GL_STATIC_DRAW: u32 = 0x88E4;
pub const GL_DYNAMIC_COPY: u32 = 0x88EA;

/// One buffer object (table 2.6 gives its state).
#[derive(Debug)]
pub struct Buffer {
    pub data: Vec<u8>,
    pub usage: u32,
    /// BUFFER_ACCESS: the access of the last (or current) mapping; READ_WRITE initially.
    pub access: u32,
    pub mapped: bool,
    /// BUFFER_ACCESS_FLAGS, BUFFER_MAP_OFFSET and BUFFER_MAP_LENGTH of the
    /// current mapping (zero when unmapped).
    pub access_flags: u32,
    pub map_offset: usize,
    pub map_length: usize,
}

impl Buffer {
    fn new() -> Buffer {
        Buffer { data: Vec::new(), usage: GL_STATIC_DRAW, access: GL_READ_WRITE, mapped: false, access_flags: 0, map_offset: 0, map_length: 0 }
    }

    fn unmap(&mut self) {
        self.mapped = false;
        self.access_flags = 0;
        self.map_offset = 0;
        self.map_length = 0;
    }
}


#[derive(Debug, Default)]
pub struct Buffers {
    names: Reserved,
    objects: HashMap<u32, Buffer>,
    /// ARRAY_BUFFER_BINDING: captured by the array pointer calls.
    pub array: u32,
    /// ELEMENT_ARRAY_BUFFER_BINDING: read by glDrawElements and friends.
    pub element_array: u32,
    /// PIXEL_PACK_BUFFER_BINDING: where pixel commands that return images
    /// write (`pixel_buffer`).
    pub pixel_pack: u32,
    /// PIXEL_UNPACK_BUFFER_BINDING: where pixel commands that take images read.
    pub pixel_unpack: u32,
}

impl Buffers {
    /// Exchanges the buffer objects and their names with a share group's
    /// (gl::share); the bindings stay per context.
    pub fn swap_objects(&mut self, other: &mut Buffers) {
        std::mem::swap(&mut self.names, &mut other.names);
        std::mem::swap(&mut self.objects, &mut other.objects);
    }

    pub fn get(&self, name: u32) -> Option<&Buffer> {
        self.objects.get(&name)
    }

    /// The data store of buffer `name` (empty for 0 or an unknown name).
    #[inline]
    pub fn data(&self, name: u32) -> &[u8] {
        self.objects.get(&name).map_or(&[], |b| &b.data)
    }

    pub fn is_mapped(&self, name: u32) -> bool {
        name != 0 && self.objects.get(&name).is_some_and(|b| b.mapped)
    }

    pub fn is_buffer(&self, name: u32) -> bool {
        name != 0 && self.objects.contains_key(&name)
    }

    /// The buffer object `name`, mutable (pixel packing writes its store).
    pub fn get_mut(&mut self, name: u32) -> Option<&mut Buffer> {
        self.objects.get_mut(&name)
    }
}

fn valid_usage(usage: u32) -> bool {
    (GL_STREAM_DRAW..=GL_DYNAMIC_COPY).contains(&usage) && usage & 3 != 3
}

impl Context {
    /// The binding point of `target`, or INVALID_ENUM.
    fn buffer_binding(&mut self, target: u32) -> Option<u32> {
        match target {
            GL_ARRAY_BUFFER => Some(self.buffers.array),
            GL_ELEMENT_ARRAY_BUFFER => Some(self.buffers.element_array),
            GL_PIXEL_PACK_BUFFER => Some(self.buffers.pixel_pack),
            GL_PIXEL_UNPACK_BUFFER => Some(self.buffers.pixel_unpack),
            _ => {
                self.set_error(GL_INVALID_ENUM);
                None
            }
        }
    }

    /// The buffer bound to `target`: INVALID_ENUM for a bad target,
    /// INVALID_OPERATION when zero is bound.
    fn bound_buffer(&mut self, target: u32) -> Option<&mut Buffer> {
        let name = self.buffer_binding(target)?;
        if name == 0 {
            self.set_error(GL_INVALID_OPERATION);
            return None;
        }
        self.buffers.objects.get_mut(&name)
    }

    pub fn gen_buffers(&mut self, n: i32) -> Option<Vec<u32>> {
        if n < 0 {
            self.set_error(GL_INVALID_VALUE);
            return None;
        }
        Some(self.buffers.names.generate(n as usize, |_| false))
    }

    pub fn bind_buffer(&mut self, target: u32, name: u32) {
        let slot = match target {
            GL_ARRAY_BUFFER => &mut self.buffers.array,
            GL_ELEMENT_ARRAY_BUFFER => &mut self.buffers.element_array,
            GL_PIXEL_PACK_BUFFER => &mut self.buffers.pixel_pack,
            GL_PIXEL_UNPACK_BUFFER => &mut self.buffers.pixel_unpack,
            _ => return self.set_error(GL_INVALID_ENUM),
        };
        *slot = name;
        if name != 0 {
            self.buffers.names.insert(name);
            self.buffers.objects.entry(name).or_insert_with(Buffer::new);
        }
    }

    pub fn delete_buffers(&mut self, names: &[u32]) {
        for &name in names {
            if name == 0 {
                continue;
            }
            // Deleting a mapped buffer unmaps it (section 2.9.3).
            self.buffers.objects.remove(&name);
            self.buffers.names.remove(name);
            if self.buffers.array == name {
                self.buffers.array = 0;
            }
            if self.buffers.element_array == name {
                self.buffers.element_array = 0;
            }
            if self.buffers.pixel_pack == name {
                self.buffers.pixel_pack = 0;
            }
            if self.buffers.pixel_unpack == name {
                self.buffers.pixel_unpack = 0;
            }
            self.arrays.unbind_buffer(name);
        }
    }

    /// glBufferData.
    ///
    /// # Safety
    /// `data` is NULL or points to `size` readable bytes.
    pub unsafe fn buffer_data(&mut self, target: u32, size: isize, data: *const u8, usage: u32) {
        if self.buffer_binding(target).is_none() {
            return;
        }
        if size < 0 {
            return self.set_error(GL_INVALID_VALUE);
        }
        if !valid_usage(usage) {
            return self.set_error(GL_INVALID_ENUM);
        }
        let Some(b) = self.bound_buffer(target) else { return };
        let mut store = Vec::new();
        if store.try_reserve_exact(size as usize).is_err() {
            return self.set_error(GL_OUT_OF_MEMORY);
        }
        if data.is_null() {
            store.resize(size as usize, 0);
        } else {
            // SAFETY: the caller passes `size` readable bytes (glBufferData).
            store.extend_from_slice(std::slice::from_raw_parts(data, size as usize));
        }
        b.data = store;
        b.usage = usage;
        b.unmap();
        b.access = GL_READ_WRITE;
    }

    /// The checked range [offset, offset + size) of the buffer bound to
    /// `target`, for glBufferSubData and glGetBufferSubData.
    fn buffer_range(&mut self, target: u32, offset: isize, size: isize) -> Option<(&mut Buffer, std::ops::Range<usize>)> {
        let name = self.buffer_binding(target)?;
        if offset < 0 || size < 0 {
            self.set_error(GL_INVALID_VALUE);
            return None;
        }
        let (o, s) = (offset as usize, size as usize);
        let len = match self.buffers.objects.get(&name) {
            Some(b) => {
                if b.mapped {
                    self.set_error(GL_INVALID_OPERATION);
                    return None;
                }
                b.data.len()
            }
            None => {
                self.set_error(GL_INVALID_OPERATION);
                return None;
            }
        };
        if o.checked_add(s).is_none_or(|end| end > len) {
            self.set_error(GL_INVALID_VALUE);
            return None;
        }
        let b = self.bound_buffer(target)?;
        Some((b, o..o + s))
    }

    /// glBufferSubData.
    ///
    /// # Safety
    /// `data` is NULL or points to `size` readable bytes.
    pub unsafe fn buffer_sub_data(&mut self, target: u32, offset: isize, size: isize, data: *const u8) {
        let Some((b, r)) = self.buffer_range(target, offset, size) else { return };
        if !data.is_null() {
            // SAFETY: the caller passes `size` readable bytes.
            b.data[r.clone()].copy_from_slice(std::slice::from_raw_parts(data, r.len()));
        }
    }

    /// glGetBufferSubData.
    ///
    /// # Safety
    /// `data` is NULL or points to room for `size` bytes.
    pub unsafe fn get_buffer_sub_data(&mut self, target: u32, offset: isize, size: isize, data: *mut u8) {
        let Some((b, r)) = self.buffer_range(target, offset, size) else { return };
        if !data.is_null() {
            // SAFETY: the caller provides room for `size` bytes.
            std::slice::from_raw_parts_mut(data, r.len()).copy_from_slice(&b.data[r]);
        }
    }

    pub fn map_buffer(&mut self, target: u32, access: u32) -> *mut u8 {
        if self.buffer_binding(target).is_none() {
            return std::ptr::null_mut();
        }
        if !matches!(access, GL_READ_ONLY | GL_WRITE_ONLY | GL_READ_WRITE) {
            self.set_error(GL_INVALID_ENUM);
            return std::ptr::null_mut();
        }
        let flags = match access {
            GL_READ_ONLY => GL_MAP_READ_BIT,
            GL_WRITE_ONLY => GL_MAP_WRITE_BIT,
            _ => GL_MAP_READ_BIT | GL_MAP_WRITE_BIT,
        };
        self.map_bound(target, access, flags, None)
    }

    /// Maps the buffer bound to `target` (INVALID_OPERATION if it is mapped
    /// already): [offset, offset + length) of its store, or all of it.
    /// The range is within the store (the callers check).
    fn map_bound(&mut self, target: u32, access: u32, flags: u32, range: Option<(usize, usize)>) -> *mut u8 {
        let Some(b) = self.bound_buffer(target) else { return std::ptr::null_mut() };
        if b.mapped {
            self.set_error(GL_INVALID_OPERATION);
            return std::ptr::null_mut();
        }
        let (offset, length) = range.unwrap_or((0, b.data.len()));
        b.mapped = true;
        b.access = access;
        b.access_flags = flags;
        b.map_offset = offset;
        b.map_length = length;
        // SAFETY: offset + length is within the store.
        unsafe { b.data.as_mut_ptr().add(offset) }
    }

    /// glMapBufferRange (ARB_map_buffer_range): a pointer to bytes
    /// [offset, offset + length) of the store. The store is CPU memory, so
    /// the mapping is the store itself: INVALIDATE_* leave the old bytes
    /// (their contents are undefined, keeping them is allowed),
    /// UNSYNCHRONIZED has nothing to wait for, and with FLUSH_EXPLICIT every
    /// write is already in place whether flushed or not.
    pub fn map_buffer_range(&mut self, target: u32, offset: isize, length: isize, access: u32) -> *mut u8 {
        let Some(name) = self.buffer_binding(target) else { return std::ptr::null_mut() };
        let all = GL_MAP_READ_BIT | GL_MAP_WRITE_BIT | GL_MAP_INVALIDATE_RANGE_BIT | GL_MAP_INVALIDATE_BUFFER_BIT | GL_MAP_FLUSH_EXPLICIT_BIT | GL_MAP_UNSYNCHRONIZED_BIT;
        // The value errors first (offset, length, unknown bits), then the
        // operation errors, as the extension lists them.
        let size = self.buffers.objects.get(&name).map_or(0, |b| b.data.len());
        if offset < 0 || length <= 0 || access & !all != 0 || (name != 0 && (offset as usize).saturating_add(length as usize) > size) {
            self.set_error(GL_INVALID_VALUE);
            return std::ptr::null_mut();
        }
        let rw = access & (GL_MAP_READ_BIT | GL_MAP_WRITE_BIT);
        let bad = rw == 0
            || (access & GL_MAP_READ_BIT != 0 && access & (GL_MAP_INVALIDATE_RANGE_BIT | GL_MAP_INVALIDATE_BUFFER_BIT | GL_MAP_UNSYNCHRONIZED_BIT) != 0)
            || (access & GL_MAP_FLUSH_EXPLICIT_BIT != 0 && access & GL_MAP_WRITE_BIT == 0);
        if bad {
            self.set_error(GL_INVALID_OPERATION);
            return std::ptr::null_mut();
        }
        let legacy = match rw {
            GL_MAP_READ_BIT => GL_READ_ONLY,
            GL_MAP_WRITE_BIT => GL_WRITE_ONLY,
            _ => GL_READ_WRITE,
        };
        // offset + length is within the store (checked above).
        self.map_bound(target, legacy, access, Some((offset as usize, length as usize)))
    }

    /// glFlushMappedBufferRange: checks the range against the mapping; the
    /// writes are already in the store (see [`Self::map_buffer_range`]).
    pub fn flush_mapped_buffer_range(&mut self, target: u32, offset: isize, length: isize) {
        let Some(b) = self.bound_buffer(target) else { return };
        if !b.mapped || b.access_flags & GL_MAP_FLUSH_EXPLICIT_BIT == 0 {
            return self.set_error(GL_INVALID_OPERATION);
        }
        let map_length = b.map_length;
        if offset < 0 || length < 0 || (offset as usize).saturating_add(length as usize) > map_length {
            self.set_error(GL_INVALID_VALUE);
        }
    }

    pub fn unmap_buffer(&mut self, target: u32) -> bool {
        let Some(b) = self.bound_buffer(target) else { return false };
        if !b.mapped {
            self.set_error(GL_INVALID_OPERATION);
            return false;
        }
        b.unmap();
        // The store never becomes corrupt in memory.
        true
    }

    pub fn get_buffer_parameter(&mut self, target: u32, pname: u32) -> Option<i64> {
        self.buffer_binding(target)?;
        if !matches!(pname, GL_BUFFER_SIZE | GL_BUFFER_USAGE | GL_BUFFER_ACCESS | GL_BUFFER_MAPPED | GL_BUFFER_ACCESS_FLAGS | GL_BUFFER_MAP_OFFSET | GL_BUFFER_MAP_LENGTH) {
            self.set_error(GL_INVALID_ENUM);
            return None;
        }
        let b = self.bound_buffer(target)?;
        Some(match pname {
            GL_BUFFER_SIZE => b.data.len() as i64,
            GL_BUFFER_USAGE => b.usage as i64,
            GL_BUFFER_ACCESS => b.access as i64,
            GL_BUFFER_ACCESS_FLAGS => b.access_flags as i64,
            GL_BUFFER_MAP_OFFSET => b.map_offset as i64,
            GL_BUFFER_MAP_LENGTH => b.map_length as i64,
            _ => b.mapped as i64,
        })
    }

    pub fn get_buffer_pointer(&mut self, target: u32, pname: u32) -> Option<*mut u8> {
        self.buffer_binding(target)?;
        if pname != GL_BUFFER_MAP_POINTER {
            self.set_error(GL_INVALID_ENUM);
            return None;
        }
        let b = self.bound_buffer(target)?;
        // SAFETY: map_offset is within the store while it is mapped.
        Some(if b.mapped { unsafe { b.data.as_mut_ptr().add(b.map_offset) } } else { std::ptr::null_mut() })
    }
}
