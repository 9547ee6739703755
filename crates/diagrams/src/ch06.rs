//! Chapter 6: the refracted direction as the split of chapter 5 with the
//! part across scaled by η, the critical angle, and Schlick's curve. The
//! directions come from the chapter's own `refract` and `reflect`, the
//! critical angle from where `refract` starts to answer `None`, the curve
//! from `schlick`.

use ch06_refraction::toolkit::Vec3;
use ch06_refraction::{reflect, refract, schlick};
use glam::DVec2;

use crate::Diagram;
use crate::svg::{
    FRAME, GLASS_FILL, HEADING, INK, LABEL, MEASURE, MIRROR, MUTED, NORMAL, NOTE, Plot, RAY,
    REFRACT, SURFACE, Svg, fixed, xy,
};

const CHAPTER: &str = "06-refraction";
/// The chapters' glass.
const GLASS: f32 = 1.5;

pub fn diagrams() -> Vec<Diagram> {
    vec![
        Diagram::new(CHAPTER, "refraction-split", refraction_split()),
        Diagram::new(CHAPTER, "critical-angle", critical_angle_diagram()),
        Diagram::new(CHAPTER, "schlick", schlick_curve()),
    ]
}

fn v2(v: Vec3) -> DVec2 {
    DVec2::new(v.x as f64, v.y as f64)
}

/// A unit direction going down at `degrees` from −N (N = +y), leaning to +x.
fn downwards(degrees: f64) -> Vec3 {
    let (sin, cos) = degrees.to_radians().sin_cos();
    Vec3::new(sin as f32, -cos as f32, 0.0)
}

/// The angle of a downward direction from −N, in degrees.
fn from_minus_n(d: Vec3) -> f64 {
    (-d.y as f64).acos().to_degrees()
}

/// The critical angle for leaving glass into air, in degrees: where the
/// chapter's `refract` stops returning a ray (found by bisection).
pub fn critical_angle() -> f64 {
    let (mut low, mut high) = (0.0, 90.0);
    for _ in 0..60 {
        let mid = (low + high) / 2.0;
        if refract(downwards(mid), Vec3::Y, GLASS).is_some() {
            low = mid;
        } else {
            high = mid;
        }
    }
    low
}

/// Glass below the page's line `y`, air above, from `x0` to `x1`.
fn glass(svg: &mut Svg, x0: f64, x1: f64, y: f64, bottom: f64) {
    svg.rect(xy(x0, y), xy(x1 - x0, bottom - y), GLASS_FILL, "none", 0.0);
    svg.line(xy(x0, y), xy(x1, y), SURFACE, 2.0);
}

/// 30° into glass: the unit circle shows d's part across N (length sin θ₁)
/// and the refracted ray's, η times as long (sin θ₂).
fn refraction_split() -> crate::svg::Drawn {
    let theta1 = 30.0;
    let eta = 1.0 / GLASS;
    let d = downwards(theta1);
    let refracted = refract(d, Vec3::Y, eta).expect("30° into glass refracts");
    let theta2 = from_minus_n(refracted);
    let mut svg = Svg::new(
        600.0,
        390.0,
        "Refraction: the part across N scaled by η",
        &format!(
            "A ray arrives along d at θ₁ = {theta1}° from the normal N and enters glass \
             (n₁ = 1, n₂ = 1.5, η = n₁ / n₂). On the unit circle around the hit, d's part \
             across N has length sin θ₁; the refracted ray d' keeps its direction across \
             but η times as long, sin θ₂ = η sin θ₁, so it bends towards the normal, to \
             θ₂ = {}°.",
            fixed(theta2, 2)
        ),
    );
    svg.text(
        xy(20.0, 28.0),
        "Into glass: the part across N shrinks by η",
        HEADING,
    );
    let hit = xy(185.0, 205.0);
    let plot = Plot::new(hit, 140.0);
    glass(&mut svg, 0.0, 350.0, hit.y, 390.0);
    // The media's names in the corners, where the circle leaves room
    // (beside the surface it crossed them).
    svg.text(xy(14.0, 84.0), "n₁ = 1 (air)", NOTE.colour(INK));
    svg.text(xy(14.0, 372.0), "n₂ = 1.5 (glass)", NOTE.colour(INK));
    svg.circle(hit, plot.scale, "none", MUTED);
    svg.dashed(plot.at(0.0, -1.12), plot.at(0.0, 1.12), MUTED, 1.0);
    svg.arrow(hit, plot.at(0.0, 0.6), NORMAL, 2.5);
    svg.text(
        plot.at(0.0, 0.6) + xy(8.0, 8.0),
        "N",
        LABEL.colour(NORMAL).bold(),
    );
    let tail = plot.p(-v2(d));
    let tip = plot.p(v2(refracted));
    svg.arrow(tail, hit, RAY, 2.5);
    svg.arrow(hit, tip, REFRACT, 2.5);
    svg.text(
        (tail + hit) / 2.0 + xy(-10.0, 6.0),
        "d",
        LABEL.colour(RAY).bold().end(),
    );
    svg.text(
        (hit + tip) / 2.0 + xy(10.0, 6.0),
        "d'",
        LABEL.colour(REFRACT).bold(),
    );
    // The parts across N, where d starts and where d' ends.
    let top = xy(hit.x, tail.y);
    let bottom = xy(hit.x, tip.y);
    svg.arrow(tail, top, FRAME, 2.2);
    svg.arrow(bottom, tip, FRAME, 2.2);
    svg.text(
        (tail + top) / 2.0 + xy(0.0, -22.0),
        "sin θ₁",
        LABEL.colour(FRAME).middle(),
    );
    svg.text(
        tip + xy(14.0, 26.0),
        "sin θ₂ = η sin θ₁",
        LABEL.colour(FRAME),
    );
    svg.angle(hit, 56.0, xy(0.0, -1.0), tail - hit, MEASURE);
    svg.angle(hit, 56.0, xy(0.0, 1.0), tip - hit, MEASURE);
    svg.text(
        hit + xy(-20.0, -62.0),
        "θ₁",
        LABEL.colour(MEASURE).bold().end(),
    );
    // Inside the angle, below its arc and clear of d'.
    svg.text(hit + xy(5.0, 100.0), "θ₂", LABEL.colour(MEASURE).bold());
    let left = 365.0;
    svg.text(xy(left, 80.0), &format!("θ₁ = {theta1}°, so"), LABEL);
    svg.fact(
        xy(left, 102.0),
        &format!("θ₂ = {}°", fixed(theta2, 2)),
        LABEL.bold(),
    );
    svg.fact(xy(left, 150.0), "η = n₁ / n₂", LABEL);
    svg.fact(xy(left, 174.0), "sin θ₂ = η sin θ₁", LABEL);
    svg.text(xy(left, 222.0), "the part across N, scaled:", NOTE);
    svg.text(
        xy(left, 244.0),
        "across': η times d's part across N",
        LABEL.colour(FRAME),
    );
    svg.text(
        xy(left, 292.0),
        "with its part along N, of length cos θ₂:",
        NOTE,
    );
    svg.text(xy(left, 314.0), "d', a unit vector", LABEL.colour(REFRACT));
    svg.finish()
}

/// Rays from a point inside glass at growing angles: refracted, grazing
/// at the critical angle, reflected beyond it.
fn critical_angle_diagram() -> crate::svg::Drawn {
    let critical = critical_angle();
    let mut svg = Svg::new(
        600.0,
        360.0,
        "The critical angle",
        &format!(
            "Rays from a point inside glass (n₁ = 1.5) meet the surface to the air \
             (n₂ = 1) at growing angles. The smaller angles refract out, bent away from \
             the normal. At the critical angle θ_c = arcsin(1/η), arcsin(1/1.5) = {}° for \
             glass into air, the refracted ray grazes the surface. Beyond it there is no \
             refracted ray: total internal reflection sends all the light back into the \
             glass.",
            fixed(critical, 2)
        ),
    );
    svg.text(
        xy(20.0, 28.0),
        "Out of glass: beyond θ_c, no way out",
        HEADING,
    );
    let surface = 160.0;
    let source = xy(120.0, 330.0);
    glass(&mut svg, 0.0, 600.0, surface, 360.0);
    svg.text(xy(14.0, surface - 12.0), "n₂ = 1 (air)", NOTE.colour(INK));
    svg.text(
        xy(14.0, surface + 22.0),
        "n₁ = 1.5 (glass)",
        NOTE.colour(INK),
    );
    let depth = source.y - surface;
    for angle in [0.0, 22.0, critical, 52.0, 62.0] {
        // Upwards from the source; `refract` wants the normal on the side
        // the ray comes from, −y here, so mirror the picture: up is −y.
        let d = downwards(angle);
        let up = Vec3::new(d.x, -d.y, 0.0);
        let hit = source + xy(depth * angle.to_radians().tan(), -depth);
        let critical_ray = angle == critical;
        svg.arrow(source, hit, RAY, if critical_ray { 2.5 } else { 1.8 });
        match refract(up, -Vec3::Y, GLASS) {
            Some(out) => {
                let out = v2(out);
                // The grazing ray runs along the surface: short, so that
                // it ends before the next ray's hit point.
                let length = if critical_ray { 50.0 } else { 105.0 };
                svg.arrow(hit, hit + xy(out.x, -out.y) * length, REFRACT, 2.2);
            }
            None => {
                let back = v2(reflect(up, -Vec3::Y));
                svg.arrow(hit, hit + xy(back.x, -back.y) * 105.0, MIRROR, 2.2);
            }
        }
        if critical_ray {
            svg.dashed(hit + xy(0.0, -60.0), hit + xy(0.0, 110.0), MUTED, 1.0);
            svg.angle(hit, 72.0, xy(0.0, 1.0), source - hit, MEASURE);
            svg.fact(
                hit + xy(-14.0, 96.0),
                "θ_c",
                LABEL.colour(MEASURE).bold().end(),
            );
        }
    }
    svg.dot(source, INK);
    svg.text(
        xy(300.0, surface - 40.0),
        "refracted, bent away from the normal",
        NOTE.colour(REFRACT),
    );
    svg.text(
        // Above the grazing ray, high enough that the subscript clears it.
        xy(282.0, surface - 14.0),
        "grazing at θ_c",
        NOTE.colour(REFRACT),
    );
    svg.text(
        xy(430.0, surface + 68.0),
        "total internal",
        NOTE.colour(MIRROR),
    );
    svg.text(xy(430.0, surface + 86.0), "reflection", NOTE.colour(MIRROR));
    svg.fact(xy(300.0, 300.0), "θ_c = arcsin(1/η)", LABEL.bold());
    svg.fact(
        xy(300.0, 324.0),
        &format!("arcsin(1/1.5) = {}°", fixed(critical, 2)),
        LABEL.bold(),
    );
    svg.text(xy(300.0, 344.0), "for glass into air", NOTE.colour(INK));
    svg.finish()
}

/// R against the angle: entering glass (θ₁ outside), and leaving it,
/// plotted against the angle inside, with Schlick's cosine taken outside.
fn schlick_curve() -> crate::svg::Drawn {
    let critical = critical_angle();
    let r0 = schlick(1.0, 1.0, GLASS) as f64;
    let mut svg = Svg::new(
        600.0,
        380.0,
        "Schlick's approximation for glass",
        &format!(
            "The share R that glass reflects by Schlick's approximation, with \
             R₀ = 0.04 head-on. Entering glass from air, plotted against \
             the angle outside, it stays near 0.04 until about 60° and rises to 1 at 90°. \
             Leaving glass, plotted against the angle inside and computed with the angle \
             outside as the text says, it rises to 1 at the critical angle, {}°, and total \
             internal reflection continues it.",
            fixed(critical, 2)
        ),
    );
    svg.text(xy(20.0, 28.0), "How much glass reflects", HEADING);
    let origin = xy(70.0, 290.0);
    let (per_degree, height) = (5.4, 220.0);
    let at = |angle: f64, r: f64| origin + xy(angle * per_degree, -r * height);
    svg.line(origin, at(92.0, 0.0), INK, 1.5);
    svg.line(origin, at(0.0, 1.08), INK, 1.5);
    for r in [0.0, 0.5, 1.0] {
        svg.text(at(0.0, r) + xy(-8.0, 5.0), &fixed(r, 1), NOTE.end());
    }
    for angle in [0.0, 30.0, 60.0, 90.0] {
        svg.text(
            at(angle, 0.0) + xy(0.0, 20.0),
            &format!("{angle}°"),
            NOTE.middle(),
        );
    }
    svg.text(
        at(45.0, 0.0) + xy(0.0, 40.0),
        "θ₁, the angle of the arriving ray",
        NOTE.colour(INK).middle(),
    );
    svg.text(at(0.0, 1.08) + xy(8.0, 4.0), "R", LABEL.bold());
    let entering: Vec<DVec2> = (0..=180)
        .map(|i| {
            let angle = i as f64 * 0.5;
            at(
                angle,
                schlick(angle.to_radians().cos() as f32, 1.0, GLASS) as f64,
            )
        })
        .collect();
    let leaving: Vec<DVec2> = (0..=180)
        .map(|i| {
            let angle = i as f64 * 0.5;
            let d = downwards(angle);
            let r =
                refract(d, Vec3::Y, GLASS).map_or(1.0, |out| schlick(-out.y, GLASS, 1.0) as f64);
            at(angle, r)
        })
        .collect();
    svg.dashed(at(critical, 0.0), at(critical, 1.0), MUTED, 1.0);
    svg.polyline(&leaving, REFRACT, 2.5);
    svg.polyline(&entering, MIRROR, 2.5);
    svg.text(
        at(critical, 0.9) + xy(6.0, 0.0),
        &format!("θ_c = {}°", fixed(critical, 2)),
        NOTE.colour(INK),
    );
    svg.text(
        at(critical, 1.0) + xy(-8.0, -8.0),
        "leaving glass: θ₁ inside",
        LABEL.colour(REFRACT).bold().end(),
    );
    svg.text(
        at(79.0, 0.5),
        "entering glass: θ₁ outside",
        LABEL.colour(MIRROR).bold().end(),
    );
    svg.dot(at(0.0, r0), INK);
    svg.fact(
        at(0.0, r0) + xy(10.0, -10.0),
        &format!("R₀ = {}", fixed(r0, 2)),
        NOTE.colour(INK),
    );
    svg.text(
        xy(300.0, 362.0),
        "Schlick's R(θ), from R₀ head-on to 1 at grazing",
        LABEL.bold().middle(),
    );
    svg.finish()
}
