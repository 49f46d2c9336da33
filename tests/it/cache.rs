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

/// Every object of the shared cache, as (path, bytes), in path order.
fn objects(cache: &Path) -> Vec<(PathBuf, Vec<u8>)> {
    let mut found: Vec<(PathBuf, Vec<u8>)> = walkdir::WalkDir::new(cache.join("objects"))
        .into_iter()
        .map(|e| e.expect("walk"))
        .filter(|e| e.file_type().is_file())
        .map(|e| (e.path().to_path_buf(), std::fs::read(e.path()).expect("read")))
        .collect();
    found.sort();
    found
}

#[test]
fn swapped_or_edited_objects_are_misses_that_stats_counts_never_shipped() {
    let dir = tempfile::tempdir().expect("temp dir");
    let (project, cache) = (dir.path().join("project"), dir.path().join("cache"));
    synthetic_project(&project, 8);
    let first = dir.path().join("first");
    finished(build(&project, &first, Some(&cache)).output().expect("kiln runs"));
    let all = objects(&cache);
    assert!(all.len() >= 3, "{} objects", all.len());

    // Two whole, valid objects of one project swapped: each is the other key's.
    let (a, b) = (&all[0], &all[1]);
    std::fs::write(&a.0, &b.1).expect("swap");
    std::fs::write(&b.0, &a.1).expect("swap");
    // One digit of a uniform member's offset edited in a third object's header: its modules'
    // bytes and their hashes are untouched.
    let (c_path, c_bytes) = &all[2];
    let text = String::from_utf8_lossy(c_bytes).into_owned();
    let at = text.find("\"offset\":").expect("a member offset in the header") + "\"offset\":".len();
    let digit = text.as_bytes()[at];
    let mut edited = c_bytes.clone();
    edited[at] = if digit == b'9' { b'8' } else { digit + 1 };
    std::fs::write(c_path, &edited).expect("edit");
    assert!(stats(&cache).contains("3 damaged"), "{}", stats(&cache));

    let again = dir.path().join("again");
    let summary = finished(build(&project, &again, Some(&cache)).output().expect("kiln runs"));
    assert_eq!(compiled(&summary), 3, "the three are compiled again, none reused: {summary}");
    assert_eq!(tree(&again), tree(&first), "what ships is a clean build's");
    assert!(!stats(&cache).contains("damaged"), "rewritten: {}", stats(&cache));
}

#[cfg(unix)]
#[test]
fn links_planted_in_the_cache_are_replaced_never_written_through() {
    let dir = tempfile::tempdir().expect("temp dir");
    let (project, cache) = (dir.path().join("project"), dir.path().join("cache"));
    synthetic_project(&project, 8);
    finished(build(&project, &dir.path().join("first"), Some(&cache)).output().expect("kiln runs"));
    // Another user of the cache replaces every object with a link to a file of the victim's.
    let victim = dir.path().join("victim.txt");
    std::fs::write(&victim, "the victim's file\n").expect("write");
    let planted = objects(&cache);
    for (path, _) in &planted {
        std::fs::remove_file(path).expect("remove");
        std::os::unix::fs::symlink(&victim, path).expect("link");
    }
    let summary =
        finished(build(&project, &dir.path().join("again"), Some(&cache)).output().expect("kiln runs"));
    assert_eq!(compiled(&summary), planted.len(), "{summary}");
    assert_eq!(std::fs::read_to_string(&victim).expect("read"), "the victim's file\n");
    for (path, _) in &planted {
        assert!(!std::fs::symlink_metadata(path).expect("there").is_symlink(), "{} replaced", path.display());
    }
}

#[cfg(unix)]
#[test]
fn gc_of_a_cache_it_cannot_change_fails_and_says_what_is_left() {
    use std::os::unix::fs::PermissionsExt;
    let dir = tempfile::tempdir().expect("temp dir");
    let (project, cache) = (dir.path().join("project"), dir.path().join("cache"));
    synthetic_project(&project, 4);
    finished(build(&project, &dir.path().join("first"), Some(&cache)).output().expect("kiln runs"));
    let before = objects(&cache).len();
    let folders: Vec<PathBuf> = std::iter::once(dir.path().to_path_buf())
        .chain(
            walkdir::WalkDir::new(&cache)
                .into_iter()
                .map(|e| e.expect("walk"))
                .filter(|e| e.file_type().is_dir())
                .map(|e| e.into_path()),
        )
        .collect();
    // Read-only for whoever runs gc: the folders for this user, or, where this user is root
    // (whom permissions do not stop), the whole cache for another user that gc runs as.
    let as_root = running_as_root();
    for folder in &folders {
        std::fs::set_permissions(
            folder,
            std::fs::Permissions::from_mode(if as_root { 0o755 } else { 0o555 }),
        )
        .expect("permissions");
    }
    let limit = ["--max-size", "0", "--cache-dir", cache.to_str().expect("utf-8")];
    let run = if as_root {
        // A copy of the binary where the other user can run it (the checkout may be closed to it).
        let binary = dir.path().join("kiln");
        std::fs::copy(env!("CARGO_BIN_EXE_kiln"), &binary).expect("copy");
        std::fs::set_permissions(&binary, std::fs::Permissions::from_mode(0o755)).expect("executable");
        Command::new("setpriv")
            .args(["--reuid=65534", "--regid=65534", "--clear-groups"])
            .arg(&binary)
            .args(["cache", "gc"])
            .args(limit)
            .output()
            .expect("setpriv (util-linux) runs")
    } else {
        kiln(&[&["cache", "gc"][..], &limit[..]].concat())
    };
    for folder in &folders {
        std::fs::set_permissions(folder, std::fs::Permissions::from_mode(0o755)).expect("writable");
    }
    let stderr = String::from_utf8_lossy(&run.stderr);
    assert_eq!(run.status.code(), Some(2), "{stderr}");
    assert!(stderr.contains("removed 0 entries but not"), "{stderr}");
    assert_eq!(objects(&cache).len(), before, "everything is still there, as it says");
}

/// Whether this process runs as root (uid 0), from `/proc/self/status`.
fn running_as_root() -> bool {
    std::fs::read_to_string("/proc/self/status")
        .is_ok_and(|s| s.lines().any(|l| l.starts_with("Uid:") && l.split_whitespace().nth(1) == Some("0")))
}
