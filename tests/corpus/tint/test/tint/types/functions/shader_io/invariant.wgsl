@vertex
fn main() -> @builtin(position) @invariant vec4<f32> {
  return vec4<f32>();
}
