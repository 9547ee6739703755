//! The ray tree as indented text, for people: one block per ray, its
//! secondary rays indented below it. The full tree shows every ray and
//! every detail; the short tree (the default of `--pixel`) shows the
//! secondary rays in brief and folds the rays that matter little to the
//! pixel (`fold.rs`), each group into one line.

use std::fmt::Write;

use super::fold::{Fold, Folded};
use super::words::{num, step, vec3};
use super::*;

/// How much the text shows.
#[derive(Debug, Clone, Copy)]
struct View {
    fold: Fold,
    /// Secondary rays in brief: their hit, lights, split and colour, one
    /// line each (the primary ray is always shown in full).
    brief: bool,
}

impl View {
    const FULL: View = View {
        fold: Fold::NONE,
        brief: false,
    };
}

impl RayTree {
    /// The full tree as indented text: every ray, one block per ray and its hit.
    pub fn to_text(&self) -> String {
        self.text(View::FULL)
    }

    /// The short tree: the primary ray in full, the secondary rays in
    /// brief, and the rays that `fold` folds as one line per group.
    pub fn to_short_text(&self, fold: Fold) -> String {
        self.text(View { fold, brief: true })
    }

    fn text(&self, view: View) -> String {
        let mut out = String::new();
        let [x, y] = self.pixel;
        let [w, h] = self.image;
        let _ = writeln!(
            out,
            "ray tree of pixel ({x}, {y}) in {w}×{h}, chapter {}, {}: one ray through the pixel's centre (the scene's samples = {} are ignored here)",
            self.chapter, self.scene, self.samples
        );
        let _ = writeln!(out, "{}", self.tracer.describe());
        if view.brief && !self.primary.secondary.is_empty() {
            let _ = writeln!(
                out,
                "short tree: secondary rays in brief; rays {} folded (--full shows every ray in full)",
                view.fold.describe()
            );
        }
        write_ray(&mut out, &self.primary, &self.tracer, "eye", &view);
        out
    }
}

impl TracerInfo {
    /// One line saying what this chapter traces.
    fn describe(&self) -> String {
        let mut parts = vec![if self.hits {
            "closest hit"
        } else {
            "no objects (the sky only)"
        }];
        if self.lights {
            parts.push("lights");
        }
        if self.shadow_rays {
            parts.push("shadow rays");
        }
        let mut line = format!("this chapter traces: {}", parts.join(", "));
        if let Some(depth) = self.max_depth {
            let _ = write!(line, ", secondary rays up to max_depth = {depth} bounces");
        }
        if let Some(w) = self.min_weight {
            let _ = write!(line, ", paths ended below min_weight = {}", num(w));
        }
        line
    }
}

/// Writes one ray's block and, indented below it, its secondary rays.
/// `path` names the ray by the bounces that lead to it from the eye
/// (R a reflection, T a refraction), so that a reader knows where in a
/// deep tree a block is.
fn write_ray(out: &mut String, ray: &RayNode, tracer: &TracerInfo, path: &str, view: &View) {
    let pad = "  ".repeat(ray.depth as usize);
    let brief = view.brief && ray.kind != RayKind::Primary;
    write_head(out, ray, path, &pad);
    if !ray.traced {
        let why = ray.end.map_or("", end_text);
        let _ = writeln!(out, "{pad}  not traced: {why}");
        return;
    }
    match (&ray.hit, ray.color) {
        (None, Some(color)) if brief && tracer.hits => {
            let _ = writeln!(
                out,
                "{pad}  hits nothing: brings back the background {}; path ended (no hit)",
                vec3(color)
            );
            return;
        }
        (None, _) if !tracer.hits => {
            let _ = writeln!(out, "{pad}  hits nothing (this chapter has no objects yet)");
        }
        (None, _) => {
            let _ = writeln!(
                out,
                "{pad}  hits nothing: sees the background; path ended (no hit)"
            );
        }
        (Some(hit), _) => write_hit(out, hit, &pad, brief),
    }
    if brief {
        write_lights_briefly(out, ray, &pad);
    } else {
        write_lights(out, ray, tracer, &pad);
    }
    if let Some(split) = &ray.refraction {
        write_refraction(out, split, &pad, brief);
    }
    if ray.end == Some(End::NoSecondaryRays) {
        let _ = writeln!(
            out,
            "{pad}  no secondary rays (neither mirror nor transparent): path ended"
        );
    }
    write_secondary(out, ray, tracer, path, view);
    write_color(out, ray, &format!("{} ({path})", kind_name(ray.kind)), &pad);
}

/// A ray's first two lines: which ray, its weights, where it starts and goes.
fn write_head(out: &mut String, ray: &RayNode, path: &str, pad: &str) {
    let mut head = format!("{pad}{} (depth {}: {path})", kind_name(ray.kind), ray.depth);
    if ray.kind != RayKind::Primary {
        let _ = write!(
            head,
            ", weight {}, path weight {}",
            vec3(ray.weight),
            vec3(ray.path_weight)
        );
    }
    let _ = writeln!(out, "{head}");
    let _ = writeln!(
        out,
        "{pad}  from {} along {}",
        vec3(ray.origin),
        vec3(ray.direction)
    );
}

/// The secondary rays of `ray`, each as its block, except those the view
/// folds: one line for all of them, where the first of them would be.
fn write_secondary(out: &mut String, ray: &RayNode, tracer: &TracerInfo, path: &str, view: &View) {
    let mut folded = Folded::below(ray, &view.fold);
    for next in &ray.secondary {
        let next_path = format!("{path} → {}", step(next.kind));
        if !view.fold.folds(next) {
            write_ray(out, next, tracer, &next_path, view);
        } else if let Some(group) = folded.take() {
            let pad = "  ".repeat(next.depth as usize);
            let _ = writeln!(out, "{pad}{}", group.line(path));
        }
    }
}

/// A ray's kind, as its block names it.
fn kind_name(kind: RayKind) -> &'static str {
    match kind {
        RayKind::Primary => "primary ray",
        RayKind::Reflection => "reflection ray",
        RayKind::Refraction => "refraction ray",
    }
}

/// The last line of a ray's block: what it brings back, and how.
/// `name` is the ray's kind and path, as its first line gives them.
fn write_color(out: &mut String, ray: &RayNode, name: &str, pad: &str) {
    let Some(color) = ray.color else { return };
    let what = if ray.kind == RayKind::Primary {
        format!("{name} brings back the pixel's colour")
    } else {
        format!("{name} brings back")
    };
    let sum = if ray.secondary.iter().any(|r| r.traced) {
        " = local + Σ weight × what each secondary ray brings back"
    } else {
        ""
    };
    let _ = writeln!(out, "{pad}  {what}: {}{sum}", vec3(color));
}

/// Why a path ended, in words.
fn end_text(end: End) -> &'static str {
    match end {
        End::NoHit => "path ended (no hit)",
        End::MaxDepth => "path ended (maximum depth: one bounce more than max_depth)",
        End::WeightThreshold => {
            "path ended (weight threshold: the path weight is below min_weight)"
        }
        End::NoSecondaryRays => "path ended (no secondary rays)",
        End::NotTraced => "the tracer did not follow it",
    }
}

/// The hit: which object, where, which way the surface faces (in brief:
/// the first line only).
fn write_hit(out: &mut String, hit: &HitNode, pad: &str, brief: bool) {
    let side = match hit.side {
        Side::Front => "front side (d·n < 0)",
        Side::Back => "back side (d·n > 0)",
    };
    let _ = writeln!(
        out,
        "{pad}  hit object {} ({}, material {}) at t = {}, {side}",
        hit.object,
        hit.shape,
        hit.material,
        num(hit.t)
    );
    if brief {
        return;
    }
    if let Some([t0, t1]) = hit.roots {
        let _ = writeln!(
            out,
            "{pad}    the quadratic's roots: t₀ = {}, t₁ = {} (nearest first){}",
            num(t0),
            num(t1),
            if t0 <= hit.t / 1000.0 {
                "; t₀ is at or behind the ray's origin, which is on or inside the sphere"
            } else {
                ""
            }
        );
    }
    let _ = writeln!(
        out,
        "{pad}    point {}, normal {}, facing normal {}",
        vec3(hit.point),
        vec3(hit.normal),
        vec3(hit.facing_normal)
    );
}

/// Each light's lines and the hit's local light.
fn write_lights(out: &mut String, ray: &RayNode, tracer: &TracerInfo, pad: &str) {
    for light in &ray.lights {
        write_light(out, light, tracer, pad);
    }
    if let Some(local) = ray.local {
        let _ = writeln!(
            out,
            "{pad}  local light (sum of the lights): {}",
            vec3(local)
        );
    }
}

/// The lights in brief, on one line: what each does, and their sum.
fn write_lights_briefly(out: &mut String, ray: &RayNode, pad: &str) {
    let Some(local) = ray.local else { return };
    let lights: Vec<String> = ray.lights.iter().map(light_briefly).collect();
    let _ = writeln!(
        out,
        "{pad}  lights: {} → local light {}",
        lights.join("; "),
        vec3(local)
    );
}

/// One light in brief: whether it reaches the point, and what it adds.
fn light_briefly(light: &LightNode) -> String {
    let name = format!("{} ({})", light.light, light.kind);
    let adds = vec3(light.adds);
    match light.status {
        LightStatus::Ambient => format!("{name} adds {adds}"),
        LightStatus::Dark => format!("{name} dark here"),
        LightStatus::Behind => format!("{name} behind the surface"),
        LightStatus::AddsNothing => format!("{name} adds nothing"),
        LightStatus::Free => format!("{name} free, adds {adds}"),
        LightStatus::Blocked => {
            let by = light
                .shadow_ray
                .as_ref()
                .and_then(|s| s.blocked_by.as_ref());
            match by {
                Some(o) => format!("{name} blocked by object {}", o.object),
                None => format!("{name} blocked"),
            }
        }
    }
}

/// One light: where it is, whether it is blocked, what it adds.
fn write_light(out: &mut String, light: &LightNode, tracer: &TracerInfo, pad: &str) {
    let name = format!("light {} ({})", light.light, light.kind);
    let cos = light
        .n_dot_l
        .map_or(String::new(), |c| format!("n·l = {}, ", num(c)));
    let status = match light.status {
        LightStatus::Ambient => {
            let _ = writeln!(
                out,
                "{pad}  {name}: albedo × its colour adds {}",
                vec3(light.adds)
            );
            return;
        }
        LightStatus::Dark => "dark here (outside its cone)".to_string(),
        LightStatus::Behind => "behind the surface: adds nothing, no shadow ray".to_string(),
        LightStatus::AddsNothing => "would add nothing: no shadow ray".to_string(),
        LightStatus::Free | LightStatus::Blocked => shadow_text(light, tracer),
    };
    let _ = writeln!(out, "{pad}  {name}: {cos}{status}");
    if matches!(light.status, LightStatus::Dark | LightStatus::Behind) {
        return; // it adds nothing, as the line says
    }
    let terms = match (light.lambert, light.highlight) {
        (Some(l), Some(h)) => format!("lambert {} + highlight {} → ", vec3(l), vec3(h)),
        (Some(l), None) => format!("lambert {} → ", vec3(l)),
        _ => String::new(),
    };
    let _ = writeln!(out, "{pad}    {terms}adds {}", vec3(light.adds));
}

/// Free or blocked, and by what: the shadow ray's verdict.
fn shadow_text(light: &LightNode, tracer: &TracerInfo) -> String {
    let Some(shadow) = &light.shadow_ray else {
        return if !tracer.shadow_rays {
            "free (this chapter traces no shadow rays)".into()
        } else if light.casts_shadows == Some(false) {
            "free (the light casts no shadows: no shadow ray)".into()
        } else {
            "free (no shadow ray traced)".into()
        };
    };
    let ray = format!(
        "shadow ray from {} along {} up to t = {}",
        vec3(shadow.origin),
        vec3(shadow.direction),
        num(shadow.t_max)
    );
    match (&shadow.blocked_by, shadow.blocker_t) {
        (Some(o), Some(t)) => format!(
            "{ray}: blocked by object {} ({}) at t = {}",
            o.object,
            o.shape,
            num(t)
        ),
        _ if shadow.blocked => format!("{ray}: blocked"),
        _ => format!("{ray}: free"),
    }
}

/// How a transparent surface splits the light: Snell, TIR, Fresnel (in
/// brief: the indices and the split, on one line).
fn write_refraction(out: &mut String, r: &RefractionNode, pad: &str, brief: bool) {
    let way = if r.entering { "entering" } else { "leaving" };
    if brief {
        let _ = writeln!(
            out,
            "{pad}  transparent, {way} the object (n₁ = {} → n₂ = {}): {}",
            num(r.n1),
            num(r.n2),
            share_text(r)
        );
        return;
    }
    let _ = writeln!(
        out,
        "{pad}  transparent: {way} the object, n₁ = {} → n₂ = {}, η = {}, cos θ₁ = {}, sin²θ₂ = η²(1 − cos²θ₁) = {}",
        num(r.n1),
        num(r.n2),
        num(r.eta),
        num(r.cos_theta1),
        num(r.sin2_theta2)
    );
    let _ = writeln!(out, "{pad}    {}", share_text(r));
}

/// How the light is shared between the mirror ray and the refracted ray.
fn share_text(r: &RefractionNode) -> String {
    if r.total_internal_reflection {
        return format!(
            "total internal reflection (sin²θ₂ > 1): no refracted ray; the mirror ray gets reflectance + T = {}",
            vec3(r.reflected_weight)
        );
    }
    let fresnel = r.fresnel.map_or("no Fresnel term, R = 0".to_string(), |f| {
        format!("Schlick's R = {}", num(f))
    });
    let refracted = r.refracted_weight.map_or([0.0; 3], |w| w);
    format!(
        "T = {}, {fresnel}: mirror ray reflectance + T·R = {}, refracted ray T·(1 − R) = {}",
        num(r.transparency),
        vec3(r.reflected_weight),
        vec3(refracted)
    )
}
