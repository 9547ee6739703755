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
