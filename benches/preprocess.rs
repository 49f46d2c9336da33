//! Preprocessing against naga's own parse, on the Lit pass of the bundled project and on the same
//! pass written with Unity-style function-like macros (`fixtures/macros/MacroLit.shader`), in
//! one run:
//! `cargo bench --bench preprocess`. Prints per-variant medians and the ratio that matters
//! (preprocess / naga parse); see docs/performance.md.

use kiln::listing::program_blocks;
use kiln::preprocess::{Includes, PassProgram, Stage, load_pass, preprocess};
use kiln::shaderlab::parse_shader;
use kiln::source::SourceStore;
use std::hint::black_box;
use std::path::{Path, PathBuf};
use std::time::{Duration, Instant};

/// Median time of one call, over `rounds` rounds of `batch` calls each.
fn median(rounds: usize, batch: usize, mut f: impl FnMut()) -> Duration {
    let mut times: Vec<Duration> = (0..rounds)
        .map(|_| {
            let start = Instant::now();
            for _ in 0..batch {
                f();
            }
            start.elapsed() / batch as u32
        })
        .collect();
    times.sort();
    times[rounds / 2]
}

/// Reads and parses the shader, then loads its first pass with everything it includes: the work
/// done once per pass, before any variant.
fn load(path: &Path) -> (SourceStore, Includes, PassProgram) {
    let mut store = SourceStore::new();
    let file = store.load(path).expect("the shader loads");
    let shader = parse_shader(&store, file).shader.expect("the shader parses");
    let (_, sub, _, pass) = shader.passes().next().expect("a pass");
    let mut includes = Includes::new(kiln::project::include_config(&[path.to_path_buf()]));
    let (program, _) = load_pass(&mut includes, &mut store, &program_blocks(&shader, sub, &pass.programs));
    (store, includes, program)
}

fn main() {
    let root = PathBuf::from(env!("CARGO_MANIFEST_DIR"));
    let lit = root.join("fixtures/project/shaders/Lit.shader");
    let once = median(21, 20, || {
        black_box(load(&lit));
    });
    println!("once per pass (read, parse, scan every include): {once:.2?}");
    println!();
    println!(
        "{:<34} {:>12} {:>12} {:>8} {:>14}",
        "variant", "preprocess", "naga parse", "ratio", "parse+validate"
    );
    let lit_variants: [&[&str]; 4] =
        [&[], &["_CLIPPING"], &["_PREMULTIPLY_ALPHA"], &["_CLIPPING", "_PREMULTIPLY_ALPHA"]];
    for (path, prefix) in [(lit, "Lit"), (root.join("fixtures/macros/MacroLit.shader"), "Lit, macros")] {
        let (store, includes, program) = load(&path);
        for keywords in lit_variants {
            row(&store, &includes, &program, prefix, keywords);
        }
    }
}

/// One variant: preprocessing, naga's parse of its output, and parse plus validation.
fn row(store: &SourceStore, includes: &Includes, program: &PassProgram, prefix: &str, keywords: &[&str]) {
    let text = preprocess(includes, store, &program.program, keywords, Stage::Fragment).text;
    let pre = median(31, 200, || {
        black_box(preprocess(includes, store, &program.program, keywords, Stage::Fragment));
    });
    let parse = median(31, 20, || {
        black_box(naga::front::wgsl::parse_str(&text).expect("parses"));
    });
    let validate = median(31, 20, || {
        let module = naga::front::wgsl::parse_str(&text).expect("parses");
        let flags = naga::valid::ValidationFlags::all() - naga::valid::ValidationFlags::BINDINGS;
        black_box(
            naga::valid::Validator::new(flags, naga::valid::Capabilities::all())
                .validate(&module)
                .expect("valid"),
        );
    });
    let name = if keywords.is_empty() { "(none)".to_string() } else { keywords.join(" ") };
    let name = format!("{prefix} {name}");
    let ratio = pre.as_secs_f64() / parse.as_secs_f64();
    println!("{name:<34} {pre:>12.2?} {parse:>12.2?} {:>7.1}% {validate:>14.2?}", ratio * 100.0);
}
