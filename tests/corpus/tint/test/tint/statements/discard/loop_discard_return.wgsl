@fragment
fn f() {
  loop {
    discard;
    return;
  }
}
