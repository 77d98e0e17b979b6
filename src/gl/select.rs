//! Selection and feedback (GL 1.5 sections 5.2 and 5.3): glRenderMode,
//! glSelectBuffer, the name stack, glFeedbackBuffer, glPassThrough.
//!
//! In GL_SELECT and GL_FEEDBACK mode, primitives are clipped to the view
//! volume exactly (no guard band here: a hit means the primitive
//! intersects the clip volume), face-culled like rendered polygons, and
//! nothing reaches the framebuffer. Polygons arrive as the triangles
//! primitive assembly makes of them, so feedback reports each as a
//! GL_POLYGON_TOKEN with 3 vertices (as Mesa does).
//!
//! Feedback vertices carry texture unit 0's coordinates (after texgen and
//! the texture matrix). glBitmap, glDrawPixels and glCopyPixels draw
//! nothing in either mode; in feedback they report their token and the
//! current raster position as a vertex when it is valid (5.3), and glBitmap
//! still moves the raster position.
//!
//! The client's buffers are written as results arrive; the context keeps
//! only their pointers and sizes, as GL does.

use super::context::Context;
use super::enums::*;
use crate::render::clip::Plane;
use crate::render::setup::to_window;
use crate::render::signed_area;
use crate::render::ClipVertex;
use glam::Vec4;

pub const GL_RENDER: u32 = 0x1C00;
pub const GL_FEEDBACK: u32 = 0x1C01;
pub const GL_SELECT: u32 = 0x1C02;
pub const GL_2D: u32 = 0x0600;
pub const GL_3D: u32 = 0x0601;
pub const GL_3D_COLOR: u32 = 0x0602;
pub const GL_3D_COLOR_TEXTURE: u32 = 0x0603;
pub const GL_4D_COLOR_TEXTURE: u32 = 0x0604;
pub const GL_PASS_THROUGH_TOKEN: f32 = 0x0700 as f32;
pub const GL_POINT_TOKEN: f32 = 0x0701 as f32;
pub const GL_LINE_TOKEN: f32 = 0x0702 as f32;
pub const GL_POLYGON_TOKEN: f32 = 0x0703 as f32;
pub const GL_BITMAP_TOKEN: f32 = 0x0704 as f32;
pub const GL_DRAW_PIXEL_TOKEN: f32 = 0x0705 as f32;
pub const GL_COPY_PIXEL_TOKEN: f32 = 0x0706 as f32;
pub const GL_LINE_RESET_TOKEN: f32 = 0x0707 as f32;
/// GL_MAX_NAME_STACK_DEPTH.
pub const MAX_NAME_STACK_DEPTH: usize = 64;

pub struct SelectState {
    pub mode: u32,
    select_buf: *mut u32,
    select_size: usize,
    select_used: usize,
    hits: i32,
    overflow: bool,
    names: Vec<u32>,
    /// A hit since the last name-stack change: (min z, max z) in [0, 1].
    pending: Option<(f64, f64)>,
    feedback_buf: *mut f32,
    feedback_size: usize,
    feedback_type: u32,
    feedback_used: usize,
    feedback_overflow: bool,
}

impl SelectState {
    /// GL_SELECTION_BUFFER_POINTER and GL_FEEDBACK_BUFFER_POINTER: the
    /// client's buffers as last given (NULL initially).
    pub fn buffer_pointers(&self) -> (usize, usize) {
        (self.select_buf as usize, self.feedback_buf as usize)
    }

    /// GL_SELECTION_BUFFER_SIZE, GL_FEEDBACK_BUFFER_SIZE and
    /// GL_FEEDBACK_BUFFER_TYPE: as last given (0, 0, GL_2D initially).
    pub fn buffer_sizes(&self) -> (usize, usize, u32) {
        (self.select_size, self.feedback_size, self.feedback_type)
    }
}

impl Default for SelectState {
    fn default() -> Self {
        SelectState {
            mode: GL_RENDER,
            select_buf: std::ptr::null_mut(),
            select_size: 0,
            select_used: 0,
            hits: 0,
            overflow: false,
            names: Vec::new(),
            pending: None,
            feedback_buf: std::ptr::null_mut(),
            feedback_size: 0,
            feedback_type: GL_2D,
            feedback_used: 0,
            feedback_overflow: false,
        }
    }
}

impl SelectState {
    fn put_select(&mut self, v: u32) {
        if self.select_used < self.select_size {
            // SAFETY: glSelectBuffer's caller promised `size` writable values.
            unsafe { *self.select_buf.add(self.select_used) = v };
            self.select_used += 1;
        } else {
            self.overflow = true;
        }
    }

    /// Writes the pending hit record (name-stack changes and glRenderMode).
    fn flush_hit(&mut self) {
        let Some((zmin, zmax)) = self.pending.take() else { return };
        let scale = |z: f64| (z.clamp(0.0, 1.0) * 4294967295.0).round() as u32;
        let start = self.select_used;
        let names = self.names.clone();
        self.put_select(names.len() as u32);
        self.put_select(scale(zmin));
        self.put_select(scale(zmax));
        for n in names {
            self.put_select(n);
        }
        if !self.overflow {
            self.hits += 1;
        } else {
            self.select_used = start.min(self.select_used);
        }
    }

    fn put_feedback(&mut self, v: f32) {
        if self.feedback_used < self.feedback_size {
            // SAFETY: glFeedbackBuffer's caller promised `size` writable values.
            unsafe { *self.feedback_buf.add(self.feedback_used) = v };
            self.feedback_used += 1;
        } else {
            self.feedback_overflow = true;
        }
    }
}

/// The view volume exactly (no guard band: a hit means the primitive
/// meets the clip volume), plus w > 0 so window coordinates stay finite.
const VIEW_VOLUME: [Plane; 7] = [
    Plane { n: Vec4::new(1.0, 0.0, 0.0, 1.0), d: 0.0 },
    Plane { n: Vec4::new(-1.0, 0.0, 0.0, 1.0), d: 0.0 },
    Plane { n: Vec4::new(0.0, 1.0, 0.0, 1.0), d: 0.0 },
    Plane { n: Vec4::new(0.0, -1.0, 0.0, 1.0), d: 0.0 },
    Plane { n: Vec4::new(0.0, 0.0, 1.0, 1.0), d: 0.0 },
    Plane { n: Vec4::new(0.0, 0.0, -1.0, 1.0), d: 0.0 },
    crate::render::clip::FIXED_PLANES[2],
];

/// Clips a triangle, a segment or a point to the view volume and the user
/// clip planes with the renderer's own clippers.
fn clip_to_view_volume(verts: &[&ClipVertex], user: &[Plane]) -> Vec<ClipVertex> {
    let planes: Vec<Plane> = VIEW_VOLUME.iter().chain(user).copied().collect();
    match verts {
        [p] => {
            let keep = p.pos.is_finite() && planes.iter().all(|pl| pl.dist(&p.pos) >= 0.0);
            if keep { vec![**p] } else { Vec::new() }
        }
        [a, b] => crate::render::line::clip_segment(&planes, a, b).map_or(Vec::new(), |(a, b)| vec![a, b]),
        [a, b, c] => {
            let mut poly = crate::render::clip::Polygon::new();
            match crate::render::clip::clip_triangle(&planes, [a, b, c], &mut poly) {
                crate::render::clip::Outcome::Rejected => Vec::new(),
                crate::render::clip::Outcome::Inside => vec![**a, **b, **c],
                crate::render::clip::Outcome::Clipped => poly.verts,
            }
        }
        _ => Vec::new(),
    }
}

impl Context {
    pub fn render_mode(&mut self, mode: u32) -> i32 {
        if !matches!(mode, GL_RENDER | GL_SELECT | GL_FEEDBACK) {
            self.set_error(GL_INVALID_ENUM);
            return 0;
        }
        let s = &mut self.select;
        let result = match s.mode {
            GL_SELECT => {
                s.flush_hit();
                let r = if s.overflow { -1 } else { s.hits };
                s.hits = 0;
                s.select_used = 0;
                s.overflow = false;
                r
            }
            GL_FEEDBACK => {
                let r = if s.feedback_overflow { -1 } else { s.feedback_used as i32 };
                s.feedback_used = 0;
                s.feedback_overflow = false;
                r
            }
            _ => 0,
        };
        match mode {
            GL_SELECT if s.select_buf.is_null() => {
                self.set_error(GL_INVALID_OPERATION);
                return result;
            }
            GL_FEEDBACK if s.feedback_buf.is_null() => {
                self.set_error(GL_INVALID_OPERATION);
                return result;
            }
            _ => {}
        }
        s.mode = mode;
        result
    }

    pub fn select_buffer(&mut self, size: i32, buf: *mut u32) {
        if size < 0 {
            return self.set_error(GL_INVALID_VALUE);
        }
        if self.select.mode == GL_SELECT {
            return self.set_error(GL_INVALID_OPERATION);
        }
        self.select.select_buf = buf;
        self.select.select_size = if buf.is_null() { 0 } else { size as usize };
    }

    pub fn feedback_buffer(&mut self, size: i32, ty: u32, buf: *mut f32) {
        if !matches!(ty, GL_2D | GL_3D | GL_3D_COLOR | GL_3D_COLOR_TEXTURE | GL_4D_COLOR_TEXTURE) {
            return self.set_error(GL_INVALID_ENUM);
        }
        if size < 0 {
            return self.set_error(GL_INVALID_VALUE);
        }
        if self.select.mode == GL_FEEDBACK {
            return self.set_error(GL_INVALID_OPERATION);
        }
        let s = &mut self.select;
        s.feedback_buf = buf;
        s.feedback_size = if buf.is_null() { 0 } else { size as usize };
        s.feedback_type = ty;
    }

    /// glInitNames / glPushName / glPopName / glLoadName: `op` says which.
    pub fn name_stack(&mut self, op: NameOp) {
        if self.select.mode != GL_SELECT {
            return; // ignored outside selection mode
        }
        self.select.flush_hit();
        let depth = self.select.names.len();
        let error = match op {
            NameOp::Push(_) if depth >= MAX_NAME_STACK_DEPTH => GL_STACK_OVERFLOW,
            NameOp::Pop if depth == 0 => GL_STACK_UNDERFLOW,
            NameOp::Load(_) if depth == 0 => GL_INVALID_OPERATION,
            _ => GL_NO_ERROR,
        };
        if error != GL_NO_ERROR {
            return self.set_error(error);
        }
        let names = &mut self.select.names;
        match op {
            NameOp::Init => names.clear(),
            NameOp::Push(n) => names.push(n),
            NameOp::Pop => {
                names.pop();
            }
            NameOp::Load(n) => names[depth - 1] = n,
        }
    }

    pub fn pass_through(&mut self, token: f32) {
        if self.select.mode == GL_FEEDBACK {
            self.select.put_feedback(GL_PASS_THROUGH_TOKEN);
            self.select.put_feedback(token);
        }
    }

    pub fn name_stack_depth(&self) -> usize {
        self.select.names.len()
    }

    /// A primitive in selection or feedback mode: `kind` is the feedback
    /// token; `reset` marks the first segment of a line (LINE_RESET_TOKEN).
    pub fn select_primitive(&mut self, verts: &[&ClipVertex], kind: f32, reset: bool) {
        let user = &self.derived.render.clip_planes[crate::render::clip::FIXED_PLANES.len()..];
        let clipped = clip_to_view_volume(verts, user);
        if clipped.is_empty() || (verts.len() >= 3 && clipped.len() < 3) {
            return;
        }
        let rs = &self.derived.render;
        let win: Vec<_> = clipped.iter().map(|v| to_window(rs, v)).collect();
        // Face culling (3.5.1) applies: culled polygons are no hits.
        if verts.len() >= 3 && rs.facing(signed_area(&win) > 0.0).is_none() {
            return;
        }
        if self.select.mode == GL_SELECT {
            let (lo, hi) = win.iter().fold((f64::MAX, f64::MIN), |(lo, hi), w| (lo.min(w.z), hi.max(w.z)));
            let p = self.select.pending.get_or_insert((lo, hi));
            p.0 = p.0.min(lo);
            p.1 = p.1.max(hi);
            return;
        }
        let token = if kind == GL_LINE_TOKEN && reset { GL_LINE_RESET_TOKEN } else { kind };
        self.select.put_feedback(token);
        if kind == GL_POLYGON_TOKEN {
            self.select.put_feedback(win.len() as f32);
        }
        let ty = self.select.feedback_type;
        for (v, w) in clipped.iter().zip(&win) {
            let s = &mut self.select;
            s.put_feedback(w.x as f32);
            s.put_feedback(w.y as f32);
            if ty != GL_2D {
                s.put_feedback(w.z as f32);
            }
            if ty == GL_4D_COLOR_TEXTURE {
                s.put_feedback(v.pos.w);
            }
            if matches!(ty, GL_3D_COLOR | GL_3D_COLOR_TEXTURE | GL_4D_COLOR_TEXTURE) {
                for c in v.color.to_array() {
                    s.put_feedback(c);
                }
            }
            if matches!(ty, GL_3D_COLOR_TEXTURE | GL_4D_COLOR_TEXTURE) {
                for t in v.tex[0].to_array() {
                    s.put_feedback(t);
                }
            }
        }
    }

    /// glRasterPos and glWindowPos in selection mode: a valid raster
    /// position is a hit at its depth (5.2).
    pub fn raster_hit(&mut self) {
        if self.select.mode == GL_SELECT && self.raster.valid {
            let z = self.raster.pos[2] as f64;
            let p = self.select.pending.get_or_insert((z, z));
            p.0 = p.0.min(z);
            p.1 = p.1.max(z);
        }
    }

    /// glBitmap, glDrawPixels, glCopyPixels in feedback or selection mode
    /// (`token` says which): the feedback record of the raster position.
    pub fn pixel_primitive(&mut self, token: f32) {
        if self.select.mode != GL_FEEDBACK || !self.raster.valid {
            return;
        }
        let r = &self.raster;
        let ty = self.select.feedback_type;
        let mut vals = vec![token, r.pos[0], r.pos[1]];
        if ty != GL_2D {
            vals.push(r.pos[2]);
        }
        if ty == GL_4D_COLOR_TEXTURE {
            vals.push(r.pos[3]);
        }
        if matches!(ty, GL_3D_COLOR | GL_3D_COLOR_TEXTURE | GL_4D_COLOR_TEXTURE) {
            vals.extend(r.color);
        }
        if matches!(ty, GL_3D_COLOR_TEXTURE | GL_4D_COLOR_TEXTURE) {
            vals.extend(r.tex[0]);
        }
        for v in vals {
            self.select.put_feedback(v);
        }
    }

    /// Texture unit 0's coordinates for a feedback vertex when the vertex
    /// stage did not make them (unit 0 not texturing): the current ones
    /// with linear texgen and the texture matrix applied.
    pub fn feedback_texcoord(&self, obj: Vec4) -> Vec4 {
        let unit = &self.texture.units[0];
        let mut t = Vec4::from_array(self.current.tex_coords[0]);
        let dot = |p: [f64; 4], v: Vec4| (p[0] * v.x as f64 + p[1] * v.y as f64 + p[2] * v.z as f64 + p[3] * v.w as f64) as f32;
        for (k, g) in unit.gen.iter().enumerate() {
            if !g.enabled {
                continue;
            }
            match g.mode {
                super::texture::enums::GL_OBJECT_LINEAR => t[k] = dot(g.object_plane, obj),
                super::texture::enums::GL_EYE_LINEAR => t[k] = dot(g.eye_plane, self.derived.modelview * obj),
                // Sphere, normal and reflection maps need the vertex
                // stage's normal work: left as the current value here.
                _ => {}
            }
        }
        self.transform.textures[0].top().as_mat4() * t
    }
}

/// The name-stack commands.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum NameOp {
    Init,
    Push(u32),
    Pop,
    Load(u32),
}
