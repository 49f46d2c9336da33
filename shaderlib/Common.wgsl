// Common.wgsl: small helpers and space transforms every other library file may use.
#ifndef KILN_COMMON_INCLUDED
#define KILN_COMMON_INCLUDED

#include "Input.wgsl"

// The smallest normal f32: clamping a squared length to it keeps inverseSqrt finite.
#define KILN_FLT_MIN 1.17549435e-38

fn Square(v: f32) -> f32 {
    return v * v;
}

// Normalises v, or returns zero for a zero-length vector instead of NaN (L = -V makes the half
// vector zero, where normalize() would divide by zero).
fn SafeNormalize(v: vec3<f32>) -> vec3<f32> {
    return v * inverseSqrt(max(dot(v, v), KILN_FLT_MIN));
}

fn TransformObjectToWorld(positionOS: vec3<f32>) -> vec3<f32> {
    return (UnityPerDraw.unity_ObjectToWorld * vec4<f32>(positionOS, 1.0)).xyz;
}

fn TransformWorldToHClip(positionWS: vec3<f32>) -> vec4<f32> {
    return UnityPerFrame.unity_MatrixVP * vec4<f32>(positionWS, 1.0);
}

// Normals go through the inverse transpose of object-to-world; multiplying the row vector by
// world-to-object is exactly that, and stays correct under non-uniform scale.
fn TransformObjectToWorldNormal(normalOS: vec3<f32>) -> vec3<f32> {
    return SafeNormalize((vec4<f32>(normalOS, 0.0) * UnityPerDraw.unity_WorldToObject).xyz);
}

#endif
