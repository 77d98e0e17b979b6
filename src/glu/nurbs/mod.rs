//! GLU NURBS (GLU 1.3 section 7): the NURBS object, its properties and
//! callbacks, curves, surfaces and trimming loops.
//!
//! Geometry is evaluated in f64 with de Boor's algorithm ([`bspline`]) and
//! emitted directly as GL primitives ([`render`]), not through GL
//! evaluators: curves as GL_LINE_STRIP, surfaces as GL_TRIANGLE_STRIP rows
//! (GL_TRIANGLES when trimmed) with a normal at every vertex, counter-
//! clockwise in (u, v) and so front-facing on the side of the normal
//! dS/du x dS/dv (GL's AUTO_NORMAL rule). In GLU_NURBS_TESSELLATOR mode the
//! same primitives go to the GLU_NURBS_BEGIN/VERTEX/NORMAL/COLOR/
//! TEXTURE_COORD/END callbacks (their _DATA forms when set, with the pointer
//! of gluNurbsCallbackData), vertices always three floats.
//!
//! Errors go to the GLU_NURBS_ERROR callback as GLU_NURBS_ERRORn (the GLU
//! 1.3 list: 1 order, 2 too few knots, 3 empty range, 4 decreasing knots,
//! 5 multiplicity, 6/7 curve begin/end, 8 missing or extra geometry, 12
//! gluEndSurface inside a trim, 13/27 surface begin/end, 14 non-trim curve
//! in a trim, 15/16/17 trim begin/end, 19 gluPwlCurve outside a trim, 22 a
//! trim type outside a trim, 31 unconnected trim curves, 33 negative count,
//! 34 negative stride, 35 unknown type, 36 NULL data), and
//! GLU_INVALID_ENUM / GLU_INVALID_VALUE for properties and callbacks.
//! A curve or surface with an error is not drawn. gluNurbsCurve and
//! gluNurbsSurface outside a Begin/End pair draw on their own (as GLU does).

pub mod bspline;
pub mod render;

use crate::api::types::*;
use crate::gl::enums::*;
use crate::glu::strings::{GLU_INVALID_ENUM, GLU_INVALID_VALUE};
use std::ffi::c_void;

pub const GLU_AUTO_LOAD_MATRIX: GLenum = 100200;
pub const GLU_CULLING: GLenum = 100201;
pub const GLU_PARAMETRIC_TOLERANCE: GLenum = 100202;
pub const GLU_SAMPLING_TOLERANCE: GLenum = 100203;
pub const GLU_DISPLAY_MODE: GLenum = 100204;
pub const GLU_SAMPLING_METHOD: GLenum = 100205;
pub const GLU_U_STEP: GLenum = 100206;
pub const GLU_V_STEP: GLenum = 100207;
pub const GLU_NURBS_MODE: GLenum = 100160;
pub const GLU_NURBS_TESSELLATOR: GLenum = 100161;
pub const GLU_NURBS_RENDERER: GLenum = 100162;
pub const GLU_OBJECT_PARAMETRIC_ERROR: GLenum = 100208;
pub const GLU_OBJECT_PATH_LENGTH: GLenum = 100209;
pub const GLU_PATH_LENGTH: GLenum = 100215;
pub const GLU_PARAMETRIC_ERROR: GLenum = 100216;
pub const GLU_DOMAIN_DISTANCE: GLenum = 100217;
pub const GLU_MAP1_TRIM_2: GLenum = 100210;
pub const GLU_MAP1_TRIM_3: GLenum = 100211;
pub const GLU_FILL: GLenum = 100012;
pub const GLU_OUTLINE_POLYGON: GLenum = 100240;
pub const GLU_OUTLINE_PATCH: GLenum = 100241;
pub const GLU_NURBS_ERROR: GLenum = 100103;
pub const GLU_NURBS_BEGIN: GLenum = 100164;
pub const GLU_NURBS_VERTEX: GLenum = 100165;
pub const GLU_NURBS_NORMAL: GLenum = 100166;
pub const GLU_NURBS_COLOR: GLenum = 100167;
pub const GLU_NURBS_TEXTURE_COORD: GLenum = 100168;
pub const GLU_NURBS_END: GLenum = 100169;
pub const GLU_NURBS_BEGIN_DATA: GLenum = 100170;
pub const GLU_NURBS_VERTEX_DATA: GLenum = 100171;
pub const GLU_NURBS_NORMAL_DATA: GLenum = 100172;
pub const GLU_NURBS_COLOR_DATA: GLenum = 100173;
pub const GLU_NURBS_TEXTURE_COORD_DATA: GLenum = 100174;
pub const GLU_NURBS_END_DATA: GLenum = 100175;
pub const GLU_NURBS_ERROR1: GLenum = 100251;

pub const GL_MAP1_INDEX: GLenum = 0x0D91;
pub const GL_MAP1_NORMAL: GLenum = 0x0D92;
pub const GL_MAP1_TEXTURE_COORD_1: GLenum = 0x0D93;
pub const GL_MAP1_TEXTURE_COORD_4: GLenum = 0x0D96;
pub const GL_MAP1_VERTEX_3: GLenum = 0x0D97;
pub const GL_MAP2_INDEX: GLenum = 0x0DB1;
pub const GL_MAP2_NORMAL: GLenum = 0x0DB2;
pub const GL_MAP2_TEXTURE_COORD_1: GLenum = 0x0DB3;
pub const GL_MAP2_TEXTURE_COORD_4: GLenum = 0x0DB6;
pub const GL_MAP2_VERTEX_3: GLenum = 0x0DB7;

/// What a map carries.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Role {
    Position,
    Normal,
    Color,
    Index,
    TexCoord,
    Trim,
}

/// Role, components read from the caller, and whether the last one is w,
/// of a GL_MAP1_* / GL_MAP2_* / GLU_MAP1_TRIM_* type.
pub fn map_type(t: GLenum, surface: bool) -> Option<(Role, usize, bool)> {
    let t1 = if surface { t.wrapping_sub(GL_MAP2_COLOR_4).wrapping_add(GL_MAP1_COLOR_4) } else { t };
    if surface && matches!(t, GLU_MAP1_TRIM_2 | GLU_MAP1_TRIM_3) {
        return None;
    }
    if surface && !(GL_MAP2_COLOR_4..=GL_MAP2_VERTEX_4).contains(&t) {
        return None;
    }
    Some(match t1 {
        GL_MAP1_COLOR_4 => (Role::Color, 4, false),
        GL_MAP1_INDEX => (Role::Index, 1, false),
        GL_MAP1_NORMAL => (Role::Normal, 3, false),
        GL_MAP1_TEXTURE_COORD_1..=GL_MAP1_TEXTURE_COORD_4 => (Role::TexCoord, (t1 - GL_MAP1_TEXTURE_COORD_1 + 1) as usize, false),
        GL_MAP1_VERTEX_3 => (Role::Position, 3, false),
        GL_MAP1_VERTEX_4 => (Role::Position, 4, true),
        GLU_MAP1_TRIM_2 => (Role::Trim, 2, false),
        GLU_MAP1_TRIM_3 => (Role::Trim, 3, true),
        _ => return None,
    })
}

/// A NURBS curve (or one map of a curve): control points as 4-vectors.
/// Positions and trims hold (x, y, z, w) (w = 1 unless rational); other
/// maps their `dim` components, the rest zero.
#[derive(Clone, Debug)]
pub struct Curve {
    pub role: Role,
    pub dim: usize,
    pub order: usize,
    pub knots: Vec<f64>,
    pub pts: Vec<[f64; 4]>,
}

/// A NURBS surface map: control point (i, j) (i along u = s, j along v = t)
/// at `pts[i * nv + j]`.
#[derive(Clone, Debug)]
pub struct Surface {
    pub role: Role,
    pub dim: usize,
    pub order: [usize; 2],
    pub knots: [Vec<f64>; 2],
    pub nu: usize,
    pub nv: usize,
    pub pts: Vec<[f64; 4]>,
}

/// One piece of a trimming loop.
#[derive(Clone, Debug)]
pub enum TrimPiece {
    Pwl(Vec<[f64; 2]>),
    Nurbs(Curve),
}

#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum Block {
    None,
    Curve,
    Surface,
    Trim,
}

/// Where the primitives go.
pub trait NurbsSink {
    fn begin(&mut self, mode: GLenum);
    fn end(&mut self);
    fn vertex(&mut self, p: [f64; 3]);
    fn normal(&mut self, n: [f64; 3]);
    fn color(&mut self, c: &[f64]);
    fn tex_coord(&mut self, t: &[f64]);
}

/// GLU_NURBS_RENDERER: the public GL entry points.
pub struct GlSink;

impl NurbsSink for GlSink {
    fn begin(&mut self, mode: GLenum) {
        unsafe { crate::api::table::glBegin(mode) }
    }
    fn end(&mut self) {
        unsafe { crate::api::table::glEnd() }
    }
    fn vertex(&mut self, p: [f64; 3]) {
        unsafe { crate::api::table::glVertex3d(p[0], p[1], p[2]) }
    }
    fn normal(&mut self, n: [f64; 3]) {
        unsafe { crate::api::table::glNormal3d(n[0], n[1], n[2]) }
    }
    fn color(&mut self, c: &[f64]) {
        use crate::api::table as gl;
        unsafe {
            match c.len() {
                4 => gl::glColor4d(c[0], c[1], c[2], c[3]),
                _ => gl::glIndexd(c[0]),
            }
        }
    }
    fn tex_coord(&mut self, t: &[f64]) {
        use crate::api::table as gl;
        unsafe {
            match t.len() {
                1 => gl::glTexCoord1d(t[0]),
                2 => gl::glTexCoord2d(t[0], t[1]),
                3 => gl::glTexCoord3d(t[0], t[1], t[2]),
                _ => gl::glTexCoord4d(t[0], t[1], t[2], t[3]),
            }
        }
    }
}

pub type BeginCb = unsafe extern "system" fn(GLenum);
pub type BeginDataCb = unsafe extern "system" fn(GLenum, *mut c_void);
pub type FloatsCb = unsafe extern "system" fn(*mut GLfloat);
pub type FloatsDataCb = unsafe extern "system" fn(*mut GLfloat, *mut c_void);
pub type EndCb = unsafe extern "system" fn();
pub type EndDataCb = unsafe extern "system" fn(*mut c_void);
pub type ErrorCb = unsafe extern "system" fn(GLenum);

/// The GLU 1.3 tessellator-mode callbacks.
#[derive(Clone, Copy, Default)]
pub struct Callbacks {
    pub begin: Option<BeginCb>,
    pub begin_data: Option<BeginDataCb>,
    /// vertex, normal, color, texture coordinate
    pub floats: [Option<FloatsCb>; 4],
    pub floats_data: [Option<FloatsDataCb>; 4],
    pub end: Option<EndCb>,
    pub end_data: Option<EndDataCb>,
    pub data: *mut c_void,
}

/// GLU_NURBS_TESSELLATOR: the callbacks.
pub struct CallbackSink(pub Callbacks);

impl CallbackSink {
    fn floats(&self, which: usize, v: &[f64]) {
        let mut f = [0f32; 4];
        for (d, s) in f.iter_mut().zip(v) {
            *d = *s as f32;
        }
        let c = &self.0;
        unsafe {
            if let Some(cb) = c.floats_data[which] {
                cb(f.as_mut_ptr(), c.data)
            } else if let Some(cb) = c.floats[which] {
                cb(f.as_mut_ptr())
            }
        }
    }
}

impl NurbsSink for CallbackSink {
    fn begin(&mut self, mode: GLenum) {
        let c = &self.0;
        unsafe {
            if let Some(cb) = c.begin_data {
                cb(mode, c.data)
            } else if let Some(cb) = c.begin {
                cb(mode)
            }
        }
    }
    fn end(&mut self) {
        let c = &self.0;
        unsafe {
            if let Some(cb) = c.end_data {
                cb(c.data)
            } else if let Some(cb) = c.end {
                cb()
            }
        }
    }
    fn vertex(&mut self, p: [f64; 3]) {
        self.floats(0, &p)
    }
    fn normal(&mut self, n: [f64; 3]) {
        self.floats(1, &n)
    }
    fn color(&mut self, c: &[f64]) {
        self.floats(2, c)
    }
    fn tex_coord(&mut self, t: &[f64]) {
        self.floats(3, t)
    }
}

/// The sampling matrices: modelview and projection (column-major) and the
/// viewport.
#[derive(Clone, Copy, Debug)]
pub struct Matrices {
    pub model: [f64; 16],
    pub proj: [f64; 16],
    pub viewport: [f64; 4],
}

const IDENTITY: [f64; 16] = [1.0, 0.0, 0.0, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0, 0.0, 1.0];

impl Default for Matrices {
    /// Identity with a viewport of (0, 0, 2, 2): window units are object
    /// units.
    fn default() -> Self {
        Matrices { model: IDENTITY, proj: IDENTITY, viewport: [0.0, 0.0, 2.0, 2.0] }
    }
}

/// A NURBS object.
pub struct Nurbs {
    pub auto_load_matrix: bool,
    pub culling: bool,
    pub sampling_method: GLenum,
    pub sampling_tolerance: f64,
    pub parametric_tolerance: f64,
    pub u_step: f64,
    pub v_step: f64,
    pub display_mode: GLenum,
    pub mode: GLenum,
    pub loaded: Matrices,
    pub callbacks: Callbacks,
    pub error: Option<ErrorCb>,
    /// Replaces GL / the callbacks (tests).
    pub sink: Option<Box<dyn NurbsSink>>,
    block: Block,
    failed: bool,
    curves: Vec<Curve>,
    surfaces: Vec<Surface>,
    loops: Vec<Vec<TrimPiece>>,
}

impl Default for Nurbs {
    fn default() -> Self {
        Nurbs {
            auto_load_matrix: true,
            culling: false,
            sampling_method: GLU_PATH_LENGTH,
            sampling_tolerance: 50.0,
            parametric_tolerance: 0.5,
            u_step: 100.0,
            v_step: 100.0,
            display_mode: GLU_FILL,
            mode: GLU_NURBS_RENDERER,
            loaded: Matrices::default(),
            callbacks: Callbacks { data: std::ptr::null_mut(), ..Default::default() },
            error: None,
            sink: None,
            block: Block::None,
            failed: false,
            curves: vec![],
            surfaces: vec![],
            loops: vec![],
        }
    }
}

/// Reads `n` floats of a caller's array.
unsafe fn floats(p: *const GLfloat, n: usize) -> Vec<f64> {
    (0..n).map(|i| *p.add(i) as f64).collect()
}

impl Nurbs {
    /// Reports `code` (a GLU error code) through the error callback.
    pub fn report(&self, code: GLenum) {
        if let Some(f) = self.error {
            unsafe { f(code) }
        }
    }
    fn nurbs_error(&mut self, n: u32) {
        self.failed = true;
        self.report(GLU_NURBS_ERROR1 + n - 1);
    }

    // ---- properties and callbacks ----

    pub fn set_property(&mut self, property: GLenum, value: f32) {
        let v = value as f64;
        let positive = v > 0.0 && v.is_finite();
        match property {
            GLU_AUTO_LOAD_MATRIX => self.auto_load_matrix = v != 0.0,
            GLU_CULLING => self.culling = v != 0.0,
            GLU_SAMPLING_TOLERANCE if positive => self.sampling_tolerance = v,
            GLU_PARAMETRIC_TOLERANCE if positive => self.parametric_tolerance = v,
            GLU_U_STEP if positive => self.u_step = v,
            GLU_V_STEP if positive => self.v_step = v,
            GLU_SAMPLING_TOLERANCE | GLU_PARAMETRIC_TOLERANCE | GLU_U_STEP | GLU_V_STEP => self.report(GLU_INVALID_VALUE),
            GLU_SAMPLING_METHOD => match value as GLenum {
                m @ (GLU_PATH_LENGTH | GLU_PARAMETRIC_ERROR | GLU_DOMAIN_DISTANCE | GLU_OBJECT_PATH_LENGTH | GLU_OBJECT_PARAMETRIC_ERROR) if value as GLenum as f32 == value => self.sampling_method = m,
                _ => self.report(GLU_INVALID_VALUE),
            },
            GLU_DISPLAY_MODE => match value as GLenum {
                m @ (GLU_FILL | GLU_OUTLINE_POLYGON | GLU_OUTLINE_PATCH) if value as GLenum as f32 == value => self.display_mode = m,
                _ => self.report(GLU_INVALID_VALUE),
            },
            GLU_NURBS_MODE => match value as GLenum {
                m @ (GLU_NURBS_RENDERER | GLU_NURBS_TESSELLATOR) if value as GLenum as f32 == value => self.mode = m,
                _ => self.report(GLU_INVALID_VALUE),
            },
            _ => self.report(GLU_INVALID_ENUM),
        }
    }

    pub fn get_property(&self, property: GLenum) -> Option<f32> {
        Some(match property {
            GLU_AUTO_LOAD_MATRIX => self.auto_load_matrix as u8 as f32,
            GLU_CULLING => self.culling as u8 as f32,
            GLU_SAMPLING_TOLERANCE => self.sampling_tolerance as f32,
            GLU_PARAMETRIC_TOLERANCE => self.parametric_tolerance as f32,
            GLU_U_STEP => self.u_step as f32,
            GLU_V_STEP => self.v_step as f32,
            GLU_SAMPLING_METHOD => self.sampling_method as f32,
            GLU_DISPLAY_MODE => self.display_mode as f32,
            GLU_NURBS_MODE => self.mode as f32,
            _ => {
                self.report(GLU_INVALID_ENUM);
                return None;
            }
        })
    }

    /// # Safety
    /// NULL or 16, 16 and 4 values.
    pub unsafe fn load_sampling_matrices(&mut self, model: *const GLfloat, proj: *const GLfloat, view: *const GLint) {
        if model.is_null() || proj.is_null() || view.is_null() {
            return self.report(GLU_INVALID_VALUE);
        }
        for k in 0..16 {
            self.loaded.model[k] = *model.add(k) as f64;
            self.loaded.proj[k] = *proj.add(k) as f64;
        }
        for k in 0..4 {
            self.loaded.viewport[k] = *view.add(k) as f64;
        }
    }

    pub fn set_callback(&mut self, which: GLenum, f: GLproc) {
        // SAFETY (all transmutes): the application registered `f` as the
        // callback `which`, whose C type glu.h gives.
        unsafe {
            use std::mem::transmute as t;
            type F = unsafe extern "system" fn();
            let c = &mut self.callbacks;
            match which {
                GLU_NURBS_ERROR => self.error = f.map(|f| t::<F, ErrorCb>(f)),
                GLU_NURBS_BEGIN => c.begin = f.map(|f| t::<F, BeginCb>(f)),
                GLU_NURBS_BEGIN_DATA => c.begin_data = f.map(|f| t::<F, BeginDataCb>(f)),
                GLU_NURBS_VERTEX..=GLU_NURBS_TEXTURE_COORD => c.floats[(which - GLU_NURBS_VERTEX) as usize] = f.map(|f| t::<F, FloatsCb>(f)),
                GLU_NURBS_VERTEX_DATA..=GLU_NURBS_TEXTURE_COORD_DATA => {
                    c.floats_data[(which - GLU_NURBS_VERTEX_DATA) as usize] = f.map(|f| t::<F, FloatsDataCb>(f))
                }
                GLU_NURBS_END => c.end = f,
                GLU_NURBS_END_DATA => c.end_data = f.map(|f| t::<F, EndDataCb>(f)),
                _ => self.report(GLU_INVALID_ENUM),
            }
        }
    }

    pub fn set_callback_data(&mut self, data: *mut c_void) {
        self.callbacks.data = data;
    }

    // ---- curves ----

    pub fn begin_curve(&mut self) {
        if self.block != Block::None {
            return self.nurbs_error(6);
        }
        self.block = Block::Curve;
        self.failed = false;
        self.curves.clear();
    }

    pub fn end_curve(&mut self) {
        if self.block != Block::Curve {
            return self.nurbs_error(7);
        }
        self.block = Block::None;
        let curves = std::mem::take(&mut self.curves);
        if self.failed {
            return;
        }
        if curves.iter().filter(|c| c.role == Role::Position).count() != 1 {
            return self.nurbs_error(8);
        }
        self.draw(|r, sink| r.curve(&curves, sink));
    }

    /// Reads and checks a curve; None after reporting an error.
    #[allow(clippy::too_many_arguments)]
    unsafe fn read_curve(&mut self, knot_count: GLint, knots: *const GLfloat, stride: GLint, ctl: *const GLfloat, order: GLint, role: Role, dim: usize, rational: bool) -> Option<Curve> {
        if knot_count < 0 {
            self.nurbs_error(33);
            return None;
        }
        if stride < 0 {
            self.nurbs_error(34);
            return None;
        }
        if order < 1 {
            self.nurbs_error(1);
            return None;
        }
        if knots.is_null() || (ctl.is_null() && knot_count > order) {
            self.nurbs_error(36);
            return None;
        }
        let k = floats(knots, knot_count as usize);
        if let Err(e) = bspline::check_knots(&k, order as usize) {
            self.nurbs_error(e);
            return None;
        }
        let n = k.len() - order as usize;
        let pts = (0..n).map(|i| point(ctl.add(i * stride as usize), role, dim, rational)).collect();
        Some(Curve { role, dim, order: order as usize, knots: k, pts })
    }

    /// # Safety
    /// `knots` holds `knot_count` floats and `ctl` the control points.
    pub unsafe fn nurbs_curve(&mut self, knot_count: GLint, knots: *const GLfloat, stride: GLint, ctl: *const GLfloat, order: GLint, type_: GLenum) {
        let Some((role, dim, rational)) = map_type(type_, false) else {
            return self.nurbs_error(35);
        };
        match (self.block, role) {
            (Block::Trim, Role::Trim) => {
                if let Some(c) = self.read_curve(knot_count, knots, stride, ctl, order, role, dim, rational) {
                    if let Some(l) = self.loops.last_mut() {
                        l.push(TrimPiece::Nurbs(c));
                    }
                }
            }
            (Block::Trim, _) => self.nurbs_error(14),
            (_, Role::Trim) => self.nurbs_error(22),
            (Block::Curve, _) => {
                if let Some(c) = self.read_curve(knot_count, knots, stride, ctl, order, role, dim, rational) {
                    self.curves.push(c);
                }
            }
            (Block::Surface, _) => self.nurbs_error(8),
            (Block::None, _) => {
                // An implicit gluBeginCurve / gluEndCurve.
                self.begin_curve();
                if let Some(c) = self.read_curve(knot_count, knots, stride, ctl, order, role, dim, rational) {
                    self.curves.push(c);
                }
                self.end_curve();
            }
        }
    }

    // ---- surfaces ----

    pub fn begin_surface(&mut self) {
        if self.block != Block::None {
            return self.nurbs_error(27);
        }
        self.block = Block::Surface;
        self.failed = false;
        self.surfaces.clear();
        self.loops.clear();
    }

    pub fn end_surface(&mut self) {
        match self.block {
            Block::Surface => {}
            Block::Trim => {
                self.nurbs_error(12);
            }
            _ => return self.nurbs_error(13),
        }
        self.block = Block::None;
        let surfaces = std::mem::take(&mut self.surfaces);
        let loops = std::mem::take(&mut self.loops);
        if self.failed {
            return;
        }
        if surfaces.iter().filter(|c| c.role == Role::Position).count() != 1 {
            return self.nurbs_error(8);
        }
        if !loops.iter().all(|l| render::connected(l)) {
            return self.nurbs_error(31);
        }
        self.draw(|r, sink| r.surface(&surfaces, &loops, sink));
    }

    /// # Safety
    /// `s_knots`/`t_knots` hold their counts of floats and `ctl` the net.
    #[allow(clippy::too_many_arguments)]
    pub unsafe fn nurbs_surface(
        &mut self,
        s_count: GLint,
        s_knots: *const GLfloat,
        t_count: GLint,
        t_knots: *const GLfloat,
        s_stride: GLint,
        t_stride: GLint,
        ctl: *const GLfloat,
        s_order: GLint,
        t_order: GLint,
        type_: GLenum,
    ) {
        let implicit = self.block == Block::None;
        if self.block == Block::Trim || self.block == Block::Curve {
            return self.nurbs_error(if self.block == Block::Trim { 14 } else { 8 });
        }
        let Some((role, dim, rational)) = map_type(type_, true) else {
            return self.nurbs_error(35);
        };
        if implicit {
            self.begin_surface();
        }
        if let Some(s) = self.read_surface([s_count, t_count], [s_knots, t_knots], [s_stride, t_stride], ctl, [s_order, t_order], role, dim, rational) {
            self.surfaces.push(s);
        }
        if implicit {
            self.end_surface();
        }
    }

    #[allow(clippy::too_many_arguments)]
    unsafe fn read_surface(&mut self, count: [GLint; 2], knots: [*const GLfloat; 2], stride: [GLint; 2], ctl: *const GLfloat, order: [GLint; 2], role: Role, dim: usize, rational: bool) -> Option<Surface> {
        let mut kv: [Vec<f64>; 2] = [vec![], vec![]];
        for a in 0..2 {
            let e = if count[a] < 0 {
                33
            } else if stride[a] < 0 {
                34
            } else if order[a] < 1 {
                1
            } else if knots[a].is_null() || ctl.is_null() {
                36
            } else {
                0
            };
            if e != 0 {
                self.nurbs_error(e);
                return None;
            }
            kv[a] = floats(knots[a], count[a] as usize);
            if let Err(e) = bspline::check_knots(&kv[a], order[a] as usize) {
                self.nurbs_error(e);
                return None;
            }
        }
        let nu = kv[0].len() - order[0] as usize;
        let nv = kv[1].len() - order[1] as usize;
        let mut pts = Vec::with_capacity(nu * nv);
        for i in 0..nu {
            for j in 0..nv {
                pts.push(point(ctl.add(i * stride[0] as usize + j * stride[1] as usize), role, dim, rational));
            }
        }
        Some(Surface { role, dim, order: order.map(|o| o as usize), knots: kv, nu, nv, pts })
    }

    // ---- trimming ----

    pub fn begin_trim(&mut self) {
        match self.block {
            Block::Surface => {
                self.block = Block::Trim;
                self.loops.push(vec![]);
            }
            Block::Trim => self.nurbs_error(16),
            _ => self.nurbs_error(15),
        }
    }

    pub fn end_trim(&mut self) {
        if self.block != Block::Trim {
            return self.nurbs_error(17);
        }
        self.block = Block::Surface;
        if self.loops.last().is_some_and(|l| l.is_empty()) {
            self.loops.pop();
            self.nurbs_error(18);
        }
    }

    /// # Safety
    /// `data` holds `count` points `stride` floats apart.
    pub unsafe fn pwl_curve(&mut self, count: GLint, data: *const GLfloat, stride: GLint, type_: GLenum) {
        if self.block != Block::Trim {
            return self.nurbs_error(19);
        }
        let dim = match type_ {
            GLU_MAP1_TRIM_2 => 2,
            GLU_MAP1_TRIM_3 => 3,
            _ => return self.nurbs_error(14),
        };
        if count < 0 {
            return self.nurbs_error(33);
        }
        if stride < 0 {
            return self.nurbs_error(34);
        }
        if data.is_null() {
            return self.nurbs_error(36);
        }
        let pts = (0..count as usize)
            .map(|i| {
                let p = data.add(i * stride as usize);
                let (u, v) = (*p as f64, *p.add(1) as f64);
                if dim == 3 {
                    let w = *p.add(2) as f64;
                    [u / w, v / w]
                } else {
                    [u, v]
                }
            })
            .collect();
        if let Some(l) = self.loops.last_mut() {
            l.push(TrimPiece::Pwl(pts));
        }
    }

    // ---- output ----

    fn matrices(&self) -> Matrices {
        if !self.auto_load_matrix {
            return self.loaded;
        }
        let mut m = Matrices::default();
        let mut buf = [f32::NAN; 16];
        unsafe { crate::api::table::glGetFloatv(GL_MODELVIEW_MATRIX, buf.as_mut_ptr()) };
        if !buf[0].is_nan() {
            m.model = buf.map(|v| v as f64);
        }
        let mut buf = [f32::NAN; 16];
        unsafe { crate::api::table::glGetFloatv(GL_PROJECTION_MATRIX, buf.as_mut_ptr()) };
        if !buf[0].is_nan() {
            m.proj = buf.map(|v| v as f64);
        }
        let mut vp = [i32::MIN; 4];
        unsafe { crate::api::table::glGetIntegerv(GL_VIEWPORT, vp.as_mut_ptr()) };
        if vp[0] != i32::MIN {
            m.viewport = vp.map(|v| v as f64);
        }
        m
    }

    fn draw(&mut self, f: impl FnOnce(&render::Renderer, &mut dyn NurbsSink)) {
        let r = render::Renderer {
            method: self.sampling_method,
            tolerance: if matches!(self.sampling_method, GLU_PARAMETRIC_ERROR | GLU_OBJECT_PARAMETRIC_ERROR) { self.parametric_tolerance } else { self.sampling_tolerance },
            step: [self.u_step, self.v_step],
            display: self.display_mode,
            culling: self.culling,
            m: self.matrices(),
        };
        if let Some(s) = self.sink.as_deref_mut() {
            f(&r, s)
        } else if self.mode == GLU_NURBS_TESSELLATOR {
            f(&r, &mut CallbackSink(self.callbacks))
        } else {
            f(&r, &mut GlSink)
        }
    }
}

/// A control point as a 4-vector (see [`Curve`]).
unsafe fn point(p: *const GLfloat, role: Role, dim: usize, rational: bool) -> [f64; 4] {
    let mut v = [0.0; 4];
    match role {
        Role::Position | Role::Trim => {
            let n = if rational { dim - 1 } else { dim };
            for (k, c) in v.iter_mut().enumerate().take(n) {
                *c = *p.add(k) as f64;
            }
            v[3] = if rational { *p.add(dim - 1) as f64 } else { 1.0 };
        }
        _ => {
            for (k, c) in v.iter_mut().enumerate().take(dim) {
                *c = *p.add(k) as f64;
            }
        }
    }
    v
}

// ---- the C entry points ----

pub fn new_nurbs() -> *mut c_void {
    Box::into_raw(Box::new(Nurbs::default())) as *mut c_void
}

/// # Safety
/// `n` is NULL or from [`new_nurbs`], not yet deleted.
pub unsafe fn delete_nurbs(n: *mut c_void) {
    if !n.is_null() {
        drop(Box::from_raw(n as *mut Nurbs));
    }
}

/// # Safety
/// As [`delete_nurbs`]; NULL makes every call a no-op.
pub unsafe fn with(n: *mut c_void, f: impl FnOnce(&mut Nurbs)) {
    if let Some(n) = (n as *mut Nurbs).as_mut() {
        f(n)
    }
}

/// gluGetNurbsProperty.
///
/// # Safety
/// `data` NULL or one float.
pub unsafe fn get_property(n: *mut c_void, property: GLenum, data: *mut GLfloat) {
    with(n, |n| {
        if let Some(v) = n.get_property(property) {
            if !data.is_null() {
                *data = v;
            }
        }
    })
}
