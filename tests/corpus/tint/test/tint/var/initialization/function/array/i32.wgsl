@compute @workgroup_size(1)
fn main() {
    var zero : array<i32, 3>;
    var init : array<i32, 3> = array<i32, 3>(1, 2, 3);
}
