//! `kiln preview`: a material drawn through the run time, as Unity's inspector shows one: its
//! variant on a sphere standing on a plane of the same material, under four fixed directional
//! lights, on whatever adapter there is (lavapipe in CI).
//!
//! Everything a pass binds besides the material is filled by name, so that any shader draws
//! without code of its own: the frame's and object's matrices under the names the bundled
//! libraries and Unity's give them ([`scene_value`]), white textures, default samplers. What the
//! preview cannot give a pass (a depth or multisampled texture, a storage texture, an integer
//! vertex input) is an error naming it, never a guess; members it leaves at zero are named in
//! [`Preview::notes`]. docs/preview.md lists the names.
//!
//! One job, drawing a material, kept in one file: the names filled, the textures, the vertex
//! bytes and the read-back are each a function below, and none is used elsewhere.

use crate::manifest::{
    AttributeFormat, Member, PassManifest, Resource, SampleType, ShaderManifest, VariantManifest,
    ViewDimension,
};
use crate::reference::camera::{Basis, Mat4, mat_mul, object_to_world, perspective, view};
use crate::reference::{self as r, geometry};
use crate::runtime::{
    Library, MATERIAL_GROUP, MaterialTextures, PassId, PipelineRequest, Runtime, RuntimeError, Targets,
};
use std::collections::BTreeMap;
use wgpu::util::DeviceExt;

/// What went wrong drawing a preview.
#[derive(Debug, thiserror::Error)]
pub enum PreviewError {
    /// The build has no material of that name.
    #[error("no material `{name}` in the build{}", suggestion.as_ref().map(|s| format!(" (did you mean `{s}`?)")).unwrap_or_default())]
    NoMaterial {
        /// The name asked for.
        name: String,
        /// The closest name the build has.
        suggestion: Option<String>,
    },
    /// No pass of the material's shader draws it (a shadow-caster-only shader, say).
    #[error("no pass of `{shader}` draws `{material}`: {why}")]
    NoPass {
        /// The material.
        material: String,
        /// Its shader.
        shader: String,
        /// What the passes are.
        why: String,
    },
    /// There is no adapter or device.
    #[error("{0}")]
    Device(String),
    /// The run time refused something (a layout, a pipeline).
    #[error(transparent)]
    Runtime(#[from] RuntimeError),
    /// The pass needs something the preview does not provide.
    #[error("the preview cannot draw pass {pass} of `{shader}`: {what}")]
    Unsupported {
        /// The shader.
        shader: String,
        /// The pass's index.
        pass: usize,
        /// What it needs.
        what: String,
    },
}

/// A drawn preview.
#[derive(Debug, Clone, PartialEq)]
pub struct Preview {
    /// The image, 8-bit RGBA, rows top to bottom.
    pub picture: Picture,
    /// The shader drawn.
    pub shader: String,
    /// The pass drawn (its index in the shader).
    pub pass: usize,
    /// The variant's keywords.
    pub keywords: Vec<String>,
    /// The adapter it was drawn on.
    pub adapter: String,
    /// What the preview could not fill and left at zero, for the user to know.
    pub notes: Vec<String>,
}

/// An 8-bit RGBA image, rows top to bottom.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Picture {
    /// Width in pixels.
    pub width: u32,
    /// Height in pixels.
    pub height: u32,
    /// `width * height * 4` bytes.
    pub rgba: Vec<u8>,
}

impl Picture {
    /// The picture as a PNG file's bytes.
    pub fn png(&self) -> Result<Vec<u8>, png::EncodingError> {
        let mut bytes = Vec::new();
        let mut encoder = png::Encoder::new(&mut bytes, self.width, self.height);
        encoder.set_color(png::ColorType::Rgba);
        encoder.set_depth(png::BitDepth::Eight);
        encoder.write_header()?.write_image_data(&self.rgba)?;
        Ok(bytes)
    }

    /// A PNG file's picture (8-bit RGB or RGBA), for comparing with one drawn.
    pub fn from_png(bytes: &[u8]) -> Result<Picture, String> {
        let decoder = png::Decoder::new(std::io::Cursor::new(bytes));
        let mut reader = decoder.read_info().map_err(|e| e.to_string())?;
        let mut buffer = vec![0; reader.output_buffer_size().unwrap_or_default()];
        let info = reader.next_frame(&mut buffer).map_err(|e| e.to_string())?;
        let data = &buffer[..info.buffer_size()];
        let rgba = match (info.color_type, info.bit_depth) {
            (png::ColorType::Rgba, png::BitDepth::Eight) => data.to_vec(),
            (png::ColorType::Rgb, png::BitDepth::Eight) => {
                data.chunks_exact(3).flat_map(|p| [p[0], p[1], p[2], 255]).collect()
            }
            (color, depth) => {
                return Err(format!("a {color:?} PNG of {depth:?} bits is neither 8-bit RGB nor RGBA"));
            }
        };
        Ok(Picture { width: info.width, height: info.height, rgba })
    }
}

/// How big the preview is: a square of this many pixels a side unless given.
pub const DEFAULT_SIZE: u32 = 256;

/// The largest side drawn: 4096 pixels is 64 MiB of RGBA, and every adapter's 2D limit.
pub const MAX_SIZE: u32 = 4096;

/// The preview's lights: direction towards the light and colour, as the example scene's four.
pub const LIGHTS: [([f64; 3], [f64; 3]); 4] = [
    ([0.4, 1.0, 0.7], [1.6, 1.5, 1.35]),
    ([-0.8, 0.3, 0.4], [0.25, 0.3, 0.5]),
    ([0.0, -1.0, 0.2], [0.08, 0.06, 0.05]),
    ([-0.2, 0.4, -1.0], [0.4, 0.4, 0.4]),
];

/// The camera: where it stands, what it looks at, the tangent of half its vertical field of view.
pub const CAMERA: ([f64; 3], [f64; 3], f64) = ([0.0, 1.5, 4.6], [0.0, -0.3, 0.0], 0.4);

/// What the background is cleared to (linear RGB, as the target stores it).
pub const BACKGROUND: [f64; 3] = [0.16, 0.17, 0.19];

/// The sphere: unit radius at the origin. The plane below it: side 5, its top at y = -1.
const PLANE_HEIGHT: f64 = -1.0;
const PLANE_HALF_SIDE: f64 = 2.5;
const NEAR: f64 = 0.1;
const FAR: f64 = 100.0;
const SPHERE_RINGS: u32 = 64;
const SPHERE_SEGMENTS: u32 = 128;

/// The LightModes of passes that draw no colour: a preview draws the first pass that is none.
const NOT_DRAWN: [&str; 7] =
    ["ShadowCaster", "DepthOnly", "DepthNormals", "Meta", "ShadowCollector", "MotionVectors", "Deferred"];

/// Draws `material` of `library` on a `size` x `size` picture, on the first adapter that runs
/// WebGPU (`WGPU_BACKEND` narrows the search).
pub fn draw(library: Library, material: &str, size: u32) -> Result<Preview, PreviewError> {
    let Some(found) = library.materials().iter().find(|m| m.name == material).cloned() else {
        let names = library.materials().iter().map(|m| m.name.as_str());
        let suggestion = crate::manifest::closest(material, names);
        return Err(PreviewError::NoMaterial { name: material.to_string(), suggestion });
    };
    let size = size.clamp(1, MAX_SIZE);
    let shader = library.shader(&found.shader)?.clone();
    let (pass, variant) = drawn_pass(&shader, &found.name)?;
    let (needed, keywords) = (needed_features(&shader.passes[pass], variant), variant.keywords.clone());
    let backends = wgpu::Backends::from_env().unwrap_or_default();
    let adapter = crate::runtime::adapter(backends).map_err(|e| PreviewError::Device(e.to_string()))?;
    let adapter_name = adapter.get_info().name;
    let descriptor = wgpu::DeviceDescriptor {
        required_features: adapter.features() & needed,
        ..wgpu::DeviceDescriptor::default()
    };
    let (device, queue) = pollster::block_on(adapter.request_device(&descriptor))
        .map_err(|e| PreviewError::Device(format!("no device on {adapter_name}: {e}")))?;
    let mut runtime = Runtime::new(&device, library);
    let (picture, notes) = render(&mut runtime, &device, &queue, &found, pass, &keywords, size)?;
    Ok(Preview { picture, shader: shader.name, pass, keywords, adapter: adapter_name, notes })
}

/// The first pass of the shader with a vertex stage, not a shadow or depth pass, whose variants
/// include the material's; and that variant.
fn drawn_pass<'s>(
    shader: &'s ShaderManifest,
    material: &str,
) -> Result<(usize, &'s VariantManifest), PreviewError> {
    let mut why = Vec::new();
    for (index, pass) in shader.passes.iter().enumerate() {
        let light_mode = pass.tags.iter().find(|(k, _)| k == "LightMode").map(|(_, v)| v.as_str());
        if let Some(mode) = light_mode.filter(|mode| NOT_DRAWN.contains(mode)) {
            why.push(format!("pass {index} is `{mode}`"));
            continue;
        }
        if !pass.kernels.is_empty() {
            why.push(format!("pass {index} is a compute pass"));
            continue;
        }
        match pass.variants.iter().find(|v| v.materials.iter().any(|m| m == material)) {
            Some(variant) if variant.vertex.is_some() => return Ok((index, variant)),
            Some(_) => why.push(format!("pass {index}'s variant for it failed to build")),
            None => why.push(format!("pass {index} built no variant for it")),
        }
    }
    if why.is_empty() {
        why.push("the shader has no passes".to_string());
    }
    Err(PreviewError::NoPass {
        material: material.to_string(),
        shader: shader.name.clone(),
        why: why.join(", "),
    })
}

/// The GPU features the variant's modules were validated with.
fn needed_features(pass: &PassManifest, variant: &VariantManifest) -> wgpu::Features {
    pass.variant_stages(variant)
        .into_iter()
        .flatten()
        .flat_map(|stage| stage.module.features.iter().copied())
        .fold(wgpu::Features::empty(), |all, feature| all | crate::runtime::wgpu_feature(feature))
}

/// One object of the preview: its mesh and where it stands.
struct Object {
    vertices: Vec<geometry::Vertex>,
    indices: Vec<u32>,
    to_world: (Mat4, Mat4),
}

/// The camera's matrices, made once for every member that names one.
struct Frame {
    eye: [f64; 3],
    view: Mat4,
    projection: Mat4,
    view_projection: Mat4,
    camera_to_world: Mat4,
}

impl Frame {
    fn new() -> Frame {
        let (eye, target, tan_half_fov) = CAMERA;
        let basis = Basis::looking_at(eye, target);
        let view = view(eye, &basis);
        // The picture is square.
        let projection = perspective(tan_half_fov, 1.0, NEAR, FAR);
        let (right, up, back) = (basis.right, basis.up, r::scale(basis.forward, -1.0));
        Frame {
            eye,
            view,
            projection,
            view_projection: mat_mul(&projection, &view),
            camera_to_world: [
                [right[0], right[1], right[2], 0.0],
                [up[0], up[1], up[2], 0.0],
                [back[0], back[1], back[2], 0.0],
                [eye[0], eye[1], eye[2], 1.0],
            ],
        }
    }
}

/// The values the preview gives uniform members by name, for one object: matrices column-major,
/// vectors as four components, arrays as their elements.
fn scene_value(name: &str, frame: &Frame, object: &Object, size: u32) -> Option<Vec<Vec<f64>>> {
    let flat = |m: &Mat4| vec![m.iter().flatten().copied().collect::<Vec<f64>>()];
    let four = |v: [f64; 3], w: f64| vec![vec![v[0], v[1], v[2], w]];
    let key = r::normalize(LIGHTS[0].0);
    let side = f64::from(size);
    Some(match name {
        "unity_MatrixVP" => flat(&frame.view_projection),
        "unity_MatrixV" => flat(&frame.view),
        "unity_MatrixInvV" | "unity_CameraToWorld" => flat(&frame.camera_to_world),
        "glstate_matrix_projection" | "unity_MatrixP" | "unity_CameraProjection" => flat(&frame.projection),
        "unity_ObjectToWorld" => flat(&object.to_world.0),
        "unity_WorldToObject" => flat(&object.to_world.1),
        "unity_WorldTransformParams" => vec![vec![0.0, 0.0, 0.0, 1.0]],
        "_WorldSpaceCameraPos" => four(frame.eye, 1.0),
        "_DirectionalLightCount" => vec![vec![LIGHTS.len() as f64]],
        "_DirectionalLightColors" => LIGHTS.iter().map(|(_, c)| four(*c, 0.0).remove(0)).collect(),
        "_DirectionalLightDirections" => {
            LIGHTS.iter().map(|(d, _)| four(r::normalize(*d), 0.0).remove(0)).collect()
        }
        "_WorldSpaceLightPos0" => four(key, 0.0),
        "_LightColor0" => four(LIGHTS[0].1, 1.0),
        "_ProjectionParams" => vec![vec![1.0, NEAR, FAR, 1.0 / FAR]],
        "_ScreenParams" => vec![vec![side, side, 1.0 + 1.0 / side, 1.0 + 1.0 / side]],
        _ => return None,
    })
}

/// The scalar count and kind of a WGSL type name (`vec3<f32>`, `mat4x4<f32>`, `i32`), with a
/// matrix's column count and column stride; `None` for any other type.
fn shape(ty: &str) -> Option<(usize, usize, u32, &str)> {
    if let Some(rest) = ty.strip_prefix("mat") {
        let (dims, scalar) = rest.split_once('<')?;
        let (columns, rows) = dims.split_once('x')?;
        let (columns, rows): (usize, usize) = (columns.parse().ok()?, rows.parse().ok()?);
        let stride = if rows == 2 { 8 } else { 16 };
        return Some((columns, rows, stride, scalar.trim_end_matches('>')));
    }
    if let Some(rest) = ty.strip_prefix("vec") {
        let (count, scalar) = rest.split_once('<')?;
        return Some((1, count.parse().ok()?, 0, scalar.trim_end_matches('>')));
    }
    matches!(ty, "f32" | "i32" | "u32").then_some((1, 1, 0, ty))
}

/// Writes `elements` (one for a plain member, one per element of an array) into a member's
/// bytes as its scalar type; whether the member's type was one the preview writes.
fn write_value(bytes: &mut [u8], member: &Member, elements: &[Vec<f64>]) -> bool {
    let (element_type, stride, count) = match (member.array_stride, member.ty.strip_prefix("array<")) {
        (Some(stride), Some(inner)) => {
            let inner = inner.rsplit_once(',').map_or(inner.trim_end_matches('>'), |(ty, _)| ty);
            (inner.trim(), stride, member.array_length.unwrap_or(1) as usize)
        }
        _ => (member.ty.as_str(), 0, 1),
    };
    let Some((columns, rows, column_stride, scalar)) = shape(element_type) else { return false };
    for (i, element) in elements.iter().take(count).enumerate() {
        for c in 0..columns {
            for row in 0..rows {
                let Some(&value) = element.get(4 * c + row) else { continue };
                let word = match scalar {
                    "f32" => (value as f32).to_le_bytes(),
                    "i32" => (value as i32).to_le_bytes(),
                    "u32" => (value as u32).to_le_bytes(),
                    _ => return false,
                };
                let at = member.offset as usize + i * stride as usize + c * column_stride as usize + 4 * row;
                if let Some(slot) = bytes.get_mut(at..at + 4) {
                    slot.copy_from_slice(&word);
                }
            }
        }
    }
    true
}

/// The renderer side of a preview: one white (or black, grey, bump) texture per name and
/// dimension the pass samples, and one sampler.
struct Textures {
    views: BTreeMap<String, wgpu::TextureView>,
    sampler: wgpu::Sampler,
    comparison: wgpu::Sampler,
}

impl MaterialTextures for Textures {
    fn texture(&self, property: &str, _texture: &str) -> Option<&wgpu::TextureView> {
        self.views.get(property)
    }
    fn sampler(&self, _property: &str) -> Option<&wgpu::Sampler> {
        Some(&self.sampler)
    }
}

/// The colour of a 1 x 1 texture Unity names by default (`white`, `black`, `grey`, `bump`), or
/// `None` for any other name (a file the preview does not load).
fn texel(name: &str) -> Option<[u8; 4]> {
    Some(match name {
        "white" | "" => [255, 255, 255, 255],
        "black" => [0, 0, 0, 255],
        "gray" | "grey" => [128, 128, 128, 255],
        "bump" => [128, 128, 255, 255],
        "red" => [255, 0, 0, 255],
        _ => return None,
    })
}

fn textures(
    device: &wgpu::Device,
    queue: &wgpu::Queue,
    pass: &PassManifest,
    shader: &str,
    values: &BTreeMap<String, serde_json::Value>,
    notes: &mut Vec<String>,
) -> Result<Textures, PreviewError> {
    let unsupported =
        |what: String| PreviewError::Unsupported { shader: shader.to_string(), pass: pass.index, what };
    let mut views = BTreeMap::new();
    for entry in pass.layout.iter().flat_map(|g| &g.entries) {
        let Resource::Texture { dimension, sample_type, multisampled } = &entry.resource else { continue };
        if *multisampled || matches!(sample_type, SampleType::Depth) {
            return Err(unsupported(format!("`{}` is a depth or multisampled texture", entry.name)));
        }
        let value = values.get(&entry.name).and_then(|v| v.as_str()).unwrap_or("white");
        let texel = texel(value).unwrap_or_else(|| {
            notes.push(format!(
                "`{}` names the texture `{value}`, which the preview draws as white (it loads no files)",
                entry.name
            ));
            [255; 4]
        });
        let (layers, view_dimension, texture_dimension) = match dimension {
            ViewDimension::D1 => (1, wgpu::TextureViewDimension::D1, wgpu::TextureDimension::D1),
            ViewDimension::D2 => (1, wgpu::TextureViewDimension::D2, wgpu::TextureDimension::D2),
            ViewDimension::D2Array => (1, wgpu::TextureViewDimension::D2Array, wgpu::TextureDimension::D2),
            ViewDimension::D3 => (1, wgpu::TextureViewDimension::D3, wgpu::TextureDimension::D3),
            ViewDimension::Cube => (6, wgpu::TextureViewDimension::Cube, wgpu::TextureDimension::D2),
            ViewDimension::CubeArray => {
                (6, wgpu::TextureViewDimension::CubeArray, wgpu::TextureDimension::D2)
            }
        };
        let format = match sample_type {
            SampleType::Sint => wgpu::TextureFormat::Rgba8Sint,
            SampleType::Uint => wgpu::TextureFormat::Rgba8Uint,
            _ => wgpu::TextureFormat::Rgba8Unorm,
        };
        let data: Vec<u8> = (0..layers).flat_map(|_| texel).collect();
        let texture = device.create_texture_with_data(
            queue,
            &wgpu::TextureDescriptor {
                label: Some(&entry.name),
                size: wgpu::Extent3d { width: 1, height: 1, depth_or_array_layers: layers },
                mip_level_count: 1,
                sample_count: 1,
                dimension: texture_dimension,
                format,
                usage: wgpu::TextureUsages::TEXTURE_BINDING,
                view_formats: &[],
            },
            wgpu::util::TextureDataOrder::LayerMajor,
            &data,
        );
        let view = texture.create_view(&wgpu::TextureViewDescriptor {
            dimension: Some(view_dimension),
            ..Default::default()
        });
        views.insert(entry.name.clone(), view);
    }
    let sampler = device.create_sampler(&wgpu::SamplerDescriptor {
        mag_filter: wgpu::FilterMode::Linear,
        min_filter: wgpu::FilterMode::Linear,
        ..Default::default()
    });
    let comparison = device.create_sampler(&wgpu::SamplerDescriptor {
        compare: Some(wgpu::CompareFunction::LessEqual),
        ..Default::default()
    });
    Ok(Textures { views, sampler, comparison })
}

/// The vertex buffer of an object for the pass's inputs, packed as the run time's default
/// vertex layout reads them (location order, each right after the last): each input by its name
/// (`position`/`vertex`, `normal`, `tangent`, `uv`/`texcoord`, `color`), location 0 a position.
fn vertex_bytes(
    inputs: &[(u32, String, AttributeFormat)],
    vertices: &[geometry::Vertex],
) -> Result<Vec<u8>, String> {
    let mut sorted: Vec<&(u32, String, AttributeFormat)> = inputs.iter().collect();
    sorted.sort_by_key(|(location, _, _)| *location);
    let mut bytes = Vec::new();
    for vertex in vertices {
        for (location, name, format) in &sorted {
            let lower = name.to_ascii_lowercase();
            let [nx, ny, nz] = vertex.normal;
            // The tangent along +u: d(position)/du of the sphere, or +x on the plane.
            let tangent = r::safe_normalize([-nz, 0.0, nx]);
            let tangent = if r::dot(tangent, tangent) > 0.5 { tangent } else { [1.0, 0.0, 0.0] };
            let value: [f64; 4] = if lower.contains("normal") {
                [nx, ny, nz, 0.0]
            } else if lower.contains("tangent") {
                [tangent[0], tangent[1], tangent[2], 1.0]
            } else if lower.contains("uv") || lower.contains("texcoord") {
                [vertex.uv[0], vertex.uv[1], 0.0, 0.0]
            } else if lower.contains("color") || lower.contains("colour") {
                [1.0; 4]
            } else if lower.contains("pos") || lower.contains("vertex") || *location == 0 {
                let p = vertex.position;
                [p[0], p[1], p[2], 1.0]
            } else {
                return Err(format!(
                    "the vertex input `{name}` (location {location}) is none the preview fills \
                     (a position, normal, tangent, uv or colour)"
                ));
            };
            let components = match format {
                AttributeFormat::Float32 => 1,
                AttributeFormat::Float32x2 => 2,
                AttributeFormat::Float32x3 => 3,
                AttributeFormat::Float32x4 => 4,
                other => {
                    return Err(format!(
                        "the vertex input `{name}` is `{other}`; the preview fills 32-bit float inputs"
                    ));
                }
            };
            bytes.extend(value[..components].iter().flat_map(|v| (*v as f32).to_le_bytes()));
        }
    }
    Ok(bytes)
}

/// The preview drawn through `runtime`: the plane, then the sphere, one draw each.
fn render(
    runtime: &mut Runtime,
    device: &wgpu::Device,
    queue: &wgpu::Queue,
    material: &crate::manifest::MaterialManifest,
    pass_index: usize,
    keywords: &[String],
    size: u32,
) -> Result<(Picture, Vec<String>), PreviewError> {
    let library = runtime.library();
    let pass_manifest = library.pass(&material.shader, pass_index)?.clone();
    let unsupported =
        |what: String| PreviewError::Unsupported { shader: material.shader.clone(), pass: pass_index, what };
    let mut notes = Vec::new();
    let pass: PassId = runtime.pass(&material.shader, pass_index)?;
    let keyword_refs: Vec<&str> = keywords.iter().map(String::as_str).collect();
    let variant = runtime.variant(&material.shader, pass_index, &keyword_refs)?;
    let variant_manifest = runtime.library().variant_of(variant)?.clone();
    let [Some(vertex_stage), _] = pass_manifest.variant_stages(&variant_manifest) else {
        return Err(unsupported("the variant has no vertex stage".into()));
    };
    let inputs: Vec<(u32, String, AttributeFormat)> =
        vertex_stage.interface.inputs.iter().map(|a| (a.location, a.name.clone(), a.format)).collect();
    let textures = textures(device, queue, &pass_manifest, &material.shader, &material.values, &mut notes)?;

    let (sphere_vertices, sphere_indices) = geometry::uv_sphere(SPHERE_RINGS, SPHERE_SEGMENTS);
    let (plane_vertices, plane_indices) = geometry::plane();
    let objects = [
        Object {
            vertices: plane_vertices,
            indices: plane_indices,
            to_world: object_to_world([0.0, PLANE_HEIGHT, 0.0], [PLANE_HALF_SIDE, 1.0, PLANE_HALF_SIDE]),
        },
        Object {
            vertices: sphere_vertices,
            indices: sphere_indices,
            to_world: object_to_world([0.0; 3], [1.0; 3]),
        },
    ];

    let targets = Targets {
        colors: vec![wgpu::TextureFormat::Rgba8Unorm],
        depth: Some(wgpu::TextureFormat::Depth32Float),
        samples: 1,
    };
    let request =
        PipelineRequest { variant, material, targets: &targets, vertex_layout: None, overrides: &[] };
    let pipeline = runtime.pipeline(&request)?;
    let layout = runtime.pass_layout(pass)?;
    let entries_of = |group: u32| {
        pass_manifest.layout.iter().find(|g| g.group == group).map_or(&[][..], |g| &g.entries[..])
    };
    let material_group = match entries_of(MATERIAL_GROUP).is_empty() {
        true => None,
        false => Some(runtime.material_bind_group(material, pass, &textures)?),
    };

    // Each object's bind groups besides the material's, and its buffers.
    let frame = Frame::new();
    let mut left_zero = std::collections::BTreeSet::new();
    let mut draws = Vec::new();
    for object in &objects {
        let vertices = vertex_bytes(&inputs, &object.vertices).map_err(unsupported)?;
        let vertex_buffer = device.create_buffer_init(&wgpu::util::BufferInitDescriptor {
            label: Some("preview vertices"),
            contents: if vertices.is_empty() { &[0; 4] } else { &vertices },
            usage: wgpu::BufferUsages::VERTEX,
        });
        let index_buffer = device.create_buffer_init(&wgpu::util::BufferInitDescriptor {
            label: Some("preview indices"),
            contents: bytemuck::cast_slice(&object.indices),
            usage: wgpu::BufferUsages::INDEX,
        });
        let mut groups = Vec::new();
        // Every group of the layout is bound, an empty one too, as wgpu requires.
        for group in
            (0..layout.groups.len() as u32).filter(|&g| g != MATERIAL_GROUP || material_group.is_none())
        {
            let mut buffers = Vec::new();
            for entry in entries_of(group) {
                let contents = match &entry.resource {
                    Resource::Uniform { .. } | Resource::Storage { .. } => {
                        let block = pass_manifest.uniform_blocks.iter().find(|b| b.name == entry.name);
                        let Some(block) = block else {
                            return Err(unsupported(format!("no layout for the buffer `{}`", entry.name)));
                        };
                        // The material's values where members are named after its properties.
                        let mut bytes = match block.storage {
                            true => vec![0; block.size.max(16) as usize],
                            false => runtime.library().material_uniform(material, pass_index, &block.name)?,
                        };
                        for member in &block.members {
                            match scene_value(&member.name, &frame, object, size) {
                                Some(value) if write_value(&mut bytes, member, &value) => {}
                                _ if material.values.contains_key(&member.name) => {}
                                _ => {
                                    left_zero.insert(member.name.clone());
                                }
                            }
                        }
                        Some(bytes)
                    }
                    _ => None,
                };
                buffers.push((entry, contents));
            }
            let made: Vec<Option<wgpu::Buffer>> = buffers
                .iter()
                .map(|(entry, contents)| {
                    contents.as_ref().map(|bytes| {
                        let usage = match entry.resource {
                            Resource::Storage { .. } => wgpu::BufferUsages::STORAGE,
                            _ => wgpu::BufferUsages::UNIFORM,
                        };
                        device.create_buffer_init(&wgpu::util::BufferInitDescriptor {
                            label: Some(&entry.name),
                            contents: bytes,
                            usage,
                        })
                    })
                })
                .collect();
            let mut bound = Vec::new();
            for ((entry, _), buffer) in buffers.iter().zip(&made) {
                let resource = match (&entry.resource, buffer) {
                    (_, Some(buffer)) => buffer.as_entire_binding(),
                    (Resource::Texture { .. }, None) => match textures.views.get(&entry.name) {
                        Some(view) => wgpu::BindingResource::TextureView(view),
                        None => return Err(unsupported(format!("no texture for `{}`", entry.name))),
                    },
                    (Resource::Sampler { comparison: true }, None) => {
                        wgpu::BindingResource::Sampler(&textures.comparison)
                    }
                    (Resource::Sampler { comparison: false }, None) => {
                        wgpu::BindingResource::Sampler(&textures.sampler)
                    }
                    _ => {
                        return Err(unsupported(format!(
                            "`{}` is a storage texture or a binding the preview cannot fill",
                            entry.name
                        )));
                    }
                };
                bound.push(wgpu::BindGroupEntry { binding: entry.binding, resource });
            }
            let bind_group = device.create_bind_group(&wgpu::BindGroupDescriptor {
                label: Some("preview"),
                layout: &layout.groups[group as usize],
                entries: &bound,
            });
            groups.push((group, bind_group));
        }
        draws.push((vertex_buffer, index_buffer, object.indices.len() as u32, groups));
    }
    if !left_zero.is_empty() {
        let names: Vec<String> = left_zero.iter().take(6).map(|n| format!("`{n}`")).collect();
        let more = left_zero.len().saturating_sub(names.len());
        let more = if more > 0 { format!(" and {more} more") } else { String::new() };
        notes.push(format!(
            "the preview leaves {}{more} at zero: it sets only the names docs/preview.md lists",
            names.join(", ")
        ));
    }

    let extent = wgpu::Extent3d { width: size, height: size, depth_or_array_layers: 1 };
    let target = device.create_texture(&wgpu::TextureDescriptor {
        label: Some("preview colour"),
        size: extent,
        mip_level_count: 1,
        sample_count: 1,
        dimension: wgpu::TextureDimension::D2,
        format: targets.colors[0],
        usage: wgpu::TextureUsages::RENDER_ATTACHMENT | wgpu::TextureUsages::COPY_SRC,
        view_formats: &[],
    });
    let depth = device.create_texture(&wgpu::TextureDescriptor {
        label: Some("preview depth"),
        size: extent,
        mip_level_count: 1,
        sample_count: 1,
        dimension: wgpu::TextureDimension::D2,
        format: wgpu::TextureFormat::Depth32Float,
        usage: wgpu::TextureUsages::RENDER_ATTACHMENT,
        view_formats: &[],
    });
    let (target_view, depth_view) =
        (target.create_view(&Default::default()), depth.create_view(&Default::default()));
    let mut encoder = device.create_command_encoder(&Default::default());
    {
        let [red, green, blue] = BACKGROUND;
        let mut render_pass = encoder.begin_render_pass(&wgpu::RenderPassDescriptor {
            label: Some("preview"),
            color_attachments: &[Some(wgpu::RenderPassColorAttachment {
                view: &target_view,
                depth_slice: None,
                resolve_target: None,
                ops: wgpu::Operations {
                    load: wgpu::LoadOp::Clear(wgpu::Color { r: red, g: green, b: blue, a: 1.0 }),
                    store: wgpu::StoreOp::Store,
                },
            })],
            depth_stencil_attachment: Some(wgpu::RenderPassDepthStencilAttachment {
                view: &depth_view,
                depth_ops: Some(wgpu::Operations {
                    load: wgpu::LoadOp::Clear(1.0),
                    store: wgpu::StoreOp::Store,
                }),
                stencil_ops: None,
            }),
            ..Default::default()
        });
        render_pass.set_pipeline(&pipeline);
        if let Some(material_group) = &material_group {
            render_pass.set_bind_group(material_group.group, &material_group.bind_group, &[]);
        }
        for (vertex_buffer, index_buffer, count, groups) in &draws {
            for (index, group) in groups {
                render_pass.set_bind_group(*index, group, &[]);
            }
            render_pass.set_vertex_buffer(0, vertex_buffer.slice(..));
            render_pass.set_index_buffer(index_buffer.slice(..), wgpu::IndexFormat::Uint32);
            render_pass.draw_indexed(0..*count, 0, 0..1);
        }
    }
    let row = (size * 4).div_ceil(wgpu::COPY_BYTES_PER_ROW_ALIGNMENT) * wgpu::COPY_BYTES_PER_ROW_ALIGNMENT;
    let readback = device.create_buffer(&wgpu::BufferDescriptor {
        label: Some("preview read-back"),
        size: u64::from(row * size),
        usage: wgpu::BufferUsages::COPY_DST | wgpu::BufferUsages::MAP_READ,
        mapped_at_creation: false,
    });
    encoder.copy_texture_to_buffer(
        target.as_image_copy(),
        wgpu::TexelCopyBufferInfo {
            buffer: &readback,
            layout: wgpu::TexelCopyBufferLayout { offset: 0, bytes_per_row: Some(row), rows_per_image: None },
        },
        extent,
    );
    queue.submit([encoder.finish()]);
    readback.map_async(wgpu::MapMode::Read, .., |_| {});
    device
        .poll(wgpu::PollType::wait_indefinitely())
        .map_err(|e| PreviewError::Device(format!("the GPU did not finish: {e}")))?;
    let mapped = readback.get_mapped_range(..).map_err(|e| PreviewError::Device(e.to_string()))?;
    let mut rgba = Vec::with_capacity((size * size * 4) as usize);
    for y in 0..size {
        let start = (y * row) as usize;
        rgba.extend_from_slice(&mapped[start..start + (size * 4) as usize]);
    }
    Ok((Picture { width: size, height: size, rgba }, notes))
}
