//! Who may receive a remote cache's credentials: decided once, when the build's settings are
//! resolved, from who named the server (the user, or a project's `kiln.toml`) and how it is
//! reached (docs/security.md).

/// Who named a remote cache's URL: that decides whether credentials go with it.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum UrlSource {
    /// The user, on the command line (`--remote-cache`) or in the environment
    /// (`KILN_REMOTE_CACHE`).
    User,
    /// The project's `kiln.toml`, which a pull request or a third-party shader pack can edit.
    Project,
}

/// An `Authorization` header's value: never printed (its `Debug` hides it), never written.
#[derive(Clone, PartialEq, Eq, Hash)]
pub struct Credentials(String);

impl std::fmt::Debug for Credentials {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str("Credentials(<hidden>)")
    }
}

impl Credentials {
    /// The header's value, for the request alone.
    pub(super) fn header(&self) -> &str {
        &self.0
    }

    /// From `KILN_REMOTE_CACHE_TOKEN` (bearer) or `KILN_REMOTE_CACHE_USER` and
    /// `KILN_REMOTE_CACHE_PASSWORD` (basic), when the environment has them.
    pub fn from_env() -> Option<Credentials> {
        let token = std::env::var("KILN_REMOTE_CACHE_TOKEN").ok().filter(|t| !t.is_empty());
        let basic = std::env::var("KILN_REMOTE_CACHE_USER").ok().map(|user| {
            let password = std::env::var("KILN_REMOTE_CACHE_PASSWORD").unwrap_or_default();
            use base64::Engine as _;
            format!(
                "Basic {}",
                base64::engine::general_purpose::STANDARD.encode(format!("{user}:{password}"))
            )
        });
        token.map(|t| format!("Bearer {t}")).or(basic).map(Credentials)
    }
}

/// Whether credentials may go to `url` (checked by [`check_url`]), named by `source`, when the
/// environment pins `pinned` (`KILN_REMOTE_CACHE_HOST`: a host, or `host:port`): to a URL the user
/// named, or to the pinned host, and only over HTTPS unless the host is this machine. `Err` says
/// why not.
pub fn credentials_for(url: &str, source: UrlSource, pinned: Option<&str>) -> Result<(), &'static str> {
    let (https, authority) = match url.strip_prefix("https://") {
        Some(rest) => (true, rest),
        None => (false, url.strip_prefix("http://").unwrap_or(url)),
    };
    let authority = authority.split('/').next().unwrap_or_default().to_ascii_lowercase();
    let host = match authority.strip_prefix('[') {
        Some(v6) => v6.split(']').next().unwrap_or_default().to_string(),
        None => authority.split(':').next().unwrap_or_default().to_string(),
    };
    let pinned = pinned.map(str::to_ascii_lowercase);
    let named_by_user = source == UrlSource::User
        || pinned.as_deref().is_some_and(|pin| pin == authority || pin == host || pin == format!("[{host}]"));
    if !named_by_user {
        return Err("its URL comes from `kiln.toml`, which anyone who edits the project can change");
    }
    let loopback = host == "localhost"
        || host == "::1"
        || host.split('.').next() == Some("127") && host.parse::<std::net::Ipv4Addr>().is_ok();
    if !https && !loopback {
        return Err("its URL is plain `http://` to another machine, where anyone on the way reads them");
    }
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn credentials_go_only_to_a_url_the_user_named_and_never_in_the_clear_off_this_machine() {
        use UrlSource::{Project, User};
        let allowed = |url: &str, source, pinned: Option<&str>| credentials_for(url, source, pinned).is_ok();
        // Named by the user: over HTTPS anywhere, over HTTP only to this machine.
        assert!(allowed("https://cache.example.com/kiln", User, None));
        for loopback in [
            "http://127.0.0.1:9090/kiln",
            "http://127.3.2.1/kiln",
            "http://localhost:80",
            "http://[::1]:8080/k",
        ] {
            assert!(allowed(loopback, User, None), "{loopback}");
        }
        for clear in
            ["http://cache.example.com/kiln", "http://10.0.0.5:8080/kiln", "http://127.0.0.1.evil.com/k"]
        {
            assert!(!allowed(clear, User, None), "{clear}");
        }
        // Named by kiln.toml: none, unless the environment pins that host (and port, if given).
        assert!(!allowed("https://cache.example.com/kiln", Project, None));
        assert!(!allowed("http://127.0.0.1:9090/kiln", Project, None));
        assert!(!allowed("https://cache.example.com/kiln", Project, Some("cache.example.org")));
        assert!(!allowed("https://cache.example.com:8443/kiln", Project, Some("cache.example.com:443")));
        assert!(allowed("https://cache.example.com/kiln", Project, Some("cache.example.com")));
        assert!(allowed("https://Cache.Example.com:8443/kiln", Project, Some("cache.example.com:8443")));
        // A pinned host over plain HTTP off this machine still gets none.
        assert!(!allowed("http://cache.example.com/kiln", Project, Some("cache.example.com")));
    }

    #[test]
    fn credentials_are_not_printed() {
        let credentials = Credentials("Bearer s3cret".into());
        assert!(!format!("{credentials:?}").contains("s3cret"));
    }
}
