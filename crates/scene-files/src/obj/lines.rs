//! An OBJ file's lines, one at a time: read from a buffer, not the whole
//! file, so that memory stays the same however long the file is. A UTF-8
//! byte order mark before the first line and a carriage return before each
//! newline (CRLF, as Windows writes) are valid OBJ and are skipped; a byte
//! that no text has (NUL, most control characters) means the file is not
//! text at all.

use std::io::{BufRead, Read};

/// The longest line read: a face of some thousand corners fits many times
/// over. A longer "line" is a file without newlines, such as a binary one,
/// which would otherwise be read whole before it could be refused.
pub(super) const MAX_LINE: usize = 1 << 20;

/// The UTF-8 byte order mark, which some editors write at a file's start.
const BOM: &[u8] = b"\xEF\xBB\xBF";

/// Hands out the lines of an OBJ file, numbered from 1.
pub(super) struct Lines<R> {
    input: R,
    /// The current line, without its line end.
    pub text: Vec<u8>,
    /// The current line's number.
    pub number: usize,
}

impl<R: BufRead> Lines<R> {
    pub fn new(input: R) -> Lines<R> {
        Lines {
            input,
            text: Vec::with_capacity(256),
            number: 0,
        }
    }

    /// Reads the next line into `text`: `Ok(false)` at the end of the file;
    /// for a line that cannot be read or is not text, an error: the column
    /// and a message.
    pub fn next(&mut self) -> Result<bool, (usize, String)> {
        if self.number == 0 {
            self.refuse_binary_start()?;
        }
        self.text.clear();
        let limit = MAX_LINE as u64 + 1;
        let read = (&mut self.input)
            .take(limit)
            .read_until(b'\n', &mut self.text);
        let read = read.map_err(|e| (1, format!("cannot read the OBJ file: {e}")))?;
        if read == 0 {
            return Ok(false);
        }
        self.number += 1;
        if self.text.len() > MAX_LINE && !self.text.ends_with(b"\n") {
            let mib = MAX_LINE >> 20;
            let message =
                format!("the line is longer than {mib} MiB: not an OBJ file (is it binary?)");
            return Err((1, message));
        }
        while matches!(self.text.last(), Some(b'\n' | b'\r')) {
            self.text.pop();
        }
        if self.number == 1 && self.text.starts_with(BOM) {
            self.text.drain(..BOM.len());
        }
        match self.text.iter().position(|&b| not_text(b)) {
            Some(i) => Err((i + 1, binary(self.text[i]))),
            None => Ok(true),
        }
    }

    /// Refuses a file whose start (as much as the first read brings) has a
    /// byte that no text has, on the line of the first such byte: a binary
    /// file is then named as such, rather than by what its first "line"
    /// seems to say.
    fn refuse_binary_start(&mut self) -> Result<(), (usize, String)> {
        let start = (self.input.fill_buf()).map_err(|e| (1, format!("cannot read: {e}")))?;
        let Some(i) = start.iter().position(|&b| b != b'\n' && not_text(b)) else {
            return Ok(());
        };
        let line_start = start[..i]
            .iter()
            .rposition(|&b| b == b'\n')
            .map_or(0, |n| n + 1);
        let line_end = start[i..]
            .iter()
            .position(|&b| b == b'\n')
            .map_or(start.len(), |n| i + n);
        self.number = start[..i].iter().filter(|&&b| b == b'\n').count() + 1;
        self.text = start[line_start..line_end].to_vec();
        Err((i - line_start + 1, binary(start[i])))
    }
}

/// A byte that text does not have: a control character other than tab,
/// carriage return and form feed (and the newline that ends a line).
fn not_text(b: u8) -> bool {
    (b < 0x20 && !matches!(b, b'\t' | b'\r' | 0x0C)) || b == 0x7F
}

/// Why a file with the byte `b` (which no text has) is refused.
fn binary(b: u8) -> String {
    format!("byte 0x{b:02X} is not text, and an OBJ file is text (is this one binary?)")
}

/// The words of a line without its comment (from `#` on), each with its
/// 1-based column (counted in bytes: OBJ is ASCII).
pub(super) fn words(line: &[u8]) -> impl Iterator<Item = (usize, &[u8])> {
    let line = match line.iter().position(|&b| b == b'#') {
        Some(comment) => &line[..comment],
        None => line,
    };
    let start = line.as_ptr() as usize;
    (line.split(|b| b.is_ascii_whitespace()))
        .filter(|word| !word.is_empty())
        .map(move |word| (word.as_ptr() as usize - start + 1, word))
}

/// A word as text, for messages: bytes that are not UTF-8 shown as �, and
/// a long word cut after 60 bytes.
pub(super) fn shown(word: &[u8]) -> String {
    const LONGEST: usize = 60;
    match word.get(..LONGEST) {
        Some(start) if word.len() > LONGEST => format!("{}…", String::from_utf8_lossy(start)),
        _ => String::from_utf8_lossy(word).into_owned(),
    }
}

/// A coordinate: a finite number within f32's range.
pub(super) fn number(word: &[u8]) -> Result<f32, String> {
    let text = std::str::from_utf8(word).unwrap_or("");
    let Ok(x) = text.parse::<f32>() else {
        return Err(format!("expected a number, found `{}`", shown(word)));
    };
    if x.is_finite() {
        return Ok(x);
    }
    let named = text.trim_start_matches(['+', '-']).to_ascii_lowercase();
    if ["inf", "infinity", "nan"].contains(&named.as_str()) {
        Err(format!("expected a finite number, found `{text}`"))
    } else {
        Err(format!(
            "{} is too large for the tracer's f32 numbers (largest {:e})",
            shown(word),
            f32::MAX
        ))
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Every line of `bytes`, or the first error with its line and column.
    fn all(bytes: &[u8]) -> Result<Vec<String>, (usize, usize, String)> {
        let mut lines = Lines::new(bytes);
        let mut found = Vec::new();
        loop {
            match lines.next() {
                Ok(true) => found.push(shown(&lines.text)),
                Ok(false) => return Ok(found),
                Err((column, e)) => return Err((lines.number, column, e)),
            }
        }
    }

    #[test]
    fn crlf_and_a_byte_order_mark_are_skipped() {
        let lines = all(b"\xEF\xBB\xBFv 1 2 3\r\nf 1 1 1\r\n\r\nlast").unwrap();
        assert_eq!(lines, ["v 1 2 3", "f 1 1 1", "", "last"]);
    }

    #[test]
    fn a_nul_byte_is_not_text() {
        let (line, column, e) = all(b"v 1 2 3\nv \0\0\n").unwrap_err();
        assert_eq!((line, column), (2, 3));
        assert!(e.contains("byte 0x00 is not text"), "{e}");
    }

    #[test]
    fn a_byte_that_is_not_text_after_the_first_read_is_found_on_its_line() {
        let mut bytes = b"v 1 2 3\n".repeat(10_000);
        bytes.extend(b"v 1 \x01\n");
        let reader = std::io::BufReader::with_capacity(64, &bytes[..]);
        let mut lines = Lines::new(reader);
        while let Ok(true) = lines.next() {}
        assert_eq!(lines.number, 10_001);
    }

    #[test]
    fn a_line_without_end_is_cut_at_the_limit() {
        let long = vec![b'x'; MAX_LINE + 10];
        let (line, _, e) = all(&long).unwrap_err();
        assert_eq!(line, 1);
        assert!(e.contains("longer than 1 MiB"), "{e}");
    }

    #[test]
    fn words_know_their_columns_and_end_at_a_comment() {
        let found: Vec<(usize, String)> = (words(b"f  1/2/3\t4 # 5 6"))
            .map(|(c, w)| (c, shown(w)))
            .collect();
        assert_eq!(
            found,
            [(1, "f".into()), (4, "1/2/3".into()), (10, "4".into())]
        );
    }

    #[test]
    fn numbers_are_finite_f32() {
        assert_eq!(number(b"-1.5e2"), Ok(-150.0));
        assert!(number(b"nan").unwrap_err().contains("finite"));
        assert!(number(b"-inf").unwrap_err().contains("finite"));
        assert!(number(b"1e39").unwrap_err().contains("too large"));
        assert!(number(b"1,5").unwrap_err().contains("expected a number"));
    }
}
