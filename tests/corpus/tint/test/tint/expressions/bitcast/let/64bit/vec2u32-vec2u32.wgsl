@compute @workgroup_size(1)
fn f() {
    let a : vec2<u32> = vec2<u32>(1073757184u, 3288351232u);
    let b : vec2<u32> = bitcast<vec2<u32>>(a);
}
