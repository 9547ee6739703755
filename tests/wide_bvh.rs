//! The complete tracer's wide BVH answers exactly as brute force does:
//! the same hits to the last bit, so the same pictures and ray counts.

mod common;
#[path = "wide_bvh/leaving.rs"]
mod leaving;

use proptest::prelude::*;
use raybook::nff;
use raybook::scene_files;
use raybook::toolkit::scene::{Object, Shape};
use raybook::toolkit::{Image, Scene, Stats, Vec3};
use raybook::tracer::{Ray, Termination, World, render_complete};
use raybook::wide::WideBvh;
use raybook::workbench::snapshot::workspace_root;
use test_support::strategies::{point, usable_cone};

fn render(scene: &Scene, world: &(impl World + ?Sized)) -> (Image, Stats) {
    render_complete(scene, world, Termination::of(scene), || {})
}

#[test]
fn wide_bvh_and_brute_force_give_the_same_picture_on_every_chapter_scene() {
    for path in common::chapter_scene_files() {
        let scene = scene_files::load(&path).unwrap().with_size(80, 60);
        let wide = WideBvh::build(&scene.objects);
        let same = render(&scene, &scene.objects[..]) == render(&scene, &wide);
        assert!(same, "{} differs", path.display());
    }
}

/// The SPD scenes that come with the repository (`scenes/spd/*.nff`), sorted.
fn spd_scenes() -> Vec<std::path::PathBuf> {
    let dir = workspace_root().join("scenes/spd");
    let mut paths: Vec<_> = std::fs::read_dir(dir)
        .unwrap()
        .map(|e| e.unwrap().path())
        .filter(|p| p.extension().is_some_and(|e| e == "nff"))
        .collect();
    paths.sort();
    assert!(paths.len() >= 7, "{paths:?}");
    paths
}

#[test]
fn wide_bvh_and_chapter_8s_give_the_same_picture_on_the_spd_scenes() {
    for path in spd_scenes() {
        let scene = nff::load(&path).unwrap().with_size(64, 64);
        let wide = WideBvh::build(&scene.objects);
        let binary = ch08_bvh::Bvh::build(&scene.objects);
        let same = render(&scene, &binary) == render(&scene, &wide);
        assert!(same, "{} differs", path.display());
    }
}

#[test]
fn an_empty_scene_and_a_single_object_are_handled() {
    let ray = Ray::new(Vec3::ZERO, Vec3::X);
    let empty = WideBvh::build(&[]);
    assert_eq!(empty.closest_hit(&ray, 0.0, f32::INFINITY), None);
    assert!(!empty.any_hit(&ray, 0.0, f32::INFINITY));
    let one = [Object {
        shape: Shape::Sphere {
            center: Vec3::new(5.0, 0.0, 0.0),
            radius: 1.0,
        },
        material: 0,
        shadows: true,
    }];
    let wide = WideBvh::build(&one);
    assert_eq!(wide.node_count(), 1, "a root with one leaf lane");
    assert_eq!(
        wide.closest_hit(&ray, 0.0, f32::INFINITY).map(|h| h.t),
        Some(4.0)
    );
    assert!(wide.any_hit(&ray, 0.0, 10.0));
    assert!(!wide.any_hit(&ray, 0.0, 3.9));
}

/// A 6×6 grid of unit squares in the plane z = 0, two triangles each: 72
/// triangles, so a tree whose leaves hold packets of several. Rays aimed
/// straight down at every shared corner, at the middle of every shared
/// edge and along the diagonals, where the watertight test decides on an
/// edge (a packet lane finished in f64): every one hits, exactly as brute
/// force says, and nothing falls through a crack.
#[test]
fn rays_at_the_shared_edges_and_corners_of_packed_triangles_hit_as_brute_force_does() {
    let mut objects = Vec::new();
    for (i, j) in (0..6).flat_map(|i| (0..6).map(move |j| (i as f32, j as f32))) {
        let [a, b, c, d] = [(i, j), (i + 1.0, j), (i + 1.0, j + 1.0), (i, j + 1.0)]
            .map(|(x, y)| Vec3::new(x, y, 0.0));
        for vertices in [[a, b, c], [a, c, d]] {
            objects.push(Object {
                shape: Shape::Triangle { vertices },
                material: 0,
                shadows: true,
            });
        }
    }
    let wide = WideBvh::build(&objects);
    assert!(wide.node_count() > 1, "a tree, not one leaf");
    let mut rays = 0;
    for step in 1..12 {
        for other in 1..12 {
            let (x, y) = (step as f32 / 2.0, other as f32 / 2.0);
            for direction in [Vec3::NEG_Z, Vec3::new(0.25, 0.5, -1.0)] {
                let ray = Ray::new(Vec3::new(x, y, 0.0) - 2.0 * direction, direction);
                let hit = wide.closest_hit(&ray, 0.0, f32::INFINITY);
                assert!(hit.is_some(), "a ray through ({x}, {y}) fell through");
                assert_eq!(hit, objects[..].closest_hit(&ray, 0.0, f32::INFINITY));
                assert!(wide.any_hit(&ray, 0.0, f32::INFINITY));
                rays += 1;
            }
        }
    }
    assert_eq!(rays, 2 * 11 * 11);
}

/// Rays that leave a sphere's surface (as shadow and mirror rays do, just
/// off it, outwards or inwards) and rays from inside it: the wide BVH's
/// shortcut for a sphere behind the origin (chapter 2's b > 0, c ≥ 0)
/// answers as chapter 2's test does, and is not taken for t_min < 0.
#[test]
fn rays_leaving_a_sphere_get_chapter_2s_answers() {
    let objects: Vec<Object> = (0..12)
        .map(|k| Object {
            shape: Shape::Sphere {
                center: Vec3::new(3.0 * (k % 4) as f32, 3.0 * (k / 4) as f32, 0.5 * k as f32),
                radius: 0.5 + 0.1 * k as f32,
            },
            material: 0,
            shadows: true,
        })
        .collect();
    let wide = WideBvh::build(&objects);
    let mut checked = 0;
    for object in &objects {
        let Shape::Sphere { center, radius } = object.shape else {
            unreachable!()
        };
        for k in 0..40 {
            let angle = k as f32 * 0.7;
            let normal = Vec3::new(angle.cos(), angle.sin(), (0.3 * angle).sin()).normalize();
            for offset in [-1e-3, -1e-6, 0.0, 1e-6, 1e-3, -0.5] {
                let origin = center + (radius + offset) * normal;
                for direction in [normal, -normal, normal + Vec3::Y, Vec3::Z - normal] {
                    let ray = Ray::new(origin, direction);
                    for (t_min, t_max) in [(0.0, f32::INFINITY), (0.0, 2.0), (-1.0, 1.0)] {
                        assert_eq!(
                            wide.closest_hit(&ray, t_min, t_max),
                            objects[..].closest_hit(&ray, t_min, t_max),
                            "{ray:?} in ({t_min}, {t_max})"
                        );
                        assert_eq!(
                            wide.any_hit(&ray, t_min, t_max),
                            objects[..].any_hit(&ray, t_min, t_max),
                            "{ray:?} in ({t_min}, {t_max})"
                        );
                        checked += 1;
                    }
                }
            }
        }
    }
    assert_eq!(checked, 12 * 40 * 6 * 4 * 3);
}

/// Shadow rays whose blocker the wide BVH may decide without solving the
/// sphere's quadratic: from inside a sphere and from outside through it, at
/// several scales, with the light (t_max) a few units in the last place
/// either side of each root, of |f| and of |f| + ρ, and far away. Each
/// answer is chapter 4's.
#[test]
fn shadow_rays_through_spheres_get_chapter_4s_answers() {
    let mut checked = 0;
    for (center, radius) in [
        (Vec3::new(0.5, -0.25, 1.0), 1.0),
        (Vec3::new(300.0, 20.0, -1e3), 0.01),
        (Vec3::new(-1e3, 5.0, 2.0), 1e3),
    ] {
        let objects = [Object {
            shape: Shape::Sphere { center, radius },
            material: 0,
            shadows: true,
        }];
        let wide = WideBvh::build(&objects);
        for k in 0..24 {
            let angle = k as f32 * 0.9;
            let normal = Vec3::new(angle.cos(), angle.sin(), (0.4 * angle).cos()).normalize();
            for distance in [
                0.0,
                0.3,
                1.0 - 1e-6,
                1.0 - 1e-4,
                1.0 + 1e-6,
                1.0 + 1e-3,
                1.5,
                40.0,
            ] {
                let origin = center + distance * radius * normal;
                let across = normal.cross(Vec3::Y).normalize();
                for aim in [
                    -normal,
                    -normal + 0.5 * across,
                    -normal + 0.99 * across,
                    across,
                ] {
                    let ray = Ray::new(origin, aim);
                    let f = (origin - center).length();
                    let mut lights = vec![f32::INFINITY, 1e-3, f, f + radius, 2.0 * (f + radius)];
                    if let Some((near, far)) = raybook::tracer::sphere_roots(center, radius, &ray) {
                        lights.extend([near, far]);
                    }
                    for light in lights.clone() {
                        let mut t = light;
                        for _ in 0..4 {
                            t = t.next_down();
                        }
                        for _ in 0..8 {
                            if t > 0.0 {
                                assert_eq!(
                                    wide.any_hit(&ray, 0.0, t),
                                    objects[..].any_hit(&ray, 0.0, t),
                                    "{ray:?} to {t}"
                                );
                                checked += 1;
                            }
                            t = t.next_up();
                        }
                    }
                }
            }
        }
    }
    assert!(checked > 3 * 24 * 8 * 4 * 5 * 8 / 2, "{checked}");
}

/// A direction, often along an axis or in a coordinate plane (zeros in rd
/// make 1/rd infinite in the slab test), else anywhere.
fn direction() -> impl Strategy<Value = Vec3> {
    prop_oneof![
        2 => point(),
        1 => (point(), 0..3usize).prop_map(|(p, axis)| {
            let mut d = Vec3::ZERO;
            d[axis] = if p.x < 0.0 { -1.0 } else { 1.0 };
            d
        }),
        1 => (point(), 0..3usize).prop_map(|(mut p, axis)| {
            p[axis] = 0.0;
            p
        }),
    ]
}

/// A cone or cylinder (some along a coordinate axis, which rays along axes run parallel to), pointed at either end or not.
fn cone() -> impl Strategy<Value = Shape> {
    (
        point(),
        point(),
        0.0f32..1.0,
        0.0f32..1.0,
        any::<bool>(),
        0..6usize,
    )
        .prop_filter_map(
            "no axis or no radius",
            |(base, apex, base_radius, apex_radius, inside_out, along)| {
                let apex = match along {
                    0..3 => base + apex.length() * Vec3::AXES[along],
                    _ => apex,
                };
                usable_cone((base, apex), (base_radius, apex_radius), inside_out)
            },
        )
}

fn object() -> impl Strategy<Value = Object> {
    let shape = prop_oneof![
        4 => (point(), 0.05f32..1.5).prop_map(|(center, radius)| Shape::Sphere { center, radius }),
        4 => (point(), point(), point()).prop_filter_map("no area", |(a, b, c)| {
            let area = (b - a).cross(c - a).length();
            (area > 1e-3).then_some(Shape::Triangle { vertices: [a, b, c] })
        }),
        // Axis-aligned triangles: flat boxes, rays along their faces.
        2 => (point(), point(), point(), 0..3usize).prop_filter_map("no area", |(a, b, c, axis)| {
            let [a, mut b, mut c] = [a, b, c];
            (b[axis], c[axis]) = (a[axis], a[axis]);
            let area = (b - a).cross(c - a).length();
            (area > 1e-3).then_some(Shape::Triangle { vertices: [a, b, c] })
        }),
        3 => cone(),
        1 => (point(), -3.0f32..3.0).prop_filter_map("no normal", |(n, offset)| {
            (n.length() > 0.1).then(|| Shape::Plane { normal: n.normalize(), offset })
        }),
    ];
    (shape, any::<bool>()).prop_map(|(shape, shadows)| Object {
        shape,
        material: 0,
        shadows,
    })
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(300))]

    /// Random objects, random rays (many along axes, some starting on a
    /// primitive's corner): both questions answered exactly as chapter 2's
    /// and chapter 4's loops answer them.
    #[test]
    fn wide_bvh_agrees_with_brute_force_on_random_rays(
        objects in prop::collection::vec(object(), 1..80),
        rays in prop::collection::vec((point(), direction(), 0.1f32..20.0, any::<bool>()), 24),
    ) {
        agrees_with_brute_force(&objects, rays)?;
    }

    /// The same for scenes of a few objects, which get no tree: their
    /// packets are tested in turn, those of triangles and cones only if the
    /// ray enters their box.
    #[test]
    fn a_few_objects_agree_with_brute_force_on_random_rays(
        objects in prop::collection::vec(object(), 1..10),
        rays in prop::collection::vec((point(), direction(), 0.1f32..20.0, any::<bool>()), 24),
    ) {
        agrees_with_brute_force(&objects, rays)?;
    }
}

/// Both questions, for each of `rays` (origin, direction, t_max, whether to
/// start at the first object's corner instead), answered by the wide BVH
/// exactly as chapter 2's and chapter 4's loops answer them.
fn agrees_with_brute_force(
    objects: &[Object],
    rays: Vec<(Vec3, Vec3, f32, bool)>,
) -> Result<(), TestCaseError> {
    let wide = WideBvh::build(objects);
    for (origin, direction, t_max, from_corner) in rays {
        prop_assume!(direction.length() > 1e-3);
        let origin = match (from_corner, objects[0].shape) {
            (true, Shape::Triangle { vertices }) => vertices[0],
            _ => origin * 2.0,
        };
        let ray = Ray::new(origin, direction);
        prop_assert_eq!(
            wide.any_hit(&ray, 0.0, t_max),
            objects[..].any_hit(&ray, 0.0, t_max)
        );
        prop_assert_eq!(
            wide.closest_hit(&ray, 0.0, t_max),
            objects[..].closest_hit(&ray, 0.0, t_max)
        );
        prop_assert_eq!(
            wide.closest_hit(&ray, 0.0, f32::INFINITY),
            objects[..].closest_hit(&ray, 0.0, f32::INFINITY)
        );
    }
    Ok(())
}

#[test]
fn the_complete_tracer_makes_the_same_bytes_on_any_number_of_threads() {
    use raybook::workbench::cli::with_threads;
    let root = workspace_root();
    let scenes = [
        nff::load(root.join("scenes/spd/mount-3.nff")).unwrap(),
        scene_files::load(root.join("scenes/peers/tinyraytracer.toml")).unwrap(),
    ];
    for scene in scenes {
        let scene = scene.with_size(64, 48);
        let render = |threads| with_threads(Some(threads), || raybook::render(&scene, || {}));
        let (one, one_stats) = render(1).unwrap();
        let (three, three_stats) = render(3).unwrap();
        assert_eq!(one.to_png(), three.to_png());
        assert_eq!(one_stats, three_stats);
    }
}

/// The eight-wide tree (AVX2) and the four-wide one give the same bytes and
/// statistics on every SPD scene; on a CPU without AVX2 both are four wide
/// (`build_with` does not read `RAYBOOK_NO_AVX2`).
#[test]
fn eight_wide_and_four_wide_trees_give_the_same_bytes_on_the_spd_scenes() {
    use raybook::wide::Width;
    for path in spd_scenes() {
        let scene = nff::load(&path).unwrap().with_size(96, 96);
        let four = WideBvh::build_with(&scene.objects, Width::Four);
        let eight = WideBvh::build_with(&scene.objects, Width::Eight);
        assert_eq!(four.width(), Width::Four);
        let (four, four_stats) = render(&scene, &four);
        let (eight, eight_stats) = render(&scene, &eight);
        assert_eq!(four.to_png(), eight.to_png(), "{}", path.display());
        assert_eq!(four_stats, eight_stats, "{}", path.display());
    }
}
