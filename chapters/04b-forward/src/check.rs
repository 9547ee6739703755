//! Which scenes the forward tracer can render so that they converge to
//! chapter 4's picture.

use ch04_shadows::toolkit::scene::{Falloff, Light};
use ch04_shadows::toolkit::{Color, Scene};

/// Can the forward tracer render this scene so that it converges to chapter
/// 4's picture? It needs what both tracers agree on: point lights only (no
/// ambient light, which comes from nowhere; no spot light), every light and
/// object casting shadows, and a black background (a photon that hits
/// nothing is lost; it never paints the sky). Both see every material as
/// diffuse with its albedo `color`. The error names what is in the way.
pub fn check_scene(scene: &Scene) -> Result<(), String> {
    let mut problems = Vec::new();
    for (i, light) in scene.lights.iter().enumerate() {
        match light {
            Light::Point {
                falloff: Falloff::None,
                ..
            } => problems.push(format!(
                "lights[{i}] has falloff = \"none\": photons spread out, so their light falls off with 1/r²"
            )),
            Light::Point { shadows: true, .. } => {}
            Light::Point { .. } => problems.push(format!(
                "lights[{i}] has shadows = false: its light would pass through objects"
            )),
            Light::Ambient { .. } => problems.push(format!(
                "lights[{i}] is ambient light: it comes from nowhere, so no photon carries it"
            )),
            _ => problems.push(format!(
                "lights[{i}] is not a point light: only point lights emit photons here"
            )),
        }
    }
    for (i, object) in scene.objects.iter().enumerate() {
        if !object.shadows {
            problems.push(format!(
                "objects[{i}] has shadows = false: photons cannot pass through it"
            ));
        }
    }
    if scene.image.background != Color::ZERO {
        problems.push(format!(
            "the background is {}, not black: no photon paints the sky",
            scene.image.background
        ));
    }
    if problems.is_empty() {
        Ok(())
    } else {
        Err(problems.join("\n"))
    }
}
