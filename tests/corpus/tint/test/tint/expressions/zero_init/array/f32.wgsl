@compute @workgroup_size(1)
fn f() {
    var v = array<f32, 4>();
}
