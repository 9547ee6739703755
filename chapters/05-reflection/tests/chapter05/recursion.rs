//! The recursion, against a tracer whose answers the test fixes.

use std::sync::Mutex;

use ch05_reflection::toolkit::{Color, Scene, Stats, Vec3};
use ch05_reflection::{
    Path, Ray, Secondary, SecondaryKind, Surface, Whitted, World, follow_secondary_rays, trace,
};

use super::{arriving, close, floor};

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
pub(crate) fn assert_the_recursion_is_sound() {
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
pub(crate) fn a_secondary_ray_is_one_bounce_deeper_and_carries_the_product_of_the_weights() {
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
pub(crate) fn trace_offers_the_secondary_rays_one_bounce_deeper() {
    assert_the_recursion_is_sound();
}

#[test]
pub(crate) fn each_secondary_ray_brings_back_its_weight_times_what_it_sees() {
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
pub(crate) fn a_ray_the_tracer_stops_is_neither_traced_nor_counted() {
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
pub(crate) fn trace_sees_the_background_where_the_ray_hits_nothing() {
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
pub(crate) fn trace_adds_the_local_light_and_what_the_secondary_rays_bring_back() {
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
    // Each ray weighted by its path's weight (0.5 × its own) instead of its own.
    let by_path = probe.local + path.weight * (MIRROR_WEIGHT + GLASS_WEIGHT) * background;
    let hint = if close(found, by_path) {
        format!(
            " = the local light plus the rays weighted by their path's weight {} × their own: \
             a secondary ray brings back its own weight × what it sees; the path's weight is \
             only for may_trace (the levels above multiply in their own weights on the way \
             back)",
            path.weight
        )
    } else {
        String::new()
    };
    assert!(
        close(found, expected),
        "at a hit on a path of weight {}: the local light {} plus what the secondary rays \
         bring back, each its own weight × the background ({} and {}) = {expected}; found \
         {found}{hint}",
        path.weight,
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
