//! A language client for `kiln lsp` over stdio, as an editor is one: the tests (`tests/it/lsp.rs`)
//! and the latency benchmark (`benches/lsp.rs`) drive the built binary through it.

use serde_json::{Value, json};
use std::io::{BufRead, BufReader, Write};
use std::path::Path;
use std::process::{Child, ChildStdin, Command, Stdio};
use std::sync::mpsc::{Receiver, RecvTimeoutError};
use std::time::{Duration, Instant};

/// How long a test waits for one message before it fails (a check of the example takes ~20 ms).
const PATIENCE: Duration = Duration::from_secs(60);

/// A language client: the server's process, its stdin, and the messages read from its stdout.
pub struct Client {
    child: Child,
    stdin: ChildStdin,
    incoming: Receiver<Value>,
    /// Notifications read while waiting for something else.
    pending: Vec<Value>,
    next_id: i64,
}

// The tests use some methods, the benchmark others.
#[allow(dead_code)]
impl Client {
    /// Starts `kiln lsp` with its caches in `scratch` and initializes it.
    pub fn start(scratch: &Path) -> Client {
        Client::start_with(scratch, json!({ "workspace": { "codeLens": { "refreshSupport": false } } }))
    }

    /// [`Client::start`] for a client with these capabilities.
    pub fn start_with(scratch: &Path, capabilities: Value) -> Client {
        let mut child = Command::new(env!("CARGO_BIN_EXE_kiln"))
            .args(["lsp", "--cache-dir"])
            .arg(scratch.join("cache"))
            .env("XDG_CACHE_HOME", scratch)
            .stdin(Stdio::piped())
            .stdout(Stdio::piped())
            .stderr(Stdio::inherit())
            .spawn()
            .expect("kiln lsp starts");
        let stdin = child.stdin.take().expect("stdin");
        let mut stdout = BufReader::new(child.stdout.take().expect("stdout"));
        let (send, incoming) = std::sync::mpsc::channel();
        std::thread::spawn(move || {
            while let Some(message) = read_message(&mut stdout) {
                if send.send(message).is_err() {
                    break;
                }
            }
        });
        let mut client = Client { child, stdin, incoming, pending: Vec::new(), next_id: 0 };
        let init = client.request(
            "initialize",
            json!({ "processId": null, "rootUri": null, "capabilities": capabilities }),
        );
        assert_eq!(init["serverInfo"]["name"], "kiln", "{init}");
        client.notify("initialized", json!({}));
        client
    }

    /// Sends a notification.
    pub fn notify(&mut self, method: &str, params: Value) {
        self.send(&json!({ "jsonrpc": "2.0", "method": method, "params": params }));
    }

    /// Sends a request and waits for its result (an error response fails the test).
    pub fn request(&mut self, method: &str, params: Value) -> Value {
        let response = self.request_raw(method, params);
        assert!(response.get("error").is_none(), "{method}: {response}");
        response["result"].clone()
    }

    /// Sends a request and waits for its response, error or not.
    pub fn request_raw(&mut self, method: &str, params: Value) -> Value {
        self.next_id += 1;
        let id = self.next_id;
        self.send(&json!({ "jsonrpc": "2.0", "id": id, "method": method, "params": params }));
        self.wait(|m| m["id"] == id && m.get("method").is_none())
    }

    /// Waits for the diagnostics of `uri` published for buffer `version` (or any, with `None`).
    pub fn diagnostics(&mut self, uri: &str, version: Option<i64>) -> Vec<Value> {
        let published = self.wait(|m| {
            m["method"] == "textDocument/publishDiagnostics"
                && m["params"]["uri"] == uri
                && version.is_none_or(|v| m["params"]["version"] == v)
        });
        published["params"]["diagnostics"].as_array().cloned().unwrap_or_default()
    }

    /// The diagnostics of `uri` last published before the last response (which a command's
    /// publishing precedes); earlier ones are dropped.
    pub fn latest_diagnostics(&mut self, uri: &str) -> Vec<Value> {
        self.pending.extend(self.incoming.try_iter());
        let is_for =
            |m: &Value| m["method"] == "textDocument/publishDiagnostics" && m["params"]["uri"] == uri;
        let latest =
            self.pending.iter().rev().find(|m| is_for(m)).cloned().expect("diagnostics were published");
        self.pending.retain(|m| !is_for(m));
        latest["params"]["diagnostics"].as_array().cloned().unwrap_or_default()
    }

    /// How many times each URI's diagnostics were published among the messages received so far
    /// (which are dropped).
    pub fn publications(&mut self) -> std::collections::BTreeMap<String, usize> {
        self.pending.extend(self.incoming.try_iter());
        let mut counts = std::collections::BTreeMap::new();
        for message in self.pending.drain(..) {
            if message["method"] == "textDocument/publishDiagnostics" {
                *counts
                    .entry(message["params"]["uri"].as_str().unwrap_or_default().to_string())
                    .or_insert(0) += 1;
            }
        }
        counts
    }

    /// How many messages with `method` arrived so far and are not yet taken (none is taken).
    pub fn received(&mut self, method: &str) -> usize {
        self.pending.extend(self.incoming.try_iter());
        self.pending.iter().filter(|m| m["method"] == method).count()
    }

    /// Waits for the next message from the server with `method` (a notification or a request)
    /// and returns its parameters.
    pub fn notification(&mut self, method: &str) -> Value {
        self.wait(|m| m["method"] == method)["params"].clone()
    }

    /// Opens a buffer with `text`.
    pub fn open(&mut self, uri: &str, text: &str) {
        let document = json!({ "uri": uri, "languageId": "wgsl", "version": 1, "text": text });
        self.notify("textDocument/didOpen", json!({ "textDocument": document }));
    }

    /// Replaces a buffer's text (full sync), as version `version`.
    pub fn change(&mut self, uri: &str, version: i64, text: &str) {
        let params = json!({ "textDocument": { "uri": uri, "version": version }, "contentChanges": [{ "text": text }] });
        self.notify("textDocument/didChange", params);
    }

    /// The server process's peak resident memory so far, in KiB (Linux; `None` elsewhere).
    pub fn peak_memory_kib(&self) -> Option<u64> {
        let status = std::fs::read_to_string(format!("/proc/{}/status", self.child.id())).ok()?;
        let line = status.lines().find(|l| l.starts_with("VmHWM:"))?;
        line.split_whitespace().nth(1)?.parse().ok()
    }

    /// `shutdown` then `exit`: the server must end with status 0.
    pub fn shutdown(mut self) {
        assert_eq!(self.request("shutdown", Value::Null), Value::Null);
        self.notify("exit", Value::Null);
        let status = self.child.wait().expect("server ends");
        assert!(status.success(), "kiln lsp exited with {status}");
    }

    fn send(&mut self, message: &Value) {
        let body = message.to_string();
        write!(self.stdin, "Content-Length: {}\r\n\r\n{body}", body.len()).expect("write to the server");
        self.stdin.flush().expect("flush");
    }

    fn wait(&mut self, wanted: impl Fn(&Value) -> bool) -> Value {
        if let Some(at) = self.pending.iter().position(&wanted) {
            return self.pending.remove(at);
        }
        let deadline = Instant::now() + PATIENCE;
        loop {
            match self.incoming.recv_timeout(deadline.saturating_duration_since(Instant::now())) {
                Ok(message) if wanted(&message) => return message,
                Ok(message) => self.pending.push(message),
                Err(RecvTimeoutError::Timeout) => {
                    panic!("no such message from the server; had {:#?}", self.pending)
                }
                Err(RecvTimeoutError::Disconnected) => {
                    panic!("the server closed stdout; had {:#?}", self.pending)
                }
            }
        }
    }
}

impl Drop for Client {
    fn drop(&mut self) {
        let _ = self.child.kill();
        let _ = self.child.wait();
    }
}

/// One framed message (`Content-Length: N` then N bytes of JSON), `None` at the end of the stream.
fn read_message(reader: &mut impl BufRead) -> Option<Value> {
    let mut length = None;
    loop {
        let mut line = String::new();
        if reader.read_line(&mut line).ok()? == 0 {
            return None;
        }
        let line = line.trim_end();
        if line.is_empty() {
            break;
        }
        if let Some(value) = line.strip_prefix("Content-Length: ") {
            length = value.parse::<usize>().ok();
        }
    }
    let mut body = vec![0; length?];
    std::io::Read::read_exact(reader, &mut body).ok()?;
    serde_json::from_slice(&body).ok()
}

/// The `file:` URI of a path.
pub fn uri(path: &Path) -> String {
    let path = std::fs::canonicalize(path).unwrap_or_else(|_| path.to_path_buf());
    format!("file://{}", path.display())
}
