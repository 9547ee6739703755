//! Larger versions of two SPD scenes, made here for `bench --scaling`: a
//! sphereflake of more levels, and a Sierpinski tetrahedron of more levels.

use std::f32::consts::TAU;

use raybook::toolkit::scene::{MaterialId, Object, Shape};
use raybook::toolkit::{Scene, Vec3};

/// `scene` with its spheres replaced by a sphereflake of `level` levels:
/// a sphere with nine spheres a third its size around it (six round the
/// equator, three above), each with nine around it, and so on; the first
/// sphere's centre, radius and material are kept. A scene without spheres
/// is returned as it is.
pub fn with_sphereflake(scene: &Scene, level: u32) -> Scene {
    let mut scene = scene.clone();
    let Some((center, radius, material)) = scene.objects.iter().find_map(sphere) else {
        return scene;
    };
    scene
        .objects
        .retain(|o| !matches!(o.shape, Shape::Sphere { .. }));
    let mut spheres = Vec::new();
    flake(center, radius, Vec3::Z, level, &mut spheres);
    scene
        .objects
        .extend(spheres.into_iter().map(|(center, radius)| Object {
            shape: Shape::Sphere { center, radius },
            material,
            shadows: true,
        }));
    scene
}

/// The centre, radius and material of `object` if it is a sphere.
fn sphere(object: &Object) -> Option<(Vec3, f32, MaterialId)> {
    match object.shape {
        Shape::Sphere { center, radius } => Some((center, radius, object.material)),
        _ => None,
    }
}

/// Pushes a sphere and, for `level` more levels, its nine children onto
/// `out`. `up` is the direction from the parent, the children's pole.
fn flake(center: Vec3, radius: f32, up: Vec3, level: u32, out: &mut Vec<(Vec3, f32)>) {
    out.push((center, radius));
    if level == 0 {
        return;
    }
    let (u, v) = up.any_orthonormal_pair();
    let child = radius / 3.0;
    let ring = (0..6).map(|i| (i as f32 * TAU / 6.0, 0.0f32));
    let top = (0..3).map(|i| (i as f32 * TAU / 3.0 + 0.5, 0.955f32));
    for (around, elevation) in ring.chain(top) {
        let flat = around.cos() * u + around.sin() * v;
        let direction = elevation.cos() * flat + elevation.sin() * up;
        let center = center + direction * (radius + child);
        flake(center, child, direction, level - 1, out);
    }
}

/// `scene` with its triangles replaced by a Sierpinski tetrahedron of size
/// `level` as SPD counts it (4^(level − 1) tetrahedra of 4 triangles) in the
/// box the old triangles filled, with the first triangle's material. A
/// scene without triangles is returned as it is.
pub fn with_tetrahedron(scene: &Scene, level: u32) -> Scene {
    let mut scene = scene.clone();
    let triangles: Vec<([Vec3; 3], MaterialId)> =
        scene.objects.iter().filter_map(triangle).collect();
    let Some(&(_, material)) = triangles.first() else {
        return scene;
    };
    let (low, high) = bounds(triangles.iter().flat_map(|(vertices, _)| *vertices));
    let (center, half) = ((low + high) / 2.0, (high - low) / 2.0);
    let corners = [
        Vec3::new(1.0, 1.0, 1.0),
        Vec3::new(-1.0, -1.0, 1.0),
        Vec3::new(1.0, -1.0, -1.0),
        Vec3::new(-1.0, 1.0, -1.0),
    ]
    .map(|c| center + c * half);
    scene
        .objects
        .retain(|o| !matches!(o.shape, Shape::Triangle { .. }));
    let mut tetrahedra = Vec::new();
    sierpinski(corners, level.saturating_sub(1), &mut tetrahedra);
    for [a, b, c, d] in tetrahedra {
        for vertices in [[a, b, c], [a, c, d], [a, d, b], [b, d, c]] {
            scene.objects.push(Object {
                shape: Shape::Triangle { vertices },
                material,
                shadows: true,
            });
        }
    }
    scene
}

/// The vertices and material of `object` if it is a triangle.
fn triangle(object: &Object) -> Option<([Vec3; 3], MaterialId)> {
    match object.shape {
        Shape::Triangle { vertices } => Some((vertices, object.material)),
        _ => None,
    }
}

/// The smallest and largest coordinates of some points.
fn bounds(points: impl Iterator<Item = Vec3>) -> (Vec3, Vec3) {
    points.fold((Vec3::INFINITY, Vec3::NEG_INFINITY), |(low, high), p| {
        (low.min(p), high.max(p))
    })
}

/// Pushes the tetrahedra of a Sierpinski tetrahedron `level` levels below
/// the one with these corners onto `out`: each level keeps, at each corner,
/// the half-size tetrahedron there.
fn sierpinski(corners: [Vec3; 4], level: u32, out: &mut Vec<[Vec3; 4]>) {
    if level == 0 {
        out.push(corners);
        return;
    }
    for keep in corners {
        sierpinski(corners.map(|c| (c + keep) / 2.0), level - 1, out);
    }
}
