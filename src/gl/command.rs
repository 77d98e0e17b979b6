//! The display-listable commands, as values. An entry point converts its C
//! arguments into one of these (so glColor3ub and glColor4fv both become
//! `Color`), then [`Context::submit`] records it in a display list,
//! executes it, or both. Display lists keep the per-vertex ones packed
//! and the rest as these values (gl::lists).

use super::context::Context;
use super::enums::*;
use super::draw_pixels::{Bitmap, PixelRect};
use glam::DMat4;
use std::rc::Rc;

#[derive(Clone, Debug, PartialEq)]
pub enum Command {
    // Section 2.6: Begin/End and vertex attributes.
    Begin(u32),
    End,
    Vertex([f32; 4]),
    Color([f32; 4]),
    Normal([f32; 3]),
    /// glIndex: stored, no effect in RGBA mode.
    Index(f32),
    FogCoord(f32),
    /// glSecondaryColor3: RGB and alpha 1.
    SecondaryColor([f32; 4]),
    // Section 2.14: lighting. Parameters padded to 4 values.
    Light(u32, u32, [f32; 4]),
    LightModel(u32, [f32; 4]),
    Material(u32, u32, [f32; 4]),
    ColorMaterial(u32, u32),
    /// glRect: x1, y1, x2, y2 (section 2.10).
    Rect([f32; 4]),
    // Section 2.11: coordinate transformations.
    MatrixMode(u32),
    LoadIdentity,
    /// Boxed: a matrix is the largest payload, and every command (each
    /// glVertex) would otherwise be as large as it.
    LoadMatrix(Box<DMat4>),
    MultMatrix(Box<DMat4>),
    Ortho([f64; 6]),
    Frustum([f64; 6]),
    Translate([f64; 3]),
    Rotate(f64, [f64; 3]),
    Scale([f64; 3]),
    PushMatrix,
    PopMatrix,
    Viewport(i32, i32, i32, i32),
    DepthRange(f64, f64),
    // Section 2.14.7, 3.5: shading and polygons.
    ShadeModel(u32),
    CullFace(u32),
    FrontFace(u32),
    // Sections 3.3, 3.4: points and lines.
    PointSize(f32),
    LineWidth(f32),
    /// glLineStipple(factor, pattern).
    LineStipple(i32, u16),
    // Section 4.1: fragment operations.
    Scissor(i32, i32, i32, i32),
    AlphaFunc(u32, f32),
    StencilFunc(u32, i32, u32),
    StencilOp(u32, u32, u32),
    DepthFunc(u32),
    /// glBlendFunc and glBlendFuncSeparate: src RGB, dst RGB, src alpha, dst alpha.
    BlendFunc([u32; 4]),
    BlendColor([f32; 4]),
    BlendEquation(u32),
    LogicOp(u32),
    // Section 4.2: whole-framebuffer operations.
    ColorMask([bool; 4]),
    DepthMask(bool),
    StencilMask(u32),
    ClearColor([f32; 4]),
    ClearDepth(f64),
    ClearStencil(i32),
    Clear(u32),
    ClearAccum([f32; 4]),
    Accum(u32, f32),
    // Section 5: enables, hints, display lists.
    Enable(u32),
    Disable(u32),
    Hint(u32, u32),
    CallList(u32),
    /// glCallLists: names before the list base is added (added when run).
    CallLists(Vec<u32>),
    ListBase(u32),
    // Section 4.1.6: occlusion queries (compiled into lists).
    BeginQuery(u32, u32),
    EndQuery(u32),
    ClipPlane(u32, [f64; 4]),
    DrawBuffer(u32),
    ReadBuffer(u32),
    /// Colour-index mode state: stored, no effect on an RGBA surface.
    IndexMask(u32),
    ClearIndex(f32),
    /// glSampleCoverage: stored; softgl's framebuffers have no multisample
    /// buffer, where the spec makes coverage have no effect (3.2.1).
    SampleCoverage(f32, bool),
    /// glPointParameter(pname, up to 3 values).
    PointParameter(u32, [f32; 3]),
    /// glFog(pname, values).
    Fog(u32, [f32; 4]),
    PushAttrib(u32),
    PopAttrib,
    // Sections 2.6.2 and 3.5: edge flags and polygon modes.
    EdgeFlag(bool),
    PolygonMode(u32, u32),
    PolygonOffset(f32, f32),
    PolygonStipple(Box<[u32; 32]>),
    // Section 5.2, 5.3: the name stack and feedback markers.
    NameStack(super::select::NameOp),
    // Section 5.1: evaluators. Map points are copied at the call.
    Map { target: u32, u: (f32, f32), uorder: i32, v: Option<((f32, f32), i32)>, points: Vec<f32> },
    EvalCoord(f32, Option<f32>),
    EvalPoint(i32, Option<i32>),
    MapGrid(i32, (f32, f32), Option<(i32, (f32, f32))>),
    EvalMesh1(u32, i32, i32),
    EvalMesh2(u32, i32, i32, i32, i32),
    PassThrough(f32),
    // Sections 2.13, 3.6, 3.7, 4.3.3: raster position and pixel rectangles.
    /// glRasterPos: object coordinates.
    RasterPos([f32; 4]),
    /// glWindowPos: window x, y and depth.
    WindowPos([f32; 3]),
    PixelTransfer(u32, f64),
    /// glPixelMap: the map and its entries as floats.
    PixelMap(u32, Vec<f32>),
    PixelZoom(f32, f32),
    /// glBitmap, unpacked when built.
    Bitmap(Rc<Bitmap>),
    /// glDrawPixels, unpacked when built.
    DrawPixels(Rc<PixelRect>),
    /// glCopyPixels(x, y, width, height, type).
    CopyPixels(i32, i32, i32, i32, u32),
    /// A command whose arguments failed a check made when it was built
    /// (unpacking needs a valid format and type): executing it raises the
    /// error, so a display list raises it when called, as the spec says.
    Error(u32),
    // Section 3.8 and 2.11.4: texturing. TexCoord(unit enum, strq).
    TexCoord(u32, [f32; 4]),
    ActiveTexture(u32),
    BindTexture(u32, u32),
    /// glTexParameter(target, pname, values as floats).
    TexParameter(u32, u32, [f32; 4]),
    /// glTexEnv(target, pname, values as floats).
    TexEnv(u32, u32, [f32; 4]),
    /// glTexGen(coord, pname, values).
    TexGen(u32, u32, [f64; 4]),
    TexImage(Box<super::texture::TexImageCmd>),
    TexSubImage(Box<super::texture::TexSubImageCmd>),
    CopyTex(Box<super::texture::CopyTexCmd>),
    PrioritizeTextures(Vec<(u32, f32)>),
    // Section 3.6.3, ARB_imaging: colour tables, convolution filters,
    // histogram and minmax (client data unpacked when built).
    Imaging(Box<super::imaging::ImagingCmd>),
}

impl Command {
    /// Can this command run while binned triangles are pending
    /// (render::tile)? True for commands that neither read nor write the
    /// framebuffer nor change which buffer is drawn: vertices, primitives
    /// (they bin or shade in order themselves), transforms and the state
    /// binned triangles copy. Every other command shades the batch first.
    pub fn leaves_framebuffer(&self) -> bool {
        use Command::*;
        matches!(
            self,
            Begin(_) | End | Vertex(_) | Color(_) | Normal(_) | Index(_) | FogCoord(_) | SecondaryColor(_) | TexCoord(..) | EdgeFlag(_)
                | Light(..) | LightModel(..) | Material(..) | ColorMaterial(..) | Rect(_)
                | MatrixMode(_) | LoadIdentity | LoadMatrix(_) | MultMatrix(_) | Ortho(_) | Frustum(_) | Translate(_) | Rotate(..) | Scale(_) | PushMatrix | PopMatrix
                | Viewport(..) | DepthRange(..) | ShadeModel(_) | CullFace(_) | FrontFace(_) | PointSize(_) | LineWidth(_) | LineStipple(..) | Scissor(..)
                | AlphaFunc(..) | StencilFunc(..) | StencilOp(..) | DepthFunc(_) | BlendFunc(_) | BlendColor(_) | BlendEquation(_) | LogicOp(_)
                | ColorMask(_) | DepthMask(_) | StencilMask(_) | ClearColor(_) | ClearDepth(_) | ClearStencil(_) | Enable(_) | Disable(_) | Hint(..)
                | CallList(_) | CallLists(_) | ListBase(_) | ClipPlane(..) | PolygonMode(..) | PolygonOffset(..) | PolygonStipple(_) | PointParameter(..)
                | Fog(..) | ActiveTexture(_) | BindTexture(..) | TexEnv(..) | TexGen(..) | EvalCoord(..) | EvalPoint(..) | MapGrid(..) | EvalMesh1(..) | EvalMesh2(..)
        )
    }

    /// May this command appear between Begin and End (GL 1.5 section 2.6.3)?
    pub fn allowed_in_begin_end(&self) -> bool {
        matches!(
            self,
            Command::Vertex(_)
                | Command::Color(_)
                | Command::Normal(_)
                | Command::Index(_)
                | Command::FogCoord(_)
                | Command::SecondaryColor(_)
                | Command::Material(..)
                | Command::EvalCoord(..)
                | Command::EdgeFlag(_)
                | Command::EvalPoint(..)
                | Command::TexCoord(..)
                | Command::End
                | Command::CallList(_)
                | Command::CallLists(_)
        )
    }
}

impl Context {
    /// glColor: the current colour, and the material properties colour
    /// material tracks (2.14.3).
    #[inline]
    pub fn set_color(&mut self, c: [f32; 4]) {
        // One 16-byte store, forwarded to the next vertex's load.
        super::begin_end::store4(&mut self.current.color, glam::Vec4::new(c[0], c[1], c[2], c[3]));
        if self.lighting.color_material {
            self.apply_color_material();
        }
    }

    /// `submit` for the entry points (api::table's `list` kind), inlined
    /// into each: the command's variant is known there, so outside list
    /// compilation the per-vertex commands reach their setter directly,
    /// with no match over every command and no drop of a generic value
    /// (immediate mode's hot path: about 60 instructions a call less).
    #[inline(always)]
    pub fn submit_direct(&mut self, cmd: Command) {
        if self.lists.compile_mode().is_some() {
            return self.submit(cmd);
        }
        // The per-vertex variants own nothing: held in ManuallyDrop, they
        // skip the out-of-line drop of a generic Command that a plain
        // match keeps; every other variant is dropped as usual.
        let cmd = std::mem::ManuallyDrop::new(cmd);
        match &*cmd {
            Command::Vertex(v) => self.vertex(*v),
            Command::Color(c) => self.set_color(*c),
            Command::Normal(n) => self.current.normal = *n,
            Command::TexCoord(unit, v) => self.tex_coord(*unit, *v),
            _ => self.execute(&std::mem::ManuallyDrop::into_inner(cmd)),
        }
    }

    /// [`Context::submit_direct`] while `plain_vertex` holds (no list is
    /// being compiled): a vertex goes straight to the batched path's
    /// plain case, as `vertex` would send it (round 16).
    #[inline(always)]
    pub(crate) fn submit_plain(&mut self, cmd: Command) {
        debug_assert!(self.plain_vertex && self.plain_batch() && self.lists.compile_mode().is_none());
        // As in `submit_direct`: a vertex owns nothing, and held in
        // ManuallyDrop skips the out-of-line drop of a generic Command.
        let cmd = std::mem::ManuallyDrop::new(cmd);
        match &*cmd {
            Command::Vertex(v) => self.vertex_fast::<true>(*v),
            _ => self.submit_direct(std::mem::ManuallyDrop::into_inner(cmd)),
        }
    }

    /// [`Context::submit_direct`] while `compile_fast` holds: the command
    /// goes into the list being compiled with GL_COMPILE, inlined into
    /// the entry point so that a vertex's or colour's words are stored
    /// from registers (round 20: the out-of-line `submit` and
    /// `List::push` read the 64-byte command back from memory, a
    /// store-forwarding stall a call). The recorded glEnd ends the fast
    /// path, as `submit` does.
    #[inline(always)]
    pub(crate) fn record_compiled(&mut self, cmd: Command) {
        debug_assert!(self.compile_fast && self.lists.compile_mode() == Some(GL_COMPILE));
        // Matched here, where it was built (see `List::push_compact`),
        // not behind `Lists::record`'s `Option` check: through `record`
        // the same compile took 18 ms instead of 14 (the match stayed a
        // jump table). The compact variants own nothing, so ManuallyDrop
        // skips a generic drop.
        let cmd = std::mem::ManuallyDrop::new(cmd);
        if matches!(*cmd, Command::End) {
            self.compile_fast = false;
        }
        if !self.lists.record_compact(&cmd) {
            self.lists.record(std::mem::ManuallyDrop::into_inner(cmd));
        }
    }

    /// Executes one command against the context.
    pub fn execute(&mut self, cmd: &Command) {
        // The per-vertex commands first: legal anywhere, so no Begin/End
        // check (immediate mode's hot path).
        match cmd {
            Command::Vertex(v) => return self.vertex(*v),
            Command::Color(c) => return self.set_color(*c),
            Command::Normal(n) => {
                self.current.normal = *n;
                return;
            }
            _ => {}
        }
        // glClear and glAccum sync themselves unless they record their
        // work in the rasterizer's batch (round 13).
        if !cmd.leaves_framebuffer() && !matches!(cmd, Command::Clear(_) | Command::Accum(..)) {
            self.sync_render();
        }
        if self.in_begin_end() && !cmd.allowed_in_begin_end() {
            self.set_error(GL_INVALID_OPERATION);
            return;
        }
        use Command::*;
        match cmd {
            Begin(mode) => self.begin(*mode),
            End => self.end(),
            Vertex(v) => self.vertex(*v),
            Color(c) => self.set_color(*c),
            Normal(n) => self.current.normal = *n,
            Index(i) => self.current.index = *i,
            FogCoord(f) => self.current.fog_coord = *f,
            SecondaryColor(c) => self.current.secondary_color = *c,
            Light(l, pname, v) => self.light(*l, *pname, *v),
            LightModel(pname, v) => self.light_model(*pname, *v),
            Material(face, pname, v) => self.material(*face, *pname, *v),
            ColorMaterial(face, mode) => self.color_material(*face, *mode),
            Rect([x1, y1, x2, y2]) => {
                self.begin(GL_POLYGON);
                for v in [[*x1, *y1], [*x2, *y1], [*x2, *y2], [*x1, *y2]] {
                    self.vertex([v[0], v[1], 0.0, 1.0]);
                }
                self.end();
            }
            MatrixMode(m) => self.matrix_mode(*m),
            LoadIdentity => self.load_matrix(DMat4::IDENTITY),
            LoadMatrix(m) => self.load_matrix(**m),
            MultMatrix(m) => self.mult_matrix(**m),
            Ortho(p) => self.ortho(*p),
            Frustum(p) => self.frustum(*p),
            Translate(t) => self.mult_matrix(DMat4::from_translation((*t).into())),
            Rotate(angle, axis) => self.rotate(*angle, *axis),
            Scale(s) => self.mult_matrix(DMat4::from_scale((*s).into())),
            PushMatrix => self.push_matrix(),
            PopMatrix => self.pop_matrix(),
            Viewport(x, y, w, h) => self.set_viewport(*x, *y, *w, *h),
            DepthRange(n, f) => self.depth_range(*n, *f),
            ShadeModel(m) => self.set_shade_model(*m),
            CullFace(m) => self.cull_face(*m),
            FrontFace(m) => self.front_face(*m),
            PointSize(s) => {
                if !(*s > 0.0) {
                    return self.set_error(GL_INVALID_VALUE);
                }
                self.point.size = *s;
                self.dirty |= super::validate::DIRTY_RASTER;
            }
            LineWidth(w) => {
                if !(*w > 0.0) {
                    return self.set_error(GL_INVALID_VALUE);
                }
                self.line.width = *w;
                self.dirty |= super::validate::DIRTY_RASTER;
            }
            LineStipple(factor, pattern) => {
                self.line.stipple_repeat = (*factor).clamp(1, 256);
                self.line.stipple_pattern = *pattern;
                self.dirty |= super::validate::DIRTY_RASTER;
            }
            Scissor(x, y, w, h) => self.set_scissor(*x, *y, *w, *h),
            AlphaFunc(f, r) => self.alpha_func(*f, *r),
            StencilFunc(f, r, m) => self.stencil_func(*f, *r, *m),
            StencilOp(a, b, c) => self.stencil_op(*a, *b, *c),
            DepthFunc(f) => self.depth_func(*f),
            BlendFunc(f) => self.blend_func(*f),
            BlendColor(c) => {
                self.color_buffer.blend_color = c.map(|v| v.clamp(0.0, 1.0));
                self.dirty |= super::validate::DIRTY_FRAGMENT;
            }
            BlendEquation(m) => self.blend_equation(*m),
            LogicOp(op) => self.logic_op(*op),
            ColorMask(m) => {
                self.color_buffer.write_mask = *m;
                self.dirty |= super::validate::DIRTY_FRAGMENT;
            }
            DepthMask(m) => {
                self.depth.write_mask = *m;
                self.dirty |= super::validate::DIRTY_FRAGMENT;
            }
            StencilMask(m) => {
                self.stencil.write_mask = *m;
                self.dirty |= super::validate::DIRTY_FRAGMENT;
            }
            ClearColor(c) => self.color_buffer.clear = c.map(|v| v.clamp(0.0, 1.0)),
            ClearDepth(d) => self.depth.clear = d.clamp(0.0, 1.0),
            ClearStencil(s) => self.stencil.clear = *s,
            Clear(mask) => self.clear(*mask),
            ClearAccum(c) => self.accum_clear = c.map(|v| v.clamp(-1.0, 1.0)),
            Accum(op, value) => self.accum(*op, *value),
            Enable(cap) => self.set_enabled(*cap, true),
            Disable(cap) => self.set_enabled(*cap, false),
            Hint(target, mode) => self.hint(*target, *mode),
            CallList(n) => self.call_list(*n),
            CallLists(names) => self.call_lists(names),
            ListBase(b) => self.lists.base = *b,
            BeginQuery(target, id) => self.begin_query(*target, *id),
            EndQuery(target) => self.end_query(*target),
            ClipPlane(p, eq) => self.clip_plane(*p, *eq),
            DrawBuffer(m) => self.draw_buffer(*m),
            ReadBuffer(m) => self.read_buffer(*m),
            IndexMask(m) => self.color_buffer.index_mask = *m,
            ClearIndex(c) => self.color_buffer.clear_index = *c,
            SampleCoverage(v, inv) => self.color_buffer.sample_coverage = (v.clamp(0.0, 1.0), *inv),
            PointParameter(pname, v) => self.point_parameter(*pname, *v),
            Fog(pname, v) => self.fog(*pname, *v),
            PushAttrib(mask) => self.push_attrib(*mask),
            PopAttrib => self.pop_attrib(),
            EdgeFlag(f) => self.current.edge_flag = *f,
            PolygonMode(face, mode) => self.polygon_mode(*face, *mode),
            PolygonOffset(f, u) => self.polygon_offset(*f, *u),
            PolygonStipple(p) => self.polygon_stipple(**p),
            NameStack(op) => self.name_stack(*op),
            Map { target, u, uorder, v, points } => self.map(*target, *u, *uorder, *v, points.clone()),
            EvalCoord(u, v) => self.eval_coord(*u, *v),
            EvalPoint(i, j) => self.eval_point(*i, *j),
            MapGrid(un, u, v) => self.map_grid(*un, *u, *v),
            EvalMesh1(mode, i1, i2) => self.eval_mesh1(*mode, *i1, *i2),
            EvalMesh2(mode, i1, i2, j1, j2) => self.eval_mesh2(*mode, *i1, *i2, *j1, *j2),
            PassThrough(t) => self.pass_through(*t),
            RasterPos(p) => {
                self.raster_pos(*p);
                self.raster_hit();
            }
            WindowPos(p) => {
                self.window_pos(*p);
                self.raster_hit();
            }
            PixelTransfer(pname, v) => self.pixel_transfer(*pname, *v),
            PixelMap(map, v) => self.pixel_map(*map, v),
            PixelZoom(x, y) => self.pixel_zoom(*x, *y),
            // Feedback and selection (5.2, 5.3): pixel rectangles draw
            // nothing; feedback records the raster position.
            Bitmap(b) if self.select.mode != super::select::GL_RENDER => {
                if self.raster.valid {
                    self.pixel_primitive(super::select::GL_BITMAP_TOKEN);
                    self.raster.pos[0] += b.step[0];
                    self.raster.pos[1] += b.step[1];
                }
            }
            DrawPixels(_) if self.select.mode != super::select::GL_RENDER => self.pixel_primitive(super::select::GL_DRAW_PIXEL_TOKEN),
            CopyPixels(_, _, w, h, ty) if self.select.mode != super::select::GL_RENDER => {
                if *w < 0 || *h < 0 {
                    self.set_error(GL_INVALID_VALUE)
                } else if !matches!(*ty, GL_COLOR | GL_DEPTH | GL_STENCIL) {
                    self.set_error(GL_INVALID_ENUM)
                } else {
                    self.pixel_primitive(super::select::GL_COPY_PIXEL_TOKEN)
                }
            }
            Bitmap(b) => self.bitmap(b),
            DrawPixels(r) => self.draw_pixels(r),
            CopyPixels(x, y, w, h, ty) => self.copy_pixels(*x, *y, *w, *h, *ty),
            Error(e) => self.set_error(*e),
            TexCoord(unit, v) => self.tex_coord(*unit, *v),
            ActiveTexture(e) => self.active_texture(*e),
            BindTexture(t, name) => self.bind_texture(*t, *name),
            TexParameter(t, p, v) => self.tex_parameter(*t, *p, *v),
            TexEnv(t, p, v) => self.tex_env(*t, *p, *v),
            TexGen(c, p, v) => self.tex_gen(*c, *p, *v),
            // An attached image may change: framebuffer objects' staging
            // copies are written back first and reloaded after.
            TexImage(cmd) => self.with_fbo_stored(|c| c.tex_image(cmd)),
            TexSubImage(cmd) => self.with_fbo_stored(|c| c.tex_sub_image(cmd)),
            CopyTex(cmd) => self.with_fbo_stored(|c| c.copy_tex(cmd)),
            PrioritizeTextures(p) => self.prioritize_textures(p),
            Imaging(cmd) => self.imaging_command(cmd),
        }
    }
}
