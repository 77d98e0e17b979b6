//! The stencil test (GL 1.5 section 4.1.5): `(ref & mask) func (s & mask)`,
//! and glStencilOp's eight operations on stencil fail, depth fail and depth
//! pass, written through the stencil write mask.
//!
//! Invariants of [`StencilTest`] (established by validation): `reference`
//! is already clamped to [0, max] and `max = 2^bits - 1` of the stencil
//! buffer; `masked_ref = reference & value_mask`; `write_mask <= max`.

use super::CompareFunc;

/// One of glStencilOp's operations.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum StencilOp {
    Keep,
    Zero,
    Replace,
    Incr,
    Decr,
    Invert,
    IncrWrap,
    DecrWrap,
}

impl StencilOp {
    pub fn from_gl(e: u32) -> Option<StencilOp> {
        use StencilOp::*;
        Some(match e {
            0x1E00 => Keep,
            0 => Zero,
            0x1E01 => Replace,
            0x1E02 => Incr,
            0x1E03 => Decr,
            0x150A => Invert,
            0x8507 => IncrWrap,
            0x8508 => DecrWrap,
            _ => return None,
        })
    }

    pub fn to_gl(self) -> u32 {
        use StencilOp::*;
        match self {
            Keep => 0x1E00,
            Zero => 0,
            Replace => 0x1E01,
            Incr => 0x1E02,
            Decr => 0x1E03,
            Invert => 0x150A,
            IncrWrap => 0x8507,
            DecrWrap => 0x8508,
        }
    }
}

/// The derived stencil configuration the fragment loop reads.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct StencilTest {
    pub func: CompareFunc,
    /// The reference clamped to [0, max].
    pub reference: u8,
    pub masked_ref: u8,
    pub value_mask: u8,
    pub write_mask: u8,
    /// Largest stencil value, 2^bits - 1.
    pub max: u8,
    pub fail: StencilOp,
    pub zfail: StencilOp,
    pub zpass: StencilOp,
}

impl StencilTest {
    /// Does a fragment pass against the stored value `s`?
    #[inline(always)]
    pub fn test(&self, s: u8) -> bool {
        self.func.test(self.masked_ref, s & self.value_mask)
    }

    /// The new stored value after `op` on `s`, through the write mask.
    #[inline(always)]
    pub fn apply(&self, op: StencilOp, s: u8) -> u8 {
        let max = self.max;
        let v = match op {
            StencilOp::Keep => return s,
            StencilOp::Zero => 0,
            StencilOp::Replace => self.reference,
            StencilOp::Incr => if s >= max { max } else { s + 1 },
            StencilOp::Decr => s.saturating_sub(1),
            StencilOp::Invert => !s & max,
            StencilOp::IncrWrap => s.wrapping_add(1) & max,
            StencilOp::DecrWrap => s.wrapping_sub(1) & max,
        };
        (s & !self.write_mask) | (v & self.write_mask)
    }

    /// Can this configuration ever change the stencil buffer?
    pub fn writes(&self) -> bool {
        self.write_mask != 0 && [self.fail, self.zfail, self.zpass].iter().any(|&o| o != StencilOp::Keep)
    }
}
