@fragment
fn f() {
  discard;
  return;
}
