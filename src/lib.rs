//! kiln: a shader-variant compiler and keyword system for Rust renderers.
//!
//! From a renderer's `build.rs`:
//!
//! ```no_run
//! fn main() -> Result<(), kiln::BuildError> {
//!     kiln::Build::new("shaders").run()?;
//!     Ok(())
//! }
//! ```
//!
//! and in the renderer, `include!(concat!(env!("OUT_DIR"), "/kiln_shaders.rs"));` gives each
//! shader a module with its passes' variants (WGSL, SPIR-V), strict lookup by keywords, bind group
//! layouts and `#[repr(C)]` uniform structs.
//!
//! # The API
//!
//! - [`Build`], [`BuildError`], [`BuildOutput`]: the build-script builder.
//! - [`manifest`]: the output's schema (`manifest.json`, docs/manifest.md).
//! - `runtime` (feature `wgpu`): layouts, pipelines and materials from a build, on wgpu.
//! - [`project`]: the jobs the `kiln` command runs (build, check, list, merge, watch), with
//!   [`config`] (`kiln.toml`), [`diagnostics`] (what every job reports, with [`codes`]) and
//!   [`source`] (the files and spans diagnostics point into).
//!
//! The compiler's stages (`shaderlab`, `preprocess`, `keywords`, `material`, `catalog`,
//! `compile`, `reflect`, `build`, `store`, `codegen`, `listing`, `lsp`, `accuracy`, ...) are
//! public for the `kiln` command, the benchmarks and the tests, hidden from these docs and
//! outside any compatibility promise: ARCHITECTURE.md describes them.

// Diagnostics travel as plain values on the error path, where their size costs nothing that
// matters; boxing each one would only add noise.
#![allow(clippy::result_large_err)]
#![warn(missing_docs, unreachable_pub, clippy::print_stdout, clippy::print_stderr)]
// The stages' module docs link their private parts for maintainers, who read them with
// `cargo doc --document-private-items`.
#![allow(rustdoc::private_intra_doc_links)]

#[doc(hidden)]
pub mod accuracy;
mod build_script;
#[doc(hidden)]
pub mod catalog;
#[doc(hidden)]
pub mod codegen;
pub mod codes;
#[doc(hidden)]
pub mod compile;
pub mod config;
pub mod diagnostics;
#[doc(hidden)]
pub mod keywords;
#[doc(hidden)]
pub mod listing;
#[doc(hidden)]
#[cfg(feature = "lsp")]
pub mod lsp;
#[doc(hidden)]
pub mod orchestrate;
pub use kiln_manifest as manifest;
#[doc(hidden)]
pub mod material;
#[doc(hidden)]
pub mod preprocess;
pub mod project;
#[doc(hidden)]
pub use kiln_reference as reference;
#[cfg(feature = "preview")]
pub mod preview;
#[doc(hidden)]
pub mod reflect;
#[cfg(feature = "wgpu")]
pub use kiln_runtime as runtime;
#[doc(hidden)]
pub mod shaderlab;
#[doc(hidden)]
pub mod shaderlib;
pub mod source;
#[doc(hidden)]
pub mod store;

pub use build_script::{Build, BuildError, BuildOutput};
