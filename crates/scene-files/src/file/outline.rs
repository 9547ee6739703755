//! The outline of a scene file: where its `[[objects]]` tables are, found
//! without parsing the file.
//!
//! A scene with millions of objects is mostly `[[objects]]` tables. Parsed
//! whole, toml keeps a spanned value of every key of every table at once
//! (about 3 KB per sphere); parsed a batch of tables at a time, only one
//! batch is alive per thread. This module finds the cut points: the lines
//! where a table header starts (a `[` at the start of a line, outside strings,
//! comments and arrays). Each `[[objects]]` table runs from its header to the
//! next header; everything else (the camera, materials, lights, the keys
//! before the first header) is the *head*, parsed on its own.

use std::ops::Range;

/// At most this many `[[objects]]` tables are parsed together: enough to
/// make the cost of starting a parse negligible, few enough that a batch's
/// spanned values (about 3 KB per object) stay in the processor's cache.
/// Parsing a million spheres took 1.8 s of CPU time in batches of 256,
/// 2.1 s in batches of 1024 and 3.1 s in batches of 16384.
pub(super) const BATCH: usize = 256;

/// Where the parts of a scene file are.
#[derive(Debug, Default, PartialEq)]
pub(super) struct Outline {
    /// The text that is not `[[objects]]` tables, as ranges of the file in
    /// order (adjacent ranges merged).
    pub head: Vec<Range<usize>>,
    /// The `[[objects]]` tables, in runs of adjacent tables.
    pub batches: Vec<Batch>,
    /// How many `[[objects]]` tables the file has.
    pub objects: usize,
    /// The file names `objects` in another way as well (a header such as
    /// `[objects.center]`, or an `objects` key before the first header):
    /// only a parse of the whole file can tell what it means.
    pub unusual: bool,
}

/// Adjacent `[[objects]]` tables, parsed together.
#[derive(Debug, Clone, PartialEq)]
pub(super) struct Batch {
    /// Their text in the file, from the first header to the next table.
    pub span: Range<usize>,
    /// The index of the first one among all the file's objects.
    pub first: usize,
}

/// What a line that starts a table says.
#[derive(Debug, Clone, Copy, PartialEq)]
enum Header {
    /// `[[objects]]`: one more object.
    Object,
    /// Any other header, or key, that starts with `objects` (such as
    /// `[objects.center]` or `objects = [...]`).
    OtherObjects,
    /// A header of another table (`[camera]`, `[[lights]]`, ...).
    Other,
}

impl Outline {
    /// Finds the tables of `text`.
    pub fn of(text: &str) -> Outline {
        let mut outline = Outline::default();
        let mut part = (0, Header::Other);
        for (start, header) in headers(text) {
            outline.add(part.0..start, part.1);
            part = (start, header);
        }
        outline.add(part.0..text.len(), part.1);
        outline
    }

    /// Adds the part of the file at `range`, which starts with `header`.
    fn add(&mut self, range: Range<usize>, header: Header) {
        match header {
            Header::Object => self.add_object(range),
            Header::Other => extend(&mut self.head, range),
            Header::OtherObjects => {
                self.unusual = true;
                extend(&mut self.head, range);
            }
        }
    }

    /// Adds one `[[objects]]` table to the last batch if it follows it and
    /// has room, else to a new batch.
    fn add_object(&mut self, range: Range<usize>) {
        let first = self.objects;
        self.objects += 1;
        match self.batches.last_mut() {
            Some(batch) if batch.span.end == range.start && first - batch.first < BATCH => {
                batch.span.end = range.end;
            }
            _ => self.batches.push(Batch { span: range, first }),
        }
    }
}

/// Adds `range` to `ranges`, merged with the last one if they touch.
fn extend(ranges: &mut Vec<Range<usize>>, range: Range<usize>) {
    match ranges.last_mut() {
        Some(last) if last.end == range.start => last.end = range.end,
        _ if range.is_empty() => {}
        _ => ranges.push(range),
    }
}

/// The start of every line that begins a table, with what the table is; and
/// the start of every line before the first table whose key is `objects`.
///
/// A TOML value never starts a line, so a `[` that is the first thing on a
/// line, outside strings, comments and open arrays or inline tables, starts
/// a header. Text that is not TOML may be cut in odd places: the parser of
/// each part then finds the mistake.
fn headers(text: &str) -> Vec<(usize, Header)> {
    let bytes = text.as_bytes();
    let mut found = Vec::new();
    // Open `[` and `{` of values.
    let mut depth = 0usize;
    let mut line_start = 0;
    while line_start < bytes.len() {
        let mut i = bytes.len() - skip_blanks(&bytes[line_start..]).len();
        if depth == 0 && i < bytes.len() {
            let header = if bytes[i] == b'[' {
                Some(header(&bytes[i..]))
            } else if found.is_empty() && first_key_is_objects(&bytes[i..]) {
                Some(Header::OtherObjects)
            } else {
                None
            };
            found.extend(header.map(|h| (line_start, h)));
        }
        // The rest of the line, from one byte that matters to the next.
        loop {
            let Some(n) = bytes[i..].iter().position(|&b| MATTERS[b as usize]) else {
                return found;
            };
            i += n;
            i = match bytes[i] {
                b'\n' => break,
                b'#' => line_end(bytes, i),
                b'"' | b'\'' => string_end(bytes, i),
                b'[' | b'{' => {
                    depth += 1;
                    i + 1
                }
                _ => {
                    depth = depth.saturating_sub(1);
                    i + 1
                }
            };
        }
        line_start = i + 1;
    }
    found
}

/// The bytes that change what follows: a newline, a comment, a string, or
/// an array or inline table opening or closing.
const MATTERS: [bool; 256] = {
    let (set, mut matters) = (b"\n#\"'[]{}", [false; 256]);
    let mut i = 0;
    while i < set.len() {
        matters[set[i] as usize] = true;
        i += 1;
    }
    matters
};

/// What the header at the start of `line` (which starts with `[`) is.
fn header(line: &[u8]) -> Header {
    let array = line.starts_with(b"[[");
    let key = skip_blanks(&line[if array { 2 } else { 1 }..]);
    if !first_key_is_objects(key) {
        return Header::Other;
    }
    let after = skip_blanks(&key[first_key_len(key)..]);
    if array && after.starts_with(b"]]") {
        Header::Object
    } else {
        Header::OtherObjects
    }
}

/// Does the dotted key at the start of `key` (after blanks) begin with
/// `objects` (bare or quoted)?
fn first_key_is_objects(key: &[u8]) -> bool {
    let key = skip_blanks(key);
    let len = first_key_len(key);
    let name = match key.first() {
        Some(b'"' | b'\'') if len >= 2 => &key[1..len - 1],
        _ => &key[..len],
    };
    name == b"objects"
}

/// The length of the first key of a dotted key: a bare key, or a quoted one
/// with its quotes.
fn first_key_len(key: &[u8]) -> usize {
    match key.first() {
        Some(&quote @ (b'"' | b'\'')) => key[1..]
            .iter()
            .position(|&b| b == quote || b == b'\n')
            .map_or(key.len(), |end| end + 2),
        _ => key
            .iter()
            .position(|&b| !(b.is_ascii_alphanumeric() || b == b'_' || b == b'-'))
            .unwrap_or(key.len()),
    }
}

fn skip_blanks(text: &[u8]) -> &[u8] {
    let blanks = text.iter().take_while(|&&b| b == b' ' || b == b'\t');
    &text[blanks.count()..]
}

/// The index of the newline that ends the line at `i` (or the text's end).
fn line_end(bytes: &[u8], i: usize) -> usize {
    bytes[i..]
        .iter()
        .position(|&b| b == b'\n')
        .map_or(bytes.len(), |n| i + n)
}

/// The index just past the string that starts at `i`: basic (`"`, with
/// backslash escapes) or literal (`'`), on one line or multi-line (`"""`,
/// `'''`). A one-line string that is not closed ends at the newline.
fn string_end(bytes: &[u8], i: usize) -> usize {
    let quote = bytes[i];
    let multi_line = bytes[i..].starts_with(&[quote; 3]);
    let mut j = if multi_line { i + 3 } else { i + 1 };
    while j < bytes.len() {
        match bytes[j] {
            b'\\' if quote == b'"' => j += 2,
            b'\n' if !multi_line => return j,
            b if b == quote && (!multi_line || bytes[j..].starts_with(&[quote; 3])) => {
                return j + if multi_line { 3 } else { 1 };
            }
            _ => j += 1,
        }
    }
    bytes.len()
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The head's text and each batch's text.
    fn parts(text: &str) -> (String, Vec<&str>) {
        let outline = Outline::of(text);
        let head = outline.head.iter().map(|r| &text[r.clone()]).collect();
        let batches = outline.batches.iter().map(|b| &text[b.span.clone()]);
        (head, batches.collect())
    }

    #[test]
    fn objects_are_cut_from_the_head() {
        let text = "a = 1\n[camera]\nx = 2\n[[objects]]\nr = 1\n\n[[ objects ]]\nr = 2\n\
                    [[lights]]\nl = 3\n[[objects]]\nr = 3\n";
        let outline = Outline::of(text);
        assert_eq!(outline.objects, 3);
        assert!(!outline.unusual);
        let (head, batches) = parts(text);
        assert_eq!(head, "a = 1\n[camera]\nx = 2\n[[lights]]\nl = 3\n");
        assert_eq!(
            batches,
            [
                "[[objects]]\nr = 1\n\n[[ objects ]]\nr = 2\n",
                "[[objects]]\nr = 3\n"
            ]
        );
        let firsts: Vec<usize> = outline.batches.iter().map(|b| b.first).collect();
        assert_eq!(firsts, [0, 2]);
    }

    #[test]
    fn headers_inside_strings_arrays_and_comments_are_text() {
        let text = "[camera]\nnote = \"\"\"\n[[objects]]\n\"\"\"\nraw = '''\n[[objects]]'''\n\
                    v = [\n  [1, 2],\n[3]\n]\n# [[objects]]\ns = \"[\"\n[[objects]]\nr = 1\n";
        let outline = Outline::of(text);
        assert_eq!(outline.objects, 1);
        let (head, batches) = parts(text);
        assert_eq!(head, &text[..text.find("[[objects]]\nr").unwrap()]);
        assert_eq!(batches, ["[[objects]]\nr = 1\n"]);
    }

    #[test]
    fn escaped_quotes_do_not_end_a_string() {
        let text = "[camera]\ns = \"a\\\"[[objects]]\"\n[[objects]]\n";
        assert_eq!(Outline::of(text).objects, 1);
    }

    #[test]
    fn batches_hold_at_most_batch_objects() {
        let text = "[[objects]]\n".repeat(BATCH + 1);
        let outline = Outline::of(&text);
        let firsts: Vec<usize> = outline.batches.iter().map(|b| b.first).collect();
        assert_eq!(firsts, [0, BATCH]);
        assert!(outline.head.is_empty());
    }

    #[test]
    fn other_ways_to_name_objects_are_unusual() {
        for text in [
            "[[objects]]\n[objects.center]\n",
            "[[objects.x]]\n",
            "['objects']\n",
            "objects = []\n[camera]\n",
            "objects.x = 1\n",
        ] {
            assert!(Outline::of(text).unusual, "{text:?}");
        }
        for text in ["[objectsx]\n", "objects_x = 1\n", "[camera]\nobjects = 1\n"] {
            assert!(!Outline::of(text).unusual, "{text:?}");
        }
    }

    #[test]
    fn quoted_objects_is_objects() {
        let outline = Outline::of("[[\"objects\"]]\n[[ 'objects' ]]\n");
        assert_eq!(outline.objects, 2);
    }
}
