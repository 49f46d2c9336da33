//! Every malformed input in `fixtures/bad/` gets its diagnostics pinned in a sibling `.stderr`
//! golden, and is an error (never a panic, never success). `fixtures/warn/` holds inputs that
//! only warn.

use crate::support::{assert_pinned, fixture_files, kiln, load};

fn check(folder: &str, expect_errors: bool) {
    let files = fixture_files(folder, "shader");
    assert!(!files.is_empty());
    for path in files {
        let (mut store, ids, mut diagnostics) = load(std::slice::from_ref(&path));
        let mut includes =
            kiln::preprocess::Includes::new(kiln::project::include_config(std::slice::from_ref(&path)));
        let (_, found) = kiln::listing::list_shaders(
            &mut store,
            &mut includes,
            &kiln::catalog::CatalogInput { shaders: ids, ..Default::default() },
        );
        diagnostics.extend(found);
        assert_pinned(&path, &store, &diagnostics, expect_errors);
    }
}

#[test]
fn every_bad_fixture_is_an_error_with_a_pinned_diagnostic() {
    let count = fixture_files("fixtures/bad", "shader").len();
    assert!(count >= 15, "the issue asks for at least 15 malformed shaders, found {count}");
    check("fixtures/bad", true);
}

#[test]
fn warnings_are_reported_without_failing() {
    check("fixtures/warn", false);
}

#[test]
fn the_cli_exits_1_on_each_bad_fixture() {
    for path in fixture_files("fixtures/bad", "shader") {
        let output = kiln(&["list", path.to_str().expect("utf-8 path")]);
        assert_eq!(output.status.code(), Some(1), "{}", path.display());
        let stderr = String::from_utf8_lossy(&output.stderr);
        assert!(stderr.contains("error[K"), "{}: {stderr}", path.display());
    }
}
