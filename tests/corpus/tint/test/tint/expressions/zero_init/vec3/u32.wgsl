@compute @workgroup_size(1)
fn f() {
    var v = vec3<u32>();
}
