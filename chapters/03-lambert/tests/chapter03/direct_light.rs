//! Direct light: the lights added up channel by channel, ambient light once,
//! and `visible` asked only about the lights that could add something.

use ch03_lambert::toolkit::{Color, Vec3};
use ch03_lambert::workbench::exercise::builds_on;
use ch03_lambert::{
    Incoming, Surface, always_visible, closest_hit, direct_light, lambert, spot_factor,
};

use super::{ALBEDO, close, floor_with};

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
/// `visible` and `reflect` (None: Lambert's law). The light loop builds on
/// the chapter's two other exercises, so they are checked first at this
/// point (`ch03-spot` for a spot among the lights, `ch03-lambert` when
/// `reflect` is Lambert's law): a wrong factor there would otherwise be
/// blamed on the loop.
fn light_at_floor(
    lights: &str,
    visible: impl FnMut(&Surface, &Incoming) -> bool,
    reflect: Option<Reflect>,
) -> Color {
    let (scene, ray) = floor_with(lights);
    let hit = closest_hit(&scene.objects, &ray, 0.0, f32::INFINITY).unwrap();
    let surface = Surface::new(&scene, hit, &ray);
    if lights.contains("spot") {
        spot_misses_the_floor();
    }
    if reflect.is_none() {
        lambert_is_right_at(&surface);
    }
    match reflect {
        None => direct_light(&scene, &surface, visible, |i| lambert(&surface, i)),
        Some(f) => direct_light(&scene, &surface, visible, |i| f(&surface, i)),
    }
}

/// `ch03-spot` first: [`SPOT_AWAY`]'s cone (axis +x, half-angles 10° and
/// 20°) sends nothing straight down, 90° from its axis.
fn spot_misses_the_floor() {
    let down = Vec3::NEG_Y;
    let factor = spot_factor(Vec3::X, 10.0, 20.0, down);
    builds_on(
        "ch03-spot",
        factor == 0.0,
        format_args!(
            "spot_factor(axis +x, 10°, 20°, straight down) is {factor}, but a direction \
             90° from the axis is outside the outer cone: 0 (the tests in `spot` say more)"
        ),
    );
}

/// `ch03-lambert` first, on light B's numbers at the floor (n·l = 0.8,
/// irradiance (1, 0.5, 0.25)) and on light from below (nothing).
fn lambert_is_right_at(surface: &Surface) {
    let incoming = |direction: Vec3| Incoming {
        direction,
        distance: 5.0,
        irradiance: Color::new(1.0, 0.5, 0.25),
        casts_shadows: true,
    };
    for (direction, want) in [
        (Vec3::new(0.6, 0.8, 0.0), ALBEDO * Vec3::new(0.8, 0.4, 0.2)),
        (Vec3::new(0.6, -0.8, 0.0), Color::ZERO),
    ] {
        let got = lambert(surface, &incoming(direction));
        builds_on(
            "ch03-lambert",
            close(got, want),
            format_args!(
                "at the floor, light of irradiance (1, 0.5, 0.25) from {direction} should \
                 give {want}, lambert gave {got} (the tests in `lambert` say more)"
            ),
        );
    }
}

#[test]
pub(crate) fn ambient_light_adds_albedo_times_its_colour_once() {
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
pub(crate) fn the_lights_add_up_channel_by_channel() {
    let lights = format!("{AMBIENTS}{LIGHT_A}{LIGHT_B}");
    let ambient = ALBEDO * Vec3::new(0.15, 0.25, 0.35);
    let a = ALBEDO;
    let b = ALBEDO * Vec3::new(1.0, 0.5, 0.25) * 0.8;
    let got = light_at_floor(&lights, always_visible, None);
    let want = ambient + a + b;
    let hint = if close(got, want.min(Color::ONE)) {
        "that is the sum with each channel capped at 1: light may add up to more than 1 while \
         shading; direct_light returns the sum as it is, and the colour is clamped only when \
         the pixel is written (Image::to_rgb8)"
            .to_string()
    } else {
        format!("multiplied instead of added: {}", ambient * a * b)
    };
    assert!(
        close(got, want),
        "ambient {ambient} + light A {a} + light B {b} = {want}, got {got} ({hint})"
    );
}

#[test]
pub(crate) fn a_light_that_is_not_visible_adds_nothing() {
    let lights = format!("{LIGHT_A}{LIGHT_B}");
    // Light B (the one off to the side, +x) is blocked.
    let got = light_at_floor(&lights, |_, i| i.direction.x <= 0.0, None);
    assert!(
        close(got, ALBEDO),
        "`visible` says light B is blocked, so only light A adds: {ALBEDO}, got {got}"
    );
}

#[test]
pub(crate) fn a_light_behind_the_surface_is_skipped_whatever_reflect_says() {
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
pub(crate) fn visible_is_asked_only_about_lights_that_could_add_something() {
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
    assert!(
        asked == 0,
        "reflect gives zero for every light (as a black surface, albedo 0, would): a light \
         that adds nothing needs no visibility question, so visible must not be asked; it was \
         asked {asked} times"
    );
}

#[test]
fn a_light_in_the_surfaces_plane_is_skipped_like_one_behind_it() {
    // Light D lies in the floor's plane: n·l = 0 exactly, a grazing light.
    // It adds nothing whatever reflect says, and costs no visibility
    // question (no shadow ray in chapter 4).
    let light_d = r#"
        [[lights]]
        type = "point"
        position = [5, 0, 0]
        intensity = 25
    "#;
    let mut asked = 0;
    let visible = |_: &Surface, _: &Incoming| {
        asked += 1;
        true
    };
    let got = light_at_floor(light_d, visible, Some(&|_, _| Color::ONE));
    assert!(
        got == Color::ZERO && asked == 0,
        "a light in the surface's plane (n·l = 0) must be skipped like one behind it \
         (skip n·l ≤ 0, not only n·l < 0): it added {got} and visible was asked {asked} times"
    );
}
