//! Material files: a new `.mat` for a shader, a preset applied to one, and the project a
//! material belongs to.

use super::ProjectError;
use super::workspace::{load_files, open_workspace};
use crate::material::Preset;
use crate::shaderlab::parse_shader;
use crate::source::{LoadError, SourceStore};
use std::path::{Path, PathBuf};

/// The project a material file belongs to: the nearest folder above it with a `kiln.toml`; without
/// one (the file is optional), the current folder when the material lies under it, as for `kiln
/// build` run there, else the material's own folder.
pub fn project_of(material: &Path) -> PathBuf {
    let folder = material.parent().map(Path::to_path_buf).unwrap_or_default();
    let absolute = std::path::absolute(&folder).unwrap_or_else(|_| folder.clone());
    let current = std::env::current_dir().ok().filter(|cwd| absolute.starts_with(cwd));
    config_folder_above(material).or(current).unwrap_or(folder)
}

/// The nearest folder above `file` (absolute) that holds a `kiln.toml`.
pub fn config_folder_above(file: &Path) -> Option<PathBuf> {
    let absolute = std::path::absolute(file).ok()?;
    absolute.ancestors().skip(1).find(|a| a.join(crate::config::FILE_NAME).is_file()).map(Path::to_path_buf)
}

/// Parses the project's shaders and returns the one named `name`.
fn find_shader(
    store: &mut SourceStore,
    project: &Path,
    name: &str,
) -> Result<crate::shaderlab::ast::Shader, ProjectError> {
    let (workspace, _) = open_workspace(store, &[project.to_path_buf()])?;
    let (files, _) = load_files(store, &workspace.shaders);
    let shaders: Vec<_> = files.into_iter().filter_map(|f| parse_shader(store, f).shader).collect();
    let names = shaders.iter().map(|s| s.name.value.as_str());
    let suggestion = crate::diagnostics::closest(name, names);
    shaders.into_iter().find(|s| s.name.value == name).ok_or_else(|| ProjectError::ShaderNotFound {
        name: name.to_string(),
        suggestion,
        project: project.to_path_buf(),
    })
}

fn parse_preset(name: &str, shader: &crate::shaderlab::ast::Shader) -> Result<Preset, ProjectError> {
    let preset = Preset::parse(name).ok_or_else(|| ProjectError::UnknownPreset(name.to_string()))?;
    if !preset.offered_for(|p| shader.property(p).is_some()) {
        return Err(ProjectError::PresetNotOffered {
            preset: preset.name(),
            shader: shader.name.value.clone(),
        });
    }
    Ok(preset)
}

/// `kiln material new`: writes a material for the named shader with its defaults (and a preset).
/// Never overwrites a file.
pub fn new_material(
    path: &Path,
    shader: &str,
    preset: Option<&str>,
    project: &Path,
) -> Result<(), ProjectError> {
    if path.exists() {
        return Err(ProjectError::Exists(path.to_path_buf()));
    }
    let shader = find_shader(&mut SourceStore::new(), project, shader)?;
    let preset = preset.map(|p| parse_preset(p, &shader)).transpose()?;
    write_atomically(path, &crate::material::preset::new_material(&shader, preset))
}

/// `kiln material preset`: applies a preset to an existing material, keeping its other values
/// and comments.
pub fn apply_preset(path: &Path, preset: &str, project: &Path) -> Result<(), ProjectError> {
    let text =
        std::fs::read_to_string(path).map_err(|source| LoadError::Io { path: path.to_path_buf(), source })?;
    let not_a_material = |message: String| ProjectError::NotAMaterial { path: path.to_path_buf(), message };
    let mut document: toml_edit::DocumentMut =
        text.parse().map_err(|e: toml_edit::TomlError| not_a_material(e.message().to_string()))?;
    let name = document
        .get("shader")
        .and_then(|s| s.as_str())
        .ok_or_else(|| not_a_material("it names no `shader`".into()))?;
    let shader = find_shader(&mut SourceStore::new(), project, name)?;
    let preset = parse_preset(preset, &shader)?;
    crate::material::preset::apply(&mut document, &shader, preset);
    write_atomically(path, &document.to_string())
}

fn write_atomically(path: &Path, text: &str) -> Result<(), ProjectError> {
    crate::store::write_atomically(path, text.as_bytes())
        .map_err(|source| ProjectError::Write { path: path.to_path_buf(), source })
}
