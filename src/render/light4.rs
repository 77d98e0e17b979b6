//! The lighting equation (GL 1.5 section 2.14.1) for the batched vertex
//! path's queued vertices, four at a time: eye position, eye normal and
//! both lit colours of each lane, as `Context::vertex_colors` computes
//! them one vertex at a time with [`LightingSetup::eye_normal`] and
//! [`LightingSetup::shade_split`].
//!
//! Invariant: every lane performs the same f32 operations, in the same
//! order, as those scalar functions (glam's `Vec3` is plain f32 code: a dot
//! product is (x x' + y y') + z z'; `normalize_or_zero` multiplies by
//! 1 / sqrt of it when that is finite and positive; `Vec4::clamp` is SSE
//! max-then-min, which returns the second operand for NaN and equal
//! values), so a lane's colours have the scalar path's bits. What does not
//! depend on the vertex (products of material and light colours, a
//! directional light's half vector with an infinite viewer) is computed
//! once with the same glam operations. `powf` stays one libm call per lit
//! lane. Why lanes: a lit vertex is about 400 instructions of short
//! dependent chains (two square roots and four divisions per positional
//! light); four vertices' chains run side by side in SSE registers.

use super::light::LightingSetup;
use super::vertex4::{Positions, LANES};
use crate::gl::enums::{GL_AMBIENT, GL_AMBIENT_AND_DIFFUSE, GL_DIFFUSE, GL_EMISSION, GL_SPECULAR};
use crate::gl::lighting::Material;
use glam::{Vec3, Vec4};

/// Object-space normals of the queued vertices, one array per coordinate.
#[derive(Clone, Copy, Debug)]
pub struct Normals {
    pub x: [f32; LANES],
    pub y: [f32; LANES],
    pub z: [f32; LANES],
}

impl Normals {
    pub const ZERO: Normals = Normals { x: [0.0; LANES], y: [0.0; LANES], z: [1.0; LANES] };

    #[inline(always)]
    pub fn set(&mut self, lane: usize, n: [f32; 3]) {
        self.x[lane] = n[0];
        self.y[lane] = n[1];
        self.z[lane] = n[2];
    }
}

/// GL_COLOR_MATERIAL (2.14.3) over the queued vertices: the current
/// colour at each glVertex, one array per channel, stands for the tracked
/// material property `mode` of the faces in `faces` (front, back).
#[derive(Clone, Copy, Debug)]
pub struct Tracked {
    pub colors: [[f32; LANES]; 4],
    pub faces: [bool; 2],
    pub mode: u32,
}

impl Tracked {
    #[inline(always)]
    pub fn set(&mut self, lane: usize, c: [f32; 4]) {
        for (ch, v) in self.colors.iter_mut().zip(c) {
            ch[lane] = v;
        }
    }
}

/// Per lane: the front and back primary and secondary colours.
pub type LitColors = [[Vec4; 4]; LANES];

/// Four f32 lanes and lane masks: SSE registers where the target has
/// SSE2, arrays otherwise. Each operation is the one IEEE operation per
/// lane (so the same bits either way).
#[cfg(all(any(target_arch = "x86_64", target_arch = "x86"), target_feature = "sse2"))]
mod lane {
    #[cfg(target_arch = "x86")]
    use core::arch::x86::*;
    #[cfg(target_arch = "x86_64")]
    use core::arch::x86_64::*;

    #[derive(Clone, Copy)]
    pub struct F(__m128);
    /// All ones in a true lane.
    #[derive(Clone, Copy)]
    pub struct M(__m128);

    // SAFETY (every `unsafe` block below): SSE2 is enabled for this target
    // (the module's cfg), and the intrinsics only read and write registers
    // or the four-lane arrays passed by reference.
    impl F {
        #[inline(always)]
        pub fn splat(x: f32) -> F {
            F(unsafe { _mm_set1_ps(x) })
        }
        #[inline(always)]
        pub fn load(a: &[f32; 4]) -> F {
            F(unsafe { _mm_loadu_ps(a.as_ptr()) })
        }
        #[inline(always)]
        pub fn get(self) -> [f32; 4] {
            let mut a = [0.0; 4];
            unsafe { _mm_storeu_ps(a.as_mut_ptr(), self.0) };
            a
        }
        #[inline(always)]
        pub fn add(self, o: F) -> F {
            F(unsafe { _mm_add_ps(self.0, o.0) })
        }
        #[inline(always)]
        pub fn sub(self, o: F) -> F {
            F(unsafe { _mm_sub_ps(self.0, o.0) })
        }
        #[inline(always)]
        pub fn mul(self, o: F) -> F {
            F(unsafe { _mm_mul_ps(self.0, o.0) })
        }
        #[inline(always)]
        pub fn div(self, o: F) -> F {
            F(unsafe { _mm_div_ps(self.0, o.0) })
        }
        #[inline(always)]
        pub fn sqrt(self) -> F {
            F(unsafe { _mm_sqrt_ps(self.0) })
        }
        #[inline(always)]
        pub fn neg(self) -> F {
            F(unsafe { _mm_xor_ps(self.0, _mm_set1_ps(-0.0)) })
        }
        /// SSE `maxps`: `self` where `self > o`, else `o` (so `o` for NaN
        /// and for equal values), as glam's `Vec4::max`.
        #[inline(always)]
        pub fn max_sse(self, o: F) -> F {
            F(unsafe { _mm_max_ps(self.0, o.0) })
        }
        /// SSE `minps`, as glam's `Vec4::min`.
        #[inline(always)]
        pub fn min_sse(self, o: F) -> F {
            F(unsafe { _mm_min_ps(self.0, o.0) })
        }
        #[inline(always)]
        pub fn gt(self, o: F) -> M {
            M(unsafe { _mm_cmpgt_ps(self.0, o.0) })
        }
        #[inline(always)]
        pub fn ne(self, o: F) -> M {
            M(unsafe { _mm_cmpneq_ps(self.0, o.0) })
        }
        /// |self| < infinity: finite (false for NaN).
        #[inline(always)]
        pub fn finite(self) -> M {
            M(unsafe { _mm_cmplt_ps(_mm_andnot_ps(_mm_set1_ps(-0.0), self.0), _mm_set1_ps(f32::INFINITY)) })
        }
        /// `if m { a } else { b }` per lane.
        #[inline(always)]
        pub fn select(m: M, a: F, b: F) -> F {
            F(unsafe { _mm_or_ps(_mm_and_ps(m.0, a.0), _mm_andnot_ps(m.0, b.0)) })
        }
    }

    impl M {
        #[inline(always)]
        pub fn and(self, o: M) -> M {
            M(unsafe { _mm_and_ps(self.0, o.0) })
        }
        /// Bit i set where lane i is true.
        #[inline(always)]
        pub fn bits(self) -> u32 {
            (unsafe { _mm_movemask_ps(self.0) }) as u32
        }
    }
}

/// The lanes as arrays, for targets without SSE2.
#[cfg(not(all(any(target_arch = "x86_64", target_arch = "x86"), target_feature = "sse2")))]
mod lane {
    #[derive(Clone, Copy)]
    pub struct F([f32; 4]);
    #[derive(Clone, Copy)]
    pub struct M([bool; 4]);

    impl F {
        #[inline(always)]
        fn zip(self, o: F, f: impl Fn(f32, f32) -> f32) -> F {
            F(std::array::from_fn(|i| f(self.0[i], o.0[i])))
        }
        #[inline(always)]
        fn test(self, o: F, f: impl Fn(f32, f32) -> bool) -> M {
            M(std::array::from_fn(|i| f(self.0[i], o.0[i])))
        }
        pub fn splat(x: f32) -> F {
            F([x; 4])
        }
        pub fn load(a: &[f32; 4]) -> F {
            F(*a)
        }
        pub fn get(self) -> [f32; 4] {
            self.0
        }
        pub fn add(self, o: F) -> F {
            self.zip(o, |a, b| a + b)
        }
        pub fn sub(self, o: F) -> F {
            self.zip(o, |a, b| a - b)
        }
        pub fn mul(self, o: F) -> F {
            self.zip(o, |a, b| a * b)
        }
        pub fn div(self, o: F) -> F {
            self.zip(o, |a, b| a / b)
        }
        pub fn sqrt(self) -> F {
            F(self.0.map(f32::sqrt))
        }
        pub fn neg(self) -> F {
            F(self.0.map(|a| -a))
        }
        pub fn max_sse(self, o: F) -> F {
            self.zip(o, |a, b| if a > b { a } else { b })
        }
        pub fn min_sse(self, o: F) -> F {
            self.zip(o, |a, b| if a < b { a } else { b })
        }
        pub fn gt(self, o: F) -> M {
            self.test(o, |a, b| a > b)
        }
        pub fn ne(self, o: F) -> M {
            self.test(o, |a, b| a != b)
        }
        pub fn finite(self) -> M {
            M(self.0.map(f32::is_finite))
        }
        pub fn select(m: M, a: F, b: F) -> F {
            F(std::array::from_fn(|i| if m.0[i] { a.0[i] } else { b.0[i] }))
        }
    }

    impl M {
        pub fn and(self, o: M) -> M {
            M(std::array::from_fn(|i| self.0[i] && o.0[i]))
        }
        pub fn bits(self) -> u32 {
            (0..4).map(|i| (self.0[i] as u32) << i).sum()
        }
    }
}

use lane::{F, M};

/// A three-component vector per lane (glam's `Vec3` operations).
#[derive(Clone, Copy)]
struct V3 {
    x: F,
    y: F,
    z: F,
}

impl V3 {
    #[inline(always)]
    fn splat(v: Vec3) -> V3 {
        V3 { x: F::splat(v.x), y: F::splat(v.y), z: F::splat(v.z) }
    }
    #[inline(always)]
    fn neg(self) -> V3 {
        V3 { x: self.x.neg(), y: self.y.neg(), z: self.z.neg() }
    }
    #[inline(always)]
    fn add(self, o: V3) -> V3 {
        V3 { x: self.x.add(o.x), y: self.y.add(o.y), z: self.z.add(o.z) }
    }
    #[inline(always)]
    fn sub(self, o: V3) -> V3 {
        V3 { x: self.x.sub(o.x), y: self.y.sub(o.y), z: self.z.sub(o.z) }
    }
    /// `Vec3::dot`: (x x' + y y') + z z'.
    #[inline(always)]
    fn dot(self, o: V3) -> F {
        self.x.mul(o.x).add(self.y.mul(o.y)).add(self.z.mul(o.z))
    }
    /// `Vec3 * f32` per lane.
    #[inline(always)]
    fn scale(self, s: F) -> V3 {
        V3 { x: self.x.mul(s), y: self.y.mul(s), z: self.z.mul(s) }
    }
    /// `Vec3 / f32` per lane.
    #[inline(always)]
    fn div(self, s: F) -> V3 {
        V3 { x: self.x.div(s), y: self.y.div(s), z: self.z.div(s) }
    }
    #[inline(always)]
    fn select(m: M, a: V3, b: V3) -> V3 {
        V3 { x: F::select(m, a.x, b.x), y: F::select(m, a.y, b.y), z: F::select(m, a.z, b.z) }
    }
    /// `Vec3::normalize_or_zero`: times 1 / sqrt(v . v) when that is
    /// finite and positive, else zero.
    #[inline(always)]
    fn normalize_or_zero(self) -> V3 {
        let rcp = F::splat(1.0).div(self.dot(self).sqrt());
        let ok = rcp.finite().and(rcp.gt(F::splat(0.0)));
        V3::select(ok, self.scale(rcp), V3::splat(Vec3::ZERO))
    }
}

/// A colour per lane, one register per channel.
#[derive(Clone, Copy)]
struct C4([F; 4]);

impl C4 {
    #[inline(always)]
    fn splat(c: Vec4) -> C4 {
        C4([F::splat(c.x), F::splat(c.y), F::splat(c.z), F::splat(c.w)])
    }
    /// glam's `self + o * Vec4::splat(s)` in the lanes of `on`.
    #[inline(always)]
    fn add_times(&mut self, o: &C4, s: F, on: M) {
        for (c, oc) in self.0.iter_mut().zip(o.0) {
            *c = F::select(on, c.add(oc.mul(s)), *c);
        }
    }
    /// `Vec4::clamp(ZERO, ONE)`: SSE max then min.
    #[inline(always)]
    fn clamp01(&self) -> C4 {
        C4(self.0.map(|c| c.max_sse(F::splat(0.0)).min_sse(F::splat(1.0))))
    }
    #[inline(always)]
    fn load(c: &[[f32; LANES]; 4]) -> C4 {
        C4(c.each_ref().map(F::load))
    }
    /// glam's `self * k` for a lane-invariant colour k.
    #[inline(always)]
    fn mul_by(&self, k: Vec4) -> C4 {
        let k = k.to_array();
        C4(std::array::from_fn(|c| self.0[c].mul(F::splat(k[c]))))
    }
    #[inline(always)]
    fn add(&self, o: &C4) -> C4 {
        C4(std::array::from_fn(|c| self.0[c].add(o.0[c])))
    }
    /// The colours as a `Vec4` per lane, alpha `a`.
    #[inline(always)]
    fn lanes(&self, a: [f32; LANES]) -> [Vec4; LANES] {
        let [r, g, b] = [self.0[0].get(), self.0[1].get(), self.0[2].get()];
        std::array::from_fn(|i| Vec4::new(r[i], g[i], b[i], a[i]))
    }
}

/// A material per lane: the material's colours, with the property
/// GL_COLOR_MATERIAL tracks taken from the lanes' current colours.
struct LaneMaterial {
    emission: C4,
    ambient: C4,
    diffuse: C4,
    specular: C4,
    shininess: f32,
    /// The diffuse alpha per lane (the lit colour's alpha).
    alpha: [f32; LANES],
}

impl LaneMaterial {
    fn new(m: &Material, tracked: Option<(&Tracked, usize)>) -> LaneMaterial {
        let mut l = LaneMaterial {
            emission: C4::splat(m.emission),
            ambient: C4::splat(m.ambient),
            diffuse: C4::splat(m.diffuse),
            specular: C4::splat(m.specular),
            shininess: m.shininess,
            alpha: [m.diffuse.w; LANES],
        };
        if let Some((t, _)) = tracked.filter(|(t, face)| t.faces[*face]) {
            let c = C4::load(&t.colors);
            match t.mode {
                GL_EMISSION => l.emission = c,
                GL_AMBIENT => l.ambient = c,
                GL_DIFFUSE => l.diffuse = c,
                GL_SPECULAR => l.specular = c,
                GL_AMBIENT_AND_DIFFUSE => (l.ambient, l.diffuse) = (c, c),
                _ => {}
            }
            if matches!(t.mode, GL_DIFFUSE | GL_AMBIENT_AND_DIFFUSE) {
                l.alpha = t.colors[3];
            }
        }
        l
    }
}

/// The lit colours of the first `k` queued vertices (object positions
/// `obj`, object normals `normals`) under `ls` and the front and back
/// materials `m` (with GL_COLOR_MATERIAL's property from `tracked`): per
/// lane `[front, back, front secondary, back secondary]` as `shade_split`
/// and `vertex_colors`' lighting arm give them (before the colour sum).
/// Lanes from `k` on are left zero.
pub fn light_lanes(ls: &LightingSetup, m: &[Material; 2], tracked: Option<&Tracked>, obj: &Positions, normals: &Normals, k: usize) -> LitColors {
    // The eye position: glam's Mat4 * Vec4, ((c0 x + c1 y) + c2 z) + c3 w.
    let (x, y, z, w) = (F::load(&obj.x), F::load(&obj.y), F::load(&obj.z), F::load(&obj.w));
    let mv = ls.modelview.to_cols_array();
    let row = |j: usize| F::splat(mv[j]).mul(x).add(F::splat(mv[4 + j]).mul(y)).add(F::splat(mv[8 + j]).mul(z)).add(F::splat(mv[12 + j]).mul(w));
    let e3 = V3 { x: row(0), y: row(1), z: row(2) };
    let ew = row(3);
    // x / 1 is x exactly: `shade_split` divides only where w is not 0 or 1.
    let divide = ew.ne(F::splat(0.0)).and(ew.ne(F::splat(1.0)));
    let v = V3::select(divide, e3.div(ew), e3);
    // The eye normal: glam's Mat3 * Vec3, then normalized or rescaled.
    let nm = ls.normal_matrix.to_cols_array();
    let (nx, ny, nz) = (F::load(&normals.x), F::load(&normals.y), F::load(&normals.z));
    let nrow = |j: usize| F::splat(nm[j]).mul(nx).add(F::splat(nm[3 + j]).mul(ny)).add(F::splat(nm[6 + j]).mul(nz));
    let e = V3 { x: nrow(0), y: nrow(1), z: nrow(2) };
    let n = if ls.normalize { e.normalize_or_zero() } else { e.scale(F::splat(ls.rescale)) };
    let front = shade_lanes(ls, &LaneMaterial::new(&m[0], tracked.map(|t| (t, 0))), v, n, k);
    let back = if ls.two_side { shade_lanes(ls, &LaneMaterial::new(&m[1], tracked.map(|t| (t, 1))), v, n.neg(), k) } else { front };
    let mut out = [[Vec4::ZERO; 4]; LANES];
    for (i, o) in out.iter_mut().enumerate().take(k) {
        *o = [front[0][i], back[0][i], front[1][i], back[1][i]];
    }
    out
}

/// `shade_split` per lane for eye positions `v` (already divided by w) and
/// eye normals `n`: the primary and secondary colours of each lane.
#[inline(always)]
fn shade_lanes(ls: &LightingSetup, m: &LaneMaterial, v: V3, n: V3, k: usize) -> [[Vec4; LANES]; 2] {
    let used = (1u32 << k) - 1;
    let zero = F::splat(0.0);
    let mut primary = m.emission.add(&m.ambient.mul_by(ls.model_ambient));
    let mut specular = C4::splat(Vec4::ZERO);
    for l in &ls.lights {
        let light = &l.light;
        let (vp, att) = if l.positional {
            let d = V3::splat(l.pos).sub(v);
            let dist = d.dot(d).sqrt();
            let [k0, k1, k2] = light.attenuation.map(F::splat);
            // k0 + k1 dist + k2 dist dist, in Rust's left-to-right order.
            let denom = k0.add(k1.mul(dist)).add(k2.mul(dist).mul(dist));
            let vp = V3::select(dist.gt(zero), d.div(dist), V3::splat(Vec3::ZERO));
            (vp, F::select(denom.gt(zero), F::splat(1.0).div(denom), F::splat(1.0)))
        } else {
            (V3::splat(l.pos), F::splat(1.0))
        };
        let kk = match l.spot {
            None => att,
            Some((dir, cos_cutoff)) => {
                // The spot factor is one libm `powf` per lane: scalar.
                let c = vp.neg().dot(V3::splat(dir)).get();
                let spot = c.map(|c| {
                    if c >= cos_cutoff {
                        if light.spot_exponent == 0.0 { 1.0 } else { c.max(0.0).powf(light.spot_exponent) }
                    } else {
                        0.0
                    }
                });
                att.mul(F::load(&spot))
            }
        };
        // `shade_split` skips a light whose att * spot is 0.
        let on = kk.ne(zero);
        let ndotl = n.dot(vp);
        let lit = on.and(ndotl.gt(zero));
        let mut c = m.ambient.mul_by(light.ambient);
        c.add_times(&m.diffuse.mul_by(light.diffuse), ndotl, lit);
        let lit_bits = lit.bits() & used;
        if lit_bits != 0 {
            let h = if !ls.local_viewer && !l.positional {
                // A directional light and an infinite viewer: the same
                // half vector for every vertex.
                V3::splat((l.pos + Vec3::Z).normalize_or_zero())
            } else {
                let eye_dir = if ls.local_viewer { v.neg().normalize_or_zero() } else { V3::splat(Vec3::Z) };
                vp.add(eye_dir).normalize_or_zero()
            };
            let mut p = [1.0; LANES];
            if m.shininess != 0.0 {
                let ndoth = n.dot(h).get();
                for (i, p) in p.iter_mut().enumerate() {
                    if lit_bits & (1 << i) != 0 {
                        *p = ndoth[i].max(0.0).powf(m.shininess);
                    }
                }
            }
            specular.add_times(&m.specular.mul_by(light.specular), F::load(&p).mul(kk), lit);
        }
        primary.add_times(&c, kk, on);
    }
    let alpha = m.alpha.map(|a| a.clamp(0.0, 1.0));
    if ls.separate_specular {
        [primary.clamp01().lanes(alpha), specular.clamp01().lanes([0.0; LANES])]
    } else {
        [primary.add(&specular).clamp01().lanes(alpha), [Vec4::ZERO; LANES]]
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::gl::lighting::Light;
    use glam::Mat4;

    struct Lcg(u64);
    impl Lcg {
        fn next(&mut self) -> f32 {
            self.0 = self.0.wrapping_mul(6364136223846793005).wrapping_add(1442695040888963407);
            ((self.0 >> 40) as f32) / (1u64 << 24) as f32
        }
        fn range(&mut self, a: f32, b: f32) -> f32 {
            a + (b - a) * self.next()
        }
        fn color(&mut self) -> Vec4 {
            Vec4::new(self.range(-0.2, 1.2), self.next(), self.next(), self.range(0.0, 1.2))
        }
    }

    fn random_light(r: &mut Lcg, i: usize) -> Light {
        let positional = r.next() < 0.6;
        Light {
            enabled: true,
            ambient: r.color(),
            diffuse: r.color(),
            specular: r.color(),
            position: Vec4::new(r.range(-3.0, 3.0), r.range(-3.0, 3.0), r.range(-3.0, 3.0), if positional { r.range(0.5, 2.0) } else { 0.0 }),
            spot_direction: Vec3::new(r.range(-1.0, 1.0), r.range(-1.0, 1.0), r.range(-1.0, 1.0)),
            spot_exponent: if i.is_multiple_of(2) { 0.0 } else { r.range(0.0, 30.0) },
            spot_cutoff: if r.next() < 0.5 { 180.0 } else { r.range(10.0, 90.0) },
            attenuation: [r.range(0.0, 1.0), r.range(0.0, 0.5), if r.next() < 0.5 { 0.0 } else { r.range(0.0, 0.2) }],
        }
    }

    fn random_material(r: &mut Lcg) -> Material {
        Material {
            ambient: r.color(),
            diffuse: r.color(),
            specular: r.color(),
            emission: if r.next() < 0.5 { Vec4::ZERO } else { r.color() },
            shininess: if r.next() < 0.2 { 0.0 } else { r.range(0.0, 128.0) },
        }
    }

    /// Every lane equals `eye_normal` + `shade_split` on its own vertex, bit
    /// for bit, over random lights (directional, positional, spot,
    /// attenuated), materials, matrices (some singular, some with w rows),
    /// flags, positions (some w = 0 or 1) and normals (some zero).
    #[test]
    fn lanes_match_shade_split() {
        let mut r = Lcg(12345);
        let mut lit_lanes = 0;
        for case in 0..20_000 {
            let nl = 1 + case % 3;
            let lights: Vec<Light> = (0..nl).map(|i| random_light(&mut r, i)).collect();
            let flags = [r.next() < 0.3, r.next() < 0.5, r.next() < 0.5, r.next() < 0.6, r.next() < 0.5];
            let mut mv = Mat4::from_cols_array(&std::array::from_fn(|_| r.range(-2.0, 2.0)));
            if case % 7 == 0 {
                mv = Mat4::from_translation(Vec3::new(r.range(-1.0, 1.0), 0.5, -4.0)) * Mat4::from_scale(Vec3::new(1.0, r.range(0.0, 2.0), 1.0));
            }
            if case % 11 == 0 {
                mv = Mat4::from_scale(Vec3::new(1.0, 0.0, 1.0));
            }
            let ls = LightingSetup::new(&lights, r.color(), flags, mv);
            let m = [random_material(&mut r), random_material(&mut r)];
            let mut obj = Positions::ORIGIN;
            let mut normals = Normals::ZERO;
            let k = 1 + case % LANES;
            for i in 0..LANES {
                let w = match i % 3 {
                    0 => 1.0,
                    1 => r.range(0.5, 2.0),
                    _ => if r.next() < 0.3 { 0.0 } else { 1.0 },
                };
                obj.set(i, [r.range(-2.0, 2.0), r.range(-2.0, 2.0), r.range(-2.0, 2.0), w]);
                let n = if r.next() < 0.05 { [0.0; 3] } else { [r.range(-1.5, 1.5), r.range(-1.5, 1.5), r.range(-1.5, 1.5)] };
                normals.set(i, n);
            }
            // GL_COLOR_MATERIAL in a third of the cases, every face and mode.
            let tracked = (case % 3 == 1).then(|| {
                let faces = [[true, false], [false, true], [true, true]][case / 3 % 3];
                let mode = [GL_EMISSION, GL_AMBIENT, GL_DIFFUSE, GL_SPECULAR, GL_AMBIENT_AND_DIFFUSE][case / 9 % 5];
                let mut t = Tracked { colors: [[0.0; LANES]; 4], faces, mode };
                for i in 0..LANES {
                    t.set(i, r.color().to_array());
                }
                t
            });
            let got = light_lanes(&ls, &m, tracked.as_ref(), &obj, &normals, k);
            for i in 0..k {
                let o = Vec4::new(obj.x[i], obj.y[i], obj.z[i], obj.w[i]);
                let eye = ls.modelview * o;
                let n = ls.eye_normal(Vec3::new(normals.x[i], normals.y[i], normals.z[i]));
                // The materials as glColor's `apply_color_material` leaves them.
                let mut m = m.clone();
                if let Some(t) = &tracked {
                    let c = Vec4::from_array(std::array::from_fn(|ch| t.colors[ch][i]));
                    for f in (0..2).filter(|&f| t.faces[f]) {
                        match t.mode {
                            GL_EMISSION => m[f].emission = c,
                            GL_AMBIENT => m[f].ambient = c,
                            GL_DIFFUSE => m[f].diffuse = c,
                            GL_SPECULAR => m[f].specular = c,
                            _ => (m[f].ambient, m[f].diffuse) = (c, c),
                        }
                    }
                }
                let f = ls.shade_split(&m[0], eye, n);
                let b = if ls.two_side { ls.shade_split(&m[1], eye, -n) } else { f };
                let want = [f.0, b.0, f.1, b.1];
                for (g, w) in got[i].iter().zip(want) {
                    let (g, w) = (g.to_array().map(f32::to_bits), w.to_array().map(f32::to_bits));
                    assert_eq!(g, w, "case {case} lane {i}");
                }
                lit_lanes += (want[0].truncate() != (m[0].emission + m[0].ambient * ls.model_ambient).truncate().clamp(Vec3::ZERO, Vec3::ONE)) as usize;
            }
            for o in &got[k..] {
                assert_eq!(*o, [Vec4::ZERO; 4]);
            }
        }
        // Most lanes are lit by something (the test is not of the ambient term alone).
        assert!(lit_lanes > 20_000, "{lit_lanes}");
    }
}
