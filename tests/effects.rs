//! Simulate only the effects a scene calls for: the sets are right, and the
//! ray counts show that nothing else is computed.

mod common;

use raybook::render;
use raybook::scene_files;
use raybook::toolkit::scene::{Effect, Effects, Light};
use raybook::toolkit::{Scene, Stats};
use raybook::workbench::cli::{Chapter, EffectPlan};

fn chapter_scene(path: &str) -> Scene {
    let root = env!("CARGO_MANIFEST_DIR");
    scene_files::load(format!("{root}/chapters/{path}"))
        .unwrap()
        .with_size(80, 60)
}

fn stats(scene: &Scene) -> Stats {
    render(scene, || {}).1
}

fn set(effects: &[Effect]) -> Effects {
    Effects::of(effects)
}

#[test]
fn each_chapter_scene_calls_for_what_it_shows() {
    use Effect::*;
    let cases = [
        ("01-rays/scenes/default.toml", set(&[])),
        (
            "03-lambert/scenes/default.toml",
            set(&[Lambert, Spot, Shadows]),
        ),
        ("04-shadows/scenes/box.toml", set(&[Lambert, Shadows])),
        (
            "05-reflection/scenes/default.toml",
            set(&[Lambert, Shadows, Reflection]),
        ),
        (
            "06-refraction/scenes/default.toml",
            set(&[Lambert, Shadows, Reflection, Refraction]),
        ),
        ("07-termination/scenes/default.toml", Effects::ALL),
    ];
    for (path, expected) in cases {
        assert_eq!(chapter_scene(path).calls_for(), expected, "{path}");
    }
}

#[test]
fn a_diffuse_scene_traces_no_reflection_or_refraction_ray() {
    let s = stats(&chapter_scene("04-shadows/scenes/default.toml"));
    assert_eq!((s.reflection, s.refraction), (0, 0));
    assert!(s.shadow > 0);
}

#[test]
fn a_light_without_shadows_costs_no_shadow_ray() {
    let mut scene = chapter_scene("04-shadows/scenes/default.toml");
    scene.lights.retain(|l| matches!(l, Light::Point { .. }));
    let Light::Point { shadows, .. } = &mut scene.lights[0] else {
        unreachable!()
    };
    *shadows = false;
    assert!(!scene.calls_for().contains(Effect::Shadows));
    assert_eq!(stats(&scene).shadow, 0);
}

#[test]
fn a_light_behind_every_surface_costs_no_shadow_ray() {
    let text = r#"
        [camera]
        eye = [0, 3, 6]
        look_at = [0, 0, 0]
        up = [0, 1, 0]
        vfov = 60
        [image]
        width = 80
        height = 60
        [materials.grey]
        [[lights]]
        type = "point"
        position = [0, -2, 0]
        intensity = 10
        [[objects]]
        type = "plane"
        normal = [0, 1, 0]
        offset = 0
        material = "grey"
        [[objects]]
        type = "triangle"
        vertices = [[-1, 1, 0], [1, 1, 0], [0, 1, -1]]
        material = "grey"
    "#;
    let scene = scene_files::parse(text, "behind.toml").unwrap();
    let (image, s) = render(&scene, || {});
    assert_eq!(s.shadow, 0);
    assert!(
        s.primary > 0
            && image
                .pixels
                .iter()
                .all(|c| *c == raybook::toolkit::Vec3::ZERO)
    );
}

#[test]
fn a_black_mirror_asks_for_no_shadow_ray() {
    // Mirrors with no diffuse colour and no highlight: no light they receive
    // directly can reach the eye, so no shadow ray is traced from them.
    let mut scene = chapter_scene("07-termination/scenes/mirrors.toml");
    scene.lights.push(Light::Point {
        position: raybook::toolkit::Vec3::new(0.0, 1.0, 0.0),
        color: raybook::toolkit::Vec3::ONE,
        intensity: 5.0,
        shadows: true,
        falloff: raybook::toolkit::scene::Falloff::InverseSquare,
    });
    let s = stats(&scene);
    assert!(s.reflection > 0);
    assert_eq!(s.shadow, 0);
}

#[test]
fn switching_reflection_off_removes_the_reflection_rays_and_nothing_else() {
    let scene = chapter_scene("05-reflection/scenes/default.toml");
    let with = stats(&scene);
    let without = stats(&scene.clone().without(set(&[Effect::Reflection])));
    // What primary hits need is unchanged: the same rays as a render that
    // follows no bounce at all.
    let mut no_bounce = scene.clone();
    no_bounce.trace.max_depth = 0;
    let direct = stats(&no_bounce);
    assert!(with.reflection > 0);
    assert_eq!(without.reflection, 0);
    assert_eq!(without.primary, with.primary);
    assert_eq!(
        without.shadow, direct.shadow,
        "only the shadow rays of bounced hits go"
    );
    assert_eq!(without.refraction, with.refraction);
}

#[test]
fn a_scene_can_switch_effects_off_itself() {
    let mut scene = chapter_scene("04-shadows/scenes/default.toml");
    scene.trace.effects = Some(vec![Effect::Lambert, Effect::Spot]);
    let chapter = raybook::CHAPTER;
    let plan = EffectPlan::new(&chapter, &scene, &[]);
    assert_eq!(plan.simulated, set(&[Effect::Lambert, Effect::Spot]));
    assert_eq!(stats(&plan.apply(&chapter, scene)).shadow, 0);
}

#[test]
fn the_command_line_can_switch_effects_off() {
    let scene = chapter_scene("06-refraction/scenes/default.toml");
    let chapter = raybook::CHAPTER;
    let plan = EffectPlan::new(&chapter, &scene, &[Effect::Refraction, Effect::Shadows]);
    assert!(!plan.simulated.contains(Effect::Refraction));
    let s = stats(&plan.apply(&chapter, scene));
    assert_eq!((s.refraction, s.shadow), (0, 0));
    assert!(s.reflection > 0);
}

#[test]
fn an_earlier_chapter_names_the_chapter_that_would_simulate_the_rest() {
    let scene = chapter_scene("06-refraction/scenes/default.toml");
    let chapter3 = Chapter {
        package: "ch03-lambert",
        ..raybook::CHAPTER
    };
    let plan = EffectPlan::new(&chapter3, &scene, &[]);
    let notes = plan.notes().join("\n");
    assert!(
        notes.contains(
            "this scene calls for shadows, introduced in chapter 4 (chapters/04-shadows)"
        ),
        "{notes}"
    );
    assert!(
        notes.contains("refraction, introduced in chapter 6 (chapters/06-refraction)"),
        "{notes}"
    );
    assert_eq!(plan.simulated, set(&[Effect::Lambert]));
}

#[test]
fn the_tracer_chosen_for_the_effects_gives_the_full_tracers_picture_and_counts() {
    use raybook::tracer::{Termination, Tracer, render_complete, render_whitted};
    let secondary = set(&[Effect::Reflection, Effect::Refraction]);
    let mut direct = 0;
    for file in common::chapter_scene_files() {
        let (path, scene) = (
            file.display(),
            scene_files::load(&file).unwrap().with_size(80, 60),
        );
        // Each scene as it is, and cut down to what chapter 4 can show.
        for scene in [scene.clone(), scene.without(secondary)] {
            let termination = Termination::of(&scene);
            let world = &scene.objects[..];
            let chosen = render_complete(&scene, world, termination, || {});
            let full = render_whitted(&Tracer { termination }, &scene, world, || {});
            assert!(
                chosen.0.pixels == full.0.pixels,
                "{path}: the pictures differ"
            );
            assert_eq!(chosen.1, full.1, "{path}");
            if scene.calls_for().and(secondary).is_empty() {
                direct += 1;
            }
        }
    }
    assert!(direct >= 12, "the direct tracer was chosen {direct} times");
}
