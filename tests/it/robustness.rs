//! Arbitrary and mutated input never panics the parser, the pragma reader or the listing.

use kiln::source::SourceStore;
use proptest::prelude::*;

fn list_text(text: &str) {
    let mut store = SourceStore::new();
    let file = store.add("fuzz.shader", text);
    let (_, diagnostics) = kiln::listing::list_shaders(
        &mut store,
        &mut kiln::preprocess::Includes::new(kiln::preprocess::IncludeConfig::new(Vec::new())),
        &kiln::catalog::CatalogInput { shaders: vec![file], ..Default::default() },
    );
    // Rendering walks every span: a span outside its file would fail here.
    let _ = kiln::diagnostics::render_plain(&store, &diagnostics);
    let _ = kiln::diagnostics::to_json(&store, &diagnostics);
}

/// Lists a file holding these bytes, read as kiln reads files: no panic, and every diagnostic
/// says where (a span, or a line and column in its message when the file was refused unread).
fn list_bytes(bytes: &[u8]) {
    let dir = tempfile::tempdir().expect("temp dir");
    let path = dir.path().join("fuzz.shader");
    std::fs::write(&path, bytes).expect("write");
    let mut store = SourceStore::new();
    let (shaders, mut diagnostics) = kiln::project::load_files(&mut store, &[path]);
    let (_, found) = kiln::listing::list_shaders(
        &mut store,
        &mut kiln::preprocess::Includes::new(kiln::preprocess::IncludeConfig::new(Vec::new())),
        &kiln::catalog::CatalogInput { shaders, ..Default::default() },
    );
    diagnostics.extend(found);
    let _ = kiln::diagnostics::render_plain(&store, &diagnostics);
    for d in kiln::diagnostics::to_json(&store, &diagnostics) {
        let placed = d.location.is_some() || (d.message.contains(" line ") && d.message.contains(" column "));
        assert!(placed, "a diagnostic without a place: {}", d.message);
    }
}

fn fixtures() -> Vec<String> {
    let mut texts = Vec::new();
    for folder in ["fixtures/project/shaders", "fixtures/unity", "fixtures/bad"] {
        for path in crate::support::fixture_files(folder, "shader") {
            if let Ok(text) = std::fs::read_to_string(crate::support::root().join(path)) {
                texts.push(text);
            }
        }
    }
    texts
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 256, ..ProptestConfig::default() })]

    #[test]
    fn arbitrary_text_never_panics(text in "\\PC{0,400}") {
        list_text(&text);
    }

    #[test]
    fn arbitrary_bytes_never_panic(bytes in proptest::collection::vec(any::<u8>(), 0..400)) {
        list_bytes(&bytes);
    }

    #[test]
    fn fixtures_with_stray_bytes_never_panic(
        pick in any::<prop::sample::Index>(),
        strays in proptest::collection::vec((any::<prop::sample::Index>(), any::<u8>()), 1..8),
    ) {
        let fixtures = fixtures();
        let mut bytes = fixtures[pick.index(fixtures.len())].clone().into_bytes();
        for (at, byte) in strays {
            bytes.insert(at.index(bytes.len() + 1), byte);
        }
        list_bytes(&bytes);
    }

    #[test]
    fn mutated_fixtures_never_panic(
        pick in any::<prop::sample::Index>(),
        edits in proptest::collection::vec((any::<prop::sample::Index>(), 0usize..4, "[{}\"\\[\\]()=,#/*a-zA-Z0-9 \n]{0,3}"), 1..6),
    ) {
        let fixtures = fixtures();
        let mut text = fixtures[pick.index(fixtures.len())].clone();
        for (at, remove, insert) in edits {
            let mut start = at.index(text.len() + 1);
            while !text.is_char_boundary(start) { start -= 1; }
            let mut end = (start + remove).min(text.len());
            while !text.is_char_boundary(end) { end += 1; }
            text.replace_range(start..end, &insert);
        }
        list_text(&text);
    }
}

/// Preprocesses arbitrary text (with the bundled library reachable) under some keywords: no
/// panic, every output byte maps back into a file, and diagnostics render.
fn preprocess_text(text: &str, keywords: &[&str]) {
    let mut store = SourceStore::new();
    let file = store.add("fuzz.wgsl", text);
    let mut includes = kiln::preprocess::Includes::new(kiln::preprocess::IncludeConfig::new(Vec::new()));
    let span = kiln::source::Span::new(file, 0..text.len());
    let (program, mut diagnostics) = includes.load_program(&mut store, &[span]);
    let out =
        kiln::preprocess::preprocess(&includes, &store, &program, keywords, kiln::preprocess::Stage::Vertex);
    for offset in 0..out.text.len() {
        let origin = out.source_map.locate(offset).expect("every output byte is mapped");
        assert!(origin.span.end as usize <= store.text(origin.span.file).len());
    }
    diagnostics.extend(out.diagnostics);
    let _ = kiln::diagnostics::render_plain(&store, &diagnostics);
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 256, ..ProptestConfig::default() })]

    #[test]
    fn arbitrary_preprocessor_input_never_panics(
        lines in proptest::collection::vec(
            prop_oneof![
                "#(if|ifdef|ifndef|elif|else|endif|define|undef|include|error|warning|pragma)[ (A-Z_a-z0-9!&|<>=+*/%\")]{0,16}",
                "#include \"(Common|BRDF|Light|fuzz)\\.wgsl\"",
                "[ -~]{0,30}",
                "/\\*|\\*/|//.*|\\\\",
            ],
            0..40,
        ),
        keywords in proptest::collection::vec("_?[A-C]", 0..3),
    ) {
        let keywords: Vec<&str> = keywords.iter().map(String::as_str).collect();
        preprocess_text(&lines.join("\n"), &keywords);
    }
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 256, ..ProptestConfig::default() })]

    /// Materials with arbitrary (mostly TOML-looking) text, against the Lit shader.
    #[test]
    fn arbitrary_material_text_never_panics(
        lines in proptest::collection::vec(
            prop_oneof![
                Just("shader = \"Custom RP/Lit\"".to_string()),
                Just("[properties]".to_string()),
                "(preset|render_queue|keywords|_BaseColor|_Cutoff|_Clipping|_SrcBlend|_ZWrite|_PremulAlpha) = (\"[A-Za-z+]{0,12}\"|-?[0-9]{1,6}(\\.[0-9]{1,3})?|\\[[0-9., \"_A-Z]{0,20}\\]|true|false)",
                "[ -~]{0,30}",
            ],
            0..12,
        ),
    ) {
        let mut store = SourceStore::new();
        let shader = store.load(&crate::support::root().join("fixtures/project/shaders/Lit.shader")).expect("fixture");
        let material = store.add("fuzz.mat", lines.join("\n"));
        let mut includes = kiln::preprocess::Includes::new(kiln::preprocess::IncludeConfig::new(Vec::new()));
        let input = kiln::catalog::CatalogInput { shaders: vec![shader], materials: vec![material], ..Default::default() };
        let (_, diagnostics) = kiln::listing::list_shaders(&mut store, &mut includes, &input);
        let _ = kiln::diagnostics::render_plain(&store, &diagnostics);
    }
}

#[test]
fn a_file_over_the_size_limit_is_refused_not_read() {
    let dir = tempfile::tempdir().expect("temp dir");
    let path = dir.path().join("huge.shader");
    let file = std::fs::File::create(&path).expect("create");
    file.set_len(kiln::source::MAX_FILE_SIZE + 1).expect("sparse file");
    let mut store = SourceStore::new();
    let (ids, diagnostics) = kiln::project::load_files(&mut store, &[path]);
    assert!(ids.is_empty());
    assert_eq!(diagnostics.len(), 1);
    assert_eq!(diagnostics[0].code, "K0004");
    assert!(diagnostics[0].message.contains("more than the 16777216 bytes"), "{}", diagnostics[0].message);
}

/// Found by the `shader_parser` fuzz target: a multi-byte character (here a byte-order mark)
/// right before a comment in a program block panicked the pragma scanner.
#[test]
fn a_multibyte_character_before_a_comment_in_a_program() {
    for text in [
        "Shader \"A\" { SubShader { Pass { CGPROGRAM\n a\u{feff}/* b */ c\n #pragma vertex v \u{feff}// x\nENDCG } } }",
        "Shader \"A\" { SubShader { Pass { WGSLPROGRAM\n/* \u{e9}\u{feff}*/ #pragma fragment f\u{feff}\nENDWGSL } } }",
    ] {
        list_text(text);
    }
}

/// 17 shaders of 250 distinct keywords each, a `pragma` line each.
fn many_keyword_shaders(pragma: &str) -> (SourceStore, Vec<kiln::source::FileId>) {
    let mut store = SourceStore::new();
    let files = (0..17)
        .map(|s| {
            let pragmas: String = (0..250).map(|k| format!("#pragma {pragma} _S{s}_K{k}\n")).collect();
            let text = format!(
                "Shader \"Limits/S{s}\" {{ SubShader {{ Pass {{\nWGSLPROGRAM\n{pragmas}ENDWGSL\n}} }} }}\n"
            );
            store.add(format!("limits/S{s:02}.shader"), text)
        })
        .collect();
    (store, files)
}

fn catalog_of(
    store: &mut SourceStore,
    shaders: Vec<kiln::source::FileId>,
) -> Vec<kiln::diagnostics::Diagnostic> {
    let mut includes = kiln::preprocess::Includes::new(kiln::preprocess::IncludeConfig::new(Vec::new()));
    let input = kiln::catalog::CatalogInput { shaders, ..Default::default() };
    kiln::catalog::catalog(store, &mut includes, &input).1
}

#[test]
fn a_project_over_the_global_keyword_limit_is_refused_at_the_first_keyword_over() {
    let (mut store, files) = many_keyword_shaders("shader_feature");
    let limit: Vec<_> = catalog_of(&mut store, files).into_iter().filter(|d| d.code == "K0214").collect();
    assert_eq!(limit.len(), 1);
    expect_test::expect_file![crate::support::root().join("tests/golden/limits/global_keywords.stderr")]
        .assert_eq(&kiln::diagnostics::render_plain(&store, &limit));
    // Local keywords are per shader: the same count of them is fine.
    let (mut store, files) = many_keyword_shaders("shader_feature_local");
    assert!(catalog_of(&mut store, files).iter().all(|d| d.code != "K0214"));
}

#[cfg(target_os = "linux")]
#[test]
fn a_thread_count_past_the_bound_runs_no_more_workers_than_the_bound() {
    let dir = tempfile::tempdir().expect("temp dir");
    let project = dir.path().join("project");
    crate::support::synthetic_project(&project, 160);
    let mut child = std::process::Command::new(env!("CARGO_BIN_EXE_kiln"))
        .args(["build", project.to_str().expect("utf-8"), "--output"])
        .arg(dir.path().join("out"))
        .env("RAYON_NUM_THREADS", "100000")
        .stderr(std::process::Stdio::null())
        .spawn()
        .expect("kiln runs");
    let status = format!("/proc/{}/status", child.id());
    let mut most = 0;
    while child.try_wait().expect("wait").is_none() {
        let threads = std::fs::read_to_string(&status).ok().and_then(|s| {
            s.lines().find_map(|l| l.strip_prefix("Threads:").and_then(|n| n.trim().parse::<usize>().ok()))
        });
        most = most.max(threads.unwrap_or(0));
    }
    assert!(child.wait().expect("ends").success());
    // The workers, the main thread, the remote cache's uploaders and a few readers.
    assert!(most > 0 && most <= kiln::config::MAX_THREADS + 32, "{most} threads");
}
