//! What an entry point returns when it cannot run: no current context, a
//! caught panic, or an error the spec says makes the command return zero.

use std::ffi::c_void;

pub trait Zero {
    fn zero() -> Self;
}

macro_rules! zero_is_default {
    ($($t:ty),*) => { $(impl Zero for $t { #[inline] fn zero() -> Self { Default::default() } })* };
}
zero_is_default!((), u8, i8, u16, i16, u32, i32, u64, i64, f32, f64, isize, usize);

impl<T> Zero for *const T {
    #[inline]
    fn zero() -> Self {
        std::ptr::null()
    }
}
impl<T> Zero for *mut T {
    #[inline]
    fn zero() -> Self {
        std::ptr::null_mut()
    }
}
impl<T> Zero for Option<T> {
    #[inline]
    fn zero() -> Self {
        None
    }
}

/// Keeps `c_void` in scope for the table's pointer types.
pub type Void = c_void;
