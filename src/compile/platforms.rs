//! Metal, DX12 and GL: a validated stage module written through naga's MSL, HLSL and GLSL
//! writers with the options wgpu 30's back ends give them, so that what would fail on a Mac, on
//! Windows or in a browser fails in CI instead (docs/backends.md).
//!
//! Resource slots are numbered as wgpu numbers them, per kind in (group, binding) order, from the
//! resources the module itself uses: a module's bytes depend on its own declarations only, as its
//! cache key says.

use crate::manifest::Backend;
use naga::valid::{Capabilities, ModuleInfo, ValidationFlags, Validator};
use naga::{AddressSpace, ImageClass, ResourceBinding, ShaderStage, StorageAccess, TypeInner};
use std::borrow::Cow;

/// The Metal Shading Language version written: macOS 12 and iOS 15 have it.
pub const MSL_VERSION: (u8, u8) = (2, 4);
/// The HLSL shader model written: what D3D12's FXC compiles, and DXC too.
pub const HLSL_SHADER_MODEL: naga::back::hlsl::ShaderModel = naga::back::hlsl::ShaderModel::V5_1;
/// The GLSL written: ES 3.00, what WebGL2 has and wgpu's GL back end needs at least.
pub const GLSL_VERSION: naga::back::glsl::Version =
    naga::back::glsl::Version::Embedded { version: 300, is_webgl: false };

/// Why a back end has no text for a module.
pub(super) enum Refusal {
    /// The module uses what the language does not have (GLSL ES 3.00's storage buffers), in
    /// words.
    Lacks(String),
    /// naga's writer failed on a module naga validated: a gap in naga's back end.
    Writer(String),
}

/// A module in one of the three languages.
pub(super) struct Text {
    pub text: String,
    /// The entry point's name in it (GLSL's is `main`; a name a language reserves is changed).
    pub entry: String,
}

/// The module's text in `backend`'s language (one of the three), for entry point `entry`.
/// `None` for a module with `override`s that lack defaults: wgpu specialises those per pipeline.
pub(super) fn write(
    backend: Backend,
    module: &naga::Module,
    info: &ModuleInfo,
    stage: ShaderStage,
    entry: &str,
    capabilities: Capabilities,
) -> Result<Option<Text>, Refusal> {
    if module.overrides.iter().any(|(_, o)| o.init.is_none()) {
        return Ok(None);
    }
    // Every other back end than WGSL needs the overrides' values in place, as wgpu gives them.
    let (module, info) = naga::back::pipeline_constants::process_overrides(
        module,
        info,
        Some((stage, entry)),
        &Default::default(),
    )
    .map_err(|e| Refusal::Writer(format!("its `override` defaults cannot be applied: {e}")))?;
    check_capabilities(backend, &module, capabilities)?;
    let slots = Slots::of(&module);
    match backend {
        Backend::Msl => msl(&module, &info, stage, entry, &slots),
        Backend::Hlsl => hlsl(&module, &info, stage, entry),
        Backend::Glsl => glsl(&module, &info, stage, entry, &slots),
        Backend::Wgsl | Backend::Spirv => Err(Refusal::Writer(format!("{backend} is not written here"))),
    }
    .map(Some)
}

/// A module that validates with everything its target allows but not with what `backend` can
/// express (64-bit floats in Metal): said in naga's words, which name the capability.
fn check_capabilities(backend: Backend, module: &naga::Module, allowed: Capabilities) -> Result<(), Refusal> {
    let supported = match backend {
        Backend::Msl => naga::back::msl::supported_capabilities(),
        Backend::Hlsl => naga::back::hlsl::supported_capabilities(),
        Backend::Glsl => naga::back::glsl::supported_capabilities(),
        Backend::Wgsl | Backend::Spirv => return Ok(()),
    };
    // The module validated with `allowed` already: only a capability the language lacks can fail.
    if supported.contains(allowed) {
        return Ok(());
    }
    let flags = ValidationFlags::all() - ValidationFlags::BINDINGS;
    match Validator::new(flags, allowed & supported).validate(module) {
        Ok(_) => Ok(()),
        Err(error) => Err(Refusal::Lacks(super::messages::validation_message(error.as_inner(), module))),
    }
}

/// The language a back end writes, as a message names it.
pub fn language(backend: Backend) -> &'static str {
    match backend {
        Backend::Wgsl => "WGSL",
        Backend::Spirv => "SPIR-V",
        Backend::Msl => "MSL 2.4 (Metal)",
        Backend::Hlsl => "HLSL shader model 5.1 (DX12)",
        Backend::Glsl => "GLSL ES 3.00 (WebGL2, wgpu's GL back end)",
    }
}

/// What kind of slot a resource takes in the APIs that number slots per kind.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum SlotKind {
    /// A `var<uniform>` block.
    Uniform,
    /// A `var<storage>` buffer; `mutable` when the stage may write it.
    Storage {
        /// The stage may write it.
        mutable: bool,
    },
    /// A sampled or depth texture.
    Texture,
    /// A storage texture; `mutable` when the stage may write it.
    StorageTexture {
        /// The stage may write it.
        mutable: bool,
    },
    /// A sampler.
    Sampler,
}

/// The resources a module uses, in (group, binding) order, each with its kind.
pub struct Slots {
    resources: Vec<(ResourceBinding, SlotKind)>,
}

impl Slots {
    /// The resources `module` declares.
    pub fn of(module: &naga::Module) -> Slots {
        let mut resources: Vec<(ResourceBinding, SlotKind)> = module
            .global_variables
            .iter()
            .filter_map(|(_, g)| Some((g.binding?, slot_kind(module, g)?)))
            .collect();
        resources.sort_by_key(|(b, _)| (b.group, b.binding));
        Slots { resources }
    }

    /// Each resource with its slot, counted apart for each class `class` puts kinds in.
    fn numbered<C: PartialEq + Copy>(
        &self,
        class: impl Fn(SlotKind) -> C,
    ) -> Vec<(ResourceBinding, SlotKind, u32)> {
        let mut counts: Vec<(C, u32)> = Vec::new();
        self.resources
            .iter()
            .map(|&(binding, kind)| {
                let slot = match counts.iter_mut().find(|(c, _)| *c == class(kind)) {
                    Some((_, count)) => count,
                    None => {
                        counts.push((class(kind), 0));
                        &mut counts.last_mut().expect("just pushed").1
                    }
                };
                let at = *slot;
                *slot += 1;
                (binding, kind, at)
            })
            .collect()
    }

    /// Metal's slots: buffers numbered together, textures (sampled and storage) together,
    /// samplers.
    fn metal(&self) -> Vec<(ResourceBinding, SlotKind, u32)> {
        self.numbered(|kind| match kind {
            SlotKind::Uniform | SlotKind::Storage { .. } => 0,
            SlotKind::Texture | SlotKind::StorageTexture { .. } => 1,
            SlotKind::Sampler => 2,
        })
    }

    /// GL's slots: each of the five kinds numbered apart, as wgpu's GL back end binds them.
    fn gl(&self) -> Vec<(ResourceBinding, SlotKind, u32)> {
        self.numbered(|kind| std::mem::discriminant(&kind))
    }
}

fn slot_kind(module: &naga::Module, global: &naga::GlobalVariable) -> Option<SlotKind> {
    let mut ty = &module.types[global.ty].inner;
    if let TypeInner::BindingArray { base, .. } = ty {
        ty = &module.types[*base].inner;
    }
    match global.space {
        AddressSpace::Uniform => Some(SlotKind::Uniform),
        AddressSpace::Storage { access } => {
            Some(SlotKind::Storage { mutable: access.contains(StorageAccess::STORE) })
        }
        AddressSpace::Handle => match ty {
            TypeInner::Sampler { .. } => Some(SlotKind::Sampler),
            TypeInner::Image { class: ImageClass::Storage { access, .. }, .. } => {
                Some(SlotKind::StorageTexture { mutable: access.contains(StorageAccess::STORE) })
            }
            TypeInner::Image { .. } => Some(SlotKind::Texture),
            _ => None,
        },
        _ => None,
    }
}

fn msl(
    module: &naga::Module,
    info: &ModuleInfo,
    stage: ShaderStage,
    entry: &str,
    slots: &Slots,
) -> Result<Text, Refusal> {
    use naga::back::msl;
    let mut resources = msl::EntryPointResources::default();
    let mut storage = false;
    let metal = slots.metal();
    for &(binding, kind, slot) in &metal {
        let slot = slot as u8;
        let mut target = msl::BindTarget::default();
        match kind {
            SlotKind::Uniform => target.buffer = Some(slot),
            SlotKind::Storage { mutable } => {
                target.buffer = Some(slot);
                target.mutable = mutable;
                storage = true;
            }
            SlotKind::Texture => target.texture = Some(slot),
            SlotKind::StorageTexture { mutable } => {
                target.texture = Some(slot);
                target.mutable = mutable;
            }
            SlotKind::Sampler => target.sampler = Some(msl::BindSamplerTarget::Resource(slot)),
        }
        resources.resources.insert(binding, target);
    }
    // wgpu passes storage buffers' sizes, and immediate data, in buffers after the bound ones.
    let buffers =
        metal.iter().filter(|(_, kind, _)| matches!(kind, SlotKind::Uniform | SlotKind::Storage { .. }));
    let mut next = buffers.count() as u8;
    if storage {
        resources.sizes_buffer = Some(next);
        next += 1;
    }
    if module.global_variables.iter().any(|(_, g)| g.space == AddressSpace::Immediate) {
        resources.immediates_buffer = Some(next);
    }
    let options = msl::Options {
        lang_version: MSL_VERSION,
        per_entry_point_map: msl::EntryPointResourceMap::from([(entry.to_string(), resources)]),
        fake_missing_bindings: false,
        ..msl::Options::default()
    };
    let pipeline = msl::PipelineOptions {
        entry_point: Some((stage, entry.to_string())),
        ..msl::PipelineOptions::default()
    };
    msl::write_string(module, info, &options, &pipeline)
        .map(|(text, written)| Text { text, entry: written_entry(written.entry_point_names, entry) })
        .map_err(|e| Refusal::Writer(e.to_string()))
}

/// The entry point's name as a writer gives it, or as it was.
fn written_entry<E>(names: Vec<Result<String, E>>, entry: &str) -> String {
    names.into_iter().next().and_then(Result::ok).unwrap_or_else(|| entry.to_string())
}

fn hlsl(module: &naga::Module, info: &ModuleInfo, stage: ShaderStage, entry: &str) -> Result<Text, Refusal> {
    use naga::back::hlsl;
    // Each `@group` a register space, each `@binding` its register: naga's own mapping. Immediate
    // data is a root constant in the space after the last group's (wgpu gives it a space apart).
    let spaces = module.global_variables.iter().filter_map(|(_, g)| Some(g.binding.as_ref()?.group + 1));
    let immediates_target = Some(hlsl::BindTarget {
        space: spaces.max().unwrap_or(0).min(u8::MAX.into()) as u8,
        ..hlsl::BindTarget::default()
    });
    let options =
        hlsl::Options { shader_model: HLSL_SHADER_MODEL, immediates_target, ..hlsl::Options::default() };
    let pipeline = hlsl::PipelineOptions { entry_point: Some((stage, entry.to_string())) };
    let mut text = String::new();
    let written = hlsl::Writer::new(&mut text, &options, &pipeline)
        .write(module, info, None)
        .map_err(|e| Refusal::Writer(e.to_string()))?;
    Ok(Text { text, entry: written_entry(written.entry_point_names, entry) })
}

fn glsl(
    module: &naga::Module,
    info: &ModuleInfo,
    stage: ShaderStage,
    entry: &str,
    slots: &Slots,
) -> Result<Text, Refusal> {
    use naga::back::glsl;
    // naga's GLSL writer lets `sample_mask` through to ES 3.00, where `gl_SampleMaskIn` does not
    // exist (glslang refuses what it writes); said here, in words.
    if uses_builtin(module, naga::BuiltIn::SampleMask) {
        return Err(Refusal::Lacks("`sample_mask`".to_string()));
    }
    if let Some(gap) = glsl_layout_gap(module) {
        return Err(Refusal::Lacks(gap));
    }
    let options = glsl::Options {
        version: GLSL_VERSION,
        writer_flags: glsl::WriterFlags::ADJUST_COORDINATE_SPACE | glsl::WriterFlags::FORCE_POINT_SIZE,
        binding_map: slots.gl().into_iter().map(|(b, _, slot)| (b, slot as u8)).collect(),
        zero_initialize_workgroup_memory: true,
    };
    let pipeline =
        glsl::PipelineOptions { shader_stage: stage, entry_point: entry.to_string(), multiview: None };
    let mut text = String::new();
    let policies = naga::proc::BoundsCheckPolicies::default();
    let written = glsl::Writer::new(&mut text, module, info, &options, &pipeline, policies)
        .and_then(|mut writer| writer.write().map(|_| ()));
    match written {
        Ok(()) => Ok(Text { text, entry: "main".to_string() }),
        Err(glsl::Error::MissingFeatures(missing)) => Err(Refusal::Lacks(glsl_features(missing))),
        Err(glsl::Error::UnsupportedScalar(scalar)) => Err(Refusal::Lacks(format!(
            "{}-bit {}",
            scalar.width * 8,
            match scalar.kind {
                naga::ScalarKind::Float | naga::ScalarKind::AbstractFloat => "floats",
                _ => "integers",
            }
        ))),
        Err(e) => Err(Refusal::Writer(e.to_string())),
    }
}

/// A struct member of a uniform or storage block that GLSL would put elsewhere: GLSL lays a block's
/// members out one after another by std140 (uniform) or std430 (storage) rules, GLSL ES has no
/// `layout(offset)`, and naga's GLSL writer writes no padding, so a member placed further on by
/// `@size` or `@align` is read from the wrong bytes on GL. Found by the layout round trip on wgpu's
/// GL back end (tests/it/layouts.rs), as `0xabababab` read where a value was written.
fn glsl_layout_gap(module: &naga::Module) -> Option<String> {
    let mut layouter = naga::proc::Layouter::default();
    layouter.update(module.to_ctx()).ok()?;
    let mut seen = std::collections::HashSet::new();
    let mut pending: Vec<(naga::Handle<naga::Type>, bool)> = module
        .global_variables
        .iter()
        .filter_map(|(_, g)| match g.space {
            AddressSpace::Uniform => Some((g.ty, true)),
            AddressSpace::Storage { .. } => Some((g.ty, false)),
            _ => None,
        })
        .collect();
    while let Some((ty, uniform)) = pending.pop() {
        if !seen.insert((ty, uniform)) {
            continue;
        }
        match &module.types[ty].inner {
            TypeInner::Array { base, .. } | TypeInner::BindingArray { base, .. } => {
                pending.push((*base, uniform))
            }
            TypeInner::Struct { members, .. } => {
                let mut end: u32 = 0;
                let mut after_aggregate = false;
                let name = |n: &Option<String>| n.clone().unwrap_or_else(|| "?".to_string());
                for member in members {
                    if uniform && two_row_matrix(module, member.ty) {
                        return Some(format!(
                            "a two-row matrix in a uniform block (`{}.{}`): std140 gives each of its columns 16 bytes, \
                             WGSL 8, and naga's GLSL writer keeps std140's, so wgpu's GL back end reads it from the wrong bytes",
                            name(&module.types[ty].name),
                            name(&member.name),
                        ));
                    }
                    let mut align = layouter[member.ty].alignment.round_up(1);
                    let aggregate = matches!(
                        module.types[member.ty].inner,
                        TypeInner::Struct { .. } | TypeInner::Array { .. }
                    );
                    if uniform && aggregate {
                        align = align.max(16);
                    }
                    // std140 starts the member after a struct or an array on a 16-byte boundary.
                    let start = if uniform && after_aggregate { end.next_multiple_of(16) } else { end };
                    let natural = start.next_multiple_of(align);
                    if member.offset != natural {
                        return Some(format!(
                            "explicit member offsets (`{}.{}` is at byte {}, where GLSL's {} layout puts it at {natural}; GLSL ES has no \
                             `layout(offset)` and naga writes no padding, so wgpu's GL back end reads it from the wrong bytes)",
                            name(&module.types[ty].name),
                            name(&member.name),
                            member.offset,
                            if uniform { "std140" } else { "std430" },
                        ));
                    }
                    end = member.offset + layouter[member.ty].size;
                    after_aggregate = aggregate;
                    pending.push((member.ty, uniform));
                }
            }
            _ => {}
        }
    }
    None
}

/// Whether `ty` is a matrix of two-component columns, or an array of them.
fn two_row_matrix(module: &naga::Module, ty: naga::Handle<naga::Type>) -> bool {
    match &module.types[ty].inner {
        TypeInner::Matrix { rows, .. } => *rows == naga::VectorSize::Bi,
        TypeInner::Array { base, .. } => two_row_matrix(module, *base),
        _ => false,
    }
}

/// Whether an entry point of `module` takes or gives `builtin`.
fn uses_builtin(module: &naga::Module, builtin: naga::BuiltIn) -> bool {
    let is =
        |binding: Option<&naga::Binding>| matches!(binding, Some(naga::Binding::BuiltIn(b)) if *b == builtin);
    let in_type = |ty: naga::Handle<naga::Type>| match &module.types[ty].inner {
        TypeInner::Struct { members, .. } => members.iter().any(|m| is(m.binding.as_ref())),
        _ => false,
    };
    module.entry_points.iter().any(|e| {
        let arguments = e.function.arguments.iter().any(|a| is(a.binding.as_ref()) || in_type(a.ty));
        let result = e.function.result.as_ref().is_some_and(|r| is(r.binding.as_ref()) || in_type(r.ty));
        arguments || result
    })
}

/// GLSL features a module needs, in words.
fn glsl_features(missing: naga::back::glsl::Features) -> String {
    use naga::back::glsl::Features as F;
    let named: &[(F, &str)] = &[
        (F::BUFFER_STORAGE, "storage buffers (`var<storage>`)"),
        (F::COMPUTE_SHADER, "compute shaders"),
        (F::IMAGE_LOAD_STORE, "storage textures"),
        (F::ARRAY_OF_ARRAYS, "arrays of arrays"),
        (F::DOUBLE_TYPE, "64-bit floats"),
        (F::MULTISAMPLED_TEXTURES, "multisampled textures"),
        (F::CUBE_TEXTURES_ARRAY, "cube texture arrays"),
        (F::SAMPLE_VARIABLES, "`sample_index` and `sample_mask`"),
        (F::SAMPLE_QUALIFIER, "`@interpolate(..., sample)`"),
        (F::NOPERSPECTIVE_QUALIFIER, "`@interpolate(linear)`"),
        (F::DUAL_SOURCE_BLENDING, "dual-source blending (`@blend_src`)"),
        (F::TEXTURE_SAMPLES, "`textureNumSamples`"),
        (F::TEXTURE_LEVELS, "`textureNumLevels`"),
        (F::IMAGE_SIZE, "`textureDimensions` of a storage texture"),
        (F::DYNAMIC_ARRAY_SIZE, "runtime-sized arrays"),
        (F::CLIP_DISTANCE, "`clip_distances`"),
        (F::TEXTURE_ATOMICS, "texture atomics"),
        (F::SUBGROUP_OPERATIONS, "subgroup operations"),
    ];
    let mut words: Vec<Cow<str>> =
        named.iter().filter(|(f, _)| missing.contains(*f)).map(|(_, w)| Cow::Borrowed(*w)).collect();
    let rest = named.iter().fold(missing, |rest, (f, _)| rest - *f);
    words.extend(rest.iter_names().map(|(name, _)| Cow::Owned(name.to_lowercase().replace('_', " "))));
    words.join(", ")
}
