//! Sampler objects (ARB_sampler_objects): the sampling state of texture
//! parameters (wraps, filters, border colour, LOD range and bias, depth
//! comparison) held apart from any texture and bound per texture unit.
//! A unit with a sampler bound samples its texture with the sampler's
//! state in place of the texture's own (completeness follows the
//! sampler's minification filter); BASE_LEVEL, MAX_LEVEL and
//! DEPTH_TEXTURE_MODE stay the texture's. Sampler objects are shared
//! within a share group (`gl::share`); unit bindings are per context.

use super::enums::*;
use crate::gl::context::Context;
use crate::gl::enums::{GL_INVALID_ENUM, GL_INVALID_OPERATION, GL_INVALID_VALUE};
use crate::gl::get::Value;
use crate::render::fragment::CompareFunc;
use crate::render::texture::{Filter, Params, Wrap, MAX_UNITS};

fn wrap_of(e: u32) -> Option<Wrap> {
    Some(match e {
        GL_REPEAT => Wrap::Repeat,
        GL_CLAMP => Wrap::Clamp,
        GL_CLAMP_TO_EDGE => Wrap::ClampToEdge,
        GL_CLAMP_TO_BORDER => Wrap::ClampToBorder,
        GL_MIRRORED_REPEAT => Wrap::MirroredRepeat,
        _ => return None,
    })
}

/// The sampling state that glTexParameter and glSamplerParameter share
/// (wraps, filters, border colour, LOD range and bias, depth comparison):
/// None when `pname` is not one of it, else whether the value was valid
/// (and applied). Values come as floats (enums are exact in f32).
pub(super) fn set_sampling(p: &mut Params, pname: u32, v: [f32; 4]) -> Option<bool> {
    let e = v[0] as u32;
    Some(match pname {
        GL_TEXTURE_WRAP_S | GL_TEXTURE_WRAP_T | GL_TEXTURE_WRAP_R => wrap_of(e).map(|w| p.wrap[(pname - GL_TEXTURE_WRAP_S).min(2) as usize] = w).is_some(),
        GL_TEXTURE_MIN_FILTER => filter_of(e).map(|f| p.min_filter = f).is_some(),
        GL_TEXTURE_MAG_FILTER => filter_of(e).filter(|f| !f.is_mipmap()).map(|f| p.mag_filter = f).is_some(),
        GL_TEXTURE_BORDER_COLOR => {
            p.border_color = v.map(|c| c.clamp(0.0, 1.0));
            true
        }
        GL_TEXTURE_MIN_LOD => {
            p.min_lod = v[0];
            true
        }
        GL_TEXTURE_MAX_LOD => {
            p.max_lod = v[0];
            true
        }
        GL_TEXTURE_LOD_BIAS => {
            p.lod_bias = v[0];
            true
        }
        GL_TEXTURE_COMPARE_MODE => match e {
            GL_NONE | GL_COMPARE_R_TO_TEXTURE => {
                p.compare_mode = e == GL_COMPARE_R_TO_TEXTURE;
                true
            }
            _ => false,
        },
        GL_TEXTURE_COMPARE_FUNC => CompareFunc::from_gl(e).map(|f| p.compare_func = f).is_some(),
        _ => return None,
    })
}

fn wrap_enum(w: Wrap) -> u32 {
    match w {
        Wrap::Repeat => GL_REPEAT,
        Wrap::Clamp => GL_CLAMP,
        Wrap::ClampToEdge => GL_CLAMP_TO_EDGE,
        Wrap::ClampToBorder => GL_CLAMP_TO_BORDER,
        Wrap::MirroredRepeat => GL_MIRRORED_REPEAT,
    }
}

fn filter_of(e: u32) -> Option<Filter> {
    Some(match e {
        GL_NEAREST => Filter::Nearest,
        GL_LINEAR => Filter::Linear,
        GL_NEAREST_MIPMAP_NEAREST => Filter::NearestMipmapNearest,
        GL_LINEAR_MIPMAP_NEAREST => Filter::LinearMipmapNearest,
        GL_NEAREST_MIPMAP_LINEAR => Filter::NearestMipmapLinear,
        GL_LINEAR_MIPMAP_LINEAR => Filter::LinearMipmapLinear,
        _ => return None,
    })
}

fn filter_enum(f: Filter) -> u32 {
    match f {
        Filter::Nearest => GL_NEAREST,
        Filter::Linear => GL_LINEAR,
        Filter::NearestMipmapNearest => GL_NEAREST_MIPMAP_NEAREST,
        Filter::LinearMipmapNearest => GL_LINEAR_MIPMAP_NEAREST,
        Filter::NearestMipmapLinear => GL_NEAREST_MIPMAP_LINEAR,
        Filter::LinearMipmapLinear => GL_LINEAR_MIPMAP_LINEAR,
    }
}

/// The sampler-object state of a context.
#[derive(Clone, Debug, Default)]
pub struct Samplers {
    pub objects: std::collections::HashMap<u32, Params>,
    /// The sampler bound to each unit (0: none).
    pub bound: [u32; MAX_UNITS],
    /// Where glGenSamplers' search starts (`gl::names`).
    next: u32,
}

/// A share group's sampler objects.
#[derive(Default)]
pub struct SharedSamplers {
    objects: std::collections::HashMap<u32, Params>,
}

impl Samplers {
    /// Exchanges this context's sampler objects with a share group's
    /// (names come from a per-context counter that skips names in use, so
    /// contexts of a group never hand out the same one).
    pub fn swap_objects(&mut self, t: &mut SharedSamplers) {
        std::mem::swap(&mut self.objects, &mut t.objects);
    }
}

/// Overrides a texture's parameters with a sampler's.
pub fn apply(tex: &Params, s: &Params) -> Params {
    Params {
        wrap: s.wrap,
        min_filter: s.min_filter,
        mag_filter: s.mag_filter,
        border_color: s.border_color,
        min_lod: s.min_lod,
        max_lod: s.max_lod,
        lod_bias: s.lod_bias,
        compare_mode: s.compare_mode,
        compare_func: s.compare_func,
        ..tex.clone()
    }
}

impl Context {
    pub fn gen_samplers(&mut self, n: i32) -> Option<Vec<u32>> {
        if n < 0 {
            self.set_error(GL_INVALID_VALUE);
            return None;
        }
        // Samplers exist from glGenSamplers on (unlike textures).
        let s = &mut self.samplers;
        let mut out = Vec::with_capacity((n as usize).min(1 << 12));
        while out.len() < n as usize {
            let objects = &s.objects;
            let Some(k) = crate::gl::names::next_free(&mut s.next, |k| !objects.contains_key(&k)) else { break };
            s.objects.insert(k, Params::default());
            out.push(k);
        }
        Some(out)
    }

    pub fn delete_samplers(&mut self, names: &[u32]) {
        for &n in names {
            if n != 0 && self.samplers.objects.remove(&n).is_some() {
                for b in self.samplers.bound.iter_mut() {
                    if *b == n {
                        *b = 0;
                    }
                }
                self.dirty |= crate::gl::validate::DIRTY_TEXTURE;
            }
        }
    }

    /// SAMPLER_BINDING: the active unit's sampler.
    pub fn sampler_get(&self, pname: u32) -> Option<Value> {
        (pname == 0x8919).then(|| Value::Ints(vec![self.samplers.bound[self.texture.active] as i64]))
    }

    pub fn is_sampler(&self, n: u32) -> bool {
        n != 0 && self.samplers.objects.contains_key(&n)
    }

    pub fn bind_sampler(&mut self, unit: u32, sampler: u32) {
        if unit as usize >= MAX_UNITS {
            return self.set_error(GL_INVALID_VALUE);
        }
        if sampler != 0 && !self.samplers.objects.contains_key(&sampler) {
            return self.set_error(GL_INVALID_OPERATION);
        }
        self.samplers.bound[unit as usize] = sampler;
        self.dirty |= crate::gl::validate::DIRTY_TEXTURE;
    }

    /// glSamplerParameter*: values as floats (enums are exact in f32).
    pub fn sampler_parameter(&mut self, sampler: u32, pname: u32, v: [f32; 4]) {
        let Some(p) = self.samplers.objects.get_mut(&sampler) else { return self.set_error(GL_INVALID_OPERATION) };
        let ok = set_sampling(p, pname, v).unwrap_or(false);
        if !ok {
            return self.set_error(GL_INVALID_ENUM);
        }
        self.dirty |= crate::gl::validate::DIRTY_TEXTURE;
    }

    pub fn get_sampler_parameter(&mut self, sampler: u32, pname: u32) -> Option<Value> {
        let Some(p) = self.samplers.objects.get(&sampler) else {
            self.set_error(GL_INVALID_OPERATION);
            return None;
        };
        let i = |x: u32| Value::Ints(vec![x as i64]);
        Some(match pname {
            GL_TEXTURE_WRAP_S | GL_TEXTURE_WRAP_T | GL_TEXTURE_WRAP_R => i(wrap_enum(p.wrap[(pname - GL_TEXTURE_WRAP_S).min(2) as usize])),
            GL_TEXTURE_MIN_FILTER => i(filter_enum(p.min_filter)),
            GL_TEXTURE_MAG_FILTER => i(filter_enum(p.mag_filter)),
            GL_TEXTURE_BORDER_COLOR => Value::Normalized(p.border_color.iter().map(|&c| c as f64).collect()),
            GL_TEXTURE_MIN_LOD => Value::Floats(vec![p.min_lod as f64]),
            GL_TEXTURE_MAX_LOD => Value::Floats(vec![p.max_lod as f64]),
            GL_TEXTURE_LOD_BIAS => Value::Floats(vec![p.lod_bias as f64]),
            GL_TEXTURE_COMPARE_MODE => i(if p.compare_mode { GL_COMPARE_R_TO_TEXTURE } else { GL_NONE }),
            GL_TEXTURE_COMPARE_FUNC => i(p.compare_func.to_gl()),
            _ => {
                self.set_error(GL_INVALID_ENUM);
                return None;
            }
        })
    }
}
