//! The team's cache on an HTTP server (`remote_cache`): stage modules as content-addressed
//! objects (`PUT`/`GET /cas/<sha256>`, the object's bytes as the shared cache stores them) and
//! entries that name them (`/ac/<sha256 of the key>`), as bazel-remote serves them and as any
//! server that takes `PUT` (nginx's WebDAV) does; a pass's parsed resources as one entry each.
//! Everything fetched is verified before use: the object against its SHA-256, then against its
//! key, compiler and module hashes (the shared cache's seal); what fails is a miss.
//!
//! A server that is down, slow or refusing must never fail or stall a build: each request has a
//! timeout, three failures in a row open a breaker that ends the remote cache for the build, a
//! refused write ends writes, and each is one warning (K0620). Credentials come from the
//! environment and are sent, never written anywhere else (docs/scaling.md).

use super::cache::{ModuleBytes, unsealed};
pub use super::credentials::{Credentials, UrlSource, credentials_for};
use super::shared::{joined_layouts, layouts_key, object_bytes, parse_object};
use crate::compile::bind::Declared;
use crate::diagnostics::Diagnostic;
use crate::manifest::PerBackend;
use crate::reflect::StageReflection;
use sha2::{Digest as _, Sha256};
use std::collections::BTreeMap;
use std::sync::atomic::{AtomicBool, AtomicU64, AtomicUsize, Ordering};
use std::sync::{Arc, Mutex};
use std::time::Duration;

/// What a build may do with the remote cache (`--remote-cache-mode`).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, Default, serde::Deserialize)]
#[serde(rename_all = "lowercase")]
pub enum RemoteMode {
    /// Fetch only (a CI job that must not publish).
    Read,
    /// Fetch, and publish what the build compiled.
    #[default]
    Write,
    /// Neither.
    Off,
}

impl RemoteMode {
    /// Its name on the command line and in kiln.toml.
    pub fn name(self) -> &'static str {
        match self {
            RemoteMode::Read => "read",
            RemoteMode::Write => "write",
            RemoteMode::Off => "off",
        }
    }

    /// The mode a name gives.
    pub fn parse(name: &str) -> Option<RemoteMode> {
        [RemoteMode::Read, RemoteMode::Write, RemoteMode::Off].into_iter().find(|m| m.name() == name)
    }
}

/// Where the remote cache is and what a build may do with it: decided once, before the build.
#[derive(Debug, Clone, PartialEq, Eq, Hash)]
pub struct RemoteConfig {
    /// `http://host:port/prefix` or `https://...`, without a trailing `/`.
    pub url: String,
    /// Read, write or off.
    pub mode: RemoteMode,
    /// How long each step of a request (connecting, sending, waiting for the answer, reading
    /// it) may take.
    pub timeout: Duration,
    /// How long the build's requests may take together, whatever each answers: past it, the
    /// build stops asking (a server that answers every request slowly, but within its timeout).
    pub budget: Duration,
    /// The `Authorization` header sent with every request, where the user's settings allow one
    /// for this URL ([`credentials_for`]).
    pub credentials: Option<Credentials>,
}

/// Why a remote cache URL is refused.
pub fn check_url(url: &str) -> Result<String, String> {
    let rest = url.strip_prefix("http://").or_else(|| url.strip_prefix("https://"));
    let Some(rest) = rest else { return Err("it must start with `http://` or `https://`".into()) };
    if rest.is_empty() || rest.starts_with('/') {
        return Err("it names no host".into());
    }
    if rest.split('/').next().is_some_and(|host| host.contains('@')) {
        return Err(
            "credentials belong in KILN_REMOTE_CACHE_TOKEN or KILN_REMOTE_CACHE_USER/_PASSWORD, not the URL"
                .into(),
        );
    }
    if url.chars().any(|c| c.is_whitespace() || c.is_control()) {
        return Err("it has blanks or control characters".into());
    }
    // What follows `?` or `#` would be printed in warnings (tokens travel there) and would end
    // up before every object's path.
    if url.contains(['?', '#']) {
        return Err("it has a query string or a fragment; give the server's prefix alone".into());
    }
    Ok(url.trim_end_matches('/').to_string())
}

/// Requests that failed in a row before the breaker opens.
const BREAKER: usize = 3;

/// The largest object fetched (a module's every back end, with its reflection): an answer is read
/// into memory no further than this (or than a module entry's or layouts' own bound).
const MAX_OBJECT: u64 = 64 << 20;

/// The largest module entry (64 hexadecimal digits, with room for a line break).
const MAX_ENTRY: u64 = 1 << 10;

/// The largest entry of a pass's parsed resources (a pass of thousands of texts is tens of KB).
const MAX_LAYOUTS: u64 = 4 << 20;

/// Uploads in flight at most, and the threads that make them: a build's workers hand what they
/// compiled over and go on compiling (the queue's bound is its memory's).
const UPLOAD_QUEUE: usize = 64;
const UPLOADERS: usize = 8;

/// A build's use of the remote cache: fetches on the build's threads, uploads on threads of its
/// own (started at the first, joined by [`RemoteCache::finish`]).
pub struct RemoteCache {
    connection: Arc<Connection>,
    uploads: Mutex<Option<Uploads>>,
}

/// The upload threads and their queue.
struct Uploads {
    queue: std::sync::mpsc::SyncSender<Upload>,
    threads: Vec<std::thread::JoinHandle<()>>,
}

/// What an upload thread puts: an object and the entry that names it, or an entry alone.
enum Upload {
    Object { cas: String, object: Vec<u8>, entry: String },
    Entry { path: String, bytes: Vec<u8> },
}

/// The HTTP side: one agent (keep-alive), the credentials, and what went wrong so far.
struct Connection {
    config: RemoteConfig,
    agent: ureq::Agent,
    failures_in_a_row: AtomicUsize,
    /// Answers that failed verification, in all (a server that answers every path with a page
    /// answers each request well).
    unverified: AtomicUsize,
    /// Nanoseconds the build's requests took, summed over threads (against the budget).
    waited: AtomicU64,
    broken: AtomicBool,
    writes_refused: AtomicBool,
    /// The first problem of each kind, reported once after the build.
    problems: Mutex<Vec<String>>,
    received: AtomicU64,
    sent: AtomicU64,
}

/// How a request went.
enum Answer {
    Found(Vec<u8>),
    Missing,
    Failed(String),
}

impl RemoteCache {
    /// The remote cache for one build, with the credentials its configuration allows.
    pub fn new(config: RemoteConfig) -> RemoteCache {
        RemoteCache { connection: Arc::new(Connection::new(config)), uploads: Mutex::new(None) }
    }

    /// A stage module stored under `key` by `compiler`, verified, or `None`.
    pub fn fetch_object(
        &self,
        key: &str,
        compiler: &str,
    ) -> Option<(PerBackend<Option<ModuleBytes>>, StageReflection)> {
        let connection = &self.connection;
        if !connection.usable() {
            return None;
        }
        let Answer::Found(entry) = connection.get(&entry_path("module", key), MAX_ENTRY) else { return None };
        let cas = std::str::from_utf8(&entry).ok().map(str::trim).filter(|cas| is_sha256(cas));
        let Some(cas) = cas else {
            // Found, but not an entry (a server that answers every path with a page).
            connection.unverified("an answer was not a cache entry");
            return None;
        };
        let Answer::Found(object) = connection.get(&format!("cas/{cas}"), MAX_OBJECT) else { return None };
        // Damaged on the way or on the server, or another object: a miss, never used, and
        // counted against the server.
        let parsed = (sha256(&object) == cas).then(|| parse_object(&object, key, Some(compiler))).flatten();
        if parsed.is_none() {
            connection.unverified("an object failed verification");
        }
        parsed
    }

    /// Publishes a module this build compiled, in the background: its object, then the entry
    /// that names it.
    pub fn publish_object(
        &self,
        key: &str,
        compiler: &str,
        modules: &PerBackend<Option<ModuleBytes>>,
        reflection: &StageReflection,
    ) {
        if !self.connection.writable() {
            return;
        }
        let Ok(object) = object_bytes(key, compiler, modules, reflection) else { return };
        self.upload(Upload::Object { cas: sha256(&object), object, entry: entry_path("module", key) });
    }

    /// A pass's parsed resources, by stage text (empty when there are none or they are not
    /// what was sealed under the pass).
    pub fn read_layouts(&self, pass: &str) -> BTreeMap<String, Vec<Declared>> {
        if !self.connection.usable() {
            return BTreeMap::new();
        }
        let key = layouts_key(pass);
        let Answer::Found(bytes) = self.connection.get(&entry_path("layouts", &key), MAX_LAYOUTS) else {
            return BTreeMap::new();
        };
        // A broken seal counts against the server; an entry of another kiln's form (the key
        // names no version) is only a miss.
        let Some(json) = unsealed(&key, &bytes) else {
            self.connection.unverified("an entry failed verification");
            return BTreeMap::new();
        };
        serde_json::from_slice(json).unwrap_or_default()
    }

    /// Publishes a pass's parsed resources, joined with what the server has for the pass (two
    /// builds publishing at once may lose each other's additions: a miss later, as in the
    /// shared cache).
    pub fn publish_layouts(&self, pass: &str, layouts: &BTreeMap<String, Vec<Declared>>) {
        if !self.connection.writable() {
            return;
        }
        if let Some(bytes) = joined_layouts(pass, self.read_layouts(pass), layouts) {
            self.upload(Upload::Entry { path: entry_path("layouts", &layouts_key(pass)), bytes });
        }
    }

    /// Queues an upload, starting the upload threads the first time; waits while the queue is
    /// full.
    fn upload(&self, upload: Upload) {
        // The lock is not held while waiting for room: other workers queue too.
        let queue = {
            let mut uploads = self.uploads.lock().unwrap_or_else(std::sync::PoisonError::into_inner);
            let uploads = uploads.get_or_insert_with(|| {
                let (queue, receiver) = std::sync::mpsc::sync_channel::<Upload>(UPLOAD_QUEUE);
                let receiver = Arc::new(Mutex::new(receiver));
                let threads = (0..UPLOADERS)
                    .filter_map(|i| {
                        let (connection, receiver) = (self.connection.clone(), receiver.clone());
                        let name = format!("kiln upload {i}");
                        std::thread::Builder::new()
                            .name(name)
                            .spawn(move || connection.uploads(&receiver))
                            .ok()
                    })
                    .collect();
                Uploads { queue, threads }
            });
            uploads.queue.clone()
        };
        let _ = queue.send(upload);
    }

    /// Waits for the uploads queued (each within its request's time limit): at the end of the
    /// build, before it reports.
    pub fn finish(&self) {
        let uploads = self.uploads.lock().unwrap_or_else(std::sync::PoisonError::into_inner).take();
        if let Some(Uploads { queue, threads }) = uploads {
            drop(queue);
            for thread in threads {
                let _ = thread.join();
            }
        }
    }

    /// Bytes received from the server and sent to it.
    pub fn bytes(&self) -> [u64; 2] {
        [self.connection.received.load(Ordering::Relaxed), self.connection.sent.load(Ordering::Relaxed)]
    }

    /// The build's one warning about the server, if anything went wrong (after [`finish`]).
    ///
    /// [`finish`]: RemoteCache::finish
    pub fn warning(&self) -> Option<Diagnostic> {
        self.connection.warning()
    }
}

impl Connection {
    fn new(config: RemoteConfig) -> Connection {
        // A limit per step, not one for the whole call: with a global limit ureq resolves the
        // host on a thread of its own for every request, pooled connection or not (ureq 3.5).
        let limit = Some(config.timeout);
        let agent_config = ureq::Agent::config_builder()
            .timeout_connect(limit)
            .timeout_send_request(limit)
            .timeout_send_body(limit)
            .timeout_recv_response(limit)
            .timeout_recv_body(limit)
            .http_status_as_error(false)
            // A redirect could lead the credentials to another host: none is followed.
            .max_redirects(0)
            .max_idle_connections_per_host(64)
            .build();
        Connection {
            config,
            agent: ureq::Agent::new_with_config(agent_config),
            failures_in_a_row: AtomicUsize::new(0),
            unverified: AtomicUsize::new(0),
            waited: AtomicU64::new(0),
            broken: AtomicBool::new(false),
            writes_refused: AtomicBool::new(false),
            problems: Mutex::new(Vec::new()),
            received: AtomicU64::new(0),
            sent: AtomicU64::new(0),
        }
    }

    fn usable(&self) -> bool {
        self.config.mode != RemoteMode::Off && !self.broken.load(Ordering::Relaxed)
    }

    fn writable(&self) -> bool {
        self.config.mode == RemoteMode::Write && self.usable() && !self.writes_refused.load(Ordering::Relaxed)
    }

    fn problem(&self, problem: String) {
        let mut problems = self.problems.lock().unwrap_or_else(std::sync::PoisonError::into_inner);
        problems.push(problem);
    }

    /// Counts a failure; the third in a row opens the breaker.
    fn failed(&self, reason: String) {
        if self.failures_in_a_row.fetch_add(1, Ordering::Relaxed) + 1 >= BREAKER
            && !self.broken.swap(true, Ordering::Relaxed)
        {
            self.problem(format!(
                "it failed {BREAKER} times in a row (last: {reason}); this build stopped using it"
            ));
        }
    }

    /// Counts an answer that failed verification; the third opens the breaker.
    fn unverified(&self, what: &str) {
        if self.unverified.fetch_add(1, Ordering::Relaxed) + 1 >= BREAKER
            && !self.broken.swap(true, Ordering::Relaxed)
        {
            self.problem(format!(
                "{BREAKER} of its answers failed verification (last: {what}); this build stopped using it"
            ));
        }
    }

    /// Adds a request's time to the build's; past the budget, the build stops asking.
    fn waited(&self, started: std::time::Instant) {
        let took = u64::try_from(started.elapsed().as_nanos()).unwrap_or(u64::MAX);
        let waited = self.waited.fetch_add(took, Ordering::Relaxed).saturating_add(took);
        if waited > u64::try_from(self.config.budget.as_nanos()).unwrap_or(u64::MAX)
            && !self.broken.swap(true, Ordering::Relaxed)
        {
            self.problem(format!(
                "its answers took more than the build's budget of {:.0} s (KILN_REMOTE_CACHE_BUDGET); this build stopped using it",
                self.config.budget.as_secs_f64()
            ));
        }
    }

    /// `path`'s object, read into memory no further than `limit` bytes.
    fn get(&self, path: &str, limit: u64) -> Answer {
        let url = format!("{}/{path}", self.config.url);
        let mut request = self.agent.get(&url);
        if let Some(credentials) = &self.config.credentials {
            request = request.header("Authorization", credentials.header());
        }
        let started = std::time::Instant::now();
        let answer = match request.call() {
            Ok(mut response) => match response.status().as_u16() {
                200 => match read_at_most(&mut response, limit) {
                    Ok(bytes) => Answer::Found(bytes),
                    Err(why) => Answer::Failed(why),
                },
                404 => {
                    drain(&mut response);
                    Answer::Missing
                }
                status => {
                    drain(&mut response);
                    Answer::Failed(status_reason(status, "GET"))
                }
            },
            Err(error) => Answer::Failed(reason(&error)),
        };
        self.waited(started);
        match &answer {
            Answer::Found(bytes) => {
                self.received.fetch_add(bytes.len() as u64, Ordering::Relaxed);
                self.failures_in_a_row.store(0, Ordering::Relaxed);
            }
            Answer::Missing => self.failures_in_a_row.store(0, Ordering::Relaxed),
            Answer::Failed(reason) => self.failed(reason.clone()),
        }
        answer
    }

    /// Stores `bytes` at `path`; false when it did not.
    fn put(&self, path: &str, bytes: &[u8]) -> bool {
        let url = format!("{}/{path}", self.config.url);
        let mut request = self.agent.put(&url);
        if let Some(credentials) = &self.config.credentials {
            request = request.header("Authorization", credentials.header());
        }
        let started = std::time::Instant::now();
        let sent = request.send(bytes).map(|mut response| {
            drain(&mut response);
            response
        });
        self.waited(started);
        match sent {
            Ok(response) if response.status().is_success() => {
                self.sent.fetch_add(bytes.len() as u64, Ordering::Relaxed);
                self.failures_in_a_row.store(0, Ordering::Relaxed);
                true
            }
            Ok(response) if matches!(response.status().as_u16(), 401 | 403 | 405) => {
                if !self.writes_refused.swap(true, Ordering::Relaxed) {
                    let status = response.status().as_u16();
                    self.problem(format!(
                        "it refused a write (HTTP {status}); this build published nothing more"
                    ));
                }
                false
            }
            Ok(response) => {
                self.failed(status_reason(response.status().as_u16(), "PUT"));
                false
            }
            Err(error) => {
                self.failed(reason(&error));
                false
            }
        }
    }

    /// An upload thread: puts what the queue gives until it is closed (after the breaker opens
    /// or writes are refused, what is left is dropped unsent).
    fn uploads(&self, receiver: &Mutex<std::sync::mpsc::Receiver<Upload>>) {
        loop {
            let next = receiver.lock().unwrap_or_else(std::sync::PoisonError::into_inner).recv();
            let Ok(upload) = next else { return };
            if !self.writable() {
                continue;
            }
            match upload {
                Upload::Object { cas, object, entry } => {
                    if self.put(&format!("cas/{cas}"), &object) {
                        self.put(&entry, cas.as_bytes());
                    }
                }
                Upload::Entry { path, bytes } => {
                    self.put(&path, &bytes);
                }
            }
        }
    }

    fn warning(&self) -> Option<Diagnostic> {
        let problems = self.problems.lock().unwrap_or_else(std::sync::PoisonError::into_inner);
        let first = problems.first()?;
        let mut diagnostic = Diagnostic::warning(
            "K0620",
            format!("the remote cache at {} could not be used: {first}", self.config.url),
        );
        for more in problems.iter().skip(1) {
            diagnostic = diagnostic.note(more.clone());
        }
        Some(diagnostic.help("the build compiled locally what it could not fetch; its output is the same"))
    }
}

/// What the entry of a module or a pass's layouts is stored under: `ac/` and the SHA-256 of the
/// kind and key (bazel-remote takes only SHA-256 names).
fn entry_path(kind: &str, key: &str) -> String {
    format!("ac/{}", sha256(format!("kiln {kind} {key}").as_bytes()))
}

/// Lower-case hexadecimal SHA-256.
pub fn sha256(bytes: &[u8]) -> String {
    Sha256::digest(bytes).iter().map(|b| format!("{b:02x}")).collect()
}

fn is_sha256(text: &str) -> bool {
    text.len() == 64 && text.bytes().all(|b| b.is_ascii_digit() || (b'a'..=b'f').contains(&b))
}

/// Reads what is left of an answer, so that its connection goes back to the pool (ureq keeps a
/// connection alive only once its answer is read to the end).
fn drain(response: &mut ureq::http::Response<ureq::Body>) {
    let _ = response.body_mut().with_config().limit(1 << 20).read_to_vec();
}

/// An answer's status that is neither a success nor a miss, in a few words.
fn status_reason(status: u16, method: &str) -> String {
    match status {
        300..=399 => {
            format!("it answered a {method} with a redirect (HTTP {status}), which kiln does not follow")
        }
        _ => format!("HTTP {status} for a {method}"),
    }
}

/// An answer's body, refused past `limit` bytes without reading further: memory sized by what the
/// server says its length is, and never past the limit whatever it says.
fn read_at_most(response: &mut ureq::http::Response<ureq::Body>, limit: u64) -> Result<Vec<u8>, String> {
    let too_large = || "an answer was too large".to_string();
    let said = response.body().content_length();
    if said.is_some_and(|length| length > limit) {
        return Err(too_large());
    }
    if let Some(length) = said {
        let mut bytes = Vec::with_capacity(length as usize);
        let reader = response.body_mut().as_reader();
        std::io::Read::read_to_end(&mut std::io::Read::take(reader, limit + 1), &mut bytes)
            .map_err(|_| "an answer could not be read".to_string())?;
        return if bytes.len() as u64 > limit { Err(too_large()) } else { Ok(bytes) };
    }
    // No length said: read in pieces of one size, joined once at the end, so that a body that
    // never ends costs its limit once over, not a vector doubled up to it on every thread.
    let mut reader = std::io::Read::take(response.body_mut().as_reader(), limit + 1);
    let (mut pieces, mut total) = (Vec::new(), 0u64);
    loop {
        let mut piece = vec![0; 64 << 10];
        let mut filled = 0;
        while filled < piece.len() {
            let read = std::io::Read::read(&mut reader, &mut piece[filled..])
                .map_err(|_| "an answer could not be read".to_string())?;
            if read == 0 {
                break;
            }
            filled += read;
        }
        let ended = filled < piece.len();
        piece.truncate(filled);
        total += filled as u64;
        if total > limit {
            return Err(too_large());
        }
        pieces.push(piece);
        if ended {
            break;
        }
    }
    Ok(pieces.concat())
}

/// A failed request in a few words (no URL, no header: nothing secret).
fn reason(error: &ureq::Error) -> String {
    match error {
        ureq::Error::Timeout(_) => "a request timed out".into(),
        ureq::Error::ConnectionFailed => "the connection failed".into(),
        ureq::Error::HostNotFound => "the host was not found".into(),
        ureq::Error::Io(error) => match error.kind() {
            std::io::ErrorKind::ConnectionRefused => "the connection was refused".into(),
            std::io::ErrorKind::ConnectionReset | std::io::ErrorKind::ConnectionAborted => {
                "the connection was closed".into()
            }
            std::io::ErrorKind::TimedOut => "a request timed out".into(),
            _ => "an I/O error".into(),
        },
        ureq::Error::BodyExceedsLimit(_) => "an answer was too large".into(),
        ureq::Error::TooManyRedirects | ureq::Error::RedirectFailed => {
            "it answered with a redirect, which kiln does not follow".into()
        }
        _ => "a protocol error".into(),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn urls_whose_query_or_userinfo_would_be_printed_are_refused_without_echoing_them() {
        for url in ["https://h/kiln?token=s3cret", "https://h/kiln#s3cret", "https://user:s3cret@h/kiln"] {
            let why = check_url(url).expect_err(url);
            assert!(!why.contains("s3cret"), "{why}");
        }
        assert_eq!(check_url("https://h/kiln/").as_deref(), Ok("https://h/kiln"));
    }
}
