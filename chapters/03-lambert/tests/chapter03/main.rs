//! Chapter 3: the cosine law, the spot cone, ambient light, and the picture.

use ch03_lambert::scene_files;
use ch03_lambert::toolkit::scene::Light;
use ch03_lambert::toolkit::{Color, Image, Scene, Vec3};
use ch03_lambert::workbench::snapshot::assert_image;
use ch03_lambert::{
    CHAPTER, Camera, Incoming, Ray, Surface, always_visible, closest_hit, direct_light, lambert,
    render_lambert, spot_factor,
};

fn render(scene: &Scene) -> Image {
    render_lambert(scene, || {}).0
}

/// A unit sphere at the origin seen from +z, lit by one point light placed
/// `degrees` away from the normal of the sphere's front point (0, 0, 1), at
/// distance 10 from that point.
fn sphere_lit_at(degrees: f32) -> Scene {
    let (s, c) = degrees.to_radians().sin_cos();
    let light = Vec3::new(0.0, 0.0, 1.0) + 10.0 * Vec3::new(s, 0.0, c);
    let text = format!(
        r#"
        [camera]
        eye = [0, 0, 5]
        look_at = [0, 0, 0]
        up = [0, 1, 0]
        vfov = 30
        [image]
        width = 41
        height = 41
        [materials.white]
        color = [0.9, 0.9, 0.9]
        [[lights]]
        type = "point"
        position = [{}, {}, {}]
        intensity = 50
        [[objects]]
        type = "sphere"
        center = [0, 0, 0]
        radius = 1
        material = "white"
        "#,
        light.x, light.y, light.z
    );
    scene_files::parse(&text, "cosine.toml").unwrap()
}

#[test]
fn cosine_law_head_on_versus_sixty_degrees() {
    // The centre pixel sees the point (0, 0, 1) whose normal is +z.
    let head_on = render(&sphere_lit_at(0.0)).get(20, 20);
    let at_sixty = render(&sphere_lit_at(60.0)).get(20, 20);
    // Head on: 0.9 × 50 / 10² = 0.45, below 1, so nothing is clamped.
    assert!(
        (head_on.x - 0.45).abs() < 1e-3,
        "head on, albedo 0.9 × irradiance 50/10² × cos 0° = 0.45, got {head_on} \
         (0.5: the albedo is missing; 0.0045: the 1/r² is applied twice; \
         0: l points away from the light)"
    );
    let ratio = at_sixty.x / head_on.x;
    assert!(
        (ratio - 0.5).abs() < 0.005,
        "at 60° the cosine law gives cos 60° = 0.5 of the head-on value, measured {ratio}"
    );
}

#[test]
fn a_light_behind_the_surface_adds_nothing() {
    let behind = render(&sphere_lit_at(120.0)).get(20, 20);
    assert_eq!(
        behind,
        Vec3::ZERO,
        "a light 120° from the normal is behind the surface"
    );
}

/// A floor of albedo (0.5, 0.6, 0.7) seen from straight above, with the
/// scene's `lights` (TOML), and the ray that sees its point (0, 0, 0).
fn floor_with(lights: &str) -> (Scene, Ray) {
    floor_facing(1.0, lights)
}

/// The same floor, its plane y = 0 written with the normal (0, `up`, 0).
fn floor_facing(up: f32, lights: &str) -> (Scene, Ray) {
    let text = format!(
        r#"
        [camera]
        eye = [0, 5, 0.001]
        look_at = [0, 0, 0]
        up = [0, 1, 0]
        vfov = 30
        [image]
        width = 9
        height = 9
        [materials.floor]
        color = [0.5, 0.6, 0.7]
        [[objects]]
        type = "plane"
        normal = [0, {up}, 0]
        offset = 0
        material = "floor"
        {lights}
        "#
    );
    let scene = scene_files::parse(&text, "floor.toml").unwrap();
    (scene, Ray::new(Vec3::new(0.0, 5.0, 0.0), Vec3::NEG_Y))
}

const ALBEDO: Vec3 = Vec3::new(0.5, 0.6, 0.7);

/// Light A: straight above at distance 4, intensity 16: irradiance 1, n·l = 1.
const LIGHT_A: &str = r#"
    [[lights]]
    type = "point"
    position = [0, 4, 0]
    intensity = 16
"#;

/// Light B: at (3, 4, 0), distance 5, intensity 25: irradiance its colour
/// (1, 0.5, 0.25), n·l = 0.8.
const LIGHT_B: &str = r#"
    [[lights]]
    type = "point"
    position = [3, 4, 0]
    color = [1, 0.5, 0.25]
    intensity = 25
"#;

/// Light C: below the floor, behind the surface the eye sees.
const LIGHT_C: &str = r#"
    [[lights]]
    type = "point"
    position = [0, -2, 0]
    intensity = 100
"#;

/// A spot light whose cone points away from the floor: dark there.
const SPOT_AWAY: &str = r#"
    [[lights]]
    type = "spot"
    position = [0, 4, 0]
    direction = [1, 0, 0]
    intensity = 100
    inner_angle = 10
    outer_angle = 20
"#;

const AMBIENTS: &str = r#"
    [[lights]]
    type = "ambient"
    color = [0.1, 0.2, 0.3]
    [[lights]]
    type = "ambient"
    color = [0.05, 0.05, 0.05]
"#;

/// A `reflect` for `direct_light`, given the surface.
type Reflect<'a> = &'a dyn Fn(&Surface, &Incoming) -> Color;

/// Chapter 3's direct light at the floor's point (0, 0, 0), with these
/// `visible` and `reflect` (None: Lambert's law).
fn light_at_floor(
    lights: &str,
    visible: impl FnMut(&Surface, &Incoming) -> bool,
    reflect: Option<Reflect>,
) -> Color {
    let (scene, ray) = floor_with(lights);
    let hit = closest_hit(&scene.objects, &ray, 0.0, f32::INFINITY).unwrap();
    let surface = Surface::new(&scene, hit, &ray);
    match reflect {
        None => direct_light(&scene, &surface, visible, |i| lambert(&surface, i)),
        Some(f) => direct_light(&scene, &surface, visible, |i| f(&surface, i)),
    }
}

fn close(a: Color, b: Color) -> bool {
    (a - b).abs().max_element() < 1e-5
}

#[test]
fn lambert_gives_the_cosine_law_and_nothing_from_behind() {
    let (scene, ray) = floor_with("");
    let hit = closest_hit(&scene.objects, &ray, 0.0, f32::INFINITY).unwrap();
    let surface = Surface::new(&scene, hit, &ray);
    let from = |direction: Vec3| Incoming {
        direction: direction.normalize(),
        distance: 2.0,
        irradiance: Vec3::new(2.0, 1.0, 0.5),
        casts_shadows: true,
    };
    let sixty = lambert(&surface, &from(Vec3::new(3f32.sqrt(), 1.0, 0.0)));
    let want = ALBEDO * Vec3::new(2.0, 1.0, 0.5) * 0.5;
    assert!(
        close(sixty, want),
        "light at 60° from the normal: albedo × irradiance × cos 60° = {want}, got {sixty}"
    );
    let behind = lambert(&surface, &from(Vec3::new(1.0, -1.0, 0.0)));
    assert_eq!(
        behind,
        Color::ZERO,
        "light from behind the surface (n·l < 0) must give nothing, not a negative amount"
    );
}

#[test]
fn a_plane_seen_from_its_back_is_lit_like_its_front() {
    let light = r#"
        [[lights]]
        type = "point"
        position = [1, 3, 0]
        intensity = 10
    "#;
    let front = render(&floor_facing(1.0, light).0).get(4, 4);
    let back = render(&floor_facing(-1.0, light).0).get(4, 4);
    assert!(front.x > 0.1, "the floor is lit: {front}");
    assert_eq!(
        back, front,
        "the floor written with normal (0, -1, 0) is seen from its back: it is lit like \
         its front (shade with the normal that faces the eye, Surface::normal)"
    );
}

#[test]
fn ambient_light_adds_albedo_times_its_colour_once() {
    // Two ambient lights, point lights whose reflection is zero: only the
    // ambient light is left.
    let lights = format!("{AMBIENTS}{LIGHT_A}{LIGHT_B}");
    let got = light_at_floor(&lights, always_visible, Some(&|_, _| Color::ZERO));
    let want = ALBEDO * Vec3::new(0.15, 0.25, 0.35);
    assert!(
        close(got, want),
        "each ambient light adds albedo × its colour, once: {want}, got {got} \
         (0: ambient forgotten; {}: ambient added once per light)",
        4.0 * want
    );
}

#[test]
fn the_lights_add_up_channel_by_channel() {
    let lights = format!("{AMBIENTS}{LIGHT_A}{LIGHT_B}");
    let ambient = ALBEDO * Vec3::new(0.15, 0.25, 0.35);
    let a = ALBEDO;
    let b = ALBEDO * Vec3::new(1.0, 0.5, 0.25) * 0.8;
    let got = light_at_floor(&lights, always_visible, None);
    assert!(
        close(got, ambient + a + b),
        "ambient + light A + light B = {}, got {got} (multiplied instead of added: {})",
        ambient + a + b,
        ambient * a * b
    );
}

#[test]
fn a_light_that_is_not_visible_adds_nothing() {
    let lights = format!("{LIGHT_A}{LIGHT_B}");
    // Light B (the one off to the side, +x) is blocked.
    let got = light_at_floor(&lights, |_, i| i.direction.x <= 0.0, None);
    assert!(
        close(got, ALBEDO),
        "`visible` says light B is blocked, so only light A adds: {ALBEDO}, got {got}"
    );
}

#[test]
fn a_light_behind_the_surface_is_skipped_whatever_reflect_says() {
    // A `reflect` that does not clamp: n·l itself, negative for light C.
    let lights = format!("{LIGHT_A}{LIGHT_C}");
    let n_dot_l: Reflect = &|s, i| Color::splat(s.normal.dot(i.direction));
    let got = light_at_floor(&lights, always_visible, Some(n_dot_l));
    assert!(
        close(got, Color::ONE),
        "light A adds n·l = 1, light C behind the surface must be skipped (n·l ≤ 0), \
         got {got} (0: light C subtracted its n·l = −1)"
    );
}

#[test]
fn visible_is_asked_only_about_lights_that_could_add_something() {
    let lights = format!("{AMBIENTS}{LIGHT_A}{LIGHT_B}{LIGHT_C}{SPOT_AWAY}");
    let mut asked = Vec::new();
    light_at_floor(
        &lights,
        |_, i| {
            asked.push(i.direction);
            true
        },
        None,
    );
    assert_eq!(
        asked.len(),
        2,
        "visible must be asked about lights A and B only (chapter 4 traces a shadow ray \
         for each question), not about ambient light, light C behind the surface or a \
         spot whose cone misses: asked about {asked:?}"
    );
    let mut asked = 0;
    light_at_floor(
        &lights,
        |_, _| {
            asked += 1;
            true
        },
        Some(&|_, _| Color::ZERO),
    );
    assert_eq!(
        asked, 0,
        "reflect gives zero for every light (a black mirror): visible must not be asked"
    );
}

#[test]
fn spot_factor_is_one_inside_zero_outside_and_smooth_between() {
    let axis = Vec3::new(0.0, -1.0, 0.0);
    let at = |deg: f32| {
        let r = deg.to_radians();
        spot_factor(axis, 10.0, 20.0, Vec3::new(r.sin(), -r.cos(), 0.0))
    };
    for deg in [0.0, 5.0, 9.9] {
        assert_eq!(at(deg), 1.0, "{deg}° is inside the inner cone (10°)");
    }
    for deg in [20.1, 45.0, 90.0, 180.0] {
        assert_eq!(at(deg), 0.0, "{deg}° is outside the outer cone (20°)");
    }
    let (a, b, c) = (at(12.0), at(15.0), at(18.0));
    assert!(
        1.0 > a && a > b && b > c && c > 0.0,
        "between the cones the factor falls from 1 to 0: at 12°, 15°, 18°: {a} {b} {c}"
    );
    // s = 1/4 of the way from the outer cosine to the inner one.
    let (cos_inner, cos_outer) = (10f32.to_radians().cos(), 20f32.to_radians().cos());
    let angle = (cos_outer + 0.25 * (cos_inner - cos_outer))
        .acos()
        .to_degrees();
    let quarter = at(angle);
    assert!(
        (quarter - 0.15625).abs() < 1e-3,
        "at s = 1/4 (of the way between the cosines) the smooth step 3s² − 2s³ is \
         0.15625, got {quarter} (0.25: a linear ramp; about 0.10: s measured in degrees \
         instead of cosines)"
    );
}

/// The default scene with only its spot light (and ambient light).
fn spot_only() -> Scene {
    let mut scene = CHAPTER.default_scene().unwrap().with_size(160, 120);
    scene.lights.retain(|l| !matches!(l, Light::Point { .. }));
    scene
}

#[test]
fn nothing_is_lit_outside_the_spot_cone() {
    let scene = spot_only();
    let Some(&Light::Spot {
        position,
        direction,
        outer_degrees,
        ..
    }) = scene
        .lights
        .iter()
        .find(|l| matches!(l, Light::Spot { .. }))
    else {
        panic!("the default scene has a spot light")
    };
    let Some(&Light::Ambient { color: ambient }) = scene
        .lights
        .iter()
        .find(|l| matches!(l, Light::Ambient { .. }))
    else {
        panic!("the default scene has ambient light")
    };
    let image = render(&scene);
    let camera = Camera::new(&scene.camera, 160, 120);
    let (mut inside, mut outside) = (0, 0);
    for y in 0..120 {
        for x in 0..160 {
            let ray: Ray = camera.primary_ray(x, y);
            let Some(hit) = closest_hit(&scene.objects, &ray, 0.0, f32::INFINITY) else {
                continue;
            };
            let from_light = (hit.point - position).normalize();
            let angle = direction.angle_between(from_light).to_degrees();
            let albedo = scene.material(&scene.objects[hit.object]).color;
            let pixel = image.get(x, y);
            if angle > outer_degrees + 0.01 {
                outside += 1;
                assert_eq!(pixel, albedo * ambient, "pixel ({x}, {y}) at {angle}°");
            } else if angle < outer_degrees - 1.0 && pixel.x > (albedo * ambient).x * 2.0 {
                inside += 1;
            }
        }
    }
    assert!(
        outside > 1000 && inside > 200,
        "{outside} outside, {inside} lit inside"
    );
}

#[test]
fn ambient_only_is_exactly_albedo_times_ambient() {
    let mut scene = CHAPTER.default_scene().unwrap().with_size(80, 60);
    let ambient = Vec3::new(0.3, 0.2, 0.1);
    scene.lights = vec![Light::Ambient { color: ambient }];
    let image = render(&scene);
    let camera = Camera::new(&scene.camera, 80, 60);
    for y in 0..60 {
        for x in 0..80 {
            let hit = closest_hit(
                &scene.objects,
                &camera.primary_ray(x, y),
                0.0,
                f32::INFINITY,
            );
            let expected = match hit {
                Some(hit) => scene.material(&scene.objects[hit.object]).color * ambient,
                None => scene.image.background,
            };
            assert_eq!(image.get(x, y), expected, "pixel ({x}, {y})");
        }
    }
}

#[test]
fn colours_are_clamped_when_written() {
    let mut scene = sphere_lit_at(0.0);
    scene.lights[0] = match scene.lights[0].clone() {
        Light::Point {
            position,
            color,
            shadows,
            falloff,
            ..
        } => Light::Point {
            position,
            color,
            intensity: 1e4,
            shadows,
            falloff,
        },
        other => other,
    };
    let image = render(&scene);
    assert!(
        image.get(20, 20).x > 1.0,
        "linear values may exceed 1 while shading"
    );
    assert_eq!(image.to_rgb8().get_pixel(20, 20).0, [255, 255, 255]);
}

#[test]
fn snapshot_default() {
    let scene = CHAPTER.default_scene().unwrap().with_size(160, 120);
    assert_image("03-lambert", "default", &render(&scene));
}
