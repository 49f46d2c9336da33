//! Pipeline-overridable constants: the values a pipeline's stages are specialised with, from the
//! request's `dynamic_branch` keywords and the renderer's own `override` values, checked against
//! what each stage module declares.

use super::RuntimeError;
use kiln_manifest::{KeywordSetManifest, PassManifest, StageView};

/// Each stage's constants (in the order the stages were given), by the key a pipeline sets them
/// by, sorted.
pub(super) type StageConstants = Vec<Vec<(String, f64)>>;

/// What the constants are worked out for: names for errors, the pass, the request.
pub(super) struct ConstantRequest<'a> {
    pub shader: &'a str,
    pub pass: &'a PassManifest,
    /// The `dynamic_branch` keywords on, at most one of each set ([`super::Library::variant_id`]).
    pub keywords: &'a [&'a str],
    pub overrides: &'a [(&'a str, f64)],
}

/// The constants each stage is created with: a `dynamic_branch` keyword is 1 when the request
/// turns it on (or it is its set's default), else 0, in the stages its set is for; every other
/// override the module uses takes the request's value, or its default.
pub(super) fn stage_constants(
    request: &ConstantRequest,
    stages: &[Option<StageView>],
) -> Result<StageConstants, RuntimeError> {
    let (shader, pass) = (request.shader, request.pass.index);
    let declared = || stages.iter().flatten().flat_map(|s| &s.interface.overrides);
    for &(name, value) in request.overrides {
        let found = declared().find(|o| o.key() == name && !request.pass.is_dynamic(&o.name));
        let Some(constant) = found else {
            let names = declared().filter(|o| !request.pass.is_dynamic(&o.name)).map(|o| o.name.as_str());
            return Err(RuntimeError::UnknownOverride {
                shader: shader.to_string(),
                pass,
                name: name.to_string(),
                keyword: request.pass.is_dynamic(name),
                suggestion: kiln_manifest::closest(name, names),
            });
        };
        if !constant.accepts(value) {
            return Err(RuntimeError::OverrideValue {
                shader: shader.to_string(),
                pass,
                name: name.to_string(),
                ty: constant.ty,
                value,
            });
        }
    }
    // Each dynamic set with the keyword it has on (the request's, else its default).
    let mut chosen: Vec<(&KeywordSetManifest, Option<&str>)> = Vec::new();
    for set in request.pass.dynamic_sets() {
        let requested = request.keywords.iter().copied().find(|k| set.keywords.iter().any(|s| s == k));
        let default = || set.keywords.first().filter(|_| !set.keywords.iter().any(|k| k == "_"));
        chosen.push((set, requested.or_else(|| default().map(String::as_str))));
    }
    let mut constants: StageConstants = vec![Vec::new(); stages.len()];
    for (stage, constants) in stages.iter().zip(&mut constants) {
        let Some(stage) = stage else { continue };
        for constant in &stage.interface.overrides {
            let value = match chosen.iter().find(|(set, _)| set.keywords.contains(&constant.name)) {
                // A `_fragment` keyword keeps its default in the vertex stage, as Unity's does.
                Some((set, _)) if !set.stage.includes(stage.interface.stage) => continue,
                Some((_, on)) => Some(f64::from(u8::from(*on == Some(constant.name.as_str())))),
                None => {
                    request.overrides.iter().rev().find(|(key, _)| *key == constant.key()).map(|&(_, v)| v)
                }
            };
            match value {
                Some(value) => constants.push((constant.key(), value)),
                None if constant.required => {
                    return Err(RuntimeError::OverrideRequired {
                        shader: shader.to_string(),
                        pass,
                        name: constant.name.clone(),
                        ty: constant.ty,
                    });
                }
                None => {}
            }
        }
        constants.sort_by(|a, b| a.0.cmp(&b.0));
    }
    Ok(constants)
}
