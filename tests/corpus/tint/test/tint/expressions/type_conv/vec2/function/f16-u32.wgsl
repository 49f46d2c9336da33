// flags:  --hlsl-shader-model 6.2
enable f16;
var<private> t : f16;
fn m() -> vec2<f16> {
    t = 1.0h;
    return vec2<f16>(t);
}

@compute @workgroup_size(1)
fn f() {
    var v : vec2<u32> = vec2<u32>(m());
}
