//! The display-listable commands, as values. An entry point converts its C
//! arguments into one of these (so glColor3ub and glColor4fv both become
//! `Color`), then [`Context::submit`] records it in a display list,
//! executes it, or both. Display lists are vectors of these.

use super::context::Context;
use super::enums::*;
use glam::DMat4;

#[derive(Clone, Debug, PartialEq)]
pub enum Command {
    // Section 2.6: Begin/End and vertex attributes.
    Begin(u32),
    End,
    Vertex([f32; 4]),
    Color([f32; 4]),
    Normal([f32; 3]),
    EdgeFlag(bool),
    /// glIndex: stored, no effect in RGBA mode.
    Index(f32),
    FogCoord(f32),
    /// glSecondaryColor3: RGB and alpha 1.
    SecondaryColor([f32; 4]),
    /// Texture coordinates of a unit (0-based): the hook vertex arrays feed
    /// and compile into lists (gl::arrays); glTexCoord/glMultiTexCoord
    /// should become this or replace it.
    MultiTexCoord(u32, [f32; 4]),
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
    LoadMatrix(DMat4),
    MultMatrix(DMat4),
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
}

impl Command {
    /// May this command appear between Begin and End (GL 1.5 section 2.6.3)?
    pub fn allowed_in_begin_end(&self) -> bool {
        matches!(
            self,
            Command::Vertex(_)
                | Command::Color(_)
                | Command::Normal(_)
                | Command::EdgeFlag(_)
                | Command::Index(_)
                | Command::FogCoord(_)
                | Command::SecondaryColor(_)
                | Command::MultiTexCoord(..)
                | Command::Material(..)
                | Command::End
                | Command::CallList(_)
                | Command::CallLists(_)
        )
    }
}

impl Context {
    /// Executes one command against the context.
    pub fn execute(&mut self, cmd: &Command) {
        if self.in_begin_end() && !cmd.allowed_in_begin_end() {
            self.set_error(GL_INVALID_OPERATION);
            return;
        }
        use Command::*;
        match cmd {
            Begin(mode) => self.begin(*mode),
            End => self.end(),
            Vertex(v) => self.vertex(*v),
            Color(c) => {
                self.current.color = *c;
                self.apply_color_material();
            }
            Normal(n) => self.current.normal = *n,
            EdgeFlag(f) => self.current.edge_flag = *f,
            Index(i) => self.current.index = *i,
            FogCoord(f) => self.current.fog_coord = *f,
            SecondaryColor(c) => self.current.secondary_color = *c,
            MultiTexCoord(unit, t) => self.set_tex_coord(*unit as usize, *t),
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
            LoadMatrix(m) => self.load_matrix(*m),
            MultMatrix(m) => self.mult_matrix(*m),
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
            }
            LineWidth(w) => {
                if !(*w > 0.0) {
                    return self.set_error(GL_INVALID_VALUE);
                }
                self.line.width = *w;
            }
            LineStipple(factor, pattern) => {
                self.line.stipple_repeat = (*factor).clamp(1, 256);
                self.line.stipple_pattern = *pattern;
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
            Enable(cap) => self.set_enabled(*cap, true),
            Disable(cap) => self.set_enabled(*cap, false),
            Hint(target, mode) => self.hint(*target, *mode),
            CallList(n) => self.call_list(*n),
            CallLists(names) => self.call_lists(names),
            ListBase(b) => self.lists.base = *b,
            BeginQuery(target, id) => self.begin_query(*target, *id),
            EndQuery(target) => self.end_query(*target),
        }
    }
}
