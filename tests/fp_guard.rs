//! The floating-point environment across the entry points (api/fpenv.rs)
//! in immediate mode: a caller that unmasks exceptions gets its MXCSR
//! back exactly after every call, between glBegin and glEnd too (no
//! sticky flag raised by softgl's arithmetic, no trap), and a primitive
//! begun by a masked caller skips the per-call guard (`fp_trusted`) only
//! until glEnd. The images drawn both ways are the same.
#![cfg(target_arch = "x86_64")]

use softgl::api::table::*;
use softgl::gl::enums::*;
use std::ffi::c_void;

const W: i32 = 37;
const H: i32 = 29;

fn read_mxcsr() -> u32 {
    let mut v: u32 = 0;
    // SAFETY: stmxcsr stores 4 bytes to a valid, aligned local.
    unsafe { core::arch::asm!("stmxcsr [{}]", in(reg) &mut v as *mut u32, options(nostack, preserves_flags)) };
    v
}

fn write_mxcsr(v: u32) {
    // SAFETY: loads 4 bytes from a valid local holding a valid MXCSR.
    unsafe { core::arch::asm!("ldmxcsr [{}]", in(reg) &v as *const u32, options(nostack, preserves_flags)) };
}

/// Delphi's default: invalid, divide-by-zero and overflow unmasked, no
/// flag set.
const UNMASKED: u32 = 0x1900;
/// The C default: everything masked, no flag set.
const MASKED: u32 = 0x1F80;

/// Draws smooth triangles at inexact positions (their set-up divides and
/// rounds: the inexact flag would be raised), calling `check` after each
/// entry point with what it returned to.
unsafe fn draw(mut check: impl FnMut(&str)) {
    // Computed first: the test's own arithmetic raises flags too.
    let data: Vec<[f32; 10]> = (0..40)
        .map(|i| {
            let t = std::hint::black_box(i as f32 * 0.1);
            [0.3 * t % 1.0, 0.7, 1.0 / 3.0, -0.9 + 0.03 * t, -0.8 + 0.01 * t, 0.7 - 0.01 * t, -0.6, 0.1, 0.9 - 0.02 * t, 0.3]
        })
        .collect();
    let clean = read_mxcsr() & 0xFFC0;
    write_mxcsr(clean);
    glClear(GL_COLOR_BUFFER_BIT);
    check("glClear");
    glBegin(GL_TRIANGLES);
    check("glBegin");
    for d in &data {
        glColor3f(d[0], d[1], d[2]);
        check("glColor3f");
        glVertex2f(d[3], d[4]);
        check("glVertex2f");
        glVertex2f(d[5], d[6]);
        check("glVertex2f");
        glVertex3f(d[7], d[8], d[9]);
        check("glVertex3f");
    }
    glEnd();
    check("glEnd");
    glFinish();
    check("glFinish");
}

#[test]
fn unmasking_callers_get_their_environment_back_inside_primitives() {
    unsafe {
        let mut buf = vec![0u8; (W * H * 4) as usize];
        let ctx = OSMesaCreateContextExt(GL_RGBA, 24, 8, 0, std::ptr::null_mut());
        assert!(!ctx.is_null());
        assert_eq!(OSMesaMakeCurrent(ctx, buf.as_mut_ptr() as *mut c_void, GL_UNSIGNED_BYTE, W, H), 1);
        let before = read_mxcsr();

        // A masked caller: the primitive skips the guard; softgl's flags
        // may show, the masks stay.
        write_mxcsr(MASKED);
        let mut trusted = 0;
        draw(|call| {
            assert_eq!(read_mxcsr() & 0x1F80, MASKED, "{call}: masks changed");
            trusted += (*ctx).gl.fp_trusted() as usize;
        });
        assert!(trusted > 100, "a masked caller's primitive is trusted ({trusted} calls)");
        assert!(!(*ctx).gl.fp_trusted(), "not after glEnd");
        let masked_image = buf.clone();
        buf.fill(0);

        // An unmasking caller: every call restores it exactly.
        write_mxcsr(UNMASKED);
        let mut calls = 0;
        draw(|call| {
            let now = read_mxcsr();
            // Put it back before asserting (a failed assertion unwinds).
            write_mxcsr(UNMASKED);
            assert_eq!(now, UNMASKED, "{call} left MXCSR {now:#x}");
            assert!(!(*ctx).gl.fp_trusted(), "{call}: an unmasking caller's primitive is never trusted");
            calls += 1;
        });
        write_mxcsr(before);
        assert!(calls > 100);
        assert!(masked_image.iter().any(|&b| b != 0), "something was drawn");
        assert!(buf == masked_image, "the same image either way");

        // A masked glBegin followed by an unmasking caller inside the
        // primitive is the case given up (fpenv); a new glBegin reads the
        // environment again.
        write_mxcsr(MASKED);
        glBegin(GL_TRIANGLES);
        assert!((*ctx).gl.fp_trusted());
        glEnd();
        write_mxcsr(UNMASKED);
        glBegin(GL_TRIANGLES);
        let trusted = (*ctx).gl.fp_trusted();
        glEnd();
        write_mxcsr(before);
        assert!(!trusted, "each glBegin reads the environment anew");
        OSMesaDestroyContext(ctx);
    }
}
