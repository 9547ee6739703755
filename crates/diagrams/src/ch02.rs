//! Chapter 2: the sphere's two roots, and the areas behind a triangle's
//! barycentric weights. Both draw the README's worked examples, with the
//! numbers from the chapter's own tests (`sphere_roots`, `barycentrics`).

use ch02_hits::toolkit::Vec3;
use ch02_hits::{Ray, barycentrics, sphere_roots};
use glam::DVec2;

use crate::Diagram;
use crate::svg::{
    HEADING, INK, LABEL, MEASURE, MUTED, NOTE, Plot, RAY, SURFACE, SURFACE_FILL, Svg, number, xy,
};

const CHAPTER: &str = "02-hits";

pub fn diagrams() -> Vec<Diagram> {
    vec![
        Diagram::new(CHAPTER, "sphere-roots", sphere_roots_diagram()),
        Diagram::new(CHAPTER, "barycentric-areas", barycentric_areas()),
    ]
}

/// The README's rays straight down onto the unit sphere at the origin:
/// through the centre (two roots), at x = 1 (a tangent) and further out
/// (no root).
fn sphere_roots_diagram() -> crate::svg::Drawn {
    let mut svg = Svg::new(
        600.0,
        420.0,
        "The sphere's two roots",
        "Three rays straight down onto the unit sphere at the origin. The ray from \
         (0, 2, 0) has two roots: it enters the sphere at t₀ = 1 and leaves at t₁ = 3 \
         (Δ > 0). The ray from (1, 2, 0) touches the sphere at t = 2, a double root \
         (Δ = 0). A ray further out has no real root (Δ < 0) and misses.",
    );
    svg.text(xy(20.0, 28.0), "Where a ray's line meets a sphere", HEADING);
    let plot = Plot::new(xy(180.0, 240.0), 80.0);
    let m = plot.at(0.0, 0.0);
    svg.circle(m, plot.scale, SURFACE_FILL, SURFACE);
    svg.dot(m, INK);
    svg.text(m + xy(-8.0, -4.0), "m", LABEL.bold().end());
    let rim = plot.at(-0.6, -0.8);
    svg.line(m, rim, INK, 1.2);
    svg.text((m + rim) / 2.0 + xy(-6.0, 0.0), "ρ", LABEL.end());
    let rd = Vec3::new(0.0, -1.0, 0.0);
    for (i, x) in [0.0f32, 1.0, 1.6].into_iter().enumerate() {
        let r0 = Vec3::new(x, 2.0, 0.0);
        let ray = Ray::new(r0, rd);
        let start = plot.at(x as f64, 2.0);
        svg.arrow(start, plot.at(x as f64, -1.75), RAY, 2.0);
        svg.dot(start, RAY);
        badge(&mut svg, start + xy(0.0, -20.0), i + 1);
        if let Some((t0, t1)) = sphere_roots(Vec3::ZERO, 1.0, &ray) {
            for t in [t0, t1] {
                let p = ray.at(t);
                svg.circle(plot.at(p.x as f64, p.y as f64), 5.5, "#ffffff", MEASURE);
            }
            if t0 == t1 {
                let p = plot.at(x as f64, ray.at(t0).y as f64);
                svg.text(p + xy(-10.0, -8.0), "t", LABEL.colour(MEASURE).end());
            } else {
                let (p0, p1) = (ray.at(t0), ray.at(t1));
                svg.text(
                    plot.at(0.0, p0.y as f64) + xy(-10.0, -6.0),
                    "t₀",
                    LABEL.colour(MEASURE).end(),
                );
                svg.text(
                    plot.at(0.0, p1.y as f64) + xy(-10.0, 18.0),
                    "t₁",
                    LABEL.colour(MEASURE).end(),
                );
            }
        }
    }
    svg.text(
        plot.at(0.0, 2.0) + xy(-12.0, 5.0),
        "r0",
        LABEL.colour(RAY).end(),
    );
    legend(&mut svg, plot);
    svg.finish()
}

/// A ray's number, in a small circle.
fn badge(svg: &mut Svg, at: DVec2, number: usize) {
    svg.circle(at, 10.0, "#ffffff", RAY);
    svg.text(
        at + xy(0.0, 5.0),
        &number.to_string(),
        NOTE.colour(RAY).middle().bold(),
    );
}

/// What each ray's discriminant says, with the README's numbers.
fn legend(svg: &mut Svg, plot: Plot) {
    let rd = Vec3::new(0.0, -1.0, 0.0);
    let roots = |x: f32| sphere_roots(Vec3::ZERO, 1.0, &Ray::new(Vec3::new(x, 2.0, 0.0), rd));
    let (t0, t1) = roots(0.0).expect("the ray through the centre hits");
    let (touch, _) = roots(1.0).expect("the tangent touches");
    let left = 370.0;
    let rows: [(f64, &str, Vec<String>); 3] = [
        (
            110.0,
            "Δ > 0: two roots",
            vec![
                format!("enters at t = {}", number(t0 as f64, 3)),
                format!("leaves at t = {}", number(t1 as f64, 3)),
            ],
        ),
        (
            215.0,
            "Δ = 0: one double root",
            vec![
                format!("t = {}", number(touch as f64, 3)),
                "a tangent".to_owned(),
            ],
        ),
        (
            310.0,
            "Δ < 0: no real root",
            vec!["the line passes by".to_owned()],
        ),
    ];
    for (i, (y, head, lines)) in rows.iter().enumerate() {
        badge(svg, xy(left, y - 5.0), i + 1);
        svg.fact(xy(left + 18.0, *y), head, LABEL.bold());
        for (k, line) in lines.iter().enumerate() {
            let at = xy(left + 18.0, y + 22.0 * (k as f64 + 1.0));
            if line.starts_with("enters") || line.starts_with("leaves") || line.starts_with("t =") {
                svg.fact(at, line, LABEL.colour(MEASURE));
            } else {
                svg.text(at, line, LABEL.colour(MUTED));
            }
        }
    }
    svg.text(
        xy(20.0, 405.0),
        "t = (−b ± √Δ) / 2a, with Δ = b² − 4ac: the roots of the whole line, t₀ ≤ t₁",
        NOTE,
    );
    let _ = plot;
}

/// The README's triangle p₀ = (0, 0, −1), p₁ = (4, 0, −1), p₂ = (0, 2, −1)
/// and the point x = (2, 0.5, −1) where its ray meets it: the three parts
/// whose areas are the weights.
fn barycentric_areas() -> crate::svg::Drawn {
    let corners = [
        Vec3::new(0.0, 0.0, -1.0),
        Vec3::new(4.0, 0.0, -1.0),
        Vec3::new(0.0, 2.0, -1.0),
    ];
    let ray = Ray::new(Vec3::new(2.0, 0.5, 3.0), Vec3::NEG_Z);
    let (alpha, beta) = barycentrics(corners, &ray);
    let twice_area = (corners[1] - corners[0])
        .cross(corners[2] - corners[0])
        .length();
    let x = (1.0 - alpha - beta) * corners[0] + alpha * corners[1] + beta * corners[2];
    let mut svg = Svg::new(
        600.0,
        330.0,
        "Barycentric weights as areas",
        "The triangle p₀ = (0, 0), p₁ = (4, 0), p₂ = (0, 2) and the point x = (2, 0.5) \
         inside it, joined to the three corners. The part (p₀, x, p₂), opposite p₁, is \
         α = 4 / 8 = 0.5 of the whole area; the part (p₀, p₁, x), opposite p₂, is \
         β = 2 / 8 = 0.25; the part (x, p₁, p₂), opposite p₀, is the rest, \
         1 − α − β = 0.25.",
    );
    svg.text(
        xy(20.0, 28.0),
        "The weights are shares of the area",
        HEADING,
    );
    let plot = Plot::new(xy(45.0, 260.0), 72.0);
    let at = |v: Vec3| plot.at(v.x as f64, v.y as f64);
    let [p0, p1, p2] = corners.map(at);
    let px = at(x);
    let (alpha_fill, beta_fill, gamma_fill) = ("#f2a541", "#7b9acc", "#8cc084");
    svg.shade(&[p0, px, p2], alpha_fill, 0.55);
    svg.shade(&[p0, p1, px], beta_fill, 0.55);
    svg.shade(&[px, p1, p2], gamma_fill, 0.55);
    for &corner in &[p0, p1, p2] {
        svg.line(px, corner, MUTED, 1.2);
    }
    svg.polygon(&[p0, p1, p2], "none", SURFACE);
    svg.dot(px, INK);
    svg.text(px + xy(8.0, -8.0), "x", LABEL.bold());
    svg.text(p0 + xy(-6.0, 20.0), "p₀", LABEL.bold().end());
    svg.text(p1 + xy(6.0, 20.0), "p₁", LABEL.bold());
    svg.text(p2 + xy(-8.0, 4.0), "p₂", LABEL.bold().end());
    let centroid = |a: DVec2, b: DVec2, c: DVec2| (a + b + c) / 3.0;
    svg.text(
        centroid(p0, px, p2) + xy(0.0, 6.0),
        "α",
        LABEL.bold().middle(),
    );
    svg.text(
        centroid(p0, p1, px) + xy(0.0, 6.0),
        "β",
        LABEL.bold().middle(),
    );
    let gamma = centroid(px, p1, p2);
    let gamma_label = plot.at(2.6, 1.45);
    svg.line(gamma, gamma_label + xy(0.0, 4.0), MUTED, 1.0);
    svg.text(gamma_label, "1 − α − β", LABEL.bold());
    let left = 392.0;
    let share = |weight: f32| {
        format!(
            "{} / {} = {}",
            number((weight * twice_area) as f64, 3),
            number(twice_area as f64, 3),
            number(weight as f64, 3)
        )
    };
    let rows = [
        (
            "(p₀, x, p₂), opposite p₁:",
            format!("α = {}", share(alpha)),
            alpha_fill,
        ),
        (
            "(p₀, p₁, x), opposite p₂:",
            format!("β = {}", share(beta)),
            beta_fill,
        ),
        (
            "(x, p₁, p₂), opposite p₀:",
            format!("1 − α − β = {}", number((1.0 - alpha - beta) as f64, 3)),
            gamma_fill,
        ),
    ];
    for (i, (part, weight, fill)) in rows.iter().enumerate() {
        let y = 80.0 + 62.0 * i as f64;
        svg.rounded(xy(left - 14.0, y - 16.0), xy(10.0, 42.0), fill, 0.8, "none");
        svg.text(xy(left, y), part, LABEL);
        if i < 2 {
            svg.fact(xy(left, y + 22.0), weight, LABEL.bold());
        } else {
            svg.text(xy(left, y + 22.0), weight, LABEL.bold());
        }
    }
    svg.text(
        xy(left - 14.0, 280.0),
        "x = (1 − α − β)·p₀ + α·p₁ + β·p₂",
        NOTE.colour(INK),
    );
    svg.text(
        xy(left - 14.0, 302.0),
        "a weight is 0 on the edge it faces",
        NOTE,
    );
    svg.finish()
}
