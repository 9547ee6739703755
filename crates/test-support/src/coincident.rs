//! Scenes of coincident surfaces, for the tests of chapter 2's rule: a
//! plane and triangles in it, in shuffled orders.

use ch00_toolkit::Vec3;
use ch00_toolkit::scene::{Object, Shape};

use crate::Rng;

/// An object of `shape` with material 0 that casts shadows.
pub fn object(shape: Shape) -> Object {
    Object {
        shape,
        material: 0,
        shadows: true,
    }
}

/// A plane through `at` with unit normal `n`, and `count` triangles of it
/// whose corners are its points rounded to f32, overlapping around `at`.
pub fn coplanar(rng: &mut Rng, n: Vec3, at: Vec3, count: usize) -> Vec<Object> {
    let a = n.any_orthonormal_vector();
    let b = n.cross(a);
    let mut objects = vec![object(Shape::Plane {
        normal: n,
        offset: -n.dot(at),
    })];
    for _ in 0..count {
        let centre = at + rng.range(-2.0, 2.0) * a + rng.range(-2.0, 2.0) * b;
        let size = rng.range(0.5, 3.0);
        let vertices = [0.0f32, 2.1, 4.2].map(|angle| {
            let angle = angle + rng.range(0.0, 1.0);
            centre + size * (angle.cos() * a + angle.sin() * b)
        });
        objects.push(object(Shape::Triangle { vertices }));
    }
    objects
}

/// Fisher–Yates, with the test's generator.
pub fn shuffle(rng: &mut Rng, objects: &mut [Object]) {
    for i in (1..objects.len()).rev() {
        let j = (rng.range(0.0, 1.0) * (i + 1) as f32) as usize;
        objects.swap(i, j.min(i));
    }
}
