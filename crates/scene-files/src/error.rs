//! Errors in scene files: file, line, field path, what is wrong, what is valid.

use std::fmt;
use std::ops::Range;

/// A scene file that cannot be used, and where exactly.
#[derive(Debug, Clone, PartialEq)]
pub struct SceneError {
    /// The file as the user named it.
    pub file: String,
    /// 1-based line and column, when the problem has a place in the text.
    pub line: Option<u32>,
    pub column: Option<u32>,
    /// Field path such as `objects[3].radius`; empty for the whole file.
    pub path: String,
    /// What is wrong and what would be valid.
    pub message: String,
    /// The offending source line, for display.
    pub source_line: Option<String>,
}

impl SceneError {
    /// An error at a place in the text.
    pub(crate) fn at(
        file: &str,
        text: &str,
        span: Option<Range<usize>>,
        path: &str,
        message: impl Into<String>,
    ) -> SceneError {
        let (line, column, source_line) = match span {
            Some(span) => {
                let (line, column) = line_and_column(text, span.start);
                let source_line = text.lines().nth(line as usize - 1).map(str::to_owned);
                (Some(line), Some(column), source_line)
            }
            None => (None, None, None),
        };
        SceneError {
            file: file.to_owned(),
            line,
            column,
            path: path.to_owned(),
            message: message.into(),
            source_line,
        }
    }

    /// A file that cannot be read at all, and why.
    pub(crate) fn unreadable(file: &str, why: impl fmt::Display) -> SceneError {
        SceneError::at(
            file,
            "",
            None,
            "",
            format!("cannot read the scene file: {why}"),
        )
    }

    /// The error as shown, without the source line under it:
    /// `file:line:column: path: message`. An error in a file that a scene
    /// names (an OBJ mesh) becomes the message of the scene's error so.
    pub fn headline(&self) -> String {
        let mut headline = self.file.clone();
        if let (Some(line), Some(column)) = (self.line, self.column) {
            headline += &format!(":{line}:{column}");
        }
        if !self.path.is_empty() {
            headline += &format!(": {}", self.path);
        }
        headline + ": " + &self.message
    }
}

/// 1-based line and column (in characters) of a byte offset.
fn line_and_column(text: &str, offset: usize) -> (u32, u32) {
    let offset = offset.min(text.len());
    let before = text.get(..offset).unwrap_or(text);
    let line = before.matches('\n').count() + 1;
    let line_start = before.rfind('\n').map_or(0, |i| i + 1);
    let column = before[line_start..].chars().count() + 1;
    (line as u32, column as u32)
}

impl fmt::Display for SceneError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "{}", self.headline())?;
        if let (Some(line), Some(column), Some(text)) = (self.line, self.column, &self.source_line)
        {
            let gutter = line.to_string().len();
            let column = column as usize;
            write!(
                f,
                "\n{:gutter$} |\n{line} | {text}\n{:gutter$} | {:>column$}",
                "", "", "^"
            )?;
        }
        Ok(())
    }
}

impl std::error::Error for SceneError {}
