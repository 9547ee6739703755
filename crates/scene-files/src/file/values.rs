//! Values that check themselves while they are read: each number, vector and
//! colour of a scene file is one of these small types, so an error found here
//! carries toml's span (the line) and serde_path_to_error's path
//! (`objects[3].radius`). The rules shared with NFF are in `scene/rules.rs`.

use crate::Vec3;
use serde::Deserialize;
use serde::de::{self, Deserializer, SeqAccess, Visitor};

use crate::rules;

/// Reads a TOML number (integer or float) as f32, refusing NaN, infinities and
/// values beyond f32's range.
fn number<'de, D: Deserializer<'de>>(d: D) -> Result<f32, D::Error> {
    let x = f64::deserialize(d)?;
    if !x.is_finite() {
        return Err(de::Error::custom(format!(
            "expected a finite number, found {x}"
        )));
    }
    if x.abs() > f32::MAX as f64 {
        return Err(de::Error::custom(format!(
            "{x:e} is too large for the tracer's f32 numbers (largest {:e})",
            f32::MAX
        )));
    }
    Ok(x as f32)
}

/// Any finite number.
#[derive(Clone, Copy)]
pub(super) struct Number(pub(super) f32);

impl<'de> Deserialize<'de> for Number {
    fn deserialize<D: Deserializer<'de>>(d: D) -> Result<Self, D::Error> {
        number(d).map(Number)
    }
}

/// A finite number > 0.
#[derive(Clone, Copy)]
pub(super) struct Positive(pub(super) f32);

impl<'de> Deserialize<'de> for Positive {
    fn deserialize<D: Deserializer<'de>>(d: D) -> Result<Self, D::Error> {
        let x = number(d)?;
        if x <= 0.0 {
            return Err(de::Error::custom(format!(
                "must be greater than 0, found {x}"
            )));
        }
        Ok(Positive(x))
    }
}

/// A finite number ≥ 0.
#[derive(Clone, Copy)]
pub(super) struct NonNegative(pub(super) f32);

impl<'de> Deserialize<'de> for NonNegative {
    fn deserialize<D: Deserializer<'de>>(d: D) -> Result<Self, D::Error> {
        let x = number(d)?;
        if x < 0.0 {
            return Err(de::Error::custom(format!("must be 0 or more, found {x}")));
        }
        Ok(NonNegative(x))
    }
}

/// A weight in [0, 1].
#[derive(Clone, Copy, Default)]
pub(super) struct Fraction(pub(super) f32);

impl<'de> Deserialize<'de> for Fraction {
    fn deserialize<D: Deserializer<'de>>(d: D) -> Result<Self, D::Error> {
        let x = number(d)?;
        if !(0.0..=1.0).contains(&x) {
            return Err(de::Error::custom(format!(
                "must be between 0 and 1, found {x}"
            )));
        }
        Ok(Fraction(x))
    }
}

/// A vertical field of view in degrees, strictly between 0 and 180.
#[derive(Clone, Copy)]
pub(super) struct FieldOfView(pub(super) f32);

impl<'de> Deserialize<'de> for FieldOfView {
    fn deserialize<D: Deserializer<'de>>(d: D) -> Result<Self, D::Error> {
        let x = number(d)?;
        rules::field_of_view(x)
            .map(FieldOfView)
            .map_err(de::Error::custom)
    }
}

/// A spot light's half-angle in degrees, in [0, 90].
#[derive(Clone, Copy)]
pub(super) struct HalfAngle(pub(super) f32);

impl<'de> Deserialize<'de> for HalfAngle {
    fn deserialize<D: Deserializer<'de>>(d: D) -> Result<Self, D::Error> {
        let x = number(d)?;
        if !(0.0..=90.0).contains(&x) {
            return Err(de::Error::custom(format!(
                "a cone's half-angle is in degrees, from 0 to 90; found {x}"
            )));
        }
        Ok(HalfAngle(x))
    }
}

/// An image side in pixels: 1 to [`rules::MAX_IMAGE_SIDE`].
#[derive(Clone, Copy)]
pub(super) struct Side(pub(super) u32);

impl<'de> Deserialize<'de> for Side {
    fn deserialize<D: Deserializer<'de>>(d: D) -> Result<Self, D::Error> {
        let x = i64::deserialize(d)?;
        rules::image_side(x).map(Side).map_err(de::Error::custom)
    }
}

/// Rays per pixel: a square number (1, 4, 9, 16, ...) up to 1024, so that
/// a pixel splits into a √N × √N grid of cells, one ray in each.
#[derive(Clone, Copy)]
pub(super) struct Samples(pub(super) u32);

impl Default for Samples {
    fn default() -> Self {
        Samples(1)
    }
}

impl<'de> Deserialize<'de> for Samples {
    fn deserialize<D: Deserializer<'de>>(d: D) -> Result<Self, D::Error> {
        let n = i64::deserialize(d)?;
        match u32::try_from(n) {
            Ok(n) if rules::is_square_sample_count(n) => Ok(Samples(n)),
            _ => Err(de::Error::custom(format!(
                "samples per pixel must be a square number from 1 to 1024 \
                 (1, 4, 9, 16, ...); found {n}"
            ))),
        }
    }
}

/// A recursion depth: 0 to 64.
#[derive(Clone, Copy)]
pub(super) struct Depth(pub(super) u32);

impl<'de> Deserialize<'de> for Depth {
    fn deserialize<D: Deserializer<'de>>(d: D) -> Result<Self, D::Error> {
        let x = i64::deserialize(d)?;
        if !(0..=64).contains(&x) {
            return Err(de::Error::custom(format!(
                "max_depth counts bounces, from 0 to 64; found {x}"
            )));
        }
        Ok(Depth(x as u32))
    }
}

/// Reads exactly three finite numbers `[x, y, z]`: fewer or more is an error,
/// never silently cut.
fn three_numbers<'de, D: Deserializer<'de>>(d: D) -> Result<Vec3, D::Error> {
    struct Three;
    impl<'de> Visitor<'de> for Three {
        type Value = Vec3;
        fn expecting(&self, f: &mut std::fmt::Formatter) -> std::fmt::Result {
            f.write_str("an array of three numbers [x, y, z]")
        }
        fn visit_seq<A: SeqAccess<'de>>(self, mut seq: A) -> Result<Vec3, A::Error> {
            let mut values = Vec::with_capacity(3);
            while let Some(Number(x)) = seq.next_element()? {
                values.push(x);
            }
            match values[..] {
                [x, y, z] => Ok(Vec3::new(x, y, z)),
                _ => Err(de::Error::custom(format!(
                    "expected three numbers [x, y, z], found {}",
                    values.len()
                ))),
            }
        }
    }
    d.deserialize_seq(Three)
}

/// A point or vector `[x, y, z]`.
#[derive(Clone, Copy)]
pub(super) struct Xyz(pub(super) Vec3);

impl<'de> Deserialize<'de> for Xyz {
    fn deserialize<D: Deserializer<'de>>(d: D) -> Result<Self, D::Error> {
        three_numbers(d).map(Xyz)
    }
}

/// A direction: a non-zero vector, kept as its unit vector and its length.
#[derive(Clone, Copy)]
pub(super) struct Direction(pub(super) Vec3, pub(super) f32);

impl<'de> Deserialize<'de> for Direction {
    fn deserialize<D: Deserializer<'de>>(d: D) -> Result<Self, D::Error> {
        let v = three_numbers(d)?;
        let (unit, length) = rules::direction(v).map_err(de::Error::custom)?;
        Ok(Direction(unit, length))
    }
}

/// A light's colour: three numbers ≥ 0 (brighter than 1 is allowed).
#[derive(Clone, Copy, Default)]
pub(super) struct Rgb(pub(super) Vec3);

impl<'de> Deserialize<'de> for Rgb {
    fn deserialize<D: Deserializer<'de>>(d: D) -> Result<Self, D::Error> {
        let c = three_numbers(d)?;
        if c.min_element() < 0.0 {
            return Err(de::Error::custom(format!(
                "colour components must be 0 or more, found {c}"
            )));
        }
        Ok(Rgb(c))
    }
}

/// A surface weight per channel: three numbers in [0, 1].
#[derive(Clone, Copy, Default)]
pub(super) struct Albedo(pub(super) Vec3);

impl<'de> Deserialize<'de> for Albedo {
    fn deserialize<D: Deserializer<'de>>(d: D) -> Result<Self, D::Error> {
        let c = three_numbers(d)?;
        if c.min_element() < 0.0 || c.max_element() > 1.0 {
            return Err(de::Error::custom(format!(
                "a surface reflects between 0 and 1 of each channel, found {c}"
            )));
        }
        Ok(Albedo(c))
    }
}

/// A triangle's three corners, refused when they are (nearly) collinear
/// (see [`rules::has_area`]).
#[derive(Clone, Copy)]
pub(super) struct Corners(pub(super) [Vec3; 3]);

impl<'de> Deserialize<'de> for Corners {
    fn deserialize<D: Deserializer<'de>>(d: D) -> Result<Self, D::Error> {
        let corners: Vec<Xyz> = Vec::deserialize(d)?;
        let [a, b, c] = corners[..] else {
            return Err(de::Error::custom(format!(
                "a triangle has three vertices [[x, y, z], [x, y, z], [x, y, z]], found {}",
                corners.len()
            )));
        };
        let vertices = [a.0, b.0, c.0];
        if !rules::has_area(vertices) {
            return Err(de::Error::custom(rules::ZERO_AREA));
        }
        Ok(Corners(vertices))
    }
}
