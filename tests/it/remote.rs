//! The remote cache (`remote_cache`, docs/scaling.md) against servers: nginx with WebDAV `PUT`
//! (Debian's package) where installed, and a minimal in-test server that speaks bazel-remote's
//! HTTP protocol and stages what a real server will not on demand (errors, slowness, refused
//! writes, a death mid-build, tampered objects). Builds run as the CLI runs, in a process of their
//! own with the environment the test gives.

use crate::support::{compiled, root, shipped};
use expect_test::expect_file;
use kiln::diagnostics::{has_errors, render_plain};
use kiln::project::{Request, build_project};
use kiln::source::SourceStore;
use std::collections::BTreeMap;
use std::io::{BufRead, BufReader, Read, Write};
use std::net::{TcpListener, TcpStream};
use std::path::{Path, PathBuf};
use std::process::{Command, Output};
use std::sync::atomic::{AtomicBool, AtomicUsize, Ordering};
use std::sync::{Arc, Mutex};
use std::time::{Duration, Instant};

/// What the in-test server does with requests.
#[derive(Debug, Clone, Copy, PartialEq)]
enum Behaviour {
    /// Stores and serves.
    Serve,
    /// Answers every request with this status.
    Status(u16),
    /// Answers after this long.
    Slow(Duration),
    /// Serves `GET`, answers `PUT` with 403 (a read-only token).
    ReadOnly,
    /// Serves this many requests, then closes every connection and stops listening.
    DieAfter(usize),
    /// Answers every request with a redirect to this port on the same machine.
    Redirect(u16),
    /// Answers every `GET` with 404 and takes every `PUT`, after this long (within the client's
    /// timeout).
    SlowMiss(Duration),
    /// Answers every request with 200 and an HTML page (a captive portal, a misconfigured proxy).
    Page,
    /// Answers every request with 200 and bytes without end (no length; closed when it is done).
    Endless,
}

#[derive(Default)]
struct ServerState {
    objects: Mutex<BTreeMap<String, Vec<u8>>>,
    /// Each request: method, path, `Authorization` header.
    requests: Mutex<Vec<(String, String, Option<String>)>>,
    served: AtomicUsize,
    dead: AtomicBool,
}

/// A minimal HTTP/1.1 server (keep-alive, `Content-Length` bodies) written for these tests: it
/// speaks bazel-remote's protocol, `GET`/`PUT` of any path under `/`, and stores in memory.
struct TestServer {
    port: u16,
    state: Arc<ServerState>,
    behaviour: Arc<Mutex<Behaviour>>,
}

impl TestServer {
    fn start(behaviour: Behaviour) -> TestServer {
        let listener = TcpListener::bind("127.0.0.1:0").expect("a loopback port");
        let port = listener.local_addr().expect("address").port();
        listener.set_nonblocking(true).expect("non-blocking");
        let state = Arc::new(ServerState::default());
        let behaviour = Arc::new(Mutex::new(behaviour));
        let (accept_state, accept_behaviour) = (state.clone(), behaviour.clone());
        std::thread::spawn(move || {
            while !accept_state.dead.load(Ordering::SeqCst) {
                match listener.accept() {
                    Ok((stream, _)) => {
                        let (state, behaviour) = (accept_state.clone(), accept_behaviour.clone());
                        std::thread::spawn(move || serve(stream, &state, &behaviour));
                    }
                    Err(_) => std::thread::sleep(Duration::from_millis(2)),
                }
            }
            // Dropping the listener: new connections are refused from here on.
        });
        TestServer { port, state, behaviour }
    }

    fn url(&self) -> String {
        format!("http://127.0.0.1:{}/kiln", self.port)
    }

    fn set(&self, behaviour: Behaviour) {
        *self.behaviour.lock().expect("lock") = behaviour;
    }

    fn requests(&self, method: &str) -> usize {
        self.state.requests.lock().expect("lock").iter().filter(|(m, ..)| m == method).count()
    }
}

fn serve(stream: TcpStream, state: &ServerState, behaviour: &Mutex<Behaviour>) {
    let _ = stream.set_nonblocking(false);
    let mut writer = stream.try_clone().expect("clone");
    let mut reader = BufReader::new(stream);
    loop {
        let mut line = String::new();
        if reader.read_line(&mut line).unwrap_or(0) == 0 || state.dead.load(Ordering::SeqCst) {
            return;
        }
        let mut parts = line.split_whitespace();
        let (method, path) = (parts.next().unwrap_or("").to_string(), parts.next().unwrap_or("").to_string());
        let (mut length, mut authorization) = (0usize, None);
        loop {
            let mut header = String::new();
            if reader.read_line(&mut header).unwrap_or(0) == 0 {
                return;
            }
            let header = header.trim_end();
            if header.is_empty() {
                break;
            }
            if let Some((name, value)) = header.split_once(':') {
                match name.to_ascii_lowercase().as_str() {
                    "content-length" => length = value.trim().parse().unwrap_or(0),
                    "authorization" => authorization = Some(value.trim().to_string()),
                    _ => {}
                }
            }
        }
        let mut body = vec![0; length];
        if reader.read_exact(&mut body).is_err() {
            return;
        }
        state.requests.lock().expect("lock").push((method.clone(), path.clone(), authorization));
        let behaviour = *behaviour.lock().expect("lock");
        let served = state.served.fetch_add(1, Ordering::SeqCst) + 1;
        let (status, answer) = match behaviour {
            Behaviour::DieAfter(n) if served > n => {
                state.dead.store(true, Ordering::SeqCst);
                return;
            }
            Behaviour::Redirect(port) => {
                let head = format!(
                    "HTTP/1.1 302 Found\r\nLocation: http://127.0.0.1:{port}{path}\r\nContent-Length: 0\r\n\r\n"
                );
                if writer.write_all(head.as_bytes()).is_err() {
                    return;
                }
                continue;
            }
            Behaviour::SlowMiss(delay) => {
                std::thread::sleep(delay);
                (if method == "PUT" { 201 } else { 404 }, Vec::new())
            }
            Behaviour::Page => (200, b"<html><body>Please sign in</body></html>".to_vec()),
            Behaviour::Endless => {
                let _ = writer.write_all(b"HTTP/1.1 200 OK\r\nConnection: close\r\n\r\n");
                let chunk = vec![b'x'; 1 << 16];
                // 1 GiB at most, until the client hangs up.
                for _ in 0..(1 << 14) {
                    if writer.write_all(&chunk).is_err() {
                        break;
                    }
                }
                return;
            }
            Behaviour::Status(status) => (status, Vec::new()),
            Behaviour::ReadOnly if method == "PUT" => (403, Vec::new()),
            Behaviour::Slow(delay) => {
                std::thread::sleep(delay);
                handle(state, &method, &path, body)
            }
            _ => handle(state, &method, &path, body),
        };
        let head = format!("HTTP/1.1 {status} X\r\nContent-Length: {}\r\n\r\n", answer.len());
        if writer.write_all(head.as_bytes()).and_then(|()| writer.write_all(&answer)).is_err() {
            return;
        }
    }
}

fn handle(state: &ServerState, method: &str, path: &str, body: Vec<u8>) -> (u16, Vec<u8>) {
    let mut objects = state.objects.lock().expect("lock");
    match method {
        "GET" => objects.get(path).map_or((404, Vec::new()), |found| (200, found.clone())),
        "PUT" => {
            objects.insert(path.to_string(), body);
            (201, Vec::new())
        }
        _ => (405, Vec::new()),
    }
}

/// `kiln build` of the example project into `output`, with a cache folder of its own (a machine)
/// and the remote cache `url`, plus `env`.
fn build(output: &Path, cache: &Path, url: &str, env: &[(&str, &str)]) -> Output {
    let mut command = Command::new(env!("CARGO_BIN_EXE_kiln"));
    command
        .args(["build", "fixtures/project", "--output"])
        .arg(output)
        .arg("--cache-dir")
        .arg(cache)
        .args(["--remote-cache", url])
        .current_dir(root())
        .env("NO_COLOR", "1")
        .env_remove("KILN_REMOTE_CACHE_MODE")
        .env_remove("KILN_REMOTE_CACHE_TOKEN")
        .env("KILN_REMOTE_CACHE_TIMEOUT", "0.5");
    for (name, value) in env {
        command.env(name, value);
    }
    command.output().expect("kiln runs")
}

fn stderr(output: &Output) -> String {
    String::from_utf8_lossy(&output.stderr).into_owned()
}

/// A build that succeeded; its diagnostics and summary.
fn succeeded(output: Output) -> String {
    let text = stderr(&output);
    assert_eq!(output.status.code(), Some(0), "{text}");
    text
}

/// Two machines: folders for each one's cache and output.
struct Machines {
    _dir: tempfile::TempDir,
    a: (PathBuf, PathBuf),
    b: (PathBuf, PathBuf),
}

fn machines() -> Machines {
    let dir = tempfile::tempdir().expect("temp dir");
    let folder = |name: &str| dir.path().join(name);
    Machines { a: (folder("a-out"), folder("a-cache")), b: (folder("b-out"), folder("b-cache")), _dir: dir }
}

/// A clean build without any cache, for what every other build must ship.
fn clean_build(dir: &Path) -> BTreeMap<PathBuf, Vec<u8>> {
    let output = dir.join("clean");
    let run =
        crate::support::kiln(&["build", "fixtures/project", "--output", output.to_str().expect("utf-8")]);
    assert!(run.status.success(), "{}", stderr(&run));
    shipped(&output)
}

#[test]
fn a_second_machine_compiles_nothing_that_the_first_published_and_ships_the_same_bytes() {
    let server = TestServer::start(Behaviour::Serve);
    let m = machines();
    let first = succeeded(build(&m.a.0, &m.a.1, &server.url(), &[]));
    let made = compiled(&first);
    assert!(made > 10, "{first}");
    assert!(server.requests("PUT") >= made, "every compiled module published: {}", server.requests("PUT"));
    let second = succeeded(build(&m.b.0, &m.b.1, &server.url(), &[]));
    assert_eq!(compiled(&second), 0, "{second}");
    assert!(!second.contains("warning"), "{second}");
    // What the server holds is what the second machine fetched (each object and entry once).
    let stored: usize = server.state.objects.lock().expect("lock").values().map(Vec::len).sum();
    assert!(
        second.contains(&format!(", {stored} bytes fetched from the remote cache and 0 sent")),
        "{second}"
    );
    assert_eq!(shipped(&m.b.0), shipped(&m.a.0), "byte-identical outputs");
    assert_eq!(shipped(&m.a.0), clean_build(m._dir.path()), "and what a build without caches ships");
    // The second machine kept what it fetched in its own cache: a clean build there, into a
    // new output folder, fetches nothing and compiles nothing.
    let gets = server.requests("GET");
    let again = succeeded(build(&m._dir.path().join("b-out-again"), &m.b.1, &server.url(), &[]));
    assert_eq!(compiled(&again), 0, "{again}");
    assert_eq!(server.requests("GET"), gets, "a clean build asked the server again:\n{again}");
    assert_eq!(shipped(&m._dir.path().join("b-out-again")), shipped(&m.a.0));
}

#[test]
fn tampered_and_forged_objects_are_misses_and_recompiled() {
    let server = TestServer::start(Behaviour::Serve);
    let m = machines();
    let made = compiled(&succeeded(build(&m.a.0, &m.a.1, &server.url(), &[])));
    {
        let mut objects = server.state.objects.lock().expect("lock");
        let cas: Vec<String> = objects.keys().filter(|k| k.contains("/cas/")).cloned().collect();
        let entries: Vec<String> = objects.keys().filter(|k| k.contains("/ac/")).cloned().collect();
        assert!(
            cas.len() >= 3 && entries.len() >= cas.len(),
            "{} objects, {} entries",
            cas.len(),
            entries.len()
        );
        // A flipped byte in one object (its SHA-256 no longer matches its name).
        objects.get_mut(&cas[0]).expect("object")[40] ^= 1;
        // Another object renamed to a third's SHA-256 (the name checked only by content).
        let other = objects[&cas[1]].clone();
        objects.insert(cas[2].clone(), other);
        // Every module entry pointed at one valid object: its SHA-256 matches, its key does not.
        // (A module's entry is the 64 hex digits of its object; a pass's layouts are JSON.)
        let modules: Vec<String> = entries.into_iter().filter(|e| objects[e].len() == 64).collect();
        assert!(modules.len() >= 3);
        let named = objects[&modules[0]].clone();
        for entry in &modules {
            objects.insert(entry.clone(), named.clone());
        }
    }
    let second = succeeded(build(&m.b.0, &m.b.1, &server.url(), &[]));
    // At most the one module whose entry still names its own object is taken.
    assert!(compiled(&second) >= made - 1, "{second}");
    assert_eq!(shipped(&m.b.0), shipped(&m.a.0), "nothing tampered ships");
}

#[test]
fn a_server_that_fails_is_slow_or_gone_costs_one_warning_and_never_the_build() {
    let dir = tempfile::tempdir().expect("temp dir");
    let clean = clean_build(dir.path());
    // Nothing listening: a port bound and released.
    let gone = TcpListener::bind("127.0.0.1:0").expect("port").local_addr().expect("address").port();
    let failing = TestServer::start(Behaviour::Status(500));
    let slow = TestServer::start(Behaviour::Slow(Duration::from_secs(5)));
    let dying = TestServer::start(Behaviour::DieAfter(4));
    for (name, url) in [
        ("gone", format!("http://127.0.0.1:{gone}/kiln")),
        ("failing", failing.url()),
        ("slow", slow.url()),
        ("dying", dying.url()),
    ] {
        let (output, cache) =
            (dir.path().join(format!("{name}-out")), dir.path().join(format!("{name}-cache")));
        let started = Instant::now();
        let text = succeeded(build(&output, &cache, &url, &[]));
        assert!(started.elapsed() < Duration::from_secs(30), "{name}: {:?}, not a hang", started.elapsed());
        assert_eq!(text.matches("warning[K0620]").count(), 1, "{name}: one warning\n{text}");
        assert_eq!(shipped(&output), clean, "{name}: what a build without caches ships");
    }
    // The breaker: after three failures in a row, the failing server is asked nothing more.
    let asked = failing.state.requests.lock().expect("lock").len();
    assert!(asked <= 3 + 16, "{asked} requests to a server that answers 500");
}

#[test]
fn read_mode_and_a_read_only_token_publish_nothing() {
    let m = machines();
    let reader = TestServer::start(Behaviour::Serve);
    let text = succeeded(build(&m.a.0, &m.a.1, &reader.url(), &[("KILN_REMOTE_CACHE_MODE", "read")]));
    assert_eq!(reader.requests("PUT"), 0, "{text}");
    assert!(reader.requests("GET") > 0);
    assert!(!text.contains("warning"), "{text}");
    let refusing = TestServer::start(Behaviour::ReadOnly);
    let text = succeeded(build(&m.b.0, &m.b.1, &refusing.url(), &[]));
    assert_eq!(text.matches("warning[K0620]").count(), 1, "{text}");
    assert!(text.contains("refused a write (HTTP 403)"), "{text}");
    // Writes end at the first refusal: at most the one in flight on each upload thread (8).
    assert!((1..=8).contains(&refusing.requests("PUT")), "{} PUTs", refusing.requests("PUT"));
    assert!(refusing.state.objects.lock().expect("lock").is_empty());
    // `off` asks nothing.
    let quiet = TestServer::start(Behaviour::Serve);
    let off = m.a.0.with_file_name("off-out");
    succeeded(build(&off, &m.a.1, &quiet.url(), &[("KILN_REMOTE_CACHE_MODE", "off")]));
    assert_eq!(quiet.state.requests.lock().expect("lock").len(), 0);
}

#[test]
fn a_token_is_sent_and_written_nowhere() {
    let secret = "s3cret-token-7f1c";
    let server = TestServer::start(Behaviour::Serve);
    let m = machines();
    let text = succeeded(build(&m.a.0, &m.a.1, &server.url(), &[("KILN_REMOTE_CACHE_TOKEN", secret)]));
    let requests = server.state.requests.lock().expect("lock").clone();
    assert!(!requests.is_empty());
    let bearer = format!("Bearer {secret}");
    assert!(requests.iter().all(|(.., auth)| auth.as_deref() == Some(bearer.as_str())), "{requests:?}");
    assert!(!text.contains(secret));
    for (path, bytes) in crate::support::tree(&m.a.0).into_iter().chain(crate::support::tree(&m.a.1)) {
        let text = String::from_utf8_lossy(&bytes);
        assert!(!text.contains(secret), "{} holds the token", path.display());
    }
    // A server that fails says why without the token either.
    server.set(Behaviour::Status(401));
    let text = succeeded(build(&m.b.0, &m.b.1, &server.url(), &[("KILN_REMOTE_CACHE_TOKEN", secret)]));
    assert!(text.contains("warning[K0620]") && !text.contains(secret), "{text}");
}

/// A project's build through the library, with `mode`; its diagnostics rendered.
fn diagnostics_of(project: &str, mode: &Request) -> (bool, String) {
    let mut store = SourceStore::new();
    let (result, mut diagnostics) =
        build_project(&mut store, &[root().join(project)], mode, &|_, _| {}).expect("exists");
    diagnostics.extend(result.diagnostics);
    let shown = render_plain(&store, &diagnostics).replace(&format!("{}/", root().display()), "");
    (has_errors(&diagnostics), shown)
}

#[test]
fn settings_kiln_cannot_use_are_errors_where_they_are_written() {
    let out = tempfile::tempdir().expect("temp dir");
    let mode = Request { output: Some(out.path().to_path_buf()), ..Request::default() };
    let (failed, shown) = diagnostics_of("fixtures/bad/remote_cache", &mode);
    assert!(failed);
    expect_file![root().join("fixtures/bad/remote_cache/kiln.stderr")].assert_eq(&shown);
    let run =
        crate::support::kiln(&["check", "fixtures/ubershader", "--remote-cache", "http://user:pw@host/kiln"]);
    assert_eq!(run.status.code(), Some(1));
    assert!(stderr(&run).contains("credentials belong in KILN_REMOTE_CACHE_TOKEN"), "{}", stderr(&run));
    assert!(!stderr(&run).contains("pw@"), "the URL with its password is not echoed");
    let run = crate::support::kiln(&["check", "fixtures/ubershader", "--remote-cache-mode", "sometimes"]);
    assert_eq!(run.status.code(), Some(2), "clap refuses it");
}

#[test]
fn a_server_nothing_listens_on_is_one_warning() {
    let out = tempfile::tempdir().expect("temp dir");
    // Port 9 (discard): nothing listens there on a test machine.
    let mode = Request {
        output: Some(out.path().to_path_buf()),
        remote_cache: Some("http://127.0.0.1:9/kiln".to_string()),
        ..Request::default()
    };
    let (failed, shown) = diagnostics_of("fixtures/ubershader", &mode);
    assert!(!failed, "{shown}");
    expect_file![root().join("tests/golden/remote/unavailable.stderr")].assert_eq(&shown);
}

/// nginx (Debian's package) with WebDAV `PUT`, on a loopback port with a temporary root.
/// The password of the CI's user in the test's nginx (docs/scaling.md's `limit_except`).
const NGINX_PASSWORD: &str = "s3cret-of-ci";

struct Nginx {
    child: std::process::Child,
    port: u16,
    _dir: tempfile::TempDir,
}

impl Nginx {
    fn start() -> Nginx {
        let dir = tempfile::tempdir().expect("temp dir");
        let port = TcpListener::bind("127.0.0.1:0").expect("port").local_addr().expect("address").port();
        let root = dir.path().join("root");
        std::fs::create_dir_all(root.join("kiln")).expect("mkdir");
        // docs/scaling.md's server block as the page gives it, on a loopback port, its root and
        // password file here; one process, as whoever runs the test: no worker to drop
        // privileges to.
        let page =
            std::fs::read_to_string(crate::support::root().join("docs/scaling.md")).expect("scaling.md");
        let block =
            page.split("```nginx\n").nth(1).and_then(|b| b.split("```").next()).expect("an nginx block");
        let server = block
            .replace("listen 8080;", &format!("listen 127.0.0.1:{port};"))
            .replace("root /srv/kiln-cache;", &format!("root {};", root.display()))
            .replace("/etc/nginx/kiln.htpasswd", &dir.path().join("kiln.htpasswd").display().to_string());
        assert!(server.contains(&format!(":{port};")) && !server.contains("root /srv"), "{server}");
        std::fs::write(dir.path().join("kiln.htpasswd"), format!("ci:{{PLAIN}}{NGINX_PASSWORD}\n"))
            .expect("htpasswd");
        let config = format!(
            "daemon off;\nmaster_process off;\npid {dir}/nginx.pid;\nerror_log {dir}/error.log;\n\
             events {{}}\nhttp {{\n  access_log off;\n  client_body_temp_path {dir}/body;\n  proxy_temp_path {dir}/proxy;\n\
             fastcgi_temp_path {dir}/fastcgi;\n  uwsgi_temp_path {dir}/uwsgi;\n  scgi_temp_path {dir}/scgi;\n\
             {server}}}\n",
            dir = dir.path().display(),
        );
        let conf = dir.path().join("nginx.conf");
        std::fs::write(&conf, config).expect("config");
        let child = Command::new("nginx")
            .args(["-p", dir.path().to_str().expect("utf-8"), "-c", conf.to_str().expect("utf-8")])
            .arg("-e")
            .arg(dir.path().join("error.log"))
            .stderr(std::process::Stdio::null())
            .spawn()
            .expect("nginx starts");
        let started = Instant::now();
        while TcpStream::connect(("127.0.0.1", port)).is_err() {
            assert!(started.elapsed() < Duration::from_secs(10), "nginx listens");
            std::thread::sleep(Duration::from_millis(20));
        }
        Nginx { child, port, _dir: dir }
    }
}

impl Drop for Nginx {
    fn drop(&mut self) {
        let _ = self.child.kill();
        let _ = self.child.wait();
    }
}

#[test]
fn machines_share_modules_through_nginx_with_webdav() {
    // `nginx -v`, not `--version`: its own flag.
    let found = Command::new("nginx").arg("-v").output().is_ok_and(|o| o.status.success());
    if !found {
        assert!(std::env::var_os("KILN_REQUIRE_TOOLS").is_none(), "nginx is required but missing");
        crate::support::skipped(
            "machines_share_modules_through_nginx_with_webdav: nginx missing (apt-get install nginx)",
        );
        return;
    }
    let nginx = Nginx::start();
    let url = format!("http://127.0.0.1:{}/kiln", nginx.port);
    let m = machines();
    // As the page sets it up: writes with the CI's password, reads with none.
    let ci = [("KILN_REMOTE_CACHE_USER", "ci"), ("KILN_REMOTE_CACHE_PASSWORD", NGINX_PASSWORD)];
    let first = succeeded(build(&m.a.0, &m.a.1, &url, &ci));
    assert!(compiled(&first) > 10 && !first.contains("warning"), "{first}");
    let second = succeeded(build(&m.b.0, &m.b.1, &url, &[]));
    assert_eq!(compiled(&second), 0, "{second}");
    assert_eq!(shipped(&m.b.0), shipped(&m.a.0));
    // nginx killed: the next machine builds alone, with one warning.
    drop(nginx);
    let c = m.b.0.with_file_name("c-out");
    let third = succeeded(build(&c, &m.b.1.with_file_name("c-cache"), &url, &[]));
    assert_eq!(third.matches("warning[K0620]").count(), 1, "{third}");
    assert_eq!(shipped(&c), shipped(&m.a.0));
}

/// A copy of the example project whose `kiln.toml` names the remote cache `url`.
fn project_naming(dir: &Path, url: &str) -> PathBuf {
    let project = crate::support::example_project_copy(dir);
    let config = project.join("kiln.toml");
    let mut text = std::fs::read_to_string(&config).unwrap_or_default();
    text.insert_str(0, &format!("remote_cache = \"{url}\"\n"));
    std::fs::write(&config, text).expect("write");
    project
}

/// `kiln build` of `project` with the environment `env` and no remote cache on the command line.
fn build_named_by_project(project: &Path, env: &[(&str, &str)]) -> Output {
    let mut command = Command::new(env!("CARGO_BIN_EXE_kiln"));
    command
        .args(["build", "."])
        .current_dir(project)
        .env("NO_COLOR", "1")
        .env_remove("KILN_REMOTE_CACHE")
        .env_remove("KILN_REMOTE_CACHE_HOST")
        .env_remove("KILN_REMOTE_CACHE_TOKEN")
        .env_remove("KILN_REMOTE_CACHE_USER")
        .env("KILN_REMOTE_CACHE_TIMEOUT", "0.5");
    for (name, value) in env {
        command.env(name, value);
    }
    command.output().expect("kiln runs")
}

/// The rendered diagnostic with `code` from a command's error output (up to its blank line).
fn diagnostic_with(text: &str, code: &str) -> String {
    let start = text.find(&format!("warning[{code}]")).unwrap_or_else(|| panic!("no {code} in {text}"));
    let end = text[start..].find("\n\n").map_or(text.len(), |n| start + n + 1);
    text[start..end].to_string()
}

#[test]
fn a_url_from_kiln_toml_gets_no_credentials_unless_the_environment_pins_its_host() {
    let secret = "s3cret-from-ci";
    let server = TestServer::start(Behaviour::Serve);
    let dir = tempfile::tempdir().expect("temp dir");
    let project = project_naming(dir.path(), &server.url());
    let text = succeeded(build_named_by_project(&project, &[("KILN_REMOTE_CACHE_TOKEN", secret)]));
    let requests = server.state.requests.lock().expect("lock").clone();
    assert!(!requests.is_empty(), "the cache is still used, without credentials");
    assert!(requests.iter().all(|(.., auth)| auth.is_none()), "{requests:?}");
    assert!(!text.contains(secret), "{text}");
    let shown = diagnostic_with(&text, "K0621").replace(&server.port.to_string(), "PORT");
    expect_file![root().join("tests/golden/remote/withheld.stderr")].assert_eq(&shown);
    // Pinned by the environment, the same URL gets them.
    server.state.requests.lock().expect("lock").clear();
    std::fs::remove_dir_all(project.join("build")).ok();
    let host = format!("127.0.0.1:{}", server.port);
    let text = succeeded(build_named_by_project(
        &project,
        &[("KILN_REMOTE_CACHE_TOKEN", secret), ("KILN_REMOTE_CACHE_HOST", &host)],
    ));
    assert!(!text.contains("K0621"), "{text}");
    let bearer = format!("Bearer {secret}");
    let requests = server.state.requests.lock().expect("lock").clone();
    assert!(!requests.is_empty() && requests.iter().all(|(.., a)| a.as_deref() == Some(bearer.as_str())));
}

#[test]
fn a_redirect_is_never_followed_and_takes_the_credentials_nowhere() {
    let elsewhere = TestServer::start(Behaviour::Serve);
    let redirecting = TestServer::start(Behaviour::Redirect(elsewhere.port));
    let m = machines();
    let text = succeeded(build(&m.a.0, &m.a.1, &redirecting.url(), &[("KILN_REMOTE_CACHE_TOKEN", "s3cret")]));
    assert_eq!(elsewhere.state.requests.lock().expect("lock").len(), 0, "a redirect was followed");
    assert_eq!(text.matches("warning[K0620]").count(), 1, "{text}");
    assert!(text.contains("redirect"), "{text}");
}

#[test]
fn a_server_that_misses_slowly_pages_or_never_ends_costs_the_build_its_budget_at_most() {
    let dir = tempfile::tempdir().expect("temp dir");
    let clean = clean_build(dir.path());
    let slow = TestServer::start(Behaviour::SlowMiss(Duration::from_millis(400)));
    let page = TestServer::start(Behaviour::Page);
    let endless = TestServer::start(Behaviour::Endless);
    for (name, server, expected) in [
        ("slow", &slow, "budget"),
        ("page", &page, "failed verification"),
        ("endless", &endless, "too large"),
    ] {
        let (output, cache) =
            (dir.path().join(format!("{name}-out")), dir.path().join(format!("{name}-cache")));
        let started = Instant::now();
        // Each request within its 5 s; together within 2 s of the build's time.
        let env = [("KILN_REMOTE_CACHE_TIMEOUT", "5"), ("KILN_REMOTE_CACHE_BUDGET", "2")];
        let text = succeeded(build(&output, &cache, &server.url(), &env));
        assert!(started.elapsed() < Duration::from_secs(30), "{name}: {:?}", started.elapsed());
        assert_eq!(text.matches("warning[K0620]").count(), 1, "{name}: one warning\n{text}");
        assert!(text.contains(expected), "{name}: {text}");
        assert_eq!(shipped(&output), clean, "{name}: what a build without caches ships");
        // Asked no more once the budget is spent or three answers failed (what was in flight on
        // the build's threads and the upload threads aside).
        let asked = server.state.requests.lock().expect("lock").len();
        assert!(asked <= 5 + 3 + 16, "{name}: {asked} requests");
    }
}
