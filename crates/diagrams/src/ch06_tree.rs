//! Chapter 6: the ray tree of the glass pixel (160, 110) of the default
//! scene, as the chapter's own `ray_tree::explain` computes it (the tree
//! that `cargo run -p ch06-refraction -- --pixel 160,110` prints). The
//! first levels are drawn; deeper and weaker rays are folded into one row.

use ch06_refraction::ray_tree::explain;
use ch06_refraction::scene_files;
use ch06_refraction::workbench::cli::Pixel;
use ch06_refraction::workbench::ray_tree::{Fold, Folded, RayKind, RayNode, Side, num};

use crate::Diagram;
use crate::svg::{HEADING, INK, LABEL, MIRROR, MUTED, NOTE, RAY, REFRACT, SURFACE, Svg, xy};

const CHAPTER: &str = "06-refraction";
/// The pixel: it looks at the glass sphere head on.
pub const PIXEL: Pixel = Pixel { x: 160, y: 110 };
/// The short text tree's folds (rays deeper than 3 bounces or with a path
/// weight below 0.01): the picture folds exactly what `--pixel` folds, so
/// that its counts are the ones the student reads in the terminal.
const FOLD: Fold = Fold::DEFAULT;
const MAX_SHOWN_DEPTH: u32 = FOLD.depth;
const MIN_SHOWN_WEIGHT: f32 = FOLD.weight;

/// The tree of [`PIXEL`] in the chapter's default scene.
pub fn tree() -> RayNode {
    let path = crate::workspace_root().join("chapters/06-refraction/scenes/default.toml");
    let scene = scene_files::load(&path).expect("chapter 6's default scene loads");
    explain(&scene, PIXEL).1
}

/// A row of the drawing: a ray, or the rays folded under a parent.
enum Row<'a> {
    Ray(&'a RayNode),
    Folded { rays: usize, not_traced: usize },
}

struct Line<'a> {
    row: Row<'a>,
    level: usize,
    parent: Option<usize>,
}

/// The rows of `node`'s subtree: the rays the short tree shows, and one row
/// per group it folds, counted as [`Folded::below`] counts it.
fn flatten<'a>(node: &'a RayNode, level: usize, parent: Option<usize>, lines: &mut Vec<Line<'a>>) {
    let me = lines.len();
    lines.push(Line {
        row: Row::Ray(node),
        level,
        parent,
    });
    // The group's row stands where its first ray would, as in the text.
    let mut group = Folded::below(node, &FOLD);
    for child in &node.secondary {
        if !FOLD.folds(child) {
            flatten(child, level + 1, Some(me), lines);
        } else if let Some(group) = group.take() {
            lines.push(Line {
                row: Row::Folded {
                    rays: group.rays,
                    not_traced: group.not_traced,
                },
                level: level + 1,
                parent: Some(me),
            });
        }
    }
}

fn kind(node: &RayNode) -> (&'static str, &'static str) {
    match node.kind {
        RayKind::Primary => ("primary", RAY),
        RayKind::Reflection => ("mirror", MIRROR),
        RayKind::Refraction => ("refracted", REFRACT),
    }
}

/// What the ray meets, in a few words.
fn meets(node: &RayNode) -> String {
    let Some(hit) = &node.hit else {
        return "→ nothing: the background".to_owned();
    };
    let side = match (hit.shape.as_str(), hit.side) {
        ("sphere", Side::Front) => ", from outside",
        ("sphere", Side::Back) => ", from inside",
        _ => "",
    };
    let what = if hit.shape == "triangle" {
        "floor tile".to_owned()
    } else {
        hit.shape.clone()
    };
    format!("→ {} {what}{side}", hit.material)
}

/// The weights of the first two rays that leave the primary ray's hit, as
/// the tree shows them: (mirror, refracted).
pub fn first_split(tree: &RayNode) -> (String, String) {
    let weight = |k: RayKind| {
        tree.secondary
            .iter()
            .find(|n| n.kind == k)
            .map(|n| num(n.weight[0]))
            .expect("the glass splits the primary ray")
    };
    (weight(RayKind::Reflection), weight(RayKind::Refraction))
}

pub fn diagram() -> Diagram {
    let tree = tree();
    let mut lines = Vec::new();
    flatten(&tree, 0, None, &mut lines);
    let row_height = 30.0;
    let top = 96.0;
    let height = top + row_height * lines.len() as f64 + 64.0;
    let (mirror, refracted) = first_split(&tree);
    let mut svg = Svg::new(
        600.0,
        height,
        "The ray tree of chapter 6's glass pixel (160, 110)",
        &format!(
            "The rays that chapter 6's tracer follows for pixel (160, 110) of its \
             default scene, where the eye looks at the glass sphere head on. The \
             primary ray hits the sphere from outside and splits: a mirror ray of \
             weight {mirror} that sees the background, and a refracted ray of weight \
             {refracted} that crosses the sphere and splits again at its far side. \
             Rays deeper than {MAX_SHOWN_DEPTH} bounces or with a path weight below \
             {MIN_SHOWN_WEIGHT} are folded into one row each."
        ),
    );
    svg.text(xy(20.0, 28.0), "The ray tree of pixel (160, 110)", HEADING);
    let glass = tree
        .refraction
        .as_ref()
        .expect("the primary ray meets the glass");
    svg.text(
        xy(20.0, 50.0),
        &format!(
            "chapter 6's default scene: the glass sphere (T = {}, ρ = {}, ior {}, Fresnel)",
            num(glass.transparency),
            num(glass.reflectance[0]),
            num(glass.n2)
        ),
        NOTE,
    );
    let (weight_x, path_x) = (486.0, 578.0);
    svg.text(xy(weight_x, top - 18.0), "weight", NOTE.colour(INK).end());
    svg.text(
        xy(path_x, top - 18.0),
        "path weight",
        NOTE.colour(INK).end(),
    );
    svg.line(xy(20.0, top - 10.0), xy(580.0, top - 10.0), MUTED, 0.8);
    let indent = 26.0;
    let tag_width = 74.0;
    let row_y = |i: usize| top + 20.0 + row_height * i as f64;
    for (i, line) in lines.iter().enumerate() {
        let y = row_y(i);
        let x = 24.0 + indent * line.level as f64;
        if let Some(parent) = line.parent {
            let px = 24.0 + indent * lines[parent].level as f64 + 10.0;
            svg.polyline(
                &[xy(px, row_y(parent) + 8.0), xy(px, y - 5.0), xy(x, y - 5.0)],
                SURFACE,
                1.2,
            );
        }
        match line.row {
            Row::Ray(node) => {
                let (name, colour) = kind(node);
                svg.rounded(xy(x, y - 17.0), xy(tag_width, 23.0), colour, 0.15, colour);
                svg.text(
                    xy(x + tag_width / 2.0, y),
                    name,
                    LABEL.colour(colour).bold().middle(),
                );
                svg.text(xy(x + tag_width + 8.0, y), &meets(node), LABEL);
                if node.kind != RayKind::Primary {
                    let weight = num(node.weight[0]);
                    if node.depth == 1 {
                        svg.fact(xy(weight_x, y), &weight, LABEL.colour(colour).bold().end());
                    } else {
                        svg.text(xy(weight_x, y), &weight, LABEL.colour(colour).bold().end());
                    }
                }
                svg.text(xy(path_x, y), &num(node.path_weight[0]), LABEL.end());
            }
            Row::Folded { rays, not_traced } => {
                let plural = if rays == 1 { "ray" } else { "rays" };
                let untraced = match not_traced {
                    0 => String::new(),
                    n => format!(" ({n} not traced)"),
                };
                svg.text(
                    xy(x + 4.0, y),
                    &format!("… {rays} more {plural}, deeper or weaker{untraced}"),
                    LABEL.colour(MUTED),
                );
            }
        }
    }
    let foot = row_y(lines.len()) + 6.0;
    svg.text(
        xy(20.0, foot),
        "The mirror ray and the refracted ray share T by Schlick's R",
        NOTE.colour(INK),
    );
    let fresnel = glass.fresnel.expect("the glass has a Fresnel term");
    svg.text(
        xy(20.0, foot + 20.0),
        &format!(
            "with Schlick's R = {} near head-on; a path's weight is the product of the weights on it",
            num(fresnel)
        ),
        NOTE,
    );
    Diagram::new(CHAPTER, "ray-tree", svg.finish())
}
