//! Converting C arguments: reading the arrays behind `v` pointers (a NULL
//! pointer makes the command do nothing rather than crash), and GL's
//! conversions of integer components to floating point (GL 1.5 table 2.9).

/// Reads `N` values from `p`, or `None` if `p` is NULL.
///
/// # Safety
/// `p` must be NULL or point to `N` readable values, as the GL call requires.
#[inline]
pub unsafe fn arr<T: Copy, const N: usize>(p: *const T) -> Option<[T; N]> {
    if p.is_null() {
        None
    } else {
        Some(std::ptr::read_unaligned(p as *const [T; N]))
    }
}

/// Reads `n` values from `p` into a Vec (empty when `p` is NULL or n <= 0).
///
/// # Safety
/// `p` must be NULL or point to `n` readable values.
pub unsafe fn slice<T: Copy>(p: *const T, n: i64) -> Vec<T> {
    if p.is_null() || n <= 0 {
        return Vec::new();
    }
    (0..n as usize).map(|i| std::ptr::read_unaligned(p.add(i))).collect()
}

/// A component type GL converts to floating point, for colours and normals.
pub trait Component: Copy {
    /// The spec's conversion to [0,1] (unsigned) or [-1,1] (signed).
    fn normalized(self) -> f32;
    /// Plain conversion (vertex coordinates, texture coordinates).
    fn plain(self) -> f32;
}

impl Component for f32 {
    #[inline]
    fn normalized(self) -> f32 {
        self
    }
    #[inline]
    fn plain(self) -> f32 {
        self
    }
}
impl Component for f64 {
    #[inline]
    fn normalized(self) -> f32 {
        self as f32
    }
    #[inline]
    fn plain(self) -> f32 {
        self as f32
    }
}
impl Component for u8 {
    #[inline]
    fn normalized(self) -> f32 {
        self as f32 / 255.0
    }
    #[inline]
    fn plain(self) -> f32 {
        self as f32
    }
}
impl Component for i8 {
    #[inline]
    fn normalized(self) -> f32 {
        (2.0 * self as f32 + 1.0) / 255.0
    }
    #[inline]
    fn plain(self) -> f32 {
        self as f32
    }
}
impl Component for u16 {
    #[inline]
    fn normalized(self) -> f32 {
        self as f32 / 65535.0
    }
    #[inline]
    fn plain(self) -> f32 {
        self as f32
    }
}
impl Component for i16 {
    #[inline]
    fn normalized(self) -> f32 {
        (2.0 * self as f32 + 1.0) / 65535.0
    }
    #[inline]
    fn plain(self) -> f32 {
        self as f32
    }
}
impl Component for u32 {
    #[inline]
    fn normalized(self) -> f32 {
        (self as f64 / 4294967295.0) as f32
    }
    #[inline]
    fn plain(self) -> f32 {
        self as f32
    }
}
impl Component for i32 {
    #[inline]
    fn normalized(self) -> f32 {
        ((2.0 * self as f64 + 1.0) / 4294967295.0) as f32
    }
    #[inline]
    fn plain(self) -> f32 {
        self as f32
    }
}

/// A colour from 3 or 4 components; alpha defaults to 1.
#[inline]
pub fn color<T: Component>(c: &[T]) -> [f32; 4] {
    [
        c[0].normalized(),
        c[1].normalized(),
        c[2].normalized(),
        c.get(3).map_or(1.0, |a| a.normalized()),
    ]
}

/// A position from 2, 3 or 4 coordinates; z defaults to 0 and w to 1.
#[inline]
pub fn position<T: Component>(v: &[T]) -> [f32; 4] {
    [
        v[0].plain(),
        v[1].plain(),
        v.get(2).map_or(0.0, |z| z.plain()),
        v.get(3).map_or(1.0, |w| w.plain()),
    ]
}
