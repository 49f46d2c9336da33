//! wgpu layouts from reflection: bind group and pipeline layouts from a pass's layout entries,
//! vertex buffer layouts from a vertex stage's inputs.

use crate::manifest::{BindGroup, LayoutEntry};
use crate::reflect::Resource;

/// A pass's bind group layouts (groups 0 to the highest it uses, empty ones included) and its
/// pipeline layout. Every variant of a pass shares it.
#[derive(Debug)]
pub struct PassLayout {
    /// One layout per bind group, in group order.
    pub groups: Vec<wgpu::BindGroupLayout>,
    /// The pipeline layout over them.
    pub pipeline: wgpu::PipelineLayout,
}

impl PassLayout {
    /// Creates the layouts of a pass's bind groups.
    pub fn new(device: &wgpu::Device, layout: &[BindGroup]) -> Result<PassLayout, String> {
        let count = layout.iter().map(|g| g.group + 1).max().unwrap_or(0);
        let groups = (0..count)
            .map(|group| {
                let entries = layout.iter().find(|g| g.group == group).map_or(&[][..], |g| &g.entries[..]);
                let entries = entries.iter().map(bind_group_layout_entry).collect::<Result<Vec<_>, _>>()?;
                Ok(device.create_bind_group_layout(&wgpu::BindGroupLayoutDescriptor {
                    label: Some(&format!("kiln group {group}")),
                    entries: &entries,
                }))
            })
            .collect::<Result<Vec<_>, String>>()?;
        let refs: Vec<Option<&wgpu::BindGroupLayout>> = groups.iter().map(Some).collect();
        let pipeline = device.create_pipeline_layout(&wgpu::PipelineLayoutDescriptor {
            label: Some("kiln pass"),
            bind_group_layouts: &refs,
            immediate_size: 0,
        });
        Ok(PassLayout { groups, pipeline })
    }
}

/// One entry of a bind group layout, for every resource kind kiln reflects.
pub fn bind_group_layout_entry(entry: &LayoutEntry) -> Result<wgpu::BindGroupLayoutEntry, String> {
    let mut visibility = wgpu::ShaderStages::NONE;
    for stage in &entry.visibility {
        visibility |= match stage.as_str() {
            "vertex" => wgpu::ShaderStages::VERTEX,
            "fragment" => wgpu::ShaderStages::FRAGMENT,
            _ => wgpu::ShaderStages::COMPUTE,
        };
    }
    let unsupported = |what: &str| format!("binding `{}`: {what}", entry.name);
    let ty = match &entry.resource {
        Resource::Uniform { size, .. } => wgpu::BindingType::Buffer {
            ty: wgpu::BufferBindingType::Uniform,
            has_dynamic_offset: false,
            min_binding_size: wgpu::BufferSize::new(u64::from(*size)),
        },
        Resource::Storage { read_only, .. } => wgpu::BindingType::Buffer {
            ty: wgpu::BufferBindingType::Storage { read_only: *read_only },
            has_dynamic_offset: false,
            min_binding_size: None,
        },
        Resource::Texture { dimension, sample_type, multisampled } => wgpu::BindingType::Texture {
            sample_type: match sample_type.as_str() {
                "sint" => wgpu::TextureSampleType::Sint,
                "uint" => wgpu::TextureSampleType::Uint,
                "depth" => wgpu::TextureSampleType::Depth,
                // Multisampled float textures cannot be filtered.
                _ => wgpu::TextureSampleType::Float { filterable: !multisampled },
            },
            view_dimension: view_dimension(dimension).ok_or_else(|| unsupported(dimension))?,
            multisampled: *multisampled,
        },
        Resource::StorageTexture { dimension, format, access } => wgpu::BindingType::StorageTexture {
            access: match access.as_str() {
                "load" => wgpu::StorageTextureAccess::ReadOnly,
                "store" => wgpu::StorageTextureAccess::WriteOnly,
                _ => wgpu::StorageTextureAccess::ReadWrite,
            },
            format: texture_format(format)
                .ok_or_else(|| unsupported(&format!("storage format `{format}`")))?,
            view_dimension: view_dimension(dimension).ok_or_else(|| unsupported(dimension))?,
        },
        // A comparison sampler samples depth; any other may filter.
        Resource::Sampler { comparison: true } => {
            wgpu::BindingType::Sampler(wgpu::SamplerBindingType::Comparison)
        }
        Resource::Sampler { comparison: false } => {
            wgpu::BindingType::Sampler(wgpu::SamplerBindingType::Filtering)
        }
        Resource::Other { description } => {
            return Err(unsupported(&format!("no wgpu binding for {description}")));
        }
    };
    Ok(wgpu::BindGroupLayoutEntry { binding: entry.binding, visibility, ty, count: None })
}

fn view_dimension(dimension: &str) -> Option<wgpu::TextureViewDimension> {
    Some(match dimension {
        "1d" => wgpu::TextureViewDimension::D1,
        "2d" => wgpu::TextureViewDimension::D2,
        "2d_array" => wgpu::TextureViewDimension::D2Array,
        "3d" => wgpu::TextureViewDimension::D3,
        "cube" => wgpu::TextureViewDimension::Cube,
        "cube_array" => wgpu::TextureViewDimension::CubeArray,
        _ => return None,
    })
}

/// naga's storage format names (`rgba8unorm`, from its `Debug`, lowercased) as wgpu formats.
fn texture_format(name: &str) -> Option<wgpu::TextureFormat> {
    use wgpu::TextureFormat as F;
    Some(match name {
        "r32float" => F::R32Float,
        "r32uint" => F::R32Uint,
        "r32sint" => F::R32Sint,
        "rg32float" => F::Rg32Float,
        "rgba8unorm" => F::Rgba8Unorm,
        "rgba8snorm" => F::Rgba8Snorm,
        "rgba8uint" => F::Rgba8Uint,
        "rgba8sint" => F::Rgba8Sint,
        "rgba16float" => F::Rgba16Float,
        "rgba16uint" => F::Rgba16Uint,
        "rgba16sint" => F::Rgba16Sint,
        "rgba32float" => F::Rgba32Float,
        "rgba32uint" => F::Rgba32Uint,
        "rgba32sint" => F::Rgba32Sint,
        "bgra8unorm" => F::Bgra8Unorm,
        _ => return None,
    })
}

/// How a pipeline reads its vertex attributes.
///
/// The default ([`VertexLayout::packed`]) is one interleaved buffer, attributes in location order,
/// each right after the last (`float32x3` position at 0, `float32x3` normal at 12, `float32x2` uv
/// at 24: stride 32). A renderer with its own layout passes it instead.
#[derive(Debug, Clone, PartialEq, Eq, Hash)]
pub struct VertexLayout {
    /// The vertex buffers, in slot order.
    pub buffers: Vec<VertexBuffer>,
}

/// One vertex buffer's layout.
#[derive(Debug, Clone, PartialEq, Eq, Hash)]
pub struct VertexBuffer {
    /// Bytes between vertices.
    pub stride: u64,
    /// Per vertex or per instance.
    pub step_mode: wgpu::VertexStepMode,
    /// The attributes it feeds.
    pub attributes: Vec<wgpu::VertexAttribute>,
}

impl VertexLayout {
    /// The default packing of a vertex stage's inputs (`(location, format)` as reflected).
    pub fn packed(inputs: &[(u32, String)]) -> Result<VertexLayout, String> {
        let mut inputs: Vec<&(u32, String)> = inputs.iter().collect();
        inputs.sort_by_key(|(location, _)| *location);
        let mut offset = 0;
        let mut attributes = Vec::new();
        for (location, format) in inputs {
            let format = vertex_format(format)
                .ok_or_else(|| format!("vertex input {location}: no vertex format `{format}`"))?;
            attributes.push(wgpu::VertexAttribute { format, offset, shader_location: *location });
            offset += format.size();
        }
        Ok(VertexLayout {
            buffers: vec![VertexBuffer {
                stride: offset,
                step_mode: wgpu::VertexStepMode::Vertex,
                attributes,
            }],
        })
    }

    /// The layouts as wgpu takes them, borrowing from `self`.
    pub fn wgpu(&self) -> Vec<Option<wgpu::VertexBufferLayout<'_>>> {
        self.buffers
            .iter()
            .map(|b| {
                Some(wgpu::VertexBufferLayout {
                    array_stride: b.stride,
                    step_mode: b.step_mode,
                    attributes: &b.attributes,
                })
            })
            .collect()
    }
}

/// A reflected vertex format (`float32x3`) as wgpu's.
fn vertex_format(name: &str) -> Option<wgpu::VertexFormat> {
    use wgpu::VertexFormat as V;
    Some(match name {
        "float32" => V::Float32,
        "float32x2" => V::Float32x2,
        "float32x3" => V::Float32x3,
        "float32x4" => V::Float32x4,
        "float16x2" => V::Float16x2,
        "float16x4" => V::Float16x4,
        "sint32" => V::Sint32,
        "sint32x2" => V::Sint32x2,
        "sint32x3" => V::Sint32x3,
        "sint32x4" => V::Sint32x4,
        "uint32" => V::Uint32,
        "uint32x2" => V::Uint32x2,
        "uint32x3" => V::Uint32x3,
        "uint32x4" => V::Uint32x4,
        _ => return None,
    })
}
