//! `workbook verify` as a command: its verdict, its messages and its exit status.

use std::process::Command;

use super::{reference_image, save};

#[test]
fn a_wrong_size_fails_with_a_clear_message() {
    let small = image::RgbImage::new(320, 240);
    let path = save("big.png", &small);
    let output = Command::new(env!("CARGO_BIN_EXE_workbook"))
        .args(["verify", "3"])
        .arg(&path)
        .output()
        .unwrap();
    assert!(!output.status.success());
    let stdout = String::from_utf8_lossy(&output.stdout);
    assert!(stdout.contains("FAIL"), "{stdout}");
    assert!(
        stdout.contains("the image is 320×240 but the reference is 160×120"),
        "{stdout}"
    );
    assert!(stdout.contains("--width 160 --height 120"), "{stdout}");
}

#[test]
fn the_command_passes_the_reference_and_writes_a_diff() {
    let path = save("mine.png", &reference_image("7"));
    let output = Command::new(env!("CARGO_BIN_EXE_workbook"))
        .args(["verify", "07-termination"])
        .arg(&path)
        .output()
        .unwrap();
    let stdout = String::from_utf8_lossy(&output.stdout);
    assert!(output.status.success(), "{stdout}");
    assert!(stdout.starts_with("PASS"), "{stdout}");
    assert!(path.with_extension("diff.png").exists());
}

#[test]
fn the_command_names_the_mistake_and_its_fix() {
    let flipped = image::imageops::flip_vertical(&reference_image("3"));
    let path = save("flipped-command.png", &flipped);
    let output = Command::new(env!("CARGO_BIN_EXE_workbook"))
        .args(["verify", "3"])
        .arg(&path)
        .output()
        .unwrap();
    assert!(!output.status.success());
    let stdout = String::from_utf8_lossy(&output.stdout);
    println!("{stdout}");
    assert!(stdout.starts_with("FAIL"), "{stdout}");
    assert!(
        stdout.contains("diff (reference | mask | yours)"),
        "{stdout}"
    );
    assert!(
        stdout.contains("likely mistake: your picture is upside down"),
        "{stdout}"
    );
    assert!(stdout.contains("\nfix: row 0 is the top"), "{stdout}");
}

/// `workbook verify --tree` run as a command, on chapter 6's glass pixel.
fn verify_tree(args: &[&str], tree: &serde_json::Value, name: &str) -> (bool, String, String) {
    let path = super::temp(name);
    std::fs::write(&path, tree.to_string()).unwrap();
    let output = Command::new(env!("CARGO_BIN_EXE_workbook"))
        .args(["verify", "--tree"])
        .args(args)
        .arg(&path)
        .output()
        .unwrap();
    let stdout = String::from_utf8_lossy(&output.stdout).into_owned();
    let stderr = String::from_utf8_lossy(&output.stderr).into_owned();
    println!("{stdout}{stderr}");
    (output.status.success(), stdout, stderr)
}

#[test]
fn the_tree_command_passes_the_reference_and_names_a_difference() {
    let text = workbook::verify::tree::reference_tree("06-refraction", 160, 110).unwrap();
    let mut tree: serde_json::Value = serde_json::from_str(text).unwrap();
    let (passed, stdout, _) = verify_tree(&["6", "160,110"], &tree, "glass.json");
    assert!(
        passed && stdout.starts_with("PASS: chapter 06-refraction, pixel (160, 110)"),
        "{stdout}"
    );
    *tree.pointer_mut("/primary/secondary/1/hit/t").unwrap() = serde_json::json!(2.5);
    let (passed, stdout, _) = verify_tree(&["ch06-refraction", "160,110"], &tree, "glass-t.json");
    assert!(!passed);
    assert!(stdout.starts_with("FAIL"), "{stdout}");
    assert!(
        stdout.contains("at primary → refraction: hit.t differs"),
        "{stdout}"
    );
    assert!(stdout.contains("1e-4 relative"), "{stdout}");
}

#[test]
fn the_tree_command_says_what_it_takes() {
    let tree = serde_json::json!({});
    let (passed, _, stderr) = verify_tree(&["6"], &tree, "no-pixel.json");
    assert!(!passed);
    assert!(
        stderr.contains("verify --tree 6 160,110 mine.json"),
        "{stderr}"
    );
    let (passed, _, stderr) = verify_tree(&["6", "160x110"], &tree, "bad-pixel.json");
    assert!(!passed);
    assert!(stderr.contains("expected the pixel as X,Y"), "{stderr}");
    let (passed, _, stderr) = verify_tree(&["6", "160,110"], &tree, "empty.json");
    assert!(!passed);
    assert!(
        stderr.contains("your tree has no `primary` ray"),
        "{stderr}"
    );
}

#[test]
fn the_tree_command_compares_with_another_reference() {
    let text = workbook::verify::tree::reference_tree("05-reflection", 162, 128).unwrap();
    let against = super::temp("against.json");
    std::fs::write(&against, text).unwrap();
    let tree: serde_json::Value = serde_json::from_str(text).unwrap();
    let against = against.to_str().unwrap();
    let (passed, stdout, _) = verify_tree(&["5", "162,128", "--against", against], &tree, "a.json");
    assert!(passed, "{stdout}");
    let (passed, _, stderr) = verify_tree(&["5", "1,2", "--against", against], &tree, "b.json");
    assert!(!passed);
    assert!(
        stderr.contains("is of pixel (162, 128), not (1, 2)"),
        "{stderr}"
    );
}
