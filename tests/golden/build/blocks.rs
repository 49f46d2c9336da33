    /// The struct `Inner` (32 bytes).
    #[repr(C)]
    #[derive(Clone, Copy, Debug, PartialEq, ::bytemuck::Pod, ::bytemuck::Zeroable)]
    pub struct Inner {
        /// `x`: `f32` at offset 0.
        pub x: f32,
        pub _pad0: [u8; 12],
        /// `y`: `vec3<f32>` at offset 16.
        pub y: [f32; 3],
        pub _pad1: [u8; 4],
    }
    const _: () = assert!(::core::mem::size_of::<Inner>() == 32);
    const _: () = assert!(::core::mem::offset_of!(Inner, x) == 0);
    const _: () = assert!(::core::mem::offset_of!(Inner, y) == 16);
    /// The struct `Light` (32 bytes), an element of `Block::lights`.
    #[repr(C)]
    #[derive(Clone, Copy, Debug, PartialEq, ::bytemuck::Pod, ::bytemuck::Zeroable)]
    pub struct Light {
        /// `color`: `vec3<f32>` at offset 0.
        pub color: [f32; 3],
        /// `intensity`: `f32` at offset 12.
        pub intensity: f32,
        /// `dir`: `vec3<f32>` at offset 16.
        pub dir: [f32; 3],
        pub _pad0: [u8; 4],
    }
    const _: () = assert!(::core::mem::size_of::<Light>() == 32);
    const _: () = assert!(::core::mem::offset_of!(Light, color) == 0);
    const _: () = assert!(::core::mem::offset_of!(Light, intensity) == 12);
    const _: () = assert!(::core::mem::offset_of!(Light, dir) == 16);
    /// An element of `Block::v3s`, padded to its stride.
    #[repr(C)]
    #[derive(Clone, Copy, Debug, PartialEq, ::bytemuck::Pod, ::bytemuck::Zeroable)]
    pub struct Block_v3s_Element {
        pub value: [f32; 3],
        pub _pad: [u8; 4],
    }
    /// The uniform block `blk` (336 bytes, aligned to 16).
    #[repr(C)]
    #[derive(Clone, Copy, Debug, PartialEq, ::bytemuck::Pod, ::bytemuck::Zeroable)]
    pub struct Block {
        /// `a`: `vec3<f32>` at offset 0.
        pub a: [f32; 3],
        /// `b`: `f32` at offset 12.
        pub b: f32,
        /// `c`: `mat3x3<f32>` at offset 16.
        pub c: [[f32; 4]; 3],
        /// `d`: `array<vec4<f32>, 3>` at offset 64.
        pub d: [[f32; 4]; 3],
        /// `e`: `vec2<f32>` at offset 112.
        pub e: [f32; 2],
        pub _pad0: [u8; 8],
        /// `f`: `Inner` at offset 128.
        pub f: Inner,
        /// `g`: `f32` at offset 160.
        pub g: f32,
        pub _pad1: [u8; 12],
        /// `lights`: `array<Light, 4>` at offset 176.
        pub lights: [Light; 4],
        /// `v3s`: `array<vec3<f32>, 2>` at offset 304.
        pub v3s: [Block_v3s_Element; 2],
    }
    const _: () = assert!(::core::mem::size_of::<Block>() == 336);
    const _: () = assert!(::core::mem::offset_of!(Block, a) == 0);
    const _: () = assert!(::core::mem::offset_of!(Block, b) == 12);
    const _: () = assert!(::core::mem::offset_of!(Block, c) == 16);
    const _: () = assert!(::core::mem::offset_of!(Block, d) == 64);
    const _: () = assert!(::core::mem::offset_of!(Block, e) == 112);
    const _: () = assert!(::core::mem::offset_of!(Block, f) == 128);
    const _: () = assert!(::core::mem::offset_of!(Block, g) == 160);
    const _: () = assert!(::core::mem::offset_of!(Block, lights) == 176);
    const _: () = assert!(::core::mem::offset_of!(Block, v3s) == 304);
    /// The struct `Cascade` (80 bytes), an element of `Shadow::cascades`.
    #[repr(C)]
    #[derive(Clone, Copy, Debug, PartialEq, ::bytemuck::Pod, ::bytemuck::Zeroable)]
    pub struct Cascade {
        /// `view_proj`: `mat4x4<f32>` at offset 0.
        pub view_proj: [[f32; 4]; 4],
        /// `split`: `vec2<f32>` at offset 64.
        pub split: [f32; 2],
        /// `index`: `u32` at offset 72.
        pub index: u32,
        /// `flags`: `i32` at offset 76.
        pub flags: i32,
    }
    const _: () = assert!(::core::mem::size_of::<Cascade>() == 80);
    const _: () = assert!(::core::mem::offset_of!(Cascade, view_proj) == 0);
    const _: () = assert!(::core::mem::offset_of!(Cascade, split) == 64);
    const _: () = assert!(::core::mem::offset_of!(Cascade, index) == 72);
    const _: () = assert!(::core::mem::offset_of!(Cascade, flags) == 76);
    /// The uniform block `shadow` (224 bytes, aligned to 16).
    #[repr(C)]
    #[derive(Clone, Copy, Debug, PartialEq, ::bytemuck::Pod, ::bytemuck::Zeroable)]
    pub struct Shadow {
        /// `uv`: `mat2x2<f32>` at offset 0.
        pub uv: [[f32; 2]; 2],
        /// `cascades`: `array<Cascade, 2>` at offset 16.
        pub cascades: [Cascade; 2],
        /// `counts`: `vec3<u32>` at offset 176.
        pub counts: [u32; 3],
        /// `bias`: `f32` at offset 188.
        pub bias: f32,
        /// `inner`: `Inner` at offset 192.
        pub inner: Inner,
    }
    const _: () = assert!(::core::mem::size_of::<Shadow>() == 224);
    const _: () = assert!(::core::mem::offset_of!(Shadow, uv) == 0);
    const _: () = assert!(::core::mem::offset_of!(Shadow, cascades) == 16);
    const _: () = assert!(::core::mem::offset_of!(Shadow, counts) == 176);
    const _: () = assert!(::core::mem::offset_of!(Shadow, bias) == 188);
    const _: () = assert!(::core::mem::offset_of!(Shadow, inner) == 192);
    /// The struct `Particle` (32 bytes), an element of `Particles::items`.
    #[repr(C)]
    #[derive(Clone, Copy, Debug, PartialEq, ::bytemuck::Pod, ::bytemuck::Zeroable)]
    pub struct Particle {
        /// `position`: `vec3<f32>` at offset 0.
        pub position: [f32; 3],
        /// `age`: `f32` at offset 12.
        pub age: f32,
        /// `velocity`: `vec3<f32>` at offset 16.
        pub velocity: [f32; 3],
        pub _pad0: [u8; 4],
    }
    const _: () = assert!(::core::mem::size_of::<Particle>() == 32);
    const _: () = assert!(::core::mem::offset_of!(Particle, position) == 0);
    const _: () = assert!(::core::mem::offset_of!(Particle, age) == 12);
    const _: () = assert!(::core::mem::offset_of!(Particle, velocity) == 16);
    /// The storage block `particles` (16 bytes, aligned to 16).
    #[repr(C)]
    #[derive(Clone, Copy, Debug, PartialEq, ::bytemuck::Pod, ::bytemuck::Zeroable)]
    pub struct Particles {
        /// `count`: `u32` at offset 0.
        pub count: u32,
        pub _pad0: [u8; 4],
        /// `scale`: `vec2<f32>` at offset 8.
        pub scale: [f32; 2],
        // `items`: array<Particle> from offset 16, stride 32, elements `Particle`: not a field (its length is the buffer's).
    }
    const _: () = assert!(::core::mem::size_of::<Particles>() == 16);
    const _: () = assert!(::core::mem::offset_of!(Particles, count) == 0);
    const _: () = assert!(::core::mem::offset_of!(Particles, scale) == 8);
}
pub mod blocks_1 {
    /// The struct `HalfPair` (16 bytes).
    #[repr(C)]
    #[derive(Clone, Copy, Debug, PartialEq, ::bytemuck::Pod, ::bytemuck::Zeroable)]
    pub struct HalfPair {
        /// `a`: `f16` at offset 0.
        pub a: u16,
        pub _pad0: [u8; 6],
        /// `b`: `vec3<f16>` at offset 8.
        pub b: [u16; 3],
        pub _pad1: [u8; 2],
    }
    const _: () = assert!(::core::mem::size_of::<HalfPair>() == 16);
    const _: () = assert!(::core::mem::offset_of!(HalfPair, a) == 0);
    const _: () = assert!(::core::mem::offset_of!(HalfPair, b) == 8);
    /// The uniform block `halves` (56 bytes, aligned to 8).
    #[repr(C)]
    #[derive(Clone, Copy, Debug, PartialEq, ::bytemuck::Pod, ::bytemuck::Zeroable)]
    pub struct Halves {
        /// `h`: `f16` at offset 0.
        pub h: u16,
        pub _pad0: [u8; 2],
        /// `v2`: `vec2<f16>` at offset 4.
        pub v2: [u16; 2],
        /// `v3`: `vec3<f16>` at offset 8.
        pub v3: [u16; 3],
        pub _pad1: [u8; 2],
        /// `v4`: `vec4<f16>` at offset 16.
        pub v4: [u16; 4],
        /// `tail`: `f32` at offset 24.
        pub tail: f32,
        pub _pad2: [u8; 4],
        /// `pair`: `HalfPair` at offset 32.
        pub pair: HalfPair,
        /// `last`: `f16` at offset 48.
        pub last: u16,
        pub _pad3: [u8; 6],
    }
    const _: () = assert!(::core::mem::size_of::<Halves>() == 56);
    const _: () = assert!(::core::mem::offset_of!(Halves, h) == 0);
    const _: () = assert!(::core::mem::offset_of!(Halves, v2) == 4);
    const _: () = assert!(::core::mem::offset_of!(Halves, v3) == 8);
    const _: () = assert!(::core::mem::offset_of!(Halves, v4) == 16);
    const _: () = assert!(::core::mem::offset_of!(Halves, tail) == 24);
    const _: () = assert!(::core::mem::offset_of!(Halves, pair) == 32);
    const _: () = assert!(::core::mem::offset_of!(Halves, last) == 48);
}
pub(super) static INTERFACES_0: [super::Interface; 2] = [
    super::Interface { entry_point: "Vertex", inputs: &[(0, "float32x3")], outputs: &[], workgroup_size: [0, 0, 0] },
    super::Interface { entry_point: "Fragment", inputs: &[], outputs: &[(0, "float32x4")], workgroup_size: [0, 0, 0] },
];
pub(super) static LAYOUT_0: [super::BindingEntry; 3] = [
    super::BindingEntry { group: 1, binding: 0, name: "blk", vertex: true, fragment: true, kind: super::BindingKind::Uniform { size: 336 } },
    super::BindingEntry { group: 1, binding: 1, name: "shadow", vertex: true, fragment: true, kind: super::BindingKind::Uniform { size: 224 } },
    super::BindingEntry { group: 1, binding: 2, name: "particles", vertex: true, fragment: false, kind: super::BindingKind::Storage { read_only: true } },
];
pub(super) static LAYOUT_1: [super::BindingEntry; 1] = [
    super::BindingEntry { group: 1, binding: 0, name: "halves", vertex: true, fragment: true, kind: super::BindingKind::Uniform { size: 56 } },
];
}
