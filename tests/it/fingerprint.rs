//! The compiler's fingerprint: the fixtures compiled into a shared cache, each object (a stage
//! module's bytes and reflection, under the key of the text and compiler that made it) hashed and
//! pinned in `tests/golden/fingerprint.txt` with the compiler's name. A change to kiln that makes
//! the same key hold other bytes must raise `COMPILER_REVISION`, or a cache filled before it
//! serves stale modules; this test fails until it does.

use crate::support::{kiln, root};
use std::collections::BTreeMap;

/// Each fixture with the back ends it is built for: every writer and both front ends (WGSL, and
/// HLSL through glslang) are pinned. GLSL ES has no storage buffers or compute, so the compute
/// and storage fixtures leave it out.
const FIXTURES: [(&str, &str); 5] = [
    ("project", "wgsl,spirv,msl,hlsl,glsl"),
    ("compute", "wgsl,spirv,msl,hlsl"),
    ("dynamic", "wgsl,spirv,msl,hlsl,glsl"),
    ("storage", "wgsl,spirv,msl,hlsl"),
    ("hlsl", "wgsl,spirv,msl,hlsl,glsl"),
];

/// The compiler named in the object files' headers, and each object's hash by its key.
fn fingerprint(cache: &std::path::Path) -> (String, BTreeMap<String, String>) {
    let mut compiler = String::new();
    let mut objects = BTreeMap::new();
    for entry in walkdir::WalkDir::new(cache.join("objects")).into_iter().map(|e| e.expect("walk")) {
        if !entry.file_type().is_file() {
            continue;
        }
        let bytes = std::fs::read(entry.path()).expect("object");
        let header = bytes.split(|&b| b == b'\n').nth(1).expect("a header line");
        let header: serde_json::Value = serde_json::from_slice(header).expect("the header is JSON");
        compiler = header["compiler"].as_str().expect("the compiler's name").to_string();
        let key = entry.file_name().to_string_lossy().to_string();
        objects.insert(key, blake3::hash(&bytes).to_hex()[..32].to_string());
    }
    (compiler, objects)
}

fn parse(pinned: &str) -> (String, BTreeMap<String, String>) {
    let mut lines = pinned.lines();
    let compiler = lines.next().unwrap_or_default().to_string();
    let objects =
        lines.filter_map(|l| l.split_once(' ')).map(|(k, h)| (k.to_string(), h.to_string())).collect();
    (compiler, objects)
}

#[test]
fn compiled_outputs_change_only_with_a_new_compiler_revision() {
    let dir = tempfile::tempdir().expect("temp dir");
    let cache = dir.path().join("cache");
    let mut written = std::collections::BTreeSet::new();
    for (fixture, backends) in FIXTURES {
        let output = dir.path().join(fixture);
        let run = kiln(&[
            "build",
            &format!("fixtures/{fixture}"),
            "--output",
            output.to_str().expect("UTF-8"),
            "--cache-dir",
            cache.to_str().expect("UTF-8"),
            "--backends",
            backends,
        ]);
        assert!(run.status.success(), "{fixture}: {}", String::from_utf8_lossy(&run.stderr));
        let manifest = kiln::manifest::Manifest::read(&output).expect("a manifest");
        written.extend(
            manifest
                .files()
                .iter()
                .filter_map(|file| Some(file.path.file_name().split_once('.')?.1.to_string())),
        );
    }
    assert_eq!(written.len(), kiln::manifest::Backend::ALL.len(), "back ends pinned: {written:?}");
    let (compiler, objects) = fingerprint(&cache);
    assert!(objects.len() >= 20, "{} objects", objects.len());
    let golden = root().join("tests/golden/fingerprint.txt");
    let (pinned_compiler, pinned) = parse(&std::fs::read_to_string(&golden).unwrap_or_default());
    if pinned_compiler == compiler {
        let changed: Vec<&String> = objects
            .iter()
            .filter(|(key, hash)| pinned.get(*key).is_some_and(|p| p != *hash))
            .map(|(k, _)| k)
            .collect();
        assert!(
            changed.is_empty(),
            "{} cache objects hold other bytes than `{compiler}` put under the same keys ({changed:?}): \
             a shared cache filled before this change would serve them stale. Raise COMPILER_REVISION \
             (src/orchestrate/mod.rs), then pin the new outputs: UPDATE_EXPECT=1 cargo test --test it fingerprint",
            changed.len()
        );
    }
    let listed: String = objects.iter().map(|(key, hash)| format!("{key} {hash}\n")).collect();
    expect_test::expect_file![golden].assert_eq(&format!("{compiler}\n{listed}"));
}
