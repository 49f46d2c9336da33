//! The WGSL preprocessor: `#include`, `#define`, conditionals, macro substitution and a source
//! map back to the original files. So far: the `#if` expression evaluator.

pub mod expr;
