@compute @workgroup_size(1)
fn f() {
    var v = vec2<u32>();
}
