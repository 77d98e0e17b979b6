//! The record array of a batch of binned primitives (`render::tile`): a
//! growable array, as a `Vec`, whose large instances are their own
//! 2 MiB-aligned anonymous mapping advised huge pages (round 23).
//!
//! A large scene's first frame writes a few megabytes of fresh records on
//! the calling thread: in 4 KiB pages, a page fault each (spheres_m at
//! 1920x1080, 2 threads: 1,300 to 2,400 faults in the records, about
//! 1.7 microseconds each here, 2 to 4 ms of a 12 ms first frame). In
//! huge pages the same bytes take a fault per 2 MiB. Small instances
//! stay in the global allocator: a huge page commits 2 MiB at its first
//! write.

use std::mem::ManuallyDrop;
use std::ops::{Deref, DerefMut};
use std::ptr::NonNull;

/// A growable array of plain records (see the module comment).
pub struct Records<T: Copy> {
    ptr: NonNull<T>,
    len: usize,
    cap: usize,
    /// The mapping's length in bytes when the storage is one; 0 when it
    /// is a `Vec`'s buffer (`ptr` and `cap` taken from that vector).
    mapped: usize,
}

// SAFETY: a Records uniquely owns its storage (a vector's buffer or a
// private mapping nothing else refers to), as a Vec<T> does.
unsafe impl<T: Copy + Send> Send for Records<T> {}
unsafe impl<T: Copy + Sync> Sync for Records<T> {}

impl<T: Copy> Records<T> {
    /// Empty, with no storage.
    pub const fn new() -> Records<T> {
        Records { ptr: NonNull::dangling(), len: 0, cap: 0, mapped: 0 }
    }

    /// Empty, with room for at least `n` in the global allocator.
    pub fn with_capacity(n: usize) -> Records<T> {
        Records::from_vec(Vec::with_capacity(n))
    }

    /// Empty, with room for at least `n` in a mapping of its own advised
    /// huge pages; in the global allocator where no mapping is made (off
    /// Linux, or the kernel refuses).
    pub fn with_capacity_huge(n: usize) -> Records<T> {
        #[cfg(target_os = "linux")]
        {
            let size = std::mem::size_of::<T>();
            let align_ok = crate::framebuffer::plane::HUGE.is_multiple_of(std::mem::align_of::<T>());
            if let Some(bytes) = n.checked_mul(size).filter(|&b| b > 0 && size > 0 && align_ok) {
                if let Some((p, len)) = crate::framebuffer::plane::map_huge(bytes) {
                    // SAFETY: map_huge returns a non-null mapping.
                    let ptr = unsafe { NonNull::new_unchecked(p as *mut T) };
                    return Records { ptr, len: 0, cap: len / size, mapped: len };
                }
            }
        }
        Records::with_capacity(n)
    }

    fn from_vec(v: Vec<T>) -> Records<T> {
        let mut v = ManuallyDrop::new(v);
        debug_assert!(v.is_empty());
        // SAFETY: a vector's pointer is never null.
        let ptr = unsafe { NonNull::new_unchecked(v.as_mut_ptr()) };
        Records { ptr, len: 0, cap: v.capacity(), mapped: 0 }
    }

    /// Is the storage a mapping of its own?
    pub fn is_mapped(&self) -> bool {
        self.mapped > 0
    }

    #[inline(always)]
    pub fn len(&self) -> usize {
        self.len
    }

    #[inline(always)]
    pub fn is_empty(&self) -> bool {
        self.len == 0
    }

    #[inline(always)]
    pub fn capacity(&self) -> usize {
        self.cap
    }

    #[inline(always)]
    pub fn as_ptr(&self) -> *const T {
        self.ptr.as_ptr()
    }

    #[inline(always)]
    pub fn as_mut_ptr(&mut self) -> *mut T {
        self.ptr.as_ptr()
    }

    /// Sets the length, as `Vec::set_len`.
    ///
    /// # Safety
    /// `len` is at most the capacity and the first `len` records are
    /// written.
    #[inline(always)]
    pub unsafe fn set_len(&mut self, len: usize) {
        debug_assert!(len <= self.cap);
        self.len = len;
    }

    /// Empties the array, keeping its storage (records are `Copy`: nothing
    /// to drop).
    pub fn clear(&mut self) {
        self.len = 0;
    }

    /// Appends `t`, growing the storage when it is full.
    pub fn push(&mut self, t: T) {
        if self.len == self.cap {
            self.reserve(1);
        }
        // SAFETY: room for one more, just made.
        unsafe {
            self.ptr.as_ptr().add(self.len).write(t);
        }
        self.len += 1;
    }

    /// Makes room for `additional` more, as `Vec::reserve` (amortized
    /// doubling); storage that grows moves into the global allocator.
    pub fn reserve(&mut self, additional: usize) {
        if self.cap - self.len >= additional {
            return;
        }
        if self.mapped == 0 {
            // SAFETY: ptr/len/cap are the vector's, taken apart in
            // `from_vec` or here. Held in ManuallyDrop: should `reserve`
            // panic, `self` still owns the buffer, which is not freed.
            let mut v = ManuallyDrop::new(unsafe { Vec::from_raw_parts(self.ptr.as_ptr(), self.len, self.cap) });
            v.reserve(additional);
            // SAFETY: a vector's pointer is never null.
            self.ptr = unsafe { NonNull::new_unchecked(v.as_mut_ptr()) };
            self.cap = v.capacity();
            return;
        }
        let need = self.len.checked_add(additional).expect("capacity overflow");
        let mut grown = Records::with_capacity(need.max(self.cap.saturating_mul(2)));
        grown.append(self);
        *self = grown;
    }

    /// Moves every record of `other` to the end of this array, leaving
    /// `other` empty (its storage kept).
    pub fn append(&mut self, other: &mut Records<T>) {
        self.reserve(other.len);
        // SAFETY: room for other.len more, just made; distinct arrays.
        unsafe {
            std::ptr::copy_nonoverlapping(other.ptr.as_ptr(), self.ptr.as_ptr().add(self.len), other.len);
        }
        self.len += other.len;
        other.len = 0;
    }
}

impl<T: Copy> Default for Records<T> {
    fn default() -> Records<T> {
        Records::new()
    }
}

impl<T: Copy> Drop for Records<T> {
    fn drop(&mut self) {
        if self.mapped > 0 {
            #[cfg(target_os = "linux")]
            // SAFETY: ptr/mapped is the mapping map_huge made, unmapped
            // once, here; no slice of it outlives `self`.
            unsafe {
                libc::munmap(self.ptr.as_ptr() as *mut libc::c_void, self.mapped);
            }
        } else {
            // SAFETY: ptr/cap are a vector's buffer (see `from_vec`);
            // records are Copy, so nothing else is dropped.
            drop(unsafe { Vec::from_raw_parts(self.ptr.as_ptr(), 0, self.cap) });
        }
    }
}

impl<T: Copy> Deref for Records<T> {
    type Target = [T];
    #[inline(always)]
    fn deref(&self) -> &[T] {
        // SAFETY: the first len records are written; a dangling pointer is
        // valid for an empty slice.
        unsafe { std::slice::from_raw_parts(self.ptr.as_ptr(), self.len) }
    }
}

impl<T: Copy> DerefMut for Records<T> {
    #[inline(always)]
    fn deref_mut(&mut self) -> &mut [T] {
        // SAFETY: as in `deref`; `&mut self` makes the access unique.
        unsafe { std::slice::from_raw_parts_mut(self.ptr.as_ptr(), self.len) }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[derive(Clone, Copy, Debug, PartialEq)]
    #[repr(align(64))]
    struct R([u64; 16]);

    fn r(i: u64) -> R {
        R([i; 16])
    }

    /// Pushes, growth out of a mapping and out of a vector, append and
    /// clear keep every record in order.
    #[test]
    fn records_keep_their_order_through_growth() {
        for start in [Records::<R>::new(), Records::with_capacity(3), Records::with_capacity_huge(5)] {
            let mut a = start;
            for i in 0..100 {
                a.push(r(i));
            }
            assert_eq!(a.len(), 100);
            assert!(a.iter().enumerate().all(|(i, x)| *x == r(i as u64)));
            let mut b = Records::with_capacity_huge(4);
            for i in 100..150 {
                b.push(r(i));
            }
            a.append(&mut b);
            assert!(b.is_empty());
            assert!(a.iter().enumerate().all(|(i, x)| *x == r(i as u64)), "append");
            let cap = a.capacity();
            a.clear();
            assert!(a.is_empty() && a.capacity() == cap);
            a.push(r(7));
            assert_eq!(a[0], r(7));
        }
    }

    /// A huge instance is a 2 MiB-aligned mapping of its own on Linux
    /// (where the kernel allows it), with room for what was asked.
    #[test]
    fn huge_records_are_their_own_aligned_mapping() {
        let a = Records::<R>::with_capacity_huge(32 * 1024);
        assert!(a.capacity() >= 32 * 1024);
        if a.is_mapped() {
            assert_eq!(a.as_ptr() as usize % crate::framebuffer::plane::HUGE, 0);
        }
        #[cfg(target_os = "linux")]
        assert!(a.is_mapped(), "an anonymous mapping of 4 MB should be possible");
    }
}
