@compute @workgroup_size(1)
fn f() {
  for (var i : i32 = 0; false;) {}
}
