//! The generated Rust structs of `fixtures/blocks` against the GPU: fill them through their
//! fields with distinct values, upload the bytes, have a compute shader read every scalar of the
//! WGSL blocks (found by walking kiln's reflection, not written by hand) and read them back. Each
//! value must be where the Rust side put it: the generated layout, the reflected layout and the
//! GPU's agree.

mod common;

use bytemuck::Zeroable;
use kiln::manifest::Manifest;
use kiln::reflect::Member;
use kiln_renderer::blocks::test_halfblocks::{HalfPair, Halves};
use kiln_renderer::blocks::test_uniformblocks::{Block, Cascade, Inner, Light, Shadow};
use std::path::Path;
use wgpu::util::DeviceExt;

/// Hands out 1, 2, 3, ... as the scalar types of WGSL; `i32`s negated, to see the sign.
#[derive(Default)]
struct Counter(u32);

impl Counter {
    fn f(&mut self) -> f32 {
        self.0 += 1;
        self.0 as f32
    }
    fn u(&mut self) -> u32 {
        self.0 += 1;
        self.0
    }
    fn i(&mut self) -> i32 {
        self.0 += 1;
        -(self.0 as i32)
    }
    fn v2(&mut self) -> [f32; 2] {
        [self.f(), self.f()]
    }
    fn v3(&mut self) -> [f32; 3] {
        [self.f(), self.f(), self.f()]
    }
    fn v4(&mut self) -> [f32; 4] {
        [self.f(), self.f(), self.f(), self.f()]
    }
    fn inner(&mut self) -> Inner {
        Inner { x: self.f(), y: self.v3(), ..Inner::zeroed() }
    }
}

/// Both blocks filled field by field in WGSL declaration order.
fn filled() -> (Block, Shadow, u32) {
    let mut n = Counter::default();
    let mut block = Block::zeroed();
    block.a = n.v3();
    block.b = n.f();
    for column in &mut block.c {
        column[..3].copy_from_slice(&n.v3()); // mat3x3 columns are padded to vec4
    }
    for row in &mut block.d {
        *row = n.v4();
    }
    block.e = n.v2();
    block.f = n.inner();
    block.g = n.f();
    for light in &mut block.lights {
        *light = Light { color: n.v3(), intensity: n.f(), dir: n.v3(), ..Light::zeroed() };
    }
    for element in &mut block.v3s {
        element.value = n.v3();
    }
    let mut shadow = Shadow::zeroed();
    shadow.uv = [n.v2(), n.v2()];
    for cascade in &mut shadow.cascades {
        *cascade = Cascade {
            view_proj: [n.v4(), n.v4(), n.v4(), n.v4()],
            split: n.v2(),
            index: n.u(),
            flags: n.i(),
        };
    }
    shadow.counts = [n.u(), n.u(), n.u()];
    shadow.bias = n.f();
    shadow.inner = n.inner();
    (block, shadow, n.0)
}

/// Every scalar under `path` of WGSL type `ty` (with `members` for structs and arrays of
/// structs), in declaration order: its access path and its scalar type.
fn scalars(
    path: &str,
    ty: &str,
    members: &[Member],
    array_length: Option<u32>,
    out: &mut Vec<(String, String)>,
) {
    if let Some(length) = array_length {
        let element = ty.strip_prefix("array<").and_then(|t| t.rsplit_once(',')).map(|(e, _)| e.trim());
        for i in 0..length {
            scalars(&format!("{path}[{i}]"), element.expect("array type"), members, None, out);
        }
    } else if !members.is_empty() {
        for m in members {
            scalars(&format!("{path}.{}", m.name), &m.ty, &m.members, m.array_length, out);
        }
    } else if let Some(rest) = ty.strip_prefix("vec") {
        let scalar = &rest[2..rest.len() - 1];
        for c in ["x", "y", "z", "w"].iter().take(rest[..1].parse().expect("size")) {
            out.push((format!("{path}.{c}"), scalar.to_string()));
        }
    } else if let Some(rest) = ty.strip_prefix("mat") {
        let (columns, rows): (usize, usize) =
            (rest[..1].parse().expect("cols"), rest[2..3].parse().expect("rows"));
        let scalar = &rest[4..rest.len() - 1];
        for c in 0..columns {
            for r in 0..rows {
                out.push((format!("{path}[{c}][{r}]"), scalar.to_string()));
            }
        }
    } else {
        out.push((path.to_string(), ty.to_string()));
    }
}

/// The bits of a small positive integer as an `f16`.
fn half(n: u32) -> u16 {
    assert!((1..2048).contains(&n), "exact in f16");
    let exponent = 31 - n.leading_zeros();
    let mantissa = (n - (1 << exponent)) << (10 - exponent);
    (((exponent + 15) << 10) | mantissa) as u16
}

/// The f16 block filled field by field in WGSL declaration order.
fn filled_halves() -> (Halves, u32) {
    let mut n = 0;
    let mut next = || {
        n += 1;
        n
    };
    let mut halves = Halves::zeroed();
    halves.h = half(next());
    halves.v2 = [half(next()), half(next())];
    halves.v3 = [half(next()), half(next()), half(next())];
    halves.v4 = [half(next()), half(next()), half(next()), half(next())];
    halves.tail = next() as f32;
    halves.pair =
        HalfPair { a: half(next()), b: [half(next()), half(next()), half(next())], ..HalfPair::zeroed() };
    halves.last = half(next());
    (halves, n)
}

/// The reflected blocks of the build script's `fixtures/blocks` build, by name.
fn reflected(name: &str) -> kiln::reflect::UniformBlock {
    let manifest = Manifest::read(&Path::new(env!("OUT_DIR")).join("blocks/kiln")).expect("manifest");
    let found = manifest.passes().flat_map(|p| &p.uniform_blocks).find(|b| b.name == name).cloned();
    found.expect("reflected block")
}

/// Uploads each block's bytes as a uniform buffer at binding 0, 1, ...; a compute shader copies
/// every scalar the reflection lists into a storage buffer; each must read back as its position
/// in declaration order, 1, 2, 3, ... (negated for `i32`), as the fills above wrote them.
fn round_trip(device: &wgpu::Device, queue: &wgpu::Queue, structs: &str, blocks: &[(&str, &[u8])]) -> usize {
    let mut reads = Vec::new();
    let mut declarations = String::from(structs);
    for (binding, (name, _)) in blocks.iter().enumerate() {
        let block = reflected(name);
        scalars(name, &block.type_name, &block.members, None, &mut reads);
        declarations += &format!("@group(0) @binding({binding}) var<uniform> {name}: {};\n", block.type_name);
    }
    let copies: String = reads
        .iter()
        .enumerate()
        .map(|(i, (path, ty))| match ty.as_str() {
            "u32" => format!("    out[{i}] = {path};\n"),
            "f16" => format!("    out[{i}] = bitcast<u32>(f32({path}));\n"),
            _ => format!("    out[{i}] = bitcast<u32>({path});\n"),
        })
        .collect();
    let out_binding = blocks.len();
    let source = format!(
        "{declarations}@group(0) @binding({out_binding}) var<storage, read_write> out: array<u32>;\n\
         @compute @workgroup_size(1) fn main() {{\n{copies}}}\n"
    );
    let module = device.create_shader_module(wgpu::ShaderModuleDescriptor {
        label: Some("copy every scalar"),
        source: wgpu::ShaderSource::Wgsl(source.into()),
    });
    let pipeline = device.create_compute_pipeline(&wgpu::ComputePipelineDescriptor {
        label: None,
        layout: None,
        module: &module,
        entry_point: Some("main"),
        compilation_options: Default::default(),
        cache: None,
    });
    let uniforms: Vec<wgpu::Buffer> = blocks
        .iter()
        .map(|(_, bytes)| {
            device.create_buffer_init(&wgpu::util::BufferInitDescriptor {
                label: None,
                contents: bytes,
                usage: wgpu::BufferUsages::UNIFORM,
            })
        })
        .collect();
    let size = 4 * reads.len() as u64;
    let out = device.create_buffer(&wgpu::BufferDescriptor {
        label: None,
        size,
        usage: wgpu::BufferUsages::STORAGE | wgpu::BufferUsages::COPY_SRC,
        mapped_at_creation: false,
    });
    let readback = device.create_buffer(&wgpu::BufferDescriptor {
        label: None,
        size,
        usage: wgpu::BufferUsages::MAP_READ | wgpu::BufferUsages::COPY_DST,
        mapped_at_creation: false,
    });
    let mut entries: Vec<wgpu::BindGroupEntry> = uniforms
        .iter()
        .enumerate()
        .map(|(i, buffer)| wgpu::BindGroupEntry { binding: i as u32, resource: buffer.as_entire_binding() })
        .collect();
    entries.push(wgpu::BindGroupEntry { binding: out_binding as u32, resource: out.as_entire_binding() });
    let bind_group = device.create_bind_group(&wgpu::BindGroupDescriptor {
        label: None,
        layout: &pipeline.get_bind_group_layout(0),
        entries: &entries,
    });
    let mut encoder = device.create_command_encoder(&Default::default());
    {
        let mut pass = encoder.begin_compute_pass(&Default::default());
        pass.set_pipeline(&pipeline);
        pass.set_bind_group(0, &bind_group, &[]);
        pass.dispatch_workgroups(1, 1, 1);
    }
    encoder.copy_buffer_to_buffer(&out, 0, &readback, 0, size);
    queue.submit([encoder.finish()]);
    readback.map_async(wgpu::MapMode::Read, .., |result| result.expect("maps"));
    device.poll(wgpu::PollType::wait_indefinitely()).expect("poll");
    let words: Vec<u32> = bytemuck::cast_slice(&readback.get_mapped_range(..).expect("mapped")).to_vec();

    let wrong: Vec<String> = reads
        .iter()
        .zip(&words)
        .enumerate()
        .filter_map(|(i, ((path, ty), &got))| {
            let n = i as u32 + 1;
            let expected = match ty.as_str() {
                "u32" => n,
                "i32" => (-(n as i32)) as u32,
                _ => (n as f32).to_bits(),
            };
            (got != expected).then(|| format!("{path} ({ty}): read {got:#x}, expected {expected:#x}"))
        })
        .collect();
    assert!(wrong.is_empty(), "{} of {} values misplaced:\n{}", wrong.len(), reads.len(), wrong.join("\n"));
    reads.len()
}

#[test]
fn generated_structs_put_every_value_where_the_gpu_reads_it() {
    let Some((device, queue, adapter)) = common::gpu("the uniform block round trip") else { return };
    let (block, shadow, count) = filled();
    let blocks: [(&str, &[u8]); 2] =
        [("blk", bytemuck::bytes_of(&block)), ("shadow", bytemuck::bytes_of(&shadow))];
    let read = round_trip(&device, &queue, include_str!("../../../fixtures/blocks/Blocks.wgsl"), &blocks);
    assert_eq!(read, count as usize, "the Rust fill covers every scalar the reflection lists");
    println!("{adapter}: {read} scalars of 2 uniform blocks read back where the Rust structs put them");
}

#[test]
fn generated_structs_with_f16_members_put_every_value_where_the_gpu_reads_it() {
    let Some((device, queue, adapter)) = common::gpu("the f16 uniform block round trip") else { return };
    if !device.features().contains(wgpu::Features::SHADER_F16) {
        common::skipped(&format!("the f16 round trip: {adapter} has no shader-f16"));
        return;
    }
    let (halves, count) = filled_halves();
    let structs = format!("enable f16;\n{}", include_str!("../../../fixtures/blocks/HalfBlocks.wgsl"));
    let read = round_trip(&device, &queue, &structs, &[("halves", bytemuck::bytes_of(&halves))]);
    assert_eq!(read, count as usize, "the Rust fill covers every scalar the reflection lists");
    println!("{adapter}: {read} scalars of an f16 uniform block read back where the Rust structs put them");
}
