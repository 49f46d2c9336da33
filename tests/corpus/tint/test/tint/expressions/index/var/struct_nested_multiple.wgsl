struct T {
  k: array<u32, 2>,
}

struct S {
  m: i32,
  n: array<T, 4>,
}

fn f() -> u32 {
  var a = S();
  return a.n[2].k[1];
}

@compute @workgroup_size(1)
fn main() {
    _ = f();
}
