//! Chapter 2: the three intersections, the closest hit, and the pictures.

use ch02_hits::toolkit::compare::{Tolerance, compare};
use ch02_hits::toolkit::scene::Shape;
use ch02_hits::toolkit::snapshot::assert_image;
use ch02_hits::toolkit::{Image, Scene, Vec3};
use ch02_hits::{
    CHAPTER, Ray, View, closest_hit, intersect_plane, intersect_sphere, intersect_triangle,
    render_hits, sphere_roots,
};

fn scene() -> Scene {
    CHAPTER.default_scene().unwrap().with_size(160, 120)
}

fn render(scene: &Scene, view: View) -> Image {
    render_hits(scene, view, || {}).0
}

#[test]
fn the_lectures_worked_example() {
    // Ray from (0, 2, 0) straight down onto the unit sphere at the origin.
    let ray = Ray::new(Vec3::new(0.0, 2.0, 0.0), Vec3::new(0.0, -1.0, 0.0));
    let (t0, t1) = sphere_roots(Vec3::ZERO, 1.0, &ray).unwrap();
    assert_eq!((t0, t1), (1.0, 3.0));
    assert_eq!(ray.at(t0), Vec3::new(0.0, 1.0, 0.0));
    assert_eq!(ray.at(t1), Vec3::new(0.0, -1.0, 0.0));
    assert_eq!(
        intersect_sphere(Vec3::ZERO, 1.0, &ray, 0.0, f32::INFINITY),
        Some(1.0)
    );
    // Starting inside the sphere, the first hit ahead is the far side.
    assert_eq!(
        intersect_sphere(Vec3::ZERO, 1.0, &ray, 1.5, f32::INFINITY),
        Some(3.0)
    );
}

#[test]
fn a_ray_past_the_sphere_misses() {
    let ray = Ray::new(Vec3::new(0.0, 2.0, 0.0), Vec3::new(1.0, 0.0, 0.0));
    assert_eq!(sphere_roots(Vec3::ZERO, 1.0, &ray), None);
}

#[test]
fn a_sphere_behind_the_ray_is_not_hit() {
    let ray = Ray::new(Vec3::new(0.0, 2.0, 0.0), Vec3::new(0.0, 1.0, 0.0));
    assert_eq!(
        intersect_sphere(Vec3::ZERO, 1.0, &ray, 0.0, f32::INFINITY),
        None
    );
}

#[test]
fn plane_hit_solves_n_dot_x_plus_d() {
    // The plane y = 1 is n = (0, 1, 0), d = −1.
    let ray = Ray::new(Vec3::new(0.0, 5.0, 0.0), Vec3::new(0.0, -1.0, 0.0));
    assert_eq!(
        intersect_plane(Vec3::Y, -1.0, &ray, 0.0, f32::INFINITY),
        Some(4.0)
    );
    assert_eq!(
        intersect_plane(Vec3::Y, -1.0, &ray, 0.0, 3.0),
        None,
        "beyond t_max"
    );
    let parallel = Ray::new(Vec3::new(0.0, 5.0, 0.0), Vec3::X);
    assert_eq!(
        intersect_plane(Vec3::Y, -1.0, &parallel, 0.0, f32::INFINITY),
        None
    );
}

#[test]
fn triangle_barycentrics_follow_the_lecture() {
    let corners = [Vec3::ZERO, Vec3::X, Vec3::Y];
    let ray = Ray::new(Vec3::new(0.25, 0.5, 1.0), Vec3::new(0.0, 0.0, -1.0));
    let (t, alpha, beta) = intersect_triangle(corners, &ray, 0.0, f32::INFINITY).unwrap();
    assert_eq!(t, 1.0);
    assert!(
        (alpha - 0.25).abs() < 1e-6 && (beta - 0.5).abs() < 1e-6,
        "{alpha} {beta}"
    );
    // Outside: α + β > 1.
    let outside = Ray::new(Vec3::new(0.6, 0.6, 1.0), Vec3::new(0.0, 0.0, -1.0));
    assert_eq!(
        intersect_triangle(corners, &outside, 0.0, f32::INFINITY),
        None
    );
    // From behind: triangles are hit from both sides.
    let back = Ray::new(Vec3::new(0.25, 0.5, -1.0), Vec3::new(0.0, 0.0, 1.0));
    assert!(intersect_triangle(corners, &back, 0.0, f32::INFINITY).is_some());
}

#[test]
fn closest_hit_is_the_nearest_object() {
    let s = scene();
    // Straight down from high above the red sphere: it is above the floor.
    let ray = Ray::new(Vec3::new(-1.0, 10.0, 0.0), Vec3::new(0.0, -1.0, 0.0));
    let hit = closest_hit(&s.objects, &ray, 0.0, f32::INFINITY).unwrap();
    assert!(matches!(s.objects[hit.object].shape, Shape::Sphere { .. }));
    assert!((hit.t - 8.0).abs() < 1e-5, "{}", hit.t);
    assert!((hit.normal - Vec3::Y).length() < 1e-6);
    // With t_max below the sphere's t, nothing is hit.
    assert!(closest_hit(&s.objects, &ray, 0.0, 7.9).is_none());
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

fn verdict_against_default(changed: &Scene, view: View) -> ch02_hits::toolkit::compare::Verdict {
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
