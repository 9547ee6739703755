//! The snapshot helper tolerates what a correct tracer may differ in, and
//! fails on what a mistake changes.

use workbench::compare::{Tolerance, Verdict, compare};
use workbench::snapshot;
use workbench::toolkit::image::encode_png;
use workbench::toolkit::{Image, Vec3};

const W: u32 = 160;
const H: u32 = 120;

/// A lit disc, drawn analytically: the kind of picture a tracer makes.
/// `dx` moves it sideways by pixels; `flip` turns its normals inside out;
/// `wobble` adds a relative error of that size to every value, as another
/// correct implementation might (different order of operations).
fn disc(dx: f32, flip: bool, wobble: f32) -> Image {
    let light = Vec3::new(-1.0, 1.0, 1.0).normalize();
    Image::render(
        W,
        H,
        |x, y, _| {
            let (cx, cy, r) = (80.0 + dx, 60.0, 30.0);
            let (px, py) = (x as f32 + 0.5 - cx, cy - (y as f32 + 0.5));
            let d2 = px * px + py * py;
            if d2 > r * r {
                return Vec3::new(0.2, 0.3, 0.5);
            }
            let z = (r * r - d2).sqrt();
            let mut n = Vec3::new(px, py, z) / r;
            if flip {
                n = -n;
            }
            let noise = 1.0 + wobble * if (x * 7 + y * 13) % 3 == 0 { 1.0 } else { -1.0 };
            Vec3::new(0.9, 0.4, 0.2) * (0.1 + n.dot(light).max(0.0)) * noise
        },
        || {},
    )
    .0
}

fn verdict(expected: &Image, actual: &Image) -> Verdict {
    compare(
        &expected.to_rgb8(),
        &actual.to_rgb8(),
        Tolerance::for_size(W, H),
    )
}

#[test]
fn last_bit_differences_pass() {
    // f32 has 24 bits: relative differences of a few 1e-7 are the last bits.
    let verdict = verdict(&disc(0.0, false, 0.0), &disc(0.0, false, 4e-7));
    assert!(verdict.passed(), "{verdict}");
}

#[test]
fn one_step_noise_passes() {
    let reference = disc(0.0, false, 0.0).to_rgb8();
    let mut noisy = reference.clone();
    for (i, p) in noisy.pixels_mut().enumerate() {
        for c in p.0.iter_mut() {
            *c = if i % 2 == 0 {
                c.saturating_add(1)
            } else {
                c.saturating_sub(1)
            };
        }
    }
    assert!(compare(&reference, &noisy, Tolerance::for_size(W, H)).passed());
}

#[test]
fn a_one_pixel_shift_fails() {
    let verdict = verdict(&disc(0.0, false, 0.0), &disc(1.0, false, 0.0));
    let Verdict::Differs(d) = verdict else {
        panic!("a shifted disc must fail: {verdict}")
    };
    assert!(
        d.pixels_over > 4 * Tolerance::for_size(W, H).pixels,
        "{d:?}"
    );
}

#[test]
fn flipped_normals_fail() {
    assert!(!verdict(&disc(0.0, false, 0.0), &disc(0.0, true, 0.0)).passed());
}

#[test]
fn a_missing_object_fails() {
    let empty = Image::render(W, H, |_, _, _| Vec3::new(0.2, 0.3, 0.5), || {}).0;
    assert!(!verdict(&disc(0.0, false, 0.0), &empty).passed());
}

#[test]
fn a_wrong_size_fails_with_both_sizes() {
    let small = Image::render(W / 2, H, |_, _, _| Vec3::ZERO, || {}).0;
    let verdict = verdict(&disc(0.0, false, 0.0), &small);
    assert!(!verdict.passed());
    assert!(verdict.to_string().contains("80×120"), "{verdict}");
    assert!(verdict.to_string().contains("160×120"), "{verdict}");
}

#[test]
fn a_failure_writes_actual_and_diff_pictures_and_names_them() {
    let reference = encode_png(&disc(0.0, false, 0.0).to_rgb8());
    let actual = disc(1.0, false, 0.0).to_rgb8();
    let report = snapshot::check("helper-test", "shifted", &reference, &actual)
        .expect_err("a shifted disc must fail");
    let dir = snapshot::failure_dir("helper-test");
    let (actual_path, diff_path) = (dir.join("shifted.actual.png"), dir.join("shifted.diff.png"));
    assert!(
        report.contains(&actual_path.display().to_string()),
        "{report}"
    );
    assert!(
        report.contains(&diff_path.display().to_string()),
        "{report}"
    );
    assert!(report.contains("pixels differ"), "{report}");
    let diff = image::open(&diff_path).unwrap();
    assert_eq!(
        (diff.width(), diff.height()),
        (3 * W, H),
        "expected | mask | actual"
    );
    assert_eq!(image::open(&actual_path).unwrap().to_rgb8(), actual);
}

#[test]
fn a_pass_writes_nothing() {
    let reference = encode_png(&disc(0.0, false, 0.0).to_rgb8());
    let actual = disc(0.0, false, 4e-7).to_rgb8();
    assert!(snapshot::check("helper-test", "same", &reference, &actual).is_ok());
    assert!(
        !snapshot::failure_dir("helper-test")
            .join("same.diff.png")
            .exists()
    );
}

#[test]
fn a_picture_that_passes_again_takes_its_old_diff_pictures_away() {
    let reference = encode_png(&disc(0.0, false, 0.0).to_rgb8());
    let wrong = disc(1.0, false, 0.0).to_rgb8();
    assert!(snapshot::check("helper-test", "fixed", &reference, &wrong).is_err());
    let dir = snapshot::failure_dir("helper-test");
    let (actual_path, diff_path) = (dir.join("fixed.actual.png"), dir.join("fixed.diff.png"));
    assert!(actual_path.exists() && diff_path.exists());
    let right = disc(0.0, false, 0.0).to_rgb8();
    assert!(snapshot::check("helper-test", "fixed", &reference, &right).is_ok());
    assert!(
        !actual_path.exists(),
        "{} is left behind",
        actual_path.display()
    );
    assert!(
        !diff_path.exists(),
        "{} is left behind",
        diff_path.display()
    );
}
