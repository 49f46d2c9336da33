//! What a variant's `#pragma target` and `#pragma require` allow: naga capabilities, and the
//! limits kiln checks itself (interpolators between stages, colour targets).

use crate::manifest::GpuFeature;
use crate::shaderlab::pragma::{ProgramPragmas, TARGET_LEVELS};
use naga::valid::Capabilities;

/// `#pragma require` names that stand for naga capabilities, with the optional wgpu feature a
/// device needs for them (`None`: every WebGPU-compliant device has it, so it is granted at every
/// target anyway). The other requirement names are limits kiln checks itself (interpolators,
/// colour targets) or core WebGPU (`msaatex`: multisampled textures). docs/keywords.md.
pub const REQUIREMENT_CAPABILITIES: [(&str, Capabilities, Option<GpuFeature>); 11] = [
    ("native16bit", Capabilities::SHADER_FLOAT16, Some(GpuFeature::ShaderF16)),
    ("int64", Capabilities::SHADER_INT64, Some(GpuFeature::ShaderInt64)),
    ("cubearray", Capabilities::CUBE_ARRAY_TEXTURES, None),
    ("sampleshading", Capabilities::MULTISAMPLED_SHADING, None),
    ("msaatex", Capabilities::empty(), None),
    ("barycentrics", Capabilities::SHADER_BARYCENTRICS, Some(GpuFeature::ShaderBarycentrics)),
    ("wavebasic", Capabilities::SUBGROUP, Some(GpuFeature::Subgroup)),
    ("wavevote", Capabilities::SUBGROUP, Some(GpuFeature::Subgroup)),
    ("waveballot", Capabilities::SUBGROUP, Some(GpuFeature::Subgroup)),
    ("wavemath", Capabilities::SUBGROUP, Some(GpuFeature::Subgroup)),
    ("waveshuffle", Capabilities::SUBGROUP, Some(GpuFeature::Subgroup)),
];

/// The requirement kiln grants an ubershader for immediate data ([`GpuFeature::Immediates`]; no
/// `#pragma require` names it).
const IMMEDIATES: &str = "immediates";

/// What wgpu lets every WebGPU-compliant device's shaders use: its mapping from no optional
/// features and the compliant downlevel flags to naga capabilities.
pub fn webgpu_baseline() -> Capabilities {
    wgpu_naga_bridge::features_to_naga_capabilities(
        wgpu_types::Features::empty(),
        wgpu_types::DownlevelFlags::compliant(),
    )
}

/// The requirement set a variant may use.
#[derive(Debug, Clone, PartialEq, Eq, Hash)]
pub struct Allowed {
    /// The effective `#pragma target` level (`"3.5"`), for messages.
    pub level: String,
    /// The wgpu features the variant needs (`shader-f16`, ...).
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

    /// These, and immediate data (an ubershader's keywords): wgpu's `immediates` feature.
    pub fn with_immediates(mut self) -> Allowed {
        self.features.push(IMMEDIATES.to_string());
        self
    }

    fn has(&self, feature: &str) -> bool {
        self.features.iter().any(|f| f == feature)
    }

    /// naga capabilities: what every WebGPU-compliant device has (wgpu's own mapping, so cube
    /// array textures and multisampled shading at every target), plus what the requirements name
    /// ([`REQUIREMENT_CAPABILITIES`]).
    pub fn capabilities(&self) -> Capabilities {
        let mut capabilities = webgpu_baseline();
        for (name, capability, _) in REQUIREMENT_CAPABILITIES {
            if self.has(name) {
                capabilities |= capability;
            }
        }
        if self.has(IMMEDIATES) {
            capabilities |= Capabilities::IMMEDIATES;
        }
        capabilities
    }

    /// The optional GPU features the requirements need.
    pub fn features(&self) -> Vec<GpuFeature> {
        let mut features: Vec<GpuFeature> = REQUIREMENT_CAPABILITIES
            .iter()
            .filter(|(name, _, _)| self.has(name))
            .filter_map(|(_, _, feature)| *feature)
            .chain(self.has(IMMEDIATES).then_some(GpuFeature::Immediates))
            .collect();
        features.sort();
        features.dedup();
        features
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

    /// How many colour targets a fragment stage may write at this target.
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
