//! The scene file: camera, lights, spheres and their materials (a preset plus a few values).
//! Shared with `build.rs`, which reads `scene.toml`, turns the materials into `.mat` files for
//! kiln and writes the scene as JSON for the renderer (which ships no TOML parser).

use serde::{Deserialize, Serialize};

#[derive(Debug, Clone, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Scene {
    pub width: u32,
    pub height: u32,
    pub background: [f64; 3],
    pub camera: Camera,
    #[serde(default)]
    pub lights: Vec<DirectionalLight>,
    pub objects: Vec<Object>,
}

#[derive(Debug, Clone, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Camera {
    pub position: [f64; 3],
    pub target: [f64; 3],
    pub fov_y_degrees: f64,
}

#[derive(Debug, Clone, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct DirectionalLight {
    /// Towards the light.
    pub direction: [f64; 3],
    pub color: [f64; 3],
}

#[derive(Debug, Clone, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Object {
    pub position: [f64; 3],
    pub radius: f64,
    pub material: SceneMaterial,
}

#[derive(Debug, Clone, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct SceneMaterial {
    /// Opaque, Clip, Fade or Transparent, as the seed's shader GUI sets them.
    pub preset: String,
    pub color: [f64; 4],
    pub metallic: f64,
    pub smoothness: f64,
    #[serde(default = "default_cutoff")]
    pub cutoff: f64,
}

fn default_cutoff() -> f64 {
    0.5
}

/// The shader every scene material uses.
pub const SHADER: &str = "Custom RP/Lit";

impl Scene {
    /// A scene as `build.rs` writes it (JSON).
    pub fn parse(json: &str) -> Result<Scene, serde_json::Error> {
        serde_json::from_str(json)
    }

    /// The global keywords the scene runs with, which the build specialises for: with one light,
    /// the lighting without the loop over lights.
    pub fn global_keywords(&self) -> Vec<&'static str> {
        if self.lights.len() == 1 { vec!["_SINGLE_DIRECTIONAL_LIGHT"] } else { Vec::new() }
    }

    /// One kiln material file per object: `(file name, TOML text)`.
    pub fn material_files(&self) -> Vec<(String, String)> {
        self.objects
            .iter()
            .enumerate()
            .map(|(i, object)| {
                let m = &object.material;
                let text = format!(
                    "shader = {SHADER:?}\npreset = {:?}\n\n[properties]\n_BaseColor = {:?}\n_Metallic = {}\n_Smoothness = {}\n_Cutoff = {}\n",
                    m.preset, m.color, m.metallic, m.smoothness, m.cutoff
                );
                (format!("object{i:02}.mat"), text)
            })
            .collect()
    }
}

impl SceneMaterial {
    pub fn clips(&self) -> bool {
        self.preset.eq_ignore_ascii_case("Clip")
    }

    pub fn premultiplies(&self) -> bool {
        self.preset.eq_ignore_ascii_case("Transparent")
    }

    /// Blended presets draw after opaque ones, back to front, without writing depth.
    pub fn blends(&self) -> bool {
        self.preset.eq_ignore_ascii_case("Fade") || self.premultiplies()
    }

    /// The keywords this material enables, as kiln derives them from the preset's toggles.
    pub fn keywords(&self) -> Vec<&'static str> {
        let mut keywords = Vec::new();
        if self.clips() {
            keywords.push("_CLIPPING");
        }
        if self.premultiplies() {
            keywords.push("_PREMULTIPLY_ALPHA");
        }
        keywords
    }
}
