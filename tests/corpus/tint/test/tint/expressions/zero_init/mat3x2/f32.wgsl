@compute @workgroup_size(1)
fn f() {
    var v = mat3x2<f32>();
}
