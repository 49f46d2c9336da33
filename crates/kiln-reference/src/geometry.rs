//! The meshes the example renderer and `kiln preview` draw, in f64, so that a reference can
//! intersect the very triangles the GPU rasterises.

use crate::Vec3;

/// A point of the unit UV sphere (also its normal) at `v` (0 to 1, pole to pole, +y first) and
/// `u` (0 to 1, around, from +x towards -z).
pub fn sphere_point(v: f64, u: f64) -> Vec3 {
    let (theta, phi) = (v * std::f64::consts::PI, u * std::f64::consts::TAU);
    [theta.sin() * phi.cos(), theta.cos(), -theta.sin() * phi.sin()]
}

/// A mesh's vertex: position, normal, texture coordinate.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Vertex {
    /// Object-space position.
    pub position: Vec3,
    /// Object-space unit normal.
    pub normal: Vec3,
    /// Texture coordinate, 0 to 1.
    pub uv: [f64; 2],
}

/// The unit UV sphere with `rings` from pole to pole and `segments` around: its vertices (a seam
/// column repeated, so that `u` runs 0 to 1) and triangle list, counter-clockwise seen from outside.
pub fn uv_sphere(rings: u32, segments: u32) -> (Vec<Vertex>, Vec<u32>) {
    let mut vertices = Vec::with_capacity(((rings + 1) * (segments + 1)) as usize);
    for ring in 0..=rings {
        let v = f64::from(ring) / f64::from(rings);
        for segment in 0..=segments {
            let u = f64::from(segment) / f64::from(segments);
            let n = sphere_point(v, u);
            vertices.push(Vertex { position: n, normal: n, uv: [u, v] });
        }
    }
    let mut indices = Vec::with_capacity((rings * segments * 6) as usize);
    for ring in 0..rings {
        for segment in 0..segments {
            let a = ring * (segments + 1) + segment;
            let b = a + segments + 1;
            indices.extend([a, b, a + 1, a + 1, b, b + 1]);
        }
    }
    (vertices, indices)
}

/// A square of side 2 in the xz plane, centred at the origin, facing +y, counter-clockwise seen
/// from above.
pub fn plane() -> (Vec<Vertex>, Vec<u32>) {
    let corner = |x: f64, z: f64| Vertex {
        position: [x, 0.0, z],
        normal: [0.0, 1.0, 0.0],
        uv: [(x + 1.0) / 2.0, (z + 1.0) / 2.0],
    };
    (vec![corner(-1.0, -1.0), corner(-1.0, 1.0), corner(1.0, 1.0), corner(1.0, -1.0)], vec![0, 1, 2, 0, 2, 3])
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The normal of triangle `t` by its winding.
    fn winding_normal(vertices: &[Vertex], indices: &[u32], t: usize) -> Vec3 {
        let [a, b, c] = [0, 1, 2].map(|k| vertices[indices[3 * t + k] as usize].position);
        crate::cross(crate::sub(b, a), crate::sub(c, a))
    }

    #[test]
    fn the_sphere_and_the_plane_wind_counter_clockwise_seen_from_outside() {
        let (vertices, indices) = uv_sphere(8, 16);
        assert_eq!(vertices.len(), 9 * 17);
        assert_eq!(indices.len(), 8 * 16 * 6);
        for t in 0..indices.len() / 3 {
            let n = winding_normal(&vertices, &indices, t);
            let centre = vertices[indices[3 * t] as usize].position;
            // Degenerate triangles at the poles have no winding.
            if crate::dot(n, n) > 1e-12 {
                assert!(crate::dot(n, centre) > 0.0, "triangle {t} faces inwards");
            }
        }
        for v in &vertices {
            assert!((crate::dot(v.normal, v.normal) - 1.0).abs() < 1e-12);
        }
        let (vertices, indices) = plane();
        for t in 0..2 {
            assert!(winding_normal(&vertices, &indices, t)[1] > 0.0);
        }
    }
}
