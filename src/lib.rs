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

// Diagnostics travel as plain values on the error path, where their size costs nothing that
// matters; boxing each one would only add noise.
#![allow(clippy::result_large_err)]
#![warn(missing_docs, unreachable_pub, clippy::print_stdout, clippy::print_stderr)]

pub mod accuracy;
pub mod build;
mod build_script;
pub mod catalog;
pub mod codegen;
pub mod codes;
pub mod compile;
pub mod config;
pub mod diagnostics;
pub mod keywords;
pub mod listing;
#[cfg(feature = "lsp")]
pub mod lsp;
pub mod manifest;
pub mod material;
pub mod preprocess;
pub mod project;
pub mod reference;
pub mod reflect;
#[cfg(feature = "wgpu")]
pub mod runtime;
pub mod shaderlab;
pub mod shaderlib;
pub mod source;
pub mod store;

pub use build_script::{Build, BuildError, BuildOutput};
