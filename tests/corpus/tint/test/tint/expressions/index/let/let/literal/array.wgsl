fn f() -> i32 {
  let a = array<i32, 8>(1, 2, 3, 4, 5, 6, 7, 8);
  let i = 1;
  return a[i];
}

@compute @workgroup_size(1)
fn main() {
    _ = f();
}
