//! The light maps beside the references are current (and rewritten with
//! `RAYBOOK_WRITE_LIGHT_MAPS=1`), and verify names the light of a region
//! that no usual mistake explains.

use ch03_lambert::toolkit::scene::Light;
use ch03_lambert::{Arrival, Surface, arrival, closest_hit, lambert, spot_factor};
use workbook::toolkit::Color;
use workbook::verify::{Diagnosis, LightMap, Reference, references};
use workbook::workbench::ray_tree::{RayNode, light_kind};
use workbook::workbench::snapshot::workspace_root;

use super::chapters::{assert_known_arguments, chapter, default_scene, tree};
use super::{chapter3_scene, diagnosis, named};

/// The lights that add a non-zero contribution to the colour of the ray
/// `node` brings back (path weight × what the light adds, at its hit and
/// every hit after it), ambient light aside: `lit[i]` for light i.
fn lighting(node: &RayNode, kinds: &[&str], lit: &mut [bool]) {
    for light in &node.lights {
        let contribution = (0..3).map(|c| node.path_weight[c] * light.adds[c]);
        if kinds[light.light] != "ambient" && contribution.into_iter().any(|v| v > 0.0) {
            lit[light.light] = true;
        }
    }
    for ray in &node.secondary {
        lighting(ray, kinds, lit);
    }
}

/// The light map of a reference, from its chapter's ray tree of every
/// pixel as the reference is rendered (160×120, one ray through each
/// pixel's centre); None if the chapter's tracer does not light.
fn light_map(reference: &Reference) -> Option<LightMap> {
    let (chapter, explain) = chapter(&reference.chapter.folder);
    assert_known_arguments(reference.chapter);
    let (scene, name) = default_scene(&chapter, Some((160, 120)));
    assert!(
        scene.image.samples <= 1,
        "a reference has one ray per pixel"
    );
    if !tree(&chapter, explain, &scene, &name, 0, 0).tracer.lights {
        return None;
    }
    let kinds: Vec<&str> = scene.lights.iter().map(light_kind).collect();
    let lit = |x: u32, y: u32| -> Vec<usize> {
        let mut lit = vec![false; kinds.len()];
        lighting(
            &tree(&chapter, explain, &scene, &name, x, y).primary,
            &kinds,
            &mut lit,
        );
        (0..lit.len()).filter(|&i| lit[i]).collect()
    };
    let rows = |ys: std::ops::Range<u32>| -> Vec<Vec<usize>> {
        ys.flat_map(|y| (0..160).map(move |x| (x, y)))
            .map(|(x, y)| lit(x, y))
            .collect()
    };
    // Two threads, a half of the picture each.
    let pixels = std::thread::scope(|s| {
        let top = s.spawn(|| rows(0..60));
        let bottom = rows(60..120);
        [top.join().unwrap(), bottom].concat()
    });
    Some(LightMap {
        width: 160,
        height: 120,
        lights: kinds.iter().map(|k| k.to_string()).collect(),
        pixels,
    })
}

#[test]
fn light_maps_are_current() {
    let write = std::env::var_os("RAYBOOK_WRITE_LIGHT_MAPS").is_some();
    let mut stale = Vec::new();
    for reference in references() {
        let name = reference.lights_path();
        let path = workspace_root().join("snapshots").join(&name);
        let Some(map) = light_map(&reference) else {
            assert!(
                !path.exists(),
                "{name}: the chapter's tracer lights nothing"
            );
            assert!(
                reference.lights.is_none(),
                "{name} is built in: rebuild the workbook"
            );
            continue;
        };
        let picture = reference
            .objects_path()
            .replace(".objects.txt", ".snap.png");
        let picture = picture.rsplit('/').next().unwrap();
        let text = map.to_text(picture);
        assert_eq!(LightMap::parse(&text).unwrap(), map);
        if write {
            std::fs::write(&path, &text).unwrap();
        } else if std::fs::read_to_string(&path).ok().as_deref() != Some(&text) {
            stale.push(path);
        } else {
            assert_eq!(
                reference.lights,
                Some(text.as_str()),
                "the workbook binary embeds an older {name}: rebuild it (touch crates/workbook/src/verify/mod.rs)"
            );
        }
    }
    assert!(
        stale.is_empty(),
        "stale or missing light maps {stale:?}; regenerate them with\n  \
         RAYBOOK_WRITE_LIGHT_MAPS=1 cargo test -p workbook --test verify light_maps"
    );
}

/// The spot light's cone with a linear ramp from its outer edge to its
/// inner one, on the cosine, instead of the chapter's smooth step.
fn linear_ramp(
    axis: workbook::toolkit::Vec3,
    inner: f32,
    outer: f32,
    ray: workbook::toolkit::Vec3,
) -> f32 {
    let (cos_inner, cos_outer) = (inner.to_radians().cos(), outer.to_radians().cos());
    ((axis.dot(ray) - cos_outer) / (cos_inner - cos_outer)).clamp(0.0, 1.0)
}

#[test]
fn a_wrong_spot_ramp_names_the_spot_light() {
    let scene = chapter3_scene();
    let shade = |ray: &ch03_lambert::Ray| -> Color {
        let Some(hit) = closest_hit(&scene.objects, ray, 0.0, f32::INFINITY) else {
            return scene.image.background;
        };
        let surface = Surface::new(&scene, hit, ray);
        let mut color = Color::ZERO;
        for light in &scene.lights {
            match arrival(light, surface.hit.point) {
                Arrival::Ambient(ambient) => color += surface.material.color * ambient,
                Arrival::Incoming(mut incoming) => {
                    if let Light::Spot {
                        direction,
                        inner_degrees,
                        outer_degrees,
                        ..
                    } = *light
                    {
                        let ray = -incoming.direction;
                        let smooth = spot_factor(direction, inner_degrees, outer_degrees, ray);
                        let linear = linear_ramp(direction, inner_degrees, outer_degrees, ray);
                        incoming.irradiance *= linear / smooth;
                    }
                    color += lambert(&surface, &incoming);
                }
                Arrival::Dark => {}
            }
        }
        color
    };
    let (picture, _) = ch03_lambert::render(&scene, |ray, _| shade(ray), || {});
    let diagnosis = diagnosis("3", &picture.to_rgb8(), "linear-spot.png");
    assert_eq!(named(&diagnosis), None, "{diagnosis}");
    let Diagnosis::Differs(region) = &diagnosis else {
        unreachable!()
    };
    let lit = region.lit.as_ref().expect("chapter 3 has a light map");
    assert_eq!(
        (lit[0].light, lit[0].kind.as_str()),
        (2, "spot"),
        "{diagnosis}"
    );
    assert!(lit[0].share > 0.8, "{diagnosis}");
    let text = diagnosis.to_string();
    assert!(text.contains("it is lit by light 2 (spot) in "), "{text}");
}
