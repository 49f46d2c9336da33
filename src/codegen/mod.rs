//! The Rust module generated for build scripts (`kiln_shaders.rs`): every built variant's WGSL
//! and SPIR-V, strict variant lookup, the bind group layout of each pass, and a `#[repr(C)]`
//! bytemuck struct for every uniform block with compile-time assertions of its size and of every
//! member's offset, all from the manifest.
//!
//! Its size follows passes and distinct modules, not variants times bytes: each pack is embedded
//! once (`include_str!`, `include_bytes!`), each module is a row of numbers (its interface and
//! its ranges of the packs), and each variant a sorted key and two module indices.

mod handles;
mod layout;
mod names;

pub use names::NameClash;

use crate::manifest::{
    Backend, Manifest, ModuleFile, OverrideType, PassManifest, PerBackend, ShaderManifest, ShaderStage,
};
use crate::reflect::Resource;
use names::{Case, PRELUDE_NAMES, Scope, doc_text, string_literal};
use std::collections::BTreeMap;
use std::fmt::Write as _;

/// The types every generated module shares, written once at its top.
const PRELUDE: &str = r#"#[cfg(target_endian = "big")]
compile_error!("kiln embeds SPIR-V as little-endian words");

/// The structs below pad with byte arrays and hold WGSL arrays of any length, for which bytemuck
/// derives `Pod` with its `min_const_generics` feature. Without it this names what to add:
/// `bytemuck = { version = "1", features = ["derive", "min_const_generics"] }`.
const _: fn() = || {
    fn bytemuck_needs_its_min_const_generics_feature<T: ::bytemuck::Pod>() {}
    bytemuck_needs_its_min_const_generics_feature::<[u8; 33]>();
};

/// Bytes aligned for reading as `u32` words.
#[repr(C, align(4))]
struct Aligned<B: ?Sized>(B);

/// A module row: its interface, then (pack, start, end) of its WGSL and of its SPIR-V (`NONE`
/// for a backend not written).
type ModuleRow = [u32; 7];

/// No module, no pack.
const NONE: u32 = u32::MAX;

/// A stage's interface: modules of a pass that differ only in their code share one.
#[derive(Debug)]
#[allow(dead_code)]
struct Interface {
    entry_point: &'static str,
    inputs: &'static [(u32, &'static str)],
    outputs: &'static [(u32, &'static str)],
    workgroup_size: [u32; 3],
}

/// One stage module of a variant.
#[derive(Debug, Clone, Copy)]
#[allow(dead_code)]
pub struct Stage {
    pub entry_point: &'static str,
    pub wgsl: &'static str,
    pub spirv: &'static [u32],
    /// Vertex stage: `(location, format)` of each attribute, formats as WebGPU names them.
    pub inputs: &'static [(u32, &'static str)],
    /// Fragment stage: `(location, format)` of each colour target.
    pub outputs: &'static [(u32, &'static str)],
    /// A compute kernel's `@workgroup_size` (zeros for render stages).
    pub workgroup_size: [u32; 3],
    /// Its index among the pass's modules: variants with the same index share the module.
    pub module: usize,
}

/// A built variant of a pass.
#[derive(Clone, Copy)]
#[allow(dead_code)]
pub struct Variant {
    pub pass: &'static Pass,
    /// Its index among the pass's variants (sorted by key).
    pub index: usize,
    pub vertex: Option<Stage>,
    pub fragment: Option<Stage>,
}

#[allow(dead_code)]
impl Variant {
    /// Its keywords, in the pass's keyword order.
    pub fn keywords(&self) -> Vec<&'static str> {
        self.pass.keywords_of(self.index)
    }

    /// Its key: bit i stands for `pass.keywords[i]` (the manifest's order), in words of 64 bits.
    pub fn key(&self) -> &'static [u64] {
        self.pass.key(self.index)
    }

    /// A compute shader's kernel of this variant, by name (`None`: no such kernel, or it failed).
    pub fn kernel(&self, name: &str) -> Option<Stage> {
        let k = self.pass.kernels.iter().position(|n| *n == name)?;
        self.pass.stage(self.pass.kernel_modules[self.index * self.pass.kernels.len() + k])
    }
}

impl ::core::fmt::Debug for Variant {
    fn fmt(&self, f: &mut ::core::fmt::Formatter<'_>) -> ::core::fmt::Result {
        f.debug_struct("Variant")
            .field("shader", &self.pass.shader)
            .field("pass", &self.pass.index)
            .field("keywords", &self.keywords())
            .field("vertex", &self.vertex)
            .field("fragment", &self.fragment)
            .finish()
    }
}

/// What a binding holds.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
#[allow(dead_code)]
pub enum BindingKind {
    Uniform { size: u64 },
    Storage { read_only: bool },
    Texture { dimension: &'static str, sample_type: &'static str, multisampled: bool },
    StorageTexture { dimension: &'static str, format: &'static str, access: &'static str },
    Sampler { comparison: bool },
}

/// One entry of a pass's bind group layout (the same for all of its variants).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
#[allow(dead_code)]
pub struct BindingEntry {
    pub group: u32,
    pub binding: u32,
    pub name: &'static str,
    pub vertex: bool,
    pub fragment: bool,
    pub kind: BindingKind,
}

#[allow(dead_code)]
pub struct Pass {
    pub shader: &'static str,
    pub index: usize,
    pub name: Option<&'static str>,
    /// Every variant keyword the pass declares; bit i of a variant key stands for `keywords[i]`.
    pub keywords: &'static [&'static str],
    /// A compute shader's kernels (`#pragma kernel`), in order.
    pub kernels: &'static [&'static str],
    /// Its `dynamic_branch` keywords: `bool` `override` constants of its modules (set to 1 or 0
    /// when a pipeline is created), never part of a variant.
    pub dynamic_keywords: &'static [&'static str],
    pub layout: &'static [BindingEntry],
    interfaces: &'static [Interface],
    modules: &'static [ModuleRow],
    /// `u64` words per variant key.
    key_words: usize,
    /// The variants' keys, `key_words` words each, sorted.
    keys: &'static [u64],
    /// Each variant's vertex and fragment module.
    variants: &'static [[u32; 2]],
    /// A compute shader's variants' kernel modules, `kernels.len()` per variant.
    kernel_modules: &'static [u32],
}

impl ::core::fmt::Debug for Pass {
    fn fmt(&self, f: &mut ::core::fmt::Formatter<'_>) -> ::core::fmt::Result {
        f.debug_struct("Pass")
            .field("shader", &self.shader)
            .field("index", &self.index)
            .field("name", &self.name)
            .field("variants", &self.variants.len())
            .finish()
    }
}

/// A keyword combination that was not built: no closest match is ever substituted.
#[derive(Debug, Clone, PartialEq, Eq)]
#[allow(dead_code)]
pub struct MissingVariant {
    pub shader: &'static str,
    pub pass: usize,
    pub requested: Vec<String>,
    /// Requested keywords the pass does not declare at all.
    pub undeclared: Vec<String>,
    /// The keywords of every variant that was built.
    pub built: Vec<Vec<&'static str>>,
}

impl ::core::fmt::Display for MissingVariant {
    fn fmt(&self, f: &mut ::core::fmt::Formatter<'_>) -> ::core::fmt::Result {
        const SHOWN: usize = 8;
        write!(f, "`{}` pass {} has no variant with keywords [{}]", self.shader, self.pass, self.requested.join(" "))?;
        if !self.undeclared.is_empty() {
            write!(f, "; the pass declares no keyword {}", self.undeclared.join(", "))?;
        }
        let built: Vec<String> = self.built.iter().take(SHOWN).map(|k| format!("[{}]", k.join(" "))).collect();
        write!(f, "; built: {}", built.join(", "))?;
        if self.built.len() > SHOWN {
            write!(f, " and {} more", self.built.len() - SHOWN)?;
        }
        write!(f, " (add a material that uses it, or the shader to `always_include`)")
    }
}

impl ::std::error::Error for MissingVariant {}

/// A pass's own keyword type (`PassNKeyword` in each shader's module), which names its pass: a
/// lookup through it ([`variant`]) takes that pass's keywords and no other's.
pub trait PassKeyword: Copy {
    /// The pass whose keywords these are.
    fn pass() -> &'static Pass;
    /// The keyword as the shader writes it.
    fn name(self) -> &'static str;
}

/// The variant of the keywords' pass with exactly these keywords (in any order), as
/// [`Pass::variant`]: `variant(&[custom_rp_lit::Pass0Keyword::_CLIPPING])`. A keyword of another
/// pass does not compile.
#[allow(dead_code)]
pub fn variant<K: PassKeyword>(keywords: &[K]) -> Result<Variant, MissingVariant> {
    K::pass().find(keywords.iter().map(|k| k.name()))
}

#[allow(dead_code)]
impl Pass {
    /// The variant with exactly these keywords (in any order), or an error naming what is missing.
    /// `dynamic_branch` keywords among them choose no variant.
    pub fn variant(&'static self, keywords: &[&str]) -> Result<Variant, MissingVariant> {
        self.find(keywords.iter().copied())
    }

    fn find<'k>(&'static self, keywords: impl Iterator<Item = &'k str> + Clone) -> Result<Variant, MissingVariant> {
        let mut key = vec![0u64; self.key_words];
        let mut undeclared = Vec::new();
        for keyword in keywords.clone().filter(|k| !self.dynamic_keywords.contains(k)) {
            match self.keywords.iter().position(|k| *k == keyword) {
                Some(bit) => key[bit / 64] |= 1 << (bit % 64),
                None => undeclared.push(keyword.to_string()),
            }
        }
        if undeclared.is_empty() {
            let (mut low, mut high) = (0, self.variants.len());
            while low < high {
                let middle = (low + high) / 2;
                match self.key(middle).cmp(&key[..]) {
                    ::core::cmp::Ordering::Less => low = middle + 1,
                    ::core::cmp::Ordering::Greater => high = middle,
                    ::core::cmp::Ordering::Equal => return Ok(self.variant_at(middle)),
                }
            }
        }
        let mut requested: Vec<String> = keywords.map(str::to_string).collect();
        requested.sort_unstable();
        requested.dedup();
        undeclared.sort_unstable();
        undeclared.dedup();
        Err(MissingVariant {
            shader: self.shader,
            pass: self.index,
            requested,
            undeclared,
            built: (0..self.variants.len()).map(|v| self.keywords_of(v)).collect(),
        })
    }

    /// Every built variant, in key order.
    pub fn variants(&'static self) -> impl Iterator<Item = Variant> {
        (0..self.variants.len()).map(move |v| self.variant_at(v))
    }

    fn key(&self, variant: usize) -> &'static [u64] {
        &self.keys[variant * self.key_words..(variant + 1) * self.key_words]
    }

    fn keywords_of(&self, variant: usize) -> Vec<&'static str> {
        let key = self.key(variant);
        (0..self.keywords.len()).filter(|&bit| key[bit / 64] & (1 << (bit % 64)) != 0).map(|bit| self.keywords[bit]).collect()
    }

    fn variant_at(&'static self, variant: usize) -> Variant {
        let [vertex, fragment] = self.variants[variant].map(|m| self.stage(m));
        Variant { pass: self, index: variant, vertex, fragment }
    }

    fn stage(&self, module: u32) -> Option<Stage> {
        let row = self.modules.get(module as usize)?;
        let interface = &self.interfaces[row[0] as usize];
        let wgsl = match row[1] {
            NONE => "",
            pack => &WGSL_PACKS[pack as usize][row[2] as usize..row[3] as usize],
        };
        let spirv: &'static [u32] = match row[4] {
            NONE => &[],
            pack => ::bytemuck::cast_slice(&SPIRV_PACKS[pack as usize].0[row[5] as usize..row[6] as usize]),
        };
        Some(Stage {
            entry_point: interface.entry_point,
            wgsl,
            spirv,
            inputs: interface.inputs,
            outputs: interface.outputs,
            workgroup_size: interface.workgroup_size,
            module: module as usize,
        })
    }
}
"#;

/// The generated module's text. `packs_folder` is the output folder as seen from the generated
/// file's folder (`kiln` for `OUT_DIR/kiln`), so the module embeds packs by relative paths and
/// stays the same wherever the build happens. Every name from the project enters the text through
/// `names`; names that would become one identifier are refused, each clash once.
pub fn generate(manifest: &Manifest, packs_folder: &str) -> Result<String, Vec<NameClash>> {
    let mut out = String::new();
    let _ = writeln!(
        out,
        "// Generated by kiln {}: do not edit. Rebuilt when the shaders change.\n",
        manifest.kiln_version
    );
    out.push_str(PRELUDE);
    let _ = writeln!(
        out,
        "\n/// The bind groups kiln gives every pass's resources, by how often they change: bind the\n\
         /// per-frame buffers at `FRAME_GROUP`, a material at `MATERIAL_GROUP`, per-draw ones at\n\
         /// `OBJECT_GROUP`.\n\
         pub const FRAME_GROUP: u32 = {};\npub const MATERIAL_GROUP: u32 = {};\npub const OBJECT_GROUP: u32 = {};",
        crate::manifest::FRAME_GROUP,
        crate::manifest::MATERIAL_GROUP,
        crate::manifest::OBJECT_GROUP
    );
    // Each pack once, numbered in path order; modules are ranges of them.
    let mut packs: PerBackend<BTreeMap<&str, u32>> = Default::default();
    for pass in manifest.passes() {
        for module in &pass.modules {
            for &backend in Backend::ALL {
                if let Some(path) = module.file(backend).and_then(|f| pass.packs.get(f.pack)) {
                    packs[backend].insert(path, 0);
                }
            }
        }
    }
    for numbered in packs.values_mut() {
        for (n, index) in numbered.values_mut().enumerate() {
            *index = n as u32;
        }
    }
    let include = |path: &str| string_literal(&format!("{packs_folder}/{path}"));
    for (backend, numbered) in packs.iter() {
        let (name, element, include_pack, _) = embedding(backend);
        if backend != Backend::ALL[0] {
            out.push_str("];\n");
        }
        let doc = match backend {
            Backend::Wgsl => "Every WGSL pack: a pass's compiled modules, concatenated.",
            Backend::Spirv => "Every SPIR-V pack, aligned so that its modules read as words.",
        };
        let _ = writeln!(out, "\n/// {doc}\nstatic {name}: [{element}; {}] = [", numbered.len());
        for path in numbered.keys() {
            let _ = writeln!(out, "    {},", include_pack.replace("{}", &include(path)));
        }
    }
    out.push_str("];\n");
    let _ = writeln!(
        out,
        "\n/// The build's manifest and materials, for `kiln::runtime::Library::embedded`.\n\
         pub static MANIFEST_JSON: &str = include_str!({});\npub static MATERIALS_JSON: &str = include_str!({});",
        include(crate::manifest::FILE_NAME),
        include(crate::manifest::MATERIALS_FILE)
    );
    let _ = writeln!(out, "\n/// Every pack by its path in the manifest.");
    let count: usize = packs.values().map(BTreeMap::len).sum();
    let _ = writeln!(out, "pub static PACKS: [(&str, &[u8]); {count}] = [");
    for (backend, numbered) in packs.iter() {
        let (_, _, _, bytes) = embedding(backend);
        for (n, path) in numbered.keys().enumerate() {
            let _ =
                writeln!(out, "    ({}, {}),", string_literal(path), bytes.replace("{n}", &n.to_string()));
        }
    }
    out.push_str("];\n");
    let mut top = Scope::new("the top level", PRELUDE_NAMES);
    let mut clashes = Vec::new();
    for shader in &manifest.shaders {
        let place = format!("shader `{}` in `{}`", shader.name, shader.file);
        let module = top.claim(&shader.name, Case::Snake, &place);
        clashes.extend(shader_module(&mut out, shader, &module, &place, &packs));
    }
    clashes.extend(top.clashes);
    // Two names that clash as one item clash as the items made from it too (a kernel's constant
    // and its workgroup size): said once.
    let mut said = std::collections::HashSet::new();
    clashes.retain(|c| said.insert((c.first.0.clone(), c.second.0.clone())));
    if clashes.is_empty() { Ok(out) } else { Err(clashes) }
}

/// A variant as the generated module lists it: its key, its vertex and fragment modules, and a
/// compute pass's kernel modules.
type VariantRow<'a> = (Vec<u64>, [Option<usize>; 2], &'a [Option<usize>]);

/// The generated module's pack numbers, WGSL and SPIR-V, by path.
type PackNumbers<'a> = PerBackend<BTreeMap<&'a str, u32>>;

/// How the generated module embeds a back end's packs: the static's name, its element type, a
/// pack's inclusion (`{}` its path) and pack `{n}` as bytes.
fn embedding(backend: Backend) -> (&'static str, &'static str, &'static str, &'static str) {
    match backend {
        Backend::Wgsl => ("WGSL_PACKS", "&str", "include_str!({})", "WGSL_PACKS[{n}].as_bytes()"),
        Backend::Spirv => {
            ("SPIRV_PACKS", "&Aligned<[u8]>", "&Aligned(*include_bytes!({}))", "&SPIRV_PACKS[{n}].0")
        }
    }
}

/// A shader's module, named `module` (the shader, for messages: `place`); returns the names that
/// clash inside it.
fn shader_module(
    out: &mut String,
    shader: &ShaderManifest,
    module: &str,
    place: &str,
    packs: &PackNumbers,
) -> Vec<NameClash> {
    let _ = writeln!(out, "\n/// `{}` ({})", doc_text(&shader.name), doc_text(&shader.file));
    let _ = writeln!(
        out,
        "#[allow(non_snake_case, non_camel_case_types, non_upper_case_globals, dead_code, clippy::all)]"
    );
    let _ = writeln!(out, "pub mod {module} {{");
    let _ = writeln!(out, "    pub const NAME: &str = {};", string_literal(&shader.name));
    let mut scope = Scope::new(format!("module `{module}`"), PRELUDE_NAMES);
    for pass in &shader.passes {
        scope.reserve(&format!("PASS_{}", pass.index));
        scope.reserve(&format!("Pass{}Overrides", pass.index));
        scope.reserve(&format!("Pass{}Keyword", pass.index));
    }
    let mut clashes = handles::handles(out, shader, module, &mut scope, place);
    for pass in &shader.passes {
        clashes.extend(pass_static(out, pass, packs, module, &mut scope, place));
    }
    layout::uniform_structs(out, shader, &mut scope, place);
    clashes.extend(scope.clashes);
    out.push_str("}\n");
    clashes
}

fn pass_static(
    out: &mut String,
    pass: &PassManifest,
    packs: &PackNumbers,
    module: &str,
    scope: &mut Scope,
    place: &str,
) -> Vec<NameClash> {
    let quoted = |names: &[String]| names.iter().map(|k| string_literal(k)).collect::<Vec<_>>().join(", ");
    let _ = writeln!(
        out,
        "\n    /// Pass {}{}.",
        pass.index,
        pass.name.as_ref().map(|n| format!(" `{}`", doc_text(n))).unwrap_or_default()
    );
    let _ = writeln!(out, "    pub static PASS_{}: super::Pass = super::Pass {{", pass.index);
    let name = pass.name.as_ref().map_or("None".to_string(), |n| format!("Some({})", string_literal(n)));
    let _ = writeln!(out, "        shader: NAME,\n        index: {},\n        name: {name},", pass.index);
    let _ = writeln!(out, "        keywords: &[{}],", quoted(&pass.keywords));
    let _ = writeln!(out, "        kernels: &[{}],", quoted(&pass.kernels));
    let dynamic: Vec<String> =
        pass.dynamic_sets().flat_map(|set| &set.keywords).filter(|k| *k != "_").cloned().collect();
    let _ = writeln!(out, "        dynamic_keywords: &[{}],", quoted(&dynamic));
    out.push_str("        layout: &[\n");
    for group in &pass.layout {
        for entry in &group.entries {
            let kind = match &entry.resource {
                Resource::Uniform { size, .. } => format!("Uniform {{ size: {size} }}"),
                Resource::Storage { read_only, .. } => format!("Storage {{ read_only: {read_only} }}"),
                Resource::Texture { dimension, sample_type, multisampled } => format!(
                    "Texture {{ dimension: {:?}, sample_type: {:?}, multisampled: {multisampled} }}",
                    dimension.name(),
                    sample_type.name()
                ),
                Resource::StorageTexture { dimension, format, access } => format!(
                    "StorageTexture {{ dimension: {:?}, format: {:?}, access: {:?} }}",
                    dimension.name(),
                    format.name(),
                    access.name()
                ),
                Resource::Sampler { comparison } => format!("Sampler {{ comparison: {comparison} }}"),
                Resource::Other { description } => {
                    let _ = writeln!(out, "            // Unsupported: {}.", doc_text(description));
                    "Uniform { size: 0 }".to_string()
                }
            };
            let _ = writeln!(
                out,
                "            super::BindingEntry {{ group: {}, binding: {}, name: {}, vertex: {}, fragment: {}, kind: super::BindingKind::{kind} }},",
                group.group,
                entry.binding,
                string_literal(&entry.name),
                entry.visibility.contains(&ShaderStage::Vertex),
                entry.visibility.contains(&ShaderStage::Fragment),
            );
        }
    }
    out.push_str("        ],\n        interfaces: &[\n");
    let pairs = |attributes: &[crate::reflect::Attribute]| {
        attributes
            .iter()
            .map(|a| format!("({}, {})", a.location, string_literal(&a.format)))
            .collect::<Vec<_>>()
            .join(", ")
    };
    for interface in &pass.interfaces {
        let _ = writeln!(
            out,
            "            super::Interface {{ entry_point: {}, inputs: &[{}], outputs: &[{}], workgroup_size: {:?} }},",
            string_literal(&interface.entry_point),
            pairs(&interface.inputs),
            pairs(&interface.outputs),
            interface.workgroup_size.unwrap_or_default()
        );
    }
    out.push_str("        ],\n        modules: &[\n");
    let range = |backend: Backend, file: Option<&ModuleFile>| {
        let number = file.and_then(|f| packs[backend].get(pass.packs.get(f.pack)?.as_str()));
        match (file, number) {
            (Some(f), Some(pack)) => format!("{pack}, {}, {}", f.offset, f.offset + f.size),
            _ => "super::NONE, 0, 0".to_string(),
        }
    };
    for module in &pass.modules {
        let ranges: Vec<String> = Backend::ALL.iter().map(|&b| range(b, module.file(b))).collect();
        let _ = writeln!(out, "            [{}, {}],", module.interface, ranges.join(", "));
    }
    // Variants sorted by key, for binary search.
    let words = pass.keywords.len().div_ceil(64);
    let mut rows: Vec<VariantRow> = pass
        .variants
        .iter()
        .map(|variant| {
            let mut key = vec![0u64; words];
            for keyword in &variant.keywords {
                if let Some(bit) = pass.keywords.iter().position(|k| k == keyword) {
                    key[bit / 64] |= 1 << (bit % 64);
                }
            }
            (key, [variant.vertex, variant.fragment], variant.kernels.as_slice())
        })
        .collect();
    rows.sort();
    let _ = writeln!(out, "        ],\n        key_words: {words},\n        keys: &[");
    // A pass without keywords has keys of no words: its one variant is found by an empty key.
    for (key, ..) in rows.iter().filter(|(key, ..)| !key.is_empty()) {
        let words: Vec<String> = key.iter().map(|w| format!("{w:#x}")).collect();
        let _ = writeln!(out, "            {},", words.join(", "));
    }
    out.push_str("        ],\n        variants: &[\n");
    let index = |m: Option<usize>| m.map_or("super::NONE".to_string(), |m| m.to_string());
    for (_, [vertex, fragment], _) in &rows {
        let _ = writeln!(out, "            [{}, {}],", index(*vertex), index(*fragment));
    }
    out.push_str("        ],\n        kernel_modules: &[\n");
    for (.., kernels) in rows.iter().filter(|(.., kernels)| !kernels.is_empty()) {
        let modules: Vec<String> = kernels.iter().map(|m| index(*m)).collect();
        let _ = writeln!(out, "            {},", modules.join(", "));
    }
    out.push_str("        ],\n    };\n");
    handles::kernel_constants(out, pass, scope, place);
    let mut clashes = handles::pass_keywords(out, pass, module, place);
    clashes.extend(overrides_struct(out, pass, place));
    clashes
}

/// `PassNOverrides`: the pass's own `override` constants (its `dynamic_branch` keywords are set
/// through keywords), typed, with their defaults, and the list a pipeline takes.
fn overrides_struct(out: &mut String, pass: &PassManifest, place: &str) -> Vec<NameClash> {
    let mut constants: Vec<&crate::manifest::OverrideConstant> = Vec::new();
    for constant in pass.interfaces.iter().flat_map(|i| &i.overrides) {
        if !pass.is_dynamic(&constant.name) && !constants.iter().any(|c| c.name == constant.name) {
            constants.push(constant);
        }
    }
    if constants.is_empty() {
        return Vec::new();
    }
    let rust_type = |ty: OverrideType| match ty {
        OverrideType::Bool => "bool",
        OverrideType::I32 => "i32",
        OverrideType::U32 => "u32",
        // wgpu sets every constant from an f64; the struct holds floats as the renderer writes them.
        OverrideType::I64 | OverrideType::U64 | OverrideType::F16 | OverrideType::F32 | OverrideType::F64 => {
            "f32"
        }
    };
    let name = format!("Pass{}Overrides", pass.index);
    let mut fields = Scope::new(format!("struct `{name}`"), &[]);
    let constants: Vec<(&crate::manifest::OverrideConstant, String)> = constants
        .into_iter()
        .map(|c| (c, fields.claim(&c.name, Case::AsIs, &format!("an `override` of {place}"))))
        .collect();
    let _ = writeln!(
        out,
        "\n    /// The `override` constants of pass {}'s modules (`f16` ones as `f32`), for\n    \
         /// `PipelineRequest::overrides` or wgpu's `PipelineCompilationOptions::constants`.",
        pass.index
    );
    let _ = writeln!(out, "    #[derive(Debug, Clone, Copy, PartialEq)]\n    pub struct {name} {{");
    for (c, field) in &constants {
        let _ = writeln!(out, "        pub {field}: {},", rust_type(c.ty));
    }
    out.push_str("    }\n");
    let literal = |c: &crate::manifest::OverrideConstant, value: f64| match rust_type(c.ty) {
        "bool" => (value != 0.0).to_string(),
        "i32" | "u32" => format!("{value}"),
        _ => format!("{value:?}_f32"),
    };
    let defaults: Option<Vec<String>> =
        constants.iter().map(|(c, field)| c.default.map(|v| format!("{field}: {}", literal(c, v)))).collect();
    // Only constants that all have defaults make a `Default`: a required one must be chosen.
    if let Some(defaults) = defaults {
        let _ = writeln!(
            out,
            "    impl Default for {name} {{\n        fn default() -> Self {{\n            Self {{ {} }}\n        }}\n    }}",
            defaults.join(", ")
        );
    }
    let values: Vec<String> = constants
        .iter()
        .map(|(c, field)| {
            let value = match c.ty {
                OverrideType::Bool => format!("f64::from(u8::from(self.{field}))"),
                _ => format!("f64::from(self.{field})"),
            };
            format!("({}, {value})", string_literal(&c.key()))
        })
        .collect();
    let _ = writeln!(
        out,
        "    impl {name} {{\n        /// `(name or id, value)` of each constant.\n        \
         pub fn constants(&self) -> [(&'static str, f64); {}] {{\n            [{}]\n        }}\n    }}",
        values.len(),
        values.join(", ")
    );
    fields.clashes
}
