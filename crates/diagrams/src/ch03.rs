//! Chapter 3: Lambert's cos θ footprint, and the spot light's two cones
//! with the smooth step between them (the default scene's spot, its factor
//! from the chapter's own `spot_factor`).

use ch03_lambert::toolkit::Vec3;
use ch03_lambert::toolkit::scene::Light;
use ch03_lambert::{scene_files, spot_factor};
use glam::DVec2;

use crate::Diagram;
use crate::svg::{
    HEADING, INK, LABEL, LIGHT, MEASURE, MUTED, NORMAL, NOTE, SURFACE, SURFACE_FILL, Svg, fixed, xy,
};

const CHAPTER: &str = "03-lambert";

pub fn diagrams() -> Vec<Diagram> {
    vec![
        Diagram::new(CHAPTER, "lambert-footprint", lambert_footprint()),
        Diagram::new(CHAPTER, "spot-cone", spot_cone()),
    ]
}

/// The same beam on a surface that faces it and on one tilted by θ = 60°.
fn lambert_footprint() -> crate::svg::Drawn {
    let mut svg = Svg::new(
        600.0,
        360.0,
        "Lambert's cosine law: the footprint of a beam",
        "A beam of light of cross-section A falls on a surface. Facing the light, it \
         covers the area A. Tilted by θ = 60°, the same beam spreads over A / cos θ, \
         twice the area, so each unit of area receives cos θ, half, of what it got \
         facing the light: E = I_L · cos θ.",
    );
    svg.text(xy(20.0, 28.0), "The same beam on more area", HEADING);
    let floor = 262.0;
    svg.rect(xy(0.0, floor), xy(600.0, 40.0), SURFACE_FILL, "none", 0.0);
    svg.line(xy(0.0, floor), xy(600.0, floor), SURFACE, 2.0);
    beam(&mut svg, xy(150.0, floor), 0.0, "facing the light: θ = 0");
    beam(&mut svg, xy(460.0, floor), 60.0, "tilted by θ = 60°");
    svg.fact(
        xy(300.0, 342.0),
        "E = I_L · cos θ",
        LABEL.bold().math().middle(),
    );
    svg.finish()
}

/// One beam of width A arriving at `theta` degrees from the normal at
/// `hit`, with its footprint measured on the surface.
fn beam(svg: &mut Svg, hit: DVec2, theta: f64, title: &str) {
    let width = 76.0;
    let (sin, cos) = theta.to_radians().sin_cos();
    let travel = xy(sin, cos); // down the page, towards the surface
    let across = xy(cos, -sin); // at right angles to the beam
    let footprint = width / cos;
    let hits: Vec<DVec2> = (0..5)
        .map(|k| hit + xy((k as f64 / 4.0 - 0.5) * footprint, 0.0))
        .collect();
    let length = 150.0;
    // The beam starts on a cross-section at right angles to it.
    let start = hits[0] - travel * length;
    let starts: Vec<DVec2> = (0..5)
        .map(|k| start + across * (width * k as f64 / 4.0))
        .collect();
    svg.shade(&[starts[0], starts[4], hits[4], hits[0]], LIGHT, 0.14);
    for (&from, &to) in starts.iter().zip(&hits) {
        svg.arrow(from, to, LIGHT, 1.8);
    }
    // A, measured across the beam, just before it starts.
    let (a, b) = (starts[0] - travel * 12.0, starts[4] - travel * 12.0);
    svg.line(a, b, MEASURE, 2.0);
    svg.text(
        (a + b) / 2.0 - travel * 14.0 + xy(0.0, 5.0),
        "A",
        LABEL.colour(MEASURE).bold().middle(),
    );
    // The footprint, measured on the surface.
    let (left, right) = (hits[0] + xy(0.0, 16.0), hits[4] + xy(0.0, 16.0));
    svg.line(left, right, MEASURE, 2.0);
    svg.line(left - xy(0.0, 6.0), left + xy(0.0, 6.0), MEASURE, 2.0);
    svg.line(right - xy(0.0, 6.0), right + xy(0.0, 6.0), MEASURE, 2.0);
    let label = if theta == 0.0 { "A" } else { "A / cos θ" };
    let at = (left + right) / 2.0 + xy(0.0, 22.0);
    if theta == 0.0 {
        svg.text(at, label, LABEL.colour(MEASURE).bold().middle());
    } else {
        svg.fact(at, label, LABEL.colour(MEASURE).bold().middle());
    }
    // n and l at the beam's middle, and θ between them.
    let n_tip = hit + xy(0.0, -95.0);
    svg.arrow(hit, n_tip, NORMAL, 2.5);
    svg.text(
        n_tip + xy(8.0, 4.0),
        "n",
        LABEL.colour(NORMAL).bold().math(),
    );
    if theta > 0.0 {
        let l_tip = hit - travel * 95.0;
        svg.arrow(hit, l_tip, INK, 2.0);
        svg.text(l_tip + xy(-6.0, -6.0), "l", LABEL.bold().math().end());
        svg.angle(hit, 40.0, xy(0.0, -1.0), -travel, MEASURE);
        svg.text(
            hit + xy(-14.0, -46.0),
            "θ",
            LABEL.colour(MEASURE).bold().end(),
        );
    }
    svg.text(xy(hit.x, 58.0), title, LABEL.middle());
}

/// The default scene's spot light: its axis and its two half-angles.
fn default_spot() -> (Vec3, f32, f32) {
    let path = crate::workspace_root().join("chapters/03-lambert/scenes/default.toml");
    let scene = scene_files::load(&path).expect("chapter 3's default scene loads");
    scene
        .lights
        .iter()
        .find_map(|light| match *light {
            Light::Spot {
                direction,
                inner_degrees,
                outer_degrees,
                ..
            } => Some((direction, inner_degrees, outer_degrees)),
            _ => None,
        })
        .expect("chapter 3's default scene has a spot light")
}

/// The spot's factor for a direction `phi` degrees off its axis.
fn factor_at(axis: Vec3, inner: f32, outer: f32, phi: f32) -> f32 {
    // A direction phi degrees off the axis, turned about an axis at right
    // angles to it.
    let side = axis.any_orthonormal_vector();
    let (sin, cos) = phi.to_radians().sin_cos();
    spot_factor(axis, inner, outer, cos * axis + sin * side)
}

/// The spot's cones over the floor, and its factor against the angle φ.
fn spot_cone() -> crate::svg::Drawn {
    let (axis, inner, outer) = default_spot();
    let middle = (inner + outer) / 2.0;
    let s = (middle.to_radians().cos() - outer.to_radians().cos())
        / (inner.to_radians().cos() - outer.to_radians().cos());
    let factor = factor_at(axis, inner, outer, middle);
    let mut svg = Svg::new(
        600.0,
        380.0,
        "The spot light's inner and outer cone",
        &format!(
            "Left, the default scene's spot light above the floor: full light within \
             φ_i = {inner}° of its axis a, none beyond φ_o = {outer}°, and a smooth fall \
             in between. Right, the factor against the angle φ: 1 up to {inner}°, the \
             smooth step down to 0 at {outer}°; at {middle}°, halfway in \
             degrees, s ≈ {} and the factor is {}.",
            fixed(s as f64, 3),
            fixed(factor as f64, 3)
        ),
    );
    svg.text(
        xy(20.0, 28.0),
        "Full light, a smooth fall, then none",
        HEADING,
    );
    let light = xy(165.0, 78.0);
    let floor = 318.0;
    let drop = floor - light.y;
    let foot = |phi: f32| xy(light.x + drop * (phi as f64).to_radians().tan(), floor);
    // The pool of light on the floor, sampled from the factor.
    svg.rect(xy(20.0, floor), xy(290.0, 22.0), SURFACE_FILL, "none", 0.0);
    for i in 0..145 {
        let x = 20.0 + 2.0 * i as f64;
        let phi = ((x + 1.0 - light.x) / drop).atan().to_degrees().abs() as f32;
        let f = factor_at(axis, inner, outer, phi) as f64;
        if f > 0.0 {
            svg.shade(
                &[
                    xy(x, floor),
                    xy(x + 2.0, floor),
                    xy(x + 2.0, floor + 22.0),
                    xy(x, floor + 22.0),
                ],
                "#f5c000",
                f,
            );
        }
    }
    svg.line(xy(20.0, floor), xy(310.0, floor), SURFACE, 2.0);
    for (phi, colour) in [(outer, MUTED), (inner, LIGHT)] {
        svg.line(light, foot(phi), colour, 1.5);
        svg.line(light, foot(-phi), colour, 1.5);
    }
    svg.arrow(light, xy(light.x, light.y + 95.0), INK, 2.0);
    svg.text(xy(light.x - 8.0, light.y + 92.0), "a", LABEL.bold().end());
    svg.angle(light, 150.0, xy(0.0, 1.0), foot(inner) - light, LIGHT);
    svg.angle(light, 185.0, xy(0.0, 1.0), foot(outer) - light, MUTED);
    svg.dashed(light, foot(-middle), MEASURE, 1.5);
    svg.dot(foot(-middle), MEASURE);
    svg.circle(light, 11.0, "#ffe27a", LIGHT);
    svg.text(light + xy(18.0, -6.0), "spot", LABEL.colour(LIGHT).bold());
    svg.fact(
        xy(222.0, 112.0),
        &format!("φ_i = {inner}°"),
        LABEL.colour(LIGHT).bold(),
    );
    svg.text(xy(222.0, 130.0), "inner cone", NOTE.colour(LIGHT));
    svg.fact(
        xy(222.0, 158.0),
        &format!("φ_o = {outer}°"),
        LABEL.colour(MUTED).bold(),
    );
    svg.text(xy(222.0, 176.0), "outer cone", NOTE);
    svg.text(
        // Left of the outer cone's line, which passes just above the point.
        foot(-middle) + xy(-22.0, -12.0),
        &format!("φ = {middle}°"),
        LABEL.colour(MEASURE).end(),
    );
    factor_plot(&mut svg, (axis, inner, outer), middle, s, factor);
    svg.finish()
}

/// The factor against φ, from 0° to 30°, with the halfway point marked.
fn factor_plot(svg: &mut Svg, spot: (Vec3, f32, f32), middle: f32, s: f32, factor: f32) {
    let (axis, inner, outer) = spot;
    let origin = xy(350.0, 300.0);
    let (per_degree, height) = (7.5, 190.0);
    let at = |phi: f64, f: f64| origin + xy(phi * per_degree, -f * height);
    svg.line(origin, at(31.0, 0.0), INK, 1.5);
    svg.line(origin, at(0.0, 1.12), INK, 1.5);
    svg.text(at(31.0, 0.0) + xy(4.0, 5.0), "φ", LABEL.bold());
    svg.text(at(0.0, 1.12) + xy(-6.0, 4.0), "factor", LABEL.end());
    svg.text(at(0.0, 1.0) + xy(-6.0, 5.0), "1", NOTE.end());
    svg.text(at(0.0, 0.0) + xy(-6.0, 5.0), "0", NOTE.end());
    for phi in [0.0, inner, outer, 30.0] {
        let x = at(phi as f64, 0.0);
        svg.text(x + xy(0.0, 20.0), &format!("{phi}°"), NOTE.middle());
        if phi == inner || phi == outer {
            svg.dashed(x, at(phi as f64, 1.05), MUTED, 1.0);
        }
    }
    let curve: Vec<DVec2> = (0..=120)
        .map(|i| {
            let phi = i as f32 * 0.25;
            at(phi as f64, factor_at(axis, inner, outer, phi) as f64)
        })
        .collect();
    svg.polyline(&curve, LIGHT, 3.0);
    let mark = at(middle as f64, factor as f64);
    svg.dashed(at(middle as f64, 0.0), mark, MEASURE, 1.2);
    svg.dot(mark, MEASURE);
    // Right of the 22° line, which crossed them beside the mark.
    svg.text_with_fact(
        xy(at(outer as f64, 0.0).x + 8.0, mark.y - 20.0),
        &format!("s ≈ {}", fixed(s as f64, 3)),
        &format!("≈ {}", fixed(s as f64, 3)),
        LABEL.colour(MEASURE),
    );
    svg.text_with_fact(
        xy(at(outer as f64, 0.0).x + 8.0, mark.y),
        &format!("S ≈ {}", fixed(factor as f64, 3)),
        &format!("≈ {}", fixed(factor as f64, 3)),
        LABEL.colour(MEASURE).bold(),
    );
    svg.text(
        at(inner as f64 / 2.0, 1.0) + xy(0.0, -10.0),
        "inside",
        NOTE.middle(),
    );
    svg.text(at(26.0, 0.0) + xy(0.0, -10.0), "outside", NOTE.middle());
    svg.text(
        at(0.0, 0.0) + xy(0.0, 52.0),
        "the smooth step S(s) between the cones",
        NOTE,
    );
}
