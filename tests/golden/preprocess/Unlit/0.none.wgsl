// kiln preprocess fixtures/project/shaders/Unlit.shader --pass 0

// UnlitPass.wgsl: the seed's unlit pass: a tinted texture, optionally alpha clipped.

// Common.wgsl: small helpers and space transforms every other library file may use.

// Input.wgsl: the per-frame and per-object uniforms the renderer provides (Unity's names, so
// ported code reads the same). kiln binds them by update frequency: `UnityPerFrame` with the
// lights in group 0, `UnityPerDraw` in group 2.

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


// The smallest normal f32: clamping a squared length to it keeps inverseSqrt finite.

fn Square(v: f32) -> f32 {
    return v * v;
}

// Normalises v, or returns zero for a zero-length vector instead of NaN (L = -V makes the half
// vector zero, where normalize() would divide by zero).
fn SafeNormalize(v: vec3<f32>) -> vec3<f32> {
    return v * inverseSqrt(max(dot(v, v), 1.17549435e-38));
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


struct UnlitMaterial {
    _BaseMap_ST: vec4<f32>,
    _BaseColor: vec4<f32>,
    _Cutoff: f32,
}

var<uniform> UnityPerMaterial: UnlitMaterial;
var _BaseMap: texture_2d<f32>;
var sampler_BaseMap: sampler;

struct Attributes {
    @location(0) positionOS: vec3<f32>,
    @location(1) baseUV: vec2<f32>,
}

struct Varyings {
    @builtin(position) positionCS: vec4<f32>,
    @location(0) baseUV: vec2<f32>,
}

@vertex
fn UnlitPassVertex(input: Attributes) -> Varyings {
    var output: Varyings;
    output.positionCS = TransformWorldToHClip(TransformObjectToWorld(input.positionOS));
    let st = UnityPerMaterial._BaseMap_ST;
    output.baseUV = input.baseUV * st.xy + st.zw;
    return output;
}

@fragment
fn UnlitPassFragment(input: Varyings) -> @location(0) vec4<f32> {
    let base = textureSample(_BaseMap, sampler_BaseMap, input.baseUV) * UnityPerMaterial._BaseColor;
    return base;
}

            

// ---- source map: output lines <- original lines ----
// 1 <- fixtures/project/shaders/Unlit.shader:18
// 2 <- fixtures/project/shaders/UnlitPass.wgsl:1
// 3 <- fixtures/project/shaders/UnlitPass.wgsl:4
// 4 <- <kiln>/shaderlib/Common.wgsl:1
// 5 <- <kiln>/shaderlib/Common.wgsl:4
// 6-8 <- <kiln>/shaderlib/Input.wgsl:1-3
// 9-22 <- <kiln>/shaderlib/Input.wgsl:6-19
// 23-24 <- <kiln>/shaderlib/Common.wgsl:6-7
// 25-49 <- <kiln>/shaderlib/Common.wgsl:9-33
// 50-82 <- fixtures/project/shaders/UnlitPass.wgsl:6-38
// 83-85 <- fixtures/project/shaders/UnlitPass.wgsl:44-46
// 86 <- fixtures/project/shaders/Unlit.shader:24
