//! What a local server must refuse: a request from a page of another site
//! that reaches it by a name resolving to 127.0.0.1 (DNS rebinding: its Host
//! header is that name), a request without the secret token that is in the
//! address the lab printed, and any path that is not one of its own.
//!
//! The lab never maps a request's path to a file: it answers a fixed list
//! of routes (`routes.rs`), and pictures from memory. A path with `..`, a
//! backslash or an encoded one of them is refused here as well, before any
//! route is looked at.

/// The request's path below the token, or why it is refused.
#[derive(Debug, PartialEq, Eq)]
pub enum Verdict<'a> {
    /// The path below `/TOKEN`, such as `/api/state`, and the query, if any.
    Allowed { path: String, query: &'a str },
    /// Host is not the loopback address: 403.
    ForeignHost,
    /// No token, a wrong one, or a path that escapes: 404.
    NotFound,
}

/// Checks a request: its raw target (`/TOKEN/api/state?x=1`), its Host
/// header, the lab's token and port.
pub fn check<'a>(target: &'a str, host: Option<&str>, token: &str, port: u16) -> Verdict<'a> {
    if !host.is_some_and(|h| is_loopback(h, port)) {
        return Verdict::ForeignHost;
    }
    let (raw, query) = target.split_once('?').unwrap_or((target, ""));
    let Some(path) = percent_decoded(raw) else {
        return Verdict::NotFound;
    };
    let Some(below) = path.strip_prefix('/') else {
        return Verdict::NotFound;
    };
    let (first, rest) = below.split_at(below.find('/').unwrap_or(below.len()));
    if !same_secret(first, token) {
        return Verdict::NotFound;
    }
    if escapes(rest) {
        return Verdict::NotFound;
    }
    let path = if rest.is_empty() { "/" } else { rest };
    Verdict::Allowed {
        path: path.to_owned(),
        query,
    }
}

/// Is `given` the secret `token`? Compared in constant time: every byte
/// is looked at, whatever the first difference, so that how long a wrong
/// guess takes tells nothing about how much of it was right. (The length
/// is no secret: 32 hex digits.)
fn same_secret(given: &str, token: &str) -> bool {
    let differences = (given.bytes().zip(token.bytes()))
        .fold(0u8, |acc, (a, b)| std::hint::black_box(acc | (a ^ b)));
    given.len() == token.len() && differences == 0
}

/// Did the browser mark the request as sent by a page of another site?
/// `Sec-Fetch-Site` (which no page can set) is `same-origin` for the lab's
/// own page's requests, and `none` when the student types the address; a
/// request without it (curl, the tests) is judged by the token alone.
pub fn sent_by_another_site(sec_fetch_site: Option<&str>) -> bool {
    sec_fetch_site.is_some_and(|site| !matches!(site, "same-origin" | "none"))
}

/// Is `host` (a Host header) the loopback address at the lab's port?
/// `localhost`, `127.0.0.1` and `[::1]`, with the port or without.
fn is_loopback(host: &str, port: u16) -> bool {
    let name = match host.rsplit_once(':') {
        Some((name, p)) if !name.ends_with(':') && !p.contains(']') => {
            if p != port.to_string() {
                return false;
            }
            name
        }
        _ => host,
    };
    matches!(
        name.to_ascii_lowercase().as_str(),
        "localhost" | "127.0.0.1" | "[::1]"
    )
}

/// Does a decoded path try to leave the lab's own names: a `..` or `.`
/// segment, a hidden name, a backslash, an empty segment (but a last
/// one: `/`) or a NUL?
fn escapes(path: &str) -> bool {
    let segments: Vec<&str> = path.split('/').skip(1).collect();
    let last = segments.len().saturating_sub(1);
    path.contains('\\')
        || path.contains('\0')
        || (segments.iter().enumerate())
            .any(|(i, segment)| segment.starts_with('.') || (segment.is_empty() && i < last))
}

/// `%2e%2E` → `..`; None if an escape is malformed or the result is not
/// UTF-8. Decoded once: `%252e` stays `%2e`, which no route has.
pub fn percent_decoded(text: &str) -> Option<String> {
    let bytes = text.as_bytes();
    let mut out = Vec::with_capacity(bytes.len());
    let mut i = 0;
    while i < bytes.len() {
        if bytes[i] == b'%' {
            let hex = std::str::from_utf8(bytes.get(i + 1..i + 3)?).ok()?;
            out.push(u8::from_str_radix(hex, 16).ok()?);
            i += 3;
        } else {
            out.push(bytes[i]);
            i += 1;
        }
    }
    String::from_utf8(out).ok()
}

/// A fresh secret token: 128 random bits from the operating system's
/// generator (getrandom: `getrandom(2)` on Linux, for cryptographic keys),
/// in hex.
pub fn new_token() -> Result<String, String> {
    let mut bytes = [0u8; 16];
    getrandom::fill(&mut bytes).map_err(|e| format!("no random numbers for the token: {e}"))?;
    Ok(bytes.iter().map(|b| format!("{b:02x}")).collect())
}

#[cfg(test)]
mod tests {
    use super::*;

    const HOST: Option<&str> = Some("127.0.0.1:8000");

    fn allowed(target: &str) -> Option<String> {
        match check(target, HOST, "abc", 8000) {
            Verdict::Allowed { path, .. } => Some(path),
            _ => None,
        }
    }

    #[test]
    fn the_token_leads_every_path() {
        assert_eq!(allowed("/abc/"), Some("/".into()));
        assert_eq!(allowed("/abc"), Some("/".into()));
        assert_eq!(allowed("/abc/api/state?v=1"), Some("/api/state".into()));
        assert_eq!(allowed("/abcd/"), None);
        assert_eq!(allowed("/ab/"), None);
        assert_eq!(allowed("/"), None);
    }

    #[test]
    fn escaping_paths_are_refused_even_encoded() {
        for target in [
            "/abc/../Cargo.toml",
            "/abc/%2e%2e/Cargo.toml",
            "/abc/pictures/%2E%2E%2F%2E%2E%2FCargo.toml",
            "/abc/pictures/..%5c..%5cCargo.toml",
            "/abc//etc/passwd",
            "/abc/.git/config",
            "/abc/%00",
            "/abc/%zz",
        ] {
            assert_eq!(allowed(target), None, "{target}");
        }
    }

    #[test]
    fn only_the_loopback_address_may_be_the_host() {
        for host in [
            "127.0.0.1:8000",
            "localhost:8000",
            "[::1]:8000",
            "LOCALHOST",
        ] {
            assert!(is_loopback(host, 8000), "{host}");
        }
        for host in [
            "evil.example:8000",
            "127.0.0.1:8001",
            "127.0.0.2:8000",
            "[::1]:80",
        ] {
            assert!(!is_loopback(host, 8000), "{host}");
        }
        assert_eq!(check("/abc/", None, "abc", 8000), Verdict::ForeignHost);
    }

    #[test]
    fn the_token_is_compared_whole() {
        assert!(same_secret("abc", "abc"));
        for given in ["abd", "ab", "abcd", "", "xbc"] {
            assert!(!same_secret(given, "abc"), "{given}");
        }
    }

    #[test]
    fn only_the_pages_own_requests_reach_the_api() {
        for site in [None, Some("same-origin"), Some("none")] {
            assert!(!sent_by_another_site(site), "{site:?}");
        }
        for site in [Some("cross-site"), Some("same-site"), Some("")] {
            assert!(sent_by_another_site(site), "{site:?}");
        }
    }

    #[test]
    fn tokens_differ() {
        let (a, b) = (new_token().unwrap(), new_token().unwrap());
        assert_eq!(a.len(), 32);
        assert_ne!(a, b);
    }
}
