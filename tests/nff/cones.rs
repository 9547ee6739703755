//! Cones (`c`): on three lines or one, inside out, and cut short.

use raybook::nff;
use raybook::toolkit::Vec3;
use raybook::toolkit::scene::Shape;

use super::{GOOD, broken, shapes_of, with_line};

/// The one cone of a `c` entity: its base, base radius, apex, apex radius
/// and whether it is inside out.
fn the_cone(objects: &str) -> (Vec3, f32, Vec3, f32, bool) {
    match shapes_of(objects)[..] {
        [
            Shape::Cone {
                base,
                base_radius,
                apex,
                apex_radius,
                inside_out,
            },
        ] => (base, base_radius, apex, apex_radius, inside_out),
        ref other => panic!("a `c` entity is one cone, found {other:?}"),
    }
}

#[test]
fn a_cylinder_on_three_lines_is_one_cone_shape() {
    // NFF's form: `c`, then the base and the apex on lines of their own.
    let cone = the_cone("c\n1 2 0 0.5\n1 2 3 0.5\n");
    let (base, apex) = (Vec3::new(1.0, 2.0, 0.0), Vec3::new(1.0, 2.0, 3.0));
    assert_eq!(cone, (base, 0.5, apex, 0.5, false));
}

#[test]
fn a_pointed_cone_may_stand_on_one_line() {
    // The SPD generators' form: all eight numbers on the `c` line.
    let cone = the_cone("c 0 0 0 1 0 0 1 0\n");
    assert_eq!(cone, (Vec3::ZERO, 1.0, Vec3::Z, 0.0, false));
}

#[test]
fn negative_radii_turn_a_cone_inside_out() {
    let cone = the_cone("c 0 0 0 -1 0 0 2 -0.5\n");
    assert_eq!(cone, (Vec3::ZERO, 1.0, 2.0 * Vec3::Z, 0.5, true));
    // Its normals point towards the axis: a ray from the axis meets a wall
    // whose normal faces back towards it.
    let scene = nff::parse(
        &format!(
            "{}c 0 0 0 -1 0 0 2 -0.5\n",
            &GOOD[..GOOD.find("s 0 0 0 1").unwrap()]
        ),
        "inside.nff",
    )
    .unwrap();
    let ray = raybook::tracer::Ray::new(Vec3::new(0.0, 0.0, 1.0), Vec3::X);
    let hit = raybook::tracer::closest_hit(&scene.objects, &ray, 0.0, f32::INFINITY).unwrap();
    // Outward it would be d̂ + (r_b − r_a)/h·w = (1, 0, 0.25), normalised.
    let inward = -Vec3::new(1.0, 0.0, 0.25).normalize();
    assert!((hit.normal - inward).length() < 1e-6, "{}", hit.normal);
}

#[test]
fn a_cone_that_ends_early_names_its_line() {
    let e = broken(&format!(
        "{}c\n0 0 0 1\n",
        &GOOD[..GOOD.find("s 0 0 0 1").unwrap()]
    ));
    assert!(e.message.contains("the apex of the cone"), "{e}");
    assert_eq!(e.line, Some(13));
    let e = broken(&with_line(13, "c\n0 0 0 1\n0 0 1 -1"));
    assert_eq!(e.line, Some(15), "the apex's line");
    assert_eq!(e.column, Some(7), "at the radius");
}
