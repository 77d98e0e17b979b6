//! State queries (GL 1.5 section 6.1): glGet* with the spec's type
//! conversions (6.1.2), glGetString and glGetError.

use super::context::Context;
use super::enums::*;
use super::lists::MAX_LIST_NESTING;
use super::matrix::{MAX_MODELVIEW_DEPTH, MAX_PROJECTION_DEPTH, MAX_TEXTURE_DEPTH};
use crate::framebuffer::MAX_SIZE;
use crate::render::setup::SUBPIXEL_BITS;

/// A queried value before conversion to the caller's type.
pub enum Value {
    Bools(Vec<bool>),
    Ints(Vec<i64>),
    Floats(Vec<f64>),
    /// Colours, depth range, depth clear value, normals: integers map
    /// [-1, 1] linearly onto the integer range (section 6.1.2).
    Normalized(Vec<f64>),
}

impl Value {
    pub fn as_f64(&self) -> Vec<f64> {
        match self {
            Value::Bools(v) => v.iter().map(|&b| b as i32 as f64).collect(),
            Value::Ints(v) => v.iter().map(|&i| i as f64).collect(),
            Value::Floats(v) | Value::Normalized(v) => v.clone(),
        }
    }

    pub fn as_i32(&self) -> Vec<i32> {
        match self {
            Value::Bools(v) => v.iter().map(|&b| b as i32).collect(),
            Value::Ints(v) => v.iter().map(|&i| i.clamp(i32::MIN as i64, i32::MAX as i64) as i32).collect(),
            Value::Floats(v) => v.iter().map(|&f| f.round().clamp(i32::MIN as f64, i32::MAX as f64) as i32).collect(),
            Value::Normalized(v) => v
                .iter()
                .map(|&f| {
                    let f = f.clamp(-1.0, 1.0);
                    // Map -1 -> MIN, 1 -> MAX: ((2^32 - 1) f - 1) / 2. The
                    // spec leaves ties open; to even, so 0 gives 0 (-0.5),
                    // not -1, as applications expect of a zero colour.
                    ((4294967295.0 * f - 1.0) / 2.0).round_ties_even().clamp(i32::MIN as f64, i32::MAX as f64) as i32
                })
                .collect(),
        }
    }

    pub fn as_bool(&self) -> Vec<bool> {
        match self {
            Value::Bools(v) => v.clone(),
            _ => self.as_f64().iter().map(|&f| f != 0.0).collect(),
        }
    }
}

/// The stencil buffer's bits (8): what the stencil masks read back.
const STENCIL_MASK: u32 = 0xFF;

// Point and line queries (table 6.11, 6.12, 6.32).
const GL_POINT_SIZE: u32 = 0x0B11;
const GL_POINT_SIZE_RANGE: u32 = 0x0B12;
const GL_POINT_SIZE_GRANULARITY: u32 = 0x0B13;
const GL_LINE_WIDTH: u32 = 0x0B21;
const GL_LINE_WIDTH_RANGE: u32 = 0x0B22;
const GL_LINE_WIDTH_GRANULARITY: u32 = 0x0B23;
const GL_LINE_STIPPLE_PATTERN: u32 = 0x0B25;
const GL_LINE_STIPPLE_REPEAT: u32 = 0x0B26;

fn ints<const N: usize>(v: [i64; N]) -> Option<Value> {
    Some(Value::Ints(v.to_vec()))
}

impl Context {
    /// The value of `pname`, or None when it is not a valid query.
    pub fn get(&mut self, pname: u32) -> Option<Value> {
        if let Some(on) = self.is_enabled(pname) {
            return Some(Value::Bools(vec![on]));
        }
        if let Some(v) = self.texture_get(pname) {
            return Some(v);
        }
        if let Some(v) = self.fbo_get(pname) {
            return Some(v);
        }
        if let Some(v) = self.sampler_get(pname) {
            return Some(v);
        }
        if let Some(v) = self.get_array_value(pname) {
            return Some(v);
        }
        if let Some(v) = self.imaging_get(pname) {
            return Some(v);
        }
        let fb = &self.fb.config;
        let has = |bits: u8| bits as i64;
        match pname {
            GL_CURRENT_NORMAL => Some(Value::Normalized(self.current.normal.iter().map(|&c| c as f64).collect())),
            GL_LIGHT_MODEL_AMBIENT => Some(Value::Normalized(self.lighting.model_ambient.to_array().iter().map(|&c| c as f64).collect())),
            GL_LIGHT_MODEL_LOCAL_VIEWER => Some(Value::Bools(vec![self.lighting.local_viewer])),
            GL_LIGHT_MODEL_TWO_SIDE => Some(Value::Bools(vec![self.lighting.two_side])),
            GL_LIGHT_MODEL_COLOR_CONTROL => {
                ints([if self.lighting.separate_specular { GL_SEPARATE_SPECULAR_COLOR } else { GL_SINGLE_COLOR } as i64])
            }
            GL_COLOR_MATERIAL_FACE => ints([self.lighting.color_material_face as i64]),
            GL_COLOR_MATERIAL_PARAMETER => ints([self.lighting.color_material_mode as i64]),
            GL_MAX_LIGHTS => ints([super::lighting::MAX_LIGHTS as i64]),
            GL_ACCUM_CLEAR_VALUE => Some(Value::Normalized(self.accum_clear.iter().map(|&c| c as f64).collect())),
            0x0C40 /* GL_RENDER_MODE */ => ints([self.select.mode as i64]),
            0x0D70 /* GL_NAME_STACK_DEPTH */ => ints([self.name_stack_depth() as i64]),
            0x0DF4 /* GL_SELECTION_BUFFER_SIZE */ => ints([self.select.buffer_sizes().0 as i64]),
            0x0DF1 /* GL_FEEDBACK_BUFFER_SIZE */ => ints([self.select.buffer_sizes().1 as i64]),
            0x0DF2 /* GL_FEEDBACK_BUFFER_TYPE */ => ints([self.select.buffer_sizes().2 as i64]),
            GL_MAX_NAME_STACK_DEPTH => ints([super::select::MAX_NAME_STACK_DEPTH as i64]),
            GL_MAX_EVAL_ORDER => ints([super::eval::MAX_EVAL_ORDER as i64]),
            0x0DD0 /* GL_MAP1_GRID_DOMAIN */ => Some(Value::Floats(vec![self.eval.grid1.1 as f64, self.eval.grid1.2 as f64])),
            0x0DD1 /* GL_MAP1_GRID_SEGMENTS */ => ints([self.eval.grid1.0 as i64]),
            0x0DD2 /* GL_MAP2_GRID_DOMAIN */ => {
                let g = self.eval.grid2;
                Some(Value::Floats(vec![g.1 as f64, g.2 as f64, g.4 as f64, g.5 as f64]))
            }
            0x0DD3 /* GL_MAP2_GRID_SEGMENTS */ => ints([self.eval.grid2.0 as i64, self.eval.grid2.3 as i64]),
            GL_MAX_CLIP_PLANES => ints([super::clip_plane::MAX_CLIP_PLANES as i64]),
            0x0B40 /* GL_POLYGON_MODE */ => ints([self.polygon.mode[0] as i64, self.polygon.mode[1] as i64]),
            0x8038 /* GL_POLYGON_OFFSET_FACTOR */ => Some(Value::Floats(vec![self.polygon.offset_factor as f64])),
            0x2A00 /* GL_POLYGON_OFFSET_UNITS */ => Some(Value::Floats(vec![self.polygon.offset_units as f64])),
            0x0B43 /* GL_EDGE_FLAG */ => Some(Value::Bools(vec![self.current.edge_flag])),
            GL_MAX_ATTRIB_STACK_DEPTH | GL_MAX_CLIENT_ATTRIB_STACK_DEPTH => ints([super::attrib::MAX_ATTRIB_STACK_DEPTH as i64]),
            0x0BB0 /* GL_ATTRIB_STACK_DEPTH */ => ints([self.attrib.server.len() as i64]),
            0x0BB1 /* GL_CLIENT_ATTRIB_STACK_DEPTH */ => ints([self.attrib.client.len() as i64]),
            0x0B62 /* GL_FOG_DENSITY */ => Some(Value::Floats(vec![self.fog.density as f64])),
            0x0B63 /* GL_FOG_START */ => Some(Value::Floats(vec![self.fog.start as f64])),
            0x0B64 /* GL_FOG_END */ => Some(Value::Floats(vec![self.fog.end as f64])),
            0x0B61 /* GL_FOG_INDEX */ => Some(Value::Floats(vec![self.fog.index as f64])),
            0x0B65 /* GL_FOG_MODE */ => ints([self.fog.mode as i64]),
            0x0B66 /* GL_FOG_COLOR */ => Some(Value::Normalized(self.fog.color.iter().map(|&c| c as f64).collect())),
            0x8450 /* GL_FOG_COORD_SRC */ => ints([self.fog.coord_src as i64]),
            0x8126 /* GL_POINT_SIZE_MIN */ => Some(Value::Floats(vec![self.point.size_min as f64])),
            0x8127 /* GL_POINT_SIZE_MAX */ => Some(Value::Floats(vec![self.point.size_max as f64])),
            0x8128 /* GL_POINT_FADE_THRESHOLD_SIZE */ => Some(Value::Floats(vec![self.point.fade_threshold as f64])),
            0x8129 /* GL_POINT_DISTANCE_ATTENUATION */ => Some(Value::Floats(self.point.attenuation.iter().map(|&x| x as f64).collect())),
            0x80AA /* GL_SAMPLE_COVERAGE_VALUE */ => Some(Value::Floats(vec![self.color_buffer.sample_coverage.0 as f64])),
            0x80AB /* GL_SAMPLE_COVERAGE_INVERT */ => Some(Value::Bools(vec![self.color_buffer.sample_coverage.1])),
            0x80A8 /* GL_SAMPLE_BUFFERS */ | 0x80A9 /* GL_SAMPLES */ => ints([0]),
            GL_CURRENT_COLOR => Some(Value::Normalized(self.current.color.iter().map(|&c| c as f64).collect())),
            GL_COLOR_CLEAR_VALUE => Some(Value::Normalized(self.color_buffer.clear.iter().map(|&c| c as f64).collect())),
            GL_COLOR_WRITEMASK => Some(Value::Bools(self.color_buffer.write_mask.to_vec())),
            GL_DEPTH_CLEAR_VALUE => Some(Value::Normalized(vec![self.depth.clear])),
            GL_DEPTH_FUNC => ints([self.depth.func.to_gl() as i64]),
            GL_DEPTH_WRITEMASK => Some(Value::Bools(vec![self.depth.write_mask])),
            GL_DEPTH_RANGE => Some(Value::Normalized(vec![self.viewport.near, self.viewport.far])),
            GL_STENCIL_CLEAR_VALUE => ints([self.stencil.clear as i64]),
            // The masks are kept as given (all 1's initially, table 6.21)
            // and read back within the stencil buffer's 8 bits, as Mesa
            // reads them back: the 32-bit 1's clamped to a GLint gave
            // 0x7fffffff, which is neither the mask nor its bits.
            GL_STENCIL_WRITEMASK => ints([(self.stencil.write_mask & STENCIL_MASK) as i64]),
            GL_STENCIL_FUNC => ints([self.stencil.func.to_gl() as i64]),
            GL_STENCIL_VALUE_MASK => ints([(self.stencil.value_mask & STENCIL_MASK) as i64]),
            GL_STENCIL_REF => ints([self.stencil_reference() as i64]),
            GL_STENCIL_FAIL => ints([self.stencil.fail.to_gl() as i64]),
            GL_STENCIL_PASS_DEPTH_FAIL => ints([self.stencil.zfail.to_gl() as i64]),
            GL_STENCIL_PASS_DEPTH_PASS => ints([self.stencil.zpass.to_gl() as i64]),
            GL_ALPHA_TEST_FUNC => ints([self.color_buffer.alpha_func.to_gl() as i64]),
            GL_ALPHA_TEST_REF => Some(Value::Normalized(vec![self.color_buffer.alpha_ref as f64])),
            GL_BLEND_SRC | GL_BLEND_SRC_RGB => ints([self.color_buffer.blend_src_rgb.to_gl() as i64]),
            GL_BLEND_DST | GL_BLEND_DST_RGB => ints([self.color_buffer.blend_dst_rgb.to_gl() as i64]),
            GL_BLEND_SRC_ALPHA => ints([self.color_buffer.blend_src_alpha.to_gl() as i64]),
            GL_BLEND_DST_ALPHA => ints([self.color_buffer.blend_dst_alpha.to_gl() as i64]),
            GL_BLEND_COLOR => Some(Value::Normalized(self.color_buffer.blend_color.iter().map(|&c| c as f64).collect())),
            GL_BLEND_EQUATION => ints([self.color_buffer.blend_equation.to_gl() as i64]),
            GL_LOGIC_OP_MODE => ints([self.color_buffer.logic_op.to_gl() as i64]),
            GL_VIEWPORT => {
                let v = &self.viewport;
                ints([v.x as i64, v.y as i64, v.width as i64, v.height as i64])
            }
            GL_SCISSOR_BOX => {
                let s = &self.scissor;
                ints([s.x as i64, s.y as i64, s.width as i64, s.height as i64])
            }
            GL_MATRIX_MODE => ints([self.transform.mode as i64]),
            GL_MODELVIEW_MATRIX => Some(Value::Floats(self.transform.modelview.top().to_cols_array().to_vec())),
            GL_PROJECTION_MATRIX => Some(Value::Floats(self.transform.projection.top().to_cols_array().to_vec())),
            GL_TEXTURE_MATRIX => Some(Value::Floats(self.transform.texture().top().to_cols_array().to_vec())),
            GL_TRANSPOSE_MODELVIEW_MATRIX => Some(Value::Floats(self.transform.modelview.top().transpose().to_cols_array().to_vec())),
            GL_TRANSPOSE_PROJECTION_MATRIX => Some(Value::Floats(self.transform.projection.top().transpose().to_cols_array().to_vec())),
            GL_TRANSPOSE_TEXTURE_MATRIX => Some(Value::Floats(self.transform.texture().top().transpose().to_cols_array().to_vec())),
            GL_MODELVIEW_STACK_DEPTH => ints([self.transform.modelview.depth() as i64]),
            GL_PROJECTION_STACK_DEPTH => ints([self.transform.projection.depth() as i64]),
            GL_TEXTURE_STACK_DEPTH => ints([self.transform.texture().depth() as i64]),
            GL_MAX_MODELVIEW_STACK_DEPTH => ints([MAX_MODELVIEW_DEPTH as i64]),
            GL_MAX_PROJECTION_STACK_DEPTH => ints([MAX_PROJECTION_DEPTH as i64]),
            GL_MAX_TEXTURE_STACK_DEPTH => ints([MAX_TEXTURE_DEPTH as i64]),
            GL_MAX_VIEWPORT_DIMS => ints([MAX_SIZE as i64, MAX_SIZE as i64]),
            GL_SUBPIXEL_BITS => ints([SUBPIXEL_BITS as i64]),
            GL_POINT_SIZE => Some(Value::Floats(vec![self.point.size as f64])),
            // GL_POINT_SIZE_RANGE and _GRANULARITY are the smooth ones
            // (GL_SMOOTH_POINT_SIZE_*, same enums); likewise for lines.
            GL_POINT_SIZE_RANGE | GL_LINE_WIDTH_RANGE => {
                Some(Value::Floats(vec![crate::render::smooth::MIN_SIZE as f64, crate::render::smooth::MAX_SIZE as f64]))
            }
            GL_POINT_SIZE_GRANULARITY | GL_LINE_WIDTH_GRANULARITY => Some(Value::Floats(vec![crate::render::smooth::GRANULARITY as f64])),
            GL_ALIASED_POINT_SIZE_RANGE => Some(Value::Floats(vec![1.0, crate::render::point::MAX_SIZE as f64])),
            GL_LINE_WIDTH => Some(Value::Floats(vec![self.line.width as f64])),
            GL_ALIASED_LINE_WIDTH_RANGE => Some(Value::Floats(vec![1.0, crate::render::line::MAX_WIDTH as f64])),
            GL_LINE_STIPPLE_PATTERN => ints([self.line.stipple_pattern as i64]),
            GL_LINE_STIPPLE_REPEAT => ints([self.line.stipple_repeat as i64]),
            GL_SHADE_MODEL => ints([self.shade_model as i64]),
            GL_CULL_FACE_MODE => ints([self.polygon.cull_mode as i64]),
            GL_FRONT_FACE => ints([self.polygon.front_face as i64]),
            GL_RED_BITS | GL_GREEN_BITS | GL_BLUE_BITS => ints([8]),
            GL_ALPHA_BITS => ints([fb.alpha_bits as i64]),
            GL_DEPTH_BITS => ints([has(fb.depth_bits)]),
            GL_STENCIL_BITS => ints([has(fb.stencil_bits)]),
            GL_ACCUM_RED_BITS | GL_ACCUM_GREEN_BITS | GL_ACCUM_BLUE_BITS | GL_ACCUM_ALPHA_BITS => ints([has(fb.accum_bits)]),
            // RGBA visuals only: no colour-index bits.
            0x0D51 /* GL_INDEX_BITS */ => ints([0]),
            GL_RGBA_MODE => Some(Value::Bools(vec![true])),
            GL_INDEX_MODE | GL_STEREO => Some(Value::Bools(vec![false])),
            GL_DOUBLEBUFFER => Some(Value::Bools(vec![self.double_buffered])),
            GL_DRAW_BUFFER => ints([self.color_buffer.draw_buffer as i64]),
            GL_READ_BUFFER => ints([self.pixel_read_buffer as i64]),
            GL_INDEX_WRITEMASK => ints([self.color_buffer.index_mask as i64]),
            GL_INDEX_CLEAR_VALUE => Some(Value::Floats(vec![self.color_buffer.clear_index as f64])),
            0x0C00 /* GL_AUX_BUFFERS */ => ints([0]),
            GL_LIST_BASE => ints([self.lists.base as i64]),
            GL_LIST_INDEX => ints([self.lists.index() as i64]),
            GL_LIST_MODE => ints([self.lists.compile_mode().unwrap_or(0) as i64]),
            GL_MAX_LIST_NESTING => ints([MAX_LIST_NESTING as i64]),
            GL_PERSPECTIVE_CORRECTION_HINT => ints([self.hints.perspective_correction as i64]),
            GL_POINT_SMOOTH_HINT => ints([self.hints.point_smooth as i64]),
            GL_LINE_SMOOTH_HINT => ints([self.hints.line_smooth as i64]),
            GL_POLYGON_SMOOTH_HINT => ints([self.hints.polygon_smooth as i64]),
            GL_FOG_HINT => ints([self.hints.fog as i64]),
            GL_GENERATE_MIPMAP_HINT => ints([self.hints.generate_mipmap as i64]),
            GL_TEXTURE_COMPRESSION_HINT => ints([self.hints.texture_compression as i64]),
            GL_PACK_SWAP_BYTES => Some(Value::Bools(vec![self.pixel_store.pack.swap_bytes])),
            GL_PACK_LSB_FIRST => Some(Value::Bools(vec![self.pixel_store.pack.lsb_first])),
            GL_PACK_ROW_LENGTH => ints([self.pixel_store.pack.row_length as i64]),
            GL_PACK_SKIP_ROWS => ints([self.pixel_store.pack.skip_rows as i64]),
            GL_PACK_SKIP_PIXELS => ints([self.pixel_store.pack.skip_pixels as i64]),
            GL_PACK_ALIGNMENT => ints([self.pixel_store.pack.alignment as i64]),
            GL_PACK_SKIP_IMAGES => ints([self.pixel_store.pack.skip_images as i64]),
            GL_PACK_IMAGE_HEIGHT => ints([self.pixel_store.pack.image_height as i64]),
            GL_UNPACK_SWAP_BYTES => Some(Value::Bools(vec![self.pixel_store.unpack.swap_bytes])),
            GL_UNPACK_LSB_FIRST => Some(Value::Bools(vec![self.pixel_store.unpack.lsb_first])),
            GL_UNPACK_ROW_LENGTH => ints([self.pixel_store.unpack.row_length as i64]),
            GL_UNPACK_SKIP_ROWS => ints([self.pixel_store.unpack.skip_rows as i64]),
            GL_UNPACK_SKIP_PIXELS => ints([self.pixel_store.unpack.skip_pixels as i64]),
            GL_UNPACK_ALIGNMENT => ints([self.pixel_store.unpack.alignment as i64]),
            GL_UNPACK_SKIP_IMAGES => ints([self.pixel_store.unpack.skip_images as i64]),
            GL_UNPACK_IMAGE_HEIGHT => ints([self.pixel_store.unpack.image_height as i64]),
            super::buffers::GL_PIXEL_PACK_BUFFER_BINDING => ints([self.buffers.pixel_pack as i64]),
            super::buffers::GL_PIXEL_UNPACK_BUFFER_BINDING => ints([self.buffers.pixel_unpack as i64]),
            // Raster position and pixel transfer (tables 6.7, 6.17, 6.18).
            GL_CURRENT_RASTER_POSITION => Some(Value::Floats(self.raster.pos.iter().map(|&c| c as f64).collect())),
            GL_CURRENT_RASTER_POSITION_VALID => Some(Value::Bools(vec![self.raster.valid])),
            GL_CURRENT_RASTER_COLOR => Some(Value::Normalized(self.raster.color.iter().map(|&c| c as f64).collect())),
            GL_CURRENT_RASTER_SECONDARY_COLOR => Some(Value::Normalized(self.raster.secondary_color.iter().map(|&c| c as f64).collect())),
            GL_CURRENT_RASTER_DISTANCE => Some(Value::Floats(vec![self.raster.distance as f64])),
            GL_CURRENT_RASTER_TEXTURE_COORDS => Some(Value::Floats(self.raster.tex[self.texture.active].iter().map(|&c| c as f64).collect())),
            GL_CURRENT_RASTER_INDEX => Some(Value::Floats(vec![self.raster.index as f64])),
            GL_ZOOM_X => Some(Value::Floats(vec![self.pixel.zoom[0] as f64])),
            GL_ZOOM_Y => Some(Value::Floats(vec![self.pixel.zoom[1] as f64])),
            GL_MAP_COLOR => Some(Value::Bools(vec![self.pixel.map_color])),
            GL_MAP_STENCIL => Some(Value::Bools(vec![self.pixel.map_stencil])),
            GL_INDEX_SHIFT => ints([self.pixel.index_shift as i64]),
            GL_INDEX_OFFSET => ints([self.pixel.index_offset as i64]),
            GL_RED_SCALE | GL_GREEN_SCALE | GL_BLUE_SCALE | GL_ALPHA_SCALE => {
                let k = [GL_RED_SCALE, GL_GREEN_SCALE, GL_BLUE_SCALE, GL_ALPHA_SCALE].iter().position(|&e| e == pname)?;
                Some(Value::Floats(vec![self.pixel.scale[k] as f64]))
            }
            GL_RED_BIAS | GL_GREEN_BIAS | GL_BLUE_BIAS | GL_ALPHA_BIAS => {
                let k = [GL_RED_BIAS, GL_GREEN_BIAS, GL_BLUE_BIAS, GL_ALPHA_BIAS].iter().position(|&e| e == pname)?;
                Some(Value::Floats(vec![self.pixel.bias[k] as f64]))
            }
            GL_DEPTH_SCALE => Some(Value::Floats(vec![self.pixel.depth_scale as f64])),
            GL_DEPTH_BIAS => Some(Value::Floats(vec![self.pixel.depth_bias as f64])),
            GL_PIXEL_MAP_I_TO_I_SIZE..=GL_PIXEL_MAP_A_TO_A_SIZE => ints([self.pixel.maps[(pname - GL_PIXEL_MAP_I_TO_I_SIZE) as usize].len() as i64]),
            GL_MAX_PIXEL_MAP_TABLE => ints([super::pixel_transfer::MAX_PIXEL_MAP_TABLE as i64]),
            _ => None,
        }
    }

    /// glGet*v: converts and stores, or INVALID_ENUM.
    ///
    /// # Safety
    /// `out` must be NULL or have room for the query's values.
    pub unsafe fn get_into<T>(&mut self, pname: u32, out: *mut T, conv: impl Fn(&Value) -> Vec<T>) {
        match self.get(pname) {
            Some(v) => {
                if out.is_null() {
                    return;
                }
                for (i, x) in conv(&v).into_iter().enumerate() {
                    out.add(i).write_unaligned(x);
                }
            }
            None => self.set_error(GL_INVALID_ENUM),
        }
    }
}

/// The extensions advertised: those whose functionality GL 1.2-1.5
/// promoted unchanged, implemented by the core entry points (their ARB/EXT
/// names resolve to them through GetProcAddress), plus EXT_vertex_array,
/// ARB_texture_non_power_of_two, ARB_texture_rectangle (and its EXT/NV
/// names), ARB_texture_rg, ARB/EXT_framebuffer_object and
/// EXT_framebuffer_blit (`framebuffer_object`, `blit`), ARB_texture_float, EXT/NV_packed_depth_stencil, EXT_shadow_funcs,
/// ARB/EXT_pixel_buffer_object (`pixel_buffer`), ARB_map_buffer_range (`buffers`), EXT_abgr (`pixel_data`)
/// and the GL 1.2 imaging subset (ARB_imaging, `imaging`). The string ends
/// in a space, as Mesa's does: programs that print it name by name
/// (piglit's glinfo) rely on the separator after the last name.
///
/// ARB_sampler_objects and ARB_texture_storage are implemented
/// (`texture::sampler`, `Context::tex_storage`) but not advertised: their
/// only piglit user in the GL 1.x group, tex-miplevel-selection, then reads
/// GL_SHADING_LANGUAGE_VERSION, NULL in a GL 1.5 context without GLSL, and
/// crashes instead of skipping; and texture storage's own piglit tests
/// still fail on error cases (depth-stencil formats).
const EXTENSIONS: &[u8] = b"GL_ARB_depth_texture GL_ARB_framebuffer_object GL_ARB_imaging GL_ARB_multitexture GL_ARB_map_buffer_range GL_ARB_occlusion_query GL_ARB_pixel_buffer_object GL_ARB_point_parameters \
GL_ARB_shadow GL_ARB_texture_border_clamp GL_ARB_texture_cube_map GL_ARB_texture_env_add GL_ARB_texture_env_combine \
GL_ARB_texture_env_crossbar GL_ARB_texture_env_dot3 GL_ARB_texture_float GL_ARB_texture_mirrored_repeat GL_ARB_texture_non_power_of_two GL_ARB_texture_rectangle GL_ARB_texture_rg GL_ARB_texture_swizzle GL_ARB_transpose_matrix \
GL_ARB_vertex_buffer_object GL_ARB_window_pos GL_EXT_vertex_array GL_EXT_abgr GL_EXT_bgra GL_EXT_blend_color GL_EXT_blend_func_separate \
GL_EXT_blend_minmax GL_EXT_blend_subtract GL_EXT_draw_range_elements GL_EXT_fog_coord GL_EXT_framebuffer_blit GL_EXT_framebuffer_object GL_EXT_multi_draw_arrays \
GL_EXT_packed_depth_stencil GL_EXT_packed_pixels GL_EXT_pixel_buffer_object GL_EXT_rescale_normal GL_EXT_secondary_color GL_EXT_separate_specular_color GL_EXT_shadow_funcs GL_EXT_stencil_wrap \
GL_EXT_texture3D GL_EXT_texture_edge_clamp GL_EXT_texture_env_add GL_EXT_texture_env_combine GL_EXT_texture_lod_bias GL_EXT_texture_rectangle GL_EXT_texture_swizzle \
GL_NV_packed_depth_stencil GL_NV_texture_rectangle GL_SGIS_generate_mipmap GL_SGIS_texture_edge_clamp GL_SGIS_texture_lod \0";

/// glGetString's strings (NUL-terminated, static: the pointers stay valid).
pub fn string(name: u32) -> Option<&'static [u8]> {
    Some(match name {
        GL_VENDOR => b"softgl\0",
        GL_RENDERER => b"softgl (Rust software rasterizer)\0",
        GL_VERSION => concat!("1.5 softgl ", env!("CARGO_PKG_VERSION"), "\0").as_bytes(),
        GL_EXTENSIONS => EXTENSIONS,
        _ => return None,
    })
}
