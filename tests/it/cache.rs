//! The shared module cache (`--cache-dir`): eight processes building overlapping projects into
//! one cache at once, twice, leave no damaged entry and every output verifies; a build from the
//! cache compiles nothing and writes the bytes of a build without it; a damaged entry is a miss;
//! gc shrinks the cache under its limit while a build keeps working.

use crate::support::{compiled, kiln, synthetic_project, tree, verified_manifest};
use std::path::{Path, PathBuf};
use std::process::{Command, Output, Stdio};

fn build(project: &Path, output: &Path, cache: Option<&Path>) -> Command {
    let mut command = Command::new(env!("CARGO_BIN_EXE_kiln"));
    command.args(["build", project.to_str().expect("utf-8"), "--output", output.to_str().expect("utf-8")]);
    if let Some(cache) = cache {
        command.args(["--cache-dir", cache.to_str().expect("utf-8")]);
    }
    command.stderr(Stdio::piped()).stdout(Stdio::piped());
    command
}

fn finished(output: Output) -> String {
    let stderr = String::from_utf8_lossy(&output.stderr).into_owned();
    assert_eq!(output.status.code(), Some(0), "{stderr}");
    stderr
}

fn stats(cache: &Path) -> String {
    let run = kiln(&["cache", "stats", "--cache-dir", cache.to_str().expect("utf-8")]);
    assert_eq!(run.status.code(), Some(0), "{}", String::from_utf8_lossy(&run.stderr));
    String::from_utf8_lossy(&run.stdout).into_owned()
}

/// The cache's size in bytes, from `kiln cache stats`.
fn bytes(stats: &str) -> u64 {
    let at = stats.find(" bytes").expect("bytes");
    stats[..at].rsplit(' ').next().expect("number").parse().expect("number")
}

#[test]
fn eight_concurrent_builds_share_one_cache_without_damage() {
    let dir = tempfile::tempdir().expect("temp dir");
    let cache = dir.path().join("cache");
    // Overlapping projects: the first 24 materials' variants are in all of them.
    let projects: Vec<PathBuf> = (0..8)
        .map(|i| {
            let project = dir.path().join(format!("project{i}"));
            synthetic_project(&project, 24 + 8 * (i % 4));
            project
        })
        .collect();
    for round in 0..2 {
        let outputs: Vec<PathBuf> = (0..8).map(|i| dir.path().join(format!("round{round}_{i}"))).collect();
        let children: Vec<_> = projects
            .iter()
            .zip(&outputs)
            .map(|(project, output)| build(project, output, Some(&cache)).spawn().expect("kiln runs"))
            .collect();
        let summaries: Vec<String> =
            children.into_iter().map(|c| finished(c.wait_with_output().expect("kiln ends"))).collect();
        for output in &outputs {
            verified_manifest(output);
        }
        if round == 1 {
            for summary in &summaries {
                assert_eq!(compiled(summary), 0, "the second round finds everything: {summary}");
            }
        }
        assert!(!stats(&cache).contains("damaged"), "{}", stats(&cache));
    }
    // What came from the cache is what a build without it writes.
    let cold = dir.path().join("cold");
    finished(build(&projects[3], &cold, None).output().expect("kiln runs"));
    assert_eq!(tree(&cold), tree(&dir.path().join("round1_3")));
    println!("{}", stats(&cache).trim());
}

#[test]
fn a_damaged_entry_is_a_miss_and_gc_keeps_builds_working() {
    let dir = tempfile::tempdir().expect("temp dir");
    let (project, cache) = (dir.path().join("project"), dir.path().join("cache"));
    synthetic_project(&project, 32);
    finished(build(&project, &dir.path().join("first"), Some(&cache)).output().expect("kiln runs"));

    // Damage one module: the next build compiles it again and writes the same bytes.
    let victim = walkdir::WalkDir::new(cache.join("objects"))
        .into_iter()
        .map(|e| e.expect("walk"))
        .find(|e| e.file_type().is_file())
        .expect("an entry");
    std::fs::write(victim.path(), b"damaged").expect("damage");
    assert!(stats(&cache).contains("1 damaged"), "{}", stats(&cache));
    let again = dir.path().join("again");
    let summary = finished(build(&project, &again, Some(&cache)).output().expect("kiln runs"));
    assert_eq!(compiled(&summary), 1, "{summary}");
    assert_eq!(tree(&again), tree(&dir.path().join("first")));

    // gc: under the limit, least recently used first.
    let before = bytes(&stats(&cache));
    let limit = before / 2;
    let run = kiln(&[
        "cache",
        "gc",
        "--max-size",
        &limit.to_string(),
        "--cache-dir",
        cache.to_str().expect("utf-8"),
    ]);
    assert_eq!(run.status.code(), Some(0), "{}", String::from_utf8_lossy(&run.stderr));
    assert!(bytes(&stats(&cache)) <= limit, "{}", stats(&cache));

    // A build while gc empties the cache again and again still succeeds, and verifies.
    let during = dir.path().join("during");
    let child = build(&project, &during, Some(&cache)).spawn().expect("kiln runs");
    for _ in 0..20 {
        let run = kiln(&["cache", "gc", "--max-size", "0", "--cache-dir", cache.to_str().expect("utf-8")]);
        assert_eq!(run.status.code(), Some(0), "{}", String::from_utf8_lossy(&run.stderr));
    }
    finished(child.wait_with_output().expect("kiln ends"));
    verified_manifest(&during);
    assert_eq!(tree(&during), tree(&dir.path().join("first")));
}

#[test]
fn the_cache_folder_comes_from_the_flag_the_environment_or_kiln_toml() {
    let dir = tempfile::tempdir().expect("temp dir");
    let project = dir.path().join("project");
    synthetic_project(&project, 4);
    // KILN_CACHE_DIR.
    let from_env = dir.path().join("from_env");
    let mut command = build(&project, &dir.path().join("a"), None);
    finished(command.env("KILN_CACHE_DIR", &from_env).output().expect("kiln runs"));
    assert!(stats(&from_env).contains(" modules"), "{}", stats(&from_env));
    // kiln.toml's cache_dir, relative to the project; the flag wins over it.
    let toml = std::fs::read_to_string(project.join("kiln.toml")).expect("kiln.toml");
    std::fs::write(project.join("kiln.toml"), format!("{toml}cache_dir = \"../from_toml\"\n"))
        .expect("write");
    let summary = finished(
        build(&project, &dir.path().join("b"), None)
            .env_remove("KILN_CACHE_DIR")
            .output()
            .expect("kiln runs"),
    );
    assert!(compiled(&summary) > 0, "{summary}");
    let from_toml = dir.path().join("from_toml");
    assert!(bytes(&stats(&from_toml)) > 0);
    let from_flag = dir.path().join("from_flag");
    finished(
        build(&project, &dir.path().join("c"), Some(&from_flag))
            .env_remove("KILN_CACHE_DIR")
            .output()
            .expect("kiln runs"),
    );
    assert!(bytes(&stats(&from_flag)) > 0);
    // `kiln cache` finds the project's cache_dir too, and says where it looked when none is set.
    let cache_command = |args: &[&str], project: &Path| {
        let mut command = Command::new(env!("CARGO_BIN_EXE_kiln"));
        command.arg("cache").args(args).arg(project).env_remove("KILN_CACHE_DIR").env("NO_COLOR", "1");
        command.output().expect("kiln runs")
    };
    let listed = cache_command(&["stats"], &project);
    assert_eq!(String::from_utf8_lossy(&listed.stdout), stats(&from_toml));
    finished(cache_command(&["gc", "--max-size", "0"], &project));
    assert_eq!(bytes(&stats(&from_toml)), 0);
    let bare = dir.path().join("bare");
    synthetic_project(&bare, 1);
    let refused = cache_command(&["stats"], &bare);
    assert_eq!(refused.status.code(), Some(2));
    let message = String::from_utf8_lossy(&refused.stderr);
    assert!(message.contains("no cache folder") && message.contains("kiln.toml"), "{message}");
    // A cache named by the flag or the environment needs no project: run from a folder whose
    // kiln.toml is broken, neither opens it.
    let elsewhere = dir.path().join("elsewhere");
    std::fs::create_dir_all(&elsewhere).expect("mkdir");
    std::fs::write(elsewhere.join("kiln.toml"), "shaders = [").expect("write");
    let in_elsewhere = |command: &mut Command| command.current_dir(&elsewhere).output().expect("kiln runs");
    let broken = in_elsewhere(
        Command::new(env!("CARGO_BIN_EXE_kiln")).args(["cache", "stats"]).env_remove("KILN_CACHE_DIR"),
    );
    assert_eq!(broken.status.code(), Some(1), "the broken kiln.toml is read when it is needed");
    let flag = in_elsewhere(
        Command::new(env!("CARGO_BIN_EXE_kiln")).args(["cache", "stats", "--cache-dir"]).arg(&from_flag),
    );
    assert_eq!(
        String::from_utf8_lossy(&flag.stdout),
        stats(&from_flag),
        "{}",
        String::from_utf8_lossy(&flag.stderr)
    );
    let env = in_elsewhere(
        Command::new(env!("CARGO_BIN_EXE_kiln"))
            .args(["cache", "gc", "--max-size", "0"])
            .env("KILN_CACHE_DIR", &from_flag),
    );
    assert_eq!(env.status.code(), Some(0), "{}", String::from_utf8_lossy(&env.stderr));
    assert_eq!(bytes(&stats(&from_flag)), 0);
}
