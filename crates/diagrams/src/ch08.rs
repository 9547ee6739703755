//! Chapter 8: the nested boxes of a BVH over a few spheres, seen from
//! above, as the chapter's own builder makes them (`build::items` and
//! `build::build`, the steps of `Bvh::build`).

use ch08_bvh::toolkit::Vec3;
use ch08_bvh::toolkit::scene::{Object, Shape};
use ch08_bvh::{Bvh, build};

use crate::Diagram;
use crate::svg::{
    FRAME, HEADING, INK, LABEL, MIRROR, NORMAL, NOTE, RAY, REFRACT, SURFACE, SURFACE_FILL, Svg, xy,
};

const CHAPTER: &str = "08-bvh";

pub fn diagrams() -> Vec<Diagram> {
    vec![Diagram::new(CHAPTER, "bvh-boxes", bvh_boxes())]
}

/// Eleven spheres on the ground (x, z, radius): three groups and two
/// loners, so that the tree has something to separate.
const SPHERES: [(f32, f32, f32); 11] = [
    (1.0, 1.2, 0.6),
    (2.4, 1.7, 0.7),
    (1.3, 2.9, 0.5),
    (2.6, 3.3, 0.4),
    (5.0, 4.4, 0.8),
    (7.6, 0.9, 0.7),
    (9.1, 1.5, 0.5),
    (8.2, 2.4, 0.4),
    (7.0, 4.6, 0.6),
    (8.6, 5.0, 0.5),
    (9.6, 4.1, 0.4),
];

fn objects() -> Vec<Object> {
    SPHERES
        .iter()
        .map(|&(x, z, radius)| Object {
            shape: Shape::Sphere {
                center: Vec3::new(x, radius, z),
                radius,
            },
            material: 0,
            shadows: true,
        })
        .collect()
}

/// A ray across the scene, at the spheres' height, and its direction.
const RAY_ORIGIN: Vec3 = Vec3::new(-0.6, 0.3, 4.1);
const RAY_DIRECTION: Vec3 = Vec3::new(0.96, 0.0, -0.28);

/// What the ray does with a node's box.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
enum Visit {
    /// Never tested: the ray missed a box around it.
    Skipped,
    /// Tested and missed.
    Missed,
    /// Tested and entered (the slab test, `Aabb::entry`).
    Entered,
}

/// Each node's visit by the ray, going down from the root as traversal
/// does: a node is tested only if the ray entered its parent.
fn ray_visit(nodes: &[build::Node]) -> Vec<Visit> {
    let direction = RAY_DIRECTION.normalize();
    let inverse = direction.recip();
    let mut visit = vec![Visit::Skipped; nodes.len()];
    let mut stack = vec![0];
    while let Some(i) = stack.pop() {
        let node = &nodes[i];
        if node
            .bounds
            .entry(RAY_ORIGIN, inverse, 0.0, f32::INFINITY)
            .is_none()
        {
            visit[i] = Visit::Missed;
            continue;
        }
        visit[i] = Visit::Entered;
        if node.count == 0 {
            stack.extend([i + 1, node.start as usize]);
        }
    }
    visit
}

/// How much larger, in pixels on every side, a box is drawn than the
/// boxes one level deeper, so that no two nested boxes share an edge.
const GAP: f64 = 4.0;

/// The colour of the boxes at each depth.
const DEPTH_COLOURS: [&str; 5] = [INK, FRAME, MIRROR, REFRACT, NORMAL];

/// Each node's depth, from the flat array (a node's first child follows
/// it, its second is at `start`; a leaf has `count` > 0).
fn depths(nodes: &[build::Node]) -> Vec<usize> {
    let mut depth = vec![0; nodes.len()];
    for (i, node) in nodes.iter().enumerate() {
        if node.count == 0 {
            depth[i + 1] = depth[i] + 1;
            depth[node.start as usize] = depth[i] + 1;
        }
    }
    depth
}

fn bvh_boxes() -> crate::svg::Drawn {
    let objects = objects();
    let (mut items, _planes) = build::items(&objects);
    let nodes = build::build(&mut items);
    let summary = Bvh::build(&objects).summary();
    assert_eq!(summary.nodes, nodes.len(), "Bvh::build makes the same tree");
    let depth = depths(&nodes);
    let mut svg = Svg::new(
        600.0,
        450.0,
        "The boxes of a bounding volume hierarchy",
        &format!(
            "{} spheres on the ground, seen from above, and the boxes of the BVH that \
             chapter 8's builder makes over them: the root's box holds them all, each \
             inner node's box holds its two children's, and each leaf's box holds a few \
             spheres (4 objects or fewer). {} nodes, {} of them leaves, {} levels deep. \
             A ray that misses a box skips everything inside it: the ray drawn across \
             the scene tests only the boxes whose parent it enters, and only the \
             spheres of the leaves it enters (in blue).",
            summary.primitives, summary.nodes, summary.leaves, summary.depth
        ),
    );
    svg.text(
        xy(20.0, 28.0),
        "Boxes in boxes: a BVH seen from above",
        HEADING,
    );
    let (origin, scale) = (xy(45.0, 56.0), 50.0);
    let page = |x: f32, z: f32| origin + xy(x as f64, z as f64) * scale;
    let visit = ray_visit(&nodes);
    let mut tested = vec![false; objects.len()];
    for (node, _) in nodes
        .iter()
        .zip(&visit)
        .filter(|&(n, &v)| n.count > 0 && v == Visit::Entered)
    {
        let first = node.start as usize;
        for item in &items[first..first + node.count as usize] {
            tested[item.index] = true;
        }
    }
    for (object, &tested) in objects.iter().zip(&tested) {
        if let Shape::Sphere { center, radius } = object.shape {
            let fill = if tested { "#cfe0f5" } else { SURFACE_FILL };
            svg.circle(
                page(center.x, center.z),
                radius as f64 * scale,
                fill,
                SURFACE,
            );
        }
    }
    // A box drawn at its true size would share edges with its children
    // wherever a child reaches its parent's side (a box is the union of
    // its children's), and the nesting could not be read. So each box is
    // drawn GAP pixels larger on every side than the boxes one level
    // deeper: the root outermost, the leaves at their true size.
    let levels = depth.iter().max().map_or(0, |&d| d + 1);
    for level in 0..levels {
        let grow = xy(GAP, GAP) * (levels - 1 - level) as f64;
        for (_, node) in nodes.iter().enumerate().filter(|&(i, _)| depth[i] == level) {
            let low = page(node.bounds.min.x, node.bounds.min.z) - grow;
            let high = page(node.bounds.max.x, node.bounds.max.z) + grow;
            let colour = DEPTH_COLOURS[level.min(DEPTH_COLOURS.len() - 1)];
            svg.rect(low, high - low, "none", colour, 2.0);
        }
    }
    let (from, to) = (RAY_ORIGIN, RAY_ORIGIN + 11.2 * RAY_DIRECTION);
    svg.arrow(page(from.x, from.z), page(to.x, to.z), RAY, 2.5);
    svg.text(
        page(from.x, from.z) + xy(4.0, 20.0),
        "ray",
        LABEL.colour(RAY).bold(),
    );
    legend(&mut svg, levels);
    let boxes = visit.iter().filter(|&&v| v != Visit::Skipped).count();
    let spheres = tested.iter().filter(|&&t| t).count();
    svg.text(
        xy(20.0, 438.0),
        &format!(
            "the ray tests {boxes} of the {} boxes and {spheres} of the {} spheres (in blue)",
            nodes.len(),
            objects.len()
        ),
        NOTE.colour(RAY),
    );
    svg.text(
        xy(20.0, 400.0),
        &format!(
            "{} spheres, {} nodes, {} leaves; each box drawn a little outside its children",
            summary.primitives, summary.nodes, summary.leaves
        ),
        NOTE.colour(INK),
    );
    svg.text_with_fact(
        xy(20.0, 419.0),
        "a node of 4 objects or fewer stays a leaf when that is cheaper (SAH)",
        "4 objects or fewer",
        NOTE.colour(INK),
    );
    svg.finish()
}

/// Which colour is which depth.
fn legend(svg: &mut Svg, levels: usize) {
    let mut x = 20.0;
    for (d, colour) in DEPTH_COLOURS.iter().enumerate().take(levels) {
        let name = if d == 0 {
            "root".to_owned()
        } else {
            format!("depth {d}")
        };
        svg.rect(xy(x, 362.0), xy(22.0, 12.0), "none", colour, 2.0);
        svg.text(xy(x + 28.0, 373.0), &name, LABEL.colour(colour));
        x += 100.0;
    }
}
