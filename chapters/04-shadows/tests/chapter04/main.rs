//! Chapter 4: shadow rays block what they should, and nothing else.

use ch03_lambert::scene_files;
use ch03_lambert::{Arrival, arrival};
use ch04_shadows::toolkit::scene::{Light, Shape};
use ch04_shadows::toolkit::{Image, Scene, Stats, Vec3};
use ch04_shadows::{
    CHAPTER, Incoming, Ray, ShadowStart, Surface, any_hit, closest_hit, light_is_free,
    offset_origin, render_shadows, shadow_ray,
};

/// The earlier exercises, checked first by the tests that build on them.
mod earlier;

fn render(scene: &Scene, origin: ShadowStart) -> Image {
    render_shadows(scene, origin, || {}).0
}

/// Chapter 3's picture of the same scene: every light free everywhere.
fn unshadowed(scene: &Scene) -> Image {
    ch03_lambert::render_lambert(scene, || {}).0
}

/// Pixels darker with shadow rays than without: in a scene where nothing
/// can block anything, each one is acne.
fn shadowed_pixels(scene: &Scene, origin: ShadowStart) -> usize {
    let free = unshadowed(scene);
    let shadowed = render(scene, origin);
    let lit = free.pixels.iter().filter(|c| c.max_element() > 0.0).count();
    assert!(
        lit > scene.image.width as usize * 10,
        "the test scene must be lit: {lit}"
    );
    free.pixels
        .iter()
        .zip(&shadowed.pixels)
        .filter(|(a, b)| a != b)
        .count()
}

/// One of this chapter's scene files.
fn scene_file(name: &str) -> Scene {
    scene_files::load(format!("{}/scenes/{name}", env!("CARGO_MANIFEST_DIR"))).unwrap()
}

/// A floor lit by a light 1° above its horizon, seen from above
/// (`scenes/acne.toml`). The floor is tilted a little (normal (0.2, 1, 0.1)):
/// on a level floor y = 0 the hit points put back onto the plane come out
/// exact, and even rays without an offset would show no acne.
fn grazing_floor() -> Scene {
    scene_file("acne.toml")
}

/// A sphere far from the origin (around 1e4), lit from the side
/// (`scenes/acne-far.toml`).
fn far_sphere() -> Scene {
    scene_file("acne-far.toml")
}

/// "N wrongly shadowed pixels" with what it means.
fn acne(pixels: usize) -> String {
    format!(
        "{pixels} pixels wrongly shadowed in a scene where nothing blocks anything: shadow \
         acne, the shadow ray hits its own surface (start it at offset_origin)"
    )
}

#[test]
fn no_acne_on_a_floor_lit_at_a_grazing_angle() {
    earlier::offset_first();
    earlier::any_hit_first();
    let pixels = shadowed_pixels(&grazing_floor(), ShadowStart::Offset);
    assert_eq!(pixels, 0, "{}", acne(pixels));
}

#[test]
fn no_acne_on_the_same_floor_far_from_the_origin() {
    earlier::offset_first();
    earlier::any_hit_first();
    let far = grazing_floor().translated(Vec3::new(1e4, 0.0, 1e4));
    let pixels = shadowed_pixels(&far, ShadowStart::Offset);
    assert_eq!(pixels, 0, "{}", acne(pixels));
}

#[test]
fn no_acne_on_a_sphere_far_from_the_origin() {
    earlier::offset_first();
    earlier::any_hit_first();
    let pixels = shadowed_pixels(&far_sphere(), ShadowStart::Offset);
    assert_eq!(pixels, 0, "{}", acne(pixels));
}

#[test]
fn without_the_offset_the_same_scenes_show_acne() {
    earlier::offset_first();
    earlier::any_hit_first();
    // The three tests above could fail: here is the failure they guard against.
    let floor = shadowed_pixels(&grazing_floor(), ShadowStart::HitPoint);
    let far_floor = shadowed_pixels(
        &grazing_floor().translated(Vec3::new(1e4, 0.0, 1e4)),
        ShadowStart::HitPoint,
    );
    let sphere = shadowed_pixels(&far_sphere(), ShadowStart::HitPoint);
    let pixels = 160 * 120;
    println!(
        "acne without offset: floor {floor}, far floor {far_floor}, far sphere {sphere} of {pixels}"
    );
    let message = "with ShadowStart::HitPoint the shadow ray starts at the hit point itself, \
                   and these scenes show acne";
    assert!(floor > pixels / 100, "{message}: floor {floor}");
    assert!(far_floor > pixels / 100, "{message}: far floor {far_floor}");
    assert!(sphere > 100, "{message}: far sphere {sphere}");
}

#[test]
fn the_offset_moves_to_the_lights_side_and_scales_with_magnitude() {
    // A unit sphere near the origin and one far from it, hit from above.
    let ([near, _], [far, _]) = (
        earlier::hits_at(Vec3::ZERO),
        earlier::hits_at(Vec3::splat(1e4)),
    );
    let moved = |hit: &ch04_shadows::Hit| offset_origin(hit, Vec3::Y).y - hit.point.y;
    assert!(
        moved(&near) > 0.0,
        "the origin must move off the surface: offset_origin gave the hit point itself"
    );
    assert!(
        moved(&far) > 1000.0 * moved(&near),
        "the offset grows with the coordinates' magnitude (hit.error), not a fixed \
         epsilon: moved {} near the origin, {} at 10⁴ (where one f32 step is 0.001)",
        moved(&near),
        moved(&far)
    );
    for hit in [near, far] {
        let up = offset_origin(&hit, Vec3::Y);
        let down = offset_origin(&hit, -Vec3::Y);
        assert!(
            up.y > hit.point.y && down.y < hit.point.y,
            "the origin moves to the side the ray leaves by: up for a ray going up, down \
             for one going down; from {} got {up} and {down}",
            hit.point
        );
        assert_eq!(
            (up.x, up.z),
            (hit.point.x, hit.point.z),
            "the origin moves along the normal (0, 1, 0) only"
        );
    }
}

#[test]
fn a_blocker_between_point_and_light_blocks_it_one_behind_does_not() {
    let scene = far_sphere();
    let ray = Ray::new(
        Vec3::new(10000.0, 10000.0, 10003.0),
        Vec3::new(0.0, 0.0, -1.0),
    );
    assert!(
        any_hit(&scene.objects, &ray, 0.0, 10.0),
        "the sphere is 2 to 4 units ahead, within t_max = 10: it is hit"
    );
    assert!(
        !any_hit(&scene.objects, &ray, 0.0, 1.5),
        "the sphere is 2 to 4 units ahead, beyond t_max = 1.5: it is not hit"
    );
    let mut behind = scene.clone();
    behind.objects[0].shadows = false;
    assert!(
        !any_hit(&behind.objects, &ray, 0.0, 10.0),
        "an object with shadows = false blocks nothing"
    );
}

/// The hit of `ray` on `scene`, the surface it sees, and what the scene's
/// first light that is not ambient sends there.
fn lit_point<'a>(scene: &'a Scene, ray: &Ray) -> (Surface<'a>, Incoming) {
    let hit = closest_hit(&scene.objects, ray, 0.0, f32::INFINITY).unwrap();
    let surface = Surface::new(scene, hit, ray);
    let incoming = scene
        .lights
        .iter()
        .find_map(|light| match arrival(light, hit.point) {
            Arrival::Incoming(incoming) => Some(incoming),
            _ => None,
        })
        .unwrap();
    (surface, incoming)
}

/// Checks the shadow ray from the front of the far sphere that `start` gives.
fn check_shadow_ray(start: ShadowStart) {
    // The sphere near (10⁴, 10⁴, 10⁴) seen head on; its light is off to the side.
    let scene = far_sphere();
    let ray = Ray::new(Vec3::new(10000.0, 10000.0, 10005.0), Vec3::NEG_Z);
    let (surface, incoming) = lit_point(&scene, &ray);
    let light = Vec3::new(10010.0, 10000.0, 10000.0);
    let (shadow, t_max) = shadow_ray(&surface, &incoming, start);
    let origin = match start {
        ShadowStart::Offset => offset_origin(&surface.hit, incoming.direction),
        ShadowStart::HitPoint => surface.hit.point,
    };
    assert_eq!(
        shadow.origin, origin,
        "{start:?}: the shadow ray starts at {origin} (Offset: offset_origin(hit, l), \
         off the surface; HitPoint: the hit point itself)"
    );
    assert!(
        (shadow.direction - incoming.direction).length() < 1e-6,
        "the shadow ray points from the surface towards the light, along the unit l = \
         {}, got {} (from the light to the surface is -l)",
        incoming.direction,
        shadow.direction
    );
    let end = shadow.at(t_max);
    assert!(
        end.distance(light) < 0.01,
        "t_max is where the shadow ray reaches the light: {}, got {t_max}: {}",
        shadow.origin.distance(light),
        if t_max.is_infinite() {
            "the shadow ray has no end, so it went beyond the light: a blocker behind the \
             light would shadow the point. t_max must be the distance to the light"
                .to_owned()
        } else if end.distance(shadow.origin) > light.distance(shadow.origin) {
            format!("the ray ends at {end}, beyond the light")
        } else if t_max.is_nan() {
            "t_max is not a number".to_owned()
        } else if t_max == 1.0 {
            format!(
                "the ray ends at {end}, short of the light: its direction is a unit vector, so \
                 t = 1 is one unit along it, not the light"
            )
        } else {
            format!("the ray ends at {end}, short of the light")
        }
    );
}

#[test]
fn the_shadow_ray_goes_from_the_surface_to_the_light() {
    // Started at the hit point itself: this needs no offset_origin yet.
    check_shadow_ray(ShadowStart::HitPoint);
}

#[test]
fn the_shadow_ray_starts_at_the_offset_origin() {
    check_shadow_ray(ShadowStart::Offset);
}

/// A floor and a ceiling (y = 0 and y = 4) with a point light between them
/// at (0, 2, 0): nothing stands between any point and the light.
fn floor_and_ceiling() -> Scene {
    let text = r#"
        [camera]
        eye = [0, 1.5, 6]
        look_at = [0, 1.5, 0]
        up = [0, 1, 0]
        vfov = 70
        [image]
        width = 40
        height = 30
        [materials.white]
        color = [0.8, 0.8, 0.8]
        [[lights]]
        type = "point"
        position = [0, 2, 0]
        intensity = 10
        [[objects]]
        type = "plane"
        normal = [0, 1, 0]
        offset = 0
        material = "white"
        [[objects]]
        type = "plane"
        normal = [0, 1, 0]
        offset = -4
        material = "white"
    "#;
    scene_files::parse(text, "floor-and-ceiling.toml").unwrap()
}

#[test]
fn a_blocker_beyond_the_light_casts_no_shadow() {
    earlier::all_but_light_is_free();
    let scene = floor_and_ceiling();
    let (shadowed, stats) = render_shadows(&scene, ShadowStart::Offset, || {});
    let free = unshadowed(&scene);
    let darker = free
        .pixels
        .iter()
        .zip(&shadowed.pixels)
        .filter(|(a, b)| a != b)
        .count();
    assert!(
        stats.shadow > 1000,
        "shadow rays are traced: {}",
        stats.shadow
    );
    assert_eq!(
        darker, 0,
        "{darker} pixels of floor and ceiling are darkened by the other plane, on the far \
         side of the light: the shadow ray went beyond the light, though shadow_ray's \
         t_max is right (checked first): light_is_free must ask any_hit up to that t_max"
    );
}

#[test]
fn a_blocker_just_before_the_light_casts_a_shadow() {
    earlier::all_but_light_is_free();
    // A light 4 above the floor, a small ball 3.5 to 3.9 above it: from the
    // floor point below, the ball covers the last eighth of the way. Its
    // shadow on the floor is a disc of radius 3.6.
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
        [[objects]]
        type = "sphere"
        center = [0, 3.7, 0]
        radius = 0.2
        material = "white"
    "#;
    let scene = scene_files::parse(text, "ball-under-light.toml").unwrap();
    let is_free = |x: f32| {
        let ray = Ray::new(Vec3::new(x, 1.0, 0.0), Vec3::NEG_Y);
        let (surface, incoming) = lit_point(&scene, &ray);
        let mut stats = Stats::default();
        let free = light_is_free(
            &scene.objects[..],
            &surface,
            &incoming,
            ShadowStart::Offset,
            &mut stats,
        );
        assert_eq!(
            stats.shadow, 1,
            "one shadow ray per light, counted in stats.shadow"
        );
        free
    };
    assert!(
        is_free(6.0),
        "from (6, 0, 0) nothing stands between the floor and the light: it is free there"
    );
    assert!(
        !is_free(0.0),
        "the ball 3.5 to 3.9 along the way to the light, 4 away, blocks it: the shadow \
         ray stopped short of the light"
    );
}

#[test]
fn objects_that_opt_out_cast_no_shadow() {
    earlier::all_but_light_is_free();
    let mut scene = CHAPTER.default_scene().unwrap().with_size(80, 60);
    for object in &mut scene.objects {
        object.shadows = false;
    }
    let (image, stats) = render_shadows(&scene, ShadowStart::Offset, || {});
    assert!(
        image == unshadowed(&scene),
        "objects with shadows = false block no light: the picture is chapter 3's"
    );
    assert!(
        stats.shadow > 0,
        "the lights still cast shadows, so shadow rays are traced and counted in \
         stats.shadow: {}",
        stats.shadow
    );
}

#[test]
fn lights_that_opt_out_trace_no_shadow_ray() {
    earlier::all_but_light_is_free();
    let mut scene = CHAPTER.default_scene().unwrap().with_size(80, 60);
    for light in &mut scene.lights {
        if let Light::Point { shadows, .. } | Light::Spot { shadows, .. } = light {
            *shadows = false;
        }
    }
    let (image, stats) = render_shadows(&scene, ShadowStart::Offset, || {});
    assert_eq!(
        stats.shadow, 0,
        "a light with shadows = false is free without a shadow ray"
    );
    assert!(
        image == unshadowed(&scene),
        "lights with shadows = false reach everything: the picture is chapter 3's"
    );
}

#[test]
fn the_box_keeps_its_light_inside() {
    earlier::all_but_light_is_free();
    let scene = scene_file("box.toml").with_size(80, 60);
    let Some(&Light::Ambient { color: ambient }) = scene.lights.first() else {
        panic!("the box scene starts with its ambient light")
    };
    let image = render(&scene, ShadowStart::Offset);
    let camera = ch04_shadows::Camera::new(&scene.camera, 80, 60);
    for y in 0..60 {
        for x in 0..80 {
            let ray = camera.primary_ray(x, y);
            let hit = ch04_shadows::closest_hit(&scene.objects, &ray, 0.0, f32::INFINITY);
            let expected = match hit {
                Some(hit) => scene.material(&scene.objects[hit.object]).color * ambient,
                None => scene.image.background,
            };
            assert_eq!(image.get(x, y), expected, "pixel ({x}, {y})");
        }
    }
    // And the box does matter: without the walls the floor is lit.
    let mut open = scene.clone();
    open.objects
        .retain(|o| !matches!(o.shape, Shape::Triangle { .. }));
    assert_ne!(
        render(&open, ShadowStart::Offset),
        render(&scene, ShadowStart::Offset)
    );
}

/// The chapter's pictures, against their references.
mod pictures;

// Last: `workbook progress` ranks failures in this file's order, theirs after these.
/// The text's Rust listings, each a test, checked equal to the text.
mod listings;
/// The offset's margin: on thousands of hits, checked again in f64.
mod offset;
/// The ray tree names the object that blocks a shadow ray.
mod ray_tree;
/// t_max from the shadow ray's own origin, not from the hit point.
mod reach;
