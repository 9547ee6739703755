//! A small SVG writer: the shapes the diagrams draw, and their shared look.
//!
//! Every diagram has an opaque light background (readable on a dark page
//! too), a `<title>` and a `<desc>`, sans-serif text of at least 13 px, and
//! the same colour for the same thing: rays from the eye blue, normals
//! green, mirror rays orange, refracted rays purple, light and shadow rays
//! amber. Coordinates are written with one decimal, so the files do not
//! change with the last bits of a sine.

use std::fmt::Write;

use glam::DVec2;

pub use crate::text::{escape, fixed, number, plain, rich};

/// The page behind every diagram.
pub const BACKGROUND: &str = "#fdfdf8";
/// Text and outlines.
pub const INK: &str = "#222222";
/// Secondary text, construction lines.
pub const MUTED: &str = "#6e6e6e";
/// Rays cast from the eye (primary rays, the arriving direction d or d_i).
pub const RAY: &str = "#1f5fbf";
/// Normals.
pub const NORMAL: &str = "#2b8a3e";
/// Mirror (reflected) rays.
pub const MIRROR: &str = "#d9480f";
/// Refracted rays.
pub const REFRACT: &str = "#7b3fbf";
/// Lights and shadow rays.
pub const LIGHT: &str = "#b07800";
/// The camera's frame (forward, right, up) and axes.
pub const FRAME: &str = "#0b7285";
/// Angles, lengths and other measures.
pub const MEASURE: &str = "#b0203a";
/// The edge of a surface or object.
pub const SURFACE: &str = "#5c5c5c";
/// The inside of an opaque object.
pub const SURFACE_FILL: &str = "#e6e3d6";
/// The inside of glass.
pub const GLASS_FILL: &str = "#d6e8f3";

/// Every label has a thin outline in the background's colour, so that it
/// stays readable where it crosses a line.
const HALO: &str =
    " stroke=\"#fdfdf8\" stroke-width=\"3\" stroke-linejoin=\"round\" paint-order=\"stroke\"";

/// The smallest font size any diagram uses, in px.
pub const MIN_FONT: f64 = 13.0;

/// How a label is set.
#[derive(Debug, Clone, Copy)]
pub struct Font {
    pub size: f64,
    pub anchor: &'static str,
    pub colour: &'static str,
    pub bold: bool,
    /// Set as mathematics: serif italic, as print sets a variable, so
    /// that the vector l cannot be read as the capital I of a sans-serif
    /// (I_L, the light's irradiance, stands beside it).
    pub math: bool,
}

impl Font {
    /// Left-aligned ink of `size` px.
    pub const fn new(size: f64) -> Font {
        Font {
            size,
            anchor: "start",
            colour: INK,
            bold: false,
            math: false,
        }
    }
    pub const fn middle(self) -> Font {
        Font {
            anchor: "middle",
            ..self
        }
    }
    pub const fn end(self) -> Font {
        Font {
            anchor: "end",
            ..self
        }
    }
    pub const fn colour(self, colour: &'static str) -> Font {
        Font { colour, ..self }
    }
    pub const fn bold(self) -> Font {
        Font { bold: true, ..self }
    }
    /// Serif italic, for the names of vectors and variables (see [`Font::math`]).
    pub const fn math(self) -> Font {
        Font { math: true, ..self }
    }
}

/// Labels: 15 px, left-aligned.
pub const LABEL: Font = Font::new(15.0);
/// Titles of a diagram or panel.
pub const HEADING: Font = Font::new(16.0).bold();
/// Small print: notes and captions inside the picture.
pub const NOTE: Font = Font::new(13.0).colour(MUTED);

/// A diagram being drawn, `width` × `height` px.
pub struct Svg {
    width: f64,
    height: f64,
    title: String,
    desc: String,
    body: String,
    facts: Vec<String>,
}

/// A finished diagram: its SVG text, and the texts it shows that the
/// chapter's README also states (see [`Svg::fact`]).
pub struct Drawn {
    pub svg: String,
    pub facts: Vec<String>,
}

impl Svg {
    /// An empty diagram: the background and nothing else. `title` names
    /// it, `desc` says what it shows (for screen readers and search).
    pub fn new(width: f64, height: f64, title: &str, desc: &str) -> Svg {
        Svg {
            width,
            height,
            title: title.to_owned(),
            desc: desc.to_owned(),
            body: String::new(),
            facts: Vec::new(),
        }
    }

    /// The SVG file's text.
    pub fn finish(self) -> Drawn {
        let (w, h) = (n(self.width), n(self.height));
        let svg = format!(
            "<svg xmlns=\"http://www.w3.org/2000/svg\" viewBox=\"0 0 {w} {h}\" width=\"{w}\" \
             height=\"{h}\" font-family=\"sans-serif\" role=\"img\">\n\
             <title>{}</title>\n<desc>{}</desc>\n\
             <rect x=\"0\" y=\"0\" width=\"{w}\" height=\"{h}\" fill=\"{BACKGROUND}\"/>\n{}</svg>\n",
            escape(&self.title),
            escape(&self.desc),
            self.body
        );
        Drawn {
            svg,
            facts: self.facts,
        }
    }

    fn push(&mut self, element: std::fmt::Arguments) {
        self.body
            .write_fmt(element)
            .expect("a String takes any text");
        self.body.push('\n');
    }

    /// A straight line.
    pub fn line(&mut self, a: DVec2, b: DVec2, colour: &str, width: f64) {
        self.push(format_args!(
            "<line x1=\"{}\" y1=\"{}\" x2=\"{}\" y2=\"{}\" stroke=\"{colour}\" stroke-width=\"{}\" stroke-linecap=\"round\"/>",
            n(a.x),
            n(a.y),
            n(b.x),
            n(b.y),
            n(width)
        ));
    }

    /// A dashed line.
    pub fn dashed(&mut self, a: DVec2, b: DVec2, colour: &str, width: f64) {
        self.push(format_args!(
            "<line x1=\"{}\" y1=\"{}\" x2=\"{}\" y2=\"{}\" stroke=\"{colour}\" stroke-width=\"{}\" stroke-dasharray=\"6 4\"/>",
            n(a.x),
            n(a.y),
            n(b.x),
            n(b.y),
            n(width)
        ));
    }

    /// An arrow from `a` to `b`, its head at `b`.
    pub fn arrow(&mut self, a: DVec2, b: DVec2, colour: &str, width: f64) {
        let length = (b - a).length();
        if length < 1e-9 {
            return;
        }
        let u = (b - a) / length;
        let head = (7.0 + 2.0 * width).min(length);
        let side = u.perp() * head * 0.42;
        self.line(a, b - u * head * 0.7, colour, width);
        let back = b - u * head;
        self.polygon(&[b, back + side, back - side], colour, colour);
    }

    /// A dashed arrow from `a` to `b`.
    pub fn dashed_arrow(&mut self, a: DVec2, b: DVec2, colour: &str, width: f64) {
        let length = (b - a).length();
        let u = (b - a) / length;
        let head = 7.0 + 2.0 * width;
        self.dashed(a, b - u * head * 0.7, colour, width);
        let back = b - u * head;
        let side = u.perp() * head * 0.42;
        self.polygon(&[b, back + side, back - side], colour, colour);
    }

    /// A closed polygon.
    pub fn polygon(&mut self, points: &[DVec2], fill: &str, stroke: &str) {
        self.push(format_args!(
            "<polygon points=\"{}\" fill=\"{fill}\" stroke=\"{stroke}\" stroke-width=\"1.5\" stroke-linejoin=\"round\"/>",
            points_text(points)
        ));
    }

    /// A closed polygon, filled with `fill` at `opacity`, without an outline.
    pub fn shade(&mut self, points: &[DVec2], fill: &str, opacity: f64) {
        self.push(format_args!(
            "<polygon points=\"{}\" fill=\"{fill}\" fill-opacity=\"{}\"/>",
            points_text(points),
            n2(opacity)
        ));
    }

    /// An open polyline.
    pub fn polyline(&mut self, points: &[DVec2], colour: &str, width: f64) {
        self.push(format_args!(
            "<polyline points=\"{}\" fill=\"none\" stroke=\"{colour}\" stroke-width=\"{}\" stroke-linejoin=\"round\"/>",
            points_text(points),
            n(width)
        ));
    }

    /// A circle.
    pub fn circle(&mut self, centre: DVec2, radius: f64, fill: &str, stroke: &str) {
        self.push(format_args!(
            "<circle cx=\"{}\" cy=\"{}\" r=\"{}\" fill=\"{fill}\" stroke=\"{stroke}\" stroke-width=\"1.5\"/>",
            n(centre.x),
            n(centre.y),
            n(radius)
        ));
    }

    /// A dot: a small filled circle.
    pub fn dot(&mut self, centre: DVec2, colour: &str) {
        self.circle(centre, 4.0, colour, colour);
    }

    /// A rectangle from `corner` (top left) of `size`.
    pub fn rect(&mut self, corner: DVec2, size: DVec2, fill: &str, stroke: &str, width: f64) {
        self.push(format_args!(
            "<rect x=\"{}\" y=\"{}\" width=\"{}\" height=\"{}\" fill=\"{fill}\" stroke=\"{stroke}\" stroke-width=\"{}\"/>",
            n(corner.x),
            n(corner.y),
            n(size.x),
            n(size.y),
            n(width)
        ));
    }

    /// A rectangle with rounded corners, filled with `fill` at `opacity`.
    pub fn rounded(&mut self, corner: DVec2, size: DVec2, fill: &str, opacity: f64, stroke: &str) {
        self.push(format_args!(
            "<rect x=\"{}\" y=\"{}\" width=\"{}\" height=\"{}\" rx=\"5\" fill=\"{fill}\" fill-opacity=\"{}\" stroke=\"{stroke}\" stroke-width=\"1.2\"/>",
            n(corner.x),
            n(corner.y),
            n(size.x),
            n(size.y),
            n2(opacity)
        ));
    }

    /// The arc of radius `radius` around `centre` from direction `from` to
    /// direction `to` (screen directions, the shorter way round): the mark
    /// of the angle between them.
    pub fn angle(&mut self, centre: DVec2, radius: f64, from: DVec2, to: DVec2, colour: &str) {
        let (a, b) = (from.normalize(), to.normalize());
        let start = centre + a * radius;
        let end = centre + b * radius;
        let sweep = u8::from(a.perp_dot(b) > 0.0);
        self.push(format_args!(
            "<path d=\"M {} {} A {r} {r} 0 0 {sweep} {} {}\" fill=\"none\" stroke=\"{colour}\" stroke-width=\"1.5\"/>",
            n(start.x),
            n(start.y),
            n(end.x),
            n(end.y),
            r = n(radius)
        ));
    }

    /// A label at `at` (its baseline's start, middle or end), in the
    /// lecture's notation: `d_i` is set as d with a subscript i (see
    /// [`rich`]).
    pub fn text(&mut self, at: DVec2, label: &str, font: Font) {
        let weight = if font.bold {
            " font-weight=\"bold\""
        } else {
            ""
        };
        let face = if font.math {
            " font-family=\"serif\" font-style=\"italic\""
        } else {
            ""
        };
        self.push(format_args!(
            "<text x=\"{}\" y=\"{}\" font-size=\"{}\" text-anchor=\"{}\" fill=\"{}\"{weight}{face}{HALO}>{}</text>",
            n(at.x),
            n(at.y),
            n(font.size),
            font.anchor,
            font.colour,
            rich(label, font.size)
        ));
    }

    /// A label that the chapter's README states word for word: drawn as
    /// [`Svg::text`], and recorded, so that the tests find it in the README.
    pub fn fact(&mut self, at: DVec2, label: &str, font: Font) {
        self.text(at, label, font);
        self.facts.push(label.to_owned());
    }

    /// A label of which the part `fact` is stated word for word in the
    /// chapter's README: drawn as [`Svg::text`], and `fact` recorded.
    pub fn text_with_fact(&mut self, at: DVec2, label: &str, fact: &str, font: Font) {
        assert!(label.contains(fact), "{label:?} does not show {fact:?}");
        self.text(at, label, font);
        self.facts.push(fact.to_owned());
    }
}

/// A coordinate: rounded to one decimal, without a trailing ".0".
pub fn n(x: f64) -> String {
    let rounded = (x * 10.0).round() / 10.0;
    let rounded = if rounded == 0.0 { 0.0 } else { rounded };
    format!("{rounded}")
}

/// A number to two decimals at most (opacities).
fn n2(x: f64) -> String {
    let rounded = (x * 100.0).round() / 100.0;
    format!("{rounded}")
}

fn points_text(points: &[DVec2]) -> String {
    points
        .iter()
        .map(|p| format!("{},{}", n(p.x), n(p.y)))
        .collect::<Vec<_>>()
        .join(" ")
}

/// Maps a diagram's own coordinates (x to the right, y up, in units) to
/// the page (y down, in px): `origin` is where (0, 0) lands.
#[derive(Debug, Clone, Copy)]
pub struct Plot {
    pub origin: DVec2,
    pub scale: f64,
}

impl Plot {
    pub fn new(origin: DVec2, scale: f64) -> Plot {
        Plot { origin, scale }
    }

    /// The page position of the point (x, y).
    pub fn at(&self, x: f64, y: f64) -> DVec2 {
        self.origin + DVec2::new(x, -y) * self.scale
    }

    /// The page position of a point given as a vector.
    pub fn p(&self, v: DVec2) -> DVec2 {
        self.at(v.x, v.y)
    }
}

/// Shorthand for a page position.
pub fn xy(x: f64, y: f64) -> DVec2 {
    DVec2::new(x, y)
}
