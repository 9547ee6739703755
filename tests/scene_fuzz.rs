//! Nothing panics on any input: mutated scene files, TOML and NFF, and
//! mutated OBJ meshes named by a TOML scene, are either refused with an
//! error that names the right file or rendered to finite pixels.
//!
//! The mutations and their seeds are in `scene_fuzz/mutate.rs`. Besides the
//! few thousand cases each `cargo test` runs, `scene_fuzz/long.rs` fuzzes
//! for as long as `RAYBOOK_FUZZ_SECONDS` asks (see there): opt-in, never in CI.

mod common;
#[path = "scene_fuzz/long.rs"]
mod long;
#[path = "scene_fuzz/mutate.rs"]
mod mutate;

use mutate::{Mutation, apply, mutated, mutation};
use proptest::prelude::*;
use raybook::render;
use raybook::scene_files::{self, SceneError};
use raybook::toolkit::Scene;

proptest! {
    #![proptest_config(ProptestConfig::with_cases(2000))]

    #[test]
    fn mutated_scenes_never_panic(
        seed in any::<usize>(),
        mutations in prop::collection::vec(mutation(), 1..4),
    ) {
        let text = mutated(&mutate::seeds(), seed, &mutations, mutate::TOKENS);
        check(scene_files::parse(&text, "fuzz.toml"), "fuzz.toml")?;
    }
}

/// What a parser made of a mutated scene: rendered small (`true`), or
/// refused well (`false`).
fn check(parsed: Result<Scene, SceneError>, file: &str) -> Result<bool, TestCaseError> {
    match parsed {
        Ok(scene) => {
            // What parses must render, without a panic, to finite values.
            let (image, _) = render(&scene.with_size(8, 6), || {});
            prop_assert!(image.pixels.iter().all(|c| c.is_finite()));
            Ok(true)
        }
        Err(e) => {
            prop_assert_eq!(e.file.as_str(), file);
            prop_assert!(!e.message.is_empty());
            Ok(false)
        }
    }
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(1000))]

    #[test]
    fn mutated_nff_scenes_never_panic(
        seed in any::<usize>(),
        mutations in prop::collection::vec(mutation(), 1..4),
    ) {
        let text = mutated(&mutate::nff_seeds(), seed, &mutations, mutate::NFF_TOKENS);
        check(raybook::nff::parse(&text, "fuzz.nff"), "fuzz.nff")?;
    }
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(300))]

    #[test]
    fn mutated_meshes_never_panic(
        seed in any::<usize>(),
        mutations in prop::collection::vec(mutation(), 1..4),
    ) {
        let obj = mutated(&mutate::obj_seeds(), seed, &mutations, mutate::OBJ_TOKENS);
        check_mesh(&obj)?;
    }
}

/// A scene of the mesh `obj` (in a file, as a scene names it) loaded, and
/// checked as [`check`] checks a scene; an error about the mesh names the
/// scene's line and, first in its message, the mesh's file.
fn check_mesh(obj: &str) -> Result<bool, TestCaseError> {
    let dir = mutate::CaseDir::new();
    let scene = dir.scene_with_mesh(obj);
    let loaded = scene_files::load_within(&scene, None);
    if let Err(e) = &loaded {
        prop_assert!(e.line.is_some(), "{}", e);
        let mesh = dir.0.join("mesh.obj");
        let named = e.message.starts_with(&format!("{}:", mesh.display()));
        prop_assert!(e.path != "objects[0].path" || named, "{}", e);
    }
    check(loaded, &scene.display().to_string())
}

/// The long run, when `RAYBOOK_FUZZ_SECONDS` asks for it (`scene_fuzz/long.rs`).
#[test]
fn fuzz_for_the_seconds_asked() {
    long::run(|format, text| match format {
        long::Format::Toml => check(scene_files::parse(text, "fuzz.toml"), "fuzz.toml"),
        long::Format::Nff => check(raybook::nff::parse(text, "fuzz.nff"), "fuzz.nff"),
        long::Format::Obj => check_mesh(text),
    });
}

#[test]
fn a_mutation_the_fuzzer_found_is_refused_without_a_panic() {
    // Found by `mutated_scenes_never_panic`: the error's span was mapped
    // through a checker with no pieces of text at all.
    let seeds = mutate::seeds();
    let text = &seeds[11_772_836_615_416_564_769 % seeds.len()];
    let mutation = Mutation::Replace(
        681_774_403_322_263_074,
        11_600_873_228_271_460_993,
        11_735_463_111_148_212_227,
    );
    let text = apply(text, &mutation);
    check(scene_files::parse(&text, "fuzz.toml"), "fuzz.toml").unwrap();
}

/// The mesh seeds themselves load: the mutations start from good meshes.
#[test]
fn the_mesh_seeds_load() {
    for obj in mutate::obj_seeds() {
        let dir = mutate::CaseDir::new();
        let scene = scene_files::load_within(dir.scene_with_mesh(&obj), None).unwrap();
        assert!(!scene.objects.is_empty());
    }
}
