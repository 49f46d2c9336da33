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
#![warn(unreachable_pub, clippy::print_stdout, clippy::print_stderr)]

pub mod accuracy;
#[warn(missing_docs)]
pub mod build;
mod build_script;
pub mod catalog;
#[warn(missing_docs)]
pub mod codegen;
#[warn(missing_docs)]
pub mod codes;
#[warn(missing_docs)]
pub mod compile;
#[warn(missing_docs)]
pub mod config;
pub mod diagnostics;
#[warn(missing_docs)]
pub mod keywords;
pub mod listing;
pub mod manifest;
pub mod material;
pub mod preprocess;
pub mod project;
pub mod reference;
#[warn(missing_docs)]
pub mod reflect;
#[cfg(feature = "wgpu")]
#[warn(missing_docs)]
pub mod runtime;
pub mod shaderlab;
pub mod shaderlib;
pub mod source;
#[warn(missing_docs)]
pub mod store;

pub use build_script::{Build, BuildError, BuildOutput};
