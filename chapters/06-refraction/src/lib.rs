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

/// Splits the light of a ray arriving at `surface` between reflection and
/// refraction.
///
/// 1. Entering or leaving: the sign of d·n with the surface's *outward*
///    normal `surface.hit.normal`. d·n < 0: the ray comes from outside, from
///    index n₁ = 1 into n₂ = the material's `ior`; otherwise it leaves, from
///    n₁ = `ior` into n₂ = 1. (A material's `ior` is relative to what
///    surrounds the object: an air bubble inside glass has ior 1/1.5.)
/// 2. The refracted direction by Snell's law with η = n₁/n₂ and the normal
///    on the side the ray comes from, `surface.normal` (chapter 3 turned it
///    to face the ray already).
/// 3. No refracted direction (total internal reflection): the transmitted
///    weight goes to the mirror ray, which gets reflectance + transparency.
/// 4. Otherwise the transmitted weight T is shared: R = Schlick's Fresnel
///    term if the material asks for it (else 0), with cos θ taken on the side
///    of the smaller index; the mirror ray gets reflectance + T·R and the
///    refracted ray T·(1 − R). So the two shares add up to T.
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
