// Common.hlsl: the macros and helpers Unity's core library gives HLSL passes (constant buffers,
// textures, instanced properties, space transforms), written for kiln: a pass written against
// Unity's names compiles as it is. Instancing macros read the material's constant buffer, as
// Unity's do when instancing is off.
#ifndef KILN_COMMON_INCLUDED
#define KILN_COMMON_INCLUDED

#define CBUFFER_START(name) cbuffer name {
#define CBUFFER_END };

#define TEXTURE2D(name) Texture2D name
#define SAMPLER(name) SamplerState name
#define SAMPLE_TEXTURE2D(texture, state, uv) texture.Sample(state, uv)

// kiln's run time draws one instance per material, so the instanced macros read the material's
// buffer whether `INSTANCING_ON` is on or not (the variant with it compiles the same text).
#if defined(INSTANCING_ON)
#define KILN_INSTANCED_PROPERTIES_FROM_THE_MATERIAL 1
#endif
#define UNITY_INSTANCING_BUFFER_START(name) cbuffer name {
#define UNITY_INSTANCING_BUFFER_END(name) };
#define UNITY_DEFINE_INSTANCED_PROP(type, name) type name;
#define UNITY_ACCESS_INSTANCED_PROP(buffer, name) name
#define UNITY_VERTEX_INPUT_INSTANCE_ID
#define UNITY_SETUP_INSTANCE_ID(input)
#define UNITY_TRANSFER_INSTANCE_ID(input, output)

#define real float
#define real2 float2
#define real3 float3
#define real4 float4

#define PI 3.14159265359

// The smallest normal float: clamping a squared length to it keeps rsqrt finite.
#define KILN_FLT_MIN 1.17549435e-38

#include "UnityInput.hlsl"

#define UNITY_MATRIX_M unity_ObjectToWorld
#define UNITY_MATRIX_I_M unity_WorldToObject
#define UNITY_MATRIX_VP unity_MatrixVP

float Square(float v) {
    return v * v;
}

// Normalises v, or gives zero for a zero-length vector instead of NaN.
float3 SafeNormalize(float3 v) {
    return v * rsqrt(max(dot(v, v), KILN_FLT_MIN));
}

float3 TransformObjectToWorld(float3 positionOS) {
    return mul(UNITY_MATRIX_M, float4(positionOS, 1.0)).xyz;
}

float4 TransformWorldToHClip(float3 positionWS) {
    return mul(UNITY_MATRIX_VP, float4(positionWS, 1.0));
}

// Normals go through the inverse transpose of object-to-world: the row vector times
// world-to-object, correct under non-uniform scale.
float3 TransformObjectToWorldNormal(float3 normalOS) {
    return SafeNormalize(mul(normalOS, (float3x3)UNITY_MATRIX_I_M));
}

#endif
