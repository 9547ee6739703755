//! `raybook render` end to end: the command line's options reach the
//! tracer, for NFF scenes too.

use std::process::Command;

use raybook::workbench::snapshot::workspace_root;

fn spd(name: &str) -> std::path::PathBuf {
    workspace_root().join("scenes/spd").join(name)
}

/// The primary rays of `raybook render <balls-1.nff> --samples N`, an 8×8 picture.
fn primary_rays_rendered(samples: &str) -> u64 {
    let dir = std::path::Path::new(env!("CARGO_TARGET_TMPDIR"))
        .join(format!("nff-samples-{}-{samples}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let output = Command::new(env!("CARGO_BIN_EXE_raybook"))
        .arg("render")
        .arg(spd("balls-1.nff"))
        .args([
            "--samples",
            samples,
            "--width",
            "8",
            "--height",
            "8",
            "--quiet",
        ])
        .arg("-o")
        .arg(dir.join("x.png"))
        .output()
        .unwrap();
    std::fs::remove_dir_all(&dir).unwrap();
    let stdout = String::from_utf8_lossy(&output.stdout);
    assert!(
        output.status.success(),
        "{stdout}{}",
        String::from_utf8_lossy(&output.stderr)
    );
    // The statistics line: "N rays: P primary, ...".
    let primary = stdout
        .split(" primary")
        .next()
        .and_then(|before| before.rsplit(' ').next())
        .and_then(|count| count.parse().ok());
    primary.unwrap_or_else(|| panic!("no count of primary rays in:\n{stdout}"))
}

#[test]
fn render_takes_the_sample_count_of_the_command_line_for_nff_too() {
    assert_eq!(primary_rays_rendered("1"), 8 * 8);
    assert_eq!(primary_rays_rendered("4"), 4 * 8 * 8, "--samples 4");
}
