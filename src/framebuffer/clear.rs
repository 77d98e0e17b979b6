//! What glClear writes (GL 1.5 section 4.2.3), as a value: the rectangle,
//! and per buffer the clear value and write mask that apply. `gl::clear`
//! makes it and either writes it at once or, with the rasterizer's threads
//! binning, hands it to the next flight of triangles
//! (`render::tile::defer_clear`), whose workers write each band's rows
//! just before they draw that band (round 11). Both ways write the same
//! bytes through the same functions below.

use super::Rect;

/// A glClear's writes: each buffer it names that has something to write.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Clear {
    pub rect: Rect,
    /// The colour value and the channels written (not all false).
    pub color: Option<([u8; 4], [bool; 4])>,
    /// The depth value (24-bit fixed point).
    pub depth: Option<u32>,
    /// The stencil value and the written bits (not zero).
    pub stencil: Option<(u8, u8)>,
}

/// Colour `value` into `row` through `mask`.
#[inline]
pub fn color_row(row: &mut [[u8; 4]], value: [u8; 4], mask: [bool; 4]) {
    if mask == [true; 4] {
        row.fill(value);
        return;
    }
    for px in row {
        for ch in 0..4 {
            if mask[ch] {
                px[ch] = value[ch];
            }
        }
    }
}

/// Stencil `value` into `row` through the written bits `mask`.
#[inline]
pub fn stencil_row(row: &mut [u8], value: u8, mask: u8) {
    if mask == u8::MAX {
        row.fill(value);
        return;
    }
    for s in row {
        *s = (*s & !mask) | (value & mask);
    }
}

/// Applies `f` to columns [x0, x1) of each row of `rows` (whole rows of
/// `width`), as one run when the rows are whole.
#[inline]
pub fn each_row<T>(rows: &mut [T], width: usize, x0: usize, x1: usize, mut f: impl FnMut(&mut [T])) {
    if x0 == 0 && x1 == width {
        f(rows);
    } else {
        for row in rows.chunks_mut(width) {
            f(&mut row[x0..x1]);
        }
    }
}

impl Clear {
    /// Writes the clear into rows [y0, y1) of planes `width` wide, given
    /// as the slices holding exactly those rows (depth and stencil empty
    /// when absent); only the rows and columns of `rect` change.
    pub fn rows(&self, width: usize, y0: usize, y1: usize, color: &mut [[u8; 4]], depth: &mut [u32], stencil: &mut [u8]) {
        let r = self.rect;
        let (a, b) = (y0.max(r.y0.max(0) as usize), y1.min(r.y1.max(0) as usize));
        if a >= b {
            return;
        }
        let (x0, x1) = (r.x0.max(0) as usize, (r.x1.max(0) as usize).min(width));
        if x0 >= x1 {
            return;
        }
        let span = (a - y0) * width..(b - y0) * width;
        if let Some((v, m)) = self.color {
            each_row(&mut color[span.clone()], width, x0, x1, |row| color_row(row, v, m));
        }
        if let (Some(v), false) = (self.depth, depth.is_empty()) {
            each_row(&mut depth[span.clone()], width, x0, x1, |row| row.fill(v));
        }
        if let (Some((v, m)), false) = (self.stencil, stencil.is_empty()) {
            each_row(&mut stencil[span], width, x0, x1, |row| stencil_row(row, v, m));
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Writing a clear band by band (any cut into row ranges) gives what
    /// writing it in one go does, and changes only its rectangle's
    /// pixels, through its masks.
    #[test]
    fn bands_write_the_whole_clear() {
        let (w, h) = (37usize, 29usize);
        let clears = [
            Clear { rect: Rect::new(0, 0, 37, 29), color: Some(([1, 2, 3, 4], [true; 4])), depth: Some(77), stencil: Some((5, 0xff)) },
            Clear { rect: Rect::new(3, 4, 20, 11), color: Some(([9, 8, 7, 6], [true, false, true, false])), depth: None, stencil: Some((0xf0, 0x3c)) },
            Clear { rect: Rect::new(-5, 20, 100, 100), color: None, depth: Some(3), stencil: None },
        ];
        for c in clears {
            let start = |k: usize| (k * 7 % 251) as u8;
            let mut whole = (vec![[0u8; 4]; w * h], vec![0u32; w * h], vec![0u8; w * h]);
            whole.0.iter_mut().enumerate().for_each(|(i, p)| *p = [start(i); 4]);
            whole.1.iter_mut().enumerate().for_each(|(i, p)| *p = i as u32);
            whole.2.iter_mut().enumerate().for_each(|(i, p)| *p = start(i));
            let mut banded = whole.clone();
            let before = whole.clone();
            c.rows(w, 0, h, &mut whole.0, &mut whole.1, &mut whole.2);
            for band in [0..5, 5..6, 6..17, 17..29] {
                let s = band.start * w..band.end * w;
                c.rows(w, band.start, band.end, &mut banded.0[s.clone()], &mut banded.1[s.clone()], &mut banded.2[s]);
            }
            assert_eq!(whole, banded, "{c:?}");
            let r = c.rect.intersect(Rect::new(0, 0, w as i32, h as i32));
            for i in 0..w * h {
                let (x, y) = ((i % w) as i32, (i / w) as i32);
                let inside = x >= r.x0 && x < r.x1 && y >= r.y0 && y < r.y1;
                let want_color = match (c.color, inside) {
                    (Some((v, m)), true) => std::array::from_fn(|ch| if m[ch] { v[ch] } else { before.0[i][ch] }),
                    _ => before.0[i],
                };
                assert_eq!(whole.0[i], want_color, "{c:?} pixel {i}");
                assert_eq!(whole.1[i], if inside { c.depth.unwrap_or(before.1[i]) } else { before.1[i] });
                let want_s = match (c.stencil, inside) {
                    (Some((v, m)), true) => (before.2[i] & !m) | (v & m),
                    _ => before.2[i],
                };
                assert_eq!(whole.2[i], want_s);
            }
        }
    }
}
