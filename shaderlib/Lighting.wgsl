// Lighting.wgsl: light arriving at the surface, shaded by the BRDF, summed over the lights.
#ifndef KILN_LIGHTING_INCLUDED
#define KILN_LIGHTING_INCLUDED

#include "Surface.wgsl"
#include "Light.wgsl"
#include "BRDF.wgsl"

// Light from behind the surface contributes nothing, hence the saturate.
fn IncomingLight(surface: Surface, light: Light) -> vec3<f32> {
    return saturate(dot(surface.normal, light.direction)) * light.color;
}

fn GetLightingForLight(surface: Surface, brdf: BRDF, light: Light) -> vec3<f32> {
    return IncomingLight(surface, light) * DirectBRDF(surface, brdf, light);
}

#if defined(_SINGLE_DIRECTIONAL_LIGHT)
// Specialised for scenes with one directional light: no loop, the first light or none.
fn GetLighting(surface: Surface, brdf: BRDF) -> vec3<f32> {
    let lit = GetLightingForLight(surface, brdf, GetDirectionalLight(0));
    return select(vec3<f32>(0.0), lit, GetDirectionalLightCount() > 0);
}
#else
fn GetLighting(surface: Surface, brdf: BRDF) -> vec3<f32> {
    var color = vec3<f32>(0.0);
    for (var i = 0; i < GetDirectionalLightCount(); i++) {
        color += GetLightingForLight(surface, brdf, GetDirectionalLight(i));
    }
    return color;
}
#endif

#endif
