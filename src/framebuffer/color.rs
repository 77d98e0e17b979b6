//! Colour buffer storage: RGBA8 pixels, rows bottom-up, either owned by
//! softgl or lent by the caller.
//!
//! OSMesa hands softgl the memory the image is to end up in. When that
//! memory already has softgl's own layout (GL_RGBA, GL_UNSIGNED_BYTE, rows
//! bottom-up with no padding), drawing goes straight into it: no copy of
//! the caller's pixels at OSMesaMakeCurrent and none back at glFinish, two
//! full-frame copies and their page faults saved per frame (a 1920x1080
//! frame is 8 MB each way). This is what Mesa's classic OSMesa driver did.
//!
//! Either way the pixels are reached through one pointer and length, so
//! `Deref` to a slice costs no branch in the pipeline's inner loops.

use std::ops::{Deref, DerefMut};

use super::Plane;

/// An RGBA8 colour buffer (see the module comment).
pub struct ColorBuffer {
    ptr: *mut [u8; 4],
    len: usize,
    /// The storage when softgl owns it (its heap buffer never moves: the
    /// vector is never grown); empty when the caller lends the memory.
    owned: Plane<[u8; 4]>,
}

// SAFETY: a ColorBuffer is a uniquely owned `[[u8; 4]]`: either its own
// vector's buffer or caller memory the OSMesa contract reserves for the
// context while it is bound. Shared references only read it.
unsafe impl Send for ColorBuffer {}
unsafe impl Sync for ColorBuffer {}

impl ColorBuffer {
    /// A buffer owning `v`.
    pub fn owned(mut v: Plane<[u8; 4]>) -> ColorBuffer {
        ColorBuffer { ptr: v.as_mut_ptr(), len: v.len(), owned: v }
    }

    /// A buffer over `len` pixels of caller memory at `ptr`.
    ///
    /// # Safety
    /// `ptr` must be valid for reads and writes of `len` pixels, aligned to
    /// 1 byte (pixels are byte arrays), and stay so, used by nothing else
    /// while softgl draws, until this buffer is replaced or dropped.
    pub unsafe fn lent(ptr: *mut u8, len: usize) -> ColorBuffer {
        ColorBuffer { ptr: ptr as *mut [u8; 4], len, owned: Plane::default() }
    }

    /// Is this the caller's memory?
    pub fn is_lent(&self) -> bool {
        self.len > 0 && self.owned.is_empty()
    }
}

impl Default for ColorBuffer {
    fn default() -> ColorBuffer {
        ColorBuffer::owned(Plane::default())
    }
}

impl Deref for ColorBuffer {
    type Target = [[u8; 4]];
    #[inline(always)]
    fn deref(&self) -> &[[u8; 4]] {
        // SAFETY: ptr/len describe live storage (see `owned` and `lent`);
        // an empty vector's dangling pointer is valid for a 0-length slice.
        unsafe { std::slice::from_raw_parts(self.ptr, self.len) }
    }
}

impl DerefMut for ColorBuffer {
    #[inline(always)]
    fn deref_mut(&mut self) -> &mut [[u8; 4]] {
        // SAFETY: as in `deref`; `&mut self` makes the access unique.
        unsafe { std::slice::from_raw_parts_mut(self.ptr, self.len) }
    }
}

/// Equal when the pixels are.
impl PartialEq for ColorBuffer {
    fn eq(&self, other: &ColorBuffer) -> bool {
        self[..] == other[..]
    }
}

impl std::fmt::Debug for ColorBuffer {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        write!(f, "ColorBuffer({} pixels{})", self.len, if self.is_lent() { ", lent" } else { "" })
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn owned_and_lent_buffers_reach_their_pixels() {
        let mut b = ColorBuffer::owned(Plane::from_vec(vec![[1, 2, 3, 4]; 3]));
        b[1] = [9; 4];
        assert_eq!(&b[..], &[[1, 2, 3, 4], [9; 4], [1, 2, 3, 4]]);
        assert!(!b.is_lent());
        // Moving the owner keeps the pointer valid (the heap buffer stays).
        let moved = b;
        assert_eq!(moved[1], [9; 4]);

        let mut mem = vec![0u8; 8];
        let mut l = unsafe { ColorBuffer::lent(mem.as_mut_ptr(), 2) };
        l[1] = [5, 6, 7, 8];
        assert!(l.is_lent());
        drop(l);
        assert_eq!(mem, [0, 0, 0, 0, 5, 6, 7, 8]);
        assert!(!ColorBuffer::default().is_lent());
    }
}
