//! An f64 reference of the bundled shader library's lighting (Surface, Light, BRDF, Lighting),
//! formula for formula, to measure compiled shaders against. It follows WGSL semantics where
//! they matter and spells out the ones that are easy to get wrong.

#![warn(missing_docs, unreachable_pub)]

pub mod camera;
pub mod geometry;

/// `saturate` as WGSL defines it for finite values: clamp to [0, 1]. For NaN the result is
/// explicitly NaN here (GPUs differ: some return 0, some NaN), so that a NaN reaching `saturate`
/// in the reference is visible in comparisons rather than silently hidden.
pub fn saturate(x: f64) -> f64 {
    if x.is_nan() { f64::NAN } else { x.clamp(0.0, 1.0) }
}

/// A colour or direction, in f64.
pub type Vec3 = [f64; 3];

/// The dot product.
pub fn dot(a: Vec3, b: Vec3) -> f64 {
    a[0] * b[0] + a[1] * b[1] + a[2] * b[2]
}

/// The sum.
pub fn add(a: Vec3, b: Vec3) -> Vec3 {
    [a[0] + b[0], a[1] + b[1], a[2] + b[2]]
}

/// The difference `a - b`.
pub fn sub(a: Vec3, b: Vec3) -> Vec3 {
    [a[0] - b[0], a[1] - b[1], a[2] - b[2]]
}

/// The cross product.
pub fn cross(a: Vec3, b: Vec3) -> Vec3 {
    [a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]]
}

/// `v` scaled to unit length (for non-zero `v`; `safe_normalize` is the library's).
pub fn normalize(v: Vec3) -> Vec3 {
    scale(v, 1.0 / dot(v, v).sqrt())
}

/// `a` times `s`.
pub fn scale(a: Vec3, s: f64) -> Vec3 {
    [a[0] * s, a[1] * s, a[2] * s]
}

/// The component-wise product.
pub fn mul(a: Vec3, b: Vec3) -> Vec3 {
    [a[0] * b[0], a[1] * b[1], a[2] * b[2]]
}

/// The smallest normal f32, which the library clamps squared lengths to.
pub const FLT_MIN: f64 = 1.175_494_35e-38;

/// `v` squared.
pub fn square(v: f64) -> f64 {
    v * v
}

/// Zero for a zero vector, never NaN, as the library's `SafeNormalize`.
pub fn safe_normalize(v: Vec3) -> Vec3 {
    scale(v, 1.0 / dot(v, v).max(FLT_MIN).sqrt())
}

/// What the library's `Surface` holds.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Surface {
    /// Unit normal.
    pub normal: Vec3,
    /// Unit direction to the viewer.
    pub view_direction: Vec3,
    /// Base colour.
    pub color: Vec3,
    /// Opacity.
    pub alpha: f64,
    /// Metallic, 0 to 1.
    pub metallic: f64,
    /// Smoothness, 0 to 1.
    pub smoothness: f64,
}

/// A directional light.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Light {
    /// Its colour (and intensity).
    pub color: Vec3,
    /// Towards the light.
    pub direction: Vec3,
}

/// What the library's `BRDF` holds.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Brdf {
    /// Diffuse colour.
    pub diffuse: Vec3,
    /// Specular colour.
    pub specular: Vec3,
    /// Perceptual roughness squared.
    pub roughness: f64,
}

/// The reflectivity of dielectrics (the library's `MIN_REFLECTIVITY`).
pub const MIN_REFLECTIVITY: f64 = 0.04;
/// The library's light count limit.
pub const MAX_DIRECTIONAL_LIGHT_COUNT: usize = 4;

/// The share of light not reflected specularly, for a metallic value.
pub fn one_minus_reflectivity(metallic: f64) -> f64 {
    let range = 1.0 - MIN_REFLECTIVITY;
    range - metallic * range
}

/// The library's `GetBRDF`, with or without alpha applied to diffuse (premultiplied alpha).
pub fn get_brdf(surface: &Surface, apply_alpha_to_diffuse: bool) -> Brdf {
    let mut diffuse = scale(surface.color, one_minus_reflectivity(surface.metallic));
    if apply_alpha_to_diffuse {
        diffuse = scale(diffuse, surface.alpha);
    }
    let mix = |a: f64, b: f64| a + (b - a) * surface.metallic;
    let specular = [
        mix(MIN_REFLECTIVITY, surface.color[0]),
        mix(MIN_REFLECTIVITY, surface.color[1]),
        mix(MIN_REFLECTIVITY, surface.color[2]),
    ];
    let perceptual_roughness = 1.0 - surface.smoothness;
    Brdf { diffuse, specular, roughness: perceptual_roughness * perceptual_roughness }
}

/// The minimal Cook-Torrance term exactly as the seed writes it.
pub fn specular_strength(surface: &Surface, brdf: &Brdf, light: &Light) -> f64 {
    let h = safe_normalize(add(light.direction, surface.view_direction));
    let nh2 = square(saturate(dot(surface.normal, h)));
    let lh2 = square(saturate(dot(light.direction, h)));
    let r2 = square(brdf.roughness);
    let d2 = square(nh2 * (r2 - 1.0) + 1.00001);
    let normalization = brdf.roughness * 4.0 + 2.0;
    r2 / (d2 * lh2.max(0.1) * normalization)
}

/// The roughness floor of the stable form (`KILN_MIN_ROUGHNESS` in BRDF.wgsl).
pub const MIN_ROUGHNESS: f64 = 0.002;

/// The model the stable form (`_SPECULAR_STABLE`) computes: the seed's, with roughness at least
/// [`MIN_ROUGHNESS`]. In exact arithmetic the rest of that form is the same formula.
pub fn specular_strength_stable(surface: &Surface, brdf: &Brdf, light: &Light) -> f64 {
    let clamped = Brdf { roughness: brdf.roughness.max(MIN_ROUGHNESS), ..*brdf };
    specular_strength(surface, &clamped, light)
}

/// The library's `DirectBRDF`: diffuse plus the specular term.
pub fn direct_brdf(surface: &Surface, brdf: &Brdf, light: &Light) -> Vec3 {
    add(scale(brdf.specular, specular_strength(surface, brdf, light)), brdf.diffuse)
}

/// The light arriving at the surface (`saturate(dot(N, L))` times its colour).
pub fn incoming_light(surface: &Surface, light: &Light) -> Vec3 {
    scale(light.color, saturate(dot(surface.normal, light.direction)))
}

/// One light's contribution.
pub fn lighting_for_light(surface: &Surface, brdf: &Brdf, light: &Light) -> Vec3 {
    mul(incoming_light(surface, light), direct_brdf(surface, brdf, light))
}

/// Summed over the lights, at most [`MAX_DIRECTIONAL_LIGHT_COUNT`] (the library clamps the count).
pub fn lighting(surface: &Surface, brdf: &Brdf, lights: &[Light]) -> Vec3 {
    lights
        .iter()
        .take(MAX_DIRECTIONAL_LIGHT_COUNT)
        .fold([0.0; 3], |sum, light| add(sum, lighting_for_light(surface, brdf, light)))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_seed_formulas_hold_at_simple_points() {
        assert_eq!(one_minus_reflectivity(0.0), 0.96);
        assert_eq!(one_minus_reflectivity(1.0), 0.0);
        assert_eq!(safe_normalize([0.0; 3]), [0.0; 3]);
        let surface = Surface {
            normal: [0.0, 1.0, 0.0],
            view_direction: [0.0, 1.0, 0.0],
            color: [1.0; 3],
            alpha: 1.0,
            metallic: 0.0,
            smoothness: 0.5,
        };
        let light = Light { color: [1.0; 3], direction: [0.0, 1.0, 0.0] };
        let brdf = get_brdf(&surface, false);
        assert_eq!(brdf.roughness, 0.25);
        // n.h = l.h = 1: r2 / ((r2 - 1 + 1.00001)^2 * 1 * (4r + 2)).
        let r2 = 0.0625;
        let expected = r2 / (square(r2 + 0.00001) * 3.0);
        assert!((specular_strength(&surface, &brdf, &light) - expected).abs() < 1e-12);
        // Light from behind contributes nothing.
        let behind = Light { color: [1.0; 3], direction: [0.0, -1.0, 0.0] };
        assert_eq!(lighting(&surface, &brdf, &[behind]), [0.0; 3]);
        assert!(saturate(f64::NAN).is_nan());
    }
}
