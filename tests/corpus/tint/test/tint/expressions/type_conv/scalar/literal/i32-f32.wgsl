var<private> u : f32 = f32(i32(1i));

@compute @workgroup_size(1)
fn main() {
    _ = u;
}
