//! `--pixel X,Y --json`: the ray tree at glass, walked as JSON.

use std::process::Command;

use serde_json::Value;

/// The short tree, its folds, `--full` and the picture (`--svg`).
mod short;

/// The tree the chapter binary prints for `args`.
fn tree(args: &[&str]) -> Value {
    let output = Command::new(env!("CARGO_BIN_EXE_ch06-refraction"))
        .args(args)
        .arg("--json")
        .output()
        .unwrap();
    let stderr = String::from_utf8_lossy(&output.stderr);
    assert!(output.status.success(), "{stderr}");
    serde_json::from_slice(&output.stdout).unwrap()
}

/// A colour of the tree.
fn rgb(value: &Value) -> [f64; 3] {
    let c: Vec<f64> = value
        .as_array()
        .unwrap()
        .iter()
        .map(|v| v.as_f64().unwrap())
        .collect();
    [c[0], c[1], c[2]]
}

fn close(a: f64, b: f64) -> bool {
    (a - b).abs() < 1e-5
}

/// Every ray of the tree, depth first.
fn rays(node: &Value) -> Vec<&Value> {
    let mut all = vec![node];
    for next in node["secondary"].as_array().unwrap() {
        all.extend(rays(next));
    }
    all
}

#[test]
fn a_glass_pixel_splits_into_reflection_and_refraction_by_fresnel() {
    // Pixel (160, 110) of the default scene looks at the glass sphere, head on.
    let tree = tree(&["--pixel", "160,110"]);
    let primary = &tree["primary"];
    assert_eq!(primary["hit"]["material"], "glass");
    assert_eq!(primary["hit"]["side"], "front");
    let split = &primary["refraction"];
    assert_eq!(split["entering"], true);
    assert_eq!(
        (split["n1"].as_f64(), split["n2"].as_f64()),
        (Some(1.0), Some(1.5))
    );
    assert_eq!(split["total_internal_reflection"], false);
    // Nearly head on, Schlick's R is close to R₀ = ((1 − 1.5) / 2.5)² = 0.04.
    let r = split["fresnel"].as_f64().unwrap();
    assert!((0.04..0.045).contains(&r), "R = {r}");
    let kinds: Vec<&Value> = primary["secondary"].as_array().unwrap().iter().collect();
    assert_eq!(kinds.len(), 2);
    let (mirror, refracted) = (kinds[0], kinds[1]);
    assert_eq!(mirror["kind"], "reflection");
    assert_eq!(refracted["kind"], "refraction");
    let (t, reflectance) = (0.95, 0.02);
    let (wm, wr) = (rgb(&mirror["weight"])[0], rgb(&refracted["weight"])[0]);
    assert!(close(wm, reflectance + t * r), "mirror weight {wm}");
    assert!(close(wr, t * (1.0 - r)), "refracted weight {wr}");
    assert_eq!(rgb(&split["reflected_weight"]), rgb(&mirror["weight"]));
    // The refracted ray meets the sphere again from inside, leaving it.
    assert_eq!(refracted["hit"]["object"], 0);
    assert_eq!(refracted["hit"]["side"], "back");
    assert_eq!(refracted["refraction"]["entering"], false);
    assert_eq!(refracted["depth"], 1);
}

#[test]
fn a_glass_pixel_brings_back_local_plus_weighted_secondary_colours() {
    let tree = tree(&["--pixel", "160,110"]);
    for ray in rays(&tree["primary"]) {
        if ray["traced"] == false || ray["hit"].is_null() {
            continue;
        }
        let mut sum = rgb(&ray["local"]);
        for next in ray["secondary"].as_array().unwrap() {
            if next["traced"] == true {
                let (w, c) = (rgb(&next["weight"]), rgb(&next["color"]));
                (0..3).for_each(|i| sum[i] += w[i] * c[i]);
            }
        }
        let color = rgb(&ray["color"]);
        assert!(
            (0..3).all(|i| close(sum[i], color[i])),
            "{sum:?} ≠ {color:?}"
        );
    }
}

/// Inside a large glass sphere, looking along its wall: every ray meets the
/// surface from inside at 72° from the normal, beyond the critical angle
/// (41.8° for ior 1.5).
const INSIDE_GLASS: &str = r#"
[camera]
eye = [0.0, 0.0, 9.5]
look_at = [1.0, 0.0, 9.5]
up = [0.0, 1.0, 0.0]
vfov = 30.0

[image]
width = 5
height = 5

[trace]
max_depth = 3

[materials.glass]
color = [0.0, 0.0, 0.0]
transparency = 0.9
reflectance = [0.05, 0.05, 0.05]
ior = 1.5
fresnel = true

[[lights]]
type = "ambient"
color = [0.1, 0.1, 0.1]

[[objects]]
type = "sphere"
center = [0.0, 0.0, 0.0]
radius = 10.0
material = "glass"
"#;

#[test]
fn total_internal_reflection_sends_all_the_light_to_the_mirror_ray() {
    let dir = tempfile::tempdir().unwrap();
    let scene = dir.path().join("inside.toml");
    std::fs::write(&scene, INSIDE_GLASS).unwrap();
    let tree = tree(&[scene.to_str().unwrap(), "--pixel", "2,2"]);
    let primary = &tree["primary"];
    assert_eq!(primary["hit"]["side"], "back");
    let split = &primary["refraction"];
    assert_eq!(split["entering"], false);
    assert_eq!(split["total_internal_reflection"], true);
    assert!(split["sin2_theta2"].as_f64().unwrap() > 1.0);
    assert!(split["refracted_weight"].is_null());
    let secondary = primary["secondary"].as_array().unwrap();
    assert_eq!(secondary.len(), 1, "no refracted ray");
    assert_eq!(secondary[0]["kind"], "reflection");
    assert!(close(rgb(&secondary[0]["weight"])[0], 0.05 + 0.9));
    // It reflects around the wall until the depth runs out.
    let last = rays(primary).into_iter().last().unwrap();
    assert_eq!(last["traced"], false);
    assert_eq!(last["end"], "max_depth");
    assert_eq!(last["depth"], 4);
}
