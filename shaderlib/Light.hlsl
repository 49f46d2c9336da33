// Light.hlsl: up to four directional lights in `_CustomLight`, laid out as Light.wgsl's (the
// count at 0, colours at 16, directions at 80).
#ifndef KILN_LIGHT_INCLUDED
#define KILN_LIGHT_INCLUDED

#define MAX_DIRECTIONAL_LIGHT_COUNT 4

CBUFFER_START(_CustomLight)
    int _DirectionalLightCount;
    float4 _DirectionalLightColors[MAX_DIRECTIONAL_LIGHT_COUNT];
    float4 _DirectionalLightDirections[MAX_DIRECTIONAL_LIGHT_COUNT];
CBUFFER_END

struct Light {
    float3 color;
    // Towards the light, normalised.
    float3 direction;
};

// A count above the array's size would read past the lights written: clamped.
int GetDirectionalLightCount() {
    return min(_DirectionalLightCount, MAX_DIRECTIONAL_LIGHT_COUNT);
}

Light GetDirectionalLight(int index) {
    Light light;
    light.color = _DirectionalLightColors[index].rgb;
    light.direction = _DirectionalLightDirections[index].xyz;
    return light;
}

#endif
