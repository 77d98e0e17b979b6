//! imgcmp: compare a rendered image against a golden PNG.
//!
//! Usage:
//!   imgcmp ACTUAL GOLDEN [--tol N] [--max-bad K]
//!   imgcmp --to-png IN OUT.png
//!
//! ACTUAL is a PAM (P7, RGB_ALPHA or RGB, maxval 255, rows top-down) or any
//! image the `image` crate reads (PNG, PNM). GOLDEN is a PNG. Both are
//! compared as RGBA8. A pixel is bad if any channel differs by more than N
//! (default 1). Exit 0 if the sizes match and the number of bad pixels is at
//! most K (default 0); otherwise print a summary and exit 1, writing ACTUAL
//! as `<golden stem>.actual.png` beside the golden.

use image::RgbaImage;
use std::path::{Path, PathBuf};
use std::process::ExitCode;

const USAGE: &str =
    "usage: imgcmp ACTUAL GOLDEN [--tol N] [--max-bad K]\n       imgcmp --to-png IN OUT.png";

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

    let mut positional = Vec::new();
    let mut tol: u64 = 1;
    let mut max_bad: u64 = 0;
    let mut i = 0;
    while i < args.len() {
        match args[i].as_str() {
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
