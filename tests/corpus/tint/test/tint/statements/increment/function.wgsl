@compute @workgroup_size(1)
fn main() {
  var i = 0;
  i++;
}
