//! The ARB_imaging subset (GL 1.5 sections 3.6.3 and 3.6.5): colour
//! tables, convolution, the colour matrix, histogram and minmax, through
//! glDrawPixels, glReadPixels, glCopyPixels and glTexImage. Every expected
//! value is computed by hand from the spec's formulas in the comments.

use softgl::framebuffer::Config;
use softgl::gl::enums::*;
use softgl::gl::imaging::{self as im, ImagingCmd};
use softgl::gl::texture::enums as t;
use softgl::gl::{Command, Context};

fn context(w: usize, h: usize) -> Context {
    let mut c = Context::new(Config { alpha_bits: 8, depth_bits: 24, stencil_bits: 8, accum_bits: 0 });
    c.fb.resize(w, h).unwrap();
    c.surface_resized(w as i32, h as i32);
    c.execute(&Command::RasterPos([-1.0, -1.0, 0.0, 1.0]));
    c
}

fn run(c: &mut Context, cmd: ImagingCmd) {
    c.execute(&Command::Imaging(Box::new(cmd)));
}

fn table(c: &mut Context, target: u32, ifmt: u32, data: &[[f32; 4]]) {
    run(c, ImagingCmd::ColorTable { target, internal_format: ifmt, width: data.len() as i32, data: Some(data.to_vec()) });
}

fn filter_2d(c: &mut Context, ifmt: u32, w: i32, h: i32, taps: &[[f32; 4]]) {
    run(c, ImagingCmd::ConvolutionFilter { target: GL_CONVOLUTION_2D, internal_format: ifmt, width: w, height: h, data: Some(taps.to_vec()) });
}

/// glDrawPixels of a w x h RGBA float image at the window origin.
fn draw(c: &mut Context, w: i32, h: i32, px: &[[f32; 4]]) {
    let bytes: Vec<u8> = px.iter().flat_map(|p| p.iter().flat_map(|v| v.to_ne_bytes())).collect();
    let cmd = unsafe { c.build_draw_pixels(w, h, GL_RGBA, GL_FLOAT, bytes.as_ptr()) }.unwrap();
    c.execute(&cmd);
}

/// glReadPixels as RGBA floats (w x h groups).
fn read(c: &mut Context, w: i32, h: i32) -> Vec<[f32; 4]> {
    let mut out = vec![[-1.0f32; 4]; (w * h) as usize];
    unsafe { c.read_pixels(0, 0, w, h, GL_RGBA, GL_FLOAT, out.as_mut_ptr() as *mut u8) };
    out
}

fn px(c: &Context, x: usize, y: usize) -> [u8; 4] {
    c.fb.color[c.fb.index(x, y)]
}

fn grey(v: f32) -> [f32; 4] {
    [v, v, v, 1.0]
}

fn close(a: [f32; 4], b: [f32; 4]) -> bool {
    a.iter().zip(&b).all(|(x, y)| (x - y).abs() < 1e-5)
}

#[test]
fn color_table_lookup_by_base_format() {
    let mut c = context(4, 1);
    // An RGBA table of 4 entries: index round(c * 3).
    let entries = [[0.0, 0.2, 0.4, 0.6], [1.0, 0.8, 0.6, 0.4], [0.2, 0.2, 0.2, 0.2], [0.4, 0.0, 1.0, 0.0]];
    table(&mut c, GL_COLOR_TABLE, GL_RGBA, &entries);
    assert_eq!(c.take_error(), GL_NO_ERROR);
    c.execute(&Command::Enable(GL_COLOR_TABLE));
    // R = 1/3 -> entry 1's R; G = 1 -> entry 3's G; B = 0 -> entry 0's B;
    // A = 0.6 -> round(1.8) = 2 -> entry 2's A.
    draw(&mut c, 1, 1, &[[1.0 / 3.0, 1.0, 0.0, 0.6]]);
    assert_eq!(px(&c, 0, 0), [255, 0, 102, 51]);
    // A LUMINANCE table replaces R, G, B by L[index] (L is the data's R)
    // and leaves A.
    // R = 0 -> L[0]; G = 0.5 -> round(1.5) = 2 -> L[2]; B = 1 -> L[3].
    table(&mut c, GL_COLOR_TABLE, GL_LUMINANCE, &[grey(0.0), grey(0.5), grey(1.0), grey(0.25)]);
    draw(&mut c, 1, 1, &[[0.0, 0.5, 1.0, 0.3]]);
    assert_eq!(px(&c, 0, 0), [0, 255, 64, 77]);
    // An ALPHA table changes only A.
    table(&mut c, GL_COLOR_TABLE, GL_ALPHA, &[[0.0, 0.0, 0.0, 0.9], [0.0, 0.0, 0.0, 0.1]]);
    draw(&mut c, 1, 1, &[[0.2, 0.4, 0.6, 1.0]]);
    assert_eq!(px(&c, 0, 0), [51, 102, 153, 26]);
    // COLOR_TABLE_SCALE and _BIAS apply when the table is specified.
    run(&mut c, ImagingCmd::ColorTableParameter { target: GL_COLOR_TABLE, pname: im::GL_COLOR_TABLE_SCALE, v: [0.5; 4] });
    run(&mut c, ImagingCmd::ColorTableParameter { target: GL_COLOR_TABLE, pname: im::GL_COLOR_TABLE_BIAS, v: [0.1, 0.0, 0.0, 0.0] });
    table(&mut c, GL_COLOR_TABLE, GL_RGB, &[[1.0, 1.0, 1.0, 1.0], [0.4, 0.4, 0.4, 1.0]]);
    draw(&mut c, 1, 1, &[[0.0, 1.0, 0.0, 0.5]]);
    // R: entry 0: 1 * 0.5 + 0.1 = 0.6; G: entry 1: 0.2; B: entry 0: 0.5.
    assert_eq!(px(&c, 0, 0), [153, 51, 128, 128]);
    let mut out = vec![[0.0f32; 4]; 2];
    unsafe { c.get_color_table(GL_COLOR_TABLE, GL_RGBA, GL_FLOAT, out.as_mut_ptr() as *mut u8) };
    assert!(close(out[0], [0.6, 0.5, 0.5, 1.0]) && close(out[1], [0.3, 0.2, 0.2, 1.0]), "{out:?}");
    // Disabled: no lookup.
    c.execute(&Command::Disable(GL_COLOR_TABLE));
    draw(&mut c, 1, 1, &[[0.0, 1.0, 0.0, 0.5]]);
    assert_eq!(px(&c, 0, 0), [0, 255, 0, 128]);
}

#[test]
fn convolution_reduce_shrinks_the_image() {
    let mut c = context(4, 4);
    c.execute(&Command::ClearColor([0.0, 0.0, 1.0, 1.0]));
    c.execute(&Command::Clear(GL_COLOR_BUFFER_BIT));
    // A 3x3 image of R = i + 3 j (over 8), a 2x2 box filter of 1/4: the
    // 2x2 result at (i, j) is the mean of the 4 pixels from (i, j).
    let img: Vec<[f32; 4]> = (0..9).map(|n| [n as f32 / 8.0, 0.0, 0.0, 1.0]).collect();
    filter_2d(&mut c, GL_RGBA, 2, 2, &[[0.25; 4]; 4]);
    c.execute(&Command::Enable(GL_CONVOLUTION_2D));
    draw(&mut c, 3, 3, &img);
    assert_eq!(c.take_error(), GL_NO_ERROR);
    for (x, y) in [(0, 0), (1, 0), (0, 1), (1, 1)] {
        let mean = (x + 3 * y) as f32 + 2.0; // (n + n+1 + n+3 + n+4) / 4
        assert_eq!(px(&c, x, y), [(mean / 8.0 * 255.0).round() as u8, 0, 0, 255], "{x},{y}");
    }
    // The third column and row are not drawn.
    assert_eq!(px(&c, 2, 0), [0, 0, 255, 255]);
    assert_eq!(px(&c, 0, 2), [0, 0, 255, 255]);
}

#[test]
fn convolution_border_modes_and_post_scale_bias() {
    let mut c = context(4, 1);
    // A 1x3 horizontal filter (1, 1, 1) on a 3x1 image 0.1, 0.2, 0.3.
    filter_2d(&mut c, GL_LUMINANCE, 3, 1, &[grey(1.0); 3]);
    c.execute(&Command::Enable(GL_CONVOLUTION_2D));
    let img = [[0.1, 0.0, 0.0, 0.5], [0.2, 0.0, 0.0, 0.5], [0.3, 0.0, 0.0, 0.5]];
    run(&mut c, ImagingCmd::ConvolutionParameter { target: GL_CONVOLUTION_2D, pname: im::GL_CONVOLUTION_BORDER_MODE, v: [im::GL_CONSTANT_BORDER as f32, 0.0, 0.0, 0.0] });
    run(&mut c, ImagingCmd::ConvolutionParameter { target: GL_CONVOLUTION_2D, pname: im::GL_CONVOLUTION_BORDER_COLOR, v: [0.05, 0.0, 0.0, 0.0] });
    draw(&mut c, 3, 1, &img);
    // (ReadPixels would convolve too: off while reading.)
    c.execute(&Command::Disable(GL_CONVOLUTION_2D));
    // Constant border 0.05: 0.05+0.1+0.2, 0.1+0.2+0.3, 0.2+0.3+0.05;
    // a luminance filter leaves A (0.5) alone.
    let got = read(&mut c, 3, 1);
    for (g, want) in got.iter().zip([0.35f32, 0.6, 0.55]) {
        assert!((g[0] - want).abs() < 1.0 / 255.0, "{got:?}");
        assert!((g[3] - 128.0 / 255.0).abs() < 1e-6);
    }
    c.execute(&Command::Enable(GL_CONVOLUTION_2D));
    // Replicate: the edges repeat: 0.1+0.1+0.2, 0.6, 0.2+0.3+0.3; then the
    // post-convolution scale 0.5 and bias 0.1 on R.
    run(&mut c, ImagingCmd::ConvolutionParameter { target: GL_CONVOLUTION_2D, pname: im::GL_CONVOLUTION_BORDER_MODE, v: [im::GL_REPLICATE_BORDER as f32, 0.0, 0.0, 0.0] });
    c.execute(&Command::PixelTransfer(0x801C, 0.5));
    c.execute(&Command::PixelTransfer(0x8020, 0.1));
    draw(&mut c, 3, 1, &img);
    c.execute(&Command::Disable(GL_CONVOLUTION_2D));
    let got = read(&mut c, 3, 1);
    for (g, want) in got.iter().zip([0.4f32 * 0.5 + 0.1, 0.6 * 0.5 + 0.1, 0.8 * 0.5 + 0.1]) {
        assert!((g[0] - want).abs() < 1.0 / 255.0, "{got:?}");
    }
}

#[test]
fn separable_filter_is_row_times_column() {
    let mut c = context(4, 4);
    // Row (1, 2), column (0.5, 0.25): F[m][n] = row[m] col[n]. On a 2x2
    // image p00 .. p11 (REDUCE): one pixel 0.5 p00 + 1 p10 + 0.25 p01 + 0.5 p11.
    run(&mut c, ImagingCmd::SeparableFilter { target: GL_SEPARABLE_2D, internal_format: GL_RGBA, width: 2, height: 2, row: Some(vec![[1.0; 4], [2.0; 4]]), column: Some(vec![[0.5; 4], [0.25; 4]]) });
    c.execute(&Command::Enable(GL_SEPARABLE_2D));
    let img = [[0.2, 0.0, 0.0, 0.0], [0.1, 0.0, 0.0, 0.0], [0.4, 0.0, 0.0, 0.0], [0.2, 0.0, 0.0, 0.0]];
    draw(&mut c, 2, 2, &img);
    let r = 0.5 * 0.2 + 1.0 * 0.1 + 0.25 * 0.4 + 0.5 * 0.2;
    assert_eq!(px(&c, 0, 0)[0], (r * 255.0f32).round() as u8);
    let mut row = [[0.0f32; 4]; 2];
    let mut col = [[0.0f32; 4]; 2];
    unsafe { c.get_convolution_filter(GL_SEPARABLE_2D, GL_RGBA, GL_FLOAT, row.as_mut_ptr() as *mut u8, Some(col.as_mut_ptr() as *mut u8)) };
    assert_eq!((row, col), ([[1.0; 4], [2.0; 4]], [[0.5; 4], [0.25; 4]]));
    // CONVOLUTION_2D wins over SEPARABLE_2D when both are on.
    filter_2d(&mut c, GL_RGBA, 1, 1, &[[2.0; 4]]);
    c.execute(&Command::Enable(GL_CONVOLUTION_2D));
    draw(&mut c, 1, 1, &[[0.25, 0.0, 0.0, 0.0]]);
    assert_eq!(px(&c, 0, 0)[0], 128);
}

#[test]
fn color_matrix_and_stage_order() {
    let mut c = context(2, 1);
    // A colour matrix that swaps R and G and halves B (column-major).
    let m = glam::DMat4::from_cols_array(&[0.0, 1.0, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.5, 0.0, 0.0, 0.0, 0.0, 1.0]);
    c.execute(&Command::MatrixMode(GL_COLOR));
    c.execute(&Command::LoadMatrix(Box::new(m)));
    assert_eq!(c.take_error(), GL_NO_ERROR);
    assert_eq!(c.get(im::GL_COLOR_MATRIX).unwrap().as_f64()[1], 1.0);
    draw(&mut c, 1, 1, &[[0.2, 0.6, 0.8, 1.0]]);
    assert_eq!(px(&c, 0, 0), [153, 51, 102, 255]);
    // Post-colour-matrix bias on alpha: -0.5.
    c.execute(&Command::PixelTransfer(0x80BB, -0.5));
    draw(&mut c, 1, 1, &[[0.2, 0.6, 0.8, 1.0]]);
    assert_eq!(px(&c, 0, 0), [153, 51, 102, 128]);
    c.execute(&Command::PixelTransfer(0x80BB, 0.0));
    // Order: COLOR_TABLE (a 2-entry threshold on R: index round(R)) comes
    // before the matrix. R = 0.4 -> 0 -> G = 0; if the matrix came first,
    // R would be 0.6 (the old G) -> 1.
    c.execute(&Command::LoadMatrix(Box::new(m)));
    table(&mut c, GL_COLOR_TABLE, GL_RGB, &[[0.0, 0.6, 0.8, 1.0], [1.0, 0.6, 0.8, 1.0]]);
    c.execute(&Command::Enable(GL_COLOR_TABLE));
    draw(&mut c, 1, 1, &[[0.4, 0.6, 0.8, 1.0]]);
    // G index round(0.6) = 1 -> G = 0.6; matrix: R' = G = 0.6, G' = R = 0.
    assert_eq!(px(&c, 0, 0)[..2], [153, 0]);
    // The post-colour-matrix table sees the matrix's output: a luminance
    // table (1, 0.5) on R' = 0.6 (index 1) and G' = 0 (index 0).
    table(&mut c, GL_POST_COLOR_MATRIX_COLOR_TABLE, GL_LUMINANCE, &[grey(1.0), grey(0.5)]);
    c.execute(&Command::Enable(GL_POST_COLOR_MATRIX_COLOR_TABLE));
    draw(&mut c, 1, 1, &[[0.4, 0.6, 0.8, 1.0]]);
    assert_eq!(px(&c, 0, 0)[..2], [128, 255]);
    // The stack: push, change, pop.
    c.execute(&Command::PushMatrix);
    assert_eq!(c.get(im::GL_COLOR_MATRIX_STACK_DEPTH).unwrap().as_f64()[0], 2.0);
    c.execute(&Command::LoadIdentity);
    c.execute(&Command::PopMatrix);
    assert_eq!(c.get(im::GL_COLOR_MATRIX).unwrap().as_f64()[1], 1.0);
}

#[test]
fn histogram_and_minmax() {
    let mut c = context(4, 1);
    run(&mut c, ImagingCmd::Histogram { target: GL_HISTOGRAM, width: 4, internal_format: GL_RGBA, sink: false });
    run(&mut c, ImagingCmd::Minmax { target: GL_MINMAX, internal_format: GL_RGB, sink: false });
    c.execute(&Command::Enable(GL_HISTOGRAM));
    c.execute(&Command::Enable(GL_MINMAX));
    // R: 0, 0.3 (bin round(0.9) = 1), 0.7 (round(2.1) = 2), 1 (bin 3);
    // G all 0.5 (bin round(1.5) = 2); B 0.1, 0.2, 0.2, 0.9; A all 1.
    draw(&mut c, 4, 1, &[[0.0, 0.5, 0.1, 1.0], [0.3, 0.5, 0.2, 1.0], [0.7, 0.5, 0.2, 1.0], [1.0, 0.5, 0.9, 1.0]]);
    assert_eq!(px(&c, 2, 0), [179, 128, 51, 255], "drawn: no sink");
    let mut h = [[0u32; 4]; 4];
    unsafe { c.get_histogram(GL_HISTOGRAM, true, GL_RGBA, GL_UNSIGNED_INT, h.as_mut_ptr() as *mut u8) };
    assert_eq!(c.take_error(), GL_NO_ERROR);
    // B: 0.1 -> 0, 0.2 -> round(0.6) = 1 (twice), 0.9 -> round(2.7) = 3.
    assert_eq!(h, [[1, 0, 1, 0], [1, 0, 2, 0], [1, 4, 0, 0], [1, 0, 1, 4]]);
    let mut mm = [[0.0f32; 4]; 2];
    unsafe { c.get_minmax(GL_MINMAX, false, GL_RGBA, GL_FLOAT, mm.as_mut_ptr() as *mut u8) };
    // An RGB minmax: alpha reads 1 (table 6.1's default).
    assert!(close(mm[0], [0.0, 0.5, 0.1, 1.0]) && close(mm[1], [1.0, 0.5, 0.9, 1.0]), "{mm:?}");
    // Reset by the query: all zero now.
    unsafe { c.get_histogram(GL_HISTOGRAM, false, GL_RGBA, GL_UNSIGNED_INT, h.as_mut_ptr() as *mut u8) };
    assert_eq!(h, [[0; 4]; 4]);
    // A sink histogram consumes the groups: nothing is drawn.
    run(&mut c, ImagingCmd::Histogram { target: GL_HISTOGRAM, width: 2, internal_format: GL_LUMINANCE, sink: true });
    draw(&mut c, 1, 1, &[[0.9, 0.0, 0.0, 1.0]]);
    assert_eq!(px(&c, 0, 0), [0, 128, 26, 255], "sink: the old pixel stays");
    let mut h2 = [0u16; 2];
    unsafe { c.get_histogram(GL_HISTOGRAM, false, GL_LUMINANCE, GL_UNSIGNED_SHORT, h2.as_mut_ptr() as *mut u8) };
    assert_eq!(h2, [0, 1]);
    let q = |c: &mut Context, p: u32| c.get_histogram_parameter(GL_HISTOGRAM, p).unwrap().as_f64()[0];
    assert_eq!((q(&mut c, im::GL_HISTOGRAM_WIDTH), q(&mut c, im::GL_HISTOGRAM_FORMAT), q(&mut c, im::GL_HISTOGRAM_SINK)), (2.0, GL_LUMINANCE as f64, 1.0));
}

#[test]
fn tex_image_and_read_copy_pixels() {
    let mut c = context(4, 4);
    // TexImage2D of a 4x4 image with a 3x3 REDUCE filter: a 2x2 texture.
    filter_2d(&mut c, GL_RGBA, 3, 3, &[[1.0 / 9.0; 4]; 9]);
    c.execute(&Command::Enable(GL_CONVOLUTION_2D));
    let img: Vec<u8> = (0..16).flat_map(|n| [(n * 10) as u8, 0, 0, 255]).collect();
    let cmd = unsafe { c.tex_image_command(2, t::GL_TEXTURE_2D, 0, t::GL_RGBA8 as i32, [4, 4, 1], 0, t::GL_RGBA, t::GL_UNSIGNED_BYTE, img.as_ptr()) }.unwrap();
    c.execute(&cmd);
    assert_eq!(c.take_error(), GL_NO_ERROR);
    let width = c.get_tex_level_parameter(t::GL_TEXTURE_2D, 0, t::GL_TEXTURE_WIDTH).unwrap().as_f64()[0];
    assert_eq!(width, 2.0);
    let mut tex = [[0u8; 4]; 4];
    unsafe { c.get_tex_image(t::GL_TEXTURE_2D, 0, t::GL_RGBA, t::GL_UNSIGNED_BYTE, tex.as_mut_ptr() as *mut u8) };
    // Texel (0, 0): the mean of n = i + 4 j over i, j in 0..3: 5 -> 50.
    // (0, 1) and (1, 1): 60, 90, 100.
    assert_eq!(tex.map(|p| p[0]), [50, 60, 90, 100]);
    c.execute(&Command::Disable(GL_CONVOLUTION_2D));
    // ReadPixels goes through the stages: an RGBA colour matrix that
    // doubles R.
    c.execute(&Command::ClearColor([0.25, 0.5, 0.0, 1.0]));
    c.execute(&Command::Clear(GL_COLOR_BUFFER_BIT));
    c.execute(&Command::MatrixMode(GL_COLOR));
    c.execute(&Command::Scale([2.0, 1.0, 1.0]));
    let got = read(&mut c, 1, 1);
    assert!((got[0][0] - 2.0 * 64.0 / 255.0).abs() < 1e-6 && (got[0][1] - 128.0 / 255.0).abs() < 1e-6, "{got:?}");
    // CopyPixels too: (64, 128) -> (128, 128) copied to (2, 2).
    c.execute(&Command::RasterPos([0.0, 0.0, 0.0, 1.0]));
    c.copy_pixels(0, 0, 1, 1, GL_COLOR);
    assert_eq!(px(&c, 2, 2), [128, 128, 0, 255]);
    assert_eq!(px(&c, 1, 1), [64, 128, 0, 255]);
}

#[test]
fn errors_queries_and_proxies() {
    let mut c = context(2, 2);
    // Width not a power of two; an internal format that is not a colour
    // base format; a target that is not a table.
    table(&mut c, GL_COLOR_TABLE, GL_RGBA, &[[0.0; 4]; 3]);
    assert_eq!(c.take_error(), GL_INVALID_VALUE);
    table(&mut c, GL_COLOR_TABLE, t::GL_DEPTH_COMPONENT, &[[0.0; 4]; 2]);
    assert_eq!(c.take_error(), GL_INVALID_ENUM);
    table(&mut c, GL_TEXTURE_2D, GL_RGBA, &[[0.0; 4]; 2]);
    assert_eq!(c.take_error(), GL_INVALID_ENUM);
    // Too large: TABLE_TOO_LARGE, the proxy answers width 0.
    run(&mut c, ImagingCmd::ColorTable { target: GL_COLOR_TABLE, internal_format: GL_RGBA, width: 512, data: None });
    assert_eq!(c.take_error(), im::GL_TABLE_TOO_LARGE);
    run(&mut c, ImagingCmd::ColorTable { target: im::GL_PROXY_COLOR_TABLE, internal_format: GL_RGBA, width: 512, data: None });
    assert_eq!(c.get_color_table_parameter(im::GL_PROXY_COLOR_TABLE, im::GL_COLOR_TABLE_WIDTH).unwrap().as_f64()[0], 0.0);
    run(&mut c, ImagingCmd::ColorTable { target: im::GL_PROXY_COLOR_TABLE, internal_format: t::GL_LUMINANCE8, width: 64, data: None });
    let q = |c: &mut Context, p: u32| c.get_color_table_parameter(im::GL_PROXY_COLOR_TABLE, p).unwrap().as_f64()[0];
    assert_eq!((q(&mut c, im::GL_COLOR_TABLE_WIDTH), q(&mut c, im::GL_COLOR_TABLE_FORMAT), q(&mut c, 0x80DE)), (64.0, t::GL_LUMINANCE8 as f64, 8.0));
    assert_eq!(c.take_error(), GL_NO_ERROR);
    assert_eq!(c.get_color_table_parameter(GL_COLOR_TABLE, im::GL_COLOR_TABLE_RED_SIZE).unwrap().as_f64()[0], 0.0, "no table yet");
    // Sub-tables must fit.
    table(&mut c, GL_COLOR_TABLE, GL_RGBA, &[[0.0; 4]; 4]);
    run(&mut c, ImagingCmd::ColorSubTable { target: GL_COLOR_TABLE, start: 3, count: 2, data: None });
    assert_eq!(c.take_error(), GL_INVALID_VALUE);
    // Convolution filters are at most MAX_CONVOLUTION_WIDTH wide.
    let max = c.get_convolution_parameter(GL_CONVOLUTION_2D, im::GL_MAX_CONVOLUTION_WIDTH).unwrap().as_f64()[0] as i32;
    filter_2d(&mut c, GL_RGBA, max + 1, 1, &[]);
    assert_eq!(c.take_error(), GL_INVALID_VALUE);
    run(&mut c, ImagingCmd::ConvolutionParameter { target: GL_CONVOLUTION_2D, pname: im::GL_CONVOLUTION_BORDER_MODE, v: [GL_ONE as f32, 0.0, 0.0, 0.0] });
    assert_eq!(c.take_error(), GL_INVALID_ENUM);
    assert_eq!(c.get_convolution_parameter(GL_CONVOLUTION_2D, im::GL_CONVOLUTION_BORDER_MODE).unwrap().as_f64()[0], im::GL_REDUCE as f64);
    run(&mut c, ImagingCmd::Histogram { target: GL_HISTOGRAM, width: 3, internal_format: GL_RGBA, sink: false });
    assert_eq!(c.take_error(), GL_INVALID_VALUE);
    run(&mut c, ImagingCmd::Minmax { target: GL_MINMAX, internal_format: t::GL_DEPTH_COMPONENT, sink: false });
    assert_eq!(c.take_error(), GL_INVALID_ENUM);
    // Get* take colour formats only.
    let mut out = [0u8; 64];
    unsafe { c.get_color_table(GL_COLOR_TABLE, t::GL_DEPTH_COMPONENT, GL_FLOAT, out.as_mut_ptr()) };
    assert_eq!(c.take_error(), GL_INVALID_ENUM);
    // Post-convolution scale is pixel-transfer state, queryable.
    c.execute(&Command::PixelTransfer(0x801D, 3.0));
    assert_eq!(c.get(0x801D).unwrap().as_f64()[0], 3.0);
}

#[test]
fn display_lists_record_imaging_commands() {
    let mut c = context(1, 1);
    c.execute(&Command::Imaging(Box::new(ImagingCmd::Histogram { target: GL_HISTOGRAM, width: 2, internal_format: GL_RGBA, sink: false })));
    let list = c.gen_lists(1);
    c.new_list(list, GL_COMPILE);
    c.submit(Command::Imaging(Box::new(ImagingCmd::ColorTable { target: GL_COLOR_TABLE, internal_format: GL_RGBA, width: 2, data: Some(vec![[1.0; 4], [0.0; 4]]) })));
    c.end_list();
    assert_eq!(c.imaging.tables[0].width, 0, "compiled, not executed");
    c.execute(&Command::CallList(list));
    c.execute(&Command::Enable(GL_COLOR_TABLE));
    draw(&mut c, 1, 1, &[[0.0, 1.0, 0.0, 1.0]]);
    // Entries (1, 1, 1, 1) and (0, 0, 0, 0): an inverting threshold.
    assert_eq!(px(&c, 0, 0), [255, 0, 255, 0]);
}

#[test]
fn convolution_1d_on_1d_textures_and_push_attrib() {
    let mut c = context(2, 2);
    // A 1D filter (0.5, 0.5) with REDUCE: a 3-texel 1D image becomes 2
    // texels, each the mean of two neighbours.
    run(&mut c, ImagingCmd::ConvolutionFilter { target: GL_CONVOLUTION_1D, internal_format: GL_RGBA, width: 2, height: 1, data: Some(vec![[0.5; 4]; 2]) });
    c.execute(&Command::Enable(GL_CONVOLUTION_1D));
    let img: [u8; 12] = [0, 0, 0, 255, 100, 0, 0, 255, 200, 0, 0, 255];
    let cmd = unsafe { c.tex_image_command(1, t::GL_TEXTURE_1D, 0, t::GL_RGBA8 as i32, [3, 1, 1], 0, t::GL_RGBA, t::GL_UNSIGNED_BYTE, img.as_ptr()) }.unwrap();
    c.execute(&cmd);
    assert_eq!(c.take_error(), GL_NO_ERROR);
    let mut tex = [[0u8; 4]; 2];
    unsafe { c.get_tex_image(t::GL_TEXTURE_1D, 0, t::GL_RGBA, t::GL_UNSIGNED_BYTE, tex.as_mut_ptr() as *mut u8) };
    assert_eq!(tex, [[50, 0, 0, 255], [150, 0, 0, 255]]);
    // 2D images ignore CONVOLUTION_1D.
    draw(&mut c, 2, 1, &[[0.0, 0.0, 0.0, 1.0], [0.4, 0.0, 0.0, 1.0]]);
    assert_eq!(px(&c, 1, 0), [102, 0, 0, 255]);
    // GL_PIXEL_MODE_BIT saves the filter parameters and post-convolution
    // scale; not the filter itself.
    c.execute(&Command::PushAttrib(softgl::gl::attrib::GL_PIXEL_MODE_BIT));
    run(&mut c, ImagingCmd::ConvolutionParameter { target: GL_CONVOLUTION_1D, pname: im::GL_CONVOLUTION_BORDER_MODE, v: [im::GL_REPLICATE_BORDER as f32, 0.0, 0.0, 0.0] });
    c.execute(&Command::PixelTransfer(0x801C, 2.0));
    run(&mut c, ImagingCmd::ConvolutionFilter { target: GL_CONVOLUTION_1D, internal_format: GL_RGBA, width: 3, height: 1, data: Some(vec![[0.5; 4]; 3]) });
    c.execute(&Command::PopAttrib);
    assert_eq!(c.get_convolution_parameter(GL_CONVOLUTION_1D, im::GL_CONVOLUTION_BORDER_MODE).unwrap().as_f64()[0], im::GL_REDUCE as f64);
    assert_eq!(c.get(0x801C).unwrap().as_f64()[0], 1.0);
    assert_eq!(c.get_convolution_parameter(GL_CONVOLUTION_1D, im::GL_CONVOLUTION_WIDTH).unwrap().as_f64()[0], 3.0);
}

#[test]
fn advertised() {
    let s = softgl::gl::get::string(GL_EXTENSIONS).unwrap();
    let s = std::str::from_utf8(&s[..s.len() - 1]).unwrap();
    assert!(s.split(' ').any(|n| n == "GL_ARB_imaging"));
}

/// RGBA / UNSIGNED_BYTE images (kept as bytes, with their own fast path
/// at unit zoom) go through the imaging stages too: an RGBA colour table
/// that swaps red and blue.
#[test]
fn byte_images_take_the_imaging_stages() {
    let mut c = context(2, 1);
    let entries: Vec<[f32; 4]> = (0..256).map(|i| {
        let v = i as f32 / 255.0;
        [1.0 - v, v, v, 1.0]
    }).collect();
    table(&mut c, GL_COLOR_TABLE, GL_RGBA, &entries);
    c.execute(&Command::Enable(GL_COLOR_TABLE));
    let img: [u8; 8] = [255, 10, 20, 255, 0, 128, 200, 255];
    let cmd = unsafe { c.build_draw_pixels(2, 1, GL_RGBA, GL_UNSIGNED_BYTE, img.as_ptr()) }.unwrap();
    c.execute(&cmd);
    // R -> 1 - R; G, B, A looked up as themselves.
    assert_eq!(px(&c, 0, 0), [0, 10, 20, 255]);
    assert_eq!(px(&c, 1, 0), [255, 128, 200, 255]);
    // Without the table the bytes are drawn as they are.
    c.execute(&Command::Disable(GL_COLOR_TABLE));
    c.execute(&cmd);
    assert_eq!(px(&c, 0, 0), [255, 10, 20, 255]);
}
