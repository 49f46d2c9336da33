// flags:  --hlsl-shader-model 6.2
enable f16;
var<private> t : bool;
fn m() -> vec2<bool> {
    t = true;
    return vec2<bool>(t);
}

@compute @workgroup_size(1)
fn f() {
    var v : vec2<f16> = vec2<f16>(m());
}
