//! Chapter 4: the offset origin, the shadow ray, the any-hit test, one
//! shadow ray per light (through a recording world).
//!
//! Where an exercise is to call an earlier one (`shadow_ray` starts at
//! `offset_origin`), its values are given relative to what the student's
//! own earlier function returns for the same input: a mistake in the
//! earlier exercise then costs that exercise alone.

use std::sync::Mutex;

use super::Probe;
use super::ch02::{ray, shape, show_ray};
use super::ch03::{color, material};
use crate::Case;
use crate::draw::{Rng, axis, chance, number, point, show, unit, v3, whole};
use ch04_shadows::toolkit::scene::{Material, Object};
use ch04_shadows::toolkit::{Stats, Vec3};
use ch04_shadows::{Hit, Incoming, Ray, ShadowStart, Surface, World};
use serde_json::{Value, json};

pub fn probes() -> Vec<Probe> {
    let probe = |id, case| Probe {
        id,
        chapter: "04-shadows",
        tolerance: 1e-4,
        case,
    };
    vec![
        probe("ch04-shadow-ray", shadow_ray),
        probe("ch04-any-hit", any_hit),
        probe("ch04-light-is-free", light_is_free),
        probe("ch04-offset", offset),
    ]
}

/// Every counter of `stats`, in the order the struct declares them.
pub(super) fn counts(stats: &Stats) -> Value {
    json!([
        stats.primary,
        stats.shadow,
        stats.reflection,
        stats.refraction,
        stats.ended_no_hit,
        stats.ended_max_depth,
        stats.ended_threshold
    ])
}

/// A hit whose error bound is large enough to see (0.01 to 0.3: an offset
/// by it stands out of the tolerance), with a shading normal that is not
/// the geometric one (an offset must use the geometric normal).
pub(super) fn hit(rng: &mut Rng) -> Hit {
    let normal = unit(rng);
    let shading_normal = (normal + 0.4 * unit(rng)).normalize();
    Hit {
        t: number(rng, 0.5, 20.0),
        point: point(rng, 5.0),
        normal,
        shading_normal,
        error: number(rng, 0.01, 0.3),
        object: whole(rng, 0, 5) as usize,
    }
}

/// A surface around [`hit`], made field by field: its normal is the
/// shading normal turned to face `to_eye`.
pub(super) fn surface<'a>(rng: &mut Rng, material: &'a Material) -> Surface<'a> {
    let hit = hit(rng);
    let to_eye = unit(rng);
    let normal = match hit.shading_normal.dot(to_eye) < 0.0 {
        true => -hit.shading_normal,
        false => hit.shading_normal,
    };
    Surface {
        hit,
        normal,
        to_eye,
        material,
    }
}

pub(super) fn show_hit(hit: &Hit) -> String {
    format!(
        "hit point {}, normal {}, shading normal {}, error e {:?}",
        show(hit.point),
        show(hit.normal),
        show(hit.shading_normal),
        hit.error
    )
}

/// One case in six leaves exactly along the surface (a normal along an
/// axis, a direction with no part along it): that counts as the side the
/// normal faces.
fn offset(rng: &mut Rng) -> Option<Case> {
    let mut hit = hit(rng);
    let along = chance(rng, 1.0 / 6.0);
    let towards = match along {
        true => {
            hit.normal = axis(rng);
            unit(rng) * (Vec3::ONE - hit.normal.abs())
        }
        false => unit(rng) * number(rng, 0.3, 3.0),
    };
    if !along && hit.normal.dot(towards.normalize()).abs() < 0.02 {
        return None; // nearly along the surface: rounding may decide the side
    }
    let origin = ch04_shadows::offset_origin(&hit, towards);
    Some(Case {
        input: format!(
            "{}, towards {}; the value is the origin minus the hit point",
            show_hit(&hit),
            show(towards)
        ),
        value: v3(origin - hit.point),
    })
}

/// What a light sends to a surface: from a direction of the sphere's, at
/// a distance.
fn incoming(rng: &mut Rng, casts_shadows: bool) -> Incoming {
    Incoming {
        direction: unit(rng),
        distance: number(rng, 0.5, 20.0),
        irradiance: color(rng, 0.0, 5.0),
        casts_shadows,
    }
}

fn start(rng: &mut Rng) -> ShadowStart {
    match chance(rng, 0.7) {
        true => ShadowStart::Offset,
        false => ShadowStart::HitPoint,
    }
}

/// The values are the ray's origin relative to where it is to start (the
/// student's own `offset_origin`, or the hit point), its direction, and
/// t_max minus the distance from that origin to the light.
///
/// The error bound is kept small here (0.005 to 0.01) and the light at
/// least 2 away: t_max is then the distance from the origin to the light
/// whether it is measured straight or along l (the two part by at most
/// e²/2r, 2.5e-5), while a t_max measured from the hit point instead of the
/// origin is off by e·|n·l| ≥ 5e-4.
fn shadow_ray(rng: &mut Rng) -> Option<Case> {
    let material = material(rng);
    let mut surface = surface(rng, &material);
    surface.hit.error = number(rng, 0.005, 0.01);
    let mut incoming = incoming(rng, true);
    incoming.distance = number(rng, 2.0, 20.0);
    let start = start(rng);
    if surface.hit.normal.dot(incoming.direction).abs() < 0.1 {
        return None;
    }
    let (ray, t_max) = ch04_shadows::shadow_ray(&surface, &incoming, start);
    let own_start = match start {
        ShadowStart::Offset => ch04_shadows::offset_origin(&surface.hit, incoming.direction),
        ShadowStart::HitPoint => surface.hit.point,
    };
    let light = surface.hit.point + incoming.direction * incoming.distance;
    Some(Case {
        input: format!(
            "{}; l {}, r {:?}; start {start:?}; the values are origin minus where it starts, \
             direction, t_max minus the distance from the origin to the light",
            show_hit(&surface.hit),
            show(incoming.direction),
            incoming.distance
        ),
        value: json!([
            v3(ray.origin - own_start),
            v3(ray.direction),
            t_max - ray.origin.distance(light)
        ]),
    })
}

fn any_hit(rng: &mut Rng) -> Option<Case> {
    let objects: Vec<Object> = (0..whole(rng, 0, 6))
        .map(|i| Object {
            shape: shape(rng),
            material: i as usize,
            shadows: chance(rng, 0.7),
        })
        .collect();
    let aim = point(rng, 3.0);
    let ray = ray(rng, Some(aim));
    let t_min = match chance(rng, 0.5) {
        true => 0.0,
        false => number(rng, 1e-4, 1.0),
    };
    let t_max = number(rng, 1.5, 25.0);
    // Away from the ends of the range, where rounding may decide either way.
    let near = |t: f32| {
        let around = |o: &Object| robust_hit(o, &ray, t - 1e-2, t + 1e-2);
        objects.iter().any(around)
    };
    if near(t_min) || near(t_max) {
        return None;
    }
    let blocked = ch04_shadows::any_hit(&objects, &ray, t_min, t_max);
    let shapes: Vec<String> = (objects.iter())
        .map(|o| format!("{:?} shadows = {}", o.shape, o.shadows))
        .collect();
    Some(Case {
        input: format!(
            "objects [{}]; {}; t in ({t_min:?}, {t_max:?})",
            shapes.join(", "),
            show_ray(&ray)
        ),
        value: json!(blocked),
    })
}

/// Does the tracer's own (robust) test find `object` in (t_min, t_max)?
fn robust_hit(object: &Object, ray: &Ray, t_min: f32, t_max: f32) -> bool {
    ch04_shadows::intersect(&object.shape, ray, t_min.max(0.0), t_max).is_some()
}

/// A world that answers any-hit questions with `blocked` and records them,
/// and finds no closest hit.
struct Recording {
    blocked: bool,
    asked: Mutex<Vec<(Ray, f32, f32)>>,
}

impl World for Recording {
    fn closest_hit(&self, _: &Ray, _: f32, _: f32) -> Option<Hit> {
        None
    }

    fn any_hit(&self, ray: &Ray, t_min: f32, t_max: f32) -> bool {
        self.asked.lock().unwrap().push((*ray, t_min, t_max));
        self.blocked
    }
}

/// The values: whether the light is free, the counters, and each question
/// asked of the world: its ray relative to the student's own `shadow_ray`,
/// whether it starts at the origin (a t_min of at most 0.01: an epsilon is
/// no mistake), and whether it ends at the light (a t_max within 1% of
/// that ray's).
fn light_is_free(rng: &mut Rng) -> Option<Case> {
    let material = material(rng);
    let surface = surface(rng, &material);
    let casts_shadows = chance(rng, 0.75);
    let incoming = incoming(rng, casts_shadows);
    let start = start(rng);
    let world = Recording {
        blocked: chance(rng, 0.5),
        asked: Mutex::new(Vec::new()),
    };
    let mut stats = Stats::default();
    let free = ch04_shadows::light_is_free(&world, &surface, &incoming, start, &mut stats);
    let (own, own_t_max) = ch04_shadows::shadow_ray(&surface, &incoming, start);
    let asked: Vec<Value> = (world.asked.into_inner().unwrap().iter())
        .map(|(ray, t_min, t_max)| {
            json!([
                v3(ray.origin - own.origin),
                v3(ray.direction - own.direction),
                *t_min <= 0.01,
                (t_max / own_t_max - 1.0).abs() < 0.01
            ])
        })
        .collect();
    Some(Case {
        input: format!(
            "{}; l {}, r {:?}, casts shadows {}; start {start:?}; the world answers blocked = {}",
            show_hit(&surface.hit),
            show(incoming.direction),
            incoming.distance,
            incoming.casts_shadows,
            world.blocked
        ),
        value: json!([free, counts(&stats), asked]),
    })
}
