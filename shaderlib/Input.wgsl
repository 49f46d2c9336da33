// Input.wgsl: the per-frame and per-object uniforms the renderer provides (Unity's names, so
// ported code reads the same). kiln binds them by update frequency: `UnityPerFrame` with the
// lights in group 0, `UnityPerDraw` in group 2.
#ifndef KILN_INPUT_INCLUDED
#define KILN_INPUT_INCLUDED

struct PerFrame {
    unity_MatrixVP: mat4x4<f32>,
    _WorldSpaceCameraPos: vec3<f32>,
}

struct PerDraw {
    unity_ObjectToWorld: mat4x4<f32>,
    unity_WorldToObject: mat4x4<f32>,
}

var<uniform> UnityPerFrame: PerFrame;
var<uniform> UnityPerDraw: PerDraw;

#endif
