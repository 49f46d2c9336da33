@compute @workgroup_size(1)
fn f() {
    var a = vec2<f32>(1.0).y;
    var b = vec3<f32>(1.0).z;
    var c = vec4<f32>(1.0).w;
}
