//! `--pixel X,Y`: the ray tree of one pixel, as text and as JSON.

use std::path::Path;
use std::process::{Command, Output};

/// The lecture's worked example as a scene: the eye at r0 = (0, 2, 0)
/// looking straight down at the unit sphere at the origin. With an odd
/// image size the centre pixel's ray is rd = (0, −1, 0) exactly.
const WORKED_EXAMPLE: &str = r#"
[camera]
eye = [0.0, 2.0, 0.0]
look_at = [0.0, 0.0, 0.0]
up = [0.0, 0.0, -1.0]
vfov = 20.0

[image]
width = 3
height = 3

[materials.red]
color = [0.8, 0.1, 0.1]

[[objects]]
type = "sphere"
center = [0.0, 0.0, 0.0]
radius = 1.0
material = "red"
"#;

/// Runs the chapter binary in `dir` on the worked example's scene.
fn run_in(dir: &Path, args: &[&str]) -> Output {
    let scene = dir.join("worked.toml");
    std::fs::write(&scene, WORKED_EXAMPLE).unwrap();
    Command::new(env!("CARGO_BIN_EXE_ch02-hits"))
        .current_dir(dir)
        .arg(&scene)
        .args(args)
        .output()
        .unwrap()
}

fn stdout(output: &Output) -> String {
    assert!(
        output.status.success(),
        "{}",
        String::from_utf8_lossy(&output.stderr)
    );
    String::from_utf8(output.stdout.clone()).unwrap()
}

#[test]
fn the_worked_example_hits_the_sphere_at_t_1_with_roots_1_and_3_in_text() {
    let dir = tempfile::tempdir().unwrap();
    let text = stdout(&run_in(dir.path(), &["--pixel", "1,1"]));
    assert!(
        text.lines()
            .next()
            .unwrap()
            .contains("one ray through the pixel's centre"),
        "{text}"
    );
    assert!(text.contains("from (0, 2, 0) along (0, -1, 0)"), "{text}");
    assert!(
        text.contains("hit object 0 (sphere, material red) at t = 1, front side"),
        "{text}"
    );
    assert!(text.contains("t₀ = 1, t₁ = 3 (nearest first)"), "{text}");
    assert!(text.contains("point (0, 1, 0), normal (0, 1, 0)"), "{text}");
}

#[test]
fn the_worked_example_hits_the_sphere_at_t_1_with_roots_1_and_3_in_json() {
    let dir = tempfile::tempdir().unwrap();
    let json = stdout(&run_in(dir.path(), &["--pixel", "1,1", "--json"]));
    let tree: serde_json::Value = serde_json::from_str(&json).unwrap();
    let primary = &tree["primary"];
    assert_eq!(primary["kind"], "primary");
    assert_eq!(primary["direction"], serde_json::json!([0.0, -1.0, 0.0]));
    let hit = &primary["hit"];
    assert_eq!(hit["object"], 0);
    assert_eq!(hit["shape"], "sphere");
    assert_eq!(hit["side"], "front");
    assert_eq!(hit["t"].as_f64().unwrap(), 1.0, "{json}");
    assert_eq!(hit["roots"], serde_json::json!([1.0, 3.0]), "{json}");
    assert_eq!(tree["pixel"], serde_json::json!([1, 1]));
    assert_eq!(tree["image"], serde_json::json!([3, 3]));
}

#[test]
fn the_tree_goes_to_stdout_and_no_png_is_written() {
    let dir = tempfile::tempdir().unwrap();
    let out = dir.path().join("picture.png");
    let output = run_in(dir.path(), &["--pixel", "1,1", "-o", out.to_str().unwrap()]);
    let text = stdout(&output);
    assert!(
        text.starts_with("ray tree of pixel (1, 1) in 3×3"),
        "{text}"
    );
    assert!(!text.contains("wrote"), "{text}");
    let pngs: Vec<_> = std::fs::read_dir(dir.path())
        .unwrap()
        .filter_map(|e| e.ok())
        .filter(|e| e.path().extension().is_some_and(|x| x == "png"))
        .collect();
    assert!(pngs.is_empty(), "a PNG was written: {pngs:?}");
}

#[test]
fn a_pixel_outside_the_image_is_an_error_that_names_its_size() {
    let dir = tempfile::tempdir().unwrap();
    let output = run_in(dir.path(), &["--pixel", "3,1"]);
    assert!(!output.status.success());
    let stderr = String::from_utf8_lossy(&output.stderr);
    assert!(
        stderr.contains("pixel (3, 1) is outside the image, which is 3×3 pixels"),
        "{stderr}"
    );
    assert!(
        output.stdout.iter().all(|&b| b != b'{'),
        "no tree on stdout"
    );
}

#[test]
fn json_needs_a_pixel() {
    let dir = tempfile::tempdir().unwrap();
    let output = run_in(dir.path(), &["--json"]);
    assert!(!output.status.success());
    let stderr = String::from_utf8_lossy(&output.stderr);
    assert!(stderr.contains("--pixel"), "{stderr}");
}

/// The roots the tree shows at `pixel` of `scene` drawn by `method`, and
/// the ray through it.
fn shown_roots(
    scene: &ch02_hits::toolkit::Scene,
    method: ch02_hits::Method,
    pixel: ch02_hits::workbench::cli::Pixel,
) -> Option<Option<[f32; 2]>> {
    let (_, node) = ch02_hits::ray_tree::explain(scene, ch02_hits::View::Flat, method, pixel);
    node.hit.map(|hit| hit.roots)
}

#[test]
fn the_tree_shows_the_roots_of_the_quadratic_that_drew_the_pixel() {
    // On the far sphere the lecture's quadratic and the stable one return
    // different roots, and the lecture's "hits" far outside the true
    // sphere, where the stable one finds none. The tree must show the
    // roots of the method that drew the pixel: with the lecture's, the
    // student's own sphere_roots_abc.
    use ch02_hits::workbench::cli::Pixel;
    use ch02_hits::{Method, sphere_roots, sphere_roots_abc};
    let path = concat!(env!("CARGO_MANIFEST_DIR"), "/scenes/far-sphere.toml");
    let scene = ch02_hits::scene_files::load(path).unwrap();
    let (center, radius) = (ch02_hits::toolkit::Vec3::new(0.3, 0.2, -10000.0), 1.0);
    let (mut differing, mut outside) = (0, 0);
    for y in (0..scene.image.height).step_by(7) {
        for x in (0..scene.image.width).step_by(7) {
            let pixel = Pixel { x, y };
            let ray = ch02_hits::ray_tree::primary_ray(&scene, pixel);
            let Some(shown) = shown_roots(&scene, Method::Lecture, pixel) else {
                continue;
            };
            let own = sphere_roots_abc(center, radius, &ray).map(|(a, b)| [a, b]);
            assert_eq!(
                shown, own,
                "pixel ({x}, {y}): not the lecture quadratic's roots"
            );
            let stable = sphere_roots(center, radius, &ray).map(|(a, b)| [a, b]);
            match stable {
                None => outside += 1,
                Some(stable) if Some(stable) != own => differing += 1,
                Some(_) => {}
            }
            if let Some(robust) = shown_roots(&scene, Method::Robust, pixel) {
                assert_eq!(robust, stable, "pixel ({x}, {y}), --method robust");
            }
        }
    }
    assert!(
        differing > 0 && outside > 0,
        "the far sphere should have pixels where the two quadratics' roots differ ({differing}) \
         and where only the lecture's hits ({outside}): the test would not see roots from the wrong one"
    );
}
