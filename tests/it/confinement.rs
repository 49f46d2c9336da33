//! Records kiln wrote earlier, as an adversary rewrites them: a manifest, a no-op record and a
//! shard record whose paths lead out of their folder, re-sealed (a seal needs no secret), and
//! packs replaced by links and devices. Nothing outside the folder is read, embedded or written.
//! The findings a no-op record keeps are said again only where they fit the files they name.

use crate::support::{build_clean as build, kiln, root};
use kiln::store::{hash, seal, unsealed};
use std::path::{Path, PathBuf};

/// A path out of any folder, to a file every Linux machine has.
const OUTSIDE: &str = "../../../../../../../../../../../../etc/hostname";

/// Rewrites the sealed JSON file at `path` (sealed under `key`) through `edit`, and seals it again.
fn reseal(path: &Path, key: &str, edit: impl FnOnce(&mut serde_json::Value)) {
    let bytes = std::fs::read(path).expect("a sealed record");
    let mut value: serde_json::Value =
        serde_json::from_slice(unsealed(key, &bytes).expect("sealed as kiln seals")).expect("JSON");
    edit(&mut value);
    let json = serde_json::to_vec(&value).expect("JSON");
    let mut sealed = seal(key, &json).into_bytes();
    sealed.push(b'\n');
    sealed.extend(json);
    std::fs::write(path, sealed).expect("write");
}

/// An output folder of the example project whose manifest names `OUTSIDE` for its first pack,
/// with its no-op record re-sealed to vouch for that manifest, as an attacker would ship it.
fn hostile_output(dir: &Path) -> PathBuf {
    let output = dir.join("prebuilt");
    build(&root().join("fixtures/project"), Some(&output));
    let manifest_path = output.join("manifest.json");
    let text = std::fs::read_to_string(&manifest_path).expect("manifest");
    let first: serde_json::Value = serde_json::from_str(&text).expect("JSON");
    let pack = first["shaders"][0]["passes"][0]["packs"][0].as_str().expect("a pack").to_string();
    let text = text.replace(&pack, OUTSIDE);
    std::fs::write(&manifest_path, &text).expect("write");
    reseal(&output.join(".cache/build/inputs.json"), ".cache/build/inputs.json", |record| {
        for file in record["files"].as_array_mut().expect("files") {
            if file["path"] == "manifest.json" {
                file["len"] = text.len().into();
                file["hash"] = hash(text.as_bytes()).into();
            }
            if file["path"] == pack.as_str() {
                file["path"] = OUTSIDE.into();
            }
        }
    });
    output
}

#[test]
fn a_manifest_naming_a_file_outside_its_folder_is_never_read_nor_embedded() {
    let dir = tempfile::tempdir().expect("temp dir");
    let output = hostile_output(dir.path());
    // The run time refuses the folder as damaged, naming the path it will not follow.
    let refused = kiln::runtime::Library::open(&output).expect_err("a manifest naming a path outside");
    assert!(refused.to_string().contains("is not a pack's path"), "{refused}");
    // A build script starting from it distrusts the record, builds, and embeds only its packs.
    let out_dir = dir.path().join("out_dir");
    kiln::Build::new(root().join("fixtures/project"))
        .prebuilt(&output)
        .out_dir(&out_dir)
        .execute()
        .expect("builds");
    let rebuilt = std::fs::read_to_string(out_dir.join("kiln/manifest.json")).expect("manifest");
    assert!(!rebuilt.contains(OUTSIDE), "the re-sealed record was trusted as a no-op");
    let module = std::fs::read_to_string(out_dir.join("kiln_shaders.rs")).expect("the generated module");
    assert!(!module.contains("etc/hostname"), "a path out of the folder was embedded");
    let included: Vec<&str> =
        module.split("include_").skip(1).map(|rest| rest.split(')').next().unwrap_or("")).collect();
    assert!(!included.is_empty());
    for path in included {
        assert!(!path.contains(".."), "a path out of the folder was embedded: {path}");
    }
    kiln::runtime::Library::open(out_dir.join("kiln")).expect("the folder the build script made opens");
    // And `kiln build` into the hostile folder itself rebuilds it rather than taking it as a no-op.
    build(&root().join("fixtures/project"), Some(&output));
    assert!(!std::fs::read_to_string(output.join("manifest.json")).expect("manifest").contains(OUTSIDE));
}

#[cfg(target_os = "linux")]
#[test]
fn a_pack_replaced_by_a_link_or_a_device_is_not_read() {
    let dir = tempfile::tempdir().expect("temp dir");
    let output = dir.path().join("out");
    let project = root().join("fixtures/project");
    build(&project, Some(&output));
    let manifest = kiln::manifest::Manifest::read(&output).expect("manifest");
    let (pack, _) = manifest.packs().into_iter().next().expect("a pack");
    let pack = output.join(&pack);
    for target in ["/dev/zero", "/etc/hostname"] {
        std::fs::remove_file(&pack).expect("remove");
        std::os::unix::fs::symlink(target, &pack).expect("link");
        // `/dev/zero` read whole would never end; a link is refused before anything is read.
        let refused = kiln::runtime::Library::open(&output).expect_err("a pack that is a link");
        assert!(refused.to_string().contains("not a regular file"), "{refused}");
        // The next build does not take the folder as unchanged: the link is replaced by the pack.
        build(&project, Some(&output));
        assert!(std::fs::symlink_metadata(&pack).expect("the pack").is_file(), "{target}: the link was kept");
        kiln::runtime::Library::open_verified(&output).expect("the rebuilt folder opens");
    }
}

/// A change an attacker makes to a record's JSON.
type Edit = fn(&mut serde_json::Value);

/// Builds the example project as one shard into `shard`.
fn one_shard(shard: &Path) {
    let run = kiln(&[
        "build",
        root().join("fixtures/project").to_str().expect("utf-8"),
        "--output",
        shard.to_str().expect("utf-8"),
        "--shard",
        "1/1",
    ]);
    assert_eq!(run.status.code(), Some(0), "{}", String::from_utf8_lossy(&run.stderr));
}

#[test]
fn a_shard_record_naming_paths_outside_its_folder_writes_nothing_outside() {
    let dir = tempfile::tempdir().expect("temp dir");
    let (shards, merges) = (dir.path().join("shards"), dir.path().join("merges"));
    let shard = shards.join("s1");
    one_shard(&shard);
    // What the paths below reach from the shard's copy: a pack's bytes (so the record's hashes
    // and offsets still hold) and a pass's cache entry, beside the shards.
    let record = std::fs::read(shard.join("shard.json")).expect("the record");
    let record: serde_json::Value =
        serde_json::from_slice(unsealed("shard.json", &record).expect("sealed")).expect("JSON");
    let part: serde_json::Value =
        serde_json::from_str(&record["passes"][0]["manifest"].to_string()).expect("a part");
    let pack = part["packs"][0].as_str().expect("a pack");
    std::fs::copy(shard.join(pack), shards.join("payload.pack")).expect("copy");
    std::fs::write(shards.join("escaped.json"), b"{}").expect("write");
    let hostile: [(&str, Edit); 2] = [
        ("pack", |record| {
            let pass = &mut record["passes"][0];
            let mut part: serde_json::Value =
                serde_json::from_str(&pass["manifest"].to_string()).expect("a part");
            part["packs"][0] = "../payload.pack".into();
            pass["manifest"] = part;
        }),
        ("key", |record| record["passes"][0]["key"] = "../../../escaped".into()),
    ];
    for (what, edit) in hostile {
        let copy = shards.join(format!("copy-{what}"));
        for (path, bytes) in crate::support::tree(&shard) {
            let to = copy.join(&path);
            std::fs::create_dir_all(to.parent().expect("folder")).expect("mkdir");
            std::fs::write(to, bytes).expect("write");
        }
        reseal(&copy.join("shard.json"), "shard.json", edit);
        let merged = merges.join(format!("merged-{what}"));
        let run = kiln(&["merge", merged.to_str().expect("utf-8"), copy.to_str().expect("utf-8")]);
        let stderr = String::from_utf8_lossy(&run.stderr);
        assert_ne!(run.status.code(), Some(0), "{what}: a hostile shard merged: {stderr}");
        assert!(stderr.contains("damaged") || stderr.contains("is not a"), "{what}: {stderr}");
        // Nothing appeared beside the merged folders.
        let beside: Vec<String> = (std::fs::read_dir(&merges).into_iter().flatten().flatten())
            .map(|e| e.file_name().to_string_lossy().into_owned())
            .filter(|name| !name.starts_with("merged-"))
            .collect();
        assert!(beside.is_empty(), "{what}: written outside the output folder: {beside:?}");
        assert!(!merged.join("manifest.json").exists(), "{what}: a manifest was written");
    }
}

/// A copy of `from` under `to` whose every file is a link to the original, as a sandbox stages a
/// project (Bazel's, GNU `cp -rs`).
#[cfg(unix)]
fn linked_copy(from: &Path, to: &Path) {
    for (path, _) in crate::support::tree(from) {
        if path.starts_with("build") {
            continue;
        }
        let link = to.join(&path);
        std::fs::create_dir_all(link.parent().expect("folder")).expect("mkdir");
        std::os::unix::fs::symlink(from.join(&path), link).expect("link");
    }
}

#[cfg(unix)]
#[test]
fn a_project_staged_as_links_fails_loudly_and_builds_the_same_bytes_when_links_are_followed() {
    let dir = tempfile::tempdir().expect("temp dir");
    let staged = dir.path().join("sandbox/project");
    linked_copy(&root().join("fixtures/project"), &staged);
    let plain = dir.path().join("plain");
    build(&root().join("fixtures/project"), Some(&plain));
    let run = |follow: bool| {
        let mut command = std::process::Command::new(env!("CARGO_BIN_EXE_kiln"));
        command.args(["build", ".", "--output"]).arg(dir.path().join("staged-out")).current_dir(&staged);
        command.env("NO_COLOR", "1");
        if follow {
            command.env("KILN_FOLLOW_LINKS", "1")
        } else {
            command.env_remove("KILN_FOLLOW_LINKS")
        };
        command.output().expect("kiln runs")
    };
    // Links out of the project are not followed by default, and a build of nothing fails.
    let refused = run(false);
    let stderr = String::from_utf8_lossy(&refused.stderr);
    assert_eq!(refused.status.code(), Some(1), "{stderr}");
    assert!(stderr.contains("error[K0009]") && stderr.contains("KILN_FOLLOW_LINKS=1"), "{stderr}");
    // Followed, the staged project builds byte for byte what the project itself does.
    let followed = run(true);
    assert_eq!(followed.status.code(), Some(0), "{}", String::from_utf8_lossy(&followed.stderr));
    assert_eq!(crate::support::shipped(&dir.path().join("staged-out")), crate::support::shipped(&plain));
}

/// The compact manifest of the example project, built once for the property test.
fn example_manifest() -> &'static (String, String) {
    static MANIFEST: std::sync::OnceLock<(String, String)> = std::sync::OnceLock::new();
    MANIFEST.get_or_init(|| {
        let dir = tempfile::tempdir().expect("temp dir");
        build(&root().join("fixtures/project"), Some(dir.path()));
        let text = std::fs::read_to_string(dir.path().join("manifest.json")).expect("manifest");
        let first: serde_json::Value = serde_json::from_str(&text).expect("JSON");
        let pack = first["shaders"][0]["passes"][0]["packs"][0].as_str().expect("a pack").to_string();
        (text, pack)
    })
}

/// Whether `path` names something under `folder` once its `..` are taken.
fn inside(path: &Path, folder: &Path) -> bool {
    kiln::source::normalize_lexically(path).starts_with(folder)
}

proptest::proptest! {
    #![proptest_config(proptest::prelude::ProptestConfig::with_cases(256))]

    /// Every record reader, given a record whose paths are anything an attacker writes (or bytes
    /// that are no record at all), either refuses it or names only files inside its folder, and
    /// never panics.
    #[test]
    fn records_of_any_bytes_name_no_path_outside_their_folder(
        path in "(\\.\\./|/|modules/|[0-9a-f]{4,32}|\\.|[a-z]{1,6}|\\\\|pack|%2e|\u{0}){0,12}",
        bytes in proptest::collection::vec(proptest::prelude::any::<u8>(), 0..512),
    ) {
        let folder = Path::new("/srv/kiln/output");
        let (manifest, pack) = example_manifest();
        let escaped = serde_json::to_string(&path).expect("a string");
        let hostile = manifest.replace(&format!("\"{pack}\""), &escaped);
        for text in [hostile.as_bytes(), &bytes] {
            if let Ok(manifest) = kiln::manifest::Manifest::parse(text) {
                for (pack, _) in manifest.packs() {
                    proptest::prop_assert!(inside(&pack.under(folder), folder), "{pack}");
                }
            }
            if let Ok(index) = serde_json::from_slice::<kiln::store::PassIndex>(text) {
                for file in index.stage.values().flat_map(|s| s.files.values().flatten()) {
                    proptest::prop_assert!(inside(&file.path.under(folder), folder), "{}", file.path);
                }
            }
            if let Ok(record) = serde_json::from_slice::<kiln::store::Recorded>(text) {
                for file in &record.files {
                    proptest::prop_assert!(inside(&file.path.under(folder), folder), "{}", file.path.as_str());
                }
            }
            let shard = tempfile::tempdir().expect("temp dir");
            std::fs::write(shard.path().join("shard.json"), text).expect("write");
            if let Ok(record) = kiln::orchestrate::shard::ShardRecord::read(shard.path()) {
                for pass in &record.passes {
                    let entry = kiln::store::pass_index_path(&pass.key);
                    proptest::prop_assert!(inside(&shard.path().join(entry), shard.path()), "{}", pass.key.as_str());
                }
            }
            let _ = kiln::runtime::read_trace(&String::from_utf8_lossy(text));
        }
        // And the hostile manifest itself is refused unless its path is a pack's.
        let parsed = kiln::manifest::Manifest::parse(hostile.as_bytes());
        proptest::prop_assert_eq!(parsed.is_ok(), kiln::manifest::PackPath::parse(&path).is_ok());
    }
}

/// A no-op record whose kept warnings were rewritten: places past a file's end, off a character,
/// in a file never read; an unregistered code; an error. None of them is said: the next build is
/// a full one and says only what it finds. A message that would send the terminal a code is said
/// with the code written out.
#[test]
fn a_no_op_record_s_findings_are_said_again_only_where_they_fit_the_files_read() {
    use crate::hlsl::{cg_build, cg_project};
    type Forgery = (&'static str, fn(&mut serde_json::Value));
    let forgeries: [Forgery; 6] = [
        ("past the end", |f| f["labels"][0]["end"] = 1_000_000.into()),
        ("start after end", |f| {
            f["labels"][0]["start"] = (f["labels"][0]["end"].as_u64().unwrap_or(0) + 1).into()
        }),
        ("a file never read", |f| f["labels"][0]["file"] = 99.into()),
        ("no place", |f| f["labels"] = serde_json::json!([])),
        ("an unregistered code", |f| f["code"] = "K9999".into()),
        ("an error", |f| f["severity"] = "error".into()),
    ];
    let variables = "#if defined(UNITY_SINGLE_PASS_STEREO)\nfloat4 _Eye;\n#endif\nfloat4 _Tint; // é\n";
    for (what, forge) in forgeries {
        let dir = tempfile::tempdir().expect("temp dir");
        let project = cg_project(dir.path(), variables, "");
        let (_, said) = cg_build(&project);
        let record = project.join("build/kiln/.cache/build/inputs.json");
        reseal(&record, ".cache/build/inputs.json", |record| forge(&mut record["findings"][0]));
        let (again, said_again) = cg_build(&project);
        assert!(again.summary.preprocessed > 0, "{what}: taken as a no-op: {:?}", again.summary);
        assert_eq!(said_again, said, "{what}");
    }
    // Off a character boundary: inside the two bytes of `é`.
    let dir = tempfile::tempdir().expect("temp dir");
    let project = cg_project(dir.path(), variables, "");
    cg_build(&project);
    let text =
        std::fs::read_to_string(project.join("CGIncludes/UnityShaderVariables.cginc")).expect("include");
    let inside = text.find('é').expect("é") + 1;
    reseal(&project.join("build/kiln/.cache/build/inputs.json"), ".cache/build/inputs.json", |record| {
        record["findings"][0]["labels"][0]["end"] = inside.into()
    });
    assert!(cg_build(&project).0.summary.preprocessed > 0, "a place off a character was said");
    // A message that fits but carries a terminal's escape is said, the escape written out.
    reseal(&project.join("build/kiln/.cache/build/inputs.json"), ".cache/build/inputs.json", |record| {
        record["findings"][0]["message"] = "\u{1b}[2Jcleared".into()
    });
    let (again, said) = cg_build(&project);
    assert!(again.summary.preprocessed == 0, "{:?}", again.summary);
    assert!(said.contains("\\u{1b}[2Jcleared") && !said.contains('\u{1b}'), "{said}");
}
