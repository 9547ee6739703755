//! The pictures: the lecture's methods, the snapshots, and the snapshot tolerance.

use ch02_hits::toolkit::Scene;
use ch02_hits::toolkit::scene::{Object, Shape};
use ch02_hits::workbench::compare::{Tolerance, compare};
use ch02_hits::workbench::snapshot::{assert_image, check, reference_path};
use ch02_hits::{Ray, View, intersect, sphere_roots_abc, triangle_by_plane};

use super::{INF, render, scene};

/// The closest hit with the lecture's methods: `sphere_roots_abc` for
/// spheres, `triangle_by_plane` for triangles.
fn lecture_hit(objects: &[Object], ray: &Ray) -> Option<usize> {
    let mut nearest: Option<(f32, usize)> = None;
    for (index, object) in objects.iter().enumerate() {
        let bound = nearest.map_or(INF, |(t, _)| t);
        let t = match object.shape {
            Shape::Sphere { center, radius } => sphere_roots_abc(center, radius, ray)
                .and_then(|(t0, t1)| [t0, t1].into_iter().find(|&t| t > 0.0 && t < bound)),
            Shape::Triangle { vertices } => {
                triangle_by_plane(vertices, ray, 0.0, bound).map(|(t, _, _)| t)
            }
            ref shape => intersect(shape, ray, 0.0, bound),
        };
        if let Some(t) = t {
            nearest = Some((t, index));
        }
    }
    nearest.map(|(_, index)| index)
}

#[test]
fn the_lectures_methods_draw_the_same_picture() {
    // The flat view of the default scene, its spheres and its triangle hit
    // with the lecture's formulas instead of the tracer's robust ones: the
    // same picture, within the snapshot tolerance.
    let s = scene();
    let image = ch02_hits::render(
        &s,
        |ray, _| match lecture_hit(&s.objects, ray) {
            Some(index) => s.material(&s.objects[index]).color,
            None => s.image.background,
        },
        || {},
    )
    .0;
    let tracer = render(&s, View::Flat);
    let verdict = compare(
        &tracer.to_rgb8(),
        &image.to_rgb8(),
        Tolerance::for_size(160, 120),
    );
    println!("the lecture's methods against the tracer's, flat view: {verdict}");
    let reference = std::fs::read(reference_path("02-hits", "flat")).unwrap();
    if let Err(report) = check("02-hits", "flat-lecture", &reference, &image.to_rgb8()) {
        panic!(
            "the flat picture drawn with sphere_roots_abc and triangle_by_plane differs from \
             the reference:\n{report}"
        );
    }
}

#[test]
fn snapshot_flat() {
    assert_image("02-hits", "flat", &render(&scene(), View::Flat));
}

#[test]
fn snapshot_normals() {
    assert_image("02-hits", "normals", &render(&scene(), View::Normals));
}

#[test]
fn snapshot_depth() {
    assert_image("02-hits", "depth", &render(&scene(), View::Depth));
}

// The snapshot tolerance, checked on this chapter's own pictures: a real
// mistake fails, a harmless last-bit change passes.

fn verdict_against_default(changed: &Scene, view: View) -> ch02_hits::workbench::compare::Verdict {
    let expected = render(&scene(), view).to_rgb8();
    let actual = render(changed, view).to_rgb8();
    compare(&expected, &actual, Tolerance::for_size(160, 120))
}

/// The default scene with object `index` changed by `change`.
fn changed(index: usize, change: impl Fn(&mut Shape)) -> Scene {
    let mut s = scene();
    change(&mut s.objects[index].shape);
    s
}

#[test]
fn a_sphere_one_pixel_off_fails_the_snapshot() {
    // At the sphere's distance (6 units) one pixel of a 45° view 120 pixels
    // high is 2·6·tan(22.5°)/120 ≈ 0.041 units.
    let moved = changed(1, |shape| {
        if let Shape::Sphere { center, .. } = shape {
            center.x += 0.041;
        }
    });
    assert!(!verdict_against_default(&moved, View::Flat).passed());
}

#[test]
fn a_missing_object_fails_the_snapshot() {
    let mut s = scene();
    s.objects.remove(2);
    assert!(!verdict_against_default(&s, View::Flat).passed());
}

#[test]
fn a_flipped_normal_fails_the_snapshot() {
    let flipped = changed(0, |shape| {
        if let Shape::Plane { normal, offset } = shape {
            (*normal, *offset) = (-*normal, -*offset);
        }
    });
    assert!(!verdict_against_default(&flipped, View::Normals).passed());
}

#[test]
fn a_last_bit_change_passes_the_snapshot() {
    // Moving the eye by a few units in the last place changes every ray's
    // rounding, as another correct implementation would.
    let mut s = scene();
    s.camera.eye *= 1.0 + 2.0 * f32::EPSILON;
    let verdict = verdict_against_default(&s, View::Normals);
    assert!(verdict.passed(), "{verdict}");
}
