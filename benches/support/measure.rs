//! What the benchmarks that set kiln beside other tools share: medians and ratio ranges over
//! interleaved rounds, and the stage texts a build compiles (what a tool alone is handed).

use kiln::catalog::catalog;
use kiln::orchestrate::stage_texts;
use kiln::preprocess::{Includes, Stage};
use kiln::project::{load_files, open_workspace};
use kiln::source::SourceStore;
use std::path::Path;
use std::time::Duration;

/// The median of a round's times.
pub fn median(mut times: Vec<Duration>) -> Duration {
    times.sort();
    times[times.len() / 2]
}

/// Ratios as `median (lowest-highest)`.
pub fn spread(mut ratios: Vec<f64>) -> String {
    ratios.sort_by(f64::total_cmp);
    format!("{:.2}x ({:.2}-{:.2})", ratios[ratios.len() / 2], ratios[0], ratios[ratios.len() - 1])
}

/// The distinct stage texts a build of `project` compiles, whole, with their stage and entry point.
pub fn whole_texts(project: &Path) -> Vec<(Stage, String, String)> {
    let mut store = SourceStore::new();
    let (workspace, _) = open_workspace(&mut store, &[project.to_path_buf()]).expect("project");
    let mut includes = Includes::new(workspace.include.clone().expect("include config"));
    let (shaders, _) = load_files(&mut store, &workspace.shaders);
    let (materials, _) = load_files(&mut store, &workspace.materials);
    let input = workspace.catalog_input(shaders, materials);
    let (catalog, _) = catalog(&mut store, &mut includes, &input);
    stage_texts(&store, &includes, &catalog)
}
