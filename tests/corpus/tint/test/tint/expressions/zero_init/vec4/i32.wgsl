@compute @workgroup_size(1)
fn f() {
    var v = vec4<i32>();
}
