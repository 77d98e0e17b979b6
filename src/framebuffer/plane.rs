//! Storage for one framebuffer plane (colour, depth, stencil or
//! accumulation values: GL 1.5 chapter 4 intro), allocated so that the
//! first frame does not pay a 4 KiB page fault per 4 KiB of surface.
//!
//! Time to first frame at 1920x1080 was mostly page faults: the first
//! glClear touches the 8 MB colour, 8 MB depth and 2 MB stencil buffers,
//! about 4,600 faults of 4 KiB, each zeroing its page and taking the
//! kernel's page-table and LRU locks (6 to 12 ms here under load, against
//! about 1 ms for the same bytes in 2 MiB pages). So a large all-zero
//! plane is its own anonymous mapping, aligned to 2 MiB and advised
//! MADV_HUGEPAGE over its whole length (the length rounded up to 2 MiB
//! when that wastes at most 1/8 of it: a 1920x1080 stencil buffer is
//! 1.98 MiB, one huge page). Fresh anonymous memory is zero, so the plane
//! is never written before GL writes it. Anywhere the mapping fails, or
//! off Linux, or for small or non-zero planes, a `Vec` holds the plane
//! instead, with the same contents.

use std::ops::{Deref, DerefMut};

use super::AllocError;

/// Buffer element types: plain data for which all-zero bytes are a value.
pub trait Plain: Copy {}
impl Plain for u8 {}
impl Plain for u32 {}
impl Plain for [u8; 4] {}
impl Plain for [i16; 4] {}

/// Planes of at least this many bytes get a mapping of their own.
#[cfg(target_os = "linux")]
const MAP_MIN: usize = 1 << 20;
/// Transparent huge page size on x86-64 and most aarch64 kernels.
pub const HUGE: usize = 2 << 20;

/// A plane of `T`s (see the module comment). Derefs to a slice; never
/// grows.
pub struct Plane<T: Plain> {
    ptr: *mut T,
    len: usize,
    /// The storage when it is a vector (empty when mapped): kept only to
    /// be freed with the plane.
    #[allow(dead_code)]
    vec: Vec<T>,
    /// The mapping's length in bytes when it is one (0 otherwise).
    mapped: usize,
}

// SAFETY: a Plane uniquely owns its storage (a vector or a private
// mapping nothing else refers to); shared references only read it.
unsafe impl<T: Plain + Send> Send for Plane<T> {}
unsafe impl<T: Plain + Sync> Sync for Plane<T> {}

impl<T: Plain> Plane<T> {
    /// A plane holding the vector's elements.
    pub fn from_vec(mut v: Vec<T>) -> Plane<T> {
        Plane { ptr: v.as_mut_ptr(), len: v.len(), vec: v, mapped: 0 }
    }

    /// `n` copies of `fill`, or AllocError.
    pub fn new(n: usize, fill: T) -> Result<Plane<T>, AllocError> {
        // SAFETY: T is Plain (no padding), so its bytes may be read.
        let zero = unsafe { std::slice::from_raw_parts(&fill as *const T as *const u8, std::mem::size_of::<T>()) }.iter().all(|&b| b == 0);
        let bytes = n.checked_mul(std::mem::size_of::<T>()).ok_or(AllocError)?;
        #[cfg(target_os = "linux")]
        if zero && bytes >= MAP_MIN {
            if let Some((p, len)) = map_huge(bytes) {
                return Ok(Plane { ptr: p as *mut T, len: n, vec: Vec::new(), mapped: len });
            }
        }
        #[cfg(not(target_os = "linux"))]
        let _ = bytes;
        if zero && n > 0 {
            let layout = std::alloc::Layout::array::<T>(n).map_err(|_| AllocError)?;
            // SAFETY: layout has a non-zero size (n > 0, T is not
            // zero-sized); all-zero bytes are a valid T (Plain); the Vec
            // takes ownership of an allocation of exactly n T's made with
            // the global allocator.
            unsafe {
                let p = std::alloc::alloc_zeroed(layout) as *mut T;
                if p.is_null() {
                    return Err(AllocError);
                }
                advise_huge_pages(p as *mut u8, layout.size());
                return Ok(Plane::from_vec(Vec::from_raw_parts(p, n, n)));
            }
        }
        let mut v = Vec::new();
        v.try_reserve_exact(n).map_err(|_| AllocError)?;
        v.resize(n, fill);
        Ok(Plane::from_vec(v))
    }

    /// Is the plane its own 2 MiB-aligned mapping? (For tests.)
    pub fn is_mapped(&self) -> bool {
        self.mapped > 0
    }
}

impl<T: Plain> Default for Plane<T> {
    fn default() -> Plane<T> {
        Plane::from_vec(Vec::new())
    }
}

impl<T: Plain> Drop for Plane<T> {
    fn drop(&mut self) {
        #[cfg(target_os = "linux")]
        if self.mapped > 0 {
            // SAFETY: ptr/mapped is the mapping `map_huge` made, unmapped
            // once, here; no slice of it outlives `self`.
            unsafe { libc::munmap(self.ptr as *mut libc::c_void, self.mapped) };
        }
    }
}

impl<T: Plain> Deref for Plane<T> {
    type Target = [T];
    #[inline(always)]
    fn deref(&self) -> &[T] {
        // SAFETY: ptr/len describe the live storage (vector or mapping);
        // an empty vector's dangling pointer is valid for a 0-length slice.
        unsafe { std::slice::from_raw_parts(self.ptr, self.len) }
    }
}

impl<T: Plain> DerefMut for Plane<T> {
    #[inline(always)]
    fn deref_mut(&mut self) -> &mut [T] {
        // SAFETY: as in `deref`; `&mut self` makes the access unique.
        unsafe { std::slice::from_raw_parts_mut(self.ptr, self.len) }
    }
}

impl<T: Plain> Clone for Plane<T> {
    fn clone(&self) -> Plane<T> {
        Plane::from_vec(self.to_vec())
    }
}

impl<T: Plain + PartialEq> PartialEq for Plane<T> {
    fn eq(&self, other: &Plane<T>) -> bool {
        self[..] == other[..]
    }
}

impl<T: Plain + std::fmt::Debug> std::fmt::Debug for Plane<T> {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        write!(f, "Plane({} elements{})", self.len, if self.mapped > 0 { ", mapped" } else { "" })
    }
}

/// A fresh zeroed anonymous mapping of at least `bytes`, 2 MiB-aligned and
/// advised MADV_HUGEPAGE: its start and its length in bytes. None when
/// the kernel refuses (the caller falls back to the allocator).
#[cfg(target_os = "linux")]
pub(crate) fn map_huge(bytes: usize) -> Option<(*mut u8, usize)> {
    let page = 4096;
    let rounded = bytes.checked_add(HUGE - 1)? & !(HUGE - 1);
    // Whole huge pages when the tail they add is small; else the 4 KiB
    // tail beyond the last whole huge page stays in small pages.
    let len = if rounded - bytes <= bytes / 8 { rounded } else { bytes.checked_add(page - 1)? & !(page - 1) };
    let over = len.checked_add(HUGE)?;
    // SAFETY: a new private anonymous mapping; nothing else refers to it.
    unsafe {
        let p = libc::mmap(std::ptr::null_mut(), over, libc::PROT_READ | libc::PROT_WRITE, libc::MAP_PRIVATE | libc::MAP_ANONYMOUS, -1, 0);
        if p == libc::MAP_FAILED {
            return None;
        }
        let base = p as usize;
        let start = (base + HUGE - 1) & !(HUGE - 1);
        // Trim the unaligned head and the tail: [start, start + len) stays.
        if start > base {
            libc::munmap(p, start - base);
        }
        let tail = base + over - (start + len);
        if tail > 0 {
            libc::munmap((start + len) as *mut libc::c_void, tail);
        }
        // Advisory: no contents change; without THP the plane is 4 KiB pages.
        libc::madvise(start as *mut libc::c_void, len, libc::MADV_HUGEPAGE);
        Some((start as *mut u8, len))
    }
}

/// Asks the kernel for transparent huge pages over the 2 MiB-aligned part
/// of `len` bytes at `p` (memory the caller may not own: an OSMesa
/// buffer). Advisory only: no contents change, and nothing changes where
/// the kernel does not offer them or the pages are already there.
pub fn advise_huge_pages(p: *mut u8, len: usize) {
    #[cfg(target_os = "linux")]
    {
        let start = (p as usize).saturating_add(HUGE - 1) & !(HUGE - 1);
        let end = (p as usize).saturating_add(len) & !(HUGE - 1);
        if end > start {
            // SAFETY: [start, end) lies inside the buffer at p; MADV_HUGEPAGE
            // changes no contents.
            unsafe { libc::madvise(start as *mut libc::c_void, end - start, libc::MADV_HUGEPAGE) };
        }
    }
    #[cfg(not(target_os = "linux"))]
    let _ = (p, len);
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn planes_hold_their_fill_mapped_or_not() {
        // Small, large (mapped), non-zero fill, 1920x1080 stencil (rounded
        // up to one huge page) and a size whose round-up would waste more
        // than 1/8.
        for &(n, fill) in &[(0usize, 0u8), (100, 0), (3 << 20, 0), (1920 * 1080, 0), ((2 << 20) + 4097, 0), (5000, 7)] {
            let mut p = Plane::new(n, fill).unwrap();
            assert_eq!(p.len(), n);
            assert!(p.iter().all(|&b| b == fill), "n {n}");
            if cfg!(target_os = "linux") {
                assert_eq!(p.is_mapped(), fill == 0 && n >= 1 << 20, "n {n}");
            }
            if p.is_mapped() {
                assert_eq!(p.as_ptr() as usize % HUGE, 0);
            }
            // Every byte writable, including the last.
            for b in p.iter_mut() {
                *b = 0x5a;
            }
            let q = p.clone();
            assert!(q.iter().all(|&b| b == 0x5a) && q.len() == n && q == p);
        }
        let d = Plane::new(1920 * 1080, 0u32).unwrap();
        assert!(d.iter().all(|&v| v == 0));
        let a = Plane::new(1 << 18, [0i16; 4]).unwrap();
        assert!(a.iter().all(|v| *v == [0; 4]));
        assert_eq!(Plane::<u8>::default().len(), 0);
    }
}
