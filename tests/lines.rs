//! Lines and points (GL 1.5 sections 3.3 and 3.4) through the GL state
//! machine, checked pixel for pixel against expectations computed here
//! from the spec's rules: the diamond-exit rule (by an independent f64
//! model with a concrete tiny perturbation, on endpoints from a 1/4-pixel
//! grid where that model is exact), wide lines, stipple, point squares.

use softgl::framebuffer::Config;
use softgl::gl::enums::*;
use softgl::gl::{Command, Context};
use std::collections::BTreeSet;

mod common;
use common::Rng;

const N: usize = 32;

fn context() -> Context {
    let mut c = Context::new(Config { alpha_bits: 8, depth_bits: 24, stencil_bits: 8, accum_bits: 0 });
    c.fb.resize(N, N).unwrap();
    c.surface_resized(N as i32, N as i32);
    c.execute(&Command::MatrixMode(GL_PROJECTION));
    c.execute(&Command::Ortho([0.0, N as f64, 0.0, N as f64, -1.0, 1.0]));
    c.execute(&Command::MatrixMode(GL_MODELVIEW));
    c
}

type Px = BTreeSet<(i64, i64)>;

fn clear(c: &mut Context) {
    c.execute(&Command::ClearColor([0.0; 4]));
    c.execute(&Command::Clear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT));
}

fn lit(c: &Context) -> Px {
    let mut s = Px::new();
    for y in 0..N {
        for x in 0..N {
            if c.fb.color[y * N + x] != [0; 4] {
                s.insert((x as i64, y as i64));
            }
        }
    }
    s
}

fn draw(c: &mut Context, mode: u32, verts: &[[f32; 3]]) -> Px {
    clear(c);
    c.execute(&Command::Color([1.0; 4]));
    c.execute(&Command::Begin(mode));
    for v in verts {
        c.execute(&Command::Vertex([v[0], v[1], v[2], 1.0]));
    }
    c.execute(&Command::End);
    lit(c)
}

fn line(c: &mut Context, a: [f32; 2], b: [f32; 2]) -> Px {
    draw(c, GL_LINES, &[[a[0], a[1], 0.0], [b[0], b[1], 0.0]])
}

/// The diamond-exit rule, modelled directly: the segment moved by
/// (-e, -e^2) meets the open diamond of pixel (px, py) and its end does not
/// lie in it. The distance |x - cx| + |y - cy| along the segment is convex
/// and piecewise linear in t, so its minimum is at t = 0, t = 1 or where x
/// or y crosses the centre.
fn diamond_rule(a: [f64; 2], b: [f64; 2]) -> Px {
    let (e, e2) = (1e-6, 1e-12);
    let a = [a[0] - e, a[1] - e2];
    let b = [b[0] - e, b[1] - e2];
    let mut out = Px::new();
    for py in 0..N as i64 {
        for px in 0..N as i64 {
            let (cx, cy) = (px as f64 + 0.5, py as f64 + 0.5);
            let f = |t: f64| {
                let x = a[0] + t * (b[0] - a[0]);
                let y = a[1] + t * (b[1] - a[1]);
                (x - cx).abs() + (y - cy).abs()
            };
            let mut ts = vec![0.0, 1.0];
            if b[0] != a[0] {
                ts.push(((cx - a[0]) / (b[0] - a[0])).clamp(0.0, 1.0));
            }
            if b[1] != a[1] {
                ts.push(((cy - a[1]) / (b[1] - a[1])).clamp(0.0, 1.0));
            }
            let min = ts.iter().map(|&t| f(t)).fold(f64::INFINITY, f64::min);
            if min < 0.5 && !(f(1.0) < 0.5) {
                out.insert((px, py));
            }
        }
    }
    out
}

fn row(y: i64, xs: std::ops::Range<i64>) -> Px {
    xs.map(|x| (x, y)).collect()
}

fn col(x: i64, ys: std::ops::Range<i64>) -> Px {
    ys.map(|y| (x, y)).collect()
}

#[test]
fn one_pixel_lines_hand_cases() {
    let mut c = context();
    // Endpoints at pixel centres: the last pixel is not drawn.
    assert_eq!(line(&mut c, [2.5, 5.5], [10.5, 5.5]), row(5, 2..10));
    assert_eq!(line(&mut c, [10.5, 5.5], [2.5, 5.5]), row(5, 3..11));
    assert_eq!(line(&mut c, [5.5, 2.5], [5.5, 10.5]), col(5, 2..10));
    // On pixel edges (diamond corners): the perturbation moves the line
    // down / left.
    assert_eq!(line(&mut c, [2.0, 5.0], [10.0, 5.0]), row(4, 2..10));
    assert_eq!(line(&mut c, [5.0, 2.0], [5.0, 10.0]), col(4, 2..10));
    // Diagonals, centres and corners.
    let diag: Px = (2..10).map(|i| (i, i)).collect();
    assert_eq!(line(&mut c, [2.5, 2.5], [10.5, 10.5]), diag);
    assert_eq!(line(&mut c, [2.0, 2.0], [10.0, 10.0]), diag);
    // Zero length: nothing.
    assert_eq!(line(&mut c, [4.5, 4.5], [4.5, 4.5]), Px::new());
    for (a, b) in [([2.0, 5.0], [10.0, 5.0]), ([2.0, 2.0], [10.0, 10.0]), ([10.0, 2.0], [2.0, 10.0]), ([3.25, 7.75], [20.5, 1.0])] {
        assert_eq!(line(&mut c, a, b), diamond_rule([a[0] as f64, a[1] as f64], [b[0] as f64, b[1] as f64]), "{a:?} {b:?}");
    }
}

#[test]
fn one_pixel_lines_match_the_diamond_rule() {
    let mut c = context();
    let mut r = Rng(7);
    for i in 0..400 {
        // Some short, some long, some on integer or half-integer points.
        let span = if i % 3 == 0 { 4.0 } else { 30.0 };
        let a = [r.quarter(1.0, 1.0 + span), r.quarter(1.0, 1.0 + span)];
        let mut b = [r.quarter(1.0, 1.0 + span), r.quarter(1.0, 1.0 + span)];
        if i % 5 == 0 {
            // Exact diagonals and axis-parallel lines.
            let d = b[0] - a[0];
            b[1] = if i % 2 == 0 { a[1] + d } else { a[1] };
            if b[1] < 0.0 || b[1] > 31.0 {
                continue;
            }
        }
        let want = diamond_rule([a[0] as f64, a[1] as f64], [b[0] as f64, b[1] as f64]);
        assert_eq!(line(&mut c, a, b), want, "line {a:?} -> {b:?}");
    }
}

#[test]
fn strips_and_loops_draw_no_pixel_twice_at_joins() {
    let mut c = context();
    let mut r = Rng(99);
    for _ in 0..50 {
        // A strip monotone in x with |slope| <= 1: consecutive segments
        // share only their joint.
        let mut pts = vec![[r.quarter(0.0, 3.0), r.quarter(10.0, 20.0), 0.0]];
        while pts.last().unwrap()[0] < 26.0 {
            let p = *pts.last().unwrap();
            let dx = r.quarter(1.0, 6.0);
            let dy = r.quarter(-dx.min(4.0), dx.min(4.0));
            pts.push([p[0] + dx, (p[1] + dy).clamp(1.0, 30.0), 0.0]);
        }
        let mut union = Px::new();
        let mut total = 0;
        for w in pts.windows(2) {
            let s = draw(&mut c, GL_LINES, w);
            total += s.len();
            union.extend(s);
        }
        assert_eq!(total, union.len(), "segments of the strip overlap: {pts:?}");
        assert_eq!(draw(&mut c, GL_LINE_STRIP, &pts), union);
        // The loop adds the closing segment.
        let closing = draw(&mut c, GL_LINES, &[*pts.last().unwrap(), pts[0]]);
        let lp = draw(&mut c, GL_LINE_LOOP, &pts);
        assert!(union.is_subset(&lp) && closing.is_subset(&lp));
        assert_eq!(lp.len(), union.union(&closing).count());
    }
}

#[test]
fn wide_lines() {
    let mut c = context();
    c.execute(&Command::LineWidth(3.0));
    // x-major: a column of 3 centred on the width-1 fragment.
    let mut want = Px::new();
    for y in 9..12 {
        want.extend(row(y, 2..12));
    }
    assert_eq!(line(&mut c, [2.5, 10.5], [12.5, 10.5]), want);
    // Width 2: the segment moves down by 1/2 onto the pixel edge y = 10,
    // whose width-1 fragments are row 9: rows 9 and 10.
    c.execute(&Command::LineWidth(2.0));
    let mut want = row(9, 2..12);
    want.extend(row(10, 2..12));
    assert_eq!(line(&mut c, [2.5, 10.5], [12.5, 10.5]), want);
    // y-major, width 4 (2.6 rounds to 3, 3.5 to 4): rows of 4 fragments.
    c.execute(&Command::LineWidth(3.5));
    let mut want = Px::new();
    for x in 8..12 {
        want.extend(col(x, 3..20));
    }
    assert_eq!(line(&mut c, [10.0, 3.5], [10.0, 20.5]), want);
    // Diagonal width 5: 5 fragments per column.
    c.execute(&Command::LineWidth(5.0));
    let s = line(&mut c, [6.5, 6.5], [20.5, 20.5]);
    assert_eq!(s.len(), 14 * 5);
    for x in 6..20 {
        assert_eq!(s.iter().filter(|p| p.0 == x).count(), 5);
        assert!(s.contains(&(x, x - 2)) && s.contains(&(x, x + 2)));
    }
    // Invalid widths are refused and change nothing.
    c.take_error();
    c.execute(&Command::LineWidth(0.0));
    assert_eq!(c.take_error(), GL_INVALID_VALUE);
    c.execute(&Command::LineWidth(-1.0));
    assert_eq!(c.take_error(), GL_INVALID_VALUE);
    assert_eq!(c.line.width, 5.0);
}

#[test]
fn stipple() {
    let mut c = context();
    c.execute(&Command::Enable(GL_LINE_STIPPLE));
    c.execute(&Command::LineStipple(1, 0x00FF));
    // Fragment s is at x = s: drawn iff bit s % 16 is set.
    let want: Px = (0..31).filter(|x| x % 16 < 8).map(|x| (x, 4)).collect();
    assert_eq!(line(&mut c, [0.5, 4.5], [31.5, 4.5]), want);
    c.execute(&Command::LineStipple(3, 0x0F0F));
    let pat = |s: i64| 0x0F0Fu16 & (1 << ((s / 3) % 16)) != 0;
    let want: Px = (0..31).filter(|&x| pat(x)).map(|x| (x, 4)).collect();
    assert_eq!(line(&mut c, [0.5, 4.5], [31.5, 4.5]), want);
    // A strip continues the counter across its joints...
    let want: Px = (0..28).filter(|&x| pat(x)).map(|x| (x, 4)).collect();
    assert_eq!(draw(&mut c, GL_LINE_STRIP, &[[0.5, 4.5, 0.0], [11.5, 4.5, 0.0], [28.5, 4.5, 0.0]]), want);
    // ... and GL_LINES restarts it for each segment.
    let want: Px = (0..28).filter(|&x| if x < 11 { pat(x) } else { pat(x - 11) }).map(|x| (x, 4)).collect();
    assert_eq!(draw(&mut c, GL_LINES, &[[0.5, 4.5, 0.0], [11.5, 4.5, 0.0], [11.5, 4.5, 0.0], [28.5, 4.5, 0.0]]), want);
    // A loop continues it into the closing segment (drawn right to left).
    let lp = draw(&mut c, GL_LINE_LOOP, &[[0.5, 4.5, 0.0], [20.5, 4.5, 0.0], [20.5, 10.5, 0.0]]);
    // Segment 1: s = 0..19 on row 4; segment 2: s = 20..25 on column 20,
    // rows 4..9; closing from (20.5, 10.5) to (0.5, 4.5): s from 26.
    let closing = diamond_rule([20.5, 10.5], [0.5, 4.5]);
    let mut want: Px = (0..20).filter(|&x| pat(x)).map(|x| (x, 4)).collect();
    want.extend((4..10).filter(|&y| pat(20 + y - 4)).map(|y| (20, y)));
    let mut cl: Vec<_> = closing.into_iter().collect();
    cl.sort_by_key(|p| -p.0);
    want.extend(cl.iter().enumerate().filter(|(i, _)| pat(26 + *i as i64)).map(|(_, p)| *p));
    assert_eq!(lp, want);
    // Disabled: everything.
    c.execute(&Command::Disable(GL_LINE_STIPPLE));
    assert_eq!(line(&mut c, [0.5, 4.5], [31.5, 4.5]).len(), 31);
}

#[test]
fn points_of_every_size_follow_the_centre_rule() {
    let mut c = context();
    for size in 1..=6 {
        c.execute(&Command::PointSize(size as f32));
        for (x, y) in [(10.3f32, 10.7f32), (10.5, 10.5), (10.0, 11.0), (4.9, 20.2)] {
            let w = size as f64;
            let (cx, cy) = if size % 2 == 1 {
                ((x as f64).floor() + 0.5, (y as f64).floor() + 0.5)
            } else {
                ((x as f64 + 0.5).floor(), (y as f64 + 0.5).floor())
            };
            let mut want = Px::new();
            for py in 0..N as i64 {
                for px in 0..N as i64 {
                    if ((px as f64 + 0.5) - cx).abs() < w / 2.0 && ((py as f64 + 0.5) - cy).abs() < w / 2.0 {
                        want.insert((px, py));
                    }
                }
            }
            assert_eq!(want.len(), size * size);
            assert_eq!(draw(&mut c, GL_POINTS, &[[x, y, 0.0]]), want, "size {size} at {x},{y}");
        }
    }
    // 2.4 rounds to 2; 2.5 to 3.
    c.execute(&Command::PointSize(2.4));
    assert_eq!(draw(&mut c, GL_POINTS, &[[10.5, 10.5, 0.0]]).len(), 4);
    c.execute(&Command::PointSize(2.5));
    assert_eq!(draw(&mut c, GL_POINTS, &[[10.5, 10.5, 0.0]]).len(), 9);
    // Clipped by the centre: a big point whose centre is outside draws
    // nothing, even where it would overlap the window.
    c.execute(&Command::PointSize(6.0));
    assert_eq!(draw(&mut c, GL_POINTS, &[[-0.5, 10.5, 0.0]]).len(), 0);
    assert_eq!(draw(&mut c, GL_POINTS, &[[10.5, 10.5, 1.5]]).len(), 0);
    // Centre inside, square cut by the window edge: even size 6 centres
    // on (1, 11), columns -2..4.
    assert_eq!(draw(&mut c, GL_POINTS, &[[0.5, 10.5, 0.0]]).len(), 4 * 6);
    c.take_error();
    c.execute(&Command::PointSize(0.0));
    assert_eq!(c.take_error(), GL_INVALID_VALUE);
}

#[test]
fn clipping_at_near_plane_and_window_edges() {
    let mut c = context();
    // z_ndc = -z here; z = 1 is the near plane. The line crosses it at
    // x = 16.5, which becomes the end: pixels 2..15.
    assert_eq!(draw(&mut c, GL_LINES, &[[2.5, 5.5, 0.0], [30.5, 5.5, 2.0]]), row(5, 2..16));
    // Reversed: the clipped point starts the segment; 2.5 ends it.
    assert_eq!(draw(&mut c, GL_LINES, &[[30.5, 5.5, 2.0], [2.5, 5.5, 0.0]]), row(5, 3..17));
    // Entirely beyond far: nothing.
    assert_eq!(draw(&mut c, GL_LINES, &[[2.5, 5.5, -2.0], [30.5, 5.5, -3.0]]), Px::new());
    // Across the viewport: every column.
    assert_eq!(line(&mut c, [-10.5, 7.5], [40.5, 7.5]), row(7, 0..32));
    assert_eq!(line(&mut c, [7.5, -1000.0], [7.5, 1000.0]), col(7, 0..32));
    // Diagonal from far outside, same as the diamond rule inside.
    assert_eq!(line(&mut c, [-20.0, -20.0], [50.0, 50.0]), (0..32).map(|i| (i, i)).collect());
    // Stippled lines keep counting outside the window.
    c.execute(&Command::Enable(GL_LINE_STIPPLE));
    c.execute(&Command::LineStipple(1, 0x00FF));
    let want: Px = (0..32).filter(|x| (x + 10) % 16 < 8).map(|x| (x, 7)).collect();
    assert_eq!(line(&mut c, [-9.5, 7.5], [40.5, 7.5]), want);
}

#[test]
fn line_colour_and_depth() {
    let mut c = context();
    // Smooth: colour at fragment x is at t = x / 30 between the ends.
    clear(&mut c);
    c.execute(&Command::Begin(GL_LINES));
    c.execute(&Command::Color([1.0, 0.0, 0.0, 1.0]));
    c.execute(&Command::Vertex([0.5, 3.5, 0.0, 1.0]));
    c.execute(&Command::Color([0.0, 0.0, 1.0, 1.0]));
    c.execute(&Command::Vertex([30.5, 3.5, 0.0, 1.0]));
    c.execute(&Command::End);
    for x in 0..30 {
        let t = x as f32 / 30.0;
        let px = c.fb.color[3 * N + x];
        assert_eq!(px, [((1.0 - t) * 255.0 + 0.5) as u8, 0, (t * 255.0 + 0.5) as u8, 255], "x {x}");
    }
    // Flat: the second vertex of each segment.
    c.execute(&Command::ShadeModel(GL_FLAT));
    clear(&mut c);
    c.execute(&Command::Begin(GL_LINE_STRIP));
    c.execute(&Command::Color([1.0, 0.0, 0.0, 1.0]));
    c.execute(&Command::Vertex([0.5, 3.5, 0.0, 1.0]));
    c.execute(&Command::Color([0.0, 1.0, 0.0, 1.0]));
    c.execute(&Command::Vertex([10.5, 3.5, 0.0, 1.0]));
    c.execute(&Command::Color([0.0, 0.0, 1.0, 1.0]));
    c.execute(&Command::Vertex([20.5, 3.5, 0.0, 1.0]));
    c.execute(&Command::End);
    for x in 0..20 {
        let want = if x < 10 { [0, 255, 0, 255] } else { [0, 0, 255, 255] };
        assert_eq!(c.fb.color[3 * N + x], want, "x {x}");
    }
    // Depth: a line from z_ndc -0.5 to 0.5 through a z_ndc = 0 wall.
    c.execute(&Command::ShadeModel(GL_SMOOTH));
    clear(&mut c);
    c.execute(&Command::Enable(GL_DEPTH_TEST));
    c.execute(&Command::Color([0.0, 1.0, 0.0, 1.0]));
    c.execute(&Command::Rect([0.0, 0.0, 32.0, 32.0]));
    c.execute(&Command::Color([1.0, 0.0, 0.0, 1.0]));
    // z_ndc = -z: eye z 0.5 -> -0.5 (near half), -0.5 -> 0.5.
    draw_no_clear(&mut c, &[[0.5, 8.5, 0.5], [30.5, 8.5, -0.5]]);
    for x in 0..30 {
        let red = c.fb.color[8 * N + x][0] == 255;
        // t = x / 30; z_ndc = -0.5 + t: in front while < 0.
        assert_eq!(red, x < 15, "x {x}");
    }
}

fn draw_no_clear(c: &mut Context, v: &[[f32; 3]]) {
    c.execute(&Command::Begin(GL_LINES));
    for p in v {
        c.execute(&Command::Vertex([p[0], p[1], p[2], 1.0]));
    }
    c.execute(&Command::End);
}
