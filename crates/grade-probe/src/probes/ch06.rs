//! Chapter 6: Snell's law, Schlick's approximation, the split at a
//! transparent surface.
//!
//! The split's direction and Fresnel term are given relative to what the
//! student's own `refract` and `schlick` return (chapter 4's rule).

use super::Probe;
use super::ch03::{color, material};
use super::ch04::{show_hit, surface};
use crate::Case;
use crate::draw::{Rng, chance, number, show, unit, v3, whole};
use ch06_refraction::toolkit::{Color, Vec3};
use ch06_refraction::{Ray, Split};
use serde_json::{Value, json};

pub fn probes() -> Vec<Probe> {
    let probe = |id, tolerance, case| Probe {
        id,
        chapter: "06-refraction",
        tolerance,
        case,
    };
    vec![
        // Two correct ways of writing Snell's law in f32 part by up to
        // about 1e-4 (the chapter's contract test allows 1e-3).
        probe("ch06-refract", 1e-3, refract),
        probe("ch06-schlick", 1e-4, schlick),
        probe("ch06-split", 1e-3, split),
    ]
}

/// An index of refraction: a glass or a gem (1.1 to 2.4), or an air
/// bubble in one (its inverse) one time in five.
fn ior(rng: &mut Rng) -> f32 {
    let n = number(rng, 1.1, 2.4);
    match chance(rng, 0.2) {
        true => 1.0 / n,
        false => n,
    }
}

/// sin²θ₂ by Snell's law for a ray at cos θ₁ = `cos_in` and η.
fn sin2_out(cos_in: f32, eta: f32) -> f32 {
    eta * eta * (1.0 - cos_in * cos_in)
}

/// A head-on ray (one case in eight): d = −N, for a normal N whose
/// rounding puts N·N, and so cos θ₁, a hair above 1 (the contract: that
/// counts as 1, never a NaN). Otherwise any d, and N turned to face it.
fn refract(rng: &mut Rng) -> Option<Case> {
    let (d, normal) = match chance(rng, 0.125) {
        true => {
            let n = loop {
                let n = unit(rng);
                if n.dot(n) > 1.0 {
                    break n;
                }
            };
            (-n, n)
        }
        false => {
            let (d, n) = (unit(rng), unit(rng));
            (d, if n.dot(d) > 0.0 { -n } else { n })
        }
    };
    let eta = ior(rng);
    let eta = if chance(rng, 0.5) { 1.0 / eta } else { eta };
    let cos_in = -normal.dot(d);
    // Away from the critical angle, where rounding may decide either way.
    if (sin2_out(cos_in, eta) - 1.0).abs() < 1e-2 {
        return None;
    }
    let bent = ch06_refraction::refract(d, normal, eta);
    Some(Case {
        input: format!("d {}, N {}, η {eta:?}", show(d), show(normal)),
        value: bent.map_or(Value::Null, v3),
    })
}

fn schlick(rng: &mut Rng) -> Option<Case> {
    let cos = match chance(rng, 0.1) {
        true => 1.0 + number(rng, 0.0, 1e-3),
        false if chance(rng, 0.1) => -number(rng, 0.0, 1e-3),
        false => number(rng, 0.0, 1.0),
    };
    let cos = match whole(rng, 0, 9) {
        0 => 0.0,
        1 => 1.0,
        _ => cos,
    };
    let (n1, n2) = match whole(rng, 0, 9) {
        0 => (1.0, 1.0),
        1..=5 => (1.0, ior(rng)),
        _ => (ior(rng), 1.0),
    };
    let share = ch06_refraction::schlick(cos, n1, n2);
    Some(Case {
        input: format!("cos θ {cos:?}, n₁ {n1:?}, n₂ {n2:?}"),
        value: json!(share),
    })
}

/// The values: the indices; whether light is totally reflected; the
/// Fresnel term minus the student's own `schlick` for these indices and
/// the cosine on the side of the smaller one (none without `fresnel`);
/// the two weights minus ρ + T·R and T·(1 − R) with that R; and the
/// refracted direction minus the student's own `refract` with these
/// indices.
fn split(rng: &mut Rng) -> Option<Case> {
    let mut material = material(rng);
    material.transparency = number(rng, 0.1, 1.0);
    material.reflectance = match chance(rng, 0.3) {
        true => Color::ZERO,
        false => color(rng, 0.0, 0.3),
    };
    material.ior = ior(rng);
    material.fresnel = chance(rng, 0.7);
    let mut surface = surface(rng, &material);
    let d = -surface.to_eye;
    // The normal facing the ray, as `Surface::new` turns it: by the
    // geometric normal's side.
    surface.normal = match surface.hit.normal.dot(d) > 0.0 {
        true => -surface.hit.shading_normal,
        false => surface.hit.shading_normal,
    };
    let incoming = Ray {
        origin: surface.hit.point - d * surface.hit.t,
        direction: d,
    };
    let outward = surface.hit.normal;
    if d.dot(outward).abs() < 0.05 || surface.normal.dot(outward) * d.dot(outward) > 0.0 {
        // Along the surface, where the normal on the ray's side is a matter
        // of taste (the tests check the indices there); or the shading
        // normal on the other side.
        return None;
    }
    let entering = d.dot(outward) < 0.0;
    let (n1, n2) = match entering {
        true => (1.0, material.ior),
        false => (material.ior, 1.0),
    };
    let cos_in = -surface.normal.dot(d);
    if (sin2_out(cos_in, n1 / n2) - 1.0).abs() < 1e-2 {
        return None; // at the critical angle
    }
    let split: Split = ch06_refraction::split(&surface, &incoming);
    let own = ch06_refraction::refract(d, surface.normal, n1 / n2);
    let r = match (material.fresnel, own) {
        (true, Some(bent)) => {
            let cos = if n1 <= n2 {
                cos_in
            } else {
                -surface.normal.dot(bent)
            };
            Some(ch06_refraction::schlick(cos, n1, n2))
        }
        _ => None,
    };
    let t = Color::splat(material.transparency);
    let (reflected, refracted) = match own {
        None => (material.reflectance + t, Color::ZERO),
        Some(_) => {
            let r = r.unwrap_or(0.0);
            (material.reflectance + t * r, t * (1.0 - r))
        }
    };
    let fresnel = match (split.fresnel, r) {
        (Some(found), Some(own)) => json!(found - own),
        (Some(_), None) => json!("a term where there is none"),
        (None, _) => Value::Null,
    };
    let bent = split.refracted.map_or(Value::Null, |(weight, direction)| {
        json!([
            v3(weight - refracted),
            v3(direction - own.unwrap_or(Vec3::ZERO))
        ])
    });
    Some(Case {
        input: format!(
            "{}; facing normal {}; arriving d {}; ρ {}, T {:?}, ior {:?}, fresnel {}",
            show_hit(&surface.hit),
            show(surface.normal),
            show(d),
            show(material.reflectance),
            material.transparency,
            material.ior,
            material.fresnel
        ),
        value: json!([
            [split.indices.0, split.indices.1],
            fresnel,
            v3(split.reflected - reflected),
            bent
        ]),
    })
}
