//! Chapter 3: the cosine law, the light loop (through recording closures),
//! the spot's cone.

use super::Probe;
use crate::Case;
use crate::draw::{Rng, axis, chance, exact_point, number, point, show, unit, v3, whole};
use ch03_lambert::toolkit::scene::{Falloff, Light, Material};
use ch03_lambert::toolkit::{Color, Vec3};
use ch03_lambert::{Hit, Incoming, Surface};
use serde_json::json;
use std::cell::RefCell;

pub fn probes() -> Vec<Probe> {
    let probe = |id, case| Probe {
        id,
        chapter: "03-lambert",
        tolerance: 1e-4,
        case,
    };
    vec![
        probe("ch03-lambert", lambert),
        probe("ch03-light-loop", light_loop),
        probe("ch03-spot", spot),
    ]
}

/// A colour with channels in [lo, hi).
pub(super) fn color(rng: &mut Rng, lo: f32, hi: f32) -> Color {
    Color::new(
        number(rng, lo, hi),
        number(rng, lo, hi),
        number(rng, lo, hi),
    )
}

pub(super) fn material(rng: &mut Rng) -> Material {
    Material {
        name: "probe".into(),
        color: color(rng, 0.0, 1.0),
        reflectance: Color::ZERO,
        specular: 0.0,
        shininess: 1.0,
        transparency: 0.0,
        ior: 1.0,
        fresnel: false,
    }
}

/// A surface made field by field (no closest hit, no `Surface::new`).
/// Half of them are back faces: the hit's normals face away from the eye,
/// and the surface's `normal` is them turned (`Surface::new`'s rule), so
/// shading with the hit's normal instead shows in the values.
fn surface<'a>(rng: &mut Rng, material: &'a Material) -> Surface<'a> {
    let normal = unit(rng);
    let geometric = if chance(rng, 0.5) { -normal } else { normal };
    let hit = Hit {
        t: number(rng, 0.5, 20.0),
        point: point(rng, 5.0),
        normal: geometric,
        shading_normal: geometric,
        error: 1e-6,
        object: 0,
    };
    Surface {
        hit,
        normal,
        to_eye: unit(rng),
        material,
    }
}

fn lambert(rng: &mut Rng) -> Option<Case> {
    let material = material(rng);
    let surface = surface(rng, &material);
    let incoming = Incoming {
        direction: unit(rng),
        distance: number(rng, 0.5, 20.0),
        irradiance: color(rng, 0.0, 5.0),
        casts_shadows: true,
    };
    if surface.normal.dot(incoming.direction).abs() < 0.01 {
        return None;
    }
    let seen = ch03_lambert::lambert(&surface, &incoming);
    Some(Case {
        input: format!(
            "albedo {}, n {}, l {}, I_L {}",
            show(material.color),
            show(surface.normal),
            show(incoming.direction),
            show(incoming.irradiance)
        ),
        value: v3(seen),
    })
}

/// A bit of a number's last digits: the recording closures' answers, a
/// function of the light alone (not of the order of the questions).
fn bit(x: f32, which: u32) -> bool {
    (x.to_bits() >> which) & 1 == 1
}

/// `direct_light` over ambient and point lights (no spot: its cone is
/// another exercise) with a `visible` that records which lights it was
/// asked about and answers by the light, and a `reflect` that is not the
/// student's `lambert` and is black for some lights.
///
/// One case in four adds a point light exactly in the surface's plane
/// (in exact numbers, `draw::exact`, on a surface whose normal is an
/// axis): n·l = 0 exactly, so it is behind the surface, never asked about.
fn light_loop(rng: &mut Rng) -> Option<Case> {
    let material = material(rng);
    let mut surface = surface(rng, &material);
    let in_plane = chance(rng, 0.25);
    if in_plane {
        let n = axis(rng);
        (
            surface.normal,
            surface.hit.normal,
            surface.hit.shading_normal,
        ) = (n, n, n);
        surface.hit.point = exact_point(rng, 4.0);
    }
    let mut lights: Vec<Light> = (0..whole(rng, 0, 6))
        .map(|_| match chance(rng, 0.25) {
            true => Light::Ambient {
                color: color(rng, 0.0, 0.3),
            },
            false => Light::Point {
                position: surface.hit.point + unit(rng) * number(rng, 0.5, 8.0),
                color: color(rng, 0.1, 1.0),
                intensity: number(rng, 1.0, 40.0),
                shadows: true,
                falloff: if chance(rng, 0.2) {
                    Falloff::None
                } else {
                    Falloff::InverseSquare
                },
            },
        })
        .collect();
    let grazing = lights.iter().any(|l| match *l {
        Light::Point { position, .. } => {
            let l = (position - surface.hit.point).normalize();
            surface.normal.dot(l).abs() < 0.02
        }
        _ => false,
    });
    if grazing {
        return None;
    }
    if in_plane {
        let along = loop {
            let along = exact_point(rng, 4.0) * (Vec3::ONE - surface.normal.abs());
            if along.length() > 0.5 {
                break along;
            }
        };
        let at = whole(rng, 0, lights.len() as u32) as usize;
        let light = Light::Point {
            position: surface.hit.point + along,
            color: color(rng, 0.1, 1.0),
            intensity: number(rng, 1.0, 40.0),
            shadows: true,
            falloff: Falloff::InverseSquare,
        };
        lights.insert(at, light);
    }
    let mut scene = crate::scenes::parse(crate::scenes::EMPTY);
    scene.lights = lights;
    let asked = RefCell::new(Vec::new());
    let visible = |_: &Surface, incoming: &Incoming| {
        asked.borrow_mut().push(incoming.distance);
        bit(incoming.distance, 11)
    };
    let reflect =
        |incoming: &Incoming| match bit(incoming.distance, 12) && bit(incoming.distance, 13) {
            true => Color::ZERO,
            false => incoming.irradiance * Vec3::new(0.7, 0.5, 0.3) * (1.5 + incoming.direction.x),
        };
    let seen = ch03_lambert::direct_light(&scene, &surface, visible, reflect);
    let mut asked = asked.into_inner();
    asked.sort_by(f32::total_cmp);
    Some(Case {
        input: format!(
            "albedo {}, point {}, n {}, lights {:?}",
            show(material.color),
            show(surface.hit.point),
            show(surface.normal),
            scene.lights
        ),
        value: json!([v3(seen), asked]),
    })
}

fn spot(rng: &mut Rng) -> Option<Case> {
    let axis = unit(rng);
    let inner = number(rng, 0.5, 60.0);
    let outer = if chance(rng, 0.15) {
        inner
    } else {
        number(rng, inner, 89.0)
    };
    // A direction at an angle of up to outer + 20° from the axis.
    let angle = number(rng, 0.0, outer + 20.0);
    if (angle - inner).abs() < 0.05 || (angle - outer).abs() < 0.05 {
        return None;
    }
    let across = axis.cross(unit(rng)).normalize();
    let radians = angle.to_radians();
    let ray = (axis * radians.cos() + across * radians.sin()).normalize();
    let factor = ch03_lambert::spot_factor(axis, inner, outer, ray);
    Some(Case {
        input: format!(
            "axis {}, inner {inner:?}°, outer {outer:?}°, direction {}",
            show(axis),
            show(ray)
        ),
        value: json!(factor),
    })
}
