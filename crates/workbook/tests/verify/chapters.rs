//! Each chapter's ray tree, as its binary builds it with `--pixel X,Y`:
//! what the reference trees and the light maps are made from.

use workbook::toolkit::Scene;
use workbook::workbench::chapters::ChapterEntry;
use workbook::workbench::cli::{Chapter, EffectPlan, Pixel, RenderArgs};
use workbook::workbench::ray_tree::{RayNode, RayTree, TracerInfo};

/// A chapter's `explain(scene, pixel)`, as its main.rs passes it to
/// `run_or_explain` with no options.
pub(crate) type Explain = fn(&Scene, Pixel) -> (TracerInfo, RayNode);

/// A chapter binary: its chapter and its ray tree.
pub(crate) fn chapter(folder: &str) -> (Chapter, Explain) {
    match folder {
        "01-rays" => (ch01_rays::CHAPTER, ch01_rays::ray_tree::explain),
        // The default view, which is also the reference picture's `--view flat`.
        "02-hits" => (ch02_hits::CHAPTER, |scene, pixel| {
            ch02_hits::ray_tree::explain(
                scene,
                ch02_hits::View::Flat,
                ch02_hits::Method::Lecture,
                pixel,
            )
        }),
        "03-lambert" => (ch03_lambert::CHAPTER, ch03_lambert::ray_tree::explain),
        "04-shadows" => (ch04_shadows::CHAPTER, |scene, pixel| {
            ch04_shadows::ray_tree::explain(scene, pixel, ch04_shadows::ShadowStart::Offset)
        }),
        "05-reflection" => (ch05_reflection::CHAPTER, ch05_reflection::ray_tree::explain),
        "06-refraction" => (ch06_refraction::CHAPTER, ch06_refraction::ray_tree::explain),
        "07-termination" => (ch07_termination::CHAPTER, |scene, pixel| {
            let termination = ch07_termination::Termination::of(scene);
            ch07_termination::ray_tree::explain(scene, termination, pixel)
        }),
        "08-bvh" => (ch08_bvh::CHAPTER, |scene, pixel| {
            ch08_bvh::ray_tree::explain(scene, ch08_bvh::Termination::of(scene), pixel)
        }),
        other => panic!("no ray tree for chapter {other}"),
    }
}

/// The options of a chapter's reference picture in chapters.toml that the
/// trees here assume: a change there must be made here too.
pub(crate) fn assert_known_arguments(entry: &ChapterEntry) {
    let args = entry.verify.as_ref().map_or(&[][..], |v| v.args.as_slice());
    let known: &[&str] = match entry.folder.as_str() {
        "02-hits" => &["--view", "flat"],
        _ => &[],
    };
    assert_eq!(
        args, known,
        "{}: the reference's arguments changed",
        entry.folder
    );
}

/// The chapter's default scene as its binary renders it with
/// `--width W --height H` (or at its own size), and its name: the effects
/// the chapter cannot simulate taken out, as the binary does.
pub(crate) fn default_scene(chapter: &Chapter, size: Option<(u32, u32)>) -> (Scene, String) {
    let args = RenderArgs {
        width: size.map(|s| s.0),
        height: size.map(|s| s.1),
        ..RenderArgs::default()
    };
    let (scene, name) = args.load_scene(chapter).expect("the default scene loads");
    let plan = EffectPlan::new(chapter, &scene, &[]);
    (plan.apply(chapter, scene), name)
}

/// The tree `--pixel X,Y --json` prints for the chapter's `scene`.
pub(crate) fn tree(
    chapter: &Chapter,
    explain: Explain,
    scene: &Scene,
    name: &str,
    x: u32,
    y: u32,
) -> RayTree {
    let (tracer, primary) = explain(scene, Pixel { x, y });
    RayTree {
        chapter: chapter.entry().folder.clone(),
        scene: name.to_owned(),
        pixel: [x, y],
        image: [scene.image.width, scene.image.height],
        samples: scene.image.samples,
        tracer,
        primary,
    }
}
