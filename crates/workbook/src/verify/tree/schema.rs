//! Which fields of a ray tree verify compares, in which order, how, and
//! which a student's tree must have (book/appendix/ray-tree.md shows the
//! same in its tables).

use super::tolerance::Tolerance;

/// Must a student's tree have the field?
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Need {
    Required,
    Optional,
}
use Need::{Optional, Required};
use Tolerance::{Colour, Cosine, Exact, Length, Vector};

/// A field of a node: its name, how it is compared, whether it is required.
pub type Field = (&'static str, Tolerance, Need);

/// A ray's own fields, before its hit (`weight` is optional for the primary ray).
pub const RAY: &[Field] = &[
    ("kind", Exact, Required),
    ("depth", Exact, Optional),
    ("origin", Vector, Required),
    ("direction", Vector, Required),
    ("weight", Colour, Required),
    ("path_weight", Colour, Optional),
    ("end", Exact, Optional),
];

/// A hit's fields; `object` first, since a different object explains the rest.
pub const HIT: &[Field] = &[
    ("object", Exact, Optional),
    ("t", Length, Required),
    ("point", Vector, Required),
    ("normal", Vector, Required),
    ("facing_normal", Vector, Optional),
    ("side", Exact, Optional),
    ("roots", Vector, Optional),
    ("shape", Exact, Optional),
    ("material", Exact, Optional),
];

/// A light's fields before its shadow ray...
pub const LIGHT: &[Field] = &[
    ("kind", Exact, Optional),
    ("status", Exact, Optional),
    ("direction", Vector, Optional),
    ("distance", Length, Optional),
    ("n_dot_l", Cosine, Optional),
    ("casts_shadows", Exact, Optional),
];
/// ...and after it.
pub const LIGHT_TERMS: &[Field] = &[
    ("lambert", Colour, Optional),
    ("highlight", Colour, Optional),
    ("adds", Colour, Required),
];

pub const SHADOW_RAY: &[Field] = &[
    ("origin", Vector, Required),
    ("direction", Vector, Required),
    ("t_max", Length, Optional),
    ("blocked", Exact, Required),
    ("blocker_t", Length, Optional),
];

pub const REFRACTION: &[Field] = &[
    ("entering", Exact, Optional),
    ("n1", Length, Optional),
    ("n2", Length, Optional),
    ("eta", Length, Optional),
    ("cos_theta1", Cosine, Optional),
    ("sin2_theta2", Cosine, Optional),
    ("total_internal_reflection", Exact, Optional),
    ("fresnel", Colour, Optional),
    ("transparency", Colour, Optional),
    ("reflectance", Colour, Optional),
    ("reflected_weight", Colour, Optional),
    ("refracted_weight", Colour, Optional),
];
