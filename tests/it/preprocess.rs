//! The preprocessor: golden spliced WGSL for every fixture variant (which naga must accept),
//! naga errors mapped back through the source map to the exact original file, line and column,
//! and a pinned diagnostic for every bad input.

use crate::support::{fixture_files, kiln, root};
use expect_test::expect_file;
use kiln::config::ParseScope;
use kiln::diagnostics::{Diagnostic, has_errors, render_plain};
use kiln::listing::program_blocks;
use kiln::preprocess::{IncludeConfig, Includes, Stage, load_pass, preprocess};
use kiln::project::{VariantRequest, include_config, preprocess_variant};
use kiln::shaderlab::parse_shader;
use kiln::shaderlab::pragma::KeywordSet;
use kiln::source::SourceStore;
use std::fmt::Write as _;
use std::path::{Path, PathBuf};

/// Every combination of one option per set, as keyword lists.
fn combinations(sets: &[KeywordSet]) -> Vec<Vec<String>> {
    sets.iter().fold(vec![Vec::new()], |partial, set| {
        partial
            .iter()
            .flat_map(|keywords| {
                set.options.iter().map(move |option| {
                    let mut next = keywords.clone();
                    next.extend(option.keyword.clone());
                    next
                })
            })
            .collect()
    })
}

#[test]
fn every_fixture_variant_preprocesses_to_golden_wgsl_that_naga_accepts() {
    let mut checked = 0;
    for path in fixture_files("fixtures/project/shaders", "shader") {
        let mut store = SourceStore::new();
        let file = store.load(&path).expect("fixture loads");
        let shader = parse_shader(&store, file).shader.expect("fixture parses");
        let mut includes = Includes::new(include_config(std::slice::from_ref(&path)));
        for (index, (_, sub, _, pass)) in shader.passes().enumerate() {
            let blocks = program_blocks(&shader, sub, &pass.programs);
            let (program, diagnostics) = load_pass(&mut includes, &mut store, &blocks);
            assert!(diagnostics.is_empty(), "{}", render_plain(&store, &diagnostics));
            let mut base: Option<String> = None;
            for keywords in combinations(&program.pragmas.variant_sets()) {
                let refs: Vec<&str> = keywords.iter().map(String::as_str).collect();
                let out = preprocess(&includes, &store, &program.program, &refs, Stage::Fragment);
                assert!(out.diagnostics.is_empty(), "{}", render_plain(&store, &out.diagnostics));
                if let Err(errors) = kiln::compile::check(&out, &store) {
                    panic!("{keywords:?}: {}", render_plain(&store, &errors));
                }
                let stem = path.file_stem().and_then(|s| s.to_str()).expect("stem");
                if keywords.is_empty() {
                    // The pass's variant without keywords, whole, with its source map.
                    let header = format!("// kiln preprocess {} --pass {index}\n", path.display());
                    let map = out.source_map.describe_lines(&store, &out.text);
                    let commented: String = map.lines().map(|l| format!("// {l}\n")).collect();
                    let actual = format!(
                        "{header}{}\n// ---- source map: output lines <- original lines ----\n{commented}",
                        out.text
                    );
                    expect_file![root().join(format!("tests/golden/preprocess/{stem}/{index}.none.wgsl"))]
                        .assert_eq(&actual);
                    base = Some(annotated(&out.text, &out.source_map, &store));
                } else {
                    // Every other variant as what its keywords change: a diff of lines, each with
                    // the original line it came from, so a golden shows only what a keyword does.
                    let base = base.as_deref().expect("the variant without keywords comes first");
                    let header = format!(
                        "kiln preprocess {} --pass {index} --keywords {}, against {index}.none.wgsl\n",
                        path.display(),
                        keywords.join(",")
                    );
                    let diff =
                        similar::TextDiff::from_lines(base, &annotated(&out.text, &out.source_map, &store))
                            .unified_diff()
                            .context_radius(1)
                            .to_string();
                    let golden =
                        format!("tests/golden/preprocess/{stem}/{index}.{}.diff", keywords.join("+"));
                    expect_file![root().join(golden)].assert_eq(&format!("{header}{diff}"));
                }
                checked += 1;
            }
        }
    }
    // Lit 2 x 2 x 2, Unlit 2, Complex 2 x 3 x 2.
    assert_eq!(checked, 22);
}

#[test]
fn the_vertex_stage_ignores_fragment_only_keywords() {
    // `_EMISSION_MAP` is `shader_feature_fragment`: the vertex text must not fork on it.
    let path = PathBuf::from("fixtures/project/shaders/Complex.shader");
    let vertex = |keywords: &[&str]| {
        let request = VariantRequest {
            shader: path.clone(),
            pass: None,
            keywords: keywords.iter().map(|k| k.to_string()).collect(),
            stage: Stage::Vertex,
            project: None,
        };
        let (out, diagnostics) = preprocess_variant(&mut SourceStore::new(), &request, ParseScope::Whole)
            .expect("request is valid");
        assert!(diagnostics.is_empty());
        out.expect("preprocesses").text
    };
    assert_eq!(vertex(&[]), vertex(&["_EMISSION_MAP"]));
    assert_ne!(vertex(&[]), vertex(&["_METALLIC_MAP"]), "a keyword for all stages does fork it");
}

/// An error written into one file: `needle` becomes `replacement`, and naga must point at `at`
/// (a substring of the replacement).
struct Injection {
    file: &'static str,
    needle: &'static str,
    replacement: &'static str,
    at: &'static str,
}

const INJECTIONS: &[Injection] = &[
    Injection { file: "Common.wgsl", needle: "return v * v;", replacement: "return v * w;", at: "w;" },
    Injection {
        file: "Input.wgsl",
        needle: "_WorldSpaceCameraPos: vec3<f32>",
        replacement: "_WorldSpaceCameraPos: vec3<f33>",
        at: "f33",
    },
    Injection { file: "Surface.wgsl", needle: "alpha: f32,", replacement: "alpha: flaot,", at: "flaot" },
    Injection {
        file: "Light.wgsl",
        needle: "light.color = _CustomLight",
        replacement: "light.colour = _CustomLight",
        at: "colour",
    },
    Injection {
        file: "BRDF.wgsl",
        needle: "let d2 = Square(nh2 *",
        replacement: "let d2 = Sqaure(nh2 *",
        at: "Sqaure",
    },
    Injection {
        file: "Lighting.wgsl",
        needle: "return IncomingLight(surface, light) *",
        replacement: "return IncomingLigth(surface, light) *",
        at: "IncomingLigth",
    },
    // A validation error (not a syntax error): the returned type is wrong.
    Injection {
        file: "BRDF.wgsl",
        needle: "return range * (1.0 - metallic);",
        replacement: "return vec2<f32>(range);",
        at: "vec2<f32>(range)",
    },
    Injection {
        file: "LitPass.wgsl",
        needle: "surface.alpha = base.a;",
        replacement: "surface.alpha = base.q;",
        at: "q;",
    },
    // Through a macro: the error is in the expansion, reported at the macro's use.
    Injection {
        file: "Light.wgsl",
        needle: "#define MAX_DIRECTIONAL_LIGHT_COUNT 4",
        replacement: "#define MAX_DIRECTIONAL_LIGHT_COUNT 4.5",
        at: "",
    },
];

#[test]
fn naga_errors_in_every_library_file_and_the_pass_map_to_the_original_line_and_column() {
    let fixture = PathBuf::from("fixtures/project/shaders/Lit.shader");
    let pass_text =
        std::fs::read_to_string(root().join("fixtures/project/shaders/LitPass.wgsl")).expect("read");
    // The pass file is changed in a copy of the shader's folder; library files in the library.
    let copy = tempfile::tempdir().expect("temp dir");
    for (index, injection) in INJECTIONS.iter().enumerate() {
        let mut config = IncludeConfig::new(vec![PathBuf::from("fixtures/project")]);
        let mut shader = fixture.clone();
        let original = match config.library.iter_mut().find(|(name, _)| name == injection.file) {
            Some((_, text)) => text,
            None => {
                shader = copy.path().join("Lit.shader");
                config.roots = vec![copy.path().to_path_buf()];
                std::fs::copy(root().join(&fixture), &shader).expect("copy");
                &mut pass_text.clone()
            }
        };
        assert_eq!(original.matches(injection.needle).count(), 1, "{}: needle is unique", injection.file);
        let modified = original.replacen(injection.needle, injection.replacement, 1);
        *original = modified.clone();
        if injection.file == "LitPass.wgsl" {
            std::fs::write(copy.path().join("LitPass.wgsl"), &modified).expect("write");
        }

        let expected_offset = if injection.at.is_empty() {
            // The macro's use: its name in `array<vec4<f32>, MAX_DIRECTIONAL_LIGHT_COUNT>`.
            modified.find("vec4<f32>, MAX_DIRECTIONAL_LIGHT_COUNT>").expect("use") + "vec4<f32>, ".len()
        } else {
            modified.find(injection.replacement).expect("injected")
                + injection.replacement.find(injection.at).expect("at")
        };
        let expected_line = modified[..expected_offset].matches('\n').count() + 1;
        let line_start = modified[..expected_offset].rfind('\n').map_or(0, |i| i + 1);
        let expected_column = modified[line_start..expected_offset].chars().count() + 1;

        let (store, error) = first_naga_error(config, &shader);
        let span = error.primary.as_ref().expect("the error has a location").span;
        let (name, at) = (store.name(span.file), store.line_col(span.file, span.start as usize));
        assert!(name.ends_with(injection.file), "{}: reported in {name}: {}", injection.file, error.message);
        assert_eq!(
            (at.line, at.column),
            (expected_line, expected_column),
            "{}: {}",
            injection.file,
            error.message
        );
        if injection.file != "LitPass.wgsl" {
            assert!(
                error.notes.iter().any(|n| n.starts_with("included from ") && n.contains("LitPass.wgsl")),
                "{}: the include chain is shown: {:?}",
                injection.file,
                error.notes
            );
            let golden =
                root().join(format!("tests/golden/preprocess/naga/{index}.{}.stderr", injection.file));
            expect_file![golden].assert_eq(&render_plain(&store, &[error]));
        }
    }
}

/// Preprocesses Lit with every keyword on and returns naga's error.
fn first_naga_error(config: IncludeConfig, shader: &Path) -> (SourceStore, Diagnostic) {
    let mut store = SourceStore::new();
    let file = store.load(shader).expect("load");
    let parsed = parse_shader(&store, file).shader.expect("parses");
    let (_, sub, _, pass) = parsed.passes().next().expect("a pass");
    let mut includes = Includes::new(config);
    let (program, diagnostics) =
        load_pass(&mut includes, &mut store, &program_blocks(&parsed, sub, &pass.programs));
    assert!(!has_errors(&diagnostics), "{}", render_plain(&store, &diagnostics));
    let out = preprocess(
        &includes,
        &store,
        &program.program,
        &["_CLIPPING", "_PREMULTIPLY_ALPHA"],
        Stage::Fragment,
    );
    assert!(out.diagnostics.is_empty());
    let Err(mut errors) = kiln::compile::check(&out, &store) else {
        panic!("naga accepted the injected error")
    };
    assert_eq!(errors.len(), 1);
    (store, errors.remove(0))
}

/// Reads `// kiln-args: ...` from a fixture's first line into a request.
fn request_for(path: &Path) -> VariantRequest {
    let text = std::fs::read_to_string(root().join(path)).expect("fixture");
    let mut request = VariantRequest {
        shader: path.to_path_buf(),
        pass: None,
        keywords: Vec::new(),
        stage: Stage::Fragment,
        project: None,
    };
    let args = text.lines().next().and_then(|l| l.strip_prefix("// kiln-args:")).unwrap_or("");
    let mut words = args.split_whitespace();
    while let Some(flag) = words.next() {
        let value = words.next().expect("flag value");
        match flag {
            "--keywords" => request.keywords = value.split(',').map(str::to_string).collect(),
            "--pass" => request.pass = Some(value.to_string()),
            "--stage" => request.stage = if value == "vertex" { Stage::Vertex } else { Stage::Fragment },
            other => panic!("unknown fixture flag {other}"),
        }
    }
    request
}

fn check_folder(folder: &str, expect_errors: bool) {
    let files = fixture_files(folder, "shader");
    assert!(!files.is_empty());
    for path in files {
        let mut store = SourceStore::new();
        let (_, diagnostics) =
            preprocess_variant(&mut store, &request_for(&path), ParseScope::Whole).expect("request is valid");
        crate::support::assert_pinned(&path, &store, &diagnostics, expect_errors);
    }
}

#[test]
fn every_bad_preprocessor_input_has_a_pinned_diagnostic() {
    check_folder("fixtures/bad/preprocess", true);
}

#[test]
fn preprocessor_warnings_do_not_fail_the_pass() {
    check_folder("fixtures/warn/preprocess", false);
}

#[test]
fn the_cli_prints_the_variant_and_exits_1_on_bad_inputs() {
    let output = kiln(&["preprocess", "fixtures/project/shaders/Lit.shader", "--keywords", "_CLIPPING"]);
    assert_eq!(output.status.code(), Some(0));
    let request = request_for(Path::new("fixtures/project/shaders/Lit.shader"));
    let request = VariantRequest { keywords: vec!["_CLIPPING".into()], ..request };
    let (expected, _) =
        preprocess_variant(&mut SourceStore::new(), &request, ParseScope::Whole).expect("valid");
    assert_eq!(String::from_utf8_lossy(&output.stdout), expected.expect("text").text);

    for path in fixture_files("fixtures/bad/preprocess", "shader") {
        let request = request_for(&path);
        let mut args = vec!["preprocess".to_string(), path.display().to_string()];
        if !request.keywords.is_empty() {
            args.extend(["--keywords".into(), request.keywords.join(",")]);
        }
        if request.stage == Stage::Vertex {
            args.extend(["--stage".into(), "vertex".into()]);
        }
        let args: Vec<&str> = args.iter().map(String::as_str).collect();
        let output = kiln(&args);
        assert_eq!(output.status.code(), Some(1), "{}", path.display());
        assert!(output.stdout.is_empty(), "{}: no half output", path.display());
    }
}

#[test]
fn requests_that_name_nothing_are_usage_errors() {
    let cases: [(&[&str], &str); 4] = [
        (&["--keywords", "_CLIPING"], "`_CLIPING` is not a keyword of this pass (did you mean `_CLIPPING`?)"),
        (&["--pass", "Shadow"], "has no pass `Shadow`"),
        (&["--pass", "3"], "has no pass `3`"),
        (&["--keywords", "_CLIPPING,_CLIPPING,_PREMULTIPLY_ALPHA"], ""),
    ];
    for (args, message) in cases {
        let mut all = vec!["preprocess", "fixtures/project/shaders/Lit.shader"];
        all.extend(args);
        let output = kiln(&all);
        let stderr = String::from_utf8_lossy(&output.stderr);
        if message.is_empty() {
            assert_eq!(output.status.code(), Some(0), "{args:?}: {stderr}");
        } else {
            assert_eq!(output.status.code(), Some(2), "{args:?}");
            assert!(stderr.contains(message), "{args:?}: {stderr}");
        }
    }
    let output = kiln(&["preprocess", "fixtures/unity/SurfaceToon.shader", "--pass", "GLSL"]);
    assert_eq!(output.status.code(), Some(2), "{}", String::from_utf8_lossy(&output.stderr));
    let stderr = String::from_utf8_lossy(&output.stderr);
    assert!(stderr.contains("only WGSL, HLSL and Cg programs are preprocessed"), "{stderr}");
}

/// Preprocesses an in-memory program against an in-memory library and renders what it reports.
fn preprocess_in_memory(program: &str, library: Vec<(String, String)>) -> String {
    let mut store = SourceStore::new();
    let file = store.add("limits.wgsl", program);
    let mut includes = Includes::new(IncludeConfig {
        roots: Vec::new(),
        include_paths: Vec::new(),
        library,
        links_out: Default::default(),
    });
    let span = kiln::source::Span::new(file, 0..program.len());
    let (program, mut diagnostics) = includes.load_program(&mut store, &[span]);
    diagnostics.extend(preprocess(&includes, &store, &program, &[], Stage::Fragment).diagnostics);
    assert!(has_errors(&diagnostics));
    render_plain(&store, &diagnostics)
}

#[test]
fn limits_are_diagnostics_not_stack_overflows() {
    let golden = |name: &str| root().join(format!("tests/golden/preprocess/limits/{name}.stderr"));

    // A chain of 70 files, each including the next: the 65th level is refused.
    let chain = (0..70)
        .map(|i| (format!("deep_{i:02}.wgsl"), format!("#include \"deep_{:02}.wgsl\"\n", i + 1)))
        .collect();
    expect_file![golden("include_depth")]
        .assert_eq(&preprocess_in_memory("#include \"deep_00.wgsl\"\n", chain));

    // 70 macros, each defined as the next, used in text and in `#if`.
    let mut defines: String = (0..70).map(|i| format!("#define M{i} M{}\n", i + 1)).collect();
    defines.push_str("let x = M0;\n#if M0\n#endif\n");
    expect_file![golden("expansion_depth")].assert_eq(&preprocess_in_memory(&defines, Vec::new()));

    // 65 nested conditionals.
    let nested = format!("{}{}", "#if 1\n".repeat(65), "#endif\n".repeat(65));
    expect_file![golden("conditional_depth")].assert_eq(&preprocess_in_memory(&nested, Vec::new()));
}

/// Preprocesses in-memory `files` (the first is the program) placed in a temporary project
/// folder, with `keywords` defined; returns the text (or the rendered diagnostics).
fn preprocess_files(files: &[(&str, &str)], keywords: &[&str]) -> String {
    let dir = tempfile::tempdir().expect("temp dir");
    for (name, text) in files {
        let path = dir.path().join(name);
        std::fs::create_dir_all(path.parent().expect("parent")).expect("mkdir");
        std::fs::write(path, text).expect("write");
    }
    let mut store = SourceStore::new();
    let main = store.load(&dir.path().join(files[0].0)).expect("load");
    let mut config = IncludeConfig::new(vec![dir.path().to_path_buf()]);
    config.include_paths.push(dir.path().join("include"));
    let mut includes = Includes::new(config);
    let span = kiln::source::Span::new(main, 0..files[0].1.len());
    let (program, mut diagnostics) = includes.load_program(&mut store, &[span]);
    let out = preprocess(&includes, &store, &program, keywords, Stage::Fragment);
    diagnostics.extend(out.diagnostics);
    if diagnostics.is_empty() { out.text } else { render_plain(&store, &diagnostics) }
}

#[test]
fn macros_are_substituted_token_by_token() {
    let program = "#define N 4\n#define COUNT N\nlet a = array<f32, COUNT>();\n\
                   let b = N_SIZE + NN + N1; // N stays in comments\n/* N */ let c = \"N\";\nlet d = N;\n";
    let out = preprocess_files(&[("main.wgsl", program)], &[]);
    assert_eq!(
        out,
        "let a = array<f32, 4>();\nlet b = N_SIZE + NN + N1; // N stays in comments\n/* N */ let c = \"N\";\nlet d = 4;\n"
    );
    // A macro naming itself stops there, as in C.
    assert_eq!(preprocess_files(&[("main.wgsl", "#define X X + 1\nlet y = X;\n")], &[]), "let y = X + 1;\n");
}

#[test]
fn conditionals_follow_c() {
    let program = "#if defined(_A) && !defined _B\na\n#elif _B\nb\n#else\nc\n#endif\n\
                   #ifdef _A\n#ifndef _B\nd\n#endif\n#endif\n#if 2 * 3 == 6 && (7 % 4) == 3 ? 1 : 0\ne\n#endif\n\
                   #define _B\n#undef _B\n#ifdef _B\nf\n#endif\n";
    assert_eq!(preprocess_files(&[("main.wgsl", program)], &["_A"]), "a\nd\ne\n");
    assert_eq!(preprocess_files(&[("main.wgsl", program)], &["_B"]), "b\ne\n");
    assert_eq!(preprocess_files(&[("main.wgsl", program)], &[]), "c\ne\n");
    // A skipped branch is not evaluated: its division by zero is harmless.
    let skipped = "#if 1\nx\n#elif 1 / 0\ny\n#endif\n";
    assert_eq!(preprocess_files(&[("main.wgsl", skipped)], &[]), "x\n");
}

#[test]
fn includes_search_the_including_folder_then_include_paths_then_the_library() {
    let files = [
        (
            "shaders/main.wgsl",
            "#include \"Local.wgsl\"\n#include \"Shared.wgsl\"\n#include \"Square.wgsl\"\n",
        ),
        ("shaders/Local.wgsl", "// local\n"),
        // Shadows the library's Common.wgsl only for files that look in `include/` first.
        ("include/Shared.wgsl", "// shared\n#include \"Common.wgsl\"\n"),
        ("include/Common.wgsl", "// project common\n"),
        ("shaders/Square.wgsl", "#include \"../include/Shared.wgsl\"\n"),
    ];
    let out = preprocess_files(&files, &[]);
    // Shared.wgsl finds the project's Common.wgsl in its own folder; the second include of
    // Shared.wgsl (through Square.wgsl) adds it again because it has no guard.
    assert_eq!(out, "// local\n// shared\n// project common\n// shared\n// project common\n");
    let library = preprocess_files(&[("main.wgsl", "#include \"Surface.wgsl\"\n")], &[]);
    assert!(library.contains("struct Surface {"), "{library}");
}

#[test]
fn guards_and_pragma_once_include_a_file_once() {
    let files = [
        (
            "main.wgsl",
            "#include \"a.wgsl\"\n#include \"a.wgsl\"\n#include \"b.wgsl\"\n#include \"./b.wgsl\"\n",
        ),
        ("a.wgsl", "#ifndef A\n#define A\nfn a() {}\n#endif\n"),
        ("b.wgsl", "#pragma once\nfn b() {}\n"),
    ];
    assert_eq!(preprocess_files(&files, &[]), "fn a() {}\nfn b() {}\n");
    // A guarded file including itself is not a cycle.
    let guarded = [
        ("main.wgsl", "#include \"g.wgsl\"\n"),
        ("g.wgsl", "#ifndef G\n#define G\n#include \"g.wgsl\"\ng\n#endif\n"),
    ];
    assert_eq!(preprocess_files(&guarded, &[]), "g\n");
}

/// `main.wgsl` of the project in `folder` preprocessed for the fragment stage, the folder its
/// includes' only root.
fn preprocess_main(folder: &Path) -> kiln::preprocess::Preprocessed {
    let mut store = SourceStore::new();
    let main = store.load(&folder.join("main.wgsl")).expect("load");
    let mut includes = Includes::new(IncludeConfig::new(vec![folder.to_path_buf()]));
    let span = kiln::source::Span::new(main, 0..store.text(main).len());
    let (program, _) = includes.load_program(&mut store, &[span]);
    preprocess(&includes, &store, &program, &[], Stage::Fragment)
}

#[cfg(unix)]
#[test]
fn a_symlink_out_of_the_project_is_refused() {
    let outside = tempfile::tempdir().expect("temp dir");
    std::fs::write(outside.path().join("secret.wgsl"), "fn secret() {}\n").expect("write");
    let project = tempfile::tempdir().expect("temp dir");
    std::fs::write(project.path().join("main.wgsl"), "#include \"link.wgsl\"\n").expect("write");
    std::os::unix::fs::symlink(outside.path().join("secret.wgsl"), project.path().join("link.wgsl"))
        .expect("symlink");
    let out = preprocess_main(project.path());
    assert_eq!(out.diagnostics.len(), 1);
    assert_eq!(out.diagnostics[0].code, "K0304");
    assert!(!out.text.contains("secret"));
}

#[test]
fn the_source_map_points_every_byte_home() {
    let files = [
        ("main.wgsl", "#define N 4\nlet a = N;\n#include \"b.wgsl\"\nlet c = 1;\n"),
        ("b.wgsl", "let b = 2;\n"),
    ];
    let dir = tempfile::tempdir().expect("temp dir");
    for (name, text) in files {
        std::fs::write(dir.path().join(name), text).expect("write");
    }
    let mut store = SourceStore::new();
    let main = store.load(&dir.path().join("main.wgsl")).expect("load");
    let mut includes = Includes::new(IncludeConfig::new(vec![dir.path().to_path_buf()]));
    let span = kiln::source::Span::new(main, 0..files[0].1.len());
    let (program, _) = includes.load_program(&mut store, &[span]);
    let out = preprocess(&includes, &store, &program, &[], Stage::Fragment);
    assert_eq!(out.text, "let a = 4;\nlet b = 2;\nlet c = 1;\n");
    let map = &out.source_map;
    // Every copied byte maps to the same byte in its file.
    for (offset, byte) in out.text.bytes().enumerate() {
        let origin = map.locate(offset).expect("mapped");
        if out.text[offset..].starts_with('4') {
            assert_eq!(store.slice(origin.span), "N", "the expansion maps to the macro's use");
        } else {
            assert_eq!(
                store.text(origin.span.file).as_bytes()[origin.span.start as usize],
                byte,
                "offset {offset}"
            );
        }
    }
    let b = map.map_range(11..21).expect("mapped");
    assert_eq!(store.slice(b.span), "let b = 2;");
    assert_eq!(map.include_chain(b.inclusion).count(), 1);
    assert_eq!(map.included_from_notes(&store, b.inclusion).len(), 1);
    assert!(map.included_from_notes(&store, b.inclusion)[0].ends_with("main.wgsl:3:10"));
}

#[test]
fn include_with_pragmas_declares_keywords_for_the_pass() {
    let (mut store, ids, _) =
        crate::support::load(&["fixtures/warn/preprocess/keyword_analysis.shader".into()]);
    let mut includes = Includes::new(include_config(&["fixtures/warn/preprocess".into()]));
    let (listing, _) = kiln::listing::list_shaders(
        &mut store,
        &mut includes,
        &kiln::catalog::CatalogInput { shaders: ids, ..Default::default() },
    );
    let program = listing.shaders[0].passes[0].program.as_ref().expect("program");
    let sets: Vec<Vec<String>> = program.keyword_sets.iter().map(|s| s.keywords.clone()).collect();
    assert!(sets.contains(&vec!["_".to_string(), "_DETAIL".to_string()]), "{sets:?}");
    assert!(!sets.iter().flatten().any(|k| k == "_PLAIN"), "{sets:?}");
}

#[test]
fn shaders_written_with_unity_style_macros_compile() {
    let output = tempfile::tempdir().expect("temp dir");
    let summary =
        crate::support::build_clean(&crate::support::root().join("fixtures/macros"), Some(output.path()));
    // Macro Unlit with and without _BLUR; Macro Lit's clipping and premultiplying combinations.
    assert_eq!((summary.shaders, summary.variants), (2, 6));
    let manifest = crate::support::verified_manifest(output.path());
    let unlit = manifest.shaders.iter().find(|s| s.name == "Custom RP/Macro Unlit").expect("unlit");
    let pass = &unlit.passes[0];
    // CBUFFER_START/CBUFFER_END made the material block, TEXTURE2D and SAMPLER its bindings.
    let names: Vec<&str> = pass.layout.iter().flat_map(|g| &g.entries).map(|e| e.name.as_str()).collect();
    for name in ["UnityPerMaterial", "_BaseMap", "sampler_BaseMap"] {
        assert!(names.contains(&name), "{names:?}");
    }
    assert_eq!(
        pass.uniform_blocks.iter().find(|b| b.name == "UnityPerMaterial").map(|b| b.type_name.as_str()),
        Some("UnityPerMaterial_Layout")
    );
}

#[test]
fn an_include_out_of_the_project_gets_one_message_whether_or_not_the_file_exists() {
    let outside = tempfile::tempdir().expect("temp dir");
    std::fs::write(outside.path().join("exists.wgsl"), "fn secret() {}\n").expect("write");
    let project = tempfile::tempdir().expect("temp dir");
    let up = "../".repeat(project.path().components().count());
    let target =
        |name: &str| format!("{up}{}/{name}", outside.path().display().to_string().trim_start_matches('/'));
    let said = |name: &str| {
        std::fs::write(project.path().join("main.wgsl"), format!("#include \"{}\"\n", target(name)))
            .expect("write");
        let out = preprocess_main(project.path());
        assert_eq!(out.diagnostics.len(), 1, "{name}");
        let diagnostic = &out.diagnostics[0];
        (diagnostic.code.to_string(), diagnostic.message.replace(name, "NAME"))
    };
    let (exists, absent) = (said("exists.wgsl"), said("absent.wgsl"));
    assert_eq!(exists.0, "K0304");
    assert_eq!(exists, absent, "what kiln says reveals whether a file outside exists");
}

#[test]
fn a_shallow_chain_past_the_token_cap_says_tokens_not_depth() {
    // 21 levels, each twice the one below: about two million tokens, a third of the depth limit.
    let mut text = String::from("#define M0 a\n");
    for level in 1..=21 {
        text.push_str(&format!("#define M{level} M{below} M{below}\n", below = level - 1));
    }
    text.push_str("M21\n");
    let said = preprocess_files(&[("main.wgsl", &text)], &[]);
    assert!(said.contains("error[K0313]") && said.contains("more than 1048576 tokens"), "{said}");
    assert!(!said.contains("levels deep"), "{said}");
}

/// A stage text's lines, each followed by the original line the source map gives it
/// (`text  // <- file:line`): two variants' texts then differ only where their keywords do, and
/// a line moved by an earlier insertion is not a change.
fn annotated(text: &str, map: &kiln::preprocess::SourceMap, store: &SourceStore) -> String {
    let mut offset = 0;
    let mut lines = String::new();
    for line in text.split_inclusive('\n') {
        let origin = map.locate(offset).map_or(String::new(), |origin| {
            let at = store.line_col(origin.span.file, origin.span.start as usize);
            format!("{}:{}", store.name(origin.span.file), at.line)
        });
        let _ = writeln!(lines, "{}  // <- {origin}", line.trim_end_matches('\n'));
        offset += line.len();
    }
    lines
}
