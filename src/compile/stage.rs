//! One stage module: a parsed variant text, bound to its pass layout, cut down to its entry
//! point, validated with what its target allows, and written as WGSL and SPIR-V.

use super::bind::{self, PassLayout};
use super::gaps;
use super::glslang::{Glslang, Reading};
use super::layout;
use super::panics::contain_panics;
use super::platforms::{self, Refusal};
use super::target::Allowed;
use super::{Mapper, validate};
use crate::diagnostics::Diagnostic;
use crate::manifest::{Backend, PerBackend};
use crate::preprocess::{SourceMap, Stage};
use crate::reflect::{StageReflection, reflect_stage};
use crate::shaderlab::ast::ProgramLanguage;
use crate::source::Span;
use naga::valid::ValidationFlags;

/// What a stage module compiles to: its bytes for each back end written.
pub(crate) struct StageOutput {
    pub modules: PerBackend<Option<Vec<u8>>>,
    pub reflection: StageReflection,
}

pub(crate) struct StageRequest<'a> {
    /// The program's language: an HLSL or Cg module was read from glslang's SPIR-V, with its
    /// layout already decided and spans no source map knows.
    pub language: ProgramLanguage,
    /// The preprocessed text, for locating declarations naga gives no span for.
    pub text: &'a str,
    pub stage: Stage,
    pub entry: &'a str,
    /// The `#pragma vertex`/`fragment` naming the entry point, for "not found" errors.
    pub entry_pragma: Span,
    pub allowed: &'a Allowed,
    pub layout: &'a PassLayout,
    pub backends: &'a [Backend],
    /// Reads back the GLSL and HLSL written (`kiln check`, where it is installed).
    pub glslang: Option<&'a Glslang>,
    /// The module is already its entry point's alone, compacted (cut out of a parse together,
    /// `compile::together`, or read from glslang's SPIR-V of one entry point, which
    /// `compile::hlsl` compacts): binding it leaves nothing to compact.
    pub compacted: bool,
}

pub(crate) fn naga_stage(stage: Stage) -> naga::ShaderStage {
    match stage {
        Stage::Vertex => naga::ShaderStage::Vertex,
        Stage::Fragment => naga::ShaderStage::Fragment,
        Stage::Compute => naga::ShaderStage::Compute,
    }
}

/// Compiles one stage module. A panic inside naga (or kiln) becomes a diagnostic for this module
/// (K0416), so one bad module never takes the build down.
pub(crate) fn compile(
    module: naga::Module,
    request: &StageRequest,
    mapper: &Mapper,
) -> Result<StageOutput, Diagnostic> {
    contain_panics(|| compile_unguarded(module, request, mapper)).unwrap_or_else(|panic| {
        Err(Diagnostic::error(
            "K0416",
            format!("internal error while compiling the {} stage: {}", request.stage.name(), panic.message),
        )
        .at(request.entry_pragma, "compiling this entry point")
        .note(format!("the panic was at {}", panic.location))
        .note(
            "this is a bug in naga or kiln, not in the shader; please report it with this variant's \
             `kiln preprocess` output (naga: https://github.com/gfx-rs/wgpu/issues)",
        ))
    })
}

/// Faults for the tests of what no valid input reaches: debug builds fail while compiling the
/// entry point an environment variable names (`KILN_INJECT_PANIC` panics, for
/// [`contain_panics`]; `KILN_INJECT_BACKEND_ERROR` makes the WGSL writer fail, K0409;
/// `KILN_INJECT_GLSLANG_ERROR` spoils the GLSL and HLSL glslang reads, K0423).
fn injected(variable: &str, entry: &str) -> bool {
    cfg!(debug_assertions) && std::env::var(variable).is_ok_and(|name| name == entry)
}

fn compile_unguarded(
    mut module: naga::Module,
    request: &StageRequest,
    mapper: &Mapper,
) -> Result<StageOutput, Diagnostic> {
    if injected("KILN_INJECT_PANIC", request.entry) {
        panic!("fault injected by KILN_INJECT_PANIC");
    }
    // A module read from SPIR-V has its spans in the SPIR-V: what naga says of it is placed at
    // the entry point's pragma ([`located`]), not through the text's map.
    static UNMAPPED: std::sync::LazyLock<SourceMap> = std::sync::LazyLock::new(SourceMap::default);
    let spirv_mapper = Mapper { map: &UNMAPPED, store: mapper.store };
    let (host, mapper) = match request.language {
        ProgramLanguage::Wgsl => (layout::correct(&mut module, request.text, mapper)?, mapper),
        _ => (layout::from_offsets(&module), &spirv_mapper),
    };
    let stage = naga_stage(request.stage);
    if !module.entry_points.iter().any(|e| e.name == request.entry && e.stage == stage) {
        let other = module.entry_points.iter().find(|e| e.name == request.entry);
        let d = Diagnostic::error(
            "K0403",
            format!("{} entry point `{}` not found", request.stage.name(), request.entry),
        )
        .at(request.entry_pragma, "named here");
        return Err(match other {
            Some(e) => d.help(format!(
                "`{}` is a {} entry point; mark it `@{}`",
                e.name,
                format!("{:?}", e.stage).to_lowercase(),
                request.stage.name()
            )),
            None => match closest_function(&module, request.entry) {
                // The function is there, unmarked: as Unity's HLSL needs no mark, every user
                // coming from it meets this first.
                Some(name) if name == request.entry => {
                    let stage = request.stage.name();
                    let unmarked =
                        module.functions.iter().find(|(_, f)| f.name.as_deref() == Some(request.entry));
                    let place = unmarked
                        .and_then(|(handle, _)| module.functions.get_span(handle).to_range())
                        // `fn NAME`, not the whole body.
                        .map(|range| {
                            range.start..range.end.min(range.start + "fn ".len() + request.entry.len())
                        })
                        .and_then(|range| mapper.map.map_range(range));
                    let mut d = match place {
                        Some(origin) => d.label(origin.span, format!("this function has no `@{stage}`")),
                        None => d,
                    };
                    d.message = format!(
                        "`{}` is a function, not a {stage} entry point: it lacks `@{stage}`",
                        request.entry
                    );
                    d.note(format!(
                        "in WGSL the function itself is marked as an entry point: `#pragma {stage}` names it, `@{stage}` makes it one"
                    ))
                    .help(format!("mark it: `@{stage} fn {}(...)`", request.entry))
                }
                Some(name) => d.help(format!("did you mean `{name}`?")),
                None => d.help(format!(
                    "define `@{} fn {}(...)` in the program or its includes",
                    request.stage.name(),
                    request.entry
                )),
            },
        });
    }
    bind::apply(&mut module, request.layout);
    let info =
        keep_entry_point(&mut module, request, stage, mapper).map_err(|d| located(d, request, mapper))?;
    check_limits(&module, request, mapper)?;
    check_override_defaults(&module, request.text, mapper)?;

    if injected("KILN_INJECT_BACKEND_ERROR", request.entry) {
        return Err(backend_error("WGSL", "fault injected by KILN_INJECT_BACKEND_ERROR".into()));
    }
    let mut modules = PerBackend::default();
    let mut spirv_gap = None;
    for &backend in request.backends {
        match write(backend, &module, &info, request, &host)? {
            Written::Module(bytes) => modules[backend] = Some(bytes),
            Written::Gap(gap) => spirv_gap = Some(gap),
            Written::Nothing => {}
        }
    }
    // A module that would ship nothing is an error: WGSL-only is the fallback, not an outcome.
    if let (true, Some(gap)) = (modules.values().all(Option::is_none), &spirv_gap) {
        let d = Diagnostic::error("K0415", format!("no SPIR-V for `{}`: {gap}", request.entry))
            .at(request.entry_pragma, "compiling this entry point")
            .help("add `wgsl` to `backends` in kiln.toml to ship this module as WGSL");
        return Err(d);
    }
    let mut reflection = reflect_stage(&module, request.entry, &|ty| host.alignment(&module, ty));
    reflection.spirv_gap = spirv_gap;
    Ok(StageOutput { modules, reflection })
}

/// What a back end's writer gives for a module.
enum Written {
    Module(Vec<u8>),
    /// SPIR-V that naga cannot write right: the module ships without it (K0415).
    Gap(crate::reflect::SpirvGap),
    /// Nothing, by design: naga's SPIR-V writer cannot express specialisation constants (nor can
    /// MSL, HLSL or GLSL), so a module with `override`s is WGSL only, specialised by wgpu when a
    /// pipeline is made.
    Nothing,
}

/// A validated module in one back end's form.
fn write(
    backend: Backend,
    module: &naga::Module,
    info: &naga::valid::ModuleInfo,
    request: &StageRequest,
    host: &layout::HostLayout,
) -> Result<Written, Diagnostic> {
    let capabilities = request.allowed.capabilities();
    match backend {
        Backend::Wgsl => {
            Ok(Written::Module(super::wgsl::write(module, info, capabilities, host)?.into_bytes()))
        }
        Backend::Spirv if !module.overrides.is_empty() => Ok(Written::Nothing),
        Backend::Spirv => {
            let options = naga::back::spv::Options {
                lang_version: spirv_version(capabilities),
                flags: naga::back::spv::WriterFlags::empty(),
                ..naga::back::spv::Options::default()
            };
            let pipeline = naga::back::spv::PipelineOptions {
                shader_stage: naga_stage(request.stage),
                entry_point: request.entry.to_string(),
            };
            let written = match gaps::before_writing(module) {
                Some(gap) => Err(gap),
                None => gaps::write(module, info, &options, &pipeline),
            };
            Ok(match written {
                Ok(words) => Written::Module(super::spirv::to_bytes(&super::spirv::corrected(words))),
                Err(gap) => Written::Gap(gap),
            })
        }
        Backend::Msl | Backend::Hlsl | Backend::Glsl => write_platform(backend, module, info, request),
    }
}

/// A module in Metal's, DX12's or GL's language, read back by glslang where it is asked to. A
/// module with `override`s is checked with their defaults but ships as WGSL (wgpu specialises
/// it per pipeline), as for SPIR-V.
fn write_platform(
    backend: Backend,
    module: &naga::Module,
    info: &naga::valid::ModuleInfo,
    request: &StageRequest,
) -> Result<Written, Diagnostic> {
    let language = platforms::language(backend);
    let stage = naga_stage(request.stage);
    let capabilities = request.allowed.capabilities();
    let written =
        contain_panics(|| platforms::write(backend, module, info, stage, request.entry, capabilities));
    let at = |d: Diagnostic| d.at(request.entry_pragma, "compiling this entry point");
    let mut text = match written {
        Ok(Ok(Some(text))) => text,
        Ok(Ok(None)) => return Ok(Written::Nothing),
        Ok(Err(Refusal::Lacks(words))) => {
            return Err(at(Diagnostic::error("K0422", format!("`{}` uses what {language} lacks: {words}", request.entry)))
                .help(format!("remove `{backend}` from `backends`, or keep what it lacks out of the variants that ship there (a keyword)")));
        }
        Ok(Err(Refusal::Writer(message))) => return Err(at(backend_error(language, message))),
        Err(panic) => {
            return Err(at(Diagnostic::error("K0416", format!("naga's {language} writer panicked: {}", panic.message)))
                .note(format!("the panic was at {}", panic.location))
                .note("naga validated the module, so this is a bug in naga's back end; please report it with this variant's `kiln preprocess` output (https://github.com/gfx-rs/wgpu/issues)"));
        }
    };
    if injected("KILN_INJECT_GLSLANG_ERROR", request.entry) {
        text.text.push_str("\n#error fault injected by KILN_INJECT_GLSLANG_ERROR\n");
    }
    let reading = request
        .glslang
        .filter(|_| Glslang::reads(backend))
        .map(|g| g.read(backend, stage, &text.entry, &text.text));
    match reading {
        Some(Reading::Refused(errors)) => {
            return Err(at(Diagnostic::error("K0423", format!("glslang refuses the {language} naga wrote for `{}`", request.entry)))
                .note(errors)
                .note("naga validated the module and wrote it without error: a gap in naga's writer (report it: https://github.com/gfx-rs/wgpu/issues), or, for HLSL, in glslang's HLSL front end (docs/backends.md)"));
        }
        // glslang's trouble, not the module's: the module ships unread, as without glslang.
        Some(Reading::Unread(_)) | Some(Reading::Accepted) | None => {}
    }
    Ok(if module.overrides.is_empty() { Written::Module(text.text.into_bytes()) } else { Written::Nothing })
}

/// The entry point or function of `module` whose name is within two edits of `name` (a
/// misspelt `#pragma fragment ToonFragmnt`).
fn closest_function(module: &naga::Module, name: &str) -> Option<String> {
    let entry_points = module.entry_points.iter().map(|e| e.name.as_str());
    let functions = module.functions.iter().filter_map(|(_, f)| f.name.as_deref());
    crate::diagnostics::closest(name, entry_points.chain(functions))
}

/// The SPIR-V version a module is written in: 1.0 (every Vulkan device) unless it may use 16-bit
/// floats, whose storage-buffer and interface access needs `SPV_KHR_16bit_storage`, core from 1.3
/// (Vulkan 1.1, which every device with `shader-f16` has). naga declares no extensions itself.
pub(super) fn spirv_version(capabilities: naga::valid::Capabilities) -> (u8, u8) {
    if capabilities.contains(naga::valid::Capabilities::SHADER_FLOAT16) { (1, 3) } else { (1, 0) }
}

/// Cuts a bound module down to one entry point and what it uses, then validates it.
fn keep_entry_point(
    module: &mut naga::Module,
    request: &StageRequest,
    stage: naga::ShaderStage,
    mapper: &Mapper,
) -> Result<naga::valid::ModuleInfo, Diagnostic> {
    if !request.compacted {
        module.entry_points.retain(|e| e.name == request.entry && e.stage == stage);
        naga::compact::compact(module, naga::compact::KeepUnused::No);
    }
    validate(module, ValidationFlags::all(), request.allowed.capabilities(), mapper)
}

pub(super) fn backend_error(backend: &str, message: String) -> Diagnostic {
    Diagnostic::error("K0409", format!("the {backend} writer failed: {message}"))
        .note("naga validated the module, so this is a gap in naga's back end; please report it")
}

/// Where the entry point's name is declared in the preprocessed text (`fn NAME`).
fn entry_declaration(request: &StageRequest) -> Option<std::ops::Range<usize>> {
    let needle = format!("fn {}", request.entry);
    request.text.find(&needle).map(|at| at + 3..at + needle.len())
}

/// A diagnostic naga gave no place for (an entry point's interface, say), placed at the entry
/// point's declaration, or else its pragma.
fn located(diagnostic: Diagnostic, request: &StageRequest, mapper: &Mapper) -> Diagnostic {
    if diagnostic.primary.is_some() {
        return diagnostic;
    }
    let declaration = entry_declaration(request).map(|r| (r, "in this entry point".to_string()));
    let diagnostic = mapper.diagnostic_at(diagnostic, declaration.into_iter().collect());
    if diagnostic.primary.is_some() {
        diagnostic
    } else {
        diagnostic.at(request.entry_pragma, "in this entry point")
    }
}

/// An `override` whose default is an expression (`override height = 2 * depth;`): naga's WGSL
/// writer (30) can write only literals, constants and their composites there, and panics on
/// the rest, so such a module is refused at the declaration, with the rewrite that works.
fn check_override_defaults(module: &naga::Module, text: &str, mapper: &Mapper) -> Result<(), Diagnostic> {
    use naga::Expression as E;
    // A workgroup size an expression of overrides gives (`@workgroup_size(block * 2)`).
    for entry in &module.entry_points {
        let sizes = entry.workgroup_size_overrides.iter().flatten().flatten();
        let unwritable = sizes
            .into_iter()
            .find(|&&e| !matches!(module.global_expressions[e], E::Override(_) | E::Literal(_)));
        if let Some(&size) = unwritable {
            let d = Diagnostic::error(
                "K0418",
                format!(
                    "`{}`'s `@workgroup_size` is an expression naga's WGSL writer cannot write",
                    entry.name
                ),
            )
            .help("give each size as a number or one `override` constant's name");
            let range = module.global_expressions.get_span(size).to_range();
            return Err(
                mapper.diagnostic_at(d, range.into_iter().map(|r| (r, "this size".to_string())).collect())
            );
        }
    }
    for (handle, constant) in module.overrides.iter() {
        let Some(init) = constant.init else { continue };
        let writable = matches!(
            module.global_expressions[init],
            E::Literal(_)
                | E::Constant(_)
                | E::ZeroValue(_)
                | E::Compose { .. }
                | E::Splat { .. }
                | E::Override(_)
        );
        if writable {
            continue;
        }
        let range = module.overrides.get_span(handle).to_range();
        // naga makes an unnamed `override` of an array size that is an expression of overrides.
        let d = match &constant.name {
            Some(name) => Diagnostic::error(
                "K0418",
                format!("the default of `override {name}` is an expression naga's WGSL writer cannot write"),
            )
            .help("give it a literal default (or none), and compute the value where it is used"),
            None => {
                let size = range.clone().and_then(|r| text.get(r)).unwrap_or("?");
                Diagnostic::error(
                    "K0418",
                    format!(
                        "the array size `{size}` is an expression of `override` constants, which naga's WGSL \
                         writer cannot write"
                    ),
                )
                .help("size the array by one `override` constant's name, or by a number")
            }
        };
        return Err(
            mapper.diagnostic_at(d, range.into_iter().map(|r| (r, "declared here".to_string())).collect())
        );
    }
    Ok(())
}

/// Interpolators and colour targets beyond what the variant's target allows.
fn check_limits(module: &naga::Module, request: &StageRequest, mapper: &Mapper) -> Result<(), Diagnostic> {
    let Some(entry) = module.entry_points.first() else { return Ok(()) };
    let Some(result) = &entry.function.result else { return Ok(()) };
    let mut locations = Vec::new();
    count_locations(module, result.ty, result.binding.as_ref(), &mut locations);
    let (limit, what, code, raise) = match request.stage {
        Stage::Vertex => (
            request.allowed.max_interpolators(),
            "interpolators",
            "K0404",
            "interpolators15 or interpolators32",
        ),
        Stage::Fragment => (request.allowed.max_color_targets(), "colour targets", "K0405", "mrt4 or mrt8"),
        Stage::Compute => return Ok(()),
    };
    let used = locations.len() as u32;
    if used <= limit {
        return Ok(());
    }
    let declaration = entry_declaration(request);
    let d = Diagnostic::error(
        code,
        format!("`{}` writes {used} {what}; target {} allows {limit}", request.entry, request.allowed.level),
    )
    .help(format!("raise `#pragma target`, or `#pragma require {raise}`"));
    Err(mapper.diagnostic_at(d, declaration.into_iter().map(|r| (r, "declared here".to_string())).collect()))
}

fn count_locations(
    module: &naga::Module,
    ty: naga::Handle<naga::Type>,
    binding: Option<&naga::Binding>,
    out: &mut Vec<u32>,
) {
    match (binding, &module.types[ty].inner) {
        (Some(naga::Binding::Location { location, .. }), _) => out.push(*location),
        (None, naga::TypeInner::Struct { members, .. }) => {
            for m in members {
                count_locations(module, m.ty, m.binding.as_ref(), out);
            }
        }
        _ => {}
    }
}
