//! wgpu layouts from reflection: bind group and pipeline layouts from a pass's layout entries,
//! vertex buffer layouts from a vertex stage's inputs.

use kiln_manifest::Resource;
use kiln_manifest::{
    AttributeFormat, BindGroup, LayoutEntry, SampleType, ShaderStage, StorageAccess, TexelFormat,
    ViewDimension,
};

/// A layout wgpu has no form for.
#[derive(Debug, Clone, PartialEq, Eq, thiserror::Error)]
#[non_exhaustive]
// Each variant's fields are named in its message.
#[allow(missing_docs)]
pub enum LayoutError {
    /// A binding of a kind wgpu cannot bind (`Resource::Other`).
    #[error("binding `{binding}`: no wgpu binding for {description}")]
    Binding { binding: String, description: String },
    /// A vertex input of a type no vertex format reads.
    #[error("vertex input {location}: no vertex format `{format}`")]
    VertexFormat { location: u32, format: AttributeFormat },
}

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
    pub fn new(device: &wgpu::Device, layout: &[BindGroup]) -> Result<PassLayout, LayoutError> {
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
            .collect::<Result<Vec<_>, LayoutError>>()?;
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
pub fn bind_group_layout_entry(entry: &LayoutEntry) -> Result<wgpu::BindGroupLayoutEntry, LayoutError> {
    let visibility = entry.visibility.iter().fold(wgpu::ShaderStages::NONE, |all, stage| {
        all | match stage {
            ShaderStage::Vertex => wgpu::ShaderStages::VERTEX,
            ShaderStage::Fragment => wgpu::ShaderStages::FRAGMENT,
            ShaderStage::Compute => wgpu::ShaderStages::COMPUTE,
        }
    });
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
            sample_type: match sample_type {
                SampleType::Sint => wgpu::TextureSampleType::Sint,
                SampleType::Uint => wgpu::TextureSampleType::Uint,
                SampleType::Depth => wgpu::TextureSampleType::Depth,
                // Multisampled float textures cannot be filtered.
                SampleType::Float => wgpu::TextureSampleType::Float { filterable: !multisampled },
            },
            view_dimension: view_dimension(*dimension),
            multisampled: *multisampled,
        },
        Resource::StorageTexture { dimension, format, access } => wgpu::BindingType::StorageTexture {
            access: match access {
                StorageAccess::Read => wgpu::StorageTextureAccess::ReadOnly,
                StorageAccess::Write => wgpu::StorageTextureAccess::WriteOnly,
                StorageAccess::ReadWrite => wgpu::StorageTextureAccess::ReadWrite,
                StorageAccess::Atomic => wgpu::StorageTextureAccess::Atomic,
            },
            format: texture_format(*format),
            view_dimension: view_dimension(*dimension),
        },
        // A comparison sampler samples depth; any other may filter.
        Resource::Sampler { comparison: true } => {
            wgpu::BindingType::Sampler(wgpu::SamplerBindingType::Comparison)
        }
        Resource::Sampler { comparison: false } => {
            wgpu::BindingType::Sampler(wgpu::SamplerBindingType::Filtering)
        }
        Resource::Other { description } => {
            return Err(LayoutError::Binding {
                binding: entry.name.clone(),
                description: description.clone(),
            });
        }
    };
    Ok(wgpu::BindGroupLayoutEntry { binding: entry.binding, visibility, ty, count: None })
}

fn view_dimension(dimension: ViewDimension) -> wgpu::TextureViewDimension {
    match dimension {
        ViewDimension::D1 => wgpu::TextureViewDimension::D1,
        ViewDimension::D2 => wgpu::TextureViewDimension::D2,
        ViewDimension::D2Array => wgpu::TextureViewDimension::D2Array,
        ViewDimension::D3 => wgpu::TextureViewDimension::D3,
        ViewDimension::Cube => wgpu::TextureViewDimension::Cube,
        ViewDimension::CubeArray => wgpu::TextureViewDimension::CubeArray,
    }
}

/// The wgpu format of a storage texel format.
fn texture_format(format: TexelFormat) -> wgpu::TextureFormat {
    use wgpu::TextureFormat as F;
    match format {
        TexelFormat::R8Unorm => F::R8Unorm,
        TexelFormat::R8Snorm => F::R8Snorm,
        TexelFormat::R8Uint => F::R8Uint,
        TexelFormat::R8Sint => F::R8Sint,
        TexelFormat::R16Uint => F::R16Uint,
        TexelFormat::R16Sint => F::R16Sint,
        TexelFormat::R16Float => F::R16Float,
        TexelFormat::Rg8Unorm => F::Rg8Unorm,
        TexelFormat::Rg8Snorm => F::Rg8Snorm,
        TexelFormat::Rg8Uint => F::Rg8Uint,
        TexelFormat::Rg8Sint => F::Rg8Sint,
        TexelFormat::R32Uint => F::R32Uint,
        TexelFormat::R32Sint => F::R32Sint,
        TexelFormat::R32Float => F::R32Float,
        TexelFormat::Rg16Uint => F::Rg16Uint,
        TexelFormat::Rg16Sint => F::Rg16Sint,
        TexelFormat::Rg16Float => F::Rg16Float,
        TexelFormat::Rgba8Unorm => F::Rgba8Unorm,
        TexelFormat::Rgba8Snorm => F::Rgba8Snorm,
        TexelFormat::Rgba8Uint => F::Rgba8Uint,
        TexelFormat::Rgba8Sint => F::Rgba8Sint,
        TexelFormat::Bgra8Unorm => F::Bgra8Unorm,
        TexelFormat::Rgb10a2Uint => F::Rgb10a2Uint,
        TexelFormat::Rgb10a2Unorm => F::Rgb10a2Unorm,
        TexelFormat::Rg11b10Ufloat => F::Rg11b10Ufloat,
        TexelFormat::R64Uint => F::R64Uint,
        TexelFormat::Rg32Uint => F::Rg32Uint,
        TexelFormat::Rg32Sint => F::Rg32Sint,
        TexelFormat::Rg32Float => F::Rg32Float,
        TexelFormat::Rgba16Uint => F::Rgba16Uint,
        TexelFormat::Rgba16Sint => F::Rgba16Sint,
        TexelFormat::Rgba16Float => F::Rgba16Float,
        TexelFormat::Rgba32Uint => F::Rgba32Uint,
        TexelFormat::Rgba32Sint => F::Rgba32Sint,
        TexelFormat::Rgba32Float => F::Rgba32Float,
        TexelFormat::R16Unorm => F::R16Unorm,
        TexelFormat::R16Snorm => F::R16Snorm,
        TexelFormat::Rg16Unorm => F::Rg16Unorm,
        TexelFormat::Rg16Snorm => F::Rg16Snorm,
        TexelFormat::Rgba16Unorm => F::Rgba16Unorm,
        TexelFormat::Rgba16Snorm => F::Rgba16Snorm,
    }
}

/// How a pipeline reads its vertex attributes.
///
/// The default ([`VertexLayout::packed`]) is one interleaved buffer, attributes in location order,
/// each right after the last (`float32x3` position at 0, `float32x3` normal at 12, `float32x2` uv
/// at 24: stride 32). A renderer with its own layout passes it instead.
#[derive(Debug, Clone, PartialEq, Eq, Hash, serde::Serialize, serde::Deserialize)]
pub struct VertexLayout {
    /// The vertex buffers, in slot order.
    pub buffers: Vec<VertexBuffer>,
}

/// One vertex buffer's layout.
#[derive(Debug, Clone, PartialEq, Eq, Hash, serde::Serialize, serde::Deserialize)]
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
    pub fn packed(inputs: &[(u32, AttributeFormat)]) -> Result<VertexLayout, LayoutError> {
        let mut inputs: Vec<&(u32, AttributeFormat)> = inputs.iter().collect();
        inputs.sort_by_key(|(location, _)| *location);
        let mut offset = 0;
        let mut attributes = Vec::new();
        for (location, format) in inputs {
            let format = vertex_format(*format)
                .ok_or(LayoutError::VertexFormat { location: *location, format: *format })?;
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
fn vertex_format(format: AttributeFormat) -> Option<wgpu::VertexFormat> {
    use AttributeFormat as A;
    use wgpu::VertexFormat as V;
    Some(match format {
        A::Float16x2 => V::Float16x2,
        A::Float16x4 => V::Float16x4,
        A::Float32 => V::Float32,
        A::Float32x2 => V::Float32x2,
        A::Float32x3 => V::Float32x3,
        A::Float32x4 => V::Float32x4,
        A::Sint32 => V::Sint32,
        A::Sint32x2 => V::Sint32x2,
        A::Sint32x3 => V::Sint32x3,
        A::Sint32x4 => V::Sint32x4,
        A::Uint32 => V::Uint32,
        A::Uint32x2 => V::Uint32x2,
        A::Uint32x3 => V::Uint32x3,
        A::Uint32x4 => V::Uint32x4,
        // WebGPU has no three-component 16-bit format and no 64-bit integer one; the default
        // packing leaves single 16-bit and 64-bit floats to a renderer's own layout.
        A::Float16
        | A::Float16x3
        | A::Float64
        | A::Float64x2
        | A::Float64x3
        | A::Float64x4
        | A::Sint64
        | A::Sint64x2
        | A::Sint64x3
        | A::Sint64x4
        | A::Uint64
        | A::Uint64x2
        | A::Uint64x3
        | A::Uint64x4
        | A::Unsupported => return None,
    })
}
