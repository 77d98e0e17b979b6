//! B-spline evaluation in f64: knot-vector checks and de Boor's algorithm
//! with the first derivative, on homogeneous 4-vectors (a rational curve is
//! evaluated as the non-rational curve of its (wx, wy, wz, w) control
//! points and divided afterwards, as GL's evaluators define MAP_VERTEX_4).
//!
//! A curve of order k (degree p = k - 1) has `n = knots.len() - k` control
//! points and the valid parameter range `[knots[p], knots[n]]`.

/// Knot-vector errors, as GLU_NURBS_ERRORn numbers: 1 order, 2 too few
/// knots, 3 empty range, 4 decreasing, 5 multiplicity above the order.
pub fn check_knots(knots: &[f64], order: usize) -> Result<(), u32> {
    if !(1..=24).contains(&order) {
        return Err(1);
    }
    if knots.len() < 2 * order {
        return Err(2);
    }
    if knots.iter().any(|k| !k.is_finite()) {
        return Err(32);
    }
    let mut run = 1;
    for w in knots.windows(2) {
        if w[1] < w[0] {
            return Err(4);
        }
        run = if w[1] == w[0] { run + 1 } else { 1 };
        if run > order {
            return Err(5);
        }
    }
    let n = knots.len() - order;
    if knots[order - 1] >= knots[n] {
        return Err(3);
    }
    Ok(())
}

/// The valid parameter range.
pub fn domain(knots: &[f64], order: usize) -> (f64, f64) {
    (knots[order - 1], knots[knots.len() - order])
}

/// The distinct knots inside the range, ends included (span boundaries).
pub fn breakpoints(knots: &[f64], order: usize) -> Vec<f64> {
    let (a, b) = domain(knots, order);
    let mut v: Vec<f64> = knots.iter().copied().filter(|&k| k >= a && k <= b).collect();
    v.dedup();
    v
}

/// The span index i (knots[i] <= u < knots[i+1], p <= i < n) of u, clamped
/// to the range.
pub fn span(knots: &[f64], order: usize, u: f64) -> usize {
    let p = order - 1;
    let n = knots.len() - order;
    let (a, b) = domain(knots, order);
    let u = u.clamp(a, b);
    // The last non-empty span holds u == b.
    let mut i = n - 1;
    while i > p && knots[i] > u {
        i -= 1;
    }
    while i > p && knots[i] == knots[i + 1] {
        i -= 1;
    }
    i
}

pub type V4 = [f64; 4];

fn lerp(a: V4, b: V4, t: f64) -> V4 {
    [0, 1, 2, 3].map(|k| a[k] + (b[k] - a[k]) * t)
}

/// The curve and its derivative at u; `pt(j)` is control point j.
pub fn de_boor(knots: &[f64], order: usize, pt: &dyn Fn(usize) -> V4, u: f64) -> (V4, V4) {
    let p = order - 1;
    let i = span(knots, order, u);
    if p == 0 {
        return (pt(i), [0.0; 4]);
    }
    let mut d: Vec<V4> = (0..=p).map(|j| pt(j + i - p)).collect();
    let mut deriv = [0.0; 4];
    for r in 1..=p {
        if r == p {
            let h = knots[i + 1] - knots[i];
            deriv = [0, 1, 2, 3].map(|k| p as f64 * (d[p][k] - d[p - 1][k]) / h);
        }
        for j in (r..=p).rev() {
            let lo = knots[j + i - p];
            let hi = knots[j + 1 + i - r];
            let a = if hi > lo { (u - lo) / (hi - lo) } else { 0.0 };
            d[j] = lerp(d[j - 1], d[j], a);
        }
    }
    (d[p], deriv)
}

/// A Cartesian point and derivative from homogeneous ones.
pub fn dehomogenize(s: V4, ds: V4) -> ([f64; 3], [f64; 3]) {
    let w = if s[3] != 0.0 { s[3] } else { 1.0 };
    let p = [s[0] / w, s[1] / w, s[2] / w];
    let d = [0, 1, 2].map(|k| (ds[k] - p[k] * ds[3]) / w);
    (p, d)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn cubic_bezier_matches_bernstein() {
        let knots = [0.0, 0.0, 0.0, 0.0, 1.0, 1.0, 1.0, 1.0];
        let c = [[0.0, 0.0, 0.0, 1.0], [1.0, 2.0, 0.0, 1.0], [3.0, 2.0, 1.0, 1.0], [4.0, 0.0, 2.0, 1.0]];
        for s in 0..=10 {
            let t = s as f64 / 10.0;
            let (v, d) = de_boor(&knots, 4, &|j| c[j], t);
            let b = [(1.0 - t).powi(3), 3.0 * t * (1.0 - t).powi(2), 3.0 * t * t * (1.0 - t), t.powi(3)];
            let db = [-3.0 * (1.0 - t).powi(2), 3.0 * (1.0 - t).powi(2) - 6.0 * t * (1.0 - t), 6.0 * t * (1.0 - t) - 3.0 * t * t, 3.0 * t * t];
            for k in 0..3 {
                let want: f64 = (0..4).map(|j| b[j] * c[j][k]).sum();
                let dwant: f64 = (0..4).map(|j| db[j] * c[j][k]).sum();
                assert!((v[k] - want).abs() < 1e-12 && (d[k] - dwant).abs() < 1e-12, "t={t}");
            }
        }
    }

    #[test]
    fn knot_errors() {
        assert_eq!(check_knots(&[0.0, 0.0, 1.0, 1.0], 2), Ok(()));
        assert_eq!(check_knots(&[0.0, 0.0, 1.0], 2), Err(2));
        assert_eq!(check_knots(&[0.0, 1.0, 0.5, 1.0], 2), Err(4));
        assert_eq!(check_knots(&[0.0, 0.0, 0.0, 1.0], 2), Err(5));
        assert_eq!(check_knots(&[0.0, 0.0, 0.0, 1.0], 0), Err(1));
        assert_eq!(check_knots(&[0.0, 1.0, 1.0, 1.0, 2.0, 3.0], 3), Err(3));
    }
}
