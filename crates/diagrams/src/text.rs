//! The text of the diagrams' labels: numbers as the chapters print them,
//! and the lecture's notation (`d_i`, `t_max`) set with subscripts.

use std::fmt::Write;

use crate::svg::{MIN_FONT, n};

/// A number as the chapters print it: `decimals` places, trailing zeros
/// dropped, and a true minus sign (−1.5, not -1.5).
pub fn number(x: f64, decimals: usize) -> String {
    let text = format!("{x:.decimals$}");
    let text = if text.contains('.') {
        text.trim_end_matches('0').trim_end_matches('.').to_owned()
    } else {
        text
    };
    match text.strip_prefix('-') {
        Some(positive) if positive.chars().any(|c| c != '0' && c != '.') => {
            format!("\u{2212}{positive}")
        }
        Some(positive) => positive.to_owned(),
        None => text,
    }
}

/// A number to exactly `decimals` places, as the chapters print a measured
/// value (0.580, not 0.58), with a true minus sign.
pub fn fixed(x: f64, decimals: usize) -> String {
    let text = format!("{x:.decimals$}");
    match text.strip_prefix('-') {
        Some(positive) if positive.chars().any(|c| c != '0' && c != '.') => {
            format!("\u{2212}{positive}")
        }
        Some(positive) => positive.to_owned(),
        None => text,
    }
}

/// Escapes the characters XML gives a meaning to.
pub fn escape(text: &str) -> String {
    text.replace('&', "&amp;")
        .replace('<', "&lt;")
        .replace('>', "&gt;")
        .replace('"', "&quot;")
}

/// A label in the lecture's notation as SVG text: after a one-letter name,
/// `_` starts a subscript that runs to the end of the word (`d_i`, `t_max`,
/// `θ_c`, `p_L`); a longer word keeps its underscore (`half_width`).
pub fn rich(label: &str, size: f64) -> String {
    let sub = MIN_FONT.max((size * 0.8).round());
    let shift = n((size * 0.3).round());
    let mut out = String::new();
    let mut lowered = false;
    for (text, subscript) in segments(label) {
        if subscript {
            let _ = write!(
                out,
                "<tspan dy=\"{shift}\" font-size=\"{}\">{}</tspan>",
                n(sub),
                escape(&text)
            );
            lowered = true;
        } else if lowered {
            let _ = write!(out, "<tspan dy=\"-{shift}\">{}</tspan>", escape(&text));
            lowered = false;
        } else {
            out.push_str(&escape(&text));
        }
    }
    out
}

/// The label as a reader sees it, without the markers of its subscripts:
/// `d_i·n` reads `di·n`. It is what the SVG's text says once its tags are
/// taken out.
pub fn plain(label: &str) -> String {
    segments(label).into_iter().map(|(text, _)| text).collect()
}

/// The label cut into plain text and subscripts (true), in order.
fn segments(label: &str) -> Vec<(String, bool)> {
    let chars: Vec<char> = label.chars().collect();
    let mut parts = vec![(String::new(), false)];
    let mut i = 0;
    while i < chars.len() {
        let one_letter =
            i >= 1 && chars[i - 1].is_alphabetic() && (i < 2 || !chars[i - 2].is_alphanumeric());
        let word = chars[i + 1..]
            .iter()
            .take_while(|c| c.is_alphanumeric())
            .count();
        if chars[i] == '_' && one_letter && word > 0 {
            parts.push((chars[i + 1..i + 1 + word].iter().collect(), true));
            parts.push((String::new(), false));
            i += 1 + word;
        } else {
            parts.last_mut().expect("never empty").0.push(chars[i]);
            i += 1;
        }
    }
    parts.retain(|(text, _)| !text.is_empty());
    parts
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn numbers_use_a_true_minus_and_drop_trailing_zeros() {
        assert_eq!(number(-1.5, 2), "\u{2212}1.5");
        assert_eq!(number(41.8103, 2), "41.81");
        assert_eq!(number(2.0, 3), "2");
        assert_eq!(number(-0.0001, 2), "0");
    }

    #[test]
    fn a_one_letter_name_takes_a_subscript_a_word_does_not() {
        let set = rich("d_i·n", 15.0);
        assert!(set.starts_with("d<tspan dy=\"5\""), "{set}");
        assert!(set.contains(">i</tspan>"), "{set}");
        assert_eq!(rich("half_width", 15.0), "half_width");
        let two = rich("d_o = d_i", 15.0);
        assert_eq!(two.matches("font-size").count(), 2, "{two}");
    }
}
