//! Through the BVH, a pixel's ray tree is the same as chapter 7's.

use ch08_bvh::Termination;
use ch08_bvh::scene_files;
use ch08_bvh::workbench::cli::Pixel;

#[test]
fn the_tree_through_the_bvh_is_chapter_7s() {
    let glass = concat!(
        env!("CARGO_MANIFEST_DIR"),
        "/../06-refraction/scenes/default.toml"
    );
    let scene = scene_files::load(glass).unwrap();
    let termination = Termination::of(&scene);
    for (x, y) in [(160, 110), (60, 200), (250, 150)] {
        let pixel = Pixel { x, y };
        let through_bvh = ch08_bvh::ray_tree::explain(&scene, termination, pixel);
        let one_by_one = ch07_termination::ray_tree::explain(&scene, termination, pixel);
        assert_eq!(through_bvh, one_by_one, "pixel ({x}, {y})");
        assert!(!through_bvh.1.secondary.is_empty() || x != 160);
    }
}
