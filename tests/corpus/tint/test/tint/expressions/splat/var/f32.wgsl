@compute @workgroup_size(1)
fn f() {
    var v = 1.0 + 2.0;
    var v2 : vec2<f32> = vec2<f32>(v);
    var v3 : vec3<f32> = vec3<f32>(v);
    var v4 : vec4<f32> = vec4<f32>(v);
}
