@compute @workgroup_size(1)
fn f() {
  var i : i32;
  for (;i < array<i32, 1>(1)[0];) {}
}
