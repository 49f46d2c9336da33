//! Reflection: what a compiled stage module needs from the renderer (vertex inputs, fragment
//! outputs, bindings, uniform block layouts from naga's `Layouter`), converted to the manifest's
//! types (`crate::manifest`).

pub use crate::manifest::{Attribute, Member, OverrideConstant, Resource, UniformBlock};
use crate::manifest::{AttributeFormat, OverrideType, SampleType, StorageAccess, TexelFormat, ViewDimension};

use naga::proc::Layouter;
use naga::{
    AddressSpace, ArraySize, Binding, Handle, ImageClass, ImageDimension, Module, ScalarKind, Type, TypeInner,
};
use serde::{Deserialize, Serialize};

/// What one stage module exposes. Stored in the build cache, so a rebuild needs no naga.
#[derive(Debug, Clone, PartialEq, Eq, Hash, Serialize, Deserialize)]
pub struct StageReflection {
    /// The entry point's name.
    pub entry_point: String,
    /// Vertex stage: the vertex attributes it reads.
    pub inputs: Vec<Attribute>,
    /// Fragment stage: the colour targets it writes.
    pub outputs: Vec<Attribute>,
    /// The resources the module uses (after compaction to its entry point), by group and binding.
    pub bindings: Vec<BindingInfo>,
    /// The uniform and storage blocks the module uses.
    pub uniform_blocks: Vec<UniformBlock>,
    /// The `override` constants the module uses.
    #[serde(default)]
    pub overrides: Vec<OverrideConstant>,
    /// A compute kernel's `@workgroup_size` (a size an `override` gives reads as 0).
    #[serde(default)]
    pub workgroup_size: Option<[u32; 3]>,
    /// The `override` constant giving each workgroup size that one gives.
    #[serde(default)]
    pub workgroup_size_overrides: Vec<Option<String>>,
    /// Bytes of `var<workgroup>` memory the kernel uses.
    #[serde(default)]
    pub workgroup_memory: u32,
    /// Why the module has no SPIR-V though SPIR-V was asked for (it ships as WGSL only).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub spirv_gap: Option<SpirvGap>,
}

/// A construct naga's SPIR-V writer cannot write correctly, for which a module ships as WGSL
/// only (K0415).
#[derive(Debug, Clone, PartialEq, Eq, Hash, Serialize, Deserialize)]
#[serde(tag = "kind", rename_all = "snake_case")]
pub enum SpirvGap {
    /// A matrix in a uniform buffer that naga lays out against Vulkan's rules.
    UniformMatrix {
        /// The uniform buffer's variable.
        buffer: String,
        /// The member holding the matrix (`Struct.member`), or the buffer's own name.
        member: String,
        /// The matrix type, as WGSL writes it.
        matrix: String,
        /// What is wrong with it.
        problem: MatrixProblem,
    },
    /// An `alias` of an array and the array type it names, both used: one type in WGSL, two in
    /// naga's SPIR-V, which then assigns one to the other without a conversion.
    AliasedArray {
        /// The alias.
        alias: String,
        /// The type it names, as WGSL writes it.
        ty: String,
    },
    /// naga's SPIR-V writer failed (or panicked) on a module its validator accepts.
    Writer {
        /// What it said.
        message: String,
    },
}

/// Why naga's SPIR-V for a matrix in a uniform buffer is wrong.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum MatrixProblem {
    /// An f16 matrix with 3 or 4 rows: column stride 8, where a uniform buffer needs 16.
    F16Rows,
    /// A two-row matrix inside a nested struct or an array of structs, which naga's std140
    /// rewrite does not reach.
    NestedTwoRows,
}

impl std::fmt::Display for SpirvGap {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self {
            SpirvGap::UniformMatrix { buffer, member, matrix, problem: MatrixProblem::F16Rows } => write!(
                f,
                "`{member}` in uniform buffer `{buffer}` is an f16 matrix with 3 or 4 rows (`{matrix}`), whose \
                 column stride of 8 bytes a Vulkan uniform buffer cannot have"
            ),
            SpirvGap::UniformMatrix { buffer, member, matrix, problem: MatrixProblem::NestedTwoRows } => {
                write!(
                    f,
                    "`{member}` in uniform buffer `{buffer}` is a two-row matrix (`{matrix}`) inside a nested struct \
                 or an array, which naga's SPIR-V writer lays out against Vulkan's rules"
                )
            }
            SpirvGap::AliasedArray { alias, ty } => write!(
                f,
                "`alias {alias} = {ty}` and `{ty}` are both used: naga's SPIR-V writer makes them two types, \
                 and an assignment from one to the other invalid"
            ),
            SpirvGap::Writer { message } => write!(f, "naga's SPIR-V writer failed: {message}"),
        }
    }
}

/// One resource the module uses, where it is bound.
#[derive(Debug, Clone, PartialEq, Eq, Hash, Serialize, Deserialize)]
pub struct BindingInfo {
    /// Its bind group.
    pub group: u32,
    /// Its binding in the group.
    pub binding: u32,
    /// Its global variable's name.
    pub name: String,
    /// What kind of resource it is.
    pub resource: Resource,
}

/// Sizes from naga's `Layouter` (its offsets, spans and strides are the spec's once kiln has
/// corrected them), alignments from the spec's rules, which naga's `Layouter` does not follow
/// for structs raised by `@align`.
struct Layouts<'a> {
    layouter: Layouter,
    alignment: &'a dyn Fn(Handle<Type>) -> u32,
}

/// The block a uniform or storage buffer binding holds.
fn block(module: &Module, layouts: &Layouts, global: &naga::GlobalVariable) -> Option<UniformBlock> {
    let storage = match global.space {
        AddressSpace::Uniform => false,
        AddressSpace::Storage { .. } => true,
        _ => return None,
    };
    let name = global.name.clone().unwrap_or_default();
    let (size, members) = match &module.types[global.ty].inner {
        TypeInner::Struct { members, span } => {
            let members = struct_members(module, layouts, members);
            // A runtime-sized array has no size of its own: the block's size is where it starts.
            let size = match members.last() {
                Some(last) if last.array_stride.is_some() && last.array_length.is_none() => last.offset,
                _ => *span,
            };
            (size, members)
        }
        TypeInner::Array { .. } => (0, vec![member(module, layouts, &name, global.ty, 0)]),
        _ => return None,
    };
    Some(UniformBlock {
        name,
        type_name: type_name(module, global.ty),
        size,
        alignment: (layouts.alignment)(global.ty),
        storage,
        members,
    })
}

fn struct_members(module: &Module, layouts: &Layouts, members: &[naga::StructMember]) -> Vec<Member> {
    members
        .iter()
        .map(|m| member(module, layouts, m.name.as_deref().unwrap_or_default(), m.ty, m.offset))
        .collect()
}

fn member(module: &Module, layouts: &Layouts, name: &str, ty: Handle<Type>, offset: u32) -> Member {
    let (array_stride, array_length, element) = match &module.types[ty].inner {
        TypeInner::Array { base, size, stride } => {
            let length = match size {
                ArraySize::Constant(n) => Some(n.get()),
                _ => None,
            };
            (Some(*stride), length, *base)
        }
        _ => (None, None, ty),
    };
    // An array of arrays of structs lists the innermost struct's members too.
    let mut innermost = element;
    while let TypeInner::Array { base, .. } = module.types[innermost].inner {
        innermost = base;
    }
    let members = match &module.types[innermost].inner {
        TypeInner::Struct { members, .. } => struct_members(module, layouts, members),
        _ => Vec::new(),
    };
    Member {
        name: name.to_string(),
        ty: type_name(module, ty),
        offset,
        // naga's layouter gives a runtime-sized array the size of one element.
        size: if array_stride.is_some() && array_length.is_none() { 0 } else { layouts.layouter[ty].size },
        alignment: (layouts.alignment)(ty),
        array_stride,
        array_length,
        members,
    }
}

/// Reflects a module compacted to one entry point; `alignment` gives a type's alignment by the
/// WGSL spec (`compile::layout::HostLayout`).
pub fn reflect_stage(
    module: &Module,
    entry_point: &str,
    alignment: &dyn Fn(Handle<Type>) -> u32,
) -> StageReflection {
    let mut layouter = Layouter::default();
    // A module that validated always lays out; an error would leave sizes at 0, not crash.
    let _ = layouter.update(module.to_ctx());
    let layouts = Layouts { layouter, alignment };
    let mut reflection = StageReflection {
        entry_point: entry_point.to_string(),
        inputs: Vec::new(),
        outputs: Vec::new(),
        bindings: Vec::new(),
        uniform_blocks: Vec::new(),
        overrides: module.overrides.iter().map(|(_, o)| override_constant(module, o)).collect(),
        workgroup_size: None,
        workgroup_size_overrides: Vec::new(),
        workgroup_memory: 0,
        spirv_gap: None,
    };
    if let Some(entry) = module.entry_points.iter().find(|e| e.name == entry_point) {
        if entry.stage == naga::ShaderStage::Compute {
            reflection.workgroup_size = Some(entry.workgroup_size);
            if let Some(sizes) = &entry.workgroup_size_overrides {
                reflection.workgroup_size_overrides = sizes
                    .iter()
                    .map(|size| match size.map(|e| &module.global_expressions[e]) {
                        Some(naga::Expression::Override(o)) => module.overrides[*o].name.clone(),
                        _ => None,
                    })
                    .collect();
                // The pipeline's constants decide those sizes: no number stands for them.
                let given = reflection.workgroup_size_overrides.iter().map(Option::is_some);
                for (size, _) in reflection.workgroup_size.iter_mut().flatten().zip(given).filter(|(_, g)| *g)
                {
                    *size = 0;
                }
            }
            // Compaction left only what the kernel uses.
            reflection.workgroup_memory = module
                .global_variables
                .iter()
                .filter(|(_, g)| g.space == AddressSpace::WorkGroup)
                .map(|(_, g)| layouts.layouter[g.ty].size)
                .sum();
        }
        if entry.stage == naga::ShaderStage::Vertex {
            for argument in &entry.function.arguments {
                let name = argument.name.clone().unwrap_or_default();
                locations(module, argument.ty, argument.binding.as_ref(), &name, &mut reflection.inputs);
            }
        }
        if entry.stage == naga::ShaderStage::Fragment
            && let Some(result) = &entry.function.result
        {
            locations(module, result.ty, result.binding.as_ref(), "", &mut reflection.outputs);
        }
    }
    for (_, global) in module.global_variables.iter() {
        let Some(binding) = &global.binding else { continue };
        let name = global.name.clone().unwrap_or_default();
        let resource = resource(module, &layouts.layouter, global.space, global.ty);
        if let Some(block) = block(module, &layouts, global) {
            reflection.uniform_blocks.push(block);
        }
        reflection.bindings.push(BindingInfo {
            group: binding.group,
            binding: binding.binding,
            name,
            resource,
        });
    }
    reflection.bindings.sort_by_key(|b| (b.group, b.binding));
    reflection
}

/// An `override` as the manifest describes it; compaction has removed those the entry point
/// does not use.
fn override_constant(module: &Module, constant: &naga::Override) -> OverrideConstant {
    let default = constant.init.and_then(|init| match module.global_expressions[init] {
        naga::Expression::Literal(literal) => match literal {
            naga::Literal::Bool(b) => Some(f64::from(u8::from(b))),
            naga::Literal::F32(v) => Some(f64::from(v)),
            naga::Literal::F16(v) => Some(f64::from(v)),
            naga::Literal::I32(v) => Some(f64::from(v)),
            naga::Literal::U32(v) => Some(f64::from(v)),
            naga::Literal::F64(v) => Some(v),
            naga::Literal::AbstractFloat(v) => Some(v),
            _ => None,
        },
        _ => None,
    });
    OverrideConstant {
        name: constant.name.clone().unwrap_or_default(),
        id: constant.id,
        ty: override_type(module, constant.ty),
        default,
        required: constant.init.is_none(),
    }
}

/// An `override`'s scalar type (naga validates that it is a scalar; a 32-bit float stands for
/// the abstract types, which the front end has made concrete by then).
fn override_type(module: &Module, ty: Handle<Type>) -> OverrideType {
    let TypeInner::Scalar(scalar) = module.types[ty].inner else { return OverrideType::F32 };
    match (scalar.kind, scalar.width) {
        (ScalarKind::Bool, _) => OverrideType::Bool,
        (ScalarKind::Sint, 8) => OverrideType::I64,
        (ScalarKind::Sint, _) => OverrideType::I32,
        (ScalarKind::Uint, 8) => OverrideType::U64,
        (ScalarKind::Uint, _) => OverrideType::U32,
        (ScalarKind::Float, 2) => OverrideType::F16,
        (ScalarKind::Float, 8) => OverrideType::F64,
        (ScalarKind::Float | ScalarKind::AbstractFloat | ScalarKind::AbstractInt, _) => OverrideType::F32,
    }
}

/// `@location` bindings of an argument or result, flattening structs.
fn locations(
    module: &Module,
    ty: Handle<Type>,
    binding: Option<&Binding>,
    name: &str,
    out: &mut Vec<Attribute>,
) {
    match (binding, &module.types[ty].inner) {
        (Some(Binding::Location { location, .. }), _) => out.push(Attribute {
            location: *location,
            name: name.to_string(),
            format: format(&module.types[ty].inner),
        }),
        (None, TypeInner::Struct { members, .. }) => {
            for member in members {
                let member_name = member.name.clone().unwrap_or_default();
                locations(module, member.ty, member.binding.as_ref(), &member_name, out);
            }
        }
        _ => {}
    }
    out.sort_by_key(|a| a.location);
}

/// The WebGPU vertex format of a scalar or vector type (`float32x3`).
fn format(inner: &TypeInner) -> AttributeFormat {
    let (scalar, count) = match inner {
        TypeInner::Scalar(scalar) => (*scalar, 1),
        TypeInner::Vector { size, scalar } => (*scalar, *size as u32),
        _ => return AttributeFormat::Unsupported,
    };
    let kind = match scalar.kind {
        ScalarKind::Float => "float",
        ScalarKind::Sint => "sint",
        ScalarKind::Uint => "uint",
        _ => return AttributeFormat::Unsupported,
    };
    AttributeFormat::of(kind, u32::from(scalar.width) * 8, count)
}

fn resource(module: &Module, layouter: &Layouter, space: AddressSpace, ty: Handle<Type>) -> Resource {
    match (space, &module.types[ty].inner) {
        (AddressSpace::Uniform, _) => {
            Resource::Uniform { type_name: type_name(module, ty), size: layouter[ty].size }
        }
        (AddressSpace::Storage { access }, _) => Resource::Storage {
            type_name: type_name(module, ty),
            read_only: !access.contains(naga::StorageAccess::STORE),
        },
        (_, TypeInner::Sampler { comparison }) => Resource::Sampler { comparison: *comparison },
        (_, TypeInner::Image { dim, arrayed, class }) => {
            let dimension = dimension(*dim, *arrayed);
            match class {
                ImageClass::Sampled { kind, multi } => Resource::Texture {
                    dimension,
                    sample_type: match kind {
                        ScalarKind::Sint => SampleType::Sint,
                        ScalarKind::Uint => SampleType::Uint,
                        _ => SampleType::Float,
                    },
                    multisampled: *multi,
                },
                ImageClass::Depth { multi } => {
                    Resource::Texture { dimension, sample_type: SampleType::Depth, multisampled: *multi }
                }
                ImageClass::Storage { format, access } => Resource::StorageTexture {
                    dimension,
                    format: texel_format(*format),
                    access: storage_access(*access),
                },
                other => Resource::Other { description: format!("{other:?}") },
            }
        }
        (_, other) => Resource::Other { description: format!("{other:?}") },
    }
}

fn dimension(dim: ImageDimension, arrayed: bool) -> ViewDimension {
    match (dim, arrayed) {
        (ImageDimension::D1, _) => ViewDimension::D1,
        (ImageDimension::D2, false) => ViewDimension::D2,
        (ImageDimension::D2, true) => ViewDimension::D2Array,
        (ImageDimension::D3, _) => ViewDimension::D3,
        (ImageDimension::Cube, false) => ViewDimension::Cube,
        (ImageDimension::Cube, true) => ViewDimension::CubeArray,
    }
}

/// WGSL's access mode from naga's flags: `atomic` where texels are used atomically, else by
/// which of loads and stores the module may do.
fn storage_access(access: naga::StorageAccess) -> StorageAccess {
    let (load, store) =
        (access.contains(naga::StorageAccess::LOAD), access.contains(naga::StorageAccess::STORE));
    match (access.contains(naga::StorageAccess::ATOMIC), load, store) {
        (true, _, _) => StorageAccess::Atomic,
        (false, true, true) => StorageAccess::ReadWrite,
        (false, true, false) => StorageAccess::Read,
        (false, false, _) => StorageAccess::Write,
    }
}

fn texel_format(format: naga::StorageFormat) -> TexelFormat {
    use naga::StorageFormat as N;
    match format {
        N::R8Unorm => TexelFormat::R8Unorm,
        N::R8Snorm => TexelFormat::R8Snorm,
        N::R8Uint => TexelFormat::R8Uint,
        N::R8Sint => TexelFormat::R8Sint,
        N::R16Uint => TexelFormat::R16Uint,
        N::R16Sint => TexelFormat::R16Sint,
        N::R16Float => TexelFormat::R16Float,
        N::Rg8Unorm => TexelFormat::Rg8Unorm,
        N::Rg8Snorm => TexelFormat::Rg8Snorm,
        N::Rg8Uint => TexelFormat::Rg8Uint,
        N::Rg8Sint => TexelFormat::Rg8Sint,
        N::R32Uint => TexelFormat::R32Uint,
        N::R32Sint => TexelFormat::R32Sint,
        N::R32Float => TexelFormat::R32Float,
        N::Rg16Uint => TexelFormat::Rg16Uint,
        N::Rg16Sint => TexelFormat::Rg16Sint,
        N::Rg16Float => TexelFormat::Rg16Float,
        N::Rgba8Unorm => TexelFormat::Rgba8Unorm,
        N::Rgba8Snorm => TexelFormat::Rgba8Snorm,
        N::Rgba8Uint => TexelFormat::Rgba8Uint,
        N::Rgba8Sint => TexelFormat::Rgba8Sint,
        N::Bgra8Unorm => TexelFormat::Bgra8Unorm,
        N::Rgb10a2Uint => TexelFormat::Rgb10a2Uint,
        N::Rgb10a2Unorm => TexelFormat::Rgb10a2Unorm,
        N::Rg11b10Ufloat => TexelFormat::Rg11b10Ufloat,
        N::R64Uint => TexelFormat::R64Uint,
        N::Rg32Uint => TexelFormat::Rg32Uint,
        N::Rg32Sint => TexelFormat::Rg32Sint,
        N::Rg32Float => TexelFormat::Rg32Float,
        N::Rgba16Uint => TexelFormat::Rgba16Uint,
        N::Rgba16Sint => TexelFormat::Rgba16Sint,
        N::Rgba16Float => TexelFormat::Rgba16Float,
        N::Rgba32Uint => TexelFormat::Rgba32Uint,
        N::Rgba32Sint => TexelFormat::Rgba32Sint,
        N::Rgba32Float => TexelFormat::Rgba32Float,
        N::R16Unorm => TexelFormat::R16Unorm,
        N::R16Snorm => TexelFormat::R16Snorm,
        N::Rg16Unorm => TexelFormat::Rg16Unorm,
        N::Rg16Snorm => TexelFormat::Rg16Snorm,
        N::Rgba16Unorm => TexelFormat::Rgba16Unorm,
        N::Rgba16Snorm => TexelFormat::Rgba16Snorm,
    }
}

/// The WGSL spelling of a type (`array<vec4<f32>, 4>`), or a struct's name.
pub fn type_name(module: &Module, ty: Handle<Type>) -> String {
    let t = &module.types[ty];
    if let Some(name) = &t.name {
        return name.clone();
    }
    let scalar = |s: naga::Scalar| match (s.kind, s.width) {
        (ScalarKind::Float, 2) => "f16".to_string(),
        (ScalarKind::Float, 8) => "f64".to_string(),
        (ScalarKind::Float, _) => "f32".to_string(),
        (ScalarKind::Sint, 8) => "i64".to_string(),
        (ScalarKind::Sint, _) => "i32".to_string(),
        (ScalarKind::Uint, 8) => "u64".to_string(),
        (ScalarKind::Uint, _) => "u32".to_string(),
        (ScalarKind::Bool, _) => "bool".to_string(),
        (kind, width) => format!("{kind:?}{width}"),
    };
    match &t.inner {
        TypeInner::Scalar(s) => scalar(*s),
        TypeInner::Vector { size, scalar: s } => format!("vec{}<{}>", *size as u32, scalar(*s)),
        TypeInner::Matrix { columns, rows, scalar: s } => {
            format!("mat{}x{}<{}>", *columns as u32, *rows as u32, scalar(*s))
        }
        TypeInner::Array { base, size, .. } => match size {
            ArraySize::Constant(n) => format!("array<{}, {n}>", type_name(module, *base)),
            _ => format!("array<{}>", type_name(module, *base)),
        },
        TypeInner::Atomic(s) => format!("atomic<{}>", scalar(*s)),
        other => format!("{other:?}"),
    }
}
