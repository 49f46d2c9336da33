//! The `.shader` language: grammar, typed AST with spans, and `#pragma` extraction.
//!
//! pest types never leave this module: callers get [`ast::Shader`] and diagnostics.

pub mod ast;
pub(crate) mod error;
mod parse;
pub mod pragma;
mod scan;

pub use error::ShaderLabError;
pub(crate) use error::one_of;
pub use parse::{ParsedShader, parse_shader};
