//! The logical operation (GL 1.5 section 4.1.10): one of sixteen bitwise
//! functions of the fragment's colour s and the stored colour d, on the
//! 8-bit fixed-point values of all four channels at once.

/// glLogicOp's sixteen operations, in GL enum order (GL_CLEAR = 0x1500 ..
/// GL_SET = 0x150F).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum LogicOp {
    Clear,
    And,
    AndReverse,
    Copy,
    AndInverted,
    Noop,
    Xor,
    Or,
    Nor,
    Equiv,
    Invert,
    OrReverse,
    CopyInverted,
    OrInverted,
    Nand,
    Set,
}

impl LogicOp {
    pub const ALL: [LogicOp; 16] = {
        use LogicOp::*;
        [Clear, And, AndReverse, Copy, AndInverted, Noop, Xor, Or, Nor, Equiv, Invert, OrReverse, CopyInverted, OrInverted, Nand, Set]
    };

    pub fn from_gl(e: u32) -> Option<LogicOp> {
        if (0x1500..=0x150F).contains(&e) {
            Some(Self::ALL[(e - 0x1500) as usize])
        } else {
            None
        }
    }

    pub fn to_gl(self) -> u32 {
        0x1500 + self as u32
    }

    /// The operation on packed pixels (any width of bits).
    #[inline(always)]
    pub fn apply(self, s: u32, d: u32) -> u32 {
        use LogicOp::*;
        match self {
            Clear => 0,
            And => s & d,
            AndReverse => s & !d,
            Copy => s,
            AndInverted => !s & d,
            Noop => d,
            Xor => s ^ d,
            Or => s | d,
            Nor => !(s | d),
            Equiv => !(s ^ d),
            Invert => !d,
            OrReverse => s | !d,
            CopyInverted => !s,
            OrInverted => !s | d,
            Nand => !(s & d),
            Set => !0,
        }
    }
}
