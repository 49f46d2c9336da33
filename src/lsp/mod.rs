//! `kiln lsp`: a language server (LSP over stdio) for `.shader`, `.compute`, `.wgsl`, `.hlsl` and
//! `.cginc` includes, `.mat` files and `kiln.toml` (docs/editor.md).
//!
//! Built on rust-analyzer's `lsp-server` (the protocol's framing and channels, synchronous, no
//! async runtime: a check is CPU work that rayon already spreads over the cores) and `lsp-types`.
//! Every request is answered from one [`analysis::Analysis`] per project: `kiln check` run over the
//! editor's unsaved buffers (a [`crate::source::Overlay`]), with the project's caches, so a pass
//! whose text did not change costs preprocessing only. Edits that arrive together are checked once.
//!
//! A check runs on a thread of its own, one at a time, so requests are answered while it runs,
//! from the project's last check; only a request about text that check has not seen (a project
//! never checked, a buffer typed in since) waits for the check to come. An edit to the project
//! a check is reading cancels that check: it starts no further pass, its result is dropped, and
//! the project is checked again with the edit.
//!
//! Long because `Server` is the protocol's state machine: its documents, projects and the one
//! running check, and a short arm per request and notification over them. What each answer
//! computes lives beside it (`navigate`, `complete`, `publish`, `variants`).

mod analysis;
mod complete;
mod navigate;
mod publish;
mod text;
mod transport;
mod variants;

use crate::project::Cancel;
use analysis::{Analysis, Caches, project_of, write_library};
use lsp_server::{Connection, ErrorCode, Message, Notification, Request, RequestId, Response};
use lsp_types as lsp;
use serde_json::{Value, json};
use std::collections::{BTreeSet, HashMap};
use std::path::{Path, PathBuf};
use std::sync::Arc;
use text::{offset_of, path_of, uri_of};
use variants::{PassName, Selections, keyword_list, shown};

/// How the server runs.
#[derive(Debug, Clone, Default)]
pub struct ServerOptions {
    /// The module cache checks share (default: `KILN_CACHE_DIR`, else the project's `cache_dir`,
    /// else `$XDG_CACHE_HOME/kiln/lsp-modules`).
    pub cache_dir: Option<PathBuf>,
    /// Where the bundled library's files are written for go-to-definition (default:
    /// `$XDG_CACHE_HOME/kiln/shaderlib-DIGEST`, the library's [`crate::shaderlib::digest`]).
    pub library_dir: Option<PathBuf>,
}

/// Why the server stopped other than by `exit`.
#[derive(Debug, thiserror::Error)]
pub enum LspError {
    /// The client broke the protocol or went away.
    #[error("language server protocol: {0}")]
    Protocol(#[from] lsp_server::ProtocolError),
    /// The connection's threads failed.
    #[error("language server I/O: {0}")]
    Io(#[from] std::io::Error),
    /// A message the transport refused (over the size limit, not the protocol's form).
    #[error("language server protocol: {0}")]
    Refused(String),
    /// The client closed the connection without `exit`.
    #[error("the client closed the connection")]
    Disconnected,
}

/// The commands the server executes (`workspace/executeCommand`).
pub const COMMANDS: [&str; 2] = ["kiln.nextVariant", "kiln.selectVariant"];

/// Serves one client on stdin and stdout until it sends `exit`.
pub fn serve_stdio(options: &ServerOptions) -> Result<(), LspError> {
    let (connection, threads) = transport::stdio();
    let served = serve(&connection, options);
    drop(connection);
    // A message the transport refused ends the session: that is the reason to give, not the
    // disconnection the server saw.
    threads.join().map_err(|error| match error.kind() {
        std::io::ErrorKind::InvalidData => LspError::Refused(error.to_string()),
        _ => LspError::Io(error),
    })?;
    served
}

/// Serves one client on `connection` (stdio, or in memory for tests and fuzzing) until `exit`.
pub fn serve(connection: &Connection, options: &ServerOptions) -> Result<(), LspError> {
    let (id, params) = connection.initialize_start()?;
    let params: lsp::InitializeParams = serde_json::from_value(params).unwrap_or_default();
    let refresh_lenses = params
        .capabilities
        .workspace
        .as_ref()
        .and_then(|w| w.code_lens.as_ref())
        .and_then(|c| c.refresh_support)
        .unwrap_or(false);
    connection.initialize_finish(id, initialize_result())?;
    // Files changed behind the editor's back (a checkout, a generator) are checked again when the
    // client can watch them for the server.
    let watches = params.capabilities.workspace.as_ref().and_then(|w| w.did_change_watched_files.as_ref());
    if watches.and_then(|w| w.dynamic_registration).unwrap_or(false) {
        let watchers: Vec<Value> = ["**/*.{shader,compute,wgsl,hlsl,hlsli,cginc,mat}", "**/kiln.toml"]
            .iter()
            .map(|glob| json!({ "globPattern": glob }))
            .collect();
        let registration = json!({ "registrations": [{
            "id": "kiln-files",
            "method": "workspace/didChangeWatchedFiles",
            "registerOptions": { "watchers": watchers },
        }]});
        let request = Request::new(RequestId::from(0), "client/registerCapability".into(), registration);
        connection.sender.send(Message::Request(request)).map_err(|_| LspError::Disconnected)?;
    }
    let user_cache = crate::project::user_cache_dir();
    let caches = Caches {
        modules: options.cache_dir.clone(),
        fallback_modules: user_cache.join("lsp-modules"),
        library: options
            .library_dir
            .clone()
            .unwrap_or_else(|| user_cache.join(format!("shaderlib-{}", crate::shaderlib::digest()))),
    };
    // Without the copy, go-to-definition into the library has nothing to open; nothing else needs it.
    let _ = write_library(&caches.library);
    let (finished, checks) = crossbeam_channel::unbounded();
    let mut server = Server {
        connection,
        running: None,
        finished,
        deferred: Vec::new(),
        widen: BTreeSet::new(),
        cancelled: 0,
        documents: HashMap::new(),
        projects: HashMap::new(),
        stale: BTreeSet::new(),
        selections: HashMap::new(),
        caches,
        refresh_lenses,
        next_request: 0,
    };
    let served = server.run(&checks);
    // A check still running is of no use to anyone now.
    if let Some(running) = &server.running {
        running.cancel.cancel();
    }
    served
}

fn initialize_result() -> Value {
    let capabilities = lsp::ServerCapabilities {
        text_document_sync: Some(lsp::TextDocumentSyncCapability::Options(lsp::TextDocumentSyncOptions {
            open_close: Some(true),
            change: Some(lsp::TextDocumentSyncKind::INCREMENTAL),
            save: Some(lsp::TextDocumentSyncSaveOptions::Supported(true)),
            ..lsp::TextDocumentSyncOptions::default()
        })),
        hover_provider: Some(lsp::HoverProviderCapability::Simple(true)),
        definition_provider: Some(lsp::OneOf::Left(true)),
        completion_provider: Some(lsp::CompletionOptions {
            trigger_characters: Some(vec!["\"".into(), "/".into(), "(".into(), " ".into(), "_".into()]),
            ..lsp::CompletionOptions::default()
        }),
        document_symbol_provider: Some(lsp::OneOf::Left(true)),
        code_lens_provider: Some(lsp::CodeLensOptions { resolve_provider: Some(false) }),
        execute_command_provider: Some(lsp::ExecuteCommandOptions {
            commands: COMMANDS.iter().map(|c| c.to_string()).collect(),
            ..lsp::ExecuteCommandOptions::default()
        }),
        ..lsp::ServerCapabilities::default()
    };
    json!({
        "capabilities": capabilities,
        "serverInfo": { "name": "kiln", "version": env!("CARGO_PKG_VERSION") },
    })
}

#[derive(PartialEq)]
enum Flow {
    Continue,
    Exit,
}

/// An open buffer.
struct Document {
    uri: lsp::Uri,
    text: String,
    version: i32,
}

/// A project's last check and what it last published for each file (the buffer's version and the
/// diagnostics): a file is published again only when either changes, so an edit publishes its
/// own buffer and the files whose diagnostics it changed, not every open buffer.
struct Project {
    analysis: Analysis,
    published: std::collections::BTreeMap<PathBuf, (Option<i32>, Vec<lsp::Diagnostic>)>,
    /// Variants its last complete check compiled.
    variants: usize,
}

/// A check running on its own thread.
struct Running {
    root: PathBuf,
    cancel: Cancel,
}

/// What a check's thread sends back.
struct Finished {
    root: PathBuf,
    analysis: Analysis,
}

/// Past this many variants, an edit's first diagnostics come from the active variants alone.
const ACTIVE_FIRST_ABOVE: usize = 64;

/// The notification sent when a check of every variant of a project is published
/// (`{"root": URI, "variants": N, "compiled": N, "reused": N, "cancelled": N}`: stage modules
/// naga compiled and those taken from caches, and checks that newer edits cancelled since the
/// last one): `$/` marks it as one clients may ignore.
pub const CHECKED: &str = "$/kiln/checked";

struct Server<'c> {
    connection: &'c Connection,
    /// Open buffers by canonical path.
    documents: HashMap<PathBuf, Document>,
    /// Checked projects by root.
    projects: HashMap<PathBuf, Project>,
    /// Roots whose files changed since their check.
    stale: BTreeSet<PathBuf>,
    /// Each project's chosen variants.
    selections: HashMap<PathBuf, Selections>,
    caches: Caches,
    refresh_lenses: bool,
    next_request: i32,
    /// The check in flight, if any (one at a time: each spreads over every core already).
    running: Option<Running>,
    /// Where check threads send what they found.
    finished: crossbeam_channel::Sender<Finished>,
    /// Requests about text no check has seen yet, answered when the check to come ends.
    deferred: Vec<Request>,
    /// Large projects whose active variants were checked, to be checked whole next.
    widen: BTreeSet<PathBuf>,
    /// Checks cancelled by newer edits since the last `$/kiln/checked`.
    cancelled: usize,
}

/// The canonical path of a document (as given when the file is not on disk).
fn canonical(path: &Path) -> PathBuf {
    std::fs::canonicalize(path).unwrap_or_else(|_| path.to_path_buf())
}

impl Server<'_> {
    /// Serves messages and checks' results until `exit` or the client goes away.
    fn run(&mut self, checks: &crossbeam_channel::Receiver<Finished>) -> Result<(), LspError> {
        loop {
            crossbeam_channel::select! {
                recv(self.connection.receiver) -> message => {
                    let Ok(message) = message else { return Ok(()) };
                    if self.handle(message)? == Flow::Exit {
                        return Ok(());
                    }
                    // Edits that came together are checked once, after the last of them.
                    while let Ok(message) = self.connection.receiver.try_recv() {
                        if self.handle(message)? == Flow::Exit {
                            return Ok(());
                        }
                    }
                }
                recv(checks) -> finished => {
                    if let Ok(finished) = finished {
                        self.finished(finished)?;
                    }
                }
            }
            self.refresh();
        }
    }

    fn handle(&mut self, message: Message) -> Result<Flow, LspError> {
        match message {
            Message::Request(request) => {
                if self.connection.handle_shutdown(&request)? {
                    return Ok(Flow::Exit);
                }
                if let Some(root) = self.unchecked_root(&request) {
                    if !self.checking(&root) {
                        self.stale.insert(root);
                    }
                    self.deferred.push(request);
                    return Ok(Flow::Continue);
                }
                let id = request.id.clone();
                // A bug in one answer must not end the session: the request fails, not the server.
                let answer = std::panic::catch_unwind(std::panic::AssertUnwindSafe(|| self.request(request)));
                let response = match answer {
                    Ok(Ok(result)) => Response::new_ok(id, result),
                    Ok(Err((code, message))) => Response::new_err(id, code as i32, message),
                    Err(_) => Response::new_err(
                        id,
                        ErrorCode::InternalError as i32,
                        "kiln failed to answer (a bug)".into(),
                    ),
                };
                self.send(Message::Response(response))?;
            }
            Message::Notification(notification) => {
                if notification.method == "exit" {
                    return Ok(Flow::Exit);
                }
                self.notification(notification);
                // A check reading what just changed is moot.
                if let Some(running) = &self.running
                    && self.stale.contains(&running.root)
                {
                    running.cancel.cancel();
                }
            }
            Message::Response(_) => {}
        }
        Ok(Flow::Continue)
    }

    /// The project a request must wait for: one not checked yet, or one whose check to come
    /// reads the request's buffer as it is now and its last check did not (a completion just
    /// after typing is about the text typed). Every other request is answered at once.
    fn unchecked_root(&self, request: &Request) -> Option<PathBuf> {
        let uri = match request.method.as_str() {
            "workspace/executeCommand" => request.params.get("arguments")?.get(0)?,
            _ => request.params.get("textDocument")?.get("uri")?,
        };
        let uri: lsp::Uri = serde_json::from_value(uri.clone()).ok()?;
        let path = canonical(&path_of(&uri)?);
        let root = self.root_of(&path)?;
        let Some(project) = self.projects.get(&root) else { return Some(root) };
        let coming = self.stale.contains(&root) || self.checking(&root);
        let analysis = &project.analysis;
        let seen = |text: &str| analysis.file(&path).is_some_and(|file| analysis.store.text(file) == text);
        let typed = self.documents.get(&path).is_some_and(|document| !seen(&document.text));
        (coming && typed).then_some(root)
    }

    /// Whether the check in flight is of `root`.
    fn checking(&self, root: &Path) -> bool {
        self.running.as_ref().is_some_and(|running| running.root == root)
    }

    fn send(&self, message: Message) -> Result<(), LspError> {
        self.connection.sender.send(message).map_err(|_| LspError::Disconnected)
    }

    fn notification(&mut self, notification: Notification) {
        let params = notification.params;
        match notification.method.as_str() {
            "textDocument/didOpen" => {
                let Ok(p) = serde_json::from_value::<lsp::DidOpenTextDocumentParams>(params) else { return };
                let Some(path) = path_of(&p.text_document.uri) else { return };
                let document = Document {
                    uri: p.text_document.uri,
                    text: p.text_document.text,
                    version: p.text_document.version,
                };
                let path = canonical(&path);
                // A document opened again is shown its diagnostics again, changed or not.
                for project in self.projects.values_mut() {
                    project.published.remove(&path);
                }
                self.changed(&path, Some(document));
            }
            "textDocument/didChange" => {
                let Ok(p) = serde_json::from_value::<lsp::DidChangeTextDocumentParams>(params) else {
                    return;
                };
                let Some(path) = path_of(&p.text_document.uri).map(|p| canonical(&p)) else { return };
                let Some(mut document) = self.documents.remove(&path) else { return };
                for change in p.content_changes {
                    match change.range {
                        Some(range) => {
                            let start = offset_of(&document.text, range.start);
                            let end = offset_of(&document.text, range.end).max(start);
                            document.text.replace_range(start..end, &change.text);
                        }
                        None => document.text = change.text,
                    }
                }
                document.version = p.text_document.version;
                self.changed(&path, Some(document));
            }
            "textDocument/didClose" => {
                let Ok(p) = serde_json::from_value::<lsp::DidCloseTextDocumentParams>(params) else { return };
                if let Some(path) = path_of(&p.text_document.uri) {
                    self.changed(&canonical(&path), None);
                }
            }
            "textDocument/didSave" | "workspace/didChangeWatchedFiles" => {
                self.stale.extend(self.projects.keys().cloned());
            }
            _ => {}
        }
    }

    /// A file's buffer opened, changed or closed (`document`: its text now, if open): its project
    /// and every project that read it are checked again.
    fn changed(&mut self, path: &Path, document: Option<Document>) {
        match document {
            Some(document) => self.documents.insert(path.to_path_buf(), document),
            None => self.documents.remove(path),
        };
        if let Some(root) = project_of(path) {
            self.stale.insert(root);
        }
        for (root, project) in &self.projects {
            if project.analysis.file(path).is_some() {
                self.stale.insert(root.clone());
            }
        }
        self.widen.retain(|root| !self.stale.contains(root));
    }

    /// Starts the next check when none runs: a stale project (a large one's active variants
    /// first, published at once), else the whole of a large project whose active variants were
    /// checked last.
    fn refresh(&mut self) {
        if self.running.is_some() {
            return;
        }
        let (root, active_only) = if let Some(root) = self.stale.pop_first() {
            let large = self.projects.get(&root).is_some_and(|p| p.variants > ACTIVE_FIRST_ABOVE);
            (root, large)
        } else if let Some(root) = self.widen.pop_first() {
            (root, false)
        } else {
            return;
        };
        let overlay: Arc<crate::source::Overlay> =
            Arc::new(self.documents.iter().map(|(path, d)| (path.clone(), d.text.clone())).collect());
        let selections = active_only.then(|| self.selections.get(&root).cloned().unwrap_or_default());
        let (caches, cancel, sender) = (self.caches.clone(), Cancel::new(), self.finished.clone());
        let (checked, told) = (root.clone(), cancel.clone());
        let check = move || {
            let run = || Analysis::run(&checked, overlay, &caches, selections.as_ref(), told);
            // A panic in a dependency must not end the session: the project shows it and is
            // checked again after the next edit.
            let analysis = std::panic::catch_unwind(std::panic::AssertUnwindSafe(run)).unwrap_or_else(|_| {
                Analysis::failed(
                    &checked,
                    &caches.library,
                    "kiln failed while checking this project (a bug: please report it)",
                )
            });
            // The server may have stopped meanwhile: then nobody waits for this.
            let _ = sender.send(Finished { root: checked, analysis });
        };
        if let Err(error) = std::thread::Builder::new().name("kiln-check".into()).spawn(check) {
            let why = format!("kiln could not start a check: {error}");
            let analysis = Analysis::failed(&root, &self.caches.library, &why);
            let _ = self.finished.send(Finished { root: root.clone(), analysis });
        }
        self.running = Some(Running { root, cancel });
    }

    /// A check ended: unless an edit cancelled it, its project keeps it and is published, and
    /// the requests that waited for it are answered.
    fn finished(&mut self, finished: Finished) -> Result<(), LspError> {
        let Finished { root, analysis } = finished;
        // Decided here, where edits cancel: a check that ended as an edit came is moot too.
        if self.running.take().is_some_and(|running| running.cancel.is_cancelled()) {
            self.cancelled += 1;
            return Ok(());
        }
        let partial = analysis.partial;
        let before = self.projects.remove(&root);
        let variants = match (&before, partial) {
            (Some(before), true) => before.variants,
            _ => analysis.variants(),
        };
        let published = before.map(|p| p.published).unwrap_or_default();
        self.projects.insert(root.clone(), Project { analysis, published, variants });
        self.publish(&root)?;
        if partial {
            self.widen.insert(root.clone());
        } else {
            let summary =
                self.projects.get(&root).and_then(|p| p.analysis.checked.as_ref()).map(|c| &c.summary);
            let checked = json!({
                "root": uri_of(&root),
                "variants": summary.map(|s| s.variants),
                "compiled": summary.map(|s| s.compiled),
                "reused": summary.map(|s| s.reused + s.shared),
                "cancelled": std::mem::take(&mut self.cancelled),
            });
            self.send(Message::Notification(Notification::new(CHECKED.into(), checked)))?;
        }
        for request in std::mem::take(&mut self.deferred) {
            self.handle(Message::Request(request))?;
        }
        Ok(())
    }

    /// Publishes a project's diagnostics and inactive regions: for every file that has some, every
    /// file that had some, and every open buffer of the project.
    fn publish(&mut self, root: &Path) -> Result<(), LspError> {
        let Some(project) = self.projects.get(root) else { return Ok(()) };
        let analysis = &project.analysis;
        let selections = self.selections.entry(root.to_path_buf()).or_default();
        let inactive = variants::inactive(analysis, selections);
        let mut files = publish::by_file(analysis, &inactive);
        let open = self
            .documents
            .keys()
            .filter(|path| project_of(path).as_deref() == Some(root) || analysis.file(path).is_some());
        for path in project.published.keys().chain(open) {
            files.entry(path.clone()).or_default();
        }
        let mut published = std::collections::BTreeMap::new();
        for (path, diagnostics) in files {
            let document = self.documents.get(&path);
            let Some(uri) = document.map(|d| d.uri.clone()).or_else(|| uri_of(&path)) else { continue };
            // What the client shows already for this version of the buffer is not sent again.
            let version = document.map(|d| d.version);
            let shown = (version, diagnostics);
            let unchanged = project.published.get(&path) == Some(&shown);
            let diagnostics = shown.1.clone();
            published.insert(path.clone(), shown);
            if unchanged {
                continue;
            }
            let params =
                lsp::PublishDiagnosticsParams { uri, diagnostics, version: document.map(|d| d.version) };
            self.send(Message::Notification(Notification::new(
                "textDocument/publishDiagnostics".into(),
                params,
            )))?;
        }
        if let Some(project) = self.projects.get_mut(root) {
            project.published = published;
        }
        Ok(())
    }

    /// The root of the project that answers for `path` (a file no project reads: none).
    fn root_of(&self, path: &Path) -> Option<PathBuf> {
        project_of(path)
            .filter(|root| self.projects.contains_key(root) || self.documents.contains_key(path))
            .or_else(|| {
                self.projects.iter().find(|(_, p)| p.analysis.file(path).is_some()).map(|(r, _)| r.clone())
            })
    }

    /// The root of the checked project that answers for `path`: its last check answers, even
    /// while a newer one runs.
    fn checked_root(&self, path: &Path) -> Option<PathBuf> {
        self.root_of(path).filter(|root| self.projects.contains_key(root))
    }

    fn request(&mut self, request: Request) -> Result<Value, (ErrorCode, String)> {
        let invalid = |e: serde_json::Error| (ErrorCode::InvalidParams, e.to_string());
        let params = request.params;
        let null = Ok(Value::Null);
        match request.method.as_str() {
            "textDocument/hover" => {
                let p: lsp::HoverParams = serde_json::from_value(params).map_err(invalid)?;
                let Some((analysis, file, offset)) = self.place(&p.text_document_position_params) else {
                    return null;
                };
                let root = analysis.root.clone();
                let (Some(project), selections) = (self.projects.get(&root), self.selections.get(&root))
                else {
                    return null;
                };
                let (analysis, none) = (&project.analysis, Selections::default());
                let found = navigate::find(analysis, file, offset);
                let at = Some((file, offset));
                let markdown =
                    found.and_then(|f| navigate::hover(analysis, selections.unwrap_or(&none), &f, at));
                let Some(markdown) = markdown else { return null };
                let hover = lsp::Hover {
                    contents: lsp::HoverContents::Markup(lsp::MarkupContent {
                        kind: lsp::MarkupKind::Markdown,
                        value: markdown,
                    }),
                    range: None,
                };
                Ok(json!(hover))
            }
            "textDocument/definition" => {
                let p: lsp::GotoDefinitionParams = serde_json::from_value(params).map_err(invalid)?;
                let Some((analysis, file, offset)) = self.place(&p.text_document_position_params) else {
                    return null;
                };
                let found = navigate::find(analysis, file, offset);
                let span = found.and_then(|found| navigate::definition(analysis, &found, file));
                let location = span.and_then(|span| publish::location(analysis, span));
                Ok(location.map_or(Value::Null, |l| json!(lsp::GotoDefinitionResponse::Scalar(l))))
            }
            "textDocument/completion" => {
                let p: lsp::CompletionParams = serde_json::from_value(params).map_err(invalid)?;
                let Some((analysis, file, offset)) = self.place(&p.text_document_position) else {
                    return null;
                };
                let Some(path) = analysis.path(file) else { return null };
                Ok(json!(complete::complete(analysis, file, &path, offset)))
            }
            "textDocument/documentSymbol" => {
                let p: lsp::DocumentSymbolParams = serde_json::from_value(params).map_err(invalid)?;
                let Some((analysis, file)) = self.document(&p.text_document.uri) else { return null };
                Ok(json!(complete::symbols(analysis, file)))
            }
            "textDocument/codeLens" => {
                let p: lsp::CodeLensParams = serde_json::from_value(params).map_err(invalid)?;
                Ok(json!(self.code_lenses(&p.text_document.uri)))
            }
            "workspace/executeCommand" => {
                let p: lsp::ExecuteCommandParams = serde_json::from_value(params).map_err(invalid)?;
                self.execute(&p.command, &p.arguments)
            }
            other => Err((ErrorCode::MethodNotFound, format!("kiln lsp does not handle `{other}`"))),
        }
    }

    /// A document's analysis and file id.
    fn document(&mut self, uri: &lsp::Uri) -> Option<(&Analysis, crate::source::FileId)> {
        let path = canonical(&path_of(uri)?);
        let root = self.checked_root(&path)?;
        let analysis = &self.projects.get(&root)?.analysis;
        Some((analysis, analysis.file(&path)?))
    }

    /// A position's analysis, file id and byte offset.
    fn place(
        &mut self,
        at: &lsp::TextDocumentPositionParams,
    ) -> Option<(&Analysis, crate::source::FileId, usize)> {
        let (analysis, file) = self.document(&at.text_document.uri)?;
        let offset = offset_of(analysis.store.text(file), at.position);
        Some((analysis, file, offset))
    }

    /// A lens above each pass of a shader: its active variant; clicking it moves to the next.
    fn code_lenses(&mut self, uri: &lsp::Uri) -> Vec<lsp::CodeLens> {
        let Some(path) = path_of(uri).map(|p| canonical(&p)) else { return Vec::new() };
        let Some(root) = self.checked_root(&path) else { return Vec::new() };
        let Some(analysis) = self.projects.get(&root).map(|p| &p.analysis) else { return Vec::new() };
        let Some(file) = analysis.file(&path) else { return Vec::new() };
        let selections = self.selections.entry(root).or_default();
        let text = analysis.store.text(file);
        let mut lenses = Vec::new();
        for (at, shader, pass, program) in analysis.passes().filter(|(_, s, ..)| s.file == file) {
            let Some(span) = shader.pass_ast(pass).map(|p| p.span).or(Some(shader.shader.name.span)) else {
                continue;
            };
            let Some(name) = variants::pass_name(analysis, at) else { continue };
            let title = match selections.active(&name, program) {
                Some((index, variant)) => format!(
                    "variant {} of {}: {} · next ▸",
                    index + 1,
                    program.variants.len(),
                    shown(&keyword_list(program, variant))
                ),
                None => "no variant built: no material uses this shader".into(),
            };
            let command = lsp::Command::new(
                title,
                COMMANDS[0].into(),
                Some(vec![json!(uri), json!(name.0), json!(name.1)]),
            );
            let range = text::range_of(text, span.start as usize..span.start as usize);
            lenses.push(lsp::CodeLens { range, command: Some(command), data: None });
        }
        lenses
    }

    /// `kiln.nextVariant URI SHADER PASS` and `kiln.selectVariant URI SHADER PASS [KEYWORDS]`: the
    /// pass's active variant changes, its inactive regions are published again. Answers the
    /// variant now active (its keywords).
    fn execute(&mut self, command: &str, arguments: &[Value]) -> Result<Value, (ErrorCode, String)> {
        let bad = |why: &str| (ErrorCode::InvalidParams, format!("{command}: {why}"));
        if !COMMANDS.contains(&command) {
            return Err((ErrorCode::MethodNotFound, format!("no command `{command}`")));
        }
        let uri: lsp::Uri = serde_json::from_value(arguments.first().cloned().unwrap_or_default())
            .map_err(|_| bad("the first argument is the shader's URI"))?;
        let shader =
            arguments.get(1).and_then(Value::as_str).ok_or_else(|| bad("the second is the shader's name"))?;
        let pass =
            arguments.get(2).and_then(Value::as_u64).ok_or_else(|| bad("the third is the pass index"))?;
        let name: PassName = (shader.to_string(), pass as usize);
        let path = path_of(&uri).map(|p| canonical(&p)).ok_or_else(|| bad("not a file URI"))?;
        let root =
            self.checked_root(&path).ok_or_else(|| bad("the file is not part of a checked project"))?;
        let analysis = &self.projects.get(&root).ok_or_else(|| bad("not checked"))?.analysis;
        let found =
            analysis.passes().find(|&(at, ..)| variants::pass_name(analysis, at).as_ref() == Some(&name));
        let (_, _, _, program) = found.ok_or_else(|| bad("no such pass with a program kiln compiles"))?;
        let selections = self.selections.entry(root.clone()).or_default();
        let keywords = if command == COMMANDS[0] {
            let next = selections.active(&name, program).map_or(0, |(i, _)| (i + 1) % program.variants.len());
            program.variants.get(next).map(|v| keyword_list(program, v)).unwrap_or_default()
        } else {
            let wanted: Vec<String> = serde_json::from_value(arguments.get(3).cloned().unwrap_or_default())
                .map_err(|_| bad("the fourth is the list of keywords"))?;
            let found = program.variants.iter().map(|v| keyword_list(program, v)).find(|k| {
                let mut sorted = k.clone();
                sorted.sort();
                let mut w = wanted.clone();
                w.sort();
                sorted == w
            });
            found.ok_or_else(|| bad("the pass has no built variant with exactly these keywords"))?
        };
        selections.choose(name, keywords.clone());
        // The pass's regions and lenses change; a failed send means the client is gone.
        let _ = self.publish(&root);
        if self.refresh_lenses {
            self.next_request += 1;
            let request =
                Request::new(RequestId::from(self.next_request), "workspace/codeLens/refresh".into(), ());
            let _ = self.send(Message::Request(request));
        }
        Ok(json!(keywords))
    }
}
