//! A pass's keyword sets as the manifest records them: each `#pragma` set with its kind, scope
//! and stage, closed sets that the compiler's pragma reader uses too.

use super::ShaderStage;
use serde::{Deserialize, Serialize};

closed_set! {
    /// How a keyword set makes variants.
    KeywordKind {
        /// Every keyword of the set is built.
        MultiCompile = "multi_compile",
        /// Only the keywords materials use are built.
        ShaderFeature = "shader_feature",
        /// No variants: the keyword is a run-time 0/1 the shader branches on.
        DynamicBranch = "dynamic_branch",
    }
}

closed_set! {
    /// Whether a keyword is global to the project or local to its shader (`_local`).
    KeywordScope {
        /// Counts toward the project's global keywords.
        Global = "global",
        /// `_local`: the shader's own.
        Local = "local",
    }
}

closed_set! {
    /// The stage a keyword affects (`_vertex`, `_fragment`, ...); `All` when no suffix is given.
    KeywordStage {
        /// Both stages see it.
        All = "all",
        /// `_vertex`: only the vertex stage.
        Vertex = "vertex",
        /// `_fragment`: only the fragment stage.
        Fragment = "fragment",
        /// `_geometry` (no WGSL stage).
        Geometry = "geometry",
        /// `_hull` (no WGSL stage).
        Hull = "hull",
        /// `_domain` (no WGSL stage).
        Domain = "domain",
        /// `_raytracing` (no WGSL stage).
        RayTracing = "raytracing",
    }
}

impl KeywordStage {
    /// Whether a module of `stage` sees the set's keywords (a `_fragment` set is not seen by the
    /// vertex stage, nor by a kernel).
    pub fn includes(self, stage: ShaderStage) -> bool {
        match self {
            KeywordStage::All => true,
            KeywordStage::Vertex => stage == ShaderStage::Vertex,
            KeywordStage::Fragment => stage == ShaderStage::Fragment,
            KeywordStage::Geometry | KeywordStage::Hull | KeywordStage::Domain | KeywordStage::RayTracing => {
                false
            }
        }
    }
}

/// One keyword set of a pass (`#pragma multi_compile _ _FOG`), as declared.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct KeywordSetManifest {
    /// How it makes variants.
    pub kind: KeywordKind,
    /// Global or local.
    pub scope: KeywordScope,
    /// The stages that see it.
    pub stage: KeywordStage,
    /// `_` is the all-off choice.
    pub keywords: Vec<String>,
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_stage_suffix_limits_the_modules_that_see_its_keywords() {
        for stage in [ShaderStage::Vertex, ShaderStage::Fragment, ShaderStage::Compute] {
            assert!(KeywordStage::All.includes(stage));
            assert_eq!(KeywordStage::Vertex.includes(stage), stage == ShaderStage::Vertex);
            assert_eq!(KeywordStage::Fragment.includes(stage), stage == ShaderStage::Fragment);
            assert!(!KeywordStage::Hull.includes(stage));
        }
        let set: KeywordSetManifest = serde_json::from_str(
            r#"{"kind": "dynamic_branch", "scope": "local", "stage": "fragment", "keywords": ["_", "_FOG"]}"#,
        )
        .expect("the manifest's names");
        assert_eq!(
            (set.kind, set.scope, set.stage),
            (KeywordKind::DynamicBranch, KeywordScope::Local, KeywordStage::Fragment)
        );
        assert!(serde_json::from_str::<KeywordKind>(r#""dynamic""#).is_err());
    }
}
