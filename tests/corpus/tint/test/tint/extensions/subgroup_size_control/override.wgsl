// [hlsl-dxc] flags: --hlsl-shader-model 6.6 --overrides kSubgroupSize=16
// [spvasm] flags: --overrides kSubgroupSize=16

enable subgroup_size_control;

override kSubgroupSize : i32;

@group(0) @binding(0)
var<storage, read_write> buffer: array<u32>;

@compute @workgroup_size(16, 1, 1) @subgroup_size(kSubgroupSize)
fn main(@builtin(subgroup_invocation_id) sg_id : u32,
        @builtin(subgroup_size) sg_size : u32) {
    buffer[sg_id] = sg_size;
}
