//! Markdown tables, as the measuring tools print them: aligned for reading
//! in a terminal, and ready to paste into a README, where the numbers'
//! columns stay right-aligned (`---:`).

use tabled::builder::Builder;
use tabled::grid::config::Offset;
use tabled::settings::object::{Columns, Object, Rows};
use tabled::settings::style::LineChar;
use tabled::settings::{Alignment, Style};

/// A Markdown table of `header` over `rows`. The first `text_columns`
/// columns (names) are left-aligned; the others (numbers) right-aligned.
pub fn markdown<H: Into<String>, R: IntoIterator<Item = String>>(
    header: impl IntoIterator<Item = H>,
    rows: impl IntoIterator<Item = R>,
    text_columns: usize,
) -> String {
    let mut builder = Builder::new();
    builder.push_record(header.into_iter().map(Into::into));
    for row in rows {
        builder.push_record(row);
    }
    let mut table = builder.build();
    let numbers = Columns::new(text_columns..);
    table
        .with(Style::markdown())
        .modify(numbers.clone(), Alignment::right())
        // The line under the header is the one above the first row.
        .modify(
            Rows::one(1).intersect(numbers),
            LineChar::horizontal(':', Offset::End(0)),
        );
    table.to_string()
}

#[cfg(test)]
mod tests {
    use super::markdown;

    #[test]
    fn numbers_are_right_aligned_in_the_text_and_in_markdown() {
        let rows = [
            ["a".to_owned(), "1".to_owned()],
            ["bcd".to_owned(), "100".to_owned()],
        ];
        assert_eq!(
            markdown(["name", "n"], rows, 1),
            "| name |   n |\n\
             |------|----:|\n\
             | a    |   1 |\n\
             | bcd  | 100 |"
        );
    }

    #[test]
    fn a_table_without_rows_is_its_header() {
        let table = markdown(["name", "n"], Vec::<[String; 2]>::new(), 1);
        assert!(table.starts_with("| name | n |"), "{table}");
    }
}
