//! Texture micro-benchmark: texel sampling rate (the sampler alone, and
//! whole textured quads through the fragment stage) and image upload rate
//! (glTexImage2D, RGBA / UNSIGNED_BYTE). Run with
//! `cargo run --release --example tex_bench`.

use softgl::framebuffer::Config;
use softgl::gl::texture::enums as t;
use softgl::gl::{Command, Context};
use softgl::render::texture::Coord;

/// This thread's CPU time in seconds: the machine is shared, so wall-clock
/// time would measure the other processes too.
fn cpu_time() -> f64 {
    let mut ts = libc::timespec { tv_sec: 0, tv_nsec: 0 };
    unsafe { libc::clock_gettime(libc::CLOCK_THREAD_CPUTIME_ID, &mut ts) };
    ts.tv_sec as f64 + ts.tv_nsec as f64 * 1e-9
}

fn context(w: usize, h: usize) -> Context {
    let mut c = Context::new(Config { alpha_bits: 8, depth_bits: 24, stencil_bits: 8, accum_bits: 0 });
    c.fb.resize(w, h).unwrap();
    c.surface_resized(w as i32, h as i32);
    c
}

fn upload(c: &mut Context, ifmt: u32, format: u32, w: i32, h: i32, data: &[u8]) {
    let cmd = unsafe { c.tex_image_command(2, t::GL_TEXTURE_2D, 0, ifmt as i32, [w, h, 1], 0, format, t::GL_UNSIGNED_BYTE, data.as_ptr()) };
    if let Some(cmd) = cmd {
        c.submit(cmd);
    }
}

fn setup(c: &mut Context, ifmt: u32, filter: u32, wrap: u32) {
    let n = 256usize;
    let data: Vec<u8> = (0..n * n * 4).map(|i| (i * 7 % 251) as u8).collect();
    upload(c, ifmt, t::GL_RGBA, n as i32, n as i32, &data);
    let p = |c: &mut Context, pname: u32, v: u32| c.execute(&Command::TexParameter(t::GL_TEXTURE_2D, pname, [v as f32, 0.0, 0.0, 0.0]));
    p(c, t::GL_TEXTURE_MIN_FILTER, filter);
    p(c, t::GL_TEXTURE_MAG_FILTER, if filter == t::GL_NEAREST { t::GL_NEAREST } else { t::GL_LINEAR });
    p(c, t::GL_TEXTURE_WRAP_S, wrap);
    p(c, t::GL_TEXTURE_WRAP_T, wrap);
    p(c, t::GL_GENERATE_MIPMAP, 1);
    upload(c, ifmt, t::GL_RGBA, n as i32, n as i32, &data);
    c.execute(&Command::Enable(t::GL_TEXTURE_2D));
    c.execute(&Command::TexEnv(t::GL_TEXTURE_ENV, t::GL_TEXTURE_ENV_MODE, [t::GL_REPLACE as f32, 0.0, 0.0, 0.0]));
}

fn quad(c: &mut Context, reps: f32) {
    c.execute(&Command::Begin(softgl::gl::enums::GL_QUADS));
    for (x, y, s, tt) in [(-1.0, -1.0, 0.0, 0.0), (1.0, -1.0, reps, 0.0), (1.0, 1.0, reps, reps), (-1.0, 1.0, 0.0, reps)] {
        c.execute(&Command::TexCoord(t::GL_TEXTURE0, [s, tt, 0.0, 1.0]));
        c.execute(&Command::Vertex([x, y, 0.0, 1.0]));
    }
    c.execute(&Command::End);
}

fn main() {
    let cases = [
        ("RGBA8 nearest repeat", t::GL_RGBA8, t::GL_NEAREST, t::GL_REPEAT),
        ("RGBA8 nearest clamp-to-edge", t::GL_RGBA8, t::GL_NEAREST, t::GL_CLAMP_TO_EDGE),
        ("RGB8 nearest repeat", t::GL_RGB8, t::GL_NEAREST, t::GL_REPEAT),
        ("RGBA8 linear repeat", t::GL_RGBA8, t::GL_LINEAR, t::GL_REPEAT),
        ("RGBA8 trilinear repeat", t::GL_RGBA8, t::GL_LINEAR_MIPMAP_LINEAR, t::GL_REPEAT),
    ];
    println!("| case | sampler Mtexels/s | textured quad Mfragments/s |");
    println!("| --- | ---: | ---: |");
    for (name, ifmt, filter, wrap) in cases {
        let (w, h) = (512usize, 512usize);
        let mut c = context(w, h);
        setup(&mut c, ifmt, filter, wrap);
        // The whole pipeline: a full-window quad, 2 repeats of the texture
        // (minified when mipmapped: 256 texels over 256 pixels... per repeat).
        quad(&mut c, 2.0);
        let frames = 20;
        let t0 = cpu_time();
        for _ in 0..frames {
            quad(&mut c, 2.0);
        }
        let quad_rate = (frames * w * h) as f64 / (cpu_time() - t0) / 1e6;
        // The sampler alone, on the stage validation derived.
        c.validate();
        let stage = c.derived.render.texture.clone().expect("texturing on");
        let s = stage.units[0].as_ref().expect("unit 0");
        let n = 4_000_000usize;
        let mut acc = 0.0f32;
        let t0 = cpu_time();
        for i in 0..n {
            let u = (i % 1024) as f32 * (1.0 / 512.0) - 0.3;
            let v = (i / 1024 % 1024) as f32 * (1.0 / 512.0) + 0.1;
            let coord = Coord { str: [u, v, 0.0], dx: [1.0 / 256.0, 0.0, 0.0], dy: [0.0, 1.0 / 256.0, 0.0] };
            acc += s.sample(&coord).x;
        }
        let sample_rate = n as f64 / (cpu_time() - t0) / 1e6;
        std::hint::black_box(acc);
        println!("| {name} | {sample_rate:.1} | {quad_rate:.1} |");
    }
    // Upload: glTexImage2D 1024x1024 RGBA / UNSIGNED_BYTE into RGBA8.
    let mut c = context(16, 16);
    let n = 1024usize;
    let data: Vec<u8> = (0..n * n * 4).map(|i| (i % 253) as u8).collect();
    for (name, ifmt, format) in [("RGBA -> RGBA8", t::GL_RGBA8, t::GL_RGBA), ("BGRA -> RGBA8", t::GL_RGBA8, t::GL_BGRA), ("RGBA -> RGB8", t::GL_RGB8, t::GL_RGBA), ("RGBA -> RGBA16", t::GL_RGBA16, t::GL_RGBA)] {
        upload(&mut c, ifmt, format, n as i32, n as i32, &data);
        let reps = 10;
        let t0 = cpu_time();
        for _ in 0..reps {
            upload(&mut c, ifmt, format, n as i32, n as i32, &data);
        }
        let dt = (cpu_time() - t0) / reps as f64;
        println!("upload 1024x1024 {name}: {:.2} ms ({:.0} Mtexels/s)", dt * 1e3, (n * n) as f64 / dt / 1e6);
    }
    // GENERATE_MIPMAP: the same upload building the 10 smaller levels.
    c.execute(&Command::TexParameter(t::GL_TEXTURE_2D, t::GL_GENERATE_MIPMAP, [1.0, 0.0, 0.0, 0.0]));
    let reps = 5;
    let t0 = cpu_time();
    for _ in 0..reps {
        upload(&mut c, t::GL_RGBA8, t::GL_RGBA, n as i32, n as i32, &data);
    }
    let dt = (cpu_time() - t0) / reps as f64;
    println!("upload 1024x1024 RGBA -> RGBA8 with GENERATE_MIPMAP: {:.2} ms", dt * 1e3);
}
