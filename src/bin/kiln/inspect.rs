//! `kiln list`, `kiln preprocess`, `kiln reflect` and `kiln accuracy`: looking at a project
//! without building it.

use crate::args::{Format, StageArg};
use crate::output::{exit_code, host_failure, print_out, report};
use kiln::config::ParseScope;
use kiln::diagnostics;
use kiln::preprocess::Stage;
use kiln::project::VariantRequest;
use kiln::source::SourceStore;
use std::path::PathBuf;
use std::process::ExitCode;

/// `kiln list`.
pub fn list(paths: Vec<PathBuf>, format: Format, show_materials: bool) -> ExitCode {
    let paths = if paths.is_empty() { vec![kiln::project::default_project()] } else { paths };
    let mut store = SourceStore::new();
    let (listing, problems) = match kiln::project::list_project(&mut store, &paths) {
        Ok(listed) => listed,
        Err(error) => return host_failure(&error.to_string()),
    };
    match format {
        Format::Text => {
            let mut text = kiln::listing::render_text(&listing);
            if show_materials {
                text.push_str(&kiln::listing::render_materials(&listing));
            }
            print_out(&text);
            report(&store, &problems);
        }
        Format::Json => {
            let mut document = serde_json::json!({
                "shaders": listing.shaders,
                "diagnostics": diagnostics::to_json(&store, &problems),
            });
            if show_materials {
                document["materials"] = serde_json::json!(listing.materials);
            }
            print_out(&format!("{document:#}\n"));
        }
    }
    exit_code(&problems)
}

/// `kiln preprocess`.
pub fn preprocess(
    shader: PathBuf,
    pass: Option<String>,
    keywords: Vec<String>,
    stage: Option<StageArg>,
    reachable: bool,
) -> ExitCode {
    let stage = match stage {
        Some(StageArg::Vertex) => Stage::Vertex,
        Some(StageArg::Fragment) => Stage::Fragment,
        Some(StageArg::Compute) => Stage::Compute,
        None if kiln::shaderlab::compute::is_compute_file(&shader) => Stage::Compute,
        None => Stage::Fragment,
    };
    let request = VariantRequest { shader, pass, keywords, stage, project: None };
    let mut store = SourceStore::new();
    let scope = if reachable { ParseScope::Reachable } else { ParseScope::Whole };
    match kiln::project::preprocess_variant(&mut store, &request, scope) {
        Ok((output, problems)) => {
            if let Some(output) = output {
                print_out(&output.text);
            }
            report(&store, &problems);
            exit_code(&problems)
        }
        Err(error) => host_failure(&error.to_string()),
    }
}

/// `kiln reflect`.
pub fn reflect(
    shader: PathBuf,
    pass: Option<String>,
    keywords: Vec<String>,
    project: Option<PathBuf>,
) -> ExitCode {
    let mut store = SourceStore::new();
    let request = VariantRequest { shader, pass, keywords, stage: Stage::Fragment, project };
    match kiln::project::reflect_variant(&mut store, &request) {
        Ok((json, problems)) => {
            if let Some(json) = json {
                print_out(&format!("{json:#}\n"));
            }
            report(&store, &problems);
            exit_code(&problems)
        }
        Err(error) => host_failure(&error.to_string()),
    }
}

/// `kiln accuracy` in a kiln built without the GPU harness.
#[cfg(not(feature = "gpu"))]
pub fn accuracy(_plot: Vec<PathBuf>, _samples: usize) -> ExitCode {
    host_failure(
        "this kiln was built without the `gpu` feature, which `kiln accuracy` needs: cargo install --path . --features gpu (or cargo run --features gpu -- accuracy)",
    )
}

/// `kiln accuracy`.
#[cfg(feature = "gpu")]
pub fn accuracy(plots: Vec<PathBuf>, samples: usize) -> ExitCode {
    let gpu = match kiln::accuracy::gpu::device() {
        Ok(found) => found,
        Err(reason) => return host_failure(&reason),
    };
    match kiln::accuracy::gpu::run(&gpu, samples) {
        Ok((rows, timings, method)) => {
            print_out(&kiln::accuracy::render(&gpu.adapter, &rows, &timings, &method));
            let found = match kiln::accuracy::gpu::search(&gpu) {
                Ok(found) => found,
                Err(error) => return host_failure(&error),
            };
            print_out(&kiln::accuracy::render_search(&found));
            let points = kiln::accuracy::plot::points(&rows, &timings, &found);
            for path in plots {
                let written =
                    kiln::accuracy::plot::picture_for(&path, &gpu.adapter, &points).and_then(|bytes| {
                        kiln::store::write_atomically(&path, &bytes).map_err(|e| e.to_string())
                    });
                if let Err(error) = written {
                    return host_failure(&format!("cannot write `{}`: {error}", path.display()));
                }
            }
            ExitCode::SUCCESS
        }
        Err(error) => {
            report(&SourceStore::new(), &[kiln::diagnostics::Diagnostic::host_failure(error.to_string())]);
            ExitCode::from(1)
        }
    }
}

/// `kiln lsp`: the language server on stdin and stdout, until the client says `exit`.
pub fn lsp(cache_dir: Option<PathBuf>) -> ExitCode {
    let options = kiln::lsp::ServerOptions { cache_dir, library_dir: None };
    match kiln::lsp::serve_stdio(&options) {
        Ok(()) => ExitCode::SUCCESS,
        Err(error) => host_failure(&error.to_string()),
    }
}

/// `kiln preview` in a kiln built without it.
#[cfg(not(feature = "preview"))]
pub fn preview(_material: String, _project: Option<PathBuf>, _out: Option<PathBuf>, _size: u32) -> ExitCode {
    host_failure(
        "this kiln was built without the `preview` feature, which `kiln preview` needs (it adds wgpu): cargo install --path . --features preview (or cargo run --release --features preview -- preview MATERIAL)",
    )
}

/// `kiln preview`: the project built into the user's cache, the material drawn, the PNG written.
#[cfg(feature = "preview")]
pub fn preview(material: String, project: Option<PathBuf>, out: Option<PathBuf>, size: u32) -> ExitCode {
    let project = project.unwrap_or_else(kiln::project::default_project);
    // The default file is named after the material, here: a name that is one plain component.
    let plain = std::path::Path::new(&material).file_name() == Some(std::ffi::OsStr::new(&material));
    let out = match out {
        Some(out) => out,
        None if plain => PathBuf::from(format!("{material}.png")),
        None => {
            return host_failure("the material's name is not a file name: say where to write it with --out");
        }
    };
    let mut store = SourceStore::new();
    let (result, mut problems) = match kiln::project::preview_build(&mut store, &project) {
        Ok(built) => built,
        Err(error) => return host_failure(&error.to_string()),
    };
    problems.extend(result.diagnostics);
    report(&store, &problems);
    if diagnostics::has_errors(&problems) {
        return ExitCode::from(1);
    }
    let drawn = kiln::runtime::Library::open(&result.output)
        .map_err(kiln::preview::PreviewError::from)
        .and_then(|library| kiln::preview::draw(library, &material, size));
    let preview = match drawn {
        Ok(preview) => preview,
        Err(error) => {
            report(&SourceStore::new(), &[kiln::diagnostics::Diagnostic::host_failure(error.to_string())]);
            return ExitCode::from(1);
        }
    };
    for note in &preview.notes {
        eprintln!("note: {}", kiln::diagnostics::shown_text(note, false));
    }
    let written = preview
        .picture
        .png()
        .map_err(|e| e.to_string())
        .and_then(|bytes| kiln::store::write_atomically(&out, &bytes).map_err(|e| e.to_string()));
    if let Err(error) = written {
        return host_failure(&format!("cannot write `{}`: {error}", out.display()));
    }
    let keywords = match preview.keywords.is_empty() {
        true => "no keywords".to_string(),
        false => preview.keywords.join(" "),
    };
    eprintln!(
        "drew {} ({}, pass {}, {keywords}) on {} into {}",
        kiln::diagnostics::shown_text(&material, false),
        kiln::diagnostics::shown_text(&preview.shader, false),
        preview.pass,
        preview.adapter,
        out.display()
    );
    ExitCode::SUCCESS
}
