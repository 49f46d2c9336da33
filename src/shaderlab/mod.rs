//! The `.shader` language: grammar, typed AST with spans, and `#pragma` extraction.
//!
//! pest types never leave this module: callers get [`ast::Shader`] and diagnostics.

pub mod ast;
pub mod compute;
pub(crate) mod error;
mod parse;
pub mod pragma;
pub mod reserved;
mod scan;

pub use error::ShaderLabError;
pub(crate) use error::one_of;
pub use parse::{ParsedShader, parse_shader};

/// The name a shader file declares (`Shader "name"`, its first token and string), read without
/// parsing the rest: what a file that does not parse still says it is.
pub fn declared_name(text: &str) -> Option<String> {
    let mut rest = text.trim_start_matches('\u{feff}');
    loop {
        rest = rest.trim_start();
        if let Some(comment) = rest.strip_prefix("//") {
            rest = comment.split_once('\n').map_or("", |(_, after)| after);
        } else if let Some(comment) = rest.strip_prefix("/*") {
            rest = comment.split_once("*/").map_or("", |(_, after)| after);
        } else {
            break;
        }
    }
    let rest = rest.strip_prefix("Shader")?.trim_start().strip_prefix('"')?;
    let (name, _) = rest.split_once('"')?;
    Some(name.to_string())
}

#[cfg(test)]
mod tests {
    #[test]
    fn a_shader_s_declared_name_is_read_past_comments() {
        assert_eq!(
            super::declared_name("// a\n/* b */ Shader \"Custom RP/Lit\" {"),
            Some("Custom RP/Lit".into())
        );
        assert_eq!(super::declared_name("\u{feff}Shader \"X\""), Some("X".into()));
        assert_eq!(super::declared_name("Properties { }"), None);
    }
}
