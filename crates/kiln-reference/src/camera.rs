//! The camera and object matrices a renderer hands the library's `UnityPerFrame` and
//! `UnityPerDraw` blocks, in f64 and column-major as WGSL stores `mat4x4<f32>` (`m[column][row]`):
//! shared by the example renderer, `kiln preview` and the references they are measured against.

use crate::{Vec3, cross, dot, normalize, sub};

/// A 4 x 4 matrix, column-major: `m[column][row]`.
pub type Mat4 = [[f64; 4]; 4];

/// The product `a * b`.
pub fn mat_mul(a: &Mat4, b: &Mat4) -> Mat4 {
    let mut out = [[0.0; 4]; 4];
    for (c, column) in out.iter_mut().enumerate() {
        for (row, value) in column.iter_mut().enumerate() {
            *value = (0..4).map(|k| a[k][row] * b[c][k]).sum();
        }
    }
    out
}

/// A camera's orthonormal basis: where it looks, its right and its up (world up is +y).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Basis {
    /// The direction it looks in.
    pub forward: Vec3,
    /// To its right.
    pub right: Vec3,
    /// Its up.
    pub up: Vec3,
}

impl Basis {
    /// The basis of a camera at `eye` looking at `target` (not straight up or down).
    pub fn looking_at(eye: Vec3, target: Vec3) -> Basis {
        let forward = normalize(sub(target, eye));
        let right = normalize(cross(forward, [0.0, 1.0, 0.0]));
        Basis { forward, right, up: cross(right, forward) }
    }
}

/// A right-handed view matrix from a camera at `eye` with `basis` (the camera looks down -z).
pub fn view(eye: Vec3, basis: &Basis) -> Mat4 {
    let (s, u, f) = (basis.right, basis.up, basis.forward);
    [
        [s[0], u[0], -f[0], 0.0],
        [s[1], u[1], -f[1], 0.0],
        [s[2], u[2], -f[2], 0.0],
        [-dot(s, eye), -dot(u, eye), dot(f, eye), 1.0],
    ]
}

/// A perspective projection to WebGPU's clip space (depth 0 at `near`, 1 at `far`), with
/// `tan_half_fov` the tangent of half the vertical field of view and `aspect` width / height.
pub fn perspective(tan_half_fov: f64, aspect: f64, near: f64, far: f64) -> Mat4 {
    let y = 1.0 / tan_half_fov;
    let z = far / (near - far);
    [[y / aspect, 0.0, 0.0, 0.0], [0.0, y, 0.0, 0.0], [0.0, 0.0, z, -1.0], [0.0, 0.0, z * near, 0.0]]
}

/// An object scaled by `scale` (each axis) and moved to `position`, and its inverse:
/// `unity_ObjectToWorld` and `unity_WorldToObject`.
pub fn object_to_world(position: Vec3, scale: Vec3) -> (Mat4, Mat4) {
    let p = position;
    let s = scale;
    let forward =
        [[s[0], 0.0, 0.0, 0.0], [0.0, s[1], 0.0, 0.0], [0.0, 0.0, s[2], 0.0], [p[0], p[1], p[2], 1.0]];
    let inverse = [
        [1.0 / s[0], 0.0, 0.0, 0.0],
        [0.0, 1.0 / s[1], 0.0, 0.0],
        [0.0, 0.0, 1.0 / s[2], 0.0],
        [-p[0] / s[0], -p[1] / s[1], -p[2] / s[2], 1.0],
    ];
    (forward, inverse)
}

#[cfg(test)]
mod tests {
    use super::*;

    fn apply(m: &Mat4, v: [f64; 4]) -> [f64; 4] {
        [0, 1, 2, 3].map(|row| (0..4).map(|c| m[c][row] * v[c]).sum())
    }

    #[test]
    fn the_point_looked_at_projects_to_the_centre_and_near_and_far_to_depth_0_and_1() {
        let eye = [1.0, 2.0, 5.0];
        let basis = Basis::looking_at(eye, [0.0, 0.0, 0.0]);
        let view_projection = mat_mul(&perspective(0.5, 2.0, 0.1, 100.0), &view(eye, &basis));
        let at = |distance: f64| {
            let p = crate::add(eye, crate::scale(basis.forward, distance));
            let clip = apply(&view_projection, [p[0], p[1], p[2], 1.0]);
            [clip[0] / clip[3], clip[1] / clip[3], clip[2] / clip[3]]
        };
        for (distance, depth) in [(0.1, 0.0), (100.0, 1.0)] {
            let ndc = at(distance);
            assert!(ndc[0].abs() < 1e-12 && ndc[1].abs() < 1e-12, "{ndc:?}");
            assert!((ndc[2] - depth).abs() < 1e-9, "{ndc:?}");
        }
        // A point up and to the right of the centre lands up and to the right.
        let p = crate::add(crate::add(eye, basis.forward), crate::add(basis.up, basis.right));
        let clip = apply(&view_projection, [p[0], p[1], p[2], 1.0]);
        assert!(clip[0] > 0.0 && clip[1] > 0.0);
    }

    #[test]
    fn an_object_matrix_times_its_inverse_is_the_identity() {
        let (m, inverse) = object_to_world([1.0, -2.0, 3.0], [2.0, 0.5, 4.0]);
        let product = mat_mul(&m, &inverse);
        for (c, column) in product.iter().enumerate() {
            for (row, value) in column.iter().enumerate() {
                assert!((value - f64::from(u8::from(c == row))).abs() < 1e-12);
            }
        }
    }
}
