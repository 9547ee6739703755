//! Chapter 5: the mirror law as a split of d_i into its parts along and
//! across n (the mirrored direction from the chapter's own `reflect`), and
//! Blinn–Phong's halfway vector.

use ch05_reflection::reflect;
use ch05_reflection::toolkit::Vec3;
use glam::DVec2;

use crate::Diagram;
use crate::svg::{
    FRAME, HEADING, INK, LABEL, LIGHT, MEASURE, MIRROR, MUTED, NORMAL, NOTE, Plot, RAY, SURFACE,
    SURFACE_FILL, Svg, fixed, xy,
};

const CHAPTER: &str = "05-reflection";

pub fn diagrams() -> Vec<Diagram> {
    vec![
        Diagram::new(CHAPTER, "reflection-split", reflection_split()),
        Diagram::new(CHAPTER, "half-vector", half_vector()),
    ]
}

fn v2(v: Vec3) -> DVec2 {
    DVec2::new(v.x as f64, v.y as f64)
}

/// A surface along the page at `y`, filled below, from `x0` to `x1`.
fn surface(svg: &mut Svg, x0: f64, x1: f64, y: f64) {
    svg.rect(xy(x0, y), xy(x1 - x0, 26.0), SURFACE_FILL, "none", 0.0);
    svg.line(xy(x0, y), xy(x1, y), SURFACE, 2.0);
}

fn reflection_split() -> crate::svg::Drawn {
    let theta = 35f32.to_radians();
    let d_i = Vec3::new(theta.sin(), -theta.cos(), 0.0);
    let n = Vec3::Y;
    let d_o = reflect(d_i, n);
    let along = v2(d_i.dot(n) * n);
    let across = v2(d_i - d_i.dot(n) * n);
    let mut svg = Svg::new(
        600.0,
        370.0,
        "The mirror law: keep the part across n, reverse the part along it",
        "A ray arrives along d_i at a mirror with the normal n and leaves along d_o, at \
         the same angle θ on the other side of n. On the right, d_i is split into its \
         part along n and its part across n. The mirror keeps the part across and \
         reverses the part along: d_o = across − along.",
    );
    svg.text(
        xy(20.0, 28.0),
        "The mirror reverses the part along n",
        HEADING,
    );
    let hit = xy(165.0, 272.0);
    let plot = Plot::new(hit, 160.0);
    surface(&mut svg, 10.0, 320.0, hit.y);
    let a = plot.p(-v2(d_i));
    svg.arrow(a, hit, RAY, 2.5);
    svg.arrow(hit, plot.p(v2(d_o)), MIRROR, 2.5);
    svg.arrow(hit, plot.at(0.0, 0.72), NORMAL, 2.5);
    svg.text(
        plot.at(0.0, 0.72) + xy(8.0, 4.0),
        "n",
        LABEL.colour(NORMAL).bold(),
    );
    svg.angle(hit, 62.0, xy(0.0, -1.0), a - hit, MEASURE);
    svg.angle(hit, 62.0, xy(0.0, -1.0), plot.p(v2(d_o)) - hit, MEASURE);
    svg.text(
        hit + xy(-24.0, -70.0),
        "θ",
        LABEL.colour(MEASURE).bold().middle(),
    );
    svg.text(
        hit + xy(24.0, -70.0),
        "θ",
        LABEL.colour(MEASURE).bold().middle(),
    );
    svg.text(
        (a + hit) / 2.0 + xy(-12.0, 6.0),
        "d_i",
        LABEL.colour(RAY).bold().end(),
    );
    svg.text(
        (hit + plot.p(v2(d_o))) / 2.0 + xy(12.0, 6.0),
        "d_o",
        LABEL.colour(MIRROR).bold(),
    );
    svg.text(xy(20.0, 320.0), "mirror", NOTE);
    // The two sums, head to tail, on the right.
    let scale = 120.0;
    let top = xy(370.0, 70.0);
    let bottom = xy(370.0, 300.0);
    let page = |v: DVec2| xy(v.x, -v.y) * scale;
    parts(
        &mut svg,
        top,
        page(across),
        page(along),
        RAY,
        "d_i",
        "along",
    );
    parts(
        &mut svg,
        bottom,
        page(across),
        page(-along),
        MIRROR,
        "d_o",
        "−along",
    );
    // What each part is in d_i and n is the exercise (ch05-reflect): the
    // picture names the parts and the law, not their formulas.
    svg.fact(xy(20.0, 362.0), "d_o = across − along", LABEL.bold());
    svg.finish()
}

/// `sum` drawn as its part across (first) and its part along n (second),
/// head to tail from `start`.
fn parts(
    svg: &mut Svg,
    start: DVec2,
    across: DVec2,
    along: DVec2,
    colour: &'static str,
    sum: &str,
    along_name: &str,
) {
    let corner = start + across;
    let end = corner + along;
    svg.arrow(start, corner, FRAME, 2.2);
    svg.arrow(corner, end, MEASURE, 2.2);
    svg.arrow(start, end, colour, 2.5);
    svg.text(
        (start + corner) / 2.0 + xy(0.0, if along.y > 0.0 { -8.0 } else { 20.0 }),
        "across",
        LABEL.colour(FRAME).middle(),
    );
    svg.text(
        (corner + end) / 2.0 + xy(10.0, 0.0),
        along_name,
        LABEL.colour(MEASURE),
    );
    svg.text(
        (start + end) / 2.0 + xy(-10.0, 4.0),
        sum,
        LABEL.colour(colour).bold().end(),
    );
}

/// The halfway vector between l and v, and how fast the highlight falls
/// as h leans away from n.
fn half_vector() -> crate::svg::Drawn {
    let mut svg = Svg::new(
        600.0,
        340.0,
        "Blinn–Phong's halfway vector",
        "At a shiny point with the normal n, l points to the light and v to the eye. \
         Their halfway vector h is the normal a mirror would need \
         to send the light into the eye. The highlight falls as h leans from n: \
         with h 10° off n it keeps 0.86 of the peak at s = 10 but only 0.22 at s = 100.",
    );
    svg.text(xy(20.0, 28.0), "The halfway vector h", HEADING);
    let hit = xy(175.0, 270.0);
    surface(&mut svg, 10.0, 300.0, hit.y);
    let dir = |degrees: f64| {
        let (sin, cos) = degrees.to_radians().sin_cos();
        xy(sin, -cos)
    };
    let (l, v) = (dir(-52.0), dir(24.0));
    let h = (l + v).normalize();
    let length = 125.0;
    svg.arrow(hit, hit + l * length, LIGHT, 2.5);
    svg.arrow(hit, hit + v * length, RAY, 2.5);
    svg.arrow(hit, hit + xy(0.0, -length * 0.95), NORMAL, 2.5);
    svg.arrow(hit, hit + h * length * 0.8, MEASURE, 2.5);
    svg.dashed(hit + l * length, hit + (l + v) * length, MUTED, 1.0);
    svg.dashed(hit + v * length, hit + (l + v) * length, MUTED, 1.0);
    svg.circle(hit + l * (length + 14.0), 11.0, "#ffe27a", LIGHT);
    svg.text(
        hit + l * length + xy(-4.0, 22.0),
        "l",
        LABEL.colour(LIGHT).bold().math().end(),
    );
    svg.text(
        hit + v * length + xy(10.0, 4.0),
        "v",
        LABEL.colour(RAY).bold().math(),
    );
    svg.text(
        hit + v * (length + 16.0) + xy(10.0, -8.0),
        "eye",
        NOTE.colour(INK),
    );
    svg.text(
        hit + xy(8.0, -length * 0.95 + 6.0),
        "n",
        LABEL.colour(NORMAL).bold().math(),
    );
    svg.text(
        hit + h * length * 0.8 + xy(-10.0, -4.0),
        "h",
        LABEL.colour(MEASURE).bold().math().end(),
    );
    svg.text(
        hit + (l + v) * length + xy(-6.0, -6.0),
        "halfway",
        NOTE.end(),
    );
    svg.text(xy(20.0, 318.0), "h: halfway between l and v", LABEL.bold());
    falloff_plot(&mut svg);
    svg.finish()
}

/// max(0, n·h)^s against the angle between n and h, for s = 10 and 100.
fn falloff_plot(svg: &mut Svg) {
    let origin = xy(345.0, 250.0);
    let (per_degree, height) = (6.0, 170.0);
    let at = |angle: f64, value: f64| origin + xy(angle * per_degree, -value * height);
    svg.line(origin, at(40.0, 0.0), INK, 1.5);
    svg.line(origin, at(0.0, 1.1), INK, 1.5);
    svg.text(at(0.0, 1.0) + xy(-6.0, 5.0), "1", NOTE.end());
    svg.text(at(0.0, 0.0) + xy(-6.0, 5.0), "0", NOTE.end());
    for angle in [0.0, 10.0, 20.0, 30.0, 40.0] {
        svg.text(
            at(angle, 0.0) + xy(0.0, 20.0),
            &format!("{angle}°"),
            NOTE.middle(),
        );
    }
    svg.text(
        at(20.0, 0.0) + xy(0.0, 42.0),
        "angle between n and h",
        NOTE.colour(INK).middle(),
    );
    svg.text(at(0.0, 1.1) + xy(8.0, 4.0), "(n·h)^s", NOTE.colour(INK));
    svg.dashed(at(10.0, 0.0), at(10.0, 1.0), MUTED, 1.0);
    for (s, colour, label_at) in [(10.0, LIGHT, 26.0), (100.0, MEASURE, 13.0)] {
        let value = |angle: f64| angle.to_radians().cos().max(0.0).powf(s);
        let curve: Vec<DVec2> = (0..=160)
            .map(|i| at(i as f64 * 0.25, value(i as f64 * 0.25)))
            .collect();
        svg.polyline(&curve, colour, 2.5);
        svg.dot(at(10.0, value(10.0)), colour);
        svg.text(
            at(10.0, value(10.0)) + xy(8.0, -6.0),
            &fixed(value(10.0), 2),
            NOTE.colour(colour),
        );
        svg.text(
            at(label_at, value(label_at)) + xy(4.0, -8.0),
            &format!("s = {s}"),
            LABEL.colour(colour).bold(),
        );
    }
    let (broad, sharp) = (
        10f64.to_radians().cos().powf(10.0),
        10f64.to_radians().cos().powf(100.0),
    );
    svg.text_with_fact(
        xy(345.0, 318.0),
        &format!("keeps {} of the peak at s = 10", fixed(broad, 2)),
        &format!("{} of the peak at s = 10", fixed(broad, 2)),
        NOTE.colour(INK),
    );
    svg.text_with_fact(
        xy(345.0, 336.0),
        &format!("but only {} at s = 100", fixed(sharp, 2)),
        &format!("{} at s = 100", fixed(sharp, 2)),
        NOTE.colour(INK),
    );
}
