@compute @workgroup_size(1)
fn main() {
    var v : i32;
    _ = v;
}
