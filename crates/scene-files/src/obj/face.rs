//! A face's corners: `v`, `v/vt`, `v/vt/vn` or `v//vn`, each index counted
//! from 1 (the first vertex of the file) or, when negative, back from the
//! face's line (-1 is the vertex just above it). A face names only what
//! lines above it define: the file is read in one pass, and a reader that
//! accepted later vertices would have to keep every face until the end.

use super::lines::shown;

/// How many vertices, texture coordinates and normals come before a face.
pub(super) struct Counts {
    pub positions: usize,
    pub texcoords: usize,
    pub normals: usize,
}

/// A corner of a face: its vertex and its normal, if it has one, as
/// 0-based indices into the lists read so far.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(super) struct Corner {
    pub position: usize,
    pub normal: Option<usize>,
}

/// The corner that `word` of an `f` line names.
pub(super) fn corner(word: &[u8], counts: &Counts) -> Result<Corner, String> {
    let mut parts = word.split(|&b| b == b'/');
    let (v, vt, vn) = (parts.next(), parts.next(), parts.next());
    if parts.next().is_some() || v.is_none_or(<[u8]>::is_empty) {
        return Err(format!(
            "a face's corner is v, v/vt, v/vt/vn or v//vn (indices of lines above it); \
             found `{}`",
            shown(word)
        ));
    }
    let position = index(v.unwrap_or_default(), counts.positions, "vertex", "v")?;
    if let Some(vt) = vt.filter(|vt| !vt.is_empty()) {
        index(vt, counts.texcoords, "texture coordinate", "vt")?;
    }
    let normal = match vn {
        Some(vn) => Some(index(vn, counts.normals, "normal", "vn")?),
        None => None,
    };
    Ok(Corner { position, normal })
}

/// The 0-based index of the `what` (`v`, `vt` or `vn` lines) that `word`
/// names, `count` of them coming before the face.
fn index(word: &[u8], count: usize, what: &str, lines: &str) -> Result<usize, String> {
    let Some(i) = whole_number(word) else {
        return Err(format!(
            "expected the index of a {what} ({lines} line), found `{}`",
            shown(word)
        ));
    };
    let above = || format!("the file has {count} {lines} lines above this face");
    match i {
        0 => Err(format!(
            "{what} 0 names none: OBJ counts {lines} lines from 1 (or back from -1)"
        )),
        1.. if i as u64 <= count as u64 => Ok(i as usize - 1),
        1.. => Err(format!(
            "the face names {what} {i}, but {} (a face names only {lines} lines above it)",
            above()
        )),
        _ if i.unsigned_abs() <= count as u64 => Ok(count - i.unsigned_abs() as usize),
        _ => Err(format!(
            "the face names {what} {i}, {} back, but {}",
            i.unsigned_abs(),
            above()
        )),
    }
}

/// `word` as a whole number (a sign, then digits), if it is one that i64
/// holds. Faces are most of a mesh's lines, and this takes a fifth of the
/// time that `str::parse` takes.
fn whole_number(word: &[u8]) -> Option<i64> {
    let (negative, digits) = match word.split_first() {
        Some((b'-', digits)) => (true, digits),
        Some((b'+', digits)) => (false, digits),
        _ => (false, word),
    };
    if digits.is_empty() {
        return None;
    }
    let mut n: i64 = 0;
    for &digit in digits {
        let digit = digit.wrapping_sub(b'0');
        if digit > 9 {
            return None;
        }
        n = n.checked_mul(10)?.checked_add(i64::from(digit))?;
    }
    Some(if negative { -n } else { n })
}

#[cfg(test)]
mod tests {
    use super::*;

    const COUNTS: Counts = Counts {
        positions: 4,
        texcoords: 2,
        normals: 3,
    };

    fn at(word: &str) -> Result<Corner, String> {
        corner(word.as_bytes(), &COUNTS)
    }

    fn ok(position: usize, normal: Option<usize>) -> Result<Corner, String> {
        Ok(Corner { position, normal })
    }

    #[test]
    fn every_form_of_corner_is_read() {
        assert_eq!(at("1"), ok(0, None));
        assert_eq!(at("4/2"), ok(3, None));
        assert_eq!(at("2/1/3"), ok(1, Some(2)));
        assert_eq!(at("3//1"), ok(2, Some(0)));
    }

    #[test]
    fn negative_indices_count_back_from_the_face() {
        assert_eq!(at("-1"), ok(3, None));
        assert_eq!(at("-4//-3"), ok(0, Some(0)));
        assert_eq!(at("-1/-2/-1"), ok(3, Some(2)));
    }

    #[test]
    fn indices_of_lines_that_are_not_above_are_refused() {
        let e = at("5").unwrap_err();
        assert!(
            e.contains("names vertex 5, but the file has 4 v lines above"),
            "{e}"
        );
        assert!(at("-5").unwrap_err().contains("5 back"));
        assert!(at("1/3").unwrap_err().contains("texture coordinate 3"));
        assert!(at("1//4").unwrap_err().contains("normal 4"));
        assert!(at("0").unwrap_err().contains("from 1"));
        let huge = at("-9223372036854775807").unwrap_err();
        assert!(huge.contains("back"), "{huge}");
        let beyond = at("9223372036854775808").unwrap_err();
        assert!(
            beyond.contains("expected the index of a vertex"),
            "{beyond}"
        );
    }

    #[test]
    fn malformed_corners_are_refused() {
        for word in [
            "", "/1", "1/2/3/4", "x", "1/y", "1//", "1.5", "-", "+", "1-2",
        ] {
            assert!(at(word).is_err(), "{word:?}");
        }
    }
}
