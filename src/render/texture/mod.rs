//! Texturing in the fragment stage (GL 1.5 sections 3.8.7 to 3.8.13):
//! texel addressing with the wrap modes, the level-of-detail computation,
//! minification and magnification filters, depth-texture comparison, and
//! the texture environments of every unit (`env`).
//!
//! Validation (`gl::texture::derive`) builds one [`TextureStage`] per state
//! change: for each unit whose texturing is enabled *and* whose texture is
//! complete, a [`UnitSampler`] holding the levels base..q (shared, not
//! copied) and the parameters; an incomplete texture leaves the unit
//! disabled, as GL says.
//!
//! Texels are stored already expanded to the "texture source colour" of
//! table 3.23 (a LUMINANCE texel is (L, L, L, 1), an ALPHA one
//! (0, 0, 0, A), ...), with the image's [`Base`] format kept beside them for
//! the environment functions: as 8-bit RGBA ([`Texels::Rgba8`]) for the
//! internal formats of at most 8 bits per component, as f32 RGBA
//! ([`Texels::Float`]) for wider ones and depth. Depth textures keep their
//! depth in every colour channel.
//!
//! Fast paths ([`Fast`], chosen once when validation builds the sampler):
//! a 1D or 2D texture stored as 8-bit RGBA, without border, whose minification
//! and magnification filters are the same non-mipmap filter and whose S
//! and T wrap modes are REPEAT or CLAMP_TO_EDGE is sampled by a nearest or
//! bilinear fetch specialized for that case: no LOD (both filters give the
//! same answer at every λ), no border colour, no depth comparison, no
//! per-texel storage dispatch. They compute exactly what the general path
//! computes (the unit tests compare them on random coordinates);
//! `SOFTGL_REFERENCE=1` turns them off. The same fetches serve each level
//! of 1D, 2D and cube-map textures under the other filters (`fast_wrap`).
//!
//! Addressing (3.8.7): u = s * n (rectangle textures: u = s, their
//! coordinates are in texels, and ρ is taken from them directly). For
//! nearest filtering i = floor(u) after the wrap
//! mode's treatment of s; for linear filtering i0 = floor(u - 1/2),
//! i1 = i0 + 1 with weights from frac(u - 1/2). REPEAT takes indices modulo
//! the size, MIRRORED_REPEAT mirrors them with period 2N, CLAMP_TO_EDGE
//! clamps them to [0, N-1]; CLAMP clamps s to [0, 1] and CLAMP_TO_BORDER
//! clamps s to [-1/2N, 1 + 1/2N], and an index outside the image (border
//! included) then reads the border colour.
//!
//! LOD (3.8.8): ρ = max(|∂(u,v,w)/∂x|, |∂(u,v,w)/∂y|) from the fragment's
//! exact derivatives of the perspective-corrected coordinates (computed in
//! `fragment` from the 1/w plane equations); λ = log2 ρ + bias ([`lod::log2`]), clamped to
//! [min_lod, max_lod]; λ > c minifies, where c = 1/2 when the magnification
//! filter is LINEAR and the minification filter is NEAREST_MIPMAP_NEAREST
//! or LINEAR_MIPMAP_NEAREST, else 0.

pub mod env;
pub mod lod;
pub mod pairs;

use crate::render::fragment::CompareFunc;
use glam::Vec4;
use std::sync::Arc;

pub use env::Env;

/// Texture units (GL_MAX_TEXTURE_UNITS).
pub const MAX_UNITS: usize = 4;

#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Target {
    T1D,
    T2D,
    T3D,
    Cube,
    /// ARB_texture_rectangle: a 2D image addressed by unnormalized
    /// coordinates (s in [0, width]), one level, no REPEAT wraps.
    Rect,
}

impl Target {
    /// Coordinates per texel fetch (a cube map's face images are 2D).
    pub fn dims(self) -> usize {
        match self {
            Target::T1D => 1,
            Target::T2D | Target::Cube | Target::Rect => 2,
            Target::T3D => 3,
        }
    }
}

/// The base internal format of an image (table 3.15).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Base {
    Alpha,
    Luminance,
    LuminanceAlpha,
    Intensity,
    Rgb,
    Rgba,
    Depth,
}

impl Base {
    /// An RGBA value as a texel of this base format (table 3.15): the
    /// components the format keeps, the others at their defaults.
    #[inline]
    pub fn expand(self, [r, g, b, a]: [f32; 4]) -> [f32; 4] {
        match self {
            Base::Alpha => [0.0, 0.0, 0.0, a],
            Base::Luminance | Base::Depth => [r, r, r, 1.0],
            Base::LuminanceAlpha => [r, r, r, a],
            Base::Intensity => [r, r, r, r],
            Base::Rgb => [r, g, b, 1.0],
            Base::Rgba => [r, g, b, a],
        }
    }
}

/// u8 to [0, 1]: c / 255 (table 2.9), exactly as f32 division gives it.
pub static UNORM8: [f32; 256] = {
    let mut t = [0.0f32; 256];
    let mut i = 0;
    while i < 256 {
        t[i] = i as f32 / 255.0;
        i += 1;
    }
    t
};

#[inline]
fn unorm8(p: [u8; 4]) -> [f32; 4] {
    [UNORM8[p[0] as usize], UNORM8[p[1] as usize], UNORM8[p[2] as usize], UNORM8[p[3] as usize]]
}

/// [0, 1] to the nearest u8 (values outside clamp).
#[inline]
pub fn to_unorm8(v: f32) -> u8 {
    (v.clamp(0.0, 1.0) * 255.0).round() as u8
}

/// An image's stored texels (expanded by table 3.23), row-major, bottom
/// row first, slices after each other.
#[derive(Clone, Debug, PartialEq)]
pub enum Texels {
    /// Internal formats of at most 8 bits per component (shared with the
    /// command that uploaded them when no conversion was needed).
    Rgba8(Arc<Vec<[u8; 4]>>),
    /// Wider formats and depth.
    Float(Vec<[f32; 4]>),
}

impl Default for Texels {
    fn default() -> Self {
        Texels::Float(Vec::new())
    }
}

impl Texels {
    /// Texels from f32 values already expanded by the base format, stored
    /// compactly (rounded to 8 bits) when `compact`.
    pub fn from_float(v: Vec<[f32; 4]>, compact: bool) -> Texels {
        if compact {
            Texels::Rgba8(Arc::new(v.iter().map(|t| t.map(to_unorm8)).collect()))
        } else {
            Texels::Float(v)
        }
    }

    pub fn len(&self) -> usize {
        match self {
            Texels::Rgba8(v) => v.len(),
            Texels::Float(v) => v.len(),
        }
    }

    pub fn is_empty(&self) -> bool {
        self.len() == 0
    }

    pub fn is_compact(&self) -> bool {
        matches!(self, Texels::Rgba8(_))
    }

    /// Texel `i` as f32.
    #[inline]
    pub fn get(&self, i: usize) -> [f32; 4] {
        match self {
            Texels::Rgba8(v) => unorm8(v[i]),
            Texels::Float(v) => v[i],
        }
    }

    /// Every texel as f32.
    pub fn to_float(&self) -> Vec<[f32; 4]> {
        match self {
            Texels::Rgba8(v) => v.iter().map(|&p| unorm8(p)).collect(),
            Texels::Float(v) => v.clone(),
        }
    }

    /// Copies `src` (a w x h x d block) into this image of row length
    /// `full_w` and `full_h` rows per slice at `offset`, row by row. Both
    /// must have the same storage (the same internal format); a mismatch
    /// converts per texel.
    pub fn write_block(&mut self, full_w: usize, full_h: usize, offset: [usize; 3], size: [usize; 3], src: &Texels) {
        let [w, h, d] = size;
        for k in 0..d {
            for j in 0..h {
                let s0 = (k * h + j) * w;
                let d0 = ((offset[2] + k) * full_h + offset[1] + j) * full_w + offset[0];
                match (&mut *self, src) {
                    (Texels::Rgba8(dst), Texels::Rgba8(s)) => Arc::make_mut(dst)[d0..d0 + w].copy_from_slice(&s[s0..s0 + w]),
                    (Texels::Float(dst), Texels::Float(s)) => dst[d0..d0 + w].copy_from_slice(&s[s0..s0 + w]),
                    (Texels::Rgba8(dst), s) => {
                        let dst = Arc::make_mut(dst);
                        for i in 0..w {
                            dst[d0 + i] = s.get(s0 + i).map(to_unorm8);
                        }
                    }
                    (Texels::Float(dst), s) => {
                        for i in 0..w {
                            dst[d0 + i] = s.get(s0 + i);
                        }
                    }
                }
            }
        }
    }
}

/// One image (one level of one face), border included.
#[derive(Clone, Debug, PartialEq)]
pub struct Image {
    /// Sizes including the border.
    pub width: i32,
    pub height: i32,
    pub depth: i32,
    pub border: i32,
    pub internal_format: u32,
    pub base: Base,
    /// Row-major, bottom row first, slices after each other; empty for a
    /// proxy image.
    pub texels: Texels,
}

impl Image {
    /// Sizes without the border (1D images have height 1, 2D depth 1).
    #[inline]
    pub fn inner(&self, dims: usize) -> [i32; 3] {
        let b2 = 2 * self.border;
        [self.width - b2, if dims >= 2 { self.height - b2 } else { 1 }, if dims >= 3 { self.depth - b2 } else { 1 }]
    }

    /// An image of inner size w x h x d with a border of width `border`
    /// around `inner` texels (the border repeats the edge texels), stored
    /// compactly when `compact`.
    #[allow(clippy::too_many_arguments)]
    pub fn with_border(w: i32, h: i32, d: i32, dims: usize, border: i32, internal_format: u32, base: Base, inner: &[[f32; 4]], compact: bool) -> Image {
        let b = border;
        let (fw, fh, fd) = (w + 2 * b, if dims >= 2 { h + 2 * b } else { 1 }, if dims >= 3 { d + 2 * b } else { 1 });
        let mut texels = Vec::with_capacity((fw * fh * fd) as usize);
        for z in 0..fd {
            for y in 0..fh {
                for x in 0..fw {
                    let i = (x - b).clamp(0, w - 1);
                    let j = if dims >= 2 { (y - b).clamp(0, h - 1) } else { 0 };
                    let k = if dims >= 3 { (z - b).clamp(0, d - 1) } else { 0 };
                    texels.push(inner[((k * h + j) * w + i) as usize]);
                }
            }
        }
        Image { width: fw, height: fh, depth: fd, border, internal_format, base, texels: Texels::from_float(texels, compact) }
    }

    /// Texel at inner coordinates (i, j, k), which may reach into the border.
    #[inline]
    pub fn texel_at(&self, dims: usize, i: i32, j: i32, k: i32) -> [f32; 4] {
        self.texel(dims, i, j, k)
    }

    /// Texel at inner coordinates (i, j, k); they may reach into the
    /// border (-1 or size) when there is one.
    #[inline]
    fn texel(&self, dims: usize, i: i32, j: i32, k: i32) -> [f32; 4] {
        let b = self.border;
        let (x, y, z) = (i + b, if dims >= 2 { j + b } else { 0 }, if dims >= 3 { k + b } else { 0 });
        self.texels.get(((z * self.height + y) * self.width + x) as usize)
    }
}

#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Wrap {
    Repeat,
    Clamp,
    ClampToEdge,
    ClampToBorder,
    MirroredRepeat,
}

#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Filter {
    Nearest,
    Linear,
    NearestMipmapNearest,
    LinearMipmapNearest,
    NearestMipmapLinear,
    LinearMipmapLinear,
}

impl Filter {
    pub fn is_mipmap(self) -> bool {
        !matches!(self, Filter::Nearest | Filter::Linear)
    }
}

/// A texture object's sampling parameters (table 6.16).
#[derive(Clone, Debug, PartialEq)]
pub struct Params {
    pub wrap: [Wrap; 3],
    pub min_filter: Filter,
    pub mag_filter: Filter,
    pub border_color: [f32; 4],
    pub min_lod: f32,
    pub max_lod: f32,
    pub base_level: i32,
    pub max_level: i32,
    pub lod_bias: f32,
    /// TEXTURE_COMPARE_MODE is COMPARE_R_TO_TEXTURE.
    pub compare_mode: bool,
    pub compare_func: CompareFunc,
    /// DEPTH_TEXTURE_MODE: Luminance, Intensity or Alpha.
    pub depth_mode: Base,
    /// EXT/ARB_texture_swizzle: where each of R, G, B, A comes from (see
    /// [`swizzle`]).
    pub swizzle: [u8; 4],
}

/// TEXTURE_SWIZZLE sources: a component of the filtered texel, or a
/// constant.
pub const SWIZZLE_ZERO: u8 = 4;
pub const SWIZZLE_ONE: u8 = 5;
/// Each component from itself.
pub const SWIZZLE_IDENTITY: [u8; 4] = [0, 1, 2, 3];

/// Applies TEXTURE_SWIZZLE_R/G/B/A to a filtered (and, for depth textures,
/// compared) texel (ARB_texture_swizzle: after filtering, before the
/// texture environment).
#[inline]
pub fn swizzle(t: [f32; 4], s: [u8; 4]) -> [f32; 4] {
    s.map(|k| match k {
        0..=3 => t[k as usize],
        SWIZZLE_ZERO => 0.0,
        _ => 1.0,
    })
}

impl Default for Params {
    fn default() -> Self {
        Params {
            wrap: [Wrap::Repeat; 3],
            min_filter: Filter::NearestMipmapLinear,
            mag_filter: Filter::Linear,
            border_color: [0.0; 4],
            min_lod: -1000.0,
            max_lod: 1000.0,
            base_level: 0,
            max_level: 1000,
            lod_bias: 0.0,
            compare_mode: false,
            compare_func: CompareFunc::Lequal,
            depth_mode: Base::Luminance,
            swizzle: SWIZZLE_IDENTITY,
        }
    }
}

/// A complete texture bound to an enabled unit, ready to sample.
#[derive(Clone, Debug)]
pub struct UnitSampler {
    pub target: Target,
    /// faces[f][l]: level base + l of face f (6 faces for cube maps).
    pub faces: Vec<Vec<Arc<Image>>>,
    pub params: Params,
    /// The unit's TEXTURE_LOD_BIAS (GL 1.4 texture filter control).
    pub unit_bias: f32,
    /// The base format of the base level (what the environment sees).
    pub base: Base,
    /// The specialized sampling function for this texture and its
    /// parameters ([`Fast::General`] when none applies).
    pub fast: Fast,
    /// For the general path's per-level filtering: Some(repeat) when a 2D
    /// or cube-map colour texture wraps S and T (a 1D one S) by REPEAT or
    /// CLAMP_TO_EDGE, so 8-bit levels without border take the specialized
    /// fetches (mipmapped filters then pay only for the LOD and the blend
    /// of two levels; cube maps only for the face selection).
    pub fast_wrap: Option<[bool; 2]>,
    /// The padded copy of a 2D texture's levels for the 8-wide kernel's
    /// bilinear fetch ([`pairs`]), built on first use.
    pub padded: pairs::PadCache,
}

/// Specialized samplers (see the module documentation). `repeat[k]`: the
/// wrap mode of coordinate k is REPEAT (else CLAMP_TO_EDGE).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Fast {
    General,
    Nearest2D { repeat: [bool; 2] },
    Linear2D { repeat: [bool; 2] },
}

impl Fast {
    /// The fast path for a texture (its levels from the base) and its
    /// parameters, if one applies.
    pub fn choose(target: Target, faces: &[Vec<Arc<Image>>], p: &Params) -> Fast {
        let Some(img) = faces.first().and_then(|l| l.first()) else { return Fast::General };
        // A 1D texture is a 2D one of height 1 sampled at t = 1/2 (T's wrap
        // mode plays no part).
        let n = match target {
            Target::T1D => 1,
            Target::T2D => 2,
            _ => return Fast::General,
        };
        let wraps_ok = p.wrap[..n].iter().all(|w| matches!(w, Wrap::Repeat | Wrap::ClampToEdge));
        if img.border != 0 || !img.texels.is_compact() || img.base == Base::Depth || !wraps_ok || p.min_filter != p.mag_filter || p.swizzle != SWIZZLE_IDENTITY {
            return Fast::General;
        }
        let repeat = [p.wrap[0] == Wrap::Repeat, n == 1 || p.wrap[1] == Wrap::Repeat];
        match p.min_filter {
            Filter::Nearest => Fast::Nearest2D { repeat },
            Filter::Linear => Fast::Linear2D { repeat },
            _ => Fast::General,
        }
    }
}

/// `SOFTGL_REFERENCE=1` (DESIGN.md): every sampler takes the general path.
fn reference_path() -> bool {
    static REFERENCE: std::sync::OnceLock<bool> = std::sync::OnceLock::new();
    *REFERENCE.get_or_init(|| std::env::var("SOFTGL_REFERENCE").is_ok_and(|v| v == "1"))
}

/// REPEAT or CLAMP_TO_EDGE of an index into [0, n).
#[inline(always)]
fn wrap_fast(i: i32, n: i32, repeat: bool) -> i32 {
    if !repeat {
        i.clamp(0, n - 1)
    } else if n & (n - 1) == 0 {
        i & (n - 1)
    } else {
        i.rem_euclid(n)
    }
}

/// The fragment stage's texturing configuration.
#[derive(Clone, Debug)]
pub struct TextureStage {
    pub units: [Option<UnitSampler>; MAX_UNITS],
    pub envs: [Env; MAX_UNITS],
    /// Indices of the units with a sampler, in order.
    pub active: Vec<usize>,
}

/// A fragment's coordinates for one unit: (s, t, r) after division by q,
/// and their screen-space derivatives.
#[derive(Clone, Copy, Debug, Default)]
pub struct Coord {
    pub str: [f32; 3],
    pub dx: [f32; 3],
    pub dy: [f32; 3],
}

impl TextureStage {
    /// Textures a fragment: samples every active unit, then runs the
    /// environments in unit order (3.8.13), starting from the primary
    /// colour `cf`.
    pub fn shade(&self, coords: &[Coord; MAX_UNITS], cf: Vec4) -> Vec4 {
        let mut tex = [Vec4::ZERO; MAX_UNITS];
        for &u in &self.active {
            if let Some(s) = &self.units[u] {
                tex[u] = s.sample(&coords[u]);
            }
        }
        let mut prev = cf;
        for &u in &self.active {
            if let Some(s) = &self.units[u] {
                prev = self.envs[u].apply(s.base_for_env(), prev, cf, tex[u], &tex, &self.units);
            }
        }
        prev
    }
}

#[inline]
fn lerp4(a: [f32; 4], b: [f32; 4], t: f32) -> [f32; 4] {
    [a[0] + (b[0] - a[0]) * t, a[1] + (b[1] - a[1]) * t, a[2] + (b[2] - a[2]) * t, a[3] + (b[3] - a[3]) * t]
}

/// Mirrors an index with period 2n.
#[inline]
fn mirror(i: i32, n: i32) -> i32 {
    let m = i.rem_euclid(2 * n);
    if m >= n {
        2 * n - 1 - m
    } else {
        m
    }
}

/// The texel-space coordinate u (s * n, or s itself for rectangle
/// textures) after the wrap mode's treatment: CLAMP clamps s to [0, 1],
/// that is u to [0, n] (the same f32 result: s * n is monotonic and exact
/// at 0 and 1).
#[inline]
fn wrap_coord(wrap: Wrap, u: f32, n: i32) -> f32 {
    let nf = n as f32;
    match wrap {
        Wrap::Clamp => u.clamp(0.0, nf),
        Wrap::ClampToBorder => u.clamp(-0.5, nf + 0.5),
        // The others are resolved on indices.
        _ => u,
    }
}

/// An index after wrapping; None: outside the image (border colour).
#[inline]
fn wrap_index(wrap: Wrap, i: i32, n: i32, border: i32) -> Option<i32> {
    match wrap {
        Wrap::Repeat => Some(i.rem_euclid(n)),
        Wrap::MirroredRepeat => Some(mirror(i, n)),
        Wrap::ClampToEdge => Some(i.clamp(0, n - 1)),
        Wrap::Clamp | Wrap::ClampToBorder => {
            if i < -border || i >= n + border {
                None
            } else {
                Some(i)
            }
        }
    }
}

impl UnitSampler {
    /// The base format the environment function sees: a depth texture
    /// reads as its DEPTH_TEXTURE_MODE.
    #[inline]
    fn base_for_env(&self) -> Base {
        if self.base == Base::Depth {
            self.params.depth_mode
        } else {
            self.base
        }
    }

    fn dims(&self) -> usize {
        self.target.dims()
    }

    /// A sampler for a complete texture; picks its fast path.
    pub fn new(target: Target, faces: Vec<Vec<Arc<Image>>>, params: Params, unit_bias: f32, base: Base) -> UnitSampler {
        if reference_path() {
            return UnitSampler { target, faces, params, unit_bias, base, fast: Fast::General, fast_wrap: None, padded: Default::default() };
        }
        let fast = Fast::choose(target, &faces, &params);
        let wraps_ok = |n: usize| params.wrap[..n].iter().all(|w| matches!(w, Wrap::Repeat | Wrap::ClampToEdge));
        let repeat = |k: usize| params.wrap[k] == Wrap::Repeat;
        // Cube map faces are 2D images (sampled after face selection); a 1D
        // image is a 2D one of height 1 sampled at t = 1/2 (see `filter`).
        let fast_wrap = match target {
            _ if base == Base::Depth => None,
            Target::T2D | Target::Cube if wraps_ok(2) => Some([repeat(0), repeat(1)]),
            Target::T1D if wraps_ok(1) => Some([repeat(0), true]),
            _ => None,
        };
        UnitSampler { target, faces, params, unit_bias, base, fast, fast_wrap, padded: Default::default() }
    }

    /// The padded copy of a 2D texture's levels ([`pairs`]) for its
    /// REPEAT / CLAMP_TO_EDGE wrap modes; None for other textures.
    pub fn padded(&self) -> Option<&pairs::Padded> {
        let repeat = self.fast_wrap?;
        if self.target != Target::T2D || self.faces.len() != 1 {
            return None;
        }
        self.padded.get(&self.faces[0], repeat)
    }

    /// Nearest sampling of a 2D 8-bit RGBA image without border.
    #[inline(always)]
    fn nearest_2d(img: &Image, tex: &[[u8; 4]], s: f32, t: f32, repeat: [bool; 2]) -> Vec4 {
        let (w, h) = (img.width, img.height);
        let i = wrap_fast((s * w as f32).floor() as i32, w, repeat[0]);
        let j = wrap_fast((t * h as f32).floor() as i32, h, repeat[1]);
        Vec4::from_array(unorm8(tex[(j * w + i) as usize]))
    }

    /// Bilinear sampling of a 2D 8-bit RGBA image without border (the
    /// general path's weights and order of operations).
    #[inline(always)]
    fn linear_2d(img: &Image, tex: &[[u8; 4]], s: f32, t: f32, repeat: [bool; 2]) -> Vec4 {
        let (w, h) = (img.width, img.height);
        let (a, b) = (s * w as f32 - 0.5, t * h as f32 - 0.5);
        let (fa, fb) = (a.floor(), b.floor());
        let (wa, wb) = (a - fa, b - fb);
        let (i0, j0) = (fa as i32, fb as i32);
        let (i0w, i1w) = (wrap_fast(i0, w, repeat[0]), wrap_fast(i0.wrapping_add(1), w, repeat[0]));
        let (j0w, j1w) = (wrap_fast(j0, h, repeat[1]), wrap_fast(j0.wrapping_add(1), h, repeat[1]));
        let at = |i: i32, j: i32| unorm8(tex[(j * w + i) as usize]);
        let r0 = lerp4(at(i0w, j0w), at(i1w, j0w), wa);
        let r1 = lerp4(at(i0w, j1w), at(i1w, j1w), wa);
        Vec4::from_array(lerp4(r0, r1, wb))
    }

    /// The t a 2D fetch takes: a 1D texture's single row at 1/2.
    #[inline(always)]
    fn fast_t(&self, c: &Coord) -> f32 {
        if self.target == Target::T1D {
            0.5
        } else {
            c.str[1]
        }
    }

    /// Samples at a fragment's coordinates (3.8.7 - 3.8.9, 3.8.14 for cube maps).
    pub fn sample(&self, c: &Coord) -> Vec4 {
        match self.fast {
            Fast::General => {}
            Fast::Nearest2D { repeat } => {
                let img = &self.faces[0][0];
                if let Texels::Rgba8(tex) = &img.texels {
                    return Self::nearest_2d(img, tex, c.str[0], self.fast_t(c), repeat);
                }
            }
            Fast::Linear2D { repeat } => {
                let img = &self.faces[0][0];
                if let Texels::Rgba8(tex) = &img.texels {
                    return Self::linear_2d(img, tex, c.str[0], self.fast_t(c), repeat);
                }
            }
        }
        self.sample_general(c)
    }

    /// The general sampler: every target, filter, wrap mode and format.
    pub fn sample_general(&self, c: &Coord) -> Vec4 {
        let (face, str, dx, dy) = if self.target == Target::Cube {
            cube_face(c)
        } else {
            (0, c.str, c.dx, c.dy)
        };
        let levels = &self.faces[face];
        let base = &levels[0];
        let dims = self.dims();
        // Rectangle textures' coordinates are already in texels.
        let n = if self.target == Target::Rect { [1; 3] } else { base.inner(dims) };
        let rho = {
            let lx = (0..dims).map(|k| (dx[k] * n[k] as f32).powi(2)).sum::<f32>().sqrt();
            let ly = (0..dims).map(|k| (dy[k] * n[k] as f32).powi(2)).sum::<f32>().sqrt();
            lx.max(ly)
        };
        let p = &self.params;
        let lambda = (lod::log2(rho) + (p.lod_bias + self.unit_bias).clamp(-MAX_LOD_BIAS, MAX_LOD_BIAS)).clamp(p.min_lod, p.max_lod);
        let c_switch = if p.mag_filter == Filter::Linear && matches!(p.min_filter, Filter::NearestMipmapNearest | Filter::LinearMipmapNearest) {
            0.5
        } else {
            0.0
        };
        let texel = if lambda > c_switch && !lambda.is_nan() {
            // Minification.
            let q = levels.len() - 1;
            match p.min_filter {
                Filter::Nearest => self.filter(&levels[0], str, false),
                Filter::Linear => self.filter(&levels[0], str, true),
                f @ (Filter::NearestMipmapNearest | Filter::LinearMipmapNearest) => {
                    let d = if lambda <= 0.5 { 0 } else { (((lambda + 0.5).ceil() - 1.0) as usize).min(q) };
                    self.filter(&levels[d], str, f == Filter::LinearMipmapNearest)
                }
                f => {
                    let lin = f == Filter::LinearMipmapLinear;
                    let d1 = lambda.floor();
                    if d1 as usize >= q || d1 >= q as f32 {
                        self.filter(&levels[q], str, lin)
                    } else {
                        let d1i = d1.max(0.0) as usize;
                        let t1 = self.filter(&levels[d1i], str, lin);
                        let t2 = self.filter(&levels[d1i + 1], str, lin);
                        lerp4(t1, t2, lambda - lambda.floor())
                    }
                }
            }
        } else {
            self.filter(&levels[0], str, p.mag_filter == Filter::Linear)
        };
        if p.swizzle != SWIZZLE_IDENTITY {
            return Vec4::from_array(swizzle(texel, p.swizzle));
        }
        Vec4::from_array(texel)
    }

    /// Nearest or linear filtering within one image, with depth comparison
    /// per texel (before filtering).
    fn filter(&self, img: &Image, str: [f32; 3], linear: bool) -> [f32; 4] {
        if let (Some(repeat), Texels::Rgba8(tex), 0) = (self.fast_wrap, &img.texels, img.border) {
            // A 1D image's single row at t = 1/2: the bilinear fetch then
            // weighs the row by exactly 1 (whatever t is, the general path
            // ignores it).
            let t = if self.target == Target::T1D { 0.5 } else { str[1] };
            let v = if linear { Self::linear_2d(img, tex, str[0], t, repeat) } else { Self::nearest_2d(img, tex, str[0], t, repeat) };
            return v.to_array();
        }
        let dims = self.dims();
        let n = img.inner(dims);
        let p = &self.params;
        let b = img.border;
        let fetch = |i: i32, j: i32, k: i32| -> [f32; 4] {
            let ii = wrap_index(p.wrap[0], i, n[0], b);
            let jj = if dims >= 2 { wrap_index(p.wrap[1], j, n[1], b) } else { Some(0) };
            let kk = if dims >= 3 { wrap_index(p.wrap[2], k, n[2], b) } else { Some(0) };
            let t = match (ii, jj, kk) {
                (Some(i), Some(j), Some(k)) => img.texel(dims, i, j, k),
                _ => self.border_texel(),
            };
            self.compare(t, str[2])
        };
        let unnormalized = self.target == Target::Rect;
        let u = [0, 1, 2].map(|k| if k < dims { wrap_coord(p.wrap[k], if unnormalized { str[k] } else { str[k] * n[k] as f32 }, n[k]) } else { 0.0 });
        if !linear {
            let i = u.map(|x| x.floor() as i32);
            // CLAMP at s = 1 reads the last texel, not the border.
            let fix = |k: usize, i: i32| if p.wrap[k] == Wrap::Clamp && i >= n[k] { n[k] - 1 } else { i };
            return fetch(fix(0, i[0]), fix(1, i[1]), fix(2, i[2]));
        }
        let a = u.map(|x| x - 0.5);
        let i0 = a.map(|x| x.floor() as i32);
        let w = [a[0] - a[0].floor(), a[1] - a[1].floor(), a[2] - a[2].floor()];
        match dims {
            1 => lerp4(fetch(i0[0], 0, 0), fetch(i0[0] + 1, 0, 0), w[0]),
            2 => {
                let r0 = lerp4(fetch(i0[0], i0[1], 0), fetch(i0[0] + 1, i0[1], 0), w[0]);
                let r1 = lerp4(fetch(i0[0], i0[1] + 1, 0), fetch(i0[0] + 1, i0[1] + 1, 0), w[0]);
                lerp4(r0, r1, w[1])
            }
            _ => {
                let slice = |k: i32| {
                    let r0 = lerp4(fetch(i0[0], i0[1], k), fetch(i0[0] + 1, i0[1], k), w[0]);
                    let r1 = lerp4(fetch(i0[0], i0[1] + 1, k), fetch(i0[0] + 1, i0[1] + 1, k), w[0]);
                    lerp4(r0, r1, w[1])
                };
                lerp4(slice(i0[2]), slice(i0[2] + 1), w[2])
            }
        }
    }

    /// The border colour as a texel of this texture's format.
    fn border_texel(&self) -> [f32; 4] {
        self.base.expand(self.params.border_color)
    }

    /// Depth textures (3.8.14 of GL 1.4): the comparison of r against the
    /// texel, then DEPTH_TEXTURE_MODE.
    #[inline]
    fn compare(&self, t: [f32; 4], r: f32) -> [f32; 4] {
        if self.base != Base::Depth {
            return t;
        }
        let d = t[0];
        // Comparisons use r clamped to [0, 1], as the texel is.
        let v = if !self.params.compare_mode {
            d
        } else if self.params.compare_func.test(r.clamp(0.0, 1.0), d) {
            1.0
        } else {
            0.0
        };
        match self.params.depth_mode {
            Base::Intensity => [v, v, v, v],
            Base::Alpha => [0.0, 0.0, 0.0, v],
            _ => [v, v, v, 1.0],
        }
    }
}

/// GL_MAX_TEXTURE_LOD_BIAS.
pub const MAX_LOD_BIAS: f32 = 16.0;

/// Cube map face selection (table 3.19): the face, (s, t) on it, and the
/// derivatives of (s, t) approximated by those of the direction over the
/// major axis.
fn cube_face(c: &Coord) -> (usize, [f32; 3], [f32; 3], [f32; 3]) {
    let [rx, ry, rz] = c.str;
    let (ax, ay, az) = (rx.abs(), ry.abs(), rz.abs());
    // (face, sc, tc, ma) as functions of a direction.
    let pick = |v: [f32; 3], face: usize| -> (f32, f32, f32) {
        let [x, y, z] = v;
        match face {
            0 => (-z, -y, x),
            1 => (z, -y, -x),
            2 => (x, z, y),
            3 => (x, -z, -y),
            4 => (x, -y, z),
            _ => (-x, -y, -z),
        }
    };
    let face = if ax >= ay && ax >= az {
        if rx >= 0.0 { 0 } else { 1 }
    } else if ay >= az {
        if ry >= 0.0 { 2 } else { 3 }
    } else if rz >= 0.0 {
        4
    } else {
        5
    };
    let (sc, tc, ma) = pick(c.str, face);
    let ma = ma.abs().max(1e-30);
    let st = [(sc / ma + 1.0) / 2.0, (tc / ma + 1.0) / 2.0, 0.0];
    let d = |dv: [f32; 3]| {
        let (ds, dt, _) = pick(dv, face);
        [ds / (2.0 * ma), dt / (2.0 * ma), 0.0]
    };
    (face, st, d(c.dx), d(c.dy))
}

#[cfg(test)]
mod tests {
    use super::*;

    fn img(w: i32, h: i32, f: impl Fn(i32, i32) -> [f32; 4]) -> Arc<Image> {
        let mut texels = Vec::new();
        for j in 0..h {
            for i in 0..w {
                texels.push(f(i, j));
            }
        }
        Arc::new(Image { width: w, height: h, depth: 1, border: 0, internal_format: 0x1908, base: Base::Rgba, texels: Texels::Float(texels) })
    }

    fn sampler(levels: Vec<Arc<Image>>, params: Params) -> UnitSampler {
        UnitSampler::new(Target::T2D, vec![levels], params, 0.0, Base::Rgba)
    }

    /// The fast nearest and bilinear paths give exactly what the general
    /// path gives, for 8-bit textures of power-of-two and other sizes,
    /// REPEAT and CLAMP_TO_EDGE, at coordinates in and far outside [0, 1].
    #[test]
    fn fast_paths_match_the_general_path() {
        let mut seed = 12345u32;
        let mut rnd = move || {
            seed = seed.wrapping_mul(1664525).wrapping_add(1013904223);
            seed
        };
        for (w, h) in [(4, 4), (8, 2), (5, 3), (1, 7)] {
            let texels: Vec<[u8; 4]> = (0..w * h).map(|_| rnd().to_ne_bytes()).collect();
            let image = Arc::new(Image { width: w, height: h, depth: 1, border: 0, internal_format: 0x8058, base: Base::Rgba, texels: Texels::Rgba8(Arc::new(texels)) });
            for filter in [Filter::Nearest, Filter::Linear] {
                for wrap in [[Wrap::Repeat, Wrap::Repeat], [Wrap::ClampToEdge, Wrap::Repeat], [Wrap::Repeat, Wrap::ClampToEdge]] {
                    let params = Params { min_filter: filter, mag_filter: filter, wrap: [wrap[0], wrap[1], Wrap::Repeat], ..Default::default() };
                    let s = sampler(vec![image.clone()], params);
                    assert_ne!(s.fast, Fast::General, "{filter:?} {wrap:?}");
                    let reference = UnitSampler { fast: Fast::General, fast_wrap: None, ..s.clone() };
                    for _ in 0..2000 {
                        let u = (rnd() % 20000) as f32 / 1000.0 - 10.0;
                        let v = (rnd() % 20000) as f32 / 1000.0 - 10.0;
                        let c = Coord { str: [u, v, 0.0], dx: [0.01, 0.0, 0.0], dy: [0.0, 0.3, 0.0] };
                        assert_eq!(s.sample(&c), reference.sample(&c), "{w}x{h} {filter:?} {wrap:?} at {u} {v}");
                    }
                }
            }
        }
    }

    /// Mipmapped filters on 8-bit levels (the per-level fast fetches)
    /// against the reference path, across magnification and minification.
    #[test]
    fn mipmapped_fast_fetches_match_the_reference() {
        let mut seed = 99u32;
        let mut level = |n: i32| {
            let texels: Vec<[u8; 4]> = (0..n * n)
                .map(|_| {
                    seed = seed.wrapping_mul(1664525).wrapping_add(1013904223);
                    seed.to_ne_bytes()
                })
                .collect();
            Arc::new(Image { width: n, height: n, depth: 1, border: 0, internal_format: 0x8058, base: Base::Rgba, texels: Texels::Rgba8(Arc::new(texels)) })
        };
        let levels = vec![level(8), level(4), level(2), level(1)];
        for filter in [Filter::NearestMipmapNearest, Filter::LinearMipmapNearest, Filter::NearestMipmapLinear, Filter::LinearMipmapLinear] {
            let params = Params { min_filter: filter, mag_filter: Filter::Linear, ..Default::default() };
            let s = sampler(levels.clone(), params);
            assert_eq!(s.fast, Fast::General);
            assert!(s.fast_wrap.is_some());
            let reference = UnitSampler { fast_wrap: None, ..s.clone() };
            for k in 0..3000 {
                let (u, v) = ((k % 97) as f32 / 31.0 - 1.0, (k % 89) as f32 / 29.0 - 1.0);
                let d = 0.01 * (k % 50) as f32;
                let c = Coord { str: [u, v, 0.0], dx: [d, 0.0, 0.0], dy: [0.0, d * 0.7, 0.0] };
                assert_eq!(s.sample(&c), reference.sample(&c), "{filter:?} at {u} {v} d {d}");
            }
        }
    }

    /// 1D textures and cube maps take the per-level fetches; they give
    /// exactly the reference path's texels, for every filter, at
    /// coordinates (and cube directions) all around.
    #[test]
    fn one_d_and_cube_fetches_match_the_reference() {
        let mut seed = 4242u32;
        let mut rnd = move || {
            seed = seed.wrapping_mul(1664525).wrapping_add(1013904223);
            seed
        };
        let level = |w: i32, h: i32, rnd: &mut dyn FnMut() -> u32| {
            let texels: Vec<[u8; 4]> = (0..w * h).map(|_| rnd().to_ne_bytes()).collect();
            Arc::new(Image { width: w, height: h, depth: 1, border: 0, internal_format: 0x8058, base: Base::Rgba, texels: Texels::Rgba8(Arc::new(texels)) })
        };
        let one_d = vec![level(8, 1, &mut rnd), level(4, 1, &mut rnd), level(2, 1, &mut rnd), level(1, 1, &mut rnd)];
        let cube: Vec<Vec<Arc<Image>>> = (0..6).map(|_| vec![level(4, 4, &mut rnd), level(2, 2, &mut rnd), level(1, 1, &mut rnd)]).collect();
        let filters = [Filter::Nearest, Filter::Linear, Filter::NearestMipmapNearest, Filter::LinearMipmapNearest, Filter::NearestMipmapLinear, Filter::LinearMipmapLinear];
        for (target, faces) in [(Target::T1D, vec![one_d]), (Target::Cube, cube)] {
            for min_filter in filters {
                for wrap in [Wrap::Repeat, Wrap::ClampToEdge] {
                    // NEAREST/NEAREST and LINEAR/LINEAR 1D textures take the
                    // whole-sampler fetches, the rest the per-level ones.
                    let mag_filter = if min_filter == Filter::Nearest { Filter::Nearest } else { Filter::Linear };
                    let params = Params { min_filter, mag_filter, wrap: [wrap; 3], ..Default::default() };
                    let s = UnitSampler::new(target, faces.clone(), params, 0.0, Base::Rgba);
                    assert!(s.fast_wrap.is_some(), "{target:?}");
                    assert_eq!(s.fast != Fast::General, target == Target::T1D && !min_filter.is_mipmap(), "{target:?} {min_filter:?}");
                    let reference = UnitSampler { fast: Fast::General, fast_wrap: None, ..s.clone() };
                    for _ in 0..3000 {
                        let mut v = || (rnd() % 40000) as f32 / 10000.0 - 2.0;
                        let str = [v(), v(), v()];
                        let d = (rnd() % 100) as f32 / 200.0;
                        let c = Coord { str, dx: [d, 0.0, d * 0.5], dy: [0.0, d * 0.3, 0.0] };
                        assert_eq!(s.sample(&c), reference.sample(&c), "{target:?} {min_filter:?} {wrap:?} at {str:?} d {d}");
                    }
                }
            }
        }
    }

    #[test]
    fn fast_path_needs_its_conditions() {
        let image = img(4, 4, |_, _| [0.5; 4]);
        let p = Params { min_filter: Filter::Nearest, mag_filter: Filter::Nearest, ..Default::default() };
        // f32 storage, mipmapped filters, different filters, CLAMP: general.
        assert_eq!(sampler(vec![image.clone()], p.clone()).fast, Fast::General);
        let compact = Arc::new(Image { texels: Texels::Rgba8(Arc::new(vec![[1, 2, 3, 4]; 16])), ..(*image).clone() });
        assert_eq!(sampler(vec![compact.clone()], p.clone()).fast, Fast::Nearest2D { repeat: [true, true] });
        let mixed = Params { mag_filter: Filter::Linear, ..p.clone() };
        assert_eq!(sampler(vec![compact.clone()], mixed).fast, Fast::General);
        let clamp = Params { wrap: [Wrap::Clamp; 3], ..p.clone() };
        assert_eq!(sampler(vec![compact.clone()], clamp).fast, Fast::General);
        let mip = Params { min_filter: Filter::NearestMipmapNearest, ..p };
        assert_eq!(sampler(vec![compact], mip).fast, Fast::General);
    }

    #[test]
    fn wrap_indices() {
        assert_eq!(mirror(-1, 4), 0);
        assert_eq!(mirror(4, 4), 3);
        assert_eq!(mirror(8, 4), 0);
        assert_eq!(wrap_index(Wrap::Repeat, -1, 4, 0), Some(3));
        assert_eq!(wrap_index(Wrap::ClampToEdge, 7, 4, 0), Some(3));
        assert_eq!(wrap_index(Wrap::Clamp, 4, 4, 0), None);
        assert_eq!(wrap_index(Wrap::Clamp, 4, 4, 1), Some(4));
    }

    #[test]
    fn bilinear_weights() {
        let s = sampler(
            vec![img(2, 2, |i, j| [(i + 2 * j) as f32, 0.0, 0.0, 1.0])],
            Params { min_filter: Filter::Linear, mag_filter: Filter::Linear, wrap: [Wrap::ClampToEdge; 3], ..Default::default() },
        );
        // Halfway between the four texel centres.
        let c = Coord { str: [0.5, 0.5, 0.0], ..Default::default() };
        assert!((s.sample(&c).x - 1.5).abs() < 1e-6);
        // At texel (0, 0)'s centre plus a quarter texel in s.
        let c = Coord { str: [0.375, 0.25, 0.0], ..Default::default() };
        assert!((s.sample(&c).x - 0.25).abs() < 1e-6);
    }
}

/// Texture coordinates of a line fragment at parameter `t` of the segment
/// from a to b (window vertices with q = 1/w), perspective-correct as
/// the colours (equation 3.7); the derivative is taken over `step`, the
/// parameter change of one pixel along the major axis.
pub fn line_coords(stage: &TextureStage, ta: &[Vec4; MAX_UNITS], qa: f64, tb: &[Vec4; MAX_UNITS], qb: f64, t: f64, step: f64) -> [Coord; MAX_UNITS] {
    let mut out = [Coord::default(); MAX_UNITS];
    let at = |u: usize, t: f64| -> Option<[f64; 3]> {
        let (ka, kb) = ((1.0 - t) * qa, t * qb);
        let v = (ta[u].as_dvec4() * ka + tb[u].as_dvec4() * kb) / (ka + kb);
        (v.w != 0.0 && v.is_finite()).then(|| [v.x / v.w, v.y / v.w, v.z / v.w])
    };
    for &u in &stage.active {
        let (Some(p), Some(p2)) = (at(u, t), at(u, t + step)) else { continue };
        out[u] = Coord { str: p.map(|x| x as f32), dx: [0, 1, 2].map(|k| (p2[k] - p[k]) as f32), dy: [0.0; 3] };
    }
    out
}

/// Texture coordinates of a point's fragments: the vertex's, divided by q;
/// no derivatives (points magnify).
pub fn point_coords(stage: &TextureStage, tex: &[Vec4; MAX_UNITS]) -> [Coord; MAX_UNITS] {
    let mut out = [Coord::default(); MAX_UNITS];
    for &u in &stage.active {
        let v = tex[u];
        if v.w != 0.0 {
            out[u].str = [v.x / v.w, v.y / v.w, v.z / v.w];
        }
    }
    out
}
