//! Vertices after the vertex stage: clip coordinates and the attributes
//! rasterization interpolates.

use glam::Vec4;

#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ClipVertex {
    /// Clip coordinates (x, y, z, w).
    pub pos: Vec4,
    /// Primary colour, RGBA in [0, 1] (clamped at interpolation).
    pub color: Vec4,
    /// The colour back-facing polygons take: the back face's lit colour
    /// under two-sided lighting, else the same as `color`.
    pub back_color: Vec4,
    /// Edge flag of the polygon edge that starts at this vertex (2.6.2):
    /// polygon mode LINE and POINT draw only flagged edges and vertices.
    pub edge: bool,
    /// Texture coordinates (s, t, r, q) per unit, after texgen and the
    /// texture matrix.
    pub tex: [Vec4; super::texture::MAX_UNITS],
    /// Fog: the fog coordinate, or f itself when fog is per vertex.
    pub fog: f32,
    /// The secondary colour the colour sum (3.9) adds after texturing.
    /// Without texturing the vertex stage adds it into `color` already
    /// (the same result: both interpolate linearly) and this is 0.
    pub secondary: Vec4,
    /// The back face's secondary colour under two-sided lighting with
    /// texturing (else the same as `secondary`).
    pub back_secondary: Vec4,
    /// Computed once per vertex by [`ClipVertex::place`] (a strip's vertex
    /// serves three triangles): the position is finite and inside the
    /// fixed clip planes (`clip::inside_fixed`), and then `win` holds its
    /// window x, y, z and 1/w and `snapped` its fixed-point x and y.
    /// False for vertices made by clipping; never trusted when false.
    pub inside: bool,
    pub win: [f64; 4],
    pub snapped: [i64; 2],
}

impl ClipVertex {
    /// Every attribute zero, edge flag false, not placed.
    pub const ZERO: ClipVertex = ClipVertex {
        pos: Vec4::ZERO,
        color: Vec4::ZERO,
        back_color: Vec4::ZERO,
        edge: false,
        tex: [Vec4::ZERO; super::texture::MAX_UNITS],
        fog: 0.0,
        secondary: Vec4::ZERO,
        back_secondary: Vec4::ZERO,
        inside: false,
        win: [0.0; 4],
        snapped: [0; 2],
    };

    /// The vertex a fraction `t` of the way from `a` to `b` (clip-space
    /// linear interpolation, GL 1.5 section 2.12 equation 2.6).
    #[inline]
    pub fn lerp(a: &ClipVertex, b: &ClipVertex, t: f32) -> ClipVertex {
        ClipVertex {
            pos: a.pos + (b.pos - a.pos) * t,
            color: a.color + (b.color - a.color) * t,
            back_color: a.back_color + (b.back_color - a.back_color) * t,
            edge: a.edge,
            tex: std::array::from_fn(|u| a.tex[u] + (b.tex[u] - a.tex[u]) * t),
            fog: a.fog + (b.fog - a.fog) * t,
            secondary: a.secondary + (b.secondary - a.secondary) * t,
            back_secondary: a.back_secondary + (b.back_secondary - a.back_secondary) * t,
            inside: false,
            win: [0.0; 4],
            snapped: [0; 2],
        }
    }

    /// Fills in `inside`, `win` and `snapped` for the render state's
    /// viewport.
    #[inline]
    pub fn place(&mut self, rs: &super::RenderState) {
        self.inside = super::clip::inside_fixed(self.pos);
        if self.inside {
            self.win = super::setup::window_pos(rs, self.pos);
            self.snapped = [snap(self.win[0]), snap(self.win[1])];
        }
    }
}

/// [`super::setup::snap`] (round(c * 256) as i64, half away from zero)
/// without its data-dependent branches: the fraction's two tests become
/// 0/1 terms, which the vertex stage, snapping random sub-pixel positions,
/// would otherwise mispredict about half the time. Out of the exact range
/// (never for an inside vertex) it defers to `setup::snap`.
#[inline(always)]
pub fn snap(c: f64) -> i64 {
    let v = c * super::setup::ONE as f64;
    if !(v.abs() < 4503599627370496.0) {
        return super::setup::snap(c);
    }
    // SAFETY: |v| < 2^52, so the truncation fits (one cvttsd2si, not the
    // saturating `as`).
    let t = unsafe { v.to_int_unchecked::<i64>() }; // toward zero, exact
    let frac = v - t as f64; // exact
    t + (frac >= 0.5) as i64 - (frac <= -0.5) as i64
}

#[cfg(test)]
mod tests {
    /// `snap` equals `setup::snap` on random values, on and beside every
    /// rounding point of a range, and on extreme and non-finite values.
    #[test]
    fn snap_matches_setup_snap() {
        let mut seed = 3u64;
        let mut next = || {
            seed = seed.wrapping_mul(6364136223846793005).wrapping_add(1442695040888963407);
            seed >> 11
        };
        let mut values = vec![0.0, -0.0, f64::MAX, f64::MIN, f64::INFINITY, f64::NEG_INFINITY, f64::NAN, 1e300, -1e300, 2f64.powi(44), -(2f64.powi(44)), 2f64.powi(45) - 0.5];
        for k in -4096i64..4096 {
            // k/512: every half-subpixel point (the rounding ties) of +-8
            // pixels, and its neighbours one and a few ulps away.
            let x = k as f64 / 512.0;
            values.extend([x, x.next_up(), x.next_down(), x + 1e-12, x - 1e-12, x + 1e-9, x - 1e-9]);
            values.extend([x + 1000.0, x - 1000.0, (x + 1000.0).next_up(), (x - 1000.0).next_down()]);
        }
        for _ in 0..200_000 {
            let u = (next() as f64) / (1u64 << 53) as f64;
            let scale = [1.0, 100.0, 5000.0, 1e7, 1e13][(next() % 5) as usize];
            values.push((u - 0.5) * scale);
        }
        for c in values {
            assert_eq!(super::snap(c), super::super::setup::snap(c), "{c:e}");
        }
    }
}
