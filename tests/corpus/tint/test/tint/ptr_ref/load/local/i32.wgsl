@compute @workgroup_size(1)
fn main() {
  var i : i32 = 123;
  let u : i32 = i + 1;
}
