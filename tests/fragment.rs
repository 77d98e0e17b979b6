//! The per-fragment operations of GL 1.5 section 4.1 through the state
//! machine: every alpha function, every stencil function and operation
//! (wraps, masks, reference clamping), every blend factor and equation
//! against the real-number formula, every logic op against the bitwise truth
//! table its opcode encodes, and the order and interplay of the stages.
//! Expectations are computed here, independently of `render::fragment`.

use softgl::framebuffer::Config;
use softgl::gl::enums::*;
use softgl::gl::{Command, Context};

fn context_with(stencil_bits: u8) -> Context {
    let mut c = Context::new(Config { alpha_bits: 8, depth_bits: 24, stencil_bits, accum_bits: 0 });
    c.fb.resize(2, 2).unwrap();
    c.surface_resized(2, 2);
    c
}

fn context() -> Context {
    context_with(8)
}

fn run(c: &mut Context, cmds: &[Command]) {
    for cmd in cmds {
        c.execute(cmd);
    }
}

/// Colour from bytes: k/255 converts back to exactly k.
fn rgba(b: [u8; 4]) -> [f32; 4] {
    b.map(|v| v as f32 / 255.0)
}

/// Covers the whole 2x2 window with colour `col` at window depth 0.5.
fn draw(c: &mut Context, col: [u8; 4]) {
    run(c, &[Command::Color(rgba(col)), Command::Rect([-1.0, -1.0, 1.0, 1.0])]);
}

/// Clears colour to `col`, stencil to `s`, depth to `d`.
fn clear(c: &mut Context, col: [u8; 4], s: i32, d: f64) {
    run(
        c,
        &[
            Command::ClearColor(rgba(col)),
            Command::ClearStencil(s),
            Command::ClearDepth(d),
            Command::Clear(GL_COLOR_BUFFER_BIT | GL_STENCIL_BUFFER_BIT | GL_DEPTH_BUFFER_BIT),
        ],
    );
}

fn all_same<T: PartialEq + Copy + std::fmt::Debug>(v: &[T]) -> T {
    assert!(v.iter().all(|x| *x == v[0]), "pixels differ: {v:?}");
    v[0]
}

fn pixel(c: &Context) -> [u8; 4] {
    all_same(&c.fb.color)
}

fn stencil(c: &Context) -> u8 {
    all_same(&c.fb.stencil)
}

fn get_i(c: &mut Context, pname: u32) -> Vec<i32> {
    c.get(pname).expect("valid query").as_i32()
}

fn get_f(c: &mut Context, pname: u32) -> Vec<f64> {
    c.get(pname).expect("valid query").as_f64()
}

const FUNCS: [u32; 8] = [GL_NEVER, GL_LESS, GL_EQUAL, GL_LEQUAL, GL_GREATER, GL_NOTEQUAL, GL_GEQUAL, GL_ALWAYS];

fn passes(func: u32, a: i64, b: i64) -> bool {
    match func {
        GL_NEVER => false,
        GL_LESS => a < b,
        GL_EQUAL => a == b,
        GL_LEQUAL => a <= b,
        GL_GREATER => a > b,
        GL_NOTEQUAL => a != b,
        GL_GEQUAL => a >= b,
        GL_ALWAYS => true,
        _ => unreachable!(),
    }
}

const BLACK: [u8; 4] = [0, 0, 0, 0];
const WHITE: [u8; 4] = [255; 4];

#[test]
fn alpha_test_every_function() {
    let mut c = context();
    c.execute(&Command::Enable(GL_ALPHA_TEST));
    // References are clamped to [0, 1] and rounded to 8 bits like alpha.
    let refs: [(f32, i64); 7] = [(-0.25, 0), (0.0, 0), (100.0 / 255.0, 100), (0.5, 128), (0.502, 128), (1.0, 255), (7.0, 255)];
    for func in FUNCS {
        for (r, r8) in refs {
            for a in [0u8, 99, 100, 101, 127, 128, 129, 254, 255] {
                clear(&mut c, BLACK, 0, 1.0);
                c.execute(&Command::AlphaFunc(func, r));
                draw(&mut c, [255, 255, 255, a]);
                let expect = if passes(func, a as i64, r8) { [255, 255, 255, a] } else { BLACK };
                assert_eq!(pixel(&c), expect, "alpha func {func:#x} ref {r} alpha {a}");
            }
        }
    }
    assert_eq!(get_i(&mut c, GL_ALPHA_TEST_FUNC), vec![GL_ALWAYS as i32]);
    assert_eq!(get_f(&mut c, GL_ALPHA_TEST_REF), vec![1.0]);
    // Disabled: everything passes.
    c.execute(&Command::AlphaFunc(GL_NEVER, 0.0));
    c.execute(&Command::Disable(GL_ALPHA_TEST));
    clear(&mut c, BLACK, 0, 1.0);
    draw(&mut c, WHITE);
    assert_eq!(pixel(&c), WHITE);
}

#[test]
fn stencil_test_every_function_with_masks_and_clamping() {
    let mut c = context();
    c.execute(&Command::Enable(GL_STENCIL_TEST));
    for func in FUNCS {
        for (r, r_clamped) in [(-5i32, 0i64), (0, 0), (1, 1), (0x5A, 0x5A), (255, 255), (256, 255), (100000, 255)] {
            for mask in [0xFFu32, 0x0F, 0xF0, 0, 0xFFFF_FF0F] {
                for stored in [0i32, 1, 0x5A, 0x5B, 0xA5, 255] {
                    clear(&mut c, BLACK, stored, 1.0);
                    c.execute(&Command::StencilFunc(func, r, mask));
                    draw(&mut c, WHITE);
                    let m = (mask & 0xFF) as i64;
                    let expect = if passes(func, r_clamped & m, stored as i64 & m) { WHITE } else { BLACK };
                    assert_eq!(pixel(&c), expect, "stencil func {func:#x} ref {r} mask {mask:#x} stored {stored}");
                    assert_eq!(stencil(&c), stored as u8, "KEEP ops leave the stencil buffer");
                }
            }
            assert_eq!(get_i(&mut c, GL_STENCIL_REF), vec![r_clamped as i32]);
        }
    }
    c.execute(&Command::StencilFunc(GL_LEQUAL, 3, 0x0F));
    assert_eq!(get_i(&mut c, GL_STENCIL_FUNC), vec![GL_LEQUAL as i32]);
    assert_eq!(get_i(&mut c, GL_STENCIL_VALUE_MASK), vec![0x0F]);
}

const OPS: [u32; 8] = [GL_KEEP, GL_ZERO, GL_REPLACE, GL_INCR, GL_DECR, GL_INVERT, GL_INCR_WRAP, GL_DECR_WRAP];

/// The stencil value an operation produces, before the write mask.
fn op_result(op: u32, s: i32, reference: i32) -> i32 {
    match op {
        GL_KEEP => s,
        GL_ZERO => 0,
        GL_REPLACE => reference,
        GL_INCR => (s + 1).min(255),
        GL_DECR => (s - 1).max(0),
        GL_INVERT => 255 - s,
        GL_INCR_WRAP => (s + 1) % 256,
        GL_DECR_WRAP => (s + 255) % 256,
        _ => unreachable!(),
    }
}

#[derive(Clone, Copy, Debug, PartialEq)]
enum Case {
    StencilFail,
    DepthFail,
    DepthPass,
    /// The depth test is disabled: counts as passing.
    DepthOff,
}

#[test]
fn stencil_every_operation_in_every_slot() {
    let mut c = context();
    c.execute(&Command::Enable(GL_STENCIL_TEST));
    let reference = 0x5A;
    for case in [Case::StencilFail, Case::DepthFail, Case::DepthPass, Case::DepthOff] {
        for op in OPS {
            for write_mask in [0xFFu32, 0x0F, 0xF0, 0] {
                for stored in [0i32, 1, 0x0F, 0x10, 0x5A, 128, 254, 255] {
                    clear(&mut c, BLACK, stored, 0.75);
                    let (func, depth_func) = match case {
                        Case::StencilFail => (GL_NEVER, GL_ALWAYS),
                        Case::DepthFail => (GL_ALWAYS, GL_GREATER),
                        _ => (GL_ALWAYS, GL_LESS),
                    };
                    // The op under test in its slot; the other two slots hold
                    // INVERT so that running the wrong slot shows.
                    let slot = |k: Case| if k == case || (k == Case::DepthPass && case == Case::DepthOff) { op } else { GL_INVERT };
                    run(
                        &mut c,
                        &[
                            Command::StencilFunc(func, reference, 0xFF),
                            Command::StencilOp(slot(Case::StencilFail), slot(Case::DepthFail), slot(Case::DepthPass)),
                            Command::StencilMask(write_mask),
                            Command::DepthFunc(depth_func),
                            if case == Case::DepthOff { Command::Disable(GL_DEPTH_TEST) } else { Command::Enable(GL_DEPTH_TEST) },
                        ],
                    );
                    draw(&mut c, WHITE);
                    c.execute(&Command::StencilMask(!0));
                    let v = op_result(op, stored, reference);
                    let wm = (write_mask & 0xFF) as i32;
                    let expect = (stored & !wm) | (v & wm);
                    assert_eq!(stencil(&c) as i32, expect, "{case:?} op {op:#x} mask {write_mask:#x} stored {stored}");
                    let color_expect = if matches!(case, Case::DepthPass | Case::DepthOff) { WHITE } else { BLACK };
                    assert_eq!(pixel(&c), color_expect, "{case:?} colour");
                }
            }
        }
    }
    c.execute(&Command::StencilOp(GL_INCR_WRAP, GL_DECR_WRAP, GL_INVERT));
    assert_eq!(get_i(&mut c, GL_STENCIL_FAIL), vec![GL_INCR_WRAP as i32]);
    assert_eq!(get_i(&mut c, GL_STENCIL_PASS_DEPTH_FAIL), vec![GL_DECR_WRAP as i32]);
    assert_eq!(get_i(&mut c, GL_STENCIL_PASS_DEPTH_PASS), vec![GL_INVERT as i32]);
}

#[test]
fn no_stencil_buffer_means_the_test_passes() {
    let mut c = context_with(0);
    run(&mut c, &[Command::Enable(GL_STENCIL_TEST), Command::StencilFunc(GL_NEVER, 1, 0xFF)]);
    clear(&mut c, BLACK, 0, 1.0);
    draw(&mut c, WHITE);
    assert_eq!(pixel(&c), WHITE);
    assert_eq!(get_i(&mut c, GL_STENCIL_REF), vec![0], "reference clamps to 2^0 - 1");
}

#[test]
fn alpha_test_comes_before_stencil_and_depth() {
    let mut c = context();
    clear(&mut c, BLACK, 7, 1.0);
    run(
        &mut c,
        &[
            Command::Enable(GL_ALPHA_TEST),
            Command::AlphaFunc(GL_NEVER, 0.0),
            Command::Enable(GL_STENCIL_TEST),
            Command::StencilFunc(GL_NEVER, 0, 0xFF),
            Command::StencilOp(GL_ZERO, GL_ZERO, GL_ZERO),
            Command::Enable(GL_DEPTH_TEST),
            Command::DepthFunc(GL_ALWAYS),
        ],
    );
    draw(&mut c, WHITE);
    assert_eq!(stencil(&c), 7, "a fragment failing the alpha test does not reach the stencil test");
    assert_eq!(all_same(&c.fb.depth), (1 << 24) - 1, "nor the depth buffer");
    // Failing the stencil test: no depth write.
    c.execute(&Command::Disable(GL_ALPHA_TEST));
    draw(&mut c, WHITE);
    assert_eq!(stencil(&c), 0);
    assert_eq!(all_same(&c.fb.depth), (1 << 24) - 1, "a fragment failing the stencil test writes no depth");
    assert_eq!(pixel(&c), BLACK);
}

/// The reflection program's floor pass: colour masked off, depth test off,
/// stencil REPLACE; only the stencil buffer changes.
#[test]
fn stencil_only_pass() {
    let mut c = context();
    clear(&mut c, [10, 20, 30, 40], 0, 0.25);
    run(
        &mut c,
        &[
            Command::ColorMask([false; 4]),
            Command::Enable(GL_STENCIL_TEST),
            Command::StencilFunc(GL_ALWAYS, 1, 0xFF),
            Command::StencilOp(GL_KEEP, GL_KEEP, GL_REPLACE),
        ],
    );
    draw(&mut c, WHITE);
    assert_eq!(stencil(&c), 1);
    assert_eq!(pixel(&c), [10, 20, 30, 40]);
    assert_eq!(all_same(&c.fb.depth), ((1u64 << 24) - 1) as u32 / 4 + 1, "depth untouched (0.25)");
    // Then draw only where stencil == 1.
    run(&mut c, &[Command::ColorMask([true; 4]), Command::StencilFunc(GL_EQUAL, 1, 0xFF), Command::StencilOp(GL_KEEP, GL_KEEP, GL_KEEP)]);
    draw(&mut c, WHITE);
    assert_eq!(pixel(&c), WHITE);
    run(&mut c, &[Command::StencilFunc(GL_EQUAL, 2, 0xFF)]);
    draw(&mut c, BLACK);
    assert_eq!(pixel(&c), WHITE);
}

const FACTORS: [u32; 15] = [
    GL_ZERO,
    GL_ONE,
    GL_SRC_COLOR,
    GL_ONE_MINUS_SRC_COLOR,
    GL_DST_COLOR,
    GL_ONE_MINUS_DST_COLOR,
    GL_SRC_ALPHA,
    GL_ONE_MINUS_SRC_ALPHA,
    GL_DST_ALPHA,
    GL_ONE_MINUS_DST_ALPHA,
    GL_CONSTANT_COLOR,
    GL_ONE_MINUS_CONSTANT_COLOR,
    GL_CONSTANT_ALPHA,
    GL_ONE_MINUS_CONSTANT_ALPHA,
    GL_SRC_ALPHA_SATURATE,
];

const EQUATIONS: [u32; 5] = [GL_FUNC_ADD, GL_FUNC_SUBTRACT, GL_FUNC_REVERSE_SUBTRACT, GL_MIN, GL_MAX];

/// The real-number factor of channel `ch` (3 = alpha).
fn factor(f: u32, ch: usize, s: [f64; 4], d: [f64; 4], k: [f64; 4]) -> f64 {
    match f {
        GL_ZERO => 0.0,
        GL_ONE => 1.0,
        GL_SRC_COLOR => s[ch],
        GL_ONE_MINUS_SRC_COLOR => 1.0 - s[ch],
        GL_DST_COLOR => d[ch],
        GL_ONE_MINUS_DST_COLOR => 1.0 - d[ch],
        GL_SRC_ALPHA => s[3],
        GL_ONE_MINUS_SRC_ALPHA => 1.0 - s[3],
        GL_DST_ALPHA => d[3],
        GL_ONE_MINUS_DST_ALPHA => 1.0 - d[3],
        GL_CONSTANT_COLOR => k[ch],
        GL_ONE_MINUS_CONSTANT_COLOR => 1.0 - k[ch],
        GL_CONSTANT_ALPHA => k[3],
        GL_ONE_MINUS_CONSTANT_ALPHA => 1.0 - k[3],
        GL_SRC_ALPHA_SATURATE => {
            if ch == 3 {
                1.0
            } else {
                s[3].min(1.0 - d[3])
            }
        }
        _ => unreachable!(),
    }
}

/// The exact blended value of each channel, in units of 1/255.
fn blend_expect(eq: u32, f: [u32; 4], src: [u8; 4], dst: [u8; 4], k: [f64; 4]) -> [f64; 4] {
    let s = src.map(|v| v as f64 / 255.0);
    let d = dst.map(|v| v as f64 / 255.0);
    let mut out = [0.0; 4];
    for ch in 0..4 {
        let (sf, df) = if ch == 3 { (f[2], f[3]) } else { (f[0], f[1]) };
        let a = s[ch] * factor(sf, ch, s, d, k);
        let b = d[ch] * factor(df, ch, s, d, k);
        let v = match eq {
            GL_FUNC_ADD => a + b,
            GL_FUNC_SUBTRACT => a - b,
            GL_FUNC_REVERSE_SUBTRACT => b - a,
            GL_MIN => s[ch].min(d[ch]),
            GL_MAX => s[ch].max(d[ch]),
            _ => unreachable!(),
        };
        out[ch] = v.clamp(0.0, 1.0) * 255.0;
    }
    out
}

#[test]
fn blending_every_factor_and_equation() {
    let mut c = context();
    c.execute(&Command::Enable(GL_BLEND));
    let constant = [0.2f32, 0.55, 0.9, 0.35];
    c.execute(&Command::BlendColor(constant));
    let k = constant.map(|v| v as f64);
    let pairs: [([u8; 4], [u8; 4]); 4] = [
        ([200, 100, 50, 153], [30, 160, 240, 77]),
        ([255, 0, 128, 255], [128, 255, 0, 0]),
        ([17, 233, 91, 64], [250, 3, 190, 230]),
        ([0, 0, 0, 0], [255, 255, 255, 255]),
    ];
    let mut worst = 0.0f64;
    let mut checked = 0;
    for eq in EQUATIONS {
        c.execute(&Command::BlendEquation(eq));
        for (i, &sr) in FACTORS.iter().enumerate() {
            for (j, &dr) in FACTORS.iter().enumerate() {
                if dr == GL_SRC_ALPHA_SATURATE {
                    continue; // a source factor only
                }
                // Separate alpha factors, varied independently of the RGB ones.
                let sa = FACTORS[(i * 7 + j + 3) % 15];
                let da = FACTORS[(j * 5 + i + 1) % 14];
                let f = [sr, dr, sa, da];
                c.execute(&Command::BlendFunc(f));
                for (src, dst) in pairs {
                    clear(&mut c, dst, 0, 1.0);
                    draw(&mut c, src);
                    let got = pixel(&c);
                    let exp = blend_expect(eq, f, src, dst, k);
                    for ch in 0..4 {
                        let err = (got[ch] as f64 - exp[ch]).abs();
                        worst = worst.max(err);
                        assert!(err <= 0.5 + 1e-3, "eq {eq:#x} factors {f:x?} src {src:?} dst {dst:?}: got {got:?}, exact {exp:?}");
                    }
                    checked += 1;
                }
            }
        }
    }
    assert!(checked > 4000);
    eprintln!("blending: worst error {worst} LSB over {checked} cases");
    // Queries.
    c.execute(&Command::BlendFunc([GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA, GL_ONE, GL_ZERO]));
    assert_eq!(get_i(&mut c, GL_BLEND_SRC), vec![GL_SRC_ALPHA as i32]);
    assert_eq!(get_i(&mut c, GL_BLEND_SRC_RGB), vec![GL_SRC_ALPHA as i32]);
    assert_eq!(get_i(&mut c, GL_BLEND_DST), vec![GL_ONE_MINUS_SRC_ALPHA as i32]);
    assert_eq!(get_i(&mut c, GL_BLEND_DST_RGB), vec![GL_ONE_MINUS_SRC_ALPHA as i32]);
    assert_eq!(get_i(&mut c, GL_BLEND_SRC_ALPHA), vec![GL_ONE as i32]);
    assert_eq!(get_i(&mut c, GL_BLEND_DST_ALPHA), vec![GL_ZERO as i32]);
    assert_eq!(get_i(&mut c, GL_BLEND_EQUATION), vec![GL_MAX as i32]);
    let bc = get_f(&mut c, GL_BLEND_COLOR);
    assert!(bc.iter().zip(constant).all(|(a, b)| (a - b as f64).abs() < 1e-6), "{bc:?}");
    c.execute(&Command::BlendColor([-1.0, 2.0, 0.5, 1.0]));
    assert_eq!(get_f(&mut c, GL_BLEND_COLOR), vec![0.0, 1.0, 0.5, 1.0], "clamped");
}

#[test]
fn blend_enums_are_checked() {
    let mut c = context();
    c.execute(&Command::BlendFunc([GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA, GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA]));
    for bad in [
        [GL_ONE, GL_SRC_ALPHA_SATURATE, GL_ONE, GL_ZERO],
        [GL_ONE, GL_ZERO, GL_ONE, GL_SRC_ALPHA_SATURATE],
        [GL_ONE, 0x0309, GL_ONE, GL_ZERO],
        [GL_ONE, GL_ZERO, 2, GL_ZERO],
    ] {
        c.execute(&Command::BlendFunc(bad));
        assert_eq!(c.take_error(), GL_INVALID_ENUM, "{bad:x?}");
    }
    assert_eq!(get_i(&mut c, GL_BLEND_SRC), vec![GL_SRC_ALPHA as i32], "unchanged by the errors");
    c.execute(&Command::BlendEquation(GL_FUNC_ADD + 1 + 0x10));
    assert_eq!(c.take_error(), GL_INVALID_ENUM);
    c.execute(&Command::LogicOp(GL_SET + 1));
    assert_eq!(c.take_error(), GL_INVALID_ENUM);
    c.execute(&Command::StencilOp(GL_KEEP, GL_KEEP, GL_NEVER));
    assert_eq!(c.take_error(), GL_INVALID_ENUM);
    c.execute(&Command::StencilFunc(GL_KEEP, 0, 0));
    assert_eq!(c.take_error(), GL_INVALID_ENUM);
    c.execute(&Command::AlphaFunc(GL_ZERO, 0.0));
    assert_eq!(c.take_error(), GL_INVALID_ENUM);
    // Between Begin and End: INVALID_OPERATION.
    c.execute(&Command::Begin(GL_TRIANGLES));
    c.execute(&Command::BlendFunc([GL_ONE, GL_ONE, GL_ONE, GL_ONE]));
    c.execute(&Command::End);
    assert_eq!(c.take_error(), GL_INVALID_OPERATION);
    assert_eq!(get_i(&mut c, GL_BLEND_DST), vec![GL_ONE_MINUS_SRC_ALPHA as i32]);
}

const LOGIC_OPS: [u32; 16] = [
    GL_CLEAR,
    GL_AND,
    GL_AND_REVERSE,
    GL_COPY,
    GL_AND_INVERTED,
    GL_NOOP,
    GL_XOR,
    GL_OR,
    GL_NOR,
    GL_EQUIV,
    GL_INVERT,
    GL_OR_REVERSE,
    GL_COPY_INVERTED,
    GL_OR_INVERTED,
    GL_NAND,
    GL_SET,
];

/// Bit by bit from the truth table in the opcode's low four bits: the
/// result for (s, d) is bit 3 - (2s + d) (GL_AND = 0001: only s = d = 1).
fn logic_expect(op: u32, s: u8, d: u8) -> u8 {
    let table = op & 0xF;
    let mut out = 0u8;
    for bit in 0..8 {
        let sb = (s >> bit) & 1;
        let db = (d >> bit) & 1;
        let r = (table >> (3 - (2 * sb + db))) & 1;
        out |= (r as u8) << bit;
    }
    out
}

#[test]
fn logic_op_every_operation() {
    let mut c = context();
    // Blending is bypassed while the logic op is enabled.
    run(&mut c, &[Command::Enable(GL_COLOR_LOGIC_OP), Command::Enable(GL_BLEND), Command::BlendFunc([GL_ZERO, GL_ONE, GL_ZERO, GL_ONE])]);
    let pairs: [([u8; 4], [u8; 4]); 3] = [([0xF0, 0xCC, 0xAA, 0x00], [0xFF, 0xAA, 0xCC, 0x0F]), ([0x5A, 0x00, 0xFF, 0x81], [0x3C, 0xFF, 0x00, 0x18]), ([255; 4], [0; 4])];
    for op in LOGIC_OPS {
        c.execute(&Command::LogicOp(op));
        assert_eq!(get_i(&mut c, GL_LOGIC_OP_MODE), vec![op as i32]);
        for (src, dst) in pairs {
            clear(&mut c, dst, 0, 1.0);
            draw(&mut c, src);
            let expect = [0, 1, 2, 3].map(|ch| logic_expect(op, src[ch], dst[ch]));
            assert_eq!(pixel(&c), expect, "logic op {op:#x} src {src:x?} dst {dst:x?}");
        }
    }
    // With the colour mask: masked channels keep the destination.
    clear(&mut c, [0x0F; 4], 0, 1.0);
    run(&mut c, &[Command::LogicOp(GL_XOR), Command::ColorMask([true, false, true, false])]);
    draw(&mut c, [0xFF; 4]);
    assert_eq!(pixel(&c), [0xF0, 0x0F, 0xF0, 0x0F]);
    // GL 1.0's GL_LOGIC_OP (index mode) has no effect in RGBA: blending applies.
    run(&mut c, &[Command::ColorMask([true; 4]), Command::Disable(GL_COLOR_LOGIC_OP), Command::Enable(GL_INDEX_LOGIC_OP)]);
    assert_eq!(c.is_enabled(GL_INDEX_LOGIC_OP), Some(true));
    assert_eq!(c.take_error(), GL_NO_ERROR);
    clear(&mut c, [1, 2, 3, 4], 0, 1.0);
    draw(&mut c, WHITE);
    assert_eq!(pixel(&c), [1, 2, 3, 4], "BlendFunc(ZERO, ONE) keeps the destination");
    run(&mut c, &[Command::Disable(GL_BLEND)]);
    draw(&mut c, WHITE);
    assert_eq!(pixel(&c), WHITE, "no logic op in RGBA mode from GL_INDEX_LOGIC_OP");
}

#[test]
fn blending_through_the_colour_mask() {
    let mut c = context();
    clear(&mut c, [100, 100, 100, 100], 0, 1.0);
    run(&mut c, &[Command::Enable(GL_BLEND), Command::BlendFunc([GL_ONE, GL_ONE, GL_ONE, GL_ONE]), Command::ColorMask([false, true, false, true])]);
    draw(&mut c, [50, 50, 50, 200]);
    assert_eq!(pixel(&c), [100, 150, 100, 255]);
}

#[test]
fn clear_honours_masks_and_ignores_fragment_ops() {
    let mut c = context();
    clear(&mut c, [0; 4], 0xF0, 1.0);
    run(
        &mut c,
        &[
            Command::Enable(GL_BLEND),
            Command::BlendFunc([GL_ZERO, GL_ONE, GL_ZERO, GL_ONE]),
            Command::Enable(GL_STENCIL_TEST),
            Command::StencilFunc(GL_NEVER, 0, 0),
            Command::Enable(GL_ALPHA_TEST),
            Command::AlphaFunc(GL_NEVER, 0.0),
            Command::StencilMask(0x0F),
            Command::ColorMask([true, false, false, true]),
            Command::ClearStencil(0xFF),
            Command::ClearColor([1.0; 4]),
            Command::Clear(GL_COLOR_BUFFER_BIT | GL_STENCIL_BUFFER_BIT),
        ],
    );
    assert_eq!(stencil(&c), 0xFF);
    assert_eq!(pixel(&c), [255, 0, 0, 255]);
    run(&mut c, &[Command::StencilMask(0x0F), Command::ClearStencil(0x00), Command::Clear(GL_STENCIL_BUFFER_BIT)]);
    assert_eq!(stencil(&c), 0xF0);
    assert_eq!(get_i(&mut c, GL_STENCIL_WRITEMASK), vec![0x0F]);
}

/// The stencil masks start as all 1's and read back within the stencil
/// buffer's 8 bits (as Mesa reads them), whatever bits above were given.
#[test]
fn stencil_masks_read_back_within_the_stencil_bits() {
    let mut c = context();
    assert_eq!(get_i(&mut c, GL_STENCIL_WRITEMASK), vec![0xFF]);
    assert_eq!(get_i(&mut c, GL_STENCIL_VALUE_MASK), vec![0xFF]);
    assert_eq!(get_f(&mut c, GL_STENCIL_WRITEMASK), vec![255.0]);
    run(&mut c, &[Command::StencilMask(0xFFFF_FF3C), Command::StencilFunc(GL_EQUAL, 1, 0x8000_0081)]);
    assert_eq!(get_i(&mut c, GL_STENCIL_WRITEMASK), vec![0x3C]);
    assert_eq!(get_i(&mut c, GL_STENCIL_VALUE_MASK), vec![0x81]);
}

#[test]
fn fragment_state_in_display_lists() {
    let mut c = context();
    let n = c.gen_lists(1);
    c.new_list(n, GL_COMPILE);
    for cmd in [
        Command::Enable(GL_BLEND),
        Command::BlendFunc([GL_ONE, GL_ONE, GL_ONE, GL_ONE]),
        Command::BlendEquation(GL_FUNC_REVERSE_SUBTRACT),
        Command::BlendColor([0.5; 4]),
        Command::AlphaFunc(GL_GREATER, 0.5),
        Command::StencilFunc(GL_EQUAL, 3, 0x7F),
        Command::StencilOp(GL_INCR, GL_DECR, GL_INVERT),
        Command::LogicOp(GL_XOR),
    ] {
        c.submit(cmd);
    }
    c.end_list();
    assert_eq!(c.is_enabled(GL_BLEND), Some(false), "compiled, not executed");
    assert_eq!(get_i(&mut c, GL_BLEND_EQUATION), vec![GL_FUNC_ADD as i32]);
    c.execute(&Command::CallList(n));
    assert_eq!(c.take_error(), GL_NO_ERROR);
    assert_eq!(get_i(&mut c, GL_BLEND_EQUATION), vec![GL_FUNC_REVERSE_SUBTRACT as i32]);
    assert_eq!(get_i(&mut c, GL_BLEND_SRC_ALPHA), vec![GL_ONE as i32]);
    assert_eq!(get_f(&mut c, GL_BLEND_COLOR), vec![0.5; 4]);
    assert_eq!(get_i(&mut c, GL_ALPHA_TEST_FUNC), vec![GL_GREATER as i32]);
    assert_eq!(get_i(&mut c, GL_STENCIL_REF), vec![3]);
    assert_eq!(get_i(&mut c, GL_STENCIL_VALUE_MASK), vec![0x7F]);
    assert_eq!(get_i(&mut c, GL_STENCIL_FAIL), vec![GL_INCR as i32]);
    assert_eq!(get_i(&mut c, GL_LOGIC_OP_MODE), vec![GL_XOR as i32]);
    // Reverse subtract with ONE, ONE: dst - src.
    clear(&mut c, [100, 50, 0, 200], 0, 1.0);
    draw(&mut c, [30, 60, 0, 40]);
    assert_eq!(pixel(&c), [70, 0, 0, 160]);
}

/// Points and lines take the same per-fragment operations.
#[test]
fn points_and_lines_are_blended_and_stencilled() {
    let mut c = context();
    clear(&mut c, [100, 100, 100, 100], 0, 1.0);
    run(
        &mut c,
        &[
            Command::Enable(GL_BLEND),
            Command::BlendFunc([GL_ONE, GL_ONE, GL_ONE, GL_ONE]),
            Command::Enable(GL_STENCIL_TEST),
            Command::StencilOp(GL_KEEP, GL_KEEP, GL_INCR),
            Command::Color(rgba([10, 20, 30, 40])),
            // Window (1.5, 1.5): pixel (1, 1).
            Command::Begin(GL_POINTS),
            Command::Vertex([0.5, 0.5, 0.0, 1.0]),
            Command::End,
        ],
    );
    let i = c.fb.index(1, 1);
    assert_eq!(c.fb.color[i], [110, 120, 130, 140]);
    assert_eq!(c.fb.stencil[i], 1);
    assert_eq!(c.fb.color[c.fb.index(0, 0)], [100; 4]);
    assert_eq!(c.fb.stencil[c.fb.index(0, 0)], 0);
    // A horizontal line along row 0 (pixel 0 by the diamond-exit rule).
    run(
        &mut c,
        &[Command::Begin(GL_LINES), Command::Vertex([-1.0, -0.5, 0.0, 1.0]), Command::Vertex([1.0, -0.5, 0.0, 1.0]), Command::End],
    );
    let i = c.fb.index(0, 0);
    assert_eq!(c.fb.color[i], [110, 120, 130, 140], "line pixel");
    assert_eq!(c.fb.stencil[i], 1);
}
