@compute @workgroup_size(1)
fn f() {
    var v = array<u32, 4>();
}
