@compute @workgroup_size(1)
fn main() {
    var v : mat2x3<f32>;
    _ = v;
}
