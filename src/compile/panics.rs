//! Panics as values: a stage module whose compile panics (inside naga, or kiln) becomes a
//! diagnostic instead of taking the build down. The process's panic hook is wrapped once so that
//! a panic inside a guarded call is recorded, not printed (the library never prints); every other
//! panic goes to the hook that was there before.

/// A panic caught while compiling, with where it happened.
pub(super) struct Panic {
    pub message: String,
    pub location: String,
}

thread_local! {
    /// Set while this thread compiles a module: its panics are caught, not printed.
    static GUARDED: std::cell::Cell<bool> = const { std::cell::Cell::new(false) };
    static CAUGHT: std::cell::RefCell<Option<Panic>> = const { std::cell::RefCell::new(None) };
}

/// Runs `f`, turning a panic into a value (the hook is wrapped the first time).
pub(super) fn contain_panics<T>(f: impl FnOnce() -> T) -> Result<T, Panic> {
    static HOOK: std::sync::Once = std::sync::Once::new();
    HOOK.call_once(|| {
        let previous = std::panic::take_hook();
        std::panic::set_hook(Box::new(move |info| {
            if !GUARDED.with(std::cell::Cell::get) {
                return previous(info);
            }
            let payload = info.payload();
            let message = payload
                .downcast_ref::<&str>()
                .map(|s| s.to_string())
                .or_else(|| payload.downcast_ref::<String>().cloned())
                .unwrap_or_else(|| "a panic without a message".to_string());
            let location = info.location().map_or_else(
                || "an unknown place".to_string(),
                |l| {
                    // `…/registry/src/<index>/naga-30.0.1/src/back/spv/block.rs` → from the crate on.
                    let file = l.file().replace('\\', "/");
                    let short = match file.rsplit_once("/src/") {
                        Some((krate, rest)) => {
                            format!("{}/src/{rest}", krate.rsplit('/').next().unwrap_or(krate))
                        }
                        None => file,
                    };
                    format!("{short}:{}:{}", l.line(), l.column())
                },
            );
            CAUGHT.with(|c| *c.borrow_mut() = Some(Panic { message, location }));
        }));
    });
    let was_guarded = GUARDED.with(|g| g.replace(true));
    let result = std::panic::catch_unwind(std::panic::AssertUnwindSafe(f));
    GUARDED.with(|g| g.set(was_guarded));
    result.map_err(|_| {
        CAUGHT.with(|c| c.borrow_mut().take()).unwrap_or(Panic {
            message: "a panic".to_string(),
            location: "an unknown place (another panic hook was installed)".to_string(),
        })
    })
}
