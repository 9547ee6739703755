//! Chapter 4: the shadow ray, which stops at the light (t_max), and its
//! origin moved off the surface by the hit's error bound (shadow acne).

use glam::DVec2;

use crate::Diagram;
use crate::svg::{
    HEADING, INK, LABEL, LIGHT, MEASURE, MUTED, NORMAL, NOTE, SURFACE, SURFACE_FILL, Svg, xy,
};

const CHAPTER: &str = "04-shadows";

pub fn diagrams() -> Vec<Diagram> {
    vec![Diagram::new(CHAPTER, "shadow-ray", shadow_ray())]
}

/// Where a segment from `a` along `d` meets the horizontal line at `y`.
fn at_height(a: DVec2, d: DVec2, y: f64) -> DVec2 {
    a + d * ((y - a.y) / d.y)
}

/// A cross: something the ray hits.
fn cross(svg: &mut Svg, at: DVec2, colour: &str) {
    svg.line(at + xy(-6.0, -6.0), at + xy(6.0, 6.0), colour, 2.5);
    svg.line(at + xy(-6.0, 6.0), at + xy(6.0, -6.0), colour, 2.5);
}

fn shadow_ray() -> crate::svg::Drawn {
    let mut svg = Svg::new(
        600.0,
        380.0,
        "The shadow ray: from just off the surface up to the light",
        "A point light p_L between a floor and a ceiling. From the floor point p, the \
         shadow ray starts at r0 and goes towards the light; it stops at the light, at \
         t_max, so the ceiling beyond the light, hit at t > t_max, casts no \
         shadow. From a second point, a ball between the point and the light, hit at \
         0 < t < t_max, blocks the light. The magnified circle shows why the ray starts \
         at r0 and not at p: the computed hit point p lies a hair below the true \
         surface, within the error bound e; a ray from p would hit its own surface \
         (shadow acne), so r0 is p moved e along the normal n, to the light's side.",
    );
    svg.text(xy(20.0, 28.0), "The shadow ray stops at the light", HEADING);
    let floor = 340.0;
    let ceiling = 70.0;
    let light = xy(205.0, 160.0);
    svg.rect(xy(0.0, floor), xy(600.0, 40.0), SURFACE_FILL, "none", 0.0);
    svg.line(xy(0.0, floor), xy(600.0, floor), SURFACE, 2.0);
    svg.rect(
        xy(20.0, ceiling - 14.0),
        xy(370.0, 14.0),
        SURFACE_FILL,
        "none",
        0.0,
    );
    svg.line(xy(20.0, ceiling), xy(390.0, ceiling), SURFACE, 2.0);
    svg.text(xy(330.0, ceiling - 20.0), "ceiling", NOTE);
    svg.text(xy(530.0, floor + 22.0), "floor", NOTE);
    // The free point: its ray stops at the light; the ceiling is beyond.
    let p = xy(335.0, floor);
    let r0 = p + xy(0.0, -4.0);
    let d = (light - r0).normalize();
    svg.arrow(r0, light - d * 13.0, LIGHT, 2.5);
    let beyond = at_height(light, d, ceiling);
    svg.dashed(light + d * 13.0, beyond, MUTED, 1.5);
    cross(&mut svg, beyond, MUTED);
    for (i, line) in ["t > t_max:", "beyond the light,", "blocks nothing"]
        .iter()
        .enumerate()
    {
        svg.text(beyond + xy(-14.0, 26.0 + 18.0 * i as f64), line, NOTE.end());
    }
    // High on the ray: lower down, the leader line to the magnified view
    // crosses it.
    let along = r0 + (light - r0) * 0.7;
    svg.text(
        along + xy(14.0, 4.0),
        "t_max: at the light",
        LABEL.colour(LIGHT).bold(),
    );
    // Left of the ray, which leaves up and to the left: on the right the
    // leader line runs.
    svg.text(r0 + xy(-20.0, -4.0), "t = 0", NOTE.colour(INK).end());
    svg.dot(p, INK);
    svg.text(p + xy(0.0, 22.0), "p", LABEL.bold().middle());
    // The blocked point: a ball on the way.
    let q = xy(70.0, floor);
    let dq = (light - q).normalize();
    let ball = q + (light - q) * 0.45;
    svg.circle(ball, 24.0, SURFACE_FILL, SURFACE);
    let blocked = ball - dq * 24.0;
    svg.arrow(q + xy(0.0, -4.0), blocked, LIGHT, 2.5);
    svg.dashed(ball + dq * 24.0, light - dq * 13.0, MUTED, 1.2);
    cross(&mut svg, blocked, MEASURE);
    svg.text(ball + xy(30.0, 8.0), "0 < t < t_max:", NOTE.colour(INK));
    svg.text(ball + xy(30.0, 26.0), "blocked", NOTE.colour(INK));
    svg.dot(q, INK);
    // The light.
    svg.circle(light, 12.0, "#ffe27a", LIGHT);
    svg.text(light + xy(18.0, -8.0), "p_L", LABEL.colour(LIGHT).bold());
    inset(&mut svg, p, d);
    svg.finish()
}

/// The magnified view around `p`: the true surface, the computed point
/// below it, its error bound e, and the origin r0 moved off by e.
fn inset(svg: &mut Svg, p: DVec2, towards: DVec2) {
    let centre = xy(500.0, 150.0);
    let radius = 80.0;
    let lens = 14.0;
    svg.circle(p, lens, "none", MUTED);
    // One leader line, from the lens to the magnified view along the line
    // between their centres: the notes below the view stay to its right,
    // clear of it (two lines to the view's sides crossed the notes).
    let towards_view = (centre - p).normalize();
    svg.line(
        p + towards_view * lens,
        centre - towards_view * radius,
        MUTED,
        0.8,
    );
    svg.circle(centre, radius, "#ffffff", MUTED);
    let unit = 34.0;
    let surface_y = centre.y + 10.0;
    let chord = (radius * radius - 10.0 * 10.0).sqrt();
    svg.shade(&half_disc(centre, radius, surface_y), SURFACE_FILL, 1.0);
    svg.line(
        xy(centre.x - chord, surface_y),
        xy(centre.x + chord, surface_y),
        SURFACE,
        2.0,
    );
    let computed = xy(centre.x + 24.0, surface_y + 0.7 * unit);
    let e = unit;
    svg.dashed(computed + xy(-e, -e), computed + xy(e, -e), MEASURE, 1.2);
    svg.dashed(computed + xy(e, -e), computed + xy(e, e), MEASURE, 1.2);
    svg.dashed(computed + xy(e, e), computed + xy(-e, e), MEASURE, 1.2);
    svg.dashed(computed + xy(-e, e), computed + xy(-e, -e), MEASURE, 1.2);
    let r0 = computed + xy(0.0, -e);
    // From p itself the ray meets its own surface: acne.
    let own = at_height(computed, towards, surface_y);
    svg.dashed(computed, own, MEASURE, 1.5);
    cross(svg, own, MEASURE);
    svg.arrow(r0, r0 + towards * 70.0, LIGHT, 2.5);
    svg.arrow(computed, r0, NORMAL, 2.0);
    svg.dot(computed, INK);
    svg.dot(r0, LIGHT);
    svg.text(computed + xy(8.0, 20.0), "p", LABEL.bold());
    svg.text(r0 + xy(8.0, -4.0), "r0", LABEL.colour(LIGHT).bold());
    svg.text(
        computed + xy(8.0, -e / 2.0 + 5.0),
        "e",
        LABEL.colour(NORMAL).bold(),
    );
    // Beside the circle, up and to its left, clear of its edge.
    let corner = centre + xy(-1.0, -1.0) * (radius * std::f64::consts::FRAC_1_SQRT_2 + 8.0);
    svg.text(corner, "magnified", NOTE.end());
    let notes = [
        "p is off by up to e;",
        "from p, the ray hits",
        "its own surface (acne):",
        "r0 is p moved e along n",
    ];
    for (i, note) in notes.iter().enumerate() {
        svg.text(
            xy(centre.x - 70.0, 256.0 + 18.0 * i as f64),
            note,
            NOTE.colour(INK),
        );
    }
}

/// The part of the disc below the line y = `cut` (the surface's inside).
fn half_disc(centre: DVec2, radius: f64, cut: f64) -> Vec<DVec2> {
    let start = ((cut - centre.y) / radius).asin();
    let end = std::f64::consts::PI - start;
    (0..=40)
        .map(|i| {
            let a = start + (end - start) * i as f64 / 40.0;
            centre + xy(a.cos(), a.sin()) * radius
        })
        .collect()
}
