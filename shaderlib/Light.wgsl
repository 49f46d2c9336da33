// Light.wgsl: up to four directional lights, uploaded by the renderer in `_CustomLight`.
#ifndef KILN_LIGHT_INCLUDED
#define KILN_LIGHT_INCLUDED

#define MAX_DIRECTIONAL_LIGHT_COUNT 4

// Layout (std140-like, from naga): count at 0, colours at 16, directions at 80, 144 bytes.
struct CustomLight {
    _DirectionalLightCount: i32,
    _DirectionalLightColors: array<vec4<f32>, MAX_DIRECTIONAL_LIGHT_COUNT>,
    _DirectionalLightDirections: array<vec4<f32>, MAX_DIRECTIONAL_LIGHT_COUNT>,
}

var<uniform> _CustomLight: CustomLight;

struct Light {
    color: vec3<f32>,
    // Towards the light (where it comes from), normalised.
    direction: vec3<f32>,
}

// A count above the array size would read past the lights the renderer wrote, so it is clamped.
fn GetDirectionalLightCount() -> i32 {
    return min(_CustomLight._DirectionalLightCount, MAX_DIRECTIONAL_LIGHT_COUNT);
}

fn GetDirectionalLight(index: i32) -> Light {
    var light: Light;
    light.color = _CustomLight._DirectionalLightColors[index].rgb;
    light.direction = _CustomLight._DirectionalLightDirections[index].xyz;
    return light;
}

#endif
