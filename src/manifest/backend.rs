//! The back ends kiln writes stage modules for, and one value per back end. Adding a back end:
//! its line in [`Backend`] and its pack extension, its writer in `compile/stage.rs::write`, its
//! field in [`super::ModuleManifest`] (the schema names each), and docs/manifest.md.

use serde::{Deserialize, Serialize};

closed_set! {
    /// A back end kiln writes stage modules for (`backends` in `kiln.toml`), in the order a
    /// module's files are kept.
    Backend {
        /// WGSL text, as naga's writer prints it (with `@align`/`@size` restored).
        Wgsl = "wgsl",
        /// SPIR-V binary, for Vulkan.
        Spirv = "spirv",
    }
}

impl Backend {
    /// How many there are.
    pub const COUNT: usize = Backend::ALL.len();

    /// The extension of the packs its modules are written to.
    pub fn pack_extension(self) -> &'static str {
        match self {
            Backend::Wgsl => "wgsl.pack",
            Backend::Spirv => "spv.pack",
        }
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
