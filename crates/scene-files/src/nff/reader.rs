//! NFF's lines: one entity per line, numbers separated by white space, `#`
//! starts a comment. The reader hands out the lines with their words and
//! makes errors that name the file, the line and the column.

use std::ops::RangeInclusive;

use crate::SceneError;

/// One line of the file, cut into words.
#[derive(Debug, Clone)]
pub(super) struct Line<'a> {
    /// 1-based.
    pub number: usize,
    /// The line without its comment.
    pub text: &'a str,
    /// Each word with its 1-based column (in characters).
    pub words: Vec<(usize, &'a str)>,
}

impl<'a> Line<'a> {
    pub fn new(number: usize, text: &'a str) -> Line<'a> {
        let text = text.split('#').next().unwrap_or("");
        let words = (text.split_whitespace())
            .map(|word| {
                let start = word.as_ptr() as usize - text.as_ptr() as usize;
                (text[..start].chars().count() + 1, word)
            })
            .collect();
        Line {
            number,
            text,
            words,
        }
    }

    /// The first word, which names the entity or the viewpoint's field.
    pub fn keyword(&self) -> &'a str {
        self.words.first().map_or("", |w| w.1)
    }

    /// The column of word `i` (0 is the keyword), or just past the line's end.
    pub fn column(&self, i: usize) -> usize {
        (self.words.get(i)).map_or(self.text.chars().count() + 1, |w| w.0)
    }
}

/// The lines still to read, and the file's name for errors.
pub(super) struct Reader<'a> {
    file: &'a str,
    lines: Vec<Line<'a>>,
    next: usize,
}

impl<'a> Reader<'a> {
    /// The lines of `text` that say something: not blank, not comments.
    pub fn new(text: &'a str, file: &'a str) -> Reader<'a> {
        let lines = (text.lines().enumerate())
            .filter(|(_, l)| !l.trim().is_empty() && !l.trim_start().starts_with('#'))
            .map(|(i, l)| Line::new(i + 1, l))
            .collect();
        Reader {
            file,
            lines,
            next: 0,
        }
    }

    pub fn next_line(&mut self) -> Option<Line<'a>> {
        let line = self.lines.get(self.next).cloned();
        self.next += 1;
        line
    }

    /// How many lines that say something are still to read.
    pub fn lines_left(&self) -> usize {
        self.lines.len().saturating_sub(self.next)
    }

    /// The next line, which `what` needs.
    pub fn expect_line(&mut self, after: &Line, what: &str) -> Result<Line<'a>, SceneError> {
        self.next_line()
            .ok_or_else(|| self.error(after, 1, format!("the file ends, but {what} is missing")))
    }

    /// An empty line in place of the last one, for errors about the whole file.
    pub fn end(&self) -> Line<'a> {
        Line::new(self.lines.last().map_or(1, |l| l.number), "")
    }

    /// An error at a column of a line.
    pub fn error(&self, line: &Line, column: usize, message: impl Into<String>) -> SceneError {
        SceneError {
            file: self.file.to_owned(),
            line: Some(line.number as u32),
            column: Some(column as u32),
            path: String::new(),
            message: message.into(),
            source_line: Some(line.text.to_owned()),
        }
    }

    /// The `count` numbers after the keyword of `line` (exactly that many).
    pub fn numbers(&self, line: &Line, count: usize, form: &str) -> Result<Vec<f32>, SceneError> {
        self.numbers_from(line, 1, count..=count, form)
    }

    /// The numbers of `line` from word `skip` on, how many `counts` allows.
    pub fn numbers_from(
        &self,
        line: &Line,
        skip: usize,
        counts: RangeInclusive<usize>,
        form: &str,
    ) -> Result<Vec<f32>, SceneError> {
        let words = &line.words[skip.min(line.words.len())..];
        if !counts.contains(&words.len()) {
            return Err(self.error(
                line,
                line.column(skip),
                format!("expected `{form}`, found {} numbers", words.len()),
            ));
        }
        (words.iter())
            .map(|&(column, word)| match word.parse::<f32>() {
                Ok(x) if x.is_finite() => Ok(x),
                _ => Err(self.error(
                    line,
                    column,
                    format!("expected a finite number in `{form}`, found `{word}`"),
                )),
            })
            .collect()
    }
}
