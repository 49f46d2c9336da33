// BRDF.wgsl: the metallic workflow split into diffuse and specular colours, and the minimal
// Cook-Torrance specular term Unity's Universal RP uses.
#ifndef KILN_BRDF_INCLUDED
#define KILN_BRDF_INCLUDED

#include "Common.wgsl"
#include "Surface.wgsl"
#include "Light.wgsl"

// Dielectrics still reflect about 4% of light specularly.
#define MIN_REFLECTIVITY 0.04

struct BRDF {
    diffuse: vec3<f32>,
    specular: vec3<f32>,
    roughness: f32,
}

// Maps metallic 0..1 to a diffuse share of 0.96..0, so that no surface loses its highlight.
// 1 - metallic first: exact in f32 for metallic from 0.5 to 1 (Sterbenz), where
// range - metallic * range would subtract a rounded product and lose the digits of a small share
// (1e-3 relative at metallic 0.99998, found by `kiln accuracy`).
fn OneMinusReflectivity(metallic: f32) -> f32 {
    let range = 1.0 - MIN_REFLECTIVITY;
    return range * (1.0 - metallic);
}

fn PerceptualSmoothnessToPerceptualRoughness(smoothness: f32) -> f32 {
    return 1.0 - smoothness;
}

// Disney's mapping: perceptual roughness is squared.
fn PerceptualRoughnessToRoughness(perceptualRoughness: f32) -> f32 {
    return perceptualRoughness * perceptualRoughness;
}

// With `applyAlphaToDiffuse` the diffuse part is premultiplied by alpha (glass-like blending that
// keeps the specular highlight); blending with `One`/`OneMinusSrcAlpha` then expects it.
fn GetBRDF(surface: Surface, applyAlphaToDiffuse: bool) -> BRDF {
    var brdf: BRDF;
    let oneMinusReflectivity = OneMinusReflectivity(surface.metallic);
    brdf.diffuse = surface.color * oneMinusReflectivity;
    if (applyAlphaToDiffuse) {
        brdf.diffuse *= surface.alpha;
    }
    brdf.specular = mix(vec3<f32>(MIN_REFLECTIVITY), surface.color, surface.metallic);
    let perceptualRoughness = PerceptualSmoothnessToPerceptualRoughness(surface.smoothness);
    brdf.roughness = PerceptualRoughnessToRoughness(perceptualRoughness);
    return brdf;
}

// Roughness is kept at or above this in the stable forms, so that r^2 stays a normal f32 number
// (and, scaled by 2^10, a normal f16 one) instead of flushing to zero.
#define KILN_MIN_ROUGHNESS 0.002

#if defined(_SPECULAR_HALF)
// The stable form with its arithmetic in half precision, for adapters with `shader-f16`. The pass
// must begin its program with `enable f16;` and declare `#pragma require native16bit`. f16's
// smallest normal number is 2^-14, which r^2 = 0.002^2 and (1 - (N.H)^2) near a highlight fall
// below; so squares are carried scaled by 2^10 (lengths by 2^5), where every term stays normal.
// The peak, r^2 / d^2, exceeds f16's largest number (65504) for smooth surfaces, so the last
// square and division are taken in f32.
fn SpecularStrength(surface: Surface, brdf: BRDF, light: Light) -> f32 {
    let h32 = SafeNormalize(light.direction + surface.viewDirection);
    let n = vec3<f16>(surface.normal);
    let h = vec3<f16>(h32);
    let nh = saturate(dot(n, h));
    let nxh = cross(n, h) * 32.0h;
    let deficit = 1.0h - dot(n, n) * dot(h, h);
    // H below the surface (N.H <= 0, which saturate makes 0): 1 - (N.H)^2 is 1, not |N x H|^2.
    let oneMinusNh2 = select(1024.0h, clamp(dot(nxh, nxh) + select(deficit * 1024.0h, 0.0h, abs(deficit) < 0.01h), 0.0h, 1024.0h), dot(n, h) > 0.0h);
    let lh = saturate(dot(vec3<f16>(light.direction), h));
    let roughness = max(f16(brdf.roughness), f16(KILN_MIN_ROUGHNESS)) * 32.0h;
    let d = oneMinusNh2 + nh * nh * roughness * roughness + 0.01024h;
    let q = f32(roughness / d) * 32.0;
    let normalization = f32(roughness) * 0.125 + 2.0;
    return q * q / (max(0.1, f32(lh * lh)) * normalization);
}
#elif defined(_SPECULAR_RATIO)
// The stable form's model without normalising H. With M = L + V: (N.H)^2 = (N.M)^2 / M.M,
// (L.H)^2 = (L.M)^2 / M.M and, for a unit N, 1 - (N.H)^2 = |N x M|^2 / M.M (Lagrange's identity),
// so d = q / M.M with q = |N x M|^2 + (N.M)^2 r^2 + 0.00001 M.M, and the term is
// r^2 (M.M / q)^2 (M.M / x) / (4r + 2) with x = max(0.1 M.M, (L.M)^2): ratios of squares of M,
// each of degree 0, so that no product of them underflows however short M is (L nearly -V).
// One cross product takes the place of the reciprocal square root, and 1 - (N.H)^2 is never a
// difference of nearly equal numbers. A zero or denormal normal keeps the identity's first term,
// 1 - |N|^2; M = 0 (L = -V) is the seed's zero half vector.
fn SpecularStrength(surface: Surface, brdf: BRDF, light: Light) -> f32 {
    let m = light.direction + surface.viewDirection;
    let mm = dot(m, m);
    let n = surface.normal;
    let nm = max(dot(n, m), 0.0);
    let lm = max(dot(light.direction, m), 0.0);
    let nxm = cross(n, m);
    let deficit = 1.0 - dot(n, n);
    let roughness = max(brdf.roughness, KILN_MIN_ROUGHNESS);
    let r2 = roughness * roughness;
    // H below the surface (N.H <= 0, which saturate makes 0): 1 - (N.H)^2 is 1, not |N x H|^2.
    let sin2mm = select(mm, dot(nxm, nxm) + select(deficit * mm, 0.0, abs(deficit) < 1e-3), dot(n, m) > 0.0);
    // M so short that its squared terms would leave f32's normal range (L = -V): the zero half
    // vector.
    let zero = mm < 1e-30;
    let s = select(mm, 1.0, zero);
    let q = select(sin2mm + nm * nm * r2 + 0.00001 * mm, 1.00001, zero);
    let x = select(max(0.1 * mm, lm * lm), 0.1, zero);
    let a = s / q;
    let normalization = roughness * 4.0 + 2.0;
    return r2 * a * a * s / (x * normalization);
}
#elif defined(_SPECULAR_STABLE)
// The same model, written to avoid cancellation: d = (1 - (N.H)^2) + (N.H)^2 r^2 + 0.00001 with
// 1 - (N.H)^2 taken from |N x H|^2 (Lagrange's identity: 1 - (N.H)^2 = 1 - |N|^2|H|^2 + |N x H|^2),
// exact where N.H is near 1 and the seed's form loses every digit of 1 - (N.H)^2. The identity's
// first term is rounding noise for unit vectors and is dropped then; it is kept when N or H is
// degenerate (a zero half vector when L = -V, a zero or denormal normal).
fn SpecularStrength(surface: Surface, brdf: BRDF, light: Light) -> f32 {
    let h = SafeNormalize(light.direction + surface.viewDirection);
    let nh = saturate(dot(surface.normal, h));
    let nxh = cross(surface.normal, h);
    let deficit = 1.0 - dot(surface.normal, surface.normal) * dot(h, h);
    // H below the surface (N.H <= 0, which saturate makes 0): 1 - (N.H)^2 is 1, not |N x H|^2.
    let oneMinusNh2 = select(1.0, saturate(dot(nxh, nxh) + select(deficit, 0.0, abs(deficit) < 1e-3)), dot(surface.normal, h) > 0.0);
    let lh2 = Square(saturate(dot(light.direction, h)));
    let roughness = max(brdf.roughness, KILN_MIN_ROUGHNESS);
    let r2 = Square(roughness);
    let d2 = Square(oneMinusNh2 + nh * nh * r2 + 0.00001);
    let normalization = roughness * 4.0 + 2.0;
    return r2 / (d2 * max(0.1, lh2) * normalization);
}
#else
// The seed's minimal Cook-Torrance exactly as written:
// r^2 / (d^2 * max(0.1, (L.H)^2) * (4r + 2)) with d = (N.H)^2 (r^2 - 1) + 1.00001.
fn SpecularStrength(surface: Surface, brdf: BRDF, light: Light) -> f32 {
    let h = SafeNormalize(light.direction + surface.viewDirection);
    let nh2 = Square(saturate(dot(surface.normal, h)));
    let lh2 = Square(saturate(dot(light.direction, h)));
    let r2 = Square(brdf.roughness);
    let d2 = Square(nh2 * (r2 - 1.0) + 1.00001);
    let normalization = brdf.roughness * 4.0 + 2.0;
    return r2 / (d2 * max(0.1, lh2) * normalization);
}
#endif

fn DirectBRDF(surface: Surface, brdf: BRDF, light: Light) -> vec3<f32> {
    return SpecularStrength(surface, brdf, light) * brdf.specular + brdf.diffuse;
}

#endif
