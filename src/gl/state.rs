//! GL state, grouped by the spec's attribute groups (GL 1.5 section 6.2,
//! tables 6.5 onwards), with the initial values the spec gives.

use crate::render::fragment::{BlendEquation, BlendFactor, CompareFunc, LogicOp, StencilOp};

/// GL_COLOR_BUFFER_BIT state (the parts implemented so far).
#[derive(Clone, Debug)]
pub struct ColorBufferState {
    /// glDrawBuffer.
    pub draw_buffer: u32,
    /// glIndexMask and glClearIndex (colour-index mode; stored only).
    pub index_mask: u32,
    pub clear_index: f32,
    /// glSampleCoverage (value, invert).
    pub sample_coverage: (f32, bool),
    pub clear: [f32; 4],
    pub write_mask: [bool; 4],
    pub dither: bool,
    pub alpha_test: bool,
    pub alpha_func: CompareFunc,
    /// glAlphaFunc's reference, clamped to [0, 1].
    pub alpha_ref: f32,
    pub blend: bool,
    pub blend_src_rgb: BlendFactor,
    pub blend_dst_rgb: BlendFactor,
    pub blend_src_alpha: BlendFactor,
    pub blend_dst_alpha: BlendFactor,
    /// glBlendColor, clamped to [0, 1].
    pub blend_color: [f32; 4],
    pub blend_equation: BlendEquation,
    pub color_logic_op: bool,
    /// GL 1.0's GL_LOGIC_OP (colour-index mode only: no effect in RGBA).
    pub index_logic_op: bool,
    pub logic_op: LogicOp,
}

impl Default for ColorBufferState {
    fn default() -> Self {
        ColorBufferState {
            draw_buffer: super::enums::GL_FRONT,
            index_mask: !0,
            clear_index: 0.0,
            sample_coverage: (1.0, false),
            clear: [0.0; 4],
            write_mask: [true; 4],
            dither: true,
            alpha_test: false,
            alpha_func: CompareFunc::Always,
            alpha_ref: 0.0,
            blend: false,
            blend_src_rgb: BlendFactor::One,
            blend_dst_rgb: BlendFactor::Zero,
            blend_src_alpha: BlendFactor::One,
            blend_dst_alpha: BlendFactor::Zero,
            blend_color: [0.0; 4],
            blend_equation: BlendEquation::Add,
            color_logic_op: false,
            index_logic_op: false,
            logic_op: LogicOp::Copy,
        }
    }
}

/// GL_DEPTH_BUFFER_BIT state.
#[derive(Clone, Debug)]
pub struct DepthState {
    pub test: bool,
    pub func: CompareFunc,
    pub write_mask: bool,
    pub clear: f64,
}

impl Default for DepthState {
    fn default() -> Self {
        DepthState { test: false, func: CompareFunc::Less, write_mask: true, clear: 1.0 }
    }
}

/// GL_STENCIL_BUFFER_BIT state.
#[derive(Clone, Debug)]
pub struct StencilState {
    pub test: bool,
    pub clear: i32,
    pub write_mask: u32,
    pub func: CompareFunc,
    /// glStencilFunc's reference as given; clamped to [0, 2^bits - 1] when
    /// used and when queried.
    pub reference: i32,
    pub value_mask: u32,
    pub fail: StencilOp,
    pub zfail: StencilOp,
    pub zpass: StencilOp,
}

impl Default for StencilState {
    fn default() -> Self {
        StencilState {
            test: false,
            clear: 0,
            write_mask: !0,
            func: CompareFunc::Always,
            reference: 0,
            value_mask: !0,
            fail: StencilOp::Keep,
            zfail: StencilOp::Keep,
            zpass: StencilOp::Keep,
        }
    }
}

/// GL_VIEWPORT_BIT state.
#[derive(Clone, Debug)]
pub struct ViewportState {
    pub x: i32,
    pub y: i32,
    pub width: i32,
    pub height: i32,
    pub near: f64,
    pub far: f64,
}

impl Default for ViewportState {
    fn default() -> Self {
        ViewportState { x: 0, y: 0, width: 0, height: 0, near: 0.0, far: 1.0 }
    }
}

/// GL_SCISSOR_BIT state.
#[derive(Clone, Debug, Default)]
pub struct ScissorState {
    pub test: bool,
    pub x: i32,
    pub y: i32,
    pub width: i32,
    pub height: i32,
}

/// GL_POLYGON_BIT state (the parts implemented so far).
#[derive(Clone, Debug)]
pub struct PolygonState {
    pub cull: bool,
    pub cull_mode: u32,
    pub front_face: u32,
    /// glPolygonMode for front and back faces.
    pub mode: [u32; 2],
    pub offset_factor: f32,
    pub offset_units: f32,
    /// GL_POLYGON_OFFSET_POINT, _LINE, _FILL.
    pub offset_point: bool,
    pub offset_line: bool,
    pub offset_fill: bool,
    pub stipple: bool,
    /// Bit x of row y (rows bottom-up, as window y).
    pub stipple_pattern: [u32; 32],
}

impl Default for PolygonState {
    fn default() -> Self {
        PolygonState {
            cull: false,
            cull_mode: super::enums::GL_BACK,
            front_face: super::enums::GL_CCW,
            mode: [super::enums::GL_FILL; 2],
            offset_factor: 0.0,
            offset_units: 0.0,
            offset_point: false,
            offset_line: false,
            offset_fill: false,
            stipple: false,
            stipple_pattern: [!0; 32],
        }
    }
}

/// GL_HINT_BIT state: target -> mode.
#[derive(Clone, Debug)]
pub struct HintState {
    pub perspective_correction: u32,
    pub point_smooth: u32,
    pub line_smooth: u32,
    pub polygon_smooth: u32,
    pub fog: u32,
    pub generate_mipmap: u32,
    pub texture_compression: u32,
}

impl Default for HintState {
    fn default() -> Self {
        let d = super::enums::GL_DONT_CARE;
        HintState {
            perspective_correction: d,
            point_smooth: d,
            line_smooth: d,
            polygon_smooth: d,
            fog: d,
            generate_mipmap: d,
            texture_compression: d,
        }
    }
}

/// Current values (GL_CURRENT_BIT): what the next vertex takes.
#[derive(Clone, Copy, Debug)]
pub struct CurrentState {
    pub color: [f32; 4],
    pub normal: [f32; 3],
    pub edge_flag: bool,
    /// Per texture unit (s, t, r, q).
    pub tex_coords: [[f32; 4]; crate::render::texture::MAX_UNITS],
    /// Stored for the colour sum (section 3.9): RGB as given, alpha 1.
    pub secondary_color: [f32; 4],
    /// Stored for fog (section 3.10).
    pub fog_coord: f32,
    /// Colour index: accepted and stored; no effect in RGBA mode.
    pub index: f32,
}

impl Default for CurrentState {
    fn default() -> Self {
        CurrentState {
            color: [1.0; 4],
            normal: [0.0, 0.0, 1.0],
            edge_flag: true,
            tex_coords: [[0.0, 0.0, 0.0, 1.0]; crate::render::texture::MAX_UNITS],
            secondary_color: [0.0, 0.0, 0.0, 1.0],
            fog_coord: 0.0,
            index: 1.0,
        }
    }
}

/// GL_LINE_BIT state (section 3.4): width, stipple. GL_LINE_SMOOTH lives in
/// enable.rs's OtherCaps; validation hands it to the renderer.
#[derive(Clone, Debug)]
pub struct LineState {
    /// As specified (glGet returns it); rasterization rounds and clamps it.
    pub width: f32,
    pub stipple: bool,
    /// glLineStipple's factor, clamped to [1, 256].
    pub stipple_repeat: i32,
    pub stipple_pattern: u16,
}

impl Default for LineState {
    fn default() -> Self {
        LineState { width: 1.0, stipple: false, stipple_repeat: 1, stipple_pattern: 0xFFFF }
    }
}

/// GL_POINT_BIT state (section 3.3): the size and the GL 1.4 point
/// parameters. GL_POINT_SMOOTH lives in enable.rs's OtherCaps.
#[derive(Clone, Debug)]
pub struct PointState {
    pub size: f32,
    /// GL 1.4 point parameters: derived sizes are clamped to [min, max].
    pub size_min: f32,
    pub size_max: f32,
    pub fade_threshold: f32,
    /// Distance attenuation (a, b, c): size * sqrt(1 / (a + b d + c d^2)).
    pub attenuation: [f32; 3],
}

impl Default for PointState {
    fn default() -> Self {
        PointState { size: 1.0, size_min: 0.0, size_max: 64.0, fade_threshold: 1.0, attenuation: [1.0, 0.0, 0.0] }
    }
}
