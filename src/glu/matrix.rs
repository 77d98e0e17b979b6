//! GLU matrix utilities (GLU 1.3 section 4): gluOrtho2D, gluPerspective,
//! gluLookAt, gluPickMatrix (which multiply the current GL matrix through
//! the public entry points) and gluProject / gluUnProject / gluUnProject4.

use crate::api::args::arr;
use crate::api::table as gl;
use crate::api::types::*;
use glam::{DMat4, DVec3, DVec4};

fn mult(m: DMat4) {
    let a = m.to_cols_array();
    // SAFETY: a 16-element array, as glMultMatrixd reads.
    unsafe { gl::glMultMatrixd(a.as_ptr()) }
}

pub fn ortho_2d(left: f64, right: f64, bottom: f64, top: f64) {
    unsafe { gl::glOrtho(left, right, bottom, top, -1.0, 1.0) }
}

/// Degenerate arguments (zero aspect, zero depth range, a zero field of
/// view) leave the matrix unchanged, as SGI's GLU does.
pub fn perspective(fovy: f64, aspect: f64, near: f64, far: f64) {
    let half = (fovy / 2.0).to_radians();
    let (sin, cos) = half.sin_cos();
    let dz = far - near;
    if dz == 0.0 || sin == 0.0 || aspect == 0.0 {
        return;
    }
    let f = cos / sin;
    mult(DMat4::from_cols_array(&[
        f / aspect, 0.0, 0.0, 0.0,
        0.0, f, 0.0, 0.0,
        0.0, 0.0, -(far + near) / dz, -1.0,
        0.0, 0.0, -2.0 * near * far / dz, 0.0,
    ]));
}

pub fn look_at(eye: [f64; 3], center: [f64; 3], up: [f64; 3]) {
    let eye = DVec3::from(eye);
    let f = (DVec3::from(center) - eye).normalize_or_zero();
    let s = f.cross(DVec3::from(up)).normalize_or_zero();
    let u = s.cross(f);
    // Rows s, u, -f.
    mult(DMat4::from_cols(
        DVec4::new(s.x, u.x, -f.x, 0.0),
        DVec4::new(s.y, u.y, -f.y, 0.0),
        DVec4::new(s.z, u.z, -f.z, 0.0),
        DVec4::W,
    ));
    unsafe { gl::glTranslated(-eye.x, -eye.y, -eye.z) }
}

/// # Safety
/// `viewport` must be NULL or point to 4 integers.
pub unsafe fn pick_matrix(x: f64, y: f64, dx: f64, dy: f64, viewport: *const GLint) {
    let Some(vp) = arr::<GLint, 4>(viewport) else { return };
    if dx <= 0.0 || dy <= 0.0 {
        return;
    }
    let vp = vp.map(|v| v as f64);
    gl::glTranslated((vp[2] - 2.0 * (x - vp[0])) / dx, (vp[3] - 2.0 * (y - vp[1])) / dy, 0.0);
    gl::glScaled(vp[2] / dx, vp[3] / dy, 1.0);
}

unsafe fn read_matrices(model: *const GLdouble, proj: *const GLdouble, view: *const GLint) -> Option<(DMat4, DMat4, [f64; 4])> {
    let m = DMat4::from_cols_array(&arr::<f64, 16>(model)?);
    let p = DMat4::from_cols_array(&arr::<f64, 16>(proj)?);
    let v = arr::<GLint, 4>(view)?.map(|x| x as f64);
    Some((m, p, v))
}

/// gluProject: object to window coordinates. GL_FALSE when w is 0.
///
/// # Safety
/// Matrix and viewport pointers as GLU requires; outputs NULL or writable.
pub unsafe fn project(obj: [f64; 3], model: *const GLdouble, proj: *const GLdouble, view: *const GLint, out: [*mut GLdouble; 3]) -> GLint {
    let Some((m, p, v)) = read_matrices(model, proj, view) else { return 0 };
    let c = p * (m * DVec4::new(obj[0], obj[1], obj[2], 1.0));
    if c.w == 0.0 {
        return 0;
    }
    let n = c.truncate() / c.w;
    let win = [v[0] + v[2] * (n.x + 1.0) / 2.0, v[1] + v[3] * (n.y + 1.0) / 2.0, (n.z + 1.0) / 2.0];
    for (p, w) in out.iter().zip(win) {
        if !p.is_null() {
            **p = w;
        }
    }
    1
}

/// gluUnProject4 (and gluUnProject with w = 1, depth range [0, 1]):
/// window to object coordinates. GL_FALSE when the matrix is singular or
/// the result has w = 0.
///
/// # Safety
/// Matrix and viewport pointers as GLU requires; outputs NULL or writable.
#[allow(clippy::too_many_arguments)]
pub unsafe fn unproject(
    win: [f64; 4],
    model: *const GLdouble,
    proj: *const GLdouble,
    view: *const GLint,
    near: f64,
    far: f64,
    out: [*mut GLdouble; 4],
) -> GLint {
    let Some((m, p, v)) = read_matrices(model, proj, view) else { return 0 };
    let pm = p * m;
    if pm.determinant() == 0.0 || v[2] == 0.0 || v[3] == 0.0 || far == near {
        return 0;
    }
    let ndc = DVec4::new(
        2.0 * (win[0] - v[0]) / v[2] - 1.0,
        2.0 * (win[1] - v[1]) / v[3] - 1.0,
        2.0 * (win[2] - near) / (far - near) - 1.0,
        win[3],
    );
    let o = pm.inverse() * ndc;
    let result = if out[3].is_null() {
        // gluUnProject divides by w.
        if o.w == 0.0 {
            return 0;
        }
        [o.x / o.w, o.y / o.w, o.z / o.w, 1.0]
    } else {
        [o.x, o.y, o.z, o.w]
    };
    for (p, r) in out.iter().zip(result) {
        if !p.is_null() {
            **p = r;
        }
    }
    1
}
