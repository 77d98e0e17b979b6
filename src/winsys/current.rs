//! The per-thread current context (GL 1.5 spec, section 2.1: commands act on
//! the context current in the calling thread).
//!
//! Every entry point reads it, so the read is on immediate mode's hot path.
//! A Rust `thread_local!` in a shared library uses the general-dynamic TLS
//! model: each read calls `__tls_get_addr` (about 11 instructions plus the
//! call). On x86-64 Linux the pointer lives instead in an initial-exec TLS
//! slot declared in assembly (stable Rust cannot ask for the model):
//! a read is two loads, the slot's offset from the GOT and the value at
//! that offset from `%fs`. Initial-exec TLS in a library is what Mesa's
//! libGL does too: the dynamic loader places the 8 bytes in the static TLS
//! block, from its reserve when the library is dlopen'ed. Elsewhere
//! (Windows, 32-bit) the `thread_local!` stays.

use crate::gl::Context;

#[cfg(all(target_arch = "x86_64", target_os = "linux"))]
mod slot {
    use crate::gl::Context;

    // One 8-byte, zero-initialised thread-local variable. Global (hidden,
    // so never exported or interposed) because the reads below are in
    // other codegen units of the crate.
    core::arch::global_asm!(
        ".pushsection .tbss,\"awT\",@nobits",
        ".p2align 3",
        ".globl softgl_current_context",
        ".hidden softgl_current_context",
        ".type softgl_current_context, @object",
        ".size softgl_current_context, 8",
        "softgl_current_context:",
        ".zero 8",
        ".popsection",
    );

    #[inline(always)]
    pub fn get() -> *mut Context {
        let p: *mut Context;
        // SAFETY: reads this thread's 8-byte slot (initial-exec access:
        // the GOT holds its offset from the thread pointer in %fs).
        unsafe {
            core::arch::asm!(
                "mov {p}, qword ptr [rip + softgl_current_context@GOTTPOFF]",
                "mov {p}, qword ptr fs:[{p}]",
                p = out(reg) p,
                options(nostack, preserves_flags, readonly, pure),
            )
        };
        p
    }

    pub fn set(ctx: *mut Context) {
        // SAFETY: writes this thread's 8-byte slot.
        unsafe {
            core::arch::asm!(
                "mov {t}, qword ptr [rip + softgl_current_context@GOTTPOFF]",
                "mov qword ptr fs:[{t}], {v}",
                t = out(reg) _,
                v = in(reg) ctx,
                options(nostack, preserves_flags),
            )
        };
    }
}

#[cfg(not(all(target_arch = "x86_64", target_os = "linux")))]
mod slot {
    use crate::gl::Context;
    use std::cell::Cell;
    use std::ptr::null_mut;

    thread_local! {
        static CURRENT: Cell<*mut Context> = const { Cell::new(null_mut()) };
    }

    #[inline(always)]
    pub fn get() -> *mut Context {
        CURRENT.with(|c| c.get())
    }

    pub fn set(ctx: *mut Context) {
        CURRENT.with(|c| c.set(ctx));
    }
}

/// The calling thread's current context, or null.
#[inline(always)]
pub fn current() -> *mut Context {
    slot::get()
}

pub fn set_current(ctx: *mut Context) {
    slot::set(ctx);
    if !ctx.is_null() {
        // Round 11: the rasterizer's workers start with the first current
        // context, not at the first large clear or batch, so the
        // scheduler has placed them on a core before frame 0.
        crate::render::pool::warm(crate::render::tile::threads_default());
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Each thread sees its own slot: null at start, its own value after
    /// setting, unaffected by another thread's.
    #[test]
    fn current_is_per_thread() {
        let a = 0x1000 as *mut Context;
        let b = 0x2000usize;
        let saved = current();
        set_current(a);
        let other = std::thread::spawn(move || {
            let before = current() as usize;
            set_current(b as *mut Context);
            (before, current() as usize)
        })
        .join()
        .unwrap();
        assert_eq!(other, (0, b));
        assert_eq!(current(), a);
        set_current(std::ptr::null_mut());
        assert!(current().is_null());
        set_current(saved);
    }
}
