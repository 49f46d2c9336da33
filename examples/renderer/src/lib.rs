//! A headless wgpu renderer for the seed's scene, using only what kiln generated in `build.rs`:
//! variant lookup by keywords, bind group layouts and `#[repr(C)]` uniform structs. Also a CPU
//! f64 reference of the same scene (analytic spheres, kiln's reference lighting) and an image
//! comparison.

pub mod keywords;
pub mod scene;

/// What kiln generated in `build.rs` for the scene's variants.
pub mod shaders {
    include!(concat!(env!("OUT_DIR"), "/kiln_shaders.rs"));
}

/// What kiln generated for `fixtures/blocks` (uniform and storage blocks of every shape), which
/// the GPU round-trip test of generated structs fills.
pub mod blocks {
    include!(concat!(env!("OUT_DIR"), "/blocks/kiln_shaders.rs"));
}

use kiln_reference as r;
use kiln_runtime::{Library, PipelineRequest, Runtime, Targets};
pub use scene::Scene;
use shaders::custom_rp_lit as lit;

/// An RGBA image, 8 bits per channel, rows top to bottom.
#[derive(Debug, Clone, PartialEq)]
pub struct Image {
    pub width: u32,
    pub height: u32,
    pub pixels: Vec<u8>,
}

impl Image {
    /// The image in a mapped read-back buffer whose rows are `row` bytes apart (a multiple of
    /// 256, as copies need), without the padding.
    pub fn read(buffer: &wgpu::Buffer, width: u32, height: u32, row: u32) -> Result<Image, String> {
        let mapped = buffer.get_mapped_range(..).map_err(|e| e.to_string())?;
        let mut pixels = Vec::with_capacity((width * height * 4) as usize);
        for y in 0..height {
            let start = (y * row) as usize;
            pixels.extend_from_slice(&mapped[start..start + (width * 4) as usize]);
        }
        Ok(Image { width, height, pixels })
    }

    /// Each pixel's colour, 0..1 per channel.
    pub fn colors(&self) -> Vec<[f64; 3]> {
        self.pixels.chunks_exact(4).map(|p| [0, 1, 2].map(|k| f64::from(p[k]) / 255.0)).collect()
    }

    pub fn write_png(&self, path: &std::path::Path) -> Result<(), Box<dyn std::error::Error>> {
        let file = std::io::BufWriter::new(std::fs::File::create(path)?);
        let mut encoder = png::Encoder::new(file, self.width, self.height);
        encoder.set_color(png::ColorType::Rgba);
        encoder.set_depth(png::BitDepth::Eight);
        encoder.write_header()?.write_image_data(&self.pixels)?;
        Ok(())
    }
}

use r::camera::{Basis, Mat4};

/// The camera's basis and projection, shared by the GPU and the reference.
struct View {
    eye: r::Vec3,
    forward: r::Vec3,
    right: r::Vec3,
    up: r::Vec3,
    tan_half_fov: f64,
    aspect: f64,
}

const NEAR: f64 = 0.1;
const FAR: f64 = 100.0;

impl View {
    fn new(scene: &Scene) -> View {
        let eye = scene.camera.position;
        let Basis { forward, right, up } = Basis::looking_at(eye, scene.camera.target);
        View {
            eye,
            forward,
            right,
            up,
            tan_half_fov: (scene.camera.fov_y_degrees.to_radians() / 2.0).tan(),
            aspect: f64::from(scene.width) / f64::from(scene.height),
        }
    }

    /// Right-handed view and a [0, 1]-depth perspective projection, as wgpu expects.
    fn view_projection(&self) -> Mat4 {
        let basis = Basis { forward: self.forward, right: self.right, up: self.up };
        r::camera::mat_mul(
            &r::camera::perspective(self.tan_half_fov, self.aspect, NEAR, FAR),
            &r::camera::view(self.eye, &basis),
        )
    }

    /// The ray through the centre of pixel (x, y).
    fn ray(&self, scene: &Scene, x: u32, y: u32) -> r::Vec3 {
        let ndc_x = (f64::from(x) + 0.5) / f64::from(scene.width) * 2.0 - 1.0;
        let ndc_y = 1.0 - (f64::from(y) + 0.5) / f64::from(scene.height) * 2.0;
        let d = r::add(
            self.forward,
            r::add(
                r::scale(self.right, ndc_x * self.tan_half_fov * self.aspect),
                r::scale(self.up, ndc_y * self.tan_half_fov),
            ),
        );
        r::normalize(d)
    }
}

fn to_f32<const N: usize>(v: [f64; N]) -> [f32; N] {
    v.map(|x| x as f32)
}

fn mat_f32(m: &Mat4) -> [[f32; 4]; 4] {
    m.map(to_f32)
}

/// Drawing order: opaque and clipped objects first, then blended ones back to front.
fn draw_order(scene: &Scene) -> Vec<usize> {
    let distance = |i: usize| {
        let d = r::sub(scene.objects[i].position, scene.camera.position);
        r::dot(d, d)
    };
    let (mut blended, opaque): (Vec<usize>, Vec<usize>) =
        (0..scene.objects.len()).partition(|&i| scene.objects[i].material.blends());
    blended.sort_by(|&a, &b| distance(b).total_cmp(&distance(a)));
    opaque.into_iter().chain(blended).collect()
}

/// A UV sphere of radius 1: interleaved position, normal, uv.
fn sphere_mesh(rings: u32, segments: u32) -> (Vec<f32>, Vec<u32>) {
    let (vertices, indices) = r::geometry::uv_sphere(rings, segments);
    let interleaved = vertices
        .iter()
        .flat_map(|v| to_f32(v.position).into_iter().chain(to_f32(v.normal)).chain(to_f32(v.uv)));
    (interleaved.collect(), indices)
}

/// A device on an adapter that runs WebGPU in full (with `shader-f16` and timestamp queries
/// where it has them), or why there is none.
pub fn device() -> Result<(wgpu::Device, wgpu::Queue, String), String> {
    let backends = wgpu::Backends::from_env().unwrap_or_default();
    let adapter = kiln_runtime::adapter(backends)
        .map_err(|e| format!("{e}; lavapipe runs it: apt-get install mesa-vulkan-drivers libvulkan1"))?;
    device_on(adapter, wgpu::Limits::default())
}

/// A device on wgpu's OpenGL back end (Mesa's llvmpipe through EGL in CI), with the adapter's
/// own limits: kiln's run time passes such an adapter by as below WebGPU, but the scene must
/// still draw the same there (docs/backends.md).
pub fn gl_device() -> Result<(wgpu::Device, wgpu::Queue, String), String> {
    let adapter = kiln_runtime::gl_adapter()
        .map_err(|e| format!("{e}; Mesa's OpenGL runs it: apt-get install libegl1 libgl1-mesa-dri"))?;
    let limits = adapter.limits();
    device_on(adapter, limits)
}

fn device_on(
    adapter: wgpu::Adapter,
    limits: wgpu::Limits,
) -> Result<(wgpu::Device, wgpu::Queue, String), String> {
    let name = adapter.get_info().name;
    let descriptor = wgpu::DeviceDescriptor {
        required_features: adapter.features()
            & (wgpu::Features::SHADER_F16
                | wgpu::Features::TIMESTAMP_QUERY
                | wgpu::Features::PIPELINE_CACHE
                | wgpu::Features::IMMEDIATES),
        // An ubershader's keywords (kiln_runtime::UBERSHADER_IMMEDIATE_SIZE), where the adapter has them.
        required_limits: wgpu::Limits {
            max_immediate_size: adapter
                .limits()
                .max_immediate_size
                .min(kiln_runtime::UBERSHADER_IMMEDIATE_SIZE),
            ..limits
        },
        ..wgpu::DeviceDescriptor::default()
    };
    let (device, queue) =
        pollster::block_on(adapter.request_device(&descriptor)).map_err(|e| format!("no device: {e}"))?;
    Ok((device, queue, name))
}

impl Scene {
    /// The bundled scene, `scene.toml`, as `build.rs` wrote it.
    pub fn bundled() -> Scene {
        // build.rs wrote it from a file it parsed, with this crate's own types.
        Scene::parse(include_str!(concat!(env!("OUT_DIR"), "/scene.json")))
            .expect("build.rs writes a scene that parses")
    }
}

/// The build the program embeds, as `kiln_runtime` reads it.
pub fn library() -> Result<Library, String> {
    Library::embedded(shaders::MANIFEST_JSON, shaders::MATERIALS_JSON, &shaders::PACKS)
        .map_err(|e| e.to_string())
}

/// A 1 x 1 white texture's view: what the scene's materials name (`"white"`, the default).
pub fn white_texture(device: &wgpu::Device, queue: &wgpu::Queue) -> wgpu::TextureView {
    use wgpu::util::DeviceExt;
    let white = device.create_texture_with_data(
        queue,
        &wgpu::TextureDescriptor {
            label: Some("white"),
            size: wgpu::Extent3d { width: 1, height: 1, depth_or_array_layers: 1 },
            mip_level_count: 1,
            sample_count: 1,
            dimension: wgpu::TextureDimension::D2,
            format: wgpu::TextureFormat::Rgba8Unorm,
            usage: wgpu::TextureUsages::TEXTURE_BINDING,
            view_formats: &[],
        },
        wgpu::util::TextureDataOrder::LayerMajor,
        &[255, 255, 255, 255],
    );
    white.create_view(&Default::default())
}

/// The scene's textures for materials: every texture property is white (the scene's materials
/// use the default `"white"`), sampled by one sampler.
struct SceneTextures<'a> {
    white: &'a wgpu::TextureView,
    sampler: &'a wgpu::Sampler,
}

impl kiln_runtime::MaterialTextures for SceneTextures<'_> {
    fn texture(&self, _property: &str, texture: &str) -> Option<&wgpu::TextureView> {
        (texture == "white").then_some(self.white)
    }

    fn sampler(&self, _property: &str) -> Option<&wgpu::Sampler> {
        Some(self.sampler)
    }
}

/// The attachments the scene renders to.
pub fn targets() -> Targets {
    Targets {
        colors: vec![wgpu::TextureFormat::Rgba8Unorm],
        depth: Some(wgpu::TextureFormat::Depth32Float),
        samples: 1,
    }
}

/// Renders the scene with the compiled Lit variants and the embedded build's runtime.
pub fn render(device: &wgpu::Device, queue: &wgpu::Queue, scene: &Scene) -> Result<Image, String> {
    let mut runtime = Runtime::new(device, library()?);
    render_with(&mut runtime, device, queue, scene)
}

/// Renders the scene through a runtime: every layout, vertex buffer layout, render state and
/// pipeline comes from it; the materials are the build's (`objectNN`, from `scene.toml`).
pub fn render_with(
    runtime: &mut Runtime,
    device: &wgpu::Device,
    queue: &wgpu::Queue,
    scene: &Scene,
) -> Result<Image, String> {
    Ok(render_frames(runtime, device, queue, scene, 1)?.0)
}

/// The scene as a game meets it: frame k draws its first k objects, so each material's pipeline
/// is first asked for on the frame its object appears. Returns, per frame, the pipelines created
/// during it (on this thread, the render thread) and the frame's wall time, and the last image.
pub fn introduce(
    runtime: &mut Runtime,
    device: &wgpu::Device,
    queue: &wgpu::Queue,
    scene: &Scene,
) -> Result<(Vec<(usize, std::time::Duration)>, Image), String> {
    let mut frames = Vec::new();
    let mut image = None;
    for count in 1..=scene.objects.len() {
        let partial = Scene { objects: scene.objects[..count].to_vec(), ..scene.clone() };
        let (before, started) = (runtime.pipelines_created(), std::time::Instant::now());
        image = Some(render_with(runtime, device, queue, &partial)?);
        frames.push((runtime.pipelines_created() - before, started.elapsed()));
    }
    Ok((frames, image.ok_or("the scene has no objects")?))
}

/// Renders the scene `frames` times in one submission (each frame clears and draws every
/// object) and returns the last image with the GPU time per frame in nanoseconds, measured with
/// timestamp queries where the device has them (`device()` asks for them).
pub fn render_frames(
    runtime: &mut Runtime,
    device: &wgpu::Device,
    queue: &wgpu::Queue,
    scene: &Scene,
    frames: u32,
) -> Result<(Image, Option<f64>), String> {
    use wgpu::util::DeviceExt;
    let view = View::new(scene);
    let uniform = |contents: &[u8]| {
        device.create_buffer_init(&wgpu::util::BufferInitDescriptor {
            label: None,
            contents,
            usage: wgpu::BufferUsages::UNIFORM,
        })
    };
    let white_view = white_texture(device, queue);
    let sampler = device.create_sampler(&wgpu::SamplerDescriptor::default());
    let textures = SceneTextures { white: &white_view, sampler: &sampler };

    // Everything a binding of the pass may name, by name.
    let per_frame = lit::PerFrame {
        unity_MatrixVP: mat_f32(&view.view_projection()),
        _WorldSpaceCameraPos: to_f32(view.eye),
        ..bytemuck::Zeroable::zeroed()
    };
    let mut light = lit::CustomLight {
        _DirectionalLightCount: scene.lights.len() as i32,
        ..bytemuck::Zeroable::zeroed()
    };
    for (i, l) in scene.lights.iter().take(4).enumerate() {
        let d = r::normalize(l.direction);
        light._DirectionalLightColors[i] = to_f32([l.color[0], l.color[1], l.color[2], 0.0]);
        light._DirectionalLightDirections[i] = to_f32([d[0], d[1], d[2], 0.0]);
    }
    let frame_buffers = [uniform(bytemuck::bytes_of(&per_frame)), uniform(bytemuck::bytes_of(&light))];
    // Per frame and per object: the renderer's buffers, bound by their names in the layout.
    let frame_buffers = [("UnityPerFrame", &frame_buffers[0]), ("_CustomLight", &frame_buffers[1])];
    let lit_pass = runtime.pass(scene::SHADER, 0).map_err(|e| e.to_string())?;
    let frame_group = runtime
        .buffer_bind_group(lit_pass, shaders::FRAME_GROUP, &frame_buffers)
        .map_err(|e| e.to_string())?;

    // The runtime's default vertex packing of the pass's inputs (position, normal, uv) is the
    // mesh's interleaving.
    let (vertices, indices) = sphere_mesh(SPHERE_RINGS, SPHERE_SEGMENTS);
    let vertex_buffer = device.create_buffer_init(&wgpu::util::BufferInitDescriptor {
        label: None,
        contents: bytemuck::cast_slice(&vertices),
        usage: wgpu::BufferUsages::VERTEX,
    });
    let index_buffer = device.create_buffer_init(&wgpu::util::BufferInitDescriptor {
        label: None,
        contents: bytemuck::cast_slice(&indices),
        usage: wgpu::BufferUsages::INDEX,
    });

    let size = wgpu::Extent3d { width: scene.width, height: scene.height, depth_or_array_layers: 1 };
    let targets = targets();
    let target = device.create_texture(&wgpu::TextureDescriptor {
        label: Some("colour"),
        size,
        mip_level_count: 1,
        sample_count: 1,
        dimension: wgpu::TextureDimension::D2,
        format: targets.colors[0],
        usage: wgpu::TextureUsages::RENDER_ATTACHMENT | wgpu::TextureUsages::COPY_SRC,
        view_formats: &[],
    });
    let depth = device.create_texture(&wgpu::TextureDescriptor {
        label: Some("depth"),
        size,
        mip_level_count: 1,
        sample_count: 1,
        dimension: wgpu::TextureDimension::D2,
        format: wgpu::TextureFormat::Depth32Float,
        usage: wgpu::TextureUsages::RENDER_ATTACHMENT,
        view_formats: &[],
    });
    let (target_view, depth_view) =
        (target.create_view(&Default::default()), depth.create_view(&Default::default()));

    // Per object: its pipeline (variant + the material's render state) and bind groups.
    let mut draws = Vec::new();
    for index in draw_order(scene) {
        let object = &scene.objects[index];
        let material =
            runtime.library().material(&format!("object{index:02}")).map_err(|e| e.to_string())?.clone();
        let keywords: Vec<&str> =
            material.keywords.iter().map(String::as_str).chain(scene.global_keywords()).collect();
        let variant = runtime.variant(scene::SHADER, 0, &keywords).map_err(|e| e.to_string())?;
        let request = PipelineRequest {
            variant,
            material: &material,
            targets: &targets,
            vertex_layout: None,
            overrides: &[],
        };
        let pipeline = runtime.pipeline(&request).map_err(|e| e.to_string())?;
        // The material's group: its uniform block from its values at the manifest's offsets
        // (`tests/render.rs` checks the bytes against the generated struct), its texture and
        // sampler from `textures`.
        let material_group =
            runtime.material_bind_group(&material, lit_pass, &textures).map_err(|e| e.to_string())?;
        let (object_to_world, world_to_object) =
            r::camera::object_to_world(object.position, [object.radius; 3]);
        let draw = lit::PerDraw {
            unity_ObjectToWorld: mat_f32(&object_to_world),
            unity_WorldToObject: mat_f32(&world_to_object),
        };
        let draw_buffer = uniform(bytemuck::bytes_of(&draw));
        let draw_group = runtime
            .buffer_bind_group(lit_pass, shaders::OBJECT_GROUP, &[("UnityPerDraw", &draw_buffer)])
            .map_err(|e| e.to_string())?;
        let groups = [material_group.bind_group, draw_group];
        draws.push((pipeline, groups));
    }

    let timed = device.features().contains(wgpu::Features::TIMESTAMP_QUERY);
    let queries = timed.then(|| {
        let set = device.create_query_set(&wgpu::QuerySetDescriptor {
            label: None,
            ty: wgpu::QueryType::Timestamp,
            count: 2,
        });
        let buffer = |usage| {
            device.create_buffer(&wgpu::BufferDescriptor {
                label: None,
                size: 16,
                usage,
                mapped_at_creation: false,
            })
        };
        let resolved = buffer(wgpu::BufferUsages::QUERY_RESOLVE | wgpu::BufferUsages::COPY_SRC);
        let read = buffer(wgpu::BufferUsages::COPY_DST | wgpu::BufferUsages::MAP_READ);
        (set, resolved, read)
    });
    let mut encoder = device.create_command_encoder(&Default::default());
    for frame in 0..frames.max(1) {
        let bg = scene.background;
        // The first frame's start and the last one's end.
        let (first, last) = (frame == 0, frame + 1 == frames.max(1));
        let timestamp_writes =
            queries.as_ref().filter(|_| first || last).map(|(set, _, _)| wgpu::RenderPassTimestampWrites {
                query_set: set,
                beginning_of_pass_write_index: first.then_some(0),
                end_of_pass_write_index: last.then_some(1),
            });
        let clear = wgpu::Color { r: bg[0], g: bg[1], b: bg[2], a: 1.0 };
        let mut render_pass = begin_cleared(&mut encoder, &target_view, &depth_view, clear, timestamp_writes);
        render_pass.set_bind_group(shaders::FRAME_GROUP, &frame_group, &[]);
        render_pass.set_vertex_buffer(0, vertex_buffer.slice(..));
        render_pass.set_index_buffer(index_buffer.slice(..), wgpu::IndexFormat::Uint32);
        for (pipeline, groups) in &draws {
            render_pass.set_pipeline(pipeline);
            render_pass.set_bind_group(shaders::MATERIAL_GROUP, &groups[0], &[]);
            render_pass.set_bind_group(shaders::OBJECT_GROUP, &groups[1], &[]);
            render_pass.draw_indexed(0..indices.len() as u32, 0, 0..1);
        }
    }
    let row = (scene.width * 4).div_ceil(256) * 256;
    let readback = device.create_buffer(&wgpu::BufferDescriptor {
        label: None,
        size: u64::from(row * scene.height),
        usage: wgpu::BufferUsages::COPY_DST | wgpu::BufferUsages::MAP_READ,
        mapped_at_creation: false,
    });
    encoder.copy_texture_to_buffer(
        target.as_image_copy(),
        wgpu::TexelCopyBufferInfo {
            buffer: &readback,
            layout: wgpu::TexelCopyBufferLayout { offset: 0, bytes_per_row: Some(row), rows_per_image: None },
        },
        size,
    );
    if let Some((set, resolved, read)) = &queries {
        encoder.resolve_query_set(set, 0..2, resolved, 0);
        encoder.copy_buffer_to_buffer(resolved, 0, read, 0, 16);
    }
    queue.submit([encoder.finish()]);
    readback.map_async(wgpu::MapMode::Read, .., |_| {});
    if let Some((_, _, read)) = &queries {
        read.map_async(wgpu::MapMode::Read, .., |_| {});
    }
    device.poll(wgpu::PollType::wait_indefinitely()).map_err(|e| e.to_string())?;
    let gpu_time = match &queries {
        Some((_, _, read)) => {
            let stamps = read.get_mapped_range(..).map_err(|e| e.to_string())?;
            let stamp = |at: usize| u64::from_le_bytes(stamps[at..at + 8].try_into().unwrap_or_default());
            let ticks = stamp(8).saturating_sub(stamp(0)) as f64;
            Some(ticks * f64::from(queue.get_timestamp_period()) / f64::from(frames.max(1)))
        }
        None => None,
    };
    let image = Image::read(&readback, scene.width, scene.height, row)?;
    Ok((image, gpu_time))
}

/// A render pass into a colour and a depth target, cleared to `clear` and depth 1, stored.
pub fn begin_cleared<'e>(
    encoder: &'e mut wgpu::CommandEncoder,
    color: &wgpu::TextureView,
    depth: &wgpu::TextureView,
    clear: wgpu::Color,
    timestamp_writes: Option<wgpu::RenderPassTimestampWrites<'_>>,
) -> wgpu::RenderPass<'e> {
    encoder.begin_render_pass(&wgpu::RenderPassDescriptor {
        label: None,
        color_attachments: &[Some(wgpu::RenderPassColorAttachment {
            view: color,
            depth_slice: None,
            resolve_target: None,
            ops: wgpu::Operations { load: wgpu::LoadOp::Clear(clear), store: wgpu::StoreOp::Store },
        })],
        depth_stencil_attachment: Some(wgpu::RenderPassDepthStencilAttachment {
            view: depth,
            depth_ops: Some(wgpu::Operations { load: wgpu::LoadOp::Clear(1.0), store: wgpu::StoreOp::Store }),
            stencil_ops: None,
        }),
        timestamp_writes,
        ..Default::default()
    })
}

/// The spheres' tessellation: rings from pole to pole, segments around.
pub const SPHERE_RINGS: u32 = 96;
/// See [`SPHERE_RINGS`].
pub const SPHERE_SEGMENTS: u32 = 192;

/// What the reference intersects its rays with.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Geometry {
    /// Exact spheres, with the exact normal at the hit point.
    Analytic,
    /// The triangles the GPU draws ([`SPHERE_RINGS`] x [`SPHERE_SEGMENTS`], vertices rounded to
    /// f32 as in the vertex buffer), with the vertex normals interpolated at the hit point and
    /// normalised, as rasterisation and the fragment shader do; the lighting is still f64.
    Tessellated,
}

/// What the reference blends into.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Target {
    /// Exact colours between draws.
    Exact,
    /// The render target's 8 bits per channel: a blended draw reads the colour below it rounded
    /// as `Rgba8Unorm` stores it. The last draw's value is left exact, so a comparison with an
    /// image measures how far the GPU's 8-bit value is from what rounding alone would give.
    EightBit,
}

/// The scene drawn on the CPU in f64: analytic spheres, kiln's reference lighting, the same
/// blending and order. Also returns, per pixel, whether it sits on an object's silhouette, where
/// a tessellated sphere and an analytic one legitimately differ.
pub fn reference(scene: &Scene) -> (Vec<[f64; 3]>, Vec<bool>) {
    let drawn = reference_with(scene, Geometry::Analytic, Target::Exact);
    (drawn.colors, drawn.edge)
}

/// The reference image and what each pixel sees.
#[derive(Debug, Clone, PartialEq)]
pub struct Reference {
    /// Each pixel's colour (unclamped, as the lighting computes it before the target).
    pub colors: Vec<[f64; 3]>,
    /// Whether a pixel sits on a silhouette (analytic geometry).
    pub edge: Vec<bool>,
    /// Whether a pixel's colour was blended over another (a faded or transparent object).
    pub blended: Vec<bool>,
}

impl Reference {
    /// A mask for [`difference`] that leaves out the silhouettes and every pixel whose blending
    /// is not `blended`: the opaque pixels alone, or the blended ones alone.
    pub fn left_out_unless(&self, blended: bool) -> Vec<bool> {
        self.edge.iter().zip(&self.blended).map(|(edge, b)| *edge || *b != blended).collect()
    }
}

/// Where a ray meets a unit sphere's tessellation near the exact hit `q` (object space), as the
/// distance along the ray (object space) and the interpolated, normalised normal.
fn mesh_hit(origin: r::Vec3, ray: r::Vec3, q: r::Vec3) -> Option<(f64, r::Vec3)> {
    let (rings, segments) = (SPHERE_RINGS as i64, SPHERE_SEGMENTS as i64);
    // The vertex buffer's f32 values; position and normal are the same vector.
    let vertex = |ring: i64, segment: i64| -> r::Vec3 {
        r::geometry::sphere_point(ring as f64 / rings as f64, segment as f64 / segments as f64)
            .map(|v| f64::from(v as f32))
    };
    let theta = q[1].clamp(-1.0, 1.0).acos();
    let phi = (-q[2]).atan2(q[0]).rem_euclid(std::f64::consts::TAU);
    let ring = (theta / std::f64::consts::PI * rings as f64).floor() as i64;
    let segment = (phi / std::f64::consts::TAU * segments as f64).floor() as i64;
    let mut best: Option<(f64, r::Vec3)> = None;
    for a in (ring - 1).max(0)..=(ring + 1).min(rings - 1) {
        for b in segment - 1..=segment + 1 {
            let b = b.rem_euclid(segments);
            let corners = [vertex(a, b), vertex(a + 1, b), vertex(a, b + 1), vertex(a + 1, b + 1)];
            for [i, j, k] in [[0, 1, 2], [2, 1, 3]] {
                let (p0, p1, p2) = (corners[i], corners[j], corners[k]);
                // Moeller-Trumbore: the hit's distance and barycentric coordinates.
                let (e1, e2) = (r::sub(p1, p0), r::sub(p2, p0));
                let h = r::cross(ray, e2);
                let det = r::dot(e1, h);
                if det.abs() < 1e-300 {
                    continue;
                }
                let s = r::sub(origin, p0);
                let u = r::dot(s, h) / det;
                let qv = r::cross(s, e1);
                let v = r::dot(ray, qv) / det;
                let t = r::dot(e2, qv) / det;
                let inside = (0.0..=1.0).contains(&u) && v >= 0.0 && u + v <= 1.0;
                if inside && t > 0.0 && best.is_none_or(|(nearest, _)| t < nearest) {
                    let w = 1.0 - u - v;
                    let normal = [0, 1, 2].map(|c| p0[c] * w + p1[c] * u + p2[c] * v);
                    best = Some((t, r::normalize(normal)));
                }
            }
        }
    }
    best
}

/// [`reference()`] with the geometry and the target chosen: the analytic spheres or the triangles
/// the GPU draws, exact colours or 8-bit ones between draws. Each choice emulates one thing the
/// GPU does besides the shader's arithmetic, so that its share of the difference can be measured.
/// The silhouette mask is always the analytic one, so every choice compares the same pixels.
pub fn reference_with(scene: &Scene, geometry: Geometry, target: Target) -> Reference {
    let stored = |color: r::Vec3| match target {
        Target::Exact => color,
        Target::EightBit => color.map(|c| (c.clamp(0.0, 1.0) * 255.0).round() / 255.0),
    };
    let view = View::new(scene);
    let lights: Vec<r::Light> = scene
        .lights
        .iter()
        .map(|l| r::Light { color: l.color, direction: r::normalize(l.direction) })
        .collect();
    let order = draw_order(scene);
    let (w, h) = (scene.width, scene.height);
    let mut colors = vec![[0.0; 3]; (w * h) as usize];
    // What each pixel sees: the opaque object and the set of blended ones in front of it.
    let mut ids = vec![(usize::MAX, 0u64); (w * h) as usize];
    for y in 0..h {
        for x in 0..w {
            let ray = view.ray(scene, x, y);
            // Distance along the ray and the shading normal.
            let hit = |i: usize| -> Option<(f64, r::Vec3)> {
                let o = &scene.objects[i];
                let oc = r::sub(view.eye, o.position);
                let b = r::dot(oc, ray);
                let c = r::dot(oc, oc) - o.radius * o.radius;
                let disc = b * b - c;
                let t = (disc >= 0.0).then(|| -b - disc.sqrt()).filter(|t| *t > 0.0)?;
                let point = r::add(view.eye, r::scale(ray, t));
                let exact = r::normalize(r::sub(point, o.position));
                match geometry {
                    Geometry::Analytic => Some((t, exact)),
                    // Object space is world space scaled by 1/radius: distances scale back.
                    Geometry::Tessellated => mesh_hit(r::scale(oc, 1.0 / o.radius), ray, exact)
                        .map(|(t, normal)| (t * o.radius, normal)),
                }
            };
            let visible = |i: usize| {
                let m = &scene.objects[i].material;
                !m.clips() || m.color[3] >= m.cutoff
            };
            let mut color = scene.background;
            let mut depth = f64::INFINITY;
            let mut id = (usize::MAX, 0u64);
            for &i in &order {
                let Some((t, normal)) = hit(i) else { continue };
                let m = &scene.objects[i].material;
                if t > depth || !visible(i) {
                    continue;
                }
                let point = r::add(view.eye, r::scale(ray, t));
                let surface = r::Surface {
                    normal,
                    view_direction: r::normalize(r::sub(view.eye, point)),
                    color: [m.color[0], m.color[1], m.color[2]],
                    alpha: m.color[3],
                    metallic: m.metallic,
                    smoothness: m.smoothness,
                };
                let brdf = r::get_brdf(&surface, m.premultiplies());
                let lit = r::lighting(&surface, &brdf, &lights).map(|c| c.clamp(0.0, 1.0));
                let a = surface.alpha.clamp(0.0, 1.0);
                let below = stored(color);
                color = if m.premultiplies() {
                    [0, 1, 2].map(|k| lit[k] + below[k] * (1.0 - a))
                } else if m.blends() {
                    [0, 1, 2].map(|k| lit[k] * a + below[k] * (1.0 - a))
                } else {
                    depth = t;
                    lit
                };
                if m.blends() {
                    id.1 |= 1 << (i % 64);
                } else {
                    id.0 = i;
                }
            }
            colors[(y * w + x) as usize] = color;
            ids[(y * w + x) as usize] = id;
        }
    }
    // A pixel whose neighbours see another object (or the background) is on a silhouette.
    let edge = (0..h)
        .flat_map(|y| (0..w).map(move |x| (x, y)))
        .map(|(x, y)| {
            let id = ids[(y * w + x) as usize];
            [(-1i64, 0i64), (1, 0), (0, -1), (0, 1)].iter().any(|(dx, dy)| {
                let (nx, ny) = (i64::from(x) + dx, i64::from(y) + dy);
                nx >= 0
                    && ny >= 0
                    && nx < i64::from(w)
                    && ny < i64::from(h)
                    && ids[(ny as u32 * w + nx as u32) as usize] != id
            })
        })
        .collect();
    let blended = ids.iter().map(|id| id.1 != 0).collect();
    Reference { colors, edge, blended }
}

/// How far two images are apart, per channel (0..1), over the pixels off the silhouettes.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Difference {
    /// Largest absolute difference.
    pub max: f64,
    /// Mean absolute difference.
    pub mean: f64,
    /// Pixels compared.
    pub pixels: usize,
    /// The pixel (index, row-major) where the largest difference is.
    pub worst: usize,
}

/// [`Difference`] between two images given as colours (the reference's are clamped to 0..1, as
/// a render target clamps).
pub fn difference(got: &[[f64; 3]], want: &[[f64; 3]], edge: &[bool]) -> Difference {
    let mut found = Difference { max: 0.0, mean: 0.0, pixels: 0, worst: 0 };
    let mut sum = 0.0;
    for (i, (got, want)) in got.iter().zip(want).enumerate() {
        if edge[i] {
            continue;
        }
        for (g, w) in got.iter().zip(want) {
            let error = (g.clamp(0.0, 1.0) - w.clamp(0.0, 1.0)).abs();
            if error > found.max {
                found.max = error;
                found.worst = i;
            }
            sum += error;
        }
        found.pixels += 1;
    }
    found.mean = sum / (3 * found.pixels.max(1)) as f64;
    found
}

/// Largest and mean absolute per-channel difference (0..1) between the rendered image and the
/// reference, over the pixels not on a silhouette, and how many pixels were compared.
pub fn compare(image: &Image, reference: &[[f64; 3]], edge: &[bool]) -> (f64, f64, usize) {
    let found = difference(&image.colors(), reference, edge);
    (found.max, found.mean, found.pixels)
}

/// The reference as an image, for looking at side by side.
pub fn reference_image(scene: &Scene, colors: &[[f64; 3]]) -> Image {
    let pixels = colors
        .iter()
        .flat_map(|c| {
            let [r, g, b] = c.map(|v| (v.clamp(0.0, 1.0) * 255.0).round() as u8);
            [r, g, b, 255]
        })
        .collect();
    Image { width: scene.width, height: scene.height, pixels }
}
