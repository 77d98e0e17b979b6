//! Blending (GL 1.5 section 4.1.8, with the ARB_imaging/GL 1.4 additions:
//! glBlendColor's constant factors, glBlendEquation, glBlendFuncSeparate).
//!
//! Source and destination colours are the 8-bit fixed-point values k, taken
//! as the real numbers k/255 (section 2.14.9); the constant colour is the
//! clamped float given to glBlendColor. Factors and the equation are
//! evaluated in f32 and the result is clamped to [0, 1] and rounded to 8
//! bits by [`super::color_to_u8`].
//!
//! Precision: every operand is in [0, 1] and the equation is at most two
//! products and a sum, so the f32 result is within about 4 * 2^-24 of the
//! real-number result. After rounding to the nearest k/255 the stored value
//! is the correctly rounded real result except when the real result lies
//! within that distance of a rounding midpoint (k + 1/2)/255, where it may be
//! the neighbour: always within 1/255 of the real result.

use glam::Vec4;

/// A source or destination blend factor (GL 1.5 tables 4.1 and 4.2).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum BlendFactor {
    Zero,
    One,
    SrcColor,
    OneMinusSrcColor,
    SrcAlpha,
    OneMinusSrcAlpha,
    DstAlpha,
    OneMinusDstAlpha,
    DstColor,
    OneMinusDstColor,
    SrcAlphaSaturate,
    ConstantColor,
    OneMinusConstantColor,
    ConstantAlpha,
    OneMinusConstantAlpha,
}

impl BlendFactor {
    pub const ALL: [BlendFactor; 15] = {
        use BlendFactor::*;
        [
            Zero,
            One,
            SrcColor,
            OneMinusSrcColor,
            SrcAlpha,
            OneMinusSrcAlpha,
            DstAlpha,
            OneMinusDstAlpha,
            DstColor,
            OneMinusDstColor,
            SrcAlphaSaturate,
            ConstantColor,
            OneMinusConstantColor,
            ConstantAlpha,
            OneMinusConstantAlpha,
        ]
    };

    /// From the GL enum. `source` says whether this is a source factor:
    /// GL_SRC_ALPHA_SATURATE is a source factor only (GL 1.5 table 4.2).
    pub fn from_gl(e: u32, source: bool) -> Option<BlendFactor> {
        use BlendFactor::*;
        Some(match e {
            0 => Zero,
            1 => One,
            0x0300..=0x0307 => Self::ALL[(e - 0x0300 + 2) as usize],
            0x0308 if source => SrcAlphaSaturate,
            0x8001 => ConstantColor,
            0x8002 => OneMinusConstantColor,
            0x8003 => ConstantAlpha,
            0x8004 => OneMinusConstantAlpha,
            _ => return None,
        })
    }

    pub fn to_gl(self) -> u32 {
        use BlendFactor::*;
        match self {
            Zero => 0,
            One => 1,
            ConstantColor => 0x8001,
            OneMinusConstantColor => 0x8002,
            ConstantAlpha => 0x8003,
            OneMinusConstantAlpha => 0x8004,
            f => 0x0300 + f as u32 - 2,
        }
    }

    /// The factor for channel `ch` (3 = alpha) given source s, destination
    /// d and constant c, all on [0, 1].
    #[inline(always)]
    fn value(self, ch: usize, s: &[f32; 4], d: &[f32; 4], c: &[f32; 4]) -> f32 {
        use BlendFactor::*;
        match self {
            Zero => 0.0,
            One => 1.0,
            SrcColor => s[ch],
            OneMinusSrcColor => 1.0 - s[ch],
            SrcAlpha => s[3],
            OneMinusSrcAlpha => 1.0 - s[3],
            DstAlpha => d[3],
            OneMinusDstAlpha => 1.0 - d[3],
            DstColor => d[ch],
            OneMinusDstColor => 1.0 - d[ch],
            SrcAlphaSaturate => {
                if ch == 3 {
                    1.0
                } else {
                    s[3].min(1.0 - d[3])
                }
            }
            ConstantColor => c[ch],
            OneMinusConstantColor => 1.0 - c[ch],
            ConstantAlpha => c[3],
            OneMinusConstantAlpha => 1.0 - c[3],
        }
    }
}

/// glBlendEquation's modes.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum BlendEquation {
    Add,
    Subtract,
    ReverseSubtract,
    Min,
    Max,
}

impl BlendEquation {
    pub const ALL: [BlendEquation; 5] = [BlendEquation::Add, BlendEquation::Subtract, BlendEquation::ReverseSubtract, BlendEquation::Min, BlendEquation::Max];

    pub fn from_gl(e: u32) -> Option<BlendEquation> {
        use BlendEquation::*;
        Some(match e {
            0x8006 => Add,
            0x800A => Subtract,
            0x800B => ReverseSubtract,
            0x8007 => Min,
            0x8008 => Max,
            _ => return None,
        })
    }

    pub fn to_gl(self) -> u32 {
        use BlendEquation::*;
        match self {
            Add => 0x8006,
            Subtract => 0x800A,
            ReverseSubtract => 0x800B,
            Min => 0x8007,
            Max => 0x8008,
        }
    }
}

/// The derived blending configuration.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Blend {
    pub equation: BlendEquation,
    pub src_rgb: BlendFactor,
    pub dst_rgb: BlendFactor,
    pub src_alpha: BlendFactor,
    pub dst_alpha: BlendFactor,
    /// glBlendColor, clamped to [0, 1].
    pub constant: [f32; 4],
}

impl Blend {
    /// Is this blend the identity "store the source" (so it can be skipped)?
    pub fn is_replace(&self) -> bool {
        self.equation == BlendEquation::Add
            && self.src_rgb == BlendFactor::One
            && self.src_alpha == BlendFactor::One
            && self.dst_rgb == BlendFactor::Zero
            && self.dst_alpha == BlendFactor::Zero
    }

    /// Blends source `src` with destination `dst`.
    #[inline]
    pub fn apply(&self, src: [u8; 4], dst: [u8; 4]) -> [u8; 4] {
        let s = src.map(|v| v as f32 / 255.0);
        let d = dst.map(|v| v as f32 / 255.0);
        let c = &self.constant;
        let mut r = [0.0f32; 4];
        for ch in 0..4 {
            let (sf, df) = if ch == 3 { (self.src_alpha, self.dst_alpha) } else { (self.src_rgb, self.dst_rgb) };
            r[ch] = match self.equation {
                BlendEquation::Min => s[ch].min(d[ch]),
                BlendEquation::Max => s[ch].max(d[ch]),
                eq => {
                    let a = s[ch] * sf.value(ch, &s, &d, c);
                    let b = d[ch] * df.value(ch, &s, &d, c);
                    match eq {
                        BlendEquation::Add => a + b,
                        BlendEquation::Subtract => a - b,
                        _ => b - a,
                    }
                }
            };
        }
        super::color_to_u8(Vec4::from_array(r))
    }
}
