//! Sharded builds: shards built by concurrent processes merge into the bytes one build writes,
//! a second round compiles nothing, a new shader costs the shards only its own modules, a shard
//! preprocesses nothing of passes that are not its own, and merge refuses shards that do not
//! belong together.

use crate::support::{compiled, kiln, shipped, synthetic_project, tree};
use expect_test::expect_file;
use std::path::{Path, PathBuf};
use std::process::{Command, Output};

fn text(output: &Output) -> String {
    String::from_utf8_lossy(&output.stderr).into_owned()
}

/// `kiln build --shard i/N` for every shard at once, as N processes (sharing a module cache when
/// one is given).
fn build_shards(project: &Path, shards: &[PathBuf], cache: Option<&Path>) -> Vec<String> {
    let children: Vec<_> = shards
        .iter()
        .enumerate()
        .map(|(i, out)| {
            Command::new(env!("CARGO_BIN_EXE_kiln"))
                .args(["build", project.to_str().expect("utf-8"), "--output", out.to_str().expect("utf-8")])
                .args(["--shard", &format!("{}/{}", i + 1, shards.len())])
                .args(
                    cache
                        .map(|c| ["--cache-dir".to_string(), c.to_string_lossy().into_owned()])
                        .into_iter()
                        .flatten(),
                )
                .stderr(std::process::Stdio::piped())
                .spawn()
                .expect("kiln runs")
        })
        .collect();
    children
        .into_iter()
        .map(|child| {
            let output = child.wait_with_output().expect("kiln ends");
            assert_eq!(output.status.code(), Some(0), "{}", text(&output));
            text(&output)
        })
        .collect()
}

/// A project of 1,024 variants: the synthetic one (256 materials of one shader) four times over,
/// under four shader names.
fn project_of_1024_variants(project: &Path) {
    synthetic_project(project, 256);
    let shader = std::fs::read_to_string(project.join("Synth.shader")).expect("shader");
    for copy in 2..=4 {
        let name = format!("Custom RP/Lit {copy}");
        // Another name, and a constant (kept in every stage) that makes every stage text its own.
        let renamed = shader.replace("Shader \"Custom RP/Lit\"", &format!("Shader {name:?}")).replacen(
            "WGSLPROGRAM\n",
            &format!("WGSLPROGRAM\n            const KILN_COPY: u32 = {copy}u;\n"),
            1,
        );
        assert_ne!(renamed, shader);
        std::fs::write(project.join(format!("Synth{copy}.shader")), renamed).expect("write");
        for m in 0..256 {
            let material =
                std::fs::read_to_string(project.join(format!("materials/M{m:03}.mat"))).expect("mat");
            let material = material.replace("\"Custom RP/Lit\"", &format!("{name:?}"));
            std::fs::write(project.join(format!("materials/M{m:03}_{copy}.mat")), material).expect("write");
        }
    }
}

/// The synthetic project (16 variants of one pass) under `dir`, built as `count` shards.
fn synthetic_shards(dir: &Path, count: usize) -> (PathBuf, Vec<PathBuf>) {
    let project = dir.join("project");
    synthetic_project(&project, 16);
    let shards: Vec<PathBuf> = (1..=count).map(|i| dir.join(format!("shard{i}"))).collect();
    build_shards(&project, &shards, None);
    (project, shards)
}

/// The first pack file in the shards' folders.
fn first_pack(shards: &[PathBuf]) -> PathBuf {
    shards
        .iter()
        .flat_map(|shard| walkdir::WalkDir::new(shard.join("modules")).into_iter().flatten())
        .find(|e| e.file_type().is_file())
        .expect("a pack")
        .into_path()
}

fn merge(out: &Path, shards: &[PathBuf]) -> Output {
    let mut args = vec!["merge".to_string(), out.to_string_lossy().into_owned()];
    args.extend(shards.iter().map(|s| s.to_string_lossy().into_owned()));
    let args: Vec<&str> = args.iter().map(String::as_str).collect();
    kiln(&args)
}

#[test]
fn four_concurrent_shards_merge_into_the_bytes_of_one_build() {
    let dir = tempfile::tempdir().expect("temp dir");
    let project = dir.path().join("project");
    project_of_1024_variants(&project);
    let shards: Vec<PathBuf> = (1..=4).map(|i| dir.path().join(format!("shard{i}"))).collect();
    let cache = dir.path().join("cache");
    let summaries = build_shards(&project, &shards, Some(&cache));
    // Each shard says what it built, not the project's counts: the shards' add up to them.
    let counts: Vec<[usize; 3]> = summaries.iter().map(|s| crate::support::built_counts(s)).collect();
    let variants: Vec<usize> = counts.iter().map(|[_, _, variants]| *variants).collect();
    assert!(variants.iter().all(|&v| v < 1024), "{summaries:?}");
    assert_eq!(variants.iter().sum::<usize>(), 1024, "{summaries:?}");
    let passes: usize = counts.iter().map(|[_, passes, _]| passes).sum();
    let per_shard: Vec<usize> = summaries.iter().map(|s| compiled(s)).collect();
    assert!(per_shard.iter().all(|&n| n > 150), "every shard does its share: {per_shard:?}");

    let single = dir.path().join("single");
    let run = kiln(&["build", project.to_str().expect("utf-8"), "--output", single.to_str().expect("utf-8")]);
    assert_eq!(run.status.code(), Some(0), "{}", text(&run));
    let [_, whole_passes, whole_variants] = crate::support::built_counts(&text(&run));
    assert_eq!((passes, whole_variants), (whole_passes, 1024), "{}", text(&run));
    // No module is compiled by two shards: the shards' work adds up to one build's.
    assert_eq!(per_shard.iter().sum::<usize>(), compiled(&text(&run)), "{summaries:?}");

    let merged = dir.path().join("merged");
    let run = merge(&merged, &shards);
    assert_eq!(run.status.code(), Some(0), "{}", text(&run));
    assert!(text(&run).contains("naga compiled none"), "{}", text(&run));
    let (ours, theirs) = (tree(&merged), tree(&single));
    assert_eq!(ours.keys().collect::<Vec<_>>(), theirs.keys().collect::<Vec<_>>());
    for (path, bytes) in &ours {
        assert!(bytes == &theirs[path], "{} differs", path.display());
    }
    println!(
        "{} files, {} modules from 4 shards, byte-identical to one build",
        ours.len(),
        per_shard.iter().sum::<usize>()
    );
    // The project named (its files read while the shards' records are), the same bytes; a
    // project that is not there, no output.
    let named = dir.path().join("merged_named");
    let mut args: Vec<String> = ["merge", named.to_str().expect("utf-8")].map(String::from).to_vec();
    args.extend(shards.iter().map(|s| s.to_string_lossy().into_owned()));
    let with_project = |project: &Path| {
        let mut args = args.clone();
        args.extend(["--project".to_string(), project.to_string_lossy().into_owned()]);
        kiln(&args.iter().map(String::as_str).collect::<Vec<_>>())
    };
    let missing = with_project(&dir.path().join("no_such_project"));
    assert_eq!(missing.status.code(), Some(2), "{}", text(&missing));
    assert!(text(&missing).contains("no_such_project` does not exist"), "{}", text(&missing));
    assert!(!named.exists(), "nothing written");
    let run = with_project(&project);
    assert_eq!(run.status.code(), Some(0), "{}", text(&run));
    assert!(tree(&named) == ours, "a merge naming its project writes the same bytes");

    // A second round finds every module in place and compiles nothing; so do fresh shard
    // folders, from the cache the first round shared.
    for summary in build_shards(&project, &shards, Some(&cache)) {
        assert_eq!(compiled(&summary), 0, "{summary}");
    }

    let fresh: Vec<PathBuf> = (1..=4).map(|i| dir.path().join(format!("fresh{i}"))).collect();
    for summary in build_shards(&project, &fresh, Some(&cache)) {
        assert_eq!(compiled(&summary), 0, "{summary}");
    }

    // A build script can start from the merged folder, and compiles nothing.
    let out_dir = dir.path().join("out_dir");
    let output = kiln::Build::new(&project).prebuilt(&merged).out_dir(&out_dir).execute().expect("builds");
    assert_eq!(output.summary.compiled, 0);
    assert!(output.cargo_lines.iter().any(|l| l.contains("nothing compiled")), "{:?}", output.cargo_lines);
    // It asks cargo to watch what a build that compiled does, includes too.
    let compiled_here =
        kiln::Build::new(&project).out_dir(dir.path().join("out_dir2")).execute().expect("builds");
    assert!(compiled_here.summary.compiled > 0);
    let watched = |lines: &[String]| -> Vec<String> {
        lines.iter().filter(|l| l.starts_with("cargo:rerun-if-changed=")).cloned().collect()
    };
    assert_eq!(watched(&output.cargo_lines), watched(&compiled_here.cargo_lines));
    assert!(
        watched(&output.cargo_lines).iter().any(|l| l.ends_with("SynthPass.wgsl")),
        "{:?}",
        output.cargo_lines
    );
}

#[test]
fn a_new_shader_costs_the_shards_only_its_own_modules() {
    let dir = tempfile::tempdir().expect("temp dir");
    let project = dir.path().join("project");
    synthetic_project(&project, 64);
    let shards: Vec<PathBuf> = (1..=4).map(|i| dir.path().join(format!("shard{i}"))).collect();
    let first = build_shards(&project, &shards, None);
    assert!(first.iter().map(|s| compiled(s)).sum::<usize>() > 2);
    // A second shader, used by a material.
    let root = crate::support::root().join("fixtures/project/shaders");
    for name in ["Unlit.shader", "UnlitPass.wgsl"] {
        std::fs::copy(root.join(name), project.join(name)).expect("copy");
    }
    std::fs::write(project.join("materials/Unlit.mat"), "shader = \"Custom RP/Unlit\"\n").expect("write");
    // A pass lighter than every other one moves none of them: each shard folder still holds its
    // passes, and only the new one is compiled, by one shard.
    let again: Vec<usize> = build_shards(&project, &shards, None).iter().map(|s| compiled(s)).collect();
    assert_eq!(again.iter().sum::<usize>(), 2, "the Unlit pass's vertex and fragment modules: {again:?}");
    assert_eq!(again.iter().filter(|&&n| n > 0).count(), 1, "{again:?}");
}

#[test]
fn a_shard_preprocesses_only_its_own_passes() {
    let dir = tempfile::tempdir().expect("temp dir");
    let project = dir.path().join("project");
    project_of_1024_variants(&project);
    // A mistake in one shader's program that only preprocessing finds: the shard that owns its
    // pass reports it; the others never preprocess that pass and build cleanly.
    let shader = project.join("Synth3.shader");
    let text = std::fs::read_to_string(&shader).expect("shader");
    std::fs::write(
        &shader,
        text.replacen("WGSLPROGRAM\n", "WGSLPROGRAM\n            #error only its owner sees this\n", 1),
    )
    .expect("write");
    let outcomes: Vec<Option<i32>> = (1..=4)
        .map(|i| {
            let out = dir.path().join(format!("shard{i}"));
            let run =
                kiln(&["build", text_of(&project), "--output", text_of(&out), "--shard", &format!("{i}/4")]);
            run.status.code()
        })
        .collect();
    assert_eq!(outcomes.iter().filter(|c| **c == Some(1)).count(), 1, "{outcomes:?}");
    assert_eq!(outcomes.iter().filter(|c| **c == Some(0)).count(), 3, "{outcomes:?}");
}

fn text_of(path: &Path) -> &str {
    path.to_str().expect("utf-8")
}

#[test]
fn merge_refuses_shards_that_do_not_belong_together() {
    let dir = tempfile::tempdir().expect("temp dir");
    let (project, shards) = synthetic_shards(dir.path(), 3);
    let refused = |shards: &[PathBuf], expected: &str| {
        let run = merge(&dir.path().join("merged"), shards);
        assert_eq!(run.status.code(), Some(2), "{}", text(&run));
        assert!(text(&run).contains(expected), "{expected}: {}", text(&run));
    };
    refused(&shards[..2], "shard 3/3 is missing");
    refused(&[shards[0].clone(), shards[0].clone(), shards[1].clone()], "shard 1/3 is given twice");
    refused(&[shards[0].clone(), dir.path().join("nothing")], "is not a shard's output");

    // A shard of another build (another shard count) does not belong.
    let other = dir.path().join("other");
    let run = kiln(&[
        "build",
        project.to_str().expect("utf-8"),
        "--output",
        other.to_str().expect("utf-8"),
        "--shard",
        "1/2",
    ]);
    assert_eq!(run.status.code(), Some(0), "{}", text(&run));
    refused(&[other.clone(), shards[1].clone(), shards[2].clone()], "a different number of shards");

    // A shard of another project.
    let elsewhere = dir.path().join("elsewhere");
    synthetic_project(&elsewhere, 8);
    let stranger = dir.path().join("stranger");
    let run = kiln(&[
        "build",
        elsewhere.to_str().expect("utf-8"),
        "--output",
        stranger.to_str().expect("utf-8"),
        "--shard",
        "2/3",
    ]);
    assert_eq!(run.status.code(), Some(0), "{}", text(&run));
    refused(&[shards[0].clone(), stranger, shards[2].clone()], "another project");

    // Another kiln.
    let record_path = shards[2].join("shard.json");
    let record = std::fs::read_to_string(&record_path).expect("record");
    std::fs::write(
        &record_path,
        sealed_again(&record, |r| r.replace(env!("CARGO_PKG_VERSION"), "0.0.1-other")),
    )
    .expect("write");
    refused(&shards, "kiln 0.0.1-other");
    // A record that claims shard 0 holds no shard of the merge (not a crash).
    assert!(record.contains("\"shard\":3,"), "{record}");
    std::fs::write(&record_path, sealed_again(&record, |r| r.replace("\"shard\":3,", "\"shard\":0,")))
        .expect("write");
    refused(&shards, "shard 3/3 is missing");
    // A record that is not JSON any more.
    std::fs::write(&record_path, &record[..record.len() / 2]).expect("write");
    refused(&shards, "shard.json` is damaged");
    std::fs::write(&record_path, record).expect("write");
    // A record that still parses but is not what the shard wrote (its parts would go into the
    // manifest as they are): refused by its hash, whatever changed.
    let first_record = shards[0].join("shard.json");
    let first = std::fs::read_to_string(&first_record).expect("record");
    assert!(first.contains("\"interfaces\""), "the first shard holds the pass");
    for (field, edited) in [("\"shard\":1,", "\"shard\":0,"), ("\"size\":", "\"size\":1")] {
        assert!(first.contains(field), "{field}");
        std::fs::write(&first_record, first.replacen(field, edited, 1)).expect("write");
        refused(&shards, "shard.json` is damaged: it is not the text the shard wrote");
    }
    // A pass's part that does not read: the merge names the shard and writes nothing.
    std::fs::write(&first_record, sealed_again(&first, |r| r.replace("\"interfaces\"", "\"interfacez\"")))
        .expect("write");
    let run = merge(&dir.path().join("merged"), &shards);
    assert_eq!(run.status.code(), Some(1), "{}", text(&run));
    assert!(text(&run).starts_with("error[K0412]: a pass's part in "), "{}", text(&run));
    assert!(!dir.path().join("merged/manifest.json").exists());
    // A part that reads but names a pack or an interface it does not list, or a module whose end
    // no offset can address, is damaged too (a pack index out of range made the merge panic).
    let past_any_pack = ("\"pack\":0,\"offset\":0,", "\"pack\":0,\"offset\":18446744073709551615,");
    for (field, edited) in
        [("\"pack\":1", "\"pack\":7"), ("\"interface\":0", "\"interface\":9"), past_any_pack]
    {
        assert!(first.contains(field), "{field}");
        std::fs::write(&first_record, sealed_again(&first, |r| r.replacen(field, edited, 1))).expect("write");
        let run = merge(&dir.path().join("merged"), &shards);
        assert_eq!(run.status.code(), Some(1), "{}", text(&run));
        assert!(text(&run).starts_with("error[K0412]: a pass's part in "), "{}", text(&run));
        assert!(!dir.path().join("merged/manifest.json").exists());
    }
    // A part whose module lies past its pack's end, or whose pack's recorded hash is not the
    // pack's: the merge finds no module of that pack intact.
    let other_hash = |r: &str| {
        let at = r.find("\"packs\":[\"").expect("the first pass's pack hashes") + "\"packs\":[\"".len();
        format!("{}{}{}", &r[..at], "0".repeat(32), &r[at + 32..])
    };
    let edits: [&dyn Fn(&str) -> String; 2] = [
        &|r| r.replacen("\"pack\":0,\"offset\":0,\"size\":", "\"pack\":0,\"offset\":0,\"size\":99999999", 1),
        &other_hash,
    ];
    for edit in edits {
        let edited = sealed_again(&first, edit);
        assert_ne!(edited, first);
        std::fs::write(&first_record, edited).expect("write");
        let run = merge(&dir.path().join("merged"), &shards);
        assert_eq!(run.status.code(), Some(1), "{}", text(&run));
        assert!(text(&run).starts_with("error[K0412]: no shard holds the "), "{}", text(&run));
        assert!(!dir.path().join("merged/manifest.json").exists());
    }
    std::fs::write(&first_record, first).expect("write");

    // The project changed since the shards were built: an error, and nothing written.
    let shader = project.join("Synth.shader");
    let text_before = std::fs::read_to_string(&shader).expect("shader");
    std::fs::write(&shader, format!("{text_before}\n// edited\n")).expect("edit");
    let run = merge(&dir.path().join("merged"), &shards);
    assert_eq!(run.status.code(), Some(1), "{}", text(&run));
    expect_file![crate::support::root().join("tests/golden/shards/project_changed.stderr")]
        .assert_eq(&diagnostics(&run));
    assert!(!dir.path().join("merged/manifest.json").exists());
    std::fs::write(&shader, &text_before).expect("restore");
    // A file the shards never saw (a new material): the project is not what they read either.
    let added = project.join("materials/New.mat");
    std::fs::write(&added, "shader = \"Custom RP/Lit\"\n").expect("write");
    let run = merge(&dir.path().join("merged"), &shards);
    assert_eq!(run.status.code(), Some(1), "{}", text(&run));
    assert!(text(&run).starts_with("error[K0413]"), "{}", text(&run));
    std::fs::remove_file(&added).expect("remove");

    // A shard's pack with a byte changed (its length kept), cut short, or gone: the merge names a
    // module it cannot find intact, and writes nothing.
    let victim = first_pack(&shards);
    let intact = std::fs::read(&victim).expect("pack");
    let mut changed = intact.clone();
    changed[intact.len() / 2] ^= 1;
    for damaged in [Some(changed), Some(intact[..intact.len() - 1].to_vec()), None] {
        match damaged {
            Some(bytes) => std::fs::write(&victim, bytes).expect("damage"),
            None => std::fs::remove_file(&victim).expect("remove"),
        }
        let run = merge(&dir.path().join("merged"), &shards);
        assert_eq!(run.status.code(), Some(1), "{}", text(&run));
        let shown = diagnostics(&run);
        assert!(shown.starts_with("error[K0412]: no shard holds the "), "{shown}");
        let name = victim.file_name().expect("name").to_string_lossy().into_owned();
        assert!(shown.contains(&name), "{shown}");
        assert!(!dir.path().join("merged/manifest.json").exists());
    }
}

#[test]
fn a_merge_that_cannot_link_a_pack_replaces_neither_manifest_nor_materials() {
    let dir = tempfile::tempdir().expect("temp dir");
    let (_, shards) = synthetic_shards(dir.path(), 2);
    // An earlier build's files in the output, and a folder where one of the packs must go: the
    // manifest and the materials are written while the packs are linked, and must stay unused.
    let merged = dir.path().join("merged");
    std::fs::create_dir_all(&merged).expect("mkdir");
    for name in ["manifest.json", "materials.json"] {
        std::fs::write(merged.join(name), "an earlier build's\n").expect("write");
    }
    let pack = first_pack(&shards);
    let pack = pack.file_name().expect("a name");
    let in_the_way = merged.join("modules").join(pack).join("in the way");
    std::fs::create_dir_all(&in_the_way).expect("mkdir");
    let run = merge(&merged, &shards);
    assert_eq!(run.status.code(), Some(1), "{}", text(&run));
    assert!(text(&run).contains("error[K0410]: cannot write to "), "{}", text(&run));
    for name in ["manifest.json", "materials.json"] {
        assert_eq!(std::fs::read_to_string(merged.join(name)).expect("read"), "an earlier build's\n");
    }
    let left: Vec<String> = std::fs::read_dir(&merged)
        .expect("list")
        .flatten()
        .map(|e| e.file_name().to_string_lossy().into_owned())
        .filter(|name| name.ends_with(".tmp"))
        .collect();
    assert!(left.is_empty(), "{left:?}");
    // Out of the way, the same merge writes one build's output.
    std::fs::remove_dir_all(merged.join("modules").join(pack)).expect("remove");
    let run = merge(&merged, &shards);
    assert_eq!(run.status.code(), Some(0), "{}", text(&run));
    assert_ne!(std::fs::read_to_string(merged.join("manifest.json")).expect("read"), "an earlier build's\n");
}

/// `shard.json`'s text with `edit` applied to its record and the record sealed again, as a shard
/// that wrote the edited record would have written it.
fn sealed_again(text: &str, edit: impl Fn(&str) -> String) -> String {
    let record = kiln::store::unsealed("shard.json", text.as_bytes()).expect("a sealed record");
    let edited = edit(std::str::from_utf8(record).expect("utf-8"));
    let raw = serde_json::value::RawValue::from_string(edited).expect("still JSON");
    String::from_utf8(kiln::store::sealed("shard.json", &raw).expect("sealed")).expect("utf-8")
}

/// The diagnostics of a run, without its closing summary line (which has timings).
fn diagnostics(run: &Output) -> String {
    text(run).lines().take_while(|l| !l.starts_with("built ")).map(|l| format!("{l}\n")).collect()
}

#[test]
fn indented_shards_merge_into_the_bytes_of_one_indented_build() {
    let dir = tempfile::tempdir().expect("temp dir");
    let project = dir.path().join("project");
    synthetic_project(&project, 16);
    let run = |args: &[&str]| {
        let run = kiln(args);
        assert_eq!(run.status.code(), Some(0), "{}", text(&run));
    };
    let path = |name: &str| dir.path().join(name).to_string_lossy().into_owned();
    run(&["build", text_of(&project), "--pretty", "--output", &path("single")]);
    for shard in ["1/2", "2/2"] {
        let out = path(&format!("shard{}", &shard[..1]));
        run(&["build", text_of(&project), "--pretty", "--shard", shard, "--output", &out]);
    }
    run(&["merge", &path("merged"), &path("shard1"), &path("shard2"), "--pretty"]);
    for file in ["manifest.json", "materials.json"] {
        let read = |folder: &str| std::fs::read(dir.path().join(folder).join(file)).expect("written");
        assert_eq!(read("merged"), read("single"), "{file}");
        assert!(
            read("merged").starts_with(b"{\n") || read("merged").starts_with(b"[\n"),
            "{file} is indented"
        );
    }
}

/// The crash sweep for `kiln merge`: killed (debug builds: `KILN_KILL_AT`) just before each of its
/// renames and links in turn, over a folder holding an earlier merge of other shards; the merge
/// run again then writes a whole build's bytes, every time.
#[test]
fn a_merge_killed_before_any_rename_or_link_is_whole_when_run_again() {
    let dir = tempfile::tempdir().expect("temp dir");
    let (project, shards) = synthetic_shards(dir.path(), 2);
    let whole = dir.path().join("whole");
    let run = kiln(&["build", project.to_str().expect("utf-8"), "--output", whole.to_str().expect("utf-8")]);
    assert_eq!(run.status.code(), Some(0), "{}", text(&run));
    // Another state of the project, merged first into each folder the sweep kills merges over.
    let earlier = dir.path().join("earlier");
    std::fs::create_dir_all(&earlier).expect("mkdir");
    for entry in walkdir::WalkDir::new(&project).into_iter().flatten().filter(|e| e.file_type().is_file()) {
        let to = earlier.join(entry.path().strip_prefix(&project).expect("inside"));
        std::fs::create_dir_all(to.parent().expect("folder")).expect("mkdir");
        std::fs::copy(entry.path(), to).expect("copy");
    }
    std::fs::write(earlier.join("Tint.wgsl"), "#define TINT 0.75\n").expect("write");
    let earlier_shards: Vec<PathBuf> = (1..=2).map(|i| dir.path().join(format!("earlier{i}"))).collect();
    build_shards(&earlier, &earlier_shards, None);
    let mut kill_at = 1;
    loop {
        let out = dir.path().join(format!("merged{kill_at}"));
        assert_eq!(merge(&out, &earlier_shards).status.code(), Some(0));
        let mut args = vec!["merge".to_string(), out.to_string_lossy().into_owned()];
        args.extend(shards.iter().map(|s| s.to_string_lossy().into_owned()));
        let killed = Command::new(env!("CARGO_BIN_EXE_kiln"))
            .args(&args)
            .env("KILN_KILL_AT", kill_at.to_string())
            .output();
        if killed.expect("kiln runs").status.code() == Some(0) {
            break;
        }
        let again = merge(&out, &shards);
        assert_eq!(again.status.code(), Some(0), "killed at {kill_at}: {}", text(&again));
        assert!(
            shipped(&out) == shipped(&whole),
            "killed at {kill_at}: the merge run again is not a whole build"
        );
        kill_at += 1;
    }
    assert!(kill_at > 4, "a merge puts {} files in place", kill_at - 1);
}

/// The Starlark rules docs/scaling.md gives, run by Debian's `bazel-bootstrap` in its Linux
/// sandbox (inputs staged as links, outputs as `declare_directory` folders): four shards and the
/// merge write byte for byte what one plain build writes. The rules and the BUILD file are taken
/// from the doc itself, so the doc cannot drift from what runs.
#[test]
fn the_bazel_rules_in_the_docs_build_in_bazel_s_sandbox_what_a_plain_build_writes() {
    if !crate::support::tool("bazel", "bazel-bootstrap", "bazel_rules") {
        return;
    }
    let doc = std::fs::read_to_string(crate::support::root().join("docs/scaling.md")).expect("doc");
    let section = &doc[doc.find("## From Bazel").expect("the Bazel section")..];
    let blocks: Vec<&str> =
        section.split("```python\n").skip(1).map(|b| &b[..b.find("```").expect("end")]).collect();
    let (rules, build) = (blocks[0], blocks[1]);
    assert!(rules.contains("declare_directory") && build.contains("kiln_merge("), "{blocks:?}");

    let dir = tempfile::tempdir().expect("tempdir");
    let workspace = dir.path().join("workspace");
    let package = workspace.join("game");
    std::fs::create_dir_all(workspace.join("tools")).expect("tools");
    let project = crate::support::example_project_copy(&package);
    std::fs::rename(&project, package.join("shaders")).expect("the project where the BUILD file has it");
    std::fs::write(workspace.join("WORKSPACE"), "").expect("WORKSPACE");
    std::fs::write(package.join("kiln.bzl"), rules).expect("rules");
    std::fs::write(package.join("BUILD"), build).expect("BUILD");
    std::fs::write(
        workspace.join("tools/BUILD"),
        "exports_files([\"kiln\"], visibility = [\"//visibility:public\"])\n",
    )
    .expect("tools");
    let wrapper = workspace.join("tools/kiln");
    std::fs::write(&wrapper, format!("#!/bin/sh\nexec '{}' \"$@\"\n", env!("CARGO_BIN_EXE_kiln")))
        .expect("wrapper");
    let mut permissions = std::fs::metadata(&wrapper).expect("meta").permissions();
    std::os::unix::fs::PermissionsExt::set_mode(&mut permissions, 0o755);
    std::fs::set_permissions(&wrapper, permissions).expect("chmod");

    // Bazel's own state in the test's folder; the sandbox required, never a silent fallback to
    // running the actions unsandboxed.
    let user_root = dir.path().join("bazel-root");
    let bazel = Command::new("bazel")
        .arg("--batch")
        .arg(format!("--output_user_root={}", user_root.display()))
        .args(["build", "//game:kiln_build", "--spawn_strategy=linux-sandbox", "--noshow_progress"])
        .current_dir(&workspace)
        .env_remove("KILN_FOLLOW_LINKS")
        .output()
        .expect("bazel runs");
    assert!(bazel.status.success(), "bazel build failed:\n{}", text(&bazel));
    let staged = text(&bazel);
    assert!(staged.contains("merged 4 shards"), "{staged}");

    let plain = dir.path().join("plain");
    let built = kiln(&[
        "build",
        package.join("shaders").to_str().expect("utf-8"),
        "--output",
        plain.to_str().expect("utf-8"),
    ]);
    assert!(built.status.success(), "{}", text(&built));
    let bazel_output = workspace.join("bazel-bin/game/kiln_build");
    let (from_bazel, from_plain) = (tree(&bazel_output), tree(&plain));
    assert!(from_plain.keys().any(|k| k.starts_with("modules")), "{:?}", from_plain.keys());
    assert_eq!(
        from_bazel.keys().collect::<Vec<_>>(),
        from_plain.keys().collect::<Vec<_>>(),
        "the same files"
    );
    assert!(
        from_bazel == from_plain,
        "Bazel's sandboxed shards and merge wrote other bytes than a plain build"
    );
    // Bazel leaves its output base read-only; the folder is removed only once it is writable.
    let _ = Command::new("chmod").args(["-R", "u+w"]).arg(dir.path()).status();
}
