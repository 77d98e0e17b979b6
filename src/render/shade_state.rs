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
use super::fragment::{self, FragmentState};
use super::setup::{Plane, TexPlanes, TriangleSetup};
use super::texture::{TextureStage, MAX_UNITS};
use super::RenderState;
use std::cell::RefCell;
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
    /// By [`Self::kernel_index`].
    kernels: [Kernel; 4],
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
            kernels: [fragment::reference::shade_span; 4],
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
        let constant = t.color.iter().all(|p| p.dx == 0.0 && p.dy == 0.0);
        (t.perspective as usize) << 1 | constant as usize
    }

    /// The span kernel for a triangle set up under this state: what
    /// `fast::select` picks for it.
    #[inline(always)]
    pub fn kernel(&self, t: &TriangleSetup) -> Kernel {
        self.kernels[Self::kernel_index(t)]
    }
}

/// A render state's last capture. Clones start empty (a clone may be
/// changed without a new stamp).
#[derive(Default)]
pub struct ShadeCache(RefCell<Option<Arc<ShadeState>>>);

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
    /// Runs `f` with the capture of `rs` (whose cache this is), capturing
    /// it first when the state changed.
    #[inline]
    pub fn with<R>(&self, rs: &RenderState, f: impl FnOnce(&Arc<ShadeState>) -> R) -> R {
        {
            let c = self.0.borrow();
            if let Some(s) = c.as_ref() {
                if s.is_of(rs) {
                    return f(s);
                }
            }
        }
        let s = Arc::new(ShadeState::capture(rs));
        let r = f(&s);
        *self.0.borrow_mut() = Some(s);
        r
    }
}
