//! NFF polygons into triangles, by ear clipping that cuts the best-shaped
//! ear first.
//!
//! An *ear* of a polygon is a corner b, with neighbours a and c, whose
//! triangle (a, b, c) lies inside the polygon: the corner is convex and no
//! other corner lies in the triangle. Every simple polygon with more than
//! three corners has at least two ears (Meisters' two ears theorem), so
//! cutting off one ear after another leaves n − 2 triangles that cover the
//! polygon exactly, concave or not. A fan from the first corner covers only
//! polygons that are convex (or star-shaped around that corner): SPD's gears
//! are concave, their teeth outlines have 144 corners, and a fan gives them
//! triangles outside the outline and long slivers that a BVH boxes badly.
//!
//! Of all the ears, this cuts the one whose triangle is closest to
//! equilateral ([`shape_quality`]), so the triangles stay compact.
//! Cutting an ear changes only whether its two neighbours are ears, so each
//! cut re-checks those two: O(n²) for n corners.

use crate::Vec3;

/// The most corners a polygon may have. Cutting a polygon into triangles
/// ([`triangulate`]) takes time that grows with the square of its corners
/// at least: measured 0.5 s for 4,000 corners, 11 s for 16,000 and 95 s
/// for 64,000 (a convex one, release build). SPD's largest polygon, a
/// gear's outline, has 144 corners.
pub(super) const MAX_POLYGON_CORNERS: usize = 4096;

/// The corners a polygon's `count` says it has, `left` lines following it:
/// a whole number from 3 to [`MAX_POLYGON_CORNERS`]; or what is wrong.
pub(super) fn corner_count(count: f32, left: usize) -> Result<usize, String> {
    if count < 3.0 || count.fract() != 0.0 {
        return Err(format!(
            "a polygon has a whole number of corners, 3 or more; found {count}"
        ));
    }
    if count > MAX_POLYGON_CORNERS as f32 {
        let missing = match (left as f32) < count {
            true => format!(", and only {left} lines follow it"),
            false => String::new(),
        };
        return Err(format!(
            "a polygon has at most {MAX_POLYGON_CORNERS} corners (cutting it into triangles \
             takes time that grows with the square of its corners); this one says it has \
             {count}{missing}"
        ));
    }
    Ok(count as usize)
}

/// The triangles of a planar polygon whose corners are given in order: n − 2
/// triples of indices into `corners`, each in the polygon's own winding (so
/// each triangle faces where the polygon faces).
///
/// The polygon should be simple (its edges do not cross). If it is not, or
/// rounding hides every ear, the rest is cut as a fan, so a result always
/// comes back.
pub(super) fn triangulate(corners: &[Vec3]) -> Vec<[usize; 3]> {
    let normal = area_vector(corners);
    let mut ring: Vec<usize> = (0..corners.len()).collect();
    let mut quality: Vec<Option<f32>> = (0..ring.len())
        .map(|k| ear_quality(corners, &ring, k, normal))
        .collect();
    let mut triangles = Vec::with_capacity(corners.len().saturating_sub(2));
    while ring.len() > 3 {
        let Some(k) = best_ear(&quality) else {
            break; // no ear: not a simple polygon, or lost to rounding
        };
        triangles.push(corner_triangle(&ring, k));
        ring.remove(k);
        quality.remove(k);
        // The cut ear's neighbours are now k − 1 and k (cyclically).
        for j in [(k + ring.len() - 1) % ring.len(), k % ring.len()] {
            quality[j] = ear_quality(corners, &ring, j, normal);
        }
    }
    triangles.extend((1..ring.len() - 1).map(|i| [ring[0], ring[i], ring[i + 1]]));
    triangles
}

/// The area vector of a planar polygon: its unit normal (counter-clockwise
/// corners seen from its front) times twice its area,
/// Σ (pᵢ − p₀) × (pᵢ₊₁ − p₀) (Newell's method, measured from p₀ for
/// precision). Unlike the normal of the first three corners, it is right
/// for concave polygons too.
pub(super) fn area_vector(corners: &[Vec3]) -> Vec3 {
    let p0 = corners[0];
    (corners.windows(2))
        .map(|pair| (pair[0] - p0).cross(pair[1] - p0))
        .sum()
}

/// The position in the ring of the best-shaped ear, if there is an ear.
fn best_ear(quality: &[Option<f32>]) -> Option<usize> {
    (quality.iter().enumerate())
        .filter_map(|(k, q)| q.map(|q| (k, q)))
        .max_by(|a, b| a.1.total_cmp(&b.1))
        .map(|(k, _)| k)
}

/// Corner `k` of the ring with its two neighbours, as indices into the corners.
fn corner_triangle(ring: &[usize], k: usize) -> [usize; 3] {
    let n = ring.len();
    [ring[(k + n - 1) % n], ring[k], ring[(k + 1) % n]]
}

/// The [`shape_quality`] of the triangle of corner `k` if it is an ear of
/// the polygon that `ring` has left; `None` if it is not.
fn ear_quality(corners: &[Vec3], ring: &[usize], k: usize, normal: Vec3) -> Option<f32> {
    let ear = corner_triangle(ring, k);
    let [a, b, c] = ear.map(|i| corners[i]);
    // Convex: the corner turns the way the whole polygon turns.
    if (b - a).cross(c - b).dot(normal) <= 0.0 {
        return None;
    }
    let others = ring.iter().filter(|i| !ear.contains(i));
    if others
        .map(|&i| corners[i])
        .any(|p| in_triangle(p, [a, b, c], normal))
    {
        return None;
    }
    Some(shape_quality([a, b, c]))
}

/// Does `p`, in the plane of the triangle, lie inside it or on its edge?
/// It does when it is on the inner side of all three edges: for each edge
/// from u to v, ((v − u) × (p − u)) · n ≥ 0 with n the polygon's normal.
fn in_triangle(p: Vec3, [a, b, c]: [Vec3; 3], normal: Vec3) -> bool {
    [(a, b), (b, c), (c, a)]
        .iter()
        .all(|&(u, v)| (v - u).cross(p - u).dot(normal) >= 0.0)
}

/// How close a triangle is to equilateral: 4√3·A / (|e₁|² + |e₂|² + |e₃|²)
/// for area A and edges eᵢ. It is 1 for an equilateral triangle and tends
/// to 0 for a sliver, whatever the triangle's size.
pub(super) fn shape_quality([a, b, c]: [Vec3; 3]) -> f32 {
    let area = 0.5 * (b - a).cross(c - a).length();
    let squares = (b - a).length_squared() + (c - b).length_squared() + (a - c).length_squared();
    4.0 * 3f32.sqrt() * area / squares
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_corner_count_beyond_the_limit_says_so_and_what_follows() {
        assert_eq!(corner_count(3.0, 3), Ok(3));
        let e = corner_count(1e9, 3).unwrap_err();
        assert!(e.contains("at most 4096 corners"), "{e}");
        assert!(
            e.ends_with("says it has 1000000000, and only 3 lines follow it"),
            "{e}"
        );
        let e = corner_count(5000.0, 6000).unwrap_err();
        assert!(e.ends_with("says it has 5000"), "{e}");
        assert!(
            corner_count(2.0, 9)
                .unwrap_err()
                .contains("3 or more; found 2")
        );
        assert!(corner_count(3.5, 9).unwrap_err().contains("whole number"));
    }
}
