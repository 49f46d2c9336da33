//! Real ShaderLab from public Unity repositories (tests/corpus/unity, each folder with its
//! licence; ORIGIN.md there says where each file comes from): every file lists without an error,
//! as Unity accepts every one.

use crate::support::{load, root};

#[test]
fn every_real_unity_shader_lists_without_an_error() {
    let corpus = root().join("tests/corpus/unity");
    let mut files: Vec<std::path::PathBuf> = walkdir::WalkDir::new(&corpus)
        .into_iter()
        .map(|e| e.expect("entry").into_path())
        .filter(|p| p.extension().is_some_and(|e| e == "shader"))
        .collect();
    files.sort();
    assert!(files.len() >= 200, "{} files", files.len());
    let (mut failures, mut warned, mut passes) = (Vec::new(), 0, 0);
    for path in &files {
        let (mut store, ids, mut diagnostics) = load(std::slice::from_ref(path));
        let mut includes =
            kiln::preprocess::Includes::new(kiln::project::include_config(std::slice::from_ref(path)));
        let (catalog, found) = kiln::listing::list_shaders(
            &mut store,
            &mut includes,
            &kiln::catalog::CatalogInput { shaders: ids, ..Default::default() },
        );
        diagnostics.extend(found);
        passes += catalog.shaders.iter().map(|s| s.passes.len()).sum::<usize>();
        if kiln::diagnostics::has_errors(&diagnostics) {
            failures.push(kiln::diagnostics::render_plain(&store, &diagnostics));
        } else if !diagnostics.is_empty() {
            warned += 1;
        }
    }
    println!("{} real Unity shaders listed ({passes} passes), {warned} with warnings", files.len());
    assert!(
        failures.is_empty(),
        "{} of {} files refused:\n{}",
        failures.len(),
        files.len(),
        failures.join("\n")
    );
}
