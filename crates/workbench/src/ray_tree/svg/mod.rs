//! A picture of a pixel's rays (`--pixel X,Y --svg FILE`), seen from the
//! side: every ray's segment projected onto the plane through the eye that
//! holds the primary ray and the camera's up vector, over the
//! cross-sections of the objects the rays meet. Each shown ray is one
//! `<line class="ray …">`, labelled with its kind and path weight; the rays
//! the short tree folds (`fold.rs`) are drawn thin, grey and unlabelled.
//!
//! `geometry.rs` holds the plane and the cross-sections, `layout.rs` the
//! segments and the frame, `labels.rs` the labels' places; this file
//! writes the picture.

mod geometry;
mod labels;
mod layout;

use std::fmt::Write;

use ch00_toolkit::{Scene, Vec3};

use super::fold::Fold;
use super::{RayKind, RayTree, num};
use geometry::{Outline, P2, Plane, Section, size};
use labels::{Labels, along, text_width};
use layout::{Drawn, Frame, Met, objects_met, reach, segments};

/// The picture's width; its height follows the rays' extent.
const WIDTH: f32 = 900.0;
/// Around the drawing, in pixels.
const MARGIN: f32 = 24.0;
/// The drawing's largest height, in pixels.
const MAX_DRAWING_HEIGHT: f32 = 500.0;
/// The text's size, in pixels.
const FONT: f32 = 14.0;
/// A line of the legend, in pixels.
const LINE: f32 = 20.0;

/// The picture of `tree`'s rays: `scene` gives the camera's up vector and
/// the objects' shapes; the rays `fold` folds are drawn thin and grey.
pub fn to_svg(tree: &RayTree, scene: &Scene, fold: Fold) -> String {
    to_svg_noted(tree, scene, fold, None)
}

/// [`to_svg`] with a `note` as the legend's first line: what the drawing
/// is drawn from, when that is not a whole tree (the lab draws the
/// reference's shortened facts).
pub fn to_svg_noted(tree: &RayTree, scene: &Scene, fold: Fold, note: Option<&str>) -> String {
    let plane = Plane::of(scene.camera.up, &tree.primary);
    let rays = segments(&tree.primary, &plane, &fold, reach(&tree.primary, &plane));
    let met = objects_met(&rays, scene, &plane);
    let frame = Frame::fit(&rays, &met);
    let mut lines: Vec<String> = note.map(str::to_owned).into_iter().collect();
    lines.extend(legend(&rays, &met, &frame, &fold));
    lines.extend(off_plane(&rays, &plane, &frame));
    let legend: Vec<String> = lines.iter().flat_map(|line| wrap(line, 100)).collect();
    let mut svg = String::new();
    let height = frame.top + frame.height + MARGIN + LINE * legend.len() as f32;
    head(&mut svg, tree, height);
    let _ = writeln!(
        svg,
        r#"<clipPath id="drawing"><rect x="0" y="{:.1}" width="{WIDTH}" height="{:.1}"/></clipPath>"#,
        frame.top, frame.height
    );
    svg.push_str("<g clip-path=\"url(#drawing)\">\n");
    let names = draw_objects(&mut svg, &met, &frame);
    draw_rays(&mut svg, &rays, &frame);
    svg.push_str("</g>\n");
    let mut labels = Labels::new(&rays, &frame);
    label_rays(&mut svg, &rays, &frame, &mut labels);
    for (name, places) in names {
        labels.place(&mut svg, "object-label", &name, &places);
    }
    let mut y = frame.top + frame.height + MARGIN;
    for line in legend {
        let _ = writeln!(
            svg,
            r#"<text x="{MARGIN}" y="{y:.1}">{}</text>"#,
            escape(&line)
        );
        y += LINE;
    }
    svg.push_str("</svg>\n");
    svg
}

/// A note if the shown rays' hits lie off the plane, by more than a
/// fiftieth of the frame: they are drawn where they project.
fn off_plane(rays: &[Drawn], plane: &Plane, frame: &Frame) -> Option<String> {
    let off = (rays.iter().filter(|d| d.shown))
        .filter_map(|d| d.ray.hit.as_ref())
        .map(|hit| plane.distance(Vec3::from_array(hit.point)).abs())
        .fold(0.0, f32::max);
    (off > 0.02 * size(frame.lo, frame.hi)).then(|| {
        format!(
            "The rays leave this plane (their hits lie up to {} from it): each is drawn where it \
             projects, so a hit may lie away from its object's cross-section.",
            num(off)
        )
    })
}

/// The opening tag, title, description, styles, arrowheads, background and heading.
fn head(svg: &mut String, tree: &RayTree, height: f32) {
    let [x, y] = tree.pixel;
    let _ = writeln!(
        svg,
        r#"<svg xmlns="http://www.w3.org/2000/svg" width="{WIDTH}" height="{height:.0}" viewBox="0 0 {WIDTH} {height:.0}" font-family="DejaVu Sans, Arial, Helvetica, sans-serif" font-size="{FONT}">"#
    );
    let _ = writeln!(
        svg,
        "<title>Rays of pixel ({x}, {y}), chapter {}</title>",
        escape(&tree.chapter)
    );
    let _ = writeln!(
        svg,
        "<desc>The ray tree of pixel ({x}, {y}) of {}: every ray projected onto the plane through the eye that holds the primary ray (drawn to the right) and the camera's up vector (drawn upwards), over the cross-sections of the objects the rays hit.</desc>",
        escape(&tree.scene)
    );
    svg.push_str(STYLE);
    let _ = writeln!(
        svg,
        r##"<rect width="100%" height="100%" fill="#fbfaf5"/>"##
    );
    let _ = writeln!(
        svg,
        r#"<text class="heading" x="{MARGIN}" y="{:.1}">Rays of pixel ({x}, {y}), chapter {}, seen from the side</text>"#,
        MARGIN + FONT * 0.5,
        escape(&tree.chapter)
    );
}

const STYLE: &str = r##"<style>
text { fill: #1a1a1a; }
.heading { font-size: 16px; font-weight: bold; }
.label, .object-label { paint-order: stroke; stroke: #fbfaf5; stroke-width: 4px; stroke-linejoin: round; }
.object-label { fill: #555; }
.object { fill: #e4e9ef; fill-opacity: 0.6; stroke: #7d8a99; stroke-width: 1.5; }
line.object { stroke-width: 2; }
.ray { stroke-linecap: round; }
.primary { stroke: #222; fill: #222; }
.reflection { stroke: #1f5fbf; fill: #1f5fbf; }
.refraction { stroke: #c85a12; fill: #c85a12; }
.outline { fill: none; stroke: #9aa5b1; stroke-width: 1.2; stroke-dasharray: 6 4; }
.folded { stroke: #a0a0a0; stroke-width: 1; stroke-dasharray: 4 3; }
.not-traced { stroke-dasharray: 2 4; }
</style>
<defs>
<marker id="arrow-primary" class="primary" viewBox="0 0 10 10" refX="8" refY="5" markerWidth="5" markerHeight="5" orient="auto"><path d="M0,0 L10,5 L0,10 z"/></marker>
<marker id="arrow-reflection" class="reflection" viewBox="0 0 10 10" refX="8" refY="5" markerWidth="5" markerHeight="5" orient="auto"><path d="M0,0 L10,5 L0,10 z"/></marker>
<marker id="arrow-refraction" class="refraction" viewBox="0 0 10 10" refX="8" refY="5" markerWidth="5" markerHeight="5" orient="auto"><path d="M0,0 L10,5 L0,10 z"/></marker>
</defs>
"##;

/// The objects' cross-sections and outlines; places for their names.
fn draw_objects(svg: &mut String, met: &[Met], frame: &Frame) -> Vec<(String, Vec<P2>)> {
    let mut names = Vec::new();
    for m in met {
        let outline = m.outline.as_ref().map(|o| draw_outline(svg, o, frame));
        let places = match m.section {
            Some(Section::Circle { center, radius }) => {
                circle(svg, "object", frame.px(center), radius * frame.scale)
            }
            Some(Section::Segment { a, b }) => {
                segment(svg, frame, [frame.px(a), frame.px(b)], &m.name)
            }
            Some(Section::Line { point, dir }) => {
                let far = 4.0 * size(frame.lo, frame.hi);
                let at = |s: f32| frame.px([point[0] + s * dir[0], point[1] + s * dir[1]]);
                segment(svg, frame, [at(-far), at(far)], &m.name)
            }
            None => outline.unwrap_or_default(),
        };
        names.push((m.name.clone(), places));
    }
    names
}

/// An object's outline, dashed; places for its name.
fn draw_outline(svg: &mut String, outline: &Outline, frame: &Frame) -> Vec<P2> {
    match outline {
        Outline::Circle { center, radius } => {
            circle(svg, "outline", frame.px(*center), radius * frame.scale)
        }
        Outline::Triangle(corners) => {
            let px = corners.map(|c| frame.px(c));
            let points: Vec<String> = px
                .iter()
                .map(|p| format!("{:.1},{:.1}", p[0], p[1]))
                .collect();
            let _ = writeln!(
                svg,
                r#"<polygon class="outline" points="{}"/>"#,
                points.join(" ")
            );
            let top = px
                .iter()
                .fold(px[0], |a, p| if p[1] < a[1] { *p } else { a });
            let bottom = px
                .iter()
                .fold(px[0], |a, p| if p[1] > a[1] { *p } else { a });
            vec![[top[0], top[1] - 6.0], [bottom[0], bottom[1] + FONT + 4.0]]
        }
    }
}

/// A circle of `class`; places for its name: above it, below it, beside it.
fn circle(svg: &mut String, class: &str, [cx, cy]: P2, r: f32) -> Vec<P2> {
    let _ = writeln!(
        svg,
        r#"<circle class="{class}" cx="{cx:.1}" cy="{cy:.1}" r="{r:.1}"/>"#
    );
    vec![
        [cx, cy - r - 6.0],
        [cx, cy + r + FONT + 4.0],
        [cx + 0.8 * r, cy - 0.8 * r - 6.0],
        [cx - 0.8 * r, cy + 0.8 * r + FONT + 4.0],
    ]
}

/// A straight cross-section; places for its name along its visible part.
fn segment(svg: &mut String, frame: &Frame, [a, b]: [P2; 2], name: &str) -> Vec<P2> {
    let _ = writeln!(
        svg,
        r#"<line class="object" x1="{:.1}" y1="{:.1}" x2="{:.1}" y2="{:.1}"/>"#,
        a[0], a[1], b[0], b[1]
    );
    (frame.visible(a, b)).map_or(Vec::new(), |(a, b)| along(a, b, text_width(name)))
}

/// The class of a ray's kind.
fn kind_class(kind: RayKind) -> &'static str {
    match kind {
        RayKind::Primary => "primary",
        RayKind::Reflection => "reflection",
        RayKind::Refraction => "refraction",
    }
}

/// Every ray: the folded ones first, thin, so that the shown ones lie on top.
fn draw_rays(svg: &mut String, rays: &[Drawn], frame: &Frame) {
    for d in rays.iter().filter(|d| !d.shown) {
        let ([x1, y1], [x2, y2]) = (frame.px(d.a), frame.px(d.b));
        let _ = writeln!(
            svg,
            r#"<line class="folded" x1="{x1:.1}" y1="{y1:.1}" x2="{x2:.1}" y2="{y2:.1}"/>"#
        );
    }
    for d in rays.iter().filter(|d| d.shown) {
        let ([x1, y1], [x2, y2]) = (frame.px(d.a), frame.px(d.b));
        let kind = kind_class(d.ray.kind);
        let width = 1.5 + 3.0 * super::fold::largest(d.ray.path_weight).min(1.0);
        let (extra, marker) = match (d.escapes, d.ray.traced) {
            (true, _) => ("", format!(r#" marker-end="url(#arrow-{kind})""#)),
            (false, false) => (" not-traced", String::new()),
            _ => ("", String::new()),
        };
        let _ = writeln!(
            svg,
            r#"<line class="ray {kind}{extra}" x1="{x1:.1}" y1="{y1:.1}" x2="{x2:.1}" y2="{y2:.1}" stroke-width="{width:.1}"{marker}/>"#
        );
        if d.ray.hit.is_some() {
            let _ = writeln!(
                svg,
                r#"<circle class="{kind}" cx="{x2:.1}" cy="{y2:.1}" r="3"/>"#
            );
        }
    }
}

/// Each shown ray's label, kind and path weight, beside its segment.
fn label_rays(svg: &mut String, rays: &[Drawn], frame: &Frame, labels: &mut Labels) {
    if frame.eye_in {
        let [ex, ey] = frame.px(rays[0].a);
        labels.place(
            svg,
            "label",
            "eye",
            &[[ex, ey - 10.0], [ex, ey + 2.0 * FONT]],
        );
    }
    for d in rays.iter().filter(|d| d.shown) {
        let mut text = format!(
            "{} {}",
            kind_class(d.ray.kind),
            num(super::fold::largest(d.ray.path_weight))
        );
        if !d.ray.traced {
            text.push_str(" (not traced)");
        }
        if let Some((a, b)) = frame.visible(frame.px(d.a), frame.px(d.b)) {
            labels.place(svg, "label", &text, &along(a, b, text_width(&text)));
        }
    }
}

/// The lines under the drawing: what it shows, what it folds, what it leaves out.
fn legend(rays: &[Drawn], met: &[Met], frame: &Frame, fold: &Fold) -> Vec<String> {
    let mut lines = vec![
        "Seen from the side: the plane through the eye of the primary ray (→) and the camera's up (↑), made \
         orthogonal to it (a level floor looks tilted when the camera looks down); each ray projected onto \
         it, each object drawn where it cuts the plane."
            .to_string(),
        "Primary ray black, reflection rays blue, refraction rays orange, thicker for a larger path weight; \
         labels: kind and path weight (its largest channel); an arrow: the ray hits nothing."
            .to_string(),
    ];
    let folded = rays.iter().filter(|d| !d.shown).count();
    if folded > 0 {
        lines.push(format!(
            "{folded} folded rays ({}) drawn thin, grey, dashed and unlabelled; --full shows them all.",
            fold.describe()
        ));
    }
    if let (false, Some(hit)) = (frame.eye_in, &rays[0].ray.hit) {
        lines.push(format!(
            "The eye is further left, out of the picture: the primary ray comes from t = {} before its hit.",
            num(hit.t)
        ));
    }
    if met.iter().any(|m| m.outline.is_some()) {
        lines.push(
            "Dashed: an object's outline seen across the plane, for the hits off it.".to_string(),
        );
    }
    for m in met
        .iter()
        .filter(|m| m.section.is_none() && m.outline.is_none())
    {
        lines.push(format!(
            "{} is hit but not drawn: a cone, or a plane parallel to this one.",
            m.name
        ));
    }
    lines
}

/// `text` cut into lines of at most `width` characters, between words.
fn wrap(text: &str, width: usize) -> Vec<String> {
    let mut lines = vec![String::new()];
    for word in text.split(' ') {
        let last = lines.last_mut().expect("one line at least");
        if last.is_empty() {
            last.push_str(word);
        } else if last.chars().count() + 1 + word.chars().count() <= width {
            last.push(' ');
            last.push_str(word);
        } else {
            lines.push(word.to_string());
        }
    }
    lines
}

/// Text for XML: &, < and > escaped.
fn escape(text: &str) -> String {
    text.replace('&', "&amp;")
        .replace('<', "&lt;")
        .replace('>', "&gt;")
}
