//! Nothing panics on any input: mutated scene files, TOML and NFF, are either
//! refused with an error or rendered.

mod common;

use proptest::prelude::*;
use raybook::render;
use raybook::scene_files::{self, SceneError};
use raybook::toolkit::Scene;
use raybook::workbench::snapshot::workspace_root;

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

/// The small SPD scenes (NFF) of the repository, as mutation seeds.
fn nff_seeds() -> Vec<String> {
    ["balls-1.nff", "balls-2.nff", "mount-3.nff", "tetra-3.nff"]
        .map(|name| std::fs::read_to_string(workspace_root().join("scenes/spd").join(name)))
        .map(Result::unwrap)
        .to_vec()
}

/// NFF's tokens that are likely to break something.
const NFF_TOKENS: &[&str] = &[
    "nan",
    "inf",
    "-1",
    "0",
    "0 0 0",
    "1e39",
    "1e-45",
    "16385",
    "3.5",
    "\n",
    "#",
    "é",
    "\u{0}",
    "\nv\n",
    "\np 3\n",
    "\npp 3\n",
    "\ns 0 0 0 1\n",
    "\nf 1 1 1 1 0 1 0 1\n",
    "\nl 1 1 1\n",
    "\nc\n",
    "\nresolution 1 1\n",
    "\nangle 179.99999\n",
    "\nup 0 0 0\n",
];

fn apply(text: &str, m: &Mutation) -> String {
    apply_with(text, m, TOKENS)
}

fn apply_with(text: &str, m: &Mutation, tokens: &[&str]) -> String {
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
                tokens[token % tokens.len()],
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
                tokens[token % tokens.len()],
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
        check(scene_files::parse(&text, "fuzz.toml"), "fuzz.toml")?;
    }
}

/// What a parser made of a mutated scene: rendered small, or refused well.
fn check(parsed: Result<Scene, SceneError>, file: &str) -> Result<(), TestCaseError> {
    match parsed {
        Ok(scene) => {
            // What parses must render, without a panic, to finite values.
            let (image, _) = render(&scene.with_size(8, 6), || {});
            prop_assert!(image.pixels.iter().all(|c| c.is_finite()));
        }
        Err(e) => {
            prop_assert_eq!(e.file.as_str(), file);
            prop_assert!(!e.message.is_empty());
        }
    }
    Ok(())
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(1000))]

    #[test]
    fn mutated_nff_scenes_never_panic(
        seed in any::<usize>(),
        mutations in prop::collection::vec(mutation(), 1..4),
    ) {
        let seeds = nff_seeds();
        let mut text = seeds[seed % seeds.len()].clone();
        for m in &mutations {
            text = apply_with(&text, m, NFF_TOKENS);
        }
        check(raybook::nff::parse(&text, "fuzz.nff"), "fuzz.nff")?;
    }
}

#[test]
fn a_mutation_the_fuzzer_found_is_refused_without_a_panic() {
    // Found by `mutated_scenes_never_panic`: the error's span was mapped
    // through a checker with no pieces of text at all.
    let seeds = seeds();
    let text = &seeds[11_772_836_615_416_564_769 % seeds.len()];
    let mutation = Mutation::Replace(
        681_774_403_322_263_074,
        11_600_873_228_271_460_993,
        11_735_463_111_148_212_227,
    );
    let text = apply(text, &mutation);
    check(scene_files::parse(&text, "fuzz.toml"), "fuzz.toml").unwrap();
}
