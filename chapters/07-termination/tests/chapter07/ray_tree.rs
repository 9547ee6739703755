//! `--pixel X,Y --json`: which criterion ended each path.

use std::process::Command;

use serde_json::Value;

const GLASS: &str = concat!(
    env!("CARGO_MANIFEST_DIR"),
    "/../06-refraction/scenes/default.toml"
);

/// The tree of pixel (160, 110), which looks at chapter 6's glass sphere.
fn glass_tree(args: &[&str]) -> Value {
    let output = Command::new(env!("CARGO_BIN_EXE_ch07-termination"))
        .arg(GLASS)
        .args(["--pixel", "160,110", "--json"])
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

/// Every ray of the tree, depth first.
fn rays(node: &Value) -> Vec<&Value> {
    let mut all = vec![node];
    for next in node["secondary"].as_array().unwrap() {
        all.extend(rays(next));
    }
    all
}

#[test]
fn a_light_path_ends_at_the_weight_threshold() {
    // The mirror ray off the glass carries 0.02 + 0.95 · 0.04 = 0.058 < 0.1.
    let tree = glass_tree(&["--min-weight", "0.1"]);
    assert_eq!(tree["tracer"]["min_weight"].as_f64(), Some(0.1));
    let mirror = &tree["primary"]["secondary"][0];
    assert_eq!(mirror["kind"], "reflection");
    assert_eq!(mirror["traced"], false);
    assert_eq!(mirror["end"], "weight_threshold");
    let refracted = &tree["primary"]["secondary"][1];
    assert_eq!(refracted["kind"], "refraction");
    assert_eq!(refracted["traced"], true);
    for ray in rays(&tree["primary"]) {
        let w = ray["path_weight"].as_array().unwrap();
        let below = w.iter().all(|c| c.as_f64().unwrap() < 0.1);
        assert_eq!(ray["end"] == "weight_threshold", below, "{ray}");
    }
}

#[test]
fn paths_end_at_the_maximum_depth_before_the_weight_threshold() {
    let tree = glass_tree(&["--max-depth", "1", "--min-weight", "0"]);
    let mut ends = Vec::new();
    for ray in rays(&tree["primary"]) {
        if ray["depth"] == 2 {
            assert_eq!(
                ray["traced"], false,
                "--max-depth 1: a ray at depth 2 is one bounce too deep and is not traced"
            );
            ends.push(ray["end"].as_str().unwrap().to_string());
        }
        assert!(
            ray["depth"].as_u64().unwrap() <= 2,
            "--max-depth 1: no ray deeper than 2 is even offered, found one at depth {}",
            ray["depth"]
        );
    }
    let first_bounce: Vec<&str> = (rays(&tree["primary"]).into_iter())
        .filter(|ray| ray["depth"] == 1)
        .map(|ray| ray["end"].as_str().unwrap_or("nothing"))
        .collect();
    assert!(
        !ends.is_empty(),
        "--max-depth 1 and a glass sphere: the first bounce (depth 1) is traced, so its \
         mirror and refracted rays are offered at depth 2 and end there by max_depth; but the \
         tree has no ray at depth 2, and the rays at depth 1 end by {first_bounce:?}: does \
         may_trace end a path at depth == max_depth (>= instead of >)?"
    );
    assert!(
        ends.iter().all(|e| e == "max_depth"),
        "--max-depth 1 --min-weight 0: every ray at depth 2 ends by max_depth, the depth being \
         asked before the weight; they end by {ends:?}"
    );
}

#[test]
fn a_ray_that_hits_nothing_ends_its_path() {
    let tree = glass_tree(&[]);
    let mirror = &tree["primary"]["secondary"][0];
    assert_eq!(mirror["traced"], true);
    assert!(mirror["hit"].is_null());
    assert_eq!(mirror["end"], "no_hit");
    assert_eq!(mirror["color"], serde_json::json!([0.55, 0.7, 0.9]));
}
