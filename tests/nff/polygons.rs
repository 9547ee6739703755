//! Polygons (`p`): cut into as few, compact triangles as cover them exactly.

use raybook::toolkit::Vec3;
use raybook::toolkit::scene::Shape;

use super::shapes_of;

/// (b − a) × (c − a): the normal of a triangle's winding, twice its area long.
fn area_vector([a, b, c]: [Vec3; 3]) -> Vec3 {
    (b - a).cross(c - a)
}

/// Checks that the triangles of a polygon cover it exactly: as many as a
/// triangulation has (n − 2), each wound as the polygon is (so none is
/// flipped, as a fan's are outside a concave corner), and together as large
/// as the polygon (so none overlaps another or pokes out).
fn covers_exactly(corners: &[[f32; 2]]) -> Vec<[Vec3; 3]> {
    let lines: Vec<String> = corners.iter().map(|[x, y]| format!("{x} {y} 0")).collect();
    let shapes = shapes_of(&format!("p {}\n{}\n", corners.len(), lines.join("\n")));
    let triangles: Vec<[Vec3; 3]> = (shapes.iter())
        .map(|s| match *s {
            Shape::Triangle { vertices } => vertices,
            other => panic!("{other:?}"),
        })
        .collect();
    assert_eq!(triangles.len(), corners.len() - 2);
    // The shoelace formula: the polygon's area, positive if counter-clockwise.
    let n = corners.len();
    let area: f32 = (0..n)
        .map(|i| {
            let ([x0, y0], [x1, y1]) = (corners[i], corners[(i + 1) % n]);
            (x0 * y1 - x1 * y0) / 2.0
        })
        .sum();
    assert!(area > 0.0, "the test's polygons are counter-clockwise");
    let mut covered = 0.0;
    for t in &triangles {
        let z = area_vector(*t).z / 2.0;
        assert!(z > 0.0, "{t:?} is wound against the polygon");
        covered += z;
    }
    assert!((covered - area).abs() < 1e-4 * area, "{covered} ≠ {area}");
    triangles
}

#[test]
fn concave_polygons_are_cut_into_triangles_inside_them() {
    // An L, starting at a corner from which a fan would leave the L.
    covers_exactly(&[
        [2.0, 0.0],
        [2.0, 1.0],
        [1.0, 1.0],
        [1.0, 2.0],
        [0.0, 2.0],
        [0.0, 0.0],
    ]);
    // A five-pointed star, starting at a tip.
    let star: Vec<[f32; 2]> = (0..10)
        .map(|i| {
            let angle = std::f32::consts::TAU * i as f32 / 10.0;
            let r = if i % 2 == 0 { 1.0 } else { 0.4 };
            [r * angle.cos(), r * angle.sin()]
        })
        .collect();
    covers_exactly(&star);
}

#[test]
fn polygons_are_cut_into_compact_triangles() {
    // A long thin rhombus: the fan from the first corner cuts it along its
    // long diagonal into two slivers; the short diagonal is the better cut.
    let triangles = covers_exactly(&[[0.0, 0.0], [10.0, -1.0], [20.0, 0.0], [10.0, 1.0]]);
    for t in triangles {
        assert!(t.contains(&Vec3::new(10.0, -1.0, 0.0)) && t.contains(&Vec3::new(10.0, 1.0, 0.0)));
    }
}
