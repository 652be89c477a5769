//! Reading the text files users write (scenes, includes, camera paths) as POV-Ray reads them.

/// Decodes a text file a user wrote (scene, include, camera path) the way POV-Ray reads them: a
/// UTF-8 byte-order mark at the start is dropped (Windows editors write one); a file that is not
/// valid UTF-8 is read as Latin-1 (ISO-8859-1), one character per byte, which is what POV-Ray's
/// byte-wise reader and `charset sys` amount to on Western systems. Either way columns in
/// messages count characters as an editor in that encoding shows them.
pub fn decode_user_text(bytes: Vec<u8>) -> String {
    const BOM: &[u8] = "\u{feff}".as_bytes();
    let bytes = match bytes.strip_prefix(BOM) {
        Some(rest) => rest.to_vec(),
        None => bytes,
    };
    match String::from_utf8(bytes) {
        Ok(text) => text,
        Err(e) => e.into_bytes().iter().map(|&b| char::from(b)).collect(),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn utf8_byte_order_mark_is_dropped() {
        assert_eq!(decode_user_text(b"\xef\xbb\xbfcamera".to_vec()), "camera");
        // Only at the start: a mark in the middle is a character like any other.
        assert_eq!(decode_user_text(b"a\xef\xbb\xbf".to_vec()), "a\u{feff}");
    }

    #[test]
    fn non_utf8_file_is_read_as_latin1() {
        assert_eq!(decode_user_text(b"// caf\xe9\nx".to_vec()), "// caf\u{e9}\nx");
        assert_eq!(decode_user_text("// café".as_bytes().to_vec()), "// café");
    }
}
