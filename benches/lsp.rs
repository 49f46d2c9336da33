//! `kiln lsp` latency, end to end through the protocol: from a `didChange` to the
//! `publishDiagnostics` for that buffer version, with the server's peak memory.
//! `cargo bench --bench lsp` (edits per case: `-- 40`). Cases: the bundled example project
//! (`LitPass.wgsl`, read by one pass), and a generated project of 1,000 variants (the scale
//! benchmark's: 10 shaders of 100 variants) edited in one shader's file, in an include a tenth of
//! the shaders read, and in the pass file every shader reads. Each edit changes the text (a
//! comment with a counter), so the passes that read the file are preprocessed and compiled again.
//! Results and how to read them: docs/performance.md.

#[path = "support/generate.rs"]
mod generate;
#[path = "../tests/it/lsp_client.rs"]
mod lsp_client;

use lsp_client::{Client, uri};
use std::path::Path;
use std::time::{Duration, Instant};

/// Edits `file` `edits` times through `client` and returns, for each edit, the time from its
/// `didChange` to its first diagnostics and to the end of the check of every variant.
fn edit_latencies(client: &mut Client, file: &Path, edits: usize) -> (Vec<Duration>, Vec<Duration>) {
    let text = std::fs::read_to_string(file).expect("file");
    let uri = uri(file);
    client.open(&uri, &text);
    let first = client.diagnostics(&uri, Some(1));
    client.notification(kiln::lsp::CHECKED);
    let errors = first.iter().filter(|d| d["severity"] == 1).count();
    assert_eq!(errors, 0, "the benchmark's project has errors: {first:#?}");
    (0..edits)
        .map(|n| {
            let version = n as i64 + 2;
            let started = Instant::now();
            client.change(&uri, version, &format!("{text}// edit {n}\n"));
            client.diagnostics(&uri, Some(version));
            let first = started.elapsed();
            client.notification(kiln::lsp::CHECKED);
            (first, started.elapsed())
        })
        .unzip()
}

fn report(case: &str, (mut first, mut complete): (Vec<Duration>, Vec<Duration>), client: &Client) {
    let ms = |times: &mut Vec<Duration>, q: f64| {
        times.sort();
        times[((times.len() - 1) as f64 * q).round() as usize].as_secs_f64() * 1e3
    };
    let peak = client.peak_memory_kib().map_or("n/a".into(), |k| format!("{:.1} MiB", k as f64 / 1024.0));
    println!(
        "{case:<52} edits {:>3}  first diagnostics: median {:>6.1} ms, p90 {:>6.1} ms  every variant checked: median {:>6.1} ms, p90 {:>6.1} ms  server peak {peak}",
        first.len(),
        ms(&mut first, 0.5),
        ms(&mut first, 0.9),
        ms(&mut complete, 0.5),
        ms(&mut complete, 0.9),
    );
}

fn main() {
    let edits: usize =
        std::env::args().skip(1).find(|a| !a.starts_with('-')).and_then(|a| a.parse().ok()).unwrap_or(40);
    let scratch = tempfile::tempdir().expect("tempdir");
    let example = scratch.path().join("example");
    copy_example(&example);
    let mut client = Client::start(&scratch.path().join("example-server"));
    let times = edit_latencies(&mut client, &example.join("shaders/LitPass.wgsl"), edits);
    report("example project: LitPass.wgsl (1 pass, 3 variants)", times, &client);
    client.shutdown();

    let generated = scratch.path().join("generated");
    let shaders = generate::generate(&generated, 1000);
    let cases = [
        ("shaders/S00000.shader", "1,000 variants: one shader (1 pass, 100 variants)".to_string()),
        (
            "shaders/Shared0.wgsl",
            format!(
                "1,000 variants: an include {} shaders read",
                shaders.div_ceil(generate::SHARED_INCLUDES)
            ),
        ),
        ("shaders/SynthPass.wgsl", format!("1,000 variants: the pass file all {shaders} shaders read")),
    ];
    for (file, case) in cases {
        let mut client = Client::start(&scratch.path().join(format!("server-{}", file.replace('/', "-"))));
        let times = edit_latencies(&mut client, &generated.join(file), edits.min(20));
        report(&case, times, &client);
        client.shutdown();
    }
}

/// The bundled example project without its build output.
fn copy_example(to: &Path) {
    let from = Path::new(env!("CARGO_MANIFEST_DIR")).join("fixtures/project");
    for entry in walkdir::WalkDir::new(&from).into_iter().filter_map(Result::ok) {
        let relative = entry.path().strip_prefix(&from).expect("inside");
        if entry.file_type().is_file() && !relative.starts_with("build") {
            std::fs::create_dir_all(to.join(relative).parent().expect("folder")).expect("mkdir");
            std::fs::copy(entry.path(), to.join(relative)).expect("copy");
        }
    }
}
