//! Nothing panics on any input: mutated scene files are either refused with
//! an error or rendered.

mod common;

use proptest::prelude::*;
use raybook::render;
use raybook::toolkit::Scene;

/// Every scene file of the repository, as mutation seeds.
fn seeds() -> Vec<String> {
    (common::chapter_scene_files().iter())
        .map(|path| std::fs::read_to_string(path).unwrap())
        .collect()
}

/// Tokens that are likely to break something when dropped into a scene.
const TOKENS: &[&str] = &[
    "nan",
    "inf",
    "-inf",
    "-1",
    "0",
    "0.0",
    "1e39",
    "1e-45",
    "16385",
    "[",
    "]",
    "\"",
    "=",
    ",",
    "\n",
    "[[objects]]",
    "type = \"sphere\"",
    "[0, 0, 0]",
    "[1, 2]",
    "[1, 2, 3, 4]",
    "material = \"nope\"",
    "true",
    "#",
    "{",
    "}",
    ".",
    "é",
    "\u{0}",
];

#[derive(Debug, Clone)]
enum Mutation {
    Insert(usize, usize),
    Delete(usize, usize),
    Replace(usize, usize, usize),
}

fn apply(text: &str, m: &Mutation) -> String {
    let cut = |i: usize| {
        let mut i = i % (text.len() + 1);
        while !text.is_char_boundary(i) {
            i -= 1;
        }
        i
    };
    match *m {
        Mutation::Insert(at, token) => {
            let at = cut(at);
            format!(
                "{}{}{}",
                &text[..at],
                TOKENS[token % TOKENS.len()],
                &text[at..]
            )
        }
        Mutation::Delete(at, len) => {
            let (a, b) = (cut(at), cut(at.saturating_add(len % 40)));
            let (a, b) = (a.min(b), a.max(b));
            format!("{}{}", &text[..a], &text[b..])
        }
        Mutation::Replace(at, len, token) => {
            let (a, b) = (cut(at), cut(at.saturating_add(len % 8)));
            let (a, b) = (a.min(b), a.max(b));
            format!(
                "{}{}{}",
                &text[..a],
                TOKENS[token % TOKENS.len()],
                &text[b..]
            )
        }
    }
}

fn mutation() -> impl Strategy<Value = Mutation> {
    prop_oneof![
        (any::<usize>(), any::<usize>()).prop_map(|(a, t)| Mutation::Insert(a, t)),
        (any::<usize>(), any::<usize>()).prop_map(|(a, l)| Mutation::Delete(a, l)),
        (any::<usize>(), any::<usize>(), any::<usize>())
            .prop_map(|(a, l, t)| Mutation::Replace(a, l, t)),
    ]
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(2000))]

    #[test]
    fn mutated_scenes_never_panic(
        seed in any::<usize>(),
        mutations in prop::collection::vec(mutation(), 1..4),
    ) {
        let seeds = seeds();
        let mut text = seeds[seed % seeds.len()].clone();
        for m in &mutations {
            text = apply(&text, m);
        }
        match Scene::parse(&text, "fuzz.toml") {
            Ok(scene) => {
                // What parses must render, without a panic, to finite values.
                let (image, _) = render(&scene.with_size(8, 6), || {});
                prop_assert!(image.pixels.iter().all(|c| c.is_finite()));
            }
            Err(e) => {
                prop_assert_eq!(e.file.as_str(), "fuzz.toml");
                prop_assert!(!e.message.is_empty());
            }
        }
    }
}
