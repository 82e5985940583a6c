//! Compatibility with esmini, whose corpus scenarios use forms outside the OpenSCENARIO 1.3
//! text. Each is accepted only where it cannot change the meaning of a standard file.

/// Replaces the bare name `pi` (not `$pi`, not a call `pi(`) by its value. The 1.3 grammar
/// (§9.2) has no constants, but esmini accepts `pi` and its corpus uses it
/// (`parking_demo.xosc`); the text is handed to the standard evaluator afterwards.
pub(crate) fn esmini_constants(source: &str) -> std::borrow::Cow<'_, str> {
    let bytes = source.as_bytes();
    let is_ident = |b: u8| b.is_ascii_alphanumeric() || b == b'_' || b == b'$';
    let mut out = String::new();
    let mut last = 0;
    for (i, _) in source.match_indices("pi") {
        let before_ok = i == 0 || !is_ident(bytes[i - 1]);
        let rest = source[i + 2..].trim_start();
        let after_ok = bytes.get(i + 2).is_none_or(|&b| !is_ident(b)) && !rest.starts_with('(');
        if before_ok && after_ok {
            out.push_str(&source[last..i]);
            out.push_str("3.141592653589793");
            last = i + 2;
        }
    }
    if last == 0 {
        return std::borrow::Cow::Borrowed(source);
    }
    out.push_str(&source[last..]);
    std::borrow::Cow::Owned(out)
}

#[cfg(test)]
mod tests {
    use super::esmini_constants;

    #[test]
    fn only_the_bare_name_pi_is_replaced() {
        assert_eq!(esmini_constants("pi"), "3.141592653589793");
        assert_eq!(esmini_constants("2*pi/4"), "2*3.141592653589793/4");
        assert_eq!(esmini_constants("$pi + $spin + pi2"), "$pi + $spin + pi2");
    }
}
