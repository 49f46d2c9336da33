//! The generated module's prelude: the types every generated module shares (`Pass`, `Variant`,
//! `Stage`, `PassKeyword`, the strict lookup), as Rust source text written once at its top.

/// The types every generated module shares, written once at its top.
pub(super) const PRELUDE: &str = r#"#[cfg(target_endian = "big")]
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

/// A pass's keyword type, its keywords as constants and its pass: one line per pass in each
/// shader's module, so the types cost little of the module's size.
macro_rules! pass_keywords {
    ($ty:ident, $pass:ident, $($constant:ident = $name:literal),*) => {
        /// A keyword of the pass: `super::variant(&[...])` looks up its variants.
        #[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
        pub struct $ty(&'static str);

        impl $ty {
            $(pub const $constant: $ty = $ty($name);)*
        }

        impl super::PassKeyword for $ty {
            fn pass() -> &'static super::Pass {
                &$pass
            }
            fn name(self) -> &'static str {
                self.0
            }
        }
    };
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
