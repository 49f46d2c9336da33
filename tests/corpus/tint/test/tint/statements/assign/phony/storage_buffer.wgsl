struct S {
    i : i32,
};

@group(0) @binding(0) var<storage, read_write> s : S;
@group(0) @binding(1) var<storage> v1 : f32;
@group(0) @binding(2) var<storage> v2 : vec3u;

@compute @workgroup_size(1)
fn main() {
    _ = s;
    _ = s.i;
    _ = v1;
    _ = v2;
    _ = v2.x;
}
