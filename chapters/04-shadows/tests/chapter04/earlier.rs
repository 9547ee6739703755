//! The chapter's exercises that later ones build on, checked first: a test
//! of the light's shadow ray (`ch04-light-is-free`) or of a whole picture
//! calls these before its own check, so that a mistake in `offset_origin`,
//! `shadow_ray` or `any_hit` is named there, and not blamed on the
//! exercise the test is about.

use ch04_shadows::toolkit::scene::{Object, Shape};
use ch04_shadows::toolkit::{Scene, Vec3};
use ch04_shadows::workbench::exercise::builds_on;
use ch04_shadows::{Hit, Ray, ShadowStart, any_hit, closest_hit, offset_origin, shadow_ray};

use super::{far_sphere, lit_point};

/// The top of a unit sphere at `center`, hit from above (normal +y), and
/// the same point of the plane y = `center.y` + 1 written with the normal
/// (0, −1, 0) (normal facing away from the ray).
pub(crate) fn hits_at(center: Vec3) -> [Hit; 2] {
    let ray = Ray::new(center + Vec3::new(0.0, 5.0, 0.0), Vec3::NEG_Y);
    let shapes = [
        Shape::Sphere {
            center,
            radius: 1.0,
        },
        Shape::Plane {
            normal: Vec3::NEG_Y,
            offset: center.y + 1.0,
        },
    ];
    shapes.map(|shape| {
        let object = [Object {
            shape,
            material: 0,
            shadows: true,
        }];
        closest_hit(&object, &ray, 0.0, f32::INFINITY).unwrap()
    })
}

/// `ch04-offset`: off the hit point, along the geometric normal, to the
/// side `towards` leaves by, by about the error bound e (at least e/2).
pub(crate) fn offset_first() {
    for hit in hits_at(Vec3::ZERO)
        .into_iter()
        .chain(hits_at(Vec3::splat(1e4)))
    {
        for towards in [Vec3::Y, Vec3::NEG_Y, Vec3::new(0.6, 0.8, 0.0)] {
            let moved = offset_origin(&hit, towards) - hit.point;
            let along = moved.dot(hit.normal);
            let side = along * hit.normal.dot(towards) > 0.0;
            let across = (moved - along * hit.normal).length();
            let size = along.abs() >= 0.5 * hit.error && along.abs() <= 4.0 * hit.error;
            builds_on(
                "ch04-offset",
                side && size && across <= 1e-3 * along.abs(),
                format_args!(
                    "offset_origin(hit at {}, normal {}, error bound {}; towards {towards}) \
                     moved the point by {moved}: it must move along the normal, to the side \
                     `towards` leaves by, by about the error bound (the tests \
                     the_offset_moves_… and offset::… say more)",
                    hit.point, hit.normal, hit.error
                ),
            );
        }
    }
}

/// `ch04-shadow-ray` (after `ch04-offset`): from the right origin, along l,
/// and t_max where the ray reaches the light.
pub(crate) fn shadow_ray_first() {
    offset_first();
    let scene: Scene = far_sphere();
    let ray = Ray::new(Vec3::new(10000.0, 10000.0, 10005.0), Vec3::NEG_Z);
    let (surface, incoming) = lit_point(&scene, &ray);
    let light = Vec3::new(10010.0, 10000.0, 10000.0);
    for (start, origin) in [
        (ShadowStart::HitPoint, surface.hit.point),
        (
            ShadowStart::Offset,
            offset_origin(&surface.hit, incoming.direction),
        ),
    ] {
        let (shadow, t_max) = shadow_ray(&surface, &incoming, start);
        let right = shadow.origin == origin
            && (shadow.direction - incoming.direction).length() < 1e-6
            && shadow.at(t_max).distance(light) < 0.01;
        builds_on(
            "ch04-shadow-ray",
            right,
            format_args!(
                "with {start:?}, shadow_ray gave origin {}, direction {}, t_max {t_max}; \
                 the light is at {light} (the tests the_shadow_ray_… say more)",
                shadow.origin, shadow.direction
            ),
        );
    }
}

/// `ch04-any-hit`: a blocker within (t_min, t_max) is found, one beyond
/// t_max is not, and an object with `shadows = false` never blocks.
pub(crate) fn any_hit_first() {
    let mut scene = far_sphere();
    let ray = Ray::new(
        Vec3::new(10000.0, 10000.0, 10003.0),
        Vec3::new(0.0, 0.0, -1.0),
    );
    let within = any_hit(&scene.objects, &ray, 0.0, 10.0);
    let beyond = any_hit(&scene.objects, &ray, 0.0, 1.5);
    scene.objects[0].shadows = false;
    let opted_out = any_hit(&scene.objects, &ray, 0.0, 10.0);
    builds_on(
        "ch04-any-hit",
        within && !beyond && !opted_out,
        format_args!(
            "a sphere 2 to 4 units ahead: any_hit within t_max = 10 gave {within} (true \
             expected), within 1.5 gave {beyond} (false expected), and with shadows = false \
             gave {opted_out} (false expected)"
        ),
    );
}

/// Every exercise of the chapter but `ch04-light-is-free`, checked first.
pub(crate) fn all_but_light_is_free() {
    shadow_ray_first();
    any_hit_first();
}
