//! Triangle meshes from Wavefront OBJ files (read with the tobj crate).

use std::path::Path;

use crate::Vec3;

use super::Shape;
use super::rules::has_area;

/// The triangles of an OBJ file: faces with more corners are split into
/// fans, corners with normals (`vn`) make smooth triangles. Faces without
/// area (repeated or collinear corners, common in real meshes) are left out,
/// since they cannot be seen. Returns a message for the user on failure.
pub(super) fn load_obj(path: &Path) -> Result<Vec<Shape>, String> {
    let options = tobj::LoadOptions {
        triangulate: true,
        single_index: true,
        ..tobj::LoadOptions::default()
    };
    let (models, _materials) =
        tobj::load_obj(path, &options).map_err(|e| format!("cannot read the OBJ file: {e}"))?;
    let mut shapes = Vec::new();
    for model in &models {
        let mesh = &model.mesh;
        let point = |i: u32| corner(&mesh.positions, i);
        let normal = |i: u32| corner(&mesh.normals, i).map(|n| n.normalize_or_zero());
        for face in mesh.indices.chunks_exact(3) {
            let vertices = [point(face[0])?, point(face[1])?, point(face[2])?];
            if !vertices.iter().all(|v| v.is_finite()) {
                return Err(format!(
                    "model `{}` has a corner that is not a finite number",
                    model.name
                ));
            }
            if !has_area(vertices) {
                continue;
            }
            let normals = [normal(face[0]), normal(face[1]), normal(face[2])];
            shapes.push(match normals {
                [Ok(a), Ok(b), Ok(c)] if [a, b, c].iter().all(|n| n.length() > 0.5) => {
                    Shape::SmoothTriangle {
                        vertices,
                        normals: [a, b, c],
                    }
                }
                _ => Shape::Triangle { vertices },
            });
        }
    }
    if shapes.is_empty() {
        return Err("the OBJ file has no triangles with area".into());
    }
    Ok(shapes)
}

/// Corner `i` of a flat list of x, y, z coordinates.
fn corner(coordinates: &[f32], i: u32) -> Result<Vec3, String> {
    let start = 3 * i as usize;
    coordinates
        .get(start..start + 3)
        .map(Vec3::from_slice)
        .ok_or_else(|| {
            format!(
                "a face refers to vertex {} that the file does not have",
                i + 1
            )
        })
}
