//! Khronos' `glslangValidator`, the reference GLSL front end (and an HLSL one), as a second
//! reader of the GLSL and HLSL kiln writes: `kiln check` runs it on every such module when it is
//! installed (Debian: `glslang-tools`).

use crate::manifest::Backend;
use naga::ShaderStage;
use std::io::{Read, Write};
use std::path::PathBuf;
use std::process::{Command, Stdio};
use std::time::{Duration, Instant};

/// What glslang's HLSL front end refuses in HLSL that DXC and FXC compile, as the first error of
/// its output (those after it follow from it): such a module is taken as read. Each is listed in
/// docs/backends.md.
const GLSLANG_HLSL_GAPS: &[&str] = &[
    // naga zero-initialises an array `x` as `(float[4])0`, a cast of a scalar to an array.
    "array constructor needs one argument per array element",
    // A module-scope `var<private>` array with a value is a `static` initialised by naga's
    // array-constructor helper; glslang's linker calls that recursion. It cannot be: WGSL
    // forbids recursion and naga's validator refuses it, so no module naga wrote recurses.
    "Recursion detected",
];

/// How long glslang may take over one module: its HLSL front end has been seen to run for
/// minutes, and to take 13 GB, over a compute kernel of Tint's corpus.
const READ_LIMIT: Duration = Duration::from_secs(20);

/// The address space glslang may take: 13 GB over one module was seen (see [`READ_LIMIT`]), and
/// `kiln check` runs one per worker thread.
const MEMORY_LIMIT: u64 = 2 << 30;

/// Bounds what a glslang child may take ([`MEMORY_LIMIT`]) and, on Linux, ends it with kiln: a
/// kiln killed while glslang reads (a CI job cancelled, an editor closed) leaves no child behind
/// holding gigabytes.
#[cfg(target_os = "linux")]
fn confine_child(command: &mut Command) {
    use std::os::unix::process::CommandExt;
    let parent = std::process::id();
    // SAFETY: between fork and exec the closure only calls `setrlimit`, `prctl` and `getppid`,
    // which are async-signal-safe and allocate nothing.
    unsafe {
        command.pre_exec(move || {
            let limit = libc::rlimit {
                rlim_cur: MEMORY_LIMIT as libc::rlim_t,
                rlim_max: MEMORY_LIMIT as libc::rlim_t,
            };
            // A limit that cannot be set leaves glslang to the time limit alone.
            let _ = libc::setrlimit(libc::RLIMIT_AS, &limit);
            // Killed when the thread that started it ends: kiln's worker threads live as long as
            // the command. A kiln that died before this line is seen by its parent's change.
            if libc::prctl(libc::PR_SET_PDEATHSIG, libc::SIGKILL) != 0 || libc::getppid() as u32 != parent {
                return Err(std::io::Error::other("kiln ended before glslang started"));
            }
            Ok(())
        });
    }
}

#[cfg(not(target_os = "linux"))]
fn confine_child(_: &mut Command) {}

/// What glslang made of a module.
#[derive(Debug, Clone, PartialEq, Eq)]
pub enum Reading {
    /// It compiles.
    Accepted,
    /// It does not: glslang's first errors.
    Refused(String),
    /// glslang could not say (it did not start, or did not finish in time).
    Unread(String),
}

/// An installed `glslangValidator`.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Glslang {
    program: PathBuf,
    /// Its `--version` line, part of the key of every module it checked.
    version: String,
}

impl Glslang {
    /// `glslangValidator` on the `PATH`, if it runs.
    pub fn find() -> Option<Glslang> {
        let program = PathBuf::from("glslangValidator");
        let output = Command::new(&program).arg("--version").stdin(Stdio::null()).output().ok()?;
        let version = String::from_utf8_lossy(&output.stdout).lines().next()?.trim().to_string();
        output.status.success().then_some(Glslang { program, version })
    }

    /// Its version line.
    pub fn version(&self) -> &str {
        &self.version
    }

    /// Whether it reads `backend`'s language.
    pub fn reads(backend: Backend) -> bool {
        matches!(backend, Backend::Glsl | Backend::Hlsl)
    }

    /// Reads `text` (GLSL or HLSL, entry point `entry`) back.
    pub fn read(&self, backend: Backend, stage: ShaderStage, entry: &str, text: &str) -> Reading {
        let stage_name = match stage {
            ShaderStage::Vertex => "vert",
            ShaderStage::Fragment => "frag",
            _ => "comp",
        };
        let mut command = Command::new(&self.program);
        command.args(["--stdin", "-S", stage_name]);
        if backend == Backend::Hlsl {
            // glslang reads HLSL only on its way to SPIR-V, which is thrown away.
            command.args(["-D", "-V", "-e", entry, "-o", "/dev/null"]);
        }
        confine_child(&mut command);
        let mut child =
            match command.stdin(Stdio::piped()).stdout(Stdio::piped()).stderr(Stdio::piped()).spawn() {
                Ok(child) => child,
                Err(e) => return Reading::Unread(format!("glslangValidator could not be started: {e}")),
            };
        // Fed and drained from other threads: a long text must not fill a pipe while it waits.
        let mut stdin = child.stdin.take();
        let text = text.to_string();
        let feeder = std::thread::spawn(move || stdin.as_mut().map(|s| s.write_all(text.as_bytes())));
        let drain = |pipe: Option<Box<dyn Read + Send>>| {
            std::thread::spawn(move || {
                let mut said = String::new();
                if let Some(mut pipe) = pipe {
                    let _ = pipe.read_to_string(&mut said);
                }
                said
            })
        };
        let stdout = drain(child.stdout.take().map(|p| Box::new(p) as Box<dyn Read + Send>));
        let stderr = drain(child.stderr.take().map(|p| Box::new(p) as Box<dyn Read + Send>));
        let started = Instant::now();
        let status = loop {
            match child.try_wait() {
                Ok(Some(status)) => break Some(status),
                Ok(None) if started.elapsed() < READ_LIMIT => std::thread::sleep(Duration::from_millis(5)),
                _ => {
                    let _ = child.kill();
                    let _ = child.wait();
                    break None;
                }
            }
        };
        let _ = feeder.join();
        let said = stdout.join().unwrap_or_default() + &stderr.join().unwrap_or_default();
        let Some(status) = status else {
            return Reading::Unread(format!(
                "glslangValidator did not finish within {} s",
                READ_LIMIT.as_secs()
            ));
        };
        if status.success() {
            return Reading::Accepted;
        }
        let errors: Vec<&str> = said.lines().filter(|l| l.starts_with("ERROR")).take(5).collect();
        // No error of its own: glslang failed (its memory limit, a crash), not the module.
        if errors.is_empty() {
            return Reading::Unread(format!("glslangValidator failed without an error ({status})"));
        }
        if backend == Backend::Hlsl
            && let Some(first) = errors.first()
            && GLSLANG_HLSL_GAPS.iter().any(|gap| first.contains(gap))
        {
            return Reading::Accepted;
        }
        Reading::Refused(errors.join("\n"))
    }
}
