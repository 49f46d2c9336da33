// kiln preprocess fixtures/project/shaders/Complex.shader --pass 0

// ComplexPass.wgsl: after the seed's "Complex Materials": metallic from a map or a value,
// smoothness from the albedo alpha, the metallic map's alpha or a value, optional emission map.

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

// Surface.wgsl: what lighting needs to know about the point being shaded.

struct Surface {
    normal: vec3<f32>,
    // From the surface towards the camera, normalised.
    viewDirection: vec3<f32>,
    color: vec3<f32>,
    alpha: f32,
    metallic: f32,
    smoothness: f32,
}

// Light.wgsl: up to four directional lights, uploaded by the renderer in `_CustomLight`.


// Layout (std140-like, from naga): count at 0, colours at 16, directions at 80, 144 bytes.
struct CustomLight {
    _DirectionalLightCount: i32,
    _DirectionalLightColors: array<vec4<f32>, 4>,
    _DirectionalLightDirections: array<vec4<f32>, 4>,
}

var<uniform> _CustomLight: CustomLight;

struct Light {
    color: vec3<f32>,
    // Towards the light (where it comes from), normalised.
    direction: vec3<f32>,
}

// A count above the array size would read past the lights the renderer wrote, so it is clamped.
fn GetDirectionalLightCount() -> i32 {
    return min(_CustomLight._DirectionalLightCount, 4);
}

fn GetDirectionalLight(index: i32) -> Light {
    var light: Light;
    light.color = _CustomLight._DirectionalLightColors[index].rgb;
    light.direction = _CustomLight._DirectionalLightDirections[index].xyz;
    return light;
}

// BRDF.wgsl: the metallic workflow split into diffuse and specular colours, and the minimal
// Cook-Torrance specular term Unity's Universal RP uses.


// Dielectrics still reflect about 4% of light specularly.

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
    let range = 1.0 - 0.04;
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
    brdf.specular = mix(vec3<f32>(0.04), surface.color, surface.metallic);
    let perceptualRoughness = PerceptualSmoothnessToPerceptualRoughness(surface.smoothness);
    brdf.roughness = PerceptualRoughnessToRoughness(perceptualRoughness);
    return brdf;
}

// Roughness is kept at or above this in the stable forms, so that r^2 stays a normal f32 number
// (and, scaled by 2^10, a normal f16 one) instead of flushing to zero.

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

fn DirectBRDF(surface: Surface, brdf: BRDF, light: Light) -> vec3<f32> {
    return SpecularStrength(surface, brdf, light) * brdf.specular + brdf.diffuse;
}

// Lighting.wgsl: light arriving at the surface, shaded by the BRDF, summed over the lights.


// Light from behind the surface contributes nothing, hence the saturate.
fn IncomingLight(surface: Surface, light: Light) -> vec3<f32> {
    return saturate(dot(surface.normal, light.direction)) * light.color;
}

fn GetLightingForLight(surface: Surface, brdf: BRDF, light: Light) -> vec3<f32> {
    return IncomingLight(surface, light) * DirectBRDF(surface, brdf, light);
}

fn GetLighting(surface: Surface, brdf: BRDF) -> vec3<f32> {
    var color = vec3<f32>(0.0);
    for (var i = 0; i < GetDirectionalLightCount(); i++) {
        color += GetLightingForLight(surface, brdf, GetDirectionalLight(i));
    }
    return color;
}


struct ComplexMaterial {
    _BaseMap_ST: vec4<f32>,
    _BaseColor: vec4<f32>,
    _Emission: vec4<f32>,
    _Metallic: f32,
    _Smoothness: f32,
}

var<uniform> UnityPerMaterial: ComplexMaterial;
var _BaseMap: texture_2d<f32>;
var sampler_BaseMap: sampler;
var _MetallicMap: texture_2d<f32>;
var sampler_MetallicMap: sampler;
var _EmissionMap: texture_2d<f32>;
var sampler_EmissionMap: sampler;

struct Attributes {
    @location(0) positionOS: vec3<f32>,
    @location(1) normalOS: vec3<f32>,
    @location(2) baseUV: vec2<f32>,
}

struct Varyings {
    @builtin(position) positionCS: vec4<f32>,
    @location(0) positionWS: vec3<f32>,
    @location(1) normalWS: vec3<f32>,
    @location(2) baseUV: vec2<f32>,
}

@vertex
fn ComplexPassVertex(input: Attributes) -> Varyings {
    var output: Varyings;
    output.positionWS = TransformObjectToWorld(input.positionOS);
    output.positionCS = TransformWorldToHClip(output.positionWS);
    output.normalWS = TransformObjectToWorldNormal(input.normalOS);
    let st = UnityPerMaterial._BaseMap_ST;
    output.baseUV = input.baseUV * st.xy + st.zw;
    return output;
}

fn GetMetallic(uv: vec2<f32>) -> f32 {
    return UnityPerMaterial._Metallic;
}

fn GetSmoothness(uv: vec2<f32>) -> f32 {
    var smoothness = 1.0;
    return smoothness * UnityPerMaterial._Smoothness;
}

fn GetEmission(uv: vec2<f32>) -> vec3<f32> {
    return UnityPerMaterial._Emission.rgb;
}

@fragment
fn ComplexPassFragment(input: Varyings) -> @location(0) vec4<f32> {
    let base = textureSample(_BaseMap, sampler_BaseMap, input.baseUV) * UnityPerMaterial._BaseColor;
    var surface: Surface;
    surface.normal = SafeNormalize(input.normalWS);
    surface.viewDirection = SafeNormalize(UnityPerFrame._WorldSpaceCameraPos - input.positionWS);
    surface.color = base.rgb;
    surface.alpha = base.a;
    surface.metallic = GetMetallic(input.baseUV);
    surface.smoothness = GetSmoothness(input.baseUV);
    let brdf = GetBRDF(surface, false);
    let color = GetLighting(surface, brdf) + GetEmission(input.baseUV);
    return vec4<f32>(color, surface.alpha);
}

            

// ---- source map: output lines <- original lines ----
// 1 <- fixtures/project/shaders/Complex.shader:18
// 2-3 <- fixtures/project/shaders/ComplexPass.wgsl:1-2
// 4 <- fixtures/project/shaders/ComplexPass.wgsl:5
// 5 <- <kiln>/shaderlib/Common.wgsl:1
// 6 <- <kiln>/shaderlib/Common.wgsl:4
// 7-9 <- <kiln>/shaderlib/Input.wgsl:1-3
// 10-23 <- <kiln>/shaderlib/Input.wgsl:6-19
// 24-25 <- <kiln>/shaderlib/Common.wgsl:6-7
// 26-50 <- <kiln>/shaderlib/Common.wgsl:9-33
// 51 <- <kiln>/shaderlib/Surface.wgsl:1
// 52-62 <- <kiln>/shaderlib/Surface.wgsl:4-14
// 63 <- <kiln>/shaderlib/Light.wgsl:1
// 64 <- <kiln>/shaderlib/Light.wgsl:4
// 65-92 <- <kiln>/shaderlib/Light.wgsl:6-33
// 93-94 <- <kiln>/shaderlib/BRDF.wgsl:1-2
// 95 <- <kiln>/shaderlib/BRDF.wgsl:5
// 96-97 <- <kiln>/shaderlib/BRDF.wgsl:9-10
// 98-139 <- <kiln>/shaderlib/BRDF.wgsl:12-53
// 140 <- <kiln>/shaderlib/BRDF.wgsl:55
// 141-151 <- <kiln>/shaderlib/BRDF.wgsl:131-141
// 152-156 <- <kiln>/shaderlib/BRDF.wgsl:143-147
// 157 <- <kiln>/shaderlib/Lighting.wgsl:1
// 158 <- <kiln>/shaderlib/Lighting.wgsl:4
// 159-168 <- <kiln>/shaderlib/Lighting.wgsl:8-17
// 169-175 <- <kiln>/shaderlib/Lighting.wgsl:25-31
// 176 <- <kiln>/shaderlib/Lighting.wgsl:33
// 177-218 <- fixtures/project/shaders/ComplexPass.wgsl:11-52
// 219 <- fixtures/project/shaders/ComplexPass.wgsl:56
// 220-223 <- fixtures/project/shaders/ComplexPass.wgsl:58-61
// 224-227 <- fixtures/project/shaders/ComplexPass.wgsl:67-70
// 228 <- fixtures/project/shaders/ComplexPass.wgsl:74
// 229-245 <- fixtures/project/shaders/ComplexPass.wgsl:76-92
// 246 <- fixtures/project/shaders/Complex.shader:26
