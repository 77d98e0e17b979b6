//! Texturing state and commands (GL 1.5 sections 3.8 and 2.10.4 / 2.11.4):
//! texture objects (glGenTextures, glBindTexture, glDeleteTextures,
//! glIsTexture, priorities), the 1D, 2D, 3D, cube-map and rectangle
//! (ARB_texture_rectangle: one level, no border, no REPEAT wraps or
//! mipmap filters) images and their
//! specification (glTexImage*, glTexSubImage*, glCopyTexImage*,
//! glCopyTexSubImage*, proxies, GENERATE_MIPMAP), parameters, the
//! per-unit environment and texture coordinate generation, and their
//! queries. Texture completeness (3.8.10) is decided at validation, which
//! builds the fragment stage's `render::texture::TextureStage`.
//!
//! Invariants: texel arrays are shared (Arc) with the derived stage; every
//! command that changes an image first drops the derived stage, so the
//! change happens in place and the next draw re-derives. Object names live
//! in `objects` once bound (IsTexture is true only then); names returned
//! by glGenTextures and not bound yet are kept in `reserved`.

pub mod enums;
pub mod image;
pub mod sampler;
pub mod texgen;

use self::enums::*;
use self::image::{internal_format, InternalFormat};
use super::context::Context;
use super::enums::{GL_INVALID_ENUM, GL_INVALID_OPERATION, GL_INVALID_VALUE, GL_OUT_OF_MEMORY};
use super::pixel_data;
use super::get::Value;
use crate::render::texture::{Base, Env, Filter, Image, Params, Target, Texels, TextureStage, UnitSampler, Wrap, MAX_LOD_BIAS, MAX_UNITS};
use crate::gl::names::Reserved;
use std::collections::HashMap;
use std::sync::Arc;

/// Pixel transfer that changes nothing (for groups already transferred).
static IDENTITY_TRANSFER: std::sync::LazyLock<super::pixel_transfer::PixelTransfer> = std::sync::LazyLock::new(Default::default);

/// Dirty bit: texture state the fragment stage derives from.
pub const DIRTY_TEXTURE: u32 = super::validate::DIRTY_TEXTURE;

/// 4096 as on the hardware of GL 1.5's time (piglit's
/// tex-upside-down-miptree asks for it); an image still may not exceed
/// MAX_IMAGE_BYTES, so a 4096x4096 RGBA32F level (256 MB) is the worst.
pub const MAX_TEXTURE_SIZE: i32 = 4096;
pub const MAX_3D_TEXTURE_SIZE: i32 = 256;
pub const MAX_CUBE_MAP_TEXTURE_SIZE: i32 = 4096;
pub const MAX_RECTANGLE_TEXTURE_SIZE: i32 = 4096;
/// Levels per face: log2(MAX_TEXTURE_SIZE) + 1.
pub const MAX_LEVELS: usize = 13;
/// The largest image softgl allocates (bytes of stored texels): larger
/// requests are GL_OUT_OF_MEMORY at once (proxies: not supported).
const MAX_IMAGE_BYTES: usize = 1 << 30;

/// Every object target, in `Target` order (`target_index`).
const TARGETS: [Target; 5] = [Target::T1D, Target::T2D, Target::T3D, Target::Cube, Target::Rect];

fn target_index(t: Target) -> usize {
    t as usize
}

/// A texture-object target (glBindTexture, glTexParameter, glEnable).
fn object_target(e: u32) -> Option<Target> {
    Some(match e {
        GL_TEXTURE_1D => Target::T1D,
        GL_TEXTURE_2D => Target::T2D,
        GL_TEXTURE_3D => Target::T3D,
        GL_TEXTURE_CUBE_MAP => Target::Cube,
        GL_TEXTURE_RECTANGLE => Target::Rect,
        _ => return None,
    })
}

/// An image target: (object target, face, proxy).
fn image_target(e: u32, dims: u8) -> Option<(Target, usize, bool)> {
    Some(match (e, dims) {
        (GL_TEXTURE_1D, 1) => (Target::T1D, 0, false),
        (GL_PROXY_TEXTURE_1D, 1) => (Target::T1D, 0, true),
        (GL_TEXTURE_2D, 2) => (Target::T2D, 0, false),
        (GL_PROXY_TEXTURE_2D, 2) => (Target::T2D, 0, true),
        (GL_PROXY_TEXTURE_CUBE_MAP, 2) => (Target::Cube, 0, true),
        (GL_TEXTURE_CUBE_MAP_POSITIVE_X..=GL_TEXTURE_CUBE_MAP_NEGATIVE_Z, 2) => (Target::Cube, (e - GL_TEXTURE_CUBE_MAP_POSITIVE_X) as usize, false),
        (GL_TEXTURE_3D, 3) => (Target::T3D, 0, false),
        (GL_PROXY_TEXTURE_3D, 3) => (Target::T3D, 0, true),
        (GL_TEXTURE_RECTANGLE, 2) => (Target::Rect, 0, false),
        (GL_PROXY_TEXTURE_RECTANGLE, 2) => (Target::Rect, 0, true),
        _ => return None,
    })
}

fn dims_of(t: Target) -> u8 {
    t.dims() as u8
}

fn max_size(t: Target) -> i32 {
    match t {
        Target::T3D => MAX_3D_TEXTURE_SIZE,
        Target::Cube => MAX_CUBE_MAP_TEXTURE_SIZE,
        Target::Rect => MAX_RECTANGLE_TEXTURE_SIZE,
        _ => MAX_TEXTURE_SIZE,
    }
}

/// The last level an image of target `t` may have (rectangle textures
/// have only level 0).
fn max_level_of(t: Target) -> i32 {
    if t == Target::Rect {
        0
    } else {
        log2_floor(max_size(t))
    }
}

fn log2_floor(n: i32) -> i32 {
    31 - (n.max(1) as u32).leading_zeros() as i32
}

/// A texture object (section 3.8.11).
#[derive(Clone, Debug)]
pub struct TexObject {
    /// The target it was first bound to (None: never bound).
    pub target: Option<Target>,
    /// images[face * MAX_LEVELS + level].
    pub images: Vec<Option<Arc<Image>>>,
    pub params: Params,
    pub generate_mipmap: bool,
    pub priority: f32,
    /// Made by glTexStorage (ARB_texture_storage): its images may be
    /// replaced in content only.
    pub immutable: bool,
    /// glTexStorage's level count: completeness clamps MAX_LEVEL to it.
    pub immutable_levels: i32,
}

impl TexObject {
    fn new(target: Option<Target>) -> TexObject {
        let mut params = Params::default();
        if target == Some(Target::Rect) {
            // ARB_texture_rectangle's initial state: no REPEAT, no mipmaps.
            params.wrap = [Wrap::ClampToEdge; 3];
            params.min_filter = Filter::Linear;
        }
        TexObject { target, images: vec![None; 6 * MAX_LEVELS], params, generate_mipmap: false, priority: 1.0, immutable: false, immutable_levels: 0 }
    }

    fn image(&self, face: usize, level: usize) -> Option<&Arc<Image>> {
        self.images.get(face * MAX_LEVELS + level).and_then(|i| i.as_ref())
    }

    /// Section 3.8.10: the levels base..=q of each face when the texture is
    /// complete for its target (cube completeness for cube maps).
    pub fn complete(&self, target: Target) -> Option<Vec<Vec<Arc<Image>>>> {
        self.complete_with(target, &self.params)
    }

    /// Completeness under parameters `p` (a sampler object's, in place of
    /// the texture's own).
    pub fn complete_with(&self, target: Target, p: &Params) -> Option<Vec<Vec<Arc<Image>>>> {
        // Immutable storage: the levels that exist bound MAX_LEVEL.
        let clamped;
        let p = if self.immutable_levels > 0 {
            clamped = Params { max_level: p.max_level.min(self.immutable_levels - 1), ..p.clone() };
            &clamped
        } else {
            p
        };
        if p.base_level < 0 || p.base_level as usize >= MAX_LEVELS || p.base_level > p.max_level {
            return None;
        }
        let base = p.base_level as usize;
        let dims = dims_of(target) as usize;
        let faces = if target == Target::Cube { 6 } else { 1 };
        let first = self.image(0, base)?;
        let n0 = first.inner(dims);
        if n0.iter().any(|&n| n <= 0) {
            return None;
        }
        if target == Target::Cube && n0[0] != n0[1] {
            return None;
        }
        let mut out = Vec::with_capacity(faces);
        for f in 0..faces {
            let b = self.image(f, base)?;
            if b.inner(dims) != n0 || b.internal_format != first.internal_format || b.border != first.border {
                return None;
            }
            let mut levels = vec![b.clone()];
            if p.min_filter.is_mipmap() {
                let pmax = log2_floor(*n0[..dims].iter().max().unwrap_or(&1)) + p.base_level;
                let q = pmax.min(p.max_level).min(MAX_LEVELS as i32 - 1);
                let mut size = n0;
                for l in base + 1..=q as usize {
                    size = size.map(|s| (s / 2).max(1));
                    for s in size.iter_mut().skip(dims) {
                        *s = 1;
                    }
                    let img = self.image(f, l)?;
                    if img.inner(dims) != size || img.internal_format != first.internal_format || img.border != first.border {
                        return None;
                    }
                    levels.push(img.clone());
                }
            }
            out.push(levels);
        }
        Some(out)
    }
}

/// Texture coordinate generation for one coordinate (2.11.4).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct TexGenCoord {
    pub enabled: bool,
    pub mode: u32,
    pub object_plane: [f64; 4],
    /// Stored in eye coordinates (transformed at specification).
    pub eye_plane: [f64; 4],
}

/// One texture unit's state (server side).
#[derive(Clone, Debug)]
pub struct TexUnit {
    /// TEXTURE_1D, 2D, 3D, CUBE_MAP, RECTANGLE enables (`Target` order).
    pub enabled: [bool; 5],
    /// Bound object names per target (0: the default object).
    pub bound: [u32; 5],
    pub env: Env,
    /// TEXTURE_FILTER_CONTROL's TEXTURE_LOD_BIAS.
    pub lod_bias: f32,
    pub gen: [TexGenCoord; 4],
}

impl Default for TexUnit {
    fn default() -> Self {
        let plane = |i: usize| {
            let mut p = [0.0; 4];
            if i < 2 {
                p[i] = 1.0;
            }
            p
        };
        TexUnit {
            enabled: [false; 5],
            bound: [0; 5],
            env: Env::default(),
            lod_bias: 0.0,
            gen: [0, 1, 2, 3].map(|i| TexGenCoord { enabled: false, mode: GL_EYE_LINEAR, object_plane: plane(i), eye_plane: plane(i) }),
        }
    }
}

/// All texturing state of a context.
#[derive(Clone, Debug)]
pub struct TextureState {
    /// ACTIVE_TEXTURE - TEXTURE0.
    pub active: usize,
    /// CLIENT_ACTIVE_TEXTURE - TEXTURE0.
    pub client_active: usize,
    pub units: [TexUnit; MAX_UNITS],
    pub objects: HashMap<u32, TexObject>,
    pub reserved: Reserved,
    /// The default objects (name 0) per target.
    pub defaults: [TexObject; 5],
    /// The proxy "objects" per target: only their level state matters.
    pub proxies: [TexObject; 5],
    /// Derived: what the vertex stage does per unit.
    pub vertex: texgen::VertexTexSetup,
}

impl Default for TextureState {
    fn default() -> Self {
        TextureState {
            active: 0,
            client_active: 0,
            units: Default::default(),
            objects: HashMap::new(),
            reserved: Reserved::default(),
            defaults: TARGETS.map(|t| TexObject::new(Some(t))),
            proxies: TARGETS.map(|t| TexObject::new(Some(t))),
            vertex: Default::default(),
        }
    }
}

impl TextureState {
    fn object(&self, unit: usize, t: Target) -> &TexObject {
        let name = self.units[unit].bound[target_index(t)];
        if name == 0 {
            &self.defaults[target_index(t)]
        } else {
            self.objects.get(&name).unwrap_or(&self.defaults[target_index(t)])
        }
    }

    fn object_mut(&mut self, unit: usize, t: Target) -> &mut TexObject {
        let name = self.units[unit].bound[target_index(t)];
        if name != 0 && self.objects.contains_key(&name) {
            self.objects.get_mut(&name).expect("checked")
        } else {
            &mut self.defaults[target_index(t)]
        }
    }

    /// The target a unit textures with: the highest-priority enabled one
    /// (cube map, 3D, rectangle, 2D, 1D), if any.
    pub fn unit_target(&self, u: usize) -> Option<Target> {
        let e = &self.units[u].enabled;
        [Target::Cube, Target::T3D, Target::Rect, Target::T2D, Target::T1D].into_iter().find(|t| e[target_index(*t)])
    }
}

/// glTexImage's arguments, with the client pixels already unpacked (so a
/// display list holds the image, section 5.4).
#[derive(Clone, Debug, PartialEq)]
pub struct TexImageCmd {
    pub dims: u8,
    pub target: u32,
    pub level: i32,
    pub internal_format: i32,
    pub size: [i32; 3],
    pub border: i32,
    pub format: u32,
    pub ty: u32,
    pub pixels: Option<Arc<image::Pixels>>,
}

/// glTexSubImage's arguments.
#[derive(Clone, Debug, PartialEq)]
pub struct TexSubImageCmd {
    pub dims: u8,
    pub target: u32,
    pub level: i32,
    pub offset: [i32; 3],
    pub size: [i32; 3],
    pub format: u32,
    pub ty: u32,
    pub pixels: Option<Arc<image::Pixels>>,
}

/// glCopyTexImage / glCopyTexSubImage arguments: target, level, internal
/// format (0 for the Sub form), offsets, window x, y, width, height, border.
#[derive(Clone, Debug, PartialEq)]
pub struct CopyTexCmd {
    pub dims: u8,
    pub sub: bool,
    pub target: u32,
    pub level: i32,
    pub internal_format: u32,
    pub offset: [i32; 3],
    pub rect: [i32; 4],
    pub border: i32,
}

/// A width, height or depth the GL accepts at all (INVALID_VALUE
/// otherwise): at least twice the border. Any size is allowed, not only
/// powers of two (ARB_texture_non_power_of_two).
fn valid_size(n: i32, border: i32) -> bool {
    n >= 0 && n - 2 * border >= 0
}

/// Does an inner size fit level `level` of a target whose largest image is
/// `max` (2^(k - level), section 3.8.1)?
fn fits_level(n: i32, border: i32, max: i32, level: i32) -> bool {
    n - 2 * border <= max >> level.clamp(0, 31)
}

/// The size limit of level `level` of an image target enum (for unpacking
/// client images only when they can be valid).
fn level_limit(target: u32, dims: u8, level: i32) -> i32 {
    match image_target(target, dims) {
        Some((t, _, _)) => (max_size(t) >> level.clamp(0, 31)) + 2,
        None => 0,
    }
}

impl Context {
    fn drop_derived_textures(&mut self) {
        self.derived.render.texture = None;
        self.dirty |= DIRTY_TEXTURE;
    }

    /// glActiveTexture.
    pub fn active_texture(&mut self, e: u32) {
        if !(GL_TEXTURE0..GL_TEXTURE0 + MAX_UNITS as u32).contains(&e) {
            return self.set_error(GL_INVALID_ENUM);
        }
        self.texture.active = (e - GL_TEXTURE0) as usize;
        self.transform.active_texture = self.texture.active;
    }

    /// glClientActiveTexture.
    pub fn client_active_texture(&mut self, e: u32) {
        if !(GL_TEXTURE0..GL_TEXTURE0 + MAX_UNITS as u32).contains(&e) {
            return self.set_error(GL_INVALID_ENUM);
        }
        self.texture.client_active = (e - GL_TEXTURE0) as usize;
    }

    /// glTexCoord / glMultiTexCoord (unit as an enum for MultiTexCoord).
    pub fn tex_coord(&mut self, unit: u32, v: [f32; 4]) {
        let u = unit.wrapping_sub(GL_TEXTURE0) as usize;
        if u >= MAX_UNITS {
            return self.set_error(GL_INVALID_ENUM);
        }
        self.current.tex_coords[u] = v;
    }

    /// glGenTextures.
    pub fn gen_textures(&mut self, n: i32) -> Option<Vec<u32>> {
        if n < 0 {
            self.set_error(GL_INVALID_VALUE);
            return None;
        }
        let objects = &self.texture.objects;
        Some(self.texture.reserved.generate(n as usize, |k| objects.contains_key(&k)))
    }

    /// glDeleteTextures: bound objects revert to the default ones.
    pub fn delete_textures(&mut self, names: &[u32]) {
        for &name in names {
            if name == 0 {
                continue;
            }
            self.texture.reserved.remove(name);
            if self.texture.objects.remove(&name).is_some() {
                for u in self.texture.units.iter_mut() {
                    for b in u.bound.iter_mut() {
                        if *b == name {
                            *b = 0;
                        }
                    }
                }
                self.drop_derived_textures();
            }
        }
    }

    pub fn is_texture(&self, name: u32) -> bool {
        name != 0 && self.texture.objects.contains_key(&name)
    }

    /// glBindTexture.
    pub fn bind_texture(&mut self, target: u32, name: u32) {
        let Some(t) = object_target(target) else { return self.set_error(GL_INVALID_ENUM) };
        if name != 0 {
            match self.texture.objects.get(&name) {
                Some(o) if o.target != Some(t) => return self.set_error(GL_INVALID_OPERATION),
                Some(_) => {}
                None => {
                    self.texture.reserved.remove(name);
                    self.texture.objects.insert(name, TexObject::new(Some(t)));
                }
            }
        }
        let u = self.texture.active;
        self.texture.units[u].bound[target_index(t)] = name;
        self.drop_derived_textures();
    }

    /// glPrioritizeTextures: priorities clamp to [0, 1]; name 0 is ignored.
    pub fn prioritize_textures(&mut self, p: &[(u32, f32)]) {
        for &(name, pr) in p {
            if let Some(o) = self.texture.objects.get_mut(&name) {
                o.priority = pr.clamp(0.0, 1.0);
            }
        }
    }

    /// glAreTexturesResident: every texture is resident; INVALID_VALUE for
    /// a name that is not a texture.
    pub fn are_textures_resident(&mut self, names: &[u32]) -> Option<Vec<bool>> {
        if names.iter().any(|&n| !self.is_texture(n)) {
            self.set_error(GL_INVALID_VALUE);
            return None;
        }
        Some(vec![true; names.len()])
    }

    /// glEnable/glDisable for the texturing capabilities of the active
    /// unit; false when `cap` is not one of them.
    pub fn set_texture_enabled(&mut self, cap: u32, on: bool) -> bool {
        let u = self.texture.active;
        let unit = &mut self.texture.units[u];
        match cap {
            GL_TEXTURE_1D => unit.enabled[0] = on,
            GL_TEXTURE_2D => unit.enabled[1] = on,
            GL_TEXTURE_3D => unit.enabled[2] = on,
            GL_TEXTURE_CUBE_MAP => unit.enabled[3] = on,
            GL_TEXTURE_RECTANGLE => unit.enabled[4] = on,
            GL_TEXTURE_GEN_S..=GL_TEXTURE_GEN_Q => unit.gen[(cap - GL_TEXTURE_GEN_S) as usize].enabled = on,
            _ => return false,
        }
        self.dirty |= DIRTY_TEXTURE;
        true
    }

    pub fn texture_is_enabled(&self, cap: u32) -> Option<bool> {
        let unit = &self.texture.units[self.texture.active];
        Some(match cap {
            GL_TEXTURE_1D => unit.enabled[0],
            GL_TEXTURE_2D => unit.enabled[1],
            GL_TEXTURE_3D => unit.enabled[2],
            GL_TEXTURE_CUBE_MAP => unit.enabled[3],
            GL_TEXTURE_RECTANGLE => unit.enabled[4],
            GL_TEXTURE_GEN_S..=GL_TEXTURE_GEN_Q => unit.gen[(cap - GL_TEXTURE_GEN_S) as usize].enabled,
            _ => return None,
        })
    }

    /// Builds glTexImage's command: unpacks the client image when the
    /// arguments allow it (errors are raised when the command runs). A
    /// proxy target runs at once and is never compiled (section 5.4).
    ///
    /// # Safety
    /// `pixels` must be NULL or point to the image as the unpack modes lay it out.
    #[allow(clippy::too_many_arguments)]
    pub unsafe fn tex_image_command(&mut self, dims: u8, target: u32, level: i32, internal_format: i32, size: [i32; 3], border: i32, format: u32, ty: u32, pixels: *const u8) -> Option<super::Command> {
        let mut cmd = TexImageCmd { dims, target, level, internal_format, size, border, format, ty, pixels: None };
        let proxy = matches!(image_target(target, dims), Some((_, _, true)));
        let limit = level_limit(target, dims, level);
        let sizes_ok = size[..dims as usize].iter().all(|&s| (0..=limit).contains(&s));
        if !proxy && (!pixels.is_null() || self.unpack_buffer_bound()) && sizes_ok && image::check_format_type(format, ty).is_ok() {
            let modes = unpack_modes(&self.pixel_store.unpack, dims);
            let pixels = match self.unpack_image(&modes, size[0], size[1], size[2], format, ty, pixels) {
                Ok(p) => p,
                Err(e) => return Some(super::Command::Error(e)),
            };
            let [w, h, d] = size.map(|s| s as usize);
            cmd.pixels = Some(Arc::new(image::unpack(&modes, w, h, d, format, ty, pixels)));
        }
        if proxy {
            if self.in_begin_end() {
                self.set_error(GL_INVALID_OPERATION);
            } else {
                self.tex_image(&cmd);
            }
            return None;
        }
        Some(super::Command::TexImage(Box::new(cmd)))
    }

    /// Builds glTexSubImage's command.
    ///
    /// # Safety
    /// As [`Self::tex_image_command`].
    #[allow(clippy::too_many_arguments)]
    pub unsafe fn tex_sub_image_command(&mut self, dims: u8, target: u32, level: i32, offset: [i32; 3], size: [i32; 3], format: u32, ty: u32, pixels: *const u8) -> super::Command {
        let mut cmd = TexSubImageCmd { dims, target, level, offset, size, format, ty, pixels: None };
        let limit = level_limit(target, dims, 0);
        let sizes_ok = size[..dims as usize].iter().all(|&s| (0..=limit).contains(&s));
        if (!pixels.is_null() || self.unpack_buffer_bound()) && sizes_ok && image::check_format_type(format, ty).is_ok() {
            let modes = unpack_modes(&self.pixel_store.unpack, dims);
            let pixels = match self.unpack_image(&modes, size[0], size[1], size[2], format, ty, pixels) {
                Ok(p) => p,
                Err(e) => return super::Command::Error(e),
            };
            let [w, h, d] = size.map(|s| s as usize);
            cmd.pixels = Some(Arc::new(image::unpack(&modes, w, h, d, format, ty, pixels)));
        }
        super::Command::TexSubImage(Box::new(cmd))
    }

    /// Checks an image call's common arguments; the target, face, proxy
    /// flag, internal format and whether the image fits the level's size
    /// limit on success (the error is set otherwise). An image that does
    /// not fit is INVALID_VALUE, except for a proxy, which it zeroes.
    #[allow(clippy::type_complexity)]
    fn check_image_args(&mut self, dims: u8, target: u32, level: i32, ifmt: u32, size: [i32; 3], border: i32) -> Option<(Target, usize, bool, InternalFormat, bool)> {
        let Some((t, face, proxy)) = image_target(target, dims) else {
            self.set_error(GL_INVALID_ENUM);
            return None;
        };
        let max = max_size(t);
        // A rectangle texture has one level and no border.
        if level < 0 || level > max_level_of(t) || (t == Target::Rect && border != 0) {
            self.set_error(GL_INVALID_VALUE);
            return None;
        }
        let Some(f) = internal_format(ifmt) else {
            self.set_error(GL_INVALID_VALUE);
            return None;
        };
        if !(0..=1).contains(&border) {
            self.set_error(GL_INVALID_VALUE);
            return None;
        }
        for &s in &size[..dims as usize] {
            if !valid_size(s, border) {
                self.set_error(GL_INVALID_VALUE);
                return None;
            }
        }
        if t == Target::Cube && size[0] != size[1] {
            self.set_error(GL_INVALID_VALUE);
            return None;
        }
        if f.base == Base::Depth && t == Target::T3D {
            self.set_error(GL_INVALID_OPERATION);
            return None;
        }
        let texels: usize = size[..dims as usize].iter().map(|&s| s as usize).product();
        let bytes = texels.saturating_mul(if f.compact() { 4 } else { 16 });
        let fits = size[..dims as usize].iter().all(|&s| fits_level(s, border, max, level)) && bytes <= MAX_IMAGE_BYTES;
        if !fits && !proxy {
            let too_big = size[..dims as usize].iter().any(|&s| !fits_level(s, border, max, level));
            self.set_error(if too_big { GL_INVALID_VALUE } else { GL_OUT_OF_MEMORY });
            return None;
        }
        Some((t, face, proxy, f, fits))
    }

    /// The ARB_imaging stages on a texture image's colour groups (section
    /// 3.8.1: texture images go through pixel transfer as glDrawPixels'
    /// do): None when no stage is on (the caller transfers as usual),
    /// Some(None) when a histogram or minmax sink consumed the image, else
    /// the transferred groups and the image's size after convolution.
    #[allow(clippy::option_option)]
    fn imaging_texture(&mut self, dims: u8, pixels: Option<&image::Pixels>, size: [i32; 3]) -> Option<Option<(image::Pixels, [i32; 3])>> {
        let p = pixels?;
        let st = self.imaging_stages(dims)?;
        let mut c: Vec<[f32; 4]> = match p {
            image::Pixels::Rgba8(v) => v.iter().map(|p| p.map(|x| crate::render::texture::UNORM8[x as usize])).collect(),
            image::Pixels::Color(v) => v.clone(),
            image::Pixels::Index(v) => v.iter().map(|&i| self.pixel.index_to_rgba(i)).collect(),
            _ => return None,
        };
        if !matches!(p, image::Pixels::Index(_)) {
            self.pixel.scale_bias_map(&mut c);
        }
        // A 3D image's slices stack up as rows (no convolution applies).
        let (w, h) = (size[0].max(0) as usize, (size[1].max(1) * if dims >= 3 { size[2].max(1) } else { 1 }) as usize);
        let (c, w2, h2) = self.imaging(st, c, w, h)?;
        let size = match dims {
            1 => [w2 as i32, 1, 1],
            2 => [w2 as i32, h2 as i32, 1],
            _ => size,
        };
        Some(Some((image::Pixels::Color(c), size)))
    }

    /// glTexImage1D/2D/3D (section 3.8.1).
    pub fn tex_image(&mut self, cmd: &TexImageCmd) {
        // glTexStorage's images are immutable in size and format.
        if let Some((t, _, false)) = image_target(cmd.target, cmd.dims) {
            if self.texture.object(self.texture.active, t).immutable {
                return self.set_error(GL_INVALID_OPERATION);
            }
        }
        match self.imaging_texture(cmd.dims, cmd.pixels.as_deref(), cmd.size) {
            None => self.tex_image_transferred(cmd, false),
            Some(None) => {}
            Some(Some((p, size))) => self.tex_image_transferred(&TexImageCmd { size, pixels: Some(Arc::new(p)), ..cmd.clone() }, true),
        }
    }

    /// glTexImage with `cmd`'s groups, already through pixel transfer when
    /// `transferred`.
    fn tex_image_transferred(&mut self, cmd: &TexImageCmd, transferred: bool) {
        let dims = cmd.dims as usize;
        let mut size = cmd.size;
        for s in size.iter_mut().skip(dims) {
            *s = 1;
        }
        let Some((t, face, proxy, f, fits)) = self.check_image_args(cmd.dims, cmd.target, cmd.level, cmd.internal_format as u32, size, cmd.border) else {
            return;
        };
        // Depth data for a colour format or the reverse: INVALID_OPERATION,
        // before STENCIL_INDEX's INVALID_ENUM (it is not depth data either).
        let depth_data = matches!(cmd.format, GL_DEPTH_COMPONENT | GL_DEPTH_STENCIL);
        if depth_data != (f.base == Base::Depth) && pixel_data::format_info(cmd.format).is_some() {
            return self.set_error(GL_INVALID_OPERATION);
        }
        if let Err(e) = image::check_format_type(cmd.format, cmd.ty) {
            return self.set_error(e);
        }
        let (w, h, d) = (size[0], if dims >= 2 { size[1] } else { 1 }, if dims >= 3 { size[2] } else { 1 });
        let img = Image { width: w, height: h, depth: d, border: cmd.border, internal_format: cmd.internal_format as u32, base: f.base, texels: Texels::default() };
        let slot = face * MAX_LEVELS + cmd.level as usize;
        if proxy {
            // The proxy's level state: an image softgl cannot hold zeroes it.
            self.texture.proxies[target_index(t)].images[slot] = if fits { Some(Arc::new(img)) } else { None };
            return;
        }
        let n = w as usize * h as usize * d as usize;
        let mut img = img;
        img.texels = match &cmd.pixels {
            Some(p) if p.len() == n => image::texels(&f, p, if transferred { &IDENTITY_TRANSFER } else { &self.pixel }),
            _ => image::zero_texels(&f, n),
        };
        self.drop_derived_textures();
        let u = self.texture.active;
        let obj = self.texture.object_mut(u, t);
        obj.images[slot] = Some(Arc::new(img));
        if obj.generate_mipmap && cmd.level == obj.params.base_level {
            generate_mipmaps(obj, t, face, &f);
        }
    }

    /// glTexSubImage1D/2D/3D (section 3.8.2).
    pub fn tex_sub_image(&mut self, cmd: &TexSubImageCmd) {
        match self.imaging_texture(cmd.dims, cmd.pixels.as_deref(), cmd.size) {
            None => self.tex_sub_image_transferred(cmd, false),
            Some(None) => {}
            Some(Some((p, size))) => self.tex_sub_image_transferred(&TexSubImageCmd { size, pixels: Some(Arc::new(p)), ..cmd.clone() }, true),
        }
    }

    fn tex_sub_image_transferred(&mut self, cmd: &TexSubImageCmd, transferred: bool) {
        let dims = cmd.dims as usize;
        let Some((t, face, false)) = image_target(cmd.target, cmd.dims) else { return self.set_error(GL_INVALID_ENUM) };
        if cmd.level < 0 || cmd.level > max_level_of(t) {
            return self.set_error(GL_INVALID_VALUE);
        }
        let u = self.texture.active;
        let Some(img) = self.texture.object(u, t).image(face, cmd.level as usize).cloned() else {
            return self.set_error(GL_INVALID_OPERATION);
        };
        let depth_data = matches!(cmd.format, GL_DEPTH_COMPONENT | GL_DEPTH_STENCIL);
        if depth_data != (img.base == Base::Depth) && pixel_data::format_info(cmd.format).is_some() {
            return self.set_error(GL_INVALID_OPERATION);
        }
        if let Err(e) = image::check_format_type(cmd.format, cmd.ty) {
            return self.set_error(e);
        }
        let full = [img.width, img.height, img.depth];
        let b = img.border;
        #[allow(clippy::needless_range_loop)]
        for k in 0..dims {
            let (o, s) = (cmd.offset[k], cmd.size[k]);
            if s < 0 || o < -b || o as i64 + s as i64 > (full[k] - b) as i64 {
                return self.set_error(GL_INVALID_VALUE);
            }
        }
        let size = [0, 1, 2].map(|k| if k < dims { cmd.size[k] } else { 1 });
        let offset = [0, 1, 2].map(|k| if k < dims { cmd.offset[k] + b } else { 0 });
        let n = size.iter().map(|&s| s as usize).product::<usize>();
        let Some(f) = internal_format(img.internal_format) else { return };
        drop(img);
        self.drop_derived_textures();
        let obj = self.texture.object_mut(u, t);
        if let Some(Some(dst)) = obj.images.get_mut(face * MAX_LEVELS + cmd.level as usize) {
            if let Some(p) = cmd.pixels.as_ref().filter(|p| p.len() == n) {
                let src = image::texels(&f, p, if transferred { &IDENTITY_TRANSFER } else { &self.pixel });
                let dst = Arc::make_mut(dst);
                let (w, h) = (dst.width as usize, dst.height as usize);
                dst.texels.write_block(w, h, offset.map(|o| o as usize), size.map(|s| s as usize), &src);
            }
        }
        if obj.generate_mipmap && cmd.level == obj.params.base_level {
            generate_mipmaps(obj, t, face, &f);
        }
    }

    /// glCopyTexImage1D/2D and glCopyTexSubImage1D/2D/3D (sections 3.8.2):
    /// the image comes from the framebuffer (colour, or depth for depth
    /// formats); pixels outside the window read as zero.
    pub fn copy_tex(&mut self, cmd: &CopyTexCmd) {
        let [x, y, w, h] = cmd.rect;
        let dims = cmd.dims;
        if !cmd.sub {
            let size = [w, if dims >= 2 { h } else { 1 }, 1];
            let Some((_, _, false)) = image_target(cmd.target, dims) else { return self.set_error(GL_INVALID_ENUM) };
            // "internalformat may not be specified as 1, 2, 3, or 4" (GL 1.1).
            if matches!(cmd.internal_format, 1..=4) {
                return self.set_error(GL_INVALID_ENUM);
            }
            let Some((_, _, _, f, _)) = self.check_image_args(dims, cmd.target, cmd.level, cmd.internal_format, size, cmd.border) else {
                return;
            };
            if f.base == Base::Depth && !self.fb.has_depth() {
                return self.set_error(GL_INVALID_OPERATION);
            }
            let ds = image::is_depth_stencil(cmd.internal_format) && self.fb.has_stencil();
            let pixels = self.read_framebuffer(x, y, size[0], size[1], f.base == Base::Depth, ds);
            let (format, ty) = copy_format(f.base == Base::Depth, ds);
            let img = TexImageCmd {
                dims,
                target: cmd.target,
                level: cmd.level,
                internal_format: cmd.internal_format as i32,
                size,
                border: cmd.border,
                format,
                ty,
                pixels: Some(Arc::new(pixels)),
            };
            self.tex_image(&img);
        } else {
            let Some((t, face, false)) = image_target(cmd.target, dims) else { return self.set_error(GL_INVALID_ENUM) };
            let u = self.texture.active;
            let Some(img) = self.texture.object(u, t).image(face, cmd.level.clamp(0, MAX_LEVELS as i32 - 1) as usize) else {
                return self.set_error(if cmd.level < 0 || cmd.level > max_level_of(t) { GL_INVALID_VALUE } else { GL_INVALID_OPERATION });
            };
            let depth = img.base == Base::Depth;
            if depth && !self.fb.has_depth() {
                return self.set_error(GL_INVALID_OPERATION);
            }
            if w < 0 || h < 0 {
                return self.set_error(GL_INVALID_VALUE);
            }
            let hh = if dims >= 2 { h } else { 1 };
            let ds = image::is_depth_stencil(img.internal_format) && self.fb.has_stencil();
            let pixels = self.read_framebuffer(x, y, w, hh, depth, ds);
            let (format, ty) = copy_format(depth, ds);
            let sub = TexSubImageCmd {
                dims,
                target: cmd.target,
                level: cmd.level,
                offset: cmd.offset,
                size: [w, hh, 1],
                format,
                ty,
                pixels: Some(Arc::new(pixels)),
            };
            // A 3D copy writes one slice: a 2D-shaped region at zoffset.
            self.tex_sub_image(&sub);
        }
    }

    /// The framebuffer's colour bytes or depth values of a rectangle (pixel
    /// transfer comes after, in `tex_image`); pixels outside the window
    /// read as zero.
    fn read_framebuffer(&self, x: i32, y: i32, w: i32, h: i32, depth: bool, stencil: bool) -> image::Pixels {
        let (fb, read) = self.read_source(); // glReadBuffer's buffer
        let n = w.max(0) as usize * h.max(0) as usize;
        let at = |i: i32, j: i32| {
            let (fx, fy) = (x as i64 + i as i64, y as i64 + j as i64);
            (fx >= 0 && fy >= 0 && fx < fb.width as i64 && fy < fb.height as i64).then(|| fb.index(fx as usize, fy as usize))
        };
        if depth && stencil {
            // Packed depth/stencil formats copy both (EXT_packed_depth_stencil).
            let mut out = Vec::with_capacity(n);
            for j in 0..h {
                for i in 0..w {
                    out.push(at(i, j).map_or((0.0, 0.0), |k| (fb.depth[k] as f64 / crate::framebuffer::DEPTH_MAX as f64, fb.stencil[k] as f64)));
                }
            }
            image::Pixels::DepthStencil(out)
        } else if depth {
            let mut out = Vec::with_capacity(n);
            for j in 0..h {
                for i in 0..w {
                    out.push(at(i, j).map_or(0.0, |k| fb.depth[k] as f64 / crate::framebuffer::DEPTH_MAX as f64));
                }
            }
            image::Pixels::Depth(out)
        } else {
            let mut out = Vec::with_capacity(n);
            for j in 0..h {
                for i in 0..w {
                    out.push(at(i, j).map_or([0; 4], |k| read[k]));
                }
            }
            image::Pixels::Rgba8(Arc::new(out))
        }
    }

    /// glTexParameter (section 3.8.4). Values arrive as floats (enums are
    /// exact in f32); the border colour of the integer forms is already
    /// normalized.
    pub fn tex_parameter(&mut self, target: u32, pname: u32, v: [f32; 4]) {
        let Some(t) = object_target(target) else { return self.set_error(GL_INVALID_ENUM) };
        let e = v[0] as u32;
        // ARB_texture_rectangle: no REPEAT wraps, no mipmap filters
        // (INVALID_ENUM), no base level but 0 (INVALID_OPERATION).
        if t == Target::Rect {
            let bad = match pname {
                GL_TEXTURE_WRAP_S | GL_TEXTURE_WRAP_T | GL_TEXTURE_WRAP_R => matches!(e, GL_REPEAT | GL_MIRRORED_REPEAT).then_some(GL_INVALID_ENUM),
                GL_TEXTURE_MIN_FILTER => (!matches!(e, GL_NEAREST | GL_LINEAR)).then_some(GL_INVALID_ENUM),
                GL_TEXTURE_BASE_LEVEL => (v[0] != 0.0).then_some(if v[0] < 0.0 { GL_INVALID_VALUE } else { GL_INVALID_OPERATION }),
                _ => None,
            };
            if let Some(err) = bad {
                return self.set_error(err);
            }
        }
        let u = self.texture.active;
        let obj = self.texture.object_mut(u, t);
        let p = &mut obj.params;
        let bad_enum = match sampler::set_sampling(p, pname, v) {
            Some(ok) => !ok,
            None => match pname {
                GL_TEXTURE_PRIORITY => {
                    obj.priority = v[0].clamp(0.0, 1.0);
                    false
                }
                GL_TEXTURE_BASE_LEVEL | GL_TEXTURE_MAX_LEVEL => {
                    if v[0] < 0.0 {
                        return self.set_error(GL_INVALID_VALUE);
                    }
                    let l = v[0].round() as i32;
                    if pname == GL_TEXTURE_BASE_LEVEL {
                        p.base_level = l;
                    } else {
                        p.max_level = l;
                    }
                    false
                }
                GL_GENERATE_MIPMAP => {
                    obj.generate_mipmap = v[0] != 0.0;
                    false
                }
                GL_TEXTURE_SWIZZLE_R..=GL_TEXTURE_SWIZZLE_A => match swizzle_source(v[0]) {
                    Some(k) => {
                        p.swizzle[(pname - GL_TEXTURE_SWIZZLE_R) as usize] = k;
                        false
                    }
                    None => true,
                },
                // All four or none.
                GL_TEXTURE_SWIZZLE_RGBA => match v.map(swizzle_source) {
                    [Some(r), Some(g), Some(b), Some(a)] => {
                        p.swizzle = [r, g, b, a];
                        false
                    }
                    _ => true,
                },
                GL_DEPTH_TEXTURE_MODE => match e {
                    GL_LUMINANCE => {
                        p.depth_mode = Base::Luminance;
                        false
                    }
                    GL_INTENSITY => {
                        p.depth_mode = Base::Intensity;
                        false
                    }
                    GL_ALPHA => {
                        p.depth_mode = Base::Alpha;
                        false
                    }
                    _ => true,
                },
                _ => true,
            },
        };
        if bad_enum {
            return self.set_error(GL_INVALID_ENUM);
        }
        self.dirty |= DIRTY_TEXTURE;
    }

    /// glGetTexParameter.
    pub fn get_tex_parameter(&mut self, target: u32, pname: u32) -> Option<Value> {
        let Some(t) = object_target(target) else {
            self.set_error(GL_INVALID_ENUM);
            return None;
        };
        let obj = self.texture.object(self.texture.active, t);
        let p = &obj.params;
        let wrap = |w: Wrap| match w {
            Wrap::Repeat => GL_REPEAT,
            Wrap::Clamp => GL_CLAMP,
            Wrap::ClampToEdge => GL_CLAMP_TO_EDGE,
            Wrap::ClampToBorder => GL_CLAMP_TO_BORDER,
            Wrap::MirroredRepeat => GL_MIRRORED_REPEAT,
        } as i64;
        let filter = |f: Filter| match f {
            Filter::Nearest => GL_NEAREST,
            Filter::Linear => GL_LINEAR,
            Filter::NearestMipmapNearest => GL_NEAREST_MIPMAP_NEAREST,
            Filter::LinearMipmapNearest => GL_LINEAR_MIPMAP_NEAREST,
            Filter::NearestMipmapLinear => GL_NEAREST_MIPMAP_LINEAR,
            Filter::LinearMipmapLinear => GL_LINEAR_MIPMAP_LINEAR,
        } as i64;
        let v = match pname {
            GL_TEXTURE_WRAP_S => Value::Ints(vec![wrap(p.wrap[0])]),
            GL_TEXTURE_WRAP_T => Value::Ints(vec![wrap(p.wrap[1])]),
            GL_TEXTURE_WRAP_R => Value::Ints(vec![wrap(p.wrap[2])]),
            GL_TEXTURE_MIN_FILTER => Value::Ints(vec![filter(p.min_filter)]),
            GL_TEXTURE_MAG_FILTER => Value::Ints(vec![filter(p.mag_filter)]),
            GL_TEXTURE_BORDER_COLOR => Value::Normalized(p.border_color.iter().map(|&c| c as f64).collect()),
            GL_TEXTURE_PRIORITY => Value::Floats(vec![obj.priority as f64]),
            GL_TEXTURE_RESIDENT => Value::Bools(vec![true]),
            GL_TEXTURE_MIN_LOD => Value::Floats(vec![p.min_lod as f64]),
            GL_TEXTURE_MAX_LOD => Value::Floats(vec![p.max_lod as f64]),
            GL_TEXTURE_BASE_LEVEL => Value::Ints(vec![p.base_level as i64]),
            GL_TEXTURE_MAX_LEVEL => Value::Ints(vec![p.max_level as i64]),
            GL_TEXTURE_LOD_BIAS => Value::Floats(vec![p.lod_bias as f64]),
            GL_GENERATE_MIPMAP => Value::Bools(vec![obj.generate_mipmap]),
            GL_TEXTURE_COMPARE_MODE => Value::Ints(vec![if p.compare_mode { GL_COMPARE_R_TO_TEXTURE } else { GL_NONE } as i64]),
            GL_TEXTURE_COMPARE_FUNC => Value::Ints(vec![p.compare_func.to_gl() as i64]),
            // ARB_texture_storage.
            0x912F => Value::Bools(vec![obj.immutable]),
            GL_TEXTURE_SWIZZLE_R..=GL_TEXTURE_SWIZZLE_A => Value::Ints(vec![swizzle_enum(p.swizzle[(pname - GL_TEXTURE_SWIZZLE_R) as usize])]),
            GL_TEXTURE_SWIZZLE_RGBA => Value::Ints(p.swizzle.iter().map(|&k| swizzle_enum(k)).collect()),
            GL_DEPTH_TEXTURE_MODE => Value::Ints(vec![match p.depth_mode {
                Base::Intensity => GL_INTENSITY,
                Base::Alpha => GL_ALPHA,
                _ => GL_LUMINANCE,
            } as i64]),
            _ => {
                self.set_error(GL_INVALID_ENUM);
                return None;
            }
        };
        Some(v)
    }

    /// glGetTexLevelParameter (section 6.1.3).
    pub fn get_tex_level_parameter(&mut self, target: u32, level: i32, pname: u32) -> Option<Value> {
        let found = [1u8, 2, 3].iter().find_map(|&d| image_target(target, d));
        let Some((t, face, proxy)) = found else {
            self.set_error(GL_INVALID_ENUM);
            return None;
        };
        if level < 0 || level > max_level_of(t) {
            self.set_error(GL_INVALID_VALUE);
            return None;
        }
        let obj = if proxy { &self.texture.proxies[target_index(t)] } else { self.texture.object(self.texture.active, t) };
        let img = obj.image(face, level as usize);
        let f = img.and_then(|i| internal_format(i.internal_format));
        let bits = f.map(|f| f.stored_bits()).unwrap_or([0; 7]);
        let v = |x: i64| Some(Value::Ints(vec![x]));
        match pname {
            GL_TEXTURE_WIDTH => v(img.map_or(0, |i| i.width as i64)),
            GL_TEXTURE_HEIGHT => v(img.map_or(0, |i| if dims_of(t) >= 2 { i.height } else { 1 } as i64)),
            GL_TEXTURE_DEPTH => v(img.map_or(0, |i| if dims_of(t) >= 3 { i.depth } else { 1 } as i64)),
            GL_TEXTURE_BORDER => v(img.map_or(0, |i| i.border as i64)),
            GL_TEXTURE_INTERNAL_FORMAT => v(img.map_or(1, |i| i.internal_format as i64)),
            GL_TEXTURE_RED_SIZE => v(bits[0] as i64),
            GL_TEXTURE_GREEN_SIZE => v(bits[1] as i64),
            GL_TEXTURE_BLUE_SIZE => v(bits[2] as i64),
            GL_TEXTURE_ALPHA_SIZE => v(bits[3] as i64),
            GL_TEXTURE_LUMINANCE_SIZE => v(bits[4] as i64),
            GL_TEXTURE_INTENSITY_SIZE => v(bits[5] as i64),
            GL_TEXTURE_DEPTH_SIZE => v(bits[6] as i64),
            GL_TEXTURE_STENCIL_SIZE => v(img.map_or(0, |i| if matches!(i.internal_format, GL_DEPTH_STENCIL | GL_DEPTH24_STENCIL8) { 8 } else { 0 })),
            GL_TEXTURE_COMPRESSED => Some(Value::Bools(vec![false])),
            // ARB_texture_float's component types (GL_NONE when absent).
            GL_TEXTURE_RED_TYPE..=GL_TEXTURE_DEPTH_TYPE => {
                let k = [0, 1, 2, 3, 4, 5, 6][(pname - GL_TEXTURE_RED_TYPE) as usize];
                let float = img.is_some_and(|i| image::is_float_format(i.internal_format));
                v(if bits[k] == 0 { 0 } else if float { 0x1406 } else { 0x8C17 })
            }
            GL_TEXTURE_COMPRESSED_IMAGE_SIZE => {
                self.set_error(GL_INVALID_OPERATION);
                None
            }
            _ => {
                self.set_error(GL_INVALID_ENUM);
                None
            }
        }
    }

    /// glGetTexImage (section 6.1.4): the whole image, border included.
    ///
    /// # Safety
    /// `out` must be NULL or have room for the image as the pack modes lay it out.
    pub unsafe fn get_tex_image(&mut self, target: u32, level: i32, format: u32, ty: u32, out: *mut u8) {
        let found = [1u8, 2, 3].iter().find_map(|&d| image_target(target, d));
        let Some((t, face, false)) = found else { return self.set_error(GL_INVALID_ENUM) };
        if level < 0 || level > max_level_of(t) {
            return self.set_error(GL_INVALID_VALUE);
        }
        match image::check_format_type(format, ty) {
            Err(e) => return self.set_error(e),
            Ok(pixel_data::Kind::ColorIndex) => return self.set_error(GL_INVALID_ENUM),
            Ok(_) => {}
        }
        let Some(img) = self.texture.object(self.texture.active, t).image(face, level as usize) else { return };
        if matches!(format, GL_DEPTH_COMPONENT | GL_DEPTH_STENCIL) != (img.base == Base::Depth) {
            return self.set_error(GL_INVALID_OPERATION);
        }
        if (out.is_null() && !self.pack_buffer_bound()) || img.texels.is_empty() {
            return;
        }
        let (w, h, d) = (img.width as i32, img.height as i32, img.depth as i32);
        let modes = self.pixel_store.pack;
        let out = match self.pack_image(&modes, w, h, d, format, ty, out) {
            Ok(p) => p,
            Err(e) => return self.set_error(e),
        };
        let Some(img) = self.texture.object(self.texture.active, t).image(face, level as usize) else { return };
        image::pack(&modes, img, format, ty, &self.pixel, out);
    }

    /// glTexEnv (section 3.8.13); the integer form's colour is normalized.
    pub fn tex_env(&mut self, target: u32, pname: u32, v: [f32; 4]) {
        let u = self.texture.active;
        let e = v[0] as u32;
        if target == GL_TEXTURE_FILTER_CONTROL {
            if pname != GL_TEXTURE_LOD_BIAS {
                return self.set_error(GL_INVALID_ENUM);
            }
            self.texture.units[u].lod_bias = v[0];
            self.dirty |= DIRTY_TEXTURE;
            return;
        }
        if target != GL_TEXTURE_ENV {
            return self.set_error(GL_INVALID_ENUM);
        }
        let env = &mut self.texture.units[u].env;
        let source_ok = |s: u32| matches!(s, GL_TEXTURE | GL_CONSTANT | GL_PRIMARY_COLOR | GL_PREVIOUS) || (GL_TEXTURE0..GL_TEXTURE0 + MAX_UNITS as u32).contains(&s);
        let ok = match pname {
            GL_TEXTURE_ENV_MODE if matches!(e, GL_MODULATE | GL_DECAL | GL_BLEND | GL_REPLACE | GL_ADD | GL_COMBINE) => {
                env.mode = e;
                true
            }
            GL_TEXTURE_ENV_COLOR => {
                env.color = v.map(|c| c.clamp(0.0, 1.0));
                true
            }
            GL_COMBINE_RGB if matches!(e, GL_REPLACE | GL_MODULATE | GL_ADD | GL_ADD_SIGNED | GL_INTERPOLATE | GL_SUBTRACT | GL_DOT3_RGB | GL_DOT3_RGBA) => {
                env.combine_rgb = e;
                true
            }
            GL_COMBINE_ALPHA if matches!(e, GL_REPLACE | GL_MODULATE | GL_ADD | GL_ADD_SIGNED | GL_INTERPOLATE | GL_SUBTRACT) => {
                env.combine_alpha = e;
                true
            }
            GL_SOURCE0_RGB..=GL_SOURCE2_RGB if source_ok(e) => {
                env.src_rgb[(pname - GL_SOURCE0_RGB) as usize] = e;
                true
            }
            GL_SOURCE0_ALPHA..=GL_SOURCE2_ALPHA if source_ok(e) => {
                env.src_alpha[(pname - GL_SOURCE0_ALPHA) as usize] = e;
                true
            }
            GL_OPERAND0_RGB..=GL_OPERAND2_RGB if matches!(e, GL_SRC_COLOR | GL_ONE_MINUS_SRC_COLOR | GL_SRC_ALPHA | GL_ONE_MINUS_SRC_ALPHA) => {
                env.op_rgb[(pname - GL_OPERAND0_RGB) as usize] = e;
                true
            }
            GL_OPERAND0_ALPHA..=GL_OPERAND2_ALPHA if matches!(e, GL_SRC_ALPHA | GL_ONE_MINUS_SRC_ALPHA) => {
                env.op_alpha[(pname - GL_OPERAND0_ALPHA) as usize] = e;
                true
            }
            GL_RGB_SCALE | GL_ALPHA_SCALE => {
                if !matches!(v[0], 1.0 | 2.0 | 4.0) {
                    return self.set_error(GL_INVALID_VALUE);
                }
                if pname == GL_RGB_SCALE {
                    env.scale_rgb = v[0];
                } else {
                    env.scale_alpha = v[0];
                }
                true
            }
            _ => false,
        };
        if !ok {
            return self.set_error(GL_INVALID_ENUM);
        }
        self.dirty |= DIRTY_TEXTURE;
    }

    /// glGetTexEnv.
    pub fn get_tex_env(&mut self, target: u32, pname: u32) -> Option<Value> {
        let u = &self.texture.units[self.texture.active];
        let env = &u.env;
        let i = |x: u32| Some(Value::Ints(vec![x as i64]));
        let v = match (target, pname) {
            (GL_TEXTURE_FILTER_CONTROL, GL_TEXTURE_LOD_BIAS) => Some(Value::Floats(vec![u.lod_bias as f64])),
            (GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE) => i(env.mode),
            (GL_TEXTURE_ENV, GL_TEXTURE_ENV_COLOR) => Some(Value::Normalized(env.color.iter().map(|&c| c as f64).collect())),
            (GL_TEXTURE_ENV, GL_COMBINE_RGB) => i(env.combine_rgb),
            (GL_TEXTURE_ENV, GL_COMBINE_ALPHA) => i(env.combine_alpha),
            (GL_TEXTURE_ENV, GL_SOURCE0_RGB..=GL_SOURCE2_RGB) => i(env.src_rgb[(pname - GL_SOURCE0_RGB) as usize]),
            (GL_TEXTURE_ENV, GL_SOURCE0_ALPHA..=GL_SOURCE2_ALPHA) => i(env.src_alpha[(pname - GL_SOURCE0_ALPHA) as usize]),
            (GL_TEXTURE_ENV, GL_OPERAND0_RGB..=GL_OPERAND2_RGB) => i(env.op_rgb[(pname - GL_OPERAND0_RGB) as usize]),
            (GL_TEXTURE_ENV, GL_OPERAND0_ALPHA..=GL_OPERAND2_ALPHA) => i(env.op_alpha[(pname - GL_OPERAND0_ALPHA) as usize]),
            (GL_TEXTURE_ENV, GL_RGB_SCALE) => Some(Value::Floats(vec![env.scale_rgb as f64])),
            (GL_TEXTURE_ENV, GL_ALPHA_SCALE) => Some(Value::Floats(vec![env.scale_alpha as f64])),
            _ => None,
        };
        if v.is_none() {
            self.set_error(GL_INVALID_ENUM);
        }
        v
    }

    /// Texture queries of glGet (tables 6.8, 6.15, 6.17, 6.26).
    pub fn texture_get(&self, pname: u32) -> Option<Value> {
        let ts = &self.texture;
        let u = &ts.units[ts.active];
        let ints = |v: &[i64]| Some(Value::Ints(v.to_vec()));
        match pname {
            GL_ACTIVE_TEXTURE => ints(&[(GL_TEXTURE0 as usize + ts.active) as i64]),
            GL_CLIENT_ACTIVE_TEXTURE => ints(&[(GL_TEXTURE0 as usize + ts.client_active) as i64]),
            GL_MAX_TEXTURE_UNITS => ints(&[MAX_UNITS as i64]),
            GL_MAX_TEXTURE_SIZE => ints(&[MAX_TEXTURE_SIZE as i64]),
            GL_MAX_3D_TEXTURE_SIZE => ints(&[MAX_3D_TEXTURE_SIZE as i64]),
            GL_MAX_CUBE_MAP_TEXTURE_SIZE => ints(&[MAX_CUBE_MAP_TEXTURE_SIZE as i64]),
            GL_MAX_TEXTURE_LOD_BIAS => Some(Value::Floats(vec![MAX_LOD_BIAS as f64])),
            GL_TEXTURE_BINDING_1D => ints(&[u.bound[0] as i64]),
            GL_TEXTURE_BINDING_2D => ints(&[u.bound[1] as i64]),
            GL_TEXTURE_BINDING_3D => ints(&[u.bound[2] as i64]),
            GL_TEXTURE_BINDING_CUBE_MAP => ints(&[u.bound[3] as i64]),
            GL_TEXTURE_BINDING_RECTANGLE => ints(&[u.bound[4] as i64]),
            GL_MAX_RECTANGLE_TEXTURE_SIZE => ints(&[MAX_RECTANGLE_TEXTURE_SIZE as i64]),
            GL_CURRENT_TEXTURE_COORDS => Some(Value::Floats(self.current.tex_coords[ts.active].iter().map(|&c| c as f64).collect())),
            GL_NUM_COMPRESSED_TEXTURE_FORMATS => ints(&[0]),
            GL_COMPRESSED_TEXTURE_FORMATS => Some(Value::Ints(Vec::new())),
            _ => None,
        }
    }

    /// Validation: the fragment stage's samplers and environments (on
    /// texture changes), and the vertex stage's per-unit work.
    pub fn validate_texture(&mut self, texture_changed: bool) {
        if texture_changed {
            let ts = &self.texture;
            let mut stage = TextureStage { units: Default::default(), envs: [Env::default(); MAX_UNITS], active: Vec::new() };
            for u in 0..MAX_UNITS {
                stage.envs[u] = ts.units[u].env;
                let Some(t) = ts.unit_target(u) else { continue };
                let obj = ts.object(u, t);
                // A bound sampler object's state replaces the texture's.
                let params = match self.samplers.objects.get(&self.samplers.bound[u]) {
                    Some(s) => sampler::apply(&obj.params, s),
                    None => obj.params.clone(),
                };
                if let Some(faces) = obj.complete_with(t, &params) {
                    let base = faces[0][0].base;
                    stage.units[u] = Some(UnitSampler::new(t, faces, params, ts.units[u].lod_bias, base));
                    stage.active.push(u);
                }
            }
            self.derived.render.texture = if stage.active.is_empty() { None } else { Some(Arc::new(stage)) };
        }
        self.texture.vertex = texgen::VertexTexSetup::new(self);
    }
}

impl Context {
    /// glTexStorage1D/2D/3D (ARB_texture_storage): every level of the bound
    /// texture (every face of a cube map) at once, sized internal formats
    /// only, made immutable (TEXTURE_IMMUTABLE_FORMAT).
    pub fn tex_storage(&mut self, dims: u8, target: u32, levels: i32, ifmt: u32, size: [i32; 3]) {
        let (t, proxy) = match (dims, target) {
            (1, GL_TEXTURE_1D) => (Target::T1D, false),
            (2, GL_TEXTURE_2D) => (Target::T2D, false),
            (2, GL_TEXTURE_CUBE_MAP) => (Target::Cube, false),
            (2, GL_TEXTURE_RECTANGLE) => (Target::Rect, false),
            (3, GL_TEXTURE_3D) => (Target::T3D, false),
            (1, GL_PROXY_TEXTURE_1D) => (Target::T1D, true),
            (2, GL_PROXY_TEXTURE_2D) => (Target::T2D, true),
            (2, GL_PROXY_TEXTURE_CUBE_MAP) => (Target::Cube, true),
            (2, GL_PROXY_TEXTURE_RECTANGLE) => (Target::Rect, true),
            (3, GL_PROXY_TEXTURE_3D) => (Target::T3D, true),
            _ => return self.set_error(GL_INVALID_ENUM),
        };
        let unsized_format = matches!(ifmt, 1..=4 | GL_ALPHA | GL_LUMINANCE | GL_LUMINANCE_ALPHA | GL_INTENSITY | GL_RGB | GL_RGBA | GL_RED | GL_RG | GL_DEPTH_COMPONENT | GL_DEPTH_STENCIL)
            || (0x84E9..=0x84EE).contains(&ifmt);
        let Some(f) = internal_format(ifmt).filter(|_| !unsized_format) else { return self.set_error(GL_INVALID_ENUM) };
        // Depth formats exist for 1D, 2D, cube map and rectangle textures.
        if f.base == Base::Depth && t == Target::T3D {
            return self.set_error(GL_INVALID_OPERATION);
        }
        let n = &size[..dims as usize];
        if levels < 1 || n.iter().any(|&s| s < 1) {
            return self.set_error(GL_INVALID_VALUE);
        }
        let largest = if t == Target::T3D { size.iter().copied().max().unwrap_or(1) } else { n.iter().copied().max().unwrap_or(1) };
        if levels > log2_floor(largest) + 1 || (t == Target::Rect && levels > 1) {
            return self.set_error(GL_INVALID_OPERATION);
        }
        let u = self.texture.active;
        if !proxy && (self.texture.units[u].bound[target_index(t)] == 0 || self.texture.object(u, t).immutable) {
            return self.set_error(GL_INVALID_OPERATION);
        }
        let (format, ty) = if f.base == Base::Depth { (GL_DEPTH_COMPONENT, GL_FLOAT) } else { (GL_RGBA, GL_UNSIGNED_BYTE) };
        // A proxy target only answers whether the levels would fit (its
        // level queries), as glTexImage's proxies do.
        let faces: Vec<u32> = if t == Target::Cube && !proxy { (0..6).map(|i| GL_TEXTURE_CUBE_MAP_POSITIVE_X + i).collect() } else { vec![target] };
        let mut s = size;
        for level in 0..levels {
            for &face in &faces {
                let cmd = TexImageCmd { dims, target: face, level, internal_format: ifmt as i32, size: s, border: 0, format, ty, pixels: None };
                self.tex_image(&cmd);
            }
            for (k, v) in s.iter_mut().enumerate() {
                if k < dims as usize {
                    *v = (*v / 2).max(1);
                }
            }
        }
        if proxy {
            return;
        }
        let obj = self.texture.object_mut(u, t);
        obj.immutable = true;
        obj.immutable_levels = levels;
    }

    /// glGenerateMipmap (EXT_framebuffer_object section 3.8.8): the bound
    /// texture's levels above the base one from the base, by
    /// GENERATE_MIPMAP's filter. INVALID_OPERATION without a base image
    /// (or for a cube map whose faces are not all there).
    pub fn generate_mipmap_now(&mut self, target: u32) {
        let Some(t) = object_target(target).filter(|&t| t != Target::Rect) else { return self.set_error(GL_INVALID_ENUM) };
        let u = self.texture.active;
        let base = self.texture.object(u, t).params.base_level.max(0) as usize;
        let faces = if t == Target::Cube { 6 } else { 1 };
        let Some(img) = self.texture.object(u, t).image(0, base).cloned() else { return self.set_error(GL_INVALID_OPERATION) };
        if (1..faces).any(|f| self.texture.object(u, t).image(f, base).is_none()) {
            return self.set_error(GL_INVALID_OPERATION);
        }
        let Some(f) = internal_format(img.internal_format) else { return };
        self.drop_derived_textures();
        let obj = self.texture.object_mut(u, t);
        for face in 0..faces {
            generate_mipmaps(obj, t, face, &f);
        }
    }
}

/// The unpack modes of a texture image: 1D and 2D images ignore
/// SKIP_IMAGES and IMAGE_HEIGHT (section 3.8.1: they are unpacked as 3D
/// images of depth 1 "except that UNPACK_SKIP_IMAGES is ignored").
fn unpack_modes(m: &super::pixels::PixelModes, dims: u8) -> super::pixels::PixelModes {
    let mut m = *m;
    if dims < 3 {
        m.skip_images = 0;
        m.image_height = 0;
    }
    m
}

/// The format and type a copy's framebuffer pixels are given as.
fn copy_format(depth: bool, stencil: bool) -> (u32, u32) {
    match (depth, stencil) {
        (true, true) => (GL_DEPTH_STENCIL, GL_UNSIGNED_INT_24_8),
        (true, false) => (GL_DEPTH_COMPONENT, GL_FLOAT),
        _ => (GL_RGBA, GL_UNSIGNED_BYTE),
    }
}

/// GENERATE_MIPMAP (GL 1.4): levels base + 1 .. q of one face from the
/// base level, by the 2x2(x2) box filter. Images with a border are filtered
/// without it (the border of derived levels is the base's border colour
/// region left at zero).
fn generate_mipmaps(obj: &mut TexObject, t: Target, face: usize, f: &InternalFormat) {
    let base = obj.params.base_level.max(0) as usize;
    let Some(b) = obj.image(face, base).cloned() else { return };
    let dims = dims_of(t) as usize;
    let n = b.inner(dims);
    let bw = b.border;
    let (mut w, mut h, mut d) = (n[0] as usize, n[1] as usize, n[2] as usize);
    let q = (base as i32 + log2_floor(n[..dims].iter().copied().max().unwrap_or(1))).min(obj.params.max_level).min(MAX_LEVELS as i32 - 1);
    if let (0, Texels::Rgba8(src)) = (bw, &b.texels) {
        // 8-bit storage without border: the box filter on bytes, each level
        // from the previous stored one (exact mean, rounded).
        let mut cur = src.clone();
        for level in base + 1..=q.max(base as i32) as usize {
            let (next, nw, nh, nd) = image::downsample_rgba8(&cur, w, h, d);
            let next = Arc::new(next);
            let img = Image { width: nw as i32, height: nh as i32, depth: nd as i32, border: 0, internal_format: b.internal_format, base: f.base, texels: Texels::Rgba8(next.clone()) };
            obj.images[face * MAX_LEVELS + level] = Some(Arc::new(img));
            cur = next;
            (w, h, d) = (nw, nh, nd);
        }
        return;
    }
    // Strip the border.
    let mut cur: Vec<[f32; 4]> = if bw == 0 {
        b.texels.to_float()
    } else {
        let mut v = Vec::with_capacity((n[0] * n[1] * n[2]) as usize);
        for k in 0..n[2] {
            for j in 0..n[1] {
                for i in 0..n[0] {
                    v.push(b.texel_at(dims, i, j, k));
                }
            }
        }
        v
    };
    for level in base + 1..=q.max(base as i32) as usize {
        let (next, nw, nh, nd) = image::downsample(&cur, w, h, d);
        // Derived levels have the base's border width, filled from the edge.
        let img = Image::with_border(nw as i32, nh as i32, nd as i32, dims, bw, b.internal_format, f.base, &next, f.compact());
        obj.images[face * MAX_LEVELS + level] = Some(Arc::new(img));
        cur = next;
        (w, h, d) = (nw, nh, nd);
    }
}

/// A TEXTURE_SWIZZLE value: RED, GREEN, BLUE, ALPHA, ZERO or ONE (else
/// None: INVALID_ENUM).
fn swizzle_source(v: f32) -> Option<u8> {
    use crate::render::texture::{SWIZZLE_ONE, SWIZZLE_ZERO};
    if v != v.trunc() {
        return None;
    }
    // RED, GREEN, BLUE and ALPHA are consecutive enums.
    let e = v as i64;
    Some(match e {
        _ if (GL_RED as i64..=GL_ALPHA as i64).contains(&e) => (e - GL_RED as i64) as u8,
        0 => SWIZZLE_ZERO,
        1 => SWIZZLE_ONE,
        _ => return None,
    })
}

/// The enum glGetTexParameter reports for a swizzle source.
fn swizzle_enum(k: u8) -> i64 {
    match k {
        0..=3 => (GL_RED + k as u32) as i64,
        crate::render::texture::SWIZZLE_ZERO => 0,
        _ => 1,
    }
}
