//! The `v` entity, six lines: the camera and the image size, checked by the
//! rules TOML scenes obey (`scene/rules.rs`).

use super::reader::{Line, Reader};
use crate::Vec3;
use crate::rules::{self, CameraProblem, CameraWords};
use crate::{CameraSpec, SceneError};

/// The viewpoint's lines in the order NFF writes them, and their numbers.
const FIELDS: [(&str, usize); 6] = [
    ("from", 3),
    ("at", 3),
    ("up", 3),
    ("angle", 1),
    ("hither", 1),
    ("resolution", 2),
];

/// The lines a viewpoint needs, for messages.
const NEEDS: &str = "from, at, up, angle, hither and resolution";

/// The camera's fields as NFF names them, for the shared rules' messages.
const CAMERA_WORDS: CameraWords = CameraWords {
    eye: "`from`",
    look_at: "`at`",
    up: "`up`",
    level_up: "`up 0 0 1` (z up, as in the SPD scenes)",
};

/// One line of the viewpoint and its numbers.
struct Field<'a> {
    line: Line<'a>,
    numbers: Vec<f32>,
}

impl Field<'_> {
    fn vector(&self) -> Vec3 {
        Vec3::from_slice(&self.numbers)
    }

    /// An error about the `i`th number of this line, with the path `v.<field>`.
    fn error(&self, reader: &Reader, i: usize, message: impl Into<String>) -> SceneError {
        SceneError {
            path: format!("v.{}", self.line.keyword()),
            ..reader.error(&self.line, self.line.column(i + 1), message)
        }
    }
}

/// The lines of the `v` entity on `v`: the camera and the image's width and height.
pub(super) fn viewpoint(
    v: &Line,
    reader: &mut Reader,
) -> Result<(CameraSpec, u32, u32), SceneError> {
    let [from, at, up, angle, _hither, resolution] = fields(v, reader)?;
    let (width, height) = image_size(&resolution, reader)?;
    let vfov = vertical_field_of_view(&angle, height, reader)?;
    let (up_unit, _) = rules::direction(up.vector()).map_err(|m| up.error(reader, 0, m))?;
    let camera = rules::camera(from.vector(), at.vector(), up_unit, vfov).map_err(|problem| {
        let field = match problem {
            CameraProblem::LooksNowhere => &at,
            CameraProblem::UpAlongView => &up,
        };
        field.error(reader, 0, problem.message(&CAMERA_WORDS))
    })?;
    Ok((camera, width, height))
}

/// The six lines after `v`, in any order, each once.
fn fields<'a>(v: &Line, reader: &mut Reader<'a>) -> Result<[Field<'a>; 6], SceneError> {
    let mut fields: [Option<Field>; 6] = Default::default();
    for _ in 0..FIELDS.len() {
        let line = reader.expect_line(v, "a line of the viewpoint")?;
        let Some(i) = FIELDS.iter().position(|&(f, _)| f == line.keyword()) else {
            let message = format!(
                "expected a viewpoint line (from, at, up, angle, hither, resolution), found `{}`",
                line.keyword()
            );
            return Err(reader.error(&line, 1, message));
        };
        let (name, count) = FIELDS[i];
        if fields[i].is_some() {
            let message = format!("the viewpoint has `{name}` twice; it needs {NEEDS}, each once");
            return Err(reader.error(&line, 1, message));
        }
        let numbers = reader.numbers(&line, count, &format!("{name} and {count} numbers"))?;
        fields[i] = Some(Field { line, numbers });
    }
    let [Some(a), Some(b), Some(c), Some(d), Some(e), Some(f)] = fields else {
        // Six lines, none twice: all are there.
        return Err(reader.error(v, 1, format!("the viewpoint needs {NEEDS}")));
    };
    Ok([a, b, c, d, e, f])
}

/// `resolution width height`, each side as a TOML scene's image side.
fn image_size(resolution: &Field, reader: &Reader) -> Result<(u32, u32), SceneError> {
    let side = |i: usize| {
        let x = resolution.numbers[i];
        let side = match x.fract() == 0.0 {
            true => rules::image_side(x as i64),
            false => Err(rules::not_an_image_side(x)),
        };
        side.map_err(|m| resolution.error(reader, i, m))
    };
    Ok((side(0)?, side(1)?))
}

/// raybook's vertical field of view for NFF's `angle`, which spans the
/// centres of the first and the last pixel row; raybook's spans the image's
/// edges, half a pixel further out (the same for a picture of one row).
fn vertical_field_of_view(angle: &Field, height: u32, reader: &Reader) -> Result<f32, SceneError> {
    let degrees = angle.numbers[0];
    rules::field_of_view(degrees).map_err(|m| angle.error(reader, 0, m))?;
    if height == 1 {
        return Ok(degrees);
    }
    let half = (degrees.to_radians() / 2.0).tan() / (1.0 - 1.0 / height as f32);
    let vfov = 2.0 * half.atan().to_degrees();
    rules::field_of_view(vfov).map_err(|m| {
        let why = format!(
            "an angle of {degrees}° between the centres of the first and the last of {height} \
             rows is {vfov}° between the image's edges: {m}"
        );
        angle.error(reader, 0, why)
    })
}
