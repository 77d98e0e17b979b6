//! The floating-point environment across the C ABI.
//!
//! softgl's arithmetic relies on IEEE default behaviour: a 0/0 in an unused
//! SIMD lane, an overflow to infinity in a degenerate matrix or an invalid
//! comparison with NaN must produce a value, not a trap. Rust code (and
//! LLVM's optimizer) assumes floating-point exceptions are masked. Programs
//! do not always run that way: Delphi and Free Pascal unmask the invalid,
//! divide-by-zero and overflow exceptions by default, and the book programs
//! are Delphi programs. So every entry point masks all floating-point
//! exceptions for its duration and puts the caller's environment back,
//! exactly, on the way out (so flags raised inside softgl do not leak into
//! the caller's sticky status either).
//!
//! Cost: one `stmxcsr` per call when the caller already masks everything
//! (the C default); a load and a restore only for callers that unmask.
//! `stmxcsr` reads the sticky flags, so it waits for the floating-point
//! work in flight (the previous vertex's transform and triangle setup):
//! in immediate mode that wait was about a seventh of the time. So
//! between glBegin and glEnd the environment is read once: a primitive
//! begun by a caller that masked every exception (`Context::fp_trusted`)
//! runs its vertex commands without the guard, up to and including
//! glEnd. The one case this gives up is a caller that unmasks exceptions
//! between glBegin and glEnd: its vertex commands may then trap.
//! Callbacks into the program (GLU tessellator, NURBS) run with the masked
//! environment, which only means they cannot trap.
//!
//! On 32-bit x86 the x87 control word is saved and masked as well, since
//! C library maths may still use the x87 unit there.

/// Restores the caller's floating-point environment when dropped.
pub struct FpGuard {
    #[cfg(any(target_arch = "x86_64", target_arch = "x86"))]
    saved_mxcsr: Option<u32>,
    #[cfg(target_arch = "x86")]
    saved_x87: Option<u16>,
}

/// MXCSR bits 7..12: the six exception masks.
#[cfg(any(target_arch = "x86_64", target_arch = "x86"))]
const MXCSR_MASKS: u32 = 0x3F << 7;
/// x87 control word bits 0..5: the six exception masks.
#[cfg(target_arch = "x86")]
const X87_MASKS: u16 = 0x3F;

#[cfg(any(target_arch = "x86_64", target_arch = "x86"))]
#[inline(always)]
fn read_mxcsr() -> u32 {
    let mut v: u32 = 0;
    // SAFETY: stmxcsr stores 4 bytes to a valid, aligned local.
    unsafe { core::arch::asm!("stmxcsr [{}]", in(reg) &mut v as *mut u32, options(nostack, preserves_flags)) };
    v
}

#[cfg(any(target_arch = "x86_64", target_arch = "x86"))]
#[inline(always)]
fn write_mxcsr(v: u32) {
    // SAFETY: loads 4 bytes from a valid local; every value we write is
    // one read from the register, or one with only mask bits added.
    unsafe { core::arch::asm!("ldmxcsr [{}]", in(reg) &v as *const u32, options(nostack, preserves_flags)) };
}

impl FpGuard {
    /// Masks every floating-point exception until the guard is dropped.
    #[inline(always)]
    pub fn enter() -> FpGuard {
        #[cfg(any(target_arch = "x86_64", target_arch = "x86"))]
        let saved_mxcsr = {
            let m = read_mxcsr();
            if m & MXCSR_MASKS != MXCSR_MASKS {
                write_mxcsr(m | MXCSR_MASKS);
                Some(m)
            } else {
                None
            }
        };
        #[cfg(target_arch = "x86")]
        let saved_x87 = {
            let mut cw: u16 = 0;
            // SAFETY: fnstcw/fldcw on a valid local.
            unsafe { core::arch::asm!("fnstcw [{}]", in(reg) &mut cw as *mut u16, options(nostack, preserves_flags)) };
            if cw & X87_MASKS != X87_MASKS {
                let masked = cw | X87_MASKS;
                unsafe { core::arch::asm!("fldcw [{}]", in(reg) &masked as *const u16, options(nostack, preserves_flags)) };
                Some(cw)
            } else {
                None
            }
        };
        FpGuard {
            #[cfg(any(target_arch = "x86_64", target_arch = "x86"))]
            saved_mxcsr,
            #[cfg(target_arch = "x86")]
            saved_x87,
        }
    }
}

impl FpGuard {
    /// Did the caller mask every exception already (nothing to restore)?
    #[inline(always)]
    pub fn caller_masked(&self) -> bool {
        #[cfg(any(target_arch = "x86_64", target_arch = "x86"))]
        let m = self.saved_mxcsr.is_none();
        #[cfg(not(any(target_arch = "x86_64", target_arch = "x86")))]
        let m = true;
        #[cfg(target_arch = "x86")]
        let m = m && self.saved_x87.is_none();
        m
    }
}

impl Drop for FpGuard {
    #[inline(always)]
    fn drop(&mut self) {
        #[cfg(any(target_arch = "x86_64", target_arch = "x86"))]
        if let Some(m) = self.saved_mxcsr {
            // The caller's masks and its own sticky flags, as they were:
            // SSE does not trap on flags already set, only on new ones.
            write_mxcsr(m);
        }
        #[cfg(target_arch = "x86")]
        if let Some(cw) = self.saved_x87 {
            // Clear what softgl raised first: the x87 would otherwise trap
            // at the caller's next instruction on a now-unmasked flag.
            unsafe { core::arch::asm!("fnclex", "fldcw [{}]", in(reg) &cw as *const u16, options(nostack)) };
        }
    }
}

#[cfg(all(test, target_arch = "x86_64"))]
mod tests {
    use super::*;

    #[test]
    fn masks_inside_and_restores_exactly() {
        let before = read_mxcsr();
        // A caller that unmasks invalid, divide-by-zero and overflow, as
        // Delphi does (MXCSR 0x1900).
        write_mxcsr(0x1900);
        {
            let _g = FpGuard::enter();
            assert_eq!(read_mxcsr() & MXCSR_MASKS, MXCSR_MASKS);
            let z = std::hint::black_box(0.0f32);
            // Would trap (SIGFPE) without the guard.
            let nan = std::hint::black_box(z / z);
            assert!(nan.is_nan());
        }
        assert_eq!(read_mxcsr(), 0x1900, "caller's environment restored exactly");
        write_mxcsr(before);
    }

    #[test]
    fn masked_callers_are_left_alone() {
        let before = read_mxcsr();
        assert_eq!(before & MXCSR_MASKS, MXCSR_MASKS);
        let g = FpGuard::enter();
        assert!(g.saved_mxcsr.is_none());
        drop(g);
        assert_eq!(read_mxcsr(), before);
    }
}
