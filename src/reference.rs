//! An f64 reference of the bundled shader library's lighting (Surface, Light, BRDF, Lighting),
//! formula for formula, to measure compiled shaders against. It follows WGSL semantics where
//! they matter and spells out the ones that are easy to get wrong.

/// `saturate` as WGSL defines it for finite values: clamp to [0, 1]. For NaN the result is
/// explicitly NaN here (GPUs differ: some return 0, some NaN), so that a NaN reaching `saturate`
/// in the reference is visible in comparisons rather than silently hidden.
pub fn saturate(x: f64) -> f64 {
    if x.is_nan() { f64::NAN } else { x.clamp(0.0, 1.0) }
}

pub type Vec3 = [f64; 3];

pub fn dot(a: Vec3, b: Vec3) -> f64 {
    a[0] * b[0] + a[1] * b[1] + a[2] * b[2]
}

pub fn add(a: Vec3, b: Vec3) -> Vec3 {
    [a[0] + b[0], a[1] + b[1], a[2] + b[2]]
}

pub fn scale(a: Vec3, s: f64) -> Vec3 {
    [a[0] * s, a[1] * s, a[2] * s]
}

pub fn mul(a: Vec3, b: Vec3) -> Vec3 {
    [a[0] * b[0], a[1] * b[1], a[2] * b[2]]
}

/// The smallest normal f32, which the library clamps squared lengths to.
pub const FLT_MIN: f64 = 1.175_494_35e-38;

pub fn square(v: f64) -> f64 {
    v * v
}

/// Zero for a zero vector, never NaN, as the library's `SafeNormalize`.
pub fn safe_normalize(v: Vec3) -> Vec3 {
    scale(v, 1.0 / dot(v, v).max(FLT_MIN).sqrt())
}

#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Surface {
    pub normal: Vec3,
    pub view_direction: Vec3,
    pub color: Vec3,
    pub alpha: f64,
    pub metallic: f64,
    pub smoothness: f64,
}

#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Light {
    pub color: Vec3,
    /// Towards the light.
    pub direction: Vec3,
}

#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Brdf {
    pub diffuse: Vec3,
    pub specular: Vec3,
    pub roughness: f64,
}

pub const MIN_REFLECTIVITY: f64 = 0.04;
pub const MAX_DIRECTIONAL_LIGHT_COUNT: usize = 4;

pub fn one_minus_reflectivity(metallic: f64) -> f64 {
    let range = 1.0 - MIN_REFLECTIVITY;
    range - metallic * range
}

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

pub fn direct_brdf(surface: &Surface, brdf: &Brdf, light: &Light) -> Vec3 {
    add(scale(brdf.specular, specular_strength(surface, brdf, light)), brdf.diffuse)
}

pub fn incoming_light(surface: &Surface, light: &Light) -> Vec3 {
    scale(light.color, saturate(dot(surface.normal, light.direction)))
}

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
