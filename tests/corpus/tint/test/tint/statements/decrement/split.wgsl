@compute @workgroup_size(1)
fn main() {
  var b = 2;
  var c = b--b;
}
