//! Chapter 2: the plane, the lecture's sphere quadratic, the nearest root,
//! the lecture's triangle test, the closest hit.

use super::Probe;
use crate::Case;
use crate::draw::{
    Rng, axis, chance, exact, exact_point, num, number, point, show, unit, v3, whole,
};
use ch02_hits::toolkit::Vec3;
use ch02_hits::toolkit::scene::{Object, Shape};
use ch02_hits::{Hit, Ray};
use serde_json::{Value, json};

pub fn probes() -> Vec<Probe> {
    let probe = |id, tolerance, case| Probe {
        id,
        chapter: "02-hits",
        tolerance,
        case,
    };
    vec![
        probe("ch02-closest", 1e-4, closest),
        probe("ch02-plane", 1e-4, plane),
        // The lecture's quadratic in f32 loses digits to cancellation; two
        // correct ways of writing it agree to about 1e-4 away from tangency.
        probe("ch02-sphere", 1e-3, sphere),
        probe("ch02-nearest", 1e-6, nearest),
        probe("ch02-triangle", 1e-3, triangle),
    ]
}

/// A ray from anywhere in a box, towards `target` if given.
pub(super) fn ray(rng: &mut Rng, target: Option<Vec3>) -> Ray {
    let origin = point(rng, 8.0);
    let direction = match target {
        Some(target) if (target - origin).length() > 1e-3 => (target - origin).normalize(),
        _ => unit(rng),
    };
    Ray { origin, direction }
}

/// A range (t_min, t_max): from 0 or a small positive number, to a finite
/// bound or infinity.
pub(super) fn range(rng: &mut Rng) -> (f32, f32) {
    let t_min = if chance(rng, 0.5) {
        0.0
    } else {
        number(rng, 1e-4, 2.0)
    };
    let t_max = if chance(rng, 0.4) {
        f32::INFINITY
    } else {
        number(rng, 12.0, 40.0)
    };
    (t_min, t_max)
}

pub(super) fn show_ray(ray: &Ray) -> String {
    format!("ray {} → {}", show(ray.origin), show(ray.direction))
}

/// Is t within `margin` of either end of the range (where rounding may
/// rightly decide either way)?
fn near_ends(t: f32, (t_min, t_max): (f32, f32), margin: f32) -> bool {
    (t - t_min).abs() < margin || (t - t_max).abs() < margin
}

/// A unit direction with no part along the unit axis `axis` (exactly).
fn across(rng: &mut Rng, axis: Vec3) -> Vec3 {
    let v = unit(rng) * (Vec3::ONE - axis.abs());
    match v.length() < 0.1 {
        true => across(rng, axis),
        false => v.normalize(),
    }
}

fn plane_case(normal: Vec3, offset: f32, ray: &Ray, range: (f32, f32)) -> Case {
    let hit = ch02_hits::intersect_plane(normal, offset, ray, range.0, range.1);
    Case {
        input: format!(
            "plane n {}, d {offset:?}; {}; t in ({:?}, {:?})",
            show(normal),
            show_ray(ray),
            range.0,
            range.1
        ),
        value: hit.map_or(Value::Null, num),
    }
}

/// The plane's edge cases, in exact numbers (`draw::exact`), on a plane
/// whose normal is an axis: a ray that starts on the plane (t = 0 is not
/// in a range from 0: the bounds are strict); a ray parallel to it (no hit,
/// never one at infinity); a hit exactly at t_min or at t_max (outside).
fn plane_edge(rng: &mut Rng) -> Case {
    let normal = axis(rng);
    let origin = exact_point(rng, 4.0);
    match whole(rng, 0, 2) {
        0 => {
            let ray = Ray {
                origin,
                direction: unit(rng),
            };
            plane_case(normal, -normal.dot(origin), &ray, (0.0, f32::INFINITY))
        }
        1 => {
            let ray = Ray {
                origin,
                direction: across(rng, normal),
            };
            let offset = exact(rng, 4.0);
            plane_case(normal, offset, &ray, (0.0, f32::INFINITY))
        }
        _ => {
            let distance = exact(rng, 4.0).abs();
            let offset = -normal.dot(origin) - distance;
            let ray = Ray {
                origin,
                direction: normal,
            };
            let range = match chance(rng, 0.5) {
                true => (0.0, distance),
                false => (distance, f32::INFINITY),
            };
            plane_case(normal, offset, &ray, range)
        }
    }
}

fn plane(rng: &mut Rng) -> Option<Case> {
    if chance(rng, 0.3) {
        return Some(plane_edge(rng));
    }
    let (normal, offset) = (unit(rng), number(rng, -5.0, 5.0));
    let ray = ray(rng, None);
    let range = range(rng);
    let cos = normal.dot(ray.direction);
    let t = -(normal.dot(ray.origin) + offset) / cos;
    if cos.abs() < 0.05 || near_ends(t, range, 1e-2) {
        return None;
    }
    Some(plane_case(normal, offset, &ray, range))
}

fn sphere_case(center: Vec3, radius: f32, ray: &Ray) -> Case {
    let roots = ch02_hits::sphere_roots_abc(center, radius, ray);
    Case {
        input: format!("sphere m {}, ρ {radius:?}; {}", show(center), show_ray(ray)),
        value: roots.map_or(Value::Null, |(a, b)| json!([num(a), num(b)])),
    }
}

/// Tangency in exact numbers: a ray along an axis that grazes the sphere
/// (discriminant exactly 0: one double root, a hit), or passes it by 1/64
/// outside (no roots).
fn sphere_edge(rng: &mut Rng) -> Case {
    let center = exact_point(rng, 4.0);
    let radius = exact(rng, 2.0).abs();
    let direction = axis(rng);
    let side = loop {
        let side = axis(rng);
        if side.dot(direction) == 0.0 {
            break side;
        }
    };
    let past = if chance(rng, 0.7) { 0.0 } else { 1.0 / 64.0 };
    let along = exact(rng, 6.0);
    let origin = center + (radius + past) * side + along * direction;
    sphere_case(center, radius, &Ray { origin, direction })
}

fn sphere(rng: &mut Rng) -> Option<Case> {
    if chance(rng, 0.2) {
        return Some(sphere_edge(rng));
    }
    let (center, radius) = (point(rng, 5.0), number(rng, 0.2, 3.0));
    let aim = center + unit(rng) * number(rng, 0.0, 1.3 * radius);
    let ray = ray(rng, Some(aim));
    // Away from tangency, where the f32 roots of two correct formulas part.
    let to_center = center - ray.origin;
    let along = to_center.dot(ray.direction);
    let miss = (to_center - along * ray.direction).length() / radius;
    if (0.95..1.05).contains(&miss) {
        return None;
    }
    Some(sphere_case(center, radius, &ray))
}

fn nearest(rng: &mut Rng) -> Option<Case> {
    let a = number(rng, -4.0, 14.0);
    let b = if chance(rng, 0.1) {
        a
    } else {
        number(rng, -4.0, 14.0)
    };
    let range = (number(rng, -2.0, 2.0), number(rng, 2.5, 12.0));
    // A root exactly at an end of the range, one case in three: the ends
    // are not in it. (The roots are given: no rounding can move them.)
    let end = [range.0, range.1][whole(rng, 0, 1) as usize];
    let (a, b) = match whole(rng, 0, 5) {
        0 => (end, b),
        1 => (a, end),
        _ => (a, b),
    };
    let (near, far) = (a.min(b), a.max(b));
    let root = ch02_hits::nearest_root((near, far), range.0, range.1);
    Some(Case {
        input: format!(
            "roots ({near:?}, {far:?}); t in ({:?}, {:?})",
            range.0, range.1
        ),
        value: root.map_or(Value::Null, num),
    })
}

fn triangle_case(vertices: [Vec3; 3], ray: &Ray, range: (f32, f32)) -> Case {
    let hit = ch02_hits::triangle_by_plane(vertices, ray, range.0, range.1);
    let [p0, p1, p2] = vertices;
    Case {
        input: format!(
            "triangle {}, {}, {}; {}; t in ({:?}, {:?})",
            show(p0),
            show(p1),
            show(p2),
            show_ray(ray),
            range.0,
            range.1
        ),
        value: hit.map_or(Value::Null, |(t, a, b)| json!([num(t), num(a), num(b)])),
    }
}

/// Corners and edges in exact numbers: a triangle in a plane across an
/// axis, and a ray along the axis through a corner, or through a point of
/// an edge from p0 (a barycentric coordinate exactly 0: on the triangle,
/// so a hit); or through an inside point, with the triangle behind the ray
/// (no hit in a range from 0).
fn triangle_edge(rng: &mut Rng) -> Case {
    let normal = axis(rng);
    let level = exact(rng, 4.0) * normal.abs();
    let in_plane = |rng: &mut Rng| exact_point(rng, 4.0) * (Vec3::ONE - normal.abs()) + level;
    let vertices = loop {
        let vertices = [in_plane(rng), in_plane(rng), in_plane(rng)];
        let [p0, p1, p2] = vertices;
        if (p1 - p0).cross(p2 - p0).length() > 1.0 {
            break vertices;
        }
    };
    let [p0, p1, p2] = vertices;
    let share = (2 * whole(rng, 0, 31) + 1) as f32 / 64.0;
    let behind = chance(rng, 0.2);
    let through = match whole(rng, 0, 4) {
        _ if behind => p0 + (p1 - p0) * 0.25 + (p2 - p0) * 0.25,
        0 => p0,
        1 => p1,
        2 => p2,
        3 => p0 + (p1 - p0) * share,
        _ => p0 + (p2 - p0) * share,
    };
    let distance = exact(rng, 4.0).abs();
    // `axis` has drawn the normal's sign: the ray comes from either side.
    let towards = normal;
    let ray = Ray {
        origin: through - towards * distance,
        direction: if behind { -towards } else { towards },
    };
    let range = match behind || chance(rng, 0.5) {
        true => (0.0, f32::INFINITY),
        false => (distance * 0.5, distance * 2.0),
    };
    triangle_case(vertices, &ray, range)
}

fn triangle(rng: &mut Rng) -> Option<Case> {
    if chance(rng, 0.3) {
        return Some(triangle_edge(rng));
    }
    let p0 = point(rng, 5.0);
    let (p1, p2) = (p0 + point(rng, 3.0), p0 + point(rng, 3.0));
    let normal = (p1 - p0).cross(p2 - p0);
    if normal.length() < 0.5 {
        return None;
    }
    let (a, b) = (number(rng, -0.2, 0.9), number(rng, -0.2, 0.9));
    // Away from the edges, where two correct tests may rightly differ.
    if [a, b, 1.0 - a - b].iter().any(|w| w.abs() < 0.02) {
        return None;
    }
    let ray = ray(rng, Some(p0 + a * (p1 - p0) + b * (p2 - p0)));
    if normal.normalize().dot(ray.direction).abs() < 0.1 {
        return None;
    }
    let range = range(rng);
    let t = (p0 + a * (p1 - p0) + b * (p2 - p0) - ray.origin).length();
    if near_ends(t, range, 1e-2) {
        return None;
    }
    Some(triangle_case([p0, p1, p2], &ray, range))
}

/// The closest of a few spheres, planes and triangles, found with the
/// tracer's own tests (`ch02_hits::intersect`, none of the student's
/// intersection exercises). The value holds the hit and, in order, the
/// range (t_min, t_max) each object was asked about: t_min as given, and
/// t_max shrinking to the nearest t so far (README question 1; a bound
/// that stays finds the same hit). One case
/// in four lists one object a second time, last: met at the same t as the
/// first, which must win the tie (`t < best`, not `t <= best`).
fn closest(rng: &mut Rng) -> Option<Case> {
    let count = whole(rng, 0, 6);
    let objects: Vec<Object> = (0..count)
        .map(|i| Object {
            shape: shape(rng),
            material: i as usize,
            shadows: true,
        })
        .collect();
    let aim = point(rng, 4.0);
    let ray = ray(rng, Some(aim));
    // One case in three starts the range further out, past some objects.
    let range = match chance(rng, 0.3) {
        true => {
            let t_min = number(rng, 2.0, 8.0);
            (t_min, t_min + number(rng, 1.0, 6.0))
        }
        false => range(rng),
    };
    let near_an_end = |t: f32| {
        let window = ((t - 1e-2).max(0.0), t + 1e-2);
        let hit = |o: &Object| ch02_hits::intersect(&o.shape, &ray, window.0, window.1);
        objects.iter().any(|o| hit(o).is_some())
    };
    if near_an_end(range.0) || near_an_end(range.1) {
        return None;
    }
    let mut ts: Vec<f32> = (objects.iter())
        .filter_map(|o| ch02_hits::intersect(&o.shape, &ray, range.0, range.1))
        .collect();
    ts.sort_by(f32::total_cmp);
    if ts.windows(2).any(|w| w[1] - w[0] < 1e-3) {
        return None;
    }
    let mut objects = objects;
    if count > 0 && chance(rng, 0.25) {
        let twice = whole(rng, 0, count - 1) as usize;
        let copy = Object {
            material: objects.len(),
            ..objects[twice].clone()
        };
        objects.push(copy);
    }
    let asked = std::cell::RefCell::new(Vec::new());
    let recording = |shape: &Shape, ray: &Ray, t_min: f32, t_max: f32| {
        asked.borrow_mut().push([t_min, t_max]);
        ch02_hits::intersect(shape, ray, t_min, t_max)
    };
    let hit = ch02_hits::closest_hit_by(recording, &objects, &ray, range.0, range.1);
    let shapes: Vec<String> = objects.iter().map(|o| format!("{:?}", o.shape)).collect();
    Some(Case {
        input: format!(
            "objects [{}]; {}; t in ({:?}, {:?})",
            shapes.join(", "),
            show_ray(&ray),
            range.0,
            range.1
        ),
        value: json!([
            hit.map_or(Value::Null, |h: Hit| {
                json!([h.t, h.object, v3(h.point), v3(h.normal)])
            }),
            asked.into_inner(),
        ]),
    })
}

/// A sphere, plane or triangle near the origin.
pub(super) fn shape(rng: &mut Rng) -> Shape {
    match whole(rng, 0, 2) {
        0 => Shape::Sphere {
            center: point(rng, 4.0),
            radius: number(rng, 0.2, 1.5),
        },
        1 => Shape::Plane {
            normal: unit(rng),
            offset: number(rng, -6.0, 6.0),
        },
        _ => {
            let p0 = point(rng, 4.0);
            let vertices = [p0, p0 + point(rng, 3.0), p0 + point(rng, 3.0)];
            match (vertices[1] - p0).cross(vertices[2] - p0).length() > 0.3 {
                true => Shape::Triangle { vertices },
                false => Shape::Sphere {
                    center: p0,
                    radius: 0.7,
                },
            }
        }
    }
}
