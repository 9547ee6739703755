//! Beside chapter 4: tracing forward from the light against tracing
//! backward from the eye, on one small scene (a light, a ball, a floor and
//! an eye), traced in two dimensions.

use glam::DVec2;

use crate::Diagram;
use crate::svg::{HEADING, INK, LIGHT, MEASURE, MUTED, NOTE, RAY, SURFACE, SURFACE_FILL, Svg, xy};

const CHAPTER: &str = "04b-forward";

pub fn diagrams() -> Vec<Diagram> {
    vec![Diagram::new(
        CHAPTER,
        "forward-backward",
        forward_backward(),
    )]
}

/// The scene of both panels, in the left panel's coordinates.
struct Scene {
    light: DVec2,
    ball: DVec2,
    radius: f64,
    floor: f64,
    eye: DVec2,
    /// The eye's opening, drawn far larger than the chapter's a = 0.05.
    aperture: f64,
}

const SCENE: Scene = Scene {
    light: DVec2::new(70.0, 150.0),
    ball: DVec2::new(168.0, 262.0),
    radius: 30.0,
    floor: 292.0,
    eye: DVec2::new(262.0, 112.0),
    aperture: 6.0,
};

/// What a ray from `origin` along the unit `d` meets first: the ball or
/// the floor, with the normal there.
fn first_hit(origin: DVec2, d: DVec2) -> Option<(DVec2, DVec2)> {
    let f = origin - SCENE.ball;
    let b = f.dot(d);
    let c = f.length_squared() - SCENE.radius * SCENE.radius;
    let ball = (b * b - c >= 0.0)
        .then(|| -b - (b * b - c).sqrt())
        .filter(|&t| t > 1e-6);
    let floor = (d.y > 0.0)
        .then(|| (SCENE.floor - origin.y) / d.y)
        .filter(|&t| t > 1e-6 && (6.0..=290.0).contains(&(origin.x + d.x * t)));
    match (ball, floor) {
        (Some(t), Some(u)) if t < u => {
            Some((origin + d * t, (origin + d * t - SCENE.ball) / SCENE.radius))
        }
        (Some(t), None) => Some((origin + d * t, (origin + d * t - SCENE.ball) / SCENE.radius)),
        (_, Some(u)) => Some((origin + d * u, xy(0.0, -1.0))),
        (None, None) => None,
    }
}

/// Where a ray from `origin` along `d` leaves the panel's box.
fn to_edge(origin: DVec2, d: DVec2) -> DVec2 {
    let (low, high) = (xy(6.0, 44.0), xy(290.0, 300.0));
    let mut t = f64::INFINITY;
    for axis in 0..2 {
        if d[axis] != 0.0 {
            let bound = if d[axis] > 0.0 { high[axis] } else { low[axis] };
            t = t.min((bound - origin[axis]) / d[axis]);
        }
    }
    origin + d * t
}

/// Does the ray from `origin` along `d` pass through the eye's opening?
fn reaches_eye(origin: DVec2, d: DVec2) -> bool {
    let to_eye = SCENE.eye - origin;
    let along = to_eye.dot(d);
    along > 0.0 && (to_eye - d * along).length() <= SCENE.aperture
}

fn forward_backward() -> crate::svg::Drawn {
    let photons = 28;
    let mut svg = Svg::new(
        600.0,
        380.0,
        "Forward from the light against backward from the eye",
        "Two copies of one scene: a light, a ball on a floor and an eye. Left, Idea 1: \
         photons leave the light in every direction, light the first surface they hit \
         and bounce off it in a random direction; of the ones drawn, none passes \
         through the eye's small opening, and on the chapter's scene 1026 of 10⁹ reach \
         the image. Right, Idea 2: one ray per pixel leaves the eye through the image \
         plane, finds the surface it sees, and a shadow ray from there asks whether the \
         light reaches it.",
    );
    for offset in [0.0, 305.0] {
        let shift = xy(offset, 0.0);
        svg.rect(
            xy(offset, SCENE.floor),
            xy(295.0, 30.0),
            SURFACE_FILL,
            "none",
            0.0,
        );
        svg.line(
            xy(offset, SCENE.floor),
            xy(offset + 295.0, SCENE.floor),
            SURFACE,
            2.0,
        );
        svg.circle(SCENE.ball + shift, SCENE.radius, SURFACE_FILL, SURFACE);
    }
    svg.line(xy(300.0, 40.0), xy(300.0, 330.0), MUTED, 1.0);
    let reached = forward(&mut svg, photons);
    backward(&mut svg, xy(305.0, 0.0));
    for offset in [0.0, 305.0] {
        let shift = xy(offset, 0.0);
        svg.circle(SCENE.light + shift, 11.0, "#ffe27a", LIGHT);
        svg.circle(SCENE.eye + shift, SCENE.aperture, "#ffffff", INK);
        svg.text(
            SCENE.eye + shift + xy(0.0, -14.0),
            "eye",
            NOTE.colour(INK).middle(),
        );
        svg.text(
            SCENE.light + shift + xy(0.0, -18.0),
            "light",
            NOTE.colour(INK).middle(),
        );
    }
    svg.text(xy(14.0, 28.0), "Idea 1: forward, from the light", HEADING);
    svg.text(xy(319.0, 28.0), "Idea 2: backward, from the eye", HEADING);
    svg.text(
        xy(14.0, 344.0),
        &format!("{reached} of these {photons} photons pass through the eye;"),
        NOTE.colour(INK),
    );
    svg.text_with_fact(
        xy(14.0, 364.0),
        "on chapter 4's scene, 1026 of 10⁹ reach the image",
        "1026 of 10⁹",
        NOTE.colour(MEASURE),
    );
    svg.text(
        xy(319.0, 344.0),
        "one ray per pixel, each one used;",
        NOTE.colour(INK),
    );
    svg.text(
        xy(319.0, 364.0),
        "a shadow ray asks the light",
        NOTE.colour(INK),
    );
    svg.finish()
}

/// The photons of the left panel: emitted evenly around the light, one
/// random-looking diffuse bounce each. Returns how many reach the eye.
fn forward(svg: &mut Svg, photons: usize) -> usize {
    let mut reached = 0;
    // The arrowheads: where the photons hit, then the bounces' ends.
    let direction = |k: usize| {
        let angle = std::f64::consts::TAU * (k as f64 + 0.3) / photons as f64;
        xy(angle.cos(), angle.sin())
    };
    let mut heads: Vec<DVec2> = (0..photons)
        .filter_map(|k| first_hit(SCENE.light, direction(k)).map(|(hit, _)| hit))
        .collect();
    for k in 0..photons {
        let d = direction(k);
        let Some((hit, normal)) = first_hit(SCENE.light, d) else {
            svg.line(SCENE.light, to_edge(SCENE.light, d), "#e9cf8f", 1.2);
            continue;
        };
        svg.arrow(SCENE.light, hit, LIGHT, 1.3);
        // A bounce between −75° and 75° from the normal, spread by a fixed
        // scramble of k so that neighbours go different ways.
        let spread = ((k * 7) % photons) as f64 / (photons - 1) as f64;
        let turn = (spread * 150.0 - 75.0).to_radians();
        let (sin, cos) = turn.sin_cos();
        let out = xy(
            normal.x * cos - normal.y * sin,
            normal.x * sin + normal.y * cos,
        );
        if reaches_eye(hit, out) {
            reached += 1;
            svg.arrow(hit, SCENE.eye, MEASURE, 2.0);
        } else {
            let end = bounce_end(hit, out, &heads);
            heads.push(end);
            svg.dashed_arrow(hit, end, "#c9a94f", 1.1);
        }
    }
    reached
}

/// Where the drawn bounce from `hit` along `out` ends: at most 56 px
/// along, never past the surface it meets next or the panel's edge (an
/// arrow poked through the floor), and shortened, if need be, so that its
/// head keeps 16 px from the arrowheads already drawn (`heads`).
fn bounce_end(hit: DVec2, out: DVec2, heads: &[DVec2]) -> DVec2 {
    let room = first_hit(hit, out)
        .map(|(p, _)| (p - hit).length() - 3.0)
        .unwrap_or(f64::INFINITY)
        .min((to_edge(hit, out) - hit).length());
    let clear = |end: DVec2| heads.iter().all(|&h| (h - end).length() >= 16.0);
    [56.0, 46.0, 36.0, 28.0, 0.7 * room, 0.5 * room]
        .into_iter()
        .map(|length: f64| hit + out * length.min(room))
        .find(|&end| clear(end))
        .unwrap_or(hit + out * 28.0_f64.min(room))
}

/// The right panel: an image plane of five pixels, one ray through each
/// pixel's centre, and a shadow ray from each hit towards the light.
fn backward(svg: &mut Svg, shift: DVec2) {
    // Aimed so that no ray's hit lies near the ✗ where the ball blocks a
    // floor point's shadow ray (the ✗ must belong to that shadow ray).
    let look = (SCENE.ball + xy(10.0, 0.0) - SCENE.eye).normalize();
    let side = look.perp();
    let plane = SCENE.eye + look * 40.0;
    let half = 28.0;
    let (a, b) = (plane - side * half, plane + side * half);
    svg.line(a + shift, b + shift, INK, 3.0);
    for i in 1..5 {
        let tick = a + (b - a) * (i as f64 / 5.0);
        svg.line(
            tick - look * 4.0 + shift,
            tick + look * 4.0 + shift,
            INK,
            1.2,
        );
    }
    for i in 0..5 {
        let centre = a + (b - a) * ((i as f64 + 0.5) / 5.0);
        let d = (centre - SCENE.eye).normalize();
        let Some((hit, _)) = first_hit(SCENE.eye, d) else {
            svg.arrow(SCENE.eye + shift, to_edge(SCENE.eye, d) + shift, RAY, 1.8);
            continue;
        };
        svg.arrow(SCENE.eye + shift, hit + shift, RAY, 1.8);
        let to_light = (SCENE.light - hit).normalize();
        let blocker = first_hit(hit + to_light * 0.5, to_light)
            .map(|(p, _)| p)
            .filter(|p| (p - hit).length() < (SCENE.light - hit).length());
        match blocker {
            Some(p) => {
                svg.dashed(hit + shift, p + shift, LIGHT, 1.4);
                svg.line(
                    p + shift + xy(-5.0, -5.0),
                    p + shift + xy(5.0, 5.0),
                    MEASURE,
                    2.2,
                );
                svg.line(
                    p + shift + xy(-5.0, 5.0),
                    p + shift + xy(5.0, -5.0),
                    MEASURE,
                    2.2,
                );
            }
            None => svg.dashed(hit + shift, SCENE.light + shift, LIGHT, 1.4),
        }
        svg.dot(hit + shift, RAY);
    }
}
