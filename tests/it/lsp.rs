//! `kiln lsp` driven through the real protocol: the built binary on stdio, framed JSON-RPC
//! messages as an editor sends them, on a copy of the bundled example project.

use crate::lsp_client::{Client, uri};
use crate::support::{example_project_copy, fixture_copy, root};
use serde_json::{Value, json};
use std::path::{Path, PathBuf};
use std::process::Command;

fn position(line: u32, character: u32) -> Value {
    json!({ "line": line, "character": character })
}

fn at(uri: &str, line: u32, character: u32) -> Value {
    json!({ "textDocument": { "uri": uri }, "position": position(line, character) })
}

/// The 0-based line and column of the first `needle` in `text`.
fn find(text: &str, needle: &str) -> (u32, u32) {
    let offset = text.find(needle).unwrap_or_else(|| panic!("`{needle}` not in the text"));
    let line = text[..offset].matches('\n').count();
    let column = offset - text[..offset].rfind('\n').map_or(0, |n| n + 1);
    (line as u32, column as u32)
}

/// Opens a file of the project as saved; its URI and text.
fn open_saved(client: &mut Client, project: &Path, relative: &str) -> (String, String) {
    let path = project.join(relative);
    let text = std::fs::read_to_string(&path).expect("a file of the project");
    let uri = uri(&path);
    client.open(&uri, &text);
    (uri, text)
}

fn errors(diagnostics: &[Value]) -> Vec<&Value> {
    diagnostics.iter().filter(|d| d["severity"] == 1).collect()
}

struct Session {
    _dir: tempfile::TempDir,
    project: PathBuf,
    client: Client,
}

fn session() -> Session {
    let dir = tempfile::tempdir().expect("tempdir");
    let project = example_project_copy(dir.path());
    let client = Client::start(dir.path());
    Session { _dir: dir, project, client }
}

#[test]
fn an_error_typed_in_an_include_is_shown_there_with_its_variants_and_the_includer() {
    let Session { _dir, project, mut client } = session();
    let (pass_uri, saved) = open_saved(&mut client, &project, "shaders/LitPass.wgsl");
    assert_eq!(errors(&client.diagnostics(&pass_uri, Some(1))), Vec::<&Value>::new());

    // Unsaved: a name that does not exist, inside the `_CLIPPING` group.
    let broken =
        saved.replace("        discard;\n", "        discard;\n        let oops: f32 = undefined_thing;\n");
    client.change(&pass_uri, 2, &broken);
    let diagnostics = client.diagnostics(&pass_uri, Some(2));
    let found = errors(&diagnostics);
    assert_eq!(found.len(), 1, "{diagnostics:#?}");
    let (line, _) = find(&broken, "undefined_thing");
    assert_eq!(found[0]["range"]["start"]["line"], line, "{:#}", found[0]);
    let message = found[0]["message"].as_str().expect("message");
    assert!(message.contains("undefined_thing"), "{message}");
    // Lit's pass builds 3 variants (its materials' keywords: none, `_CLIPPING`,
    // `_PREMULTIPLY_ALPHA`); the one with `_CLIPPING` has the error, and it says so.
    assert!(message.contains("in 1 of 3 variants of `Custom RP/Lit` pass 0"), "{message}");
    assert!(message.contains("those with `_CLIPPING`"), "{message}");
    let related = found[0]["relatedInformation"].as_array().expect("related places");
    let lit_shader = uri(&project.join("shaders/Lit.shader"));
    assert!(related.iter().any(|r| r["location"]["uri"] == lit_shader.as_str()), "{related:#?}");
    // The whole diagnostic as the editor gets it, reviewed like any golden file.
    let project_uri = uri(&project);
    let shown =
        serde_json::to_string_pretty(found[0]).expect("json").replace(&project_uri, "file:///PROJECT");
    expect_test::expect_file![root().join("tests/golden/lsp/include_error.json")]
        .assert_eq(&format!("{shown}\n"));
    // The disk still has the saved text: a check never writes.
    assert_eq!(std::fs::read_to_string(project.join("shaders/LitPass.wgsl")).expect("LitPass"), saved);
    // The passes' other variants still compile: a uniform member's layout is still there, with
    // a variant of each pass that has `_Cutoff` broken (Unlit's too).
    let (unlit_uri, unlit) = open_saved(&mut client, &project, "shaders/UnlitPass.wgsl");
    let unlit_broken = unlit.replace("discard;\n", "discard;\n        let oops: f32 = undefined_thing;\n");
    assert_ne!(unlit_broken, unlit);
    client.change(&unlit_uri, 2, &unlit_broken);
    assert_eq!(errors(&client.diagnostics(&unlit_uri, Some(2))).len(), 1);
    let (line, column) = find(&broken, "_Cutoff) {");
    let hover = client.request("textDocument/hover", at(&pass_uri, line, column + 1));
    let member = hover["contents"]["value"].as_str().unwrap_or_default();
    assert!(member.contains("offset 32, size 4, alignment 4"), "hover with a variant broken: {hover}");
    client.change(&unlit_uri, 3, &unlit);

    client.change(&pass_uri, 3, &saved);
    assert_eq!(errors(&client.diagnostics(&pass_uri, Some(3))), Vec::<&Value>::new());
    client.shutdown();
}

#[test]
fn hover_explains_keywords_includes_properties_and_uniform_members() {
    let Session { _dir, project, mut client } = session();
    let (shader_uri, shader_text) = open_saved(&mut client, &project, "shaders/Lit.shader");
    let hover = |client: &mut Client, uri: &str, (line, column): (u32, u32)| -> String {
        let result = client.request("textDocument/hover", at(uri, line, column + 1));
        result["contents"]["value"].as_str().unwrap_or_default().to_string()
    };
    let keyword = hover(&mut client, &shader_uri, find(&shader_text, "_CLIPPING\n"));
    assert!(keyword.contains("`shader_feature` keyword"), "{keyword}");
    assert!(keyword.contains("LitClip"), "materials that enable it: {keyword}");
    assert!(keyword.contains("in 2 of the project's"), "{keyword}");

    let include = hover(&mut client, &shader_uri, find(&shader_text, "\"LitPass.wgsl\""));
    assert!(
        include.contains(
            &project.join("shaders/LitPass.wgsl").canonicalize().expect("path").display().to_string()
        ),
        "{include}"
    );

    let (material_uri, material_text) = open_saved(&mut client, &project, "materials/LitClip.mat");
    let property = hover(&mut client, &material_uri, find(&material_text, "_Cutoff"));
    assert!(property.contains("\"Alpha Cutoff\""), "{property}");
    assert!(property.contains("material uniform block: offset 32"), "{property}");

    let (pass_uri, pass_text) = open_saved(&mut client, &project, "shaders/LitPass.wgsl");
    let member = hover(&mut client, &pass_uri, find(&pass_text, "_Cutoff) {"));
    assert!(member.contains("`_Cutoff: f32` in `UnityPerMaterial`"), "{member}");
    assert!(member.contains("offset 32, size 4, alignment 4"), "{member}");
    let library = hover(&mut client, &pass_uri, find(&pass_text, "\"Common.wgsl\""));
    assert!(library.contains("bundled shader library"), "{library}");
    let macro_hover = hover(&mut client, &pass_uri, find(&pass_text, "CUSTOM_LIT_PASS_INCLUDED"));
    assert!(macro_hover.contains("#define CUSTOM_LIT_PASS_INCLUDED"), "{macro_hover}");
    // A macro used in the library: its definition, and what it expands to there.
    let brdf = client.request("textDocument/definition", json!({ "textDocument": { "uri": pass_uri }, "position": { "line": find(&pass_text, "\"BRDF.wgsl\"").0, "character": 12 } }));
    let brdf_uri = brdf["uri"].as_str().expect("BRDF.wgsl").to_string();
    let brdf_text =
        std::fs::read_to_string(brdf_uri.strip_prefix("file://").expect("file")).expect("BRDF.wgsl");
    client.open(&brdf_uri, &brdf_text);
    let use_line = brdf_text
        .lines()
        .position(|l| l.contains("MIN_REFLECTIVITY") && !l.contains("#define"))
        .expect("a use");
    let column = brdf_text.lines().nth(use_line).expect("line").find("MIN_REFLECTIVITY").expect("column");
    let expansion = hover(&mut client, &brdf_uri, (use_line as u32, column as u32));
    assert!(expansion.contains("#define MIN_REFLECTIVITY 0.04"), "{expansion}");
    // The first pass that reads BRDF.wgsl is Complex's; its active variant, the first its materials use.
    assert!(expansion.contains("expands here, in `Custom RP/Complex` pass 0, variant `"), "{expansion}");
    assert!(expansion.ends_with("to:\n```wgsl\n0.04\n```"), "{expansion}");
    client.shutdown();
}

#[test]
fn go_to_definition_follows_includes_keywords_properties_and_functions() {
    let Session { _dir, project, mut client } = session();
    let (pass_uri, pass_text) = open_saved(&mut client, &project, "shaders/LitPass.wgsl");
    let definition = |client: &mut Client, uri: &str, (line, column): (u32, u32)| -> Value {
        client.request("textDocument/definition", at(uri, line, column + 1))
    };
    // A library function: into the bundled file kiln writes out for the editor.
    let function = definition(&mut client, &pass_uri, find(&pass_text, "GetLighting(surface"));
    let target = function["uri"].as_str().expect("a location");
    assert!(target.ends_with("/Lighting.wgsl"), "{function}");
    let path = url_path(target);
    let text = std::fs::read_to_string(&path).expect("the library file is on disk");
    assert_eq!(text, std::fs::read_to_string(root().join("shaderlib/Lighting.wgsl")).expect("library"));
    let line = function["range"]["start"]["line"].as_u64().expect("line") as usize;
    assert!(text.lines().nth(line).expect("line").contains("fn GetLighting("), "{function}");

    let include = definition(&mut client, &pass_uri, find(&pass_text, "\"BRDF.wgsl\""));
    assert!(include["uri"].as_str().expect("uri").ends_with("/BRDF.wgsl"), "{include}");

    let (material_uri, material_text) = open_saved(&mut client, &project, "materials/LitClip.mat");
    let property = definition(&mut client, &material_uri, find(&material_text, "_Cutoff"));
    let shader = project.join("shaders/Lit.shader");
    let shader_text = std::fs::read_to_string(&shader).expect("Lit");
    assert_eq!(property["uri"], uri(&shader).as_str());
    assert_eq!(property["range"]["start"]["line"], find(&shader_text, "_Cutoff (").0);

    let keyword = definition(&mut client, &pass_uri, find(&pass_text, "_CLIPPING"));
    assert_eq!(keyword["uri"], uri(&shader).as_str());
    let pragma = find(&shader_text, "#pragma shader_feature _CLIPPING");
    assert_eq!(keyword["range"]["start"]["line"], pragma.0, "{keyword}");

    let local = definition(&mut client, &pass_uri, find(&pass_text, "Varyings {"));
    assert_eq!(local["range"]["start"]["line"], find(&pass_text, "struct Varyings").0);
    client.shutdown();
}

fn url_path(uri: &str) -> PathBuf {
    PathBuf::from(uri.strip_prefix("file://").expect("a file URI"))
}

#[test]
fn completion_offers_keywords_properties_pragmas_and_include_paths() {
    let Session { _dir, project, mut client } = session();
    let labels = |result: Value| -> Vec<String> {
        result
            .as_array()
            .expect("items")
            .iter()
            .map(|i| i["label"].as_str().expect("label").to_string())
            .collect()
    };
    let material = project.join("materials/LitClip.mat");
    let material_uri = uri(&material);
    let text = "shader = \"Custom RP/Lit\"\nkeywords = [\"\n[properties]\n_\n";
    client.open(&material_uri, text);
    let keywords = labels(client.request("textDocument/completion", at(&material_uri, 1, 13)));
    assert!(
        keywords.contains(&"_CLIPPING".to_string()) && keywords.contains(&"_PREMULTIPLY_ALPHA".to_string()),
        "{keywords:?}"
    );
    assert!(!keywords.contains(&"_EMISSION_MAP".to_string()), "another shader's keyword: {keywords:?}");
    let properties = labels(client.request("textDocument/completion", at(&material_uri, 3, 1)));
    assert!(
        properties.contains(&"_BaseColor".to_string()) && properties.contains(&"_Cutoff".to_string()),
        "{properties:?}"
    );

    let pass = project.join("shaders/LitPass.wgsl");
    let pass_uri = uri(&pass);
    let pass_text = std::fs::read_to_string(&pass).expect("LitPass");
    let edited =
        pass_text.replace("#include \"Common.wgsl\"\n", "#include \"\n#pragma \n#if defined(\n#endif\n");
    client.open(&pass_uri, &edited);
    let (line, _) = find(&edited, "#include \"\n");
    let includes = labels(client.request("textDocument/completion", at(&pass_uri, line, 10)));
    assert!(
        includes.contains(&"Common.wgsl".to_string()) && includes.contains(&"UnlitPass.wgsl".to_string()),
        "{includes:?}"
    );
    let pragmas = labels(client.request("textDocument/completion", at(&pass_uri, line + 1, 8)));
    assert!(
        pragmas.contains(&"multi_compile".to_string()) && pragmas.contains(&"multi_compile_fog".to_string()),
        "{pragmas:?}"
    );
    let conditions = labels(client.request("textDocument/completion", at(&pass_uri, line + 2, 12)));
    assert!(conditions.contains(&"_CLIPPING".to_string()), "{conditions:?}");
    client.shutdown();
}

#[test]
fn document_symbols_outline_the_shader() {
    let Session { _dir, project, mut client } = session();
    let shader = project.join("shaders/Lit.shader");
    let shader_uri = uri(&shader);
    client.open(&shader_uri, &std::fs::read_to_string(&shader).expect("Lit"));
    let symbols =
        client.request("textDocument/documentSymbol", json!({ "textDocument": { "uri": shader_uri } }));
    let names = |s: &Value| -> Vec<String> {
        s["children"]
            .as_array()
            .into_iter()
            .flatten()
            .map(|c| c["name"].as_str().expect("name").to_string())
            .collect()
    };
    assert_eq!(symbols[0]["name"], "Shader \"Custom RP/Lit\"");
    assert_eq!(names(&symbols[0]), ["Properties", "SubShader 0"]);
    assert_eq!(names(&symbols[0]["children"][0]).len(), 10, "the ten properties");
    assert_eq!(names(&symbols[0]["children"][1]), ["Pass 0"]);
    client.shutdown();
}

/// The hints for regions the active variant leaves out, by 0-based line.
fn inactive_lines(diagnostics: &[Value]) -> Vec<u64> {
    let mut lines: Vec<u64> = diagnostics
        .iter()
        .filter(|d| d["severity"] == 4 && d["tags"] == json!([1]))
        .flat_map(|d| {
            let (start, end) = (&d["range"]["start"]["line"], &d["range"]["end"]["line"]);
            start.as_u64().expect("line")..=end.as_u64().expect("line")
        })
        .collect();
    lines.dedup();
    lines
}

#[test]
fn the_active_variant_greys_out_what_it_leaves_out_and_can_be_changed() {
    let Session { _dir, project, mut client } = session();
    let shader = project.join("shaders/Lit.shader");
    let shader_uri = uri(&shader);
    let pass = project.join("shaders/LitPass.wgsl");
    let pass_uri = uri(&pass);
    let pass_text = std::fs::read_to_string(&pass).expect("LitPass");
    client.open(&shader_uri, &std::fs::read_to_string(&shader).expect("Lit"));
    client.open(&pass_uri, &pass_text);
    let clip = find(&pass_text, "if (base.a < UnityPerMaterial._Cutoff)").0 as u64;
    let premultiplied = find(&pass_text, "GetBRDF(surface, true)").0 as u64;
    let straight = find(&pass_text, "GetBRDF(surface, false)").0 as u64;
    // The default: the first variant a material uses (LitOpaque: no keywords).
    client.request("textDocument/documentSymbol", json!({ "textDocument": { "uri": pass_uri } }));
    let lines = inactive_lines(&client.latest_diagnostics(&pass_uri));
    assert!(
        lines.contains(&clip) && lines.contains(&premultiplied) && !lines.contains(&straight),
        "{lines:?}"
    );

    let lenses = client.request("textDocument/codeLens", json!({ "textDocument": { "uri": shader_uri } }));
    let title = lenses[0]["command"]["title"].as_str().expect("a lens").to_string();
    assert!(title.starts_with("variant 1 of 3: (no keywords)"), "{title}");

    let args = json!([shader_uri, "Custom RP/Lit", 0, ["_PREMULTIPLY_ALPHA"]]);
    let chosen = client
        .request("workspace/executeCommand", json!({ "command": "kiln.selectVariant", "arguments": args }));
    assert_eq!(chosen, json!(["_PREMULTIPLY_ALPHA"]));
    let lines = inactive_lines(&client.latest_diagnostics(&pass_uri));
    assert!(
        lines.contains(&clip) && !lines.contains(&premultiplied) && lines.contains(&straight),
        "{lines:?}"
    );

    let args = json!([shader_uri, "Custom RP/Lit", 0]);
    let mut seen = Vec::new();
    for _ in 0..3 {
        seen.push(client.request(
            "workspace/executeCommand",
            json!({ "command": "kiln.nextVariant", "arguments": args }),
        ));
    }
    assert_eq!(seen.last(), Some(&json!(["_PREMULTIPLY_ALPHA"])), "three steps come back round: {seen:?}");
    assert!(seen.contains(&json!([])) && seen.contains(&json!(["_CLIPPING"])), "{seen:?}");
    let refused = client.request_raw(
        "workspace/executeCommand",
        json!({ "command": "kiln.selectVariant", "arguments": [shader_uri, "Custom RP/Lit", 0, ["_NOPE"]] }),
    );
    assert!(
        refused["error"]["message"].as_str().expect("an error").contains("no built variant"),
        "{refused}"
    );
    client.shutdown();
}

#[test]
fn bad_buffers_get_diagnostics_and_the_server_keeps_serving() {
    let Session { _dir, project, mut client } = session();
    let (pass_uri, pass_text) = open_saved(&mut client, &project, "shaders/LitPass.wgsl");
    client.diagnostics(&pass_uri, Some(1));
    // Half-typed directives, one keystroke at a time.
    let mut typed = String::new();
    for (version, c) in "#if defined(_CLI".chars().enumerate() {
        typed.push(c);
        let text =
            pass_text.replace("#include \"Common.wgsl\"\n", &format!("#include \"Common.wgsl\"\n{typed}\n"));
        client.change(&pass_uri, version as i64 + 2, &text);
    }
    let last = "#if defined(_CLI".len() as i64 + 1;
    let diagnostics = client.diagnostics(&pass_uri, Some(last));
    assert!(!errors(&diagnostics).is_empty(), "an unterminated `#if` is an error: {diagnostics:#?}");
    // Binary data in a buffer.
    client.change(&pass_uri, last + 1, "\u{0}\u{1}\u{fffd}#if\u{0}");
    client.diagnostics(&pass_uri, Some(last + 1));
    // A broken kiln.toml: its error, at the file.
    let config = project.join("kiln.toml");
    let config_uri = uri(&config);
    client.open(&config_uri, "shaders = [\"shaders\"\nbackends = 3\n");
    let config_errors = client.diagnostics(&config_uri, Some(1));
    assert!(!errors(&config_errors).is_empty(), "{config_errors:#?}");
    // A file outside any project: nothing to say, no crash.
    let outside = tempfile::tempdir().expect("tempdir");
    let lone = outside.path().join("Lone.wgsl");
    std::fs::write(&lone, "fn f() {}\n").expect("write");
    let lone_uri = uri(&lone);
    client.open(&lone_uri, "fn f() {}\n");
    assert_eq!(client.request("textDocument/hover", at(&lone_uri, 0, 3)), Value::Null);
    // Unknown requests are refused, not fatal.
    let unknown = client.request_raw("textDocument/rename", at(&pass_uri, 0, 0));
    assert_eq!(unknown["error"]["code"], -32601, "{unknown}");
    // Still serving: the saved text back, hover answers.
    client.notify("textDocument/didClose", json!({ "textDocument": { "uri": config_uri } }));
    client.change(&pass_uri, last + 2, &pass_text);
    assert_eq!(errors(&client.diagnostics(&pass_uri, Some(last + 2))), Vec::<&Value>::new());
    let hover = client.request(
        "textDocument/hover",
        at(&pass_uri, find(&pass_text, "_Cutoff)").0, find(&pass_text, "_Cutoff)").1 + 1),
    );
    assert!(hover["contents"]["value"].as_str().expect("hover").contains("offset 32"), "{hover}");
    client.shutdown();
}

/// Neovim's own LSP client (Debian's `neovim`), headless: the error typed into an include shows
/// at the line it was typed on.
#[test]
fn neovim_shows_an_error_typed_into_an_include_at_its_line() {
    if !crate::support::tool("nvim", "neovim", "neovim_shows_an_error_typed_into_an_include_at_its_line") {
        return;
    }
    let dir = tempfile::tempdir().expect("tempdir");
    let project = example_project_copy(dir.path());
    let report = dir.path().join("report.txt");
    let run = Command::new("nvim")
        .args(["--headless", "--clean", "-c"])
        .arg(format!("luafile {}", root().join("tests/editor/neovim.lua").display()))
        .env("KILN", env!("CARGO_BIN_EXE_kiln"))
        .env("KILN_FILE", project.join("shaders/LitPass.wgsl"))
        .env("KILN_CACHE", dir.path().join("cache"))
        .env("KILN_OUT", &report)
        .env("XDG_CACHE_HOME", dir.path())
        .output()
        .expect("nvim runs");
    let report = std::fs::read_to_string(&report).unwrap_or_else(|_| {
        panic!(
            "nvim wrote no report: {}{}",
            String::from_utf8_lossy(&run.stdout),
            String::from_utf8_lossy(&run.stderr)
        )
    });
    assert!(report.ends_with("status ok\n"), "{report}");
    // `typed-at N`: the typed line is line N (0-based) of the buffer.
    let typed: u32 =
        report.lines().find_map(|l| l.strip_prefix("typed-at ")?.parse().ok()).expect("typed-at");
    let errors: Vec<&str> = report.lines().filter(|l| l.starts_with("error ")).collect();
    assert_eq!(errors.len(), 1, "{report}");
    assert!(
        errors[0].starts_with(&format!(
            "error {typed} 24 no definition in scope for identifier: `undefined_thing`"
        )),
        "{report}"
    );
}

/// Pieces of text an edit inserts: directives half typed, brackets, quotes, non-ASCII, NUL.
const TYPED: [&str; 12] = [
    "#if defined(",
    "#endif\n",
    "#include \"",
    "#define X(a) a",
    "}",
    "{",
    "\"",
    "\n",
    "é\u{1F600}",
    "\u{0}",
    "_CLIPPING",
    "fn f(",
];

proptest::proptest! {
    #![proptest_config(proptest::prelude::ProptestConfig { cases: 24, ..proptest::prelude::ProptestConfig::default() })]

    /// Random edit sequences on an include of the example project: the server answers every
    /// request after every edit and ends cleanly (the `lsp_edits` fuzz target runs the same).
    #[test]
    fn random_edits_never_stop_the_server(
        edits in proptest::collection::vec((0usize..3000, 0usize..40, 0usize..TYPED.len()), 1..12)
    ) {
        let dir = tempfile::tempdir().expect("tempdir");
        let project = example_project_copy(dir.path());
        let edits: Vec<crate::lsp_edits::Edit> = edits
            .into_iter()
            .map(|(start, removed, typed)| crate::lsp_edits::Edit { start, removed, inserted: TYPED[typed].to_string() })
            .collect();
        crate::lsp_edits::replay(&project.join("shaders/LitPass.wgsl"), dir.path(), &edits);
    }
}

/// An edit compiles again only the modules of the passes that read the edited file; the rest
/// come from the module cache a build uses.
#[test]
fn an_edit_compiles_only_the_passes_that_read_the_file() {
    let Session { _dir, project, mut client } = session();
    let (unlit_uri, text) = open_saved(&mut client, &project, "shaders/UnlitPass.wgsl");
    let first = client.notification(kiln::lsp::CHECKED);
    assert_eq!(first["reused"], 0, "a cold cache: {first}");
    let all = first["compiled"].as_u64().expect("compiled");
    client.change(&unlit_uri, 2, &text.replace("return", "return /* edited */"));
    let second = client.notification(kiln::lsp::CHECKED);
    let compiled = second["compiled"].as_u64().expect("compiled");
    // Unlit's pass: its variants' fragment modules and the vertex module the edit changed.
    assert!(compiled > 0 && compiled < all / 2, "{first} then {second}");
    assert_eq!(second["reused"].as_u64().expect("reused") + compiled, all, "{second}");
    client.shutdown();
}

/// A client that goes away (stdin closed before `initialize`, or bytes that are not the
/// protocol) ends the server with exit 2 and the reason, never a hang.
#[test]
fn a_client_that_goes_away_ends_the_server() {
    for input in [&b""[..], b"Content-Length: 5\r\n\r\nhello"] {
        let mut child = Command::new(env!("CARGO_BIN_EXE_kiln"))
            .arg("lsp")
            .stdin(std::process::Stdio::piped())
            .stdout(std::process::Stdio::null())
            .stderr(std::process::Stdio::piped())
            .spawn()
            .expect("kiln lsp starts");
        let mut stdin = child.stdin.take().expect("stdin");
        std::io::Write::write_all(&mut stdin, input).expect("write");
        drop(stdin);
        let output = crate::support::output_within_a_minute(child, "kiln lsp");
        let stderr = String::from_utf8_lossy(&output.stderr);
        assert_eq!(output.status.code(), Some(2), "{stderr}");
        assert!(stderr.contains("error[K0007]: language server protocol"), "{stderr}");
    }
}

/// A client that can watch files for the server is asked to watch the project's; a file changed
/// on disk (not open in the editor) is checked again when the client says so.
#[test]
fn files_changed_behind_the_editor_are_checked_again() {
    let dir = tempfile::tempdir().expect("tempdir");
    let project = example_project_copy(dir.path());
    let capabilities = json!({ "workspace": { "didChangeWatchedFiles": { "dynamicRegistration": true } } });
    let mut client = Client::start_with(dir.path(), capabilities);
    let registration = client.notification("client/registerCapability");
    let watchers = &registration["registrations"][0]["registerOptions"]["watchers"];
    assert!(
        watchers.to_string().contains("**/*.{shader,compute,wgsl,hlsl,hlsli,cginc,mat}"),
        "{registration}"
    );
    let (lit_uri, _) = open_saved(&mut client, &project, "shaders/LitPass.wgsl");
    client.diagnostics(&lit_uri, Some(1));
    let unlit = project.join("shaders/UnlitPass.wgsl");
    let text = std::fs::read_to_string(&unlit).expect("UnlitPass");
    std::fs::write(&unlit, text.replacen("return", "return not_declared +", 1)).expect("write");
    let unlit_uri = uri(&unlit);
    let changes = json!({ "changes": [{ "uri": unlit_uri, "type": 2 }] });
    client.notify("workspace/didChangeWatchedFiles", changes);
    // Unlit's publications until one has the error (its inactive regions were published before
    // the change; each wait fails the test after a minute).
    let names_it = |d: &&Value| d["message"].as_str().is_some_and(|m| m.contains("not_declared"));
    while !errors(&client.diagnostics(&unlit_uri, None)).iter().any(names_it) {}
    client.shutdown();
}

#[test]
fn an_edit_publishes_its_own_buffer_and_what_it_changed_not_every_open_buffer() {
    let Session { _dir, project, mut client } = session();
    let others = [
        "shaders/Lit.shader",
        "shaders/Unlit.shader",
        "shaders/Complex.shader",
        "shaders/ComplexPass.wgsl",
        "shaders/UnlitPass.wgsl",
    ];
    for relative in others {
        open_saved(&mut client, &project, relative);
    }
    let (edited, text) = open_saved(&mut client, &project, "shaders/LitPass.wgsl");
    client.diagnostics(&edited, Some(1));
    let hover = |client: &mut Client| client.request("textDocument/hover", at(&edited, 0, 0));
    hover(&mut client);
    let opened = client.publications();
    assert!(opened.len() >= others.len(), "each open buffer is shown its diagnostics once: {opened:?}");
    // Edits that change no diagnostic: the edited buffer is published for each version, nothing else.
    for version in 2..=11 {
        client.change(&edited, version, &format!("{text}\n// edit {version}\n"));
        client.diagnostics(&edited, Some(version));
    }
    hover(&mut client);
    let published = client.publications();
    let elsewhere: usize = published.iter().filter(|(uri, _)| **uri != edited).map(|(_, n)| n).sum();
    assert_eq!(elsewhere, 0, "unchanged buffers published again: {published:?}");
    // An edit that breaks a file the others include is published where it shows.
    client.change(&edited, 12, &text.replace("return", "retrun"));
    assert!(!errors(&client.diagnostics(&edited, Some(12))).is_empty());
    client.shutdown();
}

/// A shader whose check takes naga seconds (eight functions of about 43,000 operands and
/// operators each, under kiln's cap per function: naga's time grows with each one's square),
/// its result `version` apart from the others'.
fn slow_shader(version: u32) -> String {
    let statements = "S3 ".repeat(24);
    let functions: String = (0..8)
        .map(|i| format!("            fn f{i}(x: f32) -> f32 {{ var v = x; {statements} return v; }}\n"))
        .collect();
    let calls = (0..8).map(|i| format!("f{i}({version}.0)")).collect::<Vec<_>>().join(" + ");
    format!(
        "Shader \"Test/Slow\" {{\n    SubShader {{\n        Pass {{\n            WGSLPROGRAM\n\
         #pragma vertex Vertex\n            #pragma fragment Fragment\n\
         #define S1 v = v * 1.0001 + 0.5;\n\
         #define S2 S1 S1 S1 S1 S1 S1 S1 S1 S1 S1 S1 S1 S1 S1 S1 S1\n\
         #define S3 S2 S2 S2 S2 S2 S2 S2 S2 S2 S2 S2 S2 S2 S2 S2 S2\n{functions}\
         @vertex fn Vertex() -> @builtin(position) vec4<f32> {{ return vec4<f32>(1.0); }}\n\
         @fragment fn Fragment() -> @location(0) vec4<f32> {{ return vec4<f32>({calls}); }}\n\
         ENDWGSL\n        }}\n    }}\n}}\n"
    )
}

/// While a slow check runs, a hover elsewhere is answered at once (from the last check), and an
/// edit to the file being checked cancels the check: its result, for a text the editor no longer
/// has, is never published, and the check that follows is of the edit.
#[test]
fn an_edit_cancels_the_check_it_makes_moot_and_requests_are_answered_meanwhile() {
    let Session { _dir, project, mut client } = session();
    let (lit_uri, lit) = open_saved(&mut client, &project, "shaders/LitPass.wgsl");
    client.notification(kiln::lsp::CHECKED);
    client.publications();
    let slow = project.join("shaders/Slow.shader");
    std::fs::write(&slow, slow_shader(0)).expect("shader");
    std::fs::write(project.join("materials/Slow.mat"), "shader = \"Test/Slow\"\n").expect("material");
    let slow_uri = crate::lsp_client::uri(&slow);

    client.open(&slow_uri, &slow_shader(1));
    // Long enough for the server to start checking version 1, far shorter than the check.
    std::thread::sleep(std::time::Duration::from_millis(200));
    client.change(&slow_uri, 2, &slow_shader(2));
    let (line, column) = find(&lit, "_CLIPPING)");
    let hover = client.request("textDocument/hover", at(&lit_uri, line, column + 1));
    assert_eq!(client.received(kiln::lsp::CHECKED), 0, "the hover waited for the check");
    let shown = hover["contents"]["value"].as_str().unwrap_or_default();
    assert!(shown.contains("`shader_feature` keyword"), "answered from the last check: {hover}");

    let checked = client.notification(kiln::lsp::CHECKED);
    assert_eq!(checked["cancelled"], 1, "version 1's check was cancelled by version 2: {checked}");
    assert!(checked["compiled"].as_u64().expect("compiled") >= 2, "{checked}");
    let mut published = Vec::new();
    while client.received("textDocument/publishDiagnostics") > 0 {
        let params = client.notification("textDocument/publishDiagnostics");
        if params["uri"] == slow_uri.as_str() {
            published.push(params["version"].clone());
        }
    }
    assert_eq!(published, vec![json!(2)], "only the edit the editor has is published");
    client.shutdown();
}

#[test]
fn an_error_typed_into_an_hlsl_include_is_shown_at_its_line_with_its_variants() {
    let dir = tempfile::tempdir().expect("tempdir");
    let project = fixture_copy(dir.path(), "hlsl");
    let mut client = Client::start(dir.path());
    let (pass_uri, saved) = open_saved(&mut client, &project, "shaders/UnlitPass.hlsl");
    assert_eq!(errors(&client.diagnostics(&pass_uri, Some(1))), Vec::<&Value>::new());
    // Unsaved: a name that does not exist, inside the `_CLIPPING` group.
    let broken = saved.replace(
        "    clip(base.a - _Cutoff);\n",
        "    clip(base.a - _Cutoff);\n    base *= undefined_thing;\n",
    );
    client.change(&pass_uri, 2, &broken);
    let diagnostics = client.diagnostics(&pass_uri, Some(2));
    let found = errors(&diagnostics);
    assert_eq!(found.len(), 1, "{diagnostics:#?}");
    let (line, column) = find(&broken, "undefined_thing");
    assert_eq!(found[0]["range"]["start"]["line"], line, "{:#}", found[0]);
    assert_eq!(found[0]["range"]["start"]["character"], column, "{:#}", found[0]);
    let message = found[0]["message"].as_str().expect("message");
    assert!(message.contains("undefined_thing") && message.contains("glslang"), "{message}");
    assert!(message.contains("_CLIPPING"), "{message}");
    client.change(&pass_uri, 3, &saved);
    assert_eq!(errors(&client.diagnostics(&pass_uri, Some(3))), Vec::<&Value>::new());
    // The active variant greys out in HLSL what it leaves out: `(no keywords)` the clip,
    // `_CLIPPING` nothing of it.
    let shader = project.join("shaders/Unlit.shader");
    let shader_uri = uri(&shader);
    client.open(&shader_uri, &std::fs::read_to_string(&shader).expect("Unlit"));
    let clip = find(&saved, "clip(base.a - _Cutoff)").0 as u64;
    for (keywords, greyed) in
        [(json!(["_CLIPPING"]), false), (json!([]), true), (json!(["_CLIPPING"]), false)]
    {
        let args = json!([shader_uri, "HLSL/Unlit", 0, keywords]);
        let chosen = client.request(
            "workspace/executeCommand",
            json!({ "command": "kiln.selectVariant", "arguments": args }),
        );
        assert_eq!(chosen, keywords);
        client.request("textDocument/documentSymbol", json!({ "textDocument": { "uri": pass_uri } }));
        let lines = inactive_lines(&client.latest_diagnostics(&pass_uri));
        assert_eq!(lines.contains(&clip), greyed, "{keywords}: {lines:?}");
    }
    client.shutdown();
}

#[test]
fn hover_definition_symbols_and_completion_read_hlsl() {
    let dir = tempfile::tempdir().expect("tempdir");
    let project = fixture_copy(dir.path(), "hlsl_lit");
    let mut client = Client::start(dir.path());
    let (pass_uri, pass_text) = open_saved(&mut client, &project, "shaders/LitPass.hlsl");
    assert_eq!(errors(&client.diagnostics(&pass_uri, Some(1))), Vec::<&Value>::new());
    let hover = |client: &mut Client, (line, column): (u32, u32)| -> String {
        let result = client.request("textDocument/hover", at(&pass_uri, line, column + 1));
        result["contents"]["value"].as_str().unwrap_or_default().to_string()
    };
    let definition = |client: &mut Client, (line, column): (u32, u32)| -> (PathBuf, String, u64) {
        let found = client.request("textDocument/definition", at(&pass_uri, line, column + 1));
        let path = url_path(found["uri"].as_str().unwrap_or_else(|| panic!("a location: {found}")));
        let text = std::fs::read_to_string(&path).expect("the definition's file");
        (path, text, found["range"]["start"]["line"].as_u64().expect("line"))
    };
    let line_of = |text: &str, line: u64| text.lines().nth(line as usize).unwrap_or_default().to_string();

    // A function of kiln's HLSL library: its declaration, fenced as HLSL, and the file it is in.
    let function = hover(&mut client, find(&pass_text, "TransformObjectToWorld(input"));
    assert!(
        function
            .starts_with("```hlsl\nfloat3 TransformObjectToWorld(float3 positionOS) {\n```\nCommon.hlsl:"),
        "{function}"
    );
    let (path, text, line) = definition(&mut client, find(&pass_text, "TransformObjectToWorld(input"));
    assert!(path.ends_with("Common.hlsl"), "{}", path.display());
    assert_eq!(text, std::fs::read_to_string(root().join("shaderlib/Common.hlsl")).expect("library"));
    assert!(line_of(&text, line).contains("float3 TransformObjectToWorld("), "{}", line_of(&text, line));

    // The pass's own declarations: a struct, and a function used before the cursor's file ends.
    let (_, _, line) = definition(&mut client, find(&pass_text, "Varyings LitPassVertex"));
    assert_eq!(line, u64::from(find(&pass_text, "struct Varyings").0));

    // A constant-buffer member declared through Unity's macro: the manifest's layout on hover, the
    // macro's line as its definition.
    let member = hover(&mut client, find(&pass_text, "_Cutoff));"));
    assert!(member.contains("in `UnityPerMaterial`") && member.contains("offset 32, size 4"), "{member}");
    let (_, _, line) = definition(&mut client, find(&pass_text, "_Cutoff));"));
    assert_eq!(line, u64::from(find(&pass_text, "UNITY_DEFINE_INSTANCED_PROP(float, _Cutoff)").0));

    // A macro: its `#define`, and what the active variant expands it to, fenced as HLSL.
    let expansion = hover(&mut client, find(&pass_text, "SAMPLE_TEXTURE2D(_BaseMap"));
    assert!(expansion.contains("#define SAMPLE_TEXTURE2D(texture, state, uv)"), "{expansion}");
    assert!(expansion.contains("to:\n```hlsl\n"), "{expansion}");

    // The outline of an HLSL include: its structs and functions.
    let symbols =
        client.request("textDocument/documentSymbol", json!({ "textDocument": { "uri": pass_uri } }));
    let names: Vec<&str> =
        symbols.as_array().expect("symbols").iter().map(|s| s["name"].as_str().expect("name")).collect();
    assert_eq!(names, ["UnityPerMaterial", "Attributes", "Varyings", "LitPassVertex", "LitPassFragment"]);

    // Completion: the library's HLSL files after `#include "`, keywords and macros after `#if`.
    let edited = pass_text.replace("#include \"Common.hlsl\"\n", "#include \"\n#if defined(\n#endif\n");
    client.change(&pass_uri, 2, &edited);
    let labels = |result: Value| -> Vec<String> {
        let items = result.as_array().cloned().unwrap_or_default();
        items.iter().map(|i| i["label"].as_str().expect("label").to_string()).collect()
    };
    let (line, _) = find(&edited, "#include \"\n");
    let includes = labels(client.request("textDocument/completion", at(&pass_uri, line, 10)));
    for name in ["Common.hlsl", "Lighting.hlsl", "LitPass.hlsl"] {
        assert!(includes.iter().any(|i| i == name), "{name}: {includes:?}");
    }
    let conditions = labels(client.request("textDocument/completion", at(&pass_uri, line + 1, 12)));
    for name in ["_CLIPPING", "_PREMULTIPLY_ALPHA", "CUSTOM_LIT_PASS_INCLUDED"] {
        assert!(conditions.iter().any(|c| c == name), "{name}: {conditions:?}");
    }
    client.shutdown();
}
