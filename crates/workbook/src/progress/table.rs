//! The table as results come: each chapter's row as soon as its tests end.
//!
//! On a terminal the whole table is drawn again in place at each change
//! (rows waiting for their tests say so). Into a pipe or a file, the header
//! comes first and then each row once, as its chapter finishes, so that a
//! script or an editor sees the edited chapter's verdict first.

use std::io::{IsTerminal, Write};
use std::path::{Path, PathBuf};

use super::report::{ChapterResult, header, here, next_step, row_line, waiting_line};
use crate::workbench::chapters::ChapterEntry;

/// A row: waiting for its tests, running them, or done.
enum Row {
    Waiting(&'static ChapterEntry),
    Running(&'static ChapterEntry),
    Done(ChapterResult),
}

pub struct Table {
    rows: Vec<Row>,
    root: PathBuf,
    /// Drawn again in place (a terminal), or printed a row at a time.
    in_place: bool,
    /// Printed at all (`progress`), or only kept (the lab's call).
    printed: bool,
    /// Lines drawn last time, to go back over.
    drawn: usize,
}

impl Table {
    /// A table of `chapters`, none of them tested yet, printed as it
    /// fills if `printed` (else only kept, for [`Table::results`]).
    pub fn new(chapters: &[&'static ChapterEntry], root: &Path, printed: bool) -> Table {
        let in_place = printed && std::io::stdout().is_terminal();
        let table = Table {
            rows: chapters.iter().map(|c| Row::Waiting(c)).collect(),
            root: root.to_owned(),
            in_place,
            printed,
            drawn: 0,
        };
        if printed && !in_place {
            println!("{}", header());
        }
        table
    }

    /// Did a chapter before row `i` fail?
    pub fn fails_before(&self, i: usize) -> bool {
        self.rows[..i].iter().any(|row| match row {
            Row::Done(result) => result.output.as_ref().is_some_and(|o| !o.passed_all()),
            _ => false,
        })
    }

    /// Row `i` starts its tests.
    pub fn running(&mut self, i: usize) {
        if let Row::Waiting(chapter) = self.rows[i] {
            self.rows[i] = Row::Running(chapter);
        }
        self.draw();
    }

    /// Row `i` is done: shown now.
    pub fn done(&mut self, i: usize, result: ChapterResult) {
        self.rows[i] = Row::Done(result);
        if self.in_place {
            self.draw();
        } else if self.printed {
            let marker = !self.passes(i) && !self.fails_before(i);
            let Row::Done(result) = &self.rows[i] else {
                unreachable!()
            };
            println!("{}", row_line(result, marker, &self.root));
            let _ = std::io::stdout().flush();
        }
    }

    fn passes(&self, i: usize) -> bool {
        match &self.rows[i] {
            Row::Done(result) => result.output.as_ref().is_none_or(|o| o.passed_all()),
            _ => true,
        }
    }

    /// The rows done, in order.
    pub fn results(self) -> Vec<ChapterResult> {
        (self.rows.into_iter())
            .filter_map(|row| match row {
                Row::Done(result) => Some(result),
                _ => None,
            })
            .collect()
    }

    /// The rows, all done, and the advice; true if every chapter run passed.
    pub fn finish(mut self) -> bool {
        self.draw();
        let root = self.root.clone();
        let results = self.results();
        let here = here(&results);
        println!("\n{}", next_step(&results, here, &root));
        here.is_none()
    }

    /// Draws the whole table again over the last one (a terminal only).
    fn draw(&mut self) {
        if !self.in_place {
            return;
        }
        let results: Vec<&ChapterResult> = (self.rows.iter())
            .filter_map(|row| match row {
                Row::Done(result) => Some(result),
                _ => None,
            })
            .collect();
        let first_failing = results
            .iter()
            .find(|r| r.output.as_ref().is_some_and(|o| !o.passed_all()))
            .map(|r| r.chapter.folder.clone());
        let mut lines = vec![header()];
        for row in &self.rows {
            lines.push(match row {
                Row::Waiting(chapter) => waiting_line(chapter, false),
                Row::Running(chapter) => waiting_line(chapter, true),
                Row::Done(r) => {
                    let here = first_failing.as_deref() == Some(r.chapter.folder.as_str());
                    row_line(r, here, &self.root)
                }
            });
        }
        let mut out = std::io::stdout().lock();
        if self.drawn > 0 {
            // Back to the table's first line, and clear what follows.
            let _ = write!(out, "\x1b[{}F\x1b[J", self.drawn);
        }
        let _ = writeln!(out, "{}", lines.join("\n"));
        let _ = out.flush();
        self.drawn = lines.len();
    }
}
