//! Light arriving at a point: from where, and how much.

use crate::toolkit::scene::{Falloff, Light};
use crate::toolkit::{Color, Vec3};

/// Light from a point or spot light arriving at a point of a surface.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Incoming {
    /// Unit vector l from the surface point towards the light: the
    /// direction of n·l in the cosine law.
    pub direction: Vec3,
    /// Distance from the surface point to the light.
    pub distance: f32,
    /// Colour × intensity / r² (no 1/r² for a light without falloff),
    /// times the spot's cone factor: the *irradiance* the light gives a
    /// surface at distance r that faces it (at normal incidence), per
    /// channel; the README's I_L. A surface tilted away from the light
    /// receives less of it (README, *Lambert's cosine law*; the workbook
    /// folds the 1/π of the diffuse BRDF into the light's intensity, see
    /// *Why there is no 1/π*).
    pub irradiance: Color,
    /// Does the light cast shadows? (Chapter 4 traces no shadow ray if not.)
    pub casts_shadows: bool,
}

/// What one light sends to a point.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Arrival {
    /// Ambient light: the same everywhere, from no direction.
    Ambient(Color),
    /// Light from one direction.
    Incoming(Incoming),
    /// Nothing: outside a spot's cone, or the light sits exactly on the point.
    Dark,
}

/// The light that `light` sends to `point`.
///
/// A point light of intensity I at distance r gives the irradiance
/// colour × I / r² to a surface facing it: its power spreads over a sphere
/// whose area grows with r² (or colour × I at any distance, if the light
/// says it has no falloff, [`Falloff::None`]: see `attenuation`). A spot
/// light is a point light times [`spot_factor`].
// Inlined: it runs for every light at every hit (why, measured:
// book/appendix/performance.md, "Notes moved from the code").
#[inline(always)]
pub fn arrival(light: &Light, point: Vec3) -> Arrival {
    match *light {
        Light::Ambient { color } => Arrival::Ambient(color),
        Light::Point {
            position,
            color,
            intensity,
            shadows,
            falloff,
        } => from_point(position, color * intensity, falloff, shadows, point),
        Light::Spot {
            position,
            direction,
            color,
            intensity,
            inner_degrees,
            outer_degrees,
            shadows,
        } => {
            let falloff = Falloff::InverseSquare;
            let Arrival::Incoming(mut incoming) =
                from_point(position, color * intensity, falloff, shadows, point)
            else {
                return Arrival::Dark;
            };
            let cone = spot_factor(direction, inner_degrees, outer_degrees, -incoming.direction);
            if cone == 0.0 {
                return Arrival::Dark;
            }
            incoming.irradiance *= cone;
            Arrival::Incoming(incoming)
        }
    }
}

/// Light of strength `power` from `position`, falling off with distance as
/// `falloff` says (1/r² for a physical light).
fn from_point(
    position: Vec3,
    power: Color,
    falloff: Falloff,
    casts_shadows: bool,
    point: Vec3,
) -> Arrival {
    let to_light = position - point;
    let distance = to_light.length();
    if distance == 0.0 {
        return Arrival::Dark; // a light exactly on the point has no direction
    }
    Arrival::Incoming(Incoming {
        direction: to_light / distance,
        distance,
        irradiance: power * attenuation(falloff, distance),
        casts_shadows,
    })
}

/// How much of a point light's strength arrives at `distance` r from it:
/// 1/r² for [`Falloff::InverseSquare`], 1 for [`Falloff::None`] (NFF's
/// lights, which are as bright everywhere).
fn attenuation(falloff: Falloff, distance: f32) -> f32 {
    match falloff {
        Falloff::InverseSquare => 1.0 / (distance * distance),
        Falloff::None => 1.0,
    }
}

/// How much of a spot light goes out in the direction `ray`: the cone's
/// factor, from 0 to 1, that multiplies the light's irradiance. Derived in
/// the README, section *The spot light's cone*.
///
/// * `axis` is the cone's axis a (the spot's `direction`), and `ray` the
///   direction from the light towards the lit point, both of length 1.
/// * `inner_degrees` and `outer_degrees` are the cone's half-angles, in
///   **degrees**, with 0 ≤ inner ≤ outer ≤ 90 (the scene file checks it).
/// * 1 for a direction within the inner half-angle of the axis, its edge
///   included; 0 for one at or beyond the outer half-angle.
/// * In between, the factor falls from 1 at the inner edge to 0 at the
///   outer one along the README's smooth step, measured on the cosine of the
///   angle to the axis (not on the angle itself): no kink at either edge.
/// * inner = outer is a cone with a hard edge: 1 up to the edge and on
///   it, 0 beyond, and no division by zero.
pub fn spot_factor(axis: Vec3, inner_degrees: f32, outer_degrees: f32, ray: Vec3) -> f32 {
    // EXERCISE(ch03-spot): the cone's factor for this direction: 1 within inner degrees of the axis, 0 beyond outer, between them the smooth step of the cosine (README)
    crate::workbench::exercise::solution_begins("ch03-spot");
    let cos_angle = axis.dot(ray);
    let cos_inner = inner_degrees.to_radians().cos();
    let cos_outer = outer_degrees.to_radians().cos();
    if cos_angle >= cos_inner {
        return 1.0;
    }
    if cos_angle <= cos_outer {
        return 0.0;
    }
    let s = (cos_angle - cos_outer) / (cos_inner - cos_outer);
    s * s * (3.0 - 2.0 * s)
    // END EXERCISE
}
