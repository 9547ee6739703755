//! Folding a tree for people: the short text tree (`text.rs`) and the
//! picture (`svg.rs`) fold the rays that matter little to the pixel, each
//! group of them into one summary. Folding changes what is shown, never
//! what was traced: the JSON keeps every ray.

use super::words::{step, vec3};
use super::{RayKind, RayNode};

/// Which rays fold: those deeper than `depth` bounces, and those whose
/// path weight is below `weight`, each with every ray after it.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Fold {
    /// Rays with more bounces than this fold (the primary ray has 0).
    pub depth: u32,
    /// Rays whose path weight is below this in its largest channel fold.
    pub weight: f32,
}

impl Fold {
    /// The short tree's folds: rays deeper than 3 bounces, and rays that
    /// carry less than 1% of the pixel's light.
    pub const DEFAULT: Fold = Fold {
        depth: 3,
        weight: 0.01,
    };

    /// No fold at all: every ray is shown.
    pub const NONE: Fold = Fold {
        depth: u32::MAX,
        weight: 0.0,
    };

    /// Does `ray` fold? The primary ray's path weight is 1 in every
    /// channel, so a weight W is W of the pixel's (0.01 = 1%). A ray folds
    /// when its path weight is below W as the complete tracer compares a
    /// path weight with min_weight.
    pub fn folds(&self, ray: &RayNode) -> bool {
        ray.kind != RayKind::Primary && (self.too_deep(ray) || self.too_light(ray))
    }

    fn too_deep(&self, ray: &RayNode) -> bool {
        ray.depth > self.depth
    }

    fn too_light(&self, ray: &RayNode) -> bool {
        largest(ray.path_weight) < self.weight
    }

    /// Which rays fold, in words.
    pub fn describe(&self) -> String {
        self.reason(true, true)
    }

    /// Why rays of a group fold, in words.
    fn reason(&self, deep: bool, light: bool) -> String {
        let bounces = if self.depth == 1 { "bounce" } else { "bounces" };
        let deep_text = format!("deeper than {} {bounces}", self.depth);
        let light_text = format!("with a path weight below {}", super::num(self.weight));
        match (deep, light) {
            (true, true) => format!("{deep_text} or {light_text}"),
            (true, false) => deep_text,
            _ => light_text,
        }
    }
}

/// The largest channel of a weight or colour.
pub fn largest(v: [f32; 3]) -> f32 {
    v[0].max(v[1]).max(v[2])
}

/// A group of folded rays: the folded secondary rays of one shown ray
/// (its "tops"), with every ray after them.
#[derive(Debug, Clone, PartialEq)]
pub struct Folded<'a> {
    /// The folded secondary rays, in the order the tracer follows them.
    pub tops: Vec<&'a RayNode>,
    /// How many rays fold: the tops and every ray after them.
    pub rays: usize,
    /// How many of them were not traced (a termination criterion stopped them).
    pub not_traced: usize,
    /// What they bring back to the pixel: Σ over the tops of path weight ×
    /// the colour the top brings back (which holds all that follows it).
    pub brings: [f32; 3],
    /// Why they fold, in words.
    pub reason: String,
}

impl<'a> Folded<'a> {
    /// The group folded below `parent`, if any of its secondary rays folds.
    pub fn below(parent: &'a RayNode, fold: &Fold) -> Option<Folded<'a>> {
        let tops: Vec<&RayNode> = parent.secondary.iter().filter(|r| fold.folds(r)).collect();
        if tops.is_empty() {
            return None;
        }
        let deep = tops.iter().any(|r| fold.too_deep(r));
        let light = tops.iter().any(|r| fold.too_light(r));
        let mut brings = [0.0; 3];
        for top in &tops {
            let color = top.color.unwrap_or([0.0; 3]);
            (0..3).for_each(|i| brings[i] += top.path_weight[i] * color[i]);
        }
        Some(Folded {
            rays: tops.iter().map(|r| count_rays(r)).sum(),
            not_traced: tops.iter().map(|r| count_untraced(r)).sum(),
            brings,
            reason: fold.reason(deep, light),
            tops,
        })
    }
}

impl Folded<'_> {
    /// The group's line in the short tree: how many rays, why they fold,
    /// which (from `parent_path`, the path of the ray they leave), and
    /// what they bring back to the pixel.
    pub fn line(&self, parent_path: &str) -> String {
        let steps: Vec<&str> = self.tops.iter().map(|r| step(r.kind)).collect();
        let mut which = format!("{parent_path} → {}", steps.join(" and → "));
        let after = self.rays - self.tops.len();
        if after > 0 {
            let them = if self.tops.len() == 1 { "it" } else { "them" };
            which += &format!(" and the {after} after {them}");
        }
        let brings = match self.not_traced {
            n if n == self.rays => "; not traced: they add nothing to the pixel's colour".into(),
            n => format!(
                "{}; they add {} to the pixel's colour (path weight × colour brought back)",
                if n > 0 {
                    format!(", {n} of them not traced")
                } else {
                    String::new()
                },
                vec3(self.brings)
            ),
        };
        let rays = if self.rays == 1 { "ray" } else { "rays" };
        format!(
            "⋯ {} {rays} folded ({}): {which}{brings}",
            self.rays, self.reason
        )
    }
}

/// How many rays `ray` and every ray after it make.
pub fn count_rays(ray: &RayNode) -> usize {
    1 + ray.secondary.iter().map(count_rays).sum::<usize>()
}

/// How many of them were not traced.
fn count_untraced(ray: &RayNode) -> usize {
    usize::from(!ray.traced) + ray.secondary.iter().map(count_untraced).sum::<usize>()
}

#[cfg(test)]
mod tests {
    use super::*;
    use ch00_toolkit::Vec3;

    fn ray(kind: RayKind, depth: u32, path_weight: f32) -> RayNode {
        let mut ray = RayNode::new(kind, depth, Vec3::ZERO, Vec3::X);
        ray.path_weight = [path_weight, path_weight / 2.0, 0.0];
        ray.color = Some([1.0, 0.5, 0.0]);
        ray
    }

    #[test]
    fn rays_fold_below_the_weight_in_their_largest_channel_or_beyond_the_depth() {
        let fold = Fold::DEFAULT;
        assert!(!fold.folds(&ray(RayKind::Reflection, 3, 0.01)));
        assert!(fold.folds(&ray(RayKind::Reflection, 3, 0.0099)));
        assert!(fold.folds(&ray(RayKind::Refraction, 4, 1.0)));
        assert!(!fold.folds(&ray(RayKind::Primary, 0, 0.0)));
        assert!(!Fold::NONE.folds(&ray(RayKind::Reflection, 1000, 0.0)));
    }

    #[test]
    fn a_group_counts_every_ray_after_its_tops_and_what_they_bring_back() {
        let mut parent = ray(RayKind::Primary, 0, 1.0);
        let mut light = ray(RayKind::Reflection, 1, 0.005);
        let mut untraced = ray(RayKind::Reflection, 2, 0.001);
        untraced.traced = false;
        untraced.color = None;
        light.secondary = vec![untraced, ray(RayKind::Refraction, 2, 0.004)];
        parent.secondary = vec![light, ray(RayKind::Refraction, 1, 0.5)];
        let group = Folded::below(&parent, &Fold::DEFAULT).unwrap();
        assert_eq!((group.tops.len(), group.rays, group.not_traced), (1, 3, 1));
        // Only the top counts: its colour already holds what follows it.
        assert_eq!(group.brings, [0.005, 0.00125, 0.0]);
        assert_eq!(group.reason, "with a path weight below 0.01");
        assert_eq!(count_rays(&parent), 5);
        assert_eq!(
            group.line("eye"),
            "⋯ 3 rays folded (with a path weight below 0.01): eye → R and the 2 after it, \
             1 of them not traced; they add (0.005, 0.0012, 0) to the pixel's colour \
             (path weight × colour brought back)"
        );
    }
}
