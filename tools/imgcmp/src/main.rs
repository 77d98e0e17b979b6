//! imgcmp: compare a rendered image against a golden PNG.
//!
//! Usage:
//!   imgcmp ACTUAL GOLDEN [--tol N] [--max-bad K] [--crop X Y]
//!   imgcmp --to-png IN OUT.png
//!   imgcmp --stats IMG [X Y W H]
//!
//! ACTUAL is a PAM (P7, RGB_ALPHA or RGB, maxval 255, rows top-down) or any
//! image the `image` crate reads (PNG, PNM). GOLDEN is a PNG. Both are
//! compared as RGBA8. A pixel is bad if any channel differs by more than N
//! (default 1). Exit 0 if the sizes match and the number of bad pixels is at
//! most K (default 0); otherwise print a summary and exit 1, writing ACTUAL
//! as `<golden stem>.actual.png` beside the golden. `--crop X Y` compares
//! the golden-sized rectangle of ACTUAL whose top-left corner is (X, Y)
//! (a window in a screenshot of the screen against the window's frame).
//!
//! `--stats` prints how many pixels of IMG (or of its rectangle) are dark
//! (every channel below 32), mostly red, green or blue (that channel at
//! least 48 and above twice each other one), or other, and the range of
//! the dominant channel within each of the three (how much lighting
//! shades them; 0 0 when none):
//! `WxH dark N red N green N blue N other N levels R0 R1 G0 G1 B0 B1`.

use image::RgbaImage;
use std::path::{Path, PathBuf};
use std::process::ExitCode;

const USAGE: &str = "usage: imgcmp ACTUAL GOLDEN [--tol N] [--max-bad K] [--crop X Y]\n       imgcmp --to-png IN OUT.png\n       imgcmp --stats IMG [X Y W H]";

/// `--stats`: pixel counts by dominant colour.
fn stats(img: &RgbaImage) -> String {
    let (mut dark, mut other) = (0u64, 0u64);
    // Per class: count, lowest and highest dominant channel.
    let mut class = [(0u64, 255u32, 0u32); 3];
    for p in img.pixels() {
        let [r, g, b, _] = p.0.map(u32::from);
        let dominant = |c: u32, o1: u32, o2: u32| c >= 48 && c > 2 * o1 && c > 2 * o2;
        let k = if r < 32 && g < 32 && b < 32 {
            dark += 1;
            continue;
        } else if dominant(r, g, b) {
            (0, r)
        } else if dominant(g, r, b) {
            (1, g)
        } else if dominant(b, r, g) {
            (2, b)
        } else {
            other += 1;
            continue;
        };
        let c = &mut class[k.0];
        *c = (c.0 + 1, c.1.min(k.1), c.2.max(k.1));
    }
    let level = |c: (u64, u32, u32)| if c.0 == 0 { (0, 0) } else { (c.1, c.2) };
    let (r, g, b) = (level(class[0]), level(class[1]), level(class[2]));
    format!(
        "{}x{} dark {dark} red {} green {} blue {} other {other} levels {} {} {} {} {} {}",
        img.width(),
        img.height(),
        class[0].0,
        class[1].0,
        class[2].0,
        r.0,
        r.1,
        g.0,
        g.1,
        b.0,
        b.1
    )
}

/// The `w`x`h` rectangle of `img` at (`x`, `y`), or an error if it is not
/// inside.
fn crop(img: &RgbaImage, x: u32, y: u32, w: u32, h: u32) -> Result<RgbaImage, String> {
    if x.checked_add(w).is_none_or(|e| e > img.width()) || y.checked_add(h).is_none_or(|e| e > img.height()) {
        return Err(format!("rectangle {w}x{h} at ({x},{y}) is outside the {}x{} image", img.width(), img.height()));
    }
    Ok(image::imageops::crop_imm(img, x, y, w, h).to_image())
}

fn load(path: &Path) -> Result<RgbaImage, String> {
    let err = |e: &dyn std::fmt::Display| format!("{}: {}", path.display(), e);
    // Guess the format from the contents, so the file name does not matter.
    let img = image::ImageReader::open(path)
        .map_err(|e| err(&e))?
        .with_guessed_format()
        .map_err(|e| err(&e))?
        .decode()
        .map_err(|e| err(&e))?;
    Ok(img.to_rgba8())
}

fn actual_path_for(golden: &Path) -> PathBuf {
    let stem = golden
        .file_stem()
        .map(|s| s.to_string_lossy().into_owned())
        .unwrap_or_else(|| "image".to_string());
    golden.with_file_name(format!("{stem}.actual.png"))
}

struct Diff {
    bad: u64,
    max_diff: u8,
    rmse: f64,
    first_bad: Vec<(u32, u32, [u8; 4], [u8; 4])>,
}

fn compare(a: &RgbaImage, g: &RgbaImage, tol: u8) -> Diff {
    let mut bad = 0u64;
    let mut max_diff = 0u8;
    let mut sum_sq = 0f64;
    let mut first_bad = Vec::new();
    for (x, y, pa) in a.enumerate_pixels() {
        let pg = g.get_pixel(x, y);
        let mut is_bad = false;
        for c in 0..4 {
            let d = pa.0[c].abs_diff(pg.0[c]);
            max_diff = max_diff.max(d);
            sum_sq += f64::from(d) * f64::from(d);
            if d > tol {
                is_bad = true;
            }
        }
        if is_bad {
            bad += 1;
            if first_bad.len() < 10 {
                first_bad.push((x, y, pa.0, pg.0));
            }
        }
    }
    let n = f64::from(a.width()) * f64::from(a.height()) * 4.0;
    let rmse = if n > 0.0 { (sum_sq / n).sqrt() } else { 0.0 };
    Diff {
        bad,
        max_diff,
        rmse,
        first_bad,
    }
}

fn parse_num(args: &[String], i: usize, flag: &str) -> Result<u64, String> {
    args.get(i)
        .ok_or_else(|| format!("{flag} needs a value"))?
        .parse::<u64>()
        .map_err(|e| format!("{flag}: {e}"))
}

fn run(args: &[String]) -> Result<bool, String> {
    if args.first().map(String::as_str) == Some("--to-png") {
        if args.len() != 3 {
            return Err(USAGE.to_string());
        }
        let img = load(Path::new(&args[1]))?;
        img.save_with_format(&args[2], image::ImageFormat::Png)
            .map_err(|e| format!("{}: {}", args[2], e))?;
        return Ok(true);
    }
    if args.first().map(String::as_str) == Some("--stats") {
        let img = load(Path::new(args.get(1).ok_or(USAGE)?))?;
        let img = match args.len() {
            2 => img,
            6 => {
                let n = |i| parse_num(args, i, "--stats").map(|v| v.min(u64::from(u32::MAX)) as u32);
                crop(&img, n(2)?, n(3)?, n(4)?, n(5)?)?
            }
            _ => return Err(USAGE.to_string()),
        };
        println!("{}", stats(&img));
        return Ok(true);
    }

    let mut positional = Vec::new();
    let mut tol: u64 = 1;
    let mut max_bad: u64 = 0;
    let mut crop_at: Option<(u32, u32)> = None;
    let mut i = 0;
    while i < args.len() {
        match args[i].as_str() {
            "--crop" => {
                let n = |i| parse_num(args, i, "--crop").map(|v| v.min(u64::from(u32::MAX)) as u32);
                crop_at = Some((n(i + 1)?, n(i + 2)?));
                i += 3;
            }
            "--tol" => {
                tol = parse_num(args, i + 1, "--tol")?;
                i += 2;
            }
            "--max-bad" => {
                max_bad = parse_num(args, i + 1, "--max-bad")?;
                i += 2;
            }
            "-h" | "--help" => {
                println!("{USAGE}");
                return Ok(true);
            }
            s if s.starts_with("--") => return Err(format!("unknown option {s}\n{USAGE}")),
            _ => {
                positional.push(args[i].clone());
                i += 1;
            }
        }
    }
    if positional.len() != 2 {
        return Err(USAGE.to_string());
    }
    let tol = u8::try_from(tol.min(255)).unwrap_or(255);
    let actual_path = Path::new(&positional[0]);
    let golden_path = Path::new(&positional[1]);
    let actual = load(actual_path)?;
    let golden = load(golden_path)?;
    let actual = match crop_at {
        Some((x, y)) => crop(&actual, x, y, golden.width(), golden.height())?,
        None => actual,
    };

    let write_actual = |img: &RgbaImage| {
        let out = actual_path_for(golden_path);
        match img.save_with_format(&out, image::ImageFormat::Png) {
            Ok(()) => println!("  actual written to {}", out.display()),
            Err(e) => println!("  could not write {}: {}", out.display(), e),
        }
    };

    if actual.dimensions() != golden.dimensions() {
        println!(
            "imgcmp: size mismatch: actual {}x{}, golden {}x{} ({})",
            actual.width(),
            actual.height(),
            golden.width(),
            golden.height(),
            golden_path.display()
        );
        write_actual(&actual);
        return Ok(false);
    }

    let d = compare(&actual, &golden, tol);
    if d.bad <= max_bad {
        return Ok(true);
    }
    println!(
        "imgcmp: {} vs {}: size {}x{}, {} bad pixels (tol {}, max-bad {}), max channel diff {}, RMSE {:.3}",
        actual_path.display(),
        golden_path.display(),
        actual.width(),
        actual.height(),
        d.bad,
        tol,
        max_bad,
        d.max_diff,
        d.rmse
    );
    for (x, y, pa, pg) in &d.first_bad {
        println!(
            "  bad pixel at ({x},{y}) [top-left origin]: actual {},{},{},{} golden {},{},{},{}",
            pa[0], pa[1], pa[2], pa[3], pg[0], pg[1], pg[2], pg[3]
        );
    }
    write_actual(&actual);
    Ok(false)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn stats_classify_and_range() {
        let mut img = RgbaImage::new(4, 2);
        img.put_pixel(0, 0, image::Rgba([200, 10, 10, 255]));
        img.put_pixel(1, 0, image::Rgba([90, 20, 30, 255]));
        img.put_pixel(2, 0, image::Rgba([10, 250, 10, 255]));
        img.put_pixel(3, 0, image::Rgba([100, 100, 100, 255]));
        img.put_pixel(0, 1, image::Rgba([0, 0, 60, 255]));
        assert_eq!(stats(&img), "4x2 dark 3 red 2 green 1 blue 1 other 1 levels 90 200 250 250 60 60");
    }

    #[test]
    fn crop_inside_only() {
        let mut img = RgbaImage::new(5, 4);
        img.put_pixel(3, 2, image::Rgba([1, 2, 3, 4]));
        let c = crop(&img, 2, 1, 3, 3).unwrap();
        assert_eq!(c.dimensions(), (3, 3));
        assert_eq!(c.get_pixel(1, 1).0, [1, 2, 3, 4]);
        assert!(crop(&img, 3, 1, 3, 3).is_err());
        assert!(crop(&img, u32::MAX, 0, 2, 2).is_err());
    }
}

fn main() -> ExitCode {
    let args: Vec<String> = std::env::args().skip(1).collect();
    match run(&args) {
        Ok(true) => ExitCode::SUCCESS,
        Ok(false) => ExitCode::from(1),
        Err(e) => {
            eprintln!("imgcmp: {e}");
            ExitCode::from(2)
        }
    }
}
