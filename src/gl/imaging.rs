//! The ARB_imaging stages of pixel transfer (GL 1.5 section 3.6.5, the
//! operations after "RGBA to RGBA lookup" in figure 3.7, with their
//! state commands of section 3.6.3): colour table lookup, convolution
//! with post-convolution scale and bias, the post-convolution colour
//! table, the colour matrix with post-colour-matrix scale and bias, the
//! post-colour-matrix colour table, histogram and minmax.
//!
//! They apply to the RGBA groups of glDrawPixels, glCopyPixels,
//! glReadPixels and the texture image commands (colour indices join after
//! their I_TO_* lookup), in that order; convolution only to 2D images
//! (CONVOLUTION_2D, else SEPARABLE_2D) or 1D texture images
//! (CONVOLUTION_1D), and with the REDUCE border mode the image shrinks by
//! the filter size less one. [`Context::imaging_stages`] says which
//! stages are on; the pixel commands call [`Context::imaging`] only when
//! one is, so with imaging off they pay one check per command.
//!
//! Values are not clamped between stages (the colour tables clamp their
//! index), only by the final conversion at the end. A histogram or minmax
//! with `sink` consumes the groups: nothing is drawn, written or stored.
//!
//! Tables and filters are stored as RGBA f32 after their own scale and
//! bias (tables also clamped), with the base format of their internal
//! format deciding which components they hold (table 3.15: luminance and
//! intensity in R). glPushAttrib(GL_PIXEL_MODE_BIT) saves the tables' and
//! filters' parameters ([`PixelModeParams`]), not their contents nor the
//! histogram and minmax (tables 6.20-6.22 list no attribute group for
//! them).

use super::context::Context;
use super::enums::*;
use super::get::Value;
use super::pixel_data::{check_format_type, Dest, Kind, Source};
use super::texture::image::{internal_format, texel_to_rgba};
use crate::render::texture::Base;

pub const GL_PROXY_COLOR_TABLE: u32 = 0x80D3;
pub const GL_PROXY_POST_CONVOLUTION_COLOR_TABLE: u32 = 0x80D4;
pub const GL_PROXY_POST_COLOR_MATRIX_COLOR_TABLE: u32 = 0x80D5;
pub const GL_COLOR_TABLE_SCALE: u32 = 0x80D6;
pub const GL_COLOR_TABLE_BIAS: u32 = 0x80D7;
pub const GL_COLOR_TABLE_FORMAT: u32 = 0x80D8;
pub const GL_COLOR_TABLE_WIDTH: u32 = 0x80D9;
pub const GL_COLOR_TABLE_RED_SIZE: u32 = 0x80DA;
pub const GL_COLOR_TABLE_INTENSITY_SIZE: u32 = 0x80DF;
pub const GL_CONVOLUTION_BORDER_MODE: u32 = 0x8013;
pub const GL_CONVOLUTION_FILTER_SCALE: u32 = 0x8014;
pub const GL_CONVOLUTION_FILTER_BIAS: u32 = 0x8015;
pub const GL_REDUCE: u32 = 0x8016;
pub const GL_CONVOLUTION_FORMAT: u32 = 0x8017;
pub const GL_CONVOLUTION_WIDTH: u32 = 0x8018;
pub const GL_CONVOLUTION_HEIGHT: u32 = 0x8019;
pub const GL_MAX_CONVOLUTION_WIDTH: u32 = 0x801A;
pub const GL_MAX_CONVOLUTION_HEIGHT: u32 = 0x801B;
pub const GL_POST_CONVOLUTION_RED_SCALE: u32 = 0x801C;
pub const GL_POST_CONVOLUTION_ALPHA_BIAS: u32 = 0x8023;
pub const GL_CONSTANT_BORDER: u32 = 0x8151;
pub const GL_REPLICATE_BORDER: u32 = 0x8153;
pub const GL_CONVOLUTION_BORDER_COLOR: u32 = 0x8154;
pub const GL_PROXY_HISTOGRAM: u32 = 0x8025;
pub const GL_HISTOGRAM_WIDTH: u32 = 0x8026;
pub const GL_HISTOGRAM_FORMAT: u32 = 0x8027;
pub const GL_HISTOGRAM_RED_SIZE: u32 = 0x8028;
pub const GL_HISTOGRAM_LUMINANCE_SIZE: u32 = 0x802C;
pub const GL_HISTOGRAM_SINK: u32 = 0x802D;
pub const GL_MINMAX_FORMAT: u32 = 0x802F;
pub const GL_MINMAX_SINK: u32 = 0x8030;
pub const GL_TABLE_TOO_LARGE: u32 = 0x8031;
pub const GL_COLOR_MATRIX: u32 = 0x80B1;
pub const GL_COLOR_MATRIX_STACK_DEPTH: u32 = 0x80B2;
pub const GL_MAX_COLOR_MATRIX_STACK_DEPTH: u32 = 0x80B3;
pub const GL_POST_COLOR_MATRIX_RED_SCALE: u32 = 0x80B4;
pub const GL_POST_COLOR_MATRIX_ALPHA_BIAS: u32 = 0x80BB;
pub const GL_TRANSPOSE_COLOR_MATRIX: u32 = 0x84E6;

/// GL_MAX_COLOR_TABLE width softgl accepts (proxies answer 0 above it),
/// and the largest histogram.
pub const MAX_TABLE: usize = 256;
/// MAX_CONVOLUTION_WIDTH and _HEIGHT.
pub const MAX_CONVOLUTION: usize = 11;

/// A colour table (or a proxy's state, without entries).
#[derive(Clone, Debug, PartialEq)]
pub struct ColorTable {
    pub internal_format: u32,
    pub base: Base,
    pub width: usize,
    /// RGBA after COLOR_TABLE_SCALE/BIAS, clamped; `width` of them.
    pub entries: Vec<[f32; 4]>,
    pub scale: [f32; 4],
    pub bias: [f32; 4],
}

impl Default for ColorTable {
    fn default() -> Self {
        ColorTable { internal_format: GL_RGBA, base: Base::Rgba, width: 0, entries: Vec::new(), scale: [1.0; 4], bias: [0.0; 4] }
    }
}

impl ColorTable {
    /// Colour table lookup (3.6.5): each component the table holds is
    /// replaced by the entry its clamped value indexes (round(c (w - 1))).
    fn lookup(&self, c: [f32; 4]) -> [f32; 4] {
        let n = self.entries.len();
        if n == 0 {
            return c;
        }
        let at = |comp: usize| &self.entries[((c[comp].clamp(0.0, 1.0) * (n - 1) as f32).round() as usize).min(n - 1)];
        // Luminance and intensity tables hold their value in R.
        match self.base {
            Base::Alpha => [c[0], c[1], c[2], at(3)[3]],
            Base::Luminance => [at(0)[0], at(1)[0], at(2)[0], c[3]],
            Base::LuminanceAlpha => [at(0)[0], at(1)[0], at(2)[0], at(3)[3]],
            Base::Intensity => [at(0)[0], at(1)[0], at(2)[0], at(3)[0]],
            Base::Rgb => [at(0)[0], at(1)[1], at(2)[2], c[3]],
            _ => [at(0)[0], at(1)[1], at(2)[2], at(3)[3]],
        }
    }
}

/// A convolution filter (CONVOLUTION_1D, CONVOLUTION_2D or SEPARABLE_2D)
/// and its parameters.
#[derive(Clone, Debug, PartialEq)]
pub struct Filter {
    pub internal_format: u32,
    pub base: Base,
    pub width: usize,
    pub height: usize,
    /// width x height taps (separable: the row's `width`, then the
    /// column's `height`), after the filter scale and bias.
    pub taps: Vec<[f32; 4]>,
    pub border_mode: u32,
    pub border_color: [f32; 4],
    pub scale: [f32; 4],
    pub bias: [f32; 4],
}

impl Default for Filter {
    fn default() -> Self {
        Filter { internal_format: GL_RGBA, base: Base::Rgba, width: 0, height: 0, taps: Vec::new(), border_mode: GL_REDUCE, border_color: [0.0; 4], scale: [1.0; 4], bias: [0.0; 4] }
    }
}

impl Filter {
    /// Which components the filter convolves (table 3.x: the others pass
    /// through), and the tap's weight for each (L and I from R).
    fn weights(&self, t: [f32; 4]) -> ([bool; 4], [f32; 4]) {
        match self.base {
            Base::Alpha => ([false, false, false, true], [0.0, 0.0, 0.0, t[3]]),
            Base::Luminance => ([true, true, true, false], [t[0], t[0], t[0], 0.0]),
            Base::LuminanceAlpha => ([true; 4], [t[0], t[0], t[0], t[3]]),
            Base::Intensity => ([true; 4], [t[0]; 4]),
            Base::Rgb => ([true, true, true, false], [t[0], t[1], t[2], 0.0]),
            _ => ([true; 4], t),
        }
    }

    /// Tap (m, n) of the 2D filter (separable: row[m] * column[n]).
    fn tap(&self, separable: bool, m: usize, n: usize) -> [f32; 4] {
        if separable {
            let (r, c) = (self.taps[m], self.taps[self.width + n]);
            [r[0] * c[0], r[1] * c[1], r[2] * c[2], r[3] * c[3]]
        } else {
            self.taps[n * self.width + m]
        }
    }
}

/// Histogram state.
#[derive(Clone, Debug, PartialEq)]
pub struct Histogram {
    pub width: usize,
    pub internal_format: u32,
    pub base: Base,
    pub sink: bool,
    pub counts: Vec<[u64; 4]>,
}

impl Default for Histogram {
    fn default() -> Self {
        Histogram { width: 0, internal_format: GL_RGBA, base: Base::Rgba, sink: false, counts: Vec::new() }
    }
}

/// Minmax state: the extremes of each component seen so far.
#[derive(Clone, Debug, PartialEq)]
pub struct Minmax {
    pub internal_format: u32,
    pub base: Base,
    pub sink: bool,
    pub min: [f32; 4],
    pub max: [f32; 4],
}

impl Default for Minmax {
    fn default() -> Self {
        Minmax { internal_format: GL_RGBA, base: Base::Rgba, sink: false, min: [f32::MAX; 4], max: [f32::MIN; 4] }
    }
}

/// Which components a table, histogram or minmax of base `b` holds.
fn components(b: Base) -> [bool; 4] {
    match b {
        Base::Alpha => [false, false, false, true],
        Base::Luminance | Base::Intensity => [true, false, false, false],
        Base::LuminanceAlpha => [true, false, false, true],
        Base::Rgb => [true, true, true, false],
        _ => [true; 4],
    }
}

/// All ARB_imaging state but the enables (in `OtherCaps`), the colour
/// matrix stack (`Transform::color`) and the post-convolution and
/// post-colour-matrix scale and bias (`PixelTransfer`).
#[derive(Clone, Debug, Default)]
pub struct Imaging {
    /// COLOR_TABLE, POST_CONVOLUTION_COLOR_TABLE, POST_COLOR_MATRIX_COLOR_TABLE.
    pub tables: [ColorTable; 3],
    pub proxies: [ColorTable; 3],
    /// CONVOLUTION_1D, CONVOLUTION_2D, SEPARABLE_2D.
    pub filters: [Filter; 3],
    pub histogram: Histogram,
    pub proxy_histogram: Histogram,
    pub minmax: Minmax,
}

/// The imaging state of GL_PIXEL_MODE_BIT: each colour table's scale and
/// bias, each filter's border mode, border colour, scale and bias.
#[derive(Clone, Debug, PartialEq)]
pub struct PixelModeParams {
    tables: [([f32; 4], [f32; 4]); 3],
    filters: [FilterParams; 3],
}

/// A filter's border mode, border colour, scale and bias.
type FilterParams = (u32, [f32; 4], [f32; 4], [f32; 4]);

impl Imaging {
    pub fn pixel_mode_params(&self) -> PixelModeParams {
        PixelModeParams { tables: self.tables.each_ref().map(|t| (t.scale, t.bias)), filters: self.filters.each_ref().map(|f| (f.border_mode, f.border_color, f.scale, f.bias)) }
    }

    pub fn set_pixel_mode_params(&mut self, p: PixelModeParams) {
        for (t, (scale, bias)) in self.tables.iter_mut().zip(p.tables) {
            (t.scale, t.bias) = (scale, bias);
        }
        for (f, (mode, color, scale, bias)) in self.filters.iter_mut().zip(p.filters) {
            (f.border_mode, f.border_color, f.scale, f.bias) = (mode, color, scale, bias);
        }
    }
}

/// The stages on for one image, decided once per command.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct Stages {
    pub tables: [bool; 3],
    /// The filter to convolve with: 0 (1D), 1 (2D) or 2 (separable).
    pub filter: Option<usize>,
    pub matrix: bool,
    pub histogram: bool,
    pub minmax: bool,
}

/// A table target: (index, proxy).
fn table_target(target: u32) -> Option<(usize, bool)> {
    Some(match target {
        GL_COLOR_TABLE => (0, false),
        GL_POST_CONVOLUTION_COLOR_TABLE => (1, false),
        GL_POST_COLOR_MATRIX_COLOR_TABLE => (2, false),
        GL_PROXY_COLOR_TABLE => (0, true),
        GL_PROXY_POST_CONVOLUTION_COLOR_TABLE => (1, true),
        GL_PROXY_POST_COLOR_MATRIX_COLOR_TABLE => (2, true),
        _ => return None,
    })
}

fn filter_target(target: u32) -> Option<usize> {
    Some(match target {
        GL_CONVOLUTION_1D => 0,
        GL_CONVOLUTION_2D => 1,
        GL_SEPARABLE_2D => 2,
        _ => return None,
    })
}

/// A table/filter/histogram internal format: a colour base format
/// (INVALID_ENUM otherwise, as the imaging commands say).
fn color_format(f: u32) -> Option<(Base, [u8; 7])> {
    let i = internal_format(f).filter(|i| i.base != Base::Depth && !matches!(f, 0x1903 | 0x8227 | 0x8229 | 0x822A | 0x822B | 0x822C | 0x8225 | 0x8226))?;
    // Formats 1-4 are texture-only shorthands.
    (f > 4).then_some((i.base, i.stored_bits()))
}

/// The commands of section 3.6.3 that display lists record, with their
/// client data already unpacked (RGBA, before any transfer).
#[derive(Clone, Debug, PartialEq)]
pub enum ImagingCmd {
    ColorTable { target: u32, internal_format: u32, width: i32, data: Option<Vec<[f32; 4]>> },
    ColorSubTable { target: u32, start: i32, count: i32, data: Option<Vec<[f32; 4]>> },
    CopyColorTable { target: u32, internal_format: u32, x: i32, y: i32, width: i32 },
    CopyColorSubTable { target: u32, start: i32, x: i32, y: i32, width: i32 },
    ColorTableParameter { target: u32, pname: u32, v: [f32; 4] },
    ConvolutionFilter { target: u32, internal_format: u32, width: i32, height: i32, data: Option<Vec<[f32; 4]>> },
    SeparableFilter { target: u32, internal_format: u32, width: i32, height: i32, row: Option<Vec<[f32; 4]>>, column: Option<Vec<[f32; 4]>> },
    CopyConvolutionFilter { target: u32, internal_format: u32, x: i32, y: i32, width: i32, height: i32 },
    ConvolutionParameter { target: u32, pname: u32, v: [f32; 4] },
    Histogram { target: u32, width: i32, internal_format: u32, sink: bool },
    ResetHistogram(u32),
    Minmax { target: u32, internal_format: u32, sink: bool },
    ResetMinmax(u32),
}

impl Context {
    /// Unpacks a w x h colour image for an imaging command (RGBA groups,
    /// no pixel transfer); Err: the format/type error; Ok(None): no data.
    ///
    /// # Safety
    /// `ptr` must be NULL or point to the image as the unpack modes lay it out.
    pub unsafe fn unpack_imaging(&self, w: i32, h: i32, format: u32, ty: u32, ptr: *const u8) -> Result<Option<Vec<[f32; 4]>>, u32> {
        match check_format_type(format, ty)? {
            Kind::Color => {}
            _ => return Err(GL_INVALID_ENUM),
        }
        if (ptr.is_null() && !self.unpack_buffer_bound()) || w < 0 || h < 0 || w as usize > MAX_TABLE * MAX_TABLE || h as usize > MAX_TABLE {
            return Ok(None);
        }
        let ptr = self.unpack_image(&self.pixel_store.unpack, w, h, 1, format, ty, ptr)?;
        let (w, h) = (w as usize, h as usize);
        Ok(Some(Source::new(&self.pixel_store.unpack, w, h, 1, format, ty, ptr).colors(w, h, 1)))
    }

    /// Runs an imaging state command.
    pub fn imaging_command(&mut self, cmd: &ImagingCmd) {
        use ImagingCmd::*;
        match cmd {
            ColorTable { target, internal_format, width, data } => self.color_table(*target, *internal_format, *width, data.as_deref()),
            ColorSubTable { target, start, count, data } => self.color_sub_table(*target, *start, *count, data.as_deref()),
            CopyColorTable { target, internal_format, x, y, width } => {
                let px = self.framebuffer_colors(*x, *y, *width, 1);
                self.color_table(*target, *internal_format, *width, Some(&px));
            }
            CopyColorSubTable { target, start, x, y, width } => {
                let px = self.framebuffer_colors(*x, *y, *width, 1);
                self.color_sub_table(*target, *start, *width, Some(&px));
            }
            ColorTableParameter { target, pname, v } => self.color_table_parameter(*target, *pname, *v),
            ConvolutionFilter { target, internal_format, width, height, data } => self.convolution_filter(*target, *internal_format, *width, *height, data.as_deref(), None),
            SeparableFilter { target, internal_format, width, height, row, column } => {
                if *target != GL_SEPARABLE_2D {
                    return self.set_error(GL_INVALID_ENUM);
                }
                self.convolution_filter(*target, *internal_format, *width, *height, row.as_deref(), Some(column.as_deref()))
            }
            CopyConvolutionFilter { target, internal_format, x, y, width, height } => {
                if !matches!(*target, GL_CONVOLUTION_1D | GL_CONVOLUTION_2D) {
                    return self.set_error(GL_INVALID_ENUM);
                }
                let px = self.framebuffer_colors(*x, *y, *width, *height);
                self.convolution_filter(*target, *internal_format, *width, *height, Some(&px), None)
            }
            ConvolutionParameter { target, pname, v } => self.convolution_parameter(*target, *pname, *v),
            Histogram { target, width, internal_format, sink } => self.histogram(*target, *width, *internal_format, *sink),
            ResetHistogram(target) => {
                if *target != GL_HISTOGRAM {
                    return self.set_error(GL_INVALID_ENUM);
                }
                let h = &mut self.imaging.histogram;
                h.counts = vec![[0; 4]; h.width];
            }
            Minmax { target, internal_format, sink } => {
                if *target != GL_MINMAX {
                    return self.set_error(GL_INVALID_ENUM);
                }
                let Some((base, _)) = color_format(*internal_format) else { return self.set_error(GL_INVALID_ENUM) };
                self.imaging.minmax = self::Minmax { internal_format: *internal_format, base, sink: *sink, ..Default::default() };
            }
            ResetMinmax(target) => {
                if *target != GL_MINMAX {
                    return self.set_error(GL_INVALID_ENUM);
                }
                let m = &mut self.imaging.minmax;
                (m.min, m.max) = ([f32::MAX; 4], [f32::MIN; 4]);
            }
        }
    }

    /// Colours of a framebuffer rectangle (glReadBuffer's buffer) as RGBA
    /// groups; pixels outside the window read as zero.
    pub(crate) fn framebuffer_colors(&self, x: i32, y: i32, w: i32, h: i32) -> Vec<[f32; 4]> {
        let fb = &self.fb;
        let read = self.read_color();
        let mut out = Vec::with_capacity(w.max(0) as usize * h.max(0) as usize);
        for j in 0..h.max(0) {
            for i in 0..w.max(0) {
                let (fx, fy) = (x as i64 + i as i64, y as i64 + j as i64);
                let inside = fx >= 0 && fy >= 0 && fx < fb.width as i64 && fy < fb.height as i64;
                out.push(if inside { read[fb.index(fx as usize, fy as usize)].map(|v| v as f32 / 255.0) } else { [0.0; 4] });
            }
        }
        out
    }

    /// glColorTable / glCopyColorTable (section 3.6.3).
    fn color_table(&mut self, target: u32, ifmt: u32, width: i32, data: Option<&[[f32; 4]]>) {
        let Some((k, proxy)) = table_target(target) else { return self.set_error(GL_INVALID_ENUM) };
        let Some((base, _)) = color_format(ifmt) else { return self.set_error(GL_INVALID_ENUM) };
        if width < 0 || !(width as u32).is_power_of_two() && width != 0 {
            return self.set_error(GL_INVALID_VALUE);
        }
        let too_large = width as usize > MAX_TABLE;
        if proxy {
            // A table softgl cannot hold reads back as width 0, format 0.
            self.imaging.proxies[k] = if too_large { ColorTable { internal_format: 0, width: 0, ..Default::default() } } else { ColorTable { internal_format: ifmt, base, width: width as usize, ..Default::default() } };
            return;
        }
        if too_large {
            return self.set_error(GL_TABLE_TOO_LARGE);
        }
        let t = &mut self.imaging.tables[k];
        let (scale, bias) = (t.scale, t.bias);
        let entries = match data {
            Some(d) if d.len() == width as usize => d.iter().map(|c| std::array::from_fn(|i| (c[i] * scale[i] + bias[i]).clamp(0.0, 1.0))).collect(),
            _ => vec![[0.0; 4]; width as usize],
        };
        *t = ColorTable { internal_format: ifmt, base, width: width as usize, entries, scale, bias };
    }

    /// glColorSubTable / glCopyColorSubTable.
    fn color_sub_table(&mut self, target: u32, start: i32, count: i32, data: Option<&[[f32; 4]]>) {
        let Some((k, false)) = table_target(target) else { return self.set_error(GL_INVALID_ENUM) };
        let t = &mut self.imaging.tables[k];
        if start < 0 || count < 0 || start as usize + count as usize > t.width {
            return self.set_error(GL_INVALID_VALUE);
        }
        let (scale, bias) = (t.scale, t.bias);
        if let Some(d) = data.filter(|d| d.len() == count as usize) {
            for (i, c) in d.iter().enumerate() {
                t.entries[start as usize + i] = std::array::from_fn(|n| (c[n] * scale[n] + bias[n]).clamp(0.0, 1.0));
            }
        }
    }

    fn color_table_parameter(&mut self, target: u32, pname: u32, v: [f32; 4]) {
        let Some((k, false)) = table_target(target) else { return self.set_error(GL_INVALID_ENUM) };
        let t = &mut self.imaging.tables[k];
        match pname {
            GL_COLOR_TABLE_SCALE => t.scale = v,
            GL_COLOR_TABLE_BIAS => t.bias = v,
            _ => self.set_error(GL_INVALID_ENUM),
        }
    }

    /// glGetColorTableParameter.
    pub fn get_color_table_parameter(&mut self, target: u32, pname: u32) -> Option<Value> {
        let Some((k, proxy)) = table_target(target) else {
            self.set_error(GL_INVALID_ENUM);
            return None;
        };
        let t = if proxy { &self.imaging.proxies[k] } else { &self.imaging.tables[k] };
        let bits = color_format(t.internal_format).map_or([0; 7], |f| f.1);
        // Component sizes of an empty table are 0 (their initial value).
        let size = |c: usize| if t.width > 0 { bits[c] as i64 } else { 0 };
        Some(match pname {
            GL_COLOR_TABLE_SCALE if !proxy => Value::Floats(t.scale.iter().map(|&x| x as f64).collect()),
            GL_COLOR_TABLE_BIAS if !proxy => Value::Floats(t.bias.iter().map(|&x| x as f64).collect()),
            GL_COLOR_TABLE_FORMAT => Value::Ints(vec![t.internal_format as i64]),
            GL_COLOR_TABLE_WIDTH => Value::Ints(vec![t.width as i64]),
            GL_COLOR_TABLE_RED_SIZE..=GL_COLOR_TABLE_INTENSITY_SIZE => Value::Ints(vec![size((pname - GL_COLOR_TABLE_RED_SIZE) as usize)]),
            _ => {
                self.set_error(GL_INVALID_ENUM);
                return None;
            }
        })
    }

    /// Checks a Get* call's format and type (colour formats only).
    fn check_get_format(&mut self, format: u32, ty: u32) -> bool {
        match check_format_type(format, ty) {
            Ok(Kind::Color) => true,
            Ok(_) => {
                self.set_error(GL_INVALID_ENUM);
                false
            }
            Err(e) => {
                self.set_error(e);
                false
            }
        }
    }

    /// glGetColorTable: the table as RGBA (table 6.1's components; no
    /// pixel transfer), packed by the pack modes.
    ///
    /// # Safety
    /// `out` must be NULL or have room for the table as packed.
    pub unsafe fn get_color_table(&mut self, target: u32, format: u32, ty: u32, out: *mut u8) {
        let Some((k, false)) = table_target(target) else { return self.set_error(GL_INVALID_ENUM) };
        if !self.check_get_format(format, ty) || (out.is_null() && !self.pack_buffer_bound()) {
            return;
        }
        let pack = self.pixel_store.pack;
        let out = match self.pack_image(&pack, self.imaging.tables[k].width as i32, 1, 1, format, ty, out) {
            Ok(p) => p,
            Err(e) => return self.set_error(e),
        };
        let t = &self.imaging.tables[k];
        let mut dest = Dest::new(&self.pixel_store.pack, t.width, 1, format, ty, out);
        for (i, e) in t.entries.iter().enumerate() {
            put_value(&mut dest, i, 0, texel_to_rgba(t.base, *e));
        }
    }

    /// glConvolutionFilter1D/2D, glCopyConvolutionFilter*, and (with
    /// `column`) glSeparableFilter2D.
    fn convolution_filter(&mut self, target: u32, ifmt: u32, width: i32, height: i32, data: Option<&[[f32; 4]]>, column: Option<Option<&[[f32; 4]]>>) {
        let Some(k) = filter_target(target) else { return self.set_error(GL_INVALID_ENUM) };
        if (k == 2) != column.is_some() {
            return self.set_error(GL_INVALID_ENUM);
        }
        let Some((base, _)) = color_format(ifmt) else { return self.set_error(GL_INVALID_ENUM) };
        let height = if k == 0 { 1 } else { height };
        if width < 0 || height < 0 || width as usize > MAX_CONVOLUTION || height as usize > MAX_CONVOLUTION {
            return self.set_error(GL_INVALID_VALUE);
        }
        let (w, h) = (width as usize, height as usize);
        let f = &mut self.imaging.filters[k];
        let (scale, bias) = (f.scale, f.bias);
        let sb = |c: &[f32; 4]| -> [f32; 4] { std::array::from_fn(|i| c[i] * scale[i] + bias[i]) };
        let taps = match column {
            None => data.filter(|d| d.len() == w * h).map_or(vec![[0.0; 4]; w * h], |d| d.iter().map(sb).collect()),
            Some(col) => {
                let mut t: Vec<[f32; 4]> = data.filter(|d| d.len() == w).map_or(vec![[0.0; 4]; w], |d| d.iter().map(sb).collect());
                t.extend(col.filter(|d| d.len() == h).map_or(vec![[0.0; 4]; h], |d| d.iter().map(sb).collect()));
                t
            }
        };
        f.internal_format = ifmt;
        f.base = base;
        f.width = w;
        f.height = h;
        f.taps = taps;
    }

    fn convolution_parameter(&mut self, target: u32, pname: u32, v: [f32; 4]) {
        let Some(k) = filter_target(target) else { return self.set_error(GL_INVALID_ENUM) };
        let f = &mut self.imaging.filters[k];
        match pname {
            GL_CONVOLUTION_BORDER_MODE => match v[0] as u32 {
                m @ (GL_REDUCE | GL_CONSTANT_BORDER | GL_REPLICATE_BORDER) => f.border_mode = m,
                _ => self.set_error(GL_INVALID_ENUM),
            },
            GL_CONVOLUTION_BORDER_COLOR => f.border_color = v,
            GL_CONVOLUTION_FILTER_SCALE => f.scale = v,
            GL_CONVOLUTION_FILTER_BIAS => f.bias = v,
            _ => self.set_error(GL_INVALID_ENUM),
        }
    }

    /// glGetConvolutionParameter.
    pub fn get_convolution_parameter(&mut self, target: u32, pname: u32) -> Option<Value> {
        let Some(k) = filter_target(target) else {
            self.set_error(GL_INVALID_ENUM);
            return None;
        };
        let f = &self.imaging.filters[k];
        let floats = |v: [f32; 4]| Value::Floats(v.iter().map(|&x| x as f64).collect());
        Some(match pname {
            GL_CONVOLUTION_BORDER_MODE => Value::Ints(vec![f.border_mode as i64]),
            GL_CONVOLUTION_BORDER_COLOR => floats(f.border_color),
            GL_CONVOLUTION_FILTER_SCALE => floats(f.scale),
            GL_CONVOLUTION_FILTER_BIAS => floats(f.bias),
            GL_CONVOLUTION_FORMAT => Value::Ints(vec![f.internal_format as i64]),
            GL_CONVOLUTION_WIDTH => Value::Ints(vec![f.width as i64]),
            GL_CONVOLUTION_HEIGHT => Value::Ints(vec![f.height as i64]),
            GL_MAX_CONVOLUTION_WIDTH => Value::Ints(vec![MAX_CONVOLUTION as i64]),
            GL_MAX_CONVOLUTION_HEIGHT => Value::Ints(vec![if k == 0 { 1 } else { MAX_CONVOLUTION as i64 }]),
            _ => {
                self.set_error(GL_INVALID_ENUM);
                return None;
            }
        })
    }

    /// glGetConvolutionFilter (1D and 2D filters) and glGetSeparableFilter
    /// (`column` Some): the taps as RGBA, no pixel transfer.
    ///
    /// # Safety
    /// `out` and `column` must be NULL or have room for the images as packed.
    pub unsafe fn get_convolution_filter(&mut self, target: u32, format: u32, ty: u32, out: *mut u8, column: Option<*mut u8>) {
        let Some(k) = filter_target(target) else { return self.set_error(GL_INVALID_ENUM) };
        if (k == 2) != column.is_some() {
            return self.set_error(GL_INVALID_ENUM);
        }
        if !self.check_get_format(format, ty) {
            return;
        }
        let pack = self.pixel_store.pack;
        // With a pixel pack buffer, the pointers are offsets into it.
        let bound = self.pack_buffer_bound();
        let (fw, fh) = (self.imaging.filters[k].width as i32, self.imaging.filters[k].height as i32);
        let (out, column) = match column {
            None => (self.pack_image(&pack, fw, fh, 1, format, ty, out), None),
            Some(col) => (self.pack_image(&pack, fw, 1, 1, format, ty, out), Some(self.pack_image(&pack, fh, 1, 1, format, ty, col))),
        };
        let (out, column) = match (out, column.transpose()) {
            (Ok(o), Ok(c)) => (o, c),
            (Err(e), _) | (_, Err(e)) => return self.set_error(e),
        };
        let f = &self.imaging.filters[k];
        let write = |ptr: *mut u8, w: usize, h: usize, taps: &[[f32; 4]]| {
            if ptr.is_null() && !bound {
                return;
            }
            let mut dest = Dest::new(&pack, w, h, format, ty, ptr);
            for (n, t) in taps.iter().enumerate() {
                put_value(&mut dest, n % w.max(1), n / w.max(1), texel_to_rgba(f.base, *t));
            }
        };
        match column {
            None => write(out, f.width, f.height, &f.taps),
            Some(col) => {
                write(out, f.width, 1, &f.taps[..f.width]);
                write(col, f.height, 1, &f.taps[f.width..]);
            }
        }
    }

    /// glHistogram (proxy: level state only).
    fn histogram(&mut self, target: u32, width: i32, ifmt: u32, sink: bool) {
        let proxy = match target {
            GL_HISTOGRAM => false,
            GL_PROXY_HISTOGRAM => true,
            _ => return self.set_error(GL_INVALID_ENUM),
        };
        if width < 0 || width != 0 && !(width as u32).is_power_of_two() {
            return self.set_error(GL_INVALID_VALUE);
        }
        let Some((base, _)) = color_format(ifmt).filter(|(b, _)| *b != Base::Intensity) else { return self.set_error(GL_INVALID_ENUM) };
        let too_large = width as usize > MAX_TABLE;
        let h = Histogram { width: width as usize, internal_format: ifmt, base, sink, counts: vec![[0; 4]; if proxy || too_large { 0 } else { width as usize }] };
        if proxy {
            self.imaging.proxy_histogram = if too_large { Histogram { internal_format: 0, ..Default::default() } } else { h };
        } else if too_large {
            self.set_error(GL_TABLE_TOO_LARGE);
        } else {
            self.imaging.histogram = h;
        }
    }

    /// glGetHistogram: the counts of the components the histogram keeps
    /// (others 0), packed as integers of the type; `reset` zeroes them.
    ///
    /// # Safety
    /// `out` must be NULL or have room for the histogram as packed.
    pub unsafe fn get_histogram(&mut self, target: u32, reset: bool, format: u32, ty: u32, out: *mut u8) {
        if target != GL_HISTOGRAM {
            return self.set_error(GL_INVALID_ENUM);
        }
        if !self.check_get_format(format, ty) {
            return;
        }
        let pack = self.pixel_store.pack;
        let out = match self.pack_image(&pack, self.imaging.histogram.width as i32, 1, 1, format, ty, out) {
            Ok(p) => p,
            Err(e) => return self.set_error(e),
        };
        let bound = self.pack_buffer_bound();
        let h = &mut self.imaging.histogram;
        if !out.is_null() || bound {
            let mut dest = Dest::new(&self.pixel_store.pack, h.width, 1, format, ty, out);
            for (i, c) in h.counts.iter().enumerate() {
                dest.put_counts(i, 0, c.map(|n| n as f64));
            }
        }
        if reset {
            h.counts.iter_mut().for_each(|c| *c = [0; 4]);
        }
    }

    pub fn get_histogram_parameter(&mut self, target: u32, pname: u32) -> Option<Value> {
        let h = match target {
            GL_HISTOGRAM => &self.imaging.histogram,
            GL_PROXY_HISTOGRAM => &self.imaging.proxy_histogram,
            _ => {
                self.set_error(GL_INVALID_ENUM);
                return None;
            }
        };
        let bits = color_format(h.internal_format).map_or([0; 7], |f| f.1);
        let i = |v: i64| Some(Value::Ints(vec![v]));
        match pname {
            GL_HISTOGRAM_WIDTH => i(h.width as i64),
            GL_HISTOGRAM_FORMAT => i(h.internal_format as i64),
            // Counts are 64-bit integers: report 32 bits per kept component.
            GL_HISTOGRAM_RED_SIZE..=GL_HISTOGRAM_LUMINANCE_SIZE => {
                let k = (pname - GL_HISTOGRAM_RED_SIZE) as usize;
                i(if bits[k] > 0 && h.width > 0 { 32 } else { 0 })
            }
            GL_HISTOGRAM_SINK => Some(Value::Bools(vec![h.sink])),
            _ => {
                self.set_error(GL_INVALID_ENUM);
                None
            }
        }
    }

    /// glGetMinmax: (min, max) as two RGBA groups (components the minmax
    /// does not keep read 0; before any value they read as the extreme
    /// floats, clamped by the type); `reset` restarts it.
    ///
    /// # Safety
    /// `out` must be NULL or have room for 2 groups as packed.
    pub unsafe fn get_minmax(&mut self, target: u32, reset: bool, format: u32, ty: u32, out: *mut u8) {
        if target != GL_MINMAX {
            return self.set_error(GL_INVALID_ENUM);
        }
        if !self.check_get_format(format, ty) {
            return;
        }
        let pack = self.pixel_store.pack;
        let out = match self.pack_image(&pack, 2, 1, 1, format, ty, out) {
            Ok(p) => p,
            Err(e) => return self.set_error(e),
        };
        let bound = self.pack_buffer_bound();
        let m = &mut self.imaging.minmax;
        if !out.is_null() || bound {
            let keep = components(m.base);
            let pick = |v: [f32; 4]| -> [f32; 4] {
                let v = std::array::from_fn(|k| if keep[k] { v[k] } else { 0.0 });
                texel_to_rgba(m.base, v)
            };
            let mut dest = Dest::new(&self.pixel_store.pack, 2, 1, format, ty, out);
            put_value(&mut dest, 0, 0, pick(m.min));
            put_value(&mut dest, 1, 0, pick(m.max));
        }
        if reset {
            (m.min, m.max) = ([f32::MAX; 4], [f32::MIN; 4]);
        }
    }

    pub fn get_minmax_parameter(&mut self, target: u32, pname: u32) -> Option<Value> {
        if target != GL_MINMAX {
            self.set_error(GL_INVALID_ENUM);
            return None;
        }
        let m = &self.imaging.minmax;
        match pname {
            GL_MINMAX_FORMAT => Some(Value::Ints(vec![m.internal_format as i64])),
            GL_MINMAX_SINK => Some(Value::Bools(vec![m.sink])),
            _ => {
                self.set_error(GL_INVALID_ENUM);
                None
            }
        }
    }

    /// glGet of the imaging state outside the tables (tables 6.20, 6.21).
    pub fn imaging_get(&self, pname: u32) -> Option<Value> {
        let t = &self.pixel;
        let floats = |v: &[f32]| Some(Value::Floats(v.iter().map(|&x| x as f64).collect()));
        let m = self.transform.color.top();
        match pname {
            GL_COLOR_MATRIX => Some(Value::Floats(m.to_cols_array().to_vec())),
            GL_TRANSPOSE_COLOR_MATRIX => Some(Value::Floats(m.transpose().to_cols_array().to_vec())),
            GL_COLOR_MATRIX_STACK_DEPTH => Some(Value::Ints(vec![self.transform.color.depth() as i64])),
            GL_MAX_COLOR_MATRIX_STACK_DEPTH => Some(Value::Ints(vec![super::matrix::MAX_COLOR_DEPTH as i64])),
            GL_POST_CONVOLUTION_RED_SCALE..=GL_POST_CONVOLUTION_ALPHA_BIAS => {
                let k = (pname - GL_POST_CONVOLUTION_RED_SCALE) as usize;
                floats(&[if k < 4 { t.post_convolution_scale[k] } else { t.post_convolution_bias[k - 4] }])
            }
            GL_POST_COLOR_MATRIX_RED_SCALE..=GL_POST_COLOR_MATRIX_ALPHA_BIAS => {
                let k = (pname - GL_POST_COLOR_MATRIX_RED_SCALE) as usize;
                floats(&[if k < 4 { t.post_color_matrix_scale[k] } else { t.post_color_matrix_bias[k - 4] }])
            }
            _ => None,
        }
    }

    /// The imaging stages on for a `dims`-dimensional image (1: a 1D
    /// texture image, 2: pixel rectangles and 2D texture images, 3: 3D
    /// texture images), or None when none is: the caller then skips
    /// [`Context::imaging`] altogether.
    pub fn imaging_stages(&self, dims: u8) -> Option<Stages> {
        let caps = &self.other_caps.0;
        let im = &self.imaging;
        let on = |cap: u32| caps.contains(&cap);
        let t = &self.pixel;
        let tables = [GL_COLOR_TABLE, GL_POST_CONVOLUTION_COLOR_TABLE, GL_POST_COLOR_MATRIX_COLOR_TABLE];
        let filter = match dims {
            1 if on(GL_CONVOLUTION_1D) => Some(0),
            2 if on(GL_CONVOLUTION_2D) => Some(1),
            2 if on(GL_SEPARABLE_2D) => Some(2),
            _ => None,
        };
        let s = Stages {
            tables: [0, 1, 2].map(|k| on(tables[k]) && im.tables[k].width > 0),
            filter,
            matrix: *self.transform.color.top() != glam::DMat4::IDENTITY || t.post_color_matrix_scale != [1.0; 4] || t.post_color_matrix_bias != [0.0; 4],
            histogram: on(GL_HISTOGRAM) && im.histogram.width > 0,
            minmax: on(GL_MINMAX),
        };
        (s != Stages::default()).then_some(s)
    }

    /// Runs the stages on a w x h image of RGBA groups (after scale, bias
    /// and MAP_COLOR, unclamped), then the final clamp. Returns the image
    /// and its size (convolution's REDUCE shrinks it), or None when a
    /// histogram or minmax sink consumed it.
    pub fn imaging(&mut self, s: Stages, mut px: Vec<[f32; 4]>, mut w: usize, mut h: usize) -> Option<(Vec<[f32; 4]>, usize, usize)> {
        let im = &mut self.imaging;
        if s.tables[0] {
            px.iter_mut().for_each(|c| *c = im.tables[0].lookup(*c));
        }
        if let Some(k) = s.filter {
            (px, w, h) = convolve(&im.filters[k], k == 2, &px, w, h);
            let (sc, bi) = (self.pixel.post_convolution_scale, self.pixel.post_convolution_bias);
            px.iter_mut().for_each(|c| *c = std::array::from_fn(|i| c[i] * sc[i] + bi[i]));
        }
        if s.tables[1] {
            px.iter_mut().for_each(|c| *c = im.tables[1].lookup(*c));
        }
        if s.matrix {
            let m = self.transform.color.top().as_mat4();
            let (sc, bi) = (self.pixel.post_color_matrix_scale, self.pixel.post_color_matrix_bias);
            for c in px.iter_mut() {
                let v = (m * glam::Vec4::from_array(*c)).to_array();
                *c = std::array::from_fn(|i| v[i] * sc[i] + bi[i]);
            }
        }
        if s.tables[2] {
            px.iter_mut().for_each(|c| *c = im.tables[2].lookup(*c));
        }
        let mut sink = false;
        if s.histogram {
            let hist = &mut im.histogram;
            let keep = components(hist.base);
            let n = hist.width;
            for c in &px {
                for k in 0..4 {
                    // Luminance counts R.
                    if keep[k] {
                        let i = ((c[k].clamp(0.0, 1.0) * (n - 1) as f32).round() as usize).min(n - 1);
                        hist.counts[i][k] += 1;
                    }
                }
            }
            sink |= hist.sink;
        }
        if s.minmax {
            let m = &mut im.minmax;
            for c in &px {
                for (k, &v) in c.iter().enumerate() {
                    m.min[k] = m.min[k].min(v);
                    m.max[k] = m.max[k].max(v);
                }
            }
            sink |= m.sink;
        }
        if sink {
            return None;
        }
        px.iter_mut().for_each(|c| *c = c.map(|v| if v.is_nan() { 0.0 } else { v.clamp(0.0, 1.0) }));
        Some((px, w, h))
    }
}

/// Packs a table, filter or minmax value: FLOAT as it is (filters and
/// minmax values may lie outside [0, 1]), other types normalized.
fn put_value(dest: &mut Dest, i: usize, j: usize, c: [f32; 4]) {
    if dest.ty == GL_FLOAT {
        dest.put_counts(i, j, c.map(|v| v as f64));
    } else {
        dest.put_color(i, j, c);
    }
}

/// Convolution (3.6.5) of a w x h image by a filter: REDUCE shrinks the
/// image to (w - Wf + 1) x (h - Hf + 1) and sums over the filter's
/// footprint from each output pixel; the border modes keep the size,
/// centre the filter (Cw = floor(Wf / 2)) and read outside pixels as the
/// border colour or the nearest edge pixel. Components the filter does not
/// hold pass through from the pixel under the filter's centre.
fn convolve(f: &Filter, separable: bool, px: &[[f32; 4]], w: usize, h: usize) -> (Vec<[f32; 4]>, usize, usize) {
    let (fw, fh) = (f.width, f.height.max(1));
    if fw == 0 {
        return (px.to_vec(), w, h);
    }
    let reduce = f.border_mode == GL_REDUCE;
    let (ow, oh) = if reduce { ((w + 1).saturating_sub(fw), (h + 1).saturating_sub(fh)) } else { (w, h) };
    let (cw, ch) = ((fw / 2) as i64, (fh / 2) as i64);
    // REDUCE reads from (i + m, j + n): the footprint starts at the output pixel.
    let (ox, oy) = if reduce { (0, 0) } else { (cw, ch) };
    let read = |x: i64, y: i64| -> [f32; 4] {
        if x >= 0 && y >= 0 && (x as usize) < w && (y as usize) < h {
            px[y as usize * w + x as usize]
        } else if f.border_mode == GL_REPLICATE_BORDER {
            px[y.clamp(0, h as i64 - 1) as usize * w + x.clamp(0, w as i64 - 1) as usize]
        } else {
            f.border_color
        }
    };
    let mut out = Vec::with_capacity(ow * oh);
    for j in 0..oh as i64 {
        for i in 0..ow as i64 {
            let centre = read(i - ox + cw, j - oy + ch);
            let mut acc = [0.0f32; 4];
            let mut mask = [false; 4];
            for n in 0..fh {
                for m in 0..fw {
                    let (k, wt) = f.weights(f.tap(separable, m, n));
                    mask = k;
                    let c = read(i - ox + m as i64, j - oy + n as i64);
                    for q in 0..4 {
                        acc[q] += c[q] * wt[q];
                    }
                }
            }
            out.push(std::array::from_fn(|q| if mask[q] { acc[q] } else { centre[q] }));
        }
    }
    (out, ow, oh)
}
