//! A GL context: all of its state, the error flag (GL 1.5 section 2.5), and
//! the path every display-listable command takes (`submit`).

use super::command::Command;
use super::enums::*;
use super::state::*;
use super::{arrays, attrib, begin_end, buffers, clip_plane, enable, eval, fog, lighting, lists, matrix, pixels, queries, select, texture, validate};
use crate::framebuffer::{Config, Framebuffer, Present};

pub struct Context {
    /// The error flag: the first error since the last glGetError.
    error: u32,
    pub color_buffer: ColorBufferState,
    pub depth: DepthState,
    pub stencil: StencilState,
    pub viewport: ViewportState,
    pub scissor: ScissorState,
    pub polygon: PolygonState,
    pub shade_model: u32,
    pub hints: HintState,
    pub current: CurrentState,
    pub lighting: lighting::LightingState,
    /// glClearAccum's value, clamped to [-1, 1].
    pub accum_clear: [f32; 4],
    /// Render mode, selection and feedback (section 5.2, 5.3).
    pub select: select::SelectState,
    /// Evaluator maps and grids (section 5.1).
    pub eval: eval::EvalState,
    pub user_clip: clip_plane::UserClipState,
    /// glPushAttrib / glPushClientAttrib stacks.
    pub attrib: attrib::AttribStacks,
    pub fog: fog::FogState,
    /// The surface keeps a back buffer (GLX/wgl double-buffered configs):
    /// GL_BACK exists, and is the initial draw and read buffer.
    pub double_buffered: bool,
    /// glReadBuffer (in the pixel-mode group).
    pub pixel_read_buffer: u32,
    pub line: LineState,
    pub point: PointState,
    /// Capabilities glEnable stores whose rendering is not implemented yet.
    pub other_caps: enable::OtherCaps,
    pub transform: matrix::Transform,
    /// Primitive assembly while between glBegin and glEnd.
    pub prim: Option<begin_end::Assembly>,
    /// The batched vertex path (`begin_end::Assembly::fast`) and the
    /// specialized array loops (`arrays`, `draw_specialized`) may serve
    /// primitives; tests turn them off to compare them with the general
    /// paths (the reference path never uses the batched vertex path).
    pub vertex_batching: bool,
    /// The current entry point's caller masked every floating-point
    /// exception (set by `api::dispatch::with_current`); glBegin keeps it
    /// for the primitive (`Context::fp_trusted`).
    pub fp_caller_masked: bool,
    /// Round 16: the open primitive is on the batched path's plain case
    /// (`Context::plain_batch`), was begun by a caller that masked every
    /// floating-point exception (`fp_trusted`), and no list is being
    /// compiled: set at glBegin, cleared at glEnd, none of which can
    /// change in between. The `list` entry points test this one flag
    /// (`api::dispatch::with_current_list`) instead of the guard's, the
    /// list's and the batch's tests per vertex.
    pub plain_vertex: bool,
    /// Round 20: a list is being compiled with GL_COMPILE (nothing
    /// executes) and its recorded glBegin came from a caller that masked
    /// every floating-point exception: until the recorded glEnd (or
    /// glEndList), the `list` entry points record their command straight
    /// into the list (`Context::record_compiled`) without the guard's
    /// read of the environment, as `plain_vertex` does for an executed
    /// primitive. Set and cleared by `Context::submit`,
    /// `record_compiled` and `end_list`.
    pub compile_fast: bool,
    pub lists: lists::Lists,
    pub pixel_store: pixels::PixelStore,
    /// Vertex arrays (client state, GL_CLIENT_VERTEX_ARRAY_BIT).
    pub arrays: arrays::ArrayState,
    /// Buffer objects and their bindings.
    pub buffers: buffers::Buffers,
    /// Occlusion query objects.
    pub queries: queries::Queries,
    /// Pixel transfer, maps and zoom (GL_PIXEL_MODE_BIT).
    pub pixel: super::pixel_transfer::PixelTransfer,
    /// ARB_imaging's tables, filters, histogram and minmax.
    pub imaging: super::imaging::Imaging,
    /// The current raster position (section 2.13).
    pub raster: super::raster_pos::RasterPos,
    pub texture: texture::TextureState,
    /// The framebuffer this context draws into and reads from.
    pub fb: Framebuffer,
    /// Binned triangles stay pending across draw calls until something
    /// needs the framebuffer (render::tile, `sync_render`). Set for
    /// contexts the window-system APIs create, whose every framebuffer
    /// access goes through the entry points; off (shaded at the end of
    /// each draw call) for contexts driven directly, as the tests do.
    pub defer_render: bool,
    /// Where glFlush/glFinish deliver the image (set by the window system).
    pub surface: Option<Box<dyn Present>>,
    /// A window-system drawable's framebuffers, shared with the other
    /// contexts bound to it: swapped into `fb` (and `read_fb`) for the
    /// length of each call (winsys::bound). None: `fb` is the context's own.
    pub bound: Option<crate::framebuffer::shared::Binding>,
    /// The read drawable's framebuffer when it is not the draw one
    /// (glXMakeContextCurrent): glReadPixels, glCopyPixels and
    /// glCopyTexImage read it (`read_source`).
    pub read_fb: Option<Framebuffer>,
    /// Dirty bits (validate::DIRTY_*): derived state to recompute.
    pub dirty: u32,
    pub derived: validate::Derived,
    /// The share group whose display lists, textures and buffer objects
    /// this context uses (gl::share); None: its own.
    pub share: Option<std::sync::Arc<super::share::ShareGroup>>,
    /// The viewport and scissor are set to the surface size at the first
    /// MakeCurrent only (GL 1.5 section 2.11.1; GLX/WGL say the same).
    pub sized_once: bool,
    /// Framebuffer and renderbuffer objects (framebuffer_object).
    pub fbo: super::framebuffer_object::FboState,
    /// Sampler objects and their unit bindings (texture::sampler).
    pub samplers: super::texture::sampler::Samplers,
}

/// The workers may still be shading a batch into this context's
/// framebuffer (render::tile): wait for them before it is freed.
impl Drop for Context {
    fn drop(&mut self) {
        self.sync_render();
    }
}

impl Context {
    pub fn new(config: Config) -> Context {
        Context {
            error: GL_NO_ERROR,
            color_buffer: Default::default(),
            depth: Default::default(),
            stencil: Default::default(),
            viewport: Default::default(),
            scissor: Default::default(),
            polygon: Default::default(),
            shade_model: GL_SMOOTH,
            hints: Default::default(),
            current: Default::default(),
            lighting: Default::default(),
            accum_clear: [0.0; 4],
            select: Default::default(),
            eval: Default::default(),
            user_clip: Default::default(),
            attrib: Default::default(),
            fog: Default::default(),
            double_buffered: false,
            pixel_read_buffer: GL_FRONT,
            line: Default::default(),
            point: Default::default(),
            // GL_MULTISAMPLE starts enabled (GL 1.5 table 6.17); with one
            // sample per pixel it changes nothing, but glIsEnabled says so.
            other_caps: enable::OtherCaps([GL_MULTISAMPLE].into_iter().collect()),
            transform: matrix::Transform::new(),
            prim: None,
            vertex_batching: true,
            fp_caller_masked: false,
            plain_vertex: false,
            compile_fast: false,
            lists: Default::default(),
            pixel_store: Default::default(),
            arrays: Default::default(),
            buffers: Default::default(),
            queries: Default::default(),
            pixel: Default::default(),
            imaging: Default::default(),
            raster: Default::default(),
            texture: Default::default(),
            fb: Framebuffer::new(config),
            defer_render: false,
            surface: None,
            bound: None,
            read_fb: None,
            dirty: validate::DIRTY_ALL,
            derived: validate::Derived::default(),
            share: None,
            sized_once: false,
            fbo: Default::default(),
            samplers: Default::default(),
        }
    }

    /// Records an error unless one is already pending (section 2.5: the
    /// flag keeps the first error until it is read).
    pub fn set_error(&mut self, e: u32) {
        if self.error == GL_NO_ERROR {
            self.error = e;
        }
    }

    /// glGetError.
    pub fn take_error(&mut self) -> u32 {
        std::mem::replace(&mut self.error, GL_NO_ERROR)
    }

    pub fn in_begin_end(&self) -> bool {
        self.prim.is_some()
    }

    /// A display-listable command: compiled into the open list, executed,
    /// or both (GL 1.5 section 5.4).
    /// Shades the triangles binned for tiles (render::tile): before
    /// anything reads or writes the framebuffer, or changes which buffer
    /// is drawn. Cheap when nothing is pending.
    #[inline]
    pub fn sync_render(&mut self) {
        // Vertices still queued in an open primitive (a frame shown
        // between glBegin and glEnd) are drawn first, as they were before
        // the queue existed.
        if self.prim.is_some() {
            self.flush_vertices();
        }
        crate::render::tile::sync(&self.derived.render, &mut self.fb);
    }

    pub fn submit(&mut self, cmd: Command) {
        match self.lists.compile_mode() {
            None => self.execute(&cmd),
            Some(GL_COMPILE) => {
                // The recorded primitive's commands may skip the guard
                // when its glBegin's caller masked every exception (this
                // call's environment, read by `with_current`).
                match cmd {
                    Command::Begin(_) => self.compile_fast = self.fp_caller_masked,
                    Command::End => self.compile_fast = false,
                    _ => {}
                }
                self.lists.record(cmd)
            }
            Some(_) => {
                self.lists.record(cmd.clone());
                self.execute(&cmd);
            }
        }
    }

    /// glFlush / glFinish: rendering is synchronous, so both just deliver
    /// the front buffer to the surface: always on a single-buffered
    /// surface, and on a double-buffered one when the front buffer may have
    /// been drawn into since it was last shown (glDrawBuffer(GL_FRONT)).
    pub fn flush(&mut self) {
        self.sync_render();
        if self.double_buffered && !self.window_fb().front_dirty {
            return;
        }
        self.window_fb_mut().front_dirty = false;
        let fb = self.fbo.parked.as_ref().unwrap_or(&self.fb);
        if let Some(s) = self.surface.as_mut() {
            s.present(fb);
        }
    }

    /// SwapBuffers: the back buffer becomes the front one (a copy: see
    /// `framebuffer`) and is presented. No effect on a single-buffered
    /// surface.
    pub fn swap_buffers(&mut self) {
        self.sync_render();
        if !self.double_buffered {
            return;
        }
        self.window_fb_mut().swap_buffers();
        let fb = self.fbo.parked.as_ref().unwrap_or(&self.fb);
        if let Some(s) = self.surface.as_mut() {
            s.present(fb);
        }
    }

    /// The window system says whether the surface is double-buffered;
    /// draw and read buffers start at BACK there (4.2.1, 4.3.2).
    pub fn set_double_buffered(&mut self, double: bool) {
        if self.fb.set_double_buffered(double).is_err() {
            // No memory for a back buffer: stay single-buffered.
            return self.set_error(GL_OUT_OF_MEMORY);
        }
        self.double_buffered = double;
        let initial = if double { GL_BACK } else { GL_FRONT };
        self.color_buffer.draw_buffer = initial;
        self.pixel_read_buffer = initial;
        self.sync_draw_buffer();
        self.dirty |= validate::DIRTY_FRAGMENT;
    }

    /// Called by the window system when the surface is (re)bound with a size.
    pub fn surface_resized(&mut self, width: i32, height: i32) {
        if !self.sized_once {
            self.sized_once = true;
            self.viewport.width = width;
            self.viewport.height = height;
            self.scissor.width = width;
            self.scissor.height = height;
        }
        self.dirty |= validate::DIRTY_ALL;
    }
}
