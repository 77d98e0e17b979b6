//! The state a filled triangle is set up and shaded under (GL 1.5 sections
//! 3.5 and 4.1), captured once per state change instead of per triangle.
//!
//! [`ShadeState`] copies the parts of [`RenderState`] that triangle setup
//! (`setup::planes_of`) and the span kernels read, and holds the kernels
//! [`fast::select`] picks for them. Which kernel a triangle takes depends
//! on the state and on two facts of the triangle only: whether its 1/w
//! varies (perspective) and whether its colour planes are constant. The
//! kernels for all four combinations are chosen when the state is
//! captured, so a triangle's choice is an index (`select` cost about 150
//! instructions per triangle before).
//!
//! Validity: `gl::validate` gives the render state a fresh, never reused
//! `stamp` whenever it recomputes anything, and every draw validates
//! first, so a captured state with the render state's stamp is the same
//! state. A render state that was never validated (stamp 0) is captured
//! anew for every triangle. The binned path (`tile`) shares one capture
//! among all the triangles drawn under it, on every worker.

use super::fog::Fog;
use super::fragment::fast::{self, Kernel};
use super::fragment::stamp::{self, StampKernel};
use super::fragment::{self, FragmentState};
use super::setup::{Plane, TexPlanes, TriangleSetup};
use super::texture::{TextureStage, MAX_UNITS};
use super::RenderState;
use std::cell::{Cell, RefCell};
use std::sync::atomic::{AtomicU64, Ordering};
use std::sync::Arc;

/// A stamp no render state has had before (never 0).
pub fn next_stamp() -> u64 {
    static NEXT: AtomicU64 = AtomicU64::new(1);
    NEXT.fetch_add(1, Ordering::Relaxed)
}

/// What setup reads from the state, from a [`RenderState`] (shading now)
/// or a [`ShadeState`] (shading later, in a tile worker).
pub trait SetupParams {
    fn flat(&self) -> bool;
    fn offset_fill(&self) -> Option<(f32, f32)>;
    fn texture(&self) -> Option<&Arc<TextureStage>>;
    fn fog(&self) -> Option<Fog>;
    fn color_sum(&self) -> bool;
}

/// Both states keep these five in fields of the same names and types.
macro_rules! setup_params_from_fields {
    ($($t:ty),*) => {$(
        impl SetupParams for $t {
            #[inline(always)]
            fn flat(&self) -> bool {
                self.flat
            }
            #[inline(always)]
            fn offset_fill(&self) -> Option<(f32, f32)> {
                self.offset_fill
            }
            #[inline(always)]
            fn texture(&self) -> Option<&Arc<TextureStage>> {
                self.texture.as_ref()
            }
            #[inline(always)]
            fn fog(&self) -> Option<Fog> {
                self.fog
            }
            #[inline(always)]
            fn color_sum(&self) -> bool {
                self.color_sum
            }
        }
    )*};
}

setup_params_from_fields!(RenderState, ShadeState);

/// A render state's triangle setup and fragment parameters, with its
/// span kernels chosen.
#[derive(Debug)]
pub struct ShadeState {
    /// The render state's stamp when captured.
    pub stamp: u64,
    pub reference: bool,
    pub fragment: FragmentState,
    pub polygon_stipple: Option<Box<[u32; 32]>>,
    pub flat: bool,
    pub offset_fill: Option<(f32, f32)>,
    pub texture: Option<Arc<TextureStage>>,
    pub fog: Option<Fog>,
    pub color_sum: bool,
    /// What a binned triangle under this state keeps besides its colours
    /// (`tile::ExtraLayout`).
    pub extras: super::tile::ExtraLayout,
    /// By [`Self::kernel_index`].
    kernels: [Kernel; 4],
    /// The block kernels (`fragment::stamp`) for tiny triangles, where
    /// the state has them; by [`Self::kernel_index`].
    stamps: [Option<StampKernel>; 4],
}

impl ShadeState {
    pub fn capture(rs: &RenderState) -> ShadeState {
        let mut s = ShadeState {
            stamp: rs.stamp,
            reference: rs.reference,
            fragment: rs.fragment.clone(),
            polygon_stipple: rs.polygon_stipple.clone(),
            flat: rs.flat,
            offset_fill: rs.offset_fill,
            texture: rs.texture.clone(),
            fog: rs.fog,
            color_sum: rs.color_sum,
            extras: super::tile::ExtraLayout::of(rs.texture.as_ref().map(|t| &t.active[..]), rs.fog.is_some(), rs.color_sum),
            kernels: [fragment::reference::shade_span; 4],
            stamps: [None; 4],
        };
        if !rs.reference {
            // A triangle of each kind, with exactly what `select` reads
            // set as setup would set it under this state.
            for (i, k) in s.kernels.iter_mut().enumerate() {
                let (perspective, constant) = (i & 2 != 0, i & 1 != 0);
                let slope = if constant { 0.0 } else { 1.0 };
                let tex = s.texture.as_ref().map(|stage| Box::new(TexPlanes { stage: stage.clone(), planes: [[Plane::default(); 4]; MAX_UNITS] }));
                let t = TriangleSetup {
                    x0: 0.0,
                    y0: 0.0,
                    z: Plane::default(),
                    q: Plane::default(),
                    color: [Plane { a0: 0.0, dx: slope, dy: slope }; 4],
                    perspective,
                    flat: s.flat.then_some([0; 4]),
                    front_facing: true,
                    secondary: (s.color_sum && tex.is_some()).then_some([Plane::default(); 3]),
                    tex,
                    fog: s.fog.map(|f| (Plane::default(), f)),
                };
                *k = fast::select(&s.fragment, &t, rs.approximate);
                s.stamps[i] = stamp::select(&s.fragment, &t, rs.approximate);
            }
        }
        s
    }

    /// Is this the capture of `rs`?
    #[inline(always)]
    pub fn is_of(&self, rs: &RenderState) -> bool {
        self.stamp == rs.stamp && self.stamp != 0 && self.reference == rs.reference
    }

    /// Which of the four kernels a triangle takes: what `select` decides
    /// from the triangle rather than the state.
    #[inline(always)]
    fn kernel_index(t: &TriangleSetup) -> usize {
        // Every slope == 0.0 (either zero; a NaN is not): no bit but the
        // sign bits set, tested at once without a branch per slope.
        // Round 28: each slope read alone (volatile: LLVM merges plain
        // reads of a plane's dx and dy into one 16-byte load, which the
        // set-up's two 8-byte stores just before cannot forward to).
        let bits = t.color.iter().fold(0u64, |b, p| {
            // SAFETY: references to initialized f64s.
            let (dx, dy) = unsafe { (std::ptr::read_volatile(&p.dx), std::ptr::read_volatile(&p.dy)) };
            b | dx.to_bits() | dy.to_bits()
        });
        let constant = bits << 1 == 0;
        (t.perspective as usize) << 1 | constant as usize
    }

    /// The span kernel for a triangle set up under this state: what
    /// `fast::select` picks for it.
    #[inline(always)]
    pub fn kernel(&self, t: &TriangleSetup) -> Kernel {
        self.kernels[Self::kernel_index(t)]
    }

    /// The block kernel for a tiny triangle set up under this state, if
    /// there is one: it computes what [`Self::kernel`]'s does.
    #[inline(always)]
    pub fn stamp(&self, t: &TriangleSetup) -> Option<StampKernel> {
        self.stamps[Self::kernel_index(t)]
    }
}

/// A render state's last capture. Clones start empty (a clone may be
/// changed without a new stamp).
#[derive(Default)]
pub struct ShadeCache(RefCell<Option<Arc<ShadeState>>>, Cell<KernelCache>);

/// The last capture's stamp and kernels, copied out of it: a triangle's
/// kernel choice is a stamp compare and an index (no borrow of the
/// `RefCell`, no reference count, no call).
#[derive(Clone, Copy)]
struct KernelCache {
    /// 0: empty (no validated state has stamp 0).
    stamp: u64,
    kernels: [Kernel; 4],
    stamps: [Option<StampKernel>; 4],
}

impl Default for KernelCache {
    fn default() -> Self {
        KernelCache { stamp: 0, kernels: [fragment::reference::shade_span; 4], stamps: [None; 4] }
    }
}

impl Clone for ShadeCache {
    fn clone(&self) -> Self {
        ShadeCache::default()
    }
}

impl std::fmt::Debug for ShadeCache {
    fn fmt(&self, f: &mut std::fmt::Formatter) -> std::fmt::Result {
        f.write_str("ShadeCache")
    }
}

impl ShadeCache {
    /// The span kernel for a triangle set up under `rs` (whose cache this
    /// is) on the fast path (`rs.reference` is false): what
    /// `with(rs, |st| st.kernel(t))` gives.
    #[inline(always)]
    pub fn kernel(&self, rs: &RenderState, t: &TriangleSetup) -> Kernel {
        let c = self.1.get();
        if c.stamp == rs.stamp && c.stamp != 0 && !rs.reference {
            return c.kernels[ShadeState::kernel_index(t)];
        }
        self.kernel_captured(rs, t)
    }

    /// The block kernel for a tiny triangle set up under `rs` (whose
    /// cache this is) on the fast path, if the state has one: what
    /// `with(rs, |st| st.stamp(t))` gives.
    #[inline(always)]
    pub fn stamp(&self, rs: &RenderState, t: &TriangleSetup) -> Option<StampKernel> {
        let c = self.1.get();
        if c.stamp == rs.stamp && c.stamp != 0 && !rs.reference {
            return c.stamps[ShadeState::kernel_index(t)];
        }
        self.stamp_captured(rs, t)
    }

    #[cold]
    #[inline(never)]
    fn stamp_captured(&self, rs: &RenderState, t: &TriangleSetup) -> Option<StampKernel> {
        self.kernel_captured(rs, t);
        self.with(rs, |st| st.stamp(t))
    }

    #[cold]
    #[inline(never)]
    fn kernel_captured(&self, rs: &RenderState, t: &TriangleSetup) -> Kernel {
        self.with(rs, |st| {
            // Only fast-path captures are copied out (the test above
            // leaves reference states to `with`).
            if !st.reference {
                self.1.set(KernelCache { stamp: st.stamp, kernels: st.kernels, stamps: st.stamps });
            }
            st.kernel(t)
        })
    }

    /// Runs `f` with the capture of `rs` (whose cache this is), capturing
    /// it first when the state changed.
    /// The hit (the state unchanged since the last triangle: every
    /// triangle of a vertex-bound scene but the first after a change) is
    /// inlined into the binning path; the capture is out of line.
    #[inline(always)]
    pub fn with<R>(&self, rs: &RenderState, f: impl FnOnce(&Arc<ShadeState>) -> R) -> R {
        {
            let c = self.0.borrow();
            if let Some(s) = c.as_ref() {
                if s.is_of(rs) {
                    return f(s);
                }
            }
        }
        f(&self.captured(rs))
    }

    /// Captures `rs` and keeps the capture (the miss of [`Self::with`]).
    #[cold]
    #[inline(never)]
    fn captured(&self, rs: &RenderState) -> Arc<ShadeState> {
        let s = Arc::new(ShadeState::capture(rs));
        *self.0.borrow_mut() = Some(s.clone());
        s
    }
}
