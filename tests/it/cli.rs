//! The command line as a user meets it: exit codes, output streams, colour.

use crate::support::kiln;

#[test]
fn exit_codes() {
    assert_eq!(kiln(&["list"]).status.code(), Some(0));
    assert_eq!(kiln(&["list", "fixtures/bad/unclosed_brace.shader"]).status.code(), Some(1));
    assert_eq!(kiln(&["list", "no/such/folder"]).status.code(), Some(2));
    assert_eq!(kiln(&["list", "--format", "yaml"]).status.code(), Some(2));
    assert_eq!(kiln(&["frobnicate"]).status.code(), Some(2));
}

#[test]
fn a_missing_path_is_named() {
    let output = kiln(&["list", "no/such/folder"]);
    assert!(String::from_utf8_lossy(&output.stderr).contains("`no/such/folder` does not exist"));
    assert!(output.stdout.is_empty());
}

#[test]
fn good_files_are_listed_even_when_others_fail() {
    let output =
        kiln(&["list", "fixtures/project/shaders/Lit.shader", "fixtures/bad/missing_endwgsl.shader"]);
    assert_eq!(output.status.code(), Some(1));
    assert!(String::from_utf8_lossy(&output.stdout).contains("Custom RP/Lit"));
    assert!(String::from_utf8_lossy(&output.stderr).contains("fixtures/bad/missing_endwgsl.shader:4:13"));
}

#[test]
fn json_diagnostics_carry_line_and_column() {
    let output = kiln(&["list", "fixtures/bad/unknown_render_state_value.shader", "--format", "json"]);
    assert_eq!(output.status.code(), Some(1));
    let value: serde_json::Value = serde_json::from_slice(&output.stdout).expect("json on stdout");
    let first = &value["diagnostics"][0];
    assert_eq!(first["code"], "K0120");
    assert_eq!(first["severity"], "error");
    assert_eq!(first["location"]["file"], "fixtures/bad/unknown_render_state_value.shader");
    assert_eq!(
        (first["location"]["line"].as_u64(), first["location"]["column"].as_u64()),
        (Some(4), Some(20))
    );
    assert_eq!(value["diagnostics"].as_array().map(Vec::len), Some(3));
}

#[test]
fn no_colour_when_not_a_terminal() {
    let output = kiln(&["list", "fixtures/bad/unclosed_brace.shader"]);
    assert!(!output.stderr.contains(&0x1b), "escape codes in piped output");
}
