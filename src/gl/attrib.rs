//! The attribute stacks (GL 1.5 section 6.1.14): glPushAttrib/glPopAttrib
//! and glPushClientAttrib/glPopClientAttrib.
//!
//! A push saves a copy of each selected group; a pop puts the copies back
//! (and re-derives everything). GL_ENABLE_BIT is saved as the value of every
//! capability glIsEnabled knows, and restored through glEnable/glDisable,
//! so it covers state that lives in several groups.
//!
//! GL_TEXTURE_BIT saves the active unit, every unit's enables, bindings,
//! environment and texture-coordinate generation, and the parameters of
//! the objects bound at the push; the pop rebinds those objects (a name
//! deleted since then binds the default object, as deletion left it) and
//! puts their parameters back. GL_PIXEL_MODE_BIT is the pixel transfer
//! modes, the pixel maps, the zoom and the read buffer (there are no colour
//! tables, convolution or histogram state yet).

use super::context::Context;
use super::enums::*;
use super::state::*;
use super::texture::TexUnit;
use super::validate::DIRTY_ALL;
use crate::render::texture::{Params, MAX_UNITS};

/// GL_MAX_ATTRIB_STACK_DEPTH and GL_MAX_CLIENT_ATTRIB_STACK_DEPTH.
pub const MAX_ATTRIB_STACK_DEPTH: usize = 16;

pub const GL_CURRENT_BIT: u32 = 0x1;
pub const GL_POINT_BIT: u32 = 0x2;
pub const GL_LINE_BIT: u32 = 0x4;
pub const GL_POLYGON_BIT: u32 = 0x8;
pub const GL_POLYGON_STIPPLE_BIT: u32 = 0x10;
pub const GL_PIXEL_MODE_BIT: u32 = 0x20;
pub const GL_LIGHTING_BIT: u32 = 0x40;
pub const GL_FOG_BIT: u32 = 0x80;
pub const GL_VIEWPORT_BIT: u32 = 0x800;
pub const GL_TRANSFORM_BIT: u32 = 0x1000;
pub const GL_ENABLE_BIT: u32 = 0x2000;
pub const GL_HINT_BIT: u32 = 0x8000;
pub const GL_EVAL_BIT: u32 = 0x10000;
pub const GL_LIST_BIT: u32 = 0x20000;
pub const GL_TEXTURE_BIT: u32 = 0x40000;
pub const GL_SCISSOR_BIT: u32 = 0x80000;
pub const GL_MULTISAMPLE_BIT: u32 = 0x2000_0000;
pub const GL_CLIENT_PIXEL_STORE_BIT: u32 = 0x1;

/// Every capability of GL 1.5 (glIsEnabled answers for those it knows).
fn all_caps() -> Vec<u32> {
    let mut caps = vec![
        GL_ALPHA_TEST, GL_AUTO_NORMAL, GL_BLEND, GL_COLOR_LOGIC_OP, GL_COLOR_MATERIAL, GL_COLOR_SUM, GL_COLOR_TABLE,
        GL_CONVOLUTION_1D, GL_CONVOLUTION_2D, GL_CULL_FACE, GL_DEPTH_TEST, GL_DITHER, GL_FOG, GL_HISTOGRAM,
        GL_INDEX_LOGIC_OP, GL_LIGHTING, GL_LINE_SMOOTH, GL_LINE_STIPPLE, GL_MINMAX, GL_MULTISAMPLE, GL_NORMALIZE,
        GL_POINT_SMOOTH, GL_POLYGON_OFFSET_FILL, GL_POLYGON_OFFSET_LINE, GL_POLYGON_OFFSET_POINT, GL_POLYGON_SMOOTH,
        GL_POLYGON_STIPPLE, GL_POST_COLOR_MATRIX_COLOR_TABLE, GL_POST_CONVOLUTION_COLOR_TABLE, GL_RESCALE_NORMAL,
        GL_SAMPLE_ALPHA_TO_COVERAGE, GL_SAMPLE_ALPHA_TO_ONE, GL_SAMPLE_COVERAGE, GL_SCISSOR_TEST, GL_SEPARABLE_2D,
        GL_STENCIL_TEST, GL_TEXTURE_1D, GL_TEXTURE_2D, GL_TEXTURE_3D, GL_TEXTURE_CUBE_MAP, GL_TEXTURE_GEN_S,
        GL_TEXTURE_GEN_T, GL_TEXTURE_GEN_R, GL_TEXTURE_GEN_Q,
    ];
    caps.push(super::texture::enums::GL_TEXTURE_RECTANGLE);
    caps.extend(GL_CLIP_PLANE0..GL_CLIP_PLANE0 + 6);
    caps.extend(GL_LIGHT0..GL_LIGHT0 + 8);
    caps.extend(GL_MAP1_COLOR_4..=GL_MAP1_VERTEX_4);
    caps.extend(GL_MAP2_COLOR_4..=GL_MAP2_VERTEX_4);
    caps
}

/// One glPushAttrib's saved groups.
#[derive(Default)]
pub struct Saved {
    mask: u32,
    current: Option<CurrentState>,
    point: Option<PointState>,
    line: Option<LineState>,
    polygon: Option<PolygonState>,
    stipple: Option<[u32; 32]>,
    lighting: Option<(super::lighting::LightingState, u32)>,
    depth: Option<DepthState>,
    accum_clear: Option<[f32; 4]>,
    stencil: Option<StencilState>,
    viewport: Option<ViewportState>,
    transform: Option<(u32, super::clip_plane::UserClipState, bool, bool)>,
    enables: Option<Vec<(u32, bool)>>,
    color_buffer: Option<ColorBufferState>,
    hints: Option<HintState>,
    eval: Option<super::eval::EvalState>,
    list_base: Option<u32>,
    scissor: Option<ScissorState>,
    fog: Option<super::fog::FogState>,
    pixel_mode: Option<(super::pixel_transfer::PixelTransfer, u32, super::imaging::PixelModeParams)>,
    texture: Option<SavedTexture>,
    /// GL_MULTISAMPLE_BIT: its four enables and the sample coverage.
    multisample: Option<([(u32, bool); 4], (f32, bool))>,
}

/// GL_TEXTURE_BIT's copy.
struct SavedTexture {
    active: usize,
    units: [TexUnit; MAX_UNITS],
    /// The bound objects' state per unit and target: name, parameters,
    /// priority, GENERATE_MIPMAP.
    objects: Vec<(u32, usize, Params, f32, bool)>,
}

#[derive(Default)]
pub struct AttribStacks {
    pub server: Vec<Saved>,
    pub client: Vec<ClientAttrib>,
}

/// One glPushClientAttrib entry. The pixel-store group includes the pixel
/// pack and unpack buffer bindings (ARB_pixel_buffer_object's state table:
/// attribute "pixel-store"); the vertex-array group the array buffer
/// bindings (GL 1.5, table 6.8).
pub struct ClientAttrib {
    mask: u32,
    store: super::pixels::PixelStore,
    pixel_buffers: [u32; 2],
    arrays: super::arrays::ClientArrays,
}

impl Context {
    pub fn push_attrib(&mut self, mask: u32) {
        if self.attrib.server.len() >= MAX_ATTRIB_STACK_DEPTH {
            return self.set_error(GL_STACK_OVERFLOW);
        }
        let s = self.save_attrib(mask);
        self.attrib.server.push(s);
    }

    pub fn pop_attrib(&mut self) {
        match self.attrib.server.pop() {
            Some(s) => self.restore_attrib(s),
            None => self.set_error(GL_STACK_UNDERFLOW),
        }
    }

    /// A copy of the groups in `mask` (glPushAttrib, wglCopyContext).
    pub fn save_attrib(&self, mask: u32) -> Saved {
        let has = |bit: u32| mask & bit != 0;
        Saved {
            mask,
            current: has(GL_CURRENT_BIT).then_some(self.current),
            point: has(GL_POINT_BIT).then(|| self.point.clone()),
            line: has(GL_LINE_BIT).then(|| self.line.clone()),
            polygon: has(GL_POLYGON_BIT).then(|| self.polygon.clone()),
            stipple: has(GL_POLYGON_STIPPLE_BIT).then_some(self.polygon.stipple_pattern),
            lighting: has(GL_LIGHTING_BIT).then(|| (self.lighting.clone(), self.shade_model)),
            depth: has(GL_DEPTH_BUFFER_BIT).then(|| self.depth.clone()),
            accum_clear: has(GL_ACCUM_BUFFER_BIT).then_some(self.accum_clear),
            stencil: has(GL_STENCIL_BUFFER_BIT).then(|| self.stencil.clone()),
            viewport: has(GL_VIEWPORT_BIT).then(|| self.viewport.clone()),
            transform: has(GL_TRANSFORM_BIT)
                .then(|| (self.transform.mode, self.user_clip.clone(), self.lighting.normalize, self.lighting.rescale_normal)),
            enables: has(GL_ENABLE_BIT).then(|| all_caps().into_iter().filter_map(|c| self.is_enabled(c).map(|on| (c, on))).collect()),
            color_buffer: has(GL_COLOR_BUFFER_BIT).then(|| self.color_buffer.clone()),
            hints: has(GL_HINT_BIT).then(|| self.hints.clone()),
            eval: has(GL_EVAL_BIT).then(|| self.eval.clone()),
            list_base: has(GL_LIST_BIT).then_some(self.lists.base),
            scissor: has(GL_SCISSOR_BIT).then(|| self.scissor.clone()),
            fog: has(GL_FOG_BIT).then(|| self.fog.clone()),
            pixel_mode: has(GL_PIXEL_MODE_BIT).then(|| (self.pixel.clone(), self.pixel_read_buffer, self.imaging.pixel_mode_params())),
            texture: has(GL_TEXTURE_BIT).then(|| self.save_texture()),
            multisample: has(GL_MULTISAMPLE_BIT).then(|| {
                let caps = [GL_MULTISAMPLE, GL_SAMPLE_ALPHA_TO_COVERAGE, GL_SAMPLE_ALPHA_TO_ONE, GL_SAMPLE_COVERAGE];
                (caps.map(|c| (c, self.is_enabled(c) == Some(true))), self.color_buffer.sample_coverage)
            }),
        }
    }

    fn save_texture(&self) -> SavedTexture {
        let t = &self.texture;
        let mut objects = Vec::new();
        for unit in &t.units {
            for (target, &name) in unit.bound.iter().enumerate() {
                let o = if name == 0 { Some(&t.defaults[target]) } else { t.objects.get(&name) };
                if let Some(o) = o {
                    objects.push((name, target, o.params.clone(), o.priority, o.generate_mipmap));
                }
            }
        }
        SavedTexture { active: t.active, units: t.units.clone(), objects }
    }

    fn restore_texture(&mut self, s: SavedTexture) {
        let t = &mut self.texture;
        t.active = s.active;
        t.units = s.units;
        for unit in t.units.iter_mut() {
            for name in unit.bound.iter_mut() {
                if *name != 0 && !t.objects.contains_key(name) {
                    *name = 0;
                }
            }
        }
        for (name, target, params, priority, generate_mipmap) in s.objects {
            let o = if name == 0 { Some(&mut t.defaults[target]) } else { t.objects.get_mut(&name) };
            if let Some(o) = o {
                o.params = params;
                o.priority = priority;
                o.generate_mipmap = generate_mipmap;
            }
        }
    }

    /// Puts saved groups back (glPopAttrib, wglCopyContext).
    pub fn restore_attrib(&mut self, s: Saved) {
        if let Some(v) = s.current {
            self.current = v;
        }
        if let Some(v) = s.point {
            self.point = v;
        }
        if let Some(v) = s.line {
            self.line = v;
        }
        if let Some(v) = s.polygon {
            // The stipple pattern is its own group.
            let pattern = self.polygon.stipple_pattern;
            self.polygon = v;
            self.polygon.stipple_pattern = pattern;
        }
        if let Some(v) = s.stipple {
            self.polygon.stipple_pattern = v;
        }
        if let Some((v, shade)) = s.lighting {
            // GL_NORMALIZE and GL_RESCALE_NORMAL belong to the transform group.
            let (n, r) = (self.lighting.normalize, self.lighting.rescale_normal);
            self.lighting = v;
            self.lighting.normalize = n;
            self.lighting.rescale_normal = r;
            self.shade_model = shade;
        }
        if let Some(v) = s.depth {
            self.depth = v;
        }
        if let Some(v) = s.accum_clear {
            self.accum_clear = v;
        }
        if let Some(v) = s.stencil {
            self.stencil = v;
        }
        if let Some(v) = s.viewport {
            self.viewport = v;
        }
        if let Some((mode, clip, n, r)) = s.transform {
            self.transform.mode = mode;
            self.user_clip = clip;
            self.lighting.normalize = n;
            self.lighting.rescale_normal = r;
        }
        if let Some(v) = s.color_buffer {
            self.color_buffer = v;
        }
        if let Some(v) = s.hints {
            self.hints = v;
        }
        if let Some(v) = s.eval {
            self.eval = v;
        }
        if let Some(v) = s.list_base {
            self.lists.base = v;
        }
        if let Some(v) = s.scissor {
            self.scissor = v;
        }
        if let Some(v) = s.fog {
            self.fog = v;
        }
        if let Some((v, read_buffer, imaging)) = s.pixel_mode {
            self.pixel = v;
            self.pixel_read_buffer = read_buffer;
            self.imaging.set_pixel_mode_params(imaging);
        }
        if let Some(v) = s.texture {
            self.restore_texture(v);
        }
        if let Some((caps, coverage)) = s.multisample {
            for (cap, on) in caps {
                self.set_enabled(cap, on);
            }
            self.color_buffer.sample_coverage = coverage;
        }
        if let Some(list) = s.enables {
            for (cap, on) in list {
                self.set_enabled(cap, on);
            }
        }
        let _ = s.mask;
        self.dirty |= DIRTY_ALL;
    }

    pub fn push_client_attrib(&mut self, mask: u32) {
        if self.attrib.client.len() >= MAX_ATTRIB_STACK_DEPTH {
            return self.set_error(GL_STACK_OVERFLOW);
        }
        let arrays = self.client_arrays();
        let pixel_buffers = [self.buffers.pixel_pack, self.buffers.pixel_unpack];
        self.attrib.client.push(ClientAttrib { mask, store: self.pixel_store, pixel_buffers, arrays });
    }

    pub fn pop_client_attrib(&mut self) {
        let Some(ClientAttrib { mask, store, pixel_buffers, arrays }) = self.attrib.client.pop() else {
            return self.set_error(GL_STACK_UNDERFLOW);
        };
        if mask & GL_CLIENT_PIXEL_STORE_BIT != 0 {
            self.pixel_store = store;
            // A buffer deleted since the push comes back unbound, as its
            // deletion left the binding.
            let live = |b: u32| if b != 0 && !self.buffers.is_buffer(b) { 0 } else { b };
            let [pack, unpack] = pixel_buffers.map(live);
            self.buffers.pixel_pack = pack;
            self.buffers.pixel_unpack = unpack;
        }
        if mask & super::arrays::GL_CLIENT_VERTEX_ARRAY_BIT != 0 {
            self.restore_client_arrays(arrays);
        }
    }
}
