//! The rules every scene obeys, whatever file it was read from. The TOML
//! reader's self-checking values (`file/values.rs`) and the NFF reader
//! (`nff/`) check with these same functions, so both formats refuse the
//! same scenes with the same words; each format adds its own place (line,
//! column, field path) to the message.

use std::fmt::Display;

use crate::Vec3;

use super::CameraSpec;

/// The largest image side we accept: beyond this a typo, not a picture.
pub const MAX_IMAGE_SIDE: u32 = 16384;

/// An image side in pixels: 1 to [`MAX_IMAGE_SIDE`].
pub(crate) fn image_side(pixels: i64) -> Result<u32, String> {
    match u32::try_from(pixels) {
        Ok(side) if (1..=MAX_IMAGE_SIDE).contains(&side) => Ok(side),
        _ => Err(not_an_image_side(pixels)),
    }
}

/// What [`image_side`] says about `found`, also for sides that are not whole.
pub(crate) fn not_an_image_side(found: impl Display) -> String {
    format!("an image side is a whole number of pixels from 1 to {MAX_IMAGE_SIDE}; found {found}")
}

/// Is `n` one of 1, 4, 9, ..., 1024, the sample counts a pixel's √N × √N
/// grid of cells can have?
pub fn is_square_sample_count(n: u32) -> bool {
    let side = (n as f64).sqrt().round() as u32;
    (1..=1024).contains(&n) && side * side == n
}

/// A vertical field of view in degrees, strictly between 0 and 180.
pub(crate) fn field_of_view(degrees: f32) -> Result<f32, String> {
    if degrees > 0.0 && degrees < 180.0 {
        Ok(degrees)
    } else {
        Err(format!(
            "the field of view is in degrees, strictly between 0 and 180; found {degrees}"
        ))
    }
}

/// A direction: a vector of non-zero length (that f32 can measure), as its
/// unit vector and its length.
pub(crate) fn direction(v: Vec3) -> Result<(Vec3, f32), String> {
    if v == Vec3::ZERO {
        return Err(
            "a direction must have non-zero length (such as [0, 1, 0]); found [0, 0, 0]".into(),
        );
    }
    let length = v.length();
    if length == 0.0 || !length.is_finite() {
        let too = if length == 0.0 { "short" } else { "long" };
        let scaled = v / v.abs().max_element();
        return Err(format!(
            "the direction is too {too} for the tracer's f32 numbers to measure; \
             a vector along it such as {scaled} points the same way"
        ));
    }
    Ok((v / length, length))
}

/// Why a cone whose base and apex coincide is refused.
pub(crate) const CONE_AXIS: &str =
    "the base and the apex coincide: a cone needs an axis of non-zero length";

/// Why a cone with two zero radii is refused.
pub(crate) const CONE_RADII: &str = "a cone needs a radius > 0 at one end at least";

/// A cone's ends: distinct, radii ≥ 0 and not both 0, and an axis that f32
/// can measure. The intersection divides by the height h = |apex − base|
/// and the normal tilts by (r_base − r_apex)/h, so both must be finite and
/// h > 0 in f32 (an axis of length 1e-44 passes `base != apex` but not this).
pub(crate) fn cone(
    base: Vec3,
    base_radius: f32,
    apex: Vec3,
    apex_radius: f32,
) -> Result<(), String> {
    if base == apex {
        return Err(CONE_AXIS.into());
    }
    if !(base_radius >= 0.0 && apex_radius >= 0.0) {
        return Err(format!(
            "a cone's radii are ≥ 0; found {base_radius} and {apex_radius}"
        ));
    }
    if base_radius == 0.0 && apex_radius == 0.0 {
        return Err(CONE_RADII.into());
    }
    let height = (apex - base).length();
    let tilt = (base_radius - apex_radius) / height;
    if !(height > 0.0 && height.is_finite() && tilt.is_finite()) {
        return Err(
            "the cone is too short for its radii, or too far out, to measure in f32".into(),
        );
    }
    Ok(())
}

/// Why [`has_area`] refuses a triangle.
pub(crate) const ZERO_AREA: &str =
    "the triangle has zero area (two vertices coincide or all three lie on a line)";

/// Is a triangle usable: not (nearly) collinear? |e1 × e2| ≤ 1e-6 |e1| |e2|
/// means the angle between the edges is below 1e-6 radians, and such a
/// triangle has no usable normal.
pub(crate) fn has_area([a, b, c]: [Vec3; 3]) -> bool {
    across(b - a, c - a)
}

/// True when non-zero a and b do not point along one line:
/// |a × b| > 1e-6 |a| |b| (false for zero vectors, and when it overflows).
fn across(a: Vec3, b: Vec3) -> bool {
    a.cross(b).length() > 1e-6 * a.length() * b.length()
}

/// What a format calls the camera's fields, for [`CameraProblem::message`].
pub(crate) struct CameraWords {
    pub eye: &'static str,
    pub look_at: &'static str,
    pub up: &'static str,
    /// An `up` for a camera that looks level, written as in the format.
    pub level_up: &'static str,
}

/// A camera whose eye, look-at point and up give no picture.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(crate) enum CameraProblem {
    /// The look-at point is the eye.
    LooksNowhere,
    /// Up lies along the view direction.
    UpAlongView,
}

impl CameraProblem {
    pub(crate) fn message(self, w: &CameraWords) -> String {
        let CameraWords {
            eye,
            look_at,
            up,
            level_up,
        } = w;
        match self {
            CameraProblem::LooksNowhere => format!(
                "{look_at} equals {eye}, so the camera looks nowhere; \
                 move {look_at} away from {eye}"
            ),
            CameraProblem::UpAlongView => format!(
                "{up} is parallel to the view direction ({look_at} - {eye}), so the image has \
                 no 'up'; choose a vector across the view, such as {level_up} for a level camera"
            ),
        }
    }
}

/// The pinhole camera at `eye` looking at `look_at`; `up` is a unit vector
/// (see [`direction`]) and `vfov_degrees` a [`field_of_view`].
pub(crate) fn camera(
    eye: Vec3,
    look_at: Vec3,
    up: Vec3,
    vfov_degrees: f32,
) -> Result<CameraSpec, CameraProblem> {
    let view = look_at - eye;
    if view.length_squared() == 0.0 {
        return Err(CameraProblem::LooksNowhere);
    }
    if !across(view, up) {
        return Err(CameraProblem::UpAlongView);
    }
    Ok(CameraSpec {
        eye,
        look_at,
        up,
        vfov_degrees,
    })
}
