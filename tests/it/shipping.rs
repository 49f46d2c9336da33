//! What a game ships: the example renderer's normal dependency tree, as cargo itself resolves it,
//! holds the run time and not the compiler.

use crate::support::root;
use std::collections::BTreeMap;
use std::process::Command;

/// Every package in `package`'s normal (not build, not dev) dependency tree, with its features.
fn normal_tree(package: &str) -> BTreeMap<String, Vec<String>> {
    let output = Command::new(env!("CARGO"))
        .current_dir(root())
        .args(["tree", "--locked", "--offline", "-p", package, "-e", "normal", "--prefix", "none"])
        .args(["--format", "{p}|{f}"])
        .output()
        .expect("cargo runs");
    assert!(output.status.success(), "cargo tree: {}", String::from_utf8_lossy(&output.stderr));
    let mut packages = BTreeMap::new();
    for line in String::from_utf8(output.stdout).expect("UTF-8").lines() {
        let (package, features) = line.trim_end_matches(" (*)").split_once('|').expect("{p}|{f}");
        let name = package.split(' ').next().expect("a name").to_string();
        let features = features.split(',').filter(|f| !f.is_empty()).map(str::to_string);
        let known: &mut Vec<String> = packages.entry(name).or_default();
        known.extend(features);
        known.sort();
        known.dedup();
    }
    packages
}

#[test]
fn the_example_renderer_ships_the_run_time_and_no_compiler() {
    let packages = normal_tree("kiln-renderer");
    for must in ["kiln-runtime", "kiln-manifest", "wgpu"] {
        assert!(packages.contains_key(must), "{must} is missing from {:?}", packages.keys());
    }
    // The compiler, its HTTP client and TLS, its parsers, file walker, thread pool, command line
    // and language server.
    let forbidden = [
        "kiln",
        "ureq",
        "rustls",
        "ring",
        "sha2",
        "pest",
        "toml",
        "toml_edit",
        "walkdir",
        "rayon",
        "glslang",
        "clap",
        "notify",
        "lsp-server",
    ];
    let shipped: Vec<&str> = forbidden.iter().copied().filter(|name| packages.contains_key(*name)).collect();
    assert!(shipped.is_empty(), "a game would ship {shipped:?}");
    // naga is wgpu's: no front end but those wgpu's own features turn on (WGSL, and SPIR-V,
    // which the run time hands wgpu on Vulkan).
    let naga = packages.get("naga").expect("wgpu brings naga");
    let wgpu = &packages["wgpu"];
    let front_ends: Vec<&str> = naga.iter().map(String::as_str).filter(|f| f.ends_with("-in")).collect();
    let wgpu_s: Vec<&str> = [("glsl", "glsl-in"), ("spirv", "spv-in"), ("wgsl", "wgsl-in")]
        .into_iter()
        .filter(|(feature, _)| wgpu.iter().any(|f| f == feature))
        .map(|(_, front_end)| front_end)
        .collect();
    assert_eq!(front_ends, wgpu_s, "naga's features in the renderer: {naga:?}; wgpu's: {wgpu:?}");
    assert!(!front_ends.contains(&"glsl-in"), "{front_ends:?}");
    // And the run time's own dependencies are few: wgpu's tree and a handful beside it.
    let runtime = normal_tree("kiln-runtime");
    let wgpu = normal_tree("wgpu");
    let own: Vec<&String> = runtime.keys().filter(|name| !wgpu.contains_key(*name)).collect();
    assert!(own.len() <= 12, "kiln-runtime adds {} crates to wgpu's: {own:?}", own.len());
}

/// The README's first command, `cargo run --release -- build fixtures/project`, compiles the CLI
/// and what it needs: no wgpu and no renderer (the example renderer, a default workspace member,
/// once turned on the compiler's `wgpu` feature for every build). Read from the units cargo
/// itself plans for the binary that command runs (`cargo build --bin kiln --unit-graph`, which
/// builds nothing; `cargo run` plans the same units, but its `--unit-graph` stops on an assertion).
#[test]
fn the_readme_s_first_command_compiles_no_wgpu() {
    let output = Command::new(env!("CARGO"))
        .current_dir(root())
        .env("RUSTC_BOOTSTRAP", "1")
        .args(["build", "--release", "--bin", "kiln", "--locked", "--offline"])
        .args(["--unit-graph", "-Z", "unstable-options"])
        .output()
        .expect("cargo runs");
    assert!(output.status.success(), "cargo: {}", String::from_utf8_lossy(&output.stderr));
    let graph: serde_json::Value = serde_json::from_slice(&output.stdout).expect("the unit graph is JSON");
    let packages: std::collections::BTreeSet<String> = graph["units"]
        .as_array()
        .expect("units")
        .iter()
        .filter_map(|unit| unit["pkg_id"].as_str())
        .map(|id| id.rsplit(['#', '/']).next().unwrap_or(id).split('@').next().unwrap_or(id).to_string())
        .collect();
    assert!(packages.contains("kiln") && packages.contains("naga"), "{packages:?}");
    for absent in ["wgpu", "wgpu-core", "wgpu-hal", "kiln-runtime", "kiln-renderer"] {
        assert!(!packages.contains(absent), "the README's first command compiles {absent}");
    }
}
