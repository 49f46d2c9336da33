//! A project: finding and loading its files, and running the stages over them for the CLI and
//! build scripts, one module per operation (as cargo's `ops`): `workspace` finds and loads,
//! `jobs` builds, checks, merges, watches and lists, `variant` preprocesses and reflects one
//! variant, `materials` writes material files. Files are read here and through
//! [`SourceStore`](crate::source::SourceStore) only (stages get file ids, never paths); the build's outputs are written by `crate::store` and
//! `crate::orchestrate`.

mod jobs;
mod materials;
mod variant;
mod workspace;

pub use crate::config::Request;
pub use crate::orchestrate::{Cancel, Part};
pub use jobs::{
    Checked, build_part, build_project, check_project, list_project, merge_shards, preview_build,
    user_cache_dir, watch_build,
};
pub use materials::{apply_preset, config_folder_above, new_material, project_of};
pub use variant::{VariantRequest, preprocess_variant, reflect_variant};
pub use workspace::{
    SHADER_EXTENSIONS, Workspace, default_project, find_files, include_config, load_error, load_files,
    open_workspace,
};

use crate::keywords::VariantError;
use crate::source::LoadError;
use std::path::PathBuf;

/// Host failures: what was asked for cannot be read at all.
#[derive(Debug, thiserror::Error)]
// Each variant's fields are named in its message.
#[allow(missing_docs)]
#[non_exhaustive]
pub enum ProjectError {
    #[error("`{0}` does not exist")]
    NotFound(PathBuf),
    #[error("cannot walk `{path}`: {message}")]
    Walk { path: PathBuf, message: String },
    #[error("{0}")]
    Load(#[from] LoadError),
    #[error("`{shader}` has no pass {}", selector.as_ref().map_or("with a program".to_string(), |s| format!("`{s}`")))]
    PassNotFound { shader: String, selector: Option<String> },
    #[error(
        "the pass's program is {language}: only WGSL, HLSL and Cg programs are preprocessed and compiled"
    )]
    NotCompiled { language: &'static str },
    #[error(transparent)]
    Variant(#[from] VariantError),
    #[error("no shader named `{name}` in the project at `{}`{}", project.display(), suggestion.as_ref().map(|s| format!(" (did you mean `{s}`?)")).unwrap_or_else(|| " (pass `--project` to look elsewhere)".into()))]
    ShaderNotFound { name: String, suggestion: Option<String>, project: PathBuf },
    #[error("unknown preset `{0}`: presets are Opaque, Clip, Fade and Transparent")]
    UnknownPreset(String),
    #[error("preset `{preset}` is not offered for `{shader}`: it has no `_PremulAlpha` property")]
    PresetNotOffered { preset: &'static str, shader: String },
    #[error("`{0}` already exists; use `kiln material preset` to change it")]
    Exists(PathBuf),
    #[error("`{path}` is not a valid material: {message}")]
    NotAMaterial { path: PathBuf, message: String },
    #[error("cannot write `{path}`: {source}")]
    Write { path: PathBuf, source: std::io::Error },
    #[error("`{}` is not a .shader or .compute file: give the shader that holds the pass", .0.display())]
    NotAShader(PathBuf),
    #[error("cannot merge: {0}")]
    Shards(#[from] crate::orchestrate::shard::ShardError),
}
