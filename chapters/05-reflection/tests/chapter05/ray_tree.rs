//! `--pixel X,Y --json`: mirror rays, their weights, and the depth limit.

use std::process::Command;

use serde_json::{Value, json};

/// Two facing mirrors, z = −1 and z = 1, with the eye between them looking
/// at one: the mirror rays bounce back and forth until max_depth = 3.
/// Each mirror is grey (0.2, lit by an ambient light of 1) and reflects half.
const FACING_MIRRORS: &str = r#"
[camera]
eye = [0.0, 0.0, 0.0]
look_at = [0.0, 0.0, -1.0]
up = [0.0, 1.0, 0.0]
vfov = 30.0

[image]
width = 3
height = 3

[trace]
max_depth = 3

[materials.mirror]
color = [0.2, 0.2, 0.2]
reflectance = [0.5, 0.5, 0.5]

[[lights]]
type = "ambient"
color = [1.0, 1.0, 1.0]

[[objects]]
type = "plane"
normal = [0.0, 0.0, 1.0]
offset = 1.0
material = "mirror"

[[objects]]
type = "plane"
normal = [0.0, 0.0, -1.0]
offset = 1.0
material = "mirror"
"#;

fn tree() -> Value {
    tree_with(&[])
}

/// The tree of the facing mirrors' middle pixel, with `args` given too.
fn tree_with(args: &[&str]) -> Value {
    let dir = tempfile::tempdir().unwrap();
    let scene = dir.path().join("mirrors.toml");
    std::fs::write(&scene, FACING_MIRRORS).unwrap();
    let output = Command::new(env!("CARGO_BIN_EXE_ch05-reflection"))
        .arg(&scene)
        .args(["--pixel", "1,1", "--json"])
        .args(args)
        .output()
        .unwrap();
    assert!(
        output.status.success(),
        "{}",
        String::from_utf8_lossy(&output.stderr)
    );
    serde_json::from_slice(&output.stdout).unwrap()
}

fn first(c: &Value) -> f64 {
    c[0].as_f64().unwrap()
}

/// The object `ray` hits; between the facing mirrors every ray hits one,
/// and a mirror ray that hits nothing was sent the wrong way.
#[track_caller]
fn hit_object(ray: &Value) -> u64 {
    match ray["hit"]["object"].as_u64() {
        Some(object) => object,
        None => panic!("{}", missed(ray)),
    }
}

/// Why a ray between the facing mirrors hit nothing: the mirror ray at
/// depth 1 goes from (0, 0, −1) straight back, along +z.
fn missed(ray: &Value) -> String {
    format!(
        "the ray at depth {} leaves {} along {} and hits nothing; between two facing mirrors \
         every mirror ray hits the other mirror (here straight back, along (0, 0, 1)): does \
         reflect reverse the part of d along n and keep the rest, d − 2(d·n)n?",
        ray["depth"], ray["origin"], ray["direction"]
    )
}

#[test]
fn mirror_rays_bounce_with_multiplying_weights_until_the_maximum_depth() {
    let tree = tree();
    assert_eq!(tree["tracer"]["max_depth"], 3);
    let mut ray = &tree["primary"];
    let mut objects = Vec::new();
    for depth in 1..=4 {
        objects.push(hit_object(ray));
        let secondary = ray["secondary"].as_array().unwrap();
        assert_eq!(secondary.len(), 1, "one mirror ray at depth {depth}");
        ray = &secondary[0];
        assert_eq!(ray["kind"], "reflection");
        assert_eq!(ray["depth"], depth);
        assert_eq!(ray["weight"], json!([0.5, 0.5, 0.5]));
        assert!((first(&ray["path_weight"]) - 0.5f64.powi(depth)).abs() < 1e-6);
    }
    assert_eq!(objects, [0, 1, 0, 1], "back and forth between the mirrors");
    assert_eq!(ray["traced"], false);
    assert_eq!(ray["end"], "max_depth");
    assert!(ray["color"].is_null());
}

#[test]
fn each_ray_brings_back_its_local_light_plus_half_the_next() {
    let tree = tree();
    // 0.2 at depth 3; 0.2 + 0.5 · 0.2 = 0.3 at depth 2; 0.35; 0.375.
    // Weighted by the path's weight 0.5^(depth + 1) instead of the ray's own
    // 0.5: 0.2 + 0.125 · 0.2 = 0.225 at depth 2; 0.25625; 0.328125.
    let mut ray = &tree["primary"];
    for (depth, expected, by_path) in [
        (0, 0.375, 0.328125),
        (1, 0.35, 0.25625),
        (2, 0.3, 0.225),
        (3, 0.2, 0.2),
    ] {
        let found = first(&ray["color"]);
        let next = &ray["secondary"][0];
        let hint = if depth < 3 && next["traced"] == true && next["hit"].is_null() {
            format!(" ({})", missed(next))
        } else if (found - by_path).abs() < 1e-5 {
            " (that is each mirror ray weighted by its path's weight, 0.5 per bounce so far, \
             instead of its own 0.5: a ray brings back its own weight × what it sees)"
                .to_string()
        } else {
            String::new()
        };
        assert!(
            (found - expected).abs() < 1e-5,
            "the ray at depth {depth} brings back its local light 0.2 plus 0.5 × what its \
             mirror ray brings back: red {expected}, found {found} in {}{hint}",
            ray["color"]
        );
        assert!(
            (first(&ray["local"]) - 0.2).abs() < 1e-6,
            "the ray at depth {depth}: its local light is the mirror's albedo 0.2 × ambient 1 \
             = 0.2, found {}",
            ray["local"]
        );
        assert_eq!(ray["lights"][0]["status"], "ambient");
        ray = next;
    }
}

#[test]
fn max_depth_on_the_command_line_replaces_the_scenes() {
    let tree = tree_with(&["--max-depth", "1"]);
    assert_eq!(tree["tracer"]["max_depth"], 1);
    let first_bounce = &tree["primary"]["secondary"][0];
    assert_eq!(
        first_bounce["traced"], true,
        "--max-depth 1: the first bounce (depth 1) is traced"
    );
    hit_object(first_bounce);
    let second_bounce = &first_bounce["secondary"][0];
    assert_eq!(
        second_bounce["depth"], 2,
        "--max-depth 1: the first bounce's mirror ray is offered at depth 2"
    );
    assert_eq!(
        second_bounce["end"], "max_depth",
        "--max-depth 1: the mirror ray at depth 2 is one bounce too deep and ends there"
    );
}
