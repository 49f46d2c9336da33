// flags:  --hlsl-shader-model 6.2
enable f16;
var<private> v = vec4(0.h, 1.h, 2.h, 3.h);

@compute @workgroup_size(1)
fn main() {
    _ = v;
}
