//! Rasterization of pixel rectangles (GL 1.5 section 3.6.4, "Conversion
//! to fragments") and bitmaps (section 3.7).
//!
//! Zoom: the group in column i, row j of a rectangle drawn at raster
//! position (xr, yr) with zoom (zx, zy) covers the window rectangle with
//! corners (xr + zx i, yr + zy j) and (xr + zx (i + 1), yr + zy (j + 1));
//! it produces a fragment for each pixel whose centre lies inside it. The
//! rectangle is taken half-open, lower edges in, upper edges out (whichever
//! corner is lower when a zoom is negative), so that neighbouring groups
//! never share a pixel and together leave no gap. A zero zoom produces no
//! fragments.
//!
//! Bitmaps are not zoomed: bit (i, j) is the pixel (floor(xr - xo) + i,
//! floor(yr - yo) + j).
//!
//! Only pixels inside `clip` (the window cut by the scissor box: the
//! viewport does not clip pixel rectangles) are produced.

use crate::framebuffer::Rect;

/// Window pixels [first, end) whose centres lie in the span of group `i`.
#[inline]
pub fn covered(origin: f64, zoom: f64, i: usize) -> (i64, i64) {
    let a = origin + zoom * i as f64;
    let b = origin + zoom * (i + 1) as f64;
    let (lo, hi) = if a <= b { (a, b) } else { (b, a) };
    // Centres x + 1/2 with lo <= x + 1/2 < hi.
    let first = (lo - 0.5).ceil();
    let end = (hi - 0.5).ceil();
    let clamp = |v: f64| v.clamp(-(1i64 << 40) as f64, (1i64 << 40) as f64) as i64;
    (clamp(first), clamp(end))
}

/// Calls `frag(group, x, y)` for every fragment of a `w` x `h` rectangle
/// at `origin` with `zoom`, inside `clip`; `group` is j * w + i. Rows are
/// visited bottom-up, and within a row, groups left to right in image order.
pub fn rectangle(clip: Rect, origin: [f64; 2], zoom: [f64; 2], w: usize, h: usize, mut frag: impl FnMut(usize, usize, usize)) {
    if clip.is_empty() || w == 0 || h == 0 || zoom[0] == 0.0 || zoom[1] == 0.0 {
        return;
    }
    let cols: Vec<(i64, i64)> = (0..w)
        .map(|i| {
            let (a, b) = covered(origin[0], zoom[0], i);
            (a.max(clip.x0 as i64), b.min(clip.x1 as i64))
        })
        .collect();
    if cols.iter().all(|&(a, b)| a >= b) {
        return;
    }
    for j in 0..h {
        let (r0, r1) = covered(origin[1], zoom[1], j);
        for y in r0.max(clip.y0 as i64)..r1.min(clip.y1 as i64) {
            for (i, &(c0, c1)) in cols.iter().enumerate() {
                for x in c0..c1 {
                    frag(j * w + i, x as usize, y as usize);
                }
            }
        }
    }
}

/// Calls `frag(x, y)` for every set bit of a bitmap whose rows are
/// `stride` bytes, most significant bit first, with its lower left pixel
/// at (x0, y0), inside `clip`.
#[allow(clippy::too_many_arguments)]
pub fn bitmap(clip: Rect, x0: i64, y0: i64, w: usize, h: usize, stride: usize, bits: &[u8], mut frag: impl FnMut(usize, usize)) {
    for j in 0..h {
        let y = y0 + j as i64;
        if y < clip.y0 as i64 || y >= clip.y1 as i64 {
            continue;
        }
        let row = &bits[j * stride..(j + 1) * stride];
        for i in 0..w {
            let x = x0 + i as i64;
            if row[i / 8] & (0x80 >> (i % 8)) != 0 && x >= clip.x0 as i64 && x < clip.x1 as i64 {
                frag(x as usize, y as usize);
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn unit_zoom_maps_one_to_one() {
        for origin in [10.0, 10.25, 10.5, 10.75] {
            for i in 0..4 {
                let (a, b) = covered(origin, 1.0, i);
                assert_eq!(b - a, 1, "origin {origin} i {i}");
            }
        }
    }

    #[test]
    fn zoomed_groups_tile_without_gaps() {
        for zoom in [0.3, 0.5, 1.5, 2.0, 3.7, -1.0, -2.5] {
            let mut prev: Option<(i64, i64)> = None;
            for i in 0..20 {
                let c = covered(5.25, zoom, i);
                if let Some(p) = prev {
                    if zoom > 0.0 {
                        assert_eq!(p.1, c.0);
                    } else {
                        assert_eq!(c.1, p.0);
                    }
                }
                prev = Some(c);
            }
        }
    }
}
