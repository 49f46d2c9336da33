//! What a variant's `#pragma target` and `#pragma require` allow: naga capabilities, and the
//! limits kiln checks itself (interpolators between stages, colour targets).

use crate::shaderlab::pragma::{ProgramPragmas, TARGET_LEVELS};
use naga::valid::Capabilities;

/// The requirement set a variant may use.
#[derive(Debug, Clone, PartialEq, Eq, Hash)]
pub struct Allowed {
    /// The effective `#pragma target` level (`"3.5"`), for messages.
    pub level: String,
    pub features: Vec<String>,
}

impl Allowed {
    /// The target and requirements that hold for a variant with these keywords: the base
    /// `#pragma target`, raised by `#pragma target X KW...` whose keywords are all on, plus every
    /// applicable `#pragma require`.
    pub fn for_variant(pragmas: &ProgramPragmas, keywords: &[&str]) -> Allowed {
        let applies = |conditions: &[crate::source::Spanned<String>]| {
            conditions.iter().all(|k| keywords.contains(&k.value.as_str()))
        };
        let rank = |level: &str| TARGET_LEVELS.iter().position(|(l, _)| *l == level);
        let mut level = "2.5".to_string();
        for target in pragmas.targets.iter().filter(|t| applies(&t.keywords)) {
            if rank(&target.level.value) >= rank(&level) || target.keywords.is_empty() {
                level = target.level.value.clone();
            }
        }
        let mut features: Vec<String> = TARGET_LEVELS
            .iter()
            .take(rank(&level).map_or(TARGET_LEVELS.len(), |r| r + 1))
            .flat_map(|(_, features)| features.iter().map(|f| f.to_string()))
            .collect();
        for require in pragmas.requires.iter().filter(|r| applies(&r.keywords)) {
            features.extend(require.features.iter().map(|f| f.value.clone()));
        }
        features.sort();
        features.dedup();
        Allowed { level, features }
    }

    fn has(&self, feature: &str) -> bool {
        self.features.iter().any(|f| f == feature)
    }

    /// naga capabilities: WGSL's baseline, plus 16-bit floats with `native16bit`, 64-bit
    /// integers with `int64`.
    pub fn capabilities(&self) -> Capabilities {
        let mut capabilities = Capabilities::empty();
        if self.has("native16bit") {
            capabilities |= Capabilities::SHADER_FLOAT16;
        }
        if self.has("int64") {
            capabilities |= Capabilities::SHADER_INT64;
        }
        capabilities
    }

    /// The optional GPU features of [`Allowed::capabilities`], by wgpu's names.
    pub fn features(&self) -> Vec<String> {
        let capabilities = self.capabilities();
        [(Capabilities::SHADER_FLOAT16, "shader-f16"), (Capabilities::SHADER_INT64, "shader-int64")]
            .into_iter()
            .filter(|(c, _)| capabilities.contains(*c))
            .map(|(_, name)| name.to_string())
            .collect()
    }

    /// User interpolators the vertex stage may pass to the fragment stage (WebGPU allows 16).
    pub fn max_interpolators(&self) -> u32 {
        if self.has("interpolators32") {
            16
        } else if self.has("interpolators15") {
            15
        } else if self.has("interpolators10") {
            10
        } else {
            8
        }
    }

    pub fn max_color_targets(&self) -> u32 {
        if self.has("mrt8") {
            8
        } else if self.has("mrt4") {
            4
        } else {
            1
        }
    }

    /// Part of the cache key: what changes the compiled module.
    pub fn key(&self) -> String {
        format!("{}:{}", self.level, self.features.join(","))
    }
}
