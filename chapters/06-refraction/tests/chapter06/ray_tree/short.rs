//! `--pixel X,Y`: the short tree of the glass pixel, its folds, `--full`,
//! `--fold-depth`, `--fold-weight`, and its picture (`--svg`).

use std::path::Path;
use std::process::{Command, Output};

use serde_json::Value;

/// The glass pixel of the default scene.
const GLASS: &str = "160,110";

fn run(args: &[&str]) -> Output {
    Command::new(env!("CARGO_BIN_EXE_ch06-refraction"))
        .args(args)
        .output()
        .unwrap()
}

/// What the binary prints for `--pixel GLASS` and `args`.
fn glass(args: &[&str]) -> String {
    let output = run(&[&["--pixel", GLASS], args].concat());
    let stderr = String::from_utf8_lossy(&output.stderr);
    assert!(output.status.success(), "{stderr}");
    String::from_utf8(output.stdout).unwrap()
}

/// The first line of each ray's block: "primary ray (depth 0: eye)", …
fn ray_heads(text: &str) -> Vec<&str> {
    let kinds = [
        "primary ray (depth",
        "reflection ray (depth",
        "refraction ray (depth",
    ];
    (text.lines())
        .filter(|l| kinds.iter().any(|k| l.trim_start().starts_with(k)))
        .collect()
}

/// The fold lines and the number of rays each says it folds.
fn folds(text: &str) -> Vec<(usize, &str)> {
    (text.lines())
        .filter_map(|l| {
            let rest = l.trim_start().strip_prefix("⋯ ")?;
            let (n, _) = rest.split_once(' ')?;
            Some((n.parse().unwrap(), l))
        })
        .collect()
}

/// Every ray of a JSON tree, depth first.
fn rays(node: &Value) -> Vec<&Value> {
    let mut all = vec![node];
    for next in node["secondary"].as_array().unwrap() {
        all.extend(rays(next));
    }
    all
}

fn largest(v: &Value) -> f64 {
    let c = v.as_array().unwrap().iter().map(|c| c.as_f64().unwrap());
    c.fold(f64::MIN, f64::max)
}

#[test]
fn the_glass_pixels_short_tree_fits_on_one_screen_and_the_full_one_does_not() {
    let short = glass(&[]);
    let full = glass(&["--full"]);
    assert!(
        short.lines().count() <= 40,
        "{} lines:\n{short}",
        short.lines().count()
    );
    assert!(full.lines().count() > 100, "{} lines", full.lines().count());
    assert!(short.contains("short tree:"), "{short}");
    assert!(!full.contains("⋯") && !full.contains("short tree"));
    // The primary ray is shown in full: the short tree begins as the full one does.
    let primary: Vec<&str> = full.lines().take(13).collect();
    assert!(short.contains(&primary[2..].join("\n")), "{short}");
}

#[test]
fn the_folded_rays_and_the_shown_ones_are_all_the_rays_of_the_full_tree() {
    let short = glass(&[]);
    let folded: usize = folds(&short).iter().map(|(n, _)| n).sum();
    let shown = ray_heads(&short).len();
    let all = ray_heads(&glass(&["--full"])).len();
    assert_eq!(all, rays(&json(&[])["primary"]).len());
    assert!(folded > 0 && shown > 1, "{short}");
    assert_eq!(shown + folded, all, "{short}");
}

fn json(args: &[&str]) -> Value {
    serde_json::from_str(&glass(&[&["--json"], args].concat())).unwrap()
}

#[test]
fn a_fold_line_names_its_reason_and_adds_up_what_its_rays_bring_back() {
    let short = glass(&[]);
    let [(n, line)] = folds(&short)[..] else {
        panic!("one group folds at glass:\n{short}")
    };
    // eye → T → R → R carries 0.058 of 0.0529: below 1% of the pixel.
    assert!(
        line.contains("(with a path weight below 0.01): eye → T → R → R and the"),
        "{line}"
    );
    let tree = json(&[]);
    let top = &tree["primary"]["secondary"][1]["secondary"][0]["secondary"][0];
    assert_eq!(n, rays(top).len());
    let brings = largest(&top["path_weight"]) * top["color"][0].as_f64().unwrap();
    let (_, added) = line.split_once("they add (").unwrap();
    let first: f64 = added.split(',').next().unwrap().parse().unwrap();
    assert!((first - brings).abs() < 1e-4, "{brings}: {line}");
}

#[test]
fn folding_nothing_shows_every_ray_of_the_full_tree() {
    let unfolded = glass(&["--fold-depth", "100", "--fold-weight", "0"]);
    let full = glass(&["--full"]);
    assert!(folds(&unfolded).is_empty(), "{unfolded}");
    assert_eq!(ray_heads(&unfolded), ray_heads(&full));
    // What every ray brings back is the same too.
    let brings = |t: &str| -> Vec<String> {
        let closing = t.lines().filter(|l| l.contains(" brings back"));
        closing
            .map(|l| l.rsplit(": ").next().unwrap().to_string())
            .collect()
    };
    assert_eq!(brings(&unfolded).len(), brings(&full).len());
}

#[test]
fn the_fold_options_set_the_folds_and_change_nothing_traced() {
    let shallow = glass(&["--fold-depth", "1", "--fold-weight", "0"]);
    assert!(
        ray_heads(&shallow)
            .iter()
            .all(|h| h.contains("(depth 0") || h.contains("(depth 1"))
    );
    assert!(
        folds(&shallow)
            .iter()
            .all(|(_, l)| l.contains("(deeper than 1 bounce)"))
    );
    let folded: usize = folds(&shallow).iter().map(|(n, _)| n).sum();
    assert_eq!(
        ray_heads(&shallow).len() + folded,
        ray_heads(&glass(&["--full"])).len()
    );
    let heavy = glass(&["--fold-weight", "0.5"]);
    assert_eq!(
        ray_heads(&heavy).len(),
        3,
        "the eye's, 0.912, then 0.832: {heavy}"
    );
    // The JSON keeps every ray, whatever the folds.
    assert_eq!(json(&["--fold-depth", "1"]), json(&[]));
}

#[test]
fn full_refuses_the_fold_options_and_they_need_a_pixel() {
    let both = run(&["--pixel", GLASS, "--full", "--fold-depth", "2"]);
    assert!(!both.status.success());
    let alone = run(&["--fold-weight", "0.1"]);
    assert!(!alone.status.success());
    let stderr = String::from_utf8_lossy(&alone.stderr);
    assert!(stderr.contains("--pixel"), "{stderr}");
    let help = String::from_utf8(run(&["--help"]).stdout).unwrap();
    for option in [
        "--full",
        "--fold-depth <N>",
        "--fold-weight <W>",
        "--svg <FILE.svg>",
    ] {
        assert!(help.contains(option), "{option} in\n{help}");
    }
    assert!(help.contains("never what is traced"), "{help}");
}

/// The picture of the glass pixel, written into `dir` with `args`.
fn svg(dir: &Path, name: &str, args: &[&str]) -> String {
    let path = dir.join(name);
    glass(&[&["--svg", path.to_str().unwrap()], args].concat());
    std::fs::read_to_string(path).unwrap()
}

#[test]
fn the_picture_draws_each_shown_ray_once_and_the_folded_ones_thin() {
    let dir = tempfile::tempdir().unwrap();
    let picture = svg(dir.path(), "glass.svg", &[]);
    assert!(picture.starts_with("<svg xmlns=\"http://www.w3.org/2000/svg\""));
    assert!(picture.trim_end().ends_with("</svg>"));
    assert!(picture.contains("<title>Rays of pixel (160, 110), chapter 06-refraction</title>"));
    assert!(picture.contains("<desc>"));
    assert_eq!(
        picture.matches("<text").count(),
        picture.matches("</text>").count()
    );
    let short = glass(&[]);
    let shown = picture.matches("<line class=\"ray ").count();
    assert_eq!(shown, ray_heads(&short).len());
    let folded: usize = folds(&short).iter().map(|(n, _)| n).sum();
    assert_eq!(picture.matches("<line class=\"folded\"").count(), folded);
    assert!(picture.contains(">refraction 0.912</text>"), "a label");
    assert!(picture.contains(">object 0 (sphere, glass)</text>"));
    let full = svg(dir.path(), "full.svg", &["--full"]);
    let all = ray_heads(&glass(&["--full"])).len();
    assert_eq!(full.matches("<line class=\"ray ").count(), all);
    assert!(!full.contains("class=\"folded\""));
}

#[test]
fn the_picture_is_the_same_every_time_and_written_whole() {
    let dir = tempfile::tempdir().unwrap();
    let first = svg(dir.path(), "a.svg", &[]);
    let again = svg(dir.path(), "a.svg", &[]);
    assert_eq!(first, again);
    let files: Vec<_> = std::fs::read_dir(dir.path()).unwrap().collect();
    assert_eq!(files.len(), 1, "no temporary file left behind");
    // A file where its folder should be: an error, and nothing written.
    let blocker = dir.path().join("a.svg");
    let nowhere = run(&[
        "--pixel",
        GLASS,
        "--svg",
        &format!("{}/b.svg", blocker.display()),
    ]);
    assert!(!nowhere.status.success());
    let stderr = String::from_utf8_lossy(&nowhere.stderr);
    assert!(stderr.contains("cannot write"), "{stderr}");
}
