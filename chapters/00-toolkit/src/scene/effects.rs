//! Effects: what a scene calls for, what a chapter can simulate.
//!
//! Every effect is introduced by one chapter. A scene *calls for* an effect
//! when something in it needs it; a tracer simulates the effects that are
//! called for, switched on and known to its chapter, and nothing else.

use std::fmt;

use super::{Effect, Falloff, Light, Scene};

impl Effect {
    /// Every effect, in the order the chapters introduce them.
    pub const ALL: [Effect; 5] = [
        Effect::Lambert,
        Effect::Spot,
        Effect::Shadows,
        Effect::Reflection,
        Effect::Refraction,
    ];

    /// The effect's name in scene files and on the command line.
    pub fn name(self) -> &'static str {
        match self {
            Effect::Lambert => "lambert",
            Effect::Spot => "spot",
            Effect::Shadows => "shadows",
            Effect::Reflection => "reflection",
            Effect::Refraction => "refraction",
        }
    }
}

impl fmt::Display for Effect {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(self.name())
    }
}

/// A set of effects.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub struct Effects(u8);

impl Effects {
    pub const NONE: Effects = Effects(0);
    pub const ALL: Effects = Effects(0b1_1111);

    /// Each effect's bit, in the order the enum lists them.
    const fn bit(effect: Effect) -> u8 {
        1 << effect as u8
    }

    /// The set of the given effects.
    pub fn of(effects: &[Effect]) -> Effects {
        effects.iter().fold(Effects::NONE, |set, &e| set.with(e))
    }

    pub const fn with(self, effect: Effect) -> Effects {
        Effects(self.0 | Effects::bit(effect))
    }

    pub fn contains(self, effect: Effect) -> bool {
        self.0 & Effects::bit(effect) != 0
    }

    /// The effects in both sets.
    pub fn and(self, other: Effects) -> Effects {
        Effects(self.0 & other.0)
    }

    /// The effects of this set that are not in `other`.
    pub fn minus(self, other: Effects) -> Effects {
        Effects(self.0 & !other.0)
    }

    pub fn is_empty(self) -> bool {
        self.0 == 0
    }

    /// The effects in the set, in chapter order.
    pub fn iter(self) -> impl Iterator<Item = Effect> {
        Effect::ALL.into_iter().filter(move |&e| self.contains(e))
    }
}

impl fmt::Display for Effects {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        if self.is_empty() {
            return f.write_str("none");
        }
        let names: Vec<&str> = self.iter().map(Effect::name).collect();
        f.write_str(&names.join(", "))
    }
}

impl Scene {
    /// The effects something in the scene needs:
    /// * lambert: a light meets a material with a diffuse colour;
    /// * spot: a spot light lights a material that answers direct light;
    /// * shadows: a light that casts shadows, an object that can block it,
    ///   and a material that answers direct light;
    /// * reflection: a material with a mirror reflectance, or a highlight lit
    ///   by a point or spot light;
    /// * refraction: a material that transmits light.
    ///
    /// Only materials that some object uses count. It is worked out once,
    /// before rendering.
    pub fn calls_for(&self) -> Effects {
        let used = |i: usize| self.objects.iter().any(|o| o.material == i);
        let materials: Vec<_> = (0..self.materials.len())
            .filter(|&i| used(i))
            .map(|i| &self.materials[i])
            .collect();
        let direct: Vec<&Light> = (self.lights.iter())
            .filter(|l| !matches!(l, Light::Ambient { .. }))
            .collect();
        let diffuse = materials.iter().any(|m| m.color != crate::Vec3::ZERO);
        let shiny = materials.iter().any(|m| m.specular > 0.0);
        let answers_direct = !direct.is_empty() && (diffuse || shiny);
        let casts = direct.iter().any(|l| match l {
            Light::Point { shadows, .. } | Light::Spot { shadows, .. } => *shadows,
            Light::Ambient { .. } => false,
        });
        let blocks = self.objects.iter().any(|o| o.shadows);
        let spot = direct.iter().any(|l| matches!(l, Light::Spot { .. }));
        let checks = [
            (Effect::Lambert, diffuse && !self.lights.is_empty()),
            (Effect::Spot, spot && answers_direct),
            (Effect::Shadows, casts && blocks && answers_direct),
            (
                Effect::Reflection,
                materials.iter().any(|m| m.reflectance != crate::Vec3::ZERO)
                    || (shiny && !direct.is_empty()),
            ),
            (
                Effect::Refraction,
                materials.iter().any(|m| m.transparency > 0.0),
            ),
        ];
        checks
            .into_iter()
            .filter(|&(_, called)| called)
            .fold(Effects::NONE, |set, (effect, _)| set.with(effect))
    }

    /// The effects switched on by the scene's `[trace] effects` (all if absent).
    pub fn switched_on(&self) -> Effects {
        self.trace
            .effects
            .as_deref()
            .map_or(Effects::ALL, Effects::of)
    }

    /// The same scene with `effects` switched off, by removing what calls for
    /// them. A tracer then spawns no ray for them, since it spawns none whose
    /// weight is zero:
    /// * lambert: no diffuse colour (ambient light is diffuse light too);
    /// * spot: spot lights shine all round, as point lights;
    /// * shadows: no light casts shadows (no shadow ray is traced);
    /// * reflection: no mirror reflectance, no highlights;
    /// * refraction: nothing transmits light.
    pub fn without(mut self, effects: Effects) -> Scene {
        for m in &mut self.materials {
            if effects.contains(Effect::Lambert) {
                m.color = crate::Vec3::ZERO;
            }
            if effects.contains(Effect::Reflection) {
                m.reflectance = crate::Vec3::ZERO;
                m.specular = 0.0;
            }
            if effects.contains(Effect::Refraction) {
                m.transparency = 0.0;
            }
        }
        for light in &mut self.lights {
            if let (
                true,
                Light::Spot {
                    position,
                    color,
                    intensity,
                    shadows,
                    ..
                },
            ) = (effects.contains(Effect::Spot), &light)
            {
                *light = Light::Point {
                    position: *position,
                    color: *color,
                    intensity: *intensity,
                    shadows: *shadows,
                    falloff: Falloff::InverseSquare,
                };
            }
            if let (true, Light::Point { shadows, .. } | Light::Spot { shadows, .. }) =
                (effects.contains(Effect::Shadows), light)
            {
                *shadows = false;
            }
        }
        self
    }
}
