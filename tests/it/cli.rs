//! The command line as a user meets it: exit codes, output streams, colour.

use crate::support::kiln;

#[test]
fn exit_codes() {
    assert_eq!(kiln(&["list", "fixtures/project"]).status.code(), Some(0));
    assert_eq!(kiln(&["list", "fixtures/bad/unclosed_brace.shader"]).status.code(), Some(1));
    assert_eq!(kiln(&["list", "no/such/folder"]).status.code(), Some(2));
    assert_eq!(kiln(&["list", "--format", "yaml"]).status.code(), Some(2));
    assert_eq!(kiln(&["frobnicate"]).status.code(), Some(2));
}

#[test]
fn a_missing_path_is_named() {
    let output = kiln(&["list", "no/such/folder"]);
    assert!(String::from_utf8_lossy(&output.stderr).contains("`no/such/folder` does not exist"));
    expect_test::expect_file![crate::support::root().join("tests/golden/cli/missing_path.stderr")]
        .assert_eq(&String::from_utf8_lossy(&output.stderr));
    assert!(output.stdout.is_empty());
}

#[test]
fn good_files_are_listed_even_when_others_fail() {
    let output =
        kiln(&["list", "fixtures/project/shaders/Lit.shader", "fixtures/bad/missing_endwgsl.shader"]);
    assert_eq!(output.status.code(), Some(1));
    assert!(String::from_utf8_lossy(&output.stdout).contains("Custom RP/Lit"));
    assert!(String::from_utf8_lossy(&output.stderr).contains("fixtures/bad/missing_endwgsl.shader:4:13"));
}

#[test]
fn json_diagnostics_carry_line_and_column() {
    let output = kiln(&["list", "fixtures/bad/unknown_render_state_value.shader", "--format", "json"]);
    assert_eq!(output.status.code(), Some(1));
    let value: serde_json::Value = serde_json::from_slice(&output.stdout).expect("json on stdout");
    let first = &value["diagnostics"][0];
    assert_eq!(first["code"], "K0120");
    assert_eq!(first["severity"], "error");
    assert_eq!(first["location"]["file"], "fixtures/bad/unknown_render_state_value.shader");
    assert_eq!(
        (first["location"]["line"].as_u64(), first["location"]["column"].as_u64()),
        (Some(4), Some(20))
    );
    assert_eq!(value["diagnostics"].as_array().map(Vec::len), Some(3));
}

#[test]
fn no_colour_when_not_a_terminal() {
    let output = kiln(&["list", "fixtures/bad/unclosed_brace.shader"]);
    assert!(!output.stderr.contains(&0x1b), "escape codes in piped output");
}

#[test]
fn watch_rebuilds_on_an_edit_and_reports_a_broken_one() {
    use std::io::BufRead as _;
    let project = tempfile::tempdir().expect("temp dir");
    let user_cache = tempfile::tempdir().expect("temp dir");
    for name in ["kiln.toml", "Blend.shader", "materials/Opaque.mat"] {
        let to = project.path().join(name);
        std::fs::create_dir_all(to.parent().expect("folder")).expect("mkdir");
        std::fs::copy(crate::support::root().join("fixtures/runtime").join(name), to).expect("copy");
    }
    let mut child = std::process::Command::new(env!("CARGO_BIN_EXE_kiln"))
        .args(["watch", project.path().to_str().expect("utf-8")])
        .env("NO_COLOR", "1")
        .env("XDG_CACHE_HOME", user_cache.path())
        .stderr(std::process::Stdio::piped())
        .spawn()
        .expect("kiln watch runs");
    let (sender, lines) = std::sync::mpsc::channel();
    let stderr = child.stderr.take().expect("stderr");
    std::thread::spawn(move || {
        for line in std::io::BufReader::new(stderr).lines().map_while(Result::ok) {
            let _ = sender.send(line);
        }
    });
    // Lines up to the next "watching" line, or what came before a timeout.
    let next_build = || {
        let mut seen = Vec::new();
        while let Ok(line) = lines.recv_timeout(std::time::Duration::from_secs(60)) {
            if line.starts_with("watching for changes") {
                break;
            }
            seen.push(line);
        }
        seen.join("\n")
    };
    let first = next_build();
    assert!(first.contains("built 1 shader, 1 pass, 1 variant: 2 stage modules"), "{first}");
    let shader = project.path().join("Blend.shader");
    let text = std::fs::read_to_string(&shader).expect("shader");
    // An edit, then the edit undone: the undone one compiles nothing (the user's cache kept it).
    std::fs::write(&shader, text.replace("vec4<f32>(1.0, 0.5, 0.0, 0.5)", "vec4<f32>(0.5, 0.5, 0.0, 0.5)"))
        .expect("edit");
    let edited = next_build();
    assert!(edited.contains("(1 compiled"), "{edited}");
    std::fs::write(&shader, &text).expect("undo");
    let undone = next_build();
    assert!(undone.contains("(0 compiled, 2 reused"), "{undone}");
    std::fs::write(&shader, text.replace("return color;", "return colour;")).expect("edit");
    let broken = next_build();
    let output = project.path().join("build/kiln");
    let _ = child.kill();
    let _ = child.wait();
    assert!(broken.contains("error[K0401]") && broken.contains("Blend.shader:40:"), "{broken}");
    assert!(broken.contains(", with errors"), "{broken}");
    let errors = std::fs::read_to_string(output.join("errors.txt")).expect("errors.txt left for the runtime");
    assert!(errors.contains("Blend.shader:40:"), "{errors}");
    assert!(output.join("manifest.json").exists(), "the last good build stays");
}

#[test]
fn a_file_that_exists_but_cannot_be_read_is_named_with_the_system_s_reason() {
    // A folder given where a file is read: it exists, and reading it fails (K0002).
    let out = tempfile::tempdir().expect("temp dir");
    let output = out.path().to_str().expect("utf-8");
    let run = kiln(&["build", "fixtures/project", "--output", output, "--variants-from", "fixtures"]);
    let stderr = String::from_utf8_lossy(&run.stderr);
    assert_eq!(run.status.code(), Some(1), "{stderr}");
    assert!(stderr.starts_with("error[K0002]: cannot read `fixtures`: "), "{stderr}");
    assert!(!out.path().join("manifest.json").exists(), "nothing is written");
}

#[test]
fn mistakes_in_the_command_exit_2_with_the_reason_and_never_hang() {
    let dir = tempfile::tempdir().expect("temp dir");
    let out = dir.path().join("out");
    let out = out.to_str().expect("utf-8");
    let cases: [(&[&str], &str); 5] = [
        (&["build", "fixtures/project", "--output", out, "--threads", "100000"], "100000"),
        (&["watch", "no/such/project"], "`no/such/project` does not exist"),
        (
            &["cache", "stats", "fixtures/project", "--cache-dir", "no/such/cache"],
            "no cache at `no/such/cache`",
        ),
        (
            &["build", "fixtures/project", "--output", out, "--variants-from", "missing.jsonl"],
            "`missing.jsonl` does not exist",
        ),
        (
            &["reflect", "fixtures/project/materials/ComplexPlain.mat"],
            "`fixtures/project/materials/ComplexPlain.mat` is not a .shader or .compute file",
        ),
    ];
    for (args, expected) in cases {
        // `kiln` waits for nothing here: a hang would fail the test by its timeout below.
        let child = std::process::Command::new(env!("CARGO_BIN_EXE_kiln"))
            .args(args)
            .current_dir(crate::support::root())
            .stderr(std::process::Stdio::piped())
            .stdout(std::process::Stdio::null())
            .spawn()
            .expect("kiln runs");
        let output = crate::support::output_within_a_minute(child, &format!("`kiln {}`", args.join(" ")));
        let stderr = String::from_utf8_lossy(&output.stderr);
        assert_eq!(output.status.code(), Some(2), "kiln {}: {stderr}", args.join(" "));
        assert!(stderr.contains(expected), "kiln {}: {stderr}", args.join(" "));
    }
    assert!(!dir.path().join("out").exists(), "nothing written");
}

#[test]
fn the_summary_says_where_the_output_went() {
    let dir = tempfile::tempdir().expect("temp dir");
    let out = dir.path().join("out");
    let run = kiln(&["build", "fixtures/project", "--output", out.to_str().expect("utf-8")]);
    let stderr = String::from_utf8_lossy(&run.stderr);
    assert_eq!(run.status.code(), Some(0), "{stderr}");
    assert!(stderr.contains(&format!("bytes written to {} in ", out.display())), "{stderr}");
}

#[test]
fn a_project_without_shaders_fails_a_check_and_warns_a_build() {
    let check = kiln(&["check", "fixtures/empty"]);
    let stderr = String::from_utf8_lossy(&check.stderr);
    assert_eq!(check.status.code(), Some(1), "{stderr}");
    let diagnostics: String =
        stderr.lines().take_while(|l| !l.starts_with("checked ")).map(|l| format!("{l}\n")).collect();
    expect_test::expect_file![crate::support::root().join("tests/golden/cli/no_shaders.stderr")]
        .assert_eq(&diagnostics);
    let dir = tempfile::tempdir().expect("temp dir");
    let build = kiln(&["build", "fixtures/empty", "--output", dir.path().to_str().expect("utf-8")]);
    let stderr = String::from_utf8_lossy(&build.stderr);
    assert_eq!(build.status.code(), Some(0), "{stderr}");
    assert!(stderr.starts_with("warning[K0009]: no shaders in `fixtures/empty`"), "{stderr}");
}

#[test]
fn a_misspelt_kiln_toml_field_is_named_with_the_one_meant_and_nothing_follows_it() {
    let dir = tempfile::tempdir().expect("temp dir");
    std::fs::write(dir.path().join("kiln.toml"), "shaderz = [\"shaders\"]\n").expect("write");
    let run = kiln(&["check", dir.path().to_str().expect("utf-8")]);
    let stderr = String::from_utf8_lossy(&run.stderr);
    assert_eq!(run.status.code(), Some(1), "{stderr}");
    assert!(stderr.contains("unknown field `shaderz`\n"), "the field list once, in the help: {stderr}");
    assert!(stderr.contains("= help: did you mean `shaders`? fields are shaders, materials"), "{stderr}");
    assert!(!stderr.contains("K0009"), "no follow-on \"no shaders\": {stderr}");
}

#[test]
fn without_a_path_kiln_works_on_the_folder_it_runs_in_not_its_own_fixtures() {
    // An empty folder with no kiln.toml above it: a project of defaults, with no shaders.
    let empty = tempfile::tempdir().expect("temp dir");
    let check = crate::support::kiln_in(empty.path(), &["check"]);
    assert_eq!(check.status.code(), Some(1), "CI on the wrong folder fails");
    assert!(String::from_utf8_lossy(&check.stderr).contains("error[K0009]"));
    let build = crate::support::kiln_in(empty.path(), &["build"]);
    assert_eq!(build.status.code(), Some(0));
    assert!(String::from_utf8_lossy(&build.stderr).contains("warning[K0009]"));
}

/// One file, one name: a project whose `kiln.toml` says `shaders = ["."]`, checked with no path,
/// with `.` and with `./`, names the shader and its include the same way, without a `./`.
#[test]
fn a_file_is_named_one_way_however_the_project_is_reached() {
    let project = tempfile::tempdir().expect("temp dir");
    let pass = std::fs::read_to_string(crate::support::root().join("fixtures/project/shaders/LitPass.wgsl"))
        .expect("LitPass");
    let broken = pass.replace("GetLighting(surface, brdf)", "GetLightin(surface, brdf)");
    assert_ne!(broken, pass);
    std::fs::create_dir_all(project.path().join("shaders")).expect("mkdir");
    std::fs::write(project.path().join("shaders/LitPass.wgsl"), broken).expect("write");
    std::fs::copy(
        crate::support::root().join("fixtures/project/shaders/Lit.shader"),
        project.path().join("shaders/Lit.shader"),
    )
    .expect("copy");
    std::fs::write(
        project.path().join("kiln.toml"),
        "shaders = [\".\"]\nalways_include = [\"Custom RP/Lit\"]\n",
    )
    .expect("write");
    let names = |args: &[&str]| {
        let run = crate::support::kiln_in(project.path(), args);
        assert_eq!(run.status.code(), Some(1), "{args:?}");
        let stderr = String::from_utf8_lossy(&run.stderr).to_string();
        let located: Vec<String> = stderr
            .lines()
            .filter_map(|l| {
                l.split_once("┌─ ")
                    .map(|(_, at)| at)
                    .or_else(|| l.split_once("included from ").map(|(_, at)| at))
            })
            .map(|at| at.rsplitn(3, ':').last().unwrap_or_default().to_string())
            .collect();
        assert!(!located.is_empty(), "{stderr}");
        located
    };
    let plain = names(&["check"]);
    assert!(plain.contains(&"shaders/LitPass.wgsl".to_string()), "{plain:?}");
    assert!(plain.contains(&"shaders/Lit.shader".to_string()), "{plain:?}");
    for args in
        [&["check", "."][..], &["check", "./"], &["check", "./shaders/Lit.shader"], &["check", "shaders"]]
    {
        assert_eq!(names(args), plain, "{args:?}");
    }
}

/// A `kiln.toml` broken on its first line is reported on that line, at the column where TOML
/// stops making sense, however the file ends (newline, none, CRLF, blank lines after).
#[test]
fn a_kiln_toml_broken_on_its_first_line_is_reported_there() {
    let project = tempfile::tempdir().expect("temp dir");
    let cases = [
        ("shaders = [\"shaders\"\n", 21),
        ("shaders = [\"shaders\"", 21),
        ("shaders = [\"a\",\r\n", 16),
        ("shaders = [\"a\",\n\n\n", 16),
        ("shaders =\n", 10),
        ("shaders\n", 8),
        ("strict = tru\n", 10),
        ("[bind_groups\n", 13),
    ];
    for (text, column) in cases {
        std::fs::write(project.path().join("kiln.toml"), text).expect("write");
        let run = crate::support::kiln_in(project.path(), &["check"]);
        let stderr = String::from_utf8_lossy(&run.stderr);
        assert_eq!(run.status.code(), Some(1), "{text:?}: {stderr}");
        assert!(stderr.contains(&format!("┌─ kiln.toml:1:{column}\n")), "{text:?}: {stderr}");
    }
}

/// `build`, `watch` and `check` take the same project flags: a check given the shared cache a
/// build filled compiles nothing (a build from whole texts, as a check parses them), and one
/// given a usage log checks the variant it names.
#[test]
fn check_takes_the_project_flags_build_takes() {
    let dir = tempfile::tempdir().expect("temp dir");
    let (cache, output) = (dir.path().join("cache"), dir.path().join("out"));
    let (cache, output) = (cache.to_str().expect("UTF-8"), output.to_str().expect("UTF-8"));
    let built =
        kiln(&["build", "fixtures/project", "--output", output, "--cache-dir", cache, "--parse-whole"]);
    assert!(built.status.success(), "{}", String::from_utf8_lossy(&built.stderr));
    let checked = kiln(&["check", "fixtures/project", "--cache-dir", cache, "--threads", "1"]);
    let stderr = String::from_utf8_lossy(&checked.stderr);
    assert!(checked.status.success() && stderr.contains("(0 compiled, 19 reused from cache)"), "{stderr}");
    let log = dir.path().join("usage.jsonl");
    std::fs::write(&log, "{\"shader\": \"Custom RP/Lit\", \"pass\": 0, \"keywords\": [\"_NO_SUCH\"]}\n")
        .expect("write");
    let checked = kiln(&["check", "fixtures/project", "--variants-from", log.to_str().expect("UTF-8")]);
    let stderr = String::from_utf8_lossy(&checked.stderr);
    assert_eq!(checked.status.code(), Some(1), "{stderr}");
    assert!(stderr.contains("K0533") && stderr.contains("_NO_SUCH"), "{stderr}");
}

#[test]
fn a_ci_job_pointed_at_unity_shaders_fails_rather_than_checking_nothing() {
    for command in ["check", "build"] {
        let out = tempfile::tempdir().expect("temp dir");
        let run = crate::support::kiln(&[
            command,
            "fixtures/unity",
            "--output",
            out.path().to_str().expect("utf-8"),
        ]);
        let stderr = String::from_utf8_lossy(&run.stderr);
        assert_eq!(run.status.code(), Some(1), "{command}: {stderr}");
        assert!(stderr.contains("error[K0424]"), "{command}: {stderr}");
    }
}

/// The summary line counts in the singular where there is one, and says how many modules failed
/// rather than leave them out of every count.
#[test]
fn the_summary_line_counts_one_in_the_singular_and_counts_what_failed() {
    let run = crate::support::kiln(&["check", "fixtures/bad/build/hlsl_missing_entry_point.shader"]);
    let stderr = String::from_utf8_lossy(&run.stderr);
    assert_eq!(run.status.code(), Some(1), "{stderr}");
    // The fragment stage names no function; the vertex stage still compiles.
    let summary =
        "checked 1 shader, 1 pass, 1 variant: 2 stage modules (1 compiled, 0 reused from cache, 1 failed)";
    assert!(stderr.contains(summary), "{stderr}");
}

/// A back end named for its API (`metal`) or misspelt is refused with the one meant.
#[test]
fn a_back_end_named_for_its_api_is_told_the_one_meant() {
    for (given, meant) in [("metal", "msl"), ("vulkan", "spirv"), ("dx12", "hlsl"), ("spirvv", "spirv")] {
        let run = crate::support::kiln(&["check", "fixtures/project", "--backends", given]);
        let stderr = String::from_utf8_lossy(&run.stderr);
        assert_eq!(run.status.code(), Some(2), "{given}: {stderr}");
        assert!(stderr.contains(&format!("no back end `{given}` (did you mean `{meant}`?)")), "{stderr}");
    }
}
