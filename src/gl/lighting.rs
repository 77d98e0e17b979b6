//! Lighting state and commands (GL 1.5 section 2.14): glLight, glLightModel,
//! glMaterial, glColorMaterial, the current normal, and their queries.
//! The lighting equation itself is `render::light`, evaluated per vertex.
//!
//! Positions and spot directions are transformed to eye coordinates by the
//! modelview matrix current when glLight is called (2.14.2), and stored so.

use super::context::Context;
use super::enums::*;
use super::validate::DIRTY_LIGHTING;
use glam::{Vec3, Vec4};

pub const MAX_LIGHTS: usize = 8;

#[derive(Clone, Debug, PartialEq)]
pub struct Light {
    pub enabled: bool,
    pub ambient: Vec4,
    pub diffuse: Vec4,
    pub specular: Vec4,
    /// Eye coordinates; w = 0 for a directional light.
    pub position: Vec4,
    /// Eye coordinates.
    pub spot_direction: Vec3,
    pub spot_exponent: f32,
    pub spot_cutoff: f32,
    /// Constant, linear, quadratic.
    pub attenuation: [f32; 3],
}

impl Light {
    fn new(i: usize) -> Light {
        let on = if i == 0 { Vec4::ONE } else { Vec4::new(0.0, 0.0, 0.0, 1.0) };
        Light {
            enabled: false,
            ambient: Vec4::new(0.0, 0.0, 0.0, 1.0),
            diffuse: on,
            specular: on,
            position: Vec4::new(0.0, 0.0, 1.0, 0.0),
            spot_direction: Vec3::new(0.0, 0.0, -1.0),
            spot_exponent: 0.0,
            spot_cutoff: 180.0,
            attenuation: [1.0, 0.0, 0.0],
        }
    }
}

#[derive(Clone, Debug, PartialEq)]
pub struct Material {
    pub ambient: Vec4,
    pub diffuse: Vec4,
    pub specular: Vec4,
    pub emission: Vec4,
    pub shininess: f32,
}

impl Default for Material {
    fn default() -> Self {
        Material {
            ambient: Vec4::new(0.2, 0.2, 0.2, 1.0),
            diffuse: Vec4::new(0.8, 0.8, 0.8, 1.0),
            specular: Vec4::new(0.0, 0.0, 0.0, 1.0),
            emission: Vec4::new(0.0, 0.0, 0.0, 1.0),
            shininess: 0.0,
        }
    }
}

/// GL_LIGHTING_BIT state (and GL_NORMALIZE / GL_RESCALE_NORMAL from the
/// transform group, which only lighting uses).
#[derive(Clone, Debug)]
pub struct LightingState {
    pub enabled: bool,
    pub lights: [Light; MAX_LIGHTS],
    pub model_ambient: Vec4,
    pub local_viewer: bool,
    pub two_side: bool,
    pub separate_specular: bool,
    /// Front and back.
    pub materials: [Material; 2],
    pub color_material: bool,
    pub color_material_face: u32,
    pub color_material_mode: u32,
    pub normalize: bool,
    pub rescale_normal: bool,
}

impl Default for LightingState {
    fn default() -> Self {
        LightingState {
            enabled: false,
            lights: std::array::from_fn(Light::new),
            model_ambient: Vec4::new(0.2, 0.2, 0.2, 1.0),
            local_viewer: false,
            two_side: false,
            separate_specular: false,
            materials: [Material::default(), Material::default()],
            color_material: false,
            color_material_face: GL_FRONT_AND_BACK,
            color_material_mode: GL_AMBIENT_AND_DIFFUSE,
            normalize: false,
            rescale_normal: false,
        }
    }
}

/// Which materials a face enum selects.
fn faces(face: u32) -> Option<&'static [usize]> {
    match face {
        GL_FRONT => Some(&[0]),
        GL_BACK => Some(&[1]),
        GL_FRONT_AND_BACK => Some(&[0, 1]),
        _ => None,
    }
}

impl Context {
    /// glLight{f,i}[v]: `v` holds the parameter's 1 or 4 values.
    pub fn light(&mut self, light: u32, pname: u32, v: [f32; 4]) {
        let i = light.wrapping_sub(GL_LIGHT0) as usize;
        if i >= MAX_LIGHTS {
            return self.set_error(GL_INVALID_ENUM);
        }
        let mv = self.transform.modelview.top().as_mat4();
        let l = &mut self.lighting.lights[i];
        match pname {
            GL_AMBIENT => l.ambient = Vec4::from_array(v),
            GL_DIFFUSE => l.diffuse = Vec4::from_array(v),
            GL_SPECULAR => l.specular = Vec4::from_array(v),
            GL_POSITION => l.position = mv * Vec4::from_array(v),
            GL_SPOT_DIRECTION => l.spot_direction = glam::Mat3::from_mat4(mv) * Vec3::new(v[0], v[1], v[2]),
            GL_SPOT_EXPONENT if (0.0..=128.0).contains(&v[0]) => l.spot_exponent = v[0],
            GL_SPOT_CUTOFF if (0.0..=90.0).contains(&v[0]) || v[0] == 180.0 => l.spot_cutoff = v[0],
            GL_CONSTANT_ATTENUATION | GL_LINEAR_ATTENUATION | GL_QUADRATIC_ATTENUATION if v[0] >= 0.0 => {
                l.attenuation[(pname - GL_CONSTANT_ATTENUATION) as usize] = v[0]
            }
            GL_SPOT_EXPONENT | GL_SPOT_CUTOFF | GL_CONSTANT_ATTENUATION | GL_LINEAR_ATTENUATION | GL_QUADRATIC_ATTENUATION => {
                return self.set_error(GL_INVALID_VALUE)
            }
            _ => return self.set_error(GL_INVALID_ENUM),
        }
        self.dirty |= DIRTY_LIGHTING;
    }

    pub fn light_model(&mut self, pname: u32, v: [f32; 4]) {
        let s = &mut self.lighting;
        match pname {
            GL_LIGHT_MODEL_AMBIENT => s.model_ambient = Vec4::from_array(v),
            GL_LIGHT_MODEL_LOCAL_VIEWER => s.local_viewer = v[0] != 0.0,
            GL_LIGHT_MODEL_TWO_SIDE => s.two_side = v[0] != 0.0,
            GL_LIGHT_MODEL_COLOR_CONTROL => match v[0] as u32 {
                GL_SINGLE_COLOR => s.separate_specular = false,
                GL_SEPARATE_SPECULAR_COLOR => s.separate_specular = true,
                _ => return self.set_error(GL_INVALID_ENUM),
            },
            _ => return self.set_error(GL_INVALID_ENUM),
        }
        self.dirty |= DIRTY_LIGHTING;
    }

    /// glMaterial{f,i}[v] (allowed between Begin and End).
    pub fn material(&mut self, face: u32, pname: u32, v: [f32; 4]) {
        let Some(fs) = faces(face) else { return self.set_error(GL_INVALID_ENUM) };
        if pname == GL_SHININESS && !(0.0..=128.0).contains(&v[0]) {
            return self.set_error(GL_INVALID_VALUE);
        }
        // Vertices queued for lighting take the material as it was.
        self.flush_lit_vertices();
        if !self.set_material(fs, pname, v) {
            return self.set_error(GL_INVALID_ENUM);
        }
        // Properties GL_COLOR_MATERIAL tracks keep following the current
        // colour (2.14.3): a glMaterial of one of them is overridden at
        // once, as implementations (and piglit's dlist-color-material) do.
        self.apply_color_material();
    }

    /// Stores a material property for the given faces; false (and nothing
    /// stored) for an unknown name.
    fn set_material(&mut self, fs: &[usize], pname: u32, v: [f32; 4]) -> bool {
        if !matches!(pname, GL_AMBIENT | GL_DIFFUSE | GL_SPECULAR | GL_EMISSION | GL_SHININESS | GL_AMBIENT_AND_DIFFUSE | GL_COLOR_INDEXES) {
            return false;
        }
        let c = Vec4::from_array(v);
        for &f in fs {
            let m = &mut self.lighting.materials[f];
            match pname {
                GL_AMBIENT => m.ambient = c,
                GL_DIFFUSE => m.diffuse = c,
                GL_SPECULAR => m.specular = c,
                GL_EMISSION => m.emission = c,
                GL_SHININESS => m.shininess = v[0],
                GL_AMBIENT_AND_DIFFUSE => {
                    m.ambient = c;
                    m.diffuse = c;
                }
                _ => {} // GL_COLOR_INDEXES: colour-index lighting, no effect in RGBA
            }
        }
        true
    }

    pub fn color_material(&mut self, face: u32, mode: u32) {
        if faces(face).is_none() || !matches!(mode, GL_EMISSION | GL_AMBIENT | GL_DIFFUSE | GL_SPECULAR | GL_AMBIENT_AND_DIFFUSE) {
            return self.set_error(GL_INVALID_ENUM);
        }
        self.flush_lit_vertices();
        self.lighting.color_material_face = face;
        self.lighting.color_material_mode = mode;
        self.apply_color_material();
    }

    /// With GL_COLOR_MATERIAL on, the current colour is the tracked material
    /// property (2.14.3): called on glColor, glColorMaterial and the enable.
    pub fn apply_color_material(&mut self) {
        if !self.lighting.color_material {
            return;
        }
        let (face, mode) = (self.lighting.color_material_face, self.lighting.color_material_mode);
        // Face and mode were validated by glColorMaterial.
        if let Some(fs) = faces(face) {
            self.set_material(fs, mode, self.current.color);
        }
    }

    /// glGetLight{f,i}v values (positions and directions in eye coordinates).
    pub fn get_light(&self, light: u32, pname: u32) -> Option<Vec<f32>> {
        let l = self.lighting.lights.get(light.wrapping_sub(GL_LIGHT0) as usize)?;
        Some(match pname {
            GL_AMBIENT => l.ambient.to_array().to_vec(),
            GL_DIFFUSE => l.diffuse.to_array().to_vec(),
            GL_SPECULAR => l.specular.to_array().to_vec(),
            GL_POSITION => l.position.to_array().to_vec(),
            GL_SPOT_DIRECTION => l.spot_direction.to_array().to_vec(),
            GL_SPOT_EXPONENT => vec![l.spot_exponent],
            GL_SPOT_CUTOFF => vec![l.spot_cutoff],
            GL_CONSTANT_ATTENUATION | GL_LINEAR_ATTENUATION | GL_QUADRATIC_ATTENUATION => {
                vec![l.attenuation[(pname - GL_CONSTANT_ATTENUATION) as usize]]
            }
            _ => return None,
        })
    }

    /// glGetMaterial{f,i}v values; face is GL_FRONT or GL_BACK.
    pub fn get_material(&self, face: u32, pname: u32) -> Option<Vec<f32>> {
        let m = match face {
            GL_FRONT => &self.lighting.materials[0],
            GL_BACK => &self.lighting.materials[1],
            _ => return None,
        };
        Some(match pname {
            GL_AMBIENT => m.ambient.to_array().to_vec(),
            GL_DIFFUSE => m.diffuse.to_array().to_vec(),
            GL_SPECULAR => m.specular.to_array().to_vec(),
            GL_EMISSION => m.emission.to_array().to_vec(),
            GL_SHININESS => vec![m.shininess],
            GL_COLOR_INDEXES => vec![0.0, 1.0, 1.0],
            _ => return None,
        })
    }
}

/// How many values glLight*v reads for `pname` (0: not a light parameter).
pub fn light_param_count(pname: u32) -> usize {
    match pname {
        GL_AMBIENT | GL_DIFFUSE | GL_SPECULAR | GL_POSITION => 4,
        GL_SPOT_DIRECTION => 3,
        GL_SPOT_EXPONENT | GL_SPOT_CUTOFF | GL_CONSTANT_ATTENUATION | GL_LINEAR_ATTENUATION | GL_QUADRATIC_ATTENUATION => 1,
        _ => 0,
    }
}

/// How many values glMaterial*v reads for `pname`.
pub fn material_param_count(pname: u32) -> usize {
    match pname {
        GL_AMBIENT | GL_DIFFUSE | GL_SPECULAR | GL_EMISSION | GL_AMBIENT_AND_DIFFUSE => 4,
        GL_COLOR_INDEXES => 3,
        GL_SHININESS => 1,
        _ => 0,
    }
}

/// How many values glLightModel*v reads for `pname`.
pub fn light_model_param_count(pname: u32) -> usize {
    match pname {
        GL_LIGHT_MODEL_AMBIENT => 4,
        GL_LIGHT_MODEL_LOCAL_VIEWER | GL_LIGHT_MODEL_TWO_SIDE | GL_LIGHT_MODEL_COLOR_CONTROL => 1,
        _ => 0,
    }
}

/// Is `pname`'s value a colour (integer forms map it like glColor, 2.14.2)?
pub fn is_color_param(pname: u32) -> bool {
    matches!(pname, GL_AMBIENT | GL_DIFFUSE | GL_SPECULAR | GL_EMISSION | GL_AMBIENT_AND_DIFFUSE | GL_LIGHT_MODEL_AMBIENT)
}

/// Reads a parameter array for the *v forms: `count` values from `p`,
/// integers converted as colours or plainly, padded to 4. None for a NULL
/// pointer.
///
/// # Safety
/// `p` must be NULL or point to `count` values.
pub unsafe fn read_params<T: crate::api::args::Component>(p: *const T, count: usize, pname: u32) -> Option<[f32; 4]> {
    if p.is_null() {
        return None;
    }
    let mut out = [0.0f32; 4];
    for (i, o) in out.iter_mut().enumerate().take(count.min(4)) {
        let v = std::ptr::read_unaligned(p.add(i));
        *o = if is_color_param(pname) { v.normalized() } else { v.plain() };
    }
    Some(out)
}
