#![doc = include_str!("../README.md")]

mod snell;

pub mod ray_tree;

pub use ch05_reflection::{
    Camera, Hit, Mirrors, Path, Ray, Secondary, SecondaryKind, ShadowStart, Surface, Whitted,
    World, closest_hit, lambert, mirror_ray, offset_origin, reflect, render, render_whitted,
    scene_files, shade, toolkit, trace, workbench,
};
pub use snell::{refract, schlick};

use toolkit::{Color, Image, Scene, Stats, Vec3};

/// How light splits at a transparent surface, and what decided it.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Split {
    /// n₁ and n₂: the index of refraction on the side the ray comes from,
    /// and on the side it goes into.
    pub indices: (f32, f32),
    /// Schlick's Fresnel term R, where the material asks for it and there
    /// is a refracted ray; `None` otherwise.
    pub fresnel: Option<f32>,
    /// Weight of the mirror ray (the material's reflectance, plus what
    /// total internal reflection or the Fresnel term sends there).
    pub reflected: Color,
    /// Weight of the refracted ray, and its direction (none if totally reflected).
    pub refracted: Option<(Color, Vec3)>,
}

/// How the light of a ray arriving at a transparent `surface` splits
/// between the mirror ray and the refracted ray. Derived in the README,
/// sections *Entering or leaving*, *Fresnel and Schlick's approximation*
/// and *The split* (the refracted direction: [`refract`]).
///
/// * `incoming.direction` is the arriving unit direction d.
///   `surface.hit.normal` is the surface's *outward* geometric normal;
///   `surface.normal` is the normal already turned to face the ray, so it
///   cannot tell entering from leaving. From the material: its reflectance
///   ρ (per channel), its transparency T (one number for every channel),
///   its `ior` (relative to what surrounds the object: an air bubble in
///   glass has 1/1.5) and `fresnel`.
/// * `indices`: (n₁, n₂), the index on the side the ray comes from and on
///   the side it goes into: 1 outside the object, `ior` inside it. Whether
///   the ray enters or leaves is decided with the outward normal (a ray
///   that meets the outside enters; one exactly along the surface counts
///   as leaving).
/// * `refracted`: the refracted ray's weight and its direction, by
///   [`refract`] with the η of these two indices and the normal on the
///   ray's side; `None` on total internal reflection.
/// * `reflected`: the mirror ray's weight: ρ plus the part of T that the
///   surface reflects. On total internal reflection that part is all of T.
///   Otherwise it is T's share R, Schlick's Fresnel term ([`schlick`], with
///   cos θ on the side of the smaller index), or none when the material
///   does not ask for `fresnel`; the refracted ray carries the rest of T.
///   So the two shares of T always add up to T.
/// * `fresnel`: `Some(R)`, the Fresnel term used, when the material asks
///   for it and there is a refracted ray; `None` on total internal
///   reflection or without `fresnel`.
/// * `indices` and `fresnel` are not used for tracing, but chapter 6's ray
///   tree (`--pixel X,Y`) prints them as this function returns them,
///   beside the η it works out from them and the weights: they must be the
///   ones the split used.
pub fn split(surface: &Surface, incoming: &Ray) -> Split {
    // EXERCISE(ch06-split): entering or leaving (from the outward normal), the indices on either side, Snell's refracted direction; on total internal reflection everything transmitted is reflected, else the transmitted weight is shared by the Fresnel term (if the material asks for it) between the mirror ray and the refracted one
    crate::workbench::exercise::solution_begins("ch06-split");
    let material = surface.material;
    let transparency = Color::splat(material.transparency);
    let d = incoming.direction;
    let entering = d.dot(surface.hit.normal) < 0.0;
    let (n1, n2) = if entering {
        (1.0, material.ior)
    } else {
        (material.ior, 1.0)
    };
    let Some(direction) = refract(d, surface.normal, n1 / n2) else {
        // Total internal reflection: the transmitted light is reflected too.
        return Split {
            indices: (n1, n2),
            fresnel: None,
            reflected: material.reflectance + transparency,
            refracted: None,
        };
    };
    let fresnel = if material.fresnel {
        // The cosine on the side of the smaller index: of the arriving ray
        // going into the denser medium, of the refracted ray coming out.
        let cos_in = -surface.normal.dot(d);
        let cos_out = -surface.normal.dot(direction);
        schlick(if n1 <= n2 { cos_in } else { cos_out }, n1, n2)
    } else {
        0.0
    };
    Split {
        indices: (n1, n2),
        fresnel: material.fresnel.then_some(fresnel),
        reflected: material.reflectance + transparency * fresnel,
        refracted: Some((transparency * (1.0 - fresnel), direction)),
    }
    // END EXERCISE
}

/// The refracted ray, started just off the surface on the far side (where
/// `direction` goes); none if its weight is zero, as for every secondary ray.
pub fn refracted_ray(surface: &Surface, direction: Vec3, weight: Color) -> Option<Secondary> {
    let far_side = offset_origin(&surface.hit, direction);
    let ray = Ray {
        origin: far_side,
        direction,
    };
    let kind = SecondaryKind::Refraction;
    (weight != Color::ZERO).then_some(Secondary { ray, weight, kind })
}

/// The secondary rays of a hit on a surface that may be transparent: an
/// opaque one sends chapter 5's mirror ray of its reflectance; a
/// transparent one [`split`]s the light between the mirror ray and the
/// refracted ray.
pub fn glass_secondary_rays(surface: &Surface, incoming: &Ray) -> [Option<Secondary>; 2] {
    if surface.material.transparency == 0.0 {
        return [
            mirror_ray(surface, incoming, surface.material.reflectance),
            None,
        ];
    }
    let split = split(surface, incoming);
    let refraction = split
        .refracted
        .and_then(|(weight, direction)| refracted_ray(surface, direction, weight));
    [mirror_ray(surface, incoming, split.reflected), refraction]
}

/// This chapter's tracer: mirrors and transparent materials, with chapter
/// 5's fixed depth.
#[derive(Debug, Clone, Copy)]
pub struct Glass {
    pub mirrors: Mirrors,
}

impl Whitted for Glass {
    fn secondary_rays(&self, surface: &Surface, incoming: &Ray) -> [Option<Secondary>; 2] {
        glass_secondary_rays(surface, incoming)
    }

    fn may_trace(&self, depth: u32, weight: Color, stats: &mut Stats) -> bool {
        self.mirrors.may_trace(depth, weight, stats)
    }
}

/// Chapter 6's picture.
pub fn render_glass(scene: &Scene, on_row: impl Fn() + Sync) -> (Image, Stats) {
    let tracer = Glass {
        mirrors: Mirrors {
            max_depth: scene.trace.max_depth,
        },
    };
    render_whitted(&tracer, scene, &scene.objects[..], on_row)
}

/// This chapter, for the command line (the rest is in chapters/chapters.toml).
pub const CHAPTER: workbench::cli::Chapter = workbench::cli::Chapter {
    package: env!("CARGO_PKG_NAME"),
    default_scene: include_str!("../scenes/default.toml"),
};
