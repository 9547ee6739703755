//! Where the shadow ray ends: t_max is measured from the ray's own origin
//! r0, the offset start, not from the hit point p.

use ch04_shadows::toolkit::Vec3;
use ch04_shadows::toolkit::scene::Shape;
use ch04_shadows::{Ray, ShadowStart, intersect, shadow_ray};
use ch04_shadows::{scene_files, toolkit::Scene};

use super::{earlier, lit_point};

/// A floor y = 0 and a point light 4 above its origin.
fn floor_under_light() -> Scene {
    let text = r#"
        [camera]
        eye = [0, 2, 6]
        look_at = [0, 0, 0]
        up = [0, 1, 0]
        vfov = 40
        [image]
        width = 8
        height = 8
        [materials.white]
        [[lights]]
        type = "point"
        position = [0, 4, 0]
        intensity = 16
        [[objects]]
        type = "plane"
        normal = [0, 1, 0]
        offset = 0
        material = "white"
    "#;
    scene_files::parse(text, "floor-under-light.toml").unwrap()
}

#[test]
fn t_max_is_measured_from_the_offset_origin_not_from_the_point() {
    earlier::offset_first();
    let scene = floor_under_light();
    let ray = Ray::new(Vec3::new(0.0, 1.0, 0.0), Vec3::NEG_Y);
    let (mut surface, incoming) = lit_point(&scene, &ray);
    // An error bound of 0.25, as a point 10⁶ from the origin could have:
    // the offset start r0 is 0.25 above p, so the light is 3.75 from r0.
    surface.hit.error = 0.25;
    let light = Vec3::new(0.0, 4.0, 0.0);
    let (shadow, t_max) = shadow_ray(&surface, &incoming, ShadowStart::Offset);
    // A blocker 0.1 beyond the light: between |p_L − r0| and |p_L − p|.
    let beyond = Shape::Plane {
        normal: Vec3::Y,
        offset: -4.1,
    };
    let blocked = intersect(&beyond, &shadow, 0.0, t_max).is_some();
    assert!(
        !blocked && (t_max - shadow.origin.distance(light)).abs() < 1e-4,
        "the shadow ray starts at r0 = {}, 0.25 above the floor point p = {}, and its t_max \
         is {t_max}: it ends at {}, while the light is at {light}{}. t_max is the distance \
         from the ray's own origin to the light, |p_L − r0| = {}; incoming.distance = \
         |p_L − p| = {} is measured from p, not from r0",
        shadow.origin,
        surface.hit.point,
        shadow.at(t_max),
        if blocked {
            ", so a plane 0.1 beyond the light blocks it"
        } else {
            ""
        },
        shadow.origin.distance(light),
        incoming.distance
    );
}
