//! Chapter 5: the mirror law, the mirror ray, the highlight, and the
//! recursion (`trace` and `follow_secondary_rays`, through a tracer and a
//! world whose answers the probe fixes).
//!
//! As in chapter 4, a value that an earlier exercise's function takes part
//! in is given relative to what the student's own earlier function returns
//! (the mirror ray's direction to their `reflect`, its origin to their
//! `offset_origin`; what a secondary ray sees to their `trace`).

use std::sync::Mutex;

use super::Probe;
use super::ch03::{color, material};
use super::ch04::{counts, show_hit, surface};
use crate::Case;
use crate::draw::{Rng, chance, number, point, show, unit, v3, whole};
use ch05_reflection::toolkit::scene::{Object, Shape};
use ch05_reflection::toolkit::{Color, Scene, Stats, Vec3};
use ch05_reflection::{Hit, Path, Ray, Secondary, SecondaryKind, Surface, Whitted, World};
use serde_json::{Value, json};

pub fn probes() -> Vec<Probe> {
    let probe = |id, case| Probe {
        id,
        chapter: "05-reflection",
        tolerance: 1e-4,
        case,
    };
    vec![
        probe("ch05-trace", trace),
        probe("ch05-recursion", recursion),
        probe("ch05-reflect", reflect),
        probe("ch05-mirror-ray", mirror_ray),
        probe("ch05-highlight", highlight),
    ]
}

fn reflect(rng: &mut Rng) -> Option<Case> {
    let d = unit(rng) * number(rng, 0.3, 3.0);
    let n = unit(rng);
    let mirrored = ch05_reflection::reflect(d, n);
    Some(Case {
        input: format!("d {}, n {}", show(d), show(n)),
        value: v3(mirrored),
    })
}

/// A weight: zero (one case in five), zero in some channels (one in
/// five), or any.
fn weight(rng: &mut Rng) -> Color {
    match whole(rng, 0, 4) {
        0 => Color::ZERO,
        1 => {
            let w = color(rng, 0.05, 1.0);
            Color::new(w.x, if chance(rng, 0.5) { 0.0 } else { w.y }, 0.0)
        }
        _ => color(rng, 0.05, 1.0),
    }
}

/// The values: none, or the ray's kind, weight, direction relative to the
/// student's own `reflect` (made unit), and origin relative to their own
/// `offset_origin` for the direction it leaves in.
fn mirror_ray(rng: &mut Rng) -> Option<Case> {
    let material = material(rng);
    let surface = surface(rng, &material);
    let direction = -surface.to_eye;
    let incoming = Ray {
        origin: surface.hit.point - direction * surface.hit.t,
        direction,
    };
    let weight = weight(rng);
    if surface.normal.dot(direction).abs() < 0.05 {
        return None;
    }
    let ray = ch05_reflection::mirror_ray(&surface, &incoming, weight);
    let own = ch05_reflection::reflect(direction, surface.normal).normalize();
    let value = ray.map_or(Value::Null, |s: Secondary| {
        let start = ch05_reflection::offset_origin(&surface.hit, s.ray.direction);
        json!([
            s.kind == SecondaryKind::Reflection,
            v3(s.weight),
            v3(s.ray.direction - own),
            v3(s.ray.origin - start)
        ])
    });
    Some(Case {
        input: format!(
            "{}; facing normal n {}; arriving d {}; weight {}",
            show_hit(&surface.hit),
            show(surface.normal),
            show(direction),
            show(weight)
        ),
        value,
    })
}

/// A unit vector at `angle` (radians) from the unit vector `axis`, turned
/// about it at random.
fn leaning(rng: &mut Rng, axis: Vec3, angle: f32) -> Vec3 {
    let across = axis.cross(unit(rng)).normalize();
    (axis * angle.cos() + across * angle.sin()).normalize()
}

/// The highlight where it can be seen: the halfway vector h is drawn so
/// that cos(h, n)^s lies between 0.02 and 1 (most cases), or leans beyond
/// 90° (its value is 0); v and l lie symmetric about h.
fn highlight(rng: &mut Rng) -> Option<Case> {
    let mut material = material(rng);
    material.specular = match chance(rng, 0.15) {
        true => 0.0,
        false => number(rng, 0.05, 1.0),
    };
    material.shininess = number(rng, 1.0, 200.0);
    let mut surface = surface(rng, &material);
    let n = surface.normal;
    let lean = match chance(rng, 0.1) {
        true => number(rng, 1.6, 3.0),
        false => number(rng, 0.02, 1.0).powf(1.0 / material.shininess).acos(),
    };
    let h = leaning(rng, n, lean);
    let apart = number(rng, 0.0, 1.4);
    let v = leaning(rng, h, apart);
    // One case in ten: l exactly opposite v, where h has no direction.
    let l = match chance(rng, 0.1) {
        true => -v,
        false => (2.0 * h.dot(v) * h - v).normalize(),
    };
    surface.to_eye = v;
    let incoming = ch05_reflection::Incoming {
        direction: l,
        distance: number(rng, 0.5, 20.0),
        irradiance: color(rng, 0.0, 5.0),
        casts_shadows: true,
    };
    let seen = ch05_reflection::highlight(&surface, &incoming);
    Some(Case {
        input: format!(
            "n {}, v {}, l {}, I_L {}, k_s {:?}, s {:?}",
            show(n),
            show(v),
            show(l),
            show(incoming.irradiance),
            material.specular,
            material.shininess
        ),
        value: v3(seen),
    })
}

/// A tracer whose answers the probe fixes: a local colour from the hit's
/// distance, fixed secondary rays, and `may_trace` by a depth and a weight
/// limit; it records the surfaces it was asked to light and each (depth,
/// weight) `may_trace` was offered.
struct Scripted {
    rays: [Option<Secondary>; 2],
    depth_limit: u32,
    weight_limit: f32,
    lit: Mutex<Vec<(f32, Vec3)>>,
    offered: Mutex<Vec<(u32, Color)>>,
}

impl Scripted {
    fn draw(rng: &mut Rng) -> Scripted {
        let mut ray = || {
            chance(rng, 0.75).then(|| Secondary {
                ray: Ray {
                    origin: point(rng, 5.0),
                    direction: unit(rng),
                },
                weight: color(rng, 0.05, 1.0),
                kind: match chance(rng, 0.5) {
                    true => SecondaryKind::Reflection,
                    false => SecondaryKind::Refraction,
                },
            })
        };
        Scripted {
            rays: [ray(), ray()],
            depth_limit: whole(rng, 0, 4),
            weight_limit: number(rng, 0.0, 0.4),
            lit: Mutex::new(Vec::new()),
            offered: Mutex::new(Vec::new()),
        }
    }

    /// What `may_trace` answers.
    fn allows(&self, depth: u32, weight: Color) -> bool {
        depth <= self.depth_limit && weight.max_element() >= self.weight_limit
    }

    fn show(&self) -> String {
        let rays: Vec<String> = (self.rays.iter().flatten())
            .map(|s| format!("{:?} of weight {}", s.kind, show(s.weight)))
            .collect();
        format!(
            "secondary rays [{}]; may_trace allows depth ≤ {} with a channel ≥ {:?}",
            rays.join(", "),
            self.depth_limit,
            self.weight_limit
        )
    }
}

impl Whitted for Scripted {
    fn local(
        &self,
        _: &Scene,
        _: &(impl World + ?Sized),
        surface: &Surface,
        _: &mut Stats,
    ) -> Color {
        self.lit
            .lock()
            .unwrap()
            .push((surface.hit.t, surface.normal));
        let t = surface.hit.t;
        Color::new(t.fract(), 0.5 / (1.0 + t), 0.1 * t.sqrt())
    }

    fn secondary_rays(&self, _: &Surface, _: &Ray) -> [Option<Secondary>; 2] {
        self.rays
    }

    fn may_trace(&self, depth: u32, weight: Color, _: &mut Stats) -> bool {
        self.offered.lock().unwrap().push((depth, weight));
        self.allows(depth, weight)
    }
}

/// A world in which only the ray `seen` hits anything (at `hit`), and
/// which records the ranges it was asked about.
struct OneHit {
    seen: Ray,
    hit: Option<Hit>,
    asked: Mutex<Vec<(f32, f32)>>,
}

impl World for OneHit {
    fn closest_hit(&self, ray: &Ray, t_min: f32, t_max: f32) -> Option<Hit> {
        self.asked.lock().unwrap().push((t_min, t_max));
        let same = ray.origin == self.seen.origin && ray.direction == self.seen.direction;
        self.hit.filter(|_| same)
    }

    fn any_hit(&self, _: &Ray, _: f32, _: f32) -> bool {
        false
    }
}

/// A path: its depth and weight.
fn path(rng: &mut Rng) -> Path {
    Path {
        depth: whole(rng, 0, 3),
        weight: color(rng, 0.1, 1.0),
    }
}

/// A scene with a camera, a background, and the one object (and its
/// material) that the scripted world's hits are of.
fn scene(rng: &mut Rng) -> Scene {
    let mut scene = crate::scenes::parse(crate::scenes::EMPTY);
    scene.image.background = color(rng, 0.0, 1.0);
    scene.materials = vec![material(rng)];
    let shape = Shape::Sphere {
        center: Vec3::ZERO,
        radius: 1.0,
    };
    scene.objects = vec![Object {
        shape,
        material: 0,
        shadows: true,
    }];
    scene
}

fn show_path(path: &Path) -> String {
    format!("path depth {}, weight {}", path.depth, show(path.weight))
}

/// `trace` with a scripted tracer in a world where only the traced ray
/// hits. The values: its colour minus what the student's own
/// `follow_secondary_rays` brings back for the hit's rays (so, the local
/// light, or the background); its own counts (the counts of that
/// recursion taken off); the surfaces lit (t, and whether the normal faces
/// the ray); and each range the world was asked about, as whether it
/// starts at the origin (a t_min of at most 0.01: an epsilon is no
/// mistake the tests name) and whether it is unbounded.
fn trace(rng: &mut Rng) -> Option<Case> {
    let scene = scene(rng);
    let tracer = Scripted::draw(rng);
    let ray = Ray {
        origin: point(rng, 5.0),
        direction: unit(rng),
    };
    let t = number(rng, 0.5, 20.0);
    let normal = unit(rng);
    let hit = chance(rng, 0.7).then(|| Hit {
        t,
        point: ray.origin + t * ray.direction,
        normal,
        shading_normal: normal,
        error: 1e-5,
        object: 0,
    });
    let world = OneHit {
        seen: ray,
        hit,
        asked: Mutex::new(Vec::new()),
    };
    let path = path(rng);
    let mut stats = Stats::default();
    let color = ch05_reflection::trace(&tracer, &scene, &world, &ray, path, &mut stats);
    let lit = std::mem::take(&mut *tracer.lit.lock().unwrap());
    let asked = std::mem::take(&mut *world.asked.lock().unwrap());
    let mut own = Stats::default();
    let brought = match hit {
        None => Color::ZERO,
        Some(_) => {
            let rays = tracer.rays;
            ch05_reflection::follow_secondary_rays(&tracer, &scene, &world, rays, path, &mut own)
        }
    };
    let lit: Vec<Value> = (lit.iter())
        .map(|(t, n)| json!([t, n.dot(ray.direction) <= 0.0]))
        .collect();
    let asked: Vec<Value> = (asked.iter())
        .map(|(t_min, t_max)| json!([*t_min <= 0.01, *t_max >= 1e30]))
        .collect();
    Some(Case {
        input: format!(
            "ray {} → {}; hit {}; {}; {}; background {}",
            show(ray.origin),
            show(ray.direction),
            hit.map_or("none".to_owned(), |_| format!(
                "at t {t:?}, normal {}",
                show(normal)
            )),
            show_path(&path),
            tracer.show(),
            show(scene.image.background)
        ),
        value: json!([
            v3(color - brought),
            counts(&difference(&stats, &own)),
            lit,
            asked.first()
        ]),
    })
}

/// `a − b`, counter by counter (none below zero).
fn difference(a: &Stats, b: &Stats) -> Stats {
    Stats {
        primary: a.primary.saturating_sub(b.primary),
        shadow: a.shadow.saturating_sub(b.shadow),
        reflection: a.reflection.saturating_sub(b.reflection),
        refraction: a.refraction.saturating_sub(b.refraction),
        ended_no_hit: a.ended_no_hit.saturating_sub(b.ended_no_hit),
        ended_max_depth: a.ended_max_depth.saturating_sub(b.ended_max_depth),
        ended_threshold: a.ended_threshold.saturating_sub(b.ended_threshold),
    }
}

/// `follow_secondary_rays` with a scripted tracer, in a world where the
/// secondary rays hit nothing. The values: its colour minus the sum the
/// README defines, computed with what the student's own `trace` sees along
/// each ray the tracer allows; the reflection and refraction counts; and
/// each (depth, weight) it offered the tracer.
fn recursion(rng: &mut Rng) -> Option<Case> {
    let scene = scene(rng);
    let tracer = Scripted::draw(rng);
    let world = OneHit {
        seen: Ray {
            origin: Vec3::splat(1e9),
            direction: Vec3::X,
        },
        hit: None,
        asked: Mutex::new(Vec::new()),
    };
    let path = path(rng);
    let mut stats = Stats::default();
    let color = ch05_reflection::follow_secondary_rays(
        &tracer,
        &scene,
        &world,
        tracer.rays,
        path,
        &mut stats,
    );
    let offered = std::mem::take(&mut *tracer.offered.lock().unwrap());
    let mut expected = Color::ZERO;
    for s in tracer.rays.iter().flatten() {
        let next = Path {
            depth: path.depth + 1,
            weight: path.weight * s.weight,
        };
        if tracer.allows(next.depth, next.weight) {
            let mut ignored = Stats::default();
            let seen = ch05_reflection::trace(&tracer, &scene, &world, &s.ray, next, &mut ignored);
            expected += s.weight * seen;
        }
    }
    let offered: Vec<Value> = (offered.iter())
        .map(|(depth, weight)| json!([depth, v3(*weight)]))
        .collect();
    Some(Case {
        input: format!(
            "{}; {}; background {}",
            show_path(&path),
            tracer.show(),
            show(scene.image.background)
        ),
        value: json!([
            v3(color - expected),
            stats.reflection,
            stats.refraction,
            offered
        ]),
    })
}
