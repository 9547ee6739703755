//! The hard numerical cases of chapter 2's intersections, in the tracer's f32.
//!
//! Each case states a geometric fact and checks the tracer against an exact
//! answer computed in f64 from the same f32 inputs. Where a naive formula is
//! the reason for the case (the textbook quadratic, Möller–Trumbore), it is
//! written here too, and the test shows that it really fails: otherwise the
//! case would prove nothing.
//!
//! One test target (`cargo test -p raybook --test numerics_hits`), in modules:
//!
//! * `spheres`: tangent rays, far tiny spheres and huge close ones, where the
//!   textbook quadratic fails, and chords from a hit point;
//! * `planes`: parallel and almost parallel rays, against planes and a triangle;
//! * `triangles`: shared edges and fan apexes without cracks (unlike
//!   Möller–Trumbore), and rays along an edge;
//! * `closest`: the closest hit of random shapes is the closest;
//! * `coincident`: surfaces in one place are decided by the rule for
//!   coincident surfaces, whatever the order of traversal.

mod closest;
mod coincident;
mod planes;
mod spheres;
mod triangles;

pub(crate) const INF: f32 = f32::INFINITY;

/// Said by the cases that need more than the lecture's formulas, so that a
/// student who tries the lecture's method in the tracer (chapter 2's
/// exercises) knows that this failure is expected, not a mistake.
pub(crate) const NEEDS_STABLE: &str = "this needs the stable quadratic (chapter 2's sphere_roots); \
    the lecture's a, b, c formula in f32 is expected to fail here";
pub(crate) const NEEDS_WATERTIGHT: &str = "this needs the watertight test (chapter 2's intersect_triangle); \
    the lecture's method (the plane, then α and β) is expected to fail here";

/// |actual − exact| / |exact|.
pub(crate) fn relative_error(actual: f32, exact: f64) -> f64 {
    (actual as f64 - exact).abs() / exact.abs()
}

/// No NaN and no infinity in a triangle hit.
pub(crate) fn finite_triangle_hit(hit: Option<(f32, f32, f32)>) -> bool {
    hit.is_none_or(|(t, a, b)| t.is_finite() && a.is_finite() && b.is_finite())
}
