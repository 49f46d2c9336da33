// UnityInput.hlsl: the per-frame and per-object constant buffers the renderer provides, with
// Unity's names and the members of Input.wgsl, so that an HLSL and a WGSL pass bind alike.
#ifndef KILN_UNITY_INPUT_INCLUDED
#define KILN_UNITY_INPUT_INCLUDED

CBUFFER_START(UnityPerFrame)
    float4x4 unity_MatrixVP;
    float3 _WorldSpaceCameraPos;
CBUFFER_END

CBUFFER_START(UnityPerDraw)
    float4x4 unity_ObjectToWorld;
    float4x4 unity_WorldToObject;
CBUFFER_END

#endif
