//! Chapter 5: the mirror law, the mirror ray, the highlight, the recursion
//! (against a tracer whose answers the test fixes, and in two facing mirrors
//! whose pixels are known exactly), and the pictures.

use ch05_reflection::scene_files;
use std::sync::Mutex;

use ch05_reflection::toolkit::{Color, Image, Scene, Stats, Vec3};
use ch05_reflection::workbench::snapshot::assert_image;
use ch05_reflection::{
    CHAPTER, Incoming, Path, Ray, Secondary, SecondaryKind, Surface, Whitted, World, closest_hit,
    follow_secondary_rays, highlight, mirror_ray, reflect, render_mirrors, trace,
};

/// A mirror floor (y = 0) under a blue-grey sky, shiny, in ambient light.
const FLOOR: &str = r#"
[camera]
eye = [0.0, 1.0, 3.0]
look_at = [0.0, 0.0, 0.0]
up = [0.0, 1.0, 0.0]
vfov = 40.0

[image]
width = 4
height = 3
background = [0.2, 0.4, 0.6]

[materials.floor]
color = [0.5, 0.5, 0.5]
reflectance = [0.3, 0.3, 0.3]
specular = 0.5
shininess = 8.0

[[lights]]
type = "ambient"
color = [0.2, 0.2, 0.2]

[[objects]]
type = "plane"
normal = [0.0, 1.0, 0.0]
offset = 0.0
material = "floor"
"#;

fn floor() -> Scene {
    scene_files::parse(FLOOR, "floor.toml").unwrap()
}

/// The point of the floor every test ray aims at: away from the origin, so
/// that its coordinates carry a rounding error that the offset must clear.
const SPOT: Vec3 = Vec3::new(0.3, 0.0, 0.7);

/// The ray that arrives at [`SPOT`] from above along `direction`.
fn arriving(direction: Vec3) -> Ray {
    let direction = direction.normalize();
    Ray {
        origin: SPOT - 2.0 * direction,
        direction,
    }
}

/// The floor as the ray sees it where it hits.
fn surface<'a>(scene: &'a Scene, ray: &Ray) -> Surface<'a> {
    let hit = closest_hit(&scene.objects, ray, 0.0, f32::INFINITY).expect("the ray hits the floor");
    Surface::new(scene, hit, ray)
}

fn close(a: Color, b: Color) -> bool {
    (a - b).abs().max_element() < 1e-5
}

// The mirror law.

#[test]
fn a_ray_at_45_degrees_leaves_at_45_degrees() {
    let s = 0.5f32.sqrt();
    let d = Vec3::new(s, -s, 0.0);
    let out = reflect(d, Vec3::Y);
    assert!(
        (out - Vec3::new(s, s, 0.0)).length() < 1e-7,
        "reflect({d}, n = +y) gave {out}: expected {}, the part along n reversed and the part \
         across n kept",
        Vec3::new(s, s, 0.0)
    );
    // Angle in = angle out, and the length is kept.
    assert!((d.dot(-Vec3::Y) - out.dot(Vec3::Y)).abs() < 1e-7);
    assert!((out.length() - d.length()).abs() < 1e-7);
}

#[test]
fn straight_on_comes_straight_back() {
    let out = reflect(Vec3::NEG_Z, Vec3::Z);
    assert!(
        (out - Vec3::Z).length() < 1e-7,
        "a ray straight onto a mirror comes straight back: reflect(-z, +z) gave {out}"
    );
}

#[test]
fn the_mirror_law_does_not_care_which_way_the_normal_points() {
    let d = Vec3::new(0.48, -0.6, 0.64);
    let n = Vec3::new(0.0, 0.8, 0.6);
    let (up, down) = (reflect(d, n), reflect(d, -n));
    assert!((up - down).length() < 1e-6, "{up} and {down}");
    assert!(
        (up.dot(n) + d.dot(n)).abs() < 1e-6,
        "the part along n must be reversed: d·n = {}, out·n = {}",
        d.dot(n),
        up.dot(n)
    );
}

// The mirror ray.

#[test]
fn the_mirror_ray_leaves_at_the_mirror_angle_from_just_above_the_surface() {
    let scene = floor();
    let s = 0.5f32.sqrt();
    let incoming = arriving(Vec3::new(s, -s, 0.0));
    let surface = surface(&scene, &incoming);
    let weight = Color::new(0.1, 0.2, 0.4);
    let Some(mirror) = mirror_ray(&surface, &incoming, weight) else {
        panic!("a weight of {weight} spawns a mirror ray, but mirror_ray gave none");
    };
    let expected = Vec3::new(s, s, 0.0);
    assert!(
        (mirror.ray.direction - expected).length() < 1e-6,
        "the mirror ray goes {}: expected the mirror direction {expected} (angle out = angle in)",
        mirror.ray.direction
    );
    let above = (mirror.ray.origin - surface.hit.point).dot(Vec3::Y);
    assert!(
        above > 0.0,
        "the mirror ray starts {above} along the normal from the hit point: it must start just \
         off the surface on the side it leaves to (offset_origin), or it can hit its own surface"
    );
    assert_eq!(
        mirror.weight, weight,
        "the mirror ray carries the weight it is given ({weight}), not the material's \
         reflectance: chapter 6 passes more than the reflectance"
    );
    assert_eq!(
        mirror.kind,
        SecondaryKind::Reflection,
        "a mirror ray is counted as a reflection"
    );
}

#[test]
fn a_zero_weight_spawns_no_mirror_ray() {
    let scene = floor();
    let incoming = arriving(Vec3::new(0.3, -1.0, 0.2));
    let surface = surface(&scene, &incoming);
    assert_eq!(
        mirror_ray(&surface, &incoming, Color::ZERO),
        None,
        "a mirror ray of weight zero would add nothing: spawn none"
    );
}

// The highlight.

/// Light arriving from `direction` (towards the light) with irradiance (2, 1, 0.5).
fn light_from(direction: Vec3) -> Incoming {
    Incoming {
        direction: direction.normalize(),
        distance: 3.0,
        irradiance: Color::new(2.0, 1.0, 0.5),
        casts_shadows: false,
    }
}

#[test]
fn the_highlight_is_brightest_where_the_lights_mirror_image_is_seen() {
    let scene = floor();
    // specular 0.5 × irradiance (2, 1, 0.5), with h = n: cos = 1.
    let peak = Color::new(1.0, 0.5, 0.25);
    let s = 0.5f32.sqrt();
    for (eye_ray, light, case) in [
        (Vec3::NEG_Y, Vec3::Y, "eye and light straight above"),
        (
            Vec3::new(s, -s, 0.0),
            Vec3::new(s, s, 0.0),
            "eye and light at 45° on either side of the normal",
        ),
    ] {
        let ray = arriving(eye_ray);
        let found = highlight(&surface(&scene, &ray), &light_from(light));
        assert!(
            close(found, peak),
            "{case}: the halfway vector of the directions to the light and to the eye is the \
             normal, so the highlight is specular × irradiance = {peak}; found {found}"
        );
    }
}

#[test]
fn the_highlight_falls_off_with_the_halfway_angle_to_the_power_shininess() {
    let scene = floor();
    // Eye straight above, light 60° from the normal: h is 30° from n.
    let ray = arriving(Vec3::NEG_Y);
    let (s, c) = 60f32.to_radians().sin_cos();
    let found = highlight(&surface(&scene, &ray), &light_from(Vec3::new(s, c, 0.0)));
    let expected = 0.5 * Color::new(2.0, 1.0, 0.5) * 30f32.to_radians().cos().powf(8.0);
    assert!(
        close(found, expected),
        "eye above, light 60° off the normal: h lies 30° from n, so the highlight is \
         specular × irradiance × cos(30°)^8 = {expected}; found {found} (is h a unit vector?)"
    );
}

#[test]
fn a_matte_surface_has_no_highlight() {
    let mut scene = floor();
    scene.materials[0].specular = 0.0;
    let ray = arriving(Vec3::NEG_Y);
    let found = highlight(&surface(&scene, &ray), &light_from(Vec3::Y));
    assert_eq!(found, Color::ZERO, "specular 0: no highlight");
}

// The recursion, against a tracer whose answers the test fixes.

/// A tracer with a fixed local colour and fixed secondary rays into the sky
/// (they see the background), which records what `may_trace` is asked.
struct Probe {
    local: Color,
    rays: [Option<Secondary>; 2],
    allow: bool,
    asked: Mutex<Vec<(u32, Color)>>,
}

impl Probe {
    fn new(rays: [Option<Secondary>; 2], allow: bool) -> Probe {
        Probe {
            local: Color::new(0.1, 0.2, 0.3),
            rays,
            allow,
            asked: Mutex::new(Vec::new()),
        }
    }

    fn asked(&self) -> Vec<(u32, Color)> {
        self.asked.lock().unwrap().clone()
    }
}

impl Whitted for Probe {
    fn local(&self, _: &Scene, _: &(impl World + ?Sized), _: &Surface, _: &mut Stats) -> Color {
        self.local
    }

    fn secondary_rays(&self, _: &Surface, _: &Ray) -> [Option<Secondary>; 2] {
        self.rays
    }

    fn may_trace(&self, depth: u32, weight: Color, _: &mut Stats) -> bool {
        self.asked.lock().unwrap().push((depth, weight));
        self.allow && depth < 100
    }
}

/// A secondary ray from above the floor straight up, into the sky.
fn to_the_sky(weight: Color, kind: SecondaryKind) -> Option<Secondary> {
    Some(Secondary {
        ray: Ray {
            origin: Vec3::new(0.0, 1.0, 0.0),
            direction: Vec3::Y,
        },
        weight,
        kind,
    })
}

const MIRROR_WEIGHT: Color = Color::new(0.5, 0.5, 0.25);
const GLASS_WEIGHT: Color = Color::new(0.25, 0.5, 1.0);

/// What `may_trace` was asked must be `expected`: each secondary ray of a
/// path at `path`, one bounce deeper, with the path's weight times its own.
fn assert_offered(asked: &[(u32, Color)], path: Path, weights: &[Color]) {
    assert!(
        !asked.is_empty(),
        "may_trace was never asked: each secondary ray must be offered to the tracer (one bounce \
         deeper, with its path's weight), which decides whether it is traced; a recursion that \
         does not ask never ends"
    );
    assert_eq!(
        asked.len(),
        weights.len(),
        "may_trace was asked {asked:?}: once per secondary ray ({})",
        weights.len()
    );
    for (&(depth, weight), &own) in asked.iter().zip(weights) {
        assert_eq!(
            depth,
            path.depth + 1,
            "a secondary ray of a path at depth {} was offered at depth {depth}: it is one bounce \
             deeper, depth + 1 = {} (did trace hand its own path on?)",
            path.depth,
            path.depth + 1
        );
        let product = path.weight * own;
        assert!(
            close(weight, product),
            "a secondary ray of weight {own} on a path of weight {} was offered with weight \
             {weight}: weights multiply along a path, {} × {own} = {product}",
            path.weight,
            path.weight
        );
    }
}

/// The recursion's bookkeeping is sound: at a hit, `trace` offers each
/// secondary ray one bounce deeper than its own path, with the product of
/// the weights. Every test that renders mirrors checks this first: a
/// recursion whose depth does not grow would never end there, and would
/// overflow the stack before it could say why.
fn assert_the_recursion_is_sound() {
    let scene = floor();
    let probe = Probe::new(
        [to_the_sky(MIRROR_WEIGHT, SecondaryKind::Reflection), None],
        true,
    );
    let path = Path {
        depth: 2,
        weight: Color::splat(0.5),
    };
    let down = arriving(Vec3::new(0.2, -1.0, 0.1));
    let mut stats = Stats::default();
    trace(&probe, &scene, &scene.objects[..], &down, path, &mut stats);
    assert_offered(&probe.asked(), path, &[MIRROR_WEIGHT]);
}

#[test]
fn a_secondary_ray_is_one_bounce_deeper_and_carries_the_product_of_the_weights() {
    let scene = floor();
    let probe = Probe::new(
        [to_the_sky(MIRROR_WEIGHT, SecondaryKind::Reflection), None],
        true,
    );
    let path = Path {
        depth: 2,
        weight: Color::splat(0.5),
    };
    let mut stats = Stats::default();
    follow_secondary_rays(
        &probe,
        &scene,
        &scene.objects[..],
        probe.rays,
        path,
        &mut stats,
    );
    assert_offered(&probe.asked(), path, &[MIRROR_WEIGHT]);
}

#[test]
fn trace_offers_the_secondary_rays_one_bounce_deeper() {
    assert_the_recursion_is_sound();
}

#[test]
fn each_secondary_ray_brings_back_its_weight_times_what_it_sees() {
    let scene = floor();
    let background = scene.image.background;
    let rays = [
        to_the_sky(MIRROR_WEIGHT, SecondaryKind::Reflection),
        to_the_sky(GLASS_WEIGHT, SecondaryKind::Refraction),
    ];
    let probe = Probe::new(rays, true);
    let path = Path {
        depth: 0,
        weight: Color::ONE,
    };
    let mut stats = Stats::default();
    let found = follow_secondary_rays(&probe, &scene, &scene.objects[..], rays, path, &mut stats);
    let expected = MIRROR_WEIGHT * background + GLASS_WEIGHT * background;
    assert!(
        close(found, expected),
        "two rays into the sky (background {background}) of weights {MIRROR_WEIGHT} and \
         {GLASS_WEIGHT} bring back Σ weight × colour seen = {expected}; found {found} (unweighted \
         it would be {})",
        2.0 * background
    );
    assert_eq!(
        (stats.reflection, stats.refraction),
        (1, 1),
        "each ray traced is counted, by its kind"
    );
}

#[test]
fn a_ray_the_tracer_stops_is_neither_traced_nor_counted() {
    let scene = floor();
    let rays = [to_the_sky(MIRROR_WEIGHT, SecondaryKind::Reflection), None];
    let probe = Probe::new(rays, false);
    let mut stats = Stats::default();
    let found = follow_secondary_rays(
        &probe,
        &scene,
        &scene.objects[..],
        rays,
        Path::START,
        &mut stats,
    );
    assert_eq!(
        probe.asked().len(),
        1,
        "may_trace is asked once per secondary ray"
    );
    assert_eq!(
        found,
        Color::ZERO,
        "may_trace said no: the ray brings back nothing"
    );
    assert_eq!(
        (stats.reflection, stats.ended_no_hit),
        (0, 0),
        "may_trace said no: the ray is neither traced nor counted"
    );
}

#[test]
fn trace_sees_the_background_where_the_ray_hits_nothing() {
    let scene = floor();
    let probe = Probe::new([None, None], true);
    let up = Ray {
        origin: Vec3::new(0.0, 1.0, 0.0),
        direction: Vec3::Y,
    };
    let mut stats = Stats::default();
    let found = trace(
        &probe,
        &scene,
        &scene.objects[..],
        &up,
        Path::START,
        &mut stats,
    );
    assert_eq!(
        found, scene.image.background,
        "a ray that hits nothing sees the background"
    );
    assert_eq!(
        stats.ended_no_hit, 1,
        "a ray that hits nothing ends its path: count it in stats.ended_no_hit"
    );
}

#[test]
fn trace_adds_the_local_light_and_what_the_secondary_rays_bring_back() {
    let scene = floor();
    let background = scene.image.background;
    let rays = [
        to_the_sky(MIRROR_WEIGHT, SecondaryKind::Reflection),
        to_the_sky(GLASS_WEIGHT, SecondaryKind::Refraction),
    ];
    let probe = Probe::new(rays, true);
    let path = Path {
        depth: 2,
        weight: Color::splat(0.5),
    };
    let mut stats = Stats::default();
    let down = arriving(Vec3::new(0.2, -1.0, 0.1));
    let found = trace(&probe, &scene, &scene.objects[..], &down, path, &mut stats);
    assert_offered(&probe.asked(), path, &[MIRROR_WEIGHT, GLASS_WEIGHT]);
    let expected = probe.local + MIRROR_WEIGHT * background + GLASS_WEIGHT * background;
    assert!(
        close(found, expected),
        "at a hit: the local light {} plus what the secondary rays bring back ({} and {}) = \
         {expected}; found {found}",
        probe.local,
        MIRROR_WEIGHT * background,
        GLASS_WEIGHT * background
    );
    assert_eq!(
        (stats.reflection, stats.refraction, stats.ended_no_hit),
        (1, 1, 2),
        "one reflection and one refraction traced, each ending in the sky"
    );
}

// The recursion in two facing mirrors, where every pixel is known.

/// Two facing mirrors (z = ±2), the camera between them looking askew: every
/// ray bounces between them until the depth limit ends it. Each hit's local
/// light is ambient 0.4 × albedo 0.5 = 0.2; each bounce weighs red by 0.5,
/// green by 0.25 and blue by 0.
const FACING: &str = r#"
[camera]
eye = [0.0, 0.0, 0.0]
look_at = [0.3, 0.2, -1.0]
up = [0.0, 1.0, 0.0]
vfov = 30.0

[image]
width = 4
height = 3

[materials.mirror]
color = [0.5, 0.5, 0.5]
reflectance = [0.5, 0.25, 0.0]

[[lights]]
type = "ambient"
color = [0.4, 0.4, 0.4]

[[objects]]
type = "plane"
normal = [0.0, 0.0, 1.0]
offset = 2.0
material = "mirror"

[[objects]]
type = "plane"
normal = [0.0, 0.0, -1.0]
offset = 2.0
material = "mirror"
"#;

/// The pixel after `bounces` bounces: 0.2 × Σₖ₌₀..bounces reflectanceᵏ.
fn after(bounces: u32) -> Color {
    (0..=bounces)
        .map(|k| 0.2 * Color::new(0.5, 0.25, 0.0).powf(k as f32))
        .fold(Color::ZERO, |sum, c| sum + c)
}

/// Renders with chapter 5's tracer, once the recursion is known to end.
fn render(scene: &Scene) -> (Image, Stats) {
    assert_the_recursion_is_sound();
    render_mirrors(scene, || {})
}

#[test]
fn max_depth_n_follows_exactly_n_bounces() {
    for max_depth in 0..=3 {
        let mut scene = scene_files::parse(FACING, "facing.toml").unwrap();
        scene.trace.max_depth = max_depth;
        let (image, stats) = render(&scene);
        let expected = after(max_depth);
        for &found in &image.pixels {
            let hint = if close(found, after(max_depth + 1)) {
                " That is one bounce too many."
            } else if max_depth > 0 && close(found, after(max_depth - 1)) {
                " That is one bounce too few."
            } else {
                ""
            };
            assert!(
                close(found, expected),
                "max_depth = {max_depth} follows exactly {max_depth} bounces: every pixel is \
                 0.2 × (1 + r + … + r^{max_depth}) with r = (0.5, 0.25, 0), {expected}; found \
                 {found}.{hint}"
            );
        }
        assert_eq!(
            stats.reflection,
            stats.primary * max_depth as u64,
            "max_depth = {max_depth}: {max_depth} mirror rays per pixel"
        );
        assert_eq!(stats.ended_max_depth, stats.primary, "{stats}");
    }
}

#[test]
fn no_reflectance_no_reflection_ray() {
    let mut scene = CHAPTER.default_scene().unwrap().with_size(80, 60);
    for m in &mut scene.materials {
        m.reflectance = Vec3::ZERO;
    }
    let (_, stats) = render(&scene);
    assert_eq!(stats.reflection, 0, "no material reflects: no mirror ray");
}

fn corridor() -> Scene {
    scene_files::load(concat!(env!("CARGO_MANIFEST_DIR"), "/scenes/corridor.toml")).unwrap()
}

#[test]
fn the_corridor_is_ended_by_depth() {
    let scene = corridor().with_size(40, 30);
    let (image, stats) = render(&scene);
    assert!(stats.ended_max_depth > 0, "{stats}");
    assert!(image.pixels.iter().all(|c| c.is_finite()));
    // One less bounce allowed, fewer reflection rays.
    let mut shallower = scene.clone();
    shallower.trace.max_depth -= 1;
    let (_, fewer) = render(&shallower);
    assert!(fewer.reflection < stats.reflection);
}

#[test]
fn snapshot_default() {
    let scene = CHAPTER.default_scene().unwrap().with_size(160, 120);
    assert_image("05-reflection", "default", &render(&scene).0);
}

#[test]
fn snapshot_corridor() {
    let scene = corridor().with_size(160, 120);
    assert_image("05-reflection", "corridor", &render(&scene).0);
}
