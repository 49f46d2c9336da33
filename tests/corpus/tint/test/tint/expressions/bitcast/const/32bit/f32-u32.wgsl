@compute @workgroup_size(1)
fn f() {
    const a : f32 = f32(2.003662109375f);
    let b : u32 = bitcast<u32>(a);
}
