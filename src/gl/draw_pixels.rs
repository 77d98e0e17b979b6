//! glDrawPixels, glCopyPixels (GL 1.5 sections 3.6.4, 4.3.3) and glBitmap
//! (section 3.7).
//!
//! Display lists: the client image is unpacked when the command is built
//! (at compile time, with the unpack modes then current: section 5.4), into
//! a [`PixelRect`] of groups before pixel transfer; transfer, zoom and the
//! fragment operations happen when the command executes. A bitmap is
//! likewise unpacked (GL_UNPACK_LSB_FIRST, skips, alignment) into rows of
//! MSB-first bytes.
//!
//! Fragments: colour rectangles take the raster position's z; depth
//! rectangles take the raster colour and their own z; both go through the
//! per-fragment operations (`process_fragment`: alpha, stencil, depth,
//! blend/logic op, masks), clipped to the window and the scissor box.
//! Stencil rectangles write the stencil buffer directly through the
//! stencil write mask (only ownership and the scissor test apply).
//! Bitmap fragments take the raster colour and z.
//!
//! Texturing, the colour sum and fog (sections 3.8 to 3.10) apply to the
//! colour of every fragment these commands produce, with the raster
//! position's texture coordinates (the same for every fragment: no
//! derivatives, so textures magnify), secondary colour and fog distance
//! ([`PixelShading`]).
//!
//! DEPTH_STENCIL (EXT_packed_depth_stencil) rectangles, drawn or copied,
//! are written like stencil rectangles (GL 3.0 section 4.3.1, "Writing to
//! the Stencil or Depth/Stencil Buffers", which took the extension in):
//! only ownership and the scissor test apply, the stencil index goes
//! through the stencil write mask and the depth value is written when
//! the depth mask allows it, whatever the depth test says.
//!
//! glCopyPixels reads the whole source rectangle first, so overlapping
//! source and destination behave as if every source pixel were read before
//! any is written; source pixels outside the window produce no fragments.

use super::command::Command;
use super::context::Context;
use super::enums::*;
use super::pixel_data::{check_format_type, Kind, Source, GL_DEPTH_STENCIL};
use crate::render::fragment::{color_to_u8, depth_to_fixed, process_fragment};
use crate::render::fog::Fog;
use crate::render::pixels;
use crate::render::texture::{point_coords, Coord, TextureStage, MAX_UNITS};
use glam::Vec4;
use std::rc::Rc;
use std::sync::Arc;

/// Texturing, colour sum and fog of pixel-rectangle and bitmap fragments
/// (section 3.6.4, "Conversion to fragments": they are then treated like
/// a point's fragments at the raster position).
struct PixelShading {
    texture: Option<(Arc<TextureStage>, [Coord; MAX_UNITS])>,
    secondary: Option<glam::Vec3>,
    fog: Option<(Fog, f32)>,
}

impl PixelShading {
    /// The fragment colour after these stages, in the framebuffer's bytes.
    fn apply(&self, c: [f32; 4]) -> [u8; 4] {
        let mut c = Vec4::from_array(c).clamp(Vec4::ZERO, Vec4::ONE);
        if let Some((stage, coords)) = &self.texture {
            c = stage.shade(coords, c);
        }
        if let Some(s) = self.secondary {
            c = (c.truncate() + s).extend(c.w).clamp(Vec4::ZERO, Vec4::ONE);
        }
        if let Some((fog, d)) = &self.fog {
            c = fog.apply(c, *d);
        }
        color_to_u8(c)
    }
}

/// Unpacked groups of a pixel rectangle, before pixel transfer.
#[derive(Clone, Debug, PartialEq)]
pub enum PixelData {
    Color(Vec<[f32; 4]>),
    /// RGBA / UNSIGNED_BYTE groups as given (`draw_pixels_fast`).
    Rgba8(Vec<[u8; 4]>),
    ColorIndex(Vec<f64>),
    Depth(Vec<f64>),
    Stencil(Vec<f64>),
    /// DEPTH_STENCIL groups: (depth, stencil index).
    DepthStencil(Vec<(f64, f64)>),
}

#[derive(Clone, Debug, PartialEq)]
pub struct PixelRect {
    pub width: usize,
    pub height: usize,
    pub data: PixelData,
}

/// A bitmap: rows of ceil(width / 8) bytes, most significant bit first.
#[derive(Clone, Debug, PartialEq)]
pub struct Bitmap {
    pub width: usize,
    pub height: usize,
    pub orig: [f32; 2],
    pub step: [f32; 2],
    pub bits: Vec<u8>,
}

impl Bitmap {
    pub fn stride(&self) -> usize {
        self.width.div_ceil(8)
    }
}

/// Groups after pixel transfer, ready to become fragments; `None` marks
/// groups that produce none (CopyPixels sources outside the window).
enum Groups {
    Color(Vec<Option<[u8; 4]>>),
    Depth(Vec<Option<u32>>),
    Stencil(Vec<Option<i64>>),
    /// DEPTH_STENCIL groups: (window depth, stencil index), written directly.
    DepthStencil(Vec<Option<(u32, i64)>>),
}

impl Context {
    /// Builds glDrawPixels' command: unpacks the client image now. Errors
    /// in the arguments become a command that raises them when executed.
    ///
    /// # Safety
    /// `ptr` must be NULL or point to the image as the unpack modes lay it out.
    pub unsafe fn build_draw_pixels(&self, w: i32, h: i32, format: u32, ty: u32, ptr: *const u8) -> Option<Command> {
        if w < 0 || h < 0 {
            return Some(Command::Error(GL_INVALID_VALUE));
        }
        let kind = match check_format_type(format, ty) {
            Ok(k) => k,
            Err(e) => return Some(Command::Error(e)),
        };
        if ptr.is_null() && !self.unpack_buffer_bound() {
            return None;
        }
        let ptr = match self.unpack_image(&self.pixel_store.unpack, w, h, 1, format, ty, ptr) {
            Ok(p) => p,
            Err(e) => return Some(Command::Error(e)),
        };
        let (w, h) = (w as usize, h as usize);
        let src = Source::new(&self.pixel_store.unpack, w, h, 1, format, ty, ptr);
        let data = match kind {
            Kind::Color if format == GL_RGBA && ty == GL_UNSIGNED_BYTE => PixelData::Rgba8(super::draw_pixels_fast::unpack_rgba8(&src, w, h, self.derived.render.threads)),
            Kind::Color => PixelData::Color(src.colors(w, h, 1)),
            Kind::Depth => PixelData::Depth(src.values(w, h, 1, true)),
            Kind::ColorIndex => PixelData::ColorIndex(src.values(w, h, 1, false)),
            Kind::Stencil => PixelData::Stencil(src.values(w, h, 1, false)),
            Kind::DepthStencil => PixelData::DepthStencil(src.depth_stencil(w, h, 1)),
        };
        Some(Command::DrawPixels(Rc::new(PixelRect { width: w, height: h, data })))
    }

    /// Builds glBitmap's command, unpacking the bitmap now (a NULL bitmap
    /// draws nothing and still moves the raster position).
    ///
    /// # Safety
    /// `ptr` must be NULL or point to the bitmap as the unpack modes lay it out.
    pub unsafe fn build_bitmap(&self, w: i32, h: i32, orig: [f32; 2], step: [f32; 2], ptr: *const u8) -> Command {
        if w < 0 || h < 0 {
            return Command::Error(GL_INVALID_VALUE);
        }
        // From a pixel unpack buffer, the bitmap is at offset `ptr`.
        let bound = self.unpack_buffer_bound();
        let ptr = match self.unpack_image(&self.pixel_store.unpack, w, h, 1, GL_COLOR_INDEX, GL_BITMAP, ptr) {
            Ok(p) => p,
            Err(e) => return Command::Error(e),
        };
        let (w, h) = (w as usize, h as usize);
        let stride = w.div_ceil(8);
        let mut bits = vec![0u8; stride * h];
        if !ptr.is_null() || bound {
            let src = Source::new(&self.pixel_store.unpack, w, h, 1, GL_COLOR_INDEX, GL_BITMAP, ptr);
            for (n, v) in src.values(w, h, 1, false).into_iter().enumerate() {
                if v != 0.0 {
                    let (i, j) = (n % w, n / w);
                    bits[j * stride + i / 8] |= 0x80 >> (i % 8);
                }
            }
        }
        Command::Bitmap(Rc::new(Bitmap { width: w, height: h, orig, step, bits }))
    }

    /// The stages after rasterization that change a pixel fragment's
    /// colour, or None when none is on (derived state: validate first).
    fn pixel_shading(&self) -> Option<PixelShading> {
        let rs = &self.derived.render;
        let texture = rs.texture.as_ref().map(|stage| {
            let tex = self.raster.tex.map(Vec4::from_array);
            (stage.clone(), point_coords(stage, &tex))
        });
        let secondary = rs.color_sum.then(|| Vec4::from_array(self.raster.secondary_color).truncate());
        // The raster distance is the fog coordinate: evaluate f exactly.
        let fog = rs.fog.map(|f| (Fog { per_fragment: true, ..f }, self.raster.distance));
        (texture.is_some() || secondary.is_some() || fog.is_some()).then_some(PixelShading { texture, secondary, fog })
    }

    /// Whether [`Context::pixel_shading`] has a stage (without building it).
    pub(super) fn pixel_shading_on(&self) -> bool {
        let rs = &self.derived.render;
        rs.texture.is_some() || rs.color_sum || rs.fog.is_some()
    }

    /// glDrawPixels as called: RGBA / UNSIGNED_BYTE client images outside
    /// list compilation are drawn where they lie
    /// ([`Context::draw_client_rgba8`]); everything else is built into a
    /// command (unpacked now) for `submit`.
    ///
    /// # Safety
    /// As [`Context::build_draw_pixels`].
    pub unsafe fn draw_pixels_call(&mut self, w: i32, h: i32, format: u32, ty: u32, ptr: *const u8) -> Option<Command> {
        if self.draw_client_rgba8(w, h, format, ty, ptr) {
            return None;
        }
        self.build_draw_pixels(w, h, format, ty, ptr)
    }

    /// The colour of pixel-rectangle and bitmap fragments that take the
    /// raster colour (depth rectangles, bitmaps), textured and fogged.
    fn fragment_color(&self) -> [u8; 4] {
        match self.pixel_shading() {
            Some(sh) => sh.apply(self.raster.color),
            None => color_to_u8(Vec4::from_array(self.raster.color)),
        }
    }

    /// glDrawPixels, executed.
    pub fn draw_pixels(&mut self, r: &PixelRect) {
        let missing = match r.data {
            PixelData::Depth(_) => !self.fb.has_depth(),
            PixelData::Stencil(_) => !self.fb.has_stencil(),
            PixelData::DepthStencil(_) => !self.fb.has_depth() || !self.fb.has_stencil(),
            _ => false,
        };
        if missing {
            return self.set_error(GL_INVALID_OPERATION);
        }
        if !self.raster.valid {
            return;
        }
        self.validate();
        let (mut w, mut h) = (r.width, r.height);
        // The ARB_imaging stages (section 3.6.5) on colour groups, when on.
        let imaged = match (&r.data, self.imaging_stages(2)) {
            (PixelData::Color(_) | PixelData::Rgba8(_), Some(st)) => {
                let mut c = super::draw_pixels_fast::float_colors(&r.data);
                self.pixel.scale_bias_map(&mut c);
                Some(self.imaging(st, c, w, h))
            }
            (PixelData::ColorIndex(ix), Some(st)) => {
                let c = ix.iter().map(|&i| self.pixel.index_to_rgba(i)).collect();
                Some(self.imaging(st, c, w, h))
            }
            _ => None,
        };
        let shading = self.pixel_shading();
        if let (PixelData::Rgba8(b), None, None) = (&r.data, &shading, &imaged) {
            if self.draw_rgba8_fast(r.width, r.height, b) {
                return;
            }
        }
        let finish = |p: [f32; 4]| match &shading {
            Some(sh) => sh.apply(p),
            None => color_to_u8(Vec4::from_array(p)),
        };
        let t = &self.pixel;
        let groups = match &r.data {
            _ if imaged.is_some() => match imaged.expect("checked") {
                // A histogram or minmax sink consumed the groups.
                None => return,
                Some((c, w2, h2)) => {
                    (w, h) = (w2, h2);
                    Groups::Color(c.iter().map(|&p| Some(finish(p))).collect())
                }
            },
            PixelData::Color(_) | PixelData::Rgba8(_) => {
                let mut c = super::draw_pixels_fast::float_colors(&r.data);
                t.color(&mut c);
                Groups::Color(c.iter().map(|&p| Some(finish(p))).collect())
            }
            PixelData::ColorIndex(ix) => Groups::Color(ix.iter().map(|&i| Some(finish(t.index_to_rgba(i)))).collect()),
            PixelData::Depth(d) => Groups::Depth(d.iter().map(|&z| Some(depth_to_fixed(t.depth(z)))).collect()),
            PixelData::Stencil(s) => Groups::Stencil(s.iter().map(|&i| Some(t.stencil(i))).collect()),
            PixelData::DepthStencil(ds) => {
                Groups::DepthStencil(ds.iter().map(|&(z, i)| Some((depth_to_fixed(t.depth(z)), t.stencil(i)))).collect())
            }
        };
        self.draw_groups(w, h, groups);
    }

    /// Turns transferred groups into fragments at the raster position.
    fn draw_groups(&mut self, w: usize, h: usize, groups: Groups) {
        self.validate();
        let clip = self.scissored_surface();
        let origin = [self.raster.pos[0] as f64, self.raster.pos[1] as f64];
        let zoom = self.pixel.zoom.map(|z| z as f64);
        let raster_z = depth_to_fixed(self.raster.pos[2] as f64);
        let raster_color = self.fragment_color();
        let fs = &self.derived.render.fragment;
        let fb = &mut self.fb;
        match groups {
            Groups::Color(c) => pixels::rectangle(clip, origin, zoom, w, h, |g, x, y| {
                if let Some(color) = c[g] {
                    let i = fb.index(x, y);
                    process_fragment(fs, fb, i, raster_z, color);
                }
            }),
            Groups::Depth(d) => pixels::rectangle(clip, origin, zoom, w, h, |g, x, y| {
                if let Some(z) = d[g] {
                    let i = fb.index(x, y);
                    process_fragment(fs, fb, i, z, raster_color);
                }
            }),
            Groups::Stencil(s) => {
                let put = self.stencil_store();
                let fb = &mut self.fb;
                pixels::rectangle(clip, origin, zoom, w, h, |g, x, y| {
                    if let Some(v) = s[g] {
                        let i = fb.index(x, y);
                        put(&mut fb.stencil[i], v);
                    }
                })
            }
            Groups::DepthStencil(ds) => {
                let put = self.stencil_store();
                let write_depth = self.depth.write_mask;
                let fb = &mut self.fb;
                pixels::rectangle(clip, origin, zoom, w, h, |g, x, y| {
                    if let Some((z, v)) = ds[g] {
                        let i = fb.index(x, y);
                        put(&mut fb.stencil[i], v);
                        if write_depth {
                            fb.depth[i] = z;
                        }
                    }
                })
            }
        }
    }

    /// Stores a stencil index as drawn stencil groups are stored (4.3.1):
    /// its low bits, through the stencil write mask.
    fn stencil_store(&self) -> impl Fn(&mut u8, i64) {
        let max = ((1u32 << self.fb.config.stencil_bits.min(8)) - 1) as i64;
        let wm = (self.stencil.write_mask as i64 & max) as u8;
        move |s: &mut u8, v: i64| *s = (*s & !wm) | ((v & max) as u8 & wm)
    }

    /// glCopyPixels.
    pub fn copy_pixels(&mut self, x: i32, y: i32, w: i32, h: i32, ty: u32) {
        if w < 0 || h < 0 {
            return self.set_error(GL_INVALID_VALUE);
        }
        let missing = match ty {
            GL_COLOR => false,
            GL_DEPTH => !self.fb.has_depth(),
            GL_STENCIL => !self.fb.has_stencil(),
            GL_DEPTH_STENCIL => !self.fb.has_depth() || !self.fb.has_stencil(),
            _ => return self.set_error(GL_INVALID_ENUM),
        };
        if missing {
            return self.set_error(GL_INVALID_OPERATION);
        }
        if !self.raster.valid || w == 0 || h == 0 {
            return;
        }
        let (mut w, mut h) = (w as usize, h as usize);
        self.validate();
        if ty == GL_COLOR {
            if let Some(st) = self.imaging_stages(2) {
                // The imaging stages need the whole rectangle: read it (outside
                // the window as zero), transfer it, draw what comes out.
                let mut c = self.framebuffer_colors(x, y, w as i32, h as i32);
                self.pixel.scale_bias_map(&mut c);
                let Some((c, w2, h2)) = self.imaging(st, c, w, h) else { return };
                let shading = self.pixel_shading();
                let groups = Groups::Color(c.iter().map(|&p| Some(shading.as_ref().map_or_else(|| color_to_u8(Vec4::from_array(p)), |sh| sh.apply(p)))).collect());
                (w, h) = (w2, h2);
                return self.draw_groups(w, h, groups);
            }
        }
        let shading = self.pixel_shading();
        if ty == GL_COLOR && shading.is_none() && self.copy_rgba8_fast(x, y, w, h) {
            return;
        }
        let (fb, read) = self.read_source(); // glReadBuffer's buffer
        // Read everything first: overlapping copies see the old pixels.
        let at = |i: usize, j: usize| -> Option<usize> {
            let (fx, fy) = (x as i64 + i as i64, y as i64 + j as i64);
            (fx >= 0 && fy >= 0 && fx < fb.width as i64 && fy < fb.height as i64).then(|| fb.index(fx as usize, fy as usize))
        };
        let idx: Vec<Option<usize>> = (0..h).flat_map(|j| (0..w).map(move |i| (i, j))).map(|(i, j)| at(i, j)).collect();
        let t = &self.pixel;
        let groups = match ty {
            GL_COLOR => {
                let identity = t.color_is_identity();
                Groups::Color(
                    idx.iter()
                        .map(|o| {
                            o.map(|k| {
                                let c = read[k];
                                if identity && shading.is_none() {
                                    c
                                } else {
                                    let mut f = [c.map(|v| v as f32 / 255.0)];
                                    t.color(&mut f);
                                    match &shading {
                                        Some(sh) => sh.apply(f[0]),
                                        None => color_to_u8(Vec4::from_array(f[0])),
                                    }
                                }
                            })
                        })
                        .collect(),
                )
            }
            GL_DEPTH => {
                let max = crate::framebuffer::DEPTH_MAX as f64;
                let identity = t.depth_is_identity();
                Groups::Depth(idx.iter().map(|o| o.map(|k| if identity { fb.depth[k] } else { depth_to_fixed(t.depth(fb.depth[k] as f64 / max)) })).collect())
            }
            GL_DEPTH_STENCIL => {
                // Both read before either is written.
                let max = crate::framebuffer::DEPTH_MAX as f64;
                Groups::DepthStencil(
                    idx.iter()
                        .map(|o| o.map(|k| (depth_to_fixed(t.depth(fb.depth[k] as f64 / max)), t.stencil(fb.stencil[k] as f64))))
                        .collect(),
                )
            }
            _ => Groups::Stencil(idx.iter().map(|o| o.map(|k| t.stencil(fb.stencil[k] as f64))).collect()),
        };
        self.draw_groups(w, h, groups);
    }

    /// glBitmap, executed.
    pub fn bitmap(&mut self, b: &Bitmap) {
        if !self.raster.valid {
            return;
        }
        if b.width > 0 && b.height > 0 {
            self.validate();
            let clip = self.scissored_surface();
            let x0 = (self.raster.pos[0] as f64 - b.orig[0] as f64).floor() as i64;
            let y0 = (self.raster.pos[1] as f64 - b.orig[1] as f64).floor() as i64;
            let z = depth_to_fixed(self.raster.pos[2] as f64);
            let color = self.fragment_color();
            let fs = &self.derived.render.fragment;
            let fb = &mut self.fb;
            pixels::bitmap(clip, x0, y0, b.width, b.height, b.stride(), &b.bits, |x, y| {
                let i = fb.index(x, y);
                process_fragment(fs, fb, i, z, color);
            });
        }
        self.raster.pos[0] += b.step[0];
        self.raster.pos[1] += b.step[1];
    }
}
