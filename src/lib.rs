//! kiln: a shader-variant compiler and keyword system for Rust renderers.

pub mod catalog;
pub mod compile;
pub mod config;
pub mod diagnostics;
pub mod keywords;
pub mod listing;
pub mod material;
pub mod preprocess;
pub mod project;
pub mod shaderlab;
pub mod shaderlib;
pub mod source;
