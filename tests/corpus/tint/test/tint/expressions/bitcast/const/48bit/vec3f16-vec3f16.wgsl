// flags:  --hlsl-shader-model 6.2
enable f16;

@compute @workgroup_size(1)
fn f() {
    const a : vec3<f16> = vec3<f16>(1.0h, 2.0h, 3.0h);
    let b : vec3<f16> = bitcast<vec3<f16>>(a);
}
