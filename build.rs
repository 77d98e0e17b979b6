//! Gives the shared library the SONAME programs link against (`libGL.so.1`).
//! libGLU.so.1 and libOSMesa.so.8 are symlinks to the same object (see README,
//! "One library, several names"), so one process always holds one softgl.
fn main() {
    let os = std::env::var("CARGO_CFG_TARGET_OS").unwrap_or_default();
    if os == "linux" {
        println!("cargo:rustc-cdylib-link-arg=-Wl,-soname,libGL.so.1");
    }
    println!("cargo:rerun-if-changed=build.rs");
}
