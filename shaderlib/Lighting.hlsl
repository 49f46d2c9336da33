// Lighting.hlsl: light arriving at the surface, shaded by the BRDF, summed over the lights.
#ifndef KILN_LIGHTING_INCLUDED
#define KILN_LIGHTING_INCLUDED

#include "Surface.hlsl"
#include "Light.hlsl"
#include "BRDF.hlsl"

// Light from behind the surface contributes nothing.
float3 IncomingLight(Surface surface, Light light) {
    return saturate(dot(surface.normal, light.direction)) * light.color;
}

float3 GetLighting(Surface surface, BRDF brdf, Light light) {
    return IncomingLight(surface, light) * DirectBRDF(surface, brdf, light);
}

#if defined(_SINGLE_DIRECTIONAL_LIGHT)
// One directional light: no loop, the first light or none.
float3 GetLighting(Surface surface, BRDF brdf) {
    return GetDirectionalLightCount() > 0 ? GetLighting(surface, brdf, GetDirectionalLight(0)) : 0.0;
}
#else
float3 GetLighting(Surface surface, BRDF brdf) {
    float3 color = 0.0;
    for (int i = 0; i < GetDirectionalLightCount(); i++) {
        color += GetLighting(surface, brdf, GetDirectionalLight(i));
    }
    return color;
}
#endif

#endif
