//! kiln: a shader-variant compiler and keyword system for Rust renderers.

// Diagnostics travel as plain values on the error path, where their size costs nothing that
// matters; boxing each one would only add noise.
#![allow(clippy::result_large_err)]

pub mod catalog;
pub mod compile;
pub mod config;
pub mod diagnostics;
pub mod keywords;
pub mod listing;
pub mod material;
pub mod preprocess;
pub mod project;
pub mod reflect;
pub mod shaderlab;
pub mod shaderlib;
pub mod source;
