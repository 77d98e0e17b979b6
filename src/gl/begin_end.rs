//! glBegin/glEnd and primitive assembly (GL 1.5 sections 2.6 and 2.6.1):
//! vertices are transformed as they arrive and grouped into triangles by
//! the primitive mode, each with its provoking vertex for flat shading
//! (section 2.14.7, table 2.12: the last vertex of a triangle, strip or fan
//! triangle and of a quad; the first of a polygon).
//!
//! Points are drawn one by one; lines in pairs (GL_LINES), from each
//! vertex to the next (GL_LINE_STRIP) and back to the first at glEnd
//! (GL_LINE_LOOP). A segment's provoking vertex is its second (table
//! 2.12). The stipple counter is reset at glBegin and before each
//! GL_LINES segment, and runs on across a strip or loop (section 3.4.3).

use super::context::Context;
use super::enums::*;
use super::select;
use crate::render::light4::{self, Normals, Tracked};
use crate::render::vertex4::{self, Positions, Queue, LANES};
use crate::render::{self, ClipVertex};
use glam::Vec4;

thread_local! {
    /// The vertex buffer of the last primitive, kept for the next glBegin:
    /// programs that wrap each triangle in glBegin/glEnd then allocate
    /// nothing per primitive.
    static SPARE_VERTS: std::cell::Cell<Vec<ClipVertex>> = const { std::cell::Cell::new(Vec::new()) };
}

/// Assembly state between glBegin and glEnd.
pub struct Assembly {
    pub mode: u32,
    /// Vertices kept for the primitive being built (strips and fans keep
    /// two; polygons keep all).
    verts: Vec<ClipVertex>,
    /// Vertices seen since glBegin.
    count: usize,
    /// The line stipple counter s (section 3.4.3).
    stipple: u32,
    /// The current point's size after attenuation (GL_POINTS).
    point_size: f32,
    /// The batched path (`vertex_fast`) serves this primitive: a filled
    /// mode in render mode (not selection or feedback), lit or not,
    /// textured or not, fogged or not (only flat-shaded textured triangles
    /// with the colour sum are left out). `verts` then holds fixed slots
    /// the vertices are written into in place.
    fast: bool,
    /// With `fast`: unlit, untextured and fog-free, so a vertex needs only
    /// its position and the current colours.
    plain: bool,
    /// Filled triangles whose vertices are all inside the guard band go
    /// straight to setup (`render::draw_triangle`'s first case, decided
    /// once per primitive instead of per triangle).
    direct: bool,
    /// The glBegin's caller masked every floating-point exception: the
    /// entry points skip the guard until glEnd (`api::fpenv`).
    fp_trusted: bool,
    /// With `fast`: the object positions of the last `pending` vertices,
    /// whose attributes are already in their slots and whose positions
    /// are transformed and placed four at a time (`flush_vertices`).
    queue: Queue,
    pending: usize,
    /// With `fast`: the ring slot the next vertex takes (`ring_slot` of
    /// `count`, stepped per vertex rather than divided out), and the
    /// slots of the queued vertices, lane by lane (round 15: `vertex_fast`
    /// and `flush_vertices` each divided by RING).
    slot: usize,
    slots: [usize; LANES],
    /// With `fast`: lit, so a vertex's colours depend only on its
    /// position, its normal, the materials and (GL_COLOR_MATERIAL) its
    /// current colour; they are lit four at a time in `flush_vertices`
    /// (`render::light4`), normals and colours queued beside the
    /// positions. glMaterial and glColorMaterial flush the queue first.
    lit: bool,
    normals: Normals,
    /// With `lit` and GL_COLOR_MATERIAL on: the queued current colours.
    tracked: Option<Tracked>,
}

/// Stores a current value (a colour) as one 16-byte store (round 17):
/// the batched vertex path reads it with one 16-byte load, which a store
/// of the same size forwards; the narrower stores a plain assignment of
/// three components and a constant compiles to cannot be forwarded, and
/// the load waited for them to reach the cache (immediate_1m: a fifth of
/// glVertex2f's cycles, at the vertex after each glColor3f).
#[inline(always)]
pub(crate) fn store4(dst: &mut [f32; 4], v: Vec4) {
    #[cfg(all(target_arch = "x86_64", target_feature = "sse2"))]
    // SAFETY: `dst` is 16 writable bytes; SSE2 is enabled (cfg above).
    unsafe {
        std::arch::x86_64::_mm_storeu_ps(dst.as_mut_ptr(), v.into())
    }
    #[cfg(not(all(target_arch = "x86_64", target_feature = "sse2")))]
    {
        *dst = v.to_array();
    }
}

/// The batched path's ring of slots: vertex n of the primitive lives in
/// slot n % RING (a fan's vertices after the first in (n - 1) % RING, its
/// centre in slot RING). A multiple of 3 and 4, so a triangle's or
/// quad's vertices are consecutive slots, and large enough that the
/// queued vertices never overwrite one an unassembled triangle still
/// needs (at most LANES queued and 3 before them).
const RING: usize = 12;
const SLOTS: usize = RING + 1;
const _: () = assert!(RING.is_multiple_of(12) && RING >= LANES + 3);
// `vertex_fast` masks its lane index by LANES - 1.
const _: () = assert!(LANES.is_power_of_two());

/// The slot of vertex `n` of a batched primitive of mode `mode`.
#[inline(always)]
fn ring_slot(mode: u32, n: usize) -> usize {
    if mode == GL_TRIANGLE_FAN {
        if n == 0 { RING } else { (n - 1) % RING }
    } else {
        n % RING
    }
}

impl Context {
    pub fn begin(&mut self, mode: u32) {
        if mode > GL_POLYGON {
            return self.set_error(GL_INVALID_ENUM);
        }
        // Begin inside Begin is caught by the Begin/End rule (execute).
        self.validate();
        let mut verts = SPARE_VERTS.with(|s| s.take());
        verts.clear();
        if verts.capacity() < 4 {
            verts.reserve(4);
        }
        let rs = &self.derived.render;
        let filled = matches!(mode, GL_TRIANGLES | GL_TRIANGLE_STRIP | GL_TRIANGLE_FAN | GL_QUADS | GL_QUAD_STRIP);
        // Flat shading of textured triangles with the colour sum copies the
        // provoking vertex's secondary colour (`flat_secondary`): left to
        // the general path.
        let fast = filled
            && !(rs.flat && rs.color_sum && rs.texture.is_some())
            && self.select.mode == select::GL_RENDER
            && !rs.reference
            && self.vertex_batching;
        let direct = !rs.draw_rect.is_empty()
            && rs.cull != render::Cull::All
            && rs.polygon_mode == [GL_FILL; 2]
            && rs.smooth.polygon.is_none()
            && rs.clip_planes.len() == render::clip::FIXED_PLANES.len();
        if fast {
            // Every field the batched path does not write (texture
            // coordinates, fog, secondary colours) stays zero, as the
            // general path computes it under the same state.
            verts.resize(SLOTS, ClipVertex::ZERO);
        }
        let plain = self.derived.lighting.is_none() && self.texture.vertex.units.is_empty() && rs.texture.is_none() && rs.fog.is_none();
        let fp_trusted = self.fp_caller_masked;
        self.plain_vertex = fast && plain && fp_trusted && self.lists.compile_mode().is_none();
        let lit = fast && self.derived.lighting.is_some();
        let tracked = (lit && self.lighting.color_material).then(|| {
            let face = self.lighting.color_material_face;
            Tracked { colors: [[0.0; LANES]; 4], faces: [face != GL_BACK, face != GL_FRONT], mode: self.lighting.color_material_mode }
        });
        self.prim = Some(Assembly {
            mode,
            verts,
            count: 0,
            stipple: 0,
            point_size: 1.0,
            fast,
            plain,
            direct,
            fp_trusted,
            queue: Queue::ORIGIN,
            pending: 0,
            slot: ring_slot(mode, 0),
            slots: [0; LANES],
            lit,
            normals: Normals::ZERO,
            tracked,
        });
    }

    pub fn end(&mut self) {
        self.plain_vertex = false;
        self.flush_vertices();
        let Some(mut asm) = self.prim.take() else {
            return self.set_error(GL_INVALID_OPERATION);
        };
        if asm.mode == GL_LINE_LOOP && asm.count >= 2 {
            let (last, first) = (asm.verts[1], asm.verts[0]);
            self.line(&last, &first, &mut asm.stipple);
        }
        if asm.mode == GL_POLYGON && asm.verts.len() >= 3 {
            // A convex polygon as a fan; flat shading takes the first vertex.
            // Only the polygon's own edges are boundary edges (2.6.2).
            let v = &asm.verts;
            let n = v.len();
            for i in 1..n - 1 {
                let edges = [i == 1 && v[0].edge, v[i].edge, i + 1 == n - 1 && v[n - 1].edge];
                self.triangle([&v[0], &v[i], &v[i + 1]], 0, edges);
            }
        }
        SPARE_VERTS.with(|s| s.set(std::mem::take(&mut asm.verts)));
        // Binned triangles may stay pending across draw calls: the context
        // then shades them before anything touches the framebuffer
        // (`Context::sync_render`).
        if !self.defer_render {
            self.sync_render();
        }
    }

    /// Inside a primitive whose glBegin came from a caller that masked
    /// every floating-point exception (`api::fpenv`).
    #[inline(always)]
    pub fn fp_trusted(&self) -> bool {
        self.prim.as_ref().is_some_and(|a| a.fp_trusted)
    }

    /// glVertex: the vertex takes the current colour (section 2.7).
    /// Outside Begin/End a vertex has no effect.
    #[inline(always)]
    pub fn vertex(&mut self, p: [f32; 4]) {
        self.vertex_xyzw(p[0], p[1], p[2], p[3])
    }

    /// [`Context::vertex`] with the coordinates passed as four scalars:
    /// they arrive in registers. An array argument is passed through
    /// memory, written by the entry point as a few narrower stores and
    /// read here as one 16-byte load, which cannot be forwarded from them
    /// (a store-forwarding stall per vertex, about a tenth of the
    /// function's time in immediate_1m).
    ///
    /// The batched plain case (most immediate-mode vertices) is inlined
    /// into the entry points on its own; every other case is out of line
    /// ([`Context::vertex_other`]): beside them the plain case paid for
    /// their stack frame and shuffled the coordinates into the Vec4 only
    /// they read, about 30 instructions a vertex.
    #[inline(always)]
    pub fn vertex_xyzw(&mut self, x: f32, y: f32, z: f32, w: f32) {
        if self.plain_batch() {
            return self.vertex_fast::<true>([x, y, z, w]);
        }
        self.vertex_other(x, y, z, w)
    }

    /// [`Context::vertex_xyzw`] outside the batched plain case.
    #[inline(never)]
    fn vertex_other(&mut self, x: f32, y: f32, z: f32, w: f32) {
        let p = [x, y, z, w];
        let Some((mode, fast, plain)) = self.prim.as_ref().map(|a| (a.mode, a.fast, a.plain)) else { return };
        if fast {
            return if plain { self.vertex_fast::<true>(p) } else { self.vertex_fast::<false>(p) };
        }
        let obj = Vec4::from_array(p);
        let [color, back_color, secondary, back_secondary] = self.vertex_colors(obj);
        // No texture unit enabled: all zero, without the out-of-line call.
        let mut tex = if self.texture.vertex.units.is_empty() { [Vec4::ZERO; render::texture::MAX_UNITS] } else { self.vertex_texcoords(obj) };
        if self.select.mode == select::GL_FEEDBACK && !self.texture.vertex.units.iter().any(|u| u.unit == 0) {
            tex[0] = self.feedback_texcoord(obj);
        }
        let fog = self.vertex_fog(obj);
        let mut v = ClipVertex { pos: self.derived.mvp * obj, color, back_color, edge: self.current.edge_flag, tex, fog, secondary, back_secondary, inside: false, win: [0.0; 4], snapped: [0; 2] };
        v.place(&self.derived.render);
        if mode == GL_POINTS {
            let size = self.derived_point_size(obj);
            if let Some(asm) = self.prim.as_mut() {
                asm.point_size = size;
            }
        }
        self.assemble(v);
    }

    /// Is the open primitive on the batched path's plain case (what
    /// `vertex` sends to `vertex_fast::<true>`)?
    #[inline(always)]
    pub(crate) fn plain_batch(&self) -> bool {
        self.prim.as_ref().is_some_and(|a| a.fast && a.plain)
    }

    /// A vertex's primary and secondary colours, front and back (2.14,
    /// 3.9): the current colours, or lit. Shared by `vertex` and
    /// `vertex_fast`, so both paths compute the same bits.
    #[inline(always)]
    fn vertex_colors(&self, obj: Vec4) -> [Vec4; 4] {
        let sum_enabled = self.derived.render.color_sum;
        let (color, back_color, secondary, back_secondary) = match &self.derived.lighting {
            None => {
                let c = Vec4::from_array(self.current.color);
                let s = if sum_enabled { Vec4::from_array(self.current.secondary_color).truncate().extend(0.0) } else { Vec4::ZERO };
                (c, c, s, s)
            }
            Some(ls) => {
                // Lighting (2.14.1) in eye coordinates.
                let eye = ls.modelview * obj;
                let n = ls.eye_normal(glam::Vec3::from_array(self.current.normal));
                let m = &self.lighting.materials;
                let front = ls.shade_split(&m[0], eye, n);
                let back = if ls.two_side { ls.shade_split(&m[1], eye, -n) } else { front };
                (front.0, back.0, front.1, back.1)
            }
        };
        // Without texturing the colour sum can be made here exactly: both
        // colours interpolate linearly and the sum is clamped per fragment.
        if self.derived.render.texture.is_some() {
            [color, back_color, secondary, back_secondary]
        } else {
            [color + secondary, back_color + back_secondary, Vec4::ZERO, Vec4::ZERO]
        }
    }

    /// The fog coordinate (3.10): glFogCoord's value, or the eye-space
    /// distance, taken as |z_eye| as the spec allows; 0 without fog.
    #[inline(always)]
    fn vertex_fog(&self, obj: Vec4) -> f32 {
        match &self.derived.render.fog {
            None => 0.0,
            Some(f) if self.fog.coord_src == super::fog::GL_FOG_COORD => f.vertex_value(self.current.fog_coord),
            Some(f) => f.vertex_value((self.derived.modelview * obj).z.abs()),
        }
    }

    /// The batched vertex path for filled primitives (`Assembly::fast`):
    /// the attributes come from the functions `vertex` calls (so the same
    /// bits: colours, lighting, texture coordinates, fog), but the
    /// vertex is written field by field into its slot of the assembly's
    /// ring (no 224-byte temporary copied per vertex), its position is
    /// queued and transformed with three others (`flush_vertices`), and
    /// triangles whose vertices are inside the guard band go straight to
    /// setup.
    #[inline(always)]
    pub(crate) fn vertex_fast<const PLAIN: bool>(&mut self, p: [f32; 4]) {
        self.vertex_fast_colored::<PLAIN>(p, Vec4::from_array(self.current.color))
    }

    /// [`Context::vertex_fast`] with the current colour given (`current`,
    /// equal to `self.current.color`): a caller that has just set it
    /// (an array draw's colour array) passes it in a register, rather
    /// than the vertex reading it back from memory while its stores are
    /// still in flight (a store-forwarding stall per vertex, round 17:
    /// over half of arrays_1m's element loop cycles).
    #[inline(always)]
    pub(crate) fn vertex_fast_colored<const PLAIN: bool>(&mut self, p: [f32; 4], current: Vec4) {
        debug_assert_eq!(current.to_array().map(f32::to_bits), self.current.color.map(f32::to_bits));
        let obj = Vec4::from_array(p);
        // The attributes as `vertex` computes them (the same functions);
        // PLAIN (unlit, untextured, fog-free) skips the tests for what the
        // state cannot need.
        let lit = !PLAIN && self.prim.as_ref().is_some_and(|a| a.lit);
        let [color, back_color, secondary, back_secondary] = if PLAIN {
            let rs = &self.derived.render;
            let c = current;
            // `vertex_colors` without lighting or texturing.
            let s = if rs.color_sum { Vec4::from_array(self.current.secondary_color).truncate().extend(0.0) } else { Vec4::ZERO };
            [c + s, c + s, Vec4::ZERO, Vec4::ZERO]
        } else if lit {
            // Lit in `flush_vertices` with the three vertices queued
            // beside it.
            [Vec4::ZERO; 4]
        } else {
            self.vertex_colors(obj)
        };
        let textured = !PLAIN && !self.texture.vertex.units.is_empty();
        let tex = if textured { self.vertex_texcoords(obj) } else { [Vec4::ZERO; render::texture::MAX_UNITS] };
        let fog = if PLAIN { 0.0 } else { self.vertex_fog(obj) };
        let edge = self.current.edge_flag;
        let normal = self.current.normal;
        if PLAIN {
            let Context { prim, derived, fb, .. } = self;
            let Some(a) = prim.as_mut() else { return };
            return plain_vertex(a, &derived.mvp, &derived.render, fb, obj, color, edge);
        }
        let Some(a) = self.prim.as_mut() else { return };
        let (s, lane) = a.queue_vertex(obj);
        let v = &mut a.verts[s];
        v.color = color;
        v.back_color = back_color;
        v.edge = edge;
        // Fields this state leaves zero stay as `begin` zeroed them.
        v.secondary = secondary;
        v.back_secondary = back_secondary;
        if textured {
            v.tex = tex;
        }
        v.fog = fog;
        if lit {
            a.normals.set(lane, normal);
            if let Some(t) = &mut a.tracked {
                t.set(lane, current.to_array());
            }
        }
        if lane + 1 == LANES {
            self.flush_vertices();
        }
    }

    /// Transforms and places the batched path's queued vertices four at a
    /// time (`render::vertex4`: the bits `ClipVertex::place` gives), then
    /// assembles and draws, in order, the triangles they complete. Called
    /// when the queue is full, at glEnd, and before the context shades its
    /// batch (`sync_render`: a frame ended inside glBegin/glEnd).
    #[inline(never)]
    pub(crate) fn flush_vertices(&mut self) {
        let Some(a) = self.prim.as_mut() else { return };
        let k = a.pending;
        if k == 0 {
            return;
        }
        // Lanes from k on hold stale slots: nothing below reads past k.
        let slots = a.queued_slots();
        let rs = &self.derived.render;
        if a.lit {
            if let Some(ls) = &self.derived.lighting {
                let lit = light4::light_lanes(ls, &self.lighting.materials, a.tracked.as_ref(), &Positions::of(&a.queue), &a.normals, k);
                // `vertex_colors`' colour sum.
                let sum = rs.texture.is_none();
                for (&s, c) in slots.iter().zip(lit).take(k) {
                    let v = &mut a.verts[s];
                    if sum {
                        (v.color, v.back_color) = (c[0] + c[2], c[1] + c[3]);
                    } else {
                        (v.color, v.back_color, v.secondary, v.back_secondary) = (c[0], c[1], c[2], c[3]);
                    }
                }
            }
        }
        flush_queue(a, &self.derived.mvp, rs, &mut self.fb);
    }

    /// Lights and places the vertices queued on a lit batched primitive
    /// (called before glMaterial or glColorMaterial changes what they
    /// take; GL_COLOR_MATERIAL's own updates at glColor need not, as
    /// each queued vertex keeps its colour).
    pub(crate) fn flush_lit_vertices(&mut self) {
        if self.prim.as_ref().is_some_and(|a| a.lit) {
            self.flush_vertices();
        }
    }

    /// The point size after GL 1.4's distance attenuation and clamping
    /// (section 3.3). d is the eye-coordinate distance |Pe| the spec
    /// names, not |z_eye| (Mesa's, and piglit point-attenuation's, choice).
    /// Fading applies only with multisampling, which softgl does not have.
    fn derived_point_size(&self, obj: Vec4) -> f32 {
        let p = &self.point;
        let [a, b, c] = p.attenuation;
        let size = if [a, b, c] == [1.0, 0.0, 0.0] {
            p.size
        } else {
            let d = (self.derived.modelview * obj).truncate().length();
            let k = a + b * d + c * d * d;
            if k > 0.0 { p.size * (1.0 / k).sqrt() } else { p.size }
        };
        size.clamp(p.size_min, p.size_max.max(p.size_min))
    }

    /// Adds a vertex to the primitive being assembled. Only the vertex
    /// buffer is moved out while primitives are drawn (not the whole
    /// assembly state, moved out and back per vertex before); inlined into
    /// `vertex` so the new vertex is built where it is stored.
    #[inline(always)]
    fn assemble(&mut self, v: ClipVertex) {
        let Some(a) = self.prim.as_mut() else { return };
        let n = a.count;
        a.count += 1;
        // A triangle not yet complete: stored, nothing drawn (two of every
        // three vertices of GL_TRIANGLES).
        if a.mode == GL_TRIANGLES && a.verts.len() < 2 {
            a.verts.push(v);
            return;
        }
        let mut asm = Assembly { verts: std::mem::take(&mut a.verts), ..*a };
        self.assemble_into(&mut asm, n, v);
        if let Some(a) = self.prim.as_mut() {
            a.verts = asm.verts;
            a.stipple = asm.stipple;
        }
    }

    fn assemble_into(&mut self, asm: &mut Assembly, n: usize, v: ClipVertex) {
        match asm.mode {
            GL_TRIANGLES => {
                asm.verts.push(v);
                if asm.verts.len() == 3 {
                    let t = std::mem::take(&mut asm.verts);
                    self.triangle([&t[0], &t[1], &t[2]], 2, [t[0].edge, t[1].edge, t[2].edge]);
                    asm.verts = t;
                    asm.verts.clear();
                }
            }
            GL_TRIANGLE_STRIP => {
                // verts[n % 2] holds vertex n - 2 and the other slot n - 1:
                // each new vertex replaces the oldest, with no shifting.
                if n >= 2 {
                    let (old, prev) = (n % 2, 1 - n % 2);
                    // Odd triangles swap their first two vertices to keep
                    // the strip's orientation; the provoking vertex is the
                    // newest either way.
                    let t = if n.is_multiple_of(2) { [&asm.verts[old], &asm.verts[prev], &v] } else { [&asm.verts[prev], &asm.verts[old], &v] };
                    self.triangle(t, 2, [true; 3]);
                    asm.verts[old] = v;
                } else {
                    asm.verts.push(v);
                }
            }
            GL_TRIANGLE_FAN => {
                if n >= 2 {
                    self.triangle([&asm.verts[0], &asm.verts[1], &v], 2, [true; 3]);
                    asm.verts[1] = v;
                } else {
                    asm.verts.push(v);
                }
            }
            GL_QUADS => {
                asm.verts.push(v);
                if asm.verts.len() == 4 {
                    let q = std::mem::take(&mut asm.verts);
                    self.quad(&q[0], &q[1], &q[2], &q[3], &q[3], true);
                    asm.verts = q;
                    asm.verts.clear();
                }
            }
            GL_QUAD_STRIP => {
                if n >= 3 && n % 2 == 1 {
                    // Quad (v0, v1, v3, v2) in boundary order, split along
                    // v0-v3 as Mesa's softpipe does (the spec leaves the
                    // split open); v3, the last sent, provokes.
                    let (a, b, c) = (asm.verts[0], asm.verts[1], asm.verts[2]);
                    self.quad(&c, &a, &b, &v, &v, false);
                    asm.verts.clear();
                    asm.verts.push(c);
                    asm.verts.push(v);
                } else {
                    asm.verts.push(v);
                }
            }
            GL_POLYGON => asm.verts.push(v),
            GL_POINTS if self.select.mode != select::GL_RENDER => {
                self.select_primitive(&[&v], select::GL_POINT_TOKEN, false);
            }
            GL_POINTS => {
                render::point::draw_point(&self.derived.render, &mut self.fb, asm.point_size, &v);
            }
            GL_LINES => {
                if n % 2 == 1 {
                    asm.stipple = 0;
                    self.line(&asm.verts[0], &v, &mut asm.stipple);
                    asm.verts.clear();
                } else {
                    asm.verts.push(v);
                }
            }
            GL_LINE_STRIP => {
                if n >= 1 {
                    self.line(&asm.verts[0], &v, &mut asm.stipple);
                    asm.verts[0] = v;
                } else {
                    asm.verts.push(v);
                }
            }
            GL_LINE_LOOP => {
                // verts[0]: the first vertex; verts[1]: the latest.
                if n >= 1 {
                    self.line(&asm.verts[1], &v, &mut asm.stipple);
                    asm.verts[1] = v;
                } else {
                    asm.verts.push(v);
                    asm.verts.push(v);
                }
            }
            _ => {}
        }
    }

    /// One line segment; flat shading takes `b`'s colour.
    fn line(&mut self, a: &ClipVertex, b: &ClipVertex, stipple: &mut u32) {
        if self.select.mode != select::GL_RENDER {
            // The first segment of a strip or of each GL_LINES pair resets
            // the stipple: feedback marks it with GL_LINE_RESET_TOKEN.
            let reset = *stipple == 0;
            *stipple += 1;
            return self.select_primitive(&[a, b], select::GL_LINE_TOKEN, reset);
        }
        let l = &self.line;
        let lp = render::line::LineParams {
            width: l.width,
            stipple: if l.stipple { Some((l.stipple_repeat as u32, l.stipple_pattern)) } else { None },
        };
        render::line::draw_line(&self.derived.render, &mut self.fb, &lp, a, b, b.color, stipple);
    }

    /// A quad in boundary order (a, b, c, d), split into (a, b, d) and
    /// (b, c, d); flat shading takes `provoking`'s colour for both. The
    /// diagonal is never a boundary edge; the others carry the vertices'
    /// edge flags for GL_QUADS (`flags`) and are all boundary in strips.
    #[allow(clippy::too_many_arguments)]
    fn quad(&mut self, a: &ClipVertex, b: &ClipVertex, c: &ClipVertex, d: &ClipVertex, provoking: &ClipVertex, flags: bool) {
        let f = |v: &ClipVertex| !flags || v.edge;
        if self.select.mode != select::GL_RENDER {
            self.select_primitive(&[a, b, d], select::GL_POLYGON_TOKEN, false);
            return self.select_primitive(&[b, c, d], select::GL_POLYGON_TOKEN, false);
        }
        let flat = [provoking.color, provoking.back_color];
        let rs = &self.derived.render;
        match flat_secondary(rs, [a, b, c, d], provoking) {
            Some([a2, b2, c2, d2]) => {
                render::draw_triangle(rs, &mut self.fb, [&a2, &b2, &d2], flat, [f(a), false, f(d)]);
                render::draw_triangle(rs, &mut self.fb, [&b2, &c2, &d2], flat, [f(b), f(c), false]);
            }
            None => {
                render::draw_triangle(rs, &mut self.fb, [a, b, d], flat, [f(a), false, f(d)]);
                render::draw_triangle(rs, &mut self.fb, [b, c, d], flat, [f(b), f(c), false]);
            }
        }
    }

    /// One triangle; `edges[i]` flags the edge from v[i] to v[i + 1].
    fn triangle(&mut self, v: [&ClipVertex; 3], provoking: usize, edges: [bool; 3]) {
        if self.select.mode != select::GL_RENDER {
            return self.select_primitive(&v, select::GL_POLYGON_TOKEN, false);
        }
        let flat = [v[provoking].color, v[provoking].back_color];
        match flat_secondary(&self.derived.render, v, v[provoking]) {
            Some(w) => render::draw_triangle(&self.derived.render, &mut self.fb, [&w[0], &w[1], &w[2]], flat, edges),
            None => render::draw_triangle(&self.derived.render, &mut self.fb, v, flat, edges),
        }
    }
}

impl Assembly {
    /// The queued vertices' slots, each read alone. Round 27: `slots`
    /// is written a lane at a time (`queue_vertex`), and copied as an
    /// array it was read back as two 16-byte loads, each spanning two of
    /// those 8-byte stores: a failed store forwarding per flush (perf: a
    /// quarter to a half of `plain_flush`'s samples in arrays_1m and
    /// spheres_l). Volatile reads are not merged.
    #[inline(always)]
    fn queued_slots(&self) -> [usize; LANES] {
        // SAFETY: reads of initialized array elements through a reference.
        std::array::from_fn(|i| unsafe { std::ptr::read_volatile(&self.slots[i]) })
    }

    /// Gives a batched primitive's next vertex its ring slot and queues
    /// its object position; returns the slot (for its attributes) and its
    /// lane in the queue. The caller flushes the queue when the lane is
    /// the last (`LANES - 1`).
    #[inline(always)]
    fn queue_vertex(&mut self, obj: Vec4) -> (usize, usize) {
        let s = self.slot;
        debug_assert_eq!(s, ring_slot(self.mode, self.count));
        self.count += 1;
        // After a fan's centre (slot RING) comes slot 0, as after RING - 1.
        self.slot = if s + 1 >= RING { 0 } else { s + 1 };
        // The position waits for three more (`flush_vertices`); nothing
        // a vertex's position feeds (assembly, setup) can be observed
        // before glEnd except through it.
        // `pending` is below LANES here (the queue is flushed when full):
        // the mask only lets the lane indices go unchecked.
        debug_assert!(self.pending < LANES);
        // Round 28: `pending` read alone (volatile): LLVM otherwise loads
        // `count` and `pending` as one 16-byte vector, which cannot take
        // its data from the flush's 8-byte store of `pending` while that
        // store waits in the store buffer behind the records' stores.
        // SAFETY: a reference to an initialized usize.
        let lane = unsafe { std::ptr::read_volatile(&self.pending) } & (LANES - 1);
        self.queue.set(lane, obj);
        self.slots[lane] = s;
        self.pending = lane + 1;
        (s, lane)
    }
}

/// One vertex of a batched plain primitive (`Context::vertex_fast::<true>`):
/// `color` is its primary colour with the colour sum added, front and
/// back alike.
#[inline(always)]
fn plain_vertex(a: &mut Assembly, mvp: &glam::Mat4, rs: &render::RenderState, fb: &mut crate::framebuffer::Framebuffer, obj: Vec4, color: Vec4, edge: bool) {
    let (s, lane) = a.queue_vertex(obj);
    let v = &mut a.verts[s];
    v.color = color;
    v.back_color = color;
    v.edge = edge;
    if lane + 1 == LANES {
        plain_flush(a, mvp, rs, fb);
    }
}

/// `Context::flush_vertices` for an unlit batched primitive.
#[inline(never)]
fn plain_flush(a: &mut Assembly, mvp: &glam::Mat4, rs: &render::RenderState, fb: &mut crate::framebuffer::Framebuffer) {
    debug_assert!(!a.lit);
    flush_queue(a, mvp, rs, fb);
}

/// Transforms and places the queued positions of `a` (lit already if
/// lit), empties the queue, then assembles and draws, in order, the
/// triangles they complete.
#[inline(always)]
fn flush_queue(a: &mut Assembly, mvp: &glam::Mat4, rs: &render::RenderState, fb: &mut crate::framebuffer::Framebuffer) {
    let k = a.pending;
    if k == 0 {
        return;
    }
    a.pending = 0;
    let n0 = a.count - k;
    // Lanes from k on hold stale slots: nothing below reads past k.
    let slots = a.queued_slots();
    vertex4::transform_place(mvp, rs, &a.queue, k, &mut a.verts, slots);
    // One loop per mode: the assembly's choices fold away. Whether
    // setup bins is the same for every triangle of the flush (binning
    // changes neither the state nor the framebuffer's draw buffers).
    let to = Direct { on: a.direct, bin: render::setup::binned_here(rs, fb) };
    match a.mode {
        GL_TRIANGLES => assemble_batch::<GL_TRIANGLES>(rs, fb, a, to, n0, k, slots),
        GL_TRIANGLE_STRIP => assemble_batch::<GL_TRIANGLE_STRIP>(rs, fb, a, to, n0, k, slots),
        GL_TRIANGLE_FAN => assemble_batch::<GL_TRIANGLE_FAN>(rs, fb, a, to, n0, k, slots),
        GL_QUADS => assemble_batch::<GL_QUADS>(rs, fb, a, to, n0, k, slots),
        _ => assemble_batch::<GL_QUAD_STRIP>(rs, fb, a, to, n0, k, slots),
    }
}

/// The slot `d` places before `slot` on the ring (not for a fan's centre).
#[inline(always)]
fn ring_back(slot: usize, d: usize) -> usize {
    if slot >= d { slot - d } else { slot + RING - d }
}

/// `assemble_placed` for the `k` vertices from `n0`, in `slots`, of a
/// primitive of mode MODE. Round 27: while binning, the triangles of a
/// strip's, fan's or quad strip's flush whose vertices are all inside the
/// guard band are binned four at a time (`render::bin4`), in order with
/// the others.
#[inline(always)]
fn assemble_batch<const MODE: u32>(rs: &render::RenderState, fb: &mut crate::framebuffer::Framebuffer, a: &Assembly, to: Direct, n0: usize, k: usize, slots: [usize; LANES]) {
    // A strip, fan or quad strip completes four triangles a flush;
    // separate triangles and quads at most two, too few to pay for the
    // lanes (arrays_1m, 2 threads: 3 % slower grouped).
    let four = matches!(MODE, GL_TRIANGLE_STRIP | GL_TRIANGLE_FAN | GL_QUAD_STRIP);
    if four && to.on && to.bin && render::bin4::available() {
        let mut out = Grouped { rs, fb, group: render::bin4::Group::new(&a.verts[0]) };
        for (i, &slot) in slots.iter().enumerate().take(k) {
            assemble_placed::<MODE, _>(a, n0 + i, slot, &mut out);
        }
        out.group.bin(rs, out.fb);
    } else {
        let mut out = Draw { rs, fb, direct: to };
        for (i, &slot) in slots.iter().enumerate().take(k) {
            assemble_placed::<MODE, _>(a, n0 + i, slot, &mut out);
        }
    }
}

/// How the batched path's triangles whose vertices are all inside the
/// guard band enter setup, decided once per flush: straight to setup
/// (`on`, `Assembly::direct`), and there to the binning path (`bin`,
/// `setup::binned_here`: round 15, the test `setup::triangle_placed`
/// makes per triangle).
#[derive(Clone, Copy)]
struct Direct {
    on: bool,
    bin: bool,
}

/// Where [`assemble_placed`] sends the triangles it forms: `v` in
/// order, `provoking` giving the flat colour, `edges` the edge flags
/// (read only by the general path, `render::draw_triangle`: round 17,
/// read beside `inside`, the newest vertex's two flags were loaded as
/// one word over two separate byte stores, a store-forwarding stall per
/// triangle).
trait Triangles<'a> {
    fn flat(&mut self, v: [&'a ClipVertex; 3], provoking: &'a ClipVertex, edges: impl Fn() -> [bool; 3]);

    /// A triangle whose vertex `v[provoking]` gives the flat colour.
    #[inline(always)]
    fn fill(&mut self, v: [&'a ClipVertex; 3], provoking: usize, edges: impl Fn() -> [bool; 3]) {
        self.flat(v, v[provoking], edges)
    }
}

/// The triangles the batched path's vertex `n` (placed, in `slot`)
/// completes, as `assemble_into` forms them: the same vertices, order,
/// provoking vertex and edge flags.
#[inline(always)]
fn assemble_placed<'a, const MODE: u32, T: Triangles<'a>>(a: &'a Assembly, n: usize, slot: usize, out: &mut T) {
    let t = &a.verts;
    // Vertex m <= n (m >= 1 in a fan): its slot counted back along the
    // ring (a fan's vertices after its centre are consecutive too).
    let ring = |m: usize| ring_back(slot, n - m);
    match MODE {
        GL_TRIANGLES => {
            // Triangles start at slots that are multiples of 3.
            if slot % 3 == 2 {
                let (s0, s1) = (slot - 2, slot - 1);
                out.fill([&t[s0], &t[s1], &t[slot]], 2, || [t[s0].edge, t[s1].edge, t[slot].edge]);
            }
        }
        GL_TRIANGLE_STRIP => {
            if n >= 2 {
                let (old, prev) = (ring(n - 2), ring(n - 1));
                // Odd triangles swap their first two vertices (as in
                // `assemble_into`); the newest provokes.
                let v = if n.is_multiple_of(2) { [&t[old], &t[prev], &t[slot]] } else { [&t[prev], &t[old], &t[slot]] };
                out.fill(v, 2, || [true; 3]);
            }
        }
        GL_TRIANGLE_FAN => {
            if n >= 2 {
                out.fill([&t[RING], &t[ring(n - 1)], &t[slot]], 2, || [true; 3]);
            }
        }
        GL_QUADS => {
            // Quads start at slots that are multiples of 4.
            if slot % 4 == 3 {
                // `quad(q0, q1, q2, q3)` with q3 provoking.
                let (q0, q1, q2) = (slot - 3, slot - 2, slot - 1);
                let e = |v: &ClipVertex| v.edge;
                out.fill([&t[q0], &t[q1], &t[slot]], 2, || [e(&t[q0]), false, e(&t[slot])]);
                out.flat([&t[q1], &t[q2], &t[slot]], &t[slot], || [e(&t[q1]), e(&t[q2]), false]);
            }
        }
        _ => {
            // GL_QUAD_STRIP: as `assemble_into`, the quad
            // (v[n-1], v[n-3], v[n-2], v[n]) split along v[n-1]-v[n].
            if n >= 3 && n % 2 == 1 {
                let (a3, b2, c1) = (ring(n - 3), ring(n - 2), ring(n - 1));
                out.fill([&t[c1], &t[a3], &t[slot]], 2, || [true, false, true]);
                out.flat([&t[a3], &t[b2], &t[slot]], &t[slot], || [true, true, false]);
            }
        }
    }
}

/// [`Triangles`] drawing each triangle at once (`fill_flat`).
struct Draw<'r> {
    rs: &'r render::RenderState,
    fb: &'r mut crate::framebuffer::Framebuffer,
    direct: Direct,
}

impl<'a> Triangles<'a> for Draw<'_> {
    #[inline(always)]
    fn flat(&mut self, v: [&'a ClipVertex; 3], provoking: &'a ClipVertex, edges: impl Fn() -> [bool; 3]) {
        fill_flat(self.rs, self.fb, self.direct, v, provoking, edges)
    }
}

/// [`Triangles`] while binning with `render::bin4`: a triangle inside the
/// guard band joins the group; any other is drawn by the general path
/// after the group before it is binned.
struct Grouped<'a, 'r> {
    rs: &'r render::RenderState,
    fb: &'r mut crate::framebuffer::Framebuffer,
    group: render::bin4::Group<'a>,
}

impl<'a> Triangles<'a> for Grouped<'a, '_> {
    #[inline(always)]
    fn flat(&mut self, v: [&'a ClipVertex; 3], provoking: &'a ClipVertex, edges: impl Fn() -> [bool; 3]) {
        if v[0].inside & v[1].inside & v[2].inside {
            self.group.push(self.rs, self.fb, v, provoking);
        } else {
            self.group.bin(self.rs, self.fb);
            render::draw_triangle(self.rs, self.fb, v, [provoking.color, provoking.back_color], edges())
        }
    }
}

/// `render::draw_triangle` for a triangle with no flat secondary colour to
/// copy (`Assembly::fast` leaves those out), entering setup at once when `direct` and every vertex
/// is inside the guard band: the decision `draw_triangle` would take.
#[inline(always)]
fn fill_flat(rs: &render::RenderState, fb: &mut crate::framebuffer::Framebuffer, direct: Direct, v: [&ClipVertex; 3], provoking: &ClipVertex, edges: impl Fn() -> [bool; 3]) {
    let flat = [provoking.color, provoking.back_color];
    if direct.on && v[0].inside & v[1].inside & v[2].inside {
        if direct.bin {
            render::setup::bin_placed(rs, fb, v, flat)
        } else {
            render::setup::triangle_placed(rs, fb, v, flat)
        }
    } else {
        render::draw_triangle(rs, fb, v, flat, edges())
    }
}

/// Flat shading gives every fragment the provoking vertex's secondary
/// colour as well as its primary (section 2.14.7). Only textured
/// fragments interpolate the secondary colour (the colour sum comes after
/// texturing, render::setup); for them the vertices are copied with the
/// provoking vertex's secondary colours. None when nothing needs it.
fn flat_secondary<const N: usize>(rs: &render::RenderState, v: [&ClipVertex; N], provoking: &ClipVertex) -> Option<[ClipVertex; N]> {
    if !(rs.flat && rs.color_sum && rs.texture.is_some()) {
        return None;
    }
    Some(v.map(|x| ClipVertex { secondary: provoking.secondary, back_secondary: provoking.back_secondary, ..*x }))
}
