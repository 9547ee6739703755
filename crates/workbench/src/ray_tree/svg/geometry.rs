//! The picture's plane and what lies in it: points projected onto it, the
//! objects' cross-sections with it, boxes and clipping.

use ch00_toolkit::Vec3;
use scene_files::Shape;

use crate::ray_tree::RayNode;

/// A point of the plane, or of the picture.
pub(super) type P2 = [f32; 2];

/// The picture's plane: through the eye, spanned by the primary ray's
/// direction `u` (drawn to the right) and the camera's up made orthogonal
/// to it, `v` (drawn upwards).
pub(super) struct Plane {
    eye: Vec3,
    u: Vec3,
    v: Vec3,
    normal: Vec3,
}

impl Plane {
    pub(super) fn of(up: Vec3, primary: &RayNode) -> Plane {
        let u = Vec3::from_array(primary.direction).normalize();
        let v = up - up.dot(u) * u;
        let v = if v.length() < 1e-6 {
            u.any_orthonormal_vector()
        } else {
            v.normalize()
        };
        let eye = Vec3::from_array(primary.origin);
        Plane {
            eye,
            u,
            v,
            normal: u.cross(v),
        }
    }

    /// A point's coordinates in the plane (its distance from it dropped).
    pub(super) fn project(&self, p: Vec3) -> P2 {
        let d = p - self.eye;
        [d.dot(self.u), d.dot(self.v)]
    }

    /// A point's signed distance from the plane.
    pub(super) fn distance(&self, p: Vec3) -> f32 {
        (p - self.eye).dot(self.normal)
    }
}

/// An object cut by the plane.
pub(super) enum Section {
    Circle {
        center: P2,
        radius: f32,
    },
    /// An infinite line: a point on it and its unit direction.
    Line {
        point: P2,
        dir: P2,
    },
    Segment {
        a: P2,
        b: P2,
    },
}

/// Where `shape` cuts the plane, if it does (and is not a cone).
pub(super) fn section(plane: &Plane, shape: &Shape) -> Option<Section> {
    match *shape {
        Shape::Sphere { center, radius } => {
            let d = plane.distance(center);
            (d.abs() < radius).then(|| Section::Circle {
                center: plane.project(center),
                radius: (radius * radius - d * d).sqrt(),
            })
        }
        Shape::Plane { normal, offset } => plane_section(plane, normal, offset),
        Shape::Triangle { vertices } | Shape::SmoothTriangle { vertices, .. } => {
            triangle_section(plane, vertices)
        }
        Shape::Cone { .. } => None,
    }
}

/// An object seen along the plane's normal: its shape projected onto the
/// plane, to show where hits out of the plane lie.
pub(super) enum Outline {
    Circle { center: P2, radius: f32 },
    Triangle([P2; 3]),
}

/// The outline of a sphere or a triangle (a plane's or a cone's: none).
/// None either for a sphere whose cross-section already is its outline,
/// or nearly, and for a triangle that the plane cuts.
pub(super) fn outline(plane: &Plane, shape: &Shape, cut: Option<&Section>) -> Option<Outline> {
    match (*shape, cut) {
        (Shape::Sphere { center, radius }, cut) => {
            let cut_radius = match cut {
                Some(Section::Circle { radius, .. }) => *radius,
                _ => 0.0,
            };
            (cut_radius < 0.95 * radius).then(|| Outline::Circle {
                center: plane.project(center),
                radius,
            })
        }
        (Shape::Triangle { vertices } | Shape::SmoothTriangle { vertices, .. }, None) => {
            Some(Outline::Triangle(vertices.map(|v| plane.project(v))))
        }
        _ => None,
    }
}

/// The line where the plane n·x + d = 0 cuts the picture's plane.
fn plane_section(plane: &Plane, n: Vec3, d: f32) -> Option<Section> {
    let g = [n.dot(plane.u), n.dot(plane.v)];
    let g2 = g[0] * g[0] + g[1] * g[1];
    if g2 < 1e-12 {
        return None; // parallel to the picture's plane
    }
    let k = -(n.dot(plane.eye) + d) / g2;
    let len = g2.sqrt();
    Some(Section::Line {
        point: [g[0] * k, g[1] * k],
        dir: [-g[1] / len, g[0] / len],
    })
}

/// The segment where the plane cuts a triangle: one point on each of the
/// two edges whose ends lie on either side of it.
fn triangle_section(plane: &Plane, v: [Vec3; 3]) -> Option<Section> {
    let s = v.map(|p| plane.distance(p));
    let mut points = Vec::new();
    for (i, j) in [(0, 1), (1, 2), (2, 0)] {
        if (s[i] <= 0.0) != (s[j] <= 0.0) {
            let t = s[i] / (s[i] - s[j]);
            points.push(plane.project(v[i] + t * (v[j] - v[i])));
        }
    }
    match points[..] {
        [a, b] => Some(Section::Segment { a, b }),
        _ => None,
    }
}

/// The smallest box around `points`.
pub(super) fn bounds(points: &[P2]) -> (P2, P2) {
    let mut lo = [f32::INFINITY; 2];
    let mut hi = [f32::NEG_INFINITY; 2];
    for p in points {
        lo = [lo[0].min(p[0]), lo[1].min(p[1])];
        hi = [hi[0].max(p[0]), hi[1].max(p[1])];
    }
    (lo, hi)
}

/// The larger side of a box (−∞ for the box around no point).
pub(super) fn size(lo: P2, hi: P2) -> f32 {
    (hi[0] - lo[0]).max(hi[1] - lo[1])
}

/// The part of the segment from `a` to `b` inside the box from `min` to
/// `max`, if any (Liang and Barsky's clipping).
pub(super) fn clip(a: P2, b: P2, min: P2, max: P2) -> Option<(P2, P2)> {
    let d = [b[0] - a[0], b[1] - a[1]];
    let (mut t0, mut t1) = (0.0f32, 1.0f32);
    for i in 0..2 {
        for (p, q) in [(-d[i], a[i] - min[i]), (d[i], max[i] - a[i])] {
            if p == 0.0 {
                if q < 0.0 {
                    return None;
                }
            } else if p < 0.0 {
                t0 = t0.max(q / p);
            } else {
                t1 = t1.min(q / p);
            }
        }
    }
    let at = |t: f32| [a[0] + t * d[0], a[1] + t * d[1]];
    (t0 <= t1).then(|| (at(t0), at(t1)))
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::ray_tree::RayKind;

    /// The plane of an eye at the origin looking down −z, up +y: the
    /// picture's right is −z, its up +y, so (x, y, z) ↦ (−z, y).
    fn plane() -> Plane {
        let primary = RayNode::new(RayKind::Primary, 0, Vec3::ZERO, -Vec3::Z);
        Plane::of(Vec3::Y, &primary)
    }

    fn close(a: P2, b: P2) -> bool {
        (a[0] - b[0]).abs() < 1e-5 && (a[1] - b[1]).abs() < 1e-5
    }

    #[test]
    fn a_sphere_off_the_plane_is_cut_in_a_smaller_circle() {
        let shape = Shape::Sphere {
            center: Vec3::new(0.6, 1.0, -5.0),
            radius: 1.0,
        };
        let Some(Section::Circle { center, radius }) = section(&plane(), &shape) else {
            panic!("a circle")
        };
        assert!(close(center, [5.0, 1.0]), "{center:?}");
        assert!((radius - 0.8).abs() < 1e-5, "{radius}");
        let far = Shape::Sphere {
            center: Vec3::new(2.0, 0.0, -5.0),
            radius: 1.0,
        };
        assert!(section(&plane(), &far).is_none());
        assert!(matches!(
            outline(&plane(), &far, None),
            Some(Outline::Circle { .. })
        ));
    }

    #[test]
    fn a_floor_is_cut_in_a_line_and_a_wall_beside_the_ray_not_at_all() {
        let floor = Shape::Plane {
            normal: Vec3::Y,
            offset: 1.0,
        };
        let Some(Section::Line { point, dir }) = section(&plane(), &floor) else {
            panic!("a line")
        };
        assert!(
            close(point, [0.0, -1.0]) && close(dir, [-1.0, 0.0]),
            "{point:?} {dir:?}"
        );
        let wall = Shape::Plane {
            normal: Vec3::X,
            offset: 2.0,
        };
        assert!(section(&plane(), &wall).is_none());
    }

    #[test]
    fn a_triangle_across_the_plane_is_cut_in_a_segment() {
        let vertices = [
            Vec3::new(-1.0, 0.0, -2.0),
            Vec3::new(1.0, 0.0, -2.0),
            Vec3::new(1.0, 0.0, -4.0),
        ];
        let Some(Section::Segment { a, b }) = section(&plane(), &Shape::Triangle { vertices })
        else {
            panic!("a segment")
        };
        assert!(close(a, [2.0, 0.0]) && close(b, [3.0, 0.0]), "{a:?} {b:?}");
        let aside = vertices.map(|v| v + Vec3::X * 5.0);
        assert!(section(&plane(), &Shape::Triangle { vertices: aside }).is_none());
    }

    #[test]
    fn clipping_keeps_the_part_inside_the_box() {
        let (a, b) = clip([-1.0, 0.5], [3.0, 0.5], [0.0, 0.0], [2.0, 1.0]).unwrap();
        assert!(close(a, [0.0, 0.5]) && close(b, [2.0, 0.5]));
        assert!(clip([-1.0, 2.0], [3.0, 2.0], [0.0, 0.0], [2.0, 1.0]).is_none());
    }
}
