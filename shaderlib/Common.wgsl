// Common.wgsl: small helpers every other library file may use.
#ifndef KILN_COMMON_INCLUDED
#define KILN_COMMON_INCLUDED

fn Square(v: f32) -> f32 {
    return v * v;
}

// Normalises v, or returns zero for a zero-length vector instead of NaN (L = -V makes the half
// vector zero; normalize() would divide by zero there).
fn SafeNormalize(v: vec3<f32>) -> vec3<f32> {
    let len_sq = dot(v, v);
    if (len_sq < 1e-30) {
        return vec3<f32>(0.0);
    }
    return v * inverseSqrt(len_sq);
}

#endif
