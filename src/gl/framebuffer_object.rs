//! Framebuffer objects (EXT_framebuffer_object, and ARB_framebuffer_object's
//! additions for a compatibility context: separate draw and read bindings,
//! DEPTH_STENCIL_ATTACHMENT, FramebufferTextureLayer; glBlitFramebuffer is
//! in `blit`): framebuffer and renderbuffer objects, attachments, the
//! completeness rules of section 4.4.4 and the queries of 6.1.
//!
//! Design: rendering keeps writing `Context::fb`, an ordinary softgl
//! framebuffer (RGBA8 colour, 24-bit depth, 8-bit stencil). Binding a
//! framebuffer object parks the window's framebuffer (`FboState::parked`,
//! which `winsys::bound` exchanges with the drawable instead of `fb`) and
//! puts in its place a *staging* framebuffer loaded from the attached
//! images. What was drawn is written back to the attached texture levels
//! and renderbuffers ("store") before anything else can look at them:
//! when the binding changes, before a texture image command or
//! glGetTexImage, before an attachment changes. Staging rather than
//! rendering into texture storage directly keeps one pipeline for every
//! internal format (texture storage is RGBA8 or f32 per format) and keeps
//! the deferred tile renderer unaware of render targets: pending triangles
//! are shaded (`sync_render`) before any switch.
//!
//! Store writes back only the pixels that differ from what was loaded
//! (`snapshot`), so texels nothing drew keep their full precision (float
//! and 16-bit textures pass through an 8-bit staging buffer only where
//! rendering touched them). Renderbuffers keep the staging formats.
//!
//! Framebuffer objects are per context, as ARB_framebuffer_object says;
//! renderbuffers are shared within a share group (`share`). One colour
//! attachment (MAX_COLOR_ATTACHMENTS 1);
//! no multisampling (MAX_SAMPLES 0).

use super::context::Context;
use super::enums::*;
use super::get::Value;
use super::texture::enums::{GL_LINEAR, GL_TEXTURE_RECTANGLE};
use super::texture::image::{internal_format, is_depth_stencil};
use super::texture::MAX_LEVELS;
use super::validate::DIRTY_ALL;
use crate::framebuffer::{Config, Framebuffer, DEPTH_MAX, MAX_SIZE};
use crate::render::texture::{to_unorm8, Base, Image, Texels, UNORM8};
use super::names::Reserved;
use std::collections::HashMap;
use std::sync::{Arc, Mutex, MutexGuard};

pub const GL_INVALID_FRAMEBUFFER_OPERATION: u32 = 0x0506;
pub const GL_FRAMEBUFFER: u32 = 0x8D40;
pub const GL_RENDERBUFFER: u32 = 0x8D41;
pub const GL_READ_FRAMEBUFFER: u32 = 0x8CA8;
pub const GL_DRAW_FRAMEBUFFER: u32 = 0x8CA9;
pub const GL_FRAMEBUFFER_BINDING: u32 = 0x8CA6;
pub const GL_RENDERBUFFER_BINDING: u32 = 0x8CA7;
pub const GL_READ_FRAMEBUFFER_BINDING: u32 = 0x8CAA;
pub const GL_MAX_COLOR_ATTACHMENTS: u32 = 0x8CDF;
pub const GL_MAX_RENDERBUFFER_SIZE: u32 = 0x84E8;
pub const GL_MAX_SAMPLES: u32 = 0x8D57;
pub const GL_COLOR_ATTACHMENT0: u32 = 0x8CE0;
pub const GL_COLOR_ATTACHMENT15: u32 = 0x8CEF;
pub const GL_DEPTH_ATTACHMENT: u32 = 0x8D00;
pub const GL_STENCIL_ATTACHMENT: u32 = 0x8D20;
pub const GL_DEPTH_STENCIL_ATTACHMENT: u32 = 0x821A;
pub const GL_FRAMEBUFFER_COMPLETE: u32 = 0x8CD5;
pub const GL_FRAMEBUFFER_INCOMPLETE_ATTACHMENT: u32 = 0x8CD6;
pub const GL_FRAMEBUFFER_INCOMPLETE_MISSING_ATTACHMENT: u32 = 0x8CD7;
pub const GL_FRAMEBUFFER_INCOMPLETE_DIMENSIONS: u32 = 0x8CD9;
pub const GL_FRAMEBUFFER_INCOMPLETE_FORMATS: u32 = 0x8CDA;
pub const GL_FRAMEBUFFER_INCOMPLETE_DRAW_BUFFER: u32 = 0x8CDB;
pub const GL_FRAMEBUFFER_INCOMPLETE_READ_BUFFER: u32 = 0x8CDC;
pub const GL_FRAMEBUFFER_UNSUPPORTED: u32 = 0x8CDD;
pub const GL_FRAMEBUFFER_ATTACHMENT_OBJECT_TYPE: u32 = 0x8CD0;
pub const GL_FRAMEBUFFER_ATTACHMENT_OBJECT_NAME: u32 = 0x8CD1;
pub const GL_FRAMEBUFFER_ATTACHMENT_TEXTURE_LEVEL: u32 = 0x8CD2;
pub const GL_FRAMEBUFFER_ATTACHMENT_TEXTURE_CUBE_MAP_FACE: u32 = 0x8CD3;
pub const GL_FRAMEBUFFER_ATTACHMENT_TEXTURE_LAYER: u32 = 0x8CD4;
pub const GL_FRAMEBUFFER_ATTACHMENT_COLOR_ENCODING: u32 = 0x8210;
pub const GL_FRAMEBUFFER_ATTACHMENT_COMPONENT_TYPE: u32 = 0x8211;
pub const GL_FRAMEBUFFER_ATTACHMENT_RED_SIZE: u32 = 0x8212;
pub const GL_FRAMEBUFFER_ATTACHMENT_STENCIL_SIZE: u32 = 0x8217;
pub const GL_FRAMEBUFFER_DEFAULT: u32 = 0x8218;
pub const GL_RENDERBUFFER_SAMPLES: u32 = 0x8CAB;
pub const GL_RENDERBUFFER_WIDTH: u32 = 0x8D42;
pub const GL_RENDERBUFFER_HEIGHT: u32 = 0x8D43;
pub const GL_RENDERBUFFER_INTERNAL_FORMAT: u32 = 0x8D44;
pub const GL_RENDERBUFFER_RED_SIZE: u32 = 0x8D50;
pub const GL_RENDERBUFFER_STENCIL_SIZE: u32 = 0x8D55;
pub const GL_STENCIL_INDEX1: u32 = 0x8D46;
pub const GL_STENCIL_INDEX4: u32 = 0x8D47;
pub const GL_STENCIL_INDEX8: u32 = 0x8D48;
pub const GL_STENCIL_INDEX16: u32 = 0x8D49;
const GL_UNSIGNED_NORMALIZED: u32 = 0x8C17;
const GL_TEXTURE_CUBE_MAP_POSITIVE_X: u32 = 0x8515;
const GL_TEXTURE_CUBE_MAP_NEGATIVE_Z: u32 = 0x851A;

/// How many colour attachment points there are.
pub const MAX_COLOR_ATTACHMENTS: u32 = 1;

/// What an attachment point holds.
#[derive(Clone, Debug, PartialEq, Eq, Default)]
pub enum Attachment {
    #[default]
    None,
    /// A texture image: name, image target (the cube face for cube maps),
    /// level, and the slice of a 3D texture.
    Texture { name: u32, target: u32, level: i32, layer: i32 },
    Renderbuffer(RbRef),
}

/// A renderbuffer object. The share group's name table and every
/// attachment point hold it by reference, so glDeleteRenderbuffers frees
/// the name at once while the image lives on in the framebuffers it is
/// still attached to (any context's, bound or not: only the current
/// context's bound framebuffers detach it), until they let it go. Access
/// is serialized by the share group's lock (`share`); the mutex is never
/// contended.
pub type RbObject = Arc<Mutex<Renderbuffer>>;

/// An attached renderbuffer: the name it was attached by (what
/// FRAMEBUFFER_ATTACHMENT_OBJECT_NAME reports) and the object itself.
#[derive(Clone, Debug)]
pub struct RbRef {
    pub name: u32,
    pub obj: RbObject,
}

impl PartialEq for RbRef {
    fn eq(&self, o: &Self) -> bool {
        Arc::ptr_eq(&self.obj, &o.obj)
    }
}
impl Eq for RbRef {}

/// The renderbuffer behind a reference (a poisoned lock still holds
/// valid pixels: nothing panics while holding it).
fn rb(o: &RbObject) -> MutexGuard<'_, Renderbuffer> {
    o.lock().unwrap_or_else(|e| e.into_inner())
}

/// A framebuffer object: its attachments and its draw and read buffers.
#[derive(Clone, Debug)]
pub struct FramebufferObject {
    pub color: Attachment,
    pub depth: Attachment,
    pub stencil: Attachment,
    pub draw_buffer: u32,
    pub read_buffer: u32,
}

impl Default for FramebufferObject {
    fn default() -> Self {
        FramebufferObject { color: Attachment::None, depth: Attachment::None, stencil: Attachment::None, draw_buffer: GL_COLOR_ATTACHMENT0, read_buffer: GL_COLOR_ATTACHMENT0 }
    }
}

/// A renderbuffer: storage in the staging framebuffer's own formats.
#[derive(Clone, Debug, Default)]
pub struct Renderbuffer {
    pub internal_format: u32,
    pub width: i32,
    pub height: i32,
    pub kind: RbKind,
    pub color: Vec<[u8; 4]>,
    pub depth: Vec<u32>,
    pub stencil: Vec<u8>,
}

/// What a renderbuffer's internal format stores.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub enum RbKind {
    #[default]
    None,
    Color(Base),
    Depth,
    Stencil,
    DepthStencil,
}

/// The renderbuffer formats (RenderbufferStorage's internalformat).
fn renderbuffer_kind(f: u32) -> Option<RbKind> {
    match f {
        GL_STENCIL_INDEX | GL_STENCIL_INDEX1 | GL_STENCIL_INDEX4 | GL_STENCIL_INDEX8 | GL_STENCIL_INDEX16 => Some(RbKind::Stencil),
        _ if is_depth_stencil(f) => Some(RbKind::DepthStencil),
        // Compressed formats are textures only.
        0x84E9..=0x84EE | 1..=4 => None,
        _ => internal_format(f).map(|i| if i.base == Base::Depth { RbKind::Depth } else { RbKind::Color(i.base) }),
    }
}

/// Pixels of the staging framebuffer as loaded, to find what drawing
/// changed (see the module comment).
#[derive(Default)]
struct Snapshot {
    color: Vec<[u8; 4]>,
    depth: Vec<u32>,
    stencil: Vec<u8>,
}

/// The framebuffer-object state of a context.
#[derive(Default)]
pub struct FboState {
    pub framebuffers: HashMap<u32, FramebufferObject>,
    /// Names glGenFramebuffers returned and not yet bound.
    reserved: Reserved,
    pub renderbuffers: HashMap<u32, RbObject>,
    rb_reserved: Reserved,
    pub renderbuffer_binding: u32,
    pub draw_binding: u32,
    pub read_binding: u32,
    /// The window system's framebuffer while a framebuffer object is the
    /// draw framebuffer (`Context::fb` holds the staging one).
    pub parked: Option<Framebuffer>,
    /// The window's draw and read buffers while objects are bound.
    window_draw_buffer: u32,
    window_read_buffer: u32,
    snapshot: Snapshot,
    /// The read framebuffer's staging copy when it is an object other
    /// than the draw framebuffer.
    pub read_staging: Option<Framebuffer>,
}

/// A share group's renderbuffers (their names and storage).
#[derive(Default)]
pub struct SharedRenderbuffers {
    renderbuffers: HashMap<u32, RbObject>,
    reserved: Reserved,
}

impl FboState {
    /// Exchanges this context's renderbuffers with a share group's.
    pub fn swap_renderbuffers(&mut self, t: &mut SharedRenderbuffers) {
        std::mem::swap(&mut self.renderbuffers, &mut t.renderbuffers);
        std::mem::swap(&mut self.rb_reserved, &mut t.reserved);
    }
}

/// Which bindings a framebuffer target names: (draw, read).
fn fb_target(t: u32) -> Option<(bool, bool)> {
    match t {
        GL_FRAMEBUFFER => Some((true, true)),
        GL_DRAW_FRAMEBUFFER => Some((true, false)),
        GL_READ_FRAMEBUFFER => Some((false, true)),
        _ => None,
    }
}

/// An attached image's size and where it lives, resolved for one access.
struct Resolved {
    width: usize,
    height: usize,
    /// Texture: (full width, full height, offset of the attached region's
    /// first texel) in the image's texel array.
    kind: ResolvedKind,
}

enum ResolvedKind {
    Texture { name: u32, slot: usize, stride: usize, start: usize, base: Base, ifmt: u32 },
    Renderbuffer(RbObject),
}

impl Context {
    /// The draw buffer of object `b` (the context's own while it is bound
    /// for drawing) and its read buffer.
    fn buffers_of(&self, b: u32, o: &FramebufferObject) -> (u32, u32) {
        let d = if b == self.fbo.draw_binding { self.color_buffer.draw_buffer } else { o.draw_buffer };
        let r = if b == self.fbo.read_binding { self.pixel_read_buffer } else { o.read_buffer };
        (d, r)
    }

    fn fbo_object(&self, binding: u32) -> Option<&FramebufferObject> {
        (binding != 0).then(|| self.fbo.framebuffers.get(&binding)).flatten()
    }

    /// The window's framebuffer, wherever it is (winsys::bound swaps it
    /// with the drawable's; glFlush presents it).
    pub fn window_fb_mut(&mut self) -> &mut Framebuffer {
        match self.fbo.parked {
            Some(ref mut fb) => fb,
            None => &mut self.fb,
        }
    }

    pub fn window_fb(&self) -> &Framebuffer {
        self.fbo.parked.as_ref().unwrap_or(&self.fb)
    }

    /// Is a framebuffer object the draw framebuffer?
    pub fn drawing_to_fbo(&self) -> bool {
        self.fbo.draw_binding != 0
    }

    pub fn gen_framebuffers(&mut self, n: i32) -> Option<Vec<u32>> {
        if n < 0 {
            self.set_error(GL_INVALID_VALUE);
            return None;
        }
        let fbs = &self.fbo.framebuffers;
        Some(self.fbo.reserved.generate(n as usize, |k| fbs.contains_key(&k)))
    }

    pub fn gen_renderbuffers(&mut self, n: i32) -> Option<Vec<u32>> {
        if n < 0 {
            self.set_error(GL_INVALID_VALUE);
            return None;
        }
        let rbs = &self.fbo.renderbuffers;
        Some(self.fbo.rb_reserved.generate(n as usize, |k| rbs.contains_key(&k)))
    }

    pub fn is_framebuffer(&self, name: u32) -> bool {
        name != 0 && self.fbo.framebuffers.contains_key(&name)
    }

    pub fn is_renderbuffer(&self, name: u32) -> bool {
        name != 0 && self.fbo.renderbuffers.contains_key(&name)
    }

    /// glBindFramebuffer: any name may be bound (compatibility contexts);
    /// a new name makes an object.
    pub fn bind_framebuffer(&mut self, target: u32, name: u32) {
        let Some((draw, read)) = fb_target(target) else { return self.set_error(GL_INVALID_ENUM) };
        if name != 0 && !self.fbo.framebuffers.contains_key(&name) {
            self.fbo.reserved.remove(name);
            self.fbo.framebuffers.insert(name, FramebufferObject::default());
        }
        if draw && name != self.fbo.draw_binding {
            self.rebind_draw(name);
        }
        if read && name != self.fbo.read_binding {
            self.rebind_read(name);
        } else if read || draw {
            self.refresh_read_staging();
        }
    }

    fn rebind_draw(&mut self, name: u32) {
        self.fbo_store();
        let old = self.fbo.draw_binding;
        if old != 0 {
            let db = self.color_buffer.draw_buffer;
            if let Some(o) = self.fbo.framebuffers.get_mut(&old) {
                o.draw_buffer = db;
            }
        }
        if old == 0 {
            // Park the window's framebuffer and its draw-buffer choice.
            let staging = Framebuffer::new(Config { alpha_bits: 8, depth_bits: 0, stencil_bits: 0, accum_bits: 0 });
            self.fbo.parked = Some(std::mem::replace(&mut self.fb, staging));
            self.fbo.window_draw_buffer = self.color_buffer.draw_buffer;
        }
        self.fbo.draw_binding = name;
        if name == 0 {
            if let Some(w) = self.fbo.parked.take() {
                self.fb = w;
            }
            self.color_buffer.draw_buffer = self.fbo.window_draw_buffer;
            self.fbo.snapshot = Snapshot::default();
        } else {
            self.color_buffer.draw_buffer = self.fbo.framebuffers.get(&name).map_or(GL_COLOR_ATTACHMENT0, |o| o.draw_buffer);
            self.fbo_load();
        }
        self.sync_draw_buffer();
        self.dirty |= DIRTY_ALL;
    }

    fn rebind_read(&mut self, name: u32) {
        let old = self.fbo.read_binding;
        if old != 0 {
            let rb = self.pixel_read_buffer;
            if let Some(o) = self.fbo.framebuffers.get_mut(&old) {
                o.read_buffer = rb;
            }
        } else {
            self.fbo.window_read_buffer = self.pixel_read_buffer;
        }
        self.fbo.read_binding = name;
        self.pixel_read_buffer = if name == 0 { self.fbo.window_read_buffer } else { self.fbo.framebuffers.get(&name).map_or(GL_COLOR_ATTACHMENT0, |o| o.read_buffer) };
        self.refresh_read_staging();
    }

    /// Loads the read framebuffer's staging copy when it is an object that
    /// is not also the draw framebuffer.
    fn refresh_read_staging(&mut self) {
        let r = self.fbo.read_binding;
        self.fbo.read_staging = if r != 0 && r != self.fbo.draw_binding {
            let o = self.fbo.framebuffers.get(&r).cloned().unwrap_or_default();
            self.build_staging(&o).map(|(fb, _)| fb)
        } else {
            None
        };
    }

    pub fn delete_framebuffers(&mut self, names: &[u32]) {
        for &name in names {
            if name == 0 {
                continue;
            }
            self.fbo.reserved.remove(name);
            if !self.fbo.framebuffers.contains_key(&name) {
                continue;
            }
            // Deleting a bound framebuffer binds 0 in its place.
            if self.fbo.draw_binding == name {
                self.rebind_draw(0);
            }
            if self.fbo.read_binding == name {
                self.rebind_read(0);
            }
            self.fbo.framebuffers.remove(&name);
        }
    }

    pub fn delete_renderbuffers(&mut self, names: &[u32]) {
        for &name in names {
            if name == 0 {
                continue;
            }
            self.fbo.rb_reserved.remove(name);
            let Some(obj) = self.fbo.renderbuffers.get(&name).cloned() else { continue };
            if self.fbo.renderbuffer_binding == name {
                self.fbo.renderbuffer_binding = 0;
            }
            // Detached from the bound framebuffers (section 4.4.2.2); other
            // framebuffers keep the image (`RbObject`).
            let gone = Attachment::Renderbuffer(RbRef { name, obj });
            self.detach_where(|a| *a == gone);
            self.fbo.renderbuffers.remove(&name);
        }
    }

    /// glDeleteTextures' side here: images of deleted textures are
    /// detached from the bound framebuffers first (section 4.4.2.3).
    pub fn fbo_textures_deleted(&mut self, names: &[u32]) {
        if self.fbo.draw_binding == 0 && self.fbo.read_binding == 0 {
            return;
        }
        for &n in names {
            if n != 0 {
                self.detach_where(|a| matches!(*a, Attachment::Texture { name, .. } if name == n));
            }
        }
    }

    fn detach_where(&mut self, hit: impl Fn(&Attachment) -> bool) {
        let bound = [self.fbo.draw_binding, self.fbo.read_binding];
        let touched = bound.iter().any(|&b| {
            self.fbo_object(b).is_some_and(|o| hit(&o.color) || hit(&o.depth) || hit(&o.stencil))
        });
        if !touched {
            return;
        }
        self.fbo_store();
        for b in bound {
            if let Some(o) = self.fbo.framebuffers.get_mut(&b) {
                for a in [&mut o.color, &mut o.depth, &mut o.stencil] {
                    if hit(a) {
                        *a = Attachment::None;
                    }
                }
            }
        }
        self.fbo_reload();
    }

    pub fn bind_renderbuffer(&mut self, target: u32, name: u32) {
        if target != GL_RENDERBUFFER {
            return self.set_error(GL_INVALID_ENUM);
        }
        if name != 0 && !self.fbo.renderbuffers.contains_key(&name) {
            self.fbo.rb_reserved.remove(name);
            self.fbo.renderbuffers.insert(name, Arc::new(Mutex::new(Renderbuffer::default())));
        }
        self.fbo.renderbuffer_binding = name;
    }

    /// glRenderbufferStorage(Multisample): samples above MAX_SAMPLES (0)
    /// are INVALID_VALUE.
    pub fn renderbuffer_storage(&mut self, target: u32, samples: i32, ifmt: u32, w: i32, h: i32) {
        if target != GL_RENDERBUFFER {
            return self.set_error(GL_INVALID_ENUM);
        }
        let Some(kind) = renderbuffer_kind(ifmt) else { return self.set_error(GL_INVALID_ENUM) };
        if w < 0 || h < 0 || w as usize > MAX_SIZE || h as usize > MAX_SIZE || samples < 0 || samples > 0 {
            return self.set_error(GL_INVALID_VALUE);
        }
        let Some(obj) = self.fbo.renderbuffers.get(&self.fbo.renderbuffer_binding).cloned() else {
            return self.set_error(GL_INVALID_OPERATION);
        };
        let n = w as usize * h as usize;
        let mut new = Renderbuffer { internal_format: ifmt, width: w, height: h, kind, ..Default::default() };
        let ok = match kind {
            RbKind::Color(base) => alloc(&mut new.color, n, to_bytes(base.expand([0.0; 4]))),
            RbKind::Depth => alloc(&mut new.depth, n, 0),
            RbKind::Stencil => alloc(&mut new.stencil, n, 0),
            RbKind::DepthStencil => alloc(&mut new.depth, n, 0) && alloc(&mut new.stencil, n, 0),
            RbKind::None => true,
        };
        if !ok {
            return self.set_error(GL_OUT_OF_MEMORY);
        }
        self.fbo_store();
        // New storage for the same object: every framebuffer it is
        // attached to sees it.
        *rb(&obj) = new;
        self.fbo_reload();
    }

    pub fn get_renderbuffer_parameter(&mut self, target: u32, pname: u32) -> Option<i32> {
        if target != GL_RENDERBUFFER {
            self.set_error(GL_INVALID_ENUM);
            return None;
        }
        let Some(obj) = self.fbo.renderbuffers.get(&self.fbo.renderbuffer_binding).cloned() else {
            self.set_error(GL_INVALID_OPERATION);
            return None;
        };
        let rb = rb(&obj);
        let (rgba, d, s) = rb_sizes(rb.kind);
        Some(match pname {
            GL_RENDERBUFFER_WIDTH => rb.width,
            GL_RENDERBUFFER_HEIGHT => rb.height,
            GL_RENDERBUFFER_INTERNAL_FORMAT => if rb.internal_format == 0 { GL_RGBA as i32 } else { rb.internal_format as i32 },
            GL_RENDERBUFFER_SAMPLES => 0,
            GL_RENDERBUFFER_RED_SIZE..=0x8D53 => rgba[(pname - GL_RENDERBUFFER_RED_SIZE) as usize],
            0x8D54 => d,
            GL_RENDERBUFFER_STENCIL_SIZE => s,
            _ => {
                self.set_error(GL_INVALID_ENUM);
                return None;
            }
        })
    }

    /// The object bound to `target` for attaching: errors as the spec
    /// names them.
    fn attach_target(&mut self, target: u32, attachment: u32) -> Option<(u32, &'static [usize])> {
        let Some((draw, _)) = fb_target(target) else {
            self.set_error(GL_INVALID_ENUM);
            return None;
        };
        let slots: &'static [usize] = match attachment {
            GL_COLOR_ATTACHMENT0 => &[0],
            GL_DEPTH_ATTACHMENT => &[1],
            GL_STENCIL_ATTACHMENT => &[2],
            GL_DEPTH_STENCIL_ATTACHMENT => &[1, 2],
            a if (GL_COLOR_ATTACHMENT0..=GL_COLOR_ATTACHMENT15).contains(&a) => {
                self.set_error(GL_INVALID_OPERATION);
                return None;
            }
            _ => {
                self.set_error(GL_INVALID_ENUM);
                return None;
            }
        };
        let b = if draw { self.fbo.draw_binding } else { self.fbo.read_binding };
        if b == 0 {
            self.set_error(GL_INVALID_OPERATION);
            return None;
        }
        Some((b, slots))
    }

    fn set_attachment(&mut self, fbo: u32, slots: &[usize], a: Attachment) {
        let bound = fbo == self.fbo.draw_binding || fbo == self.fbo.read_binding;
        if bound {
            self.fbo_store();
        }
        if let Some(o) = self.fbo.framebuffers.get_mut(&fbo) {
            for &s in slots {
                *[&mut o.color, &mut o.depth, &mut o.stencil][s] = a.clone();
            }
        }
        if bound {
            self.fbo_reload();
        }
    }

    /// glFramebufferTexture1D/2D/3D and glFramebufferTextureLayer
    /// (`textarget` 0: the layer form, any texture target).
    pub fn framebuffer_texture(&mut self, dims: u8, target: u32, attachment: u32, textarget: u32, texture: u32, level: i32, layer: i32) {
        let Some((fbo, slots)) = self.attach_target(target, attachment) else { return };
        if texture == 0 {
            return self.set_attachment(fbo, slots, Attachment::None);
        }
        let Some(obj) = self.texture.objects.get(&texture) else { return self.set_error(GL_INVALID_OPERATION) };
        let t = obj.target.map(|t| t.dims()).unwrap_or(0);
        let cube = obj.target == Some(crate::render::texture::Target::Cube);
        let rect = obj.target == Some(crate::render::texture::Target::Rect);
        let ok_target = match (dims, textarget) {
            (1, GL_TEXTURE_1D) => t == 1,
            (2, GL_TEXTURE_2D) => t == 2 && !cube && !rect,
            (2, GL_TEXTURE_RECTANGLE) => rect,
            (2, GL_TEXTURE_CUBE_MAP_POSITIVE_X..=GL_TEXTURE_CUBE_MAP_NEGATIVE_Z) => cube,
            (3, GL_TEXTURE_3D) => t == 3,
            (0, 0) => t == 3,
            (1 | 2 | 3, _) if !matches!(textarget, GL_TEXTURE_1D | GL_TEXTURE_2D | GL_TEXTURE_3D | GL_TEXTURE_RECTANGLE | GL_TEXTURE_CUBE_MAP_POSITIVE_X..=GL_TEXTURE_CUBE_MAP_NEGATIVE_Z) => {
                return self.set_error(GL_INVALID_ENUM);
            }
            _ => false,
        };
        if !ok_target {
            return self.set_error(GL_INVALID_OPERATION);
        }
        let max_level = if rect { 0 } else { MAX_LEVELS as i32 - 1 };
        if level < 0 || level > max_level || layer < 0 || (t == 3 && layer >= super::texture::MAX_3D_TEXTURE_SIZE) {
            return self.set_error(GL_INVALID_VALUE);
        }
        let target = if dims == 0 { GL_TEXTURE_3D } else { textarget };
        self.set_attachment(fbo, slots, Attachment::Texture { name: texture, target, level, layer: if t == 3 { layer } else { 0 } });
    }

    pub fn framebuffer_renderbuffer(&mut self, target: u32, attachment: u32, rb_target: u32, rb: u32) {
        let Some((fbo, slots)) = self.attach_target(target, attachment) else { return };
        if rb_target != GL_RENDERBUFFER {
            return self.set_error(GL_INVALID_ENUM);
        }
        let a = if rb == 0 {
            Attachment::None
        } else {
            let Some(obj) = self.fbo.renderbuffers.get(&rb).cloned() else { return self.set_error(GL_INVALID_OPERATION) };
            Attachment::Renderbuffer(RbRef { name: rb, obj })
        };
        self.set_attachment(fbo, slots, a);
    }

    /// Where an attachment's image is and how large (None: no image).
    fn resolve(&self, a: &Attachment) -> Option<Resolved> {
        match *a {
            Attachment::None => None,
            Attachment::Renderbuffer(ref r) => {
                let (width, height) = {
                    let b = rb(&r.obj);
                    (b.width as usize, b.height as usize)
                };
                Some(Resolved { width, height, kind: ResolvedKind::Renderbuffer(r.obj.clone()) })
            }
            Attachment::Texture { name, target, level, layer } => {
                let obj = self.texture.objects.get(&name)?;
                let face = if (GL_TEXTURE_CUBE_MAP_POSITIVE_X..=GL_TEXTURE_CUBE_MAP_NEGATIVE_Z).contains(&target) { (target - GL_TEXTURE_CUBE_MAP_POSITIVE_X) as usize } else { 0 };
                let slot = face * MAX_LEVELS + level as usize;
                let img = obj.images.get(slot)?.as_ref()?;
                let dims = obj.target?.dims();
                let inner = img.inner(dims);
                if layer >= inner[2] || img.texels.is_empty() {
                    return None;
                }
                let b = img.border as usize;
                let (bx, by, bz) = (b, if dims >= 2 { b } else { 0 }, if dims >= 3 { b } else { 0 });
                let (fw, fh) = (img.width as usize, img.height as usize);
                let start = ((layer as usize + bz) * fh + by) * fw + bx;
                Some(Resolved { width: inner[0] as usize, height: inner[1] as usize, kind: ResolvedKind::Texture { name, slot, stride: fw, start, base: img.base, ifmt: img.internal_format } })
            }
        }
    }

    /// Section 4.4.4's completeness of a framebuffer object.
    /// `draw_buffer`: the object's draw buffer, when it is to be checked.
    pub fn framebuffer_status(&self, o: &FramebufferObject, draw_buffer: Option<u32>) -> u32 {
        let mut sizes = Vec::new();
        for (i, a) in [&o.color, &o.depth, &o.stencil].into_iter().enumerate() {
            if *a == Attachment::None {
                continue;
            }
            let Some(r) = self.resolve(a) else { return GL_FRAMEBUFFER_INCOMPLETE_ATTACHMENT };
            if r.width == 0 || r.height == 0 {
                return GL_FRAMEBUFFER_INCOMPLETE_ATTACHMENT;
            }
            // Colour-, depth- and stencil-renderable formats.
            let ok = match (&r.kind, i) {
                (ResolvedKind::Texture { base, .. }, 0) => *base != Base::Depth,
                (ResolvedKind::Texture { base, .. }, 1) => *base == Base::Depth,
                (ResolvedKind::Texture { ifmt, .. }, _) => is_depth_stencil(*ifmt),
                (ResolvedKind::Renderbuffer(obj), _) => {
                    let k = rb(obj).kind;
                    match i {
                        0 => matches!(k, RbKind::Color(_)),
                        1 => matches!(k, RbKind::Depth | RbKind::DepthStencil),
                        _ => matches!(k, RbKind::Stencil | RbKind::DepthStencil),
                    }
                }
            };
            if !ok {
                return GL_FRAMEBUFFER_INCOMPLETE_ATTACHMENT;
            }
            sizes.push((r.width, r.height));
        }
        if sizes.is_empty() {
            return GL_FRAMEBUFFER_INCOMPLETE_MISSING_ATTACHMENT;
        }
        // EXT_framebuffer_object: every image has one size.
        if sizes.iter().any(|&s| s != sizes[0]) {
            return GL_FRAMEBUFFER_INCOMPLETE_DIMENSIONS;
        }
        if o.color == Attachment::None && draw_buffer.is_some_and(|d| d != 0) {
            return GL_FRAMEBUFFER_INCOMPLETE_DRAW_BUFFER;
        }
        GL_FRAMEBUFFER_COMPLETE
    }

    pub fn check_framebuffer_status(&mut self, target: u32) -> u32 {
        let Some((draw, _)) = fb_target(target) else {
            self.set_error(GL_INVALID_ENUM);
            return 0;
        };
        let b = if draw { self.fbo.draw_binding } else { self.fbo.read_binding };
        match self.fbo_object(b) {
            None => GL_FRAMEBUFFER_COMPLETE,
            Some(o) => {
                let (db, rb) = self.buffers_of(b, o);
                let mut status = self.framebuffer_status(o, Some(db));
                // EXT_framebuffer_object checks the read buffer as well.
                if status == GL_FRAMEBUFFER_COMPLETE && o.color == Attachment::None && rb != 0 {
                    status = GL_FRAMEBUFFER_INCOMPLETE_READ_BUFFER;
                }
                status
            }
        }
    }

    /// Is the draw framebuffer complete (the window's always is)? Commands
    /// that draw, read or clear raise INVALID_FRAMEBUFFER_OPERATION when not.
    pub fn draw_framebuffer_complete(&mut self) -> bool {
        match self.fbo_object(self.fbo.draw_binding) {
            None => true,
            Some(o) => {
                let ok = self.framebuffer_status(o, Some(self.color_buffer.draw_buffer)) == GL_FRAMEBUFFER_COMPLETE;
                if !ok {
                    self.set_error(GL_INVALID_FRAMEBUFFER_OPERATION);
                }
                ok
            }
        }
    }

    pub fn read_framebuffer_complete(&mut self) -> bool {
        match self.fbo_object(self.fbo.read_binding) {
            None => true,
            Some(o) => {
                // A missing read colour buffer is the reading command's
                // INVALID_OPERATION (GL 3.0 section 4.3.2), not this.
                let ok = self.framebuffer_status(o, None) == GL_FRAMEBUFFER_COMPLETE;
                if !ok {
                    self.set_error(GL_INVALID_FRAMEBUFFER_OPERATION);
                }
                ok
            }
        }
    }

    /// Does the read framebuffer lack the colour buffer glReadPixels would
    /// read (an object's NONE read buffer or empty colour attachment)?
    pub fn fbo_read_color_missing(&self) -> bool {
        match self.fbo_object(self.fbo.read_binding) {
            None => false,
            Some(o) => o.color == Attachment::None || self.pixel_read_buffer == 0,
        }
    }

    pub fn get_framebuffer_attachment_parameter(&mut self, target: u32, attachment: u32, pname: u32) -> Option<i32> {
        let Some((draw, _)) = fb_target(target) else {
            self.set_error(GL_INVALID_ENUM);
            return None;
        };
        let b = if draw { self.fbo.draw_binding } else { self.fbo.read_binding };
        let Some(o) = self.fbo_object(b) else { return self.default_attachment_parameter(attachment, pname) };
        let a = match attachment {
            GL_COLOR_ATTACHMENT0 => o.color.clone(),
            GL_DEPTH_ATTACHMENT => o.depth.clone(),
            GL_STENCIL_ATTACHMENT => o.stencil.clone(),
            GL_DEPTH_STENCIL_ATTACHMENT if o.depth == o.stencil => o.depth.clone(),
            GL_DEPTH_STENCIL_ATTACHMENT => {
                self.set_error(GL_INVALID_OPERATION);
                return None;
            }
            a if (GL_COLOR_ATTACHMENT0..=GL_COLOR_ATTACHMENT15).contains(&a) => {
                self.set_error(GL_INVALID_OPERATION);
                return None;
            }
            _ => {
                self.set_error(GL_INVALID_ENUM);
                return None;
            }
        };
        let sizes = |c: &Context| -> ([i32; 4], i32, i32, bool) {
            match a {
                Attachment::Renderbuffer(ref r) => {
                    let k = rb(&r.obj).kind;
                    let (rgba, d, s) = rb_sizes(k);
                    (rgba, d, s, false)
                }
                Attachment::Texture { .. } => match c.resolve(&a).map(|r| r.kind) {
                    Some(ResolvedKind::Texture { ifmt, .. }) => {
                        let f = internal_format(ifmt).map(|f| f.stored_bits()).unwrap_or([0; 7]);
                        let float = super::texture::image::is_float_format(ifmt);
                        let lum = f[4].max(f[5]) as i32;
                        ([(f[0] as i32).max(lum), (f[1] as i32).max(lum), (f[2] as i32).max(lum), (f[3] as i32).max(f[5] as i32)], f[6] as i32, if is_depth_stencil(ifmt) { 8 } else { 0 }, float)
                    }
                    _ => ([0; 4], 0, 0, false),
                },
                Attachment::None => ([0; 4], 0, 0, false),
            }
        };
        Some(match (pname, a.clone()) {
            (GL_FRAMEBUFFER_ATTACHMENT_OBJECT_TYPE, Attachment::None) => 0,
            (GL_FRAMEBUFFER_ATTACHMENT_OBJECT_TYPE, Attachment::Texture { .. }) => GL_TEXTURE as i32,
            (GL_FRAMEBUFFER_ATTACHMENT_OBJECT_TYPE, Attachment::Renderbuffer(_)) => GL_RENDERBUFFER as i32,
            (GL_FRAMEBUFFER_ATTACHMENT_OBJECT_NAME, Attachment::None) => 0,
            (GL_FRAMEBUFFER_ATTACHMENT_OBJECT_NAME, Attachment::Texture { name, .. }) => name as i32,
            (GL_FRAMEBUFFER_ATTACHMENT_OBJECT_NAME, Attachment::Renderbuffer(ref r)) => r.name as i32,
            (GL_FRAMEBUFFER_ATTACHMENT_TEXTURE_LEVEL, Attachment::Texture { level, .. }) => level,
            (GL_FRAMEBUFFER_ATTACHMENT_TEXTURE_CUBE_MAP_FACE, Attachment::Texture { target, .. }) => {
                if (GL_TEXTURE_CUBE_MAP_POSITIVE_X..=GL_TEXTURE_CUBE_MAP_NEGATIVE_Z).contains(&target) { target as i32 } else { 0 }
            }
            (GL_FRAMEBUFFER_ATTACHMENT_TEXTURE_LAYER, Attachment::Texture { layer, .. }) => layer,
            (GL_FRAMEBUFFER_ATTACHMENT_COLOR_ENCODING, a) if a != Attachment::None => GL_LINEAR as i32,
            (GL_FRAMEBUFFER_ATTACHMENT_COMPONENT_TYPE, a) if a != Attachment::None => {
                if sizes(self).3 { GL_FLOAT as i32 } else { GL_UNSIGNED_NORMALIZED as i32 }
            }
            (GL_FRAMEBUFFER_ATTACHMENT_RED_SIZE..=GL_FRAMEBUFFER_ATTACHMENT_STENCIL_SIZE, a) if a != Attachment::None => {
                let (rgba, d, s, _) = sizes(self);
                match pname - GL_FRAMEBUFFER_ATTACHMENT_RED_SIZE {
                    k @ 0..=3 => rgba[k as usize],
                    4 => d,
                    _ => s,
                }
            }
            // ARB_framebuffer_object: with nothing attached, only the type
            // and name may be asked (INVALID_OPERATION for the others).
            (GL_FRAMEBUFFER_ATTACHMENT_TEXTURE_LEVEL..=GL_FRAMEBUFFER_ATTACHMENT_TEXTURE_LAYER | GL_FRAMEBUFFER_ATTACHMENT_COLOR_ENCODING..=GL_FRAMEBUFFER_ATTACHMENT_STENCIL_SIZE, Attachment::None) => {
                self.set_error(GL_INVALID_OPERATION);
                return None;
            }
            _ => {
                self.set_error(GL_INVALID_ENUM);
                return None;
            }
        })
    }

    /// GetFramebufferAttachmentParameteriv on the window's framebuffer
    /// (ARB_framebuffer_object): its colour, depth and stencil buffers.
    fn default_attachment_parameter(&mut self, attachment: u32, pname: u32) -> Option<i32> {
        let cfg = self.window_fb().config;
        let (present, sizes) = match attachment {
            GL_FRONT | GL_FRONT_LEFT_ | GL_LEFT_ => (true, [8, 8, 8, 8, 0, 0]),
            GL_BACK | GL_BACK_LEFT_ => (self.double_buffered, [8, 8, 8, 8, 0, 0]),
            GL_DEPTH_ => (cfg.depth_bits > 0, [0, 0, 0, 0, cfg.depth_bits as i32, 0]),
            GL_STENCIL_ => (cfg.stencil_bits > 0, [0, 0, 0, 0, 0, cfg.stencil_bits as i32]),
            _ => {
                self.set_error(if (GL_COLOR_ATTACHMENT0..=GL_COLOR_ATTACHMENT15).contains(&attachment) || attachment == GL_DEPTH_ATTACHMENT || attachment == GL_STENCIL_ATTACHMENT { GL_INVALID_OPERATION } else { GL_INVALID_ENUM });
                return None;
            }
        };
        Some(match pname {
            GL_FRAMEBUFFER_ATTACHMENT_OBJECT_TYPE => if present { GL_FRAMEBUFFER_DEFAULT as i32 } else { 0 },
            _ if !present => {
                self.set_error(GL_INVALID_OPERATION);
                return None;
            }
            GL_FRAMEBUFFER_ATTACHMENT_COLOR_ENCODING => GL_LINEAR as i32,
            GL_FRAMEBUFFER_ATTACHMENT_COMPONENT_TYPE => GL_UNSIGNED_NORMALIZED as i32,
            GL_FRAMEBUFFER_ATTACHMENT_RED_SIZE..=GL_FRAMEBUFFER_ATTACHMENT_STENCIL_SIZE => sizes[(pname - GL_FRAMEBUFFER_ATTACHMENT_RED_SIZE) as usize],
            _ => {
                self.set_error(GL_INVALID_ENUM);
                return None;
            }
        })
    }

    /// glGenerateMipmap: levels base + 1 .. q of the bound texture from its
    /// base level (the box filter of GENERATE_MIPMAP).
    pub fn generate_mipmap(&mut self, target: u32) {
        self.fbo_store();
        self.generate_mipmap_now(target);
        self.fbo_reload();
    }

    /// Queries of this module's state (glGet).
    pub fn fbo_get(&self, pname: u32) -> Option<Value> {
        let v = match pname {
            GL_FRAMEBUFFER_BINDING => self.fbo.draw_binding as i64,
            GL_READ_FRAMEBUFFER_BINDING => self.fbo.read_binding as i64,
            GL_RENDERBUFFER_BINDING => self.fbo.renderbuffer_binding as i64,
            GL_MAX_COLOR_ATTACHMENTS => MAX_COLOR_ATTACHMENTS as i64,
            GL_MAX_RENDERBUFFER_SIZE => MAX_SIZE as i64,
            GL_MAX_SAMPLES => 0,
            _ => return None,
        };
        Some(Value::Ints(vec![v]))
    }

    // ---- staging ----

    /// A staging framebuffer holding the images of `o` (None: incomplete
    /// or out of memory), and the attachments it was built from.
    fn build_staging(&self, o: &FramebufferObject) -> Option<(Framebuffer, Snapshot)> {
        if self.framebuffer_status(o, None) != GL_FRAMEBUFFER_COMPLETE {
            return None;
        }
        let color = self.resolve(&o.color);
        let depth = self.resolve(&o.depth);
        let stencil = self.resolve(&o.stencil);
        let (mut w, mut h) = (usize::MAX, usize::MAX);
        for r in [&color, &depth, &stencil].into_iter().flatten() {
            w = w.min(r.width);
            h = h.min(r.height);
        }
        if w == usize::MAX {
            return None;
        }
        let config = Config { alpha_bits: 8, depth_bits: if depth.is_some() { 24 } else { 0 }, stencil_bits: if stencil.is_some() { 8 } else { 0 }, accum_bits: 0 };
        let mut fb = Framebuffer::new(config);
        fb.resize(w, h).ok()?;
        if let Some(r) = &color {
            self.read_attached(r, w, h, &mut fb.color, [0; 4], |rb, k| rb.color.get(k).copied(), |img, base, i| match &img.texels {
                Texels::Rgba8(v) if matches!(base, Base::Rgba | Base::Rgb) => v[i],
                t => super::texture::image::texel_to_rgba(base, t.get(i)).map(to_unorm8),
            });
        }
        if let Some(r) = &depth {
            self.read_attached(r, w, h, &mut fb.depth, 0, |rb, k| rb.depth.get(k).copied(), |img, _, i| {
                let d = img.texels.get(i)[0] as f64;
                (d.clamp(0.0, 1.0) * DEPTH_MAX as f64).round() as u32
            });
        }
        if let Some(r) = &stencil {
            self.read_attached(r, w, h, &mut fb.stencil, 0, |rb, k| rb.stencil.get(k).copied(), |img, _, i| img.texels.get(i)[3] as u8);
        }
        let snap = Snapshot { color: if color.is_some() { fb.color.to_vec() } else { Vec::new() }, depth: fb.depth.to_vec(), stencil: fb.stencil.to_vec() };
        Some((fb, snap))
    }

    /// Copies the `w` x `h` corner of an attached image into `dst` (rows
    /// `w` long), taking the renderbuffer's lock or finding the texture
    /// image once for the whole copy. A texel missing (storage replaced by
    /// a sharing context, image gone) reads as `zero`.
    #[allow(clippy::too_many_arguments)]
    fn read_attached<T: Copy>(
        &self,
        r: &Resolved,
        w: usize,
        h: usize,
        dst: &mut [T],
        zero: T,
        from_rb: impl Fn(&Renderbuffer, usize) -> Option<T>,
        from_tex: impl Fn(&Image, Base, usize) -> T,
    ) {
        match r.kind {
            ResolvedKind::Renderbuffer(ref obj) => {
                let rb = rb(obj);
                let rw = rb.width as usize;
                for y in 0..h {
                    for x in 0..w {
                        dst[y * w + x] = from_rb(&rb, y * rw + x).unwrap_or(zero);
                    }
                }
            }
            ResolvedKind::Texture { name, slot, stride, start, base, .. } => {
                let Some(img) = self.texture.objects.get(&name).and_then(|o| o.images[slot].as_ref()) else {
                    dst[..w * h].fill(zero);
                    return;
                };
                for y in 0..h {
                    for x in 0..w {
                        dst[y * w + x] = from_tex(img, base, start + y * stride + x);
                    }
                }
            }
        }
    }

    /// Loads the draw framebuffer's staging copy from its attachments.
    fn fbo_load(&mut self) {
        let b = self.fbo.draw_binding;
        if b == 0 {
            return;
        }
        let o = self.fbo.framebuffers.get(&b).cloned().unwrap_or_default();
        let (fb, snap) = self.build_staging(&o).unwrap_or_else(|| (Framebuffer::new(Config { alpha_bits: 8, depth_bits: 0, stencil_bits: 0, accum_bits: 0 }), Snapshot::default()));
        let samples = self.fb.samples_passed;
        self.fb = fb;
        self.fb.samples_passed = samples;
        self.fbo.snapshot = snap;
        self.dirty |= DIRTY_ALL;
    }

    /// Runs a command that may change texture images (attached ones
    /// among them) with the draw framebuffer's drawing stored and the
    /// staging copies reloaded after. Free when no object is bound.
    pub fn with_fbo_stored<R>(&mut self, f: impl FnOnce(&mut Context) -> R) -> R {
        if self.fbo.draw_binding == 0 && self.fbo.read_binding == 0 {
            return f(self);
        }
        self.fbo_store();
        let r = f(self);
        self.fbo_reload();
        r
    }

    /// After attachments or attached images changed: the staging copies
    /// follow.
    pub fn fbo_reload(&mut self) {
        if self.fbo.draw_binding != 0 {
            self.fbo_load();
        }
        self.refresh_read_staging();
    }

    /// Writes what drawing changed in the staging framebuffer back to the
    /// draw framebuffer's attached images (see the module comment).
    pub fn fbo_store(&mut self) {
        let b = self.fbo.draw_binding;
        if b == 0 {
            return;
        }
        self.sync_render();
        let Some(o) = self.fbo.framebuffers.get(&b).cloned() else { return };
        let (w, h) = (self.fb.width, self.fb.height);
        if w == 0 || h == 0 {
            return;
        }
        let snap = std::mem::take(&mut self.fbo.snapshot);
        let mut changed_tex = false;
        if let Some(r) = self.resolve(&o.color) {
            if snap.color.len() == w * h {
                let diff: Vec<usize> = (0..w * h).filter(|&i| self.fb.color[i] != snap.color[i]).collect();
                if !diff.is_empty() {
                    changed_tex |= self.write_color(&r, w, &diff);
                }
            }
        }
        if let Some(r) = self.resolve(&o.depth) {
            if snap.depth.len() == w * h && self.fb.depth.len() == w * h {
                let diff: Vec<usize> = (0..w * h).filter(|&i| self.fb.depth[i] != snap.depth[i]).collect();
                if !diff.is_empty() {
                    changed_tex |= self.write_depth_stencil(&r, w, &diff, true);
                }
            }
        }
        if let Some(r) = self.resolve(&o.stencil) {
            if snap.stencil.len() == w * h && self.fb.stencil.len() == w * h {
                let diff: Vec<usize> = (0..w * h).filter(|&i| self.fb.stencil[i] != snap.stencil[i]).collect();
                if !diff.is_empty() {
                    changed_tex |= self.write_depth_stencil(&r, w, &diff, false);
                }
            }
        }
        // What was stored is the new baseline.
        self.fbo.snapshot = Snapshot {
            color: if snap.color.is_empty() { Vec::new() } else { self.fb.color.to_vec() },
            depth: self.fb.depth.to_vec(),
            stencil: self.fb.stencil.to_vec(),
        };
        if changed_tex {
            // Texture images changed in place: the fragment stage re-derives.
            self.derived.render.texture = None;
            self.dirty |= super::validate::DIRTY_TEXTURE;
        }
    }

    fn write_color(&mut self, r: &Resolved, w: usize, pixels: &[usize]) -> bool {
        match r.kind {
            ResolvedKind::Renderbuffer(ref obj) => {
                let mut rb = rb(obj);
                let base = match rb.kind {
                    RbKind::Color(b) => b,
                    _ => return false,
                };
                let rw = rb.width as usize;
                for &i in pixels {
                    let c = self.fb.color[i];
                    // Bounds-checked: a context sharing the renderbuffer
                    // may have given it new storage meanwhile.
                    if let Some(t) = rb.color.get_mut((i / w) * rw + i % w) {
                        *t = to_bytes(base.expand(c.map(|v| UNORM8[v as usize])));
                    }
                }
                false
            }
            ResolvedKind::Texture { name, slot, stride, start, base, ifmt } => {
                let mask = internal_format(ifmt).map_or([true; 3], |f| f.rgb_mask());
                let fb = &self.fb;
                let Some(img) = self.texture.objects.get_mut(&name).and_then(|o| o.images[slot].as_mut()) else { return false };
                let img = Arc::make_mut(img);
                let texel = |c: [u8; 4]| {
                    let mut f = c.map(|v| UNORM8[v as usize]);
                    for k in 0..3 {
                        if !mask[k] {
                            f[k] = 0.0;
                        }
                    }
                    base.expand(f)
                };
                match &mut img.texels {
                    Texels::Rgba8(v) => {
                        let v = Arc::make_mut(v);
                        for &i in pixels {
                            v[start + (i / w) * stride + i % w] = to_bytes(texel(fb.color[i]));
                        }
                    }
                    Texels::Float(v) => {
                        for &i in pixels {
                            v[start + (i / w) * stride + i % w] = texel(fb.color[i]);
                        }
                    }
                }
                true
            }
        }
    }

    fn write_depth_stencil(&mut self, r: &Resolved, w: usize, pixels: &[usize], depth: bool) -> bool {
        match r.kind {
            ResolvedKind::Renderbuffer(ref obj) => {
                let mut rb = rb(obj);
                let rw = rb.width as usize;
                for &i in pixels {
                    let k = (i / w) * rw + i % w;
                    if depth {
                        if let Some(d) = rb.depth.get_mut(k) {
                            *d = self.fb.depth[i];
                        }
                    } else if let Some(s) = rb.stencil.get_mut(k) {
                        *s = self.fb.stencil[i];
                    }
                }
                false
            }
            ResolvedKind::Texture { name, slot, stride, start, .. } => {
                let fb = &self.fb;
                let Some(img) = self.texture.objects.get_mut(&name).and_then(|o| o.images[slot].as_mut()) else { return false };
                let img = Arc::make_mut(img);
                if let Texels::Float(v) = &mut img.texels {
                    for &i in pixels {
                        let t = &mut v[start + (i / w) * stride + i % w];
                        if depth {
                            let d = (fb.depth[i] as f64 / DEPTH_MAX as f64) as f32;
                            t[0] = d;
                            t[1] = d;
                            t[2] = d;
                        } else {
                            t[3] = fb.stencil[i] as f32;
                        }
                    }
                }
                true
            }
        }
    }
}

fn to_bytes(c: [f32; 4]) -> [u8; 4] {
    c.map(to_unorm8)
}

fn alloc<T: Copy>(v: &mut Vec<T>, n: usize, fill: T) -> bool {
    if v.try_reserve_exact(n).is_err() {
        return false;
    }
    v.resize(n, fill);
    true
}

/// (R, G, B, A) bits, depth bits, stencil bits of a renderbuffer kind.
fn rb_sizes(k: RbKind) -> ([i32; 4], i32, i32) {
    match k {
        RbKind::Color(base) => {
            let e = base.expand([1.0, 1.0, 1.0, 0.0]);
            let a = matches!(base, Base::Alpha | Base::LuminanceAlpha | Base::Intensity | Base::Rgba);
            ([8 * (e[0] > 0.0) as i32, 8 * (e[1] > 0.0) as i32, 8 * (e[2] > 0.0) as i32, 8 * a as i32], 0, 0)
        }
        RbKind::Depth => ([0; 4], 24, 0),
        RbKind::Stencil => ([0; 4], 0, 8),
        RbKind::DepthStencil => ([0; 4], 24, 8),
        RbKind::None => ([0; 4], 0, 0),
    }
}

const GL_FRONT_LEFT_: u32 = 0x0400;
const GL_BACK_LEFT_: u32 = 0x0402;
const GL_LEFT_: u32 = 0x0406;
const GL_DEPTH_: u32 = 0x1801;
const GL_STENCIL_: u32 = 0x1802;
