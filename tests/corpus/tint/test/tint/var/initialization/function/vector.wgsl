@compute @workgroup_size(1)
fn main() {
    var v : vec3<i32>;
    _ = v;
}
