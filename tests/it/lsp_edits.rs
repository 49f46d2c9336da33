//! Edit sequences replayed on an open buffer through an in-process `kiln lsp` (a memory
//! connection): the proptest in `tests/it/lsp.rs` and the `lsp_edits` fuzz target share it, so
//! it uses nothing of the test binary but kiln, lsp-server and serde_json.

use lsp_server::{Connection, Message, Notification, Request, RequestId};
use serde_json::{Value, json};
use std::path::Path;

/// One edit: `removed` bytes at byte `start` (both clamped to the text and its characters)
/// replaced by `inserted`.
#[derive(Debug, Clone)]
pub struct Edit {
    pub start: usize,
    pub removed: usize,
    pub inserted: String,
}

fn position(text: &str, offset: usize) -> Value {
    let before = &text[..offset];
    let line = before.matches('\n').count();
    let column: usize = before[before.rfind('\n').map_or(0, |n| n + 1)..].chars().map(char::len_utf16).sum();
    json!({ "line": line, "character": column })
}

fn boundary(text: &str, mut offset: usize) -> usize {
    offset = offset.min(text.len());
    while !text.is_char_boundary(offset) {
        offset -= 1;
    }
    offset
}

/// Opens `file` (of a project on disk), applies `edits` as incremental changes, asking for hover,
/// completion and definition at each edit's place, then shuts the server down. Panics when the
/// server stops answering, answers a request with an error, or ends without `exit`.
pub fn replay(file: &Path, scratch: &Path, edits: &[Edit]) {
    let (server, client) = Connection::memory();
    let options = kiln::lsp::ServerOptions {
        cache_dir: Some(scratch.join("cache")),
        library_dir: Some(scratch.join("shaderlib")),
    };
    let serving = std::thread::spawn(move || kiln::lsp::serve(&server, &options));
    let mut next = 0;
    let mut request = |method: &str, params: Value| -> Value {
        next += 1;
        let id = RequestId::from(next);
        client.sender.send(Message::Request(Request::new(id.clone(), method.into(), params))).expect("send");
        loop {
            match client.receiver.recv_timeout(std::time::Duration::from_secs(60)) {
                Ok(Message::Response(response)) if response.id == id => {
                    return response.response_result.unwrap_or_else(|e| panic!("{method}: {e:?}"));
                }
                Ok(_) => {}
                Err(e) => panic!("{method}: the server stopped answering ({e})"),
            }
        }
    };
    request("initialize", json!({ "capabilities": {} }));
    let notify = |method: &str, params: Value| {
        client.sender.send(Message::Notification(Notification::new(method.into(), params))).expect("send");
    };
    notify("initialized", json!({}));
    let canonical = std::fs::canonicalize(file).expect("the file exists");
    let uri = format!("file://{}", canonical.display());
    let mut text = std::fs::read_to_string(file).expect("file");
    notify(
        "textDocument/didOpen",
        json!({ "textDocument": { "uri": uri, "languageId": "wgsl", "version": 1, "text": text } }),
    );
    for (n, edit) in edits.iter().enumerate() {
        let start = boundary(&text, edit.start);
        let end = boundary(&text, start.saturating_add(edit.removed));
        let range = json!({ "start": position(&text, start), "end": position(&text, end) });
        text.replace_range(start..end, &edit.inserted);
        let change = json!({ "range": range, "text": edit.inserted });
        let params = json!({ "textDocument": { "uri": uri, "version": n + 2 }, "contentChanges": [change] });
        notify("textDocument/didChange", params);
        let at =
            json!({ "textDocument": { "uri": uri }, "position": position(&text, boundary(&text, start)) });
        request("textDocument/hover", at.clone());
        request("textDocument/completion", at.clone());
        request("textDocument/definition", at);
    }
    request("textDocument/documentSymbol", json!({ "textDocument": { "uri": uri } }));
    request("shutdown", Value::Null);
    notify("exit", Value::Null);
    serving.join().expect("the server thread ends").expect("the server ends cleanly");
}
