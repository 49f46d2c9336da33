//! What the renderer's test files share.

/// Reports a skipped check where it stays visible: straight to the process's stderr, which the
/// test harness does not capture (a passing test's `println!` is hidden).
pub fn skipped(what: &str) {
    use std::io::Write as _;
    let _ = writeln!(std::io::stderr(), "SKIPPED {what}");
}

/// Skips (with the reason printed) when there is no adapter, unless CI requires one.
pub fn gpu(test: &str) -> Option<(wgpu::Device, wgpu::Queue, String)> {
    device_or_skip(test, kiln_renderer::device())
}

/// [`gpu`] on wgpu's OpenGL back end.
#[allow(dead_code)]
pub fn gl_gpu(test: &str) -> Option<(wgpu::Device, wgpu::Queue, String)> {
    device_or_skip(test, kiln_renderer::gl_device())
}

fn device_or_skip(
    test: &str,
    device: Result<(wgpu::Device, wgpu::Queue, String), String>,
) -> Option<(wgpu::Device, wgpu::Queue, String)> {
    match device {
        Ok(found) => Some(found),
        Err(reason) => {
            assert!(
                std::env::var("KILN_REQUIRE_GPU").as_deref() != Ok("1"),
                "KILN_REQUIRE_GPU=1 but {reason}"
            );
            skipped(&format!("{test}: {reason}"));
            None
        }
    }
}
