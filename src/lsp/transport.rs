//! The server's stdio transport: lsp-server's own, but a message is read only once its header
//! says a size the server takes (lsp-server fills as many zero bytes as `Content-Length` asks
//! before the body arrives: 4 GB for one header line), and a header line is bounded too.

use crossbeam_channel::{Receiver, Sender, bounded};
use lsp_server::{Connection, Message};
use std::io::{self, BufRead, Read, Write};

/// The largest message the server reads: far above any source file an editor sends (kiln
/// refuses files over 16 MiB) and its JSON escaping.
pub(super) const MAX_MESSAGE: usize = 64 << 20;

/// The longest header line, and the most header bytes of one message.
const MAX_HEADER: u64 = 16 << 10;

/// The two threads that move messages between the connection and stdin/stdout.
pub(super) struct IoThreads {
    reader: std::thread::JoinHandle<io::Result<()>>,
    writer: std::thread::JoinHandle<io::Result<()>>,
}

impl IoThreads {
    /// Waits for both; the reader's error (a message refused, stdin broken) first.
    pub(super) fn join(self) -> io::Result<()> {
        let read = self.reader.join().unwrap_or_else(|_| Err(io::Error::other("the reader panicked")));
        let written = self.writer.join().unwrap_or_else(|_| Err(io::Error::other("the writer panicked")));
        read.and(written)
    }
}

/// A connection over stdin and stdout with bounded messages.
pub(super) fn stdio() -> (Connection, IoThreads) {
    let (to_server, receiver): (Sender<Message>, Receiver<Message>) = bounded(0);
    let (sender, from_server): (Sender<Message>, Receiver<Message>) = bounded(0);
    let reader = std::thread::spawn(move || {
        let stdin = io::stdin();
        let mut input = stdin.lock();
        while let Some(message) = read_message(&mut input)? {
            let exit = matches!(&message, Message::Notification(n) if n.method == "exit");
            if to_server.send(message).is_err() || exit {
                break;
            }
        }
        Ok(())
    });
    let writer = std::thread::spawn(move || {
        let stdout = io::stdout();
        let mut output = stdout.lock();
        for message in from_server {
            message.write(&mut output)?;
            output.flush()?;
        }
        Ok(())
    });
    (Connection { sender, receiver }, IoThreads { reader, writer })
}

/// The next message, `None` at the end of input, or an error for a header the server refuses:
/// a size over [`MAX_MESSAGE`], a header line over 16 KiB, none at all.
pub(super) fn read_message(input: &mut impl BufRead) -> io::Result<Option<Message>> {
    let refused = |what: String| io::Error::new(io::ErrorKind::InvalidData, what);
    let mut frame = Vec::new();
    let mut length = None;
    loop {
        let before = frame.len();
        let read = input.by_ref().take(MAX_HEADER).read_until(b'\n', &mut frame)?;
        if read == 0 {
            return if frame.is_empty() {
                Ok(None)
            } else {
                Err(refused("the input ended in a header".into()))
            };
        }
        if !frame.ends_with(b"\n") || frame.len() as u64 > MAX_HEADER {
            return Err(refused(format!("a message header over {MAX_HEADER} bytes")));
        }
        let line = String::from_utf8_lossy(&frame[before..]);
        let line = line.trim_end();
        if line.is_empty() {
            break;
        }
        if let Some((name, value)) = line.split_once(':')
            && name.trim().eq_ignore_ascii_case("Content-Length")
        {
            let size: u64 =
                value.trim().parse().map_err(|_| refused(format!("`{}` is not a size", value.trim())))?;
            if size > MAX_MESSAGE as u64 {
                return Err(refused(format!(
                    "a message of {size} bytes (`Content-Length`) is over the server's limit of {MAX_MESSAGE} bytes"
                )));
            }
            length = Some(size as usize);
        }
    }
    let length = length.ok_or_else(|| refused("a message without `Content-Length`".into()))?;
    let body = frame.len();
    frame.resize(body + length, 0);
    input.read_exact(&mut frame[body..])?;
    Message::read(&mut &frame[..])
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_message_over_the_limit_is_refused_before_anything_is_allocated_for_it() {
        let huge = b"Content-Length: 4000000000\r\n\r\n{}";
        let error = read_message(&mut &huge[..]).expect_err("refused");
        assert!(error.to_string().contains("4000000000 bytes"), "{error}");
        let endless = vec![b'x'; 100_000];
        assert!(read_message(&mut &endless[..]).is_err(), "an endless header line is refused");
        let body = r#"{"jsonrpc":"2.0","method":"exit"}"#;
        let framed = format!("Content-Length: {}\r\n\r\n{body}", body.len());
        let message = read_message(&mut framed.as_bytes()).expect("reads").expect("a message");
        assert!(matches!(message, Message::Notification(n) if n.method == "exit"));
        assert!(read_message(&mut &b""[..]).expect("end").is_none());
    }
}
