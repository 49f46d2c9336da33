//! The back ends kiln writes stage modules for, and one value per back end. Adding a back end:
//! its line in [`Backend`] and its pack extension, its writer in `compile/stage.rs::write` (or
//! `compile/platforms.rs` for a language a wgpu back end translates to), its field in
//! [`super::ModuleManifest`] (the schema names each), and docs/manifest.md.

use serde::{Deserialize, Serialize};

closed_set! {
    /// A back end kiln writes stage modules for (`backends` in `kiln.toml`), in the order a
    /// module's files are kept.
    Backend {
        /// WGSL text, as naga's writer prints it (with `@align`/`@size` restored).
        Wgsl = "wgsl",
        /// SPIR-V binary, for Vulkan.
        Spirv = "spirv",
        /// Metal Shading Language 2.4 source, as wgpu's Metal back end has naga write it.
        Msl = "msl",
        /// HLSL source for shader model 5.1, as wgpu's DX12 back end has naga write it.
        Hlsl = "hlsl",
        /// GLSL ES 3.00 source, for WebGL2 and wgpu's GL back end.
        Glsl = "glsl",
    }
}

impl Backend {
    /// How many there are.
    pub const COUNT: usize = Backend::ALL.len();

    /// What a project writes when `kiln.toml` does not say: what wgpu loads (WGSL, SPIR-V).
    pub const DEFAULT: &'static [Backend] = &[Backend::Wgsl, Backend::Spirv];

    /// The extension of the packs its modules are written to.
    pub fn pack_extension(self) -> &'static str {
        match self {
            Backend::Wgsl => "wgsl.pack",
            Backend::Spirv => "spv.pack",
            Backend::Msl => "metal.pack",
            Backend::Hlsl => "hlsl.pack",
            Backend::Glsl => "glsl.pack",
        }
    }

    /// The back end a name that is none means: the API it is for (`metal` is `msl`, `vulkan`
    /// `spirv`, `dx12` `hlsl`, `gl` `glsl`, `webgpu` `wgsl`), or a spelling two edits away.
    pub fn meant(name: &str) -> Option<Backend> {
        let by_api = match name.to_ascii_lowercase().as_str() {
            "metal" | "mtl" | "macos" | "ios" => Some(Backend::Msl),
            "vulkan" | "vk" | "spv" | "spir-v" => Some(Backend::Spirv),
            "dx12" | "d3d12" | "directx" | "dx" | "d3d" => Some(Backend::Hlsl),
            "gl" | "opengl" | "gles" | "webgl" | "webgl2" => Some(Backend::Glsl),
            "webgpu" | "wgpu" => Some(Backend::Wgsl),
            _ => None,
        };
        by_api.or_else(|| {
            let closest = crate::closest(name, Backend::ALL.iter().map(|b| b.name()))?;
            Backend::ALL.iter().copied().find(|b| b.name() == closest)
        })
    }

    fn index(self) -> usize {
        self as usize
    }
}

/// One value per back end, in [`Backend::ALL`]'s order; written as an array.
#[derive(Debug, Clone, PartialEq, Eq, Hash, Default, Serialize, Deserialize)]
#[serde(transparent)]
pub struct PerBackend<T>([T; Backend::COUNT]);

impl<T> PerBackend<T> {
    /// The value of each back end, from a function of it.
    pub fn from_fn(mut value: impl FnMut(Backend) -> T) -> PerBackend<T> {
        PerBackend(std::array::from_fn(|i| value(Backend::ALL[i])))
    }

    /// Each back end with its value.
    pub fn iter(&self) -> impl Iterator<Item = (Backend, &T)> {
        Backend::ALL.iter().copied().zip(&self.0)
    }

    /// The values, each through `f`.
    pub fn map<U>(self, f: impl FnMut(T) -> U) -> PerBackend<U> {
        PerBackend(self.0.map(f))
    }

    /// The values, in order.
    pub fn values(&self) -> impl Iterator<Item = &T> {
        self.0.iter()
    }

    /// The values, in order, to change.
    pub fn values_mut(&mut self) -> impl Iterator<Item = &mut T> {
        self.0.iter_mut()
    }
}

impl<T> std::ops::Index<Backend> for PerBackend<T> {
    type Output = T;
    fn index(&self, backend: Backend) -> &T {
        &self.0[backend.index()]
    }
}

impl<T> std::ops::IndexMut<Backend> for PerBackend<T> {
    fn index_mut(&mut self, backend: Backend) -> &mut T {
        &mut self.0[backend.index()]
    }
}
