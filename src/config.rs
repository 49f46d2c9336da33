//! `kiln.toml`: where a project's shaders, materials and includes are, and what a build emits.
//! Every field has a default, so a folder of `.shader` and `.mat` files needs no file at all.

use crate::diagnostics::Diagnostic;
pub use crate::manifest::Backend;
use crate::source::{FileId, SourceStore, Span};
use serde::Deserialize;
use std::path::PathBuf;

/// The project file's name, looked for in the project folder.
pub const FILE_NAME: &str = "kiln.toml";

/// `kiln.toml`: a project's settings (docs/project.md), every field defaulted.
#[derive(Debug, Clone, PartialEq, Deserialize)]
#[serde(default, deny_unknown_fields)]
pub struct ProjectConfig {
    /// Folders searched for `.shader` files, relative to the project folder.
    pub shaders: Vec<PathBuf>,
    /// Folders searched for `.mat` files.
    pub materials: Vec<PathBuf>,
    /// Folders `#include` searches after the including file's own folder.
    pub include_paths: Vec<PathBuf>,
    /// Where builds write their output.
    pub output: PathBuf,
    /// The back ends each stage module is written for (default: both).
    pub backends: Vec<Backend>,
    /// Shaders built with every variant, whether or not a material uses them (by shader name).
    pub always_include: Vec<String>,
    /// The renderer's global keyword state, when it is known (a scene's light setup, say): each
    /// `multi_compile` set is then built only with the option these choose (docs/keywords.md).
    /// Unset: every option of every set.
    pub global_keywords: Option<Vec<toml::Spanned<String>>>,
    /// Warnings count as errors.
    pub strict: bool,
    /// Variant usage logs (JSON Lines, as `kiln_runtime::UsageLog` writes them): the variants
    /// they name are built besides those the materials use.
    pub variant_logs: Vec<PathBuf>,
    /// A module cache shared between builds and machines (docs/scaling.md).
    pub cache_dir: Option<PathBuf>,
    /// The team's cache on an HTTP server, `http://host:port/prefix` (docs/scaling.md).
    pub remote_cache: Option<toml::Spanned<String>>,
    /// What builds may do with it: `read`, `write` (read and publish; the default) or `off`.
    pub remote_cache_mode: Option<crate::store::remote::RemoteMode>,
    /// The variants of each compute shader to build (`[compute.NAME]`), which no material
    /// selects (docs/compute.md).
    pub compute: std::collections::BTreeMap<String, ComputeConfig>,
    /// Resource names the project binds per frame or per object, besides kiln's own
    /// (`[bind_groups]`, docs/project.md).
    pub bind_groups: BindGroupsConfig,
}

/// `[bind_groups]`: names added to the per-frame (0) and per-object (2) groups.
#[derive(Debug, Clone, Default, PartialEq, Deserialize)]
#[serde(default, deny_unknown_fields)]
pub struct BindGroupsConfig {
    /// Bound once per frame, in group 0 (kiln's own: `UnityPerFrame`, `_CustomLight`).
    pub per_frame: Vec<toml::Spanned<String>>,
    /// Bound once per object, in group 2 (kiln's own: `UnityPerDraw`).
    pub per_object: Vec<toml::Spanned<String>>,
}

/// `[compute.NAME]`: which variants of a compute shader are built.
#[derive(Debug, Clone, PartialEq, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct ComputeConfig {
    /// `"all"`, or a list of keyword lists (`[[], ["_SQUARE"]]`), each one variant.
    pub variants: ComputeVariants,
}

/// A compute shader's variants: every one, or those listed.
#[derive(Debug, Clone, PartialEq)]
pub enum ComputeVariants {
    /// `"all"`: every variant, as `always_include` builds a shader.
    All,
    /// Keyword lists, each choosing one variant as a usage log line does.
    Listed(Vec<toml::Spanned<Vec<String>>>),
}

// By hand, not `untagged`: the lists keep their places in the file (`toml::Spanned`).
impl<'de> Deserialize<'de> for ComputeVariants {
    fn deserialize<D: serde::Deserializer<'de>>(deserializer: D) -> Result<ComputeVariants, D::Error> {
        struct Visitor;
        impl<'de> serde::de::Visitor<'de> for Visitor {
            type Value = ComputeVariants;
            fn expecting(&self, f: &mut std::fmt::Formatter) -> std::fmt::Result {
                f.write_str(r#""all", or a list of keyword lists such as [[], ["_SQUARE"]]"#)
            }
            fn visit_str<E: serde::de::Error>(self, word: &str) -> Result<ComputeVariants, E> {
                match word {
                    "all" => Ok(ComputeVariants::All),
                    _ => Err(E::invalid_value(serde::de::Unexpected::Str(word), &self)),
                }
            }
            fn visit_seq<A: serde::de::SeqAccess<'de>>(
                self,
                mut seq: A,
            ) -> Result<ComputeVariants, A::Error> {
                let mut lists = Vec::new();
                while let Some(list) = seq.next_element()? {
                    lists.push(list);
                }
                Ok(ComputeVariants::Listed(lists))
            }
        }
        deserializer.deserialize_any(Visitor)
    }
}

impl Default for ProjectConfig {
    fn default() -> ProjectConfig {
        ProjectConfig {
            shaders: vec![PathBuf::from(".")],
            materials: vec![PathBuf::from(".")],
            include_paths: Vec::new(),
            output: PathBuf::from("build/kiln"),
            backends: Backend::DEFAULT.to_vec(),
            always_include: Vec::new(),
            global_keywords: None,
            strict: false,
            variant_logs: Vec::new(),
            cache_dir: None,
            remote_cache: None,
            remote_cache_mode: None,
            compute: Default::default(),
            bind_groups: Default::default(),
        }
    }
}

/// Reads a loaded `kiln.toml`; a malformed one is reported and the defaults are used.
pub fn parse_config(store: &SourceStore, file: FileId) -> (ProjectConfig, Vec<Diagnostic>) {
    match toml::from_str(store.text(file)) {
        Ok(config) => (config, Vec::new()),
        Err(error) => {
            let span = Span::new(file, error.span().unwrap_or(0..0));
            let message = error.message().trim().trim_end_matches('.').to_string();
            // serde lists the fields after an unknown one; said once, in the help, with the closest.
            let (message, unknown) = match message.split_once(", expected one of") {
                Some((head, _)) => {
                    let field = head.strip_prefix("unknown field `").and_then(|f| f.strip_suffix('`'));
                    (head.to_string(), field.map(str::to_string))
                }
                None => (message, None),
            };
            let suggestion = unknown
                .and_then(|field| crate::diagnostics::closest(&field, FIELDS.iter().copied()))
                .map(|near| format!("did you mean `{near}`? "))
                .unwrap_or_default();
            let diagnostic = Diagnostic::error("K0003", "invalid `kiln.toml`")
                .at(span, message)
                .help(format!("{suggestion}fields are {} (docs/project.md)", FIELDS.join(", ")));
            (ProjectConfig::default(), vec![diagnostic])
        }
    }
}

/// The fields of `kiln.toml`, as a message lists them.
const FIELDS: &[&str] = &[
    "shaders",
    "materials",
    "include_paths",
    "output",
    "backends",
    "always_include",
    "global_keywords",
    "strict",
    "variant_logs",
    "cache_dir",
    "remote_cache",
    "remote_cache_mode",
    "compute",
    "bind_groups",
];
